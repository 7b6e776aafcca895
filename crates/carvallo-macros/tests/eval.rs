//! The generated evaluators compile and compute the right values.
//!
//! Scenes over the hand-written fixture `tests/fixtures/demo.ir` (every IR operation once) are
//! compared with values computed by hand in 40-digit arithmetic (mpmath) and with the IR's
//! reference interpreter on the same program, for a full scene, pruned and fixed scenes and a
//! scene split into helper functions.

// The reference values are kept with the 40 digits they were computed with.
#![allow(clippy::excessive_precision)]
// The generated modules document every public item.
#![deny(missing_docs)]

use carvallo_ir::Program;

carvallo_macros::scene! {
    /// Every output, nothing fixed.
    pub mod full {
        model: demo,
        path: "fixtures/demo.ir",
    }

    /// Only `trig`.
    pub mod trig_only {
        model: demo,
        path: "fixtures/demo.ir",
        outputs: [trig],
    }

    /// `R` and `g` fixed, two outputs in a new order.
    pub mod fixed {
        model: demo,
        path: "fixtures/demo.ir",
        fixed: { R: 0.5, g: 9.81 },
        outputs: [scaled, poly],
    }

    /// Every output, at most two operations per function.
    pub mod split {
        model: demo,
        path: "fixtures/demo.ir",
        max_fn_ops: 2,
    }

    /// Every output, also on four points per call.
    pub mod four {
        model: demo,
        path: "fixtures/demo.ir",
        lanes: 4,
    }

    /// As `fixed`, on eight points per call, at most three operations per function.
    pub mod eight_split {
        model: demo,
        path: "fixtures/demo.ir",
        fixed: { R: 0.5, g: 9.81 },
        outputs: [scaled, poly],
        max_fn_ops: 3,
        lanes: 8,
    }
}

/// Relative tolerance of the comparisons with the 40-digit values: a few ulps of the largest
/// intermediate (the formulas have at most a handful of roundings each).
const REL_TOL: f64 = 1e-14;
/// Absolute tolerance, for values near zero.
const ABS_TOL: f64 = 1e-15;

fn close(got: f64, want: f64) -> bool {
    (got - want).abs() <= ABS_TOL + REL_TOL * want.abs()
}

fn assert_close(what: &str, got: f64, want: f64) {
    assert!(close(got, want), "{what}: got {got:e}, want {want:e}, error {:e}", got - want);
}

/// 40-digit values at R = 0.5, g = 9.81, x = 0.5, y = 2, z = 4 (mpmath, `mp.dps = 40`).
const POLY: f64 = -5.081666666666666666666666666666666666667;
const TRIG: f64 = -0.9790265950742909202489940791258527733884;
const ROOT: f64 = -0.1957557470420728158704578879227758939679;
const SCALED: f64 = 9.81;

/// 40-digit values at R = 1.25, g = -3, x = -0.75, y = 0.25 (mpmath, `mp.dps = 40`).
const POLY_2: f64 = 0.6614583333333333333333333333333333333333;
const TRIG_2: f64 = -4.411886820843273259689336653917713187217;
const SCALED_2: f64 = -7.5;

#[test]
fn constants_describe_the_scenes() {
    assert_eq!(full::MODEL, "demo");
    assert_eq!(full::PARAMS, ["R", "g"]);
    assert_eq!(full::INPUTS, ["x", "y", "z"]);
    assert_eq!(full::OUTPUTS, ["poly", "trig", "root", "scaled"]);
    assert_eq!(full::FIXED, []);
    assert_eq!((full::OP_COUNT, full::SOURCE_OP_COUNT), (19, 19));
    assert_eq!(full::OP_COUNT_BY_OP.iter().map(|(_, n)| n).sum::<usize>(), 19);

    assert_eq!(trig_only::PARAMS, [] as [&str; 0]);
    assert_eq!(trig_only::INPUTS, ["x", "y"]);
    assert_eq!(trig_only::OP_COUNT, 7);
    assert_eq!((trig_only::Args::LEN, trig_only::Out::LEN), (2, 1));

    assert_eq!(fixed::FIXED, [("R", 0.5), ("g", 9.81)]);
    assert_eq!(fixed::OUTPUTS, ["scaled", "poly"]);
    assert_eq!(fixed::INPUTS, ["x", "y"]);
    assert_eq!(fixed::OP_COUNT, 6);
    const { assert!(fixed::OP_COUNT < full::OP_COUNT && trig_only::OP_COUNT < full::OP_COUNT) };

    assert_eq!(split::OP_COUNT, full::OP_COUNT);
}

#[test]
fn values_match_the_hand_computed_ones() {
    let out = full::eval(&full::Args { R: 0.5, g: 9.81, x: 0.5, y: 2.0, z: 4.0 });
    assert_close("poly", out.poly, POLY);
    assert_close("trig", out.trig, TRIG);
    assert_close("root", out.root, ROOT);
    assert_close("scaled", out.scaled, SCALED);

    let out = trig_only::eval(&trig_only::Args { x: 0.5, y: 2.0 });
    assert_close("trig_only.trig", out.trig, TRIG);

    let out = fixed::eval(&fixed::Args { x: 0.5, y: 2.0 });
    assert_close("fixed.poly", out.poly, POLY);
    assert_close("fixed.scaled", out.scaled, SCALED);

    let [poly, trig, _root, scaled] = full::eval_array(&[1.25, -3.0, -0.75, 0.25, 1.0]);
    assert_close("poly 2", poly, POLY_2);
    assert_close("trig 2", trig, TRIG_2);
    assert_close("scaled 2", scaled, SCALED_2);
}

#[test]
fn generated_code_equals_the_reference_interpreter_bit_for_bit() {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/demo.ir"))
            .expect("fixture readable");
    let program = Program::parse(&text).expect("fixture parses");
    // A fixed grid of points (no randomness needed): signs, zero and large values.
    let values = [-2.5, -0.75, 0.0, 0.3, 1.0, 7.25];
    for (i, &x) in values.iter().enumerate() {
        for (j, &y) in values.iter().enumerate() {
            let (r, g, z) =
                (values[(i + j) % 6], values[(i + 2 * j + 1) % 6], values[(2 * i + j + 2) % 6]);
            let want = program.eval_f64(&[r, g, 1.0], &[x, y, z, 1.0]).expect("interpreter runs");
            let got = full::eval_array(&[r, g, x, y, z]);
            let split = split::eval_array(&[r, g, x, y, z]);
            for k in 0..4 {
                // Same operations in the same order: identical bits (NaN compares by bits too).
                assert_eq!(
                    got[k].to_bits(),
                    want[k].to_bits(),
                    "output {k} at R={r} g={g} x={x} y={y} z={z}"
                );
                assert_eq!(split[k].to_bits(), want[k].to_bits(), "split output {k}");
            }
            let trig = trig_only::eval_array(&[x, y]);
            assert_eq!(trig[0].to_bits(), want[1].to_bits());
        }
    }
}

#[test]
fn args_and_outputs_round_trip_through_arrays() {
    let a = full::Args::from_array([1.0, 2.0, 3.0, 4.0, 5.0]);
    assert_eq!(a, full::Args { R: 1.0, g: 2.0, x: 3.0, y: 4.0, z: 5.0 });
    assert_eq!(a.to_array(), [1.0, 2.0, 3.0, 4.0, 5.0]);
    let o = full::eval(&a);
    assert_eq!(full::Out::from_array(o.to_array()), o);
    assert_eq!(full::Args::default().to_array(), [0.0; 5]);
}

#[test]
fn args_from_fn_fills_the_fields_by_name_in_args_order() {
    // `ARGS` is `PARAMS` then `INPUTS`, and `from_fn` asks for the names in that order.
    assert_eq!(full::ARGS, ["R", "g", "x", "y", "z"]);
    assert_eq!(fixed::ARGS.as_slice(), [fixed::PARAMS, fixed::INPUTS].concat().as_slice());
    let mut asked = Vec::new();
    let a = full::Args::from_fn(|name| {
        asked.push(name.to_string());
        asked.len() as f64
    });
    assert_eq!(asked, full::ARGS);
    assert_eq!(a.to_array(), [1.0, 2.0, 3.0, 4.0, 5.0]);
    // Field `k` is the value of `ARGS[k]`, whatever order the values come from.
    let value = |name: &str| match name {
        "R" => 0.5,
        "g" => 9.81,
        "x" => -1.0,
        "y" => 2.0,
        "z" => 3.0,
        _ => f64::NAN,
    };
    let by_name = full::Args::from_fn(value);
    for (k, name) in full::ARGS.iter().enumerate() {
        assert_eq!(by_name.to_array()[k], value(name), "{name}");
    }
    let f = fixed::Args::from_fn(value);
    assert_eq!(f.to_array(), fixed::ARGS.map(value));
}

/// A seeded SplitMix64 stream of numbers in [-4, 4), with a few special values mixed in.
fn stream(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    let mut n = 0u32;
    move || {
        n += 1;
        if n.is_multiple_of(17) {
            return [0.0, -0.0, 1e-300, 1e300][(n / 17 % 4) as usize];
        }
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        8.0 * ((z >> 11) as f64 / (1u64 << 53) as f64) - 4.0
    }
}

#[test]
fn lanes_equal_the_scalar_evaluator_lane_by_lane_bit_for_bit() {
    let mut next = stream(15);
    for _ in 0..500 {
        let mut args = [[0.0; 4]; 5];
        args.iter_mut().flatten().for_each(|a| *a = next());
        // `eval_lanes` runs the AVX2 variant where the CPU has it; both variants are checked.
        let mut variants = vec![("dispatched", four::eval_lanes(&args))];
        variants.push(("portable", four::eval_lanes_portable(&args)));
        #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
        if std::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2.
            variants.push(("avx2", unsafe { four::eval_lanes_avx2(&args) }));
        }
        for (variant, got) in variants {
            for j in 0..4 {
                let want = full::eval_array(&args.map(|a| a[j]));
                for k in 0..4 {
                    assert_eq!(
                        got[k][j].to_bits(),
                        want[k].to_bits(),
                        "{variant}: output {k} lane {j}"
                    );
                }
            }
        }
        let mut args = [[0.0; 8]; 2];
        args.iter_mut().flatten().for_each(|a| *a = next());
        let mut variants = vec![("dispatched", eight_split::eval_lanes(&args))];
        variants.push(("portable", eight_split::eval_lanes_portable(&args)));
        #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
        if std::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2.
            variants.push(("avx2", unsafe { eight_split::eval_lanes_avx2(&args) }));
        }
        for (variant, got) in variants {
            for j in 0..8 {
                let want = fixed::eval_array(&args.map(|a| a[j]));
                for k in 0..2 {
                    assert_eq!(
                        got[k][j].to_bits(),
                        want[k].to_bits(),
                        "{variant}: fixed output {k} lane {j}"
                    );
                }
            }
        }
    }
    assert_eq!((four::LANES, eight_split::LANES), (4, 8));
}
