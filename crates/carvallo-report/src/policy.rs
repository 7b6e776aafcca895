//! The verdict policy of the concordance: how a derived value and what the memoir prints are
//! compared and judged.
//!
//! # Verdicts
//! * Formulas: `agrees` when the largest relative difference is at most
//!   [`AGREEMENT_TOLERANCE`], otherwise `derivation-differs` with the worst point in the note.
//! * Exact numbers (n° 4 coefficients, the threshold $s^2 = 1/4$): `agrees` within
//!   [`AGREEMENT_TOLERANCE`].
//! * Numbers Carvallo computed with his slide rule: `rounding` when within one unit of the
//!   last printed digit or $2\cdot10^{-3}$ relative; otherwise `memoir-error` when the
//!   formulas they come from agree with the memoir (the slip is in his arithmetic, the note
//!   says how his own intermediate values show it), `derivation-differs` when they do not.
//! * Symbolic checks: a check `<output>_memoir` annotates the formula entry of that output;
//!   any other check is an entry that agrees when its outcome is the expected one.
//!
//! # Comparing two formulas
//! At every sample point the relative difference is
//! $$\delta = \frac{|d - m|}{\max(|d|, |m|, \varepsilon)}$$
//! with $d$ the derived value, $m$ the memoir's, and the floor $\varepsilon$ given by
//! [`REL_DIFF_FLOOR`] (in the unit of the quantity) so that values that are both near zero
//! do not turn rounding noise into a large ratio. The entry reports the maximum over the
//! points; it *agrees* when that maximum is at most [`AGREEMENT_TOLERANCE`].

use std::collections::BTreeMap;

use crate::entry::{Derived, Entry, Memoir, Verdict};

/// Largest relative difference (see the module docs) for which a derived formula and the
/// memoir's printed formula are said to agree: a few hundred units in the last place, the
/// rounding of two different but equal algebraic forms evaluated in `f64`.
pub const AGREEMENT_TOLERANCE: f64 = 1e-12;

/// The floor $\varepsilon$ of the relative difference (module docs), in the unit of the
/// compared quantity.
pub const REL_DIFF_FLOOR: f64 = 1e-9;

/// Relative difference with the floor [`REL_DIFF_FLOOR`] (module docs).
pub(crate) fn rel_diff(derived: f64, memoir: f64) -> f64 {
    (derived - memoir).abs() / derived.abs().max(memoir.abs()).max(REL_DIFF_FLOOR)
}

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
        section: section.to_string(),
        quantity: quantity.to_string(),
        memoir: Memoir::Number(memoir),
        derived: Derived::Number(derived),
        rel_diff: Some(rel),
        verdict: if rel <= AGREEMENT_TOLERANCE { Verdict::Agrees } else { otherwise },
        note,
    }
}

/// A number the memoir prints with `decimals` decimals, computed slide-rule style by Carvallo.
/// `Rounding` when the derived value is within one unit of the last printed digit or within
/// 2e-3 relative (a slide rule's three significant digits); otherwise `MemoirError` when the
/// underlying formulas agree with the memoir (so the difference is in his arithmetic),
/// `DerivationDiffers` when they do not.
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
    let close = (derived - memoir).abs() <= 10f64.powi(-decimals) || rel <= 2e-3;
    let verdict = if rel <= AGREEMENT_TOLERANCE {
        Verdict::Agrees
    } else if close {
        Verdict::Rounding
    } else if formulas_agree {
        Verdict::MemoirError
    } else {
        Verdict::DerivationDiffers
    };
    Entry {
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
    let verdict = if worst <= AGREEMENT_TOLERANCE { Verdict::Agrees } else { otherwise };
    Entry {
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

/// A printed slide-rule number with `decimals` decimals (policy in the module docs).
pub(crate) fn number(
    section: &str,
    quantity: &str,
    memoir: f64,
    decimals: i32,
    derived: f64,
    note: &str,
) -> Entry {
    let rel = rel_diff(derived, memoir);
    let verdict = if rel <= AGREEMENT_TOLERANCE {
        Verdict::Agrees
    } else if (derived - memoir).abs() <= 10f64.powi(-decimals) * (1.0 + 1e-9) || rel <= 2e-3 {
        Verdict::Rounding
    } else {
        Verdict::MemoirError
    };
    Entry {
        section: section.into(),
        quantity: quantity.into(),
        memoir: Memoir::Number(memoir),
        derived: Derived::Number(derived),
        rel_diff: Some(rel),
        verdict,
        note: note.into(),
    }
}

/// `number` with a fixed verdict for a non-`agrees` outcome.
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
        section: section.into(),
        quantity: quantity.into(),
        memoir: Memoir::Number(memoir),
        derived: Derived::Number(derived),
        rel_diff: Some(rel),
        verdict: if rel <= AGREEMENT_TOLERANCE { Verdict::Agrees } else { v },
        note: note.into(),
    }
}
