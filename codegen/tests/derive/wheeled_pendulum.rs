//! The two-wheeled inverted pendulum (`derive/wheeled_pendulum`), the engine's worked example of
//! a rolling system that is not a bicycle, against routes that do not use the engine:
//!
//! - a planar Lagrangian written by hand for the straight motion (axle's forward position $x$,
//!   pitch θ, both wheels alike):
//!   $T = \tfrac12 M_t\dot x^2 - m_B l\cos\theta\,\dot x\dot\theta + \tfrac12 J\dot\theta^2$,
//!   $V = m_B g l\cos\theta$, with $M_t = m_B + 2m_W + 2I_{Wa}/r^2$, $J = I_{Byy} + m_B l^2$ and
//!   the rolling $\dot x = -r(\dot\theta + \dot\theta_L)$ (z down: a wheel rolling forward turns
//!   negatively about the right-pointing axle). So the kinetic energy of the speeds
//!   $u = (a, b, b)$ is that $T$, the pitch's growth rate is
//!   $\lambda^2 = m_B g l M_t/(J M_t - m_B^2 l^2)$, and a hub torque is the generalised force of
//!   its own wheel's rate only;
//! - the turning in place written by hand: $u = (0, 1, -1)$ moves the wheel centres at $\mp r$,
//!   spins both wheels at unit rate and turns the heading at $2r/W$, so
//!   $u^{\mathsf T}Mu = 2m_Wr^2 + 2I_{Wa} + (2I_{Wd} + I_{Bzz})(2r/W)^2$;
//! - Carvallo's modified Lagrange equations from the same description, at 256 bits at seeded
//!   states (the nonlinear equations, not only the linear ones the derivation compares exactly).
//!
//! What breaks them (run here): the body's centre put *below* the axle (a hanging pendulum) turns
//! the growth rate's sign, and the closed form no longer holds.

use carvallo_codegen::derive::wheeled_pendulum::{self, INDEPENDENT};
use carvallo_codegen::emit::emit_program;
use carvallo_codegen::mechanics::engine::{self, sym};
use carvallo_ir::hp::to_f64;
use carvallo_ir::Program;
use rand::{Rng, SeedableRng};

/// A design drawn around a personal transporter's: r, W, mW, IWd, IWa, l, mB, IBxx, IByy, IBzz, g.
fn design(rng: &mut impl Rng) -> Vec<f64> {
    vec![
        rng.gen_range(0.15..0.35),
        rng.gen_range(0.4..0.8),
        rng.gen_range(2.0..8.0),
        rng.gen_range(0.02..0.1),
        rng.gen_range(0.05..0.2),
        rng.gen_range(0.3..1.2),
        rng.gen_range(40.0..120.0),
        rng.gen_range(5.0..20.0),
        rng.gen_range(5.0..20.0),
        rng.gen_range(0.5..3.0),
        9.81,
    ]
}

fn at(p: &Program, out: &[f64], name: &str) -> f64 {
    out[p.outputs.iter().position(|o| o.name == name).unwrap_or_else(|| panic!("no {name}"))]
}

/// The largest relative residual of the closed forms for the linearised program `p` at the
/// design `x`, speed `v`.
fn closed_form_residual(p: &Program, x: &[f64], v: f64) -> f64 {
    let [r, w, mw, iwd, iwa, l, mb, _, iby, ibz, g] = x.try_into().expect("11 parameters");
    // Inputs: phi, theta, thetad, thetaLd, thetaRd, TL, TR, v (the state is unused by the
    // linear outputs).
    let out = p.eval_f64(x, &[0.0, 0.0, 0.0, -v / r, -v / r, 0.0, 0.0, v]).expect("evaluates");
    let m = |i: usize, j: usize| {
        let (i, j) = (i.min(j), i.max(j));
        at(p, &out, &format!("lin_M_{}_{}", INDEPENDENT[i], INDEPENDENT[j]))
    };
    let quad = |u: [f64; 3]| -> f64 {
        (0..3).map(|i| (0..3).map(|j| u[i] * m(i, j) * u[j]).sum::<f64>()).sum()
    };
    let mt = mb + 2.0 * mw + 2.0 * iwa / (r * r);
    let jb = iby + mb * l * l;
    let mut worst = 0.0f64;
    let mut rel = |got: f64, want: f64| {
        worst = worst.max((got - want).abs() / want.abs().max(1e-300));
    };
    for (a, b) in [(1.0, 0.0), (0.0, 1.0), (0.7, -0.3)] {
        let xd = -r * (a + b);
        let planar = mt * xd * xd - 2.0 * mb * l * xd * a + jb * a * a;
        rel(quad([a, b, b]), planar);
    }
    let yaw = 2.0 * r / w;
    rel(quad([0.0, 1.0, -1.0]), 2.0 * mw * r * r + 2.0 * iwa + (2.0 * iwd + ibz) * yaw * yaw);
    // The pitch's growth rate: theta'' = (M^-1 f_q)_0 theta when f_u vanishes.
    let mm = nalgebra::Matrix3::from_fn(m);
    let fq = nalgebra::Vector3::from_fn(|i, _| at(p, &out, &format!("lin_fq_{}", INDEPENDENT[i])));
    let growth = mm.lu().solve(&fq).expect("M is invertible")[0];
    rel(growth, mb * g * l * mt / (jb * mt - mb * mb * l * l));
    let scale = fq.amax();
    for ui in INDEPENDENT {
        for uj in INDEPENDENT {
            let fu = at(p, &out, &format!("lin_fu_{ui}_{uj}"));
            worst = worst.max(fu.abs() / scale);
        }
        for (t, wheel) in [("TL", "thetaLd"), ("TR", "thetaRd")] {
            let want = if ui == wheel { 1.0 } else { 0.0 };
            worst = worst.max((at(p, &out, &format!("lin_fT_{ui}_{t}")) - want).abs());
        }
    }
    worst
}

#[test]
fn wheeled_pendulum_linearisation_equals_the_planar_lagrangian() {
    crate::on_symbolica_thread(|| {
        let prog = emit_program(crate::derived("wheeled_pendulum")).expect("emits");
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(2012);
        let mut worst = 0.0f64;
        for _ in 0..50 {
            let x = design(&mut rng);
            let v = rng.gen_range(0.0..6.0);
            worst = worst.max(closed_form_residual(&prog, &x, v));
        }
        eprintln!("wheeled pendulum against the closed forms: worst relative residual {worst:e}");
        assert!(worst < 1e-12, "worst relative residual {worst:e}");

        // The body below the axle: the engine derives a hanging pendulum, the closed form of the
        // inverted one fails (the growth rate changes sign).
        let mut hanging = wheeled_pendulum::wheeled_pendulum();
        let g = hanging.points.iter_mut().find(|p| p.name == "G").expect("point G");
        g.offset[2] = sym("l");
        let (d, _, _) = engine::derivation(&hanging, file!()).expect("derives");
        let reference = wheeled_pendulum::upright(-sym("v") / sym("r"));
        let lin = wheeled_pendulum::route(&d, "", &reference).expect("linearises");
        let mut formulas = d.formulas.clone();
        for (name, expr) in wheeled_pendulum::entries(&lin) {
            formulas.push(carvallo_codegen::Formula {
                name,
                section: "engine".into(),
                description: String::new(),
                expr,
            });
        }
        let mut inputs = d.inputs.clone();
        inputs.push("v".into());
        let broken =
            emit_program(&carvallo_codegen::Derivation { formulas, inputs, ..d }).expect("emits");
        let x = design(&mut rng);
        let r = closed_form_residual(&broken, &x, 2.0);
        assert!(r > 1.0, "a hanging body must fail the inverted closed form: {r:e}");
    });
}

#[test]
fn wheeled_pendulum_kane_equals_lagrange_at_256_bits() {
    crate::on_symbolica_thread(|| {
        let (d, _, _) =
            engine::derivation(&wheeled_pendulum::wheeled_pendulum(), file!()).expect("derives");
        let prog = emit_program(&d).expect("emits");
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(97);
        let mut worst = 0.0f64;
        for _ in 0..30 {
            let x = design(&mut rng);
            // phi on the constraint (flat ground: zero), the rest anywhere.
            let mut inputs = vec![0.0, rng.gen_range(-1.2..1.2)];
            inputs.extend((0..3).map(|_| rng.gen_range(-10.0..10.0)));
            inputs.extend((0..2).map(|_| rng.gen_range(-20.0..20.0)));
            assert_eq!(prog.inputs.len(), inputs.len(), "phi, theta, three speeds, two torques");
            let e = carvallo_ir::hp::eval(&prog, &x, &inputs, 256).expect("256 bits");
            let get = |name: &str| {
                let k = prog.outputs.iter().position(|o| o.name == name).expect("output");
                e[k].clone()
            };
            let mut pairs = Vec::new();
            for (i, ui) in INDEPENDENT.iter().enumerate() {
                for uj in &INDEPENDENT[i..] {
                    pairs.push((format!("M_{ui}_{uj}"), format!("L_M_{ui}_{uj}")));
                }
                pairs.push((format!("f_{ui}"), format!("L_f_{ui}")));
            }
            for (a, b) in pairs {
                let (x, y) = (get(&a), get(&b));
                let diff = to_f64(&x.sub(&y, 256, astro_float::RoundingMode::ToEven)).abs();
                let scale = to_f64(&x).abs().max(to_f64(&y).abs()).max(1e-300);
                worst = worst.max(diff / scale);
            }
        }
        eprintln!("wheeled pendulum, Kane against Lagrange at 256 bits: worst {worst:e}");
        assert!(worst < 1e-60, "worst relative difference {worst:e}");
    });
}
