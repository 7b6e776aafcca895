//! Numerical stress tests: the hoop near $\theta = 0$ and $\theta = \pi/2$ (the memoir divides
//! by $\sin\theta\cos\theta$) and near $s = 0$; the bicycle where a coefficient vanishes (the
//! capsize speed), at the weave–capsize double root, over length scales from millimetres to
//! kilometres and masses from grams to tonnes; certified classification at the boundary; and
//! NaN and infinite inputs rejected with typed errors.
//!
//! Each tolerance is stated where it is used, with the reason for its size.

use carvallo::hoop::Hoop;
use carvallo::numerics::eigen;
use carvallo::numerics::quartic;
use carvallo::whipple::certified::{classify, Certified};
use carvallo::whipple::{Whipple, WhippleError, WhippleParams, PARAM_NAMES};
use carvallo::ParameterError;

const EPS: f64 = f64::EPSILON;

#[test]
fn hoop_steady_turning_near_upright_and_near_flat() {
    let hoop = Hoop::new(0.5, 1.0, 9.81).unwrap();
    let nu = hoop.rate_unit();
    let s = 3.0 * nu;
    // theta -> 0: the roots exist and solve (E); the coefficients lose accuracy like eps/theta,
    // so the residual is allowed 64 eps/theta times the size of the terms.
    for theta in [1e-2, 1e-4, 1e-6, 1e-8] {
        let [n1, n2] = hoop.steady_turning_rates(theta, s).expect("real roots near upright");
        for n in [n1, n2] {
            assert!(n.is_finite(), "theta {theta}: n = {n}");
            let terms = hoop.equilibrium(theta, s, 0.0).abs()
                + (hoop.equilibrium(theta, s, n) - hoop.equilibrium(theta, s, 0.0)).abs()
                + nu * nu * (n / nu).powi(2);
            let res = hoop.equilibrium(theta, s, n).abs();
            assert!(res <= 64.0 * EPS / theta * terms, "theta {theta}, n {n}: residual {res:e}");
        }
    }
    // theta = 0 exactly: the n^2 coefficient vanishes, no pair of finite roots (documented).
    assert!(hoop.steady_turning_rates(0.0, s).is_none());
    // theta -> pi/2 (lying flat): every evaluator stays finite.
    for d in [1e-3, 1e-8, 1e-12] {
        let theta = std::f64::consts::FRAC_PI_2 - d;
        let rhs = hoop.rhs_pns([theta, 0.0, 0.1, s]);
        assert!(rhs.iter().all(|x| x.is_finite()), "theta = pi/2 - {d}: {rhs:?}");
        assert!(hoop.stability(theta, s, 0.1).is_finite());
    }
}

#[test]
fn hoop_near_zero_rolling_rate() {
    let hoop = Hoop::new(0.5, 1.0, 9.81).unwrap();
    // s -> 0: too slow to turn steadily at theta = 0.3 (the point lies left of AE, n° 13).
    for s in [1e-3, 1e-8, 0.0] {
        assert!(hoop.steady_turning_rates(0.3, s).is_none(), "s = {s}");
        let rhs = hoop.rhs_pns([0.3, 0.0, 0.0, s]);
        assert!(rhs.iter().all(|x| x.is_finite()), "s = {s}: {rhs:?}");
        // With n = 0 every term of s carries a factor n and vanishes exactly: the hoop pivots
        // about its contact's tangent (moment 3 mu R^2 / 2 against mu g R sin theta), so
        // p' = (2/3) (g/R) sin theta, to a few roundings.
        let rhs0 = hoop.rhs_pns([0.3, 0.0, 0.0, 0.0]);
        assert_eq!(rhs[1], rhs0[1], "s = {s}");
        let pendulum = 2.0 / 3.0 * (9.81 / 0.5) * 0.3f64.sin();
        assert!((rhs[1] - pendulum).abs() <= 4.0 * EPS * pendulum, "{} vs {pendulum}", rhs[1]);
    }
}

/// The benchmark with lengths scaled by `l` and masses by `m` (inertias by `m l^2`).
fn scaled(l: f64, m: f64) -> WhippleParams {
    let base = *WhippleParams::benchmark().values();
    let mut v = base;
    for (i, name) in PARAM_NAMES.iter().enumerate() {
        v[i] *= match *name {
            "w" | "c" | "rR" | "xB" | "zB" | "xH" | "zH" | "rF" => l,
            "mR" | "mB" | "mH" | "mF" => m,
            n if n.starts_with('I') => m * l * l,
            _ => 1.0,
        };
    }
    WhippleParams::from_values(v).unwrap()
}

#[test]
fn bicycle_speeds_scale_like_the_square_root_of_length_and_not_with_mass() {
    let base = Whipple::new(WhippleParams::benchmark()).stability_window();
    let (vw, vc) = (base.weave_speed.unwrap(), base.capsize_speed.unwrap());
    // Froude scaling: v ~ sqrt(g l). The scaled parameters are rounded to f64 once, so the
    // speeds agree to a few ulps of the conditioning (1e-12 relative).
    for l in [1e-3, 1e-1, 1.0, 10.0, 1e3] {
        for m in [1e-3 / 85.0, 1.0, 1e3 / 85.0] {
            let w = Whipple::new(scaled(l, m)).stability_window();
            let s = l.sqrt();
            for (got, want) in [(w.weave_speed, vw * s), (w.capsize_speed, vc * s)] {
                let got = got.unwrap_or(f64::NAN);
                let rel = ((got - want) / want).abs();
                assert!(rel <= 1e-12, "l {l}, m {m}: {got} vs {want} ({rel:e})");
            }
            assert_eq!(w.stable.len(), 1, "l {l}, m {m}");
        }
    }
}

#[test]
fn quartic_solvers_where_a_coefficient_vanishes_and_at_the_double_root() {
    let w = Whipple::new(WhippleParams::benchmark());
    let win = w.stability_window();
    // At the capsize speed a0 ~ 0: a root near zero. Relative to the largest root the
    // compensated roots are accurate to 1e-13 (the root at zero itself is an absolute 1e-13).
    let c = w.char_poly(win.capsize_speed.unwrap());
    assert!(c[0].abs() <= 1e-9 * c[1].abs(), "a0 at capsize {:e}", c[0]);
    let (reference, conv) = quartic::reference_roots(&c, 256);
    assert!(conv < 1e-60, "reference converged: {conv:e}");
    let scale = reference.iter().map(|z| z.norm()).fold(0.0, f64::max);
    let got = quartic::aberth_compensated(&c);
    for z in &reference {
        let d = got.iter().map(|g| (g - z).norm()).fold(f64::INFINITY, f64::min);
        assert!(d <= 1e-13 * scale, "root {z}: nearest computed at {d:e}");
    }
    // At the bifurcation two real roots merge: a perturbation eps of the coefficients moves
    // them by sqrt(eps) ~ 1e-8, so 1e-7 relative is what any f64 method can promise.
    let (vd, s) = w.bifurcation().unwrap();
    let c = w.char_poly(vd);
    let (reference, _) = quartic::reference_roots(&c, 256);
    for (name, roots) in [
        ("ferrari", quartic::ferrari(&c)),
        ("aberth", quartic::aberth(&c)),
        ("aberth compensated", quartic::aberth_compensated(&c)),
    ] {
        let e = quartic::max_rel_error(&roots, &reference);
        assert!(e <= 1e-7, "{name}: {e:e}");
    }
    // The double root is where Carvallo's variables say: s ~ 3.78.
    assert!(reference.iter().filter(|z| (z.re - s).abs() < 1e-6).count() == 2, "{reference:?}");
}

#[test]
fn certified_classification_never_claims_stability_across_the_boundary() {
    let w = Whipple::new(WhippleParams::benchmark());
    let (m, g) = (w.matrices(), w.params().get("g").unwrap());
    let win = w.stability_window();
    let (vw, vc) = (win.weave_speed.unwrap(), win.capsize_speed.unwrap());
    assert_eq!(classify(&m, g, 0.5 * (vw + vc), 0.0), Certified::Stable);
    assert_eq!(classify(&m, g, 0.5 * vw, 0.0), Certified::Unstable);
    assert_eq!(classify(&m, g, 2.0 * vc, 0.0), Certified::Unstable);
    assert_eq!(classify(&m, g, vw * (1.0 + 1e-12), 0.0), Certified::Stable);
    assert_eq!(classify(&m, g, vw * (1.0 - 1e-12), 0.0), Certified::Unstable);
    // With the entries uncertain by 1e-6, speeds 1e-9 from the boundary cannot be decided.
    assert_eq!(classify(&m, g, vw * (1.0 + 1e-9), 1e-6), Certified::Indeterminate);
    assert_eq!(classify(&m, g, vw * (1.0 - 1e-9), 1e-6), Certified::Indeterminate);
    // Everywhere on a fine grid the certified verdict never contradicts the window.
    for i in 1..2000 {
        let v = 10.0 * i as f64 / 2000.0;
        let inside = win.stable.iter().any(|&(a, b)| a < v && v < b);
        match classify(&m, g, v, 0.0) {
            Certified::Stable => assert!(inside, "v = {v}"),
            Certified::Unstable => assert!(!inside, "v = {v}"),
            Certified::Indeterminate => {}
        }
    }
}

#[test]
fn nan_and_infinite_inputs_are_typed_errors() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(matches!(
            Hoop::new(bad, 1.0, 9.81),
            Err(ParameterError::InvalidParameter { name: "radius", reason: "must be finite", .. })
        ));
        for (i, key) in PARAM_NAMES.iter().enumerate() {
            let mut v = *WhippleParams::benchmark().values();
            v[i] = bad;
            match WhippleParams::from_values(v) {
                Err(WhippleError::Parameter(ParameterError::InvalidParameter {
                    name: k,
                    reason,
                    ..
                })) => {
                    assert_eq!((k, reason), (*key, "must be finite"));
                }
                other => panic!("{key} = {bad}: {other:?}"),
            }
        }
    }
    // A non-finite speed gives no stable verdict.
    let w = Whipple::new(WhippleParams::benchmark());
    let (m, g) = (w.matrices(), 9.81);
    assert_ne!(classify(&m, g, f64::NAN, 0.0), Certified::Stable);
    assert!(eigen::eigenvalues4(&w.state_matrix(f64::NAN)).is_none());
}

/// The message each model's error gave for an invalid value before it carried
/// [`ParameterError`]: the same template in every `Display` that had an `InvalidParameter` (or
/// `InvalidAngle`) variant.
fn old_message(e: &ParameterError) -> String {
    let ParameterError::InvalidParameter { name, value, reason } = e;
    format!("invalid {name} {value:?}: {reason}")
}

#[test]
fn every_invalid_value_is_one_parameter_error_with_the_old_message() {
    use carvallo::bicycle::geometry::{ContactError, Geometry};
    use carvallo::bicycle::straight::Constants;
    use carvallo::bicycle::turn::{LockedSteer, TurnError};
    use carvallo::whipple::nonlinear::{NonlinearError, WhippleNonlinear};

    let mut checked = 0;
    let mut check = |shown: String, inner: &ParameterError| {
        assert_eq!(shown, old_message(inner));
        checked += 1;
    };
    for (i, bad) in [(10, -85.0), (0, f64::NAN), (2, 2.0), (7, 1.0), (14, 6.0), (12, 13.0)] {
        let mut v = *WhippleParams::benchmark().values();
        v[i] = bad;
        match WhippleParams::from_values(v) {
            Err(e @ WhippleError::Parameter(inner)) => check(e.to_string(), &inner),
            other => panic!("{i} = {bad}: {other:?}"),
        }
    }
    let bike = WhippleNonlinear::new(WhippleParams::benchmark());
    let start = bike.initial_state(5.0, 0.0).expect("state");
    for e in [
        bike.initial_state(f64::NAN, 0.0).unwrap_err(),
        bike.simulate(start, -1.0, 1e-3, 1).unwrap_err(),
        bike.simulate(start, 1.0, 2.0, 1).unwrap_err(),
        bike.simulate(start, 1.0, 1e-3, 0).unwrap_err(),
        bike.pitch(f64::INFINITY, 0.0, 0.0).unwrap_err(),
    ] {
        match e {
            NonlinearError::Parameter(inner) => check(e.to_string(), &inner),
            other => panic!("{other:?}"),
        }
    }
    let turn = LockedSteer::new(Constants::MEMOIR).expect("valid");
    for (gamma, speed) in [(f64::NAN, 5.0), (1.2, 5.0), (0.1, -2.0), (0.1, f64::NAN)] {
        match turn.steady_turn(gamma, speed).unwrap_err() {
            e @ TurnError::Parameter(inner) => check(e.to_string(), &inner),
            other => panic!("{other:?}"),
        }
    }
    let geometry = Geometry::old_model();
    for (theta, gamma) in [(2.0, 0.0), (f64::NAN, 0.0), (0.1, f64::INFINITY)] {
        match geometry.solve(theta, gamma).unwrap_err() {
            e @ ContactError::Parameter(inner) => check(e.to_string(), &inner),
            other => panic!("{other:?}"),
        }
    }
    assert_eq!(checked, 18);
}
