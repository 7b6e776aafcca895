//! Scenes with `jacobian: [...]`: the generated derivatives equal the dual numbers of the IR
//! interpreter (a route without any source transformation) to a few ulps and 256-bit central
//! differences of the value program; structural zeros are `0.0` and cost no code; the values
//! are unchanged by asking for derivatives.

// The generated modules document every public item.
#![deny(missing_docs)]

use carvallo_ir::dual::{self, Dual};
use carvallo_ir::{hp, Program};

carvallo_macros::scene! {
    /// Every output, differentiated with respect to every input and two parameters.
    pub mod full {
        model: demo,
        path: "fixtures/demo.ir",
        jacobian: [x, y, z, w, R, g],
    }

    /// Every output, values only: the reference for the values.
    pub mod values {
        model: demo,
        path: "fixtures/demo.ir",
    }

    /// `R` fixed, two outputs, one variable they do not share, split into small functions
    /// and on four points per call.
    pub mod fixed_split {
        model: demo,
        path: "fixtures/demo.ir",
        fixed: { R: 0.5 },
        outputs: [scaled, root],
        jacobian: [z, g],
        max_fn_ops: 2,
        lanes: 4,
    }
}

fn demo() -> Program {
    Program::parse(include_str!("fixtures/demo.ir")).expect("fixture parses")
}

/// Points away from the singularities (z ≠ 0, x ≠ 0).
const POINTS: [[f64; 7]; 4] = [
    // R, g, mu, x, y, z, w
    [0.5, 9.81, 0.3, 0.7, -0.4, 1.3, 2.0],
    [1.2, 3.0, 0.0, -0.9, 0.25, -0.6, 0.0],
    [0.05, 0.5, 1.0, 1.4, 2.0, 0.2, -1.0],
    [2.0, 20.0, 0.0, 0.1, -3.0, 4.0, 5.0],
];

#[test]
fn derivatives_equal_dual_numbers_and_256_bit_differences() {
    let p = demo();
    assert_eq!(full::JACOBIAN_OF, ["poly", "trig", "root", "scaled"]);
    assert_eq!(full::JACOBIAN_WRT, ["x", "y", "z", "w", "R", "g"]);
    for pt in POINTS {
        let (params, inputs) = (&pt[..3], &pt[3..]);
        let out = full::eval(&full::Args::from_fn(|n| {
            let i = ["R", "g", "mu", "x", "y", "z", "w"].iter().position(|m| *m == n).unwrap();
            pt[i]
        }));
        let jac = full::jacobian(&out);
        // Dual numbers: variables x, y, z, w, R, g are 0..6.
        let dp = [
            Dual::<6>::variable(params[0], 4),
            Dual::variable(params[1], 5),
            Dual::constant(params[2]),
        ];
        let di: Vec<Dual<6>> =
            inputs.iter().enumerate().map(|(k, &v)| Dual::variable(v, k)).collect();
        let want = dual::eval(&p, &dp, &di).expect("dual evaluation");
        let vals = values::eval_array(&std::array::from_fn(|i| match i {
            0 => pt[0],
            1 => pt[1],
            k => pt[k + 1],
        }));
        for (i, row) in jac.iter().enumerate() {
            assert_eq!(out.to_array()[i].to_bits(), vals[i].to_bits(), "value {i} changed");
            for (k, &d) in row.iter().enumerate() {
                let w = want[i].grad[k];
                let tol = 8.0 * f64::EPSILON * w.abs().max(1.0);
                assert!(
                    (d - w).abs() <= tol,
                    "d{}/d{}: {d} vs dual {w}",
                    full::JACOBIAN_OF[i],
                    full::JACOBIAN_WRT[k]
                );
            }
        }
        for (k, x) in full::JACOBIAN_WRT.iter().enumerate() {
            let fd = hp::derivative(&p, params, inputs, x, 256).expect("256-bit difference");
            for i in 0..4 {
                let tol = 8.0 * f64::EPSILON * fd[i].abs().max(1.0);
                assert!(
                    (jac[i][k] - fd[i]).abs() <= tol,
                    "d{}/d{x}: {} vs {}",
                    full::JACOBIAN_OF[i],
                    jac[i][k],
                    fd[i]
                );
            }
        }
    }
}

#[test]
fn structural_zeros_are_not_computed() {
    // poly = (R + x)(y - g)/1.5 + x^3 does not depend on z or w; w appears in no output.
    // Nonzero: poly: x y R g; trig: x y; root: z g; scaled: R g = 10 of 24.
    assert_eq!(full::JACOBIAN_NONZEROS, 10);
    assert!(!full::OUTPUTS.contains(&"d_poly__z") && full::OUTPUTS.contains(&"d_poly__x"));
    assert!(!full::INPUTS.contains(&"w"), "w is used by no output: pruned");
    let out = full::eval(&full::Args::from_fn(|_| 0.7));
    let jac = full::jacobian(&out);
    assert_eq!(jac[0][2], 0.0);
    assert_eq!(jac[3][0], 0.0);
    // fixed_split: scaled = 2 R g = g with R = 0.5: d/dz = 0, d/dg = 1; root depends on both.
    assert_eq!(fixed_split::JACOBIAN_NONZEROS, 3);
}

#[test]
fn lanes_and_split_functions_give_the_same_derivatives() {
    let g = [9.81, 3.0, 0.5, 20.0];
    let z = [1.3, -0.6, 0.2, 4.0];
    let names = fixed_split::ARGS;
    let args: [[f64; 4]; 2] = std::array::from_fn(|i| if names[i] == "g" { g } else { z });
    let lanes = fixed_split::eval_lanes(&args);
    for j in 0..4 {
        let one: [f64; 2] = std::array::from_fn(|i| args[i][j]);
        let out = fixed_split::eval_array(&one);
        for (k, v) in out.iter().enumerate() {
            assert_eq!(lanes[k][j].to_bits(), v.to_bits());
        }
        let jac = fixed_split::jacobian_array(&out);
        // root = -sqrt(g) z^-2: d/dz = 2 sqrt(g) z^-3, d/dg = -z^-2 / (2 sqrt g).
        let (gg, zz) = (g[j], z[j]);
        let want = [[0.0, 1.0], [2.0 * gg.sqrt() / zz.powi(3), -1.0 / (zz * zz * 2.0 * gg.sqrt())]];
        for (r, w) in jac.iter().zip(want) {
            for (a, b) in r.iter().zip(w) {
                assert!((a - b).abs() <= 4.0 * f64::EPSILON * b.abs().max(1.0), "{a} vs {b}");
            }
        }
    }
}
