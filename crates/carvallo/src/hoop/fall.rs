//! The fall laws of memoir n° 9: the motion of the fall angle $\theta$ of a hoop released with
//! no fall rate ($p_0 = 0$) from a state $(\theta_0, s_0, n_0)$ close to a steady state, to first
//! order in the initial fall acceleration $f = p'(0)$.
//!
//! With $f$ the value of (E) (n° 8) at the initial state and $f_1 = p''/p$ the coefficient of the
//! recursion (7), which the derivation shows to be minus the first member of (S) (n° 9, n° 77),
//! the memoir's series $p = ft + ff_1t^3/3! + ff_1^2t^5/5! + \dots$ sums to
//! $$\theta - \theta_0 = f\,\frac{\cosh(\sqrt{f_1}\,t) - 1}{f_1},$$
//! which is the uniformly accelerated fall (8) $\tfrac12 ft^2$ for $f_1 = 0$, the exponential fall
//! (10) $\frac{f}{h^2}(\cosh ht - 1)$ for $f_1 = h^2 > 0$ and the pendular motion (11)
//! $\frac{2f}{h^2}\sin^2\frac{ht}2$ for $f_1 = -h^2 < 0$, about the mean position
//! $\theta_0 + f/h^2$.

use super::Hoop;

/// Which of the three laws of n° 9 applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FallRegime {
    /// $f_1 = 0$: uniformly accelerated fall, formula (8).
    Uniform,
    /// $f_1 > 0$: exponential fall, formula (10); the state is unstable.
    Exponential,
    /// $f_1 < 0$: pendular motion, formula (11); the state is stable.
    Pendular,
}

/// The first-order fall law of n° 9 from the state $(\theta_0, s_0, n_0)$ with $p_0 = 0$.
///
/// # Example
/// ```
/// use carvallo::hoop::{fall::{FallLaw, FallRegime}, Hoop};
///
/// let hoop = Hoop::new(0.5, 1.0, 9.81)?;
/// // Upright, rolling fast and leaning a little: the fall is pendular (n° 9, n° 14).
/// let law = FallLaw::new(&hoop, 0.01, 2.0 * hoop.rate_unit(), 0.0);
/// assert_eq!(law.regime(), FallRegime::Pendular);
/// let h = (-law.f1).sqrt();
/// // After a half period the lean is at its extreme 2f/h^2 from the start.
/// let extreme = law.theta(std::f64::consts::PI / h) - 0.01;
/// assert!((extreme - 2.0 * law.f / (h * h)).abs() < 1e-12 * extreme.abs());
/// # Ok::<(), carvallo::ParameterError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FallLaw {
    /// The initial fall angle $\theta_0$ (rad).
    pub theta0: f64,
    /// $f = p'(0)$, the value of (E) of n° 8 at the initial state (1/s²).
    pub f: f64,
    /// $f_1 = p''/p$ at the initial state, minus the first member of (S) of n° 9 (1/s²).
    pub f1: f64,
}

impl FallLaw {
    /// The law from the state $(\theta_0, s_0, n_0)$, $p_0 = 0$: $f$ from the generated (E)
    /// ([`Hoop::equilibrium`]) and $f_1$ from the generated (S) ([`Hoop::stability`]).
    pub fn new(hoop: &Hoop, theta0: f64, s0: f64, n0: f64) -> FallLaw {
        FallLaw { theta0, f: hoop.equilibrium(theta0, s0, n0), f1: -hoop.stability(theta0, s0, n0) }
    }

    /// The regime: the sign of $f_1$ (exactly zero gives [`FallRegime::Uniform`]).
    pub fn regime(&self) -> FallRegime {
        if self.f1 > 0.0 {
            FallRegime::Exponential
        } else if self.f1 < 0.0 {
            FallRegime::Pendular
        } else {
            FallRegime::Uniform
        }
    }

    /// $(\cosh(\sqrt{f_1}t) - 1)/f_1$ for any sign of $f_1$ (its limit $t^2/2$ at $f_1 = 0$),
    /// by its series where $|f_1|t^2$ is small.
    fn kernel(&self, t: f64) -> f64 {
        let z = self.f1 * t * t;
        if z.abs() < 1e-3 {
            // t^2 (1/2 + z/24 + z^2/720 + z^3/40320): truncation below 1e-15 relative.
            t * t * (0.5 + z * (1.0 / 24.0 + z * (1.0 / 720.0 + z / 40320.0)))
        } else if self.f1 > 0.0 {
            // cosh x - 1 = 2 sinh^2(x/2), free of cancellation.
            2.0 * (0.5 * self.f1.sqrt() * t).sinh().powi(2) / self.f1
        } else {
            let h = (-self.f1).sqrt();
            2.0 * (0.5 * h * t).sin().powi(2) / (h * h)
        }
    }

    /// The fall angle at time `t` (s): $\theta_0 + \frac12 ft^2$ (8), $\theta_0 + \frac
    /// f{h^2}(\cosh ht - 1)$ (10) or $\theta_0 + \frac{2f}{h^2}\sin^2\frac{ht}2$ (11).
    pub fn theta(&self, t: f64) -> f64 {
        self.theta0 + self.f * self.kernel(t)
    }

    /// The fall rate $p$ at time `t` (rad/s): $ft$, $\frac fh\sinh ht$ or $\frac fh\sin ht$.
    pub fn p(&self, t: f64) -> f64 {
        let z = self.f1 * t * t;
        if z.abs() < 1e-3 {
            self.f * t * (1.0 + z * (1.0 / 6.0 + z * (1.0 / 120.0 + z / 5040.0)))
        } else if self.f1 > 0.0 {
            let h = self.f1.sqrt();
            self.f / h * (h * t).sinh()
        } else {
            let h = (-self.f1).sqrt();
            self.f / h * (h * t).sin()
        }
    }

    /// The mean position $\theta_0 + f/h^2$ of the pendular motion (n° 9); `None` unless
    /// $f_1 < 0$.
    pub fn mean_position(&self) -> Option<f64> {
        (self.f1 < 0.0).then(|| self.theta0 - self.f / self.f1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_three_laws_join_continuously() {
        let law = |f1: f64| FallLaw { theta0: 0.1, f: 2.0, f1 };
        for t in [0.01, 0.3, 1.0] {
            let uniform = law(0.0).theta(t);
            assert!((uniform - (0.1 + t * t)).abs() < 1e-15);
            // Either side of f1 = 0 the kernel tends to t^2/2: first order in f1.
            for f1 in [1e-6, -1e-6] {
                assert!((law(f1).theta(t) - uniform).abs() < 1e-6 * t.powi(4));
            }
            // The series branch and the closed forms meet where the branch changes.
            let z = 1e-3 / (t * t);
            for f1 in [z, -z] {
                let below = law(f1 * (1.0 - 1e-12)).theta(t);
                let above = law(f1 * (1.0 + 1e-12)).theta(t);
                assert!((below - above).abs() < 1e-13, "{f1}: {below} {above}");
            }
        }
        assert_eq!(law(-4.0).mean_position(), Some(0.6));
        assert_eq!(law(4.0).mean_position(), None);
    }

    #[test]
    fn the_rate_is_the_derivative_of_the_angle() {
        for f1 in [-3.0, 0.0, 3.0] {
            let law = FallLaw { theta0: 0.0, f: 1.5, f1 };
            for t in [0.2, 0.9] {
                let h = 1e-5;
                let slope = (law.theta(t + h) - law.theta(t - h)) / (2.0 * h);
                assert!((slope - law.p(t)).abs() < 1e-8, "f1 = {f1}, t = {t}");
            }
        }
    }
}
