//! Tests of the handlebar's rest equilibrium (memoir n° 67, module `carvallo::bicycle::rest`):
//! the Newton/bisection results against brute-force scans of the exact functions, the massless
//! front wheel giving back the frame's lowest position, the mirror symmetry θ → −θ, the virtual
//! work of the hands' torque over finite displacements, the lowest position of n° 55/56 against
//! its closed form (the point E on the ground), the front wheel's centre against the vectors of
//! n° 46–47 written by hand, the small-lean limit and the typed errors.

use carvallo::bicycle::geometry::{ContactError, Geometry};
use carvallo::bicycle::rest::{RestBicycle, RestConstants, RestError};
use carvallo::ParameterError;

fn rad(x: f64) -> f64 {
    x.to_radians()
}

/// The leans of the tests (rad): the frame leaning to the side of positive γ is θ < 0.
const LEANS: [f64; 4] = [0.0, -10.0, -25.0, -40.0];

/// The vertex of the parabola through the smallest sample of `f` on a grid of `n + 1` points
/// over `[a, b]` and its two neighbours.
fn scan_minimum(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    let h = (b - a) / n as f64;
    let values: Vec<f64> = (0..=n).map(|k| f(a + k as f64 * h)).collect();
    let k = (1..n).min_by(|&i, &j| values[i].total_cmp(&values[j])).unwrap();
    let (fm, f0, fp) = (values[k - 1], values[k], values[k + 1]);
    a + k as f64 * h + 0.5 * h * (fm - fp) / (fm - 2.0 * f0 + fp)
}

#[test]
fn newton_agrees_with_a_brute_force_scan() {
    let bike = RestBicycle::memoir();
    for t in LEANS {
        let theta = rad(t);
        let p = bike.rest_position(theta).unwrap();
        assert!(p.lowest.gamma > 0.0, "theta {t}: the handlebar falls to gamma > 0");
        let energy = |g: f64| bike.state(theta, g).unwrap().energy;
        let sigma = |g: f64| bike.geometry().solve(theta, g).unwrap().sigma;
        // Coarse scan over the side, then a fine one around the coarse minimum.
        for (f, newton, what) in [
            (&energy as &dyn Fn(f64) -> f64, p.equilibrium.gamma, "gamma67"),
            (&sigma as &dyn Fn(f64) -> f64, p.lowest.gamma, "gamma55"),
        ] {
            let coarse = scan_minimum(f, rad(1.0), rad(89.0), 176);
            let fine = scan_minimum(f, coarse - rad(0.5), coarse + rad(0.5), 200);
            assert!(
                (fine - newton).abs() <= 1e-6,
                "theta {t}: {what} scan {fine} newton {newton} differ by {:e} rad",
                fine - newton
            );
        }
    }
}

#[test]
fn a_massless_front_wheel_rests_where_the_frame_is_lowest() {
    let bike = RestBicycle::memoir();
    for t in LEANS {
        let theta = rad(t);
        let light = bike.with_wheel_mass(0.0).unwrap().rest_position(theta).unwrap();
        assert!(
            (light.equilibrium.gamma - light.lowest.gamma).abs() <= 1e-7,
            "theta {t}: mu1 = 0 gives gamma67 - gamma55 = {:e} rad",
            light.difference()
        );
        // The lowest centre of gravity is the smallest sigma wherever G is in the frame
        // (ahead of the rear centre): another G, massless wheel, the same position.
        let other =
            RestConstants { forward: 0.45, height: 1.3, wheel_mass: 0.0, ..RestConstants::MEMOIR };
        let moved =
            RestBicycle::new(*bike.geometry(), other).unwrap().rest_position(theta).unwrap();
        assert!(
            (moved.equilibrium.gamma - light.lowest.gamma).abs() <= 1e-7,
            "theta {t}: another G gives {:e} rad",
            moved.equilibrium.gamma - light.lowest.gamma
        );
        // The shift is first order in mu1 / mu: a tenth of the mass, a tenth of the shift.
        let d =
            |m: f64| bike.with_wheel_mass(m).unwrap().rest_position(theta).unwrap().difference();
        let ratio = d(0.05) / d(0.5);
        assert!(
            (ratio - 0.1).abs() <= 0.005,
            "theta {t}: shift ratio {ratio} for masses 0.05, 0.5"
        );
    }
}

#[test]
fn mirror_symmetry_theta_to_minus_theta() {
    let bike = RestBicycle::memoir();
    for t in [-5.0, -20.0, -40.0] {
        let a = bike.rest_position_on(rad(t), 1.0).unwrap();
        let b = bike.rest_position_on(rad(-t), -1.0).unwrap();
        assert!((a.lowest.gamma + b.lowest.gamma).abs() <= 1e-8, "gamma55 at {t}");
        assert!((a.equilibrium.gamma + b.equilibrium.gamma).abs() <= 1e-8, "gamma67 at {t}");
        let (ua, ub) = (a.at_equilibrium.energy, b.at_equilibrium.energy);
        assert!((ua - ub).abs() <= 1e-9, "energies {ua} {ub} at {t}");
        // rest_position picks the side the handlebar falls to: gamma > 0 for theta < 0.
        assert_eq!(bike.rest_position(rad(-t)).unwrap().equilibrium.gamma, b.equilibrium.gamma);
    }
}

/// Simpson's rule with `n` (even) intervals.
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    let h = (b - a) / n as f64;
    let inner: f64 = (1..n).map(|k| f(a + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 }).sum();
    (f(a) + f(b) + inner) * h / 3.0
}

#[test]
fn virtual_work_of_the_hands_torque() {
    let bike = RestBicycle::memoir();
    for t in LEANS {
        let theta = rad(t);
        let p = bike.rest_position(theta).unwrap();
        // The torque the hands must apply to hold gamma is -dU/dgamma; its work from gamma = 0
        // to gamma55 and from gamma55 to gamma67 is the change of U.
        let slope = |g: f64| bike.slope(theta, g).unwrap().value;
        for (a, b) in [(0.0, p.lowest.gamma), (p.lowest.gamma, p.equilibrium.gamma)] {
            let work = simpson(slope, a, b, 64);
            let du = bike.state(theta, b).unwrap().energy - bike.state(theta, a).unwrap().energy;
            assert!((work - du).abs() <= 1e-6, "theta {t}: work {work} J, dU {du} J on [{a}, {b}]");
        }
        // At gamma55 the frame's part of dU/dgamma vanishes: the slope is the front wheel's
        // mu1 g dz_C/dgamma (n° 67: turning further lowers the front wheel).
        let k = bike.constants();
        let h = 1e-4;
        let zc = |g: f64| bike.state(theta, g).unwrap().wheel_height;
        let g55 = p.lowest.gamma;
        let wheel = k.wheel_mass * k.g * (zc(g55 + h) - zc(g55 - h)) / (2.0 * h);
        let s = bike.slope(theta, g55).unwrap();
        assert!(wheel < 0.0, "theta {t}: the front wheel rises when gamma grows ({wheel})");
        assert!((s.value - wheel).abs() <= 1e-5, "theta {t}: slope {} against {wheel}", s.value);
        // Past gamma55 the frame rises and the wheel falls: gamma67 lies beyond gamma55.
        assert!(p.difference() > 0.0, "theta {t}: gamma67 - gamma55 = {}", p.difference());
        assert!(p.frame_rise() > 0.0 && p.at_equilibrium.wheel_height < p.at_lowest.wheel_height);
        assert!(p.equilibrium.curvature.value > 0.0, "theta {t}: unstable");
        assert!(p.equilibrium.curvature.error <= 1e-5 * p.equilibrium.curvature.value);
    }
}

#[test]
fn the_lowest_frame_has_the_point_e_on_the_ground() {
    let bike = RestBicycle::memoir();
    let g = *bike.geometry();
    let (sigma_min, mu_e, gamma_0) = g.lowest_frame();
    for t in LEANS {
        let theta = rad(t);
        let p = bike.rest_position(theta).unwrap();
        // n° 56: the same sigma as for the upright frame, with M at E (R sin mu = c).
        assert!(
            (p.at_lowest.sigma - sigma_min).abs() <= 1e-11,
            "theta {t}: sigma {}",
            p.at_lowest.sigma
        );
        assert!((p.at_lowest.mu - mu_e).abs() <= 1e-7, "theta {t}: mu {}", p.at_lowest.mu);
        // Independently: the gamma where (2) puts the lowest point at E with that sigma,
        // by bisection on the generated mu_lowest.
        let f = |x: f64| g.mu_lowest(theta, x, sigma_min) - mu_e;
        let (mut lo, mut hi) = (rad(1.0), rad(89.0));
        assert!(f(lo) > 0.0 && f(hi) < 0.0, "theta {t}: no sign change");
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if f(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        assert!(
            (lo - p.lowest.gamma).abs() <= 1e-7,
            "theta {t}: bisection {lo} newton {}",
            p.lowest.gamma
        );
    }
    let upright = bike.rest_position(0.0).unwrap();
    assert!(
        (upright.lowest.gamma - gamma_0).abs() <= 1e-7,
        "upright gamma55 {}",
        upright.lowest.gamma
    );
}

#[test]
fn the_front_centre_is_the_vectors_of_n46_written_by_hand() {
    let bike = RestBicycle::memoir();
    let g = bike.geometry();
    for (t, gd) in [(0.0, 0.0), (0.0, 60.0), (-20.0, 30.0), (-40.0, 15.0), (30.0, -70.0)] {
        let (theta, gamma) = (rad(t), rad(gd));
        let s = bike.state(theta, gamma).unwrap();
        // OC = Rk + aH - bG + cH1 on K (n° 46-47).
        let (st, ct) = theta.sin_cos();
        let (ss, cs) = s.sigma.sin_cos();
        let (sg, cg) = gamma.sin_cos();
        let by_hand = g.radius() * ct + g.a() * ct * ss - g.b() * ct * cs
            + g.offset() * (st * sg + ct * cg * ss);
        assert!(
            (s.wheel_height - by_hand).abs() <= 1e-14,
            "({t}, {gd}): {} against {by_hand}",
            s.wheel_height
        );
        // n° 69 (1): Z = (R + x sin eta1 + z cos eta1) cos theta.
        let k = bike.constants();
        let s1 = s.sigma - g.sigma0();
        let z = (g.radius() + k.forward * s1.sin() + (k.height - g.radius()) * s1.cos()) * ct;
        assert_eq!(s.frame_height, z);
    }
    // Upright and straight: the normal position, G at h and C at R.
    let s = bike.state(0.0, 0.0).unwrap();
    assert!((s.frame_height - 1.0).abs() <= 1e-14 && (s.wheel_height - 0.38).abs() <= 1e-14);
}

#[test]
fn the_small_lean_limit() {
    let bike = RestBicycle::memoir();
    let upright = bike.rest_position(0.0).unwrap();
    // gamma = 0 is the unstable equilibrium the wheel starts from (n° 67).
    let at_zero = bike.stiffness(0.0, 0.0).unwrap();
    assert!(at_zero.value < 0.0, "stiffness at gamma = 0: {at_zero:?}");
    assert!(bike.slope(0.0, 0.0).unwrap().value.abs() <= 1e-9);
    // Leaning a little, both positions tend to those of the upright frame, not to gamma = 0.
    let small = bike.rest_position(-1e-4).unwrap();
    assert!((small.lowest.gamma - upright.lowest.gamma).abs() <= 1e-3);
    assert!((small.equilibrium.gamma - upright.equilibrium.gamma).abs() <= 1e-3);
    assert!(upright.difference() > rad(5.0), "upright shift {}", upright.difference());
}

#[test]
fn typed_errors_name_the_bad_value() {
    let g = Geometry::old_model();
    let k = RestConstants::MEMOIR;
    for (c, name, value) in [
        (RestConstants { frame_mass: 0.0, ..k }, "frame_mass", 0.0),
        (RestConstants { wheel_mass: -1.0, ..k }, "wheel_mass", -1.0),
        (RestConstants { forward: f64::INFINITY, ..k }, "forward", f64::INFINITY),
        (RestConstants { height: 0.3, ..k }, "height", 0.3),
        (RestConstants { g: f64::NAN, ..k }, "g", f64::NAN),
    ] {
        match RestBicycle::new(g, c) {
            Err(ParameterError::InvalidParameter { name: n, value: v, .. }) => {
                assert_eq!(n, name);
                assert!(v == value || (v.is_nan() && value.is_nan()));
            }
            other => panic!("{name}: {other:?}"),
        }
    }
    let bike = RestBicycle::memoir();
    // No sign change of dU/dgamma between 10° and 20° at theta = 0.
    let e = bike.equilibrium(0.0, rad(10.0), rad(20.0)).unwrap_err();
    assert!(matches!(e, RestError::NoEquilibrium { .. }), "{e:?}");
    assert!(
        e.to_string().starts_with("no stable equilibrium of the handlebar at theta 0.0 rad"),
        "{e}"
    );
    let e = bike.rest_position(2.0).unwrap_err();
    assert!(
        matches!(
            e,
            RestError::Contact(ContactError::Parameter(ParameterError::InvalidParameter {
                name: "theta",
                ..
            }))
        ),
        "{e:?}"
    );
    assert_eq!(e.to_string(), "invalid theta 2.0: must be finite with |theta| < pi/2");
}
