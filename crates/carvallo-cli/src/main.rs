//! The `carvallo` command line: the memoir concordance and the benchmark bicycle's stability.
//!
//! Every subcommand is one row of [`COMMANDS`]: the word that selects it, its lines in the help,
//! the usage it prints for `--help` and after a usage error, and the function that runs it
//! (modules in [`commands`]). The help ([`help`]), the dispatch and the messages for a missing
//! or unknown command are all made from that table. Arguments are parsed by hand (there are
//! only a few); an unknown argument is an error that names it, with exit code 2.

use std::io::Write;
use std::process::ExitCode;

mod args;
mod bench;
mod commands;
mod figures;
mod perf;
mod report_dir;
mod report_html;

use commands::{accel, eig, kinematics, report, rest, simulate, turn, window};

/// One subcommand of `carvallo`.
pub(crate) struct Command {
    /// The word that selects it: `carvallo NAME ...`.
    pub name: &'static str,
    /// Its usage forms in `carvallo --help`, each with what it does.
    pub forms: &'static [Form],
    /// What `carvallo NAME --help` prints, also after a usage error; `None`: the whole help
    /// (`report`, the command the help's options describe).
    pub help: Option<&'static str>,
    /// Runs it on the whole argument list, its name first.
    pub run: Run,
}

/// One usage form of a command in `carvallo --help`.
pub(crate) struct Form {
    /// The command line without the indentation; continuation lines keep their alignment under
    /// the first.
    pub usage: &'static str,
    /// What it does, one or more lines; empty when the next form's description covers both.
    pub what: &'static str,
}

/// How a command runs.
pub(crate) enum Run {
    /// Returns the text to print, or a usage error naming the bad argument or value (printed
    /// with the command's help, exit code 2).
    Text(fn(&[String]) -> Result<String, String>),
    /// Returns the text to print as it is, or an error: a [`UsageError`] (printed with the
    /// help, exit code 2), a [`report_dir::BadInput`] (exit code 2) or a failure (exit code 1).
    Fallible(fn(&[String]) -> anyhow::Result<String>),
}

/// The subcommands in the order of the help.
pub(crate) const COMMANDS: [Command; 10] = [
    Command {
        name: "report",
        forms: &[
            Form {
                usage: "carvallo report [--json]",
                what: "print the memoir concordance (text table, or JSON with --json)",
            },
            Form {
                usage: "carvallo report --claims [--json]",
                what: "print the memoir's claims checked: claim, how checked,
evidence, verdict (JSON array with --json)",
            },
            Form {
                usage: "carvallo report --out DIR [--model benchmark|FILE.toml|FILE.txt]",
                what: "write DIR/report.md and DIR/report.html (concordance, errata)
and the SVG figures; a FILE.txt with uncertainties
(BicycleParameters' name = value+/-sigma) adds their
propagation and the eigenvalues with uncertainty bands",
            },
        ],
        help: None,
        run: Run::Fallible(report::main),
    },
    Command {
        name: "window",
        forms: &[
            Form {
                usage: "carvallo window --model benchmark|FILE.toml|FILE.txt [--rider FILE.txt] [--strict] [--json]",
                what: "stable speed range of the linearised Carvallo-Whipple bicycle",
            },
            Form {
                usage: "carvallo window --model carvallo|carvallo-formulas|carvallo-memoir|carvallo-quartic [--json]",
                what: "Carvallo's bicycle without hands (memoir n° 117-121)",
            },
        ],
        help: Some(window::HELP),
        run: Run::Text(window::main),
    },
    Command {
        name: "eig",
        forms: &[Form {
            usage: "carvallo eig --model benchmark|FILE.toml|FILE.txt [--rider FILE.txt] [--strict] --speed V [--json]",
            what: "eigenvalues of the linearised bicycle at speed V [m/s]",
        }],
        help: Some(eig::HELP),
        run: Run::Text(eig::main),
    },
    Command {
        name: "bench",
        forms: &[Form {
            usage: "carvallo bench [--json] [--quick]",
            what: "time per evaluation beside the error against 256 bits",
        }],
        help: Some(perf::SUBCOMMAND.help),
        run: Run::Text(perf::SUBCOMMAND.run),
    },
    Command {
        name: "sweep",
        forms: &[
            Form {
                usage: "carvallo sweep --model benchmark|FILE.toml --vary NAME=FROM:TO:COUNT [--vary ...]
               [--rider FILE.txt] [--strict] [--method hurwitz|eigen] [--json | --csv]",
                what: "",
            },
            Form {
                usage: "carvallo sweep --model benchmark|FILE.toml --random N --spread NAME=REL [--spread ...]
               [--seed S] [--rider FILE.txt] [--strict] [--method hurwitz|eigen] [--json | --csv]",
                what: "stability windows of many designs (a grid or random
designs around the model), in parallel",
            },
        ],
        help: Some(perf::SUBCOMMAND.help),
        run: Run::Text(perf::SUBCOMMAND.run),
    },
    Command {
        name: "accel",
        forms: &[Form {
            usage: "carvallo accel --model benchmark|FILE.toml --basu-mandal",
            what: "accelerations of the nonlinear bicycle in Basu-Mandal's
coordinates: reads {\"q\": [..9], \"qd\": [..9]} on stdin",
        }],
        help: Some(accel::HELP),
        run: Run::Text(accel::main),
    },
    Command {
        name: "simulate",
        forms: &[Form {
            usage: "carvallo simulate --model benchmark|FILE.toml --speed V --lean0 RAD --duration S
                  [--step DT] [--every N] [--json]",
            what: "simulate the nonlinear bicycle (time series, energy drift)",
        }],
        help: Some(simulate::HELP),
        run: Run::Text(simulate::main),
    },
    Command {
        name: "turn",
        forms: &[Form {
            usage: "carvallo turn --model carvallo --gamma DEG --speed V [--json]",
            what: "steady turn with the handlebar held (memoir n° 99-105)",
        }],
        help: Some(turn::HELP),
        run: Run::Text(turn::main),
    },
    Command {
        name: "rest",
        forms: &[Form {
            usage: "carvallo rest --theta DEG [--wheel-mass KG] [--json]",
            what: "the handlebar's rest position at a lean (memoir n° 67)",
        }],
        help: Some(rest::HELP),
        run: Run::Text(rest::main),
    },
    Command {
        name: "kinematics",
        forms: &[Form {
            usage: "carvallo kinematics --theta DEG --gamma DEG [--json]",
            what: "contact, relations (I) and steady rates (2) (memoir n° 59-69)",
        }],
        help: Some(kinematics::HELP),
        run: Run::Text(kinematics::main),
    },
];

/// The help's first line.
const TITLE: &str =
    "carvallo: E. Carvallo's memoir (1897) on the hoop, unicycle and bicycle, re-derived and checked";

/// The help's last form, after the commands.
const HELP_FORM: Form = Form { usage: "carvallo --help", what: "print this help" };

/// The options the help describes (those of `report`, and the help's own).
const OPTIONS: &str = "\
Options:
    --json       print the report as a JSON array of
                 {section, quantity, memoir, derived, rel_diff, verdict, note}
    -h, --help   print this help
";

/// The words `carvallo --help` (or `carvallo report --help`) accepts beside itself: the
/// command and the option its options section describes. Any other word is named as unknown,
/// so that a typo is never silent.
const HELP_WORDS: [&str; 5] = ["-h", "--help", "report", "--json", "--claims"];

/// Where the description of a form starts in the help.
const WHAT_COLUMN: usize = 32;

/// The help of `carvallo`: [`TITLE`], every form of [`COMMANDS`] in order, [`OPTIONS`].
pub(crate) fn help() -> String {
    let mut out = format!("{TITLE}\n\nUsage:\n");
    let forms = COMMANDS.iter().flat_map(|c| c.forms).chain([&HELP_FORM]);
    for form in forms {
        let indent = " ".repeat(4);
        let mut usage: Vec<String> = form.usage.lines().map(|l| format!("{indent}{l}")).collect();
        let mut what = form.what.lines();
        // A short usage takes the first line of its description beside it.
        if let Some(last) = usage.last_mut().filter(|l| l.chars().count() + 2 <= WHAT_COLUMN) {
            if let Some(first) = what.next() {
                *last = format!("{last:<WHAT_COLUMN$}{first}");
            }
        }
        for line in usage {
            out.push_str(&line);
            out.push('\n');
        }
        for line in what {
            out.push_str(&format!("{:WHAT_COLUMN$}{line}\n", ""));
        }
    }
    out.push('\n');
    out.push_str(OPTIONS);
    out
}

/// A command line that cannot be understood; printed to stderr with the help, exit code 2.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum UsageError {
    Missing,
    Unknown(String),
    Repeated(String),
    MissingValue(String),
    Conflict(&'static str, &'static str),
}

impl std::fmt::Display for UsageError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            UsageError::Missing => {
                let names: Vec<String> = COMMANDS.iter().map(|c| format!("`{}`", c.name)).collect();
                write!(f, "missing command: expected {} or `--help`", names.join(", "))
            }
            UsageError::Unknown(arg) => write!(f, "unknown argument `{arg}`"),
            UsageError::Repeated(arg) => write!(f, "argument `{arg}` given more than once"),
            UsageError::MissingValue(arg) => write!(f, "missing value after `{arg}`"),
            UsageError::Conflict(a, b) => write!(f, "`{a}` cannot be combined with `{b}`"),
        }
    }
}

impl std::error::Error for UsageError {}

/// The shape in which [`perf`] exports `bench` and `sweep` (until it moves into [`commands`]
/// with the bench): [`COMMANDS`] takes its `run` and `help`.
pub(crate) struct Subcommand {
    /// The words that select it (the table's names; checked by a test).
    #[cfg_attr(not(test), expect(dead_code, reason = "COMMANDS names the commands"))]
    pub names: &'static [&'static str],
    /// Parses the whole argument list (the subcommand's name first) and runs it.
    pub run: fn(&[String]) -> Result<String, String>,
    /// Its usage text.
    pub help: &'static str,
}

fn is_help(arg: &String) -> bool {
    arg == "-h" || arg == "--help"
}

impl Command {
    /// Runs the command on `args` (its name first) and prints its outcome. `-h` or `--help`
    /// anywhere prints its help instead (exit 0).
    fn dispatch(&self, args: &[String]) -> ExitCode {
        if args.iter().any(is_help) {
            return match self.help {
                Some(text) => print(text),
                None => whole_help(args),
            };
        }
        match self.run {
            Run::Text(run) => finish(run(args), self.help.unwrap_or_default()),
            Run::Fallible(run) => match run(args) {
                Ok(text) => match emit(&text) {
                    Ok(()) => ExitCode::SUCCESS,
                    Err(err) => {
                        eprintln!("error: {err:#}");
                        ExitCode::FAILURE
                    }
                },
                Err(err) => match err.downcast_ref::<UsageError>() {
                    Some(usage) => usage_error(usage),
                    // A bad output directory or model file found before anything is written.
                    None if err.downcast_ref::<report_dir::BadInput>().is_some() => {
                        eprintln!("error: {err}");
                        ExitCode::from(2)
                    }
                    None => {
                        eprintln!("error: {err:#}");
                        ExitCode::FAILURE
                    }
                },
            },
        }
    }
}

/// Prints the whole help (exit 0) if every word of `args` is one of [`HELP_WORDS`], otherwise
/// names the first other word as unknown (exit 2).
fn whole_help(args: &[String]) -> ExitCode {
    match args.iter().find(|a| !HELP_WORDS.contains(&a.as_str())) {
        Some(bad) => usage_error(&UsageError::Unknown(bad.clone())),
        None => print(&help()),
    }
}

/// Prints `err` and the whole help on standard error; exit code 2.
fn usage_error(err: &UsageError) -> ExitCode {
    eprintln!("error: {err}\n\n{}", help());
    ExitCode::from(2)
}

/// Prints `text` as it is: exit 0, or 1 if it cannot be written.
fn print(text: &str) -> ExitCode {
    match emit(text) {
        Ok(()) => ExitCode::SUCCESS,
        Err(_) => ExitCode::FAILURE,
    }
}

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
        // A bad file is named in one message; the usage is for a bad command line.
        Err(err) if args::is_data_error(&err) => {
            eprintln!("error: {err}");
            ExitCode::from(2)
        }
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

/// The command `args` selects by its first word, or the usage error without one.
fn select(args: &[String]) -> Result<&'static Command, UsageError> {
    let first = args.first().ok_or(UsageError::Missing)?;
    COMMANDS.iter().find(|c| c.name == first).ok_or_else(|| UsageError::Unknown(first.clone()))
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match select(&args) {
        Ok(command) => command.dispatch(&args),
        // `carvallo --help`, with only words the help describes beside it.
        Err(_) if args.iter().any(is_help) => whole_help(&args),
        Err(err) => usage_error(&err),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::words as args;

    #[test]
    fn selects_the_commands_by_name() {
        for c in &COMMANDS {
            assert_eq!(select(&args(&[c.name, "--json"])).map(|s| s.name), Ok(c.name));
        }
        assert_eq!(select(&args(&[])).err(), Some(UsageError::Missing));
        assert_eq!(select(&args(&["rapport"])).err(), Some(UsageError::Unknown("rapport".into())));
        assert_eq!(select(&args(&["--help"])).err(), Some(UsageError::Unknown("--help".into())));
    }

    #[test]
    fn the_help_and_the_missing_command_name_every_command_in_order() {
        let text = help();
        let missing = UsageError::Missing.to_string();
        let mut at = (0, 0);
        for c in &COMMANDS {
            let usage = format!("\n    carvallo {} ", c.name);
            let found = text[at.0..].find(&usage).map(|k| at.0 + k);
            assert!(found.is_some(), "the help does not list `{}` after its predecessor", c.name);
            let named = missing[at.1..].find(&format!("`{}`", c.name)).map(|k| at.1 + k);
            assert!(named.is_some(), "{missing} does not name `{}` in order", c.name);
            at = (found.unwrap_or(0), named.unwrap_or(0));
            for form in c.forms {
                let first = form.usage.lines().next().unwrap_or_default();
                assert!(first.starts_with(&format!("carvallo {} ", c.name)), "{}", form.usage);
                assert!(text.contains(&format!("    {first}")), "{first}");
            }
            if let Some(own) = c.help {
                assert!(own.contains(&format!("carvallo {}", c.name)), "{}'s usage", c.name);
            }
        }
        assert!(missing.ends_with("or `--help`"), "{missing}");
        assert!(text.starts_with(TITLE) && text.ends_with(OPTIONS));
    }

    #[test]
    fn perf_answers_the_names_the_table_gives_it() {
        let perf_rows: Vec<&str> = COMMANDS
            .iter()
            .filter(|c| c.help == Some(perf::SUBCOMMAND.help))
            .map(|c| c.name)
            .collect();
        assert_eq!(perf_rows, perf::SUBCOMMAND.names);
    }

    #[test]
    fn help_words_are_the_report_and_its_json_flag() {
        assert!(HELP_WORDS.iter().all(|w| is_help(&w.to_string()) || help().contains(w)));
    }
}
