//! The figures of one bicycle or a few compared, titled by the bicycles' names
//! ([`crate::args::bicycle_name`]): the side view of the geometry
//! ([`carvallo::whipple::drawing::SideView`]), the eigenvalues against speed with each mode
//! labelled as `carvallo::whipple::modes` labels it (weave, capsize, caster), and the Bode
//! diagram (magnitude and phase, one panel each, on a logarithmic frequency axis labelled by
//! decades) of several bicycles or riders at one or more speeds, and the hands-free steady
//! turns in the speed–lean plane ([`fig_hands_free`]). `carvallo plot` draws the first three,
//! and the report draws the geometry, the eigenvalues and the hands-free turns of its bicycle.

use anyhow::{anyhow, Result};
use carvallo::whipple::drawing::SideView;
use carvallo::whipple::lean_rider::LeanRider;
use carvallo::whipple::modes::ModeLabel;
use carvallo::whipple::steady_turn::hands_free::{self, HandsFree, Special};
use carvallo::whipple::steady_turn::TurnSolver;
use carvallo::whipple::transfer::{FrequencyPoint, Input, Output};
use carvallo::whipple::{Whipple, WhippleParams};
use plotters::prelude::*;

use super::chart::{color, trim, Chart, Curve, Stroke, GREY};

/// The mode labels in the order of the legend, with their colours.
const MODES: [(ModeLabel, usize); 3] =
    [(ModeLabel::Weave, 0), (ModeLabel::Capsize, 1), (ModeLabel::Caster, 2)];

/// The leaning rider's mode labels: the bicycle's and the torso's.
const RIDER_MODES: [(ModeLabel, usize); 4] =
    [(ModeLabel::Weave, 0), (ModeLabel::Capsize, 1), (ModeLabel::Caster, 2), (ModeLabel::Torso, 3)];

/// A circle of radius `r` about `c`, as a closed polyline.
fn circle(c: [f64; 2], r: f64) -> Vec<(f64, f64)> {
    (0..=180)
        .map(|k| f64::from(k) * std::f64::consts::PI / 90.0)
        .map(|t| (c[0] + r * t.cos(), c[1] + r * t.sin()))
        .collect()
}

fn segment(a: [f64; 2], b: [f64; 2]) -> Vec<(f64, f64)> {
    vec![(a[0], a[1]), (b[0], b[1])]
}

/// The side view of each of `bikes` (name, view), on equal scales: wheels, the schematic frame
/// and fork, the steer axis (dashed) and the trail, the mass centres. One bicycle is drawn in
/// its parts' colours with each mass centre named; several are drawn one colour each, named in
/// the legend.
pub fn fig_geometry(bikes: &[(String, SideView)]) -> Result<String> {
    let first = &bikes.first().ok_or_else(|| anyhow!("no bicycle to draw"))?.1;
    let (mut x, mut h) = ([f64::INFINITY, f64::NEG_INFINITY], [0.0, f64::NEG_INFINITY]);
    for (_, v) in bikes {
        let (bx, bh) = v.extent();
        x = [x[0].min(bx[0]), x[1].max(bx[1])];
        h = [h[0].min(bh[0]), h[1].max(bh[1])];
    }
    let pad = 0.08 * (x[1] - x[0]).max(h[1] - h[0]).max(0.1);
    // Room on the right, and above the drawing for the labels and the legend (its entries
    // are about 18 pixels high, at the scale of the 792 pixels of the width).
    let x_range = x[0] - pad..x[1] + if bikes.len() > 1 { 6.0 * pad } else { 2.5 * pad };
    let entries = if bikes.len() > 1 { bikes.len() } else { 4 };
    let legend = (24.0 + 18.0 * entries as f64) * (x_range.end - x_range.start) / 792.0;
    let h_range = h[0] - 0.5 * pad..h[1] + pad + legend;
    let title = match bikes {
        [(name, _)] => format!("{name}: geometry"),
        _ => format!("Geometry: {}", who(bikes.iter().map(|b| b.0.as_str()))),
    };
    let mut c = Chart::new(&title, "x forward (m)", "height (m)", x_range.clone(), h_range);
    c.equal_scale = true;
    c.add(Curve::new("", vec![(x_range.start, 0.0), (x_range.end, 0.0)], GREY, Stroke::Solid));
    let single = bikes.len() == 1;
    for (i, (name, v)) in bikes.iter().enumerate() {
        let (wheel, frame, axis, trail) = if single {
            (color(11), color(0), color(11), color(1))
        } else {
            (color(i), color(i), color(i), color(i))
        };
        // One bicycle: each part in the legend; several: each bicycle once, by its frame.
        let legend = |what: &str| if single { what.to_string() } else { String::new() };
        c.add(Curve::new("", circle(v.rear_hub, v.rear_radius), wheel, Stroke::Solid));
        c.add(Curve::new("", circle(v.front_hub, v.front_radius), wheel, Stroke::Solid));
        let f = v.frame;
        c.add(Curve::new(
            if single { "frame (schematic) and fork".to_string() } else { name.clone() },
            vec![(f[0][0], f[0][1]), (f[1][0], f[1][1]), (f[2][0], f[2][1]), (f[0][0], f[0][1])],
            frame,
            Stroke::Solid,
        ));
        c.add(Curve::new("", segment(v.fork[0], v.fork[1]), frame, Stroke::Solid));
        // The tilt back from the vertical, of the axis's points (x0 − t sin λ, t cos λ).
        let [[x0, h0], [x1, h1]] = v.steer_axis;
        let lambda = (x0 - x1).atan2(h1 - h0);
        c.add(Curve::new(
            legend(&format!("steer axis, λ = {:.1}°", lambda.to_degrees())),
            segment(v.steer_axis[0], v.steer_axis[1]),
            axis,
            Stroke::Dashed,
        ));
        // Signed: the axis meets the ground ahead of the contact for a positive trail.
        let c_trail = v.trail[1][0] - v.trail[0][0];
        c.add(Curve::new(
            legend(&format!("trail c = {c_trail:.3} m")),
            segment(v.trail[0], v.trail[1]),
            trail,
            Stroke::Solid,
        ));
        let dots = v.mass_centres.iter().map(|m| (m.at[0], m.at[1])).collect();
        let label = if single { "mass centres" } else { "" };
        c.add(Curve::new(label, dots, if single { BLACK } else { color(i) }, Stroke::Dots));
    }
    c.legend = SeriesLabelPosition::UpperRight;
    if !single {
        return c.render();
    }
    // Labels of the mass centres, to the right (the rear wheel's to the left, clear of the
    // frame), and of the trail.
    for m in &first.mass_centres {
        let offset = match m.name {
            "rear wheel" => (-92, -20),
            "whole bicycle" => (8, 4),
            _ => (8, -18),
        };
        let text = if m.name == "whole bicycle" { "whole".to_string() } else { m.name.to_string() };
        c.label_at((m.at[0], m.at[1]), text, offset);
    }
    let [_, ground] = first.trail;
    c.label_at((ground[0], ground[1]), "c", (-8, 4));
    c.render()
}

/// The report's geometry figure of its bicycle `p` named `name` (the rider, if any, is in its
/// rear frame).
pub(super) fn fig_report_geometry(p: &WhippleParams, name: &str) -> Result<String> {
    fig_geometry(&[(name.to_string(), SideView::new(p, None))])
}

/// `a`, `a and b`, `a, b and c`.
fn names<'a>(list: impl Iterator<Item = &'a str>) -> String {
    let v: Vec<&str> = list.collect();
    match v.split_last() {
        None => String::new(),
        Some((last, [])) => last.to_string(),
        Some((last, head)) => format!("{} and {last}", head.join(", ")),
    }
}

/// The bicycles of a title: their names (`a and b`), or their count when the names are too long
/// for a title line (the legend names them).
fn who<'a>(list: impl Iterator<Item = &'a str>) -> String {
    let v: Vec<&str> = list.collect();
    let all = names(v.iter().copied());
    if all.chars().count() <= TITLE_NAMES {
        all
    } else {
        format!("{} bicycles", v.len())
    }
}

/// The most characters of names in a title: with the rest of a Bode title it still fits the
/// figure's width.
const TITLE_NAMES: usize = 40;

/// The eigenvalues of the bicycle `p` named `name` against speed up to `v_max` (301 speeds),
/// each labelled by its mode (`Whipple::modes`: continuation in speed from a reference where
/// the weave is a complex pair): the real parts in the mode's colour, the weave's imaginary
/// part (its frequency) dashed, the stable range shaded. A bicycle without a reference speed
/// (no speed up to 50 m/s with a complex pair and two real roots) is drawn unlabelled.
pub fn fig_modes(p: &WhippleParams, name: &str, v_max: f64) -> Result<String> {
    let bike = Whipple::new(p.clone());
    let speeds = modes_speeds(v_max);
    let title = format!("{name}: eigenvalues against speed");
    let Some(modes) = bike.modes(&speeds) else {
        return super::fig_bicycle_eigenvalues(p, &title, v_max);
    };
    let modes: Vec<Vec<Labelled>> = modes
        .iter()
        .map(|ms| ms.iter().map(|m| (m.label, m.eigenvalue.re, m.eigenvalue.im)).collect())
        .collect();
    draw_modes(&title, v_max, &speeds, &modes, &bike.stability_window().stable, &MODES)
}

/// The eigenvalues of Moore's leaning rider `rider` named `name` against speed up to `v_max`
/// (301 speeds), as [`fig_modes`] draws the bicycle's, with the torso's two roots beside the
/// weave, capsize and caster ([`LeanRider::modes`]); the stable range (none for a passive
/// torso) shaded. A rider without a reference speed is an error.
pub fn fig_rider_modes(rider: &LeanRider, name: &str, v_max: f64) -> Result<String> {
    let speeds = modes_speeds(v_max);
    let modes = rider.modes(&speeds).ok_or_else(|| {
        anyhow!("the leaning rider's modes have no reference speed (one complex pair and four real roots at 5 to 50 m/s)")
    })?;
    let modes: Vec<Vec<Labelled>> = modes
        .iter()
        .map(|ms| ms.iter().map(|m| (m.label, m.eigenvalue.re, m.eigenvalue.im)).collect())
        .collect();
    let stable = rider.stable_speeds(0.0, v_max, 300);
    let title = format!("{name}: eigenvalues against speed");
    draw_modes(&title, v_max, &speeds, &modes, &stable, &RIDER_MODES)
}

/// An eigenvalue with its label: (label, real part, imaginary part).
type Labelled = (ModeLabel, f64, f64);

/// The 301 speeds of an eigenvalue figure up to `v_max`.
fn modes_speeds(v_max: f64) -> Vec<f64> {
    (0..=300).map(|k| v_max * f64::from(k) / 300.0).collect()
}

/// The figure of [`fig_modes`]: the labelled eigenvalues `modes` at `speeds`, the `stable`
/// speed ranges shaded, the modes `legend` (label, colour) in its order.
fn draw_modes(
    title: &str,
    v_max: f64,
    speeds: &[f64],
    modes: &[Vec<Labelled>],
    stable: &[(f64, f64)],
    legend: &[(ModeLabel, usize)],
) -> Result<String> {
    let y_max = 10.0;
    let mut c =
        Chart::new(title, "forward speed v (m/s)", "eigenvalue (1/s)", 0.0..v_max, -y_max..y_max);
    for &(a, b) in stable {
        c.shade.push([(a, -y_max), (b.min(v_max), y_max)]);
    }
    c.shade_label = match stable.first() {
        Some((a, b)) => format!("stable: {}", super::chart::speed_range(*a, *b)),
        None => "no stable speed".to_string(),
    };
    let inside = |y: f64| (-y_max..=y_max).contains(&y);
    for &(label, k) in legend {
        let re: Vec<(f64, f64)> = speeds
            .iter()
            .zip(modes)
            .flat_map(|(&v, ms)| ms.iter().filter(move |m| m.0 == label).map(move |m| (v, m.1)))
            .filter(|p| inside(p.1))
            .collect();
        c.add(Curve::new(format!("{}: Re λ", label.name()), re, color(k), Stroke::Points));
    }
    let im: Vec<(f64, f64)> = speeds
        .iter()
        .zip(modes)
        .filter_map(|(&v, ms)| {
            ms.iter().find(|m| m.0 == ModeLabel::Weave && m.2 > 0.0).map(|m| (v, m.2))
        })
        .filter(|p| inside(p.1))
        .collect();
    c.add_pieces("weave: Im λ", &im, 1.5 * v_max / 300.0, color(0), Stroke::Dashed);
    c.add(Curve::new("", vec![(0.0, 0.0), (v_max, 0.0)], BLACK, Stroke::Solid));
    // The legend in the corner with the fewest points under it (its box is about a quarter
    // of the width and a fifth of the height), each mode's name beside its curve where the
    // curve is inside the frame and clear of the legend.
    let drawn: Vec<(f64, f64)> = c.curves.iter().flat_map(|k| k.points.iter().copied()).collect();
    let corners = [
        (SeriesLabelPosition::LowerRight, (0.74, 1.0), (-1.0, -0.56)),
        (SeriesLabelPosition::UpperRight, (0.74, 1.0), (0.56, 1.0)),
        (SeriesLabelPosition::UpperLeft, (0.0, 0.26), (0.56, 1.0)),
        (SeriesLabelPosition::LowerLeft, (0.0, 0.26), (-1.0, -0.56)),
    ];
    let under = |(x, y): (f64, f64), (x0, x1): (f64, f64), (y0, y1): (f64, f64)| {
        (x0 * v_max..=x1 * v_max).contains(&x) && (y0 * y_max..=y1 * y_max).contains(&y)
    };
    let (position, bx, by) = corners
        .into_iter()
        .min_by_key(|(_, bx, by)| drawn.iter().filter(|p| under(**p, *bx, *by)).count())
        .unwrap_or((SeriesLabelPosition::LowerRight, (0.74, 1.0), (-1.0, -0.56)));
    for &(label, _) in legend {
        let at = speeds.iter().zip(modes).rev().find_map(|(&v, ms)| {
            let m = ms.iter().find(|m| m.0 == label)?;
            let at = (v, m.1);
            (v <= 0.93 * v_max && at.1.abs() < 0.85 * y_max && !under(at, bx, by)).then_some(at)
        });
        if let Some(at) = at {
            // Above the rising curves, below left of the falling caster (right of it at the
            // left edge).
            let offset = match label {
                ModeLabel::Caster if at.0 > 0.15 * v_max => (-52, 6),
                ModeLabel::Caster => (8, 0),
                _ => (4, -22),
            };
            c.label_at(at, label.name(), offset);
        }
    }
    c.legend = position;
    c.render()
}

/// What an output is, for the axis: `lean φ`, `steer δ`, their rates.
fn output_text(o: Output) -> &'static str {
    match o {
        Output::Roll => "lean φ",
        Output::Steer => "steer δ",
        Output::RollRate => "lean rate dφ/dt",
        Output::SteerRate => "steer rate dδ/dt",
    }
}

fn input_text(i: Input) -> &'static str {
    match i {
        Input::Roll => "roll torque Tφ",
        Input::Steer => "steer torque Tδ",
    }
}

/// The Bode diagram from `input` to `output` of each of `bikes` (name, parameters) at each of
/// `speeds`, over `omegas` [rad/s]: the magnitude (dB) above, the phase (degrees, on the branch
/// of `carvallo bode`) below, both against ω on a logarithmic axis labelled by decades; one
/// curve per bicycle and speed, named in the legend.
pub fn fig_bode(
    bikes: &[(String, WhippleParams)],
    speeds: &[f64],
    omegas: &[f64],
    input: Input,
    output: Output,
) -> Result<String> {
    if bikes.is_empty() || speeds.is_empty() || omegas.is_empty() {
        return Err(anyhow!("nothing to draw: no bicycle, speed or frequency"));
    }
    let mut curves: Vec<(String, Vec<FrequencyPoint>)> = Vec::new();
    for (name, p) in bikes {
        let bike = Whipple::new(p.clone());
        for &v in speeds {
            let label = match (bikes.len(), speeds.len()) {
                (1, _) => format!("v = {} m/s", trim(v)),
                (_, 1) => name.clone(),
                _ => format!("{name}, v = {} m/s", trim(v)),
            };
            let pts = bike.frequency_response(&[v], omegas, input, output);
            curves.push((label, pts.into_iter().filter(|q| q.magnitude_db.is_finite()).collect()));
        }
    }
    let (w0, w1) =
        omegas.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &w| (a.min(w), b.max(w)));
    let (x0, x1) = (w0.log10().floor(), w1.log10().ceil().max(w0.log10().floor() + 1.0));
    let at = match speeds {
        [v] => format!(", v = {} m/s", trim(*v)),
        _ => String::new(),
    };
    let who = who(bikes.iter().map(|b| b.0.as_str()));
    let what = format!("{} to {}", input_text(input), output_text(output));
    let panel = |title: String, y_desc: &str, value: fn(&FrequencyPoint) -> f64| -> Result<Chart> {
        let all: Vec<f64> = curves.iter().flat_map(|(_, pts)| pts.iter().map(value)).collect();
        let (lo, hi) =
            all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| (a.min(y), b.max(y)));
        if !(lo.is_finite() && hi.is_finite()) {
            return Err(anyhow!("the frequency response is not finite"));
        }
        let pad = 0.06 * (hi - lo).max(1.0);
        let mut c =
            Chart::new(&title, "angular frequency ω (rad/s)", y_desc, x0..x1, lo - pad..hi + pad);
        c.log_x = true;
        for (k, (label, pts)) in curves.iter().enumerate() {
            let xy = pts.iter().map(|q| (q.omega.log10(), value(q))).collect();
            c.add(Curve::new(label.clone(), xy, color(k), Stroke::Solid));
        }
        c.legend = SeriesLabelPosition::LowerLeft;
        Ok(c)
    };
    let mut magnitude = panel(format!("{who}: {what}{at}"), "magnitude (dB)", |q| q.magnitude_db)?;
    magnitude.legend = SeriesLabelPosition::LowerLeft;
    let mut phase = panel("Phase".to_string(), "phase (degrees)", |q| q.phase_deg)?;
    // The legend is in the magnitude panel.
    for c in &mut phase.curves {
        c.label.clear();
    }
    Chart::render_stacked(&[magnitude, phase], 560)
}

/// The name of a family for the legend: its upright line of [`hands_free::LINES`], or, for the
/// `k`-th family meeting neither, `isolated k`.
fn line_name(f: &hands_free::Family, k: usize) -> String {
    if f.is_isolated() {
        format!("isolated {k}")
    } else if f.line_steer == hands_free::LINES[0] {
        "handlebar forward".to_string()
    } else {
        "handlebar reversed".to_string()
    }
}

/// The hands-free steady turns of the bicycle `p` named `name` in the speed–lean plane
/// ([`HandsFree::families`]: every family followed from its branch point on upright running,
/// straight ahead and with the handlebar reversed, towards positive lean, and those meeting
/// neither line, found by a scan; the families are symmetric in the lean): each family in its colour, solid where the turn is stable with no
/// steer torque, dashed where it is not, its branch point named with its speed, and its folds
/// in speed or lean and its branch points along it marked.
pub(super) fn fig_hands_free(p: &WhippleParams, name: &str) -> Result<String> {
    let solver = TurnSolver::new(p)?;
    let families = HandsFree::new(&solver).families()?;
    let points = || families.iter().flat_map(|f| f.points.iter());
    let v_max = points().map(|q| q.speed).fold(1.0, f64::max).ceil();
    let lean_max = (points().map(|q| q.lean).fold(0.1, f64::max) * 1.15).min(1.4);
    let mut c = Chart::new(
        &format!("{name}: hands-free steady turns (n° 97)"),
        "rear contact's speed v (m/s)",
        "lean φ (rad)",
        0.0..v_max,
        0.0..lean_max,
    );
    c.add(Curve::new("", vec![(0.0, 0.0), (v_max, 0.0)], BLACK, Stroke::Solid));
    if families.is_empty() {
        c.label_at((0.05 * v_max, 0.5 * lean_max), "no family branches below 20 m/s", (0, 0));
    }
    for (i, f) in families.iter().enumerate() {
        let line = line_name(f, 1 + families[..i].iter().filter(|g| g.is_isolated()).count());
        let (mut stable_named, mut unstable_named) = (false, false);
        let mut k = 0;
        while k < f.points.len() {
            let stable = f.points[k].stable;
            let mut end = k;
            while end + 1 < f.points.len() && f.points[end + 1].stable == stable {
                end += 1;
            }
            // Each run joined to the next one's first point, so that the curve is unbroken.
            let run: Vec<(f64, f64)> = f.points[k..=(end + 1).min(f.points.len() - 1)]
                .iter()
                .map(|q| (q.speed, q.lean))
                .collect();
            let named = if stable { &mut stable_named } else { &mut unstable_named };
            let label = if *named {
                String::new()
            } else {
                format!("{line}, {}", if stable { "stable" } else { "unstable" })
            };
            *named = true;
            let stroke = if stable { Stroke::Solid } else { Stroke::Dashed };
            c.add(Curve::new(label, run, color(i), stroke));
            k = end + 1;
        }
        if !f.is_isolated() {
            c.mark_at(
                (f.branch_speed, 0.0),
                format!("{} m/s", trim_to(f.branch_speed, 3)),
                if i % 2 == 0 { (-40, -22) } else { (6, -22) },
            );
        }
        // Folds and branch points, one mark for points closer than 2 % of the axes.
        let mut marked: Vec<(f64, f64)> = Vec::new();
        for s in &f.special {
            let (k, text) = match *s {
                Special::SpeedFold(k) | Special::LeanFold(k) => (k, "fold"),
                Special::Branch(k) => (k, "branch point"),
                Special::StabilityChange(_) => continue,
            };
            let q = &f.points[k.min(f.points.len() - 1)];
            let at = (q.speed, q.lean);
            let near = |m: &(f64, f64)| {
                (m.0 - at.0).abs() < 0.02 * v_max && (m.1 - at.1).abs() < 0.02 * lean_max
            };
            if marked.iter().any(near) {
                continue;
            }
            marked.push(at);
            c.mark_at(at, text, (6, -18));
        }
    }
    c.legend = SeriesLabelPosition::UpperLeft;
    c.render()
}

/// `x` with `digits` decimals.
fn trim_to(x: f64, digits: usize) -> String {
    format!("{x:.digits$}")
}

#[cfg(test)]
mod tests {
    use super::super::chart::svg_texts;
    use super::*;
    use carvallo::parameter_text::Rider;

    #[test]
    fn the_benchmark_side_view_has_its_contacts_hubs_and_trail_where_the_table_puts_them() {
        // Meijaard et al. 2007, Table 1: w = 1.02, c = 0.08, λ = π/10, rR = 0.3, rF = 0.35.
        let v = SideView::new(&WhippleParams::benchmark(), None);
        let lam = std::f64::consts::PI / 10.0;
        let close =
            |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12;
        assert!(close(v.rear_contact, [0.0, 0.0]) && close(v.rear_hub, [0.0, 0.3]));
        assert!(close(v.front_contact, [1.02, 0.0]) && close(v.front_hub, [1.02, 0.35]));
        // The axis meets the ground 0.08 m ahead of the front contact, tilted back by λ.
        assert!(close(v.trail[0], [1.02, 0.0]) && close(v.trail[1], [1.10, 0.0]));
        assert!(close(v.steer_axis[0], [1.10, 0.0]));
        let [[x0, h0], [x1, h1]] = v.steer_axis;
        assert!(((x0 - x1) / (h1 - h0) - lam.tan()).abs() < 1e-12);
        // The top at the higher of the front wheel's top 2 rF = 0.70 and H's height 0.70.
        assert!((h1 - 0.7).abs() < 1e-12, "{h1}");
        // The fork offset rF sin λ − c cos λ, and its foot on the axis.
        let e = 0.35 * lam.sin() - 0.08 * lam.cos();
        assert!((v.fork_offset() - e).abs() < 1e-12, "{} {e}", v.fork_offset());
        // A long trail puts the hub behind the axis: a negative offset.
        let mut long = *WhippleParams::benchmark().values();
        long[1] = 0.2;
        let behind = SideView::new(&WhippleParams::from_values(long).unwrap(), None).fork_offset();
        let e_long = 0.35 * lam.sin() - 0.2 * lam.cos();
        assert!(e_long < 0.0 && (behind - e_long).abs() < 1e-12, "{behind} {e_long}");
        let [hub, foot] = v.fork;
        let along = [(foot[0] - 1.10) / -lam.sin(), foot[1] / lam.cos()];
        assert!((along[0] - along[1]).abs() < 1e-12, "the foot is on the axis");
        let d = [hub[0] - foot[0], hub[1] - foot[1]];
        assert!((d[0] * -lam.sin() + d[1] * lam.cos()).abs() < 1e-12, "perpendicular");
        // Mass centres: H at (0.9, 0.7), B at (0.3, 0.9); the whole one by hand.
        let at = |n: &str| v.mass_centres.iter().find(|m| m.name == n).map(|m| m.at).unwrap();
        assert!(close(at("front frame"), [0.9, 0.7]) && close(at("rear frame"), [0.3, 0.9]));
        let m = 2.0 + 85.0 + 4.0 + 3.0;
        let whole = [
            (85.0 * 0.3 + 4.0 * 0.9 + 3.0 * 1.02) / m,
            (2.0 * 0.3 + 85.0 * 0.9 + 4.0 * 0.7 + 3.0 * 0.35) / m,
        ];
        assert!(close(at("whole bicycle"), whole), "{:?} {whole:?}", at("whole bicycle"));
        // A rider apart: its centre (x, −z), and counted in the whole.
        let rider =
            Rider { values: [72.0, 0.29, 0.0, -1.11, 8.0, -1.9, 8.1, 2.4], sigma: [0.0; 8] };
        let w = SideView::new(&WhippleParams::benchmark(), Some(&rider));
        let at =
            |n: &str| w.mass_centres.iter().find(|m| m.name == n).map(|m| (m.mass, m.at)).unwrap();
        assert_eq!(at("rider"), (72.0, [0.29, 1.11]));
        assert!((at("whole bicycle").0 - (m + 72.0)).abs() < 1e-12);
    }

    #[test]
    fn the_figures_name_the_bicycle_the_modes_and_the_decades() {
        let p = WhippleParams::benchmark();
        let svg = fig_geometry(&[("Browser + Jason".into(), SideView::new(&p, None))]).unwrap();
        let texts = svg_texts(&svg);
        assert!(texts.iter().any(|t| t == "Browser + Jason: geometry"), "{texts:?}");
        for t in ["trail c = 0.080 m", "steer axis, λ = 18.0°", "rear frame", "front frame"] {
            assert!(texts.iter().any(|x| x == t), "no `{t}` in {texts:?}");
        }
        let texts = svg_texts(&fig_modes(&p, "Browser + Jason", 10.0).unwrap());
        assert!(texts.iter().any(|t| t == "Browser + Jason: eigenvalues against speed"));
        for t in [
            "weave: Re λ",
            "capsize: Re λ",
            "caster: Re λ",
            "weave: Im λ",
            "weave",
            "capsize",
            "caster",
        ] {
            assert!(texts.iter().any(|x| x == t), "no `{t}` in {texts:?}");
        }
        let mut light = p.clone();
        let mut vals = *light.values();
        vals[1] = 0.06;
        light = WhippleParams::from_values(vals).unwrap();
        let omegas = carvallo::whipple::transfer::log_space(0.1, 100.0, 61).unwrap();
        let svg = fig_bode(
            &[("Benchmark".into(), p), ("Short trail".into(), light)],
            &[5.0],
            &omegas,
            Input::Steer,
            Output::Roll,
        )
        .unwrap();
        let texts = svg_texts(&svg);
        for t in [
            "10⁻¹",
            "10⁰",
            "10¹",
            "10²",
            "Benchmark",
            "Short trail",
            "magnitude (dB)",
            "phase (degrees)",
        ] {
            assert!(texts.iter().any(|x| x == t), "no `{t}` in {texts:?}");
        }
        assert!(texts.iter().any(|t| t.starts_with("Benchmark and Short trail: steer torque")));
        assert!(!texts.iter().any(|t| t.contains("log10")));
        // Names too long for the title are counted there and named in the legend.
        let long: Vec<(String, WhippleParams)> =
            ["Alpha + Alexandra", "Bravo + Bartholomew", "Charlie + Christine"]
                .iter()
                .map(|n| (n.to_string(), WhippleParams::benchmark()))
                .collect();
        let texts =
            svg_texts(&fig_bode(&long, &[5.0], &omegas, Input::Steer, Output::Roll).unwrap());
        assert!(texts.iter().any(|t| t.starts_with("3 bicycles: steer torque")), "{texts:?}");
        assert!(texts.iter().any(|t| t == "Bravo + Bartholomew"), "{texts:?}");
    }
}
