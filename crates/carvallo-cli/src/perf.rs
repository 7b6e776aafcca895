//! The measurement subcommands of the `carvallo` command line.
//!
//! * `carvallo bench [--json] [--quick]`: the tables of [`crate::bench`] (time per
//!   evaluation beside the error against a 256-bit reference, measured in the same run, and
//!   the issue's targets), as text or as one JSON object `{mode, rows, distributions,
//!   targets}`. `--quick` runs tiny samples (seconds); the default is the full measurement
//!   ($10^6$ samples and sweep designs, 5 to 15 minutes on a busy 2-core machine).
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
//!   The designs stream in blocks ([`sweep::sweep_stream`]): memory does not depend on their
//!   number, CSV rows are written as the blocks finish, and Ctrl-C ends the sweep with the
//!   summary of the designs done and the line `interrupted after K of N designs` (exit 0).
//!
//! Bad arguments are usage errors naming the value, exit code 2 (a count that does not fit a
//! `usize` too).

use std::io::{IsTerminal, Write};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Duration;

use carvallo::sweep::{self, Designs, Method, Spread, SweepOutput, Vary};
use serde_json::{json, Value};

const HELP: &str = "\
Usage:
    carvallo bench [--json] [--quick]
    carvallo sweep --model benchmark|FILE.toml --vary NAME=FROM:TO:COUNT [--vary ...]
                   [--rider FILE.txt] [--strict] [--method hurwitz|eigen] [--json | --csv]
    carvallo sweep --model benchmark|FILE.toml --random N --spread NAME=REL [--spread ...]
                   [--seed S] [--rider FILE.txt] [--strict] [--method hurwitz|eigen]
                   [--json | --csv]
";

/// How `sweep` prints its result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Output {
    Text,
    Json,
    Csv,
}

#[derive(Debug, PartialEq)]
enum Command {
    Bench {
        json: bool,
        quick: bool,
    },
    Sweep {
        model: String,
        data: crate::args::DataOptions,
        designs: Designs,
        method: Method,
        output: Output,
    },
}

/// Reads `NAME=FROM:TO:COUNT`.
fn parse_vary(text: &str) -> Result<Vary, String> {
    let bad = || format!("invalid --vary `{text}`: expected NAME=FROM:TO:COUNT");
    let (name, range) = text.split_once('=').ok_or_else(bad)?;
    let parts: Vec<&str> = range.split(':').collect();
    let [from, to, count] = parts[..] else { return Err(bad()) };
    let num = |s: &str| -> Result<f64, String> {
        let x: f64 = s.parse().map_err(|_| format!("invalid number `{s}` in --vary `{text}`"))?;
        if x.is_finite() {
            Ok(x)
        } else {
            Err(format!("invalid number `{s}` in --vary `{text}`: must be finite"))
        }
    };
    let count: usize = count.parse().map_err(|e: std::num::ParseIntError| {
        if *e.kind() == std::num::IntErrorKind::PosOverflow {
            format!("invalid count `{count}` in --vary `{text}`: more than {} designs", usize::MAX)
        } else {
            format!("invalid count `{count}` in --vary `{text}`")
        }
    })?;
    if count == 0 {
        return Err(format!("invalid count `0` in --vary `{text}`: must be at least 1"));
    }
    Ok(Vary { name: name.to_string(), from: num(from)?, to: num(to)?, count })
}

/// Reads `NAME=REL` of `--spread`.
fn parse_spread(text: &str) -> Result<Spread, String> {
    let (name, rel) = text
        .split_once('=')
        .ok_or_else(|| format!("invalid --spread `{text}`: expected NAME=REL"))?;
    let rel: f64 =
        rel.parse().map_err(|_| format!("invalid spread `{rel}` in --spread `{text}`"))?;
    if !(0.0..1.0).contains(&rel) {
        return Err(format!("invalid spread `{rel}` in --spread `{text}`: must lie in [0, 1)"));
    }
    Ok(Spread { name: name.to_string(), rel })
}

fn parse(args: &[String]) -> Result<Command, String> {
    let (first, rest) = args.split_first().ok_or("missing command")?;
    let (mut output, mut quick, mut model, mut method) = (Output::Text, false, None, None);
    let (mut vary, mut spreads, mut random, mut seed) = (Vec::new(), Vec::new(), None, None);
    let mut data = crate::args::DataOptions::default();
    let mut it = rest.iter();
    while let Some(arg) = it.next() {
        if first == "sweep" && data.take(arg, &mut it)? {
            continue;
        }
        let mut value =
            |what: &str| it.next().cloned().ok_or_else(|| format!("missing value after `{what}`"));
        match (first.as_str(), arg.as_str()) {
            (_, "--json" | "--csv") if output != Output::Text => {
                let given = if output == Output::Json { "--json" } else { "--csv" };
                if given == arg {
                    return Err(format!("argument `{arg}` given more than once"));
                }
                return Err(format!("`{arg}` cannot be combined with `{given}`"));
            }
            (_, "--json") => output = Output::Json,
            ("sweep", "--csv") => output = Output::Csv,
            ("bench", "--quick") if quick => {
                return Err("argument `--quick` given more than once".into())
            }
            ("bench", "--quick") => quick = true,
            ("sweep", "--model") if model.is_none() => model = Some(value("--model")?),
            ("sweep", "--vary") => vary.push(parse_vary(&value("--vary")?)?),
            ("sweep", "--spread") => spreads.push(parse_spread(&value("--spread")?)?),
            ("sweep", "--random") if random.is_none() => {
                let v = value("--random")?;
                match v.parse::<usize>() {
                    Ok(n) if n >= 1 => random = Some(n),
                    Err(e) if *e.kind() == std::num::IntErrorKind::PosOverflow => {
                        return Err(format!(
                            "invalid count `{v}` of --random: more than {} designs",
                            usize::MAX
                        ))
                    }
                    _ => {
                        return Err(format!("invalid count `{v}` of --random: expected at least 1"))
                    }
                }
            }
            ("sweep", "--seed") if seed.is_none() => {
                let v = value("--seed")?;
                seed = Some(v.parse::<u64>().map_err(|_| format!("invalid seed `{v}`"))?);
            }
            ("sweep", "--method") if method.is_none() => {
                method = Some(match value("--method")?.as_str() {
                    "hurwitz" => Method::Hurwitz,
                    "eigen" => Method::Eigen,
                    other => {
                        return Err(format!("invalid method `{other}`: expected hurwitz or eigen"))
                    }
                })
            }
            ("sweep", "--model" | "--method" | "--random" | "--seed") => {
                return Err(format!("argument `{arg}` given more than once"))
            }
            _ => return Err(format!("unknown argument `{arg}`")),
        }
    }
    if first == "bench" {
        return Ok(Command::Bench { json: output == Output::Json, quick });
    }
    let model = model.ok_or("missing `--model benchmark|FILE.toml`")?;
    let designs = match (random, vary.is_empty()) {
        (Some(_), false) => return Err("`--vary` cannot be combined with `--random`".into()),
        (Some(count), true) => {
            if spreads.is_empty() {
                return Err("missing `--spread NAME=REL` for `--random`".into());
            }
            Designs::Random { count, spreads, seed: seed.unwrap_or(1) }
        }
        (None, _) if !spreads.is_empty() => return Err("`--spread` needs `--random N`".into()),
        (None, _) if seed.is_some() => return Err("`--seed` needs `--random N`".into()),
        (None, true) => return Err("missing `--vary NAME=FROM:TO:COUNT` or `--random N`".into()),
        (None, false) => Designs::Grid(vary),
    };
    Ok(Command::Sweep { model, data, designs, method: method.unwrap_or(Method::Hurwitz), output })
}

/// Draws a progress bar on standard error until `done` is set.
fn progress_bar(counter: &AtomicUsize, total: usize, done: &AtomicBool) {
    let width = 40;
    while !done.load(Ordering::Relaxed) {
        let n = counter.load(Ordering::Relaxed).min(total);
        let filled = n * width / total.max(1);
        eprint!("\r[{}{}] {n}/{total}", "#".repeat(filled), " ".repeat(width - filled));
        std::thread::sleep(Duration::from_millis(100));
    }
    eprint!("\r{}\r", " ".repeat(width + 30));
}

fn range(r: Option<(f64, f64)>) -> Value {
    r.map_or(Value::Null, |(a, b)| json!([a, b]))
}

fn run(cmd: Command) -> Result<String, String> {
    match cmd {
        Command::Bench { json, quick } => {
            let cfg =
                if quick { crate::bench::Config::quick() } else { crate::bench::Config::full() };
            let mut report = crate::bench::run(&cfg);
            crate::bench::extend(&cfg, &mut report);
            if json {
                serde_json::to_string_pretty(&report).map_err(|e| e.to_string())
            } else {
                Ok(crate::bench::render_text(&report))
            }
        }
        Command::Sweep { model, data, designs, method, output } => {
            let base = crate::args::bicycle(&model, &data)?;
            let count = match &designs {
                Designs::Grid(axes) => axes
                    .iter()
                    .try_fold(1usize, |n, a| n.checked_mul(a.count))
                    .ok_or_else(|| {
                        let counts = axes.iter().map(|a| a.count).collect();
                        sweep::DesignsError::TooManyDesigns { counts }.to_string()
                    })?,
                Designs::Random { count, .. } => *count,
            };
            let counter = AtomicUsize::new(0);
            let done = AtomicBool::new(false);
            let stop = interrupt_flag();
            let names: Vec<&str> = match &designs {
                Designs::Grid(axes) => axes.iter().map(|a| a.name.as_str()).collect(),
                Designs::Random { spreads, .. } => {
                    spreads.iter().map(|s| s.name.as_str()).collect()
                }
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
            let interrupted = (out.summary.count < out.requested).then(|| {
                format!("interrupted after {} of {} designs", out.summary.count, out.requested)
            });
            match output {
                Output::Csv => {
                    let last =
                        rows.finish().map_err(|e| format!("cannot write the output: {e}"))?;
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
    }
}

/// The flag that Ctrl-C sets (the handler is installed on the first call). Without a handler
/// (the platform refused it) Ctrl-C ends the process as usual.
fn interrupt_flag() -> &'static AtomicBool {
    static STOP: AtomicBool = AtomicBool::new(false);
    static HANDLER: std::sync::Once = std::sync::Once::new();
    HANDLER.call_once(|| {
        // An error only means Ctrl-C keeps its default effect.
        let _ = ctrlc::set_handler(|| STOP.store(true, Ordering::Relaxed));
    });
    &STOP
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

/// The subcommands `bench` or `sweep`.
pub const SUBCOMMAND: crate::Subcommand = crate::Subcommand {
    names: &["bench", "sweep"],
    run: |args| parse(args).and_then(run),
    help: HELP,
};

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::words as args;

    #[test]
    fn parses_and_rejects_by_value() {
        assert_eq!(
            parse(&args(&["bench", "--quick", "--json"])),
            Ok(Command::Bench { json: true, quick: true })
        );
        let vary = |name: &str, from: f64, to: f64, count: usize| Vary {
            name: name.into(),
            from,
            to,
            count,
        };
        assert_eq!(
            parse(&args(&["sweep", "--model", "benchmark", "--vary", "c=0:0.2:10"])),
            Ok(Command::Sweep {
                data: crate::args::DataOptions::default(),
                model: "benchmark".into(),
                designs: Designs::Grid(vec![vary("c", 0.0, 0.2, 10)]),
                method: Method::Hurwitz,
                output: Output::Text,
            })
        );
        assert_eq!(
            parse(&args(&[
                "sweep",
                "--model",
                "b",
                "--vary",
                "c=0:0.2:10",
                "--csv",
                "--vary",
                "w=1:1.2:3"
            ])),
            Ok(Command::Sweep {
                data: crate::args::DataOptions::default(),
                model: "b".into(),
                designs: Designs::Grid(vec![vary("c", 0.0, 0.2, 10), vary("w", 1.0, 1.2, 3)]),
                method: Method::Hurwitz,
                output: Output::Csv,
            })
        );
        assert_eq!(
            parse(&args(&[
                "sweep", "--model", "b", "--random", "100", "--spread", "c=0.1", "--spread",
                "mB=0.2", "--seed", "9", "--json"
            ])),
            Ok(Command::Sweep {
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
                method: Method::Hurwitz,
                output: Output::Json,
            })
        );
        let err = |list: &[&str]| parse(&args(list)).unwrap_err();
        assert_eq!(
            err(&["sweep", "--model", "benchmark", "--vary", "c=0:x:10"]),
            "invalid number `x` in --vary `c=0:x:10`"
        );
        assert_eq!(
            err(&["sweep", "--model", "b", "--vary", "c=0:1:10", "--method", "qr"]),
            "invalid method `qr`: expected hurwitz or eigen"
        );
        assert_eq!(
            err(&["sweep", "--model", "b", "--vary", "c=0:1"]),
            "invalid --vary `c=0:1`: expected NAME=FROM:TO:COUNT"
        );
        assert_eq!(err(&["bench", "--fast"]), "unknown argument `--fast`");
        assert_eq!(
            err(&["sweep", "--model", "b", "--vary", "c=0:1:3", "--json", "--csv"]),
            "`--csv` cannot be combined with `--json`"
        );
        assert_eq!(
            err(&["sweep", "--model", "b", "--vary", "c=0:1:3", "--random", "5"]),
            "`--vary` cannot be combined with `--random`"
        );
        assert_eq!(
            err(&["sweep", "--model", "b", "--random", "5"]),
            "missing `--spread NAME=REL` for `--random`"
        );
        assert_eq!(
            err(&["sweep", "--model", "b", "--random", "0", "--spread", "c=0.1"]),
            "invalid count `0` of --random: expected at least 1"
        );
        assert_eq!(
            err(&["sweep", "--model", "b", "--random", "5", "--spread", "c=1.5"]),
            "invalid spread `1.5` in --spread `c=1.5`: must lie in [0, 1)"
        );
        assert_eq!(
            err(&["sweep", "--model", "b", "--random", "5", "--spread", "c"]),
            "invalid --spread `c`: expected NAME=REL"
        );
        assert_eq!(
            err(&["sweep", "--model", "b", "--random", "5", "--spread", "c=.1", "--seed", "-1"]),
            "invalid seed `-1`"
        );
        assert_eq!(
            err(&["sweep", "--model", "b", "--spread", "c=0.1"]),
            "`--spread` needs `--random N`"
        );
        assert_eq!(
            err(&["sweep", "--model", "b"]),
            "missing `--vary NAME=FROM:TO:COUNT` or `--random N`"
        );
    }
}
