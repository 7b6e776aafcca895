//! The section `simulation` of `carvallo bench`: work-precision rows of the simulations — the
//! nonlinear bicycle (4.6 m/s from a lean of 0.05 rad over 5 s and 30 s, and a fall at 2 m/s
//! ended by the event `lean=±0.5`), the hoop and the unicycle — for every method: DOPRI5 and
//! DOP853 at tolerances $10^{-3}$ to $10^{-13}$ (atol $= 10^{-3}$ rtol), Verner's 9(8) pair
//! (`vern9`) at $10^{-4}$, $10^{-7}$, $10^{-10}$, $10^{-13}$, and RK4 at halving steps. Each row has the error at the final time and the largest over the samples (every
//! 0.01 s: the dense output of the adaptive methods) against a reference run (DOP853 at rtol
//! $10^{-14}$, atol $10^{-17}$), the wall time, the right-hand side evaluations, the steps, the
//! energy drift and (bicycle) the contact constraint's residual. Each reference is checked by
//! a second, independent route — RK4 at a step of $10^{-4}$ s ($2.5 \cdot 10^{-5}$ s for the
//! hoop and the unicycle) — and by DOPRI5 at rtol $10^{-14}$, and both agreements are reported.
//!
//! The error of a state is the largest over its components of $|x - x_{ref}|$ divided by
//! $\max(1, |x_{ref}|)$ (the lean and steer absolutely, the wheel angles and positions
//! relatively); for the fall, the event time's error is reported too.

use super::measure::{time_ns, Config, SimulationReference, SimulationRow};
use carvallo::hoop::Hoop;
use carvallo::numerics::integrate::{Grid, Integration, Method, Stats};
use carvallo::unicycle::{Rider, Unicycle, Wheel};
use carvallo::whipple::nonlinear::{Stop, WhippleNonlinear};
use carvallo::whipple::WhippleParams;

/// The interval of the samples compared (s).
const SAMPLE: f64 = 0.01;

/// One run of a problem, reduced to what the rows compare.
struct Run {
    samples: Vec<(f64, Vec<f64>)>,
    stats: Stats,
    drift: f64,
    residual: Option<f64>,
    event: Option<f64>,
}

/// A run of a problem by a method on a grid (`None` when it fails).
type Runner<T> = Box<dyn Fn(&Integration, &Grid) -> Option<T>>;

/// A simulated motion: its name, duration and how to run it.
struct Problem {
    name: String,
    duration: f64,
    /// The step of the RK4 run that checks the reference.
    check_step: f64,
    run: Runner<Run>,
    /// The same run as the timings see it: without the samples where they cost more than
    /// the integration (the bicycle's, each a Newton solve and an energy evaluation).
    timed: Runner<Stats>,
}

fn bicycle(speed: f64, duration: f64, stop: Option<Stop>) -> Problem {
    let bike = WhippleNonlinear::new(WhippleParams::benchmark());
    let name = match stop {
        Some(s) => format!("bicycle {speed} m/s, lean0 0.05, until {}", s.text()),
        None => format!("bicycle {speed} m/s, lean0 0.05, {duration} s"),
    };
    let timed_bike = bike.clone();
    Problem {
        name,
        duration,
        check_step: 1e-4,
        timed: Box::new(move |how, grid| {
            let start = timed_bike.initial_state(speed, 0.05).ok()?;
            let stops: Vec<Stop> = stop.into_iter().collect();
            timed_bike.simulate_final(start, grid, how, &stops).ok().map(|f| f.stats)
        }),
        run: Box::new(move |how, grid| {
            let start = bike.initial_state(speed, 0.05).ok()?;
            let stops: Vec<Stop> = stop.into_iter().collect();
            let tr = bike.simulate_with(start, grid, how, &stops).ok()?;
            let samples = tr
                .iter()
                .map(|(t, s)| {
                    let st = s.state;
                    let x = [
                        st.x,
                        st.y,
                        st.yaw,
                        st.lean,
                        st.steer,
                        st.rear_wheel,
                        st.front_wheel,
                        st.lean_rate,
                        st.steer_rate,
                        st.rear_wheel_rate,
                    ];
                    (t, x.to_vec())
                })
                .collect();
            Some(Run {
                samples,
                stats: tr.stats,
                drift: tr.energy_drift,
                residual: Some(tr.max_contact_residual),
                event: tr.event.map(|e| e.1),
            })
        }),
    }
}

fn conservative(
    name: &str,
    duration: f64,
    sim: impl Fn(&Integration, &Grid) -> Option<carvallo::hoop::Trajectory> + Clone + 'static,
) -> Problem {
    let timed = sim.clone();
    Problem {
        name: name.to_string(),
        duration,
        check_step: 2.5e-5,
        timed: Box::new(move |how, grid| timed(how, grid).map(|t| t.stats)),
        run: Box::new(move |how, grid| {
            let tr = sim(how, grid)?;
            Some(Run {
                samples: tr.iter().map(|(t, x)| (t, x.to_vec())).collect(),
                stats: tr.stats,
                drift: tr.max_energy_drift,
                residual: None,
                event: tr.event.map(|e| e.1),
            })
        }),
    }
}

fn problems(quick: bool) -> Vec<Problem> {
    let hoop = Hoop::new(0.5, 1.0, 9.81).expect("hoop");
    let s0 = 3.0 * hoop.rate_unit();
    let rider = Rider { mass: 60.0, height: 1.25, a: 100.0, b: 99.5, c: 1.4, l: -0.3 };
    let uni = Unicycle::new(0.5, 9.81, rider, Wheel::hoop(5.0, 0.5)).expect("unicycle");
    let u0 = 3.0 * uni.rate_unit();
    let mut list = vec![
        bicycle(4.6, 5.0, None),
        bicycle(2.0, 5.0, Stop::parse("lean=±0.5")),
        conservative("hoop R 0.5 m, theta0 0.2, s0 3 sqrt(g/R), 10 s", 10.0, move |how, grid| {
            hoop.simulate_with([0.2, 0.0, 0.0, s0], grid, how, &[]).ok()
        }),
        conservative(
            "unicycle R 0.5 m, theta0 0.05, s0 3 sqrt(g/R), 10 s",
            10.0,
            move |how, grid| uni.simulate_with([0.05, 0.0, 0.0, u0], grid, how, &[]).ok(),
        ),
    ];
    if !quick {
        list.insert(1, bicycle(4.6, 30.0, None));
    }
    list
}

/// The error of `x` against `r` (see the module docs).
fn state_error(x: &[f64], r: &[f64]) -> f64 {
    x.iter().zip(r).map(|(a, b)| (a - b).abs() / b.abs().max(1.0)).fold(0.0, f64::max)
}

/// The largest error of `run`'s samples against `reference`'s at the same times.
fn dense_error(run: &Run, reference: &Run) -> f64 {
    let mut worst = 0.0f64;
    for (t, x) in &run.samples {
        let k = (t / SAMPLE).round() as usize;
        match reference.samples.get(k) {
            Some((tr, r)) if (tr - t).abs() <= 1e-9 => worst = worst.max(state_error(x, r)),
            _ => {}
        }
    }
    worst
}

fn final_error(run: &Run, reference: &Run) -> f64 {
    match (run.samples.last(), reference.samples.last()) {
        (Some((_, x)), Some((_, r))) => state_error(x, r),
        _ => f64::NAN,
    }
}

/// Appends the section's rows and references (see the [module docs](self)).
pub fn simulation_rows(
    cfg: &Config,
    rows: &mut Vec<SimulationRow>,
    references: &mut Vec<SimulationReference>,
) {
    let quick = cfg.samples < 1_000_000;
    let tolerances: Vec<f64> =
        if quick { vec![1e-3, 1e-6, 1e-9] } else { (3..=13).map(|k| 10f64.powi(-k)).collect() };
    let steps: Vec<u32> = if quick { vec![0, 2] } else { (0..=6).collect() };
    // Verner's 9(8) at every third tolerance (four rows per problem).
    let verner_tolerances: Vec<f64> =
        if quick { vec![1e-9] } else { vec![1e-4, 1e-7, 1e-10, 1e-13] };
    let reference_how = Integration::adaptive(Method::Dop853, 1e-14, 1e-17);
    for p in problems(quick) {
        let sample_grid = Grid::new(p.duration, SAMPLE, 1).expect("grid");
        let Some(reference) = (p.run)(&reference_how, &sample_grid) else {
            continue;
        };
        let every = (SAMPLE / p.check_step).round() as usize;
        let check_grid = Grid::new(p.duration, p.check_step, every).expect("grid");
        let check = (p.run)(&Integration::RK4, &check_grid);
        let agreement = check
            .as_ref()
            .map_or(f64::NAN, |c| dense_error(c, &reference).max(final_error(c, &reference)));
        let dopri5 = (p.run)(&Integration::adaptive(Method::Dopri5, 1e-14, 1e-17), &sample_grid);
        let agreement_dopri5 = dopri5
            .as_ref()
            .map_or(f64::NAN, |c| dense_error(c, &reference).max(final_error(c, &reference)));
        references.push(SimulationReference {
            problem: p.name.clone(),
            reference: "dop853 rtol 1e-14 atol 1e-17".into(),
            check: format!("rk4 step {:e} s", p.check_step),
            agreement,
            agreement_dopri5,
            event_time: reference.event,
        });
        let mut push = |how: Integration, grid: Grid, rtol: Option<f64>, step: Option<f64>| {
            let Some(run) = (p.run)(&how, &grid) else {
                return;
            };
            let ns = time_ns(cfg.min_time, || (p.timed)(&how, &grid));
            rows.push(SimulationRow {
                problem: p.name.clone(),
                method: how.method.name(),
                rtol,
                step,
                rhs_evaluations: run.stats.rhs_evaluations,
                steps: run.stats.steps,
                rejected_steps: run.stats.rejected_steps,
                ns,
                error_final: final_error(&run, &reference),
                error_dense: dense_error(&run, &reference),
                energy_drift: run.drift,
                constraint_residual: run.residual,
                event_time_error: match (run.event, reference.event) {
                    (Some(a), Some(b)) => Some((a - b).abs()),
                    _ => None,
                },
            });
        };
        for method in Method::ALL.into_iter().filter(|m| m.is_adaptive()) {
            let tolerances = match method {
                Method::Dopri5 | Method::Dop853 => &tolerances,
                _ => &verner_tolerances,
            };
            for &rtol in tolerances {
                push(
                    Integration::adaptive(method, rtol, 1e-3 * rtol),
                    sample_grid,
                    Some(rtol),
                    None,
                );
            }
        }
        for &k in &steps {
            let h = SAMPLE / f64::from(1u32 << k);
            let grid = Grid::new(p.duration, h, 1 << k).expect("grid");
            push(Integration::RK4, grid, None, Some(h));
        }
    }
}

/// The section as text.
pub fn render(rows: &[SimulationRow], references: &[SimulationReference]) -> String {
    let mut s = String::from(
        "\n== simulation (error against the reference: largest over the state of |x - ref| / max(1, |ref|))\n",
    );
    for r in references {
        s.push_str(&format!(
            "reference {}: {}, checked by {}: agree to {:.1e}, by dopri5 rtol 1e-14: {:.1e}{}\n",
            r.problem,
            r.reference,
            r.check,
            r.agreement,
            r.agreement_dopri5,
            r.event_time.map_or(String::new(), |t| format!(", event at t = {t:.15} s"))
        ));
    }
    let mut problem = "";
    for r in rows {
        if r.problem != problem {
            problem = &r.problem;
            s.push_str(&format!(
                "\n{problem}\n{:<8} {:>9} {:>9} {:>8} {:>7} {:>12} {:>10} {:>10} {:>10} {:>10}\n",
                "method",
                "rtol/step",
                "rhs evals",
                "steps",
                "reject",
                "ns",
                "err final",
                "err dense",
                "E drift",
                "residual"
            ));
        }
        let tol = r.rtol.or(r.step).map_or("-".into(), |x| format!("{x:.1e}"));
        s.push_str(&format!(
            "{:<8} {:>9} {:>9} {:>8} {:>7} {:>12.0} {:>10.1e} {:>10.1e} {:>10.1e} {:>10}{}\n",
            r.method,
            tol,
            r.rhs_evaluations,
            r.steps,
            r.rejected_steps,
            r.ns,
            r.error_final,
            r.error_dense,
            r.energy_drift,
            r.constraint_residual.map_or("-".into(), |x| format!("{x:.1e}")),
            r.event_time_error.map_or(String::new(), |x| format!("  event time error {x:.1e} s"))
        ));
    }
    s
}
