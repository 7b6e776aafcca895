//! Geometry of the bicycle (memoir Part II, ch. I, n° 43–58), derived with symbolica: the
//! position of the front contact point M in the rear wheel's trihedra OIJK and OIjk (n° 46–47),
//! the two contact equations $K|OM = 0$ and $K|\frac{dOM}{d\mu} = 0$ (n° 45 and 48), their
//! transformed forms of n° 49–50, the first-order method of n° 51, the ground coordinates of M
//! (n° 54), the accessory angles α, β (n° 57) and the front wheel's axes (n° 58).
//!
//! The specific constants are $R, l, c, \sigma_0$ (n° 44), with $a = l\cos\sigma_0 - c$ and
//! $b = l\sin\sigma_0$ from the relations (a), (b); the position parameters are the lean θ, the
//! steer γ, the frame angle σ and the contact parameter μ (called η and ω from n° 58 bis on).
//!
//! Inside the derivation every angle $x$ is a pair of polynomial stand-ins $\sin x, \cos x$
//! (θ keeps the stand-ins of [`crate::frame`], so that its trihedra can be reused). Equalities
//! are decided exactly by [`is_zero_mod`]: both sides are brought to one fraction and the
//! numerator is reduced by a triangular set of rules $x^2 \to r(x)$, first the normalisers and
//! half angles ($W^2 = \cos^2\sigma + \sin^2\sigma\cos^2\gamma$ for the lowest-point condition,
//! $\sin^2\frac{\gamma}{2} = \frac{1 - \cos\gamma}{2}$, ...), then $\sin^2 x = 1 - \cos^2 x$ for
//! every angle. Each rule eliminates its own leading symbol and its right side holds only
//! symbols reduced later, so the normal form is unique and the test is exact.
//!
//! [`derive`] returns the residuals of the two contact equations and their Jacobian with respect
//! to (σ, μ), for the Newton solver of the runtime, and the other formulas listed in
//! `generated/bicycle_geometry.md`, with every check made on the way.

use anyhow::{ensure, Result};
use symbolica::atom::{Atom, AtomCore};
use symbolica::domains::integer::Z;
use symbolica::domains::rational::Q;

use crate::cas::{cos_t, expr, monomial_degree, sin_t, var};
use crate::mechanics::frame::{Trihedron, Vector};
use crate::{Check, Derivation, Formula};

/// Parameter names of the geometry model, in order: the specific constants of n° 44.
pub const PARAMS: [&str; 4] = ["R", "l", "c", "sigma0"];
/// Input names of the geometry model, in order.
pub const INPUTS: [&str; 4] = ["theta", "gamma", "sigma", "mu"];

/// The angles that have stand-ins, with the names of their sine and cosine stand-ins.
const ANGLES: [(&str, &str, &str); 8] = [
    ("theta", "sin_theta", "cos_theta"),
    ("gamma", "sin_gamma", "cos_gamma"),
    ("sigma", "sin_sigma", "cos_sigma"),
    ("mu", "sin_mu", "cos_mu"),
    ("sigma0", "sin_sigma0", "cos_sigma0"),
    ("tau0", "sin_tau0", "cos_tau0"),
    ("alpha", "sin_alpha", "cos_alpha"),
    ("beta", "sin_beta", "cos_beta"),
];

/// $(\sin x, \cos x)$ stand-ins of the angle `name`.
///
/// # Panics
/// Panics when `name` is not one of the model's angles (callers pass literals).
pub fn sc(name: &str) -> (Atom, Atom) {
    let (_, s, c) = ANGLES.iter().find(|(n, _, _)| *n == name).expect("a known angle");
    (var(s), var(c))
}

fn sin(name: &str) -> Atom {
    sc(name).0
}

fn cos(name: &str) -> Atom {
    sc(name).1
}

/// $\sin\frac{\gamma}{2}$ stand-in (it only ever appears squared).
fn half_gamma() -> Atom {
    var("sin_half_gamma")
}

/// $\sin\frac{\tau_0}{2}$ stand-in (it only ever appears squared).
fn half_tau0() -> Atom {
    var("sin_half_tau0")
}

/// Normaliser of the lowest-point condition of n° 50: $W = \cos\tau$ at θ = 0.
pub fn w50() -> Atom {
    var("W")
}

/// Normaliser of n° 57–58: $\cos\beta = \sqrt{CN_I^2 + CN_J^2}$.
pub fn wb() -> Atom {
    var("Wb")
}

/// The reduction rules $x^2 \to r$, in the order they are applied (module docs).
fn rules() -> Vec<(Atom, Atom)> {
    let one = Atom::num(1);
    let two = Atom::num(2);
    let sq = |e: &Atom| e.pow(Atom::num(2));
    let [ci, cj, _] = normal_components();
    let mut r = vec![
        (w50(), sq(&cos("sigma")) + sq(&sin("sigma")) * sq(&cos("gamma"))),
        (wb(), sq(&ci) + sq(&cj)),
        (half_gamma(), (&one - cos("gamma")) / &two),
        (half_tau0(), (&one - cos("tau0")) / &two),
        (cos("tau0"), &one - sq(&sin("sigma0")) * sq(&sin("gamma"))),
    ];
    for (name, _, _) in ANGLES {
        if name != "tau0" {
            r.push((sin(name), &one - sq(&cos(name))));
        }
    }
    r
}

fn reduce_rule(e: &Atom, x: &Atom, rhs: &Atom) -> Atom {
    let Some(sym) = x.get_symbol() else { return e.clone() };
    let expanded = e.expand();
    if !expanded.contains_symbol(sym) {
        return expanded;
    }
    let mut out = Atom::num(0);
    for (key, coeff) in expanded.coefficient_list::<u8>(std::slice::from_ref(x)) {
        let k = monomial_degree(&key, x).unwrap_or(0);
        let mut term = coeff * rhs.pow(Atom::num((k / 2) as i64));
        if k % 2 == 1 {
            term *= x;
        }
        out += term;
    }
    out.expand()
}

/// Reduces a polynomial by the rules of the module docs (exact normal form).
pub fn reduce(e: &Atom) -> Atom {
    rules().iter().fold(e.expand(), |acc, (x, rhs)| reduce_rule(&acc, x, rhs))
}

/// Exact test that the rational function `e` vanishes modulo the relations (module docs).
pub fn is_zero_mod(e: &Atom) -> bool {
    let rp = e.expand().to_rational_polynomial::<_, _, u16>(&Q, &Z, ());
    reduce(&rp.numerator.to_expression()).is_zero()
}

/// Derivative with respect to the angle `name` through its stand-ins:
/// $\partial_x = \cos x\,\partial_{\sin x} - \sin x\,\partial_{\cos x}$.
pub fn d_angle(e: &Atom, name: &str) -> Atom {
    let (s, c) = sc(name);
    let ds = e.derivative(s.get_symbol().expect("symbol"));
    let dc = e.derivative(c.get_symbol().expect("symbol"));
    ds * &c - dc * &s
}

/// Replaces the stand-ins by `sin(x)`, `cos(x)` of the inputs and parameters (θ, γ, σ, μ,
/// σ0), for the emitted formulas.
pub fn to_trig(e: &Atom) -> Atom {
    let mut out = crate::cas::to_trig(e);
    for (name, s, c) in &ANGLES[1..5] {
        out = out
            .replace(var(s).to_pattern())
            .with(expr(&format!("sin({name})")).to_pattern())
            .replace(var(c).to_pattern())
            .with(expr(&format!("cos({name})")).to_pattern());
    }
    out
}

/// Reads a printed formula: `tan(x)`, `sin(x)`, `cos(x)` of every angle, `sin(gamma/2)`,
/// `sin(tau0/2)` and `sin(sigma1)`, `cos(sigma1)` ($\sigma_1 = \sigma - \sigma_0$) become the
/// stand-ins.
pub fn from_printed(text: &str) -> Atom {
    let mut e = expr(text);
    let rep =
        |e: Atom, from: &str, to: &Atom| e.replace(expr(from).to_pattern()).with(to.to_pattern());
    let (s0, c0) = sc("sigma0");
    let (ss, cs) = sc("sigma");
    e = rep(e, "sin(sigma1)", &(&ss * &c0 - &cs * &s0));
    e = rep(e, "cos(sigma1)", &(&cs * &c0 + &ss * &s0));
    e = rep(e, "sin(gamma/2)", &half_gamma());
    e = rep(e, "sin(tau0/2)", &half_tau0());
    for (name, s, c) in ANGLES {
        e = rep(e, &format!("tan({name})"), &(var(s) / var(c)));
        e = rep(e, &format!("sin({name})"), &var(s));
        e = rep(e, &format!("cos({name})"), &var(c));
    }
    e
}

/// Shows a stand-in expression with `sin(x)`, `cos(x)`.
pub fn show(e: &Atom) -> String {
    let mut s = to_trig(e);
    for (name, sn, cn) in &ANGLES[5..] {
        s = s
            .replace(var(sn).to_pattern())
            .with(expr(&format!("sin({name})")).to_pattern())
            .replace(var(cn).to_pattern())
            .with(expr(&format!("cos({name})")).to_pattern());
    }
    s.to_string()
}

/// The `i`-th unit vector of OIJK.
pub fn ijk(i: usize) -> Vector {
    Vector::unit(Trihedron::IJK, i)
}

/// The `i`-th unit vector of OIjk.
pub fn ijk_small(i: usize) -> Vector {
    Vector::unit(Trihedron::Ijk, i)
}

/// $H = I\cos\sigma + k\sin\sigma$: normal to the steering axis, forward, in the frame's plane
/// (n° 44, 47), on I, J, K.
pub fn h() -> Vector {
    ijk(0).scale(&cos("sigma")).add(&ijk_small(2).scale(&sin("sigma")))
}

/// $G = -I\sin\sigma + k\cos\sigma$: the steering axis, upwards (n° 44, 47).
pub fn g() -> Vector {
    ijk(0).scale(&-sin("sigma")).add(&ijk_small(2).scale(&cos("sigma")))
}

/// $H_1 = H\cos\gamma + j\sin\gamma$: H turned by the steer γ about G (n° 44, 47).
pub fn h1() -> Vector {
    h().scale(&cos("gamma")).add(&ijk_small(1).scale(&sin("gamma")))
}

/// $a = l\cos\sigma_0 - c$ (relation (a) of n° 44).
pub fn a_const() -> Atom {
    var("l") * cos("sigma0") - var("c")
}

/// $b = l\sin\sigma_0$ (relation (b) of n° 44).
pub fn b_const() -> Atom {
    var("l") * sin("sigma0")
}

/// $CM = -R(H_1\sin\mu + G\cos\mu)$ (n° 46).
pub fn cm() -> Vector {
    h1().scale(&sin("mu")).add(&g().scale(&cos("mu"))).scale(&-var("R"))
}

/// $OM = OS + SA + AB + BC + CM$ with $OS = Rk$, $SA = aH$, $AB = -bG$, $BC = cH_1$ (n° 46),
/// with the letters `a`, `b` left symbolic.
pub fn om_ab() -> Vector {
    ijk_small(2)
        .scale(&var("R"))
        .add(&h().scale(&var("a")))
        .add(&g().scale(&-var("b")))
        .add(&h1().scale(&var("c")))
        .add(&cm())
}

/// `e` with a, b replaced by their values (a), (b) of n° 44.
pub fn with_ab(e: &Atom) -> Atom {
    e.replace(var("a").to_pattern())
        .with(a_const().to_pattern())
        .replace(var("b").to_pattern())
        .with(b_const().to_pattern())
}

/// The unit normal $CN = |H_1 G$ to the front wheel (n° 57), on I, J, K.
pub fn normal_components() -> [Atom; 3] {
    let n = h1().cross(&g()).to(Trihedron::IJK);
    n.comps.map(|x| x.expand())
}

/// A [`Check`] that `diff` vanishes by [`is_zero_mod`], its detail ending with the reduced
/// numerator of the difference. `derived` is the derived side of the difference (its first
/// term, `diff` = `derived` − expected, or `diff` itself for a quantity that must vanish): the
/// check is run again with `derived` perturbed ([`crate::falsify`]) and the expected side kept.
pub fn check(
    section: &str,
    id: &str,
    statement: &str,
    derived: &Atom,
    diff: &Atom,
    detail: String,
) -> Check {
    let holds = is_zero_mod(diff);
    let perturbed = crate::falsify::perturb_derived(derived, diff, is_zero_mod);
    let rp = diff.expand().to_rational_polynomial::<_, _, u16>(&Q, &Z, ());
    let reduced = reduce(&rp.numerator.to_expression());
    let mut shown = show(&reduced);
    if shown.len() > 300 {
        shown = format!("{} terms", reduced.nterms());
    }
    Check {
        perturbed: Some(perturbed),
        section: section.into(),
        id: id.into(),
        statement: statement.into(),
        holds,
        detail: format!("{detail}; numerator of the difference, reduced: {shown}"),
    }
}

fn compare(section: &str, id: &str, statement: &str, derived: &Atom, printed: &str) -> Check {
    let p = from_printed(printed);
    check(
        section,
        id,
        statement,
        derived,
        &(derived - &p),
        format!("printed: {printed}; derived: {}", {
            let s = show(derived);
            if s.len() > 300 {
                format!("{} terms", derived.expand().nterms())
            } else {
                s
            }
        }),
    )
}

fn compare_vec(
    section: &str,
    id: &str,
    statement: &str,
    derived: &Vector,
    printed: [&str; 3],
) -> Check {
    let d = derived.to(Trihedron::IJK);
    let diffs: Vec<Atom> = (0..3).map(|i| &d.comps[i] - from_printed(printed[i])).collect();
    let holds = diffs.iter().all(is_zero_mod);
    let perturbed = crate::falsify::perturb(&d.comps, |dd| {
        (0..3).all(|i| is_zero_mod(&(&dd[i] - from_printed(printed[i]))))
    });
    Check {
        perturbed: Some(perturbed),
        section: section.into(),
        id: id.into(),
        statement: statement.into(),
        holds,
        detail: format!(
            "printed on I, J, K: [{}]; differences reduced: [{}]",
            printed.join(", "),
            diffs.iter().map(|x| show(&reduce(&x.expand()))).collect::<Vec<_>>().join(", ")
        ),
    }
}

/// A [`Formula`] with the stand-ins replaced by `sin(x)`, `cos(x)` ([`to_trig`]).
pub fn formula(name: &str, section: &str, description: &str, e: &Atom) -> Formula {
    Formula {
        name: name.into(),
        section: section.into(),
        description: description.into(),
        expr: to_trig(e),
    }
}

/// `e` at θ = 0 (the frame vertical).
pub fn zero_theta(e: &Atom) -> Atom {
    e.replace(sin_t().to_pattern())
        .with(Atom::num(0).to_pattern())
        .replace(cos_t().to_pattern())
        .with(Atom::num(1).to_pattern())
}

fn at_sigma0(e: &Atom) -> Atom {
    let (s, c) = sc("sigma");
    let (s0, c0) = sc("sigma0");
    e.replace(s.to_pattern()).with(s0.to_pattern()).replace(c.to_pattern()).with(c0.to_pattern())
}

/// `e` with every occurrence of `x` replaced by `v`.
pub fn subst(e: &Atom, x: &Atom, v: &Atom) -> Atom {
    e.replace(x.to_pattern()).with(v.to_pattern())
}

/// The square of `e`.
pub fn sq(e: &Atom) -> Atom {
    e.pow(Atom::num(2))
}

/// Derives every geometry formula and runs the checks.
pub fn derive() -> Result<Derivation> {
    let mut checks = Vec::new();
    let (r_, l_, c_) = (var("R"), var("l"), var("c"));
    let one = Atom::num(1);
    let two = Atom::num(2);
    let k_big = ijk(2);

    // n° 47: the remarkable directions on I, J, K.
    checks.push(compare_vec(
        "47",
        "direction_h_47",
        "H = I cos(sigma) + k sin(sigma) on I, J, K is the printed expansion",
        &h(),
        ["cos(sigma)", "-sin(theta)*sin(sigma)", "cos(theta)*sin(sigma)"],
    ));
    checks.push(compare_vec(
        "47",
        "direction_g_47",
        "G = -I sin(sigma) + k cos(sigma) on I, J, K is the printed expansion",
        &g(),
        ["-sin(sigma)", "-sin(theta)*cos(sigma)", "cos(theta)*cos(sigma)"],
    ));
    checks.push(compare_vec(
        "47",
        "direction_h1_47",
        "H1 = H cos(gamma) + j sin(gamma) on I, J, K is the printed expansion",
        &h1(),
        [
            "cos(sigma)*cos(gamma)",
            "cos(theta)*sin(gamma) - sin(theta)*cos(gamma)*sin(sigma)",
            "sin(theta)*sin(gamma) + cos(theta)*cos(gamma)*sin(sigma)",
        ],
    ));
    let orth = [h().dot(&g()), h1().dot(&g()), h1().dot(&h1()) - &one, g().dot(&g()) - &one];
    // The derived side: G's components (as G|G - 1 and the products use them), G scaled.
    let orth_perturbed = crate::Perturbed {
        what: format!("the derived direction G scaled by {}", crate::falsify::FACTOR),
        holds: {
            let gs = g().scale(&crate::falsify::factor());
            is_zero_mod(&h().dot(&gs)) && is_zero_mod(&(gs.dot(&gs) - &one))
        },
    };
    checks.push(Check {
        perturbed: Some(orth_perturbed),
        section: "47".into(),
        id: "directions_orthonormal_47".into(),
        statement: "H, G, H1 are unit vectors and G is normal to H and to H1".into(),
        holds: orth.iter().all(is_zero_mod),
        detail: "H|G, H1|G, H1|H1 - 1, G|G - 1 reduced to 0 with sin^2 + cos^2 = 1".into(),
    });

    // n° 46: OM.
    let om = om_ab().to(Trihedron::IJK);
    let printed_om = ijk_small(2)
        .scale(&r_)
        .add(&h().scale(&var("a")))
        .add(&g().scale(&-(var("b") + &r_ * cos("mu"))))
        .add(&h1().scale(&(&c_ - &r_ * sin("mu"))));
    let d_om = om.sub(&printed_om);
    let om_perturbed = crate::falsify::perturb(&om.comps, |d| {
        (0..3).all(|i| is_zero_mod(&(&d[i] - &printed_om.comps[i])))
    });
    checks.push(Check {
        perturbed: Some(om_perturbed),
        section: "46".into(),
        id: "om_46".into(),
        statement: "OS + SA + AB + BC + CM is the printed OM = Rk + aH - (b + R cos mu)G + (c - R sin mu)H1".into(),
        holds: d_om.comps.iter().all(is_zero_mod),
        detail: "the three components of the difference reduce to 0".into(),
    });
    let sc_upright = h().scale(&a_const()).add(&g().scale(&-b_const())).add(&h().scale(&c_));
    let sc_upright = sc_upright.map(|e| at_sigma0(&zero_theta(e)));
    let ab_perturbed = crate::falsify::perturb(&sc_upright.comps, |d| {
        is_zero_mod(&(&d[0] - &l_)) && is_zero_mod(&d[1]) && is_zero_mod(&d[2])
    });
    checks.push(Check {
        perturbed: Some(ab_perturbed),
        section: "44".into(),
        id: "relations_ab_44".into(),
        statement: "with (a) a + c = l cos(sigma0) and (b) b = l sin(sigma0), SA + AB + BC = l I in the normal position (theta = gamma = 0, sigma = sigma0)".into(),
        holds: is_zero_mod(&(&sc_upright.comps[0] - &l_))
            && is_zero_mod(&sc_upright.comps[1])
            && is_zero_mod(&sc_upright.comps[2]),
        detail: format!(
            "components {}, {}, {}",
            show(&reduce(&sc_upright.comps[0])),
            show(&reduce(&sc_upright.comps[1])),
            show(&reduce(&sc_upright.comps[2]))
        ),
    });

    // n° 48: the two equations of the problem.
    let eq1_ab = om.dot(&k_big).expand();
    checks.push(compare(
        "48",
        "equation_1_48",
        "K|OM is the printed first member of (1) of n° 48",
        &eq1_ab,
        "R*cos(theta) + a*cos(theta)*sin(sigma) - b*cos(theta)*cos(sigma) + c*(sin(theta)*sin(gamma) + cos(theta)*cos(gamma)*sin(sigma)) - R*sin(mu)*(sin(theta)*sin(gamma) + cos(theta)*cos(gamma)*sin(sigma)) - R*cos(mu)*cos(theta)*cos(sigma)",
    ));
    let d_cm = h1().scale(&cos("mu")).sub(&g().scale(&sin("mu"))).scale(&-r_.clone());
    let eq2_vec = d_cm.dot(&k_big).expand();
    let eq2_ab = d_angle(&eq1_ab, "mu").expand();
    checks.push(check(
        "48",
        "equation_2_derivative_48",
        "K|dOM/dmu (dOM/dmu = dCM/dmu = -R(H1 cos mu - G sin mu)) is the derivative of K|OM with respect to mu",
        &eq2_vec,
        &(&eq2_vec - &eq2_ab),
        "derivative of the dot product vs dot product of the derivative".into(),
    ));
    checks.push(compare(
        "48",
        "equation_2_48",
        "K|dOM/dmu is the printed second equation of n° 48",
        &eq2_ab,
        "-R*cos(mu)*(sin(theta)*sin(gamma) + cos(theta)*cos(gamma)*sin(sigma)) + R*sin(mu)*cos(theta)*cos(sigma)",
    ));
    let tan_mu_rhs = from_printed("tan(sigma)*cos(gamma) + tan(theta)*sin(gamma)/cos(sigma)");
    checks.push(check(
        "48",
        "tan_mu_48",
        "K|dOM/dmu = 0 is the printed (2): tan mu = tan sigma cos gamma + tan theta sin gamma / cos sigma (K|dOM/dmu = R cos(mu) cos(theta) cos(sigma) (tan mu - right side))",
        &eq2_ab,
        &(&eq2_ab - &r_ * cos("mu") * cos_t() * cos("sigma") * (sin("mu") / cos("mu") - &tan_mu_rhs)),
        "printed (2): tan(mu) = tan(sigma)*cos(gamma) + tan(theta)*sin(gamma)/cos(sigma)".into(),
    ));

    // n° 49: ordered by theta, then with (a), (b).
    let eq1_ordered = &eq1_ab / cos_t();
    checks.push(compare(
        "49",
        "equation_1_ordered_49",
        "K|OM / cos(theta) is the first printed form of n° 49, ordered by theta",
        &eq1_ordered,
        "(a + c*cos(gamma))*sin(sigma) - b*cos(sigma) + R*(1 - cos(gamma)*sin(sigma)*sin(mu) - cos(sigma)*cos(mu)) + tan(theta)*sin(gamma)*(c - R*sin(mu))",
    ));
    checks.push(compare(
        "49",
        "first_terms_49",
        "with (a), (b) the two first terms (a + c cos gamma) sin sigma - b cos sigma become the printed l (cos sigma0 sin sigma - cos sigma sin sigma0) + c (cos gamma - 1) sin sigma",
        &with_ab(&((var("a") + &c_ * cos("gamma")) * sin("sigma") - var("b") * cos("sigma"))),
        "l*(cos(sigma0)*sin(sigma) - cos(sigma)*sin(sigma0)) + c*(cos(gamma) - 1)*sin(sigma)",
    ));
    let eq1 = with_ab(&eq1_ab).expand();
    let eq2 = with_ab(&eq2_ab).expand();
    checks.push(compare(
        "49",
        "equation_1_final_49",
        "K|OM / cos(theta) with (a), (b) is the final printed (1) of n° 49 (sigma1 = sigma - sigma0)",
        &(&eq1 / cos_t()),
        "l*sin(sigma1) - 2*c*sin(gamma/2)^2*sin(sigma) + R*(1 - cos(sigma)*cos(mu) - sin(sigma)*sin(mu)*cos(gamma)) + tan(theta)*sin(gamma)*(c - R*sin(mu))",
    ));

    // n° 50: the frame vertical.
    let cos_km = -(cm().dot(&k_big)) / &r_;
    checks.push(compare(
        "50",
        "cos_km_50",
        "at theta = 0 the cosine of the angle K'M of the spherical triangle (between -K and CM) is the printed cos sigma cos mu + sin sigma sin mu cos gamma",
        &zero_theta(&cos_km.expand()),
        "cos(sigma)*cos(mu) + sin(sigma)*sin(mu)*cos(gamma)",
    ));
    // Lowest point at theta = 0: cos mu = cos sigma / W, sin mu = sin sigma cos gamma / W.
    let lowest0 = |e: &Atom| {
        subst(
            &subst(&zero_theta(e), &cos("mu"), &(cos("sigma") / w50())),
            &sin("mu"),
            &(sin("sigma") * cos("gamma") / w50()),
        )
    };
    // The substitution leaves a literal 0: the falsification scales a symbol of the derived
    // K|dOM/dmu before it.
    let perturbed = crate::falsify::perturb_one(&eq2, |d| is_zero_mod(&lowest0(d)));
    checks.push(crate::falsify::with_perturbation(
        check(
            "50",
            "lowest_point_50",
            "at theta = 0 the point with cos mu = cos sigma / W, sin mu = sin sigma cos gamma / W (W^2 = cos^2 sigma + sin^2 sigma cos^2 gamma) satisfies K|dOM/dmu = 0",
            &lowest0(&eq2),
            &lowest0(&eq2),
            "W reduced with W^2 = cos^2 sigma + sin^2 sigma cos^2 gamma".into(),
        ),
        Some(crate::Perturbed { what: format!("{} (K|dOM/dmu before the lowest point is put in)", perturbed.what), ..perturbed }),
    ));
    let cos_tau = lowest0(&zero_theta(&cos_km.expand()));
    checks.push(check(
        "50",
        "sin_tau_50",
        "at the lowest point (theta = 0) cos tau = cos K'M satisfies cos^2 tau = 1 - (sin sigma sin gamma)^2, the printed (3) sin tau = sin sigma sin gamma",
        &(sq(&cos_tau) + sq(&(sin("sigma") * sin("gamma")))),
        &(sq(&cos_tau) + sq(&(sin("sigma") * sin("gamma"))) - &one),
        "cos tau reduces to W, and W^2 + sin^2 sigma sin^2 gamma = 1".into(),
    ));
    checks.push(check(
        "50",
        "cos_tau_positive_50",
        "at the lowest point cos tau = W (the positive root), so tau is in (-pi/2, pi/2)",
        &cos_tau,
        &(&cos_tau - w50()),
        "cos tau - W".into(),
    ));
    let tau_c = var("cos_tau");
    let eq2_50 =
        from_printed("l*sin(sigma1) - 2*c*sin(gamma/2)^2*sin(sigma)") + &r_ * (&one - &tau_c);
    checks.push(check(
        "50",
        "equation_2_50",
        "at theta = 0, with cos tau = cos K'M, K|OM is the printed (2) of n° 50: R(1 - cos tau) + l sin sigma1 - 2c sin^2(gamma/2) sin sigma",
        &(zero_theta(&eq1)),
        &(zero_theta(&eq1) - subst(&eq2_50, &tau_c, &zero_theta(&cos_km.expand()))),
        "(2) of n° 50 with cos tau replaced by cos K'M".into(),
    ));

    // n° 51: first order in sigma1 about sigma0. F(sigma, tau) = (2) of n° 50, tau(sigma) from
    // sin tau = sin sigma sin gamma; dF/dsigma = F_sigma + F_tau dtau/dsigma with
    // cos tau dtau/dsigma = d(sin sigma sin gamma)/dsigma.
    let (st, ct) = (var("sin_tau"), var("cos_tau"));
    let f50 = subst(&eq2_50, &tau_c, &ct);
    let tau_rel = sin("sigma") * sin("gamma");
    let dtau = d_angle(&tau_rel, "sigma") / &ct;
    let f_tau = -(f50.derivative(ct.get_symbol().expect("symbol"))) * &st; // dF/dtau via cos tau
    let df = d_angle(&f50, "sigma") + &f_tau * &dtau;
    let at0 = |e: &Atom| {
        let e = subst(&at_sigma0(e), &st, &sin("tau0"));
        let e = subst(&e, &ct, &cos("tau0"));
        subst(&e, &sin("tau0"), &(sin("sigma0") * sin("gamma")))
    };
    // sin(sigma1) = 0 at sigma = sigma0.
    let f0 = at0(&f50);
    let df0 = at0(&df);
    checks.push(check(
        "51",
        "tau1_51",
        "the first-order increment of (3) is the printed (3)' tau1 cos tau0 = sigma1 cos sigma0 sin gamma",
        &(at0(&(&dtau * &ct))),
        &(at0(&(&dtau * &ct)) - cos("sigma0") * sin("gamma")),
        "dtau/dsigma cos tau at sigma0".into(),
    ));
    let printed_const = from_printed("2*R*sin(tau0/2)^2 - 2*c*sin(gamma/2)^2*sin(sigma0)");
    checks.push(check(
        "51",
        "first_order_constant_51",
        "the constant term of (2) expanded about sigma0 is the printed 2R sin^2(tau0/2) - 2c sin^2(gamma/2) sin sigma0",
        &f0,
        &(&f0 - subst(&printed_const, &sin("tau0"), &(sin("sigma0") * sin("gamma")))),
        format!("derived: {}", show(&f0)),
    ));
    let printed_coef = "R*tan(tau0)*sin(sigma0)*sin(gamma) + l - 2*c*sin(gamma/2)^2*cos(sigma0)";
    let coef_as_printed =
        subst(&from_printed(printed_coef), &sin("tau0"), &(sin("sigma0") * sin("gamma")));
    checks.push(check(
        "51",
        "first_order_coefficient_51_as_printed",
        "the coefficient of sigma1 in (2)' is the printed R tan tau0 sin sigma0 sin gamma + l - 2c sin^2(gamma/2) cos sigma0",
        &df0,
        &(&df0 - &coef_as_printed),
        format!(
            "derived: {}; the derivation gives R tan tau0 cos sigma0 sin gamma (tau1 cos tau0 = sigma1 cos sigma0 sin gamma, (3)'), the print has sin sigma0",
            show(&df0)
        ),
    ));
    let coef_read = subst(
        &from_printed("R*tan(tau0)*cos(sigma0)*sin(gamma) + l - 2*c*sin(gamma/2)^2*cos(sigma0)"),
        &sin("tau0"),
        &(sin("sigma0") * sin("gamma")),
    );
    checks.push(check(
        "51",
        "first_order_coefficient_51",
        "the coefficient of sigma1 in (2)' is R tan tau0 cos sigma0 sin gamma + l - 2c sin^2(gamma/2) cos sigma0 (the print with cos sigma0 for sin sigma0)",
        &df0,
        &(&df0 - &coef_read),
        "implicit derivative of (2) of n° 50 through (3)".into(),
    ));
    // Emitted first-order formulas: cos tau0 = sqrt(1 - sin^2 sigma0 sin^2 gamma) (|tau0| < pi/2),
    // sin^2(gamma/2) = (1 - cos gamma)/2, sin^2(tau0/2) = (1 - cos tau0)/2.
    let cos_tau0 = (&one - sq(&(sin("sigma0") * sin("gamma")))).pow(Atom::num(1) / Atom::num(2));
    let emit51 = |e: &Atom| {
        let e = subst(e, &half_gamma().pow(Atom::num(2)), &((&one - cos("gamma")) / &two));
        let e = subst(&e, &half_tau0().pow(Atom::num(2)), &((&one - cos("tau0")) / &two));
        subst(&e, &cos("tau0"), &cos_tau0)
    };
    let f0_emit = emit51(&f0);
    let sigma1_first = -&f0_emit / emit51(&df0);
    let sigma1_printed = -&f0_emit / emit51(&coef_as_printed);
    ensure!(
        !f0_emit.contains_symbol(half_gamma().get_symbol().expect("symbol")),
        "sin(gamma/2) left in (2)'"
    );
    let mu1_first = var("sigma1_first") * cos("gamma")
        / (sq(&cos("sigma0")) + sq(&sin("sigma0")) * sq(&cos("gamma")));
    checks.push(check(
        "51",
        "mu1_51",
        "mu1 = sigma1 dmu/dsigma at sigma0 with tan mu = tan sigma cos gamma: dmu/dsigma = cos gamma / (cos^2 sigma + sin^2 sigma cos^2 gamma)",
        &({
            // d/dsigma of atan(tan sigma cos gamma) = cos gamma / cos^2 sigma / (1 + tan^2 sigma cos^2 gamma)
            let t = sin("sigma") / cos("sigma") * cos("gamma");
            let dt = d_angle(&t, "sigma");
            at_sigma0(&(dt / (&one + sq(&t))))
        }),
        &({
            // d/dsigma of atan(tan sigma cos gamma) = cos gamma / cos^2 sigma / (1 + tan^2 sigma cos^2 gamma)
            let t = sin("sigma") / cos("sigma") * cos("gamma");
            let dt = d_angle(&t, "sigma");
            at_sigma0(&(dt / (&one + sq(&t))))
        } - cos("gamma") / (sq(&cos("sigma0")) + sq(&sin("sigma0")) * sq(&cos("gamma")))),
        "derivative of atan(tan sigma cos gamma)".into(),
    ));

    // n° 53: at the point E (R sin mu = c) the height does not depend on gamma at theta = 0.
    let at_e = subst(&zero_theta(&eq1), &sin("mu"), &(&c_ / &r_));
    checks.push(check(
        "53",
        "lowest_frame_53",
        "at theta = 0 with M at E (R sin mu = c, on the steering axis) K|OM = l sin sigma1 - c sin sigma + R(1 - cos sigma cos mu), free of gamma: sigma of the lowest position follows from (1) alone, gamma then from tan mu = tan sigma cos gamma",
        &at_e,
        &(&at_e - from_printed("l*sin(sigma1) - c*sin(sigma) + R*(1 - cos(sigma)*cos(mu))")),
        format!("K|OM at E: {}", show(&at_e)),
    ));

    // n° 54: the contact locus.
    let x_ab = om.dot(&ijk(0)).expand();
    let y_ab = om.dot(&ijk(1)).expand();
    checks.push(compare(
        "54",
        "locus_y_54",
        "at theta = 0, J|OM is the printed y = -(R sin mu - c) sin gamma",
        &zero_theta(&y_ab),
        "-(R*sin(mu) - c)*sin(gamma)",
    ));
    checks.push(compare(
        "54",
        "locus_x_54",
        "at theta = 0, I|OM is the printed x = a cos sigma + (b + R cos mu) sin sigma + (c - R sin mu) cos sigma cos gamma",
        &zero_theta(&x_ab),
        "a*cos(sigma) + (b + R*cos(mu))*sin(sigma) + (c - R*sin(mu))*cos(sigma)*cos(gamma)",
    ));
    let cos_cm_oi = cm().dot(&ijk(0)) / &r_;
    checks.push(check(
        "54",
        "locus_x_second_54",
        "at theta = 0 with (a), (b), x is the printed l cos sigma1 - c cos sigma (1 - cos gamma) + R cos(CM, OI)",
        &(zero_theta(&with_ab(&x_ab))),
        &(zero_theta(&with_ab(&x_ab))
            - from_printed("l*cos(sigma1) - c*cos(sigma)*(1 - cos(gamma))")
            - &r_ * zero_theta(&cos_cm_oi.expand())),
        format!("cos(CM, OI) = I|CM / R = {}", show(&zero_theta(&cos_cm_oi.expand()))),
    ));

    // n° 57: the normal CN and the angles alpha, beta.
    let [ci, cj, ck] = normal_components();
    checks.push(compare_vec(
        "57",
        "normal_57",
        "CN = |H1 G is the printed (2) of n° 57",
        &Vector::new(Trihedron::IJK, ci.clone(), cj.clone(), ck.clone()),
        [
            "cos(sigma)*sin(gamma)",
            "-(cos(theta)*cos(gamma) + sin(theta)*sin(gamma)*sin(sigma))",
            "-sin(theta)*cos(gamma) + cos(theta)*sin(gamma)*sin(sigma)",
        ],
    ));
    let cn = Vector::new(Trihedron::IJK, ci.clone(), cj.clone(), ck.clone());
    let unit_normal = |cn: &Vector| {
        is_zero_mod(&(cn.dot(cn) - &one))
            && is_zero_mod(&cn.dot(&h1()))
            && is_zero_mod(&cn.dot(&g()))
    };
    let cn_perturbed = crate::falsify::perturb(&cn.comps, |d| {
        unit_normal(&Vector::new(Trihedron::IJK, d[0].clone(), d[1].clone(), d[2].clone()))
    });
    checks.push(Check {
        perturbed: Some(cn_perturbed),
        section: "57".into(),
        id: "normal_unit_57".into(),
        statement: "CN is a unit vector (the memoir's sum of the squares of the second members is 1) normal to H1 and G".into(),
        holds: is_zero_mod(&(cn.dot(&cn) - &one))
            && is_zero_mod(&cn.dot(&h1()))
            && is_zero_mod(&cn.dot(&g())),
        detail: "CN|CN - 1, CN|H1, CN|G reduced to 0".into(),
    });
    let cn_ab = Vector::new(
        Trihedron::IJK,
        cos("beta") * sin("alpha"),
        -(cos("beta") * cos("alpha")),
        sin("beta"),
    );
    let ab_unit = crate::Perturbed {
        what: format!("the derived form (1) of CN scaled by {}", crate::falsify::FACTOR),
        holds: {
            let scaled = cn_ab.scale(&crate::falsify::factor());
            is_zero_mod(&(scaled.dot(&scaled) - &one))
        },
    };
    checks.push(Check {
        perturbed: Some(ab_unit),
        section: "57".into(),
        id: "normal_alpha_beta_unit_57".into(),
        statement: "the form (1) CN = I cos beta sin alpha - J cos beta cos alpha + K sin beta is a unit vector (sum of the squares of the first members is 1)".into(),
        holds: is_zero_mod(&(cn_ab.dot(&cn_ab) - &one)),
        detail: "reduced with sin^2 + cos^2 = 1 for alpha and beta".into(),
    });

    // n° 58: the front wheel's axes, theta1 = -beta.
    let (sa, ca) = sc("alpha");
    let (sb, cb) = sc("beta");
    let (st1, ct1) = (-&sb, cb.clone());
    let i1 = Vector::new(Trihedron::IJK, ca.clone(), sa.clone(), Atom::num(0));
    let j1_big = Vector::new(Trihedron::IJK, -&sa, ca.clone(), Atom::num(0));
    let j1 = j1_big.scale(&ct1).add(&k_big.scale(&st1));
    let k1 = j1_big.scale(&-&st1).add(&k_big.scale(&ct1));
    let printed_j1 = Vector::new(Trihedron::IJK, -(&sa * &ct1), &ca * &ct1, st1.clone());
    let printed_k1 = Vector::new(Trihedron::IJK, &sa * &st1, -(&ca * &st1), ct1.clone());
    let axes_ok = j1.sub(&printed_j1).comps.iter().all(is_zero_mod)
        && k1.sub(&printed_k1).comps.iter().all(is_zero_mod);
    let axes_perturbed = crate::falsify::perturb(&j1.comps, |d| {
        (0..3).all(|i| is_zero_mod(&(&d[i] - &printed_j1.comps[i])))
    });
    checks.push(Check {
        perturbed: Some(axes_perturbed),
        section: "58".into(),
        id: "front_axes_58".into(),
        statement: "j1 = J1 cos theta1 + K sin theta1 and k1 = -J1 sin theta1 + K cos theta1 expand to the printed forms on I, J, K".into(),
        holds: axes_ok,
        detail: "theta1 = -beta; J1 = -I sin alpha + J cos alpha".into(),
    });
    let frame_ok = j1.add(&cn_ab).comps.iter().all(is_zero_mod)
        && i1.cross(&j1).sub(&k1).comps.iter().all(is_zero_mod)
        && is_zero_mod(&i1.dot(&cn_ab))
        && is_zero_mod(&k1.dot(&cn_ab));
    let trihedron_perturbed = crate::Perturbed {
        what: format!("the derived axis j1 scaled by {}", crate::falsify::FACTOR),
        holds: j1.scale(&crate::falsify::factor()).add(&cn_ab).comps.iter().all(is_zero_mod),
    };
    checks.push(Check {
        perturbed: Some(trihedron_perturbed),
        section: "58".into(),
        id: "front_trihedron_58".into(),
        statement: "j1 = -N (N = CN of n° 57), I1 and k1 lie in the wheel's plane and (I1, j1, k1) is direct: |I1 j1 = k1".into(),
        holds: frame_ok,
        detail: "j1 + CN, |I1 j1 - k1, I1|CN, k1|CN reduced to 0".into(),
    });
    // alpha, beta from CN on I, J, K: cos beta = Wb = sqrt(CN_I^2 + CN_J^2).
    let k1_direct = Vector::new(Trihedron::IJK, -(&ci * &ck / wb()), -(&cj * &ck / wb()), wb());
    let k1_from_abn = k1.map(|e| {
        let e = subst(e, &sa, &(&ci / wb()));
        let e = subst(&e, &ca, &(-&cj / wb()));
        let e = subst(&e, &sb, &ck);
        subst(&e, &cb, &wb())
    });
    let k1_perturbed = crate::falsify::perturb(&k1_from_abn.comps, |d| {
        (0..3).all(|i| is_zero_mod(&(&d[i] - &k1_direct.comps[i])))
    });
    checks.push(Check {
        perturbed: Some(k1_perturbed),
        section: "58".into(),
        id: "front_axes_in_theta_gamma_sigma_58".into(),
        statement: "with sin alpha = CN_I / cos beta, cos alpha = -CN_J / cos beta, sin beta = CN_K, cos beta = Wb = sqrt(CN_I^2 + CN_J^2), k1 = (-CN_I CN_K, -CN_J CN_K, Wb^2) / Wb, the steepest line of the front wheel (k1|CN = 0, k1|k1 = 1)".into(),
        holds: k1_from_abn.sub(&k1_direct).comps.iter().all(is_zero_mod)
            && is_zero_mod(&k1_direct.dot(&cn))
            && is_zero_mod(&(k1_direct.dot(&k1_direct) - &one)),
        detail: "Wb reduced with Wb^2 = CN_I^2 + CN_J^2, then sin^2 + cos^2 = 1".into(),
    });

    // Emitted formulas.
    let d_eq1_s = d_angle(&eq1, "sigma").expand();
    let d_eq1_m = d_angle(&eq1, "mu").expand();
    let d_eq2_s = d_angle(&eq2, "sigma").expand();
    let d_eq2_m = d_angle(&eq2, "mu").expand();
    checks.push(check(
        "48",
        "jacobian_structure_48",
        "d(K|OM)/dmu is the second residual K|dOM/dmu, so the Jacobian is triangular at a solution",
        &d_eq1_m,
        &(&d_eq1_m - &eq2),
        "d(K|OM)/dmu - K|dOM/dmu".into(),
    ));
    let sqrt = |e: &Atom| e.pow(Atom::num(1) / Atom::num(2));
    let atan2 = |y: &Atom, x: &Atom| expr(&format!("atan2({}, {})", y, x));
    let wb_val = sqrt(&(sq(&ci) + sq(&cj)));
    let mu_lowest = atan2(
        &(sin_t() * sin("gamma") + cos_t() * cos("gamma") * sin("sigma")),
        &(cos_t() * cos("sigma")),
    );
    let mu0 = atan2(&(sin("sigma0") * cos("gamma")), &cos("sigma0"));
    let mu1_emit = subst(&mu1_first, &var("sigma1_first"), &sigma1_first);
    let formulas = vec![
        formula("contact_height", "45, 48", "K|OM: height of the front wheel's point of parameter mu above the ground (m), with (a), (b); equation (1) is contact_height = 0.", &eq1),
        formula("lowest_point", "45, 48", "K|dOM/dmu (m): equation (2), zero when M is the lowest point of the front wheel.", &eq2),
        formula("d_height_d_sigma", "48", "d(K|OM)/dsigma (m/rad), Jacobian of the residuals.", &d_eq1_s),
        formula("d_height_d_mu", "48", "d(K|OM)/dmu (m/rad), Jacobian of the residuals (equal to lowest_point).", &d_eq1_m),
        formula("d_lowest_d_sigma", "48", "d(K|dOM/dmu)/dsigma (m/rad), Jacobian of the residuals.", &d_eq2_s),
        formula("d_lowest_d_mu", "48", "d(K|dOM/dmu)/dmu (m/rad), Jacobian of the residuals; positive at a lowest point.", &d_eq2_m),
        formula("mu_lowest", "48", "mu (rad) solving (2) for the given sigma: atan2(sin theta sin gamma + cos theta cos gamma sin sigma, cos theta cos sigma).", &mu_lowest),
        formula("contact_x", "54", "I|OM (m): abscissa of M along the rear wheel's trace, from the rear contact O.", &with_ab(&x_ab)),
        formula("contact_y", "54", "J|OM (m): ordinate of M, to the rider's left.", &with_ab(&y_ab)),
        formula("sigma1_first", "51", "sigma1 (rad) of the first-order method at theta = 0, from (2)' as derived (coefficient R tan tau0 cos sigma0 sin gamma).", &sigma1_first),
        formula("memoir_sigma1_first", "51", "sigma1 (rad) of (2)' as printed (coefficient R tan tau0 sin sigma0 sin gamma).", &sigma1_printed),
        formula("mu0", "51", "mu0 (rad): tan mu0 = tan sigma0 cos gamma (theta = 0, sigma = sigma0).", &mu0),
        formula("mu1_first", "51", "mu1 (rad) of the first-order method: sigma1 cos gamma / (cos^2 sigma0 + sin^2 sigma0 cos^2 gamma).", &mu1_emit),
        formula("normal_i", "57", "CN|I: component of the front wheel's unit normal CN = |H1 G on I.", &ci),
        formula("normal_j", "57", "CN|J.", &cj),
        formula("normal_k", "57", "CN|K = sin beta.", &ck),
        formula("alpha", "57", "alpha (rad): angle of the front wheel's trace O1I1 with OI (cos beta sin alpha = CN_I, cos beta cos alpha = -CN_J).", &atan2(&ci, &-&cj)),
        formula("beta", "57", "beta (rad): angle of the front wheel with the vertical (sin beta = CN_K, cos beta >= 0).", &atan2(&ck, &wb_val)),
        formula("axis_i1_x", "58", "I1|I = cos alpha: tangent to the front wheel's path.", &(-&cj / &wb_val)),
        formula("axis_i1_y", "58", "I1|J = sin alpha.", &(&ci / &wb_val)),
        formula("axis_k1_x", "58", "k1|I = sin alpha sin theta1 (theta1 = -beta): the front wheel's steepest line.", &(-(&ci * &ck / &wb_val))),
        formula("axis_k1_y", "58", "k1|J = -cos alpha sin theta1.", &(-(&cj * &ck / &wb_val))),
        formula("axis_k1_z", "58", "k1|K = cos theta1 = cos beta.", &wb_val),
    ];
    Ok(Derivation {
        model: "bicycle_geometry".into(),
        source: file!().to_string(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: INPUTS.iter().map(|s| s.to_string()).collect(),
        formulas,
        checks,
        nominal: crate::derive::nominal::values("bicycle_geometry"),
        horner_schemes: Vec::new(),
    })
}
