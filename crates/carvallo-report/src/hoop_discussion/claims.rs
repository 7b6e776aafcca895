//! The memoir's claims of the hoop discussion (n° 13–19): which root of (E) is real, stable,
//! walks or pivots, resists skidding, in which region of the diagrams; Carvallo's worked tables
//! of n° 14 cell by cell; the practical complements of n° 17–19. Checked on the generated
//! curves of `generated/hoop_discussion.ir`, the generated normalised (E), (S), (D) of n° 12,
//! and RK4 simulations of the generated system (2).

use std::sync::OnceLock;

use carvallo::hoop_discussion::{self as hd, special_points};
use carvallo::numerics::poly::{bisect, poly_eval};

use super::e_roots;
use crate::claims::{Assertion, Claim, Status};
use crate::entry::Verdict;
use crate::hoop_simulation::{perturb, unit_hoop};
use crate::perturb::Perturbation;
use crate::policy::{self, rel_diff, unit_of};

/// The two y roots of the generated (S) at x, as [`carvallo::hoop_discussion::curve_s_roots`]
/// but read through [`crate::perturb::discussion_output`] (so that a perturbed program is
/// seen): (S) is quadratic in y, fitted at y = -1, 0, 1.
fn curve_s_roots(x: f64) -> Option<(f64, f64)> {
    let f = |y: f64| crate::perturb::discussion_output("curve_s", &[("x", x), ("y", y)]);
    let (c, plus, minus) = (f(0.0), f(1.0), f(-1.0));
    let (a, b) = (0.5 * (plus + minus) - c, 0.5 * (plus - minus));
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 || a == 0.0 {
        return None;
    }
    let r = disc.sqrt();
    let (y1, y2) = ((-b - r) / (2.0 * a), (-b + r) / (2.0 * a));
    Some((y1.min(y2), y1.max(y2)))
}

/// The claims of n° 13–19, computed once per process.
pub(super) fn claims() -> Vec<Claim> {
    static CLAIMS: OnceLock<Vec<Claim>> = OnceLock::new();
    crate::claims::once_in_memoir_order(&CLAIMS, compute)
}

/// A constant of the hoop's generated normalised (E) of n° 12 (its 4/3, first in the cone)
/// scaled by 1 + 1e-3.
const E_SCALED: Perturbation = Perturbation {
    model: "hoop",
    output: "equilibrium_n12",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-3,
};
/// The first constant of the generated normalised (S) of n° 12 (its 2/3) scaled by 1 + 1e-3.
const S_SCALED: Perturbation = Perturbation {
    model: "hoop",
    output: "stability_n12",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-3,
};
/// The first constant of the generated (S1) (its 4) scaled by 1 + 1e-3.
const S1_SCALED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "curve_s1_y",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-3,
};
/// The first constant of the generated (N) (its 4) scaled by 1 + 1e-3.
const N_SCALED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "curve_n_s2",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-3,
};

/// The first constant of the generated (ℰ) s² (`reality_s2`) scaled by 1 + 1e-3.
const E_CURVE_SCALED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "reality_s2",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-3,
};
/// The first constant of the generated (ℰ) y(x) (`reality_y`) scaled by 1 + 1e-3.
const E_Y_SCALED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "reality_y",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-3,
};

/// The first constant of the generated skid D(n) (`skid_of_n`) scaled by 1 + 1e-3.
const D_SCALED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "skid_of_n",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-3,
};

/// The first constant of the hoop's generated normalised (E) of n° 12 (its 4/3) scaled by
/// 1 + 1e-2.
const E_SCALED_1E2: Perturbation = Perturbation {
    model: "hoop",
    output: "equilibrium_n12",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-2,
};
/// The first constant of the hoop's generated normalised (E) of n° 12 (its 4/3, the term in
/// $sn$) negated.
const E_FLIPPED: Perturbation = Perturbation {
    model: "hoop",
    output: "equilibrium_n12",
    target: crate::perturb::Target::Constant(0),
    factor: -1.0,
};
/// The constant of the hoop's generated n' of system (2) (`pns_dn`, its 2) scaled by 1 + 1e-1.
const DN_SCALED: Perturbation = Perturbation {
    model: "hoop",
    output: "pns_dn",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-1,
};
/// The first constant of the hoop's generated physical (S) of n° 9 (its 2/3) scaled by
/// 1 + 1e-3.
const S_PHYSICAL_SCALED: Perturbation = Perturbation {
    model: "hoop",
    output: "stability",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-3,
};
/// The fifth constant of the generated F(t) (`quartic_f`, the 15 of $15t^2$) negated.
const QUARTIC_FLIPPED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "quartic_f",
    target: crate::perturb::Target::Constant(4),
    factor: -1.0,
};
/// The first constant of the generated skid D(n) (`skid_of_n`, its 4) negated.
const D_FLIPPED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "skid_of_n",
    target: crate::perturb::Target::Constant(0),
    factor: -1.0,
};

/// Every use of θ in the generated skid D(n) (`skid_of_n`) halved: D read at half the lean,
/// which stays below 1/2 (D(n2) lies between tan θ/3 and tan θ/2) for every lean below 90°.
const D_THETA_HALVED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "skid_of_n",
    target: crate::perturb::Target::Argument("theta"),
    factor: 0.5,
};

/// The third constant of the generated cubic of H (`h_cubic`, its 14) negated.
const H_CUBIC_FLIPPED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "h_cubic",
    target: crate::perturb::Target::Constant(2),
    factor: -1.0,
};
/// The first constant of the generated vertical tangent of (S) (`vertical_t`, the 2 under the
/// square root of (2 + 3 sqrt 2)/7) scaled by 1 + 1e-3.
const VERTICAL_T_SCALED: Perturbation = Perturbation {
    model: "hoop_discussion",
    output: "vertical_t",
    target: crate::perturb::Target::Constant(0),
    factor: 1.0 + 1e-3,
};

/// The claims with the falsification of those whose check a perturbation of the generated
/// programs breaks: the checks run again with the perturbation active
/// ([`crate::perturb::with`]), only the functions giving the claims named.
fn compute() -> Vec<Claim> {
    let checks = compute_checks();
    let table: [crate::perturb::Row; 16] = [
        (&D_THETA_HALVED, skid_16, &["hoop-n2-skid-left"]),
        (&H_CUBIC_FLIPPED, h_17_bis, &["hoop-h-cubic-one-root"]),
        (&VERTICAL_T_SCALED, || vec![u_smallest()], &["hoop-u-smallest-root"]),
        (
            &E_SCALED_1E2,
            || vec![reality_sides(), roots_on_ac()],
            &["hoop-reality-sides", "hoop-roots-on-ac"],
        ),
        (&E_FLIPPED, marche_17, &["hoop-e-minus-s-sign"]),
        (&DN_SCALED, || vec![upright_threshold()], &["hoop-upright-threshold"]),
        (&S_PHYSICAL_SCALED, practical_18, &["hoop-threshold-grows-sqrt-r"]),
        (
            &QUARTIC_FLIPPED,
            || {
                let mut v =
                    vec![quartic_bracket(), u_roots(), graeffe_separated(), half_thousandth()];
                v.extend(tables());
                v
            },
            &[
                "hoop-quartic-root-bracket",
                "hoop-u-no-positive-root",
                "hoop-horner-tableau-cells",
                "hoop-graeffe-table-cells",
                "hoop-verification-tableau-cells",
                "hoop-graeffe-separated",
                "hoop-root-squaring-half-thousandth",
            ],
        ),
        (
            &D_FLIPPED,
            || {
                let mut v = discussion_15();
                v.extend(marche_17());
                v
            },
            &["hoop-d-half-three-cases", "hoop-no-skid-normal-play"],
        ),
        (
            &E_SCALED,
            || {
                let mut v = vec![which_root_stable()];
                v.extend(skid_16());
                v.extend(marche_17());
                v.extend(h_17_bis());
                v.extend(practical_18());
                v
            },
            &[
                "hoop-which-root-stable",
                "hoop-n1-skid-region",
                "hoop-n2-walking-root",
                "hoop-h-is-n2",
                "hoop-practical-threshold",
            ],
        ),
        (
            &S_SCALED,
            || {
                let mut v = vec![stable_along_ae()];
                v.extend(marche_17());
                v
            },
            &["hoop-stable-along-ae", "hoop-n2-acceptable-region"],
        ),
        (&S1_SCALED, || vec![s_in_triangle()], &["hoop-s-in-triangle-afd"]),
        (&N_SCALED, marche_17, &["hoop-n-above-e"]),
        (&E_CURVE_SCALED, discussion_15, &["hoop-d-half-touches-e", "hoop-n0-separates-roots"]),
        (&E_Y_SCALED, || vec![reality_curve_shape()], &["hoop-reality-curve-shape"]),
        (&D_SCALED, discussion_15, &["hoop-variation-table", "hoop-d-minus-half-n1"]),
    ];
    crate::perturb::falsify(checks, &table)
        .into_iter()
        .map(|c| match c.id.as_str() {
            "hoop-cyclist-centrifugal-adds" => c.falsified_by(
                "the n° 36 rider a tenth as heavy, 6 kg instead of 60 (his moments A, B, C scaled with him; centre of gravity at 1.25 m and the 5 kg hoop wheel kept)",
                cyclist_footnote_for(0.1),
            ),
            _ => c,
        })
        .collect()
}

/// The checks of n° 13–19, as derived.
fn compute_checks() -> Vec<Claim> {
    let mut out = vec![
        reality_curve_shape(),
        reality_sides(),
        stable_along_ae(),
        roots_on_ac(),
        upright_threshold(),
        which_root_stable(),
        s_in_triangle(),
        quartic_bracket(),
        u_roots(),
        u_smallest(),
    ];
    out.extend(tables());
    out.push(graeffe_separated());
    out.push(half_thousandth());
    out.extend(discussion_15());
    out.extend(skid_16());
    out.extend(marche_17());
    out.push(cyclist_footnote_17());
    out.extend(h_17_bis());
    out.extend(practical_18());
    out.push(neglected_term());
    out.push(heavier_hoop_18());
    out
}

/// $S(n)$ of n° 12 at $(\theta, s)$, from the generated evaluator.
fn s_of(theta: f64, s: f64, n: f64) -> f64 {
    crate::perturb::normalised("stability_n12", theta, s, n)
}

fn reality_curve_shape() -> Claim {
    let y = |x: f64| crate::perturb::discussion_output("reality_y", &[("x", x)]);
    let at_a = y(1.0);
    let asymptote = 1e-6 * y(1e-6);
    // Conic x^2 + (2/3) x y - 1: B^2 - 4AC = 4/9 > 0 (read off the generated reality_curve).
    let curve = |x: f64, yy: f64| {
        crate::perturb::discussion_output("reality_curve", &[("x", x), ("y", yy)])
    };
    let (a, b, c) = (
        curve(1.0, 0.0) - curve(0.0, 0.0),
        curve(1.0, 1.0) - curve(1.0, 0.0) - curve(0.0, 1.0) + curve(0.0, 0.0),
        curve(0.0, 1.0) - curve(0.0, 0.0),
    );
    let disc = b * b - 4.0 * a * c;
    let ok = at_a.abs() < 1e-15 && (asymptote - 1.5).abs() < 1e-5 && disc > 0.0;
    Claim::new(
        "hoop-reality-curve-shape",
        "13",
        "The curve AE of the reality of the roots of (E), x^2 + (2/3) x y - 1 = 0 in x = cos θ, y = s^2, \"c'est une branche d'hyperbole qui part du point A (x = 1, y = 0); elle a pour asymptote l'axe Oy\".",
        "the generated reality_y(x) at x = 1 and x reality_y(x) at x = 1e-6 (y ~ 3/(2x): the asymptote x = 0); the conic's discriminant B^2 - 4AC from the generated reality_curve's coefficients",
        &[("y_at_x_1", at_a), ("x_times_y_at_x_1e-6", asymptote), ("conic_discriminant", disc)],
        policy::claim(ok, Verdict::DerivationDiffers),
        "y = 3(1 - x^2)/(2x): a hyperbola (B^2 - 4AC = 4/9) through A, with the asymptote x = 0",
    )
}

fn reality_sides() -> Claim {
    let (mut left_real, mut right_complex, mut cases) = (0usize, 0usize, 0usize);
    for i in 1..=89 {
        let theta = (i as f64).to_radians();
        let y_e = crate::perturb::discussion_output("reality_s2", &[("theta", theta)]);
        for f in [0.5, 0.9, 0.99, 1.01, 1.1, 2.0, 5.0] {
            cases += 1;
            let real = e_roots(theta, (f * y_e).sqrt()).is_some();
            if f < 1.0 {
                left_real += usize::from(real);
            } else {
                right_complex += usize::from(!real);
            }
        }
    }
    Claim::new(
        "hoop-reality-sides",
        "13",
        "Left of the curve AE (ℰ) is not satisfied and (E) is impossible; right of it (E) has two real roots n1, n2 giving the equilibrium.",
        "θ = 1° to 89° by 1°; s^2 at 0,5 to 5 times the generated (ℰ) s^2 (reality_s2); the roots of the generated normalised (E) (real or not)",
        &[("cases", cases as f64), ("left_with_real_roots", left_real as f64), ("right_without_real_roots", right_complex as f64)],
        policy::claim(left_real == 0 && right_complex == 0, Verdict::DerivationDiffers),
        "",
    )
}

fn stable_along_ae() -> Claim {
    let mut min = f64::INFINITY;
    for i in 1..=89 {
        let theta = (i as f64).to_radians();
        let s = crate::perturb::discussion_output("reality_s2", &[("theta", theta)]).sqrt();
        min = min.min(s_of(theta, s, -2.0 * s / (3.0 * theta.sin())));
    }
    Claim::new(
        "hoop-stable-along-ae",
        "14",
        "Along AE the roots are equal, n = -2s/(3 sin θ), and S(n) there is \"visiblement positive\": the condition (S) is satisfied along AE.",
        "θ = 1° to 89° by 1°, s on the generated (ℰ); the generated normalised (S) at the double root",
        &[("min_S_on_AE", min)],
        policy::claim(min > 0.0, Verdict::DerivationDiffers),
        "S = 4s^2/(9 sin^2 θ) + 8s^2/9 - 2 cos θ/3 with the first term equal to 2/(3 cos θ) on AE",
    )
}

fn roots_on_ac() -> Claim {
    let (mut n1_dev, mut n2_max, mut s_n1_min, mut s_n2_dev) =
        (0.0f64, 0.0f64, f64::INFINITY, 0.0f64);
    for s in [0.3, 0.5, 0.8, 1.2] {
        let theta = 1e-4;
        if let Some((n1, n2)) = e_roots(theta, s) {
            n1_dev = n1_dev.max(rel_diff(n1 * theta.sin(), -4.0 * s / 3.0));
            n2_max = n2_max.max(n2.abs());
            s_n1_min = s_n1_min.min(s_of(theta, s, n1));
            s_n2_dev = s_n2_dev.max((s_of(theta, s, n2) - (8.0 * s * s / 3.0 - 2.0 / 3.0)).abs());
        }
    }
    let ok = n1_dev < 1e-3 && n2_max < 1e-3 && s_n1_min > 0.0 && s_n2_dev < 1e-3;
    Claim::new(
        "hoop-roots-on-ac",
        "14",
        "On AC (θ infinitely small) the roots of E are n1 = -∞ and n2 = 0; the first makes S positive, the second reduces S to 8s^2/3 - 2/3.",
        "θ = 1e-4 rad, s = 0,3; 0,5; 0,8; 1,2: the roots of the generated normalised (E), n1 sin θ against -4s/3, |n2|, and the generated (S) at each; tolerance 1e-3 (first order in θ)",
        &[("max_rel_diff_n1_sin_vs_minus_4s_over_3", n1_dev), ("max_abs_n2", n2_max), ("min_S_at_n1", s_n1_min), ("max_diff_S_at_n2_vs_8s2_3_minus_2_3", s_n2_dev)],
        policy::claim(ok, Verdict::DerivationDiffers),
        "n1 ~ -4s/(3 θ), n2 ~ -θ/(2s) as θ tends to 0",
    )
}

fn upright_threshold() -> Claim {
    let hoop = unit_hoop();
    let mut agree = 0usize;
    let mut rows = Vec::new();
    for s in [0.4, 0.45, 0.48, 0.52, 0.55, 0.6] {
        let run = perturb(&hoop, (0.0, s, 0.0), 1e-10, 0.005, 120.0);
        let predicted = s * s > 0.25;
        agree += usize::from(predicted != run.diverged);
        rows.push(run.rate);
    }
    Claim::new(
        "hoop-upright-threshold",
        "14",
        "On AC, n2 = 0 makes S positive \"que pour s^2 > 1/4, c'est-à-dire pour les points de AC situés au-dessus du point D\": upright straight rolling is stable iff s > 0,5 sqrt(g/R).",
        "unit hoop (g = R = 1): upright straight rolling at s = 0,40 to 0,60 disturbed by 1e-10 in θ and p, RK4 (step 0,005) of the generated system (2) over 120 time units; stable when the lean stays below 1e6 times the disturbance; the threshold itself is the value entry of n° 14/18",
        &[("cases", 6.0), ("agreeing_with_s2_over_1_4", agree as f64), ("rate_at_s_0.48", rows[2]), ("rate_at_s_0.52", rows[3])],
        policy::claim(agree == 6, Verdict::DerivationDiffers),
        "the rates are the growth rate below the threshold and the angular frequency above, both sqrt|8s^2/3 - 2/3|",
    )
}

/// The sample of the region EAC for the claim of which root is stable: θ from 0,5° to 30°, y
/// from just right of (ℰ) to 0,4, classified by the generated curve (S).
fn region_sample() -> Vec<(f64, f64, bool)> {
    let mut out = Vec::new();
    for i in 1..=60 {
        let deg = 0.5 * i as f64;
        let theta = deg.to_radians();
        let x = theta.cos();
        let y_e = crate::perturb::discussion_output("reality_y", &[("x", x)]);
        let bounds = curve_s_roots(x);
        for k in 1..=40 {
            let y = y_e + (0.4 - y_e) * k as f64 / 41.0;
            if y <= y_e {
                continue;
            }
            let inside = match bounds {
                Some((lo, hi)) => {
                    // Away from the boundary, where the sign of S(n2) is rounding.
                    if (y - lo).abs() < 1e-6 || (y - hi).abs() < 1e-6 {
                        continue;
                    }
                    y > lo && y < hi
                }
                None => false,
            };
            out.push((theta, y.sqrt(), inside));
        }
    }
    out
}

fn which_root_stable() -> Claim {
    let sample = region_sample();
    let (mut wrong, mut inside) = (0usize, 0usize);
    for &(theta, s, ins) in &sample {
        let Some((n1, n2)) = e_roots(theta, s) else {
            wrong += 1;
            continue;
        };
        inside += usize::from(ins);
        let ok = s_of(theta, s, n1) > 0.0 && (s_of(theta, s, n2) > 0.0) != ins;
        wrong += usize::from(!ok);
    }
    // Simulation of a subset: the roots' actual stability.
    let hoop = unit_hoop();
    let (mut simulated, mut sim_wrong) = (0usize, 0usize);
    for &(theta, s, ins) in sample.iter().step_by(61) {
        let Some((n1, n2)) = e_roots(theta, s) else { continue };
        for (n, stable) in [(n1, true), (n2, !ins)] {
            if s_of(theta, s, n).abs() < 0.05 || n.abs() > 8.0 {
                continue;
            }
            simulated += 1;
            let run = perturb(&hoop, (theta, s, n), 1e-10, 0.005, 120.0);
            sim_wrong += usize::from(run.diverged == stable);
        }
    }
    Claim::new(
        "hoop-which-root-stable",
        "14",
        "A curve (S) from A to D splits the region EAC: \"dans la première, contenant AD, la plus petite racine n1 donne seule un équilibre stable; dans la deuxième, renfermant AE et DC, les deux racines n1 et n2 donnent des équilibres stables\"; its equation is S(n2) = 0.",
        "θ = 0,5° to 30° by 0,5°, 40 values of y = s^2 from (ℰ) to 0,4 (points within 1e-6 of (S) skipped); inside or outside the generated curve (S) (its two y roots at x = cos θ); sign of the generated normalised (S) at both roots of the generated (E); and a subset (every 61st point, roots with |S| ≥ 0,05) simulated on the unit hoop (RK4 step 0,005 over 120 time units, disturbance 1e-10, unstable past 1e6 times it)",
        &[("points", sample.len() as f64), ("inside_S", inside as f64), ("sign_disagreements", wrong as f64), ("simulated_roots", simulated as f64), ("simulation_disagreements", sim_wrong as f64)],
        policy::claim(wrong == 0 && sim_wrong == 0 && inside > 0 && simulated > 0, Verdict::DerivationDiffers),
        "n1 is stable everywhere in EAC; n2 is unstable exactly inside (S) (the part containing the segment AD of the axis)",
    )
}

fn s_in_triangle() -> Claim {
    let sp = special_points();
    let (xf, xv) = (sp.f.0, sp.vertical.x);
    let (mut below_e, mut above_s1, mut points) = (f64::INFINITY, f64::INFINITY, 0usize);
    for k in 0..=200 {
        let x = xv + (1.0 - xv) * k as f64 / 200.0;
        let Some((lo, hi)) = curve_s_roots(x.min(1.0)) else { continue };
        for y in [lo, hi] {
            points += 1;
            below_e = below_e.min(y - crate::perturb::discussion_output("reality_y", &[("x", x)]));
            above_s1 =
                above_s1.min(crate::perturb::discussion_output("curve_s1_y", &[("x", x)]) - y);
        }
    }
    let ok = xv > xf && below_e > -1e-9 && above_s1 > -1e-9 && points > 300;
    Claim::new(
        "hoop-s-in-triangle-afd",
        "14",
        "\"Ainsi la courbe (S) est confinée dans le petit triangle curviligne AFD\" bounded by (ℰ), (S1) and the axis x = 1.",
        "201 values of x from the vertical tangent of (S) to 1, both y roots of the generated (S): their margins above the generated (ℰ) and below the generated (S1), and the vertical tangent's x against F's; tolerance 1e-9",
        &[("points", points as f64), ("min_margin_above_E", below_e), ("min_margin_below_S1", above_s1), ("x_vertical_minus_x_F", xv - xf)],
        policy::claim(ok, Verdict::DerivationDiffers),
        "the margins are zero at A and D, where (S) meets (ℰ) and (S1)",
    )
}

fn quartic_bracket() -> Claim {
    let f = |t: f64| crate::perturb::discussion_output("quartic_f", &[("t", t)]);
    let t = crate::perturb::discussion_output("vertical_t", &[]);
    let sp = special_points();
    let tf = sp.f.0 * sp.f.0;
    let ok = f(0.0) < 0.0 && f(1.0) > 0.0 && t > 0.8 && t < 1.0 && tf > 0.8;
    Claim::new(
        "hoop-quartic-root-bracket",
        "14",
        "\"F(t) a une racine comprise entre zéro et un, car F(0) est négatif et F(1) est positif\"; it lies between 0,8 and 1 (by the triangle AFD), so the equation in u = t - 1 has a negative root between 0 and -0,2.",
        "the generated quartic_f at 0 and 1, its root t = (2 + 3 sqrt 2)/7 (generated vertical_t), and t at F (x_F^2, generated point_f_x)",
        &[("F_0", f(0.0)), ("F_1", f(1.0)), ("root_t", t), ("t_at_F", tf)],
        policy::claim(ok, Verdict::DerivationDiffers),
        "F = (2t - 1)^2 (7t^2 - 4t - 2) also has the double root t = 1/2 in (0, 1), which the sign test cannot see; it is an isolated point of (S), not the vertical tangent",
    )
}

/// The roots of the equation in u: from the factorisation of F checked at regeneration,
/// $t = 1/2$ (double) and $t = (2 \pm 3\sqrt2)/7$, shifted by $-1$.
fn u_equation_roots() -> Vec<f64> {
    let r2 = 2f64.sqrt();
    vec![-0.5, -0.5, (2.0 + 3.0 * r2) / 7.0 - 1.0, (2.0 - 3.0 * r2) / 7.0 - 1.0]
}

fn u_roots() -> Claim {
    // The equation in u: the Horner shift t = 1 + u of the generated F(t).
    let (shifted, _) = carvallo::numerics::graeffe::horner_shift(&quartic_f_coefficients(), 1.0);
    let min_coeff = shifted.iter().copied().fold(f64::INFINITY, f64::min);
    let roots = u_equation_roots();
    let residual = roots.iter().map(|&u| poly_eval(&shifted, u).abs()).fold(0.0, f64::max);
    let largest = roots.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    Claim::new(
        "hoop-u-no-positive-root",
        "14",
        "The equation in u, 28u^4 + 68u^3 + 51u^2 + 14u + 1 = 0, \"n'a aucune racine positive, puisqu'elle n'a pas de variation\".",
        "the coefficients of the Horner shift of the generated F(t) (all positive: Descartes' rule), and the four roots u = -1/2 (double), (-5 ± 3 sqrt 2)/7 from the factorisation of F checked at regeneration, with their residuals",
        &[("smallest_coefficient", min_coeff), ("largest_root", largest), ("max_residual", residual)],
        policy::claim(min_coeff > 0.0 && largest < 0.0 && residual < 1e-12, Verdict::DerivationDiffers),
        "",
    )
}

fn u_smallest() -> Claim {
    // The root sought: the vertical tangent of (S), t = (2 + 3 sqrt 2)/7 (generated vertical_t).
    let exact_u = crate::perturb::discussion_output("vertical_t", &[]) - 1.0;
    let roots = u_equation_roots();
    let smallest = roots.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let next = roots.iter().copied().filter(|&u| u < smallest).fold(f64::NEG_INFINITY, f64::max);
    Claim::new(
        "hoop-u-smallest-root",
        "14",
        "\"C'est certainement la plus petite racine négative qui convient\": with u = 1/v, the root sought is the v of largest modulus.",
        "the roots of the equation in u (hoop-u-no-positive-root) against the root of the vertical tangent (generated vertical_t - 1)",
        &[("root_sought", exact_u), ("smallest_modulus_root", smallest), ("next_root", next)],
        policy::claim(rel_diff(smallest, exact_u) < 1e-12 && smallest.abs() < next.abs(), Verdict::DerivationDiffers),
        "the root in (-0,2; 0) is the one of smallest modulus (the others are -1/2, double, and -1,32), so 1/u has the largest modulus",
    )
}

/// One printed cell of a worked table: what is printed, with the unit of its last digit, the
/// value Carvallo's own arithmetic gives from his printed inputs, and the exact value.
struct Cell {
    printed: f64,
    unit: f64,
    his: f64,
    exact: f64,
}

fn cell(printed: f64, decimals: i32, his: f64, exact: f64) -> Cell {
    Cell { printed, unit: unit_of(decimals), his, exact }
}

/// The cells' comparison: (count, faithful to his arithmetic within a slide rule's precision
/// by the policy's rule for printed numbers, largest relative difference to his arithmetic,
/// largest relative difference to the exact values).
fn judge(cells: &[Cell]) -> (usize, usize, f64, f64) {
    let (mut faithful, mut his_max, mut exact_max) = (0, 0.0f64, 0.0f64);
    for c in cells {
        let v = policy::printed(c.his, c.printed, c.unit, Verdict::MemoirError);
        faithful += usize::from(matches!(v, Verdict::Agrees | Verdict::Rounding));
        his_max = his_max.max(rel_diff(c.his, c.printed));
        exact_max = exact_max.max(rel_diff(c.exact, c.printed));
    }
    (cells.len(), faithful, his_max, exact_max)
}

/// Carvallo's method of n° 14 as [`carvallo::hoop_discussion::carvallo_root`] runs it, but on
/// the generated F(t) read through [`crate::perturb::discussion_output`]
/// ([`quartic_f_coefficients`]) instead of the compiled copy, so that a perturbed program is
/// seen: the equation in u (the Horner shift t = 1 + u), the root-squaring rows on v = 1/u
/// after 0, 1 and 2 squarings, and the exact root polished by Newton from the generated
/// `vertical_t`.
struct GeneratedRoot {
    /// The equation in u, highest power first (28, 68, 51, 14, 1).
    shifted: Vec<f64>,
    /// The root-squaring rows on the equation in v.
    graeffe_rows: Vec<Vec<f64>>,
    /// The root from (generated `vertical_t`) - 1, three Newton steps on the equation in u.
    exact_u: f64,
    /// The relative error of the method's u (two squarings) against `exact_u`.
    method_rel_error: f64,
    /// The same after six squarings.
    converged_rel_error: f64,
}

fn generated_root() -> GeneratedRoot {
    use carvallo::numerics::graeffe::{graeffe_largest, horner_shift};
    let (shifted, _) = horner_shift(&quartic_f_coefficients(), 1.0);
    let reversed: Vec<f64> = shifted.iter().rev().copied().collect();
    let (graeffe_rows, v_abs) = graeffe_largest(&reversed, 2);
    let u = -1.0 / v_abs;
    let (_, v_conv) = graeffe_largest(&reversed, 6);
    let mut exact_u = crate::perturb::discussion_output("vertical_t", &[]) - 1.0;
    for _ in 0..3 {
        let h = 1e-7;
        let d = (poly_eval(&shifted, exact_u + h) - poly_eval(&shifted, exact_u - h)) / (2.0 * h);
        if d != 0.0 {
            exact_u -= poly_eval(&shifted, exact_u) / d;
        }
    }
    GeneratedRoot {
        method_rel_error: ((u - exact_u) / exact_u).abs(),
        converged_rel_error: ((-1.0 / v_conv - exact_u) / exact_u).abs(),
        shifted,
        graeffe_rows,
        exact_u,
    }
}

/// The equation in v = 1/u that Carvallo squares, 1, 14, 51, 68, 28 (his first row).
const PRINTED_V_EQUATION: [f64; 5] = [1.0, 14.0, 51.0, 68.0, 28.0];

fn tables() -> Vec<Claim> {
    let root = generated_root();
    // Horner tableau: the coefficients, then for each pass the products line (1 x the new row
    // but its last entry) and the new row; the last pass carries the leading 28.
    let printed_horner: [&[f64]; 11] = [
        &[28.0, -44.0, 15.0, 4.0, -2.0],
        &[28.0, -16.0, -1.0, 3.0],
        &[28.0, -16.0, -1.0, 3.0, 1.0],
        &[28.0, 12.0, 11.0],
        &[28.0, 12.0, 11.0, 14.0],
        &[28.0, 40.0],
        &[28.0, 40.0, 51.0],
        &[28.0],
        &[28.0, 68.0],
        &[28.0],
        &[28.0],
    ];
    let coefficients = quartic_f_coefficients();
    let (shifted, horner_rows) = carvallo::numerics::graeffe::horner_shift(&coefficients, 1.0);
    let mut derived: Vec<Vec<f64>> = vec![coefficients];
    for row in &horner_rows {
        derived.push(row[..row.len() - 1].to_vec());
        derived.push(row.clone());
    }
    derived.push(vec![shifted[0]]);
    derived.push(vec![shifted[0]]);
    let (mut cells, mut differ) = (0usize, 0usize);
    for (p, d) in printed_horner.iter().zip(&derived) {
        for (a, b) in p.iter().zip(d) {
            cells += 1;
            differ += usize::from(a != b);
        }
        differ += p.len().abs_diff(d.len());
    }
    let horner = Claim::new(
        "hoop-horner-tableau-cells",
        "14",
        "The printed Horner tableau of the shift t = 1 + u (11 lines, \"la minute du calcul, sans omettre un seul chiffre\") gives the equation 28u^4 + 68u^3 + 51u^2 + 14u + 1 = 0.",
        "every printed cell (31) against the repeated synthetic division by t - 1 (carvallo::numerics::graeffe::horner_shift) of the generated F(t) (coefficients read off quartic_f): the products lines are the new rows but their last entry, the last two lines carry the leading 28; exact comparison",
        &[("cells", cells as f64), ("cells_differing", differ as f64)],
        policy::claim(cells == 31 && differ == 0, Verdict::DerivationDiffers),
        "integers: every cell exact",
    );
    // Root-squaring table. Carvallo writes a number of k + 1 digits as "k.digits" (2.196 =
    // 196, 5.565 = 565 000); the double products are printed by their leading digits.
    let e = &root.graeffe_rows;
    let (h0, h1) = (PRINTED_V_EQUATION, [1.0, 94.0, 752.0, 1770.0, 784.0]);
    // His first row is the equation in v of the generated F (the tableau's shift reversed).
    let v_equation: Vec<f64> = root.shifted.iter().rev().copied().collect();
    let from_equation = v_equation == h0;
    let ex1 = &e[1];
    let g = vec![
        // 2^0 squares and double products (his inputs are the exact coefficients).
        cell(196.0, 0, 196.0, 196.0),
        cell(2600.0, 0, 2601.0, 2601.0),
        cell(4625.0, 0, 4624.0, 4624.0),
        cell(-102.0, 0, -2.0 * h0[0] * h0[2], -102.0),
        cell(-1904.0, 0, -2.0 * h0[1] * h0[3], -1904.0),
        cell(-2855.0, 0, -2.0 * h0[2] * h0[4], -2856.0),
        cell(56.0, 0, 2.0 * h0[0] * h0[4], 56.0),
        // 2^1 row, from his squares and products.
        cell(94.0, 0, 196.0 - 102.0, ex1[1]),
        cell(752.0, 0, 2600.0 - 1904.0 + 56.0, ex1[2]),
        cell(1770.0, 0, 4625.0 - 2855.0, ex1[3]),
        cell(784.0, 0, 28.0 * 28.0, ex1[4]),
        // 2^1 squares and double products.
        cell(8836.0, 0, h1[1] * h1[1], ex1[1] * ex1[1]),
        cell(565_000.0, -3, h1[2] * h1[2], ex1[2] * ex1[2]),
        cell(3_130_000.0, -4, h1[3] * h1[3], ex1[3] * ex1[3]),
        cell(-1504.0, 0, -2.0 * h1[0] * h1[2], -2.0 * ex1[0] * ex1[2]),
        cell(-332_700.0, -2, -2.0 * h1[1] * h1[3], -2.0 * ex1[1] * ex1[3]),
        cell(-1_180_000.0, -4, -2.0 * h1[2] * h1[4], -2.0 * ex1[2] * ex1[4]),
        cell(1600.0, -2, 2.0 * h1[0] * h1[4], 2.0 * ex1[0] * ex1[4]),
        // 2^2 row, from his squares and products; 784^2 is printed twice ("5.613").
        cell(7332.0, 0, 8836.0 - 1504.0, e[2][1]),
        cell(234_000.0, -3, 565_000.0 - 332_700.0 + 1600.0, e[2][2]),
        cell(1_950_000.0, -4, 3_130_000.0 - 1_180_000.0, e[2][3]),
        cell(613_000.0, -3, h1[4] * h1[4], e[2][4]),
        cell(613_000.0, -3, h1[4] * h1[4], e[2][4]),
        // The logarithms and the root.
        cell(3.86522, 5, 7332f64.log10(), -4.0 * (-root.exact_u).log10()),
        cell(0.9663, 4, 3.86522 / 4.0, -(-root.exact_u).log10()),
        cell(-0.9663, 4, -0.9663, (-root.exact_u).log10()),
        cell(0.10807, 5, 10f64.powf(-0.9663), -root.exact_u),
    ];
    let (n, faithful, his_max, exact_max) = judge(&g);
    let graeffe = Claim::new(
        "hoop-graeffe-table-cells",
        "14",
        "The printed root-squaring table on v = 1/u (two squarings, \"les opérations étant faites à la règle à calcul\") and the logarithms that follow, down to -u = 0,10807.",
        "27 printed cells (Carvallo writes a number of k + 1 digits as k.digits, 5.565 = 565 000; double products by their leading digits; the \"5.613\" printed at the end of the first squares line is read as 784^2, printed again as the last coefficient of the 2^2 row; the truncated start of a third squaring, \"10.537\", is not read) each against Carvallo's own arithmetic on his printed inputs (a slide rule: within one unit of the last printed digit or 2e-3 relative, the policy's rule for printed numbers) and against the exact root squaring of the generated equation (carvallo::numerics::graeffe); his first row 1, 14, 51, 68, 28 against the equation in v of the generated F (its Horner shift read backwards, through the generated quartic_f): another equation is derivation-differs",
        &[("cells", n as f64), ("faithful_to_his_arithmetic", faithful as f64), ("max_rel_diff_to_his_arithmetic", his_max), ("max_rel_diff_to_exact", exact_max), ("first_row_is_the_generated_equation", f64::from(u8::from(from_equation)))],
        if from_equation { policy::claim(faithful == n, Verdict::MemoirError) } else { Verdict::DerivationDiffers },
        "every cell is his arithmetic at slide-rule precision under the one rule of printed numbers (policy::printed: within one unit of the last printed digit, or 2e-3 relative, the rule that makes u's 1,1e-3 `rounding`): the largest relative difference, 2 %, is the double product 2 x 784 = 1568 printed by its two digits 16, i.e. 1600 with a last digit worth 100, within one unit; the exception is 784^2 = 614 656 printed 613 (thousands, both times), 1,7 units of the last digit and 2,7e-3 relative, outside both halves of the rule: a slip, kept `memoir-error`, that does not reach the root (only the first two coefficients of the last row give v^4); against the exact squaring the cells drift by up to 2 % (his 752 for 753 and 1770 for 1768 propagate)",
    );
    // The verification by substitution of u = -0,10807 (synthetic division).
    let u = -0.10807;
    let exact_rows = {
        let mut acc = Vec::new();
        let mut b = 0.0;
        for (k, c) in root.shifted.iter().enumerate() {
            let prod = if k == 0 { 0.0 } else { b * u };
            b = c + prod;
            acc.push((prod, b));
        }
        acc
    };
    let v = vec![
        cell(-3.025, 3, 28.0 * u, exact_rows[1].0),
        cell(64.975, 3, 68.0 - 3.025, exact_rows[1].1),
        cell(-7.02, 2, 64.975 * u, exact_rows[2].0),
        cell(43.98, 2, 51.0 - 7.02, exact_rows[2].1),
        cell(-4.752, 3, 43.98 * u, exact_rows[3].0),
        cell(9.248, 3, 14.0 - 4.752, exact_rows[3].1),
        cell(-0.9996, 4, 9.248 * u, exact_rows[4].0),
        cell(0.0004, 4, 1.0 - 0.9996, exact_rows[4].1),
    ];
    let (vn, vf, vh, ve) = judge(&v);
    // His equation in u, 28, 68, 51, 14, 1, is the generated F shifted.
    let u_from_equation = root.shifted == [28.0, 68.0, 51.0, 14.0, 1.0];
    let verification = Claim::new(
        "hoop-verification-tableau-cells",
        "14",
        "The printed verification of u = -0,10807 by substitution in the equation in u (synthetic division) ends with the residual +0,0004.",
        "the 8 computed cells (4 products, 4 partial sums; the first line is the equation's coefficients) each against Carvallo's own arithmetic on his printed inputs (slide-rule rule of the policy) and against the exact synthetic division at u = -0,10807; the first line 28, 68, 51, 14, 1 against the Horner shift of the generated F (through the generated quartic_f): another equation is derivation-differs",
        &[("cells", vn as f64), ("faithful_to_his_arithmetic", vf as f64), ("max_rel_diff_to_his_arithmetic", vh), ("max_rel_diff_to_exact", ve), ("exact_residual", exact_rows[4].1), ("first_line_is_the_generated_equation", f64::from(u8::from(u_from_equation)))],
        if u_from_equation { policy::claim(vf == vn, Verdict::MemoirError) } else { Verdict::DerivationDiffers },
        "every cell is his slide-rule arithmetic (9,248 x 0,10807 = 0,99943 read 0,9996); that reading, 1,7e-4 relative, is what turns the exact residual 0,00065 into his 0,0004 (the value entry of the residual)",
    );
    vec![horner, graeffe, verification]
}

/// The coefficients of the generated F(t), highest first, read off its evaluator.
fn quartic_f_coefficients() -> Vec<f64> {
    let f = |t: f64| crate::perturb::discussion_output("quartic_f", &[("t", t)]);
    // Values at 0, ±1, ±2 determine the quartic; the coefficients are integers.
    let (f0, f1, fm1, f2, fm2) = (f(0.0), f(1.0), f(-1.0), f(2.0), f(-2.0));
    let even2 = 0.5 * (f1 + fm1) - f0; // a2 + a4
    let even4 = 0.5 * (f2 + fm2) - f0; // 4 a2 + 16 a4
    let a4 = (even4 - 4.0 * even2) / 12.0;
    let a2 = even2 - a4;
    let odd1 = 0.5 * (f1 - fm1); // a1 + a3
    let odd2 = 0.5 * (f2 - fm2); // 2 a1 + 8 a3
    let a3 = (odd2 - 2.0 * odd1) / 6.0;
    let a1 = odd1 - a3;
    [a4, a3, a2, a1, f0].iter().map(|c| c.round()).collect()
}

fn graeffe_separated() -> Claim {
    let root = generated_root();
    let rows = &root.graeffe_rows;
    let last = &rows[2];
    let prev = &rows[1];
    let share = (last[1] - prev[1] * prev[1]).abs() / (prev[1] * prev[1]);
    let v = u_equation_roots().iter().map(|u| 1.0 / u.abs()).collect::<Vec<_>>();
    let v1 = v.iter().copied().fold(0.0, f64::max);
    let rest4: f64 = v.iter().filter(|&&x| x < v1).map(|x| x.powi(4)).sum();
    Claim::new(
        "hoop-graeffe-separated",
        "14",
        "After two squarings \"la plus grande racine est visiblement séparée et la dernière transformée donne pour cette racine\" v^4 = 7332.",
        "the exact root squaring (carvallo::numerics::graeffe) of the equation in v of the generated F (through the generated quartic_f), v^4 + 14v^3 + 51v^2 + 68v + 28: the double products' share of the square in the first coefficient of the last row (the usual test of separation: negligible when separated), the other roots' share of the sum of fourth powers that this coefficient is, and the relative error of the root it gives against the exact one",
        &[("double_product_share_last_row", share), ("other_roots_share_of_b1", rest4 / (v1.powi(4))), ("root_rel_error_after_2", root.method_rel_error), ("root_rel_error_after_6", root.converged_rel_error)],
        // Separated, or else judged by what the separation is for, the root read off, with the
        // one rule of slide-rule numbers (policy::printed, as the value entry `u exact vs
        // printed`): within one unit of the last printed digit or 2e-3 relative is rounding.
        if share < 0.01 && root.method_rel_error < 5e-5 {
            Verdict::Agrees
        } else {
            policy::printed(root.exact_u, -0.10807, 1e-5, Verdict::MemoirError)
        },
        "not fully separated: the double products are still 17 % of the square in the last row, because the next root v = -2 is double (its two fourth powers are 0,44 % of b1), and the fourth root of 7330 is off the exact |v| by 1,1e-3 relative (-u = 0,10807, exact 0,10819); four more squarings separate it (error 1e-16). Judged as every slide-rule number of the report (one unit of the last printed digit or 2e-3 relative, the rule of the value entry `u exact vs printed`), the root the claim delivers is within a slide rule's three digits: `rounding`, not `memoir-error`; his fifth printed digit is beyond his instrument",
    )
}

fn half_thousandth() -> Claim {
    let root = generated_root();
    let u = -0.10807;
    let residual = poly_eval(&root.shifted, u);
    let largest_term = (14.0 * u).abs();
    let rel_u = rel_diff(u, root.exact_u);
    let t = 1.0 + root.exact_u;
    let rel_t = rel_diff(1.0 + u, t);
    let rel_x = rel_diff((1.0 + u).sqrt(), t.sqrt());
    let holds =
        residual.abs() / largest_term < 5e-4 && 0.0004 / largest_term < 5e-4 && rel_t < 5e-4;
    Claim::new(
        "hoop-root-squaring-half-thousandth",
        "14",
        "\"On peut dire que u = -0,10807 est une solution qui satisfait à l'équation avec une erreur relative moindre que 1/2 millième\" (the residual 0,0004 \"négligeable par rapport au terme 14u = 1,5...\").",
        "the equation in u (Horner shift of the generated F) evaluated in floating point at u = -0,10807: its residual relative to the largest term 14u; Carvallo's own residual 0,0004 likewise; and the relative errors of u, t = 1 + u and x = sqrt t against the exact root u = (3 sqrt 2 - 5)/7",
        &[("exact_residual", residual), ("exact_residual_over_14u", residual.abs() / largest_term), ("printed_residual_over_14u", 0.0004 / largest_term), ("rel_error_u", rel_u), ("rel_error_t", rel_t), ("rel_error_x", rel_x)],
        policy::claim(holds, Verdict::MemoirError),
        "holds in the memoir's reading, a relative error of the equation: the residual (exact 0,00065 or his 0,0004) is below 5e-4 of the equation's largest term 14u; it also holds for the quantities used next, t = x^2 (1,4e-4) and x = cos θ (7e-5); it does not hold for the root u itself, off by 1,15e-3 relative (P'(u) = 5,2 is small against the terms, so a small residual allows a larger error in u)",
    )
}

fn discussion_15() -> Vec<Claim> {
    let skid = |th: f64, n: f64| {
        crate::perturb::discussion_output("skid_of_n", &[("theta", th), ("n", n)])
    };
    let s_n =
        |th: f64, n: f64| crate::perturb::discussion_output("s_of_n", &[("theta", th), ("n", n)]);
    // n0 between the roots; s and D monotone either side of n0; the limits of the table.
    let (mut order_wrong, mut mono_wrong, mut limit_dev, mut cases) =
        (0usize, 0usize, 0.0f64, 0usize);
    let mut minimum_dev = 0.0f64;
    for i in 1..=17 {
        let theta = (5.0 * i as f64).to_radians();
        let n0 = -(2.0 / (3.0 * theta.cos())).sqrt();
        let s_e = crate::perturb::discussion_output("reality_s2", &[("theta", theta)]).sqrt();
        minimum_dev = minimum_dev.max(rel_diff(s_n(theta, n0), s_e));
        for f in [1.01, 1.2, 2.0, 4.0] {
            cases += 1;
            if let Some((n1, n2)) = e_roots(theta, f * s_e) {
                order_wrong += usize::from(!(n1 < n0 && n0 < n2));
            }
        }
        // n from 0 to n0 (root n2): s decreases to s0, D decreases to tan/3; beyond n0 (n1):
        // s increases, D decreases.
        let grid: Vec<f64> = (1..=400).map(|k| n0 * k as f64 / 200.0).collect();
        for w in grid.windows(2) {
            let (a, b) = (w[0], w[1]);
            let s_ok =
                if b <= n0 { s_n(theta, b) > s_n(theta, a) } else { s_n(theta, b) < s_n(theta, a) };
            let d_ok = skid(theta, b) < skid(theta, a);
            mono_wrong +=
                usize::from(!(s_ok && d_ok) && (a - n0).abs() > 1e-12 && (b - n0).abs() > 1e-12);
        }
        limit_dev = limit_dev
            .max(rel_diff(skid(theta, -1e-9), 0.5 * theta.tan()))
            .max(rel_diff(skid(theta, n0), theta.tan() / 3.0));
    }
    // The curve D = 1/2: for θ < 45° no point; for 45° < θ < 56,3° one point on n2; beyond, on n1.
    let mut case_wrong = 0usize;
    let mut d_cases = 0usize;
    for i in 1..=85 {
        let theta = (i as f64).to_radians();
        if (theta.tan() - 1.0).abs() < 1e-9 || (theta.tan() - 1.5).abs() < 1e-2 {
            continue;
        }
        d_cases += 1;
        let n0 = -(2.0 / (3.0 * theta.cos())).sqrt();
        // Roots of D(n) = 1/2 for n < 0, on a fine grid.
        let mut roots = Vec::new();
        let grid: Vec<f64> = (1..=4000).map(|k| -0.005 * k as f64).collect();
        for w in grid.windows(2) {
            if (skid(theta, w[0]) - 0.5) * (skid(theta, w[1]) - 0.5) < 0.0 {
                roots.push(w[0]);
            }
        }
        let expect = if theta.tan() < 1.0 {
            roots.is_empty()
        } else if theta.tan() < 1.5 {
            roots.len() == 1 && roots[0] > n0
        } else {
            roots.len() == 1 && roots[0] < n0
        };
        case_wrong += usize::from(!expect);
    }
    // H: the curve D = 1/2 touches (ℰ) at θ = arctan 1,5 (s on the curve minus s on (ℰ) has a
    // minimum 0 there).
    let s_d =
        |theta: f64| crate::perturb::discussion_output("s2_of_d", &[("theta", theta), ("d", 0.5)]);
    let s_e = |theta: f64| crate::perturb::discussion_output("reality_s2", &[("theta", theta)]);
    let th_h = 1.5f64.atan();
    let touch = (s_d(th_h) - s_e(th_h)).abs();
    let mut gap_min = f64::INFINITY;
    for k in 1..=60 {
        let th = (45.5 + 0.5 * k as f64).to_radians();
        if (th - th_h).abs() > 0.01 {
            gap_min = gap_min.min(s_d(th) - s_e(th));
        }
    }
    // D = -1/2 belongs to n1 only: n^2 = 2(tan θ + 1)/sin θ > n0^2.
    let mut minus_wrong = 0usize;
    for i in 1..=89 {
        let theta = (i as f64).to_radians();
        let n = -(2.0 * (theta.tan() + 1.0) / theta.sin()).sqrt();
        let n0 = -(2.0 / (3.0 * theta.cos())).sqrt();
        minus_wrong += usize::from(!(n < n0 && (skid(theta, n) + 0.5).abs() < 1e-9));
    }
    vec![
        Claim::new(
            "hoop-n0-separates-roots",
            "15",
            "s(n) of (E') has its minimum s0 at n0 = -sqrt(2/(3 cos θ)): \"les valeurs de n inférieures à n0 correspondent à la racine n1 de l'équation (E); les autres correspondent à n2\", and the curve (ℰ) is the curve of these minima.",
            "θ = 5° to 85° by 5°: the generated s_of_n at n0 against the generated (ℰ) s (reality_s2); the roots of the generated normalised (E) at s = 1,01 to 4 times the (ℰ) s placed around n0",
            &[("cases", cases as f64), ("roots_not_around_n0", order_wrong as f64), ("max_rel_diff_s_at_n0_vs_E", minimum_dev)],
            policy::claim(order_wrong == 0 && minimum_dev < 1e-12, Verdict::DerivationDiffers),
            "n0 is minus the geometric mean of the roots (their product is 2/(3 cos θ)), hence between them",
        ),
        Claim::new(
            "hoop-variation-table",
            "15",
            "The table of variations at constant θ: as n goes from 0 to n0 (root n2) s decreases from +∞ to s0 and D from tan θ/2 to tan θ/3; from n0 to -∞ (root n1) s increases to +∞ and D decreases to -∞.",
            "θ = 5° to 85° by 5°, 400 values of n from 0 to 2 n0: monotonicity of the generated s_of_n and skid_of_n on each side of n0; D at n = -1e-9 against tan θ/2 and at n0 against tan θ/3",
            &[("monotonicity_failures", mono_wrong as f64), ("max_rel_diff_of_D_limits", limit_dev)],
            policy::claim(mono_wrong == 0 && limit_dev < 1e-6, Verdict::DerivationDiffers),
            "the s0 of the table is misprinted (value entry s0 (table of variations)); the variations hold",
        ),
        Claim::new(
            "hoop-d-half-three-cases",
            "15",
            "The ray θ meets the curve D = 1/2 not at all for θ < 45°, at a point of the root n2 for 45° < θ < 56,3°, at a point of n1 beyond (and at H (n0, s0) for tan θ = 3/2).",
            "θ = 1° to 85° by 1° (the two limits excepted): the zeros of the generated skid_of_n - 1/2 for n < 0 on a grid of step 0,005 down to -20, placed against n0",
            &[("angles", d_cases as f64), ("angles_disagreeing", case_wrong as f64)],
            policy::claim(case_wrong == 0, Verdict::DerivationDiffers),
            "D = tan θ/2 - n^2 sin θ/4 = 1/2 at n^2 = 2(tan θ - 1)/sin θ, real for tan θ ≥ 1, below n0^2 for tan θ < 3/2",
        ),
        Claim::new(
            "hoop-d-half-touches-e",
            "15",
            "\"Ce point H est le point de contact de la courbe D = 1/2 avec la courbe (ℰ) des minima de s, qui est aussi la courbe de réalité des racines n1 et n2.\"",
            "the generated (D'') s^2 on D = 1/2 against the generated (ℰ) s^2 at θ = arctan 3/2 and at θ = 46° to 75,5° by 0,5° elsewhere",
            &[("gap_at_H", touch), ("min_gap_elsewhere", gap_min)],
            policy::claim(touch < 1e-12 && gap_min > 0.0, Verdict::DerivationDiffers),
            "the curve D = 1/2 stays on the real side of (ℰ) and meets it only at H: a contact",
        ),
        Claim::new(
            "hoop-d-minus-half-n1",
            "15",
            "With a friction coefficient 1/2, the curve D = -1/2 \"appartient tout entière à la racine n1\".",
            "θ = 1° to 89° by 1°: the n with D' = -1/2, n^2 = 2(tan θ + 1)/sin θ, checked on the generated skid_of_n and placed against n0",
            &[("angles", 89.0), ("angles_disagreeing", minus_wrong as f64)],
            policy::claim(minus_wrong == 0, Verdict::DerivationDiffers),
            "D is at least tan θ/3 > 0 on the root n2",
        ),
    ]
}

fn skid_16() -> Vec<Claim> {
    // At fixed s, the angles where D(n2) ≥ 1/2 must all lie beyond those where D(n2) < 1/2.
    let d = |theta: f64, n: f64| {
        crate::perturb::discussion_output("skid_of_n", &[("theta", theta), ("n", n)])
    };
    let (mut left_after, mut points, mut skidding) = (0usize, 0usize, 0usize);
    for s in [0.5, 0.8, 1.0, 1.5, 2.0, 3.0, 5.0, 10.0] {
        let mut seen_skid = false;
        for k in 1..=170 {
            let theta = (0.5 * k as f64).to_radians();
            let Some((_, n2)) = e_roots(theta, s) else { continue };
            let v = d(theta, n2);
            if (v - 0.5).abs() < 1e-9 {
                continue;
            }
            points += 1;
            if v >= 0.5 {
                seen_skid = true;
                skidding += 1;
            } else if seen_skid {
                left_after += 1;
            }
        }
    }
    // The region where n1 resists skidding (friction 1/2): -1/2 < D(n1) < 1/2, bounded above by
    // D(n1) = -1/2 and below by (ℰ) to H then D(n1) = +1/2.
    let th_h = 1.5f64.atan();
    let (mut region_wrong, mut region_points) = (0usize, 0usize);
    for k in 1..=85 {
        let theta = (k as f64).to_radians();
        let s_e = crate::perturb::discussion_output("reality_s2", &[("theta", theta)]).sqrt();
        let s_minus =
            crate::perturb::discussion_output("s2_of_d", &[("theta", theta), ("d", -0.5)]).sqrt();
        let s_plus = if theta > th_h {
            crate::perturb::discussion_output("s2_of_d", &[("theta", theta), ("d", 0.5)]).sqrt()
        } else {
            s_e
        };
        for f in [1.001, 1.05, 1.3, 2.0, 3.0, 6.0] {
            let s = s_e * f;
            let Some((n1, _)) = e_roots(theta, s) else { continue };
            let dn1 = d(theta, n1);
            if (dn1.abs() - 0.5).abs() < 1e-6 {
                continue;
            }
            region_points += 1;
            let resists = dn1.abs() < 0.5;
            let between = s < s_minus && s > s_plus;
            region_wrong += usize::from(resists != between);
        }
    }
    vec![
        Claim::new(
            "hoop-n2-skid-left",
            "16",
            "\"La solution n2 ne résiste au dérapage qu'à gauche de la courbe D(n2) = 1/2\" (friction coefficient 1/2).",
            "s = 0,5 to 10 (units sqrt(g/R)), θ = 0,5° to 85° by 0,5° where the roots are real: the generated skid_of_n at the root n2 of the generated (E); along each ray of constant s the points with D(n2) < 1/2 must all come before (left of) the first point with D(n2) ≥ 1/2",
            &[("points", points as f64), ("points_skidding", skidding as f64), ("resisting_points_right_of_a_skidding_one", left_after as f64)],
            policy::claim(left_after == 0 && skidding > 0, Verdict::DerivationDiffers),
            "D(n2) lies between tan θ/3 and tan θ/2: below 1/2 for θ < 45°, above it beyond 56,3°, and crossing 1/2 once in between",
        ),
        Claim::new(
            "hoop-n1-skid-region",
            "16",
            "\"La région où l'autre solution n1 résiste au dérapage est comprise entre la courbe D(n1) = 1/2, d'une part, et la courbe formée des deux branches (ℰ), du point O au point H; puis la courbe D(n1) = 1/2 à partir du point H.\"",
            "θ = 1° to 85°, s from 1,001 to 6 times the (ℰ) s: |D(n1)| < 1/2 from the generated skid_of_n at the root n1 against lying between the generated (D'') curve D = -1/2 (above) and (ℰ) up to H (θ = arctan 3/2), then the curve D = +1/2 (below)",
            &[("points", region_points as f64), ("disagreements_reading_minus_half", region_wrong as f64)],
            policy::finding_if(region_wrong == 0 && region_points > 0, Verdict::Ocr),
            "the printed first curve \"D(n1) = 1/2\" cannot be meant (it is also the second branch of the other boundary); with D(n1) = -1/2 (the curve n° 15 says belongs wholly to n1 and n° 17 calls \"D(n1) = -1/2\") the region is exactly right: a minus sign lost (OCR or print)",
        ),
    ]
}

fn marche_17() -> Vec<Claim> {
    let th_i = (2.0f64 / 3.0).asin();
    // (N) above (ℰ), touching at I only; E(-s) sign either side of (N).
    let (mut below, mut min_gap, mut sign_wrong) = (0usize, f64::INFINITY, 0usize);
    for k in 1..=170 {
        let theta = (0.5 * k as f64).to_radians();
        let (n, e) = (
            crate::perturb::discussion_output("curve_n_s2", &[("theta", theta)]),
            crate::perturb::discussion_output("reality_s2", &[("theta", theta)]),
        );
        below += usize::from(n < e - 1e-12);
        if (theta - th_i).abs() > 0.02 {
            min_gap = min_gap.min(n - e);
        }
        for f in [0.5, 0.9, 1.1, 2.0] {
            let s = (f * n).sqrt();
            let v = crate::perturb::normalised("equilibrium_n12", theta, s, -s);
            sign_wrong += usize::from((v < 0.0) != (f > 1.0));
        }
    }
    let contact = (crate::perturb::discussion_output("curve_n_s2", &[("theta", th_i)])
        - crate::perturb::discussion_output("reality_s2", &[("theta", th_i)]))
    .abs();
    // Normal play: θ ≤ θ_I, s ≤ 1 in the real region: n1 never walks; n2 walks exactly above (N);
    // |D(n2)| < 1/2; the curve D(n1) = +1/2 lies beyond 56,3°.
    let (mut n1_walks, mut n2_wrong, mut max_d2, mut pts) = (0usize, 0usize, 0.0f64, 0usize);
    for k in 1..=83 {
        let theta = (0.5 * k as f64).to_radians();
        if theta > th_i {
            break;
        }
        let n_s = crate::perturb::discussion_output("curve_n_s2", &[("theta", theta)]).sqrt();
        for j in 1..=50 {
            let s = 0.02 * j as f64;
            let Some((n1, n2)) = e_roots(theta, s) else { continue };
            if (s - n_s).abs() < 1e-9 {
                continue;
            }
            pts += 1;
            n1_walks += usize::from(n1.abs() < s);
            n2_wrong += usize::from((n2.abs() < s) != (s > n_s));
            max_d2 = max_d2.max(
                crate::perturb::discussion_output("skid_of_n", &[("theta", theta), ("n", n2)])
                    .abs(),
            );
        }
    }
    let first_d1_half = (0..=880)
        .map(|k| 1.0 + 0.1 * k as f64)
        .find(|&deg| {
            let theta = deg.to_radians();
            crate::perturb::discussion_output("s2_of_d", &[("theta", theta), ("d", 0.5)]) > 0.0
                && theta.tan() > 1.5
        })
        .unwrap_or(f64::NAN);
    // CDHIE: n2 real, stable, walking, for θ < 45° and s ≤ 3.
    let sp = special_points();
    let th_h = sp.h.1.to_radians();
    let (mut region_wrong, mut region_pts) = (0usize, 0usize);
    for k in 1..=89 {
        let theta = (0.5 * k as f64).to_radians();
        let x = theta.cos();
        let upper_s = curve_s_roots(x).map(|(_, hi)| hi.sqrt());
        let n_s = crate::perturb::discussion_output("curve_n_s2", &[("theta", theta)]).sqrt();
        let e_s = crate::perturb::discussion_output("reality_s2", &[("theta", theta)]).sqrt();
        for j in 1..=60 {
            let s = 0.05 * j as f64;
            let boundary = if theta < th_h {
                upper_s.unwrap_or(f64::NAN)
            } else if theta < th_i {
                n_s
            } else {
                e_s
            };
            if (s - boundary).abs() < 1e-6 {
                continue;
            }
            region_pts += 1;
            let inside = s > boundary;
            let acceptable =
                e_roots(theta, s).is_some_and(|(_, n2)| s_of(theta, s, n2) > 0.0 && n2.abs() <= s);
            region_wrong += usize::from(inside != acceptable);
        }
    }
    vec![
        Claim::new(
            "hoop-n-above-e",
            "17",
            "\"La courbe (N) suit la courbe (ℰ), en restant au-dessus. Elle la touche au point I\" (sin θ = 2/3).",
            "θ = 0,5° to 85° by 0,5°: the generated (N) s^2 (curve_n_s2) against the generated (ℰ) s^2; their gap at sin θ = 2/3 and away from it",
            &[("points_below", below as f64), ("gap_at_I", contact), ("min_gap_elsewhere", min_gap)],
            policy::claim(below == 0 && contact < 1e-12 && min_gap > 0.0, Verdict::DerivationDiffers),
            "",
        ),
        Claim::new(
            "hoop-e-minus-s-sign",
            "17",
            "\"E(-s) est négatif pour les points situés au-dessus de la courbe (N) et positif au-dessous.\"",
            "θ = 0,5° to 85° by 0,5°, s^2 at 0,5 to 2 times the (N) s^2: sign of the generated normalised (E) at n = -s",
            &[("points", 680.0), ("sign_disagreements", sign_wrong as f64)],
            policy::claim(sign_wrong == 0, Verdict::DerivationDiffers),
            "",
        ),
        Claim::new(
            "hoop-n2-walking-root",
            "17",
            "Since the used part of the diagram hardly extends beyond I, \"c'est la racine n2, la plus petite en valeur absolue, qui est utilisée dans le jeu normal du cerceau\" (the root that walks, |n| < s).",
            "θ = 0,5° to θ_I by 0,5°, s = 0,02 to 1 (the used part, n° 16): at each real point, whether each root of the generated (E) walks (|n| < s)",
            &[("points", pts as f64), ("points_where_n1_walks", n1_walks as f64), ("points_where_n2_walks_off_the_side_of_N", n2_wrong as f64)],
            policy::claim(n1_walks == 0 && n2_wrong == 0 && pts > 0, Verdict::DerivationDiffers),
            "in the used part n1 always pivots; n2 walks above (N) and pivots between (N) and (ℰ)",
        ),
        Claim::new(
            "hoop-no-skid-normal-play",
            "17",
            "\"Le dérapage, si redouté des cyclistes, n'est pas à craindre dans le jeu normal du cerceau\": the curve D(n1) = +1/2 is outside the useful limits and D(n1) = -1/2 concerns n1 only.",
            "friction coefficient 1/2 (n° 15); the used part θ ≤ θ_I (41,8°), s ≤ 1: the largest |D(n2)| from the generated skid_of_n at the root n2 of the generated (E); the smallest θ of the curve D = +1/2 on the root n1 (where the generated (D'') is real and tan θ > 3/2)",
            &[("points", pts as f64), ("max_abs_D_n2", max_d2), ("first_theta_deg_of_D_n1_half", first_d1_half)],
            policy::claim(max_d2 < 0.5 && first_d1_half > 41.8, Verdict::DerivationDiffers),
            "reading: normal play is the root n2 (hoop-n2-walking-root) in the used part of the diagram; there D(n2) ≤ tan θ_I/2 = 0,447 < 1/2",
        ),
        Claim::new(
            "hoop-n2-acceptable-region",
            "17",
            "\"La solution n2, seule intéressante pour la marche du cerceau, est acceptable toutes les fois que le point (s, θ) est compris dans la région du plan CDHIE\" (fig. 4 bis).",
            "θ = 0,5° to 44,5° by 0,5° (below the skid limit of 45°), s = 0,05 to 3: acceptable when the root n2 of the generated (E) is real, stable (generated (S) > 0) and walks (|n2| ≤ s); CDHIE is above the generated (S) up to H, above (N) from H to I, above (ℰ) beyond",
            &[("points", region_pts as f64), ("disagreements", region_wrong as f64)],
            policy::claim(region_wrong == 0 && region_pts > 0, Verdict::DerivationDiffers),
            "",
        ),
    ]
}

/// n° 17's footnote: for the cyclist the frame's and rider's centrifugal force adds to the
/// wheel's and is much larger, which is why skidding is feared by cyclists and not in hoop play.
fn cyclist_footnote_17() -> Claim {
    cyclist_footnote_for(1.0)
}

/// [`cyclist_footnote_17`] with the rider's mass and moments scaled by `scale` (1 for the
/// n° 36 rider).
fn cyclist_footnote_for(scale: f64) -> Claim {
    use carvallo::unicycle::{Rider, Unicycle, Wheel};
    let (r, g, mu1) = (0.5f64, 9.81f64, 5.0f64);
    // The n° 36 rider (60 kg, centre of gravity at 2.5 R) on a hoop wheel of 5 kg, R = 0.5 m.
    let rider = Rider {
        mass: 60.0 * scale,
        height: 1.25,
        a: 100.0 * scale,
        b: 100.0 * scale,
        c: 0.77 * scale,
        l: 0.0,
    };
    let unicycle = Unicycle::new(r, g, rider, Wheel::hoop(mu1, r)).ok();
    let hoop = carvallo::hoop::Hoop::new(r, mu1, g).ok();
    let unit = (g / r).sqrt();
    // The steady root of smaller |n| of a quadratic (E) read off its evaluator at 0, ±1.
    let slow_root = |e: &dyn Fn(f64) -> f64| {
        let (c, a, b) = (e(0.0), 0.5 * (e(1.0) + e(-1.0)) - e(0.0), 0.5 * (e(1.0) - e(-1.0)));
        let disc = b * b - 4.0 * a * c;
        if !(disc >= 0.0 && a != 0.0) {
            return f64::NAN;
        }
        let q = -0.5 * (b + b.signum() * disc.sqrt());
        let (x, y) = (q / a, c / q);
        if x.abs() < y.abs() {
            x
        } else {
            y
        }
    };
    let (mut min_ratio, mut min_skid_ratio, mut worst_residual) =
        (f64::INFINITY, f64::INFINITY, 0.0f64);
    let mut ev: Vec<(String, f64)> = Vec::new();
    for deg in [5.0f64, 10.0, 20.0] {
        let theta = deg.to_radians();
        let s = 1.5 * unit;
        let (Some(u), Some(h)) = (unicycle.as_ref(), hoop.as_ref()) else { continue };
        let nu = slow_root(&|n| u.equilibrium(theta, s, n));
        let nh = slow_root(&|n| h.equilibrium(theta, s, n));
        worst_residual = worst_residual
            .max(u.equilibrium(theta, s, nu).abs() / (rider.mass * g * rider.height))
            .max(h.equilibrium(theta, s, nh).abs() / (mu1 * g * r));
        // The centrifugal forces at the cyclist's turn: the wheel's (n° 10, its centre at
        // height R) and the rider's (n° 30, his centre at height h).
        let wheel = mu1 * (r * s * nu + r * nu * nu * theta.sin()).abs();
        let man = rider.mass * (r * s * nu + rider.height * nu * nu * theta.sin()).abs();
        let (du, dh) = (u.skid(theta, s, nu), h.skid(theta, s, nh));
        min_ratio = min_ratio.min(man / wheel);
        min_skid_ratio = min_skid_ratio.min(du.abs() / dh.abs());
        ev.push((format!("θ = {deg}°: rider's / wheel's centrifugal force"), man / wheel));
        ev.push((format!("θ = {deg}°: skid tendency D, cyclist (n° 30)"), du));
        ev.push((format!("θ = {deg}°: skid tendency D, hoop alone (n° 10, root n2)"), dh));
        ev.push((format!("θ = {deg}°: turning rate n, cyclist (1/s)"), nu));
        ev.push((format!("θ = {deg}°: turning rate n, hoop alone (1/s)"), nh));
    }
    ev.push(("largest |(E)| at the roots over the weight moment".to_string(), worst_residual));
    let evr: Vec<(&str, f64)> = ev.iter().map(|(a, b)| (a.as_str(), *b)).collect();
    Claim::new(
        "hoop-cyclist-centrifugal-adds",
        "17",
        "Footnote: « pour le cycliste, effectuant une conversion, à la force centrifuge des roues (due à la vitesse n) s'ajoute celle du cadre et du cavalier qui est beaucoup plus grande »: the reason skidding, feared by cyclists, is not to be feared in hoop play.",
        "the mounted unicycle of n° 20-30 (carvallo::unicycle, the n° 36 rider: 60 kg, centre of gravity at h = 2.5 R = 1.25 m, A = B = 100, C = 0.77 kg m², on a hoop wheel of 5 kg, R = 0.5 m, g = 9.81) against the same wheel alone (carvallo::hoop), both in the steady turn of smaller |n| (the root used in play, n2 for the hoop) of their generated (E) at the same lean θ = 5°, 10°, 20° and the same rolling rate s = 1.5 sqrt(g/R): the rider's centrifugal force μ|Rsn + h n² sin θ| over the wheel's μ1|Rsn + R n² sin θ| (n° 10, 30), and the skid tendencies D of n° 30 and n° 10 (generated). Holds if the rider's force is at least 5 times the wheel's and the cyclist's |D| exceeds the hoop's at every θ",
        &evr,
        policy::claim(min_ratio >= 5.0 && min_skid_ratio > 1.0 && worst_residual < 1e-9, Verdict::DerivationDiffers),
        "the rider's centrifugal force is 11 to 12 times the wheel's, and the cyclist's skid tendency is about twice the hoop's at the same lean and speed (0.085, 0.171, 0.353 against 0.044, 0.088, 0.181 at 5°, 10°, 20°). The cause is not the added force as such: D is a ratio to the weight, which the rider adds too; it is that the rider's weight moment about the contact is held in a steady turn by a faster turn (centrifugal force), where the hoop's lean is held mostly by its own spin (the gyroscopic term 4sn/3 of (E)) with a slow n2",
    )
}

fn h_17_bis() -> Vec<Claim> {
    let sp = special_points();
    let (w, th) = (sp.h.0, sp.h.1.to_radians());
    let s = sp.h.2;
    let n2 = e_roots(th, s).map_or(f64::NAN, |r| r.1);
    let cubic = |w: f64| crate::perturb::discussion_output("h_cubic", &[("theta", w.asin())]);
    let mut sign_changes = 0usize;
    let grid: Vec<f64> = (0..=10000).map(|k| k as f64 / 10000.0).collect();
    for pair in grid.windows(2) {
        sign_changes += usize::from(cubic(pair[0]) * cubic(pair[1]) < 0.0);
    }
    // The cubic 3w^3 + 4w^2 - 14w + 4 (check point_h_cubic): the other two roots.
    let others = [-3.24, 1.6];
    let other_roots: Vec<f64> = others
        .iter()
        .filter_map(|&g| {
            bisect(|w| 3.0 * w.powi(3) + 4.0 * w * w - 14.0 * w + 4.0, g - 0.3, g + 0.3)
        })
        .collect();
    vec![
        Claim::new(
            "hoop-h-is-n2",
            "17 bis",
            "At the meeting of (S) and (N) \"la quantité -s se trouve justement être égale à la racine n2\", so their common points solve E(-s) = 0, S(-s) = 0.",
            "at H (root of the generated cubic h_cubic, s from the generated h_s2): the root n2 of the generated (E) against -s, and the generated (S) at -s",
            &[("n2_plus_s", n2 + s), ("S_at_minus_s", s_of(th, s, -s))],
            policy::claim((n2 + s).abs() < 1e-9 && s_of(th, s, -s).abs() < 1e-9, Verdict::DerivationDiffers),
            "",
        ),
        Claim::new(
            "hoop-h-cubic-one-root",
            "17 bis",
            "The cubic in sin θ obtained by eliminating s^2 \"dont une seule racine est comprise entre 0 et 1\".",
            "sign changes of the generated h_cubic on 10001 points of sin θ in [0, 1]; the other two roots of 3w^3 + 4w^2 - 14w + 4 (check point_h_cubic) by bisection",
            &[("sign_changes_in_0_1", sign_changes as f64), ("root_in_0_1", w), ("other_root_1", other_roots.first().copied().unwrap_or(f64::NAN)), ("other_root_2", other_roots.get(1).copied().unwrap_or(f64::NAN))],
            policy::claim(sign_changes == 1 && other_roots.len() == 2 && other_roots.iter().all(|r| !(0.0..=1.0).contains(r)), Verdict::DerivationDiffers),
            "",
        ),
    ]
}

fn practical_18() -> Vec<Claim> {
    // The largest y = s^2 on (S) is 1/4, at D only.
    let sp = special_points();
    let xv = sp.vertical.x;
    let (mut max_y, mut at) = (0.0f64, 0.0f64);
    for k in 0..=2000 {
        let x = xv + (1.0 - xv) * k as f64 / 2000.0;
        if let Some((_, hi)) = curve_s_roots(x.min(1.0)) {
            if hi > max_y {
                max_y = hi;
                at = x;
            }
        }
    }
    // And a few states at s = 0,5 sqrt(g/R) simulated (root n2).
    let hoop = unit_hoop();
    let (mut sim_unstable, mut min_k) = (0usize, f64::INFINITY);
    for deg in [5.0, 10.0, 15.0, 18.0] {
        let theta: f64 = f64::to_radians(deg);
        if let Some((_, n2)) = e_roots(theta, 0.5) {
            min_k = min_k.min(s_of(theta, 0.5, n2));
            sim_unstable +=
                usize::from(perturb(&hoop, (theta, 0.5, n2), 1e-10, 0.005, 120.0).diverged);
        }
    }
    // Threshold speed sR = 0,5 sqrt(gR): bisection on the generated physical (S) for several R.
    let mut ratio_spread = (f64::INFINITY, 0.0f64);
    for r in [0.25, 0.5, 1.0, 2.0] {
        let Ok(h) = carvallo::hoop::Hoop::new(r, 1.0, 9.81) else { continue };
        let s = bisect(|s| crate::perturb::hoop_stability(&h, 0.0, s, 0.0), 0.01, 100.0)
            .unwrap_or(f64::NAN);
        let v = s * r / r.sqrt();
        ratio_spread = (ratio_spread.0.min(v), ratio_spread.1.max(v));
    }
    // Fall from rest: time to go from 0,05 to 0,5 rad grows like sqrt(R).
    let mut fall = Vec::new();
    for r in [0.25, 1.0] {
        let Ok(h) = carvallo::hoop::Hoop::new(r, 1.0, 9.81) else { continue };
        let mut x = [0.05, 0.0, 0.0, 0.0];
        let (mut t, dt) = (0.0, 1e-4);
        while x[0] < 0.5 && t < 20.0 {
            x = carvallo::numerics::ode::rk4_step(|y| h.rhs_pns(y), x, dt);
            t += dt;
        }
        fall.push(t);
    }
    let fall_ratio =
        fall.get(1).copied().unwrap_or(f64::NAN) / fall.first().copied().unwrap_or(f64::NAN);
    vec![
        Claim::new(
            "hoop-practical-threshold",
            "18",
            "\"La condition pour qu'il existe un état d'équilibre stable est ... s / sqrt(g/R) ≥ 0,5\" (the arc DH of (S) taken as the circle s = 0,5).",
            "2001 points of x from the vertical tangent of (S) to 1: the largest y = s^2 on the generated (S) and where; and the root n2 at s = 0,5 at θ = 5°, 10°, 15°, 18° simulated (unit hoop, RK4 step 0,005 over 120 time units, disturbance 1e-10)",
            &[("max_y_on_S", max_y), ("x_of_max", at), ("min_S_at_n2_s_0.5", min_k), ("unstable_runs_at_s_0.5", sim_unstable as f64)],
            policy::claim((max_y - 0.25).abs() < 1e-12 && (at - 1.0).abs() < 1e-12 && min_k > 0.0 && sim_unstable == 0, Verdict::DerivationDiffers),
            "reading: a stable steady state of the walking root n2 (n1 is always stable, n° 14); (S) never rises above y = 1/4, reached only at D, so s ≥ 0,5 is sufficient at every θ and necessary only upright; for 0 < θ < θ_H the exact limit is the arc DH, below 0,5 by up to 6 % (value entry arc DH)",
        ),
        Claim::new(
            "hoop-threshold-grows-sqrt-r",
            "18",
            "By (1), sR ≥ 0,5 sqrt(gR), \"la vitesse limite de stabilité augmente comme la racine carrée du rayon du cerceau\".",
            "the upright straight-rolling threshold s by bisection on the generated physical (S) at θ = 0, n = 0 for R = 0,25; 0,5; 1; 2 m (g = 9,81): the spread of sR / sqrt R",
            &[("min_sR_over_sqrt_R", ratio_spread.0), ("max_sR_over_sqrt_R", ratio_spread.1)],
            policy::claim(rel_diff(ratio_spread.0, ratio_spread.1) < 1e-9 && rel_diff(ratio_spread.0, 0.5 * 9.81f64.sqrt()) < 1e-9, Verdict::DerivationDiffers),
            "sR / sqrt R = 0,5 sqrt g for every R; the memoir then says the law \"ne semble guère vérifiée par la pratique\" (not checkable here)",
        ),
        Claim::new(
            "hoop-fall-slower-for-large-r",
            "18",
            "Reduced to its two first terms the fall equation is θ'' = 2g sin θ/(3R), of the pendulum's form: \"quand R est grand, les vitesses de chute sont lentes et peuvent être corrigées par le jeu de la baguette\".",
            "the generated system (2) at rest (n = s = 0) for R = 0,25 m and 1 m (g = 9,81), RK4 (0,1 ms steps) from θ = 0,05 to 0,5 rad: the ratio of the fall times, sqrt(1/0,25) = 2 for a time scale sqrt(R/g). Holds by construction because at n = s = 0 the generated p' is a coefficient times (g/R) sin θ: whatever the coefficient the fall time scales as sqrt(R/g), so the ratio 2 is dimensional analysis, which no change of a coefficient breaks (the threshold's value is falsified in hoop-threshold-grows-sqrt-r)",
            &[("fall_time_R_0.25_s", fall.first().copied().unwrap_or(f64::NAN)), ("fall_time_R_1_s", fall.get(1).copied().unwrap_or(f64::NAN)), ("ratio", fall_ratio)],
            policy::claim((fall_ratio - 2.0).abs() < 1e-3, Verdict::DerivationDiffers),
            "the time scale of the fall is sqrt(3R/(2g)); the ratio is 2 within the step of the time count",
        ),
    ]
}

/// The first time after the start at which θ turns positive, from RK4 states `states` (θ, θ')
/// at the times `k dt` (k ≥ 1), by the cubic Hermite interpolant of θ through θ and θ' on the
/// step where it changes sign, its root bisected: a resolution far finer than the step.
fn reversal_time(states: &[(f64, f64)], dt: f64) -> f64 {
    let Some(i) = states.windows(2).position(|w| w[0].0 <= 0.0 && w[1].0 > 0.0) else {
        return f64::NAN;
    };
    let ((y0, d0), (y1, d1)) = (states[i], states[i + 1]);
    let hermite = |u: f64| {
        let (u2, u3) = (u * u, u * u * u);
        (2.0 * u3 - 3.0 * u2 + 1.0) * y0
            + (u3 - 2.0 * u2 + u) * dt * d0
            + (-2.0 * u3 + 3.0 * u2) * y1
            + (u3 - u2) * dt * d1
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if hermite(mid) <= 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (i as f64 + 1.0 + 0.5 * (lo + hi)) * dt
}

/// n° 19's neglected term n² sin θ cos θ, added to θ'' with the sign `term_sign` (1 as
/// derived; -1 is the perturbation that must break the check).
fn neglected_term_check(term_sign: f64) -> Claim {
    let (r, g) = (0.5_f64, 9.81_f64);
    let s = 2.0 * (g / r).sqrt();
    let h = (2.0 / 3.0 * (4.0 * s * s - g / r)).sqrt();
    let steps = 600;
    let dt = 6.0 / h / steps as f64;
    // The generated linearised equations of n° 19 with and without the term n^2 sin θ cos θ:
    // the states (θ, θ') after each step.
    let run = |m: f64, m1: f64, with_term: bool| {
        let rhs = |x: [f64; 3]| {
            let v = hd::eval(&[
                ("R", r),
                ("g", g),
                ("s", s),
                ("M", m),
                ("M1", m1),
                ("theta", x[0]),
                ("p", x[1]),
                ("n", x[2]),
            ]);
            let extra =
                if with_term { term_sign * x[2] * x[2] * x[0].sin() * x[0].cos() } else { 0.0 };
            [x[1], v["stick_dp"] + extra, v["stick_dn"]]
        };
        let mut x = [0.0; 3];
        let mut out = Vec::with_capacity(steps);
        for _ in 0..steps {
            x = carvallo::numerics::ode::rk4_step(rhs, x, dt);
            out.push((x[0], x[1]));
        }
        out
    };
    let (mut sign_changes, mut not_larger, mut cases) = (0usize, 0usize, 0usize);
    let mut front = (0usize, f64::NAN, 0usize);
    // Moments in 1/s^2, large enough for the cubic term to show (θ reaches a few tenths).
    for (m, m1, keeps_sign) in [(-20.0, -20.0, true), (-20.0, 0.0, true), (-20.0, 80.0, false)] {
        let (without, with) = (run(m, m1, false), run(m, m1, true));
        let mut reduced = 0usize;
        let mut opposite = 0usize;
        for ((a, _), (b, _)) in without.iter().zip(&with) {
            if a.abs() < 1e-12 {
                continue;
            }
            opposite += usize::from(a.signum() != b.signum());
            reduced += usize::from(b.abs() < a.abs() * (1.0 - 1e-12));
        }
        if keeps_sign {
            cases += without.len();
            sign_changes += opposite;
            not_larger += reduced;
        } else {
            // The front push turns θ from - to +; the term, with the sign of θ, delays that
            // reversal. The delay, in units 1/h, from the interpolated crossings (not from the
            // steps: a step of 0.01/h is coarser than the delay).
            let delay = (reversal_time(&with, dt) - reversal_time(&without, dt)) * h;
            front = (reduced, delay, opposite);
        }
    }
    let holds = cases > 0 && sign_changes == 0 && not_larger == 0 && front.1 > 0.0;
    Claim::new(
        "hoop-stick-neglected-term",
        "19",
        "\"Quant au terme négligé n^2 sin θ cos θ, outre qu'il est du troisième ordre, il a le signe de θ. Il ne fait donc qu'exagérer la vitesse de variation de θ, mais sans changer son signe.\"",
        "R = 0,5 m, g = 9,81, s = 2 sqrt(g/R), constant stick moments of the three cases of n° 19 (back push M = M1 = -20; top M = -20, M1 = 0; front M = -20, M1 = 80, in 1/s^2): the generated linearised equations (stick_dp, stick_dn) integrated by RK4 (600 steps up to t = 6/h) without and with the term n^2 sin θ cos θ added to θ''. Where θ keeps its sign (back, top) the two θ compared at every step: the term must never change the sign nor reduce |θ|. In the front push, where θ turns from - to +, the crossing times of both runs found between the steps (cubic Hermite interpolation of θ, θ' on the step of the crossing, bisected): the term must delay the reversal (push θ on in its current direction); during the delay the two θ have opposite signs, which a comparison at the steps (0.01/h apart) does not see",
        &[
            ("back_and_top_steps_compared", cases as f64),
            ("back_and_top_sign_changes", sign_changes as f64),
            ("back_and_top_steps_where_the_term_reduces_theta", not_larger as f64),
            ("front_steps_where_the_term_reduces_theta", front.0 as f64),
            ("front_steps_with_opposite_signs", front.2 as f64),
            ("front_reversal_delay_h_t", front.1),
        ],
        policy::claim(holds, Verdict::DerivationDiffers),
        &format!("where θ keeps its sign (push at the back, at the top) the term only increases |θ| and never changes its sign; in the front push, where the M1 term turns θ from - to +, the term (with the sign of θ) delays that reversal by {:.2e}/h, far less than a step (0.01/h), so no step sees the two θ of opposite signs, but during that delay they are: the term changes the sign of θ there for {:.2e}/h, and |θ| is smaller for {} steps after it. \"sans changer son signe\" holds as \"exagérer\": the term pushes θ on in its current direction, and delays, never advances, a reversal", front.1, front.1, front.0),
    )
}

fn neglected_term() -> Claim {
    neglected_term_check(1.0).falsified_by(
        "the neglected term's sign flipped (-n^2 sin θ cos θ added to θ'')",
        neglected_term_check(-1.0),
    )
}

/// n° 18: « la masse du cerceau étant plus grande, les causes perturbatrices ont moins
/// d'influence sur lui », with n° 19's disturbing moments.
fn heavier_hoop_18() -> Claim {
    let (r, g) = (0.5_f64, 9.81_f64);
    let s = 2.0 * (g / r).sqrt();
    let h = (2.0 / 3.0 * (4.0 * s * s - g / r)).sqrt();
    let time = 1.0 / h;
    // A push of 1 N at the back of the rim, on the right cheek: moments -F R about OI and OK,
    // divided by the hoop's moments of inertia A and C at the contact, as n° 19's (2) are the
    // equations (1) of n° 7 divided by the moments of inertia.
    let response = |mass: f64, linear: bool| {
        let Ok(hoop) = carvallo::hoop::Hoop::new(r, mass, g) else { return (f64::NAN, f64::NAN) };
        let [a, _, c] = hoop.inertia();
        let (m, m1) = (-r / a, -r / c);
        if linear {
            hd::stick_theta_n(r, g, s, m, m1, time)
        } else {
            hd::stick_linearised_rk4(r, g, s, (m, m1), time, 2000, false)
        }
    };
    let (th1, n1) = response(1.0, true);
    let (th2, n2) = response(2.0, true);
    let (f1, fn1) = response(1.0, false);
    let (f2, fn2) = response(2.0, false);
    let lin = (th2 / th1, n2 / n1);
    let full = (f2 / f1, fn2 / fn1);
    Claim::new(
        "hoop-heavier-less-disturbed",
        "18",
        "« Ajoutons que la masse du cerceau étant plus grande, les causes perturbatrices ont moins d'influence sur lui. »",
        "n° 19's disturbing moments: a push of 1 N at the back of the rim (right cheek) gives the moments -F R about OI and OK, which enter n° 19's (2) divided by the hoop's moments of inertia A = 3/2 μ R² and C = 1/2 μ R² (carvallo::hoop::Hoop::inertia); R = 0.5 m, g = 9.81, s = 2 sqrt(g/R), from rest upright, at t = 1/h: the lean θ and turning rate n for μ = 1 and 2 kg, by n° 19's closed forms (6)-(7) (generated stick_theta, stick_n) and by the full equations (2) with s held (generated stick_full_dp, stick_full_dn, RK4, 2000 steps). Holds if doubling the mass halves the response: the ratio 1/2 within 1e-12 for the linear forms, within 1e-3 for the full equations (a response of a few thousandths of a radian: the nonlinear terms are of the relative order θ², about 1e-5). Holds by construction because the hoop's moments of inertia carry its mass as a factor (A = 3/2 μ R², C = 1/2 μ R²) and the push enters n° 19's equations only as F R/A and F R/C, while the equations' own coefficients do not contain μ: no change of a coefficient of the generated programs moves the ratio from 1/2 (beyond the full equations' θ² terms); only inertias not proportional to the mass would",
        &[
            ("θ(2 kg) / θ(1 kg), closed forms", lin.0),
            ("n(2 kg) / n(1 kg), closed forms", lin.1),
            ("θ(2 kg) / θ(1 kg), full equations", full.0),
            ("n(2 kg) / n(1 kg), full equations", full.1),
            ("θ(1 kg) at t = 1/h, full equations (rad)", f1),
        ],
        policy::claim(
            (lin.0 - 0.5).abs() < 1e-12
                && (lin.1 - 0.5).abs() < 1e-12
                && (full.0 - 0.5).abs() < 1e-3
                && (full.1 - 0.5).abs() < 1e-3,
            Verdict::DerivationDiffers,
        ),
        "for a disturbing force (a push, a shock on the rim) the response is inversely proportional to the mass: the force's moment is divided by moments of inertia proportional to μ, while the hoop's own equations do not contain μ. Disturbances that scale with the mass (a slope, a bump acting through the weight) are not reduced; a claim that the mass does not matter would give the ratio 1",
    )
}

/// The assertions of n° 13–19.
pub(super) const INVENTORY: &[Assertion] = &[
    Assertion { section: "13", says: "the curve AE is a branch of hyperbola from A with the asymptote Oy", status: Status::Checked("hoop-reality-curve-shape") },
    Assertion { section: "13", says: "left of AE (E) is impossible; right of it two real roots", status: Status::Checked("hoop-reality-sides") },
    Assertion { section: "13", says: "(ℰ) can be solved easily for s² or for cos θ", status: Status::Left("a remark on the algebra, nothing to check") },
    Assertion { section: "14", says: "along AE the double root satisfies (S)", status: Status::Checked("hoop-stable-along-ae") },
    Assertion { section: "14", says: "on AC the roots are -∞ and 0; the first makes S positive", status: Status::Checked("hoop-roots-on-ac") },
    Assertion { section: "14", says: "on AC n2 is stable only above D, s² > 1/4", status: Status::Checked("hoop-upright-threshold") },
    Assertion { section: "14", says: "the curve (S) from A to D separates EAC: only n1 stable inside (containing AD), both stable outside (containing AE and DC)", status: Status::Checked("hoop-which-root-stable") },
    Assertion { section: "14", says: "(S) is the resultant of E(n) and S(n)", status: Status::Value("(S) resultant of E(n), S(n)") },
    Assertion { section: "14", says: "(S) is confined in the triangle AFD", status: Status::Checked("hoop-s-in-triangle-afd") },
    Assertion { section: "14", says: "at A (S) is tangent to (ℰ)", status: Status::Value("check tangent_a_reality") },
    Assertion { section: "14", says: "at D the tangent of (S) is horizontal", status: Status::Value("tangent of (S) at D: slope") },
    Assertion { section: "14", says: "F(t) has a root in (0, 1) (F(0) < 0 < F(1)), between 0,8 and 1", status: Status::Checked("hoop-quartic-root-bracket") },
    Assertion { section: "14", says: "the Horner tableau gives 28u⁴ + 68u³ + 51u² + 14u + 1", status: Status::Checked("hoop-horner-tableau-cells") },
    Assertion { section: "14", says: "the equation in u has no positive root (no sign variation)", status: Status::Checked("hoop-u-no-positive-root") },
    Assertion { section: "14", says: "the smallest negative root is the one sought; u = 1/v, v of largest modulus", status: Status::Checked("hoop-u-smallest-root") },
    Assertion { section: "14", says: "the root-squaring table and logarithms as printed, made with a slide rule", status: Status::Checked("hoop-graeffe-table-cells") },
    Assertion { section: "14", says: "after two squarings the largest root is visibly separated", status: Status::Checked("hoop-graeffe-separated") },
    Assertion { section: "14", says: "the verification tableau by substitution, residual +0,0004", status: Status::Checked("hoop-verification-tableau-cells") },
    Assertion { section: "14", says: "u = -0,10807 satisfies the equation with a relative error below half a thousandth", status: Status::Checked("hoop-root-squaring-half-thousandth") },
    Assertion { section: "14", says: "the minute of the calculation is reproduced faithfully, every figure, made with a slide rule", status: Status::Left("a statement about the manuscript; its content is the tables, checked cell by cell (hoop-graeffe-table-cells)") },
    Assertion { section: "14", says: "at the vertical tangent the two values of y are equal to the square root of their product 0,0430", status: Status::Value("vertical tangent: product of the y roots") },
    Assertion { section: "15", says: "n0 gives the minimum of s; n < n0 is the root n1, the others n2; (ℰ) is the curve of the minima", status: Status::Checked("hoop-n0-separates-roots") },
    Assertion { section: "15", says: "the table of variations of s and D", status: Status::Checked("hoop-variation-table") },
    Assertion { section: "15", says: "the curve D = 1/2: no point below 45°, root n2 from 45° to 56,3°, root n1 beyond", status: Status::Checked("hoop-d-half-three-cases") },
    Assertion { section: "15", says: "H (n0, s0) is the contact of D = 1/2 with (ℰ), the curve of minima and of reality", status: Status::Checked("hoop-d-half-touches-e") },
    Assertion { section: "15", says: "(D'') is less suited to telling the roots apart", status: Status::Left("a remark on method") },
    Assertion { section: "15", says: "with friction 1/2 the curve D = -1/2 belongs wholly to n1", status: Status::Checked("hoop-d-minus-half-n1") },
    Assertion { section: "16", says: "n2 resists skidding only left of D(n2) = 1/2", status: Status::Checked("hoop-n2-skid-left") },
    Assertion { section: "16", says: "the region where n1 resists skidding", status: Status::Checked("hoop-n1-skid-region") },
    Assertion { section: "16", says: "the figure is the complete summary of the discussion", status: Status::Left("about the figure") },
    Assertion { section: "16", says: "the used part of the diagram hardly leaves the circle s = 1 (pas gymnastique 2,27 m/s)", status: Status::Value("pas gymnastique 2,27 m/s vs circle s = 1") },
    Assertion { section: "17", says: "the distinction walk/pivot is somewhat arbitrary; the hoop walks when ρ > R", status: Status::Left("a definition") },
    Assertion { section: "17", says: "ρ = Rs/n, so walking is |n| < s", status: Status::Left("algebra of the definition with ρ of n° 8 (checked there, hoop-trajectory-radius)") },
    Assertion { section: "17", says: "(N) follows (ℰ) above it and touches it at I", status: Status::Checked("hoop-n-above-e") },
    Assertion { section: "17", says: "E(-s) is negative above (N), positive below", status: Status::Checked("hoop-e-minus-s-sign") },
    Assertion { section: "17", says: "above (N): -n2 < s < -n1", status: Status::Value("marche/pivot: above (N)") },
    Assertion { section: "17", says: "between (N) and (ℰ) from O to I: s < -n2 < -n1 (printed s < n2)", status: Status::Value("marche/pivot: (N)-(ℰ), O to I") },
    Assertion { section: "17", says: "between (N) and (ℰ) beyond I: -n2 < -n1 < s", status: Status::Value("marche/pivot: (N)-(ℰ), beyond I") },
    Assertion { section: "17", says: "n2 is the root used in normal play", status: Status::Checked("hoop-n2-walking-root") },
    Assertion { section: "17", says: "D(n1) = ±1/2 useless or outside the useful limits: skidding is not to be feared in normal hoop play", status: Status::Checked("hoop-no-skid-normal-play") },
    Assertion { section: "17", says: "footnote: for the cyclist the centrifugal force of frame and rider adds to the wheels'", status: Status::Checked("hoop-cyclist-centrifugal-adds") },
    Assertion { section: "17", says: "n2 is stable only outside (S)", status: Status::Left("restates n° 14 (hoop-which-root-stable)") },
    Assertion { section: "17", says: "n2 is acceptable whenever (s, θ) is in CDHIE", status: Status::Checked("hoop-n2-acceptable-region") },
    Assertion { section: "17 bis", says: "(N) enters (S) at H; -s is the root n2 there, so E(-s) = S(-s) = 0", status: Status::Checked("hoop-h-is-n2") },
    Assertion { section: "17 bis", says: "the cubic in sin θ has a single root between 0 and 1", status: Status::Checked("hoop-h-cubic-one-root") },
    Assertion { section: "17 bis", says: "the cubic was solved by the method of n° 14; the curves n2 = -0,1, -0,3, -0,5 added to fig. 4 bis", status: Status::Left("about the working and the figure") },
    Assertion { section: "18", says: "the arc DH may be roughly taken as the circle of radius 0,5", status: Status::Value("arc DH of (S) ~ circle s = 0,5") },
    Assertion { section: "18", says: "a stable steady state exists for s/sqrt(g/R) ≥ 0,5", status: Status::Checked("hoop-practical-threshold") },
    Assertion { section: "18", says: "sR ≥ 1,20 m/s for R = 0,50 m, a little below the pas accéléré 1,50 m/s", status: Status::Value("pas accéléré 1,50 m/s vs threshold sR") },
    Assertion { section: "18", says: "the theoretical condition is only an indication (wind, ground, skill)", status: Status::Left("practical remark, outside the model") },
    Assertion { section: "18", says: "the limit speed grows as the square root of the hoop's radius", status: Status::Checked("hoop-threshold-grows-sqrt-r") },
    Assertion { section: "18", says: "that law hardly agrees with practice: theoretical and practical stability differ", status: Status::Left("an observation of play, not checkable in the model") },
    Assertion { section: "18", says: "the needle and the cane: a long pendulum falls slowly", status: Status::Left("an analogy outside the hoop model") },
    Assertion { section: "18", says: "the fall equation reduced to its first terms is a pendulum's; for large R the fall is slow", status: Status::Checked("hoop-fall-slower-for-large-r") },
    Assertion { section: "18", says: "a heavier hoop is less influenced by disturbances", status: Status::Checked("hoop-heavier-less-disturbed") },
    Assertion { section: "19", says: "observed: a push at the back or at the top leans and turns the hoop left, a push at the front right", status: Status::Left("an observation of play; its explanation is checked by the sign entries of n° 19") },
    Assertion { section: "19", says: "the rotation about the horizontal OI seems natural for the push at the back or the top, paradoxical for the front push; the rotation about the vertical OK is paradoxical in every case", status: Status::Left("a judgement on the player's intuition, not a property of the motion; the motion it qualifies is checked: the lean's sign in the three cases and n of the sign opposite to θ in all three (value entries `sign of th and n` and `n opposite to th`), i.e. the hoop always turns toward its lean, whatever side the stick pushes") },
    Assertion { section: "19", says: "footnote: s varies only by a small fraction (experience)", status: Status::Left("an observation; the model of n° 19 holds s constant") },
    Assertion { section: "19", says: "the coefficient of θ in (4) is negative by the stability condition", status: Status::Left("algebra: -(2/3)(4s² - g/R) < 0 is s² > g/(4R), the upright threshold of n° 14 (hoop-upright-threshold)") },
    Assertion { section: "19", says: "back push (M < 0, M1 < 0): θ < 0, the hoop leans left", status: Status::Value("sign of th and n: back push") },
    Assertion { section: "19", says: "push at the top: θ has the sign of M, leans left", status: Status::Value("sign of th and n: push at the top") },
    Assertion { section: "19", says: "a front push: the M1 term, growing with t, soon gives θ its sign +: leans right", status: Status::Value("sign of th and n: front push") },
    Assertion { section: "19", says: "n takes in the three cases the sign opposite to θ", status: Status::Value("n opposite to th") },
    Assertion { section: "19", says: "the neglected term n² sin θ cos θ only exaggerates the variation of θ without changing its sign", status: Status::Checked("hoop-stick-neglected-term") },
    Assertion { section: "19", says: "with some skill the player can approach a steady regime in the turn", status: Status::Left("a remark on play") },
];
