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
//! * Each sum is checked exactly (symbolically) against the closed form printed in n° 117.
//! * Every entry of the tables is derived independently from the general Carvallo–Whipple
//!   bicycle ([`crate::derive::whipple`]) with Carvallo's model written as a parameter set of it
//!   ([`whipple_mapping`]: hoop wheels, a massless front frame, trail $c_1/\cos\eta$, steer
//!   tilt $\eta$, lean $\theta = \varphi$, steer $\gamma = -\delta$, speed $v = Rs$, his
//!   handlebar equation being minus the steer equation), one part at a time (the other parts'
//!   masses and moments set to zero: the general model's terms are sums over its bodies), and
//!   by origin: the rows $(\partial T/\partial q')'$ and $-\sum m\,M'\,|\,(\partial M/
//!   \partial q)'$ against the two terms of the mechanics engine's modified Lagrange equations
//!   of the general model, linearised apart ([`linearised::Origins`]), their sum against Kane's
//!   $M$ (accelerations), $vC_1$ (gyroscopic) and $v^2K_2$ (centrifugal), the gravity row
//!   against $gK_0$ (the engine's matrices, [`linearised::matrices`], symbolic in the general
//!   model's parameters, [`general`]). The comparison is made in exact rational arithmetic at
//!   three rational points of the constants and of $s$ ([`points`], $\sin\eta$, $\cos\eta$
//!   Pythagorean pairs), the general model's matrices being evaluated at each point. The whole
//!   bicycle and the yaw rate of n° 108 (6) (the engine's dependent speed $\psi'$ linearised)
//!   are compared the same way.
//! * The quartic of n° 119 with $T = st$ (n° 118), its constant term's root in $s^2$ (the
//!   upper limit, n° 120 and n° 122) in closed form, checked symbolically against the printed
//!   closed form and its simplification for $c_1 = \tfrac12R\sin\eta$; the lower limit's
//!   condition of n° 121, $a_3^2 - a_1a_2a_3 + a_1^2a_4 = 0$, checked to be minus the third
//!   Hurwitz determinant of the monic quartic.
//!
//! Outputs: the twelve coefficients (`fall_a2` … `bar_b0`, column sums of the tables), the
//! quartic's coefficients `quartic0` … `quartic4` and the upper limits `s2_upper`,
//! `s2_upper_half_trail`. The parameter $c_1$ is named `c_1` (the IR names its constants
//! `c0`, `c1`, …).

use anyhow::Result;
use symbolica::atom::{Atom, AtomCore};

use crate::cas::{rat, var};
use crate::cas::{show, subst};
use crate::derive::whipple::linearised::{self, Origins};
use crate::derive::whipple::{reduce, vanishes, Matrices, COS_LAMBDA, SIN_LAMBDA};
use crate::{Check, Derivation, Formula, Perturbed};

/// Parameter names, in order: the constants of n° 117 (`c_1` is $c_1$, `ecg` the rider's distance $e$,
/// `A2` is $A + 2A_1$, `eta` the steering axis' angle with the vertical) and gravity.
pub const PARAMS: [&str; 12] =
    ["R", "l", "c_1", "eta", "ecg", "h", "mu", "mu1", "A2", "C", "L", "g"];
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
    (v(SIN_LAMBDA), v(COS_LAMBDA))
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
        (v("R"), v("l"), v("c_1"), v("ecg"), v("h"), v("mu"), v("mu1"), v("g"), v("s"));
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

/// The $\gamma''$ entries of the rows $(\partial T/\partial q')'$ of the n° 116 tables as the OCR
/// prints them, where they differ from n° 109–111 (every other entry is printed as
/// [`tables`] has it): `(equation, part, printed, text)`. All five have the sign opposite to
/// that of n° 109–111, while the printed sums of n° 117 have the signs of n° 109–111.
pub fn printed_gamma2() -> Vec<(&'static str, &'static str, Atom, &'static str)> {
    let (sn, co) = sc();
    let k = v("c_1") / v("l");
    let (a1, _, cc1) = wheel_moments();
    vec![
        ("fall", "frame", v("L") * &k, "+L c1/l"),
        ("fall", "front wheel", &a1 * &sn, "+A1 sin(eta)"),
        ("bar", "frame", -(v("C") * k.pow(n(2))), "-C c1^2/l^2"),
        ("bar", "rear wheel", -(&cc1 * k.pow(n(2))), "-C1 c1^2/l^2"),
        (
            "bar",
            "front wheel",
            -(&a1 * sn.pow(n(2)) + &cc1 * (&k + &co).pow(n(2))),
            "-[A1 sin^2(eta) + C1 (c1/l + cos(eta))^2]",
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

/// The check of column `i`'s sum against `printed` run again with the first nonzero entry of
/// the column in the n° 116 tables scaled by [`crate::falsify::FACTOR`]; `None` when every
/// entry is 0.
fn column_perturbed(i: usize, printed: &Atom) -> Option<Perturbed> {
    let (base, j) = if i < 6 { ("fall", i) } else { ("bar", i - 6) };
    let rows: Vec<(String, String, Atom)> = tables()
        .into_iter()
        .filter(|(eq, _, _, _)| *eq == base)
        .map(|(_, origin, part, row)| (origin.to_string(), part.to_string(), row[j].clone()))
        .collect();
    let first = rows.iter().position(|(_, _, x)| !x.expand().is_zero())?;
    let mut sum = n(0);
    for (k, (_, _, x)) in rows.iter().enumerate() {
        sum = if k == first { sum + x * crate::falsify::factor() } else { sum + x };
    }
    let (origin, part, _) = &rows[first];
    Some(Perturbed {
        what: format!(
            "the entry of the {part}'s row {origin} of the {base} equation's n° 116 table in this column scaled by {} before the sum",
            crate::falsify::FACTOR
        ),
        holds: vanishes(&(sum.expand() - printed)),
    })
}

/// The twelve closed forms printed in n° 117 (with $\mathfrak B_1'$'s first term read
/// $R c_1/l^2$: the OCR prints $R c_1/l$, dimensionally wrong), in the order of [`COEFFS`].
pub fn printed_117() -> [Atom; 12] {
    let (sn, co) = sc();
    let (r, l, c1, e, h, mu, mu1, g, s) =
        (v("R"), v("l"), v("c_1"), v("ecg"), v("h"), v("mu"), v("mu1"), v("g"), v("s"));
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

/// The three parts of Carvallo's model, in the order of the tables of n° 116.
pub const PARTS: [&str; 3] = ["frame", "rear wheel", "front wheel"];

/// Carvallo's model as a parameter set of the general Carvallo–Whipple bicycle, by benchmark
/// parameter name, for one part alone (`Some` index into [`PARTS`]: the other two parts'
/// masses and moments are set to zero) or for the whole bicycle (`None`). The general model's
/// $M$, $C_1$, $K_0$, $K_2$ are sums over its bodies, each linear in the body's mass and
/// moments, so a part alone gives that part's terms of the equations.
///
/// Assumptions: both wheels are hoops of mass $\mu_1$ and radius $R$ (benchmark moments about
/// the centre: $I_{xx} = \tfrac12\mu_1R^2$, $I_{yy} = \mu_1R^2$); the front frame (fork and
/// handlebar) is massless; the steer tilt is $\eta$ and the trail $c_1/\cos\eta$ ($c_1$ is
/// measured perpendicular to the steering axis); the wheelbase is $l$; the rear body is the
/// mounted frame, centre of mass at $x = e$, $z = -h$ (z down), its moments about its centre of
/// mass from Carvallo's moments about the rear contact point: $I_{xx} = A - \mu h^2$ with
/// $A = (A + 2A_1) - 2A_1 = (A + 2A_1) - 3\mu_1R^2$, $I_{zz} = C - \mu e^2$,
/// $I_{xz} = L - \mu e h$ (tensor components in the benchmark's z-down axes, where Carvallo's
/// $L = \sum m x z$ with z up). `IByy`, `xH`, `zH` are not given: they stay symbols and must
/// drop out.
pub fn whipple_mapping(part: Option<usize>) -> Vec<(&'static str, Atom)> {
    let (_, co) = sc();
    let (r, mu, mu1) = (v("R"), v("mu"), v("mu1"));
    let r2 = r.pow(n(2));
    let on = |k: usize, x: Atom| if part.is_none_or(|p| p == k) { x } else { n(0) };
    vec![
        ("w", v("l")),
        ("c", v("c_1") / &co),
        ("rR", r.clone()),
        ("mR", on(1, mu1.clone())),
        ("IRxx", on(1, rat(1, 2) * &mu1 * &r2)),
        ("IRyy", on(1, &mu1 * &r2)),
        ("xB", v("ecg")),
        ("zB", -v("h")),
        ("mB", on(0, mu.clone())),
        ("IBxx", on(0, v("A2") - n(3) * &mu1 * &r2 - &mu * v("h").pow(n(2)))),
        ("IBzz", on(0, v("C") - &mu * v("ecg").pow(n(2)))),
        ("IBxz", on(0, v("L") - &mu * v("ecg") * v("h"))),
        ("mH", n(0)),
        ("IHxx", n(0)),
        ("IHyy", n(0)),
        ("IHzz", n(0)),
        ("IHxz", n(0)),
        ("rF", r.clone()),
        ("mF", on(2, mu1.clone())),
        ("IFxx", on(2, rat(1, 2) * &mu1 * &r2)),
        ("IFyy", on(2, &mu1 * &r2)),
        ("g", v("g")),
        (SIN_LAMBDA, v(SIN_LAMBDA)),
        (COS_LAMBDA, v(COS_LAMBDA)),
    ]
}

/// An exact rational point of Carvallo's constants, the spin $s$ and the stand-ins of
/// $\sin\eta$, $\cos\eta$ (a Pythagorean pair), by name.
pub type Point = Vec<(&'static str, Atom)>;

/// The three rational points at which the tables are compared with the general model: near the
/// old bicycle of n° 117 ($\sin\eta = 5/13$), near the new one of n° 122 ($\sin\eta = 3/5$) and
/// a third set ($\sin\eta = 8/17$); all values exact.
pub fn points() -> Vec<Point> {
    let sets: [[(i64, i64); 14]; 3] = [
        [
            (19, 50),
            (11, 10),
            (2, 25),
            (1, 5),
            (1, 1),
            (70, 1),
            (5, 1),
            (100, 1),
            (4, 1),
            (14, 1),
            (981, 100),
            (41, 5),
            (5, 13),
            (12, 13),
        ],
        [
            (19, 50),
            (23, 20),
            (1, 20),
            (7, 20),
            (9, 10),
            (64, 1),
            (7, 2),
            (90, 1),
            (6, 1),
            (11, 1),
            (10, 1),
            (3, 1),
            (3, 5),
            (4, 5),
        ],
        [
            (2, 5),
            (1, 1),
            (1, 10),
            (1, 4),
            (11, 10),
            (80, 1),
            (4, 1),
            (120, 1),
            (5, 1),
            (16, 1),
            (49, 5),
            (13, 2),
            (8, 17),
            (15, 17),
        ],
    ];
    let names = [
        "R", "l", "c_1", "ecg", "h", "mu", "mu1", "A2", "C", "L", "g", "s", SIN_LAMBDA, COS_LAMBDA,
    ];
    sets.iter()
        .map(|set| names.iter().zip(set).map(|(nm, (p, q))| (*nm, rat(*p, *q))).collect())
        .collect()
}

/// `e` at the point (every named symbol replaced by its exact value), expanded.
pub fn at(e: &Atom, pt: &Point) -> Atom {
    let mut a = e.clone();
    for (name, value) in pt {
        a = subst(&a, name, value);
    }
    a.expand()
}

/// The six columns of an equation, in the order of the tables: $\theta'', \theta', \theta,
/// \gamma'', \gamma', \gamma$.
pub const COLUMNS: [&str; 6] = ["theta''", "theta'", "theta", "gamma''", "gamma'", "gamma"];

/// One part's terms of the two equations from the general model at a point, each `[fall, bar]`
/// by [`COLUMNS`] (exact numbers): Kane's inertial terms (accelerations $M$, rates $vC_1$,
/// angles $v^2K_2$), the gravity terms $gK_0$ (angle columns), and the two terms of Carvallo's
/// modified Lagrange equations from the engine ([`linearised::Origins`]): the momentum
/// derivative $(\partial T^*/\partial q')'$ and the correction
/// $-\sum m\,M'\,|\,(\partial M/\partial q)'$. The fall equation is the lean equation, the
/// handlebar equation minus the steer equation, the steer columns change sign
/// ($\gamma = -\delta$) and $v = Rs$.
pub struct PartTerms {
    /// Kane's inertial terms.
    pub kane: [Row; 2],
    /// Gravity.
    pub gravity: [Row; 2],
    /// Carvallo's $(\partial T^*/\partial q')'$.
    pub momentum: [Row; 2],
    /// Carvallo's correction terms.
    pub correction: [Row; 2],
    /// The yaw rate $\psi'$ of the general model (in `v`, `delta`, `deltad`).
    pub yaw_rate: Atom,
}

/// The general model's linear terms, symbolic in its parameters: Kane's matrices and the modified
/// Lagrange equations' parts ([`linearised::matrices`]).
pub struct General {
    /// $M$, $C_1$, $K_0$, $K_2$.
    pub kane: Matrices,
    /// The momentum's derivative, the correction and the yaw rate.
    pub parts: Origins,
}

/// The general model from the mechanics engine.
pub fn general() -> Result<General> {
    let model = crate::derive::whipple::description::whipple_rear_spin_from_lean();
    let (kane, parts) = linearised::matrices_of(&model, false, None)?;
    Ok(General { kane, parts })
}

/// The terms of one part (or of the whole bicycle, `None`) at `pt` from the general model.
// The row and column index six matrices and the output rows together.
#[allow(clippy::needless_range_loop)]
pub fn general_terms(part: Option<usize>, pt: &Point, gen: &General) -> PartTerms {
    let rs = at(&(v("R") * v("s")), pt);
    let mut mapping: Vec<(&str, Atom)> =
        whipple_mapping(part).into_iter().map(|(name, x)| (name, at(&x, pt))).collect();
    mapping.push(("v", rs.clone()));
    let to_point = |e: &Atom| -> Atom {
        let mut a = e.clone();
        for (name, x) in &mapping {
            a = subst(&a, name, x);
        }
        a.expand()
    };
    let g = at(&v("g"), pt);
    let (k, p) = (&gen.kane, &gen.parts);
    let sign = |row: usize, col: usize| if (row == 1) != (col == 1) { n(-1) } else { n(1) };
    let zero_row = || -> Row { std::array::from_fn(|_| n(0)) };
    let y = &p.yaw_rate;
    let mut out = PartTerms {
        kane: [zero_row(), zero_row()],
        gravity: [zero_row(), zero_row()],
        momentum: [zero_row(), zero_row()],
        correction: [zero_row(), zero_row()],
        yaw_rate: to_point(&y[0]) * v("phi")
            + to_point(&y[1]) * v("delta")
            + to_point(&y[2]) * v("phid")
            + to_point(&y[3]) * v("deltad"),
    };
    for row in 0..2 {
        for col in 0..2 {
            // The equation's sign (handlebar = minus steer) times the column's (gamma = -delta).
            let sg = sign(row, col);
            let b = 3 * col;
            let put = |x: &Atom| (&sg * to_point(x)).expand();
            out.kane[row][b] = put(&k.m[row][col]);
            out.kane[row][b + 1] = (&rs * put(&k.c1[row][col])).expand();
            out.kane[row][b + 2] = (rs.pow(n(2)) * put(&k.k2[row][col])).expand();
            out.gravity[row][b + 2] = (&g * put(&k.k0[row][col])).expand();
            out.momentum[row][b] = put(&k.m[row][col]);
            out.momentum[row][b + 1] = put(&p.momentum_rate[row][col]);
            out.momentum[row][b + 2] = put(&p.momentum_angle[row][col]);
            out.correction[row][b + 1] = put(&p.correction_rate[row][col]);
            out.correction[row][b + 2] = put(&p.correction_angle[row][col]);
        }
    }
    out
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

/// A [`Check`] that `diff` vanishes; `derived` is its derived side (see
/// [`geometry::check`](crate::derive::bicycle::geometry::check)), run again perturbed
/// ([`crate::falsify`]).
fn check(
    section: &str,
    id: &str,
    statement: &str,
    derived: &Atom,
    diff: &Atom,
    detail: String,
) -> Check {
    let holds = vanishes(diff);
    let perturbed = crate::falsify::perturb_derived(derived, diff, vanishes);
    Check {
        perturbed: Some(perturbed),
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
    let a = subst(e, SIN_LAMBDA, &var("sin(eta)"));
    subst(&a, COS_LAMBDA, &var("cos(eta)"))
}

/// Compares the transcribed rows `table` with the general model's `derived`, both `[point][fall
/// or bar][column]`, column by column at every point (exact numbers); returns whether all are
/// equal and a detail naming the columns that differ (values at the first point where they do).
fn compare_rows(table: &[[Row; 2]], derived: &[[Row; 2]], eq: usize) -> (bool, String) {
    let mut bad = Vec::new();
    for j in 0..6 {
        if let Some(k) =
            (0..table.len()).find(|&k| !(&table[k][eq][j] - &derived[k][eq][j]).expand().is_zero())
        {
            bad.push(format!(
                "{}: table {} vs general model {} at point {}",
                COLUMNS[j],
                table[k][eq][j],
                derived[k][eq][j],
                k + 1
            ));
        }
    }
    if bad.is_empty() {
        (
            true,
            format!(
                "all six columns equal at the {} rational points (exact arithmetic)",
                table.len()
            ),
        )
    } else {
        (false, bad.join("; "))
    }
}

/// The check [`compare_rows`] run again with the derived side perturbed (issue 38,
/// [`crate::falsify`]): the first column of the general model's row `eq` that is not zero at
/// every point scaled by 9/8 at every point; `None` when every column is zero.
fn compare_rows_perturbed(
    table: &[[Row; 2]],
    derived: &[[Row; 2]],
    eq: usize,
) -> Option<Perturbed> {
    let Some(j) = (0..6).find(|&j| derived.iter().any(|d| !d[eq][j].expand().is_zero())) else {
        // The row is 0 at every point: the other equation's row in its place.
        let other = 1 - eq;
        if derived.iter().all(|d| d[other].iter().all(|x| x.expand().is_zero())) {
            return None;
        }
        let swapped: Vec<[Row; 2]> = derived
            .iter()
            .map(|d| {
                let mut d = d.clone();
                d[eq] = d[other].clone();
                d
            })
            .collect();
        return Some(Perturbed {
            what: format!(
                "the general model's row of the {} equation (not 0) in place of this equation's (0 at every point)",
                ["fall", "bar"][other]
            ),
            holds: compare_rows(table, &swapped, eq).0,
        });
    };
    let scaled: Vec<[Row; 2]> = derived
        .iter()
        .map(|d| {
            let mut d = d.clone();
            d[eq][j] = (&d[eq][j] * crate::falsify::factor()).expand();
            d
        })
        .collect();
    Some(Perturbed {
        what: format!(
            "the {} column of the general model's row scaled by {} at every point",
            COLUMNS[j],
            crate::falsify::FACTOR
        ),
        holds: compare_rows(table, &scaled, eq).0,
    })
}

/// A check decided at exact rational points, `perturbed` its outcome on a perturbed derived
/// side when one is stated.
fn numeric_check(
    section: &str,
    id: &str,
    statement: &str,
    (holds, detail): (bool, String),
    perturbed: Option<Perturbed>,
) -> Check {
    Check {
        perturbed,
        section: section.to_string(),
        id: id.to_string(),
        statement: statement.to_string(),
        holds,
        detail,
    }
}

/// Derives the model's formulas and checks.
pub fn derive() -> Result<Derivation> {
    let mut checks = Vec::new();
    let sums = table_sums();
    let printed = printed_117();
    for i in 0..12 {
        let c = check(
            "117",
            &format!("{}_printed", COEFFS[i]),
            &format!("the column sum of the n° 116 tables for {} equals the closed form printed in n° 117", COEFFS[i]),
            &sums[i],
            &(&sums[i] - &printed[i]),
            format!("sum: {}", show(&reduce(&sums[i]))),
        );
        // A sum that is a literal 0 (its entries cancel): the falsification scales the
        // column's first nonzero entry in the tables before the sum.
        let c = match (sums[i].is_zero(), column_perturbed(i, &printed[i])) {
            (true, Some(p)) => crate::falsify::with_perturbation(c, Some(p)),
            (true, None) => Check {
                perturbed: None,
                detail: format!("{}; Holds by construction because every entry of this column of the n° 116 tables (transcribed from the memoir) is 0, so the sum is the literal 0 printed in n° 117; that the column is 0 is checked against the general model, part by part, by the n° 116 checks (each with its perturbation)", c.detail),
                ..c
            },
            (false, _) => c,
        };
        checks.push(c);
    }
    // n° 116 by part and by origin, against the general model at exact rational points.
    let gen = general()?;
    let pts = points();
    let tabs = tables();
    let zero_rows =
        || -> [Row; 2] { [std::array::from_fn(|_| n(0)), std::array::from_fn(|_| n(0))] };
    let n_pts = pts.len();
    let intro = format!("at {n_pts} exact rational points of Carvallo's constants and s (sin(eta), cos(eta) Pythagorean pairs)");
    for (p, part) in PARTS.iter().enumerate() {
        let mut tab_mom = Vec::new();
        let mut tab_cor = Vec::new();
        let mut tab_grav = Vec::new();
        let mut tab_inert = Vec::new();
        let mut gen_mom = Vec::new();
        let mut gen_cor = Vec::new();
        let mut gen_grav = Vec::new();
        let mut gen_kane = Vec::new();
        for pt in &pts {
            let (mut mom, mut cor, mut grav) = (zero_rows(), zero_rows(), zero_rows());
            for (eq, origin, tpart, row) in &tabs {
                if tpart != part {
                    continue;
                }
                let r = usize::from(*eq == "bar");
                let target = if origin.starts_with("dT") {
                    &mut mom
                } else if origin.starts_with("-sum") {
                    &mut cor
                } else {
                    &mut grav
                };
                for j in 0..6 {
                    target[r][j] = (&target[r][j] + at(&row[j], pt)).expand();
                }
            }
            let inert: [Row; 2] = std::array::from_fn(|r| {
                std::array::from_fn(|j| (&mom[r][j] + &cor[r][j]).expand())
            });
            let g = general_terms(Some(p), pt, &gen);
            tab_mom.push(mom);
            tab_cor.push(cor);
            tab_grav.push(grav);
            tab_inert.push(inert);
            gen_mom.push(g.momentum);
            gen_cor.push(g.correction);
            gen_grav.push(g.gravity);
            gen_kane.push(g.kane);
        }
        let key = part.replace(' ', "_");
        for (eq_name, tpart, printed, text) in printed_gamma2() {
            if tpart != *part {
                continue;
            }
            let eq = usize::from(eq_name == "bar");
            let mut bad = None;
            for (k, pt) in pts.iter().enumerate() {
                let (mine, general) = (at(&printed, pt), &gen_mom[k][eq][3]);
                if bad.is_none() && !(&mine - general).expand().is_zero() {
                    bad = Some(format!(
                        "as printed {mine} vs general model {general} at point {}",
                        k + 1
                    ));
                }
            }
            let holds = bad.is_none();
            checks.push(numeric_check(
                "116",
                &format!("{eq_name}_{key}_gamma2_as_printed"),
                &format!("the gamma'' entry {text} of the {part}'s row (dT/dq')' of the {eq_name} table, as the OCR of n° 116 prints it, equals the general model's momentum term for the {part} alone, {intro} (n° 109-111 and the sums of n° 117 have the opposite sign)"),
                (holds, bad.unwrap_or_else(|| "equal at every point".to_string())),
                None,
            ));
        }
        for (eq, eq_name, q) in [(0, "fall", "theta"), (1, "bar", "gamma")] {
            checks.push(numeric_check(
                "116",
                &format!("{eq_name}_{key}_momentum"),
                &format!("the {part}'s row (dT/d{q}')' of the n° 116 table of the {eq_name} equation equals the momentum derivative (dT*/d{q}')' of Carvallo's modified Lagrange equation for the {part} alone in the general Carvallo-Whipple bicycle (the mechanics engine's modified Lagrange equations, linearised part by part), {intro}"),
                compare_rows(&tab_mom, &gen_mom, eq),
                compare_rows_perturbed(&tab_mom, &gen_mom, eq),
            ));
            checks.push(numeric_check(
                "116",
                &format!("{eq_name}_{key}_correction"),
                &format!("the {part}'s row -sum m M'|(dM/d{q})' of the n° 116 table of the {eq_name} equation equals the correction term of Carvallo's modified Lagrange equation for the {part} alone in the general model, {intro}"),
                compare_rows(&tab_cor, &gen_cor, eq),
                compare_rows_perturbed(&tab_cor, &gen_cor, eq),
            ));
            checks.push(numeric_check(
                "116",
                &format!("{eq_name}_{key}_gravity"),
                &format!("the {part}'s gravity row of the n° 116 table of the {eq_name} equation equals g K0 (second-order potential with the contact-constrained pitch) for the {part} alone in the general model, {intro}"),
                compare_rows(&tab_grav, &gen_grav, eq),
                compare_rows_perturbed(&tab_grav, &gen_grav, eq),
            ));
            checks.push(numeric_check(
                "116",
                &format!("{eq_name}_{key}_kane"),
                &format!("the sum of the {part}'s two inertial rows of the n° 116 table of the {eq_name} equation equals Kane's terms M (accelerations), v C1 (gyroscopic, rates) and v^2 K2 (centrifugal, angles) for the {part} alone in the general model, {intro}"),
                compare_rows(&tab_inert, &gen_kane, eq),
                compare_rows_perturbed(&tab_inert, &gen_kane, eq),
            ));
        }
    }
    // The whole bicycle, and the yaw rate of n° 108 (6).
    let (_, co) = sc();
    let n_108 = v("R") / v("l") * &co * v("gamma") * v("s") + v("c_1") / v("l") * v("gammad");
    let mut tab_all = Vec::new();
    let mut gen_all = Vec::new();
    let mut yaw_ok = true;
    let mut yaw_detail = String::new();
    // The falsification: the general model's yaw rate scaled by 9/8.
    let mut yaw_scaled_ok = true;
    for (k, pt) in pts.iter().enumerate() {
        let g = general_terms(None, pt, &gen);
        let rows: [Row; 2] =
            std::array::from_fn(|r| std::array::from_fn(|j| at(&sums[6 * r + j], pt)));
        let gen: [Row; 2] = std::array::from_fn(|r| {
            std::array::from_fn(|j| (&g.kane[r][j] + &g.gravity[r][j]).expand())
        });
        tab_all.push(rows);
        gen_all.push(gen);
        let yaw = subst(&g.yaw_rate, "v", &(v("R") * v("s")));
        let yaw = subst(&yaw, "delta", &-v("gamma"));
        let yaw = subst(&yaw, "deltad", &-v("gammad"));
        let diff = at(&(&n_108 + &yaw), pt);
        yaw_scaled_ok &= at(&(&n_108 + &yaw * crate::falsify::factor()), pt).is_zero();
        if !diff.is_zero() && yaw_ok {
            yaw_ok = false;
            yaw_detail = format!("at point {}: n + psi' = {diff}", k + 1);
        }
    }
    for (eq, eq_name) in [(0, "fall"), (1, "bar")] {
        checks.push(numeric_check(
            "116",
            &format!("{eq_name}_whole_whipple"),
            &format!("the column sums of the n° 116 tables of the {eq_name} equation (the coefficients of n° 117) equal the general model's exact linearisation (Kane, M, v C1, g K0 + v^2 K2) of the whole bicycle with Carvallo's parameter set, {intro}"),
            compare_rows(&tab_all, &gen_all, eq),
            compare_rows_perturbed(&tab_all, &gen_all, eq),
        ));
    }
    checks.push(numeric_check(
        "108",
        "yaw_rate",
        &format!("n = (R/l) cos(eta) gamma s + (c1/l) gamma' (n° 108 (6)) is minus the general model's yaw rate psi' with Carvallo's parameter set, identically in gamma and gamma', {intro}"),
        (yaw_ok, if yaw_ok { format!("n + psi' = 0 at the {n_pts} points") } else { yaw_detail }),
        Some(Perturbed {
            what: format!("the general model's yaw rate psi' scaled by {}", crate::falsify::FACTOR),
            holds: yaw_scaled_ok,
        }),
    ));
    // n° 119-122.
    let q = quartic(&sums);
    // n° 118-119: the characteristic determinant in the time eigenvalue z = s lambda, divided by
    // s^4, is the quartic in lambda.
    let (lam, z) = (v("lambda"), v("s") * v("lambda"));
    let tri = |b: usize| &sums[b] * z.pow(n(2)) + &sums[b + 1] * &z + &sums[b + 2];
    let det_t = (tri(0) * tri(9) - tri(3) * tri(6)) / v("s").pow(n(4));
    let poly: Atom = (0..5).map(|k| &q[k] * lam.pow(n(k as i64))).fold(n(0), |acc, t| acc + t);
    checks.push(check(
        "119",
        "quartic_time_scale",
        "with T = s t (n° 118) the characteristic determinant of the n° 117 equations in the time eigenvalue z = s lambda, divided by s^4, is the quartic of n° 119 in lambda, identically in lambda and s",
        &det_t,
        &(&det_t - &poly).expand(),
        "det(coefficients at z = s lambda) / s^4 - sum q_k lambda^k = 0".to_string(),
    ));
    let num0 = (&sums[2] * &sums[11] - &sums[8] * &sums[5]).expand();
    let n0 = subst(&num0, "s", &n(0));
    let n1 = (subst(&num0, "s", &n(1)) - &n0).expand();
    let quad = (subst(&num0, "s", &n(2)) - &n0 - n(4) * &n1).expand();
    checks.push(check(
        "122",
        "constant_term_linear_in_s2",
        "the constant term's numerator A B1 - A1 B (script letters of n° 117) is of degree one in s^2",
        &(subst(&num0, "s", &n(2)) - &n0 - n(4) * &n1),
        &quad,
        format!("coefficient of s^0: {}", show(&reduce(&n0))),
    ));
    let s2_upper = reduce(&(-&n0 / &n1));
    let (sn, _) = sc();
    let (r, l, c1, e, h, mu, mu1, g) =
        (v("R"), v("l"), v("c_1"), v("ecg"), v("h"), v("mu"), v("mu1"), v("g"));
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
        &s2_upper,
        &(&s2_upper - &printed_122),
        format!("derived: s^2 = {}", show(&s2_upper)),
    ));
    let half = rat(1, 2) * &r * &sn;
    let s2_half = reduce(&subst(&s2_upper, "c_1", &half));
    let el = &e / &l;
    let printed_half = &g * &sn / (&r * &r / &l * &co)
        * (rat(1, 2) * &mu / &mu1 * &el + n(1))
        * (&h - rat(1, 2) * &r * &el + &mu1 / &mu * &r)
        / (&h - &r * &el);
    checks.push(check(
        "122",
        "upper_limit_half_trail",
        "with c1 = R sin(eta)/2 the upper limit reduces to the three-factor product printed in n° 122",
        &s2_half,
        &(&s2_half - &printed_half),
        format!("derived: s^2 = {}", show(&s2_half)),
    ));
    let den_half = (&mu * &h + n(2) * &mu1 * &r) * (rat(1, 2) * &mu * &el + n(2) * &mu1)
        - (&mu * &h + n(4) * &mu1 * &r) * (rat(1, 2) * &mu * &el + &mu1);
    checks.push(check(
        "122",
        "half_trail_denominator",
        "the denominator of the second fraction reduces to mu mu1 (h - R e/l)",
        &den_half,
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
        &eliminated,
        &(&eliminated - &cond),
        "exact".to_string(),
    ));
    let hurwitz3 = &x1 * (&x2 * &x3 - &x1 * &x4) - x3.pow(n(2));
    checks.push(check(
        "121",
        "routh_hurwitz",
        "Carvallo's condition (4) is minus the third Hurwitz determinant H3 = det[[a1, a3, 0], [1, a2, a4], [0, a1, a3]] of the monic quartic, so his lower limit is where H3 changes sign",
        &-&hurwitz3,
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
    Ok(Derivation {
        model: "bicycle_straight".to_string(),
        source: file!().to_string(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: INPUTS.iter().map(|s| s.to_string()).collect(),
        formulas,
        checks,
        nominal: crate::derive::nominal::values("bicycle_straight"),
        horner_schemes: Vec::new(),
    })
}
