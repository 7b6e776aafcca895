//! The symbolic checks recorded at regeneration (`generated/*.checks.tsv`, embedded by
//! [`carvallo::artifacts`]) turned into concordance entries.

use std::collections::BTreeMap;

pub use carvallo::artifacts::{parse_checks, SymbolicCheck};

use crate::entry::{Derived, Entry, Memoir, Verdict};
use crate::policy::{self, Expect};

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
                verdict: policy::finding(Verdict::DerivationDiffers),
                note: format!("cannot read generated/{file}: {message}"),
            }]
        }
    };
    checks
        .into_iter()
        .map(|c| {
            let finding = findings.iter().find(|(id, _, _)| *id == c.id);
            let detail: String = c.detail.chars().take(detail_chars).collect();
            let why = match finding {
                Some((_, _, why)) if !c.holds => format!("; {why}"),
                Some(_) => "; expected not to hold".to_string(),
                None => String::new(),
            };
            let expect = finding.map_or(Expect::Holds, |(_, v, _)| Expect::Finding(*v));
            let verdict = policy::check(c.holds, expect);
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
