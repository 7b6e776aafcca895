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

use nalgebra::Complex;

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
}

impl ModeLabel {
    /// `weave`, `capsize` or `caster`.
    pub fn name(self) -> &'static str {
        match self {
            ModeLabel::Weave => "weave",
            ModeLabel::Capsize => "capsize",
            ModeLabel::Caster => "caster",
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

/// `new` reordered to follow `old`: the permutation of least total distance.
fn follow(old: &[Eigenvalue; 4], new: &[Eigenvalue]) -> [Eigenvalue; 4] {
    let mut best = (f64::INFINITY, [0, 1, 2, 3]);
    let mut perm = [0usize, 1, 2, 3];
    permute(&mut perm, 0, &mut |p| {
        let d: f64 = (0..4).map(|i| dist(old[i], new[p[i]])).sum();
        if d < best.0 {
            best = (d, *p);
        }
    });
    std::array::from_fn(|i| new[best.1[i]])
}

fn permute(p: &mut [usize; 4], k: usize, f: &mut impl FnMut(&[usize; 4])) {
    if k == 4 {
        f(p);
        return;
    }
    for i in k..4 {
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
                    ev = follow(&ev, &new);
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
}
