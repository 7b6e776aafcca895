//! The bicycle's steady states with and without hands and the stability with hands (memoir
//! Part II, ch. IV, n° 79–106), evaluated from the generated code of
//! `generated/bicycle_steady.ir` (`cargo xtask regen`, derivation
//! `codegen/src/derive/bicycle/steady/mod.rs`).
//!
//! The model is the memoir's: a loaded frame (frame with a rigid rider) of mass $\mu$, centre
//! of gravity at $e$ ahead of and $h$ above the rear contact point O in the frame's plane,
//! moments $A, B, C$ about OI, Oj, Ok and product $L = \sum m\,zx$; two equal hoop wheels of
//! radius $R$ and mass $\mu_1$ (moments $A_1, B_1, C_1$ about their contact points, n° 4);
//! wheelbase $l$ and fork offset $c$ (n° 44). A steady state is given by the lean θ, the front
//! wheel's lean θ₁, its heading α relative to the frame (n° 57), the frame's angle η, the
//! contact angle ω of the front wheel (n° 48, 58 bis), the rolling rates $s, s_1$, the turning
//! rate $n$ and the geometric derivatives $d\eta/d\theta$, $d\nu/d\theta$, $d\eta/d\gamma$,
//! $d\nu/d\gamma$ of n° 66, all handed in by the caller ([`SteadyState`]): the geometry of
//! n° 43–69 is not part of this module.
//!
//! The memoir gives $\mu, h, e, R, l, c, \mu_1$ and η (n° 52, 88, 89, 95, 96, 104) but not
//! the frame's $A, B, C, L$: [`BicycleParams::memoir`] uses illustrative values for them,
//! stated as such; none of the memoir's numbers depends on them.

use crate::error::ParameterError;

crate::scene! {
    /// Every output of the `bicycle_steady` program (derived and transcribed).
    pub mod all_scene {
        model: bicycle_steady,
        outputs: [
            fall_rear, fall_front, fall_frame, fall_grav_rear, fall_grav_front, fall_grav_frame,
            fall_equilibrium, memoir_fall_equilibrium, steer_front, steer_frame,
            steer_grav_front, steer_grav_frame, steer_equilibrium, minus_g_i1,
            fall_first_order, tan_theta_86, curvature_87, ratio_88, epsilon_bound_89,
            steer_first_order, theta1_over_theta, memoir_theta1_over_theta,
            theta1_over_theta_geometry, no_hands_s2, memoir_no_hands_s2, shift_98,
            memoir_shift_98, shift_98_exact, kinetic_frame, dt0_dp, dt0_deta, dt0_dn, dfdpp_frame,
            memoir_fall_rear, memoir_fall_front, memoir_fall_frame, memoir_fall_grav_rear,
            memoir_fall_grav_front, memoir_fall_grav_frame, memoir_tan_theta_86,
            memoir_curvature_87, memoir_ratio_88, memoir_epsilon_bound_89, memoir_steer_front,
            memoir_steer_frame, memoir_steer_grav_front, memoir_steer_grav_frame,
            memoir_kinetic_frame, memoir_dt0_dp, memoir_dt0_deta, memoir_dt0_dn,
        ],
    }
}

/// The bicycle's constants (SI units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BicycleParams {
    /// Wheel radius $R$ (m).
    pub radius: f64,
    /// Gravity $g$ (m/s²).
    pub g: f64,
    /// Mass $\mu$ of the loaded frame (kg).
    pub mass: f64,
    /// Abscissa $e$ of its centre of gravity on Oi (m).
    pub e: f64,
    /// Height $h$ of its centre of gravity on Ok (m).
    pub h: f64,
    /// $A$, moment about OI (kg m²).
    pub a: f64,
    /// $B$, moment about Oj (kg m²).
    pub b: f64,
    /// $C$, moment about Ok (kg m²).
    pub c: f64,
    /// $L = \sum m\,zx$ (kg m²).
    pub l_product: f64,
    /// Mass $\mu_1$ of each wheel (kg).
    pub wheel_mass: f64,
    /// $A_1$ of each wheel about its contact point (kg m²).
    pub a1: f64,
    /// $B_1$ (kg m²).
    pub b1: f64,
    /// $C_1$ (kg m²).
    pub c1: f64,
    /// Wheelbase $l$ (m).
    pub wheelbase: f64,
    /// Fork offset $c$ (m).
    pub offset: f64,
}

impl BicycleParams {
    /// The memoir's constants: $R = 0.38$ m, $l = 1.10$ m (n° 52, 88), $c = 0.08$ m,
    /// $h = 1.00$ m (n° 89, 104), $e = 0.15$ m, $\mu = 70$ kg, $\mu_1 = 5$ kg (n° 95–96,
    /// "57 kg" in the OCR of n° 95), hoop wheels ($A_1, B_1, C_1 = \frac32, 2, \frac12\,
    /// \mu_1R^2$, n° 4), $g = 9.81$ m/s². The frame's $A, B, C, L$ are not in the memoir:
    /// the values here ($A = 75$, $B = 78$, $C = 8$, $L = 6$ kg m², a 70 kg rider and frame
    /// about the rear contact point) are illustrative only.
    pub fn memoir() -> BicycleParams {
        let (radius, wheel_mass) = (0.38, 5.0);
        let m = wheel_mass * radius * radius;
        BicycleParams {
            radius,
            g: 9.81,
            mass: 70.0,
            e: 0.15,
            h: 1.0,
            a: 75.0,
            b: 78.0,
            c: 8.0,
            l_product: 6.0,
            wheel_mass,
            a1: 1.5 * m,
            b1: 2.0 * m,
            c1: 0.5 * m,
            wheelbase: 1.10,
            offset: 0.08,
        }
    }
}

/// A steady state: the inputs of the generated program (angles in radians, rates in 1/s).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SteadyState {
    /// Lean θ of the frame.
    pub theta: f64,
    /// Lean θ₁ of the front wheel.
    pub theta1: f64,
    /// Heading α of the front wheel relative to the frame (n° 57).
    pub alpha: f64,
    /// Frame angle η (σ of ch. I).
    pub eta: f64,
    /// Contact angle ω of the front wheel (μ of ch. I).
    pub omega: f64,
    /// Rolling rate $s$ of the rear wheel.
    pub s: f64,
    /// Rolling rate $s_1$ of the front wheel on the ground.
    pub s1: f64,
    /// Turning rate $n$.
    pub n: f64,
    /// $d\eta/d\theta$.
    pub deta: f64,
    /// $d\nu/d\theta$.
    pub dnu: f64,
    /// $d\eta/d\gamma$.
    pub deta_g: f64,
    /// $d\nu/d\gamma$.
    pub dnu_g: f64,
    /// Fall rate $p$ (only the kinetic-energy outputs use it).
    pub p: f64,
    /// Rate η′ (only the kinetic-energy outputs use it).
    pub deta_t: f64,
}

/// A bicycle with validated constants.
///
/// # Example
/// ```
/// use carvallo::bicycle::steady::{BicycleParams, BicycleSteady};
///
/// let b = BicycleSteady::new(BicycleParams::memoir())?;
/// // n° 88 at 20 km/h: tan(alpha)/tan(theta) = -g l/(R s)^2.
/// let ratio = b.tan_alpha_over_tan_theta(20.0 / 3.6 / 0.38);
/// assert!((ratio + 0.3497).abs() < 1e-3);
/// # Ok::<(), carvallo::ParameterError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BicycleSteady {
    p: BicycleParams,
}

fn check_finite(name: &'static str, value: f64) -> Result<f64, ParameterError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ParameterError::InvalidParameter { name, value, reason: "must be finite" })
    }
}

impl BicycleSteady {
    /// Validates the constants.
    ///
    /// # Errors
    /// [`ParameterError::InvalidParameter`] naming the first offending value: `radius`, `g`,
    /// `mass`, `h`, `a`, `b`, `c`, `wheel_mass`, `wheelbase` must be positive; `e`,
    /// `l_product`, `offset` finite; `a1`, `b1`, `c1` positive; the frame's moments must
    /// satisfy the triangle inequalities of a mass distribution, reported on the moment that
    /// breaks them.
    pub fn new(p: BicycleParams) -> Result<BicycleSteady, ParameterError> {
        for (name, v) in [
            ("radius", p.radius),
            ("g", p.g),
            ("mass", p.mass),
            ("h", p.h),
            ("a", p.a),
            ("b", p.b),
            ("c", p.c),
            ("wheel_mass", p.wheel_mass),
            ("a1", p.a1),
            ("b1", p.b1),
            ("c1", p.c1),
            ("wheelbase", p.wheelbase),
        ] {
            ParameterError::check_positive(name, v)?;
        }
        check_finite("e", p.e)?;
        check_finite("l_product", p.l_product)?;
        check_finite("offset", p.offset)?;
        for (name, x, y, z) in [("a", p.a, p.b, p.c), ("b", p.b, p.c, p.a), ("c", p.c, p.a, p.b)] {
            if x > y + z {
                return Err(ParameterError::InvalidParameter {
                    name,
                    value: x,
                    reason: "exceeds the sum of the two other moments",
                });
            }
        }
        Ok(BicycleSteady { p })
    }

    /// The constants.
    pub fn params(&self) -> BicycleParams {
        self.p
    }

    /// Every output of the program at the state `x`, in the order of
    /// [`all_scene::OUTPUTS`].
    pub fn eval(&self, x: &SteadyState) -> [f64; all_scene::OUTPUTS.len()] {
        let mut args = [0.0; all_scene::PARAMS.len() + all_scene::INPUTS.len()];
        let values = self.arguments(x);
        let names = all_scene::PARAMS.iter().chain(all_scene::INPUTS.iter());
        for (slot, name) in args.iter_mut().zip(names) {
            *slot = values.iter().find(|(n, _)| n == name).map_or(f64::NAN, |(_, v)| *v);
        }
        all_scene::eval_array(&args)
    }

    /// The program's parameters and inputs at the state `x`, by name: the constants, then the
    /// state's angles and rates.
    pub fn arguments(&self, x: &SteadyState) -> [(&'static str, f64); 29] {
        let p = &self.p;
        [
            ("R", p.radius),
            ("g", p.g),
            ("mu", p.mass),
            ("e", p.e),
            ("h", p.h),
            ("A", p.a),
            ("B", p.b),
            ("C", p.c),
            ("L", p.l_product),
            ("mu1", p.wheel_mass),
            ("A1", p.a1),
            ("B1", p.b1),
            ("C1", p.c1),
            ("l", p.wheelbase),
            ("c", p.offset),
            ("theta", x.theta),
            ("theta1", x.theta1),
            ("alpha", x.alpha),
            ("eta", x.eta),
            ("omega", x.omega),
            ("s", x.s),
            ("s1", x.s1),
            ("n", x.n),
            ("deta", x.deta),
            ("dnu", x.dnu),
            ("deta_g", x.deta_g),
            ("dnu_g", x.dnu_g),
            ("p", x.p),
            ("deta_t", x.deta_t),
        ]
    }

    /// One output of the program by name; `None` when no output has that name.
    pub fn output(&self, x: &SteadyState, name: &str) -> Option<f64> {
        let i = all_scene::OUTPUTS.iter().position(|o| *o == name)?;
        Some(self.eval(x)[i])
    }

    fn get(&self, x: &SteadyState, name: &str) -> f64 {
        self.output(x, name).unwrap_or(f64::NAN)
    }

    /// n° 88: $\tan\alpha/\tan\theta$ along (3)′ of n° 86 bis at the rolling rate `s`.
    pub fn tan_alpha_over_tan_theta(&self, s: f64) -> f64 {
        self.get(&SteadyState { s, ..SteadyState::default() }, "ratio_88")
    }

    /// n° 87: the memoir's curvature $n/s$ along (3)′ at lean `theta` and rolling rate `s`.
    pub fn curvature(&self, theta: f64, s: f64) -> f64 {
        self.get(&SteadyState { theta, s, ..SteadyState::default() }, "curvature_87")
    }

    /// n° 95: $\theta_1/\theta$ of the first-order handlebar equation (derived, with the front
    /// wheel's weight term $\mu_1 R g\sin\omega\sin\theta_1$ kept whole) at frame angle `eta`.
    pub fn theta1_over_theta(&self, eta: f64) -> f64 {
        self.get(&SteadyState { eta, ..SteadyState::default() }, "theta1_over_theta")
    }

    /// The same ratio from the memoir's printed (1)′ of n° 95 ($\mu_1$ for $\mu_1\sin\omega$).
    pub fn memoir_theta1_over_theta(&self, eta: f64) -> f64 {
        self.get(&SteadyState { eta, ..SteadyState::default() }, "memoir_theta1_over_theta")
    }

    /// n° 97: the ratio $\theta_1/\theta$ the geometry imposes at first order with (3)′.
    pub fn geometric_theta1_over_theta(&self, eta: f64, s: f64) -> f64 {
        self.get(&SteadyState { eta, s, ..SteadyState::default() }, "theta1_over_theta_geometry")
    }

    /// Beyond the memoir: the forward speed $Rs$ (m/s) at which a steady turn without hands
    /// and without lateral shift satisfies both the handlebar equation and the geometry at
    /// first order; `None` when the two ratios never agree ($s^2 \le 0$).
    pub fn no_hands_speed(&self, eta: f64) -> Option<f64> {
        let s2 = self.get(&SteadyState { eta, ..SteadyState::default() }, "no_hands_s2");
        (s2 > 0.0).then(|| self.p.radius * s2.sqrt())
    }

    /// n° 98: the lateral shift ε/θ of the rider a steady turn without hands needs at rolling
    /// rate `s` (derived ratio).
    pub fn lateral_shift(&self, eta: f64, s: f64) -> f64 {
        self.get(&SteadyState { eta, s, ..SteadyState::default() }, "shift_98")
    }

    /// n° 98 exactly at first order: the lateral shift ε/θ of a steady turn without hands at
    /// rolling rate `s`, from the mechanics engine's bicycle with the body turned about the
    /// frame's ground trace, linearised (generated `shift_98_exact`; the wheels' diametral
    /// moment about the centre is $C_1$). [`Self::lateral_shift`] is the memoir's route, which
    /// reduces the fall equation first (n° 86).
    pub fn lateral_shift_exact(&self, eta: f64, s: f64) -> f64 {
        self.get(&SteadyState { eta, s, ..SteadyState::default() }, "shift_98_exact")
    }
}
