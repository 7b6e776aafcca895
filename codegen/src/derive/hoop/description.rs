//! The rolling hoop as a description for the mechanics engine ([`crate::mechanics::engine`]):
//! the memoir's hoop (n° 1–7: a homogeneous circle of radius $R$ and mass $\mu$ rolling without
//! slipping on a horizontal plane) written as frames and one wheel, with nothing of the memoir's
//! own derivation in it: no trihedron (I, j, k), no $p, n, s$, no moments of the inertia forces.
//! The engine derives it by Kane's method and by the modified Lagrange equations; the hoop's
//! derivation ([`super::derive`]) solves both in closed form ([`accelerations`]), checks them
//! exactly against the memoir's routes (n° 7 and n° 73) and generates the model from Kane's,
//! and the test `codegen/tests/derive/engine_hoop.rs` compares the engine's own program with
//! `generated/hoop.ir` at 256 bits. It is also the guide's worked example of a model that is
//! not a bicycle (`docs/guide/src/contributing.md`).
//!
//! Frames: the yawed frame Y (heading ψ about the downward vertical) and the lean frame
//! L = Y·Rx(φ), which carries the hoop's axle (its y axis). The hoop's centre (the memoir's S) is
//! $S = P - R\,L_z$ from the contact P, which is the root point: the contact is on the ground by
//! construction, so the only constraints are the two horizontal rolling rows. The heading's and
//! the spin's rates are independent speeds (a rolling disc has three degrees of freedom of
//! velocity), the contact's velocity is dependent.

use symbolica::atom::Atom;

use super::PARAMS;
use crate::mechanics::engine::{coordinate, frame, point, rot, sym, Axis, Kind, Model, Wheel};

/// The rolling hoop's description.
pub fn hoop() -> Model {
    let (r, mu) = (sym("R"), sym("mu"));
    Model {
        name: "hoop_engine".into(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: Vec::new(),
        coordinates: vec![
            coordinate("psi", "heading (rad)", Kind::Ignorable { dependent_rate: false }),
            coordinate(
                "phi",
                "lean of the hoop's plane from the vertical (rad)",
                Kind::Independent,
            ),
            coordinate(
                "thetaR",
                "rotation of the hoop about its axle, relative to L (rad)",
                Kind::Ignorable { dependent_rate: false },
            ),
        ],
        heading: Some("psi".into()),
        root: "P".into(),
        frames: vec![
            frame("Y", "N", vec![rot(Axis::Z, "psi")]),
            frame("L", "Y", vec![rot(Axis::X, "phi")]),
        ],
        points: vec![point("S", "P", "L", [Atom::num(0), Atom::num(0), -&r])],
        bodies: Vec::new(),
        wheels: vec![Wheel {
            name: "R".into(),
            carrier: "L".into(),
            centre: "S".into(),
            axle: Axis::Y,
            spin: "thetaR".into(),
            radius: r.clone(),
            mass: mu.clone(),
            // A homogeneous circle: mu R^2 / 2 about a diameter, mu R^2 about the axle.
            diametral: &mu * &r * &r / Atom::num(2),
            axial: &mu * &r * &r,
            down: Some(("L".into(), Axis::Z)),
            at_root: true,
        }],
        torques: Vec::new(),
        gravity: sym("g"),
    }
}

/// The accelerations $\dot p, \dot n, \dot s$ of a description built on the hoop's (the hoop,
/// the unicycle), by Kane's method and by the modified Lagrange equations (in that order), and
/// its energy, written in the memoir's variables: the engine's lean φ is σ₁θ and its rates
/// $\dot\varphi, \dot\psi, \dot\theta_R$ are σ₁p, σ₂n, σ₃s, with the signs `sigma` the engine
/// tests found (`engine_hoop`, `engine_unicycle`: the heading is about the downward vertical and
/// n about the upward one). Expressions in the stand-ins $\sin\theta, \cos\theta$, simplified.
pub fn accelerations(model: &Model, sigma: [i64; 3]) -> anyhow::Result<([Vec<Atom>; 2], Atom)> {
    use crate::cas::{cos_t, expr, simplify, sin_t, solve_linear, var};
    use symbolica::atom::AtomCore;
    let c = crate::mechanics::engine::closed_form(model)
        .map_err(|e| anyhow::anyhow!("the description {}: {e}", model.name))?;
    let sign = |k: usize| Atom::num(sigma[k]);
    let memoir = |e: &Atom| {
        let mut e = e
            .replace(expr("sin(phi)").to_pattern())
            .with((sign(0) * sin_t()).to_pattern())
            .replace(expr("cos(phi)").to_pattern())
            .with(cos_t().to_pattern());
        for (engine, ours, k) in [("phid", "p", 0), ("psid", "n", 1), ("thetaRd", "s", 2)] {
            e = e.replace(var(engine).to_pattern()).with((sign(k) * var(ours)).to_pattern());
        }
        e
    };
    let rate = |speed: &str| match speed {
        "phid" => Ok(sign(0) * var("dp")),
        "psid" => Ok(sign(1) * var("dn")),
        "thetaRd" => Ok(sign(2) * var("ds")),
        other => Err(anyhow::anyhow!("{} has the unexpected speed {other}", model.name)),
    };
    let rates: Vec<Atom> = c.speeds.iter().map(|s| rate(s)).collect::<anyhow::Result<_>>()?;
    let solve = |(mass, forcing): &(Vec<Vec<Atom>>, Vec<Atom>)| {
        let eqs: Vec<Atom> = mass
            .iter()
            .zip(forcing)
            .map(|(row, f)| {
                let lhs =
                    row.iter().zip(&rates).fold(Atom::num(0), |acc, (m, r)| acc + memoir(m) * r);
                lhs - memoir(f)
            })
            .collect();
        solve_linear(&eqs, &["dp", "dn", "ds"])
    };
    Ok(([solve(&c.kane), solve(&c.lagrange)], simplify(&memoir(&c.energy))))
}
