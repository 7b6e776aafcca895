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

use astro_float::{BigFloat, RoundingMode};
use carvallo_codegen::derive::unicycle::description;
use carvallo_codegen::emit::emit_program;
use carvallo_codegen::mechanics::engine;
use carvallo_ir::Program;
use rand::{Rng, SeedableRng};

const RM: RoundingMode = RoundingMode::ToEven;

fn at<'a>(p: &Program, values: &'a [BigFloat], name: &str) -> &'a BigFloat {
    let k =
        p.outputs.iter().position(|o| o.name == name).unwrap_or_else(|| panic!("no output {name}"));
    &values[k]
}

/// The largest residual of $M\dot u = f$ relative to the largest term, for one prefix (`""` for
/// Kane's equations, `"L_"` for Lagrange's), with the memoir's accelerations mapped by `sigma`.
fn residual(
    prog: &Program,
    e: &[BigFloat],
    prefix: &str,
    accel: [&BigFloat; 3],
    sigma: [f64; 3],
) -> f64 {
    // Independent speeds in the coordinates' order: psid, phid, thetaRd.
    let speeds = ["psid", "phid", "thetaRd"];
    // psidd = sigma2 n', phidd = sigma1 p', thetaRdd = sigma3 s'.
    let p = 256;
    let big = |x: f64| carvallo_ir::hp::from_f64(x, p);
    let ud = [
        accel[1].mul(&big(sigma[1]), p, RM),
        accel[0].mul(&big(sigma[0]), p, RM),
        accel[2].mul(&big(sigma[2]), p, RM),
    ];
    let mut worst = 0.0f64;
    for i in 0..3 {
        let mut sum = at(prog, e, &format!("{prefix}f_{}", speeds[i])).neg();
        let mut scale = carvallo_ir::hp::to_f64(&sum).abs();
        for (j, udj) in ud.iter().enumerate() {
            let (a, b) = if i <= j { (i, j) } else { (j, i) };
            let m = at(prog, e, &format!("{prefix}M_{}_{}", speeds[a], speeds[b]));
            let term = m.mul(udj, p, RM);
            scale = scale.max(carvallo_ir::hp::to_f64(&term).abs());
            sum = sum.add(&term, p, RM);
        }
        worst = worst.max(carvallo_ir::hp::to_f64(&sum).abs() / scale.max(1e-300));
    }
    worst
}

#[test]
fn engine_unicycle_equals_the_memoirs_hand_derivation_at_256_bits() {
    crate::on_symbolica_thread(|| {
        let model = description::unicycle();
        let (d, kane_len, redundant) =
            engine::derivation(&model, file!()).expect("the description derives");
        // The contact is the root point: its vertical velocity vanishes identically.
        assert_eq!(redundant.len(), 1, "dropped rows: {redundant:?}");
        let prog = emit_program(&d).expect("the engine's derivation emits");
        let hand_text = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/unicycle.ir"),
        )
        .expect("generated/unicycle.ir");
        let hand = Program::parse(&hand_text).expect("the committed IR parses");
        eprintln!(
            "unicycle engine: {} formulas ({} Kane's), {} ops; inputs {:?}; hand IR {} ops",
            d.formulas.len(),
            kane_len,
            prog.op_count().total,
            prog.inputs,
            hand.op_count().total
        );
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(342);
        let mut found: Option<[f64; 3]> = None;
        let mut worst = [0.0f64; 2];
        for k in 0..30 {
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
            let params = [r, g, mu, z, a, b, c, l, mu1, d1 + mu1 * r * r, j1 + mu1 * r * r, d1];
            let phi = rng.gen_range(-1.2..1.2);
            let (psid, phid, thetard) =
                (rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0), rng.gen_range(-20.0..20.0));
            let inputs: Vec<f64> = prog
                .inputs
                .iter()
                .map(|n| match n.as_str() {
                    "phi" => phi,
                    "psid" => psid,
                    "phid" => phid,
                    "thetaRd" => thetard,
                    other => panic!("unexpected engine input {other}"),
                })
                .collect();
            let e = carvallo_ir::hp::eval(&prog, &params, &inputs, 256).expect("engine");
            let hand_at = |sigma: [f64; 3]| {
                let (theta, p, n, s) =
                    (sigma[0] * phi, sigma[0] * phid, sigma[1] * psid, sigma[2] * thetard);
                let hi: Vec<f64> = hand
                    .inputs
                    .iter()
                    .map(|name| match name.as_str() {
                        "theta" => theta,
                        "p" => p,
                        "n" => n,
                        "s" => s,
                        _ => 0.0, // dp, dn, ds: not used by pns_* and energy
                    })
                    .collect();
                carvallo_ir::hp::eval(&hand, &params, &hi, 256).expect("hand")
            };
            let sigmas: Vec<[f64; 3]> =
                (0..8).map(|b| [1, 2, 4].map(|m| if b & m == 0 { 1.0 } else { -1.0 })).collect();
            let sigma = match found {
                Some(s) => s,
                None => {
                    let fits: Vec<([f64; 3], f64)> = sigmas
                        .iter()
                        .map(|&s| {
                            let h = hand_at(s);
                            let acc = [
                                at(&hand, &h, "pns_dp"),
                                at(&hand, &h, "pns_dn"),
                                at(&hand, &h, "pns_ds"),
                            ];
                            (s, residual(&prog, &e, "", acc, s))
                        })
                        .collect();
                    eprintln!("sign choices and residuals: {fits:?}");
                    // The memoir's trihedron (I, j, k) is (x, -y, -z) of the engine's lean
                    // frame: theta = phi, p = phi', n = -psi', s = -thetaR'. The mirror
                    // (theta, p, n) -> (-theta, -p, -n) is a symmetry even with the product L;
                    // the hoop's other mirrors are not (L changes sign under them).
                    for (s, r) in &fits {
                        let fits_axes = s[2] == -1.0 && s[0] * s[1] == -1.0;
                        assert!(
                            if fits_axes { *r < 1e-60 } else { *r > 1e-3 },
                            "signs {s:?}: residual {r:e} ({fits:?})"
                        );
                    }
                    found = Some([1.0, -1.0, -1.0]);
                    [1.0, -1.0, -1.0]
                }
            };
            let h = hand_at(sigma);
            let acc = [at(&hand, &h, "pns_dp"), at(&hand, &h, "pns_dn"), at(&hand, &h, "pns_ds")];
            for (w, prefix) in worst.iter_mut().zip(["", "L_"]) {
                let r = residual(&prog, &e, prefix, acc, sigma);
                assert!(r < 1e-60, "state {k}, {prefix}equations: residual {r:e}");
                *w = w.max(r);
            }
            // The energies agree too (the memoir's includes mu g R cos theta).
            let (ea, eb) = (at(&prog, &e, "energy"), at(&hand, &h, "energy"));
            let diff = carvallo_ir::hp::to_f64(&ea.sub(eb, 256, RM)).abs();
            assert!(
                diff <= 1e-15 * carvallo_ir::hp::to_f64(eb).abs().max(1.0),
                "state {k}: energy"
            );
        }
        eprintln!(
            "signs {:?}; largest residual of M u' = f with the memoir's accelerations: Kane {:e}, Lagrange {:e}",
            found, worst[0], worst[1]
        );
    });
}
