//! `carvallo accel --model benchmark|FILE.toml --basu-mandal|--state`: the accelerations of the
//! nonlinear Carvallo–Whipple bicycle. With `--basu-mandal` it reads `{"q": [9 numbers], "qd":
//! [9 numbers]}` on standard input, in the coordinates of Basu-Mandal, Chatterjee and
//! Papadopoulos (2007: x, y, z, θ, ψ, φ, ψf, βr, βf), and prints `{"qdd": [9 numbers]}`. With
//! `--state` it reads `{"state": [11 numbers]}`, the state of the right-hand side an integrator
//! calls ([`StateRate`]: x, y, yaw, lean, steer, rear and front wheel angles, lean, steer and
//! rear wheel rates, pitch), and prints `{"derivative": [11 numbers], "pitch": p, "speed": v}`
//! (the pitch projected onto the contact constraint, the rear contact's speed): what the peers
//! of `scripts/pydy-c-peer` compare their whole right-hand side with.
//!
//! The parameter file is the anchors TOML format ([`crate::args::toml_model`]). Unknown,
//! repeated or missing arguments and bad JSON are errors naming the value, exit code 2.

use carvallo::whipple_nonlinear::rate::{self, StateRate};
use carvallo::whipple_nonlinear::WhippleNonlinear;
use serde_json::{json, Value};

use crate::args::toml_model;

/// `carvallo accel`: the accelerations of the nonlinear bicycle in Basu-Mandal's coordinates.
#[derive(Clone, Debug, PartialEq, clap::Args)]
#[command(group(clap::ArgGroup::new("coordinates").required(true).args(["basu_mandal", "state"])))]
pub struct Args {
    /// The bicycle: `benchmark` or a parameter file in the anchors' TOML format
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    /// Read and write Basu-Mandal's coordinates: stdin `{"q": [..9], "qd": [..9]}`, stdout
    /// `{"qdd": [..9]}`
    #[arg(long)]
    pub basu_mandal: bool,
    /// Read the state of the simulations' right-hand side, stdin `{"state": [..11]}` (x, y, yaw,
    /// lean, steer, rear wheel, front wheel, lean rate, steer rate, rear wheel rate, pitch), and
    /// write its derivative: `{"derivative": [..11], "pitch": .., "speed": ..}`
    #[arg(long)]
    pub state: bool,
}

/// What standard input must hold, for the errors.
const EXPECTED: &str = r#"expected one JSON object {"q": [9 numbers], "qd": [9 numbers]}"#;

/// What standard input must hold with `--state`, for the errors.
const EXPECTED_STATE: &str = r#"expected one JSON object {"state": [11 numbers]}"#;

/// The nine numbers of `key` in the input object.
fn nine(v: &Value, key: &str) -> Result<[f64; 9], String> {
    numbers(v, key, EXPECTED)
}

/// The `N` numbers of `key` in the input object; `expected` ends the error of a missing key.
fn numbers<const N: usize>(v: &Value, key: &str, expected: &str) -> Result<[f64; N], String> {
    let arr = v
        .get(key)
        .and_then(Value::as_array)
        .ok_or(format!("input has no array `{key}`: {expected}"))?;
    if arr.len() != N {
        return Err(format!("`{key}` has {} entries, expected {N}", arr.len()));
    }
    let mut out = [0.0; N];
    for (k, x) in arr.iter().enumerate() {
        out[k] = x.as_f64().ok_or(format!("`{key}[{k}]` is not a number: {x}"))?;
    }
    Ok(out)
}

/// `{"derivative": [...], "pitch": .., "speed": ..}` for the JSON text `input` (`--state`).
fn state_rate(model: &str, input: &str) -> Result<String, String> {
    let f = StateRate::new(&toml_model(model)?);
    let v: Value = serde_json::from_str(input)
        .map_err(|e| format!("invalid JSON on standard input ({e}): {EXPECTED_STATE}"))?;
    if !v.is_object() {
        return Err(format!("invalid input `{v}` on standard input: {EXPECTED_STATE}"));
    }
    let y: [f64; rate::LEN] = numbers(&v, "state", EXPECTED_STATE)?;
    // Positions and angles, then the three rates, then the pitch.
    for (k, x) in y.iter().enumerate() {
        let range = if (7..10).contains(&k) { crate::args::RATE } else { crate::args::ANGLE };
        range.check(*x).map_err(|e| format!("`state[{k}]` = {x:?} {e}"))?;
    }
    let r = f.rates_with(&y, &mut |_| Ok([0.0, 0.0])).map_err(|e| e.to_string())?;
    serde_json::to_string_pretty(
        &json!({ "derivative": r.derivative, "pitch": r.pitch, "speed": r.speed }),
    )
    .map_err(|e| e.to_string())
}

/// `{"qdd": [...]}` for the JSON text `input`.
fn accel(model: &str, input: &str) -> Result<String, String> {
    let bike = WhippleNonlinear::new(toml_model(model)?);
    let v: Value = serde_json::from_str(input)
        .map_err(|e| format!("invalid JSON on standard input ({e}): {EXPECTED}"))?;
    if !v.is_object() {
        return Err(format!("invalid input `{v}` on standard input: {EXPECTED}"));
    }
    let (q, qd) = (nine(&v, "q")?, nine(&v, "qd")?);
    // Positions and angles, and rates, within the ranges where the equations keep their digits.
    for (key, values, range) in [("q", &q, crate::args::ANGLE), ("qd", &qd, crate::args::RATE)] {
        for (k, x) in values.iter().enumerate() {
            range.check(*x).map_err(|e| format!("`{key}[{k}]` = {x:?} {e}"))?;
        }
    }
    let qdd = bike.basu_mandal_accelerations(q, qd).map_err(|e| e.to_string())?;
    serde_json::to_string_pretty(&json!({ "qdd": qdd })).map_err(|e| e.to_string())
}

/// Runs `carvallo accel` on standard input: the text to print, or an error naming the bad value.
pub fn run(cmd: &Args) -> Result<String, String> {
    let input = crate::args::read_bounded(std::io::stdin().lock())
        .map_err(|e| format!("cannot read standard input: {e}"))?;
    if cmd.state {
        state_rate(&cmd.model, &input)
    } else {
        accel(&cmd.model, &input)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse::<Args>(&["accel", "--model", "benchmark", "--basu-mandal"]),
            Ok(Args { model: "benchmark".into(), basu_mandal: true, state: false })
        );
        assert_eq!(
            parse::<Args>(&["accel", "--model", "benchmark", "--state"]),
            Ok(Args { model: "benchmark".into(), basu_mandal: false, state: true })
        );
        let e = parse::<Args>(&["accel", "--model", "benchmark"]).unwrap_err();
        assert!(e.contains("required arguments were not provided") && e.contains("--basu-mandal"));
        let e = parse::<Args>(&["accel", "--model", "benchmark", "--state", "--basu-mandal"])
            .unwrap_err();
        assert!(e.contains("cannot be used with"), "{e}");
        let e = parse::<Args>(&["accel", "--speed", "1"]).unwrap_err();
        assert!(e.starts_with("error: unexpected argument '--speed'"), "{e}");
    }

    #[test]
    fn accel_reports_bad_input_by_name() {
        let e = accel("benchmark", "{").unwrap_err();
        assert!(e.starts_with("invalid JSON on standard input (EOF while parsing"), "{e}");
        assert!(e.ends_with(r#"expected one JSON object {"q": [9 numbers], "qd": [9 numbers]}"#));
        let e = accel("benchmark", "[1, 2]").unwrap_err();
        assert!(e.starts_with("invalid input `[1,2]` on standard input: expected one"), "{e}");
        let e = accel("benchmark", r#"{"qd": []}"#).unwrap_err();
        assert!(e.starts_with("input has no array `q`: expected one JSON object"), "{e}");
        assert_eq!(
            accel("benchmark", r#"{"q": [1, 2], "qd": []}"#).unwrap_err(),
            "`q` has 2 entries, expected 9"
        );
        let bad = r#"{"q": [0, 0, 0, 0, "x", 0, 0, 0, 0], "qd": [0, 0, 0, 0, 0, 0, 0, 0, 0]}"#;
        assert_eq!(accel("benchmark", bad).unwrap_err(), "`q[4]` is not a number: \"x\"");
        let big =
            r#"{"q": [0, 0, 0, 0, 1.5, 2.8, 0, 0, 0], "qd": [0, 0, 0, 0, 0, 0, 0, 1e200, 0]}"#;
        let e = accel("benchmark", big).unwrap_err();
        assert!(e.starts_with("`qd[7]` = 1e200 must lie within [-1e6, 1e6]"), "{e}");
    }

    #[test]
    fn state_rate_is_the_right_hand_side_of_the_simulations() {
        // The bench's state: lean 0.1, steer 0.05, lean rate 0.2, steer rate -0.1, rear wheel
        // rate -5/0.3, the pitch from the contact constraint.
        let params = toml_model("benchmark").unwrap();
        let pitch = WhippleNonlinear::new(params.clone()).pitch(0.1, 0.05, 0.0).unwrap();
        let y = [0.0, 0.0, 0.0, 0.1, 0.05, 0.0, 0.0, 0.2, -0.1, -5.0 / 0.3, pitch];
        let input = json!({ "state": y }).to_string();
        let out: Value = serde_json::from_str(&state_rate("benchmark", &input).unwrap()).unwrap();
        // The state as serde_json reads it, evaluated by the library.
        let read: Value = serde_json::from_str(&input).unwrap();
        let y: [f64; rate::LEN] = numbers(&read, "state", "").unwrap();
        let want = StateRate::new(&params).eval(&y).unwrap();
        let got: Vec<f64> =
            out["derivative"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        // serde_json's reading of its own output may be an ulp off: 1e-15 relative.
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).abs() <= 1e-15 * w.abs(), "{got:?} against {want:?}");
        }
        // One Newton step from the converged pitch moves it by rounding only.
        assert!((out["pitch"].as_f64().unwrap() - pitch).abs() <= 1e-15, "{out}");
        // The lean and steer rates are the state's.
        assert_eq!((got[3], got[4]), (0.2, -0.1));
    }

    #[test]
    fn state_rate_reports_bad_input_by_name() {
        let e = state_rate("benchmark", "[]").unwrap_err();
        assert!(e.ends_with(r#"expected one JSON object {"state": [11 numbers]}"#), "{e}");
        let e = state_rate("benchmark", r#"{"q": []}"#).unwrap_err();
        assert!(e.starts_with("input has no array `state`"), "{e}");
        assert_eq!(
            state_rate("benchmark", r#"{"state": [1, 2]}"#).unwrap_err(),
            "`state` has 2 entries, expected 11"
        );
        let big = r#"{"state": [0, 0, 0, 0, 0, 0, 0, 1e200, 0, 0, 0]}"#;
        let e = state_rate("benchmark", big).unwrap_err();
        assert!(e.starts_with("`state[7]` = 1e200 must lie within"), "{e}");
    }
}
