//! The concordance as an aligned plain-text table (`carvallo report`).

use std::fmt::Write as _;

use crate::entry::{Derived, Entry, Memoir};
use crate::render::normalise::normalise_numbers;
/// The number format shared by every renderer (defined in [`super::number`]).
pub use crate::render::number::format_significant;

/// Widest memoir cell of the text table; longer formulas are cut with `...` (the JSON keeps
/// them whole).
pub const MEMOIR_CELL_CHARS: usize = 64;

fn memoir_cell(m: &Memoir) -> String {
    match m {
        Memoir::Number(x) => format_significant(*x, 10),
        Memoir::Formula(text) if text.chars().count() > MEMOIR_CELL_CHARS => {
            let cut: String = text.chars().take(MEMOIR_CELL_CHARS - 3).collect();
            format!("{cut}...")
        }
        Memoir::Formula(text) => text.clone(),
    }
}

fn derived_cell(d: &Derived) -> String {
    match d {
        Derived::Number(x) => format_significant(*x, 10),
        Derived::Numbers(map) => map
            .iter()
            .map(|(k, v)| format!("{k}={}", format_significant(*v, 10)))
            .collect::<Vec<_>>()
            .join(", "),
    }
}

fn rel_diff_cell(r: Option<f64>) -> String {
    match r {
        Some(x) => format!("{x:.1e}"),
        None => "-".to_string(),
    }
}

/// Renders the entries as an aligned plain-text table (columns n°, quantity, memoir, derived,
/// relative difference, verdict), each row followed by its note on an indented line.
pub fn render_text(entries: &[Entry]) -> String {
    render_text_with(entries, &|cell| cell)
}

/// [`render_text`] with every number to 4 significant digits ([`normalise_numbers`] applied to
/// each cell and note before the columns are laid out, so the padding does not depend on the
/// digits dropped): the form the snapshot tests compare.
pub fn render_text_normalised(entries: &[Entry]) -> String {
    render_text_with(entries, &|cell| normalise_numbers(&cell))
}

fn render_text_with(entries: &[Entry], cell: &dyn Fn(String) -> String) -> String {
    let header = ["n°", "quantity", "memoir", "derived", "rel. diff", "verdict"];
    let rows: Vec<[String; 6]> = entries
        .iter()
        .map(|e| {
            [
                e.section.clone(),
                e.quantity.clone(),
                memoir_cell(&e.memoir),
                derived_cell(&e.derived),
                rel_diff_cell(e.rel_diff),
                e.verdict.as_str().to_string(),
            ]
            .map(cell)
        })
        .collect();
    let mut widths = header.map(|h| h.chars().count());
    for row in &rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let mut out = String::new();
    let line = |cells: &[String], out: &mut String| {
        let mut text = String::new();
        for (i, (cell, w)) in cells.iter().zip(widths).enumerate() {
            if i > 0 {
                text.push_str("  ");
            }
            text.push_str(cell);
            let pad = w - cell.chars().count();
            text.extend(std::iter::repeat_n(' ', pad));
        }
        out.push_str(text.trim_end());
        out.push('\n');
    };
    line(&header.map(str::to_string), &mut out);
    let rule: Vec<String> = widths.iter().map(|w| "-".repeat(*w)).collect();
    line(&rule, &mut out);
    for (row, entry) in rows.iter().zip(entries) {
        line(row, &mut out);
        if !entry.note.is_empty() {
            let _ = writeln!(out, "    {}", cell(entry.note.clone()));
        }
    }
    out
}
