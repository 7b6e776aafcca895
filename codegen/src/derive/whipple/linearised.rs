//! The linear Carvallo–Whipple bicycle from the mechanics engine: the description of
//! [`super::description`] derived by both of the engine's routes (Kane's method and Carvallo's
//! modified Lagrange equations) and linearised about upright straight running at speed $v$
//! ([`crate::mechanics::engine::linear`]): lean, pitch and steer zero, the lean and steer rates
//! zero, the rear wheel turning at $\dot\theta_R = -v/r_R$.
//!
//! With $u = (\dot\varphi, \dot\delta, \dot\theta_R)$ the linearised equations are
//! $M_0\,\delta\dot u = f_q\,\delta q + f_u\,\delta u$; the rear wheel's row decouples, and the
//! lean and steer rows are the benchmark's
//! $M\ddot q + vC_1\dot q + (gK_0 + v^2K_2)q = 0$ with $M = M_0$, $vC_1 = -f_u$ and
//! $gK_0 + v^2K_2 = -f_q$ (the pitch's perturbation, solved from the front contact's height,
//! vanishes at first order). Each of these facts is a check of the derivation, not an
//! assumption, and so is the agreement of the two routes, entry by entry, exactly.

use std::collections::BTreeMap;

use anyhow::{anyhow, Result};
use symbolica::atom::{Atom, AtomCore};

use super::nonlinear::INDEPENDENT;
use super::{
    check, check_perturbed, description, reduce, vanishes, with_perturbation, Matrices, COS_LAMBDA,
    SIN_LAMBDA,
};
use crate::cas::{expr, reduce_pair, var};
use crate::mechanics::engine;
use crate::mechanics::engine::linear::{self, Linear, Reference};
use crate::{Check, Derivation};

/// The engine's $\sin\lambda$, $\cos\lambda$ written as the stand-ins of [`super::reduce`].
fn stand_ins(e: &Atom) -> Atom {
    e.replace(expr("sin(lambda)").to_pattern())
        .with(var(SIN_LAMBDA).to_pattern())
        .replace(expr("cos(lambda)").to_pattern())
        .with(var(COS_LAMBDA).to_pattern())
}

/// The reference motion: upright straight running, the rear wheel turning at `rear_rate`
/// ($-v/r_R$ for the speed $v$); lean and steer perturbed, the pitch solved from the front
/// contact's height.
pub fn upright(rear_rate: Atom) -> Reference {
    let strings = |xs: &[&str]| xs.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let mut values: BTreeMap<String, Atom> = ["phi", "theta", "delta", "phid", "deltad"]
        .iter()
        .map(|s| (s.to_string(), Atom::num(0)))
        .collect();
    values.insert("thetaRd".into(), rear_rate);
    Reference {
        values,
        coordinates: strings(&["phi", "delta"]),
        dependent: strings(&["theta"]),
        speeds: strings(&INDEPENDENT),
        heights: strings(&["F_contact_height"]),
        inputs: Vec::new(),
    }
}

/// The engine's derivation of the description by both routes (Kane's formulas, then the
/// modified Lagrange equations').
pub fn both_routes() -> Result<Derivation> {
    let (d, _, _) = engine::derivation(&description::whipple(), file!())
        .map_err(|e| anyhow!("the Whipple bicycle: {e}"))?;
    Ok(d)
}

/// One route's equations (`""` Kane's, `"L_"` the modified Lagrange equations) linearised
/// about `reference`, every jet reduced modulo $\sin^2\lambda + \cos^2\lambda = 1$ as it is
/// made (which keeps the mass matrix's entries at tens of terms instead of thousands).
pub fn route(d: &Derivation, prefix: &str, reference: &Reference) -> Result<Linear> {
    linear::linearise(&d.formulas, prefix, reference, &normal)
        .map_err(|e| anyhow!("the Whipple bicycle: {e}"))
}

/// The lean and steer rows of Carvallo's modified Lagrange equations split by origin, linearised
/// about upright running and written as generalised inertia forces (the left-hand side of
/// $\ldots = Q$), each a $2 \times 2$ matrix (rows lean, steer; columns lean, steer), reduced:
/// the momentum's derivative $(\partial T/\partial q')'$ has the accelerations' coefficients
/// $M$ and the rates' and angles' `momentum_rate`, `momentum_angle`; Carvallo's correction
/// $-\sum m\,M'\,|\,(\partial M/\partial q)'$ has no accelerations; the plain Lagrange term
/// $-\mathrm{d}T/\mathrm{d}q$ it replaces (the pitch following through the front contact) is
/// given for comparison. Momentum plus correction is Kane's $M$, $vC_1$, $v^2K_2$.
pub struct Origins {
    /// Coefficients of the rates in $(\partial T/\partial q')'$.
    pub momentum_rate: [[Atom; 2]; 2],
    /// Coefficients of the angles in $(\partial T/\partial q')'$.
    pub momentum_angle: [[Atom; 2]; 2],
    /// Coefficients of the rates in the correction.
    pub correction_rate: [[Atom; 2]; 2],
    /// Coefficients of the angles in the correction.
    pub correction_angle: [[Atom; 2]; 2],
    /// The plain Lagrange term, when the derivation has it.
    pub plain: Option<Plain>,
    /// The yaw rate $\psi'$ to first order: coefficients of lean, steer, lean rate, steer rate.
    pub yaw_rate: [Atom; 4],
}

/// The plain Lagrange term $-\mathrm{d}T/\mathrm{d}q$ linearised, beside the correction's value.
pub struct Plain {
    /// Coefficients of the rates in $-\mathrm{d}T/\mathrm{d}q$.
    pub rate: [[Atom; 2]; 2],
    /// Coefficients of the angles in $-\mathrm{d}T/\mathrm{d}q$.
    pub angle: [[Atom; 2]; 2],
    /// The values at the reference of the correction and of $-\mathrm{d}T/\mathrm{d}q$, by row.
    pub values: [[Atom; 2]; 2],
}

/// The modified Lagrange route of `d` linearised about `reference` with its parts
/// ([`Origins`]).
pub fn origins(d: &Derivation, reference: &Reference) -> Result<(Linear, Origins)> {
    let rows = ["phid", "deltad"];
    let plain = d.formulas.iter().any(|f| f.name == "L_q_phid");
    let mut extra = Vec::new();
    let parts_asked: &[&str] = if plain { &["L_p_", "L_c_", "L_q_"] } else { &["L_p_", "L_c_"] };
    for part in parts_asked {
        extra.extend(rows.iter().map(|u| format!("{part}{u}")));
    }
    extra.push("psid".to_string());
    let (lin, parts) = linear::linearise_with(&d.formulas, "L_", reference, &normal, &extra)
        .map_err(|e| anyhow!("the Whipple bicycle: {e}"))?;
    let red = |e: &Atom| reduce(&stand_ins(e));
    // Rows of a part (0 momentum, 1 correction, 2 dT/dq), signed as inertia forces.
    let mat = |part: usize, rate: bool, sign: i64| -> [[Atom; 2]; 2] {
        std::array::from_fn(|r| {
            std::array::from_fn(|c| {
                let row = &parts[2 * part + r];
                red(&(Atom::num(sign) * if rate { &row.u[c] } else { &row.q[c] }))
            })
        })
    };
    let yaw = parts.last().expect("the yaw rate");
    Ok((
        lin,
        Origins {
            momentum_rate: mat(0, true, 1),
            momentum_angle: mat(0, false, 1),
            correction_rate: mat(1, true, -1),
            correction_angle: mat(1, false, -1),
            plain: plain.then(|| Plain {
                rate: mat(2, true, -1),
                angle: mat(2, false, -1),
                values: std::array::from_fn(|part| {
                    std::array::from_fn(|r| red(&-&parts[2 * (part + 1) + r].value))
                }),
            }),
            yaw_rate: [red(&yaw.q[0]), red(&yaw.q[1]), red(&yaw.u[0]), red(&yaw.u[1])],
        },
    ))
}

/// The normal form of every jet: expanded, in the stand-ins, reduced modulo
/// $\sin^2\lambda + \cos^2\lambda = 1$.
fn normal(e: &Atom) -> Atom {
    reduce_pair(&stand_ins(&e.expand()), &var(SIN_LAMBDA), &var(COS_LAMBDA))
}

/// The reference moved off upright for the falsification of the checks that upright running
/// makes literal zeros (the front contact on the ground, the pitch's first-order term, the
/// equilibrium, the rear wheel's decoupling): the steer set to $\delta_0 = 2\arctan(1/16)$
/// ($\sin\delta_0 = 32/257$, $\cos\delta_0 = 255/257$, about 7.1°), lean and pitch kept at zero,
/// linearised at a rational point of parameter space (the benchmark's values of
/// [`crate::derive::nominal`], $\lambda = 2\arctan(4/25)$ with $\sin\lambda = 200/641$ in
/// place of $\pi/10$, $v = 5$ m/s) so that every jet is a number and the linearisation costs
/// a fraction of the symbolic one.
pub const MOVED: &str = "the reference's steer moved from 0 to 2 atan(1/16) (about 7.1 degrees; lean and pitch kept at 0), linearised at the benchmark's parameters (lambda = 2 atan(4/25)) and v = 5 m/s";

/// `route`'s equations linearised about the reference [`MOVED`] describes.
pub fn moved(d: &Derivation, prefix: &str) -> Result<Linear> {
    at_rational_point(d, prefix, Some((crate::cas::rat(32, 257), crate::cas::rat(255, 257))))
}

/// `route`'s equations linearised at the rational point of parameter space [`MOVED`] names,
/// about upright running, or, with `steer` $= (\sin\delta_0, \cos\delta_0)$, about the
/// reference with the steer moved to $\delta_0$ (lean and pitch kept at zero).
pub fn at_rational_point(
    d: &Derivation,
    prefix: &str,
    steer: Option<(Atom, Atom)>,
) -> Result<Linear> {
    let point: Vec<(String, Atom)> = crate::derive::nominal::values("whipple")
        .into_iter()
        .filter(|(n, _)| n != "lambda" && super::PARAMS.contains(&n.as_str()))
        .map(|(n, v)| (n, crate::cas::rat((v * 1e6).round() as i64, 1_000_000)))
        .collect();
    let numeric = |e: &Atom| -> Atom {
        let mut a = e
            .replace(expr("sin(lambda)").to_pattern())
            .with(crate::cas::rat(200, 641).to_pattern())
            .replace(expr("cos(lambda)").to_pattern())
            .with(crate::cas::rat(609, 641).to_pattern());
        for (n, v) in &point {
            a = crate::cas::subst(&a, n, v);
        }
        a
    };
    let formulas: Vec<crate::Formula> =
        d.formulas.iter().map(|f| crate::Formula { expr: numeric(&f.expr), ..f.clone() }).collect();
    let rr = point.iter().find(|(n, _)| n == "rR").map(|(_, v)| v.clone()).expect("rR");
    let mut reference = upright(Atom::num(-5) / rr);
    let (sin_d, cos_d) = match steer {
        Some(sc) => {
            reference.values.insert("delta".into(), var("delta_ref"));
            sc
        }
        None => (Atom::num(0), Atom::num(1)),
    };
    let normal = |e: &Atom| -> Atom {
        e.expand()
            .replace(expr("sin(delta_ref)").to_pattern())
            .with(sin_d.to_pattern())
            .replace(expr("cos(delta_ref)").to_pattern())
            .with(cos_d.to_pattern())
            .expand()
    };
    linear::linearise(&formulas, prefix, &reference, &normal)
        .map_err(|e| anyhow!("the Whipple bicycle about a moved reference: {e}"))
}

/// One route's lean and steer matrices, with the checks that they are the benchmark's form;
/// `moved` is the same route linearised about the reference [`MOVED`] describes, the
/// falsification of the checks upright running makes literal zeros.
pub fn lateral(
    lin: &Linear,
    route: &str,
    checks: &mut Vec<Check>,
    moved: Option<&Linear>,
) -> Matrices {
    let s = |e: &Atom| stand_ins(e);
    let all0 = |es: &[&Atom]| es.iter().all(|e| vanishes(&s(e)));
    let show =
        |es: &[&Atom]| es.iter().map(|e| reduce(&s(e)).to_string()).collect::<Vec<_>>().join("; ");
    // A quantity that must vanish run again with its first term scaled ([`crate::falsify`]).
    let vanishing = |es: &[&Atom]| {
        let reduced: Vec<Atom> = es.iter().map(|e| s(e)).collect();
        let refs: Vec<&Atom> = reduced.iter().collect();
        // The others vanish when the check holds: the outcome is the perturbed one's.
        crate::falsify::perturb_first_nonzero(&refs, vanishes)
    };
    // The quantities each check asks to vanish, taken from a linearisation.
    let heights =
        |l: &'_ Linear| -> Vec<Atom> { l.heights0.iter().map(|(_, h)| h.clone()).collect() };
    let pitch = |l: &'_ Linear| -> Vec<Atom> {
        l.dependent.iter().flat_map(|(_, row)| row.iter().cloned()).collect()
    };
    let f0 = |l: &'_ Linear| -> Vec<Atom> { l.f0.clone() };
    // The rear wheel rate (index 2) against lean and steer (0, 1).
    let coupling = |l: &'_ Linear| -> Vec<Atom> {
        [
            &l.m[0][2],
            &l.m[1][2],
            &l.f_u[0][2],
            &l.f_u[1][2],
            &l.f_u[2][0],
            &l.f_u[2][1],
            &l.f_q[2][0],
            &l.f_q[2][1],
        ]
        .into_iter()
        .cloned()
        .collect()
    };
    type Pick<'a> = &'a dyn Fn(&Linear) -> Vec<Atom>;
    let cases: [(&str, String, Pick); 4] = [
        ("on_the_ground", format!("{route}: at the reference (lean, pitch and steer zero) the front contact's height vanishes"), &heights),
        ("pitch_second_order", format!("{route}: the front contact's height has no first-order term in lean and steer, so the pitch's perturbation vanishes at first order"), &pitch),
        ("equilibrium", format!("{route}: upright straight running at any speed is an equilibrium (the forcing of every equation vanishes there)"), &f0),
        ("rear_decoupled", format!("{route}: the rear wheel rate's perturbation decouples from lean and steer at first order (no mass, rate or angle coupling either way)"), &coupling),
    ];
    for (id, statement, pick) in cases {
        let derived = pick(lin);
        let refs: Vec<&Atom> = derived.iter().collect();
        // A quantity that must vanish run again with its first term scaled
        // ([`crate::falsify`]); when upright running has made every one a literal zero, the
        // same quantities about the moved reference.
        let perturbed = vanishing(&refs).or_else(|| {
            moved.map(|m| {
                let at = pick(m);
                let refs: Vec<&Atom> = at.iter().collect();
                let nonzero = refs.iter().filter(|e| !vanishes(&s(e))).count();
                crate::Perturbed {
                    what: format!(
                        "{MOVED}: {nonzero} of the {} quantities are then nonzero (exact)",
                        refs.len()
                    ),
                    holds: nonzero == 0,
                }
            })
        });
        checks.push(with_perturbation(
            check(&format!("{route}_{id}"), &statement, all0(&refs), show(&refs)),
            perturbed,
        ));
    }
    let (v, g) = (var("v"), var("g"));
    let (vs, gs) = (v.get_symbol().expect("symbol"), g.get_symbol().expect("symbol"));
    let mat = |f: &dyn Fn(usize, usize) -> Atom| -> [[Atom; 2]; 2] {
        std::array::from_fn(|r| std::array::from_fn(|c| reduce(&s(&f(r, c)))))
    };
    let m = mat(&|r, c| lin.m[r][c].clone());
    let c1 = mat(&|r, c| (-&lin.f_u[r][c] / &v).expand());
    let k0 = mat(&|r, c| (-&lin.f_q[r][c]).derivative(gs).expand());
    let k2 = mat(&|r, c| {
        let stiff = -&lin.f_q[r][c];
        ((&stiff - &g * stiff.derivative(gs)) / v.pow(Atom::num(2))).expand()
    });
    let free = [&m, &c1, &k0, &k2]
        .iter()
        .all(|x| x.iter().flatten().all(|e| !e.contains_symbol(vs) && !e.contains_symbol(gs)));
    // The derived M11 given a speed dependence (times 1 + v): the structure must then fail.
    let structure_perturbed = crate::Perturbed {
        what: "the derived entry M11 multiplied by 1 + v (a speed-dependent mass)".to_string(),
        holds: !(&m[0][0] * (Atom::num(1) + &v)).contains_symbol(vs),
    };
    checks.push(with_perturbation(check(
        &format!("{route}_structure"),
        &format!("{route}: the lean and steer rows are exactly M q'' + v C1 q' + (g K0 + v^2 K2) q: the rate terms are v times, the angle terms g times plus v^2 times expressions free of v and g"),
        free,
        if free { String::new() } else { "an entry depends on v or g".to_string() },
    ), Some(structure_perturbed)));
    Matrices { m, c1, k0, k2 }
}

fn entries(m: &Matrices) -> Vec<(String, &Atom)> {
    let mut out = Vec::new();
    for (prefix, mat) in [("m", &m.m), ("c1_", &m.c1), ("k0_", &m.k0), ("k2_", &m.k2)] {
        for (r, row) in mat.iter().enumerate() {
            for (c, e) in row.iter().enumerate() {
                out.push((format!("{prefix}{}{}", r + 1, c + 1), e));
            }
        }
    }
    out
}

/// $M$, $C_1$, $K_0$, $K_2$ from the engine (Kane's route), reduced as [`super::reduce`]
/// reduces, with the checks of both routes and of their agreement.
pub fn matrices(checks: &mut Vec<Check>) -> Result<(Matrices, Origins)> {
    matrices_of(&description::whipple(), true, Some(checks))
}

/// [`matrices`] for another description of the bicycle (the same bicycle with other speeds,
/// [`description::whipple_rear_spin_from_lean`]).
/// With `plain`, [`Origins::plain`] is filled. With `checks` `None` the checks are not wanted,
/// and the linearisations about the moved reference ([`MOVED`], their falsifications) are not
/// made.
pub fn matrices_of(
    model: &engine::Model,
    plain: bool,
    checks: Option<&mut Vec<Check>>,
) -> Result<(Matrices, Origins)> {
    let derive = if plain { engine::derivation_with_plain_lagrange } else { engine::derivation };
    let (d, _, _) =
        derive(model, file!()).map_err(|e| anyhow!("the Whipple bicycle ({}): {e}", model.name))?;
    let falsified = checks.is_some();
    let mut unwanted = Vec::new();
    let checks = checks.unwrap_or(&mut unwanted);
    let moved_route = |prefix: &str| falsified.then(|| moved(&d, prefix)).transpose();
    let reference = upright(-var("v") / var("rR"));
    let kane = lateral(&route(&d, "", &reference)?, "kane", checks, moved_route("")?.as_ref());
    let (lin, parts) = origins(&d, &reference)?;
    let lagrange = lateral(&lin, "lagrange", checks, moved_route("L_")?.as_ref());
    let differ = differing(&kane, &lagrange);
    let perturbed = crate::falsify::perturb_one(&kane.m[0][0], |d| {
        let mut k = kane.clone();
        k.m[0][0] = d.clone();
        differing(&k, &lagrange).is_empty()
    });
    checks.push(check_perturbed(
        "kane_equals_lagrange",
        "the linearised Kane equations and Carvallo's linearised modified Lagrange equations (memoir n° 72), both derived by the engine from the one description, give the same M, C1, K0, K2, entry by entry, exactly (symbolic in all 25 parameters)",
        differ.is_empty(),
        if differ.is_empty() { String::new() } else { format!("differ: {}", differ.join(", ")) },
        perturbed,
    ));
    Ok((kane, parts))
}

/// The entries in which two sets of matrices differ (exactly), by name.
pub fn differing(a: &Matrices, b: &Matrices) -> Vec<String> {
    entries(a)
        .into_iter()
        .zip(entries(b))
        .filter(|((_, x), (_, y))| !vanishes(&(*x - *y)))
        .map(|((name, _), _)| name)
        .collect()
}

/// The memoir's n° 98 by the engine: the bicycle with the rider's body moved sideways by the
/// angle ε about the rear frame's ground trace OI ([`description::whipple_shifted`]), derived
/// by Kane's method (the modified Lagrange equations agree with it on the unshifted bicycle,
/// `kane_equals_lagrange`; [`shift_checks_of`] takes either route) and linearised in the lean,
/// the steer, the speeds and ε about upright running.
/// With ε = 0 the matrices are the bicycle's (`unshifted`). The memoir says (n° 98): the gravity
/// moment of the fall equation, $\mu g h\sin\theta$, becomes $\mu g h\sin(\theta + \varepsilon)$
/// — so ε's coefficient in the lean row is $\mu g h = -g\,m_B z_B$, the rear body's (the
/// benchmark's B is the memoir's loaded frame; its height is $-z_B$); the moment of the
/// centrifugal force is not changed appreciably — so that coefficient is free of the speed; and
/// the handlebar equation is not changed — so ε's coefficient in the steer row vanishes. Each
/// is a check; so is the rear wheel's row, untouched.
///
/// Two negative controls follow, recorded as checks that hold when the perturbed description
/// *fails* the corresponding Kane check (so that the report can state what breaks each claim):
/// the body turned about the axis through the rear wheel's centre instead of OI must fail the
/// gravity check; the front frame carried with the shifted body (the whole frame turned, the
/// front assembly with it) must fail the handlebar check; the shift turning the handlebar by ε
/// too must fail the centrifugal check (ε then acts through the speed-dependent steer terms).
pub fn shift_checks(checks: &mut Vec<Check>, unshifted: &Matrices) -> Result<()> {
    shift_checks_of(&description::whipple_shifted(), checks, Some(unshifted), &[("", "kane")])?;
    let mut about_the_axle = description::whipple_shifted();
    if let Some(p) = about_the_axle.points.iter_mut().find(|p| p.name == "CRe") {
        p.frame = "L".into();
    }
    let mut whole_frame = description::whipple_shifted();
    if let Some(p) = whole_frame.points.iter_mut().find(|p| p.name == "A") {
        p.from = "CRe".into();
        p.frame = "E".into();
    }
    // The front frame turned with the body: H from E, declared after it.
    let h = whole_frame.frames.iter().position(|f| f.name == "H").expect("H");
    let mut front = whole_frame.frames.remove(h);
    front.parent = "E".into();
    whole_frame.frames.push(front);
    // CRe before A: the points are declared in order.
    let cre = whole_frame.points.iter().position(|p| p.name == "CRe").expect("CRe");
    let moved = whole_frame.points.remove(cre);
    whole_frame.points.insert(0, moved);
    let mut steered = description::whipple_shifted();
    if let Some(h) = steered.frames.iter_mut().find(|f| f.name == "H") {
        h.rotations.insert(
            2,
            engine::Rotation {
                axis: engine::Axis::Z,
                angle: engine::Angle::Parameter { name: "epsilon".into(), negated: false },
            },
        );
    }
    for (model, name, what, broken) in [
        (&about_the_axle, "axle", "the body turned about the axis through the rear wheel's centre instead of the ground trace OI", &["gravity"][..]),
        (&whole_frame, "whole_frame", "the steering axis and the front frame carried by the shifted body (the whole frame turned by epsilon about OI, the front assembly with it)", &["handlebar"][..]),
        (&steered, "steer", "the shift also turning the handlebar by epsilon about the steering axis", &["centrifugal"][..]),
    ] {
        let mut perturbed = Vec::new();
        shift_checks_of(model, &mut perturbed, None, &[("", "kane")])?;
        for b in broken {
            let id = format!("kane_shift_{b}");
            let fails = perturbed.iter().any(|c| c.id == id && !c.holds);
            let detail = perturbed.iter().find(|c| c.id == id).map_or(String::new(), |c| c.detail.clone());
            // The control is the Kane check's falsification (a model ingredient moved), and
            // the Kane check on the bicycle's own description is the control's.
            let own = checks.iter_mut().find(|c| c.id == id);
            let own_holds = own.as_ref().is_some_and(|c| c.holds);
            if let Some(own) = own {
                own.perturbed = Some(crate::Perturbed {
                    what: format!("the description with {what}"),
                    holds: !fails,
                });
            }
            checks.push(Check {
                perturbed: Some(crate::Perturbed {
                    what: format!("the description as the memoir has it (the body shifted about OI alone): {id} run on it"),
                    holds: !own_holds,
                }),
                section: "98".into(),
                id: format!("shift_{b}_breaks_with_{name}"),
                statement: format!("negative control of {id}: with {what} the check fails"),
                holds: fails,
                detail,
            });
        }
    }
    Ok(())
}

/// The bicycle with the rider's body shifted by ε ([`description::whipple_shifted`]), Kane's
/// route linearised about upright running in the lean, the steer, the speeds and ε (ε's
/// coefficients are the inputs' column of [`Linear::f_t`]).
pub fn shifted() -> Result<Linear> {
    let (d, _, _) = engine::derivation(&description::whipple_shifted(), file!())
        .map_err(|e| anyhow!("the Whipple bicycle with its rider shifted: {e}"))?;
    route(&d, "", &shifted_reference())
}

/// Upright running with the shift ε as a perturbed input (its value 0).
fn shifted_reference() -> Reference {
    let mut reference = upright(-var("v") / var("rR"));
    reference.values.insert("epsilon".into(), Atom::num(0));
    reference.inputs.push("epsilon".into());
    reference
}

/// [`shift_checks`] for another description of the shift (a test moves the axis of the shift).
pub fn shift_checks_of(
    model: &engine::Model,
    checks: &mut Vec<Check>,
    unshifted: Option<&Matrices>,
    routes: &[(&str, &str)],
) -> Result<()> {
    let (d, _, _) = engine::derivation(model, file!())
        .map_err(|e| anyhow!("the Whipple bicycle with its rider shifted: {e}"))?;
    let reference = shifted_reference();
    let vs = var("v").get_symbol().expect("symbol");
    let expected = -var("g") * var("mB") * var("zB");
    for &(prefix, name) in routes {
        let lin = route(&d, prefix, &reference)?;
        let s = |e: &Atom| reduce(&stand_ins(e));
        let (lean, steer, wheel) = (s(&lin.f_t[0][0]), s(&lin.f_t[1][0]), s(&lin.f_t[2][0]));
        if let Some(unshifted) = unshifted {
            let shifted = lateral(&lin, &format!("{name}_shifted"), &mut Vec::new(), None);
            let same = differing(&shifted, unshifted);
            let perturbed = crate::falsify::perturb_one(&shifted.m[0][0], |d| {
                let mut m = shifted.clone();
                m.m[0][0] = d.clone();
                differing(&m, unshifted).is_empty()
            });
            checks.push(Check {
                perturbed: Some(crate::Perturbed { what: format!("{} (the shifted bicycle's M11 at epsilon = 0)", perturbed.what), ..perturbed }),
                section: "98".into(),
                id: format!("{name}_shift_unshifted"),
                statement: format!("{name}: with the body shifted by epsilon = 0 the engine's bicycle has the unshifted matrices M, C1, K0, K2 exactly"),
                holds: same.is_empty(),
                detail: if same.is_empty() { String::new() } else { format!("differ: {}", same.join(", ")) },
            });
        }
        checks.push(Check {
            perturbed: None,
            section: "98".into(),
            id: format!("{name}_shift_gravity"),
            statement: format!("{name}: epsilon's coefficient in the lean row is the loaded frame's gravity moment mu g h = -g mB zB, as mu g h sin(theta) becoming mu g h sin(theta + epsilon) (n° 98) requires at first order"),
            holds: vanishes(&(&lean - &expected)),
            detail: format!("derived: {lean}"),
        });
        checks.push(Check {
            perturbed: None,
            section: "98".into(),
            id: format!("{name}_shift_centrifugal"),
            statement: format!("{name}: epsilon's coefficient in the lean row does not depend on the speed (the centrifugal moment is not changed by the shift at first order, n° 98)"),
            holds: !lean.contains_symbol(vs),
            detail: format!("derived: {lean}"),
        });
        checks.push(Check {
            perturbed: None,
            section: "98".into(),
            id: format!("{name}_shift_handlebar"),
            statement: format!("{name}: epsilon's coefficients in the steer row and in the rear wheel's row vanish (the handlebar equation is not changed by the shift, n° 98)"),
            holds: vanishes(&steer) && vanishes(&wheel),
            detail: format!("steer row: {steer}; rear wheel row: {wheel}"),
        });
    }
    Ok(())
}
