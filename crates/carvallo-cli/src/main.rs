//! The `carvallo` command line: prints the memoir concordance of the rolling hoop.
//!
//! `carvallo report` prints the concordance as an aligned text table, `carvallo report --json`
//! as a JSON array of objects with the keys `section`, `quantity`, `memoir`, `derived`,
//! `rel_diff`, `verdict` and `note`. Arguments are parsed by hand (there are only a few); an
//! unknown argument is an error that names it, with exit code 2.

use std::process::ExitCode;

mod whipple;

const HELP: &str = "\
carvallo: E. Carvallo's rolling hoop (1897), re-derived and checked against the memoir

Usage:
    carvallo report [--json]    print the memoir concordance (text table, or JSON with --json)
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
}

/// A command line that cannot be understood; printed to stderr, exit code 2.
#[derive(Debug, PartialEq, Eq)]
enum UsageError {
    Missing,
    Unknown(String),
    Repeated(String),
}

impl std::fmt::Display for UsageError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            UsageError::Missing => write!(f, "missing command: expected `report` or `--help`"),
            UsageError::Unknown(arg) => write!(f, "unknown argument `{arg}`"),
            UsageError::Repeated(arg) => write!(f, "argument `{arg}` given more than once"),
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
    let mut json = false;
    for arg in rest {
        match arg.as_str() {
            "--json" if json => return Err(UsageError::Repeated(arg.clone())),
            "--json" => json = true,
            _ => return Err(UsageError::Unknown(arg.clone())),
        }
    }
    Ok(Command::Report { json })
}

fn run(command: Command) -> anyhow::Result<()> {
    match command {
        Command::Help => print!("{HELP}"),
        Command::Report { json } => {
            let entries = carvallo::report::all_entries();
            if json {
                println!("{}", serde_json::to_string_pretty(&entries)?);
            } else {
                print!("{}", carvallo::report::render_text(&entries));
            }
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if let Some(code) = whipple::dispatch(&args) {
        return code;
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
        Err(err) => {
            eprintln!("error: {err:#}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(list: &[&str]) -> Vec<String> {
        list.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn parses_the_commands() {
        assert_eq!(parse(&args(&["report"])), Ok(Command::Report { json: false }));
        assert_eq!(parse(&args(&["report", "--json"])), Ok(Command::Report { json: true }));
        assert_eq!(parse(&args(&["--help"])), Ok(Command::Help));
        assert_eq!(parse(&args(&["report", "-h"])), Ok(Command::Help));
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
    }
}
