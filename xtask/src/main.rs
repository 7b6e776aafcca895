//! Workspace automation, reached through the `cargo xtask` alias of `.cargo/config.toml`.
//!
//! Subcommands (one module each):
//!
//! * `regen [--check] [MODEL...]`: re-run the symbolic derivations (all, or the named models
//!   only) and rewrite `generated/` atomically, or, with `--check`, fail without writing
//!   anything when `generated/` is out of date.

mod regen;

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{bail, Result};

/// The usage text; the model list comes from the derivation table.
fn usage() -> String {
    let models: Vec<&str> = carvallo_codegen::derive::DERIVATIONS.iter().map(|(n, _)| *n).collect();
    format!(
        "usage: cargo xtask regen [--check] [MODEL...]

subcommands:
  regen                     re-derive every model and rewrite generated/ atomically
  regen MODEL...            re-derive the named models only (the others' files are kept)
  regen --check [MODEL...]  re-derive and fail if generated/ is out of date

models: {}",
        models.join(", ")
    )
}

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
        bail!("missing subcommand\n{}", usage());
    };
    match command.as_str() {
        "regen" => regen::run(&workspace_root(), rest),
        "-h" | "--help" | "help" => {
            println!("{}", usage());
            Ok(())
        }
        other => bail!("unknown subcommand {other:?}\n{}", usage()),
    }
}

/// The workspace root: the parent of this crate's manifest directory.
fn workspace_root() -> PathBuf {
    let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    manifest.parent().map(PathBuf::from).unwrap_or(manifest)
}
