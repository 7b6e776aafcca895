//! The one verdict policy of the concordance: how a derived value and what the memoir prints
//! are compared and judged. Every entry of every model's report gets its verdict from one of
//! the functions here; the Markdown report's introduction ([`PREAMBLE`]) says the same in
//! prose.
//!
//! # The rules
//! * [`formula`]: two formulas (the derived output and the memoir's, transcribed) or two
//!   exact values are compared at seeded points; `agrees` when the largest relative difference
//!   is at most [`AGREEMENT_TOLERANCE`], otherwise the finding the report attributes
//!   (`memoir-error`, `ocr`) or `derivation-differs`. Never `rounding`.
//! * [`numeric`]: a derived formula against an independent numerical route (finite
//!   differences, Newton, an eigenvalue solver) whose own error is bounded by a stated
//!   tolerance, at most [`NUMERIC_TOLERANCE_MAX`]: `agrees` within it.
//! * [`printed`]: a number Carvallo computed and printed with a given last digit (his slide
//!   rule, n° 14): `agrees` within [`AGREEMENT_TOLERANCE`]; `rounding` when within one unit
//!   of the last printed digit (with a slack of [`UNIT_SLACK`] for the binary representation
//!   of decimal numbers) or within [`SLIDE_RULE`] relative (a slide rule's three significant
//!   digits); otherwise the attributed finding (`memoir-error` when the formulas the number
//!   comes from agree, so the slip is in his arithmetic), or `derivation-differs`. A number
//!   he obtained as a difference of terms that cancel ([`printed_difference`]) carries the
//!   slide rule's three digits on its terms, not on the difference: `rounding` also when the
//!   difference is within [`SLIDE_RULE`] of the largest term.
//! * [`approx`]: an approximation the memoir declares (first order, "negligible", "à peu
//!   près"): `agrees` only when it is exact within [`AGREEMENT_TOLERANCE`]; `rounding` when the
//!   difference is within the size of what the memoir declares it neglects (for a first-order
//!   theory, the second-order terms, $\theta_0^2 + \gamma^2$); beyond that, the attributed
//!   finding or `derivation-differs`. An approximation accepted within 23 % is not `agrees`.
//! * [`claim`]: a qualitative statement (a sign, a root being real, an inequality): `agrees`
//!   when the derivation shows it, otherwise the attributed finding or `derivation-differs`.
//! * [`check`]: a symbolic check recorded at regeneration (`generated/*.checks.tsv`): `agrees`
//!   when it holds and is expected to; a check that fails never `agrees`, except where the
//!   memoir itself says the statement must fail (n° 71: the unmodified Lagrange equations do
//!   not apply), which is the memoir's claim confirmed ([`Expect::FailsAsTheMemoirSays`]); a
//!   failing check that is a finding takes the finding's verdict; an unexpected outcome is
//!   `derivation-differs`.
//! * [`finding`]: an entry whose verdict is the report's attribution alone (an OCR misreading
//!   named in the note, a formula the memoir does not evaluate); never `agrees`.
//!
//! # The relative difference
//! At every sample point the relative difference is
//! $$\delta = \frac{|d - m|}{\max(|d|, |m|, \varepsilon)}$$
//! with $d$ the derived value, $m$ the memoir's, and the floor $\varepsilon$ given by
//! [`REL_DIFF_FLOOR`] (in the unit of the quantity) so that values that are both near zero
//! do not turn rounding noise into a large ratio ([`rel_diff`]). A formula entry reports the
//! maximum over the points.

use std::collections::BTreeMap;

use crate::entry::{Derived, Entry, Memoir, Verdict};

/// Largest relative difference (see the module docs) for which a derived formula and the
/// memoir's printed formula are said to agree: a few hundred units in the last place, the
/// rounding of two different but equal algebraic forms evaluated in `f64`.
pub const AGREEMENT_TOLERANCE: f64 = 1e-12;

/// The floor $\varepsilon$ of the relative difference (module docs), in the unit of the
/// compared quantity.
pub const REL_DIFF_FLOOR: f64 = 1e-9;

/// Relative slack on "one unit of the last printed digit": the printed decimal number and the
/// unit are not exact in binary, so a difference of exactly one unit may come out a few ulps
/// above it.
pub const UNIT_SLACK: f64 = 1e-9;

/// Relative precision of a slide rule (three significant digits): within it a printed number
/// is `rounding` whatever its last digit.
pub const SLIDE_RULE: f64 = 2e-3;

/// Largest tolerance [`numeric`] accepts for an independent numerical route: beyond it the
/// comparison says nothing about exactness and must be an [`approx`] or a [`claim`].
pub const NUMERIC_TOLERANCE_MAX: f64 = 1e-4;

/// The policy in prose, for the preamble of the Markdown report.
pub const PREAMBLE: &str = "How the verdicts are decided (one policy for every entry):\n\n\
- Formulas are compared at seeded sample points by the relative difference |d − m| / max(|d|, |m|, 1e-9); they **agree** when the largest difference is at most 1e-12 (a few hundred units in the last place of `f64`). Otherwise the verdict is the finding the note explains (`memoir-error`, `ocr`) or `derivation-differs`; a formula is never `rounding`.\n\
- A derived value checked against an independent numerical route (finite differences, Newton, an eigenvalue solver) **agrees** within that route's stated error, at most 1e-4 relative.\n\
- A number the memoir prints is judged by the digits it prints: it **agrees** when equal within 1e-12, is **rounding** when the derived value is within one unit of its last printed digit or within 2e-3 relative (a slide rule's three significant digits; for a number Carvallo obtained as a difference of terms that cancel, within 2e-3 of the largest of those terms), and beyond that is a `memoir-error` when the formulas it comes from agree with the memoir (the slip is in Carvallo's arithmetic), otherwise the finding the note names or `derivation-differs`.\n\
- An approximation the memoir declares (first order, \"negligible\", \"à peu près\") **agrees** only when it is exact; it is **rounding** when the difference is within the order the memoir declares it neglects (for a first-order theory the second-order terms, θ0² + γ²), and beyond that a finding or `derivation-differs`.\n\
- A qualitative claim (a sign, real roots, an inequality) **agrees** when the derivation shows it.\n\
- An entry whose verdict is the report's attribution alone (an OCR misreading or a slip the note names, confirmed by the derivation where it can be) carries that verdict; it never `agrees`.\n\
- A symbolic check recorded at regeneration **agrees** when it holds; a failing check is never `agrees`, except where the memoir itself says the statement fails (n° 71: the unmodified Lagrange equations), and otherwise takes the verdict of the finding it records or `derivation-differs`.\n";

/// Relative difference with the floor [`REL_DIFF_FLOOR`] (module docs).
pub fn rel_diff(derived: f64, memoir: f64) -> f64 {
    (derived - memoir).abs() / derived.abs().max(memoir.abs()).max(REL_DIFF_FLOOR)
}

/// The unit of the last digit of a number printed with `decimals` decimals, $10^{-d}$.
pub fn unit_of(decimals: i32) -> f64 {
    10f64.powi(-decimals)
}

/// The verdict of a comparison that failed: `otherwise`, except that a failed comparison is
/// never `agrees` nor `rounding` (those would be `derivation-differs`).
fn attributed(otherwise: Verdict) -> Verdict {
    match otherwise {
        Verdict::Agrees | Verdict::Rounding => Verdict::DerivationDiffers,
        v => v,
    }
}

/// Two formulas, or two exact values, whose largest relative difference is `max_rel`: `agrees`
/// within [`AGREEMENT_TOLERANCE`], otherwise `otherwise` (never `agrees` or `rounding`). A NaN
/// difference (one side undefined) does not agree.
pub fn formula(max_rel: f64, otherwise: Verdict) -> Verdict {
    if max_rel <= AGREEMENT_TOLERANCE {
        Verdict::Agrees
    } else {
        attributed(otherwise)
    }
}

/// A derived value against an independent numerical route with relative error at most
/// `tolerance` (capped at [`NUMERIC_TOLERANCE_MAX`]): `agrees` when `max_rel` is within it,
/// otherwise `otherwise` (never `agrees` or `rounding`).
pub fn numeric(max_rel: f64, tolerance: f64, otherwise: Verdict) -> Verdict {
    if max_rel <= tolerance.min(NUMERIC_TOLERANCE_MAX) {
        Verdict::Agrees
    } else {
        attributed(otherwise)
    }
}

/// A number the memoir prints, `memoir`, whose last printed digit has the unit `unit`
/// ([`unit_of`]), against the `derived` one: `agrees` within [`AGREEMENT_TOLERANCE`],
/// `rounding` within one unit (times $1 +$ [`UNIT_SLACK`]) or [`SLIDE_RULE`] relative,
/// otherwise `otherwise` (never `agrees` or `rounding`).
pub fn printed(derived: f64, memoir: f64, unit: f64, otherwise: Verdict) -> Verdict {
    let rel = rel_diff(derived, memoir);
    if rel <= AGREEMENT_TOLERANCE {
        Verdict::Agrees
    } else if (derived - memoir).abs() <= unit * (1.0 + UNIT_SLACK) || rel <= SLIDE_RULE {
        Verdict::Rounding
    } else {
        attributed(otherwise)
    }
}

/// A number the memoir prints that Carvallo obtained as a difference of terms that cancel, the
/// largest of size `terms`: as [`printed`], and also `rounding` when the difference is within
/// [`SLIDE_RULE`] of `terms` (his slide rule carries three digits of each term, so a
/// cancellation leaves fewer in the difference).
pub fn printed_difference(
    derived: f64,
    memoir: f64,
    unit: f64,
    terms: f64,
    otherwise: Verdict,
) -> Verdict {
    match printed(derived, memoir, unit, otherwise) {
        v @ (Verdict::Agrees | Verdict::Rounding) => v,
        v => {
            if (derived - memoir).abs() <= SLIDE_RULE * terms.abs() {
                Verdict::Rounding
            } else {
                v
            }
        }
    }
}

/// An approximation the memoir declares, off the exact value by `deviation` (relative, or in
/// the unit of `declared`), where `declared` is the size of what the memoir says it neglects:
/// `agrees` only when exact ([`AGREEMENT_TOLERANCE`]), `rounding` within `declared`, otherwise
/// `otherwise` (never `agrees` or `rounding`).
pub fn approx(deviation: f64, declared: f64, otherwise: Verdict) -> Verdict {
    if deviation <= AGREEMENT_TOLERANCE {
        Verdict::Agrees
    } else if deviation <= declared {
        Verdict::Rounding
    } else {
        attributed(otherwise)
    }
}

/// A qualitative claim of the memoir: `agrees` when the derivation shows it (`holds`),
/// otherwise `otherwise` (never `agrees` or `rounding`).
pub fn claim(holds: bool, otherwise: Verdict) -> Verdict {
    if holds {
        Verdict::Agrees
    } else {
        attributed(otherwise)
    }
}

/// A finding whose cause the derivation confirms: `verdict` (`memoir-error`, `ocr`) when
/// `confirmed`, `derivation-differs` otherwise (never `agrees` or `rounding`).
pub fn finding_if(confirmed: bool, verdict: Verdict) -> Verdict {
    if confirmed {
        attributed(verdict)
    } else {
        Verdict::DerivationDiffers
    }
}

/// An entry whose verdict is the report's attribution alone (an OCR misreading named in the
/// note, a formula the memoir states without a value to compare): `verdict`, which may not be
/// `agrees` or `rounding` (those come from a comparison).
pub fn finding(verdict: Verdict) -> Verdict {
    attributed(verdict)
}

/// What a symbolic check is expected to show.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expect {
    /// The check must hold.
    Holds,
    /// The memoir itself says the statement fails (n° 71: the unmodified Lagrange equations do
    /// not apply): failing confirms the memoir.
    FailsAsTheMemoirSays,
    /// The check records a finding of the concordance: when it fails, the entry takes this
    /// verdict (`memoir-error`, `ocr`, or `rounding` for an approximation the memoir declares;
    /// never `agrees`).
    Finding(Verdict),
}

/// A symbolic check that `holds` or not, against what is expected of it (module docs): a
/// failing check is never `agrees` except [`Expect::FailsAsTheMemoirSays`]; an unexpected
/// outcome is `derivation-differs`.
pub fn check(holds: bool, expect: Expect) -> Verdict {
    match (expect, holds) {
        (Expect::Holds, true) | (Expect::FailsAsTheMemoirSays, false) => Verdict::Agrees,
        (Expect::Finding(Verdict::Rounding), false) => Verdict::Rounding,
        (Expect::Finding(v), false) => attributed(v),
        _ => Verdict::DerivationDiffers,
    }
}

// Entry builders shared by the model reports, each deciding through the rules above.

/// A number entry: `derived` against the printed `memoir`, agreeing within
/// [`AGREEMENT_TOLERANCE`], otherwise given `otherwise` as verdict.
pub(crate) fn number_entry(
    section: &str,
    quantity: &str,
    memoir: f64,
    derived: f64,
    otherwise: Verdict,
    note: String,
) -> Entry {
    let rel = rel_diff(derived, memoir);
    Entry {
        falsification: None,
        section: section.to_string(),
        quantity: quantity.to_string(),
        memoir: Memoir::Number(memoir),
        derived: Derived::Number(derived),
        rel_diff: Some(rel),
        verdict: formula(rel, otherwise),
        note,
    }
}

/// A number the memoir prints with `decimals` decimals, computed slide-rule style by Carvallo
/// ([`printed`]); beyond rounding `memoir-error` when the underlying formulas agree with the
/// memoir (so the difference is in his arithmetic), `derivation-differs` when they do not.
pub(crate) fn printed_number(
    section: &str,
    quantity: &str,
    memoir: f64,
    decimals: i32,
    derived: f64,
    formulas_agree: bool,
    note: &str,
) -> Entry {
    let rel = rel_diff(derived, memoir);
    let otherwise = if formulas_agree { Verdict::MemoirError } else { Verdict::DerivationDiffers };
    let verdict = printed(derived, memoir, unit_of(decimals), otherwise);
    Entry {
        falsification: None,
        section: section.to_string(),
        quantity: quantity.to_string(),
        memoir: Memoir::Number(memoir),
        derived: Derived::Number(derived),
        rel_diff: Some(rel),
        verdict,
        note: note.to_string(),
    }
}

/// A formula entry: the largest relative difference of `derived` and `memoir` over `pts`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn formula_entry<P>(
    section: &str,
    quantity: &str,
    printed: &str,
    pts: &[P],
    derived: impl Fn(&P) -> f64,
    memoir: impl Fn(&P) -> f64,
    otherwise: Verdict,
    note: &str,
) -> Entry {
    let mut worst = 0.0f64;
    for p in pts {
        worst = worst.max(rel_diff(derived(p), memoir(p)));
    }
    let verdict = formula(worst, otherwise);
    Entry {
        falsification: None,
        section: section.into(),
        quantity: quantity.into(),
        memoir: Memoir::Formula(printed.into()),
        derived: Derived::Numbers(BTreeMap::from([
            ("max_rel_diff".to_string(), worst),
            ("points".to_string(), pts.len() as f64),
        ])),
        rel_diff: Some(worst),
        verdict,
        note: note.into(),
    }
}

/// A printed slide-rule number with `decimals` decimals ([`printed`]), `memoir-error` beyond
/// rounding.
pub(crate) fn number(
    section: &str,
    quantity: &str,
    memoir: f64,
    decimals: i32,
    derived: f64,
    note: &str,
) -> Entry {
    let rel = rel_diff(derived, memoir);
    let verdict = printed(derived, memoir, unit_of(decimals), Verdict::MemoirError);
    Entry {
        falsification: None,
        section: section.into(),
        quantity: quantity.into(),
        memoir: Memoir::Number(memoir),
        derived: Derived::Number(derived),
        rel_diff: Some(rel),
        verdict,
        note: note.into(),
    }
}

/// An exact number ([`formula`]) with the verdict `v` when it does not agree.
pub(crate) fn number_as(
    section: &str,
    quantity: &str,
    memoir: f64,
    derived: f64,
    v: Verdict,
    note: &str,
) -> Entry {
    let rel = rel_diff(derived, memoir);
    Entry {
        falsification: None,
        section: section.into(),
        quantity: quantity.into(),
        memoir: Memoir::Number(memoir),
        derived: Derived::Number(derived),
        rel_diff: Some(rel),
        verdict: formula(rel, v),
        note: note.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formulas_agree_only_within_the_tolerance_and_are_never_rounding() {
        assert_eq!(formula(1e-13, Verdict::MemoirError), Verdict::Agrees);
        assert_eq!(formula(1e-6, Verdict::MemoirError), Verdict::MemoirError);
        assert_eq!(formula(f64::NAN, Verdict::Ocr), Verdict::Ocr);
        assert_eq!(formula(1e-6, Verdict::Rounding), Verdict::DerivationDiffers);
        assert_eq!(formula(1e-6, Verdict::Agrees), Verdict::DerivationDiffers);
    }

    #[test]
    fn a_difference_is_judged_against_the_terms_that_cancel() {
        // n° 41 at 60°: -0.30681 for the printed -0.308, 3.9e-3 of the difference but 6e-4 of
        // the largest term 2.0 (1/cos 60°).
        assert_eq!(
            printed(-0.30681, -0.308, unit_of(3), Verdict::MemoirError),
            Verdict::MemoirError
        );
        assert_eq!(
            printed_difference(-0.30681, -0.308, unit_of(3), 2.0, Verdict::MemoirError),
            Verdict::Rounding
        );
        // Beyond 2e-3 of the terms it stays the finding (n° 41 at 10°: 2.6e-3 against 1.015).
        assert_eq!(
            printed_difference(0.40041, 0.403, unit_of(3), 1.0154, Verdict::MemoirError),
            Verdict::MemoirError
        );
        assert_eq!(
            printed_difference(0.403, 0.403, unit_of(3), 1.0, Verdict::MemoirError),
            Verdict::Agrees
        );
    }

    #[test]
    fn printed_numbers_follow_their_last_digit() {
        // 0.917 printed, 0.9176 derived: within one unit of the third decimal.
        assert_eq!(printed(0.9176, 0.917, unit_of(3), Verdict::MemoirError), Verdict::Rounding);
        // Exactly one unit away, not exact in binary: the slack keeps it rounding.
        assert_eq!(printed(0.721 + 0.001, 0.721, unit_of(3), Verdict::Ocr), Verdict::Rounding);
        // A slide rule's three digits on a large number.
        assert_eq!(printed(7330.0, 7332.0, unit_of(0), Verdict::MemoirError), Verdict::Rounding);
        assert_eq!(printed(19.12, 19.33, unit_of(2), Verdict::MemoirError), Verdict::MemoirError);
        assert_eq!(printed(2.0, 2.0, unit_of(1), Verdict::MemoirError), Verdict::Agrees);
    }

    #[test]
    fn an_approximation_agrees_only_when_exact() {
        assert_eq!(approx(0.0, 0.3, Verdict::DerivationDiffers), Verdict::Agrees);
        assert_eq!(approx(0.23, 0.3, Verdict::DerivationDiffers), Verdict::Rounding);
        assert_eq!(approx(0.23, 0.1, Verdict::MemoirError), Verdict::MemoirError);
    }

    #[test]
    fn numeric_routes_are_capped() {
        assert_eq!(numeric(1e-7, 1e-6, Verdict::DerivationDiffers), Verdict::Agrees);
        assert_eq!(numeric(1e-3, 1e-2, Verdict::DerivationDiffers), Verdict::DerivationDiffers);
    }

    #[test]
    fn a_failing_check_never_agrees_unless_the_memoir_says_it_fails() {
        assert_eq!(check(true, Expect::Holds), Verdict::Agrees);
        assert_eq!(check(false, Expect::Holds), Verdict::DerivationDiffers);
        assert_eq!(check(false, Expect::FailsAsTheMemoirSays), Verdict::Agrees);
        assert_eq!(check(true, Expect::FailsAsTheMemoirSays), Verdict::DerivationDiffers);
        assert_eq!(check(false, Expect::Finding(Verdict::Ocr)), Verdict::Ocr);
        assert_eq!(check(false, Expect::Finding(Verdict::Rounding)), Verdict::Rounding);
        assert_eq!(check(false, Expect::Finding(Verdict::Agrees)), Verdict::DerivationDiffers);
        assert_eq!(check(true, Expect::Finding(Verdict::Ocr)), Verdict::DerivationDiffers);
    }

    #[test]
    fn claims_and_findings_never_agree_by_attribution() {
        assert_eq!(claim(true, Verdict::MemoirError), Verdict::Agrees);
        assert_eq!(claim(false, Verdict::MemoirError), Verdict::MemoirError);
        assert_eq!(finding(Verdict::Agrees), Verdict::DerivationDiffers);
        assert_eq!(finding_if(true, Verdict::Ocr), Verdict::Ocr);
        assert_eq!(finding_if(false, Verdict::Ocr), Verdict::DerivationDiffers);
    }
}
