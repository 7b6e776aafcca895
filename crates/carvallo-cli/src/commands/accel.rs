//! `carvallo accel --model benchmark|FILE.toml --basu-mandal`: the accelerations of the
//! nonlinear Carvallo–Whipple bicycle. Reads `{"q": [9 numbers], "qd": [9 numbers]}` on standard
//! input, in the coordinates of Basu-Mandal, Chatterjee and Papadopoulos (2007: x, y, z, θ, ψ,
//! φ, ψf, βr, βf), and prints `{"qdd": [9 numbers]}`.
//!
//! The parameter file is the anchors TOML format ([`crate::args::toml_model`]). Unknown,
//! repeated or missing arguments and bad JSON are errors naming the value, exit code 2.

use std::io::Read;

use carvallo::whipple_nonlinear::WhippleNonlinear;
use serde_json::{json, Value};

use crate::args::{options, toml_model};

/// The usage `accel` prints: the one of `accel` and `simulate` together.
pub const HELP: &str = super::simulate::HELP;

#[derive(Debug, PartialEq)]
struct Command {
    model: String,
}

fn parse(args: &[String]) -> Result<Command, String> {
    let (mut model, mut basu) = (None, false);
    for (a, v) in options(args.get(1..).unwrap_or_default(), &["--model"], &["--basu-mandal"])? {
        match a {
            "--model" => model = Some(v.to_string()),
            _ => basu = true,
        }
    }
    let model = model.ok_or("missing `--model benchmark|FILE.toml`")?;
    if !basu {
        return Err("missing `--basu-mandal` (the only coordinates `accel` reads)".into());
    }
    Ok(Command { model })
}

/// The nine numbers of `key` in the input object.
fn nine(v: &Value, key: &str) -> Result<[f64; 9], String> {
    let arr = v.get(key).and_then(Value::as_array).ok_or(format!("input has no array `{key}`"))?;
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
    let v: Value =
        serde_json::from_str(input).map_err(|e| format!("invalid JSON on standard input: {e}"))?;
    let (q, qd) = (nine(&v, "q")?, nine(&v, "qd")?);
    let qdd = bike.basu_mandal_accelerations(q, qd).map_err(|e| e.to_string())?;
    serde_json::to_string_pretty(&json!({ "qdd": qdd })).map_err(|e| e.to_string())
}

fn run(cmd: &Command) -> Result<String, String> {
    let mut input = String::new();
    std::io::stdin()
        .read_to_string(&mut input)
        .map_err(|e| format!("cannot read standard input: {e}"))?;
    accel(&cmd.model, &input)
}

/// Runs `carvallo accel ARGS` (the argument list, the command's name first) on standard input:
/// the text to print, or an error naming the bad argument or value.
pub fn main(args: &[String]) -> Result<String, String> {
    parse(args).and_then(|c| run(&c))
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::words as args;

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse(&args(&["accel", "--model", "benchmark", "--basu-mandal"])),
            Ok(Command { model: "benchmark".into() })
        );
        assert_eq!(
            parse(&args(&["accel", "--model", "benchmark"])),
            Err("missing `--basu-mandal` (the only coordinates `accel` reads)".into())
        );
        assert_eq!(
            parse(&args(&["accel", "--speed", "1"])),
            Err("unknown argument `--speed`".into())
        );
    }

    #[test]
    fn accel_reports_bad_input_by_name() {
        assert!(accel("benchmark", "{").unwrap_err().starts_with("invalid JSON"));
        assert_eq!(
            accel("benchmark", r#"{"q": [1, 2], "qd": []}"#).unwrap_err(),
            "`q` has 2 entries, expected 9"
        );
        let bad = r#"{"q": [0, 0, 0, 0, "x", 0, 0, 0, 0], "qd": [0, 0, 0, 0, 0, 0, 0, 0, 0]}"#;
        assert_eq!(accel("benchmark", bad).unwrap_err(), "`q[4]` is not a number: \"x\"");
    }
}
