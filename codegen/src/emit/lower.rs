//! Lowering of canonical expressions into a [`carvallo_ir::Builder`] (the rules are listed in
//! the docs of the parent module): sums folded with subtractions, one division per product,
//! integer powers as `powi`, half-integer powers through `sqrt`.

use std::collections::BTreeMap;

use carvallo_ir::{Builder, Value};
use symbolica::domains::rational::Rational;

use super::expr::{rat, Expr, Func};
use super::text::text;
use super::{rational_to_f64, EmitError};

/// Lowers canonical expressions into a [`Builder`].
pub(super) struct Lowerer<'a> {
    pub(super) b: &'a mut Builder,
    pub(super) names: &'a BTreeMap<String, Value>,
}

impl Lowerer<'_> {
    fn constant(&mut self, r: &Rational) -> Result<Value, EmitError> {
        let x = rational_to_f64(r).ok_or_else(|| EmitError::Constant { value: r.to_string() })?;
        Ok(self.b.constant(x))
    }

    pub(super) fn value(&mut self, e: &Expr) -> Result<Value, EmitError> {
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

pub(super) fn rational_integer(k: &Rational, f: &Expr) -> Result<i64, EmitError> {
    let s = k.to_string();
    s.parse::<i64>().map_err(|_| EmitError::Unsupported {
        what: format!("exponent {s} outside the i64 range"),
        expr: text(f),
    })
}

pub(super) fn is_ir_name(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c == '_' || c.is_ascii_alphabetic())
        && chars.all(|c| c == '_' || c.is_ascii_alphanumeric())
}
