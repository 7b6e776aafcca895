//! `generated/<model>.checks.tsv`: the symbolic checks of a derivation, one per line.

use crate::{Check, Derivation};

use super::generated_header;
use super::markdown::{normalize_text, one_line};

/// `generated/<model>.checks.tsv`: `#` header lines, then one line per check:
/// `section<TAB>id<TAB>holds<TAB>statement<TAB>detail<TAB>perturbation<TAB>perturbed_holds`,
/// tabs and newlines inside the text replaced by spaces; the last two are empty and `-` when
/// the check states no perturbation ([`crate::falsify`]).
pub fn render_checks(d: &Derivation) -> String {
    let mut s = String::new();
    s.push_str(&format!("# {}\n", generated_header(&d.source)));
    s.push_str(&format!("# Symbolic checks of model {}, in the order they were made.\n", d.model));
    s.push_str(
        "# Columns: section<TAB>id<TAB>holds<TAB>statement<TAB>detail<TAB>perturbation<TAB>perturbed_holds (holds is true or false; perturbed_holds is true, false or - when no perturbation is stated).\n",
    );
    for c in &d.checks {
        s.push_str(&check_line(c));
        s.push('\n');
    }
    normalize_text(&s)
}

pub(super) fn check_line(c: &Check) -> String {
    let (what, holds) = match &c.perturbed {
        Some(p) => (one_line(&p.what), p.holds.to_string()),
        None => (String::new(), "-".to_string()),
    };
    format!(
        "{}\t{}\t{}\t{}\t{}\t{what}\t{holds}",
        one_line(&c.section),
        one_line(&c.id),
        c.holds,
        one_line(&c.statement),
        one_line(&c.detail)
    )
}
