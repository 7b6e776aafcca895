//! `carvallo simulate --model benchmark|FILE.toml --speed V --lean0 RAD --duration S
//! [--step DT] [--every N] [--json]`: integrates the nonlinear Carvallo–Whipple equations from
//! upright straight running at speed V with the initial lean RAD (RK4, step DT = 0.001 s by
//! default, the pitch re-solved at every stage) and prints the time series every N steps (10 by
//! default): time, lean, steer, pitch, rear contact speed, both ground tracks, energy, and the
//! energy drift and largest contact residual of the run.
//!
//! The parameter file is the anchors TOML format ([`crate::args::toml_model`]). Unknown,
//! repeated or missing arguments, non-finite numbers and a failed simulation (the bicycle fell
//! flat) are errors naming the value, exit code 2.

use carvallo::whipple_nonlinear::WhippleNonlinear;
use serde_json::json;

use crate::args::{number, options, toml_model};

/// The usage of `accel` and `simulate`, which either prints for `--help` and after a usage
/// error (the two commands of the nonlinear bicycle).
pub const HELP: &str = "\
Usage:
    carvallo accel --model benchmark|FILE.toml --basu-mandal   (reads {\"q\": [..9], \"qd\": [..9]} on stdin)
    carvallo simulate --model benchmark|FILE.toml --speed V --lean0 RAD --duration S
                      [--step DT] [--every N] [--json]
";

#[derive(Debug, PartialEq)]
struct Command {
    model: String,
    speed: f64,
    lean0: f64,
    duration: f64,
    step: f64,
    every: usize,
    json: bool,
}

fn parse(args: &[String]) -> Result<Command, String> {
    let mut model = None;
    let (mut speed, mut lean0, mut duration, mut step, mut every, mut json) =
        (None, None, None, 0.001, 10, false);
    let valued = ["--model", "--speed", "--lean0", "--duration", "--step", "--every"];
    for (a, v) in options(args.get(1..).unwrap_or_default(), &valued, &["--json"])? {
        match a {
            "--model" => model = Some(v.to_string()),
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
    Ok(Command {
        model: model.ok_or("missing `--model benchmark|FILE.toml`")?,
        speed: speed.ok_or("missing `--speed V`")?,
        lean0: lean0.ok_or("missing `--lean0 RAD`")?,
        duration: duration.ok_or("missing `--duration S`")?,
        step,
        every,
        json,
    })
}

fn run(cmd: &Command) -> Result<String, String> {
    let Command { model, speed, lean0, duration, step, every, json } = cmd;
    let bike = WhippleNonlinear::new(toml_model(model)?);
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

/// Runs `carvallo simulate ARGS` (the argument list, the command's name first): the text to
/// print, or an error naming the bad argument or value.
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
            Ok(Command {
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
    }
}
