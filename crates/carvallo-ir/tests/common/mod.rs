//! Random program generators shared by the integration tests (fixed seeds, deterministic).
//!
//! [`random_program`] makes arbitrary programs (every operation, constants such as 0, 1 and
//! repeated values that trigger the simplifications, negations of negations, `powi` by 0 and 1,
//! dead instructions, outputs that are arguments). [`well_conditioned_program`] makes programs
//! whose values stay positive and moderate at a given point, so that their `f64` evaluation is
//! accurate and can be compared with high-precision evaluation.

#![allow(dead_code)]

use carvallo_ir::{Builder, Op, Program, Value};
use rand::seq::SliceRandom;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// An arbitrary valid program with up to `max_insts` instructions. The last instruction is not a
/// constant and is the last output; there are at least two outputs.
pub fn random_program(rng: &mut ChaCha8Rng, max_insts: usize) -> Program {
    let mut p = Program { model: "random".to_string(), ..Program::default() };
    p.header.push(format!("random program, {} instructions at most", max_insts));
    let n_params = rng.gen_range(0..=3);
    let n_inputs = rng.gen_range(1..=4);
    p.params = (0..n_params).map(|i| format!("p{i}")).collect();
    p.inputs = (0..n_inputs).map(|i| format!("x{i}")).collect();
    let mut values: Vec<Value> = (0..n_params)
        .map(|i| Value::Param(i as u32))
        .chain((0..n_inputs).map(|i| Value::Input(i as u32)))
        .collect();
    let n_insts = rng.gen_range(2..=max_insts.max(2));
    let consts = [0.0, -0.0, 1.0, 1.0, 2.0, 0.5, -1.5, 3.0, 0.1, 1e-3];
    for k in 0..n_insts {
        let pick = |rng: &mut ChaCha8Rng| *values.choose(rng).unwrap();
        let a = pick(rng);
        let b = pick(rng);
        let last = k + 1 == n_insts;
        let op = match rng.gen_range(0..if last { 13 } else { 16 }) {
            0 => Op::Neg(a),
            1 => Op::Add(a, b),
            2 => Op::Sub(a, b),
            3 => Op::Mul(a, b),
            4 => Op::Div(a, b),
            5 => Op::Powi(a, rng.gen_range(-3..=3)),
            6 => Op::Sqrt(a),
            7 => Op::Sin(a),
            8 => Op::Cos(a),
            9 => Op::Tan(a),
            10 => Op::Atan2(a, b),
            11 => match values.iter().rev().find(
                |v| matches!(v, Value::Inst(i) if matches!(p.insts[*i as usize].op, Op::Neg(_))),
            ) {
                Some(&v) => Op::Neg(v),
                None => Op::Neg(a),
            },
            12 => Op::Powi(a, rng.gen_range(0..=1)),
            _ => Op::Const(*consts.choose(rng).unwrap()),
        };
        p.insts.push(carvallo_ir::Inst { name: format!("v{k}"), op });
        values.push(Value::Inst(k as u32));
    }
    let n_out = rng.gen_range(1..=4);
    for o in 0..n_out {
        let v = *values.choose(rng).unwrap();
        p.outputs.push(carvallo_ir::Output { name: format!("out{o}"), value: v });
    }
    p.outputs.push(carvallo_ir::Output {
        name: "last".to_string(),
        value: Value::Inst(n_insts as u32 - 1),
    });
    p.validate().expect("generated program is valid");
    p
}

/// Random argument values in `[-2, 2]`, with a few exact zeros and ones.
pub fn random_args(rng: &mut ChaCha8Rng, n: usize) -> Vec<f64> {
    (0..n)
        .map(|_| match rng.gen_range(0..10) {
            0 => 0.0,
            1 => 1.0,
            _ => rng.gen_range(-2.0..2.0),
        })
        .collect()
}

/// A program whose values at `point` (params then inputs, all in `[0.5, 2]`) and nearby are
/// positive and between about $10^{-3}$ and $10^3$, built only from well-conditioned steps
/// (relative condition number at most 3): sums of positives, products, quotients, square roots,
/// `powi` with $|k| \le 2$, `atan2` of positives, and `2 + sin`, `2 + cos`, `2 + tan` of values
/// first squashed into $(0, 1)$ by $a / (1 + a)$. Returns the program and the point.
pub fn well_conditioned_program(
    rng: &mut ChaCha8Rng,
    n_steps: usize,
) -> (Program, Vec<f64>, Vec<f64>) {
    let mut b = Builder::new("conditioned");
    let n_params = rng.gen_range(1..=2);
    let n_inputs = rng.gen_range(1..=3);
    let mut values: Vec<(Value, f64)> = Vec::new();
    let params: Vec<f64> = (0..n_params).map(|_| rng.gen_range(0.5..2.0)).collect();
    let inputs: Vec<f64> = (0..n_inputs).map(|_| rng.gen_range(0.5..2.0)).collect();
    for (i, &x) in params.iter().enumerate() {
        values.push((b.param(&format!("k{i}")), x));
    }
    for (i, &x) in inputs.iter().enumerate() {
        values.push((b.input(&format!("u{i}")), x));
    }
    let one = b.constant(1.0);
    let two = b.constant(2.0);
    for _ in 0..n_steps {
        let (a, va) = *values.choose(rng).unwrap();
        let (c, vc) = *values.choose(rng).unwrap();
        let squash = |b: &mut Builder, a: Value, va: f64| {
            let d = b.add(one, a);
            (b.div(a, d), va / (1.0 + va))
        };
        let (v, x) = match rng.gen_range(0..9) {
            0 => (b.add(a, c), va + vc),
            1 => (b.mul(a, c), va * vc),
            2 => (b.div(a, c), va / vc),
            3 => (b.sqrt(a), va.sqrt()),
            4 => {
                let k = *[-2, -1, 2].choose(rng).unwrap();
                (b.powi(a, k), va.powi(k))
            }
            5 => (b.atan2(a, c), va.atan2(vc)),
            6..=8 => {
                let (s, vs) = squash(&mut b, a, va);
                let (t, vt) = match rng.gen_range(0..3) {
                    0 => (b.sin(s), vs.sin()),
                    1 => (b.cos(s), vs.cos()),
                    _ => (b.tan(s), vs.tan()),
                };
                (b.add(two, t), 2.0 + vt)
            }
            _ => unreachable!(),
        };
        // Keep magnitudes moderate: squash large values, lift small ones.
        let (v, x) = if x > 1e3 {
            squash(&mut b, v, x)
        } else if x < 1e-3 {
            (b.add(one, v), 1.0 + x)
        } else {
            (v, x)
        };
        values.push((v, x));
    }
    let n = values.len();
    for (o, &(v, _)) in values[n - 3..].iter().enumerate() {
        b.output(&format!("y{o}"), v);
    }
    (b.finish(), params, inputs)
}
