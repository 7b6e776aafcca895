//! Falsification of the symbolic checks (issue 38): a check that compares a derived side with
//! an expected one (the memoir's printed formula, a second route, zero) is run again with its
//! derived side perturbed, and the outcome is recorded beside the check
//! ([`crate::Check::perturbed`], the last two columns of `generated/<model>.checks.tsv`).
//!
//! The perturbation is a model symbol of the derived side scaled by [`FACTOR`]: a parameter
//! (a mass, a length, a moment of inertia, $g$) or a variable of the state, changed in the
//! derived side only; the expected side keeps it. The symbols are tried in the order of
//! [`candidates`] (parameters and variables before the stand-ins of sines and cosines, then by
//! name) and the first under which the check no longer holds is recorded; when none of the
//! first [`MAX_TRIES`] breaks it (a check homogeneous in them, as an energy balance), the first
//! term of the derived side as derived is scaled instead ([`perturb_term`]); when that does
//! not break it either, the first symbol tried is recorded with its outcome (it holds), which
//! the concordance's falsifiability test reports by name. A derived side with no symbol (a
//! number) is scaled as a whole.
//!
//! The perturbed check is made in the same process as the derivation, on expressions already
//! derived: nothing is derived twice.

use symbolica::atom::{Atom, AtomCore, AtomView};

use crate::cas::{rat, subst, var};
use crate::{Check, Perturbed};

/// `check` with `perturbed` as its falsification: the one way a derivation attaches the outcome
/// of its own perturbation to a check.
pub fn with_perturbation(check: Check, perturbed: Option<Perturbed>) -> Check {
    Check { perturbed, ..check }
}

/// The factor a symbol of the derived side is scaled by: $9/8$, exact, so that the perturbed
/// check is decided as exactly as the check itself.
pub fn factor() -> Atom {
    rat(9, 8)
}

/// The factor as text, for the recorded perturbation.
pub const FACTOR: &str = "9/8";

/// The most symbols tried before the first tried is recorded as not breaking the check.
pub const MAX_TRIES: usize = 3;

/// Whether `name` is a polynomial stand-in of a sine, a cosine or a tangent
/// (`sin_theta`, `cos_mu`), tried after the other symbols.
fn is_stand_in(name: &str) -> bool {
    ["sin_", "cos_", "tan_"].iter().any(|p| name.starts_with(p))
}

/// The symbols of `derived` (function names excluded), in the order they are tried: parameters
/// and variables first, then the stand-ins of trigonometric functions, each group by name.
pub fn candidates(derived: &[Atom]) -> Vec<String> {
    let mut names: Vec<String> = derived
        .iter()
        .flat_map(|a| a.get_all_symbols(false))
        .map(|s| s.get_stripped_name().to_string())
        .collect();
    names.sort_by(|a, b| (is_stand_in(a), a).cmp(&(is_stand_in(b), b)));
    names.dedup();
    names
}

/// The check `holds` run again on `derived` with one symbol scaled by [`FACTOR`] (see the
/// module docs); `holds` receives the perturbed derived side, in the same order.
pub fn perturb(derived: &[Atom], holds: impl Fn(&[Atom]) -> bool) -> Perturbed {
    perturb_dyn(derived, &holds)
}

/// [`perturb`] with the check as a trait object (the term fallback calls it back).
fn perturb_dyn(derived: &[Atom], holds: &dyn Fn(&[Atom]) -> bool) -> Perturbed {
    let names = candidates(derived);
    if names.is_empty() {
        let scaled: Vec<Atom> = derived.iter().map(|a| a * &factor()).collect();
        return Perturbed {
            what: format!("the derived side (a number) scaled by {FACTOR}"),
            holds: holds(&scaled),
        };
    }
    let mut first: Option<Perturbed> = None;
    for name in names.iter().take(MAX_TRIES) {
        let scaled_symbol = var(name) * factor();
        let scaled: Vec<Atom> = derived.iter().map(|a| subst(a, name, &scaled_symbol)).collect();
        let outcome = Perturbed {
            what: format!("every `{name}` of the derived side scaled by {FACTOR}"),
            holds: holds(&scaled),
        };
        if !outcome.holds {
            return outcome;
        }
        first.get_or_insert(outcome);
    }
    // No symbol breaks it (the check is homogeneous in them, as an energy balance is): the
    // first term of the first derived expression, as derived, scaled instead.
    if let AtomView::Add(_) = derived[0].as_view() {
        let rest = derived[1..].to_vec();
        let by_term = term_dyn(&derived[0], &|q: &Atom| {
            let mut d = vec![q.clone()];
            d.extend(rest.iter().cloned());
            holds(&d)
        });
        if !by_term.holds {
            return by_term;
        }
    }
    first.expect("at least one symbol was tried")
}

/// A check that `diff` vanishes, with `derived` its derived side: `diff` = `derived` −
/// expected, run again as `diff` − `derived` + `derived`′ with `derived`′ the perturbed derived
/// side (the expected side kept), by [`perturb_one`]. When `derived` is `diff` itself (a derived
/// quantity that must vanish, with no expected side), scaling a symbol cannot break an identity,
/// so the first term of the quantity as derived (before any simplification) is scaled by
/// [`FACTOR`] instead ([`perturb_term`]).
pub fn perturb_derived(derived: &Atom, diff: &Atom, vanishes: impl Fn(&Atom) -> bool) -> Perturbed {
    if derived == diff {
        return perturb_term(diff, vanishes);
    }
    perturb_one(derived, |d| vanishes(&(diff - derived + d)))
}

/// A derived quantity `q` that must vanish, run again with the first of its terms (as derived,
/// a sum whose terms cancel) scaled by [`FACTOR`]; a quantity that is not a sum is perturbed by
/// [`perturb_one`] (a symbol scaled).
pub fn perturb_term(q: &Atom, vanishes: impl Fn(&Atom) -> bool) -> Perturbed {
    term_dyn(q, &vanishes)
}

/// [`perturb_term`] with the check as a trait object.
fn term_dyn(q: &Atom, vanishes: &dyn Fn(&Atom) -> bool) -> Perturbed {
    if let AtomView::Add(add) = q.as_view() {
        if let Some(first) = add.iter().next() {
            let first = first.to_owned();
            let perturbed = q + &(&first * &(factor() - Atom::num(1)));
            let mut shown = crate::cas::show(&first);
            if shown.len() > 80 {
                shown = format!("{} …", shown.chars().take(80).collect::<String>());
            }
            return Perturbed {
                what: format!(
                    "the first term of the derived quantity, {shown}, scaled by {FACTOR}"
                ),
                holds: vanishes(&perturbed),
            };
        }
    }
    perturb_dyn(std::slice::from_ref(q), &|d: &[Atom]| vanishes(&d[0]))
}

/// Derived quantities `qs` that must all vanish, run again with the first of them that is not
/// already a literal zero perturbed by [`perturb_term`] (its first term scaled); `None` when
/// every one is a literal zero (nothing derived is left to perturb: the quantity was reduced to
/// zero before the check saw it).
pub fn perturb_first_nonzero(qs: &[&Atom], vanishes: impl Fn(&Atom) -> bool) -> Option<Perturbed> {
    let q = qs.iter().find(|q| !q.is_zero())?;
    Some(perturb_term(q, vanishes))
}

/// [`perturb`] for a single derived expression.
pub fn perturb_one(derived: &Atom, holds: impl Fn(&Atom) -> bool) -> Perturbed {
    perturb(std::slice::from_ref(derived), |d| holds(&d[0]))
}
