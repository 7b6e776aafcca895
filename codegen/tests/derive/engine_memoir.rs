//! What the engine tests of the memoir's rolling systems share (`engine_hoop`,
//! `engine_unicycle`): a description derived by the engine, the memoir's hand-derived program
//! of the same system, and the check that the memoir's accelerations satisfy both of the
//! engine's equations, Kane's and Lagrange's, at 256 bits, once the coordinates are mapped.
//!
//! The engine's lean φ is about the forward axis, its heading ψ about the *downward* vertical
//! and its spin θ_R about the axle; the memoir has the inclination θ and the rotation's
//! components p on I, n on the *upward* vertical K and s on the axle j. So θ = σ₁φ, p = σ₁φ̇,
//! n = σ₂ψ̇, s = σ₃θ̇_R, with signs σ that the caller's `fits` judges at the first state (every
//! one of the eight choices is tried) and that are then used at every state.

use astro_float::{BigFloat, RoundingMode};
use carvallo_codegen::emit::emit_program;
use carvallo_codegen::mechanics::engine::{self, Model};
use carvallo_ir::Program;
use rand::Rng;

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
    // Independent speeds in the coordinates' order: psid, phid, thetaRd, whose rates are
    // sigma2 n', sigma1 p', sigma3 s'.
    let speeds = ["psid", "phid", "thetaRd"];
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

/// How one system is compared.
pub struct Comparison<'a> {
    /// The engine's description.
    pub model: Model,
    /// The memoir's program, a file under `generated/`.
    pub hand_file: &'a str,
    /// A seeded parameter vector in the order of both programs' parameters.
    pub params: &'a dyn Fn(&mut rand_chacha::ChaCha8Rng) -> Vec<f64>,
    /// Whether the sign choice `sigma` must fit (residual below `tolerance`) or must not
    /// (residual above 1e-3).
    pub must_fit: &'a dyn Fn([f64; 3]) -> bool,
    /// The signs used at every state once checked.
    pub sigma: [f64; 3],
    /// The largest residual accepted, relative to the largest term of each equation, and the
    /// largest relative difference of the energies.
    pub tolerance: f64,
    /// The seed of the states and parameters.
    pub seed: u64,
}

/// Runs `c` at 30 seeded states; returns the largest residual of Kane's and of Lagrange's
/// equations.
pub fn compare(c: &Comparison) -> [f64; 2] {
    use rand::SeedableRng;
    let (d, kane_len, redundant) =
        engine::derivation(&c.model, file!()).expect("the description derives");
    // The contact is the root point: its vertical velocity vanishes identically.
    assert_eq!(redundant.len(), 1, "dropped rows: {redundant:?}");
    let prog = emit_program(&d).expect("the engine's derivation emits");
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated").join(c.hand_file);
    let hand = Program::parse(&std::fs::read_to_string(&path).expect("the committed IR"))
        .expect("the committed IR parses");
    eprintln!(
        "{}: {} formulas ({} Kane's), {} ops; inputs {:?}; hand IR {} ops",
        c.model.name,
        d.formulas.len(),
        kane_len,
        prog.op_count().total,
        prog.inputs,
        hand.op_count().total
    );
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(c.seed);
    let mut worst = [0.0f64; 2];
    for k in 0..30 {
        let params = (c.params)(&mut rng);
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
                    "q" => s + n * theta.sin(),
                    "r" => n * theta.cos(),
                    _ => 0.0, // the unicycle's dp, dn, ds: not used by pns_* and energy
                })
                .collect();
            carvallo_ir::hp::eval(&hand, &params, &hi, 256).expect("hand")
        };
        let accel = |h: &'_ [BigFloat]| -> [BigFloat; 3] {
            ["pns_dp", "pns_dn", "pns_ds"].map(|n| at(&hand, h, n).clone())
        };
        if k == 0 {
            let fits: Vec<([f64; 3], f64)> = (0..8)
                .map(|b| [1, 2, 4].map(|m| if b & m == 0 { 1.0 } else { -1.0 }))
                .map(|s| {
                    let h = hand_at(s);
                    let a = accel(&h);
                    (s, residual(&prog, &e, "", [&a[0], &a[1], &a[2]], s))
                })
                .collect();
            eprintln!("sign choices and residuals: {fits:?}");
            for (s, r) in &fits {
                assert!(
                    if (c.must_fit)(*s) { *r < c.tolerance } else { *r > 1e-3 },
                    "signs {s:?}: residual {r:e} ({fits:?})"
                );
            }
        }
        let h = hand_at(c.sigma);
        let a = accel(&h);
        for (w, prefix) in worst.iter_mut().zip(["", "L_"]) {
            let r = residual(&prog, &e, prefix, [&a[0], &a[1], &a[2]], c.sigma);
            assert!(r < c.tolerance, "state {k}, {prefix}equations: residual {r:e}");
            *w = w.max(r);
        }
        let (ea, eb) = (at(&prog, &e, "energy"), at(&hand, &h, "energy"));
        let diff = carvallo_ir::hp::to_f64(&ea.sub(eb, 256, RM)).abs();
        let scale = carvallo_ir::hp::to_f64(eb).abs().max(1.0);
        assert!(diff <= c.tolerance * scale, "state {k}: energy differs by {diff:e}");
    }
    eprintln!(
        "{}: signs {:?}; largest residual of M u' = f with the memoir's accelerations: Kane {:e}, Lagrange {:e}",
        c.model.name, c.sigma, worst[0], worst[1]
    );
    worst
}
