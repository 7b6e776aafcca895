//! Sweeps of the stability window over many designs of the linearised Carvallo–Whipple bicycle.
//!
//! [`sweep`] computes the window for `count` designs that vary one parameter linearly between
//! two values, in parallel with rayon, and summarises them ([`SweepSummary`]).
//! [`sweep_designs`] does the same for a grid of several parameters or for seeded random designs
//! around a base ([`Designs`]), optionally keeping every design's varied values and window
//! ([`SweepOutput`]). Both evaluate the matrices four designs per call
//! (`matrices_scene::eval_lanes`, bit for bit the scalar evaluator lane by lane) and keep of each
//! window only [`hurwitz_window_summary`] (the same code as [`hurwitz_window`] without the
//! allocation of the stable intervals), computed for the same four designs at once without a
//! branch per design ([`hurwitz_window_summary_lanes`], equal to it design by design), so that
//! the Hurwitz sweep never drops to scalar code per design.
//!
//! The designs stream through the evaluators in blocks of [`BLOCK`] (parallel within a block)
//! into a running summary, so memory does not depend on the number of designs;
//! [`sweep_stream`] hands each block's designs to a callback (a CSV writer) and stops early
//! when asked to (Ctrl-C), summarising the designs done.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Instant;

use rayon::prelude::*;

use super::matrices::{matrices_of, matrices_scene, scene_index};
use super::params::{
    point_like, skate_limit, valid_within, TriangleSlack, WhippleError, WhippleParams, PARAM_NAMES,
};
#[cfg(doc)]
use super::stability::hurwitz_window;
#[cfg(doc)]
use super::stability::hurwitz_window_summary;
use super::stability::{eigen_window, EigenGrid, WindowSummary};
use super::window_lanes::hurwitz_window_summary_lanes;
use crate::numerics::rng::SplitMix64;

/// How [`sweep`] computes each design's window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// [`hurwitz_window`].
    Hurwitz,
    /// [`eigen_window`] on the default grid.
    Eigen,
}

/// What one varied parameter does to the stability window over a sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepSummary {
    /// The number of designs.
    pub count: usize,
    /// Wall-clock seconds for the whole sweep (matrices and windows).
    pub elapsed: f64,
    /// `count / elapsed`.
    pub designs_per_second: f64,
    /// How many designs have a non-empty stable speed range.
    pub stable: usize,
    /// How many designs have a weave speed.
    pub with_weave: usize,
    /// How many designs have a capsize speed.
    pub with_capsize: usize,
    /// The lowest and highest weave speed over the designs that have one.
    pub weave_range: Option<(f64, f64)>,
    /// The lowest and highest capsize speed over the designs that have one.
    pub capsize_range: Option<(f64, f64)>,
    /// How many designs the eigenvalue route could not compute (always 0 for Hurwitz).
    pub failed: usize,
}

/// Why a sweep could not run.
#[derive(Clone, Debug, PartialEq)]
pub enum SweepError {
    /// The parameter to vary is not one of [`PARAM_NAMES`].
    UnknownParameter {
        /// The name given.
        name: String,
    },
    /// Zero designs were asked for.
    InvalidCount {
        /// The count given.
        count: usize,
    },
    /// An end of the range makes an invalid bicycle.
    InvalidDesign(WhippleError),
}

impl std::fmt::Display for SweepError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SweepError::UnknownParameter { name } => write!(f, "unknown parameter {name}"),
            SweepError::InvalidCount { count } => {
                write!(f, "invalid count {count}: must be at least 1")
            }
            SweepError::InvalidDesign(e) => write!(f, "invalid design at an end of the range: {e}"),
        }
    }
}

impl std::error::Error for SweepError {}

/// Per-design results folded over a chunk.
#[derive(Clone, Copy, Debug)]
struct Acc {
    stable: usize,
    weave: usize,
    capsize: usize,
    failed: usize,
    weave_range: (f64, f64),
    capsize_range: (f64, f64),
}

impl Acc {
    const EMPTY: Acc = Acc {
        stable: 0,
        weave: 0,
        capsize: 0,
        failed: 0,
        weave_range: (f64::INFINITY, f64::NEG_INFINITY),
        capsize_range: (f64::INFINITY, f64::NEG_INFINITY),
    };

    fn add(mut self, w: Option<&WindowSummary>) -> Acc {
        let Some(w) = w else {
            self.failed += 1;
            return self;
        };
        self.stable += usize::from(w.stable);
        if let Some(x) = w.weave_speed {
            self.weave += 1;
            self.weave_range = (self.weave_range.0.min(x), self.weave_range.1.max(x));
        }
        if let Some(x) = w.capsize_speed {
            self.capsize += 1;
            self.capsize_range = (self.capsize_range.0.min(x), self.capsize_range.1.max(x));
        }
        self
    }

    fn merge(self, o: Acc) -> Acc {
        Acc {
            stable: self.stable + o.stable,
            weave: self.weave + o.weave,
            capsize: self.capsize + o.capsize,
            failed: self.failed + o.failed,
            weave_range: (
                self.weave_range.0.min(o.weave_range.0),
                self.weave_range.1.max(o.weave_range.1),
            ),
            capsize_range: (
                self.capsize_range.0.min(o.capsize_range.0),
                self.capsize_range.1.max(o.capsize_range.1),
            ),
        }
    }
}

/// Computes the window of `count` designs equal to `base` except that `name` runs linearly from
/// `from` to `to` (both included; `count = 1` takes `from`), in parallel. `progress` is
/// increased by the number of designs done as chunks finish (for a progress bar).
///
/// Both ends are validated with [`WhippleParams::from_values`]; every check there confines one
/// parameter to an interval, so the designs in between are valid too and are not checked again.
/// The same as [`sweep_designs`] with one [`Vary`].
///
/// # Errors
/// [`SweepError`] for an unknown name, a zero count or an invalid end of the range.
pub fn sweep(
    base: &WhippleParams,
    name: &str,
    from: f64,
    to: f64,
    count: usize,
    method: Method,
    progress: &AtomicUsize,
) -> Result<SweepSummary, SweepError> {
    let designs = Designs::Grid(vec![Vary { name: name.to_string(), from, to, count }]);
    match sweep_designs(base, &designs, method, false, progress) {
        Ok(out) => Ok(out.summary),
        Err(DesignsError::Sweep(e)) => Err(e),
        // A grid of one axis has no spread, no repeated parameter, is not empty and its count
        // fits: only `DesignsError::Sweep` can occur; any other is reported by its text.
        Err(e) => Err(SweepError::UnknownParameter { name: e.to_string() }),
    }
}

/// One axis of a grid: `count` values of parameter `name` from `from` to `to` (both included;
/// `count = 1` takes `from`), $x_i = \text{from} + (\text{to} - \text{from})\,i/(\text{count}-1)$
/// and the last exactly `to`.
#[derive(Clone, Debug, PartialEq)]
pub struct Vary {
    /// The parameter, one of [`PARAM_NAMES`].
    pub name: String,
    /// The first value.
    pub from: f64,
    /// The last value.
    pub to: f64,
    /// The number of values.
    pub count: usize,
}

impl Vary {
    /// The `i`-th value.
    fn at(&self, i: usize) -> f64 {
        if self.count == 1 {
            self.from
        } else if i + 1 == self.count {
            self.to
        } else {
            self.from + (self.to - self.from) * (i as f64 / (self.count - 1) as f64)
        }
    }
}

/// A random perturbation: parameter `name` times a uniform factor in $[1 - r, 1 + r]$.
#[derive(Clone, Debug, PartialEq)]
pub struct Spread {
    /// The parameter, one of [`PARAM_NAMES`].
    pub name: String,
    /// The relative spread $r$, in $[0, 1)$.
    pub rel: f64,
}

/// The designs of [`sweep_designs`].
#[derive(Clone, Debug, PartialEq)]
pub enum Designs {
    /// Every combination of the axes' values; the first axis varies slowest (design
    /// $i = (i_1 n_2 + i_2) n_3 + i_3 \dots$).
    Grid(Vec<Vary>),
    /// `count` designs around the base, each parameter of `spreads` scaled independently, drawn
    /// from the seeded stream [`SplitMix64`] of design $i$ (seed
    /// `seed + i`), so that the designs do not depend on the number of threads. A draw that
    /// [`WhippleParams::from_values_within`] rejects, with the slack that admits the base
    /// ([`TriangleSlack::admitting`]: a draw may break a triangle inequality of the moments of
    /// inertia by as much as the base does, not more), is redrawn from the same stream, at most
    /// [`MAX_DRAWS`] times; a design still invalid then is counted as rejected.
    Random {
        /// The number of designs.
        count: usize,
        /// The perturbed parameters.
        spreads: Vec<Spread>,
        /// The seed.
        seed: u64,
    },
}

/// The most draws of one random design (see [`Designs::Random`]).
pub const MAX_DRAWS: usize = 100;

/// Why [`sweep_designs`] could not run.
#[derive(Clone, Debug, PartialEq)]
pub enum DesignsError {
    /// An unknown parameter, a zero count or an invalid corner of a grid.
    Sweep(SweepError),
    /// A parameter given twice.
    DuplicateParameter {
        /// The name.
        name: String,
    },
    /// A spread outside $[0, 1)$.
    InvalidSpread {
        /// The parameter.
        name: String,
        /// The spread given.
        rel: f64,
    },
    /// A grid with no axis.
    EmptyGrid,
    /// A grid whose product of counts does not fit a `usize`.
    TooManyDesigns {
        /// The counts of the axes, in order.
        counts: Vec<usize>,
    },
}

impl std::fmt::Display for DesignsError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            DesignsError::Sweep(e) => write!(f, "{e}"),
            DesignsError::DuplicateParameter { name } => {
                write!(f, "parameter {name} is varied more than once")
            }
            DesignsError::InvalidSpread { name, rel } => {
                write!(f, "invalid spread {rel} of {name}: must lie in [0, 1)")
            }
            DesignsError::EmptyGrid => write!(f, "no parameter to vary"),
            DesignsError::TooManyDesigns { counts } => {
                let counts: Vec<String> = counts.iter().map(usize::to_string).collect();
                write!(
                    f,
                    "too many designs: the grid's counts {} multiply to more than {}",
                    counts.join(" x "),
                    usize::MAX
                )
            }
        }
    }
}

impl std::error::Error for DesignsError {}

/// What [`sweep_designs`] found.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepOutput {
    /// The summary over the designs (rejected random designs not counted in `stable`, ...).
    pub summary: SweepSummary,
    /// The varied parameters, in the order of the axes or spreads.
    pub names: Vec<String>,
    /// With `record`: the varied parameters' values of design `i` at
    /// `values[i * names.len()..(i + 1) * names.len()]`; empty otherwise.
    pub values: Vec<f64>,
    /// With `record`: the window of design `i`, `None` when the eigenvalue route failed or the
    /// random design was rejected; empty otherwise.
    pub windows: Vec<Option<WindowSummary>>,
    /// With `record`: whether design `i` is valid (`false` for a rejected random design);
    /// empty otherwise.
    pub valid: Vec<bool>,
    /// How many random designs were rejected (for a grid, how many designs around a base with
    /// a point-mass frame have a singular mass matrix; otherwise 0).
    pub rejected: usize,
    /// The number of designs asked for; `summary.count` is smaller when the sweep was stopped
    /// early ([`sweep_stream`]).
    pub requested: usize,
}

/// The designs of one block of [`sweep_stream`], in order: designs `first..first + valid.len()`.
#[derive(Clone, Copy, Debug)]
pub struct SweepChunk<'a> {
    /// The index of the first design.
    pub first: usize,
    /// The varied parameters' values, `names.len()` per design.
    pub values: &'a [f64],
    /// The window of each design, as in [`SweepOutput::windows`].
    pub windows: &'a [Option<WindowSummary>],
    /// Whether each design is valid, as in [`SweepOutput::valid`].
    pub valid: &'a [bool],
}

/// The index in [`PARAM_NAMES`] of each name, each at most once.
fn param_indices<'a>(names: impl Iterator<Item = &'a str>) -> Result<Vec<usize>, DesignsError> {
    let mut out: Vec<usize> = Vec::new();
    for name in names {
        let k = PARAM_NAMES.iter().position(|n| *n == name).ok_or_else(|| {
            DesignsError::Sweep(SweepError::UnknownParameter { name: name.to_string() })
        })?;
        if out.contains(&k) {
            return Err(DesignsError::DuplicateParameter { name: name.to_string() });
        }
        out.push(k);
    }
    Ok(out)
}

/// The indices of IRxx, IRyy, IFxx, IFyy in [`PARAM_NAMES`]: the wheels' triangle inequalities
/// $I_{yy} \le 2 I_{xx}$ (within the slack) that [`valid_within`] checks.
const WHEELS: [usize; 4] = [6, 7, 24, 25];
const _: () = assert!(
    matches!(PARAM_NAMES[6].as_bytes(), b"IRxx")
        && matches!(PARAM_NAMES[7].as_bytes(), b"IRyy")
        && matches!(PARAM_NAMES[24].as_bytes(), b"IFxx")
        && matches!(PARAM_NAMES[25].as_bytes(), b"IFyy")
);

/// Designs processed per parallel task (a multiple of the lanes).
const CHUNK: usize = 4096;
/// Designs evaluated between two updates of the running summary (and two looks at the stop
/// flag of [`sweep_stream`]); only one block's results are held at a time.
pub const BLOCK: usize = 16 * CHUNK;
/// Designs per call of [`matrices_scene::eval_lanes`] and of [`hurwitz_window_summary_lanes`].
const LANES: usize = matrices_scene::LANES;
const _: () = assert!(LANES == super::window_lanes::LANES);

/// Computes the window of every design of `designs` (a grid or random designs around `base`),
/// in parallel with rayon, four designs per evaluation of the matrices
/// ([`matrices_scene::eval_lanes`], bit for bit the scalar evaluator, so the answers are those
/// of [`hurwitz_window`] or [`eigen_window`] design by design). With `record` the varied values
/// and the window of every design are kept in [`SweepOutput`]. `progress` is increased by the
/// number of designs done as chunks finish.
///
/// The corners of a grid are validated with [`WhippleParams::from_values_within`] and the
/// slack that admits the base ([`TriangleSlack::admitting`]): along one parameter its checks
/// are intervals or convex inequalities (positive values, triangle inequalities of the moments
/// of inertia), so every design of the grid is valid too. The exception is a base with a frame
/// of zero or singular inertia (a point mass, as the two-mass-skate's), whose mass matrix is
/// regular only where the masses sit right: there every design is checked, and those with a
/// singular mass matrix are counted in [`SweepOutput::rejected`].
///
/// # Errors
/// [`DesignsError`] for an unknown or repeated name, a zero count, an empty grid, an invalid
/// corner or spread.
pub fn sweep_designs(
    base: &WhippleParams,
    designs: &Designs,
    method: Method,
    record: bool,
    progress: &AtomicUsize,
) -> Result<SweepOutput, DesignsError> {
    let (mut values, mut windows, mut valid) = (Vec::new(), Vec::new(), Vec::new());
    let never = AtomicBool::new(false);
    let sink = |c: &SweepChunk<'_>| {
        values.extend_from_slice(c.values);
        windows.extend_from_slice(c.windows);
        valid.extend_from_slice(c.valid);
    };
    let sink: Option<&mut dyn FnMut(&SweepChunk<'_>)> =
        if record { Some(&mut { sink }) } else { None };
    let mut out = sweep_stream(base, designs, method, progress, &never, sink)?;
    (out.values, out.windows, out.valid) = (values, windows, valid);
    Ok(out)
}

/// [`sweep_designs`] in constant memory: the designs go through the evaluators in blocks of
/// [`BLOCK`] (in parallel within a block, in order from block to block), folded into the
/// summary, and with a `sink` each block's varied values and windows are handed to it in
/// order (nothing is kept: [`SweepOutput::values`], `windows` and `valid` are empty). `stop` is
/// read before every block: once it is set, the sweep ends and summarises the designs done
/// (`summary.count` less than [`SweepOutput::requested`]).
///
/// # Errors
/// As [`sweep_designs`].
pub fn sweep_stream(
    base: &WhippleParams,
    designs: &Designs,
    method: Method,
    progress: &AtomicUsize,
    stop: &AtomicBool,
    mut sink: Option<&mut dyn FnMut(&SweepChunk<'_>)>,
) -> Result<SweepOutput, DesignsError> {
    let record = sink.is_some();
    let base_values = *base.values();
    // A base that breaks a triangle inequality admits designs that break it no more.
    let slack = TriangleSlack::admitting(base);
    // With a frame of zero or singular inertia the mass matrix is regular only where the masses
    // sit right, which the corners do not decide: every design of the grid is checked.
    let check_each = point_like(&base_values);
    // Whether a design can have a zero wheel radius: the base has one, or a radius is varied.
    let skates = base_values[4] == 0.0
        || base_values[22] == 0.0
        || match designs {
            Designs::Grid(axes) => axes.iter().any(|a| a.name == "rR" || a.name == "rF"),
            Designs::Random { .. } => false,
        };
    let (names, keys, count): (Vec<String>, Vec<usize>, usize) = match designs {
        Designs::Grid(axes) => {
            if axes.is_empty() {
                return Err(DesignsError::EmptyGrid);
            }
            let keys = param_indices(axes.iter().map(|a| a.name.as_str()))?;
            let mut count = 1usize;
            for a in axes {
                if a.count == 0 {
                    return Err(DesignsError::Sweep(SweepError::InvalidCount { count: 0 }));
                }
                count = count.checked_mul(a.count).ok_or_else(|| DesignsError::TooManyDesigns {
                    counts: axes.iter().map(|a| a.count).collect(),
                })?;
            }
            // Every corner of the box (2^axes of them; the axes are few).
            for corner in 0..1usize << axes.len().min(20) {
                let mut v = base_values;
                for (j, (a, &k)) in axes.iter().zip(&keys).enumerate() {
                    v[k] = if corner >> j & 1 == 0 { a.from } else { a.to };
                }
                WhippleParams::from_values_within(v, &slack)
                    .map_err(|e| DesignsError::Sweep(SweepError::InvalidDesign(e)))?;
            }
            (axes.iter().map(|a| a.name.clone()).collect(), keys, count)
        }
        Designs::Random { count, spreads, .. } => {
            if *count == 0 {
                return Err(DesignsError::Sweep(SweepError::InvalidCount { count: 0 }));
            }
            let keys = param_indices(spreads.iter().map(|s| s.name.as_str()))?;
            for s in spreads {
                if !(0.0..1.0).contains(&s.rel) {
                    return Err(DesignsError::InvalidSpread { name: s.name.clone(), rel: s.rel });
                }
            }
            (spreads.iter().map(|s| s.name.clone()).collect(), keys, *count)
        }
    };
    // The draws of a random design that set a wheel's IRxx, IRyy, IFxx or IFyy: (position among
    // the spreads, position in WHEELS, spread).
    let wheel_draws: Vec<(usize, usize, f64)> = match designs {
        Designs::Random { spreads, .. } => keys
            .iter()
            .zip(spreads)
            .enumerate()
            .filter_map(|(p, (k, s))| {
                WHEELS.iter().position(|w| w == k).map(|slot| (p, slot, s.rel))
            })
            .collect(),
        Designs::Grid(_) => Vec::new(),
    };
    // Design i's parameter vector; false for a rejected random design.
    let fill = |i: usize, v: &mut [f64; 26]| -> bool {
        match designs {
            Designs::Grid(axes) => {
                let mut rest = i;
                for (a, &k) in axes.iter().zip(&keys).rev() {
                    v[k] = a.at(rest % a.count);
                    rest /= a.count;
                }
                !check_each || valid_within(v, &slack)
            }
            Designs::Random { spreads, seed, .. } => {
                let mut rng = SplitMix64(seed.wrapping_add(i as u64));
                for draw in 0..MAX_DRAWS {
                    // The wheels' triangle inequalities first, from the draws they need (the
                    // test that rejects most draws: the benchmark's wheels are almost thin
                    // discs); a draw that breaks one is rejected by `valid_within` too, so the
                    // rest of its values are skipped, not computed (but the last draw is
                    // computed whole: a rejected design reports its values).
                    if !wheel_draws.is_empty() && draw + 1 < MAX_DRAWS {
                        let mut w = WHEELS.map(|k| base_values[k]);
                        for &(p, slot, rel) in &wheel_draws {
                            let mut r = rng;
                            r.skip(p as u64);
                            w[slot] = r.scale(w[slot], rel);
                        }
                        if w[1] > 2.0 * w[0] * (1.0 + slack.0[0])
                            || w[3] > 2.0 * w[2] * (1.0 + slack.0[1])
                        {
                            rng.skip(spreads.len() as u64);
                            continue;
                        }
                    }
                    for (s, &k) in spreads.iter().zip(&keys) {
                        v[k] = rng.scale(base_values[k], s.rel);
                    }
                    if valid_within(v, &slack) {
                        return true;
                    }
                }
                false
            }
        }
    };
    let index = scene_index();
    let g = base.get("g").unwrap_or(f64::NAN);
    let n_names = names.len();
    let start = Instant::now();
    let chunk = |lo: usize| -> Part {
        let hi = lo + CHUNK.min(count - lo);
        let mut part = Part::new(record, (hi - lo) * n_names);
        let mut values = [base_values; LANES];
        let mut ok = [true; LANES];
        for group in (lo..hi).step_by(LANES) {
            let n = LANES.min(hi - group);
            for j in 0..n {
                values[j] = base_values;
                ok[j] = fill(group + j, &mut values[j]);
            }
            let windows: [Option<WindowSummary>; LANES] = match method {
                Method::Hurwitz => {
                    // A zero wheel radius taken to its limit, as `matrices_of` does (only
                    // when a radius can be zero: the copy costs a few per cent of a sweep).
                    let args: [[f64; LANES]; matrices_scene::Args::LEN] = if skates {
                        let limit: [[f64; 26]; LANES] =
                            std::array::from_fn(|j| skate_limit(&values[j]));
                        std::array::from_fn(|a| std::array::from_fn(|j| limit[j][index[a]]))
                    } else {
                        std::array::from_fn(|a| std::array::from_fn(|j| values[j][index[a]]))
                    };
                    let o = matrices_scene::eval_lanes(&args);
                    hurwitz_window_summary_lanes(&o, g).map(Some)
                }
                Method::Eigen => std::array::from_fn(|j| {
                    if j >= n {
                        return None;
                    }
                    let m = matrices_of(&values[j], &index);
                    eigen_window(&m, g, EigenGrid::default()).as_ref().map(WindowSummary::from)
                }),
            };
            for j in 0..n {
                part.add(ok[j], windows[j], keys.iter().map(|&k| values[j][k]));
            }
        }
        progress.fetch_add(hi - lo, Ordering::Relaxed);
        part
    };
    let (mut acc, mut rejected, mut done) = (Acc::EMPTY, 0, 0);
    while done < count && !stop.load(Ordering::Relaxed) {
        let end = done + BLOCK.min(count - done);
        let parts: Vec<Part> = (0..(end - done).div_ceil(CHUNK))
            .into_par_iter()
            .map(|c| chunk(done + c * CHUNK))
            .collect();
        for (c, p) in parts.iter().enumerate() {
            acc = acc.merge(p.acc);
            rejected += p.rejected;
            if let Some(sink) = sink.as_mut() {
                let first = done + c * CHUNK;
                sink(&SweepChunk {
                    first,
                    values: &p.values,
                    windows: &p.windows,
                    valid: &p.valid,
                });
            }
        }
        done = end;
    }
    let elapsed = start.elapsed().as_secs_f64();
    let range = |n: usize, r: (f64, f64)| (n > 0).then_some(r);
    let summary = SweepSummary {
        count: done,
        elapsed,
        designs_per_second: done as f64 / elapsed,
        stable: acc.stable,
        with_weave: acc.weave,
        with_capsize: acc.capsize,
        weave_range: range(acc.weave, acc.weave_range),
        capsize_range: range(acc.capsize, acc.capsize_range),
        failed: acc.failed,
    };
    let (values, windows, valid) = (Vec::new(), Vec::new(), Vec::new());
    Ok(SweepOutput { summary, names, values, windows, valid, rejected, requested: count })
}

/// The results of one parallel task of [`sweep_designs`].
struct Part {
    acc: Acc,
    rejected: usize,
    record: bool,
    values: Vec<f64>,
    windows: Vec<Option<WindowSummary>>,
    valid: Vec<bool>,
}

impl Part {
    fn new(record: bool, n_values: usize) -> Part {
        let cap = |n: usize| if record { n } else { 0 };
        Part {
            acc: Acc::EMPTY,
            rejected: 0,
            record,
            values: Vec::with_capacity(cap(n_values)),
            windows: Vec::with_capacity(cap(CHUNK)),
            valid: Vec::with_capacity(cap(CHUNK)),
        }
    }

    /// Adds one design: `ok` false for a rejected random design, `w` `None` when the window
    /// could not be computed.
    fn add(&mut self, ok: bool, w: Option<WindowSummary>, values: impl Iterator<Item = f64>) {
        let w = if ok { w } else { None };
        if ok {
            self.acc = self.acc.add(w.as_ref());
        } else {
            self.rejected += 1;
        }
        if self.record {
            self.values.extend(values);
            self.windows.push(w);
            self.valid.push(ok);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The random designs of [`sweep_designs`] (values and validity) are those of the plain
    /// rejection loop, every value of every draw computed and checked by [`valid_within`]: the
    /// draws rejected early by the wheels' inequalities are skipped, not changed.
    #[test]
    fn skipping_rejected_draws_keeps_the_designs() {
        let base = WhippleParams::benchmark();
        let names: Vec<&str> = PARAM_NAMES.iter().copied().filter(|n| *n != "g").collect();
        let keys = param_indices(names.iter().copied()).expect("known names");
        let slack = TriangleSlack::admitting(&base);
        let count = 3000;
        for (rel, seed) in [(0.2, 11u64), (0.6, 12)] {
            let spreads: Vec<Spread> =
                names.iter().map(|n| Spread { name: n.to_string(), rel }).collect();
            let designs = Designs::Random { count, spreads: spreads.clone(), seed };
            let out = sweep_designs(&base, &designs, Method::Hurwitz, true, &AtomicUsize::new(0))
                .expect("valid spreads");
            let mut draws = 0;
            for i in 0..count {
                let mut v = *base.values();
                let mut rng = SplitMix64(seed.wrapping_add(i as u64));
                let mut ok = false;
                for _ in 0..MAX_DRAWS {
                    draws += 1;
                    for (s, &k) in spreads.iter().zip(&keys) {
                        v[k] = rng.scale(base.values()[k], s.rel);
                    }
                    if valid_within(&v, &slack) {
                        ok = true;
                        break;
                    }
                }
                assert_eq!(out.valid[i], ok, "design {i}");
                let want: Vec<f64> = keys.iter().map(|&k| v[k]).collect();
                assert_eq!(&out.values[i * keys.len()..(i + 1) * keys.len()], want, "design {i}");
            }
            // Most designs needed several draws (the early rejections were exercised), and at
            // the wide spread some were rejected after every draw.
            assert!(draws > 2 * count, "{draws} draws");
            if rel > 0.5 {
                assert!(out.rejected > 0, "no design rejected at spread {rel}");
            }
        }
    }
}
