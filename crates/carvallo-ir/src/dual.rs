//! Forward-mode automatic differentiation of a program: every value carries its `N` partial
//! derivatives beside it ([`Dual`]), and [`eval`] runs the program on such values.
//!
//! The derivatives are those of the `f64` operations the [`Interpreter`](crate::Interpreter)
//! performs, propagated by the chain rule operation by operation, so they are exact to rounding
//! (no step size, unlike finite differences). The rules: $(a \pm b)' = a' \pm b'$,
//! $(ab)' = a'b + ab'$, $(a/b)' = (a' - (a/b) b')/b$, $(a^k)' = k a^{k-1} a'$,
//! $(\sqrt a)' = a'/(2\sqrt a)$, $(\sin a)' = a' \cos a$, $(\cos a)' = -a' \sin a$,
//! $(\tan a)' = a'(1 + \tan^2 a)$ and
//! $\operatorname{atan2}(y, x)' = (x y' - y x')/(x^2 + y^2)$. The values are bit for bit those
//! of the interpreter.
//!
//! ```
//! use carvallo_ir::dual::{self, Dual};
//! use carvallo_ir::Program;
//! let p = Program::parse("carvallo-ir 1\nmodel m\nparam R\ninput x\nlet t0 = sin x\nlet t1 = mul R t0\noutput y = t1\n")?;
//! // d/dR and d/dx of R sin x at R = 2, x = 0.5.
//! let y = dual::eval(&p, &[Dual::<2>::variable(2.0, 0)], &[Dual::variable(0.5, 1)])?;
//! assert_eq!(y[0].value, 2.0 * 0.5f64.sin());
//! assert_eq!(y[0].grad, [0.5f64.sin(), 2.0 * 0.5f64.cos()]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::ops::{Add, Div, Mul, Neg, Sub};

use crate::{IrError, Op, Program, Value};

/// A value and its partial derivatives with respect to `N` variables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dual<const N: usize> {
    /// The value.
    pub value: f64,
    /// $\partial(\text{value})/\partial x_i$ for the `N` variables $x_i$.
    pub grad: [f64; N],
}

impl<const N: usize> Dual<N> {
    /// A constant: every derivative zero.
    pub fn constant(value: f64) -> Dual<N> {
        Dual { value, grad: [0.0; N] }
    }

    /// The variable number `i` (its own derivative one, the others zero); an `i` of `N` or more
    /// gives a constant.
    pub fn variable(value: f64, i: usize) -> Dual<N> {
        let mut grad = [0.0; N];
        if let Some(g) = grad.get_mut(i) {
            *g = 1.0;
        }
        Dual { value, grad }
    }

    /// `self` times the number `k` (value and derivatives).
    pub fn scale(self, k: f64) -> Dual<N> {
        Dual { value: self.value * k, grad: self.grad.map(|g| g * k) }
    }

    /// The chain rule for a function of one argument with value `f` and derivative `df` at
    /// `self.value`.
    fn chain(self, f: f64, df: f64) -> Dual<N> {
        Dual { value: f, grad: self.grad.map(|g| g * df) }
    }

    /// $a^k$ for an integer $k$.
    pub fn powi(self, k: i32) -> Dual<N> {
        let df = if k == 0 { 0.0 } else { f64::from(k) * self.value.powi(k - 1) };
        self.chain(self.value.powi(k), df)
    }

    /// $\sqrt a$.
    pub fn sqrt(self) -> Dual<N> {
        let s = self.value.sqrt();
        self.chain(s, 0.5 / s)
    }

    /// $\sin a$.
    pub fn sin(self) -> Dual<N> {
        self.chain(self.value.sin(), self.value.cos())
    }

    /// $\cos a$.
    pub fn cos(self) -> Dual<N> {
        self.chain(self.value.cos(), -self.value.sin())
    }

    /// $\tan a$.
    pub fn tan(self) -> Dual<N> {
        let t = self.value.tan();
        self.chain(t, 1.0 + t * t)
    }

    /// $\operatorname{atan2}(y, x)$ with `self` as $y$.
    pub fn atan2(self, x: Dual<N>) -> Dual<N> {
        let r2 = x.value * x.value + self.value * self.value;
        let mut grad = [0.0; N];
        for (k, g) in grad.iter_mut().enumerate() {
            *g = (x.value * self.grad[k] - self.value * x.grad[k]) / r2;
        }
        Dual { value: self.value.atan2(x.value), grad }
    }
}

impl<const N: usize> From<f64> for Dual<N> {
    fn from(value: f64) -> Dual<N> {
        Dual::constant(value)
    }
}

impl<const N: usize> Neg for Dual<N> {
    type Output = Dual<N>;
    fn neg(self) -> Dual<N> {
        Dual { value: -self.value, grad: self.grad.map(|g| -g) }
    }
}

impl<const N: usize> Add for Dual<N> {
    type Output = Dual<N>;
    fn add(self, b: Dual<N>) -> Dual<N> {
        Dual {
            value: self.value + b.value,
            grad: std::array::from_fn(|k| self.grad[k] + b.grad[k]),
        }
    }
}

impl<const N: usize> Sub for Dual<N> {
    type Output = Dual<N>;
    fn sub(self, b: Dual<N>) -> Dual<N> {
        Dual {
            value: self.value - b.value,
            grad: std::array::from_fn(|k| self.grad[k] - b.grad[k]),
        }
    }
}

#[allow(clippy::suspicious_arithmetic_impl)] // The product rule adds.
impl<const N: usize> Mul for Dual<N> {
    type Output = Dual<N>;
    fn mul(self, b: Dual<N>) -> Dual<N> {
        Dual {
            value: self.value * b.value,
            grad: std::array::from_fn(|k| self.grad[k] * b.value + self.value * b.grad[k]),
        }
    }
}

#[allow(clippy::suspicious_arithmetic_impl)] // The quotient rule subtracts and multiplies.
impl<const N: usize> Div for Dual<N> {
    type Output = Dual<N>;
    fn div(self, b: Dual<N>) -> Dual<N> {
        let q = self.value / b.value;
        Dual { value: q, grad: std::array::from_fn(|k| (self.grad[k] - q * b.grad[k]) / b.value) }
    }
}

/// Evaluates `p` on dual numbers: one result per output, each with its derivatives with respect
/// to whatever variables the arguments were seeded with ([`Dual::variable`]).
///
/// Fails with [`IrError::Invalid`] if `p` does not validate and with
/// [`IrError::ArgumentCount`] if `params` or `inputs` do not have the program's lengths.
pub fn eval<const N: usize>(
    p: &Program,
    params: &[Dual<N>],
    inputs: &[Dual<N>],
) -> Result<Vec<Dual<N>>, IrError> {
    p.validate()?;
    for (what, expected, got) in
        [("parameters", p.params.len(), params.len()), ("inputs", p.inputs.len(), inputs.len())]
    {
        if expected != got {
            return Err(IrError::ArgumentCount { what, expected, got });
        }
    }
    let mut slots: Vec<Dual<N>> = Vec::with_capacity(p.insts.len());
    let get = |slots: &[Dual<N>], v: Value| match v {
        Value::Param(i) => params[i as usize],
        Value::Input(i) => inputs[i as usize],
        Value::Inst(i) => slots[i as usize],
    };
    for inst in &p.insts {
        let g = |v| get(&slots, v);
        let x = match inst.op {
            Op::Const(c) => Dual::constant(c),
            Op::Neg(a) => -g(a),
            Op::Add(a, b) => g(a) + g(b),
            Op::Sub(a, b) => g(a) - g(b),
            Op::Mul(a, b) => g(a) * g(b),
            Op::Div(a, b) => g(a) / g(b),
            Op::Powi(a, k) => g(a).powi(k),
            Op::Sqrt(a) => g(a).sqrt(),
            Op::Sin(a) => g(a).sin(),
            Op::Cos(a) => g(a).cos(),
            Op::Tan(a) => g(a).tan(),
            Op::Atan2(a, b) => g(a).atan2(g(b)),
        };
        slots.push(x);
    }
    Ok(p.outputs.iter().map(|o| get(&slots, o.value)).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every operation's derivative against a central difference (step 1e-6, relative
    /// agreement 1e-9: the difference's rounding, eps |f| / h with |f| of order one, is about
    /// 1e-10, its truncation h^2 |f'''| / 6 far less; measured 8.5e-11) and its value against
    /// the interpreter's, bit for bit.
    #[test]
    fn every_operation_matches_central_differences_and_the_interpreter() {
        let text = "carvallo-ir 1\nmodel m\nparam a\ninput x\n\
            let c = const 1.5\nlet t0 = mul a x\nlet t1 = div t0 c\nlet t2 = sub t1 x\n\
            let t3 = neg t2\nlet t4 = powi t3 3\nlet t5 = powi x -2\nlet t6 = sqrt a\n\
            let t7 = sin t0\nlet t8 = cos t6\nlet t9 = tan t5\nlet t10 = atan2 t7 t8\n\
            let t11 = add t4 t9\nlet t12 = add t11 t10\n\
            output y = t12\noutput z = t8\n";
        let p = Program::parse(text).expect("valid program");
        let (a, x) = (0.7, 1.3);
        let d = eval(&p, &[Dual::<2>::variable(a, 0)], &[Dual::variable(x, 1)]).expect("eval");
        let plain = p.eval_f64(&[a], &[x]).expect("eval_f64");
        let h = 1e-6;
        for (k, out) in d.iter().enumerate() {
            assert_eq!(out.value, plain[k]);
            let da = (p.eval_f64(&[a + h], &[x]).expect("eval")[k]
                - p.eval_f64(&[a - h], &[x]).expect("eval")[k])
                / (2.0 * h);
            let dx = (p.eval_f64(&[a], &[x + h]).expect("eval")[k]
                - p.eval_f64(&[a], &[x - h]).expect("eval")[k])
                / (2.0 * h);
            for (got, want) in [(out.grad[0], da), (out.grad[1], dx)] {
                assert!((got - want).abs() <= 1e-9 * want.abs().max(1.0), "{got} vs {want}");
            }
        }
    }

    #[test]
    fn wrong_argument_counts_are_errors() {
        let p = Program::parse("carvallo-ir 1\nmodel m\nparam a\noutput y = a\n").expect("valid");
        let err = eval::<1>(&p, &[], &[]).unwrap_err();
        assert_eq!(err, IrError::ArgumentCount { what: "parameters", expected: 1, got: 0 });
    }
}
