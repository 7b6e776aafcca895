//! Two variants of the mounted unicycle beyond the equations of n° 22–24: the rider's pitch
//! about the wheel axle, which the memoir replaces by a constraint (n° 20) and whose stability
//! is the principle of its stable unicycle (n° 42, [`Pitch`]); and the rolling rate held
//! constant by the pedals, the case of n° 78 ([`Unicycle::rhs_constant_speed`]).
//!
//! # The pitch model (n° 42)
//! A wheel of radius $R$, mass $\mu_1$ and moment $I_1$ about its axle rolls on level ground
//! in its own plane; the rider, of mass $\mu$ and moment $J_G$ about its centre of gravity, is
//! hinged on the axle with no moment between wheel and rider (the pedals free), its centre of
//! gravity at the distance `arm` $= \ell$ from the axle, **below** it when $\ell > 0$. With
//! $x$ the axle's advance and $\varphi$ the angle of the rider's arm from the downward
//! vertical, Lagrange's equations are
//! $$\Big(\mu + \mu_1 + \frac{I_1}{R^2}\Big)\ddot x + \mu\ell\cos\varphi\,\ddot\varphi
//!   = \mu\ell\sin\varphi\,\dot\varphi^2,\qquad
//!   \mu\ell\cos\varphi\,\ddot x + (J_G + \mu\ell^2)\ddot\varphi = -\mu g\ell\sin\varphi,$$
//! and the upright (or hanging) rider $\varphi = 0$ has the linear rate
//! $\omega^2 = \mu g\ell / (J_G + \mu\ell^2 - \mu^2\ell^2/M')$, $M' = \mu + \mu_1 + I_1/R^2$:
//! an oscillation when the centre of gravity is below the axle, a fall when it is above.

use super::{all_scene, Unicycle};
use crate::error::ParameterError;
use crate::numerics::ode::rk4_step;

/// The rider hinged on the axle of a rolling wheel, in the wheel's plane (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pitch {
    radius: f64,
    g: f64,
    wheel_mass: f64,
    wheel_moment: f64,
    rider_mass: f64,
    rider_moment: f64,
    arm: f64,
}

impl Pitch {
    /// A wheel of radius `radius` (m), mass `wheel_mass` (kg) and moment `wheel_moment`
    /// (kg m²) about its axle, under gravity `g` (m/s²), carrying a rider of mass `rider_mass`
    /// (kg) and moment `rider_moment` (kg m²) about its own centre of gravity, at the distance
    /// `arm` (m) below the axle (negative: above).
    ///
    /// # Errors
    /// [`ParameterError::InvalidParameter`] naming the first offending value: `radius`, `g` and
    /// `rider_mass` must be positive; `wheel_mass`, `wheel_moment`, `rider_moment` finite and
    /// non-negative; `arm` finite.
    pub fn new(
        radius: f64,
        g: f64,
        wheel_mass: f64,
        wheel_moment: f64,
        rider_mass: f64,
        rider_moment: f64,
        arm: f64,
    ) -> Result<Pitch, ParameterError> {
        ParameterError::check_positive("radius", radius)?;
        ParameterError::check_positive("g", g)?;
        ParameterError::check_positive("rider_mass", rider_mass)?;
        for (name, value) in [
            ("wheel_mass", wheel_mass),
            ("wheel_moment", wheel_moment),
            ("rider_moment", rider_moment),
        ] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(ParameterError::InvalidParameter {
                    name,
                    value,
                    reason: "must be finite and >= 0",
                });
            }
        }
        if !arm.is_finite() {
            return Err(ParameterError::InvalidParameter {
                name: "arm",
                value: arm,
                reason: "must be finite",
            });
        }
        Ok(Pitch { radius, g, wheel_mass, wheel_moment, rider_mass, rider_moment, arm })
    }

    /// The rider's arm below the axle (m): for a rider whose centre of gravity is at the height
    /// `rider_height` above the ground, $\ell = R - h$ (positive when the wheel's radius
    /// exceeds the height, the condition of n° 42).
    pub fn arm_for_height(radius: f64, rider_height: f64) -> f64 {
        radius - rider_height
    }

    /// The translational mass of the rolling wheel and rider, $M' = \mu + \mu_1 + I_1/R^2$.
    fn rolling_mass(&self) -> f64 {
        self.rider_mass + self.wheel_mass + self.wheel_moment / (self.radius * self.radius)
    }

    /// $(\dot x, \dot\varphi, \ddot x, \ddot\varphi)$ at the state $(x, \varphi, \dot x,
    /// \dot\varphi)$.
    pub fn rhs(&self, state: [f64; 4]) -> [f64; 4] {
        let [_, phi, v, w] = state;
        let (mu, l) = (self.rider_mass, self.arm);
        let m11 = self.rolling_mass();
        let m12 = mu * l * phi.cos();
        let m22 = self.rider_moment + mu * l * l;
        let f1 = mu * l * phi.sin() * w * w;
        let f2 = -mu * self.g * l * phi.sin();
        let det = m11 * m22 - m12 * m12;
        [v, w, (f1 * m22 - m12 * f2) / det, (m11 * f2 - m12 * f1) / det]
    }

    /// Kinetic plus potential energy (J), the potential counted from the ground; conserved.
    pub fn energy(&self, state: [f64; 4]) -> f64 {
        let [_, phi, v, w] = state;
        let (mu, l) = (self.rider_mass, self.arm);
        let kinetic = 0.5 * self.rolling_mass() * v * v
            + mu * l * phi.cos() * v * w
            + 0.5 * (self.rider_moment + mu * l * l) * w * w;
        kinetic + mu * self.g * (self.radius - l * phi.cos())
    }

    /// $\omega^2$ (1/s²) of the linearised motion about $\varphi = 0$: positive, the rider
    /// oscillates with the pulsation $\omega$; negative, he falls away with the rate
    /// $\sqrt{-\omega^2}$.
    pub fn linear_rate_squared(&self) -> f64 {
        let (mu, l) = (self.rider_mass, self.arm);
        let reduced = self.rider_moment + mu * l * l - (mu * l).powi(2) / self.rolling_mass();
        mu * self.g * l / reduced
    }

    /// Integrates the equations with the classical Runge–Kutta method: `steps` steps of `dt`
    /// seconds from `state`; returns the largest $|\varphi|$ reached and the final state.
    pub fn simulate(&self, mut state: [f64; 4], dt: f64, steps: usize) -> (f64, [f64; 4]) {
        let mut largest = state[1].abs();
        for _ in 0..steps {
            state = rk4_step(|y| self.rhs(y), state, dt);
            largest = largest.max(state[1].abs());
        }
        (largest, state)
    }
}

impl Unicycle {
    /// The (p) and (n) residuals of n° 22–24 (motor moment free, so the (s) equation is
    /// dropped) at the state and accelerations given, from the generated rider and wheel sums:
    /// $[I\sum m(M-O)M''] + [I\sum m_1(M_1-O)M_1''] - (\mu z + \mu_1 R)g\sin\theta$ and the
    /// same on K without weight.
    fn residuals_pn(&self, theta: f64, p: f64, n: f64, s: f64, dp: f64, dn: f64) -> [f64; 2] {
        let (r, w) = (&self.rider, &self.wheel);
        let values = |name: &str| -> f64 {
            match name {
                "R" => self.radius,
                "g" => self.g,
                "mu" => r.mass,
                "z" => r.height,
                "A" => r.a,
                "B" => r.b,
                "C" => r.c,
                "L" => r.l,
                "mu1" => w.mass,
                "A1" => w.a1,
                "B1" => w.b1,
                "C1" => w.c1,
                "theta" => theta,
                "p" => p,
                "n" => n,
                "s" => s,
                "dp" => dp,
                "dn" => dn,
                _ => 0.0,
            }
        };
        let names = all_scene::PARAMS.iter().chain(all_scene::INPUTS.iter());
        let args: Vec<f64> = names.map(|name| values(name)).collect();
        let args = std::array::from_fn(|i| args[i]);
        let out = all_scene::eval_array(&args);
        let get = |name: &str| {
            all_scene::OUTPUTS.iter().position(|o| *o == name).map_or(f64::NAN, |i| out[i])
        };
        let weight = (r.mass * r.height + w.mass * self.radius) * self.g * theta.sin();
        [get("rider_p") + get("wheel_p") - weight, get("rider_n") + get("wheel_n")]
    }

    /// n° 78: the right-hand side $(\theta', p', n')$ of the (p) and (n) equations when the
    /// pedals hold the rolling rate `s` (1/s) constant, at the state $(\theta, p, n)$. The
    /// residuals are linear in $p', n'$; their coefficients are read off the generated sums
    /// at unit accelerations and the 2×2 system is solved.
    pub fn rhs_constant_speed(&self, state: [f64; 3], s: f64) -> [f64; 3] {
        let [theta, p, n] = state;
        let r0 = self.residuals_pn(theta, p, n, s, 0.0, 0.0);
        let rp = self.residuals_pn(theta, p, n, s, 1.0, 0.0);
        let rn = self.residuals_pn(theta, p, n, s, 0.0, 1.0);
        let (a11, a12, a21, a22) = (rp[0] - r0[0], rn[0] - r0[0], rp[1] - r0[1], rn[1] - r0[1]);
        let det = a11 * a22 - a12 * a21;
        let dp = (-r0[0] * a22 + a12 * r0[1]) / det;
        let dn = (-a11 * r0[1] + a21 * r0[0]) / det;
        [p, dp, dn]
    }

    /// Integrates [`Unicycle::rhs_constant_speed`] with the classical Runge–Kutta method:
    /// `steps` steps of `dt` seconds from $(\theta, p, n)$ at the rolling rate `s`; returns the
    /// lean $\theta$ after every step.
    pub fn simulate_constant_speed(
        &self,
        mut state: [f64; 3],
        s: f64,
        dt: f64,
        steps: usize,
    ) -> Vec<f64> {
        let mut leans = Vec::with_capacity(steps);
        for _ in 0..steps {
            state = rk4_step(|y| self.rhs_constant_speed(y, s), state, dt);
            leans.push(state[0]);
        }
        leans
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::unicycle::{Rider, Wheel};

    #[test]
    fn a_rider_below_the_axle_swings_and_conserves_energy() {
        let below = Pitch::new(1.2, 9.81, 12.0, 12.0 * 1.44, 60.0, 8.0, 0.1).unwrap();
        assert!(below.linear_rate_squared() > 0.0);
        let x0 = [0.0, 0.2, 0.0, 0.0];
        let (largest, end) = below.simulate(x0, 1e-3, 5000);
        assert!(largest < 0.2 + 1e-9, "{largest}");
        let drift = (below.energy(end) - below.energy(x0)).abs() / below.energy(x0);
        assert!(drift < 1e-9, "{drift}");
        let above = Pitch::new(0.5, 9.81, 5.0, 1.25, 60.0, 8.0, -0.75).unwrap();
        assert!(above.linear_rate_squared() < 0.0);
        let (largest, _) = above.simulate([0.0, 0.01, 0.0, 0.0], 1e-3, 3000);
        assert!(largest > 1.0, "{largest}");
    }

    #[test]
    fn the_constant_speed_equations_keep_a_steady_turn_steady() {
        let rider = Rider { mass: 60.0, height: 1.25, a: 100.0, b: 99.5, c: 1.4, l: 0.0 };
        let u = Unicycle::new(0.5, 9.81, rider, Wheel::hoop(5.0, 0.5)).unwrap();
        // Upright straight running is steady: no acceleration at θ = p = n = 0.
        let [_, dp, dn] = u.rhs_constant_speed([0.0, 0.0, 0.0], 8.0);
        assert!(dp.abs() < 1e-12 && dn.abs() < 1e-12, "{dp} {dn}");
        // With p = 0 the (n) equation gives n' = 0 and (p) is -(E)/A-like: zero on (E).
        let s = 8.0;
        let theta = 0.2;
        let e = |n: f64| u.equilibrium(theta, s, n);
        let n = crate::numerics::poly::bisect_unchecked(e, -3.0, -1e-6);
        let [_, dp, dn] = u.rhs_constant_speed([theta, 0.0, n], s);
        assert!(dp.abs() < 1e-9 && dn.abs() < 1e-12, "{dp} {dn}");
    }
}
