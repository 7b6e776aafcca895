//! `carvallo simulate --model benchmark|FILE.toml --speed V --lean0 RAD --duration S
//! [--step DT] [--every N] [--method rk4|dopri5|dop853|vern9 [--rtol R] [--atol A]]
//! [--stop-when NAME=VALUE|NAME=±VALUE ...] [--json]`: integrates the nonlinear
//! Carvallo–Whipple equations from upright straight running at speed V with the initial lean
//! RAD (RK4 at the step DT = 0.001 s by default, the pitch re-solved at every stage) and prints
//! the time series every N steps (10 by default): time, lean, steer, pitch, rear contact speed,
//! both ground tracks, energy, and the energy drift and largest contact residual of the run.
//!
//! With an adaptive `--method` (Dormand–Prince 5(4), DOP853 or Verner's 9(8) pair, tolerances
//! `--rtol`, default
//! 1e-8, and `--atol`, default 1e-3 × rtol) the step follows the error estimate and the
//! printed times are the same grid, `k N DT`, sampled from the dense output. `--stop-when`
//! ends the run when a quantity (`lean`, `steer`, `yaw`, `pitch`, `lean_rate`, `steer_rate`,
//! `x`, `y`) crosses VALUE, or its magnitude reaches VALUE (`lean=±0.5`); the time is located
//! on the interpolant and the state there is the last row. The text then names the condition
//! met and, for an adaptive method, the steps; `--json` always adds `method`, `rtol`, `atol`,
//! `rhs_evaluations`, `steps`, `rejected_steps` and `events` (`[{"when", "t"}]`).
//!
//! `--batch FILE.csv` (columns `speed`, `lean0`, optionally `steer_rate0`) runs one simulation
//! per row in parallel and keeps only their ends
//! ([`WhippleNonlinear::simulate_many`]): a summary, or with `--csv` one row per simulation
//! (the start, `status`, `fell`, the event, the final state, the counts, the diagnostics, the
//! error of a failed run), each equal bit for bit to the single run; a progress bar is drawn on
//! standard error when it is a terminal. Ctrl-C stops a batch as it stops a sweep: the runs
//! under way end within a step (every integration reads the flag,
//! [`WhippleNonlinear::simulate_many_until`]), none is started after it, and the output is
//! that of the runs that had ended, whole, with the line `interrupted after K of N
//! simulations` (after the summary, or on standard error with `--csv`, whose rows are those K
//! with their `row` numbers), exit code 0.
//!
//! `--torque`, `--torque-csv`, `--gain` and `--gain-table` drive the bicycle (roll and steer
//! torques, state feedback): see [`super::simulate_inputs`].
//!
//! The parameter file is the anchors TOML format or BicycleParameters' text, with `--rider` and
//! `--strict` as on `window` ([`crate::args::bicycle`]). Unknown,
//! repeated or missing arguments, non-finite numbers, a start at or beyond the fall angle and a
//! failed integration are errors naming the value, exit code 2.
//!
//! A fall is a result: the run ends when the lean's magnitude reaches `--fall-angle` (1.2 rad
//! by default, [`carvallo::whipple_nonlinear::DEFAULT_FALL_ANGLE`]), located on the
//! interpolant like a stop condition; the text says `fell at t = T s: ...` and the JSON has
//! `status` (`completed`, `stopped`, `fell`, `steer lock`, `singular` or `interrupted`),
//! `status_line`, `fall_angle`, `fall_t`, `steer_lock`, `steer_lock_t`, `singular_pivot`,
//! `singular_t` and `interrupted`. The steer reaching `--steer-lock` (1.4 rad by default: the
//! handlebar against the frame, short of the equations' singularity at ±π/2, which a slow fall
//! turns the fork into) ends the run the same way, and so does the neighbourhood of the
//! equations' singular configuration, status `singular` (a pivot of the constraint solve at
//! 1 % of its upright value: the front wheel broadside to the line of contacts, which a leaning
//! bicycle meets inside the steer lock; [`carvallo::whipple_nonlinear::SINGULAR_PIVOT`]); a
//! batch counts those runs as `singular`. Ctrl-C ends the run within a step: the samples so
//! far and the line `interrupted at t = T s`, exit code 0 (as an interrupted sweep).

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use carvallo::numerics::integrate::{Grid, Integration, Method};
use carvallo::whipple_nonlinear::{
    NonlinearError, Stop, WhippleNonlinear, DEFAULT_FALL_ANGLE, DEFAULT_STEER_LOCK, SINGULAR_PIVOT,
};
use serde_json::json;

use crate::args::{finite, DataOptions};

/// The integrator and its tolerances, shared by `simulate`, `hoop` and `unicycle`.
#[derive(Clone, Debug, Default, PartialEq, clap::Args)]
pub struct ToleranceArgs {
    /// The integrator: fixed-step RK4, or Dormand–Prince 5(4), DOP853 or Verner's 9(8) with
    /// error control and dense output, or the implicit Radau IIA 5 for stiff variants
    #[arg(long, value_enum, default_value_t)]
    pub method: MethodArg,
    /// The relative tolerance of an adaptive method [default: 1e-8]
    #[arg(long, value_name = "R", value_parser = finite, allow_hyphen_values = true)]
    pub rtol: Option<f64>,
    /// The absolute tolerance of an adaptive method [default: 1e-3 × rtol]
    #[arg(long, value_name = "A", value_parser = finite, allow_hyphen_values = true)]
    pub atol: Option<f64>,
}

/// How `simulate` integrates: the method, its tolerances and the stop conditions.
#[derive(Clone, Debug, Default, PartialEq, clap::Args)]
pub struct IntegrationArgs {
    #[command(flatten)]
    pub tolerance: ToleranceArgs,
    /// Stop when NAME (lean, steer, yaw, pitch, lean_rate, steer_rate, x, y) crosses VALUE,
    /// or when its magnitude reaches VALUE (NAME=±VALUE or NAME=+-VALUE); may be repeated
    #[arg(long = "stop-when", value_name = "NAME=VALUE", value_parser = parse_stop, allow_hyphen_values = true)]
    pub stop_when: Vec<Stop>,
}

/// The integrator of `--method`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum MethodArg {
    /// Classical Runge–Kutta at the fixed step --step
    #[default]
    Rk4,
    /// Dormand–Prince 5(4), error-controlled, dense output of order 4
    Dopri5,
    /// Hairer's DOP853 8(5,3), error-controlled, dense output of order 7
    Dop853,
    /// Verner's efficient 9(8) pair, error-controlled, dense output of order 9
    Vern9,
    /// Radau IIA of order 5, implicit, for stiff variants (Newton on the model's generated
    /// state Jacobian, with the feedback's derivatives when driven)
    Radau5,
}

impl ToleranceArgs {
    /// The integration these options describe, or an error naming the bad value.
    pub fn integration(&self) -> Result<Integration, String> {
        let method = match self.method {
            MethodArg::Rk4 => Method::Rk4,
            MethodArg::Dopri5 => Method::Dopri5,
            MethodArg::Dop853 => Method::Dop853,
            MethodArg::Vern9 => Method::Vern9,
            MethodArg::Radau5 => Method::Radau5,
        };
        if method == Method::Rk4 {
            if let Some(r) = self.rtol {
                return Err(format!("invalid --rtol {r:?}: rk4 has a fixed step (--step); choose an adaptive --method such as dop853"));
            }
            if let Some(a) = self.atol {
                return Err(format!("invalid --atol {a:?}: rk4 has a fixed step (--step); choose an adaptive --method such as dop853"));
            }
            return Ok(Integration::RK4);
        }
        let how = Integration::with_defaults(method, self.rtol, self.atol);
        match how.unusable() {
            Some((name, value, reason)) => Err(format!("invalid --{name} {value:?}: {reason}")),
            None => Ok(how),
        }
    }
}

/// One row of a `--batch` file: the line number and the start.
struct BatchRow {
    line: usize,
    speed: f64,
    lean0: f64,
    steer_rate0: f64,
}

/// Reads a `--batch` file: a header naming `speed`, `lean0` and optionally `steer_rate0` (in
/// any order), then one row of finite numbers per simulation (blank lines skipped).
fn read_batch(file: &std::path::Path) -> Result<Vec<BatchRow>, String> {
    let name = file.display();
    let text = crate::args::read_text(file, "batch file")?;
    let mut lines = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty());
    let (_, header) = lines.next().ok_or_else(|| format!("invalid batch file `{name}`: empty"))?;
    let columns: Vec<&str> = header.split(',').map(str::trim).collect();
    let find = |c: &str| columns.iter().position(|h| *h == c);
    let (Some(speed), Some(lean0)) = (find("speed"), find("lean0")) else {
        return Err(format!(
            "invalid batch file `{name}`: the header `{header}` must name the columns speed and lean0 (and optionally steer_rate0)"
        ));
    };
    if let Some(other) = columns.iter().find(|c| !["speed", "lean0", "steer_rate0"].contains(c)) {
        return Err(format!("invalid batch file `{name}`: unknown column `{other}`"));
    }
    let steer = find("steer_rate0");
    let mut rows = Vec::new();
    for (i, line) in lines {
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        if cells.len() != columns.len() {
            return Err(format!(
                "invalid batch file `{name}` line {}: {} values for {} columns",
                i + 1,
                cells.len(),
                columns.len()
            ));
        }
        let num = |k: usize| -> Result<f64, String> {
            cells[k].parse::<f64>().ok().filter(|x| x.is_finite()).ok_or_else(|| {
                format!(
                    "invalid batch file `{name}` line {}: {} `{}` is not a finite number",
                    i + 1,
                    columns[k],
                    cells[k]
                )
            })
        };
        rows.push(BatchRow {
            line: i + 1,
            speed: num(speed)?,
            lean0: num(lean0)?,
            steer_rate0: steer.map_or(Ok(0.0), num)?,
        });
    }
    Ok(rows)
}

/// `simulate --batch`: every row of the file simulated in parallel, as a summary or CSV rows.
fn batch(
    bike: &WhippleNonlinear,
    file: &std::path::Path,
    grid: &Grid,
    how: &Integration,
    stops: &[Stop],
    csv: bool,
) -> Result<String, String> {
    let rows = read_batch(file)?;
    let mut starts = Vec::with_capacity(rows.len());
    for r in &rows {
        let mut s = bike
            .initial_state(r.speed, r.lean0)
            .map_err(|e| format!("invalid batch file `{}` line {}: {e}", file.display(), r.line))?;
        s.steer_rate = r.steer_rate0;
        starts.push(s);
    }
    // Only the end is kept: no sample inside the run (the integration does not depend on them).
    let grid = Grid { every: grid.n.max(1), ..*grid };
    let stop = crate::interrupt::interrupt_flag();
    let clock = std::time::Instant::now();
    let (counter, finished) = (AtomicUsize::new(0), AtomicBool::new(false));
    let ends = std::thread::scope(|scope| {
        if std::io::stderr().is_terminal() {
            scope.spawn(|| {
                crate::perf::progress_bar_of(&counter, starts.len(), &finished, "simulations")
            });
        }
        let ends = bike.simulate_many_until(&starts, &grid, how, stops, &counter, stop);
        finished.store(true, Ordering::Relaxed);
        ends
    });
    let elapsed = clock.elapsed().as_secs_f64();
    // The runs that ended on their own (completed, fell, stopped or failed), with their rows:
    // after Ctrl-C the runs cut short and those never started are left out.
    type End = Result<carvallo::whipple_nonlinear::Final, NonlinearError>;
    let whole: Vec<(usize, &BatchRow, &End)> = rows
        .iter()
        .zip(&ends)
        .enumerate()
        .filter_map(|(k, (r, e))| match e {
            Some(Ok(f)) if f.interrupted.is_some() => None,
            Some(e) => Some((k, r, e)),
            None => None,
        })
        .collect();
    let interrupted = (whole.len() < rows.len())
        .then(|| format!("interrupted after {} of {} simulations", whole.len(), rows.len()));
    // Fell: the fall angle or the steer lock reached, a stop condition met, or the contact lost.
    let fell = |e: &End| match e {
        Ok(f) => f.fall.is_some() || f.steer_lock.is_some() || f.event.is_some(),
        Err(NonlinearError::NoContact { .. }) => true,
        Err(_) => false,
    };
    // Ended near a singular configuration of the equations (neither fell nor failed).
    let singular = |e: &End| matches!(e, Ok(f) if f.singular.is_some());
    if csv {
        let mut s = String::from("row,speed,lean0,steer_rate0,status,fell,stopped_by,event_t,t_end,lean,steer,yaw,x,y,lean_rate,steer_rate,rhs_evaluations,steps,rejected_steps,energy_drift,max_contact_residual,error\n");
        for &(k, r, e) in &whole {
            let head = format!("{k},{:?},{:?},{:?}", r.speed, r.lean0, r.steer_rate0);
            match e {
                Ok(f) => {
                    let st = f.state;
                    let (by, te) = match (f.event, f.fall, f.steer_lock, f.singular) {
                        (Some((j, t)), ..) => (stops[j].text(), format!("{t:?}")),
                        (None, Some(t), ..) => ("fall angle".to_string(), format!("{t:?}")),
                        (None, None, Some(t), _) => ("steer lock".to_string(), format!("{t:?}")),
                        (None, None, None, Some(t)) => ("singular".to_string(), format!("{t:?}")),
                        (None, None, None, None) => (String::new(), String::new()),
                    };
                    let values =
                        [f.t, st.lean, st.steer, st.yaw, st.x, st.y, st.lean_rate, st.steer_rate]
                            .map(|x| format!("{x:?}"))
                            .join(",");
                    s.push_str(&format!(
                        "{head},ok,{},{by},{te},{values},{},{},{},{:?},{:?},\n",
                        fell(e),
                        f.stats.rhs_evaluations,
                        f.stats.steps,
                        f.stats.rejected_steps,
                        f.diagnostics.energy_drift,
                        f.diagnostics.max_contact_residual
                    ));
                }
                Err(err) => {
                    let msg = err.to_string().replace('"', "'");
                    s.push_str(&format!("{head},failed,{},,,,,,,,,,,,,,,,\"{msg}\"\n", fell(e)));
                }
            }
        }
        // As a sweep's CSV: the rows on standard output, the note on standard error.
        if let Some(line) = &interrupted {
            eprintln!("{line}");
        }
        return Ok(s);
    }
    let failed = whole.iter().filter(|(_, _, e)| e.is_err()).count();
    let fallen = whole.iter().filter(|(_, _, e)| fell(e)).count();
    let singular = whole.iter().filter(|(_, _, e)| singular(e)).count();
    let evaluations: usize =
        whole.iter().filter_map(|(_, _, e)| e.as_ref().ok()).map(|f| f.stats.rhs_evaluations).sum();
    let text = format!(
        "{} simulations of {} s ({}{}) on {} threads in {elapsed:.3} s\n{fallen} fell (the fall angle or the steer lock reached, a stop condition met or the contact lost), {singular} singular, {failed} failed, {evaluations} right-hand side evaluations\n",
        whole.len(),
        grid.end(),
        how.method.name(),
        if how.method.is_adaptive() { format!(" rtol {:e} atol {:e}", how.rtol, how.atol) } else { format!(" step {} s", grid.h) },
        rayon::current_num_threads()
    );
    Ok(match interrupted {
        Some(line) => format!("{text}{line}\n"),
        None => text,
    })
}

/// Reads a `--stop-when` condition.
fn parse_stop(text: &str) -> Result<Stop, String> {
    Stop::parse(text).ok_or_else(|| {
        "expected NAME=VALUE or NAME=±VALUE with NAME one of lean, steer, yaw, pitch, \
         lean_rate, steer_rate, x, y and a finite VALUE (non-negative after ±)"
            .to_string()
    })
}

/// `carvallo simulate`: the nonlinear bicycle integrated from upright straight running.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    /// The bicycle: `benchmark` or a parameter file (the anchors' TOML or BicycleParameters'
    /// `name = value+/-sigma` text)
    #[arg(long, value_name = "MODEL")]
    pub model: String,
    #[command(flatten)]
    pub data: DataOptions,
    /// The initial forward speed (m/s)
    #[arg(long, value_name = "V", value_parser = crate::args::SPEED.parser(), allow_hyphen_values = true, required_unless_present = "batch")]
    pub speed: Option<f64>,
    /// The initial lean (rad)
    #[arg(long, value_name = "RAD", value_parser = crate::args::ANGLE.parser(), allow_hyphen_values = true, required_unless_present = "batch")]
    pub lean0: Option<f64>,
    /// How long to simulate (s)
    #[arg(long, value_name = "S", value_parser = finite, allow_hyphen_values = true)]
    pub duration: f64,
    /// The RK4 step in s (for an adaptive method, the grid of the printed times)
    #[arg(long, value_name = "DT", default_value_t = 0.001, value_parser = finite, allow_hyphen_values = true)]
    pub step: f64,
    /// Print every N-th step (for an adaptive method, the dense output every N × DT seconds)
    #[arg(long, value_name = "N", default_value_t = 10, value_parser = positive)]
    pub every: usize,
    /// The lean at which the bicycle has fallen (rad): the run ends there, status `fell`
    /// (a stated angle: the model gives the frame and rider no extent), in (0, π/2]
    #[arg(long, value_name = "RAD", default_value_t = DEFAULT_FALL_ANGLE, value_parser = fall_angle, allow_hyphen_values = true)]
    pub fall_angle: f64,
    /// The steer at which the handlebar meets the frame (rad): the run ends there, status
    /// `steer lock` (a stated angle short of the equations' singularity at π/2), in (0, π/2)
    #[arg(long, value_name = "RAD", default_value_t = DEFAULT_STEER_LOCK, value_parser = steer_lock, allow_hyphen_values = true)]
    pub steer_lock: f64,
    #[command(flatten)]
    pub integration: IntegrationArgs,
    #[command(flatten)]
    pub inputs: super::simulate_inputs::InputArgs,
    /// Many simulations in parallel: a CSV file with the columns speed, lean0 and optionally
    /// steer_rate0 (one simulation a row, instead of --speed and --lean0)
    #[arg(long, value_name = "FILE.csv", conflicts_with_all = ["speed", "lean0", "json"])]
    pub batch: Option<std::path::PathBuf>,
    /// With --batch: print one CSV row per simulation (final state, event, whether it fell)
    /// instead of the summary
    #[arg(long, requires = "batch")]
    pub csv: bool,
    /// Print JSON (the samples, the energy drift and the largest contact residual) instead of text
    #[arg(long)]
    pub json: bool,
}

/// A fall angle: a finite number in (0, π/2].
fn fall_angle(v: &str) -> Result<f64, String> {
    let x = finite(v)?;
    if x > 0.0 && x <= std::f64::consts::FRAC_PI_2 {
        Ok(x)
    } else {
        Err(format!(
            "must lie in (0, {}] rad (at pi/2 the wheels lie flat)",
            std::f64::consts::FRAC_PI_2
        ))
    }
}

/// A steer lock: a finite number in (0, π/2).
fn steer_lock(v: &str) -> Result<f64, String> {
    let x = finite(v)?;
    if x > 0.0 && x < std::f64::consts::FRAC_PI_2 {
        Ok(x)
    } else {
        Err(format!(
            "must lie in (0, {}) rad (at pi/2 the equations are singular)",
            std::f64::consts::FRAC_PI_2
        ))
    }
}

/// The model's limits a run reached: the times of the fall and of the steer lock, and of the
/// singular configuration with the lean, pitch and steer there.
pub(crate) type Reached = (Option<f64>, Option<f64>, Option<(f64, [f64; 3])>);

/// The limits `end` of a run reached, with the configuration of its last state (lean, pitch,
/// steer) for the singular one.
pub(crate) fn reached(
    fall: Option<f64>,
    lock: Option<f64>,
    singular: Option<f64>,
    last: [f64; 3],
) -> Reached {
    (fall, lock, singular.map(|t| (t, last)))
}

/// How a run of the bicycle ended: its status (`completed`, `stopped`, `fell`, `steer lock`,
/// `singular`, `interrupted`) and the line that says so (`fell at t = 2.34 s: the lean reached
/// ...`), from the stop condition met (its text and time), the limits reached
/// ([`reached`]), the time of the interruption, the bicycle (its limits) and the run's end.
pub(crate) fn ending(
    event: Option<&(String, f64)>,
    limits: Reached,
    interrupted: Option<f64>,
    bike: &WhippleNonlinear,
    end: f64,
) -> (&'static str, String) {
    let (fall, lock, singular) = limits;
    if let Some((t, at)) = singular {
        ("singular", bike.singular_line(t, at[0], at[1], at[2]))
    } else if let Some(t) = fall {
        let a = bike.fall_angle();
        ("fell", format!("fell at t = {t} s: the lean reached the fall angle ±{a} rad"))
    } else if let Some(t) = lock {
        let a = bike.steer_lock();
        (
            "steer lock",
            format!("steer lock at t = {t} s: the steer reached ±{a} rad, the handlebar against the frame"),
        )
    } else if let Some((when, t)) = event {
        ("stopped", format!("stopped at t = {t} s: {when}"))
    } else if let Some(t) = interrupted {
        ("interrupted", super::rolling::interrupted_line(t))
    } else {
        ("completed", format!("completed at t = {end} s"))
    }
}

/// The JSON keys of the limits: `fall_angle`, `fall_t`, `steer_lock`, `steer_lock_t`,
/// `singular_pivot` and `singular_t`.
pub(crate) fn limits_json(v: &mut serde_json::Value, bike: &WhippleNonlinear, limits: Reached) {
    let (fall, lock, singular) = limits;
    v["fall_angle"] = json!(bike.fall_angle());
    v["fall_t"] = json!(fall);
    v["steer_lock"] = json!(bike.steer_lock());
    v["steer_lock_t"] = json!(lock);
    v["singular_pivot"] = json!(SINGULAR_PIVOT);
    v["singular_t"] = json!(singular.map(|(t, _)| t));
}

/// The message of a run that left the state's domain (a fixed step too long for the rates) or
/// whose adaptive method gave up (its step below double precision, more than a million
/// steps): the failure and the options to change, `--step` for RK4, the tolerances and the
/// method for the adaptive ones (Radau5 is restarted from its last accepted step when its
/// step collapses, so what reaches here collapsed with no step accepted since).
pub(crate) fn diverged(e: &NonlinearError, how: &Integration, step: f64) -> String {
    let m = how.method.name();
    if how.method.is_adaptive() {
        format!(
            "the integration diverged: {e} (--method {m}, --rtol {:e}, --atol {:e}); try \
             another --method, --rtol or --atol",
            how.rtol, how.atol
        )
    } else {
        format!(
            "the integration diverged: {e} (--method {m}, --step {step}); take a smaller \
             --step or an adaptive --method"
        )
    }
}

/// The message of a start that [`WhippleNonlinear::check_start`] refuses, naming `--lean0`.
pub(crate) fn bad_start(lean0: f64, e: &NonlinearError) -> String {
    match e {
        NonlinearError::Fallen { fall_angle, .. } => format!(
            "invalid --lean0 {lean0}: at or beyond the fall angle ±{fall_angle} rad (--fall-angle), where the bicycle is on the ground"
        ),
        NonlinearError::Parameter(carvallo::ParameterError::InvalidParameter {
            name: "lean",
            reason,
            ..
        }) => format!("invalid --lean0 {lean0}: {reason}"),
        other => other.to_string(),
    }
}

/// A positive count.
fn positive(v: &str) -> Result<usize, String> {
    v.parse().ok().filter(|n| *n > 0).ok_or_else(|| "must be a positive integer".to_string())
}

/// Runs `carvallo simulate`: the text to print, or an error naming the bad value.
pub fn run(cmd: &Args) -> Result<String, String> {
    let Args { model, data, duration, step, every, integration, json, .. } = cmd;
    let how = integration.tolerance.integration()?;
    let stops = &integration.stop_when;
    if cmd.csv && cmd.batch.is_none() {
        return Err("invalid --csv: it prints the rows of --batch FILE.csv".into());
    }
    if let Some(rider) = crate::args::lean_rider(model, data)? {
        return super::lean_rider::simulate(cmd, &rider, &how);
    }
    let bike = WhippleNonlinear::new(crate::args::bicycle(model, data)?)
        .with_fall_angle(cmd.fall_angle)
        .and_then(|b| b.with_steer_lock(cmd.steer_lock))
        .map_err(|e| e.to_string())?;
    let grid = Grid::exact(*duration, *step, *every)
        .map_err(|(name, value, reason)| format!("invalid --{name} {value:?}: {reason}"))?;
    if let Some(file) = &cmd.batch {
        return batch(&bike, file, &grid, &how, stops, cmd.csv);
    }
    let (Some(speed), Some(lean0)) = (cmd.speed, cmd.lean0) else {
        return Err("--speed and --lean0 are required without --batch".into());
    };
    let (speed, lean0) = (&speed, &lean0);
    let start = bike.initial_state(*speed, *lean0).map_err(|e| e.to_string())?;
    bike.check_start(&start).map_err(|e| bad_start(*lean0, &e))?;
    if cmd.inputs.any() {
        let header = (model.as_str(), *speed, *lean0, *every);
        return super::simulate_inputs::run(
            &cmd.inputs,
            &bike,
            start,
            &grid,
            &how,
            stops,
            header,
            *json,
        );
    }
    // An error after the start is the integration leaving the state's domain (a step too long
    // for the rates): said so, with the options to change.
    let tr = bike
        .simulate_until(start, &grid, &how, stops, crate::interrupt::interrupt_flag())
        .map_err(|e| diverged(&e, &how, *step))?;
    let events: Vec<(String, f64)> = tr.event.iter().map(|&(k, t)| (stops[k].text(), t)).collect();
    let end = tr.times.last().copied().unwrap_or(0.0);
    let last = tr.samples.last().map_or([f64::NAN; 3], |p| [p.state.lean, p.pitch, p.state.steer]);
    let limits = reached(tr.fall, tr.steer_lock, tr.singular, last);
    let (status, line) = ending(events.first(), limits, tr.interrupted, &bike, end);
    if *json {
        let col = |f: &dyn Fn(&carvallo::whipple_nonlinear::Sample) -> f64| -> Vec<f64> {
            tr.samples.iter().map(f).collect()
        };
        let adaptive = how.method.is_adaptive();
        let v = json!({
            "model": model,
            "speed": speed,
            "lean0": lean0,
            "step": tr.step,
            "method": how.method.name(),
            "rtol": if adaptive { Some(how.rtol) } else { None },
            "atol": if adaptive { Some(how.atol) } else { None },
            "rhs_evaluations": tr.stats.rhs_evaluations,
            "steps": tr.stats.steps,
            "rejected_steps": tr.stats.rejected_steps,
            "events": events.iter().map(|(when, t)| json!({"when": when, "t": t})).collect::<Vec<_>>(),
            "status": status,
            "status_line": line,
            "interrupted": tr.interrupted.map(super::rolling::interrupted_line),
            "energy_drift": tr.energy_drift,
            "max_contact_residual": tr.max_contact_residual,
            "t": col(&|s| s.t),
            "lean": col(&|s| s.state.lean),
            "steer": col(&|s| s.state.steer),
            "pitch": col(&|s| s.pitch),
            "speed_rear": col(&|s| s.speed),
            "rear_x": col(&|s| s.rear_contact[0]),
            "rear_y": col(&|s| s.rear_contact[1]),
            "front_x": col(&|s| s.front_contact[0]),
            "front_y": col(&|s| s.front_contact[1]),
            "energy": col(&|s| s.energy),
        });
        let mut v = v;
        limits_json(&mut v, &bike, limits);
        serde_json::to_string(&v).map_err(|e| e.to_string())
    } else {
        let integrator = if how.method.is_adaptive() {
            format!(
                "{} rtol {:e} atol {:e}, samples every {} s\n{} steps ({} rejected), {} right-hand side evaluations",
                how.method.name(),
                how.rtol,
                how.atol,
                tr.step * *every as f64,
                tr.stats.steps,
                tr.stats.rejected_steps,
                tr.stats.rhs_evaluations
            )
        } else {
            format!("RK4 step {} s", tr.step)
        };
        let mut s = format!(
            "nonlinear {model} bicycle from {speed} m/s, lean {lean0} rad, {integrator}\nenergy drift {:e} J, largest contact residual {:e} m\n",
            tr.energy_drift, tr.max_contact_residual
        );
        s.push_str(&format!("{line}\n"));
        if !stops.is_empty() && events.is_empty() {
            s.push_str("no stop condition met\n");
        }
        s.push_str(
            " t        lean       steer      speed      rear (x, y)            front (x, y)\n",
        );
        for p in &tr.samples {
            s.push_str(&format!(
                "{:8.3} {:+.6} {:+.6} {:.6} ({:.4}, {:+.4}) ({:.4}, {:+.4})\n",
                p.t,
                p.state.lean,
                p.state.steer,
                p.speed,
                p.rear_contact[0],
                p.rear_contact[1],
                p.front_contact[0],
                p.front_contact[1]
            ));
        }
        Ok(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;

    #[test]
    fn parses_and_rejects_by_value() {
        let words = [
            "simulate",
            "--model",
            "benchmark",
            "--speed",
            "5",
            "--lean0",
            "0.05",
            "--duration",
            "2",
            "--json",
        ];
        assert_eq!(
            parse::<Args>(&words),
            Ok(Args {
                model: "benchmark".into(),
                data: DataOptions::default(),
                speed: Some(5.0),
                lean0: Some(0.05),
                duration: 2.0,
                step: 0.001,
                every: 10,
                fall_angle: DEFAULT_FALL_ANGLE,
                steer_lock: DEFAULT_STEER_LOCK,
                integration: IntegrationArgs::default(),
                inputs: Default::default(),
                batch: None,
                csv: false,
                json: true
            })
        );
        let e = parse::<Args>(&["simulate", "--model", "benchmark", "--speed", "inf"]).unwrap_err();
        assert!(
            e.starts_with("error: invalid value 'inf' for '--speed <V>': must be finite"),
            "{e}"
        );
        let e = parse::<Args>(&["simulate", "--model", "b", "--speed", "1", "--speed", "2"])
            .unwrap_err();
        assert!(e.contains("'--speed <V>' cannot be used multiple times"), "{e}");
        let e = parse::<Args>(&["simulate", "--model", "b", "--speed", "1", "--lean0", "0"])
            .unwrap_err();
        assert!(e.contains("--duration <S>"), "{e}");
        let e = parse::<Args>(&[&words[..9], &["--every", "0"]].concat()).unwrap_err();
        assert!(e.contains("invalid value '0' for '--every <N>'"), "{e}");
    }
}
