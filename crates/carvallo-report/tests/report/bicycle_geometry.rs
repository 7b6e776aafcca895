//! Tests of the bicycle geometry concordance (memoir n° 51–57): the expected verdict of the
//! entries that are findings, every table of the memoir present, and a snapshot of the text
//! table with numbers normalised to 4 significant digits.

use std::collections::BTreeMap;

use carvallo_report::bicycle::geometry::entries;
use carvallo_report::{render_text_normalised, Verdict};

use crate::common;

/// Entries whose verdict is not `agrees` or `rounding`, by (section, quantity). The n° 52–56
/// table findings agree with an independent recomputation (exact Newton solution of (1), (2)
/// in plain floating point, outside this workspace) made while the runtime was written: n° 52
/// sigma1 and mu1 at 60° and 80°, n° 53's 61.6°, n° 54's x - l at 60° and the sign of y,
/// n° 56's gamma = 20° column and the lost minus sign at theta = 30°, gamma = 40°.
fn findings() -> BTreeMap<(&'static str, &'static str), Verdict> {
    use Verdict::*;
    BTreeMap::from([
        (("51", "first-order sigma1 of (2)' vs the exact solution, gamma = 0..90°"), MemoirError),
        (("51", "bicycle geometry check first_order_coefficient_51_as_printed"), MemoirError),
        (("52", "table n° 52, gamma = 20°, sigma1 (minutes)"), MemoirError),
        (("52", "table n° 52, gamma = 60°, sigma1 (minutes)"), MemoirError),
        (("52", "table n° 52, gamma = 60°, mu1 (minutes)"), MemoirError),
        (("52", "table n° 52, gamma = 80°, mu (degrees)"), MemoirError),
        (("52", "table n° 52, gamma = 80°, mu1 (minutes)"), MemoirError),
        (("53", "gamma at the lowest frame position (degrees)"), MemoirError),
        (("53", "gamma at the lowest position with sigma = sigma0 (degrees)"), MemoirError),
        (("54", "table n° 54, gamma = 60°, x - l (cm)"), MemoirError),
        (("54", "table n° 54, gamma = 80°, x - l (cm)"), MemoirError),
        (("54", "table n° 54, gamma = 80°, -y (cm)"), MemoirError),
        (("54", "table n° 54, gamma = 90°, y as printed (cm)"), MemoirError),
        (("56", "table n° 56, gamma = 20°, theta = 10°, mu (degrees)"), MemoirError),
        (("56", "table n° 56, gamma = 20°, theta = 20°, mu (degrees)"), MemoirError),
        (("56", "table n° 56, gamma = 20°, theta = 30°, mu (degrees)"), MemoirError),
        (("56", "table n° 56, gamma = 20°, theta = 40°, mu (degrees)"), MemoirError),
        (("56", "table n° 56, gamma = 20°, theta = 50°, mu (degrees)"), MemoirError),
        (("56", "table n° 56, gamma = 40°, theta = 30°, mu (degrees)"), Ocr),
        (("56", "table n° 56, gamma = 60°, theta = 10°, mu (degrees)"), MemoirError),
        (("56", "table n° 56, gamma = 60°, theta = 20°, mu (degrees)"), MemoirError),
        (("56", "table n° 56, gamma = 60°, theta = 30°, mu (degrees)"), MemoirError),
    ])
}

#[test]
fn verdicts_are_the_expected_ones() {
    common::assert_verdicts(
        &entries(),
        &findings(),
        &["44", "46", "47", "48", "49", "50", "51", "52", "53", "54", "56", "57", "58"],
    );
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&entries());
    insta::with_settings!({
        description => "carvallo report: the bicycle geometry concordance table, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_geometry_report_text", text);
    });
}

/// The claims of this report ([`carvallo_report::claims`]): the verdict of each and the
/// evidence that carries it, with the thresholds of the memoir's statement written here.
#[test]
fn claims_have_the_expected_verdicts() {
    use common::Ev::*;
    let claims = carvallo_report::bicycle::geometry::claims();
    common::assert_claim_evidence(
        &claims,
        &[
            // n° 43: the axis meets CM (R = 0.38 m) when c / sin(sigma0) < R; trail positive.
            (
                "geometry-axis-crosses-contact-radius",
                Verdict::Agrees,
                &[
                    Below("crossing_below_C_m", 0.38),
                    Near("radius_m", 0.38, 0.0),
                    Above("trail_m", 0.0),
                ],
            ),
            // n° 44: at gamma = 90° the contact angle is zero and the frame lower than at rest.
            (
                "geometry-right-angle-turn-lowers-frame",
                Verdict::Agrees,
                &[Near("mu_rad", 0.0, 1e-12), Below("sigma_minus_sigma0_deg", 0.0)],
            ),
            // n° 52: mu0 off mu by "a few tenths of a degree", largest near the lowest frame.
            (
                "geometry-sigma1-barely-moves-mu",
                Verdict::Agrees,
                &[
                    Near("largest_mu_minus_mu0_deg", 0.3, 0.05),
                    Near("steer_of_largest_minus_sigma1_deg", 60.0, 5.0),
                ],
            ),
            // n° 53: the minimum of sigma is where E touches (61.856°), to the search's 1e-3°.
            (
                "geometry-lowest-frame-where-e-touches",
                Verdict::Agrees,
                &[
                    Equal("gamma_of_min_sigma_deg", "gamma_with_e_on_ground_deg", 1e-3),
                    Near("gamma_with_e_on_ground_deg", 61.855_887_779, 1e-8),
                    Near("sigma_min_minus_sigma_e_rad", 0.0, 1e-12),
                ],
            ),
        ],
    );
}

#[test]
fn claims_text_snapshot() {
    let text = carvallo_report::normalise_numbers(&carvallo_report::claims::render_claims_text(
        &carvallo_report::bicycle::geometry::claims(),
    ));
    insta::with_settings!({
        description => "carvallo report: the memoir's claims checked in the bicycle geometry report, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_geometry_claims_text", text);
    });
}
