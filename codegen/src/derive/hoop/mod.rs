//! The rolling hoop (memoir Part I, ch. I, n° 1–12, and n° 71–77): equations of motion by the
//! moments of the inertia forces ([`motion`], n° 5–7) and by Carvallo's modified Lagrange
//! equations ([`lagrange`], n° 71–73), steady states, stability and skidding ([`steady`],
//! n° 8–12 and 76–77), each derived with symbolica and checked against the memoir's printed
//! formulas, transcribed by hand in [`memoir`].
//!
//! [`derive`] returns the formulas of the hoop model contract (outputs `pqr_*`, `pns_*`,
//! `energy`, `inertia_*`, `equilibrium`, `stability`, `skid`, `equilibrium_direct`, the
//! `*_n12` forms and the `memoir_*` transcriptions) and every [`Check`] made on the way.
//! The equations of motion the model generates (systems (1) and (2) of n° 7–8, and every
//! steady-state formula drawn from them) are the mechanics engine's: the hoop's description
//! ([`description`]) derived by Kane's method, solved for p', n', s'. The derivation checks them
//! exactly against the moments of the inertia forces (n° 7), the memoir's Lagrange equations
//! of n° 73 (the engine's modified Lagrange equations as well) and the printed formulas.
//! Equalities are decided exactly: both sides are brought to one fraction and the numerator is
//! reduced modulo $\sin^2\theta + \cos^2\theta - 1$ (see [`crate::cas::reduce_trig`]).

pub mod body;
pub mod description;
pub mod discussion;
pub mod lagrange;
pub mod memoir;
pub mod motion;
pub mod steady;

use anyhow::{ensure, Result};
use symbolica::atom::{Atom, AtomCore};

use crate::cas::{cos_t, is_zero, rat, show, simplify, sin_t, solve_linear, subst, to_trig, var};
use crate::mechanics::frame::{time_derivative, Trihedron, Vector};
use crate::{Check, Derivation, Formula};

/// Parameter names of the hoop model, in order.
pub const PARAMS: [&str; 3] = ["R", "g", "mu"];
/// Input names of the hoop model, in order.
pub const INPUTS: [&str; 6] = ["theta", "p", "q", "r", "n", "s"];

/// Rotation $\Omega = pI + sj + nK$ written on (I, j, k): $q = s + n\sin\theta$,
/// $r = n\cos\theta$ (n° 2).
pub fn omega_pns() -> Vector {
    Vector::new(Trihedron::IJK, var("p"), Atom::num(0), var("n"))
        .add(&Vector::unit(Trihedron::Ijk, 1).scale(&var("s")))
        .to(Trihedron::Ijk)
}

/// Total energy $T + V$ with $2T = \sum m M'^2$, $M' = |\Omega(M - O)$ and
/// $V = \mu g R\cos\theta$ (height of S), in θ, p, n, s.
pub fn energy() -> Atom {
    simplify(&(lagrange::kinetic_energy() + var("mu") * var("g") * var("R") * cos_t()))
}

/// A check that `derived` equals `factor` times `printed`.
fn compare(
    section: &str,
    id: &str,
    statement: &str,
    derived: &Atom,
    printed: &Atom,
    factor: &Atom,
) -> Check {
    let diff = simplify(&(derived - factor * printed));
    let holds = is_zero(&diff);
    let scale = if *factor == Atom::num(1) { String::new() } else { format!("({}) * ", factor) };
    let perturbed = crate::falsify::perturb_one(derived, |d| is_zero(&(d - factor * printed)));
    Check {
        perturbed: Some(perturbed),
        section: section.to_string(),
        id: id.to_string(),
        statement: statement.to_string(),
        holds,
        detail: format!(
            "derived: {}; expected: {}; simplified difference derived - {}expected (exact, reduced with sin^2+cos^2=1): {}",
            show(derived),
            show(printed),
            scale,
            show(&diff)
        ),
    }
}

/// A check that two lists of expressions agree term by term.
fn compare_all(
    section: &str,
    id: &str,
    statement: &str,
    names: &[&str],
    a: &[Atom],
    b: &[Atom],
) -> Check {
    let diffs: Vec<Atom> = a.iter().zip(b).map(|(x, y)| simplify(&(x - y))).collect();
    let holds = diffs.iter().all(is_zero);
    let perturbed = crate::falsify::perturb(a, |d| d.iter().zip(b).all(|(x, y)| is_zero(&(x - y))));
    let detail = names
        .iter()
        .zip(&diffs)
        .map(|(n, d)| format!("{n}: difference {}", show(d)))
        .collect::<Vec<_>>()
        .join("; ");
    Check {
        perturbed: Some(perturbed),
        section: section.to_string(),
        id: id.to_string(),
        statement: statement.to_string(),
        holds,
        detail,
    }
}

/// A derived formula handed to the emission, simplified and written with `sin`, `cos`, `tan`.
pub(crate) fn formula(name: &str, section: &str, description: &str, expr: &Atom) -> Formula {
    Formula {
        name: name.to_string(),
        section: section.to_string(),
        description: description.to_string(),
        expr: to_trig(&simplify(expr)),
    }
}

/// A memoir transcription handed over as is (with `sin`, `cos`, `tan` of θ).
pub(crate) fn printed_formula(name: &str, p: &memoir::Printed, description: &str) -> Formula {
    Formula {
        name: name.to_string(),
        section: p.section.to_string(),
        description: description.to_string(),
        expr: p.trig_atom(),
    }
}

/// Derives every hoop formula and runs the checks.
pub fn derive() -> Result<Derivation> {
    use memoir as m;
    let mut checks: Vec<Check> = Vec::new();
    let one = Atom::num(1);
    let (mu, r_, g) = (var("mu"), var("R"), var("g"));
    let mr2 = &mu * &r_.pow(Atom::num(2));

    // n° 4: moments of inertia by integration over the circle.
    let i = Vector::unit(Trihedron::Ijk, 0);
    let j = Vector::unit(Trihedron::Ijk, 1);
    let k = Vector::unit(Trihedron::Ijk, 2);
    let a = body::moment_of_inertia(&i);
    let b = body::moment_of_inertia(&j);
    let c = body::moment_of_inertia(&k);
    for (id, val, pr, axis) in [
        ("inertia_a", &a, &m::INERTIA_A, "OI"),
        ("inertia_b", &b, &m::INERTIA_B, "Oj"),
        ("inertia_c", &c, &m::INERTIA_C, "Sk"),
    ] {
        checks.push(compare("4", &format!("{id}_memoir"), &format!("the moment of inertia about {axis} integrated over the hoop equals the printed value (7)"), val, &pr.atom(), &one));
    }
    checks.push(compare(
        "7",
        "revolution_relation",
        "A = C + mu R^2 (the hoop is of revolution about its axis, n° 7)",
        &a,
        &(&c + &mr2),
        &one,
    ));
    let abc = |e: &Atom| subst(&subst(&subst(e, "A", &a), "B", &b), "C", &c);

    // n° 5–6: moments about O.
    let h_sums = motion::momentum_moment_from_sums();
    let h = motion::momentum_moment(&a, &b, &c);
    checks.push(compare_all("6", "principal_axes", "the momentum moment about O summed over the hoop's points is Ap I + Bq j + Cr k (I, j, k are principal axes)", &["I", "j", "k"], &h_sums.comps, &h.comps));
    let w = motion::weight_moment();
    checks.push(compare_all(
        "5",
        "weight_moment_memoir",
        "the moment of the weight about O is I mu g R sin(theta)",
        &["I", "j", "k"],
        &w.comps,
        &[m::WEIGHT_MOMENT_I.atom(), Atom::num(0), Atom::num(0)],
    ));
    let h_gen = motion::momentum_moment(&var("A"), &var("B"), &var("C"));
    let j_gen = motion::inertia_moment(&h_gen);
    checks.push(compare_all("6", "inertia_moment_memoir", "the moment of the inertia forces J = J1 + J2 with general A, B, C equals the printed J of n° 6", &["I", "j", "k"], &j_gen.comps, &[m::INERTIA_MOMENT_I.atom(), m::INERTIA_MOMENT_J.atom(), m::INERTIA_MOMENT_K.atom()]));

    // n° 7: power identity with A = C + mu R^2 (the memoir's verification).
    let eq_gen = motion::equations_pqr(&h_gen);
    let power = &var("p") * &eq_gen[0] + &var("q") * &eq_gen[1] + &var("r") * &eq_gen[2];
    let d_t = var("A") * var("p") * var("dp")
        + var("B") * var("q") * var("dq")
        + var("C") * var("r") * var("dr");
    let power_minus = &power - &d_t + &mu * &g * &r_ * sin_t() * var("p");
    let with_relation = subst(&power_minus, "A", &(var("C") + &mr2));
    let mut chk = compare("7", "power_identity", "p, q, r times the three equations of n° 7, summed with A = C + mu R^2, give the energy equation d(T)/dt = mu g R sin(theta) p", &with_relation, &Atom::num(0), &one);
    chk.detail =
        format!("{}; without A = C + mu R^2 the residual is {}", chk.detail, show(&power_minus));
    checks.push(chk);

    // n° 7: systems (1) and (2).
    let pqr = motion::system1(&h);
    let pns = motion::system2(&h);
    let eq1 = motion::equations_pqr(&h);
    let printed_sys1 = [m::SYSTEM1_I.atom(), m::SYSTEM1_J.atom(), m::SYSTEM1_K.atom()];
    let scaled: Vec<Atom> = eq1.iter().map(|e| simplify(&(e / &mr2))).collect();
    checks.push(compare_all(
        "7",
        "system1_memoir",
        "the moment equations divided by mu R^2 are the printed system (1) of n° 7",
        &["(I)", "(j)", "(k)"],
        &scaled,
        &printed_sys1,
    ));
    let memoir_pqr = [m::PQR_DP.atom(), m::PQR_DQ.atom(), m::PQR_DR.atom()];
    checks.push(compare_all(
        "8",
        "system1_solved_memoir",
        "system (1) solved for p', q', r' is the printed system (1) of n° 8",
        &["p'", "q'", "r'"],
        &pqr,
        &memoir_pqr,
    ));
    let printed_sys2 = [m::SYSTEM2_P.atom(), m::SYSTEM2_N.atom(), m::SYSTEM2_S.atom()];
    let memoir_pns = solve_linear(&printed_sys2, &["dp", "dn", "ds"]);
    checks.push(compare_all(
        "7",
        "system2_memoir",
        "system (2) in p, n, s solved for p', n', s' equals the printed system (2) of n° 7 solved",
        &["p'", "n'", "s'"],
        &pns,
        &memoir_pns,
    ));
    let en = energy();
    let flow = |e: &Atom| {
        let e = subst(e, "dp", &pns[0]);
        let e = subst(&e, "dn", &pns[1]);
        subst(&e, "ds", &pns[2])
    };
    checks.push(compare(
        "7",
        "energy_conservation",
        "the energy T + V is constant along system (2)",
        &flow(&time_derivative(&en)),
        &Atom::num(0),
        &one,
    ));

    // n° 71–73: Lagrange.
    let t = lagrange::kinetic_energy();
    checks.push(compare("71", "kinetic_energy_memoir", "T summed over the hoop's points is half the printed 2T = Ap^2 + B(s + n sin)^2 + C n^2 cos^2", &t, &abc(&m::TWICE_KINETIC.atom()), &rat(1, 2)));
    let corr_nu = lagrange::correction_nu();
    let corr_sigma = lagrange::correction_sigma();
    checks.push(compare(
        "73",
        "correction_nu_memoir",
        "the correction -sum m M'|(dM/dnu)' summed over the hoop is -mu R^2 p s cos(theta)",
        &corr_nu,
        &m::CORRECTION_NU.atom(),
        &one,
    ));
    checks.push(compare(
        "73",
        "correction_sigma_memoir",
        "the correction -sum m M'|(dM/dsigma)' summed over the hoop is (A - C) p r",
        &corr_sigma,
        &abc(&m::CORRECTION_SIGMA.atom()),
        &one,
    ));
    checks.push(compare(
        "73",
        "correction_nu_via_centre",
        "the nu correction summed over the points equals the memoir's mu [S'KO'] (sum of m M' = mu S')",
        &corr_nu,
        &lagrange::correction_nu_via_centre(),
        &one,
    ));
    let h_pns = h_sums.map(motion::to_pns);
    let (corr_sigma_memoir_route, last_term) = lagrange::correction_sigma_via_momentum(&h_pns);
    checks.push(compare(
        "73",
        "correction_sigma_via_momentum",
        "the sigma correction summed over the points equals the memoir's -(p Cr - r Ap + [S'jO'] mu) from the momentum moment",
        &corr_sigma,
        &corr_sigma_memoir_route,
        &one,
    ));
    // The mixed product is a literal 0: the falsification moves the centre S off the hoop's
    // plane.
    let off = Vector::unit(Trihedron::Ijk, 1).scale(&(var("R") / Atom::num(8)));
    let perturbed = crate::Perturbed {
        what: "the centre S moved off the hoop's plane by R/8 along j: [S'jO'] run on it".into(),
        holds: is_zero(&simplify(&lagrange::last_term_product(&off))),
    };
    checks.push(crate::falsify::with_perturbation(
        compare(
            "73",
            "sigma_last_term_zero",
            "the last term sum of m [M'jO'] of the sigma correction vanishes (\"on vérifie simplement que le dernier terme est nul\")",
            &last_term,
            &Atom::num(0),
            &one,
        ),
        Some(perturbed),
    ));
    let lag = lagrange::equations(true);
    checks.push(compare_all("73", "lagrange_equations_memoir", "the modified Lagrange equations (theta), (nu), (sigma) are the printed ones with A, B, C of n° 4", &["(theta)", "(nu)", "(sigma)"], &lag, &[abc(&m::LAGRANGE_THETA.atom()), abc(&m::LAGRANGE_NU.atom()), abc(&m::LAGRANGE_SIGMA.atom())]));
    let eq1_pns: Vec<Atom> = eq1.iter().map(motion::to_pns).collect();
    checks.push(compare_all("73", "lagrange_combinations", "(theta) is the (I) equation, (sigma) the (j) equation and (nu) is sin(theta) (j) + cos(theta) (k) of the moment equations", &["(theta)", "(nu)", "(sigma)"], &lag, &[eq1_pns[0].clone(), sin_t() * &eq1_pns[1] + cos_t() * &eq1_pns[2], eq1_pns[1].clone()]));
    let lag_solved = lagrange::solved(true);
    checks.push(compare_all("73", "lagrange_modified_agrees", "the modified Lagrange equations solved for p', n', s' agree with the moment equations (system (2))", &["p'", "n'", "s'"], &lag_solved, &pns));
    let plain = lagrange::equations(false);
    checks.push(compare(
        "71",
        "lagrange_unmodified_theta",
        "the unmodified Lagrange (theta) equation is the (I) equation of n° 7",
        &plain[0],
        &eq1_pns[0],
        &one,
    ));
    let plain_solved = lagrange::solved(false);
    for (idx, id, what, corr) in [
        (1usize, "lagrange_unmodified_nu", "n'", &corr_nu),
        (2, "lagrange_unmodified_sigma", "s'", &corr_sigma),
    ] {
        let mut chk = compare(
            "71",
            id,
            &format!("the unmodified Lagrange equations give the {what} of n° 7"),
            &plain_solved[idx],
            &pns[idx],
            &one,
        );
        chk.detail = format!("{}; the plain equation lacks the term {}", chk.detail, show(corr));
        // The memoir's statement fails; with Carvallo's correction added to the plain
        // equations (the modified equations of n° 72) it must hold, so the verdict moves.
        chk.perturbed = Some(crate::Perturbed {
            what: format!(
                "Carvallo's correction ({}) added to the plain equation: the modified equations of n° 72",
                show(corr)
            ),
            holds: is_zero(&(&lag_solved[idx] - &pns[idx])),
        });
        checks.push(chk);
    }

    // The hoop as a description (`description`): the mechanics engine's Kane and modified
    // Lagrange equations give the same accelerations and energy as the moments of n° 7 and the
    // memoir's Lagrange equations of n° 73, exactly. From here on the engine's accelerations are
    // the model's: what follows (n° 8-12) and the generated systems (1) and (2) use them.
    let ([kane, lagrange_engine], engine_energy) =
        description::accelerations(&description::hoop(), [1, 1, 1])?;
    checks.push(compare_all("7", "engine_kane_is_system2", "the engine's Kane equations of the hoop's description, solved for p', n', s', are system (2) of n° 7 (the moments of the inertia forces)", &["p'", "n'", "s'"], &kane, &pns));
    checks.push(compare_all("73", "engine_lagrange_is_memoir_lagrange", "the engine's modified Lagrange equations of the description, solved for p', n', s', are the memoir's modified Lagrange equations of n° 73 solved", &["p'", "n'", "s'"], &lagrange_engine, &lag_solved));
    checks.push(compare(
        "7",
        "engine_energy",
        "the engine's total energy of the description is T + V of n° 7",
        &engine_energy,
        &en,
        &one,
    ));
    let pns = kane;
    let en = engine_energy;
    // System (1) from the engine's (2): q = s + n sin(theta), r = n cos(theta).
    let in_pqr = |e: &Atom| {
        let n = var("r") / cos_t();
        subst(&subst(e, "s", &(var("q") - &n * sin_t())), "n", &n)
    };
    let pqr_engine: Vec<Atom> = [
        pns[0].clone(),
        &pns[2] + &pns[1] * sin_t() + var("n") * cos_t() * var("p"),
        &pns[1] * cos_t() - var("n") * sin_t() * var("p"),
    ]
    .iter()
    .map(|e| simplify(&in_pqr(e)))
    .collect();
    checks.push(compare_all("8", "engine_is_system1", "the engine's accelerations written in p, q, r (q = s + n sin(theta), r = n cos(theta)) are system (1) of n° 8 solved from the moments", &["p'", "q'", "r'"], &pqr_engine, &pqr));
    let pqr = pqr_engine;

    // n° 8: equilibrium.
    let e = steady::equilibrium(&pns);
    checks.push(compare(
        "8",
        "equilibrium_memoir",
        "p' at p = 0 is the printed (E) of n° 8",
        &e,
        &m::EQUILIBRIUM.atom(),
        &one,
    ));

    // n° 76–77 and 9: stability.
    let (stab, factor_ok, coeffs) = steady::stability_by_determinant(&pns);
    // The derived side: the coefficient of lambda^4, scaled.
    let lead = crate::Perturbed {
        what: format!(
            "the derived coefficient of lambda^4 ({}) scaled by {}",
            show(&coeffs[4]),
            crate::falsify::FACTOR
        ),
        holds: factor_ok
            && is_zero(&coeffs[3])
            && is_zero(&(&coeffs[4] * crate::falsify::factor() - &one)),
    };
    checks.push(Check {
        perturbed: Some(lead),
        section: "77".to_string(),
        id: "characteristic_factor".to_string(),
        statement: "the characteristic determinant of n° 76–77 for system (2) at p = 0 is lambda^2 (lambda^2 + K)".to_string(),
        holds: factor_ok && is_zero(&coeffs[3]) && is_zero(&(&coeffs[4] - &one)),
        detail: format!("coefficients of lambda^0..lambda^4: {}", coeffs.iter().map(show).collect::<Vec<_>>().join(", ")),
    });
    checks.push(compare(
        "9",
        "stability_memoir",
        "the constant term K of the reduced characteristic equation is the printed (S) of n° 9",
        &stab,
        &m::STABILITY.atom(),
        &one,
    ));
    let route9 = steady::minus_p2_over_p(
        &pns[0],
        &[("dp", pns[0].clone()), ("dn", pns[1].clone()), ("ds", pns[2].clone())],
    );
    checks.push(compare(
        "9",
        "stability_taylor_route",
        "n° 9's route -p''/p at p = 0 (variables p, n, s) equals the determinant's K",
        &route9,
        &stab,
        &one,
    ));
    let route9_pqr = motion::to_pns(&steady::minus_p2_over_p(
        &pqr[0],
        &[("dp", pqr[0].clone()), ("dq", pqr[1].clone()), ("dr", pqr[2].clone())],
    ));
    checks.push(compare("9", "stability_taylor_route_pqr", "n° 9's route in p, q, r then q = s + n sin, r = n cos (the memoir's order) equals the determinant's K", &route9_pqr, &stab, &one));
    let f1 = simplify(&(-time_derivative(&pqr[0]) / var("p")));
    checks.push(compare(
        "9",
        "minus_f1_memoir",
        "-p''/p before substituting q', r' is the printed -f1 of n° 9",
        &f1,
        &m::MINUS_F1.atom(),
        &one,
    ));
    let routh = simplify(&subst(
        &subst(&subst(&stab, "sin_theta", &Atom::num(0)), "cos_theta", &one),
        "n",
        &Atom::num(0),
    ));
    checks.push(compare("9", "routh_thin_ring", "at theta = 0, n = 0 the stability first member is (8/3)(s^2 - g/(4R)): positive iff s^2 > g/(4R) (Routh, thin ring)", &routh, &(var("s").pow(Atom::num(2)) - &g / (Atom::num(4) * &r_)), &rat(8, 3)));

    // n° 10: skid.
    let force = steady::centre_inertia_force();
    checks.push(compare_all(
        "10",
        "centre_force_memoir",
        "the inertia force of the centre in the steady state is -J mu R n^2 (sin(theta) + s/n)",
        &["I", "J", "K"],
        &force.comps,
        &[Atom::num(0), m::CENTRE_FORCE_J.atom(), Atom::num(0)],
    ));
    let d = steady::skid();
    checks.push(compare(
        "10",
        "skid_memoir",
        "the skid tendency is the printed D of n° 10",
        &d,
        &m::SKID.atom(),
        &one,
    ));

    // n° 11: direct method.
    let mom = steady::direct_moments();
    checks.push(compare(
        "11",
        "moment_conversion_memoir",
        "the moment about OI of the conversion centrifugal forces is the printed (1) of n° 11",
        &mom[0],
        &m::MOMENT_CONVERSION.atom(),
        &one,
    ));
    checks.push(compare(
        "11",
        "moment_compound_memoir",
        "the moment about OI of the compound centrifugal forces is the printed (2) of n° 11",
        &mom[1],
        &m::MOMENT_COMPOUND.atom(),
        &one,
    ));
    // Each point's moment is a literal 0 (the forces lie in the hoop's plane, which holds OI):
    // the falsification tilts the rolling rotation's axis out of the plane.
    let tilted = Vector::unit(Trihedron::Ijk, 1)
        .add(&Vector::unit(Trihedron::Ijk, 2).scale(&rat(1, 8)))
        .scale(&var("s"));
    let perturbed = crate::Perturbed {
        what: "the rolling rotation s j tilted toward k, s (j + k/8) (an axis that is not the hoop's own): its centrifugal forces' moment about OI".into(),
        holds: is_zero(&steady::rolling_moment(&tilted)),
    };
    checks.push(crate::falsify::with_perturbation(
        compare(
            "11",
            "moment_rolling_zero",
            "the rolling (relative) centrifugal forces have no moment about OI",
            &mom[2],
            &Atom::num(0),
            &one,
        ),
        Some(perturbed),
    ));
    checks.push(compare(
        "11",
        "moment_weight_memoir",
        "the moment about OI of the weight is the printed (3) of n° 11",
        &mom[3],
        &m::MOMENT_WEIGHT.atom(),
        &one,
    ));
    let e_direct = steady::equilibrium_direct();
    checks.push(compare(
        "11",
        "equilibrium_direct_memoir",
        "the sum of the moments about OI over mu R^2 is the printed equation of n° 11",
        &e_direct,
        &m::EQUILIBRIUM_DIRECT.atom(),
        &one,
    ));
    checks.push(compare(
        "11",
        "equilibrium_direct_three_halves",
        "the direct sum over mu R^2 is 3/2 times (E) of n° 8",
        &e_direct,
        &e,
        &rat(3, 2),
    ));

    // n° 12: normalised forms.
    let e12 = steady::equilibrium_n12(&e);
    let s12 = steady::normalise(&stab);
    let d12 = steady::normalise(&d);
    checks.push(compare("12", "equilibrium_n12_memoir", "(E) with g/R = 1 divided by sin(theta) cos(theta) ((3/2)E divided by (3/2) sin cos) is the printed (E) of n° 12", &e12, &m::EQUILIBRIUM_N12.atom(), &one));
    checks.push(compare(
        "12",
        "stability_n12_memoir",
        "(S) with g/R = 1 is the printed (S) of n° 12",
        &s12,
        &m::STABILITY_N12.atom(),
        &one,
    ));
    checks.push(compare(
        "12",
        "skid_n12_memoir",
        "D with g/R = 1 is the printed (D) of n° 12",
        &d12,
        &m::SKID_N12.atom(),
        &one,
    ));

    let mut formulas = vec![
        formula("pqr_dp", "8", "p' of system (1) (n° 7/8), fall acceleration (1/s^2).", &pqr[0]),
        formula("pqr_dq", "8", "q' of system (1) (n° 7/8), rate of change of the rotation on j (1/s^2).", &pqr[1]),
        formula("pqr_dr", "8", "r' of system (1) (n° 7/8), rate of change of the rotation on k (1/s^2).", &pqr[2]),
        formula("pns_dp", "7", "p' of system (2) (n° 7), fall acceleration in the variables p, n, s (1/s^2).", &pns[0]),
        formula("pns_dn", "7", "n' of system (2) (n° 7), turning acceleration (1/s^2).", &pns[1]),
        formula("pns_ds", "7", "s' of system (2) (n° 7), rolling acceleration (1/s^2).", &pns[2]),
        formula("energy", "7", "Total energy T + V of the rolling hoop with q = s + n sin(theta), r = n cos(theta) (J).", &en),
        formula("inertia_a", "4", "Moment of inertia A about the tangent OI, integrated over the hoop (kg m^2).", &a),
        formula("inertia_b", "4", "Moment of inertia B about the normal Oj to the hoop's plane (kg m^2).", &b),
        formula("inertia_c", "4", "Moment of inertia C about the diameter Sk (kg m^2).", &c),
        formula("equilibrium", "8", "(E): p' at p = 0, zero in a steady state (1/s^2).", &e),
        formula("stability", "9", "(S) by n° 76-77: constant term of the characteristic equation divided by lambda^2; positive iff stable (1/s^2).", &stab),
        formula("skid", "10", "D: skid tendency, J-component of the centre's inertia force over the weight (dimensionless).", &d),
        formula("equilibrium_direct", "11", "Sum of the moments about OI of the conversion and compound centrifugal forces and of the weight, over mu R^2 (1/s^2).", &e_direct),
        formula("equilibrium_n12", "12", "(E) normalised: g/R = 1, divided by (3/2) sin(theta) cos(theta) so the n^2 coefficient is 1.", &e12),
        formula("stability_n12", "12", "(S) normalised: g/R = 1.", &s12),
        formula("skid_n12", "12", "(D) normalised: g/R = 1.", &d12),
    ];
    let mp = |idx: usize, eqs: &[memoir::Printed; 3], name: &str, desc: &str| Formula {
        name: name.to_string(),
        section: eqs[idx].section.to_string(),
        description: desc.to_string(),
        expr: to_trig(&memoir_pns[idx]),
    };
    let sys2 = [m::SYSTEM2_P, m::SYSTEM2_N, m::SYSTEM2_S];
    formulas.extend([
        printed_formula("memoir_pqr_dp", &m::PQR_DP, "Printed p' of system (1), n° 8 (1/s^2)."),
        printed_formula("memoir_pqr_dq", &m::PQR_DQ, "Printed q' of system (1), n° 8 (1/s^2)."),
        printed_formula("memoir_pqr_dr", &m::PQR_DR, "Printed r' of system (1), n° 8 (1/s^2)."),
        mp(0, &sys2, "memoir_pns_dp", "Printed system (2) of n° 7 solved for p' (1/s^2)."),
        mp(1, &sys2, "memoir_pns_dn", "Printed system (2) of n° 7 solved for n' (1/s^2)."),
        mp(2, &sys2, "memoir_pns_ds", "Printed system (2) of n° 7 solved for s' (1/s^2)."),
        printed_formula("memoir_inertia_a", &m::INERTIA_A, "Printed A of (7), n° 4 (kg m^2)."),
        printed_formula("memoir_inertia_b", &m::INERTIA_B, "Printed B of (7), n° 4 (kg m^2)."),
        printed_formula("memoir_inertia_c", &m::INERTIA_C, "Printed C of (7), n° 4 (kg m^2)."),
        printed_formula("memoir_equilibrium", &m::EQUILIBRIUM, "Printed (E) of n° 8 (1/s^2)."),
        printed_formula("memoir_stability", &m::STABILITY, "Printed (S) of n° 9 (1/s^2)."),
        printed_formula("memoir_skid", &m::SKID, "Printed D of n° 10 (dimensionless)."),
        printed_formula(
            "memoir_equilibrium_direct",
            &m::EQUILIBRIUM_DIRECT,
            "Printed sum of moments of n° 11 over mu R^2 (1/s^2).",
        ),
        printed_formula(
            "memoir_equilibrium_n12",
            &m::EQUILIBRIUM_N12,
            "Printed (E) of n° 12 (normalised).",
        ),
        printed_formula(
            "memoir_stability_n12",
            &m::STABILITY_N12,
            "Printed (S) of n° 12 (normalised).",
        ),
        printed_formula("memoir_skid_n12", &m::SKID_N12, "Printed (D) of n° 12 (normalised)."),
    ]);
    for f in &formulas {
        let allowed = ["R", "g", "mu", "theta", "p", "q", "r", "n", "s"];
        for sym in f.expr.get_all_symbols(false) {
            let name = sym.get_stripped_name();
            ensure!(
                allowed.contains(&name),
                "formula {} uses the unexpected symbol {name}",
                f.name
            );
        }
    }
    Ok(Derivation {
        model: "hoop".to_string(),
        source: file!().to_string(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: INPUTS.iter().map(|s| s.to_string()).collect(),
        formulas,
        checks,
        nominal: crate::derive::nominal::values("hoop"),
        horner_schemes: Vec::new(),
    })
}
