//! Run time against error, measured in one run: the tables printed by `carvallo bench`.
//!
//! [`run`] measures, with the same inputs for every method:
//!
//! 1. **evaluators**: the generated (`scene!`) code, the `carvallo_ir` interpreter and a naive
//!    tree evaluation of the same formulas (each output recomputed as an expression tree, no
//!    common subexpressions shared), nanoseconds per evaluation and the largest relative error
//!    against the 256-bit evaluation of `carvallo_ir::hp`;
//! 2. **windows**: the bicycle's weave and capsize speeds by the closed-form Hurwitz route, by
//!    an eigenvalue sweep and by the former 200 000-point scan, nanoseconds per design and the
//!    relative error against the speeds computed at 256 bits from the 256-bit matrices;
//! 3. **quartic**: the root solvers of `carvallo::numerics::quartic` on the hard suite, against
//!    the 256-bit roots ([`super::quartic`]);
//! 4. **certified**: the compensated classification of `carvallo::whipple::certified` near the
//!    weave speed against the plain `f64` sign of $H_3$ ([`super::certified`]);
//! 5. **distributions**: relative errors of the generated characteristic polynomial over seeded
//!    random parameter sets (benchmark values scaled by independent factors in [0.8, 1.2],
//!    speeds in [0, 10] m/s), max and quantiles in units of $\varepsilon = 2^{-52}$;
//! 6. **scenes**: operation count and time of scenes that ask for less (window only, one
//!    speed's polynomial, full right-hand side), with the benchmark parameters free or fixed;
//! 7. **sweep**: $10^6$ designs (fewer with `quick`) through [`sweep::sweep`] (the trail
//!    on a line) and [`sweep::sweep_designs`] (a Monte Carlo of the 25 parameters other
//!    than $g$, each scaled in [0.8, 1.2]), with the designs per second.
//!
//! [`super::extend`] appends the C peer and the batched evaluators.
//!
//! Timings are wall-clock means over repeated calls (`std::time::Instant`), so they vary from
//! run to run and machine to machine; errors do not. [`Targets`] compares the ratios asked for in
//! the issue with the measured ones.

use std::hint::black_box;
use std::sync::atomic::AtomicUsize;

use carvallo::ir::{hp, Interpreter, Op, Program, Value};
use rayon::prelude::*;

use carvallo::numerics::integrate::{self, Grid, Integration, Method as Integrator, Point};
use carvallo::numerics::quartic;
use carvallo::numerics::rng::SplitMix64;
use carvallo::whipple::nonlinear::rate::{
    self, project_jacobian_scene, project_scene, projected_rate_scene, state_rate_jacobian_scene,
    state_rate_scene, StateRate,
};
use carvallo::whipple::nonlinear::{dynamics_scene, Configuration, WhippleNonlinear};
use carvallo::whipple::stability::{self, reference_speeds, EigenGrid};
use carvallo::whipple::sweep::{self, Method};
use carvallo::whipple::uncertainty;
use carvallo::whipple::window_lanes;
use carvallo::whipple::{matrices_scene, Matrices, Whipple, WhippleParams, PARAM_NAMES};

use super::measure::{
    matrices_of, random_design, rel, time_ns, time_ns_interleaved, Config, Distribution, Report,
    Row, Target, Targets, REFERENCE_BITS,
};
use nalgebra::{Matrix3, Vector3};

const HOOP_IR: &str = carvallo::artifacts::HOOP.ir;
const UNICYCLE_IR: &str = carvallo::artifacts::UNICYCLE.ir;
const WHIPPLE_IR: &str = carvallo::artifacts::WHIPPLE.ir;
const WHEELED_PENDULUM_IR: &str = carvallo::artifacts::WHEELED_PENDULUM.ir;
const LEAN_RIDER_IR: &str = carvallo::artifacts::LEAN_RIDER.ir;

/// Default values of the hoop's and the unicycle's arguments.
fn model_value(name: &str) -> f64 {
    match name {
        "R" => 0.5,
        "g" => 9.81,
        "mu" => 1.2,
        "theta" => 0.3,
        "p" => 0.1,
        "q" => 2.0,
        "r" => -0.4,
        "n" => -0.8,
        "s" => 3.0,
        "z" => 1.25,
        "A" => 100.0,
        "B" => 99.5,
        "C" => 1.4,
        "L" => 0.1,
        "mu1" => 5.0,
        "A1" => 1.875,
        "B1" => 2.5,
        "C1" => 0.625,
        "dp" | "dn" | "ds" => 0.01,
        // Feedback gains of the closed loop (N m/rad, N m s/rad), nonzero so that every term
        // of the closed-loop polynomial is exercised.
        "k_roll_roll" => 100.0,
        "k_roll_steer" => 10.0,
        "k_roll_roll_rate" => 20.0,
        "k_roll_steer_rate" => 2.0,
        "k_steer_roll" => 10.0,
        "k_steer_steer" => 2.0,
        "k_steer_roll_rate" => -10.0,
        "k_steer_steer_rate" => 1.0,
        _ => f64::NAN,
    }
}

/// The value of argument `name` in a random sample: whipple parameters from `design`, the
/// speed from `speed`, other models' arguments scaled around [`model_value`].
fn arg_value(name: &str, design: &WhippleParams, speed: f64, rng: &mut SplitMix64) -> f64 {
    if name == "v" {
        speed
    } else if let Some(x) = design.get(name) {
        x
    } else {
        rng.scale(model_value(name), 0.2)
    }
}

/// Naive tree evaluation: `v` recomputed from the leaves, nothing shared.
fn tree_eval(p: &Program, v: Value, params: &[f64], inputs: &[f64]) -> f64 {
    let i = match v {
        Value::Param(i) => return params[i as usize],
        Value::Input(i) => return inputs[i as usize],
        Value::Inst(i) => i as usize,
    };
    let e = |a: Value| tree_eval(p, a, params, inputs);
    match p.insts[i].op {
        Op::Const(c) => c,
        Op::Neg(a) => -e(a),
        Op::Add(a, b) => e(a) + e(b),
        Op::Sub(a, b) => e(a) - e(b),
        Op::Mul(a, b) => e(a) * e(b),
        Op::Div(a, b) => e(a) / e(b),
        Op::Powi(a, k) => e(a).powi(k),
        Op::Sqrt(a) => e(a).sqrt(),
        Op::Sin(a) => e(a).sin(),
        Op::Cos(a) => e(a).cos(),
        Op::Tan(a) => e(a).tan(),
        Op::Atan2(a, b) => e(a).atan2(e(b)),
    }
}

/// The number of operations of the naive tree evaluation of every output (saturating).
fn tree_ops(p: &Program) -> u64 {
    let mut size = vec![0u64; p.insts.len()];
    for (i, inst) in p.insts.iter().enumerate() {
        let own = u64::from(!matches!(inst.op, Op::Const(_)));
        size[i] = inst.op.operands().fold(own, |acc, v| match v {
            Value::Inst(j) => acc.saturating_add(size[j as usize]),
            _ => acc,
        });
    }
    p.outputs
        .iter()
        .map(|o| match o.value {
            Value::Inst(j) => size[j as usize],
            _ => 0,
        })
        .fold(0, u64::saturating_add)
}

/// A scene to measure: its generated evaluator, argument names and outputs.
struct Scene<'a> {
    name: &'static str,
    ir: &'a str,
    args: &'a [&'a str],
    outputs: &'a [&'a str],
    ops: usize,
    eval: &'a (dyn Fn(&[f64], &mut [f64]) + Sync),
    /// The model's own values of its arguments (parameters and state), each drawn within
    /// ±20 % of it at every point; `None` for the hoop's, the unicycle's and the Whipple
    /// bicycle's scenes, whose arguments [`arg_value`] gives.
    values: Option<fn(&str) -> Option<f64>>,
}

/// The wheeled pendulum's arguments: the nominal transporter
/// ([`WheeledPendulumParams::nominal`](carvallo::wheeled_pendulum::WheeledPendulumParams::nominal)),
/// a pitched body on wheels turning at different rates under both motors at 2 m/s, on flat
/// ground.
fn pendulum_value(name: &str) -> Option<f64> {
    use carvallo::wheeled_pendulum::WheeledPendulumParams;
    WheeledPendulumParams::nominal().get(name).or(match name {
        "phi" => Some(0.0),
        "theta" => Some(0.2),
        "thetad" => Some(0.5),
        "thetaLd" => Some(-8.0),
        "thetaRd" => Some(-7.5),
        "TL" => Some(2.0),
        "TR" => Some(-1.0),
        "v" => Some(2.0),
        _ => None,
    })
}

/// The leaning rider's arguments: Browser + Jason
/// ([`LeanRiderParams::browser_jason`](carvallo::whipple::lean_rider::LeanRiderParams::browser_jason))
/// with a stiff, damped lean joint ($k_9 = 50$ N m/rad, $c_9 = 5$ N m s/rad, so that its
/// terms are exercised), the pitch and $\lambda$ at the upright pitch, a leaning, steering,
/// turning state at 5 m/s under all four torques.
fn rider_value(name: &str) -> Option<f64> {
    use carvallo::whipple::lean_rider::{LeanRider, LeanRiderParams};
    static PITCH: std::sync::OnceLock<f64> = std::sync::OnceLock::new();
    let pitch = *PITCH.get_or_init(|| {
        LeanRider::new(LeanRiderParams::browser_jason()).map_or(0.0, |r| r.upright_pitch())
    });
    match name {
        "k9" => Some(50.0),
        "c9" => Some(5.0),
        "lam" | "q5" => Some(pitch),
        "q4" => Some(0.1),
        "q7" => Some(0.05),
        "q9" => Some(0.02),
        "q4d" => Some(0.2),
        "q6d" => Some(-5.0 / 0.340958858855),
        "q7d" => Some(-0.1),
        "q9d" => Some(0.05),
        "T4" => Some(1.0),
        "T6" => Some(0.5),
        "T7" => Some(0.5),
        "T9" => Some(1.0),
        _ => LeanRiderParams::browser_jason().get(name),
    }
}

/// A generated scene's `eval_array` as a function of a slice.
macro_rules! scene_fn {
    ($m:path) => {{
        use $m as s;
        &|x: &[f64], out: &mut [f64]| {
            let mut a = [0.0; s::Args::LEN];
            a.copy_from_slice(&x[..s::Args::LEN]);
            out.copy_from_slice(&s::eval_array(&a));
        }
    }};
}

fn scene_args(params: &[&'static str], inputs: &[&'static str]) -> Vec<&'static str> {
    params.iter().chain(inputs).copied().collect()
}

/// Below this magnitude a 256-bit reference value is zero (the rounding of a quantity zero in
/// exact arithmetic; every other output of the scenes is above $10^{-20}$).
const TINY: f64 = 1e-60;

/// Rows of table 1 for one scene; also returns generated-vs-interpreter speed ratio.
fn evaluator_rows(cfg: &Config, sc: &Scene<'_>, rows: &mut Vec<Row>) -> f64 {
    let program = Program::parse(sc.ir)
        .expect("the committed IR parses")
        .select_outputs(sc.outputs)
        .expect("the IR has the scene's outputs");
    let interp = Interpreter::new(&program).expect("a parsed program compiles");
    let mut rng = SplitMix64(6);
    // Points: argument vectors in the scene's order, and split for the interpreter.
    let points: Vec<(Vec<f64>, Vec<f64>, Vec<f64>)> = (0..cfg.points)
        .map(|_| {
            let design = random_design(&mut rng);
            let speed = 10.0 * rng.next_unit();
            let mut vals = std::collections::BTreeMap::new();
            for n in program
                .params
                .iter()
                .chain(&program.inputs)
                .map(String::as_str)
                .chain(sc.args.iter().copied())
            {
                if !vals.contains_key(n) {
                    let x = match sc.values.and_then(|f| f(n)) {
                        Some(x) => rng.scale(x, 0.2),
                        None => arg_value(n, &design, speed, &mut rng),
                    };
                    vals.insert(n.to_string(), x);
                }
            }
            let args = sc.args.iter().map(|n| vals[*n]).collect();
            let params = program.params.iter().map(|n| vals[n.as_str()]).collect();
            let inputs = program.inputs.iter().map(|n| vals[n.as_str()]).collect();
            (args, params, inputs)
        })
        .collect();
    let reference: Vec<Vec<f64>> = points
        .par_iter()
        .map(|(_, p, i)| hp::eval_f64(&program, p, i, REFERENCE_BITS).expect("valid arguments"))
        .collect();
    let mut scratch = vec![0.0; interp.scratch_len()];
    let mut out = vec![0.0; interp.n_outputs()];
    let (mut err_gen, mut err_int, mut err_tree, mut identical) = (0.0f64, 0.0f64, 0.0f64, 0usize);
    // The outputs zero at 256 bits only to its rounding (below TINY, not 0) at some point.
    let mut zero = std::collections::BTreeSet::new();
    for ((args, p, i), r) in points.iter().zip(&reference) {
        let mut g = vec![0.0; r.len()];
        (sc.eval)(args, &mut g);
        interp.eval(p, i, &mut scratch, &mut out).expect("lengths match");
        let t: Vec<f64> =
            program.outputs.iter().map(|o| tree_eval(&program, o.value, p, i)).collect();
        identical += usize::from(g.iter().zip(&out).all(|(a, b)| a.to_bits() == b.to_bits()));
        for k in 0..r.len() {
            // An output zero in exact arithmetic (the leaning rider's lateral contact velocity
            // P_v) is zero at 256 bits only to that precision's rounding: its error is absolute.
            let rk = if r[k].abs() < TINY { 0.0 } else { r[k] };
            if rk != r[k] {
                zero.insert(program.outputs[k].name.as_str());
            }
            err_gen = err_gen.max(rel(g[k], rk));
            err_int = err_int.max(rel(out[k], rk));
            err_tree = err_tree.max(rel(t[k], rk));
        }
    }
    let (a0, p0, i0) = &points[0];
    let mut gen_out = vec![0.0; interp.n_outputs()];
    let t_gen = time_ns(cfg.min_time, || {
        (sc.eval)(black_box(a0), &mut gen_out);
        gen_out[0]
    });
    let t_int = time_ns(cfg.min_time, || {
        interp.eval(black_box(p0), black_box(i0), &mut scratch, &mut out).map(|()| out[0])
    });
    let tops = tree_ops(&program);
    let t_tree = (tops <= 2_000_000).then(|| {
        time_ns(cfg.min_time, || {
            program
                .outputs
                .iter()
                .map(|o| tree_eval(&program, o.value, black_box(p0), i0))
                .sum::<f64>()
        })
    });
    let iops = program.op_count().total as u64;
    let n = cfg.points;
    rows.push(Row {
        section: "evaluators",
        name: sc.name.to_string(),
        method: "generated".into(),
        ops: Some(sc.ops as u64),
        ns: Some(t_gen),
        max_rel_err: Some(err_gen),
        note: {
            let zero: Vec<&str> = zero.into_iter().collect();
            let mut note =
                format!("{identical} of {n} points bit for bit equal to the interpreter");
            if !zero.is_empty() {
                note.push_str(&format!(
                    "; {} zero at 256 bits to its rounding: absolute error",
                    zero.join(", ")
                ));
            }
            note
        },
    });
    rows.push(Row {
        section: "evaluators",
        name: sc.name.to_string(),
        method: "interpreter".into(),
        ops: Some(iops),
        ns: Some(t_int),
        max_rel_err: Some(err_int),
        note: format!("generated is {:.1}x faster", t_int / t_gen),
    });
    rows.push(Row {
        section: "evaluators",
        name: sc.name.to_string(),
        method: "naive tree".into(),
        ops: Some(tops),
        ns: t_tree,
        max_rel_err: Some(err_tree),
        note: match t_tree {
            Some(t) => format!("generated is {:.1}x faster", t / t_gen),
            None => "tree too large to time".into(),
        },
    });
    t_int / t_gen
}

/// The vector instructions the dispatching evaluators use on this CPU.
pub fn simd_name() -> &'static str {
    #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
    {
        if std::is_x86_feature_detected!("avx2") {
            return "AVX2";
        }
        "SSE2"
    }
    #[cfg(not(any(target_arch = "x86", target_arch = "x86_64")))]
    {
        "portable"
    }
}

/// Table 2; returns (Hurwitz time, eigen time, Hurwitz and eigen errors on the speeds both
/// report, benchmark error).
/// The windows of table 2; returns the Hurwitz and eigenvalue times per design, their errors,
/// the benchmark's error and the time of the matrices' scene.
fn window_rows(cfg: &Config, rows: &mut Vec<Row>) -> (f64, f64, f64, f64, f64, f64) {
    let mut rng = SplitMix64(7);
    let mut designs = vec![WhippleParams::benchmark()];
    designs.extend((1..cfg.designs.max(1)).map(|_| random_design(&mut rng)));
    let whipples: Vec<Whipple> = designs.iter().cloned().map(Whipple::new).collect();
    let grid = EigenGrid::default();
    let results: Vec<_> = whipples
        .par_iter()
        .map(|w| {
            let (m, g) = matrices_of(w);
            let hw = stability::hurwitz_window(&m, g);
            let hpw = stability::hurwitz_window_polished(&m, g);
            let ew = stability::eigen_window(&m, g, grid);
            let refs =
                reference_speeds(w.params(), (hw.weave_speed, hw.capsize_speed), REFERENCE_BITS);
            (hw, ew, refs, hpw)
        })
        .collect();
    let err = |x: Option<f64>, r: Option<f64>| match (x, r) {
        (Some(x), Some(r)) => rel(x, r),
        (None, None) => 0.0,
        _ => f64::INFINITY,
    };
    let (mut eh, mut ee, mut missing, mut compared, mut unlabelled) = (0.0f64, 0.0f64, 0, 0, 0);
    let mut eh_common = 0.0f64;
    let mut bench_err = 0.0;
    let mut ep = 0.0f64;
    let mut bench_err_p = 0.0;
    for (i, (hw, ew, (rw, rc), hpw)) in results.iter().enumerate() {
        let e = err(hw.weave_speed, *rw).max(err(hw.capsize_speed, *rc));
        let e_p = err(hpw.weave_speed, *rw).max(err(hpw.capsize_speed, *rc));
        ep = ep.max(e_p);
        if i == 0 {
            bench_err_p = e_p;
        }
        eh = eh.max(e);
        if i == 0 {
            bench_err = e;
        }
        let Some(ew) = ew else {
            missing += 1;
            continue;
        };
        // The eigenvalue route sees only the speeds where the largest real part changes sign
        // below grid.vmax: a root of a0 or H3 hidden by another unstable mode is no edge
        // there. Compare the speeds both routes report.
        let pairs =
            [(ew.weave_speed, hw.weave_speed, rw), (ew.capsize_speed, hw.capsize_speed, rc)];
        for (x, h, r) in pairs {
            match (x, r) {
                (Some(x), Some(r)) if h.is_some_and(|h| (h - x).abs() <= 1e-6 * h) => {
                    ee = ee.max(rel(x, *r));
                    eh_common = eh_common.max(h.map_or(f64::INFINITY, |h| rel(h, *r)));
                    compared += 1;
                }
                _ => unlabelled += 1,
            }
        }
    }
    let (m, g) = matrices_of(&whipples[0]);
    let t_h = time_ns(cfg.min_time, || stability::hurwitz_window(black_box(&m), g));
    let t_hp = time_ns(cfg.min_time, || stability::hurwitz_window_polished(black_box(&m), g));
    let t_e = time_ns(cfg.min_time, || stability::eigen_window(black_box(&m), g, grid));
    let t_scan = time_ns(cfg.min_time.min(0.05), || stability::scan_window(black_box(&m), g));
    let scan = stability::scan_window(&m, g);
    let (rw, rc) = results[0].2;
    let e_scan = err(scan.weave_speed, rw).max(err(scan.capsize_speed, rc));
    let params = whipples[0].params().values();
    let index: Vec<usize> = matrices_scene::PARAMS
        .iter()
        .map(|p| PARAM_NAMES.iter().position(|n| n == p).unwrap_or(0))
        .collect();
    let arr: [f64; matrices_scene::Args::LEN] = std::array::from_fn(|i| params[index[i]]);
    let t_m = time_ns(cfg.min_time, || matrices_scene::eval_array(black_box(&arr)));
    let n = designs.len();
    let name = format!("weave and capsize speeds, {n} designs");
    rows.push(Row {
        section: "windows",
        name: "matrices M, C1, K0, K2 (shared input)".into(),
        method: "generated".into(),
        ops: Some(matrices_scene::OP_COUNT as u64),
        ns: Some(t_m),
        max_rel_err: None,
        note: "needed by every route; not in the per-route times below".into(),
    });
    rows.push(Row {
        section: "windows",
        name: name.clone(),
        method: "hurwitz closed form".into(),
        ops: None,
        ns: Some(t_h),
        max_rel_err: Some(eh),
        note: format!(
            "benchmark bicycle: {bench_err:.1e}; {eh_common:.1e} on the speeds the eigenvalue \
             sweep also reports"
        ),
    });
    rows.push(Row {
        section: "windows",
        name: name.clone(),
        method: "hurwitz + double-double polish".into(),
        ops: None,
        ns: Some(t_hp),
        max_rel_err: Some(ep),
        note: format!("benchmark bicycle: {bench_err_p:.1e}; Whipple::stability_window"),
    });
    rows.push(Row {
        section: "windows",
        name: name.clone(),
        method: "eigenvalue sweep".into(),
        ops: None,
        ns: Some(t_e),
        max_rel_err: Some(ee),
        note: format!(
            "{} grid points to {} m/s + bisection; {:.0}x slower than hurwitz; error over the \
             {compared} speeds both routes report ({unlabelled} not seen as edges by the \
             eigenvalues); {missing} failed",
            grid.points,
            grid.vmax,
            t_e / t_h
        ),
    });
    // What a sweep keeps of each window, design by design and four designs at once (the
    // designs above, cycled to fill the lanes), per design.
    let lane_matrices: [[[f64; 4]; 16]; 1] = {
        let ms: Vec<Matrices> = whipples.iter().map(|w| matrices_of(w).0).collect();
        let flat = |m: &Matrices| {
            let mut f = [0.0; 16];
            for (k, a) in [m.m, m.c1, m.k0, m.k2].iter().enumerate() {
                f[4 * k..4 * k + 4].copy_from_slice(&[a[0][0], a[0][1], a[1][0], a[1][1]]);
            }
            f
        };
        [std::array::from_fn(|k| std::array::from_fn(|j| flat(&ms[j % ms.len()])[k]))]
    };
    let lanes_of = |o: &[[f64; 4]; 16]| -> [Matrices; 4] {
        std::array::from_fn(|j| {
            let r = |k: usize| [[o[k][j], o[k + 1][j]], [o[k + 2][j], o[k + 3][j]]];
            Matrices { m: r(0), c1: r(4), k0: r(8), k2: r(12) }
        })
    };
    let scalar_ms = lanes_of(&lane_matrices[0]);
    let t_summary = time_ns(cfg.min_time, || {
        black_box(&scalar_ms).map(|m| stability::hurwitz_window_summary(&m, g))
    }) / 4.0;
    let t_lanes = time_ns(cfg.min_time, || {
        window_lanes::hurwitz_window_summary_lanes(black_box(&lane_matrices[0]), g)
    }) / 4.0;
    let same = window_lanes::hurwitz_window_summary_lanes(&lane_matrices[0], g)
        == scalar_ms.map(|m| stability::hurwitz_window_summary(&m, g));
    rows.push(Row {
        section: "windows",
        name: "weave, capsize, stable? (a sweep's summary)".into(),
        method: "hurwitz, one design at a time".into(),
        ops: None,
        ns: Some(t_summary),
        max_rel_err: None,
        note: "per design; hurwitz_window_summary (branches per design)".into(),
    });
    rows.push(Row {
        section: "windows",
        name: "weave, capsize, stable? (a sweep's summary)".into(),
        method: format!("hurwitz, 4 designs at once ({})", simd_name()),
        ops: None,
        ns: Some(t_lanes),
        max_rel_err: None,
        note: format!(
            "per design; window_lanes (no branch per design), {:.2}x the time of one at a time; \
             {} the scalar summary",
            t_lanes / t_summary,
            if same { "equal to" } else { "DIFFERS FROM" }
        ),
    });
    rows.push(Row {
        section: "windows",
        name: "benchmark bicycle".into(),
        method: "former 200 000-point scan".into(),
        ops: None,
        ns: Some(t_scan),
        max_rel_err: Some(e_scan),
        note: format!("{:.0}x slower than hurwitz", t_scan / t_h),
    });
    (t_h, t_e, eh_common, ee, bench_err, t_m)
}

/// The closed-loop windows of table 2: random gains (as in the tests of
/// `carvallo::whipple::feedback`) on the benchmark and random designs, the Hurwitz route on the
/// generated closed-loop polynomial against the edges located at 256 bits
/// ([`feedback::closed_loop_reference_edges`](carvallo::whipple::feedback::closed_loop_reference_edges): the coefficients at 256 bits from the IR, each
/// edge bisected on the Hurwitz verdict at 256 bits) and against the eigenvalue sweep of
/// $A - BK$ (200 grid steps to 10 m/s, each edge bisected to adjacent floats); the time per
/// gain set of the fast route and of the former one (every root of every Hurwitz function),
/// measured in the same run, against `open_ns`, the open-loop window per design (matrices and
/// closed form).
fn closed_loop_rows(cfg: &Config, open_ns: f64, rows: &mut Vec<Row>) {
    use carvallo::whipple::feedback::{self, closed_loop_scene as cl, Gains};
    const SCALE: [f64; 8] = [200.0, 20.0, 50.0, 5.0, 20.0, 5.0, 20.0, 2.0];
    let (to, points) = (10.0, 200);
    let mut rng = SplitMix64(40);
    let n = (5 * cfg.designs).max(2);
    let cases: Vec<(Whipple, Gains)> = (0..n)
        .map(|i| {
            let design = if i == 0 { WhippleParams::benchmark() } else { random_design(&mut rng) };
            let gains = if i == 0 {
                Gains::balance_assist(10.0)
            } else {
                let mut g = Gains::ZERO;
                for (k, s) in SCALE.iter().enumerate() {
                    g.0[k / 4][k % 4] = rng.uniform(-s, *s);
                }
                g
            };
            (Whipple::new(design), gains)
        })
        .collect();
    let results: Vec<_> = cases
        .par_iter()
        .map(|(w, g)| {
            let h = w.closed_loop_window(g, 0.0, to).ok();
            let e = w.closed_loop_eigen_window(g, 0.0, to, points).ok();
            let r =
                h.as_ref().map(|h| feedback::closed_loop_reference_edges(w, g, h, REFERENCE_BITS));
            (h, e, r)
        })
        .collect();
    let (mut worst_lo, mut worst_hi, mut compared, mut differ, mut stable) =
        (0.0f64, 0.0f64, 0usize, 0usize, 0usize);
    let (mut worst_ref, mut bench_ref, mut ref_edges, mut ref_failed) = (0.0f64, 0.0f64, 0, 0);
    for (i, (h, e, r)) in results.iter().enumerate() {
        if let (Some(h), Some(r)) = (h, r) {
            for (x, y) in h.stable.iter().zip(r) {
                for (edge, reference) in [(x.0, y.0), (x.1, y.1)] {
                    if edge == 0.0 || edge == to {
                        continue;
                    }
                    match reference {
                        Some(reference) => {
                            let err = rel(edge, reference);
                            worst_ref = worst_ref.max(err);
                            if i == 0 {
                                bench_ref = bench_ref.max(err);
                            }
                            ref_edges += 1;
                        }
                        None => ref_failed += 1,
                    }
                }
            }
        }
        let (Some(h), Some(e)) = (h, e) else { continue };
        stable += usize::from(!h.stable.is_empty());
        if h.stable.len() != e.stable.len() {
            differ += 1;
            continue;
        }
        for (x, y) in h.stable.iter().zip(&e.stable) {
            if x.0 > 0.0 {
                worst_lo = worst_lo.max(rel(x.0, y.0));
            }
            if x.1 < to {
                worst_hi = worst_hi.max(rel(x.1, y.1));
            }
            compared += 1;
        }
    }
    let (w0, g0) = &cases[0];
    let t_h = time_ns(cfg.min_time, || w0.closed_loop_window(black_box(g0), 0.0, to));
    let t_inf = time_ns(cfg.min_time, || w0.closed_loop_window(black_box(g0), 0.0, f64::INFINITY));
    let t_poly = time_ns(cfg.min_time, || w0.closed_loop_poly(black_box(g0)));
    let t_old = time_ns(cfg.min_time, || {
        feedback::closed_loop_window_all_roots(&w0.closed_loop_poly(black_box(g0)), 0.0, to)
    });
    let t_e = time_ns(cfg.min_time, || w0.closed_loop_eigen_window(black_box(g0), 0.0, to, points));
    // Over all the cases (gains stable somewhere or not, the mix of the tests): the mean time.
    let polys: Vec<_> = cases.iter().map(|(w, g)| w.closed_loop_poly(g)).collect();
    let t_mix = time_ns(cfg.min_time, || {
        polys
            .iter()
            .map(|p| feedback::closed_loop_window_of(black_box(p), 0.0, to).stable.len())
            .sum::<usize>()
    }) / n as f64;
    let name = format!("closed-loop window, {n} random gains and designs");
    rows.push(Row {
        section: "windows",
        name: name.clone(),
        method: "hurwitz on the closed-loop polynomial".into(),
        ops: Some(cl::OP_COUNT as u64),
        ns: Some(t_h),
        max_rel_err: Some(worst_ref),
        note: format!(
            "speeds 0 to {to} m/s, the scene included (its ops, {t_poly:.0} ns); error against \
             the edges at 256 bits over {ref_edges} edges (benchmark + balance assist \
             {bench_ref:.1e}; {ref_failed} not found); lower edges {worst_lo:.1e}, upper \
             edges {worst_hi:.1e} against the eigenvalue sweep over {compared} intervals; \
             {stable} gain sets stable somewhere, {differ} where the sweep's grid misses a \
             narrow window; every speed: {t_inf:.0} ns; mean over the {n} gain sets, \
             scene excluded: {t_mix:.0} ns"
        ),
    });
    rows.push(Row {
        section: "windows",
        name: name.clone(),
        method: "former route: every root of every Hurwitz function".into(),
        ops: Some(cl::OP_COUNT as u64),
        ns: Some(t_old),
        max_rel_err: None,
        note: format!(
            "real_roots_in (isolation by derivatives, vectors), the scene included; {:.1}x \
             slower than the Bernstein/Descartes route",
            t_old / t_h
        ),
    });
    rows.push(Row {
        section: "windows",
        name: "closed-loop window per gain set".into(),
        method: "gain sets per second, one thread".into(),
        ops: None,
        ns: Some(t_h),
        max_rel_err: None,
        note: format!(
            "{:.3e} gain sets/s (former route {:.3e}/s); open-loop window {:.3e} designs/s \
             (matrices + closed form, {open_ns:.0} ns): gains {:.1}x slower than designs",
            1e9 / t_h,
            1e9 / t_old,
            1e9 / open_ns,
            t_h / open_ns
        ),
    });
    rows.push(Row {
        section: "windows",
        name,
        method: "eigenvalue sweep of A - BK".into(),
        ops: None,
        ns: Some(t_e),
        max_rel_err: None,
        note: format!(
            "{points} grid points to {to} m/s + bisection (the reference of the interval \
             count); {:.0}x slower than hurwitz",
            t_e / t_h
        ),
    });
}

/// Table 5 and its distributions.
fn distributions(cfg: &Config) -> Vec<Distribution> {
    use carvallo::whipple::char_poly_scene as cp;
    let program = Program::parse(WHIPPLE_IR)
        .expect("whipple.ir parses")
        .select_outputs(cp::OUTPUTS)
        .expect("whipple.ir has the characteristic polynomial");
    let samples = cfg.samples;
    let errs: Vec<[f64; 5]> = (0..samples)
        .into_par_iter()
        .map(|i| {
            let mut rng = SplitMix64(1_000_003 * i as u64 + 11);
            let d = random_design(&mut rng);
            let v = 10.0 * rng.next_unit();
            let params: Vec<f64> =
                program.params.iter().map(|n| d.get(n).unwrap_or(f64::NAN)).collect();
            let r = hp::eval_f64(&program, &params, &[v], REFERENCE_BITS)
                .unwrap_or_else(|_| vec![f64::NAN; 5]);
            let names = cp::PARAMS;
            let arr: [f64; cp::Args::LEN] = std::array::from_fn(|k| {
                if k < names.len() {
                    d.get(names[k]).unwrap_or(f64::NAN)
                } else {
                    v
                }
            });
            let g = cp::eval_array(&arr);
            std::array::from_fn(|k| rel(g[k], r[k]) / f64::EPSILON)
        })
        .collect();
    (0..5)
        .map(|k| {
            let mut e: Vec<f64> = errs.iter().map(|x| x[k]).collect();
            e.sort_by(f64::total_cmp);
            let q = |f: f64| e[((e.len() - 1) as f64 * f).round() as usize];
            Distribution {
                name: format!("whipple a{k} (generated, f64)"),
                samples,
                p50: q(0.5),
                p99: q(0.99),
                p9999: q(0.9999),
                max: q(1.0),
            }
        })
        .collect()
}

carvallo::scene! {
    /// The bicycle's matrices with every benchmark parameter fixed but the trail `c`.
    pub mod window_fixed_scene {
        model: whipple,
        fixed: { w: 1.02, lambda: 0.3141592653589793, g: 9.81, rR: 0.3, mR: 2.0,
                 IRxx: 0.0603, IRyy: 0.12, xB: 0.3, zB: -0.9, mB: 85.0, IBxx: 9.2, IByy: 11.0,
                 IBzz: 2.8, IBxz: 2.4, xH: 0.9, zH: -0.7, mH: 4.0, IHxx: 0.05892, IHyy: 0.06,
                 IHzz: 0.00708, IHxz: -0.00756, rF: 0.35, mF: 3.0, IFxx: 0.1405, IFyy: 0.28 },
        outputs: [m11, m12, m21, m22, c1_11, c1_12, c1_21, c1_22,
                  k0_11, k0_12, k0_21, k0_22, k2_11, k2_12, k2_21, k2_22],
    }
}

carvallo::scene! {
    /// The bicycle's characteristic polynomial at speed `v`, every benchmark parameter fixed.
    pub mod char_poly_fixed_scene {
        model: whipple,
        fixed: { w: 1.02, c: 0.08, lambda: 0.3141592653589793, g: 9.81, rR: 0.3, mR: 2.0,
                 IRxx: 0.0603, IRyy: 0.12, xB: 0.3, zB: -0.9, mB: 85.0, IBxx: 9.2, IByy: 11.0,
                 IBzz: 2.8, IBxz: 2.4, xH: 0.9, zH: -0.7, mH: 4.0, IHxx: 0.05892, IHyy: 0.06,
                 IHzz: 0.00708, IHxz: -0.00756, rF: 0.35, mF: 3.0, IFxx: 0.1405, IFyy: 0.28 },
        outputs: [a0, a1, a2, a3, a4],
    }
}

carvallo::scene! {
    /// The hoop's stability (S) only, R = 0.5 m, g = 9.81 m/s², mu = 1.2 kg fixed.
    pub mod hoop_window_fixed_scene {
        model: hoop,
        fixed: { R: 0.5, g: 9.81, mu: 1.2 },
        outputs: [stability],
    }
}

carvallo::scene! {
    /// The hoop's right-hand side (2), R = 0.5 m, g = 9.81 m/s², mu = 1.2 kg fixed.
    pub mod hoop_rhs_fixed_scene {
        model: hoop,
        fixed: { R: 0.5, g: 9.81, mu: 1.2 },
        outputs: [pns_dp, pns_dn, pns_ds],
    }
}

carvallo::scene! {
    /// The unicycle's stability first member only, free parameters.
    pub mod unicycle_window_scene {
        model: unicycle,
        outputs: [stability],
    }
}

carvallo::scene! {
    /// The unicycle's stability first member only, the tutorial rider fixed.
    pub mod unicycle_window_fixed_scene {
        model: unicycle,
        fixed: { R: 0.5, g: 9.81, mu: 60.0, z: 1.25, A: 100.0, B: 99.5, C: 1.4, L: 0.1,
                 mu1: 5.0, A1: 1.875, B1: 2.5, C1: 0.625 },
        outputs: [stability],
    }
}

carvallo::scene! {
    /// The unicycle's right-hand side, the tutorial rider fixed.
    pub mod unicycle_rhs_fixed_scene {
        model: unicycle,
        fixed: { R: 0.5, g: 9.81, mu: 60.0, z: 1.25, A: 100.0, B: 99.5, C: 1.4, L: 0.1,
                 mu1: 5.0, A1: 1.875, B1: 2.5, C1: 0.625 },
        outputs: [pns_dp, pns_dn, pns_ds],
    }
}

carvallo::scene! {
    /// The unicycle's right-hand side, free parameters.
    pub mod unicycle_rhs_scene {
        model: unicycle,
        outputs: [pns_dp, pns_dn, pns_ds],
    }
}

carvallo::scene! {
    /// The nonlinear bicycle's mass matrix $M_3$ and forcing $f_3$, free parameters.
    pub mod nonlinear_rhs_scene {
        model: whipple_nonlinear,
        lanes: 4,
        outputs: [m3_11, m3_12, m3_13, m3_22, m3_23, m3_33, f3_1, f3_2, f3_3],
    }
}

carvallo::scene! {
    /// The nonlinear bicycle's $M_3$ and $f_3$, every benchmark parameter fixed.
    pub mod nonlinear_rhs_fixed_scene {
        model: whipple_nonlinear,
        fixed: { w: 1.02, c: 0.08, lambda: 0.3141592653589793, g: 9.81, rR: 0.3, mR: 2.0,
                 IRxx: 0.0603, IRyy: 0.12, xB: 0.3, zB: -0.9, mB: 85.0, IBxx: 9.2, IByy: 11.0,
                 IBzz: 2.8, IBxz: 2.4, xH: 0.9, zH: -0.7, mH: 4.0, IHxx: 0.05892, IHyy: 0.06,
                 IHzz: 0.00708, IHxz: -0.00756, rF: 0.35, mF: 3.0, IFxx: 0.1405, IFyy: 0.28 },
        outputs: [m3_11, m3_12, m3_13, m3_22, m3_23, m3_33, f3_1, f3_2, f3_3],
    }
}

carvallo::scene! {
    /// The nonlinear bicycle's mass matrix $M_3$ only, free parameters.
    pub mod nonlinear_mass_scene {
        model: whipple_nonlinear,
        outputs: [m3_11, m3_12, m3_13, m3_22, m3_23, m3_33],
    }
}

/// Table 6: scenes that ask for less.
fn scene_rows(cfg: &Config, rows: &mut Vec<Row>) {
    let mut add = |name: &str, kind: &str, ops: usize, ns: f64, note: &str| {
        rows.push(Row {
            section: "scenes",
            name: name.into(),
            method: kind.into(),
            ops: Some(ops as u64),
            ns: Some(ns),
            max_rel_err: None,
            note: note.into(),
        })
    };
    let mt = cfg.min_time;
    let args = |names: &[&str], v: f64| -> Vec<f64> {
        let b = WhippleParams::benchmark();
        names
            .iter()
            .map(|n| if *n == "v" { v } else { b.get(n).unwrap_or_else(|| model_value(n)) })
            .collect()
    };
    let g = 9.81;
    macro_rules! arr {
        ($m:path, $v:expr) => {{
            use $m as s;
            let a = args(&scene_args(s::PARAMS, s::INPUTS), $v);
            let arr: [f64; s::Args::LEN] = std::array::from_fn(|i| a[i]);
            arr
        }};
    }
    let to_m = |o: [f64; 16]| {
        let r = |k: usize| [[o[k], o[k + 1]], [o[k + 2], o[k + 3]]];
        Matrices { m: r(0), c1: r(4), k0: r(8), k2: r(12) }
    };
    let a = arr!(matrices_scene, 0.0);
    let t = time_ns(mt, || {
        stability::hurwitz_window(&to_m(matrices_scene::eval_array(black_box(&a))), g)
    });
    add(
        "bicycle (a) window only",
        "free",
        matrices_scene::OP_COUNT,
        t,
        "matrices + hurwitz_window",
    );
    let a = arr!(window_fixed_scene, 0.0);
    let t = time_ns(mt, || {
        stability::hurwitz_window(&to_m(window_fixed_scene::eval_array(black_box(&a))), g)
    });
    add(
        "bicycle (a) window only",
        "fixed but c",
        window_fixed_scene::OP_COUNT,
        t,
        "matrices + hurwitz_window",
    );
    use carvallo::whipple::char_poly_scene as cp;
    let a = arr!(cp, 5.0);
    let t = time_ns(mt, || quartic::ferrari(&cp::eval_array(black_box(&a))));
    add("bicycle (b) eigenvalues at one speed", "free", cp::OP_COUNT, t, "a0..a4 + ferrari");
    let a = arr!(char_poly_fixed_scene, 5.0);
    let t = time_ns(mt, || quartic::ferrari(&char_poly_fixed_scene::eval_array(black_box(&a))));
    add(
        "bicycle (b) eigenvalues at one speed",
        "fixed",
        char_poly_fixed_scene::OP_COUNT,
        t,
        "a0..a4 + ferrari",
    );
    let w = Whipple::new(WhippleParams::benchmark());
    let t = time_ns(mt, || w.eigenvalues(black_box(5.0)));
    add(
        "bicycle (b) eigenvalues at one speed",
        "fixed, via state matrix",
        0,
        t,
        "precomputed matrices + Schur (nalgebra)",
    );
    use carvallo::hoop::{pns_scene, stability_scene};
    let a = arr!(stability_scene, 0.0);
    let t = time_ns(mt, || stability_scene::eval_array(black_box(&a)));
    add("hoop (a) stability (S) only", "free", stability_scene::OP_COUNT, t, "");
    let a = arr!(hoop_window_fixed_scene, 0.0);
    let t = time_ns(mt, || hoop_window_fixed_scene::eval_array(black_box(&a)));
    add("hoop (a) stability (S) only", "fixed", hoop_window_fixed_scene::OP_COUNT, t, "");
    let a = arr!(pns_scene, 0.0);
    let t = time_ns(mt, || pns_scene::eval_array(black_box(&a)));
    add("hoop (c) full right-hand side", "free", pns_scene::OP_COUNT, t, "");
    let a = arr!(hoop_rhs_fixed_scene, 0.0);
    let t = time_ns(mt, || hoop_rhs_fixed_scene::eval_array(black_box(&a)));
    add("hoop (c) full right-hand side", "fixed", hoop_rhs_fixed_scene::OP_COUNT, t, "");
    let a = arr!(unicycle_window_scene, 0.0);
    let t = time_ns(mt, || unicycle_window_scene::eval_array(black_box(&a)));
    add("unicycle (a) stability only", "free", unicycle_window_scene::OP_COUNT, t, "");
    let a = arr!(unicycle_window_fixed_scene, 0.0);
    let t = time_ns(mt, || unicycle_window_fixed_scene::eval_array(black_box(&a)));
    add("unicycle (a) stability only", "fixed", unicycle_window_fixed_scene::OP_COUNT, t, "");
    let a = arr!(unicycle_rhs_scene, 0.0);
    let t = time_ns(mt, || unicycle_rhs_scene::eval_array(black_box(&a)));
    add("unicycle (c) full right-hand side", "free", unicycle_rhs_scene::OP_COUNT, t, "");
    let a = arr!(unicycle_rhs_fixed_scene, 0.0);
    let t = time_ns(mt, || unicycle_rhs_fixed_scene::eval_array(black_box(&a)));
    add("unicycle (c) full right-hand side", "fixed", unicycle_rhs_fixed_scene::OP_COUNT, t, "");
    // The nonlinear bicycle at a leaned, steered, moving configuration of the benchmark (the
    // pitch solved from the contact constraint), solved for the three accelerations by LU.
    let wn = WhippleNonlinear::new(WhippleParams::benchmark());
    let (lean, steer) = (0.1, 0.05);
    let config = wn.pitch(lean, steer, 0.0).map(|pitch| Configuration {
        lean,
        pitch,
        steer,
        lean_rate: 0.2,
        steer_rate: -0.1,
        rear_wheel_rate: -5.0 / 0.3,
    });
    // The design sensitivities: the weave and capsize speeds' derivatives with respect to
    // the 26 parameters, the matrices' derivatives by generated code or by dual numbers
    // through the IR interpreter.
    let p = WhippleParams::benchmark();
    let generated = time_ns(mt, || {
        uncertainty::speed_gradients_by(black_box(&p), uncertainty::Derivatives::Generated)
    });
    let interpreted = time_ns(mt, || {
        uncertainty::speed_gradients_by(black_box(&p), uncertainty::Derivatives::Interpreted)
    });
    add(
        "bicycle (a) speed derivatives, 26 parameters",
        "generated",
        uncertainty::matrices_jacobian_scene::OP_COUNT,
        generated,
        &format!(
            "speed_gradients: the matrices' derivatives by scene! jacobian, then the window and \
             the implicit function theorem; {:.1}x faster than dual numbers through the interpreter",
            interpreted / generated
        ),
    );
    add(
        "bicycle (a) speed derivatives, 26 parameters",
        "interpreted duals",
        0,
        interpreted,
        "the reference route: Dual<26> through the IR interpreter on generated/whipple.ir",
    );
    if let Ok(c) = config {
        let nl_args = |names: &[&str]| -> Vec<f64> {
            let b = WhippleParams::benchmark();
            names.iter().map(|n| c.input(n).or_else(|| b.get(n)).unwrap_or(f64::NAN)).collect()
        };
        let solve = |o: [f64; 9]| {
            let m = Matrix3::new(o[0], o[1], o[2], o[1], o[3], o[4], o[2], o[4], o[5]);
            m.lu().solve(&Vector3::new(o[6], o[7], o[8]))
        };
        macro_rules! nl_arr {
            ($m:path) => {{
                use $m as s;
                let a = nl_args(&scene_args(s::PARAMS, s::INPUTS));
                let arr: [f64; s::Args::LEN] = std::array::from_fn(|i| a[i]);
                arr
            }};
        }
        let a = nl_arr!(nonlinear_rhs_scene);
        let t = time_ns(mt, || solve(nonlinear_rhs_scene::eval_array(black_box(&a))));
        add(
            "bicycle (c) full nonlinear right-hand side",
            "free",
            nonlinear_rhs_scene::OP_COUNT,
            t,
            "M3, f3 + LU (PyDy's mass matrix + forcing: 2,367 ops published, 2,548 in its generated C by scripts/pydy-c-peer)",
        );
        let a = nl_arr!(nonlinear_rhs_fixed_scene);
        let t = time_ns(mt, || solve(nonlinear_rhs_fixed_scene::eval_array(black_box(&a))));
        add(
            "bicycle (c) full nonlinear right-hand side",
            "fixed",
            nonlinear_rhs_fixed_scene::OP_COUNT,
            t,
            "M3, f3 + LU",
        );
        let a = nl_arr!(nonlinear_mass_scene);
        let t = time_ns(mt, || nonlinear_mass_scene::eval_array(black_box(&a)));
        add(
            "bicycle (c') nonlinear mass matrix only",
            "free",
            nonlinear_mass_scene::OP_COUNT,
            t,
            "M3",
        );
        let t = time_ns(mt, || wn.accelerations(black_box(&c)));
        add(
            "bicycle (c) full nonlinear right-hand side",
            "free, with dependent rates",
            dynamics_scene::OP_COUNT,
            t,
            "WhippleNonlinear::accelerations (M3, f3, dependent rates and accelerations, LU)",
        );
        // What an integrator calls: state in, state derivative out (the pitch a state,
        // projected by one Newton step fused with M3, f3 and the dependent rates at the
        // projected pitch; the closed-form solve; the kinematic rates), against the kernel
        // it evaluates.
        let f = StateRate::new(&WhippleParams::benchmark());
        let y: [f64; rate::LEN] =
            [0.0, 0.0, 0.0, lean, steer, 0.0, 0.0, 0.2, -0.1, -5.0 / 0.3, c.pitch];
        // The same on four states per call (lean and steer moved, the pitch on the contact).
        let ys: [[f64; rate::LEN]; rate::LANES] = std::array::from_fn(|j| {
            let mut z = y;
            z[3] += 0.01 * j as f64;
            z[4] -= 0.005 * j as f64;
            z[rate::PITCH] = f.project(z[3], y[rate::PITCH], z[4]).unwrap_or(f64::NAN);
            z
        });
        let same = f.eval_lanes(&ys).iter().zip(&ys).all(|(l, z)| {
            matches!((l, f.eval(z)), (Ok(a), Ok(b)) if a.map(f64::to_bits) == b.map(f64::to_bits))
        });
        // Timed interleaved (eight rounds of a quarter of the usual time each), so that the
        // ratios to the kernel are taken under one load.
        let a = nl_arr!(state_rate_scene);
        let b = nl_arr!(projected_rate_scene);
        let [kernel, fused, t, lanes] = time_ns_interleaved(
            mt / 4.0,
            8,
            [
                &mut || {
                    black_box(state_rate_scene::eval_array(black_box(&a)));
                },
                &mut || {
                    black_box(projected_rate_scene::eval_array(black_box(&b)));
                },
                &mut || {
                    let _ = black_box(f.eval(black_box(&y)));
                },
                &mut || {
                    let _ = black_box(f.eval_lanes(black_box(&ys)));
                },
            ],
        );
        let lanes = lanes / rate::LANES as f64;
        let name = "bicycle (c) state -> state derivative";
        add(
            name,
            "kernel only",
            state_rate_scene::OP_COUNT,
            kernel,
            "M3, f3, dependent rates, rear contact speed: the kernel the right-hand side evaluates \
             (this row and the next three timed interleaved, eight rounds, each its least)",
        );
        add(
            name,
            "kernel with the pitch's Newton step",
            projected_rate_scene::OP_COUNT,
            fused,
            &format!(
                "one program (scene! newton): the contact constraint's Newton step on the pitch, \
                 then the kernel at the corrected pitch, sharing the lean's and steer's \
                 trigonometry, the corrected pitch's sine and cosine by angle addition: {} ops \
                 beyond the kernel (the contact kernel alone: {}); {:.2}x the kernel",
                projected_rate_scene::OP_COUNT - state_rate_scene::OP_COUNT,
                project_scene::OP_COUNT,
                fused / kernel
            ),
        );
        add(
            name,
            "whole",
            projected_rate_scene::OP_COUNT,
            t,
            &format!(
                "StateRate::eval: the kernel with the pitch's Newton step, closed-form 3x3 solve, \
                 kinematic rates: {:.2}x the kernel (target <= 1.3x); compare PyDy's M, F + 6x6 \
                 LU + kinematic rates in scripts/pydy-c-peer",
                t / kernel
            ),
        );
        add(
            name,
            "whole, 4 lanes",
            projected_rate_scene::OP_COUNT,
            lanes,
            &format!(
                "StateRate::eval_lanes / 4, per evaluation: {:.2}x the scalar whole, {:.2}x the \
                 scalar kernel; lanes {} the scalar right-hand side bit for bit",
                lanes / t,
                lanes / kernel,
                if same { "equal" } else { "DIFFER FROM" }
            ),
        );
        // Its full state Jacobian (11 x 11) from the generated derivative code, against the
        // whole right-hand side (target <= 3x).
        let whole = t;
        let t = time_ns(mt, || f.jacobian(black_box(&y)));
        add(
            "bicycle (c) state Jacobian",
            "generated",
            state_rate_jacobian_scene::OP_COUNT + project_jacobian_scene::OP_COUNT,
            t,
            &format!(
                "StateRate::jacobian: scene! jacobian kernels ({} + {} ops, {} + {} non-zero \
                 derivatives), chain rule through the projection, the solve and the kinematic \
                 rates: {:.2}x the whole right-hand side (target <= 3x)",
                state_rate_jacobian_scene::OP_COUNT,
                project_jacobian_scene::OP_COUNT,
                state_rate_jacobian_scene::JACOBIAN_NONZEROS,
                project_jacobian_scene::JACOBIAN_NONZEROS,
                t / whole
            ),
        );
        // Where the Jacobian's time goes: its two generated kernels alone (the rest is the
        // chain rule through the projection, the solve and the kinematic rates).
        let a = nl_arr!(state_rate_jacobian_scene);
        let kernel = time_ns(mt, || state_rate_jacobian_scene::eval_array(black_box(&a)));
        let b = nl_arr!(project_jacobian_scene);
        let projection = time_ns(mt, || project_jacobian_scene::eval_array(black_box(&b)));
        add(
            "bicycle (c) state Jacobian",
            "kernels only",
            state_rate_jacobian_scene::OP_COUNT + project_jacobian_scene::OP_COUNT,
            kernel + projection,
            &format!(
                "state_rate_jacobian_scene {kernel:.1} ns + project_jacobian_scene \
                 {projection:.1} ns: {:.0} % of StateRate::jacobian; the values' kernel alone is \
                 the row `kernel only` above",
                100.0 * (kernel + projection) / t
            ),
        );
        lean_rider_rows(mt, rows);
        integrator_overhead_rows(mt, &wn, &f, rows);
    }
}

/// The leaning rider's right-hand side as its simulation calls it
/// ([`LeanRider::projected_rate`](carvallo::whipple::lean_rider::LeanRider::projected_rate):
/// the pitch projected by one Newton step, Kane's equations, the 4 x 4 solve, the kinematic
/// rates) and its state Jacobian from generated code
/// ([`LeanRider::jacobian`](carvallo::whipple::lean_rider::LeanRider::jacobian), 13 x 13), at a
/// leaning, steering, turning state of Browser + Jason at 5 m/s.
fn lean_rider_rows(mt: f64, rows: &mut Vec<Row>) {
    use carvallo::whipple::lean_rider::{
        contact_jacobian_scene, contact_scene, dynamics_jacobian_scene, dynamics_scene, Joint,
        LeanRider, LeanRiderParams, PITCH,
    };
    let Ok(rider) = LeanRider::new(LeanRiderParams::browser_jason()) else { return };
    let mut x = rider.upright(5.0);
    (x[3], x[5], x[7], x[8], x[10], x[11]) = (0.1, 0.05, 0.02, 0.2, -0.1, 0.05);
    let Some(pitch) = rider.pitch_near(x[3], x[PITCH], x[5]) else { return };
    x[PITCH] = pitch;
    let torques = [0.0; 4];
    let row = |name: &str, ops: usize, ns: f64, note: &str| Row {
        section: "scenes",
        name: name.into(),
        method: "generated".into(),
        ops: Some(ops as u64),
        ns: Some(ns),
        max_rel_err: None,
        note: note.into(),
    };
    let whole = time_ns(mt, || rider.projected_rate(black_box(&x), &torques, Joint::Free));
    rows.push(row(
        "leaning rider state -> state derivative",
        dynamics_scene::OP_COUNT + contact_scene::OP_COUNT,
        whole,
        "LeanRider::projected_rate: pitch projected by one Newton step, M, f, dependent rates, \
         4x4 solve, kinematic rates (13 components)",
    ));
    let t = time_ns(mt, || rider.jacobian(black_box(&x), &torques, Joint::Free));
    rows.push(row(
        "leaning rider state Jacobian",
        dynamics_jacobian_scene::OP_COUNT + contact_jacobian_scene::OP_COUNT,
        t,
        &format!(
            "LeanRider::jacobian: scene! jacobian kernels ({} + {} ops, {} + {} non-zero \
             derivatives), chain rule through the projection, the solve and the kinematic \
             rates: {:.2}x the whole right-hand side",
            dynamics_jacobian_scene::OP_COUNT,
            contact_jacobian_scene::OP_COUNT,
            dynamics_jacobian_scene::JACOBIAN_NONZEROS,
            contact_jacobian_scene::JACOBIAN_NONZEROS,
            t / whole
        ),
    ));
}

/// The integrators' cost beyond the right-hand side: the bicycle at 4.6 m/s from a lean of
/// 0.05 rad over 5 s (the problem of the section `simulation`), RK4 at 0.01 s and DOPRI5 and
/// DOP853 at rtol $10^{-8}$ (atol $10^{-11}$), no samples but the end. [`integrate::integrate`]
/// alone on [`StateRate::eval`] (no events, no observer) is timed twice, as it is and with every
/// evaluation done twice: the difference is the evaluations' time in place (same steps, same
/// caches), so the work beyond them is $2T_1 - T_2$ whatever the machine's load does to the
/// right-hand side's own row; per attempted step. [`WhippleNonlinear::simulate_final`] (three
/// events, the fall, the steer lock and the singular configuration, and at every accepted step
/// the energy and the contact residual) adds its time beyond `integrate`'s. Each time is the least of four timings (at
/// `--quick`, twenty runs of about a millisecond).
fn integrator_overhead_rows(mt: f64, wn: &WhippleNonlinear, f: &StateRate, rows: &mut Vec<Row>) {
    let Ok(start) = wn.initial_state(4.6, 0.05) else { return };
    let Ok(pitch) = wn.pitch(start.lean, start.steer, 0.0) else { return };
    let y0 = rate::state_with_pitch(&start, pitch);
    let least = |f: &mut dyn FnMut() -> f64| (0..4).map(|_| f()).fold(f64::INFINITY, f64::min);
    for (method, rtol) in
        [(Integrator::Rk4, 0.0), (Integrator::Dopri5, 1e-8), (Integrator::Dop853, 1e-8)]
    {
        let how = if method == Integrator::Rk4 {
            Integration::RK4
        } else {
            Integration::adaptive(method, rtol, 1e-3 * rtol)
        };
        let Ok(grid) = Grid::new(5.0, 0.01, 500) else { return };
        let run = |twice: bool| {
            let mut rhs = |_t: f64, y: &[f64; rate::LEN]| {
                if twice {
                    black_box(f.eval(black_box(y)))?;
                }
                f.eval(y)
            };
            let mut observe = |_: Point, _: f64, _: &[f64; rate::LEN]| Ok(());
            integrate::integrate(&how, &grid, y0, &mut rhs, &mut [], &mut observe)
        };
        let (Ok(out), Ok(fin)) = (run(false), wn.simulate_final(start, &grid, &how, &[])) else {
            continue;
        };
        let once = least(&mut || time_ns(mt, || run(false).map(|o| o.end)));
        let twice = least(&mut || time_ns(mt, || run(true).map(|o| o.end)));
        let whole = least(&mut || {
            time_ns(mt, || wn.simulate_final(black_box(start), &grid, &how, &[]).map(|r| r.t))
        });
        let stats = out.stats;
        let steps = (stats.steps + stats.rejected_steps).max(1) as f64;
        let evals = stats.rhs_evaluations as f64;
        let per_eval = (twice - once) / evals;
        let beyond = (2.0 * once - twice) / steps;
        let tol = if method == Integrator::Rk4 {
            "step 0.01 s".into()
        } else {
            format!("rtol {rtol:.0e}")
        };
        let counts = format!(
            "{tol}: {} steps ({} rejected), {} evaluations ({:.2} per step)",
            stats.steps,
            stats.rejected_steps,
            stats.rhs_evaluations,
            evals / steps
        );
        let mut push = |kind: &str, ns: f64, note: String| {
            rows.push(Row {
                section: "scenes",
                name: "bicycle (c) integrator overhead per step".into(),
                method: format!("{method}, {kind}"),
                ops: None,
                ns: Some(ns),
                max_rel_err: None,
                note,
            })
        };
        push(
            "integrate",
            beyond,
            format!(
                "{counts}; {:.0} us per run, the evaluations {per_eval:.0} ns each in place: \
                 {:.0} % of the run beyond them",
                once * 1e-3,
                100.0 * beyond * steps / once
            ),
        );
        let observer = (whole - once) / steps;
        push(
            "simulate_final",
            beyond + observer,
            format!(
                "{counts} (the model's: {}); {:.0} us per run: integrate's {beyond:.0} ns per \
                 step and {observer:.0} ns of events and the per-step energy and residual",
                fin.stats.rhs_evaluations,
                whole * 1e-3
            ),
        );
    }
}

/// A basin map by [`WhippleNonlinear::simulate_many`]: the benchmark bicycle from a 16 x 16
/// grid of starts — speeds 1 to 7 m/s, initial leans -0.3 to 0.3 rad, every other rate zero
/// but the rear wheel's — for 5 s at DOPRI5's default tolerances (rtol $10^{-8}$), the fall,
/// the steer lock and the singular configuration ending a run, only the ends kept (as
/// `simulate --batch`). Simulations per
/// second, and per core (over rayon's threads); the row's `ns` is the wall time per
/// simulation on all of them.
fn basin_row(rows: &mut Vec<Row>) {
    const SIDE: usize = 16;
    let wn = WhippleNonlinear::new(WhippleParams::benchmark());
    let mut starts = Vec::with_capacity(SIDE * SIDE);
    for i in 0..SIDE {
        for j in 0..SIDE {
            let speed = 1.0 + 6.0 * i as f64 / (SIDE - 1) as f64;
            let lean = -0.3 + 0.6 * j as f64 / (SIDE - 1) as f64;
            let Ok(s) = wn.initial_state(speed, lean) else { return };
            starts.push(s);
        }
    }
    let Ok(grid) = Grid::new(5.0, 0.01, 500) else { return };
    let how = Integration::with_defaults(Integrator::Dopri5, None, None);
    let done = AtomicUsize::new(0);
    let clock = std::time::Instant::now();
    let ends = wn.simulate_many(&starts, &grid, &how, &[], &done);
    let elapsed = clock.elapsed().as_secs_f64();
    let fell = ends.iter().filter(|e| matches!(e, Ok(f) if f.fall.is_some())).count();
    let lock = ends.iter().filter(|e| matches!(e, Ok(f) if f.steer_lock.is_some())).count();
    let singular = ends.iter().filter(|e| matches!(e, Ok(f) if f.singular.is_some())).count();
    let failed = ends.iter().filter(|e| e.is_err()).count();
    let evaluations: usize = ends.iter().flatten().map(|f| f.stats.rhs_evaluations).sum();
    let threads = rayon::current_num_threads();
    let rate = starts.len() as f64 / elapsed;
    rows.push(Row {
        section: "sweep",
        name: format!("basin map, simulate_many, {SIDE} x {SIDE} starts"),
        method: "dopri5".into(),
        ops: None,
        ns: Some(elapsed * 1e9 / starts.len() as f64),
        max_rel_err: None,
        note: format!(
            "speeds 1..7 m/s x leans -0.3..0.3 rad, 5 s, rtol {:.0e}: {:.3} s, {rate:.0} \
             simulations/s on {threads} threads, {:.0} per core; {fell} fell, {lock} at the steer \
             lock, {singular} singular, {failed} failed; \
             {evaluations} evaluations ({:.0} ns each on all threads)",
            how.rtol,
            elapsed,
            rate / threads as f64,
            elapsed * 1e9 / evaluations.max(1) as f64
        ),
    });
}

/// Table 7; returns the Hurwitz sweep's seconds per $10^6$ designs and the designs per second
/// of the Hurwitz sweep and of the Monte Carlo sweep.
fn sweep_rows(cfg: &Config, rows: &mut Vec<Row>) -> (f64, f64, f64) {
    let base = WhippleParams::benchmark();
    let mut per_million = f64::INFINITY;
    let mut rates = (0.0, 0.0);
    for (method, count, label) in [
        (Method::Hurwitz, cfg.sweep_count, "hurwitz"),
        (Method::Eigen, cfg.eigen_sweep_count, "eigen"),
    ] {
        let progress = AtomicUsize::new(0);
        let Ok(s) = sweep::sweep(&base, "c", 0.0, 0.2, count, method, &progress) else { continue };
        if method == Method::Hurwitz {
            per_million = s.elapsed * 1e6 / count as f64;
            rates.0 = s.designs_per_second;
        }
        rows.push(Row {
            section: "sweep",
            name: format!("c = 0.0:0.2:{count}"),
            method: label.into(),
            ops: None,
            ns: Some(s.elapsed * 1e9 / count as f64),
            max_rel_err: None,
            note: format!(
                "{:.3} s, {:.0} designs/s on {} threads, {} stable, weave {:?}",
                s.elapsed,
                s.designs_per_second,
                rayon::current_num_threads(),
                s.stable,
                s.weave_range
            ),
        });
    }
    // Monte Carlo: every parameter but g scaled by a factor in [0.8, 1.2].
    let spreads = PARAM_NAMES
        .iter()
        .filter(|n| **n != "g")
        .map(|n| sweep::Spread { name: n.to_string(), rel: 0.2 })
        .collect();
    let designs = sweep::Designs::Random { count: cfg.sweep_count, spreads, seed: 15 };
    let progress = AtomicUsize::new(0);
    if let Ok(out) = sweep::sweep_designs(&base, &designs, Method::Hurwitz, false, &progress) {
        let s = &out.summary;
        rates.1 = s.designs_per_second;
        rows.push(Row {
            section: "sweep",
            name: format!("random 25 parameters +-20 %, {}", s.count),
            method: "hurwitz".into(),
            ops: None,
            ns: Some(s.elapsed * 1e9 / s.count as f64),
            max_rel_err: None,
            note: format!(
                "{:.3} s, {:.0} designs/s on {} threads, {} stable, {} rejected, weave {:?}",
                s.elapsed,
                s.designs_per_second,
                rayon::current_num_threads(),
                s.stable,
                out.rejected,
                s.weave_range
            ),
        });
    }
    (per_million, rates.0, rates.1)
}

/// Runs every measurement (see the [module docs](self)).
pub fn run(cfg: &Config) -> Report {
    let mut rows = Vec::new();
    use carvallo::hoop::pns_scene;
    use carvallo::unicycle::motion_scene;
    use carvallo::whipple::char_poly_scene;
    let hoop_args = scene_args(pns_scene::PARAMS, pns_scene::INPUTS);
    let cp_args = scene_args(char_poly_scene::PARAMS, char_poly_scene::INPUTS);
    let mx_args = scene_args(matrices_scene::PARAMS, matrices_scene::INPUTS);
    let uni_args = scene_args(motion_scene::PARAMS, motion_scene::INPUTS);
    use carvallo::whipple::transfer::tf_roll_steer_scene as tf;
    let tf_args = scene_args(tf::PARAMS, tf::INPUTS);
    use carvallo::whipple::feedback::closed_loop_scene as cl;
    let cl_args = scene_args(cl::PARAMS, cl::INPUTS);
    use carvallo::wheeled_pendulum::dynamics_scene as wp;
    let wp_args = scene_args(wp::PARAMS, wp::INPUTS);
    use carvallo::wheeled_pendulum::linear_scene as wpl;
    let wpl_args = scene_args(wpl::PARAMS, wpl::INPUTS);
    use carvallo::whipple::lean_rider::dynamics_scene as lr;
    let lr_args = scene_args(lr::PARAMS, lr::INPUTS);
    let scenes = [
        Scene {
            name: "hoop right-hand side (2)",
            ir: HOOP_IR,
            args: &hoop_args,
            outputs: pns_scene::OUTPUTS,
            ops: pns_scene::OP_COUNT,
            eval: scene_fn!(carvallo::hoop::pns_scene),
            values: None,
        },
        Scene {
            name: "bicycle matrices",
            ir: WHIPPLE_IR,
            args: &mx_args,
            outputs: matrices_scene::OUTPUTS,
            ops: matrices_scene::OP_COUNT,
            eval: scene_fn!(carvallo::whipple::matrices_scene),
            values: None,
        },
        Scene {
            name: "bicycle a0..a4 at v",
            ir: WHIPPLE_IR,
            args: &cp_args,
            outputs: char_poly_scene::OUTPUTS,
            ops: char_poly_scene::OP_COUNT,
            eval: scene_fn!(carvallo::whipple::char_poly_scene),
            values: None,
        },
        Scene {
            name: "bicycle steer torque -> roll transfer function at v",
            ir: WHIPPLE_IR,
            args: &tf_args,
            outputs: tf::OUTPUTS,
            ops: tf::OP_COUNT,
            eval: scene_fn!(carvallo::whipple::transfer::tf_roll_steer_scene),
            values: None,
        },
        Scene {
            name: "bicycle closed-loop polynomial (coefficients of v^j s^k, 8 gains)",
            ir: WHIPPLE_IR,
            args: &cl_args,
            outputs: cl::OUTPUTS,
            ops: cl::OP_COUNT,
            eval: scene_fn!(carvallo::whipple::feedback::closed_loop_scene),
            values: None,
        },
        Scene {
            name: "unicycle motion + energy",
            ir: UNICYCLE_IR,
            args: &uni_args,
            outputs: motion_scene::OUTPUTS,
            ops: motion_scene::OP_COUNT,
            eval: scene_fn!(carvallo::unicycle::motion_scene),
            values: None,
        },
        Scene {
            name: "wheeled pendulum M, f, heading rate, contact velocity",
            ir: WHEELED_PENDULUM_IR,
            args: &wp_args,
            outputs: wp::OUTPUTS,
            ops: wp::OP_COUNT,
            eval: scene_fn!(carvallo::wheeled_pendulum::dynamics_scene),
            values: Some(pendulum_value),
        },
        Scene {
            name: "wheeled pendulum linearisation at v",
            ir: WHEELED_PENDULUM_IR,
            args: &wpl_args,
            outputs: wpl::OUTPUTS,
            ops: wpl::OP_COUNT,
            eval: scene_fn!(carvallo::wheeled_pendulum::linear_scene),
            values: Some(pendulum_value),
        },
        Scene {
            name: "leaning rider M, f, dependent rates, contact velocity",
            ir: LEAN_RIDER_IR,
            args: &lr_args,
            outputs: lr::OUTPUTS,
            ops: lr::OP_COUNT,
            eval: scene_fn!(carvallo::whipple::lean_rider::dynamics_scene),
            values: Some(rider_value),
        },
    ];
    let mut ratios = Vec::new();
    for sc in &scenes {
        ratios.push((sc.name, evaluator_rows(cfg, sc, &mut rows)));
    }
    let (t_h, t_e, e_h, e_e, bench_err, t_m) = window_rows(cfg, &mut rows);
    closed_loop_rows(cfg, t_m + t_h, &mut rows);
    super::quartic::quartic_rows(cfg, &mut rows);
    super::certified::certified_rows(cfg, &mut rows);
    let distributions = distributions(cfg);
    scene_rows(cfg, &mut rows);
    let (per_million, grid_rate, random_rate) = sweep_rows(cfg, &mut rows);
    basin_row(&mut rows);
    let mut targets: Targets = ratios
        .iter()
        .map(|(name, r)| Target {
            name: format!("generated vs interpreter speed-up, {name}"),
            measured: *r,
            required: 20.0,
            met: *r >= 20.0,
        })
        .collect();
    targets.push(Target {
        name: "hurwitz vs eigenvalue sweep speed-up per design".into(),
        measured: t_e / t_h,
        required: 1000.0,
        met: t_e / t_h >= 1000.0,
    });
    targets.push(Target {
        name: "hurwitz / eigenvalue sweep speed error, same speeds (at most)".into(),
        measured: if e_e > 0.0 {
            e_h / e_e
        } else if e_h == 0.0 {
            0.0
        } else {
            f64::INFINITY
        },
        required: 1.0,
        met: e_h <= e_e,
    });
    targets.push(Target {
        name: "benchmark weave and capsize speeds, relative error (at most)".into(),
        measured: bench_err,
        required: 1e-13,
        met: bench_err <= 1e-13,
    });
    targets.push(Target {
        name: "seconds per 10^6 designs, hurwitz sweep with rayon (at most)".into(),
        measured: per_million,
        required: 1.0,
        met: per_million < 1.0,
    });
    // Issue 22: 10^7 designs/s for the trail grid, 3·10^6 for the 25-parameter Monte Carlo
    // (whose designs are drawn and checked before they are evaluated), on 2 quiet cores.
    for (what, rate, required) in
        [("c sweep", grid_rate, 1e7), ("Monte Carlo 25 parameters", random_rate, 3e6)]
    {
        targets.push(Target {
            name: format!(
                "designs per second, {what}, hurwitz, {} threads (at least)",
                rayon::current_num_threads()
            ),
            measured: rate,
            required,
            met: rate >= required,
        });
    }
    Report {
        mode: if cfg.samples >= 1_000_000 { "full" } else { "quick" },
        rows,
        distributions,
        targets,
        simulation: Vec::new(),
        simulation_references: Vec::new(),
    }
}

fn fmt_opt(x: Option<f64>, f: impl Fn(f64) -> String) -> String {
    x.map_or("-".into(), f)
}

/// The report as aligned text tables.
pub fn render_text(r: &Report) -> String {
    let mut s = String::new();
    let mut section = "";
    for row in &r.rows {
        if row.section != section {
            section = row.section;
            s.push_str(&format!(
                "\n== {section}\n{:<40} {:<32} {:>10} {:>12} {:>10}  note\n",
                "what", "method", "ops", "ns", "max rel err"
            ));
        }
        s.push_str(&format!(
            "{:<40} {:<32} {:>10} {:>12} {:>10}  {}\n",
            row.name,
            row.method,
            row.ops.map_or("-".into(), |o| o.to_string()),
            fmt_opt(row.ns, |x| format!("{x:.1}")),
            fmt_opt(row.max_rel_err, |x| format!("{x:.1e}")),
            row.note
        ));
    }
    if !r.simulation.is_empty() {
        s.push_str(&super::simulation::render(&r.simulation, &r.simulation_references));
    }
    s.push_str("\n== distributions (relative error / 2^-52)\n");
    s.push_str(&format!(
        "{:<32} {:>9} {:>10} {:>10} {:>10} {:>10}\n",
        "output", "samples", "p50", "p99", "p99.99", "max"
    ));
    for d in &r.distributions {
        s.push_str(&format!(
            "{:<32} {:>9} {:>10.2} {:>10.2} {:>10.2} {:>10.3e}\n",
            d.name, d.samples, d.p50, d.p99, d.p9999, d.max
        ));
    }
    s.push_str("\n== targets\n");
    for t in &r.targets {
        s.push_str(&format!(
            "{:<66} measured {:>10.3e} required {:>8.1e}  {}\n",
            t.name,
            t.measured,
            t.required,
            if t.met { "met" } else { "NOT MET" }
        ));
    }
    s
}
