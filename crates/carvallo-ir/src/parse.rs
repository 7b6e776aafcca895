//! The parser of the IR text format described in the [crate docs](crate).
//!
//! Parsing is a single pass over the lines. Every line is split into tokens (runs of characters
//! other than space and tab, up to a `#` comment), and each statement is checked as it is read:
//! names, the order of the sections, single definition before use (SSA), operation arities and
//! numbers. The first problem found is returned as a [`ParseError`] with the 1-based line and
//! column (in characters) of the offending token; the parser never panics, whatever the input.
//!
//! Header lines are the comment lines that start in column 1 before the version line; the
//! header text is what follows the `#` and at most one space. Other comments are dropped.

use std::collections::HashMap;

use crate::{Inst, Op, Output, ParseError, Program, Value};

/// The version line every program starts with.
pub(crate) const VERSION_LINE: &str = "carvallo-ir 1";

/// Whether `s` matches `[A-Za-z_][A-Za-z0-9_]*`.
pub fn is_valid_name(s: &str) -> bool {
    let mut chars = s.chars();
    match chars.next() {
        Some(c) if c.is_ascii_alphabetic() || c == '_' => {}
        _ => return false,
    }
    chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// One token of a line with its 1-based column.
#[derive(Clone, Copy, Debug)]
struct Token<'a> {
    text: &'a str,
    column: usize,
}

/// The tokens of one line (comment removed) and the column just past its last character.
struct Line<'a> {
    number: usize,
    tokens: Vec<Token<'a>>,
    end_column: usize,
}

fn split_line(number: usize, line: &str) -> Line<'_> {
    let mut tokens = Vec::new();
    let mut start: Option<(usize, usize)> = None; // (byte, column)
    let mut column = 0;
    let mut end = line.len();
    for (byte, c) in line.char_indices() {
        column += 1;
        if c == '#' {
            end = byte;
            break;
        }
        if c == ' ' || c == '\t' {
            if let Some((b, col)) = start.take() {
                tokens.push(Token { text: &line[b..byte], column: col });
            }
        } else if start.is_none() {
            start = Some((byte, column));
        }
    }
    if let Some((b, col)) = start {
        tokens.push(Token { text: &line[b..end], column: col });
    }
    let end_column = line[..end].chars().count() + 1;
    Line { number, tokens, end_column }
}

/// Which section of the program the parser is in; sections only move forward.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Debug)]
enum Section {
    Version,
    Model,
    Params,
    Inputs,
    Lets,
    Outputs,
}

struct Parser<'a> {
    program: Program,
    names: HashMap<&'a str, Value>,
    output_names: HashMap<&'a str, ()>,
    section: Section,
}

fn err(line: usize, column: usize, message: String) -> ParseError {
    ParseError { line, column, message }
}

impl<'a> Parser<'a> {
    fn at(line: &Line<'_>, t: &Token<'_>, message: String) -> ParseError {
        err(line.number, t.column, message)
    }

    /// The token at `i`, or an error at the end of the line saying what was expected.
    fn token(line: &Line<'a>, i: usize, expected: &str) -> Result<Token<'a>, ParseError> {
        line.tokens.get(i).copied().ok_or_else(|| {
            err(line.number, line.end_column, format!("expected {expected} at the end of the line"))
        })
    }

    fn no_trailing(line: &Line<'a>, n: usize) -> Result<(), ParseError> {
        match line.tokens.get(n) {
            Some(t) => Err(Self::at(line, t, format!("unexpected trailing token {:?}", t.text))),
            None => Ok(()),
        }
    }

    fn name(line: &Line<'a>, i: usize, what: &str) -> Result<Token<'a>, ParseError> {
        let t = Self::token(line, i, what)?;
        if is_valid_name(t.text) {
            Ok(t)
        } else {
            Err(Self::at(line, &t, format!("invalid name {:?}", t.text)))
        }
    }

    fn define(&mut self, line: &Line<'a>, t: Token<'a>, v: Value) -> Result<(), ParseError> {
        if self.names.insert(t.text, v).is_some() {
            return Err(Self::at(line, &t, format!("redefinition of {:?}", t.text)));
        }
        Ok(())
    }

    fn operand(&self, line: &Line<'a>, t: &Token<'a>) -> Result<Value, ParseError> {
        if !is_valid_name(t.text) {
            return Err(Self::at(line, t, format!("invalid name {:?}", t.text)));
        }
        self.names
            .get(t.text)
            .copied()
            .ok_or_else(|| Self::at(line, t, format!("use of undefined value {:?}", t.text)))
    }

    fn enter(
        &mut self,
        line: &Line<'a>,
        kw: &Token<'a>,
        section: Section,
    ) -> Result<(), ParseError> {
        if self.section > section {
            let later = match self.section {
                Section::Inputs => "input",
                Section::Lets => "let",
                _ => "output",
            };
            return Err(Self::at(
                line,
                kw,
                format!(
                    "{:?} line after {later:?} lines (order is param, input, let, output)",
                    kw.text
                ),
            ));
        }
        self.section = section;
        Ok(())
    }

    fn statement(&mut self, line: &Line<'a>) -> Result<(), ParseError> {
        let kw = line.tokens[0];
        match self.section {
            Section::Version => {
                if kw.text != "carvallo-ir" {
                    return Err(Self::at(
                        line,
                        &kw,
                        format!("expected the version line `{VERSION_LINE}`, found {:?}", kw.text),
                    ));
                }
                let v = Self::token(line, 1, "the format version")?;
                if v.text != "1" {
                    return Err(Self::at(
                        line,
                        &v,
                        format!("unsupported format version {:?}", v.text),
                    ));
                }
                Self::no_trailing(line, 2)?;
                self.section = Section::Model;
                return Ok(());
            }
            Section::Model => {
                if kw.text != "model" {
                    return Err(Self::at(
                        line,
                        &kw,
                        format!("expected the model line `model NAME`, found {:?}", kw.text),
                    ));
                }
                let name = Self::name(line, 1, "the model name")?;
                Self::no_trailing(line, 2)?;
                self.program.model = name.text.to_string();
                self.section = Section::Params;
                return Ok(());
            }
            _ => {}
        }
        match kw.text {
            "carvallo-ir" => Err(Self::at(line, &kw, "duplicate version line".to_string())),
            "model" => Err(Self::at(line, &kw, "duplicate model line".to_string())),
            "param" | "input" => {
                let (section, what) = if kw.text == "param" {
                    (Section::Params, "a parameter name")
                } else {
                    (Section::Inputs, "an input name")
                };
                self.enter(line, &kw, section)?;
                let name = Self::name(line, 1, what)?;
                Self::no_trailing(line, 2)?;
                let v = if section == Section::Params {
                    self.program.params.push(name.text.to_string());
                    Value::Param(self.program.params.len() as u32 - 1)
                } else {
                    self.program.inputs.push(name.text.to_string());
                    Value::Input(self.program.inputs.len() as u32 - 1)
                };
                self.define(line, name, v)
            }
            "let" => {
                self.enter(line, &kw, Section::Lets)?;
                let name = Self::name(line, 1, "a value name")?;
                self.equals(line, 2)?;
                let op = self.op(line, 3)?;
                if self.program.insts.len() >= u32::MAX as usize {
                    return Err(Self::at(line, &kw, "too many instructions".to_string()));
                }
                self.program.insts.push(Inst { name: name.text.to_string(), op });
                let v = Value::Inst(self.program.insts.len() as u32 - 1);
                self.define(line, name, v)
            }
            "output" => {
                self.enter(line, &kw, Section::Outputs)?;
                let name = Self::name(line, 1, "an output name")?;
                if self.output_names.insert(name.text, ()).is_some() {
                    return Err(Self::at(line, &name, format!("duplicate output {:?}", name.text)));
                }
                self.equals(line, 2)?;
                let t = Self::token(line, 3, "a value name")?;
                let value = self.operand(line, &t)?;
                Self::no_trailing(line, 4)?;
                self.program.outputs.push(Output { name: name.text.to_string(), value });
                Ok(())
            }
            other => Err(Self::at(line, &kw, format!("unknown statement {other:?}"))),
        }
    }

    fn equals(&self, line: &Line<'a>, i: usize) -> Result<(), ParseError> {
        let t = Self::token(line, i, "`=`")?;
        if t.text != "=" {
            return Err(Self::at(line, &t, format!("expected `=`, found {:?}", t.text)));
        }
        Ok(())
    }

    /// Parses `OP ARGS...` starting at token `i`, up to the end of the line.
    fn op(&self, line: &Line<'a>, i: usize) -> Result<Op, ParseError> {
        let t = Self::token(line, i, "an operation")?;
        let arity = match t.text {
            "const" | "neg" | "sqrt" | "sin" | "cos" | "tan" => 1,
            "add" | "sub" | "mul" | "div" | "atan2" | "powi" => 2,
            other => return Err(Self::at(line, &t, format!("unknown operation {other:?}"))),
        };
        let args = &line.tokens[i + 1..];
        if args.len() != arity {
            let plural = if arity == 1 { "" } else { "s" };
            return Err(Self::at(
                line,
                &t,
                format!(
                    "operation {} takes {arity} argument{plural}, found {}",
                    t.text,
                    args.len()
                ),
            ));
        }
        if t.text == "const" {
            let a = &args[0];
            let c: f64 = a
                .text
                .parse()
                .map_err(|_| Self::at(line, a, format!("invalid number {:?}", a.text)))?;
            if !c.is_finite() {
                return Err(Self::at(line, a, format!("non-finite constant {:?}", a.text)));
            }
            return Ok(Op::Const(c));
        }
        let a = self.operand(line, &args[0])?;
        Ok(match t.text {
            "neg" => Op::Neg(a),
            "sqrt" => Op::Sqrt(a),
            "sin" => Op::Sin(a),
            "cos" => Op::Cos(a),
            "tan" => Op::Tan(a),
            "powi" => {
                let k = &args[1];
                let n: i32 = k
                    .text
                    .parse()
                    .map_err(|_| Self::at(line, k, format!("invalid i32 exponent {:?}", k.text)))?;
                Op::Powi(a, n)
            }
            _ => {
                let b = self.operand(line, &args[1])?;
                match t.text {
                    "add" => Op::Add(a, b),
                    "sub" => Op::Sub(a, b),
                    "mul" => Op::Mul(a, b),
                    "div" => Op::Div(a, b),
                    _ => Op::Atan2(a, b),
                }
            }
        })
    }
}

/// Parses a program from its text form; see the [crate docs](crate) for the format.
pub(crate) fn parse(text: &str) -> Result<Program, ParseError> {
    let mut p = Parser {
        program: Program::default(),
        names: HashMap::new(),
        output_names: HashMap::new(),
        section: Section::Version,
    };
    let mut last = (1, 1);
    for (i, raw) in text.split('\n').enumerate() {
        let line = split_line(i + 1, raw);
        last = (i + 1, raw.chars().count() + 1);
        if line.tokens.is_empty() {
            if p.section == Section::Version {
                if let Some(rest) = raw.trim_start_matches([' ', '\t']).strip_prefix('#') {
                    if raw.starts_with('#') {
                        let text = rest.strip_prefix(' ').unwrap_or(rest);
                        p.program.header.push(text.to_string());
                    }
                }
            }
            continue;
        }
        p.statement(&line)?;
    }
    match p.section {
        Section::Version => {
            Err(err(last.0, last.1, format!("missing version line `{VERSION_LINE}`")))
        }
        Section::Model => Err(err(last.0, last.1, "missing model line `model NAME`".to_string())),
        _ => Ok(p.program),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names() {
        for ok in ["a", "_", "_x1", "theta", "A_b_9"] {
            assert!(is_valid_name(ok), "{ok}");
        }
        for bad in ["", "1a", "a-b", "é", "a b", "a.b", "-"] {
            assert!(!is_valid_name(bad), "{bad}");
        }
    }

    #[test]
    fn columns_count_characters() {
        let l = split_line(1, "éé\tab  c # d");
        let cols: Vec<(usize, &str)> = l.tokens.iter().map(|t| (t.column, t.text)).collect();
        assert_eq!(cols, [(1, "éé"), (4, "ab"), (8, "c")]);
        assert_eq!(l.end_column, 10);
    }
}
