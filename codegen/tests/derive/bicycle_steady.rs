//! The bicycle's steady-state derivation (memoir n° 79–106): every check must come out as
//! expected (all hold except the findings listed in `EXPECTED_FALSE`, each explained in its
//! detail and in the report's notes).

use crate::common;

/// Checks that must come out false: findings about the memoir.
const EXPECTED_FALSE: [&str; 5] = [
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
];

fn bicycle_steady_derivation_body() {
    let d = crate::derived("bicycle_steady");
    common::assert_checks(&d.checks, &EXPECTED_FALSE);
}

#[test]
fn bicycle_steady_derivation() {
    crate::on_symbolica_thread(bicycle_steady_derivation_body);
}
