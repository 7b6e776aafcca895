//! The two-wheeled inverted pendulum (a self-balancing robot or personal transporter): a
//! rolling system that is not a bicycle, derived by the mechanics engine from its description
//! (`codegen/src/derive/wheeled_pendulum/mod.rs`, Kane's method checked by Carvallo's modified
//! Lagrange equations; `generated/wheeled_pendulum.ir`).
//!
//! Two equal wheels (radius $r$, mass $m_W$, moments $I_{Wd}$ about a diameter and $I_{Wa}$
//! about the axle) on one axle of length $W$ between the wheel centres carry a body (mass
//! $m_B$, centre at $l$ above the axle's midpoint, principal moments $I_{Bxx}$, $I_{Byy}$,
//! $I_{Bzz}$) that pitches about the axle by $\theta$ (zero upright, positive forward, the
//! benchmark's axes: x forward, y right, z down). A motor in each hub applies the torque
//! $T_L$ or $T_R$ to its wheel about the axle, and the reaction to the body. The wheels'
//! rates $\dot\theta_L$, $\dot\theta_R$ are relative to the body; on flat ground the axle's
//! lean stays zero, so the independent speeds are $u = (\dot\theta, \dot\theta_L,
//! \dot\theta_R)$ and Kane's equations $M(\theta)\,\dot u = f(\theta, u, T)$ give their rates;
//! the heading rate $\dot\psi$ and the left contact's velocity $(P_u, P_v)$ on the yawed axes
//! follow from the rolling constraints.
//!
//! * [`WheeledPendulumParams`]: the eleven parameters, validated, with illustrative nominal
//!   values ([`WheeledPendulumParams::nominal`]);
//! * [`WheeledPendulum`]: the model's evaluators ([`rate`](WheeledPendulum::rate),
//!   [`energy`](WheeledPendulum::energy)), the linear model about upright straight running
//!   ([`linear`]) and the nonlinear simulation ([`simulation`]).

pub mod linear;
pub mod simulation;

use std::fmt;

use nalgebra::{Matrix3, Vector3};

use crate::error::ParameterError;

pub use linear::{Feedback, LinearModel};
pub use simulation::{Trajectory, FALL_ANGLE, STATE_NAMES};

crate::scene! {
    /// Kane's equations ($M$, $f$), the heading rate and the left contact's velocity on the
    /// yawed axes: everything the right-hand side needs (evaluated on flat ground, the lean
    /// $\phi = 0$).
    pub mod dynamics_scene {
        model: wheeled_pendulum,
        outputs: [M_thetad_thetad, M_thetad_thetaLd, M_thetad_thetaRd, M_thetaLd_thetaLd,
                  M_thetaLd_thetaRd, M_thetaRd_thetaRd, f_thetad, f_thetaLd, f_thetaRd,
                  psid, P_u, P_v],
    }
}

crate::scene! {
    /// The total energy (kinetic plus gravity's potential): conserved when the motors are off,
    /// what a simulation's drift is measured by.
    pub mod energy_scene {
        model: wheeled_pendulum,
        outputs: [energy],
    }
}

crate::scene! {
    /// The linearisation about upright straight running at speed $v$: $M$, the forcing's
    /// derivatives in the pitch (`lin_fq_*`), the speeds (`lin_fu_*`) and the motor torques
    /// (`lin_fT_*`).
    pub mod linear_scene {
        model: wheeled_pendulum,
        outputs: [lin_M_thetad_thetad, lin_M_thetad_thetaLd, lin_M_thetad_thetaRd,
                  lin_M_thetaLd_thetaLd, lin_M_thetaLd_thetaRd, lin_M_thetaRd_thetaRd,
                  lin_fq_thetad, lin_fu_thetad_thetad, lin_fu_thetad_thetaLd,
                  lin_fu_thetad_thetaRd, lin_fT_thetad_TL, lin_fT_thetad_TR,
                  lin_fq_thetaLd, lin_fu_thetaLd_thetad, lin_fu_thetaLd_thetaLd,
                  lin_fu_thetaLd_thetaRd, lin_fT_thetaLd_TL, lin_fT_thetaLd_TR,
                  lin_fq_thetaRd, lin_fu_thetaRd_thetad, lin_fu_thetaRd_thetaLd,
                  lin_fu_thetaRd_thetaRd, lin_fT_thetaRd_TL, lin_fT_thetaRd_TR],
    }
}

/// What is wrong with a parameter set, a setting or a request.
#[derive(Clone, Debug, PartialEq)]
pub enum WheeledPendulumError {
    /// A value the model does not allow.
    Parameter(ParameterError),
    /// A parameter name the model does not have.
    Unknown {
        /// The name.
        name: String,
    },
    /// The requested poles cannot be placed: the pitch and forward motion are not
    /// controllable from the motors at this design and speed.
    Uncontrollable {
        /// The speed (m/s).
        speed: f64,
    },
}

impl From<ParameterError> for WheeledPendulumError {
    fn from(e: ParameterError) -> Self {
        WheeledPendulumError::Parameter(e)
    }
}

impl fmt::Display for WheeledPendulumError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WheeledPendulumError::Parameter(e) => write!(f, "{e}"),
            WheeledPendulumError::Unknown { name } => write!(
                f,
                "unknown parameter {name:?}: the wheeled pendulum has {}",
                WheeledPendulumParams::NAMES.join(", ")
            ),
            WheeledPendulumError::Uncontrollable { speed } => write!(
                f,
                "the pitch and forward motion are not controllable from the motors at {speed} m/s"
            ),
        }
    }
}

impl std::error::Error for WheeledPendulumError {}

/// The model's eleven parameters by name ([`NAMES`](Self::NAMES)), validated.
///
/// # Example
/// ```
/// use carvallo::wheeled_pendulum::WheeledPendulumParams;
///
/// let p = WheeledPendulumParams::nominal().with("mB", 70.0)?;
/// assert_eq!(p.get("mB"), Some(70.0));
/// assert!(p.with("l", -0.9).is_err());
/// # Ok::<(), carvallo::wheeled_pendulum::WheeledPendulumError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WheeledPendulumParams {
    values: [f64; 11],
}

impl WheeledPendulumParams {
    /// The names, the generated program's order: the wheel radius `r` (m), the axle length `W`
    /// between the wheel centres (m), a wheel's mass `mW` (kg) and its moments `IWd` about a
    /// diameter and `IWa` about the axle (kg m²), the height `l` of the body's centre above
    /// the axle (m), the body's mass `mB` (kg) and principal moments `IBxx`, `IByy` (about
    /// the axle's direction) and `IBzz` (kg m²), and gravity `g` (m/s²).
    pub const NAMES: [&'static str; 11] =
        ["r", "W", "mW", "IWd", "IWa", "l", "mB", "IBxx", "IByy", "IBzz", "g"];

    /// A personal transporter with its rider: illustrative values of that size, not a
    /// published data set (the model's nominal values in `codegen/src/derive/nominal.rs`, at
    /// which its generated program is checked): $r = 0.24$ m, $W = 0.58$ m, $m_W = 4$ kg,
    /// $I_{Wd} = 0.06$, $I_{Wa} = 0.12$ kg m², $l = 0.9$ m, $m_B = 90$ kg, $I_{Bxx} = 12$,
    /// $I_{Byy} = 12.5$, $I_{Bzz} = 1.5$ kg m², $g = 9.81$ m/s².
    pub fn nominal() -> WheeledPendulumParams {
        WheeledPendulumParams {
            values: [0.24, 0.58, 4.0, 0.06, 0.12, 0.9, 90.0, 12.0, 12.5, 1.5, 9.81],
        }
    }

    /// The values in [`NAMES`](Self::NAMES) order, checked: every value finite and positive
    /// (the body's centre above the axle: $l > 0$, an inverted pendulum); the moments of each
    /// body those of a mass distribution, each at most the sum of the other two ($I_{Wa} \le
    /// 2 I_{Wd}$ for a wheel of revolution; $I_{Bxx} \le I_{Byy} + I_{Bzz}$ and cyclically),
    /// reported on the moment that breaks it.
    ///
    /// # Errors
    /// [`WheeledPendulumError::Parameter`] naming the first bad value.
    pub fn new(values: [f64; 11]) -> Result<WheeledPendulumParams, WheeledPendulumError> {
        for (&name, &value) in Self::NAMES.iter().zip(&values) {
            ParameterError::check_positive(name, value)?;
        }
        let [_, _, _, iwd, iwa, _, _, ixx, iyy, izz, _] = values;
        let triangle = "must not exceed the sum of the other two moments";
        for (name, value, others) in [
            ("IWa", iwa, 2.0 * iwd),
            ("IBxx", ixx, iyy + izz),
            ("IByy", iyy, izz + ixx),
            ("IBzz", izz, ixx + iyy),
        ] {
            if value > others {
                return Err(
                    ParameterError::InvalidParameter { name, value, reason: triangle }.into()
                );
            }
        }
        Ok(WheeledPendulumParams { values })
    }

    /// The value of `name`, or `None` for a name the model does not have.
    pub fn get(&self, name: &str) -> Option<f64> {
        Self::NAMES.iter().position(|n| *n == name).map(|k| self.values[k])
    }

    /// The values, [`NAMES`](Self::NAMES) order.
    pub fn values(&self) -> &[f64; 11] {
        &self.values
    }

    /// The same set with `name` set to `value`.
    ///
    /// # Errors
    /// [`WheeledPendulumError::Unknown`] for a name the model does not have, and as
    /// [`new`](Self::new).
    pub fn with(
        &self,
        name: &str,
        value: f64,
    ) -> Result<WheeledPendulumParams, WheeledPendulumError> {
        let k = Self::NAMES
            .iter()
            .position(|n| *n == name)
            .ok_or_else(|| WheeledPendulumError::Unknown { name: name.to_string() })?;
        let mut values = self.values;
        values[k] = value;
        WheeledPendulumParams::new(values)
    }
}

impl Default for WheeledPendulumParams {
    fn default() -> Self {
        WheeledPendulumParams::nominal()
    }
}

/// The wheeled pendulum at one design: the generated evaluators with its parameters.
///
/// # Example
/// ```
/// use carvallo::wheeled_pendulum::{WheeledPendulum, WheeledPendulumParams};
///
/// let m = WheeledPendulum::new(WheeledPendulumParams::nominal());
/// // Upright, the body's pitch grows at the real eigenvalue λ ≈ 6.1 1/s.
/// let lambda = m.linear(2.0).eigenvalues()[0].re;
/// assert!((lambda - 6.12).abs() < 0.01, "{lambda}");
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WheeledPendulum {
    params: WheeledPendulumParams,
}

impl WheeledPendulum {
    /// The model with the parameters `params`.
    pub fn new(params: WheeledPendulumParams) -> WheeledPendulum {
        WheeledPendulum { params }
    }

    /// The parameters.
    pub fn params(&self) -> &WheeledPendulumParams {
        &self.params
    }

    /// A parameter by name (one of [`WheeledPendulumParams::NAMES`]; the program's argument
    /// names are the same).
    fn param(&self, name: &str) -> f64 {
        self.params.get(name).unwrap_or(f64::NAN)
    }

    /// The wheel radius $r$ (m).
    pub fn radius(&self) -> f64 {
        self.params.values[0]
    }

    /// The upright straight-running state at `speed` (m/s), [`STATE_NAMES`] order: at the
    /// origin heading along x, both wheels turning at $-v/r$ relative to the (upright, still)
    /// body.
    pub fn upright(&self, speed: f64) -> [f64; 7] {
        let w = -speed / self.radius();
        [0.0, 0.0, 0.0, 0.0, 0.0, w, w]
    }

    /// The rates of the state `x` ([`STATE_NAMES`]: $x, y, \psi, \theta, \dot\theta,
    /// \dot\theta_L, \dot\theta_R$) under the motor torques `torques` $(T_L, T_R)$ (N m):
    /// the left contact's velocity turned from the yawed axes to the ground's, the heading
    /// rate, the pitch rate and $\dot u = M^{-1} f$ (a Cholesky solve; LU when $M$ is not
    /// numerically positive definite).
    pub fn rate(&self, x: &[f64; 7], torques: [f64; 2]) -> [f64; 7] {
        let o = dynamics_scene::eval(&dynamics_scene::Args::from_fn(|name| match name {
            "theta" => x[3],
            "thetad" => x[4],
            "thetaLd" => x[5],
            "thetaRd" => x[6],
            "TL" => torques[0],
            "TR" => torques[1],
            "phi" | "v" => 0.0,
            p => self.param(p),
        }));
        let m = Matrix3::new(
            o.M_thetad_thetad,
            o.M_thetad_thetaLd,
            o.M_thetad_thetaRd,
            o.M_thetad_thetaLd,
            o.M_thetaLd_thetaLd,
            o.M_thetaLd_thetaRd,
            o.M_thetad_thetaRd,
            o.M_thetaLd_thetaRd,
            o.M_thetaRd_thetaRd,
        );
        let f = Vector3::new(o.f_thetad, o.f_thetaLd, o.f_thetaRd);
        let ud = match m.cholesky() {
            Some(c) => c.solve(&f),
            None => m.lu().solve(&f).unwrap_or_else(|| Vector3::repeat(f64::NAN)),
        };
        let (s, c) = x[2].sin_cos();
        [o.P_u * c - o.P_v * s, o.P_u * s + o.P_v * c, o.psid, x[4], ud[0], ud[1], ud[2]]
    }

    /// The total energy (J) of the state `x` ([`STATE_NAMES`]): kinetic plus gravity's
    /// potential, zero at ground level.
    pub fn energy(&self, x: &[f64; 7]) -> f64 {
        energy_scene::eval(&energy_scene::Args::from_fn(|name| match name {
            "theta" => x[3],
            "thetad" => x[4],
            "thetaLd" => x[5],
            "thetaRd" => x[6],
            "phi" | "TL" | "TR" | "v" => 0.0,
            p => self.param(p),
        }))
        .energy
    }
}
