//! The generated nonlinear Carvallo–Whipple equations against the exact linearisation of the
//! same bicycle (`carvallo::whipple`, itself checked against the 2007 benchmark), and the
//! simulation built on them.
//!
//! * Linearisation: central differences (step 1e-5) of the nonlinear lean and steer
//!   accelerations about upright straight running at 2, 5 and 8 m/s reproduce the state
//!   matrix of $M\ddot q + vC_1\dot q + (gK_0 + v^2K_2)q = 0$ within absolute 1e-6 per entry,
//!   and the rear wheel's acceleration has no first-order term (absolute 1e-6).
//! * Small lean: a 1e-4 rad initial lean at 5 m/s follows the linear response (the same RK4 on
//!   the state matrix) within 1e-3 of the lean's initial value over 3 s.
//! * Energy: over 5 s at a 1 ms step the total energy drifts by less than 1e-8 J (the total is
//!   about 2 kJ) and the contact constraint holds to 1e-12 m.
//! * Stability: at 5 m/s (inside the benchmark's stable range 4.29–6.02 m/s) a 0.05 rad lean
//!   decays below 0.4 times its initial value within 5 s (measured 0.31 times: the slow capsize
//!   mode, eigenvalue about -0.3 /s there, dominates); at 2 m/s (unstable) it grows beyond
//!   0.5 rad within 3 s.

use carvallo::whipple::nonlinear::{Configuration, WhippleNonlinear};
use carvallo::whipple::{Whipple, WhippleParams};

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
                    err <= 1e-6,
                    "v = {v}: d acc[{r}] / d x[{k}] = {fd}, linear {}",
                    a[(2 + r, k)]
                );
            }
            let fd_rear = (fp[2] - fm[2]) / (2.0 * h);
            assert!(fd_rear.abs() <= 1e-6, "v = {v}: rear wheel acceleration slope {fd_rear}");
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
    assert!(worst <= 1e-3 * lean0, "difference {worst}");
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
    let tr = b.simulate(b.initial_state(2.0, 0.05).expect("state"), 3.0, 1e-3, 10);
    let grown = match tr {
        Ok(t) => t.samples.iter().map(|s| s.state.lean.abs()).fold(0.0, f64::max),
        // The bicycle may fall flat before the end (no contact left): that is a fall too.
        Err(e) => {
            eprintln!("2 m/s: {e}");
            f64::INFINITY
        }
    };
    eprintln!("2 m/s: largest lean {grown}");
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
