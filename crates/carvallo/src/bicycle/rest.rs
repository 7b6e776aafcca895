//! The handlebar's equilibrium at rest for a given lean θ (memoir n° 67), solved rigorously.
//!
//! Carvallo leans the frame by θ, the rear wheel held, and lets the handlebar and the front
//! wheel free. Neglecting the front wheel's weight, the handlebar settles where the frame is
//! lowest in its plane (n° 55 of the memoir's numbering, [`Geometry::lowest_frame`]); with it,
//! the equilibrium is "voisine de celle du n° 55, sinon confondue", and he does not look for
//! the rigorous solution. This module looks for it.
//!
//! With the rear wheel and the lean fixed, the potential energy of the bicycle is a function of
//! the handlebar angle γ alone,
//! $$U(\gamma; \theta) = g\,\bigl(\mu z_G + \mu_1 z_C\bigr) + \text{const},$$
//! where $z_G = \cos\theta\,(R + x\sin\sigma_1 + z\cos\sigma_1)$ is the height of the mounted
//! frame's centre of gravity (formula (1) of n° 69: $x, z$ its coordinates from the rear centre
//! S in the normal position, $\sigma_1 = \sigma - \sigma_0$ the frame's rotation about S) and
//! $z_C = R\,k_1|K$ the height of the front wheel's centre C, which lies at R from the contact
//! M along the front wheel's steepest line $k_1$ (n° 58, [`Geometry::front_wheel`]); the rear
//! wheel's $\mu_1 R\cos\theta$ is constant and left out; fork and handlebar are massless. σ
//! and μ at (θ, γ) come from the exact contact solver [`Geometry::solve`].
//!
//! Two positions are computed for each θ: γ55, where σ is smallest (the frame lowest; n° 56
//! remarks that it is again the position where the point E of the rim on the steering axis
//! touches the ground, with the same $\sigma$ as for the upright frame), and γ67, where
//! $dU/d\gamma = 0$ with $d^2U/d\gamma^2 > 0$ (the handlebar's stable equilibrium). Both are
//! found by a safeguarded Newton iteration (bisection whenever a step leaves the bracket) on a
//! derivative computed by central differences of the exact solution: step [`STEP`], error
//! estimated by the difference with the step doubled (Richardson), carried in [`Derivative`].
//!
//! As in n° 67, U is minimised over the configurations (θ held, γ free) without asking how the
//! front contact moves on the ground: a pivot of the whole bicycle about the vertical through
//! the rear contact changes no height, and the rolling constraints are not imposed.
//!
//! Findings (memoir's bicycle, the concordance `carvallo_report::bicycle::rest`): γ55 is where the point E is
//! on the ground with the upright frame's σ at every lean, as n° 56 says; γ67 lies beyond γ55
//! (a larger γ lowers the front wheel, as n° 67 reasons) by 9.2° upright and 9.0° to 3.8° for
//! θ = 5° to 40°, while the frame rises by only about 0.1 mm: the frame's height is stationary
//! at γ55 and the wheel's is not, so the shift is first order in $\mu_1/\mu$ and large because
//! the frame's minimum is flat. γ = 0 upright is an unstable equilibrium; as θ → 0 the rest
//! positions tend to ±γ55 and ±γ67 of the upright frame, not to 0.
//!
//! The masses and the centre of gravity are those of the mounted bicycle of n° 117
//! ([`RestConstants::MEMOIR`]: μ = 70 kg at e = 0.20 m ahead of the rear wheel and h = 1 m high,
//! μ1 = 5 kg); the geometry is that of n° 52 ([`Geometry::old_model`]), whose offset c = 0.08 m
//! the memoir also uses in n° 117 (there as $c_1$). Putting n° 117's centre of gravity on
//! n° 52's frame is an illustrative combination: the memoir gives no single bicycle with both.

use std::fmt;

use crate::bicycle::geometry::{ContactError, Geometry};
use crate::error::ParameterError;

/// Step (rad) of the central first differences in γ.
pub const STEP: f64 = 1e-4;
/// Step (rad) of the central second differences in γ (larger against rounding).
pub const SECOND_STEP: f64 = 1e-3;
/// Tolerance (rad) on γ at which the Newton/bisection iteration stops.
pub const GAMMA_TOLERANCE: f64 = 1e-10;
/// Iterations of the Newton/bisection before giving up.
pub const MAX_ITERATIONS: usize = 100;

/// The masses and the frame's centre of gravity (n° 117 and n° 69).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RestConstants {
    /// Mass μ of the mounted frame (frame and rider) (kg).
    pub frame_mass: f64,
    /// Mass $\mu_1$ of the front wheel (kg); zero is allowed (Carvallo's approximation).
    pub wheel_mass: f64,
    /// Horizontal distance x of the frame's centre of gravity ahead of the rear wheel, in the
    /// normal position (m); n° 117's $e$.
    pub forward: f64,
    /// Height of the frame's centre of gravity above the ground in the normal position (m);
    /// n° 117's $h$ (so $z = h - R$ above the rear centre).
    pub height: f64,
    /// Gravity g (m/s²).
    pub g: f64,
}

impl RestConstants {
    /// The constants of n° 117: μ = 70 kg, μ1 = 5 kg, e = 0.20 m, h = 1 m, g = 9.81 m/s².
    pub const MEMOIR: RestConstants =
        RestConstants { frame_mass: 70.0, wheel_mass: 5.0, forward: 0.20, height: 1.0, g: 9.81 };
}

/// Why a rest position could not be computed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RestError {
    /// The contact equations failed at a point the computation needed.
    Contact(ContactError),
    /// No stationary point of the required kind in the searched range of γ.
    NoEquilibrium {
        /// Lean θ (rad).
        theta: f64,
        /// Lower end of the searched range of γ (rad).
        lo: f64,
        /// Upper end of the searched range of γ (rad).
        hi: f64,
        /// What was looked for, lower-case.
        reason: &'static str,
    },
}

impl fmt::Display for RestError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RestError::Contact(e) => write!(f, "{e}"),
            RestError::NoEquilibrium { theta, lo, hi, reason } => {
                write!(f, "no {reason} at theta {theta:?} rad for gamma in [{lo:?}, {hi:?}] rad")
            }
        }
    }
}

impl std::error::Error for RestError {}

impl From<ContactError> for RestError {
    fn from(e: ContactError) -> RestError {
        RestError::Contact(e)
    }
}

/// The bicycle at rest at a lean θ and a handlebar angle γ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RestState {
    /// Handlebar angle γ (rad).
    pub gamma: f64,
    /// Frame angle σ (rad).
    pub sigma: f64,
    /// Contact parameter μ (rad).
    pub mu: f64,
    /// Height $z_G$ of the frame's centre of gravity (m).
    pub frame_height: f64,
    /// Height $z_C$ of the front wheel's centre (m).
    pub wheel_height: f64,
    /// $U = g(\mu z_G + \mu_1 z_C)$ (J).
    pub energy: f64,
}

/// A derivative by central differences: the value with step [`STEP`] ([`SECOND_STEP`] for a
/// second derivative) and the estimate of its error, the difference from the value with the
/// step doubled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Derivative {
    /// The derivative with the finer step.
    pub value: f64,
    /// |value with the finer step − value with the step doubled|, which bounds the truncation
    /// error of the finer one (it is a quarter of the difference) and shows the rounding noise.
    pub error: f64,
}

/// A stationary point of a function of γ found by [`RestBicycle`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stationary {
    /// γ at the stationary point (rad).
    pub gamma: f64,
    /// The second derivative there ($d^2U/d\gamma^2$ in J/rad² for the energy, $d^2\sigma/d\gamma^2$
    /// for the frame angle).
    pub curvature: Derivative,
    /// Newton or bisection steps taken.
    pub iterations: usize,
}

/// The two positions of n° 67 at one lean, on one side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RestPosition {
    /// Lean θ (rad).
    pub theta: f64,
    /// The frame's lowest position (σ smallest), n° 55/56.
    pub lowest: Stationary,
    /// The handlebar's stable equilibrium with the front wheel's weight ($dU/d\gamma = 0$).
    pub equilibrium: Stationary,
    /// The state at γ55.
    pub at_lowest: RestState,
    /// The state at γ67.
    pub at_equilibrium: RestState,
}

impl RestPosition {
    /// γ67 − γ55 (rad).
    pub fn difference(&self) -> f64 {
        self.equilibrium.gamma - self.lowest.gamma
    }

    /// How much higher the frame's centre of gravity is at γ67 than at γ55 (m), ≥ 0.
    pub fn frame_rise(&self) -> f64 {
        self.at_equilibrium.frame_height - self.at_lowest.frame_height
    }
}

/// The bicycle at rest: geometry and masses, validated.
///
/// # Example
/// ```
/// use carvallo::bicycle::geometry::Geometry;
/// use carvallo::bicycle::rest::{RestBicycle, RestConstants};
///
/// let bike = RestBicycle::new(Geometry::old_model(), RestConstants::MEMOIR)?;
/// let p = bike.rest_position(-20f64.to_radians())?;        // gamma > 0
/// assert!(p.equilibrium.curvature.value > 0.0);            // stable
/// let (g55, g67) = (p.lowest.gamma.to_degrees(), p.equilibrium.gamma.to_degrees());
/// assert!((g55 - 27.99).abs() < 0.01 && (g67 - 34.70).abs() < 0.01);
/// assert!(p.frame_rise() < 2e-4);                          // the frame 0.12 mm higher
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RestBicycle {
    geometry: Geometry,
    constants: RestConstants,
}

impl RestBicycle {
    /// The bicycle of geometry `geometry` with masses and centre of gravity `constants`.
    ///
    /// # Errors
    /// [`ParameterError::InvalidParameter`] naming the offending value: `frame_mass` and `g`
    /// must be positive, `wheel_mass` finite and non-negative, `forward` finite and `height`
    /// finite and above the wheel radius.
    pub fn new(
        geometry: Geometry,
        constants: RestConstants,
    ) -> Result<RestBicycle, ParameterError> {
        ParameterError::check_positive("frame_mass", constants.frame_mass)?;
        ParameterError::check_positive("g", constants.g)?;
        let m1 = constants.wheel_mass;
        if !(m1.is_finite() && m1 >= 0.0) {
            return Err(ParameterError::InvalidParameter {
                name: "wheel_mass",
                value: m1,
                reason: "must be finite and non-negative",
            });
        }
        if !constants.forward.is_finite() {
            return Err(ParameterError::InvalidParameter {
                name: "forward",
                value: constants.forward,
                reason: "must be finite",
            });
        }
        if !(constants.height.is_finite() && constants.height > geometry.radius()) {
            return Err(ParameterError::InvalidParameter {
                name: "height",
                value: constants.height,
                reason: "must be finite and above the wheel radius",
            });
        }
        Ok(RestBicycle { geometry, constants })
    }

    /// The memoir's bicycle: [`Geometry::old_model`] with [`RestConstants::MEMOIR`].
    pub fn memoir() -> RestBicycle {
        RestBicycle { geometry: Geometry::old_model(), constants: RestConstants::MEMOIR }
    }

    /// The bicycle of `geometry` and `constants` taken as they are, without the checks of
    /// [`RestBicycle::new`]: a perturbed bicycle for the report's falsification checks (issue
    /// 38), such as the weight reversed (`g` negative). No claim of the memoir is judged on such
    /// a model; it shows that a check can fail.
    pub fn new_unchecked(geometry: Geometry, constants: RestConstants) -> RestBicycle {
        RestBicycle { geometry, constants }
    }

    /// The same bicycle with front wheel mass `wheel_mass` (kg).
    ///
    /// # Errors
    /// As [`RestBicycle::new`].
    pub fn with_wheel_mass(&self, wheel_mass: f64) -> Result<RestBicycle, ParameterError> {
        RestBicycle::new(self.geometry, RestConstants { wheel_mass, ..self.constants })
    }

    /// The geometry.
    pub fn geometry(&self) -> &Geometry {
        &self.geometry
    }

    /// The masses and centre of gravity.
    pub fn constants(&self) -> &RestConstants {
        &self.constants
    }

    /// The state at lean `theta` and handlebar angle `gamma` (rad).
    ///
    /// # Errors
    /// [`RestError::Contact`] as [`Geometry::solve`].
    pub fn state(&self, theta: f64, gamma: f64) -> Result<RestState, RestError> {
        let g = &self.geometry;
        let k = &self.constants;
        let c = g.solve(theta, gamma)?;
        let s1 = c.sigma - g.sigma0();
        let z = k.height - g.radius();
        let frame_height = theta.cos() * (g.radius() + k.forward * s1.sin() + z * s1.cos());
        let wheel_height = g.radius() * g.front_wheel(theta, gamma, c.sigma, c.mu).k1[2];
        let energy = k.g * (k.frame_mass * frame_height + k.wheel_mass * wheel_height);
        Ok(RestState { gamma, sigma: c.sigma, mu: c.mu, frame_height, wheel_height, energy })
    }

    /// $dU/d\gamma$ (J/rad) at (θ, γ) by central differences of [`RestBicycle::state`].
    ///
    /// # Errors
    /// As [`RestBicycle::state`].
    pub fn slope(&self, theta: f64, gamma: f64) -> Result<Derivative, RestError> {
        first(|x| Ok(self.state(theta, x)?.energy), gamma)
    }

    /// $d^2U/d\gamma^2$ (J/rad²) at (θ, γ) by central differences.
    ///
    /// # Errors
    /// As [`RestBicycle::state`].
    pub fn stiffness(&self, theta: f64, gamma: f64) -> Result<Derivative, RestError> {
        second(|x| Ok(self.state(theta, x)?.energy), gamma)
    }

    /// $d\sigma/d\gamma$ at (θ, γ) by central differences.
    ///
    /// # Errors
    /// As [`RestBicycle::state`].
    pub fn frame_slope(&self, theta: f64, gamma: f64) -> Result<Derivative, RestError> {
        first(|x| Ok(self.geometry.solve(theta, x)?.sigma), gamma)
    }

    /// The frame's lowest position (σ smallest, n° 55/56) with γ in `[lo, hi]` (rad), where
    /// $d\sigma/d\gamma$ must change sign from negative to positive.
    ///
    /// # Errors
    /// [`RestError::NoEquilibrium`] when $d\sigma/d\gamma$ does not go from negative at `lo` to
    /// positive at `hi` or the iteration does not converge; [`RestError::Contact`].
    pub fn lowest_frame(&self, theta: f64, lo: f64, hi: f64) -> Result<Stationary, RestError> {
        let f = |x: f64| self.frame_slope(theta, x);
        let df = |x: f64| second(|y| Ok(self.geometry.solve(theta, y)?.sigma), x);
        minimum(f, df, theta, lo, hi, "lowest frame position")
    }

    /// The handlebar's stable equilibrium ($dU/d\gamma = 0$ going from negative to positive)
    /// with γ in `[lo, hi]` (rad).
    ///
    /// # Errors
    /// [`RestError::NoEquilibrium`] when $dU/d\gamma$ does not go from negative at `lo` to
    /// positive at `hi` or the iteration does not converge; [`RestError::Contact`].
    pub fn equilibrium(&self, theta: f64, lo: f64, hi: f64) -> Result<Stationary, RestError> {
        let f = |x: f64| self.slope(theta, x);
        let df = |x: f64| self.stiffness(theta, x);
        minimum(f, df, theta, lo, hi, "stable equilibrium of the handlebar")
    }

    /// γ55 and γ67 at lean `theta` on the side the handlebar falls to from γ = 0 (the side
    /// where $dU/d\gamma(0) < 0$; γ > 0 when the frame is upright, where the slope at 0 vanishes
    /// within its error by symmetry), with
    /// [`RestBicycle::rest_position_on`].
    ///
    /// # Errors
    /// As [`RestBicycle::rest_position_on`].
    pub fn rest_position(&self, theta: f64) -> Result<RestPosition, RestError> {
        let d = self.slope(theta, 0.0)?;
        let side = if d.value > d.error { -1.0 } else { 1.0 };
        self.rest_position_on(theta, side)
    }

    /// γ55 and γ67 at lean `theta` on the side of the sign of `side` (γ > 0 if `side >= 0`):
    /// the lowest frame position is bracketed in [1°, 89°] (or its mirror), the equilibrium in
    /// ±[`BRACKET`] around it (within the same range).
    ///
    /// # Errors
    /// [`RestError::NoEquilibrium`] when either is not found; [`RestError::Contact`].
    pub fn rest_position_on(&self, theta: f64, side: f64) -> Result<RestPosition, RestError> {
        let s = if side < 0.0 { -1.0 } else { 1.0 };
        let (a, b) = (1f64.to_radians(), 89f64.to_radians());
        let (lo, hi) = if s > 0.0 { (a, b) } else { (-b, -a) };
        let lowest = self.lowest_frame(theta, lo, hi)?;
        let equilibrium = self.equilibrium(
            theta,
            (lowest.gamma - BRACKET).max(lo),
            (lowest.gamma + BRACKET).min(hi),
        )?;
        Ok(RestPosition {
            theta,
            at_lowest: self.state(theta, lowest.gamma)?,
            at_equilibrium: self.state(theta, equilibrium.gamma)?,
            lowest,
            equilibrium,
        })
    }
}

/// Half-width (rad) of the bracket around γ55 in which [`RestBicycle::rest_position`] looks for
/// γ67: 20°.
pub const BRACKET: f64 = 20.0 * std::f64::consts::PI / 180.0;

fn first(f: impl Fn(f64) -> Result<f64, RestError>, x: f64) -> Result<Derivative, RestError> {
    let d = |h: f64| -> Result<f64, RestError> { Ok((f(x + h)? - f(x - h)?) / (2.0 * h)) };
    let fine = d(STEP)?;
    let coarse = d(2.0 * STEP)?;
    Ok(Derivative { value: fine, error: (fine - coarse).abs() })
}

fn second(f: impl Fn(f64) -> Result<f64, RestError>, x: f64) -> Result<Derivative, RestError> {
    let f0 = f(x)?;
    let d = |h: f64| -> Result<f64, RestError> { Ok((f(x + h)? - 2.0 * f0 + f(x - h)?) / (h * h)) };
    let fine = d(SECOND_STEP)?;
    let coarse = d(2.0 * SECOND_STEP)?;
    Ok(Derivative { value: fine, error: (fine - coarse).abs() })
}

/// Safeguarded Newton on `f` (a derivative, negative at `lo`, positive at `hi`) with its
/// derivative `df`; it stops when the step is below [`GAMMA_TOLERANCE`] or `f` is zero within
/// its stated error. A Newton step is taken when it stays strictly inside the bracket, otherwise
/// the bracket is bisected; the bracket shrinks on the sign of `f` at each new point.
fn minimum(
    f: impl Fn(f64) -> Result<Derivative, RestError>,
    df: impl Fn(f64) -> Result<Derivative, RestError>,
    theta: f64,
    lo: f64,
    hi: f64,
    reason: &'static str,
) -> Result<Stationary, RestError> {
    let none = RestError::NoEquilibrium { theta, lo, hi, reason };
    if !lo.is_finite() || !hi.is_finite() || lo >= hi {
        return Err(none);
    }
    let (mut a, mut b) = (lo, hi);
    let (fa, fb) = (f(a)?.value, f(b)?.value);
    if !(fa < 0.0 && fb > 0.0) {
        return Err(none);
    }
    let mut x = 0.5 * (a + b);
    for step in 1..=MAX_ITERATIONS {
        let Derivative { value: fx, error } = f(x)?;
        if fx.abs() <= error {
            // Zero within the derivative's own error.
            return Ok(Stationary { gamma: x, curvature: df(x)?, iterations: step });
        }
        if fx < 0.0 {
            a = x;
        } else {
            b = x;
        }
        let d = df(x)?;
        let newton = x - fx / d.value;
        let next = if d.value > 0.0 && newton > a && newton < b { newton } else { 0.5 * (a + b) };
        let moved = (next - x).abs();
        x = next;
        if moved <= GAMMA_TOLERANCE || b - a <= GAMMA_TOLERANCE {
            return Ok(Stationary { gamma: x, curvature: df(x)?, iterations: step });
        }
    }
    Err(none)
}
