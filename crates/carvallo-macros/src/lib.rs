//! The `scene!` proc-macro: specialised Rust evaluators generated at compile time from the IR
//! files in `generated/`.
//!
//! This crate is an implementation detail of `carvallo`, which re-exports the macro; users depend
//! on `carvallo` only. It never runs computer algebra: the symbolic work was done once by
//! `cargo xtask regen`, which wrote a straight-line program per model (`generated/<model>.ir`,
//! format in the `carvallo_ir` crate docs). The macro reads that program, folds the parameters a
//! scene fixes into constants, keeps only the outputs it asks for (dropping every instruction,
//! parameter and input they do not need) and emits flat SSA Rust.
//!
//! # Syntax
//!
//! ```text
//! carvallo::scene! {
//!     /// Doc comments and other attributes are passed through to the module.
//!     pub mod hoop_window {
//!         model: hoop,                         // required: reads generated/hoop.ir
//!         fixed: { R: 0.5, g: 9.81 },          // optional: parameters folded in as constants
//!         outputs: [equilibrium, stability],   // optional: default is every output
//!     }
//! }
//! ```
//!
//! One invocation may declare several scenes. Keys may come in any order, each at most once:
//!
//! * `model: NAME` names the model; its program is `generated/NAME.ir` of this workspace.
//! * `path: "FILE"` reads the program from `FILE` instead. A relative `FILE` is looked for
//!   first like `include_str!` does, relative to the directory of the source file that invokes
//!   the macro, then relative to the calling crate's `CARGO_MANIFEST_DIR`. The program's
//!   `model` line must still equal `NAME`. Meant for tests with fixture files.
//! * `fixed: { NAME: VALUE, ... }` fixes parameters; a value is a float or integer literal,
//!   optionally negated and optionally suffixed `f64`, and must be finite.
//! * `outputs: [NAME, ...]` selects and orders the outputs.
//! * `max_fn_ops: N` splits programs of more than `N` operations (default
//!   1500) into several `#[inline(never)]` helper functions, which
//!   keeps rustc's compile time in check for very large formulas. The helpers share one
//!   struct of the values that cross them (each stored once and loaded where it is used).
//! * `lanes: N` (2, 4, 8 or 16) also emits `eval_lanes`, the same evaluator on `N` points per
//!   call in structure-of-arrays form (`[[f64; N]; K]` in, `[[f64; N]; M]` out), lane `j`
//!   bit for bit equal to `eval_array` of point `j`. On x86 it is compiled twice,
//!   `eval_lanes_portable` (SSE2) and `eval_lanes_avx2` (AVX2, no FMA, the same bits), and
//!   `eval_lanes` picks one at run time; so is `eval` (`eval_portable`, `eval_avx2`) for
//!   programs of 1,000 operations or more.
//!
//! # What a scene module contains
//!
//! `MODEL`, `PARAMS` (the free parameters), `INPUTS`, `ARGS` (`[&str; N]`: `PARAMS` then
//! `INPUTS`, the fields of `Args` in order), `OUTPUTS`, `FIXED`, `OP_COUNT` (operations
//! of the emitted code, constants not counted), `OP_COUNT_BY_OP` and `SOURCE_OP_COUNT` (the whole
//! model program before fixing and pruning); the structs `Args` (one `f64` field per free
//! parameter, then per input, named as in the IR) and `Out` (one field per output), with
//! `from_array`/`to_array`, and `Args::from_fn(|name| value)` (the fields by name, asked in the
//! order of `ARGS`); and the evaluators `eval(&Args) -> Out` and
//! `eval_array(&[f64; N]) -> [f64; M]`; with `lanes: L` also `LANES` and
//! `eval_lanes(&[[f64; L]; N]) -> [[f64; L]; M]`. The code is straight-line `f64` arithmetic and `f64`
//! methods (`sqrt`, `sin`, `cos`, `tan`, `atan2`, `powi`): no allocation, no panics, no macros
//! (but `is_x86_feature_detected!` in the functions that choose the AVX2 variant).
//! The module also holds `const _: &str = include_str!(...)` of the IR file, so Cargo rebuilds
//! the calling crate when the file changes.
//!
//! # Errors
//!
//! An unknown model (no such file), a malformed IR file, an unknown or duplicate key, an unknown
//! parameter or output, a parameter fixed twice and a non-numeric or non-finite value are
//! reported as compile errors on the offending token; all problems found are reported at once.
//!
//! # Layout
//!
//! Private modules: `parse` reads the syntax, `validate` loads the IR and checks the scene
//! against it, `emit` writes the Rust, `expand` ties them together on `proc_macro2` token
//! streams (so that the unit tests in `tests` can run it outside the compiler). `scene` is the
//! leaf they share: the validated [`Scene`](scene::Scene), the [`Context`](scene::Context) of
//! the files, and the naming rules. The imports go one way: `parse`, `scene` ← `validate` ←
//! `expand` → `emit` → `scene`.

mod emit;
mod expand;
mod parse;
mod scene;
mod validate;

#[cfg(test)]
mod tests;

/// Declares one or more scenes: specialised evaluators of a model. See the crate docs.
#[proc_macro]
pub fn scene(input: proc_macro::TokenStream) -> proc_macro::TokenStream {
    expand::expand(syn::parse_macro_input!(input as parse::SceneInput)).into()
}
