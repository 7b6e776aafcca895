//! Tests of `carvallo rest` (memoir n° 67): the JSON output against the library's own
//! computation of the same rest position (the CLI adds nothing), the massless front wheel
//! giving γ67 = γ55, a lean without a rest position as a status (exit 0), and bad input as an
//! error naming the value with exit code 2.

use std::process::Command;

use carvallo::bicycle_rest::RestBicycle;

fn carvallo(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo")).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn json_is_the_library_rest_position() {
    let (code, out, err) = carvallo(&["rest", "--theta", "20", "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let p = RestBicycle::memoir().rest_position(-20f64.to_radians()).unwrap();
    // Same computation; serde_json's parser may read a printed float one unit in the last
    // place off, hence the relative 1e-15.
    let same = |key: &str, x: f64| {
        let y = v[key].as_f64().unwrap();
        assert!((y - x).abs() <= 1e-15 * x.abs(), "{key}: {y} {x}");
    };
    same("gamma55_deg", p.lowest.gamma.to_degrees());
    same("gamma67_deg", p.equilibrium.gamma.to_degrees());
    same("stiffness", p.equilibrium.curvature.value);
    same("frame_rise", p.frame_rise());
    assert!(v["difference_deg"].as_f64().unwrap() > 0.0);
    let (code, text, _) = carvallo(&["rest", "--theta", "20"]);
    assert_eq!(code, 0);
    assert!(text.contains("gamma67 = 34.70"), "{text}");
}

#[test]
fn a_massless_front_wheel_rests_at_the_lowest_frame() {
    let (code, out, err) = carvallo(&["rest", "--theta", "10", "--wheel-mass", "0", "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let d = v["difference_deg"].as_f64().unwrap();
    assert!(d.abs() <= 1e-5, "difference {d} deg");
}

#[test]
fn a_lean_without_a_rest_position_is_a_status() {
    // Near 90 degrees the front wheel finds no lowest point on the ground: the library says
    // so, and the command reports it as the outcome, not as a usage error.
    let e = RestBicycle::memoir().rest_position(-80f64.to_radians()).unwrap_err().to_string();
    let (code, text, err) = carvallo(&["rest", "--theta", "80"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.is_empty(), "{err}");
    assert!(text.contains(&format!("no rest position: {e}\n")), "{text}");
    let (code, out, err) = carvallo(&["rest", "--theta", "-89.9", "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["status"], "no rest position");
    assert!(v["reason"].as_str().unwrap().starts_with("no front contact at theta"), "{v}");
    assert!(v.get("gamma67_deg").is_none());
    // A lean with one says so.
    let (_, out, _) = carvallo(&["rest", "--theta", "20", "--json"]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["status"], "at rest");
}

#[test]
fn bad_input_names_the_value_with_exit_code_2() {
    for (args, msg) in [
        (&["rest", "--theta", "95"][..], "error: invalid value '95' for '--theta <DEG>'"),
        (
            &["rest", "--theta", "inf"][..],
            "error: invalid value 'inf' for '--theta <DEG>': must be finite",
        ),
        (
            &["rest", "--theta", "5", "--wheel-mass", "-2"][..],
            "error: invalid value '-2' for '--wheel-mass <KG>': must not be negative",
        ),
        (&["rest", "--tilt", "5"][..], "error: unexpected argument '--tilt' found"),
    ] {
        let (code, out, err) = carvallo(args);
        assert_eq!(code, 2, "{args:?}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert!(err.starts_with(msg), "{args:?}: {err}");
    }
}
