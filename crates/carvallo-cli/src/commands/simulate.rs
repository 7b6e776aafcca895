//! `carvallo simulate --model benchmark|FILE.toml --speed V --lean0 RAD --duration S
//! [--step DT] [--every N] [--json]`: integrates the nonlinear Carvallo–Whipple equations from
//! upright straight running at speed V with the initial lean RAD (RK4, step DT = 0.001 s by
//! default, the pitch re-solved at every stage) and prints the time series every N steps (10 by
//! default): time, lean, steer, pitch, rear contact speed, both ground tracks, energy, and the
//! energy drift and largest contact residual of the run.
//!
//! The parameter file is the anchors TOML format or BicycleParameters' text, with `--rider` and
//! `--strict` as on `window` ([`crate::args::bicycle`]). Unknown,
//! repeated or missing arguments, non-finite numbers and a failed simulation (the bicycle fell
//! flat) are errors naming the value, exit code 2.

use carvallo::whipple_nonlinear::WhippleNonlinear;
use serde_json::json;

use crate::args::{finite, DataOptions};

/// `carvallo simulate`: the nonlinear bicycle integrated from upright straight running.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: `benchmark` or a parameter file (the anchors' TOML or BicycleParameters'
    /// `name = value+/-sigma` text)
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: DataOptions,
    /// The initial forward speed [m/s]
    #[arg(long, value_name = "V", value_parser = finite, allow_hyphen_values = true)]
    pub speed: f64,
    /// The initial lean [rad]
    #[arg(long, value_name = "RAD", value_parser = finite, allow_hyphen_values = true)]
    pub lean0: f64,
    /// How long to simulate [s]
    #[arg(long, value_name = "S", value_parser = finite, allow_hyphen_values = true)]
    pub duration: f64,
    /// The RK4 step [s]
    #[arg(long, value_name = "DT", default_value_t = 0.001, value_parser = finite, allow_hyphen_values = true)]
    pub step: f64,
    /// Print every N-th step
    #[arg(long, value_name = "N", default_value_t = 10, value_parser = positive)]
    pub every: usize,
    /// Print JSON (the samples, the energy drift and the largest contact residual) instead of text
    #[arg(long)]
    pub json: bool,
}

/// A positive count.
fn positive(v: &str) -> Result<usize, String> {
    v.parse().ok().filter(|n| *n > 0).ok_or_else(|| "must be a positive integer".to_string())
}

/// Runs `carvallo simulate`: the text to print, or an error naming the bad value.
pub fn run(cmd: &Args) -> Result<String, String> {
    let Args { model, data, speed, lean0, duration, step, every, json } = cmd;
    let bike = WhippleNonlinear::new(crate::args::bicycle(model, data)?);
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

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_and_rejects_by_value() {
        let words = [
            "simulate",
            "--model",
            "benchmark",
            "--speed",
            "5",
            "--lean0",
            "0.05",
            "--duration",
            "2",
            "--json",
        ];
        assert_eq!(
            parse::<Args>(&words),
            Ok(Args {
                model: "benchmark".into(),
                data: DataOptions::default(),
                speed: 5.0,
                lean0: 0.05,
                duration: 2.0,
                step: 0.001,
                every: 10,
                json: true
            })
        );
        let e = parse::<Args>(&["simulate", "--model", "benchmark", "--speed", "inf"]).unwrap_err();
        assert!(
            e.starts_with("error: invalid value 'inf' for '--speed <V>': must be finite"),
            "{e}"
        );
        let e = parse::<Args>(&["simulate", "--model", "b", "--speed", "1", "--speed", "2"])
            .unwrap_err();
        assert!(e.contains("'--speed <V>' cannot be used multiple times"), "{e}");
        let e = parse::<Args>(&["simulate", "--model", "b", "--speed", "1", "--lean0", "0"])
            .unwrap_err();
        assert!(e.contains("--duration <S>"), "{e}");
        let e = parse::<Args>(&[&words[..9], &["--every", "0"]].concat()).unwrap_err();
        assert!(e.contains("invalid value '0' for '--every <N>'"), "{e}");
    }
}
