//! The discussion of n° 13–19 (model `hoop_discussion`): every symbolic check has its expected
//! outcome, and each derived polynomial or curve is snapshotted next to the memoir's printed
//! one.

use crate::common;

use carvallo_codegen::derive::hoop::discussion::printed;
use symbolica::atom::AtomCore;

/// Canonical text of an expression, without the namespace prefixes.
fn canonical(e: &symbolica::atom::Atom) -> String {
    e.to_canonical_string()
        .replace("{}::", "")
        .replace("carvallo_codegen::", "")
        .replace("symbolica::", "")
        .replace("+-", "-")
}

fn discussion_derivation_body() {
    let d = crate::derived("hoop_discussion");
    // Checks: all hold except the table's s0 (a misprint of the memoir, n° 15).
    common::assert_checks(&d.checks, &["s0_table_memoir"]);
    let find = |name: &str| {
        d.formulas.iter().find(|f| f.name == name).unwrap_or_else(|| panic!("no formula {name}"))
    };
    for (name, printed) in [
        ("reality_curve", printed::REALITY),
        ("curve_s", printed::CURVE_S),
        ("curve_s_raw", printed::CURVE_S),
        ("curve_s1_y", printed::CURVE_S1_Y),
        ("quartic_f", printed::QUARTIC_F),
        ("quartic_u", printed::QUARTIC_U),
        ("vertical_t", "(root of F in (0.8, 1); memoir: 0,89193)"),
        ("point_f_x", "0,917"),
        ("point_f_y", "0,258"),
        ("s_of_n", printed::S_OF_N),
        ("s0", printed::S0),
        ("skid_of_n", printed::SKID_OF_N),
        ("s2_of_d", printed::S2_OF_D),
        ("curve_n_s2", printed::CURVE_N_S2),
        ("h_cubic", "(not printed: cubic in sin(theta), root sin = 0,322)"),
        ("stick_theta", printed::STICK_6),
        ("stick_n", printed::STICK_7),
    ] {
        let f = find(name);
        let text = format!(
            "n° {}: {}\nderived: {}\nprinted: {}\n",
            f.section,
            f.description,
            canonical(&f.expr),
            printed
        );
        insta::with_settings!({
            description => format!("hoop_discussion formula {name} beside the memoir"),
            omit_expression => true,
        }, {
            insta::assert_snapshot!(format!("hoop_discussion_{name}"), text);
        });
    }
    let checks: String =
        d.checks.iter().map(|c| format!("{} {} {}\n", c.section, c.id, c.holds)).collect();
    insta::with_settings!({
        description => "hoop_discussion check outcomes",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("hoop_discussion_checks", checks);
    });
}

#[test]
fn discussion_derivation() {
    crate::on_symbolica_thread(discussion_derivation_body);
}
