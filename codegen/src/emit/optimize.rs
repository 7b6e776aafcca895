//! The optimising lowering: the formulas of a derivation handed to symbolica's expression
//! evaluator, whose optimiser tries Horner schemes and eliminates common pairs, and its exported
//! instruction list translated into a [`Builder`].
//!
//! # Route
//!
//! 1. Formulas are grouped into *levels*: a formula that names no earlier formula is on level 0,
//!    one that names earlier formulas is one level above the highest of them. Each level is one
//!    evaluator built from all its formulas at once (`evaluator_multiple`), so the optimiser
//!    shares work between them; levels are lowered in order into the same builder, whose
//!    hash-consing shares what levels have in common.
//! 2. Each formula is rebuilt from its canonical tree ([`Expr`]) with every leaf the optimiser
//!    must not look into replaced by a placeholder symbol: parameters, inputs, earlier formulas,
//!    $\pi$, and the calls of `tan` and `atan2` (symbolica has no evaluator for these user
//!    functions; they are lowered by the naive rules and enter as values). The placeholders are
//!    `carvallo_lowering::x0`, `x1`, … numbered in the order of first appearance in the
//!    canonical trees and created all at once right after the derivations' symbols
//!    ([`declare_placeholders`]), so the optimiser sees the same input whatever the process did
//!    before and its output is byte-stable.
//! 3. The instructions are translated with the naive lowering's conventions: a multiplication by
//!    $-1$ or a negative constant is carried as a sign and becomes a subtraction in the sum that
//!    uses it (a negation only where a value must be materialised), negative integer powers
//!    become one division per product, a coefficient $1/q$ with $q$ exact in `f64` a division by
//!    $q$, integer powers `powi`, half-integer powers `sqrt` raised to an integer power.
//!
//! [`choose`] then measures both programs at seeded points against 256-bit evaluations and keeps
//! the optimised one only when it has fewer operations, computes the same function (the 256-bit
//! values agree) and its rounding error does not grow by more than 2× at the 99th percentile
//! of any output, in either of two samples: uniform arguments, and the model's nominal values
//! ([`Derivation::nominal`]) scaled by up to ±20 %.

use std::collections::{BTreeMap, BTreeSet, HashMap};

use carvallo_ir::{Builder, Program, Value};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use symbolica::atom::{Atom, AtomCore, Symbol};
use symbolica::domains::rational::Rational;
use symbolica::evaluate::{Instruction, Slot};
use symbolica::{function, symbol};

use super::expr::{rat, Expr, Func};
use super::lower::Lowerer;
use super::{declare, generated_header, in_formula, rational_to_f64, EmitError};
use crate::Derivation;

/// How hard the optimiser works: the number of Horner schemes tried and the number of
/// common-pair elimination rounds (`None`: until no pair is left).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Effort {
    /// Horner schemes tried per level.
    pub horner_iterations: usize,
    /// Common-pair elimination rounds.
    pub cpe_iterations: Option<usize>,
}

impl std::fmt::Display for Effort {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.cpe_iterations {
            Some(n) => write!(f, "horner {} cpe {n}", self.horner_iterations),
            None => write!(f, "horner {} cpe all", self.horner_iterations),
        }
    }
}

/// The effort settings [`choose`] tries, cheapest first.
pub const EFFORTS: [Effort; 2] = [
    Effort { horner_iterations: 1, cpe_iterations: None },
    Effort { horner_iterations: 10, cpe_iterations: None },
];

/// The number of placeholders [`declare_placeholders`] creates, more than any level of any
/// model uses (a level that needs more is lowered naively).
pub const PLACEHOLDERS: usize = 4096;

/// Creates the placeholder symbols `carvallo_lowering::x0` … in order, right after the
/// derivations' own symbols (`derive::declare_symbols`; `regen` and the derivation tests call
/// both before anything else), so that they have the same
/// identities in every process, whatever it did before (the optimiser's output depends on them).
pub fn declare_placeholders() {
    for i in 0..PLACEHOLDERS {
        let _ = placeholder(i);
    }
}

/// The placeholder symbol number `i` (see the module docs).
fn placeholder(i: usize) -> Symbol {
    symbol!(&format!("carvallo_lowering::x{i}"))
}

/// A translated slot: a value, its sign, whether it is the reciprocal of the value, or an exact
/// number. Signs and reciprocals stay symbolic until an operation needs the plain value.
#[derive(Clone, Debug)]
enum Term {
    Val { v: Value, neg: bool },
    Recip { d: Value, neg: bool },
    Num(Rational),
}

/// Rebuilds canonical trees as symbolica expressions over placeholders.
struct Rebuild<'a> {
    lower: Lowerer<'a>,
    leaves: Vec<Value>,
    index: HashMap<Value, usize>,
}

impl Rebuild<'_> {
    fn leaf(&mut self, v: Value) -> Result<Atom, EmitError> {
        let n = self.leaves.len();
        let i = *self.index.entry(v).or_insert(n);
        if i == n {
            if n == PLACEHOLDERS {
                return Err(unsupported(format!("more than {PLACEHOLDERS} leaves in one level")));
            }
            self.leaves.push(v);
        }
        Ok(Atom::var(placeholder(i)))
    }

    fn atom(&mut self, e: &Expr) -> Result<Atom, EmitError> {
        Ok(match e {
            Expr::Num(r) => Atom::num(r.clone()),
            Expr::Sym(_) | Expr::Pi | Expr::Fun(Func::Tan | Func::Atan2, _) => {
                let v = self.lower.value(e)?;
                self.leaf(v)?
            }
            Expr::Fun(f, args) => {
                let a = self.atom(&args[0])?;
                let s = match f {
                    Func::Sin => Symbol::SIN,
                    Func::Cos => Symbol::COS,
                    _ => Symbol::SQRT,
                };
                function!(s, a)
            }
            Expr::Pow(b, k) => self.atom(b)?.pow(Atom::num(k.clone())),
            Expr::Mul(fs, c) => {
                let mut p = Atom::num(c.clone());
                for f in fs {
                    p = &p * &self.atom(f)?;
                }
                p
            }
            Expr::Add(ts) => {
                let mut s = Atom::num(0);
                for t in ts {
                    s = &s + &self.atom(t)?;
                }
                s
            }
        })
    }
}

/// Translates an exported instruction list into the builder.
struct Translate<'a> {
    b: &'a mut Builder,
    leaves: &'a [Value],
    constants: Vec<Rational>,
    slots: HashMap<Slot, Term>,
}

fn unsupported(what: impl Into<String>) -> EmitError {
    EmitError::Unsupported { what: what.into(), expr: "(optimised evaluator)".into() }
}

impl Translate<'_> {
    fn constant(&mut self, r: &Rational) -> Result<Value, EmitError> {
        let x = rational_to_f64(r).ok_or_else(|| EmitError::Constant { value: r.to_string() })?;
        Ok(self.b.constant(x))
    }

    fn term(&self, s: Slot) -> Result<Term, EmitError> {
        match s {
            Slot::Param(i) => self
                .leaves
                .get(i)
                .map(|&v| Term::Val { v, neg: false })
                .ok_or_else(|| unsupported(format!("parameter slot {i}"))),
            Slot::Const(i) => self
                .constants
                .get(i)
                .map(|c| Term::Num(c.clone()))
                .ok_or_else(|| unsupported(format!("constant slot {i}"))),
            other => {
                self.slots.get(&other).cloned().ok_or_else(|| unsupported(format!("unset {other}")))
            }
        }
    }

    /// The magnitude and sign of a term, materialising a reciprocal.
    fn signed(&mut self, t: Term) -> Result<(Value, bool), EmitError> {
        Ok(match t {
            Term::Val { v, neg } => (v, neg),
            Term::Recip { d, neg } => {
                let one = self.b.constant(1.0);
                (self.b.div(one, d), neg)
            }
            Term::Num(r) => (self.constant(&r.abs())?, r.is_negative()),
        })
    }

    fn value(&mut self, t: Term) -> Result<Value, EmitError> {
        let (v, neg) = self.signed(t)?;
        Ok(if neg { self.b.neg(v) } else { v })
    }

    fn product(&mut self, args: &[Slot]) -> Result<Term, EmitError> {
        let mut coef = rat(1);
        let mut neg = false;
        let (mut num, mut den) = (Vec::new(), Vec::new());
        for &s in args {
            match self.term(s)? {
                Term::Num(r) => coef = &coef * &r,
                Term::Val { v, neg: n } => {
                    num.push(v);
                    neg ^= n;
                }
                Term::Recip { d, neg: n } => {
                    den.push(d);
                    neg ^= n;
                }
            }
        }
        if coef.is_negative() {
            neg = !neg;
            coef = coef.abs();
        }
        if coef.is_zero() {
            return Ok(Term::Num(rat(0)));
        }
        let one = coef == rat(1);
        let fold =
            |b: &mut Builder, vs: &[Value]| vs.iter().copied().reduce(|acc, v| b.mul(acc, v));
        let n = fold(self.b, &num);
        let d = fold(self.b, &den);
        let monomial = match (n, d) {
            (None, None) => return Ok(Term::Num(if neg { -coef } else { coef })),
            (Some(n), None) if one => return Ok(Term::Val { v: n, neg }),
            (None, Some(d)) if one => return Ok(Term::Recip { d, neg }),
            (None, Some(d)) => {
                let c = self.constant(&coef)?;
                return Ok(Term::Val { v: self.b.div(c, d), neg });
            }
            (Some(n), Some(d)) => self.b.div(n, d),
            (Some(n), None) => n,
        };
        if one {
            return Ok(Term::Val { v: monomial, neg });
        }
        let inv = &rat(1) / &coef;
        if inv.is_integer() {
            if let Some(q) =
                rational_to_f64(&inv).filter(|q| Rational::try_from(*q).ok().as_ref() == Some(&inv))
            {
                let qv = self.b.constant(q);
                return Ok(Term::Val { v: self.b.div(monomial, qv), neg });
            }
        }
        let c = self.constant(&coef)?;
        Ok(Term::Val { v: self.b.mul(c, monomial), neg })
    }

    fn sum(&mut self, args: &[Slot]) -> Result<Term, EmitError> {
        let mut constant = rat(0);
        let mut parts = Vec::new();
        for &s in args {
            match self.term(s)? {
                Term::Num(r) => constant = &constant + &r,
                t => parts.push(self.signed(t)?),
            }
        }
        if !constant.is_zero() {
            let c = self.constant(&constant.abs())?;
            parts.push((c, constant.is_negative()));
        }
        let Some(first) = parts.iter().position(|&(_, neg)| !neg) else {
            // Every term negative: the sum of the magnitudes, negated lazily.
            let Some(acc) = parts.iter().map(|p| p.0).reduce(|acc, v| self.b.add(acc, v)) else {
                return Ok(Term::Num(rat(0)));
            };
            return Ok(Term::Val { v: acc, neg: true });
        };
        let mut acc = parts[first].0;
        for (i, &(v, neg)) in parts.iter().enumerate() {
            if i != first {
                acc = if neg { self.b.sub(acc, v) } else { self.b.add(acc, v) };
            }
        }
        Ok(Term::Val { v: acc, neg: false })
    }

    /// `t` raised to the integer power `k`.
    fn power(&mut self, t: Term, k: i64) -> Result<Term, EmitError> {
        if k == 0 {
            return Ok(Term::Num(rat(1)));
        }
        if let Term::Num(r) = &t {
            let mut p = rat(1);
            for _ in 0..k.unsigned_abs() {
                p = &p * r;
            }
            return Ok(Term::Num(if k < 0 { &rat(1) / &p } else { p }));
        }
        let odd = k % 2 != 0;
        let m = i32::try_from(k.unsigned_abs())
            .map_err(|_| unsupported(format!("exponent {k} outside the i32 range")))?;
        let (v, neg, recip) = match t {
            Term::Val { v, neg } => (v, neg, false),
            Term::Recip { d, neg } => (d, neg, true),
            Term::Num(_) => unreachable!("numbers are handled above"),
        };
        let p = if m == 1 { v } else { self.b.powi(v, m) };
        let neg = neg && odd;
        Ok(if recip == (k < 0) { Term::Val { v: p, neg } } else { Term::Recip { d: p, neg } })
    }

    fn run(&mut self, instructions: &[Instruction]) -> Result<(), EmitError> {
        for ins in instructions {
            let (out, t) = match ins {
                Instruction::Add(o, args, _) => (*o, self.sum(args)?),
                Instruction::Mul(o, args, _) => (*o, self.product(args)?),
                Instruction::Pow(o, b, k, _) => {
                    let t = self.term(*b)?;
                    (*o, self.power(t, *k)?)
                }
                Instruction::Powf(o, b, e, _) => {
                    let Term::Num(k) = self.term(*e)? else {
                        return Err(unsupported("symbolic exponent"));
                    };
                    let twice = &k * &rat(2);
                    if !twice.is_integer() {
                        return Err(unsupported(format!("exponent {k}")));
                    }
                    let twice: i64 = twice
                        .to_string()
                        .parse()
                        .map_err(|_| unsupported(format!("exponent {k}")))?;
                    let base = self.term(*b)?;
                    let base = self.value(base)?;
                    let s = self.b.sqrt(base);
                    (*o, self.power(Term::Val { v: s, neg: false }, twice)?)
                }
                Instruction::Fun(o, call, _) => {
                    let (sym, _, args) = &**call;
                    if args.len() != 1 {
                        return Err(unsupported(format!(
                            "call of {sym} with {} arguments",
                            args.len()
                        )));
                    }
                    let a = self.term(args[0])?;
                    let a = self.value(a)?;
                    let v = if *sym == Symbol::SIN {
                        self.b.sin(a)
                    } else if *sym == Symbol::COS {
                        self.b.cos(a)
                    } else if *sym == Symbol::SQRT {
                        self.b.sqrt(a)
                    } else {
                        return Err(unsupported(format!("function {sym}")));
                    };
                    (*o, Term::Val { v, neg: false })
                }
                Instruction::Assign(o, v) => (*o, self.term(*v)?),
                other => return Err(unsupported(format!("instruction {other}"))),
            };
            self.slots.insert(out, t);
        }
        Ok(())
    }
}

/// The IR program of a derivation through symbolica's optimiser at the given effort, except
/// the formulas numbered in `naive`, which are lowered by the naive rules: the same parameters,
/// inputs, outputs and headers as [`super::emit_program`].
pub fn emit_program_optimized(
    d: &Derivation,
    effort: Effort,
    naive: &BTreeSet<usize>,
) -> Result<Program, EmitError> {
    let (mut b, mut names) = declare(d)?;
    b.header(&generated_header(&d.source));
    let outputs: Vec<&str> = d.formulas.iter().map(|f| f.name.as_str()).collect();
    b.header(&format!("Outputs: {}.", outputs.join(", ")));
    let declared: std::collections::BTreeSet<String> = names.keys().cloned().collect();
    // Levels: a formula sits one above the highest earlier formula it names.
    let mut level_of: BTreeMap<&str, usize> = BTreeMap::new();
    let mut trees = Vec::with_capacity(d.formulas.len());
    let mut levels: Vec<Vec<usize>> = Vec::new();
    for (i, f) in d.formulas.iter().enumerate() {
        let e = Expr::from_atom(&f.expr).map_err(in_formula(f))?;
        let mut level = 0;
        e.visit_symbols(&mut |s| {
            if !declared.contains(s) {
                if let Some(&l) = level_of.get(s) {
                    level = level.max(l + 1);
                }
            }
        });
        level_of.insert(&f.name, level);
        if levels.len() <= level {
            levels.resize(level + 1, Vec::new());
        }
        levels[level].push(i);
        trees.push(e);
    }
    let mut values: Vec<Option<Value>> = vec![None; d.formulas.len()];
    for level in &levels {
        for &i in level.iter().filter(|i| naive.contains(i)) {
            let v = Lowerer { b: &mut b, names: &names }
                .value(&trees[i])
                .map_err(in_formula(&d.formulas[i]))?;
            values[i] = Some(v);
        }
        for &i in level.iter().filter(|i| naive.contains(i)) {
            if let Some(v) = values[i] {
                names.entry(d.formulas[i].name.clone()).or_insert(v);
            }
        }
        let level: Vec<usize> = level.iter().copied().filter(|i| !naive.contains(i)).collect();
        if level.is_empty() {
            continue;
        }
        let mut rb = Rebuild {
            lower: Lowerer { b: &mut b, names: &names },
            leaves: Vec::new(),
            index: HashMap::new(),
        };
        let mut atoms = Vec::with_capacity(level.len());
        for &i in &level {
            atoms.push(rb.atom(&trees[i]).map_err(in_formula(&d.formulas[i]))?);
        }
        let leaves = rb.leaves;
        let params: Vec<Atom> = (0..leaves.len()).map(|i| Atom::var(placeholder(i))).collect();
        let evaluator = Atom::evaluator_multiple(&atoms, &params)
            .horner_iterations(effort.horner_iterations)
            .cpe_iterations(effort.cpe_iterations)
            .cores(1)
            .build()
            .map_err(|e| unsupported(format!("symbolica evaluator ({e})")))?;
        let exported = evaluator.export_instructions();
        let constants = exported
            .constants
            .iter()
            .map(|c| {
                if c.im.is_zero() {
                    Ok(c.re.clone())
                } else {
                    Err(unsupported(format!("complex constant {c}")))
                }
            })
            .collect::<Result<Vec<_>, _>>()?;
        let mut t = Translate { b: &mut b, leaves: &leaves, constants, slots: HashMap::new() };
        t.run(&exported.instructions)?;
        for (j, &i) in level.iter().enumerate() {
            let term = t.term(Slot::Out(j))?;
            values[i] = Some(t.value(term)?);
        }
        for &i in &level {
            let f = &d.formulas[i];
            if let Some(v) = values[i] {
                names.entry(f.name.clone()).or_insert(v);
            }
        }
    }
    for (f, v) in d.formulas.iter().zip(values) {
        let v = v.ok_or_else(|| unsupported(format!("formula {} not computed", f.name)))?;
        b.output(&f.name, v);
    }
    Ok(b.finish())
}

/// The 256-bit values of a program's outputs at `points` (an empty row where it fails).
fn exact(p: &Program, points: &[(Vec<f64>, Vec<f64>)]) -> Vec<Vec<f64>> {
    points
        .iter()
        .map(|(params, inputs)| {
            carvallo_ir::hp::eval_f64(p, params, inputs, 256).unwrap_or_default()
        })
        .collect()
}

/// The rounding errors of a program's `f64` outputs against the 256-bit values `refs` of the
/// same function: per output, the 99th percentile of the relative errors over the points.
fn errors(p: &Program, points: &[(Vec<f64>, Vec<f64>)], refs: &[Vec<f64>]) -> Vec<f64> {
    let n = p.outputs.len();
    let mut rel: Vec<Vec<f64>> = vec![Vec::new(); n];
    let interp = carvallo_ir::Interpreter::new(p).ok();
    let mut scratch = vec![0.0; interp.as_ref().map_or(0, |it| it.scratch_len())];
    let mut got = vec![0.0; n];
    for ((params, inputs), exact) in points.iter().zip(refs) {
        let Some(it) = interp.as_ref() else { break };
        if exact.len() != n || it.eval(params, inputs, &mut scratch, &mut got).is_err() {
            continue;
        }
        for (k, (x, r)) in got.iter().zip(exact).enumerate() {
            if r.is_finite() {
                let e = if *r == 0.0 { x.abs() } else { ((x - r) / r).abs() };
                rel[k].push(if e.is_nan() { f64::INFINITY } else { e });
            }
        }
    }
    rel.into_iter()
        .map(|mut v| {
            v.sort_by(f64::total_cmp);
            if v.is_empty() {
                0.0
            } else {
                v[((v.len() - 1) as f64 * 0.99).round() as usize]
            }
        })
        .collect()
}

/// The seeded points at which [`choose`] compares programs: every parameter and input uniform
/// in [0.5, 1.5] (the first sample), or with `nominal` values by name (the derivation's
/// [`Derivation::nominal`]) each of those scaled by a uniform factor in [0.8, 1.2], the others as
/// in the first sample (the second).
fn points(p: &Program, n: usize, nominal: Option<&[(String, f64)]>) -> Vec<(Vec<f64>, Vec<f64>)> {
    let mut rng =
        ChaCha8Rng::seed_from_u64(if nominal.is_some() { 0x0a11_0ca7 } else { 0x5ca1_ab1e });
    let value = |name: &str| nominal.and_then(|t| t.iter().find(|(k, _)| k == name)).map(|e| e.1);
    let mut draw = |name: &str| match value(name) {
        Some(x) => x * rng.gen_range(0.8..1.2),
        None => rng.gen_range(0.5..1.5),
    };
    (0..n)
        .map(|_| {
            let params = p.params.iter().map(|n| draw(n)).collect();
            let inputs = p.inputs.iter().map(|n| draw(n)).collect();
            (params, inputs)
        })
        .collect()
}

/// The lowering a model keeps, and the lines that record the comparison (for the IR header).
///
/// At each effort of [`EFFORTS`] (then the derivation's own [`Derivation::horner_schemes`]), the optimised program is measured against the naive one; the
/// outputs whose error grows by more than 2x are lowered naively and the rest optimised again,
/// until every output passes (at most four rounds). The program with the fewest operations
/// wins; the naive one on a tie.
pub fn choose(d: &Derivation) -> Result<(Program, Vec<String>), EmitError> {
    let naive = super::emit_program(d)?;
    let (naive_ops, _) = super::count_ops(&naive);
    // Two samples: uniform arguments, and the model's nominal ones (when it has some).
    let mut samples = vec![points(&naive, POINTS, None)];
    if naive.params.iter().chain(&naive.inputs).any(|n| d.nominal.iter().any(|(k, _)| k == n)) {
        samples.push(points(&naive, POINTS, Some(&d.nominal)));
    }
    let refs: Vec<Vec<Vec<f64>>> = samples.iter().map(|pts| exact(&naive, pts)).collect();
    let naive_err: Vec<Vec<f64>> =
        samples.iter().zip(&refs).map(|(pts, r)| errors(&naive, pts, r)).collect();
    let deps = dependencies(d)?;
    let mut lines = vec![format!(
        "Lowering (codegen/src/emit/optimize.rs): naive {naive_ops} ops; symbolica's optimiser, \
         outputs whose p99 rounding error at {POINTS} seeded points{} grows over 2x lowered \
         naively:",
        if samples.len() > 1 { " (uniform, and around the model's nominal values)" } else { "" }
    )];
    let mut best: Option<(Program, usize, Effort)> = None;
    let further =
        d.horner_schemes.iter().map(|&h| Effort { horner_iterations: h, cpe_iterations: None });
    let efforts: Vec<Effort> = EFFORTS.iter().copied().chain(further).collect();
    'efforts: for effort in efforts {
        let mut fallback = BTreeSet::new();
        for _round in 0..12 {
            let p = match emit_program_optimized(d, effort, &fallback) {
                Ok(p) => p,
                Err(e) => {
                    lines.push(format!("  {effort}: not available ({e})"));
                    break 'efforts;
                }
            };
            // Per output, the larger ratio of the two samples' p99 errors; errors below 2^-52
            // count as the rounding of the last operation.
            let mut r = vec![0.0f64; naive.outputs.len()];
            for ((pts, refs), naive_err) in samples.iter().zip(&refs).zip(&naive_err) {
                let err = errors(&p, pts, refs);
                for (k, (n, o)) in naive_err.iter().zip(&err).enumerate() {
                    r[k] = r[k].max(o.max(f64::EPSILON) / n.max(f64::EPSILON));
                }
            }
            let before = fallback.len();
            for k in (0..r.len()).filter(|&k| r[k] > 2.0) {
                // A naive output whose error still grows inherits it from the formulas it
                // names, directly or not: those become naive too (then it is computed exactly
                // as in the naive program).
                if !fallback.insert(k) {
                    let mut stack = deps[k].clone();
                    while let Some(j) = stack.pop() {
                        if fallback.insert(j) {
                            stack.extend(deps[j].iter().copied());
                        }
                    }
                }
            }
            if fallback.len() != before {
                continue;
            }
            let (ops, _) = super::count_ops(&p);
            let (worst, at) =
                r.iter()
                    .enumerate()
                    .fold((0.0, 0), |(w, a), (k, &x)| if x > w { (x, k) } else { (w, a) });
            lines.push(format!(
                "  {effort}: {ops} ops, {} of {} outputs naive, largest error ratio {worst:.2} ({})",
                fallback.len(),
                r.len(),
                p.outputs.get(at).map_or("-", |o| o.name.as_str()),
            ));
            if worst <= 2.0 && ops < best.as_ref().map_or(naive_ops, |b| b.1) {
                best = Some((p, ops, effort));
            }
            continue 'efforts;
        }
        lines.push(format!("  {effort}: errors still grow after twelve rounds"));
    }
    let Some((p, ops, effort)) = best else {
        lines.push(format!("Kept: naive, {naive_ops} ops."));
        return Ok((naive, lines));
    };
    // The kept program computes the same function: its 256-bit values agree with the naive
    // program's far below f64 rounding.
    for (a, b) in refs[0].iter().zip(exact(&p, &samples[0])) {
        for (k, (x, y)) in a.iter().zip(&b).enumerate() {
            if a.len() == b.len() && (x - y).abs() > 1e-30 * x.abs().max(1.0) {
                return Err(unsupported(format!(
                    "optimised output {} differs from the naive one at 256 bits ({x} against {y})",
                    p.outputs[k].name
                )));
            }
        }
    }
    lines.push(format!("Kept: optimised ({effort}), {ops} ops."));
    Ok((p, lines))
}

/// For each formula, the earlier formulas it names.
fn dependencies(d: &Derivation) -> Result<Vec<Vec<usize>>, EmitError> {
    let declared: BTreeSet<&str> = d.params.iter().chain(&d.inputs).map(String::as_str).collect();
    let index: BTreeMap<&str, usize> =
        d.formulas.iter().enumerate().map(|(i, f)| (f.name.as_str(), i)).collect();
    d.formulas
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let e = Expr::from_atom(&f.expr).map_err(in_formula(f))?;
            let mut out = Vec::new();
            e.visit_symbols(&mut |s| {
                if let Some(&j) = index.get(s).filter(|&&j| j < i && !declared.contains(s)) {
                    out.push(j);
                }
            });
            Ok(out)
        })
        .collect()
}

/// The number of seeded points of the error comparison.
const POINTS: usize = 300;

impl Expr {
    /// Calls `f` with the name of every symbol in the tree.
    pub(super) fn visit_symbols(&self, f: &mut impl FnMut(&str)) {
        match self {
            Expr::Sym(s) => f(s),
            Expr::Num(_) | Expr::Pi => {}
            Expr::Fun(_, args) | Expr::Add(args) | Expr::Mul(args, _) => {
                args.iter().for_each(|a| a.visit_symbols(f))
            }
            Expr::Pow(b, _) => b.visit_symbols(f),
        }
    }
}
