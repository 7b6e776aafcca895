//! The classical fourth-order Runge–Kutta step, for any fixed state size, the
//! [`Trajectory`] every model's simulation returns and the counts it carries ([`Stats`]).
//! [`crate::numerics::integrate`] builds on these; this module uses nothing of it.

use std::ops::Deref;

/// What an integration counted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Evaluations of the right-hand side (the adaptive methods' initial step choice
    /// included).
    pub rhs_evaluations: usize,
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps (zero for RK4).
    pub rejected_steps: usize,
}

/// One classical Runge–Kutta step of $x' = f(x)$ from `x` with step `dt`.
pub fn rk4_step<const N: usize>(
    f: impl Fn([f64; N]) -> [f64; N],
    x: [f64; N],
    dt: f64,
) -> [f64; N] {
    let axpy = |a: f64, k: [f64; N]| std::array::from_fn(|i| x[i] + a * k[i]);
    let k1 = f(x);
    let k2 = f(axpy(0.5 * dt, k1));
    let k3 = f(axpy(0.5 * dt, k2));
    let k4 = f(axpy(dt, k3));
    std::array::from_fn(|i| x[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

/// A computed motion: the sample times, one sample per time (a state, or a state with what the
/// model observes at it), what the integrator measured over the whole run (`diagnostics`: an
/// energy drift, a constraint residual), its counts (`stats`) and the event that ended it.
///
/// Each model names its own: [`hoop::Trajectory`](crate::hoop::Trajectory) is
/// `Trajectory<[f64; 4], hoop::EnergyDrift>`,
/// [`whipple::nonlinear::Trajectory`](crate::whipple::nonlinear::Trajectory) is
/// `Trajectory<nonlinear::Sample, nonlinear::Diagnostics>`. The fields of the diagnostics are
/// read through the trajectory (`Deref`): `trajectory.max_energy_drift` is
/// `trajectory.diagnostics.max_energy_drift`.
#[derive(Clone, Debug, PartialEq)]
pub struct Trajectory<S, D = ()> {
    /// The integration step (s) of RK4, the grid step of the samples for the adaptive
    /// methods; samples may be kept only every few steps.
    pub step: f64,
    /// The time of each sample (s), increasing, as many as [`samples`](Self::samples).
    pub times: Vec<f64>,
    /// The samples, in the order of [`times`](Self::times).
    pub samples: Vec<S>,
    /// What the integrator measured over the run.
    pub diagnostics: D,
    /// Right-hand side evaluations, accepted and rejected steps.
    pub stats: Stats,
    /// The event that ended the run (its index among the stop conditions and its time, the
    /// time of the last sample), `None` when the run reached its end.
    pub event: Option<(usize, f64)>,
    /// When the model's own limit ended the run (the nonlinear bicycle's lean reaching its
    /// fall angle: [`WhippleNonlinear::fall_angle`](crate::whipple::nonlinear::WhippleNonlinear::fall_angle)),
    /// the time of the last sample; `None` when it was not reached or the model has none.
    pub fall: Option<f64>,
    /// When the model's steer limit ended the run (the nonlinear bicycle's steer reaching its
    /// lock: [`WhippleNonlinear::steer_lock`](crate::whipple::nonlinear::WhippleNonlinear::steer_lock)),
    /// the time of the last sample; `None` otherwise.
    pub steer_lock: Option<f64>,
    /// When the model reached the neighbourhood of a configuration where its equations are
    /// singular (the nonlinear bicycle's pivots: [`SINGULAR_PIVOT`](crate::whipple::nonlinear::SINGULAR_PIVOT)),
    /// the time of the last sample; `None` otherwise.
    pub singular: Option<f64>,
    /// When a stop flag ended the run early (Ctrl-C), the time it reached (its last accepted
    /// step; the samples are those of the grid up to it); `None` otherwise.
    pub interrupted: Option<f64>,
}

impl<S, D> Trajectory<S, D> {
    /// An empty trajectory of step `step` with room for `capacity` samples.
    pub fn with_capacity(step: f64, capacity: usize, diagnostics: D) -> Trajectory<S, D> {
        Trajectory {
            step,
            times: Vec::with_capacity(capacity),
            samples: Vec::with_capacity(capacity),
            diagnostics,
            stats: Stats::default(),
            event: None,
            fall: None,
            steer_lock: None,
            singular: None,
            interrupted: None,
        }
    }

    /// Appends the sample `sample` at time `t` (after the last one).
    pub fn push(&mut self, t: f64, sample: S) {
        self.times.push(t);
        self.samples.push(sample);
    }

    /// The number of samples.
    pub fn len(&self) -> usize {
        self.samples.len()
    }

    /// Whether there is no sample.
    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }

    /// The first sample and its time, `None` when there is none.
    pub fn first(&self) -> Option<(f64, &S)> {
        Some((*self.times.first()?, self.samples.first()?))
    }

    /// The last sample and its time, `None` when there is none.
    pub fn last(&self) -> Option<(f64, &S)> {
        Some((*self.times.last()?, self.samples.last()?))
    }

    /// The samples with their times, in order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = (f64, &S)> + '_ {
        self.times.iter().copied().zip(&self.samples)
    }

    /// The time from the first sample to the last (s), zero when there are fewer than two.
    pub fn duration(&self) -> f64 {
        match (self.times.first(), self.times.last()) {
            (Some(a), Some(b)) => b - a,
            _ => 0.0,
        }
    }
}

impl<S, D> Deref for Trajectory<S, D> {
    type Target = D;

    fn deref(&self) -> &D {
        &self.diagnostics
    }
}

/// What a simulation of a conservative system measures over a run (the hoop's
/// `simulate_pns`, the unicycle's `simulate_with`): the energy, which the exact motion
/// conserves (memoir n° 7), and how far the integrator drifted from it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnergyDrift {
    /// The energy $T + V$ of the first state (J).
    pub energy0: f64,
    /// $\max_k |E_k - E_0|$ over the trajectory (J): the integrator's energy drift, a measure of
    /// its error since the exact motion conserves energy (n° 7).
    pub max_energy_drift: f64,
}

impl EnergyDrift {
    /// The energy drift relative to the initial energy, $\max_k |E_k - E_0| / |E_0|$.
    pub fn relative_energy_drift(&self) -> f64 {
        self.max_energy_drift / self.energy0.abs()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_trajectory_keeps_times_and_samples_together() {
        let mut t: Trajectory<[f64; 1], f64> = Trajectory::with_capacity(0.5, 3, 1e-9);
        assert!(t.is_empty() && t.first().is_none() && t.last().is_none());
        assert_eq!(t.duration(), 0.0);
        for k in 0..3 {
            t.push(k as f64 * t.step, [k as f64]);
        }
        assert_eq!(t.len(), 3);
        assert_eq!(t.first(), Some((0.0, &[0.0])));
        assert_eq!(t.last(), Some((1.0, &[2.0])));
        assert_eq!(t.duration(), 1.0);
        assert_eq!(t.iter().len(), 3);
        assert_eq!(t.iter().map(|(time, x)| time + x[0]).sum::<f64>(), 4.5);
        assert_eq!(*t, 1e-9);
    }

    #[test]
    fn harmonic_oscillator_over_one_period() {
        let (n, tau) = (1000, std::f64::consts::TAU);
        let mut x = [1.0, 0.0];
        for _ in 0..n {
            x = rk4_step(|y| [y[1], -y[0]], x, tau / n as f64);
        }
        assert!((x[0] - 1.0).abs() < 1e-10 && x[1].abs() < 1e-10, "{x:?}");
    }
}
