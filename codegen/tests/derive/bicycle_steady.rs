//! The bicycle's steady-state derivation (memoir n° 79–106): every check must come out as
//! expected (all hold except the findings listed in `EXPECTED_FALSE`, each explained in its
//! detail and in the report's notes).

use crate::common;

/// Checks that must come out false: findings about the memoir.
const EXPECTED_FALSE: [&str; 9] = [
    // n° 83/85: two third-order terms of the loaded frame's row are wrong.
    "fall_frame_memoir",
    // n° 94: the same terms, copied into the handlebar equation.
    "steer_frame_memoir",
    // n° 95: (1) drops the 1/cos(alpha) of the frame's term (second order).
    "steer_95_from_before",
    // n° 95: (1)' writes mu1 for mu1 sin(omega).
    "theta1_ratio_memoir",
    // n° 102: df/dp' = A is the memoir's declared approximation.
    "dfdpp_memoir",
    // n° 83: terms (3), (4), (6) print every L term with the sign opposite to n° 99-100.
    "frame_83_term3",
    // n° 83: (4) also prints -mu R sin(theta) for +mu R e cos(theta) (the error of n° 85's row).
    "frame_83_term4",
    // n° 83: (5) drops -B eta' (the frame's own moment about Sj).
    "frame_83_term5",
    "frame_83_term6",
];

fn bicycle_steady_derivation_body() {
    let d = crate::derived("bicycle_steady");
    common::assert_checks(&d.checks, &EXPECTED_FALSE);
}

#[test]
fn bicycle_steady_derivation() {
    crate::on_symbolica_thread(bicycle_steady_derivation_body);
}
