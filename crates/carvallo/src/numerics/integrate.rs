//! Integration of $x' = f(t, x)$ for any fixed state size, by the classical fourth-order
//! Runge–Kutta method at a fixed step (the baseline) or by an error-controlled embedded pair
//! with dense output — Dormand and Prince's 5(4) pair (`dopri5`), Hairer's 8(5,3) pair
//! (`dop853`, dense output of order 7) and Verner's "most efficient" 9(8) pair (`vern9`, with
//! an interpolant of order 9) — from the `differential-equations` crate, with samples on a
//! fixed time grid and terminal events located by root finding.
//!
//! Why that crate: it implements both pairs with Hairer's coefficients and step control,
//! dense output and embedded error estimates on `[f64; N]` states (no allocation per step), is
//! Apache-2.0 and actively maintained. What it does not do is done here: a right-hand side
//! that can fail (the bicycle's contact constraint may have no solution) is wrapped so the
//! failure survives as a typed error; samples on a fixed grid come from its interpolant; events
//! are located on the same interpolant by the Illinois variant of regula falsi (on the cubic
//! Hermite interpolant of each step for RK4, whose order matches the method's) so that
//! several named events and their times are reported.
//!
//! Of the crate's Verner pairs only the 9(8) one is offered. Its 6(5), 7(6) and 8(7) pairs
//! (`rkv656e`, `rkv767e`, `rkv878e` in 0.7.0) have coefficients that meet the order
//! conditions only to about $10^{-13}$ ($\sum_j a_{ij} - c_i$ up to $5 \cdot 10^{-14}$,
//! $5.6 \cdot 10^{-14}$ and $8.7 \cdot 10^{-13}$): at a fixed step on $y' = y^2$ from 0.9 over
//! [0, 1] their relative errors stop falling at about $10^{-12}$, $2 \cdot 10^{-13}$ and
//! $10^{-11}$ (halving the step from 1/160 to 1/320: $2.3 \cdot 10^{-12} \to 9.7 \cdot
//! 10^{-13}$, $5.9 \cdot 10^{-12} \to 1.8 \cdot 10^{-13}$, $3.2 \cdot 10^{-11} \to
//! 1.4 \cdot 10^{-11}$), and on the nonlinear rotation $x' = v r^2$, $v' = -x r^2$ over one
//! period near $2 \cdot 10^{-11}$, $3 \cdot 10^{-12}$ and $10^{-10}$, where DOP853 and the
//! 9(8) pair reach $10^{-14}$. The 9(8) pair's error estimate, like all of the crate's
//! `Adaptive` family, is a maximum that skips NaN, so a step with a failed evaluation is
//! accepted rather than rejected: such a run ends with the model's error at that step
//! (DOPRI5 and DOP853 shrink the step instead and may pass).
//!
//! The crate's Radau5 (0.7.0) keeps its iteration matrices after a rejected step and after a
//! change of step whose Newton iterations contracted fast, where Hairer's RADAU5 decomposes
//! them again for the new step (and refreshes a Jacobian that is not fresh): `step` sets
//! `call_decomp` only after an accepted step that also refreshes the Jacobian, so when the
//! step changes after a run of steps at one size that skipped both, the simplified Newton
//! iterations solve with $(u_1/h_{old}) I - J$ for the step $h$. They converge slowly or
//! diverge, the step is rejected and halved, and the matrix stays the old one: the error
//! estimate, solved with the same matrix, grows as $h_{old}/h$, so every smaller step is
//! rejected too, down to $h < 10^{-16} h_{old}$, the crate's "step size below double
//! precision". When that happens after at least one accepted step since the run (re)started,
//! the run is restarted from the last accepted step with a fresh solver (its first step the
//! last accepted one), which computes the Jacobian and the matrices anew, at most
//! [`MAX_RESTARTS`] times; a collapse with no accepted step since is reported.
//!
//! The grid of samples, the event functions and an observer of every accepted step are the
//! caller's; [`integrate`] returns the counts ([`Stats`]) and the event that ended the run.

use std::cell::{Cell, RefCell};
use std::convert::Infallible;
use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};

use differential_equations::control::ControlFlag;
use differential_equations::error::Error;
use differential_equations::interpolate::Interpolation;
use differential_equations::linalg::Matrix;
use differential_equations::methods::{
    Adaptive, DormandPrince, ExplicitRungeKutta, ImplicitRungeKutta, Ordinary, Radau,
};
use differential_equations::ode::{solve_ode, OrdinaryNumericalMethod, ODE};
use differential_equations::solout::Solout;
use differential_equations::solution::Solution;

/// What an integration counted (defined beside [`Trajectory`], which carries it, so that
/// this module depends on [`crate::numerics::ode`] and not the other way).
pub use crate::numerics::ode::Stats;
use crate::numerics::ode::{EnergyDrift, Trajectory};

/// The crate's DOPRI5: order 5, 7 stages.
type Dopri5<const N: usize> = ExplicitRungeKutta<Ordinary, DormandPrince, f64, [f64; N], 5, 7, 7>;
/// The crate's DOP853: order 8, 12 stages, 16 with the dense output's.
type Dop853<const N: usize> = ExplicitRungeKutta<Ordinary, DormandPrince, f64, [f64; N], 8, 12, 16>;
/// The crate's Radau IIA of order 5.
type Radau5<const N: usize> = ImplicitRungeKutta<Ordinary, Radau, f64, [f64; N], 5, 3, 3>;
/// The crate's Verner 9(8) pair (its `rkv989e`): order 9, 16 stages, 26 with the interpolant's.
type Vern9<const N: usize> = ExplicitRungeKutta<Ordinary, Adaptive, f64, [f64; N], 9, 16, 26>;

/// The integration method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// The classical fourth-order Runge–Kutta method at the grid's fixed step.
    Rk4,
    /// Dormand and Prince's embedded 5(4) pair with step control and dense output of order 4.
    Dopri5,
    /// Hairer's DOP853: the 8(5,3) pair of Dormand and Prince with dense output of order 7.
    Dop853,
    /// Verner's efficient 9(8) pair RKV98IIa (16 stages) with an interpolant of order 9
    /// (10 more stages, evaluated after an accepted step). The crate's 6(5), 7(6) and 8(7)
    /// pairs are left out: their coefficients satisfy the order conditions only to about
    /// 1e-13 (at a fixed step their errors stop falling near 1e-12 to 1e-10, see the module
    /// docs).
    Vern9,
    /// Radau IIA of order 5 (three implicit stages, simplified Newton iterations, dense output
    /// of order 3 between the stages' collocation polynomial): for stiff variants. It uses the
    /// model's Jacobian when the caller gives one ([`integrate_with_jacobian`]), forward
    /// differences otherwise.
    Radau5,
}

impl Method {
    /// Every method, the baseline first.
    pub const ALL: [Method; 5] =
        [Method::Rk4, Method::Dopri5, Method::Dop853, Method::Vern9, Method::Radau5];

    /// The method's name on the command line (`rk4`, `dopri5`, `dop853`, `vern9`).
    pub fn name(self) -> &'static str {
        match self {
            Method::Rk4 => "rk4",
            Method::Dopri5 => "dopri5",
            Method::Dop853 => "dop853",
            Method::Vern9 => "vern9",
            Method::Radau5 => "radau5",
        }
    }

    /// The method named `name`, `None` for an unknown name.
    pub fn from_name(name: &str) -> Option<Method> {
        Method::ALL.into_iter().find(|m| m.name() == name)
    }

    /// The order of the method (of the pair's higher-order solution, which is propagated).
    pub fn order(self) -> u32 {
        match self {
            Method::Rk4 => 4,
            Method::Dopri5 => 5,
            Method::Dop853 => 8,
            Method::Vern9 => 9,
            Method::Radau5 => 5,
        }
    }

    /// Whether the method is implicit (solves for its stages by Newton's method).
    pub fn is_implicit(self) -> bool {
        self == Method::Radau5
    }

    /// Whether the method controls its step from an error estimate.
    pub fn is_adaptive(self) -> bool {
        self != Method::Rk4
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// How to integrate: the method and, for the adaptive ones, the tolerances. The local error
/// of every accepted step is at most about `atol + rtol |x|` per component (root mean square).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Integration {
    /// The method.
    pub method: Method,
    /// The relative tolerance (adaptive methods).
    pub rtol: f64,
    /// The absolute tolerance (adaptive methods).
    pub atol: f64,
}

impl Integration {
    /// The classical Runge–Kutta method (its step is the grid's).
    pub const RK4: Integration = Integration { method: Method::Rk4, rtol: 0.0, atol: 0.0 };

    /// An adaptive method with the tolerances `rtol` and `atol`.
    pub fn adaptive(method: Method, rtol: f64, atol: f64) -> Integration {
        Integration { method, rtol, atol }
    }

    /// The default relative tolerance of the command line and the Python module.
    pub const DEFAULT_RTOL: f64 = 1e-8;

    /// `method` with the tolerances given or the defaults: `rtol` [`DEFAULT_RTOL`](Self::DEFAULT_RTOL),
    /// `atol` $10^{-3}$ `rtol` (ignored for RK4).
    pub fn with_defaults(method: Method, rtol: Option<f64>, atol: Option<f64>) -> Integration {
        if !method.is_adaptive() {
            return Integration::RK4;
        }
        let rtol = rtol.unwrap_or(Integration::DEFAULT_RTOL);
        Integration { method, rtol, atol: atol.unwrap_or_else(|| thousandth(rtol)) }
    }

    /// The first setting that cannot be used, as (name, value, reason): for an adaptive
    /// method a tolerance that is not finite, negative, or `rtol` below $10^{-15}$ (beyond
    /// double precision) or both zero; `None` when all can be used.
    pub fn unusable(&self) -> Option<(&'static str, f64, &'static str)> {
        if !self.method.is_adaptive() {
            return None;
        }
        for (name, v) in [("rtol", self.rtol), ("atol", self.atol)] {
            if !v.is_finite() {
                return Some((name, v, "must be finite"));
            }
            if v < 0.0 {
                return Some((name, v, "must not be negative"));
            }
        }
        if self.rtol < 1e-15 && self.rtol != 0.0 {
            return Some(("rtol", self.rtol, "must be at least 1e-15"));
        }
        if self.rtol == 0.0 && self.atol == 0.0 {
            return Some(("atol", self.atol, "must be positive when rtol is zero"));
        }
        None
    }
}

/// $10^{-3} x$ as the decimal reading does it: the double nearest to `x`'s shortest decimal
/// with its exponent lowered by 3 (`1e-8` gives the double nearest $10^{-11}$, which `1e-3 *
/// 1e-8` misses by an ulp).
fn thousandth(x: f64) -> f64 {
    let text = format!("{x:e}");
    text.split_once('e')
        .and_then(|(m, e)| format!("{m}e{}", e.parse::<i32>().ok()? - 3).parse().ok())
        .unwrap_or(x / 1000.0)
}

/// The fixed grid of a run: `n` steps of `h` from time 0, a sample every `every` steps and at
/// the end. RK4 steps on it; the adaptive methods sample their dense output at its times
/// $i h$ ($i$ a multiple of `every`, or $n$).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// The step (s).
    pub h: f64,
    /// The number of steps.
    pub n: usize,
    /// A sample every so many steps.
    pub every: usize,
}

impl Grid {
    /// The grid of `duration` in steps as close to `step` as divide it evenly (`duration /
    /// round(duration / step)`), sampled every `every` steps.
    ///
    /// # Errors
    /// (name, value, reason) for a duration or step that is not finite and positive, a step
    /// longer than the duration, more than ten million steps, or `every == 0`.
    pub fn new(
        duration: f64,
        step: f64,
        every: usize,
    ) -> Result<Grid, (&'static str, f64, &'static str)> {
        for (name, v) in [("duration", duration), ("step", step)] {
            if !v.is_finite() {
                return Err((name, v, "must be finite"));
            }
            if v <= 0.0 {
                return Err((name, v, "must be positive"));
            }
        }
        if step > duration {
            return Err(("step", step, "must not exceed the duration"));
        }
        let n = (duration / step).round();
        if n > 1e7 {
            return Err(("step", step, "gives more than ten million steps"));
        }
        if every == 0 {
            return Err(("every", 0.0, "must be positive"));
        }
        let n = n as usize;
        Ok(Grid { h: duration / n as f64, n, every })
    }

    /// As [`Grid::new`], but the step is kept as given: an error unless `duration / step` is a
    /// whole number to $10^{-9}$ relative, so that a step is never silently changed (a step of
    /// 0.3 s over 1 s is refused, naming the step and the nearest steps that divide it).
    ///
    /// # Errors
    /// As [`Grid::new`], and (`"step"`, step, reason) for a step that does not divide the
    /// duration.
    pub fn exact(
        duration: f64,
        step: f64,
        every: usize,
    ) -> Result<Grid, (&'static str, f64, &'static str)> {
        let g = Grid::new(duration, step, every)?;
        let ratio = duration / step;
        if (ratio - g.n as f64).abs() > 1e-9 * ratio {
            return Err(("step", step, "does not divide the duration into whole steps"));
        }
        Ok(g)
    }

    /// The time of grid point `i`, $i h$.
    pub fn time(&self, i: usize) -> f64 {
        i as f64 * self.h
    }

    /// The final time, $n h$.
    pub fn end(&self) -> f64 {
        self.time(self.n)
    }

    /// Whether grid point `i` is sampled.
    pub fn sampled(&self, i: usize) -> bool {
        i.is_multiple_of(self.every) || i == self.n
    }

    /// The number of samples, the first included.
    pub fn samples(&self) -> usize {
        self.n / self.every + 1 + usize::from(!self.n.is_multiple_of(self.every))
    }
}

/// A terminal event: the first zero crossing of one of the event functions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing<const N: usize> {
    /// Which event function crossed zero (its index).
    pub index: usize,
    /// When (s).
    pub t: f64,
    /// The state then, from the interpolant.
    pub state: [f64; N],
}

/// Why a point is shown to the observer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Point {
    /// The end of an accepted step (before the samples inside it).
    Step,
    /// A sample of the grid (time $ih$, grid index $i$).
    Sample(usize),
    /// The event that ends the run.
    Event,
}

/// Why an integration failed.
#[derive(Clone, Debug, PartialEq)]
pub enum IntegrateError<E> {
    /// The right-hand side, an event function or the observer failed.
    Model(E),
    /// The adaptive method's step fell below what double precision can resolve at `t`.
    StepTooSmall {
        /// The time reached (s).
        t: f64,
    },
    /// More than the allowed number of steps (ten million for RK4's grid, a million
    /// attempted steps for the adaptive methods).
    TooManySteps {
        /// The time reached (s).
        t: f64,
    },
    /// The method detected stiffness at `t` (the explicit pairs then take tiny steps).
    Stiff {
        /// The time reached (s).
        t: f64,
    },
    /// The right-hand side is not finite at the start (an adaptive method cannot take a step).
    NotFinite {
        /// The time (s).
        t: f64,
    },
    /// More event functions than [`MAX_EVENTS`].
    TooManyEvents {
        /// How many were given.
        count: usize,
    },
}

impl<E: fmt::Display> fmt::Display for IntegrateError<E> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IntegrateError::Model(e) => write!(f, "{e}"),
            IntegrateError::StepTooSmall { t } => {
                write!(f, "the step size fell below double precision at t = {t} s")
            }
            IntegrateError::TooManySteps { t } => write!(f, "too many steps before t = {t} s"),
            IntegrateError::NotFinite { t } => {
                write!(f, "the right-hand side is not finite at t = {t} s")
            }
            IntegrateError::Stiff { t } => write!(f, "the problem became stiff at t = {t} s"),
            IntegrateError::TooManyEvents { count } => {
                write!(f, "{count} events: at most {MAX_EVENTS} may end a run")
            }
        }
    }
}

impl<E: fmt::Debug + fmt::Display> std::error::Error for IntegrateError<E> {}

impl IntegrateError<Infallible> {
    /// The same failure, for a model whose evaluations can fail with `E`.
    pub fn widen<E>(self) -> IntegrateError<E> {
        match self {
            IntegrateError::Model(never) => match never {},
            IntegrateError::StepTooSmall { t } => IntegrateError::StepTooSmall { t },
            IntegrateError::TooManySteps { t } => IntegrateError::TooManySteps { t },
            IntegrateError::NotFinite { t } => IntegrateError::NotFinite { t },
            IntegrateError::Stiff { t } => IntegrateError::Stiff { t },
            IntegrateError::TooManyEvents { count } => IntegrateError::TooManyEvents { count },
        }
    }
}

/// What a successful integration returns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome<const N: usize> {
    /// The counts.
    pub stats: Stats,
    /// The event that ended the run, `None` when it reached the end of the grid.
    pub event: Option<Crossing<N>>,
    /// The last time and state (the event's when there is one).
    pub end: (f64, [f64; N]),
    /// Whether the stop flag of [`integrate_until`] ended the run early, at `end` (the last
    /// accepted step; the samples shown are those up to it).
    pub interrupted: bool,
}

/// A right-hand side $f(t, x)$ that may fail with `E`.
pub type Rhs<'a, const N: usize, E> = dyn FnMut(f64, &[f64; N]) -> Result<[f64; N], E> + 'a;

/// The Jacobian $\partial f/\partial x$ of a right-hand side at $(t, x)$, by rows.
pub type JacobianFn<'a, const N: usize, E> =
    dyn FnMut(f64, &[f64; N]) -> Result<[[f64; N]; N], E> + 'a;

/// An event function $g(x)$ whose sign changes end a run.
pub type EventFn<'a, const N: usize, E> = dyn FnMut(&[f64; N]) -> Result<f64, E> + 'a;

/// What sees the points of a run ([`Point`]).
pub type Observer<'a, const N: usize, E> = dyn FnMut(Point, f64, &[f64; N]) -> Result<(), E> + 'a;

/// The last evaluations (t, x, f(x)) a [`System`] keeps.
type Evaluations<const N: usize> = [(f64, [f64; N], [f64; N]); RECENT];

/// The most steps (accepted or rejected) an adaptive run may attempt.
const MAX_STEPS: usize = 1_000_000;

/// The most times a Radau5 run is restarted from its last accepted step after the crate's
/// step collapsed (see the module docs).
pub const MAX_RESTARTS: usize = 100;

/// After so many failed or non-finite evaluations in a row the wrapped right-hand side is no
/// longer called (the step control only shrinks the step until it gives up).
const MAX_FAILURES: usize = 1000;

/// Integrates $x' = f(t, x)$ from `x0` at time 0 over the grid `grid` by `how`.
///
/// `observe(kind, t, x)` sees the initial state as [`Point::Sample`]`(0)`, then in time order
/// the end of every accepted step ([`Point::Step`]), the samples of the grid (exact states
/// for RK4, the dense output for the adaptive methods; the last one at the grid's end) and
/// the event that ends the run ([`Point::Event`], after which nothing is shown). `events`
/// are functions $g_j(x)$; the run ends at the first time one of them changes sign (a zero at
/// the start does not count) — the crossing is located on the interpolant to about
/// $10^{-15}$ relative in time.
///
/// # Errors
/// [`IntegrateError::Model`] when `rhs`, an event function or `observe` fails (the first
/// failure of a right-hand side evaluation in a step the adaptive methods then reject is
/// kept only when the run fails), and the adaptive methods' failures. Settings are not checked
/// here ([`Integration::unusable`]).
pub fn integrate<'e, const N: usize, E: Clone>(
    how: &Integration,
    grid: &Grid,
    x0: [f64; N],
    rhs: &mut Rhs<'_, N, E>,
    events: &mut [&'e mut EventFn<'e, N, E>],
    observe: &mut Observer<'_, N, E>,
) -> Result<Outcome<N>, IntegrateError<E>> {
    integrate_until(how, grid, x0, rhs, events, observe, &AtomicBool::new(false))
}

/// [`integrate`] that also ends when `stop` is set (by a Ctrl-C handler, or the thread that
/// waits for the run): the flag is read after every accepted step, so the run ends within one
/// step of it being set, with [`Outcome::interrupted`] and the last accepted step as its end.
///
/// # Errors
/// As [`integrate`].
pub fn integrate_until<'e, const N: usize, E: Clone>(
    how: &Integration,
    grid: &Grid,
    x0: [f64; N],
    rhs: &mut Rhs<'_, N, E>,
    events: &mut [&'e mut EventFn<'e, N, E>],
    observe: &mut Observer<'_, N, E>,
    stop: &AtomicBool,
) -> Result<Outcome<N>, IntegrateError<E>> {
    integrate_with_jacobian(how, grid, x0, rhs, None, events, observe, stop)
}

/// [`integrate_until`] with the right-hand side's Jacobian $\partial f/\partial x$, which the
/// implicit method ([`Method::Radau5`]) uses for its Newton iterations instead of forward
/// differences ($N$ more evaluations each time it refreshes the Jacobian); the explicit
/// methods ignore it. A failing or non-finite Jacobian makes the step fail like a failing
/// right-hand side.
///
/// # Errors
/// As [`integrate`].
#[allow(clippy::too_many_arguments)]
pub fn integrate_with_jacobian<'e, const N: usize, E: Clone>(
    how: &Integration,
    grid: &Grid,
    x0: [f64; N],
    rhs: &mut Rhs<'_, N, E>,
    jacobian: Option<&mut JacobianFn<'_, N, E>>,
    events: &mut [&'e mut EventFn<'e, N, E>],
    observe: &mut Observer<'_, N, E>,
    stop: &AtomicBool,
) -> Result<Outcome<N>, IntegrateError<E>> {
    if events.len() > MAX_EVENTS {
        return Err(IntegrateError::TooManyEvents { count: events.len() });
    }
    observe(Point::Sample(0), 0.0, &x0).map_err(IntegrateError::Model)?;
    let mut watch = Watch::new();
    watch.start(events, &x0).map_err(IntegrateError::Model)?;
    match how.method {
        Method::Rk4 => rk4(grid, x0, rhs, events, observe, &mut watch, stop),
        Method::Dopri5 => adaptive(
            |h0| Dopri5::<N>::dopri5().rtol(how.rtol).atol(how.atol).max_steps(MAX_STEPS).h0(h0),
            how,
            5,
            grid,
            x0,
            (rhs, None),
            events,
            observe,
            &mut watch,
            stop,
        ),
        Method::Dop853 => adaptive(
            |h0| Dop853::<N>::dop853().rtol(how.rtol).atol(how.atol).max_steps(MAX_STEPS).h0(h0),
            how,
            8,
            grid,
            x0,
            (rhs, None),
            events,
            observe,
            &mut watch,
            stop,
        ),
        Method::Vern9 => adaptive(
            |h0| Vern9::<N>::rkv989e().rtol(how.rtol).atol(how.atol).max_steps(MAX_STEPS).h0(h0),
            how,
            9,
            grid,
            x0,
            (rhs, None),
            events,
            observe,
            &mut watch,
            stop,
        ),
        Method::Radau5 => adaptive(
            |h0| {
                // newton_tol(0): Hairer's default min(0.03, rtol'^(1/2)) (the crate's is a
                // fixed 3.2e-3, whose Newton error floors the run near 1e-6 at any tolerance).
                // The tolerances go in one per component: differential-equations 0.7.0 turns
                // them into Hairer's rtol' = 0.1 rtol^(2/3) once per component, in place, so a
                // scalar tolerance is transformed N times and tends to 1e-3 whatever the rtol
                // asked (for the bicycle's 11 components, rtol 1e-12 ran at rtol' 8e-4: its
                // error stalled near 5e-6 at every rtol).
                Radau5::<N>::radau5()
                    .rtol([how.rtol; N])
                    .atol([how.atol; N])
                    .newton_tol(0.0)
                    .max_steps(MAX_STEPS)
                    .h0(h0)
            },
            how,
            5,
            grid,
            x0,
            (rhs, jacobian),
            events,
            observe,
            &mut watch,
            stop,
        ),
    }
}

/// The most event functions of one run.
pub const MAX_EVENTS: usize = 11;

/// The signs of the event functions since the start (the last nonzero value of each).
struct Watch {
    last: [f64; MAX_EVENTS],
}

impl Watch {
    fn new() -> Watch {
        Watch { last: [0.0; MAX_EVENTS] }
    }

    fn start<const N: usize, E>(
        &mut self,
        events: &mut [&mut EventFn<'_, N, E>],
        x: &[f64; N],
    ) -> Result<(), E> {
        for (j, g) in events.iter_mut().enumerate() {
            self.last[j] = g(x)?;
        }
        Ok(())
    }

    /// The earliest crossing within the step from `ta` to `tb` (state `xb` at `tb`), located
    /// on `interp`; updates the signs when there is none.
    fn check<const N: usize, E>(
        &mut self,
        events: &mut [&mut EventFn<'_, N, E>],
        ta: f64,
        tb: f64,
        xb: &[f64; N],
        interp: &mut dyn FnMut(f64) -> [f64; N],
    ) -> Result<Option<Crossing<N>>, E> {
        let mut best: Option<Crossing<N>> = None;
        let mut now = [0.0; MAX_EVENTS];
        for (j, g) in events.iter_mut().enumerate() {
            let gb = g(xb)?;
            now[j] = gb;
            let ga = self.last[j];
            let crossed = (ga != 0.0 && gb == 0.0) || ga * gb < 0.0;
            if !crossed {
                continue;
            }
            let mut err = None;
            let mut h = |t: f64| match g(&interp(t)) {
                Ok(v) => v,
                Err(e) => {
                    err.get_or_insert(e);
                    0.0
                }
            };
            let t = illinois(&mut h, ta, tb, ga, gb);
            if let Some(e) = err {
                return Err(e);
            }
            if best.is_none_or(|b| t < b.t) {
                best = Some(Crossing { index: j, t, state: interp(t) });
            }
        }
        if best.is_none() {
            for (j, &gb) in now.iter().enumerate().take(events.len()) {
                if gb != 0.0 {
                    self.last[j] = gb;
                }
            }
        }
        Ok(best)
    }
}

/// The zero of `g` in $[a, b]$ where $g(a) = g_a$ and $g(b) = g_b$ have opposite signs (or
/// $g_b = 0$), by the Illinois variant of regula falsi, to about four ulps of the time.
fn illinois(g: &mut dyn FnMut(f64) -> f64, a: f64, b: f64, ga: f64, gb: f64) -> f64 {
    if gb == 0.0 {
        // The zero may be reached earlier inside the step; bisect on the sign of `ga`.
        let (mut lo, mut hi) = (a, b);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            let gm = g(mid);
            if gm == 0.0 || gm * ga < 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return hi;
    }
    let crossed = gb.signum();
    let (mut a, mut b, mut fa, mut fb) = (a, b, ga, gb);
    let mut same_side_twice = false;
    for _ in 0..200 {
        if (b - a).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs()) {
            break;
        }
        let mut c = (a * fb - b * fa) / (fb - fa);
        if !(c > a.min(b) && c < a.max(b)) {
            c = 0.5 * (a + b);
        }
        let fc = g(c);
        if fc == 0.0 {
            return c;
        }
        if fc * fb < 0.0 {
            (a, fa) = (b, fb);
            same_side_twice = false;
        } else {
            if same_side_twice {
                fa *= 0.5;
            }
            same_side_twice = true;
        }
        (b, fb) = (c, fc);
    }
    // Of the two ends, four ulps apart, the one where the function has crossed.
    if fb.signum() == crossed {
        b
    } else {
        a
    }
}

/// The classical Runge–Kutta method on the grid.
fn rk4<'e, const N: usize, E: Clone>(
    grid: &Grid,
    x0: [f64; N],
    rhs: &mut Rhs<'_, N, E>,
    events: &mut [&'e mut EventFn<'e, N, E>],
    observe: &mut Observer<'_, N, E>,
    watch: &mut Watch,
    stop: &AtomicBool,
) -> Result<Outcome<N>, IntegrateError<E>> {
    let h = grid.h;
    let mut x = x0;
    let mut stats = Stats::default();
    let m = IntegrateError::Model;
    let mut k1 = rhs(0.0, &x).map_err(m)?;
    stats.rhs_evaluations += 1;
    for i in 1..=grid.n {
        let t0 = grid.time(i - 1);
        if stop.load(Ordering::Relaxed) {
            return Ok(Outcome { stats, event: None, end: (t0, x), interrupted: true });
        }
        let axpy = |y: &[f64; N], a: f64, k: &[f64; N]| -> [f64; N] {
            std::array::from_fn(|j| y[j] + a * k[j])
        };
        let k2 = rhs(t0 + h / 2.0, &axpy(&x, h / 2.0, &k1)).map_err(m)?;
        let k3 = rhs(t0 + h / 2.0, &axpy(&x, h / 2.0, &k2)).map_err(m)?;
        let k4 = rhs(t0 + h, &axpy(&x, h, &k3)).map_err(m)?;
        let x1: [f64; N] =
            std::array::from_fn(|j| x[j] + h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]));
        let t1 = grid.time(i);
        stats.steps += 1;
        stats.rhs_evaluations += 3;
        let mut f1 = None;
        if !events.is_empty() {
            // The cubic Hermite interpolant of the step needs the slope at its end.
            let d1 = rhs(t1, &x1).map_err(m)?;
            stats.rhs_evaluations += 1;
            f1 = Some(d1);
            let (xa, da) = (x, k1);
            let mut interp = |t: f64| hermite(t0, t1, &xa, &x1, &da, &d1, t);
            if let Some(c) = watch.check(events, t0, t1, &x1, &mut interp).map_err(m)? {
                observe(Point::Event, c.t, &c.state).map_err(m)?;
                return Ok(Outcome {
                    stats,
                    event: Some(c),
                    end: (c.t, c.state),
                    interrupted: false,
                });
            }
        }
        observe(Point::Step, t1, &x1).map_err(m)?;
        if grid.sampled(i) {
            observe(Point::Sample(i), t1, &x1).map_err(m)?;
        }
        x = x1;
        if i < grid.n {
            k1 = match f1 {
                Some(d) => d,
                None => {
                    stats.rhs_evaluations += 1;
                    rhs(t1, &x).map_err(m)?
                }
            };
        }
    }
    Ok(Outcome { stats, event: None, end: (grid.end(), x), interrupted: false })
}

/// The cubic Hermite interpolant at `t` of the step from (`t0`, `x0`, slope `d0`) to (`t1`,
/// `x1`, slope `d1`).
fn hermite<const N: usize>(
    t0: f64,
    t1: f64,
    x0: &[f64; N],
    x1: &[f64; N],
    d0: &[f64; N],
    d1: &[f64; N],
    t: f64,
) -> [f64; N] {
    let h = t1 - t0;
    let s = (t - t0) / h;
    let (h00, h10) = ((1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s), s * (1.0 - s) * (1.0 - s));
    let (h01, h11) = (s * s * (3.0 - 2.0 * s), s * s * (s - 1.0));
    std::array::from_fn(|j| h00 * x0[j] + h10 * h * d0[j] + h01 * x1[j] + h11 * h * d1[j])
}

/// The right-hand side as the crate's `ODE`: a failure is kept (the first one) and shows as
/// NaN slopes, which the step control rejects.
///
/// Evaluations the crate asks for twice are not repeated. A call at a point (t, x) among the
/// last evaluations, bit for bit, returns its slope (the crate's `init` evaluates the initial
/// slope that Hairer's initial step, computed here, already has): the same bits. And with
/// `fsal` (DOPRI5, whose seventh stage is the slope at the step's end, "first same as last"),
/// a call at the time of the previous evaluation and within [`FSAL_ULPS`] ulps of its state in
/// every component returns that slope: the crate evaluates the seventh stage at
/// $x + h \sum_j a_{7j} k_j$ and then again at the step's end $x + h \sum_j b_j k_j$, the
/// same point ($a_{7j} = b_j$) up to the rounding of the two sums, so DOPRI5 costs six
/// evaluations per step, as Hairer's, instead of seven.
struct System<'a, const N: usize, E> {
    rhs: RefCell<&'a mut Rhs<'a, N, E>>,
    jacobian: Option<RefCell<&'a mut JacobianFn<'a, N, E>>>,
    /// Whether the method's last stage is the slope at the step's end (DOPRI5).
    fsal: bool,
    failure: RefCell<Option<E>>,
    evaluations: Cell<usize>,
    failures_in_a_row: Cell<usize>,
    /// The last evaluations (t, x, f(x)), newest at `newest`: the slopes at the ends of a
    /// step are found here (DOP853 evaluates three dense-output stages after the end's).
    recent: RefCell<Evaluations<N>>,
    newest: Cell<usize>,
}

/// How many evaluations [`System`] remembers.
const RECENT: usize = 6;

/// How far apart (in ulps of the larger, per component) two states of the same time may be
/// for [`System`] to take one's slope for the other's (DOPRI5's last stage and its step's end).
const FSAL_ULPS: f64 = 8.0;

impl<'a, const N: usize, E> System<'a, N, E> {
    fn new(rhs: &'a mut Rhs<'a, N, E>, fsal: bool) -> Self {
        System::with_jacobian(rhs, None, fsal)
    }

    fn with_jacobian(
        rhs: &'a mut Rhs<'a, N, E>,
        jacobian: Option<&'a mut JacobianFn<'a, N, E>>,
        fsal: bool,
    ) -> Self {
        System {
            rhs: RefCell::new(rhs),
            jacobian: jacobian.map(RefCell::new),
            fsal,
            failure: RefCell::new(None),
            evaluations: Cell::new(0),
            failures_in_a_row: Cell::new(0),
            recent: RefCell::new([(f64::NAN, [f64::NAN; N], [f64::NAN; N]); RECENT]),
            newest: Cell::new(0),
        }
    }

    /// The slope the method computed at (`t`, `x`), if among the last evaluations.
    fn slope(&self, t: f64, x: &[f64; N]) -> Option<[f64; N]> {
        let recent = self.recent.borrow();
        (0..RECENT)
            .map(|k| &recent[(self.newest.get() + RECENT - k) % RECENT])
            .find(|(tk, xk, _)| *tk == t && xk == x)
            .map(|e| e.2)
    }

    /// The slope of an evaluation that stands for one at (`t`, `x`): see the type's docs.
    fn known(&self, t: f64, x: &[f64; N]) -> Option<[f64; N]> {
        if let Some(d) = self.slope(t, x) {
            return Some(d);
        }
        if !self.fsal {
            return None;
        }
        let recent = self.recent.borrow();
        let (tl, xl, dl) = &recent[self.newest.get()];
        let close = xl
            .iter()
            .zip(x)
            .all(|(a, b)| (a - b).abs() <= FSAL_ULPS * f64::EPSILON * a.abs().max(b.abs()));
        (*tl == t && close).then_some(*dl)
    }

    /// Keeps (`t`, `x`, `d`) as the newest evaluation.
    fn remember(&self, t: f64, x: &[f64; N], d: [f64; N]) {
        let k = (self.newest.get() + 1) % RECENT;
        self.recent.borrow_mut()[k] = (t, *x, d);
        self.newest.set(k);
    }
}

impl<const N: usize, E> ODE<f64, [f64; N]> for System<'_, N, E> {
    fn jacobian(&self, t: f64, y: &[f64; N], j: &mut Matrix<f64>) {
        let Some(jac) = &self.jacobian else {
            // Forward differences, as the crate's default does, through `diff` (so that the
            // evaluations are counted and a failure is kept).
            let mut f0 = [0.0; N];
            self.diff(t, y, &mut f0);
            let eps = f64::EPSILON.sqrt();
            for c in 0..N {
                let dx = eps * y[c].abs().max(1.0);
                let mut yp = *y;
                yp[c] += dx;
                let mut f1 = [0.0; N];
                self.diff(t, &yp, &mut f1);
                for r in 0..N {
                    j[(r, c)] = (f1[r] - f0[r]) / dx;
                }
            }
            return;
        };
        let rows = match (jac.borrow_mut())(t, y) {
            Ok(rows) => rows,
            Err(e) => {
                self.failure.borrow_mut().get_or_insert(e);
                [[f64::NAN; N]; N]
            }
        };
        for (r, row) in rows.iter().enumerate() {
            for (c, v) in row.iter().enumerate() {
                j[(r, c)] = *v;
            }
        }
    }

    fn diff(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]) {
        *dydt = [f64::NAN; N];
        let bad = self.failures_in_a_row.get();
        if bad >= MAX_FAILURES {
            return;
        }
        if let Some(d) = self.known(t, y) {
            *dydt = d;
            // Found again by `slope` at this very point (the step's end).
            self.remember(t, y, d);
            return;
        }
        self.evaluations.set(self.evaluations.get() + 1);
        match (self.rhs.borrow_mut())(t, y) {
            Ok(d) if d.iter().all(|v| v.is_finite()) => {
                *dydt = d;
                self.failures_in_a_row.set(0);
                self.remember(t, y, d);
            }
            Ok(d) => {
                *dydt = d;
                self.failures_in_a_row.set(bad + 1);
            }
            Err(e) => {
                self.failure.borrow_mut().get_or_insert(e);
                self.failures_in_a_row.set(bad + 1);
            }
        }
    }
}

/// The crate's output hook: samples the dense output on the grid, watches the events and
/// shows every accepted step.
struct Sampler<'a, 'b, const N: usize, E> {
    system: &'a System<'a, N, E>,
    /// Whether the method is DOP853, whose dense output the crate evaluates wrongly.
    dop853: bool,
    /// The slope at the start of the current step.
    slope: [f64; N],
    grid: Grid,
    next: usize,
    events: &'a mut [&'b mut EventFn<'b, N, E>],
    observe: &'a mut Observer<'a, N, E>,
    watch: &'a mut Watch,
    event: Option<Crossing<N>>,
    failure: Option<E>,
    /// The time of an accepted step that ended on a non-finite state (see `solout`).
    non_finite: Option<f64>,
    end: (f64, [f64; N]),
    /// The flag that ends the run early, and whether it did.
    stop: &'a AtomicBool,
    interrupted: bool,
    /// The accepted steps shown, and the length of the last one.
    accepted: usize,
    last_h: f64,
}

impl<const N: usize, E> Sampler<'_, '_, N, E> {
    fn step(
        &mut self,
        ta: f64,
        tb: f64,
        xb: &[f64; N],
        interp: &mut dyn FnMut(f64) -> [f64; N],
    ) -> Result<bool, E> {
        let stop = if self.events.is_empty() {
            None
        } else {
            self.watch.check(self.events, ta, tb, xb, interp)?
        };
        let last = stop.map_or(tb, |c| c.t);
        if stop.is_none() {
            (self.observe)(Point::Step, tb, xb)?;
        }
        let end = self.grid.n;
        while self.next <= end {
            let i = self.next;
            let t = self.grid.time(i);
            // The final sample is the state at the grid's end, reached up to rounding.
            let at_end = i == end && stop.is_none() && tb >= t - 4.0 * f64::EPSILON * t.abs();
            if t > last && !at_end {
                break;
            }
            if stop.is_some_and(|c| t >= c.t) {
                break;
            }
            let x = if at_end || t == tb { *xb } else { interp(t.clamp(ta, tb)) };
            (self.observe)(Point::Sample(i), t, &x)?;
            self.next = if i == end { end + 1 } else { (i + self.grid.every).min(end) };
        }
        if let Some(c) = stop {
            (self.observe)(Point::Event, c.t, &c.state)?;
            self.end = (c.t, c.state);
            self.event = Some(c);
            return Ok(true);
        }
        self.end = (tb, *xb);
        Ok(false)
    }
}

impl<const N: usize, E> Solout<f64, [f64; N]> for Sampler<'_, '_, N, E> {
    fn solout<I>(
        &mut self,
        t_curr: f64,
        t_prev: f64,
        y_curr: &[f64; N],
        y_prev: &[f64; N],
        interpolator: &mut I,
        _solution: &mut Solution<f64, [f64; N]>,
    ) -> ControlFlag<f64, [f64; N]>
    where
        I: Interpolation<f64, [f64; N]> + ?Sized,
    {
        let slope = self.system.slope(t_curr, y_curr).unwrap_or([f64::NAN; N]);
        let slope0 = std::mem::replace(&mut self.slope, slope);
        if t_curr == t_prev {
            // The call at the start: the initial sample is already shown.
            return ControlFlag::Continue;
        }
        if !y_curr.iter().all(|v| v.is_finite()) {
            // The crate's Verner pairs (its `Adaptive` family) measure the error by a maximum
            // that skips NaN, so a step whose evaluation failed (NaN slopes, see `System`) is
            // accepted instead of rejected; such a run ends here with the failure.
            self.non_finite = Some(t_curr);
            return ControlFlag::Terminate;
        }
        self.accepted += 1;
        self.last_h = t_curr - t_prev;
        let dop853 = self.dop853;
        let mut interp = |t: f64| {
            let t = t.clamp(t_prev, t_curr);
            if !dop853 {
                return interpolator.interpolate(t).unwrap_or([f64::NAN; N]);
            }
            // differential-equations 0.7.0 evaluates DOP853's dense output polynomial
            // c0 + s(c1 + s1(c2 + s(c3 + s1 p(s)))), p(s) = c4 + s(c5 + s1(c6 + s c7)),
            // with s and s1 = 1 - s exchanged inside p. The part before p, q(s), is the cubic
            // Hermite interpolant of the step and s² s1² is symmetric, so the right value is
            // the crate's at 1 - s, minus q(1 - s), plus q(s).
            let h = t_curr - t_prev;
            let s = (t - t_prev) / h;
            let mirrored = interpolator.interpolate(t_prev + (t_curr - t)).unwrap_or([f64::NAN; N]);
            let q = |s: f64, j: usize| {
                let c1 = y_curr[j] - y_prev[j];
                let c2 = h * slope0[j] - c1;
                let c3 = c1 - h * slope[j] - c2;
                y_prev[j] + s * (c1 + (1.0 - s) * (c2 + s * c3))
            };
            std::array::from_fn(|j| mirrored[j] - q(1.0 - s, j) + q(s, j))
        };
        match self.step(t_prev, t_curr, y_curr, &mut interp) {
            Ok(false) if self.stop.load(Ordering::Relaxed) => {
                self.interrupted = true;
                ControlFlag::Terminate
            }
            Ok(false) => ControlFlag::Continue,
            Ok(true) => ControlFlag::Terminate,
            Err(e) => {
                self.failure = Some(e);
                ControlFlag::Terminate
            }
        }
    }
}

/// An adaptive method of the crate, set to the tolerances, over the grid's span.
#[allow(clippy::too_many_arguments)]
fn adaptive<'e, const N: usize, E: Clone, S>(
    make: impl Fn(f64) -> S,
    how: &Integration,
    order: i32,
    grid: &Grid,
    x0: [f64; N],
    (rhs, jacobian): (&mut Rhs<'_, N, E>, Option<&mut JacobianFn<'_, N, E>>),
    events: &mut [&'e mut EventFn<'e, N, E>],
    observe: &mut Observer<'_, N, E>,
    watch: &mut Watch,
    stop: &AtomicBool,
) -> Result<Outcome<N>, IntegrateError<E>>
where
    S: OrdinaryNumericalMethod<f64, [f64; N]> + Interpolation<f64, [f64; N]>,
{
    let fsal = how.method == Method::Dopri5;
    let system = match jacobian {
        Some(j) => System::with_jacobian(rhs, Some(j), fsal),
        None => System::new(rhs, fsal),
    };
    let mut slope = [0.0; N];
    system.diff(0.0, &x0, &mut slope);
    if let Some(e) = system.failure.borrow_mut().take() {
        return Err(IntegrateError::Model(e));
    }
    if !slope.iter().all(|v| v.is_finite()) {
        return Err(IntegrateError::NotFinite { t: 0.0 });
    }
    // Hairer's initial step (`hinit` of DOP853 and DOPRI5), here so that it allocates nothing
    // (the crate's keeps a vector of scales): one more evaluation, after that of the slope.
    let sk: [f64; N] = std::array::from_fn(|i| how.atol + how.rtol * x0[i].abs());
    let norm = |v: &[f64; N]| v.iter().zip(&sk).map(|(a, s)| (a / s) * (a / s)).sum::<f64>();
    let (dnf, dny) = (norm(&slope), norm(&x0));
    let end = grid.end();
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 { 1e-6 } else { (dny / dnf).sqrt() * 0.01 };
    h = h.min(end);
    let x1: [f64; N] = std::array::from_fn(|i| x0[i] + h * slope[i]);
    let mut slope1 = [0.0; N];
    system.diff(h, &x1, &mut slope1);
    let change: [f64; N] = std::array::from_fn(|i| slope1[i] - slope[i]);
    let der2 = norm(&change).sqrt() / h;
    let der12 = der2.abs().max(dnf.sqrt());
    let h1 = if der12 <= 1e-15 {
        (h * 1e-3).max(1e-6)
    } else {
        (0.01 / der12).powf(1.0 / f64::from(order))
    };
    let h0 = (100.0 * h).min(h1).min(end);
    let h0 = if h0.is_finite() && h0 > 0.0 { h0 } else { 1e-6f64.min(end) };
    let mut sampler = Sampler {
        system: &system,
        dop853: how.method == Method::Dop853,
        slope: [f64::NAN; N],
        grid: *grid,
        next: grid.every.min(grid.n),
        events,
        observe,
        watch,
        event: None,
        failure: None,
        non_finite: None,
        end: (0.0, x0),
        stop,
        interrupted: false,
        accepted: 0,
        last_h: h0,
    };
    // Radau5 restarts from its last accepted step when the crate's step collapses (module
    // docs): the accepted steps before the last restart, counted by the sampler (the crate
    // returns no counts with its error, so the rejected attempts of a collapsed segment are
    // not counted).
    let (mut start, mut h_start, mut earlier, mut restarts) = ((0.0, x0), h0, 0, 0);
    let solution = loop {
        let mut method = make(h_start);
        let result = solve_ode(&mut method, &system, start.0, end, &start.1, &mut sampler);
        if let Some(e) = sampler.failure.take() {
            return Err(IntegrateError::Model(e));
        }
        if let Some(t) = sampler.non_finite {
            return Err(match system.failure.borrow_mut().take() {
                Some(f) => IntegrateError::Model(f),
                None => IntegrateError::NotFinite { t },
            });
        }
        match result {
            Ok(s) => break s,
            Err(e) => {
                if let Some(f) = system.failure.borrow_mut().take() {
                    return Err(IntegrateError::Model(f));
                }
                let progressed = sampler.end.0 > start.0;
                if matches!(e, Error::StepSize { .. })
                    && how.method.is_implicit()
                    && progressed
                    && restarts < MAX_RESTARTS
                {
                    restarts += 1;
                    earlier = sampler.accepted;
                    (start, h_start) = (sampler.end, sampler.last_h);
                    continue;
                }
                return Err(match e {
                    Error::StepSize { t, .. } => IntegrateError::StepTooSmall { t },
                    Error::Stiffness { t, .. } => IntegrateError::Stiff { t },
                    Error::MaxSteps { t, .. } => IntegrateError::TooManySteps { t },
                    _ => IntegrateError::StepTooSmall { t: sampler.end.0 },
                });
            }
        }
    };
    let stats = Stats {
        rhs_evaluations: system.evaluations.get(),
        steps: earlier + solution.steps.accepted,
        rejected_steps: solution.steps.rejected,
    };
    if sampler.interrupted {
        return Ok(Outcome { stats, event: None, end: sampler.end, interrupted: true });
    }
    if sampler.event.is_none() && sampler.next <= grid.n {
        // The crate ended a hair before the grid's end (a last step shorter than 10 ulps).
        let x = sampler.end.1;
        (sampler.observe)(Point::Sample(grid.n), grid.end(), &x).map_err(IntegrateError::Model)?;
        sampler.end = (grid.end(), x);
    }
    Ok(Outcome { stats, event: sampler.event, end: sampler.end, interrupted: false })
}

/// A terminal event on one state component: `x[index] - value` changes sign, or with
/// `magnitude` $|x_{index}| - $ `value` does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Threshold {
    /// The component watched.
    pub index: usize,
    /// The threshold.
    pub value: f64,
    /// Whether the magnitude is watched.
    pub magnitude: bool,
}

impl Threshold {
    /// Reads `NAME=VALUE` (the component named NAME crosses VALUE) or `NAME=±VALUE` /
    /// `NAME=+-VALUE` (its magnitude reaches VALUE), the components named by `names` in their
    /// order; `None` for an unknown name, a VALUE that is not a finite number, or a negative
    /// magnitude.
    ///
    /// # Example
    /// ```
    /// use carvallo::numerics::integrate::Threshold;
    /// let t = Threshold::parse("theta=±0.5", &["theta", "p", "n", "s"]);
    /// assert_eq!(t, Some(Threshold { index: 0, value: 0.5, magnitude: true }));
    /// assert_eq!(Threshold::parse("lean=0.5", &["theta", "p", "n", "s"]), None);
    /// ```
    pub fn parse(text: &str, names: &[&str]) -> Option<Threshold> {
        let (name, value) = text.split_once('=')?;
        let index = names.iter().position(|n| *n == name.trim())?;
        let (magnitude, value) = Threshold::parse_bound(value)?;
        Some(Threshold { index, value, magnitude })
    }

    /// The VALUE of a condition: `(false, x)` for a finite number x, `(true, x)` for `±x` or
    /// `+-x` with x finite and not negative (a magnitude bound); `None` otherwise.
    pub fn parse_bound(value: &str) -> Option<(bool, f64)> {
        let value = value.trim();
        let (magnitude, number) = match value.strip_prefix('±').or_else(|| value.strip_prefix("+-"))
        {
            Some(rest) => (true, rest),
            None => (false, value),
        };
        let value: f64 = number.parse().ok().filter(|v: &f64| v.is_finite())?;
        if magnitude && value < 0.0 {
            return None;
        }
        Some((magnitude, value))
    }

    /// The condition as [`parse`](Self::parse) reads it (`theta=±0.5`), the component named
    /// by `names` (its index when `names` is too short).
    pub fn text(&self, names: &[&str]) -> String {
        let name = names.get(self.index).map_or_else(|| self.index.to_string(), |n| n.to_string());
        format!("{name}={}{}", if self.magnitude { "±" } else { "" }, self.value)
    }
}

/// Integrates the autonomous system $x' = f(x)$ that conserves `energy` from `x0` over
/// `grid` by `how`, keeping the grid's samples (the state at an event last) and the largest
/// energy drift over the accepted steps, until the end or the first of `stops` met.
///
/// # Errors
/// The adaptive methods' failures, more than [`MAX_EVENTS`] stops (settings are not checked:
/// [`Integration::unusable`]); a `stops` index beyond the state is never met.
pub fn conservative<const N: usize>(
    how: &Integration,
    grid: &Grid,
    x0: [f64; N],
    rhs: impl Fn([f64; N]) -> [f64; N],
    energy: impl Fn([f64; N]) -> f64,
    stops: &[Threshold],
) -> Result<Trajectory<[f64; N], EnergyDrift>, IntegrateError<Infallible>> {
    conservative_until(how, grid, x0, rhs, None, energy, stops, &AtomicBool::new(false))
}

/// The state Jacobian $\partial f/\partial x$ of an autonomous right-hand side, for
/// [`conservative_until`].
pub type StateJacobian<'a, const N: usize> = &'a dyn Fn([f64; N]) -> [[f64; N]; N];

/// [`conservative`] that also ends when `stop` is set ([`integrate_until`]): the samples up to
/// the last accepted step, with its time in [`Trajectory::interrupted`]. With `jacobian`, the
/// implicit method's Newton iterations use it instead of forward differences
/// ([`integrate_with_jacobian`]).
///
/// # Errors
/// As [`conservative`].
#[allow(clippy::too_many_arguments)]
pub fn conservative_until<const N: usize>(
    how: &Integration,
    grid: &Grid,
    x0: [f64; N],
    rhs: impl Fn([f64; N]) -> [f64; N],
    jacobian: Option<StateJacobian<'_, N>>,
    energy: impl Fn([f64; N]) -> f64,
    stops: &[Threshold],
    stop: &AtomicBool,
) -> Result<Trajectory<[f64; N], EnergyDrift>, IntegrateError<Infallible>> {
    let energy0 = energy(x0);
    let drift = EnergyDrift { energy0, max_energy_drift: 0.0 };
    let mut trajectory = Trajectory::with_capacity(grid.h, grid.samples(), drift);
    let mut max_drift = 0.0f64;
    let mut f = |_t: f64, x: &[f64; N]| -> Result<[f64; N], Infallible> { Ok(rhs(*x)) };
    let mut watchers: [_; MAX_EVENTS] = std::array::from_fn(|j| {
        let stop = stops.get(j).copied();
        move |x: &[f64; N]| -> Result<f64, Infallible> {
            Ok(match stop {
                Some(s) => {
                    let v = x.get(s.index).copied().unwrap_or(f64::NAN);
                    if s.magnitude {
                        v.abs() - s.value
                    } else {
                        v - s.value
                    }
                }
                None => f64::NAN,
            })
        }
    });
    let mut events: [&mut EventFn<'_, N, Infallible>; MAX_EVENTS] =
        watchers.each_mut().map(|w| w as &mut EventFn<'_, N, Infallible>);
    let count = stops.len();
    if count > MAX_EVENTS {
        return Err(IntegrateError::TooManyEvents { count });
    }
    let mut observe = |kind: Point, t: f64, x: &[f64; N]| -> Result<(), Infallible> {
        match kind {
            Point::Step => max_drift = max_drift.max((energy(*x) - energy0).abs()),
            Point::Sample(_) | Point::Event => trajectory.push(t, *x),
        }
        Ok(())
    };
    let mut jac = jacobian
        .map(|j| move |_t: f64, x: &[f64; N]| -> Result<[[f64; N]; N], Infallible> { Ok(j(*x)) });
    let outcome = integrate_with_jacobian(
        how,
        grid,
        x0,
        &mut f,
        jac.as_mut().map(|j| j as &mut JacobianFn<'_, N, Infallible>),
        &mut events[..count],
        &mut observe,
        stop,
    )?;
    trajectory.diagnostics.max_energy_drift = max_drift;
    trajectory.stats = outcome.stats;
    trajectory.event = outcome.event.map(|c| (c.index, c.t));
    trajectory.interrupted = outcome.interrupted.then_some(outcome.end.0);
    Ok(trajectory)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// $x'' = -x$ from (1, 0): $x = \cos t$, $x' = -\sin t$.
    fn oscillator(_t: f64, x: &[f64; 2]) -> Result<[f64; 2], Infallible> {
        Ok([x[1], -x[0]])
    }

    #[test]
    fn a_stop_flag_ends_the_run_after_the_step_that_saw_it() {
        // The observer sets the flag at the first step past t = 1 (as a Ctrl-C handler would,
        // from anywhere): the run ends there, interrupted, its samples those up to it.
        let grid = Grid::new(10.0, 0.01, 1).expect("grid");
        for how in [
            Integration::RK4,
            Integration::adaptive(Method::Dopri5, 1e-8, 1e-11),
            Integration::adaptive(Method::Dop853, 1e-8, 1e-11),
            Integration::adaptive(Method::Vern9, 1e-8, 1e-11),
        ] {
            let stop = AtomicBool::new(false);
            let (mut set_at, mut last_sample, mut steps_after) = (None, 0.0, 0);
            let mut observe = |kind: Point, t: f64, _x: &[f64; 2]| -> Result<(), Infallible> {
                match kind {
                    Point::Step if set_at.is_some() => steps_after += 1,
                    Point::Step if t >= 1.0 => {
                        set_at = Some(t);
                        stop.store(true, Ordering::Relaxed);
                    }
                    Point::Sample(_) => last_sample = t,
                    _ => {}
                }
                Ok(())
            };
            let out = integrate_until(
                &how,
                &grid,
                [1.0, 0.0],
                &mut oscillator,
                &mut [],
                &mut observe,
                &stop,
            )
            .expect("run");
            let set_at = set_at.expect("a step past t = 1");
            assert!(out.interrupted, "{}", how.method);
            assert_eq!(steps_after, 0, "{}", how.method);
            assert_eq!(out.end.0, set_at, "{}", how.method);
            assert!(last_sample <= set_at && set_at - last_sample < 0.01 + 1e-12, "{}", how.method);
            assert!((out.end.1[0] - set_at.cos()).abs() < 1e-6, "{}", how.method);
        }
        // Unset, the same run reaches the end.
        let out = integrate_until(
            &Integration::RK4,
            &grid,
            [1.0, 0.0],
            &mut oscillator,
            &mut [],
            &mut |_, _, _| Ok(()),
            &AtomicBool::new(false),
        )
        .expect("run");
        assert!(!out.interrupted);
        assert_eq!(out.end.0, 10.0);
    }

    #[test]
    fn evaluations_are_not_repeated() {
        // DOPRI5: six new stages per attempted step (the seventh is the end's slope, FSAL),
        // plus the initial slope and Hairer's initial step; DOP853 twelve and three for its
        // dense output. A few ends more than FSAL_ULPS from the last stage (components
        // crossing zero) are evaluated again: at most one attempt in ten here.
        let grid = Grid::new(10.0, 0.01, 1).expect("grid");
        for (method, per_step) in [(Method::Dopri5, 6), (Method::Dop853, 15)] {
            let how = Integration::adaptive(method, 1e-9, 1e-12);
            let (out, samples) = run(&how, &grid);
            let attempts = out.stats.steps + out.stats.rejected_steps;
            let least =
                2 + per_step * out.stats.steps + (per_step.min(12) - 1) * out.stats.rejected_steps;
            assert!(out.stats.rhs_evaluations >= least, "{method}: {:?}", out.stats);
            assert!(
                out.stats.rhs_evaluations <= least + attempts / 10,
                "{method}: {:?}, expected about {least}",
                out.stats
            );
            // The reuse changes nothing beyond rounding: the oscillator is still x = cos t.
            let worst = samples.iter().map(|(t, x)| (x[0] - t.cos()).abs()).fold(0.0, f64::max);
            assert!(worst < 1e-7, "{method}: {worst:e}");
        }
    }

    fn run(how: &Integration, grid: &Grid) -> (Outcome<2>, Vec<(f64, [f64; 2])>) {
        let mut samples = Vec::new();
        let mut observe = |kind: Point, t: f64, x: &[f64; 2]| -> Result<(), Infallible> {
            if kind != Point::Step {
                samples.push((t, *x));
            }
            Ok(())
        };
        let out =
            integrate(how, grid, [1.0, 0.0], &mut oscillator, &mut [], &mut observe).expect("run");
        (out, samples)
    }

    fn largest_error(samples: &[(f64, [f64; 2])]) -> f64 {
        samples
            .iter()
            .map(|(t, x)| (x[0] - t.cos()).abs().max((x[1] + t.sin()).abs()))
            .fold(0.0, f64::max)
    }

    #[test]
    fn rk4_is_fourth_order_and_counts_four_evaluations_a_step() {
        let mut errors = Vec::new();
        for n in [50, 100, 200] {
            let grid = Grid { h: std::f64::consts::TAU / n as f64, n, every: 1 };
            let (out, samples) = run(&Integration::RK4, &grid);
            assert_eq!(out.stats, Stats { rhs_evaluations: 4 * n, steps: n, rejected_steps: 0 });
            assert_eq!(samples.len(), n + 1);
            errors.push(largest_error(&samples));
        }
        for w in errors.windows(2) {
            let ratio = w[0] / w[1];
            assert!((14.0..18.0).contains(&ratio), "rk4 error ratio {ratio} ({errors:?})");
        }
    }

    /// A problem with a known solution: $x' = f(t, x)$ from `exact(0)` to `end`.
    struct Known {
        rhs: fn(f64, &[f64; 2]) -> Result<[f64; 2], Infallible>,
        exact: fn(f64) -> [f64; 2],
        end: f64,
    }

    impl Known {
        /// The largest over the components of $|x - x_{exact}| / \max(1, |x_{exact}|)$.
        fn error(&self, t: f64, x: &[f64; 2]) -> f64 {
            let e = (self.exact)(t);
            (0..2).map(|i| (x[i] - e[i]).abs() / e[i].abs().max(1.0)).fold(0.0, f64::max)
        }
    }

    /// The oscillator over one period.
    const OSCILLATOR: Known =
        Known { rhs: oscillator, exact: |t| [t.cos(), -t.sin()], end: std::f64::consts::TAU };

    /// $y' = y^2$, $z' = -y z$ from (0.9, 1) to $t = 1$: $y = 0.9 / (1 - 0.9 t)$ grows
    /// tenfold towards its pole at $t = 1/0.9$, $z = 1 - 0.9 t$. Nonlinear, so every
    /// elementary differential of the order conditions is present (on a linear problem a
    /// method of many stages can show an order above its own).
    const POLE: Known = Known {
        rhs: |_t, x| Ok([x[0] * x[0], -x[0] * x[1]]),
        exact: |t| [0.9 / (1.0 - 0.9 * t), 1.0 - 0.9 * t],
        end: 1.0,
    };

    /// A pair of the crate at the fixed step `end / n` (tolerances so loose that no step is
    /// rejected): the error at the end and the largest at the midpoints of the steps (dense
    /// output).
    fn fixed_step_errors<S>(make: &impl Fn(f64) -> S, problem: &Known, n: usize) -> (f64, f64)
    where
        S: OrdinaryNumericalMethod<f64, [f64; 2]> + Interpolation<f64, [f64; 2]>,
    {
        let h = problem.end / n as f64;
        let mut f = problem.rhs;
        let system = System::new(&mut f, false);
        struct Mid<'k>(&'k Known, f64, usize, f64);
        impl Solout<f64, [f64; 2]> for Mid<'_> {
            fn solout<I>(
                &mut self,
                t: f64,
                tp: f64,
                y: &[f64; 2],
                _yp: &[f64; 2],
                interp: &mut I,
                _s: &mut Solution<f64, [f64; 2]>,
            ) -> ControlFlag<f64, [f64; 2]>
            where
                I: Interpolation<f64, [f64; 2]> + ?Sized,
            {
                if t > tp {
                    let m = 0.5 * (t + tp);
                    let x = interp.interpolate(m).expect("inside the step");
                    self.1 = self.1.max(self.0.error(m, &x));
                    self.2 += 1;
                    self.3 = self.0.error(t, y);
                }
                ControlFlag::Continue
            }
        }
        let mut mid = Mid(problem, 0.0, 0, f64::NAN);
        let x0 = (problem.exact)(0.0);
        let sol = solve_ode(&mut make(h), &system, 0.0, problem.end, &x0, &mut mid).expect("run");
        assert_eq!((sol.steps.accepted, sol.steps.rejected, mid.2), (n, 0, n));
        (mid.3, mid.1)
    }

    /// The crate's pairs at a fixed step: the error at the end falls like $h^p$ and that of
    /// the dense output at the midpoints of the steps like $h^q$ or faster ($q = p - 1$ for
    /// DOPRI5 and DOP853, $q = p$ for Verner's 9(8)), from `n` to `m` steps.
    #[test]
    fn the_pairs_have_their_orders_at_a_fixed_step() {
        fn orders<S>(make: impl Fn(f64) -> S, problem: &Known, n: usize, m: usize) -> [f64; 2]
        where
            S: OrdinaryNumericalMethod<f64, [f64; 2]> + Interpolation<f64, [f64; 2]>,
        {
            let ((e1, d1), (e2, d2)) =
                (fixed_step_errors(&make, problem, n), fixed_step_errors(&make, problem, m));
            let r = (m as f64 / n as f64).log2();
            eprintln!("{n} -> {m} steps: end {e1:.2e} -> {e2:.2e}, dense {d1:.2e} -> {d2:.2e}");
            [(e1 / e2).log2() / r, (d1 / d2).log2() / r]
        }
        let fixed5 = |h: f64| Dopri5::<2>::dopri5().h0(h).h_max(h).rtol(1.0).atol(1.0);
        let fixed8 = |h: f64| Dop853::<2>::dop853().h0(h).h_max(h).rtol(1.0).atol(1.0);
        let fixed9 = |h: f64| Vern9::<2>::rkv989e().h0(h).h_max(h).rtol(1.0).atol(1.0);
        let runs = [
            ("dopri5", 5.0, 4.0, orders(fixed5, &OSCILLATOR, 40, 80)),
            ("dop853", 8.0, 7.0, orders(fixed8, &OSCILLATOR, 20, 40)),
            // The end over two doublings (1.6e-7 to 6.9e-13; one doubling alone shows 8.0
            // then 9.8, before and after the asymptotic range), the dense output over the
            // second (3.9e-9 to 6.4e-12; 7.7 over the first).
            ("vern9", 9.0, 9.0, {
                let (a, b) = (orders(fixed9, &POLE, 10, 40), orders(fixed9, &POLE, 20, 40));
                [a[0], b[1]]
            }),
        ];
        for (name, p, q, [order, dense]) in runs {
            eprintln!("{name}: order {order:.2}, dense output {dense:.2}");
            assert!((p - 0.5..p + 0.7).contains(&order), "{name}: order {order}");
            assert!(dense >= q - 0.5, "{name}: dense output order {dense}");
        }
    }

    /// An adaptive run meets its tolerance: the largest error over the dense output is within
    /// ten times `rtol` (the solution is of size 1), and tightening the tolerance by 100 costs
    /// evaluations in the ratio $100^{1/p}$ of a method of order $p$ (within a factor 1.6).
    #[test]
    fn adaptive_runs_meet_their_tolerances() {
        let grid = Grid { h: 0.01, n: 1000, every: 1 };
        // Radau5 scales its tolerances as Hairer's RADAU5 does (0.1 rtol^(2/3)): see
        // `radau5_solves_a_stiff_problem`.
        for method in Method::ALL.into_iter().filter(|m| m.is_adaptive() && !m.is_implicit()) {
            let p = f64::from(method.order());
            let mut evals = Vec::new();
            for rtol in [1e-6, 1e-8, 1e-10] {
                let how = Integration::adaptive(method, rtol, 1e-3 * rtol);
                let (out, samples) = run(&how, &grid);
                let err = largest_error(&samples);
                let end = largest_error(&samples[samples.len() - 1..]);
                eprintln!(
                    "{method} rtol {rtol:e}: error {err:.2e}, at the end {end:.2e}, {:?}",
                    out.stats
                );
                // DOPRI5's dense output is of order 4: between its steps it errs more.
                let dense = if method == Method::Dopri5 { 100.0 } else { 10.0 };
                assert!(end <= 10.0 * rtol, "{method} rtol {rtol}: error at the end {end}");
                assert!(err <= dense * rtol, "{method} rtol {rtol}: error {err}");
                assert_eq!(samples.len(), 1001);
                assert_eq!(samples.last().map(|s| s.0), Some(10.0));
                evals.push(out.stats.rhs_evaluations as f64);
            }
            for w in evals.windows(2) {
                let expected = 100f64.powf(1.0 / p);
                let ratio = w[1] / w[0];
                assert!(
                    ratio > expected / 1.6 && ratio < expected * 1.6,
                    "{method}: evaluations x{ratio:.2} for rtol / 100, expected {expected:.2}"
                );
            }
        }
    }

    /// The oscillator's $x = \cos t$ crosses 0.5 first at $\pi/3$, before $|x'| = |\sin t|$
    /// reaches 0.99 at $\arcsin 0.99$: both found to about the method's error, and the second
    /// alone when it is the only event.
    #[test]
    fn events_are_found_at_their_times() {
        let grid = Grid { h: 0.01, n: 1000, every: 10 };
        let cases = [
            (Integration::RK4, 1e-9),
            (Integration::adaptive(Method::Dopri5, 1e-10, 1e-13), 1e-8),
            (Integration::adaptive(Method::Dop853, 1e-12, 1e-15), 1e-11),
            (Integration::adaptive(Method::Vern9, 1e-12, 1e-15), 1e-11),
        ];
        for (how, tol) in cases {
            for both in [true, false] {
                let mut g = |x: &[f64; 2]| -> Result<f64, Infallible> { Ok(x[0] - 0.5) };
                let mut h = |x: &[f64; 2]| -> Result<f64, Infallible> { Ok(x[1].abs() - 0.99) };
                let mut last = (0.0, [0.0; 2]);
                let mut observe = |kind: Point, t: f64, x: &[f64; 2]| -> Result<(), Infallible> {
                    if kind != Point::Step {
                        assert!(t >= last.0, "{t} after {}", last.0);
                        last = (t, *x);
                    }
                    Ok(())
                };
                let mut events: Vec<&mut EventFn<'_, 2, Infallible>> =
                    if both { vec![&mut h, &mut g] } else { vec![&mut h] };
                let out =
                    integrate(&how, &grid, [1.0, 0.0], &mut oscillator, &mut events, &mut observe)
                        .expect("run");
                let c = out.event.expect("an event");
                let (index, exact) =
                    if both { (1, std::f64::consts::FRAC_PI_3) } else { (0, 0.99f64.asin()) };
                eprintln!("{} both {both}: t = {} (error {:.1e})", how.method, c.t, c.t - exact);
                assert_eq!(c.index, index);
                assert!((c.t - exact).abs() <= tol, "{}: {} against {exact}", how.method, c.t);
                assert_eq!((last.0, out.end.0), (c.t, c.t));
                assert_eq!(last.1, c.state);
            }
        }
    }

    /// $x' = 1/(1.5 - x)$ from 0 passes $x = 1.4$ at $t = 1.12$, where its right-hand side
    /// fails: every method reports that failure (the adaptive ones after shrinking the step).
    /// On the stiff $x_1' = -\lambda(x_1 - \cos t) - \sin t$, $x_2' = x_1$ ($\lambda = 10^5$,
    /// exact solution $\cos t$, $\sin t$) over 10 s, Radau5 meets a 1e-6 error in a few hundred
    /// steps, with the exact Jacobian or by forward differences (then with more evaluations of
    /// the right-hand side and the same steps), where DOPRI5 at the same tolerance needs a step
    /// below its stability bound $3.3/\lambda$ for the whole run.
    #[test]
    fn radau5_solves_a_stiff_problem() {
        const LAMBDA: f64 = 1e5;
        let grid = Grid { h: 0.1, n: 100, every: 1 };
        let exact = |t: f64| [t.cos(), t.sin()];
        let run = |method: Method, jacobian: bool| {
            let how = Integration::adaptive(method, 1e-10, 1e-12);
            let mut f = |t: f64, x: &[f64; 2]| -> Result<[f64; 2], Infallible> {
                Ok([-LAMBDA * (x[0] - t.cos()) - t.sin(), x[0]])
            };
            let mut jac = |_t: f64, _x: &[f64; 2]| -> Result<[[f64; 2]; 2], Infallible> {
                Ok([[-LAMBDA, 0.0], [1.0, 0.0]])
            };
            let mut err = 0.0f64;
            let mut observe = |kind: Point, t: f64, x: &[f64; 2]| -> Result<(), Infallible> {
                if kind != Point::Step {
                    let e = exact(t);
                    err = err.max((x[0] - e[0]).abs()).max((x[1] - e[1]).abs());
                }
                Ok(())
            };
            let out = integrate_with_jacobian(
                &how,
                &grid,
                [1.0, 0.0],
                &mut f,
                if jacobian { Some(&mut jac) } else { None },
                &mut [],
                &mut observe,
                &AtomicBool::new(false),
            )
            .expect("run");
            eprintln!("{method} (Jacobian given: {jacobian}): error {err:.2e}, {:?}", out.stats);
            (err, out.stats)
        };
        let (err_j, with) = run(Method::Radau5, true);
        let (err_fd, without) = run(Method::Radau5, false);
        let (err_rk, explicit) = run(Method::Dopri5, false);
        assert!(err_j <= 1e-6 && err_fd <= 1e-6, "radau5 errors {err_j:e}, {err_fd:e}");
        assert!(with.steps < 500, "radau5 took {} steps", with.steps);
        assert!(without.rhs_evaluations > with.rhs_evaluations, "{without:?} vs {with:?}");
        assert!(err_rk <= 1e-5, "dopri5 error {err_rk:e}");
        assert!(explicit.steps > 100 * with.steps, "dopri5 {explicit:?} vs radau5 {with:?}");
    }

    /// Radau5's error falls with its tolerance on a system of eleven components (five
    /// pendulums of different frequencies and the integral of the first angle), against
    /// DOP853 at 1e-14. differential-equations 0.7.0 transforms a scalar tolerance once per
    /// component, in place, so given as scalars the tolerances tended to Hairer's
    /// $r' = 0.1 r^{2/3}$ iterated eleven times, about 1e-3, at every rtol; given per component
    /// they are transformed once, and the error at the end stays within 20 rtol.
    #[test]
    fn radau5_meets_its_tolerance_on_eleven_components() {
        let grid = Grid { h: 0.1, n: 50, every: 1 };
        let mut f = |_t: f64, x: &[f64; 11]| -> Result<[f64; 11], Infallible> {
            let mut d = [0.0; 11];
            for k in 0..5 {
                d[2 * k] = x[2 * k + 1];
                d[2 * k + 1] = -(1.0 + k as f64) * x[2 * k].sin();
            }
            d[10] = x[0];
            Ok(d)
        };
        let x0: [f64; 11] = std::array::from_fn(|i| if i % 2 == 0 && i < 10 { 1.0 } else { 0.0 });
        let mut end_of = |how: &Integration| {
            let mut observe =
                |_: Point, _: f64, _: &[f64; 11]| -> Result<(), Infallible> { Ok(()) };
            let out = integrate(how, &grid, x0, &mut f, &mut [], &mut observe).expect("run");
            (out.end.1, out.stats)
        };
        let (reference, _) = end_of(&Integration::adaptive(Method::Dop853, 1e-14, 1e-16));
        let mut errors = Vec::new();
        for rtol in [1e-6, 1e-8, 1e-10] {
            let (end, stats) = end_of(&Integration::adaptive(Method::Radau5, rtol, rtol));
            let err = end.iter().zip(&reference).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            eprintln!("radau5 rtol {rtol:e}: error at the end {err:.2e}, {stats:?}");
            assert!(err <= 20.0 * rtol, "radau5 rtol {rtol}: error {err}");
            errors.push(err);
        }
        for w in errors.windows(2) {
            assert!(w[1] <= w[0] / 10.0, "radau5 errors {errors:?}");
        }
    }

    #[test]
    fn a_failing_right_hand_side_is_reported() {
        let grid = Grid { h: 0.01, n: 200, every: 1 };
        for method in Method::ALL {
            let how = Integration::with_defaults(method, None, None);
            let mut f = |_t: f64, x: &[f64; 1]| -> Result<[f64; 1], &'static str> {
                if x[0] > 1.4 {
                    Err("past 1.4")
                } else {
                    Ok([1.0 / (1.5 - x[0])])
                }
            };
            let mut last = 0.0;
            let mut observe = |_: Point, t: f64, _: &[f64; 1]| {
                last = t;
                Ok(())
            };
            let e = integrate(&how, &grid, [0.0], &mut f, &mut [], &mut observe);
            assert_eq!(e, Err(IntegrateError::Model("past 1.4")), "{method}");
            assert!(last > 1.0 && last < 1.13, "{method}: last time shown {last}");
        }
    }

    #[test]
    fn settings_are_checked() {
        assert_eq!(Integration::RK4.unusable(), None);
        let bad = Integration::adaptive(Method::Dop853, -1e-8, 1e-11).unusable();
        assert_eq!(bad, Some(("rtol", -1e-8, "must not be negative")));
        let bad = Integration::adaptive(Method::Dop853, 1e-17, 1e-11).unusable();
        assert_eq!(bad, Some(("rtol", 1e-17, "must be at least 1e-15")));
        let bad = Integration::adaptive(Method::Dopri5, 0.0, 0.0).unusable();
        assert_eq!(bad, Some(("atol", 0.0, "must be positive when rtol is zero")));
        let bad = Integration::adaptive(Method::Dopri5, f64::NAN, 0.0).unusable();
        assert!(matches!(bad, Some(("rtol", _, "must be finite"))));
        for (rtol, atol) in [(1e-10, 1e-13), (1e-8, 1e-11), (2.5e-6, 2.5e-9), (1.0, 1e-3)] {
            assert_eq!(
                Integration::with_defaults(Method::Dop853, Some(rtol), None),
                Integration::adaptive(Method::Dop853, rtol, atol)
            );
        }
        assert_eq!(Grid::new(1.0, 2.0, 1), Err(("step", 2.0, "must not exceed the duration")));
        assert_eq!(Grid::new(1.0, 0.1, 0), Err(("every", 0.0, "must be positive")));
        assert_eq!(
            Grid::exact(1.0, 0.3, 1),
            Err(("step", 0.3, "does not divide the duration into whole steps"))
        );
        assert_eq!(Grid::exact(1.0, 0.1, 1).map(|g| g.n), Ok(10));
        assert_eq!(Grid::exact(6.0, 0.001, 1).map(|g| g.n), Ok(6000));
        let g = Grid::new(1.0, 0.1, 3).expect("grid");
        assert_eq!((g.n, g.samples()), (10, 5));
        assert!((0..=10).filter(|&i| g.sampled(i)).eq([0, 3, 6, 9, 10]));
        for m in Method::ALL {
            assert_eq!(Method::from_name(m.name()), Some(m));
        }
        assert_eq!(Method::from_name("vern8"), None);
    }
}
