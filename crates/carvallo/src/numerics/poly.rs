//! Polynomials and scalar root finding on an interval: Horner evaluation, bisection (two
//! flavours, each written once), the real roots of a polynomial on an interval
//! ([`real_roots_in`]) and golden-section search.

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

/// Evaluates a polynomial given lowest degree first, $\sum_k c_k x^k$, by Horner's rule.
pub fn poly_eval_low(coeffs: &[f64], x: f64) -> f64 {
    coeffs.iter().rev().fold(0.0, |acc, c| acc * x + c)
}

/// The real roots in $[lo, hi]$ of the polynomial $\sum_k c_k x^k$ (coefficients lowest
/// degree first, any degree; `hi` may be infinite: then Cauchy's bound
/// $1 + \max_k |c_k / c_n|$ closes the interval), ascending, each located to adjacent floats.
///
/// The roots are isolated by the derivative: the real roots of $p'$ in the interval
/// (recursively) cut it into pieces on which $p$ is monotone, so each piece holds at most one
/// root, found where $p$ changes sign by Newton's method kept inside the bracket (a step that
/// leaves it, or does not halve it, is replaced by bisection) until the bracket or the step
/// reaches the adjacent floats; an end where $p$ is exactly zero is a root.
/// Two roots closer than the rounding error of $p$ near them (a near-multiple root) are seen
/// as one root (odd multiplicity) or none (even): $p$ does not change sign there within the
/// precision of its evaluation, and the interval between them is below that resolution. A
/// polynomial that vanishes identically has no roots reported.
pub fn real_roots_in(coeffs: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    roots_in(coeffs, lo, hi, true)
}

/// [`real_roots_in`]; below the top level (`top` false: the critical points that only cut the
/// interval) a quadratic is solved in closed form.
fn roots_in(coeffs: &[f64], lo: f64, hi: f64, top: bool) -> Vec<f64> {
    let n = coeffs.iter().rposition(|&c| c != 0.0).map_or(0, |i| i + 1);
    let c = &coeffs[..n];
    if n < 2 || lo.is_nan() || hi.is_nan() || lo > hi {
        return Vec::new();
    }
    let hi = if hi.is_finite() {
        hi
    } else {
        let lead = c[n - 1];
        let bound = 1.0 + c[..n - 1].iter().map(|x| (x / lead).abs()).fold(0.0, f64::max);
        bound.max(lo)
    };
    if !hi.is_finite() {
        return Vec::new();
    }
    if n == 3 && !top {
        // Cancellation-free quadratic formula; a double or complex pair cuts nothing.
        let (c0, c1, c2) = (c[0], c[1], c[2]);
        let disc = c1 * c1 - 4.0 * c2 * c0;
        if disc.is_nan() || disc <= 0.0 {
            return Vec::new();
        }
        let q = -0.5 * (c1 + c1.signum() * disc.sqrt());
        let mut r: Vec<f64> = [q / c2, if q != 0.0 { c0 / q } else { 0.0 }]
            .into_iter()
            .filter(|x| *x >= lo && *x <= hi)
            .collect();
        r.sort_by(f64::total_cmp);
        return r;
    }
    let derivative: Vec<f64> = c.iter().enumerate().skip(1).map(|(k, x)| k as f64 * x).collect();
    let mut points = vec![lo];
    points.extend(roots_in(&derivative, lo, hi, false).into_iter().filter(|&x| x > lo && x < hi));
    points.push(hi);
    let f = |x: f64| poly_eval_low(c, x);
    let mut roots: Vec<f64> = Vec::new();
    let push = |x: f64, roots: &mut Vec<f64>| {
        if roots.last() != Some(&x) {
            roots.push(x);
        }
    };
    for pair in points.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let (fa, fb) = (f(a), f(b));
        if fa == 0.0 {
            push(a, &mut roots);
        }
        if fa != 0.0 && fb != 0.0 && (fa > 0.0) != (fb > 0.0) {
            push(monotone_root(c, &derivative, a, b, fa > 0.0), &mut roots);
        }
    }
    if f(hi) == 0.0 {
        push(hi, &mut roots);
    }
    roots
}

/// The root of the polynomial `c` (derivative `d`) on $[a, b]$ where it changes sign
/// (`positive_at_a` its sign at `a`): safeguarded Newton (see [`real_roots_in`]).
fn monotone_root(c: &[f64], d: &[f64], mut a: f64, mut b: f64, positive_at_a: bool) -> f64 {
    let mut x = 0.5 * (a + b);
    let mut width = b - a;
    for _ in 0..200 {
        let fx = poly_eval_low(c, x);
        if fx == 0.0 {
            return x;
        }
        if (fx > 0.0) == positive_at_a {
            a = x;
        } else {
            b = x;
        }
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            return x;
        }
        let step = fx / poly_eval_low(d, x);
        let newton = x - step;
        let next = if newton > a && newton < b && b - a <= 0.5 * width { newton } else { mid };
        width = b - a;
        if (next - x).abs() <= f64::EPSILON * x.abs() {
            return next;
        }
        x = next;
    }
    x
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
    fn real_roots_of_known_polynomials() {
        // (x - 1)(x - 2)(x - 3)(x + 1) = x^4 - 5x^3 + 5x^2 + 5x - 6, lowest first.
        let p = [-6.0, 5.0, 5.0, -5.0, 1.0];
        let r = real_roots_in(&p, 0.0, 10.0);
        assert_eq!(r.len(), 3, "{r:?}");
        for (x, want) in r.iter().zip([1.0, 2.0, 3.0]) {
            assert!((x - want).abs() <= 4.0 * f64::EPSILON * want, "{x} {want}");
        }
        assert_eq!(real_roots_in(&p, -5.0, f64::INFINITY).len(), 4);
        assert_eq!(real_roots_in(&p, 1.5, 1.9), Vec::<f64>::new());
        // An end that is an exact root is reported once.
        assert_eq!(real_roots_in(&p, 2.0, 2.5), vec![2.0]);
        // A double root (x - 1)^2 (x - 4) of even multiplicity at 1 is no sign change; the
        // simple root at 4 is found. A pair 1e-4 apart is separated by the critical point.
        let q = [-4.0, 9.0, -6.0, 1.0];
        let r = real_roots_in(&q, 0.0, 10.0);
        assert!(r.iter().any(|x| (x - 4.0).abs() < 1e-14), "{r:?}");
        let e = 1e-4;
        let close = [1.0 * (1.0 + e), -(2.0 + e), 1.0];
        let r = real_roots_in(&close, 0.0, 3.0);
        assert_eq!(r.len(), 2, "{r:?}");
        assert!((r[0] - 1.0).abs() < 1e-11 && (r[1] - 1.0 - e).abs() < 1e-11, "{r:?}");
        // Degree 6 with roots 0.5, 1, ..., 3 (a product built by multiplication).
        let mut six = vec![1.0];
        for k in 1..=6 {
            let root = 0.5 * k as f64;
            let mut next = vec![0.0; six.len() + 1];
            for (i, c) in six.iter().enumerate() {
                next[i] -= root * c;
                next[i + 1] += c;
            }
            six = next;
        }
        let r = real_roots_in(&six, 0.0, f64::INFINITY);
        assert_eq!(r.len(), 6, "{r:?}");
        for (k, x) in r.iter().enumerate() {
            assert!((x - 0.5 * (k + 1) as f64).abs() < 1e-12, "{r:?}");
        }
        assert_eq!(real_roots_in(&[0.0, 0.0], 0.0, 1.0), Vec::<f64>::new());
        assert_eq!(real_roots_in(&[1.0, 0.0, 1.0], -3.0, 3.0), Vec::<f64>::new());
        assert_eq!(poly_eval_low(&[1.0, 2.0, 3.0], 2.0), 17.0);
    }

    #[test]
    fn golden_section_finds_a_parabola_minimum() {
        let x = minimise(|x| (x - 0.3) * (x - 0.3), -1.0, 2.0);
        assert!((x - 0.3).abs() < 1e-7, "{x}");
    }
}
