//! The printer of the IR text format described in the [crate docs](crate).
//!
//! The printed form is canonical: header comments first (`# text`, or `#` for an empty line),
//! then the version line, the model, parameters, inputs, instructions and outputs, one per line,
//! tokens separated by one space, every line ending in `\n`. Constants are printed with `{:?}`,
//! Rust's shortest representation that parses back to the same bits, so for a valid program
//! `Program::parse(&p.to_text()) == Ok(p)`, and printing a parsed printed text gives it back.

use std::fmt::{self, Write};

use crate::parse::VERSION_LINE;
use crate::{Op, Program, Value};

/// The name of `v`, or `?` if the index is out of range (only for invalid programs).
fn name(p: &Program, v: Value) -> &str {
    let s = match v {
        Value::Param(i) => p.params.get(i as usize),
        Value::Input(i) => p.inputs.get(i as usize),
        Value::Inst(i) => p.insts.get(i as usize).map(|x| &x.name),
    };
    s.map_or("?", |s| s.as_str())
}

pub(crate) fn write_program(p: &Program, f: &mut impl Write) -> fmt::Result {
    for h in &p.header {
        if h.is_empty() {
            f.write_str("#\n")?;
        } else {
            writeln!(f, "# {h}")?;
        }
    }
    writeln!(f, "{VERSION_LINE}")?;
    writeln!(f, "model {}", p.model)?;
    for x in &p.params {
        writeln!(f, "param {x}")?;
    }
    for x in &p.inputs {
        writeln!(f, "input {x}")?;
    }
    for inst in &p.insts {
        write!(f, "let {} = {}", inst.name, inst.op.mnemonic())?;
        match inst.op {
            Op::Const(c) => write!(f, " {c:?}")?,
            Op::Powi(a, k) => write!(f, " {} {k}", name(p, a))?,
            op => {
                for a in op.operands() {
                    write!(f, " {}", name(p, a))?;
                }
            }
        }
        f.write_char('\n')?;
    }
    for o in &p.outputs {
        writeln!(f, "output {} = {}", o.name, name(p, o.value))?;
    }
    Ok(())
}

impl fmt::Display for Program {
    /// The text form of the program (the same as [`Program::to_text`]).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_program(self, f)
    }
}
