//! A rolling system that is not a bicycle, from description to generated code: the two-wheeled
//! inverted pendulum (a self-balancing robot or personal transporter), the guide's worked
//! example of adding a model with the mechanics engine (`docs/guide/src/contributing.md`).
//!
//! Two equal wheels (radius $r$, mass $m_W$, moments $I_{Wd}$ about a diameter and $I_{Wa}$
//! about the axle) on one axle of length $W$ between the wheel centres carry a body (mass
//! $m_B$, centre at $l$ above the axle's midpoint, principal moments $I_{Bxx}$, $I_{Byy}$,
//! $I_{Bzz}$) that pitches about the axle; a motor in each hub applies the torque $T_L$ or $T_R$
//! to its wheel about the axle, the reaction on the body. Benchmark axes: x forward, y right,
//! z down.
//!
//! Frames: the yawed frame Y (heading ψ), the lean frame L = Y·Rx(φ) and the body B = L·Ry(θ).
//! Points: the left wheel's centre $C_L = P - r L_z$ from the left contact P (the root point),
//! the axle's midpoint $A = C_L + (W/2) L_y$, the body's centre $G = A - l B_z$ and the right
//! wheel's centre $C_R = C_L + W L_y$. Both wheels are carried by the body (their spins
//! θ_L, θ_R are relative to it, so each motor torque acts between the body and its wheel).
//!
//! The lean φ is a dependent coordinate: the right wheel's contact height fixes it (at zero on
//! flat ground). Of the five rows of the rolling constraints beyond the left contact's
//! vanishing vertical row, one is implied by the others: both contacts' lateral velocities are
//! the axle's, which a rigid axle makes equal. The engine finds that row at a seeded point and
//! names it (`R lateral`), as a check of the derivation; the other four give the contact's
//! velocity, the lean rate and the heading rate, and the independent speeds are the pitch rate
//! and the two wheels' rates.
//!
//! Outputs: Kane's program (`M_<ui>_<uj>`, `f_<ui>`, the dependent rates, the contact height
//! and its derivative in the lean for Newton's method, the energy) and its linearisation about
//! upright straight running at speed $v$ (the body upright, both wheels turning at $-v/r$):
//! `lin_M_<ui>_<uj>`, `lin_fq_<ui>` (the forcing's derivative in the pitch),
//! `lin_fu_<ui>_<uj>` and `lin_fT_<ui>_<T>` (in the speeds and the motor torques). The same
//! linearisation of Carvallo's modified Lagrange equations must agree with Kane's exactly, and
//! the pitch equation's closed form (a planar Lagrangian written by hand in
//! `codegen/tests/derive/wheeled_pendulum.rs`) checks both.

use std::collections::BTreeMap;

use anyhow::{anyhow, ensure, Result};
use symbolica::atom::{Atom, AtomCore};

use crate::cas::{is_zero, simplify, var};
use crate::mechanics::engine::linear::{self, Linear, Reference};
use crate::mechanics::engine::{
    self, coordinate, frame, point, rot, sym, Axis, Body, Kind, Model, Torque, Wheel,
};
use crate::{Check, Derivation, Formula};

/// Parameter names, in order.
pub const PARAMS: [&str; 11] =
    ["r", "W", "mW", "IWd", "IWa", "l", "mB", "IBxx", "IByy", "IBzz", "g"];

/// The inputs beyond the state: the motor torques on the left and right wheels (N m).
pub const INPUTS: [&str; 2] = ["TL", "TR"];

/// The independent speeds: the body's pitch rate and the wheels' rates relative to the body.
pub const INDEPENDENT: [&str; 3] = ["thetad", "thetaLd", "thetaRd"];

fn wheel(name: &str, centre: &str, spin: &str, at_root: bool) -> Wheel {
    Wheel {
        name: name.into(),
        carrier: "B".into(),
        centre: centre.into(),
        axle: Axis::Y,
        spin: spin.into(),
        radius: sym("r"),
        mass: sym("mW"),
        diametral: sym("IWd"),
        axial: sym("IWa"),
        down: Some(("L".into(), Axis::Z)),
        at_root,
    }
}

fn motor(name: &str, wheel: &str) -> Torque {
    Torque {
        name: name.into(),
        value: sym(name),
        from: "B".into(),
        to: wheel.into(),
        axis: Axis::Y,
    }
}

/// The two-wheeled inverted pendulum's description.
pub fn wheeled_pendulum() -> Model {
    let zero = || Atom::num(0);
    let (r, w) = (sym("r"), sym("W"));
    Model {
        name: "wheeled_pendulum".into(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: INPUTS.iter().map(|s| s.to_string()).collect(),
        coordinates: vec![
            coordinate("psi", "heading (rad)", Kind::Ignorable { dependent_rate: true }),
            coordinate("phi", "lean of the axle (rad), zero on flat ground", Kind::Dependent),
            coordinate("theta", "pitch of the body from upright (rad)", Kind::Independent),
            coordinate(
                "thetaL",
                "left wheel's rotation relative to the body (rad)",
                Kind::Ignorable { dependent_rate: false },
            ),
            coordinate(
                "thetaR",
                "right wheel's rotation relative to the body (rad)",
                Kind::Ignorable { dependent_rate: false },
            ),
        ],
        heading: Some("psi".into()),
        root: "P".into(),
        frames: vec![
            frame("Y", "N", vec![rot(Axis::Z, "psi")]),
            frame("L", "Y", vec![rot(Axis::X, "phi")]),
            frame("B", "L", vec![rot(Axis::Y, "theta")]),
        ],
        points: vec![
            point("CL", "P", "L", [zero(), zero(), -&r]),
            point("A", "CL", "L", [zero(), &w / Atom::num(2), zero()]),
            point("G", "A", "B", [zero(), zero(), -sym("l")]),
            point("CR", "CL", "L", [zero(), w.clone(), zero()]),
        ],
        bodies: vec![Body {
            name: "B".into(),
            frame: "B".into(),
            centre: "G".into(),
            mass: sym("mB"),
            inertia: [
                [sym("IBxx"), zero(), zero()],
                [zero(), sym("IByy"), zero()],
                [zero(), zero(), sym("IBzz")],
            ],
        }],
        wheels: vec![wheel("L", "CL", "thetaL", true), wheel("R", "CR", "thetaR", false)],
        torques: vec![motor("TL", "L"), motor("TR", "R")],
        gravity: sym("g"),
    }
}

/// The reference motion: upright straight running, both wheels turning at `wheel_rate`
/// ($-v/r$ for the speed $v$), the torques zero; the pitch perturbed, the lean solved from the
/// right contact's height.
pub fn upright(wheel_rate: Atom) -> Reference {
    let strings = |xs: &[&str]| xs.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let mut values: BTreeMap<String, Atom> =
        ["phi", "theta", "thetad"].iter().map(|s| (s.to_string(), Atom::num(0))).collect();
    values.insert("thetaLd".into(), wheel_rate.clone());
    values.insert("thetaRd".into(), wheel_rate);
    for t in INPUTS {
        values.insert(t.into(), Atom::num(0));
    }
    Reference {
        values,
        coordinates: strings(&["theta"]),
        dependent: strings(&["phi"]),
        speeds: strings(&INDEPENDENT),
        heights: strings(&["R_contact_height"]),
        inputs: strings(&INPUTS),
    }
}

/// One route's linearisation (`""` Kane's, `"L_"` the modified Lagrange equations) of the
/// derivation `d` about `reference`.
pub fn route(d: &Derivation, prefix: &str, reference: &Reference) -> Result<Linear> {
    linear::linearise(&d.formulas, prefix, reference, &|e: &Atom| e.expand())
        .map_err(|e| anyhow!("the wheeled pendulum: {e}"))
}

/// The linearisation's entries by output name, simplified: `lin_M_*`, `lin_fq_*`, `lin_fu_*`,
/// `lin_fT_*`.
pub fn entries(lin: &Linear) -> Vec<(String, Atom)> {
    let mut out = Vec::new();
    let u = &lin.speeds;
    for i in 0..u.len() {
        for j in i..u.len() {
            out.push((format!("lin_M_{}_{}", u[i], u[j]), simplify(&lin.m[i][j])));
        }
    }
    for (i, ui) in u.iter().enumerate() {
        for (c, q) in lin.coordinates.iter().enumerate() {
            let name = if lin.coordinates.len() == 1 {
                format!("lin_fq_{ui}")
            } else {
                format!("lin_fq_{ui}_{q}")
            };
            out.push((name, simplify(&lin.f_q[i][c])));
        }
        for (j, uj) in u.iter().enumerate() {
            out.push((format!("lin_fu_{ui}_{uj}"), simplify(&lin.f_u[i][j])));
        }
        for (k, t) in lin.inputs.iter().enumerate() {
            out.push((format!("lin_fT_{ui}_{t}"), simplify(&lin.f_t[i][k])));
        }
    }
    out
}

fn check(id: &str, statement: &str, holds: bool, detail: String) -> Check {
    Check {
        section: "engine".into(),
        id: id.into(),
        statement: statement.into(),
        holds,
        detail,
        perturbed: None,
    }
}

/// Derives the model's formulas and checks.
pub fn derive() -> Result<Derivation> {
    let model = wheeled_pendulum();
    let (d, kane_len, redundant) =
        engine::derivation(&model, file!()).map_err(|e| anyhow!("the wheeled pendulum: {e}"))?;
    // The derived list of redundant rows without its first row: the check must then fail.
    let named = |rows: &[String]| {
        rows.len() == 2
            && rows.iter().any(|r| r.starts_with("R lateral"))
            && rows.iter().any(|r| r.starts_with("L vertical"))
    };
    let rows_perturbed = redundant.first().map(|first| crate::Perturbed {
        what: format!("the derived list of redundant rows without its first row ({first})"),
        holds: named(&redundant[1..]),
    });
    let mut checks = vec![crate::falsify::with_perturbation(check(
        "redundant_rows",
        "of the rolling constraints, the left contact's vertical row vanishes (the root point is on the ground) and the right contact's lateral row is implied by the others (one rigid axle: both contacts move sideways with it), so both are dropped and named",
        named(&redundant),
        redundant.join("; "),
    ), rows_perturbed)];
    let reference = upright(-var("v") / var("r"));
    let kane = route(&d, "", &reference)?;
    let lagrange = route(&d, "L_", &reference)?;
    let zeros = |xs: &[Atom]| xs.iter().all(is_zero);
    let at_rest: Vec<Atom> =
        kane.f0.iter().chain(kane.heights0.iter().map(|(_, h)| h)).cloned().collect();
    let refs: Vec<&Atom> = at_rest.iter().collect();
    let rest_perturbed = crate::falsify::perturb_first_nonzero(&refs, is_zero);
    checks.push(crate::falsify::with_perturbation(check(
        "upright_equilibrium",
        "upright straight running at any speed with the motors off is an equilibrium: every forcing and the right contact's height vanish there",
        zeros(&at_rest),
        format!("{at_rest:?}"),
    ), rest_perturbed));
    let dphi: Vec<Atom> = kane.dependent.iter().flat_map(|(_, r)| r.clone()).collect();
    let refs: Vec<&Atom> = dphi.iter().collect();
    let dphi_perturbed = crate::falsify::perturb_first_nonzero(&refs, is_zero);
    checks.push(crate::falsify::with_perturbation(
        check(
            "lean_stays_zero",
            "the right contact's height has no first-order term in the pitch: the axle stays level",
            zeros(&dphi),
            format!("{dphi:?}"),
        ),
        dphi_perturbed,
    ));
    let ek = entries(&kane);
    let el = entries(&lagrange);
    let differ: Vec<&str> = ek
        .iter()
        .zip(&el)
        .filter(|((_, a), (_, b))| !is_zero(&(a - b)))
        .map(|((n, _), _)| n.as_str())
        .collect();
    // Kane's first entry, perturbed: the two routes must then differ.
    let kane_perturbed = crate::falsify::perturb_one(&ek[0].1, |d| is_zero(&(d - &el[0].1)));
    checks.push(crate::falsify::with_perturbation(check(
        "kane_equals_lagrange",
        "the linearised Kane equations and Carvallo's linearised modified Lagrange equations (memoir n° 72), derived by the engine from the one description, are equal entry by entry, exactly (symbolic in every parameter and v)",
        differ.is_empty(),
        differ.join(", "),
    ), Some(kane_perturbed)));
    ensure!(
        checks.iter().all(|c| c.holds),
        "wheeled pendulum checks failed: {:?}",
        checks.iter().filter(|c| !c.holds).map(|c| (&c.id, &c.detail)).collect::<Vec<_>>()
    );
    let mut formulas: Vec<Formula> = d.formulas[..kane_len].to_vec();
    let section = formulas.last().map(|f| f.section.clone()).unwrap_or_default();
    for (name, expr) in ek {
        formulas.push(Formula {
            description: format!(
                "{name}: the equations M u' = f linearised about upright straight running at speed v (M at the reference; derivatives of f in the pitch, the speeds and the torques)"
            ),
            name,
            section: section.clone(),
            expr,
        });
    }
    let mut inputs = d.inputs.clone();
    inputs.push("v".into());
    Ok(Derivation {
        model: "wheeled_pendulum".into(),
        source: file!().into(),
        params: d.params,
        inputs,
        formulas,
        checks,
        nominal: crate::derive::nominal::values("wheeled_pendulum"),
        horner_schemes: Vec::new(),
    })
}
