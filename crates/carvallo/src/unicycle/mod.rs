//! The mounted unicycle of the memoir's Part I, chapter II (n° 20–42, with n° 74 and n° 78):
//! a wheel of radius $R$ rolling like the hoop, and a rider held rigid in the trihedron Oijk
//! with its centre of gravity on the wheel's steepest diameter (n° 20–21).
//!
//! Every number comes from evaluators that [`scene!`](crate::scene) generates at compile time
//! from `generated/unicycle.ir` (`cargo xtask regen`, derivation `codegen/src/derive/unicycle/mod.rs`).
//! The rider's constants are those of n° 21: mass $\mu$, height $z$ of its centre of gravity
//! on Ok (called $h$ from n° 39), moments $A, B, C$ about $I, j, k$ at the contact point and
//! the product $L = \sum m\zeta\xi$; the wheel has mass $\mu_1$ and moments $A_1, B_1, C_1$
//! (for a thin hoop $\tfrac32\mu_1R^2, 2\mu_1R^2, \tfrac12\mu_1R^2$, n° 4). Unlike the memoir's
//! n° 24, the rider's and the wheel's letters are never merged here.

pub mod discussion;
/// The rider's pitch about the axle (n° 42) and the rolling rate held by the pedals (n° 78).
pub mod variants;

use std::sync::atomic::AtomicBool;

use crate::error::ParameterError;
use crate::numerics::integrate::{
    conservative_until, Grid, IntegrateError, Integration, Threshold,
};
use crate::numerics::ode::EnergyDrift;

/// A motion computed by [`Unicycle::simulate_with`]: the states $(\theta, p, n, s)$ at the
/// grid's sample times and the [`EnergyDrift`].
pub type Trajectory = crate::numerics::ode::Trajectory<[f64; 4], EnergyDrift>;

crate::scene! {
    /// The full model's $p'$, $n'$, $s'$ and its energy (motor moment 0).
    pub mod motion_scene {
        model: unicycle,
        outputs: [pns_dp, pns_dn, pns_ds, energy],
    }
}

crate::scene! {
    /// Steady states of the full model: (E) of n° 29, (D) of n° 30, and the stability first
    /// member (n° 76 determinant, L = 0) of the full and of the simplified model of n° 33.
    pub mod steady_scene {
        model: unicycle,
        outputs: [equilibrium, skid, stability, stability_simplified],
    }
}

crate::scene! {
    /// Every output of the unicycle program (derived and transcribed), for the concordance.
    pub mod all_scene {
        model: unicycle,
        outputs: [
            pns_dp, pns_dn, pns_ds, energy, rider_p, rider_n, rider_s, wheel_p, wheel_n, wheel_s,
            equilibrium, skid_full, skid, equilibrium_n32, skid_n32, stability_simplified,
            stability, stability_n39, stability_n40, trinomial_n41, char78_c0, char78_c1,
            char78_c2, memoir_rider_p, memoir_rider_n, memoir_rider_s, memoir_wheel_p,
            memoir_wheel_n, memoir_wheel_s, memoir_eq_p, memoir_eq_n, memoir_eq_s,
            memoir_equilibrium, memoir_skid_full, memoir_skid, memoir_equilibrium_n32,
            memoir_skid_n32, memoir_stability_n39, memoir_stability_n40, memoir_trinomial_n41,
            memoir_product_78, memoir_sum_78,
        ],
    }
}

/// The rider's constants of n° 21.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rider {
    /// Mass $\mu$ (kg).
    pub mass: f64,
    /// Height $z$ (or $h$) of the centre of gravity on Ok (m).
    pub height: f64,
    /// $A = \sum m(\eta^2 + \zeta^2)$ (kg m²).
    pub a: f64,
    /// $B = \sum m(\zeta^2 + \xi^2)$ (kg m²).
    pub b: f64,
    /// $C = \sum m(\xi^2 + \eta^2)$ (kg m²).
    pub c: f64,
    /// $L = \sum m\zeta\xi$ (kg m²).
    pub l: f64,
}

/// The wheel: mass and moments of inertia about $I$, $j$, $k$ at the contact point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wheel {
    /// Mass $\mu_1$ (kg).
    pub mass: f64,
    /// $A_1$ (kg m²).
    pub a1: f64,
    /// $B_1$ (kg m²).
    pub b1: f64,
    /// $C_1$ (kg m²).
    pub c1: f64,
}

impl Wheel {
    /// A thin homogeneous hoop of mass `mass` and radius `radius` (n° 4):
    /// $A_1 = \tfrac32\mu_1R^2$, $B_1 = 2\mu_1R^2$, $C_1 = \tfrac12\mu_1R^2$.
    pub fn hoop(mass: f64, radius: f64) -> Wheel {
        let m = mass * radius * radius;
        Wheel { mass, a1: 1.5 * m, b1: 2.0 * m, c1: 0.5 * m }
    }
}

/// A mounted unicycle with validated parameters.
///
/// # Example
/// ```
/// use carvallo::unicycle::{Rider, Unicycle, Wheel};
///
/// let rider = Rider { mass: 60.0, height: 1.25, a: 100.0, b: 99.5, c: 1.4, l: 0.0 };
/// let u = Unicycle::new(0.5, 9.81, rider, Wheel::hoop(5.0, 0.5))?;
/// // Upright straight running is a steady state: (E) vanishes at θ = 0, n = 0.
/// assert_eq!(u.equilibrium(0.0, 2.0, 0.0), 0.0);
/// # Ok::<(), carvallo::ParameterError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Unicycle {
    radius: f64,
    g: f64,
    rider: Rider,
    wheel: Wheel,
}

fn check_nonnegative(name: &'static str, value: f64) -> Result<f64, ParameterError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(ParameterError::InvalidParameter { name, value, reason: "must be finite and >= 0" })
    }
}

impl Unicycle {
    /// A unicycle of wheel radius `radius` (m) under gravity `g` (m/s²).
    ///
    /// # Errors
    /// [`ParameterError::InvalidParameter`] naming the first offending value: `radius`, `g`,
    /// `rider.mass`, `rider.height`, `rider.a`, `rider.b`, `rider.c` must be positive;
    /// `rider.l` finite; the wheel's values finite and non-negative; the rider's moments must
    /// satisfy the triangle inequalities of a mass distribution ($A \le B + C$ and
    /// cyclically), reported on the moment that breaks it; the wheel must be of revolution about
    /// its axis, $A_1 = C_1 + \mu_1R^2$ (as the hoop of n° 7), which the derivation's energy
    /// conservation needs.
    pub fn new(
        radius: f64,
        g: f64,
        rider: Rider,
        wheel: Wheel,
    ) -> Result<Unicycle, ParameterError> {
        ParameterError::check_positive("radius", radius)?;
        ParameterError::check_positive("g", g)?;
        ParameterError::check_positive("rider.mass", rider.mass)?;
        ParameterError::check_positive("rider.height", rider.height)?;
        ParameterError::check_positive("rider.a", rider.a)?;
        ParameterError::check_positive("rider.b", rider.b)?;
        ParameterError::check_positive("rider.c", rider.c)?;
        if !rider.l.is_finite() {
            return Err(ParameterError::InvalidParameter {
                name: "rider.l",
                value: rider.l,
                reason: "must be finite",
            });
        }
        for (name, value, others) in [
            ("rider.a", rider.a, rider.b + rider.c),
            ("rider.b", rider.b, rider.c + rider.a),
            ("rider.c", rider.c, rider.a + rider.b),
        ] {
            if value > others {
                return Err(ParameterError::InvalidParameter {
                    name,
                    value,
                    reason: "exceeds the sum of the other two moments",
                });
            }
        }
        check_nonnegative("wheel.mass", wheel.mass)?;
        check_nonnegative("wheel.a1", wheel.a1)?;
        check_nonnegative("wheel.b1", wheel.b1)?;
        check_nonnegative("wheel.c1", wheel.c1)?;
        let revolution = wheel.c1 + wheel.mass * radius * radius;
        if (wheel.a1 - revolution).abs() > 1e-9 * wheel.a1.max(revolution) {
            return Err(ParameterError::InvalidParameter {
                name: "wheel.a1",
                value: wheel.a1,
                reason: "must equal c1 + mass radius^2 (a wheel of revolution)",
            });
        }
        Ok(Unicycle { radius, g, rider, wheel })
    }

    /// The radius $R$ (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The rate unit $\sqrt{g/R}$ (1/s) of n° 32.
    pub fn rate_unit(&self) -> f64 {
        (self.g / self.radius).sqrt()
    }

    /// The right-hand side of the full equations (n° 22–24, motor moment 0) for the state
    /// $(\theta, p, n, s)$: $(\theta', p', n', s')$.
    pub fn rhs(&self, state: [f64; 4]) -> [f64; 4] {
        let out = self.motion(state);
        [state[1], out.pns_dp, out.pns_dn, out.pns_ds]
    }

    /// Total energy $T + V$ (J) in the state $(\theta, p, n, s)$.
    pub fn energy(&self, state: [f64; 4]) -> f64 {
        self.motion(state).energy
    }

    /// The generated motion outputs (accelerations, energy) in the state $(\theta, p, n, s)$.
    fn motion(&self, state: [f64; 4]) -> motion_scene::Out {
        let [theta, p, n, s] = state;
        let (r, w) = (&self.rider, &self.wheel);
        motion_scene::eval(&motion_scene::Args {
            R: self.radius,
            g: self.g,
            mu: r.mass,
            z: r.height,
            A: r.a,
            B: r.b,
            C: r.c,
            L: r.l,
            mu1: w.mass,
            A1: w.a1,
            B1: w.b1,
            C1: w.c1,
            theta,
            p,
            n,
            s,
        })
    }

    fn steady(&self, theta: f64, s: f64, n: f64) -> steady_scene::Out {
        let (r, w) = (&self.rider, &self.wheel);
        steady_scene::eval(&steady_scene::Args {
            R: self.radius,
            g: self.g,
            mu: r.mass,
            z: r.height,
            A: r.a,
            B: r.b,
            C: r.c,
            mu1: w.mass,
            A1: w.a1,
            B1: w.b1,
            C1: w.c1,
            theta,
            n,
            s,
        })
    }

    /// (E) of n° 29 for the full model (N m): zero in a steady state $(\theta, s, n)$.
    pub fn equilibrium(&self, theta: f64, s: f64, n: f64) -> f64 {
        self.steady(theta, s, n).equilibrium
    }

    /// The steady skid tendency D of n° 30 (dimensionless).
    pub fn skid(&self, theta: f64, s: f64, n: f64) -> f64 {
        self.steady(theta, s, n).skid
    }

    /// The stability first member (1/s²) of the full model with L taken as 0: the constant
    /// term of the characteristic equation of n° 76 reduced by λ²; positive iff stable.
    pub fn stability(&self, theta: f64, s: f64, n: f64) -> f64 {
        self.steady(theta, s, n).stability
    }

    /// The same for the memoir's simplified model of n° 33 (rider's letters only, L = 0, the
    /// wheel kept only through $(B_1 - \mu_1R^2)ps\cos\theta$).
    pub fn stability_simplified(&self, theta: f64, s: f64, n: f64) -> f64 {
        self.steady(theta, s, n).stability_simplified
    }

    /// The smallest rolling rate $s > 0$ (1/s) that makes upright straight running stable
    /// (θ = 0, n = 0) in the full model, by bisection on the generated stability first member;
    /// `None` when no rate up to $10^3\sqrt{g/R}$ does.
    pub fn straight_running_threshold(&self) -> Option<f64> {
        let f = |s: f64| self.stability(0.0, s, 0.0);
        let hi = 1e3 * self.rate_unit();
        if f(hi) <= 0.0 {
            return None;
        }
        let (mut lo, mut hi) = (0.0, hi);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if f(mid) > 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Some(hi)
    }

    /// Integrates the full equations from `state0` $= (\theta, p, n, s)$ over `grid` by `how`
    /// (RK4 at the grid's step, or an error-controlled pair sampled on the grid), until the
    /// grid's end or the first of `stops` met (index 0 of the state is the lean θ); the energy
    /// drift is measured at every accepted step.
    ///
    /// # Errors
    /// [`IntegrateError::Model`] with [`ParameterError::InvalidParameter`] for an unusable
    /// tolerance or a non-finite state; the adaptive methods' failures.
    pub fn simulate_with(
        &self,
        state0: [f64; 4],
        grid: &Grid,
        how: &Integration,
        stops: &[Threshold],
    ) -> Result<Trajectory, IntegrateError<ParameterError>> {
        self.simulate_until(state0, grid, how, stops, &AtomicBool::new(false))
    }

    /// [`simulate_with`](Self::simulate_with) that also ends when `stop` is set (Ctrl-C): the
    /// samples up to the last accepted step, its time in
    /// [`Trajectory::interrupted`](crate::numerics::ode::Trajectory::interrupted).
    ///
    /// # Errors
    /// As [`simulate_with`](Self::simulate_with).
    pub fn simulate_until(
        &self,
        state0: [f64; 4],
        grid: &Grid,
        how: &Integration,
        stops: &[Threshold],
        stop: &AtomicBool,
    ) -> Result<Trajectory, IntegrateError<ParameterError>> {
        crate::hoop::check_run(state0, how)?;
        conservative_until(how, grid, state0, |y| self.rhs(y), |y| self.energy(y), stops, stop)
            .map_err(IntegrateError::widen)
    }

    /// Integrates the full equations with the classical Runge–Kutta method: `steps` steps of
    /// `dt` seconds from `state`; returns the final state.
    pub fn simulate(&self, mut state: [f64; 4], dt: f64, steps: usize) -> [f64; 4] {
        for _ in 0..steps {
            state = crate::numerics::ode::rk4_step(|y| self.rhs(y), state, dt);
        }
        state
    }
}
