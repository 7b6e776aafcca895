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
//! Unknown or missing arguments and an unreadable or invalid parameter file are usage errors:
//! a message naming the value, exit code 2.

use carvallo::bicycle_straight::{
    km_per_hour, memoir_quartic_120, window, Constants, Equations, Window,
};
use carvallo::whipple::Whipple;

use crate::args::DataOptions;
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
    /// `carvallo-formulas`, `carvallo-memoir`, `carvallo-quartic`
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: DataOptions,
    /// Print JSON `{model, weave_speed, capsize_speed, stable}` instead of text
    #[arg(long)]
    pub json: bool,
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
    let Args { model, data, json } = cmd;
    if CARVALLO_MODELS.contains(&model.as_str()) {
        if data.any() {
            return Err(format!("`--rider` and `--strict` read a bicycle file, not `{model}`"));
        }
        return carvallo_window(model).and_then(|w| render_carvallo(model, &w, *json));
    }
    let w = Whipple::new(crate::args::bicycle(model, data)?).stability_window();
    let stable: Vec<Value> =
        w.stable.iter().map(|(a, b)| json!([finite(*a), finite(*b)])).collect();
    let opt = |x: Option<f64>| x.map_or(Value::Null, finite);
    if *json {
        let v = json!({
            "model": model,
            "weave_speed": opt(w.weave_speed),
            "capsize_speed": opt(w.capsize_speed),
            "stable": stable,
        });
        Ok(serde_json::to_string_pretty(&v).map_err(|e| e.to_string())?)
    } else {
        let show = |x: Option<f64>| x.map_or("none".to_string(), |v| format!("{v} m/s"));
        let mut s = format!(
            "model {model}\nweave speed: {}\ncapsize speed: {}\n",
            show(w.weave_speed),
            show(w.capsize_speed)
        );
        for (a, b) in &w.stable {
            s.push_str(&format!("stable from {a} to {b} m/s\n"));
        }
        Ok(s)
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
            Ok(Args { model: "benchmark".into(), data: DataOptions::default(), json: true })
        );
        let e = parse::<Args>(&["window", "--speed", "3"]).unwrap_err();
        assert!(e.starts_with("error: unexpected argument '--speed'"), "{e}");
        let e = parse::<Args>(&["window"]).unwrap_err();
        assert!(e.contains("--model <MODEL>"), "{e}");
        let e = main(&["window", "--model", "/nonexistent/bike.toml"]).unwrap_err();
        assert!(e.starts_with("cannot read model file `/nonexistent/bike.toml`"), "{e}");
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
