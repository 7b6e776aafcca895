//! The bicycle kinematics derivation (memoir n° 59–69): every check must come out as expected
//! (all hold except the findings listed in `EXPECTED_FALSE`), and the emitted program must give
//! the upright straight bicycle's known rates: no turning, no pitching and equal rolling of the
//! two wheels (n° 66, (2)).

use crate::common;

/// Checks that must come out false: findings about the memoir, explained in their detail.
const EXPECTED_FALSE: [&str; 4] = [
    // n° 61: the printed dH has I where J belongs in its deta term.
    "variation_h_61_as_printed",
    // n° 64: the summary (dnu) prints R (sin mu - c) for (R sin mu - c).
    "relation_dnu_64_as_printed",
    // n° 69: (9) lacks the derivative of 1/cos eta (zero at theta = 0).
    "mu_prime_9_69",
    // n° 69: eta'' has sin^2 gamma, the print sin gamma.
    "eta_second_69_as_printed",
];

fn bicycle_kinematics_derivation_body() {
    let d = crate::derived("bicycle_kinematics");
    common::assert_checks(&d.checks, &EXPECTED_FALSE);
    // The old bicycle of n° 52 upright and straight (theta = gamma = 0, sigma = mu = sigma0):
    // M is at x = l, y = 0, alpha = beta = 0, so (I) gives no pitching or turning, the steady
    // turning rate is 0 and the front wheel rolls as the rear one (sigma1' = s).
    let s0 = 25f64.to_radians();
    let at = common::outputs_at(d, &[0.38, 1.10, 0.08, s0], &[0.0, 0.0, s0, s0]);
    for name in ["d_eta_d_theta", "d_eta_d_gamma", "d_nu_d_theta", "steady_n", "eta_second"] {
        assert!(at(name).abs() < 1e-15, "{name} = {} upright", at(name));
    }
    assert!((at("steady_sigma1_rate") - 1.0).abs() < 1e-15, "{}", at("steady_sigma1_rate"));
    // dM/dsigma = I R and dM/dsigma1 = -I1 R = -I R upright.
    assert!((at("dm_i_sigma") - 0.38).abs() < 1e-15);
    assert!((at("dm_i_sigma1") + 0.38).abs() < 1e-14, "{}", at("dm_i_sigma1"));
    let sizes: usize = d.formulas.iter().map(|f| f.expr.to_string().len()).sum();
    assert!(sizes < 100_000, "the formulas take {sizes} characters");
}

#[test]
fn bicycle_kinematics_derivation() {
    crate::on_symbolica_thread(bicycle_kinematics_derivation_body);
}
