//! The nonlinear simulation: the state $(x, y, \psi, \theta, \dot\theta, \dot\theta_L,
//! \dot\theta_R)$ ([`STATE_NAMES`]) integrated by the workspace's integrator
//! ([`crate::numerics::integrate`], the bicycle's), the left contact's position and the
//! heading from the dependent rates, the speeds from $M \dot u = f$; the motor torques are a
//! function of time and state (open loop, or a [`Feedback`](super::Feedback)). A run ends
//! early when the body falls, $|\theta|$ reaching [`FALL_ANGLE`]: a result
//! ([`Trajectory::fall`](crate::numerics::ode::Trajectory::fall)), not an error.

use std::sync::atomic::AtomicBool;

use super::{WheeledPendulum, WheeledPendulumError};
use crate::error::ParameterError;
use crate::numerics::integrate::{integrate_until, Grid, IntegrateError, Integration, Point};
use crate::numerics::ode::EnergyDrift;

/// The names of the simulation state's components: the left contact's position on the ground
/// (`x` forward, `y` right at the start, m), the heading `psi`, the pitch `theta` (rad) and the
/// speeds `thetad`, `thetaLd`, `thetaRd` (rad/s, the wheels' relative to the body).
pub const STATE_NAMES: [&str; 7] = ["x", "y", "psi", "theta", "thetad", "thetaLd", "thetaRd"];

/// The pitch at which the body has fallen (rad): lying level with the axle, $\pi/2$.
pub const FALL_ANGLE: f64 = std::f64::consts::FRAC_PI_2;

/// A motion computed by [`WheeledPendulum::simulate`]: the states ([`STATE_NAMES`]) at the
/// grid's sample times (the fall's state last when the body fell) and the energy measured over
/// the accepted steps. With the motors off the energy is conserved and
/// [`EnergyDrift::max_energy_drift`] is the integrator's error; with torques it is the largest
/// change of the energy, the motors' work.
pub type Trajectory = crate::numerics::ode::Trajectory<[f64; 7], EnergyDrift>;

impl WheeledPendulum {
    /// Simulates from `x0` ([`STATE_NAMES`]) over `grid` by `how` with the motor torques
    /// `torques(t, x)` = $(T_L, T_R)$ (N m), until the grid's end or the fall
    /// ($|\theta| = $ [`FALL_ANGLE`], its time in
    /// [`Trajectory::fall`](crate::numerics::ode::Trajectory::fall), located on the
    /// interpolant).
    ///
    /// # Errors
    /// [`WheeledPendulumError::Parameter`] naming a start component (`x0.<name>`) that is not
    /// finite, or a start pitch `x0.theta` already at or beyond the fall; the integrator's
    /// failures (settings are not checked here: [`Integration::unusable`]).
    pub fn simulate(
        &self,
        x0: [f64; 7],
        torques: &dyn Fn(f64, &[f64; 7]) -> [f64; 2],
        grid: &Grid,
        how: &Integration,
    ) -> Result<Trajectory, IntegrateError<WheeledPendulumError>> {
        const NAMES: [&str; 7] =
            ["x0.x", "x0.y", "x0.psi", "x0.theta", "x0.thetad", "x0.thetaLd", "x0.thetaRd"];
        let bad = |name, value, reason| {
            IntegrateError::Model(WheeledPendulumError::Parameter(
                ParameterError::InvalidParameter { name, value, reason },
            ))
        };
        for (name, value) in NAMES.into_iter().zip(x0) {
            if !value.is_finite() {
                return Err(bad(name, value, "must be finite"));
            }
        }
        if x0[3].abs() >= FALL_ANGLE {
            return Err(bad("x0.theta", x0[3], "must be less than pi/2 in magnitude"));
        }
        let energy0 = self.energy(&x0);
        let mut trajectory = Trajectory::with_capacity(
            grid.h,
            grid.samples(),
            EnergyDrift { energy0, max_energy_drift: 0.0 },
        );
        let mut drift = 0.0f64;
        let mut rhs = |t: f64, x: &[f64; 7]| -> Result<[f64; 7], WheeledPendulumError> {
            Ok(self.rate(x, torques(t, x)))
        };
        let mut fall =
            |x: &[f64; 7]| -> Result<f64, WheeledPendulumError> { Ok(FALL_ANGLE - x[3].abs()) };
        let mut observe =
            |point: Point, t: f64, x: &[f64; 7]| -> Result<(), WheeledPendulumError> {
                match point {
                    Point::Step => drift = drift.max((self.energy(x) - energy0).abs()),
                    Point::Sample(_) | Point::Event => trajectory.push(t, *x),
                }
                Ok(())
            };
        let outcome = integrate_until(
            how,
            grid,
            x0,
            &mut rhs,
            &mut [&mut fall],
            &mut observe,
            &AtomicBool::new(false),
        )?;
        trajectory.diagnostics.max_energy_drift = drift;
        trajectory.stats = outcome.stats;
        trajectory.event = outcome.event.map(|c| (c.index, c.t));
        trajectory.fall = outcome.event.map(|c| c.t);
        Ok(trajectory)
    }
}
