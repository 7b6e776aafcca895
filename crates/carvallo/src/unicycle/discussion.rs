//! The unicycle's diagrams (memoir n° 32 and n° 41, figures 7 and 9) as data series, evaluated
//! from the generated evaluators of `generated/unicycle.ir` (scene
//! [`crate::unicycle::all_scene`]), for the memoir's example $h/R = 2.5$
//! ([`H_OVER_R`]), $B - C = \mu h^2$, $L = 0$, no wheel inertia.
//!
//! Units: as in n° 12 and n° 32, the rates $s$ and $n$ are in the unit $\sqrt{g/R}$.
//!
//! * Figure 7 (n° 32, *construction du diagramme de la discussion*) is a polar diagram: the
//!   polar angle is the lean $\theta$, measured from the vertical axis Oz, and the radius is the
//!   rolling rate $s$. It carries the curve (ℰ) of the smallest $s$ on (E) for each $\theta$
//!   (point $n_0$, $s_0$), the curves $n = $ const of
//!   $(E)\; \tfrac{h}{R} n^2 \sin\theta + s n + \tan\theta = 0$, the walking/pivoting separation
//!   $(N)\; s^2 = \tan\theta / (1 - \tfrac{h}{R}\sin\theta)$ with its asymptote
//!   $\theta = \arcsin(R/h) = 23{,}6°$, the branch $\theta < 16°$ of the stability limit (S)
//!   of n° 41, and the two circles that bound the practical diagram, $s = 1$ (stability) and
//!   $s = 2{,}58$ (20 km/h with $R = 0{,}5$ m).
//! * Figure 9 (n° 41) plots the first member
//!   $\frac{1}{\cos\theta} - \frac{h}{R}\sin^2\theta\cos\theta - \sqrt{h/R}\,\sin 2\theta$
//!   of the reality condition of the trinomial $S(n^2)$ against $\theta$; the memoir reads its
//!   zeros as $16{,}0°$ and $62{,}7°$ (they are $16{,}32°$ and $62{,}82°$). Here it is
//!   $-b - 2\sqrt{ac}$ for the coefficients of the generated trinomial (`trinomial_n41`), so it
//!   is the derived curve, not the memoir's formula.

use std::collections::BTreeMap;

use crate::hoop::discussion::Series;
use crate::unicycle::all_scene as scene;

/// Coordinates of the polar series of figure 7: the lean in degrees and the rate $s$.
pub const POLAR: &str = "theta (degrees), s";

/// Coordinates of figure 9: the lean in degrees and the first member (dimensionless).
pub const FIRST_MEMBER: &str = "theta (degrees), first member";

/// The speed limit of n° 32: 20 km/h on a wheel of radius 0.5 m, $s\,R = 5{,}56$ m/s, in the
/// unit $\sqrt{g/R}$ with $g = 9{,}81$ m/s² (the memoir prints 2,58).
pub fn speed_limit() -> f64 {
    let (r, g): (f64, f64) = (0.5, 9.81);
    (20.0 / 3.6) / r / (g / r).sqrt()
}

/// The asymptote of (N) in degrees, $\arcsin(R/h)$ (the memoir prints 23°,6).
pub fn asymptote_deg() -> f64 {
    (1.0 / H_OVER_R).asin().to_degrees()
}

fn degrees(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> {
    (0..n).map(move |k| lo + (hi - lo) * k as f64 / (n - 1) as f64)
}

/// s on the separation curve (N) at θ: the positive root of E(θ, s, −s) = 0 (even in s), from
/// the generated `equilibrium_n32`; `None` beyond the asymptote.
pub fn curve_n_s(theta_deg: f64) -> Option<f64> {
    let e = |s: f64| out(&n32(theta_deg, s, -s), "equilibrium_n32");
    let (e0, e1) = (e(0.0), e(1.0));
    let s2 = -e0 / (e1 - e0);
    (s2.is_finite() && s2 >= 0.0).then(|| s2.sqrt())
}

/// The two points of the stability limit (S) at θ (n° 41): for each positive root $m$ of the
/// generated trinomial $S(n^2)$, $n = -\sqrt m$ and $s$ on (E). `None` where the roots are
/// not real (16° < θ < 62,7°).
pub fn stability_limit(theta_deg: f64) -> Option<[(f64, f64); 2]> {
    let (a, b, c) = trinomial(theta_deg);
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 || a == 0.0 {
        return None;
    }
    let roots = [(-b - disc.sqrt()) / (2.0 * a), (-b + disc.sqrt()) / (2.0 * a)];
    if roots.iter().any(|m| *m <= 0.0) {
        return None;
    }
    Some(roots.map(|m| {
        let n = -m.sqrt();
        (n, s_on_e(theta_deg, n))
    }))
}

/// The two zeros of the first member of n° 41 in degrees (the memoir's 16°,0 and 62°,7), by
/// bisection.
pub fn first_member_roots() -> (f64, f64) {
    (bisect(first_member_41, 5.0, 30.0), bisect(first_member_41, 50.0, 70.0))
}

/// Figure 7 (n° 32): polar series (θ in degrees, s) of (ℰ), the curves n = −0,1, −0,3, −0,5,
/// −1, −1,5, −2 on (E), the curve (N) up to the speed limit, the two branches of (S) for
/// θ below the first root of n° 41, and the circles s = 1 and s = 2,51 (the
/// memoir's 2,58 is a slip, see the report).
pub fn figure_7() -> Vec<Series> {
    let limit = speed_limit();
    let e: Vec<(f64, f64)> = degrees(0.5, 55.0, 56).map(|t| (t, minimum_on_e(t).1)).collect();
    let mut out =
        vec![Series { name: "(ℰ) smallest s on (E), n = n0".into(), coords: POLAR, points: e }];
    for n in [-0.1, -0.3, -0.5, -1.0, -1.5, -2.0] {
        let points = degrees(0.5, 55.0, 110)
            .map(|t| (t, s_on_e(t, n)))
            .filter(|(_, s)| s.is_finite() && *s >= 0.0 && *s <= limit * 1.15)
            .collect();
        out.push(Series { name: format!("n = {n}"), coords: POLAR, points });
    }
    let n_points = degrees(0.0, asymptote_deg() - 1e-6, 200)
        .filter_map(|t| curve_n_s(t).map(|s| (t, s)))
        .filter(|(_, s)| *s <= limit * 1.15)
        .collect();
    out.push(Series {
        name: "(N) separation walking / pivoting".into(),
        coords: POLAR,
        points: n_points,
    });
    let (root, _) = first_member_roots();
    let mut s_a = Vec::new();
    let mut s_b = Vec::new();
    for t in degrees(0.5, root, 60) {
        if let Some([(_, sa), (_, sb)]) = stability_limit(t) {
            s_a.push((t, sa));
            s_b.push((t, sb));
        }
    }
    // One closed branch: out along one root, back along the other.
    s_b.reverse();
    s_a.extend(s_b);
    out.push(Series { name: "(S) stability limit, θ < 16°".into(), coords: POLAR, points: s_a });
    for (name, r) in [
        ("s = 1 (practical stability)".to_string(), 1.0),
        (format!("s = {limit:.2} (20 km/h; memoir 2.58)"), limit),
    ] {
        let points = degrees(0.0, 90.0, 91).map(|t| (t, r)).collect();
        out.push(Series { name, coords: POLAR, points });
    }
    out
}

/// The table of n° 41 as the memoir prints it: θ in degrees and the first member.
pub const MEMOIR_TABLE_41: [(f64, f64); 8] = [
    (0.0, 1.000),
    (10.0, 0.403),
    (20.0, -0.225),
    (30.0, -0.757),
    (40.0, -1.054),
    (50.0, -0.874),
    (60.0, -0.308),
    (70.0, 1.149),
];

/// Figure 9 (n° 41): the derived first member against θ from 0° to 72°, and the memoir's
/// table [`MEMOIR_TABLE_41`] as a second series.
pub fn figure_9() -> Vec<Series> {
    let derived = degrees(0.0, 72.0, 145).map(|t| (t, first_member_41(t))).collect();
    vec![
        Series { name: "first member, derived".into(), coords: FIRST_MEMBER, points: derived },
        Series {
            name: "table of n° 41 (memoir)".into(),
            coords: FIRST_MEMBER,
            points: MEMOIR_TABLE_41.to_vec(),
        },
    ]
}

// The normalised forms of n° 32–41, evaluated from the generated program: shared by the
// diagrams above and by the concordance report (`carvallo_report::unicycle`).

/// $h/R$ of the diagram of n° 32 and of n° 39–41.
pub const H_OVER_R: f64 = 2.5;

/// A point of the unicycle model: a value for parameters and inputs by name (missing names
/// evaluate as NaN).
pub type Point = BTreeMap<&'static str, f64>;

/// Every output of `generated/unicycle.ir` at `point`, by output name.
pub fn eval(point: &Point) -> BTreeMap<&'static str, f64> {
    let names: Vec<&str> = scene::PARAMS.iter().chain(scene::INPUTS.iter()).copied().collect();
    let args = std::array::from_fn(|i| point.get(names[i]).copied().unwrap_or(f64::NAN));
    scene::OUTPUTS.iter().copied().zip(scene::eval_array(&args)).collect()
}

/// The output `name` of `generated/unicycle.ir` at `point`.
///
/// # Panics
/// When the program has no output `name` (a fixed name of this crate, so a bug).
pub fn out(point: &Point, name: &str) -> f64 {
    eval(point)[name]
}

pub use crate::numerics::poly::{bisect_unchecked as bisect, minimise};

/// A normalised point of n° 32–41: R = g = mu = 1, z = h/R, rates in units of sqrt(g/R).
pub fn n32(theta_deg: f64, s: f64, n: f64) -> Point {
    BTreeMap::from([
        ("R", 1.0),
        ("g", 1.0),
        ("mu", 1.0),
        ("z", H_OVER_R),
        ("theta", theta_deg.to_radians()),
        ("s", s),
        ("n", n),
    ])
}

/// s on (E) of n° 32 for given θ and n, from the generated form (linear in s).
pub fn s_on_e(theta_deg: f64, n: f64) -> f64 {
    let e0 = out(&n32(theta_deg, 0.0, n), "equilibrium_n32");
    let e1 = out(&n32(theta_deg, 1.0, n), "equilibrium_n32");
    -e0 / (e1 - e0)
}

/// (n0, s0): the smallest s on (E) at θ and the n < 0 where it is reached (n° 32).
pub fn minimum_on_e(theta_deg: f64) -> (f64, f64) {
    let n0 = minimise(|n| s_on_e(theta_deg, n), -5.0, -1e-3);
    (n0, s_on_e(theta_deg, n0))
}

/// Coefficients (a, b, c) of the generated trinomial S(n^2) = a m^2 + b m + c, m = n^2.
pub fn trinomial(theta_deg: f64) -> (f64, f64, f64) {
    let t = |m: f64| out(&n32(theta_deg, 0.0, m.sqrt()), "trinomial_n41");
    let (t0, t1, t2) = (t(0.0), t(1.0), t(2.0));
    let a = (t2 - 2.0 * t1 + t0) / 2.0;
    (a, t1 - t0 - a, t0)
}

/// The first member of n° 41, $-b - 2\sqrt{ac}$ for the trinomial's (a, b, c).
pub fn first_member_41(theta_deg: f64) -> f64 {
    let (a, b, c) = trinomial(theta_deg);
    -b - 2.0 * (a * c).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn figure_7_matches_the_memoir_landmarks() {
        // n° 32: the asymptote of (N) at 23°,6 and the speed limit 2,58 (printed to 3 digits).
        assert!((asymptote_deg() - 23.578).abs() < 1e-3, "{}", asymptote_deg());
        // 20 km/h on R = 0.5 m in the unit sqrt(g R): (50/9)/sqrt(4.905) = 2.508465, by hand
        // to 7 digits (the memoir prints 2,58; the closed form has only a few ulps of rounding).
        assert!((speed_limit() - 2.508_465).abs() < 1e-6, "{}", speed_limit());
        // (N) touches (ℰ) at I (θ = 11°,5, s0 = 0,639): there s on (N) equals s0.
        let t = (1.0 / H_OVER_R / 2.0).asin().to_degrees();
        let (_, s0) = minimum_on_e(t);
        let sn = curve_n_s(t).unwrap();
        assert!((sn - s0).abs() < 1e-6 * s0, "{sn} vs {s0}");
        assert!((s0 - 0.639).abs() < 5e-4, "{s0}");
        // Each limit point of (S) makes the generated stability condition vanish.
        let [(na, sa), (nb, sb)] = stability_limit(10.0).unwrap();
        for (n, s) in [(na, sa), (nb, sb)] {
            let v = out(&n32(10.0, s, n), "stability_n40");
            assert!(v.abs() < 1e-9 * (1.0 + s * s), "S = {v} at n = {n}, s = {s}");
        }
        assert!(stability_limit(30.0).is_none());
        let series = figure_7();
        assert_eq!(series.len(), 11);
        assert!(series.iter().all(|s| s.points.len() >= 10), "a series is almost empty");
    }

    #[test]
    fn figure_9_zeros_are_those_of_the_printed_closed_form() {
        // Independent path: the memoir's printed closed form, bisected directly. (Its zeros
        // are 16.32° and 62.82°; the memoir's 16°,0 and 62°,7 are slide-rule values.)
        let k = H_OVER_R;
        let printed = |t: f64| {
            let t = t.to_radians();
            1.0 / t.cos() - k * t.sin().powi(2) * t.cos() - k.sqrt() * (2.0 * t).sin()
        };
        let (r1, r2) = first_member_roots();
        for (r, lo, hi) in [(r1, 5.0, 30.0), (r2, 50.0, 70.0)] {
            let exact = bisect(printed, lo, hi);
            assert!((r - exact).abs() < 1e-9, "{r} vs {exact}");
        }
        assert!((r1 - 16.3157).abs() < 1e-4 && (r2 - 62.8156).abs() < 1e-4, "{r1} {r2}");
        let derived = &figure_9()[0].points;
        assert!(derived.iter().all(|(_, y)| y.is_finite()));
    }
}
