//! Tests of `carvallo kinematics` (memoir n° 59–69): the JSON output against the library's own
//! evaluation at the same position (the CLI adds nothing), the relations of n° 61 printed
//! beside (I) and (2) agreeing as two independent paths, and bad input (non-numbers,
//! non-finite numbers, |θ| ≥ 90°, no contact solution, unknown arguments) as an error naming
//! the value with exit code 2 and nothing on standard output.

use std::process::Command;

use carvallo::bicycle_kinematics::Kinematics;

fn carvallo(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo")).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn json_is_the_library_kinematics() {
    for (t, g) in [("20", "40"), ("-15", "-60"), ("0", "10")] {
        let (code, out, err) = carvallo(&["kinematics", "--theta", t, "--gamma", g, "--json"]);
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let theta = t.parse::<f64>().unwrap().to_radians();
        let gamma = g.parse::<f64>().unwrap().to_radians();
        let k = Kinematics::old_model();
        let r = k.relations(theta, gamma).unwrap();
        let f = k.geometry().front_wheel(theta, gamma, r.contact.sigma, r.contact.mu);
        let [fd_t, fd_g] = k.eta_partials_fd(theta, gamma).unwrap();
        let (det, minor) = k.fixation_rank(theta, gamma).unwrap();
        // Same computation; serde_json's parser may read a printed float one unit in the last
        // place off, hence the relative 1e-15.
        let same = |key: &str, y: f64, x: f64| {
            assert!((y - x).abs() <= 1e-15 * x.abs(), "{t} {g} {key}: {y} {x}");
        };
        let num = |key: &str| v[key].as_f64().unwrap();
        for (key, x) in [
            ("eta", r.contact.sigma),
            ("omega", r.contact.mu),
            ("x", f.contact[0]),
            ("y", f.contact[1]),
            ("alpha", f.alpha),
            ("beta", f.beta),
            ("d_eta_d_theta", r.d_eta_d_theta),
            ("d_eta_d_theta_fd", fd_t),
            ("d_eta_d_gamma", r.d_eta_d_gamma),
            ("d_eta_d_gamma_fd", fd_g),
            ("d_nu_d_theta", r.d_nu_d_theta),
            ("d_nu_d_gamma", r.d_nu_d_gamma),
            ("steady_n", r.steady_n),
            ("steady_sigma1_rate", r.steady_sigma1_rate),
            ("fixation_det", det),
            ("fixation_minor", minor),
        ] {
            same(key, num(key), x);
        }
        for (key, j) in [("d_eta", 0), ("d_nu", 1), ("d_sigma1", 2)] {
            for (i, unit) in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].iter().enumerate()
            {
                let x = k.solve_displacements(theta, gamma, *unit).unwrap().unwrap()[j];
                same(key, v[key][i].as_f64().unwrap(), x);
            }
        }
        assert_eq!(v["fixation_rank_two"], serde_json::Value::Bool(true), "{t} {g}");

        // Independent paths as printed: the solved relations of n° 61 against the generated
        // (I) and (2) (as the library's tests, 1e-10 relative, 1e-12 absolute), the finite
        // differences against (I) (1e-8 relative, 1e-10 absolute).
        let close = |a: f64, b: f64, rel: f64, abs: f64| {
            assert!((a - b).abs() <= abs + rel * a.abs().max(b.abs()), "{t} {g}: {a} vs {b}");
        };
        let row = |key: &str, i: usize| v[key][i].as_f64().unwrap();
        close(row("d_eta", 1), num("d_eta_d_theta"), 1e-10, 1e-12);
        close(row("d_eta", 2), num("d_eta_d_gamma"), 1e-10, 1e-12);
        close(row("d_nu", 1), num("d_nu_d_theta"), 1e-10, 1e-12);
        close(row("d_nu", 2), num("d_nu_d_gamma"), 1e-10, 1e-12);
        close(row("d_nu", 0), num("steady_n"), 1e-10, 1e-12);
        close(row("d_sigma1", 0), num("steady_sigma1_rate"), 1e-10, 1e-12);
        close(row("d_eta", 0), 0.0, 0.0, 1e-12);
        close(num("d_eta_d_theta_fd"), num("d_eta_d_theta"), 1e-8, 1e-10);
        close(num("d_eta_d_gamma_fd"), num("d_eta_d_gamma"), 1e-8, 1e-10);
    }
}

#[test]
fn text_prints_the_same_numbers() {
    let (code, text, err) = carvallo(&["kinematics", "--theta", "20", "--gamma", "40"]);
    assert_eq!(code, 0, "{err}");
    let r = Kinematics::old_model().relations(20f64.to_radians(), 40f64.to_radians()).unwrap();
    for x in [r.d_eta_d_theta, r.d_nu_d_gamma, r.steady_n] {
        let printed = format!("{x:+.6e}");
        assert!(text.contains(&printed), "{printed} not in\n{text}");
    }
    assert!(text.contains("n° 68 system: rank 2"), "{text}");
}

#[test]
fn bad_input_names_the_value_with_exit_code_2() {
    for (args, msg) in [
        (
            &["kinematics", "--theta", "90", "--gamma", "0"][..],
            "error: invalid value '90' for '--theta <DEG>'",
        ),
        (
            &["kinematics", "--theta", "-95", "--gamma", "0"][..],
            "error: invalid value '-95' for '--theta <DEG>'",
        ),
        (
            &["kinematics", "--theta", "5", "--gamma", "inf"][..],
            "error: invalid value 'inf' for '--gamma <DEG>': must be finite",
        ),
        (
            &["kinematics", "--theta", "NaN", "--gamma", "1"][..],
            "error: invalid value 'NaN' for '--theta <DEG>'",
        ),
        (
            &["kinematics", "--theta", "five", "--gamma", "1"][..],
            "error: invalid value 'five' for '--theta <DEG>'",
        ),
        (
            &["kinematics", "--theta", "5"][..],
            "error: the following required arguments were not provided:\n  --gamma <DEG>",
        ),
        (
            &["kinematics", "--theta", "80", "--gamma", "90"][..],
            "error: at theta `80` deg, gamma `90` deg: no front contact",
        ),
        (&["kinematics", "--lean", "5"][..], "error: unexpected argument '--lean' found"),
    ] {
        let (code, out, err) = carvallo(args);
        assert_eq!(code, 2, "{args:?}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert!(err.starts_with(msg), "{args:?}: {err}");
    }
}
