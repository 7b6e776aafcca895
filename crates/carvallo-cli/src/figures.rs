//! The figures of `carvallo report --out DIR`, drawn with `plotters` (SVG backend).
//!
//! A figure is one small function that turns data from the runtime library into a [`Chart`]
//! plus one line in [`all`]; [`Chart::render`] draws it (Cartesian axes, or the memoir's polar
//! diagrams: polar angle $\theta$ measured from the vertical axis Oz, radius $s$, drawn as
//! $x = s\sin\theta$, $y = s\cos\theta$ with a polar grid). Figures the workspace cannot draw
//! honestly yet are listed in [`MISSING`] with the reason.
//!
//! Memoir figures: 3, 4 and 4 bis (hoop, n° 13–17, from [`carvallo::hoop_discussion`]), 7 and
//! 9 (unicycle, n° 32 and 41, from [`carvallo::unicycle_discussion`]). Modern figures: the
//! benchmark bicycle's eigenvalues against speed with the stable range shaded, and its stable
//! speed window against the trail and against the steer axis tilt; Carvallo's bicycle without
//! hands (n° 117–122, [`carvallo::bicycle_straight`]): its eigenvalues against speed with the
//! memoir's and the derived limits; the rear and front ground tracks of a nonlinear simulation
//! ([`carvallo::whipple_nonlinear`]) with their crossings (n° 106) counted from the data.

use std::ops::Range;

use anyhow::{anyhow, Result};
use carvallo::bicycle_geometry::Geometry;
use carvallo::bicycle_straight::{window, Constants, Equations};
use carvallo::hoop_discussion::{self, Series};
use carvallo::parameter_text::UncertainParams;
use carvallo::quartic::aberth_compensated;
use carvallo::unicycle_discussion;
use carvallo::whipple::{Whipple, WhippleParams, PARAM_NAMES};
use carvallo::whipple_nonlinear::WhippleNonlinear;
use carvallo::whipple_uncertainty::eigenvalue_bands;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// One figure of the report.
pub struct Figure {
    /// File name inside the output directory (`*.svg`).
    pub file: &'static str,
    /// Title, also the chart's caption.
    pub title: &'static str,
    /// One or two sentences saying what the figure shows and where it comes from.
    pub caption: &'static str,
    /// Computes the data and draws the figure for a bicycle (used by the modern figures only).
    pub draw: fn(&WhippleParams) -> Result<String>,
}

/// A figure of the memoir or of the issue that the workspace does not draw yet, and why.
pub struct Missing {
    /// Which figure.
    pub figure: &'static str,
    /// Why it is not drawn.
    pub reason: &'static str,
}

/// Every figure, in the order of the report. Adding a figure: write its function, add a line.
pub fn all() -> Vec<Figure> {
    vec![
        Figure { file: "fig03_hoop_equilibrium.svg", title: "Memoir fig. 3: hoop, reality and stability of the steady states (n° 13–14)", caption: "Plane x = cos θ, y = s² (rates in √(g/R)): the curve (ℰ) where the two roots n of (E) merge, the curve (S1) where those of S are real, and the stability limit (S) through its vertical tangent; points A, B, D, F of n° 14.", draw: fig_3 },
        Figure { file: "fig04_hoop_skid.svg", title: "Memoir fig. 4: hoop, skid tendency (n° 15–16)", caption: "Polar diagram (angle θ from the vertical, radius s in √(g/R)): the curves n = const of (E′), the curves D = ±1/2 of (D″), (ℰ) and (S).", draw: fig_4 },
        Figure { file: "fig04bis_hoop_walking.svg", title: "Memoir fig. 4 bis: hoop, walking and pivoting (n° 17)", caption: "Polar diagram: (ℰ), (S), the separation (N) between walking and pivoting, and the curves n2 = −0.1, −0.3, −0.5.", draw: fig_4_bis },
        Figure { file: "fig07_unicycle_diagram.svg", title: "Memoir fig. 7: unicycle steady states, h/R = 2.5 (n° 32, 41)", caption: "Polar diagram (angle θ from the vertical, radius s in √(g/R)): (ℰ), the curves n = const of (E), the separation (N) with its asymptote, the branch θ < 16° of the stability limit (S) of n° 41, and the practical limits s = 1 and 20 km/h.", draw: fig_7 },
        Figure { file: "fig09_unicycle_first_member.svg", title: "Memoir fig. 9: unicycle, reality condition of S(n²) (n° 41)", caption: "The first member 1/cos θ − (h/R) sin²θ cos θ − √(h/R) sin 2θ from the generated trinomial, against θ, with the memoir's table (n° 41); the derived zeros (marked) are 16.32° and 62.82°, which the memoir reads off its graph as 16°,0 and 62°,7.", draw: fig_9 },
        Figure { file: "fig11_bicycle_sigma1_mu1.svg", title: "Memoir fig. 11: bicycle geometry, frame vertical (n° 52)", caption: "The frame's rotation σ1 = σ − σ0 and the front contact's μ1 = μ − μ0 (tan μ0 = tan σ0 cos γ) against the steer γ, in minutes of arc, for the old bicycle of n° 52 (R = 0.38 m, l = 1.10 m, c = 0.08 m, σ0 = 25°): the exact solution of the contact equations (1), (2) by Newton's method (lines) and the memoir's table (points).", draw: fig_11 },
        Figure { file: "fig13_bicycle_contact_locus.svg", title: "Memoir fig. 13: locus of the front wheel's contact with the ground (n° 54)", caption: "The front contact M relative to its position M0 at γ = 0, frame vertical, old bicycle of n° 52, for γ from 0° to 90°: the exact solution (line, with γ marked every 20°) and the memoir's table (points); y is counted as in the memoir's table, whose sign is opposite to its printed formula y = −(R sin μ − c) sin γ (see the report, n° 54).", draw: fig_13 },
        Figure { file: "benchmark_eigenvalues.svg", title: "Benchmark bicycle: eigenvalues against speed", caption: "Real and imaginary parts of the four eigenvalues of the linearised Carvallo–Whipple bicycle (Meijaard et al. 2007 parameters unless --model is given) against the forward speed; the stable range is shaded.", draw: fig_eigenvalues },
        Figure { file: "carvallo_eigenvalues.svg", title: "Carvallo's bicycle without hands (n° 117–122): eigenvalues against speed", caption: "Time eigenvalues sλ (λ the roots of the quartic of n° 119, T = st) of Carvallo's bicycle, exactly linearised through the general model at the constants of n° 117, against v = Rs (R = 0.38 m), the stable range shaded; marked on the axis: the memoir's limits s² = 67.3 and 83.6 (v = 0.38√s²) and the derived ones.", draw: fig_carvallo_eigenvalues },
        Figure { file: "nonlinear_ground_tracks.svg", title: "Wheel ground tracks from a nonlinear simulation", caption: "Rear and front contact tracks of the nonlinear Carvallo–Whipple bicycle (benchmark parameters unless --model is given), RK4 from upright straight running at 4.6 m/s with an initial lean of 0.05 rad for 6 s; the number of crossings of the two tracks (n° 106), counted from the simulated data, is in the figure's title.", draw: fig_tracks },
        Figure { file: "benchmark_window_trail.svg", title: "Benchmark bicycle: stable speed range against the trail", caption: "Weave and capsize speeds and the stable range (shaded) as the trail c is varied, the other parameters fixed.", draw: fig_window_trail },
        Figure { file: "benchmark_window_tilt.svg", title: "Benchmark bicycle: stable speed range against the steer axis tilt", caption: "Weave and capsize speeds and the stable range (shaded) as the steer axis tilt λ (head angle 90° − λ) is varied in steps of 0.5°, the other parameters fixed. Below about 9.5° the benchmark has no stable speed; the curves there are the lowest roots of a0 (capsize) and of the Hurwitz determinant H3 (weave), which bound no stable range (a0 has no positive root at 1.5°, hence the gap).", draw: fig_window_tilt },
    ]
}

/// Figures not drawn, with the reason (listed in `report.md`); every figure the issues name is
/// drawn now.
pub const MISSING: [Missing; 0] = [];

/// How a curve is stroked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stroke {
    /// A solid line.
    Solid,
    /// A dashed line.
    Dashed,
    /// A dotted line.
    Dotted,
    /// Unconnected dots.
    Points,
}

/// One curve of a chart; an empty label keeps it out of the legend.
pub struct Curve {
    label: String,
    points: Vec<(f64, f64)>,
    color: RGBColor,
    stroke: Stroke,
}

impl Curve {
    fn new(
        label: impl Into<String>,
        points: Vec<(f64, f64)>,
        color: RGBColor,
        stroke: Stroke,
    ) -> Curve {
        Curve { label: label.into(), points, color, stroke }
    }
}

/// A labelled point; the label is drawn `offset` pixels from it.
struct Mark {
    at: (f64, f64),
    text: String,
    offset: (i32, i32),
}

/// A filled band: polygon, colour, legend label.
type Band = (Vec<(f64, f64)>, RGBColor, String);

/// What a figure draws: axes, curves, shaded rectangles and labelled points.
pub struct Chart {
    title: String,
    x_desc: String,
    y_desc: String,
    x: Range<f64>,
    y: Range<f64>,
    curves: Vec<Curve>,
    shade: Vec<[(f64, f64); 2]>,
    shade_label: String,
    marks: Vec<Mark>,
    /// Filled bands: a polygon (the lower edge forward, the upper edge back), its colour and
    /// legend label (empty: not in the legend).
    bands: Vec<Band>,
    /// Polar grid: maximal radius and ray step in degrees (`None`: Cartesian mesh).
    polar: Option<(f64, f64)>,
    legend: SeriesLabelPosition,
}

type DrawResult = std::result::Result<(), DrawingAreaErrorKind<std::io::Error>>;
type Context<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

const PALETTE: [RGBColor; 12] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
    RGBColor(188, 189, 34),
    RGBColor(0, 0, 128),
    RGBColor(128, 0, 0),
    RGBColor(70, 70, 70),
];
const GREY: RGBColor = RGBColor(150, 150, 150);
const FONT: &str = "sans-serif";

fn color(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

impl Chart {
    fn new(title: &str, x_desc: &str, y_desc: &str, x: Range<f64>, y: Range<f64>) -> Chart {
        Chart {
            title: title.to_string(),
            x_desc: x_desc.to_string(),
            y_desc: y_desc.to_string(),
            x,
            y,
            curves: Vec::new(),
            shade: Vec::new(),
            shade_label: String::new(),
            marks: Vec::new(),
            bands: Vec::new(),
            polar: None,
            legend: SeriesLabelPosition::UpperRight,
        }
    }

    /// A polar chart of radius up to `r_max` over θ in [0°, `theta_max`°] (θ from the vertical).
    fn polar(title: &str, unit: &str, r_max: f64, theta_max: f64) -> Chart {
        let x_max = r_max * theta_max.to_radians().sin().max(0.0) * 1.02;
        let mut c = Chart::new(
            title,
            &format!("s sin θ ({unit})"),
            &format!("s cos θ ({unit})"),
            -0.02 * r_max..x_max.max(0.3 * r_max),
            -0.02 * r_max..r_max * 1.04,
        );
        c.polar = Some((r_max, 10.0));
        c
    }

    fn add(&mut self, curve: Curve) {
        self.curves.push(curve);
    }

    /// Adds a polar series (θ in degrees, s), keeping points with s up to the grid radius.
    fn add_polar(&mut self, s: &Series, color: RGBColor, stroke: Stroke) {
        let r_max = self.polar.map_or(f64::INFINITY, |(r, _)| r);
        let x_max = self.x.end;
        let points = s
            .points
            .iter()
            .filter(|(_, r)| r.is_finite() && *r <= r_max * 1.001)
            .map(|&(t, r)| (r * t.to_radians().sin(), r * t.to_radians().cos()))
            .filter(|(x, _)| *x <= x_max)
            .collect();
        self.add(Curve::new(s.name.clone(), points, color, stroke));
    }

    fn mark(&mut self, at: (f64, f64), text: impl Into<String>) {
        self.marks.push(Mark { at, text: text.into(), offset: (6, -18) });
    }

    fn mark_at(&mut self, at: (f64, f64), text: impl Into<String>, offset: (i32, i32)) {
        self.marks.push(Mark { at, text: text.into(), offset });
    }

    /// Adds `points` as one curve per run without a gap: consecutive points more than
    /// `max_gap` apart in x are not joined (only the first piece is in the legend).
    fn add_pieces(
        &mut self,
        label: &str,
        points: &[(f64, f64)],
        max_gap: f64,
        color: RGBColor,
        stroke: Stroke,
    ) {
        let mut piece: Vec<(f64, f64)> = Vec::new();
        let mut first = true;
        for &p in points {
            if piece.last().is_some_and(|q| p.0 - q.0 > max_gap) {
                self.add(Curve::new(
                    if first { label } else { "" },
                    std::mem::take(&mut piece),
                    color,
                    stroke,
                ));
                first = false;
            }
            piece.push(p);
        }
        if !piece.is_empty() {
            self.add(Curve::new(if first { label } else { "" }, piece, color, stroke));
        }
    }

    /// Pixel size: 900 wide, height from the axis ranges for a polar chart (equal scales).
    fn size(&self) -> (u32, u32) {
        match self.polar {
            Some(_) => {
                let ratio = (self.y.end - self.y.start) / (self.x.end - self.x.start);
                let h = (820.0 * ratio + 140.0).clamp(500.0, 1100.0);
                (900, h as u32)
            }
            None => (900, 620),
        }
    }

    /// Draws the chart as an SVG document.
    pub fn render(&self) -> Result<String> {
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, self.size()).into_drawing_area();
            root.fill(&WHITE).map_err(|e| anyhow!("{e}"))?;
            self.draw_on(&root).map_err(|e| anyhow!("cannot draw `{}`: {e}", self.title))?;
            root.present().map_err(|e| anyhow!("{e}"))?;
        }
        Ok(svg)
    }

    fn draw_on(&self, root: &DrawingArea<SVGBackend<'_>, Shift>) -> DrawResult {
        let mut chart = ChartBuilder::on(root)
            .caption(&self.title, (FONT, 21))
            .margin(16)
            .x_label_area_size(52)
            .y_label_area_size(70)
            .build_cartesian_2d(self.x.clone(), self.y.clone())?;
        let mut mesh = chart.configure_mesh();
        mesh.x_desc(self.x_desc.as_str())
            .y_desc(self.y_desc.as_str())
            .axis_desc_style((FONT, 17))
            .label_style((FONT, 14))
            .light_line_style(WHITE.mix(0.0));
        if self.polar.is_some() {
            mesh.disable_mesh();
        }
        mesh.draw()?;
        if let Some((r_max, step)) = self.polar {
            self.draw_polar_grid(&mut chart, r_max, step)?;
        }
        if !self.shade.is_empty() {
            let fill = RGBColor(120, 200, 120).mix(0.35).filled();
            let series = chart.draw_series(self.shade.iter().map(|r| Rectangle::new(*r, fill)))?;
            if !self.shade_label.is_empty() {
                series
                    .label(self.shade_label.as_str())
                    .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], fill));
            }
        }
        for (polygon, color, label) in &self.bands {
            let fill = color.mix(0.25).filled();
            let series = chart.draw_series(std::iter::once(Polygon::new(polygon.clone(), fill)))?;
            if !label.is_empty() {
                series
                    .label(label.as_str())
                    .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], fill));
            }
        }
        for c in &self.curves {
            let style = c.color.stroke_width(2);
            let series = match c.stroke {
                Stroke::Solid => chart.draw_series(LineSeries::new(c.points.clone(), style))?,
                Stroke::Dashed => {
                    chart.draw_series(DashedLineSeries::new(c.points.clone(), 9, 6, style))?
                }
                Stroke::Dotted => {
                    chart.draw_series(DashedLineSeries::new(c.points.clone(), 2, 5, style))?
                }
                Stroke::Points => chart
                    .draw_series(c.points.iter().map(|p| Circle::new(*p, 2, c.color.filled())))?,
            };
            if !c.label.is_empty() {
                let (color, stroke) = (c.color, c.stroke);
                series.label(c.label.as_str()).legend(move |(x, y)| {
                    let style = color.stroke_width(2);
                    // One element type for every stroke: a dot and up to three dashes.
                    let (dot, dashes): (bool, &[(i32, i32)]) = match stroke {
                        Stroke::Points => (true, &[]),
                        Stroke::Solid => (false, &[(0, 20)]),
                        Stroke::Dashed => (false, &[(0, 8), (12, 20)]),
                        Stroke::Dotted => (false, &[(0, 3), (8, 11), (16, 19)]),
                    };
                    let seg = |k: usize| {
                        let pts = dashes.get(k).map_or(Vec::new(), |&(a, b)| vec![(a, 0), (b, 0)]);
                        PathElement::new(pts, style)
                    };
                    let dot_style = if dot { color.filled() } else { color.mix(0.0).filled() };
                    EmptyElement::at((x, y))
                        + Circle::new((10, 0), 3, dot_style)
                        + seg(0)
                        + seg(1)
                        + seg(2)
                });
            }
        }
        chart.draw_series(self.marks.iter().map(|m| {
            EmptyElement::at(m.at)
                + Circle::new((0, 0), 4, BLACK.filled())
                + Text::new(m.text.clone(), m.offset, (FONT, 15))
        }))?;
        chart
            .configure_series_labels()
            .position(self.legend.clone())
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK.mix(0.6))
            .label_font((FONT, 14))
            .draw()?;
        Ok(())
    }

    fn draw_polar_grid(&self, chart: &mut Context<'_, '_>, r_max: f64, step: f64) -> DrawResult {
        let grid = GREY.mix(0.5).stroke_width(1);
        let theta_max = (self.x.end / r_max).clamp(-1.0, 1.0).asin().to_degrees().max(step);
        let ring_step = nice_step(r_max);
        let mut r = ring_step;
        while r <= r_max * 1.0001 {
            let arc: Vec<(f64, f64)> = (0..=90)
                .map(|k| (k as f64).to_radians())
                .map(|t| (r * t.sin(), r * t.cos()))
                .collect();
            let arc: Vec<(f64, f64)> = arc.into_iter().filter(|(x, _)| *x <= self.x.end).collect();
            chart.draw_series(LineSeries::new(arc, grid))?;
            chart.draw_series(std::iter::once(Text::new(
                format!("s = {}", trim(r)),
                (0.015 * r_max, r - 0.035 * r_max),
                (FONT, 12).into_font().color(&GREY),
            )))?;
            r += ring_step;
        }
        let mut t = step;
        while t <= 90.0 + 1e-9 {
            let (sx, cy) = (t.to_radians().sin(), t.to_radians().cos());
            chart.draw_series(LineSeries::new(vec![(0.0, 0.0), (r_max * sx, r_max * cy)], grid))?;
            if t <= theta_max + 1e-9 {
                chart.draw_series(std::iter::once(Text::new(
                    format!("{t:.0}°"),
                    (1.01 * r_max * sx, 1.01 * r_max * cy),
                    (FONT, 13).into_font().color(&GREY),
                )))?;
            }
            t += step;
        }
        Ok(())
    }
}

fn nice_step(r_max: f64) -> f64 {
    let raw = r_max / 6.0;
    let p = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0].iter().map(|m| m * p).find(|s| *s >= raw).unwrap_or(raw)
}

fn trim(x: f64) -> String {
    let s = format!("{x:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

const RATE_UNIT: &str = "unit √(g/R)";

fn fig_3(_: &WhippleParams) -> Result<String> {
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

fn fig_4(_: &WhippleParams) -> Result<String> {
    polar_hoop(
        "Memoir fig. 4 — hoop: curves n = const, D = ±1/2, (ℰ), (S)",
        &hoop_discussion::figure_4(),
        2.0,
    )
}

fn fig_4_bis(_: &WhippleParams) -> Result<String> {
    polar_hoop(
        "Memoir fig. 4 bis — hoop: walking and pivoting, (N)",
        &hoop_discussion::figure_4_bis(),
        2.0,
    )
}

fn fig_7(_: &WhippleParams) -> Result<String> {
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

fn fig_9(_: &WhippleParams) -> Result<String> {
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

/// The memoir's table of n° 52 (γ in degrees; σ1 and μ1 in minutes, with the minus signs the
/// table's first row gives to the whole column).
const TABLE_52: [(f64, f64, f64); 6] = [
    (0.0, 0.0, 0.0),
    (20.0, -5.0, -5.0),
    (40.0, -19.0, -16.0),
    (60.0, -31.0, -19.0),
    (80.0, -19.0, -2.0),
    (90.0, -5.0, 0.0),
];

/// The memoir's table of n° 54 (γ in degrees; x − l and y in centimetres, y as printed).
const TABLE_54: [(f64, f64, f64); 6] = [
    (0.0, 0.0, 0.0),
    (20.0, 1.2, 2.5),
    (40.0, 4.5, 3.0),
    (60.0, 8.7, 0.4),
    (80.0, 9.5, -4.8),
    (90.0, 8.8, -8.0),
];

fn fig_11(_: &WhippleParams) -> Result<String> {
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
        TABLE_52.iter().map(|t| (t.0, t.1)).collect(),
        color(0),
        Stroke::Points,
    ));
    c.add(Curve::new(
        "μ1, memoir n° 52",
        TABLE_52.iter().map(|t| (t.0, t.2)).collect(),
        color(1),
        Stroke::Points,
    ));
    c.legend = SeriesLabelPosition::LowerLeft;
    c.render()
}

fn fig_13(_: &WhippleParams) -> Result<String> {
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
    c.add(Curve::new(
        "memoir n° 54",
        TABLE_54.iter().map(|t| (t.1, t.2)).collect(),
        color(1),
        Stroke::Points,
    ));
    for d in
        data.iter().filter(|d| (d[0].round() - d[0]).abs() < 1e-9 && d[0].round() as i64 % 20 == 0)
    {
        c.mark((100.0 * d[1], -100.0 * d[2]), format!("γ = {:.0}°", d[0]));
    }
    c.legend = SeriesLabelPosition::LowerLeft;
    c.render()
}

fn fig_eigenvalues(p: &WhippleParams) -> Result<String> {
    let bike = Whipple::new(p.clone());
    let v_max = 10.0;
    let mut points = Vec::new();
    for k in 0..=400 {
        let v = v_max * k as f64 / 400.0;
        points.extend(bike.eigenvalues(v).iter().map(|e| (v, e.re, e.im)));
    }
    let mut c = eigenvalue_chart(
        "Benchmark bicycle: eigenvalues of the linearised equations",
        v_max,
        10.0,
        points,
        &bike.stability_window().stable,
    );
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
        Some((a, b)) => format!("stable: {a:.3} < v < {b:.3} m/s"),
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
fn fig_carvallo_eigenvalues(_: &WhippleParams) -> Result<String> {
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

/// Speed (m/s), initial lean (rad), duration (s) and step (s) of the ground-track run.
const TRACK_RUN: (f64, f64, f64, f64) = (4.6, 0.05, 6.0, 0.004);

/// The rear and front contact tracks of the nonlinear bicycle from upright straight running
/// at 4.6 m/s with an initial lean of 0.05 rad, and the number of crossings counted from them
/// (n° 106: the two tracks cross periodically).
fn fig_tracks(p: &WhippleParams) -> Result<String> {
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
        Some((a, bb)) => format!("nominal stable: {a:.3} < v < {bb:.3} m/s"),
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

fn fig_window_trail(p: &WhippleParams) -> Result<String> {
    let values: Vec<f64> = (0..=40).map(|k| 0.005 * k as f64).collect();
    window_sweep(
        p,
        "c",
        &values,
        1.0,
        "Benchmark bicycle: stable speeds against the trail c",
        "trail c (m)",
    )
}

fn fig_window_tilt(p: &WhippleParams) -> Result<String> {
    let values: Vec<f64> = (0..=80).map(|k| 0.5 * k as f64).collect();
    window_sweep(
        p,
        "lambda",
        &values,
        std::f64::consts::PI / 180.0,
        "Benchmark bicycle: stable speeds against the steer axis tilt λ",
        "steer axis tilt λ (degrees; head angle 90° − λ)",
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn figure_files_are_distinct_svgs_and_the_missing_ones_are_named() {
        let figs = all();
        let mut files: Vec<&str> = figs.iter().map(|f| f.file).collect();
        files.sort_unstable();
        files.dedup();
        assert_eq!(files.len(), figs.len(), "two figures share a file name");
        assert!(files.iter().all(|f| f.ends_with(".svg") && !f.contains('/')));
        assert_eq!((figs.len(), MISSING.len()), (12, 0));
        for drawn in [
            "carvallo_eigenvalues.svg",
            "nonlinear_ground_tracks.svg",
            "fig11_bicycle_sigma1_mu1.svg",
            "fig13_bicycle_contact_locus.svg",
        ] {
            assert!(files.contains(&drawn), "{drawn} not drawn");
        }
    }

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
    fn a_chart_draws_its_axes_legend_and_curves_as_svg_text_and_paths() {
        let mut c = Chart::new("title t", "x (m)", "y (s)", 0.0..1.0, 0.0..1.0);
        c.add(Curve::new("line a", vec![(0.0, 0.0), (1.0, 1.0)], color(0), Stroke::Solid));
        c.add_pieces(
            "pieces b",
            &[(0.0, 0.5), (0.1, 0.5), (0.9, 0.5)],
            0.2,
            color(1),
            Stroke::Dashed,
        );
        c.mark((0.5, 0.5), "mark m");
        let svg = c.render().unwrap();
        for text in ["title t", "x (m)", "y (s)", "line a", "pieces b", "mark m"] {
            assert!(svg.contains(text), "no text `{text}` in the SVG");
        }
        // The gap splits "pieces b" into two curves, only the first in the legend.
        assert_eq!(c.curves.len(), 3);
        assert_eq!(svg.matches("pieces b").count(), 1);
        assert!(svg.matches("<text").count() >= 6 && svg.contains("<polyline"));
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
        assert!(max_re(0.99 * lo) > 0.0 && max_re(1.01 * hi) > 0.0, "stable outside it");
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
        let svg = fig_tracks(&WhippleParams::benchmark()).unwrap();
        assert!(svg.contains(&format!("cross {} times", at.len())));
    }
}
