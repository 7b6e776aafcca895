//! Numeric spot checks of a few derived hoop formulas: symbolica evaluates the handed-over
//! expressions at fixed points, and the values are compared with the memoir's formulas typed
//! here by hand in plain f64 arithmetic. Tolerance: relative 1e-12 (absolute 1e-12 near 0).

use std::collections::HashMap;

use carvallo_codegen::cas::var;
use carvallo_codegen::Derivation;
use symbolica::atom::{Atom, AtomCore};

const REL_TOL: f64 = 1e-12;
const ABS_TOL: f64 = 1e-12;

struct Point {
    r: f64,
    g: f64,
    mu: f64,
    theta: f64,
    p: f64,
    q: f64,
    rr: f64,
    n: f64,
    s: f64,
}

/// Fixed points (no randomness): a leaning, turning hoop and a nearly upright fast one.
const POINTS: [Point; 3] = [
    Point { r: 0.5, g: 9.81, mu: 2.0, theta: 0.3, p: 0.2, q: 1.7, rr: -0.8, n: -1.5, s: 4.0 },
    Point { r: 0.35, g: 9.80665, mu: 0.7, theta: -0.05, p: -0.4, q: 6.2, rr: 0.3, n: 0.25, s: 9.0 },
    Point { r: 1.2, g: 1.62, mu: 5.0, theta: 1.1, p: 0.0, q: -0.3, rr: 2.0, n: -2.5, s: 1.5 },
];

fn eval(d: &Derivation, name: &str, x: &Point) -> f64 {
    let f = d.formulas.iter().find(|f| f.name == name).expect("formula present");
    let mut map: HashMap<Atom, f64> = HashMap::new();
    for (k, v) in [
        ("R", x.r),
        ("g", x.g),
        ("mu", x.mu),
        ("theta", x.theta),
        ("p", x.p),
        ("q", x.q),
        ("r", x.rr),
        ("n", x.n),
        ("s", x.s),
    ] {
        map.insert(var(k), v);
    }
    f.expr.evaluate(&map).unwrap_or_else(|e| panic!("evaluating {name}: {e:?}"))
}

fn close(name: &str, got: f64, want: f64) {
    let err = (got - want).abs();
    assert!(
        err <= ABS_TOL || err <= REL_TOL * want.abs(),
        "{name}: symbolica {got:.17e} vs hand {want:.17e} (error {err:.3e})"
    );
}

fn derived_formulas_match_hand_values() {
    let d = crate::derived("hoop");
    for x in &POINTS {
        let (st, ct, tt) = (x.theta.sin(), x.theta.cos(), x.theta.tan());
        let gr = x.g / x.r;
        // n° 8, system (1).
        close(
            "pqr_dp",
            eval(d, "pqr_dp", x),
            2.0 * gr * st / 3.0 + 4.0 * x.q * x.rr / 3.0 - x.rr * x.rr * tt / 3.0,
        );
        close("pqr_dq", eval(d, "pqr_dq", x), -x.p * x.rr / 2.0);
        close("pqr_dr", eval(d, "pqr_dr", x), x.p * x.rr * tt - 2.0 * x.p * x.q);
        // n° 7, system (2): ½ n' + ps/cos θ = 0, 2 s' − 4ps tan θ + 3pn cos θ = 0.
        close("pns_dn", eval(d, "pns_dn", x), -2.0 * x.p * x.s / ct);
        close("pns_ds", eval(d, "pns_ds", x), 2.0 * x.p * x.s * tt - 1.5 * x.p * x.n * ct);
        // Energy: μR²(¾p² + q² + ¼r²) + μgR cos θ with q = s + n sin θ, r = n cos θ.
        let (q, r) = (x.s + x.n * st, x.n * ct);
        let energy =
            x.mu * x.r * x.r * (0.75 * x.p * x.p + q * q + 0.25 * r * r) + x.mu * x.g * x.r * ct;
        close("energy", eval(d, "energy", x), energy);
        // n° 9 (S) and n° 10 D.
        let stab =
            -2.0 * gr * ct / 3.0 + x.n * x.n + 8.0 * x.s * x.n * st / 3.0 + 8.0 * x.s * x.s / 3.0;
        close("stability", eval(d, "stability", x), stab);
        close("skid", eval(d, "skid", x), -(x.n * x.n * st + x.s * x.n) / gr);
        // n° 12 (E).
        let e12 = x.n * x.n + 4.0 * x.s * x.n / (3.0 * st) + 2.0 / (3.0 * ct);
        close("equilibrium_n12", eval(d, "equilibrium_n12", x), e12);
        // Inertia (n° 4).
        close("inertia_b", eval(d, "inertia_b", x), 2.0 * x.mu * x.r * x.r);
    }
}

/// Routh's threshold for the thin ring rolling upright (θ = 0, n = 0): the generated stability
/// first member is (8/3)(s² − g/(4R)), so it changes sign at s² = g/(4R). Checked at relative
/// distances 1e-3, 1e-6 and 1e-9 from the threshold on both sides, the sign and the value: the
/// error budget is the rounding of s² and g/(4R) (a few ulps of terms of size (8/3)s² ≈ 13 here,
/// so 1e-14 of that), far below the first member's 2.6e-8 at 1e-9 from the threshold. A
/// generated side whose threshold is off by two parts in 1e9 (evaluated with g scaled by
/// 1 + 2e-9) fails the value check at the first point, 2.6e-8 from Routh's (run and seen).
fn routh_threshold_numerically() {
    let d = crate::derived("hoop");
    let (r, g): (f64, f64) = (0.5, 9.81);
    let s_crit = (g / (4.0 * r)).sqrt();
    for eps in [1e-3, 1e-6, 1e-9] {
        for (s, positive) in [(s_crit * (1.0 + eps), true), (s_crit * (1.0 - eps), false)] {
            let x = Point { r, g, mu: 1.0, theta: 0.0, p: 0.0, q: 0.0, rr: 0.0, n: 0.0, s };
            let v = eval(d, "stability", &x);
            assert_eq!(v > 0.0, positive, "stability at s = {s} (eps {eps}) is {v}");
            let routh = 8.0 / 3.0 * (s * s - g / (4.0 * r));
            let budget = 1e-14 * 8.0 / 3.0 * s * s;
            assert!((v - routh).abs() <= budget, "s = {s}: {v} against Routh's {routh}");
        }
    }
}

#[test]
fn derived_formulas_match_hand_values_test() {
    crate::on_symbolica_thread(derived_formulas_match_hand_values);
}

#[test]
fn routh_threshold_numerically_test() {
    crate::on_symbolica_thread(routh_threshold_numerically);
}
