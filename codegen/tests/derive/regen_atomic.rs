//! Tests of `regen` on scratch workspaces: check mode reports stale, missing and extra files and
//! names the command; write mode replaces `generated/` atomically — a failing derivation, and a
//! file-system failure injected at every single step of the write, leave the old tree exactly as
//! it was. A regeneration of some models only re-derives those and keeps the others' files as
//! they are on disk, rejecting an unknown model name or a kept model whose files are missing.

use std::collections::BTreeMap;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use anyhow::{bail, Result};
use carvallo_codegen::regen::{
    regen_selected, regen_with, DeriveFn, FileStatus, RealFs, Selection, TreeFs,
};
use carvallo_codegen::{Check, Derivation, Formula};
use symbolica::parse;

fn toy(expr: &str) -> Derivation {
    toy_model("toy", expr)
}

fn toy_model(model: &str, expr: &str) -> Derivation {
    Derivation {
        model: model.to_string(),
        source: "codegen/tests/derive/regen_atomic.rs".to_string(),
        params: vec!["a".to_string()],
        inputs: vec!["x".to_string()],
        formulas: vec![Formula {
            name: "y".to_string(),
            section: "1".to_string(),
            description: "A toy formula.".to_string(),
            expr: parse!(expr),
        }],
        checks: vec![Check {
            perturbed: None,
            section: "1".to_string(),
            id: "toy_check".to_string(),
            statement: "a toy check".to_string(),
            holds: true,
            detail: "none".to_string(),
        }],
        nominal: Vec::new(),
        horner_schemes: Vec::new(),
    }
}

fn toy_v1() -> Result<Derivation> {
    Ok(toy("a*sin(x)^2 + 1"))
}

fn toy_v2() -> Result<Derivation> {
    Ok(toy("a*cos(x)/x - 3/2"))
}

fn other_v1() -> Result<Derivation> {
    Ok(toy_model("other", "x + a"))
}

fn other_v2() -> Result<Derivation> {
    Ok(toy_model("other", "x - a"))
}

fn failing() -> Result<Derivation> {
    bail!("the toy derivation fails on purpose")
}

fn unemittable() -> Result<Derivation> {
    Ok(toy("a*nobody + x"))
}

/// A fresh scratch workspace root.
fn scratch(tag: &str) -> PathBuf {
    static N: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "carvallo-regen-{tag}-{}-{}",
        std::process::id(),
        N.fetch_add(1, Ordering::SeqCst)
    ));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

/// Every file under `dir` (relative path -> bytes), or `None` if it does not exist.
fn snapshot(dir: &Path) -> Option<BTreeMap<String, Vec<u8>>> {
    fn walk(base: &Path, dir: &Path, out: &mut BTreeMap<String, Vec<u8>>) {
        for e in fs::read_dir(dir).unwrap() {
            let e = e.unwrap();
            let p = e.path();
            let rel = p.strip_prefix(base).unwrap().to_string_lossy().into_owned();
            if e.file_type().unwrap().is_dir() {
                out.insert(format!("{rel}/"), Vec::new());
                walk(base, &p, out);
            } else {
                out.insert(rel, fs::read(&p).unwrap());
            }
        }
    }
    if !dir.exists() {
        return None;
    }
    let mut out = BTreeMap::new();
    walk(dir, dir, &mut out);
    Some(out)
}

/// Entries of the workspace root other than `generated/` (temporary trees left behind).
fn leftovers(root: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(root)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n != "generated")
        .collect();
    v.sort();
    v
}

/// The real file system, failing at the `fail_at`-th operation (0-based).
struct Failing {
    calls: usize,
    fail_at: usize,
}

impl Failing {
    fn step(&mut self, what: &str) -> io::Result<()> {
        let n = self.calls;
        self.calls += 1;
        if n == self.fail_at {
            return Err(io::Error::other(format!("injected failure at step {n} ({what})")));
        }
        Ok(())
    }
}

impl TreeFs for Failing {
    fn create_dir(&mut self, path: &Path) -> io::Result<()> {
        self.step("create_dir")?;
        RealFs.create_dir(path)
    }
    fn write(&mut self, path: &Path, contents: &[u8]) -> io::Result<()> {
        self.step("write")?;
        RealFs.write(path, contents)
    }
    fn rename(&mut self, from: &Path, to: &Path) -> io::Result<()> {
        self.step("rename")?;
        RealFs.rename(from, to)
    }
    fn remove_dir_all(&mut self, path: &Path) -> io::Result<()> {
        self.step("remove_dir_all")?;
        RealFs.remove_dir_all(path)
    }
}

fn check_and_atomic_write_body() {
    let v1: &[(&str, DeriveFn)] = &[("toy", toy_v1)];
    let v2: &[(&str, DeriveFn)] = &[("toy", toy_v2)];

    // Check mode on an empty workspace: everything missing, nothing written, command named.
    let root = scratch("check");
    let err = regen_with(&root, true, v1, &mut RealFs).unwrap_err().to_string();
    assert!(err.contains("missing: README.md, toy.checks.tsv, toy.ir, toy.md"), "{err}");
    assert!(err.contains("cargo xtask regen"), "{err}");
    assert_eq!(snapshot(&root.join("generated")), None);

    // Write mode creates the tree; check mode then passes; a second write changes nothing.
    let s = regen_with(&root, false, v1, &mut RealFs).unwrap();
    assert!(s.files.iter().all(|(_, st)| *st == FileStatus::Missing), "{s:?}");
    let gen_v1 = snapshot(&root.join("generated")).unwrap();
    assert_eq!(
        gen_v1.keys().collect::<Vec<_>>(),
        ["README.md", "toy.checks.tsv", "toy.ir", "toy.md"]
    );
    assert!(String::from_utf8_lossy(&gen_v1["toy.ir"]).starts_with(
        "# Generated by `cargo xtask regen` from codegen/tests/derive/regen_atomic.rs; do not edit by hand.\n"
    ));
    let s = regen_with(&root, true, v1, &mut RealFs).unwrap();
    assert!(s.changed().is_empty(), "{s:?}");
    regen_with(&root, false, v1, &mut RealFs).unwrap();
    assert_eq!(snapshot(&root.join("generated")).as_ref(), Some(&gen_v1));
    assert!(leftovers(&root).is_empty(), "{:?}", leftovers(&root));

    // Stale and extra files are reported by name.
    fs::write(root.join("generated/toy.md"), "edited by hand\n").unwrap();
    fs::write(root.join("generated/stray.txt"), "x\n").unwrap();
    let err = regen_with(&root, true, v1, &mut RealFs).unwrap_err().to_string();
    assert!(err.contains("stale: toy.md") && err.contains("extra: stray.txt"), "{err}");
    // Write mode repairs both (the stray file is removed).
    regen_with(&root, false, v1, &mut RealFs).unwrap();
    assert_eq!(snapshot(&root.join("generated")).as_ref(), Some(&gen_v1));

    // A failing derivation, or one that cannot be emitted, leaves generated/ untouched.
    let err = regen_with(&root, false, &[("toy", failing)], &mut RealFs).unwrap_err();
    assert!(format!("{err:#}").contains("derivation toy failed"), "{err:#}");
    let err = regen_with(&root, false, &[("toy", unemittable)], &mut RealFs).unwrap_err();
    assert!(format!("{err:#}").contains("unknown symbol \"nobody\""), "{err:#}");
    assert_eq!(snapshot(&root.join("generated")).as_ref(), Some(&gen_v1));
    assert!(leftovers(&root).is_empty(), "{:?}", leftovers(&root));

    // The new contents, for comparison.
    let other = scratch("v2");
    regen_with(&other, false, v2, &mut RealFs).unwrap();
    let gen_v2 = snapshot(&other.join("generated")).unwrap();
    assert_ne!(gen_v1, gen_v2);

    // Inject a failure at every step of the v1 -> v2 write: create the temporary directory,
    // write 4 files, rename the old tree aside, rename the new one in, remove the old one.
    let mut failures = 0;
    for fail_at in 0.. {
        let root = scratch("inject");
        regen_with(&root, false, v1, &mut RealFs).unwrap();
        let mut fs_ops = Failing { calls: 0, fail_at };
        let result = regen_with(&root, false, v2, &mut fs_ops);
        let now = snapshot(&root.join("generated"));
        let calls = fs_ops.calls;
        match result {
            Ok(_) => {
                // No failure was injected: every step ran.
                assert!(fail_at >= calls, "step {fail_at} failed silently");
                assert_eq!(now.as_ref(), Some(&gen_v2));
                assert!(leftovers(&root).is_empty(), "{:?}", leftovers(&root));
                fs::remove_dir_all(&root).unwrap();
                break;
            }
            Err(e) => {
                failures += 1;
                let msg = format!("{e:#}");
                assert!(msg.contains(&format!("injected failure at step {fail_at}")), "{msg}");
                if now.as_ref() == Some(&gen_v1) {
                    assert!(msg.contains("left unchanged"), "step {fail_at}: {msg}");
                    // Only the temporary tree may be left behind, and only when even its
                    // clean-up was the failing step (never the case with one failure).
                    assert!(leftovers(&root).is_empty(), "step {fail_at}: {:?}", leftovers(&root));
                } else {
                    // The only failure that may change generated/ is the final clean-up of the
                    // old tree, after the new tree is completely in place.
                    assert_eq!(
                        now.as_ref(),
                        Some(&gen_v2),
                        "step {fail_at}: generated/ is neither old nor new"
                    );
                    assert!(msg.contains("was updated but the old tree"), "step {fail_at}: {msg}");
                }
            }
        }
        fs::remove_dir_all(&root).unwrap();
    }
    assert_eq!(failures, 8, "create_dir + 4 writes + 2 renames + 1 removal");
    fs::remove_dir_all(&other).unwrap();
    fs::remove_dir_all(&root).unwrap();
}

#[test]
fn check_and_atomic_write() {
    crate::on_symbolica_thread(check_and_atomic_write_body);
}

fn selection_body() {
    let v1: &[(&str, DeriveFn)] = &[("toy", toy_v1), ("other", other_v1)];
    let v2: &[(&str, DeriveFn)] = &[("toy", toy_v2), ("other", other_v2)];
    let root = scratch("select");
    let generated = root.join("generated");
    regen_with(&root, false, v1, &mut RealFs).unwrap();
    let before = snapshot(&generated).unwrap();

    // Only toy is re-derived: its files change, other's are kept although its derivation
    // would now change them too; the tree is the full regeneration of (toy v2, other v1).
    let toy = ["toy".to_string()];
    let s = regen_selected(&root, false, v2, Selection::Only(&toy), &mut RealFs).unwrap();
    let timed: Vec<(&str, bool)> =
        s.models.iter().map(|m| (m.model.as_str(), m.time.is_some())).collect();
    assert_eq!(timed, [("toy", true), ("other", false)]);
    assert_eq!(s.models[1].checks, (1, 1), "the kept model's checks are read from its tsv");
    assert_eq!(s.models[1].outputs, ["y"]);
    let after = snapshot(&generated).unwrap();
    for name in ["other.ir", "other.md", "other.checks.tsv"] {
        assert_eq!(after[name], before[name], "{name} is kept");
    }
    assert_ne!(after["toy.ir"], before["toy.ir"]);
    let full = scratch("select-full");
    let mixed: &[(&str, DeriveFn)] = &[("toy", toy_v2), ("other", other_v1)];
    regen_with(&full, false, mixed, &mut RealFs).unwrap();
    assert_eq!(snapshot(&full.join("generated")).as_ref(), Some(&after));
    // Check mode with a selection compares the named model and the index.
    let s = regen_selected(&root, true, v2, Selection::Only(&toy), &mut RealFs).unwrap();
    assert!(s.changed().is_empty(), "{s:?}");

    // An unknown model is named, with the known ones; nothing is written.
    let nobody = ["nobody".to_string()];
    let err = regen_selected(&root, false, v2, Selection::Only(&nobody), &mut RealFs)
        .unwrap_err()
        .to_string();
    assert_eq!(err, "unknown model \"nobody\" (known models: toy, other)");
    let err = regen_selected(&root, false, v2, Selection::Only(&[]), &mut RealFs).unwrap_err();
    assert_eq!(err.to_string(), "no model named to regenerate");

    // A kept model must have all its files: the missing one is named with the command.
    fs::remove_file(generated.join("other.md")).unwrap();
    let without = snapshot(&generated).unwrap();
    let err = regen_selected(&root, false, v1, Selection::Only(&toy), &mut RealFs)
        .unwrap_err()
        .to_string();
    assert_eq!(err, "generated/other.md is missing; run `cargo xtask regen other`");
    assert_eq!(snapshot(&generated).as_ref(), Some(&without));
    assert!(leftovers(&root).is_empty(), "{:?}", leftovers(&root));
    fs::remove_dir_all(&root).unwrap();
    fs::remove_dir_all(&full).unwrap();
}

#[test]
fn selection() {
    crate::on_symbolica_thread(selection_body);
}
