//! Tidy checks of the workspace's source, in the style of rust-analyzer's `tidy` test: every
//! module opens with a `//!` doc, no test is ignored or expected to panic, and the layers point
//! one way (numerics → models → report → CLI), which the compiler alone does not enforce
//! inside a crate; the library is one folder per model, without `<model>_*.rs` prefixes.

use std::path::{Path, PathBuf};

/// The workspace root.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every `.rs` file under `dir` (relative to the root), sorted, `target/` skipped. A folder
/// that is missing or holds no Rust file is a failure: a rule over no file passes vacuously
/// (a renamed folder would silently end the checks of this file).
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
    assert!(!out.is_empty(), "no `.rs` file under {dir}: the tidy rules would check nothing");
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

/// The Python package's tests do not skip: a peer that is missing (BicycleParameters, yeadon,
/// dask, the binary) is an error, as `scripts/test` installs them all; a skipped module passes
/// with nothing compared.
#[test]
fn no_python_test_is_skipped() {
    // Spelled in pieces so that this file does not match itself.
    let forbidden = [
        concat!("import", "orskip"),
        concat!("pytest.", "skip"),
        concat!("mark.", "skip"),
        concat!("mark.", "xfail"),
        concat!("pytest.", "xfail"),
    ];
    let dir = root().join("crates/carvallo-py/tests");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "py"))
        .collect();
    files.sort();
    assert!(files.len() >= 10, "expected the Python tests in {}", dir.display());
    let mut found = Vec::new();
    for path in files {
        for (n, line) in read(&path).lines().enumerate() {
            if !line.trim_start().starts_with('#') && forbidden.iter().any(|f| line.contains(f)) {
                found.push(format!("{}:{}: {}", rel(&path), n + 1, line.trim()));
            }
        }
    }
    assert!(found.is_empty(), "a missing peer is an error, not a skip:\n{}", found.join("\n"));
}

/// The report modules that are leaves (shape, policy, samples, checks, outline, renderers).
const REPORT_LEAVES: [&str; 6] = ["entry", "policy", "sample", "checks", "outline", "render"];
/// The per-model report modules.
const REPORT_MODELS: [&str; 5] = ["hoop", "hoop_discussion", "unicycle", "whipple", "bicycle"];

/// The files allowed directly in `crates/carvallo/src`: everything else lives in a layer's
/// folder (`numerics/`) or in a model's (`hoop/`, `unicycle/`, `whipple/`, `bicycle/`,
/// `wheeled_pendulum/`).
const LIBRARY_ROOT_FILES: [&str; 3] = ["artifacts.rs", "error.rs", "lib.rs"];
/// The library's models, one folder each (mirrored by `codegen/src/derive/`, and by the report for
/// the memoir's models; the wheeled pendulum is not one).
const LIBRARY_MODELS: [&str; 5] = ["hoop", "unicycle", "whipple", "bicycle", "wheeled_pendulum"];
/// The flat module names of the first layout, kept in `lib.rs` only as hidden re-exports: the
/// library itself uses the new paths.
const OLD_LIBRARY_PATHS: [&str; 16] = [
    "bench",
    "bicycle_geometry",
    "bicycle_kinematics",
    "bicycle_rest",
    "bicycle_steady",
    "bicycle_straight",
    "bicycle_turn",
    "certified",
    "hoop_discussion",
    "parameter_text",
    "quartic",
    "sweep",
    "unicycle_discussion",
    "whipple_nonlinear",
    "whipple_uncertainty",
    "report",
];

/// The layout of the library: one folder per model, no `<model>_*.rs` prefixes, numerics as
/// leaves, no flat old path used inside the crate.
#[test]
fn library_is_layered_by_folders() {
    let mut wrong = Vec::new();
    let src = root().join("crates/carvallo/src");
    let Ok(entries) = std::fs::read_dir(&src) else { panic!("cannot list {}", src.display()) };
    let mut seen = 0;
    for entry in entries.flatten() {
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().to_string();
        if path.is_dir() {
            let model = LIBRARY_MODELS.contains(&name.as_str());
            if !(model || name == "numerics") {
                wrong
                    .push(format!("{}: a folder that is neither a model nor numerics", rel(&path)));
            }
            if model && !path.join("mod.rs").is_file() {
                wrong.push(format!("{}: a model folder without mod.rs", rel(&path)));
            }
            seen += usize::from(model);
        } else if name.ends_with(".rs") && !LIBRARY_ROOT_FILES.contains(&name.as_str()) {
            let stem = name.trim_end_matches(".rs");
            let prefixed =
                LIBRARY_MODELS.iter().find(|m| stem == **m || stem.starts_with(&format!("{m}_")));
            wrong.push(match prefixed {
                Some(m) => format!("{}: belongs in src/{m}/", rel(&path)),
                None => format!("{}: belongs in a model's folder or numerics/", rel(&path)),
            });
        }
    }
    assert_eq!(seen, LIBRARY_MODELS.len(), "a model folder is missing in {}", src.display());
    for path in rust_files("crates/carvallo/src") {
        let name = rel(&path);
        if name == "crates/carvallo/src/lib.rs" {
            continue;
        }
        for (n, line) in code_lines(&read(&path)) {
            for old in OLD_LIBRARY_PATHS {
                for prefix in ["crate::", "carvallo::"] {
                    let at = format!("{prefix}{old}");
                    let hit = line.match_indices(&at).any(|(i, _)| {
                        let next = line[i + at.len()..].chars().next();
                        !next.is_some_and(|c| c.is_alphanumeric() || c == '_')
                    });
                    if hit {
                        wrong.push(format!("{name}:{n}: `{at}` is an old path"));
                    }
                }
            }
        }
    }
    assert!(wrong.is_empty(), "library layout rules broken:\n{}", wrong.join("\n"));
}

#[test]
fn layers_point_one_way() {
    let mut wrong = Vec::new();
    // The library never names the report or the command line (the crate graph forbids `use`;
    // this also catches paths in macros and doc-free code).
    for path in rust_files("crates/carvallo/src") {
        let name = rel(&path);
        let text = read(&path);
        for (n, line) in code_lines(&text) {
            if line.contains("carvallo_report") {
                wrong.push(format!("{name}:{n}: the library names the report"));
            }
            if line.contains("carvallo_cli") {
                wrong.push(format!("{name}:{n}: the library names the command line"));
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
                if line.contains("super::super") {
                    wrong.push(format!("{name}:{n}: a numerics leaf reaches out of numerics"));
                }
            }
        }
    }
    // Generated artifacts are embedded in one place, `carvallo::artifacts`; the library's
    // benches and tests, the report and the command line read them from there.
    for dir in ["crates/carvallo", "crates/carvallo-report", "crates/carvallo-cli"] {
        for path in rust_files(dir) {
            let name = rel(&path);
            if name == "crates/carvallo/src/artifacts.rs" {
                continue;
            }
            for (n, line) in code_lines(&read(&path)) {
                if line.contains("include_str!") && line.contains("generated") {
                    wrong.push(format!("{name}:{n}: embeds generated/ outside artifacts.rs"));
                }
            }
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
    let mut applied = [0usize; 5];
    for path in rust_files("codegen/src") {
        let name = rel(&path);
        let text = read(&path);
        for (k, (prefix, forbidden)) in rules.iter().enumerate() {
            if !name.starts_with(prefix) {
                continue;
            }
            applied[k] += 1;
            for (n, line) in code_lines(&text) {
                for f in forbidden.iter() {
                    if line.contains(f) {
                        wrong.push(format!("{name}:{n}: {prefix} must not use {f}"));
                    }
                }
            }
        }
    }
    // A rule whose path names no file any more (a module moved) would pass vacuously.
    for ((prefix, _), n) in rules.iter().zip(applied) {
        assert!(n > 0, "the rule for {prefix} applies to no file of codegen/src");
    }
    assert!(wrong.is_empty(), "codegen layering rules broken:\n{}", wrong.join("\n"));
}

/// One shape per idea: an invalid input value is `carvallo::ParameterError` (other error enums
/// carry it in a variant such as `Parameter(ParameterError)`, not a look-alike variant of their
/// own), and a simulated motion is `carvallo::numerics::ode::Trajectory` (models name it with a
/// type alias, not a struct of their own).
#[test]
fn invalid_parameters_and_trajectories_have_one_shape() {
    let variants = ["InvalidParameter", "InvalidAngle", "InvalidValue", "InvalidInput"];
    let mut wrong = Vec::new();
    for path in rust_files("crates") {
        let name = rel(&path);
        for (n, line) in code_lines(&read(&path)) {
            let t = line.trim_start();
            let declares = variants.iter().find(|v| {
                t.strip_prefix(**v).is_some_and(|rest| {
                    let rest = rest.trim_start();
                    rest.starts_with('{') || rest.starts_with('(') || rest.starts_with(',')
                })
            });
            if let Some(v) = declares {
                if name != "crates/carvallo/src/error.rs" {
                    wrong.push(format!("{name}:{n}: a variant `{v}`: carry `ParameterError`"));
                }
            }
            if t.contains("struct Trajectory") && name != "crates/carvallo/src/numerics/ode.rs" {
                wrong.push(format!(
                    "{name}:{n}: a `Trajectory` struct: alias `numerics::ode::Trajectory`"
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "one shape per idea:\n{}", wrong.join("\n"));
}
