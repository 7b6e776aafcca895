//! Tests of the concordance of memoir n° 116–123 (the bicycle without hands near straight
//! running): the expected verdict of every entry that is a finding, every other entry agreeing
//! or a slide-rule rounding, and a snapshot of the text table with numbers normalised to 4
//! significant digits.

use std::collections::BTreeMap;

use carvallo_report::bicycle::straight::entries;
use carvallo_report::{render_text_normalised, Verdict};

use crate::common;

/// Entries whose verdict is not `agrees` or `rounding`, by (section, quantity).
fn findings() -> BTreeMap<(&'static str, &'static str), Verdict> {
    use Verdict::*;
    BTreeMap::from([
        (("116", "table (δθ) frame, γ''"), Ocr),
        (("116", "table (δθ) front wheel, γ''"), Ocr),
        (("116", "table (δγ) frame, γ''"), Ocr),
        (("116", "table (δγ) rear wheel, γ''"), Ocr),
        (("116", "table (δγ) front wheel, γ''"), Ocr),
        (("116", "bicycle straight check fall_frame_gamma2_as_printed"), Ocr),
        (("116", "bicycle straight check fall_front_wheel_gamma2_as_printed"), Ocr),
        (("116", "bicycle straight check bar_frame_gamma2_as_printed"), Ocr),
        (("116", "bicycle straight check bar_rear_wheel_gamma2_as_printed"), Ocr),
        (("116", "bicycle straight check bar_front_wheel_gamma2_as_printed"), Ocr),
        (("117", "B, coefficient of s^2"), MemoirError),
        (("117", "A1' / s"), MemoirError),
        (("117", "B1' / s"), MemoirError),
        (("117", "B1' first term"), Ocr),
        (("119", "(⊖) coefficient of λ^3"), Ocr),
        (("119", "(⊖) coefficient of λ^2"), Ocr),
        (("119", "(⊖) coefficient of λ"), Ocr),
        (("120", "λ coefficient, 1/s^2 part 4.83"), MemoirError),
        (("120", "s^2 annulling the λ coefficient, 37.05"), MemoirError),
        (("121", "μ^2 = a3 / a1"), Ocr),
        (("121", "equation (6), coefficient of s^2: -64.6"), MemoirError),
        (("121", "equation (6), constant: -179.1"), MemoirError),
        (("121", "lower limit s^2 = 67.3 from (5)"), MemoirError),
        (("121", "lower limit speed 10 km/h"), MemoirError),
        (("122", "ratio s'^2/s^2 of the three-factor formula"), MemoirError),
        (("124", "(δν) virtual work on inclined ground, as printed"), Ocr),
        (("124", "(δσ) virtual work on inclined ground"), MemoirError),
    ])
}

#[test]
fn verdicts_are_the_expected_ones() {
    let entries = entries();
    common::assert_verdicts(&entries, &findings(), &[]);
    // The concordance with the general model is the central finding: it must agree.
    let c = entries.iter().find(|e| e.section == "116" && e.quantity.starts_with("the twelve"));
    assert_eq!(c.map(|e| e.verdict), Some(Verdict::Agrees), "{c:?}");
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&entries());
    insta::with_settings!({
        description => "carvallo report: memoir n° 116-123, the bicycle without hands near straight running, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_straight_report_text", text);
    });
}
