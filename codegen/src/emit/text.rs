//! The plain-text printer of canonical expressions (`*`, `/`, `^`, function calls) and the
//! operator precedences it shares with the LaTeX printer.

use symbolica::domains::rational::Rational;

use super::expr::{rat, Expr};

pub(super) const PREC_ADD: u8 = 1;
pub(super) const PREC_MUL: u8 = 2;
pub(super) const PREC_POW: u8 = 3;
pub(super) const PREC_ATOM: u8 = 4;

pub(super) fn precedence(e: &Expr) -> u8 {
    match e {
        Expr::Add(_) => PREC_ADD,
        Expr::Mul(..) => PREC_MUL,
        Expr::Num(r) if r.is_negative() || !r.is_integer() => PREC_MUL,
        Expr::Pow(_, k) if *k == half() => PREC_ATOM,
        Expr::Pow(..) => PREC_POW,
        _ => PREC_ATOM,
    }
}

pub(super) fn half() -> Rational {
    &rat(1) / &rat(2)
}

/// Splits a product into (sign is negative, |coefficient|, numerator factors, denominator
/// factors with their exponents made positive).
pub(super) fn split_product(
    factors: &[Expr],
    c: &Rational,
) -> (bool, Rational, Vec<Expr>, Vec<Expr>) {
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

pub(super) fn wrap_text(e: &Expr, min: u8) -> String {
    if precedence(e) < min {
        format!("({})", text(e))
    } else {
        text(e)
    }
}
