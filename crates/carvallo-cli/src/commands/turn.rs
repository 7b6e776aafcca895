//! `carvallo turn`: steady turns with the handlebar held (memoir ch. IV, n° 79–106).
//!
//! `--model carvallo --gamma DEG --speed V [--json]`: a steady turn of Carvallo's bicycle
//! (memoir n° 99–105, module [`carvallo::bicycle_turn`], the constants of n° 117) and its
//! characteristic equation (C) of n° 101 with the rolling speed held: the lean θ₀, the pitch,
//! the turning rate n, the hands' torque, the three coefficients $df/dp'$, $df/dp$,
//! $df/d\theta$ and the two roots; the free-wheeling cubic's roots beside them. γ is in degrees
//! (Carvallo's sign: the bicycle leans to −γ), V is the speed $Rs$ in m/s.
//!
//! `--model benchmark|FILE --speed V --lean RAD [--steer RAD] [--json]`: every steady turn of
//! the nonlinear Carvallo–Whipple bicycle at the rear contact's speed V and the lean RAD
//! ([`carvallo::whipple::steady_turn`]): steer, pitch, yaw rate, radius of the rear contact's
//! circle, the steer torque that holds it, the normal and lateral forces and the friction each
//! contact demands, and the stability with the steer torque held (the four eigenvalues of the
//! linearisation, the family's zero set aside). `--steer RAD` keeps the turn whose steer is
//! nearest. The JSON is `{model, rider, speed, lean, status, turns: [...]}`, `status` `turns`
//! or `no steady turn`.
//!
//! `--model lean-rider|FILE` (Moore's leaning rider) gives the same with the torso's lean on its
//! joint as one more unknown ([`carvallo::whipple::steady_turn::lean_rider`]; no contact
//! forces), the lean being the roll $q_4$.
//!
//! `--model benchmark|FILE --hands-free [--json]`: the hands-free turns (no steer torque) as
//! families in speed and lean from their branch points on upright running, straight ahead
//! (at the capsize speed) and with the handlebar reversed, and the families meeting neither
//! (`isolated`, found by a scan of the turns at one lean; their `branch_speed` is null and
//! `line_steer` the steer of the seed they were followed through), with their folds and
//! stable points ([`carvallo::whipple::steady_turn::hands_free`]); the JSON has every point.
//!
//! Unknown, repeated or missing arguments, non-finite numbers, an out-of-range γ or lean, a
//! negative speed (and a zero one for the nonlinear models), and a turn of Carvallo's bicycle
//! that does not exist are errors naming the value, exit code 2. A speed and lean that no steer
//! holds is a result (exit 0); a solver failure is exit 1.

use carvallo::bicycle_straight::Constants;
use carvallo::bicycle_turn::{Hold, LockedSteer, MAX_GAMMA};
use carvallo::whipple::lean_rider::LeanRider;
use carvallo::whipple::steady_turn::hands_free::{
    self, CurvePoint, End, Family, HandsFree, Special,
};
use carvallo::whipple::steady_turn::lean_rider::RiderTurnSolver;
use carvallo::whipple::steady_turn::{SteadyTurn, TurnError, TurnSolver, Turns};
use serde_json::{json, Value};

use crate::args::{finite, DataOptions};

/// `carvallo turn`: steady turns with the handlebar held.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: `carvallo` (Carvallo's, the constants of n° 117, with --gamma); or, with
    /// --lean, the nonlinear Carvallo–Whipple bicycle `benchmark` or a parameter file (the
    /// anchors' TOML or BicycleParameters' text), or Moore's leaning rider `lean-rider` (Browser
    /// + Jason) or a file in Moore's names
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: DataOptions,
    /// With --model carvallo: the handlebar angle γ in degrees (Carvallo's sign: the bicycle
    /// leans to −γ)
    #[arg(long = "gamma", value_name = "DEG", value_parser = gamma, allow_hyphen_values = true)]
    pub gamma_deg: Option<f64>,
    /// The rear contact's speed in m/s (Carvallo's rolling speed Rs)
    #[arg(long, value_name = "V", value_parser = crate::args::SPEED.parser(), allow_hyphen_values = true,
          required_unless_present = "hands_free")]
    pub speed: Option<f64>,
    /// With a nonlinear model: the lean φ (rad), positive to the right, strictly within ±π/2
    #[arg(long, value_name = "RAD", value_parser = finite, allow_hyphen_values = true)]
    pub lean: Option<f64>,
    /// With a nonlinear model: keep only the turn whose steer is nearest RAD
    #[arg(long, value_name = "RAD", value_parser = finite, allow_hyphen_values = true)]
    pub steer: Option<f64>,
    /// With a bicycle (benchmark or a parameter file): the hands-free turns (no steer torque) as
    /// families in speed and lean, followed from their branch points on upright running
    /// (straight and with the handlebar reversed), with folds and stable sections
    #[arg(long, conflicts_with_all = ["speed", "lean", "steer", "gamma_deg"])]
    pub hands_free: bool,
    /// Print JSON instead of text
    #[arg(long)]
    pub json: bool,
}

/// The handlebar angle in degrees: finite and strictly within ±[`MAX_GAMMA`].
fn gamma(v: &str) -> Result<f64, String> {
    let x = finite(v)?;
    let max = MAX_GAMMA.to_degrees();
    if x.abs() >= max {
        return Err(format!("must lie strictly between -{max:.1} and {max:.1} degrees"));
    }
    Ok(x)
}

/// The start of the message of a solver failure: printed with exit code 1 (main.rs).
pub const SOLVER_FAILURE: &str = "the steady turn solver failed";

/// Runs `carvallo turn`: the text to print, or an error naming the bad value.
pub fn run(c: &Args) -> Result<String, String> {
    if c.hands_free {
        return hands_free(c);
    }
    // clap requires the speed unless --hands-free.
    let speed = c.speed.ok_or("--speed <V> is required".to_string())?;
    if c.model == "carvallo" {
        if c.lean.is_some() || c.steer.is_some() || c.data.any() {
            return Err(
                "--model carvallo takes --gamma and --speed; --lean, --steer, --rider and \
                        --strict are for the nonlinear models (benchmark or a parameter file)"
                    .into(),
            );
        }
        let gamma = c
            .gamma_deg
            .ok_or("--model carvallo needs --gamma <DEG>, the handlebar angle".to_string())?;
        return carvallo_turn(gamma, speed, c.json);
    }
    if c.gamma_deg.is_some() {
        return Err(format!(
            "--gamma is the handlebar angle of --model carvallo; `{}` takes --lean <RAD>",
            c.model
        ));
    }
    let lean = c.lean.ok_or(format!("--model {} needs --lean <RAD>", c.model))?;
    if let Some(rider) = crate::args::lean_rider(&c.model, &c.data)? {
        return rider_turns(c, &rider, speed, lean);
    }
    let params = crate::args::bicycle(&c.model, &c.data)?;
    let failed = |e: TurnError| match e {
        TurnError::Parameter(p) => p.to_string(),
        e @ TurnError::Solver { .. } => e.to_string(),
    };
    let solver = TurnSolver::new(&params).map_err(failed)?;
    let mut turns = solver.turns(speed, lean).map_err(failed)?;
    if let Some(steer) = c.steer {
        keep_nearest(&mut turns, steer);
    }
    let label = c.data.label(&c.model);
    if c.json {
        let out = json!({
            "model": c.model,
            "rider": c.data.rider,
            "speed": speed,
            "lean": lean,
            "steer": c.steer,
            "status": turns.status(),
            "turns": turns.turns.iter().map(turn_json).collect::<Vec<_>>(),
        });
        return serde_json::to_string_pretty(&out).map_err(|e| e.to_string());
    }
    Ok(turns_text(&label, &turns))
}

/// Keeps the turn whose steer is nearest `steer` (angles compared on the circle).
fn keep_nearest(turns: &mut Turns, steer: f64) {
    if let Some(best) = nearest(&turns.turns, steer, |t| t.steer) {
        turns.turns = vec![best];
    }
}

/// The item whose steer (`of`) is nearest `steer` on the circle.
fn nearest<T: Copy>(items: &[T], steer: f64, of: impl Fn(&T) -> f64) -> Option<T> {
    let gap = |a: f64| {
        let d = (a - steer).rem_euclid(std::f64::consts::TAU);
        d.min(std::f64::consts::TAU - d)
    };
    items.iter().copied().min_by(|a, b| gap(of(a)).total_cmp(&gap(of(b))))
}

/// The steady turns of the leaning rider `rider` ([`carvallo::whipple::steady_turn::lean_rider`]):
/// the torso's lean beside the steer, no contact forces (see the module).
fn rider_turns(c: &Args, rider: &LeanRider, speed: f64, lean: f64) -> Result<String, String> {
    let solver = RiderTurnSolver::new(rider);
    let mut turns = solver.turns(speed, lean).map_err(|e| e.to_string())?;
    if let Some(steer) = c.steer {
        if let Some(best) = nearest(&turns.turns, steer, |t| t.steer) {
            turns.turns = vec![best];
        }
    }
    let ev = |e: &[nalgebra::Complex<f64>]| {
        e.iter().map(|z| json!({ "re": z.re, "im": z.im })).collect::<Vec<_>>()
    };
    if c.json {
        let list: Vec<Value> = turns
            .turns
            .iter()
            .map(|t| {
                json!({
                    "steer": t.steer,
                    "torso_lean": t.torso_lean,
                    "pitch": t.pitch,
                    "yaw_rate": t.yaw_rate,
                    "radius": number(t.radius),
                    "steer_torque": t.steer_torque,
                    "rear_wheel_rate": t.rear_wheel_rate,
                    "stable": t.stability.stable,
                    "eigenvalues": ev(&t.stability.eigenvalues),
                    "family_eigenvalue": ev(&[t.stability.family])[0],
                    "residuals": {
                        "roll_row": t.roll_residual,
                        "lean_row": t.torso_residual,
                        "rear_wheel_row": t.rear_row_residual,
                    },
                })
            })
            .collect();
        let out = json!({
            "model": c.model,
            "rider": Value::Null,
            "speed": speed,
            "lean": lean,
            "steer": c.steer,
            "status": turns.status(),
            "turns": list,
        });
        return serde_json::to_string_pretty(&out).map_err(|e| e.to_string());
    }
    let n = turns.turns.len();
    let mut s = format!(
        "model {} (the leaning rider), speed {} m/s, roll {} rad: {}\n",
        c.model,
        speed,
        lean,
        match n {
            0 => "no steady turn (no steer holds this roll at this speed)".to_string(),
            1 => "1 steady turn".to_string(),
            _ => format!("{n} steady turns"),
        }
    );
    for t in &turns.turns {
        let radius = if t.radius.is_finite() {
            format!("{:.6} m", t.radius)
        } else {
            "infinite (straight)".to_string()
        };
        s.push_str(&format!(
            "steer {:.6} rad: torso lean {:.6} rad, pitch {:.6} rad, yaw rate {:.6} rad/s, \
             radius {radius}, steer torque {:.6} N m\n",
            t.steer,
            t.torso_lean + 0.0,
            t.pitch,
            t.yaw_rate + 0.0,
            t.steer_torque + 0.0
        ));
        let e: Vec<String> =
            t.stability.eigenvalues.iter().map(|e| format!("{:.6} {:+.6}i", e.re, e.im)).collect();
        s.push_str(&format!(
            "  eigenvalues, steer torque held: {}: {}\n",
            e.join(", "),
            if t.stability.stable { "stable" } else { "unstable" }
        ));
    }
    Ok(s)
}

/// A number for JSON: `null` when not finite (the radius of straight running).
fn number(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

fn turn_json(t: &SteadyTurn) -> Value {
    let c = |z: &nalgebra::Complex<f64>| json!({ "re": z.re, "im": z.im });
    let f = &t.forces;
    json!({
        "steer": t.steer,
        "pitch": t.pitch,
        "yaw_rate": t.yaw_rate,
        "radius": number(t.radius),
        "steer_torque": t.steer_torque,
        "rear_wheel_rate": t.rear_wheel_rate,
        "front_wheel_rate": t.front_wheel_rate,
        "normal_force": { "rear": f.rear_normal, "front": f.front_normal },
        "lateral_force": { "rear": f.rear_lateral, "front": f.front_lateral },
        "friction": { "rear": f.rear_friction, "front": f.front_friction },
        "on_ground": f.on_ground(),
        "stable": t.stability.stable,
        "eigenvalues": t.stability.eigenvalues.iter().map(c).collect::<Vec<_>>(),
        "family_eigenvalue": c(&t.stability.family),
        "residuals": {
            "roll_row": t.roll_residual,
            "rear_wheel_row": t.rear_row_residual,
            "momentum_balance": f.balance_residual,
        },
    })
}

fn turns_text(label: &str, turns: &Turns) -> String {
    let n = turns.turns.len();
    let mut s = format!(
        "model {label}, speed {} m/s, lean {} rad: {}\n",
        turns.speed,
        turns.lean,
        match n {
            0 => "no steady turn (no steer holds this lean at this speed)".to_string(),
            1 => "1 steady turn".to_string(),
            _ => format!("{n} steady turns"),
        }
    );
    for t in &turns.turns {
        let f = &t.forces;
        let radius = if t.radius.is_finite() {
            format!("{:.6} m", t.radius)
        } else {
            "infinite (straight)".to_string()
        };
        s.push_str(&format!(
            "steer {:.6} rad: pitch {:.6e} rad, yaw rate {:.6} rad/s, radius {radius}, steer \
             torque {:.6} N m\n",
            t.steer,
            t.pitch,
            t.yaw_rate + 0.0,
            t.steer_torque + 0.0
        ));
        s.push_str(&format!(
            "  normal forces rear {:.3} N, front {:.3} N; lateral rear {:.3} N, front {:.3} N; \
             friction demanded rear {:.4}, front {:.4}{}\n",
            f.rear_normal,
            f.front_normal,
            f.rear_lateral + 0.0,
            f.front_lateral + 0.0,
            f.rear_friction,
            f.front_friction,
            if f.on_ground() { "" } else { " (a wheel would have to be held down)" }
        ));
        let ev: Vec<String> =
            t.stability.eigenvalues.iter().map(|e| format!("{:.6} {:+.6}i", e.re, e.im)).collect();
        s.push_str(&format!(
            "  eigenvalues, steer torque held: {}: {}\n",
            ev.join(", "),
            if t.stability.stable { "stable" } else { "unstable" }
        ));
    }
    s
}

/// `--hands-free`: the families of hands-free turns of a bicycle from the branch points of
/// upright running, straight ahead and with the handlebar reversed
/// ([`carvallo::whipple::steady_turn::hands_free`]).
fn hands_free(c: &Args) -> Result<String, String> {
    if c.model == "carvallo" || crate::args::lean_rider(&c.model, &c.data)?.is_some() {
        return Err(format!(
            "--hands-free takes a bicycle (benchmark or a parameter file), not `{}`",
            c.model
        ));
    }
    let params = crate::args::bicycle(&c.model, &c.data)?;
    let solver = TurnSolver::new(&params).map_err(|e| e.to_string())?;
    let hf = HandsFree::new(&solver);
    let families: Vec<(&str, Family)> = hf
        .families()
        .map_err(|e| e.to_string())?
        .into_iter()
        .map(|f| {
            let name = if f.is_isolated() {
                "meeting no upright line"
            } else if f.line_steer == hands_free::LINES[0] {
                "straight ahead (steer 0)"
            } else {
                "handlebar reversed (steer pi)"
            };
            (name, f)
        })
        .collect();
    let label = c.data.label(&c.model);
    let at = |f: &Family, k: usize| {
        let p = &f.points[k.min(f.points.len() - 1)];
        (p.speed, p.lean, p.steer)
    };
    if c.json {
        let list: Vec<Value> = families
            .iter()
            .map(|(name, f)| {
                let special: Vec<Value> = f
                    .special
                    .iter()
                    .map(|s| {
                        let (kind, k) = match *s {
                            Special::SpeedFold(k) => ("speed fold", k),
                            Special::LeanFold(k) => ("lean fold", k),
                            Special::Branch(k) => ("branch point", k),
                            Special::StabilityChange(k) => ("stability change", k),
                        };
                        let (v, l, d) = at(f, k);
                        json!({ "kind": kind, "index": k, "speed": v, "lean": l, "steer": d })
                    })
                    .collect();
                json!({
                    "line": name,
                    "isolated": f.is_isolated(),
                    "line_steer": f.line_steer,
                    "branch_speed": number(f.branch_speed),
                    "end": format!("{:?}", f.end).to_lowercase(),
                    "special": special,
                    "points": f.points.iter().map(|p| json!({
                        "speed": p.speed, "lean": p.lean, "steer": p.steer, "pitch": p.pitch,
                        "stable": p.stable, "growth": p.growth,
                    })).collect::<Vec<_>>(),
                })
            })
            .collect();
        let out = json!({ "model": c.model, "rider": c.data.rider, "families": list });
        return serde_json::to_string_pretty(&out).map_err(|e| e.to_string());
    }
    let mut s = format!("model {label}, hands-free steady turns (no steer torque)\n");
    if families.is_empty() {
        s.push_str("no family branches from upright running below 20 m/s\n");
    }
    for (name, f) in &families {
        let last = f.points.last().map_or(f.branch_speed, |p| p.speed);
        let from = match f.points.first() {
            Some(p) if f.is_isolated() => format!(
                "a family found by a scan at lean {} rad, from {:.4} m/s, lean {:.4} rad, steer \
                 {:.4} rad",
                hands_free::SCAN_LEAN,
                p.speed,
                p.lean,
                p.steer
            ),
            _ => format!("a family branches at {:.6} m/s", f.branch_speed),
        };
        s.push_str(&format!(
            "{name}: {from}; {} points, followed to {last:.4} m/s ({})\n",
            f.points.len(),
            match f.end {
                End::Speed => "the speed's bound",
                End::Lean => "the fall angle",
                End::Stuck => "a singularity",
                End::Steps => "the steps' bound",
            }
        ));
        for sp in &f.special {
            let (kind, k) = match *sp {
                Special::SpeedFold(k) => ("speed fold", k),
                Special::LeanFold(k) => ("lean fold", k),
                Special::Branch(k) => ("branch point", k),
                Special::StabilityChange(k) => ("stability changes", k),
            };
            let (v, l, d) = at(f, k);
            s.push_str(&format!("  {kind} near {v:.4} m/s, lean {l:.4} rad, steer {d:.4} rad\n"));
        }
        let stable: Vec<&CurvePoint> = f.points.iter().filter(|p| p.stable).collect();
        match (stable.first(), stable.last()) {
            (Some(a), Some(b)) => s.push_str(&format!(
                "  stable points from {:.4} m/s, lean {:.4} rad to {:.4} m/s, lean {:.4} rad\n",
                a.speed, a.lean, b.speed, b.lean
            )),
            _ => s.push_str("  stable nowhere\n"),
        }
    }
    Ok(s)
}

/// The turn of Carvallo's bicycle at the handlebar angle `gamma_deg` (degrees).
fn carvallo_turn(gamma_deg: f64, speed: f64, as_json: bool) -> Result<String, String> {
    let err = |e: carvallo::bicycle_turn::TurnError| e.to_string();
    let bike = LockedSteer::new(Constants::MEMOIR).map_err(|e| e.to_string())?;
    let t = bike.steady_turn(gamma_deg.to_radians(), speed).map_err(err)?;
    let f = bike.fall_equation(&t, Hold::Rolling).map_err(err)?;
    let w = bike.free_wheel(&t).map_err(err)?;
    let roots: Vec<f64> = f.roots.iter().map(|r| r.re).collect();
    let free: Vec<[f64; 2]> = w.roots.iter().map(|r| [r.re, r.im]).collect();
    if as_json {
        let out = json!({
            "model": "carvallo",
            "gamma_deg": gamma_deg,
            "speed": speed,
            "lean": t.lean,
            "pitch": t.pitch,
            "turning_rate": t.yaw_rate,
            "hands_torque": t.hands_torque,
            "dfdpp": f.dfdpp,
            "dfdp": f.dfdp,
            "dfdtheta": f.dfdtheta,
            "dfdtheta_gravity": f.dfdtheta_gravity,
            "roots": roots,
            "free_wheel_roots": free,
        });
        return serde_json::to_string_pretty(&out).map_err(|e| e.to_string());
    }
    // Upright, the lean and the rates are signed zeros: print them as 0.
    let (lean, yaw) = (t.lean + 0.0, t.yaw_rate + 0.0);
    let mut s =
        format!("model carvallo, handlebar held at gamma = {gamma_deg} deg, speed {speed} m/s\n");
    s.push_str(&format!("lean theta0: {lean:.6} rad\n"));
    s.push_str(&format!("pitch: {:.6e} rad\n", t.pitch));
    s.push_str(&format!("turning rate n: {yaw:.6} 1/s\n"));
    s.push_str(&format!("hands' torque: {:.6} N m\n", t.hands_torque));
    s.push_str(&format!(
        "(C) with s held: {:.6} lambda^2 {:+.6} lambda {:+.6} = 0\n",
        f.dfdpp, f.dfdp, f.dfdtheta
    ));
    s.push_str(&format!("roots: {:.6} {:.6} 1/s\n", roots[0], roots[1]));
    let zero = if w.roots[1].norm() < 1e-9 {
        "0 (below 1e-9)".to_string()
    } else {
        format!("{:.6}", w.roots[1].re)
    };
    s.push_str(&format!(
        "free-wheeling roots: {:.6} {zero} {:.6} 1/s\n",
        w.roots[0].re, w.roots[2].re
    ));
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_and_rejects_by_value() {
        let turn = |words: &[&str]| parse::<Args>(&[&["turn"], words].concat());
        let a = turn(&["--model", "carvallo", "--gamma", "5", "--speed", "5.5"]).expect("parses");
        assert_eq!(
            (a.model.as_str(), a.gamma_deg, a.speed, a.lean),
            ("carvallo", Some(5.0), Some(5.5), None)
        );
        let a = turn(&["--model", "benchmark", "--hands-free"]).expect("parses");
        assert!(a.hands_free && a.speed.is_none());
        let e = turn(&["--model", "benchmark", "--hands-free", "--speed", "5"]).unwrap_err();
        assert!(e.contains("'--hands-free' cannot be used with '--speed <V>'"), "{e}");
        let a = turn(&["--model", "benchmark", "--speed", "5", "--lean", "-0.1", "--steer", "0"])
            .expect("parses");
        assert_eq!((a.lean, a.steer, a.gamma_deg), (Some(-0.1), Some(0.0), None));
        let e = turn(&["--model", "carvallo", "--gamma", "x", "--speed", "5"]).unwrap_err();
        assert!(e.contains("invalid value 'x' for '--gamma <DEG>': not a number"), "{e}");
        let e = turn(&["--model", "carvallo", "--gamma", "-89", "--speed", "5"]).unwrap_err();
        assert!(e.contains("invalid value '-89' for '--gamma <DEG>': must lie strictly"), "{e}");
        let e = turn(&["--model", "benchmark", "--speed", "5", "--lean", "NaN"]).unwrap_err();
        assert!(e.contains("invalid value 'NaN' for '--lean <RAD>': must be finite"), "{e}");
        let e = turn(&["--json", "--json"]).unwrap_err();
        assert!(e.contains("'--json' cannot be used multiple times"), "{e}");
    }

    #[test]
    fn each_model_takes_its_own_angle() {
        let run_of = |words: &[&str]| run(&parse::<Args>(&[&["turn"], words].concat()).unwrap());
        let e = run_of(&["--model", "carvallo", "--speed", "5"]).unwrap_err();
        assert!(e.contains("--model carvallo needs --gamma <DEG>"), "{e}");
        let e = run_of(&["--model", "carvallo", "--gamma", "5", "--speed", "5", "--lean", "0.1"])
            .unwrap_err();
        assert!(e.contains("--lean, --steer"), "{e}");
        let e = run_of(&["--model", "benchmark", "--speed", "5"]).unwrap_err();
        assert!(e.contains("--model benchmark needs --lean <RAD>"), "{e}");
        let e = run_of(&["--model", "benchmark", "--speed", "5", "--gamma", "5"]).unwrap_err();
        assert!(e.contains("`benchmark` takes --lean <RAD>"), "{e}");
        let e = run_of(&["--model", "benchmark", "--speed", "0", "--lean", "0.1"]).unwrap_err();
        assert_eq!(e, "invalid speed 0.0: must be positive");
        let e = run_of(&["--model", "benchmark", "--speed", "5", "--lean", "2"]).unwrap_err();
        assert_eq!(e, "invalid lean 2.0: must lie strictly between -pi/2 and pi/2 rad");
    }
}
