//! Riders from body measurements: Yeadon's inertia model of the human body (M. R. Yeadon, *The
//! simulation of aerial movement — II. A mathematical inertia model of the human body*, J.
//! Biomechanics 23(1), 1990, 67–74), ported from the Python package `yeadon` 2.0.1 (Dembia,
//! Moore, Hubbard 2014), and the seated configuration of BicycleParameters 1.5.2
//! (`rider.configure_rider`) that puts that body on a bicycle, hands on the handlebar.
//!
//! - [`Measurements`] reads yeadon's measurement file (95 lengths, perimeters, widths and depths
//!   and the total mass, YAML `name: value` lines), [`Configuration`] its configuration file
//!   (21 joint angles);
//! - [`Human`] builds the 40 solids (stadium solids and the head's semi-ellipsoid,
//!   [`solid`]) and the 11 segments (pelvis, thorax, chest-head, upper arms, forearm-hands,
//!   thighs, shank-feet) with yeadon's segmental densities (Dempster), scaled so that the body
//!   has the measured mass, and gives the whole body's mass, mass centre and inertia for a
//!   configuration ([`Human::mass_properties`]);
//! - [`seated`] solves the joint angles that seat it on a bicycle of given measured geometry
//!   and returns the rider's rigid body in the bicycle's frame, to be added to the rear frame as
//!   `Bicycle.add_rider(reCalc=True)` does.
//!
//! yeadon 2.0.1 computes three things otherwise than the integrals it states; they are kept in
//! [`Variant::Published`] so that the results equal the peer's, and corrected in
//! [`Variant::Corrected`]. See [`Variant`].

pub mod human;
pub mod seated;
pub mod solid;

use std::fmt;

use crate::error::ParameterError;

pub use human::{Human, MassProperties};
pub use seated::{
    bicycleparameters_files, describe, seat_on_bicycle, SeatedRider, SeatingGeometry,
};

/// Which computation of yeadon's solids and segments to use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Variant {
    /// As yeadon 2.0.1 computes (the peer of BicycleParameters' `add_rider(reCalc=True)`),
    /// including three errors this port's tests found: a truncated cone's mass centre measured
    /// from the wrong end (every limb solid between two circles), a stadium solid's $I_x$ with
    /// $r t^3$ for $r^3 t$ (the torso, hands and feet), and each segment's inertia carried into
    /// the body frame as $R^T I R$ instead of $R I R^T$ (its products of inertia take the
    /// sign of the opposite rotation).
    #[default]
    Published,
    /// The integrals and rotations as they are.
    Corrected,
}

/// Why a Yeadon measurement or configuration file, or a seating, was refused.
#[derive(Clone, Debug, PartialEq)]
pub enum YeadonError {
    /// A line that is not `name: value` with a known name and a number.
    Line {
        /// The 1-based line number.
        line: usize,
        /// The line (trimmed).
        text: String,
        /// What is wrong.
        reason: String,
    },
    /// A name the file must have is missing.
    Missing {
        /// The name.
        key: &'static str,
        /// Which file.
        file: &'static str,
    },
    /// A value that gives no body (a non-positive length, an impossible stadium).
    Parameter(ParameterError),
    /// The seating equations have no solution near BicycleParameters' initial guess.
    NoSeating {
        /// The residual's largest component at the last iterate (m or rad).
        residual: f64,
        /// Newton iterations taken.
        iterations: usize,
    },
}

impl fmt::Display for YeadonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            YeadonError::Line { line, text, reason } => {
                write!(f, "line {line}: {reason} (`{text}`)")
            }
            YeadonError::Missing { key, file } => write!(f, "missing {key} in the {file}"),
            YeadonError::Parameter(e) => write!(f, "{e}"),
            YeadonError::NoSeating { residual, iterations } => write!(
                f,
                "no seating of the rider on the bicycle: the hands do not reach the handlebar \
                 (residual {residual:e} after {iterations} Newton iterations from \
                 BicycleParameters' initial guess)"
            ),
        }
    }
}

impl std::error::Error for YeadonError {}

impl From<ParameterError> for YeadonError {
    fn from(e: ParameterError) -> YeadonError {
        YeadonError::Parameter(e)
    }
}

/// The 95 measurement names of yeadon, in its order (`Human.measnames`): torso `Ls`, left arm
/// `La`, right arm `Lb`, left leg `Lj`, right leg `Lk`; `L` a length, `p` a perimeter, `w` a
/// width, `d` a depth.
pub const MEASUREMENT_NAMES: [&str; 95] = [
    "Ls1L", "Ls2L", "Ls3L", "Ls4L", "Ls5L", "Ls6L", "Ls7L", "Ls8L", "Ls0p", "Ls1p", "Ls2p", "Ls3p",
    "Ls5p", "Ls6p", "Ls7p", "Ls0w", "Ls1w", "Ls2w", "Ls3w", "Ls4w", "Ls4d", "La2L", "La3L", "La4L",
    "La5L", "La6L", "La7L", "La0p", "La1p", "La2p", "La3p", "La4p", "La5p", "La6p", "La7p", "La4w",
    "La5w", "La6w", "La7w", "Lb2L", "Lb3L", "Lb4L", "Lb5L", "Lb6L", "Lb7L", "Lb0p", "Lb1p", "Lb2p",
    "Lb3p", "Lb4p", "Lb5p", "Lb6p", "Lb7p", "Lb4w", "Lb5w", "Lb6w", "Lb7w", "Lj1L", "Lj3L", "Lj4L",
    "Lj5L", "Lj6L", "Lj8L", "Lj9L", "Lj1p", "Lj2p", "Lj3p", "Lj4p", "Lj5p", "Lj6p", "Lj7p", "Lj8p",
    "Lj9p", "Lj8w", "Lj9w", "Lj6d", "Lk1L", "Lk3L", "Lk4L", "Lk5L", "Lk6L", "Lk8L", "Lk9L", "Lk1p",
    "Lk2p", "Lk3p", "Lk4p", "Lk5p", "Lk6p", "Lk7p", "Lk8p", "Lk9p", "Lk8w", "Lk9w", "Lk6d",
];

/// The 21 configuration names of yeadon, in its order (`Human.CFGnames`), radians.
pub const CONFIGURATION_NAMES: [&str; 21] = [
    "somersault",
    "tilt",
    "twist",
    "PTsagittalFlexion",
    "PTbending",
    "TCspinalTorsion",
    "TCsagittalSpinalFlexion",
    "CA1extension",
    "CA1adduction",
    "CA1rotation",
    "CB1extension",
    "CB1abduction",
    "CB1rotation",
    "A1A2extension",
    "B1B2extension",
    "PJ1extension",
    "PJ1adduction",
    "PK1extension",
    "PK1abduction",
    "J1J2flexion",
    "K1K2flexion",
];

/// Yeadon's bounds on the 21 joint angles (`Human.CFGbounds`), in multiples of $\pi$; a
/// configuration outside them is computed, with a note, as yeadon does.
const CONFIGURATION_BOUNDS: [(f64, f64); 21] = [
    (-1.0, 1.0),
    (-1.0, 1.0),
    (-1.0, 1.0),
    (-0.5, 1.0),
    (-0.5, 0.5),
    (-0.5, 0.5),
    (-0.5, 0.5),
    (-1.0, 0.5),
    (-1.5, 0.5),
    (-1.0, 1.0),
    (-1.0, 0.5),
    (-0.5, 1.5),
    (-1.0, 1.0),
    (-1.0, 0.0),
    (-1.0, 0.0),
    (-1.0, 0.5),
    (-0.5, 0.5),
    (-1.0, 0.5),
    (-0.5, 0.5),
    (0.0, 1.0),
    (0.0, 1.0),
];

/// Runs `f` on each `name: value` line of a YAML file of numbers as yeadon writes them (`#`
/// comments, blank lines), with the 1-based line number.
fn for_each_entry(
    text: &str,
    mut f: impl FnMut(usize, &str, &str, f64) -> Result<(), YeadonError>,
) -> Result<(), YeadonError> {
    for (i, raw) in text.lines().enumerate() {
        let line = match raw.find('#') {
            Some(k) => &raw[..k],
            None => raw,
        }
        .trim();
        if line.is_empty() {
            continue;
        }
        let bad = |reason: String| YeadonError::Line {
            line: i + 1,
            text: raw.trim().chars().take(80).collect(),
            reason,
        };
        let (name, value) =
            line.split_once(':').ok_or_else(|| bad("expected `name: value`".to_string()))?;
        let (name, value) = (name.trim(), value.trim());
        let v: f64 = value
            .parse()
            .ok()
            .filter(|v: &f64| v.is_finite())
            .ok_or_else(|| bad(format!("{name}: `{value}` is not a finite number")))?;
        f(i + 1, name, raw.trim(), v)?;
    }
    Ok(())
}

/// Yeadon's 95 body measurements in metres (the file's values times its
/// `measurementconversionfactor`) and the measured total mass, if given.
#[derive(Clone, Debug, PartialEq)]
pub struct Measurements {
    /// The values in the order of [`MEASUREMENT_NAMES`] (m).
    pub values: [f64; 95],
    /// The measured total mass (kg, the file's `totalmass`): the densities are scaled to give
    /// it. `None` (no `totalmass`, or one not positive: yeadon writes -1 for "not measured")
    /// leaves yeadon's densities as they are.
    pub total_mass: Option<f64>,
}

impl Measurements {
    /// Reads yeadon's measurement file (`<rider>YeadonMeas.txt`): `name: value` lines (YAML,
    /// `#` comments), the 95 names of [`MEASUREMENT_NAMES`] each once and positive,
    /// `measurementconversionfactor` (the unit in metres: `.01` for centimetres) and optionally
    /// `totalmass` (kg; not positive: not measured).
    ///
    /// # Errors
    /// [`YeadonError::Line`] naming the line (an unknown or repeated name, a value that is not
    /// a positive number); [`YeadonError::Missing`] for a missing measurement or conversion
    /// factor.
    pub fn from_text(text: &str) -> Result<Measurements, YeadonError> {
        let mut values = [f64::NAN; 95];
        let mut factor = None;
        let mut total_mass = None;
        for_each_entry(text, |line, name, raw, v| {
            let bad = |reason: String| YeadonError::Line { line, text: raw.to_string(), reason };
            match name {
                "measurementconversionfactor" => {
                    if v <= 0.0 {
                        return Err(bad(format!("{name}: {v:?} must be positive")));
                    }
                    factor = Some(v);
                }
                // yeadon's "not measured" is -1 (it scales only by a positive mass).
                "totalmass" => total_mass = (v > 0.0).then_some(v),
                _ => {
                    let k = MEASUREMENT_NAMES.iter().position(|n| *n == name).ok_or_else(|| {
                        bad(format!("`{name}` is not one of yeadon's 95 measurements"))
                    })?;
                    if !values[k].is_nan() {
                        return Err(bad(format!("measurement `{name}` given twice")));
                    }
                    if v <= 0.0 {
                        return Err(bad(format!("{name}: {v:?} must be positive")));
                    }
                    values[k] = v;
                }
            }
            Ok(())
        })?;
        if let Some(k) = values.iter().position(|v| v.is_nan()) {
            return Err(YeadonError::Missing {
                key: MEASUREMENT_NAMES[k],
                file: "measurement file",
            });
        }
        let factor = factor.ok_or(YeadonError::Missing {
            key: "measurementconversionfactor",
            file: "measurement file",
        })?;
        Ok(Measurements { values: values.map(|v| v * factor), total_mass })
    }

    /// Whether `text` looks like a Yeadon measurement file (it names `Ls1L` and `La2L` as
    /// `name:`), to tell it from a BicycleParameters rider file.
    pub fn looks_like(text: &str) -> bool {
        let has = |key: &str| {
            text.lines().any(|l| {
                l.trim_start().strip_prefix(key).is_some_and(|r| r.trim_start().starts_with(':'))
            })
        };
        has("Ls1L") && has("La2L")
    }

    /// The measurement `name` (m), `NaN` for a name that is not one.
    pub fn get(&self, name: &str) -> f64 {
        MEASUREMENT_NAMES.iter().position(|n| *n == name).map_or(f64::NAN, |k| self.values[k])
    }

    /// Sets the measurement `name`; `false` if it is not one.
    pub fn set(&mut self, name: &str, value: f64) -> bool {
        match MEASUREMENT_NAMES.iter().position(|n| *n == name) {
            Some(k) => {
                self.values[k] = value;
                true
            }
            None => false,
        }
    }
}

/// Yeadon's 21 joint angles (radians), in the order of [`CONFIGURATION_NAMES`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Configuration {
    /// The angles.
    pub angles: [f64; 21],
}

impl Configuration {
    /// Reads yeadon's configuration file (`<rider><bicycle>YeadonCFG.txt`): `name: value`
    /// lines, each of the 21 names of [`CONFIGURATION_NAMES`] once (as yeadon requires).
    ///
    /// # Errors
    /// [`YeadonError::Line`] for an unknown or repeated name or a value that is not a number;
    /// [`YeadonError::Missing`] for a missing angle.
    pub fn from_text(text: &str) -> Result<Configuration, YeadonError> {
        let mut angles = [f64::NAN; 21];
        for_each_entry(text, |line, name, raw, v| {
            let bad = |reason: String| YeadonError::Line { line, text: raw.to_string(), reason };
            let k = CONFIGURATION_NAMES
                .iter()
                .position(|n| *n == name)
                .ok_or_else(|| bad(format!("`{name}` is not one of yeadon's 21 joint angles")))?;
            if !angles[k].is_nan() {
                return Err(bad(format!("joint angle `{name}` given twice")));
            }
            angles[k] = v;
            Ok(())
        })?;
        if let Some(k) = angles.iter().position(|v| v.is_nan()) {
            return Err(YeadonError::Missing {
                key: CONFIGURATION_NAMES[k],
                file: "configuration file",
            });
        }
        Ok(Configuration { angles })
    }

    /// The angle `name` (rad), `NaN` for a name that is not one.
    pub fn get(&self, name: &str) -> f64 {
        CONFIGURATION_NAMES.iter().position(|n| *n == name).map_or(f64::NAN, |k| self.angles[k])
    }

    /// Sets the angle `name`; `false` if it is not one.
    pub fn set(&mut self, name: &str, value: f64) -> bool {
        match CONFIGURATION_NAMES.iter().position(|n| *n == name) {
            Some(k) => {
                self.angles[k] = value;
                true
            }
            None => false,
        }
    }

    /// The angles outside yeadon's bounds, as notes (yeadon prints them and computes anyway).
    pub fn out_of_bounds(&self) -> Vec<String> {
        let pi = std::f64::consts::PI;
        (0..21)
            .filter_map(|k| {
                let (lo, hi) = CONFIGURATION_BOUNDS[k];
                let x = self.angles[k];
                (x < lo * pi || x > hi * pi).then(|| {
                    format!(
                        "joint angle {} = {x:?} rad is outside yeadon's bounds [{lo}π, {hi}π]",
                        CONFIGURATION_NAMES[k]
                    )
                })
            })
            .collect()
    }
}
