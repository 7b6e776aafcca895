//! The LaTeX printer of canonical expressions (Greek letters and subscripts from the symbol
//! names), for `generated/<model>.md`.

use symbolica::domains::rational::Rational;

use super::expr::{Expr, Func};
use super::text::{half, precedence, split_product, PREC_ATOM, PREC_MUL, PREC_POW};

pub(super) const GREEK: &[&str] = &[
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
    "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi",
    "Omega",
];

pub(super) fn latex_name(name: &str) -> String {
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

pub(super) fn latex_rational(r: &Rational) -> String {
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

pub(super) fn latex_fun_arg(a: &Expr) -> String {
    match a {
        Expr::Sym(_) | Expr::Pi => format!(" {}", latex(a)),
        Expr::Num(r) if r.is_integer() && !r.is_negative() => format!(" {}", latex(a)),
        _ => format!("\\left({}\\right)", latex(a)),
    }
}

pub(super) fn wrap_latex(e: &Expr, min: u8) -> String {
    if precedence(e) < min {
        format!("\\left({}\\right)", latex(e))
    } else {
        latex(e)
    }
}
