//! The leaning rider's singular configuration as a result: Browser + Jason from 3 m/s and a
//! roll of 0.5 rad (`carvallo simulate --model lean-rider --speed 3 --lean0 0.5`, the torso
//! free and passive) rolls right while the torso falls left and the fork turns into the fall,
//! until the front wheel stands broadside to the line of contacts at a roll of 1.04 rad and a
//! steer of 1.30 rad, inside the fall angle (1.2 rad) and the steer lock (1.4 rad), before the
//! torso's lean (−1.09 rad) reaches its fall angle. There the yaw rate's pivot of the
//! constraint solve (`b_F_lateral_q3d`, the divisor of every `A_q3d_*`) vanishes.
//!
//! * The run ends [`RunEnd::Singular`] with the yaw rate's pivot at the time DOP853 and
//!   Verner's 9(8) pair at rtol 1e-12 agree on to 1e-11 s (measured 1.7e-14 s, at
//!   t = 0.46809 s), and DOPRI5 at its default tolerances and RK4 at the CLI's 1 ms step reach
//!   that reference within 1e-9 s and 1e-7 s (measured 5.8e-11 s and 6.5e-9 s).
//! * At the event's state, its pitch solved again from scratch, the yaw rate's ratio is 0.01
//!   to 1e-12, and the locked bicycle ([`LeanRider::locked`]: another generated program,
//!   `generated/whipple_nonlinear.ir`, with the parameters converted to the benchmark's) gives
//!   the same three ratios at the same roll and steer, its own pitch solved by its own Newton.
//! * An ordinary run (5 m/s from 0.01 rad, ending when the torso falls) ends exactly where the
//!   integrator alone, with the three falls' events and not the singular one, ends: the watch
//!   changes no step.
//! * A start beyond the singular configuration is refused, naming the pivot and its ratio.
//!
//! Breaking perturbations, each tried once: without the event (its value held at 1) the first
//! test's reference run returns an error instead of a result (Verner's pair: the right-hand
//! side not finite at t = 0.46883 s, past the pole); with the threshold at 0.9999 instead of
//! 0.01 the ordinary run ends singular (at 0.2527 s, the front wheel rate's pivot); without the
//! start's check the start beyond is integrated instead of refused (stepping across the pole
//! to the steer lock in 3.6 ms).

use std::sync::atomic::AtomicBool;

use carvallo::numerics::integrate::{self, Grid, IntegrateError, Integration, Method, Point};
use carvallo::whipple::lean_rider::{
    Joint, LeanRider, LeanRiderError, LeanRiderParams, LeanRun, Limits, RunEnd, PITCH,
};
use carvallo::whipple::nonlinear::WhippleNonlinear;

fn rider() -> LeanRider {
    LeanRider::new(LeanRiderParams::browser_jason()).expect("Browser + Jason stand upright")
}

/// The passive rider from `speed` (m/s) and the roll `lean0` (rad), no torques.
fn run(rider: &LeanRider, speed: f64, lean0: f64, how: &Integration, grid: &Grid) -> LeanRun {
    let mut x0 = rider.upright(speed);
    x0[3] = lean0;
    let never = AtomicBool::new(false);
    rider
        .simulate(x0, &|_| [0.0; 4], Joint::Free, grid, how, Limits::DEFAULT, &never)
        .expect("a result, not an error")
}

/// The time of a singular end and its pivot.
fn singular(run: &LeanRun) -> (f64, usize) {
    match run.end.0 {
        RunEnd::Singular { t, pivot } => (t, pivot),
        other => panic!("{other:?} at {:?}", run.end.1),
    }
}

#[test]
fn the_falling_rider_ends_singular_where_the_yaw_pivot_falls() {
    let rider = rider();
    let grid = Grid::new(1.0, 0.01, 100).expect("grid");
    let vern9 = run(&rider, 3.0, 0.5, &Integration::adaptive(Method::Vern9, 1e-12, 1e-15), &grid);
    let dop853 = run(&rider, 3.0, 0.5, &Integration::adaptive(Method::Dop853, 1e-12, 1e-15), &grid);
    let (t_ref, pivot) = singular(&vern9);
    assert_eq!(pivot, 1, "the yaw rate's pivot");
    let (t853, p853) = singular(&dop853);
    assert_eq!(p853, 1);
    assert!((t853 - t_ref).abs() < 1e-11, "{t853} against {t_ref}");
    let dopri5 =
        run(&rider, 3.0, 0.5, &Integration::with_defaults(Method::Dopri5, None, None), &grid);
    let (t5, _) = singular(&dopri5);
    let rk4 = run(&rider, 3.0, 0.5, &Integration::RK4, &Grid::new(1.0, 0.001, 10).expect("grid"));
    let (t4, _) = singular(&rk4);
    eprintln!(
        "singular at {t_ref} s (vern9), {:e} (dop853), {:e} (dopri5), {:e} (rk4) from it",
        t853 - t_ref,
        t5 - t_ref,
        t4 - t_ref
    );
    assert!((t5 - t_ref).abs() < 1e-9, "{t5} against {t_ref}");
    assert!((t4 - t_ref).abs() < 1e-7, "{t4} against {t_ref}");
    let line = vern9.status_line(Limits::DEFAULT);
    assert!(
        line.starts_with(&format!("singular at t = {t_ref} s: the front wheel stands broadside"))
            && line.contains("the yaw rate's pivot at 0.01 of its upright value"),
        "{line}"
    );
    assert_eq!(vern9.end.0.status(), "singular");

    // The state there: inside every limit, the torso not fallen.
    let x = vern9.end.1;
    eprintln!("roll {} steer {} torso {} at the event", x[3], x[5], x[7]);
    assert!(x[3] > 1.0 && x[3] < 1.2 && x[5] > 1.25 && x[5] < 1.4, "{x:?}");
    assert!(x[7] < -1.0 && x[7] > -1.2, "{x:?}");
    // Its pitch solved again from scratch (a grid of pitches, then Newton).
    let q5 = rider.pitch_on_ground(x[3], x[5]).expect("the front wheel on the ground");
    assert!((q5 - x[PITCH]).abs() < 1e-9, "{q5} against the carried {}", x[PITCH]);
    let ratios = rider.pivot_ratios(x[3], q5, x[5]);
    assert!((ratios[1] - 0.01).abs() < 1e-12, "{ratios:?}");
    assert!(ratios[0] > 0.1 && ratios[2] > 0.1, "{ratios:?}");

    // The locked bicycle's own program and pitch: the same geometry, the same ratios.
    let (locked, _) = rider.locked().expect("a bicycle");
    let bike = WhippleNonlinear::new(locked);
    let theta = bike.pitch(x[3], x[5], 0.0).expect("contact");
    assert!((theta + rider.upright_pitch() - q5).abs() < 1e-12, "{theta} against {q5}");
    let theirs = bike.pivot_ratios(x[3], theta, x[5]);
    for k in 0..3 {
        assert!((theirs[k] - ratios[k]).abs() < 1e-9, "{theirs:?} against {ratios:?}");
    }
}

#[test]
fn an_ordinary_run_is_the_integrators_own_bit_for_bit() {
    let rider = rider();
    let grid = Grid::new(3.0, 0.01, 300).expect("grid");
    let how = Integration::with_defaults(Method::Dopri5, None, None);
    let ours = run(&rider, 5.0, 0.01, &how, &grid);
    let RunEnd::TorsoFell { t } = ours.end.0 else { panic!("{:?}", ours.end.0) };
    // The same integration with the three falls' events alone.
    let mut x0 = rider.upright(5.0);
    x0[3] = 0.01;
    x0[PITCH] = rider.pitch_near(x0[3], x0[PITCH], x0[5]).expect("pitch");
    let none = [0.0; 4];
    let mut rhs = |_: f64, x: &[f64; 13]| -> Result<[f64; 13], LeanRiderError> {
        Ok(rider.projected_rate(x, &none, Joint::Free))
    };
    let mut jac = |_: f64, x: &[f64; 13]| -> Result<[[f64; 13]; 13], LeanRiderError> {
        Ok(rider.jacobian(x, &none, Joint::Free))
    };
    let limits = Limits::DEFAULT;
    let mut roll = |x: &[f64; 13]| Ok(limits.fall_angle - x[3].abs());
    let mut torso = |x: &[f64; 13]| Ok(limits.fall_angle - x[7].abs());
    let mut steer = |x: &[f64; 13]| Ok(limits.steer_lock - x[5].abs());
    let mut observe = |_: Point, _: f64, _: &[f64; 13]| -> Result<(), LeanRiderError> { Ok(()) };
    let bare = integrate::integrate_with_jacobian(
        &how,
        &grid,
        x0,
        &mut rhs,
        Some(&mut jac),
        &mut [&mut roll, &mut torso, &mut steer],
        &mut observe,
        &AtomicBool::new(false),
    )
    .expect("bare run");
    let event = bare.event.expect("the torso's fall");
    assert_eq!((event.index, event.t), (1, t));
    assert_eq!(ours.end.1, bare.end.1);
    assert_eq!(ours.stats, bare.stats);
}

#[test]
fn a_start_beyond_the_singular_configuration_is_refused() {
    let rider = rider();
    // Past the event's steer at about its roll.
    let mut x0 = rider.upright(3.0);
    (x0[3], x0[5]) = (1.04, 1.35);
    let q5 = rider.pitch_on_ground(x0[3], x0[5]).expect("contact");
    let ratio = rider.pivot_ratios(x0[3], q5, x0[5])[1];
    assert!(ratio < 0.01, "{ratio}");
    let grid = Grid::new(1.0, 0.001, 10).expect("grid");
    let never = AtomicBool::new(false);
    for how in [Integration::RK4, Integration::adaptive(Method::Dop853, 1e-8, 1e-11)] {
        let e = rider
            .simulate(x0, &|_| [0.0; 4], Joint::Free, &grid, &how, Limits::DEFAULT, &never)
            .expect_err("refused");
        let IntegrateError::Model(e @ LeanRiderError::SingularStart { pivot: 1, .. }) = e else {
            panic!("{e:?}")
        };
        let text = e.to_string();
        assert!(
            text.starts_with(
                "invalid start at roll 1.04 rad, steer 1.35 rad: at or beyond the singular \
                 configuration (the front wheel stands broadside to the line of contacts): the \
                 yaw rate's pivot of the constraint solve at "
            ) && text.ends_with("of its upright value, at or below 0.01"),
            "{text}"
        );
        let LeanRiderError::SingularStart { ratio: r, .. } = e else { unreachable!() };
        assert!((r - ratio).abs() < 1e-12, "{r} against {ratio}");
    }
}
