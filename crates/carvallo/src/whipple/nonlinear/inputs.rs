//! The nonlinear bicycle driven: a roll torque $T_\varphi$ and a steer torque $T_\delta$ as
//! functions of time (steps, impulses, sampled series) and of the state (the feedback
//! $T = -Kx$ of [`feedback`](crate::whipple::feedback)), with the input's work in the energy
//! balance.
//!
//! # How the torques enter
//!
//! The roll torque acts on the rear frame about the yawed frame's forward axis $x_\psi$ (its
//! reaction on the ground); the steer torque acts between the rear frame and the front frame
//! about the steering axis $s$ (action on the front frame, reaction on the rear one). With the
//! independent speeds $u = (\dot\varphi, \dot\delta, \dot\theta_R)$ their generalised active
//! forces are, by Kane's method, $F_r = T_\varphi\,x_\psi\cdot\omega^B_r +
//! T_\delta\,s\cdot(\omega^H_r - \omega^B_r)$, $\omega^B_r$ and $\omega^H_r$ the partial
//! angular velocities of the rear frame B and the front frame H (dependent speeds included).
//! The rear frame turns at $\dot\psi z_\psi + \dot\varphi x_\psi + \dot\theta y_\varphi$, the
//! yaw and pitch axes perpendicular to $x_\psi$, so $x_\psi\cdot\omega^B_r = (1, 0, 0)$; the
//! front frame turns relative to the rear one at $\dot\delta s$, so
//! $s\cdot(\omega^H_r - \omega^B_r) = (0, 1, 0)$. Hence $M_3\dot u = f_3 + (T_\varphi,
//! T_\delta, 0)$ at every configuration, not only upright. Both products are checked on the
//! generated partial angular velocities (`wt_B_*`, `wt_H_*`, `sH_*` of
//! `generated/whipple_nonlinear.ir`) at random configurations, and the forced response
//! against the linear state space $\dot x = Ax + BT$ of [`plant`](crate::whipple::plant)
//! at small amplitude (tests below).
//!
//! # The torque as a function of time
//!
//! Each of $T_\varphi$, $T_\delta$ is a sum of [`Signal`]s: a step (zero before its start,
//! its value from then on) or a [`Series`] of samples, linearly interpolated and **zero
//! outside** its first and last time (a series describes the torque while it was recorded;
//! a series whose first or last value is not zero therefore starts or ends with a jump). The
//! times of a series must increase strictly. At a jump the torque is the value after it.
//!
//! The run is split at every jump that falls on a grid point $kh$ (a step's start, a
//! series' ends, an impulse): each piece is integrated on its own, its torques taken on
//! its side of the jump, so RK4 keeps its order (a jump inside a step would cost it one
//! order there) and the adaptive methods do not spend rejected steps locating it. A jump
//! off the grid stays inside a step. An adaptive method may step over a feature of a series
//! narrower than its steps (nothing in the error estimate sees it): give such inputs with
//! RK4 at a step below their width, or as impulses.
//!
//! # Impulses
//!
//! An [`Impulse`] $J = (J_\varphi, J_\delta)$ (N m s) at time $t_J$ is treated exactly: the
//! generalised speeds jump by $\Delta u = M_3^{-1}(J_\varphi, J_\delta, 0)$ at $t_J$ (the
//! configuration is continuous; the dependent speeds follow from $u$), the limit of a pulse of
//! area $J$ as its width goes to zero. A pulse of finite width would add a width to choose
//! and an error of the order of that width, and would make an error-controlled integrator
//! search for its edges; the jump has neither. Its linear counterpart is the jump of the rates
//! by $M^{-1}J$, $B$'s columns times $J$. The integration is split at the impulses, whose
//! times must be points of the grid ($k\,h$); the sample at an impulse's time is the state
//! just after it. The impulse's work is the change of kinetic energy,
//! $\tfrac12 u_+^\top M_3 u_+ - \tfrac12 u_-^\top M_3 u_- = J\cdot(u_- + u_+)/2$ (the kinetic
//! energy is $\tfrac12 u^\top M_3 u$, the constraints being scleronomic).
//!
//! # Feedback
//!
//! [`Feedback`] adds $-Kx$, $x = (\varphi, \delta, \dot\varphi, \dot\delta)$, with $K$
//! constant or read from a [`GainTable`] at the current speed of the rear contact
//! ([`Sample::speed`], $-r_R(\dot\theta + \dot\theta_R)$); a speed outside the table is an
//! error ([`InputError::OutsideGainTable`]).
//!
//! # The Jacobian
//!
//! Radau5's Newton iterations take the driven run's state Jacobian from [`ForcedRate::jacobian`]:
//! the generated derivatives of the undriven bicycle ([`StateRate::jacobian_driven`]), the
//! torques' part $\partial\dot u/\partial T = M_3^{-1}$'s first two columns, and the
//! feedback's chain term $\mathrm{d}T/\mathrm{d}y = -K\,\partial x/\partial y -
//! (\mathrm{d}K/\mathrm{d}v)\,x\,\mathrm{d}v/\mathrm{d}y$ (a gain table's slope through the
//! rear contact's speed $v$). The explicit methods do not use it.
//!
//! # Energy balance
//!
//! The work $W(t) = \int_0^t (T_\varphi\dot\varphi + T_\delta\dot\delta)\,dt$ (impulses
//! included) is integrated as an eleventh state component, so that
//! $E(t) - E(0) - W(t)$ vanishes for the exact motion and its largest magnitude over the
//! accepted steps is the run's drift ([`ForcedDiagnostics::energy_drift`]).

use std::cell::Cell;
use std::fmt;
use std::sync::atomic::AtomicBool;

use nalgebra::{Matrix3, Vector3};

use super::rate::{self, StateRate, TorqueJet};
use super::{
    check_run, dynamics_scene, Configuration, NonlinearError, Sample, State, Stop, Watch,
    WhippleNonlinear,
};
use crate::numerics::integrate::{self, Grid, Integration, Point, Stats};
use crate::numerics::ode::Trajectory;
use crate::whipple::feedback::{GainTable, Gains};

/// Why an input cannot be used.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum InputError {
    /// The time and value columns of a series differ in length.
    SeriesLength {
        /// The number of times.
        times: usize,
        /// The number of values.
        values: usize,
    },
    /// A series with fewer than two samples.
    TooFewSamples {
        /// How many.
        count: usize,
    },
    /// A time or value of a series that is not finite (`row` counts from 1).
    SeriesNotFinite {
        /// `t` or `value`.
        column: &'static str,
        /// The row, from 1.
        row: usize,
        /// The value.
        value: f64,
    },
    /// A time of a series that does not exceed the one before (`row` counts from 1).
    NotIncreasing {
        /// The row, from 1.
        row: usize,
        /// Its time.
        t: f64,
        /// The time of the row before.
        previous: f64,
    },
    /// A step's or an impulse's value or time that is not finite.
    NotFinite {
        /// What it is (`step value`, `step time`, `impulse`, `impulse time`).
        what: &'static str,
        /// The value.
        value: f64,
    },
    /// An impulse whose time is not a point of the integration grid $k h$.
    ImpulseOffGrid {
        /// Its time (s).
        t: f64,
        /// The grid's step (s).
        step: f64,
    },
    /// An impulse outside $[0, \text{duration})$.
    ImpulseOutside {
        /// Its time (s).
        t: f64,
        /// The run's duration (s).
        duration: f64,
    },
    /// The speed of the rear contact left the gain table's speeds.
    OutsideGainTable {
        /// When (s).
        t: f64,
        /// The speed (m/s).
        speed: f64,
        /// The table's first speed.
        from: f64,
        /// The table's last speed.
        to: f64,
    },
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            InputError::SeriesLength { times, values } => {
                write!(f, "invalid torque series: {times} times but {values} values")
            }
            InputError::TooFewSamples { count } => {
                write!(f, "invalid torque series: {count} samples, at least two are needed")
            }
            InputError::SeriesNotFinite { column, row, value } => {
                write!(f, "invalid torque series: {column} {value} in row {row} is not finite")
            }
            InputError::NotIncreasing { row, t, previous } => write!(
                f,
                "invalid torque series: time {t} in row {row} does not exceed the time {previous} before it"
            ),
            InputError::NotFinite { what, value } => {
                write!(f, "invalid {what} {value}: must be finite")
            }
            InputError::ImpulseOffGrid { t, step } => write!(
                f,
                "invalid impulse time {t} s: not a multiple of the step {step} s (the integration is split there)"
            ),
            InputError::ImpulseOutside { t, duration } => {
                write!(f, "invalid impulse time {t} s: outside the run [0, {duration}) s")
            }
            InputError::OutsideGainTable { t, speed, from, to } => write!(
                f,
                "the rear contact speed {speed} m/s at t = {t} s is outside the gain table's speeds {from} to {to} m/s"
            ),
        }
    }
}

impl std::error::Error for InputError {}

impl From<InputError> for NonlinearError {
    fn from(e: InputError) -> NonlinearError {
        NonlinearError::Input(e)
    }
}

/// A torque sampled at strictly increasing times, linearly interpolated, zero outside its
/// first and last time.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    t: Vec<f64>,
    values: Vec<f64>,
}

impl Series {
    /// The series of the samples `(t[i], values[i])`.
    ///
    /// # Errors
    /// [`InputError`] for columns of different lengths, fewer than two samples, a value that is
    /// not finite, or a time that does not exceed the one before (naming its row, from 1).
    pub fn new(t: Vec<f64>, values: Vec<f64>) -> Result<Series, InputError> {
        if t.len() != values.len() {
            return Err(InputError::SeriesLength { times: t.len(), values: values.len() });
        }
        if t.len() < 2 {
            return Err(InputError::TooFewSamples { count: t.len() });
        }
        for (i, (&ti, &vi)) in t.iter().zip(&values).enumerate() {
            if !ti.is_finite() {
                return Err(InputError::SeriesNotFinite { column: "t", row: i + 1, value: ti });
            }
            if !vi.is_finite() {
                return Err(InputError::SeriesNotFinite { column: "value", row: i + 1, value: vi });
            }
            if i > 0 && ti <= t[i - 1] {
                return Err(InputError::NotIncreasing { row: i + 1, t: ti, previous: t[i - 1] });
            }
        }
        Ok(Series { t, values })
    }

    /// The times.
    pub fn times(&self) -> &[f64] {
        &self.t
    }

    /// The values.
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// The torque at time `t`: interpolated between the samples, zero outside $[t_0, t_n)$
    /// (right-continuous: at its last time the series has ended).
    pub fn at(&self, t: f64) -> f64 {
        let n = self.t.len();
        if t >= self.t[0] && t < self.t[n - 1] {
            self.interpolate(t)
        } else {
            0.0
        }
    }

    /// The interpolant at `t` clamped to the series' times.
    fn interpolate(&self, t: f64) -> f64 {
        let n = self.t.len();
        let t = t.clamp(self.t[0], self.t[n - 1]);
        let i = self.t.partition_point(|&x| x <= t).clamp(1, n - 1);
        let (t0, t1, v0, v1) = (self.t[i - 1], self.t[i], self.values[i - 1], self.values[i]);
        v0 + (v1 - v0) * ((t - t0) / (t1 - t0))
    }
}

/// The index $k$ of the grid point $kh$ at `t` (within $10^{-9}$ relative), `None` when `t` is
/// not a point of the grid.
fn grid_index(grid: &Grid, t: f64) -> Option<usize> {
    let k = (t / grid.h).round();
    let on = (t - k * grid.h).abs() <= 1e-9 * grid.h.max(t.abs());
    (on && k >= 0.0 && k <= grid.n as f64).then_some(k as usize)
}

/// Where a torque is evaluated: at time `t`, inside the segment of the run whose middle is
/// `mid` (between two grid points where a run is split). A jump of a step or a series at a
/// grid point is on a segment's edge and counts as passed when the segment is after it
/// (`mid` later), whatever the rounding of `t`; a jump off the grid is compared with `t`.
#[derive(Clone, Copy)]
struct When<'g> {
    t: f64,
    segment: Option<(f64, &'g Grid)>,
}

impl When<'_> {
    /// Whether the time is at or after `d` (a jump's time).
    fn after(&self, d: f64) -> bool {
        match self.segment {
            Some((mid, grid)) if grid_index(grid, d).is_some() => mid > d,
            _ => self.t >= d,
        }
    }
}

/// One term of a torque as a function of time (N m).
#[derive(Clone, Debug, PartialEq)]
pub enum Signal {
    /// Zero before `start` (s), `value` (N m) from then on.
    Step {
        /// The torque after the step (N m).
        value: f64,
        /// When it starts (s).
        start: f64,
    },
    /// A sampled series.
    Series(Series),
}

impl Signal {
    /// The torque at time `t` (N m); at a jump, the value after it.
    pub fn at(&self, t: f64) -> f64 {
        self.at_when(When { t, segment: None })
    }

    fn at_when(&self, w: When<'_>) -> f64 {
        match self {
            Signal::Step { value, start } => {
                if w.after(*start) {
                    *value
                } else {
                    0.0
                }
            }
            Signal::Series(s) => {
                let (t0, tn) = (s.t[0], s.t[s.t.len() - 1]);
                if w.after(t0) && !w.after(tn) {
                    s.interpolate(w.t)
                } else {
                    0.0
                }
            }
        }
    }

    /// The times where the torque jumps: a step's start, a series' first and last times.
    fn jumps(&self) -> [f64; 2] {
        match self {
            Signal::Step { start, .. } => [*start, *start],
            Signal::Series(s) => [s.t[0], s.t[s.t.len() - 1]],
        }
    }
}

/// An impulsive torque: the angular impulses `roll` and `steer` (N m s) at `t` (s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impulse {
    /// When (s).
    pub t: f64,
    /// Roll impulse $J_\varphi$ (N m s).
    pub roll: f64,
    /// Steer impulse $J_\delta$ (N m s).
    pub steer: f64,
}

/// State feedback $T = -Kx$.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Feedback {
    /// None.
    #[default]
    None,
    /// Constant gains.
    Constant(Gains),
    /// Gains at the current speed of the rear contact.
    Table(GainTable),
}

/// What drives the nonlinear bicycle: the terms of $T_\varphi$ and $T_\delta$ (summed), the
/// impulses and the feedback.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Inputs {
    /// The terms of the roll torque.
    pub roll: Vec<Signal>,
    /// The terms of the steer torque.
    pub steer: Vec<Signal>,
    /// The impulses.
    pub impulses: Vec<Impulse>,
    /// The feedback.
    pub feedback: Feedback,
}

impl Inputs {
    /// Whether nothing drives the bicycle.
    pub fn is_empty(&self) -> bool {
        self.roll.is_empty()
            && self.steer.is_empty()
            && self.impulses.is_empty()
            && self.feedback == Feedback::None
    }

    /// The torques of the time functions at `t`, $(T_\varphi, T_\delta)$ (N m); at a jump,
    /// the values after it.
    pub fn open_loop(&self, t: f64) -> [f64; 2] {
        self.open_loop_when(When { t, segment: None })
    }

    fn open_loop_when(&self, w: When<'_>) -> [f64; 2] {
        let sum = |v: &[Signal]| v.iter().map(|s| s.at_when(w)).sum();
        [sum(&self.roll), sum(&self.steer)]
    }

    /// The torques at `t` for the state `x` = (lean, steer, lean rate, steer rate) and the
    /// rear contact speed `speed`: the time functions plus the feedback.
    ///
    /// # Errors
    /// [`InputError::OutsideGainTable`] when `speed` is outside the gain table.
    pub fn torque(&self, t: f64, x: [f64; 4], speed: f64) -> Result<[f64; 2], InputError> {
        self.torque_when(When { t, segment: None }, x, speed)
    }

    fn torque_when(&self, w: When<'_>, x: [f64; 4], speed: f64) -> Result<[f64; 2], InputError> {
        let mut tau = self.open_loop_when(w);
        let k = match &self.feedback {
            Feedback::None => return Ok(tau),
            Feedback::Constant(k) => *k,
            Feedback::Table(table) => table.at(speed).ok_or_else(|| {
                let (from, to) = table.span();
                InputError::OutsideGainTable { t: w.t, speed, from, to }
            })?,
        };
        for (r, row) in k.0.iter().enumerate() {
            tau[r] -= row[0] * x[0] + row[1] * x[1] + row[2] * x[2] + row[3] * x[3];
        }
        Ok(tau)
    }

    /// [`torque_when`](Self::torque_when) with its derivatives with respect to the state of
    /// the right-hand side ([`rate::LEN`] components; $x$ is its lean, steer, lean rate and
    /// steer rate, components 3, 4, 7, 8) and the rear contact's speed: $-K$ in $x$'s
    /// columns and, for a gain table, $-(\mathrm{d}K/\mathrm{d}v)\,x$ for the speed. The
    /// time functions do not depend on the state. The torques are those of `torque_when`,
    /// bit for bit.
    fn torque_jet_when(
        &self,
        w: When<'_>,
        x: [f64; 4],
        speed: f64,
    ) -> Result<TorqueJet, InputError> {
        let torque = self.torque_when(w, x, speed)?;
        let (k, slope) = match &self.feedback {
            Feedback::None => return Ok(TorqueJet::constant(torque)),
            Feedback::Constant(k) => (*k, Gains::ZERO),
            Feedback::Table(table) => {
                // Inside the table: `torque_when` returned the error otherwise.
                let k = table.at(speed).unwrap_or(Gains::ZERO);
                (k, table.slope(speed).unwrap_or(Gains::ZERO))
            }
        };
        let mut jet = TorqueJet { torque, ..TorqueJet::default() };
        for r in 0..2 {
            for (c, j) in X_IN_STATE.into_iter().enumerate() {
                jet.state[r][j] = -k.0[r][c];
            }
            let s = slope.0[r];
            jet.speed[r] = -(s[0] * x[0] + s[1] * x[1] + s[2] * x[2] + s[3] * x[3]);
        }
        Ok(jet)
    }

    /// Checks the steps and impulses against `grid` (finite values, impulse times in
    /// $[0, nh)$ on the grid) and returns where the run is split: the grid points inside the
    /// run where a torque jumps or an impulse acts, in order, each with the impulse there
    /// ($J_\varphi$, $J_\delta$; zero where only a torque jumps).
    fn breaks(&self, grid: &Grid) -> Result<Vec<(usize, [f64; 2])>, InputError> {
        let mut points: Vec<(usize, [f64; 2])> = Vec::new();
        for s in self.roll.iter().chain(&self.steer) {
            if let Signal::Step { value, start } = s {
                for (what, v) in [("step value", *value), ("step time", *start)] {
                    if !v.is_finite() {
                        return Err(InputError::NotFinite { what, value: v });
                    }
                }
            }
            for d in s.jumps() {
                if let Some(k) = grid_index(grid, d).filter(|&k| k > 0 && k < grid.n) {
                    points.push((k, [0.0, 0.0]));
                }
            }
        }
        for j in &self.impulses {
            for (what, v) in [("impulse time", j.t), ("impulse", j.roll), ("impulse", j.steer)] {
                if !v.is_finite() {
                    return Err(InputError::NotFinite { what, value: v });
                }
            }
            let duration = grid.end();
            if !(j.t >= 0.0 && j.t < duration) {
                return Err(InputError::ImpulseOutside { t: j.t, duration });
            }
            let k =
                grid_index(grid, j.t).ok_or(InputError::ImpulseOffGrid { t: j.t, step: grid.h })?;
            points.push((k, [j.roll, j.steer]));
        }
        points.sort_by_key(|p| p.0);
        let mut merged: Vec<(usize, [f64; 2])> = Vec::with_capacity(points.len());
        for (k, j) in points {
            match merged.last_mut() {
                Some(last) if last.0 == k => {
                    last.1[0] += j[0];
                    last.1[1] += j[1];
                }
                _ => merged.push((k, j)),
            }
        }
        Ok(merged)
    }
}

/// One sample of a driven run: the [`Sample`], the torques then and the work done so far.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForcedSample {
    /// The state and what is observed of it.
    pub sample: Sample,
    /// $(T_\varphi, T_\delta)$ at the sample (N m), the time functions (right-continuous at a
    /// step) plus the feedback; impulses not included.
    pub torque: [f64; 2],
    /// The work of the inputs since the start, impulses included (J).
    pub work: f64,
}

/// What a driven run measures over all its accepted steps.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ForcedDiagnostics {
    /// Largest $|E(t) - E(0) - W(t)|$ (J): the integrator's error in the energy balance.
    pub energy_drift: f64,
    /// Largest $|E(t) - E(0)|$ (J): how much the inputs changed the energy.
    pub max_energy_change: f64,
    /// Largest $|h|$ of the contact constraint after Newton (m).
    pub max_contact_residual: f64,
    /// The work of the inputs over the run (J).
    pub work: f64,
}

/// A driven run ([`WhippleNonlinear::simulate_forced`]).
pub type ForcedTrajectory = Trajectory<ForcedSample, ForcedDiagnostics>;

/// The state of a driven run: the eleven of [`rate::LEN`] (the ten of [`State`] and the
/// pitch) and the work.
type Y = [f64; 12];

/// The index of the work in [`Y`].
const WORK: usize = 11;

fn state_of(y: &Y) -> State {
    State::from_array(std::array::from_fn(|i| y[i]))
}

/// The state of the right-hand side (without the work).
fn plain(y: &Y) -> [f64; rate::LEN] {
    std::array::from_fn(|i| y[i])
}

/// The components of the state of the right-hand side that the feedback's $x$ = (lean,
/// steer, lean rate, steer rate) are.
const X_IN_STATE: [usize; 4] = [3, 4, 7, 8];

/// The number of components of a driven run's state ([`ForcedRate`]).
pub const FORCED_LEN: usize = 12;

fn y_of(s: &State, pitch: f64, work: f64) -> Y {
    let a = rate::state_with_pitch(s, pitch);
    std::array::from_fn(|i| if i < WORK { a[i] } else { work })
}

/// The derivative of the driven state `y` at the time `w`: the right-hand side's, its torques
/// at the rear contact's speed, and the work's rate $T_\varphi\dot\varphi +
/// T_\delta\dot\delta$.
fn driven_rate(f: &StateRate, inputs: &Inputs, w: When<'_>, y: &Y) -> Result<Y, NonlinearError> {
    let s = state_of(y);
    let x = [s.lean, s.steer, s.lean_rate, s.steer_rate];
    let mut tau = [0.0, 0.0];
    let r = f.rates_with(&plain(y), &mut |v| {
        tau = inputs.torque_when(w, x, v)?;
        Ok(tau)
    })?;
    Ok(std::array::from_fn(|i| {
        if i < WORK {
            r.derivative[i]
        } else {
            tau[0] * s.lean_rate + tau[1] * s.steer_rate
        }
    }))
}

/// The state Jacobian of [`driven_rate`]: the right-hand side's with the torques' derivatives
/// ([`StateRate::jacobian_driven`]), and the work's row
/// $\mathrm{d}T_\varphi\,\dot\varphi + \mathrm{d}T_\delta\,\dot\delta$ plus the torques
/// in the rates' columns. Nothing depends on the work: its column is zero.
fn driven_jacobian(
    f: &StateRate,
    inputs: &Inputs,
    w: When<'_>,
    y: &Y,
) -> Result<[[f64; FORCED_LEN]; FORCED_LEN], NonlinearError> {
    let s = state_of(y);
    let x = [s.lean, s.steer, s.lean_rate, s.steer_rate];
    let d = f.jacobian_driven(&plain(y), &mut |v| Ok(inputs.torque_jet_when(w, x, v)?))?;
    let mut jac = [[0.0; FORCED_LEN]; FORCED_LEN];
    for (row, r) in jac.iter_mut().zip(&d.jacobian) {
        row[..rate::LEN].copy_from_slice(r);
    }
    let dt = &d.torque_jacobian;
    for j in 0..rate::LEN {
        jac[WORK][j] = dt[0][j] * s.lean_rate + dt[1][j] * s.steer_rate;
    }
    jac[WORK][7] += d.torque[0];
    jac[WORK][8] += d.torque[1];
    Ok(jac)
}

/// The right-hand side of a driven run and its state Jacobian, as
/// [`WhippleNonlinear::simulate_forced`] integrates them (there the torques at a jump on the
/// grid are taken on the side of the segment being integrated; here at time `t`, the value
/// after a jump). The state has [`FORCED_LEN`] components: the eleven of [`rate::LEN`] (the
/// ten of [`State`], then the pitch) and the inputs' work.
#[derive(Clone, Debug)]
pub struct ForcedRate<'a> {
    f: StateRate,
    inputs: &'a Inputs,
}

impl<'a> ForcedRate<'a> {
    /// The driven right-hand side of `bike` under `inputs`.
    pub fn new(bike: &WhippleNonlinear, inputs: &'a Inputs) -> ForcedRate<'a> {
        ForcedRate { f: StateRate::new(&bike.params), inputs }
    }

    /// The state derivative at time `t` and state `y`.
    ///
    /// # Errors
    /// As [`StateRate::rates_with`], and [`InputError::OutsideGainTable`].
    pub fn eval(&self, t: f64, y: &[f64; FORCED_LEN]) -> Result<[f64; FORCED_LEN], NonlinearError> {
        driven_rate(&self.f, self.inputs, When { t, segment: None }, y)
    }

    /// The state Jacobian of [`eval`](Self::eval) at time `t` and state `y`: generated
    /// derivatives of the bicycle ([`StateRate::jacobian_driven`]) with the feedback's
    /// chain term $\partial\dot y/\partial T\;\mathrm{d}T/\mathrm{d}y$ (`-K` in the lean,
    /// steer and their rates, and a gain table's slope through the rear contact's speed),
    /// what Radau5's Newton iterations use in a driven run.
    ///
    /// # Errors
    /// As [`eval`](Self::eval).
    pub fn jacobian(
        &self,
        t: f64,
        y: &[f64; FORCED_LEN],
    ) -> Result<[[f64; FORCED_LEN]; FORCED_LEN], NonlinearError> {
        driven_jacobian(&self.f, self.inputs, When { t, segment: None }, y)
    }
}

impl WhippleNonlinear {
    /// The accelerations at `c` with the generalised forces $(T_\varphi, T_\delta)$ added to
    /// the lean and steer rows of $f_3$: $\ddot\varphi$, $\ddot\delta$, $\ddot\theta_R$.
    ///
    /// # Errors
    /// [`NonlinearError::SingularMassMatrix`] when $M_3$ cannot be factored.
    pub fn forced_accelerations(
        &self,
        c: &Configuration,
        torque: [f64; 2],
    ) -> Result<[f64; 3], NonlinearError> {
        let a = self.args(dynamics_scene::PARAMS, dynamics_scene::INPUTS, c);
        let o = dynamics_scene::eval(&dynamics_scene::Args::from_array(a));
        rate::solve_symmetric(
            [o.m3_11, o.m3_12, o.m3_13, o.m3_22, o.m3_23, o.m3_33],
            [o.f3_1 + torque[0], o.f3_2 + torque[1], o.f3_3],
        )
        .ok_or(NonlinearError::SingularMassMatrix { lean: c.lean, steer: c.steer })
    }

    /// Integrates from `start` over `grid` by `how` driven by `inputs`, as
    /// [`simulate_with`](WhippleNonlinear::simulate_with) does undriven (the same samples,
    /// stop conditions and counts), with the torques and the work in every sample and the
    /// energy balance $E - E(0) - W$ as the drift (see the [module docs](self)).
    ///
    /// # Errors
    /// As [`simulate_with`](WhippleNonlinear::simulate_with), and [`NonlinearError::Input`]
    /// for an impulse off the grid or outside the run, a step or impulse that is not finite,
    /// or a speed outside the gain table.
    pub fn simulate_forced(
        &self,
        start: State,
        grid: &Grid,
        how: &Integration,
        stops: &[Stop],
        inputs: &Inputs,
    ) -> Result<ForcedTrajectory, NonlinearError> {
        self.simulate_forced_until(start, grid, how, stops, inputs, &AtomicBool::new(false))
    }

    /// [`simulate_forced`](Self::simulate_forced) that also ends when `stop` is set
    /// (Ctrl-C), as [`simulate_until`](WhippleNonlinear::simulate_until) does.
    ///
    /// # Errors
    /// As [`simulate_forced`](Self::simulate_forced).
    pub fn simulate_forced_until(
        &self,
        start: State,
        grid: &Grid,
        how: &Integration,
        stops: &[Stop],
        inputs: &Inputs,
        stop: &AtomicBool,
    ) -> Result<ForcedTrajectory, NonlinearError> {
        self.simulate_forced_with(start, grid, how, stops, inputs, stop, JacobianBy::Generated)
    }

    /// [`simulate_forced_until`](Self::simulate_forced_until) with the Jacobian Radau5's
    /// Newton iterations use chosen (forward differences only to compare with).
    #[allow(clippy::too_many_arguments)]
    fn simulate_forced_with(
        &self,
        start: State,
        grid: &Grid,
        how: &Integration,
        stops: &[Stop],
        inputs: &Inputs,
        stop: &AtomicBool,
        jacobian: JacobianBy,
    ) -> Result<ForcedTrajectory, NonlinearError> {
        check_run(&start, how, stops)?;
        let breaks = inputs.breaks(grid)?;
        let mut trajectory =
            Trajectory::with_capacity(grid.h, grid.samples(), ForcedDiagnostics::default());
        let pitch0 = self.check_start(&start)?;
        let (e0, _) = self.observe(&self.configuration(&start, pitch0)?);
        let run = Run {
            bike: self,
            inputs,
            jacobian,
            how,
            grid,
            e0,
            f: StateRate::new(&self.params),
            mid: Cell::new(0.0),
            diagnostics: Cell::new(ForcedDiagnostics::default()),
            stats: Cell::new(Stats::default()),
            watches: self.watches(stops),
            stop,
        };
        let mut y = y_of(&start, pitch0, 0.0);
        let mut k0 = 0;
        let mut event = None;
        // Segments between the breaks; the last ends at the grid's end.
        for (k1, jump) in breaks.into_iter().chain([(grid.n, [0.0, 0.0])]) {
            if k1 > k0 {
                let (end, crossed, interrupted) = run.segment(k0, k1, y, &mut trajectory)?;
                y = end;
                if let Some((index, t)) = crossed {
                    match index.checked_sub(stops.len()) {
                        Some(0) => trajectory.fall = Some(t),
                        Some(1) => trajectory.steer_lock = Some(t),
                        Some(_) => trajectory.singular = Some(t),
                        None => event = crossed,
                    }
                    break;
                }
                if interrupted.is_some() {
                    trajectory.interrupted = interrupted;
                    break;
                }
            }
            if jump != [0.0, 0.0] {
                y = run.jump(y, jump)?;
            }
            k0 = k1;
        }
        trajectory.diagnostics = run.diagnostics.get();
        trajectory.diagnostics.work = y[WORK];
        trajectory.stats = run.stats.get();
        trajectory.event = event;
        Ok(trajectory)
    }
}

/// The end of a segment: the state, the event that ended it (its index, the fall's after the
/// stop conditions', and the time) and the time the stop flag ended it.
type SegmentEnd = (Y, Option<(usize, f64)>, Option<f64>);

/// Where the Jacobian of a driven run's right-hand side comes from, for the implicit method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum JacobianBy {
    /// [`driven_jacobian`]: the generated derivatives and the feedback's chain term.
    Generated,
    /// The integrator's forward differences (what a driven run used before; kept to compare).
    #[cfg_attr(not(test), allow(dead_code))]
    ForwardDifferences,
}

/// A driven run in progress: what its segments share.
struct Run<'a> {
    bike: &'a WhippleNonlinear,
    inputs: &'a Inputs,
    jacobian: JacobianBy,
    how: &'a Integration,
    grid: &'a Grid,
    e0: f64,
    /// The right-hand side.
    f: StateRate,
    /// The middle of the segment being integrated (s).
    mid: Cell<f64>,
    diagnostics: Cell<ForcedDiagnostics>,
    stats: Cell<Stats>,
    /// The events: the stops, then the fall, the steer lock and the singular configuration.
    watches: [Option<Watch>; integrate::MAX_EVENTS],
    /// The flag that ends the run early.
    stop: &'a AtomicBool,
}

impl Run<'_> {
    /// Time `t` inside the segment being integrated.
    fn when(&self, t: f64) -> When<'_> {
        When { t, segment: Some((self.mid.get(), self.grid)) }
    }

    /// The torques at time `t` in the state `s` with the rear contact speed `speed`.
    fn torque(&self, t: f64, s: &State, speed: f64) -> Result<[f64; 2], NonlinearError> {
        let x = [s.lean, s.steer, s.lean_rate, s.steer_rate];
        Ok(self.inputs.torque_when(self.when(t), x, speed)?)
    }

    /// The derivative of `y` at time `t`.
    fn rhs(&self, t: f64, y: &Y) -> Result<Y, NonlinearError> {
        driven_rate(&self.f, self.inputs, self.when(t), y)
    }

    /// The state Jacobian of [`rhs`](Self::rhs) at time `t`.
    fn jacobian(&self, t: f64, y: &Y) -> Result<[[f64; FORCED_LEN]; FORCED_LEN], NonlinearError> {
        driven_jacobian(&self.f, self.inputs, self.when(t), y)
    }

    /// The configuration of `y`: its pitch projected onto the contact constraint.
    fn configuration(&self, y: &Y) -> Result<Configuration, NonlinearError> {
        Ok(Configuration {
            lean: y[3],
            pitch: self.f.project(y[3], y[rate::PITCH], y[4])?,
            steer: y[4],
            lean_rate: y[7],
            steer_rate: y[8],
            rear_wheel_rate: y[9],
        })
    }

    /// Records the energy balance and the contact residual of the state `y`.
    fn balance(&self, y: &Y) -> Result<(), NonlinearError> {
        let c = self.configuration(y)?;
        let mut d = self.diagnostics.get();
        d.max_contact_residual =
            d.max_contact_residual.max(self.f.contact(c.lean, c.pitch, c.steer).0.abs());
        let (e, _) = self.bike.observe(&c);
        d.max_energy_change = d.max_energy_change.max((e - self.e0).abs());
        d.energy_drift = d.energy_drift.max((e - self.e0 - y[WORK]).abs());
        self.diagnostics.set(d);
        Ok(())
    }

    /// The sample of `y` at time `t`.
    fn sample(&self, t: f64, y: &Y) -> Result<ForcedSample, NonlinearError> {
        let s = state_of(y);
        let sample = self.bike.sample(t, &s, y[rate::PITCH])?;
        // The sums of no terms are -0.0, the neutral element the right-hand side adds to
        // f3; the samples show +0.0.
        let [a, b] = self.torque(t, &s, sample.speed)?;
        Ok(ForcedSample { sample, torque: [a + 0.0, b + 0.0], work: y[WORK] })
    }

    /// The impulse `j` = $(J_\varphi, J_\delta)$ applied to `y`: the speeds jump by
    /// $M_3^{-1}(J_\varphi, J_\delta, 0)$ and the work by $J\cdot(u_- + u_+)/2$.
    fn jump(&self, y: Y, j: [f64; 2]) -> Result<Y, NonlinearError> {
        let c = self.configuration(&y)?;
        let m = self.bike.kane_terms(&c).mass;
        let du = Matrix3::from_fn(|r, k| m[r][k])
            .lu()
            .solve(&Vector3::new(j[0], j[1], 0.0))
            .filter(|x| x.iter().all(|v| v.is_finite()))
            .ok_or(NonlinearError::SingularMassMatrix { lean: c.lean, steer: c.steer })?;
        let mut out = y;
        out[7] += du[0];
        out[8] += du[1];
        out[9] += du[2];
        out[WORK] += j[0] * (y[7] + out[7]) / 2.0 + j[1] * (y[8] + out[8]) / 2.0;
        self.balance(&out)?;
        Ok(out)
    }

    /// Integrates `y0` over the grid points `k0..=k1` of the run's grid, keeping its samples
    /// there (the one at `k1` only at the grid's end: otherwise the run is split there and
    /// the sample is the state after the split). Returns the end state, the event, if any (the
    /// fall's index is the number of stop conditions, the steer lock's and the singular
    /// configuration's the next two), and the time the stop flag ended it.
    fn segment(
        &self,
        k0: usize,
        k1: usize,
        y0: Y,
        trajectory: &mut ForcedTrajectory,
    ) -> Result<SegmentEnd, NonlinearError> {
        let grid = self.grid;
        let last = k1 == grid.n;
        // The whole grid in one segment samples as an undriven run; a segment between
        // breaks samples every point and keeps those of the whole grid.
        let whole = k0 == 0 && last;
        let local = Grid { h: grid.h, n: k1 - k0, every: if whole { grid.every } else { 1 } };
        let offset = grid.time(k0);
        self.mid.set((grid.time(k0) + grid.time(k1)) / 2.0);
        let mut rhs = |t: f64, y: &Y| -> Result<Y, NonlinearError> { self.rhs(offset + t, y) };
        // The implicit method's Newton iterations use the generated Jacobian with the
        // feedback's chain term.
        let mut jacobian = |t: f64, y: &Y| self.jacobian(offset + t, y);
        let mut watchers = self.watches.map(|watch| {
            move |y: &Y| -> Result<f64, NonlinearError> {
                watch.map_or(Ok(f64::NAN), |w| w.value(&self.f, y))
            }
        });
        let mut events: [&mut integrate::EventFn<'_, 12, NonlinearError>; integrate::MAX_EVENTS] =
            watchers.each_mut().map(|w| w as &mut integrate::EventFn<'_, 12, NonlinearError>);
        let mut observe = |kind: Point, t: f64, y: &Y| -> Result<(), NonlinearError> {
            match kind {
                Point::Step => {
                    self.balance(y)?;
                }
                Point::Sample(i) => {
                    let global = k0 + i;
                    if whole {
                        trajectory.push(t, self.sample(t, y)?);
                    } else if grid.sampled(global) && (last || i < local.n) {
                        let t = grid.time(global);
                        trajectory.push(t, self.sample(t, y)?);
                    }
                }
                Point::Event => {
                    let t = offset + t;
                    trajectory.push(t, self.sample(t, y)?);
                }
            }
            Ok(())
        };
        let outcome = integrate::integrate_with_jacobian(
            self.how,
            &local,
            y0,
            &mut rhs,
            match self.jacobian {
                JacobianBy::Generated => Some(&mut jacobian),
                JacobianBy::ForwardDifferences => None,
            },
            &mut events[..self.watches.iter().flatten().count()],
            &mut observe,
            self.stop,
        )?;
        let mut stats = self.stats.get();
        stats.rhs_evaluations += outcome.stats.rhs_evaluations;
        stats.steps += outcome.stats.steps;
        stats.rejected_steps += outcome.stats.rejected_steps;
        self.stats.set(stats);
        Ok((
            outcome.end.1,
            outcome.event.map(|c| (c.index, offset + c.t)),
            outcome.interrupted.then_some(offset + outcome.end.0),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::integrate::Method;
    use crate::numerics::rng::SplitMix64;
    use crate::whipple::{Whipple, WhippleParams};

    crate::scene! {
        /// The pitch's and the steer axis tilt's sines and cosines and the partial angular velocities
        /// of the rear and front frames (each in its own axes).
        mod partials_scene {
            model: whipple_nonlinear,
            outputs: [s_theta, c_theta, s_lambda, c_lambda,
                      wt_B_phid_x, wt_B_phid_y, wt_B_phid_z,
                      wt_B_deltad_x, wt_B_deltad_y, wt_B_deltad_z,
                      wt_B_thetaRd_x, wt_B_thetaRd_y, wt_B_thetaRd_z,
                      wt_H_phid_x, wt_H_phid_y, wt_H_phid_z,
                      wt_H_deltad_x, wt_H_deltad_y, wt_H_deltad_z,
                      wt_H_thetaRd_x, wt_H_thetaRd_y, wt_H_thetaRd_z],
        }
    }

    fn bike() -> WhippleNonlinear {
        WhippleNonlinear::new(WhippleParams::benchmark())
    }

    #[test]
    fn the_torques_generalised_forces_are_one_in_their_own_rows() {
        // The generated partial angular velocities of the rear frame B and the front frame H
        // are in their body frames (B: yaw, lean about x, pitch about y; H: B turned about the
        // steering axis). In B's frame the yawed forward axis is x_psi = (cos th, 0, sin th)
        // and the steering axis s = (sin lam, 0, cos lam), the same in H's frame (H turns
        // about it). Then F_r = T_phi x_psi . w^B_r + T_delta s . (w^H_r - w^B_r) must be
        // (1, 0, 0) and (0, 1, 0) at 200 random configurations, to rounding.
        let bike = bike();
        let mut rng = SplitMix64(20);
        for _ in 0..200 {
            let lean = rng.uniform(-1.2, 1.2);
            let steer = rng.uniform(-1.2, 1.2);
            let pitch = bike.pitch(lean, steer, 0.0).expect("contact");
            let c = Configuration {
                lean,
                pitch,
                steer,
                lean_rate: rng.uniform(-3.0, 3.0),
                steer_rate: rng.uniform(-3.0, 3.0),
                rear_wheel_rate: rng.uniform(-30.0, 0.0),
            };
            let a = bike.args(partials_scene::PARAMS, partials_scene::INPUTS, &c);
            let o = partials_scene::eval(&partials_scene::Args::from_array(a));
            let (st, ct) = (o.s_theta, o.c_theta);
            let s_body = [o.s_lambda, 0.0, o.c_lambda];
            let x_psi = [ct, 0.0, st];
            let b = [
                [o.wt_B_phid_x, o.wt_B_phid_y, o.wt_B_phid_z],
                [o.wt_B_deltad_x, o.wt_B_deltad_y, o.wt_B_deltad_z],
                [o.wt_B_thetaRd_x, o.wt_B_thetaRd_y, o.wt_B_thetaRd_z],
            ];
            let h = [
                [o.wt_H_phid_x, o.wt_H_phid_y, o.wt_H_phid_z],
                [o.wt_H_deltad_x, o.wt_H_deltad_y, o.wt_H_deltad_z],
                [o.wt_H_thetaRd_x, o.wt_H_thetaRd_y, o.wt_H_thetaRd_z],
            ];
            let dot = |u: [f64; 3], v: [f64; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
            let roll: [f64; 3] = std::array::from_fn(|r| dot(x_psi, b[r]));
            let steer_f: [f64; 3] = std::array::from_fn(|r| dot(s_body, h[r]) - dot(s_body, b[r]));
            for (got, want) in [(roll, [1.0, 0.0, 0.0]), (steer_f, [0.0, 1.0, 0.0])] {
                for r in 0..3 {
                    assert!((got[r] - want[r]).abs() < 1e-12, "{c:?}: {got:?} vs {want:?}");
                }
            }
        }
    }

    /// The nonlinear run from upright at `speed` driven by `inputs` (DOP853, rtol 1e-11),
    /// sampled every 0.01 s for `duration`.
    fn nonlinear(speed: f64, duration: f64, inputs: &Inputs) -> ForcedTrajectory {
        let bike = bike();
        let start = bike.initial_state(speed, 0.0).expect("start");
        let grid = Grid::new(duration, 0.01, 1).expect("grid");
        let how = Integration::adaptive(Method::Dop853, 1e-11, 1e-14);
        bike.simulate_forced(start, &grid, &how, &[], inputs).expect("run")
    }

    /// The linear state space x' = A x + B T(t) at `speed` from `x0` integrated by the same
    /// method and tolerance on the same grid: the states at the samples.
    fn linear(speed: f64, duration: f64, x0: [f64; 4], inputs: &Inputs) -> Vec<[f64; 4]> {
        let ss = Whipple::new(WhippleParams::benchmark()).state_space(speed);
        let grid = Grid::new(duration, 0.01, 1).expect("grid");
        let how = Integration::adaptive(Method::Dop853, 1e-11, 1e-14);
        let mut rhs = |t: f64, x: &[f64; 4]| -> Result<[f64; 4], NonlinearError> {
            let u = inputs.torque(t, *x, speed)?;
            Ok(std::array::from_fn(|i| {
                (0..4).map(|j| ss.a[(i, j)] * x[j]).sum::<f64>()
                    + ss.b[(i, 0)] * u[0]
                    + ss.b[(i, 1)] * u[1]
            }))
        };
        let mut out = Vec::new();
        let mut observe = |kind: Point, _t: f64, x: &[f64; 4]| -> Result<(), NonlinearError> {
            if let Point::Sample(_) = kind {
                out.push(*x);
            }
            Ok(())
        };
        integrate::integrate(&how, &grid, x0, &mut rhs, &mut [], &mut observe).expect("linear");
        out
    }

    /// max |x_nonlinear - x_linear| / max |x_linear| over the samples and the four states.
    fn relative_difference(nl: &ForcedTrajectory, lin: &[[f64; 4]], skip: usize) -> f64 {
        assert_eq!(nl.samples.len(), lin.len() + skip);
        let (mut diff, mut size) = (0.0f64, 0.0f64);
        for (s, x) in nl.samples[skip..].iter().zip(lin) {
            let st = s.sample.state;
            let y = [st.lean, st.steer, st.lean_rate, st.steer_rate];
            for k in 0..4 {
                diff = diff.max((y[k] - x[k]).abs());
                size = size.max(x[k].abs());
            }
        }
        diff / size
    }

    #[test]
    fn at_small_amplitude_the_nonlinear_response_follows_the_linear_state_space() {
        // At 5 m/s (inside the benchmark's stable range) for 3 s: a steer torque step, a roll
        // torque series (a triangle), a roll and steer impulse at t = 0, and the balance-assist
        // feedback with a steer torque step at 3 m/s. The lateral equations are odd in the
        // lateral variables (left-right symmetry): the second-order terms change only the
        // forward speed and the pitch, so the lateral difference is of third order in the
        // amplitude and, relative to the response, shrinks like its square. At amplitudes a
        // and a/10 the ratio of the relative differences is 100 within a factor 2 (measured
        // 100.0, 99.2, 99.99, 99.9; 1.1e-4 relative for the 0.01 N m step). The integration error (rtol 1e-11) is far below both.
        type Case = (&'static str, f64, Box<dyn Fn(f64) -> Inputs>);
        let cases: Vec<Case> = vec![
            (
                "steer step",
                5.0,
                Box::new(|a| Inputs {
                    steer: vec![Signal::Step { value: a, start: 0.1 }],
                    ..Inputs::default()
                }),
            ),
            (
                "roll series",
                5.0,
                Box::new(|a| Inputs {
                    roll: vec![Signal::Series(
                        Series::new(vec![0.2, 0.5, 0.8], vec![0.0, 20.0 * a, 0.0]).expect("ok"),
                    )],
                    ..Inputs::default()
                }),
            ),
            (
                "impulse at 0",
                5.0,
                Box::new(|a| Inputs {
                    impulses: vec![Impulse { t: 0.0, roll: 5.0 * a, steer: -a }],
                    ..Inputs::default()
                }),
            ),
            (
                "feedback",
                3.0,
                Box::new(|a| Inputs {
                    steer: vec![Signal::Step { value: a, start: 0.0 }],
                    feedback: Feedback::Constant(Gains::balance_assist(20.0)),
                    ..Inputs::default()
                }),
            ),
        ];
        for (name, speed, inputs) in &cases {
            let mut rel = Vec::new();
            for a in [0.01, 0.001] {
                let inputs = inputs(a);
                let nl = nonlinear(*speed, 3.0, &inputs);
                let mut x0 = [0.0; 4];
                for j in &inputs.impulses {
                    // The linear jump: the rates by M^-1 J, B's lower rows times J.
                    let ss = Whipple::new(WhippleParams::benchmark()).state_space(*speed);
                    for (r, x) in x0.iter_mut().enumerate().skip(2) {
                        *x += ss.b[(r, 0)] * j.roll + ss.b[(r, 1)] * j.steer;
                    }
                }
                let lin = linear(*speed, 3.0, x0, &inputs);
                let size = lin.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
                assert!(size > 1e-3 * a, "{name}: response {size:e}");
                rel.push(relative_difference(&nl, &lin, 0));
            }
            let ratio = rel[0] / rel[1];
            assert!(
                rel[0] < 1e-3,
                "{name}: relative difference {:e} at the larger amplitude",
                rel[0]
            );
            assert!((50.0..200.0).contains(&ratio), "{name}: {rel:?}, ratio {ratio}");
        }
    }

    #[test]
    fn the_energy_balance_holds_while_the_energy_changes() {
        // A steer torque step, a roll torque series and an impulse in the middle of the run
        // at 5 m/s: E - E(0) changes by 0.3 J, E - E(0) - W stays at the integrator's error
        // (measured 1.0e-9 J for RK4 at 1 ms, 6e-11 J for DOP853 at rtol 1e-10). The run is
        // split at the jumps, so RK4 keeps its order: its end agrees with DOP853's to 1e-9.
        let bike = bike();
        let inputs = Inputs {
            steer: vec![Signal::Step { value: 0.5, start: 0.1 }],
            roll: vec![Signal::Series(
                Series::new(vec![0.0, 0.5, 1.0], vec![0.0, 2.0, 0.0]).expect("series"),
            )],
            impulses: vec![Impulse { t: 0.6, roll: 0.5, steer: 0.2 }],
            feedback: Feedback::None,
        };
        let start = bike.initial_state(5.0, 0.0).expect("start");
        let grid = Grid::new(2.0, 1e-3, 10).expect("grid");
        let mut ends = Vec::new();
        for (how, bound) in
            [(Integration::RK4, 1e-8), (Integration::adaptive(Method::Dop853, 1e-10, 1e-13), 1e-8)]
        {
            let tr = bike.simulate_forced(start, &grid, &how, &[], &inputs).expect("run");
            let d = tr.diagnostics;
            assert!(
                d.max_energy_change > 0.1,
                "{:?}: energy change {:e}",
                how.method,
                d.max_energy_change
            );
            assert!(d.energy_drift < bound, "{:?}: balance {:e}", how.method, d.energy_drift);
            assert!(d.max_contact_residual < 1e-12, "{:e}", d.max_contact_residual);
            // The samples carry the work and the torques; the last work is the run's.
            let (t_end, last) = tr.last().expect("samples");
            assert_eq!(t_end, 2.0);
            assert_eq!(last.work, d.work);
            let e0 = tr.samples[0].sample.energy;
            assert!((last.sample.energy - e0 - last.work).abs() < bound);
            assert_eq!(tr.samples.len(), grid.samples());
            // The sample at the impulse (t = 0.6) is the state just after it.
            let k = tr.times.iter().position(|&t| (t - 0.6).abs() < 1e-12).expect("0.6");
            let torque = tr.samples[k].torque;
            assert!((torque[0] - 1.6).abs() < 1e-15 && torque[1] == 0.5, "{torque:?}");
            let before = &tr.samples[k - 1].sample.state;
            let after = &tr.samples[k].sample.state;
            assert!((after.lean_rate - before.lean_rate).abs() > 1e-3);
            let st = last.sample.state;
            ends.push([st.lean, st.steer, st.lean_rate, st.steer_rate]);
        }
        let gap = (0..4).map(|k| (ends[0][k] - ends[1][k]).abs()).fold(0.0, f64::max);
        assert!(gap < 1e-9, "RK4 against DOP853: {gap:e}");
    }

    #[test]
    fn an_impulse_is_the_limit_of_narrower_pulses() {
        // A pulse of area J and width w from t = 0.5 against the impulse J at 0.5: from the
        // end of the pulse the states differ by O(w) (halving w halves the difference:
        // measured 1.07e-3 and 5.4e-4 at the end for w = 20 and 10 ms). RK4
        // at 0.5 ms steps on the pulse's edges (an adaptive method may step over a pulse
        // narrower than its steps: the reason impulses are jumps).
        let bike = bike();
        let start = bike.initial_state(5.0, 0.0).expect("start");
        let grid = Grid::new(1.5, 5e-4, 100).expect("grid");
        let how = Integration::RK4;
        let j = [0.4, -0.1];
        let impulse = Inputs {
            impulses: vec![Impulse { t: 0.5, roll: j[0], steer: j[1] }],
            ..Inputs::default()
        };
        let exact = bike.simulate_forced(start, &grid, &how, &[], &impulse).expect("impulse");
        let last = |tr: &ForcedTrajectory| {
            let s = tr.last().expect("end").1.sample.state;
            [s.lean, s.steer, s.lean_rate, s.steer_rate]
        };
        let mut errors = Vec::new();
        for w in [0.02, 0.01] {
            let pulse = |jk: f64| {
                Signal::Series(
                    Series::new(vec![0.5, 0.5 + w], vec![jk / w, jk / w]).expect("pulse"),
                )
            };
            let inputs =
                Inputs { roll: vec![pulse(j[0])], steer: vec![pulse(j[1])], ..Inputs::default() };
            let tr = bike.simulate_forced(start, &grid, &how, &[], &inputs).expect("pulse");
            let (a, b) = (last(&tr), last(&exact));
            errors.push((0..4).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max));
            // Both do the same work up to O(w).
            // Both do the same work up to O(w).
            let dw = (tr.diagnostics.work - exact.diagnostics.work).abs();
            assert!(dw < 0.1 * exact.diagnostics.work.abs(), "{dw:e}");
        }
        let ratio = errors[0] / errors[1];
        assert!(errors[1] < 1e-3 && (1.6..2.5).contains(&ratio), "{errors:?}");
    }

    #[test]
    fn radau5_with_the_driven_jacobian_needs_fewer_evaluations_for_the_same_run() {
        // Radau5 driven by a steer torque step and the feedback (constant gains, and a gain
        // table read at the rear contact's speed), from a lean of 0.02 rad, 5 s: with the
        // generated Jacobian and its feedback chain term (`ForcedRate::jacobian`) it takes the
        // steps forward differences took and ends as close to DOP853 at 1e-13, with fewer
        // evaluations of the right-hand side (forward differences cost twelve per Jacobian).
        // Measured at rtol 1e-8: constant gains 2,949 evaluations against 4,185 (387 steps,
        // 35 rejected, each), the table 2,953 against 4,141 (398 steps, 28 rejected); the same
        // ends (errors 6.5e-10 and 3.0e-10 both ways). Handing Radau5 no Jacobian (the driven
        // run before) fails the count.
        let bike = bike();
        let g = Gains::balance_assist(20.0);
        let mut g2 = g;
        g2.0[1][0] = 2.0;
        g2.0[0][0] = -5.0;
        let table = GainTable::new(vec![(0.0, g2), (4.0, g), (10.0, g2)]).expect("table");
        for (name, speed, feedback) in [
            ("constant gains", 5.0, Feedback::Constant(g)),
            ("gain table", 3.0, Feedback::Table(table)),
        ] {
            let inputs = Inputs {
                steer: vec![Signal::Step { value: 0.5, start: 0.1 }],
                feedback,
                ..Inputs::default()
            };
            let start = bike.initial_state(speed, 0.02).expect("start");
            let grid = Grid::new(5.0, 1e-3, 1000).expect("grid");
            let never = AtomicBool::new(false);
            let run = |how: Integration, by: JacobianBy| {
                bike.simulate_forced_with(start, &grid, &how, &[], &inputs, &never, by)
                    .expect("run")
            };
            let reference =
                run(Integration::adaptive(Method::Dop853, 1e-13, 1e-15), JacobianBy::Generated);
            let end = |tr: &ForcedTrajectory| {
                let s = tr.last().expect("end").1.sample.state;
                [s.lean, s.steer, s.lean_rate, s.steer_rate]
            };
            let err = |tr: &ForcedTrajectory| {
                let (a, b) = (end(tr), end(&reference));
                (0..4).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max)
            };
            let radau = Integration::adaptive(Method::Radau5, 1e-8, 1e-11);
            let exact = run(radau, JacobianBy::Generated);
            let fd = run(radau, JacobianBy::ForwardDifferences);
            eprintln!(
                "{name}: generated {:?}, error {:.1e}; forward differences {:?}, error {:.1e}",
                exact.stats,
                err(&exact),
                fd.stats,
                err(&fd)
            );
            assert!(err(&exact) < 1e-7 && err(&fd) < 1e-7, "{name}");
            assert!(
                5 * exact.stats.rhs_evaluations < 4 * fd.stats.rhs_evaluations,
                "{name}: generated {:?} against forward differences {:?}",
                exact.stats,
                fd.stats
            );
        }
    }

    #[test]
    fn radau5_runs_the_driven_bicycle_past_the_crates_step_collapse() {
        // Issue 35: at 2 m/s from a lean of 0.05 rad with k_steer_roll_rate = -20, Radau5 at
        // rtol 1e-8 stopped at t = 3.3416 s with "step size below double precision", with
        // the generated Jacobian as with forward differences: differential-equations 0.7.0
        // kept its iteration matrices of the step 0.0160 s for the steps it tried after
        // (0.0145 s, then halved down to 1e-18 s), so that every one was rejected
        // (`numerics::integrate`'s module docs). Restarted from its last accepted step, the run
        // ends within 1e-8 of DOP853 at 1e-13 (measured: lean 4.3e-10, steer 3.2e-9; without
        // the restart both runs fail at 3.3416 s).
        let bike = bike();
        let inputs = Inputs {
            feedback: Feedback::Constant(Gains::balance_assist(20.0)),
            ..Inputs::default()
        };
        let start = bike.initial_state(2.0, 0.05).expect("start");
        let grid = Grid::new(5.0, 1e-3, 1000).expect("grid");
        let never = AtomicBool::new(false);
        let run = |how: Integration, by: JacobianBy| {
            bike.simulate_forced_with(start, &grid, &how, &[], &inputs, &never, by)
        };
        let end = |tr: &ForcedTrajectory| {
            let (t, s) = tr.last().expect("end");
            let s = s.sample.state;
            (t, [s.lean, s.steer, s.lean_rate, s.steer_rate])
        };
        let reference =
            run(Integration::adaptive(Method::Dop853, 1e-13, 1e-15), JacobianBy::Generated)
                .expect("dop853");
        let (_, b) = end(&reference);
        for by in [JacobianBy::Generated, JacobianBy::ForwardDifferences] {
            let tr = run(Integration::adaptive(Method::Radau5, 1e-8, 1e-11), by);
            let tr = match tr {
                Ok(tr) => tr,
                Err(e) => panic!("radau5 ({by:?}) failed: {e}"),
            };
            let (t, a) = end(&tr);
            let err = (0..4).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max);
            eprintln!("radau5 ({by:?}): {:?}, error at the end {err:.1e}", tr.stats);
            assert_eq!(t, 5.0, "{by:?}");
            assert!(err < 1e-8, "radau5 ({by:?}) against dop853: {err:e}");
        }
    }

    #[test]
    fn balance_assist_makes_the_lean_decay_at_2_mps() {
        // At 2 m/s the benchmark is unstable (weave from 4.29 m/s): from a 0.01 rad lean it
        // falls to 0.1 rad; the balance assist k_steer_roll_rate = -20 (stable from 1.80 m/s,
        // `window`) makes the lean decay.
        let bike = bike();
        let start = bike.initial_state(2.0, 0.01).expect("start");
        let grid = Grid::new(6.0, 1e-3, 100).expect("grid");
        let stops = [Stop::parse("lean=±0.1").expect("stop")];
        let run = |inputs: &Inputs| {
            bike.simulate_forced(start, &grid, &Integration::RK4, &stops, inputs).expect("run")
        };
        let peak = |inputs: &Inputs| {
            let tr = run(inputs);
            assert_eq!(tr.event, None);
            let late = tr.iter().filter(|(t, _)| *t >= 5.0);
            late.map(|(_, s)| s.sample.state.lean.abs()).fold(0.0, f64::max)
        };
        let open = run(&Inputs::default());
        let fell = open.event.expect("the open loop falls").1;
        assert!(fell < 6.0, "{fell}");
        let assist = Feedback::Constant(Gains::balance_assist(20.0));
        let closed = peak(&Inputs { feedback: assist, ..Inputs::default() });
        assert!(closed < 0.002, "closed loop: lean {closed} after 5 s");
        // A gain table constant at those gains gives the same run bit for bit; one that does
        // not cover 2 m/s is an error naming the speed.
        let g = Gains::balance_assist(20.0);
        let table = GainTable::new(vec![(1.0, g), (3.0, g)]).expect("table");
        let tabled = peak(&Inputs { feedback: Feedback::Table(table), ..Inputs::default() });
        assert_eq!(tabled, closed);
        let table = GainTable::new(vec![(3.0, g), (4.0, g)]).expect("table");
        let inputs = Inputs { feedback: Feedback::Table(table), ..Inputs::default() };
        let e = bike.simulate_forced(start, &grid, &Integration::RK4, &[], &inputs).unwrap_err();
        let NonlinearError::Input(InputError::OutsideGainTable { t, speed, from, to }) = e else {
            panic!("{e:?}")
        };
        assert_eq!((t, from, to), (0.0, 3.0, 4.0));
        assert!((speed - 2.0).abs() < 1e-12, "{speed}");
        assert!(e.to_string().contains("outside the gain table's speeds 3 to 4 m/s"), "{e}");
    }

    #[test]
    fn undriven_it_is_the_plain_simulation_and_bad_inputs_are_named() {
        let bike = bike();
        let start = bike.initial_state(4.0, 0.02).expect("start");
        let grid = Grid::new(1.0, 1e-3, 50).expect("grid");
        let stops = [Stop::parse("lean=±0.5").expect("stop")];
        let plain = bike.simulate_with(start, &grid, &Integration::RK4, &stops).expect("plain");
        let forced = bike
            .simulate_forced(start, &grid, &Integration::RK4, &stops, &Inputs::default())
            .expect("forced");
        assert_eq!(plain.times, forced.times);
        for (p, f) in plain.samples.iter().zip(&forced.samples) {
            assert_eq!(*p, f.sample);
            assert_eq!((f.torque, f.work), ([0.0, 0.0], 0.0));
        }
        assert_eq!(plain.stats, forced.stats);
        assert_eq!(plain.energy_drift, forced.diagnostics.energy_drift);

        assert_eq!(
            Series::new(vec![0.0, 0.2, 0.2], vec![1.0, 2.0, 3.0]),
            Err(InputError::NotIncreasing { row: 3, t: 0.2, previous: 0.2 })
        );
        let e = Series::new(vec![0.0, 0.3, 0.1], vec![0.0; 3]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid torque series: time 0.1 in row 3 does not exceed the time 0.3 before it"
        );
        assert_eq!(Series::new(vec![0.0], vec![0.0]), Err(InputError::TooFewSamples { count: 1 }));
        assert_eq!(
            Series::new(vec![0.0, 1.0], vec![0.0]),
            Err(InputError::SeriesLength { times: 2, values: 1 })
        );
        assert_eq!(
            Series::new(vec![0.0, 1.0], vec![0.0, f64::NAN]).unwrap_err().to_string(),
            "invalid torque series: value NaN in row 2 is not finite"
        );
        let s = Series::new(vec![1.0, 2.0], vec![4.0, 2.0]).expect("ok");
        assert_eq!(
            [s.at(0.5), s.at(1.0), s.at(1.5), s.at(2.0), s.at(2.5)],
            [0.0, 4.0, 3.0, 0.0, 0.0]
        );
        for (j, want) in [
            (
                Impulse { t: 0.0105, roll: 1.0, steer: 0.0 },
                "invalid impulse time 0.0105 s: not a multiple of the step 0.001 s",
            ),
            (
                Impulse { t: 1.0, roll: 1.0, steer: 0.0 },
                "invalid impulse time 1 s: outside the run [0, 1) s",
            ),
            (Impulse { t: -0.1, roll: 1.0, steer: 0.0 }, "invalid impulse time -0.1 s: outside"),
            (
                Impulse { t: 0.5, roll: f64::INFINITY, steer: 0.0 },
                "invalid impulse inf: must be finite",
            ),
        ] {
            let inputs = Inputs { impulses: vec![j], ..Inputs::default() };
            let e =
                bike.simulate_forced(start, &grid, &Integration::RK4, &[], &inputs).unwrap_err();
            assert!(e.to_string().starts_with(want), "{e}");
        }
        let inputs = Inputs {
            steer: vec![Signal::Step { value: f64::NAN, start: 0.0 }],
            ..Inputs::default()
        };
        let e = bike.simulate_forced(start, &grid, &Integration::RK4, &[], &inputs).unwrap_err();
        assert_eq!(e.to_string(), "invalid step value NaN: must be finite");
    }
}
