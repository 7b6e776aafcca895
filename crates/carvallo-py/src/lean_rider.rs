//! Moore's (2012) leaning rider for Python ([`carvallo::whipple::lean_rider`]):
//! `lean_rider(path=None)` gives its parameters as a dict in Moore's names (BicycleParameters'
//! `mooreriderlean2012_browser_jason`, or a parameter file), and `eigenvalues`, `state_space`
//! and `window` take such a dict where they take a bicycle's: the parameters select the model,
//! as a file in Moore's names does for the CLI's `--model`. The work runs with the GIL released
//! and stops on Ctrl-C.

use std::sync::atomic::Ordering;

use carvallo::whipple::lean_rider::{LeanRider, LeanRiderParams, INPUT_NAMES, STATE_NAMES};
use numpy::{Complex64, PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::common::{err, pairs};
use crate::guard::{interruptible, read_text, within};

/// The leaning rider's parameters when `params` is a mapping in Moore's names (it holds `mg`,
/// `ig11` and `d4`); `None` for anything else (a bicycle's parameters, read as before).
///
/// # Errors
/// A `ParameterError` naming the unknown, missing or bad value of a mapping in Moore's names.
pub(crate) fn rider_of(params: &Bound<'_, PyAny>) -> PyResult<Option<LeanRider>> {
    let Ok(d) = params.cast::<PyDict>() else {
        return Ok(None);
    };
    for key in ["mg", "ig11", "d4"] {
        if !d.contains(key)? {
            return Ok(None);
        }
    }
    let text: String = pairs(params, "params")?
        .iter()
        .map(|(name, value)| format!("{name} = {value:?}\n"))
        .collect();
    let p = LeanRiderParams::from_text(&text)
        .map_err(|e| err(format!("the leaning rider's params: {e}")))?;
    LeanRider::new(p).map(Some).map_err(|e| err(format!("the leaning rider's params: {e}")))
}

/// The parameters of Moore's (2012) leaning rider as a dict in Moore's names (36 values: the
/// hinge and frame lengths `d1`–`d4`, `l1`–`l6`, the wheel radii `rr`, `rf`, the masses `mc`,
/// `md`, `me`, `mf`, `mg` (torso), their inertias, `g`, and the lean joint's damping `c9` and
/// stiffness `k9`): BicycleParameters' `mooreriderlean2012_browser_jason` (Jason on the
/// Browser bicycle), or the `name = value` file `path`. Give it to `eigenvalues`, `state_space`
/// and `window` in place of a bicycle.
#[pyfunction]
#[pyo3(signature = (path = None))]
fn lean_rider<'py>(py: Python<'py>, path: Option<&str>) -> PyResult<Bound<'py, PyDict>> {
    let p = match path {
        None => LeanRiderParams::browser_jason(),
        Some(path) => LeanRiderParams::from_text(&read_text(path, "leaning-rider")?)
            .map_err(|e| err(format!("invalid leaning-rider file `{path}`: {e}")))?,
    };
    let d = PyDict::new(py);
    for (name, value) in LeanRiderParams::NAMES.iter().zip(p.values()) {
        d.set_item(name, value)?;
    }
    Ok(d)
}

/// The six eigenvalues of roll, steer and lean at each speed, shape (n, 6) complex, by
/// decreasing real part (the other six of the 12-state linearisation are zero).
pub(crate) fn eigenvalues<'py>(
    py: Python<'py>,
    rider: &LeanRider,
    speeds: &[f64],
) -> PyResult<Bound<'py, PyArray2<Complex64>>> {
    within(&format!("{} speeds", speeds.len()), speeds.len() as f64, 6.0 * 16.0)?;
    let flat = interruptible(py, |stop| {
        let mut flat = Vec::with_capacity(6 * speeds.len());
        for (k, v) in speeds.iter().enumerate() {
            if k % 64 == 0 && stop.load(Ordering::Relaxed) {
                break;
            }
            flat.extend(rider.eigenvalues(*v).iter().map(|e| Complex64::new(e.re, e.im)));
        }
        flat
    })?;
    PyArray1::from_vec(py, flat).reshape([speeds.len(), 6])
}

/// `(A, B)` at each speed, shapes (n, 12, 12) and (n, 12, 3): Moore's state
/// `q1 q2 q3 q4 q6 q7 q8 q9 u4 u6 u7 u9`, inputs `T4 T7 T9` (as BicycleParameters'
/// `form_state_space_matrices`).
pub(crate) fn state_space<'py>(
    py: Python<'py>,
    rider: &LeanRider,
    speeds: &[f64],
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    within(&format!("{} speeds", speeds.len()), speeds.len() as f64, 180.0 * 8.0)?;
    let (a, b) = interruptible(py, |stop| {
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for (k, v) in speeds.iter().enumerate() {
            if k % 64 == 0 && stop.load(Ordering::Relaxed) {
                break;
            }
            let (ak, bk) = rider.state_space(*v);
            // nalgebra is column-major: row by row.
            a.extend((0..12).flat_map(|i| (0..12).map(move |j| ak[(i, j)])));
            b.extend((0..12).flat_map(|i| (0..3).map(move |j| bk[(i, j)])));
        }
        (a, b)
    })?;
    let n = speeds.len();
    Ok((
        PyArray1::from_vec(py, a).reshape([n, 12, 12])?.into_any(),
        PyArray1::from_vec(py, b).reshape([n, 12, 3])?.into_any(),
    ))
}

/// `{"stable": [(from, to), ...], "scan": (0.0, 20.0), "state": [...], "inputs": [...]}`: the
/// speeds of a scan of 0 to 20 m/s where all six eigenvalues have negative real parts (as
/// `carvallo window --model lean-rider`); empty for Browser + Jason's passive torso.
pub(crate) fn window<'py>(py: Python<'py>, rider: &LeanRider) -> PyResult<Bound<'py, PyDict>> {
    let (lo, hi, steps) = (0.0, 20.0, 400);
    let stable = interruptible(py, |_| rider.stable_speeds(lo, hi, steps))?;
    let d = PyDict::new(py);
    d.set_item("stable", PyList::new(py, stable)?)?;
    d.set_item("scan", (lo, hi))?;
    d.set_item("state", STATE_NAMES.to_vec())?;
    d.set_item("inputs", INPUT_NAMES.to_vec())?;
    Ok(d)
}

/// Adds `lean_rider` to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(lean_rider, m)?)?;
    Ok(())
}
