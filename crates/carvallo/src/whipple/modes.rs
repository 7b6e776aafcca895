//! The mode shapes of the linearised bicycle: the eigenvectors of the state matrix $A$
//! ([`plant`](super::plant)), each eigenvalue labelled weave, capsize or caster (Meijaard et
//! al. 2007, §6) by continuation in speed, not by sorting.
//!
//! An eigenvector of $A$ is $(q, \lambda q)$ with $q$ in the null space of the 2 × 2 matrix
//! $P(\lambda) = M\lambda^2 + v C_1 \lambda + g K_0 + v^2 K_2$; $q$ is the row of $P$'s
//! adjugate of larger norm, scaled so the state vector has unit 2-norm and its largest
//! component of $q$ is real and positive. The labels start at a reference speed where the
//! spectrum is one complex pair (weave) and two real roots (the more negative caster, the other
//! capsize), the first such speed at or above 1.5 times the weave–capsize bifurcation speed;
//! from there the eigenvalues are followed in steps of at most [`STEP`] m/s to every requested
//! speed, matching each step's four eigenvalues to the previous ones by the permutation of least
//! total distance. Below the bifurcation speed the weave pair are the two real roots that merge
//! into it.
//!
//! # The leaning rider
//! Moore's leaning rider ([`LeanRider`]) has six modes' eigenvalues ([`LeanRider::eigenvalues`]):
//! the bicycle's weave pair, capsize and caster, and two of the torso on its lean joint
//! ([`ModeLabel::Torso`]; with Browser + Jason's $k_9 = c_9 = 0$ an inverted pendulum, one
//! real root near $+7$ and one near $-6$ to $-7\ \mathrm{s}^{-1}$). [`LeanRider::modes`]
//! labels them the same way, by continuation in speed, from a reference speed where the labels
//! are decided by the eigenvectors:
//! - the reference is the first speed of $5, 5.1, \dots, 50$ m/s with one complex pair and
//!   four real roots: the pair is the weave; of the real roots, the two whose eigenvectors put
//!   the largest share of their coordinates on the lean joint $q_9$
//!   ([`RiderMode::torso_share`]) are the torso's, of the other two the more negative is the
//!   caster and the other the capsize;
//! - from there the eigenvalues are followed in steps of at most [`STEP`] m/s, each step's six
//!   matched to the previous ones by the permutation of least total distance;
//! - two modes of different labels may merge into one complex pair and part again (with
//!   Browser + Jason the caster and the torso's stable root do, between about 0.7 and 2.6
//!   m/s); while merged, each keeps its label, and where they part into two real roots the
//!   continuation cannot tell them apart (both are as near), so the eigenvectors decide again:
//!   the root with the larger torso share is the torso's.

use nalgebra::{Complex, SMatrix};

use super::lean_rider::{LeanRider, LATERAL};
use super::matrices::Matrices;
use super::model::Whipple;
use crate::numerics::eigen::Eigenvalue;

/// The largest speed step of the continuation (m/s).
pub const STEP: f64 = 0.01;

/// The farthest a requested speed may lie from the reference speed in m/s (20 000 steps).
pub const MAX_RANGE: f64 = 200.0;

/// Which mode an eigenvalue belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ModeLabel {
    /// The oscillatory lean–steer mode (a complex pair above the bifurcation speed, two real
    /// roots below it).
    Weave,
    /// The slow lean mode (real, crossing zero at the capsize speed).
    Capsize,
    /// The fast, strongly damped steer mode (real, strongly negative).
    Caster,
    /// The leaning rider's torso on its lean joint (two roots; never a Whipple bicycle's).
    Torso,
}

impl ModeLabel {
    /// `weave`, `capsize` or `caster`.
    pub fn name(self) -> &'static str {
        match self {
            ModeLabel::Weave => "weave",
            ModeLabel::Capsize => "capsize",
            ModeLabel::Caster => "caster",
            ModeLabel::Torso => "torso",
        }
    }
}

/// One mode at one speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mode {
    /// Its label.
    pub label: ModeLabel,
    /// The eigenvalue $\lambda$ (1/s).
    pub eigenvalue: Eigenvalue,
    /// The unit eigenvector of $A$, $(\varphi, \delta, \dot\varphi, \dot\delta)$.
    pub vector: [Complex<f64>; 4],
}

impl Mode {
    /// $|\delta / \varphi|$, the steer amplitude per unit lean (infinite for a pure steer
    /// mode).
    pub fn steer_lean_ratio(&self) -> f64 {
        self.vector[1].norm() / self.vector[0].norm()
    }

    /// $\arg(\delta / \varphi)$ in degrees, in $(-180, 180]$: by how much steer leads lean.
    pub fn phase_deg(&self) -> f64 {
        (self.vector[1] / self.vector[0]).arg().to_degrees()
    }
}

/// The unit eigenvector of $A$ for the eigenvalue `e` of the matrices `m` at speed `v`.
pub fn eigenvector(m: &Matrices, g: f64, v: f64, e: Eigenvalue) -> [Complex<f64>; 4] {
    let l = Complex::new(e.re, e.im);
    let p = |i: usize, j: usize| {
        Complex::from(m.m[i][j]) * l * l
            + Complex::from(v * m.c1[i][j]) * l
            + Complex::from(g * m.k0[i][j] + v * v * m.k2[i][j])
    };
    // P q = 0: q is orthogonal to either row of P (the one of larger norm is the better one).
    let r0 = (-p(0, 1), p(0, 0));
    let r1 = (p(1, 1), -p(1, 0));
    let n0 = r0.0.norm_sqr() + r0.1.norm_sqr();
    let n1 = r1.0.norm_sqr() + r1.1.norm_sqr();
    let (a, b) = if n0 >= n1 { r0 } else { r1 };
    let mut x = [a, b, l * a, l * b];
    let big = if a.norm() >= b.norm() { a } else { b };
    let phase = if big.norm() > 0.0 { big.conj() / big.norm() } else { Complex::from(1.0) };
    let norm = x.iter().map(|c| c.norm_sqr()).sum::<f64>().sqrt();
    for c in &mut x {
        *c = *c * phase / norm;
    }
    x
}

fn dist(a: Eigenvalue, b: Eigenvalue) -> f64 {
    (a.re - b.re).hypot(a.im - b.im)
}

/// `new` reordered to follow `old`: the permutation of least total distance `dist` (the first
/// found on a tie). `new` has at least `N` entries; the first `N` are permuted.
fn follow<T: Copy, const N: usize>(old: &[T; N], new: &[T], dist: impl Fn(T, T) -> f64) -> [T; N] {
    let mut best = (f64::INFINITY, std::array::from_fn::<usize, N, _>(|i| i));
    let mut perm = best.1;
    permute(&mut perm, 0, &mut |p| {
        let d: f64 = (0..N).map(|i| dist(old[i], new[p[i]])).sum();
        if d < best.0 {
            best = (d, *p);
        }
    });
    std::array::from_fn(|i| new[best.1[i]])
}

fn permute<const N: usize>(p: &mut [usize; N], k: usize, f: &mut impl FnMut(&[usize; N])) {
    if k == N {
        f(p);
        return;
    }
    for i in k..N {
        p.swap(k, i);
        permute(p, k + 1, f);
        p.swap(k, i);
    }
}

/// The labels in the order of [`reference`]'s eigenvalues.
const LABELS: [ModeLabel; 4] =
    [ModeLabel::Weave, ModeLabel::Weave, ModeLabel::Capsize, ModeLabel::Caster];

impl Whipple {
    /// The reference speed and its eigenvalues ordered as [`LABELS`] (weave pair, capsize,
    /// caster); `None` if no speed up to 50 m/s has one complex pair and two real roots.
    fn reference(&self) -> Option<(f64, [Eigenvalue; 4])> {
        let start = self.bifurcation().map_or(0.0, |(vd, _)| 1.5 * vd);
        (0..5000).find_map(|i| {
            let v = start + 0.01 * f64::from(i);
            let ev = self.eigenvalues(v);
            let (cx, mut re): (Vec<Eigenvalue>, Vec<Eigenvalue>) =
                ev.iter().partition(|e| e.im != 0.0);
            if ev.len() != 4 || cx.len() != 2 {
                return None;
            }
            re.sort_by(|a, b| b.re.total_cmp(&a.re));
            Some((v, [cx[0], cx[1], re[0], re[1]]))
        })
    }

    /// The four modes at each of `speeds`, labelled by continuation from the reference speed;
    /// `None` if there is no reference speed, a speed lies more than [`MAX_RANGE`] from it (or
    /// is not finite) or an eigenvalue solve fails to converge.
    pub fn modes(&self, speeds: &[f64]) -> Option<Vec<[Mode; 4]>> {
        let (v0, ev0) = self.reference()?;
        let (m, g) = (self.matrices(), self.params().value("g"));
        speeds
            .iter()
            .map(|&v| {
                if (v - v0).abs().partial_cmp(&MAX_RANGE) != Some(std::cmp::Ordering::Less) {
                    return None;
                }
                let n = ((v - v0).abs() / STEP).ceil().max(1.0) as usize;
                let mut ev = ev0;
                for k in 1..=n {
                    let u = v0 + (v - v0) * k as f64 / n as f64;
                    let new = self.eigenvalues(u);
                    if new.len() != 4 {
                        return None;
                    }
                    ev = follow(&ev, &new, dist);
                }
                Some(std::array::from_fn(|i| Mode {
                    label: LABELS[i],
                    eigenvalue: ev[i],
                    vector: eigenvector(&m, g, v, ev[i]),
                }))
            })
            .collect()
    }
}

/// One mode of the leaning rider at one speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RiderMode {
    /// Its label.
    pub label: ModeLabel,
    /// The eigenvalue $\lambda$ (1/s).
    pub eigenvalue: Complex<f64>,
    /// The unit eigenvector of $A$ on the lateral states ([`LATERAL`]:
    /// $q_4, q_7, q_9, u_4, u_7, u_9$, roll, steer, the torso's lean on its joint and their
    /// rates), its largest coordinate component real and positive.
    pub vector: [Complex<f64>; 6],
}

impl RiderMode {
    /// The shares of roll $q_4$, steer $q_7$ and the lean joint $q_9$ in the eigenvector's
    /// coordinates, $|x_k|^2 / (|x_4|^2 + |x_7|^2 + |x_9|^2)$; they sum to one.
    pub fn shares(&self) -> [f64; 3] {
        let n: [f64; 3] = std::array::from_fn(|k| self.vector[k].norm_sqr());
        let sum: f64 = n.iter().sum();
        n.map(|x| x / sum)
    }

    /// The lean joint's share of the coordinates ([`shares`](Self::shares)`[2]`).
    pub fn torso_share(&self) -> f64 {
        self.shares()[2]
    }
}

/// The unit eigenvector of the $6 \times 6$ matrix `a` for its eigenvalue `l`: the right
/// singular vector of $A - \lambda I$ of least singular value, its largest component of the
/// first three real and positive.
fn eigenvector6(a: &SMatrix<f64, 6, 6>, l: Complex<f64>) -> [Complex<f64>; 6] {
    let m = SMatrix::<Complex<f64>, 6, 6>::from_fn(|i, j| {
        Complex::from(a[(i, j)]) - if i == j { l } else { Complex::from(0.0) }
    });
    let svd = m.svd(false, true);
    let v_t = svd.v_t.expect("asked for V^H");
    let k = svd.singular_values.imin();
    let mut x: [Complex<f64>; 6] = std::array::from_fn(|j| v_t[(k, j)].conj());
    let big = x[..3].iter().copied().max_by(|p, q| p.norm().total_cmp(&q.norm())).expect("three");
    let phase = if big.norm() > 0.0 { big.conj() / big.norm() } else { Complex::from(1.0) };
    let norm = x.iter().map(|c| c.norm_sqr()).sum::<f64>().sqrt();
    for c in &mut x {
        *c = *c * phase / norm;
    }
    x
}

/// The lean joint's share of the coordinates of `a`'s eigenvector for `l`
/// ([`RiderMode::torso_share`]).
fn torso_share(a: &SMatrix<f64, 6, 6>, l: Complex<f64>) -> f64 {
    let x = eigenvector6(a, l);
    x[2].norm_sqr() / (x[0].norm_sqr() + x[1].norm_sqr() + x[2].norm_sqr())
}

/// The labels in the order of [`LeanRider::modes_reference`]'s eigenvalues.
const RIDER_LABELS: [ModeLabel; 6] = [
    ModeLabel::Weave,
    ModeLabel::Weave,
    ModeLabel::Capsize,
    ModeLabel::Caster,
    ModeLabel::Torso,
    ModeLabel::Torso,
];

impl LeanRider {
    /// The $6 \times 6$ matrix of $A$ on [`LATERAL`] at `speed`.
    fn lateral(&self, speed: f64) -> SMatrix<f64, 6, 6> {
        let (a, _) = self.state_space(speed);
        SMatrix::<f64, 6, 6>::from_fn(|i, j| a[(LATERAL[i], LATERAL[j])])
    }

    /// The six modes at `speed` with the eigenvalues `ev` in the order of [`RIDER_LABELS`].
    fn labelled(&self, speed: f64, ev: &[Complex<f64>; 6]) -> [RiderMode; 6] {
        let a = self.lateral(speed);
        std::array::from_fn(|i| RiderMode {
            label: RIDER_LABELS[i],
            eigenvalue: ev[i],
            vector: eigenvector6(&a, ev[i]),
        })
    }

    /// The reference speed and its eigenvalues ordered as [`RIDER_LABELS`] (the module docs
    /// say how); `None` if no speed of $5, 5.1, \dots, 50$ m/s has one complex pair and four
    /// real roots.
    fn modes_reference(&self) -> Option<(f64, [Complex<f64>; 6])> {
        (0..=450).find_map(|i| {
            let v = 5.0 + 0.1 * f64::from(i);
            let a = self.lateral(v);
            let ev = self.eigenvalues(v);
            let (cx, re): (Vec<Complex<f64>>, Vec<Complex<f64>>) =
                ev.iter().partition(|e| e.im != 0.0);
            if cx.len() != 2 {
                return None;
            }
            let mut re: Vec<(f64, Complex<f64>)> =
                re.iter().map(|&e| (torso_share(&a, e), e)).collect();
            re.sort_by(|p, q| q.0.total_cmp(&p.0));
            let (mut torso, mut bike) = ([re[0].1, re[1].1], [re[2].1, re[3].1]);
            torso.sort_by(|p, q| q.re.total_cmp(&p.re));
            bike.sort_by(|p, q| q.re.total_cmp(&p.re));
            Some((v, [cx[0], cx[1], bike[0], bike[1], torso[0], torso[1]]))
        })
    }

    /// One step of the continuation from `old` (labelled as [`RIDER_LABELS`]) to the speed
    /// `v`: the permutation of least distance, then two roots of different labels that were
    /// one complex pair and are now real given by their torso shares.
    fn follow_to(&self, old: &[Complex<f64>; 6], v: f64) -> [Complex<f64>; 6] {
        let mut ev = follow(old, &self.eigenvalues(v), |a, b| (a - b).norm());
        let mut a = None;
        for i in 0..6 {
            for j in i + 1..6 {
                let merged =
                    old[i].im != 0.0 && (old[i] - old[j].conj()).norm() <= 1e-9 * old[i].norm();
                let parted = ev[i].im == 0.0 && ev[j].im == 0.0;
                let torso =
                    (RIDER_LABELS[i] == ModeLabel::Torso) != (RIDER_LABELS[j] == ModeLabel::Torso);
                if merged && parted && torso {
                    let a = a.get_or_insert_with(|| self.lateral(v));
                    let t = if RIDER_LABELS[i] == ModeLabel::Torso { i } else { j };
                    let o = i + j - t;
                    if torso_share(a, ev[o]) > torso_share(a, ev[t]) {
                        ev.swap(i, j);
                    }
                }
            }
        }
        ev
    }

    /// The six modes at each of `speeds` (the module docs say how they are labelled: weave
    /// twice, capsize, caster, torso twice, in that order); `None` if there is no reference
    /// speed or a speed lies more than [`MAX_RANGE`] from it (or is not finite).
    ///
    /// The speeds are visited in order along one continuation up and one down from the
    /// reference, so the cost is that of the range covered, not of the number of speeds.
    pub fn modes(&self, speeds: &[f64]) -> Option<Vec<[RiderMode; 6]>> {
        let (v0, ev0) = self.modes_reference()?;
        if speeds
            .iter()
            .any(|v| (v - v0).abs().partial_cmp(&MAX_RANGE) != Some(std::cmp::Ordering::Less))
        {
            return None;
        }
        let mut out: Vec<Option<[RiderMode; 6]>> = vec![None; speeds.len()];
        for up in [true, false] {
            let mut order: Vec<usize> =
                (0..speeds.len()).filter(|&k| (speeds[k] >= v0) == up).collect();
            order.sort_by(|&p, &q| (speeds[p] - v0).abs().total_cmp(&(speeds[q] - v0).abs()));
            let (mut at, mut ev) = (v0, ev0);
            for k in order {
                let v = speeds[k];
                let n = ((v - at).abs() / STEP).ceil() as usize;
                for s in 1..=n {
                    ev = self.follow_to(&ev, at + (v - at) * s as f64 / n as f64);
                }
                at = v;
                out[k] = Some(self.labelled(v, &ev));
            }
        }
        out.into_iter().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::whipple::WhippleParams;

    fn by(modes: &[Mode; 4], l: ModeLabel) -> Vec<Eigenvalue> {
        modes.iter().filter(|m| m.label == l).map(|m| m.eigenvalue).collect()
    }

    #[test]
    fn eigenvectors_satisfy_a_v_equals_lambda_v() {
        let bike = Whipple::new(WhippleParams::benchmark());
        let speeds: Vec<f64> = (0..=40).map(|i| -2.0 + 0.3 * f64::from(i)).collect();
        for (v, modes) in speeds.iter().zip(bike.modes(&speeds).unwrap()) {
            let a = bike.state_space(*v).a;
            for md in modes {
                let l = Complex::new(md.eigenvalue.re, md.eigenvalue.im);
                let x = md.vector;
                let norm: f64 = x.iter().map(|c| c.norm_sqr()).sum::<f64>().sqrt();
                assert!((norm - 1.0).abs() < 1e-14, "v = {v}: norm {norm}");
                for (i, xi) in x.iter().enumerate() {
                    let ax: Complex<f64> = (0..4).map(|j| x[j] * a[(i, j)]).sum();
                    let r = (ax - l * xi).norm();
                    assert!(r < 1e-12 * a.amax().max(1.0), "v = {v}, {md:?}: residual {r:e}");
                }
            }
        }
    }

    #[test]
    fn labels_match_meijaard_2007() {
        let bike = Whipple::new(WhippleParams::benchmark());
        let speeds = [0.0, 0.5, 0.6, 1.0, 3.0, 4.29, 5.0, 6.0, 6.1, 8.0];
        let all = bike.modes(&speeds).unwrap();
        for (v, m) in speeds.iter().zip(&all) {
            let (w, cs, ct) =
                (by(m, ModeLabel::Weave), by(m, ModeLabel::Capsize), by(m, ModeLabel::Caster));
            assert_eq!((w.len(), cs.len(), ct.len()), (2, 1, 1), "v = {v}");
            assert_eq!(cs[0].im, 0.0, "v = {v}: capsize real");
            assert_eq!(ct[0].im, 0.0, "v = {v}: caster real");
            assert!(ct[0].re < -3.0 && ct[0].re < cs[0].re, "v = {v}: caster {ct:?}");
            // The weave pair: complex above vd = 0.684 m/s, two positive real roots below.
            if *v > 0.69 {
                assert!(w[0].im != 0.0 && w[0].im == -w[1].im, "v = {v}: {w:?}");
            } else {
                assert!(w.iter().all(|e| e.im == 0.0 && e.re > 0.0), "v = {v}: {w:?}");
            }
            // Capsize crosses zero at vc = 6.024 m/s; weave at vw = 4.292 m/s.
            assert_eq!(cs[0].re > 0.0, *v > 6.0243, "v = {v}: capsize {cs:?}");
            assert_eq!(w[0].re > 0.0, *v < 4.2924, "v = {v}: weave {w:?}");
        }
        // At 5 m/s the published values (Meijaard et al. 2007, Table 2).
        let m5 = &all[6];
        assert!((by(m5, ModeLabel::Caster)[0].re + 14.078389692798247).abs() < 1e-11);
        assert!((by(m5, ModeLabel::Capsize)[0].re + 0.322_866_429_004_087_1).abs() < 1e-11);
        assert!(by(m5, ModeLabel::Weave)
            .iter()
            .all(|e| (e.re + 0.775_341_882_195_841_9).abs() < 1e-11
                && (e.im.abs() - 4.464_867_713_788_225).abs() < 1e-11));
        // At 0 m/s: caster -5.53, capsize -3.13 (the stable roots of the two inverted pendula).
        assert!((by(&all[0], ModeLabel::Caster)[0].re + 5.530_943_717_653_935).abs() < 1e-11);
        assert!((by(&all[0], ModeLabel::Capsize)[0].re + 3.131_643_247_906_556).abs() < 1e-11);
        // The weave's shape at 5 m/s: steer larger than lean, a finite phase.
        let w = m5.iter().find(|m| m.label == ModeLabel::Weave).unwrap();
        assert!(w.steer_lean_ratio() > 0.0 && w.steer_lean_ratio().is_finite());
        assert!(w.phase_deg().abs() <= 180.0);
        assert!(bike.modes(&[5.0, 1e308]).is_none());
        assert!(bike.modes(&[f64::NAN]).is_none());
    }

    /// The leaning rider's labels at speeds on both sides of the reference (5 m/s) and across
    /// the caster and torso's merged pair (about 0.7 to 2.6 m/s), each checked against the
    /// eigenvectors computed here (A x = λ x), not against the continuation: the two torso
    /// roots put the largest shares of their coordinates on the lean joint q9, the caster is
    /// the stable real root of the bicycle's with the largest steer share, the capsize a real
    /// root leaning more than it steers, the weave a complex pair above 0.7 m/s (two real
    /// roots that merge into it below); the torso's unstable root stays near +7 1/s.
    #[test]
    fn rider_labels_agree_with_the_eigenvectors() {
        use crate::whipple::lean_rider::LeanRiderParams;
        let rider = LeanRider::new(LeanRiderParams::browser_jason()).unwrap();
        let speeds = [0.0, 0.5, 3.0, 4.0, 5.0, 8.0, 15.0, 20.0];
        let all = rider.modes(&speeds).unwrap();
        for (v, modes) in speeds.iter().zip(&all) {
            let (a, _) = rider.state_space(*v);
            let lat = SMatrix::<f64, 6, 6>::from_fn(|i, j| a[(LATERAL[i], LATERAL[j])]);
            for md in modes {
                let x = md.vector;
                for i in 0..6 {
                    let ax: Complex<f64> = (0..6).map(|j| x[j] * lat[(i, j)]).sum();
                    let r = (ax - md.eigenvalue * x[i]).norm();
                    assert!(r < 1e-9 * lat.amax(), "v = {v}, {md:?}: residual {r:e}");
                }
            }
            let of = |l: ModeLabel| modes.iter().filter(move |m| m.label == l);
            let count = |l: ModeLabel| of(l).count();
            assert_eq!(
                [ModeLabel::Weave, ModeLabel::Capsize, ModeLabel::Caster, ModeLabel::Torso]
                    .map(count),
                [2, 1, 1, 2],
                "v = {v}"
            );
            // The torso: real, the two largest lean-joint shares, one root near +7 1/s.
            let least_torso = of(ModeLabel::Torso).map(|m| m.torso_share()).fold(1.0, f64::min);
            let most_other = modes
                .iter()
                .filter(|m| m.label != ModeLabel::Torso)
                .map(|m| m.torso_share())
                .fold(0.0, f64::max);
            assert!(least_torso > most_other, "v = {v}: {least_torso} vs {most_other}");
            assert!(of(ModeLabel::Torso).all(|m| m.eigenvalue.im == 0.0), "v = {v}");
            let up = of(ModeLabel::Torso).map(|m| m.eigenvalue.re).fold(f64::MIN, f64::max);
            assert!((6.5..7.6).contains(&up), "v = {v}: the torso's unstable root {up}");
            // The caster: real, negative, the largest steer share of the bicycle's real
            // stable roots; the capsize: real, leaning more than it steers.
            let caster = of(ModeLabel::Caster).next().unwrap();
            let capsize = of(ModeLabel::Capsize).next().unwrap();
            assert!(caster.eigenvalue.im == 0.0 && caster.eigenvalue.re < -3.0, "v = {v}");
            let steer = modes
                .iter()
                .filter(|m| m.label != ModeLabel::Torso)
                .filter(|m| m.eigenvalue.im == 0.0 && m.eigenvalue.re < 0.0)
                .map(|m| m.shares()[1])
                .fold(0.0, f64::max);
            assert_eq!(caster.shares()[1], steer, "v = {v}");
            assert!(capsize.eigenvalue.im == 0.0, "v = {v}");
            assert!(capsize.shares()[0] > capsize.shares()[1], "v = {v}: {capsize:?}");
            let weave: Vec<_> = of(ModeLabel::Weave).map(|m| m.eigenvalue).collect();
            if *v > 0.7 {
                assert!(weave[0].im != 0.0 && weave[0] == weave[1].conj(), "v = {v}: {weave:?}");
            } else {
                assert!(weave.iter().all(|e| e.im == 0.0 && e.re > 0.0), "v = {v}: {weave:?}");
            }
        }
        // Browser + Jason's capsize crosses zero between 7 and 7.5 m/s (7.0: -0.027).
        assert!(all[5].iter().any(|m| m.label == ModeLabel::Capsize && m.eigenvalue.re > 0.0));
        assert!(rider.modes(&[5.0, 1e308]).is_none());
        assert!(rider.modes(&[f64::NAN]).is_none());
    }
}
