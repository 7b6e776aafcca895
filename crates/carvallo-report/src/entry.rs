//! The shape of one concordance line ([`Entry`]) and of its [`Verdict`]: what the memoir
//! prints, what is derived, the relative difference, the verdict and a note. This is the JSON
//! shape of `carvallo report --json`.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

/// How a derived value compares with what the memoir prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    /// Equal within [`AGREEMENT_TOLERANCE`](crate::policy::AGREEMENT_TOLERANCE) (formulas) or exactly as printed (numbers).
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
    /// The same comparison run on a perturbed derived side (issue 38): what was perturbed and
    /// the verdict it then gives; `None` when the entry states no perturbation (then its note
    /// says why it holds by construction, or it is not `agrees`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub falsification: Option<Falsification>,
}

/// A check run on a perturbed derived side (a model ingredient moved, a coefficient of the
/// generated program scaled by a stated amount, a sign flipped; never the printed value
/// replaced): what was perturbed and the verdict the check then gives. A check that can fail
/// gives a verdict other than its own.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Falsification {
    /// What was perturbed, and by how much.
    pub perturbation: String,
    /// The verdict of the same check on the perturbed input.
    pub verdict: Verdict,
    /// The evidence the check produced on the perturbed input.
    pub evidence: BTreeMap<String, f64>,
}

impl Falsification {
    /// Whether the perturbation broke the check: its verdict differs from `verdict`.
    pub fn breaks(&self, verdict: Verdict) -> bool {
        self.verdict != verdict
    }
}

/// The sort key of a section: its leading number (`"14/18"` and `"17 bis"` sort as 14 and 17),
/// sections without one (`"-"`, `"benchmark"`) last.
pub(crate) fn section_key(section: &str) -> f64 {
    let digits: String = section.chars().take_while(|c| c.is_ascii_digit()).collect();
    digits.parse::<f64>().unwrap_or(f64::INFINITY)
}
