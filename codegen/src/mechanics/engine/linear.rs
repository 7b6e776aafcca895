//! The linearisation of a description's equations about a reference motion: every named formula
//! of the derivation carried as a *jet*, its value at the reference and its first-order
//! coefficient in each perturbed input (forward differentiation with symbolic coefficients,
//! name by name, so nothing is expanded beyond what the reference leaves), then
//! $$M(q_0)\,\delta\dot u = \frac{\partial f}{\partial q}\,\delta q + \frac{\partial f}{\partial u}\,\delta u$$
//! with the dependent coordinates' perturbations eliminated through the contact heights'
//! first-order terms.
//!
//! The reference is given as a value for each coordinate and independent speed (an expression
//! in the parameters and inputs: the upright bicycle's rear wheel rate is $-v/r_R$); it is an
//! equilibrium when the forcing and every contact height vanish there, which [`Linear`] reports
//! rather than assumes. The same function linearises Kane's equations (`M_`, `f_`) and Carvallo's
//! modified Lagrange equations (`L_M_`, `L_f_`) of one derivation, so the two routes can be
//! compared on the linear model exactly.

use std::collections::BTreeMap;

use symbolica::atom::{Atom, AtomCore, AtomView};

use crate::cas::var;
use crate::Formula;

/// A formula to first order about the reference: its value there and its coefficient in each
/// perturbed input (in the order of [`Linear::vars`]), both expanded.
#[derive(Clone, Debug)]
pub struct Jet {
    /// The value at the reference.
    pub value: Atom,
    /// The coefficient of each perturbation.
    pub slope: Vec<Atom>,
}

impl Jet {
    fn constant(value: Atom, n: usize) -> Jet {
        Jet { value, slope: vec![Atom::num(0); n] }
    }
}

/// Why a linearisation could not be made.
#[derive(Debug)]
pub enum LinearError {
    /// A formula uses a function or a power the jets do not carry, named with the formula.
    Unsupported(String),
    /// A name the linearisation needs is not a formula of the derivation.
    Missing(String),
    /// The dependent coordinates' perturbations cannot be solved from the heights.
    Constraint(String),
}

impl std::fmt::Display for LinearError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LinearError::Unsupported(what) => write!(f, "linearisation: unsupported {what}"),
            LinearError::Missing(name) => write!(f, "linearisation: no formula named {name}"),
            LinearError::Constraint(why) => write!(f, "linearisation: {why}"),
        }
    }
}

impl std::error::Error for LinearError {}

fn jet_of(
    v: AtomView<'_>,
    jets: &BTreeMap<String, Jet>,
    reference: &BTreeMap<String, Atom>,
    vars: &[String],
) -> Result<Jet, String> {
    let n = vars.len();
    Ok(match v {
        AtomView::Num(_) => Jet::constant(v.to_owned(), n),
        AtomView::Var(x) => {
            let symbol = x.get_symbol();
            let name = symbol.get_stripped_name();
            if let Some(j) = jets.get(name) {
                j.clone()
            } else if let Some(k) = vars.iter().position(|s| s == name) {
                let mut slope = vec![Atom::num(0); n];
                slope[k] = Atom::num(1);
                Jet { value: reference[name].clone(), slope }
            } else {
                Jet::constant(v.to_owned(), n)
            }
        }
        AtomView::Add(a) => {
            let mut out = Jet::constant(Atom::num(0), n);
            for t in a.iter() {
                let j = jet_of(t, jets, reference, vars)?;
                out.value += j.value;
                for (s, d) in out.slope.iter_mut().zip(j.slope) {
                    *s += d;
                }
            }
            out
        }
        AtomView::Mul(m) => {
            let mut out = Jet::constant(Atom::num(1), n);
            for f in m.iter() {
                let j = jet_of(f, jets, reference, vars)?;
                for (s, d) in out.slope.iter_mut().zip(&j.slope) {
                    *s = &*s * &j.value + &out.value * d;
                }
                out.value = &out.value * &j.value;
            }
            out
        }
        AtomView::Pow(p) => {
            let (b, e) = p.get_base_exp();
            if !matches!(e, AtomView::Num(_)) {
                return Err(format!("power with exponent {}", e.to_owned()));
            }
            let e = e.to_owned();
            let j = jet_of(b, jets, reference, vars)?;
            let d = &e * j.value.pow(&e - Atom::num(1));
            Jet {
                value: j.value.pow(e),
                slope: j
                    .slope
                    .iter()
                    .map(|s| if s.is_zero() { s.clone() } else { &d * s })
                    .collect(),
            }
        }
        AtomView::Fun(f) => {
            let name = f.get_symbol().get_stripped_name().to_string();
            let mut args = f.iter();
            let (Some(arg), None) = (args.next(), args.next()) else {
                return Err(format!("function {name} of several arguments"));
            };
            let j = jet_of(arg, jets, reference, vars)?;
            if j.slope.iter().all(Atom::is_zero) {
                // A function of a constant (the steering axis' tilt): left as it is.
                return Ok(Jet::constant(v.to_owned(), n));
            }
            let call = |f: &str, x: &Atom| -> Atom {
                if x.is_zero() {
                    match f {
                        "sin" | "sqrt" => return Atom::num(0),
                        "cos" => return Atom::num(1),
                        _ => {}
                    }
                }
                var(&format!("{f}({x})"))
            };
            let (value, d) = match name.as_str() {
                "sin" => (call("sin", &j.value), call("cos", &j.value)),
                "cos" => (call("cos", &j.value), -call("sin", &j.value)),
                "sqrt" => {
                    let r = call("sqrt", &j.value);
                    let d = Atom::num(1) / (Atom::num(2) * &r);
                    (r, d)
                }
                _ => return Err(format!("function {name}")),
            };
            Jet { value, slope: j.slope.iter().map(|s| &d * s).collect() }
        }
    })
}

/// The jets of every formula, in order: `reference` gives the value of each perturbed input
/// (`vars`); every other symbol (parameters, unperturbed inputs) is constant.
pub fn jets(
    formulas: &[Formula],
    reference: &BTreeMap<String, Atom>,
    vars: &[String],
    normal: &dyn Fn(&Atom) -> Atom,
) -> Result<BTreeMap<String, Jet>, LinearError> {
    let mut out = BTreeMap::new();
    for f in formulas {
        let j = jet_of(f.expr.as_view(), &out, reference, vars)
            .map_err(|what| LinearError::Unsupported(format!("{what} in {}", f.name)))?;
        let j = Jet { value: normal(&j.value), slope: j.slope.iter().map(normal).collect() };
        out.insert(f.name.clone(), j);
    }
    Ok(out)
}

/// The formulas `roots` depend on, in their order.
fn cone(formulas: &[Formula], roots: &[String]) -> Vec<Formula> {
    let index: BTreeMap<&str, usize> =
        formulas.iter().enumerate().map(|(k, f)| (f.name.as_str(), k)).collect();
    let mut keep = vec![false; formulas.len()];
    let mut stack: Vec<usize> =
        roots.iter().filter_map(|r| index.get(r.as_str()).copied()).collect();
    while let Some(k) = stack.pop() {
        if std::mem::replace(&mut keep[k], true) {
            continue;
        }
        for s in super::store::symbols_of(&formulas[k].expr) {
            if let Some(&j) = index.get(s.as_str()) {
                stack.push(j);
            }
        }
    }
    formulas.iter().zip(keep).filter(|(_, k)| *k).map(|(f, _)| f.clone()).collect()
}

/// A description's equations $M\dot u = f$ linearised about a reference.
#[derive(Debug)]
pub struct Linear {
    /// The perturbed quantities: the independent and dependent coordinates, the independent
    /// speeds, the inputs.
    pub vars: Vec<String>,
    /// The independent coordinates (the columns of [`Linear::f_q`]).
    pub coordinates: Vec<String>,
    /// The independent speeds (the rows, and the columns of [`Linear::m`] and [`Linear::f_u`]).
    pub speeds: Vec<String>,
    /// $M$ at the reference.
    pub m: Vec<Vec<Atom>>,
    /// $f$ at the reference: zero at an equilibrium.
    pub f0: Vec<Atom>,
    /// $\partial f/\partial q$, the dependent coordinates eliminated.
    pub f_q: Vec<Vec<Atom>>,
    /// $\partial f/\partial u$.
    pub f_u: Vec<Vec<Atom>>,
    /// The perturbed inputs (the columns of [`Linear::f_t`]).
    pub inputs: Vec<String>,
    /// $\partial f/\partial T$, the inputs' coefficients.
    pub f_t: Vec<Vec<Atom>>,
    /// Each contact height's value at the reference: zero when the reference is on the ground.
    pub heights0: Vec<(String, Atom)>,
    /// $\partial q_d/\partial q$: the dependent coordinates' first-order perturbations, by
    /// dependent coordinate, in the independent ones.
    pub dependent: Vec<(String, Vec<Atom>)>,
}

/// The reference motion of a linearisation and the quantities it perturbs.
#[derive(Clone, Debug)]
pub struct Reference {
    /// The value at the reference of every coordinate and independent speed below (an
    /// expression in the parameters and inputs).
    pub values: BTreeMap<String, Atom>,
    /// The independent coordinates.
    pub coordinates: Vec<String>,
    /// The dependent coordinates, each fixed by one of `heights`.
    pub dependent: Vec<String>,
    /// The independent speeds.
    pub speeds: Vec<String>,
    /// The contact heights (formula names) whose first-order terms give the dependent
    /// coordinates' perturbations.
    pub heights: Vec<String>,
    /// The inputs perturbed (torques), each with its value in `values`.
    pub inputs: Vec<String>,
}

/// One more formula to first order about the reference, like a row of the forcing: its value
/// there and its coefficients in the independent coordinates (the dependent ones eliminated),
/// the independent speeds and the inputs.
#[derive(Clone, Debug)]
pub struct Row {
    /// The value at the reference.
    pub value: Atom,
    /// The coefficients of the independent coordinates' perturbations.
    pub q: Vec<Atom>,
    /// The coefficients of the independent speeds' perturbations.
    pub u: Vec<Atom>,
    /// The coefficients of the inputs' perturbations.
    pub t: Vec<Atom>,
}

/// Linearises the equations named `<prefix>M_<ui>_<uj>` and `<prefix>f_<ui>` (`""` for Kane's,
/// `"L_"` for the modified Lagrange equations) about `reference`: a dependent coordinate's
/// perturbation is solved from the first-order terms of the contact heights by Cramer's rule;
/// `normal` brings every jet's value and coefficients to a normal form as they are made (an
/// expansion at least).
pub fn linearise(
    formulas: &[Formula],
    prefix: &str,
    reference: &Reference,
    normal: &dyn Fn(&Atom) -> Atom,
) -> Result<Linear, LinearError> {
    Ok(linearise_with(formulas, prefix, reference, normal, &[])?.0)
}

/// [`linearise`], and the formulas named `extra` linearised the same way ([`Row`], in order):
/// the parts of an equation (the modified Lagrange equations' momentum and correction terms).
pub fn linearise_with(
    formulas: &[Formula],
    prefix: &str,
    reference: &Reference,
    normal: &dyn Fn(&Atom) -> Atom,
    extra: &[String],
) -> Result<(Linear, Vec<Row>), LinearError> {
    let Reference { values: reference, coordinates, dependent, speeds, heights, inputs } =
        reference;
    if dependent.len() != heights.len() {
        return Err(LinearError::Constraint(format!(
            "{} dependent coordinates ({}) and {} contact heights ({})",
            dependent.len(),
            dependent.join(", "),
            heights.len(),
            heights.join(", ")
        )));
    }
    let vars: Vec<String> =
        coordinates.iter().chain(dependent).chain(speeds).chain(inputs).cloned().collect();
    for v in &vars {
        if !reference.contains_key(v) {
            return Err(LinearError::Missing(format!("reference value of {v}")));
        }
    }
    // Only the formulas the equations and the heights use (a derivation holds both routes,
    // the energy, the partial velocities...).
    let mut roots: Vec<String> = heights.clone();
    for (i, ui) in speeds.iter().enumerate() {
        roots.push(format!("{prefix}f_{ui}"));
        roots.extend(speeds[i..].iter().map(|uj| format!("{prefix}M_{ui}_{uj}")));
    }
    roots.extend(extra.iter().cloned());
    let all = jets(&cone(formulas, &roots), reference, &vars, normal)?;
    let get = |name: &str| all.get(name).ok_or_else(|| LinearError::Missing(name.to_string()));
    let nq = coordinates.len();
    let nd = dependent.len();
    // The heights' first-order terms: H_d δq_d + H_q δq = 0.
    let mut dq_d: Vec<Vec<Atom>> = vec![vec![Atom::num(0); nq]; nd];
    if nd > 0 {
        let hj: Vec<&Jet> = heights.iter().map(|h| get(h)).collect::<Result<_, _>>()?;
        let unknowns: Vec<String> = dependent.iter().map(|d| format!("lin_d{d}")).collect();
        for (c, _) in coordinates.iter().enumerate() {
            let eqs: Vec<Atom> = hj
                .iter()
                .map(|j| {
                    let mut e = j.slope[c].clone();
                    for (k, u) in unknowns.iter().enumerate() {
                        e += &j.slope[nq + k] * var(u);
                    }
                    e
                })
                .collect();
            if nd > 3 {
                return Err(LinearError::Constraint(format!(
                    "{nd} dependent coordinates (at most 3 are solved)"
                )));
            }
            let names: Vec<&str> = unknowns.iter().map(String::as_str).collect();
            let sol = crate::cas::solve_linear(&eqs, &names);
            for (k, s) in sol.into_iter().enumerate() {
                dq_d[k][c] = s;
            }
        }
    }
    let heights0 = heights
        .iter()
        .map(|h| Ok((h.clone(), get(h)?.value.clone())))
        .collect::<Result<Vec<_>, LinearError>>()?;
    let n = speeds.len();
    let mut m = vec![vec![Atom::num(0); n]; n];
    for i in 0..n {
        for j in i..n {
            let e = get(&format!("{prefix}M_{}_{}", speeds[i], speeds[j]))?.value.clone();
            m[i][j] = e.clone();
            m[j][i] = e;
        }
    }
    let row = |name: &str| -> Result<Row, LinearError> {
        let j = get(name)?;
        Ok(Row {
            value: j.value.clone(),
            q: (0..nq)
                .map(|c| {
                    let mut e = j.slope[c].clone();
                    for (k, row) in dq_d.iter().enumerate() {
                        e += &j.slope[nq + k] * &row[c];
                    }
                    e.expand()
                })
                .collect(),
            u: (0..n).map(|k| j.slope[nq + nd + k].clone()).collect(),
            t: (0..inputs.len()).map(|k| j.slope[nq + nd + n + k].clone()).collect(),
        })
    };
    let mut f0 = Vec::new();
    let mut f_q = Vec::new();
    let mut f_u = Vec::new();
    let mut f_t = Vec::new();
    for s in speeds {
        let r = row(&format!("{prefix}f_{s}"))?;
        f0.push(r.value);
        f_q.push(r.q);
        f_u.push(r.u);
        f_t.push(r.t);
    }
    let extra = extra.iter().map(|name| row(name)).collect::<Result<Vec<_>, _>>()?;
    let lin = Linear {
        vars,
        coordinates: coordinates.clone(),
        speeds: speeds.clone(),
        m,
        f0,
        f_q,
        f_u,
        inputs: inputs.clone(),
        f_t,
        heights0,
        dependent: dependent.iter().cloned().zip(dq_d).collect(),
    };
    Ok((lin, extra))
}
