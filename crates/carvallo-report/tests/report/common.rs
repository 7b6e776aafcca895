//! Helpers shared by the report tests: the check that a concordance's verdicts are the expected
//! ones (each listed finding has its verdict, every other entry agrees or is a rounding), that
//! every listed finding and section has an entry.

use std::collections::BTreeMap;

use carvallo_report::{Entry, Memoir, Verdict, AGREEMENT_TOLERANCE};

/// Asserts the verdicts of `entries`: an entry listed in `findings` by (section, quantity) has
/// the listed verdict, any other entry is `agrees` or `rounding`; every finding and every
/// section of `sections` has an entry. All mismatches are reported at once.
pub fn assert_verdicts(
    entries: &[Entry],
    findings: &BTreeMap<(&str, &str), Verdict>,
    sections: &[&str],
) {
    let mut unexpected = String::new();
    for e in entries {
        let ok = match findings.get(&(e.section.as_str(), e.quantity.as_str())) {
            Some(v) => e.verdict == *v,
            None => matches!(e.verdict, Verdict::Agrees | Verdict::Rounding),
        };
        if !ok {
            unexpected.push_str(&format!(
                "n° {} {}: {} ({:?}; {})\n",
                e.section,
                e.quantity,
                e.verdict.as_str(),
                e.derived,
                e.note
            ));
        }
    }
    assert!(unexpected.is_empty(), "unexpected verdicts:\n{unexpected}");
    for (s, q) in findings.keys() {
        assert!(entries.iter().any(|e| e.section == *s && e.quantity == *q), "no entry n° {s} {q}");
    }
    for section in sections {
        assert!(entries.iter().any(|e| e.section == *section), "no entry for n° {section}");
    }
}

/// Every formula entry with a relative difference agrees exactly when that difference is within
/// [`AGREEMENT_TOLERANCE`] (the policy's formula rule).
pub fn assert_formulas_agree_within_tolerance(entries: &[Entry]) {
    for e in entries {
        if let (Some(rel), Memoir::Formula(_)) = (e.rel_diff, &e.memoir) {
            assert_eq!(
                e.verdict == Verdict::Agrees,
                rel <= AGREEMENT_TOLERANCE,
                "n° {} {}",
                e.section,
                e.quantity
            );
        }
    }
}

/// Every claim of a report has the verdict `expected` gives its id, and `expected` names no
/// other claim.
pub fn assert_claim_verdicts(
    claims: &[carvallo_report::Claim],
    expected: &BTreeMap<&'static str, Verdict>,
) {
    let ids: Vec<&str> = claims.iter().map(|c| c.id.as_str()).collect();
    assert_eq!(claims.len(), expected.len(), "claims: {ids:?}");
    for c in claims {
        assert_eq!(
            expected.get(c.id.as_str()),
            Some(&c.verdict),
            "{}: {}",
            c.id,
            c.evidence_text()
        );
    }
}
