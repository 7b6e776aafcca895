//! `carvallo accel --model benchmark|FILE.toml --basu-mandal`: the accelerations of the
//! nonlinear Carvallo–Whipple bicycle. Reads `{"q": [9 numbers], "qd": [9 numbers]}` on standard
//! input, in the coordinates of Basu-Mandal, Chatterjee and Papadopoulos (2007: x, y, z, θ, ψ,
//! φ, ψf, βr, βf), and prints `{"qdd": [9 numbers]}`.
//!
//! The parameter file is the anchors TOML format ([`crate::args::toml_model`]). Unknown,
//! repeated or missing arguments and bad JSON are errors naming the value, exit code 2.

use carvallo::whipple_nonlinear::WhippleNonlinear;
use serde_json::{json, Value};

use crate::args::toml_model;

/// `carvallo accel`: the accelerations of the nonlinear bicycle in Basu-Mandal's coordinates.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: `benchmark` or a parameter file in the anchors' TOML format
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    /// Read and write Basu-Mandal's coordinates (the only ones `accel` reads): stdin
    /// `{"q": [..9], "qd": [..9]}`
    #[arg(long, required = true)]
    pub basu_mandal: bool,
}

/// What standard input must hold, for the errors.
const EXPECTED: &str = r#"expected one JSON object {"q": [9 numbers], "qd": [9 numbers]}"#;

/// The nine numbers of `key` in the input object.
fn nine(v: &Value, key: &str) -> Result<[f64; 9], String> {
    let arr = v
        .get(key)
        .and_then(Value::as_array)
        .ok_or(format!("input has no array `{key}`: {EXPECTED}"))?;
    if arr.len() != 9 {
        return Err(format!("`{key}` has {} entries, expected 9", arr.len()));
    }
    let mut out = [0.0; 9];
    for (k, x) in arr.iter().enumerate() {
        out[k] = x.as_f64().ok_or(format!("`{key}[{k}]` is not a number: {x}"))?;
    }
    Ok(out)
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
    accel(&cmd.model, &input)
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse::<Args>(&["accel", "--model", "benchmark", "--basu-mandal"]),
            Ok(Args { model: "benchmark".into(), basu_mandal: true })
        );
        let e = parse::<Args>(&["accel", "--model", "benchmark"]).unwrap_err();
        assert!(e.contains("required arguments were not provided") && e.contains("--basu-mandal"));
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
}
