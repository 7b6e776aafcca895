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
        (("41", "first member of n° 41 at theta = 20°"), MemoirError),
        (("41", "first member of n° 41 at theta = 40°"), MemoirError),
        (("41", "first member of n° 41 at theta = 50°"), MemoirError),
        (("41", "first member of n° 41 at theta = 60°"), MemoirError),
        (("41", "first member of n° 41 at theta = 70°"), MemoirError),
        (("41", "first zero of the first member (degrees)"), MemoirError),
        (("41", "junction point n"), MemoirError),
        (("41", "junction point s"), MemoirError),
        (("36", "first member (S): s^2 over constant term"), Ocr),
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
