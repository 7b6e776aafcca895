//! The inertia terms of the bicycle's fall equation (memoir n° 81–83, 99) term by term, by an
//! independent route: each rigid part represented by point masses whose velocities are built
//! from the memoir's kinematics (n° 5, 81, 82, 99), the sums $\sum m\,M'|(dM/d\theta)'$ and
//! $\sum m\,M'^2$ taken point by point, and the memoir's printed terms (with their underlined,
//! non-steady parts) evaluated beside them at seeded, arbitrary states.
//!
//! These are kinematic identities: they hold for any values of the angles, rates and of the
//! coefficients $d\eta/d\theta$, $d\nu/d\theta$, $d\sigma_1/d\theta$ and their time derivatives,
//! so the states are drawn freely ([`STATES`] of them) and every difference beyond rounding is
//! an error of a printed term. The generated `bicycle_steady` program has the steady sums only;
//! this route also reaches the six frame terms of n° 83 one by one and the non-steady parts.
//!
//! Frames: I, J, K fixed at the instant (I the frame's trace, K up), $j = J\cos\theta +
//! K\sin\theta$, $k = -J\sin\theta + K\cos\theta$ (n° 1); the loaded frame is a cloud of point
//! masses symmetric about its plane (the memoir's $e, h, A, B, C, L$ are computed from it), a
//! wheel is a ring of [`RING`] equal masses (its moments about the contact point are then
//! exactly $A_1, B_1, C_1 = \frac32, 2, \frac12\,\mu_1R^2$).

use nalgebra::Vector3;

use crate::sample::Rng;

type V = Vector3<f64>;

/// Seeded states per check.
pub const STATES: usize = 64;
/// Point masses of a wheel's ring.
pub const RING: usize = 12;
/// Seed of the states.
pub const SEED: u64 = 0x6e38_312d_3833_7465;

fn det(a: &V, b: &V, c: &V) -> f64 {
    a.dot(&b.cross(c))
}

/// Relative difference with a floor of 1e-9 (the quantities are of order one).
fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(1e-9)
}

/// A mass point: (mass, position relative to the rear contact O).
type Point = (f64, V);

/// The kinematics the point sums are taken with: as derived, or with one ingredient changed
/// (issue 38: the perturbations of the derived side that must break the checks of n° 81–83
/// and 99).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Route {
    /// The memoir's kinematics: the wheels roll without sliding.
    #[default]
    Derived,
    /// The contacts slide sideways at this speed (m/s) along J: the rear contact's O' (and
    /// the front contact's O1') gain it, and every point of the frame and of the wheels moves
    /// with it (rolling without sliding dropped, the constraint of n° 5).
    LateralSlip(f64),
    /// The rate of the front wheel's axle j1 taken with the opposite sign,
    /// $j_1' = -(I_1p_1 + Kn_1) \times j_1$ (the sign of the memoir's (1′)).
    FrontAxleRateNegated,
}

impl Route {
    /// The sideways sliding speed (m/s): zero but for [`Route::LateralSlip`].
    fn slip(self) -> f64 {
        match self {
            Route::LateralSlip(v) => v,
            _ => 0.0,
        }
    }
}

/// Axes at the lean θ: (I, J, K, j, k).
fn axes(theta: f64) -> (V, V, V, V, V) {
    let (i, jj, kk) = (V::x(), V::y(), V::z());
    let j = jj * theta.cos() + kk * theta.sin();
    let k = -jj * theta.sin() + kk * theta.cos();
    (i, jj, kk, j, k)
}

/// The largest relative differences of the six frame terms of n° 83 (numbered as printed),
/// whole and with the underlined terms dropped at a steady state, and of their sum.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameTerms {
    /// Term (1)..(6) at arbitrary states (underlined parts included).
    pub whole: [f64; 6],
    /// Term (1)..(6) at steady states ($p = \eta' = (d\eta/d\theta)' = (d\nu/d\theta)' = 0$),
    /// the printed terms without their underlined parts.
    pub steady: [f64; 6],
    /// The six computed terms summed against $\sum m\,M'|(dM/d\theta)'$ taken whole: the
    /// decomposition of n° 83 itself.
    pub decomposition: f64,
    /// The printed sum against the computed sum, arbitrary states.
    pub sum_whole: f64,
    /// Term (1)..(6) against the corrected forms (`corrected_terms`, private to this module),
    /// every state.
    pub corrected: [f64; 6],
}

/// The loaded frame's constants and a state, for [`corrected_terms`].
struct FrameState {
    mu: f64,
    r: f64,
    e: f64,
    h: f64,
    a: f64,
    b: f64,
    c: f64,
    l: f64,
    theta: f64,
    p: f64,
    n: f64,
    s: f64,
    eta_t: f64,
    deta: f64,
    dnu: f64,
    deta_dot: f64,
    dnu_dot: f64,
}

/// The six terms of n° 83 as derived here by hand from the moments of momentum about O and S,
/// $H_O = I(Ap - Ln\cos\theta) + j[\mu Rh(s + \eta') + B(n\sin\theta - \eta')] + k(Cn\cos\theta
/// - Lp)$ and $H_S = H_O - \mu R\,k \times G'$, with $L = \sum m\,zx$ as in the $2T_0$ of n° 99.
///
/// They are the printed terms with $-L$ for $L$ in (3), (4) and (6), with
/// $+\mu R e\,n^2\cos^2\theta$ for $-\mu R e\,n^2\sin\theta\cos\theta$ in (4), and with
/// $-B\eta'$ added in (5).
fn corrected_terms(f: &FrameState) -> [f64; 6] {
    let FrameState { mu, r, e, h, a, b, c, l, theta, p, n, s, eta_t, deta, dnu, deta_dot, dnu_dot } =
        *f;
    let (st, ct) = (theta.sin(), theta.cos());
    [
        mu * r * deta * (e * n * st - e * eta_t) * (s + n * st),
        mu * r * s * dnu * (-e * n + h * p * ct + e * eta_t * st),
        mu * r * h * (s + eta_t) * n * ct + b * n * ct * (n * st - eta_t)
            - n * st * (-l * p + c * n * ct),
        deta * (l * p * p + (a - c - mu * r * h) * n * p * ct + n * n * ct * ct * (mu * r * e - l)),
        -deta_dot
            * ((b - mu * r * h) * n * st
                + mu * r * (h - r) * s
                + (mu * r * (2.0 * h - r) - b) * eta_t),
        dnu_dot
            * ((mu * r * h * (s + eta_t) + b * (n * st - eta_t)) * st + (-l * p + c * n * ct) * ct),
    ]
}

/// The loaded frame (n° 83): a symmetric cloud of `2 × 4` masses.
fn frame_cloud(rng: &mut Rng) -> Vec<Point> {
    let mut pts = Vec::new();
    for _ in 0..4 {
        let m = rng.uniform(5.0, 25.0);
        let (x, y, z) = (rng.uniform(-0.6, 1.0), rng.uniform(0.0, 0.3), rng.uniform(0.2, 1.6));
        // coordinates on I, j, k (placed on the state's axes in `frame_terms`)
        pts.push((m, V::new(x, y, z)));
        pts.push((m, V::new(x, -y, z)));
    }
    pts
}

/// n° 83 term by term.
pub fn frame_terms() -> FrameTerms {
    frame_terms_with(Route::Derived)
}

/// n° 83 term by term, the point velocities from the kinematics `route`.
pub fn frame_terms_with(route: Route) -> FrameTerms {
    let slip = route.slip();
    let mut rng = Rng(SEED);
    let mut out = FrameTerms::default();
    for case in 0..2 * STATES {
        let steady = case >= STATES;
        let cloud = frame_cloud(&mut rng);
        let theta = rng.uniform(-0.7, 0.7);
        let r = rng.uniform(0.3, 0.5);
        let (p, n, s) = (rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0), rng.uniform(2.0, 20.0));
        let eta_t = rng.uniform(-1.0, 1.0);
        let (deta, dnu) = (rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5));
        let (deta_dot, dnu_dot) = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        let (p, eta_t, deta_dot, dnu_dot) =
            if steady { (0.0, 0.0, 0.0, 0.0) } else { (p, eta_t, deta_dot, dnu_dot) };
        let (i, jj, kk, j, k) = axes(theta);
        // The frame's constants from the cloud (coordinates on I, j, k).
        let mu: f64 = cloud.iter().map(|(m, _)| m).sum();
        let e = cloud.iter().map(|(m, q)| m * q.x).sum::<f64>() / mu;
        let h = cloud.iter().map(|(m, q)| m * q.z).sum::<f64>() / mu;
        let sum = |f: &dyn Fn(&V) -> f64| cloud.iter().map(|(m, q)| m * f(q)).sum::<f64>();
        let a = sum(&|q| q.y * q.y + q.z * q.z);
        let b = sum(&|q| q.x * q.x + q.z * q.z);
        let c = sum(&|q| q.x * q.x + q.y * q.y);
        let l = sum(&|q| q.z * q.x);
        // Kinematics (n° 5, 99).
        let phi = i * p + kk * n;
        let psi = phi - j * eta_t;
        let o_dot = i * (r * s) + jj * slip;
        let s_pos = k * r;
        let s_dot = o_dot + phi.cross(&s_pos);
        let i_dot = jj * n;
        let j_dot = phi.cross(&j);
        let mut t = [0.0; 6];
        let mut direct = 0.0;
        for (m, q) in &cloud {
            let x = i * q.x + j * q.y + k * q.z; // M - O
            let v = i * (r * (s + eta_t)) + jj * slip + psi.cross(&x); // M'
            let xs = x - s_pos; // M - S
            t[0] += m * deta * det(&j, &s_dot, &v);
            t[1] += -m * dnu * det(&kk, &o_dot, &v);
            t[2] += m * det(&i_dot, &x, &v);
            t[3] += -m * deta * det(&j_dot, &xs, &v);
            t[4] += -m * deta_dot * det(&j, &xs, &v);
            t[5] += m * dnu_dot * det(&kk, &x, &v);
            // (dM/dθ)' directly: d/dt of I×(M−O) − deta j×(M−S) + dnu K×(M−O).
            let dm = i_dot.cross(&x) + i.cross(&(v - o_dot))
                - (j * deta_dot).cross(&xs)
                - (j_dot * deta).cross(&xs)
                - (j * deta).cross(&(v - s_dot))
                + (kk * dnu_dot).cross(&x)
                + (kk * dnu).cross(&(v - o_dot));
            direct += m * v.dot(&dm);
        }
        let (st, ct) = (theta.sin(), theta.cos());
        let printed = [
            mu * r * deta * (e * n * st - e * eta_t) * (s + n * st),
            mu * r * s * dnu * (-e * n + h * p * ct + e * eta_t * st),
            mu * r * h * (s + eta_t) * n * ct + b * n * ct * (n * st - eta_t)
                - n * st * (l * p + c * n * ct),
            deta * (-l * p * p
                + (a - c - mu * r * h) * n * p * ct
                + n * n * ct * (l * ct - mu * r * e * st)),
            -deta_dot
                * ((b - mu * r * h) * n * st
                    + mu * r * (h - r) * s
                    + mu * r * (2.0 * h - r) * eta_t),
            dnu_dot
                * ((mu * r * h * (s + eta_t) + b * (n * st - eta_t)) * st
                    + (l * p + c * n * ct) * ct),
        ];
        let fixed = corrected_terms(&FrameState {
            mu,
            r,
            e,
            h,
            a,
            b,
            c,
            l,
            theta,
            p,
            n,
            s,
            eta_t,
            deta,
            dnu,
            deta_dot,
            dnu_dot,
        });
        let worst = if steady { &mut out.steady } else { &mut out.whole };
        for k in 0..6 {
            worst[k] = worst[k].max(rel(t[k], printed[k]));
            out.corrected[k] = out.corrected[k].max(rel(t[k], fixed[k]));
        }
        let total: f64 = t.iter().sum();
        out.decomposition = out.decomposition.max(rel(total, direct));
        if !steady {
            out.sum_whole = out.sum_whole.max(rel(total, printed.iter().sum()));
        }
    }
    out
}

/// A wheel's ring about its contact point `o` (relative to O): centre `o + R k1` in the plane
/// of `i1`, `k1`.
fn ring(mass: f64, radius: f64, o: &V, i1: &V, k1: &V, phase: f64) -> Vec<Point> {
    (0..RING)
        .map(|q| {
            let a = phase + std::f64::consts::TAU * q as f64 / RING as f64;
            let pos = o + k1 * radius + (i1 * a.cos() + k1 * a.sin()) * radius;
            (mass / RING as f64, pos)
        })
        .collect()
}

/// The wheels' checks: n° 81 (rear), 82 (front) and the kinetic energies of n° 99.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WheelTerms {
    /// n° 81, the printed sum (underlined part included) against the point sum.
    pub rear_whole: f64,
    /// n° 81, term (2) $\mu_1R^2ps\,(d\nu/d\theta)\cos\theta$.
    pub rear_term2: f64,
    /// n° 82, (2) + (3) with the exact $\Theta_1'$ against the point sum: the route itself.
    pub front_route: f64,
    /// n° 82, (2) + (3) with the printed $\Theta_1'$ of (1′), arbitrary states.
    pub front_printed_whole: f64,
    /// The same at steady states ($p = p_1 = 0$ and the underlined terms zero).
    pub front_printed_steady: f64,
    /// n° 82, (2) + (3) with (1′)'s $d\sigma_1/d\theta$ term of the opposite sign.
    pub front_sign_corrected: f64,
    /// n° 99: $2T_1$ and $2T_2$ as printed against $\sum m\,M'^2$.
    pub kinetic: f64,
    /// The largest moments' difference of the ring from $\frac32, 2, \frac12\,\mu_1R^2$.
    pub ring_moments: f64,
}

/// n° 81, 82 and the wheels' kinetic energies of n° 99.
pub fn wheel_terms() -> WheelTerms {
    wheel_terms_with(Route::Derived)
}

/// n° 81, 82 and 99, the point velocities from the kinematics `route`.
pub fn wheel_terms_with(route: Route) -> WheelTerms {
    let slip = route.slip();
    let axle_sign = if route == Route::FrontAxleRateNegated { -1.0 } else { 1.0 };
    let mut rng = Rng(SEED ^ 0x5757);
    let mut out = WheelTerms::default();
    for case in 0..2 * STATES {
        let steady = case >= STATES;
        let theta = rng.uniform(-0.7, 0.7);
        let (r, mu1) = (rng.uniform(0.3, 0.5), rng.uniform(1.0, 8.0));
        let (a1, b1, c1) = (1.5 * mu1 * r * r, 2.0 * mu1 * r * r, 0.5 * mu1 * r * r);
        let (p, n, s) = (rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0), rng.uniform(2.0, 20.0));
        let (dnu, dnu_dot) = (rng.uniform(-0.5, 0.5), rng.uniform(-1.0, 1.0));
        let (deta, deta_dot) = (rng.uniform(-0.5, 0.5), rng.uniform(-1.0, 1.0));
        let (dsig, dsig_dot) = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        let (alpha, theta1) = (rng.uniform(-0.6, 0.6), rng.uniform(-0.7, 0.7));
        let (p1, n1, s1) = (rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0), rng.uniform(2.0, 20.0));
        let phase = rng.uniform(0.0, 1.0);
        let (p, p1, dnu_dot, deta_dot, dsig_dot) =
            if steady { (0.0, 0.0, 0.0, 0.0, 0.0) } else { (p, p1, dnu_dot, deta_dot, dsig_dot) };
        let (i, jj, kk, j, k) = axes(theta);
        // Rear wheel (n° 81): Ω = Ip + j(s + n sin θ) + k n cos θ, M' = Ω × (M − O).
        let omega = i * p + j * (s + n * theta.sin()) + k * (n * theta.cos());
        let o = V::zeros();
        let rear = ring(mu1, r, &o, &i, &k, phase);
        let big_theta = i + kk * dnu;
        let big_theta_dot = jj * n + kk * dnu_dot;
        let o_dot = i * (r * s) + jj * slip;
        let mut sum = 0.0;
        let mut kin = 0.0;
        let mut moments = [0.0; 3];
        for (m, x) in &rear {
            let v = omega.cross(x) + jj * slip;
            let dm = big_theta_dot.cross(x) + big_theta.cross(&(v - o_dot));
            sum += m * v.dot(&dm);
            kin += m * v.dot(&v);
            let (xi, xj, xk) = (x.dot(&i), x.dot(&j), x.dot(&k));
            moments[0] += m * (xj * xj + xk * xk);
            moments[1] += m * (xi * xi + xk * xk);
            moments[2] += m * (xi * xi + xj * xj);
        }
        for (got, want) in moments.iter().zip([a1, b1, c1]) {
            out.ring_moments = out.ring_moments.max(rel(*got, want));
        }
        let (st, ct) = (theta.sin(), theta.cos());
        let term2 = mu1 * r * r * p * s * dnu * ct;
        let printed = b1 * s * n * ct
            + (b1 - c1) * n * n * st * ct
            + dnu_dot * (b1 * s * st + (c1 * ct * ct + b1 * st * st) * n)
            + term2;
        out.rear_whole = out.rear_whole.max(rel(sum, printed));
        if !steady {
            // term (2) alone: −Σ m [Θ O' M'].
            let t2: f64 = rear
                .iter()
                .map(|(m, x)| -m * det(&big_theta, &o_dot, &(omega.cross(x) + jj * slip)))
                .sum();
            out.rear_term2 = out.rear_term2.max(rel(t2, term2));
        }
        let q = s + n * st;
        let kin_printed = a1 * p * p + b1 * q * q + c1 * n * n * ct * ct;
        out.kinetic = out.kinetic.max(rel(kin, kin_printed));
        // Front wheel (n° 82): axes I1, J1 at heading α, j1, k1 at lean θ1 (n° 58).
        let i1 = i * alpha.cos() + jj * alpha.sin();
        let big_j1 = -i * alpha.sin() + jj * alpha.cos();
        let j1 = big_j1 * theta1.cos() + kk * theta1.sin();
        let k1 = -big_j1 * theta1.sin() + kk * theta1.cos();
        let o1 = i * rng.uniform(0.9, 1.2) + jj * rng.uniform(-0.1, 0.1);
        let omega1 = i1 * p1 + j1 * s1 + kk * n1;
        let front = ring(mu1, r, &o1, &i1, &k1, phase);
        let vrot = i - j * deta + kk * dnu + j1 * dsig; // Θ1 of (1)
        let j_dot = (i * p + kk * n).cross(&j);
        let j1_dot = (i1 * p1 + kk * n1).cross(&j1) * axle_sign;
        let vrot_dot =
            jj * n - j_dot * deta - j * deta_dot + kk * dnu_dot + j1_dot * dsig + j1 * dsig_dot;
        // (1') as printed: Jn + (−pk + I n cos θ) dη/dθ + (−p1 k1 + I1 n1 cos θ1) dσ1/dθ − ...
        let vrot_printed =
            jj * n + (-k * p + i * (n * ct)) * deta + (-k1 * p1 + i1 * (n1 * theta1.cos())) * dsig
                - j * deta_dot
                + kk * dnu_dot
                + j1 * dsig_dot;
        let vrot_flipped =
            jj * n + (-k * p + i * (n * ct)) * deta + (k1 * p1 - i1 * (n1 * theta1.cos())) * dsig
                - j * deta_dot
                + kk * dnu_dot
                + j1 * dsig_dot;
        let o1_dot = i1 * (r * s1) + jj * slip;
        let mut fsum = 0.0;
        let mut fkin = 0.0;
        for (m, x) in &front {
            let v = omega1.cross(&(x - o1)) + jj * slip;
            let dm = vrot_dot.cross(&(x - o1)) + vrot.cross(&(v - o1_dot));
            fsum += m * v.dot(&dm);
            fkin += m * v.dot(&v);
        }
        let q1 = s1 + n1 * theta1.sin();
        let r1 = n1 * theta1.cos();
        let moment = i1 * (a1 * p1) + j1 * (b1 * q1) + k1 * (c1 * r1);
        let term2f = mu1 * r * r * p1 * s1 * det(&vrot, &i1, &j1);
        let route = term2f + vrot_dot.dot(&moment);
        out.front_route = out.front_route.max(rel(fsum, route));
        let printed_f = term2f + vrot_printed.dot(&moment);
        if steady {
            out.front_printed_steady = out.front_printed_steady.max(rel(fsum, printed_f));
        } else {
            out.front_printed_whole = out.front_printed_whole.max(rel(fsum, printed_f));
            let flipped = term2f + vrot_flipped.dot(&moment);
            out.front_sign_corrected = out.front_sign_corrected.max(rel(fsum, flipped));
        }
        let kin1 = a1 * p1 * p1 + b1 * q1 * q1 + c1 * r1 * r1;
        out.kinetic = out.kinetic.max(rel(fkin, kin1));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_frame_terms_fail_exactly_where_the_corrections_say() {
        let f = frame_terms();
        assert!(f.decomposition < 1e-12, "{f:?}");
        for k in 0..6 {
            assert!(f.corrected[k] < 1e-12, "corrected term {}: {f:?}", k + 1);
            let steady_ok = f.steady[k] < 1e-12;
            assert_eq!(steady_ok, k != 3, "steady term {}: {f:?}", k + 1);
            let whole_ok = f.whole[k] < 1e-12;
            assert_eq!(whole_ok, k < 2, "term {}: {f:?}", k + 1);
        }
    }

    #[test]
    fn the_wheel_terms_hold_but_for_the_sign_of_the_front_wheels_sigma1_term() {
        let w = wheel_terms();
        for v in [
            w.rear_whole,
            w.rear_term2,
            w.front_route,
            w.front_printed_steady,
            w.front_sign_corrected,
            w.kinetic,
            w.ring_moments,
        ] {
            assert!(v < 1e-12, "{w:?}");
        }
        assert!(w.front_printed_whole > 1e-3, "{w:?}");
    }
}
