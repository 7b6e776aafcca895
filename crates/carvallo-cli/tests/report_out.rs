//! `report --out DIR` replaces a report atomically: a kill at each step of the replacement
//! (the test-only hook `CARVALLO_TEST_KILL_AT` of debug builds) leaves the old or the new
//! report at DIR (or, on the fallback without `renameat2`, one that the next run restores), and
//! a later run works and leaves no temporary directory; eight concurrent writers to one DIR all
//! succeed or fail with exit 1 and a message, and DIR ends complete; Ctrl-C removes the
//! temporary directory; an output directory that cannot be written fails before the work.

use std::os::unix::process::ExitStatusExt as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// A scratch directory with two parameter files, `a.toml` (the benchmark) and `b.toml` (another
/// trail), whose reports differ.
fn scratch(name: &str) -> PathBuf {
    let dir =
        std::env::temp_dir().join(format!("carvallo-report-out-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let bench = carvallo::whipple::BENCHMARK_TOML;
    std::fs::write(dir.join("a.toml"), bench).unwrap();
    std::fs::write(dir.join("b.toml"), bench.replace("c = 0.08", "c = 0.09")).unwrap();
    dir
}

/// `carvallo report --out r --model MODEL` in `dir` with the environment `env`.
fn report(dir: &Path, model: &str, env: &[(&str, &str)]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_carvallo"))
        .args(["report", "--out", "r", "--model", model])
        .envs(env.iter().copied())
        .current_dir(dir)
        .output()
        .unwrap()
}

/// The model whose complete report is at `dir/r`, or `None` when it is absent; panics on an
/// incomplete one.
fn report_at(dir: &Path) -> Option<String> {
    let r = dir.join("r");
    if !r.exists() {
        return None;
    }
    let md = std::fs::read_to_string(r.join("report.md")).unwrap();
    let model = ["a.toml", "b.toml"].into_iter().find(|m| md.contains(&format!("`{m}`")));
    let model = model.expect("a report of a.toml or b.toml");
    // The figures are named after the bicycle: a_eigenvalues.svg for a.toml.
    let stem = &model[..1];
    for file in [
        ".carvallo-report".to_string(),
        "report.html".to_string(),
        format!("{stem}_eigenvalues.svg"),
        format!("{stem}_geometry.svg"),
    ] {
        assert!(r.join(&file).is_file(), "{file} missing from {r:?}");
    }
    Some(model.to_string())
}

/// The names in `dir` other than the two parameter files.
fn others(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n != "a.toml" && n != "b.toml")
        .collect();
    names.sort();
    names
}

#[test]
fn a_kill_at_any_step_leaves_a_report_that_the_next_run_keeps_or_restores() {
    let steps = [
        (false, "staged"),
        (false, "written"),
        (false, "exchanged"),
        (true, "staged"),
        (true, "written"),
        (true, "aside"),
        (true, "replaced"),
    ];
    for (fallback, step) in steps {
        let dir = scratch(step);
        let mut env = vec![("CARVALLO_TEST_KILL_AT", step)];
        if fallback {
            env.push(("CARVALLO_TEST_NO_EXCHANGE", "1"));
        }
        let first = report(&dir, "a.toml", &[]);
        assert_eq!(first.status.code(), Some(0), "{first:?}");
        let killed = report(&dir, "b.toml", &env);
        assert_eq!(killed.status.signal(), Some(9), "{step}: {killed:?}");
        // The old report or the new one, whole; only the fallback's kill between its two
        // renames leaves DIR absent.
        let at = report_at(&dir);
        let expected = match (fallback, step) {
            (_, "staged" | "written") => Some("a.toml"),
            (true, "aside") => None,
            _ => Some("b.toml"),
        };
        assert_eq!(at.as_deref(), expected, "{step} (fallback {fallback}): {:?}", others(&dir));
        // A killed run's temporary directory is removed by the next run once unlocked (an
        // empty one once ten seconds old, so as never to take a run's fresh one).
        for name in others(&dir) {
            let path = dir.join(&name);
            let touched = Command::new("touch").args(["-d", "1 minute ago"]).arg(&path).status();
            assert!(touched.unwrap().success());
        }
        let later = report(&dir, "a.toml", &[]);
        assert_eq!(later.status.code(), Some(0), "{step}: {later:?}");
        assert_eq!(report_at(&dir).as_deref(), Some("a.toml"));
        assert_eq!(others(&dir), ["r"], "{step} (fallback {fallback})");
        // The fallback restores DIR from the report set aside before it writes its own.
        if at.is_none() {
            let dir2 = scratch("restore");
            assert_eq!(report(&dir2, "a.toml", &[]).status.code(), Some(0));
            let killed = report(&dir2, "b.toml", &env);
            assert_eq!(killed.status.signal(), Some(9));
            assert_eq!(report_at(&dir2), None);
            // The next run restores DIR as it starts, before its own work (killed there).
            let restored = report(&dir2, "b.toml", &[("CARVALLO_TEST_KILL_AT", "staged")]);
            assert_eq!(restored.status.signal(), Some(9));
            assert_eq!(report_at(&dir2).as_deref(), Some("a.toml"), "{:?}", others(&dir2));
            std::fs::remove_dir_all(&dir2).unwrap();
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

#[test]
fn eight_concurrent_writers_leave_one_complete_report() {
    for fallback in [false, true] {
        let dir = scratch(if fallback { "eight-fallback" } else { "eight" });
        let env: &[(&str, &str)] =
            if fallback { &[("CARVALLO_TEST_NO_EXCHANGE", "1")] } else { &[] };
        let children: Vec<_> = (0..8)
            .map(|k| {
                Command::new(env!("CARGO_BIN_EXE_carvallo"))
                    .args([
                        "report",
                        "--out",
                        "r",
                        "--model",
                        if k % 2 == 0 { "a.toml" } else { "b.toml" },
                    ])
                    .envs(env.iter().copied())
                    .current_dir(&dir)
                    .stdout(Stdio::piped())
                    .stderr(Stdio::piped())
                    .spawn()
                    .unwrap()
            })
            .collect();
        let mut ok = 0;
        for child in children {
            let out = child.wait_with_output().unwrap();
            let err = String::from_utf8_lossy(&out.stderr);
            match out.status.code() {
                Some(0) => ok += 1,
                Some(1) => assert!(err.starts_with("error: cannot "), "{err}"),
                other => panic!("exit {other:?}: {err}"),
            }
        }
        // With renameat2 every writer succeeds; the fallback may refuse some.
        if !fallback {
            assert_eq!(ok, 8);
        }
        assert!(ok >= 1, "no writer succeeded");
        assert!(report_at(&dir).is_some());
        // The leftovers of refused fallback writers are removed by the next run.
        assert_eq!(report(&dir, "a.toml", &[]).status.code(), Some(0));
        assert_eq!(others(&dir), ["r"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

#[test]
fn ctrl_c_removes_the_temporary_directory_and_an_unwritable_place_fails_first() {
    let dir = scratch("sigint");
    // A file with stated uncertainties: its Monte Carlo takes seconds.
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/benchmark-1pct.txt");
    let child = Command::new(env!("CARGO_BIN_EXE_carvallo"))
        .args(["report", "--out", "r", "--model", data])
        .current_dir(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Once its temporary directory exists, SIGINT.
    let t0 = std::time::Instant::now();
    while !others(&dir).iter().any(|n| n.starts_with(".r.carvallo-tmp-")) {
        assert!(t0.elapsed().as_secs() < 30, "no temporary directory");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    std::thread::sleep(std::time::Duration::from_millis(200));
    let kill = Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
    assert!(kill.success());
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(130), "{out:?}");
    assert_eq!(others(&dir), Vec::<String>::new(), "left behind");
    // Not writable: refused before the work, exit 2, nothing written.
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo"))
        .args(["report", "--out", "/proc/self/x"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.starts_with("error: cannot write to the output directory's parent `/proc/self`"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
