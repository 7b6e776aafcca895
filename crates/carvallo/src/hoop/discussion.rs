//! The discussion of the hoop's steady states (memoir n° 13–19), evaluated from
//! `generated/hoop_discussion.ir` (derived by `codegen/src/derive/hoop/discussion.rs` from the
//! normalised (E), (S), (D) of n° 12).
//!
//! Units: as in n° 12, the rates $s$ and $n$ are in the unit $\sqrt{g/R}$ (that is $g/R = 1$),
//! except in n° 19 ([`stick_theta_n`], [`stick_linearised_rk4`]) which keeps physical units.
//! The plane of figure 3 has the coordinates $x = \cos\theta$, $y = s^2$; figures 4 and 4 bis
//! are polar diagrams with the polar angle $\theta$ and the radius $s$.
//!
//! Contents:
//! * [`special_points`]: the points A, B, D, F, the tangents at A and D, the vertical tangent of
//!   the curve (S) (root of the quartic $F(t) = (2t - 1)^2(7t^2 - 4t - 2)$ in closed form), the
//!   contact point I of (N) with (ℰ) and the point H where (N) meets (S);
//! * [`carvallo_root`]: Carvallo's own numerical method of n° 14 (Horner's shift
//!   $t = 1 + u$, then the root-squaring tableau on $v = 1/u$), run on his equation and set
//!   beside the exact root;
//! * [`figure_3`], [`figure_4`], [`figure_4_bis`]: data series of the figures' curves;
//! * [`stick_theta_n`], [`stick_linearised_rk4`]: the stick (*baguette*) equations of n° 19.

use std::collections::BTreeMap;

use crate::ir::Program;

crate::scene! {
    /// Every output of `generated/hoop_discussion.ir`, with every parameter and input free.
    pub(crate) mod discussion_scene {
        model: hoop_discussion,
    }
}

/// The IR text of the model, for high-precision cross-checks.
pub const HOOP_DISCUSSION_IR: &str = crate::artifacts::HOOP_DISCUSSION.ir;

/// Evaluates every output of the model at the named parameter and input values (missing names
/// are 0); returns the outputs by name. Outputs that do not depend on a given argument ignore
/// it; an output undefined at the point is NaN or infinite.
pub fn eval(args: &[(&str, f64)]) -> BTreeMap<&'static str, f64> {
    use discussion_scene as scene;
    let names: Vec<&str> = scene::PARAMS.iter().chain(scene::INPUTS.iter()).copied().collect();
    let values =
        std::array::from_fn(|i| args.iter().find(|(k, _)| *k == names[i]).map_or(0.0, |(_, v)| *v));
    scene::OUTPUTS.iter().copied().zip(scene::eval_array(&values)).collect()
}

/// One output at the given arguments (see [`eval`]); NaN when the model has no such output.
pub fn output(name: &str, args: &[(&str, f64)]) -> f64 {
    eval(args).get(name).copied().unwrap_or(f64::NAN)
}

/// The outputs that do not depend on any input (closed forms), evaluated in high precision
/// (`bits` bits) with `carvallo_ir::hp` and rounded to `f64`; `None` if the IR does not parse.
pub fn constants_hp(names: &[&str], bits: usize) -> Option<Vec<f64>> {
    let program = Program::parse(HOOP_DISCUSSION_IR).ok()?.select_outputs(names).ok()?;
    let params = vec![1.0; program.params.len()];
    let inputs = vec![0.0; program.inputs.len()];
    crate::ir::hp::eval_f64(&program, &params, &inputs, bits).ok()
}

/// The special points of n° 13–17 bis, from the generated closed forms and evaluators.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpecialPoints {
    /// A: (x, y) = (1, 0), start of (ℰ) and (S).
    pub a: (f64, f64),
    /// B: maximum of y on (S1), (x, y).
    pub b: (f64, f64),
    /// D: (1, 1/4), end of (S) on the axis θ = 0.
    pub d: (f64, f64),
    /// F: (ℰ) ∩ (S1), (x, y).
    pub f: (f64, f64),
    /// Slope dy/dx of (S) at A and at D.
    pub slopes_a_d: (f64, f64),
    /// Vertical tangent of (S): t = x², x, θ (degrees), y, s.
    pub vertical: VerticalTangent,
    /// I: contact of (N) and (ℰ): (θ in degrees, s).
    pub i: (f64, f64),
    /// H: (N) ∩ (S): (sin θ, θ in degrees, s).
    pub h: (f64, f64, f64),
}

/// The vertical tangent of the curve (S) (n° 14).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VerticalTangent {
    /// The root $t = x^2 = (2 + 3\sqrt2)/7$ of $F(t)$.
    pub t: f64,
    /// $x = \cos\theta = \sqrt t$.
    pub x: f64,
    /// θ in degrees.
    pub theta_deg: f64,
    /// The double root $y = s^2$ of (S) at that x.
    pub y: f64,
    /// $s = \sqrt y$.
    pub s: f64,
    /// The product of the two y roots there, $3(1 + x^2)(1 - x^2)/(16x^2)$ (Carvallo's 0,0430).
    pub y_product: f64,
}

pub use crate::numerics::graeffe::{graeffe_largest, graeffe_step, horner_shift};
pub use crate::numerics::poly::{bisect, poly_eval};

/// Coefficients $(a, b, c)$ of a function quadratic in its argument, read at $0, \pm1$.
fn quadratic(f: impl Fn(f64) -> f64) -> (f64, f64, f64) {
    let (c, plus, minus) = (f(0.0), f(1.0), f(-1.0));
    (0.5 * (plus + minus) - c, 0.5 * (plus - minus), c)
}

/// The special points, computed now from the generated closed forms (B, F, the vertical
/// tangent's t, the slopes) and by bisection on generated evaluators (H: root in (0, 1) of the
/// generated cubic `h_cubic` in sin θ; I: from the derived double root sin θ = 2/3 checked at
/// regeneration, s from the generated (N)).
pub fn special_points() -> SpecialPoints {
    let c = eval(&[]);
    let t = c["vertical_t"];
    let x = t.sqrt();
    let (a2, _, c2) = quadratic(|y| output("curve_s", &[("x", x), ("y", y)]));
    let sin_h = bisect(|w| output("h_cubic", &[("theta", w.asin())]), 0.0, 1.0).unwrap_or(f64::NAN);
    let theta_h = sin_h.asin();
    let theta_i = (2.0f64 / 3.0).asin();
    SpecialPoints {
        a: (1.0, 0.0),
        b: (c["point_b_x"], c["point_b_y"]),
        d: (1.0, 0.25),
        f: (c["point_f_x"], c["point_f_y"]),
        slopes_a_d: (c["tangent_a_slope"], c["tangent_d_slope"]),
        vertical: VerticalTangent {
            t,
            x,
            theta_deg: x.acos().to_degrees(),
            y: output("vertical_y", &[("x", x)]),
            s: output("vertical_y", &[("x", x)]).sqrt(),
            y_product: c2 / a2,
        },
        i: (theta_i.to_degrees(), output("curve_n_s2", &[("theta", theta_i)]).sqrt()),
        h: (sin_h, theta_h.to_degrees(), output("h_s2", &[("theta", theta_h)]).sqrt()),
    }
}

/// Carvallo's computation of n° 14 and its comparison with the exact root.
#[derive(Clone, Debug, PartialEq)]
pub struct CarvalloRoot {
    /// The equation in u after the Horner shift (highest degree first): 28, 68, 51, 14, 1.
    pub shifted: Vec<f64>,
    /// The rows of the Horner tableau.
    pub horner_rows: Vec<Vec<f64>>,
    /// The root-squaring rows on the equation in $v = 1/u$ (1, 14, 51, 68, 28), after 0, 1
    /// and 2 squarings (Carvallo stops after two).
    pub graeffe_rows: Vec<Vec<f64>>,
    /// $v^4$ read off the last row (Carvallo: 7332).
    pub v4: f64,
    /// $\log_{10} v^4$ (Carvallo: 3,86522).
    pub log_v4: f64,
    /// $u = -1/v$ (Carvallo: −0,10807).
    pub u: f64,
    /// $t = 1 + u$ (Carvallo: 0,89193).
    pub t: f64,
    /// The residual of the equation in u at Carvallo's printed $u = -0{,}10807$ (he prints
    /// +0,0004).
    pub residual_at_printed_u: f64,
    /// The exact root $u = (3\sqrt2 - 5)/7$ from the generated closed form, polished by Newton
    /// in `f64`.
    pub exact_u: f64,
    /// The same root from the closed form evaluated at 256 bits by `carvallo_ir::hp`.
    pub exact_u_hp: f64,
    /// The relative error of the method's u (two squarings) against the exact u.
    pub method_rel_error: f64,
    /// The relative error after six squarings (the method converged).
    pub converged_rel_error: f64,
}

/// Runs Carvallo's method of n° 14 on his quartic $F(t) = 28t^4 - 44t^3 + 15t^2 + 4t - 2$
/// (the generated `quartic_f`, coefficients read off the evaluator) and compares it with the
/// exact root.
pub fn carvallo_root() -> CarvalloRoot {
    carvallo_root_of(|t| output("quartic_f", &[("t", t)]), output("vertical_t", &[]))
}

/// [`carvallo_root`] run on the quartic `f` (read at $t = 0, \dots, 4$ and its coefficients
/// rounded to integers) with the exact root `exact_t` of the vertical tangent: the route of
/// [`carvallo_root`] with another evaluator of F(t) (the report's, which reads a perturbed
/// program while one is active).
pub fn carvallo_root_of(f: impl Fn(f64) -> f64, exact_t: f64) -> CarvalloRoot {
    // Coefficients of the generated F(t), read by finite interpolation at t = 0..4 (exact for
    // a quartic with integer values).
    let coeffs = quartic_coefficients(f);
    let (shifted, horner_rows) = horner_shift(&coeffs, 1.0);
    let reversed: Vec<f64> = shifted.iter().rev().copied().collect();
    let (graeffe_rows, v_abs) = graeffe_largest(&reversed, 2);
    let v4 = graeffe_rows[2][1] / graeffe_rows[2][0];
    let u = -1.0 / v_abs;
    let (_, v_conv) = graeffe_largest(&reversed, 6);
    let mut exact_u = exact_t - 1.0;
    for _ in 0..3 {
        let h = 1e-7;
        let d = (poly_eval(&shifted, exact_u + h) - poly_eval(&shifted, exact_u - h)) / (2.0 * h);
        if d != 0.0 {
            exact_u -= poly_eval(&shifted, exact_u) / d;
        }
    }
    let exact_u_hp = constants_hp(&["vertical_t"], 256).map_or(f64::NAN, |v| v[0] - 1.0);
    CarvalloRoot {
        residual_at_printed_u: poly_eval(&shifted, -0.10807),
        method_rel_error: ((u - exact_u) / exact_u).abs(),
        converged_rel_error: ((-1.0 / v_conv - exact_u) / exact_u).abs(),
        shifted,
        horner_rows,
        v4,
        log_v4: v4.log10(),
        u,
        t: 1.0 + u,
        exact_u,
        exact_u_hp,
        graeffe_rows,
    }
}

/// Coefficients (highest first) of a quartic from its values at 0, 1, 2, 3, 4 (Newton's
/// forward differences).
fn quartic_coefficients(f: impl Fn(f64) -> f64) -> Vec<f64> {
    let vals: Vec<f64> = (0..5).map(|k| f(k as f64)).collect();
    // Solve the Vandermonde system exactly enough by Lagrange interpolation in f64.
    let mut coeffs = [0.0; 5];
    for (i, vi) in vals.iter().enumerate() {
        // basis polynomial prod_{j != i} (t - j)/(i - j), expanded (lowest first)
        let mut basis = vec![1.0];
        let mut denom = 1.0;
        for j in 0..5 {
            if j == i {
                continue;
            }
            let mut next = vec![0.0; basis.len() + 1];
            for (k, b) in basis.iter().enumerate() {
                next[k + 1] += b;
                next[k] -= b * j as f64;
            }
            basis = next;
            denom *= i as f64 - j as f64;
        }
        for (k, b) in basis.iter().enumerate() {
            coeffs[k] += vi * b / denom;
        }
    }
    coeffs.iter().rev().map(|c| c.round()).collect()
}

/// A named data series: points in the coordinates stated by `coords`.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// The curve's name as in the memoir.
    pub name: String,
    /// The coordinates: `"x = cos(theta), y = s^2"` (figure 3) or `"theta (degrees), s"`
    /// (polar figures 4 and 4 bis, rates in units of sqrt(g/R)).
    pub coords: &'static str,
    /// The points, in order along the curve.
    pub points: Vec<(f64, f64)>,
}

const XY: &str = "x = cos(theta), y = s^2";
const POLAR: &str = "theta (degrees), s";

fn linspace(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> {
    (0..n).map(move |k| lo + (hi - lo) * k as f64 / (n - 1) as f64)
}

/// The two y roots of (S) at x (smaller first), from the generated `curve_s` (a quadratic in
/// y); `None` where they are not real.
pub fn curve_s_roots(x: f64) -> Option<(f64, f64)> {
    let (a, b, c) = quadratic(|y| output("curve_s", &[("x", x), ("y", y)]));
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 || a == 0.0 {
        return None;
    }
    let r = disc.sqrt();
    let (y1, y2) = ((-b - r) / (2.0 * a), (-b + r) / (2.0 * a));
    Some((y1.min(y2), y1.max(y2)))
}

/// Figure 3 (n° 13–14), plane $x = \cos\theta$, $y = s^2$: the curve (ℰ) from x = 0.5 to A,
/// the curve (S1) from x = 0.5 to 1, and the curve (S) from A to D through its vertical
/// tangent (lower branch then upper branch), 41 points each.
pub fn figure_3() -> Vec<Series> {
    let sp = special_points();
    let xv = sp.vertical.x;
    let e: Vec<(f64, f64)> =
        linspace(0.5, 1.0, 41).map(|x| (x, output("reality_y", &[("x", x)]))).collect();
    let s1: Vec<(f64, f64)> =
        linspace(0.5, 1.0, 41).map(|x| (x, output("curve_s1_y", &[("x", x)]))).collect();
    let mut s: Vec<(f64, f64)> = Vec::new();
    // Parametrise by x from 1 down to the vertical tangent (lower branch), then back up.
    let xs: Vec<f64> = linspace(0.0, 1.0, 21).map(|k| xv + (1.0 - xv) * (1.0 - k * k)).collect();
    for &x in &xs {
        if let Some((lo, _)) = curve_s_roots(x) {
            s.push((x, lo));
        }
    }
    for &x in xs.iter().rev() {
        if let Some((_, hi)) = curve_s_roots(x) {
            s.push((x, hi));
        }
    }
    vec![
        Series { name: "(ℰ) reality of the roots of E".into(), coords: XY, points: e },
        Series { name: "(S1) reality of the roots of S".into(), coords: XY, points: s1 },
        Series { name: "(S) stability limit".into(), coords: XY, points: s },
    ]
}

/// Polar form of (ℰ) and (S) used by figures 4 and 4 bis: (θ in degrees, s).
fn polar_e_and_s() -> [Series; 2] {
    let e: Vec<(f64, f64)> = linspace(0.0, 60.0, 41)
        .map(|deg| (deg, output("reality_s2", &[("theta", deg.to_radians())]).sqrt()))
        .collect();
    let xy = figure_3().remove(2);
    let s = xy.points.iter().map(|&(x, y)| (x.acos().to_degrees(), y.max(0.0).sqrt())).collect();
    [
        Series { name: "(ℰ) in polar coordinates".into(), coords: POLAR, points: e },
        Series { name: "(S) in polar coordinates".into(), coords: POLAR, points: s },
    ]
}

/// The curve n = const of (E′) (root n2 if n > n0, n1 if n < n0), θ from 1° to 60°.
fn n_curve(n: f64) -> Series {
    let points = linspace(1.0, 60.0, 60)
        .map(|deg| (deg, output("s_of_n", &[("theta", deg.to_radians()), ("n", n)])))
        .filter(|(_, s)| s.is_finite() && *s >= 0.0)
        .collect();
    Series { name: format!("n = {n}"), coords: POLAR, points }
}

/// The curve D = d from (D″), where $s^2 \ge 0$, θ from 1° to 80°.
fn d_curve(d: f64) -> Series {
    let points = linspace(1.0, 80.0, 80)
        .filter_map(|deg| {
            let s2 = output("s2_of_d", &[("theta", deg.to_radians()), ("d", d)]);
            (s2.is_finite() && s2 >= 0.0).then(|| (deg, s2.sqrt()))
        })
        .collect();
    Series { name: format!("D = {d}"), coords: POLAR, points }
}

/// Figure 4 (n° 15–16), polar (θ, s): curves n = −0,1, −0,3, −0,5, −1, −2 (from (E′)), the
/// curves D = ±1/2 (from (D″)), (ℰ) and (S).
pub fn figure_4() -> Vec<Series> {
    let mut out: Vec<Series> = [-0.1, -0.3, -0.5, -1.0, -2.0].into_iter().map(n_curve).collect();
    out.push(d_curve(0.5));
    out.push(d_curve(-0.5));
    out.extend(polar_e_and_s());
    out
}

/// Figure 4 bis (n° 17), polar (θ, s): (ℰ), (S), the curve (N) and the curves n2 = −0,1,
/// −0,3, −0,5.
pub fn figure_4_bis() -> Vec<Series> {
    let mut out: Vec<Series> = polar_e_and_s().into();
    let n: Vec<(f64, f64)> = linspace(1.0, 60.0, 60)
        .map(|deg| (deg, output("curve_n_s2", &[("theta", deg.to_radians())]).sqrt()))
        .collect();
    out.push(Series { name: "(N) E(-s) = 0".into(), coords: POLAR, points: n });
    out.extend([-0.1, -0.3, -0.5].into_iter().map(n_curve));
    out
}

/// n° 19, formulas (6) and (7): $(\theta(t), n(t))$ of the linearised stick equations from
/// rest upright, physical units ($R$ m, $g$ m/s², $s$ 1/s, stick moments $\mathfrak M$ in
/// 1/s², $\mathfrak M_1$ in 1/s², time in s); NaN unless $4s^2 > g/R$.
pub fn stick_theta_n(r: f64, g: f64, s: f64, m: f64, m1: f64, time: f64) -> (f64, f64) {
    let v = eval(&[("R", r), ("g", g), ("s", s), ("M", m), ("M1", m1), ("time", time)]);
    (v["stick_theta"], v["stick_n"])
}

/// Integrates n° 19's equations (2) with the stick moments held constant, from rest upright
/// ($\theta = p = n = 0$) with s held constant (as the memoir does), by RK4 with `steps` steps
/// up to `time`: `linearised` uses the generated linearised equations (`stick_dp`,
/// `stick_dn`), otherwise the full ones (`stick_full_dp`, `stick_full_dn`); `moments` are
/// $(M, M_1)$. Returns $(\theta, n)$ at `time`.
pub fn stick_linearised_rk4(
    r: f64,
    g: f64,
    s: f64,
    moments: (f64, f64),
    time: f64,
    steps: usize,
    linearised: bool,
) -> (f64, f64) {
    let (dp, dn) =
        if linearised { ("stick_dp", "stick_dn") } else { ("stick_full_dp", "stick_full_dn") };
    let (m, m1) = moments;
    let rhs = |x: [f64; 3]| {
        let v = eval(&[
            ("R", r),
            ("g", g),
            ("s", s),
            ("M", m),
            ("M1", m1),
            ("theta", x[0]),
            ("p", x[1]),
            ("n", x[2]),
        ]);
        [x[1], v[dp], v[dn]]
    };
    let h = time / steps as f64;
    let mut x = [0.0; 3];
    for _ in 0..steps {
        x = crate::numerics::ode::rk4_step(rhs, x, h);
    }
    (x[0], x[2])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn horner_shift_reproduces_carvallos_tableau() {
        let (u, rows) = horner_shift(&[28.0, -44.0, 15.0, 4.0, -2.0], 1.0);
        assert_eq!(u, vec![28.0, 68.0, 51.0, 14.0, 1.0]);
        assert_eq!(rows[0], vec![28.0, -16.0, -1.0, 3.0, 1.0]);
        assert_eq!(rows[1], vec![28.0, 12.0, 11.0, 14.0]);
    }

    #[test]
    fn graeffe_rows_match_the_memoir() {
        let (rows, _) = graeffe_largest(&[1.0, 14.0, 51.0, 68.0, 28.0], 2);
        // Carvallo's slide rule gives 2600 for 51^2 = 2601, hence 752 and 7332 in his rows.
        assert_eq!(rows[1], vec![1.0, 94.0, 753.0, 1768.0, 784.0]);
        assert_eq!(rows[2][1], 7330.0);
    }

    #[test]
    fn special_points_are_the_closed_forms() {
        let sp = special_points();
        let tol = 1e-12;
        assert!((sp.vertical.t - (2.0 + 3.0 * 2f64.sqrt()) / 7.0).abs() < tol);
        assert!((sp.f.0 - ((1.0 + 33f64.sqrt()) / 8.0).sqrt()).abs() < tol);
        assert!(
            (sp.b.0 - 0.5f64.sqrt()).abs() < tol && (sp.b.1 - 3.0 * 2f64.sqrt() / 16.0).abs() < tol
        );
        assert!((sp.slopes_a_d.0 + 3.0).abs() < tol && sp.slopes_a_d.1.abs() < tol);
        // H solves the cubic 3w^3 + 4w^2 - 14w + 4 = 0.
        let w = sp.h.0;
        assert!((3.0 * w.powi(3) + 4.0 * w * w - 14.0 * w + 4.0).abs() < 1e-12);
    }

    #[test]
    fn figure_3_series_lie_on_the_printed_curves() {
        let figs = figure_3();
        assert_eq!(figs.len(), 3);
        for &(x, y) in &figs[0].points {
            assert!((x * x + 2.0 / 3.0 * x * y - 1.0).abs() < 1e-12, "(ℰ) at x = {x}");
        }
        for &(x, y) in &figs[1].points {
            assert!((y - 0.75 * x / (1.0 + 2.0 * x * x)).abs() < 1e-12, "(S1) at x = {x}");
        }
        assert!(figs[2].points.len() >= 30);
        for &(x, y) in &figs[2].points {
            let p = 16.0 * x * x * (1.0 + x * x) * y * y
                + 8.0 * x * (5.0 * x.powi(4) - 5.0 * x * x - 1.0) * y
                + 3.0 * (1.0 + x * x).powi(2) * (1.0 - x * x);
            // Near the vertical tangent the roots are ill-conditioned: 1e-9 absolute.
            assert!(p.abs() < 1e-9, "(S) at ({x}, {y}): {p}");
        }
    }

    #[test]
    fn polar_series_lie_on_the_printed_curves() {
        let figs = figure_4_bis();
        let n = figs.iter().find(|f| f.name.starts_with("(N)")).expect("curve N");
        for &(deg, s) in &n.points {
            let th = deg.to_radians();
            let s2 = 2.0 * th.sin() / (th.cos() * (4.0 - 3.0 * th.sin()));
            assert!((s * s - s2).abs() < 1e-12 * s2.max(1.0), "(N) at {deg}°");
        }
        let fig4 = figure_4();
        let d = fig4.iter().find(|f| f.name == "D = 0.5").expect("curve D = 1/2");
        assert!(!d.points.is_empty());
        for &(deg, s) in &d.points {
            // The point satisfies D = 1/2 for one root n of (E).
            let th = deg.to_radians();
            let (a, b, c) = (3.0 * th.sin(), 4.0 * s, 2.0 * th.tan());
            let disc = (b * b - 4.0 * a * c).max(0.0).sqrt();
            let skid = |n: f64| -n * n * th.sin() - s * n;
            let best = [(-b - disc) / (2.0 * a), (-b + disc) / (2.0 * a)]
                .map(|n| (skid(n) - 0.5).abs())
                .into_iter()
                .fold(f64::INFINITY, f64::min);
            assert!(best < 1e-9, "D = 1/2 at {deg}°: {best}");
        }
    }

    #[test]
    fn stick_closed_form_matches_the_linearised_integration() {
        let (r, g) = (0.5_f64, 9.81_f64);
        let s = 2.0 * (g / r).sqrt();
        let (th, n) = stick_theta_n(r, g, s, -1.0, 2.0, 0.7);
        let (th_rk, n_rk) = stick_linearised_rk4(r, g, s, (-1.0, 2.0), 0.7, 1000, true);
        // RK4 with h dt ~ 0.01: global error ~1e-8 relative; 1e-6 relative stated.
        assert!((th - th_rk).abs() < 1e-6 * th.abs().max(1e-3));
        assert!((n - n_rk).abs() < 1e-6 * n.abs().max(1e-3));
    }

    #[test]
    fn carvallo_root_agrees_with_the_high_precision_closed_form() {
        let root = carvallo_root();
        assert!((root.exact_u - root.exact_u_hp).abs() < 1e-15);
        assert!((root.exact_u - (3.0 * 2f64.sqrt() - 5.0) / 7.0).abs() < 1e-15);
        assert!(root.method_rel_error > 1e-3 && root.method_rel_error < 1.3e-3);
        assert!(root.converged_rel_error < 1e-12);
    }
}
