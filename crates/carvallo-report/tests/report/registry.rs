//! The registry of reports (`carvallo_report::REPORTS`) mirrors the models of the library: one
//! report per generated artifact, named alike, and nothing in the concordance outside it.

use carvallo::artifacts::MODELS;
use carvallo_report::{all_entries, REPORTS};

/// Reports with no artifact of their own name: they evaluate other models' programs.
const BUILT_ON_OTHER_MODELS: [(&str, &str); 2] = [
    ("bicycle_turn", "the nonlinear Carvallo–Whipple model (whipple_nonlinear)"),
    ("bicycle_rest", "the geometry and kinematics of Part II"),
];

/// Artifacts whose symbolic checks are not (yet) entries of the concordance.
const NOT_IN_THE_CONCORDANCE: [&str; 1] = ["whipple_nonlinear"];

#[test]
fn one_report_per_model() {
    let mut names: Vec<&str> = REPORTS.iter().map(|r| r.model).collect();
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), REPORTS.len(), "a model is registered twice");
    for r in &REPORTS {
        let has_artifact = MODELS.iter().any(|a| a.model == r.model);
        let built_on_others = BUILT_ON_OTHER_MODELS.iter().any(|(m, _)| *m == r.model);
        assert!(has_artifact != built_on_others, "{}: artifact {has_artifact}", r.model);
    }
    for a in &MODELS {
        let reported = REPORTS.iter().any(|r| r.model == a.model);
        assert!(reported != NOT_IN_THE_CONCORDANCE.contains(&a.model), "{}", a.model);
    }
}

#[test]
fn the_concordance_is_the_registry() {
    let total: usize = REPORTS.iter().map(|r| (r.entries)().len()).sum();
    assert_eq!(all_entries().len(), total);
}

/// Every assertion of an inventory is covered by what it names: a claim of that id in the same
/// report, or a value entry of the same n° whose quantity contains the text; every claim is
/// cited by exactly one assertion of its report's inventory, and ids are unique.
#[test]
fn every_inventory_names_what_covers_it() {
    use carvallo_report::Status;
    let mut ids: Vec<String> = Vec::new();
    for r in &REPORTS {
        let claims = (r.claims)();
        let entries = (r.entries)();
        for a in r.inventory {
            match a.status {
                Status::Checked(id) => {
                    let c = claims.iter().find(|c| c.id == id);
                    let c = c.unwrap_or_else(|| {
                        panic!("{}: n° {}: no claim `{id}`", r.model, a.section)
                    });
                    assert_eq!(c.section, a.section, "{}: claim `{id}`", r.model);
                }
                Status::Value(quantity) => assert!(
                    entries.iter().any(|e| e.section == a.section && e.quantity.contains(quantity)),
                    "{}: n° {}: no entry whose quantity contains `{quantity}`",
                    r.model,
                    a.section
                ),
                Status::Left(why) => {
                    assert!(!why.trim().is_empty(), "{}: n° {}", r.model, a.section)
                }
            }
            assert!(!a.says.trim().is_empty(), "{}: n° {}", r.model, a.section);
        }
        for c in &claims {
            let cited = r
                .inventory
                .iter()
                .filter(|a| matches!(a.status, Status::Checked(id) if id == c.id))
                .count();
            assert_eq!(cited, 1, "{}: claim `{}` cited {cited} times", r.model, c.id);
            assert!(!c.how.trim().is_empty() && !c.claim.trim().is_empty(), "{}", c.id);
            ids.push(c.id.clone());
        }
    }
    let n = ids.len();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), n, "a claim id is used twice");
}

#[test]
fn the_claims_are_the_registry() {
    let total: usize = REPORTS.iter().map(|r| (r.claims)().len()).sum();
    assert_eq!(carvallo_report::all_claims().len(), total);
    let found: usize = REPORTS.iter().map(|r| r.inventory.len()).sum();
    assert_eq!(carvallo_report::all_assertions().len(), found);
}
