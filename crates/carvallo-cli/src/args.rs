//! Argument helpers shared by the subcommands: every option at most once, an unknown argument
//! or a missing value named in the error, numbers that must parse and be finite, and the
//! bicycle that `--model benchmark|FILE` names, with `--rider FILE` and `--strict`.

use carvallo::parameter_text::{add_rider, Loaded, Rider, UncertainParams};
use carvallo::whipple::WhippleParams;

/// The finite number `v` given for the quantity `name`.
pub fn number(name: &str, v: &str) -> Result<f64, String> {
    let x: f64 = v.parse().map_err(|_| format!("invalid {name} `{v}`"))?;
    if !x.is_finite() {
        return Err(format!("invalid {name} `{v}`: must be finite"));
    }
    Ok(x)
}

/// The lean angle `v` in degrees for the quantity `name`: a finite number strictly between
/// -90 and 90.
pub fn lean_deg(name: &str, v: &str) -> Result<f64, String> {
    let x = number(name, v)?;
    if x.abs() >= 90.0 {
        return Err(format!("invalid {name} `{x}`: must lie strictly between -90 and 90 degrees"));
    }
    Ok(x)
}

/// Splits `words` (what follows the subcommand) into `(option, value)` pairs in order. An option
/// listed in `valued` takes the next word as its value; one in `flags` takes none (its value is
/// empty). Anything else, an option given twice or a valued option at the end is an error that
/// names it.
pub fn options<'a>(
    words: &'a [String],
    valued: &[&str],
    flags: &[&str],
) -> Result<Vec<(&'a str, &'a str)>, String> {
    let mut out: Vec<(&str, &str)> = Vec::new();
    let mut it = words.iter();
    while let Some(arg) = it.next() {
        let a = arg.as_str();
        let takes_value = valued.contains(&a);
        if !takes_value && !flags.contains(&a) {
            return Err(format!("unknown argument `{arg}`"));
        }
        if out.iter().any(|(seen, _)| *seen == a) {
            return Err(format!("argument `{arg}` given more than once"));
        }
        let value = if takes_value {
            it.next().ok_or(format!("missing value after `{arg}`"))?.as_str()
        } else {
            ""
        };
        out.push((a, value));
    }
    Ok(out)
}

/// The bicycle `benchmark` (no uncertainty) or the one in the parameter file `model`: the
/// anchors TOML format or BicycleParameters' text format `name = value+/-sigma`
/// ([`UncertainParams::from_any`]).
pub fn uncertain_model(model: &str) -> Result<UncertainParams, String> {
    if model == "benchmark" {
        return Ok(UncertainParams::exact(WhippleParams::benchmark()));
    }
    let text = read_model_file(model)?;
    UncertainParams::from_any(&text).map_err(|e| format!("invalid model file `{model}`: {e}"))
}

/// The options beside `--model` that say how its file is read: `--rider FILE` (a
/// BicycleParameters rider file added to the rear frame, [`add_rider`]) and `--strict` (moments
/// of inertia breaking a triangle inequality are an error instead of a warning).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DataOptions {
    /// The rider file, if any.
    pub rider: Option<String>,
    /// Whether a broken triangle inequality is an error.
    pub strict: bool,
}

impl DataOptions {
    /// Takes `arg` if it is `--rider` (its value the next word of `rest`) or `--strict`:
    /// `Ok(true)` when taken, `Ok(false)` for another argument, an error for a repeated option
    /// or a missing value.
    pub fn take<'a>(
        &mut self,
        arg: &str,
        rest: &mut impl Iterator<Item = &'a String>,
    ) -> Result<bool, String> {
        match arg {
            "--strict" if self.strict => Err("argument `--strict` given more than once".into()),
            "--strict" => {
                self.strict = true;
                Ok(true)
            }
            "--rider" if self.rider.is_some() => {
                Err("argument `--rider` given more than once".into())
            }
            "--rider" => {
                self.rider = Some(rest.next().ok_or("missing value after `--rider`")?.clone());
                Ok(true)
            }
            _ => Ok(false),
        }
    }

    /// Whether any is given.
    pub fn any(&self) -> bool {
        self.rider.is_some() || self.strict
    }
}

/// The bicycle `benchmark` or the one in the parameter file `model` read as `data` says: with
/// its rider added, and broken triangle inequalities printed as warnings on standard error
/// (errors with `--strict`).
pub fn bicycle(model: &str, data: &DataOptions) -> Result<WhippleParams, String> {
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
    for w in &loaded.warnings {
        eprintln!("warning: {model}: {w}");
    }
    Ok(loaded.params.params)
}

/// Whether `message` (an error of a command) is about the data of a file rather than the
/// command line: it is printed without the usage text. The messages of [`bicycle`] and
/// [`uncertain_model`] start so.
pub fn is_data_error(message: &str) -> bool {
    [
        "invalid model file `",
        "cannot read model file `",
        "invalid rider file `",
        "cannot read rider file `",
    ]
    .iter()
    .any(|p| message.starts_with(p))
}

/// The bicycle `benchmark` or the one in the TOML parameter file `model` (the anchors format
/// only), for `accel` and `simulate`.
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

/// `list` as owned words, as the command line gives them (for the subcommands' tests).
#[cfg(test)]
pub fn words(list: &[&str]) -> Vec<String> {
    list.iter().map(|s| s.to_string()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn options_in_order_and_errors_named() {
        let w = words(&["--theta", "20", "--json", "--gamma", "-5"]);
        assert_eq!(
            options(&w, &["--theta", "--gamma"], &["--json"]),
            Ok(vec![("--theta", "20"), ("--json", ""), ("--gamma", "-5")])
        );
        let err = |list: &[&str]| options(&words(list), &["--theta"], &["--json"]).unwrap_err();
        assert_eq!(err(&["--lean", "5"]), "unknown argument `--lean`");
        assert_eq!(err(&["--json", "--json"]), "argument `--json` given more than once");
        assert_eq!(err(&["--theta"]), "missing value after `--theta`");
        assert_eq!(number("theta", "2.5"), Ok(2.5));
        assert_eq!(number("theta", "five"), Err("invalid theta `five`".into()));
        assert_eq!(number("theta", "inf"), Err("invalid theta `inf`: must be finite".into()));
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
