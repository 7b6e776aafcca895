//! Tests of `carvallo pendulum`: `eig --json` is the library's linear model (the command adds
//! nothing), a simulation's status and samples are the library's run with the same settings,
//! the placed feedback keeps the body up where the open loop falls, `--csv` writes every
//! sample, `eig --gain` gives the eigenvalues of A - BK (the placed poles, or those computed
//! here from the printed A, B and K), and bad input is an
//! error naming the value with exit code 2, under the usage line of the subcommand.

use std::process::Command;

use carvallo::numerics::integrate::{Grid, Integration, Method};
use carvallo::wheeled_pendulum::{WheeledPendulum, WheeledPendulumParams};

fn carvallo(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo")).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = carvallo(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

/// serde_json may read a printed float one unit in the last place off.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-15 * a.abs().max(b.abs()) || a == b
}

#[test]
fn eig_json_is_the_library_linear_model() {
    let v = json(&["pendulum", "eig", "--speed", "3", "--param", "mB=70", "--json"]);
    let p = WheeledPendulumParams::nominal().with("mB", 70.0).unwrap();
    let lin = WheeledPendulum::new(p).linear(3.0);
    for (k, z) in lin.eigenvalues().iter().enumerate() {
        let got = &v["eigenvalues"][k];
        assert!(close(got[0].as_f64().unwrap(), z.re) && close(got[1].as_f64().unwrap(), z.im));
    }
    for i in 0..4 {
        for j in 0..4 {
            assert!(close(v["a"][i][j].as_f64().unwrap(), lin.a[(i, j)]), "A {i} {j}");
        }
        for j in 0..2 {
            assert!(close(v["b"][i][j].as_f64().unwrap(), lin.b[(i, j)]), "B {i} {j}");
        }
    }
    let (code, text, err) = carvallo(&["pendulum", "eig"]);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("  +6.124909 +0.000000i\n"), "{text}");
}

#[test]
fn the_open_loop_falls_as_the_library_run_does() {
    let v = json(&["pendulum", "simulate", "--t-end", "2", "--pitch0", "0.1", "--json"]);
    assert_eq!(v["status"], "fell");
    let m = WheeledPendulum::new(WheeledPendulumParams::nominal());
    let mut x0 = m.upright(2.0);
    x0[3] = 0.1;
    let grid = Grid::new(2.0, 0.01, 10).unwrap();
    let how = Integration::with_defaults(Method::Dop853, None, None);
    let run = m.simulate(x0, &|_, _| [0.0, 0.0], &grid, &how).unwrap();
    assert!(close(v["fall_time"].as_f64().unwrap(), run.fall.unwrap()));
    let theta: Vec<f64> =
        v["theta"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    assert_eq!(theta.len(), run.len());
    for (a, x) in theta.iter().zip(&run.samples) {
        assert!(close(*a, x[3]));
    }
    let (code, text, _) = carvallo(&["pendulum", "simulate", "--t-end", "2", "--pitch0", "0.1"]);
    assert_eq!(code, 0);
    assert!(text.contains("status: fell at t = 0.73"), "{text}");
}

#[test]
fn the_placed_feedback_keeps_the_body_up() {
    let v = json(&[
        "pendulum", "simulate", "--t-end", "4", "--pitch0", "0.1", "--gain", "placed", "--json",
    ]);
    assert_eq!(v["status"], "completed");
    let theta = v["theta"].as_array().unwrap();
    assert!(theta.last().unwrap().as_f64().unwrap().abs() < 1e-5, "{theta:?}");
    // Poles of one's own, and a gain given by its eight numbers (the placed one, negated:
    // destabilising, it falls).
    let v = json(&[
        "pendulum", "simulate", "--t-end", "3", "--pitch0", "-0.1", "--gain", "placed", "--poles",
        "-4,-5,-6", "--json",
    ]);
    assert_eq!(v["status"], "completed");
    assert_eq!(v["poles"], serde_json::json!([-4.0, -5.0, -6.0]));
    let k: Vec<String> = v["gain"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|r| r.as_array().unwrap().iter().map(|x| (-x.as_f64().unwrap()).to_string()))
        .collect();
    let gain = k.join(",");
    let v = json(&[
        "pendulum", "simulate", "--t-end", "3", "--pitch0", "-0.1", "--gain", &gain, "--json",
    ]);
    assert_eq!(v["status"], "fell");
}

#[test]
fn csv_writes_every_sample() {
    let dir = std::env::temp_dir().join(format!("carvallo-pendulum-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("run.csv");
    let p = path.to_str().unwrap();
    let (code, text, err) = carvallo(&[
        "pendulum", "simulate", "--t-end", "1", "--pitch0", "0.05", "--gain", "placed", "--every",
        "1", "--csv", p,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains(&format!("wrote 101 samples to {p}")), "{text}");
    let csv = std::fs::read_to_string(&path).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("t,x,y,psi,theta,thetad,thetaLd,thetaRd,TL,TR"));
    assert_eq!(lines.clone().count(), 101);
    assert!(
        lines.all(|l| l.split(',').count() == 10 && l.split(',').all(|v| v.parse::<f64>().is_ok()))
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_names_the_value() {
    let cases: &[(&[&str], &str)] = &[
        (&["pendulum", "eig", "--param", "mB=-1"], "mB=-1"),
        (&["pendulum", "eig", "--param", "mass=1"], "unknown parameter `mass`"),
        (&["pendulum", "eig", "--param", "IWa=0.5"], "invalid IWa 0.5: must not exceed the sum"),
        (&["pendulum", "eig", "--speed", "NaN"], "'NaN'"),
        (&["pendulum", "simulate", "--t-end", "1", "--pitch0", "2"], "invalid --pitch0 2.0"),
        (&["pendulum", "simulate", "--t-end", "-1", "--pitch0", "0.1"], "invalid --t-end -1.0"),
        (
            &["pendulum", "simulate", "--t-end", "1", "--pitch0", "0.1", "--poles", "-1,-2,-3"],
            "invalid --poles",
        ),
        (
            &[
                "pendulum", "simulate", "--t-end", "1", "--pitch0", "0.1", "--gain", "placed",
                "--poles", "1,-2,-3",
            ],
            "'1,-2,-3'",
        ),
        (&["pendulum", "simulate", "--t-end", "1", "--pitch0", "0.1", "--gain", "1,2,3"], "not 3"),
    ];
    for (args, needle) in cases {
        let (code, out, err) = carvallo(args);
        assert_eq!(code, 2, "{args:?}: {out}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert!(err.starts_with("error: ") && err.contains(needle), "{args:?}: {err}");
    }
}

/// `eig --gain`: placed at `--poles`, the closed loop's eigenvalues are those poles and the
/// turning mode's zero; with K given, they are the eigenvalues of A - BK computed here from the
/// printed A, B and K, and differ from the open loop's.
#[test]
fn eig_with_a_gain_is_the_closed_loop() {
    let v = json(&["pendulum", "eig", "--gain", "placed", "--poles", "-2,-3,-4", "--json"]);
    let ev: Vec<(f64, f64)> = v["eigenvalues"]
        .as_array()
        .unwrap()
        .iter()
        .map(|z| (z[0].as_f64().unwrap(), z[1].as_f64().unwrap()))
        .collect();
    for (want, got) in [0.0, -2.0, -3.0, -4.0].iter().zip(&ev) {
        assert!((got.0 - want).abs() < 1e-9 && got.1 == 0.0, "{ev:?}");
    }
    assert_eq!(v["poles"], serde_json::json!([-2.0, -3.0, -4.0]));
    let k = "-500,-100,-5,0,-500,-100,0,-5";
    let v = json(&["pendulum", "eig", "--gain", k, "--json"]);
    let open = json(&["pendulum", "eig", "--json"]);
    let m = |key: &str, cols: usize| {
        nalgebra::DMatrix::from_fn(4, cols, |i, j| v[key][i][j].as_f64().unwrap())
    };
    let gain = nalgebra::DMatrix::from_fn(2, 4, |i, j| v["gain"][i][j].as_f64().unwrap());
    assert_eq!(gain[(0, 0)], -500.0);
    assert_eq!(gain[(1, 3)], -5.0);
    let closed = m("a", 4) - m("b", 2) * gain;
    let mut want: Vec<nalgebra::Complex<f64>> =
        closed.complex_eigenvalues().iter().copied().collect();
    want.sort_by(|p, q| q.re.total_cmp(&p.re).then(q.im.total_cmp(&p.im)));
    for (z, w) in v["eigenvalues"].as_array().unwrap().iter().zip(&want) {
        let got = nalgebra::Complex::new(z[0].as_f64().unwrap(), z[1].as_f64().unwrap());
        assert!((got - w).norm() < 1e-9 * w.norm().max(1.0), "{got} against {w}");
    }
    assert_ne!(v["eigenvalues"], open["eigenvalues"]);
    assert!(open.get("gain").is_none());
    let (code, out, _) = carvallo(&["pendulum", "eig", "--gain", k]);
    assert_eq!(code, 0);
    assert!(out.contains("closed-loop eigenvalues of A - BK (1/s):"), "{out}");
}

/// A bad gain is named by its place and value, `--poles` without `--gain placed` is refused
/// under the subcommand's usage line, and `carvallo pendulum` alone prints the pendulum's help
/// (exit code 2 each).
#[test]
fn bad_gains_and_a_missing_subcommand_name_what_is_wrong() {
    let (code, _, err) = carvallo(&["pendulum", "eig", "--gain", "1,2,3,4,5,6,7,x"]);
    assert_eq!(code, 2);
    assert!(err.contains("K8 `x`: not a number"), "{err}");
    let (code, _, err) = carvallo(&["pendulum", "eig", "--gain", "1,2,3"]);
    assert_eq!(code, 2);
    assert!(err.contains("eight gains K1,...,K8 (rows TL, TR), not 3"), "{err}");
    let (code, _, err) = carvallo(&["pendulum", "eig", "--poles", "-1,-2,-3"]);
    assert_eq!(code, 2);
    assert!(err.contains("invalid --poles: they are placed by --gain placed"), "{err}");
    assert!(err.contains("Usage: carvallo pendulum eig [OPTIONS]"), "{err}");
    let (code, _, err) = carvallo(&["pendulum"]);
    assert_eq!(code, 2);
    assert!(err.contains("Usage: carvallo pendulum <COMMAND>"), "{err}");
    assert!(!err.contains("Usage: carvallo <COMMAND>"), "{err}");
}
