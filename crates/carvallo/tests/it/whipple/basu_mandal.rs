//! The generated nonlinear Carvallo–Whipple equations against the external benchmark of
//! Basu-Mandal, Chatterjee and Papadopoulos, "Hands-free circular motions of a benchmark
//! bicycle", Proc. R. Soc. A 463 (2007) 1983–2003, Table 1: a state of the benchmark bicycle
//! and its nine accelerations. The numbers (13 decimals) are those transcribed in
//! `moorepants/DynamicistToolKit`, file `dtk/bicycle.py`, functions `basu_table_one_input` and
//! `basu_table_one_output`; the coordinate map is that file's `basu_to_moore_input` composed
//! with the benchmark convention of `carvallo::whipple::nonlinear` (see its module docs).
//!
//! Tolerances: each of the nine accelerations within relative 1e-11 of the table; the pitch
//! solved from the contact constraint within 1e-12 rad of the table's, the dependent rates
//! the equations give (pitch, yaw, front wheel) within relative 1e-11 of the table's rates.

use carvallo::whipple::nonlinear::{Configuration, WhippleNonlinear};
use carvallo::whipple::WhippleParams;

/// Table 1 input: x, y, z, theta, psi, phi, psif, betar, betaf.
const Q: [f64; 9] =
    [0.0, 0.0, 0.2440472102925, 0.0, 0.9501292851472, 3.1257073014894, 0.2311385135743, 0.0, 0.0];
/// Table 1 input rates.
const QD: [f64; 9] = [
    -2.8069345714545,
    -0.1480982396001,
    0.1058778746261,
    0.7830033527065,
    0.6068425835418,
    -0.0119185528069,
    0.4859824687093,
    8.9129896614890,
    8.0133620584155,
];
/// Table 1 output: the nine accelerations.
const QDD: [f64; 9] = [
    -0.5041626315047,
    -0.3449706619454,
    -1.4604528332980,
    0.8353281706379,
    -7.8555281128244,
    0.1205543897884,
    -4.6198904039403,
    1.8472554144217,
    2.4548072904550,
];
const NAMES: [&str; 9] = ["x", "y", "z", "theta", "psi", "phi", "psif", "betar", "betaf"];

#[test]
fn table_one_accelerations() {
    let bike = WhippleNonlinear::new(WhippleParams::benchmark());
    let qdd = bike.basu_mandal_accelerations(Q, QD).expect("evaluation");
    let mut worst: f64 = 0.0;
    for k in 0..9 {
        let rel = (qdd[k] - QDD[k]).abs() / QDD[k].abs();
        worst = worst.max(rel);
        eprintln!(
            "{}dd: derived {:.13}, table {:.13}, relative {rel:.1e}",
            NAMES[k], qdd[k], QDD[k]
        );
    }
    eprintln!("worst relative difference: {worst:.2e}");
    for k in 0..9 {
        assert!(
            (qdd[k] - QDD[k]).abs() <= 1e-11 * QDD[k].abs(),
            "{}dd: derived {}, table {}",
            NAMES[k],
            qdd[k],
            QDD[k]
        );
    }
}

#[test]
fn table_one_constraints() {
    let pi = std::f64::consts::PI;
    let bike = WhippleNonlinear::new(WhippleParams::benchmark());
    let (lean, steer) = (pi / 2.0 - Q[4], -Q[6]);
    let pitch = bike.pitch(lean, steer, 0.0).expect("pitch");
    assert!((pitch - (pi - Q[5])).abs() <= 1e-12, "pitch {pitch}, table {}", pi - Q[5]);
    let c = Configuration {
        lean,
        pitch,
        steer,
        lean_rate: -QD[4],
        steer_rate: -QD[6],
        rear_wheel_rate: -QD[7],
    };
    let a = bike.accelerations(&c).expect("accelerations");
    // Pitch rate = -phid_b, yaw rate = -thetad_b, front wheel rate = -betafd_b.
    for (got, want, name) in [
        (a.dependent_rates[0], -QD[5], "pitch rate"),
        (a.dependent_rates[1], -QD[3], "yaw rate"),
        (a.dependent_rates[2], -QD[8], "front wheel rate"),
    ] {
        assert!((got - want).abs() <= 1e-11 * want.abs(), "{name}: {got} vs table {want}");
    }
}

#[test]
fn bad_input_is_named() {
    let bike = WhippleNonlinear::new(WhippleParams::benchmark());
    let mut q = Q;
    q[6] = f64::NAN;
    let e = bike.basu_mandal_accelerations(q, QD).unwrap_err();
    assert_eq!(e.to_string(), "invalid q[6] (psif) NaN: must be finite");
}
