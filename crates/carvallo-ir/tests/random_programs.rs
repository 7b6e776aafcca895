//! Transformations checked on random programs (fixed seeds): folding, fixing parameters,
//! selecting outputs and dead-code elimination preserve the interpreter's results, keep the
//! program valid and keep instruction names; printing and parsing round-trip exactly.

mod common;

use std::collections::HashSet;

use carvallo_ir::{Interpreter, Op, Program};
use common::{random_args, random_program};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

const SEED: u64 = 0x00ca_2a11_0189_7000;
const PROGRAMS: usize = 400;

/// Equal as `f64` numbers (so `-0.0 == 0.0`, see the `opt` module docs) or both NaN.
fn same(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x == y || (x.is_nan() && y.is_nan()))
}

/// Names of `q`'s instructions must be names of `p`'s instructions, in the same relative order,
/// except the constants `fix_params` introduces (named after parameters).
fn keeps_names(p: &Program, q: &Program) {
    let mut it = p.insts.iter();
    for inst in &q.insts {
        if p.params.contains(&inst.name) {
            continue;
        }
        assert!(
            it.any(|i| i.name == inst.name),
            "instruction {} is new or out of order",
            inst.name
        );
    }
}

fn eval(p: &Program, params: &[f64], inputs: &[f64]) -> Vec<f64> {
    p.eval_f64(params, inputs).unwrap()
}

#[test]
fn transformations_preserve_results() {
    let mut rng = ChaCha8Rng::seed_from_u64(SEED);
    let mut folded_away = 0;
    for n in 0..PROGRAMS {
        let p = random_program(&mut rng, 60);
        // Round trip of the text form.
        let text = p.to_text();
        let q = Program::parse(&text).unwrap();
        assert_eq!(q, p, "program {n}");
        assert_eq!(q.to_text(), text);

        let folded = p.fold_constants();
        let dce = p.eliminate_dead_code();
        for t in [&folded, &dce] {
            t.validate().unwrap();
            keeps_names(&p, t);
            assert_eq!(t.params, p.params);
            assert_eq!(t.inputs, p.inputs);
            assert_eq!(t.outputs.len(), p.outputs.len());
            assert!(t.op_count().total <= p.op_count().total);
            assert_eq!(Program::parse(&t.to_text()).unwrap(), *t);
        }
        // Folding twice changes nothing more.
        assert_eq!(folded.fold_constants(), folded, "program {n}");
        folded_away += p.op_count().total - folded.op_count().total;
        // Constants are deduplicated.
        let bits: Vec<u64> = folded
            .insts
            .iter()
            .filter_map(|i| if let Op::Const(c) = i.op { Some(c.to_bits()) } else { None })
            .collect();
        assert_eq!(bits.iter().collect::<HashSet<_>>().len(), bits.len(), "program {n}");

        for _ in 0..4 {
            let params = random_args(&mut rng, p.params.len());
            let inputs = random_args(&mut rng, p.inputs.len());
            let want = eval(&p, &params, &inputs);
            assert!(same(&eval(&folded, &params, &inputs), &want), "fold, program {n}\n{p}");
            assert!(same(&eval(&dce, &params, &inputs), &want), "dce, program {n}");

            // Fixing every parameter at these values.
            let fixes: Vec<(&str, f64)> =
                p.params.iter().map(|s| s.as_str()).zip(params.iter().copied()).collect();
            let fixed = p.fix_params(&fixes).unwrap();
            fixed.validate().unwrap();
            keeps_names(&p, &fixed);
            assert!(fixed.params.is_empty());
            assert!(same(&eval(&fixed, &[], &inputs), &want), "fix_params, program {n}\n{p}");

            // Each output on its own.
            for (k, o) in p.outputs.iter().enumerate() {
                let s = p.select_outputs(&[o.name.as_str()]).unwrap();
                s.validate().unwrap();
                keeps_names(&p, &s);
                let sp: Vec<f64> = s
                    .params
                    .iter()
                    .map(|n| params[p.params.iter().position(|x| x == n).unwrap()])
                    .collect();
                let si: Vec<f64> = s
                    .inputs
                    .iter()
                    .map(|n| inputs[p.inputs.iter().position(|x| x == n).unwrap()])
                    .collect();
                assert!(
                    same(&eval(&s, &sp, &si), &want[k..k + 1]),
                    "select {}, program {n}",
                    o.name
                );
            }
        }
    }
    // The generator exercises folding: many operations disappear overall.
    assert!(folded_away > PROGRAMS, "only {folded_away} operations folded away");
}

#[test]
fn selecting_one_output_shrinks_the_program() {
    let mut rng = ChaCha8Rng::seed_from_u64(SEED + 1);
    let mut checked = 0;
    for _ in 0..PROGRAMS {
        let p = random_program(&mut rng, 40);
        let last = p.outputs.last().unwrap().value;
        let full = p.op_count().total;
        for o in &p.outputs {
            let s = p.select_outputs(&[o.name.as_str()]).unwrap();
            assert!(s.op_count().total <= full);
            // The last instruction is an operation (not a constant) that only outputs returning
            // it need.
            if o.value != last {
                assert!(s.op_count().total < full, "output {} of\n{p}", o.name);
                checked += 1;
            }
        }
        let all: Vec<&str> = p.outputs.iter().map(|o| o.name.as_str()).collect();
        let s = p.select_outputs(&all).unwrap();
        assert_eq!(s, p.eliminate_dead_code().prune_arguments());
    }
    assert!(checked > PROGRAMS, "only {checked} strict reductions checked");
}

#[test]
fn interpreter_is_reusable_and_checks_lengths() {
    let mut rng = ChaCha8Rng::seed_from_u64(SEED + 2);
    let p = random_program(&mut rng, 30);
    let it = Interpreter::new(&p).unwrap();
    let mut scratch = vec![0.0; it.scratch_len() + 3];
    let mut out = vec![0.0; it.n_outputs()];
    for _ in 0..10 {
        let params = random_args(&mut rng, p.params.len());
        let inputs = random_args(&mut rng, p.inputs.len());
        it.eval(&params, &inputs, &mut scratch, &mut out).unwrap();
        assert!(same(&out, &p.eval_f64(&params, &inputs).unwrap()));
    }
    let params = vec![0.0; p.params.len()];
    let inputs = vec![0.0; p.inputs.len()];
    let e = it.eval(&params, &inputs, &mut scratch[..1], &mut out).unwrap_err();
    assert_eq!(
        e,
        carvallo_ir::IrError::ArgumentCount {
            what: "scratch slots",
            expected: it.scratch_len(),
            got: 1
        }
    );
    let e = it.eval(&params, &[0.0; 9], &mut scratch, &mut out).unwrap_err();
    assert_eq!(
        e.to_string(),
        format!("wrong number of inputs: expected {}, got 9", p.inputs.len())
    );
}
