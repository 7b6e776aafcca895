//! Bicycle parameters with stated uncertainties, read from the benchmark parameter text files of
//! BicycleParameters (`<bicycle>Benchmark.txt`) or from the anchors TOML format.
//!
//! A text file has one parameter per line, `name = value+/-uncertainty` (the repr of the
//! `uncertainties` package's `ufloat`, spaces allowed between the parts, the uncertainty a
//! standard deviation), for example `rR = 0.3+/-0.01`; `(1.23+/-0.04)e-02` (a shared exponent, as
//! `ufloat` prints small numbers) and a plain `name = value` (no uncertainty) are read too. The
//! names are those of Meijaard et al. (2007) as in [`PARAM_NAMES`], the steer axis tilt also as
//! BicycleParameters' `lam`. Blank lines and lines starting with `#` are skipped. A TOML file
//! (the anchors format, [`WhippleParams::from_toml_str`]) gives every uncertainty zero.

use std::fmt;

use crate::whipple::{BicycleDesign, TriangleWarning, WhippleError, WhippleParams, PARAM_NAMES};

/// A bicycle and the standard deviations of its parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct UncertainParams {
    /// The nominal parameters.
    pub params: WhippleParams,
    /// The standard deviation of each parameter, in the order of [`PARAM_NAMES`] (zero when none
    /// is stated).
    pub sigma: [f64; 26],
}

/// Why a parameter text was rejected.
#[derive(Clone, Debug, PartialEq)]
pub enum ParameterTextError {
    /// A line that is not `name = value[+/-uncertainty]` with finite numbers and a
    /// non-negative uncertainty, or that names a parameter twice or an unknown one.
    Line {
        /// The 1-based line number.
        line: usize,
        /// The line as written (trimmed).
        text: String,
        /// What is wrong, in a few lower-case words naming the value.
        reason: String,
    },
    /// The values read do not make a valid bicycle (a missing key, a non-positive mass, ...).
    Invalid(WhippleError),
    /// A value that the model cannot take as written: a wheel's third moment that is not its
    /// first, a lateral position that is not zero, front-frame parts that do not make `H`.
    Rule {
        /// The key at fault.
        key: String,
        /// Its value.
        value: f64,
        /// Why, in lower-case words naming the values compared.
        reason: String,
    },
}

impl fmt::Display for ParameterTextError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParameterTextError::Line { line, text, reason } => {
                write!(f, "line {line}: {reason} (`{text}`)")
            }
            ParameterTextError::Invalid(e) => write!(f, "{e}"),
            ParameterTextError::Rule { key, value, reason } => {
                write!(f, "invalid {key} {value:?}: {reason}")
            }
        }
    }
}

impl std::error::Error for ParameterTextError {}

impl From<WhippleError> for ParameterTextError {
    fn from(e: WhippleError) -> ParameterTextError {
        ParameterTextError::Invalid(e)
    }
}

/// Reads `1.5`, `pi/10` (the forms [`WhippleParams::from_toml_str`] reads in strings) or
/// nothing.
fn number(text: &str) -> Option<f64> {
    let t = text.trim();
    if t.is_empty() {
        return None;
    }
    super::params::parse_pi(t)
}

/// Splits `value+/-sigma`, `(value+/-sigma)e-02` or `value` into numbers.
pub(crate) fn value_and_sigma(text: &str) -> Result<(f64, f64), String> {
    let t = text.trim();
    let (body, exponent) = match t.strip_prefix('(') {
        Some(rest) => {
            let (inner, tail) =
                rest.split_once(')').ok_or_else(|| format!("unclosed parenthesis in `{t}`"))?;
            let scale = match tail.trim() {
                "" => 1.0,
                e => {
                    let e = e
                        .strip_prefix(['e', 'E'])
                        .ok_or_else(|| format!("`{e}` after the parenthesis is not an exponent"))?;
                    let k: i32 = e.parse().map_err(|_| format!("invalid exponent `{e}`"))?;
                    10f64.powi(k)
                }
            };
            (inner, scale)
        }
        None => (t, 1.0),
    };
    let (v, s) = match body.split_once("+/-") {
        Some((v, s)) => (v, Some(s)),
        None => (body, None),
    };
    let value = number(v).ok_or_else(|| format!("value `{}` is not a number", v.trim()))?;
    let sigma = match s {
        Some(s) => s
            .trim()
            .parse::<f64>()
            .map_err(|_| format!("uncertainty `{}` is not a number", s.trim()))?,
        None => 0.0,
    };
    let (value, sigma) = (value * exponent, sigma * exponent);
    if !value.is_finite() {
        return Err(format!("value `{}` is not finite", v.trim()));
    }
    if !sigma.is_finite() || sigma < 0.0 {
        return Err(format!(
            "uncertainty `{}` must be a finite standard deviation of at least zero",
            s.unwrap_or("").trim()
        ));
    }
    Ok((value, sigma))
}

/// A parameter text read, with what it broke but was accepted.
#[derive(Clone, Debug, PartialEq)]
pub struct Loaded {
    /// The parameters and their uncertainties.
    pub params: UncertainParams,
    /// Triangle inequalities of measured inertias that the values break (empty when strict).
    pub warnings: Vec<TriangleWarning>,
}

/// Keys of BicycleParameters' files beside the 26 of [`PARAM_NAMES`]: the wheels' third
/// moments, lateral positions, and the front frame's parts `G` (fork) and `S` (handlebar).
/// `xcl`, `zcl` (where the lateral force of Moore's experiments is applied) play no part in the
/// model and are read and ignored.
const EXTRA_NAMES: [&str; 22] = [
    "IRzz", "IFzz", "yB", "yH", "yG", "yS", "mG", "xG", "zG", "IGxx", "IGxz", "IGyy", "IGzz", "mS",
    "xS", "zS", "ISxx", "ISxz", "ISyy", "ISzz", "xcl", "zcl",
];

/// A rigid body in the x–z plane: mass, mass centre `(x, z)` and inertia
/// `Ixx, Ixz, Iyy, Izz` about its mass centre.
pub(crate) type PlanarBody = [f64; 7];

/// The rigid body made of `a` and `b` (parallel-axis theorem about the joint mass centre,
/// $I = I_c + m (|d|^2 E - d d^T)$ with $d = (d_x, 0, d_z)$, as BicycleParameters'
/// `inertia.parallel_axis`).
pub(crate) fn combine(a: &PlanarBody, b: &PlanarBody) -> PlanarBody {
    let m = a[0] + b[0];
    let x = (a[0] * a[1] + b[0] * b[1]) / m;
    let z = (a[0] * a[2] + b[0] * b[2]) / m;
    let mut out = [m, x, z, 0.0, 0.0, 0.0, 0.0];
    for body in [a, b] {
        let (dx, dz) = (body[1] - x, body[2] - z);
        out[3] += body[3] + body[0] * dz * dz;
        out[4] += body[4] - body[0] * dx * dz;
        out[5] += body[5] + body[0] * (dx * dx + dz * dz);
        out[6] += body[6] + body[0] * dx * dx;
    }
    out
}

/// The first-order standard deviations of `f(x)` for independent inputs with standard
/// deviations `s` (the linear propagation of the `uncertainties` package): each partial
/// derivative by a central difference of relative step $10^{-6}$ (exact for the polynomial and
/// rational `f` used here up to about $10^{-10}$ relative).
pub(crate) fn propagate<const N: usize, const M: usize>(
    f: impl Fn(&[f64; N]) -> [f64; M],
    x: &[f64; N],
    s: &[f64; N],
) -> [f64; M] {
    let mut var = [0.0; M];
    for i in 0..N {
        if s[i] == 0.0 {
            continue;
        }
        let h = 1e-6 * x[i].abs().max(s[i]).max(1e-12);
        let (mut up, mut down) = (*x, *x);
        up[i] += h;
        down[i] -= h;
        let (fu, fd) = (f(&up), f(&down));
        for j in 0..M {
            let d = (fu[j] - fd[j]) / (2.0 * h) * s[i];
            var[j] += d * d;
        }
    }
    var.map(f64::sqrt)
}

impl UncertainParams {
    /// Reads a BicycleParameters benchmark parameter text (see the [module docs](self)),
    /// refusing broken triangle inequalities: [`read`](Self::read) with `strict`.
    ///
    /// # Errors
    /// As [`read`](Self::read).
    pub fn from_text(text: &str) -> Result<UncertainParams, ParameterTextError> {
        UncertainParams::read(text, true).map(|l| l.params)
    }

    /// Reads a BicycleParameters benchmark parameter text (see the [module docs](self)), with
    /// the keys of BicycleParameters' files beside the model's 26:
    /// - `IRzz`, `IFzz` (the wheels are axisymmetric): accepted when equal to `IRxx`, `IFxx`
    ///   within the sum of their stated uncertainties;
    /// - `yB`, `yH`, `yG`, `yS` (the model is laterally symmetric): accepted when zero to
    ///   $10^{-6}$ of the wheelbase `w`;
    /// - the front frame's parts, fork `G` and handlebar `S` (`mG, xG, zG, IGxx, IGxz, IGyy,
    ///   IGzz` and the same for `S`): combined by the parallel-axis theorem into `H`; beside
    ///   `H` each of the seven values of `H` must equal the combination within the sum of its
    ///   stated uncertainty and the combination's (first order).
    ///
    /// Moments of inertia that break a triangle inequality are an error when `strict`,
    /// otherwise accepted and returned as [`Loaded::warnings`].
    ///
    /// # Errors
    /// [`ParameterTextError::Line`] naming the line and the value at fault (an unknown or
    /// repeated name, a value or uncertainty that is not a number, a negative uncertainty);
    /// [`ParameterTextError::Rule`] for a rule above broken, naming the key and values;
    /// [`ParameterTextError::Invalid`] for a missing parameter or values that are not a valid
    /// bicycle ([`WhippleParams::from_values`]).
    pub fn read(text: &str, strict: bool) -> Result<Loaded, ParameterTextError> {
        let mut values = [f64::NAN; 26];
        let mut sigma = [0.0; 26];
        let mut seen = [false; 26];
        let mut extra: [Option<(f64, f64)>; 22] = [None; 22];
        for_each_line(text, |name, rest, err| {
            let key = if name == "lam" { "lambda" } else { name };
            let slot = match PARAM_NAMES.iter().position(|n| *n == key) {
                Some(k) => {
                    let first = !seen[k];
                    seen[k] = true;
                    first.then_some(())
                }
                None => {
                    let k = EXTRA_NAMES
                        .iter()
                        .position(|n| *n == key)
                        .ok_or_else(|| err(format!("unknown parameter `{name}`")))?;
                    extra[k].is_none().then_some(())
                }
            };
            if slot.is_none() {
                return Err(err(format!("parameter `{name}` given twice")));
            }
            let vs = value_and_sigma(rest).map_err(|r| err(format!("{name}: {r}")))?;
            match PARAM_NAMES.iter().position(|n| *n == key) {
                Some(k) => (values[k], sigma[k]) = vs,
                None => {
                    let k = EXTRA_NAMES.iter().position(|n| *n == key).unwrap_or(0);
                    extra[k] = Some(vs);
                }
            }
            Ok(())
        })?;
        Self::assemble(values, sigma, seen, extra, strict)
    }

    /// Reads `(name, value, sigma)` entries (a mapping of numbers, such as a Python dict of
    /// `uncertainties` ufloats) by the rules of [`read`](Self::read): the same names, the same
    /// checks of BicycleParameters' extra keys, the same warnings.
    ///
    /// # Errors
    /// [`ParameterTextError::Rule`] naming the key and value for an unknown or repeated name, a
    /// value that is not finite or a standard deviation that is negative or not finite; the
    /// other errors as [`read`](Self::read).
    pub fn from_entries(
        entries: &[(String, f64, f64)],
        strict: bool,
    ) -> Result<Loaded, ParameterTextError> {
        let mut values = [f64::NAN; 26];
        let mut sigma = [0.0; 26];
        let mut seen = [false; 26];
        let mut extra: [Option<(f64, f64)>; 22] = [None; 22];
        let rule = |name: &str, value: f64, reason: String| ParameterTextError::Rule {
            key: name.to_string(),
            value,
            reason,
        };
        for (name, v, s) in entries {
            let (name, v, s) = (name.as_str(), *v, *s);
            if !s.is_finite() || s < 0.0 {
                return Err(rule(
                    name,
                    v,
                    format!(
                        "its standard deviation {s:?} must be a finite number of at least zero"
                    ),
                ));
            }
            let key = if name == "lam" { "lambda" } else { name };
            if let Some(k) = PARAM_NAMES.iter().position(|n| *n == key) {
                if seen[k] {
                    return Err(rule(name, v, format!("{} given twice", PARAM_NAMES[k])));
                }
                (values[k], sigma[k], seen[k]) = (v, s, true);
            } else if let Some(k) = EXTRA_NAMES.iter().position(|n| *n == key) {
                if extra[k].is_some() {
                    return Err(rule(name, v, format!("{name} given twice")));
                }
                if !v.is_finite() {
                    return Err(rule(name, v, "must be finite".to_string()));
                }
                extra[k] = Some((v, s));
            } else if ["mD", "IDxx", "IDyy", "IDzz"].contains(&name) {
                return Err(rule(
                    name,
                    v,
                    "a flywheel D is not in the model (BicycleParameters' analysis ignores it): \
                     leave out mD, IDxx, IDyy to study the bicycle without it"
                        .to_string(),
                ));
            } else {
                return Err(rule(
                    name,
                    v,
                    format!(
                        "unknown parameter (the names are {}, lam, and BicycleParameters' {})",
                        PARAM_NAMES.join(", "),
                        EXTRA_NAMES.join(", ")
                    ),
                ));
            }
        }
        Self::assemble(values, sigma, seen, extra, strict)
    }

    /// The checks and combinations of [`read`](Self::read) once the entries are collected.
    fn assemble(
        mut values: [f64; 26],
        mut sigma: [f64; 26],
        mut seen: [bool; 26],
        extra: [Option<(f64, f64)>; 22],
        strict: bool,
    ) -> Result<Loaded, ParameterTextError> {
        let get = |name: &str| EXTRA_NAMES.iter().position(|n| *n == name).and_then(|k| extra[k]);
        let index = |name: &str| PARAM_NAMES.iter().position(|n| *n == name).unwrap_or(0);
        // The front frame from its parts, when they are given.
        let part = |body: char| -> Result<Option<(PlanarBody, PlanarBody)>, ParameterTextError> {
            let keys = ["m", "x", "z", "Ixx", "Ixz", "Iyy", "Izz"].map(|k| match k {
                "m" | "x" | "z" => format!("{k}{body}"),
                _ => format!("I{body}{}", &k[1..]),
            });
            let found: Vec<Option<(f64, f64)>> = keys.iter().map(|k| get(k)).collect();
            if found.iter().all(Option::is_none) {
                return Ok(None);
            }
            let mut v = [0.0; 7];
            let mut s = [0.0; 7];
            for (j, f) in found.iter().enumerate() {
                let (a, b) = f.ok_or_else(|| ParameterTextError::Rule {
                    key: keys[j].clone(),
                    value: f64::NAN,
                    reason: format!("missing: the front frame's part {body} is given in part"),
                })?;
                (v[j], s[j]) = (a, b);
            }
            Ok(Some((v, s)))
        };
        let h_keys = ["mH", "xH", "zH", "IHxx", "IHxz", "IHyy", "IHzz"];
        match (part('G')?, part('S')?) {
            (None, None) => {}
            (Some((g, gs)), Some((sv, ss))) => {
                let x: [f64; 14] = std::array::from_fn(|j| if j < 7 { g[j] } else { sv[j - 7] });
                let xs: [f64; 14] = std::array::from_fn(|j| if j < 7 { gs[j] } else { ss[j - 7] });
                let f = |x: &[f64; 14]| {
                    let (a, b): ([f64; 7], [f64; 7]) =
                        (std::array::from_fn(|j| x[j]), std::array::from_fn(|j| x[j + 7]));
                    combine(&a, &b)
                };
                let h = f(&x);
                let hs = propagate(f, &x, &xs);
                let given = h_keys.map(|k| seen[index(k)]);
                if given.iter().all(|g| !g) {
                    for (j, k) in h_keys.iter().enumerate() {
                        (values[index(k)], sigma[index(k)]) = (h[j], hs[j]);
                        seen[index(k)] = true;
                    }
                } else {
                    for (j, k) in h_keys.iter().enumerate() {
                        let i = index(k);
                        if !seen[i] {
                            continue;
                        }
                        let tol = sigma[i] + hs[j] + 1e-9 * h[j].abs().max(values[i].abs());
                        if (values[i] - h[j]).abs() > tol {
                            return Err(ParameterTextError::Rule {
                                key: k.to_string(),
                                value: values[i],
                                reason: format!(
                                    "differs from {:?}+/-{:?}, the fork G and handlebar S combined \
                                     by the parallel-axis theorem, by more than the stated \
                                     uncertainties",
                                    h[j], hs[j]
                                ),
                            });
                        }
                    }
                }
            }
            (Some(_), None) | (None, Some(_)) => {
                let (given, missing) = if part('G')?.is_some() { ('G', 'S') } else { ('S', 'G') };
                return Err(ParameterTextError::Rule {
                    key: format!("m{missing}"),
                    value: f64::NAN,
                    reason: format!(
                        "missing: the front frame's part {given} is given without its part {missing}"
                    ),
                });
            }
        }
        if let Some(k) = seen.iter().position(|s| !s) {
            return Err(WhippleError::MissingKey { key: PARAM_NAMES[k] }.into());
        }
        for (zz, xx) in [("IRzz", "IRxx"), ("IFzz", "IFxx")] {
            if let Some((v, s)) = get(zz) {
                let (a, sa) = (values[index(xx)], sigma[index(xx)]);
                if (v - a).abs() > s + sa + 1e-9 * a.abs() {
                    return Err(ParameterTextError::Rule {
                        key: zz.to_string(),
                        value: v,
                        reason: format!(
                            "must equal {xx} {a:?} within their stated uncertainties (the model's \
                             wheels are axisymmetric)"
                        ),
                    });
                }
            }
        }
        let w = values[index("w")];
        for y in ["yB", "yH", "yG", "yS"] {
            if let Some((v, _)) = get(y) {
                if v.abs() > 1e-6 * w.abs() {
                    return Err(ParameterTextError::Rule {
                        key: y.to_string(),
                        value: v,
                        reason: format!(
                            "must be zero to 1e-6 of the wheelbase w = {w:?} (the model is \
                             laterally symmetric)"
                        ),
                    });
                }
            }
        }
        let (params, warnings) = if strict {
            (WhippleParams::from_values(values)?, Vec::new())
        } else {
            WhippleParams::from_values_warning(values)?
        };
        Ok(Loaded { params: UncertainParams { params, sigma }, warnings })
    }

    /// Parameters without uncertainty.
    pub fn exact(params: WhippleParams) -> UncertainParams {
        UncertainParams { params, sigma: [0.0; 26] }
    }

    /// Reads either format: TOML (the anchors format, every uncertainty zero) when the text has
    /// a table header (a line starting with `[`, such as `[parameters]`), the BicycleParameters
    /// text otherwise.
    ///
    /// # Errors
    /// As [`WhippleParams::from_toml_str`] or [`from_text`](Self::from_text).
    pub fn from_any(text: &str) -> Result<UncertainParams, ParameterTextError> {
        if text.lines().any(|l| l.trim_start().starts_with('[')) {
            Ok(UncertainParams::exact(WhippleParams::from_toml_str(text)?))
        } else {
            UncertainParams::from_text(text)
        }
    }

    /// The parameters by name.
    pub fn design(&self) -> BicycleDesign {
        self.params.design()
    }

    /// The standard deviations by name: each field of the result is the uncertainty of the
    /// same field of [`design`](Self::design) (zero when none is stated).
    pub fn sigma_design(&self) -> BicycleDesign {
        BicycleDesign::from_array(&self.sigma)
    }

    /// Whether any uncertainty is stated.
    pub fn has_uncertainty(&self) -> bool {
        self.sigma.iter().any(|s| *s > 0.0)
    }

    /// The text form read by [`from_text`](Self::from_text): one `name = value+/-sigma` line per
    /// parameter with BicycleParameters' names (`lam`), numbers in round-trip form.
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        for (k, name) in PARAM_NAMES.iter().enumerate() {
            let name = if *name == "lambda" { "lam" } else { name };
            s.push_str(&format!("{name} = {:?}+/-{:?}\n", self.params.values()[k], self.sigma[k]));
        }
        s
    }
}

/// The keys of a BicycleParameters rider file, in order: the rider's rigid body in the
/// bicycle's frame (mass, mass centre, inertia about the mass centre).
pub const RIDER_NAMES: [&str; 8] = ["mB", "xB", "yB", "zB", "IBxx", "IBxz", "IByy", "IBzz"];

/// A rigid rider (BicycleParameters' `riders/<name>/Parameters/<name><bicycle>Benchmark.txt`):
/// values and standard deviations in the order of [`RIDER_NAMES`].
#[derive(Clone, Debug, PartialEq)]
pub struct Rider {
    /// The values.
    pub values: [f64; 8],
    /// Their standard deviations (zero when none is stated).
    pub sigma: [f64; 8],
}

/// Runs `f` on every `name = rest` line of a parameter file (blank lines and `#` comments
/// skipped) with the trimmed name, the text after `=`, and a maker of the
/// [`ParameterTextError::Line`] that names that line; a line without `=` is that error.
fn for_each_line(
    text: &str,
    mut f: impl FnMut(
        &str,
        &str,
        &dyn Fn(String) -> ParameterTextError,
    ) -> Result<(), ParameterTextError>,
) -> Result<(), ParameterTextError> {
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let err = |reason: String| ParameterTextError::Line {
            line: i + 1,
            text: line.chars().take(80).collect(),
            reason,
        };
        let (name, rest) = line
            .split_once('=')
            .ok_or_else(|| err("expected `name = value+/-uncertainty`".to_string()))?;
        f(name.trim(), rest, &err)?;
    }
    Ok(())
}

impl Rider {
    /// Reads a rider file: the eight keys of [`RIDER_NAMES`], each once, as
    /// `name = value+/-uncertainty` (the forms of [`UncertainParams::read`]).
    ///
    /// # Errors
    /// [`ParameterTextError::Line`] naming the line at fault (an unknown or repeated key, a
    /// value that is not a number); [`ParameterTextError::Rule`] for a missing key or a mass
    /// or moment that is not positive.
    pub fn from_text(text: &str) -> Result<Rider, ParameterTextError> {
        let mut values = [f64::NAN; 8];
        let mut sigma = [0.0; 8];
        let mut seen = [false; 8];
        for_each_line(text, |name, rest, err| {
            let k = RIDER_NAMES
                .iter()
                .position(|n| *n == name)
                .ok_or_else(|| err(format!("unknown rider parameter `{name}`")))?;
            if seen[k] {
                return Err(err(format!("parameter `{name}` given twice")));
            }
            seen[k] = true;
            (values[k], sigma[k]) =
                value_and_sigma(rest).map_err(|r| err(format!("{name}: {r}")))?;
            Ok(())
        })?;
        if let Some(k) = seen.iter().position(|s| !s) {
            return Err(ParameterTextError::Rule {
                key: RIDER_NAMES[k].to_string(),
                value: f64::NAN,
                reason: "missing from the rider file".to_string(),
            });
        }
        for k in [0, 4, 6, 7] {
            if values[k] <= 0.0 {
                return Err(ParameterTextError::Rule {
                    key: RIDER_NAMES[k].to_string(),
                    value: values[k],
                    reason: "must be positive (the rider's mass and principal moments)".to_string(),
                });
            }
        }
        Ok(Rider { values, sigma })
    }
}

/// The bicycle with the rider's rigid body added to its rear frame `B` (BicycleParameters'
/// `inertia.combine_bike_rider`, used by `Bicycle.add_rider`): the joint mass and mass centre,
/// and the inertia about it by the parallel-axis theorem; the uncertainties of the eight
/// frame values carried to first order from the frame's and the rider's (independent).
/// The rider's `yB` must be zero to $10^{-6}$ of the wheelbase (the model is laterally
/// symmetric). Triangle inequalities broken by the combined frame are returned as warnings.
///
/// # Errors
/// [`ParameterTextError::Rule`] for a rider `yB` that is not zero;
/// [`ParameterTextError::Invalid`] if the combination is not a valid bicycle.
pub fn add_rider(params: &UncertainParams, rider: &Rider) -> Result<Loaded, ParameterTextError> {
    let w = params.params.get("w").unwrap_or(f64::NAN);
    let y = rider.values[2];
    if y.abs() > 1e-6 * w.abs() {
        return Err(ParameterTextError::Rule {
            key: "yB".to_string(),
            value: y,
            reason: format!(
                "the rider's lateral position must be zero to 1e-6 of the wheelbase w = {w:?} \
                 (the model is laterally symmetric)"
            ),
        });
    }
    // The frame's and the rider's planar bodies, in PlanarBody order.
    let frame_keys = ["mB", "xB", "zB", "IBxx", "IBxz", "IByy", "IBzz"];
    let index = |name: &str| PARAM_NAMES.iter().position(|n| *n == name).unwrap_or(0);
    let rider_order = [0, 1, 3, 4, 5, 6, 7];
    let x: [f64; 14] = std::array::from_fn(|j| {
        if j < 7 {
            params.params.values()[index(frame_keys[j])]
        } else {
            rider.values[rider_order[j - 7]]
        }
    });
    let xs: [f64; 14] = std::array::from_fn(|j| {
        if j < 7 {
            params.sigma[index(frame_keys[j])]
        } else {
            rider.sigma[rider_order[j - 7]]
        }
    });
    let f = |x: &[f64; 14]| {
        let (a, b): (PlanarBody, PlanarBody) =
            (std::array::from_fn(|j| x[j]), std::array::from_fn(|j| x[j + 7]));
        combine(&a, &b)
    };
    let body = f(&x);
    let body_sigma = propagate(f, &x, &xs);
    let mut values = *params.params.values();
    let mut sigma = params.sigma;
    for (j, key) in frame_keys.iter().enumerate() {
        (values[index(key)], sigma[index(key)]) = (body[j], body_sigma[j]);
    }
    let (p, warnings) = WhippleParams::from_values_warning(values)?;
    Ok(Loaded { params: UncertainParams { params: p, sigma }, warnings })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn benchmark_text(sigma: f64) -> String {
        UncertainParams {
            params: WhippleParams::benchmark(),
            sigma: WhippleParams::benchmark().values().map(|v| sigma * v.abs()),
        }
        .to_text()
    }

    #[test]
    fn the_text_form_round_trips() {
        let text = benchmark_text(0.01);
        let u = UncertainParams::from_text(&text).expect("valid");
        assert_eq!(u.params, WhippleParams::benchmark());
        assert_eq!(u.sigma[0], 0.01 * 1.02);
        assert_eq!(u.to_text(), text);
    }

    #[test]
    fn entries_follow_the_rules_of_the_text() {
        let b = WhippleParams::benchmark();
        let mut entries: Vec<(String, f64, f64)> = PARAM_NAMES
            .iter()
            .zip(b.values())
            .map(|(n, v)| (n.to_string(), *v, 0.01 * v.abs()))
            .collect();
        entries.push(("yB".into(), 0.0, 0.0));
        let text = format!("{}yB = 0.0+/-0.0\n", benchmark_text(0.01));
        let from_text = UncertainParams::read(&text, true).expect("valid");
        let from_entries = UncertainParams::from_entries(&entries, true).expect("valid");
        assert_eq!(from_entries.params, from_text.params);
        entries.last_mut().expect("yB").1 = 0.1;
        assert_eq!(
            UncertainParams::from_entries(&entries, true).unwrap_err().to_string(),
            UncertainParams::read(&text.replace("yB = 0.0", "yB = 0.1"), true)
                .unwrap_err()
                .to_string()
        );
        entries.last_mut().expect("yB").0 = "mQ".into();
        assert!(UncertainParams::from_entries(&entries, true)
            .unwrap_err()
            .to_string()
            .starts_with("invalid mQ 0.1: unknown parameter"));
        entries.last_mut().expect("mQ").0 = "mD".into();
        assert!(UncertainParams::from_entries(&entries, true)
            .unwrap_err()
            .to_string()
            .starts_with("invalid mD 0.1: a flywheel D is not in the model"));
        entries.pop();
        entries[0].2 = -1.0;
        assert_eq!(
            UncertainParams::from_entries(&entries, true).unwrap_err().to_string(),
            "invalid w 1.02: its standard deviation -1.0 must be a finite number of at least zero"
        );
    }

    #[test]
    fn ufloat_forms_are_read() {
        assert_eq!(value_and_sigma("0.3+/-0.01"), Ok((0.3, 0.01)));
        assert_eq!(value_and_sigma(" 0.3 +/- 0.01 "), Ok((0.3, 0.01)));
        assert_eq!(value_and_sigma("(1.5+/-0.5)e-02"), Ok((1.5e-2, 0.5e-2)));
        assert_eq!(value_and_sigma("85.0"), Ok((85.0, 0.0)));
        let (pi, s) = value_and_sigma("pi/10+/-0.0").expect("pi form");
        assert_eq!((pi, s), (std::f64::consts::PI / 10.0, 0.0));
    }

    #[test]
    fn bad_lines_name_the_line_and_value() {
        let good = benchmark_text(0.01);
        let cases = [
            ("mB = heavy+/-1", "line 11: mB: value `heavy` is not a number (`mB = heavy+/-1`)"),
            ("mB = 85+/--1", "line 11: mB: uncertainty `-1` must be a finite standard deviation of at least zero (`mB = 85+/--1`)"),
            ("mB = 85+/-x", "line 11: mB: uncertainty `x` is not a number (`mB = 85+/-x`)"),
            ("mass = 85", "line 11: unknown parameter `mass` (`mass = 85`)"),
            ("mB 85", "line 11: expected `name = value+/-uncertainty` (`mB 85`)"),
            ("mB = inf", "line 11: mB: value `inf` is not finite (`mB = inf`)"),
        ];
        for (bad, want) in cases {
            let text: Vec<String> = good
                .lines()
                .map(|l| if l.starts_with("mB ") { bad.to_string() } else { l.to_string() })
                .collect();
            let err = UncertainParams::from_text(&text.join("\n")).unwrap_err();
            assert_eq!(err.to_string(), want);
        }
        let twice = format!("{good}c = 0.08\n");
        assert_eq!(
            UncertainParams::from_text(&twice).unwrap_err().to_string(),
            "line 27: parameter `c` given twice (`c = 0.08`)"
        );
        let missing: String =
            good.lines().filter(|l| !l.starts_with("w ")).map(|l| l.to_string() + "\n").collect();
        assert_eq!(
            UncertainParams::from_text(&missing).unwrap_err(),
            ParameterTextError::Invalid(WhippleError::MissingKey { key: "w" })
        );
        let negative = good.replace("mB = 85.0", "mB = -85.0");
        assert_eq!(
            UncertainParams::from_text(&negative).unwrap_err().to_string(),
            "invalid mB -85.0: must be positive"
        );
    }

    #[test]
    fn toml_is_read_without_uncertainty() {
        let u = UncertainParams::from_any(crate::whipple::BENCHMARK_TOML).expect("valid");
        assert_eq!(u, UncertainParams::exact(WhippleParams::benchmark()));
        assert!(!u.has_uncertainty());
        let t = UncertainParams::from_any(&benchmark_text(0.01)).expect("valid");
        assert!(t.has_uncertainty());
    }
}
