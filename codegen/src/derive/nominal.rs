//! Nominal arguments of the models: where each is evaluated in practice, handed over with each
//! derivation ([`crate::Derivation::nominal`]) for the second sample of the optimising
//! lowering's error comparison (`emit::optimize::choose`).
//!
//! Uniform arguments in $[0.5, 1.5]$ never bring two nearly equal moments of inertia or a
//! mass ratio of 40 together, so an optimised form that loses digits in such a near
//! cancellation passes there. The second sample scales each nominal value by a uniform factor
//! in $[0.8, 1.2]$ (the bench's spread); an argument without a nominal value is drawn as in the
//! first sample.
//!
//! Sources: the whipple models take the 2007 benchmark bicycle (Meijaard, Papadopoulos, Ruina,
//! Schwab, Proc. R. Soc. A 463, Table 1; `shared/anchors`) at 5 m/s with the bench's feedback
//! gains, and for the nonlinear one a state of moderate lean, steer and rates at about 4.5 m/s;
//! the hoop, the discussion of its motion and the unicycle take the values of the bench's
//! scenes (`model_value` in `crates/carvallo-cli/src/bench/tables.rs`: a wheel of radius
//! 0.5 m, its moments A = 100 and B = 99.5 nearly equal as for a thin rider-and-wheel body);
//! the memoir's bicycle models take his old bicycle of n° 52 and n° 117, as the runtime does.

/// The 2007 benchmark's parameters, in the order of the whipple models' parameters.
const BENCHMARK: [(&str, f64); 26] = [
    ("w", 1.02),
    ("c", 0.08),
    ("lambda", std::f64::consts::PI / 10.0),
    ("g", 9.81),
    ("rR", 0.3),
    ("mR", 2.0),
    ("IRxx", 0.0603),
    ("IRyy", 0.12),
    ("xB", 0.3),
    ("zB", -0.9),
    ("mB", 85.0),
    ("IBxx", 9.2),
    ("IByy", 11.0),
    ("IBzz", 2.8),
    ("IBxz", 2.4),
    ("xH", 0.9),
    ("zH", -0.7),
    ("mH", 4.0),
    ("IHxx", 0.05892),
    ("IHyy", 0.06),
    ("IHzz", 0.00708),
    ("IHxz", -0.00756),
    ("rF", 0.35),
    ("mF", 3.0),
    ("IFxx", 0.1405),
    ("IFyy", 0.28),
];

/// The wheeled pendulum (`derive::wheeled_pendulum`): a personal transporter with its rider,
/// illustrative values of that size (not a published data set), at 2 m/s, pitched and turning
/// gently, the motors pushing apart.
const WHEELED_PENDULUM: [(&str, f64); 20] = [
    ("r", 0.24),
    ("W", 0.58),
    ("mW", 4.0),
    ("IWd", 0.06),
    ("IWa", 0.12),
    ("l", 0.9),
    ("mB", 90.0),
    ("IBxx", 12.0),
    ("IByy", 12.5),
    ("IBzz", 1.5),
    ("g", 9.81),
    ("phi", 0.0),
    ("theta", 0.05),
    ("thetad", 0.1),
    ("thetaLd", -8.0),
    ("thetaRd", -8.5),
    ("TL", 1.0),
    ("TR", -1.0),
    ("v", 2.0),
    ("psi", 0.0),
];

/// The linear whipple model's inputs: the speed and the feedback gains of the bench.
const WHIPPLE_INPUTS: [(&str, f64); 9] = [
    ("v", 5.0),
    ("k_roll_roll", 100.0),
    ("k_roll_steer", 10.0),
    ("k_roll_roll_rate", 20.0),
    ("k_roll_steer_rate", 2.0),
    ("k_steer_roll", 10.0),
    ("k_steer_steer", 2.0),
    ("k_steer_roll_rate", -10.0),
    ("k_steer_steer_rate", 1.0),
];

/// The nonlinear whipple model's inputs: lean, pitch, steer and the independent rates (the rear
/// wheel's rate relative to the frame about -v / rR at 4.5 m/s).
const NONLINEAR_INPUTS: [(&str, f64); 6] = [
    ("phi", 0.1),
    ("theta", 0.02),
    ("delta", 0.2),
    ("phid", 0.5),
    ("deltad", 0.5),
    ("thetaRd", -15.0),
];

/// The hoop's and the unicycle's arguments (the bench's scenes).
const WHEELS: [(&str, f64); 21] = [
    ("R", 0.5),
    ("g", 9.81),
    ("mu", 1.2),
    ("theta", 0.3),
    ("p", 0.1),
    ("q", 2.0),
    ("r", -0.4),
    ("n", -0.8),
    ("s", 3.0),
    ("z", 1.25),
    ("A", 100.0),
    ("B", 99.5),
    ("C", 1.4),
    ("L", 0.1),
    ("mu1", 5.0),
    ("A1", 1.875),
    ("B1", 2.5),
    ("C1", 0.625),
    ("dp", 0.01),
    ("dn", 0.01),
    ("ds", 0.01),
];

/// The memoir's old bicycle of n° 52 and n° 117 (`carvallo::bicycle::straight::Constants::MEMOIR`):
/// wheels of radius 0.38 m, wheelbase 1.10 m, trail 0.08 m, steering axis at 25° from the
/// vertical, the mounted frame's centre of mass 0.20 m ahead of the rear wheel and 1 m high,
/// 70 kg, hoop wheels of 5 kg, A + 2A₁ = 100, C = 4, L = 14 kg m²; at 3.3 m/s, inside his
/// self-stable window 3.12–3.49 m/s.
const STRAIGHT: [(&str, f64); 13] = [
    ("R", 0.38),
    ("l", 1.10),
    ("c_1", 0.08),
    ("eta", 0.436_332_312_998_582_4),
    ("ecg", 0.20),
    ("h", 1.0),
    ("mu", 70.0),
    ("mu1", 5.0),
    ("A2", 100.0),
    ("C", 4.0),
    ("L", 14.0),
    ("g", 9.81),
    ("s", 3.3),
];

/// The same bicycle's geometry (n° 52: R, l, the fork offset c, the steering axis' angle σ₀ =
/// 25°) in a moderately leaned and steered configuration: lean θ and steer γ of 0.1 rad, the
/// angles σ and μ near σ₀.
const GEOMETRY: [(&str, f64); 8] = [
    ("R", 0.38),
    ("l", 1.10),
    ("c", 0.08),
    ("sigma0", 0.436_332_312_998_582_4),
    ("theta", 0.1),
    ("gamma", 0.1),
    ("sigma", 0.436_332_312_998_582_4),
    ("mu", 0.436_332_312_998_582_4),
];

/// The steady-turning model's constants (`carvallo::bicycle::steady::BicycleParams::memoir`:
/// the memoir's R, l, c, e, h, μ, μ₁ and hoop wheels; the frame's A, B, C, L, which the memoir
/// does not give, as the runtime's illustrative values). Its state variables have no nominal
/// values and are sampled uniformly.
const STEADY: [(&str, f64); 15] = [
    ("R", 0.38),
    ("g", 9.81),
    ("mu", 70.0),
    ("e", 0.15),
    ("h", 1.0),
    ("A", 75.0),
    ("B", 78.0),
    ("C", 8.0),
    ("L", 6.0),
    ("mu1", 5.0),
    ("A1", 1.083),
    ("B1", 1.444),
    ("C1", 0.361),
    ("l", 1.10),
    ("c", 0.08),
];

/// Moore's leaning rider (`lean_rider`): BicycleParameters' `mooreriderlean2012_browser_jason`
/// (`data/mooreriderlean2012/browser_jason.toml`), its upright pitch as `lam`, and a state of
/// moderate roll, steer, lean and rates at about 4.8 m/s, with moderate torques.
const LEAN_RIDER: [(&str, f64); 49] = [
    ("c9", 0.0),
    ("d1", 0.9631492634872098),
    ("d2", 0.4338396131640938),
    ("d3", 0.0705000000001252),
    ("d4", -0.6704626684911591),
    ("g", 9.81),
    ("ic11", 2.296859222953584),
    ("ic22", 2.9922715238),
    ("ic31", 0.01594448114273473),
    ("ic33", 1.5101858377464155),
    ("id11", 0.0904106601579),
    ("id22", 0.152467620286),
    ("ie11", 0.2811355367159554),
    ("ie22", 0.246138810935),
    ("ie31", 0.0063377219110826045),
    ("ie33", 0.06782113764394461),
    ("if11", 0.0883819364527),
    ("if22", 0.149389340425),
    ("ig11", 2.038073562525466),
    ("ig22", 1.692108544034995),
    ("ig31", 0.002113501449812),
    ("ig33", 1.100753962972129),
    ("k9", 0.0),
    ("l1", 0.47759794513190806),
    ("l2", -0.1680324796714025),
    ("l3", -0.07654646159268344),
    ("l4", -0.47166687226492093),
    ("l5", 0.231223496809401),
    ("l6", -0.271613547251923),
    ("mc", 33.044),
    ("md", 3.11),
    ("me", 3.22),
    ("mf", 2.02),
    ("mg", 48.816),
    ("rf", 0.34352982332),
    ("rr", 0.340958858855),
    ("lam", 0.399680398707),
    ("q4", 0.1),
    ("q5", 0.4),
    ("q7", 0.15),
    ("q9", 0.05),
    ("q4d", 0.3),
    ("q6d", -14.0),
    ("q7d", 0.5),
    ("q9d", 0.2),
    ("T4", 1.0),
    ("T6", 0.5),
    ("T7", 0.3),
    ("T9", 2.0),
];

/// The nominal values of `model`'s arguments (names not among its parameters and inputs are
/// ignored by the sampling).
pub fn values(model: &str) -> Vec<(String, f64)> {
    let tables: &[&[(&str, f64)]] = match model {
        "whipple" => &[&BENCHMARK, &WHIPPLE_INPUTS],
        "whipple_nonlinear" => &[&BENCHMARK, &NONLINEAR_INPUTS],
        "hoop" | "hoop_discussion" | "unicycle" => &[&WHEELS],
        "bicycle_straight" => &[&STRAIGHT],
        "bicycle_geometry" | "bicycle_kinematics" => &[&GEOMETRY],
        "bicycle_steady" => &[&STEADY],
        "lean_rider" => &[&LEAN_RIDER],
        "wheeled_pendulum" => &[&WHEELED_PENDULUM],
        _ => &[],
    };
    tables.iter().flat_map(|t| t.iter()).map(|&(n, v)| (n.to_string(), v)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The benchmark table is in the whipple models' parameter order, and each model finds its
    /// own table.
    #[test]
    fn the_benchmark_follows_the_parameter_order() {
        let names: Vec<&str> = BENCHMARK.iter().map(|(n, _)| *n).collect();
        assert_eq!(names, crate::derive::whipple::PARAMS);
        let get = |model: &str, name: &str| {
            values(model).into_iter().find(|(n, _)| n == name).map(|(_, v)| v)
        };
        assert_eq!(get("whipple", "IBxz"), Some(2.4));
        assert_eq!(get("whipple_nonlinear", "thetaRd"), Some(-15.0));
        assert_eq!(get("bicycle_geometry", "R"), Some(0.38));
        let eta = get("bicycle_straight", "eta").expect("eta");
        assert!((eta - 25f64.to_radians()).abs() < 1e-15, "{eta}");
        assert_eq!(get("nowhere", "R"), None);
        assert_eq!(get("unicycle", "B"), Some(99.5));
    }
}
