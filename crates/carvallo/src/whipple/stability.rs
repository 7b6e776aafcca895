//! Stability windows of the linearised Carvallo–Whipple bicycle, fast and by reference routes,
//! the reference routes that check them.
//!
//! # The Hurwitz route (fast)
//!
//! With $u = v^2$ the Hurwitz functions of $a_4 s^4 + a_3 s^3 + a_2 s^2 + a_1 s + a_0$ are
//! polynomials of degree at most two in $u$ (the structure of $M\ddot q + vC_1\dot q +
//! (gK_0 + v^2K_2)q = 0$):
//!
//! * $a_0 = p_0 + p_1 u + p_2 u^2$ with $p_0 = g^2\det K_0$, $p_1 = g\,m(K_0, K_2)$,
//!   $p_2 = \det K_2$ ($m(A, B) = a_{11}b_{22} + b_{11}a_{22} - a_{12}b_{21} - b_{12}a_{21}$);
//! * $a_1 = v(q_0 + q_1 u)$, $q_0 = g\,m(C_1, K_0)$, $q_1 = m(C_1, K_2)$;
//! * $a_2 = r_0 + r_1 u$, $r_0 = g\,m(M, K_0)$, $r_1 = m(M, K_2) + \det C_1$;
//! * $a_3 = v\,b$, $b = m(M, C_1)$, and $a_4 = \det M$;
//! * $H_3 = a_1(a_2a_3 - a_1a_4) - a_0a_3^2 = v^2 h(u)$ with
//!   $h = (q_0 + q_1u)(r_0 + r_1u)b - (q_0 + q_1u)^2 a_4 - (p_0 + p_1u + p_2u^2)b^2$.
//!
//! Every boundary of the stable range is therefore $\sqrt u$ for a positive root $u$ of one of
//! three quadratics and two linear functions: [`hurwitz_window`] solves them in closed form
//! (the cancellation-free quadratic formula), sorts the cuts and tests the Routh–Hurwitz
//! conditions once between consecutive cuts. No scan: about a hundred flops.
//! [`hurwitz_window_polished`] also polishes the roots of $a_0$ and $h$ by two Newton steps with
//! the coefficients and the polynomial in double-double arithmetic: the `f64` coefficients of
//! $h$ suffer cancellation, and polishing makes the benchmark's speeds 1.5 to 4 times more
//! accurate (4e-16 and 1.5e-16 instead of 6e-16 and 6e-16 relative) for about five times the
//! cost.
//!
//! The weave speed is the lowest root of $h$ where $H_3$ turns from negative to positive *and*
//! $a_1/a_3 > 0$: by Orlando's formula $H_3 \propto \prod_{i<j}(\lambda_i + \lambda_j)$ also
//! vanishes when two real eigenvalues $\pm r$ pass each other, and there $a_1/a_3 = -r^2 < 0$,
//! while a pair $\pm i\omega$ on the imaginary axis has $\omega^2 = a_1/a_3 > 0$.
//!
//! # The eigenvalue route (reference)
//!
//! [`eigen_window`] computes the eigenvalues of the $4\times4$ state matrix (nalgebra's Schur
//! decomposition, iterations capped) on a speed grid, finds where the largest real part changes
//! sign and bisects each change to adjacent floats. It sees only the grid's range and can miss
//! a window narrower than a grid step; it is the independent check and the baseline of the
//! speed comparison in `carvallo bench`.
//!
//! [`scan_window`] is the former implementation of
//! [`Whipple::stability_window`](crate::whipple::Whipple::stability_window) (200 000-point scan
//! of each Hurwitz function below Cauchy's bound, bisection of each sign change), kept as a
//! second reference.
//!
//! [`reference_speeds`] computes the weave and capsize speeds of the same closed form at 256
//! bits from the matrices evaluated at 256 bits: the reference of `carvallo bench` and of the
//! sweep tests.

use astro_float::{BigFloat, RoundingMode};
use carvallo_ir::{hp, Program};

use super::matrices::{state_matrix, Matrices};
use super::params::WhippleParams;
use crate::numerics::dd::Dd;
use crate::numerics::eigen::eigenvalues4;
use crate::numerics::mat2::{det, mix, Mat2};

/// The stable speed range.
#[derive(Clone, Debug, PartialEq)]
pub struct StabilityWindow {
    /// The lowest positive speed at which $H_3$ turns from negative to positive (the weave
    /// speed), `None` if there is none.
    pub weave_speed: Option<f64>,
    /// The lowest positive root of $a_0(v)$ (the capsize speed), closed form in $v^2$; `None`
    /// if $a_0$ has no positive root.
    pub capsize_speed: Option<f64>,
    /// The maximal intervals of positive speed on which every eigenvalue has a negative real
    /// part; an interval stable for every larger speed ends at `f64::INFINITY`.
    pub stable: Vec<(f64, f64)>,
}

/// The Hurwitz functions as polynomials in $u = v^2$ (coefficients lowest degree first), see
/// the [module docs](self).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HurwitzPolys {
    /// $a_0 = p_0 + p_1u + p_2u^2$.
    pub a0: [f64; 3],
    /// $a_1 / v = q_0 + q_1 u$.
    pub a1_over_v: [f64; 2],
    /// $a_2 = r_0 + r_1 u$.
    pub a2: [f64; 2],
    /// $a_3 / v = b$.
    pub a3_over_v: f64,
    /// $a_4 = \det M$.
    pub a4: f64,
    /// $H_3 / v^2 = h_0 + h_1u + h_2u^2$.
    pub h: [f64; 3],
}

impl HurwitzPolys {
    /// The coefficients from the matrices and gravity.
    pub fn new(m: &Matrices, g: f64) -> HurwitzPolys {
        let Matrices { m, c1, k0, k2 } = *m;
        let a0 = [g * g * det(&k0), capsize_coefficient(&k0, &k2, g), det(&k2)];
        let q = [g * mix(&c1, &k0), mix(&c1, &k2)];
        let r = [g * mix(&m, &k0), mix(&m, &k2) + det(&c1)];
        let b = mix(&m, &c1);
        let a4 = det(&m);
        let h = [
            q[0] * r[0] * b - q[0] * q[0] * a4 - a0[0] * b * b,
            (q[0] * r[1] + q[1] * r[0]) * b - 2.0 * q[0] * q[1] * a4 - a0[1] * b * b,
            q[1] * r[1] * b - q[1] * q[1] * a4 - a0[2] * b * b,
        ];
        HurwitzPolys { a0, a1_over_v: q, a2: r, a3_over_v: b, a4, h }
    }

    /// $(a_0, a_1, a_2, a_3, a_4, H_3)$ at speed `v`, from these coefficients.
    pub fn at(&self, v: f64) -> [f64; 6] {
        let u = v * v;
        let q = |c: &[f64; 3]| (c[2] * u + c[1]) * u + c[0];
        let l = |c: &[f64; 2]| c[1] * u + c[0];
        [
            q(&self.a0),
            v * l(&self.a1_over_v),
            l(&self.a2),
            v * self.a3_over_v,
            self.a4,
            u * q(&self.h),
        ]
    }
}

/// $p_1 = g\,m(K_0, K_2)$, the coefficient of $u$ in $a_0$, or zero where it is below the
/// rounding of its own terms (within $10^{-13}$ of their size). With $K_2$'s first column zero,
/// $m(K_0, K_2) = \frac{\cos\lambda}{w}(m_T z_T S_F \sin\lambda + S_T S_A)$ vanishes for a
/// bicycle without gyroscopic coupling ($S_R = S_F = 0$: the two-mass-skate), and its `f64`
/// value is then the difference of two rounded products, $10^{-15}$ of them, which would put a
/// capsize speed near $10^7$ m/s. A coefficient that small beside its terms describes a root at
/// such speeds in any case.
fn capsize_coefficient(k0: &Mat2, k2: &Mat2, g: f64) -> f64 {
    let p1 = g * mix(k0, k2);
    let terms = (k0[0][0] * k2[1][1]).abs()
        + (k2[0][0] * k0[1][1]).abs()
        + (k0[0][1] * k2[1][0]).abs()
        + (k2[0][1] * k0[1][0]).abs();
    if p1.abs() <= 1e-13 * g.abs() * terms {
        0.0
    } else {
        p1
    }
}

/// The positive roots of $c_0 + c_1 u + c_2 u^2$, ascending, by the cancellation-free
/// quadratic formula (a double root counts once; a vanishing polynomial has none).
fn positive_roots(c: [f64; 3]) -> ([f64; 2], usize) {
    let (c0, c1, c2) = (c[0], c[1], c[2]);
    let mut out = [0.0; 2];
    let mut n = 0;
    let mut push = |u: f64| {
        if u > 0.0 && u.is_finite() && !out[..n].contains(&u) {
            out[n] = u;
            n += 1;
        }
    };
    if c2 == 0.0 {
        if c1 != 0.0 {
            push(-c0 / c1);
        }
    } else {
        let disc = c1 * c1 - 4.0 * c2 * c0;
        if disc >= 0.0 {
            let q = -0.5 * (c1 + c1.signum() * disc.sqrt());
            push(q / c2);
            if q != 0.0 {
                push(c0 / q);
            }
        }
    }
    if n == 2 && out[1] < out[0] {
        out.swap(0, 1);
    }
    (out, n)
}

/// The coefficients of $a_0(u)$ and $h(u)$ (lowest first) in double-double arithmetic from the
/// `f64` matrices: the same formulas as [`HurwitzPolys::new`] without their cancellation.
fn dd_coefficients(m: &Matrices, g: f64) -> ([Dd; 3], [Dd; 3]) {
    let d = |a: &Mat2| a.map(|r| r.map(Dd::from));
    let (mm, c1, k0, k2) = (d(&m.m), d(&m.c1), d(&m.k0), d(&m.k2));
    let g = Dd::from(g);
    let a0 = [g * g * det(&k0), g * mix(&k0, &k2), det(&k2)];
    let q = [g * mix(&c1, &k0), mix(&c1, &k2)];
    let r = [g * mix(&mm, &k0), mix(&mm, &k2) + det(&c1)];
    let b = mix(&mm, &c1);
    let a4 = det(&mm);
    let two = Dd::from(2.0);
    let h = [
        q[0] * r[0] * b - q[0] * q[0] * a4 - a0[0] * b * b,
        (q[0] * r[1] + q[1] * r[0]) * b - two * q[0] * q[1] * a4 - a0[1] * b * b,
        q[1] * r[1] * b - q[1] * q[1] * a4 - a0[2] * b * b,
    ];
    (a0, h)
}

/// Two Newton steps on $c_0 + c_1u + c_2u^2$ from the closed-form root `u`, the polynomial
/// evaluated in double-double: the root of the `f64` data to the last bit, whatever the
/// cancellation in the `f64` coefficients. A step that is not small is refused.
fn polish(c: &[Dd; 3], mut u: f64) -> f64 {
    for _ in 0..2 {
        let x = Dd::from(u);
        let value = ((c[2] * x + c[1]) * x + c[0]).to_f64();
        let slope = 2.0 * c[2].to_f64() * u + c[1].to_f64();
        let step = value / slope;
        if !step.is_finite() || step.abs() > 1e-6 * u {
            break;
        }
        u -= step;
    }
    u
}

/// The stable speed range by the closed-form Hurwitz route (see the [module docs](self)).
///
/// If $\det M = 0$ the polynomial has no degree 4 and no speed is reported stable. The capsize
/// speed is the lowest positive root of $a_0$ (as in
/// [`Whipple::capsize_speed`](crate::whipple::Whipple::capsize_speed)), the weave speed the
/// lowest positive root of $H_3$ where it turns positive with $a_1/a_3 > 0$.
pub fn hurwitz_window(m: &Matrices, g: f64) -> StabilityWindow {
    window(m, g, false)
}

/// [`hurwitz_window`] with the roots of $a_0$ and $h$ polished by two Newton steps on the
/// double-double coefficients (about five times the cost; speeds a few times more accurate when
/// the `f64` coefficients of $h$ cancel). Used by
/// [`Whipple::stability_window`](crate::whipple::Whipple::stability_window).
pub fn hurwitz_window_polished(m: &Matrices, g: f64) -> StabilityWindow {
    window(m, g, true)
}

fn window(m: &Matrices, g: f64, polished: bool) -> StabilityWindow {
    let mut stable: Vec<(f64, f64)> = Vec::new();
    let (weave_speed, capsize_speed) = window_into(m, g, polished, &mut |lo, hi| {
        match stable.last_mut() {
            Some(last) if last.1 == lo => last.1 = hi,
            _ => stable.push((lo, hi)),
        }
        true
    });
    StabilityWindow { weave_speed, capsize_speed, stable }
}

/// The weave and capsize speeds and whether any speed is stable, as [`hurwitz_window`] computes
/// them (the same code), without collecting the stable intervals: what a sweep keeps of each
/// design, without allocating.
pub fn hurwitz_window_summary(m: &Matrices, g: f64) -> WindowSummary {
    let mut stable = false;
    let (weave_speed, capsize_speed) = window_into(m, g, false, &mut |_, _| {
        stable = true;
        false
    });
    WindowSummary { weave_speed, capsize_speed, stable }
}

/// What a sweep keeps of one design's window.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WindowSummary {
    /// [`StabilityWindow::weave_speed`].
    pub weave_speed: Option<f64>,
    /// [`StabilityWindow::capsize_speed`].
    pub capsize_speed: Option<f64>,
    /// Whether [`StabilityWindow::stable`] is not empty.
    pub stable: bool,
}

impl From<&StabilityWindow> for WindowSummary {
    fn from(w: &StabilityWindow) -> WindowSummary {
        WindowSummary {
            weave_speed: w.weave_speed,
            capsize_speed: w.capsize_speed,
            stable: !w.stable.is_empty(),
        }
    }
}

/// The Hurwitz window: returns the weave and capsize speeds and hands every stable interval
/// between consecutive cuts, in increasing order, to `stable`, until it returns `false`.
fn window_into(
    m: &Matrices,
    g: f64,
    polished: bool,
    stable: &mut dyn FnMut(f64, f64) -> bool,
) -> (Option<f64>, Option<f64>) {
    let mut p = HurwitzPolys::new(m, g);
    let dd = polished.then(|| dd_coefficients(m, g));
    let (mut a0_roots, n_a0) = positive_roots(p.a0);
    if let Some((a0_dd, _)) = &dd {
        for u in &mut a0_roots[..n_a0] {
            *u = polish(a0_dd, *u);
        }
    }
    let capsize_speed = (n_a0 > 0).then(|| a0_roots[0].sqrt());
    if p.a4 == 0.0 || !p.a4.is_finite() {
        return (None, capsize_speed);
    }
    if p.a4 < 0.0 {
        // Same roots, a positive leading coefficient; H3 is homogeneous of degree 3.
        p.a0 = p.a0.map(|x| -x);
        p.a1_over_v = p.a1_over_v.map(|x| -x);
        p.a2 = p.a2.map(|x| -x);
        p.a3_over_v = -p.a3_over_v;
        p.a4 = -p.a4;
        p.h = p.h.map(|x| -x);
    }
    let (mut h_roots, n_h) = positive_roots(p.h);
    if let Some((_, h_dd)) = &dd {
        for u in &mut h_roots[..n_h] {
            *u = polish(h_dd, *u);
        }
    }
    let weave_speed = h_roots[..n_h]
        .iter()
        .find(|&&u| {
            let slope = p.h[1] + 2.0 * p.h[2] * u;
            let a1_over_a3 = (p.a1_over_v[0] + p.a1_over_v[1] * u) / p.a3_over_v;
            slope > 0.0 && a1_over_a3 > 0.0
        })
        .map(|u| u.sqrt());
    let (a1_roots, n_a1) = positive_roots([p.a1_over_v[0], p.a1_over_v[1], 0.0]);
    let (a2_roots, n_a2) = positive_roots([p.a2[0], p.a2[1], 0.0]);
    let mut cuts = [0.0; 8];
    let mut n = 0;
    for (roots, k) in [(a0_roots, n_a0), (a1_roots, n_a1), (a2_roots, n_a2), (h_roots, n_h)] {
        for &u in &roots[..k] {
            cuts[n] = u.sqrt();
            n += 1;
        }
    }
    let cuts = &mut cuts[..n];
    cuts.sort_by(f64::total_cmp);
    let stable_at = |v: f64| p.at(v).iter().all(|&x| x > 0.0);
    let mut lo = 0.0;
    for hi in cuts.iter().copied().chain([f64::INFINITY]) {
        if hi > lo {
            let mid = if hi.is_finite() { 0.5 * (lo + hi) } else { 2.0 * lo + 1.0 };
            if stable_at(mid) && !stable(lo, hi) {
                break;
            }
        }
        lo = hi;
    }
    (weave_speed, capsize_speed)
}

/// The speed grid of [`eigen_window`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EigenGrid {
    /// The highest speed looked at (m/s); the grid is $v_i = i\,v_{\max}/n$, $i = 1..n$.
    pub vmax: f64,
    /// The number of grid points.
    pub points: usize,
}

impl Default for EigenGrid {
    /// 200 points up to 10 m/s (a step of 5 cm/s).
    fn default() -> EigenGrid {
        EigenGrid { vmax: 10.0, points: 200 }
    }
}

/// The largest real part and whether the eigenvalue that has it is complex; `None` if the
/// eigenvalues could not be computed.
fn critical(m: &Matrices, g: f64, v: f64) -> Option<(f64, bool)> {
    let ev = eigenvalues4(&state_matrix(m, g, v))?;
    let top = ev.iter().max_by(|a, b| a.re.total_cmp(&b.re))?;
    Some((top.re, top.im != 0.0))
}

/// The stable speed range by eigenvalues on a speed grid, each change of stability bisected to
/// adjacent floats (see the [module docs](self)).
///
/// A stable interval still open at the grid's last point ends at `grid.vmax`. The weave speed
/// is the lowest boundary where the speed becomes stable as a complex pair's real part crosses
/// zero, the capsize speed the lowest boundary where a real eigenvalue crosses zero. `None` if
/// the eigenvalues fail to converge at any grid point.
pub fn eigen_window(m: &Matrices, g: f64, grid: EigenGrid) -> Option<StabilityWindow> {
    window_of_critical(|v| critical(m, g, v), grid)
}

/// The stable speed range on `grid` from `f(v)` = (the largest real part of the eigenvalues at
/// speed v, whether the eigenvalue that has it is complex), as [`eigen_window`] does for the
/// undamped bicycle (and `whipple::friction` with steer friction). `None` if `f` does.
pub fn window_of_critical(
    f: impl Fn(f64) -> Option<(f64, bool)>,
    grid: EigenGrid,
) -> Option<StabilityWindow> {
    let mut stable: Vec<(f64, f64)> = Vec::new();
    let (mut weave, mut capsize) = (None, None);
    let mut prev_v = grid.vmax / grid.points as f64;
    let mut prev = f(prev_v)?;
    let mut open = (prev.0 < 0.0).then_some(prev_v);
    for i in 2..=grid.points {
        let v = grid.vmax * i as f64 / grid.points as f64;
        let cur = f(v)?;
        if (cur.0 < 0.0) != (prev.0 < 0.0) {
            // Bisect to adjacent floats; `lo` keeps the sign of `prev`.
            let (mut lo, mut hi) = (prev_v, v);
            let mut at_hi = cur;
            loop {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                let fm = f(mid)?;
                if (fm.0 < 0.0) == (prev.0 < 0.0) {
                    lo = mid;
                } else {
                    hi = mid;
                    at_hi = fm;
                }
            }
            let becomes_stable = cur.0 < 0.0;
            // The eigenvalue that crosses is the critical one on the unstable side.
            let complex = if becomes_stable { f(lo)?.1 } else { at_hi.1 };
            let edge = if becomes_stable { hi } else { lo };
            if complex && becomes_stable && weave.is_none() {
                weave = Some(edge);
            }
            if !complex && capsize.is_none() {
                capsize = Some(edge);
            }
            if becomes_stable {
                open = Some(edge);
            } else if let Some(start) = open.take() {
                stable.push((start, edge));
            }
        }
        prev_v = v;
        prev = cur;
    }
    if let Some(start) = open {
        stable.push((start, grid.vmax));
    }
    Some(StabilityWindow { weave_speed: weave, capsize_speed: capsize, stable })
}

/// Bisects a sign change of `f` on `[lo, hi]` down to adjacent floats.
fn bisect(f: &dyn Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let mut flo = f(lo);
    for _ in 0..2000 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let fm = f(mid);
        if fm == 0.0 {
            return mid;
        }
        if (fm > 0.0) == (flo > 0.0) {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
        }
    }
    if f(hi).abs() < flo.abs() {
        hi
    } else {
        lo
    }
}

/// The positive roots of `f`, a polynomial in $v$ with coefficients `p` (lowest first), by a
/// 200 000-point quadratic-spaced scan below Cauchy's bound and bisection.
fn scan_roots(p: &[f64], f: &dyn Fn(f64) -> f64) -> Vec<f64> {
    let mut p = p.to_vec();
    while p.last().is_some_and(|x| *x == 0.0) {
        p.pop();
    }
    let Some(&lead) = p.last() else { return Vec::new() };
    if p.len() < 2 {
        return Vec::new();
    }
    let bound = 1.0 + p[..p.len() - 1].iter().map(|c| (c / lead).abs()).fold(0.0, f64::max);
    let n = 200_000usize;
    let mut roots = Vec::new();
    let mut prev_x = bound * 1e-9;
    let mut prev = f(prev_x);
    for i in 1..=n {
        let t = i as f64 / n as f64;
        let x = bound * t * t;
        if x <= prev_x {
            continue;
        }
        let y = f(x);
        if y == 0.0 {
            roots.push(x);
        } else if prev != 0.0 && (y > 0.0) != (prev > 0.0) {
            roots.push(bisect(f, prev_x, x));
        }
        prev_x = x;
        prev = y;
    }
    roots
}

/// The former `Whipple::stability_window`: each Hurwitz function as a polynomial in $v$,
/// scanned at 200 000 points below its Cauchy bound, each sign change bisected; then the
/// Routh–Hurwitz test between cuts. Its weave speed is the lowest root of $H_3$ where $H_3$
/// turns positive (without the $a_1/a_3 > 0$ test). About 60 ms per call.
pub fn scan_window(m: &Matrices, g: f64) -> StabilityWindow {
    let p = HurwitzPolys::new(m, g);
    // The same functions as polynomials in v (lowest first).
    let in_v: [Vec<f64>; 5] = [
        vec![p.a0[0], 0.0, p.a0[1], 0.0, p.a0[2]],
        vec![0.0, p.a1_over_v[0], 0.0, p.a1_over_v[1]],
        vec![p.a2[0], 0.0, p.a2[1]],
        vec![0.0, p.a3_over_v],
        vec![0.0, 0.0, p.h[0], 0.0, p.h[1], 0.0, p.h[2]],
    ];
    let idx = [0, 1, 2, 3, 5];
    let mut cuts: Vec<f64> = Vec::new();
    for (k, poly) in in_v.iter().enumerate() {
        let f = |v: f64| p.at(v)[idx[k]];
        cuts.extend(scan_roots(poly, &f));
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let stable_at = |v: f64| p.at(v).iter().all(|&x| x > 0.0);
    let mut edges = vec![0.0];
    edges.extend(cuts.iter().copied());
    let mut stable: Vec<(f64, f64)> = Vec::new();
    for (i, &lo) in edges.iter().enumerate() {
        let hi = edges.get(i + 1).copied().unwrap_or(f64::INFINITY);
        let mid = if hi.is_finite() { 0.5 * (lo + hi) } else { 2.0 * lo + 1.0 };
        if stable_at(mid) {
            match stable.last_mut() {
                Some(last) if last.1 == lo => last.1 = hi,
                _ => stable.push((lo, hi)),
            }
        }
    }
    let h = |v: f64| p.at(v)[5];
    let weave_speed = scan_roots(&in_v[4], &h).into_iter().find(|&r| {
        let d = 1e-6 * r.max(1e-6);
        h(r - d) < 0.0 && h(r + d) > 0.0
    });
    let capsize_speed = hurwitz_window(m, g).capsize_speed;
    StabilityWindow { weave_speed, capsize_speed, stable }
}

const RM: RoundingMode = RoundingMode::ToEven;

/// The weave and capsize speeds computed at `bits` bits from the matrices evaluated at `bits`
/// bits (the reference of `carvallo bench`'s table 2): the closed-form quadratics of this
/// module in high precision, picking the root nearest `near` (the `f64` result). Returns `None`
/// for a speed the `f64` route did not find.
pub fn reference_speeds(
    params: &WhippleParams,
    near: (Option<f64>, Option<f64>),
    bits: usize,
) -> (Option<f64>, Option<f64>) {
    let program = Program::parse(crate::artifacts::WHIPPLE.ir).expect("whipple.ir parses");
    let names = [
        "m11", "m12", "m21", "m22", "c1_11", "c1_12", "c1_21", "c1_22", "k0_11", "k0_12", "k0_21",
        "k0_22", "k2_11", "k2_12", "k2_21", "k2_22",
    ];
    let program = program.select_outputs(&names).expect("whipple.ir has the matrices");
    let args: Vec<f64> = program.params.iter().map(|n| params.get(n).unwrap_or(f64::NAN)).collect();
    let Ok(o) = hp::eval(&program, &args, &[], bits) else { return (None, None) };
    let p = bits;
    let b = |x: f64| hp::from_f64(x, p);
    let mul = |a: &BigFloat, c: &BigFloat| a.mul(c, p, RM);
    let add = |a: &BigFloat, c: &BigFloat| a.add(c, p, RM);
    let sub = |a: &BigFloat, c: &BigFloat| a.sub(c, p, RM);
    let mat = |k: usize| [[o[k].clone(), o[k + 1].clone()], [o[k + 2].clone(), o[k + 3].clone()]];
    let (m, c1, k0, k2) = (mat(0), mat(4), mat(8), mat(12));
    let mix = |x: &[[BigFloat; 2]; 2], y: &[[BigFloat; 2]; 2]| {
        sub(
            &sub(
                &add(&mul(&x[0][0], &y[1][1]), &mul(&y[0][0], &x[1][1])),
                &mul(&x[0][1], &y[1][0]),
            ),
            &mul(&y[0][1], &x[1][0]),
        )
    };
    let det = |x: &[[BigFloat; 2]; 2]| sub(&mul(&x[0][0], &x[1][1]), &mul(&x[0][1], &x[1][0]));
    let g = b(params.get("g").unwrap_or(f64::NAN));
    let a0 = [mul(&mul(&g, &g), &det(&k0)), mul(&g, &mix(&k0, &k2)), det(&k2)];
    let q = [mul(&g, &mix(&c1, &k0)), mix(&c1, &k2)];
    let r = [mul(&g, &mix(&m, &k0)), add(&mix(&m, &k2), &det(&c1))];
    let bb = mix(&m, &c1);
    let a4 = det(&m);
    let b2 = mul(&bb, &bb);
    let h = [
        sub(&sub(&mul(&mul(&q[0], &r[0]), &bb), &mul(&mul(&q[0], &q[0]), &a4)), &mul(&a0[0], &b2)),
        sub(
            &sub(
                &mul(&add(&mul(&q[0], &r[1]), &mul(&q[1], &r[0])), &bb),
                &mul(&mul(&b(2.0), &mul(&q[0], &q[1])), &a4),
            ),
            &mul(&a0[1], &b2),
        ),
        sub(&sub(&mul(&mul(&q[1], &r[1]), &bb), &mul(&mul(&q[1], &q[1]), &a4)), &mul(&a0[2], &b2)),
    ];
    // Both roots u of c0 + c1 u + c2 u^2, then v = sqrt(u), nearest to `target`.
    let speed = |c: &[BigFloat; 3], target: Option<f64>| -> Option<f64> {
        let target = target?;
        if c[2].is_zero() {
            let u = c[0].neg().div(&c[1], p, RM);
            return u.is_positive().then(|| hp::to_f64(&u.sqrt(p, RM)));
        }
        let disc = sub(&mul(&c[1], &c[1]), &mul(&b(4.0), &mul(&c[2], &c[0])));
        if disc.is_negative() {
            return None;
        }
        let sq = disc.sqrt(p, RM);
        let two_c2 = mul(&b(2.0), &c[2]);
        let roots =
            [sub(&sq, &c[1]).div(&two_c2, p, RM), sq.neg().sub(&c[1], p, RM).div(&two_c2, p, RM)];
        roots
            .iter()
            .filter(|u| u.is_positive())
            .map(|u| hp::to_f64(&u.sqrt(p, RM)))
            .min_by(|x, y| (x - target).abs().total_cmp(&(y - target).abs()))
    };
    (speed(&h, near.0), speed(&a0, near.1))
}
