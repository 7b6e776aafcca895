//! The exit-code contract of the built `carvallo` binary under generated arguments: a seeded
//! generator builds a few hundred invocations of every command (numbers at the edges of `f64`,
//! NaN, infinities, huge and negative counts, unknown names, empty and binary files) and each
//! must end with exit code 0 or 2, print no panic text, and on failure write nothing
//! (`report --out DIR` leaves no DIR).

use std::io::Write as _;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// SplitMix64, a fixed seed: the same invocations on every run.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[(self.next() % items.len() as u64) as usize]
    }
}

const NUMBERS: &[&str] = &[
    "0",
    "1",
    "-1",
    "0.5",
    "3",
    "NaN",
    "nan",
    "inf",
    "-inf",
    "1e308",
    "-1e308",
    "1e-320",
    "5e-324",
    "1.7976931348623157e308",
    "-0",
    "x",
    "",
    "1e",
    "90",
    "-90",
    "180",
    "4.3",
];
const COUNTS: &[&str] = &[
    "0",
    "1",
    "2",
    "3",
    "-1",
    "-5",
    "18446744073709551615",
    "18446744073709551616",
    "99999999999999999999",
    "1e3",
    "NaN",
    "x",
    "",
];
const MODELS: &[&str] = &[
    "benchmark",
    "benchmark",
    "benchmark",
    "carvallo",
    "nosuch",
    "EMPTY",
    "BINARY",
    "/nonexistent.toml",
    "TMS",
    "BROWSER",
    "lean-rider",
    "LEAN",
];
/// `--rider` files: Jason's on Browser, and the bad ones.
const RIDERS: &[&str] = &["JASON", "EMPTY", "BINARY", "nosuch", "BROWSER"];
const NAMES: &[&str] = &["c", "w", "mB", "g", "nosuch", "", "IRxx"];

/// Invocations run first, whatever the generator draws: the grids and counts (the
/// largest run until Ctrl-C).
const FIXED: &[&[&str]] = &[
    &["sweep", "--model", "benchmark", "--vary", "c=0:1:1000000", "--vary", "w=0.9:1.2:1000000"],
    &["sweep", "--model", "benchmark", "--random", "18446744073709551615", "--spread", "c=0.1"],
    &["sweep", "--model", "benchmark", "--vary", "c=0:0.2:18446744073709551615", "--csv"],
    &["sweep", "--model", "benchmark", "--vary", "c=0:1:4294967296", "--vary", "w=1:2:4294967296"],
    &["sweep", "--model", "benchmark", "--random", "18446744073709551616", "--spread", "c=0.1"],
    &[
        "sweep",
        "--model",
        "benchmark",
        "--gain",
        "k_roll_roll=0:100:1000000",
        "--gain",
        "k_steer_roll_rate=0:-50:1000000",
        "--csv",
    ],
    &["sweep", "--model", "benchmark", "--gain", "k_roll_roll=0:1:18446744073709551616"],
];
/// Gain names of the state feedback (`--gain`), valid and not.
const GAINS: &[&str] = &[
    "k_steer_roll_rate",
    "k_roll_roll",
    "k_steer_steer",
    "k_yaw",
    "",
    "k_lean_lean",
    "k_roll_lean_rate",
];

#[test]
fn every_command_keeps_the_exit_code_contract() {
    let dir = std::env::temp_dir().join(format!("carvallo-fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let empty = dir.join("empty.toml");
    std::fs::write(&empty, "").unwrap();
    let binary = dir.join("binary.toml");
    std::fs::write(&binary, [0u8, 159, 146, 150, 255, 0, 1, 2, b'=', 7]).unwrap();
    let torques = dir.join("torques.csv");
    std::fs::write(&torques, "t,T_phi,T_delta\n0,0,1\n0.05,1e308,-1\n0.1,0,0\n").unwrap();
    let decreasing = dir.join("decreasing.csv");
    std::fs::write(&decreasing, "t,T_delta\n0,1\n0.05,2\n0.01,0\n").unwrap();
    let gains = dir.join("gains.csv");
    std::fs::write(&gains, "speed,k_steer_roll_rate\n0,-20\n4,-1e308\n").unwrap();
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/bicycleparameters");
    let file = |name: &str| match name {
        "EMPTY" => empty.display().to_string(),
        "BINARY" => binary.display().to_string(),
        "TMS" => format!("{data}/bicycles/Tms/Parameters/TmsBenchmark.txt"),
        "BROWSER" => format!("{data}/bicycles/Browser/Parameters/BrowserBenchmark.txt"),
        "JASON" => format!("{data}/riders/Jason/Parameters/JasonBrowserBenchmark.txt"),
        "LEAN" => format!("{data}/../mooreriderlean2012/browser_jason.toml"),
        "TORQUES" => torques.display().to_string(),
        "DECREASING" => decreasing.display().to_string(),
        "GAINS" => gains.display().to_string(),
        m => m.to_string(),
    };
    let model = |rng: &mut Rng| file(rng.pick(MODELS));
    let mut rng = Rng(25);
    let start = Instant::now();
    let (mut runs, mut ok, mut stopped) = (0, 0, 0);
    for k in 0..300 {
        let mut args: Vec<String> = Vec::new();
        let mut out_dir = None;
        let mut stdin = String::new();
        let push = |a: &mut Vec<String>, flag: &str, v: String| {
            a.push(flag.to_string());
            a.push(v);
        };
        match k % 10 {
            0 => {
                let n = rng.pick(NAMES);
                // Half the axes valid on the benchmark, so that the sweeps run.
                let (n, from, to) = if rng.next().is_multiple_of(2) {
                    ("c", "0", "0.2")
                } else {
                    (n, rng.pick(NUMBERS), rng.pick(NUMBERS))
                };
                let axis = format!("{n}={from}:{to}:{}", rng.pick(COUNTS));
                args.push("sweep".into());
                push(&mut args, "--model", model(&mut rng));
                if rng.next().is_multiple_of(4) {
                    // A gain axis of a few values (an endless one is in FIXED).
                    let (from, to) = (rng.pick(NUMBERS), rng.pick(NUMBERS));
                    let count = rng.pick(&["0", "1", "3", "-1", "x"]);
                    let axis = format!("{}={from}:{to}:{count}", rng.pick(GAINS));
                    push(&mut args, "--gain", axis);
                } else {
                    push(&mut args, "--vary", axis);
                }
                if rng.next().is_multiple_of(2) {
                    let axis = format!("w=1:1.2:{}", rng.pick(COUNTS));
                    push(&mut args, "--vary", axis);
                }
            }
            1 => {
                args.push("sweep".into());
                push(&mut args, "--model", model(&mut rng));
                push(&mut args, "--random", rng.pick(COUNTS).into());
                push(&mut args, "--spread", format!("{}={}", rng.pick(NAMES), rng.pick(NUMBERS)));
                if rng.next().is_multiple_of(2) {
                    push(&mut args, "--method", rng.pick(&["eigen", "hurwitz", "qr"]).into());
                }
            }
            2 if k % 20 == 2 => {
                args.push("eig".into());
                push(&mut args, "--model", model(&mut rng));
                push(&mut args, "--speed", rng.pick(NUMBERS).into());
                if rng.next().is_multiple_of(2) {
                    let gain = format!("{}={}", rng.pick(GAINS), rng.pick(NUMBERS));
                    push(&mut args, "--gain", gain);
                }
            }
            2 if k % 40 == 12 || k % 40 == 32 => {
                args.push("bode".into());
                push(&mut args, "--model", model(&mut rng));
                push(&mut args, "--speed", rng.pick(NUMBERS).into());
                push(&mut args, "--input", rng.pick(&["roll", "steer", "yaw", ""]).into());
                let outputs = ["roll", "steer", "roll-rate", "steer-rate", "pitch"];
                push(&mut args, "--output", rng.pick(&outputs).into());
                if rng.next().is_multiple_of(2) {
                    push(
                        &mut args,
                        "--omega",
                        format!("{},{}", rng.pick(NUMBERS), rng.pick(NUMBERS)),
                    );
                } else {
                    let range =
                        format!("{}:{}:{}", rng.pick(NUMBERS), rng.pick(NUMBERS), rng.pick(COUNTS));
                    push(&mut args, "--omega-range", range);
                }
                if rng.next().is_multiple_of(2) {
                    args.push(rng.pick(&["--json", "--csv"]).into());
                }
            }
            2 => {
                args.push("statespace".into());
                push(&mut args, "--model", model(&mut rng));
                let speeds = format!("{},{}", rng.pick(NUMBERS), rng.pick(NUMBERS));
                push(&mut args, "--speed", speeds);
                if rng.next().is_multiple_of(2) {
                    args.push("--json".into());
                }
            }
            3 => {
                args.push("window".into());
                push(&mut args, "--model", model(&mut rng));
                match rng.next() % 4 {
                    0 => {}
                    1 => {
                        let gain = format!("{}={}", rng.pick(GAINS), rng.pick(NUMBERS));
                        push(&mut args, "--gain", gain);
                    }
                    2 => push(&mut args, "--assist-down-to", rng.pick(NUMBERS).into()),
                    _ => {
                        let gain = format!("{}={}", rng.pick(GAINS), rng.pick(NUMBERS));
                        push(&mut args, "--gain", gain);
                        push(&mut args, rng.pick(&["--vmin", "--vmax"]), rng.pick(NUMBERS).into());
                    }
                }
            }
            4 => {
                args.push("simulate".into());
                push(&mut args, "--model", model(&mut rng));
                push(&mut args, "--speed", rng.pick(NUMBERS).into());
                push(&mut args, "--lean0", rng.pick(NUMBERS).into());
                push(
                    &mut args,
                    "--duration",
                    rng.pick(&["0.1", "0", "-1", "NaN", "inf", "x"]).into(),
                );
                if rng.next().is_multiple_of(2) {
                    push(&mut args, "--step", rng.pick(NUMBERS).into());
                }
                if rng.next().is_multiple_of(2) {
                    push(&mut args, "--every", rng.pick(COUNTS).into());
                }
                if rng.next().is_multiple_of(2) {
                    let methods = ["rk4", "dopri5", "dop853", "vern9", "vern8", "euler", ""];
                    push(&mut args, "--method", rng.pick(&methods).into());
                }
                if rng.next().is_multiple_of(3) {
                    push(&mut args, "--rtol", rng.pick(NUMBERS).into());
                }
                if rng.next().is_multiple_of(3) {
                    push(&mut args, "--atol", rng.pick(NUMBERS).into());
                }
                if rng.next().is_multiple_of(3) {
                    let stops = [
                        "lean=±0.5",
                        "lean=+-0.1",
                        "steer=0",
                        "pitch=NaN",
                        "lean=±-1",
                        "speed=1",
                        "lean",
                        "=",
                        "x=1e308",
                    ];
                    push(&mut args, "--stop-when", rng.pick(&stops).into());
                }
                // The inputs of a driven run: torques (valid, off the grid, unknown, not
                // finite), sampled torques and feedback gains from files good and bad.
                if rng.next().is_multiple_of(3) {
                    let torques = [
                        "steer=step:0.5@0.05",
                        "roll=impulse:1@0.05",
                        "roll=impulse:1@0.0505",
                        "steer=impulse:1@5",
                        "steer=step:NaN",
                        "yaw=step:1",
                        "steer=ramp:1",
                        "roll=impulse:1e308@0",
                        "steer=step:1@-1",
                        "",
                    ];
                    push(&mut args, "--torque", rng.pick(&torques).into());
                }
                if rng.next().is_multiple_of(4) {
                    let csv = ["TORQUES", "DECREASING", "EMPTY", "BINARY", "/nonexistent.csv"];
                    push(&mut args, "--torque-csv", file(rng.pick(&csv)));
                }
                if rng.next().is_multiple_of(4) {
                    let gain = format!("{}={}", rng.pick(GAINS), rng.pick(NUMBERS));
                    push(&mut args, "--gain", gain);
                }
                if rng.next().is_multiple_of(5) {
                    let tables = ["GAINS", "EMPTY", "BINARY", "/nonexistent.csv"];
                    push(&mut args, "--gain-table", file(rng.pick(&tables)));
                }
            }
            5 => {
                args.push("accel".into());
                push(&mut args, "--model", model(&mut rng));
                args.push("--basu-mandal".into());
                let x = rng.pick(&["0", "NaN", "1e308", "\"x\"", "null", "-1"]);
                stdin = match rng.next() % 4 {
                    0 => String::new(),
                    1 => "\u{0}\u{ff}binary".into(),
                    2 => format!("{{\"q\": [{x}], \"qd\": []}}"),
                    _ => {
                        format!("{{\"q\": [{}], \"qd\": [{}]}}", [x; 9].join(","), [x; 9].join(","))
                    }
                };
            }
            6 if k % 30 != 6 => {
                // Two rounds in three the hoop or the unicycle instead of `turn`.
                args.push(if k % 30 == 16 { "hoop" } else { "unicycle" }.into());
                if k % 30 == 26 {
                    for flag in [
                        "--radius",
                        "--rider-mass",
                        "--rider-height",
                        "--rider-a",
                        "--rider-b",
                        "--rider-c",
                        "--wheel-mass",
                    ] {
                        let v = if rng.next().is_multiple_of(3) { rng.pick(NUMBERS) } else { "1" };
                        push(&mut args, flag, v.into());
                    }
                } else if rng.next().is_multiple_of(2) {
                    push(&mut args, "--radius", rng.pick(NUMBERS).into());
                }
                push(&mut args, "--theta0", rng.pick(NUMBERS).into());
                push(&mut args, "--s0", rng.pick(NUMBERS).into());
                push(&mut args, "--duration", rng.pick(&["0.1", "0", "-1", "NaN", "x"]).into());
                if rng.next().is_multiple_of(2) {
                    let methods = ["rk4", "dopri5", "dop853", "vern9", "vern8", ""];
                    push(&mut args, "--method", rng.pick(&methods).into());
                }
                if rng.next().is_multiple_of(3) {
                    push(&mut args, "--rtol", rng.pick(NUMBERS).into());
                }
                if rng.next().is_multiple_of(3) {
                    let stops = ["theta=±0.5", "p=0", "s=+-1", "theta=±-1", "lean=1", "n=nan"];
                    push(&mut args, "--stop-when", rng.pick(&stops).into());
                }
            }
            6 => {
                args.push("turn".into());
                push(&mut args, "--model", model(&mut rng));
                push(&mut args, "--gamma", rng.pick(NUMBERS).into());
                push(&mut args, "--speed", rng.pick(NUMBERS).into());
            }
            7 => {
                args.push("rest".into());
                push(&mut args, "--theta", rng.pick(NUMBERS).into());
                if rng.next().is_multiple_of(2) {
                    push(&mut args, "--wheel-mass", rng.pick(NUMBERS).into());
                }
            }
            8 => {
                args.push("kinematics".into());
                push(&mut args, "--theta", rng.pick(NUMBERS).into());
                push(&mut args, "--gamma", rng.pick(NUMBERS).into());
            }
            _ => {
                // Only models that fail: a successful report takes too long for this test.
                let out = dir.join(format!("out{k}"));
                args.push("report".into());
                push(&mut args, "--out", out.display().to_string());
                let m = match rng.next() % 3 {
                    0 => empty.display().to_string(),
                    1 => binary.display().to_string(),
                    _ => "nosuch".to_string(),
                };
                push(&mut args, "--model", m);
                out_dir = Some(out);
            }
        }
        // The options of a bicycle file, on the commands that read one.
        if k % 10 <= 4 || k % 10 == 9 {
            if rng.next().is_multiple_of(4) {
                push(&mut args, "--rider", file(rng.pick(RIDERS)));
            }
            if rng.next().is_multiple_of(8) {
                args.push("--strict".into());
            }
        }
        if rng.next().is_multiple_of(4) {
            args.push(rng.pick(&["--json", "--csv", "--bogus", "--json"]).into());
        }
        if let Some(fixed) = FIXED.get(k) {
            args = fixed.iter().map(|a| a.to_string()).collect();
            (out_dir, stdin) = (None, String::new());
        }
        let mut child = Command::new(env!("CARGO_BIN_EXE_carvallo"))
            .args(&args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        child.stdin.take().unwrap().write_all(stdin.as_bytes()).ok();
        // Both pipes drained as the command runs (a CSV sweep writes more than a pipe holds):
        // the number of bytes on standard output, the text of standard error.
        let mut stdout = child.stdout.take().unwrap();
        let mut stderr = child.stderr.take().unwrap();
        let stdout = std::thread::spawn(move || std::io::copy(&mut stdout, &mut std::io::sink()));
        let stderr = std::thread::spawn(move || {
            let mut text = String::new();
            std::io::Read::read_to_string(&mut stderr, &mut text).map(|_| text)
        });
        let t0 = Instant::now();
        // A sweep may be asked for 10^19 designs: Ctrl-C (SIGINT) after a few seconds must
        // stop it with its partial summary, exit 0.
        let mut interrupted = false;
        while child.try_wait().unwrap().is_none() {
            if !interrupted && t0.elapsed() > Duration::from_secs(3) {
                Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
                interrupted = true;
            }
            assert!(t0.elapsed() < Duration::from_secs(30), "{args:?} hangs");
            std::thread::sleep(Duration::from_millis(5));
        }
        let code = child.wait().unwrap().code();
        let written = stdout.join().unwrap().unwrap();
        let stderr = stderr.join().unwrap().unwrap_or_else(|e| format!("not text: {e}"));
        assert!(matches!(code, Some(0 | 2)), "{args:?}: exit {code:?}\n{stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(!stderr.contains("RUST_BACKTRACE"), "{args:?}: {stderr}");
        if code == Some(2) {
            // Warnings about the data read (a broken triangle inequality) may come first.
            let message = stderr.lines().find(|l| !l.starts_with("warning: ")).unwrap_or("");
            assert!(message.starts_with("error: "), "{args:?}: no message: {stderr}");
            assert_eq!(written, 0, "{args:?}: output on failure");
        }
        if let Some(d) = out_dir {
            assert!(code == Some(2) && !d.exists(), "{args:?}: exit {code:?}, wrote {d:?}");
        }
        runs += 1;
        ok += usize::from(code == Some(0));
        // The endless sweeps of FIXED (a drawn one may be endless too).
        stopped += usize::from(interrupted && k < FIXED.len());
    }
    std::fs::remove_dir_all(&dir).unwrap();
    eprintln!(
        "{runs} invocations ({ok} exit 0, {stopped} interrupted) in {:.1} s",
        start.elapsed().as_secs_f64()
    );
    // Both outcomes occur: the generator reaches past the argument checks.
    assert_eq!(runs, 300);
    assert!(ok >= 20 && runs - ok >= 20, "{ok} of {runs} succeeded");
    assert_eq!(stopped, 4, "the four endless sweeps of FIXED were not all interrupted");
}
