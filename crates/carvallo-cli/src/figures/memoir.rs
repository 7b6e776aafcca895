//! The memoir's figures, redrawn from the derived formulas: 3, 4 and 4 bis (hoop, n° 13–17,
//! from [`carvallo::hoop_discussion`]), 7 and 9 (unicycle, n° 32 and 41, from
//! [`carvallo::unicycle_discussion`]), 11 and 13 (bicycle geometry, n° 52 and 54, from
//! [`carvallo::bicycle_geometry`], beside the printed tables of
//! [`carvallo_report::bicycle::geometry`]). They do not depend on the bicycle of `--model`.

use anyhow::{anyhow, Result};
use carvallo::bicycle_geometry::Geometry;
use carvallo::hoop_discussion::{self, Series};
use carvallo::unicycle_discussion;
use carvallo::whipple::WhippleParams;
use carvallo_report::bicycle::geometry::{LOCUS_CM, MU1_MIN, SIGMA1_MIN, TABLE_STEERS};
use plotters::prelude::*;

use super::chart::{color, Chart, Curve, Stroke};

const RATE_UNIT: &str = "unit √(g/R)";

pub(super) fn fig_3(_: &WhippleParams) -> Result<String> {
    let series = hoop_discussion::figure_3();
    let sp = hoop_discussion::special_points();
    let mut c = Chart::new(
        "Memoir fig. 3 — hoop: (ℰ), (S1), (S) in the plane x = cos θ, y = s²",
        "x = cos θ",
        &format!("y = s² ({RATE_UNIT} squared)"),
        0.48..1.02,
        0.0..0.6,
    );
    let strokes = [Stroke::Solid, Stroke::Dashed, Stroke::Solid];
    for (i, s) in series.iter().enumerate() {
        let pts = s.points.iter().copied().filter(|(_, y)| *y <= 0.6).collect();
        c.add(Curve::new(s.name.clone(), pts, color(i), strokes[i % 3]));
    }
    for (name, p) in [("A", sp.a), ("B", sp.b), ("D", sp.d), ("F", sp.f)] {
        c.mark(p, name);
    }
    c.mark_at((sp.vertical.x, sp.vertical.y), "vertical tangent of (S)", (-170, 4));
    c.legend = SeriesLabelPosition::UpperLeft;
    c.render()
}

/// The polar hoop figures: (ℰ) and (S) solid, n-curves dashed, other curves dotted.
fn polar_hoop(title: &str, series: &[Series], r_max: f64) -> Result<String> {
    let mut c = Chart::polar(title, RATE_UNIT, r_max, 70.0);
    for (i, s) in series.iter().enumerate() {
        let stroke = if s.name.starts_with("n =") {
            Stroke::Dashed
        } else if s.name.starts_with("D =") {
            Stroke::Dotted
        } else {
            Stroke::Solid
        };
        c.add_polar(s, color(i), stroke);
    }
    c.legend = SeriesLabelPosition::UpperRight;
    c.render()
}

pub(super) fn fig_4(_: &WhippleParams) -> Result<String> {
    polar_hoop(
        "Memoir fig. 4 — hoop: curves n = const, D = ±1/2, (ℰ), (S)",
        &hoop_discussion::figure_4(),
        2.0,
    )
}

pub(super) fn fig_4_bis(_: &WhippleParams) -> Result<String> {
    polar_hoop(
        "Memoir fig. 4 bis — hoop: walking and pivoting, (N)",
        &hoop_discussion::figure_4_bis(),
        2.0,
    )
}

pub(super) fn fig_7(_: &WhippleParams) -> Result<String> {
    let series = unicycle_discussion::figure_7();
    let mut c =
        Chart::polar("Memoir fig. 7 — unicycle (h/R = 2.5): steady states", RATE_UNIT, 2.6, 60.0);
    for (i, s) in series.iter().enumerate() {
        let stroke = if s.name.starts_with("n =") {
            Stroke::Dashed
        } else if s.name.starts_with("s =") {
            Stroke::Dotted
        } else {
            Stroke::Solid
        };
        c.add_polar(s, color(i), stroke);
    }
    let a = unicycle_discussion::asymptote_deg();
    let ray = Series {
        name: format!("asymptotic direction of (N), θ = {a:.1}°"),
        coords: unicycle_discussion::POLAR,
        points: vec![(a, 0.0), (a, 2.6)],
    };
    c.add_polar(&ray, BLACK, Stroke::Dashed);
    c.legend = SeriesLabelPosition::LowerRight;
    c.render()
}

pub(super) fn fig_9(_: &WhippleParams) -> Result<String> {
    let series = unicycle_discussion::figure_9();
    let (r1, r2) = unicycle_discussion::first_member_roots();
    let mut c = Chart::new(
        "Memoir fig. 9 — unicycle (h/R = 2.5): first member of the reality condition",
        "θ (degrees)",
        "first member (dimensionless)",
        0.0..72.0,
        -1.3..1.5,
    );
    c.add(Curve::new(series[0].name.clone(), series[0].points.clone(), color(0), Stroke::Solid));
    c.add(Curve::new(series[1].name.clone(), series[1].points.clone(), color(1), Stroke::Points));
    c.add(Curve::new("", vec![(0.0, 0.0), (72.0, 0.0)], BLACK, Stroke::Solid));
    c.mark((r1, 0.0), format!("{r1:.2}°"));
    c.mark((r2, 0.0), format!("{r2:.2}°"));
    c.legend = SeriesLabelPosition::UpperRight;
    c.render()
}

pub(super) fn fig_11(_: &WhippleParams) -> Result<String> {
    let g = Geometry::old_model();
    let data = g.figure_11(181).map_err(|e| anyhow!("figure 11: {e}"))?;
    let s0 = g.sigma0();
    let mu0 = |gamma: f64| (s0.tan() * gamma.to_radians().cos()).atan().to_degrees();
    let sigma1: Vec<(f64, f64)> = data.iter().map(|d| (d[0], 60.0 * d[1])).collect();
    let mu1: Vec<(f64, f64)> = data.iter().map(|d| (d[0], 60.0 * (d[2] - mu0(d[0])))).collect();
    let mut c = Chart::new(
        "Memoir fig. 11 — old bicycle, frame vertical: σ1 and μ1 against the steer",
        "steer γ (degrees)",
        "angle (minutes of arc)",
        0.0..90.0,
        -35.0..5.0,
    );
    c.add(Curve::new("σ1 = σ − σ0, exact", sigma1, color(0), Stroke::Solid));
    c.add(Curve::new("μ1 = μ − μ0, exact", mu1, color(1), Stroke::Solid));
    c.add(Curve::new(
        "σ1, memoir n° 52",
        TABLE_STEERS.iter().copied().zip(SIGMA1_MIN).collect(),
        color(0),
        Stroke::Points,
    ));
    c.add(Curve::new(
        "μ1, memoir n° 52",
        TABLE_STEERS.iter().copied().zip(MU1_MIN).collect(),
        color(1),
        Stroke::Points,
    ));
    c.legend = SeriesLabelPosition::LowerLeft;
    c.render()
}

pub(super) fn fig_13(_: &WhippleParams) -> Result<String> {
    let g = Geometry::old_model();
    let data = g.figure_13(181).map_err(|e| anyhow!("figure 13: {e}"))?;
    // The table's y is minus the printed formula's (J to the rider's left).
    let locus: Vec<(f64, f64)> = data.iter().map(|d| (100.0 * d[1], -100.0 * d[2])).collect();
    let mut c = Chart::new(
        "Memoir fig. 13 — locus of the front contact, frame vertical (old bicycle)",
        "x − l (cm, forward)",
        "y (cm, the table's sign)",
        -1.0..11.0,
        -9.0..5.0,
    );
    c.add(Curve::new("exact, γ = 0° … 90°", locus, color(0), Stroke::Solid));
    c.add(Curve::new("memoir n° 54", LOCUS_CM.to_vec(), color(1), Stroke::Points));
    for d in
        data.iter().filter(|d| (d[0].round() - d[0]).abs() < 1e-9 && d[0].round() as i64 % 20 == 0)
    {
        c.mark((100.0 * d[1], -100.0 * d[2]), format!("γ = {:.0}°", d[0]));
    }
    c.legend = SeriesLabelPosition::LowerLeft;
    c.render()
}
