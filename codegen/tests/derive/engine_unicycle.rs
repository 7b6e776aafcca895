//! The mechanics engine on the mounted unicycle: the hoop's description plus a rider body
//! (`derive/unicycle/description.rs`) gives, by Kane's method and by Carvallo's modified
//! Lagrange equations, the accelerations of the memoir's hand derivation
//! (`generated/unicycle.ir`: the virtual works of the inertia forces, n° 22–24) at 256 bits, at
//! seeded states and unicycles (the product of inertia L included).
//!
//! The two models use different coordinates: the engine's lean φ about the forward axis, heading
//! ψ about the *downward* vertical and spin θ_R about the axle, the memoir's inclination θ, the
//! rotation's components p on I, n on the *upward* vertical K and s on the axle j. So
//! θ = σ₁φ, p = σ₁φ̇, n = σ₂ψ̇, s = σ₃θ̇_R: of the eight sign choices, exactly the two the
//! axes give — (I, j, k) = (x, −y, −z), so σ = (1, −1, −1), and its mirror (−1, 1, −1) —
//! satisfy the engine's equations $M\dot u = f$ with the memoir's accelerations (the product
//! of inertia L rules out the hoop's other two mirror images); the other six leave residuals of
//! order one. Then at every state.
//!
//! Tolerance: both programs have exact constants (and the test's A1 = C1 + μ1R² is exact in
//! f64), so they agree to the rounding of 256-bit arithmetic: 1e-60 relative to the largest
//! term of each equation (largest seen 1.9e-75). The rider's x–z product entered with the wrong
//! sign in one entry of its tensor leaves 3.2e-4 (run and seen).

use carvallo_codegen::derive::unicycle::description;

use crate::engine_memoir::{compare, Comparison};

#[test]
fn engine_unicycle_equals_the_memoirs_hand_derivation_at_256_bits() {
    crate::on_symbolica_thread(|| {
        use rand::Rng;
        let params = |rng: &mut rand_chacha::ChaCha8Rng| {
            // R, g, mu, z, A, B, C, L, mu1, A1, B1, C1 (moments about the contact O, with
            // their parallel-axis parts; A1 = C1 + mu1 R^2 for a wheel of revolution).
            // R, mu1 and C1 are dyadic (multiples of 2^-10, 2^-6, 2^-10), so that
            // A1 = C1 + mu1 R^2 is exact in f64, as the engine's wheel implies it exactly.
            let dyadic = |x: f64, bits: i32| (x * 2f64.powi(bits)).round() / 2f64.powi(bits);
            let (r, g, mu, z) = (
                dyadic(rng.gen_range(0.2..0.6), 10),
                rng.gen_range(5.0..15.0),
                rng.gen_range(40.0..90.0),
                rng.gen_range(0.6..1.4),
            );
            let (a, b, c, l) = (
                mu * z * z + rng.gen_range(2.0..12.0),
                mu * z * z + rng.gen_range(2.0..12.0),
                rng.gen_range(0.5..4.0),
                rng.gen_range(-2.0..2.0),
            );
            let (mu1, d1, j1) = (
                dyadic(rng.gen_range(1.0..6.0), 6),
                dyadic(rng.gen_range(0.05..0.3), 10),
                rng.gen_range(0.1..0.6),
            );
            vec![r, g, mu, z, a, b, c, l, mu1, d1 + mu1 * r * r, j1 + mu1 * r * r, d1]
        };
        compare(&Comparison {
            model: description::unicycle(),
            hand_file: "unicycle.ir",
            params: &params,
            // The memoir's trihedron (I, j, k) is (x, -y, -z) of the engine's lean frame:
            // theta = phi, p = phi', n = -psi', s = -thetaR'. The mirror (theta, p, n) ->
            // (-theta, -p, -n) is a symmetry even with the product L; the hoop's other mirrors
            // are not (L changes sign under them).
            must_fit: &|s| s[2] == -1.0 && s[0] * s[1] == -1.0,
            sigma: [1.0, -1.0, -1.0],
            tolerance: 1e-60,
            seed: 342,
        });
    });
}
