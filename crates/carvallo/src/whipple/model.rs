//! The linearised Carvallo–Whipple bicycle of one parameter set ([`Whipple`]): its matrices,
//! characteristic polynomial, eigenvalues, Hurwitz functions, stable speed range and
//! weave–capsize bifurcation.
//!
//! Stability (Routh–Hurwitz for $a_4 s^4 + a_3 s^3 + a_2 s^2 + a_1 s + a_0$ with $a_4 > 0$):
//! all $a_i > 0$ and $H_3 = a_1(a_2 a_3 - a_1 a_4) - a_0 a_3^2 > 0$. The coefficients are
//! polynomials in $v$ whose own coefficients come from the matrices; in $u = v^2$ every
//! Hurwitz function has degree at most two, so [`super::stability::hurwitz_window`] finds every
//! boundary of the stable range in closed form.

use nalgebra::Matrix4;

use super::design::BicycleDesign;
use super::matrices::{char_poly_scene, matrices_scene, state_matrix, Matrices};
use super::params::{WhippleError, WhippleParams, PARAM_NAMES};
use super::stability::{hurwitz_window_polished, StabilityWindow};
use crate::numerics::eigen::{eigenvalues4, Eigenvalue};
use crate::numerics::mat2::{det, mix};

fn horner(c: &[f64], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, k| acc * x + k)
}

fn poly_deriv(a: &[f64]) -> Vec<f64> {
    a.iter().enumerate().skip(1).map(|(i, x)| i as f64 * x).collect()
}

/// The linearised Carvallo–Whipple bicycle for one parameter set.
#[derive(Clone, Debug, PartialEq)]
pub struct Whipple {
    params: WhippleParams,
    matrices: Matrices,
}

impl Whipple {
    /// Evaluates the matrices for `params`.
    pub fn new(params: WhippleParams) -> Whipple {
        // The values with a zero wheel radius taken to its limit (the two-mass-skate).
        let values = params.evaluated();
        let n = matrices_scene::Args::LEN;
        let names = matrices_scene::PARAMS;
        let at = |name: &str| {
            PARAM_NAMES.iter().position(|k| *k == name).map_or(f64::NAN, |i| values[i])
        };
        let arr: [f64; matrices_scene::Args::LEN] =
            std::array::from_fn(|i| if i < n { at(names[i]) } else { f64::NAN });
        let o = matrices_scene::eval(&matrices_scene::Args::from_array(arr));
        let matrices = Matrices {
            m: [[o.m11, o.m12], [o.m21, o.m22]],
            c1: [[o.c1_11, o.c1_12], [o.c1_21, o.c1_22]],
            k0: [[o.k0_11, o.k0_12], [o.k0_21, o.k0_22]],
            k2: [[o.k2_11, o.k2_12], [o.k2_21, o.k2_22]],
        };
        Whipple { params, matrices }
    }

    /// The bicycle of `params` with the matrices `matrices` evaluated elsewhere, instead of by
    /// the generated evaluator (the concordance report reads them through its perturbation
    /// layer, so that a perturbed generated program reaches the characteristic speeds).
    pub fn with_matrices(params: WhippleParams, matrices: Matrices) -> Whipple {
        Whipple { params, matrices }
    }

    /// Validates `design` ([`WhippleParams::from_design`]) and evaluates the matrices.
    ///
    /// # Errors
    /// [`WhippleError`] naming the benchmark key of the field at fault.
    pub fn from_design(design: BicycleDesign) -> Result<Whipple, WhippleError> {
        WhippleParams::from_design(design).map(Whipple::new)
    }

    /// The parameters by name.
    pub fn design(&self) -> BicycleDesign {
        self.params.design()
    }

    /// The parameters.
    pub fn params(&self) -> &WhippleParams {
        &self.params
    }

    /// $M$, $C_1$, $K_0$, $K_2$.
    pub fn matrices(&self) -> Matrices {
        self.matrices
    }

    /// The coefficients $[a_0, \dots, a_4]$ of $\det(M s^2 + v C_1 s + g K_0 + v^2 K_2)$ at speed
    /// `v`, from the generated evaluator.
    pub fn char_poly(&self, v: f64) -> [f64; 5] {
        let names = char_poly_scene::PARAMS;
        let np = names.len();
        let values = self.params.evaluated();
        let at = |name: &str| {
            PARAM_NAMES.iter().position(|k| *k == name).map_or(f64::NAN, |i| values[i])
        };
        let arr: [f64; char_poly_scene::Args::LEN] =
            std::array::from_fn(|i| if i < np { at(names[i]) } else { v });
        let o = char_poly_scene::eval(&char_poly_scene::Args::from_array(arr));
        [o.a0, o.a1, o.a2, o.a3, o.a4]
    }

    /// The coefficients $a_0, \dots, a_4$ as polynomials in $v$ (`[k][j]` is the coefficient of
    /// $v^j$ in $a_k$), computed from the matrices.
    pub fn char_poly_in_v(&self) -> [Vec<f64>; 5] {
        let Matrices { m, c1, k0, k2 } = self.matrices;
        let g = self.params.value("g");
        [
            vec![g * g * det(&k0), 0.0, g * mix(&k0, &k2), 0.0, det(&k2)],
            vec![0.0, g * mix(&c1, &k0), 0.0, mix(&c1, &k2)],
            vec![g * mix(&m, &k0), 0.0, mix(&m, &k2) + det(&c1)],
            vec![0.0, mix(&m, &c1)],
            vec![det(&m)],
        ]
    }

    /// The state matrix of $(\varphi, \delta, \varphi', \delta')$ at speed `v`.
    pub fn state_matrix(&self, v: f64) -> Matrix4<f64> {
        state_matrix(&self.matrices, self.params.value("g"), v)
    }

    /// The four eigenvalues at speed `v`, sorted by real part then imaginary part; empty if the
    /// Schur decomposition does not converge within
    /// [`MAX_SCHUR_ITERATIONS`](crate::numerics::eigen::MAX_SCHUR_ITERATIONS) (never seen for a
    /// bicycle).
    pub fn eigenvalues(&self, v: f64) -> Vec<Eigenvalue> {
        let mut ev: Vec<Eigenvalue> =
            eigenvalues4(&self.state_matrix(v)).map_or(Vec::new(), |e| e.to_vec());
        ev.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
        ev
    }

    /// $H_3 = a_1(a_2 a_3 - a_1 a_4) - a_0 a_3^2$ at speed `v`, from the coefficient values.
    pub fn hurwitz(&self, v: f64) -> f64 {
        let a = self.char_poly_in_v().map(|p| horner(&p, v));
        a[1] * (a[2] * a[3] - a[1] * a[4]) - a[0] * a[3] * a[3]
    }

    /// The capsize speed in closed form: the lowest positive root of
    /// $a_0 = g^2\det K_0 + g v^2 m(K_0, K_2) + v^4 \det K_2$, a quadratic in $v^2$.
    pub fn capsize_speed(&self) -> Option<f64> {
        self.stability_window().capsize_speed
    }

    /// The weave speed: the lowest positive speed where $H_3$ changes sign from negative to
    /// positive while $a_1/a_3 > 0$ (a pair of eigenvalues $\pm i\omega$, $\omega^2 = a_1/a_3$,
    /// crosses the imaginary axis; roots of $H_3$ where two real eigenvalues $\pm r$ pass each
    /// other are not weave speeds), see [`crate::whipple::stability`].
    pub fn weave_speed(&self) -> Option<f64> {
        self.stability_window().weave_speed
    }

    /// The weave–capsize bifurcation speed and the double real root there: the lowest positive
    /// speed at which two real eigenvalues merge into a complex pair, located on a speed grid by
    /// the eigenvalues and refined by Newton's method on $P(s, v) = \partial_s P(s, v) = 0$.
    /// `None` if no real pair turns complex below the weave speed (or 10 m/s without one).
    pub fn bifurcation(&self) -> Option<(f64, f64)> {
        let vmax = self.weave_speed().unwrap_or(10.0);
        let n = 2000;
        let count_real = |v: f64| self.eigenvalues(v).iter().filter(|e| e.im == 0.0).count();
        let mut prev_v = 0.0;
        let mut prev_n = count_real(0.0);
        for i in 1..=n {
            let v = vmax * i as f64 / n as f64;
            let k = count_real(v);
            if k < prev_n {
                // The merging pair: the two closest real eigenvalues at prev_v.
                let reals: Vec<f64> =
                    self.eigenvalues(prev_v).iter().filter(|e| e.im == 0.0).map(|e| e.re).collect();
                let mut best = (f64::INFINITY, 0.0);
                for i in 0..reals.len() {
                    for j in i + 1..reals.len() {
                        let d = (reals[i] - reals[j]).abs();
                        if d < best.0 {
                            best = (d, 0.5 * (reals[i] + reals[j]));
                        }
                    }
                }
                return self.refine_double_root(best.1, 0.5 * (prev_v + v));
            }
            prev_v = v;
            prev_n = k;
        }
        None
    }

    fn refine_double_root(&self, mut s: f64, mut v: f64) -> Option<(f64, f64)> {
        let a = self.char_poly_in_v();
        let da: Vec<Vec<f64>> = a.iter().map(|p| poly_deriv(p)).collect();
        // P = sum a_k(v) s^k; derivatives in s and v.
        let eval = |s: f64, v: f64| {
            let (mut p, mut ps, mut pss, mut pv, mut psv) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for k in 0..5 {
                let ak = horner(&a[k], v);
                let dak = horner(&da[k], v);
                let kf = k as f64;
                p += ak * s.powi(k as i32);
                pv += dak * s.powi(k as i32);
                if k >= 1 {
                    ps += kf * ak * s.powi(k as i32 - 1);
                    psv += kf * dak * s.powi(k as i32 - 1);
                }
                if k >= 2 {
                    pss += kf * (kf - 1.0) * ak * s.powi(k as i32 - 2);
                }
            }
            (p, ps, pss, pv, psv)
        };
        for _ in 0..100 {
            let (p, ps, pss, pv, psv) = eval(s, v);
            // Jacobian of (P, P_s) in (s, v).
            let det = ps * psv - pv * pss;
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let ds = (p * psv - pv * ps) / det;
            let dv = (ps * ps - pss * p) / det;
            s -= ds;
            v -= dv;
            if ds.abs() <= 1e-16 * s.abs() && dv.abs() <= 1e-16 * v.abs() {
                break;
            }
        }
        (v.is_finite() && s.is_finite()).then_some((v, s))
    }

    /// The stable speed range and the weave and capsize speeds, by the closed-form Hurwitz
    /// route with double-double polishing, [`hurwitz_window_polished`] (about a microsecond
    /// from the matrices).
    pub fn stability_window(&self) -> StabilityWindow {
        hurwitz_window_polished(&self.matrices, self.params.value("g"))
    }
}
