//! Riders from body measurements in Python: Yeadon's human body
//! ([`carvallo::whipple::yeadon`]) alone (`yeadon_human`) and seated on a bicycle as
//! BicycleParameters' `add_rider(reCalc=True)` seats it (`yeadon_rider`, and a Yeadon
//! measurement file as the `rider` of `add_rider` and `load_parameters`).

use carvallo::parameter_text::{UncertainParams, RIDER_NAMES};
use carvallo::whipple::yeadon::{
    bicycleparameters_files, describe, seat_on_bicycle, Configuration, Human, Measurements,
    SeatedRider, SeatingGeometry, Variant, CONFIGURATION_NAMES,
};
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::common::{err, pairs, uncertain_of};
use crate::guard::read_text;

fn variant_of(corrected: bool) -> Variant {
    if corrected {
        Variant::Corrected
    } else {
        Variant::Published
    }
}

/// Yeadon's measurements from the file at `path`.
pub(crate) fn measurements_at(path: &str) -> PyResult<Measurements> {
    let text = read_text(path, "Yeadon measurement")?;
    Measurements::from_text(&text)
        .map_err(|e| err(format!("invalid Yeadon measurement file `{path}`: {e}")))
}

/// Whether the file at `path` is a Yeadon measurement file (not a BicycleParameters rider file);
/// read through [`read_text`]'s bound, so an endless device is not one (and the rider file's
/// reader then names it).
pub(crate) fn is_measurement_file(path: &str) -> bool {
    read_text(path, "Yeadon measurement").is_ok_and(|t| Measurements::looks_like(&t))
}

/// yeadon's configuration file at `path`.
fn configuration_at(path: &str) -> PyResult<Configuration> {
    let text = read_text(path, "Yeadon configuration")?;
    Configuration::from_text(&text)
        .map_err(|e| err(format!("invalid Yeadon configuration file `{path}`: {e}")))
}

/// A configuration: a path to yeadon's configuration file (all 21 angles) or a dict of some of
/// the angles (the others zero); `None` is the zero configuration.
fn configuration_of(cfg: Option<&Bound<'_, PyAny>>) -> PyResult<Configuration> {
    let Some(cfg) = cfg.filter(|c| !c.is_none()) else {
        return Ok(Configuration::default());
    };
    if let Ok(path) = cfg.extract::<std::path::PathBuf>() {
        return configuration_at(&path.display().to_string());
    }
    let mut c = Configuration::default();
    for (name, v) in pairs(cfg, "configuration")? {
        if !v.is_finite() {
            return Err(err(format!("invalid joint angle {name} {v:?}: must be finite")));
        }
        if !c.set(&name, v) {
            return Err(err(format!(
                "unknown joint angle {name} = {v:?} (the names are {})",
                CONFIGURATION_NAMES.join(", ")
            )));
        }
    }
    Ok(c)
}

fn mass_properties_dict<'py>(
    py: Python<'py>,
    p: &carvallo::whipple::yeadon::MassProperties,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("mass", p.mass)?;
    d.set_item("center_of_mass", PyArray1::from_vec(py, p.centre.to_vec()))?;
    let rows: Vec<Vec<f64>> = p.inertia.iter().map(|r| r.to_vec()).collect();
    d.set_item("inertia", PyArray2::from_vec2(py, &rows).map_err(|e| err(e.to_string()))?)?;
    Ok(d)
}

/// Yeadon's human body from the measurement file `measurements` in the configuration
/// `configuration` (a yeadon configuration file, a dict of joint angles in radians, the others
/// zero, or None for all zero), as `yeadon.Human(measurements, configuration)`: a dict with
/// `mass` (kg), `center_of_mass` (3,) from the centre of the lowest torso stadium and `inertia`
/// (3, 3) about the mass centre, in yeadon's frame (x left, y forward, z up), `density_scale`
/// (the factor on Dempster's densities that gives the measured mass) and `notes` (impossible
/// stadia taken as circles, angles out of yeadon's bounds). `corrected=True` computes three
/// things yeadon 2.0.1 gets wrong as they are (see the guide).
#[pyfunction]
#[pyo3(signature = (measurements, configuration = None, corrected = false))]
fn yeadon_human<'py>(
    py: Python<'py>,
    measurements: &str,
    configuration: Option<&Bound<'py, PyAny>>,
    corrected: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let meas = measurements_at(measurements)?;
    let cfg = configuration_of(configuration)?;
    let human = Human::new(&meas, variant_of(corrected))
        .map_err(|e| err(format!("invalid Yeadon measurement file `{measurements}`: {e}")))?;
    let d = mass_properties_dict(py, &human.mass_properties(&cfg))?;
    d.set_item("density_scale", human.density_scale())?;
    let mut notes = human.notes().to_vec();
    notes.extend(cfg.out_of_bounds());
    d.set_item("notes", PyList::new(py, notes)?)?;
    Ok(d)
}

/// Seats the body of the Yeadon measurement file `meas_path` on the bicycle `u` with the
/// configuration and measured geometry given, or found by BicycleParameters' layout beside
/// `meas_path` and `model_path`.
pub(crate) fn seat(
    u: &UncertainParams,
    meas_path: &str,
    configuration: Option<&Bound<'_, PyAny>>,
    measured: Option<&str>,
    model_path: Option<&str>,
    corrected: bool,
) -> PyResult<SeatedRider> {
    let layout = model_path.and_then(|m| {
        bicycleparameters_files(std::path::Path::new(meas_path), std::path::Path::new(m))
    });
    let needs = |what: &str| {
        err(format!(
            "the Yeadon measurement file `{meas_path}` needs {what} to seat the rider on the \
             bicycle (BicycleParameters' layout names none here)"
        ))
    };
    let cfg = match configuration.filter(|c| !c.is_none()) {
        Some(c) => configuration_of(Some(c))?,
        None => {
            let path = layout
                .as_ref()
                .map(|(c, _)| c.display().to_string())
                .ok_or_else(|| needs("configuration= (a yeadon configuration file or dict)"))?;
            configuration_at(&path)?
        }
    };
    let measured_path = match measured {
        Some(m) => m.to_string(),
        None => layout
            .as_ref()
            .map(|(_, m)| m.display().to_string())
            .ok_or_else(|| needs("measured= (the bicycle's <name>Measured.txt)"))?,
    };
    let text = read_text(&measured_path, "measured geometry")?;
    let g = SeatingGeometry::from_measured(&text, &u.params)
        .map_err(|e| err(format!("invalid measured geometry file `{measured_path}`: {e}")))?;
    let meas = measurements_at(meas_path)?;
    seat_on_bicycle(&meas, &cfg, &g, variant_of(corrected))
        .map_err(|e| err(format!("invalid Yeadon rider `{meas_path}` on `{measured_path}`: {e}")))
}

/// The rider of the Yeadon measurement file `measurements` seated on the bicycle `params` as
/// BicycleParameters' `Bicycle.add_rider(name, reCalc=True)` seats it: `configuration` is
/// yeadon's configuration file (or a dict; its somersault and the angles the seating does not
/// set are used), `measured` the bicycle's `<name>Measured.txt` (seat, bottom bracket and
/// handlebar geometry). The 13 joint angles are solved by Newton's method to rounding. Returns a
/// dict: `rider` (`mB, xB, yB, zB, IBxx, IBxz, IByy, IBzz` in the bicycle's frame, as
/// `add_rider` takes), `configuration` (the 21 angles), `body` (mass, centre of mass from the
/// top of the seat post and inertia in yeadon's frame), `hands` (alpha_y, alpha_z, beta_y,
/// beta_z), `residual`, `iterations`, `notes` and `description`.
#[pyfunction]
#[pyo3(signature = (params, measurements, configuration, measured, corrected = false))]
fn yeadon_rider<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    measurements: &str,
    configuration: &Bound<'py, PyAny>,
    measured: &str,
    corrected: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let u = uncertain_of(params, None, false, false)?;
    let s = seat(&u, measurements, Some(configuration), Some(measured), None, corrected)?;
    let d = PyDict::new(py);
    let rider = PyDict::new(py);
    for (name, v) in RIDER_NAMES.iter().zip(s.rider.values) {
        rider.set_item(*name, v)?;
    }
    d.set_item("rider", rider)?;
    let cfg = PyDict::new(py);
    for (name, v) in CONFIGURATION_NAMES.iter().zip(s.configuration.angles) {
        cfg.set_item(*name, v)?;
    }
    d.set_item("configuration", cfg)?;
    d.set_item("body", mass_properties_dict(py, &s.body)?)?;
    d.set_item("hands", PyArray1::from_vec(py, s.hands.to_vec()))?;
    d.set_item("residual", s.residual)?;
    d.set_item("iterations", s.iterations)?;
    d.set_item("notes", PyList::new(py, &s.notes)?)?;
    d.set_item("description", describe(&s))?;
    Ok(d)
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(yeadon_human, m)?)?;
    m.add_function(wrap_pyfunction!(yeadon_rider, m)?)?;
    Ok(())
}
