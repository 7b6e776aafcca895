//! Error types of the IR crate.
//!
//! [`ParseError`] is returned by the text parser and carries the 1-based line and column of the
//! offending token; [`IrError`] is returned by validation, the transformations and the
//! interpreters. Both implement [`std::error::Error`] and print lower-case messages that name the
//! offending value, without a trailing period.

use std::fmt;

/// A malformed IR text: where (1-based line and column, counted in characters) and what.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseError {
    /// 1-based line number.
    pub line: usize,
    /// 1-based column, counted in Unicode scalar values (characters), of the offending token.
    pub column: usize,
    /// What is wrong, lower-case, naming the offending token.
    pub message: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}, column {}: {}", self.line, self.column, self.message)
    }
}

impl std::error::Error for ParseError {}

/// An error of validation, transformation or evaluation of a [`Program`](crate::Program).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum IrError {
    /// A parameter name that the program does not declare.
    UnknownParam {
        /// The unknown name.
        name: String,
    },
    /// An output name that the program does not declare.
    UnknownOutput {
        /// The unknown name.
        name: String,
    },
    /// A slice of the wrong length was passed (`what` is `"parameters"`, `"inputs"`,
    /// `"outputs"` or `"scratch slots"`; for scratch, `expected` is the minimum length).
    ArgumentCount {
        /// Which argument has the wrong length.
        what: &'static str,
        /// The length the program needs.
        expected: usize,
        /// The length that was passed.
        got: usize,
    },
    /// The program violates an invariant of the IR (see [`Program::validate`](crate::Program::validate)),
    /// or a request cannot be carried out.
    Invalid {
        /// What is wrong, lower-case, naming the offending value.
        message: String,
    },
}

impl fmt::Display for IrError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IrError::UnknownParam { name } => write!(f, "unknown parameter {name:?}"),
            IrError::UnknownOutput { name } => write!(f, "unknown output {name:?}"),
            IrError::ArgumentCount { what, expected, got } => {
                write!(f, "wrong number of {what}: expected {expected}, got {got}")
            }
            IrError::Invalid { message } => write!(f, "invalid program: {message}"),
        }
    }
}

impl std::error::Error for IrError {}

impl IrError {
    pub(crate) fn invalid(message: impl Into<String>) -> Self {
        IrError::Invalid { message: message.into() }
    }
}
