//! Moore's (2012) leaning rider as a description for the mechanics engine
//! ([`crate::mechanics::engine`]): the Carvallo–Whipple bicycle whose rider's upper body G leans
//! on a revolute joint fixed in the rear frame, exactly as BicycleParameters 1.5.2 defines it
//! (`bicycleparameters.models.MooreRiderLean2012Model`; the definition, read from its source and
//! checked against its generated code, is `docs/lean-rider-definition.md`).
//!
//! Moore's names throughout: coordinates `q3` (yaw), `q4` (roll), `q5` (pitch, fixed by the
//! front contact), `q6` (rear wheel), `q7` (steer), `q8` (front wheel), `q9` (the torso's lean);
//! the rear contact's ground position $q_1, q_2$ is the root point P (its velocity components
//! on the yawed axes are `P_u`, `P_v`). Parameters: the 36 of
//! `parameter_dicts.mooreriderlean2012_browser_jason` (`data/mooreriderlean2012/browser_jason.toml`)
//! and `lam`, the constant angle that orients the hinge and the torso's frame, which
//! BicycleParameters sets to the upright pitch ($q_5$ at $q_4 = q_7 = 0$).
//!
//! Frames: the yawed A, the rolled B = A·Rx(q4), the rear frame C = B·Ry(q5), the front frame
//! E = C·Rz(q7) (about the steering axis $c_3$), H = C·Ry(−λ) and the torso G = H·Rx(q9) (the
//! body-fixed 2-1-2 rotation (−λ, q9, 0) from C). Points: the rear wheel centre
//! $D_o = P - r_r b_3$, C's mass centre $D_o + l_1 c_1 + l_2 c_3$, the steering axis point
//! $C_e = D_o + d_1 c_1$, the front wheel centre $F_o = C_e + d_2 c_3 + d_3 e_1$, E's mass centre
//! $F_o + l_3 e_1 + l_4 e_3$, the hinge $C_g = D_o + d_4 h_3$ and G's mass centre
//! $C_g + l_5 g_1 + l_6 g_3$. Torques (the model's inputs): `T4` on C about $a_1$ (reaction on
//! the ground), `T6` on the rear wheel D about its axle $c_2$ (reaction on C), `T7` on E about $c_3$ (reaction on C), and on G about $g_1$ (reaction on C)
//! `T9` plus the lean joint's spring and damper $-(c_9 \dot q_9 + k_9 q_9)$.

use anyhow::{anyhow, Result};
use symbolica::atom::Atom;

use crate::Derivation;

use crate::mechanics::engine::{
    self, coordinate, frame, point, rot, sym, Angle, Axis, Body, Kind, Model, Rotation, Torque,
    Wheel,
};

/// Parameter names, in order: BicycleParameters' 36 (alphabetical, as its `eval_linear` takes
/// them), then `lam`.
pub const PARAMS: [&str; 37] = [
    "c9", "d1", "d2", "d3", "d4", "g", "ic11", "ic22", "ic31", "ic33", "id11", "id22", "ie11",
    "ie22", "ie31", "ie33", "if11", "if22", "ig11", "ig22", "ig31", "ig33", "k9", "l1", "l2", "l3",
    "l4", "l5", "l6", "mc", "md", "me", "mf", "mg", "rf", "rr", "lam",
];

/// The inputs (N m): roll torque on the rear frame, the rear wheel's driving torque (reaction
/// on the rear frame; BicycleParameters' state space drops it), steer torque, lean torque on
/// the torso.
pub const INPUTS: [&str; 4] = ["T4", "T6", "T7", "T9"];

fn zero() -> Atom {
    Atom::num(0)
}

/// A body's inertia in Moore's notation: `i<name>11`, `22`, `33` and the tensor element `31`
/// (Autolev's `inertia c, ic11, ic22, ic33, 0, 0, ic31`).
fn inertia(name: &str) -> [[Atom; 3]; 3] {
    let i = |s: &str| sym(&format!("i{name}{s}"));
    [[i("11"), zero(), i("31")], [zero(), i("22"), zero()], [i("31"), zero(), i("33")]]
}

fn body(name: &str, frame: &str, centre: &str) -> Body {
    let lower = name.to_lowercase();
    Body {
        name: name.into(),
        frame: frame.into(),
        centre: centre.into(),
        mass: sym(&format!("m{lower}")),
        inertia: inertia(&lower),
    }
}

fn torque(name: &str, value: Atom, from: &str, to: &str, axis: Axis) -> Torque {
    Torque { name: name.into(), value, from: from.into(), to: to.into(), axis }
}

/// The leaning rider's description.
pub fn lean_rider() -> Model {
    let rr = sym("rr");
    Model {
        name: "lean_rider".into(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: INPUTS.iter().map(|s| s.to_string()).collect(),
        coordinates: vec![
            coordinate("q3", "yaw (rad)", Kind::Ignorable { dependent_rate: true }),
            coordinate("q4", "roll of the rear frame (rad)", Kind::Independent),
            coordinate("q5", "pitch of the rear frame (rad)", Kind::Dependent),
            coordinate(
                "q6",
                "rear wheel rotation relative to C (rad)",
                Kind::Ignorable { dependent_rate: false },
            ),
            coordinate("q7", "steer (rad)", Kind::Independent),
            coordinate(
                "q8",
                "front wheel rotation relative to E (rad)",
                Kind::Ignorable { dependent_rate: true },
            ),
            coordinate(
                "q9",
                "lean of the rider's upper body relative to C (rad)",
                Kind::Independent,
            ),
        ],
        heading: Some("q3".into()),
        root: "P".into(),
        frames: vec![
            frame("A", "N", vec![rot(Axis::Z, "q3")]),
            frame("B", "A", vec![rot(Axis::X, "q4")]),
            frame("C", "B", vec![rot(Axis::Y, "q5")]),
            frame("E", "C", vec![rot(Axis::Z, "q7")]),
            frame(
                "H",
                "C",
                vec![Rotation {
                    axis: Axis::Y,
                    angle: Angle::Parameter { name: "lam".into(), negated: true },
                }],
            ),
            frame("G", "H", vec![rot(Axis::X, "q9")]),
        ],
        points: vec![
            point("Do", "P", "B", [zero(), zero(), -&rr]),
            point("Co", "Do", "C", [sym("l1"), zero(), sym("l2")]),
            point("Ce", "Do", "C", [sym("d1"), zero(), zero()]),
            point("Cs", "Ce", "C", [zero(), zero(), sym("d2")]),
            point("Fo", "Cs", "E", [sym("d3"), zero(), zero()]),
            point("Eo", "Fo", "E", [sym("l3"), zero(), sym("l4")]),
            point("Cg", "Do", "H", [zero(), zero(), sym("d4")]),
            point("Go", "Cg", "G", [sym("l5"), zero(), sym("l6")]),
        ],
        bodies: vec![body("C", "C", "Co"), body("E", "E", "Eo"), body("G", "G", "Go")],
        wheels: vec![
            Wheel {
                name: "D".into(),
                carrier: "C".into(),
                centre: "Do".into(),
                axle: Axis::Y,
                spin: "q6".into(),
                radius: rr.clone(),
                mass: sym("md"),
                diametral: sym("id11"),
                axial: sym("id22"),
                down: Some(("B".into(), Axis::Z)),
                at_root: true,
            },
            Wheel {
                name: "F".into(),
                carrier: "E".into(),
                centre: "Fo".into(),
                axle: Axis::Y,
                spin: "q8".into(),
                radius: sym("rf"),
                mass: sym("mf"),
                diametral: sym("if11"),
                axial: sym("if22"),
                down: None,
                at_root: false,
            },
        ],
        torques: vec![
            torque("T4", sym("T4"), "N", "B", Axis::X),
            torque("T6", sym("T6"), "C", "D", Axis::Y),
            torque("T7", sym("T7"), "C", "E", Axis::Z),
            torque(
                "T9",
                sym("T9") - sym("c9") * sym("q9d") - sym("k9") * sym("q9"),
                "C",
                "G",
                Axis::X,
            ),
        ],
        gravity: sym("g"),
    }
}

/// The leaning rider's derivation for `generated/lean_rider.*`: Kane's equations from the
/// engine (the mass matrix `M_<ui>_<uj>` and forcing `f_<ui>` of the independent speeds `q4d`,
/// `q6d`, `q7d`, `q9d`, the dependent speeds `P_u`, `P_v`, `q3d`, `q5d`, `q8d`, the front
/// contact's height and its pitch derivative for Newton's method, the energy). Carvallo's
/// modified Lagrange equations are derived too; the generated program keeps Kane's alone, and
/// `codegen/tests/derive/lean_rider.rs` checks the two routes against each other at 256 bits
/// (this layer may not emit a program to evaluate them).
pub fn derive() -> Result<Derivation> {
    let model = lean_rider();
    let d =
        engine::kane_derivation(&model, file!()).map_err(|e| anyhow!("the leaning rider: {e}"))?;
    Ok(Derivation { nominal: crate::derive::nominal::values("lean_rider"), ..d })
}
