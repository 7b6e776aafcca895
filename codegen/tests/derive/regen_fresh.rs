//! Staleness test: the committed `generated/` must be exactly what the derivations render now
//! (each model derived once for the whole test binary, see [`crate::derived`]); a failure names
//! the stale, missing and extra files and the command that repairs them.

use std::path::Path;

use carvallo_codegen::derive::DERIVATIONS;
use carvallo_codegen::regen::{compare_with_disk, render_all, FileStatus};
use carvallo_codegen::Derivation;

fn generated_is_up_to_date_body() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("codegen/ has a parent");
    let ds: Vec<Derivation> =
        DERIVATIONS.iter().map(|(name, _)| crate::derived(name).clone()).collect();
    let (files, _) = render_all(&ds).unwrap_or_else(|e| panic!("rendering fails: {e:#}"));
    if let Ok(dir) = std::env::var("CARVALLO_DUMP") {
        for (name, text) in &files {
            std::fs::write(Path::new(&dir).join(name.replace('/', "_")), text).unwrap();
        }
    }
    let statuses = compare_with_disk(root, &files).unwrap_or_else(|e| panic!("{e:#}"));
    assert!(!statuses.is_empty(), "regen checked no file");
    let changed: Vec<String> = statuses
        .iter()
        .filter(|(_, s)| *s != FileStatus::Fresh)
        .map(|(name, s)| format!("{name} ({s:?})"))
        .collect();
    assert!(
        changed.is_empty(),
        "generated/ is out of date: {}\n(to fix: run `cargo xtask regen` and commit generated/)",
        changed.join(", ")
    );
}

#[test]
fn generated_is_up_to_date() {
    crate::on_symbolica_thread(generated_is_up_to_date_body);
}
