//! Fuzzing of the bicycle parameter reader `WhippleParams::from_toml_str` with proptest: four
//! properties of [`CASES`] cases each, every runner seeded with a fixed seed so that a run is
//! reproducible, in the normal test run.
//!
//! Properties: arbitrary text never panics; replacing one value of the benchmark file by an
//! arbitrary TOML value either reads back the value or fails naming that key; removing a key
//! or adding an unknown one fails naming it; random perturbations of every value either give
//! a parameter set whose characteristic polynomial is finite or fail with a typed
//! `ParameterError::InvalidParameter` naming a key of the model. Plus hand-written cases for every rejection.

use carvallo::whipple::{WhippleError, WhippleParams, BENCHMARK_TOML, PARAM_NAMES};
use carvallo::ParameterError;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

const CASES: u32 = 2000;

/// A runner with a fixed seed, so a run is reproducible.
fn runner(seed: u8) -> TestRunner {
    let config = Config { cases: CASES, failure_persistence: None, ..Config::default() };
    TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]))
}

/// The benchmark file with the line of `key` replaced by `line` (or removed when empty).
fn with_line(key: &str, line: &str) -> String {
    BENCHMARK_TOML
        .lines()
        .map(|l| {
            if l.split('=').next().map(str::trim) == Some(key) {
                line.to_string()
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Whether the error names `key`: as its key, or in its message (a syntax error quotes the
/// line; an inconsistency between moments of inertia names the other key and lists `key`).
fn names_key(err: &WhippleError, key: &str) -> bool {
    let listed = err.to_string().split(|c: char| !c.is_alphanumeric()).any(|w| w == key);
    match err {
        WhippleError::MissingKey { key: k }
        | WhippleError::Parameter(ParameterError::InvalidParameter { name: k, .. }) => {
            *k == key || listed
        }
        WhippleError::UnknownKey { key: k } | WhippleError::NotANumber { key: k, .. } => k == key,
        WhippleError::Syntax { .. } => listed,
    }
}

/// TOML values of every kind, with the special floats and huge integers.
fn toml_value() -> impl Strategy<Value = String> {
    prop_oneof![
        any::<f64>().prop_map(|x| format!("{x:?}")),
        prop_oneof![Just("nan"), Just("inf"), Just("-inf"), Just("1e400"), Just("-0.0"), Just("0")]
            .prop_map(str::to_string),
        any::<i64>().prop_map(|n| n.to_string()),
        "[0-9]{19,25}".prop_map(|s| s),
        "\"[a-z0-9*/. ]{0,8}\"".prop_map(|s| s),
        any::<bool>().prop_map(|b| b.to_string()),
        Just("[1, 2]".to_string()),
        Just("{ a = 1 }".to_string()),
    ]
}

#[test]
fn arbitrary_text_never_panics() {
    runner(1)
        .run(&any::<String>(), |text| {
            // Either read, a valid bicycle (every parameter finite, and the values accepted
            // again by the validating constructor), or rejected by a message that names what
            // is wrong: the reader's syntax message, or a key (and value) found in the text.
            for t in [text.clone(), format!("[parameters]\n{text}")] {
                match WhippleParams::from_toml_str(&t) {
                    Ok(p) => {
                        for key in PARAM_NAMES {
                            let x = p.get(key).unwrap_or(f64::NAN);
                            prop_assert!(x.is_finite(), "{key} read as {x} from {t:?}");
                        }
                        prop_assert_eq!(WhippleParams::from_values(*p.values()).ok(), Some(p));
                    }
                    Err(e) => {
                        let msg = e.to_string();
                        match &e {
                            WhippleError::Syntax { message } => prop_assert!(
                                !message.is_empty()
                                    && msg == format!("invalid parameter file: {message}"),
                                "{msg}"
                            ),
                            WhippleError::MissingKey { key } => {
                                prop_assert!(
                                    PARAM_NAMES.contains(key) && msg.contains(key),
                                    "{msg}"
                                )
                            }
                            WhippleError::UnknownKey { key } => {
                                prop_assert!(
                                    t.contains(key.as_str()) && msg.contains(key.as_str()),
                                    "{msg}"
                                )
                            }
                            WhippleError::NotANumber { key, value } => prop_assert!(
                                t.contains(key.as_str())
                                    && msg.contains(key.as_str())
                                    && msg.contains(value.as_str()),
                                "{msg}"
                            ),
                            WhippleError::Parameter(ParameterError::InvalidParameter {
                                name,
                                value,
                                ..
                            }) => {
                                prop_assert!(
                                    PARAM_NAMES.contains(name) && msg.contains(name),
                                    "{msg}"
                                );
                                prop_assert!(msg.contains(&format!("{value:?}")), "{msg}");
                            }
                        }
                    }
                }
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn one_arbitrary_value_is_read_or_rejected_by_name() {
    let strategy = (0..PARAM_NAMES.len(), toml_value());
    runner(2)
        .run(&strategy, |(i, value)| {
            let key = PARAM_NAMES[i];
            let text = with_line(key, &format!("{key} = {value}"));
            match WhippleParams::from_toml_str(&text) {
                Ok(p) => {
                    let x = p.get(key).unwrap();
                    prop_assert!(x.is_finite(), "{key} = {value} accepted as {x}");
                    let poly = carvallo::whipple::Whipple::new(p).char_poly(5.0);
                    prop_assert!(poly.iter().all(|a| a.is_finite()), "{key} = {value}: {poly:?}");
                }
                Err(err) => {
                    prop_assert!(names_key(&err, key), "{key} = {value}: {err}");
                    let shown = err.to_string();
                    prop_assert!(!shown.ends_with('.'), "{shown}");
                }
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn a_missing_or_unknown_key_is_named() {
    let strategy = (0..PARAM_NAMES.len(), "[a-zA-Z_][a-zA-Z0-9_]{0,6}", any::<bool>());
    runner(3)
        .run(&strategy, |(i, extra, remove)| {
            let key = PARAM_NAMES[i];
            if remove {
                let err = WhippleParams::from_toml_str(&with_line(key, "")).unwrap_err();
                prop_assert_eq!(err, WhippleError::MissingKey { key });
            } else if !PARAM_NAMES.contains(&extra.as_str()) {
                let text = format!("{BENCHMARK_TOML}{extra} = 1.0\n");
                let err = WhippleParams::from_toml_str(&text).unwrap_err();
                prop_assert_eq!(err, WhippleError::UnknownKey { key: extra.clone() });
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn perturbed_bicycles_are_usable_or_rejected_with_a_reason() {
    let base = *WhippleParams::benchmark().values();
    let strategy = proptest::collection::vec(-1.5f64..1.5, PARAM_NAMES.len());
    runner(4)
        .run(&strategy, |factors| {
            let mut values = base;
            for (v, f) in values.iter_mut().zip(&factors) {
                *v *= 1.0 + f;
            }
            match WhippleParams::from_values(values) {
                Ok(p) => {
                    let poly = carvallo::whipple::Whipple::new(p).char_poly(4.0);
                    prop_assert!(poly.iter().all(|a| a.is_finite()), "{poly:?}");
                }
                Err(WhippleError::Parameter(ParameterError::InvalidParameter {
                    name: key,
                    value,
                    reason,
                })) => {
                    prop_assert!(PARAM_NAMES.contains(&key));
                    prop_assert!(!reason.is_empty());
                    let i = PARAM_NAMES.iter().position(|k| *k == key).unwrap();
                    prop_assert_eq!(value.to_bits(), values[i].to_bits());
                }
                Err(other) => prop_assert!(false, "unexpected error {other}"),
            }
            Ok(())
        })
        .unwrap();
}

fn reject(key: &str, value: &str) -> String {
    WhippleParams::from_toml_str(&with_line(key, &format!("{key} = {value}")))
        .unwrap_err()
        .to_string()
}

#[test]
fn every_rejection_names_the_key_and_the_value() {
    assert_eq!(reject("mB", "-85.0"), "invalid mB -85.0: must be positive");
    assert_eq!(reject("rR", "-0.3"), "invalid rR -0.3: must not be negative");
    // A zero radius is the two-mass-skate's only without spin inertia.
    assert_eq!(
        reject("rR", "0"),
        "invalid IRyy 0.12: must be zero for a rear wheel of zero radius rR = 0: its gyroscopic \
         coupling IRyy/rR would be infinite (the two-mass-skate's skates have neither)"
    );
    assert_eq!(reject("w", "nan"), "invalid w NaN: must be finite");
    assert_eq!(reject("g", "inf"), "invalid g inf: must be finite");
    assert_eq!(
        reject("xB", "1e400"),
        "invalid parameter file: line 10: invalid floating-point number (`xB = 1e400`)"
    );
    assert_eq!(
        reject("zB", "-2e16"),
        "invalid zB -2e16: is too large (magnitude above 1e15 in SI units)"
    );
    assert_eq!(reject("mF", "1e-18"), "invalid mF 1e-18: is too small (below 1e-15 in SI units)");
    assert_eq!(
        reject("lambda", "\"pi/2\""),
        "invalid lambda 1.5707963267948966: must lie strictly between -pi/2 and pi/2"
    );
    assert_eq!(
        reject("IBxz", "6.0"),
        "invalid IBxz 6.0: makes the inertia block [[IBxx, IBxz], [IBxz, IBzz]] not positive semidefinite"
    );
    assert_eq!(
        reject("IRyy", "0.2"),
        "invalid IRyy 0.2: exceeds 2 IRxx (triangle inequality of the wheel's moments)"
    );
    assert_eq!(
        reject("IByy", "13.0"),
        "invalid IByy 13.0: exceeds IBxx + IBzz, the sum of the other two principal moments (triangle inequality)"
    );
    assert_eq!(
        reject("IHyy", "0.01"),
        "invalid IHyy 0.01: is too small: the largest principal moment of IHxx, IHzz, IHxz exceeds the sum of the other two (triangle inequality)"
    );
    assert_eq!(reject("c", "\"fast\""), "parameter c = \"fast\" is not a number");
    assert_eq!(reject("c", "true"), "parameter c = true is not a number");
    assert!(reject("c", "123456789012345678901234").starts_with("invalid parameter file: "));
    let err = WhippleParams::from_toml_str("[parameters]\nw = 1.02\n").unwrap_err();
    assert_eq!(err.to_string(), "missing parameter c");
    let err = WhippleParams::from_toml_str("w = 1\n").unwrap_err();
    assert_eq!(err.to_string(), "invalid parameter file: no [parameters] table");
    // The anchors file itself reads (its other tables are ignored).
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../data/anchors/whipple-benchmark.toml");
    let anchors = std::fs::read_to_string(&path).unwrap();
    let read = WhippleParams::from_toml_str(&anchors).unwrap();
    let bench = WhippleParams::benchmark();
    for (a, b) in read.values().iter().zip(bench.values()) {
        assert!((a - b).abs() <= 1e-15 * b.abs(), "{a} vs {b}");
    }
}
