//! The memoir's claims — its conclusions, not its numbers: every assertion found n° by n°
//! ([`Assertion`], each model's `INVENTORY`), and for each one this workspace checks a
//! [`Claim`] saying how it was checked (a derivation, a computation or a simulation with its
//! tolerance) and the verdict of the one policy ([`crate::policy::claim`]).
//!
//! An assertion is either checked by a claim of its own ([`Status::Checked`], by the claim's
//! id), checked by a value entry of the concordance that already decides it
//! ([`Status::Value`], naming the entry's quantity), or left with the reason it is not checked
//! ([`Status::Left`]). The registry test asserts that every id and every named entry exists,
//! and that every claim is in an inventory.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::{Deserialize, Serialize};

pub use crate::entry::Falsification;
use crate::entry::Verdict;
use crate::render::text::format_significant;

/// One claim of the memoir and how it was checked.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Claim {
    /// A stable identifier (`hoop-turns-toward-lean`), cited by the inventory.
    pub id: String,
    /// The memoir's n° (`"12"`, `"26 bis"`).
    pub section: String,
    /// What the memoir asserts, in a sentence (with the memoir's words where they matter).
    pub claim: String,
    /// How this workspace checks it: the derivation, computation or simulation, where, and
    /// with which tolerance.
    pub how: String,
    /// The numbers the check produced (a margin, a largest difference, a count of cases).
    pub evidence: BTreeMap<String, f64>,
    /// The verdict ([`crate::policy::claim`]): `agrees` when the check shows the claim.
    pub verdict: Verdict,
    /// The reading under which the claim holds, where it fails, or what the numbers mean.
    pub note: String,
    /// The perturbation of the derived side that must break the check, and the verdict the
    /// same check gives on the perturbed input (`None` when no perturbation is stated yet).
    pub falsification: Option<Falsification>,
}

impl Claim {
    /// A claim with the evidence given as `(name, value)` pairs.
    pub fn new(
        id: &str,
        section: &str,
        claim: &str,
        how: &str,
        evidence: &[(&str, f64)],
        verdict: Verdict,
        note: &str,
    ) -> Claim {
        Claim {
            id: id.to_string(),
            section: section.to_string(),
            claim: claim.to_string(),
            how: how.to_string(),
            evidence: evidence.iter().map(|(k, v)| (k.to_string(), *v)).collect(),
            verdict,
            note: note.to_string(),
            falsification: None,
        }
    }

    /// The claim with the outcome of its check on a perturbed derived side: `perturbation`
    /// says what was changed, `perturbed` is the claim the same check gives on that input
    /// (its verdict and evidence are kept).
    pub fn falsified_by(mut self, perturbation: &str, perturbed: Claim) -> Claim {
        self.falsification = Some(Falsification {
            perturbation: perturbation.to_string(),
            verdict: perturbed.verdict,
            evidence: perturbed.evidence,
        });
        self
    }

    /// The evidence as text: `name = value` pairs with 6 significant digits.
    pub fn evidence_text(&self) -> String {
        let pairs: Vec<String> = self
            .evidence
            .iter()
            .map(|(k, v)| format!("{k} = {}", format_significant(*v, 6)))
            .collect();
        pairs.join(", ")
    }
}

/// The claims `compute` gives, computed once per process in `cell` (the simulations take a
/// while) and sorted by section in memoir order (a stable sort).
pub(crate) fn once_in_memoir_order(
    cell: &'static std::sync::OnceLock<Vec<Claim>>,
    compute: fn() -> Vec<Claim>,
) -> Vec<Claim> {
    cell.get_or_init(|| {
        let mut claims = compute();
        claims.sort_by(|a, b| {
            crate::entry::section_key(&a.section).total_cmp(&crate::entry::section_key(&b.section))
        });
        claims
    })
    .clone()
}

/// How an assertion of the memoir is covered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Checked by the claim with this id.
    Checked(&'static str),
    /// Decided by the value entry of the same n° whose quantity contains this text.
    Value(&'static str),
    /// Not checked, and why.
    Left(&'static str),
}

/// One assertion found in the memoir.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Assertion {
    /// The memoir's n°.
    pub section: &'static str,
    /// What it asserts, in a few words.
    pub says: &'static str,
    /// How it is covered.
    pub status: Status,
}

/// The counts of an inventory: assertions found, checked by a claim, decided by a value
/// entry, left.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Assertions found.
    pub found: usize,
    /// Checked by a claim of their own.
    pub checked: usize,
    /// Decided by a value entry.
    pub by_value: usize,
    /// Left, with a reason.
    pub left: usize,
}

/// Counts `assertions` by status.
pub fn counts(assertions: &[Assertion]) -> Counts {
    let mut c = Counts { found: assertions.len(), ..Counts::default() };
    for a in assertions {
        match a.status {
            Status::Checked(_) => c.checked += 1,
            Status::Value(_) => c.by_value += 1,
            Status::Left(_) => c.left += 1,
        }
    }
    c
}

/// The claims as an aligned plain-text list (`carvallo report --claims`, the snapshots): one
/// block per claim with its n°, verdict, id, the claim, how it was checked, the evidence and
/// the note.
pub fn render_claims_text(claims: &[Claim]) -> String {
    let mut out = String::new();
    for c in claims {
        let _ = writeln!(out, "n° {} [{}] {}", c.section, c.verdict.as_str(), c.id);
        let _ = writeln!(out, "  claim:    {}", c.claim);
        let _ = writeln!(out, "  how:      {}", c.how);
        if !c.evidence.is_empty() {
            let _ = writeln!(out, "  evidence: {}", c.evidence_text());
        }
        if !c.note.is_empty() {
            let _ = writeln!(out, "  note:     {}", c.note);
        }
        if let Some(f) = &c.falsification {
            let outcome = if f.breaks(c.verdict) { "breaks it" } else { "does not break it" };
            let _ = writeln!(
                out,
                "  falsify:  {} -> [{}], {outcome}",
                f.perturbation,
                f.verdict.as_str()
            );
        }
    }
    out
}

/// The claims as a pretty-printed JSON array (`carvallo report --claims --json`).
pub fn render_claims_json(claims: &[Claim]) -> String {
    // Serialising plain data with string keys cannot fail.
    serde_json::to_string_pretty(claims).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_split_the_inventory_by_status() {
        let inv = [
            Assertion { section: "1", says: "a", status: Status::Checked("x") },
            Assertion { section: "2", says: "b", status: Status::Value("q") },
            Assertion { section: "3", says: "c", status: Status::Left("why") },
            Assertion { section: "4", says: "d", status: Status::Checked("y") },
        ];
        assert_eq!(counts(&inv), Counts { found: 4, checked: 2, by_value: 1, left: 1 });
    }

    #[test]
    fn the_text_form_names_every_field() {
        let c = Claim::new(
            "hoop-x",
            "12",
            "the hoop turns toward its lean",
            "sign of the steady turn",
            &[("margin", 0.25)],
            Verdict::Agrees,
            "for θ0 ≠ 0",
        );
        let text = render_claims_text(&[c]);
        for part in
            ["n° 12 [agrees] hoop-x", "claim:    the hoop", "how:      sign", "margin = 0.25", "θ0"]
        {
            assert!(text.contains(part), "no `{part}` in\n{text}");
        }
    }
}
