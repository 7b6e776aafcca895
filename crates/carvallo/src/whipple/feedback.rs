//! State feedback on the bicycle as a plant and the closed-loop stable speed range.
//!
//! The feedback $u = -Kx$ of the state $x = (\varphi, \delta, \dot\varphi, \dot\delta)$ to the
//! inputs $u = (T_\varphi, T_\delta)$ (roll and steer torque), $K = (K_p\ K_d)$ a 2 × 4 matrix
//! whose rows are the inputs and columns the states, closes the loop
//!
//! $$M\ddot q + (vC_1 + K_d)\dot q + (gK_0 + v^2K_2 + K_p)q = 0,\qquad
//! \dot x = (A - BK)x.$$
//!
//! The gains are named `k_{input}_{state}` ([`GAIN_NAMES`]). The balance-assist law, steer
//! torque from the roll rate, is `k_steer_roll_rate`; in the benchmark's signs (lean and steer
//! positive to the right) steering into the fall is $T_\delta = c\,\dot\varphi$ with
//! $c > 0$, so `k_steer_roll_rate = -c` ([`Gains::balance_assist`]`(c)`): a positive
//! `k_steer_roll_rate` steers out of the fall and shrinks the window.
//!
//! Two independent routes:
//!
//! * the **eigenvalues** of $A - BK$ from the state space ([`super::plant`]):
//!   [`Whipple::closed_loop_eigenvalues`], and [`Whipple::closed_loop_eigen_window`], the
//!   stable range on a speed grid with every sign change of the largest real part bisected
//!   (the reference; it can miss a window narrower than a grid step);
//! * the **closed-loop characteristic polynomial** $\sum_k a_k(v) s^k$, derived symbolically
//!   in $v$ and the gains (`cl_a{k}_{j}` of `generated/whipple.ir`, the coefficient of $v^j$ in
//!   $a_k$) and evaluated by one generated [`scene!`](crate::scene) ([`ClosedLoopPoly`]); its
//!   stable speed range by the Hurwitz route ([`Whipple::closed_loop_window`]).
//!
//! # The Hurwitz route with gains
//!
//! With $a_4 = \det M > 0$ the closed loop is stable at $v$ iff $a_0, \dots, a_3 > 0$ and
//! $H_3 = a_1(a_2a_3 - a_1a_4) - a_0a_3^2 > 0$. The $a_k$ are polynomials in $v$ of degree at
//! most $4 - k$ and $H_3$ one of degree at most 6 (its coefficients are computed in
//! double-double arithmetic, then rounded). With gains the odd powers of $v$ no longer vanish,
//! so the substitution $u = v^2$ of [`super::stability`] does not apply. The window is found
//! in two stages without allocation ([`closed_loop_window_of`]): the points where
//! $a_0 \dots a_3$ change sign in the speed range ([`sign_change_roots_in`]: a line or a
//! quadratic in closed form; above, Descartes' rule on the Bernstein coefficients of the range
//! skips a polynomial or a half without a root, and each isolated root is located to adjacent
//! floats by safeguarded Newton) cut it into candidate intervals where all four have the sign
//! of $a_4$; only if there is one is $H_3$ formed, and only its sign changes inside the
//! candidates are located. The Routh–Hurwitz conditions are tested once between consecutive
//! cuts. A closed-loop window costs about 0.8 µs on the benchmark with balance assist, plus
//! 0.12 µs for the generated coefficients (release build, `carvallo bench`; the former route,
//! every real root of the five polynomials by [`real_roots_in`], kept as
//! [`closed_loop_window_all_roots`], about 6 µs; the open-loop window, in closed form in
//! $u = v^2$, about 0.2 µs from the parameters). [`closed_loop_reference_edges`] locates the
//! edges again at 256 bits: the reference of the tests and of `carvallo bench`.
//!
//! Near an edge [`ClosedLoopPoly::classify`] gives a certified verdict (double-double
//! arithmetic with a running error bound, as [`super::certified`] does for the open loop).
//!
//! # Gains as functions of speed
//!
//! A [`GainTable`] gives the eight gains at increasing speeds, linearly interpolated. On each
//! table interval the gains are linear in $v$, so every entry of
//! $M s^2 + (vC_1 + K_d)s + gK_0 + v^2K_2 + K_p$ is a polynomial of degree at most 2 in $v$ and
//! every $a_k$ one of degree at most 4: [`Whipple::closed_loop_window_table`] interpolates each
//! $a_k$ exactly through five speeds of the interval (in the local variable
//! $t \in [0, 1]$), forms $H_3$ (degree at most 6 in $t$) and cuts the interval at their roots
//! as above.

use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::{Matrix2x4, Matrix4};

use super::certified::{Bounded, Certified};
use super::model::Whipple;
use super::params::PARAM_NAMES;
use crate::numerics::dd::{two_prod, two_sum, Dd};
use crate::numerics::eigen::{eigenvalues4, Eigenvalue};
use crate::numerics::poly::{poly_eval_low, real_roots_in, sign_change_roots_in};

crate::scene! {
    /// The closed-loop characteristic polynomial: `cl_a{k}_{j}`, the coefficient of $v^j$ in
    /// $a_k$, for $k = 0..4$, $j = 0..4-k$; the gains are its inputs.
    pub mod closed_loop_scene {
        model: whipple,
        outputs: [
            cl_a0_0, cl_a0_1, cl_a0_2, cl_a0_3, cl_a0_4, cl_a1_0, cl_a1_1, cl_a1_2, cl_a1_3,
            cl_a2_0, cl_a2_1, cl_a2_2, cl_a3_0, cl_a3_1, cl_a4_0
        ],
    }
}

/// The names of the eight gains, `k_{input}_{state}`, in the order of $K$ by rows (inputs
/// roll, steer torque) then columns (states roll, steer, roll rate, steer rate): the inputs of
/// the closed-loop scene, as the derivation names them (`GAINS` of
/// `codegen/src/derive/whipple/mod.rs`), so that the two cannot drift apart.
pub const GAIN_NAMES: &[&str] = closed_loop_scene::INPUTS;
const _: () = assert!(GAIN_NAMES.len() == 8, "K is 2 x 4");

/// The gain matrix $K$ of $u = -Kx$: `k[input][state]`, inputs (roll torque, steer torque),
/// states (roll, steer, roll rate, steer rate); units N m/rad and N m s/rad.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Gains(pub [[f64; 4]; 2]);

/// A gain name that is none of [`GAIN_NAMES`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownGain {
    /// The name given.
    pub name: String,
}

impl fmt::Display for UnknownGain {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown gain `{}`: expected one of {}", self.name, GAIN_NAMES.join(", "))
    }
}

impl std::error::Error for UnknownGain {}

impl Gains {
    /// No feedback: the open loop.
    pub const ZERO: Gains = Gains([[0.0; 4]; 2]);

    /// The balance-assist law $T_\delta = c\,\dot\varphi$, steer torque into the fall in
    /// proportion to the roll rate ($c$ in N m s/rad): `k_steer_roll_rate = -c`.
    pub fn balance_assist(c: f64) -> Gains {
        let mut g = Gains::ZERO;
        g.0[1][2] = -c;
        g
    }

    /// The index in [`GAIN_NAMES`] of `name`.
    ///
    /// # Errors
    /// [`UnknownGain`] naming it.
    pub fn index(name: &str) -> Result<usize, UnknownGain> {
        GAIN_NAMES.iter().position(|n| *n == name).ok_or_else(|| UnknownGain { name: name.into() })
    }

    /// The gain named `name`, `None` for an unknown name.
    pub fn get(&self, name: &str) -> Option<f64> {
        Gains::index(name).ok().map(|i| self.0[i / 4][i % 4])
    }

    /// Sets the gain named `name`.
    ///
    /// # Errors
    /// [`UnknownGain`] naming it.
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), UnknownGain> {
        let i = Gains::index(name)?;
        self.0[i / 4][i % 4] = value;
        Ok(())
    }

    /// The gains given by name (the others zero; a name given twice keeps its last value).
    ///
    /// # Errors
    /// [`UnknownGain`] naming the first unknown name.
    pub fn from_named<'a>(
        pairs: impl IntoIterator<Item = (&'a str, f64)>,
    ) -> Result<Gains, UnknownGain> {
        let mut g = Gains::ZERO;
        for (name, value) in pairs {
            g.set(name, value)?;
        }
        Ok(g)
    }

    /// The eight gains in the order of [`GAIN_NAMES`].
    pub fn values(&self) -> [f64; 8] {
        std::array::from_fn(|i| self.0[i / 4][i % 4])
    }

    /// $K$ as a matrix.
    pub fn matrix(&self) -> Matrix2x4<f64> {
        Matrix2x4::from_fn(|r, c| self.0[r][c])
    }

    /// $(1 - t)\,\text{self} + t\,\text{other}$.
    pub fn lerp(&self, other: &Gains, t: f64) -> Gains {
        Gains(std::array::from_fn(|r| {
            std::array::from_fn(|c| self.0[r][c] + t * (other.0[r][c] - self.0[r][c]))
        }))
    }
}

/// The closed-loop characteristic polynomial $\sum_k a_k(v)s^k$ at fixed gains:
/// `coeffs[k][j]` is the coefficient of $v^j$ in $a_k$ (zero for $j > 4 - k$).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosedLoopPoly {
    /// `coeffs[k][j]`: the coefficient of $v^j$ in $a_k$.
    pub coeffs: [[f64; 5]; 5],
}

impl ClosedLoopPoly {
    /// $[a_0, \dots, a_4]$ at speed `v`.
    pub fn at(&self, v: f64) -> [f64; 5] {
        self.coeffs.map(|c| poly_eval_low(&c, v))
    }

    /// A certified classification at speed `v` ([`super::certified`]): each coefficient taken
    /// as known to within the relative error `coeff_rel_err` (zero: exact), $a_k(v)$ and $H_3$
    /// evaluated in double-double arithmetic with a running error bound; stable or unstable
    /// only when no bound reaches zero. Meant for speeds near a window's edges, where $H_3$ is
    /// a small difference of large products.
    pub fn classify(&self, v: f64, coeff_rel_err: f64) -> Certified {
        let b = |x: f64| Bounded::new(x, coeff_rel_err * x.abs() * (1.0 + 8.0 * f64::EPSILON));
        let vb = Bounded::new(v, 0.0);
        let a: [Bounded; 5] = self
            .coeffs
            .map(|c| c.iter().rev().fold(Bounded::new(0.0, 0.0), |acc, &x| acc * vb + b(x)));
        let h3 = a[1] * (a[2] * a[3] - a[1] * a[4]) - a[0] * a[3] * a[3];
        let Some(lead) = a[4].sign() else { return Certified::Indeterminate };
        let signs = [a[0], a[1], a[2], a[3], h3].map(|x| x.sign().map(|s| s == lead));
        if signs.contains(&Some(false)) {
            Certified::Unstable
        } else if signs.iter().all(|s| *s == Some(true)) {
            Certified::Stable
        } else {
            Certified::Indeterminate
        }
    }

    /// $H_3 = a_1(a_2a_3 - a_1a_4) - a_0a_3^2$ as a polynomial in $v$ (lowest first, degree
    /// at most 6), the products in double-double arithmetic, rounded once.
    pub fn h3(&self) -> [f64; 7] {
        h3_of(&self.coeffs)
    }
}

/// A polynomial (lowest first) of degree at most 6 in double-double arithmetic, on the
/// stack: `n` coefficients.
#[derive(Clone, Copy)]
struct DdPoly {
    c: [Dd; 7],
    n: usize,
}

/// `a + b` in double-double arithmetic, the cheaper sum (one TwoSum; error below
/// $2u^2(|a| + |b|)$, far below the final rounding of an $H_3$ coefficient to `f64` unless
/// it cancels by a factor $1/u$).
#[inline]
fn accumulate(a: Dd, b: Dd) -> Dd {
    let (s, e) = two_sum(a.hi, b.hi);
    let e = e + (a.lo + b.lo);
    let hi = s + e;
    Dd { hi, lo: e - (hi - s) }
}

/// The number of coefficients of `a` up to its last nonzero one among the first `max`.
fn len_of(a: &[f64; 5], max: usize) -> usize {
    a[..max].iter().rposition(|&x| x != 0.0).map_or(0, |i| i + 1)
}

impl DdPoly {
    const ZERO: DdPoly = DdPoly { c: [Dd { hi: 0.0, lo: 0.0 }; 7], n: 0 };

    /// The exact product of two `f64` polynomials (each product exact by Dekker's
    /// TwoProduct, the sums in double-double).
    fn mul_ff(a: &[f64], b: &[f64]) -> DdPoly {
        let mut p = DdPoly::ZERO;
        if a.is_empty() || b.is_empty() {
            return p;
        }
        for (i, &x) in a.iter().enumerate() {
            for (j, &y) in b.iter().enumerate() {
                let (hi, lo) = two_prod(x, y);
                p.c[i + j] = accumulate(p.c[i + j], Dd { hi, lo });
            }
        }
        p.n = a.len() + b.len() - 1;
        p
    }

    /// The product by an `f64` polynomial `a`.
    fn mul_f(&self, a: &[f64]) -> DdPoly {
        let mut p = DdPoly::ZERO;
        if a.is_empty() || self.n == 0 {
            return p;
        }
        for (i, &x) in a.iter().enumerate() {
            for (j, y) in self.c[..self.n].iter().enumerate() {
                let (hi, lo) = two_prod(y.hi, x);
                p.c[i + j] = accumulate(p.c[i + j], Dd { hi, lo: lo + y.lo * x });
            }
        }
        p.n = a.len() + self.n - 1;
        p
    }

    fn sub(&self, b: &DdPoly) -> DdPoly {
        let mut c = self.c;
        for (ci, y) in c.iter_mut().zip(&b.c[..b.n]) {
            *ci = *ci - *y;
        }
        DdPoly { c, n: self.n.max(b.n) }
    }
}

/// $H_3$ of the polynomials `a[k]` (lowest first; $a_k$ taken to its degree $4 - k$, the
/// coefficients above it being zero, or only rounding in interpolated ones): the products in
/// double-double arithmetic over the nonzero coefficients (the first ones exact), the result
/// rounded to `f64` once.
fn h3_of(a: &[[f64; 5]; 5]) -> [f64; 7] {
    let s: [&[f64]; 5] = std::array::from_fn(|k| &a[k][..len_of(&a[k], 5 - k)]);
    let inner = DdPoly::mul_ff(s[2], s[3]).sub(&DdPoly::mul_ff(s[1], s[4]));
    let h = inner.mul_f(s[1]).sub(&DdPoly::mul_ff(s[3], s[3]).mul_f(s[0]));
    std::array::from_fn(|i| if i < h.n { h.c[i].to_f64() } else { 0.0 })
}

/// The stable intervals of $[from, to]$ for the polynomials `a[k]` in a variable $t$ (lowest
/// first), $t$ mapped to the speed by `speed`, in two stages without allocation (but `out`'s):
///
/// 1. every point of $(t_0, t_1)$ where one of $a_0 \dots a_3$ changes sign
///    ([`sign_change_roots_in`]: Descartes' rule on the Bernstein coefficients skips a
///    polynomial or a piece without a root, and each isolated root is located to adjacent
///    floats by safeguarded Newton) is a cut; between cuts the signs of $a_k a_4$ are tested,
///    giving the candidate intervals where all are positive;
/// 2. $H_3$ (`h3`, formed only if there is a candidate) is cut at its sign changes within each
///    candidate only, and tested between those cuts.
///
/// Adjacent stable intervals are merged into `out` (already sorted, as the calls come in
/// order).
fn hurwitz_intervals(
    a: &[[f64; 5]; 5],
    h3: &dyn Fn() -> [f64; 7],
    (t0, t1): (f64, f64),
    speed: &dyn Fn(f64) -> f64,
    out: &mut Vec<(f64, f64)>,
) {
    // At most 8 sign changes per polynomial (more than its degree only from the rounding of
    // interpolated coefficients) and the two ends.
    let mut cuts = [0.0; 2 + 4 * 8];
    cuts[0] = t0;
    let mut n = 1;
    for p in &a[..4] {
        for &t in sign_change_roots_in(p, t0, t1).as_slice() {
            cuts[n] = t;
            n += 1;
        }
    }
    cuts[1..n].sort_unstable_by(f64::total_cmp);
    cuts[n] = t1;
    n += 1;
    let mid_of = |lo: f64, hi: f64| if hi.is_finite() { 0.5 * (lo + hi) } else { 2.0 * lo + 1.0 };
    // a_4 = det M (constant for constant gains; never zero for a valid design): the sign of
    // the leading coefficient is normalised by testing a_k a_4 > 0, H3 a_4 > 0.
    let lead = |t: f64| poly_eval_low(&a[4], t).signum();
    let candidate = |t: f64| {
        let s = lead(t);
        s != 0.0 && a.iter().all(|p| poly_eval_low(p, t) * s > 0.0)
    };
    // The candidate intervals, adjacent ones merged.
    let mut cand = [(0.0, 0.0); 2 + 4 * 8];
    let mut nc = 0;
    for pair in cuts[..n].windows(2) {
        let (lo, hi) = (pair[0], pair[1]);
        if hi > lo && candidate(mid_of(lo, hi)) {
            if nc > 0 && cand[nc - 1].1 == lo {
                cand[nc - 1].1 = hi;
            } else {
                cand[nc] = (lo, hi);
                nc += 1;
            }
        }
    }
    if nc == 0 {
        return;
    }
    let h3 = h3();
    for &(lo, hi) in &cand[..nc] {
        let roots = sign_change_roots_in(&h3, lo, hi);
        let mut left = lo;
        for &right in roots.as_slice().iter().chain([&hi]) {
            if right > left {
                let m = mid_of(left, right);
                if poly_eval_low(&h3, m) * lead(m) > 0.0 && candidate(m) {
                    let (vlo, vhi) = (speed(left), speed(right));
                    match out.last_mut() {
                        Some(last) if last.1 == vlo => last.1 = vhi,
                        _ => out.push((vlo, vhi)),
                    }
                }
            }
            left = right;
        }
    }
}

/// The closed-loop stable speed range looked for in $[from, to]$.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedLoopWindow {
    /// The lowest speed looked at (m/s).
    pub from: f64,
    /// The highest speed looked at in m/s (infinite: every speed above `from`).
    pub to: f64,
    /// The maximal stable intervals within $[from, to]$, ascending; an interval that reaches
    /// `to` ends there (it may go on above).
    pub stable: Vec<(f64, f64)>,
}

impl ClosedLoopWindow {
    /// The lowest stable speed, `None` if no speed of the range is stable.
    pub fn lowest_stable_speed(&self) -> Option<f64> {
        self.stable.first().map(|s| s.0)
    }
}

/// Why a window could not be computed.
#[derive(Clone, Debug, PartialEq)]
pub enum FeedbackError {
    /// The speed range is not $0 \le from \le to$ (`to` may be infinite).
    BadRange {
        /// The lower end.
        from: f64,
        /// The upper end.
        to: f64,
    },
    /// A gain table with fewer than two rows, a speed that does not increase or is not finite,
    /// or a gain that is not finite.
    BadTable {
        /// What is wrong.
        reason: String,
    },
    /// The gain table does not cover the speed range asked.
    TableDoesNotCover {
        /// The speeds of the table (first, last).
        table: (f64, f64),
        /// The range asked.
        asked: (f64, f64),
    },
    /// The eigenvalues did not converge (the eigenvalue route only).
    NoEigenvalues {
        /// The speed.
        speed: f64,
    },
}

impl fmt::Display for FeedbackError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FeedbackError::BadRange { from, to } => {
                write!(f, "invalid speed range {from} to {to}: expected 0 <= from <= to")
            }
            FeedbackError::BadTable { reason } => write!(f, "invalid gain table: {reason}"),
            FeedbackError::TableDoesNotCover { table, asked } => write!(
                f,
                "the gain table covers the speeds {} to {} m/s, not the range asked {} to {} m/s",
                table.0, table.1, asked.0, asked.1
            ),
            FeedbackError::NoEigenvalues { speed } => {
                write!(f, "the eigenvalues did not converge at {speed} m/s")
            }
        }
    }
}

impl std::error::Error for FeedbackError {}

fn check_range(from: f64, to: f64) -> Result<(), FeedbackError> {
    if from >= 0.0 && from.is_finite() && to >= from {
        Ok(())
    } else {
        Err(FeedbackError::BadRange { from, to })
    }
}

/// Gains as functions of speed: rows (speed, gains) at strictly increasing speeds, linearly
/// interpolated between them.
#[derive(Clone, Debug, PartialEq)]
pub struct GainTable {
    rows: Vec<(f64, Gains)>,
}

impl GainTable {
    /// The table of `rows`.
    ///
    /// # Errors
    /// [`FeedbackError::BadTable`] for fewer than two rows, a speed that is not finite or does
    /// not increase, or a gain that is not finite.
    pub fn new(rows: Vec<(f64, Gains)>) -> Result<GainTable, FeedbackError> {
        let bad = |reason: String| Err(FeedbackError::BadTable { reason });
        if rows.len() < 2 {
            return bad(format!("{} rows: at least two speeds are needed", rows.len()));
        }
        for (i, (v, g)) in rows.iter().enumerate() {
            if !v.is_finite() {
                return bad(format!("speed {v} in row {} is not finite", i + 1));
            }
            if let Some(k) = g.values().iter().position(|x| !x.is_finite()) {
                return bad(format!(
                    "{} = {} in row {} is not finite",
                    GAIN_NAMES[k],
                    g.values()[k],
                    i + 1
                ));
            }
            if i > 0 && *v <= rows[i - 1].0 {
                return bad(format!("speed {v} in row {} does not increase", i + 1));
            }
        }
        Ok(GainTable { rows })
    }

    /// The rows.
    pub fn rows(&self) -> &[(f64, Gains)] {
        &self.rows
    }

    /// The speeds covered: (first, last).
    pub fn span(&self) -> (f64, f64) {
        (self.rows[0].0, self.rows[self.rows.len() - 1].0)
    }

    /// The gains at speed `v`, `None` outside [`GainTable::span`].
    pub fn at(&self, v: f64) -> Option<Gains> {
        let (lo, hi) = self.span();
        if !(v >= lo && v <= hi) {
            return None;
        }
        let ((v0, g0), (v1, g1)) = self.segment(v);
        Some(g0.lerp(&g1, (v - v0) / (v1 - v0)))
    }

    /// The derivative $\mathrm{d}K/\mathrm{d}v$ of [`at`](Self::at) at speed `v`: the slope
    /// of the table's segment that `at` interpolates on (at a row's speed, the segment after
    /// it, or the last one at the last speed); `None` outside [`GainTable::span`].
    pub fn slope(&self, v: f64) -> Option<Gains> {
        let (lo, hi) = self.span();
        if !(v >= lo && v <= hi) {
            return None;
        }
        let ((v0, g0), (v1, g1)) = self.segment(v);
        let w = v1 - v0;
        Some(Gains(std::array::from_fn(|r| std::array::from_fn(|c| (g1.0[r][c] - g0.0[r][c]) / w))))
    }

    /// The rows at the ends of the segment that holds `v` (inside the span).
    fn segment(&self, v: f64) -> ((f64, Gains), (f64, Gains)) {
        let i = self.rows.partition_point(|r| r.0 <= v).clamp(1, self.rows.len() - 1);
        (self.rows[i - 1], self.rows[i])
    }
}

impl Whipple {
    /// The closed-loop characteristic polynomial for the gains `k`, from the generated
    /// evaluator.
    pub fn closed_loop_poly(&self, k: &Gains) -> ClosedLoopPoly {
        // Where each argument of the scene comes from: a parameter's index in PARAM_NAMES,
        // or (from PARAM_NAMES.len() on) a gain's index in GAIN_NAMES; found once.
        static SOURCE: std::sync::OnceLock<[usize; closed_loop_scene::Args::LEN]> =
            std::sync::OnceLock::new();
        let source = SOURCE.get_or_init(|| {
            std::array::from_fn(|i| {
                let name = closed_loop_scene::ARGS[i];
                PARAM_NAMES.iter().position(|n| *n == name).unwrap_or_else(|| {
                    PARAM_NAMES.len() + Gains::index(name).expect("a parameter or a gain")
                })
            })
        });
        let (values, gains) = (self.params().values(), k.values());
        let np = PARAM_NAMES.len();
        let args = closed_loop_scene::Args::from_array(std::array::from_fn(|i| {
            let s = source[i];
            if s < np {
                values[s]
            } else {
                gains[s - np]
            }
        }));
        let o = closed_loop_scene::eval(&args);
        ClosedLoopPoly {
            coeffs: [
                [o.cl_a0_0, o.cl_a0_1, o.cl_a0_2, o.cl_a0_3, o.cl_a0_4],
                [o.cl_a1_0, o.cl_a1_1, o.cl_a1_2, o.cl_a1_3, 0.0],
                [o.cl_a2_0, o.cl_a2_1, o.cl_a2_2, 0.0, 0.0],
                [o.cl_a3_0, o.cl_a3_1, 0.0, 0.0, 0.0],
                [o.cl_a4_0, 0.0, 0.0, 0.0, 0.0],
            ],
        }
    }

    /// $A - BK$ at speed `v`, from the state space ([`Whipple::state_space`]).
    pub fn closed_loop_matrix(&self, v: f64, k: &Gains) -> Matrix4<f64> {
        let ss = self.state_space(v);
        ss.a - ss.b * k.matrix()
    }

    /// The four eigenvalues of $A - BK$ at speed `v`, sorted by real part then imaginary
    /// part; empty if the Schur decomposition does not converge.
    pub fn closed_loop_eigenvalues(&self, v: f64, k: &Gains) -> Vec<Eigenvalue> {
        let mut ev: Vec<Eigenvalue> =
            eigenvalues4(&self.closed_loop_matrix(v, k)).map_or(Vec::new(), |e| e.to_vec());
        ev.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
        ev
    }

    /// The closed-loop stable speed range in $[from, to]$ for constant gains by the Hurwitz
    /// route (see the [module docs](self)); `to` may be `f64::INFINITY`.
    ///
    /// # Errors
    /// [`FeedbackError::BadRange`] unless $0 \le from \le to$.
    pub fn closed_loop_window(
        &self,
        k: &Gains,
        from: f64,
        to: f64,
    ) -> Result<ClosedLoopWindow, FeedbackError> {
        check_range(from, to)?;
        Ok(closed_loop_window_of(&self.closed_loop_poly(k), from, to))
    }

    /// The closed-loop stable speed range in $[from, to]$ for the gains of `table`,
    /// piecewise on its intervals (see the [module docs](self)).
    ///
    /// # Errors
    /// [`FeedbackError::BadRange`] unless $0 \le from \le to < \infty$, and
    /// [`FeedbackError::TableDoesNotCover`] when $[from, to]$ is not within the table's speeds.
    pub fn closed_loop_window_table(
        &self,
        table: &GainTable,
        from: f64,
        to: f64,
    ) -> Result<ClosedLoopWindow, FeedbackError> {
        self.closed_loop_window_table_until(table, from, to, &AtomicBool::new(false))
    }

    /// [`closed_loop_window_table`](Self::closed_loop_window_table) that reads `stop` before
    /// each interval of the table (a table of millions of rows takes seconds): once it is set,
    /// the intervals not yet seen are left out, and the caller drops the partial window
    /// (Ctrl-C).
    ///
    /// # Errors
    /// As [`closed_loop_window_table`](Self::closed_loop_window_table).
    pub fn closed_loop_window_table_until(
        &self,
        table: &GainTable,
        from: f64,
        to: f64,
        stop: &AtomicBool,
    ) -> Result<ClosedLoopWindow, FeedbackError> {
        check_range(from, to)?;
        let span = table.span();
        if !(from >= span.0 && to <= span.1) {
            return Err(FeedbackError::TableDoesNotCover { table: span, asked: (from, to) });
        }
        let mut stable = Vec::new();
        for pair in table.rows().windows(2) {
            if stop.load(Ordering::Relaxed) {
                break;
            }
            let ((v0, g0), (v1, g1)) = (pair[0], pair[1]);
            let (lo, hi) = (v0.max(from), v1.min(to));
            if hi <= lo {
                continue;
            }
            // Each a_k is a polynomial of degree <= 4 in v on [v0, v1]: interpolate it through
            // t = 0, 1/4, ..., 1 (v = v0 + t (v1 - v0)), exactly up to rounding.
            let speed = |t: f64| v0 + t * (v1 - v0);
            let samples: [[f64; 5]; 5] = std::array::from_fn(|i| {
                let v = speed(i as f64 / 4.0);
                let g = g0.lerp(&g1, i as f64 / 4.0);
                self.closed_loop_poly(&g).at(v)
            });
            let a: [[f64; 5]; 5] = std::array::from_fn(|k| {
                interpolate_quartic(&std::array::from_fn(|i| samples[i][k]))
            });
            let t = |v: f64| ((v - v0) / (v1 - v0)).clamp(0.0, 1.0);
            let exact = |x: f64| {
                if x == t(lo) {
                    lo
                } else if x == t(hi) {
                    hi
                } else {
                    speed(x)
                }
            };
            hurwitz_intervals(&a, &|| h3_of(&a), (t(lo), t(hi)), &exact, &mut stable);
        }
        Ok(ClosedLoopWindow { from, to, stable })
    }

    /// The closed-loop stable speed range in $[from, to]$ (finite) by the eigenvalues of
    /// $A - BK$ on `points` + 1 equally spaced speeds, every change of sign of the largest real
    /// part bisected to adjacent floats: the independent reference of
    /// [`Whipple::closed_loop_window`]. A stable window narrower than a grid step can be missed.
    ///
    /// # Errors
    /// [`FeedbackError::BadRange`] for a range that is not $0 \le from \le to < \infty$ or no
    /// points, [`FeedbackError::NoEigenvalues`] if the Schur decomposition fails at a speed.
    pub fn closed_loop_eigen_window(
        &self,
        k: &Gains,
        from: f64,
        to: f64,
        points: usize,
    ) -> Result<ClosedLoopWindow, FeedbackError> {
        check_range(from, to)?;
        if !to.is_finite() || points == 0 {
            return Err(FeedbackError::BadRange { from, to });
        }
        let stable_at = |v: f64| -> Result<bool, FeedbackError> {
            let ev = eigenvalues4(&self.closed_loop_matrix(v, k))
                .ok_or(FeedbackError::NoEigenvalues { speed: v })?;
            Ok(ev.iter().all(|e| e.re < 0.0))
        };
        let mut stable = Vec::new();
        let mut prev_v = from;
        let mut prev = stable_at(from)?;
        let mut open = prev.then_some(from);
        for i in 1..=points {
            let v = if i == points { to } else { from + (to - from) * i as f64 / points as f64 };
            let cur = stable_at(v)?;
            if cur != prev {
                let (mut lo, mut hi) = (prev_v, v);
                loop {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    if stable_at(mid)? == prev {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                if cur {
                    open = Some(hi);
                } else if let Some(start) = open.take() {
                    stable.push((start, lo));
                }
            }
            prev_v = v;
            prev = cur;
        }
        if let Some(start) = open {
            stable.push((start, to));
        }
        Ok(ClosedLoopWindow { from, to, stable })
    }
}

impl Whipple {
    /// The smallest balance-assist gain $c \in [0, c_{\max}]$ ([`Gains::balance_assist`],
    /// $T_\delta = c\,\dot\varphi$) at which the speed `target` is stable, by bisection on
    /// $c$ to a relative width of `1e-12` (each step one closed-loop window, Hurwitz route);
    /// assumes, as the benchmark shows, that the stable range grows downwards with $c$. `None`
    /// if `target` is not stable at $c_{\max}$; `Some(0.0)` if it is stable without
    /// assistance.
    pub fn balance_assist_gain(&self, target: f64, c_max: f64) -> Option<f64> {
        let stable = |c: f64| {
            let k = Gains::balance_assist(c);
            let p = self.closed_loop_poly(&k);
            closed_loop_window_of(&p, 0.0, f64::INFINITY)
                .stable
                .iter()
                .any(|&(lo, hi)| lo <= target && target < hi)
        };
        if !(target >= 0.0 && c_max >= 0.0 && c_max.is_finite() && stable(c_max)) {
            return None;
        }
        if stable(0.0) {
            return Some(0.0);
        }
        let (mut lo, mut hi) = (0.0, c_max);
        while hi - lo > 1e-12 * hi {
            let mid = 0.5 * (lo + hi);
            if stable(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Some(hi)
    }
}

/// The stable range of a closed-loop polynomial in $[from, to]$ ($0 \le from \le to$).
pub fn closed_loop_window_of(p: &ClosedLoopPoly, from: f64, to: f64) -> ClosedLoopWindow {
    let mut stable = Vec::new();
    hurwitz_intervals(&p.coeffs, &|| p.h3(), (from, to), &|v| v, &mut stable);
    ClosedLoopWindow { from, to, stable }
}

/// The edges of a closed-loop window located again at `bits` bits (the reference of
/// `carvallo bench` and of the tests): the closed-loop polynomial's coefficients evaluated at
/// `bits` bits from the IR program (`carvallo_ir::hp`, the design's parameters and the gains
/// `k` exactly as given), then for every edge $e$ of `window` inside $(from, to)$ a bracket
/// $e(1 \pm \delta)$ ($\delta = 10^{-10}$, grown tenfold until the verdict differs at its
/// ends, up to $10^{-3}$) bisected 200 times on the Routh–Hurwitz verdict ($a_0 \dots a_3$
/// and $H_3 = a_1(a_2a_3 - a_1a_4) - a_0a_3^2$ of the same sign as $a_4$, all at `bits`
/// bits, $H_3$ from the values $a_k(v)$ and not from coefficients). Each interval's ends in
/// the order of `window.stable`, rounded to the nearest `f64`; an end equal to `from` or `to`
/// is returned as it is, and `None` marks an edge where no bracket changes verdict (the `f64`
/// edge is off by more than $10^{-3}$ relative) or the evaluation failed.
pub fn closed_loop_reference_edges(
    bike: &Whipple,
    k: &Gains,
    window: &ClosedLoopWindow,
    bits: usize,
) -> Vec<(Option<f64>, Option<f64>)> {
    use astro_float::{BigFloat, RoundingMode};
    use carvallo_ir::{hp, Program};
    const RM: RoundingMode = RoundingMode::ToEven;
    let failed = || window.stable.iter().map(|_| (None, None)).collect();
    let Some(program) = Program::parse(crate::artifacts::WHIPPLE.ir)
        .ok()
        .and_then(|p| p.select_outputs(closed_loop_scene::OUTPUTS).ok())
    else {
        return failed();
    };
    let params = bike.params();
    let args: Vec<f64> = program.params.iter().map(|n| params.get(n).unwrap_or(f64::NAN)).collect();
    let inputs: Vec<f64> = program.inputs.iter().map(|n| k.get(n).unwrap_or(f64::NAN)).collect();
    let Ok(o) = hp::eval(&program, &args, &inputs, bits) else { return failed() };
    // o: cl_a0_0..4, cl_a1_0..3, cl_a2_0..2, cl_a3_0..1, cl_a4_0.
    let starts = [0, 5, 9, 12, 14, 15];
    let p = bits;
    let at = |v: &BigFloat| -> [BigFloat; 5] {
        std::array::from_fn(|kk| {
            o[starts[kk]..starts[kk + 1]]
                .iter()
                .rev()
                .fold(BigFloat::from_word(0, p), |acc, c| acc.mul(v, p, RM).add(c, p, RM))
        })
    };
    let stable =
        |v: &BigFloat| {
            let a = at(v);
            let h3 = a[1]
                .mul(&a[2].mul(&a[3], p, RM).sub(&a[1].mul(&a[4], p, RM), p, RM), p, RM)
                .sub(&a[0].mul(&a[3], p, RM).mul(&a[3], p, RM), p, RM);
            let lead = a[4].is_positive();
            !a[4].is_zero()
                && a[..4].iter().chain([&h3]).all(|x| !x.is_zero() && x.is_positive() == lead)
        };
    let refine = |e: f64| -> Option<f64> {
        if e == window.from || e == window.to || !e.is_finite() {
            return Some(e);
        }
        let mut delta = 1e-10;
        while delta <= 1e-3 {
            let (mut lo, mut hi) =
                (hp::from_f64(e * (1.0 - delta), p), hp::from_f64(e * (1.0 + delta), p));
            let at_lo = stable(&lo);
            if at_lo != stable(&hi) {
                let half = hp::from_f64(0.5, p);
                for _ in 0..200 {
                    let mid = lo.add(&hi, p, RM).mul(&half, p, RM);
                    if stable(&mid) == at_lo {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                return Some(hp::to_f64(&lo.add(&hi, p, RM).mul(&half, p, RM)));
            }
            delta *= 10.0;
        }
        None
    };
    window.stable.iter().map(|&(lo, hi)| (refine(lo), refine(hi))).collect()
}

/// The former route of [`closed_loop_window_of`], kept as a reference and as the baseline of
/// `carvallo bench`: every real root of $a_0 \dots a_3$ and $H_3$ in the range by
/// [`real_roots_in`] (isolation by the roots of the derivatives, recursively, each to adjacent
/// floats, in vectors), sorted, the Routh–Hurwitz conditions tested between consecutive cuts.
pub fn closed_loop_window_all_roots(p: &ClosedLoopPoly, from: f64, to: f64) -> ClosedLoopWindow {
    let (a, h3) = (&p.coeffs, p.h3());
    let mut cuts = vec![from];
    for q in a[..4].iter().map(|q| &q[..]).chain([&h3[..]]) {
        cuts.extend(real_roots_in(q, from, to).into_iter().filter(|&t| t > from && t < to));
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    cuts.push(to);
    let stable_at = |t: f64| {
        let s = poly_eval_low(&a[4], t).signum();
        s != 0.0
            && a.iter().all(|q| poly_eval_low(q, t) * s > 0.0)
            && poly_eval_low(&h3, t) * s > 0.0
    };
    let mut stable: Vec<(f64, f64)> = Vec::new();
    for pair in cuts.windows(2) {
        let (lo, hi) = (pair[0], pair[1]);
        if hi <= lo {
            continue;
        }
        let mid = if hi.is_finite() { 0.5 * (lo + hi) } else { 2.0 * lo + 1.0 };
        if stable_at(mid) {
            match stable.last_mut() {
                Some(last) if last.1 == lo => last.1 = hi,
                _ => stable.push((lo, hi)),
            }
        }
    }
    ClosedLoopWindow { from, to, stable }
}

/// The coefficients (lowest first) of the polynomial of degree at most 4 through
/// $(t_i, y_i)$, $t_i = i/4$: Newton's divided differences, then expanded.
fn interpolate_quartic(y: &[f64; 5]) -> [f64; 5] {
    let t: [f64; 5] = std::array::from_fn(|i| i as f64 / 4.0);
    let mut d = *y;
    for j in 1..5 {
        for i in (j..5).rev() {
            d[i] = (d[i] - d[i - 1]) / (t[i] - t[i - j]);
        }
    }
    // p(t) = d0 + (t - t0)(d1 + (t - t1)(d2 + ...)): expand from the innermost factor.
    let mut c = [0.0; 5];
    c[0] = d[4];
    for j in (0..4).rev() {
        // c <- c * (t - t_j) + d_j
        for i in (1..5).rev() {
            c[i] = c[i - 1] - t[j] * c[i];
        }
        c[0] = -t[j] * c[0] + d[j];
    }
    c
}

#[cfg(test)]
mod tests;
