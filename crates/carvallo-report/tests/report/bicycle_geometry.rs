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

/// The claims of this report ([`carvallo_report::claims`]): the expected verdict of each.
fn expected_claims() -> BTreeMap<&'static str, Verdict> {
    BTreeMap::from([
        ("geometry-axis-crosses-contact-radius", Verdict::Agrees),
        ("geometry-right-angle-turn-lowers-frame", Verdict::Agrees),
        ("geometry-sigma1-barely-moves-mu", Verdict::Agrees),
        ("geometry-lowest-frame-where-e-touches", Verdict::Agrees),
    ])
}

#[test]
fn claims_have_the_expected_verdicts() {
    let claims = carvallo_report::bicycle::geometry::claims();
    common::assert_claim_verdicts(&claims, &expected_claims());
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
