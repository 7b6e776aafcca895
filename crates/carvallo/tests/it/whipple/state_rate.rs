//! The whole right-hand side ([`StateRate::eval`]) is one program for the pitch's Newton step
//! and the kernel at the corrected pitch (`scene!` with `newton`, sharing the lean's and the
//! steer's trigonometry, the corrected pitch's sine and cosine by angle addition). It equals
//! the route of two programs it replaced — [`StateRate::project`], then the kernel
//! ([`state_rate_scene`]) at the projected pitch, the closed-form solve and the kinematic
//! rates — to rounding, at states on the contact constraint and off it by the drift an
//! integrator leaves (the fused route's range, steps up to $10^{-7}$ rad) and by more (the
//! fallback, Newton to convergence), over the whole range the simulations reach (leans to
//! 1.3 rad, steers to the lock at 1.4 rad). A correction left out or of the wrong size moves
//! the derivative by about the step, far beyond the tolerance.

use carvallo::numerics::rng::SplitMix64;
use carvallo::whipple::nonlinear::rate::{
    solve_symmetric, state_rate_scene, StateRate, LANES, LEN, PITCH,
};
use carvallo::whipple::WhippleParams;

/// The derivative by the former route: the pitch projected, then the kernel alone.
fn two_programs(f: &StateRate, params: &WhippleParams, y: &[f64; LEN]) -> [f64; LEN] {
    let pitch = f.project(y[3], y[PITCH], y[4]).expect("contact");
    let z = [
        ("phi", y[3]),
        ("theta", pitch),
        ("delta", y[4]),
        ("phid", y[7]),
        ("deltad", y[8]),
        ("thetaRd", y[9]),
    ];
    let a = state_rate_scene::Args::from_fn(|n| {
        z.iter().find(|(m, _)| *m == n).map_or_else(|| params.get(n).expect("parameter"), |v| v.1)
    });
    let o = state_rate_scene::eval(&a);
    let ud = solve_symmetric(
        [o.m3_11, o.m3_12, o.m3_13, o.m3_22, o.m3_23, o.m3_33],
        [o.f3_1, o.f3_2, o.f3_3],
    )
    .expect("regular");
    let speed = o.rear_speed;
    [
        speed * y[2].cos(),
        speed * y[2].sin(),
        o.psid,
        y[7],
        y[8],
        y[9],
        o.thetaFd,
        ud[0],
        ud[1],
        ud[2],
        o.thetad,
    ]
}

#[test]
fn one_program_equals_the_two_it_replaced_to_rounding() {
    let params = WhippleParams::benchmark();
    let f = StateRate::new(&params);
    let rr = params.get("rR").expect("rR");
    let mut rng = SplitMix64(36);
    let mut worst = 0.0_f64;
    for k in 0..400 {
        let mut y = [0.0; LEN];
        y[2] = rng.uniform(-3.0, 3.0);
        y[3] = rng.uniform(-1.3, 1.3);
        y[4] = rng.uniform(-1.4, 1.4);
        y[7] = rng.uniform(-3.0, 3.0);
        y[8] = rng.uniform(-7.0, 7.0);
        y[9] = -rng.uniform(0.5, 8.0) / rr;
        let offset = [0.0, 3e-15, -2e-11, 4e-9, -9e-8, 1e-6, -3e-4][k % 7];
        y[PITCH] = f.project(y[3], 0.31, y[4]).expect("pitch") + offset;
        let got = f.eval(&y).expect("evaluates");
        let want = two_programs(&f, &params, &y);
        // The scale of each component: a derivative of order one, or its own size.
        for (i, (g, w)) in got.iter().zip(&want).enumerate() {
            let err = (g - w).abs() / w.abs().max(1.0);
            worst = worst.max(err);
            assert!(err <= 1e-12, "component {i} at {y:?}: {g} vs {w} ({err:.1e})");
        }
    }
    eprintln!("largest difference {worst:.1e}");
}

/// [`StateRate::eval_lanes`] equals [`StateRate::eval`] bit for bit in every lane, a lane
/// whose pitch needs Newton to convergence (the fallback) and one with no contact included.
#[test]
fn lanes_equal_the_scalar_right_hand_side_bit_for_bit() {
    let params = WhippleParams::benchmark();
    let f = StateRate::new(&params);
    let mut rng = SplitMix64(37);
    for round in 0..50 {
        let ys: [[f64; LEN]; LANES] = std::array::from_fn(|j| {
            let mut y = [0.0; LEN];
            y[2] = rng.uniform(-3.0, 3.0);
            y[3] = rng.uniform(-1.0, 1.0);
            y[4] = rng.uniform(-1.2, 1.2);
            y[7] = rng.uniform(-3.0, 3.0);
            y[8] = rng.uniform(-7.0, 7.0);
            y[9] = rng.uniform(-25.0, -2.0);
            let offset = [0.0, 5e-8, -1e-5, 0.0][j];
            y[PITCH] = f.project(y[3], 0.31, y[4]).expect("pitch") + offset;
            if round == 7 && j == 3 {
                y[PITCH] = f64::NAN;
            }
            y
        });
        for (lane, y) in f.eval_lanes(&ys).iter().zip(&ys) {
            match (lane, f.eval(y)) {
                (Ok(a), Ok(b)) => assert_eq!(a.map(f64::to_bits), b.map(f64::to_bits), "at {y:?}"),
                (Err(a), Err(b)) => assert_eq!(*a, b),
                (a, b) => panic!("lanes {a:?} but scalar {b:?} at {y:?}"),
            }
        }
    }
}
