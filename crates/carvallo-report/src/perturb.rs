//! Perturbations of the derived side at the IR level (issue 38): a claim's check is run again
//! on a generated program with one coefficient of one output scaled by a stated relative
//! amount, and the verdict it then gives is recorded beside its own
//! ([`crate::claims::Falsification`]). The printed side is never touched: the constant is
//! changed in a copy of the output's own instructions (its cone), so an output of the memoir's
//! transcribed formulas that shares the constant keeps it.
//!
//! A perturbation is active on the current thread while [`with`] runs its closure; the
//! claims read the generated outputs through [`discussion_output`], which evaluates the
//! perturbed program with the interpreter of `carvallo_ir` when one is active and the compiled
//! evaluator otherwise.
//!
//! The concordance's entries are falsified the same way ([`falsify_entries`]): each report's
//! evaluators read the perturbed output through [`reading`] (one output of a compiled scene),
//! [`overlay`] (every output at a point) or the readers above, and the runtime's routes
//! through the hook of [`carvallo::bicycle_geometry::with_reader`] or a bicycle built from the
//! read matrices (the benchmark). An entry whose check has a margin beyond the relative changes
//! tried states a perturbation of a stated size ([`falsify_table`]); one computed by a
//! numerical route that no generated program of the report feeds is computed again with a
//! stated ingredient of the derived side changed ([`falsify_by_rerun`]).

use std::cell::RefCell;
use std::collections::{BTreeMap, BTreeSet};

use carvallo::ir::{Inst, Interpreter, Op, Program, Value};

use crate::entry::{Entry, Falsification, Verdict};

/// One coefficient, or one model ingredient, of one output of a generated program scaled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Perturbation {
    /// The model whose program is perturbed (`hoop_discussion`).
    pub model: &'static str,
    /// The output whose cone (the instructions it depends on) is perturbed.
    pub output: &'static str,
    /// What is scaled in the copy of the output's cone.
    pub target: Target,
    /// The factor it is multiplied by.
    pub factor: f64,
}

/// What a [`Perturbation`] scales in the copy of an output's instructions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Target {
    /// The constant of the cone with this index, in program order (0 is the first).
    Constant(usize),
    /// Every use of the named parameter or input in the cone (a model ingredient, such as the
    /// rider's mass, changed in that output only).
    Argument(&'static str),
    /// Every use of the `k`-th parameter or input the cone reads, in the program's order
    /// (parameters first): an argument chosen at run time ([`falsify_entries`]).
    Slot(usize),
}

/// The parts of a [`Perturbation`] with the output borrowed.
struct Probe<'a> {
    output: &'a str,
    target: Target,
    factor: f64,
}

/// The perturbed program, compiled once for the interpreter.
struct Active {
    model: &'static str,
    /// The perturbed output.
    output: String,
    program: Program,
    interp: Interpreter,
    /// The perturbed output alone (the perturbed program with its other outputs and the
    /// instructions only they need removed), for the readers that need only it.
    single: Program,
    /// The interpreter of `single`.
    single_interp: Interpreter,
}

impl Active {
    /// The perturbed output at the named arguments (`missing` for a name not given): the same
    /// value as its slot of [`Active::eval`], from its own instructions only.
    fn eval_output(&self, get: impl Fn(&str) -> Option<f64>, missing: f64) -> Option<f64> {
        let p = &self.single;
        let params: Vec<f64> = p.params.iter().map(|n| get(n).unwrap_or(missing)).collect();
        let inputs: Vec<f64> = p.inputs.iter().map(|n| get(n).unwrap_or(missing)).collect();
        let mut scratch = vec![0.0; self.single_interp.scratch_len()];
        let mut out = vec![0.0; self.single_interp.n_outputs()];
        self.single_interp.eval(&params, &inputs, &mut scratch, &mut out).ok()?;
        out.first().copied()
    }

    /// Every output at the named arguments (`missing` for a name not given).
    fn eval(&self, get: impl Fn(&str) -> Option<f64>, missing: f64) -> Option<Vec<f64>> {
        let p = &self.program;
        let params: Vec<f64> = p.params.iter().map(|n| get(n).unwrap_or(missing)).collect();
        let inputs: Vec<f64> = p.inputs.iter().map(|n| get(n).unwrap_or(missing)).collect();
        let mut scratch = vec![0.0; self.interp.scratch_len()];
        let mut out = vec![0.0; self.interp.n_outputs()];
        self.interp.eval(&params, &inputs, &mut scratch, &mut out).ok()?;
        Some(out)
    }
}

thread_local! {
    static ACTIVE: RefCell<Option<Active>> = const { RefCell::new(None) };
}

/// The instructions the output `name` depends on, in program order.
fn cone(p: &Program, name: &str) -> Option<Vec<usize>> {
    let out = p.output(name)?;
    let mut seen = BTreeSet::new();
    let mut stack = vec![out.value];
    while let Some(v) = stack.pop() {
        if let Value::Inst(i) = v {
            if seen.insert(i as usize) {
                stack.extend(p.insts[i as usize].op.operands());
            }
        }
    }
    Some(seen.into_iter().collect())
}

/// The parameters and inputs the instructions `members` of `p` read, with their names, in the
/// program's order (parameters first).
fn arguments_read(p: &Program, members: &[usize]) -> Vec<(Value, String)> {
    let read: BTreeSet<Value> = members.iter().flat_map(|&i| p.insts[i].op.operands()).collect();
    let params = p.params.iter().enumerate().map(|(i, n)| (Value::Param(i as u32), n));
    let inputs = p.inputs.iter().enumerate().map(|(i, n)| (Value::Input(i as u32), n));
    params.chain(inputs).filter(|(v, _)| read.contains(v)).map(|(v, n)| (v, n.clone())).collect()
}

/// The program of `p` with the perturbation applied: the cone of the output copied after the
/// program's instructions, the chosen constant of the copy scaled (or every use of the chosen
/// argument replaced by the argument times the factor), the output redirected to the copy.
/// Also returns the constant's value before scaling (NaN for an argument). `None` when the
/// output, the constant or the argument's use in the cone does not exist.
pub fn perturbed_program(p: &Program, pert: &Perturbation) -> Option<(Program, f64)> {
    perturbed_parts(p, pert.output, pert.target, pert.factor)
}

/// [`perturbed_program`] for the output `output`, the target `target` and the factor
/// `factor` given apart (an output named at run time, as [`falsify_entries`] chooses).
fn perturbed_parts(
    p: &Program,
    output: &str,
    target: Target,
    factor: f64,
) -> Option<(Program, f64)> {
    let pert = Probe { output, target, factor };
    let members = cone(p, pert.output)?;
    let mut q = p.clone();
    // The scaled argument, `mul arg factor`, ahead of the copies.
    let (target, value, argument) = match pert.target {
        Target::Constant(k) => {
            let consts: Vec<usize> = members
                .iter()
                .copied()
                .filter(|&i| matches!(p.insts[i].op, Op::Const(_)))
                .collect();
            let target = *consts.get(k)?;
            let Op::Const(value) = p.insts[target].op else { return None };
            (Some(target), value, None)
        }
        Target::Argument(_) | Target::Slot(_) => {
            let read = arguments_read(p, &members);
            let (arg, name) = match pert.target {
                Target::Argument(name) => read.into_iter().find(|(_, n)| n == name)?,
                Target::Slot(k) => read.into_iter().nth(k)?,
                Target::Constant(_) => unreachable!("matched above"),
            };
            let factor = q.insts.len() as u32;
            q.insts.push(Inst { name: format!("{name}__factor"), op: Op::Const(pert.factor) });
            q.insts.push(Inst {
                name: format!("{name}__perturbed"),
                op: Op::Mul(arg, Value::Inst(factor)),
            });
            (None, f64::NAN, Some((arg, Value::Inst(factor + 1))))
        }
    };
    let base = q.insts.len() as u32;
    let index: BTreeMap<usize, u32> =
        members.iter().enumerate().map(|(k, &i)| (i, base + k as u32)).collect();
    for &i in &members {
        let inst = &p.insts[i];
        let op = if Some(i) == target {
            Op::Const(value * pert.factor)
        } else {
            inst.op.map_operands(|v| match v {
                Value::Inst(j) => Value::Inst(index.get(&(j as usize)).copied().unwrap_or(j)),
                other => match argument {
                    Some((arg, scaled)) if other == arg => scaled,
                    _ => other,
                },
            })
        };
        q.insts.push(Inst { name: format!("{}__perturbed", inst.name), op });
    }
    let out = q.outputs.iter_mut().find(|o| o.name == pert.output)?;
    if let Value::Inst(j) = out.value {
        out.value = Value::Inst(index[&(j as usize)]);
    }
    Some((q, value))
}

/// The IR text of a model's generated program.
fn ir_of(model: &str) -> Option<&'static str> {
    carvallo::artifacts::artifact(model).map(|a| a.ir)
}

thread_local! {
    static PARSED: RefCell<BTreeMap<String, std::rc::Rc<Program>>> =
        const { RefCell::new(BTreeMap::new()) };
}

/// A model's generated program, parsed once per thread (every report's [`falsify_entries`]
/// searches every model's outputs).
fn parsed(model: &str) -> Option<std::rc::Rc<Program>> {
    if let Some(p) = PARSED.with(|c| c.borrow().get(model).cloned()) {
        return Some(p);
    }
    let p = std::rc::Rc::new(Program::parse(ir_of(model)?).ok()?);
    PARSED.with(|c| c.borrow_mut().insert(model.to_string(), p.clone()));
    Some(p)
}

/// Runs `f` with the perturbation active on this thread; `None` (and `f` not run) when the
/// model, output or constant does not exist. Also returns the constant's value before scaling.
pub fn with<T>(pert: &Perturbation, f: impl FnOnce() -> T) -> Option<(T, f64)> {
    with_parts(pert.model, pert.output, pert.target, pert.factor, f)
}

/// [`with`] for a perturbation given by its parts.
fn with_parts<T>(
    model: &'static str,
    output: &str,
    target: Target,
    factor: f64,
    f: impl FnOnce() -> T,
) -> Option<(T, f64)> {
    let program = parsed(model)?;
    with_program(model, &program, output, target, factor, f)
}

/// [`with_parts`] on the model's program already parsed (`program`, the program of `model`).
fn with_program<T>(
    model: &'static str,
    program: &Program,
    output: &str,
    target: Target,
    factor: f64,
    f: impl FnOnce() -> T,
) -> Option<(T, f64)> {
    let (program, value) = perturbed_parts(program, output, target, factor)?;
    let interp = Interpreter::new(&program).ok()?;
    let single = program.select_outputs(&[output]).ok()?;
    let single_interp = Interpreter::new(&single).ok()?;
    let output = output.to_string();
    let active = Active { model, output, program, interp, single, single_interp };
    let before = ACTIVE.with(|a| a.borrow_mut().replace(active));
    let out = f();
    // The perturbation active before (a rerun of [`falsify_entries`] around an entry's own
    // falsification, [`falsify_table`]) is active again.
    ACTIVE.with(|a| *a.borrow_mut() = before);
    Some((out, value))
}

/// Replaces, in `values` (every output of `model`'s generated program at one point, by name),
/// the perturbed output by its perturbed value when a perturbation of `model` is active on this
/// thread ([`with`]); `get` gives the program's arguments by name (a name it does not know is
/// NaN). Nothing changes otherwise. The model reports' evaluators call it after the compiled
/// evaluator so that a perturbation reaches every entry computed from them.
pub fn overlay(
    model: &str,
    get: impl Fn(&str) -> Option<f64>,
    values: &mut BTreeMap<&'static str, f64>,
) {
    ACTIVE.with(|a| {
        let a = a.borrow();
        let Some(active) = a.as_ref().filter(|a| a.model == model) else { return };
        if let Some(slot) = values.get_mut(active.output.as_str()) {
            if let Some(v) = active.eval_output(get, f64::NAN) {
                *slot = v;
            }
        }
    });
}

/// The output `name` of `model`'s generated program whose unperturbed value is `value`: its
/// perturbed value when a perturbation of that very output is active on this thread ([`with`]),
/// `value()` otherwise (not called then); `get` gives the program's arguments by name (a name it does not know is
/// NaN). An evaluator that reads one output at a time (a compiled scene's `output(name)`) reads
/// it through this function, so that a perturbation reaches the entries computed from it; the
/// perturbed program is evaluated only when the output read is the perturbed one.
pub fn reading(
    model: &str,
    name: &str,
    get: impl Fn(&str) -> Option<f64>,
    value: impl FnOnce() -> f64,
) -> f64 {
    let perturbed = ACTIVE.with(|a| {
        let a = a.borrow();
        let active = a.as_ref().filter(|a| a.model == model && a.output == name)?;
        active.eval_output(get, f64::NAN)
    });
    perturbed.unwrap_or_else(value)
}

/// Whether the output `name` of `model`'s program is the one perturbed on this thread now
/// ([`with`]): a report may reuse what it computed from that output unperturbed otherwise.
pub fn perturbs(model: &str, name: &str) -> bool {
    ACTIVE.with(|a| a.borrow().as_ref().is_some_and(|a| a.model == model && a.output == name))
}

/// Whether a perturbation of `model`'s program is active on this thread ([`with`]): an
/// evaluator that cannot read the perturbed program output by output (a numerical route
/// through a runtime function) routes through this module's readers instead while it is.
pub fn is_active(model: &str) -> bool {
    ACTIVE.with(|a| a.borrow().as_ref().is_some_and(|a| a.model == model))
}

/// The output `name` of the active perturbed program of `model` at the named arguments
/// (missing names are 0) when it is the perturbed output, or `None` (the caller's unperturbed
/// evaluator gives it: every other output of the perturbed program is the unperturbed one).
fn active_output(model: &str, name: &str, args: &[(&str, f64)]) -> Option<f64> {
    ACTIVE.with(|a| {
        let a = a.borrow();
        let active = a.as_ref().filter(|a| a.model == model && a.output == name)?;
        let get = |n: &str| args.iter().find(|(k, _)| *k == n).map(|(_, v)| *v);
        active.eval_output(get, 0.0)
    })
}

/// The output `name` of the generated `hoop_discussion` program: the perturbed one when a
/// perturbation of it is active, otherwise [`carvallo::hoop_discussion::output`].
pub fn discussion_output(name: &str, args: &[(&str, f64)]) -> f64 {
    active_output("hoop_discussion", name, args)
        .unwrap_or_else(|| carvallo::hoop_discussion::output(name, args))
}

/// The normalised (E), (S) or (D) of n° 12 (`equilibrium_n12`, `stability_n12`, `skid_n12` of
/// the generated `hoop` program) at (θ, s, n): the perturbed program when a perturbation of it
/// is active, otherwise [`carvallo::hoop::normalised`]; NaN for another name.
pub fn normalised(name: &str, theta: f64, s: f64, n: f64) -> f64 {
    use carvallo::hoop::normalised as h;
    active_output("hoop", name, &[("theta", theta), ("s", s), ("n", n)]).unwrap_or_else(|| {
        match name {
            "equilibrium_n12" => h::equilibrium(theta, s, n),
            "stability_n12" => h::stability(theta, s, n),
            "skid_n12" => h::skid(theta, s, n),
            _ => f64::NAN,
        }
    })
}

/// Every output of the generated `unicycle` program at `point` (missing names NaN): the
/// perturbed program's values when a perturbation of it is active, otherwise
/// [`carvallo::unicycle_discussion::eval`].
pub fn unicycle_eval(point: &carvallo::unicycle_discussion::Point) -> BTreeMap<&'static str, f64> {
    let mut map = carvallo::unicycle_discussion::eval(point);
    ACTIVE.with(|a| {
        let a = a.borrow();
        let Some(active) = a.as_ref().filter(|a| a.model == "unicycle") else { return };
        let get = |n: &str| point.get(n).copied();
        if let Some(values) = active.eval(get, f64::NAN) {
            for (o, v) in active.program.outputs.iter().zip(values) {
                if let Some(slot) = map.get_mut(o.name.as_str()) {
                    *slot = v;
                }
            }
        }
    });
    map
}

/// The output `name` of [`unicycle_eval`].
pub fn unicycle_out(point: &carvallo::unicycle_discussion::Point, name: &str) -> f64 {
    unicycle_eval(point)[name]
}

/// The outputs `names` of the active perturbed program of `model` at the named arguments, or
/// `None` when no perturbation of that model is active.
fn active_outputs<const N: usize>(
    model: &str,
    names: [&str; N],
    args: &[(&str, f64)],
) -> Option<[f64; N]> {
    ACTIVE.with(|a| {
        let a = a.borrow();
        let active = a.as_ref().filter(|a| a.model == model)?;
        let get = |n: &str| args.iter().find(|(k, _)| *k == n).map(|(_, v)| *v);
        let v = active.eval(get, 0.0)?;
        let mut out = [f64::NAN; N];
        for (slot, name) in out.iter_mut().zip(names) {
            *slot = v[active.program.outputs.iter().position(|o| o.name == name)?];
        }
        Some(out)
    })
}

fn hoop_args(
    hoop: &carvallo::hoop::Hoop,
    theta: f64,
    p: f64,
    n: f64,
    s: f64,
) -> [(&'static str, f64); 7] {
    [
        ("R", hoop.radius()),
        ("g", hoop.g()),
        ("mu", hoop.mass()),
        ("theta", theta),
        ("p", p),
        ("n", n),
        ("s", s),
    ]
}

/// [`carvallo::hoop::Hoop::rhs_pns`], from the perturbed `hoop` program when one is active.
pub fn hoop_rhs_pns(hoop: &carvallo::hoop::Hoop, state: [f64; 4]) -> [f64; 4] {
    let [theta, p, n, s] = state;
    match active_outputs("hoop", ["pns_dp", "pns_dn", "pns_ds"], &hoop_args(hoop, theta, p, n, s)) {
        Some([dp, dn, ds]) => [p, dp, dn, ds],
        None => hoop.rhs_pns(state),
    }
}

/// [`carvallo::hoop::Hoop::equilibrium`], from the perturbed `hoop` program when one is active.
pub fn hoop_equilibrium(hoop: &carvallo::hoop::Hoop, theta: f64, s: f64, n: f64) -> f64 {
    active_outputs("hoop", ["equilibrium"], &hoop_args(hoop, theta, 0.0, n, s))
        .map_or_else(|| hoop.equilibrium(theta, s, n), |[v]| v)
}

/// [`carvallo::hoop::Hoop::stability`], from the perturbed `hoop` program when one is active.
pub fn hoop_stability(hoop: &carvallo::hoop::Hoop, theta: f64, s: f64, n: f64) -> f64 {
    active_outputs("hoop", ["stability"], &hoop_args(hoop, theta, 0.0, n, s))
        .map_or_else(|| hoop.stability(theta, s, n), |[v]| v)
}

/// [`carvallo::hoop::Hoop::steady_turning_rates`] (the roots $n_1 \le n_2$ of (E) of n° 8, a
/// quadratic in $n$ whose coefficients are read off (E) at $n = 0, \pm\sqrt{g/R}$), from the
/// perturbed `hoop` program's `equilibrium` when one is active.
pub fn hoop_steady_turning_rates(
    hoop: &carvallo::hoop::Hoop,
    theta: f64,
    s: f64,
) -> Option<[f64; 2]> {
    let active = ACTIVE.with(|a| a.borrow().as_ref().is_some_and(|a| a.model == "hoop"));
    if !active {
        return hoop.steady_turning_rates(theta, s);
    }
    hoop.turning_rates_of(|n| hoop_equilibrium(hoop, theta, s, n))
}

/// One row of a falsification table: the perturbation, the claim functions to run under it,
/// and the ids of the claims whose falsification it is.
pub type Row = (&'static Perturbation, fn() -> Vec<crate::claims::Claim>, &'static [&'static str]);

/// `claims` with, for each row of `table`, the claims it names recorded with the verdict the
/// same check gives with the row's perturbation active ([`with`]).
pub fn falsify(claims: Vec<crate::claims::Claim>, table: &[Row]) -> Vec<crate::claims::Claim> {
    let mut out = claims;
    for (pert, run, ids) in table {
        let Some((perturbed, value)) = with(pert, run) else { continue };
        let what = describe(pert, value);
        out = out
            .into_iter()
            .map(|c| {
                match perturbed.iter().find(|p| p.id == c.id && ids.contains(&c.id.as_str())) {
                    Some(p) => c.falsified_by(&what, p.clone()),
                    None => c,
                }
            })
            .collect();
    }
    out
}

/// The evidence of an entry computed on a perturbed input: its relative difference when it
/// has one, otherwise what it derived (a claim's numbers).
fn evidence_of(perturbed: &Entry) -> BTreeMap<String, f64> {
    match (perturbed.rel_diff, &perturbed.derived) {
        (Some(r), _) => BTreeMap::from([("rel_diff".to_string(), r)]),
        (None, crate::entry::Derived::Number(v)) => BTreeMap::from([("derived".to_string(), *v)]),
        (None, crate::entry::Derived::Numbers(m)) => m.clone(),
    }
}

/// One row of an entries' falsification table: the perturbation, the function computing the
/// entries to run under it, and the quantities of the entries whose falsification it is.
pub type EntryRow = (&'static Perturbation, fn() -> Vec<Entry>, &'static [&'static str]);

/// `entries` with, for each row of `table`, the entries whose quantity it names given the
/// falsification the same computation gives with the row's perturbation active ([`with`]): for
/// an entry whose check has a margin that the relative changes of [`falsify_entries`] stay
/// within (a claim that an inequality holds), a perturbation of a stated size beyond it. Nothing
/// is done while another perturbation is active (inside a rerun of [`falsify_entries`], whose
/// own perturbation is then the one under test).
pub fn falsify_table(entries: Vec<Entry>, table: &[EntryRow]) -> Vec<Entry> {
    if ACTIVE.with(|a| a.borrow().is_some()) {
        return entries;
    }
    let mut out = entries;
    for (pert, run, quantities) in table {
        let Some((perturbed, value)) = with(pert, run) else { continue };
        let what = describe(pert, value);
        for e in out.iter_mut().filter(|e| quantities.contains(&e.quantity.as_str())) {
            let Some(p) =
                perturbed.iter().find(|p| p.section == e.section && p.quantity == e.quantity)
            else {
                continue;
            };
            e.falsification = Some(Falsification {
                perturbation: what.clone(),
                verdict: p.verdict,
                evidence: evidence_of(p),
            });
        }
    }
    out
}

/// `entries` with, for each row of `rows` (a quantity, the entries computed again with a
/// stated model ingredient of the derived side changed, the words stating it), the entry of
/// that quantity given the falsification the same comparison gives in the recomputed entries:
/// for an entry computed by a numerical route of the runtime that no generated program of the
/// report feeds (an RK4 integration, a potential differentiated by central differences, a
/// nonlinear model's steady turn).
pub fn falsify_by_rerun(entries: Vec<Entry>, rows: &[(String, Vec<Entry>, String)]) -> Vec<Entry> {
    let mut out = entries;
    for (quantity, perturbed, what) in rows {
        let Some(p) = perturbed.iter().find(|p| p.quantity == *quantity) else { continue };
        let Some(e) = out.iter_mut().find(|e| e.quantity == *quantity) else { continue };
        e.falsification = Some(Falsification {
            perturbation: what.clone(),
            verdict: p.verdict,
            evidence: evidence_of(p),
        });
    }
    out
}

/// The relative changes [`falsify_entries`] tries, in order: $10^{-6}$ (a million times the
/// agreement tolerance of a formula, [`crate::policy::AGREEMENT_TOLERANCE`]), then $10^{-2}$
/// (above the largest tolerance of a numerical route, [`crate::policy::NUMERIC_TOLERANCE_MAX`],
/// and beyond a slide rule's three digits, [`crate::policy::SLIDE_RULE`]).
pub const ENTRY_FACTORS: [f64; 2] = [1.0 + 1e-6, 1.0 + 1e-2];

/// The most perturbations [`falsify_entries`] tries for one entry before it records the first
/// one tried, which did not break it.
const MAX_TRIES: usize = 16;

/// The outputs of `program` that `note` names: between backticks, or as the word after
/// "generated" (`generated stability_n12`); the memoir's transcriptions (`memoir_*`) excluded,
/// in the order the note names them.
fn outputs_named(program: &Program, note: &str) -> Vec<String> {
    let ticked = note.split('`').skip(1).step_by(2);
    let after_generated = note
        .split("generated ")
        .skip(1)
        .filter_map(|rest| rest.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).next());
    let mut out: Vec<String> = Vec::new();
    for w in ticked.chain(after_generated) {
        if w.starts_with("memoir_") || out.iter().any(|o| o == w) {
            continue;
        }
        if program.outputs.iter().any(|o| o.name == w) {
            out.push(w.to_string());
        }
    }
    out
}

/// Whether `entry` is a symbolic check recorded at regeneration (its derived side is
/// `holds`): its falsification is recorded at regeneration too ([`crate::checks`]).
fn is_symbolic_check(entry: &Entry) -> bool {
    matches!(&entry.derived, crate::entry::Derived::Numbers(m) if m.contains_key("holds"))
}

/// The entry of `entries` that is `entry` computed again: the same index when section and
/// quantity match there, otherwise the first with the same section and quantity.
fn same_entry<'a>(entries: &'a [Entry], index: usize, entry: &Entry) -> Option<&'a Entry> {
    let same = |e: &&Entry| e.section == entry.section && e.quantity == entry.quantity;
    entries.get(index).filter(same).or_else(|| entries.iter().find(same))
}

/// What [`falsify_entries`] scales in a copy of an output's cone: the `k`-th argument it reads
/// ([`Target::Slot`]) or its `k`-th constant ([`Target::Constant`]), as a cache key.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Target2 {
    /// The `k`-th parameter or input the cone reads.
    Slot(usize),
    /// The `k`-th constant of the cone.
    Constant(usize),
}

/// What [`falsify_entries`] tries to scale in the cone `members` of an output of `p`, with the
/// words naming it: every argument the cone reads, then its constants (a closed form, such as
/// the abscissa of point B of n° 14, reads no argument).
fn candidates(p: &Program, members: &[usize]) -> Vec<(Target2, String)> {
    let arguments = arguments_read(p, members)
        .into_iter()
        .enumerate()
        .map(|(k, (_, name))| (Target2::Slot(k), format!("every use of `{name}`")));
    let constants = members
        .iter()
        .filter_map(|&i| match p.insts[i].op {
            Op::Const(c) => Some(c),
            _ => None,
        })
        .enumerate()
        .map(|(k, c)| {
            let value = crate::render::text::format_significant(c, 6);
            (Target2::Constant(k), format!("constant n° {} ({value})", k + 1))
        });
    arguments.chain(constants).collect()
}

/// `entries` (computed by `run`) with every `agrees` entry that states no falsification given
/// one (issue 38): for each output of the generated programs of `models` that the entry's note
/// names, each parameter or input that output reads, then each constant of it (a closed form
/// reads no argument), and each factor of [`ENTRY_FACTORS`], `run` computes the entries again
/// with that argument or constant scaled in a copy of the output's instructions
/// ([`Target::Slot`], [`Target::Constant`]; the memoir's transcriptions and every other output
/// keep theirs), until the same entry (same section and quantity) no longer `agrees`. That
/// perturbation and the verdict it gives are recorded; when none of the first
/// [`MAX_TRIES`] breaks it, the first tried is recorded with its verdict (`agrees`), which the
/// falsifiability test reports. An entry whose note names no output, or whose evaluators do
/// not read the perturbed program ([`overlay`] and the other functions of this module), is left
/// without one. Every rerun is cached by its perturbation.
pub fn falsify_entries(
    entries: Vec<Entry>,
    models: &[&'static str],
    run: impl Fn() -> Vec<Entry>,
) -> Vec<Entry> {
    let programs: Vec<(&'static str, std::rc::Rc<Program>)> =
        models.iter().filter_map(|m| Some((*m, parsed(m)?))).collect();
    type Key = (&'static str, String, Target2, usize);
    let mut cache: BTreeMap<Key, Option<(Vec<Entry>, String)>> = BTreeMap::new();
    let mut out = entries.clone();
    for (index, entry) in entries.iter().enumerate() {
        if entry.verdict != Verdict::Agrees
            || entry.falsification.is_some()
            || is_symbolic_check(entry)
        {
            continue;
        }
        let mut first: Option<Falsification> = None;
        let mut tries = 0usize;
        'search: for (model, program) in &programs {
            for output in outputs_named(program, &entry.note) {
                let Some(members) = cone(program, &output) else { continue };
                let candidates = candidates(program, &members);
                for (f, &factor) in ENTRY_FACTORS.iter().enumerate() {
                    for (candidate, what) in &candidates {
                        if tries == MAX_TRIES {
                            break 'search;
                        }
                        tries += 1;
                        let key = (*model, output.clone(), *candidate, f);
                        let rerun = cache.entry(key).or_insert_with(|| {
                            let target = match *candidate {
                                Target2::Slot(k) => Target::Slot(k),
                                Target2::Constant(k) => Target::Constant(k),
                            };
                            let (again, _) =
                                with_program(model, program, &output, target, factor, &run)?;
                            let what = format!(
                                "{what} in the generated `{output}` output of generated/{model}.ir scaled by 1 + {:.0e} (in a copy of the output's instructions: the memoir's transcribed outputs and every other output keep theirs)",
                                factor - 1.0
                            );
                            Some((again, what))
                        });
                        let Some((again, what)) = rerun.as_ref() else { continue };
                        let Some(perturbed) = same_entry(again, index, entry) else { continue };
                        let found = Falsification {
                            perturbation: what.clone(),
                            verdict: perturbed.verdict,
                            evidence: evidence_of(perturbed),
                        };
                        if found.breaks(entry.verdict) {
                            first = Some(found);
                            break 'search;
                        }
                        first.get_or_insert(found);
                    }
                }
            }
        }
        out[index].falsification = first;
    }
    out
}

/// The words stating a perturbation, with the constant's value.
pub fn describe(pert: &Perturbation, value: f64) -> String {
    let rel = pert.factor - 1.0;
    let change = if pert.factor == -1.0 {
        "negated".to_string()
    } else if pert.factor == 2.0 {
        "doubled".to_string()
    } else {
        format!("scaled by 1 {} {:.0e}", if rel < 0.0 { "-" } else { "+" }, rel.abs())
    };
    let what = match pert.target {
        Target::Constant(k) => {
            format!("constant n° {} ({})", k + 1, crate::render::text::format_significant(value, 6))
        }
        Target::Argument(name) => format!("every use of `{name}`"),
        Target::Slot(k) => format!("every use of argument n° {} read", k + 1),
    };
    format!(
        "{what} of the generated `{}` output of generated/{}.ir {change} (in a copy of the output's instructions: the memoir's transcribed outputs keep theirs)",
        pert.output, pert.model,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_perturbed_output_moves_and_the_others_do_not() {
        let p = Program::parse(ir_of("hoop_discussion").unwrap()).unwrap();
        let pert = Perturbation {
            model: "hoop_discussion",
            output: "quartic_f",
            target: crate::perturb::Target::Constant(0),
            factor: 1.01,
        };
        let (q, value) = perturbed_program(&p, &pert).unwrap();
        assert!(value.is_finite());
        let args = |p: &Program| {
            let inputs: Vec<f64> =
                p.inputs.iter().map(|n| if n == "t" { 0.3 } else { 0.2 }).collect();
            (vec![1.0; p.params.len()], inputs)
        };
        let (pa, ia) = args(&p);
        let before = p.eval_f64(&pa, &ia).unwrap();
        let after = q.eval_f64(&pa, &ia).unwrap();
        let k = |name: &str| p.outputs.iter().position(|o| o.name == name).unwrap();
        // quartic_f moves; memoir_quartic_f is the same instruction in the generated program
        // and keeps its value: only the copy was perturbed.
        assert_ne!(before[k("quartic_f")], after[k("quartic_f")]);
        assert_eq!(before[k("memoir_quartic_f")], after[k("memoir_quartic_f")]);
        for (i, o) in p.outputs.iter().enumerate() {
            if o.name != "quartic_f" {
                assert_eq!(before[i].to_bits(), after[i].to_bits(), "{}", o.name);
            }
        }
        // Unperturbed (factor 1) the copy gives the same value bit for bit.
        let same = Perturbation { factor: 1.0, ..pert };
        let (r, _) = perturbed_program(&p, &same).unwrap();
        assert_eq!(r.eval_f64(&pa, &ia).unwrap()[k("quartic_f")], before[k("quartic_f")]);
        assert!(perturbed_program(&p, &Perturbation { target: Target::Constant(10_000), ..pert })
            .is_none());
    }

    #[test]
    fn a_scaled_argument_is_the_output_at_the_scaled_argument() {
        let p = Program::parse(ir_of("unicycle").unwrap()).unwrap();
        let pert = Perturbation {
            model: "unicycle",
            output: "equilibrium",
            target: Target::Argument("z"),
            factor: 1.01,
        };
        let (q, value) = perturbed_program(&p, &pert).unwrap();
        assert!(value.is_nan());
        let args = |z: f64| -> (Vec<f64>, Vec<f64>) {
            let params = p
                .params
                .iter()
                .map(|n| match n.as_str() {
                    "z" => z,
                    "R" => 0.5,
                    "g" => 9.81,
                    _ => 3.0,
                })
                .collect();
            (params, p.inputs.iter().map(|n| if n == "theta" { 0.3 } else { 1.7 }).collect())
        };
        let k = |name: &str| p.outputs.iter().position(|o| o.name == name).unwrap();
        let (pa, ia) = args(1.25);
        let after = q.eval_f64(&pa, &ia).unwrap();
        let before = p.eval_f64(&pa, &ia).unwrap();
        // (E) with z scaled in its copy is the unperturbed (E) at 1.01 z, bit for bit (the same
        // product z * 1.01); every other output keeps its value, (E)'s memoir form too.
        let (pz, iz) = args(1.25 * 1.01);
        let at_scaled = p.eval_f64(&pz, &iz).unwrap();
        assert_eq!(after[k("equilibrium")].to_bits(), at_scaled[k("equilibrium")].to_bits());
        assert_ne!(after[k("equilibrium")], before[k("equilibrium")]);
        for (i, o) in p.outputs.iter().enumerate() {
            if o.name != "equilibrium" {
                assert_eq!(before[i].to_bits(), after[i].to_bits(), "{}", o.name);
            }
        }
        // An argument the output does not read, or no argument of that name: no perturbation.
        let unread = Perturbation { target: Target::Argument("L"), ..pert };
        assert!(perturbed_program(&p, &unread).is_none());
        let unknown = Perturbation { target: Target::Argument("zz"), ..pert };
        assert!(perturbed_program(&p, &unknown).is_none());
    }
}
