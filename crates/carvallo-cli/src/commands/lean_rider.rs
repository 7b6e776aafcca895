//! The leaning rider (Moore 2012, [`carvallo::whipple::lean_rider`]) in `eig`, `window` and
//! `statespace`, selected by `--model lean-rider` (BicycleParameters' Browser + Jason) or by a
//! parameter file in Moore's names ([`crate::args::lean_rider`]).
//!
//! - `eig`: the six eigenvalues of roll, steer and lean at each speed (the other six of the
//!   12-state linearisation are zero), JSON `{"model", "rider": null, "speed", "eigenvalues",
//!   "modes": []}` as for the bicycle (the weave and capsize labels are the bicycle's; the
//!   rider's modes are not labelled).
//! - `window`: the speeds of a scan of `[0, 20]` m/s where all six have negative real parts,
//!   each edge bisected to $10^{-10}$ m/s; with Browser + Jason's passive torso
//!   ($k_9 = c_9 = 0$) there is none, and the output says why (the torso's real eigenvalue).
//! - `statespace`: $A$ ($12 \times 12$, state `q1 q2 q3 q4 q6 q7 q8 q9 u4 u6 u7 u9`) and $B$
//!   ($12 \times 3$, inputs `T4 T7 T9`), JSON `{"speed", "state", "inputs", "A", "B"}`.

use carvallo::whipple::lean_rider::{LeanRider, INPUT_NAMES, STATE_NAMES};
use serde_json::{json, Value};

/// The speeds `window` scans (m/s) and its number of steps.
pub const SCAN: (f64, f64, usize) = (0.0, 20.0, 400);

fn header(model: &str, rider: &LeanRider) -> String {
    format!(
        "model {model} (Moore's leaning rider, 12 states; upright pitch {} rad)\n",
        rider.upright_pitch()
    )
}

/// `carvallo eig` on the leaning rider.
pub fn eig(
    model: &str,
    rider: &LeanRider,
    speeds: &[f64],
    as_json: bool,
) -> Result<String, String> {
    let mut values = Vec::new();
    let mut s = header(model, rider);
    for &v in speeds {
        let ev = rider.eigenvalues(v);
        let list: Vec<Value> = ev.iter().map(|e| json!({ "re": e.re, "im": e.im })).collect();
        values.push(json!({
            "model": model,
            "rider": Value::Null,
            "speed": v,
            "eigenvalues": list,
            "modes": [],
        }));
        s.push_str(&format!("eigenvalues of roll, steer and lean at {v} m/s:\n"));
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

/// `carvallo window` on the leaning rider.
pub fn window(model: &str, rider: &LeanRider, as_json: bool) -> Result<String, String> {
    let (lo, hi, steps) = SCAN;
    let stable = rider.stable_speeds(lo, hi, steps);
    // Why nothing is stable: the largest real part over the scan, where it is least.
    let least = (0..=steps)
        .map(|k| {
            let v = lo + (hi - lo) * k as f64 / steps as f64;
            (v, rider.eigenvalues(v)[0])
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
        });
        return serde_json::to_string_pretty(&v).map_err(|e| e.to_string());
    }
    let mut s = header(model, rider);
    if stable.is_empty() {
        s.push_str(&format!(
            "no stable speed from {lo} to {hi} m/s: the least growing mode still grows at \
             {} {:+}i 1/s ({} m/s){}\n",
            least.1.re,
            least.1.im,
            least.0,
            if least.1.im == 0.0 {
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
