//! Roots of real quartics $c_4x^4 + c_3x^3 + c_2x^2 + c_1x + c_0$ (coefficients lowest degree
//! first, $c_4 \ne 0$) by five methods, a 256-bit reference, and a suite of hard cases.
//!
//! * [`ferrari`]: the closed form (depressed quartic, Ferrari's resolvent cubic solved by
//!   Cardano or Viète, two real quadratics by the cancellation-free formula), each root then
//!   polished by at most two Newton steps that must decrease the residual;
//! * [`companion`]: eigenvalues of the companion matrix (nalgebra's Schur decomposition, its
//!   iterations capped: uncapped, it loops for ever on $x^4 + 1$);
//! * [`aberth`]: the Aberth–Ehrlich simultaneous iteration in `f64`;
//! * [`aberth_compensated`]: the same iteration with $p$ and $p'$ evaluated by a compensated
//!   (error-free transformation, double-double) Horner scheme, so the roots are as accurate as
//!   if computed in twice the working precision, then rounded;
//! * [`graeffe_moduli`]: Carvallo's own root-squaring method (n° 14, Graeffe), with the step of
//!   [`crate::numerics::graeffe::graeffe_step`]: the moduli of the roots only, as he used it.
//!
//! [`reference_roots`] runs Aberth's iteration in 256-bit arithmetic (astro-float) from the
//! compensated roots: the exact roots of the `f64` coefficients, to far below `f64` resolution.
//! [`polynomial_suite`] lists the hard test polynomials: clustered roots, spread magnitudes,
//! near-double roots and $x^4 + 1$ (`carvallo bench` adds the benchmark bicycle's
//! characteristic polynomial at its weave, capsize and weave–capsize bifurcation speeds).

use astro_float::{BigFloat, RoundingMode};
pub use nalgebra::Complex;
use nalgebra::Matrix4;

use crate::numerics::dd::Dd;

/// A complex number in `f64`.
pub type C64 = Complex<f64>;

/// $p(z)$ and $p'(z)$ by Horner's rule in `f64`.
fn horner2(c: &[f64; 5], z: C64) -> (C64, C64) {
    let mut p = C64::new(c[4], 0.0);
    let mut d = C64::new(0.0, 0.0);
    for k in (0..4).rev() {
        d = d * z + p;
        p = p * z + c[k];
    }
    (p, d)
}

/// The roots of $x^2 + bx + c$ (real $b, c$), the larger-magnitude real root first computed
/// without cancellation.
fn quadratic(b: f64, c: f64) -> [C64; 2] {
    let disc = b * b - 4.0 * c;
    if disc >= 0.0 {
        let q = -0.5 * (b + b.signum() * disc.sqrt());
        let other = if q != 0.0 { c / q } else { 0.0 };
        [C64::new(q, 0.0), C64::new(other, 0.0)]
    } else {
        let im = 0.5 * (-disc).sqrt();
        [C64::new(-0.5 * b, im), C64::new(-0.5 * b, -im)]
    }
}

/// The largest real root of $t^3 + at^2 + bt + c$ (Cardano for one real root, Viète's
/// trigonometric form for three), polished by Newton steps.
fn cubic_largest(a: f64, b: f64, c: f64) -> f64 {
    let pp = b - a * a / 3.0;
    let qq = 2.0 * a * a * a / 27.0 - a * b / 3.0 + c;
    let disc = 0.25 * qq * qq + pp * pp * pp / 27.0;
    let z = if disc > 0.0 {
        let u = (-0.5 * qq - qq.signum() * disc.sqrt()).cbrt();
        if u != 0.0 {
            u - pp / (3.0 * u)
        } else {
            0.0
        }
    } else if pp < 0.0 {
        let r = (-pp / 3.0).sqrt();
        let cos_phi = (-0.5 * qq / (r * r * r)).clamp(-1.0, 1.0);
        2.0 * r * (cos_phi.acos() / 3.0).cos()
    } else {
        0.0
    };
    let mut t = z - a / 3.0;
    for _ in 0..3 {
        let f = ((t + a) * t + b) * t + c;
        let df = (3.0 * t + 2.0 * a) * t + b;
        if df == 0.0 {
            break;
        }
        let next = t - f / df;
        let fnext = ((next + a) * next + b) * next + c;
        if fnext.abs() >= f.abs() {
            break;
        }
        t = next;
    }
    t
}

/// Newton polish of one root on the original polynomial: at most two steps, each kept only if
/// it decreases the residual.
fn polish(c: &[f64; 5], mut z: C64) -> C64 {
    for _ in 0..2 {
        let (p, d) = horner2(c, z);
        if p.norm() == 0.0 || d.norm() == 0.0 {
            break;
        }
        let next = z - p / d;
        if horner2(c, next).0.norm() >= p.norm() {
            break;
        }
        z = next;
    }
    z
}

/// The four roots by Ferrari's closed form with Newton polishing (see the [module docs](self)).
pub fn ferrari(c: &[f64; 5]) -> [C64; 4] {
    let (b, cc, d, e) = (c[3] / c[4], c[2] / c[4], c[1] / c[4], c[0] / c[4]);
    // x = y - b/4: y^4 + p y^2 + q y + r.
    let b2 = b * b;
    let p = cc - 0.375 * b2;
    let q = d - 0.5 * b * cc + 0.125 * b2 * b;
    let r = e - 0.25 * b * d + 0.0625 * b2 * cc - 3.0 / 256.0 * b2 * b2;
    let shift = -0.25 * b;
    let ys: [C64; 4] = {
        // Resolvent: m^3 + p m^2 + (p^2/4 - r) m - q^2/8 = 0, m > 0 when q != 0.
        let m = if q != 0.0 { cubic_largest(p, 0.25 * p * p - r, -0.125 * q * q) } else { 0.0 };
        if m > 0.0 {
            let s = (2.0 * m).sqrt();
            let [y1, y2] = quadratic(-s, 0.5 * p + m + q / (2.0 * s));
            let [y3, y4] = quadratic(s, 0.5 * p + m - q / (2.0 * s));
            [y1, y2, y3, y4]
        } else {
            // Biquadratic: w = y^2, w^2 + p w + r = 0.
            let [w1, w2] = quadratic(p, r);
            let (s1, s2) = (w1.sqrt(), w2.sqrt());
            [s1, -s1, s2, -s2]
        }
    };
    ys.map(|y| polish(c, y + shift))
}

/// The four roots as eigenvalues of the companion matrix; `None` if the Schur decomposition
/// does not converge within [`crate::numerics::eigen::MAX_SCHUR_ITERATIONS`].
pub fn companion(c: &[f64; 5]) -> Option<[C64; 4]> {
    let mut a = Matrix4::zeros();
    for i in 0..3 {
        a[(i + 1, i)] = 1.0;
    }
    for i in 0..4 {
        a[(i, 3)] = -c[i] / c[4];
    }
    let ev = crate::numerics::eigen::eigenvalues4(&a)?;
    Some(ev.map(|e| C64::new(e.re, e.im)))
}

/// Starting points of Aberth's iteration: a circle about the roots' centroid, of radius
/// $|p(\text{centroid})/c_4|^{1/4}$ (at least $10^{-3}$ of the centroid's size, to stay off it).
fn aberth_start(c: &[f64; 5]) -> [C64; 4] {
    let centre = -c[3] / (4.0 * c[4]);
    let (pc, _) = horner2(c, C64::new(centre, 0.0));
    let mut rho = (pc.norm() / c[4].abs()).powf(0.25);
    if rho.is_nan() || rho <= 1e-3 * centre.abs() || !rho.is_finite() {
        rho = 1e-3 * centre.abs().max(1.0);
    }
    std::array::from_fn(|k| {
        let angle = 0.4 + std::f64::consts::FRAC_PI_2 * k as f64;
        C64::new(centre + rho * angle.cos(), rho * angle.sin())
    })
}

/// Aberth–Ehrlich iteration with the Newton ratio `ratio(z) = p(z)/p'(z)`; stops when every
/// correction is below the roots' resolution twice in a row, or after 500 sweeps.
fn aberth_with(c: &[f64; 5], ratio: impl Fn(C64) -> Option<C64>) -> [C64; 4] {
    let mut z = aberth_start(c);
    let mut quiet = 0;
    for _ in 0..500 {
        let mut done = true;
        for k in 0..4 {
            let Some(n) = ratio(z[k]) else { continue };
            let mut sum = C64::new(0.0, 0.0);
            for j in 0..4 {
                if j != k {
                    sum += (z[k] - z[j]).inv();
                }
            }
            let w = n / (C64::new(1.0, 0.0) - n * sum);
            if w.is_finite() {
                z[k] -= w;
                if w.norm() > 4.0 * f64::EPSILON * z[k].norm() {
                    done = false;
                }
            }
        }
        quiet = if done { quiet + 1 } else { 0 };
        if quiet >= 2 {
            break;
        }
    }
    z
}

/// The four roots by Aberth's iteration in `f64`.
pub fn aberth(c: &[f64; 5]) -> [C64; 4] {
    aberth_with(c, |z| {
        let (p, d) = horner2(c, z);
        (p.norm() != 0.0).then(|| p / d)
    })
}

/// $p(z)$ and $p'(z)$ by a compensated Horner scheme: the accumulators are double-double
/// complex numbers, every product and sum an error-free transformation.
fn horner2_compensated(c: &[f64; 5], z: C64) -> (C64, C64) {
    let (zr, zi) = (Dd::from(z.re), Dd::from(z.im));
    let (mut pr, mut pi) = (Dd::from(c[4]), Dd::from(0.0));
    let (mut dr, mut di) = (Dd::from(0.0), Dd::from(0.0));
    for k in (0..4).rev() {
        let ndr = dr * zr - di * zi + pr;
        let ndi = dr * zi + di * zr + pi;
        dr = ndr;
        di = ndi;
        let npr = pr * zr - pi * zi + Dd::from(c[k]);
        let npi = pr * zi + pi * zr;
        pr = npr;
        pi = npi;
    }
    (C64::new(pr.to_f64(), pi.to_f64()), C64::new(dr.to_f64(), di.to_f64()))
}

/// The four roots by Aberth's iteration with compensated evaluation of $p$ and $p'$.
pub fn aberth_compensated(c: &[f64; 5]) -> [C64; 4] {
    aberth_with(c, |z| {
        let (p, d) = horner2_compensated(c, z);
        (p.norm() != 0.0).then(|| p / d)
    })
}

/// The moduli of the four roots, largest first, by root squaring (Carvallo's method of n° 14).
///
/// The polynomial is squared ([`crate::numerics::graeffe::graeffe_step`], rescaled to a unit
/// leading coefficient after each step) until its coefficients span 250 decades or ten steps
/// are done. A coefficient whose value after the last step is within 1 % of the square of its
/// value before is *regular* and gives a modulus ratio; a pair of roots of equal modulus (a
/// complex pair) makes its middle coefficient irregular, and both get the geometric mean.
/// The method cannot separate roots of nearly equal modulus: clustered roots come out wrong.
pub fn graeffe_moduli(c: &[f64; 5]) -> [f64; 4] {
    let mut a: Vec<f64> = c.iter().rev().copied().collect();
    let mut prev = a.clone();
    let mut steps = 0;
    while steps < 10 {
        let mut next = crate::numerics::graeffe::graeffe_step(&a);
        let lead = next[0];
        next.iter_mut().for_each(|x| *x /= lead);
        let span = next
            .iter()
            .filter(|x| **x != 0.0)
            .map(|x| x.abs().log10())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), l| (lo.min(l), hi.max(l)));
        if !next.iter().all(|x| x.is_finite()) || span.1 - span.0 > 250.0 {
            break;
        }
        prev = a;
        a = next;
        steps += 1;
    }
    let scale = 1.0 / 2f64.powi(steps);
    let regular = |j: usize| {
        let sq = prev[j] * prev[j] / (prev[0] * prev[0]);
        a[j] > 0.0 && sq > 0.0 && ((a[j] / sq) - 1.0).abs() < 0.01
    };
    let mut out = [0.0; 4];
    let mut j = 1;
    while j <= 4 {
        if j < 4 && !regular(j) {
            let m = (a[j + 1] / a[j - 1]).abs().powf(0.5 * scale);
            out[j - 1] = m;
            out[j] = m;
            j += 2;
        } else {
            out[j - 1] = (a[j] / a[j - 1]).abs().powf(scale);
            j += 1;
        }
    }
    out
}

/// The largest relative error $\max_i |z_i - w_{\pi(i)}| / \max(|w_{\pi(i)}|, \varepsilon\rho)$
/// over the best matching $\pi$ of computed roots `got` to reference roots `want` (all 24
/// permutations), $\rho$ the largest reference modulus: a root smaller than $\varepsilon\rho$
/// (such as the root near zero at the capsize speed) is measured relative to $\varepsilon\rho$,
/// the resolution any method has there.
pub fn max_rel_error(got: &[C64; 4], want: &[C64; 4]) -> f64 {
    let floor = f64::EPSILON * want.iter().map(|z| z.norm()).fold(0.0, f64::max);
    permutations()
        .iter()
        .map(|p| {
            (0..4)
                .map(|i| {
                    (got[i] - want[p[i]]).norm()
                        / want[p[i]].norm().max(floor).max(f64::MIN_POSITIVE)
                })
                .fold(0.0, f64::max)
        })
        .fold(f64::INFINITY, f64::min)
}

/// The largest relative error of moduli sorted in decreasing order against the reference
/// roots' moduli (with the floor of [`max_rel_error`]).
pub fn max_rel_error_moduli(got: &[f64; 4], want: &[C64; 4]) -> f64 {
    let mut g = *got;
    let mut w = want.map(|z| z.norm());
    g.sort_by(|a, b| b.total_cmp(a));
    w.sort_by(|a, b| b.total_cmp(a));
    let floor = f64::EPSILON * w[0];
    (0..4).map(|i| (g[i] - w[i]).abs() / w[i].max(floor).max(f64::MIN_POSITIVE)).fold(0.0, f64::max)
}

fn permutations() -> Vec<[usize; 4]> {
    let mut out = Vec::with_capacity(24);
    for a in 0..4 {
        for b in 0..4 {
            for c in 0..4 {
                for d in 0..4 {
                    let p = [a, b, c, d];
                    if (0..4).all(|i| (0..4).filter(|&j| p[j] == i).count() == 1) {
                        out.push(p);
                    }
                }
            }
        }
    }
    out
}

const RM: RoundingMode = RoundingMode::ToEven;

/// A complex number of `BigFloat`s.
#[derive(Clone, Debug)]
struct Cbig {
    re: BigFloat,
    im: BigFloat,
}

impl Cbig {
    fn from(z: C64, p: usize) -> Cbig {
        Cbig { re: carvallo_ir::hp::from_f64(z.re, p), im: carvallo_ir::hp::from_f64(z.im, p) }
    }
    fn add(&self, o: &Cbig, p: usize) -> Cbig {
        Cbig { re: self.re.add(&o.re, p, RM), im: self.im.add(&o.im, p, RM) }
    }
    fn sub(&self, o: &Cbig, p: usize) -> Cbig {
        Cbig { re: self.re.sub(&o.re, p, RM), im: self.im.sub(&o.im, p, RM) }
    }
    fn mul(&self, o: &Cbig, p: usize) -> Cbig {
        let re = self.re.mul(&o.re, p, RM).sub(&self.im.mul(&o.im, p, RM), p, RM);
        let im = self.re.mul(&o.im, p, RM).add(&self.im.mul(&o.re, p, RM), p, RM);
        Cbig { re, im }
    }
    fn div(&self, o: &Cbig, p: usize) -> Cbig {
        let den = o.re.mul(&o.re, p, RM).add(&o.im.mul(&o.im, p, RM), p, RM);
        let re = self.re.mul(&o.re, p, RM).add(&self.im.mul(&o.im, p, RM), p, RM);
        let im = self.im.mul(&o.re, p, RM).sub(&self.re.mul(&o.im, p, RM), p, RM);
        Cbig { re: re.div(&den, p, RM), im: im.div(&den, p, RM) }
    }
    fn to_c64(&self) -> C64 {
        C64::new(carvallo_ir::hp::to_f64(&self.re), carvallo_ir::hp::to_f64(&self.im))
    }
    /// $|z|$ rounded to `f64` (enough for convergence tests).
    fn norm_f64(&self) -> f64 {
        self.to_c64().norm()
    }
}

/// The roots of the `f64` polynomial `c`, exact to far below `f64` resolution: Aberth's
/// iteration carried out in `bits`-bit arithmetic from the compensated `f64` roots, until every
/// correction is below $2^{-(bits-20)}$ of its root (at most 200 sweeps). Returns the roots
/// rounded to `f64` and the largest relative size of the last corrections.
pub fn reference_roots(c: &[f64; 5], bits: usize) -> ([C64; 4], f64) {
    let p = bits;
    let coef: Vec<Cbig> = c.iter().map(|&x| Cbig::from(C64::new(x, 0.0), p)).collect();
    let mut z: Vec<Cbig> = aberth_compensated(c).iter().map(|&r| Cbig::from(r, p)).collect();
    let one = Cbig::from(C64::new(1.0, 0.0), p);
    let tol = 2f64.powi(-(bits as i32 - 20));
    let mut last = f64::INFINITY;
    for _ in 0..200 {
        last = 0.0;
        for k in 0..4 {
            let mut pv = coef[4].clone();
            let mut dv = Cbig::from(C64::new(0.0, 0.0), p);
            for j in (0..4).rev() {
                dv = dv.mul(&z[k], p).add(&pv, p);
                pv = pv.mul(&z[k], p).add(&coef[j], p);
            }
            if pv.norm_f64() == 0.0 {
                continue;
            }
            let n = pv.div(&dv, p);
            let mut sum = Cbig::from(C64::new(0.0, 0.0), p);
            for j in 0..4 {
                if j != k {
                    sum = sum.add(&one.div(&z[k].sub(&z[j], p), p), p);
                }
            }
            let w = n.div(&one.sub(&n.mul(&sum, p), p), p);
            z[k] = z[k].sub(&w, p);
            last = last.max(w.norm_f64() / z[k].norm_f64().max(f64::MIN_POSITIVE));
        }
        if last < tol {
            break;
        }
    }
    ([0, 1, 2, 3].map(|k| z[k].to_c64()), last)
}

/// One test polynomial.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// A short name.
    pub name: &'static str,
    /// Coefficients, lowest degree first.
    pub coeffs: [f64; 5],
}

/// The coefficients of $\prod (x - r_i)$ for real `roots`, rounded to `f64`.
fn from_roots(roots: [f64; 4]) -> [f64; 5] {
    let mut c = [1.0, 0.0, 0.0, 0.0, 0.0];
    let mut deg = 0;
    for r in roots {
        deg += 1;
        for k in (0..=deg).rev() {
            let lower = if k > 0 { c[k - 1] } else { 0.0 };
            c[k] = lower - r * if k < deg { c[k] } else { 0.0 };
        }
    }
    c
}

/// The product of two quadratics (coefficients lowest first).
fn mul2(a: [f64; 3], b: [f64; 3]) -> [f64; 5] {
    let mut c = [0.0; 5];
    for i in 0..3 {
        for j in 0..3 {
            c[i + j] += a[i] * b[j];
        }
    }
    c
}

/// The polynomial cases of the hard suite (see the [module docs](self)): clustered roots,
/// spread magnitudes, near-double roots and $x^4 + 1$. `carvallo bench` adds the benchmark
/// bicycle's $a_0, \dots, a_4$ at its weave, capsize and bifurcation speeds.
pub fn polynomial_suite() -> Vec<Case> {
    vec![
        Case { name: "well separated real", coeffs: from_roots([-3.0, -1.0, 0.5, 2.0]) },
        Case {
            name: "clustered 2, 2.001, 2.002, 2.003",
            coeffs: from_roots([2.0, 2.001, 2.002, 2.003]),
        },
        Case { name: "spread 1e-4, -1, 1e2, 1e5", coeffs: from_roots([1e-4, -1.0, 1e2, 1e5]) },
        Case {
            name: "near-double 1, 1 + 1e-7 and x^2 + x + 1",
            coeffs: mul2([1.0 + 1e-7, -(2.0 + 1e-7), 1.0], [1.0, 1.0, 1.0]),
        },
        Case { name: "complex pairs (x^2+1)(x^2+2x+5)", coeffs: [5.0, 2.0, 6.0, 2.0, 1.0] },
        Case { name: "x^4 + 1", coeffs: [1.0, 0.0, 0.0, 0.0, 1.0] },
    ]
}
