//! Tidy checks of the workspace's source, in the style of rust-analyzer's `tidy` test: every
//! module opens with a `//!` doc, no test is ignored or expected to panic, and the layers point
//! one way (numerics → models → report → CLI), which the compiler alone does not enforce
//! inside a crate.

use std::path::{Path, PathBuf};

/// The workspace root.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every `.rs` file under `dir` (relative to the root), sorted, `target/` skipped.
fn rust_files(dir: &str) -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else { return };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                if path.file_name().is_some_and(|n| n != "target") {
                    walk(&path, out);
                }
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    let mut out = Vec::new();
    walk(&root().join(dir), &mut out);
    out.sort();
    out
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()))
}

/// The path relative to the root, with `/` separators, for messages and rules.
fn rel(path: &Path) -> String {
    let root = root();
    let r = path.strip_prefix(&root).unwrap_or(path);
    r.components().map(|c| c.as_os_str().to_string_lossy()).collect::<Vec<_>>().join("/")
}

/// The lines of `text` that are code: comment lines (`//`, `///`, `//!`) left out.
fn code_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.trim_start().starts_with("//"))
        .map(|(i, l)| (i + 1, l))
}

#[test]
fn every_module_opens_with_a_doc_comment() {
    let mut missing = Vec::new();
    for dir in ["crates", "tests", "codegen", "xtask"] {
        for path in rust_files(dir) {
            if !read(&path).starts_with("//!") {
                missing.push(rel(&path));
            }
        }
    }
    assert!(missing.is_empty(), "files without a `//!` first line:\n{}", missing.join("\n"));
}

#[test]
fn no_test_is_ignored_or_expected_to_panic() {
    // Spelled in two pieces so that this file does not match itself.
    let forbidden = [concat!("#[should", "_panic"), concat!("#[ig", "nore")];
    let mut found = Vec::new();
    for dir in ["crates", "tests", "codegen", "xtask"] {
        for path in rust_files(dir) {
            for (n, line) in code_lines(&read(&path)) {
                if forbidden.iter().any(|f| line.contains(f)) {
                    found.push(format!("{}:{n}: {}", rel(&path), line.trim()));
                }
            }
        }
    }
    assert!(
        found.is_empty(),
        "assert on the `Err` value instead (STYLE.md):\n{}",
        found.join("\n")
    );
}

/// The report modules that are leaves (shape, policy, samples, checks, outline, renderers).
const REPORT_LEAVES: [&str; 6] = ["entry", "policy", "sample", "checks", "outline", "render"];
/// The per-model report modules.
const REPORT_MODELS: [&str; 5] = ["hoop", "hoop_discussion", "unicycle", "whipple", "bicycle"];

#[test]
fn layers_point_one_way() {
    let mut wrong = Vec::new();
    // The library never names the report (the crate graph forbids `use`; this also catches
    // paths in macros and doc-free code).
    for path in rust_files("crates/carvallo/src") {
        let name = rel(&path);
        let text = read(&path);
        for (n, line) in code_lines(&text) {
            if line.contains("carvallo_report") {
                wrong.push(format!("{name}:{n}: the library names the report"));
            }
        }
        // Numerics are leaves: no path into the rest of the crate.
        if name.starts_with("crates/carvallo/src/numerics/") {
            for (n, line) in code_lines(&text) {
                let mut rest = line;
                while let Some(at) = rest.find("crate::") {
                    rest = &rest[at + "crate::".len()..];
                    if !rest.starts_with("numerics") {
                        wrong.push(format!("{name}:{n}: a numerics leaf imports a model"));
                    }
                }
            }
        }
        // Generated artifacts are embedded in one place (bench.rs until it moves to the CLI).
        let embeds = text.contains("include_str!(\"../../../generated")
            || text.contains("include_str!(concat!(\"../../../generated");
        let allowed = ["crates/carvallo/src/artifacts.rs", "crates/carvallo/src/bench.rs"];
        if embeds && !allowed.contains(&name.as_str()) {
            wrong.push(format!("{name}: embeds generated/ outside artifacts.rs"));
        }
    }
    // In the report, leaves import no model report, and a model report no other one (except
    // the hoop's, which folds in the points of the hoop discussion).
    for path in rust_files("crates/carvallo-report/src") {
        let name = rel(&path);
        let module = name
            .trim_start_matches("crates/carvallo-report/src/")
            .trim_end_matches(".rs")
            .split('/')
            .next()
            .unwrap_or_default()
            .to_string();
        if module == "lib" {
            continue;
        }
        for (n, line) in code_lines(&read(&path)) {
            for model in REPORT_MODELS {
                let uses = line.contains(&format!("crate::{model}::"))
                    || line.contains(&format!("crate::{model};"))
                    || line.contains(&format!("crate::{{{model}"));
                let own = module == model;
                let allowed = module == "hoop" && model == "hoop_discussion";
                if uses && !own && !allowed {
                    let what = if REPORT_LEAVES.contains(&module.as_str()) {
                        "a leaf"
                    } else {
                        "a model report"
                    };
                    wrong.push(format!("{name}:{n}: {what} imports the report of {model}"));
                }
            }
        }
    }
    assert!(wrong.is_empty(), "layering rules broken:\n{}", wrong.join("\n"));
}

/// The derivation side's layers: the shared algebra (`cas`), the mechanics and the memoir's
/// transcription shape are leaves; the emission knows no derivation; no derivation knows the
/// regeneration that runs it.
#[test]
fn codegen_layers_point_one_way() {
    let rules: [(&str, &[&str]); 5] = [
        (
            "codegen/src/cas.rs",
            &["crate::derive", "crate::emit", "crate::regen", "crate::mechanics", "crate::memoir"],
        ),
        (
            "codegen/src/mechanics/",
            &["crate::derive", "crate::emit", "crate::regen", "crate::memoir"],
        ),
        (
            "codegen/src/memoir.rs",
            &["crate::derive", "crate::emit", "crate::regen", "crate::mechanics"],
        ),
        (
            "codegen/src/emit/",
            &["crate::derive", "crate::regen", "crate::mechanics", "crate::memoir"],
        ),
        ("codegen/src/derive/", &["crate::regen", "crate::emit"]),
    ];
    let mut wrong = Vec::new();
    for path in rust_files("codegen/src") {
        let name = rel(&path);
        let text = read(&path);
        for (prefix, forbidden) in rules {
            if !name.starts_with(prefix) {
                continue;
            }
            for (n, line) in code_lines(&text) {
                for f in forbidden {
                    if line.contains(f) {
                        wrong.push(format!("{name}:{n}: {prefix} must not use {f}"));
                    }
                }
            }
        }
    }
    assert!(wrong.is_empty(), "codegen layering rules broken:\n{}", wrong.join("\n"));
}
