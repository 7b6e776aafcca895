//! The bicycle without hands in a state infinitely near straight running (memoir Part II
//! § IV–V, n° 107–122): the fall equation $(\delta\theta)$ and the handlebar equation
//! $(\delta\gamma)$ at first order in $\theta, \gamma$ and their derivatives, the
//! characteristic quartic and the closed-form upper speed limit.
//!
//! Carvallo's model has three parts: the mounted frame (frame and rigid rider, mass $\mu$, centre
//! of mass at height $h$ and forward distance $e$ from the rear contact, moments $A$, $C$ and
//! product $L$ about the rear contact's axes), the rear wheel and the front wheel, both hoops of
//! mass $\mu_1$ and radius $R$ whose moments about their contact points are (n° 4)
//! $A_1 = \tfrac32\mu_1R^2$, $B_1 = 2\mu_1R^2$, $C_1 = \tfrac12\mu_1R^2$; the fork and handlebar
//! are massless. $\eta$ is the steering axis' angle with the vertical, $c_1 = R\sin\eta - c$
//! the distance of the front contact from the steering axis, $l$ the wheelbase, $s$ the wheels'
//! spin (forward speed $Rs$). Notation of n° 108: $\sigma, \mu$ of ch. I are $\eta, \omega$ here.
//!
//! What is derived and what is transcribed:
//! * The six tables of n° 116 (the terms of n° 109–115 by part and by origin) are transcribed
//!   term by term, with the signs that n° 109–115 give (the OCR of the tables loses or adds
//!   some minus signs, see the report); their column sums are the twelve coefficients
//!   $\mathfrak A'', \dots, \mathfrak B_1$ of n° 117.
//! * Each sum is checked exactly against the closed form printed in n° 117.
//! * Each sum is checked exactly against an independent derivation: the general
//!   Carvallo–Whipple bicycle linearised by Kane's method ([`crate::whipple::linear`]), with
//!   Carvallo's model written as a parameter set of it ([`whipple_mapping`]: hoop wheels, a
//!   massless front frame, trail $c_1/\cos\eta$, steer tilt $\eta$, lean $\theta = \varphi$,
//!   steer $\gamma = -\delta$, speed $v = Rs$, his handlebar equation being minus the steer
//!   equation). If all twelve hold, his first-order bookkeeping is the exact linearisation of
//!   his model.
//! * The quartic of n° 119 with $T = st$ (n° 118), its constant term's root in $s^2$ (the
//!   upper limit, n° 120 and n° 122) in closed form, checked against the printed closed form and
//!   its simplification for $c_1 = \tfrac12R\sin\eta$; the lower limit's condition of n° 121,
//!   $a_3^2 - a_1a_2a_3 + a_1^2a_4 = 0$, checked to be minus the third Hurwitz determinant of the
//!   monic quartic.
//!
//! Status: this module compiles but is not yet in `DERIVATIONS` and its test is ignored: a first
//! run of [`derive`] had not finished after 4 minutes (over the budget of a symbolic test), so no
//! check outcome has been observed yet and nothing under `generated/` comes from it.

use anyhow::{ensure, Result};
use symbolica::atom::{Atom, AtomCore};

use crate::frame::{rat, var};
use crate::hoop::{show, subst};
use crate::whipple::{linear, reduce, vanishes};
use crate::{Check, Derivation, Formula};

/// Parameter names, in order: the constants of n° 117 (`ecg` is the rider's distance $e$,
/// `A2` is $A + 2A_1$, `eta` the steering axis' angle with the vertical) and gravity.
pub const PARAMS: [&str; 12] =
    ["R", "l", "c1", "eta", "ecg", "h", "mu", "mu1", "A2", "C", "L", "g"];
/// Input names, in order: the wheels' spin $s$ (rad/s).
pub const INPUTS: [&str; 1] = ["s"];

/// Output names of the twelve coefficients of n° 117: the fall equation's
/// $\mathfrak A'', \mathfrak A', \mathfrak A, \mathfrak B'', \mathfrak B', \mathfrak B$, then
/// the handlebar equation's with index 1.
pub const COEFFS: [&str; 12] = [
    "fall_a2", "fall_a1", "fall_a0", "fall_b2", "fall_b1", "fall_b0", "bar_a2", "bar_a1", "bar_a0",
    "bar_b2", "bar_b1", "bar_b0",
];

fn v(name: &str) -> Atom {
    var(name)
}

fn n(k: i64) -> Atom {
    Atom::num(k)
}

/// $\sin\eta$ and $\cos\eta$ as the polynomial stand-ins of the Whipple derivation (so that its
/// exact zero test applies).
fn sc() -> (Atom, Atom) {
    (v(linear::SIN_LAMBDA), v(linear::COS_LAMBDA))
}

/// The hoop wheel's moments about its contact point (n° 4): $A_1, B_1, C_1$.
fn wheel_moments() -> (Atom, Atom, Atom) {
    let r2 = v("mu1") * v("R").pow(n(2));
    (rat(3, 2) * &r2, n(2) * &r2, rat(1, 2) * &r2)
}

/// One row of a table of n° 116: the coefficients of $\theta'', \theta', \theta, \gamma'',
/// \gamma', \gamma$ contributed by one part through one origin.
type Row = [Atom; 6];

/// The tables of n° 116, as `(equation, origin, part, row)`; `equation` is `fall` or `bar`.
pub fn tables() -> Vec<(&'static str, &'static str, &'static str, Row)> {
    let (sn, co) = sc();
    let (r, l, c1, e, h, mu, mu1, g, s) =
        (v("R"), v("l"), v("c1"), v("ecg"), v("h"), v("mu"), v("mu1"), v("g"), v("s"));
    let (a1, b1, cc1) = wheel_moments();
    let a = v("A2") - n(2) * &a1;
    let (c, ll) = (v("C"), v("L"));
    let k = &c1 / &l;
    let rl = &r / &l;
    let s2 = s.pow(n(2));
    let z = || n(0);
    let lc = (&l * &co + &c1) / &r;
    vec![
        // (δθ): (dT/dθ')', n° 109-111.
        (
            "fall",
            "dT/dtheta'",
            "frame",
            [
                a.clone(),
                z(),
                z(),
                -(&ll * &k),
                -(&mu * &r * (&h - &r) * &k + &ll * &rl * &co) * &s,
                z(),
            ],
        ),
        ("fall", "dT/dtheta'", "rear wheel", [a1.clone(), z(), z(), z(), z(), z()]),
        (
            "fall",
            "dT/dtheta'",
            "front wheel",
            [a1.clone(), z(), z(), -(&a1 * &sn), -(&b1 * &co * &s), z()],
        ),
        // (δθ): -Σ m M'|(dM/dθ)', n° 112-114.
        (
            "fall",
            "-sum m M'(dM/dtheta)'",
            "frame",
            [
                z(),
                z(),
                z(),
                z(),
                -(&mu * r.pow(n(2)) * &k * &s),
                -(&mu * &r * &h * &rl * &co * &s2),
            ],
        ),
        (
            "fall",
            "-sum m M'(dM/dtheta)'",
            "rear wheel",
            [z(), z(), z(), z(), -(&b1 * &k * &s), -(&b1 * &rl * &co * &s2)],
        ),
        (
            "fall",
            "-sum m M'(dM/dtheta)'",
            "front wheel",
            [z(), z(), z(), z(), -(&b1 * &k * &s), -(&b1 * &rl * &co * &s2)],
        ),
        // (δθ): gravity, n° 115.
        ("fall", "gravity", "frame", [z(), z(), -(&mu * &h * &g), z(), z(), &mu * &e * &k * &g]),
        ("fall", "gravity", "rear wheel", [z(), z(), -(&mu1 * &r * &g), z(), z(), z()]),
        (
            "fall",
            "gravity",
            "front wheel",
            [z(), z(), -(&mu1 * &r * &g), z(), z(), &mu1 * &r * &sn * &g],
        ),
        // (δγ): (dT/dγ')', n° 109-111.
        (
            "bar",
            "dT/dgamma'",
            "frame",
            [
                -(&ll * &k),
                &mu * r.pow(n(2)) * &k * &s,
                z(),
                &c * k.pow(n(2)),
                (&mu * &r * (&h - &r) * &k * &sn + &c * &k * &rl * &co) * &s,
                z(),
            ],
        ),
        (
            "bar",
            "dT/dgamma'",
            "rear wheel",
            [z(), &b1 * &k * &s, z(), &cc1 * k.pow(n(2)), &cc1 * &rl * &k * &co * &s, z()],
        ),
        (
            "bar",
            "dT/dgamma'",
            "front wheel",
            [
                -(&a1 * &sn),
                &b1 * &k * &s,
                z(),
                &a1 * sn.pow(n(2)) + &cc1 * (&k + &co).pow(n(2)),
                (&b1 * &k * (&lc - &sn) + &cc1 * &rl * &co * (&k + &co)) * &s,
                z(),
            ],
        ),
        // (δγ): -Σ m M'|(dM/dγ)', n° 112-114.
        (
            "bar",
            "-sum m M'(dM/dgamma)'",
            "frame",
            [
                z(),
                -(&mu * r.pow(n(2)) * &k * &s),
                z(),
                z(),
                &mu * &r * &k * (-(&h - &r) * &sn + &e * &k) * &s,
                &mu * &r * &e * &k * &rl * &co * &s2,
            ],
        ),
        (
            "bar",
            "-sum m M'(dM/dgamma)'",
            "rear wheel",
            [z(), -(&mu1 * r.pow(n(2)) * &k * &s), z(), z(), z(), z()],
        ),
        (
            "bar",
            "-sum m M'(dM/dgamma)'",
            "front wheel",
            [
                z(),
                (-(&mu1 * r.pow(n(2)) * (&co + &k)) + &b1 * &co) * &s,
                z(),
                z(),
                (&mu1 * r.pow(n(2)) * (&co + &k) * &sn + &b1 * &k * (&sn - &lc)) * &s,
                &b1 * &rl * &sn * &co * &s2,
            ],
        ),
        // (δγ): gravity, n° 115.
        (
            "bar",
            "gravity",
            "frame",
            [z(), z(), &mu * &e * &k * &g, z(), z(), -(&mu * &e * &k * &sn * &g)],
        ),
        ("bar", "gravity", "rear wheel", [z(), z(), z(), z(), z(), z()]),
        (
            "bar",
            "gravity",
            "front wheel",
            [z(), z(), &mu1 * &r * &sn * &g, z(), z(), -(&mu1 * &r * sn.pow(n(2)) * &g)],
        ),
    ]
}

/// The column sums of the tables: the twelve coefficients in the order of [`COEFFS`].
pub fn table_sums() -> [Atom; 12] {
    let mut out: [Atom; 12] = std::array::from_fn(|_| n(0));
    for (eq, _, _, row) in tables() {
        let base = if eq == "fall" { 0 } else { 6 };
        for (j, x) in row.iter().enumerate() {
            out[base + j] = &out[base + j] + x;
        }
    }
    out.map(|x| x.expand())
}

/// The twelve closed forms printed in n° 117 (with $\mathfrak B_1'$'s first term read
/// $R c_1/l^2$: the OCR prints $R c_1/l$, dimensionally wrong), in the order of [`COEFFS`].
pub fn printed_117() -> [Atom; 12] {
    let (sn, co) = sc();
    let (r, l, c1, e, h, mu, mu1, g, s) =
        (v("R"), v("l"), v("c1"), v("ecg"), v("h"), v("mu"), v("mu1"), v("g"), v("s"));
    let (a1, b1, cc1) = wheel_moments();
    let (c, ll) = (v("C"), v("L"));
    let k = &c1 / &l;
    let rl = &r / &l;
    let s2 = s.pow(n(2));
    let q = &mu * &e * &k + &mu1 * &r * &sn;
    [
        v("A2"),
        n(0),
        -(&g * (&mu * &h + n(2) * &mu1 * &r)),
        -(&ll * &k + &a1 * &sn),
        -(&s * (&k * (&mu * &r * &h + n(2) * &b1) + &co * (&ll * &rl + &b1))),
        -(&s2 * &rl * &co * (&mu * &r * &h + n(2) * &b1)) + &g * &q,
        -(&ll * &k + &a1 * &sn),
        &s * (&b1 - &mu1 * r.pow(n(2))) * (n(2) * &k + &co),
        &g * &q,
        (&c + &cc1) * k.pow(n(2)) + &cc1 * (&k + &co).pow(n(2)) + &a1 * sn.pow(n(2)),
        &s * (&r * &c1 / l.pow(n(2)) * &co * (&c + n(2) * &cc1)
            + &cc1 * &rl * co.pow(n(2))
            + &mu * &r * &e * k.pow(n(2))
            + &mu1 * r.pow(n(2)) * &sn * (&co + &k)),
        &s2 * &rl * &co * (&mu * &r * &e * &k + &b1 * &sn) - &g * &sn * &q,
    ]
}

/// Carvallo's model as a parameter set of the general Carvallo–Whipple bicycle, by benchmark
/// parameter name. Assumptions: both wheels are hoops of mass $\mu_1$ and radius $R$
/// (benchmark moments about the centre: $I_{xx} = \tfrac12\mu_1R^2$, $I_{yy} = \mu_1R^2$); the
/// front frame (fork and handlebar) is massless; the steer tilt is $\eta$ and the trail
/// $c_1/\cos\eta$ ($c_1$ is measured perpendicular to the steering axis); the wheelbase is
/// $l$; the rear body is the mounted frame, centre of mass at $x = e$, $z = -h$ (z down), its
/// moments about its centre of mass from Carvallo's moments about the rear contact point:
/// $I_{xx} = A - \mu h^2$ with $A = (A + 2A_1) - 2A_1$, $I_{zz} = C - \mu e^2$,
/// $I_{xz} = L - \mu e h$ (tensor components in the benchmark's z-down axes, where Carvallo's
/// $L = \sum m x z$ with z up). `IByy`, `xH`, `zH` are left as symbols: they must drop out.
pub fn whipple_mapping() -> Vec<(&'static str, Atom)> {
    let (_, co) = sc();
    let (r, mu, mu1) = (v("R"), v("mu"), v("mu1"));
    let r2 = r.pow(n(2));
    vec![
        ("w", v("l")),
        ("c", v("c1") / &co),
        ("rR", r.clone()),
        ("mR", mu1.clone()),
        ("IRxx", rat(1, 2) * &mu1 * &r2),
        ("IRyy", &mu1 * &r2),
        ("xB", v("ecg")),
        ("zB", -v("h")),
        ("mB", mu.clone()),
        ("IBxx", v("A2") - n(3) * &mu1 * &r2 - &mu * v("h").pow(n(2))),
        ("IBzz", v("C") - &mu * v("ecg").pow(n(2))),
        ("IBxz", v("L") - &mu * v("ecg") * v("h")),
        ("mH", n(0)),
        ("IHxx", n(0)),
        ("IHyy", n(0)),
        ("IHzz", n(0)),
        ("IHxz", n(0)),
        ("rF", r.clone()),
        ("mF", mu1.clone()),
        ("IFxx", rat(1, 2) * &mu1 * &r2),
        ("IFyy", &mu1 * &r2),
    ]
}

fn map_whipple(e: &Atom) -> Atom {
    let mut a = e.clone();
    for (name, value) in whipple_mapping() {
        a = subst(&a, name, &value);
    }
    a
}

/// The twelve coefficients from the general model's Kane linearisation with
/// [`whipple_mapping`], in the order of [`COEFFS`]: the fall equation is the lean equation, the
/// handlebar equation minus the steer equation, the steer column changes sign ($\gamma = -\delta$)
/// and $v = Rs$.
pub fn via_whipple() -> [Atom; 12] {
    let st = linear::statics();
    let dy = linear::dynamics();
    let (r, g, s) = (v("R"), v("g"), v("s"));
    let mut out: [Atom; 12] = std::array::from_fn(|_| n(0));
    for row in 0..2 {
        let row_sign = if row == 0 { n(1) } else { n(-1) };
        for col in 0..2 {
            let sign = &row_sign * if col == 0 { n(1) } else { n(-1) };
            let m = map_whipple(&dy.m[row][col]);
            let c1 = map_whipple(&dy.c1[row][col]);
            let k = &g * map_whipple(&st.k0[row][col])
                + (&r * &s).pow(n(2)) * map_whipple(&dy.k2[row][col]);
            let base = 6 * row + 3 * col;
            out[base] = &sign * m;
            out[base + 1] = &sign * &r * &s * c1;
            out[base + 2] = &sign * k;
        }
    }
    out.map(|x| reduce(&x))
}

/// The quartic of n° 119 in λ (independent variable $T = st$, n° 118), coefficients of
/// $\lambda^0, \dots, \lambda^4$, from the twelve coefficients: $a'' = \mathfrak A''$,
/// $a' = \mathfrak A'/s$, $a = \mathfrak A/s^2$ and likewise for the others.
pub fn quartic(coef: &[Atom; 12]) -> [Atom; 5] {
    let s = v("s");
    let scale = |x: &Atom, k: i64| (x / s.pow(n(k))).expand();
    let [a2, a1, a0, b2, b1, b0, p2, p1, p0, q2, q1, q0] = std::array::from_fn(|i| {
        let k = [0, 1, 2][i % 3];
        scale(&coef[i], k)
    });
    [
        &a0 * &q0 - &p0 * &b0,
        &a1 * &q0 - &p1 * &b0 + &a0 * &q1 - &p0 * &b1,
        &a2 * &q0 - &p2 * &b0 + &a1 * &q1 - &p1 * &b1 + &a0 * &q2 - &p0 * &b2,
        &a2 * &q1 - &p2 * &b1 + &a1 * &q2 - &p1 * &b2,
        &a2 * &q2 - &p2 * &b2,
    ]
}

fn check(section: &str, id: &str, statement: &str, diff: &Atom, detail: String) -> Check {
    let holds = vanishes(diff);
    Check {
        section: section.to_string(),
        id: id.to_string(),
        statement: statement.to_string(),
        holds,
        detail: if holds {
            detail
        } else {
            format!("{detail}; difference: {}", show(&reduce(diff)))
        },
    }
}

fn to_eta(e: &Atom) -> Atom {
    let a = subst(e, linear::SIN_LAMBDA, &var("sin(eta)"));
    subst(&a, linear::COS_LAMBDA, &var("cos(eta)"))
}

/// Derives the model's formulas and checks.
pub fn derive() -> Result<Derivation> {
    let mut checks = Vec::new();
    let sums = table_sums();
    let printed = printed_117();
    let whipple = via_whipple();
    for i in 0..12 {
        checks.push(check(
            "117",
            &format!("{}_printed", COEFFS[i]),
            &format!("the column sum of the n° 116 tables for {} equals the closed form printed in n° 117", COEFFS[i]),
            &(&sums[i] - &printed[i]),
            format!("sum: {}", show(&reduce(&sums[i]))),
        ));
    }
    for i in 0..12 {
        checks.push(check(
            "116",
            &format!("{}_whipple", COEFFS[i]),
            &format!("the column sum of the n° 116 tables for {} equals the exact linearisation of the general Carvallo-Whipple bicycle (Kane) with Carvallo's model as its parameter set (exact, symbolic in all constants)", COEFFS[i]),
            &(&sums[i] - &whipple[i]),
            format!("general model: {}", show(&whipple[i])),
        ));
    }
    // n° 108 (6): the yaw rate n against the general model's (n = -psi', gamma = -delta).
    let dy = linear::dynamics();
    let yaw = map_whipple(&dy.yaw_rate);
    let yaw = subst(&yaw, "v", &(v("R") * v("s")));
    let yaw = subst(&yaw, "delta", &-v("gamma"));
    let yaw = subst(&yaw, "deltad", &-v("gammad"));
    let (_, co) = sc();
    let n_108 = v("R") / v("l") * &co * v("gamma") * v("s") + v("c1") / v("l") * v("gammad");
    checks.push(check(
        "108",
        "yaw_rate",
        "n = (R/l) cos(eta) gamma s + (c1/l) gamma' (n° 108 (6)) is minus the general model's yaw rate psi' with the mapping",
        &(&n_108 + &yaw),
        format!("general model psi' = {}", show(&reduce(&yaw))),
    ));
    // n° 119-122.
    let q = quartic(&sums);
    let num0 = (&sums[2] * &sums[11] - &sums[8] * &sums[5]).expand();
    let n0 = subst(&num0, "s", &n(0));
    let n1 = (subst(&num0, "s", &n(1)) - &n0).expand();
    let quad = (subst(&num0, "s", &n(2)) - &n0 - n(4) * &n1).expand();
    checks.push(check(
        "122",
        "constant_term_linear_in_s2",
        "the constant term's numerator A B1 - A1 B (script letters of n° 117) is of degree one in s^2",
        &quad,
        format!("coefficient of s^0: {}", show(&reduce(&n0))),
    ));
    let s2_upper = reduce(&(-&n0 / &n1));
    let (sn, _) = sc();
    let (r, l, c1, e, h, mu, mu1, g) =
        (v("R"), v("l"), v("c1"), v("ecg"), v("h"), v("mu"), v("mu1"), v("g"));
    let k = &c1 / &l;
    let qq = &mu * &e * &k + &mu1 * &r * &sn;
    let printed_122 = &g * &qq * (&mu * &h * &sn + &mu1 * &r * &sn - &mu * &e * &k)
        / (&r * &r / &l
            * &co
            * ((&mu * &h + n(2) * &mu1 * &r) * (&mu * &e * &k + n(2) * &mu1 * &r * &sn)
                - (&mu * &h + n(4) * &mu1 * &r) * &qq));
    checks.push(check(
        "122",
        "upper_limit_closed_form",
        "the root in s^2 of the constant term equals the closed form printed in n° 122 (with B1 = 2 mu1 R^2)",
        &(&s2_upper - &printed_122),
        format!("derived: s^2 = {}", show(&s2_upper)),
    ));
    let half = rat(1, 2) * &r * &sn;
    let s2_half = reduce(&subst(&s2_upper, "c1", &half));
    let el = &e / &l;
    let printed_half = &g * &sn / (&r * &r / &l * &co)
        * (rat(1, 2) * &mu / &mu1 * &el + n(1))
        * (&h - rat(1, 2) * &r * &el + &mu1 / &mu * &r)
        / (&h - &r * &el);
    checks.push(check(
        "122",
        "upper_limit_half_trail",
        "with c1 = R sin(eta)/2 the upper limit reduces to the three-factor product printed in n° 122",
        &(&s2_half - &printed_half),
        format!("derived: s^2 = {}", show(&s2_half)),
    ));
    let den_half = (&mu * &h + n(2) * &mu1 * &r) * (rat(1, 2) * &mu * &el + n(2) * &mu1)
        - (&mu * &h + n(4) * &mu1 * &r) * (rat(1, 2) * &mu * &el + &mu1);
    checks.push(check(
        "122",
        "half_trail_denominator",
        "the denominator of the second fraction reduces to mu mu1 (h - R e/l)",
        &(&den_half - &mu * &mu1 * (&h - &r * &el)).expand(),
        "exact".to_string(),
    ));
    // n° 121: the condition for a root i w of the monic quartic, and Routh-Hurwitz.
    let (x1, x2, x3, x4, w2) = (v("a1"), v("a2"), v("a3"), v("a4"), v("w2"));
    let real_part = w2.pow(n(2)) - &x2 * &w2 + &x4;
    let eliminated = (subst(&real_part, "w2", &(&x3 / &x1)) * x1.pow(n(2))).expand();
    let cond = x3.pow(n(2)) - &x1 * &x2 * &x3 + x1.pow(n(2)) * &x4;
    checks.push(check(
        "121",
        "pure_imaginary_condition",
        "eliminating w^2 = a3/a1 (n° 121 (3)) from w^4 - a2 w^2 + a4 = 0 (1) gives (4) a3^2 - a1 a2 a3 + a1^2 a4 = 0",
        &(&eliminated - &cond),
        "exact".to_string(),
    ));
    let hurwitz3 = &x1 * (&x2 * &x3 - &x1 * &x4) - x3.pow(n(2));
    checks.push(check(
        "121",
        "routh_hurwitz",
        "Carvallo's condition (4) is minus the third Hurwitz determinant H3 = det[[a1, a3, 0], [1, a2, a4], [0, a1, a3]] of the monic quartic, so his lower limit is where H3 changes sign",
        &(&cond + &hurwitz3).expand(),
        "a3^2 - a1 a2 a3 + a1^2 a4 = -H3".to_string(),
    ));
    let mut formulas = Vec::new();
    let what = [
        "fall equation, coefficient of theta''",
        "fall equation, coefficient of theta'",
        "fall equation, coefficient of theta",
        "fall equation, coefficient of gamma''",
        "fall equation, coefficient of gamma'",
        "fall equation, coefficient of gamma",
        "handlebar equation, coefficient of theta''",
        "handlebar equation, coefficient of theta'",
        "handlebar equation, coefficient of theta",
        "handlebar equation, coefficient of gamma''",
        "handlebar equation, coefficient of gamma'",
        "handlebar equation, coefficient of gamma",
    ];
    for i in 0..12 {
        formulas.push(Formula {
            name: COEFFS[i].to_string(),
            section: "117".to_string(),
            description: format!(
                "{} (kg m^2 times s^0, s^1 or s^2 as the derivative order; column sum of the n° 116 tables)",
                what[i]
            ),
            expr: to_eta(&reduce(&sums[i])),
        });
    }
    for (kk, qk) in q.iter().enumerate() {
        formulas.push(Formula {
            name: format!("quartic{kk}"),
            section: "119".to_string(),
            description: format!(
                "coefficient of lambda^{kk} of the characteristic equation in lambda, T = s t (n° 118-119)"
            ),
            expr: to_eta(qk),
        });
    }
    formulas.push(Formula {
        name: "s2_upper".to_string(),
        section: "122".to_string(),
        description: "the upper limit of s^2: the root of the quartic's constant term (rad^2/s^2)"
            .to_string(),
        expr: to_eta(&s2_upper),
    });
    formulas.push(Formula {
        name: "s2_upper_half_trail".to_string(),
        section: "122".to_string(),
        description: "the upper limit of s^2 when c1 = R sin(eta)/2 (c1 not used; rad^2/s^2)"
            .to_string(),
        expr: to_eta(&s2_half),
    });
    let failed: Vec<&str> =
        checks.iter().filter(|c| !c.holds && c.section != "116").map(|c| c.id.as_str()).collect();
    ensure!(failed.is_empty(), "bicycle_straight checks failed: {failed:?}");
    Ok(Derivation {
        model: "bicycle_straight".to_string(),
        source: "codegen/src/bicycle_straight.rs".to_string(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: INPUTS.iter().map(|s| s.to_string()).collect(),
        formulas,
        checks,
    })
}
