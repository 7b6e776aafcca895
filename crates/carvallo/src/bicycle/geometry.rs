//! Geometry of the bicycle (memoir Part II, ch. I, n° 43–58): the frame angle σ and the front
//! contact parameter μ as functions of the lean θ and the steer γ, the ground coordinates of
//! the front contact (n° 54), the accessory angles α, β (n° 57) and the front wheel's axes
//! (n° 58). From n° 58 bis on the memoir calls σ and μ η and ω.
//!
//! The contact equations of n° 45 are (1) $K|OM = 0$ (M on the ground) and (2)
//! $K|\frac{dOM}{d\mu} = 0$ (M the lowest point of the front wheel). Their residuals and their
//! Jacobian with respect to (σ, μ) come from evaluators that [`scene!`](crate::scene) generates
//! from `generated/bicycle_geometry.ir` (`cargo xtask regen`, derivation
//! `codegen/src/derive/bicycle/geometry.rs`); [`Geometry::solve`] runs a damped Newton iteration on
//! them. The first-order method of n° 51 is [`Geometry::first_order`].
//!
//! The specific constants (n° 44) are the wheels' radius $R$, the distance $l$ of the wheel
//! centres, the offset $c$ of the front centre from the steering axis and the inclination
//! $\sigma_0$ of the steering axis on the vertical; $a = l\cos\sigma_0 - c$ and
//! $b = l\sin\sigma_0$ follow from the relations (a), (b).

use std::fmt;

use crate::error::ParameterError;
use crate::numerics::poly::bisect_unchecked;

crate::scene! {
    /// Residuals of the contact equations (1), (2) and their Jacobian in (σ, μ), and the μ that
    /// solves (2) for a given σ.
    pub mod contact_scene {
        model: bicycle_geometry,
        outputs: [
            contact_height, lowest_point, d_height_d_sigma, d_height_d_mu, d_lowest_d_sigma,
            d_lowest_d_mu, mu_lowest,
        ],
    }
}

crate::scene! {
    /// The first-order method of n° 51 (θ = 0): σ1 as derived and as printed, μ0, μ1.
    pub mod first_order_scene {
        model: bicycle_geometry,
        outputs: [sigma1_first, memoir_sigma1_first, mu0, mu1_first],
    }
}

crate::scene! {
    /// Ground coordinates of M (n° 54), the accessory angles (n° 57) and the front axes (n° 58).
    pub mod frame_scene {
        model: bicycle_geometry,
        outputs: [
            contact_x, contact_y, normal_i, normal_j, normal_k, alpha, beta, axis_i1_x,
            axis_i1_y, axis_k1_x, axis_k1_y, axis_k1_z,
        ],
    }
}

/// A reader of the generated outputs: given an output's name, its arguments by name and the
/// value the compiled evaluator gave, the value to use. The concordance report installs one
/// ([`with_reader`]) to read a perturbed program while it checks that its entries can fail.
pub type Reader = fn(output: &str, get: &dyn Fn(&str) -> Option<f64>, value: f64) -> f64;

thread_local! {
    static READER: std::cell::Cell<Option<Reader>> = const { std::cell::Cell::new(None) };
}

/// Runs `f` with `reader` applied, on this thread, to every output of the generated programs
/// that [`Geometry`] evaluates (the contact equations and their Jacobian, the first-order
/// method, the front wheel's coordinates and axes) and that
/// [`Kinematics`](crate::bicycle_kinematics::Kinematics) evaluates (the displacement of n° 61,
/// the relations of n° 66 and 69); the reader active before is restored after.
pub fn with_reader<T>(reader: Reader, f: impl FnOnce() -> T) -> T {
    let before = READER.with(|r| r.replace(Some(reader)));
    let out = f();
    READER.with(|r| r.set(before));
    out
}

/// `values` (output name, value) passed through the active reader, if any, with the
/// arguments `args`.
pub(crate) fn read_all(args: &[(&str, f64)], values: &mut [(&str, &mut f64)]) {
    let Some(reader) = READER.with(|r| r.get()) else { return };
    let get = |n: &str| args.iter().find(|(k, _)| *k == n).map(|(_, v)| *v);
    for (name, v) in values.iter_mut() {
        **v = reader(name, &get, **v);
    }
}

/// Why the contact equations have no acceptable solution at the given lean and steer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ContactError {
    /// An angle that is not finite or outside the range the model covers: `theta` or `gamma`.
    Parameter(ParameterError),
    /// Newton's iteration (direct, then by continuation from the upright frame) found no
    /// solution with the front wheel touching the ground at its lowest point.
    NoContact {
        /// Lean θ (rad).
        theta: f64,
        /// Steer γ (rad).
        gamma: f64,
        /// What failed, lower-case.
        reason: &'static str,
    },
}

impl fmt::Display for ContactError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ContactError::Parameter(e) => write!(f, "{e}"),
            ContactError::NoContact { theta, gamma, reason } => {
                write!(f, "no front contact at theta {theta:?} rad, gamma {gamma:?} rad: {reason}")
            }
        }
    }
}

impl std::error::Error for ContactError {}

impl From<ParameterError> for ContactError {
    fn from(e: ParameterError) -> ContactError {
        ContactError::Parameter(e)
    }
}

/// A solution of the contact equations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact {
    /// Frame angle σ (rad), called η from n° 58 bis.
    pub sigma: f64,
    /// Contact parameter μ (rad), called ω from n° 58 bis.
    pub mu: f64,
    /// Newton steps taken (over all continuation stages).
    pub iterations: usize,
    /// Largest residual $|K|OM|, |K|dOM/d\mu|$ at the solution (m).
    pub residual: f64,
}

/// The first-order method of n° 51 at θ = 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FirstOrder {
    /// σ1 from (2)' as derived (coefficient $R\tan\tau_0\cos\sigma_0\sin\gamma$) (rad).
    pub sigma1: f64,
    /// σ1 from (2)' as printed (coefficient $R\tan\tau_0\sin\sigma_0\sin\gamma$) (rad).
    pub sigma1_printed: f64,
    /// $\mu_0$ with $\tan\mu_0 = \tan\sigma_0\cos\gamma$ (rad).
    pub mu0: f64,
    /// $\mu_1 = \sigma_1\,d\mu/d\sigma$ (rad).
    pub mu1: f64,
}

/// The front wheel's frame quantities at a position (n° 54, 57, 58).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrontWheel {
    /// $x = I|OM$, $y = J|OM$: the front contact on the ground from the rear contact (m).
    pub contact: [f64; 2],
    /// Unit normal CN of the front wheel's plane on I, J, K.
    pub normal: [f64; 3],
    /// α: angle of the front wheel's trace with OI (rad).
    pub alpha: f64,
    /// β: angle of the front wheel with the vertical (rad); $\theta_1 = -\beta$.
    pub beta: f64,
    /// $I_1$ on I, J (horizontal tangent to the front path).
    pub i1: [f64; 2],
    /// $k_1$ on I, J, K (the front wheel's steepest line, upwards).
    pub k1: [f64; 3],
}

/// The specific constants of n° 44, validated.
///
/// # Example
/// ```
/// use carvallo::bicycle::geometry::Geometry;
///
/// let g = Geometry::old_model();                    // n° 52: R 0.38, l 1.10, c 0.08, 25°
/// let upright = g.solve(0.0, 0.0)?;
/// assert!((upright.sigma - 25f64.to_radians()).abs() < 1e-14);
/// let turned = g.solve(0.0, 60f64.to_radians())?;   // the frame is lowered (n° 52)
/// assert!(turned.sigma < upright.sigma);
/// # Ok::<(), carvallo::bicycle::geometry::ContactError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry {
    radius: f64,
    wheelbase: f64,
    offset: f64,
    sigma0: f64,
}

/// Tolerance on the residuals (m) and on the Newton step (rad) at convergence.
pub const NEWTON_TOLERANCE: f64 = 1e-14;
/// Newton steps per stage before giving up.
pub const MAX_NEWTON_STEPS: usize = 60;
/// Stages of the continuation in (θ, γ) from the upright straight position.
pub const CONTINUATION_STAGES: usize = 32;

impl Geometry {
    /// A bicycle of wheel radius `radius`, distance of the wheel centres `wheelbase`, offset
    /// `offset` of the front centre from the steering axis and steering-axis inclination
    /// `sigma0` (rad) on the vertical (n° 44).
    ///
    /// # Errors
    /// [`ParameterError::InvalidParameter`] naming the first offending value: `radius` and
    /// `wheelbase` must be positive; `offset` must satisfy $0 \le c < R$ (the steering axis
    /// meets the front wheel's vertical radius, n° 43, and the rim at E, n° 53); `sigma0` must
    /// lie in $[0, \pi/2)$; and $a = l\cos\sigma_0 - c$ must be positive.
    pub fn new(
        radius: f64,
        wheelbase: f64,
        offset: f64,
        sigma0: f64,
    ) -> Result<Geometry, ParameterError> {
        let radius = ParameterError::check_positive("radius", radius)?;
        let wheelbase = ParameterError::check_positive("wheelbase", wheelbase)?;
        if !(offset.is_finite() && offset >= 0.0 && offset < radius) {
            return Err(ParameterError::InvalidParameter {
                name: "offset",
                value: offset,
                reason: "must satisfy 0 <= c < radius",
            });
        }
        if !(sigma0.is_finite() && (0.0..std::f64::consts::FRAC_PI_2).contains(&sigma0)) {
            return Err(ParameterError::InvalidParameter {
                name: "sigma0",
                value: sigma0,
                reason: "must lie in [0, pi/2)",
            });
        }
        let a = wheelbase * sigma0.cos() - offset;
        if a <= 0.0 {
            return Err(ParameterError::InvalidParameter {
                name: "offset",
                value: offset,
                reason: "must be below l cos(sigma0) (a > 0)",
            });
        }
        Ok(Geometry { radius, wheelbase, offset, sigma0 })
    }

    /// The old-model bicycle of n° 52: $R = 0.38$ m, $l = 1.10$ m, $c = 0.08$ m,
    /// $\sigma_0 = 25°$.
    pub fn old_model() -> Geometry {
        Geometry { radius: 0.38, wheelbase: 1.10, offset: 0.08, sigma0: 25f64.to_radians() }
    }

    /// $R$ (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// $l$ (m).
    pub fn wheelbase(&self) -> f64 {
        self.wheelbase
    }

    /// $c$ (m).
    pub fn offset(&self) -> f64 {
        self.offset
    }

    /// $\sigma_0$ (rad).
    pub fn sigma0(&self) -> f64 {
        self.sigma0
    }

    /// $a = l\cos\sigma_0 - c$ (relation (a), n° 44) (m).
    pub fn a(&self) -> f64 {
        self.wheelbase * self.sigma0.cos() - self.offset
    }

    /// $b = l\sin\sigma_0$ (relation (b), n° 44) (m).
    pub fn b(&self) -> f64 {
        self.wheelbase * self.sigma0.sin()
    }

    /// The program's arguments at the position (θ, γ, σ, μ), by name.
    fn arguments(&self, theta: f64, gamma: f64, sigma: f64, mu: f64) -> [(&'static str, f64); 8] {
        [
            ("R", self.radius),
            ("l", self.wheelbase),
            ("c", self.offset),
            ("sigma0", self.sigma0),
            ("theta", theta),
            ("gamma", gamma),
            ("sigma", sigma),
            ("mu", mu),
        ]
    }

    fn contact_eval(&self, theta: f64, gamma: f64, sigma: f64, mu: f64) -> contact_scene::Out {
        let mut o = contact_scene::eval(&contact_scene::Args {
            R: self.radius,
            l: self.wheelbase,
            c: self.offset,
            sigma0: self.sigma0,
            theta,
            gamma,
            sigma,
            mu,
        });
        read_all(
            &self.arguments(theta, gamma, sigma, mu),
            &mut [
                ("contact_height", &mut o.contact_height),
                ("lowest_point", &mut o.lowest_point),
                ("d_height_d_sigma", &mut o.d_height_d_sigma),
                ("d_height_d_mu", &mut o.d_height_d_mu),
                ("d_lowest_d_sigma", &mut o.d_lowest_d_sigma),
                ("d_lowest_d_mu", &mut o.d_lowest_d_mu),
                ("mu_lowest", &mut o.mu_lowest),
            ],
        );
        o
    }

    /// The residuals $(K|OM, K|dOM/d\mu)$ of the contact equations (1), (2) (m).
    pub fn residuals(&self, theta: f64, gamma: f64, sigma: f64, mu: f64) -> [f64; 2] {
        let o = self.contact_eval(theta, gamma, sigma, mu);
        [o.contact_height, o.lowest_point]
    }

    /// The μ solving (2) for a given σ (the lowest point of the front wheel) (rad).
    pub fn mu_lowest(&self, theta: f64, gamma: f64, sigma: f64) -> f64 {
        self.contact_eval(theta, gamma, sigma, 0.0).mu_lowest
    }

    /// Newton from `(sigma, mu)` at fixed (θ, γ); `Some((sigma, mu, steps, residual))` at
    /// convergence.
    fn newton(
        &self,
        theta: f64,
        gamma: f64,
        mut sigma: f64,
        mut mu: f64,
    ) -> Option<(f64, f64, usize, f64)> {
        let norm = |o: &contact_scene::Out| o.contact_height.abs().max(o.lowest_point.abs());
        let mut o = self.contact_eval(theta, gamma, sigma, mu);
        for step in 1..=MAX_NEWTON_STEPS {
            let det = o.d_height_d_sigma * o.d_lowest_d_mu - o.d_height_d_mu * o.d_lowest_d_sigma;
            if !det.is_finite() || det == 0.0 {
                return None;
            }
            let ds = (o.contact_height * o.d_lowest_d_mu - o.d_height_d_mu * o.lowest_point) / det;
            let dm =
                (o.d_height_d_sigma * o.lowest_point - o.d_lowest_d_sigma * o.contact_height) / det;
            // Damping: halve the step until the residual decreases (at most 30 halvings).
            let before = norm(&o);
            let mut t = 1.0;
            let mut next = self.contact_eval(theta, gamma, sigma - ds, mu - dm);
            while norm(&next).partial_cmp(&before) != Some(std::cmp::Ordering::Less)
                && t > 1e-9
                && before > NEWTON_TOLERANCE
            {
                t *= 0.5;
                next = self.contact_eval(theta, gamma, sigma - t * ds, mu - t * dm);
            }
            sigma -= t * ds;
            mu -= t * dm;
            o = next;
            let r = norm(&o);
            if !r.is_finite() {
                return None;
            }
            if (t * ds).abs().max((t * dm).abs()) <= NEWTON_TOLERANCE || r <= NEWTON_TOLERANCE {
                // One more full step polishes the last digits when it does not hurt.
                return Some((sigma, mu, step, r));
            }
        }
        None
    }

    fn acceptable(&self, theta: f64, gamma: f64, sigma: f64, mu: f64) -> bool {
        let o = self.contact_eval(theta, gamma, sigma, mu);
        (sigma - self.sigma0).abs() < std::f64::consts::FRAC_PI_2 && o.d_lowest_d_mu > 0.0
    }

    /// Solves the contact equations (1), (2) for σ and μ at lean `theta` and steer `gamma`
    /// (rad): damped Newton with the generated Jacobian, started from the first-order estimate
    /// (σ0 + σ1 of n° 51 and the lowest point μ for it); when that fails, by continuation in
    /// [`CONTINUATION_STAGES`] stages from the upright straight position. The solution is
    /// accepted only if M is the *lowest* point of the wheel ($\partial^2 K|OM/\partial\mu^2 > 0$)
    /// and the frame has turned by less than a right angle ($|\sigma - \sigma_0| < \pi/2$).
    /// μ is returned in $(-\pi, \pi]$.
    ///
    /// # Errors
    /// [`ContactError::Parameter`] when θ is not finite or $|\theta| \ge \pi/2$ (the frame
    /// lying on the ground) or γ is not finite; [`ContactError::NoContact`] when no acceptable
    /// solution is found.
    pub fn solve(&self, theta: f64, gamma: f64) -> Result<Contact, ContactError> {
        if !theta.is_finite() || theta.abs() >= std::f64::consts::FRAC_PI_2 {
            return Err(ContactError::Parameter(ParameterError::InvalidParameter {
                name: "theta",
                value: theta,
                reason: "must be finite with |theta| < pi/2",
            }));
        }
        if !gamma.is_finite() {
            return Err(ContactError::Parameter(ParameterError::InvalidParameter {
                name: "gamma",
                value: gamma,
                reason: "must be finite",
            }));
        }
        let fo = self.first_order(gamma);
        let s_start = self.sigma0 + if fo.sigma1.is_finite() { fo.sigma1 } else { 0.0 };
        let m_start = self.mu_lowest(theta, gamma, s_start);
        let wrap = |m: f64| {
            (m + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI
        };
        if let Some((s, m, steps, r)) = self.newton(theta, gamma, s_start, m_start) {
            if self.acceptable(theta, gamma, s, m) {
                return Ok(Contact { sigma: s, mu: wrap(m), iterations: steps, residual: r });
            }
        }
        // Continuation from the upright straight position.
        let (mut s, mut m) = (self.sigma0, self.sigma0);
        let mut total = 0;
        let mut residual = 0.0;
        for k in 1..=CONTINUATION_STAGES {
            let f = k as f64 / CONTINUATION_STAGES as f64;
            match self.newton(f * theta, f * gamma, s, m) {
                Some((s1, m1, steps, r)) if self.acceptable(f * theta, f * gamma, s1, m1) => {
                    s = s1;
                    m = m1;
                    total += steps;
                    residual = r;
                }
                _ => return Err(ContactError::NoContact {
                    theta,
                    gamma,
                    reason:
                        "newton's iteration finds no lowest point of the front wheel on the ground",
                }),
            }
        }
        Ok(Contact { sigma: s, mu: wrap(m), iterations: total, residual })
    }

    /// The first-order method of n° 51 at θ = 0 and steer `gamma` (rad).
    pub fn first_order(&self, gamma: f64) -> FirstOrder {
        let mut o = first_order_scene::eval(&first_order_scene::Args {
            R: self.radius,
            l: self.wheelbase,
            c: self.offset,
            sigma0: self.sigma0,
            gamma,
        });
        read_all(
            &self.arguments(0.0, gamma, f64::NAN, f64::NAN),
            &mut [
                ("sigma1_first", &mut o.sigma1_first),
                ("memoir_sigma1_first", &mut o.memoir_sigma1_first),
                ("mu0", &mut o.mu0),
                ("mu1_first", &mut o.mu1_first),
            ],
        );
        FirstOrder {
            sigma1: o.sigma1_first,
            sigma1_printed: o.memoir_sigma1_first,
            mu0: o.mu0,
            mu1: o.mu1_first,
        }
    }

    /// The front contact on the ground, the accessory angles and the front axes at the position
    /// (θ, γ, σ, μ) (n° 54, 57, 58); σ, μ are normally those of [`Geometry::solve`].
    pub fn front_wheel(&self, theta: f64, gamma: f64, sigma: f64, mu: f64) -> FrontWheel {
        let mut o = frame_scene::eval(&frame_scene::Args {
            R: self.radius,
            l: self.wheelbase,
            c: self.offset,
            sigma0: self.sigma0,
            theta,
            gamma,
            sigma,
            mu,
        });
        read_all(
            &self.arguments(theta, gamma, sigma, mu),
            &mut [
                ("contact_x", &mut o.contact_x),
                ("contact_y", &mut o.contact_y),
                ("normal_i", &mut o.normal_i),
                ("normal_j", &mut o.normal_j),
                ("normal_k", &mut o.normal_k),
                ("alpha", &mut o.alpha),
                ("beta", &mut o.beta),
                ("axis_i1_x", &mut o.axis_i1_x),
                ("axis_i1_y", &mut o.axis_i1_y),
                ("axis_k1_x", &mut o.axis_k1_x),
                ("axis_k1_y", &mut o.axis_k1_y),
                ("axis_k1_z", &mut o.axis_k1_z),
            ],
        );
        FrontWheel {
            contact: [o.contact_x, o.contact_y],
            normal: [o.normal_i, o.normal_j, o.normal_k],
            alpha: o.alpha,
            beta: o.beta,
            i1: [o.axis_i1_x, o.axis_i1_y],
            k1: [o.axis_k1_x, o.axis_k1_y, o.axis_k1_z],
        }
    }

    /// The lowest frame position at θ = 0 (n° 53): M at the point E where the steering axis
    /// meets the rim ($R\sin\mu = c$), σ from (1) (which does not depend on γ there, by
    /// bisection on the generated residual) and γ from $\tan\mu = \tan\sigma\cos\gamma$.
    /// Returns (σ, μ, γ) in rad.
    pub fn lowest_frame(&self) -> (f64, f64, f64) {
        let mu = (self.offset / self.radius).asin();
        let h = |s: f64| self.residuals(0.0, 0.0, s, mu)[0];
        let sigma = bisect_unchecked(h, self.sigma0 - 0.5, self.sigma0);
        let gamma = (mu.tan() / sigma.tan()).clamp(-1.0, 1.0).acos();
        (sigma, mu, gamma)
    }

    /// Data of the memoir's figure 11 (θ = 0): for `points` steers evenly spaced over
    /// [0°, 90°], `(γ, σ1, μ)` in degrees from the exact solution.
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn figure_11(&self, points: usize) -> Result<Vec<[f64; 3]>, ContactError> {
        steers(points)
            .map(|g| {
                let s = self.solve(0.0, g)?;
                Ok([g.to_degrees(), (s.sigma - self.sigma0).to_degrees(), s.mu.to_degrees()])
            })
            .collect()
    }

    /// Data of the memoir's figure 13 (θ = 0): for `points` steers evenly spaced over
    /// [0°, 90°], `(γ in degrees, x − l, y)` with the front contact's coordinates in metres.
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn figure_13(&self, points: usize) -> Result<Vec<[f64; 3]>, ContactError> {
        steers(points)
            .map(|g| {
                let s = self.solve(0.0, g)?;
                let f = self.front_wheel(0.0, g, s.sigma, s.mu);
                Ok([g.to_degrees(), f.contact[0] - self.wheelbase, f.contact[1]])
            })
            .collect()
    }
}

fn steers(points: usize) -> impl Iterator<Item = f64> {
    let n = points.max(2);
    (0..n).map(move |k| (90.0 * k as f64 / (n - 1) as f64).to_radians())
}
