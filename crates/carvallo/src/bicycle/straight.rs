//! The bicycle without hands near straight running (memoir n° 107–123): the fall and handlebar
//! equations at first order, the characteristic quartic with $T = st$ (n° 118–119) and the
//! stable range of the wheels' spin $s$ (n° 120–121), forward speed $v = Rs$.
//!
//! Carvallo's equations (n° 117), rows (fall $(\delta\theta)$, handlebar $(\delta\gamma)$),
//! columns (lean $\theta$, steer $\gamma$):
//! $\mathfrak A''\theta'' + \mathfrak A'\theta' + \mathfrak A\theta + \mathfrak B''\gamma'' +
//! \mathfrak B'\gamma' + \mathfrak B\gamma = 0$ and the same with index 1. Their coefficients
//! have the form $\mathfrak X'' = m$, $\mathfrak X' = c\,s$, $\mathfrak X = k_0 + k_2 s^2$,
//! held by [`Equations`] from three sources:
//! * [`Equations::memoir_118`]: the numbers printed in n° 118 (and n° 117);
//! * [`Equations::from_formulas`]: Carvallo's closed forms of n° 117 (the column sums of the
//!   n° 116 tables, `generated/bicycle_straight.ir`) at any [`Constants`];
//! * [`Equations::via_whipple`]: the exact linearisation of Carvallo's model through the
//!   general Carvallo–Whipple bicycle (`generated/whipple.ir`, Kane's method) with the mapping
//!   of [`Constants::whipple_values`]: hoop wheels, massless fork and handlebar, trail
//!   $c_1/\cos\eta$, steer tilt $\eta$, $\theta = \varphi$, $\gamma = -\delta$, the handlebar
//!   equation being minus the steer equation.
//!
//! Stability (n° 120–121): with $T = st$ the characteristic equation is a quartic
//! $q_4\lambda^4 + q_3\lambda^3 + q_2\lambda^2 + q_1\lambda + q_0$ whose coefficients depend on
//! $s^2$; for $s > 0$ the real parts of $\lambda$ and of the time eigenvalues $s\lambda$ have
//! the same sign, so the Routh–Hurwitz conditions (all $q_i$ of the sign of $q_4$ and
//! $H_3 = q_1(q_2q_3 - q_1q_4) - q_0q_3^2$ of the sign of $q_4^3$) decide it. Carvallo's lower
//! limit condition $a_3^2 - a_1a_2a_3 + a_1^2a_4 = 0$ of n° 121 is $-H_3 = 0$ for the monic
//! quartic (checked symbolically at regeneration). [`window`] scans $s$ and bisects each sign
//! change to adjacent floats.

use crate::error::ParameterError;
use crate::numerics::ode::rk4_step;
use crate::numerics::poly::bisect_unchecked;

crate::scene! {
    /// The general model's matrices, evaluated at Carvallo's parameter set.
    pub mod general_scene {
        model: whipple,
        outputs: [m11, m12, m21, m22, c1_11, c1_12, c1_21, c1_22,
                  k0_11, k0_12, k0_21, k0_22, k2_11, k2_12, k2_21, k2_22],
    }
}

crate::scene! {
    /// Carvallo's coefficients of n° 117 (column sums of the n° 116 tables) and the upper
    /// limits of n° 122, from `generated/bicycle_straight.ir`.
    pub mod straight_scene {
        model: bicycle_straight,
        outputs: [fall_a2, fall_a1, fall_a0, fall_b2, fall_b1, fall_b0,
                  bar_a2, bar_a1, bar_a0, bar_b2, bar_b1, bar_b0,
                  s2_upper, s2_upper_half_trail],
    }
}

/// A 2 × 2 matrix by rows: (fall, handlebar) equation × (θ, γ).
pub use crate::numerics::mat2::Mat2;

/// The characteristic constants of Carvallo's bicycle (n° 117; metre, kilogram, second).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Constants {
    /// Wheel radius $R$ (both wheels).
    pub r: f64,
    /// Wheelbase $l$.
    pub l: f64,
    /// Distance $c_1 = R\sin\eta - c$ of the front contact from the steering axis.
    pub c1: f64,
    /// Angle $\eta$ of the steering axis with the vertical (rad).
    pub eta: f64,
    /// Forward distance $e$ of the mounted frame's centre of mass from the rear wheel.
    pub e: f64,
    /// Height $h$ of the mounted frame's centre of mass.
    pub h: f64,
    /// Mass $\mu$ of the mounted frame (frame and rider).
    pub mu: f64,
    /// Mass $\mu_1$ of each wheel (a hoop).
    pub mu1: f64,
    /// $A + 2A_1$: the frame's and the two wheels' moments about the ground line (kg m²).
    pub a2: f64,
    /// The frame's moment $C$ about the vertical through the rear contact (kg m²).
    pub c: f64,
    /// The frame's product of inertia $L = \sum m x z$ about the rear contact (kg m²).
    pub ll: f64,
    /// Gravity $g$ (m/s²).
    pub g: f64,
}

impl Constants {
    /// The old bicycle of n° 117: $R = 0.38$, $l = 1.10$, $c_1 = 0.08$, $\eta = 25°$,
    /// $e = 0.20$, $h = 1$, $\mu = 70$, $\mu_1 = 5$, $A + 2A_1 = 100$, $C = 4$, $L = 14$;
    /// $g = 9.81$ (not printed; $\mathfrak A = -g(\mu h + 2\mu_1R) = -724$ implies it).
    pub const MEMOIR: Constants = Constants {
        r: 0.38,
        l: 1.10,
        c1: 0.08,
        eta: 25.0 * std::f64::consts::PI / 180.0,
        e: 0.20,
        h: 1.0,
        mu: 70.0,
        mu1: 5.0,
        a2: 100.0,
        c: 4.0,
        ll: 14.0,
        g: 9.81,
    };

    /// The new bicycle of n° 122 ($e = 0.35$, $\tfrac12\mu = 32$, $l = 1.15$, $\mu_1 = 3.5$, the
    /// other constants as in n° 117; only the upper limit is discussed for it).
    pub const MEMOIR_NEW: Constants =
        Constants { e: 0.35, mu: 64.0, l: 1.15, mu1: 3.5, ..Constants::MEMOIR };

    /// Checks that the constants can describe a bicycle.
    ///
    /// # Errors
    /// [`ParameterError::InvalidParameter`] for a non-finite value, a non-positive length,
    /// mass, moment or gravity, an angle outside $(0, \pi/2)$ or a frame moment $A$ that the
    /// wheels' $2A_1 = 3\mu_1R^2$ leave non-positive.
    pub fn validate(&self) -> Result<(), ParameterError> {
        for (name, value) in [
            ("r", self.r),
            ("l", self.l),
            ("h", self.h),
            ("mu", self.mu),
            ("mu1", self.mu1),
            ("a2", self.a2),
            ("c", self.c),
            ("g", self.g),
        ] {
            ParameterError::check_positive(name, value)?;
        }
        for (name, value) in [("c1", self.c1), ("e", self.e), ("ll", self.ll)] {
            if !value.is_finite() {
                return Err(ParameterError::InvalidParameter {
                    name,
                    value,
                    reason: "must be finite",
                });
            }
        }
        if !(self.eta > 0.0 && self.eta < std::f64::consts::FRAC_PI_2) {
            return Err(ParameterError::InvalidParameter {
                name: "eta",
                value: self.eta,
                reason: "must lie strictly between 0 and pi/2",
            });
        }
        if self.a2 <= 3.0 * self.mu1 * self.r * self.r {
            return Err(ParameterError::InvalidParameter {
                name: "a2",
                value: self.a2,
                reason: "must exceed the wheels' 3 mu1 r^2",
            });
        }
        Ok(())
    }

    /// Carvallo's model as a parameter set of the general Carvallo–Whipple bicycle, by
    /// benchmark name (see [`crate::whipple::PARAM_NAMES`]): `w` $= l$, `c` $= c_1/\cos\eta$,
    /// `lambda` $= \eta$, hoop wheels `rR = rF` $= R$, `mR = mF` $= \mu_1$, `IRxx = IFxx`
    /// $= \tfrac12\mu_1R^2$, `IRyy = IFyy` $= \mu_1R^2$; the rear body is the mounted frame,
    /// `mB` $= \mu$, `xB` $= e$, `zB` $= -h$, `IBxx` $= A + 2A_1 - 3\mu_1R^2 - \mu h^2$, `IBzz`
    /// $= C - \mu e^2$, `IBxz` $= L - \mu e h$ (`IByy` does not enter the linear equations;
    /// set to `IBxx + IBzz`); the front frame is massless (`mH` and its moments 0, `xH`, `zH`
    /// at the front axle). These values are not a valid [`crate::whipple::WhippleParams`]
    /// (which requires a front frame of positive mass), so they are evaluated directly.
    pub fn whipple_values(&self) -> [(&'static str, f64); 26] {
        let k = self;
        let r2 = k.r * k.r;
        let ibxx = k.a2 - 3.0 * k.mu1 * r2 - k.mu * k.h * k.h;
        let ibzz = k.c - k.mu * k.e * k.e;
        [
            ("w", k.l),
            ("c", k.c1 / k.eta.cos()),
            ("lambda", k.eta),
            ("g", k.g),
            ("rR", k.r),
            ("mR", k.mu1),
            ("IRxx", 0.5 * k.mu1 * r2),
            ("IRyy", k.mu1 * r2),
            ("xB", k.e),
            ("zB", -k.h),
            ("mB", k.mu),
            ("IBxx", ibxx),
            ("IByy", ibxx + ibzz),
            ("IBzz", ibzz),
            ("IBxz", k.ll - k.mu * k.e * k.h),
            ("xH", k.l),
            ("zH", -k.r),
            ("mH", 0.0),
            ("IHxx", 0.0),
            ("IHyy", 0.0),
            ("IHzz", 0.0),
            ("IHxz", 0.0),
            ("rF", k.r),
            ("mF", k.mu1),
            ("IFxx", 0.5 * k.mu1 * r2),
            ("IFyy", k.mu1 * r2),
        ]
    }

    /// The outputs of `generated/bicycle_straight.ir` at these constants and the spin `s`, in
    /// the order of [`straight_scene::OUTPUTS`] (no validation).
    pub fn generated(&self, s: f64) -> [f64; straight_scene::OUTPUTS.len()] {
        let k = self;
        let values = [
            ("R", k.r),
            ("l", k.l),
            ("c_1", k.c1),
            ("eta", k.eta),
            ("ecg", k.e),
            ("h", k.h),
            ("mu", k.mu),
            ("mu1", k.mu1),
            ("A2", k.a2),
            ("C", k.c),
            ("L", k.ll),
            ("g", k.g),
            ("s", s),
        ];
        let mut args = [0.0; straight_scene::PARAMS.len() + straight_scene::INPUTS.len()];
        let names = straight_scene::PARAMS.iter().chain(straight_scene::INPUTS.iter());
        for (slot, name) in args.iter_mut().zip(names) {
            *slot = values.iter().find(|(n, _)| n == name).map_or(f64::NAN, |(_, v)| *v);
        }
        straight_scene::eval_array(&args)
    }

    /// The upper limit of $s^2$ (n° 120, n° 122): the root in $s^2$ of the quartic's constant
    /// term, and the same for $c_1 = R\sin\eta/2$ (which ignores `c1`), from the generated IR.
    /// The derivation checks them symbolically equal to the closed forms printed in n° 122,
    /// $s^2 = gQ(\mu h\sin\eta + \mu_1R\sin\eta - \mu ec_1/l) / (R(R/l)\cos\eta\,
    /// [(\mu h + 2\mu_1R)(\mu ec_1/l + 2\mu_1R\sin\eta) - (\mu h + 4\mu_1R)Q])$,
    /// $Q = \mu ec_1/l + \mu_1R\sin\eta$ (with $B_1 = 2\mu_1R^2$), and
    /// $s^2 = \frac{g\sin\eta}{R(R/l)\cos\eta}\left(\frac12\frac{\mu}{\mu_1}\frac el + 1\right)
    /// \frac{h - \frac12Re/l + (\mu_1/\mu)R}{h - Re/l}$ (checks `upper_limit_closed_form`,
    /// `upper_limit_half_trail` of `generated/bicycle_straight.checks.tsv`).
    pub fn upper_limit_s2(&self) -> (f64, f64) {
        let o = self.generated(0.0);
        (o[12], o[13])
    }
}

/// A part of Carvallo's bicycle: a column of the tables of n° 116 (the fork and handlebar are
/// massless, n° 117).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// The mounted frame (frame and rider), the rear body of the general model.
    Frame,
    /// The rear wheel.
    RearWheel,
    /// The front wheel.
    FrontWheel,
}

impl Part {
    /// The three parts, in the order of the tables.
    pub const ALL: [Part; 3] = [Part::Frame, Part::RearWheel, Part::FrontWheel];

    /// The part's mass and moments among the general model's parameters
    /// ([`Constants::whipple_values`]).
    pub fn whipple_names(self) -> &'static [&'static str] {
        match self {
            Part::Frame => &["mB", "IBxx", "IByy", "IBzz", "IBxz"],
            Part::RearWheel => &["mR", "IRxx", "IRyy"],
            Part::FrontWheel => &["mF", "IFxx", "IFyy"],
        }
    }
}

/// The coefficients of the two equations: $\mathfrak X'' = m$, $\mathfrak X' = c\,s$,
/// $\mathfrak X = k_0 + k_2 s^2$ (rows fall, handlebar; columns θ, γ).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Equations {
    /// Coefficients of the second derivatives.
    pub m: Mat2,
    /// Coefficients of the first derivatives, per unit $s$.
    pub c: Mat2,
    /// Coefficients of the angles at $s = 0$ (gravity).
    pub k0: Mat2,
    /// Coefficients of the angles, part proportional to $s^2$.
    pub k2: Mat2,
}

impl Equations {
    /// The numbers printed in n° 118 (identical to those of n° 117):
    /// $a'' = 100$, $a' = 0$, $a = -724/s^2$, $b'' = -1.476$, $b' = -7.83$,
    /// $b = -9.21 + 17.85/s^2$; $a_1'' = -1.48$, $a_1' = 0.757$, $a_1 = 17.85/s^2$,
    /// $b_1'' = 0.56$, $b_1' = 0.535$, $b_1 = 0.312 - 7.54/s^2$.
    pub const MEMOIR_118: Equations = Equations {
        m: [[100.0, -1.476], [-1.48, 0.56]],
        c: [[0.0, -7.83], [0.757, 0.535]],
        k0: [[-724.0, 17.85], [17.85, -7.54]],
        k2: [[0.0, -9.21], [0.0, 0.312]],
    };

    /// The numbers of n° 118.
    pub fn memoir_118() -> Equations {
        Equations::MEMOIR_118
    }

    /// Carvallo's coefficients of n° 117 at `k`: the column sums of the n° 116 tables,
    /// evaluated from `generated/bicycle_straight.ir`. The derivation checks them
    /// symbolically equal to the closed forms printed in n° 117 (with the first term of
    /// $\mathfrak B_1'$ read $Rc_1/l^2$; the OCR prints $Rc_1/l$), with the hoop moments
    /// $A_1 = \tfrac32\mu_1R^2$, $B_1 = 2\mu_1R^2$, $C_1 = \tfrac12\mu_1R^2$ (n° 4):
    ///
    /// $\mathfrak A'' = A + 2A_1$, $\mathfrak A' = 0$, $\mathfrak A = -g(\mu h + 2\mu_1R)$,
    /// $\mathfrak B'' = -(Lc_1/l + A_1\sin\eta)$,
    /// $\mathfrak B' = -s[(c_1/l)(\mu Rh + 2B_1) + \cos\eta(LR/l + B_1)]$,
    /// $\mathfrak B = -s^2(R/l)\cos\eta(\mu Rh + 2B_1) + gQ$ with
    /// $Q = \mu e c_1/l + \mu_1R\sin\eta$;
    /// $\mathfrak A_1'' = \mathfrak B''$, $\mathfrak A_1' = s(B_1 - \mu_1R^2)(2c_1/l + \cos\eta)$,
    /// $\mathfrak A_1 = gQ$,
    /// $\mathfrak B_1'' = (C + C_1)(c_1/l)^2 + C_1(c_1/l + \cos\eta)^2 + A_1\sin^2\eta$,
    /// $\mathfrak B_1' = s[(Rc_1/l^2)\cos\eta(C + 2C_1) + C_1(R/l)\cos^2\eta +
    /// \mu Re(c_1/l)^2 + \mu_1R^2\sin\eta(\cos\eta + c_1/l)]$,
    /// $\mathfrak B_1 = s^2(R/l)\cos\eta(\mu Rec_1/l + B_1\sin\eta) - gQ\sin\eta$,
    /// and every table entry equal, part by part and origin by origin, to the general model's
    /// at three rational points. The split $\mathfrak X = k_0 + k_2s^2$ is read from the values
    /// at $s = 0$ and $s = 1$.
    ///
    /// These are Carvallo's equations; [`Equations::via_whipple`] is the independent
    /// evaluation of the general model they are tested against at run time
    /// (`tests/it/bicycle/straight.rs`).
    ///
    /// # Errors
    /// [`ParameterError`] from [`Constants::validate`].
    pub fn from_formulas(k: &Constants) -> Result<Equations, ParameterError> {
        k.validate()?;
        let (o0, o1) = (k.generated(0.0), k.generated(1.0));
        let mat = |f: &dyn Fn(usize) -> f64| -> Mat2 {
            std::array::from_fn(|r| std::array::from_fn(|c| f(6 * r + 3 * c)))
        };
        Ok(Equations {
            m: mat(&|i| o1[i]),
            c: mat(&|i| o1[i + 1]),
            k0: mat(&|i| o0[i + 2]),
            k2: mat(&|i| o1[i + 2] - o0[i + 2]),
        })
    }

    /// The exact linearisation of Carvallo's model through the general Carvallo–Whipple
    /// bicycle ([`Constants::whipple_values`]): $m = \pm M$, $c = \pm R\,C_1$, $k_0 = \pm gK_0$,
    /// $k_2 = \pm R^2K_2$, the sign $-$ for the handlebar row and for the steer column (not both).
    ///
    /// # Errors
    /// [`ParameterError`] from [`Constants::validate`].
    pub fn via_whipple(k: &Constants) -> Result<Equations, ParameterError> {
        k.validate()?;
        Ok(Equations::from_whipple_values(k, &k.whipple_values()))
    }

    /// The contribution of one [`Part`] to [`Equations::via_whipple`]: the general model with
    /// the masses and moments of the two other parts set to zero (its equations are linear in
    /// the masses and moments, so the three parts sum to the whole). These are the columns of
    /// Carvallo's n° 116 tables, computed independently of them.
    ///
    /// # Errors
    /// [`ParameterError`] from [`Constants::validate`].
    pub fn via_whipple_part(k: &Constants, part: Part) -> Result<Equations, ParameterError> {
        k.validate()?;
        let mut values = k.whipple_values();
        for (name, value) in values.iter_mut() {
            if Part::ALL.iter().any(|p| *p != part && p.whipple_names().contains(name)) {
                *value = 0.0;
            }
        }
        Ok(Equations::from_whipple_values(k, &values))
    }

    /// The general model at the benchmark `values`, signs and scales as in
    /// [`Equations::via_whipple`] (no validation).
    fn from_whipple_values(k: &Constants, values: &[(&'static str, f64)]) -> Equations {
        let names = general_scene::PARAMS;
        let arr: [f64; general_scene::Args::LEN] = std::array::from_fn(|i| {
            names.get(i).and_then(|n| values.iter().find(|(k, _)| k == n)).map_or(0.0, |(_, x)| *x)
        });
        let o = general_scene::eval(&general_scene::Args::from_array(arr));
        let m = [[o.m11, o.m12], [o.m21, o.m22]];
        let c1 = [[o.c1_11, o.c1_12], [o.c1_21, o.c1_22]];
        let k0 = [[o.k0_11, o.k0_12], [o.k0_21, o.k0_22]];
        let k2 = [[o.k2_11, o.k2_12], [o.k2_21, o.k2_22]];
        let sign = |r: usize, c: usize| if (r == 1) != (c == 1) { -1.0 } else { 1.0 };
        let map = |x: &Mat2, f: f64| -> Mat2 {
            std::array::from_fn(|r| std::array::from_fn(|c| sign(r, c) * f * x[r][c]))
        };
        Equations { m: map(&m, 1.0), c: map(&c1, k.r), k0: map(&k0, k.g), k2: map(&k2, k.r * k.r) }
    }

    /// The twelve coefficients at spin `s` in the order of n° 117: fall equation
    /// $\mathfrak A'', \mathfrak A', \mathfrak A, \mathfrak B'', \mathfrak B', \mathfrak B$, then
    /// the handlebar equation's.
    pub fn coefficients(&self, s: f64) -> [f64; 12] {
        std::array::from_fn(|i| {
            let (r, c, d) = (i / 6, (i / 3) % 2, i % 3);
            match d {
                0 => self.m[r][c],
                1 => self.c[r][c] * s,
                _ => self.k0[r][c] + self.k2[r][c] * s * s,
            }
        })
    }

    /// The quartic of n° 119 in λ ($T = st$), coefficients of $\lambda^0, \dots, \lambda^4$.
    pub fn quartic(&self, s: f64) -> [f64; 5] {
        let tri = |r: usize, c: usize| {
            [self.k0[r][c] / (s * s) + self.k2[r][c], self.c[r][c], self.m[r][c]]
        };
        let (a, b, p, q) = (tri(0, 0), tri(0, 1), tri(1, 0), tri(1, 1));
        let mut out = [0.0; 5];
        for i in 0..3 {
            for j in 0..3 {
                out[i + j] += a[i] * q[j] - b[i] * p[j];
            }
        }
        out
    }
}

/// The quartic of n° 120 as printed (divided by its leading coefficient):
/// $\lambda^4 + 0.80\lambda^3 + (0.437 - 20.54/s^2)\lambda^2 + (0.1295 - 4.83/s^2)\lambda
/// - 1.143/s^2 + 95.6/s^4$, coefficients of $\lambda^0, \dots, \lambda^4$.
pub fn memoir_quartic_120(s: f64) -> [f64; 5] {
    let u = 1.0 / (s * s);
    [-1.143 * u + 95.6 * u * u, 0.1295 - 4.83 * u, 0.437 - 20.54 * u, 0.80, 1.0]
}

/// The Routh–Hurwitz functions of a quartic $[q_0, \dots, q_4]$, normalised so that the leading
/// coefficient is positive: $q_0, q_1, q_2, q_3, H_3 = q_1(q_2q_3 - q_1q_4) - q_0q_3^2$. All
/// positive iff every root has a negative real part.
pub fn hurwitz(q: &[f64; 5]) -> [f64; 5] {
    let sg = if q[4] < 0.0 { -1.0 } else { 1.0 };
    let [a0, a1, a2, a3, a4] = q.map(|x| sg * x);
    [a0, a1, a2, a3, a1 * (a2 * a3 - a1 * a4) - a0 * a3 * a3]
}

/// The stable range in the wheels' spin $s$ (rad/s).
#[derive(Clone, Debug, PartialEq)]
pub struct Window {
    /// The lowest $s$ at which $H_3$ turns from negative to positive (a complex pair crosses
    /// the imaginary axis: Carvallo's lower limit, n° 121); `None` if there is none below
    /// [`S_MAX`].
    pub weave_s: Option<f64>,
    /// The lowest $s$ at which $q_0$ turns from positive to negative (a real root crosses
    /// zero: the upper limit, n° 120); `None` if there is none below [`S_MAX`].
    pub capsize_s: Option<f64>,
    /// The maximal intervals of $s$ in $(0, S_{\max}]$ on which every root has a negative
    /// real part.
    pub stable_s: Vec<(f64, f64)>,
}

/// The largest spin scanned by [`window`] (rad/s; 38 m/s with $R = 0.38$).
pub const S_MAX: f64 = 100.0;
/// Grid points of the scan of [`window`].
const GRID: usize = 20_000;

/// Scans $s \in (0, S_{\max}]$ on a uniform grid of 20 000 points, bisects every sign change
/// of the Routh–Hurwitz functions ([`hurwitz`]) of `quartic(s)` to adjacent floats and returns
/// the weave and capsize limits and the stable intervals.
pub fn window(quartic: &dyn Fn(f64) -> [f64; 5]) -> Window {
    let h = |k: usize, s: f64| hurwitz(&quartic(s))[k];
    let step = S_MAX / GRID as f64;
    let mut cuts: Vec<(usize, f64, bool)> = Vec::new();
    for k in 0..5 {
        let f = |s: f64| h(k, s);
        let mut prev = f(step);
        for i in 2..=GRID {
            let s = step * i as f64;
            let y = f(s);
            if (y > 0.0) != (prev > 0.0) {
                cuts.push((k, bisect_unchecked(f, s - step, s), y > 0.0));
            }
            prev = y;
        }
    }
    let first = |k: usize, rising: bool| {
        cuts.iter().filter(|c| c.0 == k && c.2 == rising).map(|c| c.1).min_by(f64::total_cmp)
    };
    let mut edges: Vec<f64> = cuts.iter().map(|c| c.1).collect();
    edges.sort_by(f64::total_cmp);
    edges.dedup();
    let stable_at = |s: f64| hurwitz(&quartic(s)).iter().all(|x| *x > 0.0);
    let mut bounds = vec![step];
    bounds.extend(edges);
    bounds.push(S_MAX);
    let mut stable: Vec<(f64, f64)> = Vec::new();
    for w in bounds.windows(2) {
        if w[1] > w[0] && stable_at(0.5 * (w[0] + w[1])) {
            match stable.last_mut() {
                Some(last) if last.1 == w[0] => last.1 = w[1],
                _ => stable.push((w[0], w[1])),
            }
        }
    }
    Window { weave_s: first(4, true), capsize_s: first(0, false), stable_s: stable }
}

/// A forward speed in km/h from the spin `s` and the wheel radius `r` (n° 120:
/// $V = sR \cdot 3600/1000$).
pub fn km_per_hour(s: f64, r: f64) -> f64 {
    s * r * 3.6
}

/// Memoir n° 123: a pendulum $\theta'' = -a^2\theta - a^2k\,\mathrm{sgn}(\theta')$ (constant
/// friction $a^2k$) released at rest from $-\theta_0$ ($\theta_0 > k$), optionally with a weak
/// negative damping: $\theta'' - 2\varepsilon\theta' + a^2(\theta + k) = 0$. Integrated by RK4
/// with `steps` steps per unit of $1/a$ until $\theta'$ returns to zero (located by bisection of
/// the last step); returns the time and the elongation at that instant. Carvallo's closed
/// forms: $\pi/a$ and $\theta_0 - 2k$ for $\varepsilon = 0$; $-k + (\theta_0 - k)e^{\varepsilon
/// \pi/a}$ when $\varepsilon^2$ is neglected.
pub fn friction_half_swing(a: f64, k: f64, theta0: f64, eps: f64, steps: usize) -> (f64, f64) {
    let f = |y: [f64; 2]| [y[1], 2.0 * eps * y[1] - a * a * (y[0] + k)];
    let rk4 = |y: [f64; 2], h: f64| rk4_step(f, y, h);
    let h = 1.0 / (a * steps as f64);
    let mut y = [-theta0, 0.0];
    let mut t = 0.0;
    // Leave the start (where theta' = 0) before watching for the next zero.
    y = rk4(y, h);
    t += h;
    for _ in 0..(100 * steps) {
        let next = rk4(y, h);
        if next[1] <= 0.0 {
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if rk4(y, mid)[1] > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let tau = 0.5 * (lo + hi);
            return (t + tau, rk4(y, tau)[0]);
        }
        y = next;
        t += h;
    }
    (f64::NAN, f64::NAN)
}

/// Memoir n° 124: the virtual works of gravity on a mounted unicycle (mass $\mu$, centre of
/// mass at height $h$ on the wheel plane's axis $k$) on ground inclined by $i$, for the lean
/// $\theta$, the turn $\nu$ about the ground normal $K$ and the wheel rotation $\sigma$
/// (radius $R$), with $\delta$ the angle of the travel direction $I$ with the upward slope line.
///
/// Computed by central differences ($h = 10^{-5}$) of the potential $V = \mu g\,(G\cdot K')$
/// built from the vectors: ground axes $(x$ up the slope$, y, K)$, vertical $K' = (\sin i, 0,
/// \cos i)$, $I = (\cos\delta, \sin\delta, 0)$, $J = K\times I$, $k = -J\sin\theta +
/// K\cos\theta$ (n° 1), $G = O + hk$; a turn $\nu$ adds to $\delta$, a rotation $\sigma$
/// moves $O$ by $R\sigma I$. Returns $(-\partial V/\partial\theta, -\partial V/\partial\nu,
/// -\partial V/\partial\sigma)$.
pub fn incline_virtual_works(
    mu: f64,
    g: f64,
    h: f64,
    r: f64,
    i: f64,
    delta: f64,
    theta: f64,
) -> [f64; 3] {
    let v = |th: f64, nu: f64, sg: f64| {
        let d = delta + nu;
        let kv = [i.sin(), 0.0, i.cos()];
        let ii = [d.cos(), d.sin(), 0.0];
        let jj = [-d.sin(), d.cos(), 0.0];
        let kk = [0.0, 0.0, 1.0];
        let o = [r * sg * ii[0], r * sg * ii[1], 0.0];
        let gpos: [f64; 3] =
            std::array::from_fn(|n| o[n] + h * (-jj[n] * th.sin() + kk[n] * th.cos()));
        mu * g * (0..3).map(|n| gpos[n] * kv[n]).sum::<f64>()
    };
    let e = 1e-5;
    [
        -(v(theta + e, 0.0, 0.0) - v(theta - e, 0.0, 0.0)) / (2.0 * e),
        -(v(theta, e, 0.0) - v(theta, -e, 0.0)) / (2.0 * e),
        -(v(theta, 0.0, e) - v(theta, 0.0, -e)) / (2.0 * e),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_constants_by_name() {
        let bad = Constants { r: -0.38, ..Constants::MEMOIR };
        assert_eq!(
            Equations::from_formulas(&bad).unwrap_err().to_string(),
            "invalid r -0.38: must be positive"
        );
        let bad = Constants { eta: 2.0, ..Constants::MEMOIR };
        assert!(Equations::via_whipple(&bad)
            .unwrap_err()
            .to_string()
            .starts_with("invalid eta 2.0"));
    }

    #[test]
    fn hurwitz_of_a_known_quartic() {
        // (x + 1)(x + 2)(x^2 + x + 1) = x^4 + 4x^3 + 6x^2 + 5x + 2: stable.
        let h = hurwitz(&[2.0, 5.0, 6.0, 4.0, 1.0]);
        assert!(h.iter().all(|x| *x > 0.0), "{h:?}");
        // (x - 0.1)... a pair with positive real part: x^2 - 0.2x + 1 times (x + 1)^2.
        let q = [1.0, 1.8, 1.6, 1.8, 1.0];
        assert!(hurwitz(&q)[4] < 0.0);
    }
}
