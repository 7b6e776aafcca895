//! Tests of the bicycle kinematics concordance (memoir n° 59–69): the expected verdict of the
//! entries that are findings, every section present, and a snapshot of the text table with
//! numbers normalised to 4 significant digits.

use std::collections::BTreeMap;

use carvallo_report::bicycle::kinematics::entries;
use carvallo_report::{render_text_normalised, Verdict};

use crate::common;

/// Entries whose verdict is not `agrees` or `rounding`, by (section, quantity).
fn findings() -> BTreeMap<(&'static str, &'static str), Verdict> {
    use Verdict::*;
    BTreeMap::from([
        (("61", "bicycle kinematics check variation_h_61_as_printed"), Ocr),
        (("64", "bicycle kinematics check relation_dnu_64_as_printed"), Ocr),
        (("69", "bicycle kinematics check mu_prime_9_69"), MemoirError),
        (("69", "bicycle kinematics check eta_second_69_as_printed"), MemoirError),
        (("69", "eta'' at the rest equilibrium (1/rad)"), MemoirError),
        (("69", "steer of the rest equilibrium, the lowest frame position (degrees)"), MemoirError),
    ])
}

#[test]
fn verdicts_are_the_expected_ones() {
    common::assert_verdicts(
        &entries(),
        &findings(),
        &["59", "61", "62", "63", "64", "65", "66", "66 bis", "68", "69"],
    );
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&entries());
    insta::with_settings!({
        description => "carvallo report: the bicycle kinematics concordance table, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_kinematics_report_text", text);
    });
}

/// The claims of this report ([`carvallo_report::claims`]): the verdict of each and the
/// evidence that carries it, with the thresholds written here.
#[test]
fn claims_have_the_expected_verdicts() {
    use common::Ev::*;
    let claims = carvallo_report::bicycle::kinematics::claims();
    common::assert_claim_evidence(
        &claims,
        &[
            // n° 69: upright rest is a maximum of the height (d2Z/dtheta2 = -Z < 0), eta fixed;
            // second differences of step 1e-3 agree with -Z to their truncation, 1e-5.
            (
                "kinematics-upright-rest-unstable",
                Verdict::Agrees,
                &[
                    Below("d2z_dtheta2", 0.0),
                    Equal("d2z_dtheta2", "minus_z", 1e-5),
                    Near("eta_drift_at_0_3_rad", 0.0, 1e-12),
                ],
            ),
            // n° 69: lowering or moving the rider forward raises d2Z (less unstable); at M
            // (Z = 0) it is positive, at the illustrative centre negative.
            (
                "kinematics-rider-low-and-forward",
                Verdict::Agrees,
                &[
                    Exceeds("d2z_lower", "d2z_illustrative"),
                    Exceeds("d2z_forward", "d2z_illustrative"),
                    Above("d2z_at_m", 0.0),
                    Below("d2z_illustrative", 0.0),
                ],
            ),
        ],
    );
}

#[test]
fn claims_text_snapshot() {
    let text = carvallo_report::normalise_numbers(&carvallo_report::claims::render_claims_text(
        &carvallo_report::bicycle::kinematics::claims(),
    ));
    insta::with_settings!({
        description => "carvallo report: the memoir's claims checked in the bicycle kinematics report, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_kinematics_claims_text", text);
    });
}
