//! Tests of `carvallo turn` (memoir n° 99–105): the JSON output against the library's own
//! computation of the same turn (the CLI adds nothing), the saddle of n° 105 in the output,
//! and bad input as an error naming the value with exit code 2.

use std::process::Command;

use carvallo::bicycle_straight::Constants;
use carvallo::bicycle_turn::{Hold, LockedSteer};

fn carvallo(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo")).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn json_is_the_library_turn() {
    let (code, out, err) =
        carvallo(&["turn", "--model", "carvallo", "--gamma", "8", "--speed", "4.5", "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let bike = LockedSteer::new(Constants::MEMOIR).unwrap();
    let t = bike.steady_turn(8f64.to_radians(), 4.5).unwrap();
    let c = bike.fall_equation(&t, Hold::Rolling).unwrap();
    // Same computation; serde_json's default parser may read a printed float one unit in
    // the last place off, hence the relative 1e-15.
    let same = |key: &str, x: f64| {
        let y = v[key].as_f64().unwrap();
        assert!((y - x).abs() <= 1e-15 * x.abs(), "{key}: {y} {x}");
    };
    same("lean", t.lean);
    same("turning_rate", t.yaw_rate);
    same("dfdpp", c.dfdpp);
    same("dfdp", c.dfdp);
    same("dfdtheta", c.dfdtheta);
    let r: Vec<f64> = v["roots"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    assert_eq!(r.len(), 2, "{r:?}");
    assert!(r[0] < 0.0 && r[1] > 0.0, "{r:?}");
    // The roots are those of the printed fall equation
    // $f_{pp} x^2 + f_p x + f_\theta = 0$, checked here by substitution (not by the library's
    // quadratic formula): the residual is rounding, a few ulps of the largest term.
    let (a, b, c) = (num(&v, "dfdpp"), num(&v, "dfdp"), num(&v, "dfdtheta"));
    for x in &r {
        let terms = [a * x * x, b * x, c];
        let residual: f64 = terms.iter().sum();
        let size = terms.iter().fold(0.0f64, |m, t| m.max(t.abs()));
        assert!(residual.abs() <= 1e-13 * size, "root {x}: residual {residual:e} of {size:e}");
    }
    // Vieta: the product of the roots is $f_\theta / f_{pp}$.
    assert!((r[0] * r[1] - c / a).abs() <= 1e-13 * (c / a).abs(), "{r:?}");
}

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("no number {key}: {v}"))
}

#[test]
fn bad_input_exits_2_naming_the_value() {
    for (args, message) in [
        (vec!["--gamma", "60", "--speed", "5"], "invalid value '60' for '--gamma <DEG>'"),
        (vec!["--gamma", "5", "--speed", "fast"], "invalid value 'fast' for '--speed <V>'"),
        (vec!["--gamma", "5", "--speed", "-2"], "invalid speed -2.0: must not be negative"),
        (vec!["--gamma", "30", "--speed", "40"], "no steady turn"),
        (
            vec!["--gamma", "5"],
            "the following required arguments were not provided:\n  --speed <V>",
        ),
    ] {
        let mut all = vec!["turn", "--model", "carvallo"];
        all.extend(args);
        let (code, out, err) = carvallo(&all);
        assert_eq!(code, 2, "{all:?}: {out}");
        assert!(err.starts_with(&format!("error: {message}")), "{all:?}: {err}");
    }
}
