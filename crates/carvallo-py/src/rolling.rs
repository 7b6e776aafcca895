//! The hoop (memoir n° 1–20) and the mounted unicycle (n° 21–41) for Python: `simulate_hoop`
//! and `simulate_unicycle` integrate their equations for the state $(\theta, p, n, s)$ (lean,
//! lean rate, the rates $n$ and $s$ of n° 7) by RK4 at a fixed step or by an error-controlled
//! pair (`dopri5`, `dop853`, `vern9`) sampled from its dense output, with terminal events on
//! a state component (`stop_when=["theta=±0.5"]`), as `simulate` does for the bicycle; the
//! runtime's `Hoop::simulate_with` and `Unicycle::simulate_with` do the work, the GIL released.

use carvallo::hoop::{Hoop, Trajectory};
use carvallo::numerics::integrate::{Grid, Integration, Threshold};
use carvallo::unicycle::{Rider, Unicycle, Wheel};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::common::{err, integration_of, set_run, OrBad};
use crate::guard::{arg, interruptible, within};

/// The names of the state's components, in its order.
const STATE: [&str; 4] = ["theta", "p", "n", "s"];

/// The stop conditions `NAME=VALUE` (the component crosses VALUE) or `NAME=±VALUE` /
/// `NAME=+-VALUE` (its magnitude reaches VALUE), NAME one of [`STATE`].
fn thresholds(stop_when: &[String]) -> PyResult<Vec<Threshold>> {
    stop_when
        .iter()
        .map(|text| {
            Threshold::parse(text, &STATE).ok_or_else(|| {
                err(format!(
                    "invalid stop condition `{text}`: expected NAME=VALUE or NAME=±VALUE with \
                     NAME one of theta, p, n, s and a finite VALUE"
                ))
            })
        })
        .collect()
}

/// The grid of `duration`, `step` and `every`, or the error naming the bad value.
fn grid_of(duration: f64, step: f64, every: usize) -> PyResult<Grid> {
    Grid::new(duration, step, every).map_err(|(name, value, reason)| {
        err(carvallo::ParameterError::InvalidParameter { name, value, reason }.to_string())
    })
}

/// Refuses a run whose samples (time, state, then five columns) need more than the limit.
fn samples_within(grid: &Grid, duration: f64, step: f64, every: usize) -> PyResult<()> {
    let what = format!("duration = {duration}, step = {step}, every = {every}");
    within(&what, grid.samples() as f64, (8 + 4 * 8 + 5 * 8) as f64)
}

/// The run as a dict: arrays `t`, `theta`, `p`, `n`, `s`; `energy_drift` (J) and
/// `relative_energy_drift`; `method`, `rtol`, `atol` (None for rk4); the counts; `events`.
fn trajectory_dict<'py>(
    py: Python<'py>,
    tr: &Trajectory,
    how: &Integration,
    stop_when: &[String],
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("t", PyArray1::from_vec(py, tr.times.clone()))?;
    for (k, name) in STATE.iter().enumerate() {
        d.set_item(*name, PyArray1::from_vec(py, tr.samples.iter().map(|x| x[k]).collect()))?;
    }
    d.set_item("energy_drift", tr.diagnostics.max_energy_drift)?;
    d.set_item("relative_energy_drift", tr.diagnostics.relative_energy_drift())?;
    set_run(&d, how, &tr.stats, tr.event.map(|(k, t)| (stop_when[k].clone(), t)))?;
    Ok(d)
}

/// The finite number `key` of the dict `what` (`rider` or `wheel`), every key of `keys`
/// required and no other accepted.
fn numbers_of<const K: usize>(
    mapping: &Bound<'_, PyAny>,
    what: &str,
    keys: [&str; K],
) -> PyResult<[f64; K]> {
    let d = mapping
        .cast::<PyDict>()
        .map_err(|_| err(format!("{what} must be a dict with the keys {}", keys.join(", "))))?;
    for (k, _) in d.iter() {
        let name: String = k.str()?.to_string();
        if !keys.contains(&name.as_str()) {
            return Err(err(format!("unknown {what} key `{name}`: expected {}", keys.join(", "))));
        }
    }
    let mut out = [0.0; K];
    for (slot, key) in out.iter_mut().zip(keys) {
        let v = d.get_item(key)?.ok_or_else(|| err(format!("{what} lacks the key `{key}`")))?;
        let x: f64 = v.extract().or_bad(|| err(format!("invalid {what}.{key}: not a number")))?;
        if !x.is_finite() {
            return Err(err(format!("invalid {what}.{key} {x:?}: must be finite")));
        }
        *slot = x;
    }
    Ok(out)
}

/// Integrates the rolling hoop of radius `radius` (m), mass `mass` (kg) under `g` (m/s²),
/// system (2) of n° 7, from the lean `theta0` (rad) and the rates `p0`, `n0`, `s0` (rad/s):
/// `method` `rk4` at `step`, or `dopri5`, `dop853`, `vern9` with `rtol` (default 1e-8) and
/// `atol` (default 1e-3 rtol), sampled every `every` × `step` seconds, until `duration` or
/// the first of `stop_when` (`"theta=±0.5"`: a component of the state crossing a value or
/// its magnitude reaching it). A dict: arrays `t`, `theta`, `p`, `n`, `s`, the energy drift
/// (`energy_drift`, J, and `relative_energy_drift`), `method`, `rtol`, `atol`, the counts
/// `rhs_evaluations`, `steps`, `rejected_steps` and `events` (a list of dicts `when`, `t`).
#[pyfunction]
#[pyo3(signature = (theta0, s0, duration, step = 0.001, every = 10, *, p0 = 0.0, n0 = 0.0, radius = 0.5, mass = 1.0, g = 9.81, method = "rk4", rtol = None, atol = None, stop_when = Vec::new()))]
#[allow(clippy::too_many_arguments)]
fn simulate_hoop<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = arg::theta0)] theta0: f64,
    #[pyo3(from_py_with = arg::s0)] s0: f64,
    #[pyo3(from_py_with = arg::duration)] duration: f64,
    #[pyo3(from_py_with = arg::step)] step: f64,
    #[pyo3(from_py_with = arg::every)] every: usize,
    #[pyo3(from_py_with = arg::p0)] p0: f64,
    #[pyo3(from_py_with = arg::n0)] n0: f64,
    #[pyo3(from_py_with = arg::radius)] radius: f64,
    #[pyo3(from_py_with = arg::mass)] mass: f64,
    #[pyo3(from_py_with = arg::g)] g: f64,
    method: &str,
    #[pyo3(from_py_with = arg::rtol)] rtol: Option<f64>,
    #[pyo3(from_py_with = arg::atol)] atol: Option<f64>,
    stop_when: Vec<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let (how, _) = integration_of(method, rtol, atol, &[])?;
    let stops = thresholds(&stop_when)?;
    let hoop = Hoop::new(radius, mass, g).map_err(|e| err(e.to_string()))?;
    let grid = grid_of(duration, step, every)?;
    samples_within(&grid, duration, step, every)?;
    let x0 = [theta0, p0, n0, s0];
    // Ctrl-C ends the run within a step (KeyboardInterrupt, the samples dropped).
    let tr = interruptible(py, |stop| hoop.simulate_until(x0, &grid, &how, &stops, stop))?
        .map_err(|e| err(e.to_string()))?;
    trajectory_dict(py, &tr, &how, &stop_when)
}

/// Integrates the mounted unicycle (n° 21–24, no motor moment) of wheel radius `radius` (m)
/// under `g`: `rider` a dict of `mass`, `height`, `a`, `b`, `c`, `l` (n° 21), `wheel` a dict
/// of `mass`, `a1`, `b1`, `c1` (a thin hoop of mass m: `a1` = 1.5 m R², `b1` = 2 m R²,
/// `c1` = 0.5 m R²); the state, options and result as `simulate_hoop`.
#[pyfunction]
#[pyo3(signature = (rider, wheel, radius, theta0, s0, duration, step = 0.001, every = 10, *, p0 = 0.0, n0 = 0.0, g = 9.81, method = "rk4", rtol = None, atol = None, stop_when = Vec::new()))]
#[allow(clippy::too_many_arguments)]
fn simulate_unicycle<'py>(
    py: Python<'py>,
    rider: &Bound<'py, PyAny>,
    wheel: &Bound<'py, PyAny>,
    #[pyo3(from_py_with = arg::radius)] radius: f64,
    #[pyo3(from_py_with = arg::theta0)] theta0: f64,
    #[pyo3(from_py_with = arg::s0)] s0: f64,
    #[pyo3(from_py_with = arg::duration)] duration: f64,
    #[pyo3(from_py_with = arg::step)] step: f64,
    #[pyo3(from_py_with = arg::every)] every: usize,
    #[pyo3(from_py_with = arg::p0)] p0: f64,
    #[pyo3(from_py_with = arg::n0)] n0: f64,
    #[pyo3(from_py_with = arg::g)] g: f64,
    method: &str,
    #[pyo3(from_py_with = arg::rtol)] rtol: Option<f64>,
    #[pyo3(from_py_with = arg::atol)] atol: Option<f64>,
    stop_when: Vec<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let (how, _) = integration_of(method, rtol, atol, &[])?;
    let stops = thresholds(&stop_when)?;
    let [mass, height, a, b, c, l] =
        numbers_of(rider, "rider", ["mass", "height", "a", "b", "c", "l"])?;
    let [wheel_mass, a1, b1, c1] = numbers_of(wheel, "wheel", ["mass", "a1", "b1", "c1"])?;
    let rider = Rider { mass, height, a, b, c, l };
    let wheel = Wheel { mass: wheel_mass, a1, b1, c1 };
    let unicycle = Unicycle::new(radius, g, rider, wheel).map_err(|e| err(e.to_string()))?;
    let grid = grid_of(duration, step, every)?;
    samples_within(&grid, duration, step, every)?;
    let x0 = [theta0, p0, n0, s0];
    let tr = interruptible(py, |stop| unicycle.simulate_until(x0, &grid, &how, &stops, stop))?
        .map_err(|e| err(e.to_string()))?;
    trajectory_dict(py, &tr, &how, &stop_when)
}

/// Adds the functions to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(simulate_hoop, m)?)?;
    m.add_function(wrap_pyfunction!(simulate_unicycle, m)?)?;
    Ok(())
}
