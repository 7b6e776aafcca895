//! The discussion of the hoop's steady states (memoir Part I, ch. I, n° 13–19), derived with
//! symbolica from the normalised (E), (S), (D) of n° 12 that [`crate::derive::hoop::derive`] produces
//! (the expressions are taken from that derivation, not typed again).
//!
//! With $x = \cos\theta$ and $y = s^2$ (n° 13):
//! * the reality curve (ℰ) is the discriminant of $E(n)$ (n° 13);
//! * the curve (S) of n° 14 is the resultant of $E(n)$ and $S(n)$ in $n$ (symbolica's
//!   multivariate resultant, cross-checked by the Sylvester formula of two quadratics), reduced
//!   with $\sin^2\theta = 1 - x^2$; the curve (S1) is the discriminant of $S(n)$; the points A,
//!   B, D, F, the tangents at A and D, and the vertical tangent (discriminant of (S) in $y$, its
//!   quartic $F(t)$ with $t = x^2$, factored over ℚ, root in closed form);
//! * n° 15: (E′) $s(n)$, its minimum $(n_0, s_0)$, (D′) and (D″) (resultant of (E) and (D));
//! * n° 17: the curve (N) $E(-s) = 0$, its contact point I with (ℰ), and point H of n° 17 bis
//!   where (N) meets (S), through the cubic in $\sin\theta$;
//! * n° 19: the stick (*baguette*) equations: system (2) of n° 7 with the stick's moments
//!   $\mathfrak M$, $\mathfrak M_1$, linearised, and the memoir's solutions (3)–(7) checked to
//!   solve it.
//!
//! [`derive`] returns the model `hoop_discussion` (see `generated/hoop_discussion.md`).

use anyhow::{anyhow, ensure, Context, Result};
use symbolica::atom::{Atom, AtomCore};
use symbolica::domains::rational::{RationalField, Q};
use symbolica::poly::PolynomialResultant;

use crate::cas::{cos_t, expr, from_trig, is_zero, num_den, rat, simplify, sin_t, to_trig, var};
use crate::cas::{show, solve_linear, subst};
use crate::{Check, Derivation, Formula};

/// Parameter names of the model (only the stick equations of n° 19 use them).
pub const PARAMS: [&str; 2] = ["R", "g"];
/// Input names of the model: lean θ, rates s, n (n° 12 units except in n° 19), the plane
/// coordinates x = cos θ, y = s², the quartic's variable t = x², a skid value d, the time of
/// n° 19 and the stick's moments M, M1 (1/s²; M1 in 1/s³... see n° 19).
pub const INPUTS: [&str; 10] = ["theta", "s", "n", "x", "y", "t", "d", "time", "M", "M1"];

/// The memoir's printed formulas of n° 13–19 (symbolica syntax, "first member" of "= 0" for
/// curves; `x = cos(theta)`, `y = s^2`).
pub mod printed {
    /// n° 13, (ℰ).
    pub const REALITY: &str = "x^2 + 2/3*x*y - 1";
    /// n° 14, (S).
    pub const CURVE_S: &str =
        "16*x^2*(1+x^2)*y^2 + 8*x*(5*x^4 - 5*x^2 - 1)*y + 3*(1+x^2)^2*(1-x^2)";
    /// n° 14, (S1) solved for y.
    pub const CURVE_S1_Y: &str = "3/4*x/(1+2*x^2)";
    /// n° 14, the quartic of the vertical tangent.
    pub const QUARTIC_F: &str = "28*t^4 - 44*t^3 + 15*t^2 + 4*t - 2";
    /// n° 14, the quartic after the shift t = 1 + u (Horner tableau).
    pub const QUARTIC_U: &str = "28*t^4 + 68*t^3 + 51*t^2 + 14*t + 1";
    /// n° 15, (E′).
    pub const S_OF_N: &str = "-(3/4*n*sin(theta) + tan(theta)/(2*n))";
    /// n° 15, minimum of s: n0 and s0 (text; the table prints tan(theta)*sqrt(2/(3 cos))).
    pub const N0: &str = "-(2/(3*cos(theta)))^(1/2)";
    /// n° 15, s0 as in the text.
    pub const S0: &str = "tan(theta)*(3*cos(theta)/2)^(1/2)";
    /// n° 15, s0 as in the table of variations.
    pub const S0_TABLE: &str = "tan(theta)*(2/(3*cos(theta)))^(1/2)";
    /// n° 15, (D′).
    pub const SKID_OF_N: &str = "1/2*tan(theta) - 1/4*n^2*sin(theta)";
    /// n° 15, (D″): s² on the curve D = d.
    pub const S2_OF_D: &str = "2*sin(theta)*(tan(theta) - 3/2*d)^2/(tan(theta) - 2*d)";
    /// n° 17, (N): s² on E(-s) = 0.
    pub const CURVE_N_S2: &str = "2*sin(theta)/(cos(theta)*(4 - 3*sin(theta)))";
    /// n° 19, (4): theta'' of the linearised stick equations.
    pub const STICK_4: &str = "-2/3*(4*s^2 - g/R)*theta + 4*s/3*M1*time + M";
    /// n° 19, (6) with `h` (the OCR prints "cosh" for cos).
    pub const STICK_6: &str =
        "4*s*M1/(3*h^2)*time + M/h^2 - (M/h^2*cos(h*time) + 4*s*M1/(3*h^3)*sin(h*time))";
    /// n° 19, (6′).
    pub const STICK_6P: &str = "4*s*M1/(3*h^3)*(h*time - sin(h*time)) + M/h^2*(1 - cos(h*time))";
    /// n° 19, (7).
    pub const STICK_7: &str =
        "-2*g/(3*R*h^2)*M1*time - 2*s*M/h^2 + 2*s*(M/h^2*cos(h*time) + 4*s*M1/(3*h^3)*sin(h*time))";
}

fn check(section: &str, id: &str, statement: &str, holds: bool, detail: String) -> Check {
    Check {
        section: section.into(),
        id: id.into(),
        statement: statement.into(),
        holds,
        detail,
        perturbed: None,
    }
}

/// [`check`] with the outcome of the same check on a perturbed derived side
/// ([`crate::falsify`]).
fn checked(
    section: &str,
    id: &str,
    statement: &str,
    holds: bool,
    detail: String,
    perturbed: crate::Perturbed,
) -> Check {
    crate::falsify::with_perturbation(check(section, id, statement, holds, detail), Some(perturbed))
}

/// `derived - factor * printed` vanishes identically (θ functions as stand-ins).
fn compare(
    section: &str,
    id: &str,
    statement: &str,
    derived: &Atom,
    printed: &Atom,
    factor: &Atom,
) -> Check {
    let diff = simplify(&(derived - factor * printed));
    let scale = if *factor == Atom::num(1) { String::new() } else { format!("({factor}) * ") };
    let perturbed = crate::falsify::perturb_one(derived, |d| is_zero(&(d - factor * printed)));
    checked(
        section,
        id,
        statement,
        is_zero(&diff),
        format!(
            "derived: {}; printed: {}; derived - {scale}printed (exact): {}",
            show(derived),
            show(printed),
            show(&diff)
        ),
        perturbed,
    )
}

/// The coefficients of a polynomial in the symbol `v`, lowest degree first (`e` expanded).
pub fn coefficients(e: &Atom, v: &str) -> Vec<Atom> {
    let x = var(v);
    let sym = x.get_symbol().expect("symbol");
    let mut out: Vec<Atom> = Vec::new();
    for (key, coeff) in e.expand().coefficient_list::<u8>(std::slice::from_ref(&x)) {
        let deg = if key == Atom::num(1) {
            0
        } else {
            let d = (&x * &key.derivative(sym) / &key).expand();
            (1..64).find(|k| d == Atom::num(*k as i64)).unwrap_or(0)
        };
        if out.len() <= deg {
            out.resize(deg + 1, Atom::num(0));
        }
        out[deg] = &out[deg] + coeff;
    }
    out.iter().map(|c| c.expand()).collect()
}

/// Rewrites a polynomial even in `v` as a polynomial in `w = v²`.
fn even_to(e: &Atom, v: &str, w: &str) -> Result<Atom> {
    let mut out = Atom::num(0);
    for (k, c) in coefficients(e, v).iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        ensure!(k % 2 == 0, "{} has the odd power {v}^{k}", show(e));
        out += c * var(w).pow(Atom::num((k / 2) as i64));
    }
    Ok(out.expand())
}

/// Numerator (reduced with sin² + cos² = 1) of a rational function of θ, s, n, ...
fn numerator(e: &Atom) -> Atom {
    num_den(e).0
}

/// A polynomial in sin θ, cos θ and s with no odd power of sin θ or s, written in x = cos θ and
/// y = s².
fn to_xy(e: &Atom) -> Result<Atom> {
    let reduced = crate::cas::reduce_trig(e);
    ensure!(
        coefficients(&reduced, "sin_theta").len() <= 1,
        "{} still depends on sin(theta)",
        show(&reduced)
    );
    let ys = even_to(&reduced, "s", "y")?;
    Ok(subst(&ys, "cos_theta", &var("x")).expand())
}

/// A polynomial in sin θ, cos θ with no odd power of cos θ, written in `w` = sin θ.
fn to_sin(e: &Atom, w: &str) -> Result<Atom> {
    let c2 = even_to(&e.expand(), "cos_theta", "ccwx")?;
    let out = subst(&c2, "ccwx", &(Atom::num(1) - sin_t().pow(Atom::num(2))));
    Ok(subst(&out, "sin_theta", &var(w)).expand())
}

/// `derived / printed` when it is a non-zero number, after simplification.
fn constant_ratio(derived: &Atom, printed: &Atom) -> Option<Atom> {
    let r = simplify(&(derived / printed));
    (r.get_all_symbols(false).is_empty() && !r.is_zero()).then_some(r)
}

/// Resultant in `n` of two polynomials in n, sin θ, cos θ, s, d (symbolica's multivariate
/// resultant over ℚ).
pub fn resultant_in_n(a: &Atom, b: &Atom) -> Atom {
    let vars = vec![var("n"), sin_t(), cos_t(), var("s"), var("d")];
    let pa = a.expand().to_polynomial::<_, u16>(&Q, vars.clone());
    let pb = b.expand().to_polynomial::<_, u16>(&Q, vars);
    <RationalField as PolynomialResultant<u16>>::resultant(&pa, &pb, 0).to_expression()
}

/// Resultant of two quadratics $a_2n^2 + a_1n + a_0$, $b_2n^2 + b_1n + b_0$ by the Sylvester
/// determinant written out: $(a_2b_0 - a_0b_2)^2 - (a_2b_1 - a_1b_2)(a_1b_0 - a_0b_1)$.
pub fn sylvester_quadratics(a: &[Atom], b: &[Atom]) -> Atom {
    let t1 = &a[2] * &b[0] - &a[0] * &b[2];
    let t2 = &a[2] * &b[1] - &a[1] * &b[2];
    let t3 = &a[1] * &b[0] - &a[0] * &b[1];
    (&t1 * &t1 - t2 * t3).expand()
}

/// The larger root $(-b + \sqrt{b^2 - 4ac})/(2a)$, $a > 0$, of a quadratic with rational coefficients
/// (lowest degree first), as an exact expression.
fn quadratic_root(c: &[Atom]) -> Atom {
    // Make the leading coefficient positive (the coefficients are rational numbers) so that
    // the + sign gives the larger root.
    let c: Vec<Atom> =
        if c[2].to_string().starts_with('-') { c.iter().map(|a| -a).collect() } else { c.to_vec() };
    let disc = (&c[1] * &c[1] - Atom::num(4) * &c[2] * &c[0]).expand();
    ((-&c[1] + disc.pow(rat(1, 2))) / (Atom::num(2) * &c[2])).expand()
}

fn formula(name: &str, section: &str, description: &str, e: &Atom) -> Formula {
    Formula {
        name: name.into(),
        section: section.into(),
        description: description.into(),
        expr: to_trig(&e.expand()),
    }
}

fn formula_raw(name: &str, section: &str, description: &str, e: Atom) -> Formula {
    Formula { name: name.into(), section: section.into(), description: description.into(), expr: e }
}

/// The derived normalised (E), (S), (D) of n° 12 and p', n' of system (2), taken from the
/// hoop derivation, with θ functions as the polynomial stand-ins.
fn hoop_forms() -> Result<[Atom; 5]> {
    let hoop = crate::derive::hoop::derive().context("hoop derivation")?;
    let get = |name: &str| {
        hoop.formulas
            .iter()
            .find(|f| f.name == name)
            .map(|f| from_trig(&f.expr))
            .ok_or_else(|| anyhow!("the hoop derivation has no output {name}"))
    };
    Ok([
        get("equilibrium_n12")?,
        get("stability_n12")?,
        get("skid_n12")?,
        get("pns_dp")?,
        get("pns_dn")?,
    ])
}

/// Derives the discussion of n° 13–19 and runs its checks.
pub fn derive() -> Result<Derivation> {
    let [e12, s12, d12, dp, dn] = hoop_forms()?;
    let pns = [dp, dn];
    let mut checks = Vec::new();
    let mut formulas = Vec::new();
    let one = Atom::num(1);
    let (x, y, t) = (var("x"), var("y"), var("t"));

    // n° 13: reality curve.
    let ce = coefficients(&e12, "n");
    ensure!(ce.len() == 3 && ce[2] == one, "(E) of n° 12 is not monic quadratic in n");
    let disc_e = numerator(&(&ce[1] * &ce[1] - Atom::num(4) * &ce[0]));
    let reality = to_xy(&disc_e)?;
    let reality_printed = expr(printed::REALITY);
    let k_e = constant_ratio(&reality, &reality_printed);
    let reality_perturbed =
        crate::falsify::perturb_one(&reality, |d| constant_ratio(d, &reality_printed).is_some());
    checks.push(checked(
        "13",
        "reality_curve",
        "the numerator of the discriminant of E(n) written in x = cos(theta), y = s^2 is a constant times the printed (ℰ) x^2 + (2/3)xy - 1",
        k_e.is_some(),
        format!("numerator of b^2 - 4c: {}; in x, y: {}; ratio to printed: {}", show(&disc_e), reality, k_e.as_ref().map_or("not constant".into(), |k| k.to_string())),
        reality_perturbed,
    ));
    let reality_n = k_e.as_ref().map_or(reality.clone(), |k| (&reality / k).expand());

    // n° 14: resultant.
    let e_poly = numerator(&e12);
    let s_poly = numerator(&s12);
    let res = resultant_in_n(&e_poly, &s_poly);
    let syl = sylvester_quadratics(&coefficients(&e_poly, "n"), &coefficients(&s_poly, "n"));
    checks.push(compare("14", "resultant_sylvester", "symbolica's resultant in n of the numerators of E(n) and S(n) equals the Sylvester determinant of the two quadratics", &res, &syl, &one));
    let curve = to_xy(&res)?;
    let curve_printed = expr(printed::CURVE_S);
    let k_s = constant_ratio(&curve, &curve_printed);
    let curve_perturbed =
        crate::falsify::perturb_one(&curve, |d| constant_ratio(d, &curve_printed).is_some());
    checks.push(checked(
        "14",
        "curve_s_memoir",
        "the resultant of E(n) and S(n) in n (numerators, E times 3 sin cos, S times 3), reduced with sin^2 = 1 - x^2, is a constant times the printed (S) of n° 14",
        k_s.is_some(),
        format!("numerators: E: {}; S: {}; resultant in x, y: {}; ratio to printed: {}", show(&e_poly), show(&s_poly), curve, k_s.as_ref().map_or("not constant".into(), |k| k.to_string())),
        curve_perturbed,
    ));
    let curve_n = k_s.as_ref().map_or(curve.clone(), |k| (&curve / k).expand());

    // (S1): discriminant of S(n).
    let cs = coefficients(&s12, "n");
    let disc_s = numerator(&(&cs[1] * &cs[1] - Atom::num(4) * &cs[2] * &cs[0]));
    let s1 = to_xy(&disc_s)?;
    let s1c = coefficients(&s1, "y");
    ensure!(s1c.len() == 2, "(S1) is not linear in y: {s1}");
    let s1_y = simplify(&(-&s1c[0] / &s1c[1]));
    checks.push(compare(
        "14",
        "curve_s1_memoir",
        "the discriminant of S(n) vanishes on y = (3/4) x / (1 + 2x^2), the printed (S1)",
        &s1_y,
        &expr(printed::CURVE_S1_Y),
        &one,
    ));

    // Point B: maximum of y on (S1).
    let (dn, _) = num_den(&s1_y.derivative(x.get_symbol().expect("symbol")));
    let dnc = coefficients(&dn, "x");
    ensure!(dnc.len() == 3 && dnc[1].is_zero(), "dy/dx on (S1) is not even quadratic: {dn}");
    let bx = (-&dnc[0] / &dnc[2]).pow(rat(1, 2)).expand();
    let by = subst(&s1_y, "x", &bx).expand();
    checks.push(compare(
        "14",
        "point_b_memoir",
        "the maximum of y on (S1) is at the printed B: x = sqrt(2)/2, y = 3 sqrt(2)/16",
        &(&bx + &by * var("sgmx")),
        &(expr("2^(1/2)/2") + expr("3*2^(1/2)/16") * var("sgmx")),
        &one,
    ));

    // Point F: (ℰ) ∩ (S1).
    let rc = coefficients(&reality_n, "y");
    let y_e = simplify(&(-&rc[0] / &rc[1]));
    let (fnum, _) = num_den(&(&y_e - &s1_y));
    let ft = even_to(&fnum, "x", "t")?;
    let ftc = coefficients(&ft, "t");
    ensure!(ftc.len() == 3, "the equation of F is not a quadratic in x^2: {ft}");
    let f_t = quadratic_root(&ftc);
    let fx = f_t.pow(rat(1, 2));
    let fy = subst(&s1_y, "x", &fx);
    // t_F (derived) solves the quadratic; perturbed, it does not.
    let solves = |poly: &Atom, root: &Atom| is_zero(&subst(poly, "t", root));
    checks.push(checked(
        "14",
        "point_f_quadratic",
        "(ℰ) and (S1) meet where a quadratic in t = x^2 vanishes; F is its root in (0, 1)",
        solves(&ft, &f_t),
        format!("equation in t: {ft} = 0; t_F = {f_t}; x_F = sqrt(t_F)"),
        crate::falsify::perturb_one(&f_t, |d| solves(&ft, d)),
    ));

    // Points A, D and the tangents.
    let cy = coefficients(&curve_n, "y");
    let on_x1 = subst(&curve_n, "x", &one).expand();
    checks.push(compare("14", "points_a_d", "on x = 1 the curve (S) reduces to 8y(4y - 1) (times the constant): it passes through A (y = 0) and D (y = 1/4)", &on_x1, &expr("8*y*(4*y-1)"), &one));
    let px = curve_n.derivative(x.get_symbol().expect("symbol"));
    let py = curve_n.derivative(y.get_symbol().expect("symbol"));
    let at = |e: &Atom, xv: &Atom, yv: &Atom| subst(&subst(e, "x", xv), "y", yv).expand();
    let slope_a = simplify(&(-at(&px, &one, &Atom::num(0)) / at(&py, &one, &Atom::num(0))));
    checks.push(compare(
        "14",
        "tangent_a_memoir",
        "the slope dy/dx of (S) at A (1, 0) is the printed -3",
        &slope_a,
        &Atom::num(-3),
        &one,
    ));
    let rpx = reality_n.derivative(x.get_symbol().expect("symbol"));
    let rpy = reality_n.derivative(y.get_symbol().expect("symbol"));
    let slope_ea = simplify(&(-at(&rpx, &one, &Atom::num(0)) / at(&rpy, &one, &Atom::num(0))));
    checks.push(compare(
        "14",
        "tangent_a_reality",
        "at A the curve (S) is tangent to (ℰ): same slope",
        &slope_a,
        &slope_ea,
        &one,
    ));
    let slope_d = simplify(&(-at(&px, &one, &rat(1, 4)) / at(&py, &one, &rat(1, 4))));
    // The slope at D is a literal 0: the falsification scales a symbol of the derived (S)
    // before its partial derivatives are taken.
    let horizontal_at_d = |c: &Atom| {
        let cx = c.derivative(x.get_symbol().expect("symbol"));
        let cy = c.derivative(y.get_symbol().expect("symbol"));
        let dy = at(&cy, &one, &rat(1, 4));
        !dy.is_zero() && is_zero(&at(&cx, &one, &rat(1, 4)))
    };
    let perturbed = crate::falsify::perturb_one(&curve_n, horizontal_at_d);
    checks.push(crate::falsify::with_perturbation(
        compare(
            "14",
            "tangent_d_memoir",
            "the tangent of (S) at D (1, 1/4) is horizontal (slope 0), as printed",
            &slope_d,
            &Atom::num(0),
            &one,
        ),
        Some(crate::Perturbed {
            what: format!("{} (the curve (S), before its slope at D is taken)", perturbed.what),
            ..perturbed
        }),
    ));

    // Vertical tangent: discriminant in y, divided by 64 x^2, t = x^2.
    ensure!(cy.len() == 3, "(S) is not quadratic in y");
    let disc_y = (&cy[1] * &cy[1] - Atom::num(4) * &cy[2] * &cy[0]).expand();
    let over = simplify(&(&disc_y / (Atom::num(64) * x.pow(Atom::num(2)))));
    let quartic = even_to(&over, "x", "t")?;
    checks.push(compare("14", "quartic_f_memoir", "the discriminant in y of (S) over 64 x^2 (the memoir's B'^2 - AC over 16 x^2), with t = x^2, is the printed F(t) = 28t^4 - 44t^3 + 15t^2 + 4t - 2", &quartic, &expr(printed::QUARTIC_F), &one));
    let factored = quartic.factor();
    // The quadratic factor: F / (2t - 1)^2, checked exact.
    let quad = simplify(&(&quartic / expr("(2*t-1)^2")));
    let qc = coefficients(&quad, "t");
    ensure!(qc.len() == 3, "F(t) / (2t - 1)^2 is not a quadratic: {quad}");
    let square_times_quad = |f: &Atom| is_zero(&(f - expr("(2*t-1)^2") * &quad));
    checks.push(checked(
        "14",
        "quartic_f_factor",
        "F(t) factored over the rationals (symbolica): a square times an irreducible quadratic",
        square_times_quad(&quartic),
        format!("F(t) = {factored}"),
        crate::falsify::perturb_one(&quartic, square_times_quad),
    ));
    let t_root = quadratic_root(&qc);
    checks.push(checked(
        "14",
        "quartic_f_root",
        "the root of F in (0.8, 1) is the larger root of the quadratic factor, in closed form",
        solves(&quad, &t_root) && solves(&quartic, &t_root),
        format!("quadratic factor {quad}; t = {t_root}"),
        crate::falsify::perturb_one(&t_root, |d| solves(&quartic, d)),
    ));
    let shifted = subst(&quartic, "t", &(&t + &one)).expand();
    checks.push(compare("14", "horner_shift_memoir", "F(1 + u) is the printed 28u^4 + 68u^3 + 51u^2 + 14u + 1 (Carvallo's Horner tableau), u written t", &shifted, &expr(printed::QUARTIC_U), &one));
    let vy = simplify(&(-&cy[1] / (Atom::num(2) * &cy[2])));
    let vprod = simplify(&(&cy[0] / &cy[2]));
    checks.push(compare(
        "14",
        "vertical_product_memoir",
        "the product of the two y roots of (S) is the printed 3(1 + x^2)(1 - x^2)/(16 x^2)",
        &vprod,
        &expr("3*(1+x^2)*(1-x^2)/(16*x^2)"),
        &one,
    ));

    // n° 15: (E'), minimum, (D'), (D'').
    let e_lin = numerator(&e12); // 3 sin cos n^2 + 4 s cos n + 2 sin
    let s_of_n = solve_linear(std::slice::from_ref(&e_lin), &["s"]).remove(0);
    checks.push(compare(
        "15",
        "s_of_n_memoir",
        "(E) solved for s is the printed (E')",
        &s_of_n,
        &from_trig(&expr(printed::S_OF_N)),
        &one,
    ));
    let (dsn, _) = num_den(&s_of_n.derivative(var("n").get_symbol().expect("symbol")));
    let dsc = coefficients(&dsn, "n");
    ensure!(dsc.len() == 3 && dsc[1].is_zero(), "ds/dn is not even quadratic: {dsn}");
    let n0_sq = simplify(&(-&dsc[0] / &dsc[2]));
    checks.push(compare(
        "15",
        "n0_memoir",
        "ds/dn = 0 at n0^2 = 2/(3 cos(theta)), the printed n0 = -sqrt(2/(3 cos(theta)))",
        &n0_sq,
        &expr("2/(3*cos_theta)"),
        &one,
    ));
    let n0 = -expr("(2/(3*cos_theta))^(1/2)");
    let s0 = subst(&s_of_n, "n", &n0);
    let s0_sq = simplify(&(&s0 * &s0));
    let s0_text = from_trig(&expr(printed::S0));
    let s0_table = from_trig(&expr(printed::S0_TABLE));
    checks.push(compare(
        "15",
        "s0_memoir",
        "s at n0 squared is the square of the printed s0 = tan(theta) sqrt(3 cos(theta)/2) (text)",
        &s0_sq,
        &simplify(&(&s0_text * &s0_text)),
        &one,
    ));
    checks.push(compare(
        "15",
        "s0_table_memoir",
        "s at n0 squared is the square of the table's s0 = tan(theta) sqrt(2/(3 cos(theta)))",
        &s0_sq,
        &simplify(&(&s0_table * &s0_table)),
        &one,
    ));
    let skid_of_n = simplify(&subst(&d12, "s", &s_of_n));
    checks.push(compare(
        "15",
        "skid_of_n_memoir",
        "D with s from (E') is the printed (D')",
        &skid_of_n,
        &from_trig(&expr(printed::SKID_OF_N)),
        &one,
    ));
    let d_at_n0 = simplify(&subst(&skid_of_n, "n", &n0));
    checks.push(compare(
        "15",
        "skid_at_n0_memoir",
        "D at n0 is (1/3) tan(theta), as in the table",
        &d_at_n0,
        &expr("sin_theta/(3*cos_theta)"),
        &one,
    ));
    // (D''): resultant in n of (E) and D(n) - d.
    let d_poly = numerator(&(&d12 - var("d")));
    let res_d = resultant_in_n(&e_lin, &d_poly);
    let rdc = coefficients(&res_d, "s");
    ensure!(
        rdc.len() == 3 && rdc[1].is_zero(),
        "the resultant of (E) and (D) is not even quadratic in s"
    );
    let s2_of_d = simplify(&(-&rdc[0] / &rdc[2]));
    checks.push(compare("15", "s2_of_d_memoir", "eliminating n between (E) and (D) = d (resultant in n) gives the printed (D'') s^2 = 2 sin (tan - 3d/2)^2 / (tan - 2d)", &s2_of_d, &from_trig(&expr(printed::S2_OF_D)), &one));

    // n° 17: (N), I; 17 bis: H.
    let e_minus_s = simplify(&subst(&e12, "n", &-var("s")));
    checks.push(compare(
        "17",
        "e_minus_s_memoir",
        "E(-s) is the printed s^2 (1 - 4/(3 sin)) + 2/(3 cos)",
        &e_minus_s,
        &expr("s^2*(1 - 4/(3*sin_theta)) + 2/(3*cos_theta)"),
        &one,
    ));
    let s2_in = |e: &Atom| -> Result<Atom> {
        let (num, _) = num_den(e);
        let c = coefficients(&num, "s");
        ensure!(c.len() == 3 && c[1].is_zero(), "not even quadratic in s: {num}");
        Ok(simplify(&(-&c[0] / &c[2])))
    };
    let n_s2 = s2_in(&e_minus_s)?;
    checks.push(compare(
        "17",
        "curve_n_memoir",
        "E(-s) = 0 is the printed (N) s^2 = 2 sin / (cos (4 - 3 sin))",
        &n_s2,
        &from_trig(&expr(printed::CURVE_N_S2)),
        &one,
    ));
    let e_s2 = {
        // (ℰ) in θ: y = (1 - x^2)/((2/3) x) from the derived reality curve.
        let ry = subst(&y_e, "x", &cos_t());
        simplify(&ry)
    };
    let (contact, _) = num_den(&(&n_s2 - &e_s2));
    let contact_w = to_sin(&contact, "w")?;
    let contact_f = contact_w.factor();
    let double_root = |c: &Atom| {
        is_zero(&subst(c, "w", &rat(2, 3)))
            && is_zero(&subst(
                &c.derivative(var("w").get_symbol().expect("symbol")),
                "w",
                &rat(2, 3),
            ))
    };
    checks.push(checked("17", "point_i_double", "(N) and (ℰ) meet where a polynomial in w = sin(theta) has the double root 2/3 (contact at I, sin = 2/3)", double_root(&contact_w), format!("s^2 on (N) minus s^2 on (ℰ), numerator in w: {contact_f}"), crate::falsify::perturb_one(&contact_w, double_root)));
    let i_s2 =
        simplify(&subst(&subst(&n_s2, "sin_theta", &rat(2, 3)), "cos_theta", &expr("5^(1/2)/3")));
    checks.push(compare(
        "17",
        "point_i_s_memoir",
        "at I, s^2 = 2/sqrt(5) (printed s = sqrt(2/sqrt(5)))",
        &i_s2,
        &expr("2/5^(1/2)"),
        &one,
    ));
    let s_minus_s = simplify(&subst(&s12, "n", &-var("s")));
    let h_s2 = s2_in(&s_minus_s)?;
    let (hnum, _) = num_den(&(&n_s2 - &h_s2));
    let cubic = to_sin(&hnum, "w")?;
    let cubic_c = coefficients(&cubic, "w");
    let lead = cubic_c.last().cloned().unwrap_or_else(|| Atom::num(1));
    let cubic_monic = simplify(&(&cubic / &lead * Atom::num(3)));
    let is_cubic = |h: &Atom| {
        let (num, _) = num_den(&(&n_s2 - h));
        to_sin(&num, "w").is_ok_and(|c| coefficients(&c, "w").len() == 4)
    };
    // Scaling a symbol keeps the degree: the falsification scales s^2 at H by 1 + w/8.
    let perturbed = crate::Perturbed {
        what: "s^2 at H from S(-s) = 0 scaled by 1 + sin(theta)/8".into(),
        holds: is_cubic(&(&h_s2 * (Atom::num(1) + sin_t() * rat(1, 8)))),
    };
    checks.push(checked("17", "point_h_cubic", "eliminating s^2 between E(-s) = 0 and S(-s) = 0 (both linear in s^2) leaves a cubic in w = sin(theta) (the memoir does not print it)", cubic_c.len() == 4, format!("cubic (leading coefficient 3): {cubic_monic} = 0; factored over Q: {}; s^2 at H = {}", cubic_monic.factor(), show(&h_s2)), perturbed));

    // n° 19: stick equations.
    let (mm, mm1) = (var("M"), var("M1"));
    let memoir_sys = [
        expr("4*s*n*cos_theta/3 + n^2*sin_theta*cos_theta + 2*g*sin_theta/(3*R)"),
        expr("-2*p*s/cos_theta"),
    ];
    checks.push(compare(
        "19",
        "stick_system_p",
        "the first equation (2) of n° 19 without the stick is the derived p' of system (2)",
        &pns[0],
        &memoir_sys[0],
        &one,
    ));
    checks.push(compare(
        "19",
        "stick_system_n",
        "the second equation (2) of n° 19 without the stick is the derived n' of system (2)",
        &pns[1],
        &memoir_sys[1],
        &one,
    ));
    // Linearise: sin θ -> θ, cos θ -> 1, p = θ', drop n^2 sin cos (third order).
    let th = var("theta");
    let lin = |e: &Atom| {
        let e = subst(&subst(e, "sin_theta", &th), "cos_theta", &one).expand();
        let nsq = var("n").pow(Atom::num(2)) * &th;
        let c = coefficients(&e, "n");
        let dropped =
            if c.len() > 2 { (&c[2] * var("n").pow(Atom::num(2))).expand() } else { Atom::num(0) };
        let _ = nsq;
        (e - dropped).expand()
    };
    let dp_lin = &lin(&pns[0]) + &mm;
    let dn_lin = &lin(&pns[1]) + &mm1;
    // (3): n = M1 t - 2 s θ solves n' = -2 s θ' + M1 with n(0) = θ(0) = 0.
    let tau = var("time");
    let theta_f = var("thfx");
    let n3 = &mm1 * &tau - Atom::num(2) * var("s") * &theta_f;
    let dn3 = &mm1 - Atom::num(2) * var("s") * var("dthfx");
    let dn_rhs = subst(&dn_lin, "p", &var("dthfx"));
    checks.push(compare(
        "19",
        "stick_3_memoir",
        "(3) n = M1 t - 2 s theta satisfies the linearised n' = -2 s theta' + M1 (s, M1 constant)",
        &dn3,
        &dn_rhs,
        &one,
    ));
    let eq4 = subst(&subst(&dp_lin, "n", &n3), "theta", &theta_f);
    let eq4 = subst(&eq4, "thfx", &th).expand();
    checks.push(compare(
        "19",
        "stick_4_memoir",
        "substituting (3) in the linearised first equation gives the printed (4)",
        &eq4,
        &expr(printed::STICK_4),
        &one,
    ));
    // (5)-(6): h^2 = (2/3)(4s^2 - g/R); (6) solves (4) with θ(0) = θ'(0) = 0.
    let h_val = expr("(2/3*(4*s^2 - g/R))^(1/2)");
    let hs = var("h");
    let sol6 = expr(printed::STICK_6);
    let tsym = tau.get_symbol().expect("symbol");
    let d2 = sol6.derivative(tsym).derivative(tsym);
    let rhs4 = subst(
        &subst(&expr(printed::STICK_4), "theta", &sol6),
        "g",
        &(var("R")
            * (Atom::num(4) * var("s").pow(Atom::num(2)) - rat(3, 2) * hs.pow(Atom::num(2)))),
    );
    let resid = (&d2 - &rhs4).expand();
    let resid0 = subst(&sol6, "time", &Atom::num(0)).expand();
    let resid1 = subst(&sol6.derivative(tsym), "time", &Atom::num(0)).expand();
    // (6) and (6') against the derived (4) (`eq4`, equal to the printed (4) by
    // `stick_4_memoir`): the residual of (4) at a solution theta(time) with g from (5).
    let g5 =
        var("R") * (Atom::num(4) * var("s").pow(Atom::num(2)) - rat(3, 2) * hs.pow(Atom::num(2)));
    let solves_4 = |eq: &Atom, sol: &Atom| {
        let second = sol.derivative(tsym).derivative(tsym);
        let rhs = subst(&subst(eq, "theta", sol), "g", &g5);
        is_zero(&simplify(&(second - rhs)))
            && subst(sol, "time", &Atom::num(0)).expand().is_zero()
            && subst(&sol.derivative(tsym), "time", &Atom::num(0)).expand().is_zero()
    };
    let derived_4 = |what: &str, sol: &Atom| {
        let p = crate::falsify::perturb_one(&eq4, |d| solves_4(d, sol));
        crate::Perturbed {
            what: format!("{} (the derived (4), which {what} must solve)", p.what),
            ..p
        }
    };
    checks.push(checked("19", "stick_6_memoir", "(6) (with cos, the OCR's \"cosh\" read as cos) solves (4) with theta(0) = theta'(0) = 0, where g/R = 4 s^2 - (3/2) h^2 by (5); (4) as printed and as derived (the linearised first equation with (3))", resid.is_zero() && resid0.is_zero() && resid1.is_zero() && solves_4(&eq4, &sol6), format!("residual of the printed (4): {resid}; theta(0) = {resid0}; theta'(0) = {resid1}"), derived_4("(6)", &sol6)));
    let sol6p = expr(printed::STICK_6P);
    let d6p = (&sol6 - &sol6p).expand();
    checks.push(checked(
        "19",
        "stick_6p_memoir",
        "(6') is (6) regrouped, and solves the derived (4) with theta(0) = theta'(0) = 0 (g from (5))",
        d6p.is_zero() && solves_4(&eq4, &sol6p),
        format!("(6) - (6'): {d6p}"),
        derived_4("(6')", &sol6p),
    ));
    // (7) against (3), the solution of the derived n equation (`stick_3_memoir`), with (6).
    let d7_of = |n3: &Atom| {
        let n7 = subst(n3, "thfx", &sol6).expand();
        simplify(&subst(&(&n7 - expr(printed::STICK_7)), "g", &g5).expand())
    };
    let d7 = d7_of(&n3);
    let perturbed = crate::falsify::perturb_one(&n3, |d| is_zero(&d7_of(d)));
    checks.push(checked(
        "19",
        "stick_7_memoir",
        "(3) with (6) is the printed (7), using (5)",
        is_zero(&d7),
        format!("(3) with (6) minus (7): {d7}"),
        crate::Perturbed {
            what: format!("{} (the derived (3), n = M1 t - 2 s theta)", perturbed.what),
            ..perturbed
        },
    ));
    let with_h = |e: &Atom| e.replace(hs.to_pattern()).with(h_val.to_pattern());

    // Formulas.
    formulas.push(formula("reality_curve", "13", "(ℰ) derived: discriminant numerator of E(n) in x = cos(theta), y = s^2, scaled to the printed normalisation (zero on the curve).", &reality_n));
    formulas.push(formula_raw(
        "memoir_reality_curve",
        "13",
        "Printed (ℰ): x^2 + (2/3)xy - 1.",
        reality_printed,
    ));
    formulas.push(formula("curve_s", "14", "(S) derived: resultant of E(n) and S(n) in n, in x, y, divided by its constant ratio to the printed polynomial.", &curve_n));
    formulas.push(formula_raw("memoir_curve_s", "14", "Printed (S) of n° 14.", curve_printed));
    formulas.push(formula("curve_s_raw", "14", "The resultant of the numerators of E(n) (times 3 sin cos) and S(n) (times 3) in n, in x, y, not rescaled.", &curve));
    formulas.push(formula(
        "curve_s1_y",
        "14",
        "(S1) derived: y = s^2 where S(n) has a double root, as a function of x.",
        &s1_y,
    ));
    formulas.push(formula_raw(
        "memoir_curve_s1_y",
        "14",
        "Printed (S1): y = (3/4) x / (1 + 2 x^2).",
        expr(printed::CURVE_S1_Y),
    ));
    formulas.push(formula("reality_y", "13", "(ℰ) solved for y = s^2 as a function of x.", &y_e));
    formulas.push(formula("quartic_f", "14", "F(t) derived: discriminant in y of (S) over 64 x^2, t = x^2 (vertical tangent where it vanishes).", &quartic));
    formulas.push(formula_raw("memoir_quartic_f", "14", "Printed F(t).", expr(printed::QUARTIC_F)));
    formulas.push(formula("quartic_u", "14", "F(1 + u) derived, u written t.", &shifted));
    formulas.push(formula(
        "vertical_y",
        "14",
        "y of the double root of (S) in y at a given x (the vertical tangent's y when F(x^2) = 0).",
        &vy,
    ));
    formulas.push(formula(
        "vertical_t",
        "14",
        "Closed-form root of F(t) in (0.8, 1): larger root of the quadratic factor.",
        &t_root,
    ));
    formulas.push(formula("point_b_x", "14", "Point B: x of the maximum of y on (S1).", &bx));
    formulas.push(formula("point_b_y", "14", "Point B: y.", &by));
    formulas.push(formula("point_f_x", "14", "Point F: x where (ℰ) meets (S1), closed form.", &fx));
    formulas.push(formula("point_f_y", "14", "Point F: y.", &fy));
    formulas.push(formula("tangent_a_slope", "14", "Slope dy/dx of (S) at A.", &slope_a));
    formulas.push(formula("tangent_d_slope", "14", "Slope dy/dx of (S) at D.", &slope_d));
    formulas.push(formula(
        "s_of_n",
        "15",
        "(E') derived: s as a function of theta, n (n° 12 units).",
        &s_of_n,
    ));
    formulas.push(formula_raw("memoir_s_of_n", "15", "Printed (E').", expr(printed::S_OF_N)));
    formulas.push(formula(
        "s0",
        "15",
        "Minimum s0 of s over n at fixed theta (derived, value of (E') at n0).",
        &s0,
    ));
    formulas.push(formula_raw("memoir_s0", "15", "Printed s0 (text).", expr(printed::S0)));
    formulas.push(formula_raw(
        "memoir_s0_table",
        "15",
        "Printed s0 in the table of variations.",
        expr(printed::S0_TABLE),
    ));
    formulas.push(formula(
        "skid_of_n",
        "15",
        "(D') derived: D along (E) as a function of theta, n.",
        &skid_of_n,
    ));
    formulas.push(formula_raw("memoir_skid_of_n", "15", "Printed (D').", expr(printed::SKID_OF_N)));
    formulas.push(formula(
        "s2_of_d",
        "15",
        "(D'') derived: s^2 on the curve D = d, from the resultant of (E) and (D) in n.",
        &s2_of_d,
    ));
    formulas.push(formula_raw("memoir_s2_of_d", "15", "Printed (D'').", expr(printed::S2_OF_D)));
    formulas.push(formula("curve_n_s2", "17", "(N) derived: s^2 where E(-s) = 0.", &n_s2));
    formulas.push(formula_raw(
        "memoir_curve_n_s2",
        "17",
        "Printed (N).",
        expr(printed::CURVE_N_S2),
    ));
    formulas.push(formula("reality_s2", "13", "(ℰ) in theta: s^2 = 3 sin^2 / (2 cos).", &e_s2));
    formulas.push(formula("h_s2", "17", "s^2 where S(-s) = 0 (n° 17 bis).", &h_s2));
    formulas.push(formula("h_cubic", "17", "Cubic in sin(theta) (written in sin(theta)) whose root in (0, 1) is H (n° 17 bis), leading coefficient 3.", &subst(&cubic_monic, "w", &sin_t())));
    formulas.push(formula("stick_theta", "19", "(6): theta(t) of the linearised stick equations, h = sqrt((2/3)(4s^2 - g/R)) (physical units).", &with_h(&sol6)));
    formulas.push(formula(
        "stick_n",
        "19",
        "(7): n(t) of the linearised stick equations (physical units).",
        &with_h(&expr(printed::STICK_7)),
    ));
    formulas.push(formula("stick_dp", "19", "Linearised theta'' with the stick moment M (first equation (2) of n° 19, sin -> theta, cos -> 1, n^2 term dropped).", &dp_lin));
    formulas.push(formula(
        "stick_dn",
        "19",
        "Linearised n' with the stick moment M1, in theta, p.",
        &dn_lin,
    ));
    formulas.push(formula(
        "stick_full_dp",
        "19",
        "Full first equation (2) of n° 19: derived p' plus M.",
        &(&pns[0] + &mm),
    ));
    formulas.push(formula(
        "stick_full_dn",
        "19",
        "Full second equation (2) of n° 19: derived n' plus M1.",
        &(&pns[1] + &mm1),
    ));
    let _ = &t;
    let mut inputs: Vec<String> = INPUTS.iter().map(|s| s.to_string()).collect();
    inputs.push("p".into());
    Ok(Derivation {
        model: "hoop_discussion".into(),
        source: file!().to_string(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs,
        formulas,
        checks,
        nominal: crate::derive::nominal::values("hoop_discussion"),
        horner_schemes: Vec::new(),
    })
}
