//! What every table of `carvallo bench` shares: how much to measure ([`Config`]), the rows,
//! distributions and targets it reports, the timer ([`time_ns`]) and the random designs and
//! relative errors the sections compute with. It sits below [`super::tables`],
//! [`super::quartic`], [`super::certified`] and [`super::simulation`], which use it and not
//! each other; the rows of the simulations are defined here, with the report that holds them.

use std::hint::black_box;
use std::time::Instant;

use carvallo::numerics::rng::SplitMix64;
use carvallo::whipple::{Matrices, Whipple, WhippleParams};
use serde::Serialize;

/// The precision of every reference evaluation.
pub const REFERENCE_BITS: usize = 256;

/// How much to measure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Config {
    /// Minimum wall-clock time per timed measurement, in seconds.
    pub min_time: f64,
    /// Random points per evaluator for the error columns.
    pub points: usize,
    /// Random bicycle designs for the window errors.
    pub designs: usize,
    /// Random parameter sets of the error distributions.
    pub samples: usize,
    /// Designs of the Hurwitz sweep.
    pub sweep_count: usize,
    /// Designs of the eigenvalue sweep.
    pub eigen_sweep_count: usize,
}

impl Config {
    /// The full measurement: $10^6$ samples, $4 \cdot 10^6$ sweep designs (the size of issue
    /// 22's rate targets) (5 to 15 minutes on a busy 2-core machine).
    pub fn full() -> Config {
        Config {
            min_time: 0.2,
            points: 200,
            designs: 200,
            samples: 1_000_000,
            sweep_count: 4_000_000,
            eigen_sweep_count: 2_000,
        }
    }

    /// A quick run on tiny samples (seconds), for tests of the structure and the errors.
    pub fn quick() -> Config {
        Config {
            min_time: 0.002,
            points: 4,
            designs: 4,
            samples: 100,
            sweep_count: 100_000,
            eigen_sweep_count: 4,
        }
    }
}

/// One measured row.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Row {
    /// The table: `evaluators`, `windows`, `quartic`, `certified`, `scenes`, `sweep`.
    pub section: &'static str,
    /// What was measured.
    pub name: String,
    /// The method.
    pub method: String,
    /// Operations per evaluation, where that is meaningful.
    pub ops: Option<u64>,
    /// Mean wall-clock nanoseconds per evaluation (per design, per polynomial).
    pub ns: Option<f64>,
    /// The largest relative error against the 256-bit reference.
    pub max_rel_err: Option<f64>,
    /// Details.
    pub note: String,
}

/// An error distribution.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Distribution {
    /// The output.
    pub name: String,
    /// How many samples.
    pub samples: usize,
    /// Relative errors in units of $\varepsilon = 2^{-52}$: median, 99 %, 99.99 %, maximum.
    pub p50: f64,
    /// 99th percentile.
    pub p99: f64,
    /// 99.99th percentile.
    pub p9999: f64,
    /// Maximum.
    pub max: f64,
}

/// A target of the issue against the measured value.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Target {
    /// The target, in words.
    pub name: String,
    /// The measured value.
    pub measured: f64,
    /// The required value.
    pub required: f64,
    /// Whether it is met.
    pub met: bool,
}

/// Everything one run measured.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Report {
    /// `quick` or `full`.
    pub mode: &'static str,
    /// The measured rows.
    pub rows: Vec<Row>,
    /// The error distributions.
    pub distributions: Vec<Distribution>,
    /// The targets.
    pub targets: Vec<Target>,
    /// The work-precision rows of the simulations ([`super::simulation`]).
    pub simulation: Vec<SimulationRow>,
    /// The simulations' reference solutions and their independent checks.
    pub simulation_references: Vec<SimulationReference>,
}

/// One work-precision row of the section `simulation` ([`super::simulation`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SimulationRow {
    /// The simulated motion.
    pub problem: String,
    /// `rk4`, `dopri5`, `dop853` or `vern9`.
    pub method: &'static str,
    /// The relative tolerance (adaptive methods; atol is 1e-3 of it).
    pub rtol: Option<f64>,
    /// The step (RK4).
    pub step: Option<f64>,
    /// Right-hand side evaluations.
    pub rhs_evaluations: usize,
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps.
    pub rejected_steps: usize,
    /// Wall time of one simulation (ns): for the bicycle without computing its samples
    /// (`simulate_final`), for the hoop and the unicycle with them.
    pub ns: f64,
    /// Error of the final state against the reference.
    pub error_final: f64,
    /// Largest error over the samples against the reference's.
    pub error_dense: f64,
    /// Largest energy drift over the accepted steps (J).
    pub energy_drift: f64,
    /// Largest contact constraint residual (m, bicycle only).
    pub constraint_residual: Option<f64>,
    /// The event's time error (s, the fall only).
    pub event_time_error: Option<f64>,
}

/// A reference solution and its check by a second method.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SimulationReference {
    /// The simulated motion.
    pub problem: String,
    /// How the reference is computed.
    pub reference: String,
    /// The independent check.
    pub check: String,
    /// The largest error (as the rows') between the two over the samples.
    pub agreement: f64,
    /// The same against DOPRI5 at rtol 1e-14 (same crate, another pair): over long runs RK4's
    /// hundreds of thousands of additions onto the growing wheel angles limit its agreement.
    pub agreement_dopri5: f64,
    /// The event time of the reference (the fall only).
    pub event_time: Option<f64>,
}

/// The targets as a list (see [`Report::targets`]).
pub type Targets = Vec<Target>;

/// Nanoseconds per call of `f`: the smallest of five means, each over calls lasting at least
/// `min_time / 5` seconds (the minimum is the estimate least disturbed by other processes on a
/// shared machine).
pub fn time_ns<R>(min_time: f64, mut f: impl FnMut() -> R) -> f64 {
    let slice = min_time / 5.0;
    let mut n = 1u64;
    let mut best = f64::INFINITY;
    let mut rounds = 0;
    while rounds < 5 {
        let t = Instant::now();
        for _ in 0..n {
            black_box(f());
        }
        let dt = t.elapsed().as_secs_f64();
        if dt >= slice || n >= 1 << 40 {
            best = best.min(dt * 1e9 / n as f64);
            rounds += 1;
        } else if dt <= 0.0 {
            n *= 16;
        } else {
            n = (n as f64 * (1.2 * slice / dt).min(16.0)) as u64 + 1;
        }
    }
    best
}

/// [`time_ns`] of several functions, interleaved: `rounds` rounds, each timing every function
/// in turn over `min_time` seconds; each function's least time over the rounds. Functions
/// compared with each other are then timed under the same load, which other work on a shared
/// machine changes from one moment to the next (timed one after the other, a ratio moved by
/// up to 2x between runs on the loaded 2-core machine).
pub fn time_ns_interleaved<const K: usize>(
    min_time: f64,
    rounds: usize,
    mut fs: [&mut dyn FnMut(); K],
) -> [f64; K] {
    let mut best = [f64::INFINITY; K];
    for _ in 0..rounds.max(1) {
        for (b, f) in best.iter_mut().zip(fs.iter_mut()) {
            *b = b.min(time_ns(min_time, &mut **f));
        }
    }
    best
}

/// A valid random bicycle: the benchmark with every parameter scaled by a factor in
/// [0.8, 1.2] ([`WhippleParams::perturbed`]).
pub fn random_design(rng: &mut SplitMix64) -> WhippleParams {
    WhippleParams::benchmark().perturbed(rng, 0.2)
}

/// Relative error of `x` against `reference` (absolute when the reference is zero).
pub fn rel(x: f64, reference: f64) -> f64 {
    if reference == 0.0 {
        x.abs()
    } else {
        ((x - reference) / reference).abs()
    }
}

/// The matrices of `w` and its gravity $g$, as the window routes take them.
pub fn matrices_of(w: &Whipple) -> (Matrices, f64) {
    (w.matrices(), w.params().get("g").unwrap_or(f64::NAN))
}
