//! Property tests of the parameter readers (BicycleParameters' text, rider files, the anchors
//! TOML, [`WhippleParams::from_values`]): arbitrary text, mutated lines of the shipped files and
//! arbitrary numbers never make them panic, and every refusal is one message naming the key or
//! the line at fault, lower case, without a trailing period.

use carvallo::whipple::parameter_text::{add_rider, ParameterTextError, Rider, UncertainParams};
use carvallo::whipple::{WhippleParams, PARAM_NAMES};
use proptest::prelude::*;

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/bicycleparameters");

/// Every bicycle and rider file shipped, as text (read once).
fn files() -> &'static [(String, String)] {
    static FILES: std::sync::OnceLock<Vec<(String, String)>> = std::sync::OnceLock::new();
    FILES.get_or_init(|| {
        let mut out = Vec::new();
        for kind in ["bicycles", "riders"] {
            let mut dirs: Vec<_> = std::fs::read_dir(format!("{DATA}/{kind}"))
                .expect("data/bicycleparameters")
                .map(|e| e.expect("entry").path())
                .collect();
            dirs.sort();
            // Some bicycles and riders are shipped as raw measurements only (no Parameters).
            for dir in dirs.into_iter().filter(|d| d.join("Parameters").is_dir()) {
                let mut paths: Vec<_> = std::fs::read_dir(dir.join("Parameters"))
                    .expect("Parameters")
                    .map(|e| e.expect("entry").path())
                    .collect();
                paths.sort();
                for p in paths {
                    let text = std::fs::read_to_string(&p).expect("text");
                    out.push((p.display().to_string(), text));
                }
            }
        }
        assert_eq!(out.len(), 15, "12 bicycles and 3 riders");
        out
    })
}

/// The form of every message: one line, not empty, lower case first letter, no trailing period.
fn well_formed(message: &str) {
    assert!(!message.is_empty() && !message.contains('\n'), "{message:?}");
    assert!(!message.ends_with('.'), "{message:?}");
    let first = message.chars().next().unwrap_or(' ');
    assert!(!first.is_uppercase(), "{message:?}");
}

/// A refusal of a text names a line, a key or a value: a line error quotes the line; the others
/// start with `invalid <key>`, `missing parameter <key>`, `unknown parameter` or name the TOML
/// reader's line.
fn names_what(e: &ParameterTextError) {
    let m = e.to_string();
    well_formed(&m);
    let named = m.starts_with("line ")
        || m.starts_with("invalid ")
        || m.starts_with("missing parameter ")
        || m.starts_with("unknown parameter ")
        || m.starts_with("parameter ");
    assert!(named, "{m}");
}

/// Every reader on one text: never a panic, and any error well formed.
fn read_all(text: &str) {
    for strict in [false, true] {
        match UncertainParams::read(text, strict) {
            Ok(loaded) => {
                // What is read is a valid bicycle, with warnings only when not strict.
                assert!(!strict || loaded.warnings.is_empty());
                let v = *loaded.params.params.values();
                assert!(v.iter().all(|x| x.is_finite()));
            }
            Err(e) => names_what(&e),
        }
    }
    if let Err(e) = UncertainParams::from_any(text) {
        names_what(&e);
    }
    if let Err(e) = WhippleParams::from_toml_str(text) {
        well_formed(&e.to_string());
    }
    if let Err(e) = Rider::from_text(text) {
        names_what(&e);
    }
}

/// Values a mutated line may take: the awkward numbers and some text.
fn awkward_value() -> impl Strategy<Value = String> {
    prop_oneof![
        any::<f64>().prop_map(|x| format!("{x:?}")),
        (-1e3f64..1e3).prop_map(|x| format!("{x}")),
        (any::<f64>(), any::<f64>()).prop_map(|(x, s)| format!("{x:?}+/-{s:?}")),
        Just("0.0".to_string()),
        Just("-0.0".to_string()),
        Just("nan".to_string()),
        Just("inf+/-1".to_string()),
        Just("1e400".to_string()),
        Just("5e-324".to_string()),
        Just("(1.0+/-0.1)e-999".to_string()),
        Just("(1.0+/-0.1".to_string()),
        Just("pi/0".to_string()),
        Just("".to_string()),
        "[ -~]{0,12}",
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,200}") {
        read_all(&text);
    }

    #[test]
    fn arbitrary_lines_never_panic(lines in prop::collection::vec(
        (prop::sample::select(PARAM_NAMES.to_vec()), awkward_value())
            .prop_map(|(k, v)| format!("{k} = {v}")),
        0..30,
    )) {
        read_all(&lines.join("\n"));
    }

    #[test]
    fn a_mutated_line_of_a_shipped_file_is_read_or_named(
        file in 0usize..15,
        line in 0usize..40,
        value in awkward_value(),
    ) {
        let (path, text) = &files()[file];
        let lines: Vec<&str> = text.lines().collect();
        let k = line % lines.len();
        let key = lines[k].split('=').next().unwrap_or("").trim().to_string();
        let mutated: Vec<String> = lines
            .iter()
            .enumerate()
            .map(|(i, l)| if i == k { format!("{key} = {value}") } else { l.to_string() })
            .collect();
        let mutated = mutated.join("\n");
        read_all(&mutated);
        if path.contains("/riders/") {
            if let Ok(rider) = Rider::from_text(&mutated) {
                let bike = path.rsplit('/').next().unwrap_or("")
                    .trim_start_matches("Jason").trim_end_matches("Benchmark.txt").to_string();
                let bike_text = std::fs::read_to_string(format!(
                    "{DATA}/bicycles/{bike}/Parameters/{bike}Benchmark.txt"
                )).expect("the rider's bicycle");
                let base = UncertainParams::read(&bike_text, false).expect("shipped");
                if let Err(e) = add_rider(&base.params, &rider) {
                    names_what(&e);
                }
            }
        } else if let Err(e) = UncertainParams::read(&mutated, false) {
            // The error is about the mutated line or a key: it names one of them.
            let m = e.to_string();
            prop_assert!(
                m.contains(&key) || PARAM_NAMES.iter().any(|n| m.contains(n)) || m.starts_with("line "),
                "{} line {}: {}", path, k + 1, m
            );
        }
    }

    #[test]
    fn arbitrary_numbers_never_panic(
        base in prop::sample::select(vec![0usize, 1, 2]),
        changes in prop::collection::vec((0usize..26, any::<f64>()), 1..6),
    ) {
        let mut v = match base {
            0 => *WhippleParams::benchmark().values(),
            1 => *UncertainParams::read(&files()[9].1, false).expect("Tms").params.params.values(),
            _ => *UncertainParams::read(&files()[2].1, false).expect("Browser").params.params.values(),
        };
        for (k, x) in changes {
            v[k] = x;
        }
        match WhippleParams::from_values(v) {
            Ok(p) => {
                // Strictly valid: no warning either, and the model evaluates to finite matrices.
                let (_, w) = WhippleParams::from_values_warning(v).expect("lenient accepts it");
                prop_assert!(w.is_empty());
                let m = carvallo::whipple::Whipple::new(p).matrices();
                prop_assert!(m.m.iter().flatten().all(|x| x.is_finite()), "{:?}", v);
            }
            Err(e) => {
                let m = e.to_string();
                well_formed(&m);
                prop_assert!(m.starts_with("invalid "), "{}", m);
                prop_assert!(PARAM_NAMES.iter().any(|n| m.starts_with(&format!("invalid {n} "))), "{}", m);
            }
        }
    }
}
