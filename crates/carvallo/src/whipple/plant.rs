//! The bicycle as a plant: the linearised equations
//! $M\ddot q + v C_1\dot q + (g K_0 + v^2 K_2) q = f$, $q = (\varphi, \delta)$, with the
//! generalised forces $f = (T_\varphi, T_\delta)$ (roll torque, steer torque) as inputs, in the
//! state-space form $\dot x = A x + B u$, $y = C x + D u$ of $x = (\varphi, \delta, \dot\varphi,
//! \dot\delta)$ and $u = (T_\varphi, T_\delta)$:
//!
//! $$A = \begin{pmatrix} 0 & I \\ -M^{-1}(g K_0 + v^2 K_2) & -v M^{-1} C_1 \end{pmatrix},\quad
//! B = \begin{pmatrix} 0 \\ M^{-1} \end{pmatrix},\quad C = I_4,\quad D = 0,$$
//!
//! as in BicycleParameters' `Bicycle.canonical` / `state_space` and Meijaard et al. (2007),
//! eq. (A 1). The matrices $M$, $C_1$, $K_0$, $K_2$ come from the generated evaluator
//! ([`matrices_scene`](super::matrices_scene)); $M^{-1}$ is the 2 × 2 adjugate over
//! $\det M$, so $A$'s lower rows are $-B_{\text{lower}}(g K_0 + v^2 K_2)$ and
//! $-v B_{\text{lower}} C_1$.

use nalgebra::{Matrix4, Matrix4x2};

use super::matrices::Matrices;
use super::model::Whipple;
use crate::numerics::mat2::det;

/// The state space $(A, B)$ of the linearised bicycle at one speed ($C = I_4$, $D = 0$).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StateSpace {
    /// The forward speed $v$ (m/s).
    pub speed: f64,
    /// The state matrix of $(\varphi, \delta, \dot\varphi, \dot\delta)$.
    pub a: Matrix4<f64>,
    /// The input matrix, columns $T_\varphi$ (roll torque) and $T_\delta$ (steer torque).
    pub b: Matrix4x2<f64>,
}

impl StateSpace {
    /// $C = I_4$: the outputs are the four states.
    pub fn c(&self) -> Matrix4<f64> {
        Matrix4::identity()
    }

    /// $D = 0$ (4 × 2).
    pub fn d(&self) -> Matrix4x2<f64> {
        Matrix4x2::zeros()
    }

    /// $A$ by rows.
    pub fn a_rows(&self) -> [[f64; 4]; 4] {
        std::array::from_fn(|i| std::array::from_fn(|j| self.a[(i, j)]))
    }

    /// $B$ by rows.
    pub fn b_rows(&self) -> [[f64; 2]; 4] {
        std::array::from_fn(|i| std::array::from_fn(|j| self.b[(i, j)]))
    }
}

/// The state space at speed `v` of the matrices `m` with gravity `g`. $\det M \ne 0$ for every
/// valid parameter set (M is positive definite); were it zero the entries would be non-finite.
pub fn state_space(m: &Matrices, g: f64, v: f64) -> StateSpace {
    let Matrices { m, c1, k0, k2 } = *m;
    let dm = det(&m);
    let minv = [[m[1][1] / dm, -m[0][1] / dm], [-m[1][0] / dm, m[0][0] / dm]];
    let mut b = Matrix4x2::zeros();
    let mut a = Matrix4::zeros();
    a[(0, 2)] = 1.0;
    a[(1, 3)] = 1.0;
    for r in 0..2 {
        for c in 0..2 {
            b[(2 + r, c)] = minv[r][c];
            let (mut kk, mut cc) = (0.0, 0.0);
            for j in 0..2 {
                kk += minv[r][j] * (g * k0[j][c] + v * v * k2[j][c]);
                cc += minv[r][j] * v * c1[j][c];
            }
            a[(2 + r, c)] = -kk;
            a[(2 + r, 2 + c)] = -cc;
        }
    }
    StateSpace { speed: v, a, b }
}

impl Whipple {
    /// The state space $(A, B)$ at speed `v` ([`state_space`]).
    pub fn state_space(&self, v: f64) -> StateSpace {
        state_space(&self.matrices(), self.params().value("g"), v)
    }

    /// The state spaces at each of `speeds`, in order.
    pub fn state_spaces(&self, speeds: &[f64]) -> Vec<StateSpace> {
        let (m, g) = (self.matrices(), self.params().value("g"));
        speeds.iter().map(|&v| state_space(&m, g, v)).collect()
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::Matrix2;

    use super::*;
    use crate::whipple::WhippleParams;

    /// Meijaard et al. (2007), eq. (5.3)–(5.6): the benchmark's matrices as printed (14
    /// decimals), an independent source for $M$, $C_1$, $K_0$, $K_2$.
    const M: [[f64; 2]; 2] = [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]];
    const C1: [[f64; 2]; 2] = [[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]];
    const K0: [[f64; 2]; 2] = [[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]];
    const K2: [[f64; 2]; 2] = [[0.0, 76.59734589573222], [0.0, 2.65431523794604]];

    fn m2(a: [[f64; 2]; 2]) -> Matrix2<f64> {
        Matrix2::new(a[0][0], a[0][1], a[1][0], a[1][1])
    }

    /// $A$ and $B$ from the published matrices with nalgebra's general inverse.
    fn published(v: f64) -> (Matrix4<f64>, Matrix4x2<f64>) {
        let minv = m2(M).try_inverse().unwrap();
        let k = -minv * (m2(K0) * 9.81 + m2(K2) * (v * v));
        let c = -minv * m2(C1) * v;
        let mut a = Matrix4::zeros();
        a.fixed_view_mut::<2, 2>(0, 2).copy_from(&Matrix2::identity());
        a.fixed_view_mut::<2, 2>(2, 0).copy_from(&k);
        a.fixed_view_mut::<2, 2>(2, 2).copy_from(&c);
        let mut b = Matrix4x2::zeros();
        b.fixed_view_mut::<2, 2>(2, 0).copy_from(&minv);
        (a, b)
    }

    #[test]
    fn benchmark_matches_the_published_matrices() {
        // The printed matrices carry 14 decimals: relative agreement to 1e-12 of the largest
        // entry of each matrix.
        let bike = Whipple::new(WhippleParams::benchmark());
        for v in [0.0, 1.0, 4.29238253634111, 5.0, 6.02426201538837, 10.0] {
            let ss = bike.state_space(v);
            let (a, b) = published(v);
            let ea = (ss.a - a).amax() / a.amax();
            let eb = (ss.b - b).amax() / b.amax();
            assert!(ea < 1e-12 && eb < 1e-12, "v = {v}: A {ea:e}, B {eb:e}");
            assert_eq!(ss.speed, v);
        }
    }

    #[test]
    fn benchmark_a_at_5_mps_has_the_published_eigenvalues() {
        // Meijaard et al. (2007), Table 2 at v = 5 m/s (recomputed; the print agrees to ~1e-14).
        let ss = Whipple::new(WhippleParams::benchmark()).state_space(5.0);
        let ev = ss.a.complex_eigenvalues();
        let want = [
            (-14.078389692798247, 0.0),
            (-0.322_866_429_004_087_1, 0.0),
            (-0.775_341_882_195_841_9, 4.464_867_713_788_225),
            (-0.775_341_882_195_841_9, -4.464_867_713_788_225),
        ];
        for (re, im) in want {
            let d = ev.iter().map(|e| ((e.re - re).powi(2) + (e.im - im).powi(2)).sqrt());
            let best = d.fold(f64::INFINITY, f64::min);
            assert!(best < 1e-11, "{re} {im}i: nearest at {best:e}");
        }
    }

    #[test]
    fn agrees_with_the_eigenvalue_route_and_inverts_m() {
        // A equals the state matrix the eigenvalues use; M B_lower = I; and A's characteristic
        // polynomial is the generated det(M s² + v C1 s + g K0 + v² K2) over det M.
        let bike = Whipple::new(WhippleParams::benchmark());
        let mm = bike.matrices().m;
        let mm = m2(mm);
        for v in [-2.0, 0.0, 0.5, 3.0, 7.5] {
            let ss = bike.state_space(v);
            assert!((ss.a - bike.state_matrix(v)).amax() < 1e-15, "v = {v}");
            let lower = ss.b.fixed_view::<2, 2>(2, 0).into_owned();
            assert!((mm * lower - Matrix2::identity()).amax() < 1e-13, "v = {v}");
            assert_eq!(ss.b.fixed_view::<2, 2>(0, 0).amax(), 0.0);
            let p = bike.char_poly(v);
            let s = 1.7;
            let char_a = (Matrix4::identity() * s - ss.a).determinant();
            let char_g = (((p[4] * s + p[3]) * s + p[2]) * s + p[1]) * s + p[0];
            let rel = (char_a - char_g / p[4]).abs() / char_a.abs().max(1.0);
            assert!(rel < 1e-12, "v = {v}: {rel:e}");
        }
        assert_eq!(bike.state_spaces(&[1.0, 2.0]).len(), 2);
        let ss = bike.state_space(2.0);
        assert_eq!(ss.c(), Matrix4::identity());
        assert_eq!(ss.d(), Matrix4x2::zeros());
        assert_eq!(ss.a_rows()[0], [0.0, 0.0, 1.0, 0.0]);
        assert_eq!(ss.b_rows()[0], [0.0, 0.0]);
    }
}
