//! The parameter files of BicycleParameters 1.5.2 shipped in `data/bicycleparameters/` (its
//! measured bicycles): every file is read, and each rule of
//! [`UncertainParams::read`](carvallo::whipple::parameter_text::UncertainParams::read) names its
//! bad value.

use carvallo::whipple::parameter_text::{ParameterTextError, UncertainParams};

/// The bicycles of the data set (`Tms`, the two-mass-skate, is read separately below).
const BICYCLES: [&str; 11] = [
    "Balanceassistv1",
    "Benchmark",
    "Browser",
    "Browserins",
    "Crescendo",
    "Fisher",
    "Pista",
    "Rigid",
    "Silver",
    "Yellow",
    "Yellowrev",
];

fn bicycle_text(name: &str) -> String {
    let path = format!(
        "{}/../../data/bicycleparameters/bicycles/{name}/Parameters/{name}Benchmark.txt",
        env!("CARGO_MANIFEST_DIR")
    );
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

#[test]
fn every_bicycle_file_is_read() {
    for name in BICYCLES {
        let loaded = UncertainParams::read(&bicycle_text(name), false)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let warned: Vec<&str> = loaded.warnings.iter().map(|w| w.key).collect();
        // Browser, Yellow and Yellowrev are measured frames whose moments break the triangle
        // inequality by 1-3 %; the others keep it.
        let expected: &[&str] = match name {
            "Browser" => &["IByy"],
            "Yellow" | "Yellowrev" => &["IHyy"],
            _ => &[],
        };
        assert_eq!(warned, expected, "{name}");
        for w in &loaded.warnings {
            assert!(w.relative > 0.0 && w.relative < 0.05, "{name}: {w}");
        }
        let strict = UncertainParams::read(&bicycle_text(name), true);
        assert_eq!(strict.is_ok(), expected.is_empty(), "{name}: {strict:?}");
    }
}

#[test]
fn a_broken_triangle_inequality_is_named_with_its_relative_violation() {
    let loaded = UncertainParams::read(&bicycle_text("Browser"), false).expect("read");
    let w = &loaded.warnings[0];
    assert_eq!(w.value, loaded.params.params.get("IByy").expect("IByy"));
    // The bound is the sum of the principal moments of the x-z block: its trace.
    let p = &loaded.params.params;
    let trace = p.get("IBxx").expect("IBxx") + p.get("IBzz").expect("IBzz");
    assert!((w.bound - trace).abs() <= 1e-12 * trace, "{w}");
    assert!((w.relative - (w.value - trace) / trace).abs() <= 1e-12, "{w}");
    let text = w.to_string();
    assert!(text.starts_with("IByy 1.3163960125") && text.contains(" % "), "{text}");
    let strict = UncertainParams::read(&bicycle_text("Browser"), true).unwrap_err();
    assert!(strict.to_string().starts_with("invalid IByy 1.3163960125: exceeds IBxx + IBzz"));
}

fn replace_line(text: &str, key: &str, line: &str) -> String {
    text.lines()
        .map(|l| if l.split('=').next().map(str::trim) == Some(key) { line } else { l })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn a_wheel_third_moment_must_be_its_first() {
    let silver = bicycle_text("Silver");
    let bad = replace_line(&silver, "IRzz", "IRzz = 0.08+/-0.001");
    assert_eq!(
        UncertainParams::read(&bad, false).unwrap_err().to_string(),
        "invalid IRzz 0.08: must equal IRxx 0.078 within their stated uncertainties (the \
         model's wheels are axisymmetric)"
    );
    // Within the stated uncertainty it is accepted.
    let near = replace_line(&silver, "IRzz", "IRzz = 0.0785+/-0.001");
    assert!(UncertainParams::read(&near, false).is_ok());
    let bad = replace_line(&silver, "IFzz", "IFzz = 0.09");
    let err = UncertainParams::read(&bad, false).unwrap_err();
    assert!(
        matches!(&err, ParameterTextError::Rule { key, value, .. } if key == "IFzz" && *value == 0.09)
    );
    assert!(err.to_string().contains("IFxx 0.081"), "{err}");
}

#[test]
fn a_lateral_position_must_be_zero() {
    let silver = bicycle_text("Silver");
    let tiny = replace_line(&silver, "yB", "yB = 1e-7");
    assert!(UncertainParams::read(&tiny, false).is_ok());
    let bad = replace_line(&silver, "yH", "yH = 0.01+/-0.0");
    assert_eq!(
        UncertainParams::read(&bad, false).unwrap_err().to_string(),
        "invalid yH 0.01: must be zero to 1e-6 of the wheelbase w = 1.01 (the model is \
         laterally symmetric)"
    );
}

#[test]
fn the_front_frame_parts_make_h() {
    let rigid = bicycle_text("Rigid");
    let whole = UncertainParams::read(&rigid, false).expect("Rigid");
    // The parts alone: H is their combination, which must be the H that BicycleParameters
    // computed and wrote beside them (an independent route: its own parallel-axis code).
    let parts: String = rigid
        .lines()
        .filter(|l| {
            let key = l.split('=').next().unwrap_or("").trim();
            !(key.ends_with('H') && (key.len() == 2) || key.starts_with("IH"))
        })
        .map(|l| format!("{l}\n"))
        .collect();
    assert!(!parts.contains("mH") && !parts.contains("IHxx"));
    let combined = UncertainParams::read(&parts, false).expect("Rigid from its parts");
    for key in ["mH", "xH", "zH", "IHxx", "IHxz", "IHyy", "IHzz"] {
        let (a, b) = (whole.params.params.get(key), combined.params.params.get(key));
        let (a, b) = (a.expect("key"), b.expect("key"));
        assert!((a - b).abs() <= 1e-9 * a.abs(), "{key}: file {a}, parts {b}");
    }
    let k = carvallo::whipple::PARAM_NAMES.iter().position(|n| *n == "mH").expect("mH");
    // mH = mG + mS with sigma sqrt(0.01^2 + 0.01^2), as the file states.
    assert!((combined.params.sigma[k] - 0.0141421356237).abs() < 1e-12);
    // H beside parts that do not make it.
    let bad = replace_line(&rigid, "IHxx", "IHxx = 0.35+/-0.001");
    let err = UncertainParams::read(&bad, false).unwrap_err().to_string();
    assert!(
        err.starts_with("invalid IHxx 0.35: differs from 0.3438")
            && err.ends_with("by the parallel-axis theorem, by more than the stated uncertainties"),
        "{err}"
    );
    // A part given without the other.
    let no_s: String = parts
        .lines()
        .filter(|l| !l.contains('S') || l.starts_with('#'))
        .map(|l| format!("{l}\n"))
        .collect();
    let err = UncertainParams::read(&no_s, false).unwrap_err().to_string();
    assert_eq!(
        err,
        "invalid mS NaN: missing: the front frame's part G is given without its part S"
    );
}

/// The two-mass-skate's matrices as BicycleParameters 1.5.2 computes them
/// (`benchmark_par_to_canonical` on `TmsBenchmark.txt`, computed 2026-12-04): at rR = rF = 0 its
/// formulas give NaN (`SR = IRyy / rR` is 0/0), so they were evaluated at rR = rF = 1e-60, where
/// `SR = SF = 0` exactly and every other term holding a radius has the wheel's mass, zero, as a
/// factor: the limit, by BicycleParameters' own formulas (scripts/bicycleparameters_peer.py).
const PEER_TMS: [[[f64; 2]; 2]; 4] = [
    [[1.6400000000000003, 0.007471008502284511], [0.007471008502284511, 0.0013953992010301863]],
    [[0.0, 4.9849582692509715], [-0.0, 0.03795715320280739]],
    [[-4.2, -0.037355042511422555], [-0.037355042511422555, -0.0032557064754639292]],
    [[0.0, 4.184017731985228], [0.0, 0.03721289529686999]],
];

#[test]
fn the_two_mass_skate_takes_the_limit_of_zero_radius() {
    use carvallo::sweep::{eigen_window, sweep_designs, Designs, EigenGrid, Method, Spread};
    use carvallo::whipple::{Whipple, WhippleParams};
    use carvallo::whipple_uncertainty::speed_gradients;
    let loaded = UncertainParams::read(&bicycle_text("Tms"), true).expect("Tms");
    assert!(loaded.warnings.is_empty());
    let tms = loaded.params.params;
    assert_eq!(
        (tms.get("rR"), tms.get("IRyy"), tms.get("IBxx")),
        (Some(0.0), Some(0.0), Some(0.0))
    );
    let bike = Whipple::new(tms.clone());
    let m = bike.matrices();
    // Each entry to 1e-14 of the largest of its matrix (an entry is a sum of terms of that size).
    for (ours, theirs) in [m.m, m.c1, m.k0, m.k2].iter().zip(PEER_TMS) {
        let scale = theirs.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
        for i in 0..2 {
            for j in 0..2 {
                let (a, b) = (ours[i][j], theirs[i][j]);
                assert!((a - b).abs() <= 1e-14 * scale, "{a} vs {b}");
            }
        }
    }
    // A second route: the model at small positive radii converges to the limit (here the
    // wheels are massless, so the radius enters nothing but IRyy/rR = 0).
    let mut v = *tms.values();
    (v[4], v[22]) = (1e-4, 1e-4);
    let near = Whipple::new(WhippleParams::from_values(v).expect("r = 1e-4")).matrices();
    assert_eq!(near, m);
    // The window by the closed-form Hurwitz route and by the eigenvalues on a grid agree; the
    // weave speed is where BicycleParameters' eigenvalues cross (2.8410083233704153 m/s by a
    // bisection of its largest real part, scripts/bicycleparameters_peer.py).
    let w = bike.stability_window();
    let weave = w.weave_speed.expect("a weave speed");
    assert!((weave - 2.8410083233704153).abs() < 1e-8, "{weave}");
    let grid = eigen_window(&m, 9.81, EigenGrid { vmax: 20.0, points: 4000 }).expect("eig");
    assert!((grid.weave_speed.expect("weave") - weave).abs() < 1e-6);
    // No capsize: a0's coefficient of v^2 is proportional to the gyroscopic terms, zero here.
    assert_eq!((w.capsize_speed, grid.capsize_speed), (None, None), "{w:?} {grid:?}");
    assert_eq!(w.stable, [(weave, f64::INFINITY)]);
    // Sweeps and uncertainty take the limit too.
    let progress = std::sync::atomic::AtomicUsize::new(0);
    let spreads = ["xB", "zB", "xH", "zH", "mH"]
        .map(|name| Spread { name: name.to_string(), rel: 0.05 })
        .to_vec();
    let out = sweep_designs(
        &tms,
        &Designs::Random { count: 1000, spreads, seed: 7 },
        Method::Hurwitz,
        false,
        &progress,
    )
    .expect("sweep");
    assert_eq!((out.rejected, out.summary.count), (0, 1000));
    assert!(out.summary.with_weave > 500, "{:?}", out.summary);
    let (lo, hi) = out.summary.weave_range.expect("range");
    assert!(lo < weave && weave < hi, "{lo} {weave} {hi}");
    let g = speed_gradients(&tms).weave.expect("weave");
    assert_eq!(g.speed, weave);
    // The spin inertias' derivatives are unbounded at zero radius; the others are finite.
    for (k, d) in g.grad.iter().enumerate() {
        let name = carvallo::whipple::PARAM_NAMES[k];
        assert_eq!(d.is_finite(), !["IRyy", "IFyy"].contains(&name), "{name} {d}");
    }
    // Zero radius with a spin inertia is an error saying why.
    let mut spin = *tms.values();
    (spin[6], spin[7]) = (0.1, 0.1);
    assert_eq!(
        WhippleParams::from_values(spin).unwrap_err().to_string(),
        "invalid IRyy 0.1: must be zero for a rear wheel of zero radius rR = 0: its gyroscopic \
         coupling IRyy/rR would be infinite (the two-mass-skate's skates have neither)"
    );
    // Point masses placed so that no mass moves under a lean rate: M is singular.
    let mut flat = *tms.values();
    (flat[9], flat[16]) = (0.0, 0.0);
    assert!(WhippleParams::from_values(flat)
        .unwrap_err()
        .to_string()
        .starts_with("invalid IBxx 0.0: leaves the mass matrix M singular"));
    // The nonlinear model, whose speeds are the wheels' rotation rates, refuses it by name.
    let err = carvallo::whipple_nonlinear::WhippleNonlinear::new(tms).initial_state(3.0, 0.01);
    assert!(err
        .unwrap_err()
        .to_string()
        .starts_with("invalid rR 0.0: must be positive for the nonlinear model"));
}

#[test]
fn random_designs_around_a_broken_inequality_break_it_no_more() {
    use carvallo::numerics::rng::SplitMix64;
    use carvallo::sweep::{sweep_designs, Designs, Method, Spread};
    use carvallo::whipple::{TriangleSlack, WhippleParams};
    let browser = UncertainParams::read(&bicycle_text("Browser"), false).expect("Browser");
    let base = browser.params.params;
    let nominal = browser.warnings[0].relative;
    let slack = TriangleSlack::admitting(&base);
    assert_eq!(slack.0[2], nominal);
    assert!(slack.0[0] == 1e-9 && slack.0[1] == 1e-9 && slack.0[3] == 1e-9);
    // The share of single draws kept, each frame moment scaled by a factor in [0.9, 1.1]: by
    // the rule (no inequality broken by more than Browser's 2.331 %) and by the strict checks.
    let keys = [11, 12, 13, 14];
    let (mut kept, mut strict) = (0, 0);
    let n = 20_000;
    for i in 0..n {
        let mut rng = SplitMix64(1000 + i);
        let mut v = *base.values();
        for k in keys {
            v[k] = rng.scale(v[k], 0.1);
        }
        if let Ok(p) = WhippleParams::from_values_within(v, &slack) {
            kept += 1;
            let (_, warnings) = WhippleParams::from_values_warning(v).expect("valid otherwise");
            assert!(warnings.iter().all(|w| w.relative <= nominal), "{warnings:?}");
            assert_eq!(p.values(), &v);
        }
        strict += usize::from(WhippleParams::from_values(v).is_ok());
    }
    let share = kept as f64 / n as f64;
    // Measured: 10082 of 20000 (50.4 %) kept by the rule, 7801 (39.0 %) by the strict checks
    // (whose draws the rule keeps too, its slack being larger).
    assert_eq!((kept, strict), (10082, 7801));
    assert!((0.45..0.55).contains(&share), "{share}");
    assert!(strict < kept && strict > 0, "{strict} {kept}");
    // The random sweep keeps every design after its redraws; before the rule it kept none.
    let progress = std::sync::atomic::AtomicUsize::new(0);
    let spreads = ["IBxx", "IByy", "IBzz", "IBxz"]
        .map(|name| Spread { name: name.to_string(), rel: 0.1 })
        .to_vec();
    let out = sweep_designs(
        &base,
        &Designs::Random { count: 2000, spreads, seed: 3 },
        Method::Hurwitz,
        true,
        &progress,
    )
    .expect("sweep");
    assert_eq!((out.rejected, out.summary.count), (0, 2000));
    // A grid around it is checked at its corners with the same slack.
    let grid = Designs::Grid(vec![carvallo::sweep::Vary {
        name: "IByy".into(),
        from: base.get("IByy").expect("IByy") * 0.99,
        to: base.get("IByy").expect("IByy"),
        count: 5,
    }]);
    assert!(sweep_designs(&base, &grid, Method::Hurwitz, false, &progress).is_ok());
    let beyond = Designs::Grid(vec![carvallo::sweep::Vary {
        name: "IByy".into(),
        from: base.get("IByy").expect("IByy"),
        to: base.get("IByy").expect("IByy") * 1.01,
        count: 5,
    }]);
    let err = sweep_designs(&base, &beyond, Method::Hurwitz, false, &progress).unwrap_err();
    assert!(err.to_string().contains("invalid IByy 1.329"), "{err}");
}

fn rider_text(bicycle: &str) -> String {
    let path = format!(
        "{}/../../data/bicycleparameters/riders/Jason/Parameters/Jason{bicycle}Benchmark.txt",
        env!("CARGO_MANIFEST_DIR")
    );
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The rear frame with the rider Jason, as BicycleParameters 1.5.2 computes it:
/// `bp.Bicycle(name, pathToData="data")` on the sdist's `data/` folder, then
/// `add_rider("Jason")` (no recalculation: the precalculated rider file), and
/// `parameters['Benchmark'][key]`'s `nominal_value` and `std_dev` (the `uncertainties` package's
/// first-order propagation), for `mB, xB, zB, IBxx, IBxz, IByy, IBzz`. Computed on 2026-12-03
/// in a throwaway venv with `pip install bicycleparameters==1.5.2` (uncertainties 3.2.3).
const PEER_RIDER: [(&str, [(f64, f64); 7]); 3] = [
    (
        "Browser",
        [
            (81.86, 2.000099997500125),
            (0.28909943411648203, 0.0003757297428338847),
            (-1.040292283210937, 0.0017155441437212893),
            (11.35822782891604, 0.0284751583305407),
            (-1.9694273509701732, 0.015396371193683757),
            (12.217332897646934, 0.028663068086089823),
            (3.1211248578428963, 0.0034001841243437),
        ],
    ),
    (
        "Rigid",
        [
            (106.4, 0.01),
            (0.3486779831044643, 0.0014854658794505853),
            (-1.026874672881483, 0.001025986272578155),
            (14.68979624073858, 0.06453967934939966),
            (-0.2587197991996151, 0.046128993922050755),
            (16.471977830552007, 0.06479110702956326),
            (4.11198028556343, 0.019900694430651907),
        ],
    ),
    (
        "Balanceassistv1",
        [
            (106.00000000000001, 0.01),
            (0.3742621385685013, 0.0025472064096751083),
            (-1.0093113209992344, 0.0031842955072935377),
            (19.6692631863791, 0.3301098775210738),
            (-3.5160611716846075, 0.14336520625391866),
            (22.679229256352286, 0.3480780325252135),
            (4.999706659147066, 0.08371849519745167),
        ],
    ),
];

#[test]
fn a_rider_is_added_as_bicycleparameters_adds_it() {
    use carvallo::whipple::parameter_text::{add_rider, Rider};
    use carvallo::whipple::PARAM_NAMES;
    let keys = ["mB", "xB", "zB", "IBxx", "IBxz", "IByy", "IBzz"];
    for (bicycle, peer) in PEER_RIDER {
        let bike = UncertainParams::read(&bicycle_text(bicycle), false).expect("bicycle");
        let rider = Rider::from_text(&rider_text(bicycle)).expect("rider");
        let with = add_rider(&bike.params, &rider).expect("combined");
        // The rider makes Browser's frame keep the triangle inequality.
        assert!(with.warnings.is_empty(), "{bicycle}: {:?}", with.warnings);
        for (key, (value, std)) in keys.iter().zip(peer) {
            let k = PARAM_NAMES.iter().position(|n| n == key).expect("key");
            let (v, s) = (with.params.params.values()[k], with.params.sigma[k]);
            assert!((v - value).abs() <= 1e-13 * value.abs(), "{bicycle} {key}: {v} vs {value}");
            assert!((s - std).abs() <= 1e-7 * std, "{bicycle} {key} sigma: {s} vs {std}");
        }
        // The other parameters are the bicycle's.
        for (k, name) in PARAM_NAMES.iter().enumerate() {
            if !keys.contains(name) {
                assert_eq!(with.params.params.values()[k], bike.params.params.values()[k]);
            }
        }
    }
}

#[test]
fn a_bad_rider_file_is_named() {
    use carvallo::whipple::parameter_text::{add_rider, Rider};
    let good = rider_text("Browser");
    let cases = [
        (
            "mB",
            "mB = -72.0",
            "invalid mB -72.0: must be positive (the rider's mass and principal moments)",
        ),
        ("IBxx", "mR = 2", "line 5: unknown rider parameter `mR` (`mR = 2`)"),
        ("IBzz", "IBzz = big", "line 8: IBzz: value `big` is not a number (`IBzz = big`)"),
    ];
    for (key, line, want) in cases {
        let err = Rider::from_text(&replace_line(&good, key, line)).unwrap_err();
        assert_eq!(err.to_string(), want);
    }
    let missing: String =
        good.lines().filter(|l| !l.starts_with("IByy")).map(|l| format!("{l}\n")).collect();
    assert_eq!(
        Rider::from_text(&missing).unwrap_err().to_string(),
        "invalid IByy NaN: missing from the rider file"
    );
    let aside = Rider::from_text(&replace_line(&good, "yB", "yB = 0.1")).expect("read");
    let bike = UncertainParams::read(&bicycle_text("Browser"), false).expect("bicycle");
    assert_eq!(
        add_rider(&bike.params, &aside).unwrap_err().to_string(),
        "invalid yB 0.1: the rider's lateral position must be zero to 1e-6 of the wheelbase \
         w = 1.121 (the model is laterally symmetric)"
    );
}
