//! Operation counts of a program, the cost measure reported next to benchmarks.
//!
//! Every instruction except `const` counts as one operation, whatever it costs on real
//! hardware; [`OpCount::by_op`] breaks the total down by mnemonic so that expensive
//! operations (`sqrt`, `sin`, `atan2`, ...) can be weighed separately.

use std::collections::BTreeMap;
use std::fmt;

use crate::{Op, Program};

/// How many operations a program performs (constants are not counted).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct OpCount {
    /// The number of non-constant instructions.
    pub total: usize,
    /// The same count per mnemonic (`add`, `mul`, ...); mnemonics that do not occur are absent.
    pub by_op: BTreeMap<&'static str, usize>,
}

impl fmt::Display for OpCount {
    /// `12 ops (add 3, mul 7, sin 2)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ops (", self.total)?;
        for (i, (k, n)) in self.by_op.iter().enumerate() {
            if i > 0 {
                f.write_str(", ")?;
            }
            write!(f, "{k} {n}")?;
        }
        f.write_str(")")
    }
}

impl Program {
    /// Counts the instructions of the program by operation, constants excluded.
    ///
    /// ```
    /// use carvallo_ir::Program;
    /// let p = Program::parse("carvallo-ir 1\nmodel m\ninput x\nlet c = const 2.0\n\
    ///     let a = mul c x\nlet b = mul a x\nlet s = sin b\noutput y = s\n")?;
    /// let n = p.op_count();
    /// assert_eq!(n.total, 3);
    /// assert_eq!(n.by_op["mul"], 2);
    /// assert_eq!(n.to_string(), "3 ops (mul 2, sin 1)");
    /// # Ok::<(), carvallo_ir::ParseError>(())
    /// ```
    pub fn op_count(&self) -> OpCount {
        let mut c = OpCount::default();
        for inst in &self.insts {
            if let Op::Const(_) = inst.op {
                continue;
            }
            c.total += 1;
            *c.by_op.entry(inst.op.mnemonic()).or_insert(0) += 1;
        }
        c
    }
}
