//! The Python module `carvallo` (PyO3): thin wrappers over the runtime crate, numpy arrays in
//! and out, every error a `carvallo.ParameterError` (a `ValueError`) whose message names the key
//! and the value. `carvallo.pyi` beside `Cargo.toml` gives the types.
//!
//! Every function that takes parameters takes a dict of numbers, a dict of `uncertainties`
//! ufloats or a `bicycleparameters.Bicycle` (see `common`), read as the parameter files are read
//! (`load_parameters`, the command line's `--model`, `yB` and the other extra keys included): moments of inertia that break a triangle
//! inequality are computed as given with a `carvallo.PhysicsWarning` naming the parameter and
//! the relative violation, or refused with `strict=True` (the command line's `--strict`).

use std::sync::atomic::AtomicUsize;

use crate::guard::{arg, interruptible, read_text, within};
use carvallo::numerics::integrate::{Grid, Integration};
use carvallo::parameter_text::{Rider, UncertainParams, RIDER_NAMES};
use carvallo::sweep::Method;
use carvallo::whipple::{StabilityWindow, Whipple, WhippleParams, FIELD_PATHS, PARAM_NAMES};
use carvallo::whipple_nonlinear::{Feedback, Stop, WhippleNonlinear};
use carvallo::whipple_uncertainty as unc;
use numpy::{
    Complex64, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2,
    PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::{IntoPyDict, PyDict, PyList};

use crate::common::{
    cut_short, err, integration_of, pairs, params_of, set_run, uncertain_of, warn_all, Covariance,
    OrBad, ParameterError, PhysicsWarning,
};
use carvallo::whipple::transfer::FrequencyPoint;

fn dict_of<'py>(py: Python<'py>, values: &[f64; 26]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (name, v) in crate::pairs_of(values) {
        d.set_item(name, v)?;
    }
    Ok(d)
}

/// A number or a 1-d sequence of numbers (`name`: the argument, in errors).
fn number_or_numbers(x: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<f64>> {
    // Bytes are a sequence of small integers to pyo3: b"\xff" would read as [255.0].
    if x.is_instance_of::<pyo3::types::PyBytes>() || x.is_instance_of::<pyo3::types::PyString>() {
        let shown = x.repr().map_or_else(|_| "?".to_string(), |r| r.to_string());
        return Err(err(format!(
            "invalid {name} {shown}: must be a number or a 1-d sequence of numbers"
        )));
    }
    match x.extract::<f64>() {
        Ok(v) => Ok(vec![v]),
        Err(e) if cut_short(&e) => Err(e),
        Err(_) => x.extract().or_bad(|| {
            let shown = x.repr().map_or_else(|_| "?".to_string(), |r| r.to_string());
            err(format!("invalid {name} {shown}: must be a number or a 1-d sequence of numbers"))
        }),
    }
}

pub(crate) fn speeds_of(speeds: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    let v = number_or_numbers(speeds, "speeds")?;
    if let Some(x) = v.iter().find(|x| !x.is_finite()) {
        return Err(err(format!("invalid speed {x}: must be finite")));
    }
    Ok(v)
}

/// The benchmark bicycle of Meijaard et al. (2007), `{name: value}` in the benchmark's names.
#[pyfunction]
fn benchmark(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    dict_of(py, WhippleParams::benchmark().values())
}

/// The parameters by name (`carvallo::whipple::BicycleDesign`): `wheelbase`, `trail`,
/// `steer_axis_tilt`, `gravity` and the dicts `rear_wheel`, `front_wheel` (`radius`, `mass`,
/// `ixx`, `iyy`) and `rear_frame`, `front_frame` (`x`, `z`, `mass`, `ixx`, `iyy`, `izz`,
/// `ixz`), validated as every parameter dict.
#[pyfunction]
#[pyo3(signature = (params, strict = false))]
fn design<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let values = params_of(params, strict)?.design().to_array();
    let d = PyDict::new(py);
    for (path, v) in FIELD_PATHS.iter().zip(values) {
        match path.split_once('.') {
            None => d.set_item(*path, v)?,
            Some((part, field)) => {
                let sub = match d.get_item(part)? {
                    Some(sub) => sub.cast_into::<PyDict>()?,
                    None => {
                        let sub = PyDict::new(py);
                        d.set_item(part, &sub)?;
                        sub
                    }
                };
                sub.set_item(field, v)?;
            }
        }
    }
    Ok(d)
}

/// Reads a parameter file: the anchors TOML format or BicycleParameters' `name = value+/-sigma`
/// text, with the rider file `rider` (BicycleParameters' `mB, xB, yB, zB, IBxx, IBxz, IByy,
/// IBzz`) added to the rear frame. Moments of inertia breaking a triangle inequality are a
/// `carvallo.PhysicsWarning` (`warnings.warn`), or an error when `strict`. Returns
/// `(params, sigma)`, two dicts.
///
/// `rider` may also be a Yeadon measurement file (`<rider>YeadonMeas.txt`): the body is seated
/// on the bicycle as `Bicycle.add_rider(name, reCalc=True)` seats it (see `yeadon_rider`), with
/// `configuration` (yeadon's configuration file or a dict) and `measured` (the bicycle's
/// `<name>Measured.txt`), each found by BicycleParameters' data layout when not given.
#[pyfunction]
#[pyo3(signature = (path, rider=None, strict=false, configuration=None, measured=None))]
fn load_parameters<'py>(
    py: Python<'py>,
    path: &str,
    rider: Option<&str>,
    strict: bool,
    configuration: Option<&Bound<'py, PyAny>>,
    measured: Option<&str>,
) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
    let read = read_text;
    let text = read(path, "parameter")?;
    let invalid = |e: carvallo::parameter_text::ParameterTextError| {
        err(format!("invalid parameter file `{path}`: {e}"))
    };
    let mut loaded = if text.lines().any(|l| l.trim_start().starts_with('[')) {
        carvallo::parameter_text::Loaded {
            params: UncertainParams::from_any(&text).map_err(invalid)?,
            warnings: Vec::new(),
        }
    } else {
        UncertainParams::read(&text, strict).map_err(invalid)?
    };
    if let Some(r) = rider {
        let rider = if crate::yeadon::is_measurement_file(r) {
            crate::yeadon::seat(&loaded.params, r, configuration, measured, Some(path), false)?
                .rider
        } else {
            Rider::from_text(&read(r, "rider")?)
                .map_err(|e| err(format!("invalid rider file `{r}`: {e}")))?
        };
        loaded = carvallo::parameter_text::add_rider(&loaded.params, &rider)
            .map_err(|e| err(format!("invalid rider file `{r}` on `{path}`: {e}")))?;
        if strict {
            if let Some(w) = loaded.warnings.first() {
                return Err(err(format!("invalid parameter file `{path}` with rider `{r}`: {w}")));
            }
        }
    }
    warn_all(py, path, &loaded.warnings)?;
    let u = loaded.params;
    Ok((dict_of(py, u.params.values())?, dict_of(py, &u.sigma)?))
}

/// The bicycle `params` (with the standard deviations `sigma`, none if omitted) with a rider
/// added to its rear frame, as `load_parameters(path, rider=...)` and BicycleParameters'
/// `Bicycle.add_rider` do: `rider` is the path of a BicycleParameters rider file or a dict of
/// `mB, xB, yB, zB, IBxx, IBxz, IByy, IBzz` (the rider's body in the bicycle's frame, inertia
/// about its mass centre; no uncertainty). A broken triangle inequality of the combined frame is
/// a `PhysicsWarning`, or an error when `strict`. Returns `(params, sigma)`.
///
/// `rider` may also be a Yeadon measurement file, seated on this bicycle with `configuration`
/// (yeadon's configuration file or a dict) and `measured` (the bicycle's `<name>Measured.txt`)
/// as `Bicycle.add_rider(name, reCalc=True)` seats it (see `yeadon_rider`).
#[pyfunction]
#[pyo3(signature = (params, rider, sigma = None, strict = false, configuration = None, measured = None))]
fn add_rider<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    rider: &Bound<'py, PyAny>,
    sigma: Option<&Bound<'py, PyAny>>,
    strict: bool,
    configuration: Option<&Bound<'py, PyAny>>,
    measured: Option<&str>,
) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
    let u = uncertain_of(params, sigma, strict, false)?;
    let yeadon = rider
        .extract::<std::path::PathBuf>()
        .ok()
        .map(|p| p.display().to_string())
        .filter(|p| crate::yeadon::is_measurement_file(p));
    let (rider, what) = match yeadon {
        Some(path) => {
            let seated = crate::yeadon::seat(&u, &path, configuration, measured, None, false)?;
            (seated.rider, format!("Yeadon rider `{path}`"))
        }
        None => rider_of(rider)?,
    };
    let loaded = carvallo::parameter_text::add_rider(&u, &rider)
        .map_err(|e| err(format!("invalid {what}: {e}")))?;
    if strict {
        if let Some(w) = loaded.warnings.first() {
            return Err(err(format!("invalid params with the {what}: {w}")));
        }
    }
    warn_all(py, &format!("params with the {what}"), &loaded.warnings)?;
    let u = loaded.params;
    Ok((dict_of(py, u.params.values())?, dict_of(py, &u.sigma)?))
}

/// A rider: the path of a BicycleParameters rider file or a dict of its eight values; with the
/// words naming it in errors.
fn rider_of(rider: &Bound<'_, PyAny>) -> PyResult<(Rider, String)> {
    Ok(if let Ok(path) = rider.extract::<std::path::PathBuf>() {
        let path = path.display().to_string();
        let text = read_text(&path, "rider")?;
        let r = Rider::from_text(&text)
            .map_err(|e| err(format!("invalid rider file `{path}`: {e}")))?;
        (r, format!("rider file `{path}`"))
    } else {
        let mut values = [f64::NAN; 8];
        let mut seen = [false; 8];
        for (name, v) in pairs(rider, "rider")? {
            let k = RIDER_NAMES.iter().position(|n| *n == name).ok_or_else(|| {
                err(format!(
                    "unknown rider parameter {name} = {v:?} (the names are {})",
                    RIDER_NAMES.join(", ")
                ))
            })?;
            if !v.is_finite() {
                return Err(err(format!("invalid rider {name} {v:?}: must be finite")));
            }
            (values[k], seen[k]) = (v, true);
        }
        if let Some(k) = seen.iter().position(|s| !s) {
            return Err(err(format!("missing rider parameter {}", RIDER_NAMES[k])));
        }
        for k in [0, 4, 6, 7] {
            if values[k] <= 0.0 {
                return Err(err(format!(
                    "invalid rider {} {:?}: must be positive (the rider's mass and principal moments)",
                    RIDER_NAMES[k], values[k]
                )));
            }
        }
        (Rider { values, sigma: [0.0; 8] }, "rider".to_string())
    })
}

/// The side view of the bicycle `params` for a geometry drawing, with the rider `rider` (a
/// rider file or dict, as `add_rider` takes) drawn apart: the points the command line's
/// `carvallo plot geometry` draws (`carvallo::whipple::drawing::SideView`), each `[x, h]` in
/// metres (x forward from the rear contact, h the height): `rear_contact`, `rear_hub`,
/// `front_contact`, `front_hub`, the radii `rear_radius` and `front_radius`, the segments
/// `steer_axis`, `trail` and `fork` (2 x 2), the schematic `frame` (3 x 2: rear hub, foot of the
/// front hub on the steer axis, top of the axis), `mass_centres` (`{name: [x, h]}`: rear wheel,
/// rear frame, front frame, front wheel, rider, whole bicycle) and `masses` (`{name: kg}`).
#[pyfunction]
#[pyo3(signature = (params, rider = None, strict = false))]
fn geometry<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    rider: Option<&Bound<'py, PyAny>>,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let p = params_of(params, strict)?;
    let rider = rider.filter(|r| !r.is_none()).map(rider_of).transpose()?.map(|(r, _)| r);
    let v = carvallo::whipple::drawing::SideView::new(&p, rider.as_ref());
    let d = PyDict::new(py);
    let point = |x: [f64; 2]| PyArray1::from_vec(py, x.to_vec());
    let rows = |r: &[[f64; 2]]| {
        let rows: Vec<Vec<f64>> = r.iter().map(|x| x.to_vec()).collect();
        PyArray2::from_vec2(py, &rows).map_err(|e| err(e.to_string()))
    };
    d.set_item("rear_contact", point(v.rear_contact))?;
    d.set_item("rear_hub", point(v.rear_hub))?;
    d.set_item("rear_radius", v.rear_radius)?;
    d.set_item("front_contact", point(v.front_contact))?;
    d.set_item("front_hub", point(v.front_hub))?;
    d.set_item("front_radius", v.front_radius)?;
    d.set_item("steer_axis", rows(&v.steer_axis)?)?;
    d.set_item("trail", rows(&v.trail)?)?;
    d.set_item("fork", rows(&v.fork)?)?;
    d.set_item("frame", rows(&v.frame)?)?;
    let (centres, masses) = (PyDict::new(py), PyDict::new(py));
    for m in &v.mass_centres {
        centres.set_item(m.name, point(m.at))?;
        masses.set_item(m.name, m.mass)?;
    }
    d.set_item("mass_centres", centres)?;
    d.set_item("masses", masses)?;
    Ok(d)
}

/// The benchmark parameters computed from BicycleParameters' raw measurements (the file
/// `RawData/<name>Measured.txt` at `path`) as `Bicycle(name, pathToData, forceRawCalc=True)`
/// computes them: `(params, sigma)`, two dicts, the standard deviations from the measurements'
/// by linear propagation. A front frame measured in two parts, a flywheel or a frame hung in
/// more than three orientations is a `ParameterError` naming the key.
#[pyfunction]
fn parameters_from_raw<'py>(
    py: Python<'py>,
    path: &str,
) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
    let text = crate::guard::read_text(path, "raw measurement")?;
    let raw = carvallo::whipple::raw::benchmark_from_measured(&text)
        .map_err(|e| err(format!("invalid raw measurement file `{path}`: {e}")))?;
    let u = raw.params;
    Ok((dict_of(py, u.params.values())?, dict_of(py, &u.sigma)?))
}

/// Parses a parameter text (either format, see `load_parameters`).
#[pyfunction]
fn parse_parameters<'py>(
    py: Python<'py>,
    text: &str,
) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
    let u =
        UncertainParams::from_any(text).map_err(|e| err(format!("invalid parameter text: {e}")))?;
    Ok((dict_of(py, u.params.values())?, dict_of(py, &u.sigma)?))
}

/// `{"M", "C1", "K0", "K2"}`: the 2x2 matrices of the linearised equations.
#[pyfunction]
#[pyo3(signature = (params, strict = false))]
fn matrices<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let m = Whipple::new(params_of(params, strict)?).matrices();
    let d = PyDict::new(py);
    for (name, a) in [("M", m.m), ("C1", m.c1), ("K0", m.k0), ("K2", m.k2)] {
        let rows: Vec<Vec<f64>> = a.iter().map(|r| r.to_vec()).collect();
        d.set_item(name, PyArray2::from_vec2(py, &rows).map_err(|e| err(e.to_string()))?)?;
    }
    Ok(d)
}

/// The 4x4 state matrix of (lean, steer, lean rate, steer rate) at `speed`; an array of speeds
/// gives shape (n, 4, 4).
#[pyfunction]
#[pyo3(signature = (params, speed, strict = false))]
fn state_matrix<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    speed: &Bound<'py, PyAny>,
    strict: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let bike = Whipple::new(params_of(params, strict)?);
    let scalar = speed.extract::<f64>().is_ok();
    let speeds = speeds_of(speed)?;
    within(&format!("{} speeds", speeds.len()), speeds.len() as f64, 16.0 * 8.0)?;
    let mut flat = Vec::with_capacity(16 * speeds.len());
    for v in &speeds {
        let a = bike.state_matrix(*v);
        for i in 0..4 {
            for j in 0..4 {
                flat.push(a[(i, j)]);
            }
        }
    }
    let arr = PyArray1::from_vec(py, flat);
    if scalar {
        Ok(arr.reshape([4, 4])?.into_any())
    } else {
        Ok(arr.reshape([speeds.len(), 4, 4])?.into_any())
    }
}

/// The state space with roll and steer torque as inputs at each speed: `(A, B)` of shapes
/// (n, 4, 4) and (n, 4, 2), x = (lean, steer, lean rate, steer rate), u = (T_phi, T_delta),
/// C = I, D = 0 (as `carvallo statespace`). For the leaning rider's params (`lean_rider()`),
/// shapes (n, 12, 12) and (n, 12, 3), Moore's 12 states and the torques T4, T7, T9.
#[pyfunction]
#[pyo3(signature = (params, speeds, strict = false))]
fn state_space<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    speeds: &Bound<'py, PyAny>,
    strict: bool,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    if let Some(rider) = crate::lean_rider::rider_of(params)? {
        return crate::lean_rider::state_space(py, &rider, &speeds_of(speeds)?);
    }
    let bike = Whipple::new(params_of(params, strict)?);
    let speeds = speeds_of(speeds)?;
    // The state spaces, then A and B copied out of them.
    let each = std::mem::size_of::<carvallo::whipple::plant::StateSpace>() + 24 * 8;
    within(&format!("{} speeds", speeds.len()), speeds.len() as f64, each as f64)?;
    let spaces = bike.state_spaces(&speeds);
    let a: Vec<f64> = spaces.iter().flat_map(|s| s.a_rows().into_iter().flatten()).collect();
    let b: Vec<f64> = spaces.iter().flat_map(|s| s.b_rows().into_iter().flatten()).collect();
    let n = speeds.len();
    Ok((
        PyArray1::from_vec(py, a).reshape([n, 4, 4])?.into_any(),
        PyArray1::from_vec(py, b).reshape([n, 4, 2])?.into_any(),
    ))
}

/// The response of the linear plant at `speed` to a unit step (`kind="step"`) or unit impulse
/// (`"impulse"`) of the `input` torque ("roll" or "steer") from rest, or from the initial state
/// `x0` (lean, steer, lean rate, steer rate) with no input (`"initial"`), at each of `times`
/// [s]: an (n, 4) array of the state, through the matrix exponential (as
/// `carvallo response --json`; equal to SciPy's `signal.step`, `signal.impulse` and
/// `signal.lsim` on the same A and B).
#[pyfunction]
#[pyo3(signature = (params, speed, times, kind, input = "steer", x0 = None, strict = false))]
#[allow(clippy::too_many_arguments)]
fn time_response<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    #[pyo3(from_py_with = arg::speed)] speed: f64,
    times: &Bound<'py, PyAny>,
    kind: &str,
    input: &str,
    x0: Option<Vec<f64>>,
    strict: bool,
) -> PyResult<Bound<'py, PyAny>> {
    use carvallo::whipple::response::Excitation;
    use carvallo::whipple::transfer::Input;
    let bike = Whipple::new(params_of(params, strict)?);
    let times = number_or_numbers(times, "times")?;
    let input: Input = input
        .parse()
        .map_err(|e: carvallo::whipple::transfer::UnknownSignal| err(e.to_string()))?;
    let excitation = match (kind, x0) {
        ("step", None) => Excitation::Step(input),
        ("impulse", None) => Excitation::Impulse(input),
        ("initial", Some(x)) => {
            let x: [f64; 4] = x.try_into().map_err(|x: Vec<f64>| {
                err(format!(
                    "invalid x0 of {} values: must be 4 (lean, steer, lean rate, steer rate)",
                    x.len()
                ))
            })?;
            Excitation::Initial(x)
        }
        ("initial", None) => return Err(err("kind \"initial\" needs x0")),
        ("step" | "impulse", Some(_)) => {
            return Err(err(format!(
                "invalid x0 with kind {kind:?}: a step or impulse starts from rest"
            )))
        }
        (other, _) => {
            return Err(err(format!(
                "invalid kind {other:?}: expected one of step, impulse, initial"
            )))
        }
    };
    // The states, then the flat copy.
    within(&format!("{} times", times.len()), times.len() as f64, 2.0 * 4.0 * 8.0)?;
    // On a worker, so that Ctrl-C is seen during millions of times (each is independent).
    let xs = interruptible(py, |stop| {
        let mut xs = Vec::with_capacity(times.len());
        for block in times.chunks(1 << 12) {
            if stop.load(std::sync::atomic::Ordering::Relaxed) {
                break;
            }
            xs.extend(bike.time_response(speed, excitation, block)?);
        }
        Ok(xs)
    })?
    .map_err(|e: carvallo::ParameterError| err(e.to_string()))?;
    let n = xs.len();
    let flat: Vec<f64> = xs.into_iter().flatten().collect();
    Ok(PyArray1::from_vec(py, flat).reshape([n, 4])?.into_any())
}

/// The frequency response $G(i\omega)$ from `input` ("roll" or "steer" torque) to `output`
/// ("roll", "steer", "roll-rate", "steer-rate") at every speed and angular frequency (rad/s)
/// (as `carvallo bode --json`): `{"response": complex (n, m), "magnitude_db": (n, m),
/// "phase_deg": (n, m)}` for `n` speeds and `m` frequencies, the phase on the branch continuous
/// in the frequency that lies in (-180°, 180°] as ω -> 0+: the same at a frequency whatever the
/// grid.
#[pyfunction]
#[pyo3(signature = (params, speeds, omegas, input, output, strict = false))]
fn frequency_response<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    speeds: &Bound<'py, PyAny>,
    omegas: &Bound<'py, PyAny>,
    input: &str,
    output: &str,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    use carvallo::whipple::transfer::{Input, Output};
    let rider = crate::lean_rider::rider_of(params)?;
    let bike = match rider {
        None => Some(Whipple::new(params_of(params, strict)?)),
        Some(_) => None,
    };
    let speeds = speeds_of(speeds)?;
    let omegas = number_or_numbers(omegas, "omegas")?;
    if let Some(x) = omegas.iter().find(|x| !(x.is_finite() && **x >= 0.0)) {
        return Err(err(format!("invalid omega {x:?}: must be finite and not negative")));
    }
    // The points, then the response, magnitude and phase copied out of them.
    let each = std::mem::size_of::<carvallo::whipple::transfer::FrequencyPoint>() + 16 + 8 + 8;
    within(
        &format!("{} speeds x {} omegas", speeds.len(), omegas.len()),
        speeds.len() as f64 * omegas.len() as f64,
        each as f64,
    )?;
    // The plant's response at one speed to a block of frequencies.
    type Respond<'a> = Box<dyn Fn(f64, &[f64]) -> Vec<FrequencyPoint> + Sync + 'a>;
    let respond: Respond<'_> = match (&rider, &bike) {
        (Some(rider), _) => {
            let (i, o) = crate::lean_rider::signals(input, output)?;
            Box::new(move |v, block| crate::lean_rider::frequency_response(rider, v, block, i, o))
        }
        (None, Some(bike)) => {
            let input: Input = input
                .parse()
                .map_err(|e: carvallo::whipple::transfer::UnknownSignal| err(e.to_string()))?;
            let output: Output = output
                .parse()
                .map_err(|e: carvallo::whipple::transfer::UnknownSignal| err(e.to_string()))?;
            Box::new(move |v, block| bike.frequency_response(&[v], block, input, output))
        }
        (None, None) => unreachable!("a bicycle or the leaning rider"),
    };
    // On a worker, so that Ctrl-C is seen during millions of points: the speeds one at a time
    // and their frequencies in blocks (each point depends only on its speed and frequency).
    let pts = interruptible(py, |stop| {
        let mut pts = Vec::with_capacity(speeds.len() * omegas.len());
        for v in &speeds {
            for block in omegas.chunks(1 << 14) {
                if stop.load(std::sync::atomic::Ordering::Relaxed) {
                    return pts;
                }
                pts.extend(respond(*v, block));
            }
        }
        pts
    })?;
    let shape = [speeds.len(), omegas.len()];
    let g: Vec<Complex64> = pts.iter().map(|p| Complex64::new(p.re, p.im)).collect();
    let db: Vec<f64> = pts.iter().map(|p| p.magnitude_db).collect();
    let ph: Vec<f64> = pts.iter().map(|p| p.phase_deg).collect();
    let d = PyDict::new(py);
    d.set_item("response", PyArray1::from_vec(py, g).reshape(shape)?)?;
    d.set_item("magnitude_db", PyArray1::from_vec(py, db).reshape(shape)?)?;
    d.set_item("phase_deg", PyArray1::from_vec(py, ph).reshape(shape)?)?;
    Ok(d)
}

/// The gains of a state feedback: a (2, 4) array (rows roll, steer torque; columns roll,
/// steer, roll rate, steer rate) or a dict of gains by name (`k_steer_roll_rate`, ...; the
/// others zero).
fn gains_of(k: &Bound<'_, PyAny>) -> PyResult<carvallo::whipple::feedback::Gains> {
    use carvallo::whipple::feedback::Gains;
    let gains = if k.cast::<PyDict>().is_ok() {
        let pairs = pairs(k, "K")?;
        Gains::from_named(pairs.iter().map(|(n, v)| (n.as_str(), *v)))
            .map_err(|e| err(e.to_string()))?
    } else {
        let bad =
            || err("K must be a (2, 4) array (rows roll, steer torque) or a dict of gains by name");
        let arr = k.py().import("numpy")?.call_method1("asarray", (k, "float64")).or_bad(bad)?;
        let arr: PyReadonlyArray2<f64> = arr.extract().or_bad(bad)?;
        let shape = arr.shape();
        if shape != [2, 4] {
            return Err(err(format!("K must have the shape (2, 4), not {shape:?}")));
        }
        let view = arr.as_array();
        let rows: Vec<Vec<f64>> = (0..2).map(|r| (0..4).map(|c| view[[r, c]]).collect()).collect();
        Gains([0, 1].map(|r| [0, 1, 2, 3].map(|c| rows[r][c])))
    };
    if let Some(x) = gains
        .values()
        .iter()
        .zip(carvallo::whipple::feedback::GAIN_NAMES)
        .find(|(x, _)| !x.is_finite())
    {
        return Err(err(format!("gain {} = {} is not finite", x.1, x.0)));
    }
    gains_within(&gains, "")?;
    Ok(gains)
}

/// The closed-loop stable speed range of the state feedback u = -K x (as `carvallo window
/// --gain ... --json`): `{"from", "to", "stable": [(from, to), ...], "lowest_stable_speed"}`
/// between `vmin` and `vmax` (default: every speed; `None` for an unbounded end). `K` may be a
/// gain table (as `window --gain-table`): a dict with `speed` (increasing) and gains by name,
/// each a sequence of the same length, linearly interpolated; `vmin` and `vmax` default to its
/// speeds, and a range it does not cover is an error. For the leaning rider's params
/// (`lean_rider()`): `K` as in `closed_loop_eigenvalues`, the window of a scan of `vmin` (0) to
/// `vmax` (20) m/s, `{"from", "to", "stable"}`.
#[pyfunction]
#[pyo3(signature = (params, k, vmin = None, vmax = None, strict = false))]
fn closed_loop_window<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    k: &Bound<'py, PyAny>,
    #[pyo3(from_py_with = arg::vmin)] vmin: Option<f64>,
    #[pyo3(from_py_with = arg::vmax)] vmax: Option<f64>,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    if let Some(rider) = crate::lean_rider::rider_of(params)? {
        let k = crate::lean_rider::gains_of(k)?;
        return crate::lean_rider::closed_loop_window(py, &rider, &k, vmin, vmax);
    }
    let bike = Whipple::new(params_of(params, strict)?);
    for (name, x) in [("vmin", vmin), ("vmax", vmax)] {
        match x {
            Some(x) if !x.is_finite() => {
                return Err(err(format!(
                    "invalid {name} {x:?}: must be finite (None for every speed)"
                )))
            }
            Some(x) if !(0.0..=MAX_SPEED).contains(&x) => {
                return Err(err(format!(
                    "invalid {name} {x:?}: must lie within [0, {MAX_SPEED:e}] m/s (beyond it gravity is lost in the rounding of the speed terms)"
                )))
            }
            _ => {}
        }
    }
    let w = match feedback_of(k)? {
        Feedback::Table(table) => {
            // Seconds for millions of rows: Ctrl-C is read between the table's intervals.
            let (lo, hi) = table.span();
            let (from, to) = (vmin.unwrap_or(lo), vmax.unwrap_or(hi));
            interruptible(py, |stop| bike.closed_loop_window_table_until(&table, from, to, stop))?
        }
        Feedback::Constant(gains) => {
            bike.closed_loop_window(&gains, vmin.unwrap_or(0.0), vmax.unwrap_or(f64::INFINITY))
        }
        Feedback::None => unreachable!("feedback_of gives gains or a table"),
    }
    .map_err(|e| err(e.to_string()))?;
    let end = |x: f64| x.is_finite().then_some(x);
    let d = PyDict::new(py);
    d.set_item("from", w.from)?;
    d.set_item("to", end(w.to))?;
    let stable: Vec<(f64, Option<f64>)> = w.stable.iter().map(|&(a, b)| (a, end(b))).collect();
    d.set_item("stable", stable)?;
    d.set_item("lowest_stable_speed", w.lowest_stable_speed())?;
    Ok(d)
}

/// The eigenvalues of the closed loop A - B K at each speed, shape (n, 4) complex, sorted by
/// real then imaginary part; `K` as in [`closed_loop_window`] (a gain table is read at each
/// speed, which it must cover). For the leaning rider's params (`lean_rider()`): shape (n, 6),
/// `K` a dict of gains `k_{roll|steer|lean}_{roll|steer|lean|roll_rate|steer_rate|lean_rate}`
/// or a (3, 6) array.
#[pyfunction]
#[pyo3(signature = (params, k, speeds, strict = false))]
fn closed_loop_eigenvalues<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    k: &Bound<'py, PyAny>,
    speeds: &Bound<'py, PyAny>,
    strict: bool,
) -> PyResult<Bound<'py, PyAny>> {
    if let Some(rider) = crate::lean_rider::rider_of(params)? {
        let k = crate::lean_rider::gains_of(k)?;
        let speeds = speeds_of(speeds)?;
        return Ok(crate::lean_rider::eigenvalues_with(py, &rider, &k, &speeds)?.into_any());
    }
    let bike = Whipple::new(params_of(params, strict)?);
    let feedback = feedback_of(k)?;
    let speeds = speeds_of(speeds)?;
    within(&format!("{} speeds", speeds.len()), speeds.len() as f64, 4.0 * 16.0)?;
    // About 1.5 s per million speeds: Ctrl-C is read every 4096 speeds.
    let flat = interruptible(py, |stop| -> Result<Vec<Complex64>, String> {
        let mut flat = Vec::with_capacity(4 * speeds.len());
        for (i, &v) in speeds.iter().enumerate() {
            if i % 4096 == 0 && stop.load(std::sync::atomic::Ordering::Relaxed) {
                break;
            }
            let gains = match &feedback {
                Feedback::Table(table) => table.at(v).ok_or_else(|| {
                    let (lo, hi) = table.span();
                    format!("the gain table covers the speeds {lo} to {hi} m/s, not {v} m/s")
                })?,
                Feedback::Constant(g) => *g,
                Feedback::None => unreachable!("feedback_of gives gains or a table"),
            };
            let ev = bike.closed_loop_eigenvalues(v, &gains);
            if ev.len() != 4 {
                return Err(format!("the eigenvalues did not converge at speed {v}"));
            }
            flat.extend(ev.iter().map(|e| Complex64::new(e.re, e.im)));
        }
        Ok(flat)
    })?
    .map_err(err)?;
    Ok(PyArray1::from_vec(py, flat).reshape([speeds.len(), 4])?.into_any())
}

/// The feedback of `K`: constant gains ([`gains_of`]) or, for a dict with the key `speed`, a
/// gain table (the speeds and, by name, each gain at those speeds; gains not named are zero).
fn feedback_of(k: &Bound<'_, PyAny>) -> PyResult<Feedback> {
    use carvallo::whipple::feedback::{GainTable, Gains};
    let Ok(dict) = k.cast::<PyDict>() else { return Ok(Feedback::Constant(gains_of(k)?)) };
    let Some(speed) = dict.get_item("speed")? else {
        return Ok(Feedback::Constant(gains_of(k)?));
    };
    // Through numpy (`column_of`): a column of millions of values is copied, not converted
    // value by value with the GIL held.
    let column = |name: &str, v: &Bound<'_, PyAny>| -> PyResult<Vec<f64>> {
        column_of(v, &format!("gain table: {name}"))
    };
    // The rows and, while they are read, one column of each gain: checked on the length,
    // before a value is read.
    if let Ok(n) = speed.len() {
        within(
            &format!("a gain table of {n} speeds"),
            n as f64,
            (std::mem::size_of::<(f64, Gains)>() + 8) as f64,
        )?;
    }
    let speeds = column("speed", &speed)?;
    let mut rows: Vec<(f64, Gains)> = speeds.iter().map(|&v| (v, Gains::ZERO)).collect();
    for (key, v) in dict.iter() {
        let name: String = key.extract().or_bad(|| err("gain table: the keys must be strings"))?;
        if name == "speed" {
            continue;
        }
        Gains::index(&name).map_err(|e| err(format!("gain table: {e}")))?;
        let values = column(&name, &v)?;
        if values.len() != speeds.len() {
            return Err(err(format!(
                "gain table: {name} has {} values for {} speeds",
                values.len(),
                speeds.len()
            )));
        }
        for (row, x) in rows.iter_mut().zip(values) {
            let _ = row.1.set(&name, x);
        }
    }
    for (i, (v, g)) in rows.iter().enumerate() {
        if v.abs() > MAX_SPEED {
            return Err(err(format!(
                "gain table: speed {v:?} in row {}: must lie within [-{MAX_SPEED:e}, {MAX_SPEED:e}] m/s",
                i + 1
            )));
        }
        gains_within(g, &format!(" in row {}", i + 1))?;
    }
    GainTable::new(rows).map(Feedback::Table).map_err(|e| err(e.to_string()))
}

/// The largest speed (m/s) of a closed-loop range or gain table, as the command line's
/// `--speed`: beyond it gravity is lost in the rounding of the speed terms.
const MAX_SPEED: f64 = 1e6;

/// The largest gain magnitude, as the command line's `--gain`: beyond it the bicycle's own
/// terms are lost in the rounding of the feedback.
const MAX_GAIN: f64 = 1e12;

/// Refuses a gain above [`MAX_GAIN`] in magnitude, naming it (`whereabouts`: " in row 3").
fn gains_within(g: &carvallo::whipple::feedback::Gains, whereabouts: &str) -> PyResult<()> {
    for (x, name) in g.values().iter().zip(carvallo::whipple::feedback::GAIN_NAMES) {
        if x.abs() > MAX_GAIN {
            return Err(err(format!(
                "gain {name} = {x:?}{whereabouts}: must lie within [-{MAX_GAIN:e}, {MAX_GAIN:e}] (beyond it the bicycle's own terms are lost in the rounding of the feedback)"
            )));
        }
    }
    Ok(())
}

/// The modes at each speed, labelled by continuation in speed (as `carvallo eig --json`):
/// `(labels, eigenvalues, vectors)` with the four labels ("weave", "weave", "capsize",
/// "caster"), the eigenvalues (n, 4) complex and the unit eigenvectors (n, 4, 4) complex in
/// NumPy's convention (`numpy.linalg.eig`): the columns are the vectors, `vectors[k, :, i]` the
/// state (lean, steer, lean rate, steer rate) of mode `i` at speed `k`. For the leaning rider's
/// params (`lean_rider()`): six labels ("weave", "weave", "capsize", "caster", "torso",
/// "torso"), eigenvalues (n, 6) and vectors (n, 6, 6) over roll, steer, lean and their rates.
#[pyfunction]
#[pyo3(signature = (params, speeds, strict = false))]
fn modes<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    speeds: &Bound<'py, PyAny>,
    strict: bool,
) -> PyResult<(Vec<&'static str>, Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    if let Some(rider) = crate::lean_rider::rider_of(params)? {
        return crate::lean_rider::modes(py, &rider, &speeds_of(speeds)?);
    }
    let bike = Whipple::new(params_of(params, strict)?);
    let speeds = speeds_of(speeds)?;
    // The modes (four per speed), then the eigenvalues and vectors copied out of them.
    let each = 4 * std::mem::size_of::<carvallo::whipple::modes::Mode>() + 20 * 16;
    within(&format!("{} speeds", speeds.len()), speeds.len() as f64, each as f64)?;
    let all = bike
        .modes(&speeds)
        .ok_or_else(|| err("the modes cannot be followed to these speeds (more than 200 m/s from the reference speed, or no speed with one complex pair and two real roots)"))?;
    modes_arrays(
        py,
        &all,
        |x| x.label.name(),
        |x| Complex64::new(x.eigenvalue.re, x.eigenvalue.im),
        |x| x.vector.map(|c| Complex64::new(c.re, c.im)),
    )
}

/// The modes of each speed (`N` per speed) as Python's `modes` returns them: the labels, the
/// eigenvalues of shape (n, N) and the vectors of shape (n, N, N), row-major (speed, state,
/// mode), so the columns of each N x N block are the vectors.
pub(crate) fn modes_arrays<'py, M, const N: usize>(
    py: Python<'py>,
    all: &[[M; N]],
    label: impl Fn(&M) -> &'static str,
    eigenvalue: impl Fn(&M) -> Complex64,
    vector: impl Fn(&M) -> [Complex64; N],
) -> PyResult<(Vec<&'static str>, Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    let labels = all.first().map_or(Vec::new(), |m| m.iter().map(&label).collect());
    let ev: Vec<Complex64> = all.iter().flat_map(|m| m.iter().map(&eigenvalue)).collect();
    let mut vecs: Vec<Complex64> = Vec::with_capacity(all.len() * N * N);
    for m in all {
        let columns: Vec<[Complex64; N]> = m.iter().map(&vector).collect();
        for state in 0..N {
            vecs.extend(columns.iter().map(|c| c[state]));
        }
    }
    let n = all.len();
    Ok((
        labels,
        PyArray1::from_vec(py, ev).reshape([n, N])?.into_any(),
        PyArray1::from_vec(py, vecs).reshape([n, N, N])?.into_any(),
    ))
}

/// The eigenvalues at each speed, shape (n, 4) complex, sorted by real then imaginary part (as
/// `carvallo eig`). For the leaning rider's params (`lean_rider()`), the six of roll, steer and
/// lean, shape (n, 6), by decreasing real part.
#[pyfunction]
#[pyo3(signature = (params, speeds, strict = false))]
fn eigenvalues<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    speeds: &Bound<'py, PyAny>,
    strict: bool,
) -> PyResult<Bound<'py, PyArray2<Complex64>>> {
    if let Some(rider) = crate::lean_rider::rider_of(params)? {
        return crate::lean_rider::eigenvalues(py, &rider, &speeds_of(speeds)?);
    }
    let bike = Whipple::new(params_of(params, strict)?);
    let speeds = speeds_of(speeds)?;
    within(&format!("{} speeds", speeds.len()), speeds.len() as f64, 4.0 * 16.0)?;
    // On a worker, so that Ctrl-C is seen during millions of speeds.
    let flat = interruptible(py, |stop| {
        let mut flat = Vec::with_capacity(4 * speeds.len());
        for (k, v) in speeds.iter().enumerate() {
            if k % 4096 == 0 && stop.load(std::sync::atomic::Ordering::Relaxed) {
                break;
            }
            let ev = bike.eigenvalues(*v);
            if ev.len() != 4 {
                return Err(format!("the eigenvalues at speed {v} did not converge"));
            }
            flat.extend(ev.iter().map(|e| Complex64::new(e.re, e.im)));
        }
        Ok(flat)
    })?
    .map_err(err)?;
    PyArray1::from_vec(py, flat).reshape([speeds.len(), 4])
}

fn window_dict<'py>(py: Python<'py>, w: &StabilityWindow) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("weave_speed", w.weave_speed)?;
    d.set_item("capsize_speed", w.capsize_speed)?;
    d.set_item("stable", PyList::new(py, w.stable.iter().map(|&(a, b)| (a, b)))?)?;
    Ok(d)
}

/// `{"weave_speed", "capsize_speed", "stable": [(from, to), ...]}` (m/s; None where a speed
/// does not exist, inf for an interval stable at every larger speed), as `carvallo window`.
/// For the leaning rider's params (`lean_rider()`), `{"stable", "scan", "state", "inputs"}`:
/// the stable speeds of a scan of 0 to 20 m/s.
#[pyfunction]
#[pyo3(signature = (params, strict = false))]
fn window<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    if let Some(rider) = crate::lean_rider::rider_of(params)? {
        return crate::lean_rider::window(py, &rider);
    }
    window_dict(py, &Whipple::new(params_of(params, strict)?).stability_window())
}

/// The rows of `designs`, anything numpy reads as a 2-d array of floats of shape (n, 26)
/// (`numpy.asarray(designs, dtype=float64)`); otherwise a `ParameterError` naming what it got.
fn designs_of(designs: &Bound<'_, PyAny>) -> PyResult<Vec<[f64; 26]>> {
    let what = || {
        let shape =
            designs.getattr("shape").ok().and_then(|s| s.repr().ok()).map(|r| r.to_string());
        let dtype = designs.getattr("dtype").ok().and_then(|s| s.str().ok()).map(|r| r.to_string());
        match (shape, dtype) {
            (Some(shape), Some(dtype)) => format!("an array of shape {shape} and dtype {dtype}"),
            _ => format!(
                "a {}",
                designs.get_type().name().map(|n| n.to_string()).unwrap_or_default()
            ),
        }
    };
    let bad = || {
        err(format!(
            "designs must be an array of floats of shape (n, 26), columns in the order of PARAM_NAMES; got {}",
            what()
        ))
    };
    let np = designs.py().import("numpy")?;
    let array = np
        .getattr("asarray")?
        .call((designs,), Some(&[("dtype", "float64")].into_py_dict(designs.py())?))
        .or_bad(bad)?;
    let array: PyReadonlyArray2<'_, f64> = array.extract().or_bad(bad)?;
    let shape = array.shape();
    if shape[1] != 26 {
        return Err(bad());
    }
    // The rows, their windows and the result.
    let each = 26 * 8 + std::mem::size_of::<StabilityWindow>() + 2 * 8;
    within(&format!("designs of {} rows", shape[0]), shape[0] as f64, each as f64)?;
    let a = array.as_array();
    Ok(a.rows().into_iter().map(|r| std::array::from_fn(|k| r[k])).collect())
}

/// The weave and capsize speeds of many designs (rows in the order of `PARAM_NAMES`), shape
/// (n, 2), NaN where a design has none; each row is validated as a parameter dict
/// (`validate=False` skips it, as for Monte Carlo samples): rows breaking a triangle inequality
/// of the moments of inertia give one `PhysicsWarning` naming how many and the first, or an
/// error when `strict`. Parallel; the same numbers as `window` row by row.
#[pyfunction]
#[pyo3(signature = (designs, validate = true, strict = false))]
fn windows<'py>(
    py: Python<'py>,
    designs: &Bound<'py, PyAny>,
    validate: bool,
    strict: bool,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let rows = designs_of(designs)?;
    if validate {
        let (mut first, mut broken) = (None, 0usize);
        for (i, row) in rows.iter().enumerate() {
            // Millions of rows take seconds: Ctrl-C is seen between blocks of them.
            if i % (1 << 14) == 0 {
                py.check_signals()?;
            }
            let warnings = if strict {
                WhippleParams::from_values(*row).map(|_| Vec::new())
            } else {
                WhippleParams::from_values_warning(*row).map(|(_, w)| w)
            }
            .map_err(|e| err(format!("design {i}: {e}")))?;
            if let Some(w) = warnings.first() {
                broken += 1;
                first.get_or_insert_with(|| format!("design {i}: {w}"));
            }
        }
        if let Some(first) = first {
            let message = std::ffi::CString::new(format!(
                "{broken} of {} designs break a triangle inequality of the moments of inertia, \
                 computed as given; the first, {first}",
                rows.len()
            ))
            .map_err(|_| err("a warning message holds a NUL byte"))?;
            PyErr::warn(py, py.get_type::<PhysicsWarning>().as_any(), &message, 1)?;
        }
    }
    // In blocks, so that Ctrl-C is seen between two.
    let ws = interruptible(py, |stop| {
        let mut ws = Vec::with_capacity(rows.len());
        for block in rows.chunks(1 << 14) {
            if stop.load(std::sync::atomic::Ordering::Relaxed) {
                break;
            }
            ws.extend(unc::windows_unchecked(block));
        }
        ws
    })?;
    let flat: Vec<f64> = ws
        .iter()
        .flat_map(|w| [w.weave_speed.unwrap_or(f64::NAN), w.capsize_speed.unwrap_or(f64::NAN)])
        .collect();
    PyArray1::from_vec(py, flat).reshape([rows.len(), 2])
}

/// Varies one parameter linearly over `count` designs and summarises their windows, as
/// `carvallo sweep --json` (method "hurwitz" or "eigen").
#[pyfunction]
#[pyo3(signature = (params, name, start, stop, count, method = "hurwitz", strict = false))]
// The arguments are the Python function's keywords.
#[allow(clippy::too_many_arguments)]
fn sweep<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    name: &str,
    #[pyo3(from_py_with = arg::start)] start: f64,
    #[pyo3(from_py_with = arg::stop)] stop: f64,
    #[pyo3(from_py_with = arg::count)] count: usize,
    method: &str,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let base = params_of(params, strict)?;
    let m = match method {
        "hurwitz" => Method::Hurwitz,
        "eigen" => Method::Eigen,
        _ => return Err(err(format!("invalid method `{method}`: hurwitz or eigen"))),
    };
    for (what, x) in [("start", start), ("stop", stop)] {
        if !x.is_finite() {
            return Err(err(format!("invalid {what} {x}: must be finite")));
        }
    }
    let progress = AtomicUsize::new(0);
    let designs = carvallo::sweep::Designs::Grid(vec![carvallo::sweep::Vary {
        name: name.to_string(),
        from: start,
        to: stop,
        count,
    }]);
    // Constant memory (blocks of designs); Ctrl-C stops it within a few designs.
    let s = interruptible(py, |flag| {
        carvallo::sweep::sweep_stream(&base, &designs, m, &progress, flag, None)
    })?
    .map_err(|e| err(e.to_string()))?
    .summary;
    let d = PyDict::new(py);
    d.set_item("parameter", name)?;
    d.set_item("from", start)?;
    d.set_item("to", stop)?;
    d.set_item("count", s.count)?;
    d.set_item("method", method)?;
    d.set_item("elapsed", s.elapsed)?;
    d.set_item("designs_per_second", s.designs_per_second)?;
    d.set_item("stable", s.stable)?;
    d.set_item("with_weave", s.with_weave)?;
    d.set_item("with_capsize", s.with_capsize)?;
    d.set_item("weave_speed_range", s.weave_range)?;
    d.set_item("capsize_speed_range", s.capsize_range)?;
    d.set_item("failed", s.failed)?;
    Ok(d)
}

/// Integrates the nonlinear bicycle from upright straight running at `speed` with the lean
/// `lean0`, as `carvallo simulate --json` with the same options: `method` (`rk4` at the step
/// `step`, or `dopri5`, `dop853`, `vern9` with `rtol`, default 1e-8, and `atol`,
/// default 1e-3 rtol, sampled every `every` × `step` seconds) and `stop_when` (conditions such as `"lean=±0.5"`).
/// A dict of numpy arrays (`t`, `lean`, `steer`, `pitch`, `speed_rear`, `rear_x`, `rear_y`,
/// `front_x`, `front_y`, `energy`), the floats `step`, `energy_drift`,
/// `max_contact_residual`, the `method`, `rtol` and `atol` (None for rk4), the counts
/// `rhs_evaluations`, `steps`, `rejected_steps` and `events` (a list of dicts `when`, `t`),
/// and how the run ended ([`set_status`]): the run ends, fallen, when the lean's magnitude
/// reaches `fall_angle` (default 1.2 rad; a start at or beyond it is refused), when the
/// steer's reaches `steer_lock` (default 1.4 rad, the handlebar against the frame), or, status
/// `singular`, near the equations' singular configuration (`singular_t`). Ctrl-C raises
/// `KeyboardInterrupt` within a step.
///
/// Driven (as `simulate --torque ... --gain ...`): `torque_t` with `torque_roll` and/or
/// `torque_steer` (N m at those times, increasing; interpolated, zero outside), `impulses`
/// (a list of `(t, J_roll, J_steer)` in N m s, t a multiple of `step`) and the feedback
/// T = -K x with `k` as in `closed_loop_window` (a (2, 4) array, gains by name or a gain
/// table read at the rear contact's speed). The dict then adds `T_phi`, `T_delta`, `work_t`,
/// `work` and `max_energy_change`, and `energy_drift` is that of E - E(0) - W.
///
/// For the leaning rider's params (`lean_rider()`): `lean0` is the roll, `torque_lean` (with
/// `torque_t`) the lean torque T9 beside `torque_roll` and `torque_steer`; the dict holds `t`,
/// `roll`, `steer`, `lean` (the torso on its joint), `yaw`, `pitch`, `x`, `y`, `energy`, the
/// counts, `max_energy_drift` and `status` (`completed`, `fell`, `torso fell`, `steer lock`,
/// `singular`: a pivot of the constraint solve fell to `singular_pivot` of its upright value,
/// at `singular_t`, None otherwise)
/// with `status_line` naming the pivot (as `carvallo simulate --model lean-rider --json`); a
/// start with `lean0` at or beyond `fall_angle` (in (0, pi/2]), a `steer_lock` outside
/// (0, pi/2) or a start at or beyond the singular configuration raises ParameterError naming
/// the value (the pivot for the singular configuration).
#[pyfunction]
#[pyo3(signature = (params, speed, lean0, duration, step = 0.001, every = 10, strict = false, *, method = "rk4", rtol = None, atol = None, stop_when = Vec::new(), torque_t = None, torque_roll = None, torque_steer = None, impulses = Vec::new(), k = None, fall_angle = carvallo::whipple_nonlinear::DEFAULT_FALL_ANGLE, steer_lock = carvallo::whipple_nonlinear::DEFAULT_STEER_LOCK, torque_lean = None))]
#[allow(clippy::too_many_arguments)]
fn simulate<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    #[pyo3(from_py_with = arg::speed)] speed: f64,
    #[pyo3(from_py_with = arg::lean0)] lean0: f64,
    #[pyo3(from_py_with = arg::duration)] duration: f64,
    #[pyo3(from_py_with = arg::step)] step: f64,
    #[pyo3(from_py_with = arg::every)] every: usize,
    strict: bool,
    method: &str,
    #[pyo3(from_py_with = arg::rtol)] rtol: Option<f64>,
    #[pyo3(from_py_with = arg::atol)] atol: Option<f64>,
    stop_when: Vec<String>,
    #[pyo3(from_py_with = arg::torque_t)] torque_t: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::torque_roll)] torque_roll: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::torque_steer)] torque_steer: Option<Vec<f64>>,
    #[pyo3(from_py_with = arg::impulses)] impulses: Vec<(f64, f64, f64)>,
    k: Option<Bound<'py, PyAny>>,
    #[pyo3(from_py_with = arg::fall_angle)] fall_angle: f64,
    #[pyo3(from_py_with = arg::steer_lock)] steer_lock: f64,
    #[pyo3(from_py_with = arg::torque_lean)] torque_lean: Option<Vec<f64>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (how, stops) = integration_of(method, rtol, atol, &stop_when)?;
    if let Some(rider) = crate::lean_rider::rider_of(params)? {
        if !stops.is_empty() || !impulses.is_empty() || k.is_some() {
            return Err(err(
                "stop_when, impulses and k are for the bicycle, not yet for the leaning rider",
            ));
        }
        let grid = Grid::exact(duration, step, every).map_err(|(name, value, reason)| {
            err(carvallo::ParameterError::InvalidParameter { name, value, reason }.to_string())
        })?;
        within(
            &format!("duration = {duration}, step = {step}, every = {every}"),
            grid.samples() as f64,
            (13 + 9) as f64 * 8.0,
        )?;
        let torques =
            crate::lean_rider::Torques::new(torque_t, [torque_roll, torque_steer, torque_lean])?;
        let start = crate::lean_rider::Start { speed, lean0, fall_angle, steer_lock };
        return crate::lean_rider::simulate(py, &rider, start, &grid, &how, &torques);
    }
    if torque_lean.is_some() {
        return Err(err(
            "torque_lean is the leaning rider's (params = carvallo.lean_rider()); the bicycle \
             takes torque_roll and torque_steer",
        ));
    }
    let bike = WhippleNonlinear::new(params_of(params, strict)?)
        .with_fall_angle(fall_angle)
        .and_then(|b| b.with_steer_lock(steer_lock))
        .map_err(|e| err(e.to_string()))?;
    let start = bike.initial_state(speed, lean0).map_err(|e| err(e.to_string()))?;
    bike.check_start(&start).map_err(|e| {
        use carvallo::whipple_nonlinear::NonlinearError;
        err(match e {
            NonlinearError::Fallen { fall_angle, .. } => format!(
                "invalid lean0 {lean0:?}: at or beyond the fall angle ±{fall_angle} rad (fall_angle), where the bicycle is on the ground"
            ),
            NonlinearError::Parameter(carvallo::ParameterError::InvalidParameter {
                reason, ..
            }) => format!("invalid lean0 {lean0:?}: {reason}"),
            other => other.to_string(),
        })
    })?;
    let grid = Grid::exact(duration, step, every).map_err(|(name, value, reason)| {
        err(carvallo::ParameterError::InvalidParameter { name, value, reason }.to_string())
    })?;
    let inputs = inputs_of(torque_t, torque_roll, torque_steer, impulses, k.as_ref())?;
    // The samples, then ten (driven: thirteen) columns copied out of them.
    let each = std::mem::size_of::<carvallo::whipple_nonlinear::ForcedSample>() + 13 * 8;
    within(
        &format!("duration = {duration}, step = {step}, every = {every}"),
        grid.samples() as f64,
        each as f64,
    )?;
    if !inputs.is_empty() {
        return simulate_driven(py, &bike, start, &grid, &how, &stops, &inputs);
    }
    // Ctrl-C ends the run within a step (KeyboardInterrupt, the samples dropped).
    let tr = interruptible(py, |flag| bike.simulate_until(start, &grid, &how, &stops, flag))?
        .map_err(|e| err(e.to_string()))?;
    let d = PyDict::new(py);
    type Column = fn(&carvallo::whipple_nonlinear::Sample) -> f64;
    let columns: [(&str, Column); 10] = [
        ("t", |s| s.t),
        ("lean", |s| s.state.lean),
        ("steer", |s| s.state.steer),
        ("pitch", |s| s.pitch),
        ("speed_rear", |s| s.speed),
        ("rear_x", |s| s.rear_contact[0]),
        ("rear_y", |s| s.rear_contact[1]),
        ("front_x", |s| s.front_contact[0]),
        ("front_y", |s| s.front_contact[1]),
        ("energy", |s| s.energy),
    ];
    for (name, f) in columns {
        d.set_item(name, PyArray1::from_vec(py, tr.samples.iter().map(f).collect()))?;
    }
    d.set_item("step", tr.step)?;
    d.set_item("energy_drift", tr.energy_drift)?;
    d.set_item("max_contact_residual", tr.max_contact_residual)?;
    let event = tr.event.map(|(k, t)| (stops[k].text(), t));
    let end = tr.times.last().copied().unwrap_or(0.0);
    let last = tr.samples.last().map_or([f64::NAN; 3], |p| [p.state.lean, p.pitch, p.state.steer]);
    let singular = tr.singular.map(|t| (t, last));
    set_status(&d, &bike, event.as_ref(), (tr.fall, tr.steer_lock, singular), end)?;
    set_run(&d, &how, &tr.stats, event)?;
    Ok(d)
}

/// The limits a run reached: the times of the fall and of the steer lock, and of the singular
/// configuration with the lean, pitch and steer there (None where not reached).
type Reached = (Option<f64>, Option<f64>, Option<(f64, [f64; 3])>);

/// How a run of `simulate` ended: `status` (`"completed"`, `"stopped"` by a condition of
/// `stop_when`, `"fell"`: the lean reached `fall_angle`, `"steer lock"`: the steer reached
/// `steer_lock`, `"singular"`: a pivot of the constraint solve fell to `singular_pivot` of its
/// upright value, the equations near their singularity), `status_line` (`"fell at t = 1.94 s:
/// ..."`), `fall_angle`, `fall_t`, `steer_lock`, `steer_lock_t`, `singular_pivot` and
/// `singular_t` (None unless reached). An interrupted run raises `KeyboardInterrupt` instead.
fn set_status(
    d: &Bound<'_, PyDict>,
    bike: &WhippleNonlinear,
    event: Option<&(String, f64)>,
    (fall, lock, singular): Reached,
    end: f64,
) -> PyResult<()> {
    let (status, line) = if let Some((t, [lean, pitch, steer])) = singular {
        ("singular", bike.singular_line(t, lean, pitch, steer))
    } else if let Some(t) = fall {
        (
            "fell",
            format!(
                "fell at t = {t} s: the lean reached the fall angle ±{} rad",
                bike.fall_angle()
            ),
        )
    } else if let Some(t) = lock {
        (
            "steer lock",
            format!(
                "steer lock at t = {t} s: the steer reached ±{} rad, the handlebar against the frame",
                bike.steer_lock()
            ),
        )
    } else if let Some((when, t)) = event {
        ("stopped", format!("stopped at t = {t} s: {when}"))
    } else {
        ("completed", format!("completed at t = {end} s"))
    };
    d.set_item("status", status)?;
    d.set_item("status_line", line)?;
    d.set_item("fall_angle", bike.fall_angle())?;
    d.set_item("fall_t", fall)?;
    d.set_item("steer_lock", bike.steer_lock())?;
    d.set_item("steer_lock_t", lock)?;
    d.set_item("singular_pivot", carvallo::whipple_nonlinear::SINGULAR_PIVOT)?;
    d.set_item("singular_t", singular.map(|(t, _)| t))
}

/// The inputs of `simulate`: the sampled torques (`torque_t` with `torque_roll` and/or
/// `torque_steer`), the impulses `(t, J_roll, J_steer)` and the feedback `k`.
fn inputs_of(
    t: Option<Vec<f64>>,
    roll: Option<Vec<f64>>,
    steer: Option<Vec<f64>>,
    impulses: Vec<(f64, f64, f64)>,
    k: Option<&Bound<'_, PyAny>>,
) -> PyResult<carvallo::whipple_nonlinear::Inputs> {
    use carvallo::whipple_nonlinear::{Impulse, Inputs, Series, Signal};
    let mut inputs = Inputs::default();
    match (t, roll.is_some() || steer.is_some()) {
        (Some(t), true) => {
            let series = |values: Vec<f64>, name: &str| -> PyResult<Signal> {
                Series::new(t.clone(), values)
                    .map(Signal::Series)
                    .map_err(|e| err(format!("{name}: {e}")))
            };
            if let Some(v) = roll {
                inputs.roll.push(series(v, "torque_roll")?);
            }
            if let Some(v) = steer {
                inputs.steer.push(series(v, "torque_steer")?);
            }
        }
        (Some(_), false) => return Err(err("torque_t needs torque_roll or torque_steer")),
        (None, true) => return Err(err("torque_roll and torque_steer need their times torque_t")),
        (None, false) => {}
    }
    inputs.impulses =
        impulses.into_iter().map(|(t, roll, steer)| Impulse { t, roll, steer }).collect();
    if let Some(k) = k {
        inputs.feedback = feedback_of(k)?;
    }
    Ok(inputs)
}

/// `simulate` driven by `inputs`: the columns of the undriven run and `T_phi`, `T_delta`,
/// `work_t`, the floats `work` and `max_energy_change`; `energy_drift` is that of the balance
/// E - E(0) - W.
fn simulate_driven<'py>(
    py: Python<'py>,
    bike: &WhippleNonlinear,
    start: carvallo::whipple_nonlinear::State,
    grid: &Grid,
    how: &Integration,
    stops: &[Stop],
    inputs: &carvallo::whipple_nonlinear::Inputs,
) -> PyResult<Bound<'py, PyDict>> {
    let tr = interruptible(py, |flag| {
        bike.simulate_forced_until(start, grid, how, stops, inputs, flag)
    })?
    .map_err(|e| err(e.to_string()))?;
    let d = PyDict::new(py);
    type Column = fn(&carvallo::whipple_nonlinear::ForcedSample) -> f64;
    let columns: [(&str, Column); 13] = [
        ("t", |s| s.sample.t),
        ("lean", |s| s.sample.state.lean),
        ("steer", |s| s.sample.state.steer),
        ("pitch", |s| s.sample.pitch),
        ("speed_rear", |s| s.sample.speed),
        ("rear_x", |s| s.sample.rear_contact[0]),
        ("rear_y", |s| s.sample.rear_contact[1]),
        ("front_x", |s| s.sample.front_contact[0]),
        ("front_y", |s| s.sample.front_contact[1]),
        ("energy", |s| s.sample.energy),
        ("T_phi", |s| s.torque[0]),
        ("T_delta", |s| s.torque[1]),
        ("work_t", |s| s.work),
    ];
    for (name, f) in columns {
        d.set_item(name, PyArray1::from_vec(py, tr.samples.iter().map(f).collect()))?;
    }
    let diag = tr.diagnostics;
    d.set_item("step", tr.step)?;
    d.set_item("work", diag.work)?;
    d.set_item("max_energy_change", diag.max_energy_change)?;
    d.set_item("energy_drift", diag.energy_drift)?;
    d.set_item("max_contact_residual", diag.max_contact_residual)?;
    let event = tr.event.map(|(k, t)| (stops[k].text(), t));
    let end = tr.times.last().copied().unwrap_or(0.0);
    let last = tr
        .samples
        .last()
        .map_or([f64::NAN; 3], |p| [p.sample.state.lean, p.sample.pitch, p.sample.state.steer]);
    let singular = tr.singular.map(|t| (t, last));
    set_status(&d, bike, event.as_ref(), (tr.fall, tr.steer_lock, singular), end)?;
    set_run(&d, how, &tr.stats, event)?;
    Ok(d)
}

/// The values of a 1-d sequence of numbers (`what` names it in the error): any numpy array —
/// a strided slice of a larger one, or one Dask deserialised into a misaligned buffer — or a
/// list of real numbers (booleans, integers or floats; complex numbers, texts and objects are
/// refused, not cast), copied through `numpy.require(x, float64, "CA")` (no copy when already
/// contiguous and aligned float64), so a chunk of a batch is read whatever its memory layout.
fn column_of(x: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<f64>> {
    let bad = || err(format!("{what} must be a 1-d array of numbers"));
    let np = x.py().import("numpy")?;
    let a = np.getattr("asarray")?.call1((x,)).or_bad(bad)?;
    let kind: String = a.getattr("dtype")?.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "b" | "i" | "u" | "f") {
        return Err(bad());
    }
    let a = np.getattr("require")?.call1((a, "float64", "CA")).or_bad(bad)?;
    let a: PyReadonlyArray1<'_, f64> = a.extract().or_bad(bad)?;
    Ok(a.as_slice().map_err(|_| bad())?.to_vec())
}

/// Many simulations of the nonlinear bicycle in parallel, the GIL released: one from each
/// (`speeds[k]`, `lean0s[k]`, `steer_rates[k]`, zero when None) with the options of
/// `simulate`, keeping only the end (as `carvallo simulate --batch FILE --csv`). A dict of
/// numpy arrays, one entry per start: `t_end`, `lean`, `steer`, `yaw`, `x`, `y`, `lean_rate`,
/// `steer_rate` (NaN for a failed run), `event_t` (NaN when no stop condition was met),
/// `fall_t` (when the lean reached the fall angle, 1.2 rad; NaN when it did not),
/// `steer_lock_t` (when the steer reached the steer lock, 1.4 rad; NaN when it did not),
/// `singular_t` (when a pivot of the constraint solve fell to 1% of its upright value, the
/// equations near their singularity; NaN when none did),
/// `stopped_by` (the index of the condition met, -1 for none), `fell` (the fall angle or the
/// steer lock reached, a condition met or the contact lost), `ok`, `rhs_evaluations`, and `errors` (a list, None for a run that did not
/// fail). Each run equals `simulate`'s bit for bit, and a chunk (any slice of the batch, read
/// whatever its layout, see [`column_of`]) gives the batch's rows for it bit for bit: the
/// chunks of a batch can run in other processes (docs/examples/basin_dask.py over Dask).
#[pyfunction]
#[pyo3(signature = (params, speeds, lean0s, duration, steer_rates = None, step = 0.001, *, method = "rk4", rtol = None, atol = None, stop_when = Vec::new(), strict = false))]
#[allow(clippy::too_many_arguments)]
fn simulate_many<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    speeds: &Bound<'py, PyAny>,
    lean0s: &Bound<'py, PyAny>,
    #[pyo3(from_py_with = arg::duration)] duration: f64,
    steer_rates: Option<&Bound<'py, PyAny>>,
    #[pyo3(from_py_with = arg::step)] step: f64,
    method: &str,
    #[pyo3(from_py_with = arg::rtol)] rtol: Option<f64>,
    #[pyo3(from_py_with = arg::atol)] atol: Option<f64>,
    stop_when: Vec<String>,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let (how, stops) = integration_of(method, rtol, atol, &stop_when)?;
    let bike = WhippleNonlinear::new(params_of(params, strict)?);
    let speeds = column_of(speeds, "speeds")?;
    let lean0s = column_of(lean0s, "lean0s")?;
    let n = speeds.len();
    // The starts, the ends and fifteen columns.
    let each = std::mem::size_of::<carvallo::whipple_nonlinear::State>()
        + std::mem::size_of::<
            Result<carvallo::whipple_nonlinear::Final, carvallo::whipple_nonlinear::NonlinearError>,
        >()
        + 15 * 8;
    within(&format!("{n} speeds"), n as f64, each as f64)?;
    if lean0s.len() != n {
        return Err(err(format!("lean0s has {} values for {n} speeds", lean0s.len())));
    }
    let rates: Vec<f64> = match steer_rates {
        Some(r) => column_of(r, "steer_rates")?,
        None => vec![0.0; n],
    };
    if rates.len() != n {
        return Err(err(format!("steer_rates has {} values for {n} speeds", rates.len())));
    }
    let mut starts = Vec::with_capacity(n);
    for k in 0..n {
        let mut s =
            bike.initial_state(speeds[k], lean0s[k]).map_err(|e| err(format!("start {k}: {e}")))?;
        if !rates[k].is_finite() {
            return Err(err(format!(
                "start {k}: invalid steer rate {:?}: must be finite",
                rates[k]
            )));
        }
        s.steer_rate = rates[k];
        starts.push(s);
    }
    // Only the end is kept: no sample inside the run (the integration does not depend on them).
    let grid = Grid::exact(duration, step, usize::MAX).map_err(|(name, value, reason)| {
        err(carvallo::ParameterError::InvalidParameter { name, value, reason }.to_string())
    })?;
    let done = AtomicUsize::new(0);
    // Ctrl-C sets the flag every integration reads after each accepted step: a long run stops
    // within a step (the runs cut short are dropped with the rest as KeyboardInterrupt rises;
    // without it every run is there, in order).
    let ends: Vec<_> = interruptible(py, |stop| {
        bike.simulate_many_until(&starts, &grid, &how, &stops, &done, stop)
            .into_iter()
            .flatten()
            .collect()
    })?;
    let d = PyDict::new(py);
    type Column = fn(&carvallo::whipple_nonlinear::Final) -> f64;
    let columns: [(&str, Column); 12] = [
        ("t_end", |f| f.t),
        ("lean", |f| f.state.lean),
        ("steer", |f| f.state.steer),
        ("yaw", |f| f.state.yaw),
        ("x", |f| f.state.x),
        ("y", |f| f.state.y),
        ("lean_rate", |f| f.state.lean_rate),
        ("steer_rate", |f| f.state.steer_rate),
        ("event_t", |f| f.event.map_or(f64::NAN, |e| e.1)),
        ("fall_t", |f| f.fall.unwrap_or(f64::NAN)),
        ("steer_lock_t", |f| f.steer_lock.unwrap_or(f64::NAN)),
        ("singular_t", |f| f.singular.unwrap_or(f64::NAN)),
    ];
    for (name, f) in columns {
        let v: Vec<f64> = ends.iter().map(|e| e.as_ref().map_or(f64::NAN, f)).collect();
        d.set_item(name, PyArray1::from_vec(py, v))?;
    }
    let stopped: Vec<i64> = ends
        .iter()
        .map(|e| e.as_ref().ok().and_then(|f| f.event).map_or(-1, |e| e.0 as i64))
        .collect();
    d.set_item("stopped_by", PyArray1::from_vec(py, stopped))?;
    let fell: Vec<bool> = ends
        .iter()
        .map(|e| match e {
            Ok(f) => f.fall.is_some() || f.steer_lock.is_some() || f.event.is_some(),
            Err(e) => matches!(e, carvallo::whipple_nonlinear::NonlinearError::NoContact { .. }),
        })
        .collect();
    d.set_item("fell", PyArray1::from_vec(py, fell))?;
    d.set_item(
        "ok",
        PyArray1::from_vec(py, ends.iter().map(|e| e.is_ok()).collect::<Vec<bool>>()),
    )?;
    let evals: Vec<u64> =
        ends.iter().map(|e| e.as_ref().map_or(0, |f| f.stats.rhs_evaluations as u64)).collect();
    d.set_item("rhs_evaluations", PyArray1::from_vec(py, evals))?;
    let errors: Vec<Option<String>> =
        ends.iter().map(|e| e.as_ref().err().map(|e| e.to_string())).collect();
    d.set_item("errors", errors)?;
    Ok(d)
}

/// The memoir concordance: a list of dicts with the keys of `carvallo report --json`.
#[pyfunction]
fn report(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    let entries = py.detach(carvallo_report::all_entries);
    let text = carvallo_report::render_json(&entries);
    py.import("json")?.call_method1("loads", (text,))
}

/// The weave and capsize speeds and their exact derivatives with respect to every parameter:
/// `{"weave_speed", "capsize_speed", "d_weave": {name: dv/dp}, "d_capsize": {...}}` (None
/// where a speed does not exist).
#[pyfunction]
#[pyo3(signature = (params, strict = false))]
fn speed_gradients<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let g = unc::speed_gradients(&params_of(params, strict)?);
    let d = PyDict::new(py);
    d.set_item("weave_speed", g.weave.as_ref().map(|w| w.speed))?;
    d.set_item("capsize_speed", g.capsize.as_ref().map(|c| c.speed))?;
    d.set_item("d_weave", g.weave.as_ref().map(|w| dict_of(py, &w.grad)).transpose()?)?;
    d.set_item("d_capsize", g.capsize.as_ref().map(|c| dict_of(py, &c.grad)).transpose()?)?;
    Ok(d)
}

/// First-order standard deviations of the weave and capsize speeds:
/// `{"weave_speed", "weave_std", "capsize_speed", "capsize_std"}`. Either independent
/// parameters with the standard deviations `sigma` (a dict; missing names have none), or, with
/// `sigma=None`, `params` of `uncertainties` ufloats (a dict or a `bicycleparameters.Bicycle`):
/// their standard deviations and their correlations where they share sources.
#[pyfunction]
#[pyo3(signature = (params, sigma = None, strict = false))]
fn first_order<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    sigma: Option<&Bound<'py, PyAny>>,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let u = uncertain_of(params, sigma, strict, true)?;
    let cov = match sigma {
        None => Covariance::of(params, &u)?,
        Some(_) => None,
    };
    let std = |g: &unc::SpeedGradient| match &cov {
        Some(c) => c.std(&g.grad),
        None => g.std(&u.sigma),
    };
    let g = unc::speed_gradients(&u.params);
    let d = PyDict::new(py);
    d.set_item("weave_speed", g.weave.as_ref().map(|w| w.speed))?;
    d.set_item("weave_std", g.weave.as_ref().map(std))?;
    d.set_item("capsize_speed", g.capsize.as_ref().map(|c| c.speed))?;
    d.set_item("capsize_std", g.capsize.as_ref().map(std))?;
    Ok(d)
}

/// Monte Carlo: `samples` designs drawn normal about `params` with `sigma` (seeded; with
/// `sigma=None` the standard deviations of ufloat `params`, drawn independently);
/// `{"weave": array, "capsize": array, "invalid": int}` (NaN where a sample has no such speed).
#[pyfunction]
#[pyo3(signature = (params, sigma = None, samples = 10000, seed = 1897, strict = false))]
fn monte_carlo<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    sigma: Option<&Bound<'py, PyAny>>,
    #[pyo3(from_py_with = arg::samples)] samples: usize,
    #[pyo3(from_py_with = arg::seed)] seed: u64,
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let u = uncertain_of(params, sigma, strict, true)?;
    within(&format!("samples = {samples}"), samples as f64, 2.0 * 8.0 * 2.0)?;
    let mc = interruptible(py, |stop| unc::monte_carlo_until(&u, samples, seed, stop))?
        .ok_or_else(|| err("monte_carlo was stopped"))?;
    let d = PyDict::new(py);
    d.set_item("weave", PyArray1::from_vec(py, mc.weave))?;
    d.set_item("capsize", PyArray1::from_vec(py, mc.capsize))?;
    d.set_item("invalid", mc.invalid)?;
    Ok(d)
}

fn rows4<'py>(py: Python<'py>, rows: &[[f64; 4]]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    PyArray1::from_vec(py, flat).reshape([rows.len(), 4])
}

/// Quantile bands of the eigenvalues' real parts against speed for `samples` Monte Carlo
/// designs: `{"speeds", "nominal", "lower", "upper"}`, the last three of shape (n, 4), rank by
/// rank of the sorted real parts. `sigma=None` takes the standard deviations of ufloat
/// `params`, drawn independently.
#[pyfunction]
#[pyo3(signature = (params, sigma, speeds, samples = 2000, seed = 1897, quantiles = (0.025, 0.975), strict = false))]
// The arguments are the Python function's keywords.
#[allow(clippy::too_many_arguments)]
fn eigenvalue_bands<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    sigma: Option<&Bound<'py, PyAny>>,
    speeds: &Bound<'py, PyAny>,
    #[pyo3(from_py_with = arg::samples)] samples: usize,
    #[pyo3(from_py_with = arg::seed)] seed: u64,
    #[pyo3(from_py_with = arg::quantiles)] quantiles: (f64, f64),
    strict: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let u = uncertain_of(params, sigma, strict, true)?;
    let speeds = speeds_of(speeds)?;
    let (lo, hi) = quantiles;
    if !(0.0..=1.0).contains(&lo) || !(0.0..=1.0).contains(&hi) || lo > hi {
        return Err(err(format!("invalid quantiles ({lo}, {hi}): need 0 <= low <= high <= 1")));
    }
    // The designs and their sorted real parts at every speed, then one rank at a time.
    let each = 26.0 * 8.0 + 24.0 + speeds.len() as f64 * 40.0 + 8.0;
    within(&format!("samples = {samples} with {} speeds", speeds.len()), samples as f64, each)?;
    let b = interruptible(py, |stop| {
        unc::eigenvalue_bands_until(&u, &speeds, samples, seed, (lo, hi), stop)
    })?
    .ok_or_else(|| err("eigenvalue_bands was stopped"))?;
    let d = PyDict::new(py);
    d.set_item("speeds", PyArray1::from_vec(py, b.speeds))?;
    d.set_item("nominal", rows4(py, &b.nominal)?)?;
    d.set_item("lower", rows4(py, &b.lower)?)?;
    d.set_item("upper", rows4(py, &b.upper)?)?;
    Ok(d)
}

/// Fast, verified evaluators of the Carvallo–Whipple bicycle (the `carvallo` Rust crate).
#[pymodule]
#[pyo3(name = "carvallo")]
fn carvallo_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("ParameterError", py.get_type::<ParameterError>())?;
    m.add("PhysicsWarning", py.get_type::<PhysicsWarning>())?;
    m.add("PARAM_NAMES", PyList::new(py, PARAM_NAMES)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(benchmark, m)?)?;
    m.add_function(wrap_pyfunction!(design, m)?)?;
    m.add_function(wrap_pyfunction!(load_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(parse_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(parameters_from_raw, m)?)?;
    m.add_function(wrap_pyfunction!(add_rider, m)?)?;
    m.add_function(wrap_pyfunction!(geometry, m)?)?;
    m.add_function(wrap_pyfunction!(matrices, m)?)?;
    m.add_function(wrap_pyfunction!(state_matrix, m)?)?;
    m.add_function(wrap_pyfunction!(state_space, m)?)?;
    m.add_function(wrap_pyfunction!(modes, m)?)?;
    m.add_function(wrap_pyfunction!(frequency_response, m)?)?;
    m.add_function(wrap_pyfunction!(time_response, m)?)?;
    m.add_function(wrap_pyfunction!(closed_loop_window, m)?)?;
    m.add_function(wrap_pyfunction!(closed_loop_eigenvalues, m)?)?;
    m.add_function(wrap_pyfunction!(eigenvalues, m)?)?;
    m.add_function(wrap_pyfunction!(window, m)?)?;
    m.add_function(wrap_pyfunction!(windows, m)?)?;
    m.add_function(wrap_pyfunction!(sweep, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(simulate_many, m)?)?;
    m.add_function(wrap_pyfunction!(report, m)?)?;
    m.add_function(wrap_pyfunction!(speed_gradients, m)?)?;
    m.add_function(wrap_pyfunction!(first_order, m)?)?;
    m.add_function(wrap_pyfunction!(monte_carlo, m)?)?;
    m.add_function(wrap_pyfunction!(eigenvalue_bands, m)?)?;
    crate::rolling::register(m)?;
    crate::steady_turn::register(m)?;
    crate::lean_rider::register(m)?;
    crate::yeadon::register(m)?;
    crate::wheeled_pendulum::register(m)?;
    register_plot(m)?;
    Ok(())
}

/// The figures of `plot.py` (matplotlib, imported when a figure is drawn): the submodule
/// `carvallo.plot` (importable as such) and its `plot_geometry`, `plot_eigenvalues` and
/// `plot_bode` at the top level too.
fn register_plot(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    let code = std::ffi::CString::new(include_str!("plot.py")).map_err(|e| err(e.to_string()))?;
    let plot = PyModule::from_code(py, &code, c"carvallo/plot.py", c"carvallo.plot")?;
    m.add_submodule(&plot)?;
    py.import("sys")?.getattr("modules")?.set_item("carvallo.plot", &plot)?;
    for name in ["plot_geometry", "plot_eigenvalues", "plot_bode"] {
        m.add(name, plot.getattr(name)?)?;
    }
    Ok(())
}
