//! The bicycle's steady states with and without hands and the stability with hands (memoir
//! Part II, ch. IV, n° 79–106), derived with symbolica from the modified Lagrange equations of
//! n° 72 and checked against the memoir's printed terms ([`memoir`]).
//!
//! # Model and notation
//! The bicycle is the memoir's: the loaded frame (frame and rigid rider, n° 83) of mass
//! $\mu$, centre of gravity $C - O = Ie + kh$ in the rear wheel's trihedron OIjk, moments
//! $A, B, C$ about OI, Oj, Ok and product $L = \sum m\,zx$; two equal hoop wheels of mass
//! $\mu_1$ and moments $A_1, B_1, C_1$ about their contact points (n° 4, 21). The frame turns
//! by $\eta$ about Sj (counted $-j$, n° 60) and with the trihedron by $\Phi = pI + nK$. The
//! front wheel has its own trihedron $I_1J_1K$, $I_1 = I\cos\alpha + J\sin\alpha$, its lean
//! $\theta_1$ and rolling rate $s_1$ (n° 57, 66 bis).
//!
//! # What is derived, and how
//! * The steady terms of the fall equation (δθ) (n° 81–85) and of the handlebar equation (δγ)
//!   (n° 90–94), for each of the three parts, by two routes: Carvallo's
//!   $\sum m M'|(dM/d\theta)'$ with the time derivative of the virtual velocity (route A,
//!   n° 72), and $-\sum m M''|dM/d\theta$ from the accelerations (route B; equal to route A in
//!   a steady state because $\sum m M'|dM/d\theta$ is then constant). The wheels use the hoop's
//!   moment of the inertia forces about the contact point ([`crate::derive::hoop::motion`]). The
//!   virtual rotations are those of the memoir: $I + K\,d\nu/d\theta$ (rear wheel),
//!   $I - j\,d\eta/d\theta + K\,d\nu/d\theta + j_1\,d\sigma_1/d\theta$ (front wheel),
//!   $I$ about O, $-j\,d\eta/d\theta$ about S and $K\,d\nu/d\theta$ about O (frame), and for
//!   δγ the same with the steering axis $G$ added for the front wheel.
//! * The gravity terms (n° 84, 93) by the virtual velocities and, independently, by
//!   differentiating the heights of the centres (n° 69's $Z(\theta, \eta_1)$ for the frame).
//! * The minimum of geometry needed, derived here and not taken from n° 43–69: the front axle
//!   $j\cos\gamma - H\sin\gamma$ gives $\sin\theta_1$ (n° 97) and $\tan\alpha$ (n° 57), and
//!   $G|I_1 = -\sin\omega$ (n° 66 bis) with $\tan\omega$ of (2), n° 48. The derivatives
//!   $d\eta/d\theta$, $d\nu/d\theta$, $d\eta/d\gamma$, $d\nu/d\gamma$ stay inputs; where the
//!   memoir's reductions need them (n° 86, 95) its simplified forms of n° 66 are used, as it
//!   does ($x = l$, $y = 0$, $\omega = \eta$ at first order, n° 108), and said so in the checks.
//! * The first-order reductions of n° 86–88 and n° 95 (small θ, θ₁, α), the ratio
//!   $\theta_1/\theta$ of (1)′ of n° 95, the geometric ratio of n° 97 and, beyond the memoir,
//!   the speed at which both agree (a steady turn without hands and without lateral shift)
//!   and the lateral shift of n° 98 needed at other speeds.
//! * The loaded frame's kinetic energy (n° 99) from its velocity field, its partial
//!   derivatives (n° 100) and its exact coefficient of $p'$ in the fall equation (n° 102).

pub mod memoir;

use anyhow::{ensure, Result};
use symbolica::atom::{Atom, AtomCore};
use symbolica::domains::integer::Z;
use symbolica::domains::rational::Q;

use crate::cas::subst;
use crate::cas::{cos_t, expr, reduce_pair, sin_t, var};
use crate::derive::hoop;
use crate::derive::unicycle::degree;
use crate::mechanics::frame::{Trihedron, Vector};
use crate::memoir::Printed;
use crate::{Check, Derivation, Formula};

/// Parameter names of the model, in order.
pub const PARAMS: [&str; 15] =
    ["R", "g", "mu", "e", "h", "A", "B", "C", "L", "mu1", "A1", "B1", "C1", "l", "c"];
/// Input names of the model, in order.
pub const INPUTS: [&str; 14] = [
    "theta", "theta1", "alpha", "eta", "omega", "s", "s1", "n", "deta", "dnu", "deta_g", "dnu_g",
    "p", "deta_t",
];

/// The angles whose sine and cosine appear as polynomial stand-ins `sin_<a>`, `cos_<a>`.
const ANGLES: [&str; 7] = ["theta", "theta1", "alpha", "eta", "omega", "gamma", "eta1"];

fn zero() -> Atom {
    Atom::num(0)
}

fn sn(a: &str) -> Atom {
    var(&format!("sin_{a}"))
}

fn cs(a: &str) -> Atom {
    var(&format!("cos_{a}"))
}

/// Replaces every stand-in by `sin(a)`, `cos(a)`.
fn to_trig_all(e: &Atom) -> Atom {
    ANGLES.iter().fold(e.clone(), |acc, a| {
        acc.replace(sn(a).to_pattern())
            .with(expr(&format!("sin({a})")).to_pattern())
            .replace(cs(a).to_pattern())
            .with(expr(&format!("cos({a})")).to_pattern())
    })
}

/// Replaces `tan(a)`, `sin(a)`, `cos(a)` by the stand-ins.
fn from_trig_all(e: &Atom) -> Atom {
    ANGLES.iter().fold(e.clone(), |acc, a| {
        acc.replace(expr(&format!("tan({a})")).to_pattern())
            .with((sn(a) / cs(a)).to_pattern())
            .replace(expr(&format!("sin({a})")).to_pattern())
            .with(sn(a).to_pattern())
            .replace(expr(&format!("cos({a})")).to_pattern())
            .with(cs(a).to_pattern())
    })
}

fn reduce_all(e: &Atom) -> Atom {
    ANGLES.iter().fold(e.expand(), |acc, a| reduce_pair(&acc, &sn(a), &cs(a)))
}

fn num_den_all(e: &Atom) -> (Atom, Atom) {
    let rp = e.expand().to_rational_polynomial::<_, _, u16>(&Q, &Z, ());
    (reduce_all(&rp.numerator.to_expression()), reduce_all(&rp.denominator.to_expression()))
}

/// Exact test that a rational function of the symbols and of the stand-ins vanishes, every
/// angle's $\sin^2 + \cos^2 = 1$ taken into account.
fn is_zero_all(e: &Atom) -> bool {
    num_den_all(e).0.is_zero()
}

fn simplify_all(e: &Atom) -> Atom {
    let (n, d) = num_den_all(e);
    let (n, d) = num_den_all(&(n / d));
    if d.nterms() <= 1 {
        (n / d).expand()
    } else {
        n / d
    }
}

fn show_all(e: &Atom) -> String {
    to_trig_all(&simplify_all(e)).to_string()
}

/// A printed formula with every angle's stand-ins.
pub fn printed(p: &Printed) -> Atom {
    from_trig_all(&expr(p.text))
}

fn with(e: &Atom, values: &[(&str, Atom)]) -> Atom {
    values.iter().fold(e.clone(), |acc, (name, v)| subst(&acc, name, v))
}

fn d(f: &Atom, x: &str) -> Atom {
    f.derivative(var(x).get_symbol().expect("symbol"))
}

/// The rational points of the comparison with the mechanics engine (n° 98): generic constants
/// near the memoir's (hoop-like wheels with $A_1 = C_1 + \mu_1R^2$, the symmetric wheel the
/// Whipple bicycle assumes), $\sin\eta$, $\cos\eta$ Pythagorean pairs and the spin $s$.
fn engine_points() -> Vec<Vec<(&'static str, Atom)>> {
    let r = |n: i64, d: i64| Atom::num(n) / Atom::num(d);
    let sets = [
        [
            (19, 50),
            (981, 100),
            (70, 1),
            (3, 20),
            (1, 1),
            (75, 1),
            (78, 1),
            (8, 1),
            (6, 1),
            (5, 1),
            (11, 10),
            (2, 25),
            (5, 13),
            (12, 13),
            (14, 1),
        ],
        [
            (2, 5),
            (10, 1),
            (64, 1),
            (1, 5),
            (9, 10),
            (60, 1),
            (66, 1),
            (7, 1),
            (4, 1),
            (4, 1),
            (23, 20),
            (1, 20),
            (3, 5),
            (4, 5),
            (9, 1),
        ],
        [
            (7, 20),
            (49, 5),
            (80, 1),
            (1, 10),
            (11, 10),
            (90, 1),
            (95, 1),
            (10, 1),
            (9, 1),
            (6, 1),
            (1, 1),
            (1, 10),
            (8, 17),
            (15, 17),
            (20, 1),
        ],
    ];
    let names =
        ["R", "g", "mu", "e", "h", "A", "B", "C", "L", "mu1", "l", "c", "sin_eta", "cos_eta", "s"];
    sets.iter()
        .map(|set| {
            let mut pt: Vec<(&str, Atom)> =
                names.iter().zip(set).map(|(n, (p, q))| (*n, r(*p, *q))).collect();
            let get = |pt: &Vec<(&str, Atom)>, n: &str| {
                pt.iter().find(|(k, _)| *k == n).map(|(_, x)| x.clone()).expect("named")
            };
            let m = get(&pt, "mu1") * get(&pt, "R").pow(Atom::num(2));
            pt.push(("C1", (&m / Atom::num(2)).expand()));
            pt.push(("A1", (Atom::num(3) * &m / Atom::num(2)).expand()));
            pt.push(("B1", (Atom::num(2) * &m).expand()));
            pt.push(("sin_omega", get(&pt, "sin_eta")));
            pt.push(("cos_omega", get(&pt, "cos_eta")));
            pt
        })
        .collect()
}

/// Carvallo's bicycle at a point of [`engine_points`] as a parameter set of the general
/// Carvallo–Whipple bicycle: the mounted frame (mass $\mu$, centre $e$ ahead of and $h$ above
/// the rear contact, moments $A$, $B$, $C$ and product $L$ about the rear contact's axes) as
/// the rear body, a massless fork, hoop-like wheels of radius $R$ whose moments about the
/// centre are $C_1$ (diametral) and $B_1 - \mu_1R^2$ (axial), the trail
/// $(R\sin\eta - c)/\cos\eta$, the steering axis' tilt $\eta$ and the speed $v = Rs$.
fn whipple_values(pt: &[(&str, Atom)]) -> Vec<(&'static str, Atom)> {
    let get = |n: &str| pt.iter().find(|(k, _)| *k == n).map(|(_, x)| x.clone()).expect("named");
    let (r, mu, mu1, e, h) = (get("R"), get("mu"), get("mu1"), get("e"), get("h"));
    let sq = |x: &Atom| x.pow(Atom::num(2));
    let z = Atom::num(0);
    let vals = vec![
        ("w", get("l")),
        ("c", (&r * get("sin_eta") - get("c")) / get("cos_eta")),
        ("sin_lambda", get("sin_eta")),
        ("cos_lambda", get("cos_eta")),
        ("g", get("g")),
        ("rR", r.clone()),
        ("rF", r.clone()),
        ("mR", mu1.clone()),
        ("mF", mu1.clone()),
        ("IRxx", get("C1")),
        ("IFxx", get("C1")),
        ("IRyy", get("B1") - &mu1 * sq(&r)),
        ("IFyy", get("B1") - &mu1 * sq(&r)),
        ("xB", e.clone()),
        ("zB", -h.clone()),
        ("mB", mu.clone()),
        ("IBxx", get("A") - &mu * sq(&h)),
        ("IByy", get("B") - &mu * (sq(&e) + sq(&h))),
        ("IBzz", get("C") - &mu * sq(&e)),
        ("IBxz", get("L") - &mu * &e * &h),
        ("mH", z.clone()),
        ("IHxx", z.clone()),
        ("IHyy", z.clone()),
        ("IHzz", z.clone()),
        ("IHxz", z),
        ("xH", Atom::num(1)),
        ("zH", Atom::num(-1)),
        ("v", &r * get("s")),
    ];
    vals.into_iter().map(|(n, x)| (n, x.expand())).collect()
}

/// n° 98 by the mechanics engine: the general bicycle with the rider's body turned by ε about the
/// frame's ground trace OI ([`crate::derive::whipple::description::whipple_shifted`]),
/// linearised; a steady turn without hands at first order has every rate zero and no steer
/// torque, $f_q\,(\varphi, \delta) + f_\varepsilon\,\varepsilon = 0$ in the lean and steer rows,
/// whose solution per unit lean gives $\varepsilon/\theta$ exactly at first order, for
/// Carvallo's bicycle written as a parameter set of the general one ([`whipple_values`]; its
/// wheels' diametral moment about the centre is $C_1$, so $A_1 = C_1 + \mu_1R^2$ as for hoops).
/// The memoir's route (n° 95–97, `shift_98`) reduces the fall equation first ((3)′ of n° 86:
/// the frame alone, the $(B - C)n^2$ term and $d\eta/d\theta$ dropped), so the two differ; the
/// checks: the exact ratio solves both rows (residuals zero at exact rational points), and it
/// is not the reduced route's (informative).
fn shift_98_engine(shift_98: &Atom) -> Result<(Atom, Vec<Check>)> {
    let lin = crate::derive::whipple::linearised::shifted()?;
    let (fq, ft) = (&lin.f_q, &lin.f_t);
    // Per unit lean: [fq01 ft0; fq11 ft1] (delta, eps) = -(fq00, fq10), by Cramer's rule.
    let det = &fq[0][1] * &ft[1][0] - &ft[0][0] * &fq[1][1];
    let delta = (-&fq[0][0] * &ft[1][0] + &ft[0][0] * &fq[1][0]) / &det;
    let eps = (-&fq[0][1] * &fq[1][0] + &fq[0][0] * &fq[1][1]) / &det;
    let symbolic: Vec<(&str, Atom)> =
        ["R", "g", "mu", "e", "h", "A", "B", "C", "L", "mu1", "l", "c", "C1", "B1", "s"]
            .iter()
            .map(|n| (*n, var(n)))
            .chain([("sin_eta", sn("eta")), ("cos_eta", cs("eta"))])
            .collect();
    let exact = simplify_all(&with(&eps, &whipple_values(&symbolic)));
    let mut residual_bad = Vec::new();
    let mut differ = Vec::new();
    let mut shown = Vec::new();
    // The falsifications: the exact shift scaled by 9/8 (the rows must then not vanish), and
    // the reduced route's shift replaced by the exact one (no point may then differ).
    let mut scaled_solves = true;
    let mut differ_undone = Vec::new();
    for (k, pt) in engine_points().iter().enumerate() {
        let wv = whipple_values(pt);
        let (e, dl) = (with(&exact, pt), with(&delta, &wv));
        let rows: Vec<Atom> = (0..2)
            .map(|r| simplify_all(&with(&(&fq[r][0] + &fq[r][1] * &dl + &ft[r][0] * &e), &wv)))
            .collect();
        let scaled = &e * crate::falsify::factor();
        scaled_solves &= (0..2).all(|r| {
            simplify_all(&with(&(&fq[r][0] + &fq[r][1] * &dl + &ft[r][0] * &scaled), &wv)).is_zero()
        });
        if rows.iter().any(|x| !x.is_zero()) {
            residual_bad.push(format!(
                "point {}: {}",
                k + 1,
                rows.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")
            ));
        }
        let hand = simplify_all(&with(shift_98, pt));
        let e = simplify_all(&e);
        let differs = |reduced: &Atom| !simplify_all(&(&e - reduced)).is_zero();
        if differs(&hand) {
            differ.push(k + 1);
        }
        if differs(&e) {
            differ_undone.push(k + 1);
        }
        shown.push(format!("point {}: exact {e}, reduced {hand}", k + 1));
    }
    let checks = vec![
        Check {
            perturbed: Some(crate::Perturbed {
                what: format!("the exact shift epsilon/theta scaled by {}", crate::falsify::FACTOR),
                holds: scaled_solves,
            }),
            section: "98".into(),
            id: "shift_98_exact_solves".into(),
            statement: "the exact first-order lateral shift epsilon/theta of a steady turn without hands (generated shift_98_exact: the mechanics engine's general bicycle with the body turned by epsilon about the ground trace OI, linearised, Carvallo's bicycle as a parameter set of it) with the steer it implies makes the lean and the steer rows vanish with no steer torque, at three exact rational points".into(),
            holds: residual_bad.is_empty(),
            detail: if residual_bad.is_empty() { "residuals 0".into() } else { residual_bad.join("; ") },
        },
        Check {
            // The reductions undone: the reduced route's shift is then the exact one, and no
            // point can differ.
            perturbed: Some(crate::Perturbed {
                what: "the reduced route's shift (shift_98) replaced by the exact one, as if the reductions of n° 86 were undone".into(),
                holds: differ_undone.len() == 3,
            }),
            section: "98".into(),
            id: "shift_98_reduction_matters".into(),
            statement: "the exact first-order shift (shift_98_exact) differs from the reduced route's (shift_98: n° 95-97 with the reduced fall equation (3)' of n° 86) at the three rational points (informative: the reductions of n° 86 change the shift)".into(),
            holds: differ.len() == 3,
            detail: shown.join("; "),
        },
    ];
    Ok((exact, checks))
}

fn compare(section: &str, id: &str, statement: &str, derived: &Atom, expected: &Atom) -> Check {
    let diff = simplify_all(&(derived - expected));
    let perturbed = crate::falsify::perturb_one(derived, |d| is_zero_all(&(d - expected)));
    Check {
        perturbed: Some(perturbed),
        section: section.to_string(),
        id: id.to_string(),
        statement: statement.to_string(),
        holds: is_zero_all(&diff),
        detail: format!(
            "derived: {}; expected: {}; simplified difference (exact, reduced with sin^2+cos^2=1 for every angle): {}",
            show_all(derived),
            show_all(expected),
            show_all(&diff)
        ),
    }
}

fn formula(name: &str, section: &str, description: &str, e: &Atom) -> Formula {
    Formula {
        name: name.to_string(),
        section: section.to_string(),
        description: description.to_string(),
        expr: to_trig_all(&simplify_all(e)),
    }
}

fn printed_formula(name: &str, p: &Printed, description: &str) -> Formula {
    Formula {
        name: name.to_string(),
        section: p.section.to_string(),
        description: description.to_string(),
        expr: expr(p.text),
    }
}

// ---------------------------------------------------------------------------------------
// Vectors of the rear wheel's trihedra (frame.rs) and of the front wheel's (I1, J1, K).

fn k_big() -> Vector {
    Vector::unit(Trihedron::IJK, 2)
}

/// The steady rotation of the trihedra, $nK$ (p = 0).
fn spin() -> Vector {
    Vector::new(Trihedron::IJK, zero(), zero(), var("n"))
}

/// Steady time derivative of a vector fixed relative to the turning trihedra: $|nK\,v$.
fn rot(v: &Vector) -> Vector {
    spin().cross(v)
}

/// $S - O = kR$.
fn centre_rear() -> Vector {
    Vector::new(Trihedron::Ijk, zero(), zero(), var("R"))
}

/// $O' = IRs$.
fn contact_velocity() -> Vector {
    Vector::new(Trihedron::Ijk, var("R") * var("s"), zero(), zero())
}

/// A point of the loaded frame, $M - O = Ix_m + jy_m + kz_m$.
fn frame_point() -> Vector {
    Vector::new(Trihedron::Ijk, var("xm"), var("ym"), var("zm"))
}

/// $\sum m F$ over the loaded frame for F polynomial of degree at most 2 in $x_m, y_m, z_m$:
/// $\sum m = \mu$, $\sum m x = \mu e$, $\sum m z = \mu h$, $\sum m zx = L$, the moments
/// $A, B, C$ about OI, Oj, Ok, and the frame symmetric about its plane ($\sum m y = \sum m xy
/// = \sum m yz = 0$, n° 83).
///
/// # Panics
/// Panics on a monomial of degree above 2 (the derivation never produces one).
pub fn frame_sum(f: &Atom) -> Atom {
    frame_sum_shifted(f, None)
}

/// [`frame_sum`] for the loaded frame translated sideways by `shift` along j (n° 98: the
/// rider's body moved out of the frame's plane; the whole loaded frame is moved, which bounds
/// the rider's share): $\sum m y = \mu y_c$, $\sum m xy = \mu e y_c$, $\sum m yz = \mu h y_c$,
/// $\sum m y^2 = (A + C - B)/2 + \mu y_c^2$, the other sums unchanged ($A, B, C, L$ are the
/// unshifted frame's). `None` is the symmetric frame.
fn frame_sum_shifted(f: &Atom, shift: Option<&Atom>) -> Atom {
    let (x, y, w) = (var("xm"), var("ym"), var("zm"));
    let (a, b, c) = (var("A"), var("B"), var("C"));
    let yc = shift.cloned().unwrap_or_else(zero);
    let lateral = |moment: Atom| var("mu") * moment * &yc;
    let mut out = zero();
    for (key, coeff) in f.expand().coefficient_list::<u8>(&[x.clone(), y.clone(), w.clone()]) {
        let value = match (degree(&key, &x), degree(&key, &y), degree(&key, &w)) {
            (0, 0, 0) => var("mu"),
            (1, 0, 0) => var("mu") * var("e"),
            (0, 0, 1) => var("mu") * var("h"),
            (1, 0, 1) => var("L"),
            (2, 0, 0) => (&b + &c - &a) / Atom::num(2),
            (0, 2, 0) => (&a + &c - &b) / Atom::num(2) + lateral(yc.clone()),
            (0, 0, 2) => (&a + &b - &c) / Atom::num(2),
            (0, 1, 0) => lateral(Atom::num(1)),
            (1, 1, 0) => lateral(var("e")),
            (0, 1, 1) => lateral(var("h")),
            other => panic!("frame sum of a monomial of degree {other:?}"),
        };
        out += coeff * value;
    }
    out.expand()
}

/// The frame's virtual velocity for the rotations `c = [c_I, c_eta, c_nu]`: $c_I\,|I(M-O)
/// - c_\eta\,|j(M-S) + c_\nu\,|K(M-O)$ (n° 83, 91).
fn frame_virtual(c: &[Atom; 3], r: &Vector) -> Vector {
    let i = Vector::unit(Trihedron::Ijk, 0);
    let j = Vector::unit(Trihedron::Ijk, 1);
    let rs = r.sub(&centre_rear());
    i.cross(r)
        .scale(&c[0])
        .add(&j.cross(&rs).scale(&-(c[1].clone())))
        .add(&k_big().cross(r).scale(&c[2]))
}

/// Its steady time derivative: $I' = |nK\,I$, $j' = |nK\,j$, $K' = 0$, $(M-O)' = |nK(M-O)$,
/// $(M-S)' = |nK(M-S)$, the coefficients constant.
fn frame_virtual_dot(c: &[Atom; 3], r: &Vector) -> Vector {
    let i = Vector::unit(Trihedron::Ijk, 0);
    let j = Vector::unit(Trihedron::Ijk, 1);
    let rs = r.sub(&centre_rear());
    rot(&i)
        .cross(r)
        .add(&i.cross(&rot(r)))
        .scale(&c[0])
        .add(&rot(&j).cross(&rs).add(&j.cross(&rot(&rs))).scale(&-(c[1].clone())))
        .add(&k_big().cross(&rot(r)).scale(&c[2]))
}

/// The loaded frame's steady $\sum m M'|(dM/d\,\cdot)'$ by route A and by route B, and its
/// gravity term $g\sum m K|dM/d\,\cdot$.
fn frame_terms(c: &[Atom; 3]) -> (Atom, Atom, Atom) {
    frame_terms_shifted(c, None)
}

/// [`frame_terms`] for the loaded frame translated sideways by `shift` ([`frame_sum_shifted`]).
fn frame_terms_shifted(c: &[Atom; 3], shift: Option<&Atom>) -> (Atom, Atom, Atom) {
    let r = frame_point();
    let vel = contact_velocity().add(&rot(&r));
    let acc = rot(&contact_velocity()).add(&rot(&rot(&r)));
    let v = frame_virtual(c, &r);
    let route_a = frame_sum_shifted(&vel.dot(&frame_virtual_dot(c, &r)), shift);
    let route_b = -frame_sum_shifted(&acc.dot(&v), shift);
    let gravity = var("g") * frame_sum_shifted(&k_big().dot(&v), shift);
    (simplify_all(&route_a), simplify_all(&route_b), simplify_all(&gravity))
}

/// n° 83: the loaded frame's $\sum m M'|(dM/d\theta)'$ in any motion (not only a steady one):
/// $M' = IRs + |\Phi(M - O) - \eta'|j(M - S)$ with $\Phi = pI + nK$ (as in n° 99),
/// $S' = O' + |\Phi(S - O)$, $I' = |\Phi I$, $j' = |\Phi j$, $K' = 0$; the whole sum from the
/// time derivative of the virtual velocity, and each of the memoir's six terms from its
/// definition ($[abc] = a|(b \times c)$), compared with the printed ones; the sum of the six is
/// the whole, and at $p = \eta' = 0$ with constant $d\eta/d\theta$, $d\nu/d\theta$ it is the
/// steady frame term of n° 85.
fn frame_six_terms() -> Vec<Check> {
    use memoir as m;
    let (deta, dnu, ddeta, ddnu) = (var("deta"), var("dnu"), var("ddeta"), var("ddnu"));
    let eta_t = var("deta_t");
    let phi = Vector::new(Trihedron::IJK, var("p"), zero(), var("n"));
    let i = Vector::unit(Trihedron::Ijk, 0);
    let j = Vector::unit(Trihedron::Ijk, 1);
    let kk = k_big();
    let r = frame_point();
    let rs = r.sub(&centre_rear());
    let o_dot = contact_velocity();
    let s_dot = o_dot.add(&phi.cross(&centre_rear()));
    let m_dot = o_dot.add(&phi.cross(&r)).add(&j.cross(&rs).scale(&-eta_t.clone()));
    let (i_dot, j_dot) = (phi.cross(&i), phi.cross(&j));
    let triple = |a: &Vector, b: &Vector| frame_sum(&a.dot(&b.cross(&m_dot)));
    let terms = [
        &deta * triple(&j, &s_dot),
        -(&dnu * triple(&kk, &o_dot)),
        triple(&i_dot, &r),
        -(&deta * triple(&j_dot, &rs)),
        -(&ddeta * triple(&j, &rs)),
        &ddnu * triple(&kk, &r),
    ];
    // (dM/dθ)' = |I'(M-O) + |I(M'-O') - (dη/dθ)'|j(M-S) - dη/dθ (|j'(M-S) + |j(M'-S'))
    //          + (dν/dθ)'|K(M-O) + dν/dθ |K(M'-O').
    let virtual_dot = i_dot
        .cross(&r)
        .add(&i.cross(&m_dot.sub(&o_dot)))
        .add(&j.cross(&rs).scale(&-ddeta.clone()))
        .add(&j_dot.cross(&rs).add(&j.cross(&m_dot.sub(&s_dot))).scale(&-deta.clone()))
        .add(&kk.cross(&r).scale(&ddnu))
        .add(&kk.cross(&m_dot.sub(&o_dot)).scale(&dnu));
    let whole = frame_sum(&m_dot.dot(&virtual_dot));
    let printed_terms = [
        &m::FRAME_83_1,
        &m::FRAME_83_2,
        &m::FRAME_83_3,
        &m::FRAME_83_4,
        &m::FRAME_83_5,
        &m::FRAME_83_6,
    ];
    let mut checks = Vec::new();
    let mut sum = zero();
    for (k, (t, p)) in terms.iter().zip(printed_terms).enumerate() {
        checks.push(compare(
            "83",
            &format!("frame_83_term{}", k + 1),
            &format!("the loaded frame's term ({}) of n° 83, derived from its definition in any motion (p, eta', (d eta/d theta)', (d nu/d theta)' kept), is the printed one", k + 1),
            t,
            &printed(p),
        ));
        sum += t;
    }
    checks.push(compare("83", "frame_83_six_terms_sum", "the six terms of n° 83 add up to the whole sum m M'|(dM/d theta)' from the time derivative of the virtual velocity (the first line's three parallelograms and the O' term vanish)", &sum, &whole));
    let steady =
        with(&whole, &[("p", zero()), ("deta_t", zero()), ("ddeta", zero()), ("ddnu", zero())]);
    checks.push(compare("83", "frame_83_steady", "at p = eta' = 0 and constant d eta/d theta, d nu/d theta (a steady state: the underlined terms vanish) the whole frame term of n° 83 is the steady one derived for n° 85", &steady, &frame_terms(&[Atom::num(1), deta.clone(), dnu.clone()]).0));
    checks
}

/// The hoop's steady moment of the inertia forces about its contact point (n° 6 with
/// $A_1, B_1, C_1, \mu_1$, at $p = p' = n' = s' = 0$), on (I, J, K); its momentum moment
/// about O; and $O'$, $S'$.
fn hoop_steady() -> ([Atom; 3], [Atom; 3], [Atom; 3], [Atom; 3]) {
    let (a1, b1, c1) = (var("A1"), var("B1"), var("C1"));
    let h_pqr = hoop::motion::momentum_moment(&a1, &b1, &c1);
    let steady = |e: &Atom| {
        with(
            &subst(&hoop::motion::to_pns(e), "mu", &var("mu1")),
            &[("p", zero()), ("dp", zero()), ("dn", zero()), ("ds", zero())],
        )
    };
    let mom = hoop::motion::inertia_moment(&h_pqr).map(steady).to(Trihedron::IJK);
    let h = Vector::new(
        Trihedron::Ijk,
        zero(),
        &b1 * (var("s") + var("n") * sin_t()),
        &c1 * var("n") * cos_t(),
    )
    .to(Trihedron::IJK);
    let s_dot = contact_velocity().add(&rot(&centre_rear())).to(Trihedron::IJK);
    (mom.comps, h.comps, contact_velocity().to(Trihedron::IJK).comps, s_dot.comps)
}

fn dot3(a: &[Atom; 3], b: &[Atom; 3]) -> Atom {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

fn cross3(a: &[Atom; 3], b: &[Atom; 3]) -> [Atom; 3] {
    [&a[1] * &b[2] - &a[2] * &b[1], &a[2] * &b[0] - &a[0] * &b[2], &a[0] * &b[1] - &a[1] * &b[0]]
}

/// $|nK\,v$ on a direct trihedron whose third vector is K.
fn spin3(v: &[Atom; 3]) -> [Atom; 3] {
    [-(var("n") * &v[1]), var("n") * &v[0], zero()]
}

/// A wheel's steady terms for the virtual rotation `theta` about its contact point, all on
/// the wheel's (I, J, K): route A $\Theta'|H - \mu_1[\Theta O'S']$, route B $-\Theta|\mathfrak
/// J$, and the gravity $g\mu_1 K|\,|\Theta\,kR$.
fn wheel_terms(
    theta: &[Atom; 3],
    hoop: &([Atom; 3], [Atom; 3], [Atom; 3], [Atom; 3]),
    k: &[Atom; 3],
) -> (Atom, Atom, Atom) {
    let (mom, h, o_dot, s_dot) = hoop;
    let mu1 = var("mu1");
    let route_a = dot3(&spin3(theta), h) - &mu1 * dot3(theta, &cross3(o_dot, s_dot));
    let route_b = -dot3(theta, mom);
    let gravity = var("g") * &mu1 * var("R") * cross3(theta, k)[2].clone();
    (simplify_all(&route_a), simplify_all(&route_b), simplify_all(&gravity))
}

/// The front wheel as the hoop with θ₁, s₁ for θ, s.
fn to_front(e: &Atom) -> Atom {
    with(e, &[("sin_theta", sn("theta1")), ("cos_theta", cs("theta1")), ("s", var("s1"))])
}

/// The components on $(I_1, J_1, K)$ of $I$, $J$, $j$ and of the front axle $j_1$.
fn front_basis() -> [[Atom; 3]; 4] {
    let (sa, ca) = (sn("alpha"), cs("alpha"));
    let (st, ct) = (sin_t(), cos_t());
    let i = [ca.clone(), -sa.clone(), zero()];
    let jj = [sa.clone(), ca.clone(), zero()];
    let j = [&sa * &ct, &ca * &ct, st];
    let j1 = [zero(), cs("theta1"), sn("theta1")];
    [i, jj, j, j1]
}

fn comb(terms: &[(&[Atom; 3], Atom)]) -> [Atom; 3] {
    let mut out = [zero(), zero(), zero()];
    for (v, k) in terms {
        for (o, x) in out.iter_mut().zip(v.iter()) {
            *o = &*o + &(k * x);
        }
    }
    out
}

/// The steering axis $G = -I\sin\eta + k\cos\eta$ on $(I_1, J_1, K)$.
fn steering_axis() -> [Atom; 3] {
    let [i, jj, _, _] = front_basis();
    let k = [zero(), zero(), Atom::num(1)];
    let (se, ce) = (sn("eta"), cs("eta"));
    comb(&[(&i, -se), (&jj, -(sin_t() * &ce)), (&k, cos_t() * ce)])
}

/// Keeps the coefficient of `eps^order` after the substitutions, and reports whether every
/// lower power vanished.
fn leading(e: &Atom, subs: &[(&str, Atom)], order: u32) -> (Atom, bool) {
    let eps = var("eps");
    let mut out = zero();
    let mut lower_zero = true;
    for (key, coeff) in with(e, subs).expand().coefficient_list::<u8>(std::slice::from_ref(&eps)) {
        let k = degree(&key, &eps);
        if k == order {
            out += coeff;
        } else if k < order && !is_zero_all(&coeff) {
            lower_zero = false;
        }
    }
    (out.expand(), lower_zero)
}

/// Small angles θ, θ₁, α and rates of their order (n° 86, 95): $\sin \to \varepsilon\,x$,
/// $\cos \to 1$; $n$, $d\eta/d\theta$, $d\eta/d\gamma$ of the first order, $d\nu/d\theta$ of
/// the second (n° 86).
fn small() -> Vec<(&'static str, Atom)> {
    let eps = var("eps");
    vec![
        ("sin_theta", &eps * var("theta")),
        ("cos_theta", Atom::num(1)),
        ("sin_theta1", &eps * var("theta1")),
        ("cos_theta1", Atom::num(1)),
        ("sin_alpha", &eps * var("alpha")),
        ("cos_alpha", Atom::num(1)),
        ("n", &eps * var("n")),
        ("deta", &eps * var("deta")),
        ("dnu", eps.pow(Atom::num(2)) * var("dnu")),
        ("deta_g", &eps * var("deta_g")),
    ]
}

/// Derives every formula of the model and runs the checks.
pub fn derive() -> Result<Derivation> {
    use memoir as m;
    let mut checks: Vec<Check> = Vec::new();
    let (mu, mu1, r_, g, e_, h_) = (var("mu"), var("mu1"), var("R"), var("g"), var("e"), var("h"));
    let (l_, c_) = (var("l"), var("c"));
    let (st, ct) = (sin_t(), cos_t());
    let (deta, dnu, deta_g, dnu_g) = (var("deta"), var("dnu"), var("deta_g"), var("dnu_g"));
    let one = Atom::num(1);

    // n° 81: rear wheel, virtual rotation I + K dν/dθ about O.
    let hoop_s = hoop_steady();
    let rear_theta = [one.clone(), zero(), dnu.clone()];
    let k_rear = [zero(), -st.clone(), ct.clone()];
    let (rear_a, rear_b, rear_grav) = wheel_terms(&rear_theta, &hoop_s, &k_rear);
    checks.push(compare("81", "rear_routes", "rear wheel: Carvallo's route (Theta'|H - mu1 [Theta O' S'], n° 81) equals -Theta|J from the hoop's moment of the inertia forces (route B)", &rear_a, &rear_b));
    checks.push(compare(
        "85",
        "fall_rear_memoir",
        "rear wheel's steady term of the fall equation is the printed row of n° 85",
        &rear_a,
        &printed(&m::FALL_REAR),
    ));
    let rear_height = -(&g * &mu1 * &r_ * &st);
    checks.push(compare(
        "84",
        "grav_rear_heights",
        "rear wheel gravity by the virtual velocity equals g mu1 d(R cos theta)/d theta",
        &rear_grav,
        &rear_height,
    ));
    checks.push(compare(
        "85",
        "fall_grav_rear_memoir",
        "rear wheel gravity term is the printed row of n° 84-85",
        &rear_grav,
        &printed(&m::GRAV_REAR),
    ));

    // n° 82: front wheel, Theta1 = I - j dη/dθ + K dν/dθ + j1 dσ1/dθ about O1.
    let front = (
        hoop_s.0.clone().map(|x| to_front(&x)),
        hoop_s.1.clone().map(|x| to_front(&x)),
        hoop_s.2.clone().map(|x| to_front(&x)),
        hoop_s.3.clone().map(|x| to_front(&x)),
    );
    let [bi, _bj, bjs, bj1] = front_basis();
    let kk = [zero(), zero(), one.clone()];
    let k1 = [zero(), -sn("theta1"), cs("theta1")];
    let dsig = var("dsig");
    let theta1 = comb(&[
        (&bi, one.clone()),
        (&bjs, -deta.clone()),
        (&kk, dnu.clone()),
        (&bj1, dsig.clone()),
    ]);
    let (front_a, front_b, front_grav) = wheel_terms(&theta1, &front, &k1);
    checks.push(compare("82", "front_routes", "front wheel: Carvallo's route (Theta1'|H1 - mu1 [Theta1 O1' S1']) equals -Theta1|J1 (route B); d sigma1/d theta drops out", &front_a, &front_b));
    checks.push(compare(
        "85",
        "fall_front_memoir",
        "front wheel's steady term of the fall equation is the printed row of n° 85",
        &front_a,
        &printed(&m::FALL_FRONT),
    ));
    checks.push(compare(
        "85",
        "fall_grav_front_memoir",
        "front wheel gravity term is the printed row of n° 84-85",
        &front_grav,
        &printed(&m::GRAV_FRONT),
    ));

    // Minimum geometry: the front axle, sin θ1 (n° 97), tan α (n° 57), G|I1 = -sin ω.
    let (sg, cg) = (sn("gamma"), cs("gamma"));
    let (se, ce) = (sn("eta"), cs("eta"));
    let j_ijk = [zero(), ct.clone(), st.clone()];
    let h_ijk = [ce.clone(), -(&st * &se), &ct * &se];
    let axle = comb(&[(&j_ijk, cg.clone()), (&h_ijk, -sg.clone())]);
    let sin_theta1_97 = &st * &cg - &ct * &se * &sg;
    let tan_alpha_57 = &ce * &sg / (&ct * &cg + &st * &sg * &se);
    checks.push(compare("97", "front_axle_lean", "the front axle j cos(gamma) - H sin(gamma) (normal to G and H1) has the vertical component sin(theta1) printed in n° 97", &axle[2], &sin_theta1_97));
    checks.push(compare(
        "57",
        "front_axle_alpha",
        "its horizontal part is cos(theta1) J1 with tan(alpha) as printed in n° 57 and 103",
        &(-(axle[0].clone()) / &axle[1]),
        &tan_alpha_57,
    ));
    let cos_theta1_sq = Atom::num(1) - sin_theta1_97.pow(Atom::num(2));
    let c1_ca = &ct * &cg + &st * &sg * &se; // cos θ1 cos α
    let c1_sa = &ce * &sg; // cos θ1 sin α
    checks.push(compare("57", "front_axle_unit", "(cos theta1 cos alpha)^2 + (cos theta1 sin alpha)^2 = 1 - sin(theta1)^2 (the axle is a unit vector)", &(c1_ca.pow(Atom::num(2)) + c1_sa.pow(Atom::num(2))), &cos_theta1_sq));
    let g_axis = steering_axis();
    let g_i1_cos1 = with(
        &(&g_axis[0] * cs("theta1")),
        &[("cos_alpha", &c1_ca / cs("theta1")), ("sin_alpha", &c1_sa / cs("theta1"))],
    );
    let tan_omega_48 = &se / &ce * &cg + &st / &ct * &sg / &ce;
    checks.push(compare("66 bis", "g_i1_sin_omega", "-G|I1 cos(theta1) = tan(omega) cos(eta) cos(theta) with tan(omega) of (2), n° 48: -G|I1 = sin(omega), cos(omega) = cos(eta) cos(theta)/cos(theta1) (n° 66 bis: G|I1 = -sin(omega))", &(-g_i1_cos1.clone()), &(&tan_omega_48 * &ce * &ct)));
    checks.push(compare(
        "66 bis",
        "g_i1_unit",
        "(G|I1)^2 + (cos(eta) cos(theta)/cos(theta1))^2 = 1, so omega is an angle",
        &(g_i1_cos1.pow(Atom::num(2)) + (&ce * &ct).pow(Atom::num(2))),
        &cos_theta1_sq,
    ));
    let sin_omega = -g_axis[0].clone();
    // Front gravity by the height R cos θ1 and dθ1/dθ at fixed γ.
    let dsin1 = hoop::lagrange::d_theta(&sin_theta1_97)
        + d(&sin_theta1_97, "sin_eta") * &ce * &deta
        - d(&sin_theta1_97, "cos_eta") * &se * &deta;
    let front_height = -(&g * &mu1 * &r_ * sn("theta1") * &dsin1 / cs("theta1"));
    let front_grav_gamma = with(
        &front_grav,
        &[("cos_alpha", &c1_ca / cs("theta1")), ("sin_alpha", &c1_sa / cs("theta1"))],
    );
    checks.push(compare("84", "grav_front_heights", "front wheel gravity by the virtual velocity equals g mu1 d(R cos theta1)/d theta with theta1(theta, gamma, eta(theta)) of the axle (alpha written with gamma)", &front_grav_gamma, &front_height));

    // n° 83: the loaded frame.
    let (frame_a, frame_b, frame_grav) = frame_terms(&[one.clone(), deta.clone(), dnu.clone()]);
    checks.push(compare(
        "83",
        "frame_routes",
        "loaded frame: Carvallo's sum m M'|(dM/d theta)' equals -sum m M''|dM/d theta (route B)",
        &frame_a,
        &frame_b,
    ));
    checks.push(compare(
        "85",
        "fall_frame_memoir",
        "the loaded frame's steady term of the fall equation is the printed row of n° 85",
        &frame_a,
        &printed(&m::FALL_FRAME),
    ));
    let (x0, z0) = (var("x0"), var("z0"));
    let (se1, ce1) = (sn("eta1"), cs("eta1"));
    let zc = (&r_ + &x0 * &se1 + &z0 * &ce1) * &ct;
    let dzc = hoop::lagrange::d_theta(&zc)
        + (d(&zc, "sin_eta1") * &ce1 - d(&zc, "cos_eta1") * &se1) * &deta;
    let dzc = with(
        &dzc,
        &[("x0", &e_ * &ce1 + (&h_ - &r_) * &se1), ("z0", -(&e_ * &se1) + (&h_ - &r_) * &ce1)],
    );
    checks.push(compare("84", "grav_frame_heights", "frame gravity by the virtual velocity equals g mu dZ/d theta with the height Z = (R + x sin(eta1) + z cos(eta1)) cos(theta) of n° 69 and e, h the current coordinates", &frame_grav, &(&g * &mu * dzc)));
    checks.push(compare(
        "85",
        "fall_grav_frame_memoir",
        "frame gravity term is the printed row of n° 84-85",
        &frame_grav,
        &printed(&m::GRAV_FRAME),
    ));
    let fall = &rear_a + &front_a + &frame_a - (&rear_grav + &front_grav + &frame_grav);
    let fall_memoir = printed(&m::FALL_REAR) + printed(&m::FALL_FRONT) + printed(&m::FALL_FRAME)
        - printed(&m::GRAV_REAR)
        - printed(&m::GRAV_FRONT)
        - printed(&m::GRAV_FRAME);

    // n° 90–94: the handlebar equation.
    let theta1_g = comb(&[
        (&g_axis, one.clone()),
        (&bjs, -deta_g.clone()),
        (&kk, dnu_g.clone()),
        (&bj1, var("dsig_g")),
    ]);
    let (steer_front_a, steer_front_b, steer_grav_front) = wheel_terms(&theta1_g, &front, &k1);
    checks.push(compare(
        "92",
        "steer_front_routes",
        "front wheel, handlebar: Carvallo's route with G' = |nK G equals -Theta1|J1 (route B)",
        &steer_front_a,
        &steer_front_b,
    ));
    checks.push(compare(
        "94",
        "steer_front_memoir",
        "front wheel's steady term of the handlebar equation is the printed row of n° 94",
        &steer_front_a,
        &printed(&m::STEER_FRONT),
    ));
    let omega_rule = [("sin_omega", sin_omega.clone())];
    checks.push(compare("94", "steer_grav_front_memoir", "front wheel gravity term of the handlebar equation is the printed row of n° 93-94 (sin(omega) = -G|I1)", &steer_grav_front, &with(&printed(&m::STEER_GRAV_FRONT), &omega_rule)));
    let (steer_frame_a, steer_frame_b, steer_grav_frame) =
        frame_terms(&[zero(), deta_g.clone(), dnu_g.clone()]);
    checks.push(compare(
        "91",
        "steer_frame_routes",
        "loaded frame, handlebar: route A equals route B",
        &steer_frame_a,
        &steer_frame_b,
    ));
    checks.push(compare(
        "94",
        "steer_frame_memoir",
        "the loaded frame's steady term of the handlebar equation is the printed row of n° 94",
        &steer_frame_a,
        &printed(&m::STEER_FRAME),
    ));
    checks.push(compare(
        "94",
        "steer_grav_frame_memoir",
        "frame gravity term of the handlebar equation is the printed row of n° 94",
        &steer_grav_frame,
        &printed(&m::STEER_GRAV_FRAME),
    ));
    let steer = &steer_front_a + &steer_frame_a - (&steer_grav_front + &steer_grav_frame);

    // n° 86: first order of the fall equation, n = (R/l) s tan(alpha) (n° 66 (2) simplified).
    let n_86 = &r_ / &l_ * var("s") * var("alpha");
    let (fall1, fall0_zero) = leading(&fall, &small(), 1);
    let fall1 = subst(&fall1, "n", &n_86);
    let no_wheels = [("mu1", zero()), ("B1", zero()), ("C1", zero())];
    let (fall86_1, _) = leading(&printed(&m::FALL_86), &small(), 1);
    let mut chk = compare("86", "fall_86_first_order", "the derived fall equation at first order in theta, theta1, alpha (n, d eta/d theta first order, d nu/d theta second, n° 86), wheels taken out (the memoir merges them into the frame's letters), equals the printed (1) of n° 86 at first order", &with(&fall1, &no_wheels), &subst(&fall86_1, "n", &n_86));
    chk.holds &= fall0_zero;
    chk.detail = format!("order 0 vanishes: {fall0_zero}; {}", chk.detail);
    checks.push(chk);
    // (3) and (3)': frame only, d eta/d theta = d nu/d theta = 0, the (B - C) n^2 term of the
    // third order dropped, solved for tan(theta) = T.
    let tan_a = sn("alpha") / cs("alpha");
    let reduced =
        with(&(&frame_a - &frame_grav), &[("deta", zero()), ("dnu", zero()), ("B", var("C"))]);
    let reduced = subst(&reduced, "n", &(&r_ / &l_ * var("s") * &tan_a));
    let t = var("T");
    let reduced_t = simplify_all(&(subst(&reduced, "sin_theta", &(&t * &ct)) / &ct));
    let coef_t = simplify_all(&d(&reduced_t, "T"));
    let tan_theta_86 = simplify_all(&(-subst(&reduced_t, "T", &zero()) / &coef_t));
    let homogeneous = is_zero_all(&d(&reduced_t, "cos_theta"));
    let mut chk = compare("86", "tan_theta_86_memoir", "the reduced (3) of n° 86 (frame, d eta/d theta = 0, (B - C) n^2 sin cos dropped, n = (R/l) s tan(alpha)) solved for tan(theta) is the printed (3)' of n° 86 bis", &tan_theta_86, &printed(&m::TAN_THETA_86));
    chk.holds &= homogeneous;
    chk.detail = format!("homogeneous in sin, cos of theta: {homogeneous}; {}", chk.detail);
    checks.push(chk);
    let ratio_88 = simplify_all(&(&tan_a / &tan_theta_86));
    checks.push(compare(
        "88",
        "ratio_88_memoir",
        "tan(alpha)/tan(theta) from (3)' is the printed (1) of n° 88",
        &ratio_88,
        &printed(&m::RATIO_88),
    ));
    let tan_t = &st / &ct;
    let curvature_87 = simplify_all(&(&r_ / &l_ * &ratio_88 * &tan_t));
    checks.push(compare(
        "87",
        "curvature_87_memoir",
        "the curvature n/s = (R/l) tan(alpha) along (3)' is the printed -g tan(theta)/(R s^2)",
        &curvature_87,
        &printed(&m::CURVATURE_87),
    ));
    // n° 89: ratio of the neglected term to the gravity term, d eta/d theta = -y/(x cos).
    let neglected = -(&mu * &g * &e_ * &ct * &deta) / (&mu * &g * &h_ * &st);
    let eps89 = subst(&neglected, "deta", &(-var("y") / (var("x") * &ct)));
    let bound_89 = simplify_all(&with(&eps89, &[("y", &c_ * &st), ("x", l_.clone())]));
    checks.push(compare("89", "epsilon_89", "the relative size of the neglected -mu g e cos(theta) d eta/d theta with d eta/d theta = -y/(x cos(theta)) is e y/(h x sin(theta)) as printed in (1) of n° 89", &eps89, &(&e_ / &h_ * var("y") / (var("x") * &st))));
    checks.push(compare(
        "89",
        "epsilon_bound_89_memoir",
        "with y/sin(theta) bounded by c and x = l it is the printed bound e c/(h l)",
        &bound_89,
        &printed(&m::EPSILON_BOUND_89),
    ));

    // n° 95: the handlebar equation reduced with the memoir's simplified n° 66 forms.
    let geometry_95 = [
        ("n", &r_ / &l_ * var("s") * &tan_a),
        ("s1", var("s") / cs("alpha")),
        ("deta_g", (&r_ * sn("omega") - &c_) * sn("theta1") / (&l_ * &ct)),
        ("dnu_g", (&r_ * sn("omega") - &c_) * cs("theta1") / (&l_ * cs("alpha"))),
        ("B1", Atom::num(2) * &mu1 * r_.pow(Atom::num(2))),
    ];
    let before = with(&printed(&m::STEER_95_BEFORE), &geometry_95[..1]);
    let before = with(&before, &geometry_95[4..]);
    let before_divided = simplify_all(&(-before / (&r_ * &g * cs("theta1"))));
    checks.push(compare("95", "steer_95_from_before", "the printed equation before (1) of n° 95, with n = (R/l) s tan(alpha), B1 = 2 mu1 R^2, divided by -R g cos(beta), is the printed (1)", &before_divided, &printed(&m::STEER_95)));
    let first_order_95 = {
        let mut subs = vec![("sin_omega", sn("eta"))];
        subs.extend(small());
        subs
    };
    let steer_geo = with(&steer, &geometry_95);
    let (steer1, steer0_zero) = leading(&steer_geo, &first_order_95, 1);
    let (steer95_1, _) = leading(&printed(&m::STEER_95), &first_order_95, 1);
    let mut chk = compare("95", "steer_95_first_order", "the derived handlebar equation with the memoir's n° 66 forms (x = l, y = 0, s1 = s/cos(alpha)), B1 = 2 mu1 R^2, at first order in theta, theta1, alpha with omega = eta, equals R g times the printed (1) of n° 95 at first order", &steer1, &(&r_ * &g * &steer95_1));
    chk.holds &= steer0_zero;
    chk.detail = format!("order 0 vanishes: {steer0_zero}; {}", chk.detail);
    checks.push(chk);
    // θ1/θ with α from (3)' at first order.
    let alpha_3p = -(&l_ / &r_) * &g / (&r_ * var("s").pow(Atom::num(2))) * var("theta");
    let steer1_theta = simplify_all(&subst(&steer1, "alpha", &alpha_3p));
    let ratio_95 = simplify_all(&(-d(&steer1_theta, "theta") / d(&steer1_theta, "theta1")));
    let ratio_95_memoir = with(&printed(&m::THETA1_RATIO_95), &[("sin_omega", se.clone())]);
    let mut chk = compare("95", "theta1_ratio_memoir", "theta1/theta from the derived first-order handlebar equation and (3)' is the printed ratio of (1)' of n° 95 (omega = eta)", &ratio_95, &ratio_95_memoir);
    chk.detail.push_str("; (1)' writes mu1 where (1) has mu1 sin(omega): the front wheel's weight term loses its factor sin(omega) between (1) and (1)'");
    checks.push(chk);
    let (steer95_t, _) =
        leading(&with(&printed(&m::STEER_95), &[("sin_omega", se.clone())]), &small(), 1);
    let steer95_t = subst(&steer95_t, "alpha", &alpha_3p);
    let ratio_from_1 = simplify_all(&(-d(&steer95_t, "theta") / d(&steer95_t, "theta1")));
    checks.push(compare("95", "theta1_ratio_from_1", "theta1/theta from the printed (1) of n° 95 itself (first order, omega = eta) equals the derived ratio", &ratio_from_1, &ratio_95));
    // n° 97: geometry θ1 = θ - γ sin η, α = γ cos η at first order.
    let small_g = [
        ("sin_theta", var("eps") * var("theta")),
        ("cos_theta", one.clone()),
        ("sin_gamma", var("eps") * var("gamma")),
        ("cos_gamma", one.clone()),
    ];
    let (theta1_geo, _) = leading(&sin_theta1_97, &small_g, 1);
    // tan(alpha) = (cos theta1 sin alpha)/(cos theta1 cos alpha): the denominator is 1 at
    // order 0, so the first order of tan(alpha) is that of the numerator.
    let (alpha_geo, _) = leading(&c1_sa, &small_g, 1);
    let gamma_of_alpha = var("alpha") / &ce;
    checks.push(compare(
        "97",
        "alpha_first_order",
        "at first order tan(alpha) of n° 57 is gamma cos(eta)",
        &subst(&alpha_geo, "gamma", &gamma_of_alpha),
        &var("alpha"),
    ));
    let theta1_geo = subst(&subst(&theta1_geo, "gamma", &gamma_of_alpha), "alpha", &alpha_3p);
    let ratio_97 = simplify_all(&(&theta1_geo / var("theta")));
    let expected_97 = one.clone() + &g * &l_ / (&r_ * &r_ * var("s").pow(Atom::num(2))) * &se / &ce;
    let perturbed = crate::falsify::perturb_one(&ratio_97, |d| is_zero_all(&(d - &expected_97)));
    checks.push(Check {
        perturbed: Some(perturbed),
        section: "97".into(),
        id: "theta1_exceeds_theta".into(),
        statement: "geometry and (3)' give theta1/theta = 1 + (g l/(R s)^2) tan(eta) > 1 at first order (n° 97: theta1 > theta)".into(),
        holds: is_zero_all(&(&ratio_97 - &expected_97)),
        detail: format!("theta1/theta = {}", show_all(&ratio_97)),
    });
    // Beyond the memoir: the speed where the dynamic and geometric ratios agree, and the
    // lateral shift of n° 98 needed elsewhere.
    let k97 = simplify_all(&(&ratio_97 - &one));
    let k97_s2 = simplify_all(&(&k97 * var("s").pow(Atom::num(2))));
    ensure!(is_zero_all(&d(&k97_s2, "s")), "the geometric ratio is not 1 + K/s^2");
    let no_hands_s2 = simplify_all(&(&k97_s2 / (&ratio_95 - &one)));
    let no_hands_s2_memoir = simplify_all(&(&k97_s2 / (&ratio_95_memoir - &one)));
    let shift = |ratio: &Atom| simplify_all(&((&one - ratio + &k97) / (ratio - &k97)));
    let shift_98 = shift(&ratio_95);
    let shift_98_memoir = shift(&ratio_95_memoir);

    // n° 83: the loaded frame's six terms, in a motion that is not steady (p, eta' and the
    // rates of d eta/d theta, d nu/d theta kept), each from its definition.
    checks.extend(frame_six_terms());
    let (shift_98_exact, shift_checks) = shift_98_engine(&shift_98)?;
    checks.extend(shift_checks);

    // n° 98: the body moved sideways by y_c (the angle ε of the memoir, tan ε = y_c/h).
    let yc = var("yc");
    let (fall_a_98, _, fall_grav_98) =
        frame_terms_shifted(&[one.clone(), deta.clone(), dnu.clone()], Some(&yc));
    let (steer_a_98, _, steer_grav_98) =
        frame_terms_shifted(&[zero(), deta_g.clone(), dnu_g.clone()], Some(&yc));
    let mut chk = compare("98", "shift_fall_gravity", "moving the loaded frame sideways by y_c adds g mu y_c cos(theta) to the gravity term of the fall equation: mu g h sin(theta) becomes mu g (h sin(theta) + y_c cos(theta)) = mu g sqrt(h^2 + y_c^2) sin(theta + epsilon) with tan(epsilon) = y_c/h, the printed mu g h sin(theta + epsilon) of n° 98 at first order in epsilon", &(&fall_grav_98 - &frame_grav), &(&g * &mu * &yc * &ct));
    chk.detail = format!(
        "{}; exact change {}",
        chk.detail,
        show_all(&simplify_all(&(&fall_grav_98 - &frame_grav)))
    );
    checks.push(chk);
    let mut small_98 = small();
    small_98.push(("yc", var("eps") * &yc));
    let first_order_change = |change: &Atom| -> (Atom, bool, bool) {
        let (first, lower) = leading(change, &small_98, 1);
        (simplify_all(change), lower, is_zero_all(&first))
    };
    let (fall_inertia_change, low0, first0) = first_order_change(&(&fall_a_98 - &frame_a));
    let perturbed = crate::falsify::perturb_one(&fall_a_98, |d| {
        let (_, low, first) = first_order_change(&(d - &frame_a));
        low && first
    });
    checks.push(Check {
        perturbed: Some(crate::Perturbed { what: format!("{} (the shifted frame's inertia terms of the fall equation)", perturbed.what), ..perturbed }),
        section: "98".into(),
        id: "shift_fall_inertia".into(),
        statement: "the inertia (centrifugal) terms of the fall equation are unchanged by the sideways shift at first order in theta, alpha, n, d eta/d theta and y_c (n° 98: the moment of the centrifugal force is not changed appreciably)".into(),
        holds: low0 && first0,
        detail: format!("order 0 vanishes: {low0}; order 1 vanishes: {first0}; exact change {}", show_all(&fall_inertia_change)),
    });
    let steer_change = &(&steer_a_98 - &steer_grav_98) - &(&steer_frame_a - &steer_grav_frame);
    let (steer_change, low0, first0) = first_order_change(&steer_change);
    let grav_unchanged = is_zero_all(&(&steer_grav_98 - &steer_grav_frame));
    let unchanged = |a: &Atom| {
        let change = &(a - &steer_grav_98) - &(&steer_frame_a - &steer_grav_frame);
        let (_, low, first) = first_order_change(&change);
        low && first && grav_unchanged
    };
    let perturbed = crate::falsify::perturb_one(&steer_a_98, unchanged);
    checks.push(Check {
        perturbed: Some(crate::Perturbed { what: format!("{} (the shifted frame's inertia terms of the handlebar equation)", perturbed.what), ..perturbed }),
        section: "98".into(),
        id: "shift_steer_unchanged".into(),
        statement: "the handlebar equation is unchanged by the sideways shift at first order (its frame gravity term exactly, its inertia terms up to second order in theta, alpha, n, d eta/d gamma and y_c): n° 98's 'l'équation du guidon n'est pas changée'".into(),
        holds: low0 && first0 && grav_unchanged,
        detail: format!("gravity term unchanged: {grav_unchanged}; order 0 vanishes: {low0}; order 1 vanishes: {first0}; exact change {}", show_all(&steer_change)),
    });

    // n° 99–102: the loaded frame's kinetic energy.
    let phi = Vector::new(Trihedron::IJK, var("p"), zero(), var("n"));
    let r = frame_point();
    let j = Vector::unit(Trihedron::Ijk, 1);
    let vel = contact_velocity()
        .add(&phi.cross(&r))
        .add(&j.cross(&r.sub(&centre_rear())).scale(&-var("deta_t")));
    let twice_t0 = simplify_all(&frame_sum(&vel.dot(&vel)));
    checks.push(compare(
        "99",
        "kinetic_frame_memoir",
        "twice the loaded frame's kinetic energy from M' = IRs + |Phi(M - O) - eta' |j(M - S) is the printed 2 T0 of n° 99",
        &twice_t0,
        &printed(&m::KINETIC_FRAME),
    ));
    let t0 = &twice_t0 / Atom::num(2);
    let dt0 = [d(&t0, "p"), d(&t0, "deta_t"), d(&t0, "n")];
    for (id, val, pr) in [
        ("dt0_dp_memoir", &dt0[0], &m::DT0_DP),
        ("dt0_deta_memoir", &dt0[1], &m::DT0_DETA),
        ("dt0_dn_memoir", &dt0[2], &m::DT0_DN),
    ] {
        checks.push(compare(
            "100",
            id,
            "the partial derivative of T0 is the printed one of n° 100",
            val,
            &printed(pr),
        ));
    }
    let t0_p = with(&t0, &[("deta_t", &deta * var("p")), ("n", var("n") + &dnu * var("p"))]);
    let dfdpp = simplify_all(&d(&d(&t0_p, "p"), "p"));
    let mut chk = compare("102", "dfdpp_memoir", "the frame's coefficient of p' in the fall equation, d^2 T0/dp^2 with eta' = (d eta/d theta) p and dn/dp = d nu/d theta (n° 100), is the printed A of n° 102", &dfdpp, &printed(&m::DFDPP_102));
    chk.detail.push_str("; the memoir keeps A and neglects the rest as second order (it lists -L cos(theta) dn/dp and mu R^2 (y/(x cos theta))^2)");
    checks.push(chk);

    let wrap = |name: &str, section: &str, description: &str, e: &Atom| -> Result<Formula> {
        for extra in ["dsig", "dsig_g"] {
            ensure!(
                !e.contains_symbol(var(extra).get_symbol().expect("symbol")),
                "{name} keeps {extra}"
            );
        }
        Ok(formula(name, section, description, e))
    };
    let mut formulas = vec![
        wrap("fall_rear", "81", "Rear wheel: steady sum m M'|(dM/d theta)' (N m).", &rear_a)?,
        wrap("fall_front", "82", "Front wheel: steady sum m M'|(dM/d theta)' (N m).", &front_a)?,
        wrap("fall_frame", "83", "Loaded frame: steady sum m M'|(dM/d theta)' (N m).", &frame_a)?,
        wrap("fall_grav_rear", "84", "Rear wheel: g sum m dz/d theta (N m).", &rear_grav)?,
        wrap("fall_grav_front", "84", "Front wheel: g sum m dz/d theta (N m).", &front_grav)?,
        wrap("fall_grav_frame", "84", "Loaded frame: g sum m dz/d theta (N m).", &frame_grav)?,
        wrap("fall_equilibrium", "85", "Steady fall equation, centrifugal minus gravity terms (N m).", &fall)?,
        wrap("memoir_fall_equilibrium", "85", "The same from the printed table of n° 85 (N m).", &fall_memoir)?,
        wrap("steer_front", "92", "Front wheel: steady sum m M'|(dM/d gamma)' (N m).", &steer_front_a)?,
        wrap("steer_frame", "91", "Loaded frame: steady sum m M'|(dM/d gamma)' (N m).", &steer_frame_a)?,
        wrap("steer_grav_front", "93", "Front wheel: g sum m dz/d gamma (N m).", &steer_grav_front)?,
        wrap("steer_grav_frame", "93", "Loaded frame: g sum m dz/d gamma (N m).", &steer_grav_frame)?,
        wrap("steer_equilibrium", "94", "Steady handlebar equation, centrifugal minus gravity terms (N m).", &steer)?,
        wrap("minus_g_i1", "66 bis", "-G|I1, which n° 66 bis calls sin(omega) (dimensionless).", &sin_omega)?,
        wrap("fall_first_order", "86", "First-order fall equation, wheels kept, n = (R/l) s alpha; theta, theta1, alpha small (N m).", &fall1)?,
        wrap("tan_theta_86", "86", "(3)' derived: tan(theta) along the reduced fall equation (dimensionless).", &tan_theta_86)?,
        wrap("curvature_87", "87", "n/s along (3)', the memoir's curvature (turning rate per rolling rate; the path's curvature is n/(R s)) (dimensionless).", &curvature_87)?,
        wrap("ratio_88", "88", "tan(alpha)/tan(theta) along (3)' (dimensionless).", &ratio_88)?,
        wrap("epsilon_bound_89", "89", "Bound of the relative size of the neglected term of n° 86 (dimensionless).", &bound_89)?,
        wrap("steer_first_order", "95", "First-order handlebar equation with the memoir's n° 66 forms, omega = eta (N m).", &steer1)?,
        wrap("theta1_over_theta", "95", "theta1/theta of the derived first-order handlebar equation with (3)' (dimensionless).", &ratio_95)?,
        wrap("memoir_theta1_over_theta", "95", "theta1/theta of the printed (1)' with omega = eta (dimensionless).", &ratio_95_memoir)?,
        wrap("theta1_over_theta_geometry", "97", "theta1/theta imposed by the geometry with (3)', first order (dimensionless).", &ratio_97)?,
        wrap("no_hands_s2", "97", "s^2 at which a steady turn without hands needs no lateral shift (derived ratio) (1/s^2).", &no_hands_s2)?,
        wrap("memoir_no_hands_s2", "97", "The same with the printed ratio of (1)' (negative: none) (1/s^2).", &no_hands_s2_memoir)?,
        wrap("shift_98", "98", "Lateral shift epsilon/theta of n° 98 for a steady turn without hands (derived ratio).", &shift_98)?,
        wrap("memoir_shift_98", "98", "The same with the printed ratio of (1)'.", &shift_98_memoir)?,
        wrap("shift_98_exact", "98", "Lateral shift epsilon/theta of n° 98 for a steady turn without hands, exact at first order: the mechanics engine's bicycle with the body turned about OI, linearised (wheels' diametral moment C1 about the centre).", &shift_98_exact)?,
        wrap("kinetic_frame", "99", "Twice the loaded frame's kinetic energy (J).", &twice_t0)?,
        wrap("dt0_dp", "100", "dT0/dp (kg m^2/s).", &dt0[0])?,
        wrap("dt0_deta", "100", "dT0/d eta' (kg m^2/s).", &dt0[1])?,
        wrap("dt0_dn", "100", "dT0/dn (kg m^2/s).", &dt0[2])?,
        wrap("dfdpp_frame", "102", "The loaded frame's coefficient of p' in the fall equation (kg m^2).", &dfdpp)?,
    ];
    formulas.extend([
        printed_formula("memoir_fall_rear", &m::FALL_REAR, "Printed n° 85, rear wheel row."),
        printed_formula("memoir_fall_front", &m::FALL_FRONT, "Printed n° 85, front wheel row."),
        printed_formula("memoir_fall_frame", &m::FALL_FRAME, "Printed n° 85, loaded frame row."),
        printed_formula("memoir_fall_grav_rear", &m::GRAV_REAR, "Printed n° 85, rear gravity."),
        printed_formula("memoir_fall_grav_front", &m::GRAV_FRONT, "Printed n° 85, front gravity."),
        printed_formula("memoir_fall_grav_frame", &m::GRAV_FRAME, "Printed n° 85, frame gravity."),
        printed_formula("memoir_tan_theta_86", &m::TAN_THETA_86, "Printed (3)' of n° 86 bis."),
        printed_formula("memoir_curvature_87", &m::CURVATURE_87, "Printed n/s of n° 87."),
        printed_formula("memoir_ratio_88", &m::RATIO_88, "Printed (1) of n° 88."),
        printed_formula("memoir_epsilon_bound_89", &m::EPSILON_BOUND_89, "Printed bound of n° 89."),
        printed_formula("memoir_steer_front", &m::STEER_FRONT, "Printed n° 94, front wheel."),
        printed_formula("memoir_steer_frame", &m::STEER_FRAME, "Printed n° 94, loaded frame."),
        printed_formula(
            "memoir_steer_grav_front",
            &m::STEER_GRAV_FRONT,
            "Printed n° 94, front gravity.",
        ),
        printed_formula(
            "memoir_steer_grav_frame",
            &m::STEER_GRAV_FRAME,
            "Printed n° 94, frame gravity.",
        ),
        printed_formula("memoir_kinetic_frame", &m::KINETIC_FRAME, "Printed 2 T0 of n° 99."),
        printed_formula("memoir_dt0_dp", &m::DT0_DP, "Printed (1) of n° 100."),
        printed_formula("memoir_dt0_deta", &m::DT0_DETA, "Printed (2) of n° 100."),
        printed_formula("memoir_dt0_dn", &m::DT0_DN, "Printed (3) of n° 100."),
    ]);
    for f in &formulas {
        for sym in f.expr.get_all_symbols(false) {
            let name = sym.get_stripped_name();
            ensure!(
                PARAMS.contains(&name) || INPUTS.contains(&name),
                "formula {} uses the unexpected symbol {name}",
                f.name
            );
        }
    }
    let _ = (&frame_b, &front_b, &rear_b, &steer_front_b, &steer_frame_b);
    Ok(Derivation {
        model: "bicycle_steady".to_string(),
        source: file!().to_string(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: INPUTS.iter().map(|s| s.to_string()).collect(),
        formulas,
        checks,
        nominal: crate::derive::nominal::values("bicycle_steady"),
        horner_schemes: Vec::new(),
    })
}
