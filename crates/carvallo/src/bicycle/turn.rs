//! Stability of a steady turn with the handlebar held fixed (memoir Part II, ch. IV,
//! n° 99–105), computed exactly on Carvallo's bicycle as a parameter set of the nonlinear
//! Carvallo–Whipple model ([`crate::whipple::nonlinear`], Kane's method, with the mapping of
//! [`Constants::whipple_values`]: hoop wheels, massless fork and handlebar, trail
//! $c_1/\cos\eta$, $\theta = \varphi$, $\gamma = -\delta$).
//!
//! **The steady turn.** With the handlebar held at γ (steer δ = −γ), lean rate and steer
//! rate zero and the rear contact rolling at the speed $v = Rs$, the lean θ₀ solves the lean
//! row of $M_3\dot u = f_3$ with $\dot u = 0$ (Newton's method, the pitch solved from the
//! front contact at every step). The steer row then gives the torque the hands must supply;
//! the rear-wheel row needs no pedal torque (the steer does no work and the energy is
//! constant), which [`SteadyTurn::pedal_torque`] records as a check. The yaw rate is reported
//! in Carvallo's sign, $n = -\dot\psi$.
//!
//! **The fall equation (C) of n° 101.** Carvallo's $f(\theta, p, p')$ is the lean row with the
//! handlebar held (the steer row is dropped: the hands supply whatever torque it asks) and
//! his rolling speed $s$ held by the pedals (the rear-wheel row is dropped too). His $s$ is
//! the rolling of the rear wheel on the ground, $\sigma + \eta$ the rolling on the bearings
//! (n° 68); in the model the rear contact's speed is $-r_R(\dot\theta + \dot\theta_R)$, with
//! $\dot\theta_R$ the wheel's rate on the frame (the bearings) and $\dot\theta$ the frame's
//! pitch rate, so holding $s$ makes the bearing rate a function $U(\theta, p)$ of the lean
//! and its rate. Then, with $M_3$, $f_3$ the generated terms,
//! $f = (M_{11} + M_{13}U_p)\,p' + M_{13}U_\theta\,p - f_{3,1}(\theta, p, U(\theta, p))$
//! and $df/dp' = M_{11} + M_{13}U_p$ exactly, $df/dp$ and $df/d\theta$ by central differences
//! refined by Richardson's extrapolation (steps [`STEP_LEAN`], [`STEP_RATE`] and their
//! halves; the difference between the two levels is the stated error estimate). Two other
//! ways of driving the wheel are computed beside it: the bearing rate held
//! ([`Hold::BearingRate`], a quadratic as well) and free-wheeling (no pedal torque, the rear
//! wheel's rate free: a cubic in λ whose constant term vanishes, because the steady turns at a
//! fixed γ form a one-parameter family in the speed).
//!
//! **Constants.** Those of n° 117 ([`Constants::MEMOIR`]); the frame's moment $B$ about its
//! pitch axis is not printed there (straight running does not need it), and the mapping sets
//! the central $I_{Bxx} + I_{Bzz}$, the largest a mass distribution allows: illustrative, like
//! the frame's moments of the steady module; [`LockedSteer::with_pitch_moment`] changes it.
//!
//! **Gravity and centrifugal parts (n° 104).** The forcing at zero speeds is the gravity
//! alone, so $df/d\theta$ splits exactly into the derivative of the gravity forcing (at the
//! same pitch law) and the rest, the centrifugal part, whose ratio to the gravity part the
//! memoir puts at $\tan^2\theta$ through (3)′ of n° 86 bis.

use std::fmt;

use nalgebra::{Complex, Matrix2, Matrix3, Vector2};

use crate::bicycle::straight::Constants;
use crate::error::ParameterError;
use crate::whipple::nonlinear::{Configuration, KaneTerms, NonlinearError, WhippleNonlinear};
use crate::whipple::{WhippleParams, PARAM_NAMES};

/// Central-difference step in the lean (rad); Richardson also uses half of it.
pub const STEP_LEAN: f64 = 1e-4;
/// Central-difference step in the lean rate and the wheel rate (rad/s); Richardson also uses
/// half of it.
pub const STEP_RATE: f64 = 1e-4;
/// Largest handlebar angle accepted, |γ| < 1 rad.
pub const MAX_GAMMA: f64 = 1.0;

/// Why a steady turn or its characteristic equation could not be computed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TurnError {
    /// An input that cannot be used.
    Parameter(ParameterError),
    /// Newton's method found no lean that balances the turn.
    NoSteadyTurn {
        /// The handlebar angle γ (rad).
        gamma: f64,
        /// The speed $Rs$ (m/s).
        speed: f64,
    },
    /// The nonlinear model failed (no contact, singular mass matrix).
    Model(NonlinearError),
}

impl fmt::Display for TurnError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TurnError::Parameter(e) => write!(f, "{e}"),
            TurnError::NoSteadyTurn { gamma, speed } => write!(
                f,
                "no steady turn with the handlebar held at gamma {gamma} rad and speed {speed} m/s"
            ),
            TurnError::Model(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for TurnError {}

impl From<NonlinearError> for TurnError {
    fn from(e: NonlinearError) -> TurnError {
        TurnError::Model(e)
    }
}

impl From<ParameterError> for TurnError {
    fn from(e: ParameterError) -> TurnError {
        TurnError::Parameter(e)
    }
}

/// What drives the rear wheel while the fall is perturbed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hold {
    /// Carvallo's choice: the rolling speed $s$ on the ground held by the pedals.
    Rolling,
    /// The wheel's rate on its bearings held (the model's $\dot\theta_R$).
    BearingRate,
}

/// A steady turn with the handlebar held.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadyTurn {
    /// Handlebar angle γ (rad); the model's steer is −γ.
    pub gamma: f64,
    /// Speed of the rear contact $v = Rs$ (m/s).
    pub speed: f64,
    /// Lean θ₀ (rad), Carvallo's sign (= the model's φ).
    pub lean: f64,
    /// Frame pitch solved from the front contact (rad).
    pub pitch: f64,
    /// Turning rate $n = -\dot\psi$ (1/s), Carvallo's sign.
    pub yaw_rate: f64,
    /// Rear wheel rate on the frame $\dot\theta_R$ (rad/s).
    pub wheel_rate: f64,
    /// Torque the hands apply to the handlebar about the steering axis, in the sense of γ
    /// (N m).
    pub hands_torque: f64,
    /// Pedal torque the turn needs (N m): zero up to rounding (energy argument), a check.
    pub pedal_torque: f64,
    /// Residual of the lean row at θ₀ (N m).
    pub lean_residual: f64,
}

/// The quadratic (C) of n° 101: $(df/dp')\lambda^2 + (df/dp)\lambda + df/d\theta = 0$.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FallEquation {
    /// What holds the rear wheel.
    pub hold: Hold,
    /// $df/dp'$ (kg m²), exact from the generated terms.
    pub dfdpp: f64,
    /// $df/dp$ (kg m²/s), by differences.
    pub dfdp: f64,
    /// $df/d\theta$ (N m), by differences.
    pub dfdtheta: f64,
    /// Gravity part of $df/d\theta$ (N m): the derivative of the forcing at zero speeds.
    pub dfdtheta_gravity: f64,
    /// Largest error estimate of the differences (Richardson levels), in the unit of each.
    pub error: f64,
    /// The two roots λ (1/s).
    pub roots: [Complex<f64>; 2],
}

impl FallEquation {
    /// The centrifugal part of $df/d\theta$: the whole minus the gravity part (N m).
    pub fn dfdtheta_centrifugal(&self) -> f64 {
        self.dfdtheta - self.dfdtheta_gravity
    }

    /// True when the roots are real and of opposite signs (n° 105's conclusion).
    pub fn saddle(&self) -> bool {
        self.roots.iter().all(|r| r.im == 0.0) && self.roots[0].re * self.roots[1].re < 0.0
    }
}

/// The free-wheeling cubic $\lambda^3 + c_2\lambda^2 + c_1\lambda + c_0$ of the lean, lean
/// rate and bearing rate with the handlebar held and no pedal torque.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FreeWheel {
    /// $[c_0, c_1, c_2]$.
    pub coefficients: [f64; 3],
    /// The three roots λ (1/s), sorted by real part.
    pub roots: [Complex<f64>; 3],
    /// Largest error estimate of the Jacobian's entries.
    pub error: f64,
}

/// Carvallo's bicycle with the handlebar held.
///
/// # Example
/// ```
/// use carvallo::bicycle::straight::Constants;
/// use carvallo::bicycle::turn::{Hold, LockedSteer};
///
/// let bike = LockedSteer::new(Constants::MEMOIR)?;
/// let turn = bike.steady_turn(5f64.to_radians(), 20.0 / 3.6)?;
/// let c = bike.fall_equation(&turn, Hold::Rolling)?;
/// assert!(c.dfdpp > 0.0 && c.dfdtheta < 0.0 && c.saddle());
/// # Ok::<(), carvallo::bicycle::turn::TurnError>(())
/// ```
#[derive(Clone, Debug)]
pub struct LockedSteer {
    k: Constants,
    bike: WhippleNonlinear,
}

/// Richardson-refined central difference of `f` at `x` with steps `h` and `h/2`: the value
/// and the difference between the two levels (the error estimate).
fn derivative(
    f: &dyn Fn(f64) -> Result<f64, TurnError>,
    x: f64,
    h: f64,
) -> Result<(f64, f64), TurnError> {
    let d1 = (f(x + h)? - f(x - h)?) / (2.0 * h);
    let d2 = (f(x + h / 2.0)? - f(x - h / 2.0)?) / h;
    Ok(((4.0 * d2 - d1) / 3.0, (d2 - d1).abs()))
}

fn quadratic_roots(a: f64, b: f64, c: f64) -> [Complex<f64>; 2] {
    let disc = b * b - 4.0 * a * c;
    if disc >= 0.0 {
        let q = -0.5 * (b + b.signum() * disc.sqrt());
        let q = if q == 0.0 { -0.5 * disc.sqrt() } else { q };
        let (r1, r2) = (q / a, c / q);
        let (lo, hi) = if r1 <= r2 { (r1, r2) } else { (r2, r1) };
        [Complex::new(lo, 0.0), Complex::new(hi, 0.0)]
    } else {
        let (re, im) = (-b / (2.0 * a), (-disc).sqrt() / (2.0 * a));
        [Complex::new(re, -im.abs()), Complex::new(re, im.abs())]
    }
}

impl LockedSteer {
    /// Carvallo's bicycle with the constants `k` (n° 117's for [`Constants::MEMOIR`]).
    ///
    /// # Errors
    /// [`ParameterError`] from [`Constants::validate`].
    pub fn new(k: Constants) -> Result<LockedSteer, ParameterError> {
        LockedSteer::build(k, None)
    }

    /// The same with the frame's central moment about its pitch axis set to `ibyy` (kg m²)
    /// instead of the mapping's $I_{Bxx} + I_{Bzz}$: the memoir prints no $B$ for the bicycle
    /// of n° 117 (it does not enter straight running), and in a turn it enters through the
    /// frame's rotation $n\sin\theta$ about its own axle direction.
    ///
    /// # Errors
    /// [`ParameterError`] from [`Constants::validate`], or `ibyy` not positive or above
    /// $I_{Bxx} + I_{Bzz}$ (the triangle inequality of a mass distribution).
    pub fn with_pitch_moment(k: Constants, ibyy: f64) -> Result<LockedSteer, ParameterError> {
        LockedSteer::build(k, Some(ibyy))
    }

    /// The same model with the constants `k` taken as they are, without
    /// [`Constants::validate`]: a perturbed bicycle for the report's falsification checks
    /// (issue 38), such as the weight reversed (`g` negative, which `validate` refuses), built
    /// as [`LockedSteer::new`] builds it. No claim of the memoir is judged on such a model; it
    /// shows that a check can fail.
    pub fn new_unchecked(k: Constants) -> LockedSteer {
        LockedSteer::assemble(k, None)
    }

    /// [`LockedSteer::with_pitch_moment`] with the constants taken as they are, as
    /// [`LockedSteer::new_unchecked`] takes them: the same perturbed bicycle with the frame's
    /// pitch moment set to `ibyy`.
    pub fn with_pitch_moment_unchecked(k: Constants, ibyy: f64) -> LockedSteer {
        LockedSteer::assemble(k, Some(ibyy))
    }

    fn build(k: Constants, ibyy: Option<f64>) -> Result<LockedSteer, ParameterError> {
        k.validate()?;
        if let Some(ibyy) = ibyy {
            let named = k.whipple_values();
            let get = |name: &str| named.iter().find(|(n, _)| *n == name).map_or(0.0, |(_, v)| *v);
            let bound = get("IBxx") + get("IBzz");
            ParameterError::check_positive("ibyy", ibyy)?;
            if ibyy > bound {
                return Err(ParameterError::InvalidParameter {
                    name: "ibyy",
                    value: ibyy,
                    reason: "exceeds the sum of the two other central moments",
                });
            }
        }
        Ok(LockedSteer::assemble(k, ibyy))
    }

    /// The model of the constants `k` (the frame's central pitch moment `ibyy` when given),
    /// without checks.
    fn assemble(k: Constants, ibyy: Option<f64>) -> LockedSteer {
        let named = k.whipple_values();
        let get = |name: &str| named.iter().find(|(n, _)| *n == name).map_or(0.0, |(_, v)| *v);
        let mut values: [f64; 26] = std::array::from_fn(|i| get(PARAM_NAMES[i]));
        if let (Some(ibyy), Some(i)) = (ibyy, PARAM_NAMES.iter().position(|n| *n == "IByy")) {
            values[i] = ibyy;
        }
        let bike = WhippleNonlinear::new(WhippleParams::from_values_unchecked(values));
        LockedSteer { k, bike }
    }

    /// The constants.
    pub fn constants(&self) -> &Constants {
        &self.k
    }

    /// The nonlinear model these constants make (massless front frame).
    pub fn model(&self) -> &WhippleNonlinear {
        &self.bike
    }

    /// Pitch and the generated terms at lean `lean`, steer −`gamma` and speeds
    /// `(lean rate, 0, bearing rate)`.
    fn terms(
        &self,
        lean: f64,
        gamma: f64,
        lean_rate: f64,
        wheel_rate: f64,
    ) -> Result<(KaneTerms, f64), TurnError> {
        let pitch = self.bike.pitch(lean, -gamma, 0.0)?;
        let c = Configuration {
            lean,
            pitch,
            steer: -gamma,
            lean_rate,
            steer_rate: 0.0,
            rear_wheel_rate: wheel_rate,
        };
        Ok((self.bike.kane_terms(&c), pitch))
    }

    /// The bearing rate $U$ that gives the rear contact the speed `speed` at lean `lean` and
    /// lean rate `lean_rate` (the rear contact speed is linear in the speeds).
    fn rolling_wheel_rate(
        &self,
        lean: f64,
        gamma: f64,
        lean_rate: f64,
        speed: f64,
    ) -> Result<f64, TurnError> {
        let (t, _) = self.terms(lean, gamma, lean_rate, 0.0)?;
        let a = t.rates[0];
        Ok((-speed / self.k.r - a[0] * lean_rate) / (1.0 + a[2]))
    }

    fn check_inputs(gamma: f64, speed: f64) -> Result<(), TurnError> {
        if !gamma.is_finite() {
            return Err(TurnError::Parameter(ParameterError::InvalidParameter {
                name: "gamma",
                value: gamma,
                reason: "must be finite",
            }));
        }
        if gamma.abs() >= MAX_GAMMA {
            return Err(TurnError::Parameter(ParameterError::InvalidParameter {
                name: "gamma",
                value: gamma,
                reason: "must lie strictly between -1 and 1 rad",
            }));
        }
        if !speed.is_finite() {
            return Err(TurnError::Parameter(ParameterError::InvalidParameter {
                name: "speed",
                value: speed,
                reason: "must be finite",
            }));
        }
        if speed < 0.0 {
            return Err(TurnError::Parameter(ParameterError::InvalidParameter {
                name: "speed",
                value: speed,
                reason: "must not be negative",
            }));
        }
        Ok(())
    }

    /// The steady turn at handlebar angle `gamma` (rad) and speed `speed` $= Rs$ (m/s), by
    /// Newton's method on the lean from the first-order guess
    /// $\tan\theta = -(v^2/gl)\tan(\gamma\cos\eta)$ (at most 60 steps of at most 0.2 rad, until
    /// the step is below 1e-13 rad; the derivative by a central difference of [`STEP_LEAN`]).
    ///
    /// # Errors
    /// [`TurnError::Parameter`] for a non-finite or out-of-range γ ([`MAX_GAMMA`]) or a
    /// negative or non-finite speed; [`TurnError::NoSteadyTurn`] when Newton's method does not
    /// converge to a lean below 1.4 rad or the front wheel leaves the ground on the way.
    pub fn steady_turn(&self, gamma: f64, speed: f64) -> Result<SteadyTurn, TurnError> {
        Self::check_inputs(gamma, speed)?;
        let k = &self.k;
        let none = TurnError::NoSteadyTurn { gamma, speed };
        let residual = |lean: f64| -> Result<f64, TurnError> {
            let u3 = self.rolling_wheel_rate(lean, gamma, 0.0, speed)?;
            Ok(self.terms(lean, gamma, 0.0, u3)?.0.forcing[0])
        };
        let mut lean = (-(speed * speed) / (k.g * k.l) * (gamma * k.eta.cos()).tan()).atan();
        let mut converged = false;
        for _ in 0..60 {
            let r = residual(lean).map_err(|_| none)?;
            let (d, _) = derivative(&residual, lean, STEP_LEAN).map_err(|_| none)?;
            let step = (r / d).clamp(-0.2, 0.2);
            if !step.is_finite() {
                return Err(none);
            }
            lean -= step;
            if lean.abs() > 1.4 {
                return Err(none);
            }
            if step.abs() < 1e-13 {
                converged = true;
                break;
            }
        }
        if !converged {
            return Err(none);
        }
        let u3 = self.rolling_wheel_rate(lean, gamma, 0.0, speed)?;
        let (t, pitch) = self.terms(lean, gamma, 0.0, u3)?;
        let yaw = t.rates[1][2] * u3;
        Ok(SteadyTurn {
            gamma,
            speed,
            lean,
            pitch,
            yaw_rate: -yaw,
            wheel_rate: u3,
            hands_torque: t.forcing[1],
            pedal_torque: -t.forcing[2],
            lean_residual: t.forcing[0],
        })
    }

    /// The characteristic equation (C) of n° 101 about the steady turn `turn`, the rear wheel
    /// held as `hold` says.
    ///
    /// # Errors
    /// [`TurnError::Model`] when the model fails near the turn (a lean at the edge of contact).
    pub fn fall_equation(&self, turn: &SteadyTurn, hold: Hold) -> Result<FallEquation, TurnError> {
        let (g, v, th0) = (turn.gamma, turn.speed, turn.lean);
        let u3_star = turn.wheel_rate;
        let wheel = |lean: f64, p: f64| -> Result<f64, TurnError> {
            match hold {
                Hold::Rolling => self.rolling_wheel_rate(lean, g, p, v),
                Hold::BearingRate => Ok(u3_star),
            }
        };
        let forcing = |lean: f64, p: f64| -> Result<f64, TurnError> {
            Ok(self.terms(lean, g, p, wheel(lean, p)?)?.0.forcing[0])
        };
        let (t, _) = self.terms(th0, g, 0.0, u3_star)?;
        let (m11, m13) = (t.mass[0][0], t.mass[0][2]);
        let a = t.rates[0];
        let (u_p, u_theta, e_u) = match hold {
            Hold::Rolling => {
                let (d, e) = derivative(&|x| wheel(x, 0.0), th0, STEP_LEAN)?;
                (-a[0] / (1.0 + a[2]), d, e)
            }
            Hold::BearingRate => (0.0, 0.0, 0.0),
        };
        let (df_p, e_p) = derivative(&|p| forcing(th0, p), 0.0, STEP_RATE)?;
        let (df_th, e_th) = derivative(&|x| forcing(x, 0.0), th0, STEP_LEAN)?;
        let gravity = |lean: f64| -> Result<f64, TurnError> {
            Ok(self.terms(lean, g, 0.0, 0.0)?.0.forcing[0])
        };
        let (dg_th, e_g) = derivative(&gravity, th0, STEP_LEAN)?;
        let dfdpp = m11 + m13 * u_p;
        let dfdp = m13 * u_theta - df_p;
        let dfdtheta = -df_th;
        Ok(FallEquation {
            hold,
            dfdpp,
            dfdp,
            dfdtheta,
            dfdtheta_gravity: -dg_th,
            error: e_p.max(e_th).max(e_g).max(m13.abs() * e_u),
            roots: quadratic_roots(dfdpp, dfdp, dfdtheta),
        })
    }

    /// The free-wheeling cubic about `turn`: the lean and rear-wheel rows with the steer row
    /// dropped, states (lean, lean rate, bearing rate), Jacobian by Richardson differences.
    ///
    /// # Errors
    /// [`TurnError::Model`] when the model fails near the turn.
    pub fn free_wheel(&self, turn: &SteadyTurn) -> Result<FreeWheel, TurnError> {
        let g = turn.gamma;
        let x0 = [turn.lean, 0.0, turn.wheel_rate];
        let rhs =
            |x: [f64; 3]| -> Result<[f64; 3], TurnError> {
                let (t, _) = self.terms(x[0], g, x[1], x[2])?;
                let m = Matrix2::new(t.mass[0][0], t.mass[0][2], t.mass[0][2], t.mass[2][2]);
                let f = Vector2::new(t.forcing[0], t.forcing[2]);
                let ud = m.lu().solve(&f).ok_or(TurnError::Model(
                    NonlinearError::SingularMassMatrix { lean: x[0], steer: -g },
                ))?;
                Ok([x[1], ud[0], ud[1]])
            };
        let mut jac = Matrix3::zeros();
        let mut error = 0.0f64;
        for col in 0..3 {
            let h = if col == 0 { STEP_LEAN } else { STEP_RATE };
            for row in 0..3 {
                let f = |s: f64| -> Result<f64, TurnError> {
                    let mut x = x0;
                    x[col] = s;
                    Ok(rhs(x)?[row])
                };
                let (d, e) = derivative(&f, x0[col], h)?;
                jac[(row, col)] = d;
                error = error.max(e);
            }
        }
        let tr = jac.trace();
        let minors = (0..3)
            .map(|i| {
                let (a, b) = ((i + 1) % 3, (i + 2) % 3);
                jac[(a, a)] * jac[(b, b)] - jac[(a, b)] * jac[(b, a)]
            })
            .sum::<f64>();
        let det = jac.determinant();
        let mut roots: Vec<Complex<f64>> = jac.complex_eigenvalues().iter().copied().collect();
        roots.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
        Ok(FreeWheel {
            coefficients: [-det, minors, -tr],
            roots: [roots[0], roots[1], roots[2]],
            error,
        })
    }

    /// The memoir's first-order lean of a steady turn, (3)′ of n° 86 bis:
    /// $\tan\theta = -(R/l)(Rs^2/g)\tan\alpha$ with $\tan\alpha$ of n° 57 at θ (η the steering
    /// axis's angle with the vertical): the root nearest to upright, found by scanning from
    /// θ = 0 towards the side of −γ in steps of 1e-3 rad and bisecting the first sign change;
    /// `None` when there is none before ±1.5 rad.
    pub fn memoir_lean(&self, gamma: f64, speed: f64) -> Option<f64> {
        let k = &self.k;
        let (se, ce) = k.eta.sin_cos();
        let f = |th: f64| {
            let tan_alpha =
                ce * gamma.sin() / (th.cos() * gamma.cos() + th.sin() * gamma.sin() * se);
            th.tan() + speed * speed / (k.g * k.l) * tan_alpha
        };
        if f(0.0) == 0.0 {
            return Some(0.0);
        }
        let dir = -gamma.signum();
        let (mut a, mut b) = (0.0, 0.0);
        let mut found = false;
        for i in 1..=1500 {
            b = dir * i as f64 * 1e-3;
            if f(a).signum() != f(b).signum() {
                found = true;
                break;
            }
            a = b;
        }
        if !found {
            return None;
        }
        for _ in 0..100 {
            let m = 0.5 * (a + b);
            if f(m).signum() == f(a).signum() {
                a = m;
            } else {
                b = m;
            }
        }
        Some(0.5 * (a + b))
    }

    /// n° 103: the derivative $dn/d\theta$ of the turning rate along the lean at fixed γ and
    /// $s$ (1/s per rad), from the model (Richardson differences of the yaw rate with the
    /// rolling speed held) and from the memoir's $(R/l)s\,\partial\tan\alpha/\partial\theta$
    /// (n° 57, the part in $d\eta/d\theta$ dropped as the memoir does), as `(model, memoir)`.
    ///
    /// # Errors
    /// [`TurnError::Model`] when the model fails near the turn.
    pub fn yaw_rate_derivative(&self, turn: &SteadyTurn) -> Result<(f64, f64), TurnError> {
        let (g, v) = (turn.gamma, turn.speed);
        let n = |lean: f64| -> Result<f64, TurnError> {
            let u3 = self.rolling_wheel_rate(lean, g, 0.0, v)?;
            Ok(-self.terms(lean, g, 0.0, u3)?.0.rates[1][2] * u3)
        };
        let (model, _) = derivative(&n, turn.lean, STEP_LEAN)?;
        let k = &self.k;
        let (se, ce) = k.eta.sin_cos();
        let th = turn.lean;
        let d = th.cos() * g.cos() + th.sin() * g.sin() * se;
        let dtan = -ce * g.sin() * (-th.sin() * g.cos() + th.cos() * g.sin() * se) / (d * d);
        Ok((model, v / k.l * dtan))
    }

    /// The memoir's turning rate (2) of n° 86, $n = (R/l)s\tan\alpha$, at lean `lean`.
    pub fn memoir_yaw_rate(&self, gamma: f64, speed: f64, lean: f64) -> f64 {
        let k = &self.k;
        let (se, ce) = k.eta.sin_cos();
        let tan_alpha =
            ce * gamma.sin() / (lean.cos() * gamma.cos() + lean.sin() * gamma.sin() * se);
        speed / k.l * tan_alpha
    }
}
