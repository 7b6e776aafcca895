//! The mounted unicycle (memoir Part I, ch. II, n° 20–42, with n° 74 and n° 78): a wheel
//! rolling like the hoop (its own mass $\mu_1$ and moments $A_1, B_1, C_1$ about O) and a
//! rider held as a rigid body in the trihedron Oijk (n° 20–21), derived with symbolica.
//!
//! The rider's constants (n° 21) are the mass sums over its points $M - O = I\xi + j\eta +
//! k\zeta$: $\sum m = \mu$, $\sum m\zeta = \mu z$, $\sum m(\eta^2+\zeta^2) = A$,
//! $\sum m(\zeta^2+\xi^2) = B$, $\sum m(\xi^2+\eta^2) = C$, $\sum m\zeta\xi = L$, the other
//! first and product sums 0. [`rider_sum`] replaces every monomial in ξ, η, ζ by them.
//!
//! The equations of motion are derived twice: by the virtual works of the inertia forces
//! (n° 22–24: the rider moves with $\Phi = pI + nK$ and the translation $IRs$, the wheel as the
//! hoop of n° 6 with general $A_1, B_1, C_1$), and by the modified Lagrange equations (n° 74,
//! with the wheel's terms of n° 73). They agree term by term for any L. The memoir's n° 24
//! then merges each rider letter with the wheel's (A for A + A₁ ...); [`derive`] records that
//! this merge is not a substitution of letters (the residual is kept as a finding).
//!
//! Steady states, skidding and stability follow n° 29–41 and n° 76–78: (E) is the (p)
//! equation at $p = p' = n' = s' = 0$; stability is the constant term of the characteristic
//! determinant of n° 76 divided by λ² ([`crate::derive::hoop::steady::stability_by_determinant`]),
//! once for the full model and once for the memoir's hypotheses of n° 33–40 (rider letters
//! only, L = 0, the wheel kept only through its term $(B_1 - \mu_1R^2)ps\cos\theta$); n° 78
//! drops the (s) equation (s held constant by the pedals) and keeps L.
//!
//! The mechanics engine derives the same unicycle from a description ([`description`]: the
//! hoop's plus the rider's body), and [`derive`] checks exactly that its Kane and modified
//! Lagrange equations, solved, are the ones above solved once $A_1 = C_1 + \mu_1R^2$
//! (`engine_kane_is_memoir`, `engine_lagrange_is_memoir`, `engine_energy`). The program stays
//! this hand derivation for that reason: the memoir keeps the wheel's $A_1$ a letter of its own
//! (n° 24, and the merge of n° 24 and the light-wheel forms of n° 29–34 read it so), while the
//! engine's wheel is a body of revolution, for which the relation holds, so the engine's
//! equations have no $A_1$ to read. A wheel whose $A_1$ breaks the relation is not a body of
//! revolution and its inertia would not be constant in the trihedron Oijk, so the engine covers
//! every physical unicycle; the letters stay for the memoir's formulas.

pub mod description;
pub mod memoir;

use anyhow::{ensure, Result};
use symbolica::atom::{Atom, AtomCore};

use crate::cas::{cos_t, is_zero, simplify, sin_t, var};
use crate::cas::{show, solve_linear, subst};
use crate::derive::hoop::{self, formula, printed_formula};
use crate::mechanics::frame::{time_derivative, Trihedron, Vector};
use crate::{Check, Derivation};

/// Parameter names of the unicycle model, in order.
pub const PARAMS: [&str; 12] = ["R", "g", "mu", "z", "A", "B", "C", "L", "mu1", "A1", "B1", "C1"];
/// Input names of the unicycle model, in order.
pub const INPUTS: [&str; 7] = ["theta", "p", "n", "s", "dp", "dn", "ds"];

/// The degree in the symbol `x` of the monomial `m` (99 when above 15).
pub(crate) fn degree(m: &Atom, x: &Atom) -> u32 {
    let sym = x.get_symbol().expect("a symbol");
    if !m.contains_symbol(sym) {
        return 0;
    }
    let d = (x * &m.derivative(sym) / m).expand();
    (0..16).find(|k| d == Atom::num(*k as i64)).unwrap_or(99)
}

/// $\sum m\,F$ over the rider for F polynomial in ξ, η, ζ of degree at most 2 (n° 21).
///
/// # Panics
/// Panics on a monomial of degree above 2 (the derivations never produce one).
pub fn rider_sum(f: &Atom) -> Atom {
    let (x, y, w) = (var("xi"), var("eta"), var("zeta"));
    let (a, b, c) = (var("A"), var("B"), var("C"));
    let mut out = Atom::num(0);
    for (key, coeff) in f.expand().coefficient_list::<u8>(&[x.clone(), y.clone(), w.clone()]) {
        let deg = (degree(&key, &x), degree(&key, &y), degree(&key, &w));
        let value = match deg {
            (0, 0, 0) => var("mu"),
            (0, 0, 1) => var("mu") * var("z"),
            (1, 0, 1) => var("L"),
            (2, 0, 0) => (&b + &c - &a) / Atom::num(2),
            (0, 2, 0) => (&a + &c - &b) / Atom::num(2),
            (0, 0, 2) => (&a + &b - &c) / Atom::num(2),
            (1, 0, 0) | (0, 1, 0) | (0, 1, 1) | (1, 1, 0) => Atom::num(0),
            other => panic!("rider sum of a monomial of degree {other:?}"),
        };
        out += coeff * value;
    }
    out.expand()
}

/// $M - O = I\xi + j\eta + k\zeta$ for a point of the rider.
pub fn rider_point() -> Vector {
    Vector::new(Trihedron::Ijk, var("xi"), var("eta"), var("zeta"))
}

fn phi() -> Vector {
    Vector::new(Trihedron::IJK, var("p"), Atom::num(0), var("n")).to(Trihedron::Ijk)
}

fn contact_velocity() -> Vector {
    Vector::new(Trihedron::Ijk, var("R") * var("s"), Atom::num(0), Atom::num(0))
}

/// $M' = IRs + |\Phi(M - O)$ (n° 22).
pub fn rider_velocity() -> Vector {
    contact_velocity().add(&phi().cross(&rider_point()))
}

/// The rider's first members of (1) of n° 22: $[I\sum m(M-O)M'']$, $[K\sum m(M-O)M'']$,
/// $[j\sum m(S-O)M'']$ (printed (2) of n° 23).
pub fn rider_moments() -> [Atom; 3] {
    let acc = rider_velocity().derivative(&var("p"), &var("n"));
    let mom = rider_point().cross(&acc).map(rider_sum);
    let i = Vector::unit(Trihedron::Ijk, 0);
    let k_big = Vector::unit(Trihedron::IJK, 2);
    let j = Vector::unit(Trihedron::Ijk, 1);
    let s_o = Vector::new(Trihedron::Ijk, Atom::num(0), Atom::num(0), var("R"));
    let total_acc = acc.map(rider_sum);
    [simplify(&mom.dot(&i)), simplify(&mom.dot(&k_big)), simplify(&s_o.cross(&total_acc).dot(&j))]
}

/// The wheel's first members (printed (3) of n° 24): the hoop's moment of the inertia forces
/// of n° 6 with moments $A_1, B_1, C_1$ and mass $\mu_1$, on I, K and j.
pub fn wheel_moments() -> [Atom; 3] {
    let h = hoop::motion::momentum_moment(&var("A1"), &var("B1"), &var("C1"));
    let j = hoop::motion::inertia_moment(&h)
        .map(|e| subst(&hoop::motion::to_pns(e), "mu", &var("mu1")));
    let i = Vector::unit(Trihedron::Ijk, 0);
    let k_big = Vector::unit(Trihedron::IJK, 2);
    let jj = Vector::unit(Trihedron::Ijk, 1);
    [simplify(&j.dot(&i)), simplify(&j.dot(&k_big)), simplify(&j.dot(&jj))]
}

/// The weight's potential $g(\mu\,h_G + \mu_1 h_S)$ from the heights above the ground of the
/// rider's centroid $G = O + zk$ and the wheel's centre $S = O + Rk$: $h = (M - O)\cdot K$,
/// with $k$ written on the fixed trihedron (I, J, K) (n° 20–22).
pub fn weight_potential() -> Atom {
    let up = Vector::unit(Trihedron::IJK, 2);
    let height =
        |length: Atom| Vector::unit(Trihedron::Ijk, 2).scale(&length).to(Trihedron::IJK).dot(&up);
    var("g") * (var("mu") * height(var("z")) + var("mu1") * height(var("R")))
}

/// Work of the weight for δp, minus the potential's θ-derivative: the memoir's
/// $(\mu z + \mu_1 R)g\sin\theta$ (n° 22), here derived from the heights
/// ([`weight_potential`]) rather than typed in.
pub fn weight_work() -> Atom {
    simplify(&(-hoop::lagrange::d_theta(&weight_potential())))
}

/// The equations of motion (p), (n), (s) of the full model, motor moment 0.
pub fn equations() -> [Atom; 3] {
    let r = rider_moments();
    let w = wheel_moments();
    [&r[0] + &w[0] - weight_work(), &r[1] + &w[1], &r[2] + &w[2]]
}

/// Kinetic energy: the rider's $\frac12\sum mM'^2$ and the wheel's
/// $\frac12(A_1p^2 + B_1q^2 + C_1r^2)$.
pub fn kinetic_energy() -> Atom {
    let v = rider_velocity();
    let rider = rider_sum(&v.dot(&v)) / Atom::num(2);
    let q = var("s") + var("n") * sin_t();
    let r = var("n") * cos_t();
    let wheel = (var("A1") * var("p").pow(Atom::num(2))
        + var("B1") * q.pow(Atom::num(2))
        + var("C1") * r.pow(Atom::num(2)))
        / Atom::num(2);
    simplify(&(rider + wheel))
}

fn d(f: &Atom, x: &str) -> Atom {
    f.derivative(var(x).get_symbol().expect("symbol"))
}

/// The rider's corrections of n° 74: $-\sum m M'|(\partial M/\partial\nu)'$ with
/// $(\partial M/\partial\nu)' = |K(M' - O')$, and $-\sum m M'|(\partial M/\partial\sigma)'$
/// with $\partial M/\partial\sigma = IR$, $(\partial M/\partial\sigma)' = JRn$.
pub fn rider_corrections() -> [Atom; 2] {
    let v = rider_velocity();
    let k_big = Vector::unit(Trihedron::IJK, 2);
    let nu = k_big.cross(&v.sub(&contact_velocity()));
    let sigma = Vector::new(Trihedron::IJK, Atom::num(0), var("R") * var("n"), Atom::num(0));
    [simplify(&-rider_sum(&v.dot(&nu))), simplify(&-rider_sum(&v.dot(&sigma)))]
}

/// The wheel's corrections by n° 73's routes with $A_1, B_1, C_1, \mu_1$.
pub fn wheel_corrections() -> [Atom; 2] {
    let h =
        hoop::motion::momentum_moment(&var("A1"), &var("B1"), &var("C1")).map(hoop::motion::to_pns);
    let nu = subst(&hoop::lagrange::correction_nu_via_centre(), "mu", &var("mu1"));
    let sigma = subst(&hoop::lagrange::correction_sigma_via_momentum(&h).0, "mu", &var("mu1"));
    [simplify(&nu), simplify(&sigma)]
}

/// The modified Lagrange equations (θ), (ν), (σ) of n° 74 for the rider and the wheel.
pub fn lagrange_equations() -> [Atom; 3] {
    let t = kinetic_energy();
    let rc = rider_corrections();
    let wc = wheel_corrections();
    [
        time_derivative(&d(&t, "p")) - hoop::lagrange::d_theta(&t) - weight_work(),
        time_derivative(&d(&t, "n")) + &rc[0] + &wc[0],
        time_derivative(&d(&t, "s")) + &rc[1] + &wc[1],
    ]
}

/// Sets the listed symbols to the given values.
fn with(e: &Atom, values: &[(&str, Atom)]) -> Atom {
    values.iter().fold(e.clone(), |acc, (name, v)| subst(&acc, name, v))
}

fn zero() -> Atom {
    Atom::num(0)
}

/// The wheel set to nothing: $\mu_1 = A_1 = B_1 = C_1 = 0$.
fn no_wheel() -> Vec<(&'static str, Atom)> {
    vec![("mu1", zero()), ("A1", zero()), ("B1", zero()), ("C1", zero())]
}

/// n° 76–77 for a system already solved as $p', n', s'$: the stability first member.
fn stability_of(eqs: &[Atom; 3]) -> (Atom, bool) {
    let pns = solve_linear(eqs, &["dp", "dn", "ds"]);
    let (k, factor, coeffs) = hoop::steady::stability_by_determinant(&pns);
    (k, factor && is_zero(&coeffs[3]) && is_zero(&(&coeffs[4] - &Atom::num(1))))
}

/// n° 78: the characteristic determinant of n° 76 for the (p) and (n) equations with s held
/// constant (s' = 0), X = θ and U = n, at the steady state p = p' = n' = 0. Returns the
/// coefficients of λ⁰…λ³ (the λ⁰ one must vanish).
pub fn determinant_78(eq_p: &Atom, eq_n: &Atom) -> Vec<Atom> {
    let l = var("lambda");
    let steady = |e: &Atom| {
        simplify(&with(e, &[("p", zero()), ("dp", zero()), ("dn", zero()), ("ds", zero())]))
    };
    let row = |f: &Atom| {
        let f = subst(f, "ds", &zero());
        vec![
            steady(&d(&f, "dp")) * l.pow(Atom::num(2))
                + steady(&d(&f, "p")) * &l
                + steady(&hoop::lagrange::d_theta(&f)),
            steady(&d(&f, "dn")) * &l + steady(&d(&f, "n")),
        ]
    };
    let (a, b) = (row(eq_p), row(eq_n));
    let det = (&a[0] * &b[1] - &a[1] * &b[0]).expand();
    let mut out = vec![zero(); 4];
    for (key, coeff) in det.coefficient_list::<u8>(std::slice::from_ref(&l)) {
        let k = (0..4).find(|k| key == l.pow(Atom::num(*k as i64))).unwrap_or(0);
        out[k] = &out[k] + coeff;
    }
    out.iter().map(simplify).collect()
}

fn compare(section: &str, id: &str, statement: &str, derived: &Atom, printed: &Atom) -> Check {
    let diff = simplify(&(derived - printed));
    let perturbed = crate::falsify::perturb_one(derived, |d| is_zero(&(d - printed)));
    Check {
        perturbed: Some(perturbed),
        section: section.to_string(),
        id: id.to_string(),
        statement: statement.to_string(),
        holds: is_zero(&diff),
        detail: format!(
            "derived: {}; expected: {}; simplified difference (exact, reduced with sin^2+cos^2=1): {}",
            show(derived),
            show(printed),
            show(&diff)
        ),
    }
}

fn compare_all(section: &str, id: &str, statement: &str, a: &[Atom], b: &[Atom]) -> Check {
    let names = ["(p)", "(n)", "(s)"];
    let diffs: Vec<Atom> = a.iter().zip(b).map(|(x, y)| simplify(&(x - y))).collect();
    let perturbed = crate::falsify::perturb(a, |d| d.iter().zip(b).all(|(x, y)| is_zero(&(x - y))));
    Check {
        perturbed: Some(perturbed),
        section: section.to_string(),
        id: id.to_string(),
        statement: statement.to_string(),
        holds: diffs.iter().all(is_zero),
        detail: names
            .iter()
            .zip(&diffs)
            .map(|(n, d)| format!("{n}: difference {}", show(d)))
            .collect::<Vec<_>>()
            .join("; "),
    }
}

/// Derives every unicycle formula and runs the checks.
pub fn derive() -> Result<Derivation> {
    use memoir as m;
    let mut checks: Vec<Check> = Vec::new();
    let (mu, r_, g, z) = (var("mu"), var("R"), var("g"), var("z"));
    let (c_, mu1) = (var("C"), var("mu1"));

    // n° 21: the rider's constants.
    checks.push(compare(
        "21",
        "rider_centre",
        "the rider's mass sum of M - O is mu z k (centre of gravity on Ok at height z)",
        &rider_point().map(rider_sum).dot(&Vector::unit(Trihedron::Ijk, 2)),
        &(&mu * &z),
    ));

    // n° 22–24: moments.
    let rider = rider_moments();
    let wheel = wheel_moments();
    checks.push(compare_all(
        "23",
        "rider_moments_memoir",
        "the rider's virtual works of the inertia forces are the printed (2) of n° 23",
        &rider,
        &[m::RIDER_P.atom(), m::RIDER_N.atom(), m::RIDER_S.atom()],
    ));
    checks.push(compare_all(
        "24",
        "wheel_moments_memoir",
        "the wheel's (hoop of n° 6 with A1, B1, C1, mu1) are the printed (3) of n° 24",
        &wheel,
        &[m::WHEEL_P.atom(), m::WHEEL_N.atom(), m::WHEEL_S.atom()],
    ));
    let eqs = equations();
    let printed24 = [m::EQ_P.atom(), m::EQ_N.atom(), m::EQ_S.atom()];
    let light: Vec<Atom> = eqs.iter().map(|e| with(e, &no_wheel())).collect();
    let printed_light: Vec<Atom> = printed24.iter().map(|e| with(e, &no_wheel())).collect();
    checks.push(compare_all(
        "24",
        "equations_light_wheel_memoir",
        "with the wheel's mass and moments 0 the derived equations are the printed ones of n° 24",
        &light,
        &printed_light,
    ));
    let merged: Vec<Atom> = printed24
        .iter()
        .map(|e| {
            with(
                e,
                &[
                    ("A", var("A") + var("A1")),
                    ("B", var("B") + var("B1")),
                    ("C", var("C") + var("C1")),
                ],
            )
        })
        .collect();
    let mut merge = compare_all(
        "24",
        "merge_is_substitution",
        "the printed n° 24 with A + A1, B + B1, C + C1 for A, B, C equals the derived rider + wheel equations (the memoir's merge read as a substitution)",
        &eqs,
        &merged,
    );
    merge.detail.push_str("; the residual is the wheel's mu1 R and B1 terms that no letter substitution absorbs: the memoir's merge is an approximation (A1 << A)");
    checks.push(merge);

    // n° 74: modified Lagrange.
    let lag = lagrange_equations();
    checks.push(compare_all(
        "74",
        "lagrange_agrees_with_moments",
        "the modified Lagrange equations (theta), (nu), (sigma) of rider + wheel equal (p), (n), (s) of n° 22-24, for any L",
        &lag,
        &eqs,
    ));
    let rider_only_l0 = |e: &Atom| {
        with(e, &[("L", zero()), ("mu1", zero()), ("A1", zero()), ("B1", zero()), ("C1", zero())])
    };
    let t_r = rider_only_l0(&kinetic_energy());
    checks.push(compare(
        "74",
        "kinetic_energy_74_memoir",
        "twice the rider's kinetic energy with L = 0 is the printed 2T of n° 74",
        &(Atom::num(2) * &t_r),
        &m::TWICE_KINETIC_74.atom(),
    ));
    let rc = rider_corrections();
    checks.push(compare(
        "74",
        "correction_nu_74_memoir",
        "the rider's nu correction is -mu R h p s cos(theta) (n° 74)",
        &rc[0],
        &m::CORRECTION_NU_74.atom(),
    ));
    checks.push(compare(
        "74",
        "correction_sigma_74_memoir",
        "the rider's sigma correction is +mu R h p n cos(theta) (n° 74)",
        &rc[1],
        &m::CORRECTION_SIGMA_74.atom(),
    ));
    let lag_r: Vec<Atom> = lag.iter().map(rider_only_l0).collect();
    checks.push(compare_all(
        "74",
        "lagrange_74_memoir",
        "the rider's modified Lagrange equations with L = 0 are the printed (theta), (nu), (sigma) of n° 74 (theta read with mu g h)",
        &lag_r,
        &[m::LAGRANGE_THETA_74.atom(), m::LAGRANGE_NU_74.atom(), m::LAGRANGE_SIGMA_74.atom()],
    ));
    checks.push(compare(
        "74",
        "lagrange_theta_74_as_printed",
        "the printed (theta) of n° 74 with second member mu h R sin(theta) (as the OCR reads) equals the derived one",
        &lag_r[0],
        &m::LAGRANGE_THETA_74_AS_PRINTED.atom(),
    ));

    // Energy (motor 0): conserved along the solved full equations.
    let pns = solve_linear(&eqs, &["dp", "dn", "ds"]);
    let energy = simplify(&(kinetic_energy() + (&mu * &z + &mu1 * &r_) * &g * cos_t()));
    let flow = with(
        &time_derivative(&energy),
        &[("dp", pns[0].clone()), ("dn", pns[1].clone()), ("ds", pns[2].clone())],
    );
    let revolution = [("A1", var("C1") + &mu1 * r_.pow(Atom::num(2)))];
    let mut chk = compare("24", "energy_conservation", "with A1 = C1 + mu1 R^2 (a wheel of revolution, as n° 7 for the hoop) the energy T + V is constant along the solved equations (motor moment 0)", &with(&flow, &revolution), &zero());
    chk.detail.push_str(&format!("; without the relation dE/dt is {}", show(&flow)));
    checks.push(chk);

    // The unicycle as a description (`description`: the hoop's plus the rider's body): the
    // mechanics engine's Kane and modified Lagrange equations, solved, are the equations above
    // solved, exactly, once A1 = C1 + mu1 R^2. The engine's wheel is a body of revolution, which
    // implies that relation; the memoir's n° 24 keeps A1 a letter of its own, so the program
    // stays the memoir's derivation (see the module's documentation) and the engine checks it.
    let ([kane, lagrange_engine], engine_energy) =
        hoop::description::accelerations(&description::unicycle(), [1, -1, -1])?;
    let pns_revolution: Vec<Atom> = pns.iter().map(|e| with(e, &revolution)).collect();
    checks.push(compare_all("24", "engine_kane_is_memoir", "the engine's Kane equations of the unicycle's description (theta = phi, p = phi', n = -psi', s = -thetaR'), solved for p', n', s', are the equations of n° 22-24 solved, with A1 = C1 + mu1 R^2", &kane, &pns_revolution));
    checks.push(compare_all("74", "engine_lagrange_is_memoir", "the engine's modified Lagrange equations of the description, solved for p', n', s', are the equations of n° 22-24 solved, with A1 = C1 + mu1 R^2", &lagrange_engine, &pns_revolution));
    checks.push(compare(
        "24",
        "engine_energy",
        "the engine's total energy of the description is T + V, with A1 = C1 + mu1 R^2",
        &engine_energy,
        &with(&energy, &revolution),
    ));

    // n° 29: (E).
    let steady0 = [("p", zero()), ("dp", zero()), ("dn", zero()), ("ds", zero())];
    let equilibrium = simplify(&-with(&eqs[0], &steady0));
    checks.push(compare(
        "29",
        "equilibrium_memoir",
        "with the wheel's mass and moments 0, -(p) at p = p' = n' = s' = 0 is the printed (E) of n° 29",
        &with(&equilibrium, &no_wheel()),
        &m::EQUILIBRIUM.atom(),
    ));
    let n_eq_steady = simplify(&with(&eqs[1], &steady0));
    let s_eq_steady = simplify(&with(&eqs[2], &steady0));
    // Both equations reach the steady state as literal zeros (every term has p, p', n' or s'
    // as a factor): the falsification leaves the steady state's n' = 0 out.
    let unsteady = [("p", zero()), ("dp", zero()), ("ds", zero())];
    let perturbed = crate::Perturbed {
        what: "the steady state without n' = 0 (p = p' = s' = 0 only): (n) and (s) run on it"
            .into(),
        holds: is_zero(&simplify(&with(&eqs[1], &unsteady)))
            && is_zero(&simplify(&with(&eqs[2], &unsteady))),
    };
    checks.push(Check {
        perturbed: Some(perturbed),
        section: "29".into(),
        id: "steady_identities".into(),
        statement: "in a steady state (n) is an identity and (s) gives motor moment 0".into(),
        holds: is_zero(&n_eq_steady) && is_zero(&s_eq_steady),
        detail: format!("(n): {}; (s): {}", show(&n_eq_steady), show(&s_eq_steady)),
    });

    // n° 30: skid, from the inertia force of G = O + z k of mass mu.
    let g_dot = contact_velocity().add(&phi().cross(&Vector::new(
        Trihedron::Ijk,
        zero(),
        zero(),
        z.clone(),
    )));
    let g_acc = g_dot.derivative(&var("p"), &var("n")).to(Trihedron::IJK);
    let force_j = -(&mu * &g_acc.comps[1]);
    let force_k = -(&mu * &g_acc.comps[2]);
    let skid_full = simplify(&(&force_j / (&mu * &g - &force_k)));
    let skid_full_memoir_sign = simplify(&(&force_j / (&mu * &g + &force_k)));
    let mut chk = compare(
        "30",
        "skid_full_memoir",
        "D = (J inertia force)/(normal reaction mu g + mu G''_K) is the printed complete D of n° 30",
        &skid_full,
        &m::SKID_FULL.atom(),
    );
    chk.detail.push_str(&format!(
        "; with the denominator mu g - (K inertia force) instead (the printed sign): difference {}",
        show(&(skid_full_memoir_sign.clone() - m::SKID_FULL.atom()))
    ));
    checks.push(chk);
    let skid = simplify(&with(&skid_full, &[("p", zero()), ("dp", zero())]));
    checks.push(compare(
        "30",
        "skid_memoir",
        "the steady skid tendency is the printed (D) of n° 30",
        &skid,
        &m::SKID.atom(),
    ));
    checks.push(compare(
        "30",
        "skid_hoop",
        "with z = R the steady D is the hoop's D of n° 10",
        &subst(&skid, "z", &r_),
        &hoop::memoir::SKID.atom(),
    ));

    // n° 32: normalised forms with B - C = mu z^2, g/R = 1.
    let n32 = [("B", &c_ + &mu * z.pow(Atom::num(2))), ("g", r_.clone())];
    let equilibrium_n32 =
        simplify(&(with(&with(&equilibrium, &no_wheel()), &n32) / (&mu * &z * &r_ * cos_t())));
    checks.push(compare("32", "equilibrium_n32_memoir", "(E) with B - C = mu z^2, g/R = 1, divided by mu g z cos(theta), is the printed (E) of n° 32", &equilibrium_n32, &m::EQUILIBRIUM_N32.atom()));
    let skid_n32 = simplify(&subst(&skid, "g", &r_));
    checks.push(compare(
        "32",
        "skid_n32_memoir",
        "(D) with g/R = 1 is the printed (D) of n° 32",
        &skid_n32,
        &m::SKID_N32.atom(),
    ));

    // n° 33–34: the memoir's simplified model (rider letters, L = 0, wheel through its
    // (B1 - mu1 R^2) p s cos term only).
    let rider_l0: Vec<Atom> = rider.iter().map(|e| subst(e, "L", &zero())).collect();
    let gyro = simplify(&with(&wheel[1], &[("dn", zero()), ("ds", zero()), ("n", zero())]));
    checks.push(compare(
        "33",
        "wheel_gyroscopic_term",
        "the wheel's (n) terms at n = n' = s' = 0 are (B1 - mu1 R^2) p s cos(theta)",
        &gyro,
        &((var("B1") - &mu1 * r_.pow(Atom::num(2))) * var("p") * var("s") * cos_t()),
    ));
    let simplified =
        [&rider_l0[0] - &mu * &z * &g * sin_t(), &rider_l0[1] + &gyro, rider_l0[2].clone()];
    let sys_i = solve_linear(&simplified, &["dp", "dn", "ds"]);
    checks.push(compare_all(
        "34",
        "system_i_memoir",
        "the simplified equations of n° 33 solved for p', n', s' are the printed system (I) of n° 34",
        &sys_i,
        &[m::SYSTEM_I_DP.atom(), m::SYSTEM_I_DN.atom(), m::SYSTEM_I_DS.atom()],
    ));
    let (stab_simpl, ok_simpl) = stability_of(&simplified);
    let full_l0: [Atom; 3] =
        [subst(&eqs[0], "L", &zero()), subst(&eqs[1], "L", &zero()), subst(&eqs[2], "L", &zero())];
    let (stab_full, ok_full) = stability_of(&full_l0);
    // A parameter scaled keeps the factorisation (it comes from the equations' form): the
    // falsification adds a damping of the lean rate, p/8, to the (p) equation.
    let damped = [
        &simplified[0] + var("p") * crate::cas::rat(1, 8),
        simplified[1].clone(),
        simplified[2].clone(),
    ];
    let perturbed = crate::Perturbed {
        what: "a damping term p/8 added to the (p) equation of the simplified model (the lean rate resisted)".into(),
        holds: stability_of(&damped).1,
    };
    checks.push(Check {
        perturbed: Some(perturbed),
        section: "35".into(),
        id: "characteristic_factor".into(),
        statement: "for the simplified and the full (L = 0) models the determinant of n° 76 is lambda^2 (lambda^2 + K), so (S) is K > 0 as in n° 9 and 34".into(),
        holds: ok_simpl && ok_full,
        detail: format!("simplified: {ok_simpl}; full: {ok_full}"),
    });
    let route34 = hoop::steady::minus_p2_over_p(
        &sys_i[0],
        &[("dp", sys_i[0].clone()), ("dn", sys_i[1].clone()), ("ds", sys_i[2].clone())],
    );
    checks.push(compare(
        "34",
        "stability_taylor_route",
        "n° 34's -p''/p at p = 0 equals the determinant's K",
        &route34,
        &stab_simpl,
    ));
    let a_ = var("A");
    let at_straight = |e: &Atom| {
        simplify(&with(e, &[("sin_theta", zero()), ("cos_theta", Atom::num(1)), ("n", zero())]))
    };
    checks.push(compare(
        "36",
        "straight_36_memoir",
        "A K at theta = 0, n = 0 (simplified model) is the printed first member of n° 36",
        &at_straight(&(&a_ * &stab_simpl)),
        &m::STRAIGHT_36.atom(),
    ));
    let light_wheel = [("mu1", zero()), ("B1", zero())];
    let s39 = simplify(&(&a_ * with(&stab_simpl, &light_wheel)));
    checks.push(compare(
        "39",
        "stability_39_memoir",
        "A K with the wheel infinitely light is the printed (S) of n° 39 with E = B - C - mu h^2",
        &s39,
        &m::STABILITY_39.atom(),
    ));
    let b_e0 = [("B", &c_ + &mu * z.pow(Atom::num(2)))];
    let s39_e0 = simplify(&with(&s39, &b_e0));
    checks.push(compare(
        "39",
        "stability_39_e0_memoir",
        "with E = 0 it is the printed mu R h s n sin + mu h^2 n^2 - mu g h cos of n° 39",
        &s39_e0,
        &m::STABILITY_39_E0.atom(),
    ));
    let stability_n39 = simplify(&(subst(&s39_e0, "g", &r_) / (&mu * &r_ * &z)));
    checks.push(compare(
        "39",
        "stability_n39_memoir",
        "divided by mu g h with g/R = 1 it is the printed (S1) of n° 39",
        &stability_n39,
        &m::STABILITY_39_N.atom(),
    ));
    let hyp40 = [
        ("B", &c_ + &mu * z.pow(Atom::num(2))),
        ("B1", Atom::num(2) * &mu1 * r_.pow(Atom::num(2))),
    ];
    let s40 = simplify(&with(
        &with(&(&a_ * &stab_simpl), &hyp40),
        &[("mu1", &c_ / r_.pow(Atom::num(2)))],
    ));
    checks.push(compare(
        "40",
        "stability_40_memoir",
        "A K with B = C + mu h^2, B1 = 2 mu1 R^2, mu1 R^2 = C is the printed condition of n° 40",
        &s40,
        &m::STABILITY_40.atom(),
    ));
    let stability_n40 = simplify(&(subst(&s40, "g", &r_) / (&mu * &r_ * &z)));
    checks.push(compare(
        "40",
        "stability_n40_memoir",
        "divided by mu R h with g/R = 1 it is the printed (S) of n° 40",
        &stability_n40,
        &m::STABILITY_40_N.atom(),
    ));
    // n° 41: s from (E) of n° 32 into (S) of n° 40, times n^2.
    let s_of_e = -(&z / &r_ * var("n") * sin_t() + sin_t() / (cos_t() * var("n")));
    checks.push(compare(
        "41",
        "s_from_e",
        "(E) of n° 32 vanishes at s = -(h/R) n sin - tan/n",
        &subst(&equilibrium_n32, "s", &s_of_e),
        &zero(),
    ));
    let trinomial = simplify(&(subst(&stability_n40, "s", &s_of_e) * var("n").pow(Atom::num(2))));
    checks.push(compare(
        "41",
        "trinomial_n41_memoir",
        "(S) of n° 40 along (E), times n^2, is the printed trinomial S(n^2) of n° 41",
        &trinomial,
        &m::TRINOMIAL_41.atom(),
    ));

    // n° 78: s constant, L kept.
    let det_printed = determinant_78(&m::EQ_P.atom(), &m::EQ_N.atom());
    let cb = &c_ * cos_t().pow(Atom::num(2)) + var("B") * sin_t().pow(Atom::num(2));
    let l_ = var("L");
    let p_fn = with(&m::EQ_P.atom(), &[("dp", zero()), ("dn", zero())]);
    let n_fn = with(&m::EQ_N.atom(), &[("dp", zero()), ("dn", zero()), ("ds", zero())]);
    let p_n = d(&p_fn, "n");
    let n_p = simplify(&subst(&d(&n_fn, "p"), "p", &zero()));
    let p_theta = hoop::lagrange::d_theta(&p_fn);
    let printed_1p = [
        &cb * &p_theta - &p_n * &n_p,
        &l_ * cos_t() * (&p_n + &n_p),
        &a_ * &cb - l_.pow(Atom::num(2)) * cos_t().pow(Atom::num(2)),
    ];
    let ok0 = is_zero(&det_printed[0]);
    let mut chk = compare_all(
        "78",
        "characteristic_78_memoir",
        "the 2x2 determinant of n° 76 for (p), (n) of n° 24 with s' = 0 is lambda times the printed (1)' of n° 78 (coefficients of lambda^0, lambda^1, lambda^2 after the factor)",
        &det_printed[1..],
        &printed_1p,
    );
    chk.holds &= ok0;
    chk.detail = format!("lambda^0 coefficient vanishes: {ok0}; {}", chk.detail);
    checks.push(chk);
    let b1_hoop = [("B1", Atom::num(2) * &mu1 * r_.pow(Atom::num(2)))];
    checks.push(compare("78", "product_78_memoir", "the product condition (2) at theta = 0, n = 0 for the printed equations with B1 = 2 mu1 R^2 is the printed -C mu g h + mu mu1 R^3 h s^2", &at_straight(&with(&det_printed[1], &b1_hoop)), &m::PRODUCT_78.atom()));
    checks.push(compare("78", "sum_78_memoir", "the sum condition (3) at theta = 0, n = 0 for the printed equations with B1 = 2 mu1 R^2 is the printed L R s (mu1 R - mu h)", &at_straight(&with(&det_printed[2], &b1_hoop)), &m::SUM_78.atom()));
    let det_full = determinant_78(&eqs[0], &eqs[1]);
    let full_sum_straight = at_straight(&with(&det_full[2], &b1_hoop));
    let mut chk = compare("78", "sum_78_full_model", "for the derived rider + wheel equations the sum condition at theta = 0, n = 0 is also L R s (mu1 R - mu h)", &full_sum_straight, &m::SUM_78.atom());
    chk.detail.push_str(
        "; the full model gives -L s (mu R h + mu1 R^2): L <= 0 for s > 0 whatever mu1 R - mu h",
    );
    checks.push(chk);

    let mut formulas = vec![
        formula("pns_dp", "24", "p' of the full model (rider + wheel, any L, motor moment 0) (1/s^2).", &pns[0]),
        formula("pns_dn", "24", "n' of the full model (1/s^2).", &pns[1]),
        formula("pns_ds", "24", "s' of the full model (1/s^2).", &pns[2]),
        formula("energy", "24", "Total energy T + V of rider and wheel (J).", &energy),
        formula("rider_p", "23", "The rider's [I sum m (M - O) M''] (n° 23 (2)) (N m).", &rider[0]),
        formula("rider_n", "23", "The rider's [K sum m (M - O) M''] (N m).", &rider[1]),
        formula("rider_s", "23", "The rider's [j sum m (S - O) M''] (N m).", &rider[2]),
        formula("wheel_p", "24", "The wheel's [I sum m1 (M1 - O) M1''] (n° 24 (3)) (N m).", &wheel[0]),
        formula("wheel_n", "24", "The wheel's [K sum m1 (M1 - O) M1''] (N m).", &wheel[1]),
        formula("wheel_s", "24", "The wheel's [j sum m1 (M1 - O) M1''] (N m).", &wheel[2]),
        formula("equilibrium", "29", "(E) of the full model: -(p) at p = p' = n' = s' = 0 (N m).", &equilibrium),
        formula("skid_full", "30", "D complete: J inertia force of G = O + z k over the normal reaction (dimensionless).", &skid_full),
        formula("skid", "30", "D steady (dimensionless).", &skid),
        formula("equilibrium_n32", "32", "(E) normalised (n° 32): B - C = mu z^2, g/R = 1, divided by mu g z cos(theta).", &equilibrium_n32),
        formula("skid_n32", "32", "(D) normalised (n° 32).", &skid_n32),
        formula("stability_simplified", "34", "K of n° 76 for the simplified model of n° 33 (rider letters, L = 0, wheel gyroscopic term) (1/s^2).", &stab_simpl),
        formula("stability", "35", "K of n° 76 for the full model with L = 0 (1/s^2).", &stab_full),
        formula("stability_n39", "39", "(S1) of n° 39 derived: infinitely light wheel, E = 0, g/R = 1, over mu g h.", &stability_n39),
        formula("stability_n40", "40", "(S) of n° 40 derived: B = C + mu h^2, B1 = 2 mu1 R^2, mu1 R^2 = C, g/R = 1, over mu R h.", &stability_n40),
        formula("trinomial_n41", "41", "S(n^2) of n° 41 derived: (S) of n° 40 along (E) of n° 32, times n^2.", &trinomial),
        formula("char78_c0", "78", "n° 78, full model, s constant: constant term of the characteristic equation after the factor lambda.", &det_full[1]),
        formula("char78_c1", "78", "n° 78, full model: coefficient of lambda.", &det_full[2]),
        formula("char78_c2", "78", "n° 78, full model: coefficient of lambda^2.", &det_full[3]),
    ];
    formulas.extend([
        printed_formula("memoir_rider_p", &m::RIDER_P, "Printed (2) of n° 23, first line."),
        printed_formula("memoir_rider_n", &m::RIDER_N, "Printed (2) of n° 23, second line."),
        printed_formula("memoir_rider_s", &m::RIDER_S, "Printed (2) of n° 23, third line."),
        printed_formula("memoir_wheel_p", &m::WHEEL_P, "Printed (3) of n° 24, first line."),
        printed_formula("memoir_wheel_n", &m::WHEEL_N, "Printed (3) of n° 24, second line."),
        printed_formula("memoir_wheel_s", &m::WHEEL_S, "Printed (3) of n° 24, third line."),
        printed_formula("memoir_eq_p", &m::EQ_P, "Printed (p) of n° 24 (merged letters)."),
        printed_formula("memoir_eq_n", &m::EQ_N, "Printed (n) of n° 24 (merged letters)."),
        printed_formula("memoir_eq_s", &m::EQ_S, "Printed (s) of n° 24 (merged letters, motor 0)."),
        printed_formula("memoir_equilibrium", &m::EQUILIBRIUM, "Printed (E) of n° 29 (N m)."),
        printed_formula("memoir_skid_full", &m::SKID_FULL, "Printed complete D of n° 30."),
        printed_formula("memoir_skid", &m::SKID, "Printed steady (D) of n° 30."),
        printed_formula("memoir_equilibrium_n32", &m::EQUILIBRIUM_N32, "Printed (E) of n° 32."),
        printed_formula("memoir_skid_n32", &m::SKID_N32, "Printed (D) of n° 32."),
        printed_formula("memoir_stability_n39", &m::STABILITY_39_N, "Printed (S1) of n° 39."),
        printed_formula("memoir_stability_n40", &m::STABILITY_40_N, "Printed (S) of n° 40."),
        printed_formula("memoir_trinomial_n41", &m::TRINOMIAL_41, "Printed S(n^2) of n° 41."),
        printed_formula(
            "memoir_product_78",
            &m::PRODUCT_78,
            "Printed (2) of n° 78 at theta = 0, n = 0.",
        ),
        printed_formula("memoir_sum_78", &m::SUM_78, "Printed (3) of n° 78 at theta = 0, n = 0."),
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
    Ok(Derivation {
        model: "unicycle".to_string(),
        source: file!().to_string(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: INPUTS.iter().map(|s| s.to_string()).collect(),
        formulas,
        checks,
        nominal: crate::derive::nominal::values("unicycle"),
        // Every simulation step of the unicycle evaluates this program: 100 Horner schemes take
        // it from 2,281 operations (the two usual efforts) to 1,104.
        horner_schemes: vec![100],
    })
}
