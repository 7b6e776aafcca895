//! The computer algebra every derivation shares, on symbolica expressions: parsing and
//! symbols, the polynomial stand-ins $\sin\theta$, $\cos\theta$ ([`sin_t`], [`cos_t`]) tied by
//! $\sin^2\theta + \cos^2\theta = 1$ and the exact reduction modulo that relation
//! ([`reduce_trig`], which makes [`is_zero`] an exact test), conversion to and from the
//! functions `sin(theta)`, `cos(theta)`, `tan(theta)` of the handed-over formulas, substitution,
//! simplification, 3 × 3 determinants and small linear systems (Cramer's rule).

use symbolica::atom::{Atom, AtomCore};
use symbolica::domains::integer::Z;
use symbolica::domains::rational::Q;
use symbolica::parse;

/// Parses an expression in this crate's namespace (all derivation symbols live there).
///
/// # Panics
/// Panics when `text` is not a valid symbolica expression; callers only pass literals
/// written in this crate.
pub fn expr(text: &str) -> Atom {
    parse!(text)
}

/// The names of the symbols of this crate's namespace in the order they were created in this
/// process (the order symbolica sorts the terms of an expression by).
pub fn created_symbols() -> Vec<String> {
    let prefix = concat!(env!("CARGO_CRATE_NAME"), "::");
    symbolica::state::State::symbol_iter()
        .filter_map(|(_, name)| name.strip_prefix(prefix).map(str::to_string))
        .collect()
}

/// The symbol `name` as an expression.
pub fn var(name: &str) -> Atom {
    expr(name)
}

/// The rational number `num/den` as an expression.
pub fn rat(num: i64, den: i64) -> Atom {
    Atom::num(num) / Atom::num(den)
}

/// Polynomial stand-in for $\sin\theta$ used inside the derivations.
pub fn sin_t() -> Atom {
    var("sin_theta")
}

/// Polynomial stand-in for $\cos\theta$ used inside the derivations.
pub fn cos_t() -> Atom {
    var("cos_theta")
}

/// Replaces the stand-ins [`sin_t`], [`cos_t`] by `sin(theta)`, `cos(theta)`.
pub fn to_trig(e: &Atom) -> Atom {
    e.replace(sin_t().to_pattern())
        .with(expr("sin(theta)").to_pattern())
        .replace(cos_t().to_pattern())
        .with(expr("cos(theta)").to_pattern())
}

/// Replaces `tan(theta)`, `sin(theta)`, `cos(theta)` by the polynomial stand-ins.
pub fn from_trig(e: &Atom) -> Atom {
    e.replace(expr("tan(theta)").to_pattern())
        .with((sin_t() / cos_t()).to_pattern())
        .replace(expr("sin(theta)").to_pattern())
        .with(sin_t().to_pattern())
        .replace(expr("cos(theta)").to_pattern())
        .with(cos_t().to_pattern())
}

/// The degree of the monomial `m` in the symbol `x` (`m` a product of powers, no sum).
pub fn monomial_degree(m: &Atom, x: &Atom) -> Option<u32> {
    let d = (x * &m.derivative(x.get_symbol()?) / m).expand();
    (0..64).find(|k| d == Atom::num(*k as i64))
}

/// Reduces a polynomial in [`sin_t`] modulo $\sin^2\theta + \cos^2\theta - 1$ to the normal
/// form $a + \sin\theta\,b$ where $a, b$ do not contain $\sin\theta$ (exact).
pub fn reduce_trig(e: &Atom) -> Atom {
    reduce_pair(e, &sin_t(), &cos_t())
}

/// Reduces a polynomial in the stand-in `st` of a sine modulo $st^2 + ct^2 - 1$, `ct` being
/// the stand-in of the cosine of the same angle, to the normal form $a + st\,b$ (exact); the
/// rule of [`reduce_trig`] for any angle.
pub fn reduce_pair(e: &Atom, st: &Atom, ct: &Atom) -> Atom {
    let one_minus_c2 = Atom::num(1) - ct.pow(Atom::num(2));
    let expanded = e.expand();
    let mut out = Atom::num(0);
    for (key, coeff) in expanded.coefficient_list::<u8>(std::slice::from_ref(st)) {
        let k = monomial_degree(&key, st).unwrap_or(0);
        let mut term = coeff * one_minus_c2.pow(Atom::num((k / 2) as i64));
        if k % 2 == 1 {
            term *= st;
        }
        out += term;
    }
    out.expand()
}

/// Numerator and denominator of `e` brought to one fraction, both reduced by [`reduce_trig`].
pub fn num_den(e: &Atom) -> (Atom, Atom) {
    let rp = e.expand().to_rational_polynomial::<_, _, u16>(&Q, &Z, ());
    (reduce_trig(&rp.numerator.to_expression()), reduce_trig(&rp.denominator.to_expression()))
}

/// Exact test that `e`, a rational function of the symbols and of $\sin\theta, \cos\theta$
/// (stand-ins), vanishes identically.
pub fn is_zero(e: &Atom) -> bool {
    num_den(e).0.is_zero()
}

/// A readable canonical form: one fraction with reduced numerator, distributed over the
/// denominator when the denominator is a single term.
pub fn simplify(e: &Atom) -> Atom {
    let (n, d) = num_den(e);
    let (n, d) = num_den(&(n / d));
    if d.nterms() <= 1 {
        (n / d).expand()
    } else {
        n / d
    }
}

/// Replaces the symbol `name` by `value` everywhere in `e`.
pub fn subst(e: &Atom, name: &str, value: &Atom) -> Atom {
    e.replace(var(name).to_pattern()).with(value.to_pattern())
}

/// Determinant of a 3 × 3 matrix of expressions.
pub fn det3(m: &[Vec<Atom>]) -> Atom {
    &m[0][0] * &(&m[1][1] * &m[2][2] - &m[1][2] * &m[2][1])
        - &m[0][1] * &(&m[1][0] * &m[2][2] - &m[1][2] * &m[2][0])
        + &m[0][2] * &(&m[1][0] * &m[2][1] - &m[1][1] * &m[2][0])
}

/// Solves equations linear in the symbols `unknowns` (Cramer's rule), simplified.
///
/// # Panics
/// Panics unless there are as many equations as unknowns and at most three.
pub fn solve_linear(eqs: &[Atom], unknowns: &[&str]) -> Vec<Atom> {
    let n = unknowns.len();
    assert!(eqs.len() == n && (1..=3).contains(&n), "solve_linear takes 1 to 3 equations");
    let zero_all =
        |e: &Atom| unknowns.iter().fold(e.clone(), |acc, u| subst(&acc, u, &Atom::num(0)));
    let coef = |e: &Atom, u: &str| simplify(&e.derivative(var(u).get_symbol().expect("symbol")));
    let mut m: Vec<Vec<Atom>> = vec![vec![Atom::num(0); 3]; 3];
    let mut b: Vec<Atom> = vec![Atom::num(0); 3];
    for i in 0..3 {
        if i >= n {
            m[i][i] = Atom::num(1);
            continue;
        }
        for (j, u) in unknowns.iter().enumerate() {
            m[i][j] = coef(&eqs[i], u);
        }
        b[i] = -zero_all(&eqs[i]);
    }
    let det = det3(&m);
    (0..n)
        .map(|j| {
            let mut mj = m.clone();
            for i in 0..3 {
                mj[i][j] = b[i].clone();
            }
            simplify(&(det3(&mj) / &det))
        })
        .collect()
}

/// Shows an expression with `sin(theta)`, `cos(theta)`.
pub fn show(e: &Atom) -> String {
    to_trig(&simplify(e)).to_string()
}
