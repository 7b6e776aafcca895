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

/// The claims of n° 107–124: every claim's verdict with the evidence that carries it, each
/// condition with the threshold its `how` states written here (closed forms computed here as a
/// second route), and a snapshot of their text.
#[test]
fn claims_verdicts_and_snapshot() {
    use crate::common::Ev::{self, *};
    use carvallo_report::bicycle::straight::claims;
    use Verdict::*;
    let c = claims();
    let text = carvallo_report::claims::render_claims_text(&c);
    insta::with_settings!({
        description => "carvallo report: the memoir's claims of n° 107-124 (the bicycle without hands), numbers to 4 significant digits",
        omit_expression => true,
    }, {
        insta::assert_snapshot!("bicycle_straight_claims_text", carvallo_report::normalise_numbers(&text));
    });
    let get = |id: &str, key: &str| {
        c.iter().find(|x| x.id == id).and_then(|x| x.evidence.get(key).copied()).expect(key)
    };
    // n° 120's third row, from the printed quartic's coefficients: s^2 = 20.54/0.437 annuls the
    // λ^2 term, 95.6/1.143 the constant term (its upper end, where a root is zero).
    let (row_lo, row_hi) = (20.54 / 0.437, 95.6 / 1.143);
    // The general model's own third row, as the first quartic claim reports it: the other
    // quartic claims are judged against it.
    let third = "bicycle-straight-stable-only-in-third-row";
    let gc2 = get(third, "general model: s^2 annulling the λ^2 term");
    let gc0 = get(third, "general model: s^2 annulling the constant term");
    let lo = get(third, "printed quartic: stable from s^2");
    let glo = get(third, "general model: stable from s^2");
    // The footnote's synthetic division of λ³ + 0,80λ² + 0,191λ + 0,0717 by λ - r.
    let divide = |r: f64| {
        let q1 = 0.80 + r;
        let q0 = 0.191 + r * q1;
        (q1, q0, 0.0717 + r * q0)
    };
    let (m1, m0, m_rem) = divide(0.6744);
    let (p1, p0, p_rem) = divide(-0.6744);
    // n° 122: c1 = R sin η / 2 with R = 0.38 m, η = 25°; the middle factor 1 + x,
    // x = (1/2)(μ/μ1)(e/l) with μ = 70 kg, μ1 = 5 kg, e = 0.20 m, l = 1.10 m, whose elasticity
    // to μ and e is x/(1 + x) and to μ1 minus that.
    let half = 0.5 * 0.38 * 25f64.to_radians().sin();
    let x = 0.5 * 70.0 / 5.0 * 0.20 / 1.10;
    let middle = x / (1.0 + x);
    let fifth = 0.2 * middle;
    // n° 123's pendulum: a = 1.3, k = 0.02, ε = 0.01, τ = e^(επ/a) - 1; the half swing from
    // rest at -θ0 of θ'' - 2εθ' + a²(θ + k) = 0 ends at t = π/ω (ω² = a² - ε²) at
    // θ1 = -k + (θ0 - k) e^(επ/ω).
    let (a, k, eps) = (1.3f64, 0.02, 0.01);
    let tau = (eps * std::f64::consts::PI / a).exp() - 1.0;
    let threshold = (2.0 + tau) * k / tau;
    let omega = (a * a - eps * eps).sqrt();
    let swing = |th0: f64| (th0 - k) * (eps * std::f64::consts::PI / omega).exp() - k;
    // The divergence θ'' = a²θ from rest (a = 2, k = 0.1, t = 1): k + (θ0 - k) cosh(at) with
    // friction, θ0 cosh(at) without.
    let (ad, kd, th0) = (2.0f64, 0.1, 0.3);
    // A small disturbance is bounded when the last window's peak grows by at most e^1.5.
    let bounded = 1.5f64.exp();
    let w = "bicycle-straight-friction-widens-window";
    let widens: &[Ev] = &[
        Near("cases", 16.0, 0.0),
        Near("cases where the window widens", 2.0, 0.0),
        // Bearing friction: the capsize speed does not move, the benchmark's weave speed rises.
        Near("benchmark, bearing c = 1: capsize speed shift (m/s)", 0.0, 1e-9),
        Above("benchmark, bearing c = 1: weave speed shift (m/s)", 0.05),
        // The viscous pivot lowers the weave speed in every case (the next claim's count).
        Below("Carvallo, ground pivot c = 0.03: weave speed shift (m/s)", 0.0),
        Below("Carvallo, ground pivot c = 0.1: weave speed shift (m/s)", 0.0),
        Below("Carvallo, ground pivot c = 0.3: weave speed shift (m/s)", 0.0),
        Below("Carvallo, ground pivot c = 1: weave speed shift (m/s)", 0.0),
        Below("benchmark, ground pivot c = 0.03: weave speed shift (m/s)", 0.0),
        Below("benchmark, ground pivot c = 0.1: weave speed shift (m/s)", 0.0),
        Below("benchmark, ground pivot c = 0.3: weave speed shift (m/s)", 0.0),
        Below("benchmark, ground pivot c = 1: weave speed shift (m/s)", 0.0),
        // n° 123 in the memoir's terms (Coulomb pivoting friction): 0.98 times the weave speed
        // keeps both disturbances bounded, the speeds above the capsize speed do not, every
        // speed inside the window does, the three routes agree, no switch is unresolved.
        Below("Carvallo, 0.98 × weave speed, lean 0.001 rad: peak growth over the last 22 s window", bounded),
        Below("Carvallo, 0.98 × weave speed, lean 0.01 rad: peak growth over the last 22 s window", bounded),
        Below("benchmark, 0.98 × weave speed, lean 0.001 rad: peak growth over the last 26 s window", bounded),
        Below("benchmark, 0.98 × weave speed, lean 0.01 rad: peak growth over the last 26 s window", bounded),
        Above("Carvallo, 1.02 × capsize speed, lean 0.01 rad: peak growth over the last 48 s window", bounded),
        Above("Carvallo, 1.05 × capsize speed, lean 0.01 rad: peak growth over the last 22 s window", bounded),
        Above("Carvallo, 1.1 × capsize speed, lean 0.01 rad: peak growth over the last 14 s window", bounded),
        Above("benchmark, 1.02 × capsize speed, lean 0.01 rad: peak growth over the last 150 s window", bounded),
        Above("benchmark, 1.05 × capsize speed, lean 0.01 rad: peak growth over the last 70 s window", bounded),
        Above("benchmark, 1.1 × capsize speed, lean 0.01 rad: peak growth over the last 40 s window", bounded),
        Below("Carvallo, 0.25 of the window, lean 0.01 rad: peak growth over the last 33 s window", bounded),
        Below("Carvallo, 0.5 of the window, lean 0.01 rad: peak growth over the last 25 s window", bounded),
        Below("Carvallo, 0.75 of the window, lean 0.01 rad: peak growth over the last 57 s window", bounded),
        Below("benchmark, 0.25 of the window, lean 0.01 rad: peak growth over the last 12 s window", bounded),
        Below("benchmark, 0.5 of the window, lean 0.01 rad: peak growth over the last 25 s window", bounded),
        Below("benchmark, 0.75 of the window, lean 0.01 rad: peak growth over the last 66 s window", bounded),
        // The smoothed route classifies the nearest speed below the weave speed alike.
        Below("Carvallo, 0.98 × weave speed, smoothed friction (ε = 1e-3 rad/s): peak growth over the last 22 s window", bounded),
        Below("benchmark, 0.98 × weave speed, smoothed friction (ε = 1e-3 rad/s): peak growth over the last 26 s window", bounded),
        // Lowest bounded speed: the window extended by 2 to 10 %.
        Above("Carvallo: lowest sampled speed / weave speed with a bounded small disturbance", 0.9 - 1e-12),
        Below("Carvallo: lowest sampled speed / weave speed with a bounded small disturbance", 0.98 + 1e-12),
        Above("benchmark: lowest sampled speed / weave speed with a bounded small disturbance", 0.9 - 1e-12),
        Below("benchmark: lowest sampled speed / weave speed with a bounded small disturbance", 0.98 + 1e-12),
        Near("Carvallo: speeds above the capsize speed bounded", 0.0, 0.0),
        Near("benchmark: speeds above the capsize speed bounded", 0.0, 0.0),
        Near("Carvallo: speeds inside the window unbounded", 0.0, 0.0),
        Near("benchmark: speeds inside the window unbounded", 0.0, 0.0),
        Near("Carvallo: steps with unresolved switches", 0.0, 0.0),
        Near("benchmark: steps with unresolved switches", 0.0, 0.0),
        Near("Carvallo: smoothed route and steady turn and first stuck phase agree (1 = yes)", 1.0, 0.0),
        Near("benchmark: smoothed route and steady turn and first stuck phase agree (1 = yes)", 1.0, 0.0),
        // The closed-form first stuck phase within 1e-6 s, the closed-form steady turn within
        // 1e-6 relative.
        Below("Carvallo, 0.98 × weave speed: |simulated - closed form| first stuck phase (s)", 1e-6),
        Below("benchmark, 0.98 × weave speed: |simulated - closed form| first stuck phase (s)", 1e-6),
        Equal(
            "Carvallo, 0.98 × weave speed, lean 0.01 rad: first stuck phase ends, simulated (s)",
            "Carvallo, 0.98 × weave speed, lean 0.01 rad: first stuck phase ends, closed form (s)",
            1e-6,
        ),
        Equal(
            "benchmark, 0.98 × weave speed, lean 0.01 rad: first stuck phase ends, simulated (s)",
            "benchmark, 0.98 × weave speed, lean 0.01 rad: first stuck phase ends, closed form (s)",
            1e-6,
        ),
        Below("Carvallo, middle of the window: relative difference run / closed form", 1e-6),
        Below("benchmark, middle of the window: relative difference run / closed form", 1e-6),
        Equal(
            "Carvallo, middle of the window: final lean of the run (rad)",
            "Carvallo, middle of the window: steady turn held by the friction, closed form (rad)",
            1e-6 * 0.2,
        ),
        Equal(
            "benchmark, middle of the window: final lean of the run (rad)",
            "benchmark, middle of the window: steady turn held by the friction, closed form (rad)",
            1e-6 * 0.2,
        ),
    ];
    crate::common::assert_claim_evidence(
        &c,
        &[
            // The five printed γ'' cells fail, every part's column holds.
            (
                "bicycle-straight-table-gamma2-signs",
                MemoirError,
                &[
                    Near("gamma'' cells as printed that fail", 5.0, 0.0),
                    Above("checks of the parts' columns", 0.0),
                    Equal("checks of the parts' columns that hold", "checks of the parts' columns", 0.0),
                ],
            ),
            (
                "bicycle-straight-permanences-necessary",
                Agrees,
                &[
                    Near("quartics", 3000.0, 0.0),
                    Equal("with every coefficient positive", "quartics", 0.0),
                ],
            ),
            (
                third,
                Agrees,
                &[
                    Near("stable intervals of the printed quartic", 1.0, 0.0),
                    Above("printed quartic: stable from s^2", row_lo),
                    Below("printed quartic: stable to s^2", row_hi * (1.0 + 1e-12)),
                    // Its upper end is the constant term's root.
                    Near("printed quartic: stable to s^2", row_hi, 1e-9),
                    Exceeds("general model: stable from s^2", "general model: s^2 annulling the λ^2 term"),
                    AtMostTimes(
                        "general model: stable to s^2",
                        1.0 + 1e-12,
                        "general model: s^2 annulling the constant term",
                    ),
                ],
            ),
            // At 83.6 and just below every root has a negative real part; the pair's real part
            // is the printed pair's -0,1256/2 (three-digit coefficients: within 1e-3).
            (
                "bicycle-straight-upper-limit-stable",
                Agrees,
                &[
                    Below("next largest real part at 83.6", 0.0),
                    Below("largest real part at 83.6 (1 - 1e-3)", 0.0),
                    Below("general model: next largest real part at gc0", 0.0),
                    Below("general model: largest real part at gc0 (1 - 1e-3)", 0.0),
                    Near("next largest real part at 83.6", -0.1256 / 2.0, 1e-3),
                    Near("largest real part at 83.6 (the zero root)", 0.0, 1e-3),
                ],
            ),
            // The printed divisor λ - 0,6744 leaves neither the printed pair (within one unit
            // of its last digit) nor a remainder below 1e-3; λ + 0,6744 leaves both.
            (
                "bicycle-straight-footnote-divisor",
                MemoirError,
                &[
                    Near("by λ - 0,6744: q1", m1, 1e-12),
                    Near("by λ - 0,6744: q0", m0, 1e-12),
                    Near("by λ - 0,6744: remainder", m_rem, 1e-12),
                    Above("by λ - 0,6744: q1", 0.1256 + 1e-4),
                    Above("by λ - 0,6744: remainder", 1e-3),
                    Near("by λ + 0,6744: q1", p1, 1e-12),
                    Near("by λ + 0,6744: q0", p0, 1e-12),
                    Near("by λ + 0,6744: remainder", p_rem, 1e-12),
                    Near("by λ + 0,6744: q1", 0.1256, 1e-4),
                    Near("by λ + 0,6744: q0", 0.1062, 1e-4),
                    Near("by λ + 0,6744: remainder", 0.0, 1e-3),
                ],
            ),
            (
                "bicycle-straight-47-not-stable",
                Agrees,
                &[
                    Above("largest real part at s^2 = 47.0", 0.0),
                    Above("lower end of the stable range, s^2", 47.0),
                    Near("lower end of the stable range, s^2", lo, 0.0),
                    Above("general model: largest real part at gc2", 0.0),
                    Above("general model: lower end of its stable range, s^2", gc2),
                    Near("general model: lower end of its stable range, s^2", glo, 0.0),
                ],
            ),
            (
                "bicycle-straight-zero-root-turns-negative",
                Agrees,
                &[
                    Below("largest real root just below 83.6", 0.0),
                    Below("general model: largest real root just below gc0", 0.0),
                ],
            ),
            // 201 points from 47.0 to 83.6 (1 - 1e-6), each with two negative real roots.
            (
                "bicycle-straight-real-roots-stay-negative",
                Agrees,
                &[
                    Near("points", 201.0, 0.0),
                    Equal("points with two negative real roots and a pair", "points", 0.0),
                    Near("general model: points with two negative real roots and a pair", 201.0, 0.0),
                    Above("smallest |root| (re + im)", 0.0),
                ],
            ),
            // A pure imaginary pair (real part within 1e-9) with μ² = a3/a1 within 1e-6.
            (
                "bicycle-straight-lower-limit-imaginary-pair",
                Agrees,
                &[
                    Above("lower limit s^2 (printed quartic)", 47.0),
                    Below("lower limit s^2 (printed quartic)", 83.6),
                    Near("lower limit s^2 (printed quartic)", lo, 0.0),
                    Near("real part of the critical pair", 0.0, 1e-9),
                    Below("|Im^2 - a3/a1| / (a3/a1)", 1e-6),
                    Above("general model: lower limit s^2", gc2),
                    Below("general model: lower limit s^2", gc0),
                    Near("general model: real part of the critical pair", 0.0, 1e-9),
                    Below("general model: |Im^2 - a3/a1| / (a3/a1)", 1e-6),
                ],
            ),
            // Within 1 %.
            (
                "bicycle-straight-half-trail-rule",
                Agrees,
                &[
                    Near("R sin η / 2 (m)", half, 1e-15),
                    Near("c1 (m)", 0.08, 0.0),
                    Near("relative difference", (0.08 - half).abs() / half, 1e-12),
                    Below("relative difference", 0.01),
                ],
            ),
            // For μ, μ1 and e every outer elasticity below a fifth of the largest middle one;
            // the middle ones x/(1 + x) (central differences, step 1e-6: within 1e-8).
            (
                "bicycle-straight-middle-factor-dominates",
                Agrees,
                &[
                    Near("elasticity of the 2nd factor to mu", middle, 1e-8),
                    Near("elasticity of the 2nd factor to e", middle, 1e-8),
                    Near("elasticity of the 2nd factor to mu1", -middle, 1e-8),
                    Below("elasticity of the 1st factor to mu", fifth),
                    Above("elasticity of the 1st factor to mu", -fifth),
                    Below("elasticity of the 1st factor to mu1", fifth),
                    Above("elasticity of the 1st factor to mu1", -fifth),
                    Below("elasticity of the 1st factor to e", fifth),
                    Above("elasticity of the 1st factor to e", -fifth),
                    Below("elasticity of the 3rd factor to mu", fifth),
                    Above("elasticity of the 3rd factor to mu", -fifth),
                    Below("elasticity of the 3rd factor to mu1", fifth),
                    Above("elasticity of the 3rd factor to mu1", -fifth),
                    Below("elasticity of the 3rd factor to e", fifth),
                    Above("elasticity of the 3rd factor to e", -fifth),
                    // The first factor g sin η l / (R^2 cos η): elasticity -2 to R, 1 to l.
                    Near("elasticity of the 1st factor to R", -2.0, 1e-8),
                    Near("elasticity of the 1st factor to l", 1.0, 1e-8),
                ],
            ),
            // The signs of the upper limit's derivatives; the window widens with e and with
            // lighter wheels (the note).
            (
                "bicycle-straight-design-rule",
                Agrees,
                &[
                    Below("Carvallo: d capsize / d mu1 (m/s per kg)", 0.0),
                    Above("Carvallo: d capsize / d e (m/s per m)", 0.0),
                    Below("benchmark: d capsize / d ln(front wheel)", 0.0),
                    Below("benchmark: d capsize / d ln(both wheels)", 0.0),
                    Above("benchmark: d capsize / d ln xB", 0.0),
                    Exceeds("Carvallo: d weave / d mu1 (m/s per kg)", "Carvallo: d capsize / d mu1 (m/s per kg)"),
                    Exceeds("Carvallo: d capsize / d e (m/s per m)", "Carvallo: d weave / d e (m/s per m)"),
                ],
            ),
            // Below the threshold (2 + τ)k/τ the swing shrinks, above it grows; the swings
            // against the closed form (RK4, 20 000 steps per 1/a: within 1e-9).
            (
                "bicycle-straight-pendulum-friction-threshold",
                Agrees,
                &[
                    Near("threshold θ0 (rad)", threshold, 1e-12),
                    Near("θ0 below", 0.8 * threshold, 1e-12),
                    Near("θ0 above", 1.25 * threshold, 1e-12),
                    Exceeds("θ0 below", "|θ1| from below"),
                    Exceeds("|θ1| from above", "θ0 above"),
                    Near("|θ1| from below", swing(0.8 * threshold), 1e-9),
                    Near("|θ1| from above", swing(1.25 * threshold), 1e-9),
                ],
            ),
            // No start below k; the speed ratio (θ0 - k)/θ0 within 1e-9; the angles against
            // the closed forms within 1e-9.
            (
                "bicycle-straight-friction-slows-divergence",
                Agrees,
                &[
                    Near("θ(1) from θ0 = 0.05", 0.05, 0.0),
                    Exceeds("θ(1) from θ0 = 0.3 without friction", "θ(1) from θ0 = 0.3 with friction"),
                    Near("speed ratio with/without friction", (th0 - kd) / th0, 1e-9),
                    Below("|ratio - (θ0 - k)/θ0|", 1e-9),
                    Near("θ(1) from θ0 = 0.3 with friction", kd + (th0 - kd) * ad.cosh(), 1e-9),
                    Near("θ(1) from θ0 = 0.3 without friction", th0 * ad.cosh(), 1e-9),
                ],
            ),
            (w, Agrees, widens),
            // Judged in the pivoting reading: the viscous pivot lowers the weave speed in every
            // case, the Coulomb pivot keeps the weave bounded at both bicycles; the dry bearing
            // friction never shrinks the lean.
            (
                "bicycle-straight-friction-damps-weave",
                Agrees,
                &[
                    Near("ground-pivot cases", 8.0, 0.0),
                    Equal("ground-pivot cases lowering the weave speed", "ground-pivot cases", 0.0),
                    Near("Coulomb (ground pivot): bicycles", 2.0, 0.0),
                    Equal(
                        "Coulomb (ground pivot): bicycles whose weave at 0.98 weave speed stays bounded",
                        "Coulomb (ground pivot): bicycles",
                        0.0,
                    ),
                    Near("Coulomb (bearing) cases", 6.0, 0.0),
                    Near("Coulomb (bearing) cases with a shrinking lean", 0.0, 0.0),
                    Near("viscous cases", 16.0, 0.0),
                ],
            ),
            // sin i within 1e-6; n° 25's tan i off by 1/cos i - 1 at i = 0.2.
            (
                "bicycle-straight-slope-moment-sin-i",
                Agrees,
                &[
                    Below("max relative difference, sin i form", 1e-6),
                    Near("max relative difference, tan i form (n° 25)", 1.0 / 0.2f64.cos() - 1.0, 1e-6),
                ],
            ),
        ],
    );
}
