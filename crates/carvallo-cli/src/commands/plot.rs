//! `carvallo plot geometry|eigenvalues|bode --model benchmark|FILE [--model ...] [--rider FILE
//! ...] [--out FILE.svg]`: one figure of one bicycle, or of several compared, as SVG
//! ([`crate::figures`]): the side view of the geometry (wheels, schematic frame and fork, steer
//! axis and trail, mass centres, the rider's apart), the eigenvalues against speed labelled by
//! mode (weave, capsize, caster), or the Bode diagram (magnitude and phase against ω on a
//! logarithmic axis labelled by decades) from `--input` to `--output` at each `--speed`.
//! `eigenvalues --model lean-rider` (or a file in Moore's names) draws the leaning rider's six
//! roots labelled as [`carvallo::whipple::lean_rider::LeanRider::modes`] labels them, the
//! torso's beside the weave, capsize and caster (`--v-max` 10 m/s by default).
//!
//! `--model` and `--rider` repeat: the bicycles drawn are each model alone (no rider), each
//! model with the rider of the same rank (as many riders as models), one model with each rider,
//! or each model with the one rider. `eigenvalues` draws one bicycle. The figure is titled by
//! the bicycles' names ([`crate::args::bicycle_name`]: `BrowserBenchmark.txt` with
//! `JasonBrowserBenchmark.txt` is `Browser + Jason`) and written to `--out`, by default to
//! `NAME_FIGURE.svg` in the current directory after the first bicycle's name (`browser_jason_bode.svg`);
//! the path written is printed.

use carvallo::whipple::transfer::{Input, Output};
use clap::builder::{PossibleValuesParser, TypedValueParser as _};

use crate::args::{bicycle, bicycle_name, file_stem_of, side_view, DataOptions};
use crate::commands::bode::{omega_range, Frequencies};
use crate::figures;

/// Which figure.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Figure {
    /// The side view of the geometry
    Geometry,
    /// The eigenvalues against speed, labelled by mode
    Eigenvalues,
    /// The Bode diagram (magnitude and phase)
    Bode,
}

impl Figure {
    fn name(self) -> &'static str {
        match self {
            Figure::Geometry => "geometry",
            Figure::Eigenvalues => "eigenvalues",
            Figure::Bode => "bode",
        }
    }
}

/// `carvallo plot`: a figure of one bicycle or several.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The figure
    #[arg(value_enum)]
    pub figure: Figure,
    /// A bicycle: `benchmark` or a parameter file; repeat to compare bicycles. `eigenvalues`
    /// also draws Moore's leaning rider: `lean-rider` (Browser + Jason) or a file in Moore's
    /// names, its torso's mode beside the bicycle's
    #[arg(long, value_name = "MODEL", required = true)]
    pub model: Vec<String>,
    /// A BicycleParameters rider file (`name = value+/-sigma`) added to the rear frame; repeat
    /// to compare riders (one per --model, or several on one --model)
    #[arg(long, value_name = "FILE.txt")]
    pub rider: Vec<String>,
    /// A moment of inertia breaking a triangle inequality is an error instead of a warning
    #[arg(long)]
    pub strict: bool,
    /// The forward speeds of the Bode diagram (m/s), separated by commas
    #[arg(long, value_name = "V", value_delimiter = ',', default_value = "5",
          value_parser = crate::args::SPEED.parser(), allow_hyphen_values = true)]
    pub speed: Vec<f64>,
    /// The input of the Bode diagram: the roll or the steer torque
    #[arg(long, value_name = "INPUT", default_value = "steer",
          value_parser = PossibleValuesParser::new(["roll", "steer"]).try_map(|s| s.parse::<Input>()))]
    pub input: Input,
    /// The output of the Bode diagram: the lean (roll) or steer angle or its rate
    #[arg(long, value_name = "OUTPUT", default_value = "roll",
          value_parser = PossibleValuesParser::new(["roll", "steer", "roll-rate", "steer-rate"])
              .try_map(|s| s.parse::<Output>()))]
    pub output: Output,
    /// N angular frequencies (rad/s) of the Bode diagram spaced logarithmically from FROM to TO
    #[arg(long, value_name = "FROM:TO:N", value_parser = omega_range, default_value = "0.1:100:301")]
    pub omega_range: Frequencies,
    /// The top of the speed axis of the eigenvalues in m/s (default: 10, or 1.25 times the
    /// capsize speed up to 30)
    #[arg(long, value_name = "V", value_parser = top_speed)]
    pub v_max: Option<f64>,
    /// The SVG file to write (default: NAME_FIGURE.svg in the current directory, after the
    /// first bicycle's name)
    #[arg(long, value_name = "FILE.svg")]
    pub out: Option<String>,
}

/// The top of the eigenvalue figure's speed axis: positive, at most 1000 m/s.
fn top_speed(v: &str) -> Result<f64, String> {
    let x = crate::args::finite(v)?;
    if !(x > 0.0 && x <= 1000.0) {
        return Err("must lie within (0, 1000] m/s".into());
    }
    Ok(x)
}

/// The bicycles drawn: (model, rider) pairs, as the module docs pair them.
fn pairs(models: &[String], riders: &[String]) -> Result<Vec<(String, Option<String>)>, String> {
    let (n, m) = (models.len(), riders.len());
    Ok(match (n, m) {
        (_, 0) => models.iter().map(|b| (b.clone(), None)).collect(),
        (1, _) => riders.iter().map(|r| (models[0].clone(), Some(r.clone()))).collect(),
        (_, 1) => models.iter().map(|b| (b.clone(), Some(riders[0].clone()))).collect(),
        _ if n == m => {
            models.iter().zip(riders).map(|(b, r)| (b.clone(), Some(r.clone()))).collect()
        }
        _ => {
            return Err(format!(
                "{n} --model and {m} --rider do not pair: give one rider for every model, one \
                 model with several riders, or several models with one rider"
            ))
        }
    })
}

/// Runs `carvallo plot`: the path written, or an error naming the bad value.
pub fn run(args: &Args) -> Result<String, String> {
    let bikes = pairs(&args.model, &args.rider)?;
    let data = |rider: &Option<String>| DataOptions {
        rider: rider.clone(),
        strict: args.strict,
        ..DataOptions::default()
    };
    let names: Vec<String> = bikes.iter().map(|(b, r)| bicycle_name(b, r.as_deref())).collect();
    let svg = match args.figure {
        Figure::Geometry => {
            let mut views = Vec::new();
            for ((b, r), name) in bikes.iter().zip(&names) {
                views.push((name.clone(), side_view(b, &data(r))?));
            }
            figures::fig_geometry(&views)
        }
        Figure::Eigenvalues => {
            let [(b, r)] = &bikes[..] else {
                return Err(format!(
                    "eigenvalues draws one bicycle, not {}: give one --model and at most one \
                     --rider",
                    bikes.len()
                ));
            };
            if let Some(rider) = crate::args::lean_rider(b, &data(r))? {
                let v_max = args.v_max.unwrap_or(10.0);
                figures::fig_rider_modes(&rider, &names[0], v_max)
            } else {
                let p = bicycle(b, &data(r))?;
                let v_max = args.v_max.unwrap_or_else(|| {
                    let window = carvallo::whipple::Whipple::new(p.clone()).stability_window();
                    window.capsize_speed.map_or(10.0, |c| (1.25 * c).clamp(10.0, 30.0).ceil())
                });
                figures::fig_modes(&p, &names[0], v_max)
            }
        }
        Figure::Bode => {
            let mut params = Vec::new();
            for ((b, r), name) in bikes.iter().zip(&names) {
                params.push((name.clone(), bicycle(b, &data(r))?));
            }
            figures::fig_bode(&params, &args.speed, &args.omega_range.0, args.input, args.output)
        }
    }
    .map_err(|e| format!("cannot draw the figure: {e:#}"))?;
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| format!("{}_{}.svg", file_stem_of(&names[0]), args.figure.name()));
    std::fs::write(&out, svg)
        .map_err(|e| format!("cannot write --out `{out}`: {}", e.to_string().to_lowercase()))?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn models_and_riders_pair_by_rank_or_one_with_each() {
        let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
        let some = |b: &str, r: &str| (b.to_string(), Some(r.to_string()));
        assert_eq!(pairs(&s(&["a", "b"]), &[]).unwrap(), [("a".into(), None), ("b".into(), None)]);
        assert_eq!(pairs(&s(&["a"]), &s(&["x", "y"])).unwrap(), [some("a", "x"), some("a", "y")]);
        assert_eq!(pairs(&s(&["a", "b"]), &s(&["x"])).unwrap(), [some("a", "x"), some("b", "x")]);
        assert_eq!(
            pairs(&s(&["a", "b"]), &s(&["x", "y"])).unwrap(),
            [some("a", "x"), some("b", "y")]
        );
        let e = pairs(&s(&["a", "b"]), &s(&["x", "y", "z"])).unwrap_err();
        assert!(e.starts_with("2 --model and 3 --rider do not pair"), "{e}");
    }

    #[test]
    fn parses_repeated_models_and_rejects_bad_values_by_name() {
        let a = parse::<Args>(&[
            "plot",
            "bode",
            "--model",
            "benchmark",
            "--model",
            "b.txt",
            "--speed",
            "4,6",
        ])
        .expect("parses");
        assert_eq!((a.figure, a.model.len(), a.speed), (Figure::Bode, 2, vec![4.0, 6.0]));
        assert_eq!((a.input, a.output, a.omega_range.0.len()), (Input::Steer, Output::Roll, 301));
        let e = parse::<Args>(&["plot", "bode"]).unwrap_err();
        assert!(e.contains("--model <MODEL>"), "{e}");
        let e = parse::<Args>(&["plot", "bode", "--model", "b", "--v-max", "0"]).unwrap_err();
        assert!(
            e.contains("invalid value '0' for '--v-max <V>': must lie within (0, 1000]"),
            "{e}"
        );
        let e = parse::<Args>(&["plot", "sketch", "--model", "b"]).unwrap_err();
        assert!(e.contains("[possible values: geometry, eigenvalues, bode]"), "{e}");
        let a =
            parse::<Args>(&["plot", "eigenvalues", "--model", "benchmark", "--model", "benchmark"])
                .unwrap();
        let e = run(&a).unwrap_err();
        assert!(e.starts_with("eigenvalues draws one bicycle, not 2"), "{e}");
    }
}
