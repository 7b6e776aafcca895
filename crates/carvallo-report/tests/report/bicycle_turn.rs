//! Tests of the steady-turn stability concordance (memoir n° 101–105, module
//! `carvallo_report::bicycle::turn`): the expected verdicts (the findings listed), every
//! approximate coefficient judged against its declared second order consistently with its
//! relative difference, every section present, the old upright-only n° 105 entry gone, and a
//! snapshot of the text table with numbers normalised to 4 significant digits.

use carvallo::bicycle_straight::Constants;
use carvallo_report::bicycle::turn::{entries, new_bicycle_central, GRID_GAMMA, GRID_KMH, TURNS};
use carvallo_report::Derived;
use carvallo_report::{render_text_normalised, Memoir, Verdict};

/// Entries whose verdict is `derivation-differs`, by (section, quantity prefix).
const FINDINGS: &[(&str, &str)] = &[
    ("103", "dn/dtheta at fixed gamma and s (1/s per rad), gamma = 5°, 20 km/h"),
    ("103", "dn/dtheta at fixed gamma and s (1/s per rad), gamma = 5°, 10 km/h"),
    ("104", "centrifugal part / gravity part of df/dtheta, gamma = 5°, 20 km/h"),
    ("104", "centrifugal part / gravity part of df/dtheta, gamma = 10°, 20 km/h"),
    ("104", "centrifugal part / gravity part of df/dtheta, gamma = 5°, 10 km/h"),
];

#[test]
fn verdicts_are_the_expected_ones() {
    let e = entries();
    // Two upright entries, nine per turn, then the new bicycle's roots and grid.
    assert_eq!(e.len(), 2 + 9 * TURNS.len() + 2);
    for x in &e {
        let finding = FINDINGS.iter().any(|(s, q)| x.section == *s && x.quantity == *q);
        let order =
            x.note.split("theta0^2 + gamma^2 = ").nth(1).and_then(|t| t.parse::<f64>().ok());
        // Approximations of the declared second order are `rounding` (one verdict policy: an
        // approximation agrees only when exact).
        let expected = if finding {
            Verdict::DerivationDiffers
        } else if order.is_some() || x.quantity.starts_with("df/dtheta upright") {
            Verdict::Rounding
        } else {
            Verdict::Agrees
        };
        assert_eq!(x.verdict, expected, "n° {} {}: {}", x.section, x.quantity, x.note);
        // Approximations: the verdict follows the relative difference and the stated order.
        if let (Some(rel), Memoir::Number(_), Some(order)) = (x.rel_diff, &x.memoir, order) {
            assert_eq!(x.verdict == Verdict::Rounding, rel <= order, "{}", x.quantity);
            assert!(rel > crate::common::AGREEMENT, "{}: an exact approximation", x.quantity);
        }
    }
    for section in ["86", "101", "102", "103", "104", "105"] {
        assert!(e.iter().any(|x| x.section == section), "no entry for n° {section}");
    }
    let old = carvallo_report::bicycle::steady::entries();
    assert!(old.iter().all(|x| x.section != "105"), "the upright-only n° 105 entry is back");
}

#[test]
fn text_report_snapshot() {
    let text = render_text_normalised(&entries());
    insta::with_settings!({
        description => "carvallo report: steady turns with the handlebar held (n° 86, 101-105), numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_turn_report_text", text);
    });
}

/// The new bicycle of n° 122: the variant with the old frame's central moments has them
/// (through the general model's mapping, an independent path), the printed n° 122 constants,
/// and the grid entry counts every grid point in each of its three variants.
#[test]
fn new_bicycle_entries() {
    let central = |k: &Constants| {
        let v = k.whipple_values();
        let get = |n: &str| v.iter().find(|(m, _)| *m == n).map(|x| x.1).expect("mapped");
        [get("IBxx"), get("IBzz"), get("IBxz"), get("mB"), get("xB"), get("w"), get("mR")]
    };
    let (old, new, carried) = (
        central(&Constants::MEMOIR),
        central(&Constants::MEMOIR_NEW),
        central(&new_bicycle_central()),
    );
    for i in 0..3 {
        assert!(
            (carried[i] - old[i]).abs() <= 1e-12 * old[0],
            "central moment {i}: {carried:?} vs {old:?}"
        );
    }
    assert_eq!(carried[3..], new[3..], "the n° 122 constants");
    assert!(new[1] < 0.0, "n° 117's C with the new mu e^2 leaves I_Bzz = {}", new[1]);
    let e = entries();
    let grid = e
        .iter()
        .find(|x| x.section == "105" && x.quantity.contains("across a grid"))
        .expect("grid entry");
    let Derived::Numbers(n) = &grid.derived else { panic!("numbers expected: {:?}", grid.derived) };
    let total = (GRID_GAMMA.len() * GRID_KMH.len()) as f64;
    assert_eq!(n["grid_points"], total);
    for key in ["saddle_points", "bearing_held_saddle_points", "central_moments_saddle_points"] {
        assert_eq!(n[key], total, "{key}: {}", grid.note);
    }
    assert!(n["lambda_plus_min"] > 0.0 && n["lambda_plus_min"] <= n["lambda_plus_max"]);
    let roots = e
        .iter()
        .find(|x| x.quantity.starts_with("roots of (C)") && x.quantity.contains("new bicycle"))
        .expect("new bicycle roots");
    let Derived::Numbers(r) = &roots.derived else { panic!("numbers expected") };
    assert!(r["lambda_minus"] < 0.0 && r["lambda_plus"] > 0.0, "{r:?}");
    // The n° 105 turn lies on the grid: its root is inside the grid's range.
    assert!(r["lambda_plus"] >= n["lambda_plus_min"] && r["lambda_plus"] <= n["lambda_plus_max"]);
}

/// The claims of n° 101–106: every one holds (the memoir's conclusions on the held handlebar
/// are confirmed) but the trail factor's bound, a rounding, each with the evidence that
/// carries its verdict (thresholds written here), and a snapshot of their text.
#[test]
fn claims_hold_and_snapshot() {
    use crate::common::Ev::*;
    use carvallo_report::bicycle::turn::claims;
    use Verdict::*;
    let c = claims();
    // n° 102: the factor as defined, by hand from n° 96's bicycle (R = 0.38 m, c = 0.08 m,
    // l = 1.10 m, η = 25°): 0.07327, above the bound 0.073 by less than its last digit, so the
    // bound is the factor rounded (`rounding`, issue 38), not a strict inequality that holds.
    let by_hand = (0.38 * 25f64.to_radians().sin() - 0.08) / 1.10;
    // n° 102 with the constants of n° 117: μ = 70 kg, R = 0.38 m, A + 2 A1 = 100, μ1 = 5 kg
    // (the frame's A = (A + 2 A1) - 3 μ1 R^2), L = 14.
    let mu_r2 = 70.0 * 0.38 * 0.38;
    let frame_a = 100.0 - 3.0 * 5.0 * 0.38 * 0.38;
    // The fifteen turns of (C): γ = 2, 5, 10° × 5 to 25 km/h.
    let turns = Near("turns", 15.0, 0.0);
    crate::common::assert_claim_evidence(
        &c,
        &[
            (
                "bicycle-turn-extremes-opposite-signs",
                Agrees,
                &[
                    turns,
                    Equal("turns with df/dp' > 0 > df/dtheta", "turns", 0.0),
                    Above("min df/dp' (kg m^2)", 0.0),
                    Below("max df/dtheta (N m)", 0.0),
                ],
            ),
            (
                "bicycle-turn-trail-factor-small",
                Rounding,
                &[
                    Near("(R sin ω - c)/l", by_hand, 1e-15),
                    Near("memoir bound", 0.073, 0.0),
                    Above("(R sin ω - c)/l", 0.073),
                    Near("(R sin ω - c)/l", 0.073, 0.001),
                ],
            ),
            (
                "bicycle-turn-mu-r2-below-half-a",
                Agrees,
                &[
                    Near("mu R^2 (kg m^2)", mu_r2, 1e-12),
                    Near("A / 2 (kg m^2)", frame_a / 2.0, 1e-12),
                    Exceeds("A / 2 (kg m^2)", "mu R^2 (kg m^2)"),
                ],
            ),
            // "notably smaller": at most a quarter of A.
            (
                "bicycle-turn-l-below-a",
                Agrees,
                &[
                    Near("L (kg m^2)", 14.0, 0.0),
                    Near("A (kg m^2)", frame_a, 1e-12),
                    Near("L / A", 14.0 / frame_a, 1e-15),
                    Below("L / A", 0.25),
                ],
            ),
            ("bicycle-turn-y-terms-cancel", Agrees, &[Below("largest relative remainder", 1e-12)]),
            // Of the first order like tan θ: at most tan θ, and doubling within 10 % when both
            // angles double.
            (
                "bicycle-turn-x-log-derivative-small",
                Agrees,
                &[
                    Below("largest |(1/x) dx/dθ| / tan θ", 1.0),
                    Near("(1/x) dx/dθ at 10°/-10° over 5°/-5°", 2.0, 0.2),
                ],
            ),
            (
                "bicycle-turn-dfdtheta-negative",
                Agrees,
                &[
                    turns,
                    Equal("turns with df/dtheta < 0", "turns", 0.0),
                    Below("max df/dtheta (N m)", 0.0),
                ],
            ),
            (
                "bicycle-turn-centrifugal-second-order",
                Agrees,
                &[
                    turns,
                    Below("max |centrifugal / gravity| / (theta0^2 + gamma^2)", 1.0),
                    Above("max |centrifugal / gravity| / (theta0^2 + gamma^2)", 0.1),
                ],
            ),
            (
                "bicycle-turn-unstable-whatever-speed",
                Agrees,
                &[
                    turns,
                    Equal("turns with real roots of opposite signs", "turns", 0.0),
                    Above("min positive root (1/s)", 0.0),
                ],
            ),
            // Independent of the speed to the second order: the spread over the speeds within
            // θ0^2 + γ^2.
            (
                "bicycle-turn-extremes-independent-of-speed",
                Agrees,
                &[
                    Below("max spread of df/dp' / (theta0^2 + gamma^2)", 1.0),
                    Below("max spread of df/dtheta / (theta0^2 + gamma^2)", 1.0),
                ],
            ),
            // As at rest: the root within 10 %, and so the first-order shift due to df/dp λ.
            (
                "bicycle-turn-instability-as-at-rest",
                Agrees,
                &[
                    Below("max |lambda+ / lambda+(rest) - 1|", 0.1),
                    Below("max |df/dp| / (2 sqrt(df/dp' |df/dtheta|))", 0.1),
                ],
            ),
            (
                "bicycle-turn-centrifugal-moment-decreases",
                Agrees,
                &[
                    turns,
                    Equal(
                        "turns with the centrifugal part of the gravity part's sign",
                        "turns",
                        0.0,
                    ),
                ],
            ),
            // Steering into the fall opposes it (B < 0) above a walking speed.
            (
                "bicycle-turn-steer-into-the-fall",
                Agrees,
                &[
                    Below("B at 10 km/h (N m)", 0.0),
                    Above("B changes sign at (km/h)", 1.0),
                    Below("B changes sign at (km/h)", 3.0),
                ],
            ),
        ],
    );
    let text = carvallo_report::claims::render_claims_text(&c);
    insta::with_settings!({
        description => "carvallo report: the memoir's claims of n° 101-106 (the handlebar held)",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_turn_claims_text", carvallo_report::normalise_numbers(&text));
    });
}
