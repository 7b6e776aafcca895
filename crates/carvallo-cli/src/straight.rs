//! `carvallo window --model carvallo-memoir|carvallo-formulas|carvallo|carvallo-quartic`: the
//! stable speed range of Carvallo's bicycle without hands in straight running (memoir
//! n° 117–121), module [`carvallo::bicycle_straight`].
//!
//! * `carvallo-memoir`: the quartic built from the coefficients printed in n° 118;
//! * `carvallo-quartic`: the normalised quartic as printed in n° 120;
//! * `carvallo-formulas`: Carvallo's closed forms of n° 117 at his constants, unrounded;
//! * `carvallo`: the exact linearisation of his model (constants of n° 117) through the
//!   general Carvallo–Whipple bicycle.
//!
//! Speeds are forward speeds $v = Rs$ in m/s ($R = 0.38$ m, n° 117); the JSON adds the spin
//! squared `s2` (the memoir's variable) and `km_h` of both limits.

use carvallo::bicycle_straight::{
    km_per_hour, memoir_quartic_120, window, Constants, Equations, Window,
};
use serde_json::{json, Value};

/// The model names this module answers.
pub const MODELS: [&str; 4] =
    ["carvallo-memoir", "carvallo-quartic", "carvallo-formulas", "carvallo"];

fn compute(model: &str) -> Result<Window, String> {
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

/// The `window` output for a Carvallo model, `None` when `model` is not one of [`MODELS`].
pub fn window_output(model: &str, as_json: bool) -> Option<Result<String, String>> {
    if !MODELS.contains(&model) {
        return None;
    }
    Some(compute(model).and_then(|w| render(model, &w, as_json)))
}

fn render(model: &str, w: &Window, as_json: bool) -> Result<String, String> {
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

    #[test]
    fn answers_only_its_models() {
        assert!(window_output("benchmark", true).is_none());
        let out = window_output("carvallo-memoir", true).expect("a carvallo model").expect("ok");
        let v: Value = serde_json::from_str(&out).expect("json");
        assert_eq!(v["model"], "carvallo-memoir");
        let (weave, capsize) =
            (v["weave_speed"].as_f64().unwrap(), v["capsize_speed"].as_f64().unwrap());
        assert!(weave > 0.0 && weave < capsize, "{out}");
        assert_eq!(v["stable"][0][0].as_f64(), Some(weave));
    }
}
