//! `carvallo eig --model benchmark|FILE.toml --speed V[,V...] [--json]`: the four eigenvalues of
//! the linearised Carvallo–Whipple bicycle at each speed V, as JSON
//! `{ "model", "rider", "speed", "eigenvalues": [{"re", "im"}, ...], "modes": [...] }` for one
//! speed and a list of such objects for several (`rider` is the rider file or null; the text's
//! header names the rider too); each mode is
//! `{"label", "re", "im", "vector", "steer_lean_ratio", "phase_deg"}` with the label weave,
//! capsize or caster found by continuation in speed ([`carvallo::whipple::modes`]), the unit
//! eigenvector `[{"re", "im"}, ...]` of (lean, steer, lean rate, steer rate); `modes` is empty
//! if the labels cannot be followed (no speed with one complex pair and two real roots).
//!
//! With `--gain NAME=VALUE ...` the eigenvalues are those of the closed loop $A - BK$ of the
//! state feedback $u = -Kx$ (gains as in [`crate::gains`]); the JSON adds `"gains"` and its
//! `modes` is empty (the labels follow the open loop).
//!
//! The parameter file is read as for `window` ([`crate::args::bicycle`], with `--rider FILE` and `--strict`). Unknown or missing
//! arguments, a speed that is not a finite number and an unreadable or invalid parameter file
//! are usage errors: a message naming the value, exit code 2.

use carvallo::whipple::modes::Mode;
use carvallo::whipple::Whipple;

use crate::args::DataOptions;
use serde_json::{json, Value};

/// `carvallo eig`: the eigenvalues of the linearised bicycle at one speed.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: `benchmark` or a parameter file (the anchors' TOML or BicycleParameters'
    /// `name = value+/-sigma` text); or Moore's leaning rider: `lean-rider` (Browser + Jason)
    /// or a file in Moore's names
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: DataOptions,
    /// The forward speeds (m/s), separated by commas
    #[arg(long, value_name = "V", required = true, value_delimiter = ',',
          value_parser = crate::args::SPEED.parser(), allow_hyphen_values = true)]
    pub speed: Vec<f64>,
    /// Print JSON `{model, rider, speed, eigenvalues: [{re, im}, ...], modes: [...]}` instead of
    /// text (a list of them for several speeds)
    #[arg(long)]
    pub json: bool,
    /// A gain of the state feedback u = -K x (as for `window --gain`): the eigenvalues of the
    /// closed loop A - B K
    #[arg(long, value_name = "NAME=VALUE", value_parser = crate::gains::parse_gain, allow_hyphen_values = true)]
    pub gain: Vec<crate::gains::GainValue>,
}

/// One mode: its label, eigenvalue and unit eigenvector (lean, steer, lean rate, steer rate),
/// with the steer-to-lean amplitude ratio and phase.
fn mode_json(m: &Mode) -> Value {
    let c = |z: &nalgebra::Complex<f64>| json!({ "re": z.re, "im": z.im });
    json!({
        "label": m.label.name(),
        "re": m.eigenvalue.re,
        "im": m.eigenvalue.im,
        "vector": m.vector.iter().map(c).collect::<Vec<_>>(),
        "steer_lean_ratio": m.steer_lean_ratio(),
        "phase_deg": m.phase_deg(),
    })
}

/// Runs `carvallo eig`: the text to print, or an error naming the bad value.
pub fn run(cmd: &Args) -> Result<String, String> {
    if let Some(rider) = crate::args::lean_rider(&cmd.model, &cmd.data)? {
        let k = crate::gains::lean_gains_of(&cmd.gain)?;
        return super::lean_rider::eig(&cmd.model, &rider, &k, &cmd.speed, cmd.json);
    }
    crate::gains::bicycle_only(&cmd.gain)?;
    let bike = Whipple::new(crate::args::bicycle(&cmd.model, &cmd.data)?);
    let mut texts = Vec::new();
    let mut values = Vec::new();
    for &v in &cmd.speed {
        let (text, value) = at_speed(cmd, &bike, v);
        texts.push(text);
        values.push(value);
    }
    if cmd.json {
        let v = if values.len() == 1 { values.remove(0) } else { Value::Array(values) };
        return serde_json::to_string_pretty(&v).map_err(|e| e.to_string());
    }
    Ok(texts.concat())
}

/// The text and the JSON value of one speed.
fn at_speed(cmd: &Args, bike: &Whipple, v: f64) -> (String, Value) {
    let Args { model, data, gain, .. } = cmd;
    let speed = &v;
    let rider = json!(data.rider);
    let of = match &data.rider {
        Some(_) => format!(" of {}", data.label(model)),
        None => String::new(),
    };
    if !gain.is_empty() {
        let k = crate::gains::gains_of(gain);
        let ev = bike.closed_loop_eigenvalues(*speed, &k);
        let list: Vec<Value> = ev.iter().map(|e| json!({ "re": e.re, "im": e.im })).collect();
        let v = json!({
            "model": model,
            "rider": rider,
            "speed": speed,
            "gains": crate::gains::gains_json(&k),
            "eigenvalues": list,
            "modes": [],
        });
        let mut s = format!(
            "closed-loop eigenvalues{of} at {speed} m/s, gains {}:\n",
            crate::gains::gains_text(&k)
        );
        for e in &ev {
            s.push_str(&format!("{} {:+}i\n", e.re, e.im));
        }
        return (s, v);
    }
    let ev = bike.eigenvalues(*speed);
    let value = if cmd.json {
        let list: Vec<Value> = ev.iter().map(|e| json!({ "re": e.re, "im": e.im })).collect();
        let modes: Vec<Value> = bike
            .modes(&[*speed])
            .and_then(|m| m.into_iter().next())
            .map_or(Vec::new(), |m| m.iter().map(mode_json).collect());
        json!({ "model": model, "rider": rider, "speed": speed, "eigenvalues": list, "modes": modes })
    } else {
        Value::Null
    };
    let mut s = format!("eigenvalues{of} at {speed} m/s:\n");
    for e in &ev {
        s.push_str(&format!("{} {:+}i\n", e.re, e.im));
    }
    (s, value)
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
                speed: vec![5.0],
                json: false,
                gain: Vec::new(),
            })
        );
        assert_eq!(
            parse::<Args>(&["eig", "--speed", "-1", "--model", "b"]).map(|a| a.speed),
            Ok(vec![-1.0])
        );
        assert_eq!(
            parse::<Args>(&["eig", "--speed", "2,5", "--model", "b"]).map(|a| a.speed),
            Ok(vec![2.0, 5.0])
        );
        let e = parse::<Args>(&["eig", "--model", "x", "--speed", "2,fast"]).unwrap_err();
        assert!(e.contains("invalid value 'fast'"), "{e}");
        let e = parse::<Args>(&["eig", "--model", "x", "--speed", "fast"]).unwrap_err();
        assert!(
            e.starts_with("error: invalid value 'fast' for '--speed <V>': not a number"),
            "{e}"
        );
        let e = parse::<Args>(&["eig", "--model", "benchmark"]).unwrap_err();
        assert!(e.contains("--speed <V>"), "{e}");
    }

    #[test]
    fn a_gain_gives_the_roots_of_the_closed_loop_polynomial() {
        let a = parse::<Args>(&[
            "eig",
            "--model",
            "benchmark",
            "--speed",
            "3",
            "--gain",
            "k_steer_roll_rate=-10",
            "--json",
        ])
        .expect("parses");
        let v: Value = serde_json::from_str(&run(&a).unwrap()).unwrap();
        assert_eq!(v["gains"]["k_steer_roll_rate"], -10.0);
        // The independent route: Aberth's roots of the generated closed-loop polynomial.
        let bike = Whipple::new(carvallo::whipple::WhippleParams::benchmark());
        let k = carvallo::whipple::feedback::Gains::balance_assist(10.0);
        let roots = carvallo::quartic::aberth_compensated(&bike.closed_loop_poly(&k).at(3.0));
        for e in v["eigenvalues"].as_array().unwrap() {
            let (re, im) = (e["re"].as_f64().unwrap(), e["im"].as_f64().unwrap());
            let d = roots.iter().map(|z| (z.re - re).hypot(z.im - im)).fold(f64::MAX, f64::min);
            assert!(d < 1e-9, "{re} {im}i: {roots:?}");
            assert!(re < 0.0, "stable at 3 m/s with the assist: {v}");
        }
    }

    #[test]
    fn json_keeps_its_keys_and_adds_labelled_modes() {
        let a = Args {
            model: "benchmark".into(),
            data: DataOptions::default(),
            speed: vec![5.0],
            json: true,
            gain: Vec::new(),
        };
        let v: Value = serde_json::from_str(&run(&a).unwrap()).unwrap();
        assert_eq!(v["speed"], 5.0);
        assert_eq!(v["eigenvalues"].as_array().map(Vec::len), Some(4));
        let modes = v["modes"].as_array().unwrap();
        let labels: Vec<&str> = modes.iter().filter_map(|m| m["label"].as_str()).collect();
        assert_eq!(labels, ["weave", "weave", "capsize", "caster"]);
        // Caster at 5 m/s: -14.0784 (Meijaard et al. 2007, Table 2); every mode's eigenvalue
        // is one of the listed eigenvalues.
        assert!((modes[3]["re"].as_f64().unwrap() + 14.078389692798247).abs() < 1e-11);
        for m in modes {
            assert!(v["eigenvalues"].as_array().unwrap().iter().any(|e| {
                (e["re"].as_f64().unwrap() - m["re"].as_f64().unwrap()).abs() < 1e-12
                    && (e["im"].as_f64().unwrap() - m["im"].as_f64().unwrap()).abs() < 1e-12
            }));
            assert_eq!(m["vector"].as_array().map(Vec::len), Some(4));
        }
    }
}
