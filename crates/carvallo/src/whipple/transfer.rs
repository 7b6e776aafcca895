//! Transfer functions of the bicycle as a plant: from the roll torque $T_\varphi$ or the steer
//! torque $T_\delta$ to the lean $\varphi$, the steer $\delta$ or their rates, and their
//! frequency responses (Bode diagrams).
//!
//! With $P(s) = M s^2 + v C_1 s + g K_0 + v^2 K_2$ the equations from rest transform to
//! $P(s)\,q(s) = f(s)$, so the transfer function from input $j$ to the angle $q_i$ is
//!
//! $$G_{ij}(s) = \frac{N_{ij}(s)}{\det P(s)},\qquad N = \operatorname{adj} P(s),\qquad
//! \det P(s) = a_4 s^4 + a_3 s^3 + a_2 s^2 + a_1 s + a_0,$$
//!
//! and to the rate $\dot q_i$ it is $s\,G_{ij}(s)$. Both the numerators (`tf_{out}_{in}_{k}`,
//! coefficients of $s^k$, polynomials in $v$) and the characteristic polynomial are derived
//! symbolically (`codegen/src/derive/whipple/mod.rs`, the adjugate of $P$) and evaluated by
//! one generated [`scene!`](crate::scene) per input–output pair, which computes only what that
//! pair needs. The frequency response is $G(i\omega)$ in complex arithmetic; no matrix is
//! inverted. It is checked against $C(i\omega I - A)^{-1}B$ of the state space
//! ([`super::plant`]) by a complex LU solve in the tests.
//!
//! The phase is a function of $\omega$ alone, not of the grid it is evaluated on. With the
//! zeros $z_k$, the poles $p_k$ and the gain $K$ (the ratio of the leading coefficients),
//!
//! $$\arg G(i\omega) = \arg K + \sum_k \arg(i\omega - z_k) - \sum_k \arg(i\omega - p_k),$$
//!
//! each factor taken on its own branch continuous in $\omega$: $i\omega - z$ runs along the
//! vertical line $\operatorname{Re} = -\operatorname{Re} z$, so for a left-half-plane root the
//! principal argument, in $(-90°, 90°)$, is continuous, and for a right-half-plane root the branch
//! $[0°, 360°)$, in $(90°, 270°)$, is (the principal argument would jump by 360° at
//! $\omega = \operatorname{Im} z$: exactly the unstable weave). The sum is then shifted by the one
//! multiple of 360° that puts its limit as $\omega \to 0^+$ in $(-180°, 180°]$. The value itself
//! is the principal argument of $G(i\omega)$ computed directly, moved by the multiple of 360°
//! nearest to that sum: the roots choose the branch, they do not round the value. A root on the
//! imaginary axis (a pole exactly at the weave speed) is a true jump of 180°; the jump of 180° of
//! the low-frequency phase across the capsize speed (the real pole through the origin) is
//! physical too.

use std::fmt;
use std::str::FromStr;

use super::model::Whipple;
use super::params::WhippleParams;
use crate::numerics::quartic::{aberth_compensated, Complex};

crate::scene! {
    /// Numerator ($s^0, s^1, s^2$) and denominator ($a_0 \dots a_4$) of lean / roll torque.
    pub mod tf_roll_roll_scene {
        model: whipple,
        outputs: [tf_roll_roll_0, tf_roll_roll_1, tf_roll_roll_2, a0, a1, a2, a3, a4],
    }
    /// Numerator and denominator of lean / steer torque.
    pub mod tf_roll_steer_scene {
        model: whipple,
        outputs: [tf_roll_steer_0, tf_roll_steer_1, tf_roll_steer_2, a0, a1, a2, a3, a4],
    }
    /// Numerator and denominator of steer / roll torque.
    pub mod tf_steer_roll_scene {
        model: whipple,
        outputs: [tf_steer_roll_0, tf_steer_roll_1, tf_steer_roll_2, a0, a1, a2, a3, a4],
    }
    /// Numerator and denominator of steer / steer torque.
    pub mod tf_steer_steer_scene {
        model: whipple,
        outputs: [tf_steer_steer_0, tf_steer_steer_1, tf_steer_steer_2, a0, a1, a2, a3, a4],
    }
}

/// An input of the plant: a generalised force.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Input {
    /// The roll torque $T_\varphi$ in N m (acting between the ground and the rear frame).
    Roll,
    /// The steer torque $T_\delta$ in N m (acting between the rear and the front frame).
    Steer,
}

/// An output of the plant: a coordinate or its rate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Output {
    /// The lean (roll) angle $\varphi$ (rad).
    Roll,
    /// The steer angle $\delta$ (rad).
    Steer,
    /// The roll rate $\dot\varphi$ (rad/s).
    RollRate,
    /// The steer rate $\dot\delta$ (rad/s).
    SteerRate,
}

impl Input {
    /// Every input, in the order of the columns of $B$.
    pub const ALL: [Input; 2] = [Input::Roll, Input::Steer];

    /// The name on the command line and in Python: `roll` or `steer`.
    pub fn name(self) -> &'static str {
        match self {
            Input::Roll => "roll",
            Input::Steer => "steer",
        }
    }

    /// The column of $B$ (0 for the roll torque, 1 for the steer torque).
    pub fn index(self) -> usize {
        self as usize
    }
}

impl Output {
    /// Every output, in the order of the state $(\varphi, \delta, \dot\varphi, \dot\delta)$.
    pub const ALL: [Output; 4] = [Output::Roll, Output::Steer, Output::RollRate, Output::SteerRate];

    /// The name on the command line and in Python: `roll`, `steer`, `roll-rate`, `steer-rate`.
    pub fn name(self) -> &'static str {
        match self {
            Output::Roll => "roll",
            Output::Steer => "steer",
            Output::RollRate => "roll-rate",
            Output::SteerRate => "steer-rate",
        }
    }

    /// The row of the state (and of $C = I$).
    pub fn index(self) -> usize {
        self as usize
    }

    /// Whether it is a rate (its transfer function is $s$ times the angle's).
    pub fn is_rate(self) -> bool {
        matches!(self, Output::RollRate | Output::SteerRate)
    }
}

/// A name that is no input or output.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownSignal {
    /// What was given.
    pub name: String,
    /// The names allowed.
    pub expected: &'static str,
}

impl fmt::Display for UnknownSignal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown signal {:?}: expected one of {}", self.name, self.expected)
    }
}

impl std::error::Error for UnknownSignal {}

impl FromStr for Input {
    type Err = UnknownSignal;

    fn from_str(s: &str) -> Result<Input, UnknownSignal> {
        Input::ALL
            .into_iter()
            .find(|i| i.name() == s)
            .ok_or_else(|| UnknownSignal { name: s.to_string(), expected: "roll, steer" })
    }
}

impl FromStr for Output {
    type Err = UnknownSignal;

    fn from_str(s: &str) -> Result<Output, UnknownSignal> {
        Output::ALL.into_iter().find(|o| o.name() == s).ok_or_else(|| UnknownSignal {
            name: s.to_string(),
            expected: "roll, steer, roll-rate, steer-rate",
        })
    }
}

/// One transfer function at one speed: $G(s) = s^r (n_0 + n_1 s + n_2 s^2) / (a_0 + \dots +
/// a_4 s^4)$ with $r = 1$ for a rate output, else 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TransferFunction {
    /// The forward speed (m/s).
    pub speed: f64,
    /// The input.
    pub input: Input,
    /// The output.
    pub output: Output,
    /// $n_0, n_1, n_2$: the numerator of the angle (before the factor $s$ of a rate).
    pub numerator: [f64; 3],
    /// $a_0, \dots, a_4$: the characteristic polynomial.
    pub denominator: [f64; 5],
}

/// A complex number as (real, imaginary).
type C = (f64, f64);

/// $a/b$ by Smith's algorithm (no overflow for large $|b|$).
fn cdiv(a: C, b: C) -> C {
    if b.1.abs() <= b.0.abs() {
        let r = b.1 / b.0;
        let d = b.0 + b.1 * r;
        ((a.0 + a.1 * r) / d, (a.1 - a.0 * r) / d)
    } else {
        let r = b.0 / b.1;
        let d = b.0 * r + b.1;
        ((a.0 * r + a.1) / d, (a.1 * r - a.0) / d)
    }
}

/// $\sum_k c_k\, i^k w_k$ with the weights `w` (real and imaginary parts summed separately):
/// $\sum_k c_k (i\omega)^k$ for $w_k = \omega^k$.
fn at_i(c: &[f64], w: impl Fn(usize) -> f64) -> C {
    let (mut re, mut im) = (0.0, 0.0);
    for (k, x) in c.iter().enumerate() {
        let t = x * w(k);
        match k % 4 {
            0 => re += t,
            1 => im += t,
            2 => re -= t,
            _ => im -= t,
        }
    }
    (re, im)
}

impl TransferFunction {
    /// $G(i\omega)$ as (real, imaginary). Above $\omega = 1$ numerator and denominator are
    /// both divided by $(i\omega)^4$ (weights $\omega^{k-4}$), so that no power of a large
    /// $\omega$ overflows.
    pub fn at(&self, omega: f64) -> (f64, f64) {
        let n = self.numerator_with_rate();
        let d = &self.denominator;
        if omega.abs() <= 1.0 {
            let w = |k: usize| omega.powi(k as i32);
            cdiv(at_i(&n, w), at_i(d, w))
        } else {
            let x = 1.0 / omega;
            let w = |k: usize| x.powi(4 - k as i32);
            cdiv(at_i(&n, w), at_i(d, w))
        }
    }

    /// The zeros of $G$: the roots of the numerator (including the zero at the origin of a
    /// rate output), of the degree its nonzero leading coefficient gives.
    pub fn zeros(&self) -> Vec<Complex<f64>> {
        let n = self.numerator;
        let mut z = Vec::with_capacity(3);
        if self.output.is_rate() {
            z.push(Complex::new(0.0, 0.0));
        }
        if n[2] != 0.0 {
            let (b, c) = (n[1] / n[2], n[0] / n[2]);
            let disc = b * b - 4.0 * c;
            if disc >= 0.0 {
                // The larger-magnitude root without cancellation, the other from the product.
                let q = -0.5 * (b + b.signum() * disc.sqrt());
                z.push(Complex::new(q, 0.0));
                z.push(Complex::new(if q != 0.0 { c / q } else { 0.0 }, 0.0));
            } else {
                let im = 0.5 * (-disc).sqrt();
                z.push(Complex::new(-0.5 * b, im));
                z.push(Complex::new(-0.5 * b, -im));
            }
        } else if n[1] != 0.0 {
            z.push(Complex::new(-n[0] / n[1], 0.0));
        }
        z
    }

    /// The poles of $G$: the roots of the characteristic polynomial (the eigenvalues of $A$),
    /// by Aberth's iteration with compensated evaluation
    /// ([`aberth_compensated`]).
    pub fn poles(&self) -> [Complex<f64>; 4] {
        aberth_compensated(&self.denominator)
    }

    /// The phase of $G(i\omega)$ (degrees) for $\omega \ge 0$, continuous in $\omega$ and in
    /// $(-180°, 180°]$ as $\omega \to 0^+$ (see the [module docs](self)); NaN where $G$ is zero
    /// or undefined. The same $\omega$ gives the same phase whatever other frequencies are
    /// asked for.
    pub fn phase_deg(&self, omega: f64) -> f64 {
        self.phase_with(&self.zeros(), &self.poles(), omega)
    }

    /// [`Self::phase_deg`] with the zeros and poles computed once.
    fn phase_with(&self, zeros: &[Complex<f64>], poles: &[Complex<f64>], omega: f64) -> f64 {
        // The gain's sign; a rate's zero at the origin counts +90° as ω -> 0+.
        let lead = if zeros.len() > usize::from(self.output.is_rate()) {
            self.numerator[zeros.len() - usize::from(self.output.is_rate())]
        } else {
            self.numerator[0]
        };
        let negative = lead / self.denominator[4] < 0.0;
        phase_on_branch(self.at(omega), zeros, poles, negative, omega)
    }

    /// The numerator's coefficients of $s^0, s^1, s^2, s^3$ including the factor $s$ of a rate
    /// output (the last is zero for an angle).
    pub fn numerator_with_rate(&self) -> [f64; 4] {
        let n = self.numerator;
        if self.output.is_rate() {
            [0.0, n[0], n[1], n[2]]
        } else {
            [n[0], n[1], n[2], 0.0]
        }
    }
}

/// The phase of $G(i\omega) = $ `g` (real and imaginary parts) in degrees for $\omega \ge 0$ on
/// the branch that the zeros and poles choose (see the [module docs](self)): continuous in
/// $\omega$, in $(-180°, 180°]$ as $\omega \to 0^+$; `negative` when the gain $K$ (the ratio of
/// the leading coefficients) is negative. Shared by the bicycle's transfer functions and the
/// leaning rider's ([`super::lean_rider`]).
pub(crate) fn phase_on_branch(
    g: (f64, f64),
    zeros: &[Complex<f64>],
    poles: &[Complex<f64>],
    negative: bool,
    omega: f64,
) -> f64 {
    let (re, im) = g;
    let principal = im.atan2(re).to_degrees();
    let branch_sum = |w: f64| {
        let factor = |r: &Complex<f64>| {
            // arg(iω - r) on the branch continuous along the vertical line Re = -Re r.
            let a = (w - r.im).atan2(-r.re).to_degrees();
            if r.re > 0.0 && a < 0.0 {
                a + 360.0
            } else {
                a
            }
        };
        zeros.iter().map(factor).sum::<f64>() - poles.iter().map(factor).sum::<f64>()
    };
    let gain = if negative { 180.0 } else { 0.0 };
    // The limit as ω -> 0+: each factor at ω = 0 is its limit, except a root at the origin
    // (iω - 0 has argument 90° for every ω > 0).
    let at_zero = |rs: &[Complex<f64>]| -> f64 {
        rs.iter()
            .map(|r| {
                if r.re == 0.0 && r.im == 0.0 {
                    90.0
                } else {
                    let a = (-r.im).atan2(-r.re).to_degrees();
                    if r.re > 0.0 && a < 0.0 {
                        a + 360.0
                    } else {
                        a
                    }
                }
            })
            .sum()
    };
    let limit = gain + at_zero(zeros) - at_zero(poles);
    // The one multiple of 360° putting the limit in (-180°, 180°].
    let shift = -360.0 * ((limit - 180.0) / 360.0).ceil();
    let continuous = gain + branch_sum(omega) + shift;
    principal + 360.0 * ((continuous - principal) / 360.0).round()
}

/// One point of a frequency response.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrequencyPoint {
    /// The forward speed (m/s).
    pub speed: f64,
    /// The angular frequency $\omega$ (rad/s).
    pub omega: f64,
    /// $\operatorname{Re} G(i\omega)$.
    pub re: f64,
    /// $\operatorname{Im} G(i\omega)$.
    pub im: f64,
    /// $20 \log_{10} |G(i\omega)|$ (dB).
    pub magnitude_db: f64,
    /// $\arg G(i\omega)$ (degrees) on the branch continuous in $\omega$ that lies in
    /// $(-180°, 180°]$ as $\omega \to 0^+$ ([`TransferFunction::phase_deg`]): a function of
    /// the frequency, not of the grid.
    pub phase_deg: f64,
}

/// Evaluates one pair's scene at `params` and speed `v`: (numerator, denominator).
fn scene_values(
    params: &WhippleParams,
    v: f64,
    input: Input,
    output: Output,
) -> ([f64; 3], [f64; 5]) {
    macro_rules! eval {
        ($scene:ident) => {{
            let names = $scene::PARAMS;
            let np = names.len();
            let arr: [f64; $scene::Args::LEN] =
                std::array::from_fn(|i| if i < np { params.value(names[i]) } else { v });
            let o = $scene::eval_array(&arr);
            ([o[0], o[1], o[2]], [o[3], o[4], o[5], o[6], o[7]])
        }};
    }
    let angle = match output {
        Output::Roll | Output::RollRate => 0,
        Output::Steer | Output::SteerRate => 1,
    };
    match (angle, input) {
        (0, Input::Roll) => eval!(tf_roll_roll_scene),
        (0, Input::Steer) => eval!(tf_roll_steer_scene),
        (_, Input::Roll) => eval!(tf_steer_roll_scene),
        (_, Input::Steer) => eval!(tf_steer_steer_scene),
    }
}

impl Whipple {
    /// The transfer function from `input` to `output` at speed `v`, from the generated
    /// numerator and characteristic polynomial.
    ///
    /// Where the generated coefficients are not finite (the two-mass skate's zero wheel radii
    /// divide zero spin inertias by zero radii in the symbolic expressions) they are taken from
    /// the matrices instead, whose evaluator has that limit: $\det P(s)$ and the adjugate's entry
    /// of $P(s) = M s^2 + v C_1 s + g K_0 + v^2 K_2$ expanded in $s$ ([`from_matrices`]).
    pub fn transfer_function(&self, v: f64, input: Input, output: Output) -> TransferFunction {
        let (numerator, denominator) = scene_values(self.params(), v, input, output);
        if numerator.iter().chain(&denominator).all(|x| x.is_finite()) {
            return TransferFunction { speed: v, input, output, numerator, denominator };
        }
        from_matrices(&self.matrices(), self.params().value("g"), v, input, output)
    }

    /// The frequency response from `input` to `output` at every speed of `speeds` and every
    /// frequency of `omegas` [rad/s]: speed-major (all frequencies of the first speed, then
    /// the next), the phase that of [`TransferFunction::phase_deg`] at each frequency.
    pub fn frequency_response(
        &self,
        speeds: &[f64],
        omegas: &[f64],
        input: Input,
        output: Output,
    ) -> Vec<FrequencyPoint> {
        let mut out = Vec::with_capacity(speeds.len() * omegas.len());
        for &v in speeds {
            let tf = self.transfer_function(v, input, output);
            let (zeros, poles) = (tf.zeros(), tf.poles());
            for &omega in omegas {
                let (re, im) = tf.at(omega);
                let phase = tf.phase_with(&zeros, &poles, omega);
                let magnitude_db = 20.0 * re.hypot(im).log10();
                out.push(FrequencyPoint {
                    speed: v,
                    omega,
                    re,
                    im,
                    magnitude_db,
                    phase_deg: phase,
                });
            }
        }
        out
    }
}

/// The transfer function from the matrices $M, C_1, K_0, K_2$: with
/// $P(s) = M s^2 + v C_1 s + K$, $K = g K_0 + v^2 K_2$, the denominator
/// $\det P = \det M\,s^4 + m(M, vC_1)\,s^3 + (m(M, K) + \det vC_1)\,s^2 + m(vC_1, K)\,s + \det K$
/// ($m$ the mixed determinant) and the numerator the entry of $\operatorname{adj} P$.
pub fn from_matrices(
    m: &super::Matrices,
    g: f64,
    v: f64,
    input: Input,
    output: Output,
) -> TransferFunction {
    use crate::numerics::mat2::{det, mix};
    let c: [[f64; 2]; 2] = std::array::from_fn(|r| std::array::from_fn(|k| v * m.c1[r][k]));
    let k: [[f64; 2]; 2] =
        std::array::from_fn(|r| std::array::from_fn(|j| g * m.k0[r][j] + v * v * m.k2[r][j]));
    let denominator = [det(&k), mix(&c, &k), mix(&m.m, &k) + det(&c), mix(&m.m, &c), det(&m.m)];
    // adj P = [[P11, -P01], [-P10, P00]]: the entry (output angle, input).
    let row = usize::from(matches!(output, Output::Steer | Output::SteerRate));
    let col = input.index();
    let (i, j, sign) = match (row, col) {
        (0, 0) => (1, 1, 1.0),
        (0, _) => (0, 1, -1.0),
        (_, 0) => (1, 0, -1.0),
        _ => (0, 0, 1.0),
    };
    let numerator = [sign * k[i][j], sign * c[i][j], sign * m.m[i][j]];
    TransferFunction { speed: v, input, output, numerator, denominator }
}

/// `n` frequencies spaced logarithmically from `from` to `to` (both included exactly; `n = 1`
/// gives `from`), the usual axis of a Bode diagram. `None` unless `0 < from <= to`, both finite and
/// `n >= 1`.
pub fn log_space(from: f64, to: f64, n: usize) -> Option<Vec<f64>> {
    if !(from > 0.0 && from.is_finite() && to.is_finite() && to >= from && n >= 1) {
        return None;
    }
    if n == 1 {
        return Some(vec![from]);
    }
    let (a, b) = (from.ln(), to.ln());
    Some(
        (0..n)
            .map(|k| match k {
                0 => from,
                _ if k + 1 == n => to,
                _ => (a + (b - a) * k as f64 / (n - 1) as f64).exp(),
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use nalgebra::{Complex, Matrix4, Matrix4x2};

    use super::*;
    use crate::numerics::rng::SplitMix64;

    /// $C(i\omega I - A)^{-1}B$ of the state space by nalgebra's complex LU: the independent
    /// route (no generated numerator, no characteristic polynomial).
    fn by_state_space(w: &Whipple, v: f64, omega: f64) -> [[Complex<f64>; 2]; 4] {
        let ss = w.state_space(v);
        let a: Matrix4<Complex<f64>> = ss.a.map(|x| Complex::new(x, 0.0));
        let b: Matrix4x2<Complex<f64>> = ss.b.map(|x| Complex::new(x, 0.0));
        let m = Matrix4::<Complex<f64>>::identity() * Complex::new(0.0, omega) - a;
        let x = m.lu().solve(&b).expect("iωI - A is regular away from the eigenvalues");
        std::array::from_fn(|r| std::array::from_fn(|c| x[(r, c)]))
    }

    fn rel(got: (f64, f64), want: Complex<f64>) -> f64 {
        (Complex::new(got.0, got.1) - want).norm() / want.norm()
    }

    #[test]
    fn every_pair_equals_the_state_space_resolvent_at_seeded_points() {
        let mut rng = SplitMix64(20);
        let mut worst: f64 = 0.0;
        for _ in 0..200 {
            // Every parameter scaled by up to ±20 % around the benchmark, redrawn until valid.
            let w = Whipple::new(WhippleParams::benchmark().perturbed(&mut rng, 0.2));
            let v = rng.uniform(0.0, 10.0);
            let omega = 10f64.powf(rng.uniform(-1.0, 2.0));
            let want = by_state_space(&w, v, omega);
            for input in Input::ALL {
                for output in Output::ALL {
                    let got = w.transfer_function(v, input, output).at(omega);
                    let e = rel(got, want[output.index()][input.index()]);
                    worst = worst.max(e);
                    assert!(e <= 1e-12, "{output:?}/{input:?} at v {v}, ω {omega}: rel {e:e}");
                }
            }
        }
        assert!(worst > 0.0, "the two routes are independent roundings");
    }

    #[test]
    fn near_a_pole_both_routes_agree_to_the_conditioning() {
        // Just above the benchmark's weave speed the weave pair sits close to the imaginary
        // axis: |G| peaks at ω ≈ |Im λ|. Agreement there is relative to |G|, which is large.
        let w = Whipple::new(WhippleParams::benchmark());
        let vw = w.weave_speed().expect("weave speed");
        let v = vw * (1.0 + 1e-6);
        let ev = w.eigenvalues(v);
        let weave = ev.iter().find(|e| e.im > 0.0).expect("weave pair");
        assert!(weave.re.abs() < 1e-5, "weave pair near the axis: {weave:?}");
        let omega = weave.im;
        let want = by_state_space(&w, v, omega);
        for input in Input::ALL {
            for output in Output::ALL {
                let got = w.transfer_function(v, input, output).at(omega);
                let g = want[output.index()][input.index()];
                assert!(g.norm() > 1e2, "a resonance: |G| = {}", g.norm());
                let e = rel(got, g);
                assert!(e <= 1e-9, "{output:?}/{input:?} near the pole: rel {e:e}");
            }
        }
    }

    #[test]
    fn static_gain_and_rates() {
        // At ω = 0 the angle's transfer function is N(0)/a0 = adj(K)/det(K) = K^{-1}, the
        // static compliance, and a rate's is 0.
        let w = Whipple::new(WhippleParams::benchmark());
        let (v, g) = (3.0, w.params().value("g"));
        let m = w.matrices();
        let k: [[f64; 2]; 2] =
            std::array::from_fn(|r| std::array::from_fn(|c| g * m.k0[r][c] + v * v * m.k2[r][c]));
        let det = k[0][0] * k[1][1] - k[0][1] * k[1][0];
        let kinv = [[k[1][1] / det, -k[0][1] / det], [-k[1][0] / det, k[0][0] / det]];
        for input in Input::ALL {
            for (row, output) in [Output::Roll, Output::Steer].into_iter().enumerate() {
                let (re, im) = w.transfer_function(v, input, output).at(0.0);
                let want = kinv[row][input.index()];
                assert!((re - want).abs() <= 1e-13 * want.abs() && im == 0.0, "{re} {want}");
            }
            let rate = Output::ALL[2 + input.index()];
            assert_eq!(w.transfer_function(v, input, rate).at(0.0), (0.0, 0.0));
        }
        // At a huge frequency G ~ n2 (iω)^2 / (a4 (iω)^4) = -n2 / (a4 ω^2): no overflow.
        let tf = w.transfer_function(v, Input::Steer, Output::Roll);
        let (re, im) = tf.at(1e100);
        let want = -tf.numerator[2] / tf.denominator[4] * 1e-200;
        assert!(
            (re - want).abs() <= 1e-12 * want.abs() && im.abs() <= 1e-90 * want.abs(),
            "{re} {im} {want}"
        );
    }

    #[test]
    fn phase_is_unwrapped_and_names_round_trip() {
        let w = Whipple::new(WhippleParams::benchmark());
        let omegas = log_space(0.1, 1000.0, 400).expect("valid range");
        assert_eq!(omegas.len(), 400);
        assert_eq!((omegas[0], omegas[399]), (0.1, 1000.0));
        let pts = w.frequency_response(&[2.0, 5.0], &omegas, Input::Steer, Output::Roll);
        assert_eq!(pts.len(), 800);
        for pair in pts.windows(2).filter(|p| p[0].speed == p[1].speed) {
            assert!((pair[1].phase_deg - pair[0].phase_deg).abs() < 180.0, "{pair:?}");
        }
        // Roll from steer torque: numerator of degree 2 over a quartic, so the magnitude falls
        // 40 dB per decade at high frequency.
        let hi = &pts[398..400];
        let slope = (hi[1].magnitude_db - hi[0].magnitude_db) / (hi[1].omega / hi[0].omega).log10();
        assert!((slope + 40.0).abs() < 0.5, "high-frequency slope {slope} dB/decade");
        for i in Input::ALL {
            assert_eq!(i.name().parse::<Input>(), Ok(i));
        }
        for o in Output::ALL {
            assert_eq!(o.name().parse::<Output>(), Ok(o));
        }
        let e = "yaw".parse::<Output>().unwrap_err().to_string();
        assert_eq!(e, "unknown signal \"yaw\": expected one of roll, steer, roll-rate, steer-rate");
        assert_eq!(log_space(0.0, 1.0, 3), None);
        assert_eq!(log_space(2.0, 1.0, 3), None);
        assert_eq!(log_space(1.0, 2.0, 0), None);
    }

    /// Browser with Jason, as in the issue that found the grid-dependent phase.
    fn browser_jason() -> Whipple {
        use crate::whipple::parameter_text::{add_rider, Rider, UncertainParams};
        let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/bicycleparameters");
        let read = |p: &str| std::fs::read_to_string(format!("{data}/{p}")).expect("data file");
        let bike =
            UncertainParams::read(&read("bicycles/Browser/Parameters/BrowserBenchmark.txt"), false)
                .expect("Browser");
        let rider = Rider::from_text(&read("riders/Jason/Parameters/JasonBrowserBenchmark.txt"))
            .expect("Jason");
        Whipple::new(add_rider(&bike.params, &rider).expect("with rider").params.params)
    }

    #[test]
    fn the_phase_does_not_depend_on_the_grid() {
        // The case: 3.162278 rad/s alone on a three-point grid gave 298.376°, on a
        // 201-point grid -61.624°. Both must give the one value, on the branch that is
        // continuous from (-180°, 180°] at ω -> 0+.
        let w = browser_jason();
        let sparse =
            w.frequency_response(&[5.0], &[1.0, 3.162278, 10.0], Input::Steer, Output::Roll);
        let mut dense = log_space(1.0, 10.0, 201).expect("range");
        dense[100] = 3.162278;
        let dense = w.frequency_response(&[5.0], &dense, Input::Steer, Output::Roll);
        assert_eq!(sparse[1].phase_deg, dense[100].phase_deg);
        assert!((sparse[1].phase_deg - -61.624).abs() < 1e-3, "{}", sparse[1].phase_deg);
        // Every pair, speeds through capsize and weave, seeded random grids against one dense
        // grid: the same value at the same frequency, bit for bit.
        let mut rng = SplitMix64(37);
        let bench = Whipple::new(WhippleParams::benchmark());
        for bike in [&w, &bench] {
            for v in [0.0, 1.0, 3.0, 4.0, 4.5, 5.0, 6.5, 8.0, 10.0] {
                for input in Input::ALL {
                    for output in Output::ALL {
                        let tf = bike.transfer_function(v, input, output);
                        let fine = log_space(1e-3, 1e3, 2000).expect("range");
                        let pts = bike.frequency_response(&[v], &fine, input, output);
                        // Continuous along the fine grid (no pole sits on the axis here).
                        for p in pts.windows(2) {
                            let d = (p[1].phase_deg - p[0].phase_deg).abs();
                            assert!(
                                d < 90.0,
                                "v {v} {input:?}->{output:?} jump {d} at {}",
                                p[1].omega
                            );
                        }
                        // In (-180°, 180°] at the low end (no root within 1e-3 of the origin).
                        let low = pts[0].phase_deg;
                        assert!(low > -180.0 - 1.0 && low <= 180.0 + 1.0, "v {v}: {low}");
                        for _ in 0..5 {
                            let k = (rng.uniform(0.0, 1999.0)) as usize;
                            let mut grid: Vec<f64> =
                                (0..4).map(|_| 10f64.powf(rng.uniform(-3.0, 3.0))).collect();
                            grid.insert(2, fine[k]);
                            let got = bike.frequency_response(&[v], &grid, input, output);
                            assert_eq!(got[2].phase_deg, pts[k].phase_deg);
                            assert_eq!(tf.phase_deg(fine[k]), pts[k].phase_deg);
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn the_matrices_give_the_generated_transfer_functions() {
        // The fallback of a design whose generated coefficients are not finite, checked where
        // both exist, and used by the two-mass skate (zero wheel radii and spin inertias).
        let mut rng = SplitMix64(38);
        for _ in 0..50 {
            let w = Whipple::new(WhippleParams::benchmark().perturbed(&mut rng, 0.2));
            let v = rng.uniform(0.0, 10.0);
            let g = w.params().value("g");
            for input in Input::ALL {
                for output in Output::ALL {
                    let a = w.transfer_function(v, input, output);
                    let b = from_matrices(&w.matrices(), g, v, input, output);
                    let scale = a
                        .denominator
                        .iter()
                        .chain(&a.numerator)
                        .fold(0.0, |m: f64, x| m.max(x.abs()));
                    for (x, y) in a
                        .numerator
                        .iter()
                        .chain(&a.denominator)
                        .zip(b.numerator.iter().chain(&b.denominator))
                    {
                        assert!((x - y).abs() <= 1e-12 * scale, "{input:?}->{output:?}: {x} {y}");
                    }
                }
            }
        }
    }
}
