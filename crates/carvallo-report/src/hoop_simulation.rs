//! Simulations of the generated hoop equations (system (2) of n° 7, [`carvallo::hoop::Hoop`])
//! that the claims of the hoop and of the hoop discussion are checked on (shared here so that
//! neither report imports the other): perturbed steady states, the return of the fall angle,
//! and the Taylor coefficients of the fall rate at the start of a fall.

use carvallo::hoop::Hoop;
use carvallo::numerics::ode::rk4_step;

/// The hoop with $g = R = 1$: its rates are in the unit $\sqrt{g/R}$ of n° 12 and its times in
/// $\sqrt{R/g}$, so the generated physical (E), (S) are the normalised ones.
pub(crate) fn unit_hoop() -> Hoop {
    // Positive finite parameters: `Hoop::new` cannot fail.
    Hoop::new(1.0, 1.0, 1.0).unwrap_or_else(|_| unreachable!("unit parameters are valid"))
}

/// The memoir's example hoop, $R = 0{,}50$ m, under $g = 9{,}81$ m/s².
pub(crate) fn example_hoop() -> Hoop {
    Hoop::new(0.5, 1.0, 9.81).unwrap_or_else(|_| unreachable!("example parameters are valid"))
}

/// What a perturbed steady state did in a simulation.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Perturbed {
    /// The first member $K$ of (S) at the steady state (physical units).
    pub k: f64,
    /// $\max_t |\theta - \theta_e|$ over the run, divided by the perturbation.
    pub max_dev: f64,
    /// The measured rate: the angular frequency from the fall rate's zero crossings when the
    /// motion oscillates, the exponential growth rate when it diverges; NaN if not measured.
    pub rate: f64,
    /// Whether the deviation passed the divergence bound (the run stopped there).
    pub diverged: bool,
}

/// Simulates the steady state $(\theta_e, s, n)$ of `hoop` perturbed by `delta` in both
/// $\theta$ and $p$, with RK4 steps `dt` up to `t_end` (stopping once $|\theta - \theta_e|$
/// exceeds $10^6\,\delta$), and measures the rate of the motion (see [`Perturbed`]).
pub(crate) fn perturb(
    hoop: &Hoop,
    (theta_e, s, n): (f64, f64, f64),
    delta: f64,
    dt: f64,
    t_end: f64,
) -> Perturbed {
    let k = crate::perturb::hoop_stability(hoop, theta_e, s, n);
    let mut x = [theta_e + delta, delta, n, s];
    let (mut t, mut max_dev, mut diverged) = (0.0, 0.0f64, false);
    let mut crossings: Vec<f64> = Vec::new();
    // Times at which the deviation first exceeds 1e4 delta and 1e6 delta (log-interpolated): by
    // then the shift of the mean (the double root 0) and the decaying mode are negligible.
    let (mut t_lo, mut t_hi) = (f64::NAN, f64::NAN);
    let (lo, hi) = (1e4 * delta, 1e6 * delta);
    while t < t_end {
        let next = rk4_step(|y| crate::perturb::hoop_rhs_pns(hoop, y), x, dt);
        let (d0, d1) = ((x[0] - theta_e).abs(), (next[0] - theta_e).abs());
        let cross_at = |level: f64| t + dt * (level / d0).ln() / (d1 / d0).ln();
        if t_lo.is_nan() && d1 > lo && d0 > 0.0 {
            t_lo = cross_at(lo);
        }
        if t_hi.is_nan() && d1 > hi && d0 > 0.0 {
            t_hi = cross_at(hi);
        }
        if x[1] * next[1] < 0.0 {
            crossings.push(t + dt * x[1] / (x[1] - next[1]));
        }
        x = next;
        t += dt;
        max_dev = max_dev.max(d1);
        if d1 > hi {
            diverged = true;
            break;
        }
    }
    let rate = if diverged && !t_lo.is_nan() {
        (hi / lo).ln() / (t_hi - t_lo)
    } else if crossings.len() >= 3 {
        // Successive zero crossings of p are half a period apart.
        let half = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
        std::f64::consts::PI / half
    } else {
        f64::NAN
    };
    Perturbed { k, max_dev: max_dev / delta, rate, diverged }
}

/// The steady states sampled for the stability claims: $\theta$ from 2,5° to 30° by 2,5° and
/// on to 60° by 5°, $s$ in units $\sqrt{g/R}$ from 0,2 to 1,5, both roots $n_1$, $n_2$ of (E)
/// where real and $|n| \le 8$, keeping only those with $|K| \ge 0{,}15$ (away from the curve
/// (S), where the growth or oscillation would be too slow to classify in the run).
pub(crate) fn stability_sample(hoop: &Hoop) -> Vec<(f64, f64, f64)> {
    let mut out = Vec::new();
    let degrees = (1..=12).map(|i| 2.5 * i as f64).chain((7..=12).map(|i| 5.0 * i as f64));
    for deg in degrees {
        let theta = deg.to_radians();
        for s in [0.2, 0.3, 0.4, 0.45, 0.6, 0.8, 1.0, 1.5] {
            let Some(roots) = hoop.steady_turning_rates(theta, s) else { continue };
            for n in roots {
                if n.abs() <= 8.0 && crate::perturb::hoop_stability(hoop, theta, s, n).abs() >= 0.15
                {
                    out.push((theta, s, n));
                }
            }
        }
    }
    out
}

/// Integrates system (2) from `x0` with RK4 steps `dt` until the fall rate $p$ has changed sign
/// `count` times, locating each change by bisection on the length of the last step; returns
/// the states at those instants (`None` if it does not happen before `t_max`).
pub(crate) fn states_at_p_zeros(
    hoop: &Hoop,
    x0: [f64; 4],
    dt: f64,
    t_max: f64,
    count: usize,
) -> Option<Vec<(f64, [f64; 4])>> {
    let step = |x: [f64; 4], h: f64| rk4_step(|y| crate::perturb::hoop_rhs_pns(hoop, y), x, h);
    let (mut x, mut t) = (x0, 0.0);
    let mut out = Vec::new();
    while out.len() < count {
        if t > t_max {
            return None;
        }
        let next = step(x, dt);
        if x[1] != 0.0 && x[1] * next[1] < 0.0 {
            let (mut a, mut b) = (0.0, dt);
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                if step(x, m)[1] * x[1] > 0.0 {
                    a = m;
                } else {
                    b = m;
                }
            }
            let h = 0.5 * (a + b);
            out.push((t + h, step(x, h)));
        }
        x = next;
        t += dt;
    }
    Some(out)
}

/// Least-squares coefficients $c_1, c_3, \dots, c_{2m-1}$ of $p(t) \approx \sum c_k t^k$ (odd
/// powers) over the samples `(t, p)`, by Householder QR on the columns $(t/T)^k$, $T$ the
/// largest time.
pub(crate) fn odd_fit(samples: &[(f64, f64)], m: usize) -> Vec<f64> {
    let scale = samples.iter().map(|s| s.0).fold(0.0, f64::max);
    let rows = samples.len();
    // Columns (t/T)^(2j+1), reduced in place by Householder reflections.
    let mut cols: Vec<Vec<f64>> = (0..m)
        .map(|j| samples.iter().map(|(t, _)| (t / scale).powi(2 * j as i32 + 1)).collect())
        .collect();
    let mut b: Vec<f64> = samples.iter().map(|s| s.1).collect();
    let reflect = |v: &[f64], vv: f64, x: &mut [f64]| {
        let dot: f64 = v.iter().zip(x.iter()).map(|(a, b)| a * b).sum();
        for (xi, vi) in x.iter_mut().zip(v) {
            *xi -= 2.0 * dot / vv * vi;
        }
    };
    for j in 0..m {
        let norm = cols[j][j..].iter().map(|x| x * x).sum::<f64>().sqrt();
        let alpha = if cols[j][j] > 0.0 { -norm } else { norm };
        let mut v: Vec<f64> = cols[j][j..].to_vec();
        v[0] -= alpha;
        let vv: f64 = v.iter().map(|x| x * x).sum();
        if vv == 0.0 {
            continue;
        }
        for col in cols.iter_mut().skip(j) {
            reflect(&v, vv, &mut col[j..rows]);
        }
        reflect(&v, vv, &mut b[j..rows]);
    }
    let mut c = vec![0.0; m];
    for j in (0..m).rev() {
        let tail: f64 = (j + 1..m).map(|k| cols[k][j] * c[k]).sum();
        c[j] = (b[j] - tail) / cols[j][j];
    }
    c.iter().enumerate().map(|(j, cj)| cj / scale.powi(2 * j as i32 + 1)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_odd_fit_recovers_a_known_series() {
        // sinh t = t + t^3/6 + t^5/120 + ...
        let samples: Vec<(f64, f64)> =
            (1..=200).map(|i| 0.005 * i as f64).map(|t| (t, t.sinh())).collect();
        let c = odd_fit(&samples, 6);
        assert!((c[0] - 1.0).abs() < 1e-12);
        assert!((c[1] * 6.0 - 1.0).abs() < 1e-10);
        assert!((c[2] * 120.0 - 1.0).abs() < 1e-7, "{}", c[2] * 120.0);
    }

    #[test]
    fn a_fast_upright_hoop_oscillates_at_the_root_of_s() {
        let hoop = unit_hoop();
        let run = perturb(&hoop, (0.0, 1.0, 0.0), 1e-8, 0.005, 40.0);
        assert!(!run.diverged);
        // K = 8/3 - 2/3 = 2 in units g/R.
        assert!((run.rate - 2f64.sqrt()).abs() < 1e-4, "{}", run.rate);
    }
}
