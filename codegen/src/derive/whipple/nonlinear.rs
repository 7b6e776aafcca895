//! The nonlinear equations of motion of the Carvallo–Whipple bicycle for
//! `generated/whipple_nonlinear.*`, derived by the mechanics engine
//! ([`crate::mechanics::engine`]) from the bicycle's description ([`super::description`]): rear
//! wheel R, rear frame with rider B, front frame H, front wheel F, knife-edge wheels rolling
//! without slipping on flat ground, the 2007 benchmark's 25 parameters and the steer axis tilt
//! kept as symbols (benchmark axes: x forward, y right, z down; the yawed frame is the
//! engine's working frame).
//!
//! The program is Kane's part of the engine's derivation: every named quantity, the dependent
//! speeds `thetad`, `psid`, `thetaFd` (and the rear contact's velocity `P_u`, `P_v` along and
//! across the heading), the front contact's height and its pitch derivative for Newton's
//! method, the mass matrix `M_<ui>_<uj>` and forcing `f_<ui>` of $M\dot u = f$ in the
//! independent speeds $u = (\dot\varphi, \dot\delta, \dot\theta_R)$, each body's partial
//! velocities and acceleration at zero independent accelerations, the front contact's
//! position and the energy. The runtime (`crates/carvallo/src/whipple/nonlinear.rs`) reads them
//! by the names it has always used, defined here as the engine's quantities ([`runtime_names`]):
//! `m3_ij`, `f3_i`, the dependent rates' coefficients `a_<dep>_<ind>` and velocity parts
//! `<dep>dd0`, the pivots `b1_thetad`, `b2_psid`, `b3_thetaFd`, the contact height, the rear
//! wheel centre's acceleration `acc0_R`, the rear contact's speed and the front contact.
//!
//! Until this model was a description, it was a derivation written by hand (1,010 lines of
//! vector algebra). Its program is frozen as `codegen/tests/fixtures/whipple_nonlinear_hand.ir`,
//! and `codegen/tests/derive/engine.rs` checks that every output this program shares with it
//! agrees at 256 bits at seeded states and designs (Basu-Mandal et al.'s Table 1 and the
//! BicycleParameters sets are checked by the runtime's tests as before). Carvallo's modified
//! Lagrange equations are derived from the same description and checked against Kane's there;
//! the generated program keeps Kane's alone.

use anyhow::{anyhow, Result};
use symbolica::atom::Atom;

use super::description;
use crate::cas::var;
use crate::mechanics::engine;
use crate::{Derivation, Formula};

/// The parameters, in order: the 2007 benchmark's 25 and the steer axis tilt.
pub const PARAMS: [&str; 26] = crate::derive::whipple::PARAMS;

/// The inputs, in order: the lean, the pitch, the steer and the three independent speeds.
pub const INPUTS: [&str; 6] = ["phi", "theta", "delta", "phid", "deltad", "thetaRd"];

/// The independent speeds: lean rate, steer rate, rear wheel rate (relative to the rear frame).
pub const INDEPENDENT: [&str; 3] = ["phid", "deltad", "thetaRd"];

/// The dependent speeds the front contact's rows give: pitch, yaw and front wheel rates.
pub const DEPENDENT: [&str; 3] = ["thetad", "psid", "thetaFd"];

/// The runtime's names and the engine's quantities they stand for (beyond the names they
/// share: the dependent rates, the rear wheel's partial velocities `vt_R_<u>_<c>`, `energy`).
pub fn runtime_names() -> Vec<(String, String, String)> {
    let mut out = Vec::new();
    let mut alias = |name: String, engine: String, what: String| out.push((name, engine, what));
    for (i, ui) in INDEPENDENT.iter().enumerate() {
        for (j, uj) in INDEPENDENT.iter().enumerate().skip(i) {
            alias(
                format!("m3_{}{}", i + 1, j + 1),
                format!("M_{ui}_{uj}"),
                format!("mass matrix entry ({ui}, {uj}) of M3 u' = f3"),
            );
        }
    }
    for (i, u) in INDEPENDENT.iter().enumerate() {
        alias(format!("f3_{}", i + 1), format!("f_{u}"), format!("forcing of the {u} equation"));
    }
    for dep in DEPENDENT {
        for ind in INDEPENDENT {
            alias(
                format!("a_{dep}_{ind}"),
                format!("A_{dep}_{ind}"),
                format!("d {dep} / d {ind}, from the front contact's rows"),
            );
        }
        alias(
            format!("{dep}d0"),
            format!("w_{dep}"),
            format!("{dep}'s rate of change when the independent accelerations vanish"),
        );
    }
    for (name, engine, what) in [
        ("b1_thetad", "b_F_vertical_thetad", "the pitch rate's pivot (front contact's vertical row)"),
        ("b2_psid", "b_F_lateral_psid", "the yaw rate's pivot (row along the front axle's horizontal projection)"),
        ("b3_thetaFd", "b_F_longitudinal_thetaFd", "the front wheel rate's pivot (row across it)"),
        ("contact_height", "F_contact_height", "the front contact's height, down positive: the holonomic constraint (m)"),
        ("contact_height_dtheta", "F_contact_height_dtheta", "d contact_height / d theta, Newton's step for the pitch"),
        ("rear_speed", "P_u", "speed of the rear contact point along the heading (m/s)"),
        ("acc0_R_x", "a0_R_x", "rear wheel centre's acceleration at zero independent accelerations, forward (yawed frame, m/s^2)"),
        ("acc0_R_y", "a0_R_y", "rear wheel centre's acceleration at zero independent accelerations, right (yawed frame, m/s^2)"),
        ("acc0_R_z", "a0_R_z", "rear wheel centre's acceleration at zero independent accelerations, down (yawed frame, m/s^2)"),
        ("front_contact_x", "F_contact_x", "front contact point relative to the rear contact, along the heading (yawed frame, m)"),
        ("front_contact_y", "F_contact_y", "front contact point relative to the rear contact, to the right of the heading (yawed frame, m)"),
    ] {
        alias(name.into(), engine.into(), what.into());
    }
    out
}

/// The engine's quantities that vanish identically, so that it names none: the front contact's
/// vertical row has no rear wheel rate (the pitch rate is a form in the lean and steer rates).
const ZERO: [&str; 1] = ["A_thetad_thetaRd"];

/// Derives the model's formulas and checks.
pub fn derive() -> Result<Derivation> {
    let model = description::whipple();
    let d = engine::kane_derivation(&model, file!())
        .map_err(|e| anyhow!("the Whipple bicycle: {e}"))?;
    let mut formulas = d.formulas;
    let section = formulas.last().map(|f| f.section.clone()).unwrap_or_default();
    for (name, engine_name, what) in runtime_names() {
        let (expr, description) = if formulas.iter().any(|f| f.name == engine_name) {
            (var(&engine_name), format!("{what}: the engine's {engine_name}"))
        } else if ZERO.contains(&engine_name.as_str()) {
            (Atom::num(0), format!("{what}: zero (the engine names no {engine_name})"))
        } else {
            return Err(anyhow!(
                "the engine's Whipple bicycle has no output {engine_name} (for {name})"
            ));
        };
        formulas.push(Formula { name, section: section.clone(), description, expr });
    }
    Ok(Derivation {
        model: "whipple_nonlinear".into(),
        formulas,
        nominal: crate::derive::nominal::values("whipple_nonlinear"),
        // Every simulation step evaluates its M3 and f3: 100 Horner schemes take them from
        // 1,512 operations (the two usual efforts) to 1,459, within issue 34's budget of 1,490.
        horner_schemes: vec![100],
        ..d
    })
}
