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
