//! Tests of the rest-position concordance (memoir n° 67, module
//! `carvallo_report::bicycle::rest`): the expected verdicts (the findings listed), each lean's
//! verdict following its handlebar shift and the memoir's negligible 0°,6, the entries present
//! in the full report, and a snapshot of the text table with numbers normalised to 4
//! significant digits.

use carvallo_report::bicycle::rest::{entries, LEANS, NEGLIGIBLE_DEG};
use carvallo_report::{render_text_normalised, Derived, Verdict};

#[test]
fn verdicts_are_the_expected_ones() {
    let e = entries();
    // One entry per lean, the direction, the stiffnesses, the normal position and the limit.
    assert_eq!(e.len(), LEANS.len() + 4);
    for x in &e {
        assert_eq!(x.section, "67");
        let expected = if x.quantity.starts_with("stiffness") || x.quantity.starts_with("direction")
        {
            Verdict::Agrees
        } else {
            // The handlebar turns several degrees beyond the frame's lowest position.
            Verdict::DerivationDiffers
        };
        assert_eq!(x.verdict, expected, "{}: {}", x.quantity, x.note);
        if let Derived::Numbers(n) = &x.derived {
            if let Some(shift) = n.get("difference_deg") {
                assert_eq!(x.verdict == Verdict::Agrees, shift.abs() <= NEGLIGIBLE_DEG);
                assert!(*shift > 0.0 && n["frame_rise_mm"] > 0.0 && n["wheel_drop_mm"] > 0.0);
            }
        }
    }
    let all = carvallo_report::all_entries();
    assert_eq!(all.iter().filter(|x| x.section == "67").count(), e.len());
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&entries());
    insta::with_settings!({
        description => "carvallo report: the handlebar's rest position at a lean (n° 67), numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_rest_report_text", text);
    });
}
