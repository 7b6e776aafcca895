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
    point_like, skate_limit, valid_within, TriangleBody, TriangleSlack, WhippleError,
    WhippleParams, PARAM_NAMES, TRIANGLE_BODIES,
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
    /// The `i`-th value, $\mathrm{from} + i\,(\mathrm{to} - \mathrm{from})/(n - 1)$ in this
    /// order of operations (the last exactly `to`): no repeated addition, and no fraction
    /// $i/(n-1)$ rounded first, so that `0:0.12:4` gives 0.04 and 0.08, not
    /// 0.039999999999999994 and 0.07999999999999999.
    pub fn at(&self, i: usize) -> f64 {
        if self.count == 1 {
            self.from
        } else if i + 1 == self.count {
            self.to
        } else {
            self.from + i as f64 * (self.to - self.from) / (self.count - 1) as f64
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
    /// from the seeded stream [`SplitMix64`] of design $i$ (seed `seed + i`), so that the
    /// designs do not depend on the number of threads. A draw that
    /// [`WhippleParams::from_values_within`] rejects, with the slack that admits the base
    /// ([`TriangleSlack::admitting`]: a draw may break a triangle inequality of the moments of
    /// inertia by as much as the base does, not more), is redrawn from the same stream, a body
    /// whose moments break its inequalities redrawing only its moments (the sweep's sampler: the
    /// designs are uniform on the valid part of the box all the same), at most [`MAX_DRAWS`]
    /// times; a design still invalid then is counted as rejected.
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

/// How the random designs of [`Designs::Random`] are drawn. Design $i$'s stream
/// ([`SplitMix64`] seeded `seed + i`) is read in attempts of one value per spread (value $p$ of
/// attempt $a$ at position $a n + p$ of the stream, $n$ spreads, in the order of the spreads).
/// A body whose moments of inertia are spread ([`TRIANGLE_BODIES`]: the wheels, then the front
/// and the rear frame) takes its moments from its first attempt that obeys its triangle
/// inequalities, the other parameters come from the first attempt; a design that
/// [`valid_within`] then rejects is drawn again the same way from the attempts after every
/// attempt used, until [`MAX_DRAWS`] attempts are spent (then it is rejected, with the values of
/// its last draw). The rounds use disjoint parts of the stream and the bodies' inequalities read
/// their own moments only, so a design is uniform on the valid part of the box, as with plain
/// redraws of every value, but a body redraws only its own moments: with the benchmark's wheels,
/// almost thin discs, about a quarter of the plain draws obey both wheels' inequalities.
/// Without spread moments of inertia the designs are those of plain redraws.
struct Sampler {
    /// The number of spreads $n$.
    n: usize,
    /// Per spread: its index in [`PARAM_NAMES`] and its spread.
    spreads: Vec<(usize, f64)>,
    /// The bodies with spread moments, in the order they are drawn: the body, its place in
    /// [`TriangleSlack`] and the positions among the spreads of its spread moments.
    bodies: Vec<(TriangleBody, usize, Vec<usize>)>,
    /// The positions among the spreads of the other parameters.
    free: Vec<usize>,
}

impl Sampler {
    fn new(keys: &[usize], spreads: &[Spread]) -> Sampler {
        let bodies: Vec<(TriangleBody, usize, Vec<usize>)> = [0, 1, 3, 2]
            .into_iter()
            .filter_map(|b| {
                let body = TRIANGLE_BODIES[b];
                let at: Vec<usize> =
                    (0..keys.len()).filter(|&p| body.keys().contains(&keys[p])).collect();
                (!at.is_empty()).then_some((body, b, at))
            })
            .collect();
        let free =
            (0..keys.len()).filter(|p| !bodies.iter().any(|(_, _, at)| at.contains(p))).collect();
        let spreads = keys.iter().zip(spreads).map(|(&k, s)| (k, s.rel)).collect();
        Sampler { n: keys.len(), spreads, bodies, free }
    }

    /// Writes the design of `stream` into `v` (which holds the base values); whether it is
    /// valid (see [`Sampler`]).
    fn draw(
        &self,
        stream: SplitMix64,
        base: &[f64; 26],
        slack: &TriangleSlack,
        v: &mut [f64; 26],
    ) -> bool {
        let set = |v: &mut [f64; 26], attempt: usize, p: usize| {
            let (k, rel) = self.spreads[p];
            let mut r = stream;
            r.skip((attempt * self.n + p) as u64);
            v[k] = r.scale(base[k], rel);
        };
        let mut start = 0;
        while start < MAX_DRAWS {
            let mut next = start + 1;
            for (body, b, at) in &self.bodies {
                let mut attempt = start;
                loop {
                    at.iter().for_each(|&p| set(v, attempt, p));
                    if body.holds(v, slack.0[*b]) || attempt + 1 == MAX_DRAWS {
                        break;
                    }
                    attempt += 1;
                }
                next = next.max(attempt + 1);
            }
            self.free.iter().for_each(|&p| set(v, start, p));
            if valid_within(v, slack) {
                return true;
            }
            start = next;
        }
        false
    }
}

/// Designs processed per parallel task (a multiple of the lanes).
const CHUNK: usize = 4096;
/// Designs evaluated between two updates of the running summary (the stop flag of
/// [`sweep_stream`] is read every four designs); only one block's results are held at a time.
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
/// read before every four designs (a few milliseconds at most, on the eigen route too): once it
/// is set, the sweep ends and summarises the designs done, a prefix of the designs
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
    let sampler = match designs {
        Designs::Random { spreads, .. } => Sampler::new(&keys, spreads),
        Designs::Grid(_) => Sampler::new(&[], &[]),
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
            Designs::Random { seed, .. } => {
                let stream = SplitMix64(seed.wrapping_add(i as u64));
                sampler.draw(stream, &base_values, &slack, v)
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
            // Ctrl-C within a few designs, even at the eigen route's milliseconds per design.
            if stop.load(Ordering::Relaxed) {
                break;
            }
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
            part.done += n;
        }
        progress.fetch_add(part.done, Ordering::Relaxed);
        part
    };
    let (mut acc, mut rejected, mut done) = (Acc::EMPTY, 0, 0);
    while done < count && !stop.load(Ordering::Relaxed) {
        let end = done + BLOCK.min(count - done);
        let parts: Vec<Part> = (0..(end - done).div_ceil(CHUNK))
            .into_par_iter()
            .map(|c| chunk(done + c * CHUNK))
            .collect();
        // The designs done form a prefix: a chunk cut short by `stop` ends it (the chunks
        // after it, done or not, are dropped).
        let mut next = done;
        for (c, p) in parts.iter().enumerate() {
            let first = done + c * CHUNK;
            acc = acc.merge(p.acc);
            rejected += p.rejected;
            if let Some(sink) = sink.as_mut() {
                sink(&SweepChunk {
                    first,
                    values: &p.values,
                    windows: &p.windows,
                    valid: &p.valid,
                });
            }
            next = first + p.done;
            if next < end.min(first + CHUNK) {
                break;
            }
        }
        done = next;
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
    /// The designs done: all of the chunk's unless `stop` cut it short.
    done: usize,
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
            done: 0,
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

    #[test]
    fn grid_values_are_from_plus_i_steps_not_a_rounded_fraction() {
        let v = |from, to, count| Vary { name: "c".into(), from, to, count };
        let got: Vec<f64> = (0..4).map(|i| v(0.0, 0.12, 4).at(i)).collect();
        assert_eq!(got, [0.0, 0.04, 0.08, 0.12]);
        let got: Vec<f64> = (0..6).map(|i| v(0.0, 0.1, 6).at(i)).collect();
        assert_eq!(got, [0.0, 0.02, 0.04, 0.06000000000000001, 0.08, 0.1]);
        assert_eq!(v(0.3, 0.9, 1).at(0), 0.3);
    }

    /// The designs of the plain rejection loop: every value of every draw computed, the whole
    /// draw checked by [`valid_within`] and redrawn until it passes (at most [`MAX_DRAWS`]
    /// times). Returns the designs' varied values, whether each is valid and the draws spent.
    fn plain_redraws(
        base: &WhippleParams,
        keys: &[usize],
        spreads: &[Spread],
        seed: u64,
        count: usize,
    ) -> (Vec<Vec<f64>>, Vec<bool>, usize) {
        let slack = TriangleSlack::admitting(base);
        let (mut values, mut valid, mut draws) = (Vec::new(), Vec::new(), 0);
        for i in 0..count {
            let mut v = *base.values();
            let mut rng = SplitMix64(seed.wrapping_add(i as u64));
            let mut ok = false;
            for _ in 0..MAX_DRAWS {
                draws += 1;
                for (s, &k) in spreads.iter().zip(keys) {
                    v[k] = rng.scale(base.values()[k], s.rel);
                }
                if valid_within(&v, &slack) {
                    ok = true;
                    break;
                }
            }
            values.push(keys.iter().map(|&k| v[k]).collect());
            valid.push(ok);
        }
        (values, valid, draws)
    }

    /// A number computed from one design's varied values.
    type Statistic = Box<dyn Fn(&[f64]) -> f64>;

    fn spreads_of(names: &[&str], rel: f64) -> Vec<Spread> {
        names.iter().map(|n| Spread { name: n.to_string(), rel }).collect()
    }

    /// Without a spread moment of inertia the designs of [`sweep_designs`] are exactly those
    /// of plain redraws.
    #[test]
    fn without_spread_moments_the_designs_are_plain_redraws() {
        let base = WhippleParams::benchmark();
        let names = ["w", "c", "lambda", "rR", "mR", "xB", "zB", "mB", "xH", "zH", "mH", "rF"];
        let keys = param_indices(names.iter().copied()).expect("known names");
        let spreads = spreads_of(&names, 0.3);
        let designs = Designs::Random { count: 2000, spreads: spreads.clone(), seed: 4 };
        let out = sweep_designs(&base, &designs, Method::Hurwitz, true, &AtomicUsize::new(0))
            .expect("valid spreads");
        let (values, valid, _) = plain_redraws(&base, &keys, &spreads, 4, 2000);
        assert_eq!(out.valid, valid);
        assert_eq!(out.values, values.concat());
    }

    /// With every parameter spread, the designs of [`sweep_designs`] (each body redrawing only
    /// its own moments) have the distribution of plain redraws of every value: uniform on the
    /// valid part of the box. The means of every parameter and of the ratios the bodies'
    /// inequalities bound agree within five standard errors (the plain loop spends about twelve
    /// draws per design at a 20 % spread, the bodies' redraws far fewer values), every design is
    /// valid and inside its box, and at a 60 % spread too.
    #[test]
    fn body_redraws_keep_the_distribution_of_plain_redraws() {
        let base = WhippleParams::benchmark();
        let names: Vec<&str> = PARAM_NAMES.iter().copied().filter(|n| *n != "g").collect();
        let keys = param_indices(names.iter().copied()).expect("known names");
        let slack = TriangleSlack::admitting(&base);
        let count = 20_000;
        for (rel, seed) in [(0.2, 11u64), (0.6, 12)] {
            let spreads = spreads_of(&names, rel);
            let designs = Designs::Random { count, spreads: spreads.clone(), seed };
            let out = sweep_designs(&base, &designs, Method::Hurwitz, true, &AtomicUsize::new(0))
                .expect("valid spreads");
            assert_eq!(out.rejected, 0);
            let ours: Vec<&[f64]> = out.values.chunks(keys.len()).collect();
            for d in &ours {
                let mut v = *base.values();
                for (j, &k) in keys.iter().enumerate() {
                    assert!((d[j] / v[k] - 1.0).abs() <= rel * (1.0 + 1e-15), "{d:?}");
                    v[k] = d[j];
                }
                assert!(valid_within(&v, &slack), "{d:?}");
            }
            // Plain redraws from other streams; some designs are still invalid after every draw
            // (a few at 20 %, more at 60 %; the bodies' redraws reject none): the valid ones count.
            let (plain, valid, draws) = plain_redraws(&base, &keys, &spreads, seed << 40, count);
            let plain: Vec<&Vec<f64>> =
                plain.iter().zip(&valid).filter(|p| *p.1).map(|p| p.0).collect();
            assert!(plain.len() > count / 2, "{} valid", plain.len());
            assert!(draws > 5 * count, "{draws} plain draws");
            let at = |name: &str| names.iter().position(|n| *n == name).expect("spread");
            // Each statistic: a parameter, or a ratio that a body's inequality bounds.
            let mut stats: Vec<Statistic> = Vec::new();
            for j in 0..keys.len() {
                stats.push(Box::new(move |d: &[f64]| d[j]));
            }
            for (num, den) in
                [("IRyy", "IRxx"), ("IFyy", "IFxx"), ("IByy", "IBxx"), ("IHyy", "IHzz")]
            {
                let (a, b) = (at(num), at(den));
                stats.push(Box::new(move |d: &[f64]| d[a] / d[b]));
            }
            for f in &stats {
                let moments = |xs: &mut dyn Iterator<Item = f64>| {
                    let xs: Vec<f64> = xs.collect();
                    let m = xs.iter().sum::<f64>() / xs.len() as f64;
                    let var = xs.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / xs.len() as f64;
                    (m, var / xs.len() as f64)
                };
                let (m1, e1) = moments(&mut ours.iter().map(|d| f(d)));
                let (m2, e2) = moments(&mut plain.iter().map(|d| f(d.as_slice())));
                assert!(
                    (m1 - m2).abs() <= 5.0 * (e1 + e2).sqrt(),
                    "spread {rel}: means {m1} and {m2}, standard error {}",
                    (e1 + e2).sqrt()
                );
            }
        }
    }
}
