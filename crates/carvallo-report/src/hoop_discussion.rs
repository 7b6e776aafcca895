//! The concordance of the hoop discussion (memoir n° 13–19): each printed formula and number of
//! those sections set beside what `generated/hoop_discussion.ir` and
//! [`carvallo::hoop_discussion`] compute when the report runs, with the verdict policy of
//! [`crate::policy`]. The symbolic checks recorded at regeneration
//! (`generated/hoop_discussion.checks.tsv`) are folded in as entries of their own.
//!
//! Formulas are compared at [`POINTS`] seeded points of their domain (x = cos θ in (0.3, 1),
//! y = s² in (0, 1), t in (0, 1.2), θ in (0.05, 1.3) rad, n in (−3, −0.05), d in (−1, 1)).

mod claims;

use std::collections::BTreeMap;

use carvallo::hoop_discussion::{self as hd, carvallo_root_of, special_points};

use crate::checks::{self, parse_checks, Finding};
use crate::entry::{Derived, Entry, Memoir, Verdict};
use crate::perturb::Perturbation;
use crate::policy::{self, number_entry, printed_number, rel_diff};
use crate::sample::Rng;

/// Number of seeded points at which formulas are compared.
pub const POINTS: usize = 64;

const CHECKS_TSV: &str = carvallo::artifacts::HOOP_DISCUSSION.checks;

/// Checks whose expected outcome is `false` (a slip of the memoir), with the reason.
const FINDINGS: &[Finding] = &[Finding::new(
    "s0_table_memoir",
    Verdict::MemoirError,
    "the table of variations of n° 15 prints s0 = tan(th) sqrt(2/(3 cos(th))), the text's s0 = tan(th) sqrt(3 cos(th)/2) is the right one",
)];

/// Deterministic points (SplitMix64 with a fixed seed).
fn points() -> Vec<[(&'static str, f64); 6]> {
    let mut rng = Rng(0x1897_0C0A_4A11_0013);
    let mut next = |lo: f64, hi: f64| rng.uniform(lo, hi);
    (0..POINTS)
        .map(|_| {
            [
                ("x", next(0.3, 1.0)),
                ("y", next(0.0, 1.0)),
                ("t", next(0.0, 1.2)),
                ("theta", next(0.05, 1.3)),
                ("n", next(-3.0, -0.05)),
                ("d", next(-1.0, 1.0)),
            ]
        })
        .collect()
}

/// Every output of the generated program at `args` ([`hd::eval`], missing names 0), the
/// perturbed output replaced by its perturbed value while a perturbation of `hoop_discussion`
/// is active ([`crate::perturb::overlay`]).
fn eval(args: &[(&str, f64)]) -> BTreeMap<&'static str, f64> {
    let mut values = hd::eval(args);
    let get = |name: &str| Some(args.iter().find(|(k, _)| *k == name).map_or(0.0, |(_, v)| *v));
    crate::perturb::overlay("hoop_discussion", get, &mut values);
    values
}

/// Largest relative difference (floor 1e-9) between two outputs over the points.
fn max_rel(derived: &str, memoir: &str) -> f64 {
    points()
        .iter()
        .map(|p| {
            let v = eval(p);
            rel_diff(v[derived], v[memoir])
        })
        .fold(0.0, |a: f64, b| if b.is_nan() { f64::INFINITY } else { a.max(b) })
}

fn formula_entry(
    section: &str,
    quantity: &str,
    printed: &str,
    derived: &str,
    memoir: &str,
    otherwise: Verdict,
    note: &str,
) -> Entry {
    let rel = max_rel(derived, memoir);
    Entry {
        falsification: None,
        section: section.into(),
        quantity: quantity.into(),
        memoir: Memoir::Formula(printed.into()),
        derived: Derived::Numbers(BTreeMap::from([("points".to_string(), POINTS as f64)])),
        rel_diff: Some(rel),
        verdict: policy::formula(rel, otherwise),
        note: format!(
            "generated `{derived}` vs transcribed `{memoir}` at {POINTS} seeded points; {note}"
        ),
    }
}

/// Whether the derived n° 12 forms of (E) and (S) agree with the memoir's (symbolic checks
/// `equilibrium_n12_memoir` and `stability_n12_memoir` of `generated/hoop.checks.tsv`): then a
/// slip in a printed number of the discussion is Carvallo's arithmetic.
pub fn n12_forms_agree() -> bool {
    parse_checks(carvallo::artifacts::HOOP.checks).is_ok_and(|checks| {
        ["equilibrium_n12_memoir", "stability_n12_memoir"]
            .iter()
            .all(|id| checks.iter().any(|c| c.id == *id && c.holds))
    })
}

/// The remarkable points of the stability discussion that the hoop's own concordance
/// (`hoop::hoop_entries`, which calls this one) lists: point F and the vertical tangent of (S) (n° 14),
/// point H (n° 17 bis), now from the exact closed forms of `generated/hoop_discussion.ir`.
pub fn point_entries(formulas_agree: bool) -> Vec<Entry> {
    let mut out = Vec::new();
    let sp = special_points();
    let fa = formulas_agree;
    let note_f =
        "(ℰ) ∩ (S1) in closed form: x^2 = (1 + sqrt 33)/8 (generated point_f_x, point_f_y)";
    out.push(printed_number("14", "point F: x = cos(th)", 0.917, 3, sp.f.0, fa, note_f));
    out.push(printed_number("14", "point F: y = s^2", 0.258, 3, sp.f.1, fa, &format!("{note_f}; at the memoir's own x = 0,917 (ℰ) gives y = {:.4} and (S1) {:.4}: the printed 0,258 lies between", hd::output("reality_y", &[("x", 0.917)]), hd::output("curve_s1_y", &[("x", 0.917)]))));
    let v = sp.vertical;
    let note_v = "vertical tangent of (S): t = (2 + 3 sqrt 2)/7 from the factored F(t) (generated vertical_t), y the double root of the generated (S) there";
    out.push(printed_number("14", "vertical tangent of (S): t = x^2", 0.89193, 5, v.t, fa, note_v));
    out.push(printed_number(
        "14",
        "vertical tangent of (S): x = cos(th)",
        0.944,
        3,
        v.x,
        fa,
        note_v,
    ));
    out.push(printed_number("14", "vertical tangent of (S): th (degrees)", 19.33, 2, v.theta_deg, fa, &format!("{note_v}; printed \"19°,33\"; arccos of the memoir's own x = 0,944 is {:.2}°, so the slip is in his arccos", 0.944f64.acos().to_degrees())));
    out.push(printed_number("14", "vertical tangent of (S): y = s^2", 0.2073, 4, v.y, fa, note_v));
    out.push(printed_number(
        "14",
        "vertical tangent of (S): s",
        0.4656,
        4,
        v.s,
        fa,
        &format!(
            "{note_v}; the square root of the memoir's own y = 0,2073 is {:.4}",
            0.2073f64.sqrt()
        ),
    ));
    let note_h = "(S) ∩ (N): root in (0, 1) of the derived cubic 3w^3 + 4w^2 - 14w + 4 = 0, w = sin(th) (irreducible over Q: no closed form in real radicals without casus irreducibilis), s from S(-s) = 0";
    out.push(printed_number("17", "point H: sin(th)", 0.322, 3, sp.h.0, fa, note_h));
    out.push(printed_number("17", "point H: th (degrees)", 18.8, 1, sp.h.1, fa, note_h));
    out.push(printed_number("17", "point H: s", 0.474, 3, sp.h.2, fa, note_h));
    out
}

/// The other entries of n° 13–19, computed now (the points of [`point_entries`] excepted).
pub fn entries() -> Vec<Entry> {
    let mut out = Vec::new();
    let sp = special_points();
    let root = carvallo_root_of(
        |t| crate::perturb::discussion_output("quartic_f", &[("t", t)]),
        crate::perturb::discussion_output("vertical_t", &[]),
    );
    let fa = n12_forms_agree();
    // n° 13.
    out.push(formula_entry("13", "(ℰ) reality curve", "x^2 + (2/3)xy - 1 = 0", "reality_curve", "memoir_reality_curve", Verdict::DerivationDiffers, "numerator of the discriminant of the derived E(n) in x = cos(th), y = s^2, divided by its constant ratio to the printed curve (symbolic check reality_curve)"));
    // n° 14: curves.
    out.push(formula_entry("14", "(S) resultant of E(n), S(n)", "16x^2(1+x^2)y^2 + 8x(5x^4-5x^2-1)y + 3(1+x^2)^2(1-x^2) = 0", "curve_s", "memoir_curve_s", Verdict::DerivationDiffers, "symbolica's resultant in n of 3 sin cos E(n) and 3 S(n) (cross-checked by the Sylvester determinant), reduced with sin^2 = 1 - x^2, is exactly 12 x the printed polynomial (check curve_s_memoir)"));
    out.push(formula_entry(
        "14",
        "(S1) reality of the roots of S",
        "y = (3/4) x / (1 + 2x^2)",
        "curve_s1_y",
        "memoir_curve_s1_y",
        Verdict::DerivationDiffers,
        "discriminant of the derived S(n)",
    ));
    out.push(formula_entry("14", "F(t) of the vertical tangent", "28t^4 - 44t^3 + 15t^2 + 4t - 2", "quartic_f", "memoir_quartic_f", Verdict::DerivationDiffers, "discriminant in y of the derived (S) over 64x^2 (the memoir's B'^2 - AC over 16x^2), t = x^2; factored over Q: F(t) = (2t - 1)^2 (7t^2 - 4t - 2), so the root is t = (2 + 3 sqrt 2)/7 (not in the memoir); the double root t = 1/2 is an isolated point of (S) at x = 1/sqrt 2, y = 3 sqrt 2 / 8 where E and S share a complex root"));
    let sqrt2 = 2f64.sqrt();
    out.push(number_entry(
        "14",
        "point B: x",
        sqrt2 / 2.0,
        crate::perturb::discussion_output("point_b_x", &[]),
        Verdict::DerivationDiffers,
        "printed sqrt(2)/2; generated point_b_x (maximum of the derived (S1))".into(),
    ));
    out.push(number_entry(
        "14",
        "point B: y",
        3.0 * sqrt2 / 16.0,
        crate::perturb::discussion_output("point_b_y", &[]),
        Verdict::DerivationDiffers,
        "printed 3 sqrt(2)/16; generated point_b_y".into(),
    ));
    out.push(number_entry("14", "tangent of (S) at A: slope", -3.0, crate::perturb::discussion_output("tangent_a_slope", &[]), Verdict::DerivationDiffers, "-P_x/P_y of the derived (S) at (1, 0) (generated `tangent_a_slope`); equal to the slope of (ℰ) there (check tangent_a_reality)".into()));
    out.push(number_entry(
        "14",
        "tangent of (S) at D: slope",
        0.0,
        crate::perturb::discussion_output("tangent_d_slope", &[]),
        Verdict::DerivationDiffers,
        "-P_x/P_y of the derived (S) at (1, 1/4) (generated `tangent_d_slope`): horizontal. Holds by construction because the generated `tangent_d_slope` is the exact 0 that the regeneration's simplification of -P_x/P_y at D left as a constant (its derivation is the symbolic check tangent_d_memoir): no relative change or sign flip of the derived side moves a 0".into(),
    ));
    // n° 14: Carvallo's method.
    let shifted_ok = root.shifted == [28.0, 68.0, 51.0, 14.0, 1.0];
    out.push(Entry {
        falsification: None,
        section: "14".into(),
        quantity: "Horner shift t = 1 + u".into(),
        memoir: Memoir::Formula("28u^4 + 68u^3 + 51u^2 + 14u + 1".into()),
        derived: Derived::Numbers(root.shifted.iter().enumerate().map(|(k, c)| (format!("u^{}", 4 - k), *c)).collect()),
        rel_diff: None,
        verdict: policy::claim(shifted_ok, Verdict::DerivationDiffers),
        note: "Carvallo's Horner tableau (repeated synthetic division by t - 1) run on the generated F(t) (`quartic_f`); rows equal to the printed ones".into(),
    });
    out.push(printed_number("14", "root squaring: v^4 after two squarings", 7332.0, 0, root.v4, fa, "second root-squaring row of v^4 + 14v^3 + 51v^2 + 68v + 28 (v = 1/u): 94^2 - 2 x 753 = 7330; Carvallo's slide rule reads 51^2 = 2601 as 2600, whence his 752 and 7332"));
    out.push(printed_number(
        "14",
        "root squaring: log v^4",
        3.86522,
        5,
        root.log_v4,
        fa,
        "log10 of the computed v^4",
    ));
    out.push(printed_number("14", "root squaring: u = -1/v", -0.10807, 5, root.u, fa, &format!("u from v = (v^4)^(1/4) after two squarings as Carvallo stops; the method itself (two squarings, second root |v| = 2 double, ratio 0.22) is off the exact root by {:.2e} relative; after six squarings by {:.0e}", root.method_rel_error, root.converged_rel_error)));
    out.push(printed_number("14", "u exact vs printed", -0.10807, 5, root.exact_u, fa, &format!("exact u = (3 sqrt 2 - 5)/7 from the generated closed form (Newton-polished in f64; at 256 bits by carvallo_ir::hp: {:.15}); Carvallo's error comes from stopping after two squarings, not from the slide rule", root.exact_u_hp)));
    out.push(printed_number("14", "residual of the u equation at u = -0,10807", 0.0004, 4, root.residual_at_printed_u, fa, "28u^4 + 68u^3 + 51u^2 + 14u + 1 at the printed u, in f64; his check was done with the slide rule"));
    let rel_to_14u = root.residual_at_printed_u.abs() / (14.0 * 0.10807);
    out.push(Entry {
        falsification: None,
        section: "14".into(),
        quantity: "claim: relative error below 1/2 thousandth".into(),
        memoir: Memoir::Number(5e-4),
        derived: Derived::Numbers(BTreeMap::from([
            ("residual_over_14u".to_string(), rel_to_14u),
            ("root_rel_error".to_string(), ((-0.10807 - root.exact_u) / root.exact_u).abs()),
            ("t_rel_error".to_string(), ((0.89193 - (1.0 + root.exact_u)) / (1.0 + root.exact_u)).abs()),
        ])),
        rel_diff: None,
        verdict: policy::claim(rel_to_14u < 5e-4, Verdict::MemoirError),
        note: "reading: a relative error of the equation, for its root u in (-0,2; 0) (the vertical tangent): the residual at u = -0,10807 (exact, in f64, 6,5e-4; Carvallo's slide-rule 0,0004) over the equation's largest term 14u = 1,513 is below 5e-4 (his: 2,6e-4); it holds also for the quantity used next, t = x^2 = 0,89193 (t_rel_error), but not for the root u itself, off by 1,15e-3 relative (root_rel_error); the equation in u is the generated `quartic_f` shifted by Horner's tableau; claim hoop-root-squaring-half-thousandth".into(),
    });
    let v = sp.vertical;
    out.push(printed_number("14", "vertical tangent: product of the y roots", 0.0430, 4, v.y_product, fa, "3(1 + x^2)(1 - x^2)/(16 x^2) at the exact t (constant over leading coefficient of the generated (S))"));
    // n° 15.
    out.push(formula_entry(
        "15",
        "(E') s as a function of n",
        "s = -(3/4 n sin(th) + tan(th)/(2n))",
        "s_of_n",
        "memoir_s_of_n",
        Verdict::DerivationDiffers,
        "(E) solved for s",
    ));
    out.push(formula_entry(
        "15",
        "s0 (text)",
        "s0 = tan(th) sqrt(3 cos(th)/2)",
        "s0",
        "memoir_s0",
        Verdict::DerivationDiffers,
        "(E') at n0 = -sqrt(2/(3 cos(th)))",
    ));
    out.push(formula_entry(
        "15",
        "s0 (table of variations)",
        "s0 = tan(th) sqrt(2/(3 cos(th)))",
        "s0",
        "memoir_s0_table",
        Verdict::MemoirError,
        "misprint in the table: the fraction under the root is inverted (the text's s0 agrees)",
    ));
    out.push(formula_entry(
        "15",
        "(D') D as a function of n",
        "D = 1/2 tan(th) - 1/4 n^2 sin(th)",
        "skid_of_n",
        "memoir_skid_of_n",
        Verdict::DerivationDiffers,
        "derived D with s from (E')",
    ));
    out.push(formula_entry(
        "15",
        "(D'') s^2 on the curve D = d",
        "s^2 = 2 sin(th) (tan(th) - 3D/2)^2 / (tan(th) - 2D)",
        "s2_of_d",
        "memoir_s2_of_d",
        Verdict::DerivationDiffers,
        "resultant in n of (E) and D(n) - d",
    ));
    out.push(printed_number(
        "15",
        "D = 1/2 meets n0 at th (degrees)",
        56.3,
        1,
        1.5f64.atan().to_degrees(),
        fa,
        "(1/3) tan(th) = 1/2 (D at n0 = tan/3, symbolic check skid_at_n0_memoir)",
    ));
    // n° 16 and 18: which g R gives 2,40 m/s.
    let g = 9.81;
    out.push(Entry {
        falsification: None,
        section: "16".into(),
        quantity: "g R implied by V = 2,40 m/s (m^2/s^2)".into(),
        memoir: Memoir::Number(2.40 * 2.40),
        derived: Derived::Numbers(BTreeMap::from([
            ("gR_at_R_0.5_g_9.81".to_string(), g * 0.5),
            ("g_needed_at_R_0.5".to_string(), 2.40 * 2.40 / 0.5),
            ("R_needed_at_g_9.81".to_string(), 2.40 * 2.40 / g),
        ])),
        rel_diff: Some(rel_diff(g * 0.5, 2.40 * 2.40)),
        verdict: policy::finding(Verdict::MemoirError),
        note: "V = sR = sqrt(gR) at s = 1: 2,40 m/s needs g = 11.52 m/s^2 at R = 0.50 m or R = 0.587 m at g = 9.81; no terrestrial g gives it, so the slip is in his square root; n° 18's 1,20 = 0.5 x 2,40 inherits it (the right values are 2.21 and 1.11 m/s)".into(),
    });
    // n° 17.
    out.push(formula_entry(
        "17",
        "(N) s^2 where E(-s) = 0",
        "s^2 = 2 sin(th) / (cos(th)(4 - 3 sin(th)))",
        "curve_n_s2",
        "memoir_curve_n_s2",
        Verdict::DerivationDiffers,
        "E(-s) solved for s^2",
    ));
    out.push(printed_number(
        "17",
        "point I: th (degrees)",
        41.9,
        1,
        sp.i.0,
        fa,
        "(N) touches (ℰ) at the double root sin(th) = 2/3 (check point_i_double): th = arcsin(2/3)",
    ));
    out.push(printed_number(
        "17",
        "point I: s",
        0.95,
        2,
        sp.i.1,
        fa,
        "s = sqrt(2/sqrt 5) from the generated (N) at sin(th) = 2/3",
    ));
    out.extend(marche_entries());
    out.extend(speed_entries());
    // n° 18: arc DH close to the circle s = 0.5.
    let arc: Vec<f64> = (0..=20)
        .filter_map(|k| {
            let x = (sp.h.1 * k as f64 / 20.0).to_radians().cos();
            hd::curve_s_roots(x).map(|(_, hi)| hi.sqrt())
        })
        .collect();
    let dev = arc.iter().map(|s| (s - 0.5).abs() / 0.5).fold(0.0, f64::max);
    out.push(Entry {
        falsification: None,
        section: "18".into(),
        quantity: "arc DH of (S) ~ circle s = 0,5".into(),
        memoir: Memoir::Number(0.5),
        derived: Derived::Numbers(BTreeMap::from([
            ("max_rel_deviation".to_string(), dev),
            ("points".to_string(), arc.len() as f64),
        ])),
        rel_diff: Some(dev),
        verdict: policy::approx(dev, 0.06, Verdict::DerivationDiffers),
        note: "upper branch of the generated (S) for th from 0 to th_H; the memoir says \"grossièrement assimilé\", an approximation it declares: rounding within 6 %".into(),
    });
    // n° 19.
    out.extend(stick_entries());
    out.extend(check_entries());
    out
}

/// The roots n1, n2 of the generated normalised (E) of n° 12 at (θ, s), n2 the smaller in
/// absolute value (both are negative for s > 0); `None` when they are not real. (E) is a
/// quadratic in n with leading coefficient 1, so three evaluations fix it.
fn e_roots(theta: f64, s: f64) -> Option<(f64, f64)> {
    let e = |n: f64| crate::perturb::normalised("equilibrium_n12", theta, s, n);
    let c = e(0.0);
    let a = 0.5 * (e(1.0) + e(-1.0)) - c;
    let b = 0.5 * (e(1.0) - e(-1.0));
    let disc = b * b - 4.0 * a * c;
    if !(disc >= 0.0 && a.is_finite() && a != 0.0) {
        return None;
    }
    let (lo, hi) = ((-b - disc.sqrt()) / (2.0 * a), (-b + disc.sqrt()) / (2.0 * a));
    Some(if lo.abs() >= hi.abs() { (lo, hi) } else { (hi, lo) })
}

/// n° 17: the table of the orderings of s, -n1, -n2 by region of fig. 4 bis, and which root
/// "marche" (|n| < s, ρ = Rs/|n| > R) or "pivote", checked on a grid of points of each region
/// placed between the generated curves (ℰ) (`reality_s2`) and (N) (`curve_n_s2`); the orderings
/// that hold with their falsification ([`CURVE_N_LOWERED`]).
fn marche_entries() -> Vec<Entry> {
    let table: [crate::perturb::EntryRow; 1] = [(
        &CURVE_N_LOWERED,
        marche_entries_now,
        &["marche/pivot: above (N)", "marche/pivot: (N)-(ℰ), beyond I"],
    )];
    crate::perturb::falsify_table(marche_entries_now(), &table)
}

/// (N) of n° 17 (generated `curve_n_s2`) with its constant n° 2 (the factor 2 of
/// 2 sin(th)/(cos(th)(4 - 3 sin(th)))) halved: the points placed from the lowered (N) fall
/// outside the regions, so the orderings of n° 17, which hold at every point of each region,
/// must fail at some (the placements are relative to (N), within a factor 3 of it).
const CURVE_N_LOWERED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "curve_n_s2",
    target: crate::perturb::Target::Constant(1),
    factor: 0.5,
};

/// The entries of [`marche_entries`], computed now.
fn marche_entries_now() -> Vec<Entry> {
    let theta_i = (2.0f64 / 3.0).asin().to_degrees();
    // (region, printed ordering, θ range in degrees, s^2 from (ℰ)'s and (N)'s s^2 at a fraction)
    type Region = (&'static str, &'static str, (f64, f64), Place, Test, &'static str);
    type Place = fn(f64, f64, f64) -> f64;
    type Test = fn(f64, f64, f64) -> bool;
    let regions: [Region; 3] = [
        (
            "above (N)",
            "-n2 < s < -n1",
            (1.0, 80.0),
            |_, n, f| n * (1.0 + 2.0 * f),
            |s, n1, n2| -n2 < s && s < -n1,
            "-n2 < s < -n1",
        ),
        (
            "(N)-(ℰ), O to I",
            "s < n2 < -n1",
            (1.0, theta_i - 0.5),
            |e, n, f| e + f * (n - e),
            |s, n1, n2| s < -n2 && -n2 < -n1,
            "s < -n2 < -n1",
        ),
        (
            "(N)-(ℰ), beyond I",
            "-n2 < -n1 < s",
            (theta_i + 0.5, 80.0),
            |e, n, f| e + f * (n - e),
            |s, n1, n2| -n2 < -n1 && -n1 < s,
            "-n2 < -n1 < s",
        ),
    ];
    let mut out = Vec::new();
    for (region, printed, (lo, hi), place, holds, derived_order) in regions {
        let (mut points, mut ok, mut n1_marche, mut n2_marche) = (0usize, 0usize, 0usize, 0usize);
        for i in 0..20 {
            let theta = (lo + (hi - lo) * (i as f64 + 0.5) / 20.0).to_radians();
            let args = [("theta", theta)];
            let out = |name: &str| crate::perturb::discussion_output(name, &args);
            let (e_s2, n_s2) = (out("reality_s2"), out("curve_n_s2"));
            for k in 1..=5 {
                let s = place(e_s2, n_s2, k as f64 / 6.0).sqrt();
                let Some((n1, n2)) = e_roots(theta, s) else { continue };
                points += 1;
                ok += usize::from(holds(s, n1, n2));
                n1_marche += usize::from(n1.abs() < s);
                n2_marche += usize::from(n2.abs() < s);
            }
        }
        let all = points == 100 && ok == points;
        let literal_possible = printed == derived_order;
        let verdict = if literal_possible {
            policy::claim(all, Verdict::DerivationDiffers)
        } else {
            policy::finding_if(all, Verdict::Ocr)
        };
        let mut note = format!("roots n1, n2 (|n2| < |n1|) of the generated normalised (E) at 20 x 5 points of the region, s^2 placed between the generated (ℰ) and (N) (above (N): up to three times (N)'s s^2), th in ({lo:.1}°, {hi:.1}°); derived ordering {derived_order}; a root marche when |n| < s (ρ = Rs/|n| > R), pivote otherwise");
        if !literal_possible {
            note.push_str("; the printed \"s < n2\" cannot hold since n2 < 0 (n° 12, footnote of n° 17): a minus sign lost (OCR; the printed literal contradicts the memoir's own footnote), the ordering with -n2 holds");
        }
        out.push(Entry {
            falsification: None,
            section: "17".into(),
            quantity: format!("marche/pivot: {region}"),
            memoir: Memoir::Formula(printed.into()),
            derived: Derived::Numbers(BTreeMap::from([
                ("points".to_string(), points as f64),
                ("ordering_holds".to_string(), ok as f64),
                ("n1_marche".to_string(), n1_marche as f64),
                ("n2_marche".to_string(), n2_marche as f64),
            ])),
            rel_diff: None,
            verdict,
            note,
        });
    }
    out
}

/// The threshold of n° 18 from the generated `stability_n12` with its `s` scaled by 0.7: the
/// threshold moves up by 1/0.7 (to 1.58 m/s), beyond the claim's margin (1.11 m/s against the
/// pas accéléré's 1.50 m/s, 26 %), which the relative changes of
/// [`crate::perturb::falsify_entries`] stay within.
const THRESHOLD_S_SCALED: Perturbation = Perturbation {
    model: "hoop",
    output: "stability_n12",
    target: crate::perturb::Target::Argument("s"),
    factor: 0.7,
};

/// n° 16 and 18: the walking speeds 2,27 m/s (pas gymnastique) and 1,50 m/s (pas accéléré)
/// that the memoir quotes from military regulations, placed on the normalised diagram; the
/// claim of n° 18 with its falsification ([`THRESHOLD_S_SCALED`]).
fn speed_entries() -> Vec<Entry> {
    let table: [crate::perturb::EntryRow; 1] =
        [(&THRESHOLD_S_SCALED, speed_entries_now, &["pas accéléré 1,50 m/s vs threshold sR"])];
    crate::perturb::falsify_table(speed_entries_now(), &table)
}

/// The entries of [`speed_entries`], computed now.
fn speed_entries_now() -> Vec<Entry> {
    let (r, g) = (0.5_f64, 9.81_f64);
    let unit = (g * r).sqrt();
    let s_min = hd::bisect(|s| crate::perturb::normalised("stability_n12", 0.0, s, 0.0), 0.1, 2.0)
        .unwrap_or(f64::NAN);
    let why = "the speed is quoted from military regulations, not derived: nothing in the memoir's mechanics fixes it (R = 0,50 m is only his example and g is not stated), so the number itself cannot be checked; what is checked is the claim the memoir draws from it";
    let gym = 2.27 / unit;
    let accel_threshold = s_min * unit;
    vec![
        Entry {
            falsification: None,
            section: "16".into(),
            quantity: "pas gymnastique 2,27 m/s vs circle s = 1".into(),
            memoir: Memoir::Number(2.27),
            derived: Derived::Numbers(BTreeMap::from([
                ("s_at_R_0.5_g_9.81".to_string(), gym),
                ("s_with_memoir_2.40".to_string(), 2.27 / 2.40),
            ])),
            rel_diff: None,
            verdict: policy::approx((gym - 1.0).abs(), 0.05, Verdict::DerivationDiffers),
            note: format!("{why} (\"la partie utilisée du diagramme ne sortira guère du cercle s = 1\"): s = V/sqrt(gR) at R = 0.5 m, g = 9.81; an approximation the memoir declares: rounding within 5 % of 1"),
        },
        Entry {
            falsification: None,
            section: "18".into(),
            quantity: "pas accéléré 1,50 m/s vs threshold sR".into(),
            memoir: Memoir::Number(1.50),
            derived: Derived::Numbers(BTreeMap::from([
                ("threshold_sR_at_R_0.5_g_9.81".to_string(), accel_threshold),
                ("s_of_1.50_at_R_0.5_g_9.81".to_string(), 1.50 / unit),
            ])),
            rel_diff: None,
            verdict: policy::claim(accel_threshold < 1.50, Verdict::DerivationDiffers),
            note: format!("{why} (the threshold sR >= 0.5 sqrt(gR) is \"un peu inférieure\" to it): threshold s from the root of the generated normalised (S) (`stability_n12`) at th = 0, n = 0, times sqrt(gR); the memoir's 1,20 is 0.5 x his 2,40 (entry of n° 16)"),
        },
    ]
}

/// The closed forms (6), (7) of n° 19 (generated `stick_theta`, `stick_n`) at time `time`, as
/// [`hd::stick_theta_n`] gives them, read through [`crate::perturb::discussion_output`] (so that a
/// perturbed program is seen).
fn stick_theta_n(r: f64, g: f64, s: f64, m: f64, m1: f64, time: f64) -> (f64, f64) {
    let args = [("R", r), ("g", g), ("s", s), ("M", m), ("M1", m1), ("time", time)];
    let out = |name: &str| crate::perturb::discussion_output(name, &args);
    (out("stick_theta"), out("stick_n"))
}

/// n° 19: the OCR's "cosh" and the sign argument, checked on the generated closed forms (6),
/// (7) and on RK4 integrations of the linearised and full equations (2).
fn stick_entries() -> Vec<Entry> {
    let (r, g) = (0.5_f64, 9.81_f64);
    let s = 2.0 * (g / r).sqrt();
    let h = (2.0 / 3.0 * (4.0 * s * s - g / r)).sqrt();
    let time = 2.0 / h;
    let mut out = vec![Entry {
        falsification: None,
        section: "19".into(),
        quantity: "(6): cosh ht".into(),
        memoir: Memoir::Formula("theta = ... - [M/h^2 cosh ht + 4sM1/(3h^3) sin ht]".into()),
        derived: Derived::Numbers(BTreeMap::new()),
        rel_diff: None,
        verdict: policy::finding(Verdict::Ocr),
        note: "the OCR prints cosh; with h^2 > 0 the solution of (4) is cos ht (symbolic check stick_6_memoir, and (6') has 1 - cos ht)".into(),
    }];
    // (moments M, M1 in 1/s^2; back push on the right cheek: both negative)
    for (case, m, m1, theta_sign) in [
        ("back push (M < 0, M1 < 0)", -1.0, -1.0, -1.0),
        ("push at the top (M < 0, M1 = 0)", -1.0, 0.0, -1.0),
        ("front push (M < 0, M1 > 0)", -1.0, 4.0, 1.0),
    ] {
        let (th_cf, n_cf) = stick_theta_n(r, g, s, m, m1, 3.0 * time);
        let (th_lin, n_lin) = hd::stick_linearised_rk4(r, g, s, (m, m1), 3.0 * time, 400, true);
        let (th_full, n_full) = hd::stick_linearised_rk4(r, g, s, (m, m1), 3.0 * time, 400, false);
        let cf_vs_rk4 = rel_diff(th_cf, th_lin).max(rel_diff(n_cf, n_lin));
        let ok = th_cf.signum() == theta_sign
            && th_full.signum() == theta_sign
            && n_cf.signum() == -theta_sign
            && n_full.signum() == -theta_sign
            && cf_vs_rk4 < 1e-6;
        out.push(Entry {
            falsification: None,
            section: "19".into(),
            quantity: format!("sign of th and n: {case}"),
            memoir: Memoir::Number(theta_sign),
            derived: Derived::Numbers(BTreeMap::from([
                ("theta_closed_form".to_string(), th_cf),
                ("n_closed_form".to_string(), n_cf),
                ("theta_full_rk4".to_string(), th_full),
                ("n_full_rk4".to_string(), n_full),
                ("closed_form_vs_rk4".to_string(), cf_vs_rk4),
            ])),
            rel_diff: None,
            verdict: policy::claim(ok, Verdict::DerivationDiffers),
            note: format!("R = {r} m, g = {g}, s = 2 sqrt(g/R), at t = 6/h; memoir column: sign of th (n must have the opposite sign); closed forms (6), (7) generated (`stick_theta`, `stick_n`), RK4 (400 steps) of the linearised and of the full equations (2) of n° 19 with constant moments and s"),
        });
    }
    // Early times with M1 alone: n = M1 t - 2 s th has M1's sign (the sign of th) at first.
    let n_early = |t: f64| hd::stick_theta_n(r, g, s, 0.0, 1.0, t);
    let t_change = carvallo::hoop_discussion::bisect(|t| n_early(t).1, 0.01 / h, 20.0 / h);
    let (th_e, n_e) = n_early(0.5 / h);
    let same_sign = n_e * th_e > 0.0;
    out.push(Entry {
        falsification: None,
        section: "19".into(),
        quantity: "n opposite to th \"dans les trois cas\" (M1 term)".into(),
        memoir: Memoir::Number(-1.0),
        derived: Derived::Numbers(BTreeMap::from([
            ("sign_n_times_theta_at_t_0.5/h".to_string(), (n_e * th_e).signum()),
            ("sign_change_time_h_t".to_string(), t_change.map_or(f64::NAN, |t| t * h)),
        ])),
        rel_diff: None,
        verdict: policy::claim(!same_sign, Verdict::MemoirError),
        note: "for the M1 term, n = M1 t - 2 s th ~ M1 t - (4/9) s^2 M1 t^3 has the sign of M1 (that of th) at first and only takes the opposite sign after h t = sign_change_time_h_t (closed form (7), M = 0, M1 = 1): the memoir's \"dans les trois cas\" holds after that delay, the M term is opposite at once".into(),
    });
    out
}

/// The symbolic checks of `generated/hoop_discussion.checks.tsv` as entries.
fn check_entries() -> Vec<Entry> {
    let checks = match parse_checks(CHECKS_TSV) {
        Ok(c) => c,
        Err(message) => {
            return vec![Entry {
                falsification: None,
                section: "-".into(),
                quantity: "symbolic checks of hoop_discussion".into(),
                memoir: Memoir::Formula("generated/hoop_discussion.checks.tsv".into()),
                derived: Derived::Numbers(BTreeMap::new()),
                rel_diff: None,
                verdict: policy::finding(Verdict::DerivationDiffers),
                note: format!("cannot read generated/hoop_discussion.checks.tsv: {message}"),
            }]
        }
    };
    checks
        .into_iter()
        .map(|c| {
            let mut detail: String = c.detail.chars().take(160).collect();
            if detail.len() < c.detail.len() {
                detail.push_str("...");
            }
            let mut note = format!(
                "symbolic check at regen: {} ({detail})",
                if c.holds { "holds" } else { "does not hold" }
            );
            if let Some(f) = checks::find(FINDINGS, &c.id) {
                note.push_str(&format!("; expected not to hold: {}", f.why));
            }
            let verdict = policy::check(c.holds, checks::expect(FINDINGS, &c.id));
            Entry {
                falsification: checks::falsification(&c, checks::expect(FINDINGS, &c.id)),
                section: c.section,
                quantity: format!("check {}", c.id),
                memoir: Memoir::Formula(c.statement),
                derived: Derived::Numbers(BTreeMap::from([(
                    "holds".to_string(),
                    if c.holds { 1.0 } else { 0.0 },
                )])),
                rel_diff: None,
                verdict,
                note,
            }
        })
        .collect()
}

/// The memoir's claims checked in this report ([`crate::claims`]): n° 13–19.
pub fn claims() -> Vec<crate::claims::Claim> {
    claims::claims()
}

/// The memoir's assertions in this report's sections, n° by n°, with how each is covered.
pub const INVENTORY: &[crate::claims::Assertion] = claims::INVENTORY;
