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

/// The claims of this report ([`carvallo_report::claims`]): the expected verdict of each.
fn expected_claims() -> BTreeMap<&'static str, Verdict> {
    BTreeMap::from([
        ("kinematics-upright-rest-unstable", Verdict::Agrees),
        ("kinematics-rider-low-and-forward", Verdict::Agrees),
    ])
}

#[test]
fn claims_have_the_expected_verdicts() {
    let claims = carvallo_report::bicycle::kinematics::claims();
    common::assert_claim_verdicts(&claims, &expected_claims());
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
