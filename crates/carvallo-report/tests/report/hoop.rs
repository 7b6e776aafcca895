//! Tests of the hoop concordance report: the expected verdict of every entry, the JSON keys,
//! and a snapshot of the text table with numbers normalised to 4 significant digits (values
//! below 1e-12 in magnitude, rounding noise, become `~0`).

use std::collections::BTreeMap;

use carvallo_report::{hoop_entries, render_json, render_text_normalised, Verdict};

/// The verdict each (section, quantity) must get.
fn expected() -> BTreeMap<(&'static str, &'static str), Verdict> {
    use Verdict::*;
    BTreeMap::from([
        (("4", "A / (mu R^2)"), Agrees),
        (("4", "B / (mu R^2)"), Agrees),
        (("4", "C / (mu R^2)"), Agrees),
        (("14/18", "upright threshold s^2 (units g/R)"), Agrees),
        (("18", "upright threshold s (units sqrt(g/R))"), Agrees),
        (("16", "V = sR at s = 1 (m/s), R = 0.50 m"), MemoirError),
        (("18", "threshold speed sR (m/s), R = 0.50 m"), MemoirError),
        (("14", "point F: x = cos(th)"), Rounding),
        (("14", "point F: y = s^2"), MemoirError),
        (("14", "vertical tangent of (S): t = x^2"), Rounding),
        (("14", "vertical tangent of (S): x = cos(th)"), Rounding),
        (("14", "vertical tangent of (S): th (degrees)"), MemoirError),
        (("14", "vertical tangent of (S): y = s^2"), Rounding),
        (("14", "vertical tangent of (S): s"), MemoirError),
        (("17", "point H: sin(th)"), Rounding),
        (("17", "point H: th (degrees)"), Rounding),
        (("17", "point H: s"), Rounding),
        (("71", "check lagrange_unmodified_nu"), Agrees),
        (("71", "check lagrange_unmodified_sigma"), Agrees),
    ])
}

#[test]
fn verdicts_are_the_expected_ones() {
    let entries = hoop_entries();
    let expected = expected();
    for ((section, quantity), verdict) in &expected {
        let entry = entries
            .iter()
            .find(|e| e.section == *section && e.quantity == *quantity)
            .unwrap_or_else(|| panic!("no entry for n° {section} {quantity}"));
        assert_eq!(entry.verdict, *verdict, "n° {section} {quantity}: {}", entry.note);
    }
    // Every section the report must cover is there.
    for section in ["4", "7", "7/8", "8", "9", "10", "11", "12", "14/18"] {
        assert!(entries.iter().any(|e| e.section == section), "no entry for n° {section}");
    }
    // The derivation reproduces every printed formula of n° 4 to 12 (the memoir's algebra
    // is right there), and every symbolic check has its expected outcome.
    for e in &entries {
        if matches!(e.memoir, carvallo_report::Memoir::Formula(_)) {
            assert_eq!(e.verdict, Verdict::Agrees, "n° {} {}: {}", e.section, e.quantity, e.note);
        }
    }
    // A formula entry agrees exactly when its largest relative difference is within tolerance.
    for e in &entries {
        if let (Some(rel), carvallo_report::Memoir::Formula(_)) = (e.rel_diff, &e.memoir) {
            let agrees = rel <= carvallo_report::AGREEMENT_TOLERANCE;
            assert_eq!(e.verdict == Verdict::Agrees, agrees, "n° {} {}", e.section, e.quantity);
        }
    }
}

#[test]
fn json_has_the_required_keys() {
    let json: serde_json::Value = serde_json::from_str(&render_json(&hoop_entries())).unwrap();
    let array = json.as_array().expect("a JSON array");
    assert!(array.len() >= 20);
    let verdicts = ["agrees", "rounding", "memoir-error", "ocr", "derivation-differs"];
    for item in array {
        let object = item.as_object().expect("an object");
        for key in ["section", "quantity", "memoir", "derived", "rel_diff", "verdict", "note"] {
            assert!(object.contains_key(key), "missing {key} in {item}");
        }
        // The eighth, optional: the comparison run on a perturbed derived side (issue 38).
        assert_eq!(object.len(), 7 + usize::from(object.contains_key("falsification")));
        if let Some(f) = object.get("falsification") {
            assert!(f["perturbation"].is_string() && f["evidence"].is_object(), "{f}");
            assert!(verdicts.contains(&f["verdict"].as_str().unwrap()));
        }
        assert!(verdicts.contains(&object["verdict"].as_str().unwrap()));
        assert!(object["memoir"].is_number() || object["memoir"].is_string());
        assert!(object["derived"].is_number() || object["derived"].is_object());
        assert!(object["rel_diff"].is_number() || object["rel_diff"].is_null());
    }
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&hoop_entries());
    insta::with_settings!({
        description => "carvallo report: the hoop concordance table, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("hoop_report_text", text);
    });
}

#[test]
fn claims_snapshot() {
    let text = carvallo_report::normalise_numbers(&carvallo_report::claims::render_claims_text(
        &carvallo_report::hoop::claims(),
    ));
    insta::with_settings!({
        description => "carvallo report: the hoop's claims n° 1-12 and 71-78, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("hoop_claims_text", text);
    });
}

/// The key verdicts of the hoop's claims, asserted directly (the snapshot fixes the rest).
#[test]
fn claims_verdicts() {
    let claims = carvallo_report::hoop::claims();
    let get =
        |id: &str| claims.iter().find(|c| c.id == id).unwrap_or_else(|| panic!("no claim {id}"));
    for c in &claims {
        let expected = if c.id == "hoop-linear-criterion-sufficient" {
            Verdict::MemoirError
        } else {
            Verdict::Agrees
        };
        assert_eq!(c.verdict, expected, "{}: {}", c.id, c.evidence_text());
    }
    // n° 76: the general sufficiency fails in Lyapunov's critical case, the hoop's runs stay
    // bounded.
    let e = &get("hoop-linear-criterion-sufficient").evidence;
    assert_eq!(e["hoop: bounded"], e["hoop: stable_cases"]);
    assert!(e["critical case: amplitude of x'' + x = +x^2 x'"] >= 1.0);
    // The fall laws are first-order: their error falls with the release.
    for id in ["hoop-fall-law-pendular", "hoop-fall-law-exponential", "hoop-fall-law-uniform"] {
        let e = &get(id).evidence;
        assert!(
            e["rel_err_delta_1e-3"] < 0.02 && e["rel_err_delta_1e-3"] < e["rel_err_delta_2e-3"]
        );
    }
    let s = &get("hoop-stability-condition").evidence;
    assert_eq!(s["outcomes_agreeing"], s["cases"]);
    assert!(s["stable_by_S"] < s["cases"], "the sample must hold unstable states too");
    assert!(get("hoop-characteristic-roots").evidence["max_rel_diff_rate_vs_sqrt_abs_K"] < 1e-3);
    assert_eq!(get("hoop-lagrange-interchange").evidence["nu_unmodified_holds"], 0.0);
}
