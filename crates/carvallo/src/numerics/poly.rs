//! Polynomials and scalar root finding on an interval: Horner evaluation, bisection (two
//! flavours, each written once) and golden-section search.

/// Evaluates a polynomial (highest degree first) by Horner's rule.
pub fn poly_eval(coeffs: &[f64], x: f64) -> f64 {
    coeffs.iter().fold(0.0, |acc, c| acc * x + c)
}

/// Bisection for a root of a continuous `f` with a sign change on `[lo, hi]`; `None` when `f`
/// is not finite at an end or has the same sign at both. Stops at an exact zero, after 200
/// halvings, or when the midpoint no longer moves (adjacent floats).
pub fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> Option<f64> {
    let flo = f(lo);
    if !(flo.is_finite() && f(hi).is_finite()) || flo.signum() == f(hi).signum() {
        return None;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let fm = f(mid);
        if fm == 0.0 {
            return Some(mid);
        }
        if fm.signum() == flo.signum() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// Bisection that trusts its bracket: keeps the half where `f > 0` differs from `f(lo) > 0`,
/// for 200 halvings or until the midpoint no longer moves, and returns the last midpoint. It
/// does not check the bracket: without a sign change it converges to an end.
pub fn bisect_unchecked(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let positive_at_lo = f(lo) > 0.0;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if (f(mid) > 0.0) == positive_at_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Golden-section minimisation of a unimodal `f` on `[lo, hi]` (200 steps); the midpoint of
/// the last bracket.
pub fn minimise(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let r = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        let (x1, x2) = (hi - r * (hi - lo), lo + r * (hi - lo));
        if f(x1) < f(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_bisections_find_sqrt_2_to_the_last_float() {
        let f = |x: f64| x * x - 2.0;
        let checked = bisect(f, 0.0, 2.0).unwrap_or(f64::NAN);
        let trusted = bisect_unchecked(f, 0.0, 2.0);
        for x in [checked, trusted] {
            assert!((x - 2f64.sqrt()).abs() <= 4.0 * f64::EPSILON, "{x}");
        }
        assert_eq!(bisect(f, 2.0, 3.0), None);
        assert_eq!(bisect(|x| x, -1.0, 1.0), Some(0.0));
    }

    #[test]
    fn golden_section_finds_a_parabola_minimum() {
        let x = minimise(|x| (x - 0.3) * (x - 0.3), -1.0, 2.0);
        assert!((x - 0.3).abs() < 1e-7, "{x}");
    }
}
