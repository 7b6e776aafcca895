//! Benchmark: nanoseconds per evaluation of the generated hoop evaluators (the full right-hand
//! side of system (2) and a one-output scene) against the `carvallo_ir` interpreter running the
//! same programs on the same inputs. Also prints the operation counts of both scenes.
//!
//! Run with `cargo bench -p carvallo --bench hoop`; each function is measured for about 1.5 s.

use std::hint::black_box;
use std::time::Duration;

use carvallo::hoop::{equilibrium_scene, pns_scene};
use carvallo::ir::{Interpreter, Program};
use criterion::{criterion_group, criterion_main, Criterion};

const IR: &str = carvallo::artifacts::HOOP.ir;

/// Values of the hoop's parameters and inputs used for every evaluation.
fn value(name: &str) -> f64 {
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
        other => panic!("unknown hoop argument {other}"),
    }
}

/// The interpreter for the scene's outputs, and its parameter and input vectors.
fn interpreter(outputs: &[&str]) -> (Interpreter, Vec<f64>, Vec<f64>) {
    let program = Program::parse(IR).unwrap().select_outputs(outputs).unwrap();
    let params = program.params.iter().map(|n| value(n)).collect();
    let inputs = program.inputs.iter().map(|n| value(n)).collect();
    (Interpreter::new(&program).unwrap(), params, inputs)
}

fn bench(c: &mut Criterion) {
    println!(
        "op counts: full rhs scene pns_scene = {} ({:?}), one-output scene equilibrium_scene = {} ({:?}), whole hoop program = {}",
        pns_scene::OP_COUNT,
        pns_scene::OP_COUNT_BY_OP,
        equilibrium_scene::OP_COUNT,
        equilibrium_scene::OP_COUNT_BY_OP,
        pns_scene::SOURCE_OP_COUNT,
    );
    let mut group = c.benchmark_group("hoop");
    group.warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_millis(1500));

    let pns_args: [f64; pns_scene::Args::LEN] = std::array::from_fn(|i| {
        value(pns_scene::PARAMS.iter().chain(pns_scene::INPUTS).nth(i).unwrap())
    });
    group.bench_function("generated/pns_rhs", |b| {
        b.iter(|| pns_scene::eval_array(black_box(&pns_args)))
    });
    let (it, params, inputs) = interpreter(pns_scene::OUTPUTS);
    let mut scratch = vec![0.0; it.scratch_len()];
    let mut out = vec![0.0; it.n_outputs()];
    group.bench_function("interpreter/pns_rhs", |b| {
        b.iter(|| {
            it.eval(black_box(&params), black_box(&inputs), &mut scratch, &mut out).unwrap();
            black_box(out[0])
        })
    });

    let eq_args: [f64; equilibrium_scene::Args::LEN] = std::array::from_fn(|i| {
        value(equilibrium_scene::PARAMS.iter().chain(equilibrium_scene::INPUTS).nth(i).unwrap())
    });
    group.bench_function("generated/equilibrium", |b| {
        b.iter(|| equilibrium_scene::eval_array(black_box(&eq_args)))
    });
    let (it, params, inputs) = interpreter(equilibrium_scene::OUTPUTS);
    let mut scratch = vec![0.0; it.scratch_len()];
    let mut out = vec![0.0; it.n_outputs()];
    group.bench_function("interpreter/equilibrium", |b| {
        b.iter(|| {
            it.eval(black_box(&params), black_box(&inputs), &mut scratch, &mut out).unwrap();
            black_box(out[0])
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
