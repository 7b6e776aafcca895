//! `carvallo pendulum`: the two-wheeled inverted pendulum (a self-balancing robot or personal
//! transporter, [`carvallo::wheeled_pendulum`]), the mechanics engine's rolling system that is
//! not a bicycle.
//!
//! * `carvallo pendulum eig [--speed V] [--param NAME=VALUE ...] [--gain placed|K1,...,K8]
//!   [--poles P1,P2,P3] [--json]`: the eigenvalues of the linear model about upright straight
//!   running at V m/s (2 by default), with its $A$ (state θ, θ̇, θ̇_L, θ̇_R) and $B$ (inputs
//!   T_L, T_R); with `--gain` those of the closed loop $A - BK$ under the feedback `simulate`
//!   takes, the gain printed (and the poles it was placed at).
//! * `carvallo pendulum simulate --t-end T --pitch0 X [--speed V] [--param NAME=VALUE ...]
//!   [--gain placed|K1,...,K8] [--poles P1,P2,P3] [--step DT] [--every N] [--method M]
//!   [--rtol R] [--atol A] [--csv PATH] [--json]`: the nonlinear model from upright running at V
//!   pitched by X rad, open loop or under the state feedback $T = -K(x - x_{\rm ref})$
//!   (`--gain placed`: poles placed at $-\lambda, -1.5\lambda, -2\lambda$ from the linear
//!   model's growth rate λ, or at `--poles`; `--gain` with eight numbers: K's rows T_L, T_R
//!   over θ, θ̇, θ̇_L, θ̇_R), by DOP853 (`--method`, `--rtol`, `--atol` as on `simulate`),
//!   sampled every `--every` × `--step` s. A fall ($|\theta| = \pi/2$) is the run's status
//!   (exit 0), not an error. `--csv PATH` writes every sample (t, the state, the torques).
//!
//! The design is the illustrative transporter with its rider
//! ([`WheeledPendulumParams::nominal`]), each `--param NAME=VALUE` changing one value. Unknown
//! names, values that are not finite or out of range, a start already fallen and invalid poles
//! or gains are errors naming the value, exit code 2.

use std::fmt::Write as _;

use carvallo::numerics::integrate::Grid;
use carvallo::wheeled_pendulum::{
    Feedback, LinearModel, Trajectory, WheeledPendulum, WheeledPendulumParams, FALL_ANGLE,
    STATE_NAMES,
};
use serde_json::json;

use super::simulate::{MethodArg, ToleranceArgs};
use crate::args::{finite, Range, ANGLE, GAIN, GRAVITY, INERTIA, LENGTH, MASS, SPEED};

/// `carvallo pendulum`: its two commands.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub command: PendulumCommand,
}

/// The commands of `carvallo pendulum`.
#[derive(Clone, Debug, PartialEq, clap::Subcommand)]
pub enum PendulumCommand {
    /// The eigenvalues and the state space (A, B) of the linear model at speed V
    Eig(EigArgs),
    /// Simulate the nonlinear model from a pitched start, open loop or under a state feedback
    Simulate(SimulateArgs),
}

/// One `--param NAME=VALUE`.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    /// One of [`WheeledPendulumParams::NAMES`].
    pub name: &'static str,
    /// The value, finite and within its kind's range.
    pub value: f64,
}

/// The range of a parameter by its kind: lengths, masses, moments (positive) and gravity.
fn range(name: &str) -> Range {
    match name {
        "r" | "W" | "l" => LENGTH,
        "mW" | "mB" => MASS,
        "g" => GRAVITY,
        _ => Range { lo: 1e-30, ..INERTIA },
    }
}

/// Reads `NAME=VALUE` for `--param`.
fn parse_param(text: &str) -> Result<Param, String> {
    let names = WheeledPendulumParams::NAMES.join(", ");
    let (name, value) = text
        .split_once('=')
        .ok_or_else(|| format!("expected NAME=VALUE with NAME one of {names}"))?;
    let name = WheeledPendulumParams::NAMES
        .into_iter()
        .find(|n| *n == name.trim())
        .ok_or_else(|| format!("unknown parameter `{}`: expected one of {names}", name.trim()))?;
    let value = finite(value.trim())
        .and_then(|v| range(name).check(v))
        .map_err(|e| format!("{name}: {e}"))?;
    Ok(Param { name, value })
}

/// The design and the speed: the options both commands share.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct DesignArgs {
    /// The speed of the upright straight running (m/s)
    #[arg(long, value_name = "V", default_value_t = 2.0, value_parser = SPEED.parser(), allow_hyphen_values = true)]
    pub speed: f64,
    /// Set a parameter of the nominal design: NAME=VALUE with NAME one of r, W, mW, IWd, IWa,
    /// l, mB, IBxx, IByy, IBzz, g (SI units); may be repeated
    #[arg(long = "param", value_name = "NAME=VALUE", value_parser = parse_param, allow_hyphen_values = true)]
    pub params: Vec<Param>,
}

impl DesignArgs {
    /// The model, or an error naming the bad value.
    fn model(&self) -> Result<WheeledPendulum, String> {
        let mut p = WheeledPendulumParams::nominal();
        for Param { name, value } in &self.params {
            p = p.with(name, *value).map_err(|e| format!("invalid --param {name}={value}: {e}"))?;
        }
        Ok(WheeledPendulum::new(p))
    }

    /// The design in words: nominal, or the changed values.
    fn describe(&self) -> String {
        if self.params.is_empty() {
            "the nominal design (illustrative)".into()
        } else {
            let changed: Vec<String> =
                self.params.iter().map(|p| format!("{}={}", p.name, p.value)).collect();
            format!("the nominal design with {}", changed.join(", "))
        }
    }
}

/// `carvallo pendulum eig`.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct EigArgs {
    #[command(flatten)]
    pub design: DesignArgs,
    /// The state feedback: `placed` (poles placed from the linear model, or at --poles), or
    /// the eight gains of K, rows TL, TR over theta, thetad, thetaLd, thetaRd; the eigenvalues
    /// are then those of the closed loop A - BK
    #[arg(long, value_name = "placed|K1,...,K8", value_parser = parse_gain, allow_hyphen_values = true)]
    pub gain: Option<GainArg>,
    /// The three closed-loop poles (1/s) of the pitch and forward motion for `--gain placed`
    /// [default: -λ, -1.5λ, -2λ from the growth rate λ]
    #[arg(long, value_name = "P1,P2,P3", value_parser = parse_poles, allow_hyphen_values = true)]
    pub poles: Option<[f64; 3]>,
    /// Print JSON (speed, eigenvalues as [re, im] pairs, A, B; with --gain the gain and the
    /// poles) instead of text
    #[arg(long)]
    pub json: bool,
}

/// A feedback with the poles it was placed at (`None` when `--gain` gave K).
type Chosen = (Feedback, Option<[f64; 3]>);

/// The feedback of `--gain` (with the poles `--gain placed` put it at) on the linear model
/// `lin`, `None` without `--gain`; `--poles` without `--gain placed`, poles or gains the
/// model refuses are errors naming them.
fn feedback_of(
    lin: &LinearModel,
    gain: &Option<GainArg>,
    poles: Option<[f64; 3]>,
) -> Result<Option<Chosen>, String> {
    if poles.is_some() && *gain != Some(GainArg::Placed) {
        return Err("invalid --poles: they are placed by --gain placed".into());
    }
    let feedback = match gain {
        None => None,
        Some(GainArg::Placed) => {
            let poles = poles.unwrap_or_else(|| lin.default_poles());
            let k = lin.place(poles).map_err(|e| format!("invalid --poles: {e}"))?;
            Some((k, Some(poles)))
        }
        Some(GainArg::Matrix(k)) => {
            Some((lin.feedback(*k).map_err(|e| format!("invalid --gain: {e}"))?, None))
        }
    };
    if let Some((k, _)) = &feedback {
        all_finite(k.gain.iter().flatten())?;
    }
    Ok(feedback)
}

/// The lines of a gain matrix K under its heading.
fn gain_text(s: &mut String, k: &Feedback) {
    s.push_str("gain K (rows TL, TR; columns theta, thetad, thetaLd, thetaRd):\n");
    for row in &k.gain {
        let _ = writeln!(s, " {}", row.iter().map(|v| format!(" {v:+12.6}")).collect::<String>());
    }
}

/// Every entry of `values` finite, or an error saying the design overflows.
fn all_finite<'a>(values: impl IntoIterator<Item = &'a f64>) -> Result<(), String> {
    if values.into_iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err("invalid --param: the design's equations are not finite (a value too far from the others)".into())
    }
}

/// Runs `carvallo pendulum eig`: the text to print, or an error naming the bad value.
pub fn eig(c: &EigArgs) -> Result<String, String> {
    let m = c.design.model()?;
    let lin = m.linear(c.design.speed);
    all_finite(lin.a.iter().chain(lin.b.iter()))?;
    let feedback = feedback_of(&lin, &c.gain, c.poles)?;
    let ev = match &feedback {
        Some((k, _)) => lin.closed_loop_eigenvalues(k),
        None => lin.eigenvalues(),
    };
    let rows = |k: usize, cols: usize, at: &dyn Fn(usize, usize) -> f64| -> Vec<Vec<f64>> {
        (0..k).map(|i| (0..cols).map(|j| at(i, j)).collect()).collect()
    };
    let a = rows(4, 4, &|i, j| lin.a[(i, j)]);
    let b = rows(4, 2, &|i, j| lin.b[(i, j)]);
    if c.json {
        let out = json!({
            "speed": c.design.speed,
            "eigenvalues": ev.iter().map(|z| [z.re, z.im]).collect::<Vec<_>>(),
            "state": ["theta", "thetad", "thetaLd", "thetaRd"],
            "inputs": ["TL", "TR"],
            "a": a,
            "b": b,
        });
        let mut out = out;
        if let Some((k, poles)) = &feedback {
            out["gain"] = json!(k.gain);
            out["poles"] = json!(poles);
        }
        return serde_json::to_string(&out).map_err(|e| e.to_string());
    }
    let mut s =
        format!("wheeled pendulum, {}, upright at {} m/s\n", c.design.describe(), c.design.speed);
    if let Some((k, poles)) = &feedback {
        if let Some(p) = poles {
            let _ = writeln!(s, "feedback placed at poles {}, {}, {} 1/s", p[0], p[1], p[2]);
        }
        gain_text(&mut s, k);
        s.push_str("closed-loop eigenvalues of A - BK (1/s):\n");
    } else {
        s.push_str("eigenvalues (1/s):\n");
    }
    // The closed loop's turning mode is zero only to rounding (1e-16), which would print as
    // -0.000000 on one platform and +0.000000 on another.
    let zero = |v: f64| if v.abs() < 1e-9 { 0.0 } else { v };
    for z in ev {
        let _ = writeln!(s, "  {:+.6} {:+.6}i", zero(z.re), zero(z.im));
    }
    let lambda = lin.growth_rate();
    if lambda > 0.0 && feedback.is_none() {
        let _ = writeln!(
            s,
            "the pitch grows as exp({lambda:.6} t): doubles in {:.4} s without control",
            std::f64::consts::LN_2 / lambda
        );
    }
    s.push_str("A (state theta, thetad, thetaLd, thetaRd):\n");
    for row in &a {
        let _ = writeln!(s, " {}", row.iter().map(|v| format!(" {v:+12.6}")).collect::<String>());
    }
    s.push_str("B (inputs TL, TR in N m):\n");
    for row in &b {
        let _ = writeln!(s, " {}", row.iter().map(|v| format!(" {v:+12.6}")).collect::<String>());
    }
    Ok(s)
}

/// The feedback of `--gain`.
#[derive(Clone, Debug, PartialEq)]
pub enum GainArg {
    /// Placed poles (`--gain placed`).
    Placed,
    /// K given: rows T_L, T_R; columns θ, θ̇, θ̇_L, θ̇_R.
    Matrix([[f64; 4]; 2]),
}

/// Reads `--gain`: `placed` or eight numbers separated by commas.
fn parse_gain(text: &str) -> Result<GainArg, String> {
    if text.trim() == "placed" {
        return Ok(GainArg::Placed);
    }
    let values: Vec<f64> = text
        .split(',')
        .enumerate()
        .map(|(i, v)| {
            finite(v.trim()).and_then(|x| GAIN.check(x)).map_err(|e| {
                format!(
                    "expected `placed` or eight gains K1,...,K8: K{} `{}`: {e}",
                    i + 1,
                    v.trim()
                )
            })
        })
        .collect::<Result<_, _>>()?;
    let k: [f64; 8] = values.try_into().map_err(|v: Vec<f64>| {
        format!("expected `placed` or eight gains K1,...,K8 (rows TL, TR), not {}", v.len())
    })?;
    Ok(GainArg::Matrix([[k[0], k[1], k[2], k[3]], [k[4], k[5], k[6], k[7]]]))
}

/// The range of a closed-loop pole (1/s).
const POLE: Range = Range {
    lo: -1e6,
    hi: -1e-6,
    why: "a stable pole, and beyond 1e6 the gains lose the pendulum's own terms",
};

/// Reads `--poles`: three negative numbers separated by commas.
fn parse_poles(text: &str) -> Result<[f64; 3], String> {
    let values: Vec<f64> = text
        .split(',')
        .map(|v| finite(v.trim()).and_then(|x| POLE.check(x)))
        .collect::<Result<_, _>>()
        .map_err(|e| format!("expected three poles P1,P2,P3: {e}"))?;
    values
        .try_into()
        .map_err(|v: Vec<f64>| format!("expected three poles P1,P2,P3, not {}", v.len()))
}

/// A positive count.
fn positive(v: &str) -> Result<usize, String> {
    v.parse().ok().filter(|n| *n > 0).ok_or_else(|| "must be a positive integer".to_string())
}

/// `carvallo pendulum simulate`.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct SimulateArgs {
    #[command(flatten)]
    pub design: DesignArgs,
    /// How long to simulate (s)
    #[arg(long = "t-end", value_name = "T", value_parser = finite, allow_hyphen_values = true)]
    pub t_end: f64,
    /// The initial pitch of the body from upright (rad, positive forward; less than pi/2 in
    /// magnitude)
    #[arg(long, value_name = "RAD", value_parser = ANGLE.parser(), allow_hyphen_values = true)]
    pub pitch0: f64,
    /// The state feedback: `placed` (poles placed from the linear model, or at --poles), or
    /// the eight gains of K, rows TL, TR over theta, thetad, thetaLd, thetaRd; open loop
    /// without it
    #[arg(long, value_name = "placed|K1,...,K8", value_parser = parse_gain, allow_hyphen_values = true)]
    pub gain: Option<GainArg>,
    /// The three closed-loop poles (1/s) of the pitch and forward motion for `--gain placed`
    /// [default: -λ, -1.5λ, -2λ from the growth rate λ]
    #[arg(long, value_name = "P1,P2,P3", value_parser = parse_poles, allow_hyphen_values = true)]
    pub poles: Option<[f64; 3]>,
    /// The step of the sample grid (s)
    #[arg(long, value_name = "DT", default_value_t = 0.01, value_parser = finite, allow_hyphen_values = true)]
    pub step: f64,
    /// Print every N-th sample of the grid
    #[arg(long, value_name = "N", default_value_t = 10, value_parser = positive)]
    pub every: usize,
    /// The integrator
    #[arg(long, value_enum, default_value_t = MethodArg::Dop853)]
    pub method: MethodArg,
    /// The relative tolerance of an adaptive method [default: 1e-8]
    #[arg(long, value_name = "R", value_parser = finite, allow_hyphen_values = true)]
    pub rtol: Option<f64>,
    /// The absolute tolerance of an adaptive method [default: 1e-3 × rtol]
    #[arg(long, value_name = "A", value_parser = finite, allow_hyphen_values = true)]
    pub atol: Option<f64>,
    /// Write every sample (t, x, y, psi, theta, thetad, thetaLd, thetaRd, TL, TR) to PATH as CSV
    #[arg(long, value_name = "PATH")]
    pub csv: Option<std::path::PathBuf>,
    /// Print JSON (the samples, the status, the energy and the counts) instead of text
    #[arg(long)]
    pub json: bool,
}

/// Runs `carvallo pendulum simulate`: the text to print, or an error naming the bad value.
pub fn simulate(c: &SimulateArgs) -> Result<String, String> {
    let m = c.design.model()?;
    if c.pitch0.abs() >= FALL_ANGLE {
        return Err(format!(
            "invalid --pitch0 {:?}: must be less than pi/2 in magnitude (the body has fallen)",
            c.pitch0
        ));
    }
    let how = ToleranceArgs { method: c.method, rtol: c.rtol, atol: c.atol }
        .integration()
        .map_err(|e| match (c.rtol, c.atol) {
            (Some(r), None) => format!("{e} (--rtol {r:?} gives --atol 1e-3 × rtol)"),
            _ => e,
        })?;
    let grid = Grid::new(c.t_end, c.step, c.every).map_err(|(name, value, reason)| {
        let name = if name == "duration" { "t-end" } else { name };
        format!(
            "invalid --{name} {value:?}: {reason} (--t-end {:?}, --step {:?}, --every {})",
            c.t_end, c.step, c.every
        )
    })?;
    let speed = c.design.speed;
    let lin = m.linear(speed);
    all_finite(lin.a.iter().chain(lin.b.iter()))?;
    let feedback = feedback_of(&lin, &c.gain, c.poles)?;
    let torques = |x: &[f64; 7]| feedback.as_ref().map_or([0.0, 0.0], |(k, _)| k.torques(x));
    let mut x0 = m.upright(speed);
    x0[3] = c.pitch0;
    let run = m.simulate(x0, &|_, x| torques(x), &grid, &how).map_err(|e| {
        format!(
            "the simulation failed: {e} (--method {}, --rtol {:?}, --atol {:?}, --step {:?})",
            how.method.name(),
            how.rtol,
            how.atol,
            c.step
        )
    })?;
    if let Some((t, _)) = run.iter().find(|(_, x)| x.iter().any(|v| !v.is_finite())) {
        return Err(format!(
            "the integration diverged: the state is not finite at t = {t} s (--method {}, \
             --rtol {:?}, --atol {:?}); take smaller tolerances, a smaller --step or slower poles",
            how.method.name(),
            how.rtol,
            how.atol
        ));
    }
    let status = match run.fall {
        Some(t) => format!("fell at t = {t} s"),
        None => "completed".to_string(),
    };
    let rows: Vec<[f64; 10]> = run
        .iter()
        .map(|(t, x)| {
            let [tl, tr] = torques(x);
            [t, x[0], x[1], x[2], x[3], x[4], x[5], x[6], tl, tr]
        })
        .collect();
    let header = ["t"]
        .iter()
        .chain(STATE_NAMES.iter())
        .chain(["TL", "TR"].iter())
        .copied()
        .collect::<Vec<_>>();
    if let Some(path) = &c.csv {
        let mut text = header.join(",");
        text.push('\n');
        for r in &rows {
            text.push_str(&r.iter().map(|v| v.to_string()).collect::<Vec<_>>().join(","));
            text.push('\n');
        }
        std::fs::write(path, text)
            .map_err(|e| format!("invalid --csv `{}`: cannot write it: {e}", path.display()))?;
    }
    if c.json {
        let column = |k: usize| rows.iter().map(|r| r[k]).collect::<Vec<f64>>();
        let mut out = serde_json::Map::new();
        for (k, name) in header.iter().enumerate() {
            out.insert(name.to_string(), json!(column(k)));
        }
        out.insert("status".into(), json!(if run.fall.is_some() { "fell" } else { "completed" }));
        out.insert("fall_time".into(), json!(run.fall));
        out.insert("energy0".into(), json!(run.energy0));
        out.insert("max_energy_change".into(), json!(run.max_energy_drift));
        out.insert("gain".into(), json!(feedback.as_ref().map(|(k, _)| k.gain)));
        out.insert("poles".into(), json!(feedback.as_ref().and_then(|(_, p)| *p)));
        out.insert("steps".into(), json!(run.stats.steps));
        out.insert("rhs_evaluations".into(), json!(run.stats.rhs_evaluations));
        return serde_json::to_string(&serde_json::Value::Object(out)).map_err(|e| e.to_string());
    }
    Ok(render(c, &run, &feedback, &status, &rows, how.method.name()))
}

/// The text of a run.
fn render(
    c: &SimulateArgs,
    run: &Trajectory,
    feedback: &Option<Chosen>,
    status: &str,
    rows: &[[f64; 10]],
    method: &str,
) -> String {
    let mut s = format!(
        "wheeled pendulum, {}, upright at {} m/s, pitched {} rad, {method}, samples every {} s\n",
        c.design.describe(),
        c.design.speed,
        c.pitch0,
        c.step * c.every as f64
    );
    match feedback {
        None => s.push_str("open loop (motors off)\n"),
        Some((k, poles)) => {
            if let Some(p) = poles {
                let _ = writeln!(s, "feedback placed at poles {}, {}, {} 1/s", p[0], p[1], p[2]);
            }
            gain_text(&mut s, k);
        }
    }
    let _ = writeln!(s, "status: {status}");
    let _ = writeln!(
        s,
        "{} steps ({} rejected), {} right-hand side evaluations",
        run.stats.steps, run.stats.rejected_steps, run.stats.rhs_evaluations
    );
    let change = if feedback.is_some() {
        "largest energy change (the motors' work)"
    } else {
        "relative energy drift"
    };
    let value = if feedback.is_some() { run.max_energy_drift } else { run.relative_energy_drift() };
    let _ = writeln!(s, "{change} {value:.1e}{}", if feedback.is_some() { " J" } else { "" });
    if let Some(path) = &c.csv {
        let _ = writeln!(s, "wrote {} samples to {}", rows.len(), path.display());
        return s;
    }
    s.push_str(
        "    t        x        y      psi    theta   thetad  thetaLd  thetaRd       TL       TR\n",
    );
    for r in rows {
        // Rounding leaves the heading and the sideways drift of a straight run at 1e-17, which
        // would print as -0.0000 on one platform and +0.0000 on another.
        let r = r.map(|v| if v.abs() < 1e-9 { 0.0 } else { v });
        let _ = writeln!(
            s,
            "{:5.2} {:+8.4} {:+8.4} {:+8.4} {:+8.4} {:+8.4} {:+8.4} {:+8.4} {:+8.2} {:+8.2}",
            r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], r[9]
        );
    }
    s
}
