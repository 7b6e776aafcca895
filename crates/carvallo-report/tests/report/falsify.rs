//! Falsifiability of the claims (issue 38): a claim whose check states a perturbation of the
//! derived side (a model ingredient moved, a coefficient scaled, a sign flipped; never the
//! printed value replaced) carries the verdict of the same check on the perturbed input
//! ([`carvallo_report::claims::Falsification`]), and that verdict must differ from its own. A
//! claim with none either says in its `how` why it holds by construction, or is in the
//! backlog below, by name, so that the count of checks not yet shown to fail can only fall.

use carvallo_report::{all_claims, Verdict};

/// Claims whose check states no breaking perturbation yet (the backlog of issue 38). A claim
/// leaves the list when it gains one ([`carvallo_report::Claim::falsified_by`]) or says why it
/// holds by construction.
const NOT_YET_FALSIFIED: &[&str] = &[];

/// The words a claim's `how` uses to explain that its check holds by construction.
const BY_CONSTRUCTION: &str = "Holds by construction because";

#[test]
fn every_stated_perturbation_breaks_its_check() {
    let claims = all_claims();
    let mut broken = 0usize;
    for c in &claims {
        let Some(f) = &c.falsification else { continue };
        assert!(
            f.breaks(c.verdict),
            "{}: the perturbation `{}` leaves the verdict `{}`",
            c.id,
            f.perturbation,
            c.verdict.as_str()
        );
        broken += 1;
    }
    // 145 claims state one (issue 38: 37 on branch claims2, then n° 97, then 58 more on branch
    // h38, then 39 more on branch claims3, then n° 98's three, then six of the unicycle on
    // branch hC, then n° 32's practical region): the count may only rise.
    assert!(broken >= 145, "only {broken} claims state a perturbation");
}

#[test]
fn every_claim_fails_under_a_perturbation_or_says_why_not() {
    let claims = all_claims();
    let mut missing: Vec<&str> = Vec::new();
    for c in &claims {
        let stated = c.falsification.is_some() || c.how.contains(BY_CONSTRUCTION);
        if !stated {
            missing.push(&c.id);
        }
        if stated {
            assert!(!NOT_YET_FALSIFIED.contains(&c.id.as_str()), "{}: leave the backlog", c.id);
        }
    }
    let agrees_missing = claims
        .iter()
        .filter(|c| c.verdict == Verdict::Agrees && missing.contains(&c.id.as_str()))
        .count();
    let mut expected: Vec<&str> = NOT_YET_FALSIFIED.to_vec();
    expected.sort_unstable();
    missing.sort_unstable();
    assert_eq!(
        missing, expected,
        "claims with no stated perturbation ({agrees_missing} of them `agrees`) differ from the backlog"
    );
}
