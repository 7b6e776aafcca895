//! The nonlinear Carvallo–Whipple subcommands of the `carvallo` command line.
//!
//! * `carvallo accel --model benchmark|FILE.toml --basu-mandal`: reads
//!   `{"q": [9 numbers], "qd": [9 numbers]}` on standard input, in the coordinates of
//!   Basu-Mandal, Chatterjee and Papadopoulos (2007: x, y, z, θ, ψ, φ, ψf, βr, βf), and prints
//!   `{"qdd": [9 numbers]}`.
//! * `carvallo simulate --model benchmark|FILE.toml --speed V --lean0 RAD --duration S
//!   [--step DT] [--every N] [--json]`: integrates the nonlinear equations from upright
//!   straight running at speed V with the initial lean RAD (RK4, step DT = 0.001 s by
//!   default, the pitch re-solved at every stage) and prints the time series every N steps
//!   (10 by default): time, lean, steer, pitch, rear contact speed, both ground tracks, energy,
//!   and the energy drift and largest contact residual of the run.
//!
//! Unknown, repeated or missing arguments, non-finite numbers, bad JSON and a failed
//! simulation (the bicycle fell flat) are errors naming the value, exit code 2.

use std::io::Read;

use carvallo::whipple::WhippleParams;
use carvallo::whipple_nonlinear::WhippleNonlinear;
use serde_json::{json, Value};

use crate::args::{number, options};

const HELP: &str = "\
Usage:
    carvallo accel --model benchmark|FILE.toml --basu-mandal   (reads {\"q\": [..9], \"qd\": [..9]} on stdin)
    carvallo simulate --model benchmark|FILE.toml --speed V --lean0 RAD --duration S
                      [--step DT] [--every N] [--json]
";

#[derive(Debug, PartialEq)]
enum Command {
    Accel {
        model: String,
    },
    Simulate {
        model: String,
        speed: f64,
        lean0: f64,
        duration: f64,
        step: f64,
        every: usize,
        json: bool,
    },
}

fn parse(args: &[String]) -> Result<Command, String> {
    let (first, rest) = args.split_first().ok_or("missing command")?;
    let accel = first == "accel";
    let (mut model, mut basu, mut json) = (None, false, false);
    let (mut speed, mut lean0, mut duration, mut step, mut every) = (None, None, None, 0.001, 10);
    let (valued, flags): (&[&str], &[&str]) = if accel {
        (&["--model"], &["--basu-mandal"])
    } else {
        (&["--model", "--speed", "--lean0", "--duration", "--step", "--every"], &["--json"])
    };
    for (a, v) in options(rest, valued, flags)? {
        match a {
            "--model" => model = Some(v.to_string()),
            "--basu-mandal" => basu = true,
            "--json" => json = true,
            "--speed" => speed = Some(number("speed", v)?),
            "--lean0" => lean0 = Some(number("lean0", v)?),
            "--duration" => duration = Some(number("duration", v)?),
            "--step" => step = number("step", v)?,
            _ => {
                every = v
                    .parse()
                    .ok()
                    .filter(|n| *n > 0)
                    .ok_or(format!("invalid every `{v}`: must be a positive integer"))?;
            }
        }
    }
    let model = model.ok_or("missing `--model benchmark|FILE.toml`")?;
    if accel {
        if !basu {
            return Err("missing `--basu-mandal` (the only coordinates `accel` reads)".into());
        }
        return Ok(Command::Accel { model });
    }
    Ok(Command::Simulate {
        model,
        speed: speed.ok_or("missing `--speed V`")?,
        lean0: lean0.ok_or("missing `--lean0 RAD`")?,
        duration: duration.ok_or("missing `--duration S`")?,
        step,
        every,
        json,
    })
}

fn load(model: &str) -> Result<WhippleParams, String> {
    if model == "benchmark" {
        return Ok(WhippleParams::benchmark());
    }
    let text = std::fs::read_to_string(model).map_err(|e| {
        format!("cannot read model file `{model}`: {}", e.to_string().to_lowercase())
    })?;
    WhippleParams::from_toml_str(&text).map_err(|e| format!("invalid model file `{model}`: {e}"))
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
    let bike = WhippleNonlinear::new(load(model)?);
    let v: Value =
        serde_json::from_str(input).map_err(|e| format!("invalid JSON on standard input: {e}"))?;
    let (q, qd) = (nine(&v, "q")?, nine(&v, "qd")?);
    let qdd = bike.basu_mandal_accelerations(q, qd).map_err(|e| e.to_string())?;
    serde_json::to_string_pretty(&json!({ "qdd": qdd })).map_err(|e| e.to_string())
}

fn run(cmd: &Command) -> Result<String, String> {
    match cmd {
        Command::Accel { model } => {
            let mut input = String::new();
            std::io::stdin()
                .read_to_string(&mut input)
                .map_err(|e| format!("cannot read standard input: {e}"))?;
            accel(model, &input)
        }
        Command::Simulate { model, speed, lean0, duration, step, every, json } => {
            let bike = WhippleNonlinear::new(load(model)?);
            let start = bike.initial_state(*speed, *lean0).map_err(|e| e.to_string())?;
            let tr = bike.simulate(start, *duration, *step, *every).map_err(|e| e.to_string())?;
            if *json {
                let col = |f: &dyn Fn(&carvallo::whipple_nonlinear::Sample) -> f64| -> Vec<f64> {
                    tr.samples.iter().map(f).collect()
                };
                let v = json!({
                    "model": model,
                    "speed": speed,
                    "lean0": lean0,
                    "step": tr.step,
                    "energy_drift": tr.energy_drift,
                    "max_contact_residual": tr.max_contact_residual,
                    "t": col(&|s| s.t),
                    "lean": col(&|s| s.state.lean),
                    "steer": col(&|s| s.state.steer),
                    "pitch": col(&|s| s.pitch),
                    "speed_rear": col(&|s| s.speed),
                    "rear_x": col(&|s| s.rear_contact[0]),
                    "rear_y": col(&|s| s.rear_contact[1]),
                    "front_x": col(&|s| s.front_contact[0]),
                    "front_y": col(&|s| s.front_contact[1]),
                    "energy": col(&|s| s.energy),
                });
                serde_json::to_string(&v).map_err(|e| e.to_string())
            } else {
                let mut s = format!(
                    "nonlinear {model} bicycle from {speed} m/s, lean {lean0} rad, RK4 step {} s\nenergy drift {:e} J, largest contact residual {:e} m\n t        lean       steer      speed      rear (x, y)            front (x, y)\n",
                    tr.step, tr.energy_drift, tr.max_contact_residual
                );
                for p in &tr.samples {
                    s.push_str(&format!(
                        "{:8.3} {:+.6} {:+.6} {:.6} ({:.4}, {:+.4}) ({:.4}, {:+.4})\n",
                        p.t,
                        p.state.lean,
                        p.state.steer,
                        p.speed,
                        p.rear_contact[0],
                        p.rear_contact[1],
                        p.front_contact[0],
                        p.front_contact[1]
                    ));
                }
                Ok(s)
            }
        }
    }
}

/// The subcommands `accel` or `simulate`.
pub const SUBCOMMAND: crate::Subcommand = crate::Subcommand {
    names: &["accel", "simulate"],
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
            parse(&args(&["accel", "--model", "benchmark", "--basu-mandal"])),
            Ok(Command::Accel { model: "benchmark".into() })
        );
        assert_eq!(
            parse(&args(&["accel", "--model", "benchmark"])),
            Err("missing `--basu-mandal` (the only coordinates `accel` reads)".into())
        );
        assert_eq!(
            parse(&args(&[
                "simulate",
                "--model",
                "benchmark",
                "--speed",
                "5",
                "--lean0",
                "0.05",
                "--duration",
                "2",
                "--json"
            ])),
            Ok(Command::Simulate {
                model: "benchmark".into(),
                speed: 5.0,
                lean0: 0.05,
                duration: 2.0,
                step: 0.001,
                every: 10,
                json: true
            })
        );
        assert_eq!(
            parse(&args(&["simulate", "--model", "benchmark", "--speed", "inf"])),
            Err("invalid speed `inf`: must be finite".into())
        );
        assert_eq!(
            parse(&args(&["simulate", "--model", "b", "--speed", "1", "--speed", "2"])),
            Err("argument `--speed` given more than once".into())
        );
        assert_eq!(
            parse(&args(&["simulate", "--model", "b", "--speed", "1", "--lean0", "0"])),
            Err("missing `--duration S`".into())
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
