//! The whole right-hand side of the nonlinear bicycle, state in, state derivative out: what
//! an integrator calls.
//!
//! The state has eleven components: the ten of [`State`] and the rear frame pitch θ, carried
//! as a state so that no Newton solve of the contact constraint runs at every evaluation. Its
//! rate is the pitch rate of the velocity constraint (a generated linear form in the
//! independent speeds), so $h(\varphi, \theta, \delta)$ is an invariant of the exact flow and
//! an integrator moves off it only by its own error $e$. Each evaluation first projects the
//! pitch back onto the constraint by one Newton step,
//! $\theta^* = \theta - h/h_\theta$, whose residual is $O(e^2)$ (below $10^{-15}$ m whenever
//! the integrator's pitch is within $10^{-7}$ rad of the constraint), and evaluates the
//! equations at $\theta^*$: the right-hand side is a function of the state alone, smooth, and
//! nothing is carried from one call to the next.
//!
//! Per evaluation: the generated contact constraint and its pitch derivative (one small
//! kernel), then one generated kernel for $M_3$, $f_3$ and the dependent rates, then the
//! symmetric $3 \times 3$ system solved in closed form (its adjugate over its determinant)
//! and the kinematic rates. The parameters are copied into the kernels' argument arrays
//! once, when the right-hand side is built; a call allocates nothing.

use super::{NonlinearError, State, WhippleParams};

crate::scene! {
    /// $M_3$, $f_3$, the dependent rates and the rear contact's speed: every output of the
    /// dynamics a right-hand side needs, and nothing else.
    pub mod state_rate_scene {
        model: whipple_nonlinear,
        outputs: [m3_11, m3_12, m3_13, m3_22, m3_23, m3_33, f3_1, f3_2, f3_3,
                  thetad, psid, thetaFd, rear_speed],
    }
}

crate::scene! {
    /// The front contact constraint $h$ and $\partial h/\partial\theta$.
    pub mod project_scene {
        model: whipple_nonlinear,
        outputs: [contact_height, contact_height_dtheta],
    }
}

/// Number of components of the state a [`StateRate`] differentiates: the ten of [`State`]
/// (its `to_array` order), then the pitch.
pub const LEN: usize = 11;

/// The index of the pitch in the state.
pub const PITCH: usize = 10;

/// The positions of `phi`, `theta`, `delta`, `phid`, `deltad`, `thetaRd` in a scene's
/// argument array (`usize::MAX` where the scene does not take the input).
pub(crate) fn input_slots(params: &[&str], inputs: &[&str]) -> [usize; 6] {
    const NAMES: [&str; 6] = ["phi", "theta", "delta", "phid", "deltad", "thetaRd"];
    std::array::from_fn(|k| {
        inputs.iter().position(|n| *n == NAMES[k]).map_or(usize::MAX, |i| params.len() + i)
    })
}

/// A scene's argument array with the parameters filled in and the inputs zero.
pub(crate) fn filled<const N: usize>(params: &WhippleParams, names: &[&str]) -> [f64; N] {
    std::array::from_fn(|i| match names.get(i) {
        Some(name) => params.get(name).unwrap_or(f64::NAN),
        None => 0.0,
    })
}

/// The right-hand side of one bicycle: the kernels' argument arrays with its parameters.
#[derive(Clone, Debug)]
pub struct StateRate {
    project: [f64; project_scene::Args::LEN],
    project_slots: [usize; 6],
    rate: [f64; state_rate_scene::Args::LEN],
    rate_slots: [usize; 6],
}

/// What one evaluation gives besides the derivative.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rates {
    /// The state derivative.
    pub derivative: [f64; LEN],
    /// The projected pitch the equations were evaluated at (rad).
    pub pitch: f64,
    /// The rear contact's speed along the heading (m/s).
    pub speed: f64,
}

impl StateRate {
    /// The right-hand side of the bicycle with the parameters `params`.
    pub fn new(params: &WhippleParams) -> StateRate {
        StateRate {
            project: filled(params, project_scene::PARAMS),
            project_slots: input_slots(project_scene::PARAMS, project_scene::INPUTS),
            rate: filled(params, state_rate_scene::PARAMS),
            rate_slots: input_slots(state_rate_scene::PARAMS, state_rate_scene::INPUTS),
        }
    }

    /// The contact constraint $h$ (m) and $\partial h/\partial\theta$ (m/rad).
    pub fn contact(&self, lean: f64, pitch: f64, steer: f64) -> (f64, f64) {
        let mut a = self.project;
        for (slot, v) in self.project_slots.iter().zip([lean, pitch, steer]) {
            if let Some(x) = a.get_mut(*slot) {
                *x = v;
            }
        }
        let o = project_scene::eval_array(&a);
        (o[0], o[1])
    }

    /// The pitch projected onto the contact constraint by one Newton step from `pitch`; when
    /// that step is longer than $10^{-7}$ rad (a loose tolerance's drift, where one step
    /// would leave a residual above $10^{-12}$ m) Newton continues to convergence.
    ///
    /// # Errors
    /// [`NonlinearError::NoContact`] when Newton's method does not converge in 50 steps.
    pub fn project(&self, lean: f64, pitch: f64, steer: f64) -> Result<f64, NonlinearError> {
        let (h, dh) = self.contact(lean, pitch, steer);
        let step = h / dh;
        let mut th = pitch - step;
        if step.abs() <= 1e-7 {
            return Ok(th);
        }
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

    /// The state derivative at `y` ([`LEN`] components), with `torque` $(T_\varphi,
    /// T_\delta)$ of the rear contact's speed added to the lean and steer rows of $f_3$.
    ///
    /// # Errors
    /// [`NonlinearError::SingularMassMatrix`] when $M_3$ is singular or a value is not
    /// finite (the projection failed: the state is far from any contact); the errors of
    /// `torque`.
    #[inline]
    pub fn rates_with(
        &self,
        y: &[f64; LEN],
        torque: &mut dyn FnMut(f64) -> Result<[f64; 2], NonlinearError>,
    ) -> Result<Rates, NonlinearError> {
        let (lean, steer, yaw) = (y[3], y[4], y[2]);
        let u = [y[7], y[8], y[9]];
        let pitch = self.project(lean, y[PITCH], steer)?;
        let mut a = self.rate;
        for (slot, v) in self.rate_slots.iter().zip([lean, pitch, steer, u[0], u[1], u[2]]) {
            if let Some(x) = a.get_mut(*slot) {
                *x = v;
            }
        }
        let o = state_rate_scene::eval_array(&a);
        let speed = o[12];
        let tau = torque(speed)?;
        let ud = solve_symmetric(
            [o[0], o[1], o[2], o[3], o[4], o[5]],
            [o[6] + tau[0], o[7] + tau[1], o[8]],
        )
        .ok_or(NonlinearError::SingularMassMatrix { lean, steer })?;
        let (sy, cy) = yaw.sin_cos();
        Ok(Rates {
            derivative: [
                speed * cy,
                speed * sy,
                o[10],
                u[0],
                u[1],
                u[2],
                o[11],
                ud[0],
                ud[1],
                ud[2],
                o[9],
            ],
            pitch,
            speed,
        })
    }

    /// The state derivative at `y`, undriven.
    ///
    /// # Errors
    /// As [`rates_with`](Self::rates_with).
    #[inline]
    pub fn eval(&self, y: &[f64; LEN]) -> Result<[f64; LEN], NonlinearError> {
        Ok(self.rates_with(y, &mut |_| Ok([0.0, 0.0]))?.derivative)
    }
}

/// The state of `s` with the pitch `pitch`.
pub fn state_with_pitch(s: &State, pitch: f64) -> [f64; LEN] {
    let a = s.to_array();
    std::array::from_fn(|i| if i < PITCH { a[i] } else { pitch })
}

/// The [`State`] of `y` (its pitch dropped).
pub fn state_of(y: &[f64; LEN]) -> State {
    State::from_array(std::array::from_fn(|i| y[i]))
}

/// Solves $M x = f$ for the symmetric $M$ given as `[m11, m12, m13, m22, m23, m33]` by its
/// adjugate over its determinant; `None` when the solution is not finite.
#[inline]
pub fn solve_symmetric(m: [f64; 6], f: [f64; 3]) -> Option<[f64; 3]> {
    let [a, b, c, d, e, g] = m;
    // Cofactors of the symmetric matrix [[a, b, c], [b, d, e], [c, e, g]].
    let c11 = d * g - e * e;
    let c12 = c * e - b * g;
    let c13 = b * e - c * d;
    let c22 = a * g - c * c;
    let c23 = b * c - a * e;
    let c33 = a * d - b * b;
    let det = a * c11 + b * c12 + c * c13;
    let r = 1.0 / det;
    let x = [
        (c11 * f[0] + c12 * f[1] + c13 * f[2]) * r,
        (c12 * f[0] + c22 * f[1] + c23 * f[2]) * r,
        (c13 * f[0] + c23 * f[1] + c33 * f[2]) * r,
    ];
    x.iter().all(|v| v.is_finite()).then_some(x)
}
