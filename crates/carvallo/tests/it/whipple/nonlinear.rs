//! The generated nonlinear Carvallo–Whipple equations against the exact linearisation of the
//! same bicycle (`carvallo::whipple`, itself checked against the 2007 benchmark), and the
//! simulation built on them.
//!
//! * Linearisation: central differences (step 1e-5) of the nonlinear lean and steer
//!   accelerations about upright straight running at 2, 5 and 8 m/s reproduce the state
//!   matrix of $M\ddot q + vC_1\dot q + (gK_0 + v^2K_2)q = 0$ within absolute 1e-7 per entry
//!   (the differences' truncation $h^2 |f'''| / 6$; measured 1.1e-8), and the rear wheel's
//!   acceleration has no first-order term (absolute 1e-7).
//! * Small lean: a 1e-4 rad initial lean at 5 m/s follows the linear response (the same RK4 on
//!   the state matrix) within 1e-3 of the lean's initial value over 3 s.
//! * Energy: over 5 s at a 1 ms step the total energy drifts by less than 1e-8 J (the total is
//!   about 2 kJ) and the contact constraint holds to 1e-12 m.
//! * Stability: at 5 m/s (inside the benchmark's stable range 4.29–6.02 m/s) a 0.05 rad lean
//!   decays below 0.4 times its initial value within 5 s (measured 0.31 times: the slow capsize
//!   mode, eigenvalue about -0.3 /s there, dominates); at 2 m/s (unstable) it grows beyond
//!   0.5 rad within 3 s.
//! * Error-controlled integration (4.6 m/s from a lean of 0.05 rad over 5 s): a reference by
//!   DOP853 at rtol 1e-14 agrees with RK4 at a 1e-4 s step (independent code) to 1e-12 over
//!   the samples; DOP853 and DOPRI5 at rtol 1e-6, 1e-8, 1e-10 (atol 1e-3 rtol) reach it within
//!   ten times their tolerance, DOP853 at 1e-10 with fewer evaluations than RK4 at the same
//!   error (DOPRI5's dense output, of order 4, within a hundred times between its steps); RK4's
//!   error falls by 16 ± 3 when its step halves; the contact holds to 1e-14 m whatever the
//!   method (the pitch is solved, not integrated).
//! * Evaluators: the 2,500-operation `dynamics_scene` has a portable (SSE2) and an AVX2 variant
//!   chosen at run time; both, and the dispatching `eval`, equal the IR's interpreter on the
//!   same program bit for bit (no FMA anywhere) on seeded random states and designs.
//! * Events: the fall at 2 m/s stopped at `lean=±0.5` (and the first sign change of the steer
//!   rate) at the time found by bisection on single RK4 steps from a 1e-4 s run (to 1e-9 s
//!   for DOP853, 1e-7 s for RK4's Hermite interpolant at a 1 ms step).

use carvallo::numerics::integrate::{Grid, Integration, Method};
use carvallo::whipple::nonlinear::{Configuration, State, Stop, Trajectory, WhippleNonlinear};
use carvallo::whipple::{Whipple, WhippleParams};

/// The generated evaluators of the nonlinear bicycle (every variant the CPU can run) against
/// the interpreter, bit for bit.
#[test]
fn dynamics_scene_variants_equal_the_interpreter_bit_for_bit() {
    use carvallo::ir::{Interpreter, Program};
    use carvallo::numerics::rng::SplitMix64;
    use carvallo::whipple::nonlinear::dynamics_scene as s;
    let program = Program::parse(carvallo::artifacts::WHIPPLE_NONLINEAR.ir)
        .expect("the IR parses")
        .select_outputs(s::OUTPUTS)
        .expect("the IR has the scene's outputs")
        .fold_constants()
        .eliminate_dead_code();
    assert_eq!(program.params, s::PARAMS);
    assert_eq!(program.inputs, s::INPUTS);
    let it = Interpreter::new(&program).expect("valid");
    let mut scratch = vec![0.0; it.scratch_len()];
    let base = WhippleParams::benchmark();
    let mut rng = SplitMix64(22);
    for _ in 0..200 {
        let args: [f64; s::Args::LEN] = std::array::from_fn(|k| match base.get(s::ARGS[k]) {
            Some(v) => rng.scale(v, 0.2),
            None => rng.scale(1.0, 0.9) - 1.0,
        });
        let mut want = [0.0; s::Out::LEN];
        let (params, inputs) = args.split_at(s::PARAMS.len());
        it.eval(params, inputs, &mut scratch, &mut want).expect("lengths");
        let a = s::Args::from_array(args);
        let mut variants = vec![("dispatched", s::eval(&a)), ("portable", s::eval_portable(&a))];
        #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
        if std::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2.
            variants.push(("avx2", unsafe { s::eval_avx2(&a) }));
        }
        for (variant, got) in variants {
            for (k, (g, w)) in got.to_array().iter().zip(&want).enumerate() {
                assert_eq!(
                    g.to_bits(),
                    w.to_bits(),
                    "{variant}: output {} ({g} vs {w})",
                    s::OUTPUTS[k]
                );
            }
        }
    }
}

fn bike() -> WhippleNonlinear {
    WhippleNonlinear::new(WhippleParams::benchmark())
}

/// Lean, steer and rear wheel accelerations at the state (lean, steer, lean rate, steer rate)
/// with the rear wheel rate of speed `v`.
fn acc(b: &WhippleNonlinear, v: f64, x: [f64; 4]) -> [f64; 3] {
    let rr = b.params().get("rR").expect("rR");
    let pitch = b.pitch(x[0], x[1], 0.0).expect("pitch");
    let c = Configuration {
        lean: x[0],
        pitch,
        steer: x[1],
        lean_rate: x[2],
        steer_rate: x[3],
        rear_wheel_rate: -v / rr,
    };
    b.accelerations(&c).expect("accelerations").independent
}

#[test]
fn linearises_to_the_benchmark_matrices() {
    let b = bike();
    let lin = Whipple::new(WhippleParams::benchmark());
    let h = 1e-5;
    let mut worst: f64 = 0.0;
    for v in [2.0, 5.0, 8.0] {
        let a = lin.state_matrix(v);
        for k in 0..4 {
            let mut xp = [0.0; 4];
            let mut xm = [0.0; 4];
            xp[k] = h;
            xm[k] = -h;
            let (fp, fm) = (acc(&b, v, xp), acc(&b, v, xm));
            for r in 0..2 {
                let fd = (fp[r] - fm[r]) / (2.0 * h);
                let err = (fd - a[(2 + r, k)]).abs();
                worst = worst.max(err);
                assert!(
                    err <= 1e-7,
                    "v = {v}: d acc[{r}] / d x[{k}] = {fd}, linear {}",
                    a[(2 + r, k)]
                );
            }
            let fd_rear = (fp[2] - fm[2]) / (2.0 * h);
            assert!(fd_rear.abs() <= 1e-7, "v = {v}: rear wheel acceleration slope {fd_rear}");
        }
    }
    eprintln!("largest difference from the state matrix: {worst:.2e}");
}

#[test]
fn small_lean_follows_the_linear_response() {
    let b = bike();
    let v = 5.0;
    let lean0 = 1e-4;
    let tr = b.simulate(b.initial_state(v, lean0).expect("state"), 3.0, 1e-3, 1).expect("run");
    let a = Whipple::new(WhippleParams::benchmark()).state_matrix(v);
    let f = |x: &nalgebra::Vector4<f64>| a * x;
    let mut x = nalgebra::Vector4::new(lean0, 0.0, 0.0, 0.0);
    let h = tr.step;
    let mut worst: f64 = 0.0;
    for (i, s) in tr.samples.iter().enumerate() {
        if i > 0 {
            let k1 = f(&x);
            let k2 = f(&(x + k1 * (h / 2.0)));
            let k3 = f(&(x + k2 * (h / 2.0)));
            let k4 = f(&(x + k3 * h));
            x += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0);
        }
        worst = worst.max((s.state.lean - x[0]).abs()).max((s.state.steer - x[1]).abs());
    }
    eprintln!("largest nonlinear - linear difference: {worst:.2e} rad (lean0 {lean0})");
    // Budget: from the upright the nonlinear terms are odd in the lean, so the gap is of order
    // lean0^3 = 1e-12 grown over 3 s (measured 1.0e-11); both sides use RK4 at the same step,
    // whose truncation differs by O(h^4) lean0 = 1e-16. The old bound 1e-3 lean0 = 1e-7 was
    // ten thousand times the gap.
    assert!(worst <= 100.0 * lean0.powi(3), "difference {worst}");
}

#[test]
fn energy_is_conserved_and_the_contact_holds() {
    let b = bike();
    let tr = b.simulate(b.initial_state(5.0, 0.05).expect("state"), 5.0, 1e-3, 100).expect("run");
    let e0 = tr.samples[0].energy;
    eprintln!(
        "energy {e0} J, drift {:.2e} J, contact residual {:.2e} m",
        tr.energy_drift, tr.max_contact_residual
    );
    assert!(tr.energy_drift <= 1e-8, "drift {}", tr.energy_drift);
    assert!(tr.max_contact_residual <= 1e-12, "residual {}", tr.max_contact_residual);
    // Every 100th step of 5000 and the first: the times are the samples' own.
    assert_eq!(tr.len(), 51);
    assert!(tr.iter().all(|(t, s)| t == s.t));
    assert_eq!(tr.last().map(|(t, _)| t), Some(5.0));
}

#[test]
fn lean_decays_at_5_and_grows_at_2() {
    let b = bike();
    let tr = b.simulate(b.initial_state(5.0, 0.05).expect("state"), 5.0, 1e-3, 10).expect("run");
    let last = tr.samples.last().expect("samples").state.lean;
    eprintln!("5 m/s: lean after 5 s {last:e}");
    assert!(last.abs() < 0.4 * 0.05, "lean {last}");
    // A fall is a result, not an error: the run ends at the fall angle (1.2 rad).
    let tr = b
        .simulate(b.initial_state(2.0, 0.05).expect("state"), 3.0, 1e-3, 10)
        .expect("the fall is a result");
    let t_fall = tr.fall.expect("it falls within 3 s");
    let grown = tr.samples.iter().map(|s| s.state.lean.abs()).fold(0.0, f64::max);
    eprintln!("2 m/s: fell at {t_fall} s, largest lean {grown}");
    assert!(grown > 0.5, "largest lean {grown}");
}

#[test]
fn bad_simulation_input_is_named() {
    let b = bike();
    let s = b.initial_state(5.0, 0.0).expect("state");
    let e = b.simulate(s, -1.0, 1e-3, 1).unwrap_err();
    assert_eq!(e.to_string(), "invalid duration -1.0: must be positive");
    let e = b.initial_state(f64::NAN, 0.0).unwrap_err();
    assert_eq!(e.to_string(), "invalid speed NaN: must be finite");
}

fn run(how: &Integration, duration: f64, step: f64, every: usize, stops: &[Stop]) -> Trajectory {
    let b = bike();
    let grid = Grid::new(duration, step, every).expect("grid");
    b.simulate_with(b.initial_state(4.6, 0.05).expect("state"), &grid, how, stops).expect("run")
}

fn array(s: &State) -> [f64; 10] {
    [
        s.x,
        s.y,
        s.yaw,
        s.lean,
        s.steer,
        s.rear_wheel,
        s.front_wheel,
        s.lean_rate,
        s.steer_rate,
        s.rear_wheel_rate,
    ]
}

/// The largest of |x - r| / max(1, |r|) over the state, over the samples at the same times.
fn error(a: &Trajectory, r: &Trajectory) -> f64 {
    assert_eq!(a.len(), r.len());
    let mut worst = 0.0f64;
    for ((ta, sa), (tr, sr)) in a.iter().zip(r.iter()) {
        assert!((ta - tr).abs() <= 1e-12, "{ta} against {tr}");
        for (x, y) in array(&sa.state).iter().zip(array(&sr.state)) {
            worst = worst.max((x - y).abs() / y.abs().max(1.0));
        }
    }
    worst
}

/// The same at the last samples only.
fn final_error(a: &Trajectory, r: &Trajectory) -> f64 {
    let (x, y) = (array(&a.samples[a.len() - 1].state), array(&r.samples[r.len() - 1].state));
    x.iter().zip(y).map(|(x, y)| (x - y).abs() / y.abs().max(1.0)).fold(0.0, f64::max)
}

#[test]
fn adaptive_runs_reach_a_cross_checked_reference() {
    let reference = run(&Integration::adaptive(Method::Dop853, 1e-14, 1e-17), 5.0, 0.01, 1, &[]);
    let check = run(&Integration::RK4, 5.0, 1e-4, 100, &[]);
    let agreement = error(&check, &reference);
    eprintln!("reference (dop853 1e-14, {:?}) against rk4 1e-4: {agreement:.2e}", reference.stats);
    assert!(agreement <= 1e-12, "{agreement}");
    assert!(reference.max_contact_residual <= 1e-14, "{}", reference.max_contact_residual);
    let mut rk4_errors = Vec::new();
    for k in 0..4 {
        let h = 0.01 / f64::from(1u32 << k);
        let tr = run(&Integration::RK4, 5.0, h, 1 << k, &[]);
        let e = error(&tr, &reference);
        eprintln!("rk4 step {h:.2e}: error {e:.2e}, {} evaluations", tr.stats.rhs_evaluations);
        // Four a step, and the slope at the end of the last: the fall angle is an event, whose
        // location needs each step's Hermite interpolant (the end's slope is the next step's
        // first).
        assert_eq!(tr.stats.rhs_evaluations, 4 * tr.stats.steps + 1);
        rk4_errors.push((e, tr.stats.rhs_evaluations));
    }
    for w in rk4_errors.windows(2) {
        let ratio = w[0].0 / w[1].0;
        assert!((13.0..19.0).contains(&ratio), "rk4 error ratio {ratio}");
    }
    for method in [Method::Dopri5, Method::Dop853, Method::Vern9] {
        for rtol in [1e-6, 1e-8, 1e-10] {
            let tr = run(&Integration::adaptive(method, rtol, 1e-3 * rtol), 5.0, 0.01, 1, &[]);
            let e = error(&tr, &reference);
            let end = final_error(&tr, &reference);
            eprintln!("{method} rtol {rtol:e}: error {e:.2e}, at the end {end:.2e}, {:?}, residual {:.1e}", tr.stats, tr.max_contact_residual);
            // DOPRI5's dense output is of order 4: between its steps it errs more. DOP853's is
            // of order 7: since the pitch joined the state (its step control's norm over 11
            // components), its dense error at rtol 1e-6 is 1.17e-5 (5.7e-6 before), at its
            // unchanged 396 evaluations and a final error of 2.0e-8.
            let dense = match method {
                Method::Dopri5 => 100.0,
                Method::Dop853 => 20.0,
                _ => 10.0,
            };
            assert!(end <= 10.0 * rtol, "{method} rtol {rtol}: error at the end {end}");
            assert!(e <= dense * rtol, "{method} rtol {rtol}: error {e}");
            assert!(tr.max_contact_residual <= 1e-14, "{}", tr.max_contact_residual);
            if method != Method::Dopri5 && rtol == 1e-10 {
                // RK4 at the same error: its error falls like h^4 from the smallest step run.
                let (e4, n4) = rk4_errors[3];
                let needed = n4 as f64 * (e4 / e).powf(0.25);
                assert!(
                    (tr.stats.rhs_evaluations as f64) < needed,
                    "{method} {} evaluations, rk4 needs {needed:.0} for {e:.1e}",
                    tr.stats.rhs_evaluations
                );
            }
        }
    }
    // The implicit Radau5, its Newton iterations on the generated state Jacobian: meant for
    // stiff variants, not this bicycle. Its error falls with the tolerance (1.3e-8, 6.1e-10,
    // 3.0e-11 over the samples; 3.5e-10, 8.9e-12, 1.3e-13 at the end). It used not to: given
    // as scalars, the tolerances were transformed by the crate once per component (see
    // `integrate_with_jacobian`), to about 1e-3 whatever the rtol, and the error stalled near
    // 5e-6 in 43 steps at every rtol from 1e-8 to 1e-12. The samples come from Radau5's
    // collocation polynomial, of order 3: between its steps it errs more.
    let mut radau = Vec::new();
    for rtol in [1e-8, 1e-10, 1e-12] {
        let tr = run(&Integration::adaptive(Method::Radau5, rtol, 1e-3 * rtol), 5.0, 0.01, 1, &[]);
        let e = error(&tr, &reference);
        let end = final_error(&tr, &reference);
        let scaled = 0.1 * rtol.powf(2.0 / 3.0);
        eprintln!("radau5 rtol {rtol:e}: error {e:.2e}, at the end {end:.2e} (scaled tolerance {scaled:.1e}), {:?}, residual {:.1e}", tr.stats, tr.max_contact_residual);
        assert!(
            end <= rtol && e <= 100.0 * rtol,
            "radau5 rtol {rtol}: error {e}, at the end {end}"
        );
        assert!(tr.max_contact_residual <= 1e-14, "{}", tr.max_contact_residual);
        radau.push((e, end));
    }
    for w in radau.windows(2) {
        assert!(w[1].0 <= w[0].0 / 10.0 && w[1].1 <= w[0].1 / 10.0, "radau5 errors {radau:?}");
    }
}

/// The time the fall at 2 m/s first meets `g(state) = 0`: the bracketing step of an RK4 run
/// at 1e-4 s, then bisection on the length of one RK4 step from its start.
fn bisected(g: impl Fn(&State) -> f64) -> f64 {
    let b = bike();
    let start = b.initial_state(2.0, 0.05).expect("state");
    let h = 1e-4;
    // Ended when the lean reaches 1 rad, before the bicycle falls flat (no contact left).
    let guard = Stop::parse("lean=±1").expect("stop");
    let grid = Grid::new(5.0, h, 1).expect("grid");
    let fine = b.simulate_with(start, &grid, &Integration::RK4, &[guard]).expect("fine run");
    let k = fine
        .samples
        .windows(2)
        .position(|w| g(&w[0].state) != 0.0 && g(&w[0].state) * g(&w[1].state) <= 0.0)
        .expect("a crossing");
    let from = fine.samples[k];
    let at = |tau: f64| {
        let grid = Grid { h: tau, n: 1, every: 1 };
        let tr = b.simulate_with(from.state, &grid, &Integration::RK4, &[]).expect("step");
        g(&tr.samples[1].state)
    };
    let (mut lo, mut hi) = (0.0, h);
    let g0 = g(&from.state);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if at(mid) * g0 > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    from.t + 0.5 * (lo + hi)
}

#[test]
fn events_stop_the_fall_at_the_bisected_times() {
    let b = bike();
    let start = b.initial_state(2.0, 0.05).expect("state");
    let lean = Stop::parse("lean=±0.5").expect("stop");
    let steer_rate = Stop::parse("steer_rate=0").expect("stop");
    for (stop, g) in [
        (lean, Box::new(|s: &State| s.lean.abs() - 0.5) as Box<dyn Fn(&State) -> f64>),
        (steer_rate, Box::new(|s: &State| s.steer_rate)),
    ] {
        let exact = bisected(&g);
        for (how, tol) in [
            (Integration::adaptive(Method::Dop853, 1e-12, 1e-15), 1e-9),
            (Integration::adaptive(Method::Vern9, 1e-12, 1e-15), 1e-9),
            (Integration::adaptive(Method::Dopri5, 1e-10, 1e-13), 1e-7),
            (Integration::RK4, 1e-7),
        ] {
            let grid = Grid::new(5.0, 1e-3, 10).expect("grid");
            let tr = b.simulate_with(start, &grid, &how, &[stop]).expect("run");
            let (index, t) = tr.event.expect("an event");
            let last = tr.last().expect("samples");
            eprintln!(
                "{} {}: t = {t} (bisection {exact}, {:.1e}), {:?}",
                how.method,
                stop.text(),
                t - exact,
                tr.stats
            );
            assert_eq!(index, 0);
            assert_eq!(last.0, t);
            assert!(g(&last.1.state).abs() <= 1e-6, "{}", g(&last.1.state));
            assert!((t - exact).abs() <= tol, "{}: {t} against {exact}", how.method);
        }
    }
}

#[test]
fn the_rk4_baseline_is_the_old_simulate() {
    let b = bike();
    let start = b.initial_state(4.6, 0.05).expect("state");
    let old = b.simulate(start, 2.0, 1e-3, 10).expect("run");
    let new = b
        .simulate_with(start, &Grid::new(2.0, 1e-3, 10).expect("grid"), &Integration::RK4, &[])
        .expect("run");
    assert_eq!(old, new);
    assert_eq!(old.len(), 201);
    // 2000 steps of four evaluations, and the slope at the end (the fall's event).
    assert_eq!(old.stats.rhs_evaluations, 8001);
    assert!(old.event.is_none());
}

#[test]
fn a_fall_ends_the_run_at_the_fall_angle_located_by_bisection() {
    // The fall (2 m/s from a lean of 0.05 rad) with the fall angle 0.8 rad: DOP853's
    // located time against a bisection on single RK4 steps of 1e-5 s (independent code: each
    // step re-integrated from the last grid state before the crossing).
    let b = bike().with_fall_angle(0.8).expect("angle");
    let start = b.initial_state(2.0, 0.05).expect("state");
    let grid = Grid::new(5.0, 0.01, 1).expect("grid");
    let tr = b
        .simulate_with(start, &grid, &Integration::adaptive(Method::Dop853, 1e-12, 1e-15), &[])
        .expect("run");
    let t_fall = tr.fall.expect("it falls");
    assert!(tr.event.is_none() && tr.interrupted.is_none());
    assert_eq!(*tr.times.last().unwrap(), t_fall);
    assert!((tr.samples.last().unwrap().state.lean.abs() - 0.8).abs() < 1e-12);
    // The reference: RK4 at 1e-5 s up to the last grid point before the fall, then bisection
    // on the length of one more RK4 step.
    let before = (t_fall / 0.01).floor() * 0.01;
    let fine = Grid::new(before, 1e-5, 1000).expect("grid");
    // (The reference runs with the default fall angle, 1.2 rad, so that they pass 0.8 rad.)
    let free = bike();
    let mid = free.simulate_with(start, &fine, &Integration::RK4, &[]).expect("run");
    let s0 = mid.samples.last().unwrap().state;
    assert!(s0.lean.abs() < 0.8);
    let lean_after = |h: f64| -> f64 {
        let g = Grid::new(h, h, 1).expect("grid");
        let last = free.simulate_with(s0, &g, &Integration::RK4, &[]).expect("step");
        last.samples.last().unwrap().state.lean.abs()
    };
    let (mut lo, mut hi) = (0.0f64, 0.02f64);
    assert!(lean_after(hi) > 0.8);
    for _ in 0..60 {
        let m = 0.5 * (lo + hi);
        if m <= 1e-9 || lean_after(m) < 0.8 {
            lo = m;
        } else {
            hi = m;
        }
    }
    let reference = before + 0.5 * (lo + hi);
    eprintln!("fall at 0.8 rad: dop853 {t_fall}, bisection on rk4 {reference}");
    assert!((t_fall - reference).abs() < 1e-8, "{t_fall} against {reference}");
}

#[test]
fn unphysical_starts_are_refused_by_every_method() {
    use carvallo::whipple::nonlinear::NonlinearError;
    let b = bike();
    let grid = Grid::new(1.0, 0.001, 10).expect("grid");
    for how in [
        Integration::RK4,
        Integration::adaptive(Method::Dopri5, 1e-8, 1e-11),
        Integration::adaptive(Method::Dop853, 1e-8, 1e-11),
        Integration::adaptive(Method::Vern9, 1e-8, 1e-11),
    ] {
        let start = b.initial_state(5.0, 2.0).expect("state");
        let e = b.simulate_with(start, &grid, &how, &[]).unwrap_err();
        assert_eq!(e, NonlinearError::Fallen { lean: 2.0, fall_angle: 1.2 }, "{}", how.method);
        let e = b.simulate_final(start, &grid, &how, &[]).unwrap_err();
        assert!(matches!(e, NonlinearError::Fallen { .. }), "{e}");
    }
    for bad in [0.0, -0.1, 1.6, f64::NAN] {
        let e = bike().with_fall_angle(bad).unwrap_err().to_string();
        assert!(e.starts_with(&format!("invalid fall angle {bad:?}")), "{e}");
    }
    // A start whose front wheel cannot touch the ground (a lean inside a wide fall angle with
    // the fork turned into it, where a fall loses the contact) is refused before the first
    // step by every method, naming the lean; so is a steer at the lock.
    let wide = bike().with_fall_angle(std::f64::consts::FRAC_PI_2).expect("angle");
    let mut flat = wide.initial_state(5.0, 1.5).expect("state");
    flat.steer = 1.0;
    assert!(wide.pitch(flat.lean, flat.steer, 0.0).is_err());
    let mut locked = b.initial_state(5.0, 0.1).expect("state");
    locked.steer = -1.4;
    for how in [Integration::RK4, Integration::adaptive(Method::Dop853, 1e-8, 1e-11)] {
        let e = wide.simulate_with(flat, &grid, &how, &[]).unwrap_err().to_string();
        assert_eq!(
            e,
            "invalid lean 1.5: no pitch puts the front wheel on the ground at this lean and steer"
        );
        let e = b.simulate_with(locked, &grid, &how, &[]).unwrap_err().to_string();
        assert_eq!(e, "invalid steer -1.4: at or beyond the steer lock");
    }
    for bad in [0.0, -0.1, std::f64::consts::FRAC_PI_2, f64::INFINITY] {
        let e = bike().with_steer_lock(bad).unwrap_err().to_string();
        assert!(e.starts_with(&format!("invalid steer lock {bad:?}")), "{e}");
    }
    // A slow fall turns the fork to the steer lock first, where every method ends.
    let start = b.initial_state(1.0, 0.05).expect("state");
    let grid = Grid::new(20.0, 0.001, 10).expect("grid");
    for how in [Integration::RK4, Integration::adaptive(Method::Dop853, 1e-10, 1e-13)] {
        let tr = b.simulate_with(start, &grid, &how, &[]).expect("run");
        let t = tr.steer_lock.expect("the steer lock");
        assert!(tr.fall.is_none() && (t - 1.0656945415).abs() < 1e-9, "{}: {t}", how.method);
        assert!((tr.samples.last().unwrap().state.steer.abs() - 1.4).abs() < 1e-12);
    }
}
