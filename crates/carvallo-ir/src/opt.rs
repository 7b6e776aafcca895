//! Program transformations: constant folding with algebraic simplification, fixing parameters,
//! selecting outputs, dead-code elimination and pruning of unused arguments.
//!
//! The transformations expect a valid program (see [`Program::validate`]; parsed and
//! [`Builder`](crate::Builder)-made programs are valid). On an invalid one, `fix_params` and
//! `select_outputs` return the validation error and the others return the program unchanged;
//! none of them panics.
//!
//! Every transformation returns a new program that [`validate`](Program::validate)s when its
//! input does, keeps the order and the names of the instructions it keeps, and computes the same
//! outputs. Folding evaluates operations exactly as the [`Interpreter`](crate::Interpreter) does
//! (plain `f64`), so folded and unfolded programs give bitwise identical results, except that
//! `x + 0 -> x` and `0 + x -> x` turn a result of $-0 + 0 = +0$ into $-0$ (equal as numbers).

use std::collections::HashMap;

use crate::{Inst, IrError, Op, Output, Program, Value};

/// Evaluates `op` in `f64` given its operands' values (the interpreter's semantics).
pub(crate) fn apply_f64(op: Op, mut get: impl FnMut(Value) -> f64) -> f64 {
    match op {
        Op::Const(c) => c,
        Op::Neg(a) => -get(a),
        Op::Add(a, b) => get(a) + get(b),
        Op::Sub(a, b) => get(a) - get(b),
        Op::Mul(a, b) => get(a) * get(b),
        Op::Div(a, b) => get(a) / get(b),
        Op::Powi(a, k) => get(a).powi(k),
        Op::Sqrt(a) => get(a).sqrt(),
        Op::Sin(a) => get(a).sin(),
        Op::Cos(a) => get(a).cos(),
        Op::Tan(a) => get(a).tan(),
        Op::Atan2(a, b) => get(a).atan2(get(b)),
    }
}

/// Rebuilds `p` keeping the instructions for which `keep[i]` holds, remapping operands and
/// outputs. Every kept instruction and output must only use kept instructions.
fn retain_insts(p: &Program, keep: &[bool]) -> Program {
    let mut map = vec![u32::MAX; p.insts.len()];
    let mut insts = Vec::new();
    let remap = |map: &[u32], v: Value| match v {
        Value::Inst(i) => Value::Inst(map[i as usize]),
        other => other,
    };
    for (i, inst) in p.insts.iter().enumerate() {
        if keep[i] {
            map[i] = insts.len() as u32;
            insts.push(Inst {
                name: inst.name.clone(),
                op: inst.op.map_operands(|v| remap(&map, v)),
            });
        }
    }
    let outputs = p
        .outputs
        .iter()
        .map(|o| Output { name: o.name.clone(), value: remap(&map, o.value) })
        .collect();
    Program { insts, outputs, ..p.clone_without_body() }
}

impl Program {
    /// The program's header, model and arguments, without instructions and outputs.
    fn clone_without_body(&self) -> Program {
        Program {
            header: self.header.clone(),
            model: self.model.clone(),
            params: self.params.clone(),
            inputs: self.inputs.clone(),
            insts: Vec::new(),
            outputs: Vec::new(),
        }
    }

    /// Folds constants and simplifies trivial operations, then removes the instructions left
    /// dead.
    ///
    /// * An instruction whose operands are all constants is evaluated in `f64` and becomes a
    ///   `const` of the same name, unless the result is not finite (such as `div 1 0`), in which
    ///   case it is kept as it is.
    /// * $x \cdot 1$, $1 \cdot x$, $x / 1$, $x + 0$, $0 + x$, $x - 0$, $x^1$ and $-(-x)$ become
    ///   $x$; $x^0$ becomes the constant $1$.
    /// * Equal constants (same bits) are merged into the first one.
    ///
    /// Parameters and inputs are kept even if no longer used (see [`Program::prune_arguments`]).
    ///
    /// ```
    /// use carvallo_ir::Program;
    /// let p = Program::parse("carvallo-ir 1\nmodel m\ninput x\nlet a = const 2.0\n\
    ///     let b = const 0.5\nlet c = mul a b\nlet d = mul x c\nlet e = add d b\n\
    ///     let f = sub e b\noutput y = f\n")?;
    /// let q = p.fold_constants();
    /// assert_eq!(q.to_text(), "carvallo-ir 1\nmodel m\ninput x\nlet b = const 0.5\n\
    ///     let e = add x b\nlet f = sub e b\noutput y = f\n");
    /// # Ok::<(), carvallo_ir::ParseError>(())
    /// ```
    pub fn fold_constants(&self) -> Program {
        if self.validate().is_err() {
            return self.clone();
        }
        let mut out = self.clone_without_body();
        // Old instruction index -> value in `out`.
        let mut map: Vec<Value> = Vec::with_capacity(self.insts.len());
        let mut consts: HashMap<u64, Value> = HashMap::new();
        for inst in &self.insts {
            let op = inst.op.map_operands(|v| match v {
                Value::Inst(i) => map[i as usize],
                other => other,
            });
            let const_of = |v: Value| match v {
                Value::Inst(i) => match out.insts[i as usize].op {
                    Op::Const(c) => Some(c),
                    _ => None,
                },
                _ => None,
            };
            let is = |v: Value, c: f64| const_of(v) == Some(c);
            // Simplification to an existing value.
            let alias = match op {
                Op::Mul(a, b) if is(b, 1.0) => Some(a),
                Op::Mul(a, b) if is(a, 1.0) => Some(b),
                Op::Div(a, b) if is(b, 1.0) => Some(a),
                Op::Add(a, b) if is(b, 0.0) => Some(a),
                Op::Add(a, b) if is(a, 0.0) => Some(b),
                Op::Sub(a, b) if is(b, 0.0) => Some(a),
                Op::Powi(a, 1) => Some(a),
                Op::Neg(Value::Inst(i)) => match out.insts[i as usize].op {
                    Op::Neg(x) => Some(x),
                    _ => None,
                },
                _ => None,
            };
            if let Some(v) = alias {
                map.push(v);
                continue;
            }
            let folded = match op {
                Op::Const(c) => Some(c),
                Op::Powi(_, 0) => Some(1.0),
                _ => {
                    let vals: Vec<Option<f64>> = op.operands().map(const_of).collect();
                    if vals.iter().all(Option::is_some) {
                        let c = apply_f64(op, |v| const_of(v).unwrap_or(f64::NAN));
                        c.is_finite().then_some(c)
                    } else {
                        None
                    }
                }
            };
            let op = match folded {
                Some(c) => {
                    if let Some(&v) = consts.get(&c.to_bits()) {
                        map.push(v);
                        continue;
                    }
                    let v = Value::Inst(out.insts.len() as u32);
                    consts.insert(c.to_bits(), v);
                    Op::Const(c)
                }
                None => op,
            };
            map.push(Value::Inst(out.insts.len() as u32));
            out.insts.push(Inst { name: inst.name.clone(), op });
        }
        out.outputs = self
            .outputs
            .iter()
            .map(|o| Output {
                name: o.name.clone(),
                value: match o.value {
                    Value::Inst(i) => map[i as usize],
                    other => other,
                },
            })
            .collect();
        out.dce()
    }

    /// Replaces the parameters named in `values` by constants (instructions named after the
    /// parameter, placed first), removes them from [`Program::params`] and folds constants.
    ///
    /// Fails with [`IrError::UnknownParam`] for a name the program does not declare and with
    /// [`IrError::Invalid`] for a name given twice or a non-finite value.
    ///
    /// ```
    /// use carvallo_ir::Program;
    /// let p = Program::parse("carvallo-ir 1\nmodel m\nparam g\nparam R\ninput x\n\
    ///     let a = div g R\nlet b = mul a x\noutput y = b\n")?;
    /// let q = p.fix_params(&[("g", 6.0), ("R", 3.0)])?;
    /// assert_eq!(q.params.len(), 0);
    /// assert_eq!(q.to_text(), "carvallo-ir 1\nmodel m\ninput x\nlet a = const 2.0\n\
    ///     let b = mul a x\noutput y = b\n");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn fix_params(&self, values: &[(&str, f64)]) -> Result<Program, IrError> {
        self.validate()?;
        let mut fixed: Vec<Option<f64>> = vec![None; self.params.len()];
        for &(name, value) in values {
            let i = self
                .params
                .iter()
                .position(|p| p == name)
                .ok_or_else(|| IrError::UnknownParam { name: name.to_string() })?;
            if fixed[i].is_some() {
                return Err(IrError::invalid(format!("parameter {name:?} fixed twice")));
            }
            if !value.is_finite() {
                return Err(IrError::invalid(format!(
                    "non-finite value {value} for parameter {name:?}"
                )));
            }
            fixed[i] = Some(value);
        }
        let mut out = self.clone_without_body();
        out.params.clear();
        let mut param_map = Vec::with_capacity(self.params.len());
        for (name, f) in self.params.iter().zip(&fixed) {
            match f {
                Some(c) => {
                    param_map.push(Value::Inst(out.insts.len() as u32));
                    out.insts.push(Inst { name: name.clone(), op: Op::Const(*c) });
                }
                None => {
                    param_map.push(Value::Param(out.params.len() as u32));
                    out.params.push(name.clone());
                }
            }
        }
        let shift = out.insts.len() as u32;
        let remap = |v: Value| match v {
            Value::Param(i) => param_map[i as usize],
            Value::Inst(i) => Value::Inst(i + shift),
            other => other,
        };
        for inst in &self.insts {
            out.insts.push(Inst { name: inst.name.clone(), op: inst.op.map_operands(remap) });
        }
        out.outputs = self
            .outputs
            .iter()
            .map(|o| Output { name: o.name.clone(), value: remap(o.value) })
            .collect();
        Ok(out.fold_constants())
    }

    /// Keeps only the outputs named in `names`, in that order, removes the instructions they do
    /// not need and the parameters and inputs no remaining instruction or output uses.
    ///
    /// Fails with [`IrError::UnknownOutput`] for a name the program does not declare and with
    /// [`IrError::Invalid`] for a name given twice.
    ///
    /// ```
    /// use carvallo_ir::Program;
    /// let p = Program::parse("carvallo-ir 1\nmodel m\ninput x\ninput z\n\
    ///     let a = sin x\nlet b = cos z\noutput ya = a\noutput yb = b\n")?;
    /// let q = p.select_outputs(&["yb"])?;
    /// assert_eq!(q.to_text(), "carvallo-ir 1\nmodel m\ninput z\nlet b = cos z\noutput yb = b\n");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn select_outputs(&self, names: &[&str]) -> Result<Program, IrError> {
        self.validate()?;
        let mut outputs = Vec::with_capacity(names.len());
        for (k, &name) in names.iter().enumerate() {
            if names[..k].contains(&name) {
                return Err(IrError::invalid(format!("output {name:?} selected twice")));
            }
            let o = self
                .output(name)
                .ok_or_else(|| IrError::UnknownOutput { name: name.to_string() })?;
            outputs.push(o.clone());
        }
        let p = Program { outputs, insts: self.insts.clone(), ..self.clone_without_body() };
        Ok(p.dce().prune())
    }

    /// Removes the instructions no output depends on. Parameters and inputs are kept.
    ///
    /// ```
    /// use carvallo_ir::Program;
    /// let p = Program::parse("carvallo-ir 1\nmodel m\ninput x\ninput z\n\
    ///     let a = sin z\nlet b = cos x\noutput y = b\n")?;
    /// let q = p.eliminate_dead_code();
    /// assert_eq!(q.to_text(), "carvallo-ir 1\nmodel m\ninput x\ninput z\nlet b = cos x\noutput y = b\n");
    /// assert_eq!(q.prune_arguments().inputs, ["x"]);
    /// # Ok::<(), carvallo_ir::ParseError>(())
    /// ```
    pub fn eliminate_dead_code(&self) -> Program {
        if self.validate().is_err() {
            return self.clone();
        }
        self.dce()
    }

    /// [`Program::eliminate_dead_code`] of a valid program.
    fn dce(&self) -> Program {
        let mut live = vec![false; self.insts.len()];
        for o in &self.outputs {
            if let Value::Inst(i) = o.value {
                if let Some(l) = live.get_mut(i as usize) {
                    *l = true;
                }
            }
        }
        for i in (0..self.insts.len()).rev() {
            if live[i] {
                for v in self.insts[i].op.operands() {
                    if let Value::Inst(j) = v {
                        if let Some(l) = live.get_mut(j as usize) {
                            *l = true;
                        }
                    }
                }
            }
        }
        retain_insts(self, &live)
    }

    /// Removes the parameters and inputs that no instruction and no output uses, keeping the
    /// order of the others.
    pub fn prune_arguments(&self) -> Program {
        if self.validate().is_err() {
            return self.clone();
        }
        self.prune()
    }

    /// [`Program::prune_arguments`] of a valid program.
    fn prune(&self) -> Program {
        let mut used_p = vec![false; self.params.len()];
        let mut used_i = vec![false; self.inputs.len()];
        let uses = self
            .insts
            .iter()
            .flat_map(|i| i.op.operands())
            .chain(self.outputs.iter().map(|o| o.value));
        for v in uses {
            match v {
                Value::Param(i) => used_p[i as usize] = true,
                Value::Input(i) => used_i[i as usize] = true,
                Value::Inst(_) => {}
            }
        }
        let renumber = |used: &[bool]| {
            let mut n = 0u32;
            used.iter()
                .map(|&u| {
                    n += u as u32;
                    n.wrapping_sub(1)
                })
                .collect::<Vec<u32>>()
        };
        let (pm, im) = (renumber(&used_p), renumber(&used_i));
        let remap = |v: Value| match v {
            Value::Param(i) => Value::Param(pm[i as usize]),
            Value::Input(i) => Value::Input(im[i as usize]),
            other => other,
        };
        let keep = |names: &[String], used: &[bool]| {
            names.iter().zip(used).filter(|(_, &u)| u).map(|(n, _)| n.clone()).collect()
        };
        Program {
            header: self.header.clone(),
            model: self.model.clone(),
            params: keep(&self.params, &used_p),
            inputs: keep(&self.inputs, &used_i),
            insts: self
                .insts
                .iter()
                .map(|i| Inst { name: i.name.clone(), op: i.op.map_operands(remap) })
                .collect(),
            outputs: self
                .outputs
                .iter()
                .map(|o| Output { name: o.name.clone(), value: remap(o.value) })
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::Program;

    /// `let y = EXPR` over the input `x` and the constants `zero`, `one`, `two`, folded.
    fn fold(body: &str) -> String {
        let text = format!(
            "carvallo-ir 1\nmodel m\ninput x\nlet zero = const 0.0\nlet one = const 1.0\n\
             let two = const 2.0\n{body}"
        );
        let p = Program::parse(&text).unwrap().fold_constants();
        p.validate().unwrap();
        p.to_text().trim_start_matches("carvallo-ir 1\nmodel m\ninput x\n").to_string()
    }

    #[test]
    fn identities_become_the_operand() {
        for e in [
            "mul x one",
            "mul one x",
            "div x one",
            "add x zero",
            "add zero x",
            "sub x zero",
            "powi x 1",
        ] {
            assert_eq!(fold(&format!("let y = {e}\noutput y = y\n")), "output y = x\n", "{e}");
        }
        assert_eq!(fold("let a = neg x\nlet b = neg a\noutput y = b\n"), "output y = x\n");
    }

    #[test]
    fn powi_zero_is_one_and_constants_fold() {
        assert_eq!(
            fold("let y = powi x 0\noutput y = y\n"),
            "let one = const 1.0\noutput y = one\n"
        );
        assert_eq!(
            fold("let a = add two one\nlet b = sqrt a\nlet c = mul b x\noutput y = c\n"),
            format!("let b = const {:?}\nlet c = mul b x\noutput y = c\n", 3f64.sqrt())
        );
        // Equal constants are merged, the first name wins.
        assert_eq!(
            fold("let a = const 2.0\nlet b = mul a x\noutput y = b\n"),
            "let two = const 2.0\nlet b = mul two x\noutput y = b\n"
        );
    }

    #[test]
    fn non_finite_results_are_not_folded() {
        assert_eq!(
            fold("let a = div one zero\nlet b = mul a x\noutput y = b\n"),
            "let zero = const 0.0\nlet one = const 1.0\nlet a = div one zero\nlet b = mul a x\n\
             output y = b\n"
        );
    }

    #[test]
    fn invalid_programs_do_not_panic() {
        let mut p = Program::parse(
            "carvallo-ir 1\nmodel m\nparam R\ninput x\nlet a = mul R x\noutput y = a\n",
        )
        .unwrap();
        p.insts[0].op = crate::Op::Neg(crate::Value::Inst(7));
        p.outputs[0].value = crate::Value::Param(3);
        assert_eq!(p.fold_constants(), p);
        assert_eq!(p.eliminate_dead_code(), p);
        assert_eq!(p.prune_arguments(), p);
        assert!(p.fix_params(&[("R", 1.0)]).is_err());
        let e = p.select_outputs(&["y"]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid program: operand Inst(7) of \"a\" is not defined before it"
        );
        assert!(p.eval_f64(&[1.0], &[1.0]).is_err());
        assert!(crate::hp::eval(&p, &[1.0], &[1.0], 64).is_err());
        // Printing an invalid program does not panic either.
        assert!(p.to_text().contains("let a = neg ?"));
    }

    #[test]
    fn errors_name_the_offending_value() {
        let p = Program::parse(
            "carvallo-ir 1\nmodel m\nparam R\ninput x\nlet a = mul R x\noutput y = a\n",
        )
        .unwrap();
        assert_eq!(p.fix_params(&[("g", 1.0)]).unwrap_err().to_string(), "unknown parameter \"g\"");
        assert_eq!(
            p.fix_params(&[("R", 1.0), ("R", 2.0)]).unwrap_err().to_string(),
            "invalid program: parameter \"R\" fixed twice"
        );
        assert_eq!(
            p.fix_params(&[("R", f64::NAN)]).unwrap_err().to_string(),
            "invalid program: non-finite value NaN for parameter \"R\""
        );
        assert_eq!(p.select_outputs(&["z"]).unwrap_err().to_string(), "unknown output \"z\"");
        assert_eq!(
            p.select_outputs(&["y", "y"]).unwrap_err().to_string(),
            "invalid program: output \"y\" selected twice"
        );
        // Fixing R = 1 folds `mul R x` to `x`; the input stays, the constant goes.
        let q = p.fix_params(&[("R", 1.0)]).unwrap();
        assert_eq!(q.to_text(), "carvallo-ir 1\nmodel m\ninput x\noutput y = x\n");
    }
}
