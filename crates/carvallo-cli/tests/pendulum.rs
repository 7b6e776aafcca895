//! Tests of `carvallo pendulum`: `eig --json` is the library's linear model (the command adds
//! nothing), a simulation's status and samples are the library's run with the same settings,
//! the placed feedback keeps the body up where the open loop falls, `--csv` writes every
//! sample, and bad input is an error naming the value with exit code 2.

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
