//! A hash-consing builder for [`Program`]s.
//!
//! Every operation is looked up before it is appended, so a value computed twice is emitted once:
//! common-subexpression elimination happens by construction. Operands of the commutative
//! operations `add` and `mul` are put in a canonical order first, so $a + b$ and $b + a$ share
//! one instruction. Instruction names are generated (`c0, c1, ...` for constants, `t0, t1, ...`
//! for the rest) so that the printed program is a deterministic function of the call sequence.
//! A generated name never equals a parameter's or an input's: one that would is skipped, and an
//! instruction whose name a later parameter or input takes is renamed (values refer to
//! instructions by index, so only the printed label changes).

use std::collections::HashMap;

use crate::{Inst, Op, Output, Program, Value};

/// A hashable image of an [`Op`]: constants are compared by their bit pattern.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Const(u64),
    Unary(u8, Value),
    Binary(u8, Value, Value),
    Powi(Value, i32),
}

fn key(op: &Op) -> Key {
    match *op {
        Op::Const(c) => Key::Const(c.to_bits()),
        Op::Neg(a) => Key::Unary(0, a),
        Op::Sqrt(a) => Key::Unary(1, a),
        Op::Sin(a) => Key::Unary(2, a),
        Op::Cos(a) => Key::Unary(3, a),
        Op::Tan(a) => Key::Unary(4, a),
        Op::Add(a, b) => Key::Binary(0, a, b),
        Op::Sub(a, b) => Key::Binary(1, a, b),
        Op::Mul(a, b) => Key::Binary(2, a, b),
        Op::Div(a, b) => Key::Binary(3, a, b),
        Op::Atan2(a, b) => Key::Binary(4, a, b),
        Op::Powi(a, k) => Key::Powi(a, k),
    }
}

/// Builds a [`Program`] with common-subexpression elimination.
///
/// ```
/// use carvallo_ir::Builder;
/// let mut b = Builder::new("demo");
/// let r = b.param("R");
/// let x = b.input("x");
/// let s1 = b.sin(x);
/// let s2 = b.sin(x); // the same instruction
/// assert_eq!(s1, s2);
/// let y = b.mul(r, s1);
/// b.output("y", y);
/// let p = b.finish();
/// assert_eq!(p.insts.len(), 2);
/// ```
#[derive(Debug, Default)]
pub struct Builder {
    program: Program,
    seen: HashMap<KeyWrap, Value>,
    n_const: usize,
    n_temp: usize,
}

#[derive(Clone, Copy, PartialEq, Eq, Hash)]
struct KeyWrap(Key);

impl std::fmt::Debug for KeyWrap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Key")
    }
}

impl Builder {
    /// A builder for a program of the model `model`.
    pub fn new(model: &str) -> Self {
        Builder {
            program: Program { model: model.to_string(), ..Program::default() },
            ..Builder::default()
        }
    }

    /// Adds a header comment line (printed before the version line).
    pub fn header(&mut self, line: &str) -> &mut Self {
        self.program.header.push(line.to_string());
        self
    }

    /// Declares a parameter, or returns the existing one with that name.
    pub fn param(&mut self, name: &str) -> Value {
        if let Some(i) = self.program.params.iter().position(|p| p == name) {
            return Value::Param(i as u32);
        }
        self.program.params.push(name.to_string());
        self.free_name(name);
        Value::Param(self.program.params.len() as u32 - 1)
    }

    /// Declares an input, or returns the existing one with that name.
    pub fn input(&mut self, name: &str) -> Value {
        if let Some(i) = self.program.inputs.iter().position(|p| p == name) {
            return Value::Input(i as u32);
        }
        self.program.inputs.push(name.to_string());
        self.free_name(name);
        Value::Input(self.program.inputs.len() as u32 - 1)
    }

    /// Appends `op` unless an identical operation exists already; returns its value.
    pub fn push(&mut self, op: Op) -> Value {
        let op = match op {
            Op::Add(a, b) if b < a => Op::Add(b, a),
            Op::Mul(a, b) if b < a => Op::Mul(b, a),
            other => other,
        };
        let k = KeyWrap(key(&op));
        if let Some(&v) = self.seen.get(&k) {
            return v;
        }
        let name = self.fresh_name(matches!(op, Op::Const(_)));
        self.program.insts.push(Inst { name, op });
        let v = Value::Inst(self.program.insts.len() as u32 - 1);
        self.seen.insert(k, v);
        v
    }

    /// The next generated name (`c<n>` for a constant, `t<n>` otherwise) that no parameter or
    /// input uses.
    fn fresh_name(&mut self, constant: bool) -> String {
        loop {
            let name = if constant {
                self.n_const += 1;
                format!("c{}", self.n_const - 1)
            } else {
                self.n_temp += 1;
                format!("t{}", self.n_temp - 1)
            };
            let p = &self.program;
            if !p.params.iter().chain(&p.inputs).any(|n| *n == name) {
                return name;
            }
        }
    }

    /// Renames the instruction, if any, whose generated name a new parameter or input takes.
    fn free_name(&mut self, name: &str) {
        if let Some(i) = self.program.insts.iter().position(|inst| inst.name == name) {
            let constant = matches!(self.program.insts[i].op, Op::Const(_));
            self.program.insts[i].name = self.fresh_name(constant);
        }
    }

    /// A constant. Non-finite values are a programming error of the caller and panic.
    pub fn constant(&mut self, c: f64) -> Value {
        assert!(c.is_finite(), "non-finite constant {c} in IR builder");
        self.push(Op::Const(c))
    }
    /// $-a$.
    pub fn neg(&mut self, a: Value) -> Value {
        self.push(Op::Neg(a))
    }
    /// $a + b$.
    pub fn add(&mut self, a: Value, b: Value) -> Value {
        self.push(Op::Add(a, b))
    }
    /// $a - b$.
    pub fn sub(&mut self, a: Value, b: Value) -> Value {
        self.push(Op::Sub(a, b))
    }
    /// $a b$.
    pub fn mul(&mut self, a: Value, b: Value) -> Value {
        self.push(Op::Mul(a, b))
    }
    /// $a / b$.
    pub fn div(&mut self, a: Value, b: Value) -> Value {
        self.push(Op::Div(a, b))
    }
    /// $a^k$.
    pub fn powi(&mut self, a: Value, k: i32) -> Value {
        self.push(Op::Powi(a, k))
    }
    /// $\sqrt a$.
    pub fn sqrt(&mut self, a: Value) -> Value {
        self.push(Op::Sqrt(a))
    }
    /// $\sin a$.
    pub fn sin(&mut self, a: Value) -> Value {
        self.push(Op::Sin(a))
    }
    /// $\cos a$.
    pub fn cos(&mut self, a: Value) -> Value {
        self.push(Op::Cos(a))
    }
    /// $\tan a$.
    pub fn tan(&mut self, a: Value) -> Value {
        self.push(Op::Tan(a))
    }
    /// $\operatorname{atan2}(y, x)$.
    pub fn atan2(&mut self, y: Value, x: Value) -> Value {
        self.push(Op::Atan2(y, x))
    }

    /// Declares the output `name` returning `value`. Output names must be unique; a repeated
    /// name is a programming error of the caller and panics.
    pub fn output(&mut self, name: &str, value: Value) {
        assert!(self.program.output(name).is_none(), "output {name} declared twice in IR builder");
        self.program.outputs.push(Output { name: name.to_string(), value });
    }

    /// The finished program.
    pub fn finish(self) -> Program {
        self.program
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A parameter or input named like a generated instruction (`c1`, `t0`), declared before or
    /// after that instruction, gives a valid program whose evaluation is unchanged.
    #[test]
    fn generated_names_never_clash_with_parameters_or_inputs() {
        let mut b = Builder::new("clash");
        let x = b.input("x");
        let two = b.constant(2.0);
        let three = b.constant(3.0); // would be c1
        let c1 = b.param("c1"); // declared after the constant c1: the constant is renamed
        let t0 = b.input("t0"); // declared before any temporary: t0 is skipped
        let p = b.mul(two, x);
        let q = b.add(p, three);
        let r = b.mul(q, c1);
        let y = b.add(r, t0);
        b.output("y", y);
        let prog = b.finish();
        let text = prog.to_string();
        let back = Program::parse(&text).expect("printed program parses");
        back.validate().expect("valid");
        let names: Vec<&str> = prog.insts.iter().map(|i| i.name.as_str()).collect();
        assert!(!names.contains(&"c1") && !names.contains(&"t0"), "{names:?}");
        // y = (2 x + 3) c1 + t0 at x = 1.5, c1 = 0.5, t0 = 4: 3 + 4 = 7.
        let out = back.eval_f64(&[0.5], &[1.5, 4.0]).expect("evaluates");
        assert_eq!(out, vec![7.0]);
    }
}
