//! End-to-end tests of `carvallo simulate` driven by torques and feedback (`--torque`,
//! `--torque-csv`, `--gain`, `--gain-table`): the JSON keys, the energy balance with the
//! work, a sampled series equal to the same step bit for bit, a constant gain table equal to
//! the constant gains, and exit code 2 with the bad value named and nothing on standard
//! output for bad inputs.

use std::process::Command;

use serde_json::Value;

fn carvallo(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo")).args(args).output().unwrap();
    let text = |b: Vec<u8>| String::from_utf8(b).unwrap();
    (out.status.code().unwrap_or(-1), text(out.stdout), text(out.stderr))
}

const BASE: [&str; 9] =
    ["simulate", "--model", "benchmark", "--speed", "5", "--lean0", "0", "--duration", "1"];

fn run(extra: &[&str]) -> String {
    let (code, out, err) = carvallo(&[&BASE[..], extra].concat());
    assert_eq!(code, 0, "{err}");
    out
}

fn json(extra: &[&str]) -> Value {
    serde_json::from_str(&run(&[extra, &["--json"]].concat())).unwrap()
}

fn column(v: &Value, key: &str) -> Vec<f64> {
    v[key].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

/// A file in a fresh temporary directory.
fn file(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("carvallo-sim-inputs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_string_lossy().into_owned()
}

#[test]
fn a_driven_run_reports_its_inputs_and_balances_its_energy() {
    let csv = file("roll.csv", "t,T_phi\n0.2,0\n0.4,3\n0.6,0\n");
    let v = json(&[
        "--torque",
        "steer=step:0.5@0.1",
        "--torque",
        "roll=impulse:0.3@0.5",
        "--torque-csv",
        &csv,
        "--method",
        "dop853",
        "--rtol",
        "1e-10",
    ]);
    assert_eq!(v["inputs"]["torque"][0], "steer=step:0.5@0.1");
    assert_eq!(v["inputs"]["torque"][1], "roll=impulse:0.3@0.5");
    assert_eq!(v["inputs"]["torque_csv"], csv.as_str());
    assert_eq!(
        (v["inputs"]["gains"].clone(), v["inputs"]["gain_table"].clone()),
        (Value::Null, Value::Null)
    );
    let (work, energy, w_t) =
        (v["work"].as_f64().unwrap(), column(&v, "energy"), column(&v, "work_t"));
    assert_eq!(*w_t.last().unwrap(), work);
    // E - E(0) follows the work; the largest change is far above the balance's drift.
    let change = energy.last().unwrap() - energy[0];
    assert!((change - work).abs() < 1e-9, "{change} {work}");
    let (drift, most) =
        (v["energy_drift"].as_f64().unwrap(), v["max_energy_change"].as_f64().unwrap());
    assert!(drift < 1e-9 && most > 1e-2, "drift {drift:e}, change {most:e}");
    let (t, tphi, tdelta) = (column(&v, "t"), column(&v, "T_phi"), column(&v, "T_delta"));
    for k in 0..t.len() {
        let series =
            if t[k] >= 0.2 && t[k] < 0.6 { 3.0 * (1.0 - (t[k] - 0.4).abs() / 0.2) } else { 0.0 };
        assert!((tphi[k] - series).abs() < 1e-12, "t = {}: {}", t[k], tphi[k]);
        assert_eq!(tdelta[k], if t[k] >= 0.1 - 1e-12 { 0.5 } else { 0.0 }, "t = {}", t[k]);
    }
    // The text names the inputs and the balance.
    let text = run(&["--torque", "steer=step:0.5@0.1", "--every", "500"]);
    assert!(text.contains("inputs: steer=step:0.5@0.1\n"), "{text}");
    assert!(text.contains("energy balance drift (E - E0 - W) "), "{text}");
    assert!(
        text.contains(" t        lean       steer      speed      T_phi      T_delta    work\n")
    );
}

#[test]
fn a_series_equals_the_same_step_and_a_constant_table_the_constant_gains() {
    // A series constant at 0.5 N m from 0.1 s to the end is the step at 0.1 s: the runs are
    // equal bit for bit (the interpolation of equal values is exact).
    let csv = file("step.csv", "t,T_delta\n0.1,0.5\n1,0.5\n");
    let a = json(&["--torque-csv", &csv]);
    let b = json(&["--torque", "steer=step:0.5@0.1"]);
    for key in ["lean", "steer", "work_t", "energy", "T_delta"] {
        assert_eq!(a[key], b[key], "{key}");
    }
    let table = file("gains.csv", "speed,k_steer_roll_rate\n4,-20\n6,-20\n");
    let a = json(&["--gain-table", &table, "--torque", "roll=step:1"]);
    let b = json(&["--gain", "k_steer_roll_rate=-20", "--torque", "roll=step:1"]);
    for key in ["lean", "steer", "work_t", "T_delta"] {
        assert_eq!(a[key], b[key], "{key}");
    }
    assert_eq!(a["inputs"]["gain_table"], table.as_str());
    assert_eq!(b["inputs"]["gains"]["k_steer_roll_rate"], -20.0);
}

#[test]
fn bad_inputs_are_named_with_exit_code_2_and_nothing_printed() {
    let not_monotone = file("bad.csv", "t,T_phi\n0,1\n0.5,2\n0.4,0\n");
    let narrow = file("narrow.csv", "speed,k_steer_roll_rate\n0,-20\n4,-20\n");
    for (extra, msg) in [
        (vec!["--torque", "yaw=step:1"], "unknown input `yaw`: expected roll or steer"),
        (vec!["--torque", "steer=step:1@x"], "time `x` is not a number"),
        (
            vec!["--torque", "roll=impulse:1@0.0005"],
            "invalid impulse time 0.0005 s: not a multiple of the step 0.001 s",
        ),
        (
            vec!["--torque", "roll=impulse:1@2"],
            "invalid impulse time 2 s: outside the run [0, 1) s",
        ),
        (
            vec!["--torque-csv", &not_monotone],
            "line 4: time 0.4 does not exceed the time 0.5 before it",
        ),
        (
            vec!["--torque-csv", "/nonexistent/t.csv"],
            "cannot read torque file `/nonexistent/t.csv`",
        ),
        (vec!["--gain", "k_yaw=1"], "unknown gain `k_yaw`"),
        (
            vec!["--gain-table", &narrow],
            "the rear contact speed 5 m/s at t = 0 s is outside the gain table's speeds 0 to 4 m/s",
        ),
        (vec!["--gain-table", &narrow, "--gain", "k_roll_roll=1"], "cannot be used with"),
    ] {
        let (code, out, err) = carvallo(&[&BASE[..], &extra].concat());
        assert_eq!(code, 2, "{extra:?}: {err}");
        assert!(out.is_empty(), "{extra:?}: {out}");
        assert!(err.contains(msg), "{extra:?}: {err}");
    }
    let (code, out, err) = carvallo(&[
        "simulate",
        "--model",
        "benchmark",
        "--duration",
        "1",
        "--batch",
        "x.csv",
        "--torque",
        "roll=step:1",
    ]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("'--batch <FILE.csv>' cannot be used with '--torque"), "{err}");
}

/// An integration that fails is said to be one, with the method's settings and what to change
/// (before, a driven run printed the bare failure and the command's usage): Radau5 at rtol
/// 1e-15 and atol 1e-300 rejects its very first steps (no accepted step, so no restart), with
/// the feedback as without it.
#[test]
fn a_failed_integration_names_the_settings_to_change() {
    for extra in [&[][..], &["--gain", "k_steer_roll_rate=-20"][..]] {
        let tight = ["--method", "radau5", "--rtol", "1e-15", "--atol", "1e-300"];
        let (code, out, err) = carvallo(&[&BASE[..], &tight, extra].concat());
        assert_eq!(code, 2, "{err}");
        assert!(out.is_empty(), "{out}");
        let first = err.lines().next().unwrap_or("");
        assert_eq!(
            first,
            "error: the integration diverged: the integration failed at t = 0 s: step size below \
             double precision (--method radau5, --rtol 1e-15, --atol 1e-300); try another \
             --method, --rtol or --atol",
            "{extra:?}"
        );
    }
}
