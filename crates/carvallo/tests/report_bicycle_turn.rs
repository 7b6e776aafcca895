//! Tests of the steady-turn stability concordance (memoir n° 101–105, module
//! `carvallo::report_bicycle_turn`): the expected verdicts (the findings listed), every
//! approximate coefficient judged against its declared second order consistently with its
//! relative difference, every section present, the old upright-only n° 105 entry gone, and a
//! snapshot of the text table with numbers normalised to 4 significant digits.

use carvallo::report::{normalise_numbers, render_text, Memoir, Verdict};
use carvallo::report_bicycle_turn::{entries, TURNS};

/// Entries whose verdict is `derivation-differs`, by (section, quantity prefix).
const FINDINGS: &[(&str, &str)] = &[
    ("103", "dn/dtheta at fixed gamma and s (1/s per rad), gamma = 5°, 20 km/h"),
    ("103", "dn/dtheta at fixed gamma and s (1/s per rad), gamma = 5°, 10 km/h"),
    ("104", "centrifugal part / gravity part of df/dtheta, gamma = 5°, 20 km/h"),
    ("104", "centrifugal part / gravity part of df/dtheta, gamma = 10°, 20 km/h"),
    ("104", "centrifugal part / gravity part of df/dtheta, gamma = 5°, 10 km/h"),
];

#[test]
fn verdicts_are_the_expected_ones() {
    let e = entries();
    // Two upright entries, then nine per turn.
    assert_eq!(e.len(), 2 + 9 * TURNS.len());
    for x in &e {
        let finding = FINDINGS.iter().any(|(s, q)| x.section == *s && x.quantity == *q);
        let expected = if finding {
            Verdict::DerivationDiffers
        } else if x.quantity.starts_with("df/dtheta upright") {
            Verdict::Rounding
        } else {
            Verdict::Agrees
        };
        assert_eq!(x.verdict, expected, "n° {} {}: {}", x.section, x.quantity, x.note);
        // Approximations: the verdict follows the relative difference and the stated order.
        if let (Some(rel), Memoir::Number(_), Some(order)) = (
            x.rel_diff,
            &x.memoir,
            x.note.split("theta0^2 + gamma^2 = ").nth(1).and_then(|t| t.parse::<f64>().ok()),
        ) {
            assert_eq!(x.verdict == Verdict::Agrees, rel <= order, "{}", x.quantity);
        }
    }
    for section in ["86", "101", "102", "103", "104", "105"] {
        assert!(e.iter().any(|x| x.section == section), "no entry for n° {section}");
    }
    let old = carvallo::report_bicycle_steady::entries();
    assert!(old.iter().all(|x| x.section != "105"), "the upright-only n° 105 entry is back");
}

#[test]
fn text_report_snapshot() {
    let text = normalise_numbers(&render_text(&entries()));
    insta::with_settings!({
        description => "carvallo report: steady turns with the handlebar held (n° 86, 101-105), numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_turn_report_text", text);
    });
}
