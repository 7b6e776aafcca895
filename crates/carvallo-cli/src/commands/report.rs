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
//! it wrote. Its usage is the whole help of `carvallo` (the table [`crate::COMMANDS`] says so).
//!
//! A bad command line is a [`UsageError`]; an unusable output directory or model file is a
//! [`BadInput`](crate::report_dir::BadInput), found before anything is written; both exit with
//! code 2, a failure while writing with code 1.

use crate::report_dir;
use crate::UsageError;

/// What `carvallo report ...` asks for.
#[derive(Debug, PartialEq, Eq)]
enum Command {
    Print { json: bool },
    Claims { json: bool },
    Write { dir: String, model: String },
}

fn parse(args: &[String]) -> Result<Command, UsageError> {
    let (mut json, mut claims, mut out, mut model) = (false, false, None, None);
    let mut it = args.iter().skip(1);
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--json" if json => return Err(UsageError::Repeated(arg.clone())),
            "--json" => json = true,
            "--claims" if claims => return Err(UsageError::Repeated(arg.clone())),
            "--claims" => claims = true,
            "--out" | "--model" => {
                let slot = if arg == "--out" { &mut out } else { &mut model };
                if slot.is_some() {
                    return Err(UsageError::Repeated(arg.clone()));
                }
                let value = it.next().ok_or_else(|| UsageError::MissingValue(arg.clone()))?;
                *slot = Some(value.clone());
            }
            _ => return Err(UsageError::Unknown(arg.clone())),
        }
    }
    match (out, model) {
        (Some(_), _) if json => Err(UsageError::Conflict("--json", "--out")),
        (Some(_), _) if claims => Err(UsageError::Conflict("--claims", "--out")),
        (None, Some(_)) if claims => Err(UsageError::Conflict("--model", "--claims")),
        (Some(dir), model) => {
            Ok(Command::Write { dir, model: model.unwrap_or_else(|| "benchmark".into()) })
        }
        (None, Some(_)) => Err(UsageError::Conflict("--model", "the printed report (use --out)")),
        (None, None) if claims => Ok(Command::Claims { json }),
        (None, None) => Ok(Command::Print { json }),
    }
}

/// Runs `carvallo report ARGS` (the argument list, the command's name first): the text to print
/// as it is, or the error (a [`UsageError`], a [`BadInput`](report_dir::BadInput) or a failure
/// to write).
pub fn main(args: &[String]) -> anyhow::Result<String> {
    match parse(args)? {
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

    use crate::args::words as args;

    #[test]
    fn parses_the_printed_and_the_written_report() {
        assert_eq!(parse(&args(&["report"])), Ok(Command::Print { json: false }));
        assert_eq!(parse(&args(&["report", "--json"])), Ok(Command::Print { json: true }));
        assert_eq!(parse(&args(&["report", "--claims"])), Ok(Command::Claims { json: false }));
        assert_eq!(
            parse(&args(&["report", "--json", "--claims"])),
            Ok(Command::Claims { json: true })
        );
        assert_eq!(
            parse(&args(&["report", "--claims", "--out", "r"])).unwrap_err().to_string(),
            "`--claims` cannot be combined with `--out`"
        );
        assert_eq!(
            parse(&args(&["report", "--out", "r"])),
            Ok(Command::Write { dir: "r".into(), model: "benchmark".into() })
        );
        assert_eq!(
            parse(&args(&["report", "--model", "b.toml", "--out", "r"])),
            Ok(Command::Write { dir: "r".into(), model: "b.toml".into() })
        );
    }

    #[test]
    fn rejects_unknown_arguments_by_name() {
        let err = parse(&args(&["report", "--jsn"])).unwrap_err();
        assert_eq!(err.to_string(), "unknown argument `--jsn`");
        assert_eq!(
            parse(&args(&["report", "--json", "--json"])),
            Err(UsageError::Repeated("--json".into()))
        );
        assert_eq!(
            parse(&args(&["report", "--out"])),
            Err(UsageError::MissingValue("--out".into()))
        );
        assert_eq!(
            parse(&args(&["report", "--out", "a", "--out", "b"])),
            Err(UsageError::Repeated("--out".into()))
        );
        assert_eq!(
            parse(&args(&["report", "--json", "--out", "a"])).unwrap_err().to_string(),
            "`--json` cannot be combined with `--out`"
        );
    }
}
