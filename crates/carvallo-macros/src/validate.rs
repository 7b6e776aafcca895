//! Checks a parsed scene against its model's IR program and specialises the program.
//!
//! Validation turns a [`SceneDecl`] into a [`Scene`]: it checks the entries (each key at most
//! once, `model` present, every fixed value a finite numeric literal, no name fixed or selected
//! twice), loads and parses the IR file, checks the fixed names against the program's
//! parameters and the selected names against its outputs, and finally specialises the program
//! with the `carvallo_ir` transformations: `fix_params` (fixed parameters become constants,
//! which are folded), with `newton: {...}` `with_newton_step` (the program at the input
//! corrected by one Newton step, the step and the corrected input appended to the selected
//! outputs), `select_outputs` (dead-code elimination, unused parameters and inputs
//! dropped), then one more round of constant folding and dead-code elimination; with
//! `jacobian: [...]`, `with_jacobian` then adds the derivatives of the selected outputs with
//! respect to the listed inputs and parameters (structural zeros left out).
//!
//! Every problem becomes a `syn::Error` spanned on the offending token; problems are collected
//! and combined so that the user sees them all at once. Nothing here panics on user input.

use std::path::PathBuf;

use carvallo_ir::Program;
use proc_macro2::Span;
use syn::ext::IdentExt;
use syn::{Expr, Ident, Lit, LitStr, UnOp};

use crate::parse::{EntryValue, FixedEntry, Newton, SceneDecl};
use crate::scene::{rust_ident, Context, Jacobian, Scene, DEFAULT_MAX_FN_OPS, LANE_COUNTS};

/// A list of errors that are combined into one `syn::Error`.
#[derive(Default)]
pub struct Errors(Option<syn::Error>);

impl Errors {
    /// Records one more error.
    pub fn push(&mut self, e: syn::Error) {
        match &mut self.0 {
            Some(all) => all.combine(e),
            None => self.0 = Some(e),
        }
    }

    /// `Err` with every recorded error, or `Ok(())` if there is none.
    pub fn check(self) -> syn::Result<()> {
        match self.0 {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }

    /// Every recorded error and then `last`, for problems after which checking cannot go on.
    pub fn fail(self, last: syn::Error) -> syn::Error {
        match self.0 {
            Some(mut all) => {
                all.combine(last);
                all
            }
            None => last,
        }
    }
}

/// The entries of a scene after the duplicate check, still as tokens.
#[derive(Default)]
struct Entries {
    model: Option<Ident>,
    path: Option<LitStr>,
    fixed: Option<(Ident, Vec<FixedEntry>)>,
    outputs: Option<(Ident, Vec<Ident>)>,
    max_fn_ops: Option<syn::LitInt>,
    lanes: Option<syn::LitInt>,
    jacobian: Option<(Ident, Vec<Ident>)>,
    newton: Option<Newton>,
}

/// Validates one scene declaration against its IR file; see the module docs.
pub fn validate(decl: SceneDecl, ctx: &Context) -> syn::Result<Scene> {
    let mut errors = Errors::default();
    let SceneDecl { attrs, vis, name, entries: raw } = decl;

    let mut e = Entries::default();
    for entry in raw {
        let key = entry.key;
        let taken = match entry.value {
            EntryValue::Model(v) => set(&mut e.model, v),
            EntryValue::Path(v) => set(&mut e.path, v),
            EntryValue::Fixed(v) => set(&mut e.fixed, (key.clone(), v)),
            EntryValue::Outputs(v) => set(&mut e.outputs, (key.clone(), v)),
            EntryValue::MaxFnOps(v) => set(&mut e.max_fn_ops, v),
            EntryValue::Lanes(v) => set(&mut e.lanes, v),
            EntryValue::Jacobian(v) => set(&mut e.jacobian, (key.clone(), v)),
            EntryValue::Newton(v) => set(&mut e.newton, v),
        };
        if taken {
            errors.push(syn::Error::new_spanned(&key, format!("duplicate key `{key}`")));
        }
    }

    // Fixed values and selected outputs, checked without the IR file.
    let mut fixed: Vec<(Ident, f64)> = Vec::new();
    let mut seen: Vec<Ident> = Vec::new();
    for entry in e.fixed.as_ref().map(|f| f.1.as_slice()).unwrap_or_default() {
        let name = entry.name.unraw();
        if seen.contains(&name) {
            errors.push(syn::Error::new_spanned(
                &entry.name,
                format!("parameter `{name}` is fixed twice"),
            ));
            continue;
        }
        seen.push(name.clone());
        match literal_value(&name, &entry.value) {
            Ok(v) => fixed.push((entry.name.clone(), v)),
            Err(err) => errors.push(err),
        }
    }
    let mut outputs: Vec<&Ident> = Vec::new();
    if let Some((key, list)) = &e.outputs {
        if list.is_empty() {
            errors.push(syn::Error::new_spanned(
                key,
                "`outputs` is empty; list at least one output or leave the key out for all",
            ));
        }
        for o in list {
            if outputs.iter().any(|p| p.unraw() == o.unraw()) {
                errors.push(syn::Error::new_spanned(
                    o,
                    format!("output `{}` is selected twice", o.unraw()),
                ));
            } else {
                outputs.push(o);
            }
        }
    }
    let mut wrt: Vec<&Ident> = Vec::new();
    if let Some((key, list)) = &e.jacobian {
        if list.is_empty() {
            errors.push(syn::Error::new_spanned(
                key,
                "`jacobian` is empty; list the inputs or parameters to differentiate with respect to",
            ));
        }
        for x in list {
            if wrt.iter().any(|p| p.unraw() == x.unraw()) {
                errors.push(syn::Error::new_spanned(
                    x,
                    format!("`{}` is listed twice in `jacobian`", x.unraw()),
                ));
            } else if fixed.iter().any(|(f, _)| f.unraw() == x.unraw()) {
                errors.push(syn::Error::new_spanned(
                    x,
                    format!(
                        "cannot differentiate with respect to `{}`: the scene fixes it",
                        x.unraw()
                    ),
                ));
            } else {
                wrt.push(x);
            }
        }
    }
    let max_fn_ops = match &e.max_fn_ops {
        None => DEFAULT_MAX_FN_OPS,
        Some(lit) => match lit.base10_parse::<usize>() {
            Ok(n) if n >= 1 => n,
            _ => {
                errors.push(syn::Error::new_spanned(
                    lit,
                    format!("`max_fn_ops` must be a positive integer, found `{lit}`"),
                ));
                DEFAULT_MAX_FN_OPS
            }
        },
    };
    let lanes = e.lanes.as_ref().and_then(|lit| match lit.base10_parse::<usize>() {
        Ok(n) if LANE_COUNTS.contains(&n) => Some(n),
        _ => {
            errors.push(syn::Error::new_spanned(
                lit,
                format!("`lanes` must be 2, 4, 8 or 16, found `{lit}`"),
            ));
            None
        }
    });

    let Some(model) = e.model else {
        return Err(errors.fail(syn::Error::new_spanned(
            &name,
            format!("scene `{name}` has no `model` key; add `model: NAME`"),
        )));
    };
    let model_name = model.unraw().to_string();

    // Load the IR file.
    let (path, display, culprit): (PathBuf, String, &dyn quote::ToTokens) = match &e.path {
        Some(lit) => match ctx.resolve(&lit.value()) {
            Ok(path) => (path, lit.value(), lit),
            Err(tried) => {
                let tried: Vec<String> = tried.iter().map(|p| p.display().to_string()).collect();
                let msg =
                    format!("no IR file `{}` (looked for {})", lit.value(), tried.join(" and "));
                return Err(errors.fail(syn::Error::new_spanned(lit, msg)));
            }
        },
        None => (
            ctx.generated_dir.join(format!("{model_name}.ir")),
            format!("generated/{model_name}.ir"),
            &model,
        ),
    };
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(err) => {
            let msg = if err.kind() == std::io::ErrorKind::NotFound && e.path.is_none() {
                format!("unknown model `{model_name}`: there is no `{display}`")
            } else {
                format!("cannot read IR file `{display}`: {err}")
            };
            return Err(errors.fail(syn::Error::new_spanned(culprit, msg)));
        }
    };
    let ir_path = std::fs::canonicalize(&path).unwrap_or(path);
    let program = match Program::parse(&text) {
        Ok(p) => p,
        Err(err) => {
            return Err(errors.fail(syn::Error::new_spanned(
                culprit,
                format!("malformed IR file `{display}`: {err}"),
            )));
        }
    };
    if let Err(err) = program.validate() {
        return Err(errors.fail(syn::Error::new_spanned(
            culprit,
            format!("malformed IR file `{display}`: {err}"),
        )));
    }
    if program.model != model_name {
        errors.push(syn::Error::new_spanned(
            &model,
            format!(
                "IR file `{display}` is a program of model `{}`, not `{model_name}`",
                program.model
            ),
        ));
    }

    // Names against the program.
    for (ident, _) in &fixed {
        let n = ident.unraw().to_string();
        if !program.params.contains(&n) {
            let msg = if program.inputs.contains(&n) {
                format!(
                    "`{n}` is an input of model `{model_name}`, not a parameter; only parameters can be fixed (parameters: {})",
                    list(&program.params)
                )
            } else {
                format!(
                    "unknown parameter `{n}` of model `{model_name}` (parameters: {})",
                    list(&program.params)
                )
            };
            errors.push(syn::Error::new_spanned(ident, msg));
        }
    }
    let names: Vec<String> = program.outputs.iter().map(|o| o.name.clone()).collect();
    for o in &outputs {
        let n = o.unraw().to_string();
        if !names.contains(&n) {
            errors.push(syn::Error::new_spanned(
                o,
                format!("unknown output `{n}` of model `{model_name}` (outputs: {})", list(&names)),
            ));
        }
    }
    for x in &wrt {
        let n = x.unraw().to_string();
        if !program.inputs.contains(&n) && !program.params.contains(&n) {
            errors.push(syn::Error::new_spanned(
                x,
                format!(
                    "cannot differentiate with respect to `{n}`: model `{model_name}` has no such input or parameter (inputs: {}; parameters: {})",
                    list(&program.inputs),
                    list(&program.params)
                ),
            ));
        }
    }
    if let Some(n) = &e.newton {
        let x = n.input.unraw().to_string();
        if !program.inputs.contains(&x) {
            errors.push(syn::Error::new_spanned(
                &n.input,
                format!(
                    "`newton` steps an input, and `{x}` is not one of model `{model_name}` (inputs: {})",
                    list(&program.inputs)
                ),
            ));
        }
        for o in [&n.residual, &n.derivative] {
            let name = o.unraw().to_string();
            if !names.contains(&name) {
                errors.push(syn::Error::new_spanned(
                    o,
                    format!(
                        "unknown output `{name}` of model `{model_name}` (outputs: {})",
                        list(&names)
                    ),
                ));
            }
        }
    }
    errors.check()?;
    let mut errors = Errors::default();

    // Specialise.
    let source_op_count = program.op_count().total;
    let fixed: Vec<(String, f64)> =
        fixed.iter().map(|(i, v)| (i.unraw().to_string(), *v)).collect();
    let fixed_refs: Vec<(&str, f64)> = fixed.iter().map(|(n, v)| (n.as_str(), *v)).collect();
    let selected: Vec<String> = if e.outputs.is_some() {
        outputs.iter().map(|o| o.unraw().to_string()).collect()
    } else {
        names
    };
    // With `newton`, the program at the corrected input, and its step and corrected input
    // as two more outputs.
    let newton = e.newton.as_ref().map(|n| {
        let x = n.input.unraw().to_string();
        let appended =
            [carvallo_ir::newton::step_name(&x), carvallo_ir::newton::corrected_name(&x)];
        (x, n.residual.unraw().to_string(), n.derivative.unraw().to_string(), appended)
    });
    let selected: Vec<String> = match &newton {
        Some((.., appended)) => selected.into_iter().chain(appended.iter().cloned()).collect(),
        None => selected,
    };
    let selected: Vec<&str> = selected.iter().map(String::as_str).collect();
    let specialised = program
        .fix_params(&fixed_refs)
        .and_then(|p| match &newton {
            Some((x, h, dh, _)) => p.with_newton_step(x, h, dh),
            None => Ok(p),
        })
        .and_then(|p| p.select_outputs(&selected))
        .map(|p| p.fold_constants().eliminate_dead_code());
    // The derivatives: with respect to the variables the selected outputs still depend on
    // (the others are structural zeros everywhere).
    let wrt: Vec<String> = wrt.iter().map(|x| x.unraw().to_string()).collect();
    let mut jacobian = None;
    let specialised = specialised.and_then(|p| {
        if wrt.is_empty() {
            return Ok(p);
        }
        let live: Vec<&str> = wrt
            .iter()
            .filter(|x| p.inputs.contains(x) || p.params.contains(x))
            .map(String::as_str)
            .collect();
        let of: Vec<String> = p.outputs.iter().map(|o| o.name.clone()).collect();
        let d = p.with_jacobian(&live)?;
        let of_refs: Vec<&str> = of.iter().map(String::as_str).collect();
        let wrt_refs: Vec<&str> = wrt.iter().map(String::as_str).collect();
        let entries = d.jacobian_entries(&of_refs, &wrt_refs);
        jacobian = Some(Jacobian { of, wrt: wrt.clone(), entries });
        Ok(d)
    });
    let program = match specialised {
        Ok(p) => p,
        Err(err) => {
            return Err(syn::Error::new_spanned(
                &name,
                format!("cannot specialise model `{model_name}` for scene `{name}`: {err}"),
            ));
        }
    };

    // Field names must be Rust identifiers.
    let fields =
        program.params.iter().chain(&program.inputs).chain(program.outputs.iter().map(|o| &o.name));
    for n in fields {
        if rust_ident(n, Span::call_site()).is_none() {
            errors.push(syn::Error::new_spanned(
                culprit,
                format!("the IR name `{n}` of model `{model_name}` cannot be a Rust field name"),
            ));
        }
    }

    errors.check()?;
    Ok(Scene {
        attrs,
        vis,
        name,
        model: model_name,
        ir_path,
        ir_display: display,
        fixed,
        source_op_count,
        program,
        max_fn_ops,
        lanes,
        jacobian,
    })
}

/// Stores `v` in `slot`; returns whether the slot was already taken (then it is left as is).
fn set<T>(slot: &mut Option<T>, v: T) -> bool {
    if slot.is_some() {
        return true;
    }
    *slot = Some(v);
    false
}

/// `a`, `b`, `c` as "`a`, `b`, `c`" (or "none").
fn list(names: &[String]) -> String {
    if names.is_empty() {
        return "none".to_string();
    }
    names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
}

/// The value of a fixed parameter: a float or integer literal, optionally negated, with no
/// suffix or `f64`, finite.
fn literal_value(name: &Ident, expr: &Expr) -> syn::Result<f64> {
    let non_numeric = || {
        syn::Error::new_spanned(
            expr,
            format!(
                "the value of `{name}` must be a float or integer literal, found `{}`",
                quote::ToTokens::to_token_stream(expr)
            ),
        )
    };
    let (negative, lit) = match expr {
        Expr::Lit(l) => (false, &l.lit),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => match &*u.expr {
            Expr::Lit(l) => (true, &l.lit),
            _ => return Err(non_numeric()),
        },
        _ => return Err(non_numeric()),
    };
    let (value, suffix) = match lit {
        Lit::Float(f) => (f.base10_parse::<f64>(), f.suffix()),
        Lit::Int(i) => (
            i.base10_digits().parse::<f64>().map_err(|e| syn::Error::new_spanned(i, e)),
            i.suffix(),
        ),
        _ => return Err(non_numeric()),
    };
    if !(suffix.is_empty() || suffix == "f64") {
        return Err(syn::Error::new_spanned(
            lit,
            format!("the value of `{name}` must be an `f64` literal, found suffix `{suffix}`"),
        ));
    }
    let value = value?;
    if !value.is_finite() {
        return Err(syn::Error::new_spanned(
            expr,
            format!(
                "the value of `{name}` is not a finite `f64`: `{}`",
                quote::ToTokens::to_token_stream(expr)
            ),
        ));
    }
    Ok(if negative { -value } else { value })
}
