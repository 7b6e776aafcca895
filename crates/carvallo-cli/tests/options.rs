//! Every option that takes a value, of every command, at the edges of `f64` and beyond: the
//! options are enumerated at test time from clap's command table (through the completion
//! script `carvallo completions fish` that clap generates from it), so a new command or option
//! is covered without touching this test, and a command without a base invocation here fails it.
//!
//! Each case is a valid base invocation of the command with one option set to a value drawn
//! (seeded) from [`VALUES`]: it must end with exit code 0 or 2, without a panic; exit 2 must
//! print an `error:` line naming the option or the value; exit 0 must print no NaN or infinity.
//! `CARVALLO_FUZZ_SEED` reruns it with another seed; the counts are printed.

use std::io::Write as _;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Values at the edges: overflowing, at the ends of the ranges the options accept, subnormal,
/// zero of both signs, not finite, not numbers, counts past `u64`.
const VALUES: &[&str] = &[
    "1e308",
    "-1e308",
    "1.7976931348623157e308",
    "1e300",
    "-1e300",
    "1e30",
    "-1e30",
    "1e12",
    "-1e12",
    "1e7",
    "1e6",
    "-1e6",
    "1e-6",
    "1e-30",
    "5e-324",
    "-5e-324",
    "1e-300",
    "0",
    "-0",
    "-1",
    "NaN",
    "inf",
    "-inf",
    "18446744073709551616",
    "x",
    "",
];

/// Values drawn per option (besides `1e308`, always tried).
const DRAWS: usize = 8;

/// A valid invocation of each command, quick to run; `accel` reads [`STATE`].
const BASES: &[&[&str]] = &[
    &["report"],
    &["window", "--model", "benchmark"],
    &["eig", "--model", "benchmark", "--speed", "5"],
    &["statespace", "--model", "benchmark", "--speed", "5"],
    &[
        "bode",
        "--model",
        "benchmark",
        "--speed",
        "5",
        "--input",
        "steer",
        "--output",
        "roll",
        "--omega-range",
        "0.1:10:3",
    ],
    &["plot", "bode", "--model", "benchmark", "--omega-range", "0.1:10:3"],
    &["bench", "--quick"],
    &["sweep", "--model", "benchmark", "--vary", "c=0:0.1:3"],
    &["accel", "--model", "benchmark", "--basu-mandal"],
    &["simulate", "--model", "benchmark", "--speed", "5", "--lean0", "0.01", "--duration", "0.05"],
    &["turn", "--model", "carvallo", "--gamma", "5", "--speed", "3"],
    &["rest", "--theta", "10"],
    &["kinematics", "--theta", "10", "--gamma", "5"],
    &["hoop", "--theta0", "0.1", "--s0", "3", "--duration", "0.05"],
    &[
        "unicycle",
        "--radius",
        "0.5",
        "--rider-mass",
        "60",
        "--rider-height",
        "1.25",
        "--rider-a",
        "100",
        "--rider-b",
        "99.5",
        "--rider-c",
        "1.4",
        "--wheel-mass",
        "5",
        "--theta0",
        "0.05",
        "--s0",
        "13",
        "--duration",
        "0.05",
    ],
    &["response", "--model", "benchmark", "--speed", "5", "--kind", "step", "--samples", "5"],
    &[
        "parameters",
        "--raw",
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../data/bicycleparameters/bicycles/Browser/RawData/BrowserMeasured.txt"
        ),
    ],
    &["pendulum", "simulate", "--t-end", "0.05", "--pitch0", "0.05", "--gain", "placed"],
    &["completions", "bash"],
];

/// Options not varied: `report --out` writes a whole report for every value that names a
/// directory (ten seconds each); its edges are the tests of `report_out.rs`. `parameters --out`
/// is a file name, not a number: `--out=-inf` writes the file `-inf` and says so, which is right;
/// so is `plot --out`, and `pendulum --csv` (`--csv=inf` writes the CSV file `inf`).
const SKIPPED: &[(&str, &str)] =
    &[("report", "out"), ("parameters", "out"), ("plot", "out"), ("pendulum", "csv")];

/// The state of `accel`'s standard input.
const STATE: &str = r#"{"q": [0, 0, 0, 0, 1.5, 2.8, 0, 0, 0], "qd": [0, 0, 0, 0, 1, 0, 1, 1, 0]}"#;

/// SplitMix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
}

/// The options that take a value, by command, read from clap's fish completion script: a line
/// `complete -c carvallo -n "__fish_carvallo_using_subcommand CMD" -l NAME ... -r ...` for each.
fn options() -> Vec<(String, Vec<String>)> {
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo"))
        .args(["completions", "fish"])
        .output()
        .unwrap();
    let script = String::from_utf8(out.stdout).unwrap();
    let mut table: Vec<(String, Vec<String>)> = Vec::new();
    for line in script.lines() {
        let Some(rest) = line.split("__fish_carvallo_using_subcommand ").nth(1) else { continue };
        let command = rest.split(['"', ' ', ';']).next().unwrap().to_string();
        let words: Vec<&str> = line.split(' ').collect();
        let long = words.iter().position(|w| *w == "-l").map(|k| words[k + 1].to_string());
        // `-r`: the option requires a value; `-f -a` alone lists the subcommands.
        let takes_value = words.contains(&"-r");
        let entry = match table.iter_mut().find(|(c, _)| *c == command) {
            Some(e) => e,
            None => {
                table.push((command.clone(), Vec::new()));
                table.last_mut().unwrap()
            }
        };
        if let (Some(long), true) = (long, takes_value) {
            if !entry.1.contains(&long) {
                entry.1.push(long);
            }
        }
    }
    table.retain(|(c, _)| c != "help");
    table
}

/// Whether `text` prints a NaN or an infinity as a number.
fn not_finite(text: &str) -> Option<&str> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '+'))
        .find(|w| matches!(w.trim_start_matches(['-', '+']), "NaN" | "nan" | "inf" | "Infinity"))
}

#[test]
fn every_numeric_option_keeps_the_contract_at_the_edges() {
    let seed = std::env::var("CARVALLO_FUZZ_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(39);
    let mut rng = Rng(seed);
    let dir = std::env::temp_dir().join(format!("carvallo-options-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let table = options();
    assert!(table.len() >= 15 && table.iter().any(|(c, o)| c == "hoop" && o.len() > 10));
    let mut cases = Vec::new();
    for (command, opts) in &table {
        let base = BASES
            .iter()
            .find(|b| b[0] == command)
            .unwrap_or_else(|| panic!("no base invocation of `{command}` in BASES"));
        for opt in opts {
            if SKIPPED.contains(&(command.as_str(), opt.as_str())) {
                continue;
            }
            let mut values = vec!["1e308"];
            while values.len() < 1 + DRAWS {
                let v = VALUES[(rng.next() % VALUES.len() as u64) as usize];
                if !values.contains(&v) {
                    values.push(v);
                }
            }
            for v in values {
                let mut args: Vec<String> = base.iter().map(|a| a.to_string()).collect();
                // `--NAME=VALUE`: a value starting with `-` is the option's, not a flag.
                let flag = format!("--{opt}");
                if let Some(k) = args.iter().position(|a| *a == flag) {
                    args.drain(k..k + 2);
                }
                args.push(format!("{flag}={v}"));
                cases.push((opt.clone(), v, args));
            }
        }
    }
    let start = Instant::now();
    let failures = std::sync::Mutex::new(Vec::new());
    let next = std::sync::atomic::AtomicUsize::new(0);
    std::thread::scope(|s| {
        for _ in 0..4 {
            s.spawn(|| loop {
                let k = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some((opt, v, args)) = cases.get(k) else { break };
                if let Err(why) = run(&dir, opt, v, args) {
                    failures.lock().unwrap().push(format!("{args:?}: {why}"));
                }
            });
        }
    });
    let failures = failures.into_inner().unwrap();
    let options: usize = table.iter().map(|(_, o)| o.len()).sum();
    eprintln!(
        "seed {seed}: {} commands, {options} options with a value, {} cases, {} failures in {:.1} s",
        table.len(),
        cases.len(),
        failures.len(),
        start.elapsed().as_secs_f64()
    );
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

/// Runs one case in `dir`; the error says which part of the contract it broke.
fn run(dir: &std::path::Path, opt: &str, value: &str, args: &[String]) -> Result<(), String> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_carvallo"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let stdin = if args[0] == "accel" { STATE } else { "" };
    child.stdin.take().unwrap().write_all(stdin.as_bytes()).ok();
    let (mut stdout, mut stderr) = (child.stdout.take().unwrap(), child.stderr.take().unwrap());
    let stdout = std::thread::spawn(move || {
        let mut text = Vec::new();
        std::io::Read::read_to_end(&mut stdout, &mut text).map(|_| text)
    });
    let stderr = std::thread::spawn(move || {
        let mut text = Vec::new();
        std::io::Read::read_to_end(&mut stderr, &mut text).map(|_| text)
    });
    let t0 = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if t0.elapsed() > Duration::from_secs(60) {
            child.kill().unwrap();
            return Err("runs over 60 s".into());
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    let code = child.wait().unwrap().code();
    let out = String::from_utf8_lossy(&stdout.join().unwrap().unwrap()).into_owned();
    let err = String::from_utf8_lossy(&stderr.join().unwrap().unwrap()).into_owned();
    if err.contains("panicked") || err.contains("RUST_BACKTRACE") {
        return Err(format!("panic: {err}"));
    }
    match code {
        Some(0) => match not_finite(&out) {
            Some(w) => Err(format!("exit 0 printing `{w}`")),
            None => Ok(()),
        },
        Some(2) => {
            let message = err.lines().find(|l| !l.starts_with("warning: ")).unwrap_or("");
            if !message.starts_with("error: ") {
                return Err(format!("exit 2 without an error line: {err}"));
            }
            // A diverged integration names the step that was too long for the value.
            let diverged = message.starts_with("error: the integration diverged")
                && message.contains("--step");
            if !err.contains(&format!("--{opt}"))
                && !err.contains(&format!("`{value}`"))
                && !err.contains(&format!("'{value}'"))
                && !diverged
            {
                return Err(format!("the error names neither --{opt} nor `{value}`: {err}"));
            }
            Ok(())
        }
        other => Err(format!("exit {other:?}: {err}")),
    }
}
