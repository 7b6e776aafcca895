//! Moore's (2012) leaning rider for Python ([`carvallo::whipple::lean_rider`]):
//! `lean_rider(path=None)` gives its parameters as a dict in Moore's names (BicycleParameters'
//! `mooreriderlean2012_browser_jason`, or a parameter file), and `eigenvalues`, `state_space`
//! and `window` take such a dict where they take a bicycle's: the parameters select the model,
//! as a file in Moore's names does for the CLI's `--model`. The work runs with the GIL released
//! and stops on Ctrl-C.

use std::sync::atomic::Ordering;

use carvallo::numerics::integrate::{Grid, IntegrateError, Integration};
use carvallo::whipple::lean_rider::{
    Joint, LeanGains, LeanRider, LeanRiderError, LeanRiderParams, LeanRun, Limits, RunEnd,
    INPUT_NAMES, STATE_NAMES,
};
use carvallo::whipple::transfer::FrequencyPoint;
use numpy::{
    Complex64, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::common::{err, pairs, set_run, OrBad};
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
    eigenvalues_with(py, rider, &LeanGains::default(), speeds)
}

/// As [`eigenvalues`], of the loop closed by `k`.
pub(crate) fn eigenvalues_with<'py>(
    py: Python<'py>,
    rider: &LeanRider,
    k: &LeanGains,
    speeds: &[f64],
) -> PyResult<Bound<'py, PyArray2<Complex64>>> {
    within(&format!("{} speeds", speeds.len()), speeds.len() as f64, 6.0 * 16.0)?;
    let flat = interruptible(py, |stop| {
        let mut flat = Vec::with_capacity(6 * speeds.len());
        for (i, v) in speeds.iter().enumerate() {
            if i % 64 == 0 && stop.load(Ordering::Relaxed) {
                break;
            }
            let ev = rider.closed_loop_eigenvalues(*v, k);
            flat.extend(ev.iter().map(|e| Complex64::new(e.re, e.im)));
        }
        flat
    })?;
    PyArray1::from_vec(py, flat).reshape([speeds.len(), 6])
}

/// The rider's six modes at each speed ([`LeanRider::modes`], as `carvallo eig --model
/// lean-rider --json` labels them): `(labels, eigenvalues, vectors)` with the six labels
/// ("weave", "weave", "capsize", "caster", "torso", "torso"), the eigenvalues (n, 6) complex and
/// the unit eigenvectors (n, 6, 6) complex in NumPy's convention, the columns the vectors over
/// roll, steer, lean and their rates.
pub(crate) fn modes<'py>(
    py: Python<'py>,
    rider: &LeanRider,
    speeds: &[f64],
) -> PyResult<(Vec<&'static str>, Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    within(&format!("{} speeds", speeds.len()), speeds.len() as f64, 42.0 * 16.0 + 64.0)?;
    let all = interruptible(py, |_| rider.modes(speeds))?.ok_or_else(|| {
        err("the leaning rider's modes cannot be followed to these speeds (more than 200 m/s \
             from the reference speed, or no speed of 5 to 50 m/s with one complex pair and four \
             real roots)")
    })?;
    crate::python::modes_arrays(
        py,
        &all,
        |x| x.label.name(),
        |x| Complex64::new(x.eigenvalue.re, x.eigenvalue.im),
        |x| x.vector.map(|c| Complex64::new(c.re, c.im)),
    )
}

/// The leaning rider's gains of `k`: a dict by name or a (3, 6) array (rows roll, steer, lean
/// torque; columns roll, steer, lean and their rates), finite.
pub(crate) fn gains_of(k: &Bound<'_, PyAny>) -> PyResult<LeanGains> {
    let gains = if k.cast::<PyDict>().is_ok() {
        let pairs = pairs(k, "K")?;
        LeanGains::from_named(pairs.iter().map(|(n, v)| (n.as_str(), *v))).map_err(err)?
    } else {
        let bad = || {
            err("K must be a (3, 6) array (rows roll, steer, lean torque) or a dict of gains by \
                 name, for the leaning rider")
        };
        let arr = k.py().import("numpy")?.call_method1("asarray", (k, "float64")).or_bad(bad)?;
        let arr: PyReadonlyArray2<f64> = arr.extract().or_bad(bad)?;
        if arr.shape() != [3, 6] {
            return Err(err(format!("K must have the shape (3, 6), not {:?}", arr.shape())));
        }
        let view = arr.as_array();
        LeanGains(std::array::from_fn(|r| std::array::from_fn(|c| view[[r, c]])))
    };
    if let Some(x) = gains.0.iter().flatten().find(|x| !x.is_finite()) {
        return Err(err(format!("a gain {x} is not finite")));
    }
    Ok(gains)
}

/// `closed_loop_window` on the leaning rider: the stable speeds of a scan from `vmin` (0) to
/// `vmax` (20 m/s) in 400 steps, edges bisected to 1e-10 m/s.
pub(crate) fn closed_loop_window<'py>(
    py: Python<'py>,
    rider: &LeanRider,
    k: &LeanGains,
    vmin: Option<f64>,
    vmax: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let (lo, hi) = (vmin.unwrap_or(0.0), vmax.unwrap_or(20.0));
    if !(lo.is_finite() && hi.is_finite() && hi > lo) {
        return Err(err(format!("invalid vmin {lo:?}, vmax {hi:?}: finite, vmax above vmin")));
    }
    let stable = interruptible(py, |_| rider.closed_loop_stable_speeds(lo, hi, 400, k))?;
    let d = PyDict::new(py);
    d.set_item("from", lo)?;
    d.set_item("to", hi)?;
    d.set_item("stable", PyList::new(py, stable)?)?;
    Ok(d)
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

/// The torques of a simulation: `t` (increasing) and the roll, steer and lean torques at those
/// times (N m), linearly interpolated, zero outside.
pub(crate) struct Torques {
    t: Vec<f64>,
    series: [Option<Vec<f64>>; 3],
}

impl Torques {
    /// Checks the series: `t` with at least one of them, each as long as `t`, finite, `t`
    /// increasing.
    pub(crate) fn new(t: Option<Vec<f64>>, series: [Option<Vec<f64>>; 3]) -> PyResult<Torques> {
        let names = ["torque_roll", "torque_steer", "torque_lean"];
        let Some(t) = t else {
            if let Some(k) = series.iter().position(Option::is_some) {
                return Err(err(format!("{} needs torque_t, the times of its values", names[k])));
            }
            return Ok(Torques { t: Vec::new(), series });
        };
        if series.iter().all(Option::is_none) {
            return Err(err("torque_t without torque_roll, torque_steer or torque_lean"));
        }
        if let Some(x) = t.iter().find(|x| !x.is_finite()) {
            return Err(err(format!("invalid torque_t {x}: must be finite")));
        }
        if let Some(w) = t.windows(2).find(|w| w[1] <= w[0]) {
            return Err(err(format!(
                "invalid torque_t: {} after {} is not increasing",
                w[1], w[0]
            )));
        }
        for (name, s) in names.iter().zip(&series) {
            if let Some(s) = s {
                if s.len() != t.len() {
                    return Err(err(format!(
                        "invalid {name}: {} values for {} times",
                        s.len(),
                        t.len()
                    )));
                }
                if let Some(x) = s.iter().find(|x| !x.is_finite()) {
                    return Err(err(format!("invalid {name} {x}: must be finite")));
                }
            }
        }
        Ok(Torques { t, series })
    }

    /// `[T4, T6, T7, T9]` at `time`.
    fn at(&self, time: f64) -> [f64; 4] {
        let mut out = [0.0; 4];
        let (t, n) = (&self.t, self.t.len());
        if n == 0 || time < t[0] || time > t[n - 1] {
            return out;
        }
        let k = t.partition_point(|x| *x <= time).clamp(1, n.max(2) - 1);
        for (slot, s) in [0, 2, 3].into_iter().zip(&self.series) {
            if let Some(s) = s {
                out[slot] = if n == 1 {
                    s[0]
                } else {
                    let w = (time - t[k - 1]) / (t[k] - t[k - 1]);
                    s[k - 1] + w * (s[k] - s[k - 1])
                };
            }
        }
        out
    }
}

/// The start and the limits of a simulation.
pub(crate) struct Start {
    pub(crate) speed: f64,
    pub(crate) lean0: f64,
    pub(crate) fall_angle: f64,
    pub(crate) steer_lock: f64,
}

/// `simulate` on the leaning rider (see its doc in `python.rs`).
pub(crate) fn simulate<'py>(
    py: Python<'py>,
    rider: &LeanRider,
    start: Start,
    grid: &Grid,
    how: &Integration,
    torques: &Torques,
) -> PyResult<Bound<'py, PyDict>> {
    let Start { speed, lean0, fall_angle, steer_lock } = start;
    let mut x0 = rider.upright(speed);
    x0[3] = lean0;
    let limits = Limits { fall_angle, steer_lock };
    let run = interruptible(py, |stop| {
        rider.simulate(x0, &|t| torques.at(t), Joint::Free, grid, how, limits, stop)
    })?
    .map_err(|e| match e {
        IntegrateError::Model(e) => err(bad_start(speed, lean0, &e)),
        e => err(format!("the integration failed: {e:?}")),
    })?;
    if let RunEnd::Interrupted { .. } = run.end.0 {
        // interruptible raised KeyboardInterrupt already when the flag came from Ctrl-C.
        return Err(pyo3::exceptions::PyKeyboardInterrupt::new_err("interrupted"));
    }
    let (status, line) = (run.end.0.status(), run.status_line(limits));
    let table = run.table(rider);
    let d = PyDict::new(py);
    for (k, name) in LeanRun::COLUMNS.iter().enumerate() {
        d.set_item(name, PyArray1::from_vec(py, table.iter().map(|r| r[k]).collect()))?;
    }
    d.set_item("status", status)?;
    d.set_item("status_line", line)?;
    d.set_item("fall_angle", fall_angle)?;
    d.set_item("steer_lock", steer_lock)?;
    d.set_item("singular_pivot", carvallo::whipple_nonlinear::SINGULAR_PIVOT)?;
    let singular_t = match run.end.0 {
        RunEnd::Singular { t, .. } => Some(t),
        _ => None,
    };
    d.set_item("singular_t", singular_t)?;
    d.set_item("max_energy_drift", run.max_energy_drift)?;
    set_run(&d, how, &run.stats, None)?;
    Ok(d)
}

/// The message of a start at `speed` and `lean0` or of limits that [`LeanRider::simulate`]
/// refuses, naming the keyword (`lean0`, `speed`, `fall_angle`, `steer_lock`) at fault; the
/// library's message otherwise (the singular configuration, naming the roll and the pivot).
fn bad_start(speed: f64, lean0: f64, e: &LeanRiderError) -> String {
    match e {
        LeanRiderError::Fallen { fall_angle, .. } => format!(
            "invalid lean0 {lean0:?}: at or beyond the fall angle ±{fall_angle} rad (fall_angle)"
        ),
        LeanRiderError::NotFiniteStart { name: "q4", .. } => {
            format!("invalid lean0 {lean0:?}: must be finite")
        }
        LeanRiderError::NotFiniteStart { name: "u6", .. } => {
            format!("invalid speed {speed:?}: must be finite")
        }
        LeanRiderError::Invalid { name: "fall angle", value, reason } => {
            format!("invalid fall_angle {value:?}: {reason}")
        }
        LeanRiderError::Invalid { name: "steer lock", value, reason } => {
            format!("invalid steer_lock {value:?}: {reason}")
        }
        other => other.to_string(),
    }
}

/// The leaning rider's torque `input` (roll, steer, lean: 0, 1, 2) and lateral state `output`
/// (roll, steer, lean, roll-rate, steer-rate, lean-rate: 0–5) by name.
pub(crate) fn signals(input: &str, output: &str) -> PyResult<(usize, usize)> {
    const INPUTS: [&str; 3] = ["roll", "steer", "lean"];
    const OUTPUTS: [&str; 6] = ["roll", "steer", "lean", "roll-rate", "steer-rate", "lean-rate"];
    let i = INPUTS.iter().position(|n| *n == input).ok_or_else(|| {
        err(format!("unknown input `{input}` for the leaning rider: expected roll, steer or lean"))
    })?;
    let o = OUTPUTS.iter().position(|n| *n == output).ok_or_else(|| {
        err(format!(
            "unknown output `{output}` for the leaning rider: expected one of {}",
            OUTPUTS.join(", ")
        ))
    })?;
    Ok((i, o))
}

/// The frequency response of the leaning rider at `speed` from torque `input` to the lateral
/// state `output` at each of `omegas` (the CLI's `bode --model lean-rider`).
pub(crate) fn frequency_response(
    rider: &LeanRider,
    speed: f64,
    omegas: &[f64],
    input: usize,
    output: usize,
) -> Vec<FrequencyPoint> {
    rider.frequency_response(speed, omegas, input, output).expect("indices checked by signals")
}

/// Adds `lean_rider` to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(lean_rider, m)?)?;
    Ok(())
}
