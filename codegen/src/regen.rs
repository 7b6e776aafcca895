//! `cargo xtask regen`: run every derivation, render every file of `generated/` in memory, then
//! either compare them with what is on disk (`check = true`, the staleness test) or replace
//! `generated/` atomically (`check = false`).
//!
//! Atomic replacement: the complete new tree is written to a sibling temporary directory
//! (`.generated.new` next to `generated/`), the old tree is renamed aside (`.generated.old`), the
//! new one is renamed into place and only then is the old one removed. Any failure before the
//! final swap leaves `generated/` exactly as it was (the temporary directory is removed on a
//! best-effort basis); a failure of the swap itself renames the old tree back. Every program is
//! also checked to round-trip through `Program::parse(program.to_text())` before anything is
//! written.
//!
//! All file-system effects of a write go through the [`TreeFs`] trait so that tests can inject
//! a failure at every single step and check that `generated/` is untouched.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::io::{self, IsTerminal};
use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};
use carvallo_ir::Program;

use crate::emit::{emit_program, generated_header, normalize_text, render_checks, render_markdown};
use crate::Derivation;

/// A derivation entry point.
pub type DeriveFn = fn() -> Result<Derivation>;

/// Every derivation `cargo xtask regen` runs, in order: (model name, entry point).
pub const DERIVATIONS: &[(&str, DeriveFn)] = &[
    ("hoop", crate::hoop::derive),
    ("hoop_discussion", crate::hoop_discussion::derive),
    ("whipple", crate::whipple::derive),
    ("unicycle", crate::unicycle::derive),
    ("whipple_nonlinear", crate::whipple_nonlinear::derive),
    ("bicycle_steady", crate::bicycle_steady::derive),
    ("bicycle_geometry", crate::bicycle_geometry::derive),
    ("bicycle_kinematics", crate::bicycle_kinematics::derive),
    ("bicycle_straight", crate::bicycle_straight::derive),
];

/// The directory, relative to the workspace root, that holds the generated files.
pub const GENERATED_DIR: &str = "generated";

/// What happened to one generated file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum FileStatus {
    /// On disk and identical.
    Fresh,
    /// On disk with other contents (check) or rewritten with new contents (write).
    Stale,
    /// Not on disk (check) or newly created (write).
    Missing,
    /// On disk but not produced by any derivation (check) or removed (write).
    Extra,
}

/// The outcome of one model's derivation.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ModelSummary {
    /// The model name.
    pub model: String,
    /// Its output names, in order.
    pub outputs: Vec<String>,
    /// Op count of the whole program (non-constant instructions).
    pub ops: usize,
    /// Number of checks, and how many of them hold.
    pub checks: (usize, usize),
}

/// What `regen` did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RegenSummary {
    /// Whether this was a check (nothing written).
    pub check: bool,
    /// Every file compared, by its path relative to `generated/`, sorted.
    pub files: Vec<(String, FileStatus)>,
    /// The models derived, in order.
    pub models: Vec<ModelSummary>,
}

impl RegenSummary {
    /// The files that differed from (or were missing from, or extra in) the tree on disk.
    pub fn changed(&self) -> Vec<&str> {
        self.files
            .iter()
            .filter(|(_, s)| *s != FileStatus::Fresh)
            .map(|(p, _)| p.as_str())
            .collect()
    }
}

/// File-system operations used to write the new tree.
pub trait TreeFs {
    /// Creates a directory (its parent exists).
    fn create_dir(&mut self, path: &Path) -> io::Result<()>;
    /// Writes a whole file.
    fn write(&mut self, path: &Path, contents: &[u8]) -> io::Result<()>;
    /// Renames a directory.
    fn rename(&mut self, from: &Path, to: &Path) -> io::Result<()>;
    /// Removes a directory tree.
    fn remove_dir_all(&mut self, path: &Path) -> io::Result<()>;
}

/// The real file system.
#[derive(Clone, Copy, Debug, Default)]
pub struct RealFs;

impl TreeFs for RealFs {
    fn create_dir(&mut self, path: &Path) -> io::Result<()> {
        fs::create_dir(path)
    }
    fn write(&mut self, path: &Path, contents: &[u8]) -> io::Result<()> {
        fs::write(path, contents)
    }
    fn rename(&mut self, from: &Path, to: &Path) -> io::Result<()> {
        fs::rename(from, to)
    }
    fn remove_dir_all(&mut self, path: &Path) -> io::Result<()> {
        fs::remove_dir_all(path)
    }
}

/// Runs every derivation of [`DERIVATIONS`] and checks (`check = true`) or rewrites
/// (`check = false`) `<workspace_root>/generated/`.
pub fn regen(workspace_root: &Path, check: bool) -> Result<RegenSummary> {
    regen_with(workspace_root, check, DERIVATIONS, &mut RealFs)
}

/// [`regen`] with an explicit list of derivations and file system (for tests).
pub fn regen_with(
    workspace_root: &Path,
    check: bool,
    derivations: &[(&str, DeriveFn)],
    fs_ops: &mut dyn TreeFs,
) -> Result<RegenSummary> {
    let mut ds = Vec::with_capacity(derivations.len());
    // A progress bar on a terminal only; nothing when standard error is a file or a pipe.
    let progress = std::io::stderr().is_terminal();
    let n = derivations.len();
    for (k, (name, derive)) in derivations.iter().enumerate() {
        if progress {
            let bar =
                format!("{}{}", "#".repeat(20 * k / n.max(1)), "-".repeat(20 - 20 * k / n.max(1)));
            eprint!("\r[{bar}] {k}/{n} deriving {name:<24}");
        }
        let d = derive().with_context(|| format!("derivation {name} failed"));
        if progress && (d.is_err() || k + 1 == n) {
            eprintln!(
                "\r[{}] {}/{n} derived{:<32}",
                "#".repeat(20),
                k + usize::from(d.is_ok()),
                ""
            );
        }
        let d = d?;
        if d.model != *name {
            bail!("derivation {name} returned model {:?}", d.model);
        }
        ds.push(d);
    }
    let (files, models) = render_all(&ds)?;
    let dir = workspace_root.join(GENERATED_DIR);
    let on_disk = read_tree(&dir)?;
    let statuses = compare(&files, &on_disk);
    let summary = RegenSummary { check, files: statuses, models };
    if check {
        let changed = summary.changed();
        if !changed.is_empty() {
            let list = |s: FileStatus| {
                summary
                    .files
                    .iter()
                    .filter(|(_, x)| *x == s)
                    .map(|(p, _)| p.as_str())
                    .collect::<Vec<_>>()
            };
            let mut parts = Vec::new();
            for (label, s) in [
                ("stale", FileStatus::Stale),
                ("missing", FileStatus::Missing),
                ("extra", FileStatus::Extra),
            ] {
                let l = list(s);
                if !l.is_empty() {
                    parts.push(format!("{label}: {}", l.join(", ")));
                }
            }
            bail!(
                "{} is out of date ({}); run `cargo xtask regen` and commit the result",
                dir.display(),
                parts.join("; ")
            );
        }
        return Ok(summary);
    }
    if summary.changed().is_empty() {
        return Ok(summary);
    }
    write_tree_atomically(&dir, &files, fs_ops)?;
    Ok(summary)
}

/// Every generated file, by its path relative to `generated/`, and the model summaries.
pub fn render_all(ds: &[Derivation]) -> Result<(BTreeMap<String, String>, Vec<ModelSummary>)> {
    let mut files = BTreeMap::new();
    let mut models = Vec::new();
    for d in ds {
        let program = emit_program(d).with_context(|| format!("cannot emit model {}", d.model))?;
        let ir = program.to_text();
        check_round_trip(&program, &ir).with_context(|| format!("model {}", d.model))?;
        let md = render_markdown(d).with_context(|| format!("cannot render model {}", d.model))?;
        let tsv = render_checks(d);
        for (ext, contents) in [("ir", ir), ("md", md), ("checks.tsv", tsv)] {
            let name = format!("{}.{ext}", d.model);
            if files.insert(name.clone(), contents).is_some() {
                bail!("two derivations write {name}");
            }
        }
        let (ops, _) = crate::emit::count_ops(&program);
        models.push(ModelSummary {
            model: d.model.clone(),
            outputs: program.outputs.iter().map(|o| o.name.clone()).collect(),
            ops,
            checks: (d.checks.len(), d.checks.iter().filter(|c| c.holds).count()),
        });
    }
    files.insert("README.md".to_string(), render_readme(ds));
    for (name, contents) in &files {
        if normalize_text(contents) != *contents {
            bail!("rendered file {name} is not normalised (LF, no trailing spaces, one final newline)");
        }
    }
    Ok((files, models))
}

/// Checks that `text` is `program.to_text()` and parses back to exactly `program`.
fn check_round_trip(program: &Program, text: &str) -> Result<()> {
    program.validate().map_err(|e| anyhow!("emitted program is invalid: {e}"))?;
    let parsed =
        Program::parse(text).map_err(|e| anyhow!("emitted program does not parse back: {e}"))?;
    if parsed != *program {
        bail!("emitted program does not round-trip through its text form");
    }
    if parsed.to_text() != text {
        bail!("emitted program text is not stable under parse and print");
    }
    Ok(())
}

/// `generated/README.md`.
fn render_readme(ds: &[Derivation]) -> String {
    let mut s = String::new();
    let sources: BTreeSet<&str> = ds.iter().map(|d| d.source.as_str()).collect();
    let sources: Vec<&str> = sources.into_iter().collect();
    s.push_str(&format!("<!-- {} -->\n\n", generated_header(&sources.join(", "))));
    s.push_str("# generated/\n\n");
    s.push_str(
        "Everything in this directory is written by `cargo xtask regen` from the symbolic derivations in \
         `codegen/` (which use the `symbolica` crate). Do not edit these files by hand: change the \
         derivation and run the command again. `cargo xtask regen --check` (and the test \
         `codegen/tests/regen_fresh.rs`) fails when this directory is out of date.\n\n",
    );
    s.push_str("For each model `<model>`:\n\n");
    s.push_str(
        "- `<model>.ir`: the model's formulas as one straight-line program in the `carvallo-ir` text format \
         (parameters, inputs, SSA instructions with shared common subexpressions, outputs). The \
         `scene!` proc-macro and the runtime read it; they do not need symbolica.\n",
    );
    s.push_str(
        "- `<model>.md`: each formula with its memoir section (n°), description, plain-text and LaTeX \
         forms and op count.\n",
    );
    s.push_str(
        "- `<model>.checks.tsv`: the symbolic checks made during the derivation, one per line: \
         `section<TAB>id<TAB>holds<TAB>statement<TAB>detail`.\n\n",
    );
    s.push_str("Models:\n\n");
    for d in ds {
        s.push_str(&format!(
            "- `{}` from `{}`: {} outputs, {} checks.\n",
            d.model,
            d.source,
            d.formulas.len(),
            d.checks.len()
        ));
    }
    normalize_text(&s)
}

/// The regular files of `dir` by relative path (`/`-separated); subdirectories are listed as
/// extra entries with a trailing `/`. A missing directory is an empty tree.
fn read_tree(dir: &Path) -> Result<BTreeMap<String, Option<Vec<u8>>>> {
    let mut out = BTreeMap::new();
    let entries = match fs::read_dir(dir) {
        Ok(e) => e,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(out),
        Err(e) => return Err(e).with_context(|| format!("cannot read {}", dir.display())),
    };
    for entry in entries {
        let entry = entry.with_context(|| format!("cannot read {}", dir.display()))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        let path = entry.path();
        if entry.file_type()?.is_dir() {
            out.insert(format!("{name}/"), None);
        } else {
            let bytes =
                fs::read(&path).with_context(|| format!("cannot read {}", path.display()))?;
            out.insert(name, Some(bytes));
        }
    }
    Ok(out)
}

fn compare(
    files: &BTreeMap<String, String>,
    on_disk: &BTreeMap<String, Option<Vec<u8>>>,
) -> Vec<(String, FileStatus)> {
    let mut out = Vec::new();
    for (name, contents) in files {
        let status = match on_disk.get(name) {
            Some(Some(bytes)) if bytes.as_slice() == contents.as_bytes() => FileStatus::Fresh,
            Some(_) => FileStatus::Stale,
            None => FileStatus::Missing,
        };
        out.push((name.clone(), status));
    }
    for name in on_disk.keys() {
        if !files.contains_key(name) {
            out.push((name.clone(), FileStatus::Extra));
        }
    }
    out.sort();
    out
}

fn sibling(dir: &Path, suffix: &str) -> Result<PathBuf> {
    let parent =
        dir.parent().ok_or_else(|| anyhow!("{} has no parent directory", dir.display()))?;
    let name = dir
        .file_name()
        .ok_or_else(|| anyhow!("{} has no file name", dir.display()))?
        .to_string_lossy();
    Ok(parent.join(format!(".{name}.{suffix}")))
}

/// Replaces `dir` by a directory holding exactly `files`, atomically as described in the
/// module docs.
pub fn write_tree_atomically(
    dir: &Path,
    files: &BTreeMap<String, String>,
    fs_ops: &mut dyn TreeFs,
) -> Result<()> {
    let new = sibling(dir, "new")?;
    let old = sibling(dir, "old")?;
    // Leftovers of an interrupted earlier run are not part of the tree: clear them first.
    for leftover in [&new, &old] {
        if leftover.exists() {
            fs_ops
                .remove_dir_all(leftover)
                .with_context(|| format!("cannot remove leftover {}", leftover.display()))?;
        }
    }
    let staged = (|| -> Result<()> {
        fs_ops.create_dir(&new).with_context(|| format!("cannot create {}", new.display()))?;
        for (name, contents) in files {
            let path = new.join(name);
            fs_ops
                .write(&path, contents.as_bytes())
                .with_context(|| format!("cannot write {}", path.display()))?;
        }
        Ok(())
    })();
    if let Err(e) = staged {
        let _ = fs_ops.remove_dir_all(&new);
        return Err(e.context(format!("{} left unchanged", dir.display())));
    }
    let had_old = dir.exists();
    if had_old {
        if let Err(e) = fs_ops.rename(dir, &old) {
            let _ = fs_ops.remove_dir_all(&new);
            return Err(anyhow::Error::new(e)
                .context(format!("cannot move {} aside; it is left unchanged", dir.display())));
        }
    }
    if let Err(e) = fs_ops.rename(&new, dir) {
        let restore = if had_old { fs_ops.rename(&old, dir) } else { Ok(()) };
        let _ = fs_ops.remove_dir_all(&new);
        return Err(match restore {
            Ok(()) => anyhow::Error::new(e)
                .context(format!("cannot move the new tree into place; {} left unchanged", dir.display())),
            Err(r) => anyhow::Error::new(e).context(format!(
                "cannot move the new tree into place, and restoring the old tree from {} failed too ({r})",
                old.display()
            )),
        });
    }
    if had_old {
        fs_ops.remove_dir_all(&old).with_context(|| {
            format!(
                "{} was updated but the old tree {} could not be removed",
                dir.display(),
                old.display()
            )
        })?;
    }
    Ok(())
}
