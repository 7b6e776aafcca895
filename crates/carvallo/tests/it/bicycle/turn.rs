//! Tests of the steady turn with the handlebar held and its characteristic equation (memoir
//! n° 99–105, module `carvallo::bicycle::turn`): upright straight running against the
//! locked-steer reduction of the linear model, the lean of small turns against the linear
//! model's static balance, $df/dp'$ and the gravity part of $df/d\theta$ against the model's
//! energy (an independent output of the generated program), the vanishing pedal torque and
//! the free-wheeling cubic's zero root (the family of turns), n° 105's sign table over a grid,
//! the unstable root against the growth of a perturbation integrated in time through the
//! nonlinear lean row (which checks df/dp too), the model's pitch against Carvallo's frame
//! angle of n° 45 (an independent derivation of the
//! contact geometry), and the rejection of bad inputs by name.

use carvallo::bicycle::geometry::Geometry;
use carvallo::bicycle::straight::{Constants, Equations};
use carvallo::bicycle::turn::{Hold, LockedSteer, SteadyTurn, TurnError};
use carvallo::whipple::nonlinear::Configuration;

fn bike() -> LockedSteer {
    LockedSteer::new(Constants::MEMOIR).expect("the memoir's constants are valid")
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * a.abs().max(b.abs()).max(1e-12)
}

/// Upright straight running: (C) is the lean row of the linear model with the steer row and
/// column removed, $M_{11}\lambda^2 + vC_{1,11}\lambda + gK_{0,11} + v^2K_{2,11}$ (relative
/// tolerance 1e-9: the differences' error estimate is below 1e-8 of the coefficients).
#[test]
fn upright_matches_the_linear_reduction() {
    let b = bike();
    let e = Equations::via_whipple(&Constants::MEMOIR).unwrap();
    for v in [0.0, 2.0, 20.0 / 3.6, 9.0] {
        let t = b.steady_turn(0.0, v).unwrap();
        assert_eq!(t.lean, 0.0);
        let s = v / Constants::MEMOIR.r;
        for hold in [Hold::Rolling, Hold::BearingRate] {
            let c = b.fall_equation(&t, hold).unwrap();
            assert!(close(c.dfdpp, e.m[0][0], 1e-12), "{} {}", c.dfdpp, e.m[0][0]);
            assert!((c.dfdp - e.c[0][0] * s).abs() <= 1e-9 * e.m[0][0], "{}", c.dfdp);
            let k = e.k0[0][0] + e.k2[0][0] * s * s;
            assert!(close(c.dfdtheta, k, 1e-9), "{} {k}", c.dfdtheta);
            assert!(c.error <= 1e-8 * k.abs(), "{}", c.error);
            assert!(c.saddle());
        }
    }
}

/// Small turns: θ₀/γ tends to the linear model's static balance $-\mathfrak B(s)/\mathfrak A$
/// of the fall row, with an error of second order in γ (γ = 1e-3 rad: relative 1e-5).
#[test]
fn small_turn_lean_matches_the_linear_balance() {
    let b = bike();
    let e = Equations::via_whipple(&Constants::MEMOIR).unwrap();
    let gamma = 1e-3;
    for v in [1.0, 20.0 / 3.6, 8.0] {
        let s = v / Constants::MEMOIR.r;
        let linear = -(e.k0[0][1] + e.k2[0][1] * s * s) / e.k0[0][0];
        let t = b.steady_turn(gamma, v).unwrap();
        assert!(close(t.lean / gamma, linear, 1e-5), "{v}: {} {linear}", t.lean / gamma);
    }
}

fn grid() -> Vec<SteadyTurn> {
    let b = bike();
    let mut out = Vec::new();
    for gdeg in [-8.0, 1.0, 3.0, 5.0, 10.0, 15.0] {
        for v in [0.5, 10.0 / 3.6, 20.0 / 3.6, 7.0] {
            out.push(b.steady_turn(f64::to_radians(gdeg), v).unwrap());
        }
    }
    out
}

/// Every steady turn balances the lean row to rounding and needs no pedal torque (the steer
/// does no work: 1e-10 N m against forcing terms of hundreds of N m).
#[test]
fn turns_balance_and_need_no_pedal_torque() {
    for t in grid() {
        assert!(t.lean_residual.abs() < 1e-10, "{t:?}");
        assert!(t.pedal_torque.abs() < 1e-10, "{t:?}");
        assert!(t.lean * t.gamma <= 0.0 || t.speed < 1.0, "lean into the turn: {t:?}");
    }
}

/// n° 102 and 104 against the energy, an independent output of the generated program:
/// $df/dp'$ with the bearing rate held is $\partial^2T/\partial p^2$ (second difference of
/// the energy in the lean rate, step 1e-2: exact for a quadratic, relative 1e-7), and the
/// gravity part of $df/d\theta$ is $d^2V/d\theta^2$ along the contact (second difference of
/// the potential energy, step 1e-3 rad: relative 1e-5).
#[test]
fn coefficients_match_the_energy() {
    let b = bike();
    let m = b.model();
    for t in grid() {
        let c = b.fall_equation(&t, Hold::BearingRate).unwrap();
        let steer = -t.gamma;
        let energy = |lean: f64, lean_rate: f64, wheel: f64| {
            let pitch = m.pitch(lean, steer, t.pitch).unwrap();
            let cfg = Configuration {
                lean,
                pitch,
                steer,
                lean_rate,
                steer_rate: 0.0,
                rear_wheel_rate: wheel,
            };
            m.observe(&cfg).0
        };
        let h = 1e-2;
        let t2 = (energy(t.lean, h, t.wheel_rate) - 2.0 * energy(t.lean, 0.0, t.wheel_rate)
            + energy(t.lean, -h, t.wheel_rate))
            / (h * h);
        assert!(close(c.dfdpp, t2, 1e-7), "{} {t2}", c.dfdpp);
        let h = 1e-3;
        let v2 = (energy(t.lean + h, 0.0, 0.0) - 2.0 * energy(t.lean, 0.0, 0.0)
            + energy(t.lean - h, 0.0, 0.0))
            / (h * h);
        assert!(close(c.dfdtheta_gravity, v2, 1e-5), "{} {v2}", c.dfdtheta_gravity);
    }
}

/// n° 105 over the grid: $df/dp' > 0$, $df/d\theta < 0$, real roots of opposite signs, for
/// both ways of holding the wheel; the free-wheeling cubic has one zero root (constant term
/// below 1e-9 of the others: the turns at fixed γ form a family in the speed) and one root of
/// each sign.
#[test]
fn the_turn_is_a_saddle_whatever_the_speed() {
    let b = bike();
    for t in grid() {
        for hold in [Hold::Rolling, Hold::BearingRate] {
            let c = b.fall_equation(&t, hold).unwrap();
            assert!(c.dfdpp > 0.0 && c.dfdtheta < 0.0 && c.saddle(), "{t:?} {c:?}");
            assert!(c.error < 1e-5, "{c:?}");
        }
        let w = b.free_wheel(&t).unwrap();
        let [c0, c1, _] = w.coefficients;
        assert!(c0.abs() <= 1e-9 * c1.abs(), "{w:?}");
        assert!(w.roots[0].re < 0.0 && w.roots[2].re > 0.0, "{w:?}");
        assert!(w.roots[1].norm() < 1e-9, "{w:?}");
    }
}

/// Bad inputs are errors naming the value; a turn too fast for the front wheel to stay on
/// the ground is `NoSteadyTurn`.
#[test]
fn bad_inputs_are_named_errors() {
    let b = bike();
    let err = b.steady_turn(f64::NAN, 5.0).unwrap_err();
    assert_eq!(err.to_string(), "invalid gamma NaN: must be finite");
    let err = b.steady_turn(1.2, 5.0).unwrap_err();
    assert_eq!(err.to_string(), "invalid gamma 1.2: must lie strictly between -1 and 1 rad");
    let err = b.steady_turn(0.1, -1.0).unwrap_err();
    assert_eq!(err.to_string(), "invalid speed -1.0: must not be negative");
    let err = b.steady_turn(0.5, 40.0).unwrap_err();
    assert!(matches!(err, TurnError::NoSteadyTurn { .. }), "{err}");
    let bad = Constants { h: -1.0, ..Constants::MEMOIR };
    assert_eq!(LockedSteer::new(bad).unwrap_err().to_string(), "invalid h -1.0: must be positive");
}

/// The model's pitch at lean θ and steer −γ is Carvallo's frame angle σ(θ, γ) − σ₀ from the
/// contact equations of n° 45 (`carvallo::bicycle::geometry`, derived separately), for the
/// old model of n° 52 with $c_1 = R\sin\sigma_0 - c$ (absolute 1e-12 rad).
#[test]
fn pitch_is_carvallos_frame_angle() {
    let g = Geometry::old_model();
    let k = Constants { c1: g.radius() * g.sigma0().sin() - g.offset(), ..Constants::MEMOIR };
    let b = LockedSteer::new(k).unwrap();
    for (theta, gamma) in [(0.0, 0.1), (0.2, 0.0), (0.2, 0.1), (-0.3, 0.2), (0.1, -0.3), (0.5, 0.4)]
    {
        let pitch = b.model().pitch(theta, -gamma, 0.0).unwrap();
        let sigma = g.solve(theta, gamma).unwrap().sigma;
        assert!((pitch - (sigma - g.sigma0())).abs() < 1e-12, "{theta} {gamma}: {pitch} {sigma}");
    }
}

/// The frame's B is not in the memoir: the saddle of n° 105 does not depend on it (central
/// pitch moment from 1 kg m² to its largest value), nor does the upright equation.
#[test]
fn the_saddle_does_not_depend_on_the_frames_b() {
    for ibyy in [1.0, 10.0, 20.0] {
        let b = LockedSteer::with_pitch_moment(Constants::MEMOIR, ibyy).unwrap();
        for (gdeg, v) in [(5.0, 20.0 / 3.6), (12.0, 5.0), (3.0, 8.0)] {
            let t = b.steady_turn(f64::to_radians(gdeg), v).unwrap();
            let c = b.fall_equation(&t, Hold::Rolling).unwrap();
            assert!(c.saddle(), "{ibyy} {gdeg} {v}: {c:?}");
        }
        let c = b.fall_equation(&b.steady_turn(0.0, 5.0).unwrap(), Hold::Rolling).unwrap();
        assert!(close(c.dfdtheta, -723.978, 1e-12) && close(c.dfdpp, 100.0, 1e-12), "{c:?}");
    }
    let err = LockedSteer::with_pitch_moment(Constants::MEMOIR, 40.0).unwrap_err();
    assert_eq!(
        err.to_string(),
        "invalid ibyy 40.0: exceeds the sum of the two other central moments"
    );
}

/// The unstable root of (C) with s held is the growth rate of the nonlinear fall: the lean
/// row with the rolling speed held (the bearing rate $U(\theta, p)$, its acceleration
/// $U_\theta p + U_p p'$) integrated by RK4 (step 1e-3 s, 1 s) from the turn displaced by
/// 1e-7 rad along the unstable direction $(1, \lambda_+)$; $\ln(\Delta\theta(T)/\Delta\theta(0))/T$
/// equals $\lambda_+$ to relative 1e-6 (measured: 2e-8 at 5°, 20 km/h),
/// while leaving df/dp out would move it by 0.4 % at 5°, 20 km/h.
#[test]
fn unstable_root_is_the_growth_rate_of_the_nonlinear_fall() {
    let b = bike();
    let m = b.model();
    let r = Constants::MEMOIR.r;
    for (gdeg, v) in [(5.0, 20.0 / 3.6), (10.0, 20.0 / 3.6), (3.0, 3.0)] {
        let gamma = f64::to_radians(gdeg);
        let steer = -gamma;
        let t = b.steady_turn(gamma, v).unwrap();
        let c = b.fall_equation(&t, Hold::Rolling).unwrap();
        let lam = c.roots[1].re;
        let terms = |lean: f64, p: f64, u3: f64| {
            let pitch = m.pitch(lean, steer, t.pitch).unwrap();
            m.kane_terms(&Configuration {
                lean,
                pitch,
                steer,
                lean_rate: p,
                steer_rate: 0.0,
                rear_wheel_rate: u3,
            })
        };
        let wheel = |lean: f64, p: f64| {
            let a = terms(lean, p, 0.0).rates[0];
            (-v / r - a[0] * p) / (1.0 + a[2])
        };
        let accel = |lean: f64, p: f64| {
            let u3 = wheel(lean, p);
            let k = terms(lean, p, u3);
            let a = k.rates[0];
            let u_p = -a[0] / (1.0 + a[2]);
            let h = 1e-6;
            let u_theta = (wheel(lean + h, p) - wheel(lean - h, p)) / (2.0 * h);
            (k.forcing[0] - k.mass[0][2] * u_theta * p) / (k.mass[0][0] + k.mass[0][2] * u_p)
        };
        let eps = 1e-7;
        let (mut x, mut p) = (t.lean + eps, lam * eps);
        let (dt, steps) = (1e-3, 1000);
        for _ in 0..steps {
            let (k1x, k1p) = (p, accel(x, p));
            let (k2x, k2p) = (p + 0.5 * dt * k1p, accel(x + 0.5 * dt * k1x, p + 0.5 * dt * k1p));
            let (k3x, k3p) = (p + 0.5 * dt * k2p, accel(x + 0.5 * dt * k2x, p + 0.5 * dt * k2p));
            let (k4x, k4p) = (p + dt * k3p, accel(x + dt * k3x, p + dt * k3p));
            x += dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
            p += dt / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
        }
        let growth = ((x - t.lean) / eps).ln() / (dt * steps as f64);
        assert!(close(growth, lam, 1e-6), "{gdeg} {v}: {growth} {lam}");
    }
}
