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

/// The largest degree [`RootsUpTo8`] and [`sign_change_roots_in`] take.
pub const MAX_BERNSTEIN_DEGREE: usize = 8;

/// At most [`MAX_BERNSTEIN_DEGREE`] roots, ascending, on the stack.
#[derive(Clone, Copy, Debug, Default)]
pub struct RootsUpTo8 {
    xs: [f64; MAX_BERNSTEIN_DEGREE],
    n: usize,
}

impl RootsUpTo8 {
    /// The roots found.
    pub fn as_slice(&self) -> &[f64] {
        &self.xs[..self.n]
    }

    fn push(&mut self, x: f64) {
        if self.n < MAX_BERNSTEIN_DEGREE && (self.n == 0 || self.xs[self.n - 1] < x) {
            self.xs[self.n] = x;
            self.n += 1;
        }
    }
}

/// The points of the open interval $(lo, hi)$ where the polynomial $\sum_k c_k x^k$
/// (lowest first, degree at most [`MAX_BERNSTEIN_DEGREE`]; `hi` may be infinite: Cauchy's
/// bound closes the interval) changes sign, ascending, each located to adjacent floats; no
/// allocation. These are the roots of odd multiplicity that [`real_roots_in`] reports inside
/// the interval, found without the roots of the derivatives. A line or a quadratic is solved
/// in closed form (the cancellation-free quadratic formula); above,
///
/// the polynomial is written in the Bernstein basis of the interval (a Taylor shift and
/// scaling, then the change of basis, $O(n^2)$); by Descartes' rule the number of sign changes
/// of the Bernstein coefficients bounds the number of roots in the interval and has its parity.
/// No change: no root, the interval is done. One change: exactly one root, located by the same
/// safeguarded Newton iteration as [`real_roots_in`] (Newton kept inside the bracket, bisection
/// when it leaves or stalls). More: the interval is halved (de Casteljau) and each half treated
/// alike, to a depth of 64 halvings, below which a sign change between the ends is taken as one
/// root (a cluster narrower than $2^{-64}$ of the interval, below the resolution of $p$).
/// The sign at the ends of every piece is evaluated by Horner's rule on `coeffs` (as the caller
/// evaluates them): a sign change between the ends always gives a root, whatever the rounded
/// Bernstein coefficients say. A point where $p$ is exactly zero and the sign changes across
/// it is a root; an exact zero without change of sign is not.
pub fn sign_change_roots_in(coeffs: &[f64], lo: f64, hi: f64) -> RootsUpTo8 {
    let mut out = RootsUpTo8::default();
    let n = coeffs.iter().rposition(|&c| c != 0.0).map_or(0, |i| i + 1);
    if !(2..=MAX_BERNSTEIN_DEGREE + 1).contains(&n) || lo.is_nan() || hi.is_nan() || lo >= hi {
        return out;
    }
    let c = &coeffs[..n];
    let deg = n - 1;
    let hi = if hi.is_finite() {
        hi
    } else {
        let lead = c[deg];
        let bound = 1.0 + c[..deg].iter().map(|x| (x / lead).abs()).fold(0.0, f64::max);
        if bound.is_nan() || bound <= lo || !bound.is_finite() {
            return out;
        }
        bound
    };
    if deg <= 2 {
        // Closed form: the root of a line, the cancellation-free quadratic formula (a double
        // or complex pair changes no sign).
        let mut r = [f64::NAN; 2];
        if deg == 1 {
            r[0] = -c[0] / c[1];
        } else {
            let disc = c[1] * c[1] - 4.0 * c[2] * c[0];
            if disc > 0.0 {
                let q = -0.5 * (c[1] + c[1].signum() * disc.sqrt());
                r = [q / c[2], c[0] / q];
                if r[1] < r[0] {
                    r.swap(0, 1);
                }
            }
        }
        for x in r {
            if x > lo && x < hi {
                out.push(x);
            }
        }
        return out;
    }
    // Taylor shift to lo, scaling by w = hi - lo: q(y) = p(lo + w y), y in [0, 1].
    let mut q = [0.0; MAX_BERNSTEIN_DEGREE + 1];
    q[..n].copy_from_slice(c);
    if lo != 0.0 {
        for i in 0..deg {
            for j in (i..deg).rev() {
                q[j] += lo * q[j + 1];
            }
        }
    }
    let w = hi - lo;
    let mut wk = 1.0;
    for x in q.iter_mut().take(n).skip(1) {
        wk *= w;
        *x *= wk;
    }
    // Bernstein coefficients b_i = sum_{k <= i} C(i, k) q_k / C(n, k): divide by the
    // binomials, then n passes of Pascal's rule (x_i += x_{i-1}) give the sums.
    let mut b = [0.0; MAX_BERNSTEIN_DEGREE + 1];
    let mut cnk = 1.0;
    for k in 0..n {
        b[k] = q[k] / cnk;
        cnk = cnk * (deg - k) as f64 / (k + 1) as f64;
    }
    for j in 1..n {
        for i in (j..n).rev() {
            b[i] += b[i - 1];
        }
    }
    let mut d = [0.0; MAX_BERNSTEIN_DEGREE];
    for k in 1..n {
        d[k - 1] = k as f64 * c[k];
    }
    let pos = |x: f64| poly_eval_low(c, x);
    let ends = (pos(lo), pos(hi));
    bernstein_pieces(c, &d[..deg], &b[..n], (lo, hi), ends, 0, &mut out);
    out
}

/// One piece of [`sign_change_roots_in`]: `b` the Bernstein coefficients on `(l, r)`, `f`
/// the values of `c` at the ends (Horner).
fn bernstein_pieces(
    c: &[f64],
    d: &[f64],
    b: &[f64],
    (l, r): (f64, f64),
    f: (f64, f64),
    depth: u32,
    out: &mut RootsUpTo8,
) {
    let changes = b
        .iter()
        .filter(|x| **x != 0.0)
        .fold((0u32, 0.0f64), |(n, last), &x| {
            (n + u32::from(last != 0.0 && (x > 0.0) != (last > 0.0)), x)
        })
        .0;
    // An end where p is exactly zero: the sign just inside is that of the first (last)
    // nonzero Bernstein coefficient, the lowest term of p's expansion about that end.
    let inside = |x: f64, mut bs: std::slice::Iter<'_, f64>, last: bool| {
        if x != 0.0 {
            return x;
        }
        let nz = |y: &&f64| **y != 0.0;
        (if last { bs.rfind(nz) } else { bs.find(nz) }).copied().unwrap_or(0.0)
    };
    let f = (inside(f.0, b.iter(), false), inside(f.1, b.iter(), true));
    let ends_differ = f.0 != 0.0 && f.1 != 0.0 && (f.0 > 0.0) != (f.1 > 0.0);
    let mid = 0.5 * (l + r);
    if changes <= 1 || depth >= 64 || mid <= l || mid >= r {
        if ends_differ {
            out.push(bracketed_newton(c, d, (l, r), f));
        }
        return;
    }
    // de Casteljau at 1/2: the left half's coefficients are the first of each row, the right
    // half's the last.
    let n = b.len();
    let mut left = [0.0; MAX_BERNSTEIN_DEGREE + 1];
    let mut right = [0.0; MAX_BERNSTEIN_DEGREE + 1];
    let mut row = [0.0; MAX_BERNSTEIN_DEGREE + 1];
    row[..n].copy_from_slice(b);
    for j in 0..n {
        left[j] = row[0];
        right[n - 1 - j] = row[n - 1 - j];
        for i in 0..n - 1 - j {
            row[i] = 0.5 * (row[i] + row[i + 1]);
        }
    }
    let fm = poly_eval_low(c, mid);
    // An exact zero at the cut: the sign just beside it on each side, and a root at the cut
    // where they differ.
    let delta = (r - l) * 1e-9;
    let (fl, fr) = if fm == 0.0 {
        (poly_eval_low(c, mid - delta), poly_eval_low(c, mid + delta))
    } else {
        (fm, fm)
    };
    bernstein_pieces(c, d, &left[..n], (l, mid), (f.0, fl), depth + 1, out);
    if fm == 0.0 && fl != 0.0 && fr != 0.0 && (fl > 0.0) != (fr > 0.0) {
        out.push(mid);
    }
    bernstein_pieces(c, d, &right[..n], (mid, r), (fr, f.1), depth + 1, out);
}

/// The root of the polynomial `c` (derivative `d`) in $(a, b)$ where it changes sign, `f` its
/// values at the ends: Newton's method safeguarded as in `rtsafe` (Press et al., *Numerical
/// Recipes*, § 9.4): the step starts at the secant point of the ends, a Newton step that
/// leaves the bracket or does not halve the step before the last is replaced by bisection,
/// and the bracket shrinks with every evaluation; it stops at an exact zero, when the Newton
/// step is below one unit in the last place (before it is taken), or when the bracket is two
/// adjacent floats.
fn bracketed_newton(c: &[f64], d: &[f64], (mut a, mut b): (f64, f64), f: (f64, f64)) -> f64 {
    let positive_at_a = f.0 > 0.0;
    let secant = a - f.0 * (b - a) / (f.1 - f.0);
    let mut x = if secant > a && secant < b { secant } else { 0.5 * (a + b) };
    let (mut dx, mut dx_old) = (b - a, b - a);
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
        if step.abs() <= f64::EPSILON * x.abs() {
            // Newton moves less than an ulp: x is the root to the resolution of p.
            return x;
        }
        let newton = x - step;
        let dfx = fx / step;
        let next = if newton > a && newton < b && (2.0 * fx).abs() <= (dx_old * dfx).abs() {
            newton
        } else {
            mid
        };
        dx_old = dx;
        dx = next - x;
        if dx.abs() <= f64::EPSILON * x.abs() {
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
    fn sign_changes_by_descartes_rule_match_the_derivative_isolation() {
        // The known roots of real_roots_of_known_polynomials, found without derivatives.
        let p = [-6.0, 5.0, 5.0, -5.0, 1.0];
        let r = sign_change_roots_in(&p, 0.0, 10.0);
        assert_eq!(r.as_slice().len(), 3, "{r:?}");
        for (x, want) in r.as_slice().iter().zip([1.0, 2.0, 3.0]) {
            assert!((x - want).abs() <= 4.0 * f64::EPSILON * want, "{x} {want}");
        }
        assert_eq!(sign_change_roots_in(&p, -5.0, f64::INFINITY).as_slice().len(), 4);
        assert!(sign_change_roots_in(&p, 1.5, 1.9).as_slice().is_empty());
        // Ends are excluded: an exact zero at an end is not reported, and the sign just inside
        // is read from the Bernstein coefficients (x^3 - 4x, zero at 0, root at 2).
        assert!(sign_change_roots_in(&p, 2.0, 2.5).as_slice().is_empty());
        assert_eq!(sign_change_roots_in(&[0.0, -4.0, 0.0, 1.0], 0.0, 3.0).as_slice(), [2.0]);
        // A double root is no sign change; the close pair is separated by halving.
        let q = [-4.0, 9.0, -6.0, 1.0];
        let r = sign_change_roots_in(&q, 0.0, 10.0);
        assert_eq!(r.as_slice().len(), 1, "{r:?}");
        assert!((r.as_slice()[0] - 4.0).abs() < 1e-14, "{r:?}");
        let e = 1e-4;
        let close = [1.0 * (1.0 + e), -(2.0 + e), 1.0];
        let r = sign_change_roots_in(&close, 0.0, 3.0);
        assert_eq!(r.as_slice().len(), 2, "{r:?}");
        assert!((r.as_slice()[0] - 1.0).abs() < 1e-11 && (r.as_slice()[1] - 1.0 - e).abs() < 1e-11);
        // An exact root at a halving point (x - 1)(x - 2)(x - 3) on [0, 4]: 2 is the first cut.
        let cubic = [-6.0, 11.0, -6.0, 1.0];
        assert_eq!(sign_change_roots_in(&cubic, 0.0, 4.0).as_slice(), [1.0, 2.0, 3.0]);
        // Degree 6 with roots 0.5, 1, ..., 3, as real_roots_in finds them.
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
        let (r, s) =
            (sign_change_roots_in(&six, 0.0, f64::INFINITY), real_roots_in(&six, 0.0, 10.0));
        assert_eq!(r.as_slice().len(), 6, "{r:?}");
        for (x, y) in r.as_slice().iter().zip(&s) {
            assert!((x - y).abs() <= 1e-12, "{r:?} {s:?}");
        }
        assert!(sign_change_roots_in(&[0.0, 0.0], 0.0, 1.0).as_slice().is_empty());
        assert!(sign_change_roots_in(&[1.0, 0.0, 1.0], -3.0, 3.0).as_slice().is_empty());
    }

    #[test]
    fn golden_section_finds_a_parabola_minimum() {
        let x = minimise(|x| (x - 0.3) * (x - 0.3), -1.0, 2.0);
        assert!((x - 0.3).abs() < 1e-7, "{x}");
    }
}
