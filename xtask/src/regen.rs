//! `cargo xtask regen [--check]`: runs every derivation of `carvallo_codegen::regen` and
//! rewrites `generated/` atomically, or checks that it is up to date (exit status 1 and the list
//! of stale, missing and extra files when it is not).

use std::path::Path;

use anyhow::{bail, Result};
use carvallo_codegen::regen::{regen, FileStatus};

/// Runs the subcommand with the arguments that follow `regen`.
pub fn run(root: &Path, args: &[String]) -> Result<()> {
    let mut check = false;
    for a in args {
        match a.as_str() {
            "--check" => check = true,
            other => bail!("unknown argument {other:?} to regen (expected nothing or --check)"),
        }
    }
    let summary = regen(root, check)?;
    for m in &summary.models {
        println!(
            "model {}: {} outputs, {} ops, {}/{} checks hold",
            m.model,
            m.outputs.len(),
            m.ops,
            m.checks.1,
            m.checks.0
        );
    }
    if check {
        println!("generated/ is up to date ({} files)", summary.files.len());
        return Ok(());
    }
    let changed: Vec<String> = summary
        .files
        .iter()
        .filter(|(_, s)| *s != FileStatus::Fresh)
        .map(|(p, s)| {
            let what = match s {
                FileStatus::Stale => "updated",
                FileStatus::Missing => "created",
                FileStatus::Extra => "removed",
                FileStatus::Fresh => "unchanged",
            };
            format!("  {what} generated/{p}")
        })
        .collect();
    if changed.is_empty() {
        println!("generated/ was already up to date ({} files)", summary.files.len());
    } else {
        println!("wrote generated/:\n{}", changed.join("\n"));
    }
    Ok(())
}
