//! The compile errors users see, and a generated evaluator compiled as a separate crate.
//!
//! `tests/ui/fail/*.rs` must fail to compile with exactly the committed `.stderr` (message and
//! the token it points at); `tests/ui/pass/*.rs` must compile and run successfully. Fixture
//! paths in these files are relative to the file, like `include_str!`, so they work from the
//! temporary project trybuild builds.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/fail/*.rs");
    t.pass("tests/ui/pass/*.rs");
}
