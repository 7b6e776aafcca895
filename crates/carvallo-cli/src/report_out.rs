//! `carvallo report --out DIR [--model benchmark|FILE.toml]`: writes `DIR/report.md` (the
//! concordance grouped by the memoir's part, chapter and §, and the errata) and the SVG
//! figures of [`crate::figures`].
//!
//! Nothing is written unless everything succeeds: the directory is checked first (its parent
//! must exist; an existing `DIR` must be empty or a report directory written before, marked by
//! the file [`MARKER`], so that a mistyped `--out .` can never replace unrelated files), the
//! report and figures are computed in memory, written into a temporary sibling directory, and
//! that directory is renamed to `DIR`. A progress bar is drawn on standard error only when it is
//! a terminal.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};

use anyhow::{anyhow, Context, Result};
use carvallo::whipple::WhippleParams;

use crate::figures;

/// The file that marks a directory written by `carvallo report --out`.
pub const MARKER: &str = ".carvallo-report";

/// A bad output directory or parameter file (exit code 2), found before anything is written.
#[derive(Debug, PartialEq, Eq)]
pub struct BadInput(pub String);

impl std::fmt::Display for BadInput {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for BadInput {}

/// Checks that `dir` can receive a report; returns its parent directory.
pub fn check_out_dir(dir: &Path) -> Result<PathBuf, BadInput> {
    let shown = dir.display();
    if dir.file_name().is_none_or(|n| n == "." || n == "..") {
        return Err(BadInput(format!("invalid output directory `{shown}`: give a directory name")));
    }
    let parent = match dir.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if !parent.is_dir() {
        return Err(BadInput(format!(
            "invalid output directory `{shown}`: its parent `{}` is not an existing directory",
            parent.display()
        )));
    }
    if dir.exists() {
        if !dir.is_dir() {
            return Err(BadInput(format!(
                "invalid output directory `{shown}`: it is not a directory"
            )));
        }
        let empty = std::fs::read_dir(dir).map(|mut d| d.next().is_none()).unwrap_or(false);
        if !empty && !dir.join(MARKER).is_file() {
            return Err(BadInput(format!(
                "refusing to replace `{shown}`: it is not empty and was not written by `carvallo report --out`"
            )));
        }
    }
    Ok(parent)
}

/// Draws a progress bar `[####    ] k/n what` on standard error, if it is a terminal; the
/// line is ended when the work stops, also early by an error.
struct Progress {
    total: usize,
    done: usize,
    on: bool,
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.finish();
    }
}

impl Progress {
    fn new(total: usize) -> Progress {
        Progress { total, done: 0, on: std::io::stderr().is_terminal() }
    }

    /// Shows `what` as the work in progress, with the steps done so far.
    fn start(&self, what: &str) {
        if self.on {
            let width = 30;
            let filled = width * self.done / self.total.max(1);
            let bar: String = "#".repeat(filled) + &" ".repeat(width - filled);
            let mut err = std::io::stderr().lock();
            let _ = write!(err, "\r\x1b[2K[{bar}] {}/{} {what}", self.done, self.total);
            let _ = err.flush();
        }
    }

    fn done(&mut self) {
        self.done += 1;
    }

    fn finish(&mut self) {
        if self.on {
            let _ = writeln!(std::io::stderr().lock());
            self.on = false;
        }
    }
}

/// The Markdown section listing the figures (as images) and the missing ones.
pub fn figures_section(figs: &[figures::Figure]) -> String {
    let mut s = String::from("## Figures\n\n");
    for f in figs {
        s.push_str(&format!("### {}\n\n![{}]({})\n\n{}\n\n", f.title, f.title, f.file, f.caption));
    }
    s.push_str("### Figures not drawn yet\n\n");
    if figures::MISSING.is_empty() {
        s.push_str("None: every figure listed in the report's brief is drawn above.\n");
    }
    for m in &figures::MISSING {
        s.push_str(&format!("- {}: {}.\n", m.figure, m.reason));
    }
    s
}

/// Computes the report and the figures for the bicycle `params` (named `model`) and writes them
/// to `dir` (see the module docs). Returns the files written, relative to `dir`.
pub fn write_report(dir: &Path, params: &WhippleParams, model: &str) -> Result<Vec<String>> {
    let parent = check_out_dir(dir)?;
    let figs = figures::all();
    let mut progress = Progress::new(figs.len() + 2);
    progress.start("concordance");
    let entries = carvallo_report::all_entries();
    progress.done();
    let mut files: Vec<(String, String)> = Vec::new();
    for f in &figs {
        progress.start(f.file);
        let svg = (f.draw)(params).with_context(|| format!("cannot draw {}", f.file))?;
        files.push((f.file.to_string(), svg));
        progress.done();
    }
    progress.start("writing");
    let mut md = carvallo_report::render_markdown(&entries, &figures_section(&figs));
    if model != "benchmark" {
        md.push_str(&format!("The bicycle figures use the parameter file `{model}`.\n"));
    }
    files.insert(0, ("report.md".to_string(), md));
    files.push((MARKER.to_string(), "written by `carvallo report --out`\n".to_string()));
    let name = dir.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let tmp = parent.join(format!(".{name}.tmp-{}", std::process::id()));
    let result = write_all(&tmp, &files).and_then(|()| replace_dir(&tmp, dir));
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    progress.done();
    progress.start(if result.is_ok() { "written" } else { "failed" });
    progress.finish();
    result?;
    Ok(files.into_iter().map(|(n, _)| n).collect())
}

fn write_all(tmp: &Path, files: &[(String, String)]) -> Result<()> {
    std::fs::create_dir(tmp).with_context(|| format!("cannot create `{}`", tmp.display()))?;
    for (name, text) in files {
        let path = tmp.join(name);
        std::fs::write(&path, text)
            .with_context(|| format!("cannot write `{}`", path.display()))?;
    }
    Ok(())
}

/// Renames `tmp` to `dir`, moving an existing report directory aside first and removing it
/// afterwards.
fn replace_dir(tmp: &Path, dir: &Path) -> Result<()> {
    if dir.exists() {
        let old = tmp.with_extension("old");
        std::fs::rename(dir, &old)
            .with_context(|| format!("cannot move `{}` aside", dir.display()))?;
        if let Err(e) = std::fs::rename(tmp, dir) {
            let _ = std::fs::rename(&old, dir);
            return Err(anyhow!("cannot rename `{}` to `{}`: {e}", tmp.display(), dir.display()));
        }
        std::fs::remove_dir_all(&old)
            .with_context(|| format!("cannot remove `{}`", old.display()))?;
    } else {
        std::fs::rename(tmp, dir)
            .with_context(|| format!("cannot rename `{}` to `{}`", tmp.display(), dir.display()))?;
    }
    Ok(())
}
