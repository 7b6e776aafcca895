//! The two-wheeled inverted pendulum for Python ([`carvallo::wheeled_pendulum`]): its nominal
//! parameters (`pendulum_params`), the eigenvalues and the state space of its linear model about
//! upright straight running (`pendulum_eigenvalues`, `pendulum_state_space`), and the nonlinear
//! simulation open loop or under a state feedback (`simulate_pendulum`), numpy arrays out; the
//! runtime does the work, the simulation with the GIL released, as `carvallo pendulum` does on
//! the command line.

use carvallo::numerics::integrate::Grid;
use carvallo::wheeled_pendulum::{
    Feedback, WheeledPendulum, WheeledPendulumParams, FALL_ANGLE, STATE_NAMES,
};
use numpy::{Complex64, PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::common::{err, integration_of, pairs, OrBad};
use crate::guard::{arg, interruptible, optional_reals, within};

/// The model of `params`: the nominal design with the values of the dict `params` (None: the
/// nominal design), every name one of `WheeledPendulumParams::NAMES`.
fn model_of(params: Option<&Bound<'_, PyAny>>) -> PyResult<WheeledPendulum> {
    let mut p = WheeledPendulumParams::nominal();
    if let Some(params) = params.filter(|p| !p.is_none()) {
        for (name, value) in pairs(params, "params")? {
            p = p.with(&name, value).map_err(|e| err(format!("params: {e}")))?;
        }
    }
    Ok(WheeledPendulum::new(p))
}

/// The nominal design's parameters `{name: value}` (SI units): a personal transporter with its
/// rider, illustrative values, not a published data set.
#[pyfunction]
fn pendulum_params(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let d = PyDict::new(py);
    let p = WheeledPendulumParams::nominal();
    for (name, value) in WheeledPendulumParams::NAMES.iter().zip(p.values()) {
        d.set_item(*name, *value)?;
    }
    Ok(d)
}

/// The eigenvalues of the linear model at each speed (m/s), shape (n, 4) complex, by
/// decreasing real part: the pitch's λ, the two zeros, -λ. `params` changes values of the
/// nominal design (`pendulum_params()`).
#[pyfunction]
#[pyo3(signature = (speeds, *, params = None))]
fn pendulum_eigenvalues<'py>(
    py: Python<'py>,
    speeds: &Bound<'py, PyAny>,
    params: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyArray2<Complex64>>> {
    let m = model_of(params)?;
    let speeds = crate::python::speeds_of(speeds)?;
    within(&format!("{} speeds", speeds.len()), speeds.len() as f64, 4.0 * 16.0)?;
    let flat: Vec<Complex64> = speeds
        .iter()
        .flat_map(|v| m.linear(*v).eigenvalues().map(|z| Complex64::new(z.re, z.im)))
        .collect();
    PyArray1::from_vec(py, flat).reshape([speeds.len(), 4])
}

/// Two arrays of floats: a state space's `(A, B)`.
type Pair<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<f64>>);

/// `(A, B)` of the linear model at `speed` (m/s): A (4, 4) over the state (theta, thetad,
/// thetaLd, thetaRd), B (4, 2) over the motor torques (TL, TR).
#[pyfunction]
#[pyo3(signature = (speed, *, params = None))]
fn pendulum_state_space<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = arg::speed)] speed: f64,
    params: Option<&Bound<'py, PyAny>>,
) -> PyResult<Pair<'py>> {
    if !speed.is_finite() {
        return Err(err(format!("invalid speed {speed}: must be finite")));
    }
    let lin = model_of(params)?.linear(speed);
    let a: Vec<f64> =
        (0..4).flat_map(|i| (0..4).map(move |j| (i, j))).map(|ij| lin.a[ij]).collect();
    let b: Vec<f64> =
        (0..4).flat_map(|i| (0..2).map(move |j| (i, j))).map(|ij| lin.b[ij]).collect();
    Ok((PyArray1::from_vec(py, a).reshape([4, 4])?, PyArray1::from_vec(py, b).reshape([4, 2])?))
}

/// The feedback of `gain`: None (open loop), `"placed"` (poles `poles`, or -λ, -1.5λ, -2λ) or
/// K as 2 rows (TL, TR) of 4 numbers.
fn feedback_of(
    m: &WheeledPendulum,
    speed: f64,
    gain: Option<&Bound<'_, PyAny>>,
    poles: Option<Vec<f64>>,
) -> PyResult<Option<Feedback>> {
    let lin = m.linear(speed);
    let gain = gain.filter(|g| !g.is_none());
    let placed = gain.is_some_and(|g| g.extract::<String>().is_ok_and(|s| s == "placed"));
    if poles.is_some() && !placed {
        return Err(err("poles are placed by gain = \"placed\""));
    }
    let Some(gain) = gain else { return Ok(None) };
    if placed {
        let poles = match poles {
            None => lin.default_poles(),
            Some(p) => <[f64; 3]>::try_from(p.clone())
                .map_err(|_| err(format!("invalid poles {p:?}: must be 3 numbers")))?,
        };
        return lin.place(poles).map(Some).map_err(|e| err(format!("poles: {e}")));
    }
    let bad = || err("invalid gain: must be \"placed\" or K as 2 rows (TL, TR) of 4 numbers");
    let rows: Vec<Vec<f64>> = gain.extract().or_bad(bad)?;
    let k: [[f64; 4]; 2] = rows
        .into_iter()
        .map(|r| <[f64; 4]>::try_from(r).map_err(|_| bad()))
        .collect::<PyResult<Vec<_>>>()?
        .try_into()
        .map_err(|_| bad())?;
    lin.feedback(k).map(Some).map_err(|e| err(e.to_string()))
}

/// Simulates the nonlinear model from upright straight running at `speed` (m/s) pitched by
/// `pitch0` (rad) over `t_end` seconds: open loop, or under the state feedback
/// $T = -K(x - x_{ref})$ of `gain` (`"placed"`: poles placed on the pitch and forward motion at
/// `poles` or at -λ, -1.5λ, -2λ; or K, 2 rows TL, TR over theta, thetad, thetaLd, thetaRd), by
/// `method` (dop853 by default; `rtol`, `atol` as `simulate`), sampled every `every` ×
/// `step` seconds. A dict: arrays `t`, `x`, `y`, `psi`, `theta`, `thetad`, `thetaLd`,
/// `thetaRd`, `TL`, `TR`; `status` ("fell" or "completed"), `fall_time` (s or None),
/// `energy0` (J), `max_energy_change` (J: the drift with the motors off, their work with
/// feedback), `gain` (the (2, 4) K or None), and the counts of `simulate_hoop`.
#[pyfunction]
#[pyo3(signature = (t_end, pitch0, *, speed = 2.0, params = None, gain = None, poles = None, step = 0.01, every = 1, method = "dop853", rtol = None, atol = None))]
#[allow(clippy::too_many_arguments)]
fn simulate_pendulum<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = arg::t_end)] t_end: f64,
    #[pyo3(from_py_with = arg::pitch0)] pitch0: f64,
    #[pyo3(from_py_with = arg::speed)] speed: f64,
    params: Option<&Bound<'py, PyAny>>,
    gain: Option<&Bound<'py, PyAny>>,
    poles: Option<&Bound<'py, PyAny>>,
    #[pyo3(from_py_with = arg::step)] step: f64,
    #[pyo3(from_py_with = arg::every)] every: usize,
    method: &str,
    #[pyo3(from_py_with = arg::rtol)] rtol: Option<f64>,
    #[pyo3(from_py_with = arg::atol)] atol: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let (how, _) = integration_of(method, rtol, atol, &[])?;
    if !speed.is_finite() {
        return Err(err(format!("invalid speed {speed}: must be finite")));
    }
    if pitch0.is_nan() || pitch0.abs() >= FALL_ANGLE {
        return Err(err(format!("invalid pitch0 {pitch0}: must be less than pi/2 in magnitude")));
    }
    let m = model_of(params)?;
    let poles = match poles {
        Some(p) => optional_reals(p, "poles")?,
        None => None,
    };
    let feedback = feedback_of(&m, speed, gain, poles)?;
    let grid = Grid::new(t_end, step, every).map_err(|(name, value, reason)| {
        let name = if name == "duration" { "t_end" } else { name };
        err(carvallo::ParameterError::InvalidParameter { name, value, reason }.to_string())
    })?;
    within(
        &format!("t_end = {t_end}, step = {step}, every = {every}"),
        grid.samples() as f64,
        80.0,
    )?;
    let torques = |x: &[f64; 7]| feedback.as_ref().map_or([0.0, 0.0], |k| k.torques(x));
    let mut x0 = m.upright(speed);
    x0[3] = pitch0;
    let run = interruptible(py, |_stop| m.simulate(x0, &|_, x| torques(x), &grid, &how))?
        .map_err(|e| err(e.to_string()))?;
    let d = PyDict::new(py);
    d.set_item("t", PyArray1::from_vec(py, run.times.clone()))?;
    for (k, name) in STATE_NAMES.iter().enumerate() {
        d.set_item(*name, PyArray1::from_vec(py, run.samples.iter().map(|x| x[k]).collect()))?;
    }
    for (k, name) in ["TL", "TR"].iter().enumerate() {
        let column = run.samples.iter().map(|x| torques(x)[k]).collect();
        d.set_item(*name, PyArray1::from_vec(py, column))?;
    }
    d.set_item("status", if run.fall.is_some() { "fell" } else { "completed" })?;
    d.set_item("fall_time", run.fall)?;
    d.set_item("energy0", run.energy0)?;
    d.set_item("max_energy_change", run.max_energy_drift)?;
    match &feedback {
        Some(k) => {
            let flat: Vec<f64> = k.gain.iter().flatten().copied().collect();
            d.set_item("gain", PyArray1::from_vec(py, flat).reshape([2, 4])?)?
        }
        None => d.set_item("gain", py.None())?,
    }
    crate::common::set_run(&d, &how, &run.stats, None)?;
    Ok(d)
}

/// Adds the functions to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(pendulum_params, m)?)?;
    m.add_function(wrap_pyfunction!(pendulum_eigenvalues, m)?)?;
    m.add_function(wrap_pyfunction!(pendulum_state_space, m)?)?;
    m.add_function(wrap_pyfunction!(simulate_pendulum, m)?)?;
    Ok(())
}
