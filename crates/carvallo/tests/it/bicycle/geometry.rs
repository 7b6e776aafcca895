//! Tests of the bicycle geometry runtime (memoir n° 43–58): the Newton solver of the contact
//! equations against an independent hand-written evaluation of the vectors of n° 46–47, its
//! symmetry, the first-order method of n° 51 against the exact solution, the accessory angles
//! and front axes of n° 57–58, and the typed errors.

use carvallo::bicycle::geometry::{ContactError, Geometry};
use carvallo::numerics::rng::SplitMix64;
use carvallo::ParameterError;

/// $K|OM$ written by hand from n° 46–47 (not from the generated code): OM = Rk + aH - bG +
/// cH1 - R(H1 sin mu + G cos mu), on K.
fn height_by_hand(g: &Geometry, theta: f64, gamma: f64, sigma: f64, mu: f64) -> f64 {
    let (st, ct) = theta.sin_cos();
    let (ss, cs) = sigma.sin_cos();
    let (sg, cg) = gamma.sin_cos();
    let (sm, cm) = mu.sin_cos();
    let k_small = ct; // k on K
    let h = ct * ss; // H on K
    let gk = ct * cs; // G on K
    let h1 = st * sg + ct * cg * ss; // H1 on K
    g.radius() * k_small + g.a() * h - g.b() * gk + g.offset() * h1
        - g.radius() * (h1 * sm + gk * cm)
}

/// Seeded (θ, γ) pairs: |θ| ≤ 40°, |γ| ≤ 90° (SplitMix64, seed fixed).
fn positions() -> Vec<(f64, f64)> {
    let mut rng = SplitMix64(0x6765_6f6d_6574_7279);
    let mut next = || rng.next_unit();
    (0..200)
        .map(|_| ((next() * 80.0 - 40.0).to_radians(), (next() * 180.0 - 90.0).to_radians()))
        .collect()
}

#[test]
fn normal_position_is_the_upright_solution() {
    let g = Geometry::old_model();
    let c = g.solve(0.0, 0.0).unwrap();
    assert!((c.sigma - g.sigma0()).abs() <= 1e-14, "sigma = {}", c.sigma);
    assert!((c.mu - g.sigma0()).abs() <= 1e-14, "mu = {}", c.mu);
}

#[test]
fn newton_converges_and_the_hand_written_height_vanishes() {
    let g = Geometry::old_model();
    for (theta, gamma) in positions() {
        let c = g.solve(theta, gamma).unwrap_or_else(|e| panic!("{e}"));
        let r = g.residuals(theta, gamma, c.sigma, c.mu);
        assert!(r[0].abs() <= 1e-14 && r[1].abs() <= 1e-14, "residuals {r:?} at {theta}, {gamma}");
        let h = height_by_hand(&g, theta, gamma, c.sigma, c.mu);
        assert!(h.abs() <= 1e-14, "hand-written height {h} at {theta}, {gamma}");
        // M is the lowest point: the other points of the rim are above the ground.
        for dm in [-1e-2, -1e-4, 1e-4, 1e-2, 1.0, 3.0] {
            let other = height_by_hand(&g, theta, gamma, c.sigma, c.mu + dm);
            assert!(other > 0.0, "point mu + {dm} at height {other} at {theta}, {gamma}");
        }
    }
}

#[test]
fn mirror_symmetry() {
    // Mirroring in the frame's plane changes the signs of theta and gamma, not sigma or mu.
    let g = Geometry::old_model();
    for (theta, gamma) in positions().into_iter().take(50) {
        let a = g.solve(theta, gamma).unwrap();
        let b = g.solve(-theta, -gamma).unwrap();
        assert!((a.sigma - b.sigma).abs() <= 1e-14 && (a.mu - b.mu).abs() <= 1e-14);
    }
}

#[test]
fn first_order_method_against_the_exact_solution() {
    let g = Geometry::old_model();
    let mut worst: f64 = 0.0;
    for k in 0..=90 {
        let gamma = (k as f64).to_radians();
        let exact = g.solve(0.0, gamma).unwrap();
        let fo = g.first_order(gamma);
        let s1 = exact.sigma - g.sigma0();
        worst = worst.max((fo.sigma1 - s1).abs());
        // The second-order remainder: below 2 % of sigma1 itself (sigma1 <= 0.5°).
        assert!(
            (fo.sigma1 - s1).abs() <= 0.02 * s1.abs() + 1e-15,
            "gamma {k}°: {} vs {s1}",
            fo.sigma1
        );
        assert!(((fo.mu0 + fo.mu1) - exact.mu).abs() <= 2e-5, "gamma {k}°");
    }
    // The printed (2)' (sin sigma0 for cos sigma0) is farther off than the derived one.
    let gamma = 60f64.to_radians();
    let s1 = g.solve(0.0, gamma).unwrap().sigma - g.sigma0();
    let fo = g.first_order(gamma);
    assert!((fo.sigma1_printed - s1).abs() > 10.0 * (fo.sigma1 - s1).abs());
    assert!(worst < 1e-4, "worst first-order error {worst} rad");
}

/// The front wheel's plane normal CN, its horizontal axis i1 and its axis k1, written by hand
/// from n° 46–47 (not from the generated code): the frame's vectors on I, J, K with the rear
/// plane's normal n = J cos θ + K sin θ, k = −J sin θ + K cos θ, H = I cos σ + k sin σ,
/// G = −I sin σ + k cos σ (the steering axis), H1 = H cos γ + n sin γ; the front plane holds G
/// and H1, so CN = H1 × G (unit: G ⊥ H1), i1 = K × CN / |K × CN| and k1 = CN × i1.
fn front_axes_by_hand(theta: f64, gamma: f64, sigma: f64) -> [[f64; 3]; 3] {
    let (st, ct) = theta.sin_cos();
    let (ss, cs) = sigma.sin_cos();
    let (sg, cg) = gamma.sin_cos();
    let n = [0.0, ct, st];
    let k = [0.0, -st, ct];
    let h: [f64; 3] = std::array::from_fn(|i| [1.0, 0.0, 0.0][i] * cs + k[i] * ss);
    let g: [f64; 3] = std::array::from_fn(|i| -[1.0, 0.0, 0.0][i] * ss + k[i] * cs);
    let h1: [f64; 3] = std::array::from_fn(|i| h[i] * cg + n[i] * sg);
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    };
    let cn = cross(h1, g);
    let kxn = cross([0.0, 0.0, 1.0], cn);
    let norm = (kxn[0] * kxn[0] + kxn[1] * kxn[1]).sqrt();
    let i1 = [kxn[0] / norm, kxn[1] / norm, 0.0];
    [cn, i1, cross(cn, i1)]
}

#[test]
fn accessory_angles_and_front_axes() {
    let g = Geometry::old_model();
    // Steer 0: the front wheel leans with the frame, beta = -theta, alpha = 0.
    for theta in [-0.5f64, -0.1, 0.0, 0.2, 0.6] {
        let c = g.solve(theta, 0.0).unwrap();
        let f = g.front_wheel(theta, 0.0, c.sigma, c.mu);
        assert!((f.beta + theta).abs() <= 1e-14 && f.alpha.abs() <= 1e-14, "theta {theta}");
    }
    // Against the axes by hand at the solved (σ, μ): the same formulas in another order, so
    // a few ulps (measured below 1e-15); 1e-14 absolute on unit vectors and on the angles
    // (|α|, |β| < π/2, away from the poles of asin and atan2 at these positions).
    for (theta, gamma) in positions().into_iter().take(50) {
        let c = g.solve(theta, gamma).unwrap();
        let f = g.front_wheel(theta, gamma, c.sigma, c.mu);
        let [cn, i1, k1] = front_axes_by_hand(theta, gamma, c.sigma);
        for i in 0..3 {
            assert!((cn[i] - f.normal[i]).abs() <= 1e-14, "CN {cn:?} vs {:?}", f.normal);
            assert!((k1[i] - f.k1[i]).abs() <= 1e-14, "k1 {k1:?} vs {:?}", f.k1);
        }
        for i in 0..2 {
            assert!((i1[i] - f.i1[i]).abs() <= 1e-14, "i1 {i1:?} vs {:?}", f.i1);
        }
        // n° 57 (1): CN = I cos b sin a - J cos b cos a + K sin b, solved for a and b.
        let beta = cn[2].asin();
        let alpha = cn[0].atan2(-cn[1]);
        assert!((beta - f.beta).abs() <= 1e-14, "beta {beta} vs {}", f.beta);
        assert!((alpha - f.alpha).abs() <= 1e-14, "alpha {alpha} vs {}", f.alpha);
    }
}

#[test]
fn lowest_frame_is_the_minimum_of_sigma() {
    let g = Geometry::old_model();
    let (sigma, mu, gamma) = g.lowest_frame();
    assert!((mu - (0.08f64 / 0.38).asin()).abs() <= 1e-15);
    let at = g.solve(0.0, gamma).unwrap();
    assert!((at.sigma - sigma).abs() <= 1e-12 && (at.mu - mu).abs() <= 1e-12);
    for d in [-0.05, -0.01, 0.01, 0.05] {
        assert!(g.solve(0.0, gamma + d).unwrap().sigma > sigma);
    }
    let fig = g.figure_11(19).unwrap();
    assert_eq!(fig.len(), 19);
    assert!(fig.iter().all(|p| p[1] <= 0.0 && p[1] >= (sigma - g.sigma0()).to_degrees() - 1e-12));
    let locus = g.figure_13(10).unwrap();
    assert!(locus[0][1].abs() <= 1e-15 && (locus[9][2] - 0.08).abs() <= 1e-14);
}

#[test]
fn bad_input_is_a_typed_error() {
    let err = Geometry::new(0.38, 1.1, 0.5, 0.4).unwrap_err();
    assert_eq!(err.to_string(), "invalid offset 0.5: must satisfy 0 <= c < radius");
    assert!(matches!(
        Geometry::new(-1.0, 1.1, 0.0, 0.4),
        Err(ParameterError::InvalidParameter { name: "radius", .. })
    ));
    assert!(matches!(
        Geometry::new(0.38, 1.1, 0.08, 1.6),
        Err(ParameterError::InvalidParameter { name: "sigma0", .. })
    ));
    let g = Geometry::old_model();
    let e = g.solve(f64::NAN, 0.0).unwrap_err();
    assert_eq!(e.to_string(), "invalid theta NaN: must be finite with |theta| < pi/2");
    assert!(matches!(
        g.solve(0.1, f64::INFINITY),
        Err(ContactError::Parameter(ParameterError::InvalidParameter { name: "gamma", .. }))
    ));
}
