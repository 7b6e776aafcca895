//! End-to-end tests of `carvallo simulate` with an adaptive method, stop conditions and
//! batches: the JSON keys and counts, the event reported and ending the samples, the batch
//! rows equal to single runs bit for bit (floats printed round-trip), a failed row kept with
//! its message, and exit code 2 with the bad value named for bad options and batch files.

use std::process::Command;

use serde_json::Value;

fn carvallo(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo")).args(args).output().unwrap();
    let text = |b: Vec<u8>| String::from_utf8(b).unwrap();
    (out.status.code().unwrap_or(-1), text(out.stdout), text(out.stderr))
}

const BASE: [&str; 5] = ["simulate", "--model", "benchmark", "--duration", "3"];

fn single(speed: &str, lean0: &str, extra: &[&str]) -> Value {
    serde_json::from_str(&single_text(speed, lean0, extra)).unwrap()
}

fn single_text(speed: &str, lean0: &str, extra: &[&str]) -> String {
    let args = [&BASE[..], &["--speed", speed, "--lean0", lean0, "--json"], extra].concat();
    let (code, out, err) = carvallo(&args);
    assert_eq!(code, 0, "{err}");
    out
}

/// The number `key` in the JSON text, parsed by Rust's correctly rounded `str::parse`.
fn number(json: &str, key: &str) -> f64 {
    let from = json.find(&format!("\"{key}\":")).unwrap() + key.len() + 3;
    let end = from + json[from..].find([',', '}']).unwrap();
    json[from..end].parse().unwrap()
}

/// The last number of the array `key` in the JSON text, parsed by Rust's correctly rounded
/// `str::parse` (serde_json's default float parser may err by an ulp).
fn last_number(json: &str, key: &str) -> f64 {
    let from = json.find(&format!("\"{key}\":[")).unwrap() + key.len() + 4;
    let array = &json[from..from + json[from..].find(']').unwrap()];
    array.rsplit(',').next().unwrap().parse().unwrap()
}

#[test]
fn an_adaptive_run_reports_its_counts_and_its_event() {
    let opts = ["--method", "dop853", "--rtol", "1e-10", "--stop-when", "lean=±0.5"];
    let v = single("2", "0.05", &opts);
    assert_eq!(v["method"], "dop853");
    assert_eq!((v["rtol"].as_f64(), v["atol"].as_f64()), (Some(1e-10), Some(1e-13)));
    let steps = v["steps"].as_u64().unwrap();
    let evals = v["rhs_evaluations"].as_u64().unwrap();
    // DOP853: 12 evaluations a step, 3 more for the dense output of an accepted step.
    assert!(
        evals >= 12 * steps && evals <= 16 * (steps + v["rejected_steps"].as_u64().unwrap()) + 16
    );
    let events = v["events"].as_array().unwrap();
    assert_eq!(events.len(), 1, "{events:?}");
    assert_eq!(events[0]["when"], "lean=±0.5");
    let t = events[0]["t"].as_f64().unwrap();
    let times = v["t"].as_array().unwrap();
    let leans = v["lean"].as_array().unwrap();
    assert_eq!(times.last().unwrap().as_f64(), Some(t));
    assert!((leans.last().unwrap().as_f64().unwrap().abs() - 0.5).abs() < 1e-9);
    assert!(times.iter().all(|x| x.as_f64().unwrap() <= t));
    // The default RK4 run has the same keys with its own counts and no event: four
    // evaluations a step and the slope at the end (the fall angle's event).
    let v = single("4.6", "0.05", &[]);
    assert_eq!((v["method"].as_str(), v["rtol"].as_f64()), (Some("rk4"), None));
    assert_eq!((v["steps"].as_u64(), v["rhs_evaluations"].as_u64()), (Some(3000), Some(12001)));
    assert_eq!(v["status"], "completed");
    assert_eq!(v["events"].as_array().map(Vec::len), Some(0));
}

/// Verner's 9(8) pair and DOP853 at tight tolerances agree on the fall's time and end (both
/// within 1e-11 of each other; the runtime's tests check both against bisection), and the
/// pair costs 16 evaluations a step plus 10 for the dense output of an accepted one.
#[test]
fn vern9_agrees_with_dop853() {
    let stop = ["--stop-when", "lean=±0.5"];
    let a = single("2", "0.05", &[&["--method", "vern9", "--rtol", "1e-12"][..], &stop].concat());
    let b = single("2", "0.05", &[&["--method", "dop853", "--rtol", "1e-12"][..], &stop].concat());
    assert_eq!(a["method"], "vern9");
    let t = |v: &Value| v["events"][0]["t"].as_f64().unwrap();
    assert!((t(&a) - t(&b)).abs() < 1e-11, "{} against {}", t(&a), t(&b));
    let json = |v: &Value| v.to_string();
    for key in ["lean", "steer", "rear_x", "rear_y"] {
        let (x, y) = (last_number(&json(&a), key), last_number(&json(&b), key));
        assert!((x - y).abs() < 1e-10, "{key}: {x} against {y}");
    }
    let (steps, rejected) = (a["steps"].as_u64().unwrap(), a["rejected_steps"].as_u64().unwrap());
    let evals = a["rhs_evaluations"].as_u64().unwrap();
    // Per attempt 15 stages after the first (not first-same-as-last: one more evaluation at the
    // end of an accepted step), 10 for its interpolant; plus two at the start (the slope and
    // the trial of the initial step; the crate's own initial slope is the first, not redone).
    assert_eq!(evals, 2 + 15 * (steps + rejected) + 11 * steps, "{evals} {steps} {rejected}");
}

#[test]
fn batch_rows_equal_single_runs_bit_for_bit() {
    let dir = std::env::temp_dir().join(format!("carvallo-batch-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("starts.csv");
    std::fs::write(&file, "lean0,speed\n0.05,4.6\n0.05,2\n\n0.1,3\n").unwrap();
    let path = file.to_str().unwrap();
    for opts in [&["--method", "dop853", "--stop-when", "lean=±0.5"][..], &[][..]] {
        let args = [&BASE[..], &["--batch", path, "--csv"], opts].concat();
        let (code, csv, err) = carvallo(&args);
        assert_eq!(code, 0, "{err}");
        let lines: Vec<&str> = csv.lines().collect();
        let header: Vec<&str> = lines[0].split(',').collect();
        assert_eq!(lines.len(), 4, "{csv}");
        let col = |row: &[&str], name: &str| -> f64 {
            row[header.iter().position(|h| *h == name).unwrap()].parse().unwrap()
        };
        for (line, (speed, lean0)) in
            lines[1..].iter().zip([("4.6", "0.05"), ("2", "0.05"), ("3", "0.1")])
        {
            let row: Vec<&str> = line.split(',').collect();
            if row[4] == "failed" {
                // The same failure as the single run's.
                let args = [&BASE[..], &["--speed", speed, "--lean0", lean0], opts].concat();
                let (code, _, err) = carvallo(&args);
                let message = line.split('"').nth(1).unwrap();
                assert!(code == 2 && err.contains(message), "{line}: {err}");
                continue;
            }
            assert_eq!(row.len(), header.len(), "{line}");
            let text = single_text(speed, lean0, opts);
            let v: Value = serde_json::from_str(&text).unwrap();
            let last = |key: &str| last_number(&text, key);
            for (csv_name, json_name) in [
                ("t_end", "t"),
                ("lean", "lean"),
                ("steer", "steer"),
                ("x", "rear_x"),
                ("y", "rear_y"),
            ] {
                assert_eq!(
                    col(&row, csv_name).to_bits(),
                    last(json_name).to_bits(),
                    "{csv_name}: {line}"
                );
            }
            assert_eq!(col(&row, "rhs_evaluations") as u64, v["rhs_evaluations"].as_u64().unwrap());
            // Fell: a stop condition met, the fall angle or the steer lock reached (the single
            // run's status).
            let limit = v["status"] == "fell" || v["status"] == "steer lock";
            let fell = !v["events"].as_array().unwrap().is_empty() || limit;
            assert_eq!(row[header.iter().position(|h| *h == "fell").unwrap()], fell.to_string());
            for (status, by, key) in
                [("fell", ",fall angle,", "fall_t"), ("steer lock", ",steer lock,", "steer_lock_t")]
            {
                if v["status"] == status {
                    assert!(line.contains(by), "{line}");
                    assert!(v[key].is_f64(), "{key}: {text}");
                    assert_eq!(col(&row, "event_t").to_bits(), number(&text, key).to_bits());
                }
            }
        }
    }
    // A run that falls (no stop condition, 2 m/s for 5 s) is an ok row that fell at the fall
    // angle; a start beyond it is a failed row with the message.
    std::fs::write(&file, "lean0,speed\n0.05,4.6\n0.05,2\n\n2.0,3\n").unwrap();
    let args =
        [&["simulate", "--model", "benchmark", "--duration", "5"][..], &["--batch", path, "--csv"]]
            .concat();
    let (code, csv, _) = carvallo(&args);
    assert_eq!(code, 0);
    let fallen = csv.lines().nth(2).unwrap();
    assert!(fallen.starts_with("1,2.0,0.05,0.0,ok,true,fall angle,1.93"), "{fallen}");
    let failed = csv.lines().find(|l| l.contains(",failed,")).expect("a failed row");
    assert!(
        failed.contains(",failed,false,")
            && failed.contains("invalid lean 2.0 rad: at or beyond the fall angle ±1.2 rad"),
        "{failed}"
    );
    // The quoted message has one comma ("±1.2 rad, where the bicycle is on the ground").
    assert_eq!(
        failed.split(',').count(),
        csv.lines().next().unwrap().split(',').count() + 1,
        "{failed}"
    );
    // Bad files: named, exit 2, nothing on standard output.
    for (text, needle) in [
        ("speed\n1\n", "must name the columns speed and lean0"),
        ("speed,lean0\n1,x\n", "line 2: lean0 `x` is not a finite number"),
        ("speed,lean0,mass\n1,0,3\n", "unknown column `mass`"),
        ("speed,lean0\n1\n", "line 2: 1 values for 2 columns"),
    ] {
        std::fs::write(&file, text).unwrap();
        let (code, out, err) = carvallo(&[&BASE[..], &["--batch", path]].concat());
        assert_eq!((code, out.as_str()), (2, ""), "{err}");
        assert!(err.contains(needle), "{err}");
    }
    let (code, _, err) = carvallo(&[&BASE[..], &["--batch", "/nonexistent/b.csv"]].concat());
    assert!(code == 2 && err.contains("cannot read batch file"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_integration_options_are_named() {
    let run = |extra: &[&str]| {
        let args = [&BASE[..], &["--speed", "4.6", "--lean0", "0.05"], extra].concat();
        carvallo(&args)
    };
    for (extra, needle) in [
        (&["--rtol", "1e-8"][..], "invalid --rtol 1e-8: rk4 has a fixed step"),
        (
            &["--method", "dop853", "--rtol", "1e-20"][..],
            "invalid --rtol 1e-20: must be at least 1e-15",
        ),
        (&["--method", "dopri5", "--atol", "-1"][..], "invalid --atol -1.0: must not be negative"),
        (&["--method", "euler"][..], "invalid value 'euler' for '--method"),
        (&["--stop-when", "speed=1"][..], "invalid value 'speed=1' for '--stop-when"),
        (&["--stop-when", "lean=±-1"][..], "invalid value 'lean=±-1'"),
        (&["--csv"][..], "--batch"),
    ] {
        let (code, out, err) = run(extra);
        assert_eq!((code, out.as_str()), (2, ""), "{extra:?}: {err}");
        assert!(err.contains(needle), "{extra:?}: {err}");
    }
    let (code, out, _) = run(&["--stop-when", "lean=±0.5", "--stop-when", "yaw=3"]);
    assert_eq!(code, 0);
    assert!(out.contains("no stop condition met"), "{out}");
}
