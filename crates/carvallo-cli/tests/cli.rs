//! End-to-end tests of the `carvallo` binary: the report in both formats, the help, and the
//! exit code 2 with a message naming an unknown argument.

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
    assert!(text.contains("carvallo report [--json]"));
    let (code, _, err) = carvallo(&["report", "--frobnicate"]);
    assert_eq!(code, 2);
    assert!(err.starts_with("error: unknown argument `--frobnicate`"), "{err}");
    let (code, _, err) = carvallo(&[]);
    assert_eq!(code, 2);
    assert!(err.starts_with("error: missing command"), "{err}");
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
