//! `carvallo bench`: run time against error, measured in one run.
//!
//! [`run`] ([`tables`]) measures the library's evaluators, stability windows, quartic solvers
//! ([`quartic`]), certified classification ([`certified`]), error distributions, scenes and
//! sweeps. [`extend`] appends the rows that need more than the library: the C peer ([`peer`]),
//! which spawns the system C compiler, and the headline ratios of issue 15 (generated Rust
//! against the C peer, nanoseconds per operation, designs per second), as the sections `peer`
//! and `batched` and as targets, so that `--json` carries them like every other row.

pub mod certified;
pub mod measure;
pub mod peer;
pub mod quartic;
pub mod simulation;
pub mod tables;

use measure::rel;
pub use measure::{time_ns, Config, Report, Row, Target};
pub use tables::{render_text, run};

use std::hint::black_box;

use carvallo::ir::Program;
use carvallo::whipple::nonlinear::{Configuration, WhippleNonlinear};
use carvallo::whipple::{matrices_scene, WhippleParams};
use nalgebra::{Matrix3, Vector3};

const WHIPPLE_IR: &str = carvallo::artifacts::WHIPPLE.ir;
const WHIPPLE_NONLINEAR_IR: &str = carvallo::artifacts::WHIPPLE_NONLINEAR.ir;
const UNICYCLE_IR: &str = carvallo::artifacts::UNICYCLE.ir;

/// The largest relative difference allowed between the C peer's outputs and the generated
/// Rust's (the 1e-12; in practice they agree bit for bit).
pub const PEER_TOLERANCE: f64 = 1e-12;

/// The program a scene evaluates: `ir` with `outputs` selected, as `scene!` specialises it
/// (no parameter fixed).
fn scene_program(ir: &str, outputs: &[&str]) -> Program {
    Program::parse(ir)
        .expect("the committed IR parses")
        .select_outputs(outputs)
        .expect("the IR has the scene's outputs")
        .fold_constants()
        .eliminate_dead_code()
}

/// The nonlinear bicycle's arguments at a leaned, steered, moving benchmark configuration (the
/// pitch from the contact constraint), in the order of `names`.
fn nonlinear_args(names: &[&str]) -> Vec<f64> {
    let b = WhippleParams::benchmark();
    let wn = WhippleNonlinear::new(b.clone());
    let (lean, steer) = (0.1, 0.05);
    let pitch = wn.pitch(lean, steer, 0.0).unwrap_or(0.0);
    let c = Configuration {
        lean,
        pitch,
        steer,
        lean_rate: 0.2,
        steer_rate: -0.1,
        rear_wheel_rate: -5.0 / 0.3,
    };
    names.iter().map(|n| c.input(n).or_else(|| b.get(n)).unwrap_or(f64::NAN)).collect()
}

/// Arguments of the other scenes: the benchmark's parameters, made-up values for the rest.
fn other_args(names: &[&str]) -> Vec<f64> {
    let b = WhippleParams::benchmark();
    names.iter().enumerate().map(|(i, n)| b.get(n).unwrap_or(0.3 + 0.1 * i as f64)).collect()
}

/// One scene measured against its C peer.
struct PeerCase<'a> {
    name: &'static str,
    program: Program,
    args: Vec<f64>,
    /// The generated Rust on `args`, and its time per call.
    rust: &'a dyn Fn(&[f64]) -> Vec<f64>,
    rust_ns: &'a dyn Fn(f64) -> f64,
    /// `eval_lanes` on four points near `args`: nanoseconds per point, and whether every lane
    /// equals the scalar evaluator bit for bit.
    lanes: Option<&'a LanesFn>,
    /// The portable (SSE2) variants where the scene has an AVX2 one chosen at run time: the
    /// scalar evaluator's and `eval_lanes`' time per evaluation (the rows before AVX2).
    portable: Option<&'a dyn Fn(f64) -> f64>,
    lanes_portable: Option<&'a dyn Fn(f64) -> f64>,
}

/// `eval_lanes` timed over at least the given seconds on lanes near the given arguments.
type LanesFn = dyn Fn(f64, &[f64]) -> (f64, bool);

/// Four argument vectors near `args` (lane `j` scaled by `1 + j / 1000`), as lanes.
fn spread_lanes<const K: usize>(args: &[f64]) -> [[f64; 4]; K] {
    std::array::from_fn(|k| std::array::from_fn(|j| args[k] * (1.0 + j as f64 / 1000.0)))
}

/// The ratios of the nonlinear bicycle against its C peer.
struct PeerRatios {
    /// Generated Rust / C.
    eval: f64,
    /// Generated Rust with the LU solve / C without.
    with_lu: f64,
    /// Generated Rust on four lanes, per evaluation / C.
    lanes: f64,
}

/// The section `peer`; returns the nonlinear bicycle's ratios, or `None` when the C peer could
/// not run.
fn peer_rows(cfg: &Config, rows: &mut Vec<Row>) -> Option<PeerRatios> {
    use carvallo::unicycle::motion_scene as uni;
    use tables::nonlinear_rhs_scene as nl;
    let names = |p: &[&'static str], i: &[&'static str]| -> Vec<&'static str> {
        p.iter().chain(i).copied().collect()
    };
    let nl_names = names(nl::PARAMS, nl::INPUTS);
    let mx_names = names(matrices_scene::PARAMS, matrices_scene::INPUTS);
    let uni_names = names(uni::PARAMS, uni::INPUTS);
    let to = |a: &[f64]| -> [f64; nl::Args::LEN] { std::array::from_fn(|i| a[i]) };
    let nl_eval = |a: &[f64]| nl::eval_array(&to(a)).to_vec();
    let nl_ns = |mt: f64| {
        let a = to(&nonlinear_args(&nl_names));
        time_ns(mt, || nl::eval_array(black_box(&a)))
    };
    let mx_to = |a: &[f64]| -> [f64; matrices_scene::Args::LEN] { std::array::from_fn(|i| a[i]) };
    let mx_eval = |a: &[f64]| matrices_scene::eval_array(&mx_to(a)).to_vec();
    let mx_ns = |mt: f64| {
        let a = mx_to(&other_args(&mx_names));
        time_ns(mt, || matrices_scene::eval_array(black_box(&a)))
    };
    let uni_to = |a: &[f64]| -> [f64; uni::Args::LEN] { std::array::from_fn(|i| a[i]) };
    let uni_eval = |a: &[f64]| uni::eval_array(&uni_to(a)).to_vec();
    let uni_ns = |mt: f64| {
        let a = uni_to(&other_args(&uni_names));
        time_ns(mt, || uni::eval_array(black_box(&a)))
    };
    let nl_lanes = |mt: f64, args: &[f64]| {
        let l = spread_lanes::<{ nl::Args::LEN }>(args);
        let got = nl::eval_lanes(&l);
        let same = (0..4).all(|j| {
            let want = nl::eval_array(&l.map(|a| a[j]));
            (0..want.len()).all(|k| got[k][j].to_bits() == want[k].to_bits())
        });
        (time_ns(mt, || nl::eval_lanes(black_box(&l))) / 4.0, same)
    };
    let nl_portable = |mt: f64| {
        let a = nl::Args::from_array(to(&nonlinear_args(&nl_names)));
        time_ns(mt, || nl::eval_portable(black_box(&a)))
    };
    let nl_lanes_portable = |mt: f64| {
        let l = spread_lanes::<{ nl::Args::LEN }>(&nonlinear_args(&nl_names));
        time_ns(mt, || nl::eval_lanes_portable(black_box(&l))) / 4.0
    };
    let mx_lanes_portable = |mt: f64| {
        let l = spread_lanes::<{ matrices_scene::Args::LEN }>(&other_args(&mx_names));
        time_ns(mt, || matrices_scene::eval_lanes_portable(black_box(&l))) / 4.0
    };
    let mx_lanes = |mt: f64, args: &[f64]| {
        let l = spread_lanes::<{ matrices_scene::Args::LEN }>(args);
        let got = matrices_scene::eval_lanes(&l);
        let same = (0..4).all(|j| {
            let want = matrices_scene::eval_array(&l.map(|a| a[j]));
            (0..want.len()).all(|k| got[k][j].to_bits() == want[k].to_bits())
        });
        (time_ns(mt, || matrices_scene::eval_lanes(black_box(&l))) / 4.0, same)
    };
    let cases = [
        PeerCase {
            name: "bicycle (c) full nonlinear right-hand side",
            program: scene_program(WHIPPLE_NONLINEAR_IR, nl::OUTPUTS),
            args: nonlinear_args(&nl_names),
            rust: &nl_eval,
            rust_ns: &nl_ns,
            lanes: Some(&nl_lanes),
            portable: Some(&nl_portable),
            lanes_portable: Some(&nl_lanes_portable),
        },
        PeerCase {
            name: "bicycle matrices",
            program: scene_program(WHIPPLE_IR, matrices_scene::OUTPUTS),
            args: other_args(&mx_names),
            rust: &mx_eval,
            rust_ns: &mx_ns,
            lanes: Some(&mx_lanes),
            portable: None,
            lanes_portable: Some(&mx_lanes_portable),
        },
        PeerCase {
            name: "unicycle motion + energy",
            program: scene_program(UNICYCLE_IR, uni::OUTPUTS),
            args: other_args(&uni_names),
            rust: &uni_eval,
            rust_ns: &uni_ns,
            lanes: None,
            // Its portable variant exists only at `AVX2_MIN_OPS` or more, and the scene has 518
            // ops since the unicycle's lowering asks for 100 Horner schemes (1,228 before), so
            // it is not timed here.
            portable: None,
            lanes_portable: None,
        },
    ];
    let mut nonlinear = None;
    for (k, case) in cases.iter().enumerate() {
        let ops = case.program.op_count().total as u64;
        let c = match peer::run(&case.program, &case.args, cfg.min_time, &k.to_string()) {
            Ok(c) => c,
            Err(e) => {
                rows.push(Row {
                    section: "peer",
                    name: case.name.into(),
                    method: "C peer (cc -O2)".into(),
                    ops: Some(ops),
                    ns: None,
                    max_rel_err: None,
                    note: e.to_string(),
                });
                continue;
            }
        };
        let r = (case.rust)(&case.args);
        let diff = r.iter().zip(&c.outputs).map(|(a, b)| rel(*a, *b)).fold(0.0, f64::max);
        let same = r.iter().zip(&c.outputs).filter(|(a, b)| a.to_bits() == b.to_bits()).count();
        let agree = if diff <= PEER_TOLERANCE { "agree" } else { "DISAGREE" };
        let rust_ns = (case.rust_ns)(cfg.min_time);
        rows.push(Row {
            section: "peer",
            name: case.name.into(),
            method: "C peer (cc -O2, same SSA)".into(),
            ops: Some(ops),
            ns: Some(c.ns),
            max_rel_err: None,
            note: format!(
                "`{}`; outputs {agree} with the generated Rust to {diff:.1e} \
                 ({same} of {} bit for bit); {:.3} ns/op",
                c.command,
                r.len(),
                c.ns / ops as f64
            ),
        });
        let simd = tables::simd_name();
        if let Some(portable) = case.portable {
            let ns = portable(cfg.min_time);
            rows.push(Row {
                section: "peer",
                name: case.name.into(),
                method: "generated Rust, SSE2 (before AVX2)".into(),
                ops: Some(ops),
                ns: Some(ns),
                max_rel_err: None,
                note: format!(
                    "eval_portable; {:.2}x the C peer's time; {:.3} ns/op",
                    ns / c.ns,
                    ns / ops as f64
                ),
            });
        }
        rows.push(Row {
            section: "peer",
            name: case.name.into(),
            method: "generated Rust".into(),
            ops: Some(ops),
            ns: Some(rust_ns),
            max_rel_err: None,
            note: format!(
                "{:.2}x the C peer's time; {:.3} ns/op; {}",
                rust_ns / c.ns,
                rust_ns / ops as f64,
                if case.portable.is_some() {
                    format!("eval, {simd} chosen at run time")
                } else if ops >= 1000 {
                    format!("eval, {simd} chosen at run time (the portable variant not timed)")
                } else {
                    "eval, one inlined function (no AVX2 variant below 1,000 ops)".to_string()
                }
            ),
        });
        if let Some(portable) = case.lanes_portable {
            let ns = portable(cfg.min_time);
            rows.push(Row {
                section: "peer",
                name: case.name.into(),
                method: "generated Rust, 4 lanes, SSE2 (before AVX2)".into(),
                ops: Some(ops),
                ns: Some(ns),
                max_rel_err: None,
                note: format!(
                    "per evaluation (eval_lanes_portable / 4); {:.2}x the C peer's time; {:.3} ns/op",
                    ns / c.ns,
                    ns / ops as f64
                ),
            });
        }
        let mut lanes_ratio = f64::NAN;
        if let Some(lanes) = case.lanes {
            let (ns, same) = lanes(cfg.min_time, &case.args);
            lanes_ratio = ns / c.ns;
            rows.push(Row {
                section: "peer",
                name: case.name.into(),
                method: "generated Rust, 4 lanes".into(),
                ops: Some(ops),
                ns: Some(ns),
                max_rel_err: None,
                note: format!(
                    "per evaluation (eval_lanes / 4, {simd} chosen at run time); {:.2}x the C \
                     peer's time; {:.3} ns/op; lanes {} the scalar evaluator bit for bit",
                    lanes_ratio,
                    ns / ops as f64,
                    if same { "equal" } else { "DIFFER FROM" }
                ),
            });
        }
        if k == 0 && diff <= PEER_TOLERANCE {
            let a = to(&case.args);
            let solve = |o: [f64; 9]| {
                let m = Matrix3::new(o[0], o[1], o[2], o[1], o[3], o[4], o[2], o[4], o[5]);
                m.lu().solve(&Vector3::new(o[6], o[7], o[8]))
            };
            let lu_ns = time_ns(cfg.min_time, || solve(nl::eval_array(black_box(&a))));
            rows.push(Row {
                section: "peer",
                name: case.name.into(),
                method: "generated Rust + LU".into(),
                ops: Some(ops),
                ns: Some(lu_ns),
                max_rel_err: None,
                note: format!("{:.2}x the C peer's time without the solve", lu_ns / c.ns),
            });
            nonlinear = Some(PeerRatios {
                eval: rust_ns / c.ns,
                with_lu: lu_ns / c.ns,
                lanes: lanes_ratio,
            });
        }
    }
    nonlinear
}

/// Appends the command line's sections and targets to `report`.
pub fn extend(cfg: &Config, report: &mut Report) {
    match peer_rows(cfg, &mut report.rows) {
        Some(r) => {
            let mut push = |name: &str, measured: f64, required: f64| {
                report.targets.push(Target {
                    name: name.into(),
                    measured,
                    required,
                    met: measured <= required,
                })
            };
            push("generated / C peer time, nonlinear rhs, scalar (at most)", r.eval, 0.5);
            push("generated 4 lanes / C peer time per evaluation (at most)", r.lanes, 0.5);
            push("generated + LU / C peer time, nonlinear rhs (at most)", r.with_lu, 1.0);
        }
        None => report.targets.push(Target {
            name: "generated / C peer time, nonlinear rhs: skipped, no C peer".into(),
            measured: f64::NAN,
            required: 0.5,
            met: false,
        }),
    }
}
