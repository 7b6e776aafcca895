//! The expansion of `scene!` on `proc_macro2` token streams: parse, validate, emit.
//!
//! The proc-macro entry point in `lib.rs` only parses and converts between `proc_macro` and
//! `proc_macro2`; everything else is here. [`expand`] takes its [`Context`] (where files are)
//! from the compiler, [`expand_in`] takes it as an argument, so that the unit tests can run the
//! whole expansion outside the compiler.

use std::path::{Path, PathBuf};

use proc_macro2::TokenStream;

use crate::parse::SceneInput;
use crate::validate::{validate, Errors};

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

/// Expands every scene of `input` in the context the compiler reports; see [`expand_in`].
pub fn expand(input: SceneInput) -> TokenStream {
    expand_in(input, &Context::from_compiler())
}

/// Expands every scene of `input`: the modules of the valid scenes, followed by one
/// `compile_error!` per problem found in the others.
pub fn expand_in(input: SceneInput, ctx: &Context) -> TokenStream {
    let mut out = TokenStream::new();
    let mut errors = Errors::default();
    for decl in input.scenes {
        match validate(decl, ctx) {
            Ok(scene) => out.extend(crate::emit::emit(&scene)),
            Err(e) => errors.push(e),
        }
    }
    if let Err(e) = errors.check() {
        out.extend(e.into_compile_error());
    }
    out
}

/// [`expand_in`] on raw tokens, as the compiler would call it (parse errors become
/// `compile_error!` too).
#[cfg(test)]
pub fn expand_tokens(input: TokenStream, ctx: &Context) -> TokenStream {
    match syn::parse2::<SceneInput>(input) {
        Ok(scenes) => expand_in(scenes, ctx),
        Err(e) => e.into_compile_error(),
    }
}
