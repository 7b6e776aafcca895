//! The Carvallo–Whipple subcommands of the `carvallo` command line.
//!
//! * `carvallo window --model benchmark|FILE.toml [--json]`: the weave and capsize speeds and
//!   the stable speed intervals, as JSON
//!   `{ "model", "weave_speed", "capsize_speed", "stable": [[from, to], ...] }` (m/s; a speed
//!   that does not exist and an interval stable for every larger speed print as `null`).
//! * `carvallo eig --model benchmark|FILE.toml --speed V [--json]`: the four eigenvalues of the
//!   linearised equations at speed V, as JSON `{ "speed", "eigenvalues": [{"re", "im"}, ...] }`.
//!
//! A parameter file has the format of the benchmark anchors file (a `[parameters]` table) or
//! BicycleParameters' benchmark text format (`name = value+/-sigma`, one per line).
//! Unknown or missing arguments, a speed that is not a finite number and an unreadable or
//! invalid parameter file are usage errors: a message naming the value, exit code 2.

use carvallo::parameter_text::UncertainParams;
use carvallo::whipple::{Whipple, WhippleParams};
use serde_json::{json, Value};

const HELP: &str = "\
Usage:
    carvallo window --model benchmark|FILE.toml [--json]
    carvallo window --model carvallo|carvallo-formulas|carvallo-memoir|carvallo-quartic [--json]
    carvallo eig --model benchmark|FILE.toml --speed V [--json]
";

#[derive(Debug, PartialEq)]
enum Command {
    Window { model: String, json: bool },
    Eig { model: String, speed: f64, json: bool },
}

fn parse(args: &[String]) -> Result<Command, String> {
    let (first, rest) = args.split_first().ok_or("missing command")?;
    let (mut model, mut speed, mut json) = (None, None, false);
    let mut it = rest.iter();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--json" if json => return Err("argument `--json` given more than once".into()),
            "--json" => json = true,
            "--model" if model.is_some() => {
                return Err("argument `--model` given more than once".into())
            }
            "--model" => {
                model = Some(it.next().ok_or("missing value after `--model`")?.clone());
            }
            "--speed" if first == "eig" && speed.is_some() => {
                return Err("argument `--speed` given more than once".into())
            }
            "--speed" if first == "eig" => {
                let v = it.next().ok_or("missing value after `--speed`")?;
                let x: f64 = v.parse().map_err(|_| format!("invalid speed `{v}`"))?;
                if !x.is_finite() {
                    return Err(format!("invalid speed `{v}`: must be finite"));
                }
                speed = Some(x);
            }
            _ => return Err(format!("unknown argument `{arg}`")),
        }
    }
    let model = model.ok_or("missing `--model benchmark|FILE.toml`")?;
    match first.as_str() {
        "window" => Ok(Command::Window { model, json }),
        _ => Ok(Command::Eig { model, speed: speed.ok_or("missing `--speed V`")?, json }),
    }
}

/// The bicycle `benchmark` or the one in the parameter file `model` (either format of
/// [`load_uncertain`]).
pub(crate) fn load(model: &str) -> Result<WhippleParams, String> {
    load_uncertain(model).map(|u| u.params)
}

/// The bicycle `benchmark` (no uncertainty) or the one in the parameter file `model`: the
/// anchors TOML format or BicycleParameters' text format `name = value+/-sigma`
/// ([`UncertainParams::from_any`]).
pub(crate) fn load_uncertain(model: &str) -> Result<UncertainParams, String> {
    if model == "benchmark" {
        return Ok(UncertainParams::exact(WhippleParams::benchmark()));
    }
    let text = std::fs::read_to_string(model).map_err(|e| {
        format!("cannot read model file `{model}`: {}", e.to_string().to_lowercase())
    })?;
    UncertainParams::from_any(&text).map_err(|e| format!("invalid model file `{model}`: {e}"))
}

fn finite(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

fn run(cmd: &Command) -> Result<String, String> {
    match cmd {
        Command::Window { model, json } => {
            if let Some(out) = crate::straight::window_output(model, *json) {
                return out;
            }
            let w = Whipple::new(load(model)?).stability_window();
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
        Command::Eig { model, speed, json } => {
            let ev = Whipple::new(load(model)?).eigenvalues(*speed);
            if *json {
                let list: Vec<Value> =
                    ev.iter().map(|e| json!({ "re": e.re, "im": e.im })).collect();
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
    }
}

/// The subcommands `window` or `eig`.
pub const SUBCOMMAND: crate::Subcommand = crate::Subcommand {
    names: &["window", "eig"],
    run: |args| parse(args).and_then(|c| run(&c)),
    help: HELP,
};

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::words as args;

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse(&args(&["window", "--model", "benchmark", "--json"])),
            Ok(Command::Window { model: "benchmark".into(), json: true })
        );
        assert_eq!(
            parse(&args(&["eig", "--speed", "5", "--model", "b.toml"])),
            Ok(Command::Eig { model: "b.toml".into(), speed: 5.0, json: false })
        );
        assert_eq!(
            parse(&args(&["eig", "--model", "x", "--speed", "fast"])),
            Err("invalid speed `fast`".into())
        );
        assert_eq!(
            parse(&args(&["window", "--speed", "3"])),
            Err("unknown argument `--speed`".into())
        );
        assert_eq!(parse(&args(&["window"])), Err("missing `--model benchmark|FILE.toml`".into()));
        assert_eq!(
            parse(&args(&["eig", "--model", "benchmark"])),
            Err("missing `--speed V`".into())
        );
        let e = load("/nonexistent/bike.toml").unwrap_err();
        assert!(e.starts_with("cannot read model file `/nonexistent/bike.toml`"), "{e}");
    }
}
