//! Stability windows of the linearised Carvallo–Whipple bicycle, fast and by reference routes,
//! and sweeps over many designs.
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
//! # Sweeps
//!
//! [`sweep`] computes the window for `count` designs that vary one parameter linearly between
//! two values, in parallel with rayon, and summarises them ([`SweepSummary`]).
//! [`sweep_designs`] does the same for a grid of several parameters or for seeded random designs
//! around a base ([`Designs`]), optionally keeping every design's varied values and window
//! ([`SweepOutput`]). Both evaluate the matrices four designs per call
//! (`matrices_scene::eval_lanes`, bit for bit the scalar evaluator lane by lane) and keep of each
//! window only [`hurwitz_window_summary`], the same code as [`hurwitz_window`] without the
//! allocation of the stable intervals.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use nalgebra::Matrix4;
use rayon::prelude::*;

use crate::certified::Dd;
use crate::whipple::{
    matrices_scene, Eigenvalue, Mat2, Matrices, StabilityWindow, WhippleError, WhippleParams,
    PARAM_NAMES,
};

fn mix(a: &Mat2, b: &Mat2) -> f64 {
    a[0][0] * b[1][1] + b[0][0] * a[1][1] - a[0][1] * b[1][0] - b[0][1] * a[1][0]
}

fn det(a: &Mat2) -> f64 {
    a[0][0] * a[1][1] - a[0][1] * a[1][0]
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
        let a0 = [g * g * det(&k0), g * mix(&k0, &k2), det(&k2)];
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
    let mix = |a: &[[Dd; 2]; 2], b: &[[Dd; 2]; 2]| {
        a[0][0] * b[1][1] + b[0][0] * a[1][1] - a[0][1] * b[1][0] - b[0][1] * a[1][0]
    };
    let det = |a: &[[Dd; 2]; 2]| a[0][0] * a[1][1] - a[0][1] * a[1][0];
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

/// The state matrix of $(\varphi, \delta, \varphi', \delta')$ at speed `v`.
pub fn state_matrix(m: &Matrices, g: f64, v: f64) -> Matrix4<f64> {
    let Matrices { m, c1, k0, k2 } = *m;
    let dm = det(&m);
    let minv = [[m[1][1] / dm, -m[0][1] / dm], [-m[1][0] / dm, m[0][0] / dm]];
    let mut a = Matrix4::zeros();
    a[(0, 2)] = 1.0;
    a[(1, 3)] = 1.0;
    for r in 0..2 {
        for c in 0..2 {
            let (mut kk, mut cc) = (0.0, 0.0);
            for j in 0..2 {
                kk += minv[r][j] * (g * k0[j][c] + v * v * k2[j][c]);
                cc += minv[r][j] * v * c1[j][c];
            }
            a[(2 + r, c)] = -kk;
            a[(2 + r, 2 + c)] = -cc;
        }
    }
    a
}

/// The largest number of QR sweeps the Schur decomposition may take before giving up.
pub const MAX_SCHUR_ITERATIONS: usize = 500;

/// The four eigenvalues of `a`, or `None` if the Schur decomposition does not converge within
/// [`MAX_SCHUR_ITERATIONS`] (nalgebra's uncapped `complex_eigenvalues` can loop for ever on
/// matrices such as the companion of $x^4 + 1$).
pub fn eigenvalues4(a: &Matrix4<f64>) -> Option<[Eigenvalue; 4]> {
    let schur = a.try_schur(f64::EPSILON, MAX_SCHUR_ITERATIONS)?;
    let z = schur.complex_eigenvalues();
    let out = [0, 1, 2, 3].map(|i| Eigenvalue { re: z[i].re, im: z[i].im });
    out.iter().all(|e| e.re.is_finite() && e.im.is_finite()).then_some(out)
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
    let f = |v: f64| critical(m, g, v);
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

/// The matrices of a parameter vector (in the order of [`PARAM_NAMES`]), without validation.
/// `index[i]` is the position in [`PARAM_NAMES`] of the scene's `i`-th parameter.
fn matrices_of(values: &[f64; 26], index: &[usize]) -> Matrices {
    let n = matrices_scene::Args::LEN;
    let arr: [f64; matrices_scene::Args::LEN] =
        std::array::from_fn(|i| if i < n { values[index[i]] } else { f64::NAN });
    let o = matrices_scene::eval_array(&arr);
    let r = |k: usize| [[o[k], o[k + 1]], [o[k + 2], o[k + 3]]];
    Matrices { m: r(0), c1: r(4), k0: r(8), k2: r(12) }
}

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
    /// from the seeded SplitMix64 stream [`Rng`](crate::bench::Rng) of design $i$ (seed
    /// `seed + i`), so that the designs do not depend on the number of threads. A draw that
    /// [`WhippleParams::from_values`] rejects is redrawn from the same stream, at most
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
    /// More designs than a `usize` holds.
    TooManyDesigns,
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
            DesignsError::TooManyDesigns => write!(f, "too many designs"),
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
    /// How many random designs were rejected (always 0 for a grid).
    pub rejected: usize,
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

/// Designs processed per parallel task (a multiple of the lanes).
const CHUNK: usize = 4096;
/// Designs per call of [`matrices_scene::eval_lanes`].
const LANES: usize = matrices_scene::LANES;

/// Computes the window of every design of `designs` (a grid or random designs around `base`),
/// in parallel with rayon, four designs per evaluation of the matrices
/// ([`matrices_scene::eval_lanes`], bit for bit the scalar evaluator, so the answers are those
/// of [`hurwitz_window`] or [`eigen_window`] design by design). With `record` the varied values
/// and the window of every design are kept in [`SweepOutput`]. `progress` is increased by the
/// number of designs done as chunks finish.
///
/// The corners of a grid are validated with [`WhippleParams::from_values`]: its checks are
/// linear inequalities (intervals, positive values, triangle inequalities of the moments of
/// inertia), whose valid set is convex, so every design of the grid is valid too.
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
    let base_values = *base.values();
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
                count = count.checked_mul(a.count).ok_or(DesignsError::TooManyDesigns)?;
            }
            // Every corner of the box (2^axes of them; the axes are few).
            for corner in 0..1usize << axes.len().min(20) {
                let mut v = base_values;
                for (j, (a, &k)) in axes.iter().zip(&keys).enumerate() {
                    v[k] = if corner >> j & 1 == 0 { a.from } else { a.to };
                }
                WhippleParams::from_values(v)
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
    // Design i's parameter vector; false for a rejected random design.
    let fill = |i: usize, v: &mut [f64; 26]| -> bool {
        match designs {
            Designs::Grid(axes) => {
                let mut rest = i;
                for (a, &k) in axes.iter().zip(&keys).rev() {
                    v[k] = a.at(rest % a.count);
                    rest /= a.count;
                }
                true
            }
            Designs::Random { spreads, seed, .. } => {
                let mut rng = crate::bench::Rng::new(seed.wrapping_add(i as u64));
                for _ in 0..MAX_DRAWS {
                    for (s, &k) in spreads.iter().zip(&keys) {
                        v[k] = rng.scale(base_values[k], s.rel);
                    }
                    if crate::whipple::valid_fast(v) {
                        return true;
                    }
                }
                false
            }
        }
    };
    let index: Vec<usize> = matrices_scene::PARAMS
        .iter()
        .map(|p| PARAM_NAMES.iter().position(|n| n == p).unwrap_or(0))
        .collect();
    let g = base.get("g").unwrap_or(f64::NAN);
    let n_names = names.len();
    let start = Instant::now();
    let parts: Vec<Part> = (0..count.div_ceil(CHUNK))
        .into_par_iter()
        .map(|c| {
            let (lo, hi) = (c * CHUNK, ((c + 1) * CHUNK).min(count));
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
                        let args: [[f64; LANES]; matrices_scene::Args::LEN] =
                            std::array::from_fn(|a| std::array::from_fn(|j| values[j][index[a]]));
                        let o = matrices_scene::eval_lanes(&args);
                        std::array::from_fn(|j| {
                            let r = |k: usize| [[o[k][j], o[k + 1][j]], [o[k + 2][j], o[k + 3][j]]];
                            let m = Matrices { m: r(0), c1: r(4), k0: r(8), k2: r(12) };
                            Some(hurwitz_window_summary(&m, g))
                        })
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
        })
        .collect();
    let elapsed = start.elapsed().as_secs_f64();
    let mut acc = Acc::EMPTY;
    let (mut values, mut windows, mut valid, mut rejected) =
        (Vec::new(), Vec::new(), Vec::new(), 0);
    for p in parts {
        acc = acc.merge(p.acc);
        rejected += p.rejected;
        values.extend(p.values);
        windows.extend(p.windows);
        valid.extend(p.valid);
    }
    let range = |n: usize, r: (f64, f64)| (n > 0).then_some(r);
    let summary = SweepSummary {
        count,
        elapsed,
        designs_per_second: count as f64 / elapsed,
        stable: acc.stable,
        with_weave: acc.weave,
        with_capsize: acc.capsize,
        weave_range: range(acc.weave, acc.weave_range),
        capsize_range: range(acc.capsize, acc.capsize_range),
        failed: acc.failed,
    };
    Ok(SweepOutput { summary, names, values, windows, valid, rejected })
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
