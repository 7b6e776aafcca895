//! The `carvallo` command line: the memoir concordance and the benchmark bicycle's stability.
//!
//! The command table is [`Command`], parsed by `clap` (derive API): every subcommand is one
//! variant whose options are the `Args` struct of its module in [`commands`] (or [`perf`]).
//! Clap makes the help of `carvallo` and of every command, `--version`, the suggestions for a
//! misspelt command or option and the usage errors (exit code 2, the usage of that command
//! only); `carvallo completions SHELL` prints a completion script made from the same table.
//! A command's own error is a data error (a file that cannot be read or is invalid: its message
//! only, exit code 2), a usage error found after parsing (options that do not fit together: the
//! message and the command's usage, exit code 2) or a failure (exit code 1).

use std::io::Write;
use std::process::ExitCode;

use clap::{CommandFactory as _, Parser as _};

mod args;
mod bench;
mod commands;
mod figures;
mod gain_sweep;
mod gains;
mod interrupt;
mod perf;
mod report_dir;
mod report_html;
mod staging;
mod sweep_args;

use commands::{
    accel, bode, eig, kinematics, parameters, pendulum, plot, report, response, rest, rolling,
    simulate, statespace, turn, window,
};

/// carvallo: E. Carvallo's memoir (1897) on the hoop, unicycle and bicycle, re-derived and
/// checked
#[derive(Debug, clap::Parser)]
#[command(name = "carvallo", version, max_term_width = 100)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// The subcommands in the order of the help.
#[derive(Debug, clap::Subcommand)]
enum Command {
    /// Print the memoir concordance (text table, or JSON with --json), its claims checked
    /// (--claims), or write the report directory (--out DIR)
    Report(report::Args),
    /// The stable speed range of the linearised Carvallo-Whipple bicycle (open, or closed by a
    /// state feedback with --gain), or of Carvallo's bicycle without hands (memoir n° 117-121)
    Window(window::Args),
    /// The eigenvalues of the linearised bicycle at speed V (m/s)
    Eig(eig::Args),
    /// The state space (A, B) of the linearised bicycle with roll and steer torque as inputs
    Statespace(statespace::Args),
    /// The frequency response (Bode diagram) from the roll or steer torque to the lean, the
    /// steer or their rates
    Bode(bode::Args),
    /// A figure (SVG) of one bicycle or several compared: the geometry, the eigenvalues against
    /// speed labelled by mode, or the Bode diagram
    Plot(plot::Args),
    /// The time response of the linearised bicycle to a unit step or impulse of the roll or
    /// steer torque, or from an initial state (matrix exponential)
    Response(response::Args),
    /// The benchmark parameters from BicycleParameters' raw measurements (--raw FILE), with
    /// their uncertainties, as a parameter file at full precision
    Parameters(parameters::Args),
    /// Time per evaluation beside the error against 256 bits
    Bench(perf::BenchArgs),
    /// The stability windows of many designs (a grid or random designs around the model), or
    /// the closed-loop windows of a grid of feedback gains (--gain), in parallel
    Sweep(perf::SweepArgs),
    /// Accelerations of the nonlinear bicycle in Basu-Mandal's coordinates, or the derivative of
    /// the simulations' state (the state as JSON on stdin)
    Accel(accel::Args),
    /// Simulate the nonlinear bicycle (time series, energy drift)
    Simulate(simulate::Args),
    /// Steady turns with the handlebar held (memoir n° 79-106): Carvallo's bicycle, or every
    /// turn of the nonlinear bicycle at a speed and lean, with its stability
    #[command(
        override_usage = "carvallo turn --model carvallo --gamma <DEG> --speed <V> [--json]\n       \
        carvallo turn --model <MODEL> --speed <V> --lean <RAD> [--steer <RAD>] [RIDER] [--json]\n       \
        carvallo turn --model <MODEL> --hands-free [RIDER] [--json]\n\
        RIDER: [--rider <FILE.txt> [--rider-config <FILE.txt>] [--measured <FILE.txt>]] [--strict]"
    )]
    Turn(turn::Args),
    /// The handlebar's rest position at a lean (memoir n° 67)
    Rest(rest::Args),
    /// Contact, relations (I) and steady rates (2) of the memoir's bicycle (n° 59-69)
    Kinematics(kinematics::Args),
    /// Simulate the rolling hoop (memoir n° 7): time series, energy drift, events
    Hoop(rolling::HoopArgs),
    /// Simulate the mounted unicycle (memoir n° 21-24): time series, energy drift, events
    Unicycle(rolling::UnicycleArgs),
    /// The two-wheeled inverted pendulum (a self-balancing transporter): the eigenvalues of its
    /// linear model, open or closed by a state feedback, or a simulation open loop or under a
    /// state feedback
    Pendulum(pendulum::Args),
    /// Print a shell completion script: `carvallo completions bash > carvallo.bash`
    Completions {
        /// The shell
        #[arg(value_enum)]
        shell: clap_complete::Shell,
    },
}

impl Command {
    /// The word that selects it.
    fn name(&self) -> &'static str {
        match self {
            Command::Report(_) => "report",
            Command::Window(_) => "window",
            Command::Eig(_) => "eig",
            Command::Statespace(_) => "statespace",
            Command::Bode(_) => "bode",
            Command::Plot(_) => "plot",
            Command::Response(_) => "response",
            Command::Parameters(_) => "parameters",
            Command::Bench(_) => "bench",
            Command::Sweep(_) => "sweep",
            Command::Accel(_) => "accel",
            Command::Simulate(_) => "simulate",
            Command::Turn(_) => "turn",
            Command::Rest(_) => "rest",
            Command::Kinematics(_) => "kinematics",
            Command::Hoop(_) => "hoop",
            Command::Unicycle(_) => "unicycle",
            Command::Pendulum(_) => "pendulum",
            Command::Completions { .. } => "completions",
        }
    }

    /// Its name and its subcommand's (`pendulum eig`), for the usage line of its errors.
    fn path(&self) -> Vec<&'static str> {
        match self {
            Command::Pendulum(a) => vec![
                "pendulum",
                match a.command {
                    pendulum::PendulumCommand::Eig(_) => "eig",
                    pendulum::PendulumCommand::Simulate(_) => "simulate",
                },
            ],
            c => vec![c.name()],
        }
    }

    /// Runs it and prints its outcome.
    fn run(&self) -> ExitCode {
        let text = |out: Result<String, String>| out.map(|t| format!("{}\n", t.trim_end()));
        let out = match self {
            Command::Report(a) => return finish_report(report::run(a)),
            Command::Window(a) => text(window::run(a)),
            Command::Eig(a) => text(eig::run(a)),
            Command::Statespace(a) => text(statespace::run(a)),
            Command::Bode(a) => text(bode::run(a)),
            Command::Plot(a) => text(plot::run(a)),
            Command::Response(a) => text(response::run(a)),
            Command::Parameters(a) => text(parameters::run(a)),
            Command::Bench(a) => text(perf::bench(a)),
            Command::Sweep(a) => text(perf::sweep(a)),
            Command::Accel(a) => text(accel::run(a)),
            Command::Simulate(a) => text(simulate::run(a)),
            Command::Turn(a) => text(turn::run(a)),
            Command::Rest(a) => text(rest::run(a)),
            Command::Kinematics(a) => text(kinematics::run(a)),
            Command::Hoop(a) => text(rolling::hoop(a)),
            Command::Unicycle(a) => text(rolling::unicycle(a)),
            Command::Pendulum(a) => text(match &a.command {
                pendulum::PendulumCommand::Eig(e) => pendulum::eig(e),
                pendulum::PendulumCommand::Simulate(s) => pendulum::simulate(s),
            }),
            Command::Completions { shell } => {
                let mut script = Vec::new();
                clap_complete::generate(*shell, &mut Cli::command(), "carvallo", &mut script);
                Ok(String::from_utf8_lossy(&script).into_owned())
            }
        };
        match out {
            Ok(text) => print(&text),
            // A bad file is named in one message; the usage is for a bad command line.
            // A solver that failed is not the user's error.
            Err(err) if err.starts_with(turn::SOLVER_FAILURE) => {
                error(&err);
                ExitCode::FAILURE
            }
            Err(err) if args::is_data_error(&err) => {
                error(&err);
                ExitCode::from(2)
            }
            Err(err) => usage_error(&self.path(), &err),
        }
    }
}

/// Prints the outcome of `report`: its text as it is, or its error (a bad output directory or
/// model file found before anything is written: exit 2; a failure while writing: exit 1).
fn finish_report(out: anyhow::Result<String>) -> ExitCode {
    match out {
        Ok(text) => print(&text),
        Err(err) if err.downcast_ref::<report_dir::BadInput>().is_some() => {
            error(&err.to_string());
            ExitCode::from(2)
        }
        Err(err) => {
            error(&format!("{err:#}"));
            ExitCode::FAILURE
        }
    }
}

/// Prints `message`, a usage error of the command `path` (its name, then its subcommand's)
/// found after parsing, as clap prints its own: the message, the command's usage and the
/// pointer to its help; exit code 2.
fn usage_error(path: &[&str], message: &str) -> ExitCode {
    let mut cli = Cli::command();
    cli.build();
    let mut at = Some(&mut cli);
    for name in path {
        at = at.and_then(|c| c.find_subcommand_mut(name));
    }
    let usage = at.map(|c| c.render_usage().to_string()).unwrap_or_default();
    error(&format!("{message}\n\n{usage}\n\nFor more information, try '--help'."));
    ExitCode::from(2)
}

/// Writes `error: message` to standard error. A closed standard error (`2>&-`) loses the
/// message but never panics like `eprintln!` would: the exit code still tells.
fn error(message: &str) {
    let _ = writeln!(std::io::stderr().lock(), "error: {message}");
}

/// Prints `text` as it is: exit 0, or 1 if it cannot be written.
fn print(text: &str) -> ExitCode {
    match emit(text) {
        Ok(()) => ExitCode::SUCCESS,
        Err(err) => {
            error(&format!("cannot write the output: {err}"));
            ExitCode::FAILURE
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

/// The help of the command that `words` (the arguments after `carvallo`) name: the deepest
/// subcommand their leading words select (`pendulum` → `carvallo pendulum`'s help, with its
/// own usage line), `carvallo`'s own when none.
fn help_of(words: &[String]) -> String {
    fn descend(cmd: &mut clap::Command, words: &[String]) -> String {
        match words.split_first() {
            Some((w, rest)) if cmd.find_subcommand(w).is_some() => {
                descend(cmd.find_subcommand_mut(w).expect("found above"), rest)
            }
            _ => cmd.render_help().to_string(),
        }
    }
    let mut cmd = Cli::command();
    cmd.build();
    descend(&mut cmd, words)
}

fn main() -> ExitCode {
    match Cli::try_parse() {
        Ok(cli) => cli.command.run(),
        // `carvallo` alone (or `carvallo pendulum` alone): clap shows the help as an error; it
        // says so first, with the help of the command that lacks its subcommand.
        Err(err)
            if err.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand =>
        {
            let words: Vec<String> = std::env::args().skip(1).collect();
            error(&format!("a command is required\n\n{}", help_of(&words)));
            ExitCode::from(2)
        }
        Err(err) => {
            // Help and version go to standard output (exit 0), usage errors to standard error
            // (exit 2); a closed stream loses the text without a panic.
            let _ = err.print();
            ExitCode::from(if err.use_stderr() { 2 } else { 0 })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_command_table_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn every_command_is_selected_by_its_name() {
        for sub in Cli::command().get_subcommands() {
            let name = sub.get_name().to_string();
            let words: Vec<String> = match name.as_str() {
                "completions" => vec!["carvallo".into(), name.clone(), "bash".into()],
                "report" | "bench" => vec!["carvallo".into(), name.clone()],
                _ => continue,
            };
            let cli = Cli::try_parse_from(&words).expect("parses");
            assert_eq!(cli.command.name(), name);
        }
        let e = Cli::try_parse_from(["carvallo", "rapport"]).unwrap_err().to_string();
        assert!(e.contains("unrecognized subcommand 'rapport'"), "{e}");
        assert!(e.contains("similar subcommand exists: 'report'"), "{e}");
        let e = Cli::try_parse_from(["carvallo", "window", "--modle", "x"]).unwrap_err();
        assert!(e.to_string().contains("similar argument exists: '--model'"), "{e}");
    }
}
