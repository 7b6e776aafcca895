//! The leaning rider (Moore 2012, [`carvallo::whipple::lean_rider`]) in `eig`, `window`,
//! `statespace` and `simulate`, selected by `--model lean-rider` (BicycleParameters' Browser + Jason) or by a
//! parameter file in Moore's names ([`crate::args::lean_rider`]).
//!
//! - `eig`: the six eigenvalues of roll, steer and lean at each speed (the other six of the
//!   12-state linearisation are zero), JSON `{"model", "rider": null, "speed", "eigenvalues",
//!   "modes"}` as for the bicycle: the open loop's six modes labelled weave, capsize, caster
//!   or torso ([`LeanRider::modes`]), each `{"label", "re", "im", "vector"` (roll, steer,
//!   lean and their rates)`, "shares": {"roll", "steer", "lean"}}`; empty under `--gain` or
//!   where the labels have no reference speed.
//! - `window`: the speeds of a scan of `[0, 20]` m/s where all six have negative real parts,
//!   each edge bisected to $10^{-10}$ m/s; with Browser + Jason's passive torso
//!   ($k_9 = c_9 = 0$) there is none, and the output says why (the torso's real eigenvalue).
//! - `statespace`: $A$ ($12 \times 12$, state `q1 q2 q3 q4 q6 q7 q8 q9 u4 u6 u7 u9`) and $B$
//!   ($12 \times 3$, inputs `T4 T7 T9`), JSON `{"speed", "state", "inputs", "A", "B"}`.
//! - `bode`: the frequency response from the roll, steer or lean torque to roll, steer, the
//!   torso's lean or their rates ([`carvallo::whipple::lean_rider::LeanTransfer`]), the phase
//!   on the branch its zeros and poles choose, as for the bicycle.
//! - `simulate`: the nonlinear equations from upright straight running at `--speed` with the
//!   roll `--lean0` (rad), under `--torque roll|steer|lean=step:VALUE@TIME` terms, by the
//!   integrator of `--method`, until `--duration`, a fall (the roll or the torso's lean on its
//!   joint reaching `--fall-angle`), the steer lock or Ctrl-C; rows of time, roll, steer, the
//!   torso's lean, yaw, pitch, the rear contact and the energy, then the status line; JSON
//!   with the same columns, `status` (`completed`, `fell`, `torso fell`, `steer lock`,
//!   `interrupted`), `status_line`, the counts and the energy drift. Batches, impulses, torque
//!   files, gains and stop conditions are the bicycle's. A start the library refuses
//!   ([`LeanRider::simulate`]: the roll at or beyond the fall angle, named as `--lean0`, or
//!   the singular configuration) is an error (exit 2).

use carvallo::numerics::integrate::{Grid, IntegrateError, Integration};
use carvallo::whipple::lean_rider::{
    Joint, LeanGains, LeanRider, LeanRiderError, LeanRun, Limits, RunEnd, INPUT_NAMES, STATE_NAMES,
};
use carvallo::whipple::modes::RiderMode;
use carvallo::whipple::transfer::FrequencyPoint;
use carvallo::whipple_nonlinear::SINGULAR_PIVOT;
use nalgebra::Complex;
use serde_json::{json, Value};

use super::simulate_inputs::{Input, Kind};

/// The speeds `window` scans by default (m/s; `--vmin`, `--vmax` change them) and its number
/// of steps.
pub const SCAN: (f64, f64, usize) = (0.0, 20.0, 400);

fn header(model: &str, rider: &LeanRider) -> String {
    format!(
        "model {model} (Moore's leaning rider, 12 states; upright pitch {} rad)\n",
        rider.upright_pitch()
    )
}

/// The gains that are not zero, `name=value` (for text) and as a JSON object.
fn gains_shown(k: &LeanGains) -> (String, Value) {
    let mut text = Vec::new();
    let mut obj = serde_json::Map::new();
    for (i, input) in LeanGains::INPUTS.iter().enumerate() {
        for (j, state) in LeanGains::STATES.iter().enumerate() {
            if k.0[i][j] != 0.0 {
                let name = format!("k_{input}_{state}");
                text.push(format!("{name}={}", k.0[i][j]));
                obj.insert(name, json!(k.0[i][j]));
            }
        }
    }
    (text.join(", "), Value::Object(obj))
}

/// One labelled mode as JSON (the module docs' keys).
fn mode_json(m: &RiderMode) -> Value {
    let c = |z: &Complex<f64>| json!({ "re": z.re, "im": z.im });
    let [roll, steer, lean] = m.shares();
    json!({
        "label": m.label.name(),
        "re": m.eigenvalue.re,
        "im": m.eigenvalue.im,
        "vector": m.vector.iter().map(c).collect::<Vec<_>>(),
        "shares": { "roll": roll, "steer": steer, "lean": lean },
    })
}

/// `carvallo eig` on the leaning rider (`--gain`: the closed loop $A - BK$).
pub fn eig(
    model: &str,
    rider: &LeanRider,
    k: &LeanGains,
    speeds: &[f64],
    as_json: bool,
) -> Result<String, String> {
    let mut values = Vec::new();
    let mut s = header(model, rider);
    let closed = *k != LeanGains::default();
    let (gains_text, gains_json) = gains_shown(k);
    let modes = match as_json && !closed {
        true => rider.modes(speeds),
        false => None,
    };
    for (i, &v) in speeds.iter().enumerate() {
        let labelled: Vec<Value> =
            modes.as_ref().map_or(Vec::new(), |m| m[i].iter().map(mode_json).collect());
        let ev = rider.closed_loop_eigenvalues(v, k);
        let list: Vec<Value> = ev.iter().map(|e| json!({ "re": e.re, "im": e.im })).collect();
        let mut value = json!({
            "model": model,
            "rider": Value::Null,
            "speed": v,
            "eigenvalues": list,
            "modes": labelled,
        });
        if closed {
            value["gains"] = gains_json.clone();
            s.push_str(&format!(
                "closed-loop eigenvalues of roll, steer and lean at {v} m/s, gains {gains_text}:\n"
            ));
        } else {
            s.push_str(&format!("eigenvalues of roll, steer and lean at {v} m/s:\n"));
        }
        values.push(value);
        for e in &ev {
            s.push_str(&format!("{} {:+}i\n", e.re, e.im));
        }
    }
    if as_json {
        let v = if values.len() == 1 { values.remove(0) } else { Value::Array(values) };
        return serde_json::to_string_pretty(&v).map_err(|e| e.to_string());
    }
    Ok(s)
}

/// `carvallo window` on the leaning rider: the speeds of `scan` (m/s; 400 steps) where the
/// loop closed by `k` (open for zero gains) is stable.
pub fn window(
    model: &str,
    rider: &LeanRider,
    k: &LeanGains,
    scan: (f64, f64),
    as_json: bool,
) -> Result<String, String> {
    let ((lo, hi), steps) = (scan, SCAN.2);
    let stable = rider.closed_loop_stable_speeds(lo, hi, steps, k);
    // Why nothing is stable: the largest real part over the scan, where it is least.
    let least = (0..=steps)
        .map(|i| {
            let v = lo + (hi - lo) * i as f64 / steps as f64;
            (v, rider.closed_loop_eigenvalues(v, k)[0])
        })
        .min_by(|a, b| a.1.re.total_cmp(&b.1.re))
        .expect("a scan");
    if as_json {
        let v = json!({
            "model": model,
            "rider": Value::Null,
            "scan": [lo, hi],
            "stable": stable.iter().map(|(a, b)| json!([a, b])).collect::<Vec<_>>(),
            "least_growth": { "speed": least.0, "re": least.1.re, "im": least.1.im },
            "gains": gains_shown(k).1,
        });
        return serde_json::to_string_pretty(&v).map_err(|e| e.to_string());
    }
    let mut s = header(model, rider);
    if *k != LeanGains::default() {
        s.push_str(&format!("closed loop, gains {}\n", gains_shown(k).0));
    }
    if stable.is_empty() {
        s.push_str(&format!(
            "no stable speed from {lo} to {hi} m/s: the least growing mode still grows at \
             {} {:+}i 1/s ({} m/s){}\n",
            least.1.re,
            least.1.im,
            least.0,
            if least.1.im == 0.0 && k.0[2][2] == 0.0 && rider.params().get("k9") == Some(0.0) {
                " (a real eigenvalue: with k9 = c9 = 0 the torso falls on its joint; give the \
                 lean joint stiffness k9 and damping c9)"
            } else {
                ""
            }
        ));
    }
    for (a, b) in &stable {
        s.push_str(&format!("stable from {a} to {b} m/s\n"));
    }
    Ok(s)
}

/// `carvallo statespace` on the leaning rider.
pub fn statespace(
    model: &str,
    rider: &LeanRider,
    speeds: &[f64],
    as_json: bool,
) -> Result<String, String> {
    let mut values = Vec::new();
    let mut s = header(model, rider);
    for &v in speeds {
        let (a, b) = rider.state_space(v);
        let rows = |m: &dyn Fn(usize, usize) -> f64, n: usize| -> Vec<Vec<f64>> {
            (0..12).map(|i| (0..n).map(|j| m(i, j)).collect()).collect()
        };
        let (ar, br) = (rows(&|i, j| a[(i, j)], 12), rows(&|i, j| b[(i, j)], 3));
        s.push_str(&format!(
            "state space at {v} m/s, x = ({}), u = ({}), C = I, D = 0\nA =\n",
            STATE_NAMES.join(", "),
            INPUT_NAMES.join(", ")
        ));
        for (name, m) in [("A", &ar), ("B", &br)] {
            if name == "B" {
                s.push_str("B =\n");
            }
            for row in m {
                let cells: Vec<String> = row.iter().map(|x| format!("{x:>22}")).collect();
                s.push_str(&format!("{}\n", cells.join(" ")));
            }
        }
        values.push(json!({
            "speed": v,
            "state": STATE_NAMES,
            "inputs": INPUT_NAMES,
            "A": ar,
            "B": br,
        }));
    }
    if as_json {
        let v = if values.len() == 1 { values.remove(0) } else { Value::Array(values) };
        return serde_json::to_string_pretty(&v).map_err(|e| e.to_string());
    }
    Ok(s)
}

/// `carvallo simulate` on the leaning rider.
pub fn simulate(
    cmd: &super::simulate::Args,
    rider: &LeanRider,
    how: &Integration,
) -> Result<String, String> {
    let model = &cmd.model;
    let not_here = |what: &str| {
        Err(format!("{what} is for the bicycle, not yet for the leaning rider `{model}`"))
    };
    if cmd.batch.is_some() {
        return not_here("--batch");
    }
    if !cmd.integration.stop_when.is_empty() {
        return not_here("--stop-when");
    }
    let inputs = &cmd.inputs;
    if inputs.torque_csv.is_some() || !inputs.gain.is_empty() || inputs.gain_table.is_some() {
        return not_here("--torque-csv, --gain and --gain-table");
    }
    let mut steps = Vec::new();
    for term in &inputs.torque {
        if term.kind == Kind::Impulse {
            return Err(format!(
                "invalid --torque `{}`: impulses are for the bicycle; the leaning rider takes \
                 steps (INPUT=step:VALUE@TIME)",
                term.text
            ));
        }
        let k = match term.input {
            Input::Roll => 0,
            Input::Steer => 2,
            Input::Lean => 3,
        };
        steps.push((k, term.value, term.time));
    }
    let (Some(speed), Some(lean0)) = (cmd.speed, cmd.lean0) else {
        return Err("--speed and --lean0 are required without --batch".into());
    };
    let limits = Limits { fall_angle: cmd.fall_angle, steer_lock: cmd.steer_lock };
    let grid = Grid::exact(cmd.duration, cmd.step, cmd.every)
        .map_err(|(name, value, reason)| format!("invalid --{name} {value:?}: {reason}"))?;
    let torques = move |t: f64| {
        let mut u = [0.0; 4];
        for &(k, value, start) in &steps {
            if t >= start {
                u[k] += value;
            }
        }
        u
    };
    let mut x0 = rider.upright(speed);
    x0[3] = lean0;
    let run = rider
        .simulate(x0, &torques, Joint::Free, &grid, how, limits, crate::interrupt::interrupt_flag())
        .map_err(|e| match e {
            IntegrateError::Model(e) => bad_start(lean0, &e),
            e => format!(
                "the integration diverged: {e:?} (--method {}); take a smaller --step or an \
                 adaptive --method",
                how.method.name()
            ),
        })?;
    let (status, line) = (run.end.0.status(), run.status_line(limits));
    const COLUMNS: [&str; 9] = LeanRun::COLUMNS;
    let table = run.table(rider);
    if cmd.json {
        let mut v = json!({
            "model": model,
            "speed": speed,
            "lean0": lean0,
            "method": how.method.name(),
            "rtol": how.method.is_adaptive().then_some(how.rtol),
            "atol": how.method.is_adaptive().then_some(how.atol),
            "status": status,
            "status_line": line,
            "fall_angle": limits.fall_angle,
            "steer_lock": limits.steer_lock,
            "singular_pivot": SINGULAR_PIVOT,
            "singular_t": match run.end.0 {
                RunEnd::Singular { t, .. } => Some(t),
                _ => None,
            },
            "rhs_evaluations": run.stats.rhs_evaluations,
            "steps": run.stats.steps,
            "rejected_steps": run.stats.rejected_steps,
            "max_energy_drift": run.max_energy_drift,
        });
        for (k, name) in COLUMNS.iter().enumerate() {
            v[*name] = json!(table.iter().map(|r| r[k]).collect::<Vec<_>>());
        }
        return serde_json::to_string_pretty(&v).map_err(|e| e.to_string());
    }
    let mut s = header(model, rider);
    s.push_str(&format!("{}\n", COLUMNS.join(" ")));
    for r in &table {
        let cells: Vec<String> = r.iter().map(|x| format!("{x}")).collect();
        s.push_str(&format!("{}\n", cells.join(" ")));
    }
    let energy = if inputs.torque.is_empty() {
        "energy drift"
    } else {
        "largest energy change (the torques do work)"
    };
    s.push_str(&format!(
        "{line}\nmethod {}, {} steps ({} rejected), {} evaluations; {energy} {:e} J\n",
        how.method.name(),
        run.stats.steps,
        run.stats.rejected_steps,
        run.stats.rhs_evaluations,
        run.max_energy_drift
    ));
    Ok(s)
}

/// The message of a start that [`LeanRider::simulate`] refuses, naming `--lean0` for the
/// roll at or beyond the fall angle (the library's message otherwise: the singular
/// configuration names the roll and the pivot).
fn bad_start(lean0: f64, e: &LeanRiderError) -> String {
    match e {
        LeanRiderError::Fallen { fall_angle, .. } => format!(
            "invalid --lean0 {lean0}: at or beyond the fall angle ±{fall_angle} rad \
             (--fall-angle), where the bicycle is on the ground"
        ),
        other => other.to_string(),
    }
}

/// `carvallo bode` on the leaning rider: the points of the transfer function from torque
/// `input` (0 roll, 1 steer, 2 lean) to the lateral state `output` at each speed and frequency.
pub fn frequency_response(
    rider: &LeanRider,
    speeds: &[f64],
    omegas: &[f64],
    input: usize,
    output: usize,
) -> Vec<FrequencyPoint> {
    speeds
        .iter()
        .flat_map(|&v| {
            rider
                .frequency_response(v, omegas, input, output)
                .expect("indices of the possible values")
        })
        .collect()
}
