//! `carvallo sweep --model M --gain NAME=FROM:TO:COUNT ... [--vmin V] [--vmax V]
//! [--method hurwitz|eigen] [--json | --csv]`: the closed-loop stable speed range of the state
//! feedback $u = -Kx$ over a grid of gains (every combination of the `--gain` axes, the first
//! varying slowest; the gains not named are zero), on one bicycle, in parallel (rayon).
//!
//! `--method hurwitz` (default) is [`Whipple::closed_loop_window`] on the generated closed-loop
//! polynomial, over `--vmin` (default 0) to `--vmax` (default: every speed); `--method eigen`
//! is the eigenvalue reference [`Whipple::closed_loop_eigen_window`] on 200 grid steps and needs
//! `--vmax`.
//!
//! The output keeps the shape of the design sweep ([`crate::perf`]): a one-line text summary;
//! JSON with `model`, `gains` (the varied names), `designs` (`gain-grid`), `count`, `method`,
//! `threads`, `elapsed`, `designs_per_second`, `stable`, `lowest_stable_speed_range`,
//! `failed`, `speed_from`, `speed_to` (`null`: every speed), `vary` (and for one axis
//! `parameter`, `from`, `to`), and `points`: `[{"gains": {NAME: VALUE, ...}, "stable":
//! [[from, to], ...]}, ...]`; or with `--csv` one row per gain set: `design`, the varied gains,
//! `status` (`ok`, or `failed` when the eigenvalues did not converge), `stable`, `stable_from`
//! and `stable_to` (the lowest stable interval, empty without one; `stable_to` empty for every
//! speed above) and `intervals` (their number), written as the blocks of gain sets finish.
//! Ctrl-C ends the sweep with the summary of the gain sets done and the line
//! `interrupted after K of N gain sets`.

use std::io::Write;
use std::sync::atomic::Ordering;
use std::time::Instant;

use carvallo::whipple::feedback::{ClosedLoopWindow, Gains};
use carvallo::whipple::Whipple;
use rayon::prelude::*;
use serde_json::{json, Value};

use crate::gains::GainAxis;
use crate::sweep_args::{MethodArg, SweepArgs};

/// The grid points of the eigenvalue method.
const EIGEN_POINTS: usize = 200;

/// The gain sets computed at a time (in parallel), then written and summarised: memory does
/// not grow with the count.
const BLOCK: usize = 1 << 14;

/// The largest count whose JSON lists every gain set (`points`); above it only the summary.
pub const MAX_JSON_POINTS: usize = 100_000;

/// Runs `carvallo sweep --gain ...` (see the [module docs](self)), the CSV rows written to
/// standard output as they come.
pub fn run(args: &SweepArgs) -> Result<String, String> {
    run_to(args, std::io::BufWriter::new(std::io::stdout().lock()))
}

/// [`run`] with the CSV rows (all but the last, which is returned) written to `out`.
pub fn run_to<W: Write>(args: &SweepArgs, out: W) -> Result<String, String> {
    let axes = &args.gain;
    let count = axes
        .iter()
        .try_fold(1usize, |n, a| n.checked_mul(a.count))
        .ok_or_else(|| "too many gain sets: the product of the counts overflows".to_string())?;
    let (from, to) = (args.vmin.unwrap_or(0.0), args.vmax.unwrap_or(f64::INFINITY));
    if to < from {
        return Err(format!("invalid speed range {from} to {to}: expected --vmin <= --vmax"));
    }
    if args.method == MethodArg::Eigen && !to.is_finite() {
        return Err("--method eigen needs --vmax (a finite speed grid)".into());
    }
    let bike = Whipple::new(crate::args::bicycle(&args.model, &args.data)?);
    let gains_at = |i: usize| -> (Vec<f64>, Gains) {
        let mut rest = i;
        let mut values = vec![0.0; axes.len()];
        for (j, a) in axes.iter().enumerate().rev() {
            values[j] = a.value(rest % a.count);
            rest /= a.count;
        }
        let mut g = Gains::ZERO;
        for (a, x) in axes.iter().zip(&values) {
            let _ = g.set(&a.name, *x);
        }
        (values, g)
    };
    let stop = crate::interrupt::interrupt_flag();
    let start = Instant::now();
    let (mut done, mut stable, mut failed) = (0usize, 0usize, 0usize);
    let mut range: Option<(f64, f64)> = None;
    let mut points: Vec<Value> = Vec::new();
    let keep_points = args.json && count <= MAX_JSON_POINTS;
    let names: Vec<&str> = axes.iter().map(|a| a.name.as_str()).collect();
    let mut csv = args.csv.then(|| {
        CsvLines::new(
            out,
            format!("design,{},status,stable,stable_from,stable_to,intervals", names.join(",")),
        )
    });
    while done < count && !stop.load(Ordering::Relaxed) {
        let block = BLOCK.min(count - done);
        let results: Vec<(Vec<f64>, Gains, Option<ClosedLoopWindow>)> = (done..done + block)
            .into_par_iter()
            .map(|i| {
                let (values, g) = gains_at(i);
                let w = match args.method {
                    MethodArg::Hurwitz => bike.closed_loop_window(&g, from, to).ok(),
                    MethodArg::Eigen => {
                        bike.closed_loop_eigen_window(&g, from, to, EIGEN_POINTS).ok()
                    }
                };
                (values, g, w)
            })
            .collect();
        for (j, (values, g, w)) in results.iter().enumerate() {
            match w {
                Some(w) if !w.stable.is_empty() => {
                    stable += 1;
                    let lo = w.stable[0].0;
                    range = Some(range.map_or((lo, lo), |(a, b)| (a.min(lo), b.max(lo))));
                }
                Some(_) => {}
                None => failed += 1,
            }
            if keep_points {
                points.push(json!({
                    "gains": crate::gains::gains_json(g),
                    "stable": w.as_ref().map_or(Value::Null, crate::gains::stable_json),
                }));
            }
            if let Some(csv) = &mut csv {
                let values: Vec<String> = values.iter().map(|x| format!("{x:?}")).collect();
                let status = match w {
                    Some(w) => {
                        let (lo, hi) =
                            w.stable.first().map_or((String::new(), String::new()), |s| {
                                let hi = if s.1.is_finite() {
                                    format!("{:?}", s.1)
                                } else {
                                    String::new()
                                };
                                (format!("{:?}", s.0), hi)
                            });
                        format!("ok,{},{lo},{hi},{}", !w.stable.is_empty(), w.stable.len())
                    }
                    None => "failed,,,,".to_string(),
                };
                if !csv.write(format!("{},{},{status}", done + j, values.join(","))) {
                    stop.store(true, Ordering::Relaxed);
                }
            }
        }
        done += block;
    }
    let elapsed = start.elapsed().as_secs_f64();
    let method = if args.method == MethodArg::Hurwitz { "hurwitz" } else { "eigen" };
    let rate = done as f64 / elapsed.max(1e-9);
    let speed = |x: f64| if x.is_finite() { json!(x) } else { Value::Null };
    let interrupted =
        (done < count).then(|| format!("interrupted after {done} of {count} gain sets"));
    if let Some(csv) = csv {
        let last = csv.finish().map_err(|e| format!("cannot write the output: {e}"))?;
        if let Some(line) = &interrupted {
            eprintln!("{line}");
        }
        return Ok(last);
    }
    if args.json {
        let mut v = json!({
            "model": args.model,
            "gains": axes.iter().map(|a| a.name.clone()).collect::<Vec<_>>(),
            "designs": "gain-grid",
            "count": done,
            "method": method,
            "threads": rayon::current_num_threads(),
            "elapsed": elapsed,
            "designs_per_second": rate,
            "stable": stable,
            "lowest_stable_speed_range": range.map_or(Value::Null, |(a, b)| json!([a, b])),
            "failed": failed,
            "speed_from": from,
            "speed_to": speed(to),
            "vary": axes.iter().map(|a| json!({"gain": a.name, "from": a.from, "to": a.to, "count": a.count})).collect::<Vec<_>>(),
        });
        if keep_points {
            v["points"] = json!(points);
        }
        if let Some(line) = &interrupted {
            eprintln!("{line}");
            v["interrupted"] = json!(line);
        }
        if let [a] = &axes[..] {
            v["parameter"] = json!(a.name);
            v["from"] = json!(a.from);
            v["to"] = json!(a.to);
        }
        return serde_json::to_string_pretty(&v).map_err(|e| e.to_string());
    }
    let what: Vec<String> = axes
        .iter()
        .map(|a: &GainAxis| format!("{} from {} to {} ({})", a.name, a.from, a.to, a.count))
        .collect();
    let upper = if to.is_finite() { format!("{to} m/s") } else { "any speed".into() };
    let text = format!(
        "{done} gain sets, {}, speeds {from} m/s to {upper}, method {method}: {elapsed:.3} s \
         ({rate:.0} gain sets/s), {stable} with a stable speed range, lowest stable speeds {}",
        what.join(" x "),
        range.map_or("null".to_string(), |(a, b)| format!("[{a},{b}]")),
    );
    Ok(match interrupted {
        Some(line) => format!("{text}\n{line}"),
        None => text,
    })
}

/// CSV lines written to `out` as they come, the last held back for the caller to print with
/// its final newline like any output (as the design sweep's CSV does). A write that fails is
/// reported by [`CsvLines::finish`], except a closed pipe (`| head`), which ends quietly.
struct CsvLines<W: Write> {
    out: W,
    pending: String,
    error: Option<std::io::Error>,
}

impl<W: Write> CsvLines<W> {
    fn new(out: W, header: String) -> Self {
        CsvLines { out, pending: header, error: None }
    }

    /// Queues `line`; `false` once a write has failed.
    fn write(&mut self, line: String) -> bool {
        let previous = std::mem::replace(&mut self.pending, line);
        if self.error.is_none() {
            if let Err(e) = writeln!(self.out, "{previous}") {
                self.error = Some(e);
            }
        }
        self.error.is_none()
    }

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
