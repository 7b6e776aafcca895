//! The Carvallo–Whipple bicycle as a description for the mechanics engine
//! ([`crate::mechanics::engine`]): the same bicycle as the hand derivation of
//! [`super::nonlinear`] (rear wheel R, rear frame with rider B, front frame H, front wheel F,
//! knife-edge wheels on flat ground, the 2007 benchmark's 25 parameters), in about sixty lines.
//!
//! Frames: the yawed frame Y (heading ψ), the lean frame L = Y·Rx(φ), the rear frame
//! B = L·Ry(θ) and the front frame H = B·Ry(λ)·Rz(δ)·Ry(−λ). Points from the rear contact P:
//! the rear wheel centre $C_R = P - r_R\,L_z$, B's mass centre $C_R + B(x_B, 0, z_B + r_R)$, the
//! steering axis' ground point $A = C_R + B(w + c, 0, r_R)$, H's mass centre
//! $A + H(x_H - w - c, 0, z_H)$ and the front wheel centre $C_F = A + H(-c, 0, -r_F)$.

use symbolica::atom::Atom;

use super::PARAMS;
use crate::mechanics::engine::{
    coordinate, frame, point, rot, sym, Angle, Axis, Body, Kind, Model, Rotation, Wheel,
};

fn tilt(axis: Axis, negated: bool) -> Rotation {
    Rotation { axis, angle: Angle::Parameter { name: "lambda".into(), negated } }
}

fn zero() -> Atom {
    Atom::num(0)
}

/// A frame's inertia with the benchmark's x–z product: `I<name>xx`, `yy`, `zz`, `xz`.
fn frame_inertia(name: &str) -> [[Atom; 3]; 3] {
    let i = |s: &str| sym(&format!("I{name}{s}"));
    [[i("xx"), zero(), i("xz")], [zero(), i("yy"), zero()], [i("xz"), zero(), i("zz")]]
}

/// The Carvallo–Whipple bicycle's description.
pub fn whipple() -> Model {
    let (w, c, rr, rf) = (sym("w"), sym("c"), sym("rR"), sym("rF"));
    Model {
        name: "whipple_engine".into(),
        params: PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: Vec::new(),
        coordinates: vec![
            coordinate("psi", "heading (rad)", Kind::Ignorable { dependent_rate: true }),
            coordinate("phi", "lean of the rear frame (rad)", Kind::Independent),
            coordinate("theta", "pitch of the rear frame (rad)", Kind::Dependent),
            coordinate("delta", "steer (rad)", Kind::Independent),
            coordinate(
                "thetaR",
                "rear wheel rotation relative to B (rad)",
                Kind::Ignorable { dependent_rate: false },
            ),
            coordinate(
                "thetaF",
                "front wheel rotation relative to H (rad)",
                Kind::Ignorable { dependent_rate: true },
            ),
        ],
        heading: Some("psi".into()),
        root: "P".into(),
        frames: vec![
            frame("Y", "N", vec![rot(Axis::Z, "psi")]),
            frame("L", "Y", vec![rot(Axis::X, "phi")]),
            frame("B", "L", vec![rot(Axis::Y, "theta")]),
            frame("H", "B", vec![tilt(Axis::Y, false), rot(Axis::Z, "delta"), tilt(Axis::Y, true)]),
        ],
        points: vec![
            point("CR", "P", "L", [zero(), zero(), -&rr]),
            point("GB", "CR", "B", [sym("xB"), zero(), sym("zB") + &rr]),
            point("A", "CR", "B", [&w + &c, zero(), rr.clone()]),
            point("GH", "A", "H", [sym("xH") - &w - &c, zero(), sym("zH")]),
            point("CF", "A", "H", [-&c, zero(), -&rf]),
        ],
        bodies: vec![
            Body {
                name: "B".into(),
                frame: "B".into(),
                centre: "GB".into(),
                mass: sym("mB"),
                inertia: frame_inertia("B"),
            },
            Body {
                name: "H".into(),
                frame: "H".into(),
                centre: "GH".into(),
                mass: sym("mH"),
                inertia: frame_inertia("H"),
            },
        ],
        wheels: vec![
            Wheel {
                name: "R".into(),
                carrier: "B".into(),
                centre: "CR".into(),
                axle: Axis::Y,
                spin: "thetaR".into(),
                radius: rr.clone(),
                mass: sym("mR"),
                diametral: sym("IRxx"),
                axial: sym("IRyy"),
                down: Some(("L".into(), Axis::Z)),
                at_root: true,
            },
            Wheel {
                name: "F".into(),
                carrier: "H".into(),
                centre: "CF".into(),
                axle: Axis::Y,
                spin: "thetaF".into(),
                radius: rf,
                mass: sym("mF"),
                diametral: sym("IFxx"),
                axial: sym("IFyy"),
                down: None,
                at_root: false,
            },
        ],
        torques: Vec::new(),
        gravity: sym("g"),
    }
}

/// The bicycle of [`whipple`] with the rider's body moved sideways as the memoir's n° 98 moves
/// it: the rear body's centre of gravity turned by the angle `epsilon` (a parameter) about the
/// rear frame's ground trace OI, the line through the rear contact P along the heading. The
/// frames and points that carry the wheels and the steering axis are the bicycle's own; the
/// rear body (frame and rider, the benchmark's B) is carried by $L_\varepsilon = L\cdot
/// R_x(\varepsilon)$ and $E = L_\varepsilon\cdot R_y(\theta)$, its centre
/// $P - r_R\,(L_\varepsilon)_z + E\,(x_B, 0, z_B + r_R)$: the vector from P to the centre of
/// [`whipple`] turned about OI by ε.
pub fn whipple_shifted() -> Model {
    let mut m = whipple();
    let rr = sym("rR");
    m.name = "whipple_shifted".into();
    m.params.push("epsilon".into());
    m.frames.push(frame(
        "Le",
        "L",
        vec![Rotation {
            axis: Axis::X,
            angle: Angle::Parameter { name: "epsilon".into(), negated: false },
        }],
    ));
    m.frames.push(frame("E", "Le", vec![rot(Axis::Y, "theta")]));
    m.points.push(point("CRe", "P", "Le", [zero(), zero(), -&rr]));
    m.points.push(point("GBe", "CRe", "E", [sym("xB"), zero(), sym("zB") + &rr]));
    let body = m.bodies.iter_mut().find(|b| b.name == "B").expect("the rear body");
    body.frame = "E".into();
    body.centre = "GBe".into();
    m
}

/// The bicycle of [`whipple`] with the rear wheel's rotation measured from the lean frame L
/// instead of the rear frame B: the same bicycle (the axle is L's and B's y axis, the wheel is
/// symmetric about it), but its independent speed is then the wheel's spin about its axle up to
/// the heading's share, $\dot\theta_R + \dot\theta$ of [`whipple`], as the memoir's $s$ is
/// (n° 108): holding it fixed holds the forward speed at first order, where holding
/// [`whipple`]'s rate relative to the pitching frame does not. Kane's equations of lean and
/// steer are the same; how Carvallo's modified Lagrange equations split between the momentum's
/// derivative and the correction is not (the split depends on which speeds are held).
pub fn whipple_rear_spin_from_lean() -> Model {
    let mut m = whipple();
    m.name = "whipple_rear_spin_from_lean".into();
    let rear = m.wheels.iter_mut().find(|w| w.name == "R").expect("the rear wheel");
    rear.carrier = "L".into();
    m
}
