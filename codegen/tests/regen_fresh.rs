//! Staleness test: re-runs every derivation and fails, naming `cargo xtask regen`, when the
//! committed `generated/` differs from what the derivations produce now.
//!
//! This binary has a single test, so symbolica (limited to one thread without a license key)
//! runs on one thread only.

use std::path::Path;

#[test]
fn generated_is_up_to_date() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("codegen/ has a parent");
    match carvallo_codegen::regen::regen(root, true) {
        Ok(summary) => {
            assert!(summary.changed().is_empty(), "{summary:?}");
            assert!(!summary.files.is_empty(), "regen checked no file");
        }
        Err(e) => panic!("{e:#}\n(to fix: run `cargo xtask regen` and commit generated/)"),
    }
}
