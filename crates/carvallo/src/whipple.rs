//! The Carvallo–Whipple bicycle linearised about upright straight running: the matrices of
//! $M\ddot q + v C_1\dot q + (g K_0 + v^2 K_2) q = f$, $q = (\varphi, \delta)$ (lean, steer),
//! the characteristic polynomial, the eigenvalues and the stable speed range.
//!
//! The matrices and the polynomial coefficients are evaluated by [`scene!`](crate::scene)
//! evaluators over `generated/whipple.ir`, derived symbolically from the 25 parameters of the
//! 2007 benchmark (Meijaard, Papadopoulos, Ruina, Schwab, Proc. R. Soc. A 463, Table 1) by
//! `codegen/src/derive/whipple/mod.rs`. Parameters are read from a TOML file in the format of that
//! benchmark's anchors file: a `[parameters]` table with the keys of [`PARAM_NAMES`], numbers or
//! the strings `"pi"`, `"pi/N"`, `"K*pi/N"`.
//!
//! Stability (Routh–Hurwitz for $a_4 s^4 + a_3 s^3 + a_2 s^2 + a_1 s + a_0$ with $a_4 > 0$):
//! all $a_i > 0$ and $H_3 = a_1(a_2 a_3 - a_1 a_4) - a_0 a_3^2 > 0$. The coefficients are
//! polynomials in $v$ whose own coefficients come from the matrices; in $u = v^2$ every
//! Hurwitz function has degree at most two, so [`crate::sweep::hurwitz_window`] finds every
//! boundary of the stable range in closed form.

use std::fmt;

use nalgebra::Matrix4;

use crate::numerics::mat2::{det, mix};

/// Friction at the steering pivot (memoir n° 123): viscous steer damping and dry friction.
pub mod friction;

crate::scene! {
    /// The sixteen entries of $M$, $C_1$, $K_0$, $K_2$ (also on four designs per call, for
    /// the sweeps).
    pub mod matrices_scene {
        model: whipple,
        lanes: 4,
        outputs: [m11, m12, m21, m22, c1_11, c1_12, c1_21, c1_22,
                  k0_11, k0_12, k0_21, k0_22, k2_11, k2_12, k2_21, k2_22],
    }
}

crate::scene! {
    /// The characteristic polynomial's coefficients $a_0, \dots, a_4$ at speed $v$.
    pub mod char_poly_scene {
        model: whipple,
        outputs: [a0, a1, a2, a3, a4],
    }
}

/// The parameter names, in order (the benchmark's Table 1; `lambda` is the steer axis tilt).
pub const PARAM_NAMES: [&str; 26] = [
    "w", "c", "lambda", "g", "rR", "mR", "IRxx", "IRyy", "xB", "zB", "mB", "IBxx", "IByy", "IBzz",
    "IBxz", "xH", "zH", "mH", "IHxx", "IHyy", "IHzz", "IHxz", "rF", "mF", "IFxx", "IFyy",
];

/// The benchmark's parameters (Table 1 of the 2007 paper, exact values), in the anchors format.
pub const BENCHMARK_TOML: &str = r#"[parameters]
w = 1.02
c = 0.08
lambda = "pi/10"
g = 9.81
rR = 0.3
mR = 2.0
IRxx = 0.0603
IRyy = 0.12
xB = 0.3
zB = -0.9
mB = 85.0
IBxx = 9.2
IByy = 11.0
IBzz = 2.8
IBxz = 2.4
xH = 0.9
zH = -0.7
mH = 4.0
IHxx = 0.05892
IHyy = 0.06
IHzz = 0.00708
IHxz = -0.00756
rF = 0.35
mF = 3.0
IFxx = 0.1405
IFyy = 0.28
"#;

/// Keys that must be strictly positive.
const POSITIVE: [&str; 17] = [
    "w", "g", "rR", "mR", "IRxx", "IRyy", "mB", "IBxx", "IByy", "IBzz", "mH", "IHxx", "IHyy",
    "IHzz", "rF", "mF", "IFxx",
];

/// The positions of [`POSITIVE`] in [`PARAM_NAMES`] (a test checks them).
const POSITIVE_INDEX: [usize; 17] = [0, 3, 4, 5, 6, 7, 10, 11, 12, 13, 17, 18, 19, 20, 22, 23, 24];

/// Whether [`WhippleParams::from_values`] accepts `v`: the same conditions, by index and without
/// building an error (a sweep of random designs checks every design; the detailed checks that
/// name the offending key take microseconds). A test checks the two against each other.
pub(crate) fn valid_fast(v: &[f64; 26]) -> bool {
    const SLACK: f64 = 1e-9;
    if !v.iter().all(|x| x.is_finite() && x.abs() <= MAX_MAGNITUDE) {
        return false;
    }
    if !POSITIVE_INDEX.iter().all(|&k| v[k] >= MIN_POSITIVE) {
        return false;
    }
    if v[2].abs() >= std::f64::consts::FRAC_PI_2 {
        return false;
    }
    for (xx, yy) in [(6, 7), (24, 25)] {
        if v[yy] > 2.0 * v[xx] * (1.0 + SLACK) {
            return false;
        }
    }
    for (xx, yy, zz, xz) in [(11, 12, 13, 14), (18, 19, 20, 21)] {
        let (a, c, d, yy) = (v[xx], v[zz], v[xz], v[yy]);
        if a * c - d * d <= 0.0 {
            return false;
        }
        let mean = 0.5 * (a + c);
        let half = (0.25 * (a - c) * (a - c) + d * d).sqrt();
        let (l1, l2) = (mean - half, mean + half);
        if yy > (l1 + l2) * (1.0 + SLACK) || l2 > (l1 + yy) * (1.0 + SLACK) {
            return false;
        }
    }
    true
}

/// Largest magnitude accepted for any parameter (SI units). The Hurwitz determinant is a
/// product of up to six matrix entries, each a product of up to three parameters, so beyond
/// this bound `f64` could overflow; within it lengths from millimetres to kilometres and masses
/// from grams to tonnes (inertias $m l^2$ from $10^{-12}$ to $10^{9}$) are all accepted.
pub const MAX_MAGNITUDE: f64 = 1e15;

/// Smallest value accepted for a strictly positive parameter (SI units): below it the products
/// in the Hurwitz determinant could underflow (see [`MAX_MAGNITUDE`]).
pub const MIN_POSITIVE: f64 = 1e-15;

/// Why a parameter set was rejected.
#[derive(Clone, Debug, PartialEq)]
pub enum WhippleError {
    /// The text is not valid TOML or has no `[parameters]` table.
    Syntax {
        /// What the TOML reader said.
        message: String,
    },
    /// A required key is absent.
    MissingKey {
        /// The key.
        key: &'static str,
    },
    /// A key that is not a parameter of the model.
    UnknownKey {
        /// The key.
        key: String,
    },
    /// A value that is neither a number nor a multiple of pi.
    NotANumber {
        /// The key.
        key: String,
        /// The value as written.
        value: String,
    },
    /// A number that cannot describe a bicycle.
    InvalidParameter {
        /// The key.
        key: &'static str,
        /// The value.
        value: f64,
        /// Why, in a few lower-case words.
        reason: &'static str,
    },
}

impl fmt::Display for WhippleError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WhippleError::Syntax { message } => write!(f, "invalid parameter file: {message}"),
            WhippleError::MissingKey { key } => write!(f, "missing parameter {key}"),
            WhippleError::UnknownKey { key } => write!(f, "unknown parameter {key}"),
            WhippleError::NotANumber { key, value } => {
                write!(f, "parameter {key} = {value} is not a number")
            }
            WhippleError::InvalidParameter { key, value, reason } => {
                write!(f, "invalid {key} {value:?}: {reason}")
            }
        }
    }
}

impl std::error::Error for WhippleError {}

/// Reads `"pi"`, `"pi/N"`, `"K*pi"`, `"K*pi/N"` or a plain number.
pub(crate) fn parse_pi(text: &str) -> Option<f64> {
    let t: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let (num, den) = match t.split_once('/') {
        Some((a, b)) => (a.to_string(), b.parse::<f64>().ok()?),
        None => (t.clone(), 1.0),
    };
    let k = if num == "pi" {
        1.0
    } else if let Some(k) = num.strip_suffix("*pi") {
        k.parse::<f64>().ok()?
    } else {
        return num.parse::<f64>().ok().map(|x| x / den);
    };
    Some(k * std::f64::consts::PI / den)
}

/// A validated parameter set of the Carvallo–Whipple bicycle.
#[derive(Clone, Debug, PartialEq)]
pub struct WhippleParams {
    values: [f64; 26],
}

impl WhippleParams {
    /// The benchmark bicycle of the 2007 paper.
    pub fn benchmark() -> WhippleParams {
        WhippleParams::from_toml_str(BENCHMARK_TOML).expect("the benchmark parameters are valid")
    }

    /// Reads a parameter file in the anchors format (extra tables such as `[published]` are
    /// ignored; unknown keys inside `[parameters]` are errors).
    ///
    /// # Errors
    /// [`WhippleError`] naming the key and value at fault.
    pub fn from_toml_str(text: &str) -> Result<WhippleParams, WhippleError> {
        let doc: toml::Table = text.parse().map_err(|e: toml::de::Error| {
            let mut message = e.message().to_lowercase();
            if let Some(before) = e.span().and_then(|span| text.get(..span.start)) {
                // Name the line, so that the key at fault is in the message.
                let number = before.matches('\n').count() + 1;
                let line: String =
                    text.lines().nth(number - 1).unwrap_or("").trim().chars().take(60).collect();
                message = format!("line {number}: {message} (`{line}`)");
            }
            WhippleError::Syntax { message }
        })?;
        let table = doc
            .get("parameters")
            .and_then(|t| t.as_table())
            .ok_or_else(|| WhippleError::Syntax { message: "no [parameters] table".to_string() })?;
        for key in table.keys() {
            if !PARAM_NAMES.contains(&key.as_str()) {
                return Err(WhippleError::UnknownKey { key: key.clone() });
            }
        }
        let mut values = [0.0; 26];
        for (i, key) in PARAM_NAMES.iter().enumerate() {
            let item = table.get(*key).ok_or(WhippleError::MissingKey { key })?;
            let x = match item {
                toml::Value::Float(x) => Some(*x),
                toml::Value::Integer(n) => Some(*n as f64),
                toml::Value::String(s) => parse_pi(s),
                _ => None,
            };
            values[i] = x.ok_or_else(|| WhippleError::NotANumber {
                key: key.to_string(),
                value: item.to_string(),
            })?;
        }
        WhippleParams::from_values(values)
    }

    /// A parameter set taken as given, without the checks of
    /// [`from_values`](Self::from_values): for models outside them, such as Carvallo's
    /// bicycle with its massless fork and handlebar
    /// ([`crate::bicycle_straight::Constants::whipple_values`]), whose caller validates what
    /// its own model needs.
    pub(crate) fn from_values_unchecked(values: [f64; 26]) -> WhippleParams {
        WhippleParams { values }
    }

    /// Builds a parameter set from the values in the order of [`PARAM_NAMES`].
    ///
    /// # Errors
    /// [`WhippleError::InvalidParameter`] for a non-finite value, a non-positive length, mass,
    /// gravity or principal moment, a magnitude above [`MAX_MAGNITUDE`] or a positive value
    /// below [`MIN_POSITIVE`], a steer tilt outside $(-\pi/2, \pi/2)$, a frame inertia that is
    /// not positive definite in its x–z plane, or moments of inertia that break the triangle
    /// inequalities.
    pub fn from_values(values: [f64; 26]) -> Result<WhippleParams, WhippleError> {
        if valid_fast(&values) {
            return Ok(WhippleParams { values });
        }
        for (key, &value) in PARAM_NAMES.iter().zip(&values) {
            if !value.is_finite() {
                return Err(WhippleError::InvalidParameter {
                    key,
                    value,
                    reason: "must be finite",
                });
            }
            if POSITIVE.contains(key) && value <= 0.0 {
                return Err(WhippleError::InvalidParameter {
                    key,
                    value,
                    reason: "must be positive",
                });
            }
            if value.abs() > MAX_MAGNITUDE {
                return Err(WhippleError::InvalidParameter {
                    key,
                    value,
                    reason: "is too large (magnitude above 1e15 in SI units)",
                });
            }
            if POSITIVE.contains(key) && value < MIN_POSITIVE {
                return Err(WhippleError::InvalidParameter {
                    key,
                    value,
                    reason: "is too small (below 1e-15 in SI units)",
                });
            }
        }
        let p = WhippleParams { values };
        let lambda = p.get("lambda").unwrap_or(f64::NAN);
        if lambda.abs() >= std::f64::consts::FRAC_PI_2 {
            return Err(WhippleError::InvalidParameter {
                key: "lambda",
                value: lambda,
                reason: "must lie strictly between -pi/2 and pi/2",
            });
        }
        for (xx, zz, xz) in [("IBxx", "IBzz", "IBxz"), ("IHxx", "IHzz", "IHxz")] {
            let (a, b, c) = (p.value(xx), p.value(zz), p.value(xz));
            if a * b - c * c <= 0.0 {
                let key = if xz == "IBxz" { "IBxz" } else { "IHxz" };
                return Err(WhippleError::InvalidParameter {
                    key,
                    value: c,
                    reason: if key == "IBxz" {
                        "makes the inertia block [[IBxx, IBxz], [IBxz, IBzz]] not positive definite"
                    } else {
                        "makes the inertia block [[IHxx, IHxz], [IHxz, IHzz]] not positive definite"
                    },
                });
            }
        }
        p.check_triangle_inequalities()?;
        Ok(p)
    }

    /// The moments of inertia of a rigid body obey the triangle inequalities: each principal
    /// moment is at most the sum of the other two. For the wheels (principal moments
    /// $I_{xx} = I_{zz}$ and $I_{yy}$) this is $I_{yy} \le 2 I_{xx}$; for the frame and the
    /// front assembly, with $\lambda_1 \le \lambda_2$ the principal moments of the x–z block,
    /// $I_{yy} \le \lambda_1 + \lambda_2$ and $\lambda_2 \le \lambda_1 + I_{yy}$. A thin disc
    /// ($I_{yy} = 2 I_{xx}$) is allowed, with a relative slack of $10^{-9}$ for decimal input.
    fn check_triangle_inequalities(&self) -> Result<(), WhippleError> {
        const SLACK: f64 = 1e-9;
        for (xx, yy) in [("IRxx", "IRyy"), ("IFxx", "IFyy")] {
            let (a, b) = (self.value(xx), self.value(yy));
            if b > 2.0 * a * (1.0 + SLACK) {
                let (key, reason) = if yy == "IRyy" {
                    ("IRyy", "exceeds 2 IRxx (triangle inequality of the wheel's moments)")
                } else {
                    ("IFyy", "exceeds 2 IFxx (triangle inequality of the wheel's moments)")
                };
                return Err(WhippleError::InvalidParameter { key, value: b, reason });
            }
        }
        for body in ["B", "H"] {
            let name = |s: &str| format!("I{body}{s}");
            let (a, c, d, yy) = (
                self.value(&name("xx")),
                self.value(&name("zz")),
                self.value(&name("xz")),
                self.value(&name("yy")),
            );
            let mean = 0.5 * (a + c);
            let half = (0.25 * (a - c) * (a - c) + d * d).sqrt();
            let (l1, l2) = (mean - half, mean + half);
            let (key, too_large, too_small) = if body == "B" {
                (
                    "IByy",
                    "exceeds IBxx + IBzz, the sum of the other two principal moments (triangle inequality)",
                    "is too small: the largest principal moment of IBxx, IBzz, IBxz exceeds the sum of the other two (triangle inequality)",
                )
            } else {
                (
                    "IHyy",
                    "exceeds IHxx + IHzz, the sum of the other two principal moments (triangle inequality)",
                    "is too small: the largest principal moment of IHxx, IHzz, IHxz exceeds the sum of the other two (triangle inequality)",
                )
            };
            if yy > (l1 + l2) * (1.0 + SLACK) {
                return Err(WhippleError::InvalidParameter { key, value: yy, reason: too_large });
            }
            if l2 > (l1 + yy) * (1.0 + SLACK) {
                return Err(WhippleError::InvalidParameter { key, value: yy, reason: too_small });
            }
        }
        Ok(())
    }

    /// The value of the parameter `name`, if it is one.
    pub fn get(&self, name: &str) -> Option<f64> {
        PARAM_NAMES.iter().position(|k| *k == name).map(|i| self.values[i])
    }

    fn value(&self, name: &str) -> f64 {
        self.get(name).unwrap_or(f64::NAN)
    }

    /// All values, in the order of [`PARAM_NAMES`].
    pub fn values(&self) -> &[f64; 26] {
        &self.values
    }
}

/// A 2 × 2 matrix by rows.
pub use crate::numerics::mat2::Mat2;

/// The linearised equations' matrices.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Matrices {
    /// Mass matrix $M$.
    pub m: Mat2,
    /// $C_1$ (multiplied by $v$).
    pub c1: Mat2,
    /// $K_0$ (multiplied by $g$).
    pub k0: Mat2,
    /// $K_2$ (multiplied by $v^2$).
    pub k2: Mat2,
}

/// One eigenvalue.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Eigenvalue {
    /// Real part (1/s).
    pub re: f64,
    /// Imaginary part (1/s).
    pub im: f64,
}

/// The stable speed range.
#[derive(Clone, Debug, PartialEq)]
pub struct StabilityWindow {
    /// The lowest positive speed at which $H_3$ turns from negative to positive (the weave
    /// speed), `None` if there is none.
    pub weave_speed: Option<f64>,
    /// The lowest positive root of $a_0(v)$ (the capsize speed), closed form in $v^2$; `None`
    /// if $a_0$ has no positive root.
    pub capsize_speed: Option<f64>,
    /// The maximal intervals of positive speed on which every eigenvalue has a negative real
    /// part; an interval stable for every larger speed ends at `f64::INFINITY`.
    pub stable: Vec<(f64, f64)>,
}

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
        let n = matrices_scene::Args::LEN;
        let names = matrices_scene::PARAMS;
        let arr: [f64; matrices_scene::Args::LEN] =
            std::array::from_fn(|i| if i < n { params.value(names[i]) } else { f64::NAN });
        let o = matrices_scene::eval(&matrices_scene::Args::from_array(arr));
        let matrices = Matrices {
            m: [[o.m11, o.m12], [o.m21, o.m22]],
            c1: [[o.c1_11, o.c1_12], [o.c1_21, o.c1_22]],
            k0: [[o.k0_11, o.k0_12], [o.k0_21, o.k0_22]],
            k2: [[o.k2_11, o.k2_12], [o.k2_21, o.k2_22]],
        };
        Whipple { params, matrices }
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
        let arr: [f64; char_poly_scene::Args::LEN] =
            std::array::from_fn(|i| if i < np { self.params.value(names[i]) } else { v });
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
        crate::sweep::state_matrix(&self.matrices, self.params.value("g"), v)
    }

    /// The four eigenvalues at speed `v`, sorted by real part then imaginary part; empty if the
    /// Schur decomposition does not converge within
    /// [`MAX_SCHUR_ITERATIONS`](crate::sweep::MAX_SCHUR_ITERATIONS) (never seen for a bicycle).
    pub fn eigenvalues(&self, v: f64) -> Vec<Eigenvalue> {
        let mut ev: Vec<Eigenvalue> =
            crate::sweep::eigenvalues4(&self.state_matrix(v)).map_or(Vec::new(), |e| e.to_vec());
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
    /// other are not weave speeds), see [`crate::sweep`].
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
    /// route with double-double polishing, [`crate::sweep::hurwitz_window_polished`] (about a
    /// microsecond from the matrices).
    pub fn stability_window(&self) -> StabilityWindow {
        crate::sweep::hurwitz_window_polished(&self.matrices, self.params.value("g"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fast_validity_is_the_detailed_one() {
        let names: Vec<&str> = POSITIVE_INDEX.iter().map(|&k| PARAM_NAMES[k]).collect();
        assert_eq!(names, POSITIVE);
        let base = *WhippleParams::benchmark().values();
        let mut state = 99u64;
        let mut next = || {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            (z ^ (z >> 31)) >> 11
        };
        let (mut valid, mut invalid) = (0, 0);
        for i in 0..200_000 {
            let mut v = base;
            // Scale a few parameters by factors in [-1, 3], sometimes to special values.
            for _ in 0..1 + i % 4 {
                let k = (next() % 26) as usize;
                let u = next() as f64 / (1u64 << 53) as f64;
                v[k] = match next() % 50 {
                    0 => f64::NAN,
                    1 => 0.0,
                    2 => 1e-16,
                    3 => 2e15,
                    _ => v[k] * (4.0 * u - 1.0),
                };
            }
            // The detailed checks alone (what from_values did before the fast path).
            let detailed = {
                let p = WhippleParams { values: v };
                let finite_and_sized = PARAM_NAMES.iter().zip(&v).all(|(key, &x)| {
                    x.is_finite()
                        && x.abs() <= MAX_MAGNITUDE
                        && (!POSITIVE.contains(key) || x >= MIN_POSITIVE)
                });
                finite_and_sized
                    && v[2].abs() < std::f64::consts::FRAC_PI_2
                    && [(11, 13, 14), (18, 20, 21)]
                        .iter()
                        .all(|&(a, c, d)| v[a] * v[c] - v[d] * v[d] > 0.0)
                    && p.check_triangle_inequalities().is_ok()
            };
            assert_eq!(valid_fast(&v), detailed, "{v:?}");
            assert_eq!(WhippleParams::from_values(v).is_ok(), detailed, "{v:?}");
            if detailed {
                valid += 1;
            } else {
                invalid += 1;
            }
        }
        assert!(valid > 10_000 && invalid > 10_000, "{valid} valid, {invalid} invalid");
    }
}
