//! The Hurwitz window of several designs at once, without a branch per design: what a sweep
//! keeps of each design ([`WindowSummary`]), equal to [`hurwitz_window_summary`] design by
//! design, computed lane by lane in straight-line code that the compiler turns into vector
//! instructions (AVX2 when the CPU has it, chosen at run time; SSE2 otherwise).
//!
//! [`hurwitz_window_summary`] branches on every design: which roots of the five Hurwitz
//! polynomials are positive, the order of the cuts, which interval is stable first. Over random
//! designs those branches are unpredictable, and the window cost as much as the matrices' four
//! lanes. Here every lane does the same work, in the same floating-point operations as the
//! scalar code (so the same bits):
//!
//! * the coefficients are [`HurwitzPolys::new`]'s;
//! * each root formula of `positive_roots` is evaluated whether or not it applies, and an
//!   absent or rejected root becomes $+\infty$ (a division by zero or the square root of a
//!   negative number gives an infinity or a NaN that is then masked, never a trap);
//! * the at most six cuts (two roots of $a_0$, one of $a_1/v$, one of $a_2$, two of $h$) are
//!   sorted by a network of `min`/`max` (every cut is finite and positive or $+\infty$, so this
//!   is the scalar `total_cmp` order), and the Routh–Hurwitz conditions are tested at the
//!   midpoint of every interval between consecutive distinct cuts, the last one unbounded, as
//!   the scalar loop does (which stops at the first stable interval; the summary only needs
//!   whether there is one).
//!
//! The weave speed is the lower of the two roots of $h$ that satisfies the scalar test, the
//! capsize speed the lower accepted root of $a_0$.

use super::stability::WindowSummary;
#[cfg(doc)]
use super::stability::{hurwitz_window_summary, HurwitzPolys};

/// Designs per call of [`hurwitz_window_summary_lanes`].
pub const LANES: usize = 4;

/// Four `f64`, one per design, with the arithmetic of `f64` lane by lane (loops of four that the
/// compiler turns into one vector instruction each).
#[derive(Clone, Copy)]
struct F4([f64; LANES]);

/// Four booleans, the result of comparing two [`F4`], as all-ones (true) or zero 64-bit masks
/// (which stay in vector registers; `bool` lanes would be packed and unpacked as bytes).
#[derive(Clone, Copy)]
struct M4([i64; LANES]);

impl M4 {
    #[inline(always)]
    fn from_fn(f: impl Fn(usize) -> bool) -> M4 {
        M4(std::array::from_fn(|j| -i64::from(f(j))))
    }

    #[inline(always)]
    fn get(self, j: usize) -> bool {
        self.0[j] != 0
    }
}

macro_rules! lanewise {
    ($trait:ident, $method:ident, $op:tt) => {
        impl std::ops::$trait for F4 {
            type Output = F4;
            #[inline(always)]
            fn $method(self, o: F4) -> F4 {
                F4(std::array::from_fn(|j| self.0[j] $op o.0[j]))
            }
        }
    };
}
lanewise!(Add, add, +);
lanewise!(Sub, sub, -);
lanewise!(Mul, mul, *);
lanewise!(Div, div, /);

impl std::ops::Neg for F4 {
    type Output = F4;
    #[inline(always)]
    fn neg(self) -> F4 {
        self.map(|x| -x)
    }
}

impl std::ops::BitAnd for M4 {
    type Output = M4;
    #[inline(always)]
    fn bitand(self, o: M4) -> M4 {
        M4(std::array::from_fn(|j| self.0[j] & o.0[j]))
    }
}

impl std::ops::BitOr for M4 {
    type Output = M4;
    #[inline(always)]
    fn bitor(self, o: M4) -> M4 {
        M4(std::array::from_fn(|j| self.0[j] | o.0[j]))
    }
}

impl std::ops::Not for M4 {
    type Output = M4;
    #[inline(always)]
    fn not(self) -> M4 {
        M4(self.0.map(|b| !b))
    }
}

impl F4 {
    #[inline(always)]
    fn splat(x: f64) -> F4 {
        F4([x; LANES])
    }

    #[inline(always)]
    fn map(self, f: impl Fn(f64) -> f64) -> F4 {
        F4(self.0.map(f))
    }

    #[inline(always)]
    fn cmp(self, o: F4, f: impl Fn(f64, f64) -> bool) -> M4 {
        M4::from_fn(|j| f(self.0[j], o.0[j]))
    }

    #[inline(always)]
    fn min(self, o: F4) -> F4 {
        F4(std::array::from_fn(|j| self.0[j].min(o.0[j])))
    }

    #[inline(always)]
    fn max(self, o: F4) -> F4 {
        F4(std::array::from_fn(|j| self.0[j].max(o.0[j])))
    }

    /// `self > 0` and finite.
    #[inline(always)]
    fn positive_finite(self) -> M4 {
        self.cmp(ZERO, |a, b| a > b) & self.finite()
    }

    /// Finite: `x * 0 == 0` (an infinity or a NaN times zero is NaN). Written so because the
    /// compiler turns `x.is_finite()` and `x.abs() < ∞` into integer tests of the exponent,
    /// one lane at a time.
    #[inline(always)]
    fn finite(self) -> M4 {
        (self * ZERO).cmp(ZERO, |a, b| a == b)
    }

    /// `if m { self } else { o }` lane by lane.
    #[inline(always)]
    fn or_else(self, m: M4, o: F4) -> F4 {
        F4(std::array::from_fn(|j| if m.get(j) { self.0[j] } else { o.0[j] }))
    }
}

const ZERO: F4 = F4([0.0; LANES]);
const INF: F4 = F4([f64::INFINITY; LANES]);

/// The roots `positive_roots` accepts, as `[lower, upper]` with $+\infty$ for an absent root,
/// without branches (see the [module docs](self)); `c2` is `None` for a linear polynomial.
#[inline(always)]
fn roots(c0: F4, c1: F4, c2: Option<F4>) -> [F4; 2] {
    let lin = -c0 / c1;
    let lin_ok = c1.cmp(ZERO, |a, b| a != b) & lin.positive_finite();
    let Some(c2) = c2 else {
        return [lin.or_else(lin_ok, INF), INF];
    };
    // c2 == 0: the linear root; otherwise the cancellation-free quadratic formula.
    let linear = c2.cmp(ZERO, |a, b| a == b);
    let disc = c1 * c1 - F4::splat(4.0) * c2 * c0;
    let q = F4::splat(-0.5) * (c1 + c1.map(f64::signum) * disc.map(f64::sqrt));
    let (r1, r2) = (q / c2, c0 / q);
    let quadratic = !linear & disc.cmp(ZERO, |a, b| a >= b);
    let r1_ok = quadratic & r1.positive_finite();
    let r2_ok = quadratic
        & q.cmp(ZERO, |a, b| a != b)
        & r2.positive_finite()
        & !(r1_ok & r2.cmp(r1, |a, b| a == b));
    let first = lin.or_else(linear & lin_ok, r1.or_else(r1_ok, INF));
    let second = r2.or_else(r2_ok, INF);
    [first.min(second), first.max(second)]
}

/// $\det A$ and the mixed determinant, as in `numerics::mat2`.
#[inline(always)]
fn det(a: &[[F4; 2]; 2]) -> F4 {
    a[0][0] * a[1][1] - a[0][1] * a[1][0]
}

#[inline(always)]
fn mix(a: &[[F4; 2]; 2], b: &[[F4; 2]; 2]) -> F4 {
    a[0][0] * b[1][1] + b[0][0] * a[1][1] - a[0][1] * b[1][0] - b[0][1] * a[1][0]
}

/// Sorts `c` ascending by a network of compare-exchanges (values are never NaN).
#[inline(always)]
fn sort6(c: &mut [F4; 6]) {
    const PAIRS: [(usize, usize); 12] = [
        (0, 5),
        (1, 3),
        (2, 4),
        (1, 2),
        (3, 4),
        (0, 3),
        (2, 5),
        (0, 1),
        (2, 3),
        (4, 5),
        (1, 2),
        (3, 4),
    ];
    for (i, j) in PAIRS {
        let (a, b) = (c[i], c[j]);
        c[i] = a.min(b);
        c[j] = a.max(b);
    }
}

/// [`hurwitz_window_summary`] of four designs without branches, as `(weave, capsize, stable)`
/// with NaN for a missing speed: [`HurwitzPolys::new`], `positive_roots` and the loop of
/// `window_into` written over [`F4`] in the same operations.
#[inline(always)]
fn lanes(o: &[[f64; LANES]; 16], g: f64) -> ([f64; LANES], [f64; LANES], [bool; LANES]) {
    let e = |k: usize| F4(o[k]);
    let r = |k: usize| [[e(k), e(k + 1)], [e(k + 2), e(k + 3)]];
    let (m, c1, k0, k2) = (r(0), r(4), r(8), r(12));
    // HurwitzPolys::new, capsize_coefficient included.
    let p1 = F4::splat(g) * mix(&k0, &k2);
    let abs = |x: F4| x.map(f64::abs);
    let terms = abs(k0[0][0] * k2[1][1])
        + abs(k2[0][0] * k0[1][1])
        + abs(k0[0][1] * k2[1][0])
        + abs(k2[0][1] * k0[1][0]);
    let negligible = abs(p1).cmp(F4::splat(1e-13 * g.abs()) * terms, |a, b| a <= b);
    let mut a0 = [F4::splat(g * g) * det(&k0), ZERO.or_else(negligible, p1), det(&k2)];
    let mut q = [F4::splat(g) * mix(&c1, &k0), mix(&c1, &k2)];
    let mut rr = [F4::splat(g) * mix(&m, &k0), mix(&m, &k2) + det(&c1)];
    let mut b = mix(&m, &c1);
    let mut a4 = det(&m);
    let mut h = [
        q[0] * rr[0] * b - q[0] * q[0] * a4 - a0[0] * b * b,
        (q[0] * rr[1] + q[1] * rr[0]) * b - F4::splat(2.0) * q[0] * q[1] * a4 - a0[1] * b * b,
        q[1] * rr[1] * b - q[1] * q[1] * a4 - a0[2] * b * b,
    ];
    // window_into.
    let a0_roots = roots(a0[0], a0[1], Some(a0[2]));
    let capsize = a0_roots[0].map(f64::sqrt).or_else(a0_roots[0].finite(), F4::splat(f64::NAN));
    let regular = a4.cmp(ZERO, |a, b| a != b) & a4.finite();
    // A negative a4: the same roots with a positive leading coefficient (negation is exact).
    let flip = a4.cmp(ZERO, |a, b| a < b);
    let f = |x: F4| (-x).or_else(flip, x);
    a0 = a0.map(f);
    q = q.map(f);
    rr = rr.map(f);
    b = f(b);
    a4 = f(a4);
    h = h.map(f);
    let h_roots = roots(h[0], h[1], Some(h[2]));
    let weave_at = |u: F4| {
        let slope = h[1] + F4::splat(2.0) * h[2] * u;
        let a1_over_a3 = (q[0] + q[1] * u) / b;
        u.finite() & slope.cmp(ZERO, |a, b| a > b) & a1_over_a3.cmp(ZERO, |a, b| a > b)
    };
    let weave = h_roots[0].map(f64::sqrt).or_else(
        weave_at(h_roots[0]),
        h_roots[1].map(f64::sqrt).or_else(weave_at(h_roots[1]), F4::splat(f64::NAN)),
    );
    let [a1_root, _] = roots(q[0], q[1], None);
    let [a2_root, _] = roots(rr[0], rr[1], None);
    let mut cuts = [a0_roots[0], a0_roots[1], a1_root, a2_root, h_roots[0], h_roots[1]]
        .map(|u| u.map(f64::sqrt));
    sort6(&mut cuts);
    // HurwitzPolys::at and the Routh–Hurwitz test at the middle of every interval.
    let stable_at = |v: F4| {
        let u = v * v;
        let quad = |c: &[F4; 3]| (c[2] * u + c[1]) * u + c[0];
        let lin = |c: &[F4; 2]| c[1] * u + c[0];
        let gt = |x: F4| x.cmp(ZERO, |a, b| a > b);
        gt(quad(&a0)) & gt(v * lin(&q)) & gt(lin(&rr)) & gt(v * b) & gt(a4) & gt(u * quad(&h))
    };
    let mut stable = M4([0; LANES]);
    let mut lo = ZERO;
    for hi in cuts.into_iter().chain([INF]) {
        let mid =
            (F4::splat(0.5) * (lo + hi)).or_else(hi.finite(), F4::splat(2.0) * lo + F4::splat(1.0));
        stable = stable | (hi.cmp(lo, |a, b| a > b) & stable_at(mid));
        lo = hi;
    }
    let nan = F4::splat(f64::NAN);
    let stable = stable & regular;
    (weave.or_else(regular, nan).0, capsize.0, std::array::from_fn(|j| stable.get(j)))
}

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
#[target_feature(enable = "avx2")]
fn lanes_avx2(o: &[[f64; LANES]; 16], g: f64) -> ([f64; LANES], [f64; LANES], [bool; LANES]) {
    lanes(o, g)
}

/// [`hurwitz_window_summary`] of [`LANES`] designs whose matrices are `o` as
/// `matrices_scene::eval_lanes` returns them (`o[k][j]`: output `k` of design `j`, the order of
/// `matrices_scene::OUTPUTS`: $M$, $C_1$, $K_0$, $K_2$ by rows). Equal to the scalar function
/// design by design (tested on random and degenerate designs).
pub fn hurwitz_window_summary_lanes(o: &[[f64; LANES]; 16], g: f64) -> [WindowSummary; LANES] {
    let (weave, capsize, stable) = {
        #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
        {
            if std::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU has AVX2, the only feature `lanes_avx2` enables.
                unsafe { lanes_avx2(o, g) }
            } else {
                lanes(o, g)
            }
        }
        #[cfg(not(any(target_arch = "x86", target_arch = "x86_64")))]
        {
            lanes(o, g)
        }
    };
    let speed = |x: f64| (!x.is_nan()).then_some(x);
    std::array::from_fn(|j| WindowSummary {
        weave_speed: speed(weave[j]),
        capsize_speed: speed(capsize[j]),
        stable: stable[j],
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::rng::SplitMix64;
    use crate::whipple::matrices::{matrices_scene, scene_index, Matrices};
    use crate::whipple::params::{WhippleParams, PARAM_NAMES};
    use crate::whipple::stability::hurwitz_window_summary;

    /// Compares the lanes with the scalar window on `designs` (matrices in scene order).
    fn check(designs: &[[f64; 16]], g: f64) {
        for group in designs.chunks(LANES) {
            let o: [[f64; LANES]; 16] =
                std::array::from_fn(|k| std::array::from_fn(|j| group[j % group.len()][k]));
            let got = hurwitz_window_summary_lanes(&o, g);
            // The portable variant too (the dispatched one is AVX2 where the CPU has it).
            let (weave, capsize, stable) = lanes(&o, g);
            for (j, w) in got.iter().enumerate() {
                assert_eq!(w.weave_speed.unwrap_or(f64::NAN).to_bits(), weave[j].to_bits());
                assert_eq!(w.capsize_speed.unwrap_or(f64::NAN).to_bits(), capsize[j].to_bits());
                assert_eq!(w.stable, stable[j]);
            }
            for (j, d) in group.iter().enumerate() {
                let r = |k: usize| [[d[k], d[k + 1]], [d[k + 2], d[k + 3]]];
                let m = Matrices { m: r(0), c1: r(4), k0: r(8), k2: r(12) };
                let want = hurwitz_window_summary(&m, g);
                assert_eq!(got[j], want, "design {d:?}");
            }
        }
    }

    /// The network sorts every sequence of zeros and ones, hence every sequence (the 0-1
    /// principle).
    #[test]
    fn the_network_sorts() {
        for bits in 0..64u32 {
            let mut c: [F4; 6] = std::array::from_fn(|k| F4::splat(f64::from(bits >> k & 1)));
            sort6(&mut c);
            assert!(c.windows(2).all(|w| w[0].0 <= w[1].0), "{bits:06b}");
        }
    }

    /// Random designs ±40 % around the benchmark (every one of the 26 parameters), through the
    /// scene as the sweep evaluates them: the same summary bit for bit, and both outcomes of
    /// every branch of the scalar code seen.
    #[test]
    fn lanes_equal_the_scalar_window_on_random_designs() {
        let base = *WhippleParams::benchmark().values();
        let index = scene_index();
        let mut rng = SplitMix64(22);
        let mut designs = Vec::new();
        for _ in 0..20_000 {
            let v: [f64; 26] = std::array::from_fn(|k| rng.scale(base[k], 0.4));
            let args: [f64; matrices_scene::Args::LEN] = std::array::from_fn(|i| v[index[i]]);
            designs.push(matrices_scene::eval_array(&args));
        }
        let g = base[PARAM_NAMES.iter().position(|n| *n == "g").expect("g")];
        check(&designs, g);
        // The sample covers stable and unstable designs, with and without each speed.
        let summaries: Vec<WindowSummary> = designs
            .iter()
            .map(|d| {
                let r = |k: usize| [[d[k], d[k + 1]], [d[k + 2], d[k + 3]]];
                hurwitz_window_summary(&Matrices { m: r(0), c1: r(4), k0: r(8), k2: r(12) }, g)
            })
            .collect();
        for (what, count) in [
            ("stable", summaries.iter().filter(|s| s.stable).count()),
            ("unstable", summaries.iter().filter(|s| !s.stable).count()),
            ("weave", summaries.iter().filter(|s| s.weave_speed.is_some()).count()),
            ("no weave", summaries.iter().filter(|s| s.weave_speed.is_none()).count()),
            ("capsize", summaries.iter().filter(|s| s.capsize_speed.is_some()).count()),
            ("no capsize", summaries.iter().filter(|s| s.capsize_speed.is_none()).count()),
        ] {
            assert!(count > 0, "no design {what}");
        }
    }

    /// Degenerate matrices: random entries with zeros, a singular or negative mass matrix,
    /// vanishing coefficients (linear and constant Hurwitz polynomials, double roots),
    /// infinities and NaNs.
    #[test]
    fn lanes_equal_the_scalar_window_on_degenerate_matrices() {
        let mut rng = SplitMix64(7);
        let specials = [0.0, -0.0, 1.0, -1.0, 2.0, 0.5, f64::INFINITY, f64::NAN, 1e-300, 1e300];
        let mut designs = Vec::new();
        for n in 0..40_000 {
            let d: [f64; 16] = std::array::from_fn(|_| {
                let x = rng.scale(1.0, 0.99) * if rng.scale(1.0, 0.99) < 1.0 { -3.0 } else { 3.0 };
                let pick = (rng.scale(1.0, 0.99) * 50.0) as usize;
                match n % 4 {
                    // Mostly small integers: exact cancellations, double roots, zero a4.
                    0 => (x.round() / 2.0).round(),
                    1 if pick < specials.len() => specials[pick],
                    _ => x,
                }
            });
            designs.push(d);
        }
        // The benchmark's symmetric structure with K2's first column zero, as the scene's.
        designs.push([
            1.0, 0.5, 0.5, 0.25, 0.0, 1.0, -1.0, 0.5, -1.0, 0.5, 0.5, -0.25, 0.0, 1.0, 0.0, 0.5,
        ]);
        check(&designs, 9.81);
        check(&designs, -1.0);
    }
}
