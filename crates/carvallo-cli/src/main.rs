//! The `carvallo` command line: the memoir concordance and the benchmark bicycle's stability.
//!
//! `carvallo report` prints the concordance as an aligned text table, `carvallo report --json`
//! as a JSON array of objects with the keys `section`, `quantity`, `memoir`, `derived`,
//! `rel_diff`, `verdict` and `note`. `carvallo window` and `carvallo eig` (module [`whipple`])
//! give the linearised Carvallo–Whipple bicycle's stable speed range and eigenvalues. Arguments are parsed by hand (there are only a few); an
//! unknown argument is an error that names it, with exit code 2.

use std::io::Write;
use std::process::ExitCode;

mod args;
mod bench;
mod commands;
mod figures;
mod perf;
mod report_dir;
mod report_html;
mod straight;

use commands::{kinematics, rest, simulate, turn, window};

const HELP: &str = "\
carvallo: E. Carvallo's memoir (1897) on the hoop, unicycle and bicycle, re-derived and checked

Usage:
    carvallo report [--json]    print the memoir concordance (text table, or JSON with --json)
    carvallo report --out DIR [--model benchmark|FILE.toml|FILE.txt]
                                write DIR/report.md and DIR/report.html (concordance, errata)
                                and the SVG figures; a FILE.txt with uncertainties
                                (BicycleParameters' name = value+/-sigma) adds their
                                propagation and the eigenvalues with uncertainty bands
    carvallo window --model benchmark|FILE.toml [--json]
                                stable speed range of the linearised Carvallo-Whipple bicycle
    carvallo window --model carvallo|carvallo-formulas|carvallo-memoir|carvallo-quartic [--json]
                                Carvallo's bicycle without hands (memoir n° 117-121)
    carvallo eig --model benchmark|FILE.toml --speed V [--json]
                                eigenvalues of the linearised bicycle at speed V [m/s]
    carvallo bench [--json] [--quick]
                                time per evaluation beside the error against 256 bits
    carvallo sweep --model benchmark|FILE.toml --vary NAME=FROM:TO:COUNT [--vary ...]
                   [--method hurwitz|eigen] [--json | --csv]
    carvallo sweep --model benchmark|FILE.toml --random N --spread NAME=REL [--spread ...]
                   [--seed S] [--method hurwitz|eigen] [--json | --csv]
                                stability windows of many designs (a grid or random
                                designs around the model), in parallel
    carvallo accel --model benchmark|FILE.toml --basu-mandal
                                accelerations of the nonlinear bicycle in Basu-Mandal's
                                coordinates: reads {\"q\": [..9], \"qd\": [..9]} on stdin
    carvallo simulate --model benchmark|FILE.toml --speed V --lean0 RAD --duration S
                      [--step DT] [--every N] [--json]
                                simulate the nonlinear bicycle (time series, energy drift)
    carvallo turn --model carvallo --gamma DEG --speed V [--json]
                                steady turn with the handlebar held (memoir n° 99-105)
    carvallo rest --theta DEG [--wheel-mass KG] [--json]
                                the handlebar's rest position at a lean (memoir n° 67)
    carvallo kinematics --theta DEG --gamma DEG [--json]
                                contact, relations (I) and steady rates (2) (memoir n° 59-69)
    carvallo --help             print this help

Options:
    --json       print the report as a JSON array of
                 {section, quantity, memoir, derived, rel_diff, verdict, note}
    -h, --help   print this help
";

/// What the command line asks for.
#[derive(Debug, PartialEq, Eq)]
enum Command {
    Help,
    Report { json: bool },
    ReportOut { dir: String, model: String },
}

/// A command line that cannot be understood; printed to stderr, exit code 2.
#[derive(Debug, PartialEq, Eq)]
enum UsageError {
    Missing,
    Unknown(String),
    Repeated(String),
    MissingValue(String),
    Conflict(&'static str, &'static str),
}

impl std::fmt::Display for UsageError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            UsageError::Missing => write!(f, "missing command: expected `report`, `window`, `eig`, `bench`, `sweep`, `accel`, `simulate`, `turn`, `rest`, `kinematics` or `--help`"),
            UsageError::Unknown(arg) => write!(f, "unknown argument `{arg}`"),
            UsageError::Repeated(arg) => write!(f, "argument `{arg}` given more than once"),
            UsageError::MissingValue(arg) => write!(f, "missing value after `{arg}`"),
            UsageError::Conflict(a, b) => write!(f, "`{a}` cannot be combined with `{b}`"),
        }
    }
}

fn parse(args: &[String]) -> Result<Command, UsageError> {
    if args.iter().any(|a| a == "-h" || a == "--help") {
        // Still reject unknown arguments next to --help, so typos are never silent.
        if let Some(bad) =
            args.iter().find(|a| !matches!(a.as_str(), "-h" | "--help" | "report" | "--json"))
        {
            return Err(UsageError::Unknown(bad.clone()));
        }
        return Ok(Command::Help);
    }
    let (first, rest) = args.split_first().ok_or(UsageError::Missing)?;
    if first != "report" {
        return Err(UsageError::Unknown(first.clone()));
    }
    let (mut json, mut out, mut model) = (false, None, None);
    let mut it = rest.iter();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--json" if json => return Err(UsageError::Repeated(arg.clone())),
            "--json" => json = true,
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
        (Some(dir), model) => {
            Ok(Command::ReportOut { dir, model: model.unwrap_or_else(|| "benchmark".into()) })
        }
        (None, Some(_)) => Err(UsageError::Conflict("--model", "the printed report (use --out)")),
        (None, None) => Ok(Command::Report { json }),
    }
}

fn run(command: Command) -> anyhow::Result<()> {
    match command {
        Command::Help => emit(HELP)?,
        Command::ReportOut { dir, model } => {
            let params = window::load_uncertain(&model).map_err(report_dir::BadInput)?;
            let files = report_dir::write_report(std::path::Path::new(&dir), &params, &model)?;
            let list: String = files.iter().map(|f| format!("{dir}/{f}\n")).collect();
            emit(&list)?;
        }
        Command::Report { json } => {
            let entries = carvallo_report::all_entries();
            if json {
                emit(&format!("{}\n", serde_json::to_string_pretty(&entries)?))?;
            } else {
                emit(&carvallo_report::render_text(&entries))?;
            }
        }
    }
    Ok(())
}

/// A subcommand handled by a module of its own.
pub(crate) struct Subcommand {
    /// The first words that select it.
    pub names: &'static [&'static str],
    /// Parses the whole argument list (the subcommand's name first) and runs it: the text to
    /// print, or an error naming the bad argument or value.
    pub run: fn(&[String]) -> Result<String, String>,
    /// Its usage text.
    pub help: &'static str,
}

impl Subcommand {
    /// Prints the help (exit 0) when an argument is `-h` or `--help`, otherwise runs the
    /// subcommand and prints its outcome with [`finish`].
    fn dispatch(&self, args: &[String]) -> ExitCode {
        if args.iter().any(|a| a == "-h" || a == "--help") {
            return match emit(self.help) {
                Ok(()) => ExitCode::SUCCESS,
                Err(_) => ExitCode::FAILURE,
            };
        }
        finish((self.run)(args), self.help)
    }
}

/// The subcommands with a module of their own (`report` is parsed here).
const SUBCOMMANDS: [&Subcommand; 6] = [
    &window::SUBCOMMAND,
    &perf::SUBCOMMAND,
    &simulate::SUBCOMMAND,
    &turn::SUBCOMMAND,
    &rest::SUBCOMMAND,
    &kinematics::SUBCOMMAND,
];

/// Prints a subcommand's outcome: its text on standard output (exit 0; exit 1 if it cannot be
/// written), or the error and the subcommand's `help` on standard error (exit 2).
pub(crate) fn finish(out: Result<String, String>, help: &str) -> ExitCode {
    match out {
        Ok(text) => match emit(&format!("{}\n", text.trim_end())) {
            Ok(()) => ExitCode::SUCCESS,
            Err(err) => {
                eprintln!("error: cannot write the output: {err}");
                ExitCode::FAILURE
            }
        },
        Err(err) => {
            eprintln!("error: {err}\n\n{help}");
            ExitCode::from(2)
        }
    }
}

/// Writes `text` to standard output. A reader that stops early (`carvallo report | head`)
/// closes the pipe; that ends the output quietly instead of panicking like `print!` would.
pub(crate) fn emit(text: &str) -> std::io::Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let first = args.first().map(String::as_str).unwrap_or("");
    if let Some(sub) = SUBCOMMANDS.iter().find(|sub| sub.names.contains(&first)) {
        return sub.dispatch(&args);
    }
    let command = match parse(&args) {
        Ok(command) => command,
        Err(err) => {
            eprintln!("error: {err}\n\n{HELP}");
            return ExitCode::from(2);
        }
    };
    match run(command) {
        Ok(()) => ExitCode::SUCCESS,
        // A bad output directory or model file found before anything is written: exit 2.
        Err(err) if err.downcast_ref::<report_dir::BadInput>().is_some() => {
            eprintln!("error: {err}");
            ExitCode::from(2)
        }
        Err(err) => {
            eprintln!("error: {err:#}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::words as args;

    #[test]
    fn parses_the_commands() {
        assert_eq!(parse(&args(&["report"])), Ok(Command::Report { json: false }));
        assert_eq!(parse(&args(&["report", "--json"])), Ok(Command::Report { json: true }));
        assert_eq!(parse(&args(&["--help"])), Ok(Command::Help));
        assert_eq!(parse(&args(&["report", "-h"])), Ok(Command::Help));
        assert_eq!(
            parse(&args(&["report", "--out", "r"])),
            Ok(Command::ReportOut { dir: "r".into(), model: "benchmark".into() })
        );
        assert_eq!(
            parse(&args(&["report", "--model", "b.toml", "--out", "r"])),
            Ok(Command::ReportOut { dir: "r".into(), model: "b.toml".into() })
        );
    }

    #[test]
    fn rejects_unknown_arguments_by_name() {
        assert_eq!(parse(&args(&[])), Err(UsageError::Missing));
        assert_eq!(parse(&args(&["rapport"])), Err(UsageError::Unknown("rapport".into())));
        let err = parse(&args(&["report", "--jsn"])).unwrap_err();
        assert_eq!(err.to_string(), "unknown argument `--jsn`");
        assert_eq!(
            parse(&args(&["report", "--json", "--json"])),
            Err(UsageError::Repeated("--json".into()))
        );
        assert_eq!(parse(&args(&["--help", "-x"])), Err(UsageError::Unknown("-x".into())));
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
