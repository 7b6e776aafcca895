//! `carvallo window --model MODEL [--json]`: the stable speed range of a bicycle.
//!
//! * `--model benchmark|FILE.toml`: the linearised Carvallo–Whipple bicycle; the weave and
//!   capsize speeds and the stable speed intervals, as JSON
//!   `{ "model", "weave_speed", "capsize_speed", "stable": [[from, to], ...] }` (m/s; a speed
//!   that does not exist and an interval stable for every larger speed print as `null`). A
//!   parameter file has the format of the benchmark anchors file (a `[parameters]` table) or
//!   BicycleParameters' benchmark text format (`name = value+/-sigma`, one per line).
//! * `--model carvallo-memoir|carvallo-formulas|carvallo|carvallo-quartic`: Carvallo's bicycle
//!   without hands in straight running (memoir n° 117–121), module
//!   [`carvallo::bicycle_straight`]:
//!   * `carvallo-memoir`: the quartic built from the coefficients printed in n° 118;
//!   * `carvallo-quartic`: the normalised quartic as printed in n° 120;
//!   * `carvallo-formulas`: Carvallo's closed forms of n° 117 at his constants, unrounded;
//!   * `carvallo`: the exact linearisation of his model (constants of n° 117) through the
//!     general Carvallo–Whipple bicycle.
//!
//!   Speeds are forward speeds $v = Rs$ in m/s ($R = 0.38$ m, n° 117); the JSON adds the spin
//!   squared `s2` (the memoir's variable) and `km_h` of both limits.
//!
//! * `--gain NAME=VALUE ...` or `--gain-table FILE.csv` (with `--model benchmark|FILE`): the
//!   closed-loop stable speed range of the state feedback $u = -Kx$
//!   ([`carvallo::whipple::feedback`]), by the Hurwitz route on the generated closed-loop
//!   polynomial, in the speeds `--vmin` (default 0) to `--vmax` (default: every speed for
//!   constant gains, the table's speeds for a table); JSON
//!   `{ "model", "gains" | "gain_table", "from", "to", "stable": [[from, to], ...],
//!   "lowest_stable_speed" }` (`to` and an interval's end are `null` for every speed above).
//!   The gains and the table are described in [`crate::gains`].
//! * `--assist-down-to V`: the smallest balance-assist gain c (up to 1000 N m s/rad) that
//!   makes V stable and the window there (`"status": "assisted"`); when there is none, a
//!   physical outcome and not an error: the line `balance assist: no balance-assist gain ...`
//!   (`"status": "no assist gain"` with `"reason"`), exit code 0.
//!
//! Unknown or missing arguments and an unreadable or invalid parameter file are usage errors:
//! a message naming the value, exit code 2.

use carvallo::bicycle_straight::{
    km_per_hour, memoir_quartic_120, window, Constants, Equations, Window,
};
use carvallo::whipple::Whipple;

use crate::args::DataOptions;
use crate::gains::GainValue;
use serde_json::{json, Value};

/// The Carvallo models (memoir n° 117–121) this command answers besides the benchmark bicycle.
pub const CARVALLO_MODELS: [&str; 4] =
    ["carvallo-memoir", "carvallo-quartic", "carvallo-formulas", "carvallo"];

/// `carvallo window`: the stable speed range of the linearised Carvallo–Whipple bicycle, or of
/// Carvallo's bicycle without hands (memoir n° 117–121).
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: `benchmark`, a parameter file (the anchors' TOML or BicycleParameters'
    /// `name = value+/-sigma` text), or one of Carvallo's models `carvallo`,
    /// `carvallo-formulas`, `carvallo-memoir`, `carvallo-quartic`; or Moore's leaning rider:
    /// `lean-rider` (Browser + Jason) or a file in Moore's names (its stable speeds in a scan of
    /// 0 to 20 m/s)
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: DataOptions,
    /// Print JSON `{model, weave_speed, capsize_speed, stable}` instead of text
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub feedback: FeedbackOptions,
}

/// The state feedback of a closed-loop window.
#[derive(Clone, Debug, Default, PartialEq, clap::Args)]
pub struct FeedbackOptions {
    /// A gain of the state feedback u = -K x, NAME = k_{roll|steer}_{roll|steer|roll_rate|steer_rate}
    /// (roll or steer torque from roll, steer or their rates; the others are zero): the
    /// closed-loop stable speed range; for the leaning rider also the lean torque and the
    /// torso's lean, k_{roll|steer|lean}_{roll|steer|lean|roll_rate|steer_rate|lean_rate}
    #[arg(long, value_name = "NAME=VALUE", value_parser = crate::gains::parse_gain, allow_hyphen_values = true)]
    pub gain: Vec<GainValue>,
    /// Gains as functions of speed: a CSV file with the header `speed,k_...` and one row per
    /// speed, linearly interpolated
    #[arg(long, value_name = "FILE.csv", conflicts_with = "gain")]
    pub gain_table: Option<String>,
    /// The lowest speed of a closed-loop window (m/s) [default: 0, or the table's first speed]
    #[arg(long, value_name = "V", value_parser = crate::gains::speed)]
    pub vmin: Option<f64>,
    /// The highest speed of a closed-loop window (m/s) [default: every speed, or the table's
    /// last speed]
    #[arg(long, value_name = "V", value_parser = crate::gains::speed)]
    pub vmax: Option<f64>,
    /// The smallest balance-assist gain c (steer torque c times the roll rate into the fall,
    /// k_steer_roll_rate = -c) at which the speed V is stable, and the closed-loop window there
    #[arg(long, value_name = "V", value_parser = crate::gains::speed, conflicts_with_all = ["gain", "gain_table"])]
    pub assist_down_to: Option<f64>,
}

/// The largest balance-assist gain `--assist-down-to` looks at [N m s/rad].
pub const ASSIST_MAX: f64 = 1000.0;

impl FeedbackOptions {
    /// Whether any is given.
    pub fn any(&self) -> bool {
        !self.gain.is_empty()
            || self.gain_table.is_some()
            || self.vmin.is_some()
            || self.vmax.is_some()
            || self.assist_down_to.is_some()
    }
}

/// A JSON number, `null` for an infinite speed.
fn finite(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

/// Runs `carvallo window`: the text to print, or an error naming the bad value.
pub fn run(cmd: &Args) -> Result<String, String> {
    let Args { model, data, json, feedback } = cmd;
    if CARVALLO_MODELS.contains(&model.as_str()) {
        if data.any() {
            return Err(format!("`--rider` and `--strict` read a bicycle file, not `{model}`"));
        }
        if feedback.any() {
            return Err(format!(
                "the closed loop (--gain, --gain-table, --vmin, --vmax) is for the benchmark \
                 bicycle or a bicycle file, not `{model}`"
            ));
        }
        return carvallo_window(model).and_then(|w| render_carvallo(model, &w, *json));
    }
    if let Some(rider) = crate::args::lean_rider(model, data)? {
        if feedback.gain_table.is_some() || feedback.assist_down_to.is_some() {
            return Err(format!(
                "--gain-table and --assist-down-to are for the bicycle, not yet for the leaning \
                 rider `{model}`"
            ));
        }
        let k = crate::gains::lean_gains_of(&feedback.gain)?;
        let scan = (feedback.vmin.unwrap_or(0.0), feedback.vmax.unwrap_or(20.0));
        if scan.1 <= scan.0 {
            return Err(format!("invalid --vmax {}: must exceed --vmin {}", scan.1, scan.0));
        }
        return super::lean_rider::window(model, &rider, &k, scan, *json);
    }
    if feedback.any() {
        return closed_loop(model, data, feedback, *json);
    }
    let w = Whipple::new(crate::args::bicycle(model, data)?).stability_window();
    let stable: Vec<Value> =
        w.stable.iter().map(|(a, b)| json!([finite(*a), finite(*b)])).collect();
    let opt = |x: Option<f64>| x.map_or(Value::Null, finite);
    if *json {
        let v = json!({
            "model": model,
            "rider": data.rider,
            "weave_speed": opt(w.weave_speed),
            "capsize_speed": opt(w.capsize_speed),
            "stable": stable,
        });
        Ok(serde_json::to_string_pretty(&v).map_err(|e| e.to_string())?)
    } else {
        let show = |x: Option<f64>| x.map_or("none".to_string(), |v| format!("{v} m/s"));
        let mut s = format!(
            "model {}\nweave speed: {}\ncapsize speed: {}\n",
            data.label(model),
            show(w.weave_speed),
            show(w.capsize_speed)
        );
        for (a, b) in &w.stable {
            s.push_str(&format!("stable from {a} to {b} m/s\n"));
        }
        Ok(s)
    }
}

/// The outcome of `--assist-down-to` when no balance-assist gain up to [`ASSIST_MAX`] makes
/// `target` stable: the status `no assist gain` and why (exit 0).
fn no_assist(model: &str, target: f64, as_json: bool) -> Result<String, String> {
    let reason =
        format!("no balance-assist gain c up to {ASSIST_MAX} N m s/rad makes {target} m/s stable");
    if as_json {
        let v = json!({
            "model": model,
            "assist_down_to": target,
            "assist_gain": Value::Null,
            "status": "no assist gain",
            "reason": reason,
        });
        return serde_json::to_string_pretty(&v).map_err(|e| e.to_string());
    }
    Ok(format!(
        "model {model}
balance assist: {reason}
"
    ))
}

/// The closed-loop window of `window --gain` or `--gain-table`.
fn closed_loop(
    model: &str,
    data: &DataOptions,
    fb: &FeedbackOptions,
    as_json: bool,
) -> Result<String, String> {
    if fb.gain.is_empty() && fb.gain_table.is_none() && fb.assist_down_to.is_none() {
        return Err(
            "--vmin and --vmax bound a closed-loop window: give --gain or --gain-table".into()
        );
    }
    let table = fb.gain_table.as_deref().map(crate::gains::read_gain_table).transpose()?;
    crate::gains::bicycle_only(&fb.gain)?;
    let bike = Whipple::new(crate::args::bicycle(model, data)?);
    let mut gains = crate::gains::gains_of(&fb.gain);
    let assist = match fb.assist_down_to {
        Some(target) => {
            // No gain is a physical outcome, not an error: the status and why, exit 0.
            let Some(c) = bike.balance_assist_gain(target, ASSIST_MAX) else {
                return no_assist(model, target, as_json);
            };
            gains = carvallo::whipple::feedback::Gains::balance_assist(c);
            Some((target, c))
        }
        None => None,
    };
    let w = match &table {
        Some(t) => {
            let span = t.span();
            bike.closed_loop_window_table(t, fb.vmin.unwrap_or(span.0), fb.vmax.unwrap_or(span.1))
        }
        None => bike.closed_loop_window(
            &gains,
            fb.vmin.unwrap_or(0.0),
            fb.vmax.unwrap_or(f64::INFINITY),
        ),
    }
    .map_err(|e| match &fb.gain_table {
        Some(path) => {
            e.to_string().replacen("the gain table", &format!("the gain table `{path}`"), 1)
        }
        None => e.to_string(),
    })?;
    let speed = |x: f64| if x.is_finite() { json!(x) } else { Value::Null };
    if as_json {
        let mut v = json!({ "model": model });
        match &fb.gain_table {
            Some(path) => v["gain_table"] = json!(path),
            None => v["gains"] = crate::gains::gains_json(&gains),
        }
        if let Some((target, c)) = assist {
            v["assist_down_to"] = json!(target);
            v["assist_gain"] = json!(c);
            v["status"] = json!("assisted");
        }
        v["from"] = json!(w.from);
        v["to"] = speed(w.to);
        v["stable"] = crate::gains::stable_json(&w);
        v["lowest_stable_speed"] = w.lowest_stable_speed().map_or(Value::Null, speed);
        serde_json::to_string_pretty(&v).map_err(|e| e.to_string())
    } else {
        let mut what = match &fb.gain_table {
            Some(path) => format!("gain table {path}"),
            None => format!("gains {}", crate::gains::gains_text(&gains)),
        };
        if let Some((target, c)) = assist {
            what = format!(
                "balance assist: the smallest gain c making {target} m/s stable is {c} N m s/rad\n{what}"
            );
        }
        Ok(format!("model {model}\n{what}\n{}", crate::gains::window_text(&w)))
    }
}

/// The window of the Carvallo model `model` (one of [`CARVALLO_MODELS`]).
fn carvallo_window(model: &str) -> Result<Window, String> {
    let k = Constants::MEMOIR;
    let err = |e: carvallo::ParameterError| e.to_string();
    Ok(match model {
        "carvallo-memoir" => {
            let e = Equations::memoir_118();
            window(&|s| e.quartic(s))
        }
        "carvallo-quartic" => window(&memoir_quartic_120),
        "carvallo-formulas" => {
            let e = Equations::from_formulas(&k).map_err(err)?;
            window(&|s| e.quartic(s))
        }
        _ => {
            let e = Equations::via_whipple(&k).map_err(err)?;
            window(&|s| e.quartic(s))
        }
    })
}

fn render_carvallo(model: &str, w: &Window, as_json: bool) -> Result<String, String> {
    let r = Constants::MEMOIR.r;
    let v = |s: Option<f64>| s.map_or(Value::Null, |s| json!(s * r));
    let s2 = |s: Option<f64>| s.map_or(Value::Null, |s| json!(s * s));
    let kmh = |s: Option<f64>| s.map_or(Value::Null, |s| json!(km_per_hour(s, r)));
    let stable: Vec<Value> = w.stable_s.iter().map(|(a, b)| json!([a * r, b * r])).collect();
    if as_json {
        let out = json!({
            "model": model,
            "weave_speed": v(w.weave_s),
            "capsize_speed": v(w.capsize_s),
            "stable": stable,
            "s2": { "weave": s2(w.weave_s), "capsize": s2(w.capsize_s) },
            "km_h": { "weave": kmh(w.weave_s), "capsize": kmh(w.capsize_s) },
        });
        serde_json::to_string_pretty(&out).map_err(|e| e.to_string())
    } else {
        let show = |s: Option<f64>| {
            s.map_or("none".to_string(), |s| {
                format!("{} m/s (s^2 = {}, {} km/h)", s * r, s * s, km_per_hour(s, r))
            })
        };
        let mut text = format!(
            "model {model}\nweave speed: {}\ncapsize speed: {}\n",
            show(w.weave_s),
            show(w.capsize_s)
        );
        for (a, b) in &w.stable_s {
            text.push_str(&format!("stable from {} to {} m/s\n", a * r, b * r));
        }
        Ok(text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    fn main(words: &[&str]) -> Result<String, String> {
        run(&parse::<Args>(words)?)
    }

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse::<Args>(&["window", "--model", "benchmark", "--json"]),
            Ok(Args {
                model: "benchmark".into(),
                data: DataOptions::default(),
                json: true,
                feedback: FeedbackOptions::default()
            })
        );
        let e = parse::<Args>(&["window", "--speed", "3"]).unwrap_err();
        assert!(e.starts_with("error: unexpected argument '--speed'"), "{e}");
        let e = parse::<Args>(&["window"]).unwrap_err();
        assert!(e.contains("--model <MODEL>"), "{e}");
        let e = main(&["window", "--model", "/nonexistent/bike.toml"]).unwrap_err();
        assert!(e.starts_with("cannot read model file `/nonexistent/bike.toml`"), "{e}");
    }

    #[test]
    fn a_gain_gives_the_closed_loop_window_checked_by_eigenvalues() {
        let out =
            main(&["window", "--model", "benchmark", "--gain", "k_steer_roll_rate=-10", "--json"])
                .expect("ok");
        let v: Value = serde_json::from_str(&out).expect("json");
        assert_eq!(v["gains"]["k_steer_roll_rate"], -10.0);
        assert_eq!(v["to"], Value::Null);
        let lo = v["lowest_stable_speed"].as_f64().expect("stable somewhere");
        let hi = v["stable"][0][1].as_f64().expect("bounded");
        // The open-loop capsize speed stays (the roll-rate feedback does not touch a0); the
        // lower edge moves down from the weave speed 4.29 m/s; the eigenvalues cross there.
        assert!((hi - 6.024262015388).abs() < 1e-9 && lo < 4.0, "{out}");
        let bike = Whipple::new(carvallo::whipple::WhippleParams::benchmark());
        let k = carvallo::whipple::feedback::Gains::balance_assist(10.0);
        assert!(bike.closed_loop_eigenvalues(lo + 1e-6, &k).iter().all(|e| e.re < 0.0));
        assert!(bike.closed_loop_eigenvalues(lo - 1e-6, &k).iter().any(|e| e.re > 0.0));
        let text = main(&["window", "--model", "benchmark", "--gain", "k_steer_roll_rate=-10"])
            .expect("ok");
        assert!(text.starts_with("model benchmark\ngains k_steer_roll_rate = -10\nspeeds from 0 m/s to any speed\nclosed-loop stable from "), "{text}");
        let e =
            parse::<Args>(&["window", "--model", "benchmark", "--gain", "k_yaw=1"]).unwrap_err();
        assert!(e.contains("unknown gain `k_yaw`: expected one of k_roll_roll, "), "{e}");
        let e = main(&["window", "--model", "carvallo", "--gain", "k_roll_roll=1"]).unwrap_err();
        assert!(e.contains("not `carvallo`"), "{e}");
        // The assist for 2 m/s: the lower edge of its window is 2 m/s.
        let out = main(&["window", "--model", "benchmark", "--assist-down-to", "2", "--json"])
            .expect("ok");
        let v: Value = serde_json::from_str(&out).expect("json");
        let c = v["assist_gain"].as_f64().expect("a gain");
        assert_eq!(v["gains"]["k_steer_roll_rate"].as_f64(), Some(-c));
        assert!((v["lowest_stable_speed"].as_f64().unwrap() - 2.0).abs() < 1e-9, "{out}");
        assert_eq!(v["status"], "assisted");
        // No gain up to the largest one looked at: a physical outcome, not an error.
        let text = main(&["window", "--model", "benchmark", "--assist-down-to", "0.1"]).unwrap();
        assert_eq!(
            text,
            "model benchmark\nbalance assist: no balance-assist gain c up to 1000 N m s/rad makes 0.1 m/s stable\n"
        );
        let out = main(&["window", "--model", "benchmark", "--assist-down-to", "0.1", "--json"])
            .expect("ok");
        let v: Value = serde_json::from_str(&out).expect("json");
        assert_eq!(v["status"], "no assist gain");
        assert!(v["assist_gain"].is_null());
        assert_eq!(v["assist_down_to"].as_f64(), Some(0.1));
        let e = main(&["window", "--model", "benchmark", "--vmax", "3"]).unwrap_err();
        assert!(e.contains("give --gain or --gain-table"), "{e}");
        let e = main(&[
            "window",
            "--model",
            "benchmark",
            "--gain",
            "k_roll_roll=1",
            "--vmin",
            "4",
            "--vmax",
            "3",
        ])
        .unwrap_err();
        assert_eq!(e, "invalid speed range 4 to 3: expected 0 <= from <= to");
    }

    /// The largest real part of the closed loop $A - BK$ at speed `v` with the steer torque
    /// $T_\delta = c\,\dot\varphi$ (`k_steer_roll_rate = -c`), built from the published
    /// benchmark matrices (Meijaard et al. 2007, eq. A.2-A.4 and section 5: M, C1, K0, K2,
    /// g = 9.81), not from the generated code: $\ddot q = -M^{-1}((gK_0 + v^2K_2) q + vC_1
    /// \dot q) + M^{-1} T$, eigenvalues by nalgebra.
    fn published_closed_loop_max_re(v: f64, c: f64) -> f64 {
        use nalgebra::{Matrix2, Matrix4};
        let m = Matrix2::new(80.81722, 2.31941332208709, 2.31941332208709, 0.29784188199686);
        let c1 = Matrix2::new(0.0, 33.86641391492494, -0.85035641456978, 1.68540397397560);
        let k0 = Matrix2::new(-80.95, -2.59951685249872, -2.59951685249872, -0.80329488458618);
        let k2 = Matrix2::new(0.0, 76.59734589573222, 0.0, 2.65431523794604);
        let mi: Matrix2<f64> = m.try_inverse().expect("M invertible");
        let stiff: Matrix2<f64> = -mi * (k0 * 9.81 + k2 * (v * v));
        let damp: Matrix2<f64> = -mi * (c1 * v);
        // The steer torque c roll-rate enters through the second column of M^-1.
        let a = Matrix4::from_fn(|r, col| match (r, col) {
            (0, 2) | (1, 3) => 1.0,
            (2 | 3, 0 | 1) => stiff[(r - 2, col)],
            (2 | 3, 2 | 3) => {
                damp[(r - 2, col - 2)] + if col == 2 { mi[(r - 2, 1)] * c } else { 0.0 }
            }
            _ => 0.0,
        });
        a.complex_eigenvalues().iter().map(|z| z.re).fold(f64::MIN, f64::max)
    }

    #[test]
    fn a_gain_table_gives_the_window_of_speed_dependent_gains() {
        let dir = std::env::temp_dir().join(format!("carvallo-window-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let path = dir.join("gains.csv");
        // A balance assist that fades with speed: c = 40 N m s/rad at rest, 10 at 4 m/s, 0 at
        // 10 m/s, linear between the rows (the gains written by hand below, not by GainTable).
        std::fs::write(&path, "speed,k_steer_roll_rate\n0,-40\n4,-10\n10,0\n").expect("write");
        let c_at = |v: f64| if v <= 4.0 { 40.0 - 7.5 * v } else { 10.0 - (v - 4.0) * 10.0 / 6.0 };
        let file = path.to_string_lossy().into_owned();
        let out =
            main(&["window", "--model", "benchmark", "--gain-table", &file, "--json"]).expect("ok");
        let v: Value = serde_json::from_str(&out).expect("json");
        assert_eq!((v["from"].as_f64(), v["to"].as_f64()), (Some(0.0), Some(10.0)));
        let stable: Vec<(f64, f64)> = v["stable"]
            .as_array()
            .expect("intervals")
            .iter()
            .map(|i| (i[0].as_f64().unwrap(), i[1].as_f64().unwrap()))
            .collect();
        // Budget: the edges are bisected to about 1e-12 m/s; 1e-6 relative off an edge moves
        // the crossing root's real part by 1e-7 or more, far above the eigenvalues' 1e-14.
        let at = |s: f64| published_closed_loop_max_re(s, c_at(s));
        let d = 1e-6;
        assert!(!stable.is_empty(), "{out}");
        for &(lo, hi) in &stable {
            assert!(at(0.5 * (lo + hi)) < 0.0, "unstable inside ({lo}, {hi})");
            if lo > 0.0 {
                assert!(at(lo * (1.0 - d)) > 0.0 && at(lo * (1.0 + d)) < 0.0, "edge {lo}: {out}");
            }
            if hi < 10.0 {
                assert!(at(hi * (1.0 - d)) < 0.0 && at(hi * (1.0 + d)) > 0.0, "edge {hi}: {out}");
            }
        }
        // The gains do depend on speed: the constant table of the rest value c = 40 gives
        // another window.
        std::fs::write(&path, "speed,k_steer_roll_rate\n0,-40\n10,-40\n").expect("write");
        let constant =
            main(&["window", "--model", "benchmark", "--gain-table", &file, "--json"]).expect("ok");
        let w: Value = serde_json::from_str(&constant).expect("json");
        assert_ne!(w["stable"], v["stable"], "{constant}");
        let e = main(&["window", "--model", "benchmark", "--gain-table", &file, "--vmax", "12"])
            .unwrap_err();
        assert_eq!(
            e,
            format!(
                "the gain table `{file}` covers the speeds 0 to 10 m/s, not the range asked 0 to \
                 12 m/s"
            )
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_carvallo_model_has_its_window_in_speed_and_spin() {
        let out = main(&["window", "--model", "carvallo-memoir", "--json"]).expect("ok");
        let v: Value = serde_json::from_str(&out).expect("json");
        assert_eq!(v["model"], "carvallo-memoir");
        let (weave, capsize) =
            (v["weave_speed"].as_f64().unwrap(), v["capsize_speed"].as_f64().unwrap());
        assert!(weave > 0.0 && weave < capsize, "{out}");
        assert_eq!(v["stable"][0][0].as_f64(), Some(weave));
        assert!(v["s2"]["weave"].as_f64().is_some(), "{out}");
    }
}
