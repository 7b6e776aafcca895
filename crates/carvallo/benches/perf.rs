//! Criterion benchmarks of the performance work: the bicycle's stability window by the
//! closed-form Hurwitz route against the eigenvalue sweep, the quartic root solvers on the
//! benchmark bicycle's polynomial at 5 m/s, the generated characteristic polynomial against
//! the interpreter, the certified classification, the bicycle's steady turns at one speed and
//! lean (a scan of 720 steers, then Newton on the steer), its hands-free turns (the branch
//! points on upright running: 2,000 speeds, each the Jacobian of the lean and steer rows; every
//! family, what `carvallo turn --hands-free` computes) and
//! the leaning rider's steady turns at one speed and roll (a scan of 720 steers, each with the
//! torso's equilibrium by Newton, then Newton on the steer).
//!
//! Run with `cargo bench -p carvallo --bench perf`. `carvallo bench` measures the same things
//! together with their errors in one table.

use std::hint::black_box;
use std::time::Duration;

use carvallo::ir::{Interpreter, Program};
use carvallo::whipple::lean_rider::{LeanRider, LeanRiderParams};
use carvallo::whipple::steady_turn::hands_free::{HandsFree, MAX_SPEED};
use carvallo::whipple::steady_turn::lean_rider::RiderTurnSolver;
use carvallo::whipple::steady_turn::TurnSolver;
use carvallo::whipple::{char_poly_scene, Whipple, WhippleParams};
use carvallo::{certified, quartic, sweep};
use criterion::{criterion_group, criterion_main, Criterion};

const IR: &str = carvallo::artifacts::WHIPPLE.ir;

fn bench(c: &mut Criterion) {
    let w = Whipple::new(WhippleParams::benchmark());
    let (m, g) = (w.matrices(), 9.81);
    let mut group = c.benchmark_group("perf");
    group.warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_millis(1500));
    group.bench_function("window/hurwitz", |b| b.iter(|| sweep::hurwitz_window(black_box(&m), g)));
    group.sample_size(10);
    group.bench_function("window/eigen_sweep", |b| {
        b.iter(|| sweep::eigen_window(black_box(&m), g, sweep::EigenGrid::default()))
    });
    group.sample_size(100);
    let poly = w.char_poly(5.0);
    group.bench_function("quartic/ferrari", |b| b.iter(|| quartic::ferrari(black_box(&poly))));
    group.bench_function("quartic/companion", |b| b.iter(|| quartic::companion(black_box(&poly))));
    group.bench_function("quartic/aberth", |b| b.iter(|| quartic::aberth(black_box(&poly))));
    group.bench_function("quartic/aberth_compensated", |b| {
        b.iter(|| quartic::aberth_compensated(black_box(&poly)))
    });
    group.bench_function("quartic/graeffe", |b| {
        b.iter(|| quartic::graeffe_moduli(black_box(&poly)))
    });
    group.bench_function("certified/classify", |b| {
        b.iter(|| certified::classify(black_box(&m), g, 5.0, 0.0))
    });
    let p = WhippleParams::benchmark();
    let args: [f64; char_poly_scene::Args::LEN] = std::array::from_fn(|i| {
        char_poly_scene::PARAMS.get(i).map_or(5.0, |n| p.get(n).unwrap_or(f64::NAN))
    });
    group.bench_function("char_poly/generated", |b| {
        b.iter(|| char_poly_scene::eval_array(black_box(&args)))
    });
    let program = Program::parse(IR).unwrap().select_outputs(char_poly_scene::OUTPUTS).unwrap();
    let it = Interpreter::new(&program).unwrap();
    let params: Vec<f64> = program.params.iter().map(|n| p.get(n).unwrap()).collect();
    let mut scratch = vec![0.0; it.scratch_len()];
    let mut out = vec![0.0; it.n_outputs()];
    group.bench_function("char_poly/interpreter", |b| {
        b.iter(|| {
            it.eval(black_box(&params), &[5.0], &mut scratch, &mut out).unwrap();
            black_box(out[0])
        })
    });
    group.sample_size(10);
    let bicycle = TurnSolver::new(&WhippleParams::benchmark()).unwrap();
    group.bench_function("steady_turn/whipple", |b| {
        b.iter(|| bicycle.turns(black_box(5.0), black_box(0.05)).unwrap())
    });
    let hands_free = HandsFree::new(&bicycle);
    group.bench_function("hands_free/branch_speeds", |b| {
        b.iter(|| hands_free.branch_speeds(black_box(0.0), MAX_SPEED))
    });
    group.bench_function("hands_free/families", |b| b.iter(|| hands_free.families().unwrap()));
    let rider = LeanRider::new(LeanRiderParams::browser_jason()).unwrap();
    let solver = RiderTurnSolver::new(&rider);
    group.bench_function("steady_turn/lean_rider", |b| {
        b.iter(|| solver.turns(black_box(5.0), black_box(0.05)).unwrap())
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
