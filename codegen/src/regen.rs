//! `cargo xtask regen`: run the derivations, render every file of `generated/` in memory, then
//! either compare them with what is on disk (`check = true`, the staleness test) or replace
//! `generated/` atomically (`check = false`).
//!
//! A regeneration may name some models ([`Selection::Only`]): only those are re-derived; the
//! files of every other model are taken from disk as they are, after checking that they are
//! there, that their IR parses and that their headers name the derivation's source, and the
//! index `generated/README.md` is rebuilt from both. Each derivation's wall time and CPU time
//! are recorded in its [`ModelSummary`].
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
use std::time::{Duration, Instant};

use anyhow::{anyhow, bail, Context, Result};
use carvallo_ir::Program;

pub use crate::derive::{DeriveFn, DERIVATIONS};
use crate::emit::{choose, generated_header, normalize_text, render_checks, render_markdown};
use crate::Derivation;

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
    /// How long its derivation and emission took, or `None` when its files were taken from
    /// disk unchanged (a regeneration that named other models).
    pub time: Option<DeriveTime>,
}

/// The cost of one model's derivation and emission.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DeriveTime {
    /// Wall-clock time.
    pub wall: Duration,
    /// CPU time of the process (user + system) over the same span, or `None` where the
    /// platform does not report it (read from `/proc/self/stat` on Linux).
    pub cpu: Option<Duration>,
}

/// Which models a regeneration re-derives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Selection<'a> {
    /// Every model of the derivation list.
    All,
    /// Only these (by model name); the files of the others are kept as they are on disk.
    Only(&'a [String]),
}

impl Selection<'_> {
    fn includes(&self, model: &str) -> bool {
        match self {
            Selection::All => true,
            Selection::Only(names) => names.iter().any(|n| n == model),
        }
    }
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

/// [`regen`] of the models in `selection` only: the files of the others are taken from disk
/// unchanged (they must be there and valid). An unknown model name is an error listing the
/// known ones, and nothing is written.
pub fn regen_models(
    workspace_root: &Path,
    check: bool,
    selection: Selection<'_>,
) -> Result<RegenSummary> {
    regen_selected(workspace_root, check, DERIVATIONS, selection, &mut RealFs)
}

/// [`regen`] with an explicit list of derivations and file system (for tests).
pub fn regen_with(
    workspace_root: &Path,
    check: bool,
    derivations: &[(&str, DeriveFn)],
    fs_ops: &mut dyn TreeFs,
) -> Result<RegenSummary> {
    regen_selected(workspace_root, check, derivations, Selection::All, fs_ops)
}

/// [`regen_models`] with an explicit list of derivations and file system (for tests).
pub fn regen_selected(
    workspace_root: &Path,
    check: bool,
    derivations: &[(&str, DeriveFn)],
    selection: Selection<'_>,
    fs_ops: &mut dyn TreeFs,
) -> Result<RegenSummary> {
    if let Selection::Only(names) = selection {
        if names.is_empty() {
            bail!("no model named to regenerate");
        }
        let known: Vec<&str> = derivations.iter().map(|(n, _)| *n).collect();
        for name in names {
            if !known.contains(&name.as_str()) {
                bail!("unknown model {name:?} (known models: {})", known.join(", "));
            }
        }
    }
    // Every model prints its terms in the order of a full regeneration, however many are derived.
    crate::derive::declare_symbols();
    // The lowering's placeholders next, so they have the same identities in every process.
    crate::emit::declare_placeholders();
    let dir = workspace_root.join(GENERATED_DIR);
    let on_disk = read_tree(&dir)?;
    let mut models = Vec::with_capacity(derivations.len());
    // A progress bar on a terminal only; nothing when standard error is a file or a pipe.
    let progress = std::io::stderr().is_terminal();
    let n = derivations.iter().filter(|(name, _)| selection.includes(name)).count();
    let mut k = 0;
    for (name, derive) in derivations.iter().copied() {
        if !selection.includes(name) {
            models.push((kept_model(name, &on_disk)?, None));
            continue;
        }
        if progress {
            let bar =
                format!("{}{}", "#".repeat(20 * k / n.max(1)), "-".repeat(20 - 20 * k / n.max(1)));
            eprint!("\r[{bar}] {k}/{n} deriving {name:<24}");
        }
        let start = Instant::now();
        let cpu_start = process_cpu_time();
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
        if d.model != name {
            bail!("derivation {name} returned model {:?}", d.model);
        }
        let rendered = render_model(&d)?;
        let cpu = match (cpu_start, process_cpu_time()) {
            (Some(a), Some(b)) => Some(b.saturating_sub(a)),
            _ => None,
        };
        models.push((rendered, Some(DeriveTime { wall: start.elapsed(), cpu })));
        k += 1;
    }
    let (files, models) = assemble(models)?;
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

/// The three files of one model (`.ir`, `.md`, `.checks.tsv`) by name, and what the index
/// `generated/README.md` says of it.
struct Rendered {
    files: Vec<(String, String)>,
    info: ModelInfo,
    ops: usize,
    outputs: Vec<String>,
    checks: (usize, usize),
}

/// What `generated/README.md` lists of a model.
#[derive(Clone, Debug, PartialEq, Eq)]
struct ModelInfo {
    model: String,
    source: String,
    formulas: usize,
    checks: usize,
}

/// Every generated file, by its path relative to `generated/`, and the model summaries.
pub fn render_all(ds: &[Derivation]) -> Result<(BTreeMap<String, String>, Vec<ModelSummary>)> {
    let models = ds.iter().map(|d| Ok((render_model(d)?, None))).collect::<Result<Vec<_>>>()?;
    assemble(models)
}

/// Renders one derivation into its three files.
fn render_model(d: &Derivation) -> Result<Rendered> {
    let (mut program, lowering) =
        choose(d).with_context(|| format!("cannot emit model {}", d.model))?;
    program.header.extend(lowering);
    let ir = program.to_text();
    check_round_trip(&program, &ir).with_context(|| format!("model {}", d.model))?;
    let md = render_markdown(d).with_context(|| format!("cannot render model {}", d.model))?;
    let tsv = render_checks(d);
    let files = [("ir", ir), ("md", md), ("checks.tsv", tsv)]
        .into_iter()
        .map(|(ext, contents)| (format!("{}.{ext}", d.model), contents))
        .collect();
    let (ops, _) = crate::emit::count_ops(&program);
    Ok(Rendered {
        files,
        info: ModelInfo {
            model: d.model.clone(),
            source: d.source.clone(),
            formulas: d.formulas.len(),
            checks: d.checks.len(),
        },
        ops,
        outputs: program.outputs.iter().map(|o| o.name.clone()).collect(),
        checks: (d.checks.len(), d.checks.iter().filter(|c| c.holds).count()),
    })
}

/// The files of a model that this regeneration does not re-derive, as they are on disk: all
/// three must be there, the IR must parse and validate, and the three headers must name the
/// same source (what the index lists).
fn kept_model(model: &str, on_disk: &BTreeMap<String, Option<Vec<u8>>>) -> Result<Rendered> {
    let text = |ext: &str| -> Result<String> {
        let name = format!("{model}.{ext}");
        match on_disk.get(&name) {
            Some(Some(bytes)) => String::from_utf8(bytes.clone()).map_err(|_| {
                anyhow!("generated/{name} is not UTF-8; run `cargo xtask regen {model}`")
            }),
            _ => bail!("generated/{name} is missing; run `cargo xtask regen {model}`"),
        }
    };
    let (ir, md, tsv) = (text("ir")?, text("md")?, text("checks.tsv")?);
    let program = Program::parse(&ir).map_err(|e| {
        anyhow!("generated/{model}.ir does not parse ({e}); run `cargo xtask regen {model}`")
    })?;
    program.validate().map_err(|e| {
        anyhow!("generated/{model}.ir is invalid ({e}); run `cargo xtask regen {model}`")
    })?;
    let source = header_source(&ir)
        .ok_or_else(|| anyhow!("generated/{model}.ir has no generated header naming its source"))?;
    for (ext, contents) in [("md", &md), ("checks.tsv", &tsv)] {
        if header_source(contents).as_deref() != Some(source.as_str()) {
            bail!("generated/{model}.{ext} does not name the source {source} of generated/{model}.ir; run `cargo xtask regen {model}`");
        }
    }
    let check_lines: Vec<&str> =
        tsv.lines().filter(|l| !l.starts_with('#') && !l.trim().is_empty()).collect();
    let holding = check_lines.iter().filter(|l| l.split('\t').nth(2) == Some("true")).count();
    let checks = (check_lines.len(), holding);
    let outputs: Vec<String> = program.outputs.iter().map(|o| o.name.clone()).collect();
    let (ops, _) = crate::emit::count_ops(&program);
    Ok(Rendered {
        info: ModelInfo {
            model: model.to_string(),
            source,
            formulas: outputs.len(),
            checks: checks.0,
        },
        files: vec![
            (format!("{model}.ir"), ir),
            (format!("{model}.md"), md),
            (format!("{model}.checks.tsv"), tsv),
        ],
        ops,
        outputs,
        checks,
    })
}

/// The source named by a generated file's first line (the header of [`generated_header`]).
fn header_source(contents: &str) -> Option<String> {
    let first = contents.lines().next()?;
    let rest = first.split_once("from ")?.1;
    let source = rest.split_once("; do not edit by hand")?.0;
    Some(source.to_string())
}

/// The whole tree (every model's files and the index) and the summaries, in derivation order;
/// each model comes with the time of its derivation (`None`: kept from disk).
fn assemble(
    models: Vec<(Rendered, Option<DeriveTime>)>,
) -> Result<(BTreeMap<String, String>, Vec<ModelSummary>)> {
    let mut files = BTreeMap::new();
    let mut summaries = Vec::with_capacity(models.len());
    let mut infos = Vec::with_capacity(models.len());
    for (r, time) in models {
        for (name, contents) in r.files {
            if files.insert(name.clone(), contents).is_some() {
                bail!("two derivations write {name}");
            }
        }
        summaries.push(ModelSummary {
            model: r.info.model.clone(),
            outputs: r.outputs,
            ops: r.ops,
            checks: r.checks,
            time,
        });
        infos.push(r.info);
    }
    files.insert("README.md".to_string(), render_readme(&infos));
    for (name, contents) in &files {
        if normalize_text(contents) != *contents {
            bail!("rendered file {name} is not normalised (LF, no trailing spaces, one final newline)");
        }
    }
    Ok((files, summaries))
}

/// CPU time (user + system) of this process so far, from `/proc/self/stat` (Linux; fields 14
/// and 15 in clock ticks of 1/100 s, the USER_HZ of every Linux ABI); `None` elsewhere.
fn process_cpu_time() -> Option<Duration> {
    let stat = fs::read_to_string("/proc/self/stat").ok()?;
    // The command name (field 2) is in parentheses and may contain spaces: count after it.
    let after = stat.rsplit_once(')')?.1;
    let fields: Vec<&str> = after.split_whitespace().collect();
    let utime: u64 = fields.get(11)?.parse().ok()?;
    let stime: u64 = fields.get(12)?.parse().ok()?;
    Some(Duration::from_millis((utime + stime) * 10))
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
fn render_readme(ds: &[ModelInfo]) -> String {
    let mut s = String::new();
    let sources: BTreeSet<&str> = ds.iter().map(|d| d.source.as_str()).collect();
    let sources: Vec<&str> = sources.into_iter().collect();
    s.push_str(&format!("<!-- {} -->\n\n", generated_header(&sources.join(", "))));
    s.push_str("# generated/\n\n");
    s.push_str(
        "Everything in this directory is written by `cargo xtask regen` from the symbolic derivations in \
         `codegen/` (which use the `symbolica` crate). Do not edit these files by hand: change the \
         derivation and run the command again. `cargo xtask regen --check` (and the test \
         `codegen/tests/derive/regen_fresh.rs`) fails when this directory is out of date.\n\n",
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
            d.model, d.source, d.formulas, d.checks
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

/// Each file of `files` (by path relative to `generated/`) compared with
/// `<workspace_root>/generated/`, and every file on disk that `files` does not have
/// ([`FileStatus::Extra`]), sorted by name.
pub fn compare_with_disk(
    workspace_root: &Path,
    files: &BTreeMap<String, String>,
) -> Result<Vec<(String, FileStatus)>> {
    Ok(compare(files, &read_tree(&workspace_root.join(GENERATED_DIR))?))
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
