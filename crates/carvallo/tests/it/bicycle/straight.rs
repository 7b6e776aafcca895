//! Tests of Carvallo's bicycle without hands near straight running (memoir n° 117–123):
//! his closed forms against the general model's exact linearisation, the quartic against the
//! eigenvalues of the first-order system, the stability window against those eigenvalues, the
//! closed-form upper limit against the scanned one, and rejection of bad constants by name.

#![allow(clippy::needless_range_loop)]

use carvallo::bicycle::straight::{
    friction_half_swing, hurwitz, memoir_quartic_120, window, Constants, Equations, Part,
};
use nalgebra::Matrix4;

/// Relative tolerance between two evaluations of the same exact expression in `f64`.
const SAME: f64 = 1e-12;

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * a.abs().max(b.abs()).max(1e-12)
}

/// Eigenvalues (in real time t) of the two equations at spin `s`, from the 4 × 4 state matrix.
fn eigen(e: &Equations, s: f64) -> Vec<(f64, f64)> {
    let m = e.m;
    let d = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    let inv = [[m[1][1] / d, -m[0][1] / d], [-m[1][0] / d, m[0][0] / d]];
    let mut a = Matrix4::zeros();
    a[(0, 2)] = 1.0;
    a[(1, 3)] = 1.0;
    for r in 0..2 {
        for c in 0..2 {
            let (mut kk, mut cc) = (0.0, 0.0);
            for j in 0..2 {
                kk += inv[r][j] * (e.k0[j][c] + e.k2[j][c] * s * s);
                cc += inv[r][j] * e.c[j][c] * s;
            }
            a[(2 + r, c)] = -kk;
            a[(2 + r, 2 + c)] = -cc;
        }
    }
    a.complex_eigenvalues().iter().map(|z| (z.re, z.im)).collect()
}

#[test]
fn formulas_equal_the_general_model() {
    for k in [
        Constants::MEMOIR,
        Constants::MEMOIR_NEW,
        Constants { c1: 0.05, eta: 0.3, ..Constants::MEMOIR },
    ] {
        let f = Equations::from_formulas(&k).expect("valid");
        let g = Equations::via_whipple(&k).expect("valid");
        for s in [0.5, 3.0, 8.2, 20.0] {
            let (a, b) = (f.coefficients(s), g.coefficients(s));
            let scale = a.iter().map(|x| x.abs()).fold(0.0, f64::max);
            for i in 0..12 {
                assert!(
                    (a[i] - b[i]).abs() <= SAME * scale,
                    "coefficient {i} at s = {s}: {} vs {}",
                    a[i],
                    b[i]
                );
            }
        }
    }
}

#[test]
fn quartic_roots_are_the_eigenvalues() {
    let f = Equations::from_formulas(&Constants::MEMOIR).expect("valid");
    for s in [2.0, 8.0, 8.5, 9.5] {
        let q = f.quartic(s);
        for (re, im) in eigen(&f, s) {
            // lambda = eigenvalue / s (T = s t).
            let (lr, li) = (re / s, im / s);
            let (mut pr, mut pi) = (0.0, 0.0);
            let (mut zr, mut zi) = (1.0, 0.0);
            let mut scale = 0.0;
            for qk in q {
                pr += qk * zr;
                pi += qk * zi;
                scale += (qk * (zr * zr + zi * zi).sqrt()).abs();
                (zr, zi) = (zr * lr - zi * li, zr * li + zi * lr);
            }
            assert!((pr * pr + pi * pi).sqrt() <= 1e-10 * scale, "s = {s}: residual {pr} {pi}");
        }
    }
}

#[test]
fn window_matches_the_eigenvalues() {
    let k = Constants::MEMOIR;
    for e in [Equations::memoir_118(), Equations::from_formulas(&k).expect("valid")] {
        let w = window(&|s| e.quartic(s));
        let (lo, hi) = (w.weave_s.expect("weave"), w.capsize_s.expect("capsize"));
        assert_eq!(w.stable_s, vec![(lo, hi)]);
        let max_re = |s: f64| eigen(&e, s).iter().map(|z| z.0).fold(f64::NEG_INFINITY, f64::max);
        for (s, stable) in [
            (lo * 0.98, false),
            (lo * 1.02, true),
            (0.5 * (lo + hi), true),
            (hi * 1.02, false),
            (3.0, false),
        ] {
            assert_eq!(max_re(s) < 0.0, stable, "s = {s}, window {lo}..{hi}");
            assert_eq!(
                hurwitz(&e.quartic(s)).iter().all(|x| *x > 0.0),
                stable,
                "hurwitz at s = {s}"
            );
        }
    }
    // The printed n° 120 quartic: its capsize limit is 95.6/1.143 in s^2.
    let w = window(&memoir_quartic_120);
    assert!(close(w.capsize_s.expect("capsize").powi(2), 95.6 / 1.143, 1e-12));
}

#[test]
fn closed_form_upper_limit_is_the_scanned_one() {
    for k in [Constants::MEMOIR, Constants::MEMOIR_NEW] {
        let e = Equations::from_formulas(&k).expect("valid");
        let w = window(&|s| e.quartic(s));
        let (closed, _) = k.upper_limit_s2();
        assert!(close(w.capsize_s.expect("capsize").powi(2), closed, 1e-12), "{closed}");
        // With c1 = R sin(eta)/2 the simplified form equals the general one.
        let half = Constants { c1: 0.5 * k.r * k.eta.sin(), ..k };
        let (g, h) = half.upper_limit_s2();
        assert!(close(g, h, SAME), "{g} vs {h}");
    }
}

#[test]
fn friction_swing_closed_forms() {
    let (t, th) = friction_half_swing(2.0, 0.05, 0.4, 0.0, 4000);
    assert!(close(th, 0.4 - 0.1, 1e-9), "{th}");
    assert!(close(t, std::f64::consts::PI / 2.0, 1e-9), "{t}");
    // With negative damping the exact half period is pi / sqrt(a^2 - eps^2).
    let (a, eps) = (2.0, 0.05);
    let (t, th) = friction_half_swing(a, 0.05, 0.4, eps, 4000);
    let w = (a * a - eps * eps).sqrt();
    assert!(close(t, std::f64::consts::PI / w, 1e-9), "{t}");
    assert!(close(th, -0.05 + 0.35 * (eps * std::f64::consts::PI / w).exp(), 1e-9), "{th}");
}

#[test]
fn bad_constants_are_named() {
    let bad = Constants { mu1: 0.0, ..Constants::MEMOIR };
    assert_eq!(
        Equations::via_whipple(&bad).unwrap_err().to_string(),
        "invalid mu1 0.0: must be positive"
    );
    let bad = Constants { a2: 1.0, ..Constants::MEMOIR };
    assert_eq!(
        Equations::from_formulas(&bad).unwrap_err().to_string(),
        "invalid a2 1.0: must exceed the wheels' 3 mu1 r^2"
    );
    let bad = Constants { ll: f64::NAN, ..Constants::MEMOIR };
    assert_eq!(
        Equations::from_formulas(&bad).unwrap_err().to_string(),
        "invalid ll NaN: must be finite"
    );
}

/// The three parts of the n° 116 tables sum to the general model's whole equations (its
/// equations are linear in the masses and moments), at three constant sets, and the parts'
/// second-derivative terms are the n° 109–111 expressions evaluated by hand.
#[test]
fn parts_sum_to_the_general_model() {
    let sets = [
        Constants::MEMOIR,
        Constants::MEMOIR_NEW,
        Constants { c1: 0.05, eta: 0.3, ll: 11.0, c: 6.0, ..Constants::MEMOIR },
    ];
    for k in sets {
        let whole = Equations::via_whipple(&k).expect("valid");
        let parts = Part::ALL.map(|p| Equations::via_whipple_part(&k, p).expect("valid"));
        let pick = |e: &Equations| [e.m, e.c, e.k0, e.k2];
        let w = pick(&whole);
        let scale = w.iter().flatten().flatten().map(|x| x.abs()).fold(0.0, f64::max);
        for n in 0..4 {
            for r in 0..2 {
                for c in 0..2 {
                    let sum: f64 = parts.iter().map(|p| pick(p)[n][r][c]).sum();
                    assert!(
                        (sum - w[n][r][c]).abs() <= SAME * scale,
                        "{k:?}: matrix {n} ({r}, {c}): parts {sum} vs whole {}",
                        w[n][r][c]
                    );
                }
            }
        }
        let (a1, c1w, kk) = (1.5 * k.mu1 * k.r * k.r, 0.5 * k.mu1 * k.r * k.r, k.c1 / k.l);
        let (sn, co) = (k.eta.sin(), k.eta.cos());
        let [frame, rear, front] = parts;
        for (got, want) in [
            (frame.m[0][1], -k.ll * kk),
            (front.m[0][1], -a1 * sn),
            (rear.m[0][1], 0.0),
            (frame.m[1][1], k.c * kk * kk),
            (rear.m[1][1], c1w * kk * kk),
            (front.m[1][1], a1 * sn * sn + c1w * (kk + co).powi(2)),
        ] {
            assert!((got - want).abs() <= SAME * scale, "{k:?}: part term {got} vs {want}");
        }
    }
}
