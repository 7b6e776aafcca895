//! Snapshots of every derived hoop formula, rendered as text next to the memoir's printed
//! formula and its section number, so that a change in a derivation shows up as a readable
//! diff. Expressions are printed in symbolica's canonical order (independent of the order in
//! which symbols were created) with the crate namespace stripped.

use carvallo_codegen::derive::hoop::memoir;
use symbolica::atom::AtomCore;

/// Canonical text of an expression, without the namespace prefixes.
fn canonical(e: &symbolica::atom::Atom) -> String {
    e.to_canonical_string()
        .replace("{}::", "")
        .replace("carvallo_codegen::", "")
        .replace("symbolica::", "")
        .replace("+-", "-")
}

/// The memoir formula each derived output is compared with (as printed, equations as
/// "first member − second member").
fn printed_for(name: &str) -> &'static [memoir::Printed] {
    use memoir as m;
    match name {
        "pqr_dp" => &[m::PQR_DP, m::SYSTEM1_I],
        "pqr_dq" => &[m::PQR_DQ, m::SYSTEM1_J],
        "pqr_dr" => &[m::PQR_DR, m::SYSTEM1_K],
        "pns_dp" => &[m::SYSTEM2_P],
        "pns_dn" => &[m::SYSTEM2_N],
        "pns_ds" => &[m::SYSTEM2_S],
        "energy" => &[m::TWICE_KINETIC, m::INERTIA_A, m::INERTIA_B, m::INERTIA_C],
        "inertia_a" => &[m::INERTIA_A],
        "inertia_b" => &[m::INERTIA_B],
        "inertia_c" => &[m::INERTIA_C],
        "equilibrium" => &[m::EQUILIBRIUM],
        "stability" => &[m::STABILITY],
        "skid" => &[m::SKID],
        "equilibrium_direct" => {
            &[m::MOMENT_CONVERSION, m::MOMENT_COMPOUND, m::MOMENT_WEIGHT, m::EQUILIBRIUM_DIRECT]
        }
        "equilibrium_n12" => &[m::EQUILIBRIUM_N12],
        "stability_n12" => &[m::STABILITY_N12],
        "skid_n12" => &[m::SKID_N12],
        _ => &[],
    }
}

fn every_derived_formula_matches_its_snapshot_body() {
    let d = crate::derived("hoop");
    let derived: Vec<_> = d.formulas.iter().filter(|f| !f.name.starts_with("memoir_")).collect();
    assert_eq!(derived.len(), 17, "number of derived (non-memoir) formulas");
    for f in derived {
        let printed = printed_for(&f.name);
        assert!(!printed.is_empty(), "formula {} has no memoir counterpart listed", f.name);
        let mut text = format!("{} (n° {})\nderived: {}\n", f.name, f.section, canonical(&f.expr));
        for p in printed {
            text.push_str(&format!("memoir n° {} {}: {}\n", p.section, p.id, p.text));
        }
        insta::with_settings!({
            description => f.description.clone(),
            omit_expression => true,
            prepend_module_to_snapshot => false,
        }, {
            insta::assert_snapshot!(format!("hoop_{}", f.name), text);
        });
    }
}

#[test]
fn every_derived_formula_matches_its_snapshot() {
    crate::on_symbolica_thread(every_derived_formula_matches_its_snapshot_body);
}
