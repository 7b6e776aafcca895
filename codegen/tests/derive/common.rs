//! What every derivation test asserts of its checks.

use carvallo_codegen::Check;

/// The benchmark parameters of Meijaard et al. (2007), in the order of `whipple::PARAMS`.
pub const BENCHMARK: [f64; 26] = [
    1.02,
    0.08,
    std::f64::consts::PI / 10.0,
    9.81,
    0.3,
    2.0,
    0.0603,
    0.12,
    0.3,
    -0.9,
    85.0,
    9.2,
    11.0,
    2.8,
    2.4,
    0.9,
    -0.7,
    4.0,
    0.05892,
    0.06,
    0.00708,
    -0.00756,
    0.35,
    3.0,
    0.1405,
    0.28,
];

/// Every check holds except the findings named in `expected_false`, each of which is among the
/// checks and does not hold; the panic lists every check with the other outcome, with its
/// section and evidence.
pub fn assert_checks(checks: &[Check], expected_false: &[&str]) {
    let mut report = String::new();
    for c in checks {
        let expected = !expected_false.contains(&c.id.as_str());
        if c.holds != expected {
            report.push_str(&format!("{} {} holds={} {}\n", c.section, c.id, c.holds, c.detail));
        }
    }
    assert!(report.is_empty(), "unexpected check outcomes:\n{report}");
    for id in expected_false {
        assert!(checks.iter().any(|c| c.id == *id), "missing check {id}");
    }
}

/// The emitted program of `d` evaluated in f64 at `params` and `inputs`: each output's value by
/// name (a panic names an unknown output).
#[allow(dead_code)] // not every derivation test evaluates its program
pub fn outputs_at(
    d: &carvallo_codegen::Derivation,
    params: &[f64],
    inputs: &[f64],
) -> impl Fn(&str) -> f64 {
    let program = carvallo_codegen::emit::emit_program(d).expect("the derivation emits");
    let values = program.eval_f64(params, inputs).expect("the program evaluates");
    let names: Vec<String> = program.outputs.iter().map(|o| o.name.clone()).collect();
    move |name| {
        values[names.iter().position(|n| n == name).unwrap_or_else(|| panic!("no output {name}"))]
    }
}
