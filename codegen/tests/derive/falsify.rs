//! The falsification of the symbolic checks (`carvallo_codegen::falsify`): a symbol of the
//! derived side scaled breaks an identity, a check that cannot fail is recorded as holding,
//! and the stand-ins of sines and cosines are tried last.

use carvallo_codegen::cas::{expr, from_trig, is_zero};
use carvallo_codegen::falsify::{candidates, perturb_derived, perturb_one, perturb_term};
use symbolica::atom::Atom;

use crate::on_symbolica_thread;

#[test]
fn a_symbol_of_the_derived_side_breaks_an_identity() {
    on_symbolica_thread(|| {
        // (R + mu)^2 against R^2 + 2 R mu + mu^2: scaling R by 9/8 on the derived side breaks it.
        let derived = expr("(R + mu)^2");
        let expected = expr("R^2 + 2*R*mu + mu^2");
        assert!(is_zero(&(&derived - &expected)));
        let p = perturb_one(&derived, |d| is_zero(&(d - &expected)));
        assert!(!p.holds);
        assert_eq!(p.what, "every `R` of the derived side scaled by 9/8");
        // The same through the difference: the expected side is kept.
        let diff = &derived - &expected;
        let q = perturb_derived(&derived, &diff, is_zero);
        assert_eq!(q, p);
    });
}

#[test]
fn a_check_that_cannot_fail_is_recorded_as_holding() {
    on_symbolica_thread(|| {
        // A check that does not look at its derived side holds whatever is perturbed: the first
        // symbol tried is recorded, with `holds`, for the concordance to report by name.
        let p = perturb_one(&expr("R*mu + g"), |_| true);
        assert!(p.holds, "{}", p.what);
        assert_eq!(p.what, "every `R` of the derived side scaled by 9/8");
    });
}

#[test]
fn an_energy_balance_has_a_term_scaled_when_no_symbol_breaks_it() {
    on_symbolica_thread(|| {
        // sin^2 + cos^2 of a scaled angle is still 1: no symbol breaks the identity, so the first
        // term of the derived side is scaled, which does.
        let derived = expr("sin(theta)^2 + cos(theta)^2");
        let p = perturb_one(&derived, |d| is_zero(&from_trig(&(d - Atom::num(1)))));
        assert!(!p.holds, "{}", p.what);
        assert!(p.what.starts_with("the first term of the derived quantity"), "{}", p.what);
    });
}

#[test]
fn a_quantity_that_must_vanish_has_a_term_scaled() {
    on_symbolica_thread(|| {
        // sin^2 + cos^2 - 1 in the stand-ins vanishes modulo their relation; as a quantity that
        // must vanish (no expected side) its first term is scaled, and it no longer vanishes.
        let q = expr("sin_theta^2 + cos_theta^2 - 1");
        assert!(is_zero(&q));
        let p = perturb_derived(&q, &q, is_zero);
        assert!(!p.holds, "{}", p.what);
        assert!(p.what.starts_with("the first term of the derived quantity"), "{}", p.what);
        assert_eq!(p, perturb_term(&q, is_zero));
    });
}

#[test]
fn stand_ins_are_tried_last() {
    on_symbolica_thread(|| {
        let names = candidates(&[expr("sin_theta*mu + g*cos_theta + R")]);
        assert_eq!(names, ["R", "g", "mu", "cos_theta", "sin_theta"]);
    });
}
