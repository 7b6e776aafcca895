//! Workspace automation, reached through the `cargo xtask` alias of `.cargo/config.toml`.
//!
//! Subcommands (one module each):
//!
//! * `regen [--check]`: re-run every symbolic derivation and rewrite `generated/` atomically, or,
//!   with `--check`, fail without writing anything when `generated/` is out of date.

mod regen;

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{bail, Result};

const USAGE: &str = "usage: cargo xtask regen [--check]

subcommands:
  regen            re-derive every model and rewrite generated/ atomically
  regen --check    re-derive every model and fail if generated/ is out of date";

fn main() -> ExitCode {
    // symbolica colours printed expressions when standard output is a terminal (it caches that
    // decision at the first print); generated/ must not depend on where the command runs.
    // `.cargo/config.toml` sets the same for every cargo-run process; this covers a direct run.
    if std::env::var_os("SYMBOLICA_COLOR").is_none() {
        std::env::set_var("SYMBOLICA_COLOR", "0");
    }
    match run(std::env::args().skip(1).collect()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run(args: Vec<String>) -> Result<()> {
    let Some((command, rest)) = args.split_first() else {
        bail!("missing subcommand\n{USAGE}");
    };
    match command.as_str() {
        "regen" => regen::run(&workspace_root(), rest),
        "-h" | "--help" | "help" => {
            println!("{USAGE}");
            Ok(())
        }
        other => bail!("unknown subcommand {other:?}\n{USAGE}"),
    }
}

/// The workspace root: the parent of this crate's manifest directory.
fn workspace_root() -> PathBuf {
    let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    manifest.parent().map(PathBuf::from).unwrap_or(manifest)
}
