//! Tests of the hoop model's public API: parameter validation (asserting on the `Err` values),
//! the steady turning rates of (E) against the memoir's closed form of n° 14, energy
//! conservation by the RK4 integrator, and steady states staying steady; the error-controlled
//! pairs reaching a reference cross-checked by the hand-written RK4 (`simulate_pns`), and a
//! fall stopped at θ = ±0.5 at the time bisection on single RK4 steps finds.

use carvallo::hoop::{normalised, Hoop};
use carvallo::ParameterError;

fn invalid(name: &'static str, value: f64, reason: &'static str) -> ParameterError {
    ParameterError::InvalidParameter { name, value, reason }
}

#[test]
fn invalid_parameters_are_rejected_with_name_and_value() {
    assert_eq!(Hoop::new(0.0, 1.0, 9.81), Err(invalid("radius", 0.0, "must be positive")));
    assert_eq!(Hoop::new(-1.0, 1.0, 9.81), Err(invalid("radius", -1.0, "must be positive")));
    assert_eq!(Hoop::new(0.5, 0.0, 9.81), Err(invalid("mass", 0.0, "must be positive")));
    assert_eq!(Hoop::new(0.5, -2.0, 9.81), Err(invalid("mass", -2.0, "must be positive")));
    assert_eq!(Hoop::new(0.5, 1.0, -9.81), Err(invalid("g", -9.81, "must be positive")));
    assert_eq!(
        Hoop::new(0.5, 1.0, f64::INFINITY),
        Err(invalid("g", f64::INFINITY, "must be finite"))
    );
    // NaN != NaN, so match on the fields.
    match Hoop::new(f64::NAN, 1.0, 9.81) {
        Err(ParameterError::InvalidParameter { name, value, reason }) => {
            assert_eq!((name, reason), ("radius", "must be finite"));
            assert!(value.is_nan());
        }
        other => panic!("expected an invalid radius, got {other:?}"),
    }
    let err = Hoop::new(0.5, 1.0, -9.81).unwrap_err();
    assert_eq!(err.to_string(), "invalid g -9.81: must be positive");
    let hoop = Hoop::new(0.5, 1.0, 9.81).unwrap();
    assert_eq!(hoop.simulate_pns([0.0; 4], 0.0, 10), Err(invalid("dt", 0.0, "must be positive")));
    assert_eq!(
        hoop.simulate_pns([0.0; 4], -1e-3, 10),
        Err(invalid("dt", -1e-3, "must be positive"))
    );
}

#[test]
fn steady_turning_rates_are_the_roots_printed_in_n14() {
    // Tolerance: relative 1e-10 on the roots (coefficients read off the evaluator at three
    // points, then the stable quadratic formula).
    let hoop = Hoop::new(0.7, 2.0, 9.81).unwrap();
    let nu = hoop.rate_unit();
    for &(theta, s_hat) in &[(0.1, 1.0), (0.3, 0.8), (0.6, 1.5), (-0.4, 2.0), (1.0, 3.0)] {
        let s = s_hat * nu;
        let [n1, n2] = hoop.steady_turning_rates(theta, s).expect("real roots");
        // n° 14, footnote: n1 = -2s/(3 sin θ) - sqrt(4s²/(9 sin²θ) - 2/(3 cos θ)), in units of
        // sqrt(g/R); n2 from the product of the roots 2/(3 cos θ).
        let (sin, cos) = (f64::sin(theta), f64::cos(theta));
        let half = -2.0 * s_hat / (3.0 * sin);
        let root = (half * half - 2.0 / (3.0 * cos)).sqrt();
        let (m1, m2) =
            if half < 0.0 { (half - root, half + root) } else { (half + root, half - root) };
        let m2 = if half < 0.0 { 2.0 / (3.0 * cos) / m1 } else { m2 };
        let mut memoir = [m1 * nu, m2 * nu];
        memoir.sort_by(f64::total_cmp);
        for (got, want) in [n1, n2].iter().zip(memoir) {
            assert!((got - want).abs() <= 1e-10 * want.abs(), "θ={theta}: {got} vs {want}");
        }
        // The hoop turns to the side it leans to (n° 12): n has the sign opposite to θ.
        assert!(n1 * theta < 0.0 && n2 * theta < 0.0);
    }
    // Left of the curve AE (n° 13): no steady turning.
    assert_eq!(hoop.steady_turning_rates(0.5, 0.2 * nu), None);
    // Upright (n° 14: n1 = -∞, n2 = 0): no pair of finite roots.
    assert_eq!(hoop.steady_turning_rates(0.0, nu), None);
    assert_eq!(hoop.steady_turning_rates(f64::NAN, nu), None);
}

#[test]
fn rk4_conserves_energy_and_keeps_steady_states() {
    let hoop = Hoop::new(0.5, 1.5, 9.81).unwrap();
    let nu = hoop.rate_unit();
    // A perturbed, fast-rolling hoop: energy drift of RK4 with dt = 1e-3 s over 5 s should be
    // far below 1e-8 of the energy (the method's local error is O(dt^5)).
    let traj = hoop.simulate_pns([0.2, 0.5, -0.3 * nu, 2.0 * nu], 1e-3, 5000).unwrap();
    assert_eq!(traj.len(), 5001);
    assert!(traj.relative_energy_drift() < 1e-8, "drift {}", traj.relative_energy_drift());
    // A steady state (n2 of (E) at θ = 0.3, s = 2 sqrt(g/R)) stays steady: θ, n, s constant
    // to 1e-9 relative over 2 s. It is stable (S > 0), so rounding does not grow.
    let (theta, s) = (0.3, 2.0 * nu);
    let [_, n2] = hoop.steady_turning_rates(theta, s).unwrap();
    assert!(hoop.stability(theta, s, n2) > 0.0);
    let traj = hoop.simulate_pns([theta, 0.0, n2, s], 1e-3, 2000).unwrap();
    for x in &traj.samples {
        assert!((x[0] - theta).abs() < 1e-9, "theta drifted to {}", x[0]);
        assert!((x[2] - n2).abs() < 1e-9 * n2.abs() && (x[3] - s).abs() < 1e-9 * s);
    }
}

#[test]
fn physical_and_normalised_forms_agree() {
    // n° 12: S/(g/R) and D at rates measured in sqrt(g/R); E/((g/R) sin θ cos θ). Tolerance 1e-13
    // relative to the sum of the magnitudes of the terms (about 10).
    let hoop = Hoop::new(0.4, 1.0, 3.7).unwrap();
    let (nu, k) = (hoop.rate_unit(), 3.7 / 0.4);
    for &(theta, s, n) in &[(0.2, 1.0, -0.5), (-0.7, 0.3, 1.2), (1.1, 2.5, -2.0)] {
        let (sin, cos) = (f64::sin(theta), f64::cos(theta));
        let e = hoop.equilibrium(theta, s * nu, n * nu) / (k * sin * cos);
        assert!((e - normalised::equilibrium(theta, s, n)).abs() < 1e-12);
        let st = hoop.stability(theta, s * nu, n * nu) / k;
        assert!((st - normalised::stability(theta, s, n)).abs() < 1e-12);
        let d = hoop.skid(theta, s * nu, n * nu);
        assert!((d - normalised::skid(theta, s, n)).abs() < 1e-12);
    }
}

/// The largest |x - r| / max(1, |r|) over two equal-length runs.
fn error(a: &carvallo::hoop::Trajectory, r: &carvallo::hoop::Trajectory) -> f64 {
    assert_eq!(a.len(), r.len());
    let mut worst = 0.0f64;
    for ((ta, xa), (tr, xr)) in a.iter().zip(r.iter()) {
        assert!((ta - tr).abs() <= 1e-12);
        for (x, y) in xa.iter().zip(xr) {
            worst = worst.max((x - y).abs() / y.abs().max(1.0));
        }
    }
    worst
}

#[test]
fn adaptive_pairs_reach_a_reference_checked_by_rk4() {
    use carvallo::numerics::integrate::{Grid, Integration, Method};
    let hoop = Hoop::new(0.5, 1.0, 9.81).expect("hoop");
    let x0 = [0.2, 0.0, 0.0, 3.0 * hoop.rate_unit()];
    let grid = Grid::new(5.0, 0.01, 1).expect("grid");
    let reference = hoop
        .simulate_with(x0, &grid, &Integration::adaptive(Method::Dop853, 1e-14, 1e-17), &[])
        .expect("reference");
    let fine = hoop.simulate_pns(x0, 2.5e-5, 200_000).expect("rk4");
    let mut worst = 0.0f64;
    for (k, (t, x)) in reference.iter().enumerate() {
        let (tf, xf) = (fine.times[400 * k], fine.samples[400 * k]);
        assert!((t - tf).abs() <= 1e-12, "{t} {tf}");
        for (a, b) in x.iter().zip(xf) {
            worst = worst.max((a - b).abs() / b.abs().max(1.0));
        }
    }
    eprintln!("hoop reference against rk4 2.5e-5: {worst:.2e}, {:?}", reference.stats);
    assert!(worst <= 1e-12, "{worst}");
    for method in [Method::Dopri5, Method::Dop853, Method::Vern9] {
        for rtol in [1e-6, 1e-9] {
            let how = Integration::adaptive(method, rtol, 1e-3 * rtol);
            let tr = hoop.simulate_with(x0, &grid, &how, &[]).expect("run");
            let e = error(&tr, &reference);
            eprintln!(
                "{method} rtol {rtol:e}: {e:.2e}, drift {:.1e}, {:?}",
                tr.relative_energy_drift(),
                tr.stats
            );
            let allowed = if method == Method::Dopri5 { 100.0 } else { 10.0 };
            assert!(e <= allowed * rtol, "{method} rtol {rtol}: {e}");
            assert!(tr.relative_energy_drift() <= 10.0 * rtol);
        }
    }
}

#[test]
fn a_slow_hoop_falls_to_the_event_at_the_bisected_time() {
    use carvallo::numerics::integrate::{Grid, Integration, Method, Threshold};
    use carvallo::numerics::ode::rk4_step;
    let hoop = Hoop::new(0.5, 1.0, 9.81).expect("hoop");
    let x0 = [0.1, 0.0, 0.0, 0.5 * hoop.rate_unit()];
    let h = 1e-4;
    let fine = hoop.simulate_pns(x0, h, 50_000).expect("rk4");
    let k = fine.samples.iter().position(|x| x[0].abs() >= 0.5).expect("a fall") - 1;
    let (mut lo, mut hi) = (0.0, h);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if rk4_step(|y| hoop.rhs_pns(y), fine.samples[k], mid)[0].abs() < 0.5 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let exact = fine.times[k] + 0.5 * (lo + hi);
    let stop = [Threshold { index: 0, value: 0.5, magnitude: true }];
    let grid = Grid::new(5.0, 1e-3, 10).expect("grid");
    for (how, tol) in [
        (Integration::RK4, 1e-9),
        (Integration::adaptive(Method::Dopri5, 1e-10, 1e-13), 1e-8),
        (Integration::adaptive(Method::Dop853, 1e-12, 1e-15), 1e-10),
        (Integration::adaptive(Method::Vern9, 1e-12, 1e-15), 1e-10),
    ] {
        let tr = hoop.simulate_with(x0, &grid, &how, &stop).expect("run");
        let (index, t) = tr.event.expect("an event");
        eprintln!("{}: fall at {t} (bisection {exact}, {:.1e})", how.method, t - exact);
        assert_eq!((index, tr.last().map(|l| l.0)), (0, Some(t)));
        assert!((t - exact).abs() <= tol, "{}: {t} against {exact}", how.method);
        assert!((tr.samples[tr.len() - 1][0].abs() - 0.5).abs() <= 1e-9);
    }
}
