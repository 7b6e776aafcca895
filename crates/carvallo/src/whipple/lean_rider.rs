//! Moore's (2012) leaning rider: the Carvallo–Whipple bicycle with the rider's upper body on a
//! revolute lean joint on the rear frame, exactly as BicycleParameters 1.5.2 defines it
//! (`models.MooreRiderLean2012Model`, parameter set `mooreriderlean2012_browser_jason`).
//!
//! The equations come from the mechanics engine's description
//! (`codegen/src/derive/whipple/lean_rider.rs`, Kane's method; `generated/lean_rider.ir`):
//! the mass matrix $M$ and forcing $f$ of the four independent speeds $u_4, u_6, u_7, u_9$
//! (roll, rear wheel, steer, lean joint), the dependent rates $\dot q_3, \dot q_5, \dot q_8$
//! (yaw, pitch, front wheel) and the rear contact's velocity $(P_u, P_v)$ in the yawed frame.
//! The state is Moore's twelve, `q1 q2 q3 q4 q6 q7 q8 q9 u4 u6 u7 u9`
//! ([`STATE_NAMES`]), with the rear frame pitch $q_5$ carried beside them as a thirteenth so
//! that no Newton solve of the contact constraint runs at every evaluation; the inputs are the
//! roll torque $T_4$, the rear wheel torque $T_6$, the steer torque $T_7$ and the lean torque
//! $T_9$ (the joint's passive torque $-(c_9 \dot q_9 + k_9 q_9)$ is in the equations).
//!
//! The lean joint's axis is tilted by $\lambda$ from the rear frame, and Moore's $\lambda$ is
//! the rear frame's pitch upright ([`LeanRider::upright_pitch`], found here by Newton on the
//! front contact's height), so a parameter file gives Moore's 36 values without it.
//!
//! The linearisation about upright straight running at speed $v$ ($u_6 = -v/r_R$, the pitch
//! held at its upright value, which is stationary in roll and steer by symmetry) is taken by
//! forward-mode dual numbers through the whole program ([`carvallo_ir::dual`]) and the
//! $4 \times 4$ solve: exact to rounding, no step size. [`LeanRider::state_space`] gives
//! $A$ ($12 \times 12$) and $B$ ($12 \times 3$, over $T_4, T_7, T_9$, BicycleParameters' inputs: it
//! drops $T_6$); six of the twelve eigenvalues are zero (the ignorable coordinates and the rear
//! wheel's speed) and [`LeanRider::eigenvalues`] gives the other six, those of roll, steer and
//! lean. With Browser + Jason's $k_9 = c_9 = 0$ the torso is an inverted pendulum (a real
//! eigenvalue near $+7\ \mathrm{s}^{-1}$ at every speed), so its open-loop stable speed range is
//! empty ([`LeanRider::stable_speeds`] says so); joint stiffness or lean feedback makes one.
//!
//! # The singular configuration
//! The dependent rates come from the front contact's three constraint rows solved one after the
//! other, as the bicycle's do ([its singular
//! configurations](super::nonlinear#the-singular-configurations)): every `A_q5d_*` formula of
//! the generated program divides by the pitch rate's coefficient in the vertical row
//! (`b_F_vertical_q5d`), every `A_q3d_*` by the yaw rate's in the lateral row
//! (`b_F_lateral_q3d`) and every `A_q8d_*` by the front wheel rate's in the longitudinal row
//! (`b_F_longitudinal_q8d`) ([`pivot_scene`]). The program's other divisions are by $\cos q_4$
//! (zero only at a roll of ±π/2) and by `n_F`, the length of the vertical's projection on the
//! front wheel's plane (zero only where the front wheel lies flat). The torso does not enter
//! them: they are the bicycle's three pivots ([`PIVOTS`](super::nonlinear::PIVOTS)) of the same
//! geometry, and with the joint locked the rider is the bicycle of [`LeanRider::locked`]. A
//! simulation therefore ends, [`RunEnd::Singular`] (status *singular*, with the pivot), when
//! the smallest of [`LeanRider::pivot_ratios`] (each pivot over its upright value) falls to
//! [`SINGULAR_PIVOT`](super::nonlinear::SINGULAR_PIVOT) = 1 %: an event on the signed ratio,
//! located on the interpolant like the falls, so that a step jumping across the pole registers
//! too; a start at or beyond it is refused ([`LeanRiderError::SingularStart`], naming the pivot
//! and its ratio).

use std::fmt;
use std::ops::{Add, Div, Mul, Sub};
use std::sync::atomic::AtomicBool;
use std::sync::OnceLock;

use crate::numerics::integrate::{
    integrate_with_jacobian, Grid, IntegrateError, Integration, Point, Stats,
};

use carvallo_ir::dual::{self, Dual};
use carvallo_ir::Program;
use nalgebra::{Complex, DMatrix, SMatrix, SVector};

crate::scene! {
    /// Kane's equations ($M$, $f$), the dependent rates and the rear contact's velocity: every
    /// output the right-hand side needs, and nothing else.
    pub mod dynamics_scene {
        model: lean_rider,
        outputs: [M_q4d_q4d, M_q4d_q6d, M_q4d_q7d, M_q4d_q9d, M_q6d_q6d, M_q6d_q7d, M_q6d_q9d,
                  M_q7d_q7d, M_q7d_q9d, M_q9d_q9d, f_q4d, f_q6d, f_q7d, f_q9d,
                  q3d, q5d, q8d, P_u, P_v],
    }
}

crate::scene! {
    /// The total energy (kinetic plus gravity's potential; the lean joint's spring is not in
    /// it): conserved without torques and damping, what a simulation's drift is measured by.
    pub mod energy_scene {
        model: lean_rider,
        outputs: [energy],
    }
}

crate::scene! {
    /// The front contact's height $h$ above the ground and $\partial h/\partial q_5$.
    pub mod contact_scene {
        model: lean_rider,
        outputs: [F_contact_height, F_contact_height_dq5],
    }
}

crate::scene! {
    /// The pivots of the front contact's constraint rows, solved one after the other for the
    /// dependent rates: the pitch rate's coefficient in the vertical row (`b_F_vertical_q5d`,
    /// the divisor of every `A_q5d_*`), the yaw rate's in the lateral row (`b_F_lateral_q3d`,
    /// of every `A_q3d_*`) and the front wheel rate's in the longitudinal row
    /// (`b_F_longitudinal_q8d`, of every `A_q8d_*`): the bicycle's three
    /// ([`PIVOTS`](super::nonlinear::PIVOTS)). The equations are singular where one vanishes.
    pub mod pivot_scene {
        model: lean_rider,
        outputs: [b_F_vertical_q5d, b_F_lateral_q3d, b_F_longitudinal_q8d],
    }
}

crate::scene! {
    /// [`dynamics_scene`]'s outputs and their derivatives with respect to roll, pitch, steer,
    /// the torso's lean and the four independent speeds: the kernel of
    /// [`LeanRider::jacobian`], generated by forward-mode differentiation of the same program.
    pub mod dynamics_jacobian_scene {
        model: lean_rider,
        outputs: [M_q4d_q4d, M_q4d_q6d, M_q4d_q7d, M_q4d_q9d, M_q6d_q6d, M_q6d_q7d, M_q6d_q9d,
                  M_q7d_q7d, M_q7d_q9d, M_q9d_q9d, f_q4d, f_q6d, f_q7d, f_q9d,
                  q3d, q5d, q8d, P_u, P_v],
        jacobian: [q4, q5, q7, q9, q4d, q6d, q7d, q9d],
    }
}

crate::scene! {
    /// The front contact's height, its pitch derivative, and their derivatives with respect to
    /// roll, pitch and steer: the projection's part of [`LeanRider::jacobian`].
    pub mod contact_jacobian_scene {
        model: lean_rider,
        outputs: [F_contact_height, F_contact_height_dq5],
        jacobian: [q4, q5, q7],
    }
}

/// The names of the state's components, Moore's order (then the pitch `q5`, the thirteenth).
pub const STATE_NAMES: [&str; 12] =
    ["q1", "q2", "q3", "q4", "q6", "q7", "q8", "q9", "u4", "u6", "u7", "u9"];

/// The inputs of [`LeanRider::state_space`]'s $B$: roll, steer and lean torques (N m).
pub const INPUT_NAMES: [&str; 3] = ["T4", "T7", "T9"];

/// The components of the state that the six non-zero eigenvalues live on: roll, steer, lean
/// and their rates.
pub const LATERAL: [usize; 6] = [3, 5, 7, 8, 10, 11];

/// The index of the pitch `q5` in a 13-component state.
pub const PITCH: usize = 12;

/// The text of BicycleParameters' `mooreriderlean2012_browser_jason`
/// (`data/mooreriderlean2012/browser_jason.toml`, its source named there).
pub const BROWSER_JASON: &str =
    include_str!("../../../../data/mooreriderlean2012/browser_jason.toml");

/// A parameter set of the model: Moore's 36 values by name ([`LeanRiderParams::NAMES`]).
#[derive(Clone, Debug, PartialEq)]
pub struct LeanRiderParams {
    values: [f64; 36],
}

/// What is wrong with a parameter set or a parameter file.
#[derive(Clone, Debug, PartialEq)]
pub enum LeanRiderError {
    /// A line that is not `name = value`.
    Line {
        /// Its 1-based number.
        line: usize,
        /// Its text.
        text: String,
    },
    /// A name the model does not have.
    Unknown {
        /// The name.
        name: String,
    },
    /// A name given twice.
    Repeated {
        /// The name.
        name: String,
    },
    /// A name the set lacks.
    Missing {
        /// The name.
        name: &'static str,
    },
    /// A value that is not a finite number.
    NotANumber {
        /// The parameter.
        name: String,
        /// The value as written.
        text: String,
    },
    /// A value outside what the model allows.
    Invalid {
        /// The parameter.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What it must be.
        reason: &'static str,
    },
    /// The front wheel cannot touch the ground upright: no pitch puts its contact on it.
    NoUpright,
    /// A start at or beyond the singular configuration: the pivot
    /// [`PIVOTS`](super::nonlinear::PIVOTS)`[pivot]` of the constraint solve at or below
    /// [`SINGULAR_PIVOT`](super::nonlinear::SINGULAR_PIVOT) of its upright value.
    SingularStart {
        /// The roll (rad).
        q4: f64,
        /// The steer (rad).
        q7: f64,
        /// Which pivot ([`PIVOTS`](super::nonlinear::PIVOTS) order).
        pivot: usize,
        /// Its ratio to its upright value.
        ratio: f64,
    },
    /// A start whose state `name` ([`STATE_NAMES`], or `q5` for the pitch) is not a finite
    /// number.
    NotFiniteStart {
        /// The state.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A start with the roll $|q_4|$ at or beyond the fall angle: the bicycle would already
    /// lie on the ground.
    Fallen {
        /// The roll of the start (rad).
        q4: f64,
        /// The fall angle ([`Limits::fall_angle`], rad).
        fall_angle: f64,
    },
    /// A start with the torso's lean on its joint $|q_9|$ at or beyond the fall angle: the
    /// torso would already have fallen.
    TorsoFallen {
        /// The torso's lean of the start (rad).
        q9: f64,
        /// The fall angle ([`Limits::fall_angle`], rad).
        fall_angle: f64,
    },
    /// A start with the steer $|q_7|$ at or beyond the steer lock: the handlebar would
    /// already be against the frame.
    SteerLocked {
        /// The steer of the start (rad).
        q7: f64,
        /// The steer lock ([`Limits::steer_lock`], rad).
        steer_lock: f64,
    },
}

impl fmt::Display for LeanRiderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LeanRiderError::Line { line, text } => {
                write!(f, "line {line}: expected `name = value`, found `{text}`")
            }
            LeanRiderError::Unknown { name } => write!(
                f,
                "unknown parameter `{name}` (the leaning rider's are {})",
                LeanRiderParams::NAMES.join(", ")
            ),
            LeanRiderError::Repeated { name } => write!(f, "parameter `{name}` given twice"),
            LeanRiderError::Missing { name } => write!(f, "missing parameter `{name}`"),
            LeanRiderError::NotANumber { name, text } => {
                write!(f, "parameter `{name}` = `{text}` is not a finite number")
            }
            LeanRiderError::Invalid { name, value, reason } => {
                write!(f, "invalid parameter {name} = {value}: {reason}")
            }
            LeanRiderError::NoUpright => write!(
                f,
                "no rear frame pitch puts the front wheel on the ground upright (check d1, d2, \
                 d3, rf and rr)"
            ),
            LeanRiderError::SingularStart { q4, q7, pivot, ratio } => {
                let (name, where_) = super::nonlinear::PIVOTS[(*pivot).min(2)];
                write!(
                    f,
                    "invalid start at roll {q4} rad, steer {q7} rad: at or beyond the singular \
                     configuration ({where_}): the {name}'s pivot of the constraint solve at \
                     {ratio} of its upright value, at or below {}",
                    super::nonlinear::SINGULAR_PIVOT
                )
            }
            LeanRiderError::NotFiniteStart { name, value } => {
                write!(f, "invalid start {name} {value:?}: must be finite")
            }
            LeanRiderError::Fallen { q4, fall_angle } => write!(
                f,
                "invalid roll {q4:?} rad: at or beyond the fall angle ±{fall_angle} rad, where the \
                 bicycle is on the ground"
            ),
            LeanRiderError::TorsoFallen { q9, fall_angle } => write!(
                f,
                "invalid torso lean {q9:?} rad: at or beyond the fall angle ±{fall_angle} rad, \
                 where the torso has fallen on its joint"
            ),
            LeanRiderError::SteerLocked { q7, steer_lock } => write!(
                f,
                "invalid steer {q7:?} rad: at or beyond the steer lock ±{steer_lock} rad, where \
                 the handlebar is against the frame"
            ),
        }
    }
}

impl std::error::Error for LeanRiderError {}

impl LeanRiderParams {
    /// Moore's names, BicycleParameters' spelling: the hinge and frame lengths `d1`–`d4`,
    /// `l1`–`l6`, the wheel radii `rr`, `rf`, the masses `mc` (rear frame), `md` (rear wheel),
    /// `me` (front frame), `mf` (front wheel), `mg` (torso), their inertias, gravity `g` and
    /// the lean joint's damping `c9` and stiffness `k9`.
    pub const NAMES: [&'static str; 36] = [
        "c9", "d1", "d2", "d3", "d4", "g", "ic11", "ic22", "ic31", "ic33", "id11", "id22", "ie11",
        "ie22", "ie31", "ie33", "if11", "if22", "ig11", "ig22", "ig31", "ig33", "k9", "l1", "l2",
        "l3", "l4", "l5", "l6", "mc", "md", "me", "mf", "mg", "rf", "rr",
    ];

    /// BicycleParameters' `mooreriderlean2012_browser_jason`: Jason on the Browser bicycle.
    pub fn browser_jason() -> LeanRiderParams {
        LeanRiderParams::from_text(BROWSER_JASON).expect("the committed parameter file reads")
    }

    /// The values in [`NAMES`](Self::NAMES) order, checked: finite; masses, wheel radii and
    /// gravity positive; the principal moments and `c9`, `k9` not negative.
    ///
    /// # Errors
    /// [`LeanRiderError::Invalid`] naming the first bad value.
    pub fn new(values: [f64; 36]) -> Result<LeanRiderParams, LeanRiderError> {
        for (&name, &value) in Self::NAMES.iter().zip(&values) {
            let reason = if !value.is_finite() {
                Some("must be finite")
            } else if matches!(name, "mc" | "md" | "me" | "mf" | "mg" | "rf" | "rr" | "g")
                && value <= 0.0
            {
                Some("must be positive")
            } else if (matches!(name, "c9" | "k9") || (name.starts_with('i') && name[2..] != *"31"))
                && value < 0.0
            {
                Some("must not be negative")
            } else {
                None
            };
            if let Some(reason) = reason {
                return Err(LeanRiderError::Invalid { name, value, reason });
            }
        }
        Ok(LeanRiderParams { values })
    }

    /// Reads `name = value` lines (`#` comments, blank lines; TOML's plain key–value form,
    /// as `data/mooreriderlean2012/browser_jason.toml`). Every one of the 36 names is required;
    /// BicycleParameters' nominal speed `v` is accepted and not used (speeds are the caller's).
    ///
    /// # Errors
    /// The first bad line, unknown, repeated or missing name, or bad value.
    pub fn from_text(text: &str) -> Result<LeanRiderParams, LeanRiderError> {
        let mut values = [None; 36];
        let mut seen_v = false;
        for (k, line) in text.lines().enumerate() {
            let line = line.split('#').next().unwrap_or("").trim();
            if line.is_empty() {
                continue;
            }
            let Some((name, value)) = line.split_once('=') else {
                return Err(LeanRiderError::Line { line: k + 1, text: line.to_string() });
            };
            let (name, value) = (name.trim(), value.trim());
            let number = || {
                value.parse::<f64>().ok().filter(|x| x.is_finite()).ok_or_else(|| {
                    LeanRiderError::NotANumber { name: name.to_string(), text: value.to_string() }
                })
            };
            if name == "v" {
                if seen_v {
                    return Err(LeanRiderError::Repeated { name: name.to_string() });
                }
                seen_v = true;
                number()?;
                continue;
            }
            let Some(i) = Self::NAMES.iter().position(|n| *n == name) else {
                return Err(LeanRiderError::Unknown { name: name.to_string() });
            };
            if values[i].is_some() {
                return Err(LeanRiderError::Repeated { name: name.to_string() });
            }
            values[i] = Some(number()?);
        }
        let mut out = [0.0; 36];
        for (k, v) in values.iter().enumerate() {
            out[k] = v.ok_or(LeanRiderError::Missing { name: Self::NAMES[k] })?;
        }
        LeanRiderParams::new(out)
    }

    /// Whether `text` reads as this model's parameters (Moore's names, not the benchmark's):
    /// it names `mg`, `ig11` and `d4` on lines of their own.
    pub fn looks_like(text: &str) -> bool {
        ["mg", "ig11", "d4"].iter().all(|name| {
            text.lines().any(|l| l.split('=').next().is_some_and(|n| n.trim() == *name))
        })
    }

    /// The value of `name`, or `None` for a name the model does not have.
    pub fn get(&self, name: &str) -> Option<f64> {
        Self::NAMES.iter().position(|n| *n == name).map(|k| self.values[k])
    }

    /// The values, [`NAMES`](Self::NAMES) order.
    pub fn values(&self) -> &[f64; 36] {
        &self.values
    }

    /// The same set with `name` set to `value`.
    ///
    /// # Errors
    /// [`LeanRiderError::Unknown`] for a name the model does not have, and as [`new`](Self::new).
    pub fn with(&self, name: &str, value: f64) -> Result<LeanRiderParams, LeanRiderError> {
        let k = Self::NAMES
            .iter()
            .position(|n| *n == name)
            .ok_or_else(|| LeanRiderError::Unknown { name: name.to_string() })?;
        let mut values = self.values;
        values[k] = value;
        LeanRiderParams::new(values)
    }
}

/// A state feedback $T = -K x$ on the leaning rider's lateral states: rows the roll, steer and
/// lean torques (T4, T7, T9), columns roll, steer, the torso's lean and their rates ([`LATERAL`]
/// order), named `k_{roll|steer|lean}_{roll|steer|lean|roll_rate|steer_rate|lean_rate}` as the
/// bicycle's gains are. `k_lean_lean` and `k_lean_lean_rate` are a spring and a damper on the
/// lean joint: the same as $k_9$ and $c_9$.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LeanGains(pub [[f64; 6]; 3]);

impl LeanGains {
    /// The torques, rows of $K$.
    pub const INPUTS: [&'static str; 3] = ["roll", "steer", "lean"];
    /// The states, columns of $K$.
    pub const STATES: [&'static str; 6] =
        ["roll", "steer", "lean", "roll_rate", "steer_rate", "lean_rate"];

    /// The row and column of the gain `name`; `None` for a name that is not one.
    pub fn index(name: &str) -> Option<(usize, usize)> {
        let rest = name.strip_prefix("k_")?;
        Self::INPUTS.iter().enumerate().find_map(|(i, input)| {
            let state = rest.strip_prefix(input)?.strip_prefix('_')?;
            Self::STATES.iter().position(|s| *s == state).map(|j| (i, j))
        })
    }

    /// The gains given by name (the others zero; a name given twice keeps its last value).
    ///
    /// # Errors
    /// The first name that is not a gain of the leaning rider.
    pub fn from_named<'a>(
        pairs: impl IntoIterator<Item = (&'a str, f64)>,
    ) -> Result<LeanGains, String> {
        let mut k = LeanGains::default();
        for (name, value) in pairs {
            let (i, j) = Self::index(name).ok_or_else(|| {
                format!(
                    "unknown gain `{name}` for the leaning rider: expected \
                     k_{{roll|steer|lean}}_{{roll|steer|lean|roll_rate|steer_rate|lean_rate}}"
                )
            })?;
            k.0[i][j] = value;
        }
        Ok(k)
    }
}

/// The arithmetic the right-hand side is written in: `f64` for evaluation, [`Dual`] for the
/// linearisation.
pub(crate) trait Real:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
    fn sin(self) -> Self;
    fn cos(self) -> Self;
}

impl Real for f64 {
    fn sin(self) -> f64 {
        f64::sin(self)
    }
    fn cos(self) -> f64 {
        f64::cos(self)
    }
}

impl<const N: usize> Real for Dual<N> {
    fn sin(self) -> Dual<N> {
        Dual::sin(self)
    }
    fn cos(self) -> Dual<N> {
        Dual::cos(self)
    }
}

/// Solves $M x = f$ for the symmetric positive definite $4 \times 4$ mass matrix by Gaussian
/// elimination without pivoting (its pivots are the positive ones of $LDL^T$).
fn solve4<T: Real>(mut m: [[T; 4]; 4], mut f: [T; 4]) -> [T; 4] {
    for k in 0..4 {
        for i in k + 1..4 {
            let r = m[i][k] / m[k][k];
            let pivot_row = m[k];
            for (x, p) in m[i].iter_mut().zip(pivot_row).skip(k) {
                *x = *x - r * p;
            }
            f[i] = f[i] - r * f[k];
        }
    }
    let mut x = f;
    for k in (0..4).rev() {
        for j in k + 1..4 {
            x[k] = x[k] - m[k][j] * x[j];
        }
        x[k] = x[k] / m[k][k];
    }
    x
}

/// The state derivative from the outputs of [`dynamics_scene`] (its `OUTPUTS` order) at the
/// state `x` (12 components, Moore's order).
pub(crate) fn assemble<T: Real>(o: &[T; 19], x: &[T; 12]) -> [T; 13] {
    let m = [
        [o[0], o[1], o[2], o[3]],
        [o[1], o[4], o[5], o[6]],
        [o[2], o[5], o[7], o[8]],
        [o[3], o[6], o[8], o[9]],
    ];
    let ud = solve4(m, [o[10], o[11], o[12], o[13]]);
    let (q3d, q5d, q8d, pu, pv) = (o[14], o[15], o[16], o[17], o[18]);
    let (s3, c3) = (x[2].sin(), x[2].cos());
    [
        pu * c3 - pv * s3,
        pu * s3 + pv * c3,
        q3d,
        x[8],
        x[9],
        x[10],
        q8d,
        x[11],
        ud[0],
        ud[1],
        ud[2],
        ud[3],
        q5d,
    ]
}

/// The program `generated/lean_rider.ir`, parsed once.
pub(crate) fn program() -> &'static Program {
    static PROGRAM: OnceLock<Program> = OnceLock::new();
    PROGRAM.get_or_init(|| {
        Program::parse(crate::artifacts::LEAN_RIDER.ir).expect("the committed program parses")
    })
}

/// The leaning rider with one parameter set: its upright pitch found and the evaluators'
/// arguments filled.
#[derive(Clone, Debug)]
pub struct LeanRider {
    params: LeanRiderParams,
    lam: f64,
    dynamics: Filled<{ dynamics_scene::Args::LEN }>,
    contact: Filled<{ contact_scene::Args::LEN }>,
    energy: Filled<{ energy_scene::Args::LEN }>,
    dynamics_jac: Filled<{ dynamics_jacobian_scene::Args::LEN }>,
    contact_jac: Filled<{ contact_jacobian_scene::Args::LEN }>,
    pivot: Filled<{ pivot_scene::Args::LEN }>,
    /// The pivots upright (roll and steer zero, the pitch $\lambda$).
    pivot_upright: [f64; 3],
}

/// The lean joint in a simulation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Joint {
    /// Free: the torso moves on it under gravity, the spring and damper and $T_9$.
    Free,
    /// Locked at its initial angle: $\dot u_9 = 0$ (the lean equation gives the joint's
    /// reaction and is dropped); the bicycle of [`LeanRider::locked`] when that angle is zero.
    Locked,
}

/// How a simulation ended: a physical outcome, not an error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RunEnd {
    /// The end of the duration.
    Completed,
    /// The roll $|q_4|$ reached the fall angle at `t` (s).
    Fell {
        /// When (s).
        t: f64,
    },
    /// The torso's lean on its joint $|q_9|$ reached the fall angle at `t` (s).
    TorsoFell {
        /// When (s).
        t: f64,
    },
    /// The steer $|q_7|$ reached the steer lock at `t` (s).
    SteerLock {
        /// When (s).
        t: f64,
    },
    /// A pivot of the constraint solve fell to
    /// [`SINGULAR_PIVOT`](super::nonlinear::SINGULAR_PIVOT) of its upright value at `t` (s):
    /// the equations near their singular configuration ([`LeanRider::pivot_ratios`]).
    Singular {
        /// When (s).
        t: f64,
        /// Which pivot ([`PIVOTS`](super::nonlinear::PIVOTS) order: 0 pitch rate, 1 yaw
        /// rate, 2 front wheel rate).
        pivot: usize,
    },
    /// The stop flag (Ctrl-C) ended the run at `t` (s), the last accepted step.
    Interrupted {
        /// When (s).
        t: f64,
    },
}

/// Where a simulation ends as a fall (rad): the roll's or the torso's lean magnitude reaching
/// `fall_angle`, the steer's reaching `steer_lock` (the bicycle's defaults,
/// [`DEFAULT_FALL_ANGLE`](super::nonlinear::DEFAULT_FALL_ANGLE) and
/// [`DEFAULT_STEER_LOCK`](super::nonlinear::DEFAULT_STEER_LOCK), in [`Limits::DEFAULT`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// The roll's and the torso's fall angle (rad).
    pub fall_angle: f64,
    /// The steer lock (rad).
    pub steer_lock: f64,
}

impl Limits {
    /// The bicycle's: 1.2 rad and 1.4 rad.
    pub const DEFAULT: Limits = Limits {
        fall_angle: super::nonlinear::DEFAULT_FALL_ANGLE,
        steer_lock: super::nonlinear::DEFAULT_STEER_LOCK,
    };

    /// Checks the limits as the bicycle's
    /// [`with_fall_angle`](super::nonlinear::WhippleNonlinear::with_fall_angle) and
    /// [`with_steer_lock`](super::nonlinear::WhippleNonlinear::with_steer_lock) do.
    ///
    /// # Errors
    /// [`LeanRiderError::Invalid`] naming `fall angle` unless $0 <$ `fall_angle` $\le \pi/2$,
    /// or `steer lock` unless $0 <$ `steer_lock` $< \pi/2$ (at π/2 the equations are
    /// singular).
    pub fn check(&self) -> Result<(), LeanRiderError> {
        use std::f64::consts::FRAC_PI_2;
        let Limits { fall_angle, steer_lock } = *self;
        if !(fall_angle > 0.0 && fall_angle <= FRAC_PI_2) {
            let reason = "must lie in (0, pi/2] rad";
            return Err(LeanRiderError::Invalid { name: "fall angle", value: fall_angle, reason });
        }
        if !(steer_lock > 0.0 && steer_lock < FRAC_PI_2) {
            let reason = "must lie in (0, pi/2) rad";
            return Err(LeanRiderError::Invalid { name: "steer lock", value: steer_lock, reason });
        }
        Ok(())
    }

    /// Checks that the start `x0` (Moore's twelve, then the pitch) lies inside these limits:
    /// every state finite, the roll $|q_4|$ and the torso's lean $|q_9|$ below the fall angle,
    /// the steer $|q_7|$ below the steer lock. [`LeanRider::simulate`] makes this check
    /// first, as the bicycle's
    /// [`check_start`](super::nonlinear::WhippleNonlinear::check_start) does.
    ///
    /// # Errors
    /// As [`check`](Self::check) for the limits themselves;
    /// [`LeanRiderError::NotFiniteStart`] naming the first state not finite;
    /// [`LeanRiderError::Fallen`], [`LeanRiderError::TorsoFallen`] and
    /// [`LeanRiderError::SteerLocked`] naming the value at or beyond its limit.
    pub fn check_start(&self, x0: &[f64; 13]) -> Result<(), LeanRiderError> {
        self.check()?;
        if let Some(k) = x0.iter().position(|x| !x.is_finite()) {
            let name = STATE_NAMES.get(k).copied().unwrap_or("q5");
            return Err(LeanRiderError::NotFiniteStart { name, value: x0[k] });
        }
        let Limits { fall_angle, steer_lock } = *self;
        if x0[3].abs() >= fall_angle {
            return Err(LeanRiderError::Fallen { q4: x0[3], fall_angle });
        }
        if x0[7].abs() >= fall_angle {
            return Err(LeanRiderError::TorsoFallen { q9: x0[7], fall_angle });
        }
        if x0[5].abs() >= steer_lock {
            return Err(LeanRiderError::SteerLocked { q7: x0[5], steer_lock });
        }
        Ok(())
    }
}

/// A simulation of the leaning rider: the samples of the grid up to its end.
#[derive(Clone, Debug, PartialEq)]
pub struct LeanRun {
    /// The sample times (s).
    pub times: Vec<f64>,
    /// The states (Moore's twelve, then the pitch `q5`).
    pub states: Vec<[f64; 13]>,
    /// How it ended, and the state then.
    pub end: (RunEnd, [f64; 13]),
    /// The integrator's counts.
    pub stats: Stats,
    /// The largest change of the total energy at the accepted steps (J): a measure of the
    /// integration's error when no torque, damping or spring does work.
    pub max_energy_drift: f64,
}

impl RunEnd {
    /// The status word: `completed`, `fell`, `torso fell`, `steer lock`, `singular`,
    /// `interrupted`.
    pub fn status(&self) -> &'static str {
        match self {
            RunEnd::Completed => "completed",
            RunEnd::Fell { .. } => "fell",
            RunEnd::TorsoFell { .. } => "torso fell",
            RunEnd::SteerLock { .. } => "steer lock",
            RunEnd::Singular { .. } => "singular",
            RunEnd::Interrupted { .. } => "interrupted",
        }
    }
}

impl LeanRun {
    /// The columns of [`table`](Self::table).
    pub const COLUMNS: [&'static str; 9] =
        ["t", "roll", "steer", "lean", "yaw", "pitch", "x", "y", "energy"];

    /// The line that says how the run ended, under the limits it ran with.
    pub fn status_line(&self, limits: Limits) -> String {
        let Limits { fall_angle, steer_lock } = limits;
        match self.end.0 {
            RunEnd::Completed => {
                format!("completed at t = {} s", self.times.last().copied().unwrap_or(0.0))
            }
            RunEnd::Fell { t } => {
                format!("fell at t = {t} s: the roll reached the fall angle ±{fall_angle} rad")
            }
            RunEnd::TorsoFell { t } => format!(
                "torso fell at t = {t} s: the torso's lean on its joint reached ±{fall_angle} rad"
            ),
            RunEnd::SteerLock { t } => {
                format!("steer lock at t = {t} s: the steer reached ±{steer_lock} rad")
            }
            RunEnd::Singular { t, pivot } => {
                let x = &self.end.1;
                let at = format!("roll {} rad, steer {} rad", x[3], x[5]);
                super::nonlinear::singular_line_at(t, pivot, &at)
            }
            RunEnd::Interrupted { t } => format!("interrupted at t = {t} s"),
        }
    }

    /// The rows of [`COLUMNS`](Self::COLUMNS) (time, roll, steer, the torso's lean, yaw,
    /// pitch, the rear contact, the energy of `rider`): the samples, then the fall's end when
    /// it is not one of them.
    pub fn table(&self, rider: &LeanRider) -> Vec<[f64; 9]> {
        let mut rows: Vec<(f64, [f64; 13])> =
            self.times.iter().copied().zip(self.states.iter().copied()).collect();
        if let RunEnd::Fell { t }
        | RunEnd::TorsoFell { t }
        | RunEnd::SteerLock { t }
        | RunEnd::Singular { t, .. } = self.end.0
        {
            if rows.last().is_none_or(|(s, _)| *s < t) {
                rows.push((t, self.end.1));
            }
        }
        rows.iter()
            .map(|(t, x)| [*t, x[3], x[5], x[7], x[2], x[PITCH], x[0], x[1], rider.energy(x)])
            .collect()
    }
}

/// The program's inputs, in the order [`input_values`] gives them.
const INPUT_ORDER: [&str; 12] =
    ["q4", "q5", "q7", "q9", "q4d", "q6d", "q7d", "q9d", "T4", "T6", "T7", "T9"];

/// The values of [`INPUT_ORDER`] at the state `x` (Moore's twelve, then the pitch) under the
/// torques `[T4, T6, T7, T9]`.
fn input_values(x: &[f64; 13], torques: &[f64; 4]) -> [f64; 12] {
    [
        x[3], x[PITCH], x[5], x[7], x[8], x[9], x[10], x[11], torques[0], torques[1], torques[2],
        torques[3],
    ]
}

/// A scene's argument array with the parameters filled in once, and where each input of
/// [`INPUT_ORDER`] goes (`usize::MAX` where the scene does not take it): an evaluation copies
/// the array and writes the inputs, with no search by name.
#[derive(Clone, Debug)]
struct Filled<const N: usize> {
    args: [f64; N],
    slots: [usize; 12],
}

impl<const N: usize> Filled<N> {
    /// The arguments of the scene whose parameters are `params` and inputs `inputs`.
    fn new(values: &LeanRiderParams, lam: f64, params: &[&str], inputs: &[&str]) -> Filled<N> {
        Filled {
            args: std::array::from_fn(|i| match params.get(i) {
                Some(&"lam") => lam,
                Some(name) => values.get(name).unwrap_or(0.0),
                None => 0.0,
            }),
            slots: INPUT_ORDER.map(|name| {
                inputs.iter().position(|n| *n == name).map_or(usize::MAX, |i| params.len() + i)
            }),
        }
    }

    /// The argument array with the inputs `values` ([`INPUT_ORDER`]).
    fn at(&self, values: &[f64; 12]) -> [f64; N] {
        let mut a = self.args;
        for (&slot, &v) in self.slots.iter().zip(values) {
            if let Some(x) = a.get_mut(slot) {
                *x = v;
            }
        }
        a
    }
}

impl LeanRider {
    /// The model with the parameters `params`; its upright pitch (Moore's $\lambda$) is found
    /// by Newton's method on the front contact's height, from the sign change of the height
    /// nearest to zero pitch on a grid of $(-\pi/2, \pi/2)$.
    ///
    /// # Errors
    /// [`LeanRiderError::NoUpright`] when no pitch puts the front wheel on the ground.
    pub fn new(params: LeanRiderParams) -> Result<LeanRider, LeanRiderError> {
        let with_lam = |lam: f64| {
            (
                Filled::new(&params, lam, dynamics_scene::PARAMS, dynamics_scene::INPUTS),
                Filled::new(&params, lam, energy_scene::PARAMS, energy_scene::INPUTS),
                Filled::new(
                    &params,
                    lam,
                    dynamics_jacobian_scene::PARAMS,
                    dynamics_jacobian_scene::INPUTS,
                ),
            )
        };
        let (dynamics, energy, dynamics_jac) = with_lam(0.0);
        let contact = Filled::new(&params, 0.0, contact_scene::PARAMS, contact_scene::INPUTS);
        let contact_jac = Filled::new(
            &params,
            0.0,
            contact_jacobian_scene::PARAMS,
            contact_jacobian_scene::INPUTS,
        );
        let pivot = Filled::new(&params, 0.0, pivot_scene::PARAMS, pivot_scene::INPUTS);
        let mut rider = LeanRider {
            dynamics,
            contact,
            energy,
            dynamics_jac,
            contact_jac,
            pivot,
            pivot_upright: [f64::NAN; 3],
            params: params.clone(),
            lam: 0.0,
        };
        rider.lam = rider.pitch_on_ground(0.0, 0.0).ok_or(LeanRiderError::NoUpright)?;
        (rider.dynamics, rider.energy, rider.dynamics_jac) = with_lam(rider.lam);
        rider.pivot = Filled::new(&params, rider.lam, pivot_scene::PARAMS, pivot_scene::INPUTS);
        rider.pivot_upright = rider.pivots(0.0, rider.lam, 0.0);
        Ok(rider)
    }

    /// The parameters.
    pub fn params(&self) -> &LeanRiderParams {
        &self.params
    }

    /// The rear frame's pitch upright (rad), Moore's $\lambda$: the front contact on the ground
    /// with roll and steer zero.
    pub fn upright_pitch(&self) -> f64 {
        self.lam
    }

    /// The benchmark's 26 parameters of this bicycle with the torso locked upright in the rear
    /// frame (the Carvallo–Whipple bicycle the rider becomes when $q_9$ is held at zero): C's
    /// frame is the benchmark's pitched by $\lambda$, so inertias turn by
    /// $R = \begin{pmatrix}\cos\lambda&0&\sin\lambda\\0&1&0\\-\sin\lambda&0&\cos\lambda\end{pmatrix}$,
    /// $I_B = R I_C R^\top + I_G$ moved by parallel axes to the common centre of the rear frame
    /// and the torso; wheelbase and trail from the hinge geometry. Browser + Jason gives
    /// $w = 1.121$, $c = 0.0686$, $m_B = 81.86$. The triangle inequalities a measured frame may
    /// break are returned as warnings, as for a BicycleParameters file.
    ///
    /// # Errors
    /// As [`WhippleParams::from_values_warning`](super::WhippleParams::from_values_warning).
    pub fn locked(
        &self,
    ) -> Result<(super::WhippleParams, Vec<super::TriangleWarning>), super::WhippleError> {
        let p = |name: &str| self.params.get(name).expect("Moore's parameter");
        let (sl, cl) = self.lam.sin_cos();
        let (c1, c3) = ([cl, -sl], [sl, cl]); // x and z components of C's axes 1 and 3
        let along = |o: [f64; 2], a: f64, u: [f64; 2], b: f64, w: [f64; 2]| {
            [o[0] + a * u[0] + b * w[0], o[1] + a * u[1] + b * w[1]]
        };
        let rr = p("rr");
        let d_o = [0.0, -rr];
        let ce = along(d_o, p("d1"), c1, 0.0, c3);
        let fo = along(ce, p("d3"), c1, p("d2"), c3);
        let w = fo[0];
        let trail = ce[0] - ce[1] / cl * sl - w;
        let co = along(d_o, p("l1"), c1, p("l2"), c3);
        let go = [p("l5"), -rr + p("d4") + p("l6")];
        let eo = along(fo, p("l3"), c1, p("l4"), c3);
        // R I R^T for I = [[i11, 0, i31], [0, i22, 0], [i31, 0, i33]]: (xx, yy, zz, xz).
        let turn = |i11: f64, i22: f64, i33: f64, i31: f64| {
            let r = [[cl, sl], [-sl, cl]];
            let i = [[i11, i31], [i31, i33]];
            let mut o = [[0.0; 2]; 2];
            for (a, row) in o.iter_mut().enumerate() {
                for (b, x) in row.iter_mut().enumerate() {
                    for k in 0..2 {
                        for l in 0..2 {
                            *x += r[a][k] * i[k][l] * r[b][l];
                        }
                    }
                }
            }
            (o[0][0], i22, o[1][1], o[0][1])
        };
        let (mc, mg) = (p("mc"), p("mg"));
        let mb = mc + mg;
        let xb = (mc * co[0] + mg * go[0]) / mb;
        let zb = (mc * co[1] + mg * go[1]) / mb;
        let (cxx, cyy, czz, cxz) = turn(p("ic11"), p("ic22"), p("ic33"), p("ic31"));
        // Parallel axes to the common centre: m (|r|^2 1 - r r^T).
        let shift = |m: f64, c: [f64; 2]| {
            let (rx, rz) = (c[0] - xb, c[1] - zb);
            (m * rz * rz, m * (rx * rx + rz * rz), m * rx * rx, -m * rx * rz)
        };
        let (s1, s2) = (shift(mc, co), shift(mg, go));
        let (hxx, hyy, hzz, hxz) = turn(p("ie11"), p("ie22"), p("ie33"), p("ie31"));
        super::WhippleParams::from_values_warning([
            w,
            trail,
            self.lam,
            p("g"),
            rr,
            p("md"),
            p("id11"),
            p("id22"),
            xb,
            zb,
            mb,
            cxx + p("ig11") + s1.0 + s2.0,
            cyy + p("ig22") + s1.1 + s2.1,
            czz + p("ig33") + s1.2 + s2.2,
            cxz + p("ig31") + s1.3 + s2.3,
            eo[0],
            eo[1],
            p("me"),
            hxx,
            hyy,
            hzz,
            hxz,
            p("rf"),
            p("mf"),
            p("if11"),
            p("if22"),
        ])
    }

    /// The front contact's height (m) and its derivative in pitch (m/rad) at roll `q4`,
    /// pitch `q5` and steer `q7`.
    pub fn contact(&self, q4: f64, q5: f64, q7: f64) -> (f64, f64) {
        let mut values = [0.0; 12];
        values[..3].copy_from_slice(&[q4, q5, q7]);
        let o = contact_scene::eval_array(&self.contact.at(&values));
        (o[0], o[1])
    }

    /// The front contact's height $h$ (m), $\partial h/\partial q_5$ (m/rad) and their
    /// derivatives with respect to roll, pitch and steer (rows $h$, $h_{q_5}$; columns $q_4$,
    /// $q_5$, $q_7$) at roll `q4`, pitch `q5` and steer `q7`, from generated code
    /// ([`contact_jacobian_scene`]).
    pub fn contact_derivatives(&self, q4: f64, q5: f64, q7: f64) -> (f64, f64, [[f64; 3]; 2]) {
        let mut values = [0.0; 12];
        values[..3].copy_from_slice(&[q4, q5, q7]);
        let o = contact_jacobian_scene::eval_array(&self.contact_jac.at(&values));
        (o[0], o[1], contact_jacobian_scene::jacobian_array(&o))
    }

    /// The pivots of the constraint solve at roll `q4`, pitch `q5` and steer `q7`: the
    /// coefficients of the pitch rate, the yaw rate and the front wheel rate in the front
    /// contact's vertical, lateral and longitudinal rows ([`pivot_scene`]), by which the
    /// dependent rates' formulas divide.
    pub fn pivots(&self, q4: f64, q5: f64, q7: f64) -> [f64; 3] {
        let mut values = [0.0; 12];
        values[..3].copy_from_slice(&[q4, q5, q7]);
        pivot_scene::eval_array(&self.pivot.at(&values))
    }

    /// The [`pivots`](Self::pivots) relative to their upright values (roll and steer zero, the
    /// pitch $\lambda$), in the order of [`PIVOTS`](super::nonlinear::PIVOTS) (pitch rate, yaw
    /// rate, front wheel rate): 1 upright, 0 where the equations are singular. A simulation
    /// ends, [`RunEnd::Singular`], when the smallest falls to
    /// [`SINGULAR_PIVOT`](super::nonlinear::SINGULAR_PIVOT), as the bicycle's does
    /// ([the bicycle's singular configurations](super::nonlinear#the-singular-configurations)).
    /// The pitch should put the front wheel on the ground ([`pitch_near`](Self::pitch_near)).
    pub fn pivot_ratios(&self, q4: f64, q5: f64, q7: f64) -> [f64; 3] {
        let p = self.pivots(q4, q5, q7);
        std::array::from_fn(|k| p[k] / self.pivot_upright[k])
    }

    /// The [`pivot_ratios`](Self::pivot_ratios) at the state `x`, its pitch first put on the
    /// contact constraint by one Newton step as [`projected_rate`](Self::projected_rate) does.
    fn projected_pivot_ratios(&self, x: &[f64; 13]) -> [f64; 3] {
        let (h, dh) = self.contact(x[3], x[PITCH], x[5]);
        self.pivot_ratios(x[3], x[PITCH] - h / dh, x[5])
    }

    /// The pitch that puts the front contact on the ground at roll `q4` and steer `q7`: the
    /// root of its height nearest zero pitch (a grid of 256 pitches in $(-\pi/2, \pi/2)$, then
    /// Newton to a step below $10^{-15}$ rad); `None` when the height has no sign change.
    pub fn pitch_on_ground(&self, q4: f64, q7: f64) -> Option<f64> {
        let n = 256;
        let at = |k: usize| -std::f64::consts::FRAC_PI_2 * (1.0 - 2.0 * k as f64 / n as f64);
        let mut best: Option<f64> = None;
        for k in 0..n {
            let (a, b) = (at(k), at(k + 1));
            let (ha, hb) = (self.contact(q4, a, q7).0, self.contact(q4, b, q7).0);
            if ha == 0.0 || ha.signum() != hb.signum() {
                let mid = 0.5 * (a + b);
                if best.is_none_or(|x| mid.abs() < x.abs()) {
                    best = Some(mid);
                }
            }
        }
        self.pitch_near(q4, best?, q7)
    }

    /// The state derivative at the state `x` (Moore's twelve, then the pitch `q5`) under the
    /// torques `[T4, T6, T7, T9]` (N m): the twelve rates, then $\dot q_5$.
    pub fn rate(&self, x: &[f64; 13], torques: &[f64; 4]) -> [f64; 13] {
        self.rate_with(x, torques, Joint::Free)
    }

    /// The total energy (J) at the state `x` (kinetic plus gravity's potential).
    pub fn energy(&self, x: &[f64; 13]) -> f64 {
        energy_scene::eval_array(&self.energy.at(&input_values(x, &[0.0; 4])))[0]
    }

    /// As [`rate`](Self::rate), the lean joint free or locked ([`Joint`]); with it locked the
    /// lean rates $\dot q_9$, $\dot u_9$ are zero and the other three accelerations solve the
    /// $3 \times 3$ system of roll, rear wheel and steer.
    pub fn rate_with(&self, x: &[f64; 13], torques: &[f64; 4], joint: Joint) -> [f64; 13] {
        let mut o = dynamics_scene::eval_array(&self.dynamics.at(&input_values(x, torques)));
        if joint == Joint::Locked {
            // The lean row replaced by u9' = 0: M's last row and column the unit vector.
            for k in [3, 6, 8] {
                o[k] = 0.0;
            }
            o[9] = 1.0;
            o[13] = 0.0;
        }
        let x12: [f64; 12] = std::array::from_fn(|k| x[k]);
        let mut d = assemble(&o, &x12);
        if joint == Joint::Locked {
            d[7] = 0.0;
        }
        d
    }

    /// The state derivative as a simulation evaluates it: the pitch first put back on the
    /// contact constraint by one Newton step from the carried value,
    /// $q_5^* = q_5 - h/h_{q_5}$, then [`rate_with`](Self::rate_with) at $q_5^*$.
    pub fn projected_rate(&self, x: &[f64; 13], torques: &[f64; 4], joint: Joint) -> [f64; 13] {
        let mut y = *x;
        let (h, dh) = self.contact(y[3], y[PITCH], y[5]);
        y[PITCH] -= h / dh;
        self.rate_with(&y, torques, joint)
    }

    /// The state Jacobian of [`projected_rate`](Self::projected_rate) at `x` under the constant
    /// torques `torques` `[T4, T6, T7, T9]`, the lean joint `joint`: row $i$, column $j$ is
    /// $\partial \dot x_i/\partial x_j$ (thirteen components, the pitch last). The
    /// linearisation about any state; about upright straight running it is
    /// [`state_space`](Self::state_space)'s $A$ (the pitch's column and row aside).
    ///
    /// Generated code gives the derivatives of $M$, $f$, the dependent rates and the rear
    /// contact's velocity with respect to roll, pitch, steer, the torso's lean and the four
    /// speeds ([`dynamics_jacobian_scene`]), and those of the contact constraint
    /// ([`contact_jacobian_scene`]); the chain rule then runs through the pitch's Newton step
    /// ($\partial q_5^*/\partial v = [v = q_5] - (h_v h_{q_5} - h\,h_{q_5 v})/h_{q_5}^2$),
    /// the solve ($\mathrm{d}\dot u = M^{-1}(\mathrm{d}f - \mathrm{d}M\,\dot u)$) and the
    /// kinematic rates.
    pub fn jacobian(&self, x: &[f64; 13], torques: &[f64; 4], joint: Joint) -> [[f64; 13]; 13] {
        let mut values = input_values(x, torques);
        // The projection and its derivatives with respect to roll, pitch, steer.
        let hc = contact_jacobian_scene::eval_array(&self.contact_jac.at(&values));
        let (h, dh) = (hc[0], hc[1]);
        let hd = contact_jacobian_scene::jacobian_array(&hc);
        let dproj: [f64; 3] = std::array::from_fn(|k| {
            let own = if k == 1 { 1.0 } else { 0.0 };
            own - (hd[0][k] * dh - h * hd[1][k]) / (dh * dh)
        });
        values[1] = x[PITCH] - h / dh;
        let mut o = dynamics_jacobian_scene::eval_array(&self.dynamics_jac.at(&values));
        let mut dz = dynamics_jacobian_scene::jacobian_array(&o);
        if joint == Joint::Locked {
            // As in `rate_with`: the lean row replaced by u9' = 0.
            for k in [3, 6, 8, 9, 13] {
                o[k] = if k == 9 { 1.0 } else { 0.0 };
                dz[k] = [0.0; 8];
            }
        }
        // Through z = (x3, q5*(x3, x12, x5), x5, x7, x8, x9, x10, x11) to the state.
        let g: [[f64; 13]; 19] = std::array::from_fn(|k| {
            let d = &dz[k];
            let mut row = [0.0; 13];
            row[3] = d[0] + d[1] * dproj[0];
            row[PITCH] = d[1] * dproj[1];
            row[5] = d[2] + d[1] * dproj[2];
            row[7] = d[3];
            row[8..12].copy_from_slice(&d[4..8]);
            row
        });
        let m = [
            [o[0], o[1], o[2], o[3]],
            [o[1], o[4], o[5], o[6]],
            [o[2], o[5], o[7], o[8]],
            [o[3], o[6], o[8], o[9]],
        ];
        let ud = solve4(m, [o[10], o[11], o[12], o[13]]);
        // d ud / d x_j = M^-1 (df_j - dM_j ud), column by column.
        const M_AT: [[usize; 4]; 4] = [[0, 1, 2, 3], [1, 4, 5, 6], [2, 5, 7, 8], [3, 6, 8, 9]];
        let mut dud = [[0.0; 13]; 4];
        for j in 0..13 {
            let rhs: [f64; 4] = std::array::from_fn(|r| {
                g[10 + r][j] - (0..4).map(|c| g[M_AT[r][c]][j] * ud[c]).sum::<f64>()
            });
            if rhs.iter().all(|v| *v == 0.0) {
                continue;
            }
            for (row, v) in dud.iter_mut().zip(solve4(m, rhs)) {
                row[j] = v;
            }
        }
        let (pu, pv) = (o[17], o[18]);
        let (s3, c3) = x[2].sin_cos();
        let mut jac = [[0.0; 13]; 13];
        jac[0] = std::array::from_fn(|j| g[17][j] * c3 - g[18][j] * s3);
        jac[0][2] = -pu * s3 - pv * c3;
        jac[1] = std::array::from_fn(|j| g[17][j] * s3 + g[18][j] * c3);
        jac[1][2] = pu * c3 - pv * s3;
        jac[2] = g[14];
        jac[3][8] = 1.0;
        jac[4][9] = 1.0;
        jac[5][10] = 1.0;
        jac[6] = g[16];
        if joint == Joint::Free {
            jac[7][11] = 1.0;
        }
        jac[8..12].copy_from_slice(&dud);
        jac[PITCH] = g[15];
        jac
    }

    /// Integrates the nonlinear equations from `x0` (Moore's twelve, then the pitch, which is
    /// first put on the contact constraint by Newton) under the torques `torques(t)`
    /// `= [T4, T6, T7, T9]` (N m) over `grid` by `how`, with the lean joint `joint`, until the
    /// grid's end, the roll $|q_4|$ or the torso's lean $|q_9|$ reaching `limits.fall_angle`
    /// (rad; [`RunEnd::Fell`], [`RunEnd::TorsoFell`]), the steer $|q_7|$ reaching
    /// `limits.steer_lock` ([`RunEnd::SteerLock`]), the smallest of the
    /// [`pivot_ratios`](Self::pivot_ratios) falling to
    /// [`SINGULAR_PIVOT`](super::nonlinear::SINGULAR_PIVOT) ([`RunEnd::Singular`]: an event on
    /// the signed ratio, so a step across the pole registers too) or `stop` being set. At
    /// every evaluation the pitch is put back on the constraint by one Newton step from the
    /// carried value, as the bicycle's right-hand side does
    /// ([`projected_rate`](Self::projected_rate)); the energy drift is measured at every
    /// accepted step. The implicit method's Newton iterations use
    /// the generated state Jacobian ([`jacobian`](Self::jacobian)).
    ///
    /// # Errors
    /// [`IntegrateError::Model`] with what [`Limits::check_start`] refuses (limits outside
    /// their ranges, a state not finite, the roll or the torso's lean at or beyond the fall
    /// angle, the steer at or beyond the steer lock), with [`LeanRiderError::NoUpright`] when
    /// the front wheel cannot touch the ground at the start, with
    /// [`LeanRiderError::SingularStart`] naming the pivot and its ratio when the start is at or
    /// beyond the singular configuration; the integrator's failures.
    #[allow(clippy::too_many_arguments)]
    pub fn simulate(
        &self,
        x0: [f64; 13],
        torques: &(dyn Fn(f64) -> [f64; 4] + Sync),
        joint: Joint,
        grid: &Grid,
        how: &Integration,
        limits: Limits,
        stop: &AtomicBool,
    ) -> Result<LeanRun, IntegrateError<LeanRiderError>> {
        limits.check_start(&x0).map_err(IntegrateError::Model)?;
        let Limits { fall_angle, steer_lock } = limits;
        let mut x0 = x0;
        x0[PITCH] = self
            .pitch_near(x0[3], x0[PITCH], x0[5])
            .ok_or(IntegrateError::Model(LeanRiderError::NoUpright))?;
        let ratios = self.pivot_ratios(x0[3], x0[PITCH], x0[5]);
        let margin = super::nonlinear::pivot_margin(ratios);
        if margin.is_nan() || margin <= super::nonlinear::SINGULAR_PIVOT {
            let pivot = super::nonlinear::smallest_pivot(ratios);
            return Err(IntegrateError::Model(LeanRiderError::SingularStart {
                q4: x0[3],
                q7: x0[5],
                pivot,
                ratio: ratios[pivot],
            }));
        }
        let energy0 = self.energy(&x0);
        let mut rhs = |t: f64, x: &[f64; 13]| -> Result<[f64; 13], LeanRiderError> {
            Ok(self.projected_rate(x, &torques(t), joint))
        };
        let mut jacobian = |t: f64, x: &[f64; 13]| -> Result<[[f64; 13]; 13], LeanRiderError> {
            Ok(self.jacobian(x, &torques(t), joint))
        };
        let mut roll =
            |x: &[f64; 13]| -> Result<f64, LeanRiderError> { Ok(fall_angle - x[3].abs()) };
        let mut torso =
            |x: &[f64; 13]| -> Result<f64, LeanRiderError> { Ok(fall_angle - x[7].abs()) };
        let mut steer =
            |x: &[f64; 13]| -> Result<f64, LeanRiderError> { Ok(steer_lock - x[5].abs()) };
        let mut singular = |x: &[f64; 13]| -> Result<f64, LeanRiderError> {
            let margin = super::nonlinear::pivot_margin(self.projected_pivot_ratios(x));
            Ok(margin - super::nonlinear::SINGULAR_PIVOT)
        };
        let (mut times, mut states) = (Vec::new(), Vec::new());
        let mut drift = 0.0f64;
        let mut observe = |point: Point, t: f64, x: &[f64; 13]| -> Result<(), LeanRiderError> {
            match point {
                Point::Sample(_) => {
                    times.push(t);
                    states.push(*x);
                }
                Point::Step => drift = drift.max((self.energy(x) - energy0).abs()),
                Point::Event => {}
            }
            Ok(())
        };
        let outcome = integrate_with_jacobian(
            how,
            grid,
            x0,
            &mut rhs,
            Some(&mut jacobian),
            &mut [&mut roll, &mut torso, &mut steer, &mut singular],
            &mut observe,
            stop,
        )?;
        let (t, x) = outcome.end;
        let end = match (outcome.event, outcome.interrupted) {
            (Some(c), _) if c.index == 0 => RunEnd::Fell { t: c.t },
            (Some(c), _) if c.index == 1 => RunEnd::TorsoFell { t: c.t },
            (Some(c), _) if c.index == 2 => RunEnd::SteerLock { t: c.t },
            (Some(c), _) => RunEnd::Singular {
                t: c.t,
                pivot: super::nonlinear::smallest_pivot(self.projected_pivot_ratios(&x)),
            },
            (None, true) => RunEnd::Interrupted { t },
            (None, false) => RunEnd::Completed,
        };
        Ok(LeanRun { times, states, end: (end, x), stats: outcome.stats, max_energy_drift: drift })
    }

    /// The pitch that puts the front contact on the ground at roll `q4` and steer `q7`, by
    /// Newton from `guess`; `None` when it does not converge in 50 steps.
    pub fn pitch_near(&self, q4: f64, guess: f64, q7: f64) -> Option<f64> {
        let mut th = guess;
        for _ in 0..50 {
            let (h, dh) = self.contact(q4, th, q7);
            let step = h / dh;
            th -= step;
            if !th.is_finite() {
                return None;
            }
            if step.abs() < 1e-15 {
                return Some(th);
            }
        }
        (self.contact(q4, th, q7).0.abs() < 1e-12).then_some(th)
    }

    /// The upright straight-running state at speed `speed` (m/s): everything zero but the rear
    /// wheel's rate $u_6 = -v/r_R$ and the pitch.
    pub fn upright(&self, speed: f64) -> [f64; 13] {
        let mut x = [0.0; 13];
        x[9] = -speed / self.params.get("rr").expect("rr");
        x[PITCH] = self.lam;
        x
    }

    /// $A$ ($12 \times 12$, Moore's state order) and $B$ ($12 \times 3$, inputs $T_4, T_7, T_9$)
    /// of the linearisation about upright straight running at `speed` (m/s), the pitch held
    /// at its upright value: dual numbers through `generated/lean_rider.ir` and the solve.
    pub fn state_space(&self, speed: f64) -> (SMatrix<f64, 12, 12>, SMatrix<f64, 12, 3>) {
        const N: usize = 15;
        let prog = program();
        let x0 = self.upright(speed);
        let x: [Dual<N>; 12] = std::array::from_fn(|k| Dual::variable(x0[k], k));
        // The inputs of INPUT_ORDER: the states, the pitch held upright, T4, T6 (held at zero:
        // B is over BicycleParameters' inputs), T7, T9.
        let (zero, var) = (Dual::constant(0.0), |k| Dual::variable(0.0, k));
        let values = [
            x[3],
            Dual::constant(self.lam),
            x[5],
            x[7],
            x[8],
            x[9],
            x[10],
            x[11],
            var(12),
            zero,
            var(13),
            var(14),
        ];
        let params: Vec<Dual<N>> = prog
            .params
            .iter()
            .map(|name| {
                Dual::constant(if name == "lam" {
                    self.lam
                } else {
                    self.params.get(name).expect("every parameter of the program is Moore's")
                })
            })
            .collect();
        let inputs: Vec<Dual<N>> = prog
            .inputs
            .iter()
            .map(|n| {
                values[INPUT_ORDER.iter().position(|m| m == n).expect("an input of the model")]
            })
            .collect();
        let out = dual::eval(prog, &params, &inputs).expect("the committed program evaluates");
        let o: [Dual<N>; 19] = std::array::from_fn(|k| {
            let name = dynamics_scene::OUTPUTS[k];
            let i = prog.outputs.iter().position(|p| p.name == name).expect("the scene's output");
            out[i]
        });
        let d = assemble(&o, &x);
        let a = SMatrix::<f64, 12, 12>::from_fn(|i, j| d[i].grad[j]);
        let b = SMatrix::<f64, 12, 3>::from_fn(|i, j| d[i].grad[12 + j]);
        (a, b)
    }

    /// The six eigenvalues of roll, steer and lean at `speed` (m/s) — those of $A$ on
    /// [`LATERAL`]; the other six of $A$ are zero — sorted by decreasing real part, then by
    /// decreasing imaginary part.
    pub fn eigenvalues(&self, speed: f64) -> [Complex<f64>; 6] {
        self.closed_loop_eigenvalues(speed, &LeanGains::default())
    }

    /// The six eigenvalues of roll, steer and lean under the feedback `k` ($A - BK$ on
    /// [`LATERAL`]), sorted as [`eigenvalues`](Self::eigenvalues).
    pub fn closed_loop_eigenvalues(&self, speed: f64, k: &LeanGains) -> [Complex<f64>; 6] {
        let (a, b) = self.state_space(speed);
        let lateral = SMatrix::<f64, 6, 6>::from_fn(|i, j| {
            a[(LATERAL[i], LATERAL[j])]
                - (0..3).map(|r| b[(LATERAL[i], r)] * k.0[r][j]).sum::<f64>()
        });
        let mut ev: Vec<Complex<f64>> = lateral.complex_eigenvalues().iter().copied().collect();
        ev.sort_by(|p, q| q.re.total_cmp(&p.re).then(q.im.total_cmp(&p.im)));
        std::array::from_fn(|k| ev[k])
    }

    /// The speed ranges within `[lo, hi]` (m/s) where all six eigenvalues have negative real
    /// parts: a scan at `steps` equal steps, each change of stability then bisected to
    /// $10^{-10}$ m/s. Empty when no speed of the scan is stable (Browser + Jason's passive
    /// torso, $k_9 = c_9 = 0$).
    pub fn stable_speeds(&self, lo: f64, hi: f64, steps: usize) -> Vec<(f64, f64)> {
        self.closed_loop_stable_speeds(lo, hi, steps, &LeanGains::default())
    }

    /// As [`stable_speeds`](Self::stable_speeds) under the feedback `k`.
    pub fn closed_loop_stable_speeds(
        &self,
        lo: f64,
        hi: f64,
        steps: usize,
        k: &LeanGains,
    ) -> Vec<(f64, f64)> {
        let growth = |v: f64| self.closed_loop_eigenvalues(v, k)[0].re;
        let stable = |v: f64| growth(v) < 0.0;
        let edge = |mut a: f64, mut b: f64| {
            let sa = stable(a);
            while b - a > 1e-10 {
                let m = 0.5 * (a + b);
                if stable(m) == sa {
                    a = m;
                } else {
                    b = m;
                }
            }
            0.5 * (a + b)
        };
        let steps = steps.max(1);
        let at = |k: usize| lo + (hi - lo) * k as f64 / steps as f64;
        let mut out = Vec::new();
        let mut start = stable(lo).then_some(lo);
        for k in 1..=steps {
            let (a, b) = (at(k - 1), at(k));
            match (start, stable(b)) {
                (None, true) => start = Some(edge(a, b)),
                (Some(s), false) => {
                    out.push((s, edge(a, b)));
                    start = None;
                }
                _ => {}
            }
        }
        if let Some(s) = start {
            out.push((s, hi));
        }
        out
    }
}

/// A transfer function of the leaning rider at one speed: from the roll, steer or lean torque
/// (`input` 0, 1, 2: T4, T7, T9) to a lateral state (`output`, [`LeanGains::STATES`] order:
/// roll, steer, the torso's lean and their rates), $G(s) = e^\top (sI - A)^{-1} b$ on the six
/// lateral states.
///
/// The numerator $N(s) = e^\top \operatorname{adj}(sI - A)\, b$ comes from the
/// Faddeev–LeVerrier recursion ($\operatorname{adj}(sI - A) = \sum_k M_k s^{5-k}$), its roots
/// (the zeros) from the eigenvalues of its companion matrix, the poles are the open-loop
/// eigenvalues; $G(i\omega)$ itself is a complex LU solve. The phase is the bicycle's: a
/// function of $\omega$ alone, on the branch the zeros and poles choose
/// ([`transfer`](super::transfer)'s module docs).
#[derive(Clone, Debug)]
pub struct LeanTransfer {
    a: SMatrix<f64, 6, 6>,
    b: SVector<f64, 6>,
    output: usize,
    /// The numerator's coefficients of $s^0, \dots, s^5$.
    pub numerator: [f64; 6],
    /// The zeros (roots of the numerator, of the degree its leading coefficient above
    /// $10^{-12}$ of the largest gives).
    pub zeros: Vec<Complex<f64>>,
    /// The poles (the six eigenvalues).
    pub poles: [Complex<f64>; 6],
}

impl LeanTransfer {
    /// $G(i\omega)$: real and imaginary parts.
    pub fn at(&self, omega: f64) -> (f64, f64) {
        let m = SMatrix::<Complex<f64>, 6, 6>::from_fn(|i, j| {
            let d = if i == j { Complex::new(0.0, omega) } else { Complex::new(0.0, 0.0) };
            d - Complex::new(self.a[(i, j)], 0.0)
        });
        let rhs = SVector::<Complex<f64>, 6>::from_fn(|i, _| Complex::new(self.b[i], 0.0));
        match m.lu().solve(&rhs) {
            Some(x) => (x[self.output].re, x[self.output].im),
            None => (f64::NAN, f64::NAN),
        }
    }

    /// $|G(i\omega)|$ in decibels.
    pub fn magnitude_db(&self, omega: f64) -> f64 {
        let (re, im) = self.at(omega);
        20.0 * re.hypot(im).log10()
    }

    /// The phase of $G(i\omega)$ (degrees), continuous in $\omega$, in $(-180°, 180°]$ as
    /// $\omega \to 0^+$.
    pub fn phase_deg(&self, omega: f64) -> f64 {
        let lead = self.numerator[self.zeros.len()];
        super::transfer::phase_on_branch(
            self.at(omega),
            &self.zeros,
            &self.poles,
            lead < 0.0,
            omega,
        )
    }
}

impl LeanRider {
    /// The transfer function from torque `input` (0 roll, 1 steer, 2 lean) to the lateral state
    /// `output` (0–5: roll, steer, lean, their rates) at `speed` (m/s); `None` for an index out
    /// of range.
    pub fn transfer(&self, speed: f64, input: usize, output: usize) -> Option<LeanTransfer> {
        if input >= 3 || output >= 6 {
            return None;
        }
        let (a12, b12) = self.state_space(speed);
        let a = SMatrix::<f64, 6, 6>::from_fn(|i, j| a12[(LATERAL[i], LATERAL[j])]);
        let b = SVector::<f64, 6>::from_fn(|i, _| b12[(LATERAL[i], input)]);
        // Faddeev–LeVerrier: M_1 = I, c_5 = -tr(A); M_k = A M_{k-1} + c_{6-k+1} I.
        let mut numerator = [0.0; 6];
        let mut m = SMatrix::<f64, 6, 6>::identity();
        for k in 1..=6 {
            numerator[6 - k] = (m.row(output) * b)[0];
            let am = a * m;
            let c = -am.trace() / k as f64;
            m = am + SMatrix::<f64, 6, 6>::identity() * c;
        }
        let largest = numerator.iter().fold(0.0f64, |x, y| x.max(y.abs()));
        let degree = (0..6).rev().find(|&k| numerator[k].abs() > 1e-12 * largest).unwrap_or(0);
        let zeros = if degree == 0 {
            Vec::new()
        } else {
            let companion = DMatrix::<f64>::from_fn(degree, degree, |i, j| {
                if i == 0 {
                    -numerator[degree - 1 - j] / numerator[degree]
                } else if j + 1 == i {
                    1.0
                } else {
                    0.0
                }
            });
            companion.complex_eigenvalues().iter().copied().collect()
        };
        let poles = {
            let mut p: Vec<Complex<f64>> = a.complex_eigenvalues().iter().copied().collect();
            p.sort_by(|x, y| y.re.total_cmp(&x.re).then(y.im.total_cmp(&x.im)));
            std::array::from_fn(|k| p[k])
        };
        Some(LeanTransfer { a, b, output, numerator, zeros, poles })
    }

    /// The points of the transfer function from torque `input` to the lateral state `output`
    /// ([`transfer`](Self::transfer)) at `speed` and each of `omegas`: magnitude in dB, phase in
    /// degrees; `None` for an index out of range.
    pub fn frequency_response(
        &self,
        speed: f64,
        omegas: &[f64],
        input: usize,
        output: usize,
    ) -> Option<Vec<super::transfer::FrequencyPoint>> {
        let g = self.transfer(speed, input, output)?;
        Some(
            omegas
                .iter()
                .map(|&omega| {
                    let (re, im) = g.at(omega);
                    super::transfer::FrequencyPoint {
                        speed,
                        omega,
                        re,
                        im,
                        magnitude_db: 20.0 * re.hypot(im).log10(),
                        phase_deg: g.phase_deg(omega),
                    }
                })
                .collect(),
        )
    }
}
