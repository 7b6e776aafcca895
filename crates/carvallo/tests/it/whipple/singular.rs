//! The nonlinear bicycle's singular configuration as a result (issue 36's stalled basin
//! point): the benchmark from 2.6 m/s and a lean of 0.14 rad falls, its fork turning into the
//! fall, until the front wheel stands broadside to the line of contacts at a lean of −1.18 rad
//! and a steer of −1.34 rad, inside both the fall angle (1.2 rad) and the steer lock (1.4 rad).
//! There the yaw rate's pivot of the constraint solve vanishes and $M_3$ blows up; DOPRI5 took
//! a million steps towards it and gave up, RK4 and DOP853 stepped across it to the steer lock.
//!
//! * The run ends with [`Final::singular`] at the time the yaw rate's pivot falls to 1 % of its
//!   upright value: DOP853 and Verner's 9(8) pair at rtol 1e-12 agree on it to 1e-11 s
//!   (measured 1.5e-13 s), and the basin map's DOPRI5 at rtol 1e-8 and RK4 at the CLI's 1 ms
//!   step reach that reference within 1e-7 s and 1e-8 s (measured 6.8e-8 s and 4.3e-9 s).
//! * At the event's state, with the pitch solved again from scratch, the yaw rate's pivot
//!   ratio is 0.01 to 1e-12 and the two others are far above it; the pivot is the line of
//!   contacts' component along the front wheel's heading times $n_F$ (from the axle's and
//!   the front contact's generated formulas, to 1e-12), its heading then 89.5° from that line;
//!   $\det M_3$ (the generated mass matrix, not the pivots) is over 10⁴ times its upright value
//!   there (measured 6.3·10⁴) and within 10 % of its upright value at the start.
//! * A run that never comes near it (4.6 m/s from 0.05 rad, DOPRI5) ends exactly where the
//!   integrator alone, without any event, ends: the watch changes no step.
//! * A start beyond the singular configuration is refused, naming the steer.
//!
//! Breaking perturbations, each tried once: without the event (`Watch::Singular`'s value NaN)
//! the first test's reference run returns an error instead of a result; with the threshold
//! at 0.9999 instead of 0.01 the ordinary run ends singular; without the start's check the
//! start beyond is integrated instead of refused.

use carvallo::numerics::integrate::{self, Grid, Integration, Method, Point};
use carvallo::whipple::nonlinear::{
    rate, Configuration, Final, NonlinearError, State, WhippleNonlinear,
};
use carvallo::whipple::WhippleParams;

carvallo::scene! {
    /// The yaw rate's pivot and the geometry it stands for.
    mod geometry {
        model: whipple_nonlinear,
        outputs: [b2_psid, axle_F_x, axle_F_y, n_F, front_contact_x, front_contact_y],
    }
}

fn bike() -> WhippleNonlinear {
    WhippleNonlinear::new(WhippleParams::benchmark())
}

/// The basin map's start: 2.6 m/s, lean 0.14 rad (row 4, column 11 of `carvallo bench`'s map).
fn start(b: &WhippleNonlinear) -> State {
    b.initial_state(2.6, 0.14).expect("state")
}

/// The basin map's run: 5 s, samples every 0.01 s, only the end kept.
fn end(how: &Integration, grid: &Grid) -> Final {
    let b = bike();
    let f = b.simulate_final(start(&b), grid, how, &[]).expect("a result, not an error");
    assert!(f.fall.is_none() && f.steer_lock.is_none() && f.event.is_none(), "{f:?}");
    f
}

fn det(m: [[f64; 3]; 3]) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

/// The configuration of `s` with its pitch solved by Newton from `guess`.
fn configuration(b: &WhippleNonlinear, s: &State, guess: f64) -> Configuration {
    Configuration {
        lean: s.lean,
        pitch: b.pitch(s.lean, s.steer, guess).expect("contact"),
        steer: s.steer,
        lean_rate: s.lean_rate,
        steer_rate: s.steer_rate,
        rear_wheel_rate: s.rear_wheel_rate,
    }
}

#[test]
fn the_stalled_basin_point_ends_singular_where_the_yaw_pivot_falls() {
    let grid = Grid::new(5.0, 0.01, 500).expect("grid");
    // The reference: two methods at rtol 1e-12.
    let dop853 = end(&Integration::adaptive(Method::Dop853, 1e-12, 1e-15), &grid);
    let vern9 = end(&Integration::adaptive(Method::Vern9, 1e-12, 1e-15), &grid);
    let t_ref = vern9.singular.expect("singular");
    let t853 = dop853.singular.expect("singular");
    assert!((t853 - t_ref).abs() < 1e-11, "{t853} against {t_ref}");
    // The basin map's DOPRI5 at its default tolerances, and the CLI's RK4 at 1 ms.
    let dopri5 = end(&Integration::with_defaults(Method::Dopri5, None, None), &grid);
    let t5 = dopri5.singular.expect("singular");
    assert!((t5 - t_ref).abs() < 1e-7, "{t5} against {t_ref}");
    assert_eq!(dopri5.t, t5);
    let rk4 = end(&Integration::RK4, &Grid::new(5.0, 0.001, 5000).expect("grid"));
    let t4 = rk4.singular.expect("singular");
    assert!((t4 - t_ref).abs() < 1e-8, "{t4} against {t_ref}");
    eprintln!("singular at {t_ref} s (vern9), {t853} (dop853), {t5} (dopri5), {t4} (rk4)");

    // The state there, its pitch solved again from scratch.
    let b = bike();
    let s = vern9.state;
    assert!((s.lean + 1.178).abs() < 1e-3 && (s.steer + 1.341).abs() < 1e-3, "{s:?}");
    let c = configuration(&b, &s, 0.0);
    let ratios = b.pivot_ratios(c.lean, c.pitch, c.steer);
    assert!((ratios[1] - 0.01).abs() < 1e-12, "{ratios:?}");
    assert!(ratios[0] > 0.3 && ratios[2] > 0.8, "{ratios:?}");

    // The yaw rate's pivot is n_F times the line of contacts' component along the front
    // wheel's heading (the horizontal axle turned a quarter: (a_y, -a_x)).
    let p = b.params();
    let args: [f64; geometry::Args::LEN] = std::array::from_fn(|i| match geometry::ARGS[i] {
        "phi" => c.lean,
        "theta" => c.pitch,
        "delta" => c.steer,
        name => p.get(name).expect("a parameter"),
    });
    let [b2, ax, ay, nf, rx, ry] = geometry::eval_array(&args);
    let along = ay * rx - ax * ry;
    assert!((b2 - along).abs() < 1e-12, "{b2} against {along}");
    // The front wheel's heading within 0.6 degrees of broadside (measured 89.49 degrees).
    let cos_beta = b2 / (nf * rx.hypot(ry));
    assert!(cos_beta > 0.0 && cos_beta < 0.01, "cos beta {cos_beta}");

    // M3 from the generated mass matrix: far beyond its upright value at the event, near it
    // at the start.
    let upright = configuration(&b, &b.initial_state(2.6, 0.0).expect("state"), 0.0);
    let d0 = det(b.kane_terms(&upright).mass);
    let at_event = det(b.kane_terms(&c).mass) / d0;
    let at_start = det(b.kane_terms(&configuration(&b, &start(&b), 0.0)).mass) / d0;
    assert!(at_event > 1e4, "det M3 {at_event} times upright");
    assert!((at_start - 1.0).abs() < 0.1, "det M3 {at_start} times upright at the start");
}

#[test]
fn an_ordinary_run_is_the_integrators_own_bit_for_bit() {
    // The watch reads states, it moves no step: simulate_final ends where the integrator on
    // the same right-hand side without any event does.
    let b = bike();
    let s = b.initial_state(4.6, 0.05).expect("state");
    let pitch = b.pitch(s.lean, s.steer, 0.0).expect("pitch");
    let grid = Grid::new(5.0, 0.01, 500).expect("grid");
    let how = Integration::with_defaults(Method::Dopri5, None, None);
    let f = b.simulate_final(s, &grid, &how, &[]).expect("run");
    assert!(f.singular.is_none() && f.fall.is_none() && f.steer_lock.is_none(), "{f:?}");
    let rhs_of = rate::StateRate::new(b.params());
    let mut rhs = |_t: f64, y: &[f64; rate::LEN]| rhs_of.eval(y);
    let mut observe =
        |_: Point, _: f64, _: &[f64; rate::LEN]| -> Result<(), NonlinearError> { Ok(()) };
    let mut events: [&mut integrate::EventFn<'_, { rate::LEN }, NonlinearError>; 0] = [];
    let y0 = rate::state_with_pitch(&s, pitch);
    let bare = integrate::integrate(&how, &grid, y0, &mut rhs, &mut events, &mut observe)
        .expect("bare run");
    assert_eq!(f.t, bare.end.0);
    assert_eq!(f.state, rate::state_of(&bare.end.1));
    assert_eq!(f.stats, bare.stats);
}

#[test]
fn a_start_beyond_the_singular_configuration_is_refused() {
    let b = bike();
    // The basin point's lean with its steer a little further than where its run ended.
    let mut s = b.initial_state(2.6, -1.18).expect("state");
    s.steer = -1.36;
    let c = configuration(&b, &s, 0.0);
    assert!(b.pivot_ratios(c.lean, c.pitch, c.steer)[1] < 0.01);
    let grid = Grid::new(1.0, 0.001, 10).expect("grid");
    for how in [Integration::RK4, Integration::adaptive(Method::Dop853, 1e-8, 1e-11)] {
        let e = b.simulate_final(s, &grid, &how, &[]).unwrap_err().to_string();
        assert!(
            e.starts_with("invalid steer -1.36: at or beyond the singular configuration"),
            "{e}"
        );
    }
}
