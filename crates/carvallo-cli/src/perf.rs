//! The measurement subcommands of the `carvallo` command line.
//!
//! * `carvallo bench [--json] [--quick]`: the tables of `carvallo::bench` (time per
//!   evaluation beside the error against a 256-bit reference, measured in the same run, and
//!   the issue's targets), as text or as one JSON object `{mode, rows, distributions,
//!   targets}`. `--quick` runs tiny samples (seconds); the default is the full measurement
//!   ($10^6$ samples and sweep designs, 5 to 15 minutes on a busy 2-core machine).
//! * `carvallo sweep --model benchmark|FILE.toml --vary NAME=FROM:TO:COUNT
//!   [--method hurwitz|eigen] [--json]`: the stability window of COUNT designs varying one
//!   parameter linearly, in parallel, with a progress bar when standard error is a terminal;
//!   prints a summary (JSON keys `model`, `parameter`, `from`, `to`, `count`, `method`,
//!   `threads`, `elapsed`, `designs_per_second`, `stable`, `with_weave`, `with_capsize`,
//!   `weave_speed_range`, `capsize_speed_range`, `failed`).
//!
//! Bad arguments are usage errors naming the value, exit code 2.

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Duration;

use carvallo::sweep::{self, Method};
use serde_json::{json, Value};

const HELP: &str = "\
Usage:
    carvallo bench [--json] [--quick]
    carvallo sweep --model benchmark|FILE.toml --vary NAME=FROM:TO:COUNT [--method hurwitz|eigen] [--json]
";

#[derive(Debug, PartialEq)]
enum Command {
    Bench {
        json: bool,
        quick: bool,
    },
    Sweep {
        model: String,
        name: String,
        from: f64,
        to: f64,
        count: usize,
        method: Method,
        json: bool,
    },
}

/// Reads `NAME=FROM:TO:COUNT`.
fn parse_vary(text: &str) -> Result<(String, f64, f64, usize), String> {
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
    let count: usize =
        count.parse().map_err(|_| format!("invalid count `{count}` in --vary `{text}`"))?;
    if count == 0 {
        return Err(format!("invalid count `0` in --vary `{text}`: must be at least 1"));
    }
    Ok((name.to_string(), num(from)?, num(to)?, count))
}

fn parse(args: &[String]) -> Result<Command, String> {
    let (first, rest) = args.split_first().ok_or("missing command")?;
    let (mut json, mut quick, mut model, mut vary, mut method) = (false, false, None, None, None);
    let mut it = rest.iter();
    while let Some(arg) = it.next() {
        let mut value =
            |what: &str| it.next().cloned().ok_or_else(|| format!("missing value after `{what}`"));
        match (first.as_str(), arg.as_str()) {
            (_, "--json") if json => return Err("argument `--json` given more than once".into()),
            (_, "--json") => json = true,
            ("bench", "--quick") if quick => {
                return Err("argument `--quick` given more than once".into())
            }
            ("bench", "--quick") => quick = true,
            ("sweep", "--model") if model.is_none() => model = Some(value("--model")?),
            ("sweep", "--vary") if vary.is_none() => vary = Some(parse_vary(&value("--vary")?)?),
            ("sweep", "--method") if method.is_none() => {
                method = Some(match value("--method")?.as_str() {
                    "hurwitz" => Method::Hurwitz,
                    "eigen" => Method::Eigen,
                    other => {
                        return Err(format!("invalid method `{other}`: expected hurwitz or eigen"))
                    }
                })
            }
            ("sweep", "--model" | "--vary" | "--method") => {
                return Err(format!("argument `{arg}` given more than once"))
            }
            _ => return Err(format!("unknown argument `{arg}`")),
        }
    }
    if first == "bench" {
        return Ok(Command::Bench { json, quick });
    }
    let model = model.ok_or("missing `--model benchmark|FILE.toml`")?;
    let (name, from, to, count) = vary.ok_or("missing `--vary NAME=FROM:TO:COUNT`")?;
    Ok(Command::Sweep {
        model,
        name,
        from,
        to,
        count,
        method: method.unwrap_or(Method::Hurwitz),
        json,
    })
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
            let cfg = if quick {
                carvallo::bench::Config::quick()
            } else {
                carvallo::bench::Config::full()
            };
            let mut report = carvallo::bench::run(&cfg);
            crate::bench::extend(&cfg, &mut report);
            if json {
                serde_json::to_string_pretty(&report).map_err(|e| e.to_string())
            } else {
                Ok(carvallo::bench::render_text(&report))
            }
        }
        Command::Sweep { model, name, from, to, count, method, json } => {
            let base = crate::whipple::load(&model)?;
            let counter = AtomicUsize::new(0);
            let done = AtomicBool::new(false);
            let summary = std::thread::scope(|s| {
                if std::io::stderr().is_terminal() {
                    s.spawn(|| progress_bar(&counter, count, &done));
                }
                let r = sweep::sweep(&base, &name, from, to, count, method, &counter);
                done.store(true, Ordering::Relaxed);
                r
            })
            .map_err(|e| e.to_string())?;
            let method = if method == Method::Hurwitz { "hurwitz" } else { "eigen" };
            let v = json!({
                "model": model,
                "parameter": name,
                "from": from,
                "to": to,
                "count": summary.count,
                "method": method,
                "threads": rayon_threads(),
                "elapsed": summary.elapsed,
                "designs_per_second": summary.designs_per_second,
                "stable": summary.stable,
                "with_weave": summary.with_weave,
                "with_capsize": summary.with_capsize,
                "weave_speed_range": range(summary.weave_range),
                "capsize_speed_range": range(summary.capsize_range),
                "failed": summary.failed,
            });
            if json {
                serde_json::to_string_pretty(&v).map_err(|e| e.to_string())
            } else {
                Ok(format!(
                    "{count} designs, {name} from {from} to {to}, method {method}: {:.3} s \
                     ({:.0} designs/s), {} with a stable speed range, weave speeds {}, capsize \
                     speeds {}",
                    summary.elapsed,
                    summary.designs_per_second,
                    summary.stable,
                    range(summary.weave_range),
                    range(summary.capsize_range)
                ))
            }
        }
    }
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
        assert_eq!(
            parse(&args(&["sweep", "--model", "benchmark", "--vary", "c=0:0.2:10"])),
            Ok(Command::Sweep {
                model: "benchmark".into(),
                name: "c".into(),
                from: 0.0,
                to: 0.2,
                count: 10,
                method: Method::Hurwitz,
                json: false
            })
        );
        assert_eq!(
            parse(&args(&["sweep", "--model", "benchmark", "--vary", "c=0:x:10"])),
            Err("invalid number `x` in --vary `c=0:x:10`".into())
        );
        assert_eq!(
            parse(&args(&["sweep", "--model", "b", "--vary", "c=0:1:10", "--method", "qr"])),
            Err("invalid method `qr`: expected hurwitz or eigen".into())
        );
        assert_eq!(
            parse(&args(&["sweep", "--model", "b", "--vary", "c=0:1"])),
            Err("invalid --vary `c=0:1`: expected NAME=FROM:TO:COUNT".into())
        );
        assert_eq!(parse(&args(&["bench", "--fast"])), Err("unknown argument `--fast`".into()));
    }
}
