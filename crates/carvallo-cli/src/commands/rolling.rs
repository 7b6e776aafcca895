//! `carvallo hoop` and `carvallo unicycle`: the rolling hoop (memoir n° 7, system (2)) and the
//! mounted unicycle (n° 21–24, no motor moment) integrated from the lean `--theta0` and the
//! rates `--p0`, `--n0`, `--s0` of the state $(\theta, p, n, s)$ over `--duration` seconds, by
//! RK4 at `--step` (0.001 s by default) or by an error-controlled pair (`--method dopri5`,
//! `dop853`, `vern9` with `--rtol`, `--atol` as on `simulate`) sampled from its dense output,
//! printed every `--every` steps; `--stop-when NAME=VALUE` or `NAME=±VALUE` (NAME one of
//! `theta`, `p`, `n`, `s`) ends the run when the component crosses VALUE or its magnitude
//! reaches it, the time located on the interpolant. The text gives the counts, the relative
//! energy drift (the motion conserves energy, n° 7) and the samples; `--json` the arrays `t`,
//! `theta`, `p`, `n`, `s` with `energy_drift`, `relative_energy_drift`, `method`, `rtol`,
//! `atol`, `rhs_evaluations`, `steps`, `rejected_steps`, `events` and `interrupted`. Ctrl-C
//! ends a run within a step: the samples so far and the line `interrupted at t = T s` (the
//! string in `interrupted`, null otherwise), exit code 0, as an interrupted sweep.
//!
//! The hoop's radius, mass and gravity have defaults (0.5 m, 1 kg, 9.81 m/s²; its motion does
//! not depend on the mass); the unicycle's rider (n° 21: `--rider-mass`, `--rider-height`,
//! `--rider-a`, `--rider-b`, `--rider-c`, `--rider-l`) and wheel (`--wheel-mass`, a thin hoop of
//! the wheel's radius) are required. The models are the runtime's ([`carvallo::hoop::Hoop`],
//! [`carvallo::unicycle::Unicycle`], `simulate_with`). Unknown, repeated or missing arguments,
//! non-finite numbers, invalid parameters and a failed integration are errors naming the value,
//! exit code 2.

use carvallo::hoop::{Hoop, Trajectory};
use carvallo::numerics::integrate::{Grid, Integration, Threshold};
use carvallo::unicycle::{Rider, Unicycle, Wheel};
use serde_json::json;

use super::simulate::ToleranceArgs;
use crate::args::{finite, ANGLE, GRAVITY, INERTIA, LENGTH, MASS, MASS_OR_ZERO, PRODUCT, RATE};

/// The names of the state's components, in its order.
const STATE: [&str; 4] = ["theta", "p", "n", "s"];

/// A positive count.
fn positive(v: &str) -> Result<usize, String> {
    v.parse().ok().filter(|n| *n > 0).ok_or_else(|| "must be a positive integer".to_string())
}

/// A stop condition on a component of the state.
fn parse_threshold(text: &str) -> Result<Threshold, String> {
    Threshold::parse(text, &STATE).ok_or_else(|| {
        "expected NAME=VALUE or NAME=±VALUE with NAME one of theta, p, n, s and a finite VALUE \
         (non-negative after ±)"
            .to_string()
    })
}

/// The start, the run's length and how to integrate: the options both commands share.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct RunArgs {
    /// The initial lean θ (rad)
    #[arg(long, value_name = "RAD", value_parser = ANGLE.parser(), allow_hyphen_values = true)]
    pub theta0: f64,
    /// The initial rate s in rad/s (the rolling rate of n° 7; the rate unit is sqrt(g/R))
    #[arg(long, value_name = "RAD/S", value_parser = RATE.parser(), allow_hyphen_values = true)]
    pub s0: f64,
    /// The initial lean rate p (rad/s)
    #[arg(long, value_name = "RAD/S", default_value_t = 0.0, value_parser = RATE.parser(), allow_hyphen_values = true)]
    pub p0: f64,
    /// The initial rate n in rad/s (the turning rate of n° 7)
    #[arg(long, value_name = "RAD/S", default_value_t = 0.0, value_parser = RATE.parser(), allow_hyphen_values = true)]
    pub n0: f64,
    /// How long to simulate (s)
    #[arg(long, value_name = "S", value_parser = finite, allow_hyphen_values = true)]
    pub duration: f64,
    /// The RK4 step in s (for an adaptive method, the grid of the printed times)
    #[arg(long, value_name = "DT", default_value_t = 0.001, value_parser = finite, allow_hyphen_values = true)]
    pub step: f64,
    /// Print every N-th step (for an adaptive method, the dense output every N × DT seconds)
    #[arg(long, value_name = "N", default_value_t = 10, value_parser = positive)]
    pub every: usize,
    #[command(flatten)]
    pub tolerance: ToleranceArgs,
    /// Stop when NAME (theta, p, n, s) crosses VALUE, or when its magnitude reaches VALUE
    /// (NAME=±VALUE or NAME=+-VALUE); may be repeated
    #[arg(long = "stop-when", value_name = "NAME=VALUE", value_parser = parse_threshold, allow_hyphen_values = true)]
    pub stop_when: Vec<Threshold>,
    /// Print JSON (the samples, the energy drift, the counts and the events) instead of text
    #[arg(long)]
    pub json: bool,
}

impl RunArgs {
    /// The integration and the grid, or an error naming the bad value.
    fn plan(&self) -> Result<(Integration, Grid), String> {
        let how = self.tolerance.integration()?;
        let grid = Grid::new(self.duration, self.step, self.every)
            .map_err(|(name, value, reason)| format!("invalid --{name} {value:?}: {reason}"))?;
        Ok((how, grid))
    }

    /// The initial state $(\theta, p, n, s)$.
    fn start(&self) -> [f64; 4] {
        [self.theta0, self.p0, self.n0, self.s0]
    }

    /// The run printed: `title` first in the text. A run whose state stops being finite (the
    /// integration diverged) is an error naming the step and the method.
    fn render(&self, title: &str, how: &Integration, tr: &Trajectory) -> Result<String, String> {
        let bad = tr.times.iter().zip(&tr.samples).find(|(_, x)| x.iter().any(|v| !v.is_finite()));
        if let Some((t, _)) = bad {
            return Err(format!(
                "the integration diverged: the state is not finite at t = {t} s (--method {}{}); \
                 take a smaller --step or an adaptive --method",
                how.method.name(),
                if how.method.is_adaptive() {
                    String::new()
                } else {
                    format!(", --step {}", self.step)
                }
            ));
        }
        let texts: Vec<String> = self.stop_when.iter().map(|t| t.text(&STATE)).collect();
        let adaptive = how.method.is_adaptive();
        if self.json {
            let column = |k: usize| tr.samples.iter().map(|x| x[k]).collect::<Vec<f64>>();
            let events: Vec<_> =
                tr.event.iter().map(|&(k, t)| json!({"when": texts[k], "t": t})).collect();
            let out = json!({
                "t": tr.times,
                "theta": column(0),
                "p": column(1),
                "n": column(2),
                "s": column(3),
                "energy_drift": tr.diagnostics.max_energy_drift,
                "relative_energy_drift": tr.diagnostics.relative_energy_drift(),
                "method": how.method.name(),
                "rtol": adaptive.then_some(how.rtol),
                "atol": adaptive.then_some(how.atol),
                "rhs_evaluations": tr.stats.rhs_evaluations,
                "steps": tr.stats.steps,
                "rejected_steps": tr.stats.rejected_steps,
                "events": events,
                "interrupted": tr.interrupted.map(interrupted_line),
            });
            return serde_json::to_string(&out).map_err(|e| e.to_string());
        }
        let method = if adaptive {
            format!("{} rtol {:e} atol {:e}", how.method, how.rtol, how.atol)
        } else {
            format!("rk4 step {} s", self.step)
        };
        let mut s = format!(
            "{title}, from theta {} rad, p {}, n {}, s {} rad/s, {method}, samples every {} s\n",
            self.theta0,
            self.p0,
            self.n0,
            self.s0,
            self.step * self.every as f64
        );
        s.push_str(&format!(
            "{} steps ({} rejected), {} right-hand side evaluations\n",
            tr.stats.steps, tr.stats.rejected_steps, tr.stats.rhs_evaluations
        ));
        s.push_str(&format!(
            "relative energy drift {:.1e}\n",
            tr.diagnostics.relative_energy_drift()
        ));
        if let Some((k, t)) = tr.event {
            s.push_str(&format!("stopped at t = {t} s: {}\n", texts[k]));
        }
        if let Some(t) = tr.interrupted {
            s.push_str(&format!("{}\n", interrupted_line(t)));
        }
        s.push_str(" t        theta      p          n          s\n");
        for (t, x) in tr.times.iter().zip(&tr.samples) {
            s.push_str(&format!("{t:8.3} {:+.6} {:+.6} {:+.6} {:+.6}\n", x[0], x[1], x[2], x[3]));
        }
        Ok(s)
    }
}

/// The line of a run that Ctrl-C ended at `t` (its samples are those up to then; exit 0, as
/// an interrupted sweep).
pub(crate) fn interrupted_line(t: f64) -> String {
    format!("interrupted at t = {t} s")
}

/// `carvallo hoop`: the rolling hoop simulated.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct HoopArgs {
    /// The hoop's radius R (m)
    #[arg(long, value_name = "M", default_value_t = 0.5, value_parser = LENGTH.parser(), allow_hyphen_values = true)]
    pub radius: f64,
    /// The hoop's mass (kg)
    #[arg(long, value_name = "KG", default_value_t = 1.0, value_parser = MASS.parser(), allow_hyphen_values = true)]
    pub mass: f64,
    /// Gravity (m/s²)
    #[arg(long, value_name = "M/S2", default_value_t = 9.81, value_parser = GRAVITY.parser(), allow_hyphen_values = true)]
    pub g: f64,
    #[command(flatten)]
    pub run: RunArgs,
}

/// Runs `carvallo hoop`: the text to print, or an error naming the bad value.
pub fn hoop(c: &HoopArgs) -> Result<String, String> {
    let hoop = Hoop::new(c.radius, c.mass, c.g).map_err(|e| e.to_string())?;
    let (how, grid) = c.run.plan()?;
    let stop = crate::interrupt::interrupt_flag();
    let tr = hoop
        .simulate_until(c.run.start(), &grid, &how, &c.run.stop_when, stop)
        .map_err(|e| e.to_string())?;
    let title = format!("rolling hoop R {} m, mass {} kg, g {} m/s^2", c.radius, c.mass, c.g);
    c.run.render(&title, &how, &tr)
}

/// `carvallo unicycle`: the mounted unicycle simulated.
#[derive(Clone, Debug, PartialEq, clap::Args)]
pub struct UnicycleArgs {
    /// The wheel's radius R (m)
    #[arg(long, value_name = "M", value_parser = LENGTH.parser(), allow_hyphen_values = true)]
    pub radius: f64,
    /// Gravity (m/s²)
    #[arg(long, value_name = "M/S2", default_value_t = 9.81, value_parser = GRAVITY.parser(), allow_hyphen_values = true)]
    pub g: f64,
    /// The rider's mass μ (kg)
    #[arg(long, value_name = "KG", value_parser = MASS.parser(), allow_hyphen_values = true)]
    pub rider_mass: f64,
    /// The height of the rider's centre of gravity on Ok (m)
    #[arg(long, value_name = "M", value_parser = LENGTH.parser(), allow_hyphen_values = true)]
    pub rider_height: f64,
    /// The rider's A = Σ m(η² + ζ²) in kg m²
    #[arg(long, value_name = "KG_M2", value_parser = INERTIA.parser(), allow_hyphen_values = true)]
    pub rider_a: f64,
    /// The rider's B = Σ m(ζ² + ξ²) in kg m²
    #[arg(long, value_name = "KG_M2", value_parser = INERTIA.parser(), allow_hyphen_values = true)]
    pub rider_b: f64,
    /// The rider's C = Σ m(ξ² + η²) in kg m²
    #[arg(long, value_name = "KG_M2", value_parser = INERTIA.parser(), allow_hyphen_values = true)]
    pub rider_c: f64,
    /// The rider's L = Σ m ζ ξ (kg m²)
    #[arg(long, value_name = "KG_M2", default_value_t = 0.0, value_parser = PRODUCT.parser(), allow_hyphen_values = true)]
    pub rider_l: f64,
    /// The wheel's mass in kg (a thin hoop of radius R: A1 = 1.5 m R², B1 = 2 m R², C1 = 0.5 m R²)
    #[arg(long, value_name = "KG", value_parser = MASS_OR_ZERO.parser(), allow_hyphen_values = true)]
    pub wheel_mass: f64,
    #[command(flatten)]
    pub run: RunArgs,
}

/// Runs `carvallo unicycle`: the text to print, or an error naming the bad value.
pub fn unicycle(c: &UnicycleArgs) -> Result<String, String> {
    let rider = Rider {
        mass: c.rider_mass,
        height: c.rider_height,
        a: c.rider_a,
        b: c.rider_b,
        c: c.rider_c,
        l: c.rider_l,
    };
    let u = Unicycle::new(c.radius, c.g, rider, Wheel::hoop(c.wheel_mass, c.radius))
        .map_err(|e| e.to_string())?;
    let (how, grid) = c.run.plan()?;
    let stop = crate::interrupt::interrupt_flag();
    let tr = u
        .simulate_until(c.run.start(), &grid, &how, &c.run.stop_when, stop)
        .map_err(|e| e.to_string())?;
    let title = format!(
        "unicycle R {} m, g {} m/s^2, rider {} kg at {} m (A {}, B {}, C {}, L {} kg m^2), wheel {} kg",
        c.radius,
        c.g,
        c.rider_mass,
        c.rider_height,
        c.rider_a,
        c.rider_b,
        c.rider_c,
        c.rider_l,
        c.wheel_mass
    );
    c.run.render(&title, &how, &tr)
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::args::parse;
    use crate::commands::simulate::MethodArg;

    #[test]
    fn parses_and_rejects_by_value() {
        let a = parse::<HoopArgs>(&[
            "hoop",
            "--theta0",
            "0.1",
            "--s0",
            "2",
            "--duration",
            "1",
            "--method",
            "vern9",
            "--stop-when",
            "theta=±0.5",
        ])
        .expect("parse");
        assert_eq!((a.radius, a.mass, a.g, a.run.every), (0.5, 1.0, 9.81, 10));
        assert_eq!(a.run.stop_when, [Threshold { index: 0, value: 0.5, magnitude: true }]);
        assert_eq!(a.run.tolerance.method, MethodArg::Vern9);
        for (words, msg) in [
            (vec!["hoop", "--s0", "1", "--duration", "1"], "--theta0 <RAD>"),
            (
                vec![
                    "hoop",
                    "--theta0",
                    "0",
                    "--s0",
                    "1",
                    "--duration",
                    "1",
                    "--stop-when",
                    "lean=1",
                ],
                "invalid value 'lean=1' for '--stop-when <NAME=VALUE>': expected NAME=VALUE",
            ),
            (
                vec![
                    "hoop",
                    "--theta0",
                    "0",
                    "--s0",
                    "1",
                    "--duration",
                    "1",
                    "--stop-when",
                    "s=±-1",
                ],
                "non-negative after ±",
            ),
            (
                vec!["hoop", "--theta0", "nan", "--s0", "1", "--duration", "1"],
                "invalid value 'nan' for '--theta0 <RAD>': must be finite",
            ),
            (vec!["unicycle", "--radius", "0.5"], "--rider-mass <KG>"),
        ] {
            let e = if words[0] == "hoop" {
                parse::<HoopArgs>(&words).unwrap_err()
            } else {
                parse::<UnicycleArgs>(&words).unwrap_err()
            };
            assert!(e.contains(msg), "{words:?}: {e}");
        }
    }

    /// The text and the JSON of one run say the same; the event ends both.
    #[test]
    fn text_and_json_agree() {
        let words = [
            "hoop",
            "--theta0",
            "0.1",
            "--s0",
            "2.2",
            "--duration",
            "5",
            "--method",
            "dop853",
            "--rtol",
            "1e-10",
            "--stop-when",
            "theta=±0.5",
        ];
        let text = hoop(&parse::<HoopArgs>(&words).expect("parse")).expect("run");
        let json = hoop(&parse::<HoopArgs>(&[&words[..], &["--json"]].concat()).expect("parse"))
            .expect("run");
        let v: serde_json::Value = serde_json::from_str(&json).expect("json");
        let t = v["events"][0]["t"].as_f64().expect("an event");
        assert_eq!(v["events"][0]["when"], "theta=±0.5");
        assert!(text.contains(&format!("stopped at t = {t} s: theta=±0.5")), "{text}");
        let theta = v["theta"].as_array().expect("theta");
        assert_eq!(theta.len(), text.lines().count() - 5);
        assert!((theta.last().and_then(|x| x.as_f64()).expect("last").abs() - 0.5).abs() < 1e-9);
        assert_eq!(v["method"], "dop853");
        // The bad values of the run itself.
        // Outside the numerically valid ranges: the option and the range named.
        let bad = ["hoop", "--theta0", "0", "--s0", "1", "--duration", "1", "--radius", "-1"];
        let e = parse::<HoopArgs>(&bad).unwrap_err();
        assert!(e.contains("'-1' for '--radius <M>': must lie within [1e-6, 1e6]"), "{e}");
        let bad = ["hoop", "--theta0", "0", "--s0", "1e7", "--duration", "1"];
        let e = parse::<HoopArgs>(&bad).unwrap_err();
        assert!(e.contains("'1e7' for '--s0 <RAD/S>': must lie within [-1e6, 1e6]"), "{e}");
        // Inside them, a step too long for the rates: the run diverges, said so.
        let bad = ["hoop", "--theta0", "0.1", "--s0", "3", "--p0", "1e6", "--duration", "0.05"];
        let e = hoop(&parse::<HoopArgs>(&bad).expect("parse")).unwrap_err();
        assert!(e.starts_with("the integration diverged: the state is not finite at t = "), "{e}");
        assert!(
            e.ends_with(
                "(--method rk4, --step 0.001); take a smaller --step or an adaptive --method"
            ),
            "{e}"
        );
        let bad = ["hoop", "--theta0", "0", "--s0", "1", "--duration", "1", "--rtol", "1e-8"];
        let e = hoop(&parse::<HoopArgs>(&bad).expect("parse")).unwrap_err();
        assert!(e.contains("invalid --rtol"), "{e}");
    }
}
