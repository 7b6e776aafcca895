//! Unit tests of the whole expansion (parse, validate, emit) on the fixture programs in
//! `tests/fixtures/`, run outside the compiler on `proc_macro2` token streams.
//!
//! The expansions are snapshotted as formatted Rust (`prettyplease`) with the absolute path of
//! this crate replaced by `$CARGO_MANIFEST_DIR`; the error tests check the message and the token
//! each error points at. Whether the emitted code compiles and computes the right values is
//! tested in `tests/eval.rs` and `tests/ui.rs`.

use std::path::{Path, PathBuf};

use proc_macro2::TokenStream;
use quote::quote;

use crate::expand::expand_tokens;
use crate::scene::{generated_dir, Context};

fn manifest_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::fs::canonicalize(dir).unwrap_or_else(|_| dir.to_path_buf())
}

/// Relative `path:` values resolve against `tests/` (as for a macro invoked in `tests/*.rs`);
/// `model: NAME` finds `tests/fixtures/NAME.ir`.
fn ctx() -> Context {
    Context {
        source_dir: manifest_dir().join("tests"),
        manifest_dir: Some(manifest_dir()),
        generated_dir: manifest_dir().join("tests").join("fixtures"),
    }
}

/// The expansion as formatted Rust with the machine-specific path normalised.
fn pretty(ts: TokenStream) -> String {
    let out = expand_tokens(ts, &ctx());
    let file: syn::File = syn::parse2(out.clone())
        .unwrap_or_else(|e| panic!("expansion is not a Rust file: {e}\n{out}"));
    prettyplease::unparse(&file)
        .replace(&manifest_dir().display().to_string(), "$CARGO_MANIFEST_DIR")
}

/// The messages of the `compile_error!`s of an expansion, with the source text of the tokens
/// they point at (spans are not real outside the compiler, so the tokens are recovered from
/// the error's span range as the compiler would show them: here we check messages only, and
/// the trybuild tests check the spans).
fn errors(ts: TokenStream) -> Vec<String> {
    let out = expand_tokens(ts, &ctx());
    let file: syn::File = syn::parse2(out).expect("expansion parses");
    file.items
        .iter()
        .filter_map(|item| match item {
            syn::Item::Macro(m)
                if m.mac.path.segments.last().is_some_and(|s| s.ident == "compile_error") =>
            {
                Some(
                    m.mac
                        .parse_body::<syn::LitStr>()
                        .expect("compile_error! takes a string")
                        .value(),
                )
            }
            _ => None,
        })
        .collect()
}

/// The value of `pub const NAME: usize = N;` in the expansion of the scene module.
fn const_usize(text: &str, name: &str) -> usize {
    let key = format!("pub const {name}: usize = ");
    let start = text.find(&key).unwrap_or_else(|| panic!("no constant {name}")) + key.len();
    let end = start + text[start..].find(';').expect("constant ends with `;`");
    text[start..end].parse().expect("constant is an integer")
}

fn assert_one_error(ts: TokenStream, want: &str) {
    let errs = errors(ts);
    assert_eq!(errs, [want.to_string()], "unexpected errors");
}

#[test]
fn full_and_pruned_scenes() {
    let full = pretty(quote! {
        /// Every output of the demo model.
        pub mod demo_full {
            model: demo,
        }
    });
    let pruned = pretty(quote! {
        /// Only `trig`, with the parameters fixed.
        pub(crate) mod demo_trig {
            model: demo,
            fixed: { R: 0.5, g: 9.81 },
            outputs: [trig],
        }
    });
    insta::with_settings!({
        description => "scene! over tests/fixtures/demo.ir, every output, nothing fixed",
        prepend_module_to_snapshot => false,
    }, {
        insta::assert_snapshot!("demo_full", full);
    });
    insta::with_settings!({
        description => "scene! over tests/fixtures/demo.ir, R and g fixed, only the output trig",
        prepend_module_to_snapshot => false,
    }, {
        insta::assert_snapshot!("demo_trig", pruned);
    });

    // The whole fixture has 19 operations and the outputs use them all (but not `mu`, `w`).
    assert_eq!(const_usize(&full, "SOURCE_OP_COUNT"), 19);
    assert_eq!(const_usize(&full, "OP_COUNT"), 19);
    assert!(full.contains(r#"pub const PARAMS: &[&str] = &["R", "g"];"#), "{full}");
    assert!(full.contains(r#"pub const INPUTS: &[&str] = &["x", "y", "z"];"#), "{full}");
    // trig = sin x cos y + tan x - atan2(y, x): 7 operations, no parameter.
    assert_eq!(const_usize(&pruned, "OP_COUNT"), 7);
    assert_eq!(const_usize(&pruned, "SOURCE_OP_COUNT"), 19);
    assert!(pruned.contains("pub const PARAMS: &[&str] = &[];"), "{pruned}");
    assert!(pruned.contains(r#"pub const INPUTS: &[&str] = &["x", "y"];"#), "{pruned}");
    assert!(
        pruned.contains(r#"pub const FIXED: &[(&str, f64)] = &[("R", 0.5_f64), ("g", 9.81_f64)];"#),
        "{pruned}"
    );
    assert!(pruned.lines().count() < full.lines().count());
    // The evaluator itself: one `let` per operation and used constant.
    let lets = |text: &str| {
        text.lines()
            .filter(|l| l.trim_start().starts_with("let t") || l.trim_start().starts_with("let c"))
            .count()
    };
    assert_eq!((lets(&full), lets(&pruned)), (21, 7));
}

#[test]
fn fixing_folds_constants() {
    let text = pretty(quote! {
        mod scaled { model: demo, fixed: { R: 0.5, g: -9.81 }, outputs: [scaled, poly] }
    });
    // scaled = 2 R g folds to one constant; poly keeps x, y and folds R and g in.
    assert!(text.contains("let c"), "{text}");
    assert!(text.contains("-9.81_f64"), "{text}");
    assert!(text.contains(r#"pub const INPUTS: &[&str] = &["x", "y"];"#), "{text}");
    assert!(text.contains("pub const PARAMS: &[&str] = &[];"), "{text}");
    // poly: add, sub, mul, div, powi, add; scaled: nothing left.
    assert_eq!(const_usize(&text, "OP_COUNT"), 6);
    insta::with_settings!({
        description => "scene! over tests/fixtures/demo.ir, R and g fixed, outputs scaled and poly",
        prepend_module_to_snapshot => false,
    }, {
        insta::assert_snapshot!("demo_scaled", text);
    });
}

#[test]
fn large_programs_are_split() {
    let text = pretty(quote! {
        mod split { model: demo, max_fn_ops: 4 }
    });
    // 19 operations in chunks of 4: five helper functions sharing one struct of crossing values.
    for k in 0..5 {
        assert!(
            text.contains(&format!("fn part_{k}(live: &mut Live)")),
            "part_{k} missing:\n{text}"
        );
    }
    assert_eq!(text.matches("struct Live {").count(), 1, "{text}");
    assert!(!text.contains("fn part_5("), "{text}");
    assert_eq!(text.matches("#[inline(never)]").count(), 5);
    insta::with_settings!({
        description => "scene! over tests/fixtures/demo.ir with at most 4 operations per function",
        prepend_module_to_snapshot => false,
    }, {
        insta::assert_snapshot!("demo_split", text);
    });
}

#[test]
fn lanes_add_a_structure_of_arrays_evaluator() {
    let text = pretty(quote! {
        mod four { model: demo, max_fn_ops: 8, lanes: 4 }
    });
    assert_eq!(const_usize(&text, "LANES"), 4);
    assert!(text.contains("pub fn eval_lanes(args: &[[f64; 4]; 5]) -> [[f64; 4]; 4]"), "{text}");
    // AVX2 chosen at run time, never FMA (lanes stay bit for bit the scalar evaluator).
    assert!(text.contains("is_x86_feature_detected!(\"avx2\")"), "{text}");
    assert!(text.contains("#[target_feature(enable = \"avx2\")]"), "{text}");
    assert!(text.contains("fn lanes_part_0_avx2(live: &mut LiveLanes)"), "{text}");
    assert!(!text.contains("fma"), "{text}");
    // The demo is too small for an AVX2 copy of the scalar evaluator.
    assert!(!text.contains("fn eval_avx2"), "{text}");
    // Both evaluators are split the same way, each with its own struct of crossing values.
    for k in 0..3 {
        assert!(text.contains(&format!("fn part_{k}(live: &mut Live)")), "{text}");
        assert!(text.contains(&format!("fn lanes_part_{k}(live: &mut LiveLanes)")), "{text}");
    }
    // Each helper runs the scalar operations in a loop over the four lanes (twice: the portable
    // and the AVX2 variant).
    assert_eq!(text.matches("for j in 0..4 {").count(), 2 * (3 + 2), "{text}");
    assert!(text.contains("let t6 = x.sin();"), "{text}");
    insta::with_settings!({
        description => "scene! over tests/fixtures/demo.ir with 4 lanes, at most 8 operations per function",
        prepend_module_to_snapshot => false,
    }, {
        insta::assert_snapshot!("demo_lanes", text);
    });
    let plain = pretty(quote!(mod one { model: demo }));
    assert!(!plain.contains("eval_lanes") && !plain.contains("LANES"), "{plain}");
}

#[test]
fn generated_code_has_no_macros_or_panics() {
    let text = pretty(quote! {
        mod a { model: demo }
        mod b { model: demo, max_fn_ops: 3 }
    });
    let code: String =
        text.lines().filter(|l| !l.trim_start().starts_with("//")).collect::<Vec<_>>().join("\n");
    // The only macro is the include_str! that tracks the IR file, once per scene.
    assert_eq!(code.matches('!').count(), 2, "{code}");
    assert_eq!(code.matches("include_str!(").count(), 2);
    for bad in ["unwrap", "expect", "panic", "Vec", "Box", "vec", "[0]", "as usize"] {
        assert!(!code.contains(bad), "generated code contains `{bad}`");
    }
}

#[test]
fn keyword_and_clashing_names() {
    let text = pretty(quote! {
        pub mod kw { model: keywords, fixed: { r#type: 2 } }
    });
    insta::with_settings!({
        description => "scene! over tests/fixtures/keywords.ir: IR names that are keywords or scene items",
        prepend_module_to_snapshot => false,
    }, {
        insta::assert_snapshot!("keywords", text);
    });
    assert!(text.contains("pub r#match: f64"), "{text}");
    assert!(text.contains("pub MODEL: f64"), "{text}");
    // Locals that would shadow the module's constants or functions are renamed.
    assert!(text.contains("MODEL: MODEL_"), "{text}");
    assert!(text.contains("eval: eval_"), "{text}");
}

#[test]
fn rust_identifiers() {
    use crate::scene::rust_ident;
    use proc_macro2::Span;
    let show = |n: &str| rust_ident(n, Span::call_site()).map(|i| i.to_string());
    assert_eq!(show("x1"), Some("x1".into()));
    assert_eq!(show("R"), Some("R".into()));
    assert_eq!(show("type"), Some("r#type".into()));
    assert_eq!(show("__"), Some("__".into()));
    for bad in ["_", "self", "Self", "super", "crate", "1x", "", "a-b"] {
        assert_eq!(show(bad), None, "{bad:?}");
    }
}

#[test]
fn unknown_model() {
    assert_one_error(
        quote!(mod a { model: nope }),
        "unknown model `nope`: there is no `generated/nope.ir`",
    );
}

#[test]
fn the_default_generated_dir_is_the_workspace_one() {
    let dir = generated_dir();
    assert_eq!(dir.file_name().and_then(|f| f.to_str()), Some("generated"));
    assert!(dir.parent().expect("has a parent").join("Cargo.toml").exists());
}

#[test]
fn unknown_and_misused_names() {
    assert_eq!(
        errors(quote!(mod a { model: demo, newton: { input: R, residual: poly, derivative: nope } })),
        [
            "`newton` steps an input, and `R` is not one of model `demo` (inputs: `x`, `y`, `z`, `w`)",
            "unknown output `nope` of model `demo` (outputs: `poly`, `trig`, `root`, `scaled`)",
        ]
    );
    assert_one_error(
        quote!(mod a { model: demo, fixed: { Q: 1.0 } }),
        "unknown parameter `Q` of model `demo` (parameters: `R`, `g`, `mu`)",
    );
    assert_one_error(
        quote!(mod a { model: demo, fixed: { x: 1.0 } }),
        "`x` is an input of model `demo`, not a parameter; only parameters can be fixed (parameters: `R`, `g`, `mu`)",
    );
    assert_one_error(
        quote!(mod a { model: demo, outputs: [trig, nope] }),
        "unknown output `nope` of model `demo` (outputs: `poly`, `trig`, `root`, `scaled`)",
    );
    assert_one_error(
        quote!(mod a { model: demo, fixed: { R: 1.0, R: 2.0 } }),
        "parameter `R` is fixed twice",
    );
    assert_eq!(
        errors(quote!(mod a { model: demo, fixed: { R: x, R: 2.0 } })),
        [
            "the value of `R` must be a float or integer literal, found `x`",
            "parameter `R` is fixed twice"
        ]
    );
    assert_one_error(
        quote!(mod a { model: demo, outputs: [trig, trig] }),
        "output `trig` is selected twice",
    );
    assert_one_error(
        quote!(mod a { model: demo, outputs: [] }),
        "`outputs` is empty; list at least one output or leave the key out for all",
    );
}

#[test]
fn duplicate_and_missing_keys() {
    assert_one_error(
        quote!(mod a { model: demo, outputs: [poly], outputs: [trig] }),
        "duplicate key `outputs`",
    );
    assert_one_error(quote!(mod a { model: demo, model: demo }), "duplicate key `model`");
    assert_one_error(
        quote!(mod a { outputs: [poly] }),
        "scene `a` has no `model` key; add `model: NAME`",
    );
}

#[test]
fn fixed_values_must_be_finite_numbers() {
    let cases = [
        (quote!("abc"), "the value of `R` must be a float or integer literal, found `\"abc\"`"),
        (quote!(pi), "the value of `R` must be a float or integer literal, found `pi`"),
        (
            quote!(1.0 + 2.0),
            "the value of `R` must be a float or integer literal, found `1.0 + 2.0`",
        ),
        (quote!(-(1.0)), "the value of `R` must be a float or integer literal, found `- (1.0)`"),
        (quote!(1.0f32), "the value of `R` must be an `f64` literal, found suffix `f32`"),
        (quote!(3u8), "the value of `R` must be an `f64` literal, found suffix `u8`"),
        (quote!(1e999), "the value of `R` is not a finite `f64`: `1e999`"),
        (quote!(-1e999), "the value of `R` is not a finite `f64`: `- 1e999`"),
    ];
    for (value, want) in cases {
        assert_one_error(quote!(mod a { model: demo, fixed: { R: #value } }), want);
    }
    // Accepted forms, all equal to -2.
    for value in [quote!(-2), quote!(-2.0), quote!(-2f64), quote!(-2.0_f64), quote!(-0.2e1)] {
        let text = pretty(quote!(mod a { model: demo, fixed: { R: #value } }));
        assert!(text.contains(r#"("R", -2.0_f64)"#), "{value}: {text}");
    }
}

#[test]
fn bad_files() {
    assert_one_error(
        quote!(mod a { model: malformed, path: "fixtures/malformed.ir" }),
        "malformed IR file `fixtures/malformed.ir`: line 5, column 16: use of undefined value \"nope\"",
    );
    assert_one_error(
        quote!(mod a { model: demo, path: "fixtures/wrong_model.ir" }),
        "IR file `fixtures/wrong_model.ir` is a program of model `other`, not `demo`",
    );
    let errs = errors(quote!(mod a { model: demo, path: "fixtures/none.ir" }));
    assert_eq!(errs.len(), 1);
    assert!(errs[0].starts_with("no IR file `fixtures/none.ir` (looked for "), "{errs:?}");
    // Not next to the invoking file, but relative to the calling crate's manifest directory.
    let text = pretty(quote!(mod a { model: demo, path: "tests/fixtures/demo.ir" }));
    assert!(text.contains("\"$CARGO_MANIFEST_DIR/tests/fixtures/demo.ir\""), "{text}");
    assert_one_error(
        quote!(mod a { model: demo, max_fn_ops: 0 }),
        "`max_fn_ops` must be a positive integer, found `0`",
    );
    for bad in [quote!(3), quote!(0), quote!(32)] {
        assert_one_error(
            quote!(mod a { model: demo, lanes: #bad }),
            &format!("`lanes` must be 2, 4, 8 or 16, found `{bad}`"),
        );
    }
    assert_one_error(quote!(mod a { model: demo, lanes: 4, lanes: 8 }), "duplicate key `lanes`");
}

#[test]
fn malformed_scene_is_one_error() {
    assert_one_error(quote!(mod a { model demo }), "expected `:`");
    assert_one_error(
        quote!(mod a { model: demo, colour: red }),
        "unknown scene key `colour`; expected one of `model`, `path`, `fixed`, `outputs`, `max_fn_ops`, `lanes`, `jacobian`, `newton`",
    );
}

#[test]
fn all_problems_are_reported_together() {
    let errs = errors(quote! {
        mod a {
            model: demo,
            fixed: { Q: 1.0, g: "x", R: 1.0, R: 2.0 },
            outputs: [nope, trig, trig],
            outputs: [poly],
        }
        mod good { model: demo, outputs: [poly] }
        mod c { model: nope }
    });
    assert_eq!(
        errs,
        [
            "duplicate key `outputs`",
            "the value of `g` must be a float or integer literal, found `\"x\"`",
            "parameter `R` is fixed twice",
            "output `trig` is selected twice",
            "unknown parameter `Q` of model `demo` (parameters: `R`, `g`, `mu`)",
            "unknown output `nope` of model `demo` (outputs: `poly`, `trig`, `root`, `scaled`)",
            "unknown model `nope`: there is no `generated/nope.ir`",
        ]
    );
    // The valid scene is still emitted, so its uses do not add errors of their own.
    let out =
        expand_tokens(quote!(mod good { model: demo } mod c { model: nope }), &ctx()).to_string();
    assert!(out.contains("mod good"));
}
