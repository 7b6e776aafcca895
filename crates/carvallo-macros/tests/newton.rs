//! Scenes with `newton: {...}`: the emitted evaluator equals the IR interpreter on
//! `Program::with_newton_step` of the same program bit for bit, lanes equal the scalar
//! evaluator, and the outputs are the original program's at the corrected input (256-bit
//! evaluation) to a few units in the last place.

// The generated modules document every public item.
#![deny(missing_docs)]

use carvallo_ir::{hp, Program};

carvallo_macros::scene! {
    /// Two outputs after one Newton step on theta, on four points per call.
    pub mod stepped {
        model: constraint,
        path: "fixtures/constraint.ir",
        outputs: [f, k],
        newton: { input: theta, residual: h, derivative: dh },
        lanes: 4,
    }
}

fn constraint() -> Program {
    Program::parse(include_str!("fixtures/constraint.ir")).expect("fixture parses")
}

/// (r, phi, theta, delta): theta near the root of h, off it by up to 1e-6.
fn points() -> [[f64; 4]; 4] {
    let p = constraint();
    std::array::from_fn(|k| {
        let (r, phi, delta) = (1.2 + 0.1 * k as f64, 0.1 * k as f64, 0.3 - 0.2 * k as f64);
        let mut theta: f64 = 1.0;
        for _ in 0..60 {
            let o = p.eval_f64(&[r], &[phi, theta, delta]).expect("evaluates");
            theta -= o[0] / o[1];
        }
        [r, phi, theta + [0.0, 1e-9, -2e-7, 1e-6][k], delta]
    })
}

#[test]
fn the_scene_is_the_fused_program() {
    let fused = constraint()
        .with_newton_step("theta", "h", "dh")
        .and_then(|p| p.select_outputs(&["f", "k", "theta_newton_step", "theta_newton"]))
        .expect("fuses");
    assert_eq!(stepped::OUTPUTS, ["f", "k", "theta_newton_step", "theta_newton"]);
    assert_eq!(stepped::ARGS, ["r", "phi", "theta", "delta"]);
    let mut lanes = [[0.0; 4]; 4];
    for (j, pt) in points().into_iter().enumerate() {
        let got = stepped::eval_array(&pt);
        let want = fused.eval_f64(&pt[..1], &pt[1..]).expect("evaluates");
        assert_eq!(got.to_vec(), want, "at {pt:?}");
        let exact =
            hp::eval_f64(&constraint(), &pt[..1], &[pt[1], got[3], pt[3]], 256).expect("evaluates");
        for (g, w) in got[..2].iter().zip(&exact[2..4]) {
            assert!((g - w).abs() <= 1e-15 * w.abs(), "{g} vs {w} at {pt:?}");
        }
        for (i, v) in pt.iter().enumerate() {
            lanes[i][j] = *v;
        }
    }
    let out = stepped::eval_lanes(&lanes);
    for (j, pt) in points().into_iter().enumerate() {
        let scalar = stepped::eval_array(&pt);
        for (i, s) in scalar.iter().enumerate() {
            assert_eq!(out[i][j].to_bits(), s.to_bits(), "lane {j}, output {i}");
        }
    }
}
