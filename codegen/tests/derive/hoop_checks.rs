//! The hoop derivation's checks: every comparison with the memoir and every cross-check
//! between two derivation routes must hold, and the unmodified Lagrange equations (n° 71) must
//! fail to reproduce the ν- and σ-equations of n° 7 while reproducing the θ-equation.

use std::collections::BTreeSet;

use symbolica::atom::AtomCore;

/// Checks that must come out false (findings of the memoir, n° 71).
const EXPECTED_FALSE: [&str; 2] = ["lagrange_unmodified_nu", "lagrange_unmodified_sigma"];

/// Every check the derivation must make.
const EXPECTED_IDS: [&str; 46] = [
    "inertia_a_memoir",
    "inertia_b_memoir",
    "inertia_c_memoir",
    "revolution_relation",
    "principal_axes",
    "weight_moment_memoir",
    "inertia_moment_memoir",
    "power_identity",
    "system1_memoir",
    "system1_solved_memoir",
    "system2_memoir",
    "energy_conservation",
    "kinetic_energy_memoir",
    "correction_nu_memoir",
    "correction_sigma_memoir",
    "correction_nu_via_centre",
    "correction_sigma_via_momentum",
    "sigma_last_term_zero",
    "lagrange_equations_memoir",
    "lagrange_combinations",
    "lagrange_modified_agrees",
    "lagrange_unmodified_theta",
    "lagrange_unmodified_nu",
    "lagrange_unmodified_sigma",
    "equilibrium_memoir",
    "characteristic_factor",
    "stability_memoir",
    "stability_taylor_route",
    "stability_taylor_route_pqr",
    "minus_f1_memoir",
    "routh_thin_ring",
    "centre_force_memoir",
    "skid_memoir",
    "moment_conversion_memoir",
    "moment_compound_memoir",
    "moment_rolling_zero",
    "moment_weight_memoir",
    "equilibrium_direct_memoir",
    "equilibrium_direct_three_halves",
    "equilibrium_n12_memoir",
    "stability_n12_memoir",
    "skid_n12_memoir",
    "engine_kane_is_system2",
    "engine_lagrange_is_memoir_lagrange",
    "engine_energy",
    "engine_is_system1",
];

fn checks_hold_except_the_unmodified_lagrange_ones() {
    let d = crate::derived("hoop");
    let ids: Vec<&str> = d.checks.iter().map(|c| c.id.as_str()).collect();
    let unique: BTreeSet<&str> = ids.iter().copied().collect();
    assert_eq!(unique.len(), ids.len(), "check ids are unique: {ids:?}");
    let expected: BTreeSet<&str> = EXPECTED_IDS.iter().copied().collect();
    assert_eq!(unique, expected, "the set of checks");
    for c in &d.checks {
        let must_hold = !EXPECTED_FALSE.contains(&c.id.as_str());
        assert_eq!(
            c.holds, must_hold,
            "check {} (n° {}): {} — {}",
            c.id, c.section, c.statement, c.detail
        );
        assert!(!c.statement.is_empty() && !c.detail.is_empty(), "check {} documents itself", c.id);
        assert!(
            !c.statement.contains('\t') && !c.detail.contains('\n'),
            "check {} has tsv-safe text",
            c.id
        );
    }
}

fn unmodified_lagrange_misses_exactly_the_correction_terms() {
    let d = crate::derived("hoop");
    let find = |id: &str| d.checks.iter().find(|c| c.id == id).expect("check present");
    let nu = find("lagrange_unmodified_nu");
    assert!(nu.detail.contains("lacks the term -mu*R^2*p*s*cos(theta)"), "{}", nu.detail);
    let sigma = find("lagrange_unmodified_sigma");
    assert!(sigma.detail.contains("lacks the term mu*R^2*p*n*cos(theta)"), "{}", sigma.detail);
    assert!(!nu.detail.ends_with(": 0"), "{}", nu.detail);
    let theta = find("lagrange_unmodified_theta");
    assert!(theta.holds, "{}", theta.detail);
}

fn contract_names_and_order() {
    let d = crate::derived("hoop");
    assert_eq!(d.model, "hoop");
    assert_eq!(d.params, ["R", "g", "mu"]);
    assert_eq!(d.inputs, ["theta", "p", "q", "r", "n", "s"]);
    let names: Vec<&str> = d.formulas.iter().map(|f| f.name.as_str()).collect();
    let base = [
        "pqr_dp",
        "pqr_dq",
        "pqr_dr",
        "pns_dp",
        "pns_dn",
        "pns_ds",
        "energy",
        "inertia_a",
        "inertia_b",
        "inertia_c",
        "equilibrium",
        "stability",
        "skid",
        "equilibrium_direct",
        "equilibrium_n12",
        "stability_n12",
        "skid_n12",
    ];
    assert_eq!(&names[..base.len()], &base);
    for m in &names[base.len()..] {
        let stem = m.strip_prefix("memoir_").expect("the rest are memoir transcriptions");
        assert!(base.contains(&stem), "memoir output {m} has a derived counterpart");
    }
    // Which symbols each family of outputs may use (hoop model contract).
    let symbols = |name: &str| -> BTreeSet<String> {
        let f = d.formulas.iter().find(|f| f.name == name).expect("formula present");
        f.expr.get_all_symbols(false).iter().map(|s| s.get_stripped_name().to_string()).collect()
    };
    let allowed =
        |list: &[&str]| -> BTreeSet<String> { list.iter().map(|s| s.to_string()).collect() };
    for f in ["equilibrium_n12", "stability_n12", "skid_n12"] {
        assert!(symbols(f).is_subset(&allowed(&["theta", "s", "n"])), "{f} uses {:?}", symbols(f));
    }
    for f in ["pns_dp", "pns_dn", "pns_ds"] {
        assert!(
            symbols(f).is_subset(&allowed(&["theta", "p", "n", "s", "g", "R"])),
            "{f} uses {:?}",
            symbols(f)
        );
    }
    for f in ["pqr_dp", "pqr_dq", "pqr_dr"] {
        assert!(
            symbols(f).is_subset(&allowed(&["theta", "p", "q", "r", "g", "R"])),
            "{f} uses {:?}",
            symbols(f)
        );
    }
    assert!(symbols("energy").is_subset(&allowed(&["theta", "p", "n", "s", "mu", "g", "R"])));
    for f in ["equilibrium", "stability", "skid", "equilibrium_direct"] {
        assert!(
            symbols(f).is_subset(&allowed(&["theta", "n", "s", "g", "R"])),
            "{f} uses {:?}",
            symbols(f)
        );
    }
}

#[test]
fn checks_hold_except_the_unmodified_lagrange_ones_test() {
    crate::on_symbolica_thread(checks_hold_except_the_unmodified_lagrange_ones);
}

#[test]
fn unmodified_lagrange_misses_exactly_the_correction_terms_test() {
    crate::on_symbolica_thread(unmodified_lagrange_misses_exactly_the_correction_terms);
}

#[test]
fn contract_names_and_order_test() {
    crate::on_symbolica_thread(contract_names_and_order);
}
