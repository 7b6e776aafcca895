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

use std::collections::BTreeMap;
use std::fmt;

use carvallo_ir::{Builder, Op, Program, Value};
use symbolica::atom::{Atom, AtomView, Symbol};
use symbolica::coefficient::Coefficient;
use symbolica::domains::rational::Rational;
use symbolica::domains::SelfRing;

use crate::{Check, Derivation, Formula};

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

/// A function the IR knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Func {
    /// $\sqrt{a}$ (symbolica's built-in `sqrt`).
    Sqrt,
    /// $\sin a$ (built-in).
    Sin,
    /// $\cos a$ (built-in).
    Cos,
    /// $\tan a$ (a user function named `tan`).
    Tan,
    /// $\operatorname{atan2}(y, x)$ (a user function named `atan2`).
    Atan2,
}

impl Func {
    fn name(self) -> &'static str {
        match self {
            Func::Sqrt => "sqrt",
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Atan2 => "atan2",
        }
    }

    fn arity(self) -> usize {
        match self {
            Func::Atan2 => 2,
            _ => 1,
        }
    }
}

/// An expression in canonical form: the owned image of a symbolica expression with sorted
/// sums and products, independent of symbolica's internal symbol numbering.
///
/// The derived order (variant order first, then fields) is the canonical order; sums and
/// products sort their children with the keys described at [`Expr::from_atom`].
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Expr {
    /// An exact rational number.
    Num(Rational),
    /// A symbol, by its name without namespace.
    Sym(String),
    /// The constant $\pi$.
    Pi,
    /// A function call.
    Fun(Func, Vec<Expr>),
    /// A power with a rational exponent (never 0 or 1).
    Pow(Box<Expr>, Rational),
    /// A product of at least one factor (none of them a number or a product) times a rational
    /// coefficient; the factors come first so that terms sort by their monomial.
    Mul(Vec<Expr>, Rational),
    /// A sum of at least two terms (none of them a sum).
    Add(Vec<Expr>),
}

fn rat(n: i64) -> Rational {
    Rational::from(n)
}

fn unsupported(what: impl Into<String>, v: AtomView<'_>) -> EmitError {
    EmitError::Unsupported { what: what.into(), expr: v.to_string() }
}

/// The exact rational value of a numeric atom.
fn number(v: AtomView<'_>) -> Result<Rational, EmitError> {
    let AtomView::Num(n) = v else {
        return Err(unsupported("non-numeric value where a number is needed", v));
    };
    match n.get_coeff_view().normalize() {
        Coefficient::Complex(c) if c.im.is_zero() => Ok(c.re),
        Coefficient::Complex(_) => Err(unsupported("complex number", v)),
        Coefficient::Float(c) if c.im.is_zero() => Rational::try_from(c.re)
            .map_err(|e| unsupported(format!("floating-point number ({e})"), v)),
        Coefficient::Float(_) => Err(unsupported("complex floating-point number", v)),
        _ => Err(unsupported("non-rational coefficient", v)),
    }
}

/// Sort key of a term in a sum: numbers last, then by monomial, then by coefficient.
fn term_key(e: &Expr) -> (bool, &[Expr], Rational) {
    match e {
        Expr::Num(r) => (true, &[], r.clone()),
        Expr::Mul(f, c) => (false, f.as_slice(), c.clone()),
        other => (false, std::slice::from_ref(other), rat(1)),
    }
}

/// Sort key of a factor in a product: by base, then by exponent.
fn factor_key(e: &Expr) -> (&Expr, Rational) {
    match e {
        Expr::Pow(b, k) => (b, k.clone()),
        other => (other, rat(1)),
    }
}

impl Expr {
    /// Reads a symbolica expression into canonical form.
    ///
    /// Terms of a sum are sorted by monomial (numbers last), then coefficient; factors of a
    /// product by base, then exponent; numeric factors are multiplied into the coefficient.
    pub fn from_atom(atom: &Atom) -> Result<Expr, EmitError> {
        Expr::from_view(atom.as_view())
    }

    fn from_view(v: AtomView<'_>) -> Result<Expr, EmitError> {
        match v {
            AtomView::Num(_) => Ok(Expr::Num(number(v)?)),
            AtomView::Var(x) => {
                let s = x.get_symbol();
                if s == Symbol::PI {
                    Ok(Expr::Pi)
                } else if s == Symbol::E {
                    Err(unsupported("constant e", v))
                } else {
                    Ok(Expr::Sym(s.get_stripped_name().to_string()))
                }
            }
            AtomView::Fun(f) => {
                let s = f.get_symbol();
                let func = if s == Symbol::SIN {
                    Func::Sin
                } else if s == Symbol::COS {
                    Func::Cos
                } else if s == Symbol::SQRT {
                    Func::Sqrt
                } else {
                    match s.get_stripped_name() {
                        "tan" => Func::Tan,
                        "atan2" => Func::Atan2,
                        name => return Err(unsupported(format!("function {name}"), v)),
                    }
                };
                if f.get_nargs() != func.arity() {
                    return Err(unsupported(
                        format!(
                            "call of {} with {} arguments (expected {})",
                            func.name(),
                            f.get_nargs(),
                            func.arity()
                        ),
                        v,
                    ));
                }
                let args = f.iter().map(Expr::from_view).collect::<Result<Vec<_>, _>>()?;
                Ok(Expr::Fun(func, args))
            }
            AtomView::Pow(p) => {
                let (b, e) = p.get_base_exp();
                let k = match e {
                    AtomView::Num(_) => number(e)?,
                    _ => return Err(unsupported("symbolic exponent", v)),
                };
                let base = Expr::from_view(b)?;
                Ok(Expr::pow(base, k))
            }
            AtomView::Mul(m) => {
                let mut coeff = rat(1);
                let mut factors = Vec::new();
                for f in m.iter() {
                    match Expr::from_view(f)? {
                        Expr::Num(r) => coeff = &coeff * &r,
                        Expr::Mul(fs, c) => {
                            coeff = &coeff * &c;
                            factors.extend(fs);
                        }
                        other => factors.push(other),
                    }
                }
                Ok(Expr::mul(factors, coeff))
            }
            AtomView::Add(a) => {
                let mut terms = Vec::new();
                for t in a.iter() {
                    match Expr::from_view(t)? {
                        Expr::Add(ts) => terms.extend(ts),
                        other => terms.push(other),
                    }
                }
                terms.sort_by(|x, y| term_key(x).cmp(&term_key(y)));
                Ok(if terms.len() == 1 {
                    terms.pop().unwrap_or(Expr::Num(rat(0)))
                } else {
                    Expr::Add(terms)
                })
            }
        }
    }

    fn pow(base: Expr, k: Rational) -> Expr {
        if k == rat(1) {
            base
        } else if k.is_zero() {
            Expr::Num(rat(1))
        } else {
            Expr::Pow(Box::new(base), k)
        }
    }

    fn mul(mut factors: Vec<Expr>, coeff: Rational) -> Expr {
        factors.sort_by(|x, y| factor_key(x).cmp(&factor_key(y)));
        if factors.is_empty() || coeff.is_zero() {
            Expr::Num(coeff)
        } else if factors.len() == 1 && coeff == rat(1) {
            factors.pop().unwrap_or(Expr::Num(rat(1)))
        } else {
            Expr::Mul(factors, coeff)
        }
    }

    /// Whether this expression prints with a leading minus sign.
    fn is_negative(&self) -> bool {
        match self {
            Expr::Num(r) | Expr::Mul(_, r) => r.is_negative(),
            _ => false,
        }
    }

    /// The expression with the sign of its coefficient flipped (only for negative ones).
    fn negated(&self) -> Expr {
        match self {
            Expr::Num(r) => Expr::Num(-r.clone()),
            Expr::Mul(f, c) => Expr::mul(f.clone(), -c.clone()),
            other => Expr::Mul(vec![other.clone()], rat(-1)),
        }
    }
}

/// The `f64` nearest to `r` (ties to even), or `None` if it is outside the finite range.
///
/// The candidate from symbolica's conversion is verified, and corrected if needed, with exact
/// rational comparisons against its neighbours, so the result does not depend on how that
/// conversion rounds.
pub fn rational_to_f64(r: &Rational) -> Option<f64> {
    let exact = |x: f64| Rational::try_from(x).ok();
    let mut x = r.to_f64();
    if x.is_nan() {
        return None;
    }
    if x.is_infinite() {
        x = f64::MAX.copysign(x);
    }
    for _ in 0..1100 {
        let ex = exact(x)?;
        let toward_up = match ex.cmp(r) {
            std::cmp::Ordering::Equal => return Some(x),
            std::cmp::Ordering::Less => true,
            std::cmp::Ordering::Greater => false,
        };
        let next = if toward_up { x.next_up() } else { x.next_down() };
        if next.is_infinite() {
            // Beyond the largest finite value: rounds to it only below half an ulp past it.
            let half_ulp = exact(2f64.powi(970))?;
            let limit = if toward_up {
                &exact(f64::MAX)? + &half_ulp
            } else {
                &exact(-f64::MAX)? - &half_ulp
            };
            let inside = if toward_up { *r < limit } else { *r > limit };
            return inside.then_some(x);
        }
        let en = exact(next)?;
        let past = if toward_up { en <= *r } else { en >= *r };
        if past {
            x = next;
            continue;
        }
        // r lies strictly between x and next.
        let dx = (&ex - r).abs();
        let dn = (&en - r).abs();
        return Some(match dx.cmp(&dn) {
            std::cmp::Ordering::Less => x,
            std::cmp::Ordering::Greater => next,
            std::cmp::Ordering::Equal => {
                if x.to_bits() & 1 == 0 {
                    x
                } else {
                    next
                }
            }
        });
    }
    None
}

/// Lowers canonical expressions into a [`Builder`].
struct Lowerer<'a> {
    b: &'a mut Builder,
    names: &'a BTreeMap<String, Value>,
}

impl Lowerer<'_> {
    fn constant(&mut self, r: &Rational) -> Result<Value, EmitError> {
        let x = rational_to_f64(r).ok_or_else(|| EmitError::Constant { value: r.to_string() })?;
        Ok(self.b.constant(x))
    }

    fn value(&mut self, e: &Expr) -> Result<Value, EmitError> {
        match e {
            Expr::Num(r) => self.constant(r),
            _ => {
                let (negative, v) = self.magnitude(e)?;
                Ok(if negative { self.b.neg(v) } else { v })
            }
        }
    }

    /// `(true, |e|)` when `e` has a negative coefficient, `(false, e)` otherwise.
    fn magnitude(&mut self, e: &Expr) -> Result<(bool, Value), EmitError> {
        Ok(match e {
            Expr::Num(r) => (r.is_negative(), self.constant(&r.abs())?),
            Expr::Sym(name) => {
                let v = self
                    .names
                    .get(name)
                    .copied()
                    .ok_or_else(|| EmitError::UnknownSymbol { name: name.clone() })?;
                (false, v)
            }
            Expr::Pi => (false, self.b.constant(std::f64::consts::PI)),
            Expr::Fun(func, args) => {
                let a = self.value(&args[0])?;
                let v = match func {
                    Func::Sqrt => self.b.sqrt(a),
                    Func::Sin => self.b.sin(a),
                    Func::Cos => self.b.cos(a),
                    Func::Tan => self.b.tan(a),
                    Func::Atan2 => {
                        let x = self.value(&args[1])?;
                        self.b.atan2(a, x)
                    }
                };
                (false, v)
            }
            Expr::Pow(..) => (false, self.product(std::slice::from_ref(e), &rat(1))?),
            Expr::Mul(factors, c) => (c.is_negative(), self.product(factors, &c.abs())?),
            Expr::Add(terms) => (false, self.sum(terms)?),
        })
    }

    fn sum(&mut self, terms: &[Expr]) -> Result<Value, EmitError> {
        let mut parts = Vec::with_capacity(terms.len());
        for t in terms {
            parts.push(self.magnitude(t)?);
        }
        // Start from the first positive term so that no negation is needed.
        let Some(first) = parts.iter().position(|(neg, _)| !neg) else {
            let mut acc = parts[0].1;
            for &(_, v) in &parts[1..] {
                acc = self.b.add(acc, v);
            }
            return Ok(self.b.neg(acc));
        };
        let mut acc = parts[first].1;
        for (i, &(neg, v)) in parts.iter().enumerate() {
            if i == first {
                continue;
            }
            acc = if neg { self.b.sub(acc, v) } else { self.b.add(acc, v) };
        }
        Ok(acc)
    }

    /// A factor as (base value, nonzero integer exponent).
    fn factor(&mut self, f: &Expr) -> Result<(Value, i64, Expr), EmitError> {
        let Expr::Pow(base, k) = f else {
            return Ok((self.value(f)?, 1, f.clone()));
        };
        let b = self.value(base)?;
        if k.is_integer() {
            return Ok((b, rational_integer(k, f)?, f.clone()));
        }
        let twice = k * &rat(2);
        if twice.is_integer() {
            let s = self.b.sqrt(b);
            return Ok((s, rational_integer(&twice, f)?, f.clone()));
        }
        Err(EmitError::Unsupported {
            what: format!("exponent {k} (only integers and halves are supported)"),
            expr: text(f),
        })
    }

    fn power(&mut self, b: Value, k: i64, f: &Expr) -> Result<Value, EmitError> {
        if k == 1 {
            return Ok(b);
        }
        let k = i32::try_from(k).map_err(|_| EmitError::Unsupported {
            what: format!("exponent {k} outside the i32 range"),
            expr: text(f),
        })?;
        Ok(self.b.powi(b, k))
    }

    /// $c \prod b_i^{k_i}$ for a nonnegative coefficient `c`.
    fn product(&mut self, factors: &[Expr], c: &Rational) -> Result<Value, EmitError> {
        let mut num: Option<Value> = None;
        let mut den: Option<Value> = None;
        for f in factors {
            let (b, k, f) = self.factor(f)?;
            if k > 0 {
                let t = self.power(b, k, &f)?;
                num = Some(match num {
                    Some(n) => self.b.mul(n, t),
                    None => t,
                });
            } else {
                let t = self.power(b, -k, &f)?;
                den = Some(match den {
                    Some(d) => self.b.mul(d, t),
                    None => t,
                });
            }
        }
        let one = *c == rat(1);
        let monomial = match (num, den) {
            (Some(n), Some(d)) => self.b.div(n, d),
            (Some(n), None) => n,
            (None, Some(d)) => {
                let cv = self.constant(c)?;
                return Ok(self.b.div(cv, d));
            }
            (None, None) => return self.constant(c),
        };
        if one {
            return Ok(monomial);
        }
        // A coefficient 1/q with q exact in f64 divides by q: one correctly rounded operation.
        let inv = &rat(1) / c;
        if inv.is_integer() {
            if let Some(q) =
                rational_to_f64(&inv).filter(|q| Rational::try_from(*q).ok().as_ref() == Some(&inv))
            {
                let qv = self.b.constant(q);
                return Ok(self.b.div(monomial, qv));
            }
        }
        let cv = self.constant(c)?;
        Ok(self.b.mul(cv, monomial))
    }
}

fn rational_integer(k: &Rational, f: &Expr) -> Result<i64, EmitError> {
    let s = k.to_string();
    s.parse::<i64>().map_err(|_| EmitError::Unsupported {
        what: format!("exponent {s} outside the i64 range"),
        expr: text(f),
    })
}

fn is_ir_name(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c == '_' || c.is_ascii_alphabetic())
        && chars.all(|c| c == '_' || c.is_ascii_alphanumeric())
}

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
/// mnemonic (the same definition as `Program::op_count`).
pub fn count_ops(p: &Program) -> (usize, BTreeMap<&'static str, usize>) {
    let mut by_op = BTreeMap::new();
    let mut total = 0;
    for inst in &p.insts {
        if !matches!(inst.op, Op::Const(_)) {
            total += 1;
            *by_op.entry(inst.op.mnemonic()).or_insert(0) += 1;
        }
    }
    (total, by_op)
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

// ---------------------------------------------------------------------------------------------
// Printers

const PREC_ADD: u8 = 1;
const PREC_MUL: u8 = 2;
const PREC_POW: u8 = 3;
const PREC_ATOM: u8 = 4;

fn precedence(e: &Expr) -> u8 {
    match e {
        Expr::Add(_) => PREC_ADD,
        Expr::Mul(..) => PREC_MUL,
        Expr::Num(r) if r.is_negative() || !r.is_integer() => PREC_MUL,
        Expr::Pow(_, k) if *k == half() => PREC_ATOM,
        Expr::Pow(..) => PREC_POW,
        _ => PREC_ATOM,
    }
}

fn half() -> Rational {
    &rat(1) / &rat(2)
}

/// Splits a product into (sign is negative, |coefficient|, numerator factors, denominator
/// factors with their exponents made positive).
fn split_product(factors: &[Expr], c: &Rational) -> (bool, Rational, Vec<Expr>, Vec<Expr>) {
    let mut num = Vec::new();
    let mut den = Vec::new();
    for f in factors {
        match f {
            Expr::Pow(b, k) if k.is_negative() => den.push(Expr::pow((**b).clone(), -k.clone())),
            other => num.push(other.clone()),
        }
    }
    (c.is_negative(), c.abs(), num, den)
}

/// The expression as plain text (`*`, `/`, `^`, function calls), in canonical order.
pub fn text(e: &Expr) -> String {
    match e {
        Expr::Num(r) => r.to_string(),
        Expr::Sym(s) => s.clone(),
        Expr::Pi => "pi".to_string(),
        Expr::Fun(f, args) => {
            let args: Vec<String> = args.iter().map(text).collect();
            format!("{}({})", f.name(), args.join(", "))
        }
        Expr::Pow(b, k) => {
            if *k == half() {
                format!("sqrt({})", text(b))
            } else {
                let base = wrap_text(b, PREC_ATOM);
                if k.is_integer() && !k.is_negative() {
                    format!("{base}^{k}")
                } else {
                    format!("{base}^({k})")
                }
            }
        }
        Expr::Mul(factors, c) => {
            let (negative, c, num, den) = split_product(factors, c);
            let mut n: Vec<String> = Vec::new();
            let cn = c.numerator();
            let cd = c.denominator();
            if cn.to_string() != "1" {
                n.push(cn.to_string());
            }
            n.extend(num.iter().map(|f| wrap_text(f, PREC_POW)));
            let mut d: Vec<String> = Vec::new();
            if cd.to_string() != "1" {
                d.push(cd.to_string());
            }
            d.extend(den.iter().map(|f| wrap_text(f, PREC_POW)));
            let mut s = String::new();
            if negative {
                s.push('-');
            }
            s.push_str(&if n.is_empty() { "1".to_string() } else { n.join("*") });
            match d.len() {
                0 => {}
                1 => {
                    s.push('/');
                    s.push_str(&d[0]);
                }
                _ => {
                    s.push_str("/(");
                    s.push_str(&d.join("*"));
                    s.push(')');
                }
            }
            s
        }
        Expr::Add(terms) => {
            let mut s = text(&terms[0]);
            for t in &terms[1..] {
                if t.is_negative() {
                    s.push_str(" - ");
                    s.push_str(&wrap_text(&t.negated(), PREC_MUL));
                } else {
                    s.push_str(" + ");
                    s.push_str(&text(t));
                }
            }
            s
        }
    }
}

fn wrap_text(e: &Expr, min: u8) -> String {
    if precedence(e) < min {
        format!("({})", text(e))
    } else {
        text(e)
    }
}

const GREEK: &[&str] = &[
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
    "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi",
    "Omega",
];

fn latex_name(name: &str) -> String {
    let (base, sub) = match name.split_once('_') {
        Some((b, s)) if !b.is_empty() && !s.is_empty() => (b, Some(s)),
        _ => (name, None),
    };
    let base = if GREEK.contains(&base) {
        format!("\\{base}")
    } else if base.chars().count() > 1 {
        format!("\\mathrm{{{}}}", base.replace('_', "\\_"))
    } else {
        base.to_string()
    };
    match sub {
        Some(s) => format!("{base}_{{\\mathrm{{{}}}}}", s.replace('_', "\\_")),
        None => base,
    }
}

fn latex_rational(r: &Rational) -> String {
    let sign = if r.is_negative() { "-" } else { "" };
    let a = r.abs();
    if a.is_integer() {
        format!("{sign}{a}")
    } else {
        format!("{sign}\\frac{{{}}}{{{}}}", a.numerator(), a.denominator())
    }
}

/// The expression as LaTeX (math mode, without delimiters), in canonical order.
pub fn latex(e: &Expr) -> String {
    match e {
        Expr::Num(r) => latex_rational(r),
        Expr::Sym(s) => latex_name(s),
        Expr::Pi => "\\pi".to_string(),
        Expr::Fun(f, args) => match f {
            Func::Sqrt => format!("\\sqrt{{{}}}", latex(&args[0])),
            Func::Atan2 => {
                format!(
                    "\\operatorname{{atan2}}\\left({}, {}\\right)",
                    latex(&args[0]),
                    latex(&args[1])
                )
            }
            _ => format!("\\{}{}", f.name(), latex_fun_arg(&args[0])),
        },
        Expr::Pow(b, k) => {
            if *k == half() {
                return format!("\\sqrt{{{}}}", latex(b));
            }
            let exp = if k.is_integer() {
                k.to_string()
            } else {
                format!("{}/{}", k.numerator(), k.denominator())
            };
            match &**b {
                Expr::Fun(f @ (Func::Sin | Func::Cos | Func::Tan), args)
                    if k.is_integer() && !k.is_negative() =>
                {
                    format!("\\{}^{{{exp}}}{}", f.name(), latex_fun_arg(&args[0]))
                }
                base => format!("{}^{{{exp}}}", wrap_latex(base, PREC_ATOM)),
            }
        }
        Expr::Mul(factors, c) => {
            let (negative, c, num, den) = split_product(factors, c);
            let mut n: Vec<String> = Vec::new();
            if c.numerator().to_string() != "1" {
                n.push(c.numerator().to_string());
            }
            n.extend(num.iter().map(|f| wrap_latex(f, PREC_POW)));
            let mut d: Vec<String> = Vec::new();
            if c.denominator().to_string() != "1" {
                d.push(c.denominator().to_string());
            }
            d.extend(den.iter().map(|f| wrap_latex(f, PREC_POW)));
            let sign = if negative { "-" } else { "" };
            let n = if n.is_empty() { "1".to_string() } else { n.join(" ") };
            if d.is_empty() {
                format!("{sign}{n}")
            } else {
                format!("{sign}\\frac{{{n}}}{{{}}}", d.join(" "))
            }
        }
        Expr::Add(terms) => {
            let mut s = latex(&terms[0]);
            for t in &terms[1..] {
                if t.is_negative() {
                    s.push_str(" - ");
                    s.push_str(&wrap_latex(&t.negated(), PREC_MUL));
                } else {
                    s.push_str(" + ");
                    s.push_str(&latex(t));
                }
            }
            s
        }
    }
}

fn latex_fun_arg(a: &Expr) -> String {
    match a {
        Expr::Sym(_) | Expr::Pi => format!(" {}", latex(a)),
        Expr::Num(r) if r.is_integer() && !r.is_negative() => format!(" {}", latex(a)),
        _ => format!("\\left({}\\right)", latex(a)),
    }
}

fn wrap_latex(e: &Expr, min: u8) -> String {
    if precedence(e) < min {
        format!("\\left({}\\right)", latex(e))
    } else {
        latex(e)
    }
}

// ---------------------------------------------------------------------------------------------
// Artifacts

fn one_line(s: &str) -> String {
    let s: String =
        s.chars().map(|c| if c == '\t' || c == '\n' || c == '\r' { ' ' } else { c }).collect();
    s.trim().to_string()
}

/// Normalises a rendered file: LF line ends, no trailing spaces (tabs are kept: they separate
/// possibly empty TSV fields), exactly one final newline.
pub fn normalize_text(s: &str) -> String {
    let s = s.replace("\r\n", "\n").replace('\r', "\n");
    let mut out: String = s.lines().map(|l| l.trim_end_matches(' ')).collect::<Vec<_>>().join("\n");
    let trimmed = out.trim_end_matches('\n').len();
    out.truncate(trimmed);
    out.push('\n');
    out
}

/// Longest plain-text rendering of a formula that `generated/<model>.md` prints (with its
/// LaTeX form); longer formulas are listed with their op count only, to keep the file small.
pub const MAX_RENDERED_CHARS: usize = 16_000;

/// `generated/<model>.md`: every formula with its memoir section, description, plain-text and
/// LaTeX forms and op count after common-subexpression elimination.
pub fn render_markdown(d: &Derivation) -> Result<String, EmitError> {
    let mut s = String::new();
    s.push_str(&format!("<!-- {} -->\n\n", generated_header(&d.source)));
    s.push_str(&format!("# Model `{}`\n\n", d.model));
    s.push_str(&format!("Parameters: {}.\n\n", code_list(&d.params)));
    s.push_str(&format!("Inputs: {}.\n\n", code_list(&d.inputs)));
    let program = emit_program(d)?;
    let (total, by_op) = count_ops(&program);
    s.push_str(&format!(
        "{} formulas; the whole program (`{}.ir`, all outputs sharing common subexpressions) takes {} ops ({}).\n\n",
        d.formulas.len(),
        d.model,
        total,
        by_op_text(&by_op)
    ));
    s.push_str("Op counts are the non-constant IR instructions of each formula compiled on its own after common-subexpression elimination.\n\n");
    s.push_str("| output | n° | ops |\n|---|---|---|\n");
    let mut rows = Vec::new();
    for f in &d.formulas {
        let (ops, by) = formula_op_count(d, f)?;
        s.push_str(&format!("| `{}` | {} | {} |\n", f.name, one_line(&f.section), ops));
        rows.push((f, ops, by));
    }
    for (f, ops, by) in rows {
        let e = Expr::from_atom(&f.expr).map_err(in_formula(f))?;
        s.push_str(&format!("\n## `{}` (n° {})\n\n", f.name, one_line(&f.section)));
        s.push_str(&format!("{}\n\n", one_line(&f.description)));
        let plain = text(&e);
        if plain.len() > MAX_RENDERED_CHARS {
            s.push_str(&format!(
                "Not rendered: its plain text takes {} characters (more than {MAX_RENDERED_CHARS}); the formula is in `{}.ir`.\n\n",
                plain.len(),
                d.model
            ));
        } else {
            s.push_str(&format!("```text\n{plain}\n```\n\n"));
            s.push_str(&format!("$$\n{}\n$$\n\n", latex(&e)));
        }
        s.push_str(&format!("Ops after CSE: {} ({}).\n", ops, by_op_text(&by)));
    }
    Ok(normalize_text(&s))
}

fn code_list(names: &[String]) -> String {
    if names.is_empty() {
        return "none".to_string();
    }
    names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
}

fn by_op_text(by_op: &BTreeMap<&'static str, usize>) -> String {
    if by_op.is_empty() {
        return "none".to_string();
    }
    by_op.iter().map(|(k, v)| format!("{v} {k}")).collect::<Vec<_>>().join(", ")
}

/// `generated/<model>.checks.tsv`: `#` header lines, then one line per check:
/// `section<TAB>id<TAB>holds<TAB>statement<TAB>detail`, tabs and newlines inside the text
/// replaced by spaces.
pub fn render_checks(d: &Derivation) -> String {
    let mut s = String::new();
    s.push_str(&format!("# {}\n", generated_header(&d.source)));
    s.push_str(&format!("# Symbolic checks of model {}, in the order they were made.\n", d.model));
    s.push_str(
        "# Columns: section<TAB>id<TAB>holds<TAB>statement<TAB>detail (holds is true or false).\n",
    );
    for c in &d.checks {
        s.push_str(&check_line(c));
        s.push('\n');
    }
    normalize_text(&s)
}

fn check_line(c: &Check) -> String {
    format!(
        "{}\t{}\t{}\t{}\t{}",
        one_line(&c.section),
        one_line(&c.id),
        c.holds,
        one_line(&c.statement),
        one_line(&c.detail)
    )
}
