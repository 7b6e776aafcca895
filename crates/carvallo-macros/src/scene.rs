//! The scene as the other modules share it: what validation produces and emission consumes
//! ([`Scene`]), where the expansion finds its files ([`Context`]), and the naming rules both
//! sides must agree on ([`rust_ident`], [`RESERVED`], [`DEFAULT_MAX_FN_OPS`], [`LANE_COUNTS`]).
//!
//! A leaf: it imports no other module of the crate, so that `validate` and `emit` depend on it
//! and not on each other (`parse`, `scene` ← `validate` ← `expand` → `emit` → `scene`).

use std::path::{Path, PathBuf};

use carvallo_ir::Program;
use proc_macro2::{Ident, Span};
use syn::{Attribute, Visibility};

/// Default largest number of operations in one generated function.
pub const DEFAULT_MAX_FN_OPS: usize = 1500;

/// The values `lanes: N` accepts.
pub const LANE_COUNTS: [usize; 4] = [2, 4, 8, 16];

/// Items of a scene module that live in the value namespace: locals must not be named so.
pub const RESERVED: &[&str] = &[
    "MODEL",
    "PARAMS",
    "INPUTS",
    "ARGS",
    "OUTPUTS",
    "FIXED",
    "OP_COUNT",
    "OP_COUNT_BY_OP",
    "SOURCE_OP_COUNT",
    "eval",
    "eval_array",
    "eval_lanes",
    "eval_portable",
    "eval_avx2",
    "eval_lanes_portable",
    "eval_lanes_avx2",
    "LANES",
    "JACOBIAN_OF",
    "JACOBIAN_WRT",
    "JACOBIAN_NONZEROS",
    "jacobian",
    "jacobian_array",
    // Locals of the generated functions.
    "live",
    "args",
    "out",
    "j",
];

/// `name` as a Rust identifier: itself, or a raw identifier (`r#type`) for a keyword that
/// allows one; `None` for names that cannot be identifiers at all (`self`, `_`, `1x`, ...).
pub fn rust_ident(name: &str, span: Span) -> Option<Ident> {
    if let Ok(mut ident) = syn::parse_str::<Ident>(name) {
        ident.set_span(span);
        return Some(ident);
    }
    let mut chars = name.chars();
    let starts_well = matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_');
    let word = starts_well && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
    if !word || ["self", "Self", "super", "crate", "_"].contains(&name) {
        return None;
    }
    Some(Ident::new_raw(name, span))
}

/// A scene that passed validation, with its specialised program.
pub struct Scene {
    /// Outer attributes of the declaration.
    pub attrs: Vec<Attribute>,
    /// The module's visibility.
    pub vis: Visibility,
    /// The module's name.
    pub name: Ident,
    /// The model name.
    pub model: String,
    /// Absolute path of the IR file that was read (for `include_str!`).
    pub ir_path: PathBuf,
    /// The path as shown to users (`generated/hoop.ir` or the `path:` literal).
    pub ir_display: String,
    /// The fixed parameters with their values, in the order written.
    pub fixed: Vec<(String, f64)>,
    /// Total op count of the model's whole program, before fixing and pruning.
    pub source_op_count: usize,
    /// The specialised program the scene evaluates.
    pub program: Program,
    /// Largest number of operations emitted in one function before splitting.
    pub max_fn_ops: usize,
    /// `lanes: N`: also emit `eval_lanes` over `N` points per call.
    pub lanes: Option<usize>,
    /// `jacobian: [...]`: the derivatives the program computes beside its values.
    pub jacobian: Option<Jacobian>,
}

/// The Jacobian a scene asked for: $\partial\,\text{of}_i/\partial\,\text{wrt}_j$.
pub struct Jacobian {
    /// The outputs differentiated (the scene's value outputs), the rows.
    pub of: Vec<String>,
    /// The variables, the columns, in the order written.
    pub wrt: Vec<String>,
    /// The index in the program's outputs of each entry, `None` for a structural zero.
    pub entries: Vec<Vec<Option<usize>>>,
}

/// Where the expansion finds its files.
pub struct Context {
    /// The directory that relative `path:` values are resolved against first: the directory
    /// of the source file that invokes the macro.
    pub source_dir: PathBuf,
    /// Where relative `path:` values are looked for when they are not found in `source_dir`:
    /// the calling crate's `CARGO_MANIFEST_DIR`.
    pub manifest_dir: Option<PathBuf>,
    /// The workspace's `generated/` directory, where `model: NAME` finds `NAME.ir`.
    pub generated_dir: PathBuf,
}

impl Context {
    /// The context of a macro invocation being compiled: the invoking file's directory as the
    /// compiler reports it (like `include_str!`; the calling crate's `CARGO_MANIFEST_DIR` when
    /// the compiler reports no file, for example in an IDE's macro server), then the calling
    /// crate's `CARGO_MANIFEST_DIR`.
    pub fn from_compiler() -> Self {
        let manifest_dir = std::env::var_os("CARGO_MANIFEST_DIR").map(PathBuf::from);
        let source_dir = proc_macro::Span::call_site()
            .local_file()
            .and_then(|f| f.parent().map(Path::to_path_buf))
            .or_else(|| manifest_dir.clone())
            .unwrap_or_default();
        Context { source_dir, manifest_dir, generated_dir: generated_dir() }
    }

    /// The file a relative or absolute `path:` value names: in `source_dir` if it exists
    /// there, else in `manifest_dir` if it exists there; otherwise every place looked at.
    pub fn resolve(&self, path: &str) -> Result<PathBuf, Vec<PathBuf>> {
        let candidates: Vec<PathBuf> = std::iter::once(&self.source_dir)
            .chain(&self.manifest_dir)
            .map(|dir| dir.join(path))
            .collect();
        match candidates.iter().find(|c| c.is_file()) {
            Some(found) => Ok(found.clone()),
            None => Err(candidates),
        }
    }
}

/// The workspace's `generated/` directory, found from this crate's manifest directory.
pub fn generated_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("..").join("generated");
    std::fs::canonicalize(&dir).unwrap_or(dir)
}
