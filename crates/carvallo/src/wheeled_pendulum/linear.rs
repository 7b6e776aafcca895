//! The linear model about upright straight running at speed $v$: the state
//! $x = (\theta, \dot\theta, \dot\theta_L, \dot\theta_R)$ ([`LINEAR_STATE`]) measured from the
//! reference $(0, 0, -v/r, -v/r)$ and the inputs $(T_L, T_R)$ give $\dot x = A x + B T$, with
//!
//! $$A = \begin{pmatrix} 0 & e_1^\top \\ M^{-1} f_\theta & M^{-1} f_u \end{pmatrix}, \qquad
//!   B = \begin{pmatrix} 0 \\ M^{-1} f_T \end{pmatrix},$$
//!
//! $M$, $f_\theta$, $f_u$, $f_T$ the generated `lin_M_*`, `lin_fq_*`, `lin_fu_*`, `lin_fT_*`
//! (the program's linearisation of Kane's equations, checked against the modified Lagrange
//! equations' at regeneration) and $M^{-1}$ applied numerically (an LU solve). Two of the
//! eigenvalues are zero (a common and a differential wheel rate: the speed and the heading
//! rate are free), the other two $\pm\lambda$ with $\lambda^2 = m_B g l M_t / (J M_t - m_B^2
//! l^2)$, $M_t = m_B + 2 m_W + 2 I_{Wa}/r^2$, $J = I_{Byy} + m_B l^2$, at every speed.
//!
//! A stabilising state feedback [`Feedback`] ($T = -K (x - x_{\rm ref})$) comes from pole
//! placement ([`LinearModel::place`]): Ackermann's formula on the pitch and forward motion
//! (the subspace $\dot\theta_L = \dot\theta_R$, invariant by the left–right symmetry, driven
//! by equal torques), the turning mode left alone.

use nalgebra::{Complex, Matrix3, Matrix4, RowVector3, SMatrix, Vector3};

use super::{linear_scene, WheeledPendulum, WheeledPendulumError};
use crate::error::ParameterError;

/// The names of the linear state's components.
pub const LINEAR_STATE: [&str; 4] = ["theta", "thetad", "thetaLd", "thetaRd"];

/// The names of the inputs: the left and right motor torques (N m).
pub const INPUT_NAMES: [&str; 2] = ["TL", "TR"];

/// The linear model at one speed ([`WheeledPendulum::linear`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearModel {
    /// The speed $v$ (m/s).
    pub speed: f64,
    /// The reference wheel rate $-v/r$ (rad/s), relative to the body.
    pub wheel_rate: f64,
    /// $A$ ($4 \times 4$, [`LINEAR_STATE`] order).
    pub a: Matrix4<f64>,
    /// $B$ ($4 \times 2$, columns $T_L$, $T_R$).
    pub b: SMatrix<f64, 4, 2>,
}

/// A linear state feedback on the torques, $T = -K (x - x_{\rm ref})$ with $x$ the linear state
/// ([`LINEAR_STATE`]) and $x_{\rm ref} = (0, 0, -v/r, -v/r)$: upright running at the speed it
/// was designed for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Feedback {
    /// $K$: rows $T_L$, $T_R$; columns [`LINEAR_STATE`] (N m/rad, N m s/rad).
    pub gain: [[f64; 4]; 2],
    /// The reference wheel rate $-v/r$ (rad/s).
    pub wheel_rate: f64,
}

impl Feedback {
    /// The torques $(T_L, T_R)$ (N m) at the simulation state `x`
    /// ([`STATE_NAMES`](super::STATE_NAMES)).
    pub fn torques(&self, x: &[f64; 7]) -> [f64; 2] {
        let e = [x[3], x[4], x[5] - self.wheel_rate, x[6] - self.wheel_rate];
        self.gain.map(|row| -row.iter().zip(&e).map(|(k, e)| k * e).sum::<f64>())
    }

    /// $K$ as a matrix.
    pub fn matrix(&self) -> SMatrix<f64, 2, 4> {
        SMatrix::<f64, 2, 4>::from_fn(|i, j| self.gain[i][j])
    }
}

/// The eigenvalues of `a`, sorted by decreasing real part, then decreasing imaginary part.
fn sorted_eigenvalues(a: &Matrix4<f64>) -> [Complex<f64>; 4] {
    let ev = a.complex_eigenvalues();
    let mut out: [Complex<f64>; 4] = std::array::from_fn(|k| ev[k]);
    out.sort_by(|x, y| y.re.total_cmp(&x.re).then(y.im.total_cmp(&x.im)));
    out
}

impl LinearModel {
    /// The eigenvalues of $A$ (1/s), sorted by decreasing real part: $\lambda$, the two zeros,
    /// $-\lambda$.
    pub fn eigenvalues(&self) -> [Complex<f64>; 4] {
        sorted_eigenvalues(&self.a)
    }

    /// The eigenvalues of $A - BK$ under the feedback `k` (1/s), sorted as
    /// [`eigenvalues`](Self::eigenvalues).
    pub fn closed_loop_eigenvalues(&self, k: &Feedback) -> [Complex<f64>; 4] {
        sorted_eigenvalues(&(self.a - self.b * k.matrix()))
    }

    /// The largest real eigenvalue $\lambda$ (1/s): the rate at which a pitch grows.
    pub fn growth_rate(&self) -> f64 {
        self.eigenvalues()[0].re
    }

    /// Closed-loop poles for [`place`](Self::place) computed from the design: $-\lambda$,
    /// $-1.5\lambda$, $-2\lambda$ ([`growth_rate`](Self::growth_rate)), the pitch brought back
    /// about as fast as it would have fallen.
    pub fn default_poles(&self) -> [f64; 3] {
        let l = self.growth_rate();
        [-l, -1.5 * l, -2.0 * l]
    }

    /// The feedback that puts the pitch and forward motion's three poles at `poles` (1/s, real
    /// and negative), by Ackermann's formula on the subsystem $z = (\theta, \dot\theta,
    /// (\dot\theta_L + \dot\theta_R)/2)$ driven by $T_L = T_R$; the turning mode's zero
    /// eigenvalue stays.
    ///
    /// # Errors
    /// [`WheeledPendulumError::Parameter`] naming a `pole` that is not finite and negative;
    /// [`WheeledPendulumError::Uncontrollable`] when the subsystem's controllability matrix is
    /// singular to $10^{-12}$ relative.
    pub fn place(&self, poles: [f64; 3]) -> Result<Feedback, WheeledPendulumError> {
        for p in poles {
            if !p.is_finite() {
                return Err(ParameterError::InvalidParameter {
                    name: "pole",
                    value: p,
                    reason: "must be finite",
                }
                .into());
            }
            if p >= 0.0 {
                return Err(ParameterError::InvalidParameter {
                    name: "pole",
                    value: p,
                    reason: "must be negative",
                }
                .into());
            }
        }
        // z = P⁺ x, x = P z on the symmetric subspace.
        let project = SMatrix::<f64, 3, 4>::new(
            1.0, 0.0, 0.0, 0.0, //
            0.0, 1.0, 0.0, 0.0, //
            0.0, 0.0, 0.5, 0.5,
        );
        let embed = project.transpose() * Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 2.0));
        let ar: Matrix3<f64> = project * self.a * embed;
        let br: Vector3<f64> = project * self.b * nalgebra::Vector2::new(0.5, 0.5);
        let c = Matrix3::from_columns(&[br, ar * br, ar * ar * br]);
        let sv = c.singular_values();
        let controllable = sv.min() > 1e-12 * sv.max();
        if !controllable {
            return Err(WheeledPendulumError::Uncontrollable { speed: self.speed });
        }
        let ci =
            c.try_inverse().ok_or(WheeledPendulumError::Uncontrollable { speed: self.speed })?;
        let id = Matrix3::identity();
        let p = (ar - id * poles[0]) * (ar - id * poles[1]) * (ar - id * poles[2]);
        let kr: RowVector3<f64> = RowVector3::new(0.0, 0.0, 1.0) * ci * p;
        // T_L = T_R = -(1/2) k_r z, z = P⁺ x.
        let row: SMatrix<f64, 1, 4> = 0.5 * kr * project;
        let gain = [0, 1].map(|_| std::array::from_fn(|j| row[j]));
        Ok(Feedback { gain, wheel_rate: self.wheel_rate })
    }

    /// The feedback with the gain `gain` ($K$, rows $T_L$, $T_R$) about this speed's upright
    /// running.
    ///
    /// # Errors
    /// [`WheeledPendulumError::Parameter`] naming the first `gain` entry that is not finite.
    pub fn feedback(&self, gain: [[f64; 4]; 2]) -> Result<Feedback, WheeledPendulumError> {
        for &k in gain.iter().flatten() {
            if !k.is_finite() {
                return Err(ParameterError::InvalidParameter {
                    name: "gain",
                    value: k,
                    reason: "must be finite",
                }
                .into());
            }
        }
        Ok(Feedback { gain, wheel_rate: self.wheel_rate })
    }
}

impl WheeledPendulum {
    /// The linear model about upright straight running at `speed` (m/s): the generated
    /// `lin_*` outputs, $M^{-1}$ applied by an LU solve.
    pub fn linear(&self, speed: f64) -> LinearModel {
        let o = linear_scene::eval(&linear_scene::Args::from_fn(|name| match name {
            "v" => speed,
            "phi" | "theta" | "thetad" | "thetaLd" | "thetaRd" | "TL" | "TR" => 0.0,
            p => self.param(p),
        }));
        let m = Matrix3::new(
            o.lin_M_thetad_thetad,
            o.lin_M_thetad_thetaLd,
            o.lin_M_thetad_thetaRd,
            o.lin_M_thetad_thetaLd,
            o.lin_M_thetaLd_thetaLd,
            o.lin_M_thetaLd_thetaRd,
            o.lin_M_thetad_thetaRd,
            o.lin_M_thetaLd_thetaRd,
            o.lin_M_thetaRd_thetaRd,
        );
        // Columns: θ, the three speeds, the two torques.
        let f = SMatrix::<f64, 3, 6>::from_row_slice(&[
            o.lin_fq_thetad,
            o.lin_fu_thetad_thetad,
            o.lin_fu_thetad_thetaLd,
            o.lin_fu_thetad_thetaRd,
            o.lin_fT_thetad_TL,
            o.lin_fT_thetad_TR,
            o.lin_fq_thetaLd,
            o.lin_fu_thetaLd_thetad,
            o.lin_fu_thetaLd_thetaLd,
            o.lin_fu_thetaLd_thetaRd,
            o.lin_fT_thetaLd_TL,
            o.lin_fT_thetaLd_TR,
            o.lin_fq_thetaRd,
            o.lin_fu_thetaRd_thetad,
            o.lin_fu_thetaRd_thetaLd,
            o.lin_fu_thetaRd_thetaRd,
            o.lin_fT_thetaRd_TL,
            o.lin_fT_thetaRd_TR,
        ]);
        let sol = m.lu().solve(&f).unwrap_or_else(|| SMatrix::<f64, 3, 6>::repeat(f64::NAN));
        let mut a = Matrix4::zeros();
        a[(0, 1)] = 1.0;
        let mut b = SMatrix::<f64, 4, 2>::zeros();
        for i in 0..3 {
            for j in 0..4 {
                a[(i + 1, j)] = sol[(i, j)];
            }
            for j in 0..2 {
                b[(i + 1, j)] = sol[(i, 4 + j)];
            }
        }
        LinearModel { speed, wheel_rate: -speed / self.radius(), a, b }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wheeled_pendulum::WheeledPendulumParams;

    /// The placed poles are the closed loop's, with the turning mode's zero beside them; a
    /// wrong projection (the subsystem's wheel rate not the mean) would move them.
    #[test]
    fn placed_poles_are_the_closed_loop_eigenvalues() {
        let m = WheeledPendulum::new(WheeledPendulumParams::nominal());
        for v in [0.0, 2.0, 5.0] {
            let lin = m.linear(v);
            let poles = lin.default_poles();
            let k = lin.place(poles).expect("controllable");
            let ev = lin.closed_loop_eigenvalues(&k);
            let mut want = [0.0, poles[0], poles[1], poles[2]];
            want.sort_by(|a, b| b.total_cmp(a));
            for (e, w) in ev.iter().zip(want) {
                assert!((e.re - w).abs() < 1e-8 * poles[2].abs() && e.im.abs() < 1e-6, "{ev:?}");
            }
        }
        let lin = m.linear(1.0);
        let err = lin.place([-1.0, 0.5, -2.0]).unwrap_err();
        assert_eq!(err.to_string(), "invalid pole 0.5: must be negative");
    }
}
