//! Steady turns of the nonlinear Carvallo–Whipple bicycle for Python (memoir ch. IV,
//! n° 79–106): `steady_turn(params, speed, lean, steer=None)` returns every turn at the rear
//! contact's speed and the lean as a list of dicts, the runtime's
//! `carvallo::whipple::steady_turn` doing the work (the same numbers as `carvallo turn
//! --model benchmark|FILE --json`), and those of the leaning rider for its params.

use carvallo::whipple::steady_turn::lean_rider::{RiderTurn, RiderTurnSolver};
use carvallo::whipple::steady_turn::{SteadyTurn, TurnError, TurnSolver};
use numpy::Complex64;
use pyo3::prelude::*;
use pyo3::types::{PyComplex, PyDict, PyList};

use crate::common::{err, params_of};
use crate::guard::arg;

/// One turn as a dict: `steer`, `pitch`, `yaw_rate`, `radius` (inf when straight),
/// `steer_torque`, `rear_wheel_rate`, `front_wheel_rate`, `normal_force`, `lateral_force` and
/// `friction` (each `(rear, front)`), `on_ground`, `stable`, `eigenvalues` (four complex),
/// `family_eigenvalue` and the residuals `roll_row`, `rear_wheel_row`, `momentum_balance`.
fn turn_dict<'py>(py: Python<'py>, t: &SteadyTurn) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let f = &t.forces;
    d.set_item("speed", t.speed)?;
    d.set_item("lean", t.lean)?;
    d.set_item("steer", t.steer)?;
    d.set_item("pitch", t.pitch)?;
    d.set_item("yaw_rate", t.yaw_rate)?;
    d.set_item("radius", t.radius)?;
    d.set_item("steer_torque", t.steer_torque)?;
    d.set_item("rear_wheel_rate", t.rear_wheel_rate)?;
    d.set_item("front_wheel_rate", t.front_wheel_rate)?;
    d.set_item("normal_force", (f.rear_normal, f.front_normal))?;
    d.set_item("lateral_force", (f.rear_lateral, f.front_lateral))?;
    d.set_item("friction", (f.rear_friction, f.front_friction))?;
    d.set_item("on_ground", f.on_ground())?;
    d.set_item("stable", t.stability.stable)?;
    let c = |z: &Complex64| PyComplex::from_doubles(py, z.re, z.im);
    d.set_item("eigenvalues", PyList::new(py, t.stability.eigenvalues.iter().map(c))?)?;
    d.set_item("family_eigenvalue", c(&t.stability.family))?;
    d.set_item("roll_row", t.roll_residual)?;
    d.set_item("rear_wheel_row", t.rear_row_residual)?;
    d.set_item("momentum_balance", f.balance_residual)?;
    Ok(d)
}

/// One turn of the leaning rider as a dict: as the bicycle's without the forces, with
/// `torso_lean` and the lean joint's residual `lean_row`; six `eigenvalues`.
fn rider_dict<'py>(py: Python<'py>, t: &RiderTurn) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("speed", t.speed)?;
    d.set_item("lean", t.lean)?;
    d.set_item("steer", t.steer)?;
    d.set_item("torso_lean", t.torso_lean)?;
    d.set_item("pitch", t.pitch)?;
    d.set_item("yaw_rate", t.yaw_rate)?;
    d.set_item("radius", t.radius)?;
    d.set_item("steer_torque", t.steer_torque)?;
    d.set_item("rear_wheel_rate", t.rear_wheel_rate)?;
    d.set_item("stable", t.stability.stable)?;
    let c = |z: &Complex64| PyComplex::from_doubles(py, z.re, z.im);
    d.set_item("eigenvalues", PyList::new(py, t.stability.eigenvalues.iter().map(c))?)?;
    d.set_item("family_eigenvalue", c(&t.stability.family))?;
    d.set_item("roll_row", t.roll_residual)?;
    d.set_item("lean_row", t.torso_residual)?;
    d.set_item("rear_wheel_row", t.rear_row_residual)?;
    Ok(d)
}

/// The item whose steer (`of`) is nearest `steer` on the circle.
fn nearest<T: Copy>(items: &[T], steer: f64, of: impl Fn(&T) -> f64) -> Option<T> {
    let gap = |a: f64| {
        let d = (a - steer).rem_euclid(std::f64::consts::TAU);
        d.min(std::f64::consts::TAU - d)
    };
    items.iter().copied().min_by(|a, b| gap(of(a)).total_cmp(&gap(of(b))))
}

/// Every steady turn of the bicycle `params` at the rear contact's `speed` (m/s, positive) and
/// the `lean` (rad, positive to the right, within ±π/2), by increasing steer; with `steer`
/// (rad), only the turn whose steer is nearest (on the circle). An empty list when no steer
/// holds that lean at that speed. See `carvallo turn --model benchmark --lean RAD`. For the
/// leaning rider's params (`lean_rider()`), its turns with the torso's lean (`torso_lean`) on
/// its joint, six eigenvalues and no forces.
#[pyfunction]
#[pyo3(signature = (params, speed, lean, steer = None, strict = false))]
fn steady_turn<'py>(
    py: Python<'py>,
    params: &Bound<'py, PyAny>,
    #[pyo3(from_py_with = arg::speed)] speed: f64,
    #[pyo3(from_py_with = arg::lean)] lean: f64,
    #[pyo3(from_py_with = arg::steer)] steer: Option<f64>,
    strict: bool,
) -> PyResult<Bound<'py, PyList>> {
    if let Some(s) = steer {
        if !s.is_finite() {
            return Err(err(format!("invalid steer {s:?}: must be finite")));
        }
    }
    if let Some(rider) = crate::lean_rider::rider_of(params)? {
        let solver = RiderTurnSolver::new(&rider);
        let turns = py.detach(|| solver.turns(speed, lean)).map_err(|e| err(e.to_string()))?;
        let list = match steer {
            Some(s) => nearest(&turns.turns, s, |t| t.steer).into_iter().collect(),
            None => turns.turns,
        };
        let dicts = list.iter().map(|t| rider_dict(py, t)).collect::<PyResult<Vec<_>>>()?;
        return PyList::new(py, dicts);
    }
    let params = params_of(params, strict)?;
    let failed = |e: TurnError| err(e.to_string());
    let solver = TurnSolver::new(&params).map_err(failed)?;
    let turns = py.detach(|| solver.turns(speed, lean)).map_err(failed)?;
    let list = match steer {
        Some(s) => nearest(&turns.turns, s, |t| t.steer).into_iter().collect(),
        None => turns.turns,
    };
    let dicts = list.iter().map(|t| turn_dict(py, t)).collect::<PyResult<Vec<_>>>()?;
    PyList::new(py, dicts)
}

/// Adds `steady_turn` to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(steady_turn, m)?)?;
    Ok(())
}
