//! The unicycle runtime: parameter validation and the generated equations (energy
//! conservation along an RK4 run, steady states, the straight-running threshold).

use carvallo::unicycle::{Rider, Unicycle, Wheel};
use carvallo::ParameterError;

fn rider() -> Rider {
    Rider { mass: 60.0, height: 1.25, a: 100.0, b: 99.5, c: 1.4, l: -0.3 }
}

#[test]
fn invalid_parameters_are_named() {
    let wheel = Wheel::hoop(5.0, 0.5);
    assert_eq!(
        Unicycle::new(-0.5, 9.81, rider(), wheel).unwrap_err(),
        ParameterError::InvalidParameter {
            name: "radius",
            value: -0.5,
            reason: "must be positive"
        }
    );
    let bad = Rider { c: 300.0, ..rider() };
    assert_eq!(
        Unicycle::new(0.5, 9.81, bad, wheel).unwrap_err(),
        ParameterError::InvalidParameter {
            name: "rider.c",
            value: 300.0,
            reason: "exceeds the sum of the other two moments"
        }
    );
    let bad_wheel = Wheel { a1: 0.1, ..wheel };
    assert!(matches!(
        Unicycle::new(0.5, 9.81, rider(), bad_wheel),
        Err(ParameterError::InvalidParameter { name: "wheel.a1", .. })
    ));
}

#[test]
fn energy_is_conserved_along_rk4() {
    let u = Unicycle::new(0.5, 9.81, rider(), Wheel::hoop(5.0, 0.5)).unwrap();
    let start = [0.05, 0.1, -0.3, 4.0];
    let e0 = u.energy(start);
    let end = u.simulate(start, 1e-3, 500);
    let rel = (u.energy(end) - e0).abs() / e0.abs();
    assert!(rel < 1e-9, "relative energy drift {rel}");
}

#[test]
fn steady_state_has_no_acceleration() {
    let u = Unicycle::new(0.5, 9.81, rider(), Wheel::hoop(5.0, 0.5)).unwrap();
    // (E) is linear in s: solve it for s at θ = 0.2, n = -1.
    let (theta, n) = (0.2, -1.0);
    let e0 = u.equilibrium(theta, 0.0, n);
    let s = -e0 / (u.equilibrium(theta, 1.0, n) - e0);
    let rhs = u.rhs([theta, 0.0, n, s]);
    for (i, v) in rhs.iter().enumerate() {
        assert!(v.abs() < 1e-12, "component {i} of the right-hand side is {v}");
    }
    assert_eq!(u.equilibrium(0.0, 3.0, 0.0), 0.0);
    let threshold = u.straight_running_threshold().expect("a threshold exists");
    assert!(u.stability(0.0, 1.01 * threshold, 0.0) > 0.0);
    assert!(u.stability(0.0, 0.99 * threshold, 0.0) < 0.0);
}

/// The error-controlled pairs on the full unicycle equations reach a DOP853 reference at rtol
/// 1e-14, itself matched by RK4 at 2.5e-5 s (the hand-written `simulate`) to 1e-12 at the end.
#[test]
fn adaptive_pairs_reach_a_reference_checked_by_rk4() {
    use carvallo::numerics::integrate::{Grid, Integration, Method};
    let u = Unicycle::new(0.5, 9.81, rider(), Wheel::hoop(5.0, 0.5)).expect("unicycle");
    let x0 = [0.05, 0.0, 0.0, 3.0 * u.rate_unit()];
    let grid = Grid::new(5.0, 0.01, 100).expect("grid");
    let reference = u
        .simulate_with(x0, &grid, &Integration::adaptive(Method::Dop853, 1e-14, 1e-17), &[])
        .expect("reference");
    let end = reference.samples[reference.len() - 1];
    let rk4 = u.simulate(x0, 2.5e-5, 200_000);
    let err = |x: &[f64; 4]| {
        x.iter().zip(end).map(|(a, b)| (a - b).abs() / b.abs().max(1.0)).fold(0.0, f64::max)
    };
    eprintln!("unicycle reference against rk4: {:.2e}", err(&rk4));
    assert!(err(&rk4) <= 1e-12, "{}", err(&rk4));
    for method in [Method::Dopri5, Method::Dop853, Method::Vern9] {
        for rtol in [1e-6, 1e-9] {
            let how = Integration::adaptive(method, rtol, 1e-3 * rtol);
            let tr = u.simulate_with(x0, &grid, &how, &[]).expect("run");
            let e = err(&tr.samples[tr.len() - 1]);
            eprintln!("{method} rtol {rtol:e}: {e:.2e}, {:?}", tr.stats);
            assert!(e <= 10.0 * rtol, "{method} rtol {rtol}: {e}");
            assert!(tr.relative_energy_drift() <= 10.0 * rtol, "{}", tr.relative_energy_drift());
        }
    }
}
