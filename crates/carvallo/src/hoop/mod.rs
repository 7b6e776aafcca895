//! The rolling hoop of the memoir's Part I, chapter I (n° 1–19): a thin homogeneous ring of
//! radius $R$ and mass $\mu$ rolling without slipping on a horizontal plane under gravity $g$.
//!
//! Every number computed here comes from evaluators that the [`scene!`](crate::scene) macro
//! generates at compile time from `generated/hoop.ir`, the output of the symbolic derivation
//! (`cargo xtask regen`). The memoir's notation is kept:
//!
//! * $\theta$: angle of the hoop's plane with the vertical (*angle de chute*, n° 1);
//! * $p$: fall rate $\theta'$ (*vitesse de chute*); $s$: rolling rate (*vitesse de roulement*);
//!   $n$: turning rate about the vertical (*vitesse de conversion*), n° 2;
//! * $q = s + n\sin\theta$, $r = n\cos\theta$: the rotation's components on the hoop's axis $j$
//!   and on the steepest diameter $k$ (n° 2, formulas (2)).
//!
//! [`Hoop`] holds validated physical parameters; the [`normalised`] module has the
//! dimensionless forms of n° 12 ($g/R = 1$).

pub mod discussion;
/// The fall laws of n° 9 (uniform, exponential, pendular) from a state near a steady state.
pub mod fall;

use std::sync::atomic::AtomicBool;

use crate::error::ParameterError;
use crate::numerics::integrate::{
    conservative_until, Grid, IntegrateError, Integration, Threshold,
};
use crate::numerics::ode::rk4_step;

crate::scene! {
    /// System (1) of n° 7/8: $p'$, $q'$, $r'$ as functions of $\theta, p, q, r$.
    pub mod pqr_scene {
        model: hoop,
        outputs: [pqr_dp, pqr_dq, pqr_dr],
    }
}

crate::scene! {
    /// System (2) of n° 7: $p'$, $n'$, $s'$ as functions of $\theta, p, n, s$.
    pub mod pns_scene {
        model: hoop,
        outputs: [pns_dp, pns_dn, pns_ds],
    }
}

crate::scene! {
    /// Total energy $T + V$ (the *forces vives* check of n° 7).
    pub mod energy_scene {
        model: hoop,
        outputs: [energy],
    }
}

crate::scene! {
    /// The moments of inertia $A$, $B$, $C$ of n° 4.
    pub mod inertia_scene {
        model: hoop,
        outputs: [inertia_a, inertia_b, inertia_c],
    }
}

crate::scene! {
    /// Equilibrium (E) of n° 8, in physical units.
    pub mod equilibrium_scene {
        model: hoop,
        outputs: [equilibrium],
    }
}

crate::scene! {
    /// Stability (S) of n° 9, in physical units.
    pub mod stability_scene {
        model: hoop,
        outputs: [stability],
    }
}

crate::scene! {
    /// Skid tendency D of n° 10.
    pub mod skid_scene {
        model: hoop,
        outputs: [skid],
    }
}

crate::scene! {
    /// The normalised equilibrium of n° 12 ($g/R = 1$).
    pub mod equilibrium_n12_scene {
        model: hoop,
        outputs: [equilibrium_n12],
    }
}

crate::scene! {
    /// The normalised stability of n° 12 ($g/R = 1$).
    pub mod stability_n12_scene {
        model: hoop,
        outputs: [stability_n12],
    }
}

crate::scene! {
    /// The normalised skid tendency of n° 12 ($g/R = 1$).
    pub mod skid_n12_scene {
        model: hoop,
        outputs: [skid_n12],
    }
}

/// A rolling hoop with validated physical parameters (memoir n° 1: "une circonférence
/// homogène de rayon $R$ et de masse $\mu$").
///
/// # Example
/// ```
/// use carvallo::hoop::Hoop;
///
/// let hoop = Hoop::new(0.5, 1.0, 9.81)?;
/// // Straight upright rolling is an equilibrium: (E) vanishes at θ = 0, n = 0.
/// assert_eq!(hoop.equilibrium(0.0, 3.0, 0.0), 0.0);
/// # Ok::<(), carvallo::ParameterError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hoop {
    radius: f64,
    mass: f64,
    g: f64,
}

pub use crate::numerics::ode::EnergyDrift;

/// A trajectory computed by [`Hoop::simulate_pns`]: the states $(\theta, p, n, s)$ at times
/// $0, \Delta t, \dots, N\Delta t$ ($N + 1$ samples) and the [`EnergyDrift`], whose fields and
/// [`relative_energy_drift`](EnergyDrift::relative_energy_drift) are read through the
/// trajectory.
pub type Trajectory = crate::numerics::ode::Trajectory<[f64; 4], EnergyDrift>;

impl Hoop {
    /// A hoop of radius $R$ = `radius` (m), mass $\mu$ = `mass` (kg), under the gravitational
    /// acceleration `g` (m/s²).
    ///
    /// # Errors
    /// [`ParameterError::InvalidParameter`] naming `radius`, `mass` or `g` when that value is
    /// not finite or not strictly positive.
    ///
    /// # Example
    /// ```
    /// use carvallo::{hoop::Hoop, ParameterError};
    ///
    /// let err = Hoop::new(-0.5, 1.0, 9.81).unwrap_err();
    /// assert_eq!(
    ///     err,
    ///     ParameterError::InvalidParameter { name: "radius", value: -0.5, reason: "must be positive" }
    /// );
    /// ```
    pub fn new(radius: f64, mass: f64, g: f64) -> Result<Hoop, ParameterError> {
        Ok(Hoop {
            radius: ParameterError::check_positive("radius", radius)?,
            mass: ParameterError::check_positive("mass", mass)?,
            g: ParameterError::check_positive("g", g)?,
        })
    }

    /// The radius $R$ (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The mass $\mu$ (kg).
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// The gravitational acceleration $g$ (m/s²).
    pub fn g(&self) -> f64 {
        self.g
    }

    /// The rate $\sqrt{g/R}$ (1/s) that n° 12 takes as the unit of $s$ and $n$.
    pub fn rate_unit(&self) -> f64 {
        (self.g / self.radius).sqrt()
    }

    /// The moments of inertia $[A, B, C]$ about $I$, $j$, $k$ at the contact point (kg m²),
    /// memoir n° 4, formulas (7):
    /// $$A = \tfrac32\mu R^2,\qquad B = 2\mu R^2,\qquad C = \tfrac12\mu R^2.$$
    ///
    /// # Example
    /// ```
    /// let hoop = carvallo::hoop::Hoop::new(2.0, 1.0, 9.81)?;
    /// let [a, b, c] = hoop.inertia();
    /// assert!((a - 6.0).abs() < 1e-12 && (b - 8.0).abs() < 1e-12 && (c - 2.0).abs() < 1e-12);
    /// # Ok::<(), carvallo::ParameterError>(())
    /// ```
    pub fn inertia(&self) -> [f64; 3] {
        let out = inertia_scene::eval(&inertia_scene::Args { R: self.radius, mu: self.mass });
        [out.inertia_a, out.inertia_b, out.inertia_c]
    }

    /// The right-hand side of system (1) of n° 7 (solved for the derivatives in n° 8), for the
    /// state $(\theta, p, q, r)$; returns $(\theta', p', q', r')$ with $\theta' = p$. The memoir
    /// prints
    /// $$\tfrac32 p' - 2qr + \tfrac12 r^2\tan\theta = \tfrac gR\sin\theta,\qquad
    ///   2q' + rp = 0,\qquad \tfrac12 r' - \tfrac12 rp\tan\theta + pq = 0.$$
    ///
    /// # Example
    /// ```
    /// let hoop = carvallo::hoop::Hoop::new(1.0, 1.0, 9.81)?;
    /// // Upright and rolling straight: nothing changes.
    /// assert_eq!(hoop.rhs_pqr([0.0, 0.0, 2.0, 0.0]), [0.0, 0.0, 0.0, 0.0]);
    /// # Ok::<(), carvallo::ParameterError>(())
    /// ```
    pub fn rhs_pqr(&self, state: [f64; 4]) -> [f64; 4] {
        let [theta, p, q, r] = state;
        let out = pqr_scene::eval(&pqr_scene::Args { R: self.radius, g: self.g, theta, p, q, r });
        [p, out.pqr_dp, out.pqr_dq, out.pqr_dr]
    }

    /// The right-hand side of system (2) of n° 7, for the state $(\theta, p, n, s)$; returns
    /// $(\theta', p', n', s')$ with $\theta' = p$. The memoir prints
    /// $$\tfrac32 p' - 2sn\cos\theta - \tfrac32 n^2\sin\theta\cos\theta = \tfrac gR\sin\theta,
    ///   \qquad \tfrac12 n' + \frac{ps}{\cos\theta} = 0,\qquad
    ///   2s' - 4ps\tan\theta + 3pn\cos\theta = 0.$$
    ///
    /// # Example
    /// ```
    /// let hoop = carvallo::hoop::Hoop::new(1.0, 1.0, 9.81)?;
    /// let [dtheta, dp, _, _] = hoop.rhs_pns([0.1, 0.0, 0.0, 0.0]);
    /// // A hoop at rest falls like a pendulum: p' = (2g / 3R) sin θ (n° 18).
    /// assert_eq!(dtheta, 0.0);
    /// assert!((dp - 2.0 * 9.81 * 0.1_f64.sin() / 3.0).abs() < 1e-12);
    /// # Ok::<(), carvallo::ParameterError>(())
    /// ```
    pub fn rhs_pns(&self, state: [f64; 4]) -> [f64; 4] {
        let [theta, p, n, s] = state;
        let out = pns_scene::eval(&pns_scene::Args { R: self.radius, g: self.g, theta, p, n, s });
        [p, out.pns_dp, out.pns_dn, out.pns_ds]
    }

    /// The total energy (J) at the state $(\theta, p, n, s)$, kinetic energy of the rotation
    /// about the contact point plus potential energy:
    /// $$T + V = \mu R^2\left(\tfrac34 p^2 + q^2 + \tfrac14 r^2\right) + \mu g R\cos\theta,
    ///   \qquad q = s + n\sin\theta,\ r = n\cos\theta.$$
    /// It is conserved by systems (1) and (2) (the *équation des forces vives*, n° 7).
    pub fn energy(&self, state: [f64; 4]) -> f64 {
        let [theta, p, n, s] = state;
        let args = energy_scene::Args { R: self.radius, g: self.g, mu: self.mass, theta, p, n, s };
        energy_scene::eval(&args).energy
    }

    /// The equilibrium function (E) of n° 8 (1/s²): the fall acceleration $p'$ at $p = 0$,
    /// $$E = \frac{2g\sin\theta}{3R} + \frac{4sn}{3}\cos\theta + n^2\sin\theta\cos\theta.$$
    /// The hoop rolls steadily at $(\theta, s, n)$ exactly when $E = 0$.
    pub fn equilibrium(&self, theta: f64, s: f64, n: f64) -> f64 {
        let args = equilibrium_scene::Args { R: self.radius, g: self.g, theta, s, n };
        equilibrium_scene::eval(&args).equilibrium
    }

    /// The first member of the stability condition (S) of n° 9 (1/s²), derived as in n° 76–77
    /// (linearised steady state, characteristic determinant, $\lambda^2$ dropped); the memoir
    /// prints
    /// $$S = -\frac{2g\cos\theta}{3R} + n^2 + \frac{8sn\sin\theta}{3} + \frac{8s^2}{3},$$
    /// and a steady state is stable when $S > 0$.
    pub fn stability(&self, theta: f64, s: f64, n: f64) -> f64 {
        let args = stability_scene::Args { R: self.radius, g: self.g, theta, s, n };
        stability_scene::eval(&args).stability
    }

    /// The skid tendency D of n° 10 (dimensionless): the tangent of the angle between the
    /// vertical and the resultant of weight and centrifugal force, signed positive towards $J$,
    /// $$D = -\frac Rg\left(n^2\sin\theta + sn\right).$$
    /// The hoop does not skid while $|D|$ is below the friction coefficient.
    pub fn skid(&self, theta: f64, s: f64, n: f64) -> f64 {
        let args = skid_scene::Args { R: self.radius, g: self.g, theta, s, n };
        skid_scene::eval(&args).skid
    }

    /// The two turning rates $n_1 \le n_2$ (1/s) of steady rolling at lean $\theta$ and rolling
    /// rate $s$: the roots of (E) of n° 8, a quadratic in $n$,
    /// $$n^2\sin\theta\cos\theta + \frac{4s}{3}\cos\theta\,n + \frac{2g\sin\theta}{3R} = 0.$$
    /// Its coefficients are read off the generated [`Hoop::equilibrium`] evaluator at
    /// $n = 0, \pm\sqrt{g/R}$ (no formula is repeated here), and the roots are computed with
    /// the cancellation-free form $q = -\tfrac12(b + \operatorname{sign}(b)\sqrt{b^2 - 4ac})$,
    /// $n = q/a,\ c/q$.
    ///
    /// Returns `None` when there is no pair of finite real roots: when the discriminant is
    /// negative (the point $(\theta, s)$ lies left of the curve AE of n° 13, no steady turning
    /// exists), when the $n^2$ coefficient vanishes ($\theta = 0$: upright rolling, where the
    /// memoir's roots are $n_1 = -\infty$, $n_2 = 0$, n° 14, or $\cos\theta = 0$), or when an
    /// argument is not finite. Near $\theta = 0$ the relative accuracy of the coefficients
    /// degrades like $\varepsilon/|\theta|$.
    ///
    /// # Example
    /// ```
    /// let hoop = carvallo::hoop::Hoop::new(0.5, 1.0, 9.81)?;
    /// let (theta, s) = (0.3, 3.0 * hoop.rate_unit());
    /// let [n1, n2] = hoop.steady_turning_rates(theta, s).expect("real roots");
    /// assert!(n1 < n2 && n2 < 0.0); // the hoop turns towards the side it leans to (n° 12)
    /// let scale = hoop.rate_unit().powi(2);
    /// assert!(hoop.equilibrium(theta, s, n1).abs() < 1e-12 * scale * (n1 / hoop.rate_unit()).powi(2));
    /// assert!(hoop.equilibrium(theta, s, n2).abs() < 1e-12 * scale);
    /// assert!(hoop.steady_turning_rates(0.3, 0.1).is_none()); // too slow to turn steadily
    /// # Ok::<(), carvallo::ParameterError>(())
    /// ```
    pub fn steady_turning_rates(&self, theta: f64, s: f64) -> Option<[f64; 2]> {
        let nu = self.rate_unit();
        let c = self.equilibrium(theta, s, 0.0);
        let plus = self.equilibrium(theta, s, nu);
        let minus = self.equilibrium(theta, s, -nu);
        let a = (plus + minus - 2.0 * c) / (2.0 * nu * nu);
        let b = (plus - minus) / (2.0 * nu);
        quadratic_roots(a, b, c)
    }

    /// Integrates system (2) with the classical fixed-step fourth-order Runge–Kutta method from
    /// `state0` $= (\theta, p, n, s)$ for `steps` steps of `dt` seconds, and measures the energy
    /// drift (the exact motion conserves [`Hoop::energy`], n° 7). The only allocation is the
    /// returned trajectory.
    ///
    /// # Errors
    /// [`ParameterError::InvalidParameter`] naming `dt` when it is not finite and positive.
    ///
    /// # Example
    /// ```
    /// let hoop = carvallo::hoop::Hoop::new(0.5, 1.0, 9.81)?;
    /// // Leaning 0.1 rad, rolling fast (s = 3 sqrt(g/R)), not turning, not falling.
    /// let s = 3.0 * hoop.rate_unit();
    /// let traj = hoop.simulate_pns([0.1, 0.0, 0.0, s], 1e-3, 2000)?;
    /// assert_eq!(traj.len(), 2001);
    /// assert!((traj.duration() - 2.0).abs() < 1e-12);
    /// assert!(traj.relative_energy_drift() < 1e-9);
    /// // Fast rolling is stable (n° 14): the lean stays bounded.
    /// assert!(traj.samples.iter().all(|x| x[0].abs() < 0.5));
    /// # Ok::<(), carvallo::ParameterError>(())
    /// ```
    pub fn simulate_pns(
        &self,
        state0: [f64; 4],
        dt: f64,
        steps: usize,
    ) -> Result<Trajectory, ParameterError> {
        let dt = ParameterError::check_positive("dt", dt)?;
        let energy0 = self.energy(state0);
        let drift = EnergyDrift { energy0, max_energy_drift: 0.0 };
        let mut trajectory = Trajectory::with_capacity(dt, steps.saturating_add(1), drift);
        let mut max_energy_drift: f64 = 0.0;
        let mut x = state0;
        trajectory.push(0.0, x);
        for k in 1..=steps {
            x = rk4_step(|y| self.rhs_pns(y), x, dt);
            max_energy_drift = max_energy_drift.max((self.energy(x) - energy0).abs());
            trajectory.push(k as f64 * dt, x);
        }
        trajectory.diagnostics.max_energy_drift = max_energy_drift;
        Ok(trajectory)
    }

    /// Integrates system (2) from `state0` $= (\theta, p, n, s)$ over `grid` by `how` (RK4 at
    /// the grid's step, or an error-controlled pair sampled on the grid), until the grid's end
    /// or the first of `stops` met (on components of the state: index 0 is the lean θ); the
    /// energy drift is measured at every accepted step. [`simulate_pns`](Self::simulate_pns)
    /// is RK4 on the grid of `steps` steps of `dt`, sampled at every step.
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
        check_run(state0, how)?;
        conservative_until(how, grid, state0, |y| self.rhs_pns(y), |y| self.energy(y), stops, stop)
            .map_err(IntegrateError::widen)
    }
}

/// Checks the settings and the start of a simulation of the hoop or the unicycle.
pub(crate) fn check_run(
    state0: [f64; 4],
    how: &Integration,
) -> Result<(), IntegrateError<ParameterError>> {
    let bad = |(name, value, reason)| {
        IntegrateError::Model(ParameterError::InvalidParameter { name, value, reason })
    };
    if let Some(u) = how.unusable() {
        return Err(bad(u));
    }
    for (name, v) in ["theta", "p", "n", "s"].into_iter().zip(state0) {
        if !v.is_finite() {
            return Err(bad((name, v, "must be finite")));
        }
    }
    Ok(())
}

/// The real roots $r_1 \le r_2$ of $a x^2 + b x + c$, or `None` when $a = 0$, the discriminant
/// is negative or a coefficient is not finite.
fn quadratic_roots(a: f64, b: f64, c: f64) -> Option<[f64; 2]> {
    if !(a.is_finite() && b.is_finite() && c.is_finite()) || a == 0.0 {
        return None;
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return None;
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    let (x1, x2) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
    Some(if x1 <= x2 { [x1, x2] } else { [x2, x1] })
}

/// The dimensionless forms of n° 12: rates in the unit $\sqrt{g/R}$ (which amounts to
/// $g/R = 1$), and (E) divided by $\tfrac32\sin\theta\cos\theta$ so that its $n^2$
/// coefficient is 1. They apply to every hoop ("un seul barème applicable à tous les cerceaux
/// et à toutes les altitudes").
pub mod normalised {
    use super::{equilibrium_n12_scene, skid_n12_scene, stability_n12_scene};

    /// (E) of n° 12, printed as
    /// $$E(n) = n^2 + \frac{4s}{3\sin\theta}n + \frac{2}{3\cos\theta}.$$
    /// Undefined (infinite or NaN) at $\theta = 0$, where the division by $\sin\theta$ is not
    /// allowed (n° 12, footnote).
    pub fn equilibrium(theta: f64, s: f64, n: f64) -> f64 {
        equilibrium_n12_scene::eval(&equilibrium_n12_scene::Args { theta, s, n }).equilibrium_n12
    }

    /// (S) of n° 12 (positive ⇔ stable), printed as
    /// $$S(n) = n^2 + \frac{8s\sin\theta}{3}n + \frac{8s^2}{3} - \frac{2\cos\theta}{3}.$$
    ///
    /// # Example
    /// ```
    /// use carvallo::hoop::normalised::stability;
    /// // Upright straight rolling is stable above s² = 1/4 (n° 14, n° 18).
    /// assert!(stability(0.0, 0.51, 0.0) > 0.0 && stability(0.0, 0.49, 0.0) < 0.0);
    /// ```
    pub fn stability(theta: f64, s: f64, n: f64) -> f64 {
        stability_n12_scene::eval(&stability_n12_scene::Args { theta, s, n }).stability_n12
    }

    /// (D) of n° 12, printed as $D = -n^2\sin\theta - sn$.
    pub fn skid(theta: f64, s: f64, n: f64) -> f64 {
        skid_n12_scene::eval(&skid_n12_scene::Args { theta, s, n }).skid_n12
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_roots_are_ordered_and_exact_on_simple_cases() {
        assert_eq!(quadratic_roots(1.0, -3.0, 2.0), Some([1.0, 2.0]));
        assert_eq!(quadratic_roots(1.0, 0.0, 1.0), None);
        assert_eq!(quadratic_roots(0.0, 1.0, 1.0), None);
        assert_eq!(quadratic_roots(2.0, 0.0, 0.0), Some([0.0, 0.0]));
    }
}
