//! The modern figures: the benchmark bicycle's eigenvalues against speed (and, for a model
//! with stated uncertainties, their Monte Carlo bands), its stable speed window against the
//! trail and against the steer axis tilt; Carvallo's bicycle without hands (n° 117–122,
//! [`carvallo::bicycle_straight`]): its eigenvalues against speed with the memoir's and the
//! derived limits; the rear and front ground tracks of a nonlinear simulation
//! ([`carvallo::whipple_nonlinear`]) with their crossings (n° 106) counted from the data, and
//! the error of that simulation against the work, for RK4 and the error-controlled pairs; the
//! Bode diagram (magnitude and phase) from the steer torque to the lean at a few speeds
//! ([`carvallo::whipple::transfer`]); the closed-loop stable speed range against the gain of
//! a balance-assist law ([`carvallo::whipple::feedback`]).

use anyhow::{anyhow, Result};
use carvallo::bicycle_straight::{window, Constants, Equations};
use carvallo::parameter_text::UncertainParams;
use carvallo::quartic::aberth_compensated;
use carvallo::whipple::transfer::{log_space, FrequencyPoint, Input, Output};
use carvallo::whipple::{Whipple, WhippleParams, PARAM_NAMES};
use carvallo::whipple_nonlinear::WhippleNonlinear;
use carvallo::whipple_uncertainty::eigenvalue_bands;
use plotters::prelude::*;

use super::chart::{color, trim, Chart, Curve, Stroke, GREY};

/// The report's eigenvalues of its bicycle `name`, labelled by mode
/// ([`super::bicycle::fig_modes`]).
pub(super) fn fig_eigenvalues(p: &WhippleParams, name: &str) -> Result<String> {
    super::bicycle::fig_modes(p, name, 10.0)
}

/// The eigenvalues of the bicycle `p` against speed up to `v_max` (401 speeds), titled
/// `title`, the stable range shaded.
pub fn fig_bicycle_eigenvalues(p: &WhippleParams, title: &str, v_max: f64) -> Result<String> {
    let bike = Whipple::new(p.clone());
    let mut points = Vec::new();
    for k in 0..=400 {
        let v = v_max * k as f64 / 400.0;
        points.extend(bike.eigenvalues(v).iter().map(|e| (v, e.re, e.im)));
    }
    let mut c = eigenvalue_chart(title, v_max, 10.0, points, &bike.stability_window().stable);
    c.legend = SeriesLabelPosition::LowerRight;
    c.render()
}

/// The common part of the eigenvalue figures: `points` (speed, Re λ, Im λ) as dots of Re λ
/// and of |Im λ| (non-real ones only) within ±`y_max`, the `stable` speed intervals shaded
/// (the first one named in the legend) and the axis λ = 0.
fn eigenvalue_chart(
    title: &str,
    v_max: f64,
    y_max: f64,
    points: Vec<(f64, f64, f64)>,
    stable: &[(f64, f64)],
) -> Chart {
    let mut c =
        Chart::new(title, "forward speed v (m/s)", "eigenvalue (1/s)", 0.0..v_max, -y_max..y_max);
    for &(a, b) in stable {
        c.shade.push([(a, -y_max), (b.min(v_max), y_max)]);
    }
    c.shade_label = match stable.first() {
        Some((a, b)) => format!("stable: {}", super::chart::speed_range(*a, *b)),
        None => "no stable speed".to_string(),
    };
    let inside = |y: &f64| (-y_max..=y_max).contains(y);
    let re = points.iter().map(|&(v, re, _)| (v, re)).filter(|(_, y)| inside(y)).collect();
    let im = points
        .iter()
        // Real roots found by an iteration keep an imaginary part at rounding level.
        .filter(|(_, re, im)| im.abs() > 1e-9 * re.abs().max(1.0))
        .map(|&(v, _, im)| (v, im.abs()))
        .filter(|(_, y)| inside(y))
        .collect();
    c.add(Curve::new("Re λ", re, color(0), Stroke::Points));
    c.add(Curve::new("|Im λ|", im, color(1), Stroke::Points));
    c.add(Curve::new("", vec![(0.0, 0.0), (v_max, 0.0)], BLACK, Stroke::Solid));
    c
}

/// Carvallo's bicycle without hands (n° 117–122), exactly linearised through the general
/// model: the roots λ of the quartic of n° 119 ($T = st$) scaled back to time eigenvalues
/// $s\lambda$ (1/s), against $v = Rs$, with the memoir's printed limits $s^2 = 67.3$ and
/// $83.6$ (n° 120–121) and the derived ones marked on the axis.
pub(super) fn fig_carvallo_eigenvalues(_: &WhippleParams, _: &str) -> Result<String> {
    let k = Constants::MEMOIR;
    let eq = Equations::via_whipple(&k).map_err(|e| anyhow!("{e}"))?;
    let v_max = 8.0;
    let mut points = Vec::new();
    for i in 1..=400 {
        let v = v_max * i as f64 / 400.0;
        let s = v / k.r;
        let roots = aberth_compensated(&eq.quartic(s));
        points.extend(roots.iter().map(|z| (v, s * z.re, s * z.im)));
    }
    let w = window(&|s| eq.quartic(s));
    let stable: Vec<(f64, f64)> = w.stable_s.iter().map(|(a, b)| (a * k.r, b * k.r)).collect();
    let mut c = eigenvalue_chart(
        "Carvallo's bicycle without hands (n° 117–122): eigenvalues against speed",
        v_max,
        12.0,
        points,
        &stable,
    );
    for (s2, name, dy) in [(67.3, "memoir lower", 22), (83.6, "memoir upper", 40)] {
        let v = k.r * f64::sqrt(s2);
        c.mark_at((v, 0.0), format!("{name} s² = {s2}: v = {v:.3}"), (40, dy));
    }
    for (s, name, dy) in [(w.weave_s, "derived lower", -40), (w.capsize_s, "derived upper", -22)] {
        if let Some(s) = s {
            let v = s * k.r;
            c.mark_at((v, 0.0), format!("{name} s² = {:.1}: v = {v:.3}", s * s), (40, dy));
        }
    }
    c.legend = SeriesLabelPosition::LowerRight;
    c.render()
}

/// The lateral gap $y_F - y_R$ between the tracks at each front sample $(x, y_F)$, the rear
/// track interpolated linearly at the same $x$ (both tracks run forward, so each is a function
/// $y(x)$), over the $x$ range both tracks cover: `((x, y_F), gap)`.
fn lateral_gaps(rear: &[(f64, f64)], front: &[(f64, f64)]) -> Vec<((f64, f64), f64)> {
    let rear_y = |x: f64| {
        let i = rear.partition_point(|p| p.0 < x);
        if i == 0 || i >= rear.len() {
            return None;
        }
        let ((x0, y0), (x1, y1)) = (rear[i - 1], rear[i]);
        Some(y0 + (y1 - y0) * (x - x0) / (x1 - x0))
    };
    front.iter().filter_map(|&(x, y)| rear_y(x).map(|yr| ((x, y), y - yr))).collect()
}

/// Where the front track crosses the rear one (the front sample after each crossing): sign
/// changes of the lateral gap $y_F - y_R$ of [`lateral_gaps`].
fn track_crossings(rear: &[(f64, f64)], front: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let gaps: Vec<((f64, f64), f64)> =
        lateral_gaps(rear, front).into_iter().filter(|(_, d)| *d != 0.0).collect();
    gaps.windows(2).filter(|w| (w[0].1 > 0.0) != (w[1].1 > 0.0)).map(|w| w[1].0).collect()
}

/// Every `k`-th point and the last one, so that at most about `n` remain.
fn decimate(points: &[(f64, f64)], n: usize) -> Vec<(f64, f64)> {
    let k = points.len().div_ceil(n.max(1)).max(1);
    let mut out: Vec<(f64, f64)> = points.iter().step_by(k).copied().collect();
    if let Some(&last) = points.last() {
        if out.last() != Some(&last) {
            out.push(last);
        }
    }
    out
}

/// The error of the nonlinear simulation (4.6 m/s, lean 0.05 rad, 5 s) against the right-hand
/// side evaluations, log-log: RK4 at steps 0.02 s / 2^k, DOPRI5 and DOP853 at rtol 1e-3 …
/// 1e-12 (atol 1e-3 rtol), the error the largest over the state (|x − ref| / max(1, |ref|)) and
/// over the samples every 0.01 s, against DOP853 at rtol 1e-14.
pub(super) fn fig_work_precision(p: &WhippleParams, _: &str) -> Result<String> {
    use carvallo::numerics::integrate::{Grid, Integration, Method};
    let bike = WhippleNonlinear::new(p.clone());
    let start = bike.initial_state(4.6, 0.05).map_err(|e| anyhow!("{e}"))?;
    let states = |how: &Integration, grid: &Grid| -> Result<(Vec<[f64; 10]>, usize)> {
        let tr = bike.simulate_with(start, grid, how, &[]).map_err(|e| anyhow!("{e}"))?;
        let rows = tr
            .samples
            .iter()
            .map(|s| {
                let x = s.state;
                [
                    x.x,
                    x.y,
                    x.yaw,
                    x.lean,
                    x.steer,
                    x.rear_wheel,
                    x.front_wheel,
                    x.lean_rate,
                    x.steer_rate,
                    x.rear_wheel_rate,
                ]
            })
            .collect();
        Ok((rows, tr.stats.rhs_evaluations))
    };
    let sample = Grid::new(5.0, 0.01, 1).map_err(|e| anyhow!("{e:?}"))?;
    let (reference, _) = states(&Integration::adaptive(Method::Dop853, 1e-14, 1e-17), &sample)?;
    let error = |rows: &[[f64; 10]]| -> f64 {
        let stride = (reference.len() - 1) / (rows.len() - 1).max(1);
        let mut worst = 1e-16f64;
        for (k, x) in rows.iter().enumerate() {
            for (a, b) in x.iter().zip(&reference[(k * stride).min(reference.len() - 1)]) {
                worst = worst.max((a - b).abs() / b.abs().max(1.0));
            }
        }
        worst
    };
    let mut curves = Vec::new();
    for (i, method) in [Method::Dopri5, Method::Dop853, Method::Vern9].into_iter().enumerate() {
        let mut pts = Vec::new();
        for k in 3..=12 {
            let rtol = 10f64.powi(-k);
            let (rows, n) = states(&Integration::adaptive(method, rtol, 1e-3 * rtol), &sample)?;
            pts.push(((n as f64).log10(), error(&rows).log10()));
        }
        curves.push(Curve::new(method.name(), pts, color(i), Stroke::Solid));
    }
    let mut pts = Vec::new();
    for k in 0..=6u32 {
        let every = 1usize << k;
        let grid =
            Grid::new(5.0, 0.02 / every as f64, every.max(2) / 2).map_err(|e| anyhow!("{e:?}"))?;
        let (rows, n) = states(&Integration::RK4, &grid)?;
        // RK4 at 0.02 s samples every 0.02 s: compare with every other reference sample.
        pts.push(((n as f64).log10(), error(&rows).log10()));
    }
    curves.push(Curve::new("rk4", pts, color(3), Stroke::Dashed));
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for c in &curves {
        for &(x, y) in &c.points {
            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
        }
    }
    let mut c = Chart::new(
        "Nonlinear bicycle, 4.6 m/s for 5 s: error against work",
        "log10 right-hand side evaluations",
        "log10 largest error over the samples",
        x0 - 0.1..x1 + 0.1,
        y0 - 0.5..y1 + 0.5,
    );
    for curve in curves {
        let marks = Curve::new("", curve.points.clone(), curve.color, Stroke::Points);
        c.add(curve);
        c.add(marks);
    }
    c.legend = SeriesLabelPosition::UpperRight;
    c.render()
}

/// Speed (m/s), initial lean (rad), duration (s) and step (s) of the ground-track run.
const TRACK_RUN: (f64, f64, f64, f64) = (4.6, 0.05, 6.0, 0.004);

/// The rear and front contact tracks of the nonlinear bicycle from upright straight running
/// at 4.6 m/s with an initial lean of 0.05 rad, and the number of crossings counted from them
/// (n° 106: the two tracks cross periodically).
pub(super) fn fig_tracks(p: &WhippleParams, _: &str) -> Result<String> {
    let (speed, lean0, duration, step) = TRACK_RUN;
    let bike = WhippleNonlinear::new(p.clone());
    let start = bike.initial_state(speed, lean0).map_err(|e| anyhow!("{e}"))?;
    let tr = bike.simulate(start, duration, step, 1).map_err(|e| anyhow!("{e}"))?;
    let rear: Vec<(f64, f64)> =
        tr.samples.iter().map(|s| (s.rear_contact[0], s.rear_contact[1])).collect();
    let front: Vec<(f64, f64)> =
        tr.samples.iter().map(|s| (s.front_contact[0], s.front_contact[1])).collect();
    let crossings = track_crossings(&rear, &front);
    // The weave shows in the gap between the tracks, centimetres beside metres of drift: the
    // gap is drawn magnified by a power of ten (named in the legend) so that it fills about
    // half the lateral range of the tracks.
    let gaps = lateral_gaps(&rear, &front);
    let span = |it: &mut dyn Iterator<Item = f64>| {
        it.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)))
    };
    let (y0, y1) = span(&mut rear.iter().chain(&front).map(|p| p.1));
    let (g0, g1) = span(&mut gaps.iter().map(|g| g.1));
    let gap_max = g0.abs().max(g1.abs()).max(1e-12);
    let track_span = (y1 - y0).max(1e-3);
    let magnify = 10f64.powf((0.5 * track_span / gap_max).log10().floor()).max(1.0);
    let gap: Vec<(f64, f64)> = gaps.iter().map(|&((x, _), d)| (x, magnify * d)).collect();
    let (lo, hi) = (y0.min(-magnify * gap_max), y1.max(magnify * gap_max));
    let pad = 0.08 * (hi - lo);
    let x0 = rear.iter().chain(&front).map(|p| p.0).fold(f64::INFINITY, f64::min);
    let x1 = rear.iter().chain(&front).map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    let mut c = Chart::new(
        &format!(
            "Ground tracks, v = {speed} m/s, lean0 = {lean0} rad: the tracks cross {} times",
            crossings.len()
        ),
        "x forward (m)",
        "y lateral (m)",
        x0..x1,
        lo - pad..hi + pad,
    );
    for (i, &(x, _)) in crossings.iter().enumerate() {
        c.mark_at(
            (x, 0.0),
            format!("crossing {}", i + 1),
            (-30, if i % 2 == 0 { -24 } else { 10 }),
        );
    }
    c.add(Curve::new("rear contact y", decimate(&rear, 1000), color(0), Stroke::Solid));
    c.add(Curve::new("front contact y", decimate(&front, 1000), color(1), Stroke::Dashed));
    let label = if magnify > 1.0 {
        format!("lateral gap front − rear × {magnify}")
    } else {
        "lateral gap front − rear".to_string()
    };
    c.add(Curve::new(label, decimate(&gap, 1000), color(2), Stroke::Solid));
    c.add(Curve::new("", vec![(x0, 0.0), (x1, 0.0)], GREY, Stroke::Solid));
    c.legend = SeriesLabelPosition::UpperLeft;
    c.render()
}

/// The benchmark-style eigenvalue figure of a bicycle with stated uncertainties: the nominal
/// real parts against speed and, for each of the four (sorted) real parts, the band between
/// the 2.5 % and 97.5 % quantiles of a seeded Monte Carlo sample
/// ([`carvallo::whipple_uncertainty::eigenvalue_bands`]); the nominal stable range shaded.
pub fn fig_eigenvalue_bands(u: &UncertainParams, samples: usize) -> Result<String> {
    let v_max = 10.0;
    let y_max = 10.0;
    let speeds: Vec<f64> = (0..=100).map(|k| v_max * k as f64 / 100.0).collect();
    let b = eigenvalue_bands(u, &speeds, samples, BAND_SEED, 0.025, 0.975);
    let mut c = Chart::new(
        &format!("Eigenvalues (real parts) with 95 % bands, {samples} Monte Carlo samples"),
        "forward speed v (m/s)",
        "Re λ (1/s)",
        0.0..v_max,
        -y_max..y_max,
    );
    let stable = Whipple::new(u.params.clone()).stability_window().stable;
    for &(a, bb) in &stable {
        c.shade.push([(a, -y_max), (bb.min(v_max), y_max)]);
    }
    c.shade_label = match stable.first() {
        Some((a, bb)) => format!("nominal stable: {}", super::chart::speed_range(*a, *bb)),
        None => "no stable speed (nominal)".to_string(),
    };
    let clip = |y: f64| y.clamp(-y_max, y_max);
    for k in 0..4 {
        let mut polygon: Vec<(f64, f64)> =
            speeds.iter().zip(&b.lower).map(|(&v, r)| (v, clip(r[k]))).collect();
        polygon.extend(speeds.iter().zip(&b.upper).rev().map(|(&v, r)| (v, clip(r[k]))));
        let label = if k == 0 { "95 % band of each Re λ".to_string() } else { String::new() };
        c.bands.push((polygon, color(0), label));
        let nominal: Vec<(f64, f64)> = speeds
            .iter()
            .zip(&b.nominal)
            .map(|(&v, r)| (v, r[k]))
            .filter(|(_, y)| y.abs() <= y_max)
            .collect();
        c.add(Curve::new(
            if k == 0 { "nominal Re λ" } else { "" },
            nominal,
            color(0),
            Stroke::Points,
        ));
    }
    c.add(Curve::new("", vec![(0.0, 0.0), (v_max, 0.0)], BLACK, Stroke::Solid));
    c.legend = SeriesLabelPosition::LowerRight;
    c.render()
}

/// The seed of the Monte Carlo sample of the report's uncertainty bands.
pub const BAND_SEED: u64 = 1897;

/// The stable window of `p` with parameter `key` set to each value of `values` (given in the
/// plotted unit, multiplied by `scale` for the model).
fn window_sweep(
    p: &WhippleParams,
    key: &str,
    values: &[f64],
    scale: f64,
    title: &str,
    x_desc: &str,
) -> Result<String> {
    let index = PARAM_NAMES.iter().position(|k| *k == key).ok_or_else(|| anyhow!("no {key}"))?;
    let v_max = 12.0;
    let step = values.get(1).zip(values.first()).map_or(1.0, |(b, a)| b - a);
    let mut c = Chart::new(
        title,
        x_desc,
        "forward speed v (m/s)",
        values[0]..values[values.len() - 1],
        0.0..v_max,
    );
    let (mut weave, mut capsize) = (Vec::new(), Vec::new());
    for &x in values {
        let mut vals = *p.values();
        vals[index] = x * scale;
        let Ok(params) = WhippleParams::from_values(vals) else { continue };
        let w = Whipple::new(params).stability_window();
        if let Some(v) = w.weave_speed.filter(|v| *v <= v_max) {
            weave.push((x, v));
        }
        if let Some(v) = w.capsize_speed.filter(|v| *v <= v_max) {
            capsize.push((x, v));
        }
        for (a, b) in w.stable {
            let (lo, hi) =
                ((x - step / 2.0).max(values[0]), (x + step / 2.0).min(values[values.len() - 1]));
            c.shade.push([(lo, a.min(v_max)), (hi, b.min(v_max))]);
        }
    }
    c.shade_label = "stable speeds".to_string();
    // Parameter values without a weave or capsize speed below v_max leave gaps.
    c.add_pieces("weave speed", &weave, 1.5 * step, color(0), Stroke::Solid);
    c.add_pieces("capsize speed", &capsize, 1.5 * step, color(1), Stroke::Dashed);
    let here = p.values()[index] / scale;
    c.add(Curve::new(
        format!("model value {}", trim(here)),
        vec![(here, 0.0), (here, v_max)],
        BLACK,
        Stroke::Dotted,
    ));
    c.legend = SeriesLabelPosition::UpperRight;
    c.render()
}

/// The balance-assist figure's gains [N m s/rad], speed axis (m/s) and target speed (m/s).
const ASSIST_GAINS: (f64, usize) = (50.0, 100);
const ASSIST_V_MAX: f64 = 8.0;
const ASSIST_TARGET: f64 = 2.0;

/// The closed-loop stable speed range of the balance-assist law $T_\delta = c\,\dot\varphi$
/// (`k_steer_roll_rate = -c`) against $c$: the stable speeds shaded (Hurwitz route on the
/// generated closed-loop polynomial), the lower edge, and the smallest $c$ that makes
/// [`ASSIST_TARGET`] stable (bisection on the lower edge).
pub(super) fn fig_balance_assist(p: &WhippleParams, _: &str) -> Result<String> {
    use carvallo::whipple::feedback::Gains;
    let bike = Whipple::new(p.clone());
    let (c_max, n) = ASSIST_GAINS;
    let step = c_max / n as f64;
    let mut chart = Chart::new(
        "Balance assist Tδ = c·dφ/dt: closed-loop stable speeds",
        "balance-assist gain c (N m s/rad)",
        "forward speed v (m/s)",
        0.0..c_max,
        0.0..ASSIST_V_MAX,
    );
    let mut lower = Vec::new();
    for i in 0..=n {
        let c = step * i as f64;
        let w = bike.closed_loop_window(&Gains::balance_assist(c), 0.0, ASSIST_V_MAX)?;
        for &(a, b) in &w.stable {
            let (lo, hi) = ((c - step / 2.0).max(0.0), (c + step / 2.0).min(c_max));
            chart.shade.push([(lo, a), (hi, b)]);
        }
        if let Some(v) = w.lowest_stable_speed() {
            lower.push((c, v));
        }
    }
    chart.shade_label = "closed-loop stable speeds".to_string();
    chart.add_pieces("lowest stable speed", &lower, 1.5 * step, color(0), Stroke::Solid);
    if let Some(c) = bike.balance_assist_gain(ASSIST_TARGET, 1000.0).filter(|c| *c <= c_max) {
        chart.add(Curve::new(
            format!("c = {c:.2} N m s/rad: stable down to {ASSIST_TARGET} m/s"),
            vec![(c, 0.0), (c, ASSIST_V_MAX)],
            BLACK,
            Stroke::Dotted,
        ));
    }
    chart.legend = SeriesLabelPosition::UpperRight;
    chart.render()
}

/// The speeds of the Bode figures [m/s]: below, inside and above the benchmark's stable range.
const BODE_SPEEDS: [f64; 4] = [2.0, 4.0, 5.0, 8.0];

/// The frequency response from the steer torque to the lean at [`BODE_SPEEDS`], 301
/// frequencies from 0.1 to 100 rad/s: (speed, points).
fn bode_data(p: &WhippleParams) -> Vec<(f64, Vec<FrequencyPoint>)> {
    let bike = Whipple::new(p.clone());
    let omegas = log_space(0.1, 100.0, 301).unwrap_or_default();
    BODE_SPEEDS
        .iter()
        .map(|&v| (v, bike.frequency_response(&[v], &omegas, Input::Steer, Output::Roll)))
        .collect()
}

/// A Bode panel: `value` of each point against ω on a logarithmic axis labelled by decades,
/// one curve per speed.
fn bode_chart(
    p: &WhippleParams,
    title: &str,
    y_desc: &str,
    value: fn(&FrequencyPoint) -> f64,
) -> Result<String> {
    let data = bode_data(p);
    let all: Vec<f64> = data.iter().flat_map(|(_, pts)| pts.iter().map(value)).collect();
    let (lo, hi) =
        all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| (a.min(y), b.max(y)));
    if !(lo.is_finite() && hi.is_finite()) {
        return Err(anyhow!("the frequency response is not finite"));
    }
    let pad = 0.05 * (hi - lo).max(1.0);
    let mut c =
        Chart::new(title, "angular frequency ω (rad/s)", y_desc, -1.0..2.0, lo - pad..hi + pad);
    c.log_x = true;
    for (k, (v, pts)) in data.iter().enumerate() {
        let xy = pts.iter().map(|q| (q.omega.log10(), value(q))).collect();
        c.add(Curve::new(format!("v = {} m/s", trim(*v)), xy, color(k), Stroke::Solid));
    }
    c.legend = SeriesLabelPosition::LowerLeft;
    c.render()
}

pub(super) fn fig_bode_magnitude(p: &WhippleParams, name: &str) -> Result<String> {
    bode_chart(
        p,
        &format!("{name}: steer torque to lean, magnitude (Bode diagram)"),
        "|φ/Tδ| (dB, rad per N m)",
        |q| q.magnitude_db,
    )
}

pub(super) fn fig_bode_phase(p: &WhippleParams, name: &str) -> Result<String> {
    bode_chart(
        p,
        &format!("{name}: steer torque to lean, phase (Bode diagram)"),
        "arg φ/Tδ (degrees, unwrapped)",
        |q| q.phase_deg,
    )
}

pub(super) fn fig_window_trail(p: &WhippleParams, name: &str) -> Result<String> {
    let values: Vec<f64> = (0..=40).map(|k| 0.005 * k as f64).collect();
    window_sweep(
        p,
        "c",
        &values,
        1.0,
        &format!("{name}: stable speeds against the trail c"),
        "trail c (m)",
    )
}

pub(super) fn fig_window_tilt(p: &WhippleParams, name: &str) -> Result<String> {
    let values: Vec<f64> = (0..=80).map(|k| 0.5 * k as f64).collect();
    window_sweep(
        p,
        "lambda",
        &values,
        std::f64::consts::PI / 180.0,
        &format!("{name}: stable speeds against the steer axis tilt λ"),
        "steer axis tilt λ (degrees; head angle 90° − λ)",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn track_crossings_counts_sign_changes_of_the_lateral_gap_and_decimate_keeps_the_ends() {
        // Rear y = 0; front y = sin(x) on x in [1, 20]: zeros at π, 2π, ..., 6π (6 crossings).
        let rear: Vec<(f64, f64)> = (0..=200).map(|i| (0.1 * i as f64, 0.0)).collect();
        let front: Vec<(f64, f64)> =
            (10..=200).map(|i| 0.1 * i as f64).map(|x| (x, x.sin())).collect();
        let at: Vec<f64> = track_crossings(&rear, &front).iter().map(|p| p.0).collect();
        assert_eq!(at.len(), 6, "{at:?}");
        for (k, x) in at.iter().enumerate() {
            let zero = (k + 1) as f64 * std::f64::consts::PI;
            assert!(*x >= zero && *x - zero <= 0.1 + 1e-12, "crossing {x} after zero {zero}");
        }
        // Parallel tracks never cross.
        let shifted: Vec<(f64, f64)> = rear.iter().map(|&(x, _)| (x, 0.01)).collect();
        assert!(track_crossings(&rear, &shifted).is_empty());
        let d = decimate(&front, 50);
        assert!(d.len() <= 51, "{}", d.len());
        assert_eq!((d[0], d[d.len() - 1]), (front[0], front[front.len() - 1]));
    }

    #[test]
    fn the_balance_assist_figure_marks_the_gain_for_the_target_speed() {
        let svg =
            fig_balance_assist(&WhippleParams::benchmark(), "Benchmark bicycle").expect("drawn");
        assert!(svg.contains("c = 17.62 N m s/rad: stable down to 2 m/s"), "legend");
        assert!(svg.contains("closed-loop stable speeds"));
    }

    #[test]
    fn carvallo_eigenvalue_roots_agree_with_the_hurwitz_window() {
        // The plotted roots (Aberth) and the shaded range (Routh–Hurwitz) are independent.
        let k = Constants::MEMOIR;
        let eq = Equations::via_whipple(&k).unwrap();
        let w = window(&|s| eq.quartic(s));
        let (lo, hi) = w.stable_s[0];
        let max_re = |s: f64| {
            aberth_compensated(&eq.quartic(s)).iter().map(|z| s * z.re).fold(f64::MIN, f64::max)
        };
        assert!(max_re(0.5 * (lo + hi)) < 0.0, "unstable inside the window");
        // At 1e-6 relative from each edge (the real parts there are 1e-7 or more, Aberth's
        // compensated roots about 1e-15): the old 1 % bracket accepted edges 1e4 times worse.
        let d = 1e-6;
        assert!(max_re(lo * (1.0 - d)) > 0.0 && max_re(hi * (1.0 + d)) > 0.0, "stable outside it");
        assert!(max_re(lo * (1.0 + d)) < 0.0 && max_re(hi * (1.0 - d)) < 0.0, "unstable inside it");
    }

    /// The largest real part of the roots of n° 118's equations at `s`, by a route shared
    /// with neither the Hurwitz window nor the quartic: the 4x4 state matrix
    /// $[[0, I], [-M^{-1} K(s), -M^{-1} C]]$ built from the 2x2 coefficient matrices, its
    /// eigenvalues by nalgebra's Schur decomposition.
    fn max_re_state_matrix(eq: &Equations, s: f64) -> f64 {
        let m = nalgebra::Matrix2::from_fn(|r, c| eq.m[r][c]);
        let k = nalgebra::Matrix2::from_fn(|r, c| eq.k0[r][c] / (s * s) + eq.k2[r][c]);
        let c = nalgebra::Matrix2::from_fn(|r, c| eq.c[r][c]);
        let mi = m.try_inverse().expect("M invertible");
        let (mk, mc) = (-mi * k, -mi * c);
        let a = nalgebra::Matrix4::from_fn(|r, col| match (r, col) {
            (0, 2) | (1, 3) => 1.0,
            (2 | 3, 0 | 1) => mk[(r - 2, col)],
            (2 | 3, 2 | 3) => mc[(r - 2, col - 2)],
            _ => 0.0,
        });
        a.complex_eigenvalues().iter().map(|z| z.re).fold(f64::MIN, f64::max)
    }

    #[test]
    fn the_hurwitz_edges_are_where_the_state_matrix_eigenvalues_cross() {
        // Budget: the edges are bisected on the Hurwitz determinants to about 1e-15 relative;
        // the eigenvalues' real parts carry about 1e-15 |λ| (|λ| < 20) of rounding, while
        // moving 1e-6 relative off an edge moves the crossing root's real part by about
        // 1e-6 s |dRe/ds| (measured: 1.5e-7 to 9.5e-7, the two sides equal to 5 digits), so
        // ±1e-6 relative brackets each edge with a hundredfold margin over 1e-9; the old ±1 %
        // would accept an edge 1e4 times worse.
        let designs = [
            ("n° 117's bicycle", Equations::via_whipple(&Constants::MEMOIR).unwrap()),
            ("the new bicycle", Equations::via_whipple(&Constants::MEMOIR_NEW).unwrap()),
            ("n° 118's printed numbers", Equations::MEMOIR_118),
        ];
        for (name, eq) in designs {
            let w = window(&|s| eq.quartic(s));
            let (lo, hi) = w.stable_s[0];
            let at = |s: f64| max_re_state_matrix(&eq, s);
            let (below, above) = (at(lo * (1.0 - 1e-6)), at(lo * (1.0 + 1e-6)));
            assert!(below > 1e-9 && above < -1e-9, "{name}: lower edge {lo}: {below}, {above}");
            let (inside, outside) = (at(hi * (1.0 - 1e-6)), at(hi * (1.0 + 1e-6)));
            assert!(
                inside < -1e-9 && outside > 1e-9,
                "{name}: upper edge {hi}: {inside}, {outside}"
            );
        }
    }

    #[test]
    fn the_benchmark_ground_tracks_cross_while_the_weave_decays() {
        // n° 106: the tracks cross periodically; at 4.6 m/s the weave is damped, not gone.
        let (speed, lean0, duration, step) = TRACK_RUN;
        let bike = WhippleNonlinear::new(WhippleParams::benchmark());
        let start = bike.initial_state(speed, lean0).unwrap();
        let tr = bike.simulate(start, duration, step, 1).unwrap();
        let rear: Vec<(f64, f64)> =
            tr.samples.iter().map(|s| (s.rear_contact[0], s.rear_contact[1])).collect();
        let front: Vec<(f64, f64)> =
            tr.samples.iter().map(|s| (s.front_contact[0], s.front_contact[1])).collect();
        let at = track_crossings(&rear, &front);
        assert!(at.len() >= 2, "{at:?}");
        assert!(at.windows(2).all(|w| w[1].0 > w[0].0), "{at:?}");
        let svg = fig_tracks(&WhippleParams::benchmark(), "Benchmark bicycle").unwrap();
        assert!(svg.contains(&format!("cross {} times", at.len())));
    }
}
