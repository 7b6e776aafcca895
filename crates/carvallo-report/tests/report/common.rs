//! Helpers shared by the report tests: the check that a concordance's verdicts are the expected
//! ones (each listed finding has its verdict, every other entry agrees or is a rounding), that
//! every listed finding and section has an entry.

use std::collections::BTreeMap;

use carvallo_report::{Entry, Memoir, Verdict};

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

/// The policy's agreement of two formulas, as its preamble states it (`report.md`): written
/// here, not imported from the code under test, so that a tolerance loosened there fails here.
pub const AGREEMENT: f64 = 1e-12;

/// Every formula entry with a relative difference agrees exactly when that difference is within
/// [`AGREEMENT`] (the policy's formula rule).
pub fn assert_formulas_agree_within_tolerance(entries: &[Entry]) {
    for e in entries {
        if let (Some(rel), Memoir::Formula(_)) = (e.rel_diff, &e.memoir) {
            assert_eq!(
                e.verdict == Verdict::Agrees,
                rel <= AGREEMENT,
                "n° {} {}",
                e.section,
                e.quantity
            );
        }
    }
}

/// A condition a claim's evidence must meet for its verdict, with the threshold written in
/// the test (not imported from the code under test).
#[derive(Clone, Copy, Debug)]
pub enum Ev {
    /// `evidence[key] < bound`.
    Below(&'static str, f64),
    /// `evidence[key] > bound`.
    Above(&'static str, f64),
    /// `|evidence[key] - target| <= tol`.
    Near(&'static str, f64, f64),
    /// `evidence[a] > evidence[b]`.
    Exceeds(&'static str, &'static str),
    /// `|evidence[a] - evidence[b]| <= tol`.
    Equal(&'static str, &'static str, f64),
    /// `evidence[a] <= factor * evidence[b]`.
    AtMostTimes(&'static str, f64, &'static str),
}

/// Every claim has the verdict listed with its id and evidence meeting every listed
/// condition; the list names every claim and no other. All mismatches are reported at once.
pub fn assert_claim_evidence(
    claims: &[carvallo_report::Claim],
    expected: &[(&str, Verdict, &[Ev])],
) {
    let ids: Vec<&str> = claims.iter().map(|c| c.id.as_str()).collect();
    let listed: Vec<&str> = expected.iter().map(|e| e.0).collect();
    let (mut a, mut b) = (ids.clone(), listed.clone());
    a.sort_unstable();
    b.sort_unstable();
    assert_eq!(a, b, "claims against the list");
    let mut wrong = String::new();
    for (id, verdict, conditions) in expected {
        let c = claims.iter().find(|c| c.id == *id).expect("listed");
        if c.verdict != *verdict {
            wrong.push_str(&format!("{id}: {} not {}\n", c.verdict.as_str(), verdict.as_str()));
        }
        let get = |k: &str| c.evidence.get(k).copied().unwrap_or(f64::NAN);
        for cond in *conditions {
            let ok = match *cond {
                Ev::Below(k, x) => get(k) < x,
                Ev::Above(k, x) => get(k) > x,
                Ev::Near(k, x, tol) => (get(k) - x).abs() <= tol,
                Ev::Exceeds(p, q) => get(p) > get(q),
                Ev::Equal(p, q, tol) => (get(p) - get(q)).abs() <= tol,
                Ev::AtMostTimes(p, f, q) => get(p) <= f * get(q),
            };
            if !ok {
                wrong.push_str(&format!("{id}: {cond:?} fails on {}\n", c.evidence_text()));
            }
        }
    }
    assert!(wrong.is_empty(), "claims whose evidence does not carry the verdict:\n{wrong}");
}
