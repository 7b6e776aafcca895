//! The derived linearisation of the Carvallo–Whipple bicycle against the published benchmark
//! (Meijaard et al. 2007, read from `data/anchors/whipple-benchmark.toml` (a copy of `../shared/anchors`)): every symbolic
//! check of the derivation holds, and the emitted IR evaluated at the benchmark parameters
//! reproduces the published M, C1, K0, K2 (relative 1e-13; exact zeros absolute 1e-13) and the
//! characteristic polynomial equals det(M s^2 + v C1 s + g K0 + v^2 K2) computed from the
//! emitted matrices (relative 1e-12 at fixed (s, v) points), and so do the transfer
//! numerators (N P = det(P) I) and the closed-loop polynomial with gains.

#![allow(clippy::needless_range_loop)]

use std::path::PathBuf;

use carvallo_codegen::derive::whipple;
use carvallo_codegen::emit::emit_program;

const REL_TOL: f64 = 1e-13;
const ABS_TOL: f64 = 1e-13;

fn anchors() -> String {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../data/anchors/whipple-benchmark.toml");
    std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("anchors file {} unreadable: {e}", path.display()))
}

/// The value of `key = number` (or `"pi/N"`) in the anchors text, first occurrence.
fn scalar(text: &str, key: &str) -> f64 {
    for line in text.lines() {
        let line = line.split('#').next().unwrap_or("");
        if let Some((k, v)) = line.split_once('=') {
            if k.trim() == key {
                let v = v.trim().trim_matches('"');
                if let Some(d) = v.strip_prefix("pi/") {
                    return std::f64::consts::PI / d.parse::<f64>().expect("pi divisor");
                }
                return v.parse().unwrap_or_else(|e| panic!("{key} = {v}: {e}"));
            }
        }
    }
    panic!("key {key} missing from the anchors file")
}

/// The 2 × 2 matrix `key = [[a, b], [c, d]]` of the anchors text.
fn matrix(text: &str, key: &str) -> [[f64; 2]; 2] {
    let line = text
        .lines()
        .find(|l| l.split_once('=').is_some_and(|(k, _)| k.trim() == key))
        .unwrap_or_else(|| panic!("matrix {key} missing"));
    let nums: Vec<f64> = line
        .split_once('=')
        .expect("=")
        .1
        .replace(['[', ']'], " ")
        .split(',')
        .map(|x| x.trim().parse().expect("number"))
        .collect();
    assert_eq!(nums.len(), 4, "matrix {key}");
    [[nums[0], nums[1]], [nums[2], nums[3]]]
}

fn whipple_linearisation_body() {
    let d = crate::derived("whipple");
    // Every check holds except plain_lagrange_delta: the plain Lagrange equation of delta is
    // not Kane's (the memoir's point, n° 71; the report's `FailsAsTheMemoirSays`), while
    // plain_lagrange_phi happens to hold.
    crate::common::assert_checks(&d.checks, &["plain_lagrange_delta"]);
    let prog = emit_program(d).expect("emission");
    let text = anchors();
    let params: Vec<f64> = whipple::PARAMS.iter().map(|k| scalar(&text, k)).collect();
    let names: Vec<&str> = prog.outputs.iter().map(|o| o.name.as_str()).collect();
    // The inputs: the speed, then the eight feedback gains (zero unless given).
    let inputs = |v: f64, gains: [f64; 8]| -> Vec<f64> {
        assert_eq!(prog.inputs.len(), 9, "v and the gains");
        std::iter::once(v).chain(gains).collect()
    };
    let out = prog.eval_f64(&params, &inputs(0.0, [0.0; 8])).expect("eval");
    let get = |n: &str| out[names.iter().position(|x| *x == n).expect("output")];
    for (key, prefix) in [("M", "m"), ("C1", "c1_"), ("K0", "k0_"), ("K2", "k2_")] {
        let want = matrix(&text, key);
        for r in 0..2 {
            for c in 0..2 {
                let got = get(&format!("{prefix}{}{}", r + 1, c + 1));
                let w = want[r][c];
                let err = (got - w).abs();
                let ok = if w == 0.0 { err <= ABS_TOL } else { err <= REL_TOL * w.abs() };
                assert!(ok, "{key}[{r}][{c}]: derived {got:e}, published {w:e}");
            }
        }
    }
    // Characteristic polynomial against the determinant of the emitted matrices.
    let g = scalar(&text, "g");
    for (s, v) in [(1.3, 0.0), (-0.7, 2.5), (3.1, 5.0), (0.25, 7.75)] {
        let o = prog.eval_f64(&params, &inputs(v, [0.0; 8])).expect("eval");
        let at = |n: &str| o[names.iter().position(|x| *x == n).expect("output")];
        let e = |r: usize, c: usize| {
            let rc = format!("{}{}", r + 1, c + 1);
            at(&format!("m{rc}")) * s * s
                + v * at(&format!("c1_{rc}")) * s
                + g * at(&format!("k0_{rc}"))
                + v * v * at(&format!("k2_{rc}"))
        };
        let det = e(0, 0) * e(1, 1) - e(0, 1) * e(1, 0);
        let poly: f64 = (0..5).map(|k| at(&format!("a{k}")) * s.powi(k)).sum();
        let scale: f64 = (0..5).map(|k| (at(&format!("a{k}")) * s.powi(k)).abs()).sum();
        assert!((poly - det).abs() <= 1e-12 * scale, "char poly at s={s}, v={v}: {poly} vs {det}");
        // Transfer numerators: N P = det(P) I with N the emitted adjugate (entry by entry).
        let sig = ["roll", "steer"];
        let n = |i: usize, j: usize| -> f64 {
            (0..3).map(|k| at(&format!("tf_{}_{}_{k}", sig[i], sig[j])) * s.powi(k)).sum()
        };
        for i in 0..2 {
            for j in 0..2 {
                let np = n(i, 0) * e(0, j) + n(i, 1) * e(1, j);
                let want = if i == j { det } else { 0.0 };
                assert!(
                    (np - want).abs() <= 1e-12 * scale,
                    "N P [{i}][{j}] at s={s}, v={v}: {np} vs {want}"
                );
            }
        }
        // Closed loop with gains: the emitted coefficients against det(P + Kd s + Kp).
        let k = [3.0 * s, -1.5, 0.7 * v, 2.0, -0.4, 11.0, 25.0 * s, -0.9];
        let oc = prog.eval_f64(&params, &inputs(v, k)).expect("eval");
        let atc = |n: &str| oc[names.iter().position(|x| *x == n).expect("output")];
        let ec = |r: usize, c: usize| e(r, c) + k[4 * r + c] + k[4 * r + 2 + c] * s;
        let det_cl = ec(0, 0) * ec(1, 1) - ec(0, 1) * ec(1, 0);
        let mut poly_cl = 0.0;
        let mut scale_cl = 0.0;
        for kk in 0..5 {
            for j in 0..=(4 - kk) {
                let term = atc(&format!("cl_a{kk}_{j}")) * v.powi(j) * s.powi(kk);
                poly_cl += term;
                scale_cl += term.abs();
            }
        }
        assert!(
            (poly_cl - det_cl).abs() <= 1e-12 * scale_cl,
            "closed loop at s={s}, v={v}: {poly_cl} vs {det_cl}"
        );
    }
    let ops = prog.op_count();
    eprintln!("whipple IR: {} ops", ops.total);
}

#[test]
fn whipple_linearisation() {
    crate::on_symbolica_thread(whipple_linearisation_body);
}

/// The frozen program of the linear model (`codegen/tests/fixtures/whipple_linear.ir`,
/// byte-identical to `generated/whipple.ir` at commit 8eca596, when the engine's matrices were
/// still compared exactly with the hand series derivation, `engine_equals_hand`, since deleted):
/// the exact record of the hand derivation's values.
fn frozen() -> carvallo_ir::Program {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/whipple_linear.ir");
    let text = std::fs::read_to_string(&path).expect("codegen/tests/fixtures/whipple_linear.ir");
    carvallo_ir::Program::parse(&text).expect("the frozen program parses")
}

/// The sixteen matrix entries of `m` as a program in the benchmark's parameters.
fn program_of(m: &whipple::Matrices) -> carvallo_ir::Program {
    use carvallo_codegen::{Derivation, Formula};
    let mut formulas = Vec::new();
    for (prefix, mat) in [("m", &m.m), ("c1_", &m.c1), ("k0_", &m.k0), ("k2_", &m.k2)] {
        for r in 0..2 {
            for c in 0..2 {
                formulas.push(Formula {
                    name: format!("{prefix}{}{}", r + 1, c + 1),
                    section: "linear".into(),
                    description: String::new(),
                    expr: whipple::to_lambda(&mat[r][c]),
                });
            }
        }
    }
    emit_program(&Derivation {
        model: "whipple_matrices".into(),
        source: file!().into(),
        params: whipple::PARAMS.iter().map(|s| s.to_string()).collect(),
        inputs: Vec::new(),
        formulas,
        checks: Vec::new(),
        nominal: Vec::new(),
        horner_schemes: Vec::new(),
    })
    .expect("emits")
}

/// The entries (by name) in which `m` differs from the frozen program at three designs around
/// the benchmark (relative 1e-12).
fn differs_from_frozen(m: &whipple::Matrices) -> Vec<String> {
    let (mine, old) = (program_of(m), frozen());
    let bench: Vec<f64> = whipple::PARAMS.iter().map(|k| scalar(&anchors(), k)).collect();
    let mut out = Vec::new();
    for (k, scale) in [1.0, 1.1, 0.85].iter().enumerate() {
        let params: Vec<f64> = bench
            .iter()
            .enumerate()
            .map(|(i, x)| x * if i % 2 == k % 2 { *scale } else { 1.0 })
            .collect();
        let a = mine.eval_f64(&params, &[]).expect("evaluates");
        let b = old.eval_f64(&params, &vec![0.0; old.inputs.len()]).expect("evaluates");
        for (j, o) in mine.outputs.iter().enumerate() {
            let w = b[old.outputs.iter().position(|x| x.name == o.name).expect("shared")];
            if (a[j] - w).abs() > 1e-12 * w.abs().max(1.0) && !out.contains(&o.name) {
                out.push(o.name.clone());
            }
        }
    }
    out
}

/// `generated/whipple.ir` equals the frozen program on every output (relative 1e-60 at 256 bits)
/// at 300 seeded designs (the benchmark's parameters each within ±20 %), speeds in [0, 12] m/s
/// and gains in ±20, and its f64 rounding error (p99, in units of each output's root mean
/// square) is no worse than the frozen program's by more than a factor 2.
#[test]
fn whipple_linear_equals_the_frozen_hand_program() {
    use rand::{Rng, SeedableRng};
    let text = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../generated/whipple.ir"),
    )
    .expect("generated/whipple.ir");
    let now = carvallo_ir::Program::parse(&text).expect("parses");
    let old = frozen();
    assert_eq!(now.params, old.params);
    assert_eq!(now.inputs, old.inputs);
    let names: Vec<&str> = old.outputs.iter().map(|o| o.name.as_str()).collect();
    let slot: Vec<usize> = names
        .iter()
        .map(|n| {
            now.outputs.iter().position(|o| o.name == *n).unwrap_or_else(|| panic!("no output {n}"))
        })
        .collect();
    let bench: Vec<f64> = whipple::PARAMS.iter().map(|k| scalar(&anchors(), k)).collect();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x34_11ea);
    let mut worst = (0.0f64, String::new());
    let mut err: Vec<[Vec<f64>; 2]> = vec![[Vec::new(), Vec::new()]; names.len()];
    let mut exact: Vec<Vec<f64>> = vec![Vec::new(); names.len()];
    for _ in 0..300 {
        let params: Vec<f64> = bench.iter().map(|x| x * (1.0 + rng.gen_range(-0.2..0.2))).collect();
        let inputs: Vec<f64> = std::iter::once(rng.gen_range(0.0..12.0))
            .chain((0..8).map(|_| rng.gen_range(-20.0..20.0)))
            .collect();
        let a = carvallo_ir::hp::eval(&old, &params, &inputs, 256).expect("frozen at 256 bits");
        let b = carvallo_ir::hp::eval(&now, &params, &inputs, 256)
            .unwrap_or_else(|e| panic!("generated at 256 bits: {e}"));
        let af = old.eval_f64(&params, &inputs).expect("f64");
        let bf = now.eval_f64(&params, &inputs).expect("f64");
        for (j, name) in names.iter().enumerate() {
            let d = a[j].sub(&b[slot[j]], 256, astro_float::RoundingMode::ToEven);
            let x = carvallo_ir::hp::to_f64(&a[j]);
            let r = carvallo_ir::hp::to_f64(&d).abs() / x.abs().max(1.0);
            if r > worst.0 {
                worst = (r, name.to_string());
            }
            err[j][0].push((af[j] - x).abs());
            err[j][1].push((bf[slot[j]] - x).abs());
            exact[j].push(x);
        }
    }
    assert!(worst.0 < 1e-60, "the generated program differs from the frozen one: {worst:?}");
    let p99 = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[((v.len() - 1) as f64 * 0.99).round() as usize]
    };
    for (k, name) in names.iter().enumerate() {
        let rms = (exact[k].iter().map(|x| x * x).sum::<f64>() / exact[k].len() as f64).sqrt();
        if rms == 0.0 {
            continue;
        }
        let [old_err, new_err] = &mut err[k];
        let (o, n) =
            ((p99(old_err) / rms).max(f64::EPSILON), (p99(new_err) / rms).max(f64::EPSILON));
        assert!(n <= 2.0 * o, "{name}: f64 error {n:e} against the frozen program's {o:e}");
    }
}

/// The engine's linearisation against the frozen program of the hand derivation, and what breaks
/// the comparisons: the right reference gives its matrices; the rear wheel turning at $-v/r_F$
/// instead of $-v/r_R$ (a wrong reference) changes exactly the speed-dependent matrices $C_1$
/// and $K_2$, and the same wrong reference in the modified Lagrange route alone makes it
/// disagree with Kane's.
fn engine_linearisation_body() {
    use carvallo_codegen::cas::var;
    use carvallo_codegen::derive::whipple::linearised::{
        both_routes, differing, lateral, route, upright,
    };
    let d = both_routes().expect("engine derivation");
    let right = upright(-var("v") / var("rR"));
    let wrong = upright(-var("v") / var("rF"));
    let kane = lateral(&route(&d, "", &right).expect("Kane"), "kane", &mut Vec::new(), None);
    assert_eq!(
        differs_from_frozen(&kane),
        Vec::<String>::new(),
        "engine against the frozen hand program"
    );
    let mut checks = Vec::new();
    let off = lateral(&route(&d, "", &wrong).expect("Kane"), "kane", &mut checks, None);
    let moved = differs_from_frozen(&off);
    assert!(
        !moved.is_empty() && moved.iter().all(|n| n.starts_with("c1_") || n.starts_with("k2_")),
        "a wrong rear wheel rate moves C1 and K2 only: {moved:?}"
    );
    assert!(checks.iter().all(|c| c.holds), "the wrong reference is still an equilibrium");
    let lagrange = lateral(&route(&d, "L_", &wrong).expect("Lagrange"), "l", &mut Vec::new(), None);
    assert!(!differing(&kane, &lagrange).is_empty(), "Kane against a perturbed Lagrange route");
}

#[test]
fn engine_linearisation_equals_the_frozen_hand_program_and_breaks_with_a_wrong_reference() {
    crate::on_symbolica_thread(engine_linearisation_body);
}

/// The memoir's n° 98 by the engine (checks `*_shift_*` of `generated/whipple.checks.tsv`) and
/// what breaks it: the body turned by ε about the axis through the rear wheel's centre instead
/// of the ground trace OI moves its centre of gravity by a different amount, and the gravity
/// coefficient becomes $-g\,m_B(z_B + r_R)$, so both routes' gravity checks fail while the
/// handlebar's still hold.
fn shift_body() {
    use carvallo_codegen::derive::whipple::description::whipple_shifted;
    use carvallo_codegen::derive::whipple::linearised::shift_checks_of;
    let d = crate::derived("whipple");
    for c in d.checks.iter().filter(|c| c.id.contains("_shift_")) {
        assert!(c.holds, "check {} fails: {}", c.id, c.detail);
    }
    let (hand, _) = carvallo_codegen::derive::whipple::linearised::matrices_of(
        &carvallo_codegen::derive::whipple::description::whipple(),
        true,
        None,
    )
    .expect("the engine's matrices");
    let mut about_the_axle = whipple_shifted();
    let cre = about_the_axle.points.iter_mut().find(|p| p.name == "CRe").expect("CRe");
    cre.frame = "L".into();
    let mut checks = Vec::new();
    let routes = [("", "kane"), ("L_", "lagrange")];
    shift_checks_of(&about_the_axle, &mut checks, Some(&hand), &routes).expect("derives");
    let holds = |id: &str| checks.iter().find(|c| c.id == id).map(|c| c.holds);
    for route in ["kane", "lagrange"] {
        assert_eq!(holds(&format!("{route}_shift_gravity")), Some(false), "{checks:?}");
        assert_eq!(holds(&format!("{route}_shift_handlebar")), Some(true), "{checks:?}");
        assert_eq!(holds(&format!("{route}_shift_unshifted")), Some(true), "{checks:?}");
    }
}

#[test]
fn engine_shift_of_the_body_is_the_memoirs_and_breaks_about_the_wrong_axis() {
    crate::on_symbolica_thread(shift_body);
}

/// What breaks the engine's recorded equilibrium check: about a state with the handlebar
/// turning (steer rate 1 rad/s) upright running is no longer an equilibrium, so
/// `kane_equilibrium` fails; about the true reference it holds. With a symbolic angle the
/// jets' trigonometry does not reduce and a leaned or steered reference runs for minutes, so
/// the recorded falsifications of the four checks upright running makes literal zeros
/// (`MOVED`) linearise at a rational point of parameter space: there, about upright running,
/// all four quantities still vanish (the rational point alone breaks nothing), and with the
/// steer moved to 2 atan(1/16) each check fails, for both routes.
fn reference_checks_body() {
    use carvallo_codegen::cas::{rat, var};
    use carvallo_codegen::derive::whipple::linearised::{
        at_rational_point, both_routes, lateral, route, upright,
    };
    use symbolica::atom::Atom;
    let d = both_routes().expect("engine derivation");
    let ids = ["on_the_ground", "pitch_second_order", "equilibrium", "rear_decoupled"];
    for prefix in ["", "L_"] {
        let outcomes = |steer: Option<(Atom, Atom)>| -> Vec<bool> {
            let lin = at_rational_point(&d, prefix, steer).expect("linearised at the point");
            let mut checks = Vec::new();
            let _ = lateral(&lin, "r", &mut checks, None);
            ids.iter()
                .map(|id| {
                    let id = format!("r_{id}");
                    checks.iter().find(|c| c.id == id).map(|c| c.holds).expect("the check is made")
                })
                .collect()
        };
        assert_eq!(outcomes(None), [true; 4], "{prefix}: upright at the rational point");
        assert_eq!(
            outcomes(Some((rat(32, 257), rat(255, 257)))),
            [false; 4],
            "{prefix}: the steer moved"
        );
    }
    let holds = |reference: &carvallo_codegen::mechanics::engine::linear::Reference, id: &str| {
        let mut checks = Vec::new();
        let _ = lateral(&route(&d, "", reference).expect("Kane"), "kane", &mut checks, None);
        checks.iter().find(|c| c.id == id).map(|c| c.holds).expect("the check is made")
    };
    let right = upright(-var("v") / var("rR"));
    assert!(holds(&right, "kane_equilibrium"));
    let mut steering = right.clone();
    steering.values.insert("deltad".into(), Atom::num(1));
    assert!(!holds(&steering, "kane_equilibrium"), "a turning handlebar is not an equilibrium");
}

#[test]
fn engine_reference_checks_fail_off_the_reference() {
    crate::on_symbolica_thread(reference_checks_body);
}
