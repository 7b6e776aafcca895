//! Tests of `carvallo turn --model benchmark|FILE --speed V --lean RAD`, the steady turns of the
//! nonlinear Carvallo–Whipple bicycle: the JSON against the library's computation of the same
//! turns (the CLI adds nothing), upright running of a BicycleParameters file with a rider
//! against `carvallo eig` of the same files (the linearised model, another derivation), a lean
//! no steer holds as a result with exit code 0, `--steer` selecting the nearest turn, and bad
//! input as an error naming the value with exit code 2, a solver failure (a rider whose mass
//! matrix is singular) with exit code 1 and its reason. `--model lean-rider`: the library's
//! turns of Moore's leaning rider, and upright running with `carvallo eig`'s six eigenvalues.
//! `--hands-free`: the forward family branches from upright running at `carvallo window`'s
//! capsize speed (the linearised model), for the benchmark and a file with a rider.

use std::process::Command;

use carvallo::whipple::steady_turn::steady_turns;
use carvallo::whipple::WhippleParams;
use serde_json::Value;

fn carvallo(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo")).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn json(args: &[&str]) -> Value {
    let (code, out, err) = carvallo(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

/// Equal to rounding: serde_json may read a printed float one unit in the last place off.
fn same(got: &Value, want: f64) {
    let g = got.as_f64().unwrap_or_else(|| panic!("a number: {got}"));
    assert!((g - want).abs() <= 1e-15 * want.abs().max(1e-300), "{g} vs {want}");
}

#[test]
fn json_is_the_library_turns() {
    let v = json(&["turn", "--model", "benchmark", "--speed", "5", "--lean", "0.05", "--json"]);
    let lib = steady_turns(&WhippleParams::benchmark(), 5.0, 0.05).unwrap();
    assert_eq!(v["status"], "turns");
    let turns = v["turns"].as_array().unwrap();
    assert_eq!(turns.len(), lib.turns.len());
    for (j, t) in turns.iter().zip(&lib.turns) {
        same(&j["steer"], t.steer);
        same(&j["pitch"], t.pitch);
        same(&j["yaw_rate"], t.yaw_rate);
        same(&j["radius"], t.radius);
        same(&j["steer_torque"], t.steer_torque);
        same(&j["normal_force"]["rear"], t.forces.rear_normal);
        same(&j["normal_force"]["front"], t.forces.front_normal);
        same(&j["friction"]["front"], t.forces.front_friction);
        assert_eq!(j["stable"], t.stability.stable);
        let ev = j["eigenvalues"].as_array().unwrap();
        assert_eq!(ev.len(), 4);
        for (e, z) in ev.iter().zip(&t.stability.eigenvalues) {
            same(&e["re"], z.re);
            same(&e["im"], z.im);
        }
    }
    // The forward turn: stable, both wheels on the ground.
    let fwd = turns.iter().find(|t| t["steer"].as_f64().unwrap().abs() < 0.5).unwrap();
    assert_eq!((fwd["stable"].as_bool(), fwd["on_ground"].as_bool()), (Some(true), Some(true)));
}

#[test]
fn upright_running_of_a_file_has_the_linear_eigenvalues() {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/bicycleparameters");
    let bike = format!("{data}/bicycles/Browser/Parameters/BrowserBenchmark.txt");
    let rider = format!("{data}/riders/Jason/Parameters/JasonBrowserBenchmark.txt");
    let v = json(&[
        "turn", "--model", &bike, "--rider", &rider, "--speed", "5.5", "--lean", "0", "--steer",
        "0", "--json",
    ]);
    let turns = v["turns"].as_array().unwrap();
    assert_eq!(turns.len(), 1, "{v}");
    let t = &turns[0];
    assert_eq!((t["steer"].as_f64(), t["radius"].as_f64()), (Some(0.0), None), "straight: {t}");
    let eig = json(&["eig", "--model", &bike, "--rider", &rider, "--speed", "5.5", "--json"]);
    let mut linear: Vec<(f64, f64)> = eig["eigenvalues"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| (e["re"].as_f64().unwrap(), e["im"].as_f64().unwrap()))
        .collect();
    let mut nonlinear: Vec<(f64, f64)> = t["eigenvalues"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| (e["re"].as_f64().unwrap(), e["im"].as_f64().unwrap()))
        .collect();
    for l in [&mut linear, &mut nonlinear] {
        l.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    }
    for (a, b) in linear.iter().zip(&nonlinear) {
        let scale = a.0.hypot(a.1).max(1.0);
        assert!(
            (a.0 - b.0).abs() <= 1e-9 * scale && (a.1 - b.1).abs() <= 1e-9 * scale,
            "{a:?} {b:?}"
        );
    }
}

#[test]
fn a_lean_no_steer_holds_is_a_result() {
    let (code, out, err) =
        carvallo(&["turn", "--model", "benchmark", "--speed", "5", "--lean", "1.55"]);
    assert_eq!((code, err.as_str()), (0, ""), "{out}");
    assert!(out.contains("no steady turn"), "{out}");
    let v = json(&["turn", "--model", "benchmark", "--speed", "5", "--lean", "1.55", "--json"]);
    assert_eq!(v["status"], "no steady turn");
    assert_eq!(v["turns"].as_array().map(Vec::len), Some(0));
}

#[test]
fn steer_keeps_the_nearest_turn() {
    let all = json(&["turn", "--model", "benchmark", "--speed", "5", "--lean", "0.05", "--json"]);
    let steers: Vec<f64> =
        all["turns"].as_array().unwrap().iter().map(|t| t["steer"].as_f64().unwrap()).collect();
    // The reversed handlebar (near pi) is nearest to -pi + 0.01 across the cut of the circle.
    for (wanted, expect) in [(0.1, 2), (3.1316, 0), (-3.1316, 0), (1.5, 3)] {
        let v = json(&[
            "turn",
            "--model",
            "benchmark",
            "--speed",
            "5",
            "--lean",
            "0.05",
            "--steer",
            &wanted.to_string(),
            "--json",
        ]);
        let t = v["turns"].as_array().unwrap();
        assert_eq!(t.len(), 1);
        same(&t[0]["steer"], steers[expect]);
    }
}

#[test]
fn a_solver_failure_exits_1_with_its_reason() {
    // Browser + Jason with the torso's mass centre on its lean axis (l6 = 0) and no moment
    // about it (ig11 = ig31 = 0), held by a spring (k9): the torso's lean has no inertia, the
    // mass matrix is singular and no turn has a linearisation. Every (speed, lean) with a turn
    // is then a solver failure (exit 1, the reason on stderr), one with none is still a result
    // (exit 0), and a bad value is still exit 2 naming it.
    let moore =
        concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/mooreriderlean2012/browser_jason.toml");
    let text: String = std::fs::read_to_string(moore)
        .unwrap()
        .lines()
        .map(|line| match line.split(" = ").next() {
            Some(name @ ("l6" | "ig11" | "ig31")) => format!("{name} = 0.0\n"),
            Some("k9") => "k9 = 100.0\n".to_string(),
            _ => format!("{line}\n"),
        })
        .collect();
    let dir = std::env::temp_dir().join(format!("carvallo-turn-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("torso_on_its_axis.toml");
    std::fs::write(&file, text).unwrap();
    let model = file.to_str().unwrap();
    for lean in ["0", "0.1", "-0.3"] {
        let (code, out, err) =
            carvallo(&["turn", "--model", model, "--speed", "5", "--lean", lean]);
        assert_eq!((code, out.as_str()), (1, ""), "lean {lean}: {err}");
        assert!(
            err.starts_with("error: the steady turn solver failed at steer ")
                && err.contains("the mass matrix is singular at the turn"),
            "lean {lean}: {err}"
        );
    }
    let (code, out, err) = carvallo(&["turn", "--model", model, "--speed", "5", "--lean", "1.55"]);
    assert_eq!((code, err.as_str()), (0, ""), "{out}");
    assert!(out.contains("no steady turn"), "{out}");
    let (code, out, err) = carvallo(&["turn", "--model", model, "--speed", "-5", "--lean", "0.1"]);
    assert_eq!((code, out.as_str()), (2, ""), "{err}");
    assert!(err.starts_with("error: invalid speed -5.0: must be positive"), "{err}");
    // The same rider with its torso off the axis turns (exit 0): the failure is the file's.
    let (code, _, err) =
        carvallo(&["turn", "--model", "lean-rider", "--speed", "5", "--lean", "0.1"]);
    assert_eq!((code, err.as_str()), (0, ""));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_exits_2_naming_the_value() {
    for (args, message) in [
        (
            vec!["--model", "benchmark", "--speed", "0", "--lean", "0.1"],
            "invalid speed 0.0: must be positive",
        ),
        (
            vec!["--model", "benchmark", "--speed", "-3", "--lean", "0.1"],
            "invalid speed -3.0: must be positive",
        ),
        (
            vec!["--model", "benchmark", "--speed", "5", "--lean", "NaN"],
            "invalid value 'NaN' for '--lean <RAD>'",
        ),
        (
            vec!["--model", "benchmark", "--speed", "nan", "--lean", "0.1"],
            "invalid value 'nan' for '--speed <V>'",
        ),
        (
            vec!["--model", "benchmark", "--speed", "5", "--lean", "1.6"],
            "invalid lean 1.6: must lie strictly",
        ),
        (
            vec!["--model", "bogus", "--speed", "5", "--lean", "0.1"],
            "cannot read model file `bogus`",
        ),
        (vec!["--model", "benchmark", "--speed", "5"], "--model benchmark needs --lean <RAD>"),
    ] {
        let mut all = vec!["turn"];
        all.extend(args);
        let (code, out, err) = carvallo(&all);
        assert_eq!((code, out.as_str()), (2, ""), "{all:?}");
        assert!(err.starts_with(&format!("error: {message}")), "{all:?}: {err}");
    }
}

#[test]
fn the_leaning_rider_turns_as_the_library_and_has_eig_upright() {
    use carvallo::whipple::lean_rider::{LeanRider, LeanRiderParams};
    use carvallo::whipple::steady_turn::lean_rider::RiderTurnSolver;
    let v = json(&["turn", "--model", "lean-rider", "--speed", "5", "--lean", "0.05", "--json"]);
    let rider = LeanRider::new(LeanRiderParams::browser_jason()).unwrap();
    let lib = RiderTurnSolver::new(&rider).turns(5.0, 0.05).unwrap();
    let turns = v["turns"].as_array().unwrap();
    assert_eq!(turns.len(), lib.turns.len());
    for (j, t) in turns.iter().zip(&lib.turns) {
        same(&j["steer"], t.steer);
        same(&j["torso_lean"], t.torso_lean);
        same(&j["steer_torque"], t.steer_torque);
        same(&j["eigenvalues"][0]["re"], t.stability.eigenvalues[0].re);
    }
    let up = json(&[
        "turn",
        "--model",
        "lean-rider",
        "--speed",
        "5",
        "--lean",
        "0",
        "--steer",
        "0",
        "--json",
    ]);
    let eig = json(&["eig", "--model", "lean-rider", "--speed", "5", "--json"]);
    let ours = up["turns"][0]["eigenvalues"].as_array().unwrap().clone();
    let theirs = eig["eigenvalues"].as_array().unwrap().clone();
    assert_eq!((ours.len(), theirs.len()), (6, 6));
    for (a, b) in ours.iter().zip(&theirs) {
        let (x, y) = (a["re"].as_f64().unwrap(), b["re"].as_f64().unwrap());
        let (p, q) = (a["im"].as_f64().unwrap(), b["im"].as_f64().unwrap());
        assert!(
            (x - y).abs() <= 1e-9 * y.abs().max(1.0) && (p - q).abs() <= 1e-9 * q.abs().max(1.0),
            "{a} {b}"
        );
    }
}

#[test]
fn hands_free_families_branch_at_the_capsize_speed() {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/bicycleparameters");
    let bike = format!("{data}/bicycles/Browser/Parameters/BrowserBenchmark.txt");
    let rider = format!("{data}/riders/Jason/Parameters/JasonBrowserBenchmark.txt");
    for model in [vec!["--model", "benchmark"], vec!["--model", &bike, "--rider", &rider]] {
        let mut args = vec!["turn", "--hands-free", "--json"];
        args.extend(&model);
        let v = json(&args);
        let mut args = vec!["window", "--json"];
        args.extend(&model);
        let w = json(&args);
        let capsize = w["capsize_speed"].as_f64().unwrap();
        let families = v["families"].as_array().unwrap();
        let forward: Vec<_> = families.iter().filter(|f| f["line_steer"] == 0.0).collect();
        assert_eq!(forward.len(), 1, "{model:?}");
        let vb = forward[0]["branch_speed"].as_f64().unwrap();
        assert!((vb - capsize).abs() <= 1e-9 * capsize, "{model:?}: {vb} vs {capsize}");
        let points = forward[0]["points"].as_array().unwrap();
        assert!(
            points.len() > 100 && points.iter().skip(1).all(|p| p["lean"].as_f64().unwrap() > 0.0)
        );
    }
    let (code, _, err) = carvallo(&["turn", "--model", "lean-rider", "--hands-free"]);
    assert_eq!(code, 2);
    assert!(err.starts_with("error: --hands-free takes a bicycle"), "{err}");
}
