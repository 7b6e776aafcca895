//! Kinematics and rest equilibrium of the bicycle (memoir Part II, ch. II, n° 59–69).
//!
//! The bicycle has three degrees of freedom (n° 59), the lean θ, the steer γ and the rear
//! wheel's rolling σ; the turning ν of the frame, its pitch η (the σ of ch. I, n° 58 bis) and
//! the front wheel's rolling σ1 follow from the front contact point M having no velocity
//! (n° 60). Two independent paths are generated from `generated/bicycle_kinematics.ir`
//! (`cargo xtask regen`, derivation `codegen/src/derive/bicycle/kinematics.rs`):
//!
//! * the 18 coefficients of the analytic displacement $\delta M$ of n° 61 on I, J, K, which
//!   [`Kinematics::solve_displacements`] solves numerically for δη, δν, δσ1;
//! * the memoir's relations (I) and the steady state (2) of n° 66, and $\eta''$ of n° 69
//!   ([`Kinematics::relations`]).
//!
//! Both are evaluated at the exact contact of [`crate::bicycle::geometry`] and can be checked
//! against finite differences of the exact $\eta(\theta, \gamma)$. ν is not a function of
//! (θ, γ): $d\nu/d\theta$ and $d\nu/d\gamma$ of (I) are ratios of virtual displacements at
//! δσ = 0 whose cross derivatives differ ([`Kinematics::holonomy_defect`]).
//!
//! The rest equilibrium of n° 69 ([`Kinematics::rest_equilibrium`]) is the vertical frame at
//! its lowest position ($R\sin\mu = c$, γ ≈ 61.6° for the old bicycle); the height of a centre
//! of gravity fixed in the frame is $Z = (R + x\sin\eta_1 + z\cos\eta_1)\cos\theta$ and
//! $\frac{d^2Z}{d\theta^2} = -Z + X\eta''$ there.

use crate::bicycle::geometry::{read_all, Contact, ContactError, Geometry};

crate::scene! {
    /// The analytic displacement of M (n° 61): its components on I, J, K per unit δσ, δθ, δν,
    /// δη, δγ, δσ1.
    pub mod displacement_scene {
        model: bicycle_kinematics,
        outputs: [
            dm_i_sigma, dm_i_theta, dm_i_nu, dm_i_eta, dm_i_gamma, dm_i_sigma1,
            dm_j_sigma, dm_j_theta, dm_j_nu, dm_j_eta, dm_j_gamma, dm_j_sigma1,
            dm_k_sigma, dm_k_theta, dm_k_nu, dm_k_eta, dm_k_gamma, dm_k_sigma1,
        ],
    }
}

crate::scene! {
    /// The relations (I), (2) of n° 66 and the second derivatives of n° 69.
    pub mod relations_scene {
        model: bicycle_kinematics,
        outputs: [
            d_eta_d_theta, d_nu_d_theta, d_eta_d_gamma, d_nu_d_gamma, steady_n,
            steady_sigma1_rate, eta_second, memoir_eta_second, mu_prime,
        ],
    }
}

/// The memoir's relations at one position, from the generated formulas of n° 66 and 69.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Relations {
    /// The exact contact (σ = η, μ) at the position.
    pub contact: Contact,
    /// (I): dη/dθ at δσ = δγ = 0.
    pub d_eta_d_theta: f64,
    /// (I): δν/δθ at δσ = δγ = 0 (a ratio of virtual displacements, not a derivative).
    pub d_nu_d_theta: f64,
    /// (I): dη/dγ at δσ = δθ = 0.
    pub d_eta_d_gamma: f64,
    /// (I): δν/δγ at δσ = δθ = 0.
    pub d_nu_d_gamma: f64,
    /// (2): the steady turning rate n per unit rear rolling rate s.
    pub steady_n: f64,
    /// (2): the steady front rolling rate σ1' per unit s.
    pub steady_sigma1_rate: f64,
    /// η'' = d²η/dθ² along the contact at fixed steer (derived, 1/rad).
    pub eta_second: f64,
    /// η'' as printed in n° 69, $R\cos^3\mu\sin\gamma/(\lambda\cos\eta)$ (meant for θ = 0 at
    /// the lowest frame position).
    pub memoir_eta_second: f64,
    /// μ' = dμ/dθ along the contact at fixed steer.
    pub mu_prime: f64,
}

/// The rest equilibrium of n° 69: the vertical frame at its lowest position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RestEquilibrium {
    /// Steer γ of the lowest frame position (rad).
    pub gamma: f64,
    /// The exact contact there.
    pub contact: Contact,
    /// λ = OM = x, the distance of the contacts (m).
    pub lambda: f64,
    /// The generated relations there.
    pub relations: Relations,
    /// η' by central differences of the exact η(θ) (step [`FD_STEP`]).
    pub eta_prime_fd: f64,
    /// η'' by central second differences of the exact η(θ) (step [`FD_STEP_SECOND`]).
    pub eta_second_fd: f64,
}

/// The height of a centre of gravity at the rest equilibrium (n° 69).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RestStability {
    /// Z at θ = 0 (m).
    pub z: f64,
    /// X = x cos η1 − z sin η1, the current abscissa of G from S (m).
    pub x: f64,
    /// −Z + X η'' with the derived η'' (m/rad²).
    pub d2z: f64,
    /// −Z + X η'' with the printed η'' (m/rad²).
    pub d2z_memoir: f64,
    /// d²Z/dθ² by central second differences of Z along the exact contact (m/rad²).
    pub d2z_fd: f64,
}

/// Step of the central first differences (rad).
pub const FD_STEP: f64 = 1e-4;
/// Step of the central second differences (rad).
pub const FD_STEP_SECOND: f64 = 1e-3;

/// A rolling condition of the front wheel (n° 60): one component of the displacement δM of
/// its contact point vanishes, a row of [`Kinematics::displacement_matrix`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RollingCondition {
    /// δM·I = 0 (no slip along the frame's horizontal trace).
    I,
    /// δM·J = 0 (no slip across it).
    J,
    /// δM·K = 0 (the contact stays on the ground).
    K,
}

impl RollingCondition {
    /// The row of [`Kinematics::displacement_matrix`].
    fn row(self) -> usize {
        match self {
            RollingCondition::I => 0,
            RollingCondition::J => 1,
            RollingCondition::K => 2,
        }
    }
}

/// The kinematics of a bicycle of given geometry (n° 44).
///
/// # Example
/// ```
/// use carvallo::bicycle::kinematics::Kinematics;
///
/// let k = Kinematics::old_model();
/// let r = k.relations(0.0, 0.0)?;               // upright and straight
/// assert!(r.d_eta_d_theta.abs() < 1e-15);
/// assert!((r.steady_sigma1_rate - 1.0).abs() < 1e-15);
/// # Ok::<(), carvallo::bicycle::geometry::ContactError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kinematics {
    geometry: Geometry,
}

/// The arguments of the generated programs for the bicycle `g` at (θ, γ, σ, μ), by name.
fn arguments(
    g: &Geometry,
    theta: f64,
    gamma: f64,
    sigma: f64,
    mu: f64,
) -> [(&'static str, f64); 8] {
    [
        ("R", g.radius()),
        ("l", g.wheelbase()),
        ("c", g.offset()),
        ("sigma0", g.sigma0()),
        ("theta", theta),
        ("gamma", gamma),
        ("sigma", sigma),
        ("mu", mu),
    ]
}

impl Kinematics {
    /// The kinematics of `geometry`.
    pub fn new(geometry: Geometry) -> Kinematics {
        Kinematics { geometry }
    }

    /// The old-model bicycle of n° 52.
    pub fn old_model() -> Kinematics {
        Kinematics::new(Geometry::old_model())
    }

    /// The geometry.
    pub fn geometry(&self) -> &Geometry {
        &self.geometry
    }

    /// The analytic displacement of M (n° 61) at (θ, γ, σ, μ): rows I, J, K, columns δσ, δθ,
    /// δν, δη, δγ, δσ1 (m/rad).
    pub fn displacement_matrix(
        &self,
        theta: f64,
        gamma: f64,
        sigma: f64,
        mu: f64,
    ) -> [[f64; 6]; 3] {
        let g = &self.geometry;
        let mut o = displacement_scene::eval(&displacement_scene::Args {
            R: g.radius(),
            l: g.wheelbase(),
            c: g.offset(),
            sigma0: g.sigma0(),
            theta,
            gamma,
            sigma,
            mu,
        });
        read_all(
            &arguments(g, theta, gamma, sigma, mu),
            &mut [
                ("dm_i_sigma", &mut o.dm_i_sigma),
                ("dm_i_theta", &mut o.dm_i_theta),
                ("dm_i_nu", &mut o.dm_i_nu),
                ("dm_i_eta", &mut o.dm_i_eta),
                ("dm_i_gamma", &mut o.dm_i_gamma),
                ("dm_i_sigma1", &mut o.dm_i_sigma1),
                ("dm_j_sigma", &mut o.dm_j_sigma),
                ("dm_j_theta", &mut o.dm_j_theta),
                ("dm_j_nu", &mut o.dm_j_nu),
                ("dm_j_eta", &mut o.dm_j_eta),
                ("dm_j_gamma", &mut o.dm_j_gamma),
                ("dm_j_sigma1", &mut o.dm_j_sigma1),
                ("dm_k_sigma", &mut o.dm_k_sigma),
                ("dm_k_theta", &mut o.dm_k_theta),
                ("dm_k_nu", &mut o.dm_k_nu),
                ("dm_k_eta", &mut o.dm_k_eta),
                ("dm_k_gamma", &mut o.dm_k_gamma),
                ("dm_k_sigma1", &mut o.dm_k_sigma1),
            ],
        );
        [
            [o.dm_i_sigma, o.dm_i_theta, o.dm_i_nu, o.dm_i_eta, o.dm_i_gamma, o.dm_i_sigma1],
            [o.dm_j_sigma, o.dm_j_theta, o.dm_j_nu, o.dm_j_eta, o.dm_j_gamma, o.dm_j_sigma1],
            [o.dm_k_sigma, o.dm_k_theta, o.dm_k_nu, o.dm_k_eta, o.dm_k_gamma, o.dm_k_sigma1],
        ]
    }

    /// Solves δM = 0 (the analytic path, n° 61) for (δη, δν, δσ1) given the fundamental
    /// displacements `[dsigma, dtheta, dgamma]` at the exact contact for (θ, γ).
    ///
    /// # Errors
    /// As [`Geometry::solve`]; `Ok(None)` when the 3×3 system is singular.
    pub fn solve_displacements(
        &self,
        theta: f64,
        gamma: f64,
        fundamental: [f64; 3],
    ) -> Result<Option<[f64; 3]>, ContactError> {
        let c = self.geometry.solve(theta, gamma)?;
        let m = self.displacement_matrix(theta, gamma, c.sigma, c.mu);
        let [ds, dt, dg] = fundamental;
        let a: [[f64; 3]; 3] = std::array::from_fn(|i| [m[i][3], m[i][2], m[i][5]]);
        let b: [f64; 3] = std::array::from_fn(|i| -(m[i][0] * ds + m[i][1] * dt + m[i][4] * dg));
        Ok(solve3(a, b))
    }

    /// The number of independent rolling conditions on the dependent displacements (δη, δν,
    /// δσ1) at the exact contact for (θ, γ): the rank of their columns in the rows of
    /// [`Kinematics::displacement_matrix`], the condition `dropped` left out. With all three it
    /// is 3 where [`Kinematics::solve_displacements`] solves a regular system, and the bicycle
    /// keeps 6 − 3 = 3 degrees of freedom (n° 59); with one dropped it is at most 2. A pivot at
    /// most $10^{-13}$ of the largest entry counts as zero, as in
    /// [`Kinematics::solve_displacements`].
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn rolling_rank(
        &self,
        theta: f64,
        gamma: f64,
        dropped: Option<RollingCondition>,
    ) -> Result<usize, ContactError> {
        let c = self.geometry.solve(theta, gamma)?;
        let m = self.displacement_matrix(theta, gamma, c.sigma, c.mu);
        let mut a = [[0.0; 3]; 3];
        let mut n = 0;
        for (i, row) in m.iter().enumerate() {
            if dropped.map(RollingCondition::row) != Some(i) {
                a[n] = [row[3], row[2], row[5]];
                n += 1;
            }
        }
        Ok(rank(&mut a[..n]))
    }

    /// The generated relations of n° 66 and 69 at the exact contact for (θ, γ).
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn relations(&self, theta: f64, gamma: f64) -> Result<Relations, ContactError> {
        let contact = self.geometry.solve(theta, gamma)?;
        let g = &self.geometry;
        let mut o = relations_scene::eval(&relations_scene::Args {
            R: g.radius(),
            l: g.wheelbase(),
            c: g.offset(),
            sigma0: g.sigma0(),
            theta,
            gamma,
            sigma: contact.sigma,
            mu: contact.mu,
        });
        read_all(
            &arguments(g, theta, gamma, contact.sigma, contact.mu),
            &mut [
                ("d_eta_d_theta", &mut o.d_eta_d_theta),
                ("d_nu_d_theta", &mut o.d_nu_d_theta),
                ("d_eta_d_gamma", &mut o.d_eta_d_gamma),
                ("d_nu_d_gamma", &mut o.d_nu_d_gamma),
                ("steady_n", &mut o.steady_n),
                ("steady_sigma1_rate", &mut o.steady_sigma1_rate),
                ("eta_second", &mut o.eta_second),
                ("memoir_eta_second", &mut o.memoir_eta_second),
                ("mu_prime", &mut o.mu_prime),
            ],
        );
        Ok(Relations {
            contact,
            d_eta_d_theta: o.d_eta_d_theta,
            d_nu_d_theta: o.d_nu_d_theta,
            d_eta_d_gamma: o.d_eta_d_gamma,
            d_nu_d_gamma: o.d_nu_d_gamma,
            steady_n: o.steady_n,
            steady_sigma1_rate: o.steady_sigma1_rate,
            eta_second: o.eta_second,
            memoir_eta_second: o.memoir_eta_second,
            mu_prime: o.mu_prime,
        })
    }

    /// Partial derivatives of the exact η(θ, γ) by central differences of steps
    /// [`FD_STEP_SECOND`] and half of it, extrapolated (Richardson, truncation of order
    /// $h^4$): `[dη/dθ, dη/dγ]`.
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn eta_partials_fd(&self, theta: f64, gamma: f64) -> Result<[f64; 2], ContactError> {
        let s = |t: f64, g: f64| self.geometry.solve(t, g).map(|c| c.sigma);
        let central = |dt: f64, dg: f64| -> Result<f64, ContactError> {
            let h = dt + dg;
            Ok((s(theta + dt, gamma + dg)? - s(theta - dt, gamma - dg)?) / (2.0 * h))
        };
        let h = FD_STEP_SECOND;
        let richardson = |a: f64, b: f64| (4.0 * b - a) / 3.0;
        Ok([
            richardson(central(h, 0.0)?, central(0.5 * h, 0.0)?),
            richardson(central(0.0, h)?, central(0.0, 0.5 * h)?),
        ])
    }

    /// The steady state from the rolling of both wheels without slip, built geometrically and
    /// independently of (2): the instantaneous centre P of the frame's horizontal motion lies
    /// on the rear axle's trace OJ and on the normal $N_1$ to the front wheel's trace through
    /// M; then $n = Rs/OP$ and $R\sigma_1' = n\,\overline{PM}$ (the front wheel's point at M
    /// moves as the frame's). Returns `[n/s, σ1'/s]` at the exact contact, or `None` when the
    /// two lines are parallel.
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn steady_by_centre(
        &self,
        theta: f64,
        gamma: f64,
    ) -> Result<Option<[f64; 2]>, ContactError> {
        let c = self.geometry.solve(theta, gamma)?;
        let f = self.geometry.front_wheel(theta, gamma, c.sigma, c.mu);
        let [x, y] = f.contact;
        let n1 = [f.alpha.sin(), -f.alpha.cos()];
        // O + t J = M + u N1: 0 = x + u n1x, t = y + u n1y.
        if n1[0].abs() < 1e-300 {
            return Ok(None);
        }
        let u = -x / n1[0];
        let t = y + u * n1[1];
        let r = self.geometry.radius();
        let n = r / t;
        // Velocity of the frame's point at M: n K x (M - P), projected on I1.
        let (px, py) = (x, y - t);
        let v = [-n * py, n * px];
        let i1 = [f.alpha.cos(), f.alpha.sin()];
        Ok(Some([n, (v[0] * i1[0] + v[1] * i1[1]) / r]))
    }

    /// The defect of integrability of ν at δσ = 0:
    /// $\partial_\gamma(\delta\nu/\delta\theta) - \partial_\theta(\delta\nu/\delta\gamma)$ by
    /// central differences of the generated (I) (step [`FD_STEP`]). Zero would mean a function
    /// ν(θ, γ); it is not zero.
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn holonomy_defect(&self, theta: f64, gamma: f64) -> Result<f64, ContactError> {
        self.cross_derivative_defect(theta, gamma, |r| [r.d_nu_d_theta, r.d_nu_d_gamma])
    }

    /// The cross-derivative test of [`Kinematics::holonomy_defect`] on any pair of the
    /// relations: `pair` picks the rates in θ and in γ of one displacement from the generated
    /// (I) of n° 66, and the result is
    /// $\partial_\gamma(\text{rate in }\theta) - \partial_\theta(\text{rate in }\gamma)$ by
    /// central differences (step [`FD_STEP`]). For ν it is not zero; for η, whose rates are the
    /// partial derivatives of the exact η(θ, γ), it vanishes to the differences' truncation.
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn cross_derivative_defect(
        &self,
        theta: f64,
        gamma: f64,
        pair: impl Fn(&Relations) -> [f64; 2],
    ) -> Result<f64, ContactError> {
        let h = FD_STEP;
        let r = |t: f64, g: f64, k: usize| self.relations(t, g).map(|r| pair(&r)[k]);
        let a = (r(theta, gamma + h, 0)? - r(theta, gamma - h, 0)?) / (2.0 * h);
        let b = (r(theta + h, gamma, 1)? - r(theta - h, gamma, 1)?) / (2.0 * h);
        Ok(a - b)
    }

    /// The analytic system of n° 68 (pedals and brake held: δσ = −δη, δγ = δσ1 = 0) in
    /// (δθ, δη, δν) at the exact contact for (θ, γ): `(|det| / product of the column norms,
    /// largest 2×2 minor / product of the two columns' norms)`. The first vanishes (to rounding)
    /// and the second does not when the rank is 2.
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn fixation_rank(&self, theta: f64, gamma: f64) -> Result<(f64, f64), ContactError> {
        let c = self.geometry.solve(theta, gamma)?;
        let m = self.displacement_matrix(theta, gamma, c.sigma, c.mu);
        let a: [[f64; 3]; 3] = std::array::from_fn(|i| [m[i][1], m[i][3] - m[i][0], m[i][2]]);
        let col = |j: usize| (0..3).map(|i| a[i][j] * a[i][j]).sum::<f64>().sqrt();
        let det = det3(&a).abs() / (col(0) * col(1) * col(2));
        let mut minor: f64 = 0.0;
        for (r1, r2) in [(0, 1), (0, 2), (1, 2)] {
            for (c1, c2) in [(0, 1), (0, 2), (1, 2)] {
                let d = (a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]).abs() / (col(c1) * col(c2));
                minor = minor.max(d);
            }
        }
        Ok((det, minor))
    }

    /// The rest equilibrium of n° 69: θ = 0 at the lowest frame position
    /// ([`Geometry::lowest_frame`]), with the generated relations and finite differences of the
    /// exact η(θ) at that steer.
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn rest_equilibrium(&self) -> Result<RestEquilibrium, ContactError> {
        let (_, _, gamma) = self.geometry.lowest_frame();
        let relations = self.relations(0.0, gamma)?;
        let contact = relations.contact;
        let lambda = self.geometry.front_wheel(0.0, gamma, contact.sigma, contact.mu).contact[0];
        let s = |t: f64| self.geometry.solve(t, gamma).map(|c| c.sigma);
        let h = FD_STEP;
        let eta_prime_fd = (s(h)? - s(-h)?) / (2.0 * h);
        let h2 = FD_STEP_SECOND;
        let eta_second_fd = (s(h2)? - 2.0 * contact.sigma + s(-h2)?) / (h2 * h2);
        Ok(RestEquilibrium { gamma, contact, lambda, relations, eta_prime_fd, eta_second_fd })
    }

    /// $d^2Z/d\theta^2$ at the rest equilibrium `eq` for a centre of gravity with coordinates
    /// `x` (forward) and `z` (up) from S in the normal frame position η0 (n° 69), three ways.
    ///
    /// # Errors
    /// As [`Geometry::solve`].
    pub fn rest_stability(
        &self,
        eq: &RestEquilibrium,
        x: f64,
        z: f64,
    ) -> Result<RestStability, ContactError> {
        let s0 = self.geometry.sigma0();
        let r = self.geometry.radius();
        let height = |theta: f64, sigma: f64| {
            let e1 = sigma - s0;
            (r + x * e1.sin() + z * e1.cos()) * theta.cos()
        };
        let e1 = eq.contact.sigma - s0;
        let z0 = height(0.0, eq.contact.sigma);
        let x0 = x * e1.cos() - z * e1.sin();
        let h = FD_STEP_SECOND;
        let zt = |t: f64| self.geometry.solve(t, eq.gamma).map(|c| height(t, c.sigma));
        let d2z_fd = (zt(h)? - 2.0 * z0 + zt(-h)?) / (h * h);
        Ok(RestStability {
            z: z0,
            x: x0,
            d2z: -z0 + x0 * eq.relations.eta_second,
            d2z_memoir: -z0 + x0 * eq.relations.memoir_eta_second,
            d2z_fd,
        })
    }
}

fn det3(a: &[[f64; 3]; 3]) -> f64 {
    a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
}

/// The rank of the rows `a` (at most three) by Gaussian elimination with partial pivoting, a
/// pivot at most $10^{-13}$ of the largest entry counting as zero (the threshold of
/// [`solve3`]); `a` is overwritten.
#[allow(clippy::needless_range_loop)] // row i is updated from row r of the same slice
fn rank(a: &mut [[f64; 3]]) -> usize {
    let n = a.len();
    let scale = a.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut r = 0;
    for k in 0..3 {
        let Some(p) = (r..n).max_by(|i, j| a[*i][k].abs().total_cmp(&a[*j][k].abs())) else {
            break;
        };
        // (a NaN pivot counts as zero)
        if a[p][k].abs().partial_cmp(&(1e-13 * scale)) != Some(std::cmp::Ordering::Greater) {
            continue;
        }
        a.swap(r, p);
        for i in r + 1..n {
            let f = a[i][k] / a[r][k];
            for j in k..3 {
                a[i][j] -= f * a[r][j];
            }
        }
        r += 1;
    }
    r
}

/// Gaussian elimination with partial pivoting; `None` for a (numerically) singular matrix.
#[allow(clippy::needless_range_loop)] // row i is updated from row k of the same array
fn solve3(mut a: [[f64; 3]; 3], mut b: [f64; 3]) -> Option<[f64; 3]> {
    let scale = a.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..3 {
        let p = (k..3).max_by(|i, j| a[*i][k].abs().total_cmp(&a[*j][k].abs()))?;
        // (a NaN pivot counts as zero)
        if a[p][k].abs().partial_cmp(&(1e-13 * scale)) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        a.swap(k, p);
        b.swap(k, p);
        for i in k + 1..3 {
            let f = a[i][k] / a[k][k];
            for j in k..3 {
                a[i][j] -= f * a[k][j];
            }
            b[i] -= f * b[k];
        }
    }
    let mut x = [0.0; 3];
    for k in (0..3).rev() {
        let s: f64 = (k + 1..3).map(|j| a[k][j] * x[j]).sum();
        x[k] = (b[k] - s) / a[k][k];
    }
    Some(x)
}
