//! The 25 parameters of the Carvallo–Whipple bicycle (and $g$): names, the benchmark set,
//! validation, and the TOML of the benchmark's anchors file.
//!
//! The parameters are those of the 2007 benchmark (Meijaard, Papadopoulos, Ruina, Schwab,
//! Proc. R. Soc. A 463, Table 1). They are read from a TOML file in the format of that
//! benchmark's anchors file: a `[parameters]` table with the keys of [`PARAM_NAMES`], numbers or
//! the strings `"pi"`, `"pi/N"`, `"K*pi/N"`.

use std::fmt;

use crate::error::ParameterError;
use crate::numerics::rng::SplitMix64;

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
const POSITIVE: [&str; 4] = ["w", "g", "mB", "mH"];

/// The positions of [`POSITIVE`] in [`PARAM_NAMES`] (a test checks them).
const POSITIVE_INDEX: [usize; 4] = [0, 3, 10, 17];

/// Keys that may be zero but not negative: the wheels' radii, masses and moments (zero for the
/// two-mass-skate's skates) and the frames' principal moments (zero for a point mass).
const NONNEGATIVE: [&str; 14] = [
    "rR", "mR", "IRxx", "IRyy", "IBxx", "IByy", "IBzz", "IHxx", "IHyy", "IHzz", "rF", "mF", "IFxx",
    "IFyy",
];

/// The positions of [`NONNEGATIVE`] in [`PARAM_NAMES`] (a test checks them).
const NONNEGATIVE_INDEX: [usize; 14] = [4, 5, 6, 7, 11, 12, 13, 18, 19, 20, 22, 23, 24, 25];

/// The radius that stands for a zero wheel radius in the evaluators (see
/// [`WhippleParams::evaluated`]): small enough that every term it enters is below the last
/// bit of the terms beside it, large enough that its square and fourth power are normal
/// numbers (a quotient by them stays exact zero over a zero spin inertia).
pub const SKATE_RADIUS: f64 = 1e-60;

/// `v` with a zero wheel radius replaced by [`SKATE_RADIUS`] (see
/// [`WhippleParams::evaluated`]).
pub(crate) fn skate_limit(v: &[f64; 26]) -> [f64; 26] {
    let mut out = *v;
    for k in [4, 22] {
        if out[k] == 0.0 {
            out[k] = SKATE_RADIUS;
        }
    }
    out
}

/// The relative slack of each triangle inequality of the moments of inertia, by body: the
/// rear wheel's (`IRyy`), the front wheel's (`IFyy`), the rear frame's (`IByy`) and the front
/// assembly's (`IHyy`). An inequality $a \le b$ holds within slack $s$ when
/// $a \le b\,(1 + s)$.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleSlack(pub [f64; 4]);

impl TriangleSlack {
    /// The slack of [`WhippleParams::from_values`]: $10^{-9}$ (a thin disc written in decimal).
    pub const STRICT: TriangleSlack = TriangleSlack([1e-9; 4]);

    /// The slack that admits `params` itself: each body's relative violation by `params`
    /// ([`TriangleWarning::relative`]), or [`STRICT`](Self::STRICT)'s where it breaks none. The
    /// rule of the random and Monte Carlo sweeps around a nominal that breaks an inequality:
    /// a draw is kept when it breaks no inequality by more than the nominal does.
    pub fn admitting(params: &WhippleParams) -> TriangleSlack {
        let mut slack = TriangleSlack::STRICT.0;
        for w in params.triangle_violations() {
            let k = ["IRyy", "IFyy", "IByy", "IHyy"].iter().position(|n| *n == w.key).unwrap_or(0);
            slack[k] = slack[k].max(w.relative);
        }
        TriangleSlack(slack)
    }

    /// Whether every body's slack is the strict one.
    pub fn is_strict(&self) -> bool {
        *self == TriangleSlack::STRICT
    }
}

/// Whether [`WhippleParams::from_values_within`] accepts `v` with `slack`: the same
/// conditions, by index and without building an error (a sweep of random designs checks every
/// design; the detailed checks that name the offending key take microseconds). A test checks
/// the two against each other.
pub(crate) fn valid_within(v: &[f64; 26], slack: &TriangleSlack) -> bool {
    let slack = slack.0;
    if !v.iter().all(|x| x.is_finite() && x.abs() <= MAX_MAGNITUDE) {
        return false;
    }
    if !POSITIVE_INDEX.iter().all(|&k| v[k] >= MIN_POSITIVE) {
        return false;
    }
    if !NONNEGATIVE_INDEX.iter().all(|&k| v[k] == 0.0 || v[k] >= MIN_POSITIVE) {
        return false;
    }
    if v[2].abs() >= std::f64::consts::FRAC_PI_2 {
        return false;
    }
    // A wheel of zero radius has zero spin inertia (the two-mass-skate's skates).
    if (v[4] == 0.0 && v[7] != 0.0) || (v[22] == 0.0 && v[25] != 0.0) {
        return false;
    }
    if !TRIANGLE_BODIES.iter().enumerate().all(|(j, body)| body.holds(v, slack[j])) {
        return false;
    }
    !point_like(v) || mass_matrix_regular(v)
}

/// The triangle inequalities of one body's moments of inertia, by the indices of its moments
/// in [`PARAM_NAMES`], in the order of [`TriangleSlack`]'s slacks. [`valid_within`] checks them
/// all; a sweep of random designs checks each as soon as its moments are drawn (a body's
/// inequalities read its moments only).
#[derive(Clone, Copy, Debug)]
pub(crate) enum TriangleBody {
    /// A wheel, symmetric about its axle: $I_{yy} \le 2 I_{xx}$ (`[xx, yy]`).
    Wheel([usize; 2]),
    /// A frame with an $xz$ product of inertia: its principal moments $l_1 \le l_2$ in the $xz$
    /// plane and $I_{yy}$ obey the triangle inequalities, and the tensor is not indefinite
    /// (`[xx, yy, zz, xz]`).
    Frame([usize; 4]),
}

/// The bodies of [`TriangleBody`]: the rear wheel, the front wheel, the rear frame and the
/// front frame (the order of [`TriangleSlack`]).
pub(crate) static TRIANGLE_BODIES: [TriangleBody; 4] = [
    TriangleBody::Wheel([6, 7]),
    TriangleBody::Wheel([24, 25]),
    TriangleBody::Frame([11, 12, 13, 14]),
    TriangleBody::Frame([18, 19, 20, 21]),
];

impl TriangleBody {
    /// The indices of the body's moments in [`PARAM_NAMES`].
    pub(crate) fn keys(&self) -> &[usize] {
        match self {
            TriangleBody::Wheel(k) => k,
            TriangleBody::Frame(k) => k,
        }
    }

    /// Whether the moments of `v` obey the body's inequalities, each relaxed by `slack` (relative).
    pub(crate) fn holds(self, v: &[f64; 26], slack: f64) -> bool {
        match self {
            TriangleBody::Wheel([xx, yy]) => v[yy] <= 2.0 * v[xx] * (1.0 + slack),
            TriangleBody::Frame([xx, yy, zz, xz]) => {
                let (a, c, d, yy) = (v[xx], v[zz], v[xz], v[yy]);
                if a * c - d * d < 0.0 {
                    return false;
                }
                let mean = 0.5 * (a + c);
                let half = (0.25 * (a - c) * (a - c) + d * d).sqrt();
                let (l1, l2) = (mean - half, mean + half);
                let s = 1.0 + slack;
                !(yy > (l1 + l2) * s || l2 > (l1 + yy) * s)
            }
        }
    }
}

/// Whether a frame of `v` has a zero or singular inertia tensor (a point mass): then the mass
/// matrix is not positive definite by the inertias alone ([`valid_within`] computes it).
pub(crate) fn point_like(v: &[f64; 26]) -> bool {
    [(11, 12, 13, 14), (18, 19, 20, 21)]
        .iter()
        .any(|&(a, yy, c, d)| v[a] * v[c] - v[d] * v[d] <= 0.0 || v[yy] == 0.0)
}

crate::scene! {
    /// The mass matrix $M$ alone, for the validation of a parameter set: the parameters'
    /// module evaluates it itself, so that it does not depend on the matrices' module, which
    /// depends on it.
    pub(crate) mod mass_scene {
        model: whipple,
        outputs: [m11, m12, m21, m22],
    }
}

/// Whether the mass matrix $M$ of `v` is positive definite ($M_{11} > 0$, $\det M > 0$). It
/// is when both frames have positive definite inertias (every lean and steer rate turns a frame
/// with inertia); a frame of zero or singular inertia (a point mass, as the two-mass-skate's)
/// leaves it to where the masses sit, so it is computed.
fn mass_matrix_regular(v: &[f64; 26]) -> bool {
    let v = skate_limit(v);
    let a = mass_scene::Args::from_fn(|name| {
        PARAM_NAMES.iter().position(|n| *n == name).map_or(f64::NAN, |k| v[k])
    });
    let o = mass_scene::eval(&a);
    let m = [[o.m11, o.m12], [o.m21, o.m22]];
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    m[0][0] > 0.0 && det > 1e-12 * m[0][0] * m[1][1].abs()
}

/// Largest magnitude accepted for any parameter (SI units). The Hurwitz determinant is a
/// product of up to six matrix entries, each a product of up to three parameters, so beyond
/// this bound `f64` could overflow; within it lengths from millimetres to kilometres and masses
/// from grams to tonnes (inertias $m l^2$ from $10^{-12}$ to $10^{9}$) are all accepted.
pub const MAX_MAGNITUDE: f64 = 1e15;

/// Smallest value accepted for a strictly positive parameter, and smallest non-zero value for
/// one that may be zero (a wheel's radius, mass or moment, a frame's moment) (SI units): below
/// it the products in the Hurwitz determinant could underflow (see [`MAX_MAGNITUDE`]); zero
/// itself is exact.
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
    /// A number that cannot describe a bicycle: the error names its key (one of
    /// [`PARAM_NAMES`]; [`BicycleDesign::field_path`](super::BicycleDesign::field_path) gives
    /// the field).
    Parameter(ParameterError),
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
            WhippleError::Parameter(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for WhippleError {}

impl From<ParameterError> for WhippleError {
    fn from(e: ParameterError) -> WhippleError {
        WhippleError::Parameter(e)
    }
}

/// The error naming the benchmark key `key`, its value and why it was rejected.
fn invalid(key: &'static str, value: f64, reason: &'static str) -> WhippleError {
    WhippleError::Parameter(ParameterError::InvalidParameter { name: key, value, reason })
}

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

/// A broken triangle inequality of a body's moments of inertia, accepted by
/// [`WhippleParams::from_values_warning`].
#[derive(Clone, Debug, PartialEq)]
pub struct TriangleWarning {
    /// The moment that breaks it (`IRyy`, `IFyy`, `IByy` or `IHyy`).
    pub key: &'static str,
    /// Its value.
    pub value: f64,
    /// The nearest value that satisfies the inequality.
    pub bound: f64,
    /// By how much the inequality is broken, relative to its bound (0.01 is 1 %).
    pub relative: f64,
}

impl fmt::Display for TriangleWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} {:?} breaks a triangle inequality of the moments of inertia by {:.3} % \
             (bound {:?}); computed as given",
            self.key,
            self.value,
            100.0 * self.relative,
            self.bound
        )
    }
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
            // One line: the TOML reader's message may span several.
            let mut message = e
                .message()
                .to_lowercase()
                .lines()
                .map(str::trim)
                .filter(|l| !l.is_empty())
                .collect::<Vec<_>>()
                .join("; ");
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
    /// ([`crate::bicycle::straight::Constants::whipple_values`]), whose caller validates what
    /// its own model needs.
    pub(crate) fn from_values_unchecked(values: [f64; 26]) -> WhippleParams {
        WhippleParams { values }
    }

    /// Builds a parameter set from the values in the order of [`PARAM_NAMES`].
    ///
    /// # Errors
    /// [`WhippleError::Parameter`] for a non-finite value; a non-positive wheelbase, gravity or
    /// frame mass; a negative wheel radius, wheel mass or moment of inertia; a magnitude above
    /// [`MAX_MAGNITUDE`] or a non-zero magnitude below [`MIN_POSITIVE`] of a positive
    /// quantity; a steer tilt outside $(-\pi/2, \pi/2)$; a wheel of zero radius with non-zero
    /// spin inertia (its gyroscopic coupling $I_{yy}/r$ would be infinite); a frame inertia
    /// that is not positive semidefinite in its x–z plane; moments of inertia that break the
    /// triangle inequalities; frames of zero inertia (point masses) placed so that the mass
    /// matrix $M$ is singular.
    ///
    /// Zero radii with zero spin inertias are the two-mass-skate of Kooijman et al. (Science
    /// 332, 2011): the model takes the limit $r \to 0$ ([`evaluated`](Self::evaluated)).
    pub fn from_values(values: [f64; 26]) -> Result<WhippleParams, WhippleError> {
        WhippleParams::from_values_within(values, &TriangleSlack::STRICT)
    }

    /// As [`from_values`](Self::from_values), with the triangle inequalities relaxed by
    /// `slack` (see [`TriangleSlack::admitting`]).
    ///
    /// # Errors
    /// As [`from_values`](Self::from_values).
    pub fn from_values_within(
        values: [f64; 26],
        slack: &TriangleSlack,
    ) -> Result<WhippleParams, WhippleError> {
        if valid_within(&values, slack) {
            return Ok(WhippleParams { values });
        }
        for (key, &value) in PARAM_NAMES.iter().zip(&values) {
            let positive = POSITIVE.contains(key);
            let nonnegative = NONNEGATIVE.contains(key);
            if !value.is_finite() {
                return Err(invalid(key, value, "must be finite"));
            }
            if positive && value <= 0.0 {
                return Err(invalid(key, value, "must be positive"));
            }
            if nonnegative && value < 0.0 {
                return Err(invalid(key, value, "must not be negative"));
            }
            if value.abs() > MAX_MAGNITUDE {
                return Err(invalid(key, value, "is too large (magnitude above 1e15 in SI units)"));
            }
            if (positive || nonnegative) && value != 0.0 && value < MIN_POSITIVE {
                return Err(invalid(key, value, "is too small (below 1e-15 in SI units)"));
            }
        }
        let p = WhippleParams { values };
        let lambda = p.get("lambda").unwrap_or(f64::NAN);
        if lambda.abs() >= std::f64::consts::FRAC_PI_2 {
            return Err(invalid("lambda", lambda, "must lie strictly between -pi/2 and pi/2"));
        }
        if p.value("rR") == 0.0 && p.value("IRyy") != 0.0 {
            return Err(invalid(
                "IRyy",
                p.value("IRyy"),
                "must be zero for a rear wheel of zero radius rR = 0: its gyroscopic coupling \
                 IRyy/rR would be infinite (the two-mass-skate's skates have neither)",
            ));
        }
        if p.value("rF") == 0.0 && p.value("IFyy") != 0.0 {
            return Err(invalid(
                "IFyy",
                p.value("IFyy"),
                "must be zero for a front wheel of zero radius rF = 0: its gyroscopic coupling \
                 IFyy/rF would be infinite (the two-mass-skate's skates have neither)",
            ));
        }
        for (xx, zz, xz) in [("IBxx", "IBzz", "IBxz"), ("IHxx", "IHzz", "IHxz")] {
            let (a, b, c) = (p.value(xx), p.value(zz), p.value(xz));
            if a * b - c * c < 0.0 {
                let key = if xz == "IBxz" { "IBxz" } else { "IHxz" };
                return Err(invalid(
                    key,
                    c,
                    if key == "IBxz" {
                        "makes the inertia block [[IBxx, IBxz], [IBxz, IBzz]] not positive semidefinite"
                    } else {
                        "makes the inertia block [[IHxx, IHxz], [IHxz, IHzz]] not positive semidefinite"
                    },
                ));
            }
        }
        p.check_triangle_inequalities(slack)?;
        if !mass_matrix_regular(&values) {
            return Err(invalid(
                "IBxx",
                p.value("IBxx"),
                "leaves the mass matrix M singular: the frames' inertias are zero or singular \
                 and their masses sit where some lean and steer rates do not move them",
            ));
        }
        Ok(p)
    }

    /// As [`from_values`](Self::from_values), except that moments of inertia breaking a
    /// triangle inequality are accepted: each violation is returned, naming the parameter and
    /// the relative violation, for the caller to report (a measured frame, such as those of
    /// BicycleParameters' Browser and Yellow bicycles, can break them by a few per cent; the
    /// model's equations do not need them).
    ///
    /// # Errors
    /// As [`from_values`](Self::from_values) for every other check.
    pub fn from_values_warning(
        values: [f64; 26],
    ) -> Result<(WhippleParams, Vec<TriangleWarning>), WhippleError> {
        let p = WhippleParams::from_values_within(values, &TriangleSlack([f64::INFINITY; 4]))?;
        let warnings = p.triangle_violations();
        Ok((p, warnings))
    }

    /// The values the evaluators read: [`values`](Self::values) with a zero wheel radius
    /// replaced by [`SKATE_RADIUS`]. Validation admits a zero radius only with zero spin
    /// inertia, and the radius enters the linearised equations only as a polynomial factor or
    /// in the gyroscopic coupling $I_{yy}/r$, which is then exactly zero; so the matrices are
    /// those of the limit $r \to 0$ (the two-mass-skate) to within the last bit.
    pub fn evaluated(&self) -> [f64; 26] {
        skate_limit(&self.values)
    }

    /// Every broken triangle inequality (see
    /// [`check_triangle_inequalities`](Self::check_triangle_inequalities)), with the relative
    /// slack of $10^{-9}$.
    pub(crate) fn triangle_violations(&self) -> Vec<TriangleWarning> {
        self.triangle_violations_within(&TriangleSlack::STRICT)
    }

    /// Every triangle inequality broken by more than `slack`.
    fn triangle_violations_within(&self, slack: &TriangleSlack) -> Vec<TriangleWarning> {
        let slack = slack.0;
        let mut out = Vec::new();
        for (j, (xx, yy)) in [("IRxx", "IRyy"), ("IFxx", "IFyy")].into_iter().enumerate() {
            let (a, b) = (self.value(xx), self.value(yy));
            if b > 2.0 * a * (1.0 + slack[j]) {
                out.push(TriangleWarning {
                    key: yy,
                    value: b,
                    bound: 2.0 * a,
                    relative: (b - 2.0 * a) / (2.0 * a),
                });
            }
        }
        for (j, body) in ["B", "H"].into_iter().enumerate() {
            let name = |s: &str| format!("I{body}{s}");
            let (a, c, d, yy) = (
                self.value(&name("xx")),
                self.value(&name("zz")),
                self.value(&name("xz")),
                self.value(&name("yy")),
            );
            let key = if body == "B" { "IByy" } else { "IHyy" };
            let mean = 0.5 * (a + c);
            let half = (0.25 * (a - c) * (a - c) + d * d).sqrt();
            let (l1, l2) = (mean - half, mean + half);
            let s = 1.0 + slack[2 + j];
            if yy > (l1 + l2) * s {
                out.push(TriangleWarning {
                    key,
                    value: yy,
                    bound: l1 + l2,
                    relative: (yy - (l1 + l2)) / (l1 + l2),
                });
            } else if l2 > (l1 + yy) * s {
                out.push(TriangleWarning {
                    key,
                    value: yy,
                    bound: l2 - l1,
                    relative: (l2 - (l1 + yy)) / (l1 + yy),
                });
            }
        }
        out
    }

    /// The moments of inertia of a rigid body obey the triangle inequalities: each principal
    /// moment is at most the sum of the other two. For the wheels (principal moments
    /// $I_{xx} = I_{zz}$ and $I_{yy}$) this is $I_{yy} \le 2 I_{xx}$; for the frame and the
    /// front assembly, with $\lambda_1 \le \lambda_2$ the principal moments of the x–z block,
    /// $I_{yy} \le \lambda_1 + \lambda_2$ and $\lambda_2 \le \lambda_1 + I_{yy}$. A thin disc
    /// ($I_{yy} = 2 I_{xx}$) is allowed, with a relative slack of $10^{-9}$ for decimal input
    /// ([`TriangleSlack::STRICT`]), or `slack`.
    fn check_triangle_inequalities(&self, slack: &TriangleSlack) -> Result<(), WhippleError> {
        let Some(w) = self.triangle_violations_within(slack).into_iter().next() else {
            return Ok(());
        };
        // The wheels' bound is 2 Ixx; a frame's is exceeded (value above the bound) or its
        // I_yy is too small (below the bound l2 - l1).
        let reason = match (w.key, w.value > w.bound) {
            ("IRyy", _) => "exceeds 2 IRxx (triangle inequality of the wheel's moments)",
            ("IFyy", _) => "exceeds 2 IFxx (triangle inequality of the wheel's moments)",
            ("IByy", true) => {
                "exceeds IBxx + IBzz, the sum of the other two principal moments (triangle inequality)"
            }
            ("IByy", false) => {
                "is too small: the largest principal moment of IBxx, IBzz, IBxz exceeds the sum of the other two (triangle inequality)"
            }
            (_, true) => {
                "exceeds IHxx + IHzz, the sum of the other two principal moments (triangle inequality)"
            }
            (_, false) => {
                "is too small: the largest principal moment of IHxx, IHzz, IHxz exceeds the sum of the other two (triangle inequality)"
            }
        };
        Err(invalid(w.key, w.value, reason))
    }

    /// The value of the parameter `name`, if it is one.
    pub fn get(&self, name: &str) -> Option<f64> {
        PARAM_NAMES.iter().position(|k| *k == name).map(|i| self.values[i])
    }

    pub(super) fn value(&self, name: &str) -> f64 {
        self.get(name).unwrap_or(f64::NAN)
    }

    /// All values, in the order of [`PARAM_NAMES`].
    pub fn values(&self) -> &[f64; 26] {
        &self.values
    }

    /// A valid random design around this one: every parameter scaled by an independent
    /// uniform factor in $[1 - r, 1 + r]$, `r = spread`, drawn from `rng` (SplitMix64) and
    /// redrawn until [`WhippleParams::from_values_within`] accepts it with the slack that
    /// admits this design ([`TriangleSlack::admitting`]: no triangle inequality broken by more
    /// than here). With `spread` small enough for the checks to accept some draws (0.2 around
    /// the benchmark accepts most), it ends.
    pub fn perturbed(&self, rng: &mut SplitMix64, spread: f64) -> WhippleParams {
        let slack = TriangleSlack::admitting(self);
        loop {
            let v = self.values.map(|x| rng.scale(x, spread));
            if valid_within(&v, &slack) {
                return WhippleParams { values: v };
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn valid_fast(v: &[f64; 26]) -> bool {
        valid_within(v, &TriangleSlack::STRICT)
    }

    #[test]
    fn fast_validity_is_the_detailed_one() {
        let names: Vec<&str> = POSITIVE_INDEX.iter().map(|&k| PARAM_NAMES[k]).collect();
        assert_eq!(names, POSITIVE);
        let names: Vec<&str> = NONNEGATIVE_INDEX.iter().map(|&k| PARAM_NAMES[k]).collect();
        assert_eq!(names, NONNEGATIVE);
        let base = *WhippleParams::benchmark().values();
        let mut rng = crate::numerics::rng::SplitMix64(99);
        let mut next = || rng.next_u64() >> 11;
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
            // The detailed checks alone, written out again from the rules.
            let detailed = {
                let p = WhippleParams { values: v };
                let finite_and_sized = PARAM_NAMES.iter().zip(&v).all(|(key, &x)| {
                    x.is_finite()
                        && x.abs() <= MAX_MAGNITUDE
                        && (!POSITIVE.contains(key) || x >= MIN_POSITIVE)
                        && (!NONNEGATIVE.contains(key) || x == 0.0 || x >= MIN_POSITIVE)
                });
                let point_like = [(11, 12, 13, 14), (18, 19, 20, 21)]
                    .iter()
                    .any(|&(a, yy, c, d)| v[a] * v[c] - v[d] * v[d] == 0.0 || v[yy] == 0.0);
                finite_and_sized
                    && v[2].abs() < std::f64::consts::FRAC_PI_2
                    && (v[4] != 0.0 || v[7] == 0.0)
                    && (v[22] != 0.0 || v[25] == 0.0)
                    && [(11, 13, 14), (18, 20, 21)]
                        .iter()
                        .all(|&(a, c, d)| v[a] * v[c] - v[d] * v[d] >= 0.0)
                    && p.check_triangle_inequalities(&TriangleSlack::STRICT).is_ok()
                    && (!point_like || mass_matrix_regular(&v))
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

    #[test]
    fn broken_triangle_inequalities_are_warnings_and_other_errors_stay() {
        let mut v = *WhippleParams::benchmark().values();
        // IByy above IBxx + IBzz = 12.0 by 5 %, and IHyy below l2 - l1 of the front assembly.
        v[12] = 12.6;
        assert!(WhippleParams::from_values(v).is_err());
        let (p, warnings) = WhippleParams::from_values_warning(v).expect("computed as given");
        assert_eq!(p.values(), &v);
        assert_eq!(warnings.len(), 1);
        let w = &warnings[0];
        assert_eq!((w.key, w.value, w.bound), ("IByy", 12.6, 12.0));
        assert!((w.relative - 0.05).abs() < 1e-12, "{w}");
        assert_eq!(
            w.to_string(),
            "IByy 12.6 breaks a triangle inequality of the moments of inertia by 5.000 % \
             (bound 12.0); computed as given"
        );
        let (a, c, d) = (v[18], v[20], v[21]);
        let half = (0.25 * (a - c) * (a - c) + d * d).sqrt();
        v[19] = 0.9 * 2.0 * half;
        let (_, warnings) = WhippleParams::from_values_warning(v).expect("computed as given");
        assert_eq!(warnings.iter().map(|w| w.key).collect::<Vec<_>>(), ["IByy", "IHyy"]);
        // The largest principal moment l2 exceeds l1 + IHyy, relative to l1 + IHyy.
        let l1 = 0.5 * (a + c) - half;
        let want = (2.0 * half - v[19]) / (l1 + v[19]);
        assert!((warnings[1].relative - want).abs() < 1e-12, "{}", warnings[1]);
        assert!((warnings[1].bound - 2.0 * half).abs() < 1e-15, "{}", warnings[1]);
        // Every other check is still an error, also beside a broken inequality.
        v[10] = -85.0;
        assert_eq!(
            WhippleParams::from_values_warning(v).unwrap_err().to_string(),
            "invalid mB -85.0: must be positive"
        );
        let mut nan = *WhippleParams::benchmark().values();
        nan[12] = f64::NAN;
        assert!(WhippleParams::from_values_warning(nan).is_err());
    }
}
