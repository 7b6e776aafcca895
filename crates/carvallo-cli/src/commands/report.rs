//! `carvallo report [--json]`, `carvallo report --claims [--json]` and `carvallo report --out
//! DIR [--model benchmark|FILE]`: the memoir concordance.
//!
//! `report` prints it as an aligned text table, `report --json` as a JSON array of objects with
//! the keys `section`, `quantity`, `memoir`, `derived`, `rel_diff`, `verdict` and `note`;
//! `report --claims` prints the memoir's claims checked (claim, how checked, evidence, verdict,
//! note; `carvallo_report::claims`) and the count of the memoir's assertions, `--claims --json`
//! them as a JSON array with the keys `id`, `section`, `claim`, `how`, `evidence`, `verdict`,
//! `note`;
//! `report --out DIR` writes the report directory ([`crate::report_dir`]) and prints the paths
//! it wrote; `report --out DIR --model FILE [--rider FILE] [--strict]` writes the report of that
//! bicycle alone (its window, geometry, eigenvalues against speed and uncertainty, naming the
//! file and rider read; [`report_dir::write_bicycle_report`]) without the memoir's chapters,
//! which `--memoir` adds back (the whole report, its bicycle figures drawn for FILE). The
//! bicycle figures are titled and their files named after the bicycle
//! ([`crate::args::bicycle_name`]: `BrowserBenchmark.txt` with `JasonBrowserBenchmark.txt` is
//! `Browser + Jason`, its figures `browser_jason_*.svg`).
//!
//! A bad command line is a usage error of clap; an unusable output directory or model file is a
//! [`BadInput`](crate::report_dir::BadInput), found before anything is written; both exit with
//! code 2, a failure while writing with code 1.

use crate::report_dir;

/// `carvallo report`: the memoir concordance, its claims, or the report directory.
#[derive(Clone, Debug, Default, PartialEq, Eq, clap::Args)]
pub struct Args {
    /// Print JSON: the concordance as an array of {section, quantity, memoir, derived,
    /// rel_diff, verdict, note}, or with --claims the claims as an array
    #[arg(long, conflicts_with = "out")]
    pub json: bool,
    /// Print the memoir's claims checked: claim, how checked, evidence, verdict
    #[arg(long, conflicts_with = "out")]
    pub claims: bool,
    /// Write DIR/report.md, DIR/report.html (concordance, errata; or the report of the bicycle
    /// of --model) and the SVG figures
    #[arg(long, value_name = "DIR")]
    pub out: Option<String>,
    /// The bicycle: `benchmark` (the whole report) or a parameter file, whose report alone is
    /// written (window, eigenvalues against speed; stated uncertainties add their propagation
    /// and the eigenvalues with uncertainty bands)
    #[arg(long, value_name = "MODEL", requires = "out")]
    pub model: Option<String>,
    /// A BicycleParameters rider file (`name = value+/-sigma`) whose rider is added to the rear
    /// frame of the bicycle of --model
    #[arg(long, value_name = "FILE.txt", requires = "model")]
    pub rider: Option<String>,
    /// A moment of inertia of --model breaking a triangle inequality is an error instead of a
    /// warning
    #[arg(long, requires = "model")]
    pub strict: bool,
    /// With --model: write the whole report, the memoir's chapters with the bicycle figures of
    /// --model, instead of the report of that bicycle alone
    #[arg(long, requires = "model")]
    pub memoir: bool,
}

/// What `carvallo report ...` asks for.
#[derive(Debug, PartialEq, Eq)]
enum Command {
    Print { json: bool },
    Claims { json: bool },
    Write { dir: String, model: String, rider: Option<String>, strict: bool, memoir: bool },
}

impl Args {
    fn command(&self) -> Command {
        match &self.out {
            Some(dir) => Command::Write {
                dir: dir.clone(),
                model: self.model.clone().unwrap_or_else(|| "benchmark".into()),
                rider: self.rider.clone(),
                strict: self.strict,
                memoir: self.memoir,
            },
            None if self.claims => Command::Claims { json: self.json },
            None => Command::Print { json: self.json },
        }
    }
}

/// Runs `carvallo report`: the text to print as it is, or the error (a
/// [`BadInput`](report_dir::BadInput) or a failure to write).
pub fn run(args: &Args) -> anyhow::Result<String> {
    match args.command() {
        Command::Write { dir, model, rider, strict, memoir } => {
            let data =
                crate::args::DataOptions { rider: rider.clone(), strict, ..Default::default() };
            let (params, warnings) =
                crate::args::uncertain_bicycle(&model, &data).map_err(report_dir::BadInput)?;
            let path = std::path::Path::new(&dir);
            let skate = ["rR", "rF"].iter().find(|r| params.params.get(r) == Some(0.0));
            if let (true, Some(r)) = (memoir, skate) {
                return Err(report_dir::BadInput(format!(
                    "invalid model file `{model}` for --memoir: the whole report simulates the \
                     nonlinear bicycle, which needs wheels of positive radius ({r} = 0, the \
                     two-mass-skate); the report of this bicycle alone (without --memoir) takes \
                     the limit"
                ))
                .into());
            }
            let name = crate::args::bicycle_name(&model, rider.as_deref());
            let files = if memoir || (model == "benchmark" && rider.is_none()) {
                report_dir::write_report(path, &params, &model, &name)?
            } else {
                let view = crate::args::side_view(&model, &data).map_err(report_dir::BadInput)?;
                report_dir::write_bicycle_report(
                    path,
                    &params,
                    &model,
                    rider.as_deref(),
                    &view,
                    &warnings,
                )?
            };
            Ok(files.iter().map(|f| format!("{dir}/{f}\n")).collect())
        }
        Command::Claims { json } => {
            let claims = carvallo_report::all_claims();
            Ok(if json {
                format!("{}\n", carvallo_report::claims::render_claims_json(&claims))
            } else {
                let summary = carvallo_report::render::markdown::claims_summary(
                    &claims,
                    &carvallo_report::all_assertions(),
                );
                format!("{}{summary}\n", carvallo_report::claims::render_claims_text(&claims))
            })
        }
        Command::Print { json } => {
            let entries = carvallo_report::all_entries();
            Ok(if json {
                format!("{}\n", serde_json::to_string_pretty(&entries)?)
            } else {
                carvallo_report::render_text(&entries)
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    fn command(words: &[&str]) -> Result<Command, String> {
        parse::<Args>(&[&["report"], words].concat()).map(|a| a.command())
    }

    #[test]
    fn parses_the_printed_and_the_written_report() {
        assert_eq!(command(&[]), Ok(Command::Print { json: false }));
        assert_eq!(command(&["--json"]), Ok(Command::Print { json: true }));
        assert_eq!(command(&["--claims"]), Ok(Command::Claims { json: false }));
        assert_eq!(command(&["--json", "--claims"]), Ok(Command::Claims { json: true }));
        let e = command(&["--claims", "--out", "r"]).unwrap_err();
        assert!(e.contains("'--claims' cannot be used with '--out <DIR>'"), "{e}");
        let write = |model: &str, rider: Option<&str>, strict: bool, memoir: bool| Command::Write {
            dir: "r".into(),
            model: model.into(),
            rider: rider.map(String::from),
            strict,
            memoir,
        };
        assert_eq!(command(&["--out", "r"]), Ok(write("benchmark", None, false, false)));
        assert_eq!(
            command(&["--model", "b.toml", "--out", "r"]),
            Ok(write("b.toml", None, false, false))
        );
        assert_eq!(
            command(&[
                "--out", "r", "--model", "b.txt", "--rider", "j.txt", "--strict", "--memoir"
            ]),
            Ok(write("b.txt", Some("j.txt"), true, true))
        );
    }

    #[test]
    fn rejects_unknown_arguments_by_name() {
        for (words, msg) in [
            (&["--jsn"][..], "unexpected argument '--jsn' found"),
            (&["--json", "--json"], "'--json' cannot be used multiple times"),
            (&["--out"], "a value is required for '--out <DIR>'"),
            (&["--out", "a", "--out", "b"], "'--out <DIR>' cannot be used multiple times"),
            (&["--json", "--out", "a"], "'--json' cannot be used with '--out <DIR>'"),
            (&["--model", "b.toml"], "--out <DIR>"),
            (&["--out", "r", "--rider", "j.txt"], "--model <MODEL>"),
            (&["--out", "r", "--memoir"], "--model <MODEL>"),
        ] {
            let e = command(words).unwrap_err();
            assert!(e.contains(msg), "{words:?}: {e}");
        }
    }
}
