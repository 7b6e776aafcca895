//! Named intermediate quantities: every non-trivial quantity the engine builds is a formula of its
//! own, and later formulas refer to it by name. The store also differentiates through the names
//! (the chain rule over the formulas they stand for), so time derivatives and partial
//! derivatives never expand a name.

use std::collections::{BTreeMap, BTreeSet};

use symbolica::atom::{Atom, AtomCore, AtomView};

use crate::cas::var;
use crate::Formula;

/// A three-vector of expressions (components in one frame).
pub type V3 = [Atom; 3];
/// A 3 × 3 matrix of expressions.
pub type M3 = [[Atom; 3]; 3];

/// The names of the symbols an expression contains (functions' arguments included).
pub fn symbols_of(e: &Atom) -> BTreeSet<String> {
    fn walk(v: AtomView<'_>, out: &mut BTreeSet<String>) {
        match v {
            AtomView::Num(_) => {}
            AtomView::Var(x) => {
                out.insert(x.get_symbol().get_stripped_name().to_string());
            }
            AtomView::Fun(f) => f.iter().for_each(|a| walk(a, out)),
            AtomView::Pow(p) => {
                let (b, e) = p.get_base_exp();
                walk(b, out);
                walk(e, out);
            }
            AtomView::Mul(m) => m.iter().for_each(|a| walk(a, out)),
            AtomView::Add(a) => a.iter().for_each(|t| walk(t, out)),
        }
    }
    let mut out = BTreeSet::new();
    walk(e.as_view(), &mut out);
    out
}

/// Derivative of `e` with respect to the symbol `name` (zero when `e` does not contain it).
pub fn d(e: &Atom, name: &str) -> Atom {
    let s = var(name).get_symbol().expect("a symbol");
    if e.contains_symbol(s) {
        e.derivative(s)
    } else {
        Atom::num(0)
    }
}

/// The operations of an expression's tree as written (no sharing): a rough measure to choose
/// between a formula as built and expanded.
pub fn tree_ops(e: &Atom) -> usize {
    fn walk(v: AtomView<'_>) -> usize {
        match v {
            AtomView::Num(_) | AtomView::Var(_) => 0,
            AtomView::Fun(f) => 1 + f.iter().map(walk).sum::<usize>(),
            AtomView::Pow(p) => {
                let (b, e) = p.get_base_exp();
                1 + walk(b) + walk(e)
            }
            AtomView::Mul(m) => {
                m.iter().count().saturating_sub(1) + m.iter().map(walk).sum::<usize>()
            }
            AtomView::Add(a) => {
                a.iter().count().saturating_sub(1) + a.iter().map(walk).sum::<usize>()
            }
        }
    }
    walk(e.as_view())
}

/// The formulas handed over, with what each name stands for and the rules of differentiation.
pub struct Store {
    /// Memoir section or model label of the formulas.
    section: String,
    /// Prefix of every name this store makes (keeps two stores in one program apart).
    prefix: String,
    /// The formulas, in order.
    pub formulas: Vec<Formula>,
    /// What each name stands for.
    exprs: BTreeMap<String, Atom>,
    /// Time derivatives at constant speeds of leaves and of names already differentiated.
    rates: BTreeMap<String, Atom>,
    /// Partial derivatives by (name, variable), memoised.
    partials: BTreeMap<(String, String), Atom>,
}

fn is_trivial(e: &Atom) -> bool {
    match e.as_view() {
        AtomView::Num(_) | AtomView::Var(_) => true,
        AtomView::Mul(m) => {
            m.iter().count() == 2
                && m.iter().any(|f| matches!(f, AtomView::Num(_)))
                && m.iter().any(|f| matches!(f, AtomView::Var(_)))
        }
        _ => false,
    }
}

impl Store {
    /// An empty store whose formulas carry `section` and whose names start with `prefix`.
    pub fn new(section: &str, prefix: &str) -> Store {
        Store {
            section: section.to_string(),
            prefix: prefix.to_string(),
            formulas: Vec::new(),
            exprs: BTreeMap::new(),
            rates: BTreeMap::new(),
            partials: BTreeMap::new(),
        }
    }

    /// The full name of a local name.
    pub fn full(&self, name: &str) -> String {
        format!("{}{name}", self.prefix)
    }

    /// Whether `name` (a full name) is a quantity of this store.
    pub fn is_named(&self, name: &str) -> bool {
        self.exprs.contains_key(name)
    }

    /// Records `expr` as the formula `name` (prefixed) and returns the symbol standing for it; a
    /// number, a symbol or a number times a symbol (once expanded) is returned as it is,
    /// unnamed. The formula is kept as built, not expanded: products of sums (a cross product of
    /// an angular velocity with a named vector) cost fewer operations factored (choosing per
    /// formula the form with fewer [`tree_ops`] cost 20 more in the Whipple bicycle's M and f).
    pub fn name(&mut self, name: &str, description: &str, expr: Atom) -> Atom {
        let expanded = expr.expand();
        if is_trivial(&expanded) {
            return expanded;
        }
        self.put(name, description, expr)
    }

    /// Records `expr` as the formula `name` (prefixed) whatever it is, and returns its symbol.
    pub fn put(&mut self, name: &str, description: &str, expr: Atom) -> Atom {
        let full = self.full(name);
        assert!(!self.exprs.contains_key(&full), "the engine named {full} twice");
        self.formulas.push(Formula {
            name: full.clone(),
            section: self.section.clone(),
            description: description.to_string(),
            expr: expr.clone(),
        });
        self.exprs.insert(full.clone(), expr);
        var(&full)
    }

    /// Records `expr` as the formula `name` exactly (no prefix): for quantities whose symbol is
    /// already in use, like a dependent speed, so that every formula containing it uses the value.
    pub fn put_exact(&mut self, name: &str, description: &str, expr: Atom) -> Atom {
        assert!(!self.exprs.contains_key(name), "the engine named {name} twice");
        self.formulas.push(Formula {
            name: name.to_string(),
            section: self.section.clone(),
            description: description.to_string(),
            expr: expr.clone(),
        });
        self.exprs.insert(name.to_string(), expr);
        var(name)
    }

    /// Names the three components of `v` as `<name>_x`, `_y`, `_z`.
    pub fn name3(&mut self, name: &str, description: &str, v: &V3) -> V3 {
        let comps = ["x", "y", "z"];
        [0, 1, 2].map(|k| {
            self.name(
                &format!("{name}_{}", comps[k]),
                &format!("{description}, {} component", comps[k]),
                v[k].clone(),
            )
        })
    }

    /// Like [`Store::name3`], and the components it leaves unnamed (numbers, symbols, a number
    /// times a symbol) are recorded as formulas too, so that every component is an output; the
    /// vector returned is [`Store::name3`]'s, so no other formula changes.
    pub fn name3_all(&mut self, name: &str, description: &str, v: &V3) -> V3 {
        let named = self.name3(name, description, v);
        for (k, c) in ["x", "y", "z"].iter().enumerate() {
            let full = format!("{name}_{c}");
            if !self.is_named(&self.full(&full)) {
                let _ = self.put(&full, &format!("{description}, {c} component"), named[k].clone());
            }
        }
        named
    }

    /// Declares the time derivative (at constant speeds) of a leaf symbol.
    pub fn set_rate(&mut self, leaf: &str, rate: Atom) {
        self.rates.insert(leaf.to_string(), rate);
    }

    /// The time derivative at constant speeds of `e`: the chain rule over its leaves and names;
    /// the derivative of a name is itself named (`<name>_dt`) the first time it is needed.
    pub fn dt(&mut self, e: &Atom) -> Atom {
        let mut out = Atom::num(0);
        for s in symbols_of(e) {
            let rate = self.rate_of(&s);
            if !rate.is_zero() {
                out += d(e, &s) * rate;
            }
        }
        out.expand()
    }

    fn rate_of(&mut self, s: &str) -> Atom {
        if let Some(r) = self.rates.get(s) {
            return r.clone();
        }
        let Some(expr) = self.exprs.get(s).cloned() else {
            return Atom::num(0);
        };
        let inner = self.dt(&expr);
        let local = s.strip_prefix(&self.prefix).unwrap_or(s).to_string();
        let r = self.name(&format!("{local}_dt"), &format!("time derivative of {s}"), inner);
        self.rates.insert(s.to_string(), r.clone());
        r
    }

    /// The partial derivative of `e` with respect to the symbol `x`, through the names (each
    /// name's partial is named `<name>_d<x>` the first time it is needed).
    pub fn partial(&mut self, e: &Atom, x: &str) -> Atom {
        let mut out = d(e, x);
        for s in symbols_of(e) {
            if s == x || !self.exprs.contains_key(&s) {
                continue;
            }
            let p = self.partial_of(&s, x);
            if !p.is_zero() {
                out += d(e, &s) * p;
            }
        }
        out.expand()
    }

    fn partial_of(&mut self, s: &str, x: &str) -> Atom {
        let key = (s.to_string(), x.to_string());
        if let Some(p) = self.partials.get(&key) {
            return p.clone();
        }
        let expr = self.exprs.get(s).cloned().expect("a name");
        let inner = self.partial(&expr, x);
        let local = s.strip_prefix(&self.prefix).unwrap_or(s).to_string();
        let p = self.name(&format!("{local}_d{x}"), &format!("d {s} / d {x}"), inner);
        self.partials.insert(key, p.clone());
        p
    }

    /// The value of `e` in f64 at `point` (values of parameters, coordinates' sines and cosines'
    /// arguments, speeds and inputs by name), every name evaluated from its formula; `None` when
    /// a symbol has no value or a function is not one of sin, cos, sqrt.
    pub fn eval(&self, e: &Atom, point: &mut BTreeMap<String, f64>) -> Option<f64> {
        self.eval_view(e.as_view(), point)
    }

    fn eval_view(&self, v: AtomView<'_>, point: &mut BTreeMap<String, f64>) -> Option<f64> {
        Some(match v {
            AtomView::Num(_) => {
                // A rational printed as `p` or `p/q` (the engine's numbers are rationals).
                let text = v.to_owned().to_string();
                let (p, q) = text.split_once('/').unwrap_or((text.as_str(), "1"));
                p.trim().parse::<f64>().ok()? / q.trim().parse::<f64>().ok()?
            }
            AtomView::Var(x) => {
                let name = x.get_symbol().get_stripped_name().to_string();
                if let Some(val) = point.get(&name) {
                    return Some(*val);
                }
                let expr = self.exprs.get(&name)?.clone();
                let val = self.eval(&expr, point)?;
                point.insert(name, val);
                val
            }
            AtomView::Fun(f) => {
                let arg = self.eval_view(f.iter().next()?, point)?;
                match f.get_symbol().get_stripped_name() {
                    "sin" => arg.sin(),
                    "cos" => arg.cos(),
                    "sqrt" => arg.sqrt(),
                    _ => return None,
                }
            }
            AtomView::Pow(p) => {
                let (b, e) = p.get_base_exp();
                self.eval_view(b, point)?.powf(self.eval_view(e, point)?)
            }
            AtomView::Mul(m) => {
                let mut out = 1.0;
                for f in m.iter() {
                    out *= self.eval_view(f, point)?;
                }
                out
            }
            AtomView::Add(a) => {
                let mut out = 0.0;
                for t in a.iter() {
                    out += self.eval_view(t, point)?;
                }
                out
            }
        })
    }

    /// `e` with every name written out (latest first), for exact comparisons of small results.
    pub fn unname(&self, e: &Atom) -> Atom {
        let mut x = e.clone();
        for f in self.formulas.iter().rev() {
            let s = var(&f.name).get_symbol().expect("a symbol");
            if x.contains_symbol(s) {
                x = x.replace(var(&f.name).to_pattern()).with(f.expr.to_pattern());
            }
        }
        x
    }
}

/// Sum of two vectors.
pub fn add(a: &V3, b: &V3) -> V3 {
    [&a[0] + &b[0], &a[1] + &b[1], &a[2] + &b[2]]
}

/// Difference of two vectors.
pub fn sub(a: &V3, b: &V3) -> V3 {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

/// A vector times a scalar.
pub fn scale(k: &Atom, a: &V3) -> V3 {
    [k * &a[0], k * &a[1], k * &a[2]]
}

/// Scalar product.
pub fn dot(a: &V3, b: &V3) -> Atom {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

/// Vector product.
pub fn cross(a: &V3, b: &V3) -> V3 {
    [&a[1] * &b[2] - &a[2] * &b[1], &a[2] * &b[0] - &a[0] * &b[2], &a[0] * &b[1] - &a[1] * &b[0]]
}

/// Each component expanded.
pub fn expand3(a: &V3) -> V3 {
    [a[0].expand(), a[1].expand(), a[2].expand()]
}

/// Matrix times vector.
pub fn mv(m: &M3, v: &V3) -> V3 {
    [0, 1, 2].map(|r| (&m[r][0] * &v[0] + &m[r][1] * &v[1] + &m[r][2] * &v[2]).expand())
}

/// Transposed matrix times vector.
pub fn mtv(m: &M3, v: &V3) -> V3 {
    [0, 1, 2].map(|c| (&m[0][c] * &v[0] + &m[1][c] * &v[1] + &m[2][c] * &v[2]).expand())
}

/// The zero vector.
pub fn zero3() -> V3 {
    [Atom::num(0), Atom::num(0), Atom::num(0)]
}
