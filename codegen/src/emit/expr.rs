//! The canonical expression tree: a symbolica expression read through its public view API into
//! an owned tree whose sums and products are sorted by an order that depends only on the
//! expression (names, exact rationals, structure), and the correctly rounded `f64` of an exact
//! rational.

use symbolica::atom::{Atom, AtomView, Symbol};
use symbolica::coefficient::Coefficient;
use symbolica::domains::rational::Rational;
use symbolica::domains::SelfRing;

use super::EmitError;

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
    pub(super) fn name(self) -> &'static str {
        match self {
            Func::Sqrt => "sqrt",
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Atan2 => "atan2",
        }
    }

    pub(super) fn arity(self) -> usize {
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

pub(super) fn rat(n: i64) -> Rational {
    Rational::from(n)
}

pub(super) fn unsupported(what: impl Into<String>, v: AtomView<'_>) -> EmitError {
    EmitError::Unsupported { what: what.into(), expr: v.to_string() }
}

/// The exact rational value of a numeric atom.
pub(super) fn number(v: AtomView<'_>) -> Result<Rational, EmitError> {
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
pub(super) fn term_key(e: &Expr) -> (bool, &[Expr], Rational) {
    match e {
        Expr::Num(r) => (true, &[], r.clone()),
        Expr::Mul(f, c) => (false, f.as_slice(), c.clone()),
        other => (false, std::slice::from_ref(other), rat(1)),
    }
}

/// Sort key of a factor in a product: by base, then by exponent.
pub(super) fn factor_key(e: &Expr) -> (&Expr, Rational) {
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

    pub(super) fn pow(base: Expr, k: Rational) -> Expr {
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
    pub(super) fn is_negative(&self) -> bool {
        match self {
            Expr::Num(r) | Expr::Mul(_, r) => r.is_negative(),
            _ => false,
        }
    }

    /// The expression with the sign of its coefficient flipped (only for negative ones).
    pub(super) fn negated(&self) -> Expr {
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
