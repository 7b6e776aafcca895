//! Moore's (2012) leaning rider through the mechanics engine, against its peer, BicycleParameters
//! 1.5.2's `MooreRiderLean2012Model` (numbers written by `scripts/lean-rider-peer.py` into
//! `data/mooreriderlean2012/browser_jason_peer.json`, parameter set
//! `mooreriderlean2012_browser_jason`):
//! - the nonlinear dependent speeds and accelerations at the peer's six seeded states (λ held
//!   constant, as the model defines it);
//! - the linearisation about upright straight running, A (12 × 12) and B (12 × 3), at six
//!   speeds, and the six non-zero eigenvalues;
//! - Kane's equations against Carvallo's modified Lagrange equations at 256 bits;
//! - the lean joint locked: the equations of roll, rear wheel and steer equal the hand-derived
//!   Whipple bicycle's (the hand derivation's program, frozen as
//!   `codegen/tests/fixtures/whipple_nonlinear_hand.ir`) with the torso's mass and inertia in
//!   the rear frame, the parameters converted to the benchmark's.
//!
//! The linearisation is computed here from the engine's nonlinear equations by central
//! differences at 256 bits (step 1e-30: truncation ~1e-60, rounding ~1e-47), so the only f64
//! numbers in the comparison are the peer's.

use astro_float::{BigFloat, RoundingMode};
use carvallo_codegen::derive::whipple::lean_rider;
use carvallo_codegen::emit::emit_program;
use carvallo_codegen::mechanics::engine;
use carvallo_ir::hp::{eval_big, from_f64, to_f64};
use carvallo_ir::Program;
use serde_json::Value;

const P: usize = 256;
const RM: RoundingMode = RoundingMode::ToEven;

fn big(x: f64) -> BigFloat {
    from_f64(x, P)
}

fn add(a: &BigFloat, b: &BigFloat) -> BigFloat {
    a.add(b, P, RM)
}

fn sub(a: &BigFloat, b: &BigFloat) -> BigFloat {
    a.sub(b, P, RM)
}

fn mul(a: &BigFloat, b: &BigFloat) -> BigFloat {
    a.mul(b, P, RM)
}

fn div(a: &BigFloat, b: &BigFloat) -> BigFloat {
    a.div(b, P, RM)
}

/// Sine and cosine by their series (the arguments here are below 2 in size).
fn sin_cos(x: &BigFloat) -> (BigFloat, BigFloat) {
    let (mut s, mut c) = (big(0.0), big(0.0));
    let mut term = big(1.0);
    for k in 0..120u32 {
        if k % 4 == 0 {
            c = add(&c, &term);
        } else if k % 4 == 1 {
            s = add(&s, &term);
        } else if k % 4 == 2 {
            c = sub(&c, &term);
        } else {
            s = sub(&s, &term);
        }
        term = div(&mul(&term, x), &big(f64::from(k + 1)));
    }
    (s, c)
}

/// Solves `m x = f` (square, by Gaussian elimination with partial pivoting).
#[allow(clippy::needless_range_loop)]
fn solve(mut m: Vec<Vec<BigFloat>>, mut f: Vec<BigFloat>) -> Vec<BigFloat> {
    let n = f.len();
    for k in 0..n {
        let pivot = (k..n)
            .max_by(|&i, &j| {
                to_f64(&m[i][k]).abs().partial_cmp(&to_f64(&m[j][k]).abs()).expect("finite")
            })
            .expect("a row");
        m.swap(k, pivot);
        f.swap(k, pivot);
        for i in k + 1..n {
            let r = div(&m[i][k], &m[k][k]);
            for j in k..n {
                m[i][j] = sub(&m[i][j], &mul(&r, &m[k][j]));
            }
            f[i] = sub(&f[i], &mul(&r, &f[k]));
        }
    }
    let mut x = vec![big(0.0); n];
    for k in (0..n).rev() {
        let mut e = f[k].clone();
        for j in k + 1..n {
            e = sub(&e, &mul(&m[k][j], &x[j]));
        }
        x[k] = div(&e, &m[k][k]);
    }
    x
}

fn number(v: &Value) -> f64 {
    v.as_str().expect("a number as a string").parse().expect("a number")
}

fn peer() -> Value {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../data/mooreriderlean2012/browser_jason_peer.json");
    serde_json::from_str(&std::fs::read_to_string(path).expect("the peer's numbers"))
        .expect("the peer's JSON")
}

/// The engine's program (Kane and Lagrange) and the peer's parameters in `lean_rider::PARAMS`
/// order, with `lam` the peer's upright pitch.
struct Setup {
    prog: Program,
    params: Vec<BigFloat>,
    lam: f64,
}

fn setup(peer: &Value) -> Setup {
    static PROGRAM: std::sync::OnceLock<Program> = std::sync::OnceLock::new();
    let prog = PROGRAM.get_or_init(derive).clone();
    let lam = number(&peer["upright_pitch_q5"]);
    let params = lean_rider::PARAMS
        .iter()
        .map(|&name| if name == "lam" { big(lam) } else { big(number(&peer["parameters"][name])) })
        .collect();
    Setup { prog, params, lam }
}

/// The description derived (on the symbolica thread) and emitted.
fn derive() -> Program {
    let model = lean_rider::lean_rider();
    let (d, kane_len, redundant) =
        engine::derivation(&model, file!()).expect("the description derives");
    // As for the Whipple bicycle: the rear contact's vertical row, and only it, is dropped.
    assert_eq!(redundant.len(), 1, "dropped rows: {redundant:?}");
    assert!(redundant[0].starts_with("D vertical: "), "dropped rows: {redundant:?}");
    let prog = emit_program(&d).expect("the engine's derivation emits");
    let kane_only =
        carvallo_codegen::Derivation { formulas: d.formulas[..kane_len].to_vec(), ..d.clone() };
    eprintln!(
        "lean rider: {} formulas, Kane part {} ops (naive), whole program {} ops; inputs {:?}",
        d.formulas.len(),
        emit_program(&kane_only).expect("emits").op_count().total,
        prog.op_count().total,
        prog.inputs
    );
    prog
}

fn output<'a>(p: &Program, values: &'a [BigFloat], name: &str) -> &'a BigFloat {
    let k =
        p.outputs.iter().position(|o| o.name == name).unwrap_or_else(|| panic!("no output {name}"));
    &values[k]
}

const SPEEDS: [&str; 4] = ["q4d", "q6d", "q7d", "q9d"];

/// The engine's right-hand side of Moore's 12 states `q1 q2 q3 q4 q6 q7 q8 q9 u4 u6 u7 u9`
/// (the pitch `q5` given beside them, as the peer takes it), by Kane's equations (`prefix` "")
/// or by the modified Lagrange equations (`prefix` "L_").
fn rhs(
    s: &Setup,
    x: &[BigFloat; 12],
    q5: &BigFloat,
    torques: &[BigFloat; 4],
    prefix: &str,
) -> Vec<BigFloat> {
    // Inputs: q4 q5 q7 q9, then the independent speeds, then T4 T6 T7 T9.
    let inputs = [
        x[3].clone(),
        q5.clone(),
        x[5].clone(),
        x[7].clone(),
        x[8].clone(),
        x[9].clone(),
        x[10].clone(),
        x[11].clone(),
        torques[0].clone(),
        torques[1].clone(),
        torques[2].clone(),
        torques[3].clone(),
    ];
    let v = eval_big(&s.prog, &s.params, &inputs, P).expect("the engine's program at 256 bits");
    let at = |n: &str| output(&s.prog, &v, n).clone();
    let m: Vec<Vec<BigFloat>> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let (a, b) = if i <= j { (i, j) } else { (j, i) };
                    at(&format!("{prefix}M_{}_{}", SPEEDS[a], SPEEDS[b]))
                })
                .collect()
        })
        .collect();
    let f: Vec<BigFloat> = (0..4).map(|i| at(&format!("{prefix}f_{}", SPEEDS[i]))).collect();
    let ud = solve(m, f);
    let (s3, c3) = sin_cos(&x[2]);
    let (pu, pv) = (at("P_u"), at("P_v"));
    let mut out = vec![
        sub(&mul(&pu, &c3), &mul(&pv, &s3)),
        add(&mul(&pu, &s3), &mul(&pv, &c3)),
        at("q3d"),
        x[8].clone(),
        x[9].clone(),
        x[10].clone(),
        at("q8d"),
        x[11].clone(),
    ];
    out.extend(ud);
    out
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1.0)
}

#[test]
fn lean_rider_equals_bicycleparameters_moore_rider_lean_2012() {
    crate::on_symbolica_thread(|| {
        let peer = peer();
        let s = setup(&peer);

        // 1. Nonlinear: the peer's seeded states (λ constant).
        let mut worst_nonlinear = (0.0f64, String::new());
        let mut worst_routes = 0.0f64;
        let states = peer["nonlinear"]["lam_constant"].as_array().expect("states");
        assert!(states.len() >= 3);
        for state in states {
            let q: Vec<f64> = state["q1..q9"].as_array().unwrap().iter().map(number).collect();
            let u: Vec<f64> = state["u4,u6,u7,u9"].as_array().unwrap().iter().map(number).collect();
            let t: Vec<f64> = state["T4,T6,T7,T9"].as_array().unwrap().iter().map(number).collect();
            assert_eq!(number(&state["lam"]), s.lam, "the peer's λ is its upright pitch");
            let x =
                [q[0], q[1], q[2], q[3], q[5], q[6], q[7], q[8], u[0], u[1], u[2], u[3]].map(big);
            let torques = [t[0], t[1], t[2], t[3]].map(big);
            let kane = rhs(&s, &x, &big(q[4]), &torques, "");
            let lagrange = rhs(&s, &x, &big(q[4]), &torques, "L_");
            for (k, l) in kane.iter().zip(&lagrange) {
                let d = to_f64(&sub(k, l)).abs() / to_f64(k).abs().max(1.0);
                worst_routes = worst_routes.max(d);
            }
            let names = [
                "q1p", "q2p", "q3p", "q4p", "q6p", "q7p", "q8p", "q9p", "u4p", "u6p", "u7p", "u9p",
            ];
            for (name, ours) in names.iter().zip(&kane) {
                let r = rel(to_f64(ours), number(&state["values"][name]));
                if r > worst_nonlinear.0 {
                    worst_nonlinear = (r, name.to_string());
                }
            }
            // The pitch rate, a dependent speed the state derivative does not list.
            let inputs =
                [q[3], q[4], q[6], q[8], u[0], u[1], u[2], u[3], t[0], t[1], t[2], t[3]].map(big);
            let v = eval_big(&s.prog, &s.params, &inputs, P).expect("evaluates");
            let r = rel(to_f64(output(&s.prog, &v, "q5d")), number(&state["values"]["u5"]));
            if r > worst_nonlinear.0 {
                worst_nonlinear = (r, "u5".into());
            }
        }
        eprintln!(
            "nonlinear, {} states: largest relative difference to the peer {:e} ({}); Kane vs modified Lagrange at 256 bits {:e}",
            states.len(),
            worst_nonlinear.0,
            worst_nonlinear.1,
            worst_routes
        );
        // The peer is f64 code (Autolev's, 5,000 intermediate values): its own rounding.
        assert!(
            worst_nonlinear.0 < 1e-11,
            "the engine's nonlinear leaning rider differs from the peer's by {:e} in {}",
            worst_nonlinear.0,
            worst_nonlinear.1
        );
        assert!(worst_routes < 1e-60, "Kane and modified Lagrange differ by {worst_routes:e}");

        // 2. The linearisation about upright straight running at each of the peer's speeds.
        let h = big(1e-30);
        let two_h = add(&h, &h);
        let rr = number(&peer["parameters"]["rr"]);
        let zero4 = [0.0; 4].map(big);
        let (mut worst_a, mut worst_b, mut worst_eig) = (0.0f64, 0.0f64, 0.0f64);
        for case in peer["linear"].as_array().expect("speeds") {
            let v = number(&case["v"]);
            let mut x0 = [0.0; 12].map(big);
            x0[9] = big(-v / rr);
            let q5 = big(s.lam);
            let mut a = vec![vec![0.0f64; 12]; 12];
            for j in 0..12 {
                let (mut plus, mut minus) = (x0.clone(), x0.clone());
                plus[j] = add(&plus[j], &h);
                minus[j] = sub(&minus[j], &h);
                let (fp, fm) = (rhs(&s, &plus, &q5, &zero4, ""), rhs(&s, &minus, &q5, &zero4, ""));
                for i in 0..12 {
                    a[i][j] = to_f64(&div(&sub(&fp[i], &fm[i]), &two_h));
                }
            }
            let mut b = vec![vec![0.0f64; 3]; 12];
            // The peer's inputs T4, T7, T9 (it drops the rear wheel's T6).
            for (j, k) in [0, 2, 3].into_iter().enumerate() {
                let (mut plus, mut minus) = (zero4.clone(), zero4.clone());
                plus[k] = h.clone();
                minus[k] = sub(&big(0.0), &h);
                let (fp, fm) = (rhs(&s, &x0, &q5, &plus, ""), rhs(&s, &x0, &q5, &minus, ""));
                for i in 0..12 {
                    b[i][j] = to_f64(&div(&sub(&fp[i], &fm[i]), &two_h));
                }
            }
            let peer_a: Vec<Vec<f64>> = case["A"]
                .as_array()
                .unwrap()
                .iter()
                .map(|r| r.as_array().unwrap().iter().map(number).collect())
                .collect();
            let peer_b: Vec<Vec<f64>> = case["B"]
                .as_array()
                .unwrap()
                .iter()
                .map(|r| r.as_array().unwrap().iter().map(number).collect())
                .collect();
            let scale_a = peer_a.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
            let scale_b = peer_b.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
            for i in 0..12 {
                for j in 0..12 {
                    worst_a = worst_a.max((a[i][j] - peer_a[i][j]).abs() / scale_a);
                }
                for j in 0..3 {
                    worst_b = worst_b.max((b[i][j] - peer_b[i][j]).abs() / scale_b);
                }
            }
            // The six non-zero eigenvalues (the other six are zero: the ignorable
            // coordinates and the rear wheel's speed), sorted the same way on both sides.
            let matrix = nalgebra::DMatrix::from_fn(12, 12, |i, j| a[i][j]);
            let sort = |mut e: Vec<(f64, f64)>| {
                e.retain(|(re, im)| re.hypot(*im) > 1e-6);
                e.sort_by(|x, y| x.partial_cmp(y).expect("finite"));
                e
            };
            let ours =
                sort(matrix.complex_eigenvalues().iter().map(|z| (z.re, z.im)).collect::<Vec<_>>());
            let theirs = sort(
                case["eigenvalues_re_im"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|z| (number(&z[0]), number(&z[1])))
                    .collect(),
            );
            assert_eq!(ours.len(), 6, "six non-zero eigenvalues at {v} m/s: {ours:?}");
            assert_eq!(theirs.len(), 6, "the peer's six non-zero eigenvalues at {v} m/s");
            for (o, t) in ours.iter().zip(&theirs) {
                let d = (o.0 - t.0).hypot(o.1 - t.1) / t.0.hypot(t.1);
                worst_eig = worst_eig.max(d);
            }
            // With k9 = c9 = 0 the torso is an inverted pendulum: a real eigenvalue near +7.
            assert!(ours.iter().any(|(re, im)| *im == 0.0 && (6.5..8.0).contains(re)), "{ours:?}");
        }
        eprintln!(
            "linearisation at {} speeds: |ΔA|/max|A| {:e}, |ΔB|/max|B| {:e}, eigenvalues relative {:e}",
            peer["linear"].as_array().unwrap().len(),
            worst_a,
            worst_b,
            worst_eig
        );
        assert!(worst_a < 1e-10, "A differs from the peer's by {worst_a:e} of max|A|");
        assert!(worst_b < 1e-10, "B differs from the peer's by {worst_b:e} of max|B|");
        assert!(worst_eig < 1e-10, "eigenvalues differ from the peer's by {worst_eig:e}");
    });
}

/// The benchmark's 26 parameters (`whipple::PARAMS` order) of the leaning rider's bicycle with
/// the torso fixed upright in the rear frame: C's frame is the benchmark's pitched by λ, so
/// inertias turn by $R = \begin{pmatrix}\cos\lambda&0&\sin\lambda\\0&1&0\\-\sin\lambda&0&\cos\lambda\end{pmatrix}$,
/// $I_B = R I_C R^\top$; the hinge frame H is the benchmark's (at q9 = 0 so is G).
fn benchmark_of_locked(p: &dyn Fn(&str) -> f64) -> [f64; 26] {
    let (sl, cl) = p("lam").sin_cos();
    let (c1, c3) = ([cl, -sl], [sl, cl]); // x and z components
    let along = |o: [f64; 2], a: f64, u: [f64; 2], b: f64, w: [f64; 2]| {
        [o[0] + a * u[0] + b * w[0], o[1] + a * u[1] + b * w[1]]
    };
    let rr = p("rr");
    let d_o = [0.0, -rr];
    let ce = along(d_o, p("d1"), c1, 0.0, c3);
    let fo = along(ce, p("d3"), c1, p("d2"), c3);
    assert!(
        (fo[1] + p("rf")).abs() < 1e-9,
        "the front wheel touches the ground: {}",
        fo[1] + p("rf")
    );
    let w = fo[0];
    let trail = ce[0] - ce[1] / cl * sl - w;
    let co = along(d_o, p("l1"), c1, p("l2"), c3);
    let go = [p("l5"), -rr + p("d4") + p("l6")];
    let eo = along(fo, p("l3"), c1, p("l4"), c3);
    // R I R^T for I = [[i11, 0, i31], [0, i22, 0], [i31, 0, i33]]: (xx, yy, zz, xz).
    let turn = |i11: f64, i22: f64, i33: f64, i31: f64| {
        let r = [[cl, sl], [-sl, cl]]; // rows x, z; columns c1, c3
        let i = [[i11, i31], [i31, i33]];
        let mut o = [[0.0; 2]; 2];
        for a in 0..2 {
            for b in 0..2 {
                for k in 0..2 {
                    for l in 0..2 {
                        o[a][b] += r[a][k] * i[k][l] * r[b][l];
                    }
                }
            }
        }
        (o[0][0], i22, o[1][1], o[0][1])
    };
    let (mc, mg) = (p("mc"), p("mg"));
    let mb = mc + mg;
    let xb = (mc * co[0] + mg * go[0]) / mb;
    let zb = (mc * co[1] + mg * go[1]) / mb;
    let (cxx, cyy, czz, cxz) = turn(p("ic11"), p("ic22"), p("ic33"), p("ic31"));
    // Parallel axes to the common centre: m (|r|^2 1 - r r^T).
    let shift = |m: f64, c: [f64; 2]| {
        let (rx, rz) = (c[0] - xb, c[1] - zb);
        (m * rz * rz, m * (rx * rx + rz * rz), m * rx * rx, -m * rx * rz)
    };
    let (s1, s2) = (shift(mc, co), shift(mg, go));
    let ibxx = cxx + p("ig11") + s1.0 + s2.0;
    let ibyy = cyy + p("ig22") + s1.1 + s2.1;
    let ibzz = czz + p("ig33") + s1.2 + s2.2;
    let ibxz = cxz + p("ig31") + s1.3 + s2.3;
    let (hxx, hyy, hzz, hxz) = turn(p("ie11"), p("ie22"), p("ie33"), p("ie31"));
    [
        w,
        trail,
        p("lam"),
        p("g"),
        rr,
        p("md"),
        p("id11"),
        p("id22"),
        xb,
        zb,
        mb,
        ibxx,
        ibyy,
        ibzz,
        ibxz,
        eo[0],
        eo[1],
        p("me"),
        hxx,
        hyy,
        hzz,
        hxz,
        p("rf"),
        p("mf"),
        p("if11"),
        p("if22"),
    ]
}

/// With the lean joint locked (q9 = u9 = 0; the joint's reaction enters only the lean
/// equation), the roll, rear wheel and steer equations are the Whipple bicycle's with the torso
/// in the rear frame: the engine's leaning rider against the hand derivation
/// (the hand derivation's frozen program), a different formulation in different parameters, at
/// seeded states. The parameters are converted in f64, hence the tolerance.
#[test]
fn lean_rider_locked_is_the_whipple_bicycle_with_the_torso_in_the_rear_frame() {
    crate::on_symbolica_thread(|| {
        use rand::{Rng, SeedableRng};
        let peer = peer();
        let s = setup(&peer);
        let moore = |name: &str| {
            if name == "lam" {
                s.lam
            } else {
                number(&peer["parameters"][name])
            }
        };
        let bench = benchmark_of_locked(&moore);
        eprintln!("the locked leaning rider in the benchmark's parameters: {bench:?}");
        let hand_text = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("tests/fixtures/whipple_nonlinear_hand.ir"),
        )
        .expect("codegen/tests/fixtures/whipple_nonlinear_hand.ir");
        let hand = Program::parse(&hand_text).expect("the committed IR parses");
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(98);
        let mut worst = 0.0f64;
        for _ in 0..20 {
            let (q4, q7) = (rng.gen_range(-0.5..0.5), rng.gen_range(-0.7..0.7));
            let (u4, u6, u7) =
                (rng.gen_range(-2.0..2.0), rng.gen_range(-25.0..-3.0), rng.gen_range(-2.0..2.0));
            // The pitch on the front contact, by Newton on the engine's height at 256 bits.
            let mut q5 = big(s.lam);
            for _ in 0..12 {
                let inputs = [q4, 0.0, q7, 0.0, u4, u6, u7, 0.0, 0.0, 0.0, 0.0, 0.0].map(big);
                let mut inputs = inputs.to_vec();
                inputs[1] = q5.clone();
                let v = eval_big(&s.prog, &s.params, &inputs, P).expect("evaluates");
                let step = div(
                    output(&s.prog, &v, "F_contact_height"),
                    output(&s.prog, &v, "F_contact_height_dq5"),
                );
                q5 = sub(&q5, &step);
            }
            let inputs = [q4, 0.0, q7, 0.0, u4, u6, u7, 0.0, 0.0, 0.0, 0.0, 0.0].map(big);
            let mut inputs = inputs.to_vec();
            inputs[1] = q5.clone();
            let v = eval_big(&s.prog, &s.params, &inputs, P).expect("evaluates");
            let at = |n: &str| output(&s.prog, &v, n).clone();
            let m: Vec<Vec<BigFloat>> = (0..3)
                .map(|i| {
                    (0..3)
                        .map(|j| {
                            let (a, b) = if i <= j { (i, j) } else { (j, i) };
                            at(&format!("M_{}_{}", SPEEDS[a], SPEEDS[b]))
                        })
                        .collect()
                })
                .collect();
            let f: Vec<BigFloat> = (0..3).map(|i| at(&format!("f_{}", SPEEDS[i]))).collect();
            let ours = solve(m, f); // u4', u6', u7'
            let theta = to_f64(&q5) - s.lam;
            let h = carvallo_ir::hp::eval(&hand, &bench, &[q4, theta, q7, u4, u7, u6], P)
                .expect("the hand derivation at 256 bits");
            let hm = |i: usize, j: usize| {
                let (a, b) = if i <= j { (i, j) } else { (j, i) };
                output(&hand, &h, &format!("m3_{}{}", a + 1, b + 1)).clone()
            };
            let hand_m: Vec<Vec<BigFloat>> =
                (0..3).map(|i| (0..3).map(|j| hm(i, j)).collect()).collect();
            let hand_f: Vec<BigFloat> =
                (0..3).map(|i| output(&hand, &h, &format!("f3_{}", i + 1)).clone()).collect();
            let theirs = solve(hand_m, hand_f); // phi'', delta'', thetaR''
            for (o, t) in [(0, 0), (2, 1), (1, 2)] {
                worst = worst.max(rel(to_f64(&ours[o]), to_f64(&theirs[t])));
            }
        }
        eprintln!("locked lean against the hand-derived Whipple bicycle: largest relative difference of the accelerations {worst:e}");
        assert!(
            worst < 1e-11,
            "the locked leaning rider differs from the Whipple bicycle by {worst:e}"
        );
    });
}
