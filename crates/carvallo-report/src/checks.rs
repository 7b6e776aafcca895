//! The symbolic checks recorded at regeneration (`generated/*.checks.tsv`, embedded by
//! [`carvallo::artifacts`]) turned into concordance entries.

use std::collections::BTreeMap;

pub use carvallo::artifacts::{parse_checks, SymbolicCheck};

use crate::entry::{Derived, Entry, Falsification, Memoir, Verdict};
use crate::policy::{self, Expect};

/// A symbolic check whose outcome is not simply "holds": the check's id, what is expected of it
/// ([`Expect`]) and why. Every model report lists its findings in this one shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Finding {
    /// The check's id in `generated/<model>.checks.tsv`.
    pub check: &'static str,
    /// What the check is expected to show.
    pub expect: Expect,
    /// The reason, quoted in the entry's note.
    pub why: &'static str,
}

impl Finding {
    /// A check that records a finding: expected not to hold, and then of verdict `verdict`
    /// (`memoir-error`, `ocr`, or `rounding` for an approximation the memoir declares).
    pub const fn new(check: &'static str, verdict: Verdict, why: &'static str) -> Self {
        Finding { check, expect: Expect::Finding(verdict), why }
    }

    /// A check that fails because the memoir itself says the statement does not hold.
    pub const fn fails_as_the_memoir_says(check: &'static str, why: &'static str) -> Self {
        Finding { check, expect: Expect::FailsAsTheMemoirSays, why }
    }
}

/// The finding of check `id` in `findings`, if it is listed.
pub fn find<'a>(findings: &'a [Finding], id: &str) -> Option<&'a Finding> {
    findings.iter().find(|f| f.check == id)
}

/// What is expected of check `id`: its finding's expectation, or [`Expect::Holds`].
pub fn expect(findings: &[Finding], id: &str) -> Expect {
    find(findings, id).map_or(Expect::Holds, |f| f.expect)
}

/// The falsification of symbolic check `c` (issue 38): the check was run again at
/// regeneration with its derived side perturbed (`codegen/src/falsify.rs`); the verdict is the
/// one [`policy::check`] gives that outcome against what is expected of the check. `None` when
/// the check states no perturbation.
pub fn falsification(c: &SymbolicCheck, expect: Expect) -> Option<Falsification> {
    let (what, holds) = c.perturbed.as_ref()?;
    Some(Falsification {
        perturbation: format!("{what} (the symbolic check run again at regeneration)"),
        verdict: policy::check(*holds, expect),
        evidence: BTreeMap::from([("holds".to_string(), if *holds { 1.0 } else { 0.0 })]),
    })
}

/// The symbolic checks of one model's `checks.tsv` (text `tsv`, file `generated/{file}`) as
/// report entries, one per check, named `{label} check {id}`, judged by [`policy::check`]
/// against the check's [`Finding`] (a check not listed must hold). The check's detail is cut to `detail_chars` characters.
/// A file that cannot be read gives a single `derivation-differs` entry saying why.
pub(crate) fn check_entries(
    tsv: &str,
    file: &str,
    label: &str,
    findings: &[Finding],
    detail_chars: usize,
) -> Vec<Entry> {
    let checks = match parse_checks(tsv) {
        Ok(c) => c,
        Err(message) => {
            return vec![Entry {
                falsification: None,
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
            let finding = find(findings, &c.id);
            let detail: String = c.detail.chars().take(detail_chars).collect();
            let why = match finding {
                Some(f) if !c.holds => format!("; {}", f.why),
                Some(_) => "; expected not to hold".to_string(),
                None => String::new(),
            };
            let verdict = policy::check(c.holds, expect(findings, &c.id));
            Entry {
                falsification: falsification(&c, expect(findings, &c.id)),
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
