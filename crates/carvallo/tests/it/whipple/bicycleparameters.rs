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

#[test]
fn the_two_mass_skate_is_refused_for_now() {
    let err = UncertainParams::read(&bicycle_text("Tms"), false).unwrap_err();
    assert_eq!(err.to_string(), "invalid rR 0.0: must be positive");
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
