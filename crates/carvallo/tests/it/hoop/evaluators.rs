//! Cross-checks of the generated hoop evaluators against the two independent evaluation paths
//! of `carvallo_ir`: the `f64` interpreter (same program, same operations, run by a loop over
//! the instructions) and the 256-bit evaluation (`carvallo_ir::hp`), on seeded random inputs.
//!
//! Tolerances, stated once:
//! * generated vs interpreter: both evaluate the same straight-line program in `f64`; the macro
//!   may fold constants after fixing parameters, so the results may differ by a few roundings:
//!   $|a - b| \le 4\epsilon\,\max(|b|, \text{scale})$ with scale the largest magnitude of that
//!   output over the sample (so values that cancel to near zero are compared absolutely;
//!   observed: identical bits).
//! * generated vs 256-bit: the `f64` rounding error of programs of a few dozen operations whose
//!   terms are of the size of the scale, one rounding each, partly cancelling:
//!   $|a - b| \le 2\cdot10^{-15}\,\max(|b|, \text{scale})$, some twenty roundings (observed:
//!   below $2.3\cdot10^{-16}$).

use carvallo::hoop;
use carvallo::ir::{hp, Program};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const IR: &str = carvallo::artifacts::HOOP.ir;
const POINTS: usize = 200;
const TOL_INTERP: f64 = 4.0 * f64::EPSILON;
const TOL_HP: f64 = 2e-15;

carvallo::scene! {
    /// A scene with fixed parameters: R = 0.5 m, g = 9.81 m/s².
    mod fixed_scene {
        model: hoop,
        fixed: { R: 0.5, g: 9.81 },
        outputs: [stability, equilibrium, pns_dp],
    }
}

/// A value for the named parameter or input, in the physical domain of the report.
fn sample(name: &str, rng: &mut ChaCha8Rng) -> f64 {
    match name {
        "R" => rng.gen_range(0.2..1.0),
        "g" => rng.gen_range(1.0..25.0),
        "mu" => rng.gen_range(0.1..5.0),
        "theta" => {
            let t: f64 = rng.gen_range(0.05..1.3);
            if rng.gen_bool(0.5) {
                t
            } else {
                -t
            }
        }
        _ => rng.gen_range(-10.0..10.0),
    }
}

/// Compares one scene (given by its consts and `eval_array`) with the interpreter and the
/// 256-bit evaluation of the same program, returning the largest scaled differences.
fn check_scene<const N: usize, const M: usize>(
    scene: &str,
    params: &[&str],
    inputs: &[&str],
    outputs: &[&str],
    fixed: &[(&str, f64)],
    eval_array: fn(&[f64; N]) -> [f64; M],
    seed: u64,
) -> (f64, f64) {
    let full = Program::parse(IR).expect("generated/hoop.ir parses");
    let program = full
        .fix_params(fixed)
        .and_then(|p| p.select_outputs(outputs))
        .expect("the scene's outputs and fixed parameters exist");
    assert_eq!(program.params, params, "{scene}: free parameters");
    assert_eq!(program.inputs, inputs, "{scene}: inputs");
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut rows = Vec::new();
    for _ in 0..POINTS {
        let args: [f64; N] =
            std::array::from_fn(|i| sample(params.iter().chain(inputs).nth(i).unwrap(), &mut rng));
        let generated = eval_array(&args);
        let interp = program.eval_f64(&args[..params.len()], &args[params.len()..]).unwrap();
        let high =
            hp::eval_f64(&program, &args[..params.len()], &args[params.len()..], 256).unwrap();
        rows.push((generated, interp, high));
    }
    let mut worst = (0.0_f64, 0.0_f64);
    for k in 0..M {
        let scale = rows.iter().map(|r| r.2[k].abs()).fold(0.0, f64::max);
        for (generated, interp, high) in &rows {
            let (g, i, h) = (generated[k], interp[k], high[k]);
            let d_interp = (g - i).abs() / i.abs().max(scale);
            let d_hp = (g - h).abs() / h.abs().max(scale);
            assert!(
                d_interp <= TOL_INTERP,
                "{scene}.{}: generated {g} vs interpreter {i}",
                outputs[k]
            );
            assert!(d_hp <= TOL_HP, "{scene}.{}: generated {g} vs 256-bit {h}", outputs[k]);
            worst = (worst.0.max(d_interp), worst.1.max(d_hp));
        }
    }
    worst
}

macro_rules! check {
    ($module:path, $seed:expr) => {{
        use $module as m;
        check_scene(
            stringify!($module),
            m::PARAMS,
            m::INPUTS,
            m::OUTPUTS,
            m::FIXED,
            m::eval_array,
            $seed,
        )
    }};
}

#[test]
fn generated_scenes_match_interpreter_and_high_precision() {
    let results = [
        check!(hoop::pqr_scene, 1),
        check!(hoop::pns_scene, 2),
        check!(hoop::energy_scene, 3),
        check!(hoop::inertia_scene, 4),
        check!(hoop::equilibrium_scene, 5),
        check!(hoop::stability_scene, 6),
        check!(hoop::skid_scene, 7),
        check!(hoop::equilibrium_n12_scene, 8),
        check!(hoop::stability_n12_scene, 9),
        check!(hoop::skid_n12_scene, 10),
        check!(fixed_scene, 11),
    ];
    for (i, (interp, high)) in results.iter().enumerate() {
        eprintln!(
            "scene {i}: max scaled difference vs interpreter {interp:.1e}, vs 256-bit {high:.1e}"
        );
    }
}

#[test]
fn fixed_scene_takes_only_free_arguments() {
    assert_eq!(fixed_scene::FIXED, &[("R", 0.5), ("g", 9.81)]);
    assert!(fixed_scene::PARAMS.is_empty());
    const { assert!(fixed_scene::OP_COUNT < fixed_scene::SOURCE_OP_COUNT) };
    let hoop = hoop::Hoop::new(0.5, 1.0, 9.81).unwrap();
    let (theta, s, n) = (0.3, 2.0, -1.0);
    let out = fixed_scene::eval(&fixed_scene::Args { theta, s, n });
    assert!((out.stability - hoop.stability(theta, s, n)).abs() <= 1e-13 * out.stability.abs());
    assert!(
        (out.equilibrium - hoop.equilibrium(theta, s, n)).abs() <= 1e-13 * out.equilibrium.abs()
    );
}
