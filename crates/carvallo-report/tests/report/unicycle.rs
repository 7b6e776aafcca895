//! Tests of the unicycle concordance (memoir n° 21–41, 74, 78): the expected verdict of the
//! entries that are findings, every formula entry consistent with its tolerance, and a
//! snapshot of the text table with numbers normalised to 4 significant digits.

use std::collections::BTreeMap;

use carvallo_report::unicycle::entries;
use carvallo_report::{render_text_normalised, Verdict};

use crate::common;

/// Entries whose verdict is not `agrees`, by (section, quantity); every other entry agrees
/// or is a slide-rule `rounding`.
fn findings() -> BTreeMap<(&'static str, &'static str), Verdict> {
    use Verdict::*;
    BTreeMap::from([
        (("24", "equation (p), letters merged"), DerivationDiffers),
        (("24", "equation (n), letters merged"), DerivationDiffers),
        (("24", "equation (s), letters merged"), DerivationDiffers),
        (("24", "unicycle check merge_is_substitution"), DerivationDiffers),
        (("30", "D complete"), MemoirError),
        (("30", "unicycle check skid_full_memoir"), MemoirError),
        (("74", "unicycle check lagrange_theta_74_as_printed"), Ocr),
        (("78", "(2) product of the roots, straight running"), DerivationDiffers),
        (("78", "(3) sum of the roots, straight running"), DerivationDiffers),
        (("78", "unicycle check sum_78_full_model"), DerivationDiffers),
        (("32", "table n° 32, theta = 10°, s0"), MemoirError),
        (("32", "table n° 32, theta = 10°, s at n = -0.3"), MemoirError),
        (("32", "table n° 32, theta = 10°, s at n = -0.5"), MemoirError),
        (("32", "table n° 32, theta = 10°, s at n = -1"), MemoirError),
        (("32", "table n° 32, theta = 20°, D"), Ocr),
        (("32", "table n° 32, theta = 20°, s at n = -0.1"), MemoirError),
        (("32", "table n° 32, theta = 40°, s0"), MemoirError),
        (("32", "table n° 32, theta = 50°, s at n = -1.5"), MemoirError),
        (("32", "s0 of (E), formula"), MemoirError),
        (("32", "point I, theta as printed arcsin(1/2.5) (degrees)"), MemoirError),
        (("32", "limit radius s / sqrt(g/R)"), MemoirError),
        (("36", "C0 = mu0 r^2 / 2 (kg m^2)"), MemoirError),
        (("36", "C = C0 + C1 (kg m^2)"), MemoirError),
        (
            ("36", "straight running threshold s, full model (h = 2.5 R, rider C0 = 0.77)"),
            DerivationDiffers,
        ),
        (("39", "table n° 39, theta = 0°, |n| limit"), Ocr),
        (("39", "table n° 39, theta = 50°, |n| limit"), MemoirError),
        (("39", "table n° 39, theta = 50°, s"), MemoirError),
        (("41", "first member of n° 41 at theta = 10°"), MemoirError),
        (("41", "first member of n° 41 at theta = 40°"), MemoirError),
        (("41", "first member of n° 41 at theta = 50°"), MemoirError),
        (("41", "first zero of the first member (degrees)"), MemoirError),
        (("41", "junction point n"), MemoirError),
        (("41", "junction point s"), MemoirError),
        (("36", "first member (S): s^2 over constant term"), Ocr),
        (("36", "infinitely light rider, threshold s^2"), MemoirError),
        (("40", "left side A dp'/dn"), Ocr),
        (("41", "conclusion: speed limit sqrt(C/(mu1 R^2))"), Ocr),
        (("78", "characteristic determinant, second row"), Ocr),
        (("78", "dN/dp at theta = 0, n = 0"), Ocr),
    ])
}

#[test]
fn verdicts_are_the_expected_ones() {
    let entries = entries();
    common::assert_formulas_agree_within_tolerance(&entries);
    common::assert_verdicts(
        &entries,
        &findings(),
        &[
            "21", "23", "24", "29", "30", "31", "32", "33", "34", "35", "36", "39", "40", "41",
            "74", "78",
        ],
    );
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&entries());
    insta::with_settings!({
        description => "carvallo report: the unicycle concordance table, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("unicycle_report_text", text);
    });
}

#[test]
fn claims_snapshot() {
    let text = carvallo_report::normalise_numbers(&carvallo_report::claims::render_claims_text(
        &carvallo_report::unicycle::claims(),
    ));
    insta::with_settings!({
        description => "carvallo report: the unicycle's claims n° 20-42, 74, 78, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("unicycle_claims_text", text);
    });
}

/// The straight-running threshold s^2 (unit g/R) of the n° 36 example's family, in closed
/// form (the second route): a rider of 60 kg at the height `h` with C0 = `c0` on a hoop wheel
/// of mass `mu1` and radius `r` (B1 = 2 mu1 r^2, C1 = mu1 r^2 / 2). With W = 60 h + mu1 r,
/// C = C0 + C1 and the spin excess B1 - mu1 r^2, upright straight running is stable for
/// s^2 > W C r / ((B1 - mu1 r^2)(W r + B1 - mu1 r^2)) (the hoop alone: 1/4).
fn threshold_s2(r: f64, mu1: f64, h: f64, c0: f64) -> f64 {
    let m = mu1 * r * r;
    let (spin_excess, c, w) = (2.0 * m - m, c0 + 0.5 * m, 60.0 * h + mu1 * r);
    w * c * r / (spin_excess * (w * r + spin_excess))
}

/// The memoir's cylinder rider (60 kg, circumference 1 m, centre at h = 1.25 m) of length
/// `len`, in closed form: A about the contact point's I axis and E = B - C - mu h^2.
fn cylinder_a_e(len: f64) -> (f64, f64) {
    let (mu, r, h) = (60.0, 1.0 / (2.0 * std::f64::consts::PI), 1.25);
    let a = mu * (r * r / 4.0 + len * len / 12.0 + h * h);
    (a, mu * (len * len / 12.0 - r * r / 4.0))
}

/// Every claim of the unicycle (n° 20–42, 74, 78) with its verdict and the evidence that
/// carries it, each threshold the one its `how` states (or the decision the claim's check
/// makes, where the `how` names none), written here; closed forms as a second route where
/// one exists.
#[test]
fn claims_have_the_expected_verdicts() {
    use crate::common::Ev::*;
    use Verdict::*;
    let claims = carvallo_report::unicycle::claims();
    let deg = f64::to_degrees;
    let rel = |x: f64, tol: f64| x.abs() * tol;
    // n° 24, 39: the cylinder rider over lengths 1.0–1.8 m, midpoint rule within 1e-3.
    let (a_short, e_short) = cylinder_a_e(1.0);
    let (a_long, e_long) = cylinder_a_e(1.8);
    let a1 = 1.5 * 5.0 * 0.5 * 0.5;
    let c_cyl = 60.0 / (2.0 * (2.0 * std::f64::consts::PI).powi(2));
    let mu_h2 = 60.0 * 1.25 * 1.25;
    let diameter = 1.0 / std::f64::consts::PI;
    let length_e0 = 3f64.sqrt() / (2.0 * std::f64::consts::PI);
    // n° 36, 37, 40, 42: the straight-running thresholds in closed form.
    let s2_small = threshold_s2(0.5, 5.0, 1.25, 0.77);
    let s2_big = threshold_s2(1.2, 12.0, 1.10, 0.77);
    let speed = |r: f64, s2: f64| r * (s2 * 9.81 / r).sqrt();
    // n° 32: I where s0 = -n0 on (E): sin(theta) = R / (2 h).
    let theta_i = deg((0.5 / 2.5f64).asin());
    // n° 41: cos times the bracket is 1 - (h/R) sin^2 cos^2, smallest at 45°.
    let bracket_min = 1.0 - 2.5 / 4.0;
    // n° 41: (S) touches (ℰ) where tan(theta) = 2.
    let contact = deg(2f64.atan());
    crate::common::assert_claim_evidence(
        &claims,
        &[
            // n° 20: to the central differences' 1e-6.
            (
                "unicycle-unmounted-is-hoop",
                Agrees,
                &[
                    Near("states", 16.0, 0.0),
                    Below("max_diff_accelerations_in_g_over_R", 1e-6),
                    Below("max_rel_diff_stability", 1e-6),
                ],
            ),
            // n° 22: the potential within 1e-12, the work within 1e-6.
            (
                "unicycle-weight-work",
                Agrees,
                &[
                    Near("points", 16.0, 0.0),
                    Below("max_rel_diff_potential", 1e-12),
                    Below("max_rel_diff_work", 1e-6),
                ],
            ),
            // n° 24: A1 = 3/2 mu1 R^2 under 5 % of A, A's spread over the lengths above A1.
            (
                "unicycle-wheel-small-against-rider",
                Agrees,
                &[
                    Near("A1", a1, 1e-12),
                    Below("max_A1_over_A", 0.05),
                    Near("max_A1_over_A", a1 / a_short, rel(a1 / a_short, 1e-3)),
                    Near("A_min", a_short, rel(a_short, 1e-3)),
                    Near("A_max", a_long, rel(a_long, 1e-3)),
                    Above("A_max", a_long - 0.01 * a_long),
                    Below("A_min", a_long - 0.01 * a_long - a1),
                ],
            ),
            // n° 25: (s) vanishes to 1e-12, the energy drifts less than 1e-8.
            (
                "unicycle-steady-needs-no-motor",
                Agrees,
                &[Below("max_rel_s_first_member", 1e-12), Below("max_rel_energy_drift", 1e-8)],
            ),
            // n° 25: the moment is (mu + mu1) g R sin(i) within 1e-6, not tan(i): tan/sin = 1/cos,
            // so the printed tan is off by 1 - cos(i), 1 - cos 20° at the largest slope.
            (
                "unicycle-slope-moment",
                MemoirError,
                &[
                    Near("slopes", 12.0, 0.0),
                    Below("max_rel_diff_sin", 1e-6),
                    Above("max_rel_diff_tan", 1e-6),
                    Near("max_rel_diff_tan", 1.0 - 20f64.to_radians().cos(), 1e-6),
                    Near("rel_diff_tan_at_10deg", 1.0 - 10f64.to_radians().cos(), 1e-6),
                ],
            ),
            (
                "unicycle-slope-sign",
                Agrees,
                &[Near("slopes", 12.0, 0.0), Near("all_signs_of_i", 1.0, 0.0)],
            ),
            // n° 26: negative work everywhere; the largest -(R - m)/R at m/R = 0.95.
            (
                "unicycle-pedal-paradox",
                Agrees,
                &[
                    Near("cases", 19.0 * 24.0, 0.0),
                    Below("largest_work_per_F_R", 0.0),
                    Near("largest_work_per_F_R", -(1.0 - 0.95), 1e-6),
                ],
            ),
            // n° 26 bis: sin S = (m/M) sin(P, I) within 1e-6, the neutral angle inside 0°–90°.
            (
                "unicycle-string-neutral-angle",
                Agrees,
                &[
                    Near("geometries", 72.0, 0.0),
                    Below("max_abs_diff_sin", 1e-6),
                    Above("neutral_deg_min", 0.0),
                    Below("neutral_deg_max", 90.0),
                ],
            ),
            // n° 26: the work -(M - m), largest for the smallest advance 2 × 0.33 m and the
            // longest crank 0.17 m.
            (
                "unicycle-velocipede-paradox",
                Agrees,
                &[
                    Near("geometries", 72.0, 0.0),
                    Below("largest_work", 0.0),
                    Near("largest_work", -(2.0 * 0.33 - 0.17), 1e-6),
                ],
            ),
            // n° 26 bis: positive and equal to the crank m within 1e-6 (the shortest 0.15 m).
            (
                "unicycle-interior-force-advances",
                Agrees,
                &[
                    Near("geometries", 72.0, 0.0),
                    Near("reaction_points", 3.0, 0.0),
                    Above("min_work", 0.0),
                    Near("min_work", 0.15, 0.15 * 1e-6),
                    Below("max_rel_diff_work_vs_crank", 1e-6),
                ],
            ),
            // n° 29.
            (
                "unicycle-steady-n-identity",
                Agrees,
                &[Near("points", 16.0, 0.0), Below("max_rel_n_first_member", 1e-12)],
            ),
            (
                "unicycle-equilibrium-hoop-form",
                Agrees,
                &[Near("points", 128.0, 0.0), Below("max_rel_diff", 1e-9)],
            ),
            // n° 30: a formula, within 1e-12.
            (
                "unicycle-skid-reduces-to-hoop",
                Agrees,
                &[Near("points", 16.0, 0.0), Below("max_rel_diff", 1e-12)],
            ),
            // n° 31: the p' term as printed within 1e-6, the p^2 term with the opposite sign.
            (
                "unicycle-abrupt-turn-increase",
                MemoirError,
                &[
                    Below("max_rel_diff_p_prime_term", 1e-6),
                    Near("derived_over_printed_p2_term", -1.0, 1e-6),
                ],
            ),
            // n° 31: z cos / g against z cos / (D g) at D = 0.5, at least 1.99 times.
            (
                "unicycle-abrupt-turn-pprime-larger",
                Agrees,
                &[
                    Near("p2_term", 0.98 / 9.81, 0.98 / 9.81 * 1e-6),
                    Near("p_prime_term_min", 0.98 / (0.5 * 9.81), 0.98 / (0.5 * 9.81) * 1e-6),
                    AtMostTimes("p2_term", 1.0 / 1.99, "p_prime_term_min"),
                ],
            ),
            // n° 32.
            (
                "unicycle-turns-toward-lean",
                Agrees,
                &[
                    Above("roots", 100.0),
                    Near("all_opposite", 1.0, 0.0),
                    Near("all_centres_on_lean_side", 1.0, 0.0),
                ],
            ),
            (
                "unicycle-skid-is-tan-on-e",
                Agrees,
                &[Near("points", 84.0, 0.0), Below("max_rel_diff", 1e-12)],
            ),
            (
                "unicycle-separation-curve",
                Agrees,
                &[Near("points", 46.0, 0.0), Below("max_rel_diff", 1e-12)],
            ),
            (
                "unicycle-n-touches-e",
                Agrees,
                &[
                    Near("gap_at_I", 0.0, 1e-6),
                    Above("min_gap_1deg_away", 0.0),
                    Near("theta_I_deg", theta_i, 1e-6),
                ],
            ),
            (
                "unicycle-walking-pivoting-regions",
                Agrees,
                &[
                    Near("misclassified", 0.0, 0.0),
                    Near("none_below_E", 1.0, 0.0),
                    Above("points_with_roots", 1000.0),
                ],
            ),
            // n° 32: the limit within 0.05 of the circle s = 1.
            (
                "unicycle-stability-circle",
                Agrees,
                &[
                    Below("max_abs_s_limit_minus_1", 0.05),
                    Exceeds("stable_below_circle_up_to_deg", "first_root_deg"),
                ],
            ),
            // n° 32: n2 unusable only under s = 1.04, n1 usable somewhere: the memoir's « n2
            // seule » fails.
            (
                "unicycle-practical-region",
                MemoirError,
                &[
                    Above("points_with_roots", 500.0),
                    Below("n2_unusable_max_s", 1.04),
                    Above("n1_usable", 0.0),
                ],
            ),
            // n° 33.
            (
                "unicycle-l-terms-vanish-at-steady",
                Agrees,
                &[Below("max_L_part_steady", 1e-12), Below("max_diff_L_part_general", 1e-10)],
            ),
            // n° 34.
            (
                "unicycle-solved-form",
                Agrees,
                &[Below("max_dev_L0_in_g_over_R", 1e-12), Above("max_dev_L1_in_g_over_R", 1e-3)],
            ),
            (
                "unicycle-stability-recipe",
                Agrees,
                &[Near("points", 16.0, 0.0), Below("max_rel_diff", 1e-6)],
            ),
            // n° 35.
            (
                "unicycle-stability-biquadratic",
                Agrees,
                &[Below("max_rel_diff_form", 1e-9), Below("max_rel_diff_biquadratic", 1e-8)],
            ),
            // n° 36.
            (
                "unicycle-straight-running-steady",
                Agrees,
                &[Below("max_rel_diff_weight", 1e-12), Below("max_at_theta_0", 1e-12)],
            ),
            // n° 36 re-judged: the full model without rider and the hoop give s^2 > 1/4, not 1/2.
            (
                "unicycle-light-rider-hoop-limit",
                MemoirError,
                &[
                    Near("hoop_s2", 0.25, 1e-9),
                    Near("full_no_rider_s2", 0.25, 1e-9),
                    Near("full_light_rider_s2", 0.25, 1e-5),
                    Near("memoir_formula_s2", 0.5, 1e-12),
                ],
            ),
            // n° 36: no threshold without a wheel; s^2 grows more than 5 times per factor 10 of
            // the wheel's mass and s^2 mu1 tends to C0 / R^2 (within 2 %).
            (
                "unicycle-light-wheel-unstable",
                Agrees,
                &[
                    Near("massless_wheel_threshold_found", 0.0, 0.0),
                    AtMostTimes("s2_5kg", 1.0 / 125.0, "s2_0.005kg"),
                    Near("s2_times_mu1_0.005kg", 0.77 / 0.25, 0.77 / 0.25 * 2e-2),
                    Near("s2_5kg", s2_small, rel(s2_small, 1e-9)),
                    Near(
                        "s2_0.005kg",
                        threshold_s2(0.5, 0.005, 1.25, 0.77),
                        rel(threshold_s2(0.5, 0.005, 1.25, 0.77), 1e-9),
                    ),
                ],
            ),
            // n° 37: the threshold speed rises as the wheel lightens.
            (
                "unicycle-stability-decreases-with-wheel",
                Agrees,
                &[
                    Exceeds("speed_5kg", "speed_50kg"),
                    Exceeds("speed_0.5kg", "speed_5kg"),
                    Near("speed_5kg", speed(0.5, s2_small), rel(speed(0.5, s2_small), 1e-9)),
                    Near(
                        "speed_50kg",
                        speed(0.5, threshold_s2(0.5, 50.0, 1.25, 0.77)),
                        rel(speed(0.5, threshold_s2(0.5, 50.0, 1.25, 0.77)), 1e-9),
                    ),
                    Near(
                        "speed_0.5kg",
                        speed(0.5, threshold_s2(0.5, 0.5, 1.25, 0.77)),
                        rel(speed(0.5, threshold_s2(0.5, 0.5, 1.25, 0.77)), 1e-9),
                    ),
                ],
            ),
            (
                "unicycle-stability-from-wheel-spin",
                Agrees,
                &[
                    Below("max_rider_p_term", 1e-9),
                    Near("threshold_found_without_spin_excess", 0.0, 0.0),
                ],
            ),
            (
                "unicycle-fall-turns-toward-lean",
                Agrees,
                &[
                    Near("cases", 32.0, 0.0),
                    Near("turns_toward_fall", 1.0, 0.0),
                    Near("turning_rights", 1.0, 0.0),
                ],
            ),
            // n° 37: R = 0.5 m, s = 10/s, p = 0.3/s: the rim's normal acceleration is the
            // Coriolis 2 R s p, twice the printed W = R s p, and the couple 4 p s R^2, twice the
            // printed 2 p s R^2 (within the holding test's 1e-6); the ring's moment R^2 s p.
            (
                "unicycle-accelerating-couple",
                MemoirError,
                &[
                    Near("the memoir's W = Rsp (m/s²)", 0.5 * 10.0 * 0.3, 1e-12),
                    Near("the memoir's 2psR² (m²/s²)", 2.0 * 0.3 * 10.0 * 0.25, 1e-12),
                    Near("normal acceleration at A (m/s²)", 2.0 * 0.5 * 10.0 * 0.3, 3e-6),
                    Near(
                        "couple of the pair A, B per unit mass (m²/s²)",
                        4.0 * 0.3 * 10.0 * 0.25,
                        3e-6,
                    ),
                    Near("ring: R² s p (m²/s²)", 0.25 * 10.0 * 0.3, 1e-12),
                    Near("ring of unit mass: moment about OK (m²/s²)", 0.25 * 10.0 * 0.3, 0.75e-6),
                ],
            ),
            // n° 37: ratios 1, 2, 4 within 1e-12.
            (
                "unicycle-three-accelerations",
                Agrees,
                &[
                    Near("fall acceleration ratio (2s / s)", 1.0, 1e-12),
                    Near("turning acceleration ratio (2s / s)", 2.0, 1e-12),
                    Near("righting acceleration ratio (2s / s)", 4.0, 1e-12),
                ],
            ),
            (
                "unicycle-straight-running-oscillates",
                Agrees,
                &[
                    Below("fast_max_theta", 0.1),
                    Above("fast_sign_changes_of_p", 3.5),
                    Above("slow_max_theta", 1.0),
                    Below("fast_rel_energy_drift", 1e-8),
                ],
            ),
            // n° 39: stable only for |n| above sqrt(R/h) (within 1 %), never upright.
            (
                "unicycle-light-stable-only-turning",
                Agrees,
                &[
                    Near("sqrt_R_over_h", 0.4f64.sqrt(), 1e-12),
                    Above("smallest_stable_abs_n", 0.99 * 0.4f64.sqrt()),
                    Below("max_S1_straight", 0.0),
                ],
            ),
            (
                "unicycle-light-stable-root-n1",
                Agrees,
                &[
                    Near("states", 300.0, 0.0),
                    Near("exceptions", 0.0, 0.0),
                    Below("rel_gap_10deg", 0.15),
                    Below("rel_gap_30deg", 0.15),
                    Below("rel_gap_50deg", 0.15),
                ],
            ),
            // n° 39: a path under 4 m across with R = 0.5 m.
            (
                "unicycle-light-turning-radius",
                Agrees,
                &[Below("max_path_radius_m", 2.0), Below("max_path_radius_over_R", 4.0)],
            ),
            // n° 39: E = mu (l^2/12 - r^2/4) against C = mu r^2/2; E = 0 at l = sqrt 3 r.
            (
                "unicycle-e-larger-than-c",
                Agrees,
                &[
                    Above("min_E_over_C", 1.0),
                    Near("min_E_over_C", e_short / c_cyl, rel(e_short / c_cyl, 1e-3)),
                    Near("max_E_over_C", e_long / c_cyl, rel(e_long / c_cyl, 1e-3)),
                    Near("diameter_m", diameter, 1e-12),
                    Near("length_for_E0_m", length_e0, rel(length_e0, 1e-3)),
                    Exceeds("diameter_m", "length_for_E0_m"),
                ],
            ),
            // n° 39: the error of E = 0 in (S) at least ten times its error in (E).
            (
                "unicycle-e-zero-not-in-s",
                Agrees,
                &[
                    Above("error in (S) over error in (E)", 10.0),
                    Near(
                        "smallest share of E in B - C",
                        e_short / (mu_h2 + e_short),
                        rel(e_short / (mu_h2 + e_short), 1e-3),
                    ),
                    Near(
                        "largest share of E in B - C",
                        e_long / (mu_h2 + e_long),
                        rel(e_long / (mu_h2 + e_long), 1e-3),
                    ),
                    Above("smallest fraction of (S) with the real E", 1.0),
                ],
            ),
            // n° 40: no change within 1e-9; the threshold in closed form, the memoir's
            // sqrt(1.40 / 1.25).
            (
                "unicycle-straight-threshold-independent",
                Agrees,
                &[
                    Below("max_rel_change", 1e-9),
                    Near("threshold_units", s2_small.sqrt(), rel(s2_small.sqrt(), 1e-9)),
                    Near("memoir_formula_units", (1.40f64 / 1.25).sqrt(), 1e-12),
                ],
            ),
            // n° 41.
            (
                "unicycle-bracket-positive",
                Agrees,
                &[
                    Above("min_cos_times_bracket", 0.0),
                    Near("min_cos_times_bracket", bracket_min, 1e-9),
                ],
            ),
            (
                "unicycle-stable-between-roots",
                Agrees,
                &[
                    Near("states", 18000.0, 0.0),
                    Above("min_S_over_1_plus_n2", 0.0),
                    Exceeds("second_zero_deg", "first_zero_deg"),
                ],
            ),
            (
                "unicycle-small-lean-outside-interval",
                Agrees,
                &[Above("states", 1000.0), Near("exceptions", 0.0, 0.0)],
            ),
            // n° 41: (s - 1)/theta^2 constant within 2 % (0.75 × 0.02), the inner branch
            // under 0.05 at 0.5°.
            (
                "unicycle-s-curve-ends",
                Agrees,
                &[
                    Equal("s_minus_1_over_theta2_0.5deg", "s_minus_1_over_theta2_1deg", 0.015),
                    Above("s_minus_1_over_theta2_0.5deg", 0.0),
                    Above("inner_s_0.5deg", 0.0),
                    Below("inner_s_0.5deg", 0.05),
                ],
            ),
            // n° 41: one contact, beyond 62°: at tan(theta) = 2.
            (
                "unicycle-s-curve-misses-e",
                Agrees,
                &[
                    Near("contacts", 1.0, 0.0),
                    Above("contact_deg", 62.0),
                    Near("contact_deg", contact, 1e-5),
                ],
            ),
            // n° 42: the centre of gravity below the axle swings, above it falls.
            (
                "unicycle-stable-principle",
                Agrees,
                &[
                    Above("omega2_R1.2", 0.0),
                    Below("omega2_R0.5", 0.0),
                    Below("max_pitch_R1.2", 0.05 + 1e-9),
                    Above("max_pitch_R0.5", 1.0),
                ],
            ),
            // n° 42: the large wheel's threshold speed is not 5 % below the small one's.
            (
                "unicycle-big-wheel-lean-stability",
                DerivationDiffers,
                &[
                    AtMostTimes("small_threshold_m_per_s", 1.0 / 0.95, "big_threshold_m_per_s"),
                    Near("small_threshold_units", s2_small.sqrt(), rel(s2_small.sqrt(), 1e-9)),
                    Near("big_threshold_units", s2_big.sqrt(), rel(s2_big.sqrt(), 1e-9)),
                    Near(
                        "small_threshold_m_per_s",
                        speed(0.5, s2_small),
                        rel(speed(0.5, s2_small), 1e-9),
                    ),
                    Near(
                        "big_threshold_m_per_s",
                        speed(1.2, s2_big),
                        rel(speed(1.2, s2_big), 1e-9),
                    ),
                ],
            ),
            // n° 78.
            ("unicycle-78-product-is-36", Agrees, &[Below("max_rel_diff", 1e-9)]),
            (
                "unicycle-78-leading-positive",
                Agrees,
                &[Near("riders", 32.0, 0.0), Above("min_rel_coefficient", 0.0)],
            ),
            (
                "unicycle-78-l-sign",
                Agrees,
                &[
                    Above("envelope_ratio_L_pos", 1.01),
                    Below("envelope_ratio_L_neg", 0.99),
                    Near("envelope_ratio_L_0", 1.0, 0.02),
                    Near("oscillating", 1.0, 0.0),
                    Below("growth_per_period_L0.05", 1.1),
                    Above("growth_per_period_L0.05", 1.0),
                ],
            ),
            // n° 78: the factor mu1 R - mu h, and the large wheel's growth below the small one's.
            (
                "unicycle-78-big-wheel-remark",
                Agrees,
                &[
                    Near("factor_small", 5.0 * 0.5 - 60.0 * 1.25, 1e-12),
                    Near("factor_big", 12.0 * 1.2 - 60.0 * 1.10, 1e-12),
                    Exceeds("growth_small", "growth_big"),
                    Above("growth_big", 0.0),
                ],
            ),
        ],
    );
    // n° 32's practical region, falsified: with the rider's couple (B - C) n^2 sin cos of (E)
    // halved, n1 pivots at every point of the region and n2 stays usable above the band under
    // s = 1.
    let c = claims.iter().find(|c| c.id == "unicycle-practical-region").expect("n° 32");
    let f = c.falsification.as_ref().expect("n° 32's practical region states a perturbation");
    assert_eq!(f.verdict, Verdict::Agrees);
    assert_eq!(f.evidence["n1_usable"], 0.0);
    assert_eq!(f.evidence["n2_unusable"], 0.0);
    assert!(f.evidence["points_with_roots"] > 2000.0, "{:?}", f.evidence);
}
