//! The symbolic checks recorded at regeneration (`generated/*.checks.tsv`, embedded by
//! [`carvallo::artifacts`]) turned into concordance entries.

use std::collections::BTreeMap;

pub use carvallo::artifacts::{parse_checks, SymbolicCheck};

use crate::entry::{Derived, Entry, Memoir, Verdict};

/// The symbolic checks of one model's `checks.tsv` (text `tsv`, file `generated/{file}`) as
/// report entries, one per check, named `{label} check {id}`. A check listed in `findings`
/// (id, verdict, reason) is expected not to hold and takes that verdict when it does not; any
/// other check agrees when it holds. The check's detail is cut to `detail_chars` characters.
/// A file that cannot be read gives a single `derivation-differs` entry saying why.
pub(crate) fn check_entries(
    tsv: &str,
    file: &str,
    label: &str,
    findings: &[(&str, Verdict, &str)],
    detail_chars: usize,
) -> Vec<Entry> {
    let checks = match parse_checks(tsv) {
        Ok(c) => c,
        Err(message) => {
            return vec![Entry {
                section: "-".into(),
                quantity: format!("{label} symbolic checks"),
                memoir: Memoir::Formula(format!("generated/{file}")),
                derived: Derived::Numbers(BTreeMap::new()),
                rel_diff: None,
                verdict: Verdict::DerivationDiffers,
                note: format!("cannot read generated/{file}: {message}"),
            }]
        }
    };
    checks
        .into_iter()
        .map(|c| {
            let finding = findings.iter().find(|(id, _, _)| *id == c.id);
            let detail: String = c.detail.chars().take(detail_chars).collect();
            let (verdict, why) = match finding {
                Some((_, v, why)) if !c.holds => (*v, format!("; {why}")),
                Some(_) => (Verdict::DerivationDiffers, "; expected not to hold".to_string()),
                None if c.holds => (Verdict::Agrees, String::new()),
                None => (Verdict::DerivationDiffers, String::new()),
            };
            Entry {
                section: c.section.clone(),
                quantity: format!("{label} check {}", c.id),
                memoir: Memoir::Formula(c.statement.clone()),
                derived: Derived::Numbers(BTreeMap::from([(
                    "holds".to_string(),
                    if c.holds { 1.0 } else { 0.0 },
                )])),
                rel_diff: None,
                verdict,
                note: format!(
                    "symbolic check at regen: {} ({detail}){why}",
                    if c.holds { "holds" } else { "does not hold" }
                ),
            }
        })
        .collect()
}
