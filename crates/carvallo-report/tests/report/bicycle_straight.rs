//! Tests of the concordance of memoir n° 116–123 (the bicycle without hands near straight
//! running): the expected verdict of every entry that is a finding, every other entry agreeing
//! or a slide-rule rounding, and a snapshot of the text table with numbers normalised to 4
//! significant digits.

use std::collections::BTreeMap;

use carvallo_report::bicycle::straight::entries;
use carvallo_report::{render_text_normalised, Verdict};

use crate::common;

/// Entries whose verdict is not `agrees` or `rounding`, by (section, quantity).
fn findings() -> BTreeMap<(&'static str, &'static str), Verdict> {
    use Verdict::*;
    BTreeMap::from([
        (("116", "table (δθ) frame, γ''"), MemoirError),
        (("116", "table (δθ) front wheel, γ''"), MemoirError),
        (("116", "table (δγ) frame, γ''"), MemoirError),
        (("116", "table (δγ) rear wheel, γ''"), MemoirError),
        (("116", "table (δγ) front wheel, γ''"), MemoirError),
        (("116", "bicycle straight check fall_frame_gamma2_as_printed"), MemoirError),
        (("116", "bicycle straight check fall_front_wheel_gamma2_as_printed"), MemoirError),
        (("116", "bicycle straight check bar_frame_gamma2_as_printed"), MemoirError),
        (("116", "bicycle straight check bar_rear_wheel_gamma2_as_printed"), MemoirError),
        (("116", "bicycle straight check bar_front_wheel_gamma2_as_printed"), MemoirError),
        (("117", "B, coefficient of s^2"), MemoirError),
        (("117", "A1' / s"), MemoirError),
        (("117", "B1' / s"), MemoirError),
        (("117", "B1' first term"), Ocr),
        (("119", "(⊖) coefficient of λ^3"), Ocr),
        (("119", "(⊖) coefficient of λ^2"), Ocr),
        (("119", "(⊖) coefficient of λ"), Ocr),
        (("120", "λ coefficient, 1/s^2 part 4.83"), MemoirError),
        (("120", "s^2 annulling the λ coefficient, 37.05"), MemoirError),
        (("121", "μ^2 = a3 / a1"), Ocr),
        (("121", "equation (6), coefficient of s^2: -64.6"), MemoirError),
        (("121", "equation (6), constant: -179.1"), MemoirError),
        (("121", "lower limit s^2 = 67.3 from (5)"), MemoirError),
        (("121", "lower limit speed 10 km/h"), MemoirError),
        (("122", "ratio s'^2/s^2 of the three-factor formula"), MemoirError),
        (("124", "(δν) virtual work on inclined ground, as printed"), Ocr),
        (("124", "(δσ) virtual work on inclined ground"), MemoirError),
    ])
}

#[test]
fn verdicts_are_the_expected_ones() {
    let entries = entries();
    common::assert_verdicts(&entries, &findings(), &[]);
    // The concordance with the general model is the central finding: it must agree.
    let c = entries.iter().find(|e| e.section == "116" && e.quantity.starts_with("the twelve"));
    assert_eq!(c.map(|e| e.verdict), Some(Verdict::Agrees), "{c:?}");
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&entries());
    insta::with_settings!({
        description => "carvallo report: memoir n° 116-123, the bicycle without hands near straight running, numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_straight_report_text", text);
    });
}

/// The claims of n° 107–124: the verdicts that decide the issue (the γ'' cells, friction, the
/// design rule, the slope), the margins behind them, and a snapshot of their text.
#[test]
fn claims_verdicts_and_snapshot() {
    use carvallo_report::bicycle::straight::claims;
    let c = claims();
    let text = carvallo_report::claims::render_claims_text(&c);
    insta::with_settings!({
        description => "carvallo report: the memoir's claims of n° 107-124 (the bicycle without hands), numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_straight_claims_text", carvallo_report::normalise_numbers(&text));
    });
    let verdict = |id: &str| c.iter().find(|x| x.id == id).map(|x| x.verdict).expect(id);
    let get = |id: &str, key: &str| {
        c.iter().find(|x| x.id == id).and_then(|x| x.evidence.get(key).copied()).expect(key)
    };
    let not_agreeing: BTreeMap<&str, Verdict> = c
        .iter()
        .filter(|x| x.verdict != Verdict::Agrees)
        .map(|x| (x.id.as_str(), x.verdict))
        .collect();
    assert_eq!(
        not_agreeing,
        BTreeMap::from([
            ("bicycle-straight-table-gamma2-signs", Verdict::MemoirError),
            ("bicycle-straight-footnote-divisor", Verdict::MemoirError),
        ])
    );
    assert_eq!(
        get("bicycle-straight-table-gamma2-signs", "gamma'' cells as printed that fail"),
        5.0
    );
    // The design rule: the signs of the upper limit's derivatives.
    assert!(get("bicycle-straight-design-rule", "Carvallo: d capsize / d mu1 (m/s per kg)") < 0.0);
    assert!(get("bicycle-straight-design-rule", "Carvallo: d capsize / d e (m/s per m)") > 0.0);
    assert!(get("bicycle-straight-design-rule", "benchmark: d capsize / d ln(front wheel)") < 0.0);
    assert!(get("bicycle-straight-design-rule", "benchmark: d capsize / d ln xB") > 0.0);
    // Bearing friction: the capsize speed does not move, the benchmark's weave speed rises.
    let dc = get(
        "bicycle-straight-friction-widens-window",
        "benchmark, bearing c = 1: capsize speed shift (m/s)",
    );
    assert!(dc.abs() < 1e-9, "{dc}");
    let dw = get(
        "bicycle-straight-friction-widens-window",
        "benchmark, bearing c = 1: weave speed shift (m/s)",
    );
    assert!(dw > 0.05, "{dw}");
    let tan =
        get("bicycle-straight-slope-moment-sin-i", "max relative difference, tan i form (n° 25)");
    assert!((tan - (1.0 / 0.2f64.cos() - 1.0)).abs() < 1e-6, "{tan}");
    assert_eq!(verdict("bicycle-straight-slope-moment-sin-i"), Verdict::Agrees);
    // The weave damped only by the ground-pivot reading; dry friction in the bearing makes it worse.
    assert_eq!(
        get("bicycle-straight-friction-damps-weave", "ground-pivot cases lowering the weave speed"),
        8.0
    );
    assert_eq!(
        get(
            "bicycle-straight-friction-damps-weave",
            "Coulomb (bearing) cases with a shrinking lean"
        ),
        0.0
    );
    assert_eq!(
        get("bicycle-straight-friction-widens-window", "cases where the window widens"),
        2.0
    );
    // n° 123 in the memoir's own terms (Coulomb pivoting friction): the lower limit moves down,
    // the upper one does not, and the three routes agree.
    let w = "bicycle-straight-friction-widens-window";
    for bike in ["Carvallo", "benchmark"] {
        let lowest = get(
            w,
            &format!("{bike}: lowest sampled speed / weave speed with a bounded small disturbance"),
        );
        assert!((0.9..0.98 + 1e-12).contains(&lowest), "{bike}: {lowest}");
        assert_eq!(get(w, &format!("{bike}: speeds above the capsize speed bounded")), 0.0);
        assert_eq!(get(w, &format!("{bike}: speeds inside the window unbounded")), 0.0);
        assert_eq!(get(w, &format!("{bike}: steps with unresolved switches")), 0.0);
        let key =
            format!("{bike}: smoothed route and steady turn and first stuck phase agree (1 = yes)");
        assert_eq!(get(w, &key), 1.0);
        let gap = get(
            w,
            &format!("{bike}, 0.98 × weave speed: |simulated - closed form| first stuck phase (s)"),
        );
        assert!(gap <= 1e-6, "{bike}: {gap}");
    }
    assert_eq!(verdict(w), Verdict::Agrees);
    assert_eq!(verdict("bicycle-straight-friction-damps-weave"), Verdict::Agrees);
}
