//! `carvallo eig --model benchmark|FILE.toml --speed V [--json]`: the four eigenvalues of the
//! linearised Carvallo–Whipple bicycle at speed V, as JSON
//! `{ "speed", "eigenvalues": [{"re", "im"}, ...] }`.
//!
//! The parameter file is read as for `window` ([`crate::args::bicycle`], with `--rider FILE` and `--strict`). Unknown or missing
//! arguments, a speed that is not a finite number and an unreadable or invalid parameter file
//! are usage errors: a message naming the value, exit code 2.

use carvallo::whipple::Whipple;

use crate::args::DataOptions;
use serde_json::{json, Value};

/// `carvallo eig`: the eigenvalues of the linearised bicycle at one speed.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: `benchmark` or a parameter file (the anchors' TOML or BicycleParameters'
    /// `name = value+/-sigma` text)
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: DataOptions,
    /// The forward speed [m/s]
    #[arg(long, value_name = "V", value_parser = crate::args::finite, allow_hyphen_values = true)]
    pub speed: f64,
    /// Print JSON `{speed, eigenvalues: [{re, im}, ...]}` instead of text
    #[arg(long)]
    pub json: bool,
}

/// Runs `carvallo eig`: the text to print, or an error naming the bad value.
pub fn run(cmd: &Args) -> Result<String, String> {
    let Args { model, data, speed, json } = cmd;
    let ev = Whipple::new(crate::args::bicycle(model, data)?).eigenvalues(*speed);
    if *json {
        let list: Vec<Value> = ev.iter().map(|e| json!({ "re": e.re, "im": e.im })).collect();
        let v = json!({ "speed": speed, "eigenvalues": list });
        Ok(serde_json::to_string_pretty(&v).map_err(|e| e.to_string())?)
    } else {
        let mut s = format!("eigenvalues at {speed} m/s:\n");
        for e in &ev {
            s.push_str(&format!("{} {:+}i\n", e.re, e.im));
        }
        Ok(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse::<Args>(&["eig", "--speed", "5", "--model", "b.toml"]),
            Ok(Args {
                model: "b.toml".into(),
                data: DataOptions::default(),
                speed: 5.0,
                json: false
            })
        );
        assert_eq!(
            parse::<Args>(&["eig", "--speed", "-1", "--model", "b"]).map(|a| a.speed),
            Ok(-1.0)
        );
        let e = parse::<Args>(&["eig", "--model", "x", "--speed", "fast"]).unwrap_err();
        assert!(
            e.starts_with("error: invalid value 'fast' for '--speed <V>': not a number"),
            "{e}"
        );
        let e = parse::<Args>(&["eig", "--model", "benchmark"]).unwrap_err();
        assert!(e.contains("--speed <V>"), "{e}");
    }
}
