//! Tests of the hoop-discussion concordance (memoir n° 13–19): the expected verdict of the
//! entries whose verdict is not `agrees`, the sign checks of n° 19, and a snapshot of the text
//! table with numbers normalised to 4 significant digits (values below 1e-12 become `~0`).

use carvallo_report::hoop_discussion::{entries, n12_forms_agree, point_entries};
use carvallo_report::{render_text_normalised, Verdict};

#[test]
fn verdicts_are_the_expected_ones() {
    assert!(n12_forms_agree());
    let mut all = point_entries(true);
    all.extend(entries());
    let expected = [
        ("14", "point F: y = s^2", Verdict::MemoirError),
        ("14", "vertical tangent of (S): th (degrees)", Verdict::MemoirError),
        ("14", "vertical tangent of (S): s", Verdict::MemoirError),
        ("14", "residual of the u equation at u = -0,10807", Verdict::MemoirError),
        ("15", "s0 (table of variations)", Verdict::MemoirError),
        ("15", "check s0_table_memoir", Verdict::MemoirError),
        ("16", "g R implied by V = 2,40 m/s (m^2/s^2)", Verdict::MemoirError),
        ("19", "(6): cosh ht", Verdict::Ocr),
        ("19", "n opposite to th \"dans les trois cas\" (M1 term)", Verdict::MemoirError),
    ];
    for (section, quantity, verdict) in expected {
        let e = all
            .iter()
            .find(|e| e.section == section && e.quantity == quantity)
            .unwrap_or_else(|| panic!("no entry n° {section} {quantity}"));
        assert_eq!(e.verdict, verdict, "n° {section} {quantity}: {}", e.note);
    }
    // Nothing is left unexplained.
    for e in &all {
        assert_ne!(
            e.verdict,
            Verdict::DerivationDiffers,
            "n° {} {}: {}",
            e.section,
            e.quantity,
            e.note
        );
    }
    for section in ["13", "14", "15", "16", "17", "18", "19"] {
        assert!(all.iter().any(|e| e.section == section), "no entry for n° {section}");
    }
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&entries());
    insta::with_settings!({
        description => "carvallo report: the hoop discussion n° 13-19, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("hoop_discussion_report_text", text);
    });
}

#[test]
fn claims_snapshot() {
    let text = carvallo_report::normalise_numbers(&carvallo_report::claims::render_claims_text(
        &carvallo_report::hoop_discussion::claims(),
    ));
    insta::with_settings!({
        description => "carvallo report: the hoop discussion's claims n° 13-19, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("hoop_discussion_claims_text", text);
    });
}

/// The key verdicts of the discussion's claims, asserted directly.
#[test]
fn claims_verdicts() {
    let claims = carvallo_report::hoop_discussion::claims();
    let get =
        |id: &str| claims.iter().find(|c| c.id == id).unwrap_or_else(|| panic!("no claim {id}"));
    let findings = [
        ("hoop-graeffe-table-cells", Verdict::MemoirError),
        ("hoop-graeffe-separated", Verdict::Rounding),
        ("hoop-n1-skid-region", Verdict::Ocr),
    ];
    for c in &claims {
        let expected = findings.iter().find(|(id, _)| *id == c.id).map_or(Verdict::Agrees, |f| f.1);
        assert_eq!(c.verdict, expected, "{}: {}", c.id, c.evidence_text());
    }
    let w = &get("hoop-which-root-stable").evidence;
    assert_eq!(w["sign_disagreements"], 0.0);
    assert!(w["inside_S"] > 0.0 && w["simulated_roots"] > 0.0);
    // Half a thousandth: true of the equation's residual, not of the root u.
    let h = &get("hoop-root-squaring-half-thousandth").evidence;
    assert!(
        h["exact_residual_over_14u"] < 5e-4 && h["rel_error_t"] < 5e-4 && h["rel_error_u"] > 1e-3
    );
    // The Horner tableau is exact; the root-squaring table has two unfaithful cells (784^2).
    assert_eq!(get("hoop-horner-tableau-cells").evidence["cells_differing"], 0.0);
    let g = &get("hoop-graeffe-table-cells").evidence;
    assert_eq!(g["cells"] - g["faithful_to_his_arithmetic"], 2.0);
    assert!(get("hoop-no-skid-normal-play").evidence["max_abs_D_n2"] < 0.5);
}
