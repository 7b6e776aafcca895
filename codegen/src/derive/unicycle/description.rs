//! The mounted unicycle as a description for the mechanics engine ([`crate::mechanics::engine`]):
//! the memoir's unicycle (n° 20–24) — a wheel of mass $\mu_1$ and a rider held rigid in the
//! lean frame, of mass $\mu$, centroid $G = O + zk$ and moments $A, B, C$ and product $L$ about
//! the contact O (n° 21) — written as the hoop's description plus one body. The engine derives
//! it by Kane's method and by the modified Lagrange equations; the test
//! `codegen/tests/derive/engine_unicycle.rs` compares both with the hand derivation of
//! [`super`] (`generated/unicycle.ir`) at 256 bits.
//!
//! The memoir's moments are about O; a body's inertia is given about its mass centre, so the
//! parallel-axis terms are removed: about G, $A - \mu z^2$, $B - \mu z^2$, $C$ and the x–z
//! product $L$ (the axes: the engine's lean frame, here E since L names the product, has x forward, y along the axle and z *down*,
//! so $\zeta = -z_L$ and the tensor's entry $-\sum m\,x z_L = \sum m\,\xi\zeta = L$). The wheel
//! is a body of revolution: its diametral moment about its centre is $C_1$ (the k axis through O
//! passes through the centre) and its axial one $B_1 - \mu_1 R^2$; the memoir's $A_1$ is then
//! $C_1 + \mu_1 R^2$, which the engine's wheel implies.

use symbolica::atom::Atom;

use super::PARAMS;
use crate::mechanics::engine::{point, sym, Body, Model};

/// The mounted unicycle's description.
pub fn unicycle() -> Model {
    let mut m = crate::derive::hoop::description::hoop();
    let (r, z, mu) = (sym("R"), sym("z"), sym("mu"));
    m.name = "unicycle_engine".into();
    m.params = PARAMS.iter().map(|s| s.to_string()).collect();
    // The memoir's product of inertia is called L: the lean frame becomes E.
    let lean = |f: &mut String| {
        if f == "L" {
            *f = "E".into();
        }
    };
    for f in &mut m.frames {
        lean(&mut f.name);
        lean(&mut f.parent);
    }
    for p in &mut m.points {
        lean(&mut p.frame);
    }
    for w in &mut m.wheels {
        lean(&mut w.carrier);
        if let Some((f, _)) = &mut w.down {
            lean(f);
        }
    }
    let wheel = &mut m.wheels[0];
    wheel.mass = sym("mu1");
    wheel.diametral = sym("C1");
    wheel.axial = sym("B1") - sym("mu1") * &r * &r;
    m.points.push(point("G", "P", "E", [Atom::num(0), Atom::num(0), -&z]));
    let zero = || Atom::num(0);
    let mz2 = &mu * &z * &z;
    m.bodies.push(Body {
        name: "rider".into(),
        frame: "E".into(),
        centre: "G".into(),
        mass: mu,
        inertia: [
            [sym("A") - &mz2, zero(), sym("L")],
            [zero(), sym("B") - &mz2, zero()],
            [sym("L"), zero(), sym("C")],
        ],
    });
    m
}
