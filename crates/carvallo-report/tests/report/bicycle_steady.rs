//! Tests of the bicycle's steady-state concordance (memoir n° 79–106): the expected verdict
//! of the entries that are findings, every formula entry consistent with its tolerance, the
//! runtime's validation, and a snapshot of the text table with numbers normalised to 4
//! significant digits.

use std::collections::BTreeMap;

use carvallo::bicycle_steady::{BicycleParams, BicycleSteady, SteadyState};
use carvallo::ParameterError;
use carvallo_report::bicycle::steady::entries;
use carvallo_report::{render_text_normalised, Verdict};

use crate::common;

/// Entries whose verdict is not `agrees` or `rounding`, by (section, quantity).
fn findings() -> BTreeMap<(&'static str, &'static str), Verdict> {
    use Verdict::*;
    BTreeMap::from([
        (("85", "table n° 85, loaded frame, centrifugal terms"), MemoirError),
        (("85", "equilibrium with hands, whole equation (n° 85)"), MemoirError),
        (("94", "table n° 94, loaded frame, centrifugal terms"), MemoirError),
        (("85", "bicycle check fall_frame_memoir"), MemoirError),
        (("94", "bicycle check steer_frame_memoir"), MemoirError),
        (("95", "bicycle check steer_95_from_before"), MemoirError),
        (("95", "bicycle check theta1_ratio_memoir"), MemoirError),
        (("88", "|tan(alpha)/tan(theta)| at 20 km/h"), MemoirError),
        (("88", "|tan(alpha)/tan(theta)| at 10 km/h"), MemoirError),
        (("95", "mu1 R (kg m)"), MemoirError),
        (("96", "1 - 2 sin(eta)"), MemoirError),
        (("95", "theta1/theta of (1)' (first order, omega = eta)"), MemoirError),
        (("97", "theta1/theta of the handlebar equation (first order)"), MemoirError),
        (
            ("97", "speed of a steady turn without hands and without lateral shift (m/s)"),
            MemoirError,
        ),
        (("98", "lateral shift epsilon/theta at 20 km/h"), MemoirError),
        (("83", "bicycle check frame_83_term3"), MemoirError),
        (("83", "bicycle check frame_83_term4"), MemoirError),
        (("83", "bicycle check frame_83_term5"), MemoirError),
        (("83", "bicycle check frame_83_term6"), MemoirError),
    ])
}

#[test]
fn verdicts_are_the_expected_ones() {
    let entries = entries();
    common::assert_formulas_agree_within_tolerance(&entries);
    common::assert_verdicts(
        &entries,
        &findings(),
        &["84", "85", "86", "87", "88", "89", "94", "95", "96", "97", "98", "99", "100"],
    );
}

#[test]
fn bad_constants_are_rejected_with_their_name() {
    let bad = BicycleParams { wheelbase: -1.0, ..BicycleParams::memoir() };
    assert_eq!(
        BicycleSteady::new(bad),
        Err(ParameterError::InvalidParameter {
            name: "wheelbase",
            value: -1.0,
            reason: "must be positive"
        })
    );
    let bad = BicycleParams { a: 200.0, ..BicycleParams::memoir() };
    assert!(matches!(
        BicycleSteady::new(bad),
        Err(ParameterError::InvalidParameter { name: "a", .. })
    ));
    let bad = BicycleParams { e: f64::NAN, ..BicycleParams::memoir() };
    assert!(matches!(
        BicycleSteady::new(bad),
        Err(ParameterError::InvalidParameter { name: "e", .. })
    ));
}

/// The generated fall and handlebar equations are the sums of their generated parts (two
/// evaluation paths of the same program), to 1e-12 relative.
#[test]
fn equations_are_the_sums_of_their_parts() {
    let b = BicycleSteady::new(BicycleParams::memoir()).expect("valid");
    let x = SteadyState {
        theta: 0.3,
        theta1: 0.35,
        alpha: -0.1,
        eta: 0.44,
        omega: 0.45,
        s: 14.0,
        s1: 14.2,
        n: -0.4,
        deta: 0.02,
        dnu: 0.01,
        deta_g: -0.03,
        dnu_g: 0.07,
        p: 0.0,
        deta_t: 0.0,
    };
    let o = |name: &str| b.output(&x, name).expect("an output");
    let fall = o("fall_rear") + o("fall_front") + o("fall_frame")
        - o("fall_grav_rear")
        - o("fall_grav_front")
        - o("fall_grav_frame");
    assert!((fall - o("fall_equilibrium")).abs() <= 1e-12 * fall.abs().max(1.0));
    let steer = o("steer_front") + o("steer_frame") - o("steer_grav_front") - o("steer_grav_frame");
    assert!((steer - o("steer_equilibrium")).abs() <= 1e-12 * steer.abs().max(1.0));
    assert_eq!(b.output(&x, "no_such_output"), None);
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&entries());
    insta::with_settings!({
        description => "carvallo report: the bicycle's steady states (n° 79-106), numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_steady_report_text", text);
    });
}

/// The claims of this report ([`carvallo_report::claims`]): the expected verdict of each.
fn expected_claims() -> BTreeMap<&'static str, Verdict> {
    BTreeMap::from([
        ("steady-pedals-enter-the-rolling-equation-only", Verdict::MemoirError),
        ("steady-frame-decomposition", Verdict::Agrees),
        ("steady-frame-six-terms-steady", Verdict::MemoirError),
        ("steady-frame-six-terms-unsteady", Verdict::MemoirError),
        ("steady-rear-wheel-terms", Verdict::Agrees),
        ("steady-front-wheel-terms", Verdict::MemoirError),
        ("steady-wheel-kinetic-energies", Verdict::Agrees),
        ("steady-reduces-to-hoop-and-unicycle", Verdict::Agrees),
        ("steady-leading-inertia-term", Verdict::Agrees),
        ("steady-orders-fall", Verdict::Agrees),
        ("steady-y-smaller-when-leaning", Verdict::Agrees),
        ("steady-orders-handlebar", Verdict::Agrees),
        ("steady-handlebar-action-grows-with-speed", Verdict::Agrees),
        ("steady-abrupt-handlebar-throws-outward", Verdict::Agrees),
        ("steady-gravity-quadrupled-at-half-speed", Verdict::Agrees),
        ("steady-turns-toward-the-lean", Verdict::Agrees),
        ("steady-neglected-term-bound", Verdict::MemoirError),
        ("steady-wheels-lean-alike", Verdict::Agrees),
        ("steady-omega-below-eta", Verdict::Agrees),
        ("steady-shift-gravity-moment", Verdict::Agrees),
        ("steady-shift-centrifugal-moment", Verdict::Agrees),
        ("steady-shift-handlebar-unchanged", Verdict::Agrees),
    ])
}

#[test]
fn claims_have_the_expected_verdicts() {
    let claims = carvallo_report::bicycle::steady::claims();
    common::assert_claim_verdicts(&claims, &expected_claims());
}

/// n° 85: the reduction to the hoop and the unicycle is exact, and the frame's term (4) is
/// the only steady term of n° 83 that fails.
#[test]
fn the_reduction_is_exact_and_term_4_is_the_frames_steady_error() {
    let claims = carvallo_report::bicycle::steady::claims();
    let get = |id: &str| claims.iter().find(|c| c.id == id).unwrap_or_else(|| panic!("{id}"));
    let r = &get("steady-reduces-to-hoop-and-unicycle").evidence;
    for v in r.values() {
        assert!(*v <= 1e-12, "{r:?}");
    }
    let f = &get("steady-frame-six-terms-steady").evidence;
    for k in [1, 2, 3, 5, 6] {
        assert!(f[&format!("max_rel_term{k}_steady")] < 1e-12, "{f:?}");
    }
    assert!(f["max_rel_term4_steady"] > 0.1 && f["max_rel_term4_corrected"] < 1e-12, "{f:?}");
    // The symbolic route names the same failing terms (3)-(6) as the point masses.
    let u = &get("steady-frame-six-terms-unsteady");
    assert_eq!(u.evidence["symbolic_terms_holding"], 2.0, "{u:?}");
    assert_eq!(u.verdict, Verdict::MemoirError);
    let b = &get("steady-neglected-term-bound").evidence;
    assert!(
        b["largest_epsilon_20kmh"] < b["bound"] && b["largest_epsilon_10kmh"] > b["bound"],
        "{b:?}"
    );
}

#[test]
fn claims_text_snapshot() {
    let text = carvallo_report::normalise_numbers(&carvallo_report::claims::render_claims_text(
        &carvallo_report::bicycle::steady::claims(),
    ));
    insta::with_settings!({
        description => "carvallo report: the memoir's claims checked in the bicycle steady report, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_steady_claims_text", text);
    });
}
