//! Derivatives as programs: forward-mode differentiation of a program *into* a program.
//!
//! [`Program::with_jacobian`] returns a program that computes the original outputs and, beside
//! them, the partial derivatives of every output with respect to chosen inputs or parameters,
//! as new named outputs ([`derivative_name`]). It is the source-transformation twin of the
//! dual numbers of [`dual`](crate::dual): the same rules of the chain rule
//! ($(ab)' = a'b + ab'$, $(a/b)' = (a' - (a/b)\,b')/b$, $(a^k)' = k a^{k-1} a'$,
//! $(\sqrt a)' = a'/(2\sqrt a)$, $(\sin a)' = a'\cos a$, $(\cos a)' = -a'\sin a$,
//! $(\tan a)' = a'(1 + \tan^2 a)$, $\operatorname{atan2}(y, x)' = (x y' - y x')/(x^2 + y^2)$),
//! but written once as instructions, so that the derivative code is straight-line `f64`
//! arithmetic that the `scene!` macro compiles like any value, the interpreter evaluates and the
//! 256-bit evaluator of [`hp`](crate::hp) checks.
//!
//! Structural zeros are not computed: every value carries the set of variables it depends on,
//! a derivative that is identically zero by the program's structure has no instruction, and an
//! output that does not depend on a variable has no derivative output for it
//! ([`Program::jacobian_entries`] lists those that exist). A derivative equal to one (an
//! input with respect to itself) costs nothing. The new instructions go through the
//! hash-consing [`Builder`], so a product or a cosine the value and its derivatives share is
//! computed once, and then through constant folding and dead-code elimination.

use crate::{Builder, IrError, Op, Program, Value};

/// The output name of $\partial\,\text{output}/\partial\,\text{variable}$: `d_OUTPUT__VARIABLE`.
///
/// ```
/// assert_eq!(carvallo_ir::diff::derivative_name("f3_1", "phi"), "d_f3_1__phi");
/// ```
pub fn derivative_name(output: &str, variable: &str) -> String {
    format!("d_{output}__{variable}")
}

/// A derivative while it is built: structurally zero, exactly one, or a value.
#[derive(Clone, Copy, Debug, PartialEq)]
enum D {
    Zero,
    One,
    V(Value),
}

/// The builder and the helpers that skip zeros and ones.
struct Diff {
    b: Builder,
}

impl Diff {
    /// The value of `d`, materialised (a constant for one; zero is never asked for).
    fn value(&mut self, d: D) -> Option<Value> {
        match d {
            D::Zero => None,
            D::One => Some(self.b.constant(1.0)),
            D::V(v) => Some(v),
        }
    }

    /// $c\,d$.
    fn scale(&mut self, c: Value, d: D) -> D {
        match d {
            D::Zero => D::Zero,
            D::One => D::V(c),
            D::V(v) => D::V(self.b.mul(c, v)),
        }
    }

    /// $-d$.
    fn neg(&mut self, d: D) -> D {
        match d {
            D::Zero => D::Zero,
            D::One => D::V(self.b.constant(-1.0)),
            D::V(v) => D::V(self.b.neg(v)),
        }
    }

    /// $a + b$.
    fn add(&mut self, a: D, b: D) -> D {
        match (a, b) {
            (D::Zero, x) | (x, D::Zero) => x,
            _ => {
                let (x, y) = (self.value(a), self.value(b));
                match (x, y) {
                    (Some(x), Some(y)) => D::V(self.b.add(x, y)),
                    _ => D::Zero,
                }
            }
        }
    }

    /// $a - b$.
    fn sub(&mut self, a: D, b: D) -> D {
        match (a, b) {
            (x, D::Zero) => x,
            (D::Zero, y) => self.neg(y),
            _ => {
                let (x, y) = (self.value(a), self.value(b));
                match (x, y) {
                    (Some(x), Some(y)) => D::V(self.b.sub(x, y)),
                    _ => D::Zero,
                }
            }
        }
    }
}

impl Program {
    /// This program with, beside its outputs, the derivative of every output with respect to
    /// each of the inputs or parameters named in `wrt`, as the outputs
    /// [`derivative_name`]`(output, variable)`, output by output in the order of
    /// [`Program::outputs`] and, for one output, in the order of `wrt`. A derivative that is
    /// zero by the program's structure is not an output (see [`Program::jacobian_entries`]).
    /// The original outputs keep their names and values (the same operations in the same
    /// order, bit for bit).
    ///
    /// Fails with [`IrError::Invalid`] for an invalid program, a name of `wrt` that is neither
    /// an input nor a parameter or that is given twice, or a derivative name that is already
    /// an output.
    ///
    /// ```
    /// use carvallo_ir::Program;
    /// let p = Program::parse("carvallo-ir 1\nmodel m\nparam R\ninput x\ninput y\n\
    ///     let t0 = sin x\nlet t1 = mul R t0\noutput f = t1\noutput g = y\n")?;
    /// let j = p.with_jacobian(&["x", "y"])?;
    /// let names: Vec<&str> = j.outputs.iter().map(|o| o.name.as_str()).collect();
    /// // f does not depend on y, g not on x: those derivatives are not computed.
    /// assert_eq!(names, ["f", "g", "d_f__x", "d_g__y"]);
    /// let out = j.eval_f64(&[2.0], &[0.5, 3.0])?;
    /// assert_eq!(out, vec![2.0 * 0.5f64.sin(), 3.0, 2.0 * 0.5f64.cos(), 1.0]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_jacobian(&self, wrt: &[&str]) -> Result<Program, IrError> {
        self.validate()?;
        let mut vars: Vec<Value> = Vec::with_capacity(wrt.len());
        for (k, name) in wrt.iter().enumerate() {
            if wrt[..k].contains(name) {
                return Err(IrError::invalid(format!(
                    "{name:?} is named twice among the variables of the Jacobian"
                )));
            }
            let v = if let Some(i) = self.inputs.iter().position(|n| n == name) {
                Value::Input(i as u32)
            } else if let Some(i) = self.params.iter().position(|n| n == name) {
                Value::Param(i as u32)
            } else {
                return Err(IrError::invalid(format!(
                    "cannot differentiate with respect to {name:?}: it is neither an input nor a parameter of model {:?}",
                    self.model
                )));
            };
            vars.push(v);
        }
        for o in &self.outputs {
            for name in wrt {
                let d = derivative_name(&o.name, name);
                if self.output(&d).is_some() {
                    return Err(IrError::invalid(format!(
                        "the derivative output {d:?} is already an output of model {:?}",
                        self.model
                    )));
                }
            }
        }

        let mut g = Diff { b: Builder::new(&self.model) };
        for h in &self.header {
            g.b.header(h);
        }
        let params: Vec<Value> = self.params.iter().map(|n| g.b.param(n)).collect();
        let inputs: Vec<Value> = self.inputs.iter().map(|n| g.b.input(n)).collect();
        let n = vars.len();
        let seed = |v: Value| -> Vec<D> {
            vars.iter().map(|&x| if x == v { D::One } else { D::Zero }).collect()
        };
        let param_d: Vec<Vec<D>> =
            (0..self.params.len()).map(|i| seed(Value::Param(i as u32))).collect();
        let input_d: Vec<Vec<D>> =
            (0..self.inputs.len()).map(|i| seed(Value::Input(i as u32))).collect();
        // Instruction index -> its value and derivatives in the new program.
        let mut values: Vec<Value> = Vec::with_capacity(self.insts.len());
        let mut derivs: Vec<Vec<D>> = Vec::with_capacity(self.insts.len());
        let zeros = vec![D::Zero; n];
        for inst in &self.insts {
            let map = |v: Value| match v {
                Value::Param(i) => params[i as usize],
                Value::Input(i) => inputs[i as usize],
                Value::Inst(i) => values[i as usize],
            };
            let op = inst.op.map_operands(map);
            let value = g.b.push(op);
            let d_of = |v: Value| -> &[D] {
                match v {
                    Value::Param(i) => &param_d[i as usize],
                    Value::Input(i) => &input_d[i as usize],
                    Value::Inst(i) => &derivs[i as usize],
                }
            };
            let d: Vec<D> = match inst.op {
                Op::Const(_) => zeros.clone(),
                Op::Neg(a) => d_of(a).iter().map(|&x| g.neg(x)).collect(),
                Op::Add(a, b) => d_of(a).iter().zip(d_of(b)).map(|(&x, &y)| g.add(x, y)).collect(),
                Op::Sub(a, b) => d_of(a).iter().zip(d_of(b)).map(|(&x, &y)| g.sub(x, y)).collect(),
                Op::Mul(a, b) => {
                    let (va, vb) = (map(a), map(b));
                    d_of(a)
                        .iter()
                        .zip(d_of(b))
                        .map(|(&x, &y)| {
                            let l = g.scale(vb, x);
                            let r = g.scale(va, y);
                            g.add(l, r)
                        })
                        .collect()
                }
                Op::Div(a, b) => {
                    // (a' - q b') / b with q = a / b the value itself.
                    let vb = map(b);
                    let (da, db) = (d_of(a), d_of(b));
                    let any = da.iter().chain(db).any(|x| *x != D::Zero);
                    let r = if any {
                        let one = g.b.constant(1.0);
                        Some(g.b.div(one, vb))
                    } else {
                        None
                    };
                    da.iter()
                        .zip(db)
                        .map(|(&x, &y)| {
                            let Some(r) = r else { return D::Zero };
                            let qy = g.scale(value, y);
                            let num = g.sub(x, qy);
                            g.scale(r, num)
                        })
                        .collect()
                }
                Op::Powi(a, k) => {
                    let da = d_of(a);
                    let coef = if k == 0 || da.iter().all(|x| *x == D::Zero) {
                        None
                    } else {
                        let va = map(a);
                        let kc = g.b.constant(f64::from(k));
                        Some(match k - 1 {
                            0 => kc,
                            1 => g.b.mul(kc, va),
                            m => {
                                let p = g.b.powi(va, m);
                                g.b.mul(kc, p)
                            }
                        })
                    };
                    da.iter().map(|&x| coef.map_or(D::Zero, |c| g.scale(c, x))).collect()
                }
                Op::Sqrt(a) => unary(&mut g, d_of(a), |b| {
                    let half = b.constant(0.5);
                    b.div(half, value)
                }),
                Op::Sin(a) => unary(&mut g, d_of(a), |b| b.cos(map(a))),
                Op::Cos(a) => unary(&mut g, d_of(a), |b| {
                    let s = b.sin(map(a));
                    b.neg(s)
                }),
                Op::Tan(a) => unary(&mut g, d_of(a), |b| {
                    let t2 = b.powi(value, 2);
                    let one = b.constant(1.0);
                    b.add(one, t2)
                }),
                Op::Atan2(y, x) => {
                    let (dy, dx) = (d_of(y), d_of(x));
                    let any = dy.iter().chain(dx).any(|v| *v != D::Zero);
                    let coefs = any.then(|| {
                        let (vy, vx) = (map(y), map(x));
                        let x2 = g.b.powi(vx, 2);
                        let y2 = g.b.powi(vy, 2);
                        let r2 = g.b.add(x2, y2);
                        let cy = g.b.div(vx, r2);
                        let q = g.b.div(vy, r2);
                        let cx = g.b.neg(q);
                        (cy, cx)
                    });
                    dy.iter()
                        .zip(dx)
                        .map(|(&p, &q)| {
                            let Some((cy, cx)) = coefs else { return D::Zero };
                            let l = g.scale(cy, p);
                            let r = g.scale(cx, q);
                            g.add(l, r)
                        })
                        .collect()
                }
            };
            values.push(value);
            derivs.push(d);
        }

        let value_of = |v: Value| match v {
            Value::Param(i) => params[i as usize],
            Value::Input(i) => inputs[i as usize],
            Value::Inst(i) => values[i as usize],
        };
        for o in &self.outputs {
            g.b.output(&o.name, value_of(o.value));
        }
        for o in &self.outputs {
            let ds: Vec<D> = match o.value {
                Value::Param(i) => param_d[i as usize].clone(),
                Value::Input(i) => input_d[i as usize].clone(),
                Value::Inst(i) => derivs[i as usize].clone(),
            };
            for (name, d) in wrt.iter().zip(ds) {
                if let Some(v) = g.value(d) {
                    g.b.output(&derivative_name(&o.name, name), v);
                }
            }
        }
        let out = g.b.finish().fold_constants().eliminate_dead_code();
        // Keep the declared parameters and inputs (the caller prunes them if it wishes).
        debug_assert!(out.validate().is_ok());
        Ok(out)
    }

    /// The derivative outputs of a program made by [`Program::with_jacobian`] with the
    /// variables `wrt`: for each output `o` of `of` and each variable `x` of `wrt`, the index
    /// of the output [`derivative_name`]`(o, x)` in [`Program::outputs`], or `None` for a
    /// structural zero. Row `i` is `of[i]`, column `j` is `wrt[j]`.
    pub fn jacobian_entries(&self, of: &[&str], wrt: &[&str]) -> Vec<Vec<Option<usize>>> {
        of.iter()
            .map(|o| {
                wrt.iter()
                    .map(|x| {
                        let name = derivative_name(o, x);
                        self.outputs.iter().position(|out| out.name == name)
                    })
                    .collect()
            })
            .collect()
    }
}

/// The derivatives of a unary operation: `coef(builder)` times each non-zero derivative of its
/// operand, the coefficient built once and only if some derivative is not zero.
fn unary(g: &mut Diff, da: &[D], coef: impl FnOnce(&mut Builder) -> Value) -> Vec<D> {
    if da.iter().all(|x| *x == D::Zero) {
        return vec![D::Zero; da.len()];
    }
    let c = coef(&mut g.b);
    da.iter().map(|&x| g.scale(c, x)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dual::{self, Dual};
    use crate::hp;

    /// A program using every operation, with shared subexpressions and a constant.
    const TEXT: &str = "carvallo-ir 1
model every_op
param a
param b
input x
input y
input z
let c0 = const 1.5
let t0 = mul a x
let t1 = sin t0
let t2 = cos y
let t3 = tan z
let t4 = add t1 t2
let t5 = sub t4 t3
let t6 = div t5 b
let t7 = powi t6 3
let t8 = powi x -2
let t9 = mul t8 c0
let t10 = add t9 y
let t11 = sqrt t10
let t12 = atan2 t11 t7
let t13 = neg t12
let t14 = mul t13 t1
let t15 = powi y 2
output f = t14
output g = t11
output h = t15
output k = b
";

    fn program() -> Program {
        Program::parse(TEXT).expect("test program parses")
    }

    #[test]
    fn derivatives_equal_the_dual_numbers_to_rounding() {
        let p = program();
        let wrt = ["x", "y", "z", "a", "b"];
        let j = p.with_jacobian(&wrt).expect("differentiates");
        j.validate().expect("valid");
        let params = [0.7, 1.3];
        let inputs = [0.9, -0.4, 0.3];
        let got = j.eval_f64(&params, &inputs).expect("evaluates");
        // Dual numbers: variables x, y, z, a, b are 0..5.
        let dp = [Dual::<5>::variable(params[0], 3), Dual::variable(params[1], 4)];
        let di = [
            Dual::<5>::variable(inputs[0], 0),
            Dual::variable(inputs[1], 1),
            Dual::variable(inputs[2], 2),
        ];
        let want = dual::eval(&p, &dp, &di).expect("dual evaluation");
        let names: Vec<&str> = p.outputs.iter().map(|o| o.name.as_str()).collect();
        let entries = j.jacobian_entries(&names, &wrt);
        for (i, row) in entries.iter().enumerate() {
            assert_eq!(got[i].to_bits(), want[i].value.to_bits(), "value of {}", names[i]);
            for (k, e) in row.iter().enumerate() {
                let w = want[i].grad[k];
                match e {
                    Some(idx) => {
                        let err = (got[*idx] - w).abs() / w.abs().max(1.0);
                        assert!(
                            err <= 4.0 * f64::EPSILON,
                            "d{}/d{}: {} vs {w}",
                            names[i],
                            wrt[k],
                            got[*idx]
                        );
                    }
                    None => {
                        assert_eq!(w, 0.0, "d{}/d{} is not structurally zero", names[i], wrt[k])
                    }
                }
            }
        }
        // The structure: h = y^2 depends on y only, k = b on b only; f and g not on z or b?
        // g = sqrt(1.5/x^2 + y) does not depend on z, a, b.
        let absent = |o: &str, x: &str| j.output(&derivative_name(o, x)).is_none();
        assert!(absent("g", "z") && absent("g", "a") && absent("g", "b"));
        assert!(absent("h", "x") && !absent("h", "y"));
        assert!(absent("k", "x") && !absent("k", "b"));
        assert!(!absent("f", "z") && !absent("f", "b"));
    }

    #[test]
    fn derivatives_equal_256_bit_central_differences() {
        let p = program();
        let wrt = ["x", "y", "z", "a", "b"];
        let j = p.with_jacobian(&wrt).expect("differentiates");
        let params = [0.7, 1.3];
        let inputs = [0.9, -0.4, 0.3];
        let got = j.eval_f64(&params, &inputs).expect("evaluates");
        for x in wrt {
            let fd = hp::derivative(&p, &params, &inputs, x, 256).expect("256-bit difference");
            for (i, o) in p.outputs.iter().enumerate() {
                let name = derivative_name(&o.name, x);
                let g = j.outputs.iter().position(|q| q.name == name).map_or(0.0, |k| got[k]);
                let err = (g - fd[i]).abs() / fd[i].abs().max(1.0);
                assert!(err <= 4.0 * f64::EPSILON, "{name}: {g} vs 256-bit difference {}", fd[i]);
            }
        }
    }

    #[test]
    fn a_wrong_rule_is_caught() {
        // The test above would fail if a rule were wrong: differentiate sin as +sin.
        let p = Program::parse("carvallo-ir 1\nmodel m\ninput x\nlet t0 = cos x\noutput f = t0\n")
            .expect("parses");
        let j = p.with_jacobian(&["x"]).expect("differentiates");
        let d = j.eval_f64(&[], &[0.3]).expect("evaluates")[1];
        assert_eq!(d, -(0.3f64.sin()));
    }

    #[test]
    fn bad_variables_are_errors_naming_them() {
        let p = program();
        let e = p.with_jacobian(&["w"]).unwrap_err().to_string();
        assert!(e.contains("\"w\"") && e.contains("neither an input nor a parameter"), "{e}");
        let e = p.with_jacobian(&["x", "x"]).unwrap_err().to_string();
        assert!(e.contains("\"x\" is named twice"), "{e}");
        let q = Program::parse(
            "carvallo-ir 1\nmodel m\ninput x\nlet t0 = sin x\noutput f = t0\noutput d_f__x = t0\n",
        )
        .expect("parses");
        let e = q.with_jacobian(&["x"]).unwrap_err().to_string();
        assert!(e.contains("\"d_f__x\" is already an output"), "{e}");
    }

    #[test]
    fn the_values_are_unchanged_and_ones_cost_nothing() {
        let p = Program::parse(
            "carvallo-ir 1\nmodel m\ninput x\ninput y\nlet t0 = add x y\noutput f = t0\n",
        )
        .expect("parses");
        let j = p.with_jacobian(&["x", "y"]).expect("differentiates");
        // f = x + y: both derivatives are the constant one, no other instruction.
        assert_eq!(j.op_count().total, 1, "{}", j.to_text());
        assert_eq!(j.eval_f64(&[], &[2.0, 3.0]).expect("evaluates"), vec![5.0, 1.0, 1.0]);
    }
}
