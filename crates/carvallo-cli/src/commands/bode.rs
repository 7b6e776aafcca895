//! `carvallo bode --model benchmark|FILE --speed V[,V...] --input roll|steer
//! --output roll|steer|roll-rate|steer-rate [--omega W[,W...] | --omega-range FROM:TO:N]
//! [--json | --csv]`: the frequency response $G(i\omega)$ of one input–output pair of the
//! linearised bicycle ([`carvallo::whipple::transfer`]): magnitude in dB and phase in degrees,
//! on the branch continuous in $\omega$ that lies in $(-180°, 180°]$ as $\omega \to 0^+$ (the
//! same at a frequency whatever the grid).
//!
//! JSON `{"model", "rider", "input", "output", "points": [{"speed", "omega", "re", "im",
//! "magnitude_db", "phase_deg"}, ...]}`; CSV with the same columns as the points. Frequencies
//! are angular (rad/s); `--omega-range` spaces `N` of them logarithmically from `FROM` to `TO`
//! (the axis of a Bode diagram); the default is `0.1:100:61` (20 per decade).
//!
//! The parameter file is read as for `window` ([`crate::args::bicycle`], with `--rider FILE`
//! and `--strict`). An unknown input or output, a frequency that is not a positive finite number
//! and a malformed range are usage errors naming the value, exit code 2.

use carvallo::whipple::transfer::{log_space, FrequencyPoint, Input, Output};
use carvallo::whipple::Whipple;
use clap::builder::PossibleValuesParser;
use serde_json::json;

use crate::args::DataOptions;

/// `carvallo bode`: the frequency response of one input–output pair at one or several speeds.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: `benchmark` or a parameter file (the anchors' TOML or BicycleParameters'
    /// `name = value+/-sigma` text)
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: DataOptions,
    /// The forward speeds (m/s), separated by commas
    #[arg(long, value_name = "V", required = true, value_delimiter = ',',
          value_parser = crate::args::SPEED.parser(), allow_hyphen_values = true)]
    pub speed: Vec<f64>,
    /// The input: the roll torque or the steer torque (and for the leaning rider the lean
    /// torque, `lean`)
    #[arg(long, value_name = "INPUT",
          value_parser = PossibleValuesParser::new(LEAN_INPUTS))]
    pub input: String,
    /// The output: the lean (roll) or steer angle in rad or its rate in rad/s (and for the
    /// leaning rider the torso's lean on its joint, `lean`, `lean-rate`)
    #[arg(long, value_name = "OUTPUT",
          value_parser = PossibleValuesParser::new(LEAN_OUTPUTS))]
    pub output: String,
    /// The angular frequencies (rad/s), positive, separated by commas
    #[arg(long, value_name = "W", value_delimiter = ',', value_parser = positive,
          conflicts_with = "omega_range")]
    pub omega: Vec<f64>,
    /// N angular frequencies (rad/s) spaced logarithmically from FROM to TO
    #[arg(long, value_name = "FROM:TO:N", value_parser = omega_range, default_value = "0.1:100:61")]
    pub omega_range: Frequencies,
    /// Print JSON `{model, input, output, points: [{speed, omega, re, im, magnitude_db,
    /// phase_deg}]}` instead of text
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// Print CSV `speed,omega,re,im,magnitude_db,phase_deg` instead of text
    #[arg(long)]
    pub csv: bool,
}

/// The inputs of `--input`, the leaning rider's order (T4, T7, T9).
const LEAN_INPUTS: [&str; 3] = ["roll", "steer", "lean"];

/// The outputs of `--output`, the leaning rider's lateral states' order.
const LEAN_OUTPUTS: [&str; 6] = ["roll", "steer", "lean", "roll-rate", "steer-rate", "lean-rate"];

/// The frequencies of `--omega-range`.
#[derive(Clone, Debug, PartialEq)]
pub struct Frequencies(pub Vec<f64>);

/// A positive finite number, for clap's `value_parser`.
fn positive(v: &str) -> Result<f64, String> {
    let x = crate::args::finite(v)?;
    if x <= 0.0 {
        return Err("must be positive".into());
    }
    crate::args::FREQUENCY.check(x)
}

/// `FROM:TO:N` with `0 < FROM <= TO` finite and `1 <= N <= 10^6`: the frequencies of
/// [`log_space`].
pub(crate) fn omega_range(v: &str) -> Result<Frequencies, String> {
    let parts: Vec<&str> = v.split(':').collect();
    let [from, to, n] = parts[..] else {
        return Err("expected FROM:TO:N".into());
    };
    let (from, to) = (positive(from)?, positive(to)?);
    let n: usize = n.parse().map_err(|_| format!("the count `{n}` is not a whole number"))?;
    if !(1..=1_000_000).contains(&n) {
        return Err(format!("the count {n} must lie between 1 and 1000000"));
    }
    log_space(from, to, n).map(Frequencies).ok_or_else(|| format!("FROM {from} exceeds TO {to}"))
}

/// Runs `carvallo bode`: the text to print, or an error naming the bad value.
pub fn run(cmd: &Args) -> Result<String, String> {
    let Args { model, data, speed, input, output, omega, omega_range, json, csv } = cmd;
    let omegas = if omega.is_empty() { &omega_range.0 } else { omega };
    let points = if let Some(rider) = crate::args::lean_rider(model, data)? {
        let i = LEAN_INPUTS.iter().position(|n| n == input).expect("a possible value");
        let o = LEAN_OUTPUTS.iter().position(|n| n == output).expect("a possible value");
        super::lean_rider::frequency_response(&rider, speed, omegas, i, o)
    } else {
        let lean_only = |name: &str| {
            format!(
                "invalid {name}: the torso's lean is the leaning rider's (--model lean-rider); \
                 the bicycle's inputs are roll and steer, its outputs roll, steer and their rates"
            )
        };
        let input: Input = input.parse().map_err(|_| lean_only(&format!("--input {input}")))?;
        let output: Output =
            output.parse().map_err(|_| lean_only(&format!("--output {output}")))?;
        let bike = Whipple::new(crate::args::bicycle(model, data)?);
        bike.frequency_response(speed, omegas, input, output)
    };
    if *json {
        let pts: Vec<_> = points
            .iter()
            .map(|p| {
                json!({
                    "speed": p.speed, "omega": p.omega, "re": p.re, "im": p.im,
                    "magnitude_db": p.magnitude_db, "phase_deg": p.phase_deg,
                })
            })
            .collect();
        let v = json!({
            "model": model, "rider": data.rider, "input": input, "output": output, "points": pts,
        });
        return serde_json::to_string(&v).map_err(|e| e.to_string());
    }
    if *csv {
        let mut s = String::from("speed,omega,re,im,magnitude_db,phase_deg\n");
        for p in &points {
            let FrequencyPoint { speed, omega, re, im, magnitude_db, phase_deg } = p;
            s.push_str(&format!("{speed},{omega},{re},{im},{magnitude_db},{phase_deg}\n"));
        }
        return Ok(s);
    }
    let mut s = format!(
        "frequency response of {}: {} torque -> {}\n  speed [m/s]  omega [rad/s]  magnitude [dB]  phase [deg]\n",
        data.label(model),
        input,
        output
    );
    for p in &points {
        s.push_str(&format!(
            "{:>13} {:>14.6} {:>15.4} {:>12.3}\n",
            p.speed, p.omega, p.magnitude_db, p.phase_deg
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
        let a = parse::<Args>(&[
            "bode",
            "--model",
            "benchmark",
            "--speed",
            "2,5",
            "--input",
            "steer",
            "--output",
            "roll-rate",
            "--omega",
            "1,10",
        ])
        .expect("parses");
        assert_eq!((a.input.as_str(), a.output.as_str()), ("steer", "roll-rate"));
        assert_eq!((a.speed, a.omega), (vec![2.0, 5.0], vec![1.0, 10.0]));
        assert_eq!(a.omega_range.0.len(), 61);
        let base = ["bode", "--model", "b", "--speed", "5", "--input", "roll", "--output", "roll"];
        let with = |extra: &[&str]| parse::<Args>(&[&base[..], extra].concat());
        let e = with(&["--omega", "0"]).unwrap_err();
        assert!(e.contains("invalid value '0' for '--omega <W>': must be positive"), "{e}");
        let e = with(&["--omega-range", "1:10"]).unwrap_err();
        assert!(e.contains("expected FROM:TO:N"), "{e}");
        let e = with(&["--omega-range", "10:1:5"]).unwrap_err();
        assert!(e.contains("FROM 10 exceeds TO 1"), "{e}");
        let e = with(&["--omega-range", "1:10:0"]).unwrap_err();
        assert!(e.contains("the count 0 must lie between 1 and 1000000"), "{e}");
        let e = with(&["--omega", "1", "--omega-range", "1:10:3"]).unwrap_err();
        assert!(e.contains("cannot be used with"), "{e}");
        let e = parse::<Args>(&[
            "bode", "--model", "b", "--speed", "5", "--input", "yaw", "--output", "roll",
        ])
        .unwrap_err();
        assert!(e.contains("invalid value 'yaw' for '--input <INPUT>'"), "{e}");
        assert!(e.contains("[possible values: roll, steer, lean]"), "{e}");
    }

    #[test]
    fn json_points_and_csv_rows_agree() {
        let mut a = parse::<Args>(&[
            "bode",
            "--model",
            "benchmark",
            "--speed",
            "3,6",
            "--input",
            "steer",
            "--output",
            "roll",
            "--omega-range",
            "0.5:50:5",
            "--json",
        ])
        .expect("parses");
        let v: serde_json::Value = serde_json::from_str(&run(&a).unwrap()).unwrap();
        let pts = v["points"].as_array().unwrap();
        assert_eq!(pts.len(), 10);
        assert_eq!((v["input"].as_str(), v["output"].as_str()), (Some("steer"), Some("roll")));
        a.json = false;
        a.csv = true;
        let csv = run(&a).unwrap();
        let rows: Vec<&str> = csv.lines().skip(1).collect();
        assert_eq!(rows.len(), 10);
        for (row, p) in rows.iter().zip(pts) {
            let cells: Vec<f64> = row.split(',').map(|c| c.parse().unwrap()).collect();
            for (k, key) in
                ["speed", "omega", "re", "im", "magnitude_db", "phase_deg"].iter().enumerate()
            {
                // serde_json's parser may round the last bit (no `float_roundtrip`).
                let j = p[key].as_f64().unwrap();
                assert!((cells[k] - j).abs() <= 2.0 * f64::EPSILON * j.abs(), "{key}");
            }
            let (re, im) = (cells[2], cells[3]);
            assert!((20.0 * re.hypot(im).log10() - cells[4]).abs() < 1e-12);
        }
    }
}
