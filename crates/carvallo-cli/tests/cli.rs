//! End-to-end tests of the `carvallo` binary: the report in both formats, the help (and every
//! subcommand's), the exit
//! code 2 with a message naming an unknown argument, and bad output directories and parameter
//! files for `report --out` and `window` (exit code 2, empty standard output, nothing written).
//! The successful `report --out` is checked by the README replay (`tests/readme.rs`).

use std::process::Command;

fn carvallo(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo")).args(args).output().unwrap();
    let text = |b: Vec<u8>| String::from_utf8(b).unwrap();
    (out.status.code().unwrap_or(-1), text(out.stdout), text(out.stderr))
}

#[test]
fn report_prints_the_table_and_the_json() {
    let (code, text, _) = carvallo(&["report"]);
    assert_eq!(code, 0);
    assert!(text.starts_with("n°  ") && text.contains("agrees") && text.contains("memoir-error"));
    let (code, json, _) = carvallo(&["report", "--json"]);
    assert_eq!(code, 0);
    let value: serde_json::Value = serde_json::from_str(&json).unwrap();
    let first = value.as_array().unwrap()[0].as_object().unwrap();
    for key in ["section", "quantity", "memoir", "derived", "rel_diff", "verdict", "note"] {
        assert!(first.contains_key(key), "missing {key}");
    }
}

#[test]
fn help_and_unknown_arguments() {
    let (code, text, _) = carvallo(&["--help"]);
    assert_eq!(code, 0);
    assert!(text.contains("Usage: carvallo <COMMAND>") && text.contains("\n  report "), "{text}");
    let (code, version, _) = carvallo(&["--version"]);
    assert_eq!(
        (code, version.as_str()),
        (0, concat!("carvallo ", env!("CARGO_PKG_VERSION"), "\n"))
    );
    // No command: an error line first, then the help; exit 2, nothing on standard output.
    let (code, out, err) = carvallo(&[]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.starts_with("error: a command is required\n\n"), "{err}");
    assert!(err.contains("Usage: carvallo <COMMAND>"), "{err}");
    // A usage error: the message, a suggestion, the usage of that command only; exit 2.
    let (code, _, err) = carvallo(&["report", "--jsn"]);
    assert_eq!(code, 2);
    assert!(err.starts_with("error: unexpected argument '--jsn' found"), "{err}");
    assert!(err.contains("a similar argument exists: '--json'"), "{err}");
    assert!(err.contains("Usage: carvallo report ") && !err.contains("window"), "{err}");
    let (code, _, err) = carvallo(&[]);
    assert_eq!(code, 2);
    assert!(err.contains("Usage: carvallo <COMMAND>"), "{err}");
    // Completion scripts for the shells, made from the command table.
    for (shell, mark) in
        [("bash", "_carvallo()"), ("zsh", "#compdef carvallo"), ("fish", "complete -c carvallo")]
    {
        let (code, script, err) = carvallo(&["completions", shell]);
        assert_eq!(code, 0, "{shell}: {err}");
        assert!(script.contains(mark) && script.contains("kinematics"), "{shell}");
    }
    // Every subcommand prints its own usage for -h or --help, wherever it stands, with exit 0.
    for (args, usage) in [
        (&["window", "--help"][..], "carvallo window"),
        (&["sweep", "-h"][..], "carvallo sweep"),
        (&["simulate", "--help"][..], "carvallo simulate"),
        (&["turn", "--gamma", "5", "-h"][..], "carvallo turn"),
        (&["rest", "--help"][..], "carvallo rest"),
        (&["kinematics", "--help"][..], "carvallo kinematics"),
    ] {
        let (code, text, err) = carvallo(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        assert!(text.contains(usage), "{args:?}: {text}");
    }
}

#[test]
fn a_reader_that_stops_early_gets_no_panic() {
    use std::io::Read;
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_carvallo"))
        .arg("report")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Read one byte, then close the pipe while the report is still being written.
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 1];
    stdout.read_exact(&mut first).unwrap();
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "stderr: {stderr}");
    assert_eq!(out.status.code(), Some(0), "stderr: {stderr}");
}

#[test]
fn a_closed_standard_error_gets_no_panic() {
    // The reading end of standard error is closed before the message is written (a broken
    // pipe): the exit code is still 2 (a panic in `eprintln!` would be 101), for a data error
    // and for a usage error.
    use std::process::Stdio;
    for args in
        [&["eig", "--model", "no-such-model", "--speed", "1"][..], &["window", "--modle", "x"]]
    {
        let mut child = Command::new(env!("CARGO_BIN_EXE_carvallo"))
            .args(args)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        drop(child.stderr.take());
        assert_eq!(child.wait().unwrap().code(), Some(2), "{args:?}");
    }
}

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("carvallo-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn carvallo_in(dir: &std::path::Path, args: &[&str]) -> (i32, String, String) {
    let out =
        Command::new(env!("CARGO_BIN_EXE_carvallo")).args(args).current_dir(dir).output().unwrap();
    let text = |b: Vec<u8>| String::from_utf8(b).unwrap();
    (out.status.code().unwrap_or(-1), text(out.stdout), text(out.stderr))
}

/// The names in `dir`, sorted.
fn listing(dir: &std::path::Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn bad_output_directories_are_usage_errors_and_nothing_is_written() {
    let dir = scratch("outdir");
    std::fs::write(dir.join("a-file"), "x").unwrap();
    std::fs::create_dir(dir.join("mine")).unwrap();
    std::fs::write(dir.join("mine/notes.txt"), "keep me").unwrap();
    let cases: [(&str, &str); 5] = [
        ("missing/sub", "error: invalid output directory `missing/sub`: its parent `missing` is not an existing directory"),
        ("a-file", "error: invalid output directory `a-file`: it is not a directory"),
        ("mine", "error: refusing to replace `mine`: it is not empty and was not written by `carvallo report --out`"),
        (".", "error: invalid output directory `.`: give a directory name"),
        ("..", "error: invalid output directory `..`: give a directory name"),
    ];
    for (out, message) in cases {
        let (code, stdout, stderr) = carvallo_in(&dir, &["report", "--out", out]);
        assert_eq!(code, 2, "--out {out}: {stderr}");
        assert_eq!(stdout, "", "--out {out}");
        assert_eq!(stderr.trim_end(), message);
        assert!(!stderr.contains("panicked"));
    }
    assert_eq!(listing(&dir), ["a-file", "mine"]);
    assert_eq!(listing(&dir.join("mine")), ["notes.txt"]);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_parameter_files_are_usage_errors_and_nothing_is_written() {
    let dir = scratch("params");
    let bench = carvallo::whipple::BENCHMARK_TOML;
    let files = [
        (
            "negative.toml",
            bench.replace("mB = 85.0", "mB = -85.0"),
            "invalid mB -85.0: must be positive",
        ),
        ("unknown.toml", format!("{bench}wheelbase = 1.0\n"), "unknown parameter wheelbase"),
        ("missing.toml", bench.replace("rF = 0.35\n", ""), "missing parameter rF"),
        ("nan.toml", bench.replace("g = 9.81", "g = nan"), "invalid g NaN: must be finite"),
        (
            "text.toml",
            bench.replace("c = 0.08", "c = \"short\""),
            "parameter c = \"short\" is not a number",
        ),
        (
            "triangle.toml",
            bench.replace("IRyy = 0.12", "IRyy = 0.5"),
            "invalid IRyy 0.5: exceeds 2 IRxx",
        ),
    ];
    for (name, text, message) in &files {
        std::fs::write(dir.join(name), text).unwrap();
        for args in [
            vec!["report", "--out", "r", "--model", name],
            vec!["window", "--model", name],
            vec!["eig", "--model", name, "--speed", "5"],
        ] {
            let (code, stdout, stderr) = carvallo_in(&dir, &args);
            assert_eq!(code, 2, "{args:?}: {stderr}");
            assert_eq!(stdout, "", "{args:?}");
            let first = stderr.lines().next().unwrap_or("");
            assert!(first.starts_with("error: ") && first.contains(message), "{args:?}: {stderr}");
            assert!(first.contains(name), "{args:?}: the message names the file: {first}");
        }
    }
    let (code, _, stderr) = carvallo_in(&dir, &["report", "--out", "r", "--model", "absent.toml"]);
    assert_eq!(code, 2);
    assert!(stderr.starts_with("error: cannot read model file `absent.toml`"), "{stderr}");
    let (code, _, stderr) = carvallo_in(&dir, &["report", "--json", "--out", "r"]);
    assert_eq!(code, 2);
    assert!(
        stderr.starts_with("error: the argument '--json' cannot be used with '--out <DIR>'"),
        "{stderr}"
    );
    assert!(!dir.join("r").exists(), "nothing may be written");
    assert!(listing(&dir).iter().all(|n| n.ends_with(".toml")), "{:?}", listing(&dir));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn parameter_text_files_with_uncertainties() {
    let dir = scratch("text");
    let fixture = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/benchmark-1pct.txt");
    let good = std::fs::read_to_string(fixture).unwrap();
    std::fs::write(dir.join("bike.txt"), &good).unwrap();
    // Bad lines are usage errors naming the file, the line and the value; nothing is written.
    let bad = [
        (
            "bad-sigma.txt",
            good.replace("mB = 85.0+/-0.85", "mB = 85.0+/-heavy"),
            "line 15: mB: uncertainty `heavy` is not a number (`mB = 85.0+/-heavy`)",
        ),
        ("bad-name.txt", good.replace("rF = ", "rFront = "), "line 27: unknown parameter `rFront`"),
        ("no-table.toml", "[params]\nw = 1.0\n".to_string(), "no [parameters] table"),
    ];
    for (name, text, message) in &bad {
        std::fs::write(dir.join(name), text).unwrap();
        for args in [vec!["report", "--out", "r", "--model", name], vec!["window", "--model", name]]
        {
            let (code, stdout, stderr) = carvallo_in(&dir, &args);
            assert_eq!(code, 2, "{args:?}: {stderr}");
            assert_eq!(stdout, "");
            assert!(stderr.contains(message) && stderr.contains(name), "{args:?}: {stderr}");
        }
    }
    assert!(!dir.join("r").exists(), "nothing may be written");
    // The window of the text file is the benchmark's.
    let (code, stdout, _) = carvallo_in(&dir, &["window", "--model", "bike.txt"]);
    assert_eq!(code, 0);
    assert!(stdout.contains("stable from 4.292382536341106 to 6.024262015388359 m/s"), "{stdout}");
    // The report adds the uncertainty section and the bands figure, in both pages.
    let (code, _, stderr) = carvallo_in(&dir, &["report", "--out", "r", "--model", "bike.txt"]);
    assert_eq!(code, 0, "{stderr}");
    let md = std::fs::read_to_string(dir.join("r/report.md")).unwrap();
    let html = std::fs::read_to_string(dir.join("r/report.html")).unwrap();
    for page in [&md, &html] {
        assert!(page.contains("Uncertainty of the bicycle"));
        assert!(page.contains("4.2924") && page.contains("0.0397"), "weave speed and its std");
        assert!(page.contains("6.0243") && page.contains("0.0928"), "capsize speed and its std");
    }
    assert!(md.contains("](eigenvalue_bands.svg)"));
    assert!(html.contains("<figure id=\"eigenvalue_bands.svg\">"));
    let svg = std::fs::read_to_string(dir.join("r/eigenvalue_bands.svg")).unwrap();
    assert!(svg.contains("95 % band") && svg.contains("<polygon"), "the bands are drawn");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bicycleparameters_files_with_riders_warnings_and_strict() {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/bicycleparameters");
    let bike = format!("{data}/bicycles/Browser/Parameters/BrowserBenchmark.txt");
    let rider = format!("{data}/riders/Jason/Parameters/JasonBrowserBenchmark.txt");
    // A measured frame breaking a triangle inequality: computed, with a warning on stderr.
    let (code, stdout, stderr) = carvallo(&["window", "--model", &bike]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("weave speed: 4.19"), "{stdout}");
    assert!(
        stderr.starts_with("warning: ") && stderr.contains("IByy 1.3163960125 breaks a triangle"),
        "{stderr}"
    );
    // --strict: today's error, one line, no usage text.
    for args in [
        vec!["window", "--model", &bike, "--strict"],
        vec!["eig", "--strict", "--model", &bike, "--speed", "5"],
        vec!["sweep", "--model", &bike, "--strict", "--vary", "c=0.05:0.1:2"],
    ] {
        let (code, stdout, stderr) = carvallo(&args);
        assert_eq!((code, stdout.as_str()), (2, ""), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.contains("invalid IByy 1.3163960125: exceeds IBxx + IBzz"), "{stderr}");
    }
    // With the rider: the frame keeps the inequality, no warning.
    let (code, stdout, stderr) = carvallo(&["window", "--model", &bike, "--rider", &rider]);
    assert_eq!((code, stderr.as_str()), (0, ""), "{stderr}");
    assert!(stdout.contains("weave speed: 4.99"), "{stdout}");
    let (code, stdout, _) =
        carvallo(&["eig", "--model", &bike, "--rider", &rider, "--speed", "5", "--json"]);
    assert_eq!(code, 0);
    assert!(stdout.contains("\"eigenvalues\""), "{stdout}");
    // A bad rider file and a model that takes no rider.
    let (code, _, stderr) = carvallo(&["window", "--model", &bike, "--rider", &bike]);
    assert_eq!(code, 2);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("invalid rider file")
            && stderr.contains("line 5: unknown rider parameter `IFxx`")
    );
    let (code, _, stderr) = carvallo(&["window", "--model", "carvallo", "--rider", &rider]);
    assert_eq!(code, 2);
    assert!(stderr.contains("`--rider` and `--strict` read a bicycle file, not `carvallo`"));
    let (code, _, stderr) = carvallo(&["window", "--model", &bike, "--rider"]);
    assert_eq!(code, 2);
    assert!(stderr.starts_with("error: a value is required for '--rider <FILE.txt>'"), "{stderr}");
}

#[test]
fn a_report_for_one_bicycle_names_its_file_and_rider() {
    let dir = scratch("bicycle-report");
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/bicycleparameters");
    let bike = format!("{data}/bicycles/Browser/Parameters/BrowserBenchmark.txt");
    let rider = format!("{data}/riders/Jason/Parameters/JasonBrowserBenchmark.txt");
    let tms = format!("{data}/bicycles/Tms/Parameters/TmsBenchmark.txt");
    // With the rider: the bicycle's window (as `window --rider` prints it), its eigenvalues,
    // the uncertainty the files state, and no chapter of the memoir.
    let args = ["report", "--out", "r", "--model", &bike, "--rider", &rider];
    let (code, stdout, stderr) = carvallo_in(&dir, &args);
    assert_eq!((code, stderr.as_str()), (0, ""), "{stderr}");
    assert_eq!(
        stdout,
        "r/report.md\nr/report.html\nr/browser_jason_geometry.svg\nr/browser_jason_eigenvalues.svg\n\
         r/eigenvalue_bands.svg\nr/.carvallo-report\n"
    );
    let md = std::fs::read_to_string(dir.join("r/report.md")).unwrap();
    let html = std::fs::read_to_string(dir.join("r/report.html")).unwrap();
    let (_, window, _) = carvallo(&["window", "--model", &bike, "--rider", &rider, "--json"]);
    let w: serde_json::Value = serde_json::from_str(&window).unwrap();
    let weave = format!("Weave speed: {:?} m/s.", w["weave_speed"].as_f64().unwrap());
    for page in [&md, &html] {
        assert!(page.contains(&bike) && page.contains(&rider), "names the files");
        assert!(page.contains(&weave), "{weave}");
        assert!(page.contains("Uncertainty of the bicycle") && page.contains("eigenvalues.svg"));
        assert!(page.contains("Browser + Jason: eigenvalues against speed"), "titled by name");
        assert!(page.contains("Browser + Jason: geometry"), "titled by name");
        assert!(!page.contains("concordance"), "no memoir chapter");
    }
    // Browser alone: the broken triangle inequality is a warning, in the report too; --strict
    // refuses it and writes nothing.
    let (code, _, stderr) = carvallo_in(&dir, &["report", "--out", "r", "--model", &bike]);
    assert_eq!(code, 0);
    assert!(stderr.contains("IByy 1.3163960125 breaks a triangle inequality"), "{stderr}");
    let md = std::fs::read_to_string(dir.join("r/report.md")).unwrap();
    assert!(md.contains("Warning: ") && md.contains("by 2.331 %"), "{md}");
    let args = ["report", "--out", "s", "--model", &bike, "--strict"];
    let (code, stdout, stderr) = carvallo_in(&dir, &args);
    assert_eq!((code, stdout.as_str()), (2, ""));
    assert!(stderr.contains("invalid IByy 1.3163960125: exceeds IBxx + IBzz"), "{stderr}");
    assert!(!dir.join("s").exists(), "nothing may be written");
    // The two-mass-skate: stable above its weave speed, no capsize, no uncertainty stated.
    let (code, stdout, _) = carvallo_in(&dir, &["report", "--out", "t", "--model", &tms]);
    let files =
        "t/report.md\nt/report.html\nt/tms_geometry.svg\nt/tms_eigenvalues.svg\nt/.carvallo-report\n";
    assert_eq!((code, stdout.as_str()), (0, files));
    let md = std::fs::read_to_string(dir.join("t/report.md")).unwrap();
    assert!(md.contains("Capsize speed: none. Stable above 2.841008323370"), "{md}");
    // The whole report simulates the nonlinear bicycle: refused for it, nothing written.
    let (code, _, stderr) =
        carvallo_in(&dir, &["report", "--out", "u", "--model", &tms, "--memoir"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("for --memoir: the whole report simulates"), "{stderr}");
    assert!(!dir.join("u").exists(), "nothing may be written");
    // simulate takes --rider; the nonlinear model refuses the two-mass-skate by name.
    let sim = ["--speed", "5", "--lean0", "0.01", "--duration", "0.05", "--json"];
    let (code, out, stderr) =
        carvallo(&[&["simulate", "--model", &bike, "--rider", &rider][..], &sim].concat());
    assert_eq!((code, stderr.as_str()), (0, ""), "{stderr}");
    assert!(out.contains("\"energy_drift\""));
    let (code, _, stderr) = carvallo(&[&["simulate", "--model", &tms][..], &sim].concat());
    assert_eq!(code, 2);
    assert!(
        stderr.contains("invalid rR 0.0: must be positive for the nonlinear model"),
        "{stderr}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn issue_37_defects_of_the_command_line() {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/bicycleparameters");
    let bike = format!("{data}/bicycles/Browser/Parameters/BrowserBenchmark.txt");
    let rider = format!("{data}/riders/Jason/Parameters/JasonBrowserBenchmark.txt");
    // `eig` takes a list of speeds, as `statespace` and `bode` do; each speed's eigenvalues are
    // those of `eig` at that speed alone.
    let (code, both, _) = carvallo(&["eig", "--model", "benchmark", "--speed", "2,5"]);
    assert_eq!(code, 0);
    let (_, two, _) = carvallo(&["eig", "--model", "benchmark", "--speed", "2"]);
    let (_, five, _) = carvallo(&["eig", "--model", "benchmark", "--speed", "5"]);
    assert_eq!(both, format!("{two}{five}"));
    let (code, json, _) = carvallo(&["eig", "--model", "benchmark", "--speed", "2,5", "--json"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(
        v.as_array().map(|a| a.iter().map(|x| x["speed"].clone()).collect::<Vec<_>>()),
        Some(vec![serde_json::json!(2.0), serde_json::json!(5.0)])
    );
    let (code, _, err) = carvallo(&["eig", "--model", "benchmark", "--speed", "2,fast"]);
    assert_eq!(code, 2);
    assert!(err.contains("invalid value 'fast'"), "{err}");
    // Outputs say a rider was added: text headers and JSON.
    for args in [
        vec!["eig", "--speed", "5"],
        vec!["window"],
        vec!["bode", "--speed", "5", "--input", "steer", "--output", "roll", "--omega", "1"],
        vec!["statespace", "--speed", "5"],
    ] {
        let mut with: Vec<&str> = args.clone();
        with.extend(["--model", &bike, "--rider", &rider]);
        let (code, text, err) = carvallo(&with);
        assert_eq!(code, 0, "{with:?}: {err}");
        assert!(text.contains(&format!("with rider {rider}")), "{with:?}: {text}");
        {
            with.push("--json");
            let (_, json, _) = carvallo(&with);
            let v: serde_json::Value = serde_json::from_str(&json).unwrap();
            assert_eq!(v["rider"], serde_json::json!(rider), "{with:?}");
        }
        let mut without: Vec<&str> = args.clone();
        without.extend(["--model", &bike]);
        let (_, text, _) = carvallo(&without);
        assert!(!text.contains("rider"), "{without:?}: {text}");
    }
    // A rider file given as --model says what it is.
    let (code, out, err) = carvallo(&["eig", "--model", &rider, "--speed", "5"]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(err.contains("it is a rider file") && err.contains("--rider"), "{err}");
    // A step that does not divide the duration is refused, naming it.
    let (code, _, err) = carvallo(&[
        "simulate",
        "--model",
        "benchmark",
        "--speed",
        "5",
        "--lean0",
        "0.01",
        "--duration",
        "1",
        "--step",
        "0.3",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("0.3") && err.contains("does not divide the duration"), "{err}");
    // Grid values lo + i (hi - lo) / (n - 1): 0.08, not 0.07999999999999999.
    let (code, csv, _) =
        carvallo(&["sweep", "--model", "benchmark", "--vary", "c=0:0.12:4", "--csv"]);
    assert_eq!(code, 0);
    let cs: Vec<&str> = csv.lines().skip(1).map(|l| l.split(',').nth(1).unwrap()).collect();
    assert_eq!(cs, ["0.0", "0.04", "0.08", "0.12"]);
}
