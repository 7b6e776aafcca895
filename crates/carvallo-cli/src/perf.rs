//! The measurement subcommands of the `carvallo` command line.
//!
//! * `carvallo bench [--json] [--quick] [--only simulation]`: the tables of [`crate::bench`]
//!   (time per evaluation beside the error against a 256-bit reference, measured in the same
//!   run, the targets, and the simulations' work against precision), as text or as
//!   one JSON object `{mode, rows, distributions, targets, simulation,
//!   simulation_references}`. `--quick` runs tiny samples (seconds); the default is the full
//!   measurement ($10^6$ samples and sweep designs, 5 to 15 minutes on a busy 2-core
//!   machine). `--only simulation` runs the simulation section alone.
//! * `carvallo sweep --model benchmark|FILE.toml (--vary NAME=FROM:TO:COUNT ... |
//!   --random N --spread NAME=REL ... [--seed S]) [--method hurwitz|eigen] [--json | --csv]`:
//!   the stability window of many designs, in parallel, with a progress bar when standard error
//!   is a terminal. Several `--vary` make a grid (every combination, the first varying slowest);
//!   `--random N` draws N designs around the model, each `--spread` parameter scaled by a
//!   uniform factor in [1 - REL, 1 + REL] (seeded: the same `--seed` gives the same designs on
//!   any number of threads). Prints a summary (JSON keys `model`, `parameters`, `designs`
//!   (`grid` or `random`), `count`, `method`, `threads`, `elapsed`, `designs_per_second`,
//!   `stable`, `with_weave`, `with_capsize`, `weave_speed_range`, `capsize_speed_range`,
//!   `failed`, `rejected`, and for one `--vary` also `parameter`, `from`, `to`; `vary` or
//!   `random` describe the designs), or with `--csv` one row per design: `design`, the varied
//!   parameters, `status` (`ok`, `failed`: no window, `rejected`: no valid random draw),
//!   `stable`, `weave_speed`, `capsize_speed` (empty when there is none), for
//!   `pandas.read_csv`.
//!
//!   With `--gain NAME=FROM:TO:COUNT ...` instead of `--vary`/`--random` it sweeps the gains of
//!   a state feedback on the model: the closed-loop stable speed range of every gain set
//!   ([`crate::gain_sweep`]).
//!
//!   The designs stream in blocks ([`sweep::sweep_stream`]): memory does not depend on their
//!   number, CSV rows are written as the blocks finish, and Ctrl-C ends the sweep with the
//!   summary of the designs done and the line `interrupted after K of N designs` (exit 0).
//!
//! Bad arguments are usage errors naming the value, exit code 2 (a count that does not fit a
//! `usize` too).

use std::io::{IsTerminal, Write};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Duration;

use carvallo::sweep::{self, Designs, Method, SweepOutput};
use serde_json::{json, Value};

use crate::interrupt::interrupt_flag;
pub use crate::sweep_args::{MethodArg, SweepArgs};

/// How `sweep` prints its result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Output {
    Text,
    Json,
    Csv,
}

/// `carvallo bench`: time per evaluation beside the error against 256 bits.
#[derive(Clone, Debug, Default, PartialEq, Eq, clap::Args)]
pub struct BenchArgs {
    /// Print one JSON object {mode, rows, distributions, targets} instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Tiny samples (seconds) instead of the full measurement (minutes)
    #[arg(long)]
    pub quick: bool,
    /// Only the section SECTION (`simulation`: the work-precision rows of the simulations)
    #[arg(long, value_enum, value_name = "SECTION")]
    pub only: Option<Section>,
}

/// A section `carvallo bench --only` runs alone.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Section {
    /// Error against work of the simulations (every method and tolerance)
    Simulation,
}

#[derive(Debug, PartialEq)]
struct Sweep {
    model: String,
    data: crate::args::DataOptions,
    designs: Designs,
    method: Method,
    output: Output,
}

impl SweepArgs {
    /// The sweep these options describe (clap has checked that they fit together).
    fn sweep(&self) -> Sweep {
        let designs = match self.random {
            Some(count) => Designs::Random {
                count,
                spreads: self.spread.clone(),
                seed: self.seed.unwrap_or(1),
            },
            None => Designs::Grid(self.vary.clone()),
        };
        let method = match self.method {
            MethodArg::Hurwitz => Method::Hurwitz,
            MethodArg::Eigen => Method::Eigen,
        };
        let output = match (self.json, self.csv) {
            (true, _) => Output::Json,
            (_, true) => Output::Csv,
            _ => Output::Text,
        };
        Sweep { model: self.model.clone(), data: self.data.clone(), designs, method, output }
    }
}

/// Draws an `indicatif` progress bar of the sweep's designs on standard error (only when it
/// is a terminal: indicatif hides it otherwise), with the rate and the time left, until `done`
/// is set; the bar is cleared at the end.
fn progress_bar(counter: &AtomicUsize, total: usize, done: &AtomicBool) {
    progress_bar_of(counter, total, done, "designs")
}

/// The same progress bar counting `what` (`designs`, `simulations`).
pub(crate) fn progress_bar_of(counter: &AtomicUsize, total: usize, done: &AtomicBool, what: &str) {
    let bar = indicatif::ProgressBar::with_draw_target(
        Some(total as u64),
        indicatif::ProgressDrawTarget::stderr(),
    );
    let style = indicatif::ProgressStyle::with_template(&format!(
        "[{{bar:40}}] {{human_pos}}/{{human_len}} {what}, {{per_sec}}, {{eta}} left"
    ))
    .map(|s| s.progress_chars("## "))
    .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar());
    bar.set_style(style);
    while !done.load(Ordering::Relaxed) {
        bar.set_position(counter.load(Ordering::Relaxed).min(total) as u64);
        std::thread::sleep(Duration::from_millis(100));
    }
    bar.finish_and_clear();
}

/// An `indicatif` spinner on standard error for `carvallo bench` (drawn only when standard
/// error is a terminal), with the elapsed time and the part being measured.
fn bench_spinner() -> indicatif::ProgressBar {
    let spinner =
        indicatif::ProgressBar::with_draw_target(None, indicatif::ProgressDrawTarget::stderr());
    let style = indicatif::ProgressStyle::with_template("{spinner} bench, {elapsed}: {msg}")
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_spinner());
    spinner.set_style(style);
    spinner.enable_steady_tick(Duration::from_millis(120));
    spinner
}

fn range(r: Option<(f64, f64)>) -> Value {
    r.map_or(Value::Null, |(a, b)| json!([a, b]))
}

/// Runs `carvallo bench`: the tables to print.
pub fn bench(args: &BenchArgs) -> Result<String, String> {
    let cfg = if args.quick { crate::bench::Config::quick() } else { crate::bench::Config::full() };
    let spinner = bench_spinner();
    let mut report = if args.only == Some(Section::Simulation) {
        crate::bench::Report {
            mode: if args.quick { "quick" } else { "full" },
            rows: Vec::new(),
            distributions: Vec::new(),
            targets: Vec::new(),
            simulation: Vec::new(),
            simulation_references: Vec::new(),
        }
    } else {
        spinner.set_message("evaluators, windows, eigenvalues, sweeps");
        let mut report = crate::bench::run(&cfg);
        spinner.set_message("the C peer (cc -O3)");
        crate::bench::extend(&cfg, &mut report);
        report
    };
    spinner.set_message("simulations: work against precision");
    crate::bench::simulation::simulation_rows(
        &cfg,
        &mut report.simulation,
        &mut report.simulation_references,
    );
    spinner.finish_and_clear();
    if args.json {
        serde_json::to_string_pretty(&report).map_err(|e| e.to_string())
    } else {
        Ok(crate::bench::render_text(&report))
    }
}

/// Runs `carvallo sweep`: the summary to print (the CSV rows are written as they come), or an
/// error naming the bad value.
pub fn sweep(args: &SweepArgs) -> Result<String, String> {
    if !args.gain.is_empty() {
        return crate::gain_sweep::run(args);
    }
    if args.vmin.is_some() || args.vmax.is_some() {
        return Err("--vmin and --vmax bound the closed-loop windows of --gain".into());
    }
    let Sweep { model, data, designs, method, output } = args.sweep();
    let base = crate::args::bicycle(&model, &data)?;
    let count = match &designs {
        Designs::Grid(axes) => {
            axes.iter().try_fold(1usize, |n, a| n.checked_mul(a.count)).ok_or_else(|| {
                let counts = axes.iter().map(|a| a.count).collect();
                sweep::DesignsError::TooManyDesigns { counts }.to_string()
            })?
        }
        Designs::Random { count, .. } => *count,
    };
    let counter = AtomicUsize::new(0);
    let done = AtomicBool::new(false);
    let stop = interrupt_flag();
    let names: Vec<&str> = match &designs {
        Designs::Grid(axes) => axes.iter().map(|a| a.name.as_str()).collect(),
        Designs::Random { spreads, .. } => spreads.iter().map(|s| s.name.as_str()).collect(),
    };
    let stdout = std::io::BufWriter::new(std::io::stdout().lock());
    let mut rows = CsvRows::new(stdout, &names, stop);
    let out = std::thread::scope(|s| {
        if std::io::stderr().is_terminal() {
            s.spawn(|| progress_bar(&counter, count, &done));
        }
        let sink: Option<&mut dyn FnMut(&sweep::SweepChunk<'_>)> = match output {
            Output::Csv => Some(&mut |c: &sweep::SweepChunk<'_>| rows.chunk(c)),
            _ => None,
        };
        let r = sweep::sweep_stream(&base, &designs, method, &counter, stop, sink);
        done.store(true, Ordering::Relaxed);
        r
    })
    .map_err(|e| e.to_string())?;
    let method = if method == Method::Hurwitz { "hurwitz" } else { "eigen" };
    let interrupted = (out.summary.count < out.requested)
        .then(|| format!("interrupted after {} of {} designs", out.summary.count, out.requested));
    match output {
        Output::Csv => {
            let last = rows.finish().map_err(|e| format!("cannot write the output: {e}"))?;
            if let Some(line) = &interrupted {
                eprintln!("{}\n{line}", summary_text(&designs, method, &out));
            }
            Ok(last)
        }
        Output::Json => {
            let mut v = summary_json(&model, &designs, method, &out);
            if let Some(line) = &interrupted {
                eprintln!("{line}");
                v["interrupted"] = json!(line);
            }
            serde_json::to_string_pretty(&v).map_err(|e| e.to_string())
        }
        Output::Text => {
            let text = summary_text(&designs, method, &out);
            Ok(match interrupted {
                Some(line) => format!("{text}\n{line}"),
                None => text,
            })
        }
    }
}

/// The CSV of a sweep (see the [module docs](self)) written to `out` as the blocks arrive,
/// floats in Rust's shortest round-trip form. The last line is held back and returned by
/// [`CsvRows::finish`], for the caller to print with its final newline like any output. A
/// write that fails sets `stop` (the sweep ends) and is reported by `finish`, except a closed
/// pipe (`| head`), which ends the output quietly.
struct CsvRows<W: Write> {
    out: W,
    stop: &'static AtomicBool,
    pending: String,
    error: Option<std::io::Error>,
}

impl<W: Write> CsvRows<W> {
    /// Starts with the header of the varied parameters `names`.
    fn new(out: W, names: &[&str], stop: &'static AtomicBool) -> Self {
        let pending = format!("design,{},status,stable,weave_speed,capsize_speed", names.join(","));
        CsvRows { out, stop, pending, error: None }
    }

    fn write(&mut self, line: String) {
        let previous = std::mem::replace(&mut self.pending, line);
        if self.error.is_none() {
            if let Err(e) = writeln!(self.out, "{previous}") {
                self.stop.store(true, Ordering::Relaxed);
                self.error = Some(e);
            }
        }
    }

    fn chunk(&mut self, c: &sweep::SweepChunk<'_>) {
        let k = if c.valid.is_empty() { 0 } else { c.values.len() / c.valid.len() };
        let opt = |x: Option<f64>| x.map_or(String::new(), |x| format!("{x:?}"));
        for (j, (w, valid)) in c.windows.iter().zip(c.valid).enumerate() {
            let values: Vec<String> =
                c.values[j * k..(j + 1) * k].iter().map(|x| format!("{x:?}")).collect();
            let status = match w {
                Some(w) => {
                    format!("ok,{},{},{}", w.stable, opt(w.weave_speed), opt(w.capsize_speed))
                }
                None if *valid => "failed,,,".to_string(),
                None => "rejected,,,".to_string(),
            };
            self.write(format!("{},{},{status}", c.first + j, values.join(",")));
        }
    }

    /// Flushes the lines but the last and returns it (empty after a closed pipe).
    fn finish(mut self) -> std::io::Result<String> {
        match self.error.take() {
            Some(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(String::new()),
            Some(e) => Err(e),
            None => match self.out.flush() {
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(String::new()),
                other => other.map(|()| self.pending),
            },
        }
    }
}

/// The JSON summary of a sweep (see the [module docs](self)).
fn summary_json(model: &str, designs: &Designs, method: &str, out: &SweepOutput) -> Value {
    let s = &out.summary;
    let mut v = json!({
        "model": model,
        "parameters": out.names,
        "count": s.count,
        "method": method,
        "threads": rayon_threads(),
        "elapsed": s.elapsed,
        "designs_per_second": s.designs_per_second,
        "stable": s.stable,
        "with_weave": s.with_weave,
        "with_capsize": s.with_capsize,
        "weave_speed_range": range(s.weave_range),
        "capsize_speed_range": range(s.capsize_range),
        "failed": s.failed,
        "rejected": out.rejected,
    });
    match designs {
        Designs::Grid(axes) => {
            v["designs"] = json!("grid");
            v["vary"] = axes
                .iter()
                .map(|a| json!({"parameter": a.name, "from": a.from, "to": a.to, "count": a.count}))
                .collect();
            if let [a] = &axes[..] {
                v["parameter"] = json!(a.name);
                v["from"] = json!(a.from);
                v["to"] = json!(a.to);
            }
        }
        Designs::Random { count, spreads, seed } => {
            v["designs"] = json!("random");
            v["random"] = json!({
                "count": count,
                "seed": seed,
                "spreads": spreads.iter().map(|s| json!({"parameter": s.name, "rel": s.rel})).collect::<Vec<_>>(),
            });
        }
    }
    v
}

/// The one-line text summary of a sweep.
fn summary_text(designs: &Designs, method: &str, out: &SweepOutput) -> String {
    let s = &out.summary;
    let what = match designs {
        Designs::Grid(axes) => axes
            .iter()
            .map(|a| format!("{} from {} to {} ({})", a.name, a.from, a.to, a.count))
            .collect::<Vec<_>>()
            .join(" x "),
        Designs::Random { spreads, seed, .. } => format!(
            "random around the model ({}; seed {seed}), {} rejected",
            spreads
                .iter()
                .map(|s| format!("{} +-{}", s.name, s.rel))
                .collect::<Vec<_>>()
                .join(", "),
            out.rejected
        ),
    };
    format!(
        "{} designs, {what}, method {method}: {:.3} s ({:.0} designs/s), {} with a stable speed \
         range, weave speeds {}, capsize speeds {}",
        s.count,
        s.elapsed,
        s.designs_per_second,
        s.stable,
        range(s.weave_range),
        range(s.capsize_range)
    )
}

/// The number of worker threads the sweep uses.
fn rayon_threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;
    use carvallo::sweep::{Spread, Vary};

    fn sweep_of(words: &[&str]) -> Result<Sweep, String> {
        parse::<SweepArgs>(&[&["sweep", "--model"], words].concat()).map(|a| a.sweep())
    }

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse::<BenchArgs>(&["bench", "--quick", "--json"]),
            Ok(BenchArgs { json: true, quick: true, only: None })
        );
        let vary = |name: &str, from: f64, to: f64, count: usize| Vary {
            name: name.into(),
            from,
            to,
            count,
        };
        assert_eq!(
            sweep_of(&["benchmark", "--vary", "c=0:0.2:10"]),
            Ok(Sweep {
                data: crate::args::DataOptions::default(),
                model: "benchmark".into(),
                designs: Designs::Grid(vec![vary("c", 0.0, 0.2, 10)]),
                method: Method::Hurwitz,
                output: Output::Text,
            })
        );
        assert_eq!(
            sweep_of(&["b", "--vary", "c=0:0.2:10", "--csv", "--vary", "w=1:1.2:3"]),
            Ok(Sweep {
                data: crate::args::DataOptions::default(),
                model: "b".into(),
                designs: Designs::Grid(vec![vary("c", 0.0, 0.2, 10), vary("w", 1.0, 1.2, 3)]),
                method: Method::Hurwitz,
                output: Output::Csv,
            })
        );
        assert_eq!(
            sweep_of(&[
                "b", "--random", "100", "--spread", "c=0.1", "--spread", "mB=0.2", "--seed", "9",
                "--json", "--method", "eigen"
            ]),
            Ok(Sweep {
                data: crate::args::DataOptions::default(),
                model: "b".into(),
                designs: Designs::Random {
                    count: 100,
                    spreads: vec![
                        Spread { name: "c".into(), rel: 0.1 },
                        Spread { name: "mB".into(), rel: 0.2 }
                    ],
                    seed: 9
                },
                method: Method::Eigen,
                output: Output::Json,
            })
        );
        for (words, msg) in [
            (&["benchmark", "--vary", "c=0:x:10"][..], "invalid number `x` in --vary `c=0:x:10`"),
            (&["b", "--vary", "c=0:1:10", "--method", "qr"], "invalid value 'qr' for '--method"),
            (&["b", "--vary", "c=0:1"], "invalid --vary `c=0:1`: expected NAME=FROM:TO:COUNT"),
            (
                &["b", "--vary", "c=0:1:3", "--json", "--csv"],
                "'--json' cannot be used with '--csv'",
            ),
            (&["b", "--vary", "c=0:1:3", "--random", "5"], "cannot be used with '--random <N>'"),
            (&["b", "--random", "5"], "--spread <NAME=REL>"),
            (&["b", "--random", "0", "--spread", "c=0.1"], "expected a count of at least 1"),
            (
                &["b", "--random", "5", "--spread", "c=1.5"],
                "invalid spread `1.5` in --spread `c=1.5`: must lie in [0, 1)",
            ),
            (&["b", "--random", "5", "--spread", "c"], "invalid --spread `c`: expected NAME=REL"),
            (&["b", "--random", "5", "--spread", "c=.1", "--seed", "-1"], "'--seed <S>'"),
            (&["b", "--spread", "c=0.1"], "--random <N>"),
            (&["b"], "<--vary <NAME=FROM:TO:COUNT>|--random <N>|--gain <NAME=FROM:TO:COUNT>>"),
            (&["b", "--gain", "k_yaw=0:1:2"], "unknown gain `k_yaw`: expected one of k_roll_roll"),
            (&["b", "--gain", "k_roll_roll=0:1:2", "--vary", "c=0:1:2"], "cannot be used with"),
        ] {
            let e = sweep_of(words).unwrap_err();
            assert!(e.contains(msg), "{words:?}: {e}");
        }
        let e = parse::<BenchArgs>(&["bench", "--fast"]).unwrap_err();
        assert!(e.contains("unexpected argument '--fast'"), "{e}");
        // A gain sweep: the closed-loop windows of the balance-assist gain on the benchmark,
        // each the window of `window --gain` (the same library call) and the lower edge
        // falling as the assist grows.
        let a = parse::<SweepArgs>(&[
            "sweep",
            "--model",
            "benchmark",
            "--gain",
            "k_steer_roll_rate=0:-20:5",
            "--json",
        ])
        .expect("parses");
        let v: Value = serde_json::from_str(&sweep(&a).expect("runs")).expect("json");
        assert_eq!((v["count"].as_u64(), v["designs"].as_str()), (Some(5), Some("gain-grid")));
        let lows: Vec<f64> = v["points"]
            .as_array()
            .expect("points")
            .iter()
            .map(|p| p["stable"][0][0].as_f64().expect("stable"))
            .collect();
        assert!(lows.windows(2).all(|w| w[1] < w[0]), "{lows:?}");
        assert!((lows[0] - 4.292382536341).abs() < 1e-9, "{lows:?}");
        let a = parse::<SweepArgs>(&[
            "sweep",
            "--model",
            "benchmark",
            "--gain",
            "k_steer_roll_rate=0:-20:5",
            "--csv",
            "--method",
            "eigen",
            "--vmax",
            "10",
        ])
        .expect("parses");
        let mut written = Vec::new();
        let last = crate::gain_sweep::run_to(&a, &mut written).expect("runs");
        let csv = format!("{}{last}", String::from_utf8_lossy(&written));
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(
            lines[0],
            "design,k_steer_roll_rate,status,stable,stable_from,stable_to,intervals"
        );
        assert_eq!(lines.len(), 6);
        let first: Vec<&str> = lines[1].split(',').collect();
        let lo: f64 = first[4].parse().expect("a number");
        assert!((lo - 4.292382536341).abs() < 1e-9, "{csv}");
        let a = parse::<SweepArgs>(&[
            "sweep",
            "--model",
            "benchmark",
            "--gain",
            "k_roll_roll=0:1:2",
            "--method",
            "eigen",
        ])
        .expect("parses");
        assert_eq!(sweep(&a).unwrap_err(), "--method eigen needs --vmax (a finite speed grid)");
        let a = parse::<SweepArgs>(&[
            "sweep",
            "--model",
            "benchmark",
            "--vary",
            "c=0:1:2",
            "--vmax",
            "3",
        ])
        .expect("parses");
        assert_eq!(
            sweep(&a).unwrap_err(),
            "--vmin and --vmax bound the closed-loop windows of --gain"
        );
        assert!(e.contains("unexpected argument '--fast'"), "{e}");
    }
}
