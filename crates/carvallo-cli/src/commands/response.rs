//! `carvallo response --model benchmark|FILE --speed V --kind step|impulse|initial
//! [--input roll|steer] [--x0 LEAN,STEER,LEAN_RATE,STEER_RATE] [--duration D] [--samples N]
//! [--json | --csv]`: the time response of the linearised bicycle as a plant
//! ([`carvallo::whipple::response`]) to a unit step or unit impulse of the roll or steer torque
//! from rest, or from an initial state with no input, through the matrix exponential, at the
//! `N` times $t_i = i\,D/(N - 1)$.
//!
//! JSON `{"model", "rider", "speed", "kind", "input", "x0", "t": [...], "roll", "steer",
//! "roll_rate", "steer_rate"}` (arrays; `input` null for `initial`, `x0` null for a step or
//! impulse); CSV `t,roll,steer,roll_rate,steer_rate`. The parameter file is read as for
//! `window` (`--rider FILE`, `--strict`). A kind without what it needs (`initial` without
//! `--x0`, a step or impulse with `--x0`), a duration that is not positive and finite, a count
//! below 2, a speed or an initial state outside the numerically valid ranges
//! ([`crate::args::SPEED`], [`crate::args::ANGLE`]) and a duration over which the response is
//! no longer finite (an unstable bicycle grows past the largest `f64`) are usage errors naming
//! the value, exit code 2: no NaN or infinity is printed.

use carvallo::whipple::response::Excitation;
use carvallo::whipple::transfer::Input;
use carvallo::whipple::Whipple;
use clap::builder::{PossibleValuesParser, TypedValueParser as _};
use serde_json::json;

use crate::args::DataOptions;

/// `carvallo response`: the step, impulse or initial-condition response of the linear plant.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: `benchmark` or a parameter file (the anchors' TOML or BicycleParameters'
    /// `name = value+/-sigma` text)
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: DataOptions,
    /// The forward speed (m/s)
    #[arg(long, value_name = "V", value_parser = crate::args::SPEED.parser(), allow_hyphen_values = true)]
    pub speed: f64,
    /// What drives the response: a unit step (1 N m) or a unit impulse (1 N m s) of the input
    /// from rest, or the initial state --x0 with no input
    #[arg(long, value_name = "KIND", value_parser = ["step", "impulse", "initial"])]
    pub kind: String,
    /// The input of a step or impulse: the roll torque or the steer torque
    #[arg(long, value_name = "INPUT", default_value = "steer",
          value_parser = PossibleValuesParser::new(["roll", "steer"]).try_map(|s| s.parse::<Input>()))]
    pub input: Input,
    /// The initial state of `--kind initial`: lean, steer (rad), lean rate, steer rate (rad/s)
    #[arg(long, value_name = "X", value_delimiter = ',', num_args = 1,
          value_parser = crate::args::ANGLE.parser(), allow_hyphen_values = true)]
    pub x0: Vec<f64>,
    /// The duration (s)
    #[arg(long, value_name = "D", default_value_t = 5.0, value_parser = positive,
          allow_hyphen_values = true)]
    pub duration: f64,
    /// The number of times, evenly spaced from 0 to the duration
    #[arg(long, value_name = "N", default_value_t = 501,
          value_parser = clap::value_parser!(u32).range(2..=1_000_000))]
    pub samples: u32,
    /// Print JSON `{model, rider, speed, kind, input, x0, t, roll, steer, roll_rate,
    /// steer_rate}` instead of text
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print CSV `t,roll,steer,roll_rate,steer_rate` instead of text
    #[arg(long)]
    pub csv: bool,
}

/// A positive finite number, for clap's `value_parser`.
fn positive(v: &str) -> Result<f64, String> {
    let x = crate::args::finite(v)?;
    if x <= 0.0 {
        return Err("must be positive".into());
    }
    Ok(x)
}

/// `x` as Rust prints it, or in scientific notation when that would run to many digits.
fn short(x: f64) -> String {
    if x != 0.0 && !(1e-4..1e9).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// Runs `carvallo response`: the text to print, or an error naming the bad value.
pub fn run(cmd: &Args) -> Result<String, String> {
    let Args { model, data, speed, kind, input, x0, duration, samples, json, csv } = cmd;
    let excitation = match (kind.as_str(), x0.as_slice()) {
        ("initial", [a, b, c, d]) => Excitation::Initial([*a, *b, *c, *d]),
        ("initial", []) => return Err("invalid --kind initial: it needs --x0".into()),
        ("initial", x) => {
            return Err(format!(
                "invalid --x0 of {} values: must be 4 (lean, steer, lean rate, steer rate)",
                x.len()
            ))
        }
        (_, [_, ..]) => {
            return Err(format!("invalid --x0 with --kind {kind}: a {kind} starts from rest"))
        }
        ("step", []) => Excitation::Step(*input),
        _ => Excitation::Impulse(*input),
    };
    let bike = Whipple::new(crate::args::bicycle(model, data)?);
    let n = *samples as usize;
    let times: Vec<f64> = (0..n)
        .map(|i| if i + 1 == n { *duration } else { i as f64 / (n - 1) as f64 * duration })
        .collect();
    let xs = bike.time_response(*speed, excitation, &times).map_err(|e| e.to_string())?;
    if let Some(i) = xs.iter().position(|x| x.iter().any(|c| !c.is_finite())) {
        let last = if i == 0 { 0.0 } else { times[i - 1] };
        return Err(format!(
            "invalid value '{}' for '--duration <D>': the response is not finite at t = {} s \
             (the last finite time is {} s: a bicycle unstable at {speed} m/s grows past the \
             largest number, or the matrix exponential overflows); take a shorter --duration",
            short(*duration),
            short(times[i]),
            short(last)
        ));
    }
    let column = |k: usize| xs.iter().map(|x| x[k]).collect::<Vec<f64>>();
    let input_name = match excitation {
        Excitation::Initial(_) => None,
        _ => Some(input.name()),
    };
    if *json {
        let v = json!({
            "model": model, "rider": data.rider, "speed": speed, "kind": kind,
            "input": input_name, "x0": if x0.is_empty() { None } else { Some(x0) },
            "t": times, "roll": column(0), "steer": column(1), "roll_rate": column(2),
            "steer_rate": column(3),
        });
        return serde_json::to_string(&v).map_err(|e| e.to_string());
    }
    let mut s = String::new();
    if *csv {
        s.push_str("t,roll,steer,roll_rate,steer_rate\n");
        for (t, x) in times.iter().zip(&xs) {
            s.push_str(&format!("{t},{},{},{},{}\n", x[0], x[1], x[2], x[3]));
        }
        return Ok(s);
    }
    let what = match excitation {
        Excitation::Step(i) => format!("unit step of the {} torque", i.name()),
        Excitation::Impulse(i) => format!("unit impulse of the {} torque", i.name()),
        Excitation::Initial(x) => format!("initial state {x:?}"),
    };
    s.push_str(&format!(
        "response of {} at {speed} m/s to a {what}\n       t [s]       lean [rad]      steer [rad]  lean rate [rad/s] steer rate [rad/s]\n",
        data.label(model)
    ));
    for (t, x) in times.iter().zip(&xs) {
        s.push_str(&format!(
            "{t:>12.6} {:>16.9e} {:>16.9e} {:>18.9e} {:>18.9e}\n",
            x[0], x[1], x[2], x[3]
        ));
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_and_rejects_by_value() {
        let a =
            parse::<Args>(&["response", "--model", "benchmark", "--speed", "5", "--kind", "step"])
                .expect("valid");
        assert_eq!((a.input, a.duration, a.samples), (Input::Steer, 5.0, 501));
        let e = parse::<Args>(&["response", "--model", "b", "--speed", "5", "--kind", "ramp"])
            .unwrap_err();
        assert!(e.contains("invalid value 'ramp'"), "{e}");
        let e = parse::<Args>(&[
            "response",
            "--model",
            "b",
            "--speed",
            "5",
            "--kind",
            "step",
            "--duration",
            "-1",
        ])
        .unwrap_err();
        assert!(e.contains("'-1'") && e.contains("must be positive"), "{e}");
        let e = parse::<Args>(&[
            "response",
            "--model",
            "b",
            "--speed",
            "5",
            "--kind",
            "step",
            "--samples",
            "1",
        ])
        .unwrap_err();
        assert!(e.contains("'1'"), "{e}");
        for (kind, x0, want) in [
            ("initial", None, "invalid --kind initial: it needs --x0"),
            ("initial", Some("0.1,0"), "invalid --x0 of 2 values: must be 4"),
            ("step", Some("0.1,0,0,0"), "invalid --x0 with --kind step: a step starts from rest"),
        ] {
            let mut words =
                vec!["response", "--model", "benchmark", "--speed", "5", "--kind", kind];
            if let Some(x) = x0 {
                words.extend(["--x0", x]);
            }
            let e = run(&parse::<Args>(&words).expect("parses")).unwrap_err();
            assert!(e.starts_with(want), "{e}");
        }
    }

    #[test]
    fn speeds_and_initial_states_outside_their_ranges_are_refused() {
        let e = parse::<Args>(&["response", "--model", "b", "--speed", "1e308", "--kind", "step"])
            .unwrap_err();
        assert!(e.contains("'--speed <V>'") && e.contains("[-1e6, 1e6]"), "{e}");
        let e = parse::<Args>(&[
            "response",
            "--model",
            "b",
            "--speed",
            "5",
            "--kind",
            "initial",
            "--x0",
            "0,0,1e300,0",
        ])
        .unwrap_err();
        assert!(e.contains("'--x0 <X>'") && e.contains("[-1e6, 1e6]"), "{e}");
    }

    #[test]
    fn a_response_that_stops_being_finite_is_an_error_naming_the_duration() {
        // At 0 m/s the benchmark capsizes at about 6 1/s: past about 120 s the response
        // overflows; a stable bicycle over a duration of 1e300 s loses it in the exponential.
        for (speed, duration) in [("0", "300"), ("5", "1.5e300"), ("5", "1.7976931348623157e308")] {
            let a = parse::<Args>(&[
                "response",
                "--model",
                "benchmark",
                "--speed",
                speed,
                "--kind",
                "step",
                "--duration",
                duration,
                "--samples",
                "3",
            ])
            .expect("valid");
            let e = run(&a).unwrap_err();
            assert!(
                e.starts_with(&format!("invalid value '{duration}' for '--duration <D>'"))
                    && e.contains("take a shorter --duration"),
                "{e}"
            );
        }
        // Short of the overflow, the same unstable bicycle is a finite result.
        let a = parse::<Args>(&[
            "response",
            "--model",
            "benchmark",
            "--speed",
            "0",
            "--kind",
            "step",
            "--duration",
            "10",
            "--json",
        ])
        .expect("valid");
        let v: serde_json::Value = serde_json::from_str(&run(&a).unwrap()).unwrap();
        assert!(v["roll"]
            .as_array()
            .unwrap()
            .iter()
            .all(|x| x.as_f64().is_some_and(f64::is_finite)));
    }

    #[test]
    fn the_last_sample_is_the_library_s_value_at_the_duration() {
        let a = parse::<Args>(&[
            "response",
            "--model",
            "benchmark",
            "--speed",
            "5",
            "--kind",
            "impulse",
            "--input",
            "roll",
            "--duration",
            "2",
            "--samples",
            "3",
            "--json",
        ])
        .expect("valid");
        let v: serde_json::Value = serde_json::from_str(&run(&a).unwrap()).unwrap();
        assert_eq!(v["t"], json!([0.0, 1.0, 2.0]));
        let bike = Whipple::new(carvallo::whipple::WhippleParams::benchmark());
        let x = bike.time_response(5.0, Excitation::Impulse(Input::Roll), &[2.0]).unwrap();
        assert_eq!(v["steer"][2], json!(x[0][1]));
        assert_eq!(v["input"], "roll");
        assert_eq!(v["x0"], serde_json::Value::Null);
    }
}
