//! `cargo xtask regen [--check] [MODEL...]`: runs the derivations of `carvallo_codegen::regen`
//! (every model, or only the named ones: the files of the others are kept as they are) and
//! rewrites `generated/` atomically, or checks that it is up to date (exit status 1 and the list
//! of stale, missing and extra files when it is not). Prints each derivation's wall and CPU time.

use std::path::Path;

use anyhow::{bail, Result};
use carvallo_codegen::regen::{regen_models, FileStatus, Selection};

/// Runs the subcommand with the arguments that follow `regen`.
pub fn run(root: &Path, args: &[String]) -> Result<()> {
    let mut check = false;
    let mut names = Vec::new();
    for a in args {
        match a.as_str() {
            "--check" => check = true,
            other if other.starts_with('-') => {
                bail!("unknown option {other:?} to regen (expected --check or model names)")
            }
            model => names.push(model.to_string()),
        }
    }
    let selection = if names.is_empty() { Selection::All } else { Selection::Only(&names) };
    let summary = regen_models(root, check, selection)?;
    let (mut wall, mut cpu) = (0.0, Some(0.0));
    for m in &summary.models {
        let time = match m.time {
            Some(t) => {
                wall += t.wall.as_secs_f64();
                cpu = cpu.zip(t.cpu).map(|(a, b)| a + b.as_secs_f64());
                match t.cpu {
                    Some(c) => format!(
                        "derived in {:.1} s ({:.1} s CPU)",
                        t.wall.as_secs_f64(),
                        c.as_secs_f64()
                    ),
                    None => format!("derived in {:.1} s", t.wall.as_secs_f64()),
                }
            }
            None => "kept from disk".to_string(),
        };
        println!(
            "model {}: {} outputs, {} ops, {}/{} checks hold, {time}",
            m.model,
            m.outputs.len(),
            m.ops,
            m.checks.1,
            m.checks.0
        );
    }
    match cpu {
        Some(c) => println!("derivations: {wall:.1} s wall, {c:.1} s CPU"),
        None => println!("derivations: {wall:.1} s wall"),
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
