//! `carvallo parameters --raw FILE`: the parameter file it writes is read back by `--model`
//! with the weave speed `window` gives for BicycleParameters' own benchmark file of the same
//! bicycle (the same computation, printed to 16 digits: 9e-12 m/s apart), and bad input is exit code 2 with
//! a message naming the file and the line or measurement, nothing written.

use std::process::Command;

fn carvallo(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo")).args(args).output().unwrap();
    let text = |b: Vec<u8>| String::from_utf8(b).unwrap();
    (out.status.code().unwrap_or(-1), text(out.stdout), text(out.stderr))
}

fn data(rel: &str) -> String {
    format!("{}/../../data/bicycleparameters/{rel}", env!("CARGO_MANIFEST_DIR"))
}

fn weave(model: &str) -> f64 {
    let (code, json, err) = carvallo(&["window", "--model", model, "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    v["weave_speed"].as_f64().unwrap()
}

#[test]
fn raw_measurements_give_the_bicycle_of_the_benchmark_file() {
    let dir = std::env::temp_dir().join(format!("carvallo-raw-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("Browser.txt");
    let out = out.to_str().unwrap();
    let raw = data("bicycles/Browser/RawData/BrowserMeasured.txt");
    let (code, text, err) = carvallo(&["parameters", "--raw", &raw, "--out", out]);
    assert_eq!((code, text.trim()), (0, format!("wrote {out}").as_str()), "{err}");
    let (code, printed, _) = carvallo(&["parameters", "--raw", &raw]);
    assert_eq!((code, printed), (0, std::fs::read_to_string(out).unwrap()));
    let ours = weave(out);
    let file = weave(&data("bicycles/Browser/Parameters/BrowserBenchmark.txt"));
    assert!((ours - file).abs() < 1e-10, "{ours} {file}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_raw_files_exit_2_naming_the_problem() {
    let (code, out, err) =
        carvallo(&["parameters", "--raw", &data("bicycles/Silver/RawData/SilverMeasured.txt")]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(
        err.contains("invalid raw measurement file `") && err.contains("missing measurement dF"),
        "{err}"
    );
    assert!(!err.contains("Usage"), "{err}");
    let (code, _, err) = carvallo(&["parameters", "--raw", "no/such/file.txt"]);
    assert_eq!(code, 2);
    assert!(err.contains("cannot read raw measurement file `no/such/file.txt`"), "{err}");
    let (code, _, err) = carvallo(&["parameters", "--raw", &data("README.md")]);
    assert_eq!(code, 2);
    assert!(err.contains("line 3: expected `name = value`"), "{err}");
}

#[test]
fn endless_and_non_regular_raw_files_are_refused_with_the_bound_named() {
    let (code, out, err) = carvallo(&["parameters", "--raw", "/dev/zero"]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty(), "{out}");
    assert!(
        err.starts_with("error: cannot read raw measurement file `/dev/zero`: larger than 16 MiB"),
        "{err}"
    );
    let dir = data("bicycles/Browser/RawData");
    let (code, _, err) = carvallo(&["parameters", "--raw", &dir]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("it is a directory"), "{err}");
}
