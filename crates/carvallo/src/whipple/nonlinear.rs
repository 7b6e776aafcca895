//! The nonlinear Carvallo–Whipple bicycle: accelerations, total energy, ground tracks and a
//! simulation, from the evaluators generated over `generated/whipple_nonlinear.ir`
//! (derived by the mechanics engine, Kane's method, from the bicycle's description in
//! `codegen/src/derive/whipple/description.rs`, the 25 benchmark parameters symbolic; see
//! `codegen/src/derive/whipple/nonlinear.rs`).
//!
//! Coordinates (benchmark axes, x forward, y right, z down): the rear contact $(x, y)$, yaw ψ,
//! lean φ, rear frame pitch θ, rear wheel rotation $\theta_R$ relative to the rear frame, steer
//! δ, front wheel rotation $\theta_F$ relative to the front frame. The independent speeds are
//! $u = (\dot\varphi, \dot\delta, \dot\theta_R)$. The pitch is not a state: the holonomic front
//! contact constraint $h(\varphi, \theta, \delta) = 0$ is solved for it by Newton's method
//! (generated $h$ and $\partial h/\partial\theta$) whenever the equations are evaluated, so the
//! constraint holds to rounding along a simulation. The dependent speeds (pitch rate, yaw
//! rate, front wheel rate) are generated linear forms in $u$, and $\dot u$ solves the
//! generated $M_3 \dot u = f_3$ by LU decomposition.
//!
//! [`simulate_with`](WhippleNonlinear::simulate_with) integrates by RK4 at a fixed step or by
//! an error-controlled pair ([`crate::numerics::integrate`]), samples on a fixed grid and stops
//! at [`Stop`] conditions (the lean reaching a bound, a sign change) or at the model's own
//! limits: the fall (the lean reaching [`WhippleNonlinear::fall_angle`]) and the steer lock
//! ([`WhippleNonlinear::steer_lock`]), events like the stop conditions, so that a fall is a
//! result ([`Trajectory::fall`](crate::numerics::ode::Trajectory::fall)) and not the contact
//! constraint failing; a start beyond either is refused. A third limit is the model's own
//! singularity, below.
//!
//! # The singular configurations
//! The dependent speeds come from the front contact's three constraint rows, solved one after
//! the other: the vertical row for the pitch rate, the row along the front axle's horizontal
//! projection for the yaw rate, the row across it for the front wheel rate. Each division is
//! by a *pivot*: $b_1 = \partial(\text{row}_1)/\partial\dot\theta$ (the contact height's
//! pitch derivative up to sign: it vanishes where the pitch folds, the front wheel just
//! touching the ground), $b_2 = \partial(\text{row}_2)/\partial\dot\psi = n_F\,\lvert r
//! \rvert\cos\beta$ ($r$ the line of contacts, β its angle to the front wheel's heading on
//! the ground, $n_F$ the length of the vertical's projection on the front wheel's plane: it
//! vanishes where the front wheel stands broadside to the line of contacts) and $b_3 =
//! \partial(\text{row}_3)/\partial\dot\theta_F$ (the front wheel's rolling, vanishing where
//! it lies flat). $M_3 = A^{\mathsf T} M A$ is the kinetic energy's matrix in the independent
//! speeds, $A$ the map from them to all six speeds; with positive masses it is positive
//! definite wherever $A$ is finite, so it is never singular in the sense $\det M_3 = 0$: as a
//! pivot $b$ tends to zero, $A$ grows as $1/b$ and one eigenvalue of $M_3$ as $1/b^2$ ($\det
//! M_3$ and its condition with it), the dependent rates per unit speed and the constraint
//! forces without bound. The steer lock's singularity at $\delta = \pm\pi/2$ is $b_2 = 0$
//! upright; leaning moves it to smaller steers (the fork's ground angle is larger than δ), so
//! a falling bicycle can reach it inside the steer lock: the benchmark from 2.6 m/s and a lean
//! of 0.14 rad reaches $b_2 = 0$ at a lean of −1.18 rad and a steer of −1.357 rad at
//! t ≈ 3.93934 s, where DOPRI5 shrank its steps to $10^{-15}$ s and gave up after a million
//! steps, Radau IIA when its step fell below double precision, and RK4, DOP853 and Verner's
//! pair stepped across the pole and on to the steer lock with energy errors of 0.16 J,
//! $1.3 \cdot 10^{-3}$ J and $2.4 \cdot 10^{-4}$ J.
//!
//! A run therefore ends, status *singular*, when the smallest of the pivots relative to its
//! upright value (lean and steer zero), $\min_k b_k/b_k^{\text{upright}}$, falls to
//! [`SINGULAR_PIVOT`] = 1 %: an event like the fall (located on the interpolant,
//! [`Final::singular`], [`Trajectory::singular`](crate::numerics::ode::Trajectory::singular)),
//! watching the signed ratio, so that a step that jumps across the pole (the ratio then
//! negative) shows the crossing too (RK4 at steps of 0.01 and 0.02 s from 0.5 m/s and a lean
//! of −0.3 rad ends within $2 \cdot 10^{-6}$ s of the fine runs' 0.6844728 s). There the
//! dependent rates per unit speed are 100 times their upright size and
//! $\det M_3$ about $10^4$ times (6·10⁴ in the run above); a start at or beyond it is refused.
//! The pitch is solved, not
//! integrated and projected: every right-hand side evaluation, sample and event evaluation
//! solves $h(\varphi, \theta, \delta) = 0$ by Newton (from the last pitch found), so the
//! constraint holds to rounding whatever the method and tolerance.
//!
//! [`simulate_forced`](WhippleNonlinear::simulate_forced) drives it: roll and steer torques as
//! functions of time, impulses and state feedback, with the input's work in the energy balance
//! ([`inputs`]).
//!
//! [`basu_mandal_accelerations`](WhippleNonlinear::basu_mandal_accelerations) evaluates the
//! nine accelerations in the coordinates of Basu-Mandal, Chatterjee and Papadopoulos (Proc. R.
//! Soc. A 463, 2007), whose Table 1 is the external check of these equations
//! (`tests/tests/basu_mandal.rs`). The map between their coordinates and these:
//! their lean $\psi_b = \pi/2 - \varphi$, pitch $\phi_b = \pi - \theta$, heading
//! $\theta_b = -\psi$, steer $\psi_{f} = -\delta$, wheel rotations $\beta_r = -\theta_R$,
//! $\beta_f = -\theta_F$, and $(x_b, y_b, z_b) = (-X, Y, -Z)$ for the rear wheel centre.

use std::fmt;
use std::sync::atomic::AtomicBool;

use nalgebra::{Matrix3, Vector3};

use crate::error::ParameterError;
use crate::numerics::integrate::{self, Grid, IntegrateError, Integration, Point};

use crate::whipple::{BicycleDesign, WhippleError, WhippleParams};

pub mod inputs;
pub mod rate;

use self::rate::StateRate;

pub use self::inputs::{
    Feedback, ForcedDiagnostics, ForcedRate, ForcedSample, ForcedTrajectory, Impulse, InputError,
    Inputs, Series, Signal, FORCED_LEN,
};

crate::scene! {
    /// The front contact constraint and its pitch derivative.
    pub mod contact_scene {
        model: whipple_nonlinear,
        outputs: [contact_height, contact_height_dtheta],
    }
}

crate::scene! {
    /// Everything an evaluation of the equations of motion needs: $M_3$, $f_3$, the dependent
    /// speeds and accelerations, and the rear wheel centre's acceleration terms.
    pub mod dynamics_scene {
        model: whipple_nonlinear,
        outputs: [m3_11, m3_12, m3_13, m3_22, m3_23, m3_33, f3_1, f3_2, f3_3,
                  a_thetad_phid, a_thetad_deltad, a_thetad_thetaRd,
                  a_psid_phid, a_psid_deltad, a_psid_thetaRd,
                  a_thetaFd_phid, a_thetaFd_deltad, a_thetaFd_thetaRd,
                  thetadd0, psidd0, thetaFdd0, thetad, psid, thetaFd, rear_speed,
                  acc0_R_x, acc0_R_y, acc0_R_z,
                  vt_R_phid_x, vt_R_phid_y, vt_R_phid_z,
                  vt_R_deltad_x, vt_R_deltad_y, vt_R_deltad_z,
                  vt_R_thetaRd_x, vt_R_thetaRd_y, vt_R_thetaRd_z],
    }
}

crate::scene! {
    /// The total energy and the front contact relative to the rear one (yawed frame).
    pub mod observe_scene {
        model: whipple_nonlinear,
        outputs: [energy, front_contact_x, front_contact_y],
    }
}

/// The total energy of [`observe_scene`] with the parameters copied into its argument array
/// once (where [`WhippleNonlinear::observe`] looks each up by name): the observer of every
/// accepted step of a simulation. Same arguments, same evaluator: the same energy bit for bit.
#[derive(Clone, Debug)]
struct Energy {
    args: [f64; observe_scene::Args::LEN],
    slots: [usize; 6],
}

impl Energy {
    fn new(params: &WhippleParams) -> Energy {
        Energy {
            args: rate::filled(params, observe_scene::PARAMS),
            slots: rate::input_slots(observe_scene::PARAMS, observe_scene::INPUTS),
        }
    }

    /// The total energy at `c` (J).
    fn at(&self, c: &Configuration) -> f64 {
        let values = [c.lean, c.pitch, c.steer, c.lean_rate, c.steer_rate, c.rear_wheel_rate];
        let a = rate::fill(self.args, &self.slots, values);
        observe_scene::eval(&observe_scene::Args::from_array(a)).energy
    }
}

/// The names of the state's components ([`State::to_array`] order), for errors.
const STATE_NAMES: [&str; 10] = [
    "x",
    "y",
    "yaw",
    "lean",
    "steer",
    "rear wheel",
    "front wheel",
    "lean rate",
    "steer rate",
    "rear wheel rate",
];

/// Why an evaluation or a simulation of the nonlinear bicycle failed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NonlinearError {
    /// An input that cannot be used.
    Parameter(ParameterError),
    /// Newton's method found no pitch that puts the front wheel on the ground.
    NoContact {
        /// The lean (rad).
        lean: f64,
        /// The steer (rad).
        steer: f64,
    },
    /// The mass matrix of the independent speeds is singular at this configuration.
    SingularMassMatrix {
        /// The lean (rad).
        lean: f64,
        /// The steer (rad).
        steer: f64,
    },
    /// The adaptive integrator gave up at time `t`.
    Integration {
        /// The time reached (s).
        t: f64,
        /// Why, in a few lower-case words.
        reason: &'static str,
    },
    /// An input ([`inputs`]) that cannot be used, or a speed outside its gain table.
    Input(InputError),
    /// A start at or beyond the fall angle: the bicycle would already lie on the ground.
    Fallen {
        /// The lean of the start (rad).
        lean: f64,
        /// The fall angle ([`WhippleNonlinear::fall_angle`], rad).
        fall_angle: f64,
    },
}

impl fmt::Display for NonlinearError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NonlinearError::Parameter(e) => write!(f, "{e}"),
            NonlinearError::NoContact { lean, steer } => write!(
                f,
                "no pitch puts the front wheel on the ground at lean {lean} rad, steer {steer} rad"
            ),
            NonlinearError::SingularMassMatrix { lean, steer } => {
                write!(f, "singular mass matrix at lean {lean} rad, steer {steer} rad")
            }
            NonlinearError::Integration { t, reason } => {
                write!(f, "the integration failed at t = {t} s: {reason}")
            }
            NonlinearError::Input(e) => write!(f, "{e}"),
            NonlinearError::Fallen { lean, fall_angle } => write!(
                f,
                "invalid lean {lean:?} rad: at or beyond the fall angle ±{fall_angle} rad, where \
                 the bicycle is on the ground"
            ),
        }
    }
}

impl std::error::Error for NonlinearError {}

impl From<ParameterError> for NonlinearError {
    fn from(e: ParameterError) -> NonlinearError {
        NonlinearError::Parameter(e)
    }
}

impl From<IntegrateError<NonlinearError>> for NonlinearError {
    fn from(e: IntegrateError<NonlinearError>) -> NonlinearError {
        match e {
            IntegrateError::Model(e) => e,
            IntegrateError::StepTooSmall { t } => {
                NonlinearError::Integration { t, reason: "step size below double precision" }
            }
            IntegrateError::TooManySteps { t } => {
                NonlinearError::Integration { t, reason: "more than a million steps" }
            }
            IntegrateError::NotFinite { t } => {
                NonlinearError::Integration { t, reason: "the right-hand side is not finite" }
            }
            IntegrateError::Stiff { t } => {
                NonlinearError::Integration { t, reason: "the problem became stiff" }
            }
            IntegrateError::TooManyEvents { count } => {
                NonlinearError::Parameter(ParameterError::InvalidParameter {
                    name: "stop conditions",
                    value: count as f64,
                    reason:
                        "at most 8 (with the fall, the steer lock and the singular configuration)",
                })
            }
        }
    }
}

fn invalid((name, value, reason): (&'static str, f64, &'static str)) -> NonlinearError {
    NonlinearError::Parameter(ParameterError::InvalidParameter { name, value, reason })
}

fn finite(name: &'static str, value: f64) -> Result<f64, NonlinearError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(NonlinearError::Parameter(ParameterError::InvalidParameter {
            name,
            value,
            reason: "must be finite",
        }))
    }
}

/// The most stop conditions of a simulation: the integrator's events less the fall's, the
/// steer lock's and the singular configuration's.
pub const MAX_STOPS: usize = integrate::MAX_EVENTS - 3;

/// The smallest ratio of a pivot of the constraint solve to its upright value at which a
/// simulation goes on (see [the module docs](self#the-singular-configurations)): a run ends,
/// status *singular*, when one falls to 1 %, where the dependent rates per unit speed are 100
/// times their upright size and $\det M_3$ about $10^4$ times; the equations are singular where
/// it vanishes.
pub const SINGULAR_PIVOT: f64 = 0.01;

/// What the pivots are the coefficients of, in [`WhippleNonlinear::pivot_ratios`]'s order,
/// and where each vanishes.
pub const PIVOTS: [(&str, &str); 3] = [
    ("pitch rate", "the pitch folds, the front wheel just touching the ground"),
    ("yaw rate", "the front wheel stands broadside to the line of contacts"),
    ("front wheel rate", "the front wheel lies flat"),
];

/// The smallest of three pivot ratios (NaN when one is NaN): the bicycle's and the leaning
/// rider's margin to their singular configuration, compared with [`SINGULAR_PIVOT`].
pub fn pivot_margin(ratios: [f64; 3]) -> f64 {
    if ratios.iter().any(|v| v.is_nan()) {
        return f64::NAN;
    }
    ratios[0].min(ratios[1]).min(ratios[2])
}

/// The index in [`PIVOTS`] of the smallest of `ratios`.
pub fn smallest_pivot(ratios: [f64; 3]) -> usize {
    (0..3).min_by(|&a, &b| ratios[a].total_cmp(&ratios[b])).unwrap_or(1)
}

/// The status line of a run that ended near its singular configuration at time `t` (s), the
/// pivot [`PIVOTS`]`[pivot]` having fallen to [`SINGULAR_PIVOT`], at the configuration
/// `at` (words, e.g. `lean -1.18 rad, steer -1.34 rad`): `singular at t = T s: ` what the
/// bicycle does where that pivot vanishes, the configuration and which pivot. The bicycle's
/// ([`WhippleNonlinear::singular_line`]) and the leaning rider's
/// ([`LeanRun::status_line`](crate::whipple::lean_rider::LeanRun::status_line)).
pub fn singular_line_at(t: f64, pivot: usize, at: &str) -> String {
    let (name, where_) = PIVOTS[pivot.min(2)];
    format!(
        "singular at t = {t} s: {where_} ({at}), the {name}'s pivot at {SINGULAR_PIVOT} of its \
         upright value; the equations are singular where it vanishes"
    )
}

/// The fall angle of [`WhippleNonlinear::new`] (rad): a stated lean, 1.2 rad (69°). The
/// Whipple model gives its frames and rider no extent (mass centres and inertias only), so no
/// geometry tells where the frame, a pedal or the handlebar touches the ground; its only
/// solids, the knife-edge wheels, lie flat at π/2, beyond where the front contact can be
/// solved once the fork has turned in a fall (the benchmark loses it near 1.39 rad).
pub const DEFAULT_FALL_ANGLE: f64 = 1.2;

/// The steer lock of [`WhippleNonlinear::new`] (rad): a stated steer, 1.4 rad (80°), where the
/// handlebar meets the frame. The model has no lock of its own, but its equations are singular
/// at $\delta = \pm\pi/2$ (the fork across the frame: the yaw rate grows as $\tan\delta$
/// times the rear speed), which a falling bicycle at low speed turns its fork into before its
/// lean reaches the fall angle; a run ends at the lock, located like the fall.
pub const DEFAULT_STEER_LOCK: f64 = 1.4;

/// The checks every simulation makes before it starts: a usable integration, a finite start
/// state and stop values, and at most [`MAX_STOPS`] stop conditions.
fn check_run(start: &State, how: &Integration, stops: &[Stop]) -> Result<(), NonlinearError> {
    if let Some(bad) = how.unusable() {
        return Err(invalid(bad));
    }
    for (k, v) in start.to_array().iter().enumerate() {
        finite(STATE_NAMES[k], *v)?;
    }
    for stop in stops {
        finite("stop value", stop.value)?;
    }
    if stops.len() > MAX_STOPS {
        return Err(invalid(("stop conditions", stops.len() as f64, "at most 8")));
    }
    Ok(())
}

/// The coordinates that enter the equations and the three independent speeds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Configuration {
    /// Lean φ (rad).
    pub lean: f64,
    /// Rear frame pitch θ (rad), solved from the contact constraint.
    pub pitch: f64,
    /// Steer δ (rad).
    pub steer: f64,
    /// Lean rate (rad/s).
    pub lean_rate: f64,
    /// Steer rate (rad/s).
    pub steer_rate: f64,
    /// Rear wheel rate relative to the rear frame (rad/s).
    pub rear_wheel_rate: f64,
}

impl Configuration {
    /// The value of the input `name` of `generated/whipple_nonlinear.ir` (`phi`, `theta`,
    /// `delta`, `phid`, `deltad`, `thetaRd`); `None` for any other name.
    pub fn input(&self, name: &str) -> Option<f64> {
        match name {
            "phi" => Some(self.lean),
            "theta" => Some(self.pitch),
            "delta" => Some(self.steer),
            "phid" => Some(self.lean_rate),
            "deltad" => Some(self.steer_rate),
            "thetaRd" => Some(self.rear_wheel_rate),
            _ => None,
        }
    }
}

/// The equations of motion evaluated at one configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Accelerations {
    /// $\ddot\varphi$, $\ddot\delta$, $\ddot\theta_R$ (rad/s²).
    pub independent: [f64; 3],
    /// Pitch, yaw and front wheel rates $\dot\theta$, $\dot\psi$, $\dot\theta_F$ (rad/s).
    pub dependent_rates: [f64; 3],
    /// Pitch, yaw and front wheel accelerations (rad/s²).
    pub dependent: [f64; 3],
    /// Speed of the rear contact along the heading (m/s).
    pub rear_speed: f64,
    /// Acceleration of the rear wheel centre in the yawed frame (m/s²).
    pub rear_centre: [f64; 3],
}

/// The terms of Kane's equations at one configuration ([`WhippleNonlinear::kane_terms`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KaneTerms {
    /// $M_3$ (rows and columns lean, steer, rear wheel).
    pub mass: [[f64; 3]; 3],
    /// $f_3$: gravity and velocity terms.
    pub forcing: [f64; 3],
    /// Pitch, yaw and front wheel rates per unit lean, steer and rear wheel rate.
    pub rates: [[f64; 3]; 3],
    /// Speed of the rear contact along the heading, $-r_R(\dot\theta + \dot\theta_R)$ (m/s).
    pub rear_speed: f64,
}

/// The nonlinear bicycle for one parameter set, the lean at which it has fallen and the steer
/// at which the handlebar meets the frame.
#[derive(Clone, Debug)]
pub struct WhippleNonlinear {
    params: WhippleParams,
    fall_angle: f64,
    steer_lock: f64,
}

/// The full simulation state: the coordinates other than the pitch and the independent speeds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct State {
    /// Rear contact $x$ (m).
    pub x: f64,
    /// Rear contact $y$ (m).
    pub y: f64,
    /// Yaw ψ (rad).
    pub yaw: f64,
    /// Lean φ (rad).
    pub lean: f64,
    /// Steer δ (rad).
    pub steer: f64,
    /// Rear wheel rotation relative to the rear frame (rad).
    pub rear_wheel: f64,
    /// Front wheel rotation relative to the front frame (rad).
    pub front_wheel: f64,
    /// Lean rate (rad/s).
    pub lean_rate: f64,
    /// Steer rate (rad/s).
    pub steer_rate: f64,
    /// Rear wheel rate relative to the rear frame (rad/s).
    pub rear_wheel_rate: f64,
}

impl State {
    fn to_array(self) -> [f64; 10] {
        [
            self.x,
            self.y,
            self.yaw,
            self.lean,
            self.steer,
            self.rear_wheel,
            self.front_wheel,
            self.lean_rate,
            self.steer_rate,
            self.rear_wheel_rate,
        ]
    }

    fn from_array(a: [f64; 10]) -> State {
        State {
            x: a[0],
            y: a[1],
            yaw: a[2],
            lean: a[3],
            steer: a[4],
            rear_wheel: a[5],
            front_wheel: a[6],
            lean_rate: a[7],
            steer_rate: a[8],
            rear_wheel_rate: a[9],
        }
    }
}

/// One sample of a simulation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Time (s).
    pub t: f64,
    /// The state.
    pub state: State,
    /// The pitch solved from the contact constraint (rad).
    pub pitch: f64,
    /// Speed of the rear contact along the heading (m/s).
    pub speed: f64,
    /// Rear contact on the ground $(x, y)$ (m).
    pub rear_contact: [f64; 2],
    /// Front contact on the ground $(x, y)$ (m).
    pub front_contact: [f64; 2],
    /// Total energy (J).
    pub energy: f64,
}

/// What [`WhippleNonlinear::simulate`] measures over all its steps (kept or not).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Diagnostics {
    /// Largest $|E(t) - E(0)|$ over all steps (J).
    pub energy_drift: f64,
    /// Largest $|h|$ of the contact constraint after Newton over all steps (m).
    pub max_contact_residual: f64,
}

/// A simulated motion: the [`Sample`]s kept, every `every` steps (`samples`, with their
/// `times`), the integration `step` (s) and the [`Diagnostics`], whose fields are read through
/// the trajectory (`trajectory.energy_drift`).
pub type Trajectory = crate::numerics::ode::Trajectory<Sample, Diagnostics>;

/// The end of a simulation without its samples ([`WhippleNonlinear::simulate_final`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Final {
    /// The final time (s): the grid's end or the event's.
    pub t: f64,
    /// The final state.
    pub state: State,
    /// The stop condition met (its index) and when, `None` when the run reached the end.
    pub event: Option<(usize, f64)>,
    /// When the lean reached the fall angle, `None` when it did not.
    pub fall: Option<f64>,
    /// When the steer reached the steer lock, `None` when it did not.
    pub steer_lock: Option<f64>,
    /// When a pivot of the constraint solve fell to [`SINGULAR_PIVOT`] of its upright value
    /// (the equations near their singularity), `None` when none did.
    pub singular: Option<f64>,
    /// When the stop flag ended the run (its last accepted step), `None` when it did not.
    pub interrupted: Option<f64>,
    /// Right-hand side evaluations and steps.
    pub stats: integrate::Stats,
    /// The energy drift and contact residual over the accepted steps.
    pub diagnostics: Diagnostics,
}

/// A quantity a [`Stop`] condition watches.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Watched {
    /// Lean φ (rad).
    Lean,
    /// Steer δ (rad).
    Steer,
    /// Yaw ψ (rad).
    Yaw,
    /// Pitch θ (rad), solved from the contact constraint.
    Pitch,
    /// Lean rate (rad/s).
    LeanRate,
    /// Steer rate (rad/s).
    SteerRate,
    /// Rear contact x (m).
    X,
    /// Rear contact y (m).
    Y,
}

impl Watched {
    /// Every quantity, in the order of [`name`](Self::name)'s list.
    pub const ALL: [Watched; 8] = [
        Watched::Lean,
        Watched::Steer,
        Watched::Yaw,
        Watched::Pitch,
        Watched::LeanRate,
        Watched::SteerRate,
        Watched::X,
        Watched::Y,
    ];

    /// The name on the command line: `lean`, `steer`, `yaw`, `pitch`, `lean_rate`,
    /// `steer_rate`, `x`, `y`.
    pub fn name(self) -> &'static str {
        match self {
            Watched::Lean => "lean",
            Watched::Steer => "steer",
            Watched::Yaw => "yaw",
            Watched::Pitch => "pitch",
            Watched::LeanRate => "lean_rate",
            Watched::SteerRate => "steer_rate",
            Watched::X => "x",
            Watched::Y => "y",
        }
    }
}

/// Ends a simulation when `quantity - value` changes sign, or, with `magnitude`, when
/// $|$`quantity`$| - $`value` does (the lean reaching ±`value`). Written `NAME=VALUE` or
/// `NAME=±VALUE` (also `NAME=+-VALUE`) by [`Stop::parse`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stop {
    /// What is watched.
    pub quantity: Watched,
    /// The threshold.
    pub value: f64,
    /// Whether the magnitude is watched (`±`).
    pub magnitude: bool,
}

impl Stop {
    /// The condition `text` (`lean=±0.5`, `lean=+-0.5`, `steer=0`); `None` when the name is
    /// not one of [`Watched::name`]'s, the value is not a finite number, or a magnitude bound
    /// is negative.
    pub fn parse(text: &str) -> Option<Stop> {
        let (name, value) = text.split_once('=')?;
        let quantity = Watched::ALL.into_iter().find(|w| w.name() == name.trim())?;
        let (magnitude, value) = integrate::Threshold::parse_bound(value)?;
        Some(Stop { quantity, value, magnitude })
    }

    /// The condition as [`parse`](Self::parse) reads it (`lean=±0.5`).
    pub fn text(&self) -> String {
        format!("{}={}{}", self.quantity.name(), if self.magnitude { "±" } else { "" }, self.value)
    }
}

/// What ends a run besides the end of its grid: a stop condition (the fall and the steer lock
/// are two) or the singular configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Watch {
    /// `quantity - value`, or `|quantity| - value`, changing sign.
    Stop(Stop),
    /// The smallest pivot ratio ([`WhippleNonlinear::pivot_ratios`]) reaching
    /// [`SINGULAR_PIVOT`].
    Singular,
}

impl Watch {
    /// The event function at the state `y` (its first [`rate::LEN`] components, those of
    /// [`rate::state_with_pitch`]), whose sign change ends the run; the pitch, where it is
    /// needed, projected onto the contact constraint as the right-hand side does.
    pub(crate) fn value(self, f: &StateRate, y: &[f64]) -> Result<f64, NonlinearError> {
        match self {
            Watch::Stop(stop) => {
                let v = match stop.quantity {
                    Watched::Lean => y[3],
                    Watched::Steer => y[4],
                    Watched::Yaw => y[2],
                    Watched::Pitch => f.project(y[3], y[rate::PITCH], y[4])?,
                    Watched::LeanRate => y[7],
                    Watched::SteerRate => y[8],
                    Watched::X => y[0],
                    Watched::Y => y[1],
                };
                Ok(if stop.magnitude { v.abs() - stop.value } else { v - stop.value })
            }
            Watch::Singular => {
                let pitch = f.project(y[3], y[rate::PITCH], y[4])?;
                Ok(f.pivot_margin(y[3], pitch, y[4]) - SINGULAR_PIVOT)
            }
        }
    }
}

impl WhippleNonlinear {
    /// The nonlinear bicycle with the parameters `params`, the fall angle
    /// [`DEFAULT_FALL_ANGLE`] and the steer lock [`DEFAULT_STEER_LOCK`].
    pub fn new(params: WhippleParams) -> WhippleNonlinear {
        WhippleNonlinear { params, fall_angle: DEFAULT_FALL_ANGLE, steer_lock: DEFAULT_STEER_LOCK }
    }

    /// The same bicycle with the fall angle `angle` (rad): a simulation ends, fallen, when the
    /// magnitude of the lean reaches it (located on the integrator's interpolant like a stop
    /// condition), and a start at or beyond it is refused.
    ///
    /// # Errors
    /// [`NonlinearError::Parameter`] naming `fall angle` unless $0 < $ `angle` $\le \pi/2$
    /// (at π/2 the wheels lie flat).
    pub fn with_fall_angle(self, angle: f64) -> Result<WhippleNonlinear, NonlinearError> {
        finite("fall angle", angle)?;
        if !(angle > 0.0 && angle <= std::f64::consts::FRAC_PI_2) {
            return Err(invalid(("fall angle", angle, "must lie in (0, pi/2] rad")));
        }
        Ok(WhippleNonlinear { fall_angle: angle, ..self })
    }

    /// The fall angle (rad): [`DEFAULT_FALL_ANGLE`] unless
    /// [`with_fall_angle`](Self::with_fall_angle) set another.
    pub fn fall_angle(&self) -> f64 {
        self.fall_angle
    }

    /// The same bicycle with the steer lock `angle` (rad): a simulation ends when the
    /// magnitude of the steer reaches it (the handlebar against the frame), located like the
    /// fall, and a start at or beyond it is refused.
    ///
    /// # Errors
    /// [`NonlinearError::Parameter`] naming `steer lock` unless $0 < $ `angle` $< \pi/2$ (at
    /// π/2 the equations are singular).
    pub fn with_steer_lock(self, angle: f64) -> Result<WhippleNonlinear, NonlinearError> {
        finite("steer lock", angle)?;
        if !(angle > 0.0 && angle < std::f64::consts::FRAC_PI_2) {
            return Err(invalid(("steer lock", angle, "must lie in (0, pi/2) rad")));
        }
        Ok(WhippleNonlinear { steer_lock: angle, ..self })
    }

    /// The steer lock (rad): [`DEFAULT_STEER_LOCK`] unless
    /// [`with_steer_lock`](Self::with_steer_lock) set another.
    pub fn steer_lock(&self) -> f64 {
        self.steer_lock
    }

    /// The model's own limits, the events after the stop conditions, in this order: the fall
    /// (the lean's magnitude reaching the fall angle), the steer lock and the singular
    /// configuration ([`SINGULAR_PIVOT`]).
    pub(crate) fn limits(&self) -> [Watch; 3] {
        [
            Watch::Stop(Stop { quantity: Watched::Lean, value: self.fall_angle, magnitude: true }),
            Watch::Stop(Stop { quantity: Watched::Steer, value: self.steer_lock, magnitude: true }),
            Watch::Singular,
        ]
    }

    /// The events of a run: `stops`, then the [`limits`](Self::limits); `None` after them.
    pub(crate) fn watches(&self, stops: &[Stop]) -> [Option<Watch>; integrate::MAX_EVENTS] {
        let limits = self.limits();
        std::array::from_fn(|j| match j.checked_sub(stops.len()) {
            Some(k) => limits.get(k).copied(),
            None => stops.get(j).copied().map(Watch::Stop),
        })
    }

    /// The pivots of the constraint solve at (`lean`, `pitch`, `steer`) relative to their
    /// upright values, in the order of [`PIVOTS`] (pitch rate, yaw rate, front wheel rate): 1
    /// upright, 0 where the equations are singular (see [the module
    /// docs](self#the-singular-configurations)). The pitch should satisfy the contact
    /// constraint ([`pitch`](Self::pitch)).
    pub fn pivot_ratios(&self, lean: f64, pitch: f64, steer: f64) -> [f64; 3] {
        StateRate::new(&self.params).pivot_ratios(lean, pitch, steer)
    }

    /// The status line of a run that ended near the singular configuration at time `t` (s)
    /// and (`lean`, `pitch`, `steer`) (rad): `singular at t = T s: ` what the bicycle does
    /// where the smallest pivot vanishes ([`PIVOTS`]), the lean and steer, and which pivot.
    pub fn singular_line(&self, t: f64, lean: f64, pitch: f64, steer: f64) -> String {
        let k = smallest_pivot(self.pivot_ratios(lean, pitch, steer));
        singular_line_at(t, k, &format!("lean {lean} rad, steer {steer} rad"))
    }

    /// Checks that `start` is a physical start and returns its pitch: a lean inside the fall
    /// angle, a steer inside the steer lock and a pitch that puts the front wheel on the
    /// ground (Newton from 0). Every method of [`simulate_with`](Self::simulate_with) makes
    /// this check first.
    ///
    /// # Errors
    /// [`NonlinearError::Fallen`] for a lean at or beyond the fall angle;
    /// [`NonlinearError::Parameter`] naming the steer at or beyond the steer lock, or the lean
    /// when no pitch puts the front wheel on the ground (or a non-finite lean or steer).
    pub fn check_start(&self, start: &State) -> Result<f64, NonlinearError> {
        finite("lean", start.lean)?;
        finite("steer", start.steer)?;
        if start.lean.abs() >= self.fall_angle {
            return Err(NonlinearError::Fallen { lean: start.lean, fall_angle: self.fall_angle });
        }
        if start.steer.abs() >= self.steer_lock {
            return Err(invalid(("steer", start.steer, "at or beyond the steer lock")));
        }
        let pitch = self.pitch(start.lean, start.steer, 0.0).map_err(|_| {
            invalid((
                "lean",
                start.lean,
                "no pitch puts the front wheel on the ground at this lean and steer",
            ))
        })?;
        let margin = StateRate::new(&self.params).pivot_margin(start.lean, pitch, start.steer);
        if margin.is_nan() || margin <= SINGULAR_PIVOT {
            return Err(invalid((
                "steer",
                start.steer,
                "at or beyond the singular configuration at this lean (a pivot of the \
                 constraint solve at or below 1% of its upright value)",
            )));
        }
        Ok(pitch)
    }

    /// The nonlinear bicycle of `design`, validated as [`WhippleParams::from_design`].
    ///
    /// # Errors
    /// [`WhippleError`] naming the benchmark key of the field at fault.
    pub fn from_design(design: BicycleDesign) -> Result<WhippleNonlinear, WhippleError> {
        WhippleParams::from_design(design).map(WhippleNonlinear::new)
    }

    /// The parameters.
    pub fn params(&self) -> &WhippleParams {
        &self.params
    }

    fn param(&self, name: &str) -> f64 {
        self.params.get(name).unwrap_or(f64::NAN)
    }

    /// Argument array of a scene: its parameters by name, then the inputs.
    fn args<const N: usize>(
        &self,
        params: &[&str],
        inputs: &[&str],
        c: &Configuration,
    ) -> [f64; N] {
        std::array::from_fn(|i| {
            if i < params.len() {
                self.param(params[i])
            } else {
                c.input(inputs[i - params.len()]).unwrap_or(f64::NAN)
            }
        })
    }

    /// The contact constraint $h$ and $\partial h/\partial\theta$ (m, m/rad).
    pub fn contact(&self, lean: f64, pitch: f64, steer: f64) -> (f64, f64) {
        let c = Configuration {
            lean,
            pitch,
            steer,
            lean_rate: 0.0,
            steer_rate: 0.0,
            rear_wheel_rate: 0.0,
        };
        let a = self.args(contact_scene::PARAMS, contact_scene::INPUTS, &c);
        let o = contact_scene::eval(&contact_scene::Args::from_array(a));
        (o.contact_height, o.contact_height_dtheta)
    }

    /// The pitch that puts the front wheel on the ground, by Newton's method from `guess`
    /// (at most 50 iterations, stopping when the step is below 1e-14 rad).
    ///
    /// # Errors
    /// [`NonlinearError::Parameter`] for non-finite angles,
    /// [`NonlinearError::NoContact`] when Newton's method does not converge.
    pub fn pitch(&self, lean: f64, steer: f64, guess: f64) -> Result<f64, NonlinearError> {
        finite("lean", lean)?;
        finite("steer", steer)?;
        finite("pitch guess", guess)?;
        let mut th = guess;
        for _ in 0..50 {
            let (h, dh) = self.contact(lean, th, steer);
            let step = h / dh;
            if !step.is_finite() {
                break;
            }
            th -= step;
            if step.abs() <= 1e-14 * (1.0 + th.abs()) {
                return Ok(th);
            }
        }
        Err(NonlinearError::NoContact { lean, steer })
    }

    /// The equations of motion at `c` (whose pitch must satisfy the contact constraint).
    ///
    /// # Errors
    /// [`NonlinearError::SingularMassMatrix`] when $M_3$ cannot be factored.
    pub fn accelerations(&self, c: &Configuration) -> Result<Accelerations, NonlinearError> {
        let a = self.args(dynamics_scene::PARAMS, dynamics_scene::INPUTS, c);
        let o = dynamics_scene::eval(&dynamics_scene::Args::from_array(a));
        let m = Matrix3::new(
            o.m3_11, o.m3_12, o.m3_13, o.m3_12, o.m3_22, o.m3_23, o.m3_13, o.m3_23, o.m3_33,
        );
        let f = Vector3::new(o.f3_1, o.f3_2, o.f3_3);
        let ud = m
            .lu()
            .solve(&f)
            .filter(|x| x.iter().all(|v| v.is_finite()))
            .ok_or(NonlinearError::SingularMassMatrix { lean: c.lean, steer: c.steer })?;
        let ud = [ud[0], ud[1], ud[2]];
        let lin = |a: [f64; 3]| a[0] * ud[0] + a[1] * ud[1] + a[2] * ud[2];
        let dependent = [
            o.thetadd0 + lin([o.a_thetad_phid, o.a_thetad_deltad, o.a_thetad_thetaRd]),
            o.psidd0 + lin([o.a_psid_phid, o.a_psid_deltad, o.a_psid_thetaRd]),
            o.thetaFdd0 + lin([o.a_thetaFd_phid, o.a_thetaFd_deltad, o.a_thetaFd_thetaRd]),
        ];
        let rear_centre = [
            o.acc0_R_x + lin([o.vt_R_phid_x, o.vt_R_deltad_x, o.vt_R_thetaRd_x]),
            o.acc0_R_y + lin([o.vt_R_phid_y, o.vt_R_deltad_y, o.vt_R_thetaRd_y]),
            o.acc0_R_z + lin([o.vt_R_phid_z, o.vt_R_deltad_z, o.vt_R_thetaRd_z]),
        ];
        Ok(Accelerations {
            independent: ud,
            dependent_rates: [o.thetad, o.psid, o.thetaFd],
            dependent,
            rear_speed: o.rear_speed,
            rear_centre,
        })
    }

    /// The generated terms of Kane's equations at `c` before any solve: the symmetric mass
    /// matrix $M_3$ and forcing $f_3$ of $M_3\dot u = f_3$ (rows lean, steer, rear wheel), the
    /// dependent rates per unit independent speed (rows pitch, yaw, front wheel rate; columns
    /// $\dot\varphi$, $\dot\delta$, $\dot\theta_R$) and the rear contact's speed. The speeds
    /// are relative rates (lean, steer of the fork on the frame, rear wheel on the frame), so a
    /// steer torque between frame and fork enters the steer row only and a pedal torque between
    /// frame and rear wheel the rear-wheel row only.
    pub fn kane_terms(&self, c: &Configuration) -> KaneTerms {
        let a = self.args(dynamics_scene::PARAMS, dynamics_scene::INPUTS, c);
        let o = dynamics_scene::eval(&dynamics_scene::Args::from_array(a));
        KaneTerms {
            mass: [
                [o.m3_11, o.m3_12, o.m3_13],
                [o.m3_12, o.m3_22, o.m3_23],
                [o.m3_13, o.m3_23, o.m3_33],
            ],
            forcing: [o.f3_1, o.f3_2, o.f3_3],
            rates: [
                [o.a_thetad_phid, o.a_thetad_deltad, o.a_thetad_thetaRd],
                [o.a_psid_phid, o.a_psid_deltad, o.a_psid_thetaRd],
                [o.a_thetaFd_phid, o.a_thetaFd_deltad, o.a_thetaFd_thetaRd],
            ],
            rear_speed: o.rear_speed,
        }
    }

    /// Total energy (J) and the front contact relative to the rear one in the yawed frame (m).
    pub fn observe(&self, c: &Configuration) -> (f64, [f64; 2]) {
        let a = self.args(observe_scene::PARAMS, observe_scene::INPUTS, c);
        let o = observe_scene::eval(&observe_scene::Args::from_array(a));
        (o.energy, [o.front_contact_x, o.front_contact_y])
    }

    /// The nine accelerations in the coordinates of Basu-Mandal, Chatterjee and Papadopoulos
    /// (2007), `q = [x, y, z, θ, ψ, φ, ψf, βr, βf]` and `qd` their rates, as
    /// `[x'', y'', z'', θ'', ψ'', φ'', ψf'', βr'', βf'']`. The independent rates ψ', ψf', βr'
    /// of `qd` are used; the pitch is solved from the constraint starting at `q`'s φ.
    ///
    /// # Errors
    /// A non-finite entry is [`NonlinearError::Parameter`] naming it; no contact or a
    /// singular mass matrix as in [`pitch`](Self::pitch) and
    /// [`accelerations`](Self::accelerations).
    pub fn basu_mandal_accelerations(
        &self,
        q: [f64; 9],
        qd: [f64; 9],
    ) -> Result<[f64; 9], NonlinearError> {
        const Q: [&str; 9] = [
            "q[0] (x)",
            "q[1] (y)",
            "q[2] (z)",
            "q[3] (theta)",
            "q[4] (psi)",
            "q[5] (phi)",
            "q[6] (psif)",
            "q[7] (betar)",
            "q[8] (betaf)",
        ];
        const QD: [&str; 9] = [
            "qd[0] (xd)",
            "qd[1] (yd)",
            "qd[2] (zd)",
            "qd[3] (thetad)",
            "qd[4] (psid)",
            "qd[5] (phid)",
            "qd[6] (psifd)",
            "qd[7] (betard)",
            "qd[8] (betafd)",
        ];
        for k in 0..9 {
            finite(Q[k], q[k])?;
            finite(QD[k], qd[k])?;
        }
        let pi = std::f64::consts::PI;
        let lean = pi / 2.0 - q[4];
        let steer = -q[6];
        let pitch = self.pitch(lean, steer, pi - q[5])?;
        let c = Configuration {
            lean,
            pitch,
            steer,
            lean_rate: -qd[4],
            steer_rate: -qd[6],
            rear_wheel_rate: -qd[7],
        };
        let acc = self.accelerations(&c)?;
        // Rear wheel centre: yawed frame to ground frame (yaw = -theta_b), then (-X, Y, -Z).
        let yaw = -q[3];
        let (s, co) = yaw.sin_cos();
        let [ax, ay, az] = acc.rear_centre;
        // The yawed frame turns at the yaw rate: its components' acceleration is already the
        // absolute acceleration (the generated terms include the frame's rotation).
        let (gx, gy) = (co * ax - s * ay, s * ax + co * ay);
        Ok([
            -gx,
            gy,
            -az,
            -acc.dependent[1],
            -acc.independent[0],
            -acc.dependent[0],
            -acc.independent[1],
            -acc.independent[2],
            -acc.dependent[2],
        ])
    }

    /// Solves the pitch for `s` (Newton from `guess`) and returns the configuration.
    fn configuration(&self, s: &State, guess: f64) -> Result<Configuration, NonlinearError> {
        let pitch = self.pitch(s.lean, s.steer, guess)?;
        Ok(Configuration {
            lean: s.lean,
            pitch,
            steer: s.steer,
            lean_rate: s.lean_rate,
            steer_rate: s.steer_rate,
            rear_wheel_rate: s.rear_wheel_rate,
        })
    }

    fn sample(&self, t: f64, s: &State, guess: f64) -> Result<Sample, NonlinearError> {
        let c = self.configuration(s, guess)?;
        let a = self.accelerations(&c)?;
        let (energy, fc) = self.observe(&c);
        let (sy, cy) = s.yaw.sin_cos();
        Ok(Sample {
            t,
            state: *s,
            pitch: c.pitch,
            speed: a.rear_speed,
            rear_contact: [s.x, s.y],
            front_contact: [s.x + cy * fc[0] - sy * fc[1], s.y + sy * fc[0] + cy * fc[1]],
            energy,
        })
    }

    /// The upright state moving straight ahead at `speed` (m/s) with the lean `lean0` (rad)
    /// and every other angle and rate zero.
    ///
    /// # Errors
    /// [`NonlinearError::Parameter`] for a non-finite speed or lean, or a wheel of zero
    /// radius (the two-mass-skate, whose limit only the linearised model takes: here the
    /// wheels' rotation rates are coordinates).
    pub fn initial_state(&self, speed: f64, lean0: f64) -> Result<State, NonlinearError> {
        finite("speed", speed)?;
        finite("lean0", lean0)?;
        for name in ["rR", "rF"] {
            if self.param(name) == 0.0 {
                return Err(NonlinearError::Parameter(ParameterError::InvalidParameter {
                    name: if name == "rR" { "rR" } else { "rF" },
                    value: 0.0,
                    reason: "must be positive for the nonlinear model, whose speeds are the \
                             wheels' rotation rates (the linearised model takes the \
                             two-mass-skate's limit of zero radius)",
                }));
            }
        }
        Ok(State {
            x: 0.0,
            y: 0.0,
            yaw: 0.0,
            lean: lean0,
            steer: 0.0,
            rear_wheel: 0.0,
            front_wheel: 0.0,
            lean_rate: 0.0,
            steer_rate: 0.0,
            rear_wheel_rate: -speed / self.param("rR"),
        })
    }

    /// Integrates from `start` for `duration` seconds with the classical Runge–Kutta method of
    /// step `step`, solving the pitch by Newton at every stage; keeps every `every`-th step
    /// (and the first and last). The same as [`simulate_with`](Self::simulate_with) with RK4
    /// and no stop condition.
    ///
    /// # Errors
    /// [`NonlinearError::Parameter`] for a non-positive or non-finite duration or step,
    /// a step longer than the duration, more than ten million steps, or `every == 0`; no
    /// contact (the bicycle fell flat) or a singular mass matrix during the run.
    pub fn simulate(
        &self,
        start: State,
        duration: f64,
        step: f64,
        every: usize,
    ) -> Result<Trajectory, NonlinearError> {
        let grid = Grid::new(duration, step, every).map_err(invalid)?;
        self.simulate_with(start, &grid, &Integration::RK4, &[])
    }

    /// Integrates from `start` over `grid` by `how` and keeps the samples of the grid (for
    /// RK4 the states of its steps, for the adaptive methods their dense output at the same
    /// times), until the end of the grid or the first of `stops` met (its time located on the
    /// interpolant; the last sample is then the state at that time). The diagnostics are taken
    /// at every accepted step (the integrator's own states, not the interpolated samples); [`Trajectory::stats`](crate::numerics::ode::Trajectory::stats)
    /// counts the right-hand side evaluations and the steps. The pitch is solved by Newton at
    /// every evaluation (from the last pitch found), never integrated.
    ///
    /// # Errors
    /// [`NonlinearError::Parameter`] for an unusable tolerance, a non-finite start, more than
    /// eight stop conditions or a NaN threshold; no contact (the bicycle fell flat) or a
    /// singular mass matrix during the run; [`NonlinearError::Integration`] when the adaptive
    /// method gives up.
    pub fn simulate_with(
        &self,
        start: State,
        grid: &Grid,
        how: &Integration,
        stops: &[Stop],
    ) -> Result<Trajectory, NonlinearError> {
        self.simulate_until(start, grid, how, stops, &AtomicBool::new(false))
    }

    /// [`simulate_with`](Self::simulate_with) that also ends when `stop` is set (Ctrl-C): the
    /// samples up to the last accepted step, whose time is
    /// [`Trajectory::interrupted`](crate::numerics::ode::Trajectory::interrupted).
    ///
    /// # Errors
    /// As [`simulate_with`](Self::simulate_with).
    pub fn simulate_until(
        &self,
        start: State,
        grid: &Grid,
        how: &Integration,
        stops: &[Stop],
        stop: &AtomicBool,
    ) -> Result<Trajectory, NonlinearError> {
        let mut trajectory =
            Trajectory::with_capacity(grid.h, grid.samples(), Diagnostics::default());
        let mut keep = |t: f64, s: &State, guess: f64| -> Result<(), NonlinearError> {
            trajectory.push(t, self.sample(t, s, guess)?);
            Ok(())
        };
        let end = self.run(start, grid, how, stops, &mut keep, stop)?;
        trajectory.diagnostics = end.diagnostics;
        trajectory.stats = end.stats;
        trajectory.event = end.event;
        trajectory.fall = end.fall;
        trajectory.steer_lock = end.steer_lock;
        trajectory.singular = end.singular;
        trajectory.interrupted = end.interrupted;
        Ok(trajectory)
    }

    /// [`simulate_with`](Self::simulate_with) without the samples: the final time and state,
    /// the event, the counts and the diagnostics, allocating nothing (for batches).
    ///
    /// # Errors
    /// As [`simulate_with`](Self::simulate_with).
    pub fn simulate_final(
        &self,
        start: State,
        grid: &Grid,
        how: &Integration,
        stops: &[Stop],
    ) -> Result<Final, NonlinearError> {
        self.simulate_final_until(start, grid, how, stops, &AtomicBool::new(false))
    }

    /// [`simulate_final`](Self::simulate_final) that also ends when `stop` is set (Ctrl-C),
    /// read after every accepted step: the state of the last accepted step, its time in
    /// [`Final::interrupted`].
    ///
    /// # Errors
    /// As [`simulate_with`](Self::simulate_with).
    pub fn simulate_final_until(
        &self,
        start: State,
        grid: &Grid,
        how: &Integration,
        stops: &[Stop],
        stop: &AtomicBool,
    ) -> Result<Final, NonlinearError> {
        self.run(start, grid, how, stops, &mut |_, _, _| Ok(()), stop)
    }

    /// [`simulate_final`](Self::simulate_final) from every start of `starts`, in parallel
    /// (rayon), in their order; each result equals the single run's bit for bit (the runs
    /// share nothing). `done` counts the finished runs (for a progress bar).
    pub fn simulate_many(
        &self,
        starts: &[State],
        grid: &Grid,
        how: &Integration,
        stops: &[Stop],
        done: &std::sync::atomic::AtomicUsize,
    ) -> Vec<Result<Final, NonlinearError>> {
        // The flag is never set: every run is `Some`.
        self.simulate_many_until(starts, grid, how, stops, done, &AtomicBool::new(false))
            .into_iter()
            .flatten()
            .collect()
    }

    /// [`simulate_many`](Self::simulate_many) that also ends when `stop` is set (Ctrl-C): the
    /// runs under way end after their current step
    /// ([`simulate_final_until`](Self::simulate_final_until), [`Final::interrupted`] set), and
    /// the runs not yet started are `None`. The runs that ended before the flag are whole,
    /// equal to the single run's bit for bit; `done` counts them and the interrupted ones.
    pub fn simulate_many_until(
        &self,
        starts: &[State],
        grid: &Grid,
        how: &Integration,
        stops: &[Stop],
        done: &std::sync::atomic::AtomicUsize,
        stop: &AtomicBool,
    ) -> Vec<Option<Result<Final, NonlinearError>>> {
        use rayon::prelude::*;
        use std::sync::atomic::Ordering;
        starts
            .par_iter()
            .map(|s| {
                if stop.load(Ordering::Relaxed) {
                    return None;
                }
                let end = self.simulate_final_until(*s, grid, how, stops, stop);
                done.fetch_add(1, Ordering::Relaxed);
                Some(end)
            })
            .collect()
    }

    /// The integration behind [`simulate_with`](Self::simulate_with): `keep(t, state, guess)`
    /// receives every sample (and the event's state) with the Newton guess for its pitch. The
    /// fall and the steer lock are two more events after the stop conditions ([`Self::limits`]).
    fn run(
        &self,
        start: State,
        grid: &Grid,
        how: &Integration,
        stops: &[Stop],
        keep: &mut dyn FnMut(f64, &State, f64) -> Result<(), NonlinearError>,
        stop_flag: &AtomicBool,
    ) -> Result<Final, NonlinearError> {
        check_run(&start, how, stops)?;
        let pitch0 = self.check_start(&start)?;
        let conditions = stops.len() + self.limits().len();
        let energy = Energy::new(&self.params);
        let e0 = energy.at(&self.configuration(&start, pitch0)?);
        let f = StateRate::new(&self.params);
        let (mut drift, mut residual) = (0.0f64, 0.0f64);
        let mut rhs = |_t: f64, y: &[f64; rate::LEN]| f.eval(y);
        let mut watchers = self.watches(stops).map(|watch| {
            let f = &f;
            move |y: &[f64; rate::LEN]| -> Result<f64, NonlinearError> {
                watch.map_or(Ok(f64::NAN), |w| w.value(f, y))
            }
        });
        let mut events: [&mut integrate::EventFn<'_, { rate::LEN }, NonlinearError>;
            integrate::MAX_EVENTS] = watchers
            .each_mut()
            .map(|w| w as &mut integrate::EventFn<'_, { rate::LEN }, NonlinearError>);
        let mut observe =
            |kind: Point, t: f64, y: &[f64; rate::LEN]| -> Result<(), NonlinearError> {
                let s = rate::state_of(y);
                match kind {
                    Point::Step => {
                        // The pitch the right-hand side uses at this state: the integrated one
                        // projected by one Newton step.
                        let pitch = f.project(s.lean, y[rate::PITCH], s.steer)?;
                        let c = Configuration {
                            lean: s.lean,
                            pitch,
                            steer: s.steer,
                            lean_rate: s.lean_rate,
                            steer_rate: s.steer_rate,
                            rear_wheel_rate: s.rear_wheel_rate,
                        };
                        residual = residual.max(f.contact(c.lean, c.pitch, c.steer).0.abs());
                        drift = drift.max((energy.at(&c) - e0).abs());
                    }
                    Point::Sample(_) | Point::Event => keep(t, &s, y[rate::PITCH])?,
                }
                Ok(())
            };
        // The implicit method's Newton iterations use the generated state Jacobian.
        let mut jacobian = |_t: f64, y: &[f64; rate::LEN]| f.jacobian(y);
        let outcome = integrate::integrate_with_jacobian(
            how,
            grid,
            rate::state_with_pitch(&start, pitch0),
            &mut rhs,
            Some(&mut jacobian),
            &mut events[..conditions],
            &mut observe,
            stop_flag,
        )?;
        let limit = |k: usize| outcome.event.filter(|c| c.index == stops.len() + k).map(|c| c.t);
        Ok(Final {
            t: outcome.end.0,
            state: rate::state_of(&outcome.end.1),
            event: outcome.event.filter(|c| c.index < stops.len()).map(|c| (c.index, c.t)),
            fall: limit(0),
            steer_lock: limit(1),
            singular: limit(2),
            interrupted: outcome.interrupted.then_some(outcome.end.0),
            stats: outcome.stats,
            diagnostics: Diagnostics { energy_drift: drift, max_contact_residual: residual },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_steps_energy_is_observes_bit_for_bit() {
        // Energy copies the parameters once; WhippleNonlinear::observe looks them up by name.
        let wn = WhippleNonlinear::new(WhippleParams::benchmark());
        let energy = Energy::new(&WhippleParams::benchmark());
        for (lean, steer, rates) in [(0.1, 0.05, [0.2, -0.1, -16.7]), (-0.4, 0.3, [1.0, 2.0, -3.0])]
        {
            let pitch = wn.pitch(lean, steer, 0.0).unwrap();
            let c = Configuration {
                lean,
                pitch,
                steer,
                lean_rate: rates[0],
                steer_rate: rates[1],
                rear_wheel_rate: rates[2],
            };
            assert_eq!(energy.at(&c).to_bits(), wn.observe(&c).0.to_bits());
        }
    }
}
