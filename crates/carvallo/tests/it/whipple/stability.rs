//! The fast closed-form stability window against two independent routes (eigenvalues on a
//! speed grid with bisection, and the former dense scan), the Orlando root of $H_3$ that is not
//! a weave speed, the 256-bit reference speeds, and the parallel sweep's summary.
//!
//! Tolerances: window edges relative 1e-9 between routes (the eigenvalue route bisects the
//! largest real part, whose slope in v is of order one, so it is accurate to about 1e-12); the
//! benchmark's speeds relative 1e-13 against the 256-bit reference.

use std::sync::atomic::AtomicUsize;

use carvallo::numerics::rng::SplitMix64;
use carvallo::whipple::stability::{self, reference_speeds, EigenGrid, HurwitzPolys};
use carvallo::whipple::sweep::{self, Method};
use carvallo::whipple::{Whipple, WhippleParams};

fn close(a: Option<f64>, b: Option<f64>, tol: f64) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => ((a - b) / b).abs() <= tol,
        (None, None) => true,
        _ => false,
    }
}

fn parts(w: &Whipple) -> (carvallo::whipple::Matrices, f64) {
    (w.matrices(), w.params().get("g").unwrap())
}

#[test]
fn fast_window_agrees_with_scan_and_eigenvalues() {
    let mut rng = SplitMix64(42);
    let mut designs = vec![WhippleParams::benchmark()];
    designs.extend((0..12).map(|_| WhippleParams::benchmark().perturbed(&mut rng, 0.2)));
    let grid = EigenGrid { vmax: 30.0, points: 600 };
    let mut orlando = 0;
    for (i, d) in designs.into_iter().enumerate() {
        let w = Whipple::new(d);
        let (m, g) = parts(&w);
        let fast = stability::hurwitz_window(&m, g);
        let scan = stability::scan_window(&m, g);
        assert!(close(fast.capsize_speed, scan.capsize_speed, 0.0), "design {i}");
        if !close(fast.weave_speed, scan.weave_speed, 1e-9) {
            // The former scan also took roots of H3 where two real eigenvalues +-r pass
            // each other (a1/a3 < 0, Orlando); the fast route skips them.
            let vs = scan.weave_speed.expect("the scan found a root the fast route skipped");
            let h = HurwitzPolys::new(&m, g);
            let u = vs * vs;
            let ratio = (h.a1_over_v[0] + h.a1_over_v[1] * u) / h.a3_over_v;
            assert!(ratio < 0.0, "design {i}: {fast:?} {scan:?}");
            assert!(fast.weave_speed.is_none_or(|v| v > vs), "design {i}");
            orlando += 1;
        }
        assert_eq!(fast.stable.len(), scan.stable.len(), "design {i}");
        for (a, b) in fast.stable.iter().zip(&scan.stable) {
            assert!(close(Some(a.0), Some(b.0), 1e-9) || a.0 == b.0, "design {i}");
            assert!(a.1 == b.1 || close(Some(a.1), Some(b.1), 1e-9), "design {i}");
        }
        let eig = stability::eigen_window(&m, g, grid).expect("eigenvalues converge");
        // Intervals inside the grid's range agree.
        let inside: Vec<(f64, f64)> = fast
            .stable
            .iter()
            .filter(|iv| iv.0 < grid.vmax)
            .map(|&(a, b)| (a, b.min(grid.vmax)))
            .collect();
        assert_eq!(inside.len(), eig.stable.len(), "design {i}: {fast:?} vs {eig:?}");
        for (a, b) in inside.iter().zip(&eig.stable) {
            assert!(((a.0 - b.0) / a.0).abs() <= 1e-9, "design {i}: {a:?} vs {b:?}");
            assert!(((a.1 - b.1) / a.1).abs() <= 1e-9, "design {i}: {a:?} vs {b:?}");
        }
        if fast.weave_speed.is_some_and(|v| v < grid.vmax) {
            assert!(close(fast.weave_speed, eig.weave_speed, 1e-9), "design {i}");
        }
    }
    eprintln!("{orlando} of 13 designs have an H3 root with real eigenvalues +-r");
}

#[test]
fn benchmark_speeds_are_within_1e_13_of_the_256_bit_values() {
    let w = Whipple::new(WhippleParams::benchmark());
    let win = w.stability_window();
    let (rw, rc) = reference_speeds(w.params(), (win.weave_speed, win.capsize_speed), 256);
    for (got, want) in [(win.weave_speed, rw), (win.capsize_speed, rc)] {
        let (got, want) = (got.unwrap(), want.unwrap());
        let rel = ((got - want) / want).abs();
        eprintln!("{got:.17} vs 256-bit {want:.17}: {rel:.1e}");
        assert!(rel <= 1e-13, "{got} vs {want}");
    }
    // Random designs: the polished closed form against the 256-bit speeds, and the eigenvalue
    // route's edges against the same reference.
    let mut rng = SplitMix64(99);
    let (mut worst_h, mut worst_e, mut worst_both) = (0.0f64, 0.0f64, 0.0f64);
    let mut compared = 0;
    for _ in 0..30 {
        let w = Whipple::new(WhippleParams::benchmark().perturbed(&mut rng, 0.2));
        let (m, g) = parts(&w);
        let win = stability::hurwitz_window(&m, g);
        let (rw, rc) = reference_speeds(w.params(), (win.weave_speed, win.capsize_speed), 256);
        for (got, want) in [(win.weave_speed, rw), (win.capsize_speed, rc)] {
            if let (Some(got), Some(want)) = (got, want) {
                worst_h = worst_h.max(((got - want) / want).abs());
            }
        }
        let eig = stability::eigen_window(&m, g, EigenGrid::default()).unwrap();
        let pairs =
            [(eig.weave_speed, win.weave_speed, rw), (eig.capsize_speed, win.capsize_speed, rc)];
        for (got, fast, want) in pairs {
            if let (Some(got), Some(want)) = (got, want) {
                if fast.is_some_and(|h| (h - got).abs() < 1e-6 * h) {
                    worst_e = worst_e.max(((got - want) / want).abs());
                    worst_both = worst_both.max(((fast.unwrap() - want) / want).abs());
                    compared += 1;
                }
            }
        }
    }
    eprintln!(
        "30 random designs: hurwitz {worst_h:.1e} ({worst_both:.1e} on the {compared} speeds \
         the eigenvalue sweep also finds), eigenvalue sweep {worst_e:.1e}"
    );
    assert!(worst_h <= HURWITZ_TOL, "hurwitz {worst_h:e}");
    assert!(compared >= 40, "the eigenvalue sweep found only {compared} of the 60 speeds");
    assert!(worst_e <= EIGEN_TOL, "eigenvalue sweep {worst_e:e}");
}

/// The polished closed form's speeds carry only the error of the `f64` matrices.
const HURWITZ_TOL: f64 = 1e-13;

/// The eigenvalue sweep bisects the sign of the largest real part to adjacent floats: its
/// edges carry the eigenvalues' rounding (about $\epsilon\,\|A\|$, $\|A\|$ of order 100) over
/// the real part's slope in $v$ (of order one), some 1e-14 (measured 2.2e-14 over these 30
/// designs).
const EIGEN_TOL: f64 = 1e-13;

/// Orlando: $H_3$ also vanishes when two real eigenvalues $\pm r$ pass each other; there
/// $a_1/a_3 = -r^2 < 0$ and it is not a weave speed.
#[test]
fn a_root_of_h3_with_real_eigenvalues_is_not_a_weave_speed() {
    let mut rng = SplitMix64(2026);
    let base = *WhippleParams::benchmark().values();
    let mut found = None;
    'search: for _ in 0..200_000 {
        let v = base.map(|x| rng.scale(x, 0.9));
        let Ok(p) = WhippleParams::from_values(v) else { continue };
        let w = Whipple::new(p);
        let (m, g) = parts(&w);
        let h = HurwitzPolys::new(&m, g);
        let disc = h.h[1] * h.h[1] - 4.0 * h.h[0] * h.h[2];
        if disc < 0.0 {
            continue;
        }
        for sign in [-1.0, 1.0] {
            let u = (-h.h[1] + sign * disc.sqrt()) / (2.0 * h.h[2]);
            let ratio = (h.a1_over_v[0] + h.a1_over_v[1] * u) / h.a3_over_v;
            if u > 0.0 && ratio < -1e-3 && (h.h[1] + 2.0 * h.h[2] * u) > 0.0 {
                found = Some((w, u.sqrt(), ratio));
                break 'search;
            }
        }
    }
    let (w, v, ratio) = found.expect("a design with such a root among 200 000 seeded ones");
    // Two real eigenvalues r and -r at that speed.
    let ev = w.eigenvalues(v);
    let r = (-ratio).sqrt();
    let near = |x: f64| ev.iter().any(|e| e.im.abs() < 1e-6 * r && (e.re - x).abs() < 1e-6 * r);
    assert!(near(r) && near(-r), "eigenvalues at {v}: {ev:?}, expected +-{r}");
    let weave = w.weave_speed();
    assert!(weave.is_none_or(|x| ((x - v) / v).abs() > 1e-6), "{v} taken as weave: {weave:?}");
    // The former scan took any sign change of H3 from - to +.
    let (m, g) = parts(&w);
    let old = stability::scan_window(&m, g).weave_speed;
    eprintln!("Orlando root at v = {v} (a1/a3 = {ratio}); weave {weave:?}; former {old:?}");
}

#[test]
fn sweep_summarises_every_design() {
    let p = WhippleParams::benchmark();
    let progress = AtomicUsize::new(0);
    let s = sweep::sweep(&p, "c", 0.0, 0.2, 2001, Method::Hurwitz, &progress).unwrap();
    assert_eq!(s.count, 2001);
    assert_eq!(progress.load(std::sync::atomic::Ordering::Relaxed), 2001);
    assert_eq!(s.failed, 0);
    assert!(s.stable > 0 && s.stable <= 2001);
    // c = 0.08 (the benchmark) is design 800; its weave speed lies in the reported range.
    let vw = Whipple::new(p.clone()).weave_speed().unwrap();
    let (lo, hi) = s.weave_range.unwrap();
    assert!(lo <= vw && vw <= hi, "{lo} {vw} {hi}");
    let e = sweep::sweep(&p, "c", 0.0, 0.2, 11, Method::Eigen, &progress).unwrap();
    assert_eq!(e.count, 11);
    let h = sweep::sweep(&p, "c", 0.0, 0.2, 11, Method::Hurwitz, &progress).unwrap();
    assert_eq!(e.stable, h.stable, "both routes find the same number of stable designs");
    assert_eq!(
        sweep::sweep(&p, "x", 0.0, 1.0, 10, Method::Hurwitz, &progress).unwrap_err().to_string(),
        "unknown parameter x"
    );
    assert_eq!(
        sweep::sweep(&p, "mB", -1.0, 1.0, 10, Method::Hurwitz, &progress).unwrap_err().to_string(),
        "invalid design at an end of the range: invalid mB -1.0: must be positive"
    );
    assert!(sweep::sweep(&p, "c", 0.0, f64::NAN, 10, Method::Hurwitz, &progress).is_err());
}

/// The companion matrix of $x^4 + 1$, on which nalgebra's uncapped QR iterations cycle for
/// ever: [`companion`](carvallo::quartic::companion) returns, giving up with `None` (the
/// documented outcome of a Schur decomposition that does not converge within
/// `MAX_SCHUR_ITERATIONS`; if it converges one day, check its roots here instead), and
/// Aberth's iteration finds the four roots $(\pm 1 \pm i)/\sqrt 2$ to 1e-15.
#[test]
fn eigenvalues_of_x4_plus_1_terminate() {
    let c = [1.0, 0.0, 0.0, 0.0, 1.0];
    let z = carvallo::quartic::companion(&c);
    assert!(z.is_none(), "the Schur iteration converged on x^4 + 1: {z:?}");
    let roots = carvallo::quartic::aberth_compensated(&c);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    for (re, im) in [(h, h), (h, -h), (-h, h), (-h, -h)] {
        let near = roots.iter().filter(|r| (r.re - re).hypot(r.im - im) <= 1e-15).count();
        assert_eq!(near, 1, "root {re} {im}i among {roots:?}");
    }
}

/// The window of one design by the scalar route: the matrices by `Whipple::matrices` (the
/// scalar generated evaluator), then the summary of the Hurwitz window.
fn scalar_summary(values: [f64; 26]) -> stability::WindowSummary {
    let w = Whipple::new(WhippleParams::from_values(values).expect("a valid design"));
    let (m, g) = parts(&w);
    let summary = stability::hurwitz_window_summary(&m, g);
    assert_eq!(summary, stability::WindowSummary::from(&stability::hurwitz_window(&m, g)));
    summary
}

#[test]
fn grid_of_two_parameters_gives_the_scalar_windows_design_by_design() {
    use sweep::{Designs, Vary};
    let base = WhippleParams::benchmark();
    let axes = vec![
        Vary { name: "c".into(), from: 0.0, to: 0.2, count: 7 },
        Vary { name: "w".into(), from: 0.9, to: 1.3, count: 5 },
    ];
    let progress = AtomicUsize::new(0);
    let out = sweep::sweep_designs(&base, &Designs::Grid(axes), Method::Hurwitz, true, &progress)
        .unwrap();
    assert_eq!(out.summary.count, 35);
    assert_eq!(progress.into_inner(), 35);
    assert_eq!(out.names, ["c", "w"]);
    assert_eq!((out.values.len(), out.windows.len(), out.rejected), (70, 35, 0));
    let (k_c, k_w) = (1, 0);
    let mut stable = 0;
    for i in 0..35 {
        // The first axis varies slowest; the last value of an axis is exactly `to`.
        let (c, w) = (out.values[2 * i], out.values[2 * i + 1]);
        // Grid values from + k (to - from) / (n - 1) (issue 37: not a rounded fraction first).
        let want_c = if i / 5 == 6 { 0.2 } else { (i / 5) as f64 * 0.2 / 6.0 };
        let want_w = if i % 5 == 4 { 1.3 } else { 0.9 + (i % 5) as f64 * (1.3 - 0.9) / 4.0 };
        assert_eq!((c, w), (want_c, want_w), "design {i}");
        let mut v = *base.values();
        (v[k_c], v[k_w]) = (c, w);
        let got = out.windows[i].expect("the Hurwitz route always gives a window");
        assert_eq!(got, scalar_summary(v), "design {i}: c = {c}, w = {w}");
        stable += usize::from(got.stable);
    }
    assert_eq!(out.summary.stable, stable);
    // One axis gives what `sweep` gives.
    let one = sweep::sweep(&base, "c", 0.0, 0.2, 7, Method::Hurwitz, &AtomicUsize::new(0)).unwrap();
    let grid = sweep::sweep_designs(
        &base,
        &Designs::Grid(vec![Vary { name: "c".into(), from: 0.0, to: 0.2, count: 7 }]),
        Method::Hurwitz,
        false,
        &AtomicUsize::new(0),
    )
    .unwrap();
    assert_eq!(
        (one.stable, one.weave_range, one.capsize_range),
        (7, grid.summary.weave_range, grid.summary.capsize_range)
    );
    assert!(grid.values.is_empty() && grid.windows.is_empty());
}

#[test]
fn random_designs_are_seeded_valid_and_give_the_scalar_windows() {
    use sweep::{Designs, Spread};
    let base = WhippleParams::benchmark();
    let spreads = vec![
        Spread { name: "c".into(), rel: 0.5 },
        Spread { name: "IBxx".into(), rel: 0.9 },
        Spread { name: "mB".into(), rel: 0.2 },
    ];
    let designs = Designs::Random { count: 1001, spreads, seed: 7 };
    let run = || {
        sweep::sweep_designs(&base, &designs, Method::Hurwitz, true, &AtomicUsize::new(0)).unwrap()
    };
    let (a, b) = (run(), run());
    assert_eq!(a.values, b.values, "the same seed gives the same designs");
    assert_eq!(a.windows, b.windows);
    let keys = [1, 11, 10];
    let mut valid = 0;
    for i in 0..1001 {
        let mut v = *base.values();
        for (j, &k) in keys.iter().enumerate() {
            let x = a.values[3 * i + j];
            let rel = [0.5, 0.9, 0.2][j];
            assert!((x / v[k] - 1.0).abs() <= rel * (1.0 + 1e-15), "design {i}: {x}");
            v[k] = x;
        }
        match a.windows[i] {
            Some(w) => {
                assert_eq!(w, scalar_summary(v), "design {i}");
                valid += 1;
            }
            // IBxx scaled by up to 1.9 can violate IBxx <= IByy + IBzz a hundred times over.
            None => assert!(WhippleParams::from_values(v).is_err(), "design {i}"),
        }
    }
    assert_eq!(valid + a.rejected, 1001);
    assert_eq!(a.summary.count, 1001);
    let other = sweep::sweep_designs(
        &base,
        &Designs::Random {
            count: 1001,
            spreads: vec![Spread { name: "c".into(), rel: 0.5 }],
            seed: 8,
        },
        Method::Hurwitz,
        true,
        &AtomicUsize::new(0),
    )
    .unwrap();
    assert_ne!(other.values[..3], a.values[..3]);
}

#[test]
fn bad_designs_are_errors_naming_the_value() {
    use sweep::{Designs, DesignsError, Spread, Vary};
    let base = WhippleParams::benchmark();
    let run = |d: Designs| {
        sweep::sweep_designs(&base, &d, Method::Hurwitz, false, &AtomicUsize::new(0)).unwrap_err()
    };
    let vary =
        |name: &str, from: f64, to: f64, count: usize| Vary { name: name.into(), from, to, count };
    assert_eq!(
        run(Designs::Grid(vec![vary("c", 0.0, 0.1, 3), vary("c", 0.0, 0.2, 3)])),
        DesignsError::DuplicateParameter { name: "c".into() }
    );
    assert_eq!(run(Designs::Grid(vec![])), DesignsError::EmptyGrid);
    assert_eq!(
        run(Designs::Grid(vec![vary("c", 0.0, 0.1, 3), vary("x", 0.0, 0.2, 3)])).to_string(),
        "unknown parameter x"
    );
    // Every corner of the grid is validated.
    let err = run(Designs::Grid(vec![vary("mB", 85.0, -1.0, 3), vary("w", 1.0, 1.1, 2)]));
    assert!(err.to_string().starts_with("invalid design at an end of the range"), "{err}");
    assert_eq!(
        run(Designs::Random {
            count: 5,
            spreads: vec![Spread { name: "w".into(), rel: 1.0 }],
            seed: 1
        })
        .to_string(),
        "invalid spread 1 of w: must lie in [0, 1)"
    );
    assert_eq!(
        run(Designs::Random { count: 0, spreads: vec![], seed: 1 }).to_string(),
        "invalid count 0: must be at least 1"
    );
}

#[test]
fn a_stopped_stream_summarises_the_blocks_done() {
    use std::sync::atomic::{AtomicBool, Ordering};
    use sweep::{Designs, Spread, SweepChunk, BLOCK};
    let base = WhippleParams::benchmark();
    let spreads =
        vec![Spread { name: "c".into(), rel: 0.5 }, Spread { name: "mB".into(), rel: 0.2 }];
    let random = |count| Designs::Random { count, spreads: spreads.clone(), seed: 3 };
    // Stopped by the sink after its first block of 3 * BLOCK designs.
    let stop = AtomicBool::new(false);
    let (mut rows, mut firsts) = (0, Vec::new());
    let mut sink = |c: &SweepChunk<'_>| {
        rows += c.valid.len();
        firsts.push(c.first);
        stop.store(true, Ordering::Relaxed);
    };
    let progress = AtomicUsize::new(0);
    let out = sweep::sweep_stream(
        &base,
        &random(3 * BLOCK),
        Method::Hurwitz,
        &progress,
        &stop,
        Some(&mut sink),
    )
    .unwrap();
    assert_eq!((out.summary.count, out.requested, rows), (BLOCK, 3 * BLOCK, BLOCK));
    assert_eq!(firsts[0], 0);
    assert!(out.values.is_empty() && out.windows.is_empty());
    // Design i depends only on the seed and i: the first BLOCK designs of the longer stream
    // are the designs of a sweep of BLOCK, collected whole.
    let whole =
        sweep::sweep_designs(&base, &random(BLOCK), Method::Hurwitz, false, &progress).unwrap();
    let (a, b) = (&out.summary, &whole.summary);
    assert_eq!(
        (a.stable, a.with_weave, a.with_capsize, a.weave_range, a.capsize_range, out.rejected),
        (b.stable, b.with_weave, b.with_capsize, b.weave_range, b.capsize_range, whole.rejected)
    );
    // A grid whose counts overflow names them.
    let vary = |name: &str, count| sweep::Vary { name: name.into(), from: 0.0, to: 0.1, count };
    let err = sweep::sweep_designs(
        &base,
        &Designs::Grid(vec![vary("c", 1 << 40), vary("xB", 1 << 40)]),
        Method::Hurwitz,
        false,
        &progress,
    )
    .unwrap_err();
    assert!(err.to_string().contains("1099511627776 x 1099511627776"), "{err}");
}

#[test]
fn a_stream_stopped_within_a_block_keeps_a_prefix_of_the_designs() {
    use std::sync::atomic::{AtomicBool, Ordering};
    use sweep::{Designs, Spread, BLOCK};
    let base = WhippleParams::benchmark();
    let spreads = vec![Spread { name: "c".into(), rel: 0.5 }];
    let random = |count| Designs::Random { count, spreads: spreads.clone(), seed: 5 };
    // The flag is set as soon as a first chunk reports progress, in the middle of the first
    // block: the eigen route stops within it, not at its end.
    let (stop, progress) = (AtomicBool::new(false), AtomicUsize::new(0));
    let out = std::thread::scope(|s| {
        s.spawn(|| {
            while progress.load(Ordering::Relaxed) == 0 {
                std::thread::yield_now();
            }
            stop.store(true, Ordering::Relaxed);
        });
        sweep::sweep_stream(&base, &random(64 * BLOCK), Method::Eigen, &progress, &stop, None)
            .unwrap()
    });
    let n = out.summary.count;
    assert!(n > 0 && n < 64 * BLOCK, "{n} designs");
    // The designs done are the first n: their summary is that of a sweep of n designs.
    let whole = sweep::sweep_designs(&base, &random(n), Method::Eigen, false, &progress).unwrap();
    let (a, b) = (&out.summary, &whole.summary);
    assert_eq!(
        (a.stable, a.with_weave, a.with_capsize, a.weave_range, a.capsize_range, a.failed),
        (b.stable, b.with_weave, b.with_capsize, b.weave_range, b.capsize_range, b.failed)
    );
    assert_eq!(out.rejected, whole.rejected);
}
