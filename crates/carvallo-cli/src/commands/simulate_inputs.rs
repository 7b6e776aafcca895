//! The inputs of `carvallo simulate` ([`carvallo::whipple_nonlinear::inputs`]): torques as
//! functions of time and state feedback, and the driven run's text and JSON.
//!
//! * `--torque INPUT=step:VALUE@TIME` — a torque of VALUE N m from TIME s on;
//!   `--torque INPUT=impulse:J@TIME` — an angular impulse of J N m s at TIME s (a point of the
//!   step grid: the generalised speeds jump there). INPUT is `roll` ($T_\varphi$) or `steer`
//!   ($T_\delta$); `@TIME` may be left out (0). The option may be repeated: the terms add up.
//! * `--torque-csv FILE.csv` — torques sampled in time: a header naming `t` and `T_phi` and/or
//!   `T_delta` (any order), then one row of finite numbers per sample, times strictly
//!   increasing; linearly interpolated, zero outside the first and last time. Errors name the
//!   file and the line.
//! * `--gain NAME=VALUE` or `--gain-table FILE.csv` — the feedback $T = -Kx$ as `window` takes
//!   it ([`crate::gains`]); a table is read at the current speed of the rear contact, and a
//!   speed outside it ends the run with an error naming the speed and the time.
//!
//! With any of them the run is driven ([`WhippleNonlinear::simulate_forced`]): the energy
//! drift printed is that of the balance $E - E(0) - W$, $W$ the input's work; the text adds
//! the inputs, the work and the largest change of the energy, and the columns of the
//! torques and the work; `--json` adds `inputs`, `work`, `max_energy_change` and the
//! columns `T_phi`, `T_delta`, `work_t`.

use std::path::{Path, PathBuf};

use carvallo::numerics::integrate::{Grid, Integration};
use carvallo::whipple_nonlinear::{
    Feedback, ForcedSample, Impulse, InputError, Inputs, NonlinearError, Series, Signal, State,
    Stop, WhippleNonlinear,
};
use serde_json::{json, Value};

use crate::gains::GainValue;

/// The input a `--torque` term drives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Input {
    /// The roll torque $T_\varphi$.
    Roll,
    /// The steer torque $T_\delta$.
    Steer,
    /// The leaning rider's lean torque $T_9$, between the torso and the rear frame
    /// (`--model lean-rider` only).
    Lean,
}

/// The kind of a `--torque` term.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A step of VALUE N m from TIME s on.
    Step,
    /// An impulse of VALUE N m s at TIME s.
    Impulse,
}

/// One `--torque INPUT=KIND:VALUE@TIME`.
#[derive(Clone, Debug, PartialEq)]
pub struct TorqueTerm {
    /// Which torque.
    pub input: Input,
    /// Step or impulse.
    pub kind: Kind,
    /// N m for a step, N m s for an impulse.
    pub value: f64,
    /// When (s).
    pub time: f64,
    /// The text given.
    pub text: String,
}

/// Reads `--torque INPUT=KIND:VALUE[@TIME]` (clap's value parser).
pub fn parse_torque(text: &str) -> Result<TorqueTerm, String> {
    let bad = |why: String| format!("invalid --torque `{text}`: {why}");
    let (input, rest) = text
        .split_once('=')
        .ok_or_else(|| bad("expected INPUT=step:VALUE@TIME or INPUT=impulse:VALUE@TIME".into()))?;
    let input = match input.trim() {
        "roll" => Input::Roll,
        "steer" => Input::Steer,
        "lean" => Input::Lean,
        other => {
            return Err(bad(format!(
                "unknown input `{other}`: expected roll or steer (or lean, the leaning rider's)"
            )))
        }
    };
    let (kind, rest) = rest
        .split_once(':')
        .ok_or_else(|| bad("expected KIND:VALUE@TIME with KIND step or impulse".into()))?;
    let kind = match kind.trim() {
        "step" => Kind::Step,
        "impulse" => Kind::Impulse,
        other => return Err(bad(format!("unknown kind `{other}`: expected step or impulse"))),
    };
    let (value, time) = rest.split_once('@').unwrap_or((rest, "0"));
    let number = |s: &str, what: &str| -> Result<f64, String> {
        let x: f64 = s.trim().parse().map_err(|_| bad(format!("{what} `{s}` is not a number")))?;
        if x.is_finite() {
            Ok(x)
        } else {
            Err(bad(format!("{what} `{s}` must be finite")))
        }
    };
    let value = number(value, "value")?;
    let value =
        crate::args::TORQUE.check(value).map_err(|e| bad(format!("value `{value}` {e}")))?;
    let time = number(time, "time")?;
    if time < 0.0 {
        return Err(bad(format!("time `{time}` must not be negative")));
    }
    Ok(TorqueTerm { input, kind, value, time, text: text.to_string() })
}

/// The inputs of `simulate`.
#[derive(Clone, Debug, Default, PartialEq, clap::Args)]
pub struct InputArgs {
    /// A torque on the bicycle: INPUT=step:VALUE@TIME (VALUE N m from TIME s on) or
    /// INPUT=impulse:VALUE@TIME (VALUE N m s at TIME s, a multiple of --step), INPUT roll or
    /// steer (or lean, the leaning rider's lean torque, steps only); may be repeated (the terms
    /// add up)
    #[arg(long, value_name = "INPUT=KIND:VALUE@TIME", value_parser = parse_torque, allow_hyphen_values = true, conflicts_with = "batch")]
    pub torque: Vec<TorqueTerm>,
    /// Torques sampled in time: a CSV file with the columns t and T_phi and/or T_delta (N m),
    /// times increasing, linearly interpolated, zero outside the first and last time
    #[arg(long, value_name = "FILE.csv", conflicts_with = "batch")]
    pub torque_csv: Option<PathBuf>,
    /// A gain of the state feedback T = -K x, x = (lean, steer, lean rate, steer rate),
    /// NAME = k_{roll|steer}_{roll|steer|roll_rate|steer_rate}; may be repeated
    #[arg(long, value_name = "NAME=VALUE", value_parser = crate::gains::parse_gain, allow_hyphen_values = true, conflicts_with = "batch")]
    pub gain: Vec<GainValue>,
    /// Gains that vary with the rear contact's speed: a CSV file with the header speed,k_...
    /// and one row per speed (as window --gain-table)
    #[arg(long, value_name = "FILE.csv", conflicts_with_all = ["gain", "batch"])]
    pub gain_table: Option<String>,
}

impl InputArgs {
    /// Whether any input is given.
    pub fn any(&self) -> bool {
        !self.torque.is_empty()
            || self.torque_csv.is_some()
            || !self.gain.is_empty()
            || self.gain_table.is_some()
    }

    /// The inputs these options describe, files read; an error names the bad value.
    pub fn inputs(&self) -> Result<Inputs, String> {
        let mut inputs = Inputs::default();
        for term in &self.torque {
            let list = match term.input {
                Input::Roll => &mut inputs.roll,
                Input::Steer => &mut inputs.steer,
                Input::Lean => {
                    return Err(format!(
                        "invalid --torque `{}`: the lean torque is the leaning rider's \
                         (--model lean-rider); the bicycle takes roll and steer",
                        term.text
                    ))
                }
            };
            match term.kind {
                Kind::Step => list.push(Signal::Step { value: term.value, start: term.time }),
                Kind::Impulse => {
                    let (roll, steer) = match term.input {
                        Input::Roll => (term.value, 0.0),
                        _ => (0.0, term.value),
                    };
                    inputs.impulses.push(Impulse { t: term.time, roll, steer });
                }
            }
        }
        if let Some(file) = &self.torque_csv {
            let (roll, steer) = read_torque_csv(file)?;
            inputs.roll.extend(roll.map(Signal::Series));
            inputs.steer.extend(steer.map(Signal::Series));
        }
        if let Some(path) = &self.gain_table {
            inputs.feedback = Feedback::Table(crate::gains::read_gain_table(path)?);
        } else if !self.gain.is_empty() {
            crate::gains::bicycle_only(&self.gain)?;
            inputs.feedback = Feedback::Constant(crate::gains::gains_of(&self.gain));
        }
        Ok(inputs)
    }

    /// The inputs as JSON: the `--torque` terms as given, the file, the gains or the table.
    fn json(&self) -> Value {
        json!({
            "torque": self.torque.iter().map(|t| t.text.clone()).collect::<Vec<_>>(),
            "torque_csv": self.torque_csv.as_ref().map(|p| p.display().to_string()),
            "gains": if self.gain.is_empty() { Value::Null } else { crate::gains::gains_json(&crate::gains::gains_of(&self.gain)) },
            "gain_table": self.gain_table,
        })
    }

    /// The inputs in one line of text.
    fn text(&self) -> String {
        let mut parts: Vec<String> = self.torque.iter().map(|t| t.text.clone()).collect();
        if let Some(p) = &self.torque_csv {
            parts.push(format!("torques from {}", p.display()));
        }
        if !self.gain.is_empty() {
            parts.push(format!(
                "gains {}",
                crate::gains::gains_text(&crate::gains::gains_of(&self.gain))
            ));
        }
        if let Some(p) = &self.gain_table {
            parts.push(format!("gains from {p} at the rear contact speed"));
        }
        parts.join(", ")
    }
}

/// Reads a `--torque-csv` file: the roll and steer series (`None` for a column not given).
fn read_torque_csv(file: &Path) -> Result<(Option<Series>, Option<Series>), String> {
    let name = file.display();
    let text = crate::args::read_text(file, "torque file")?;
    let bad = |msg: String| format!("invalid torque file `{name}`: {msg}");
    let mut lines = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty());
    let (_, header) = lines.next().ok_or_else(|| bad("empty file".into()))?;
    let columns: Vec<&str> = header.split(',').map(str::trim).collect();
    for (i, c) in columns.iter().enumerate() {
        if !["t", "T_phi", "T_delta"].contains(c) {
            return Err(bad(format!("unknown column `{c}`: expected t, T_phi, T_delta")));
        }
        if columns[..i].contains(c) {
            return Err(bad(format!("the column `{c}` is given twice")));
        }
    }
    let find = |c: &str| columns.iter().position(|h| *h == c);
    let Some(tc) = find("t") else {
        return Err(bad(format!("the header `{header}` must name the column t")));
    };
    let (rc, sc) = (find("T_phi"), find("T_delta"));
    if rc.is_none() && sc.is_none() {
        return Err(bad(format!("the header `{header}` must name T_phi or T_delta")));
    }
    let (mut lines_of, mut t, mut roll, mut steer) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (i, line) in lines {
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        if cells.len() != columns.len() {
            return Err(bad(format!(
                "line {}: {} values for {} columns",
                i + 1,
                cells.len(),
                columns.len()
            )));
        }
        let num = |k: usize| -> Result<f64, String> {
            cells[k].parse::<f64>().ok().filter(|x| x.is_finite()).ok_or_else(|| {
                bad(format!("line {}: {} `{}` is not a finite number", i + 1, columns[k], cells[k]))
            })
        };
        let torque = |k: usize| -> Result<f64, String> {
            crate::args::TORQUE
                .check(num(k)?)
                .map_err(|e| bad(format!("line {}: {} `{}` {e}", i + 1, columns[k], cells[k])))
        };
        lines_of.push(i + 1);
        t.push(num(tc)?);
        if let Some(k) = rc {
            roll.push(torque(k)?);
        }
        if let Some(k) = sc {
            steer.push(torque(k)?);
        }
    }
    let series = |column: Option<usize>, values: Vec<f64>| -> Result<Option<Series>, String> {
        if column.is_none() {
            return Ok(None);
        }
        Series::new(t.clone(), values).map(Some).map_err(|e| match e {
            InputError::NotIncreasing { row, t, previous } => bad(format!(
                "line {}: time {t} does not exceed the time {previous} before it",
                lines_of[row - 1]
            )),
            InputError::TooFewSamples { count } => {
                bad(format!("{count} samples: at least two are needed"))
            }
            other => bad(other.to_string()),
        })
    };
    Ok((series(rc, roll)?, series(sc, steer)?))
}

/// The driven run of `simulate` from `start`: its text or JSON.
#[allow(clippy::too_many_arguments)]
pub fn run(
    args: &InputArgs,
    bike: &WhippleNonlinear,
    start: State,
    grid: &Grid,
    how: &Integration,
    stops: &[Stop],
    header: (&str, f64, f64, usize),
    json: bool,
) -> Result<String, String> {
    let (model, speed, lean0, every) = header;
    let inputs = args.inputs()?;
    let tr = bike
        .simulate_forced_until(start, grid, how, stops, &inputs, crate::interrupt::interrupt_flag())
        .map_err(|e| match e {
            NonlinearError::Integration { .. } => super::simulate::diverged(&e, how, grid.h),
            e => e.to_string(),
        })?;
    let events: Vec<(String, f64)> = tr.event.iter().map(|&(k, t)| (stops[k].text(), t)).collect();
    let end = tr.times.last().copied().unwrap_or(0.0);
    let last = tr
        .samples
        .last()
        .map_or([f64::NAN; 3], |p| [p.sample.state.lean, p.sample.pitch, p.sample.state.steer]);
    let limits = super::simulate::reached(tr.fall, tr.steer_lock, tr.singular, last);
    let (status, line) = super::simulate::ending(events.first(), limits, tr.interrupted, bike, end);
    let d = tr.diagnostics;
    if json {
        let col =
            |f: &dyn Fn(&ForcedSample) -> f64| -> Vec<f64> { tr.samples.iter().map(f).collect() };
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
            "inputs": args.json(),
            "work": d.work,
            "max_energy_change": d.max_energy_change,
            "energy_drift": d.energy_drift,
            "max_contact_residual": d.max_contact_residual,
            "t": col(&|s| s.sample.t),
            "lean": col(&|s| s.sample.state.lean),
            "steer": col(&|s| s.sample.state.steer),
            "pitch": col(&|s| s.sample.pitch),
            "speed_rear": col(&|s| s.sample.speed),
            "rear_x": col(&|s| s.sample.rear_contact[0]),
            "rear_y": col(&|s| s.sample.rear_contact[1]),
            "front_x": col(&|s| s.sample.front_contact[0]),
            "front_y": col(&|s| s.sample.front_contact[1]),
            "energy": col(&|s| s.sample.energy),
            "T_phi": col(&|s| s.torque[0]),
            "T_delta": col(&|s| s.torque[1]),
            "work_t": col(&|s| s.work),
        });
        let mut v = v;
        super::simulate::limits_json(&mut v, bike, limits);
        return serde_json::to_string(&v).map_err(|e| e.to_string());
    }
    let integrator = if how.method.is_adaptive() {
        format!(
            "{} rtol {:e} atol {:e}, samples every {} s\n{} steps ({} rejected), {} right-hand side evaluations",
            how.method.name(),
            how.rtol,
            how.atol,
            tr.step * every as f64,
            tr.stats.steps,
            tr.stats.rejected_steps,
            tr.stats.rhs_evaluations
        )
    } else {
        format!("RK4 step {} s", tr.step)
    };
    let mut s = format!(
        "nonlinear {model} bicycle from {speed} m/s, lean {lean0} rad, {integrator}\ninputs: {}\nwork of the inputs {:e} J, energy changed by up to {:e} J\nenergy balance drift (E - E0 - W) {:e} J, largest contact residual {:e} m\n",
        args.text(),
        d.work,
        d.max_energy_change,
        d.energy_drift,
        d.max_contact_residual
    );
    s.push_str(&format!("{line}\n"));
    if !stops.is_empty() && events.is_empty() {
        s.push_str("no stop condition met\n");
    }
    s.push_str(" t        lean       steer      speed      T_phi      T_delta    work\n");
    for p in &tr.samples {
        s.push_str(&format!(
            "{:8.3} {:+.6} {:+.6} {:.6} {:+.6} {:+.6} {:+.6}\n",
            p.sample.t,
            p.sample.state.lean,
            p.sample.state.steer,
            p.sample.speed,
            p.torque[0],
            p.torque[1],
            p.work
        ));
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use carvallo::whipple::feedback::Gains;

    #[test]
    fn torque_terms_parse_and_errors_name_the_value() {
        let t = parse_torque("steer=step:0.5@0.1").expect("ok");
        assert_eq!((t.input, t.kind, t.value, t.time), (Input::Steer, Kind::Step, 0.5, 0.1));
        let t = parse_torque("roll=impulse:-2").expect("ok");
        assert_eq!((t.input, t.kind, t.value, t.time), (Input::Roll, Kind::Impulse, -2.0, 0.0));
        for (text, msg) in [
            (
                "yaw=step:1",
                "invalid --torque `yaw=step:1`: unknown input `yaw`: expected roll or steer",
            ),
            ("steer=ramp:1", "unknown kind `ramp`: expected step or impulse"),
            ("steer=step:x@1", "value `x` is not a number"),
            ("steer=step:1@inf", "time `inf` must be finite"),
            ("steer=step:1@-1", "time `-1` must not be negative"),
            ("steer", "expected INPUT=step:VALUE@TIME"),
            ("steer=1", "expected KIND:VALUE@TIME"),
        ] {
            let e = parse_torque(text).unwrap_err();
            assert!(e.contains(msg), "{text}: {e}");
        }
        let args = InputArgs {
            gain: vec![crate::gains::parse_gain("k_steer_roll_rate=-20").expect("gain")],
            ..InputArgs::default()
        };
        assert_eq!(crate::gains::gains_of(&args.gain), Gains::balance_assist(20.0));
        assert!(args.any() && !InputArgs::default().any());
    }

    #[test]
    fn torque_files_are_read_and_their_errors_name_the_file_and_line() {
        let dir = std::env::temp_dir().join(format!("carvallo-torque-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let file = |name: &str, text: &str| {
            let p = dir.join(name);
            std::fs::write(&p, text).expect("write");
            p
        };
        let ok = file("ok.csv", "T_delta,t\n0,0\n1,0.5\n\n0,1\n");
        let (roll, steer) = read_torque_csv(&ok).expect("valid");
        assert!(roll.is_none());
        assert_eq!(steer.expect("steer").at(0.25), 0.5);
        for (name, text, msg) in [
            ("e.csv", "", "empty file"),
            ("u.csv", "t,T_psi\n0,1\n", "unknown column `T_psi`"),
            ("n.csv", "T_phi,T_delta\n0,1\n", "must name the column t"),
            ("o.csv", "t\n0\n1\n", "must name T_phi or T_delta"),
            ("w.csv", "t,T_phi\n0,1\n1,2,3\n", "line 3: 3 values for 2 columns"),
            ("x.csv", "t,T_phi\n0,1\n1,nan\n", "line 3: T_phi `nan` is not a finite number"),
            (
                "m.csv",
                "t,T_phi\n0,1\n0.3,2\n\n0.2,0\n",
                "line 5: time 0.2 does not exceed the time 0.3 before it",
            ),
            ("s.csv", "t,T_phi\n0,1\n", "1 samples: at least two are needed"),
            ("d.csv", "t,t\n0,1\n", "the column `t` is given twice"),
        ] {
            let path = file(name, text);
            let e = read_torque_csv(&path).unwrap_err();
            assert!(e.starts_with(&format!("invalid torque file `{}`: ", path.display())), "{e}");
            assert!(e.contains(msg), "{name}: {e}");
        }
        let e = read_torque_csv(Path::new("/nonexistent/t.csv")).unwrap_err();
        assert!(e.starts_with("cannot read torque file `/nonexistent/t.csv`"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
