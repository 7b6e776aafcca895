//! The matrices of $M\ddot q + v C_1\dot q + (g K_0 + v^2 K_2) q = f$, $q = (\varphi, \delta)$
//! (lean, steer), the scenes that evaluate them and the characteristic polynomial's
//! coefficients over `generated/whipple.ir` (derived by `codegen/src/derive/whipple/mod.rs`),
//! and the state matrix of $(\varphi, \delta, \varphi', \delta')$.

use nalgebra::Matrix4;

#[cfg(doc)]
use super::params::WhippleParams;
use super::params::{skate_limit, PARAM_NAMES};
use crate::numerics::mat2::det;

crate::scene! {
    /// The sixteen entries of $M$, $C_1$, $K_0$, $K_2$ (also on four designs per call, for
    /// the sweeps).
    pub mod matrices_scene {
        model: whipple,
        lanes: 4,
        outputs: [m11, m12, m21, m22, c1_11, c1_12, c1_21, c1_22,
                  k0_11, k0_12, k0_21, k0_22, k2_11, k2_12, k2_21, k2_22],
    }
}

crate::scene! {
    /// The characteristic polynomial's coefficients $a_0, \dots, a_4$ at speed $v$.
    pub mod char_poly_scene {
        model: whipple,
        outputs: [a0, a1, a2, a3, a4],
    }
}

/// A 2 × 2 matrix by rows.
pub use crate::numerics::mat2::Mat2;

/// The linearised equations' matrices.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Matrices {
    /// Mass matrix $M$.
    pub m: Mat2,
    /// $C_1$ (multiplied by $v$).
    pub c1: Mat2,
    /// $K_0$ (multiplied by $g$).
    pub k0: Mat2,
    /// $K_2$ (multiplied by $v^2$).
    pub k2: Mat2,
}

/// The position in [`PARAM_NAMES`] of each parameter of [`matrices_scene`], in its order.
pub(crate) fn scene_index() -> Vec<usize> {
    matrices_scene::PARAMS
        .iter()
        .map(|p| PARAM_NAMES.iter().position(|n| n == p).unwrap_or(0))
        .collect()
}

/// The matrices of a parameter vector (in the order of [`PARAM_NAMES`]), without validation,
/// a zero wheel radius taken to its limit ([`WhippleParams::evaluated`]).
/// `index[i]` is the position in [`PARAM_NAMES`] of the scene's `i`-th parameter
/// ([`scene_index`]).
pub(crate) fn matrices_of(values: &[f64; 26], index: &[usize]) -> Matrices {
    let values = &skate_limit(values);
    let n = matrices_scene::Args::LEN;
    let arr: [f64; matrices_scene::Args::LEN] =
        std::array::from_fn(|i| if i < n { values[index[i]] } else { f64::NAN });
    let o = matrices_scene::eval_array(&arr);
    let r = |k: usize| [[o[k], o[k + 1]], [o[k + 2], o[k + 3]]];
    Matrices { m: r(0), c1: r(4), k0: r(8), k2: r(12) }
}

/// The state matrix of $(\varphi, \delta, \varphi', \delta')$ at speed `v`.
pub fn state_matrix(m: &Matrices, g: f64, v: f64) -> Matrix4<f64> {
    let Matrices { m, c1, k0, k2 } = *m;
    let dm = det(&m);
    let minv = [[m[1][1] / dm, -m[0][1] / dm], [-m[1][0] / dm, m[0][0] / dm]];
    let mut a = Matrix4::zeros();
    a[(0, 2)] = 1.0;
    a[(1, 3)] = 1.0;
    for r in 0..2 {
        for c in 0..2 {
            let (mut kk, mut cc) = (0.0, 0.0);
            for j in 0..2 {
                kk += minv[r][j] * (g * k0[j][c] + v * v * k2[j][c]);
                cc += minv[r][j] * v * c1[j][c];
            }
            a[(2 + r, c)] = -kk;
            a[(2 + r, 2 + c)] = -cc;
        }
    }
    a
}
