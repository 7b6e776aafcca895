//! The memoir concordance: every formula and number the memoir prints about the hoop, set
//! beside the value this workspace derives for it, with a verdict.
//!
//! Nothing here is a stored result. [`hoop_entries`] evaluates the generated evaluators (the
//! scenes of [`crate::hoop`], built at compile time from `generated/hoop.ir`) when it runs:
//! each derived formula is compared with the memoir's printed formula, transcribed by hand in the
//! same IR program as a `memoir_*` output, at a fixed seeded set of sample points; the numbers
//! of n° 4 and the straight-rolling stability threshold of n° 14/18 are recomputed from the
//! generated evaluators; and the symbolic checks recorded by `cargo xtask regen` in
//! `generated/hoop.checks.tsv` are folded in.
//!
//! # Comparing two formulas
//! At every sample point the relative difference is
//! $$\delta = \frac{|d - m|}{\max(|d|, |m|, \varepsilon)}$$
//! with $d$ the derived value, $m$ the memoir's, and the floor $\varepsilon$ given by
//! [`REL_DIFF_FLOOR`] (in the unit of the quantity) so that values that are both near zero
//! do not turn rounding noise into a large ratio. The entry reports the maximum over the
//! points; it *agrees* when that maximum is at most [`AGREEMENT_TOLERANCE`].

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::{Deserialize, Serialize};

/// Largest relative difference (see the module docs) for which a derived formula and the
/// memoir's printed formula are said to agree: a few hundred units in the last place, the
/// rounding of two different but equal algebraic forms evaluated in `f64`.
pub const AGREEMENT_TOLERANCE: f64 = 1e-12;

/// The floor $\varepsilon$ of the relative difference (module docs), in the unit of the
/// compared quantity.
pub const REL_DIFF_FLOOR: f64 = 1e-9;

/// How a derived value compares with what the memoir prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    /// Equal within [`AGREEMENT_TOLERANCE`] (formulas) or exactly as printed (numbers).
    Agrees,
    /// The memoir's number is the derived one rounded (Carvallo used a slide rule, n° 14).
    Rounding,
    /// The memoir's own arithmetic or algebra is wrong, and the derivation shows where.
    MemoirError,
    /// The printed text is an OCR misreading of what the memoir means.
    Ocr,
    /// The derivation gives something else and the cause is not (yet) attributed.
    DerivationDiffers,
}

impl Verdict {
    /// The verdict as it is serialised (`agrees`, `rounding`, `memoir-error`, `ocr`,
    /// `derivation-differs`).
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Agrees => "agrees",
            Verdict::Rounding => "rounding",
            Verdict::MemoirError => "memoir-error",
            Verdict::Ocr => "ocr",
            Verdict::DerivationDiffers => "derivation-differs",
        }
    }
}

/// What the memoir prints: a number or a formula (as text).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Memoir {
    /// A printed number.
    Number(f64),
    /// A printed formula, transcribed as plain text.
    Formula(String),
}

/// What the workspace derives: one number or several named ones.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Derived {
    /// One number.
    Number(f64),
    /// Several named numbers (for example the largest difference and the number of points).
    Numbers(BTreeMap<String, f64>),
}

/// One line of the concordance.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    /// Memoir section number as printed in its table of contents (`"8"`, `"14/18"`).
    pub section: String,
    /// What is compared, in a few words.
    pub quantity: String,
    /// What the memoir prints.
    pub memoir: Memoir,
    /// What the workspace computes when the report runs.
    pub derived: Derived,
    /// The relative difference between the two, when it is meaningful.
    pub rel_diff: Option<f64>,
    /// The verdict.
    pub verdict: Verdict,
    /// Where a difference comes from, how the value was obtained, or the symbolic checks of the
    /// same section.
    pub note: String,
}

/// Formats `x` with `digits` significant digits, without trailing zeros: plain decimal for
/// magnitudes in $[10^{-4}, 10^{\min(6, \text{digits})})$, scientific otherwise.
pub fn format_significant(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let digits = digits.max(1);
    let sci = format!("{:.*e}", digits - 1, x);
    let (mantissa, exponent) = sci.split_once('e').unwrap_or((sci.as_str(), "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    if exponent >= -4 && exponent < (digits as i32).min(6) {
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        trim_zeros(&format!("{:.*}", decimals, x))
    } else {
        format!("{}e{}", trim_zeros(mantissa), exponent)
    }
}

fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

fn memoir_cell(m: &Memoir) -> String {
    match m {
        Memoir::Number(x) => format_significant(*x, 10),
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
            let _ = writeln!(out, "    {}", entry.note);
        }
    }
    out
}

/// The entries as a pretty-printed JSON array of objects with the keys `section`, `quantity`,
/// `memoir`, `derived`, `rel_diff`, `verdict`, `note`.
pub fn render_json(entries: &[Entry]) -> String {
    // Serialising plain data with string keys cannot fail.
    serde_json::to_string_pretty(entries).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Vec<Entry> {
        vec![
            Entry {
                section: "4".into(),
                quantity: "A / (mu R^2)".into(),
                memoir: Memoir::Number(1.5),
                derived: Derived::Number(1.5),
                rel_diff: Some(0.0),
                verdict: Verdict::Agrees,
                note: "coefficient of mu R^2".into(),
            },
            Entry {
                section: "14".into(),
                quantity: "x".into(),
                memoir: Memoir::Formula("n^2 + 1".into()),
                derived: Derived::Numbers(BTreeMap::from([("points".into(), 64.0)])),
                rel_diff: None,
                verdict: Verdict::MemoirError,
                note: String::new(),
            },
        ]
    }

    #[test]
    fn significant_digits() {
        assert_eq!(format_significant(1.5, 10), "1.5");
        assert_eq!(format_significant(0.24999999999999997, 10), "0.25");
        assert_eq!(format_significant(-123456.0, 3), "-1.23e5");
        assert_eq!(format_significant(2.5e-7, 4), "2.5e-7");
        assert_eq!(format_significant(0.0, 4), "0");
    }

    #[test]
    fn verdicts_serialise_as_kebab_case() {
        let all = [
            Verdict::Agrees,
            Verdict::Rounding,
            Verdict::MemoirError,
            Verdict::Ocr,
            Verdict::DerivationDiffers,
        ];
        for v in all {
            assert_eq!(serde_json::to_value(v).unwrap(), serde_json::json!(v.as_str()));
        }
    }

    #[test]
    fn json_has_the_seven_keys() {
        let json: serde_json::Value = serde_json::from_str(&render_json(&sample())).unwrap();
        let first = json.as_array().unwrap()[0].as_object().unwrap();
        let keys: Vec<&str> = first.keys().map(String::as_str).collect();
        let mut expected =
            vec!["section", "quantity", "memoir", "derived", "rel_diff", "verdict", "note"];
        expected.sort_unstable();
        assert_eq!(keys, expected);
        assert_eq!(first["memoir"], serde_json::json!(1.5));
        assert_eq!(json[1]["rel_diff"], serde_json::Value::Null);
        assert_eq!(json[1]["derived"]["points"], serde_json::json!(64.0));
    }

    #[test]
    fn text_table_is_aligned() {
        let text = render_text(&sample());
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines[0].starts_with("n°  quantity"));
        let col = lines[0].chars().count() - "verdict".len();
        let row: Vec<char> = lines[2].chars().collect();
        assert_eq!((row[col - 1], row[col]), (' ', 'a'));
        assert!(lines[2].contains("agrees") && lines[3] == "    coefficient of mu R^2");
        assert!(lines[4].ends_with("memoir-error"));
    }
}
