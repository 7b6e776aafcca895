//! The chart engine of the figures: a [`Chart`] is what a figure draws (axes, curves, shaded
//! speed ranges, filled bands, labelled points; Cartesian, or the memoir's polar diagrams with
//! the polar angle $\theta$ measured from the vertical axis Oz and radius $s$, drawn as
//! $x = s\sin\theta$, $y = s\cos\theta$ with a polar grid), and [`Chart::render`] draws it as SVG
//! with `plotters`.

use std::ops::Range;

use anyhow::{anyhow, Result};
use carvallo::hoop_discussion::Series;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// How a curve is stroked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Stroke {
    /// A solid line.
    Solid,
    /// A dashed line.
    Dashed,
    /// A dotted line.
    Dotted,
    /// Unconnected dots.
    Points,
    /// Unconnected large dots (a few points that matter, as mass centres).
    Dots,
}

/// One curve of a chart; an empty label keeps it out of the legend.
pub(super) struct Curve {
    pub(super) label: String,
    pub(super) points: Vec<(f64, f64)>,
    pub(super) color: RGBColor,
    pub(super) stroke: Stroke,
}

impl Curve {
    pub(super) fn new(
        label: impl Into<String>,
        points: Vec<(f64, f64)>,
        color: RGBColor,
        stroke: Stroke,
    ) -> Curve {
        Curve { label: label.into(), points, color, stroke }
    }
}

/// A labelled point; the label is drawn `offset` pixels from it, with a dot at the point or
/// without (a curve's name beside it).
pub(super) struct Mark {
    pub(super) at: (f64, f64),
    pub(super) text: String,
    pub(super) offset: (i32, i32),
    pub(super) dot: bool,
}

/// A filled band: polygon, colour, legend label.
pub(super) type Band = (Vec<(f64, f64)>, RGBColor, String);

/// What a figure draws: axes, curves, shaded rectangles and labelled points.
pub(super) struct Chart {
    pub(super) title: String,
    pub(super) x_desc: String,
    pub(super) y_desc: String,
    pub(super) x: Range<f64>,
    pub(super) y: Range<f64>,
    pub(super) curves: Vec<Curve>,
    pub(super) shade: Vec<[(f64, f64); 2]>,
    pub(super) shade_label: String,
    pub(super) marks: Vec<Mark>,
    /// Filled bands: a polygon (the lower edge forward, the upper edge back), its colour and
    /// legend label (empty: not in the legend).
    pub(super) bands: Vec<Band>,
    /// Polar grid: maximal radius and ray step in degrees (`None`: Cartesian mesh).
    pub(super) polar: Option<(f64, f64)>,
    /// The x values are $\log_{10}$ of the quantity: ticks at the decades labelled as powers
    /// of ten (`10⁻¹`, `10⁰`, `10¹`), light lines at 2…9 times each.
    pub(super) log_x: bool,
    /// Equal scales on both axes (a drawing): the height follows from the ranges.
    pub(super) equal_scale: bool,
    pub(super) legend: SeriesLabelPosition,
}

pub(super) type DrawResult = std::result::Result<(), DrawingAreaErrorKind<std::io::Error>>;
pub(super) type Context<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

pub(super) const PALETTE: [RGBColor; 12] = [
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
pub(super) const GREY: RGBColor = RGBColor(150, 150, 150);
pub(super) const FONT: &str = "sans-serif";

pub(super) fn color(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

impl Chart {
    pub(super) fn new(
        title: &str,
        x_desc: &str,
        y_desc: &str,
        x: Range<f64>,
        y: Range<f64>,
    ) -> Chart {
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
            log_x: false,
            equal_scale: false,
            legend: SeriesLabelPosition::UpperRight,
        }
    }

    /// A polar chart of radius up to `r_max` over θ in [0°, `theta_max`°] (θ from the vertical).
    pub(super) fn polar(title: &str, unit: &str, r_max: f64, theta_max: f64) -> Chart {
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

    pub(super) fn add(&mut self, curve: Curve) {
        self.curves.push(curve);
    }

    /// Adds a polar series (θ in degrees, s), keeping points with s up to the grid radius.
    pub(super) fn add_polar(&mut self, s: &Series, color: RGBColor, stroke: Stroke) {
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

    pub(super) fn mark(&mut self, at: (f64, f64), text: impl Into<String>) {
        self.marks.push(Mark { at, text: text.into(), offset: (6, -18), dot: true });
    }

    pub(super) fn mark_at(&mut self, at: (f64, f64), text: impl Into<String>, offset: (i32, i32)) {
        self.marks.push(Mark { at, text: text.into(), offset, dot: true });
    }

    /// A text `offset` pixels from the point `at`, without a dot (a curve's name).
    pub(super) fn label_at(&mut self, at: (f64, f64), text: impl Into<String>, offset: (i32, i32)) {
        self.marks.push(Mark { at, text: text.into(), offset, dot: false });
    }

    /// Adds `points` as one curve per run without a gap: consecutive points more than
    /// `max_gap` apart in x are not joined (only the first piece is in the legend).
    pub(super) fn add_pieces(
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

    /// Pixel size: 900 wide, height from the axis ranges for a polar chart or a drawing (equal
    /// scales).
    pub(super) fn size(&self) -> (u32, u32) {
        match self.polar {
            _ if self.equal_scale => {
                let ratio = (self.y.end - self.y.start) / (self.x.end - self.x.start);
                // The plot area is 792 pixels wide and the height less 115.
                let h = (792.0 * ratio + 115.0).clamp(300.0, 1100.0);
                (900, h as u32)
            }
            Some(_) => {
                let ratio = (self.y.end - self.y.start) / (self.x.end - self.x.start);
                let h = (820.0 * ratio + 140.0).clamp(500.0, 1100.0);
                (900, h as u32)
            }
            None => (900, 620),
        }
    }

    /// Draws the chart as an SVG document.
    pub(super) fn render(&self) -> Result<String> {
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, self.size()).into_drawing_area();
            root.fill(&WHITE).map_err(|e| anyhow!("{e}"))?;
            self.draw_on(&root).map_err(|e| anyhow!("cannot draw `{}`: {e}", self.title))?;
            root.present().map_err(|e| anyhow!("{e}"))?;
        }
        Ok(svg)
    }

    /// Draws several charts stacked in one SVG document, each `height` pixels high.
    pub(super) fn render_stacked(charts: &[Chart], height: u32) -> Result<String> {
        let mut svg = String::new();
        {
            let n = charts.len().max(1);
            let root =
                SVGBackend::with_string(&mut svg, (900, height * n as u32)).into_drawing_area();
            root.fill(&WHITE).map_err(|e| anyhow!("{e}"))?;
            for (chart, area) in charts.iter().zip(root.split_evenly((n, 1))) {
                chart.draw_on(&area).map_err(|e| anyhow!("cannot draw `{}`: {e}", chart.title))?;
            }
            root.present().map_err(|e| anyhow!("{e}"))?;
        }
        Ok(svg)
    }

    pub(super) fn draw_on(&self, root: &DrawingArea<SVGBackend<'_>, Shift>) -> DrawResult {
        let mut chart = ChartBuilder::on(root)
            .caption(&self.title, (FONT, 21))
            .margin(16)
            .x_label_area_size(52)
            .y_label_area_size(70)
            .build_cartesian_2d(self.x.clone(), self.y.clone())?;
        let decades = |x: &f64| decade_label(*x);
        // A drawing's ticks without `-0.0` for a zero that rounding put below it.
        let metres = |x: &f64| format!("{:.1}", if x.abs() < 1e-9 { 0.0 } else { *x });
        let mut mesh = chart.configure_mesh();
        mesh.x_desc(self.x_desc.as_str())
            .y_desc(self.y_desc.as_str())
            .axis_desc_style((FONT, 17))
            .label_style((FONT, 14))
            .light_line_style(WHITE.mix(0.0));
        if self.equal_scale {
            mesh.x_label_formatter(&metres).y_label_formatter(&metres);
        }
        if self.log_x {
            // One tick per decade (the range runs from decade to decade).
            let n = (self.x.end - self.x.start).round().max(1.0) as usize + 1;
            mesh.x_labels(n).x_label_formatter(&decades);
        }
        if self.polar.is_some() {
            mesh.disable_mesh();
        }
        mesh.draw()?;
        if self.log_x {
            let light = GREY.mix(0.25).stroke_width(1);
            let (y0, y1) = (self.y.start, self.y.end);
            for d in self.x.start.floor() as i32..self.x.end.ceil() as i32 {
                for k in 2..=9 {
                    let x = f64::from(d) + f64::from(k).log10();
                    if self.x.contains(&x) {
                        chart.draw_series(LineSeries::new(vec![(x, y0), (x, y1)], light))?;
                    }
                }
            }
        }
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
                Stroke::Dots => chart
                    .draw_series(c.points.iter().map(|p| Circle::new(*p, 4, c.color.filled())))?,
            };
            if !c.label.is_empty() {
                let (color, stroke) = (c.color, c.stroke);
                series.label(c.label.as_str()).legend(move |(x, y)| {
                    let style = color.stroke_width(2);
                    // One element type for every stroke: a dot and up to three dashes.
                    let (dot, dashes): (bool, &[(i32, i32)]) = match stroke {
                        Stroke::Points | Stroke::Dots => (true, &[]),
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
            let dot = if m.dot { BLACK.filled() } else { BLACK.mix(0.0).filled() };
            EmptyElement::at(m.at)
                + Circle::new((0, 0), 4, dot)
                + Text::new(m.text.clone(), m.offset, (FONT, 15))
        }))?;
        let labelled = self.curves.iter().any(|c| !c.label.is_empty())
            || (!self.shade.is_empty() && !self.shade_label.is_empty())
            || self.bands.iter().any(|b| !b.2.is_empty());
        if !labelled {
            return Ok(());
        }
        chart
            .configure_series_labels()
            .position(self.legend.clone())
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK.mix(0.6))
            .label_font((FONT, 14))
            .draw()?;
        Ok(())
    }

    pub(super) fn draw_polar_grid(
        &self,
        chart: &mut Context<'_, '_>,
        r_max: f64,
        step: f64,
    ) -> DrawResult {
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

/// The label of the tick at $x = \log_{10}$ of a quantity: `10ᵏ` with the exponent in
/// superscript digits at a whole decade $k$, empty between decades.
pub(super) fn decade_label(x: f64) -> String {
    let k = x.round();
    if (x - k).abs() > 1e-9 {
        return String::new();
    }
    const SUPERSCRIPT: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::from("10");
    if k < 0.0 {
        s.push('⁻');
    }
    for digit in format!("{}", k.abs() as i64).chars() {
        s.push(SUPERSCRIPT[digit.to_digit(10).unwrap_or(0) as usize]);
    }
    s
}

/// The `<text>` elements of an SVG document, their content trimmed and unescaped (`&amp;`,
/// `&lt;`, `&gt;`, `&quot;`, `&#39;`), in document order.
#[cfg(test)]
pub(crate) fn svg_texts(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(k) = rest.find("<text") {
        rest = &rest[k..];
        let Some(open) = rest.find('>') else { break };
        let Some(close) = rest.find("</text>") else { break };
        let inner = rest[open + 1..close].trim();
        out.push(
            inner
                .replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&quot;", "\"")
                .replace("&#39;", "'")
                .replace("&amp;", "&"),
        );
        rest = &rest[close + 7..];
    }
    out
}

/// A stable speed range for a legend: `a < v < b m/s`, or `v > a m/s` without an upper end.
pub(super) fn speed_range(a: f64, b: f64) -> String {
    if b.is_finite() {
        format!("{a:.3} < v < {b:.3} m/s")
    } else {
        format!("v > {a:.3} m/s")
    }
}

pub(super) fn nice_step(r_max: f64) -> f64 {
    let raw = r_max / 6.0;
    let p = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0].iter().map(|m| m * p).find(|s| *s >= raw).unwrap_or(raw)
}

pub(super) fn trim(x: f64) -> String {
    let s = format!("{x:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

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
    fn a_log_axis_is_labelled_by_decades() {
        assert_eq!(
            [-2.0, -1.0, 0.0, 1.0, 12.0, 0.5].map(decade_label),
            ["10⁻²", "10⁻¹", "10⁰", "10¹", "10¹²", ""]
        );
        let mut c = Chart::new("t", "ω (rad/s)", "y", -1.0..2.0, 0.0..1.0);
        c.log_x = true;
        c.add(Curve::new("a", vec![(-1.0, 0.0), (2.0, 1.0)], color(0), Stroke::Solid));
        let texts = svg_texts(&c.render().unwrap());
        for label in ["10⁻¹", "10⁰", "10¹", "10²"] {
            assert!(texts.iter().any(|t| t == label), "no tick `{label}` in {texts:?}");
        }
        assert!(!texts.iter().any(|t| t.contains("log10")), "{texts:?}");
    }
}
