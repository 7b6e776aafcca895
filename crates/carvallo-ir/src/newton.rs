//! One Newton step on an input, fused with the program that is then evaluated at the corrected
//! input: [`Program::with_newton_step`].
//!
//! A right-hand side that keeps a coordinate $x$ on a constraint $h(x, \dots) = 0$ evaluates
//! $h$ and $h_x = \partial h/\partial x$ at the integrated $x$, steps to
//! $x^* = x - \varepsilon$ with $\varepsilon = h/h_x$, and evaluates its equations at $x^*$.
//! Done as two programs, the trigonometry of every other input (and everything computed from
//! the other inputs alone) is evaluated twice, and $\sin x^*$, $\cos x^*$ are two more calls.
//! The fused program evaluates each value that does not depend on $x$ once (the
//! hash-consing [`Builder`] shares it between the step and the rest), and takes
//! $\sin x^*$ and $\cos x^*$ from $\sin x$ and $\cos x$ (which the step computed) by the
//! angle-addition formulas
//! $$\sin x^* = \sin x \cos\varepsilon - \cos x \sin\varepsilon, \qquad
//!   \cos x^* = \cos x \cos\varepsilon + \sin x \sin\varepsilon,$$
//! with $\cos\varepsilon \approx 1 - \varepsilon^2/2$ and
//! $\sin\varepsilon \approx \varepsilon\,(1 - \varepsilon^2/6)$. Their truncation errors are
//! below $\varepsilon^4/24$ and $|\varepsilon|\,\varepsilon^4/120$: for
//! $|\varepsilon| \le 10^{-4}$ at most $4.2 \cdot 10^{-18}$ absolute and $8.4 \cdot 10^{-19}$
//! relative, under a twentieth of the rounding unit $2^{-53} \approx 1.1 \cdot 10^{-16}$, so in
//! that range $\sin x^*$ and $\cos x^*$ are exact to the rounding of the few operations that
//! form them (a couple of units in the last place, like `sin` itself). The step is an output,
//! so the caller can check it is in range and take another route when it is not.

use crate::{Builder, IrError, Op, Program, Value};

/// The output name of the step $\varepsilon = h/h_x$ of [`Program::with_newton_step`] on the
/// input `input`: `INPUT_newton_step`.
///
/// ```
/// assert_eq!(carvallo_ir::newton::step_name("theta"), "theta_newton_step");
/// ```
pub fn step_name(input: &str) -> String {
    format!("{input}_newton_step")
}

/// The output name of the corrected input $x^* = x - \varepsilon$ of
/// [`Program::with_newton_step`] on the input `input`: `INPUT_newton`.
///
/// ```
/// assert_eq!(carvallo_ir::newton::corrected_name("theta"), "theta_newton");
/// ```
pub fn corrected_name(input: &str) -> String {
    format!("{input}_newton")
}

/// The largest step $|\varepsilon|$ for which [`Program::with_newton_step`]'s $\sin x^*$ and
/// $\cos x^*$ are exact to rounding (see the [module docs](self)).
pub const EXACT_STEP: f64 = 1e-4;

impl Program {
    /// This program evaluated after one Newton step on the input `input` for the root of the
    /// output `residual`, whose derivative with respect to `input` is the output
    /// `derivative`: every output is computed at $x^* = x - h/h_x$ (with $h$ and $h_x$ those
    /// outputs at the given $x$), and two outputs are appended, the step
    /// [`step_name`]`(input)` $= h/h_x$ and the corrected input [`corrected_name`]`(input)`
    /// $= x^*$. The inputs and parameters are those of this program, in the same order.
    ///
    /// `sin input` and `cos input` are computed at $x^*$ by the angle-addition formulas from
    /// their values at $x$ (see the [module docs](self): exact to rounding while
    /// $|h/h_x| \le$ [`EXACT_STEP`]); any other use of the input takes $x^*$ itself. That
    /// `derivative` is $\partial h/\partial x$ is the caller's statement: the program cannot
    /// check it.
    ///
    /// Fails with [`IrError::Invalid`] for an invalid program, an `input` that is not an
    /// input, or a step or corrected name that is already an output; with
    /// [`IrError::UnknownOutput`] for a `residual` or `derivative` that is not an output.
    ///
    /// ```
    /// use carvallo_ir::Program;
    /// // h(x) = sin x - 0.5 with h' = cos x: one step from x = 0.5236 towards pi/6
    /// // (a step of 1.2e-6).
    /// let p = Program::parse("carvallo-ir 1\nmodel m\ninput x\nlet s = sin x\nlet c = cos x\n\
    ///     let half = const 0.5\nlet h = sub s half\noutput h = h\noutput dh = c\noutput s = s\n")?;
    /// let n = p.with_newton_step("x", "h", "dh")?;
    /// let names: Vec<&str> = n.outputs.iter().map(|o| o.name.as_str()).collect();
    /// assert_eq!(names, ["h", "dh", "s", "x_newton_step", "x_newton"]);
    /// let out = n.eval_f64(&[], &[0.5236])?;
    /// let x = 0.5236 - (0.5236f64.sin() - 0.5) / 0.5236f64.cos();
    /// assert_eq!(out[4], x);
    /// assert!((out[2] - x.sin()).abs() <= 2e-16);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_newton_step(
        &self,
        input: &str,
        residual: &str,
        derivative: &str,
    ) -> Result<Program, IrError> {
        self.validate()?;
        let Some(x) = self.inputs.iter().position(|n| n == input) else {
            return Err(IrError::invalid(format!(
                "{input:?} is not an input of model {:?}",
                self.model
            )));
        };
        let x = Value::Input(x as u32);
        let output_value = |name: &str| {
            self.output(name)
                .map(|o| o.value)
                .ok_or_else(|| IrError::UnknownOutput { name: name.to_string() })
        };
        let (h, dh) = (output_value(residual)?, output_value(derivative)?);
        for name in [step_name(input), corrected_name(input)] {
            if self.output(&name).is_some() {
                return Err(IrError::invalid(format!(
                    "{name:?} is already an output of model {:?}",
                    self.model
                )));
            }
        }

        let mut b = Builder::new(&self.model);
        for line in &self.header {
            b.header(line);
        }
        let params: Vec<Value> = self.params.iter().map(|n| b.param(n)).collect();
        let inputs: Vec<Value> = self.inputs.iter().map(|n| b.input(n)).collect();
        let arg = |v: Value| match v {
            Value::Param(i) => params[i as usize],
            Value::Input(i) => inputs[i as usize],
            Value::Inst(_) => unreachable!("only arguments are mapped here"),
        };

        // The step's part: the instructions h and h_x need, at x.
        let mut needed = vec![false; self.insts.len()];
        for v in [h, dh] {
            if let Value::Inst(i) = v {
                needed[i as usize] = true;
            }
        }
        for i in (0..self.insts.len()).rev() {
            if needed[i] {
                for v in self.insts[i].op.operands() {
                    if let Value::Inst(j) = v {
                        needed[j as usize] = true;
                    }
                }
            }
        }
        let mut at_x: Vec<Option<Value>> = vec![None; self.insts.len()];
        for (i, inst) in self.insts.iter().enumerate() {
            if needed[i] {
                let op = inst.op.map_operands(|v| match v {
                    Value::Inst(j) => at_x[j as usize].expect("operands come first"),
                    other => arg(other),
                });
                at_x[i] = Some(b.push(op));
            }
        }
        let value_at_x = |v: Value| match v {
            Value::Inst(i) => at_x[i as usize].expect("h and h_x were computed"),
            other => arg(other),
        };
        let (vh, vdh) = (value_at_x(h), value_at_x(dh));
        let step = b.div(vh, vdh);
        let xv = arg(x);
        let corrected = b.sub(xv, step);

        // sin x* and cos x* by angle addition (module docs), built only when used.
        let mut trig: Option<(Value, Value)> = None;
        let mut trig_at_corrected = |b: &mut Builder| {
            *trig.get_or_insert_with(|| {
                let (s, c) = (b.sin(xv), b.cos(xv));
                let e2 = b.mul(step, step);
                let half = b.constant(0.5);
                let sixth = b.constant(1.0 / 6.0);
                let one = b.constant(1.0);
                let h2 = b.mul(half, e2);
                let cos_e = b.sub(one, h2);
                let e6 = b.mul(sixth, e2);
                let f = b.sub(one, e6);
                let sin_e = b.mul(step, f);
                let (sc, cs) = (b.mul(s, cos_e), b.mul(c, sin_e));
                let sin_x = b.sub(sc, cs);
                let (cc, ss) = (b.mul(c, cos_e), b.mul(s, sin_e));
                let cos_x = b.add(cc, ss);
                (sin_x, cos_x)
            })
        };

        // The whole program at x*: what does not depend on x is shared with the step's part
        // by the builder's hash-consing.
        let mut at_star: Vec<Value> = Vec::with_capacity(self.insts.len());
        for inst in &self.insts {
            let value = match inst.op {
                Op::Sin(v) if v == x => trig_at_corrected(&mut b).0,
                Op::Cos(v) if v == x => trig_at_corrected(&mut b).1,
                op => b.push(op.map_operands(|v| match v {
                    Value::Inst(j) => at_star[j as usize],
                    v if v == x => corrected,
                    other => arg(other),
                })),
            };
            at_star.push(value);
        }
        for o in &self.outputs {
            let v = match o.value {
                Value::Inst(i) => at_star[i as usize],
                v if v == x => corrected,
                other => arg(other),
            };
            b.output(&o.name, v);
        }
        b.output(&step_name(input), step);
        b.output(&corrected_name(input), corrected);
        let out = b.finish().fold_constants().eliminate_dead_code();
        debug_assert!(out.validate().is_ok());
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hp;

    /// A constraint in the style of a contact height, $h = r\cos\varphi\,(\sin\theta +
    /// \cos\theta\cos\delta) - 1$, its derivative, and outputs that use the constrained input
    /// through its sine and cosine, directly and not at all.
    fn program() -> Program {
        Program::parse(
            "carvallo-ir 1\nmodel m\nparam r\ninput phi\ninput theta\ninput delta\n\
             let sp = sin phi\nlet cp = cos phi\nlet st = sin theta\nlet ct = cos theta\n\
             let cd = cos delta\nlet sd = sin delta\nlet a = mul ct cd\nlet s1 = add st a\n\
             let rc = mul r cp\nlet g = mul rc s1\nlet one = const 1.0\nlet h = sub g one\n\
             let b = mul st cd\nlet d1 = sub ct b\nlet dh = mul rc d1\n\
             let f1 = mul sp st\nlet f2 = mul f1 sd\nlet f3 = add theta sp\nlet f4 = tan f3\n\
             output h = h\noutput dh = dh\noutput f = f2\noutput k = f4\noutput m = cp\n",
        )
        .expect("parses")
    }

    /// The fused program against the original evaluated at the corrected input, in 256 bits:
    /// the outputs to a few units in the last place, the step and the corrected input exactly
    /// as one Newton step of the original's own outputs computes them in `f64`.
    #[test]
    fn the_fused_program_is_the_original_at_the_corrected_input() {
        let p = program();
        let n = p.with_newton_step("theta", "h", "dh").expect("fuses");
        let r = 1.2;
        // A few units in the last place of each output, relative to its size or to one (the
        // residual is zero at the root); the angle addition's rounding and the outputs' own.
        let tol = 1e-15;
        for (k, offset) in [0.0, 1e-12, -3e-9, 2e-7, -1e-5].into_iter().enumerate() {
            let (phi, delta) = (0.1 + 0.05 * k as f64, -0.2 + 0.03 * k as f64);
            // The root of h in theta near 1.0, then the integrated theta off it by `offset`.
            let mut th: f64 = 1.0;
            for _ in 0..60 {
                let o = p.eval_f64(&[r], &[phi, th, delta]).expect("evaluates");
                th -= o[0] / o[1];
            }
            let theta = th + offset;
            let before = p.eval_f64(&[r], &[phi, theta, delta]).expect("evaluates");
            let step = before[0] / before[1];
            let fused = n.eval_f64(&[r], &[phi, theta, delta]).expect("evaluates");
            assert_eq!(fused[5], step, "the step");
            assert_eq!(fused[6], theta - step, "the corrected input");
            let exact =
                hp::eval_f64(&p, &[r], &[phi, theta - step, delta], 256).expect("evaluates");
            for (i, (got, want)) in fused[..5].iter().zip(&exact).enumerate() {
                let err = (got - want).abs() / want.abs().max(1.0);
                assert!(err <= tol, "output {i} at offset {offset}: {got} vs {want} ({err:.1e})");
            }
            // The correction matters: at theta itself the outputs are off by about the step.
            if offset.abs() >= 1e-9 {
                let off = (before[2] - exact[2]).abs() / exact[2].abs();
                assert!(off > 1e3 * tol, "offset {offset}: {off:.1e}");
            }
        }
    }

    /// Values that do not depend on the input are computed once, and the corrected input has
    /// no sine or cosine of its own: the fused program calls as many trigonometric functions
    /// as the original alone.
    #[test]
    fn what_does_not_depend_on_the_input_is_computed_once() {
        let p = program();
        let n = p.with_newton_step("theta", "h", "dh").expect("fuses");
        let trig = |q: &Program| {
            q.insts.iter().filter(|i| matches!(i.op, Op::Sin(_) | Op::Cos(_) | Op::Tan(_))).count()
        };
        // sin/cos of phi, theta, delta once each, and the tan of the direct use.
        assert_eq!(trig(&p), 7);
        assert_eq!(trig(&n), 7);
    }

    #[test]
    fn bad_names_are_errors_naming_them() {
        let p = program();
        let err = p.with_newton_step("r", "h", "dh").unwrap_err();
        assert_eq!(err.to_string(), "invalid program: \"r\" is not an input of model \"m\"");
        let err = p.with_newton_step("theta", "height", "dh").unwrap_err();
        assert_eq!(err, IrError::UnknownOutput { name: "height".into() });
        let n = p.with_newton_step("theta", "h", "dh").expect("fuses");
        let err = n.with_newton_step("theta", "h", "dh").unwrap_err();
        assert_eq!(
            err.to_string(),
            "invalid program: \"theta_newton_step\" is already an output of model \"m\""
        );
    }
}
