//! The two-wheeled inverted pendulum's runtime against independent routes: the pitch
//! eigenvalue against the planar Lagrangian's closed form, the linear model against central
//! differences of the nonlinear right-hand side, the energy along an unforced simulation, and
//! a feedback designed by pole placement that keeps the body up where the open loop falls.

use carvallo::numerics::integrate::{Grid, Integration, Method};
use carvallo::numerics::rng::SplitMix64;
use carvallo::wheeled_pendulum::{
    WheeledPendulum, WheeledPendulumError, WheeledPendulumParams, FALL_ANGLE,
};
use carvallo::ParameterError;

/// The nominal design and `n` seeded designs with every parameter scaled in [0.7, 1.3] (those
/// that break a moment's triangle inequality are redrawn).
fn designs(n: usize) -> Vec<WheeledPendulumParams> {
    let nominal = WheeledPendulumParams::nominal();
    let mut rng = SplitMix64(20261207);
    let mut out = vec![nominal];
    while out.len() <= n {
        let values = nominal.values().map(|x| rng.scale(x, 0.3));
        if let Ok(p) = WheeledPendulumParams::new(values) {
            out.push(p);
        }
    }
    out
}

/// The closed form of the planar Lagrangian (`codegen/tests/derive/wheeled_pendulum.rs`):
/// $\lambda^2 = m_B g l M_t / (J M_t - m_B^2 l^2)$, $M_t = m_B + 2 m_W + 2 I_{Wa}/r^2$,
/// $J = I_{Byy} + m_B l^2$.
fn closed_form_lambda(p: &WheeledPendulumParams) -> f64 {
    let g = |n: &str| p.get(n).expect("a parameter");
    let (r, mw, iwa, l, mb, iyy, grav) =
        (g("r"), g("mW"), g("IWa"), g("l"), g("mB"), g("IByy"), g("g"));
    let mt = mb + 2.0 * mw + 2.0 * iwa / (r * r);
    let j = iyy + mb * l * l;
    (mb * grav * l * mt / (j * mt - mb * mb * l * l)).sqrt()
}

/// Every bad value is an error naming it; an unknown name is named too.
#[test]
fn invalid_parameters_are_named() {
    let p = WheeledPendulumParams::nominal();
    for name in WheeledPendulumParams::NAMES {
        for (value, reason) in [(0.0, "must be positive"), (f64::NAN, "must be finite")] {
            match p.with(name, value) {
                Err(WheeledPendulumError::Parameter(ParameterError::InvalidParameter {
                    name: n,
                    reason: r,
                    ..
                })) => assert_eq!((n, r), (name, reason)),
                other => panic!("{name} = {value}: {other:?}"),
            }
        }
    }
    let err = p.with("IWa", 0.5).unwrap_err();
    assert_eq!(
        err.to_string(),
        "invalid IWa 0.5: must not exceed the sum of the other two moments"
    );
    let err = p.with("IBzz", 30.0).unwrap_err();
    assert_eq!(
        err.to_string(),
        "invalid IBzz 30.0: must not exceed the sum of the other two moments"
    );
    assert!(p.with("mass", 1.0).unwrap_err().to_string().starts_with("unknown parameter \"mass\""));
}

/// (a) The pitch eigenvalue is the closed form's $\lambda$ (and $-\lambda$) at 9 designs and 5
/// speeds, to $10^{-10}$ relative, and the other two eigenvalues are zero (to $10^{-9}
/// \lambda$). What breaks it: a wrong `lin_*` entry or its place in $A$ (the rows of
/// $M^{-1} f$ swapped, the wheel rates' columns shifted), $M^{-1}$ applied on the wrong side,
/// or a model whose wheel inertia does not enter $M_t$ as $2 I_{Wa}/r^2$.
#[test]
fn pitch_eigenvalue_is_the_planar_closed_form() {
    let mut worst = (0.0f64, 0.0f64);
    for p in designs(8) {
        let m = WheeledPendulum::new(p);
        let lambda = closed_form_lambda(&p);
        for v in [0.0, 0.5, 2.0, 5.0, 12.0] {
            let ev = m.linear(v).eigenvalues();
            let top = (ev[0].re - lambda).abs().max((ev[3].re + lambda).abs()) / lambda;
            let zeros =
                ev[1].norm().max(ev[2].norm()).max(ev[0].im.abs()).max(ev[3].im.abs()) / lambda;
            worst = (worst.0.max(top), worst.1.max(zeros));
            assert!(top < 1e-10, "v {v}: {ev:?} against ±{lambda}");
            assert!(zeros < 1e-9, "v {v}: {ev:?}");
        }
    }
    eprintln!("pitch eigenvalue against the closed form: {:e}; zeros {:e}", worst.0, worst.1);
}

/// (b) $A$ and $B$ equal the central-difference Jacobian of the nonlinear right-hand side
/// ([`WheeledPendulum::rate`]'s pitch and speed rates) at upright running, at 9 designs and
/// 4 speeds. Budget: step $h = 10^{-5}$ (times the component's scale, 1 or the wheel rate),
/// truncation $O(h^2) \approx 10^{-10}$ and rounding $\epsilon |f| / h \approx 10^{-10}$ relative
/// to the largest entry; asserted at $10^{-7}$. What breaks it: the linearisation taken at a
/// different reference (the wheels at $+v/r$), a sign of the pitch in `lin_fq_*`, or a rate
/// that solves $M \dot u = f$ wrongly.
#[test]
fn linear_model_is_the_jacobian_of_the_nonlinear_rate() {
    let mut worst = 0.0f64;
    for p in designs(8) {
        let m = WheeledPendulum::new(p);
        for v in [0.0, 1.0, 4.0, 10.0] {
            let lin = m.linear(v);
            let x0 = m.upright(v);
            // Columns: theta, thetad, thetaLd, thetaRd, then TL, TR.
            let mut fd = [[0.0; 6]; 4];
            for col in 0..6 {
                let scale = if (2..4).contains(&col) { 1.0f64.max(x0[5].abs()) } else { 1.0 };
                let h = 1e-5 * scale;
                let eval = |s: f64| {
                    let (mut x, mut t) = (x0, [0.0; 2]);
                    if col < 4 {
                        x[3 + col] += s * h;
                    } else {
                        t[col - 4] += s * h;
                    }
                    m.rate(&x, t)
                };
                let (plus, minus) = (eval(1.0), eval(-1.0));
                for row in 0..4 {
                    fd[row][col] = (plus[3 + row] - minus[3 + row]) / (2.0 * h);
                }
            }
            let big = (0..4)
                .flat_map(|i| (0..6).map(move |j| (i, j)))
                .map(|(i, j)| fd[i][j].abs())
                .fold(0.0, f64::max);
            for (i, fd_row) in fd.iter().enumerate() {
                for (j, &approx) in fd_row.iter().enumerate() {
                    let exact = if j < 4 { lin.a[(i, j)] } else { lin.b[(i, j - 4)] };
                    let r = (exact - approx).abs() / big;
                    worst = worst.max(r);
                    assert!(r < 1e-7, "v {v}: entry ({i}, {j}): {exact} against {approx}");
                }
            }
        }
    }
    eprintln!("A, B against central differences: worst relative residual {worst:e}");
}

/// (c) With the motors off the energy output is conserved along a simulation (DOP853 at
/// rtol $10^{-11}$, atol $10^{-14}$) that pitches, turns (the wheels at different rates) and
/// falls: the relative drift over every accepted step and every sample stays below
/// $10^{-9}$. What breaks it: a rate that is not Kane's (a torque term left on with zero
/// torques, a wrong sign in $f$'s gravity or gyroscopic terms, a wrong $M^{-1}$), or an energy
/// with the wrong potential.
#[test]
fn energy_is_conserved_without_torques() {
    let m = WheeledPendulum::new(WheeledPendulumParams::nominal());
    let how = Integration::adaptive(Method::Dop853, 1e-11, 1e-14);
    let grid = Grid::new(3.0, 0.01, 1).expect("grid");
    let x0 = [0.0, 0.0, 0.0, 0.1, 0.0, -8.0, -8.5];
    let run = m.simulate(x0, &|_, _| [0.0, 0.0], &grid, &how).expect("a run");
    let fall = run.fall.expect("the unforced body falls");
    let e0 = run.energy0;
    let samples = run.samples.iter().map(|x| (m.energy(x) - e0).abs()).fold(0.0, f64::max);
    let drift = run.relative_energy_drift().max(samples / e0.abs());
    eprintln!("energy {e0} J, fell at {fall} s, relative drift {drift:e}");
    assert!(drift < 1e-9, "relative energy drift {drift:e}");
    let (_, last) = run.last().expect("samples");
    assert!((last[3].abs() - FALL_ANGLE).abs() < 1e-9, "{last:?}");
    assert!(last[2].abs() > 1e-3, "the unequal wheel rates turn it: psi {}", last[2]);
}

/// (d) A feedback placed at the design's poles ($-\lambda$, $-1.5\lambda$, $-2\lambda$ on the
/// pitch and forward motion, computed from the linear model) keeps the body up from a 0.1 rad
/// pitch at 2 m/s and brings it back to upright running at that speed within 5 s; without it
/// the body falls within a second. What breaks it: a gain of the wrong sign or on the wrong
/// state (the wheel rate not measured from $-v/r$), torques applied to the wrong wheel, or a
/// $B$ whose columns are not the torques'.
#[test]
fn placed_feedback_keeps_the_body_up_and_the_open_loop_falls() {
    let m = WheeledPendulum::new(WheeledPendulumParams::nominal());
    let v = 2.0;
    let lin = m.linear(v);
    let k = lin.place(lin.default_poles()).expect("controllable");
    let how = Integration::adaptive(Method::Dop853, 1e-9, 1e-12);
    let grid = Grid::new(5.0, 0.01, 1).expect("grid");
    let mut x0 = m.upright(v);
    x0[3] = 0.1;
    let closed = m.simulate(x0, &|_, x| k.torques(x), &grid, &how).expect("a run");
    assert_eq!(closed.fall, None, "the controlled body fell");
    let peak = closed.samples.iter().map(|x| x[3].abs()).fold(0.0, f64::max);
    let (t, last) = closed.last().expect("samples");
    let speed_error = (last[5] - lin.wheel_rate).abs() * m.radius();
    eprintln!(
        "closed loop: peak pitch {peak} rad, at {t} s pitch {:e} rad, speed error {speed_error:e} m/s, x {} m",
        last[3], last[0]
    );
    assert!(peak < 0.2, "peak pitch {peak}");
    assert!(last[3].abs() < 1e-4 && speed_error < 1e-3, "{last:?}");
    assert!(last[0] > 5.0, "it runs forward: {last:?}");
    let open = m.simulate(x0, &|_, _| [0.0, 0.0], &grid, &how).expect("a run");
    let fall = open.fall.expect("the open loop falls");
    eprintln!("open loop: fell at {fall} s");
    assert!(fall < 1.0, "fell at {fall}");
}
