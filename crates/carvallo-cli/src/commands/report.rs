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
//! it wrote.
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
    /// Write DIR/report.md, DIR/report.html (concordance, errata) and the SVG figures
    #[arg(long, value_name = "DIR")]
    pub out: Option<String>,
    /// The bicycle of the report's modern sections: `benchmark`, a parameter file; a
    /// BicycleParameters FILE.txt with uncertainties adds their propagation and the
    /// eigenvalues with uncertainty bands
    #[arg(long, value_name = "MODEL", requires = "out")]
    pub model: Option<String>,
}

/// What `carvallo report ...` asks for.
#[derive(Debug, PartialEq, Eq)]
enum Command {
    Print { json: bool },
    Claims { json: bool },
    Write { dir: String, model: String },
}

impl Args {
    fn command(&self) -> Command {
        match &self.out {
            Some(dir) => Command::Write {
                dir: dir.clone(),
                model: self.model.clone().unwrap_or_else(|| "benchmark".into()),
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
        Command::Write { dir, model } => {
            let params = crate::args::uncertain_model(&model).map_err(report_dir::BadInput)?;
            let files = report_dir::write_report(std::path::Path::new(&dir), &params, &model)?;
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
        assert_eq!(
            command(&["--out", "r"]),
            Ok(Command::Write { dir: "r".into(), model: "benchmark".into() })
        );
        assert_eq!(
            command(&["--model", "b.toml", "--out", "r"]),
            Ok(Command::Write { dir: "r".into(), model: "b.toml".into() })
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
        ] {
            let e = command(words).unwrap_err();
            assert!(e.contains(msg), "{words:?}: {e}");
        }
    }
}
