//! Tests of the unicycle concordance (memoir n° 21–41, 74, 78): the expected verdict of the
//! entries that are findings, every formula entry consistent with its tolerance, and a
//! snapshot of the text table with numbers normalised to 4 significant digits.

use std::collections::BTreeMap;

use carvallo_report::unicycle::entries;
use carvallo_report::{render_text_normalised, Verdict};

use crate::common;

/// Entries whose verdict is not `agrees`, by (section, quantity); every other entry agrees
/// or is a slide-rule `rounding`.
fn findings() -> BTreeMap<(&'static str, &'static str), Verdict> {
    use Verdict::*;
    BTreeMap::from([
        (("24", "equation (p), letters merged"), DerivationDiffers),
        (("24", "equation (n), letters merged"), DerivationDiffers),
        (("24", "equation (s), letters merged"), DerivationDiffers),
        (("24", "unicycle check merge_is_substitution"), DerivationDiffers),
        (("30", "D complete"), MemoirError),
        (("30", "unicycle check skid_full_memoir"), MemoirError),
        (("74", "unicycle check lagrange_theta_74_as_printed"), Ocr),
        (("78", "(2) product of the roots, straight running"), DerivationDiffers),
        (("78", "(3) sum of the roots, straight running"), DerivationDiffers),
        (("78", "unicycle check sum_78_full_model"), DerivationDiffers),
        (("32", "table n° 32, theta = 10°, s0"), MemoirError),
        (("32", "table n° 32, theta = 10°, s at n = -0.3"), MemoirError),
        (("32", "table n° 32, theta = 10°, s at n = -0.5"), MemoirError),
        (("32", "table n° 32, theta = 10°, s at n = -1"), MemoirError),
        (("32", "table n° 32, theta = 20°, D"), Ocr),
        (("32", "table n° 32, theta = 20°, s at n = -0.1"), MemoirError),
        (("32", "table n° 32, theta = 40°, s0"), MemoirError),
        (("32", "table n° 32, theta = 50°, s at n = -1.5"), MemoirError),
        (("32", "s0 of (E), formula"), MemoirError),
        (("32", "point I, theta as printed arcsin(1/2.5) (degrees)"), MemoirError),
        (("32", "limit radius s / sqrt(g/R)"), MemoirError),
        (("36", "C0 = mu0 r^2 / 2 (kg m^2)"), MemoirError),
        (("36", "C = C0 + C1 (kg m^2)"), MemoirError),
        (
            ("36", "straight running threshold s, full model (h = 2.5 R, rider C0 = 0.77)"),
            DerivationDiffers,
        ),
        (("39", "table n° 39, theta = 0°, |n| limit"), Ocr),
        (("39", "table n° 39, theta = 50°, |n| limit"), MemoirError),
        (("39", "table n° 39, theta = 50°, s"), MemoirError),
        (("41", "first member of n° 41 at theta = 10°"), MemoirError),
        (("41", "first member of n° 41 at theta = 40°"), MemoirError),
        (("41", "first member of n° 41 at theta = 50°"), MemoirError),
        (("41", "first zero of the first member (degrees)"), MemoirError),
        (("41", "junction point n"), MemoirError),
        (("41", "junction point s"), MemoirError),
        (("36", "first member (S): s^2 over constant term"), Ocr),
        (("36", "infinitely light rider, threshold s^2"), MemoirError),
        (("40", "left side A dp'/dn"), Ocr),
        (("41", "conclusion: speed limit sqrt(C/(mu1 R^2))"), Ocr),
        (("78", "characteristic determinant, second row"), Ocr),
        (("78", "dN/dp at theta = 0, n = 0"), Ocr),
    ])
}

#[test]
fn verdicts_are_the_expected_ones() {
    let entries = entries();
    common::assert_formulas_agree_within_tolerance(&entries);
    common::assert_verdicts(
        &entries,
        &findings(),
        &[
            "21", "23", "24", "29", "30", "31", "32", "33", "34", "35", "36", "39", "40", "41",
            "74", "78",
        ],
    );
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&entries());
    insta::with_settings!({
        description => "carvallo report: the unicycle concordance table, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("unicycle_report_text", text);
    });
}

#[test]
fn claims_snapshot() {
    let text = carvallo_report::normalise_numbers(&carvallo_report::claims::render_claims_text(
        &carvallo_report::unicycle::claims(),
    ));
    insta::with_settings!({
        description => "carvallo report: the unicycle's claims n° 20-42, 74, 78, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("unicycle_claims_text", text);
    });
}

fn claim(id: &str) -> carvallo_report::Claim {
    let all = carvallo_report::unicycle::claims();
    all.into_iter().find(|c| c.id == id).unwrap_or_else(|| panic!("no claim {id}"))
}

fn evidence(c: &carvallo_report::Claim, key: &str) -> f64 {
    *c.evidence.get(key).unwrap_or_else(|| panic!("{}: no evidence {key}", c.id))
}

/// The claims the issue names, decided here directly by their evidence.
#[test]
fn the_named_claims_are_decided_by_their_numbers() {
    // n° 36 re-judged: the full model without rider and the hoop give s^2 > 1/4, not 1/2.
    let c = claim("unicycle-light-rider-hoop-limit");
    assert_eq!(c.verdict, Verdict::MemoirError);
    assert!((evidence(&c, "hoop_s2") - 0.25).abs() < 1e-9);
    assert!((evidence(&c, "full_no_rider_s2") - 0.25).abs() < 1e-9);
    assert!((evidence(&c, "full_light_rider_s2") - 0.25).abs() < 1e-5);
    assert!((evidence(&c, "memoir_formula_s2") - 0.5).abs() < 1e-12);
    // n° 25: the slope moment is sin i, not tan i.
    let c = claim("unicycle-slope-moment");
    assert_eq!(c.verdict, Verdict::MemoirError);
    assert!(evidence(&c, "max_rel_diff_sin") < 1e-8);
    let tan10 = evidence(&c, "rel_diff_tan_at_10deg");
    assert!((tan10 - (1.0 - 10f64.to_radians().cos())).abs() < 1e-6, "{tan10}");
    assert_eq!(claim("unicycle-slope-sign").verdict, Verdict::Agrees);
    // n° 26, 26 bis.
    let c = claim("unicycle-pedal-paradox");
    assert_eq!(c.verdict, Verdict::Agrees);
    assert!(evidence(&c, "largest_work_per_F_R") < -0.04);
    let c = claim("unicycle-string-neutral-angle");
    assert_eq!(c.verdict, Verdict::Agrees);
    assert!(evidence(&c, "max_abs_diff_sin") < 1e-6);
    // n° 32, 37: the cycle turns toward its lean, statically and dynamically.
    assert_eq!(claim("unicycle-turns-toward-lean").verdict, Verdict::Agrees);
    assert_eq!(claim("unicycle-fall-turns-toward-lean").verdict, Verdict::Agrees);
    // n° 32: the regions, and the practical region's « n2 seule ».
    let c = claim("unicycle-walking-pivoting-regions");
    assert_eq!(c.verdict, Verdict::Agrees);
    assert_eq!(evidence(&c, "misclassified"), 0.0);
    let c = claim("unicycle-practical-region");
    assert_eq!(c.verdict, Verdict::MemoirError);
    assert!(evidence(&c, "n2_unusable_max_s") < 1.04);
    assert!(evidence(&c, "n1_usable") > 0.0);
    // Its falsification: with the rider's couple (B - C) n^2 sin cos of (E) halved, n1 pivots
    // at every point of the region and n2 stays usable above the band under s = 1.
    let f = c.falsification.as_ref().expect("n° 32's practical region states a perturbation");
    assert_eq!(f.verdict, Verdict::Agrees);
    assert_eq!(f.evidence["n1_usable"], 0.0);
    assert_eq!(f.evidence["n2_unusable"], 0.0);
    assert!(f.evidence["points_with_roots"] > 2000.0, "{:?}", f.evidence);
    // n° 39, 41: a light unicycle is stable only while turning; every lean between the roots.
    let c = claim("unicycle-light-stable-only-turning");
    assert_eq!(c.verdict, Verdict::Agrees);
    assert!(evidence(&c, "smallest_stable_abs_n") > 0.62);
    let c = claim("unicycle-stable-between-roots");
    assert_eq!(c.verdict, Verdict::Agrees);
    assert!(evidence(&c, "min_S_over_1_plus_n2") > 0.0);
    // n° 42: the centre of gravity below the axle swings, above it falls.
    let c = claim("unicycle-stable-principle");
    assert_eq!(c.verdict, Verdict::Agrees);
    assert!(evidence(&c, "omega2_R1.2") > 0.0 && evidence(&c, "omega2_R0.5") < 0.0);
}
