//! The reference `f64` interpreter, the baseline generated code is compared and benchmarked
//! against.
//!
//! [`Interpreter::new`] compiles a [`Program`] once into a flat list of index-based operations
//! over one slot array: slots `0..P` hold the parameters, the next `I` slots the inputs and one
//! slot per instruction follows. [`Interpreter::eval`] then runs that list over a caller-provided
//! scratch slice and allocates nothing. Every operation is the plain `f64` operation of the same
//! name (`powi` is [`f64::powi`], `atan2 y x` is `y.atan2(x)`), so results are deterministic.

use crate::{IrError, Op, Program, Value};

/// One compiled operation; the destination slot is implicit (the next one).
#[derive(Clone, Copy, Debug)]
enum Code {
    Const(f64),
    Neg(u32),
    Add(u32, u32),
    Sub(u32, u32),
    Mul(u32, u32),
    Div(u32, u32),
    Powi(u32, i32),
    Sqrt(u32),
    Sin(u32),
    Cos(u32),
    Tan(u32),
    Atan2(u32, u32),
}

/// A program compiled for fast, allocation-free `f64` evaluation.
///
/// ```
/// use carvallo_ir::{Builder, Interpreter};
/// let mut b = Builder::new("demo");
/// let (r, x) = (b.param("R"), b.input("x"));
/// let y = b.mul(r, x);
/// b.output("y", y);
/// let p = b.finish();
/// let it = Interpreter::new(&p)?;
/// let mut scratch = vec![0.0; it.scratch_len()];
/// let mut out = [0.0];
/// it.eval(&[2.0], &[3.0], &mut scratch, &mut out)?;
/// assert_eq!(out, [6.0]);
/// # Ok::<(), carvallo_ir::IrError>(())
/// ```
#[derive(Clone, Debug)]
pub struct Interpreter {
    n_params: usize,
    n_inputs: usize,
    code: Vec<Code>,
    outputs: Vec<u32>,
}

impl Interpreter {
    /// Compiles `p`; fails with [`IrError::Invalid`] if `p` does not [`validate`](Program::validate).
    pub fn new(p: &Program) -> Result<Interpreter, IrError> {
        p.validate()?;
        let n_params = p.params.len();
        let n_inputs = p.inputs.len();
        if n_params + n_inputs + p.insts.len() > u32::MAX as usize {
            return Err(IrError::invalid("program too large for the interpreter"));
        }
        let slot = |v: Value| -> u32 {
            match v {
                Value::Param(i) => i,
                Value::Input(i) => n_params as u32 + i,
                Value::Inst(i) => (n_params + n_inputs) as u32 + i,
            }
        };
        let code = p
            .insts
            .iter()
            .map(|inst| match inst.op {
                Op::Const(c) => Code::Const(c),
                Op::Neg(a) => Code::Neg(slot(a)),
                Op::Add(a, b) => Code::Add(slot(a), slot(b)),
                Op::Sub(a, b) => Code::Sub(slot(a), slot(b)),
                Op::Mul(a, b) => Code::Mul(slot(a), slot(b)),
                Op::Div(a, b) => Code::Div(slot(a), slot(b)),
                Op::Powi(a, k) => Code::Powi(slot(a), k),
                Op::Sqrt(a) => Code::Sqrt(slot(a)),
                Op::Sin(a) => Code::Sin(slot(a)),
                Op::Cos(a) => Code::Cos(slot(a)),
                Op::Tan(a) => Code::Tan(slot(a)),
                Op::Atan2(a, b) => Code::Atan2(slot(a), slot(b)),
            })
            .collect();
        let outputs = p.outputs.iter().map(|o| slot(o.value)).collect();
        Ok(Interpreter { n_params, n_inputs, code, outputs })
    }

    /// The minimum length of the `scratch` slice [`eval`](Self::eval) needs.
    pub fn scratch_len(&self) -> usize {
        self.n_params + self.n_inputs + self.code.len()
    }

    /// The number of parameters the program takes.
    pub fn n_params(&self) -> usize {
        self.n_params
    }

    /// The number of inputs the program takes.
    pub fn n_inputs(&self) -> usize {
        self.n_inputs
    }

    /// The number of outputs the program returns.
    pub fn n_outputs(&self) -> usize {
        self.outputs.len()
    }

    /// Evaluates the program: `out[k]` receives output `k`. Fails with
    /// [`IrError::ArgumentCount`] if `params`, `inputs` or `out` do not have exactly the
    /// program's lengths or `scratch` is shorter than [`scratch_len`](Self::scratch_len).
    /// Allocates nothing.
    pub fn eval(
        &self,
        params: &[f64],
        inputs: &[f64],
        scratch: &mut [f64],
        out: &mut [f64],
    ) -> Result<(), IrError> {
        let check = |what, expected: usize, got: usize, exact: bool| {
            if got == expected || (!exact && got > expected) {
                Ok(())
            } else {
                Err(IrError::ArgumentCount { what, expected, got })
            }
        };
        check("parameters", self.n_params, params.len(), true)?;
        check("inputs", self.n_inputs, inputs.len(), true)?;
        check("outputs", self.outputs.len(), out.len(), true)?;
        check("scratch slots", self.scratch_len(), scratch.len(), false)?;
        let base = self.n_params + self.n_inputs;
        let s = &mut scratch[..base + self.code.len()];
        s[..self.n_params].copy_from_slice(params);
        s[self.n_params..base].copy_from_slice(inputs);
        for (k, code) in self.code.iter().enumerate() {
            // Operands always index earlier slots (checked by `validate` in `new`).
            let g = |i: u32| s[i as usize];
            let v = match *code {
                Code::Const(c) => c,
                Code::Neg(a) => -g(a),
                Code::Add(a, b) => g(a) + g(b),
                Code::Sub(a, b) => g(a) - g(b),
                Code::Mul(a, b) => g(a) * g(b),
                Code::Div(a, b) => g(a) / g(b),
                Code::Powi(a, n) => g(a).powi(n),
                Code::Sqrt(a) => g(a).sqrt(),
                Code::Sin(a) => g(a).sin(),
                Code::Cos(a) => g(a).cos(),
                Code::Tan(a) => g(a).tan(),
                Code::Atan2(a, b) => g(a).atan2(g(b)),
            };
            s[base + k] = v;
        }
        for (o, &i) in out.iter_mut().zip(&self.outputs) {
            *o = s[i as usize];
        }
        Ok(())
    }
}

impl Program {
    /// Evaluates the program in `f64` with the [`Interpreter`] (a convenience that compiles the
    /// program and allocates; build an [`Interpreter`] once for repeated evaluation).
    pub fn eval_f64(&self, params: &[f64], inputs: &[f64]) -> Result<Vec<f64>, IrError> {
        let it = Interpreter::new(self)?;
        let mut scratch = vec![0.0; it.scratch_len()];
        let mut out = vec![0.0; it.n_outputs()];
        it.eval(params, inputs, &mut scratch, &mut out)?;
        Ok(out)
    }
}
