//! Emission of a [`Derivation`] into the committed artifacts: the IR program
//! (`generated/<model>.ir`), the readable rendering (`generated/<model>.md`) and the table of
//! symbolic checks (`generated/<model>.checks.tsv`).
//!
//! # From a symbolica expression to IR
//!
//! A formula is first read, through symbolica's public view API ([`AtomView`]), into a small
//! owned expression tree ([`Expr`]) whose sums and products are sorted by a canonical order that
//! depends only on the expression itself: symbol names, exact rational numbers and structure,
//! never symbolica's internal symbol numbering (which depends on the order in which a process
//! happened to create its symbols). Every output of this module is a deterministic function of
//! that tree, so the emitted files are byte-stable across runs and processes.
//!
//! The tree is then lowered with [`carvallo_ir::Builder`], whose hash-consing shares every
//! repeated sub-expression (common-subexpression elimination by construction):
//!
//! * numbers are exact rationals and become the correctly rounded `f64` (round to nearest, ties
//!   to even), checked with exact rational arithmetic so that big numerators and denominators
//!   are handled; a number outside the finite `f64` range is an error;
//! * symbols become the parameter or input of the same name (symbolica namespaces are
//!   ignored); the constant $\pi$ becomes its `f64` value; any other symbol is an error naming
//!   it;
//! * a sum is folded left to right in canonical order, terms with a negative coefficient being
//!   subtracted rather than negated and added;
//! * a product $c \prod_i b_i^{k_i}$ is lowered as
//!   $c \cdot \bigl(\prod_{k_i>0} b_i^{k_i}\bigr) / \bigl(\prod_{k_i<0} b_i^{-k_i}\bigr)$: all
//!   factors with negative exponents are collected into one division, the monomial is built
//!   before the coefficient is applied (so terms that differ only by their coefficient share it),
//!   and a coefficient $1/q$ becomes a division by $q$ when $q$ is exact in `f64`;
//! * an integer power $b^k$, $|k| \ge 2$, becomes `powi b k`. Small positive powers are *not*
//!   expanded into multiplications here: `powi` with a constant exponent costs the same op count
//!   as the multiplications it replaces and code generators (LLVM included) expand it
//!   themselves, while keeping it makes the IR and its op counts easier to read;
//! * a half-integer power $b^{k/2}$ becomes `sqrt b`, raised to the integer power $k$ by the
//!   rule above (so $b^{1/2}$ is `sqrt b` and $b^{-1/2}$ divides by `sqrt b`);
//! * the functions `sin`, `cos`, `sqrt` (symbolica built-ins) and the user functions `tan` (one
//!   argument) and `atan2` (two arguments, $y$ then $x$) become the IR operations of the same
//!   name.
//!
//! Anything else (other functions, symbolic exponents, complex or floating-point numbers) is an
//! [`EmitError`] naming the offending sub-expression.
//!
//! # Modules
//!
//! [`expr`] reads symbolica into the canonical tree, [`lower`] turns the tree into IR, [`text`]
//! and [`latex`] print it, [`markdown`] and [`checks_tsv`] render the other two artifacts.

mod checks_tsv;
mod expr;
mod latex;
mod lower;
mod markdown;
mod optimize;
mod text;

use std::collections::BTreeMap;
use std::fmt;

use carvallo_ir::{Builder, Program, Value};
use symbolica::atom::Atom;

use crate::{Derivation, Formula};

pub use checks_tsv::render_checks;
pub use expr::{rational_to_f64, Expr, Func};
pub use latex::latex;
pub use markdown::{normalize_text, render_markdown, MAX_RENDERED_CHARS};
pub use optimize::{
    choose, declare_placeholders, emit_program_optimized, Effort, EFFORTS, PLACEHOLDERS,
};
pub use text::text;

use lower::{is_ir_name, Lowerer};

/// Why a derivation could not be emitted.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum EmitError {
    /// A symbol that is neither a parameter nor an input of the derivation.
    UnknownSymbol {
        /// The symbol's name, without namespace.
        name: String,
    },
    /// A sub-expression the IR cannot represent.
    Unsupported {
        /// What is not supported, lower-case.
        what: String,
        /// The offending sub-expression, as printed by symbolica.
        expr: String,
    },
    /// An exact number that has no finite `f64` value.
    Constant {
        /// The number, as an exact rational.
        value: String,
    },
    /// A parameter, input or output name that is not a valid IR name or is declared twice.
    BadName {
        /// The offending name.
        name: String,
        /// What is wrong with it, lower-case.
        reason: String,
    },
    /// An error inside one formula of the derivation.
    InFormula {
        /// The formula's output name.
        formula: String,
        /// The error.
        error: Box<EmitError>,
    },
}

impl fmt::Display for EmitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EmitError::UnknownSymbol { name } => {
                write!(f, "unknown symbol {name:?}: not a parameter or input of the derivation")
            }
            EmitError::Unsupported { what, expr } => write!(f, "unsupported {what} in `{expr}`"),
            EmitError::Constant { value } => {
                write!(f, "constant {value} has no finite f64 value")
            }
            EmitError::BadName { name, reason } => write!(f, "bad name {name:?}: {reason}"),
            EmitError::InFormula { formula, error } => write!(f, "formula {formula}: {error}"),
        }
    }
}

impl std::error::Error for EmitError {}

/// The header line every generated file starts with (without comment markers).
pub fn generated_header(source: &str) -> String {
    format!("Generated by `cargo xtask regen` from {source}; do not edit by hand.")
}

/// A builder with the derivation's parameters and inputs declared, in order, and the map from
/// their names to values.
fn declare(d: &Derivation) -> Result<(Builder, BTreeMap<String, Value>), EmitError> {
    let mut b = Builder::new(&d.model);
    let mut names = BTreeMap::new();
    for (name, is_param) in
        d.params.iter().map(|p| (p, true)).chain(d.inputs.iter().map(|i| (i, false)))
    {
        if !is_ir_name(name) {
            return Err(EmitError::BadName {
                name: name.clone(),
                reason: "not a valid IR name".into(),
            });
        }
        let v = if is_param { b.param(name) } else { b.input(name) };
        if names.insert(name.clone(), v).is_some() {
            return Err(EmitError::BadName { name: name.clone(), reason: "declared twice".into() });
        }
    }
    Ok((b, names))
}

fn in_formula(f: &Formula) -> impl FnOnce(EmitError) -> EmitError + '_ {
    move |e| EmitError::InFormula { formula: f.name.clone(), error: Box::new(e) }
}

/// Lowers one expression into `b`, whose parameters and inputs are named by `names`.
pub fn emit_expr(
    b: &mut Builder,
    names: &BTreeMap<String, Value>,
    expr: &Atom,
) -> Result<Value, EmitError> {
    let e = Expr::from_atom(expr)?;
    Lowerer { b, names }.value(&e)
}

/// The IR program of a derivation: every formula is an output (in the derivation's order),
/// parameters and inputs are declared in the derivation's order, and the header names the
/// command and the source. A symbol that names an earlier formula (and no parameter or input)
/// stands for that formula's value, so a derivation can hand over a chain of named intermediate
/// quantities instead of one expanded expression.
pub fn emit_program(d: &Derivation) -> Result<Program, EmitError> {
    let (mut b, mut names) = declare(d)?;
    b.header(&generated_header(&d.source));
    let outputs: Vec<&str> = d.formulas.iter().map(|f| f.name.as_str()).collect();
    b.header(&format!("Outputs: {}.", outputs.join(", ")));
    let mut seen = std::collections::BTreeSet::new();
    for f in &d.formulas {
        if !is_ir_name(&f.name) {
            return Err(EmitError::BadName {
                name: f.name.clone(),
                reason: "not a valid IR name".into(),
            });
        }
        if !seen.insert(f.name.as_str()) {
            return Err(EmitError::BadName {
                name: f.name.clone(),
                reason: "output declared twice".into(),
            });
        }
        let v = emit_expr(&mut b, &names, &f.expr).map_err(in_formula(f))?;
        b.output(&f.name, v);
        // A later formula may refer to this one by name (a parameter or input of the same
        // name keeps precedence, so models without such references emit as before).
        names.entry(f.name.clone()).or_insert(v);
    }
    Ok(b.finish())
}

/// Op counts of a program: the number of non-constant instructions and their split by
/// mnemonic ([`Program::op_count`] as a pair).
pub fn count_ops(p: &Program) -> (usize, BTreeMap<&'static str, usize>) {
    let c = p.op_count();
    (c.total, c.by_op)
}

/// The op count of one formula on its own, after common-subexpression elimination.
///
/// Earlier formulas the formula refers to by name count as free inputs here: the count is that
/// of the formula's own operations.
pub fn formula_op_count(
    d: &Derivation,
    f: &Formula,
) -> Result<(usize, BTreeMap<&'static str, usize>), EmitError> {
    let (mut b, mut names) = declare(d)?;
    for earlier in d.formulas.iter().take_while(|g| !std::ptr::eq(*g, f)) {
        if !names.contains_key(&earlier.name) && is_ir_name(&earlier.name) {
            let v = b.input(&earlier.name);
            names.insert(earlier.name.clone(), v);
        }
    }
    let v = emit_expr(&mut b, &names, &f.expr).map_err(in_formula(f))?;
    b.output(&f.name, v);
    Ok(count_ops(&b.finish()))
}
