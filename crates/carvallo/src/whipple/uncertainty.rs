//! How the stated uncertainties of a bicycle's parameters carry over to its weave and capsize
//! speeds and to its eigenvalues: first order, exactly differentiated, and Monte Carlo.
//!
//! # First order
//!
//! [`speed_gradients`] differentiates the weave and capsize speeds with respect to the 26
//! parameters: forward-mode dual numbers ([`carvallo_ir::dual`]) through the generated program
//! `generated/whipple.ir` give the matrices $M$, $C_1$, $K_0$, $K_2$ with their exact
//! derivatives; the same arithmetic gives the Hurwitz functions' coefficients in $u = v^2$
//! ([`crate::whipple::stability::HurwitzPolys`]). A speed is $v = \sqrt u$ for a simple root $u$ of
//! $F(u; p) = 0$ ($F = h$, the reduced Hurwitz determinant, for the weave speed; $F = a_0$ for
//! the capsize speed), so by the implicit function theorem
//! $$\frac{\partial v}{\partial p_i} = -\frac{1}{2v}\,
//!   \frac{\partial F/\partial p_i}{\partial F/\partial u}.$$
//! With independent parameters of standard deviations $\sigma_i$ the first-order standard
//! deviation of a speed is $\sqrt{\sum_i (\partial v/\partial p_i)^2 \sigma_i^2}$
//! ([`SpeedGradient::std`]).
//!
//! # Monte Carlo
//!
//! [`monte_carlo`] draws `samples` parameter sets, each parameter independently normal with its
//! stated mean and standard deviation (Box–Muller on a seeded SplitMix64), and computes their
//! windows with [`windows_unchecked`] (the matrices' generated evaluator and the closed-form
//! Hurwitz route, in parallel). Samples are not validated: the linearised equations are defined
//! for any parameter values, and a sample that breaks a triangle inequality of the moments of
//! inertia (possible near a thin disc, `IFyy` ≈ 2 `IFxx`) is counted in
//! [`MonteCarlo::invalid`], not dropped, so that both routes describe the same distribution.
//! Around a nominal that breaks an inequality itself (a measured frame), a sample is counted
//! only when it breaks one by more than the nominal does ([`TriangleSlack::admitting`]).
//! [`eigenvalue_bands`] does the same for the real parts of the eigenvalues on a speed grid.

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use carvallo_ir::dual::{self, Dual};
use carvallo_ir::Program;

use super::matrices::{matrices_of, scene_index};
use crate::numerics::mat2::{det, mix};
use crate::numerics::rng::SplitMix64;
use crate::whipple::parameter_text::UncertainParams;
use crate::whipple::{StabilityWindow, TriangleSlack, WhippleParams, PARAM_NAMES};

/// The generated program of the linearised bicycle (matrices and characteristic polynomial).
pub const WHIPPLE_IR: &str = crate::artifacts::WHIPPLE.ir;

/// The number of parameters.
const N: usize = 26;

type D = Dual<N>;

/// A speed and its derivatives with respect to the parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct SpeedGradient {
    /// The speed (m/s).
    pub speed: f64,
    /// $\partial v/\partial p_i$ in the order of [`PARAM_NAMES`].
    pub grad: [f64; 26],
}

impl SpeedGradient {
    /// The first-order standard deviation $\sqrt{\sum_i (\partial v/\partial p_i)^2\sigma_i^2}$
    /// for independent parameters of standard deviations `sigma` (a parameter of zero
    /// standard deviation adds nothing, also where its derivative is infinite).
    pub fn std(&self, sigma: &[f64; 26]) -> f64 {
        self.grad
            .iter()
            .zip(sigma)
            .filter(|(_, s)| **s != 0.0)
            .map(|(g, s)| (g * s) * (g * s))
            .sum::<f64>()
            .sqrt()
    }
}

/// The weave and capsize speeds with their derivatives.
#[derive(Clone, Debug, PartialEq)]
pub struct SpeedGradients {
    /// The weave speed's, `None` if the bicycle has none (see [`StabilityWindow`]).
    pub weave: Option<SpeedGradient>,
    /// The capsize speed's, `None` if the bicycle has none.
    pub capsize: Option<SpeedGradient>,
}

/// The matrices of `params` with their derivatives, from the generated program.
fn dual_matrices(params: &WhippleParams) -> [[[D; 2]; 2]; 4] {
    let names: Vec<String> = ["m", "c1_", "k0_", "k2_"]
        .iter()
        .flat_map(|p| ["11", "12", "21", "22"].map(|rc| format!("{p}{rc}")))
        .collect();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let program = Program::parse(WHIPPLE_IR)
        .expect("generated/whipple.ir parses")
        .select_outputs(&names)
        .expect("generated/whipple.ir has the matrices");
    let args: Vec<D> = program
        .params
        .iter()
        .map(|name| {
            let k = PARAM_NAMES.iter().position(|n| n == name).expect("a benchmark parameter");
            Dual::variable(params.evaluated()[k], k)
        })
        .collect();
    // The matrices depend on no input (the selection pruned them).
    let speed = vec![Dual::constant(0.0); program.inputs.len()];
    let out = dual::eval(&program, &args, &speed).expect("the program evaluates");
    let get = |name: &str| {
        let k = program.outputs.iter().position(|o| o.name == name).expect("a matrix entry");
        out[k]
    };
    let mat = |p: &str| {
        [
            [get(&format!("{p}11")), get(&format!("{p}12"))],
            [get(&format!("{p}21")), get(&format!("{p}22"))],
        ]
    };
    [mat("m"), mat("c1_"), mat("k0_"), mat("k2_")]
}

/// $\partial v/\partial p$ at the simple root $u = v^2$ of $c_0 + c_1 u + c_2 u^2$ (dual
/// coefficients), by the implicit function theorem.
fn root_gradient(c: [D; 3], v: f64) -> SpeedGradient {
    let u = v * v;
    let f_u = c[1].value + 2.0 * c[2].value * u;
    let grad = std::array::from_fn(|i| {
        let f_p = c[0].grad[i] + c[1].grad[i] * u + c[2].grad[i] * u * u;
        -f_p / f_u / (2.0 * v)
    });
    SpeedGradient { speed: v, grad }
}

/// The weave and capsize speeds of `params` (as [`crate::whipple::Whipple::stability_window`]
/// gives them) and their exact first derivatives with respect to the 26 parameters (see the
/// [module docs](self)). For a wheel of zero radius (the two-mass-skate) the derivative with
/// respect to its spin inertia is unbounded and given as an infinity of its sign.
pub fn speed_gradients(params: &WhippleParams) -> SpeedGradients {
    let [m, c1, k0, k2] = dual_matrices(params);
    let g = Dual::variable(params.values()[3], 3);
    debug_assert_eq!(PARAM_NAMES[3], "g");
    // The coefficients of a0(u) and h(u), as in sweep::HurwitzPolys::new.
    let a0 = [g * g * det(&k0), g * mix(&k0, &k2), det(&k2)];
    let q = [g * mix(&c1, &k0), mix(&c1, &k2)];
    let r = [g * mix(&m, &k0), mix(&m, &k2) + det(&c1)];
    let b = mix(&m, &c1);
    let a4 = det(&m);
    let h = [
        q[0] * r[0] * b - q[0] * q[0] * a4 - a0[0] * b * b,
        (q[0] * r[1] + q[1] * r[0]) * b - (q[0] * q[1] * a4).scale(2.0) - a0[1] * b * b,
        q[1] * r[1] * b - q[1] * q[1] * a4 - a0[2] * b * b,
    ];
    let window = crate::whipple::Whipple::new(params.clone()).stability_window();
    // At a zero wheel radius the gyroscopic coupling I_yy/r has an unbounded derivative with
    // respect to the spin inertia: the evaluators' stand-in radius would give about 1e60.
    let unbounded = |mut g: SpeedGradient| {
        for (r, yy) in [(4, 7), (22, 25)] {
            if params.values()[r] == 0.0 && g.grad[yy] != 0.0 {
                g.grad[yy] = f64::INFINITY.copysign(g.grad[yy]);
            }
        }
        g
    };
    SpeedGradients {
        weave: window.weave_speed.map(|v| unbounded(root_gradient(h, v))),
        capsize: window.capsize_speed.map(|v| unbounded(root_gradient(a0, v))),
    }
}

/// The stability windows of many designs (rows of parameter values in the order of
/// [`PARAM_NAMES`]), in parallel, by the same route as
/// [`Whipple::stability_window`](crate::whipple::Whipple::stability_window) (closed-form
/// Hurwitz with double-double polishing), so that `windows_unchecked(&[*p.values()])[0]`
/// equals `Whipple::new(p).stability_window()`. The rows are not validated (see
/// [`windows`] for the checked version).
pub fn windows_unchecked(designs: &[[f64; 26]]) -> Vec<StabilityWindow> {
    let index = scene_index();
    designs
        .par_iter()
        .with_min_len(256)
        .map(|values| {
            crate::whipple::stability::hurwitz_window_polished(
                &matrices_of(values, &index),
                values[3],
            )
        })
        .collect()
}

/// [`windows_unchecked`] after validating every row with [`WhippleParams::from_values`].
///
/// # Errors
/// The index of the first invalid row and why it is invalid.
pub fn windows(
    designs: &[[f64; 26]],
) -> Result<Vec<StabilityWindow>, (usize, crate::whipple::WhippleError)> {
    for (i, d) in designs.iter().enumerate() {
        WhippleParams::from_values(*d).map_err(|e| (i, e))?;
    }
    Ok(windows_unchecked(designs))
}

/// `samples` parameter rows drawn independently normal about `u.params` with the standard
/// deviations `u.sigma` (a parameter with zero uncertainty keeps its value), from `seed`.
pub fn sample_designs(u: &UncertainParams, samples: usize, seed: u64) -> Vec<[f64; 26]> {
    let mut rng = SplitMix64(seed);
    (0..samples).map(|_| draw(u, &mut rng)).collect()
}

/// The next row of [`sample_designs`] drawn from `rng`.
fn draw(u: &UncertainParams, rng: &mut SplitMix64) -> [f64; 26] {
    let mut row = *u.params.values();
    let mut k = 0;
    while k < N {
        let (z0, z1) = rng.normal_pair();
        row[k] += u.sigma[k] * z0;
        if k + 1 < N {
            row[k + 1] += u.sigma[k + 1] * z1;
        }
        k += 2;
    }
    row
}

/// Mean and standard deviation (with the $n - 1$ divisor) of the finite values of `x`, and
/// their count.
pub fn mean_std(x: &[f64]) -> (f64, f64, usize) {
    let f: Vec<f64> = x.iter().copied().filter(|v| v.is_finite()).collect();
    let n = f.len();
    if n == 0 {
        return (f64::NAN, f64::NAN, 0);
    }
    let mean = f.iter().sum::<f64>() / n as f64;
    let var = f.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n.max(2) - 1) as f64;
    (mean, var.sqrt(), n)
}

/// The weave and capsize speeds of a Monte Carlo sample.
#[derive(Clone, Debug, PartialEq)]
pub struct MonteCarlo {
    /// The weave speed of each sample (NaN where a sample has none).
    pub weave: Vec<f64>,
    /// The capsize speed of each sample (NaN where a sample has none).
    pub capsize: Vec<f64>,
    /// How many samples [`WhippleParams::from_values_within`] rejects with the slack that
    /// admits the nominal ([`TriangleSlack::admitting`]), kept all the same.
    pub invalid: usize,
}

/// The Monte Carlo propagation of `u`'s uncertainties to the weave and capsize speeds (see the
/// [module docs](self)).
pub fn monte_carlo(u: &UncertainParams, samples: usize, seed: u64) -> MonteCarlo {
    let never = AtomicBool::new(false);
    monte_carlo_until(u, samples, seed, &never).expect("never stopped")
}

/// Samples drawn and evaluated between two looks at the stop flag of [`monte_carlo_until`].
pub const MONTE_CARLO_BLOCK: usize = 1 << 14;

/// [`monte_carlo`] in blocks of [`MONTE_CARLO_BLOCK`] samples (the same draws in the same
/// order, so the same result), only one block's designs held at a time, reading `stop` before
/// every block: `None` once it is set (Ctrl-C in a caller).
pub fn monte_carlo_until(
    u: &UncertainParams,
    samples: usize,
    seed: u64,
    stop: &AtomicBool,
) -> Option<MonteCarlo> {
    let mut rng = SplitMix64(seed);
    let slack = TriangleSlack::admitting(&u.params);
    let mut out =
        MonteCarlo { weave: Vec::with_capacity(samples), capsize: Vec::new(), invalid: 0 };
    out.capsize.reserve_exact(samples);
    let mut done = 0;
    while done < samples {
        if stop.load(Ordering::Relaxed) {
            return None;
        }
        let n = MONTE_CARLO_BLOCK.min(samples - done);
        let designs: Vec<[f64; 26]> = (0..n).map(|_| draw(u, &mut rng)).collect();
        out.invalid += designs
            .iter()
            .filter(|d| WhippleParams::from_values_within(**d, &slack).is_err())
            .count();
        for w in windows_unchecked(&designs) {
            out.weave.push(w.weave_speed.unwrap_or(f64::NAN));
            out.capsize.push(w.capsize_speed.unwrap_or(f64::NAN));
        }
        done += n;
    }
    Some(out)
}

/// Quantile bands of the eigenvalues' real parts against speed.
#[derive(Clone, Debug, PartialEq)]
pub struct EigenBands {
    /// The speeds (m/s).
    pub speeds: Vec<f64>,
    /// The nominal bicycle's real parts at each speed, ascending.
    pub nominal: Vec<[f64; 4]>,
    /// The lower quantile of the `k`-th smallest real part at each speed.
    pub lower: Vec<[f64; 4]>,
    /// The upper quantile of the `k`-th smallest real part at each speed.
    pub upper: Vec<[f64; 4]>,
}

/// The `q` quantile of sorted data (linear interpolation between order statistics).
fn quantile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let x = q.clamp(0.0, 1.0) * (sorted.len() - 1) as f64;
    let (i, t) = (x.floor() as usize, x - x.floor());
    let j = (i + 1).min(sorted.len() - 1);
    sorted[i] + t * (sorted[j] - sorted[i])
}

/// The real parts of the eigenvalues at `speeds` for `samples` Monte Carlo designs of `u`
/// (seeded), sorted per design, and their `q_low` and `q_high` quantiles rank by rank (for a
/// 95 % band, 0.025 and 0.975). Designs whose Schur decomposition does not converge at a speed
/// are left out there.
pub fn eigenvalue_bands(
    u: &UncertainParams,
    speeds: &[f64],
    samples: usize,
    seed: u64,
    q_low: f64,
    q_high: f64,
) -> EigenBands {
    let never = AtomicBool::new(false);
    eigenvalue_bands_until(u, speeds, samples, seed, (q_low, q_high), &never)
        .expect("never stopped")
}

/// [`eigenvalue_bands`] reading `stop` before each design: `None` once it is set (Ctrl-C in a
/// caller), the quantiles `(q_low, q_high)`.
pub fn eigenvalue_bands_until(
    u: &UncertainParams,
    speeds: &[f64],
    samples: usize,
    seed: u64,
    (q_low, q_high): (f64, f64),
    stop: &AtomicBool,
) -> Option<EigenBands> {
    let designs = sample_designs(u, samples, seed);
    let index = scene_index();
    let real_parts = |values: &[f64; 26]| -> Vec<Option<[f64; 4]>> {
        let m = matrices_of(values, &index);
        speeds
            .iter()
            .map(|&v| {
                let a = crate::whipple::state_matrix(&m, values[3], v);
                crate::numerics::eigen::eigenvalues4(&a).map(|e| {
                    let mut re = e.map(|x| x.re);
                    re.sort_by(f64::total_cmp);
                    re
                })
            })
            .collect()
    };
    let per_design: Vec<Vec<Option<[f64; 4]>>> = designs
        .par_iter()
        .map(|d| if stop.load(Ordering::Relaxed) { Vec::new() } else { real_parts(d) })
        .collect();
    if stop.load(Ordering::Relaxed) {
        return None;
    }
    let nominal: Vec<[f64; 4]> =
        real_parts(u.params.values()).into_iter().map(|r| r.unwrap_or([f64::NAN; 4])).collect();
    let mut lower = Vec::with_capacity(speeds.len());
    let mut upper = Vec::with_capacity(speeds.len());
    for j in 0..speeds.len() {
        let mut lo = [0.0; 4];
        let mut hi = [0.0; 4];
        for k in 0..4 {
            let mut xs: Vec<f64> = per_design.iter().filter_map(|d| d[j].map(|r| r[k])).collect();
            xs.sort_by(f64::total_cmp);
            lo[k] = quantile(&xs, q_low);
            hi[k] = quantile(&xs, q_high);
        }
        lower.push(lo);
        upper.push(hi);
    }
    Some(EigenBands { speeds: speeds.to_vec(), nominal, lower, upper })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantiles_interpolate_between_order_statistics() {
        let x = [1.0, 2.0, 3.0, 4.0];
        assert_eq!(quantile(&x, 0.0), 1.0);
        assert_eq!(quantile(&x, 1.0), 4.0);
        assert_eq!(quantile(&x, 0.5), 2.5);
        assert!(quantile(&[], 0.5).is_nan());
    }

    #[test]
    fn the_sampler_is_standard_normal() {
        let mut rng = SplitMix64(7);
        let z: Vec<f64> = (0..50_000)
            .flat_map(|_| {
                let (a, b) = rng.normal_pair();
                [a, b]
            })
            .collect();
        let (mean, std, n) = mean_std(&z);
        assert_eq!(n, 100_000);
        // Standard errors: 1/sqrt(n) = 0.0032 for the mean, 1/sqrt(2n) = 0.0022 for the std.
        assert!(mean.abs() < 0.015, "{mean}");
        assert!((std - 1.0).abs() < 0.01, "{std}");
    }
}
