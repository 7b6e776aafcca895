//! `generated/<model>.md`: every formula with its memoir section, description, plain-text and
//! LaTeX forms and op counts; and the normalisation every rendered file goes through.

use std::collections::BTreeMap;

use crate::Derivation;

use super::expr::Expr;
use super::latex::latex;
use super::text::text;
use super::{count_ops, emit_program, formula_op_count, generated_header, in_formula, EmitError};

pub(super) fn one_line(s: &str) -> String {
    let s: String =
        s.chars().map(|c| if c == '\t' || c == '\n' || c == '\r' { ' ' } else { c }).collect();
    s.trim().to_string()
}

/// Normalises a rendered file: LF line ends, no trailing spaces (tabs are kept: they separate
/// possibly empty TSV fields), exactly one final newline.
pub fn normalize_text(s: &str) -> String {
    let s = s.replace("\r\n", "\n").replace('\r', "\n");
    let mut out: String = s.lines().map(|l| l.trim_end_matches(' ')).collect::<Vec<_>>().join("\n");
    let trimmed = out.trim_end_matches('\n').len();
    out.truncate(trimmed);
    out.push('\n');
    out
}

/// Longest plain-text rendering of a formula that `generated/<model>.md` prints (with its
/// LaTeX form); longer formulas are listed with their op count only, to keep the file small.
pub const MAX_RENDERED_CHARS: usize = 16_000;

/// `generated/<model>.md`: every formula with its memoir section, description, plain-text and
/// LaTeX forms and op count after common-subexpression elimination.
pub fn render_markdown(d: &Derivation) -> Result<String, EmitError> {
    let mut s = String::new();
    s.push_str(&format!("<!-- {} -->\n\n", generated_header(&d.source)));
    s.push_str(&format!("# Model `{}`\n\n", d.model));
    s.push_str(&format!("Parameters: {}.\n\n", code_list(&d.params)));
    s.push_str(&format!("Inputs: {}.\n\n", code_list(&d.inputs)));
    let program = emit_program(d)?;
    let (total, by_op) = count_ops(&program);
    s.push_str(&format!(
        "{} formulas; the whole program (`{}.ir`, all outputs sharing common subexpressions) takes {} ops ({}).\n\n",
        d.formulas.len(),
        d.model,
        total,
        by_op_text(&by_op)
    ));
    s.push_str("Op counts are the non-constant IR instructions of each formula compiled on its own after common-subexpression elimination.\n\n");
    s.push_str("| output | n° | ops |\n|---|---|---|\n");
    let mut rows = Vec::new();
    for f in &d.formulas {
        let (ops, by) = formula_op_count(d, f)?;
        s.push_str(&format!("| `{}` | {} | {} |\n", f.name, one_line(&f.section), ops));
        rows.push((f, ops, by));
    }
    for (f, ops, by) in rows {
        let e = Expr::from_atom(&f.expr).map_err(in_formula(f))?;
        s.push_str(&format!("\n## `{}` (n° {})\n\n", f.name, one_line(&f.section)));
        s.push_str(&format!("{}\n\n", one_line(&f.description)));
        let plain = text(&e);
        if plain.len() > MAX_RENDERED_CHARS {
            s.push_str(&format!(
                "Not rendered: its plain text takes {} characters (more than {MAX_RENDERED_CHARS}); the formula is in `{}.ir`.\n\n",
                plain.len(),
                d.model
            ));
        } else {
            s.push_str(&format!("```text\n{plain}\n```\n\n"));
            s.push_str(&format!("$$\n{}\n$$\n\n", latex(&e)));
        }
        s.push_str(&format!("Ops after CSE: {} ({}).\n", ops, by_op_text(&by)));
    }
    Ok(normalize_text(&s))
}

pub(super) fn code_list(names: &[String]) -> String {
    if names.is_empty() {
        return "none".to_string();
    }
    names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
}

pub(super) fn by_op_text(by_op: &BTreeMap<&'static str, usize>) -> String {
    if by_op.is_empty() {
        return "none".to_string();
    }
    by_op.iter().map(|(k, v)| format!("{v} {k}")).collect::<Vec<_>>().join(", ")
}
