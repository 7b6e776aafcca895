//! Argument helpers shared by the subcommands: the value parsers clap calls (numbers that must
//! parse and be finite), the options `--rider FILE` and `--strict`, and the bicycle that
//! `--model benchmark|FILE` names.

use carvallo::parameter_text::{add_rider, Loaded, Rider, UncertainParams};
use carvallo::whipple::WhippleParams;

/// A finite number, for clap's `value_parser` (the error names the value with its option).
pub fn finite(v: &str) -> Result<f64, String> {
    let x: f64 = v.parse().map_err(|_| "not a number".to_string())?;
    if !x.is_finite() {
        return Err("must be finite".into());
    }
    Ok(x)
}

/// A lean angle in degrees, for clap's `value_parser`: a finite number strictly between -90
/// and 90.
pub fn lean_deg(v: &str) -> Result<f64, String> {
    let x = finite(v)?;
    if x.abs() >= 90.0 {
        return Err("must lie strictly between -90 and 90 degrees".into());
    }
    Ok(x)
}

/// The options beside `--model` that say how its file is read: `--rider FILE` (a
/// BicycleParameters rider file added to the rear frame, [`add_rider`]) and `--strict` (moments
/// of inertia breaking a triangle inequality are an error instead of a warning).
#[derive(Clone, Debug, Default, PartialEq, clap::Args)]
pub struct DataOptions {
    /// A BicycleParameters rider file (`name = value+/-sigma`) whose rider is added to the rear
    /// frame
    #[arg(long, value_name = "FILE.txt")]
    pub rider: Option<String>,
    /// A moment of inertia breaking a triangle inequality is an error instead of a warning
    #[arg(long)]
    pub strict: bool,
}

impl DataOptions {
    /// Whether any is given.
    pub fn any(&self) -> bool {
        self.rider.is_some() || self.strict
    }
}

/// The bicycle `benchmark` or the one in the parameter file `model` read as `data` says: with
/// its rider added, and broken triangle inequalities printed as warnings on standard error
/// (errors with `--strict`).
pub fn bicycle(model: &str, data: &DataOptions) -> Result<WhippleParams, String> {
    uncertain_bicycle(model, data).map(|(u, _)| u.params)
}

/// As [`bicycle`], with the standard deviations the file states (carried through the rider)
/// and the warnings printed.
pub fn uncertain_bicycle(
    model: &str,
    data: &DataOptions,
) -> Result<(UncertainParams, Vec<String>), String> {
    let loaded = if model == "benchmark" {
        Loaded { params: UncertainParams::exact(WhippleParams::benchmark()), warnings: Vec::new() }
    } else {
        let text = read_model_file(model)?;
        let read = if text.lines().any(|l| l.trim_start().starts_with('[')) {
            UncertainParams::from_any(&text).map(|params| Loaded { params, warnings: Vec::new() })
        } else {
            UncertainParams::read(&text, data.strict)
        };
        read.map_err(|e| format!("invalid model file `{model}`: {e}"))?
    };
    let loaded = match &data.rider {
        None => loaded,
        Some(path) => {
            let text = std::fs::read_to_string(path).map_err(|e| {
                format!("cannot read rider file `{path}`: {}", e.to_string().to_lowercase())
            })?;
            let rider =
                Rider::from_text(&text).map_err(|e| format!("invalid rider file `{path}`: {e}"))?;
            add_rider(&loaded.params, &rider)
                .map_err(|e| format!("invalid rider file `{path}` on `{model}`: {e}"))?
        }
    };
    if data.strict {
        if let Some(w) = loaded.warnings.first() {
            return Err(format!(
                "invalid model file `{model}`: {} (--strict)",
                w.to_string().replace("; computed as given", "")
            ));
        }
    }
    let warnings: Vec<String> = loaded.warnings.iter().map(|w| format!("{model}: {w}")).collect();
    for w in &warnings {
        eprintln!("warning: {w}");
    }
    Ok((loaded.params, warnings))
}

/// Whether `message` (an error of a command) is about the data of a file rather than the
/// command line: it is printed without the usage text. The messages of [`bicycle`] and
/// [`uncertain_bicycle`] start so.
pub fn is_data_error(message: &str) -> bool {
    [
        "invalid model file `",
        "cannot read model file `",
        "invalid rider file `",
        "cannot read rider file `",
        "invalid gain table `",
        "cannot read gain table `",
        "invalid raw measurement file `",
        "cannot read raw measurement file `",
    ]
    .iter()
    .any(|p| message.starts_with(p))
}

/// The bicycle `benchmark` or the one in the TOML parameter file `model` (the anchors format
/// only), for `accel`.
pub fn toml_model(model: &str) -> Result<WhippleParams, String> {
    if model == "benchmark" {
        return Ok(WhippleParams::benchmark());
    }
    let text = read_model_file(model)?;
    WhippleParams::from_toml_str(&text).map_err(|e| format!("invalid model file `{model}`: {e}"))
}

/// The text of the parameter file `model`.
fn read_model_file(model: &str) -> Result<String, String> {
    std::fs::read_to_string(model)
        .map_err(|e| format!("cannot read model file `{model}`: {}", e.to_string().to_lowercase()))
}

/// Parses `words` (the command's name first) as the options `A` of one command, as the command
/// line would (for the subcommands' tests); the error is clap's message.
#[cfg(test)]
pub fn parse<A: clap::Args>(words: &[&str]) -> Result<A, String> {
    use clap::Parser as _;
    #[derive(clap::Parser)]
    struct One<A: clap::Args> {
        #[command(flatten)]
        args: A,
    }
    One::<A>::try_parse_from(words).map(|one| one.args).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_must_be_finite_and_leans_within_a_right_angle() {
        assert_eq!(finite("2.5"), Ok(2.5));
        assert_eq!(finite("five"), Err("not a number".into()));
        assert_eq!(finite("inf"), Err("must be finite".into()));
        assert_eq!(lean_deg("-89.9"), Ok(-89.9));
        assert_eq!(lean_deg("90"), Err("must lie strictly between -90 and 90 degrees".into()));
    }

    #[test]
    fn models_are_named_in_their_errors() {
        assert_eq!(bicycle("benchmark", &DataOptions::default()), Ok(WhippleParams::benchmark()));
        for e in [
            bicycle("/nonexistent/bike.toml", &DataOptions::default()).unwrap_err(),
            toml_model("/nonexistent/bike.toml").unwrap_err(),
        ] {
            assert!(e.starts_with("cannot read model file `/nonexistent/bike.toml`"), "{e}");
        }
    }
}
