//! The expansion of `scene!` on `proc_macro2` token streams: parse, validate, emit.
//!
//! The proc-macro entry point in `lib.rs` only parses and converts between `proc_macro` and
//! `proc_macro2`; everything else is here. [`expand`] takes its [`Context`] (where files are)
//! from the compiler, [`expand_in`] takes it as an argument, so that the unit tests can run the
//! whole expansion outside the compiler.

use proc_macro2::TokenStream;

use crate::parse::SceneInput;
use crate::scene::Context;
use crate::validate::{validate, Errors};

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
