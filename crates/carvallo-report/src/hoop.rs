//! The memoir concordance: every formula and number the memoir prints about the hoop, set
//! beside the value this workspace derives for it, with a verdict.
//!
//! Nothing here is a stored result. [`hoop_entries`] evaluates the generated evaluators (the
//! scenes of [`carvallo::hoop`], built at compile time from `generated/hoop.ir`) when it runs:
//! each derived formula is compared with the memoir's printed formula, transcribed by hand in the
//! same IR program as a `memoir_*` output, at a fixed seeded set of sample points; the numbers
//! of n° 4 and the straight-rolling stability threshold of n° 14/18 are recomputed from the
//! generated evaluators; the remarkable points of the stability discussion (n° 14 point F and
//! the vertical tangent of the curve (S), n° 17 bis point H) are recomputed by root finding on
//! the generated normalised (E) and (S); and the symbolic checks recorded by `cargo xtask
//! regen` in `generated/hoop.checks.tsv` are folded in.
//!
//! The verdicts follow the one policy of [`crate::policy`].

mod claims;

use std::collections::BTreeMap;

use carvallo::hoop_discussion::bisect;

use crate::checks::{self, parse_checks, Finding, SymbolicCheck};
use crate::entry::{section_key, Derived, Entry, Memoir, Verdict};
use crate::policy::{self, number_entry, rel_diff, Expect, AGREEMENT_TOLERANCE, REL_DIFF_FLOOR};
use crate::render::text::format_significant;
use crate::sample::Rng;

carvallo::scene! {
    /// Every output of `generated/hoop.ir`, derived and transcribed (`memoir_*`), with every
    /// parameter and input free: the report looks outputs up by name in `OUTPUTS`.
    pub(crate) mod concordance_scene {
        model: hoop,
    }
}

/// Number of seeded sample points at which formulas are compared.
pub const SAMPLE_POINTS: usize = 64;

/// Seed of the sample points (any fixed value; the report must not depend on it).
pub const SAMPLE_SEED: u64 = 0x1897_0C0A_4A11_0001;

/// One sample point: values for every parameter and input of the hoop model, by name.
fn sample_points() -> Vec<BTreeMap<&'static str, f64>> {
    let mut rng = Rng(SAMPLE_SEED);
    (0..SAMPLE_POINTS)
        .map(|_| {
            // Physically meaningful domain: hoop radius 0.2–1 m, mass 0.1–5 kg, gravity 1–25
            // m/s²; lean 0.05 ≤ |θ| ≤ 1.3 rad (away from the upright division by sin θ of n° 12
            // and from the horizontal hoop at π/2); rates up to 3 √(g/R) in magnitude.
            let radius = rng.uniform(0.2, 1.0);
            let g = rng.uniform(1.0, 25.0);
            let mass = rng.uniform(0.1, 5.0);
            let sign = if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
            let theta = sign * rng.uniform(0.05, 1.3);
            let nu = (g / radius).sqrt();
            let mut point =
                BTreeMap::from([("R", radius), ("g", g), ("mu", mass), ("theta", theta)]);
            for name in ["p", "q", "r", "n", "s"] {
                point.insert(name, nu * rng.uniform(-3.0, 3.0));
            }
            point
        })
        .collect()
}

/// All outputs of the hoop program at one sample point, by output name. Rates are rescaled to
/// the unit of n° 12 for the normalised (`_n12`) outputs by the caller, not here.
fn eval_all(point: &BTreeMap<&str, f64>) -> BTreeMap<&'static str, f64> {
    use concordance_scene as scene;
    let args = scene::Args::from_fn(|name| point.get(name).copied().unwrap_or(f64::NAN));
    let mut values: BTreeMap<&'static str, f64> =
        scene::OUTPUTS.iter().copied().zip(scene::eval(&args).to_array()).collect();
    crate::perturb::overlay("hoop", |name| point.get(name).copied(), &mut values);
    values
}

/// What the memoir prints for each derived output that has a `memoir_*` transcription:
/// (output, section, quantity, printed formula as text).
const PRINTED: &[(&str, &str, &str, &str)] = &[
    ("inertia_a", "4", "A (kg m^2)", "A = 3 mu R^2 / 2"),
    ("inertia_b", "4", "B (kg m^2)", "B = 2 mu R^2"),
    ("inertia_c", "4", "C (kg m^2)", "C = mu R^2 / 2"),
    ("pqr_dp", "7/8", "p' of system (1)", "p' = 2g sin(th)/(3R) + 4qr/3 - r^2 tan(th)/3"),
    ("pqr_dq", "7/8", "q' of system (1)", "q' = -pr/2"),
    ("pqr_dr", "7/8", "r' of system (1)", "r' = pr tan(th) - 2pq"),
    (
        "pns_dp",
        "7",
        "p' of system (2)",
        "3/2 p' - 2sn cos(th) - 3/2 n^2 sin(th) cos(th) = g sin(th)/R",
    ),
    ("pns_dn", "7", "n' of system (2)", "1/2 n' + ps/cos(th) = 0"),
    ("pns_ds", "7", "s' of system (2)", "2s' - 4ps tan(th) + 3pn cos(th) = 0"),
    ("energy", "7", "energy T + V (J)", "mu R^2 (3/4 p^2 + q^2 + 1/4 r^2) + mu g R cos(th)"),
    (
        "equilibrium",
        "8",
        "(E) p' at p = 0",
        "2g sin(th)/(3R) + 4sn cos(th)/3 + n^2 sin(th) cos(th)",
    ),
    ("stability", "9", "(S) stability", "-2g cos(th)/(3R) + n^2 + 8sn sin(th)/3 + 8s^2/3"),
    ("skid", "10", "(D) skid tendency", "-(R/g)(n^2 sin(th) + sn)"),
    (
        "equilibrium_direct",
        "11",
        "sum of moments about OI / (mu R^2)",
        "g sin(th)/R + 2sn cos(th) + 3/2 n^2 sin(th) cos(th)",
    ),
    ("equilibrium_n12", "12", "(E) normalised", "n^2 + 4s n/(3 sin(th)) + 2/(3 cos(th))"),
    ("stability_n12", "12", "(S) normalised", "n^2 + 8s sin(th) n/3 + 8s^2/3 - 2 cos(th)/3"),
    ("skid_n12", "12", "(D) normalised", "-n^2 sin(th) - sn"),
];

/// Values of a formula at the sample points, for derived and memoir forms.
struct Comparison {
    max_rel: f64,
    max_abs: f64,
    worst: usize,
    /// derived / memoir at every point where both are away from zero.
    ratios: Vec<f64>,
}

fn compare(derived: &[f64], memoir: &[f64]) -> Comparison {
    let mut cmp = Comparison { max_rel: 0.0, max_abs: 0.0, worst: 0, ratios: Vec::new() };
    for (i, (&d, &m)) in derived.iter().zip(memoir).enumerate() {
        let rel = rel_diff(d, m);
        // A NaN difference (one side undefined) counts as the worst possible.
        if rel > cmp.max_rel || rel.is_nan() && !cmp.max_rel.is_nan() {
            cmp.max_rel = rel;
            cmp.worst = i;
        }
        cmp.max_abs = cmp.max_abs.max((d - m).abs());
        if d.abs() > REL_DIFF_FLOOR && m.abs() > REL_DIFF_FLOOR {
            cmp.ratios.push(d / m);
        }
    }
    cmp
}

/// Describes the worst point and, if derived/memoir is the same number everywhere, that
/// constant factor.
fn describe_difference(
    cmp: &Comparison,
    point: &BTreeMap<&str, f64>,
    inputs: &[&str],
    d: f64,
    m: f64,
) -> String {
    let at: Vec<String> =
        inputs.iter().map(|k| format!("{k}={}", format_significant(point[k], 4))).collect();
    let mut note = format!(
        "largest difference at {}: derived {}, memoir {}",
        at.join(", "),
        format_significant(d, 8),
        format_significant(m, 8)
    );
    if let (Some(lo), Some(hi)) =
        (cmp.ratios.iter().copied().reduce(f64::min), cmp.ratios.iter().copied().reduce(f64::max))
    {
        if cmp.ratios.len() == SAMPLE_POINTS && (hi - lo).abs() <= 1e-9 * hi.abs() {
            note.push_str(&format!(
                "; derived = {} x memoir at every point",
                format_significant(0.5 * (lo + hi), 10)
            ));
        }
    }
    note
}

/// The inputs an output depends on, for describing points; from the one-output programs'
/// argument lists would be exact, but the memoir's variables are few enough to list by section.
fn inputs_of(output: &str) -> &'static [&'static str] {
    match output {
        o if o.starts_with("pqr_") => &["theta", "p", "q", "r", "R", "g"],
        o if o.starts_with("pns_") => &["theta", "p", "n", "s", "R", "g"],
        "energy" => &["theta", "p", "n", "s", "R", "g", "mu"],
        o if o.starts_with("inertia_") => &["R", "mu"],
        o if o.ends_with("_n12") => &["theta", "s", "n"],
        _ => &["theta", "s", "n", "R", "g"],
    }
}

/// The sample point with rates expressed in the unit $\sqrt{g/R}$ of n° 12, at which the
/// `_n12` outputs are evaluated (they do not use $R$ and $g$).
fn normalised_point(point: &BTreeMap<&'static str, f64>) -> BTreeMap<&'static str, f64> {
    let nu = (point["g"] / point["R"]).sqrt();
    let mut out = point.clone();
    for name in ["p", "q", "r", "n", "s"] {
        out.insert(name, point[name] / nu);
    }
    out
}

/// Formula entries: each derived output against its `memoir_*` transcription.
fn formula_entries(
    points: &[BTreeMap<&'static str, f64>],
    values: &[BTreeMap<&'static str, f64>],
    values_n12: &[BTreeMap<&'static str, f64>],
) -> Vec<Entry> {
    let outputs = &values[0];
    let mut names: Vec<(&str, &str, &str, &str)> =
        PRINTED.iter().copied().filter(|(name, ..)| outputs.contains_key(*name)).collect();
    // Transcriptions this table does not know yet still get an entry.
    for key in outputs.keys() {
        if let Some(base) = key.strip_prefix("memoir_") {
            if outputs.contains_key(base) && !names.iter().any(|(n, ..)| *n == base) {
                names.push((base, "?", base, "(see generated/hoop.md)"));
            }
        }
    }
    let mut entries = Vec::new();
    for (name, section, quantity, printed) in names {
        let memoir_name = format!("memoir_{name}");
        let Some(memoir_key) = outputs.keys().find(|k| **k == memoir_name) else {
            continue;
        };
        let table = if name.ends_with("_n12") { values_n12 } else { values };
        let pts: Vec<BTreeMap<&str, f64>> = if name.ends_with("_n12") {
            points.iter().map(normalised_point).collect()
        } else {
            points.to_vec()
        };
        let derived: Vec<f64> = table.iter().map(|v| v[name]).collect();
        let memoir: Vec<f64> = table.iter().map(|v| v[memoir_key]).collect();
        let cmp = compare(&derived, &memoir);
        let agrees = policy::formula(cmp.max_rel, Verdict::DerivationDiffers) == Verdict::Agrees;
        let mut note = format!(
            "generated `{name}` vs transcribed `{memoir_name}` at {SAMPLE_POINTS} seeded points"
        );
        if name.ends_with("_n12") {
            note.push_str(" (rates in units of sqrt(g/R))");
        }
        if !agrees {
            note.push_str("; ");
            note.push_str(&describe_difference(
                &cmp,
                &pts[cmp.worst],
                inputs_of(name),
                derived[cmp.worst],
                memoir[cmp.worst],
            ));
        }
        entries.push(Entry {
            falsification: None,
            section: section.to_string(),
            quantity: quantity.to_string(),
            memoir: Memoir::Formula(printed.to_string()),
            derived: Derived::Numbers(BTreeMap::from([
                ("points".to_string(), SAMPLE_POINTS as f64),
                ("max_abs_diff".to_string(), cmp.max_abs),
            ])),
            rel_diff: Some(cmp.max_rel),
            verdict: policy::formula(cmp.max_rel, Verdict::DerivationDiffers),
            note,
        });
    }
    entries
}

/// n° 4: $A$, $B$, $C$ as coefficients of $\mu R^2$ (printed $3/2$, $2$, $1/2$).
fn inertia_entries(
    points: &[BTreeMap<&'static str, f64>],
    values: &[BTreeMap<&'static str, f64>],
) -> Vec<Entry> {
    let unit = eval_all(&BTreeMap::from([
        ("R", 1.0),
        ("mu", 1.0),
        ("g", 1.0),
        ("theta", 0.1),
        ("p", 0.0),
        ("q", 0.0),
        ("r", 0.0),
        ("n", 0.0),
        ("s", 0.0),
    ]));
    [("inertia_a", "A / (mu R^2)", 1.5), ("inertia_b", "B / (mu R^2)", 2.0), ("inertia_c", "C / (mu R^2)", 0.5)]
        .into_iter()
        .filter(|(name, ..)| unit.contains_key(*name))
        .map(|(name, quantity, printed)| {
            let spread = points
                .iter()
                .zip(values)
                .map(|(pt, v)| rel_diff(v[name] / (pt["mu"] * pt["R"] * pt["R"]), printed))
                .fold(0.0, f64::max);
            let mut entry = number_entry(
                "4",
                quantity,
                printed,
                unit[name],
                Verdict::DerivationDiffers,
                format!(
                    "generated `{name}` at mu = R = 1; at the {SAMPLE_POINTS} sample points {name} / (mu R^2) differs from {printed} by at most {spread:.1e} (relative)"
                ),
            );
            if policy::formula(spread, Verdict::DerivationDiffers) != Verdict::Agrees {
                entry.verdict = Verdict::DerivationDiffers;
            }
            entry
        })
        .collect()
}

/// n° 14/18: the upright straight-rolling threshold, from the generated normalised stability.
fn threshold_entries() -> Vec<Entry> {
    let stability_n12 = |s: f64| {
        eval_all(&BTreeMap::from([
            ("R", 1.0),
            ("g", 1.0),
            ("mu", 1.0),
            ("theta", 0.0),
            ("p", 0.0),
            ("q", 0.0),
            ("r", 0.0),
            ("n", 0.0),
            ("s", s),
        ]))
        .get("stability_n12")
        .copied()
        .unwrap_or(f64::NAN)
    };
    let Some(s) = bisect(stability_n12, 0.0, 2.0) else {
        return vec![Entry {
            falsification: None,
            section: "14/18".into(),
            quantity: "upright threshold s^2 (units g/R)".into(),
            memoir: Memoir::Number(0.25),
            derived: Derived::Numbers(BTreeMap::from([
                ("stability_n12(s=0)".to_string(), stability_n12(0.0)),
                ("stability_n12(s=2)".to_string(), stability_n12(2.0)),
            ])),
            rel_diff: None,
            verdict: policy::finding(Verdict::DerivationDiffers),
            note: "the generated stability_n12(theta=0, s, n=0) has no sign change for 0 <= s <= 2"
                .into(),
        }];
    };
    let s2 = s * s;
    let anchor =
        if rel_diff(s2, 0.25) <= AGREEMENT_TOLERANCE { "agrees with" } else { "differs from" };
    // n° 16 and 18 also print the physical speeds for R = 0.50 m (g = 9.81 m/s^2 assumed).
    let (radius, g) = (0.5_f64, 9.81_f64);
    let unit_speed = (g * radius).sqrt();
    vec![
        number_entry(
            "14/18",
            "upright threshold s^2 (units g/R)",
            0.25,
            s2,
            Verdict::DerivationDiffers,
            format!(
                "bisection on the generated stability_n12(theta=0, s, n=0) = 0; {anchor} the classical thin-hoop anchor v^2 > g a / 4 (Routh; Encyclopaedia Britannica 1911, Gyroscope, eq. 23), v^2/(g R) = s^2 in the units of n° 12"
            ),
        ),
        number_entry(
            "18",
            "upright threshold s (units sqrt(g/R))",
            0.5,
            s,
            Verdict::DerivationDiffers,
            "printed s / sqrt(g/R) >= 0,5; square root of the threshold bisected on the generated `stability_n12`".into(),
        ),
        number_entry(
            "16",
            "V = sR at s = 1 (m/s), R = 0.50 m",
            2.40,
            unit_speed,
            Verdict::MemoirError,
            format!("V = sqrt(g R) with g = {g} m/s^2 (the memoir does not state its g); printed 2,40 m/s would need g R = 5.76 m^2/s^2"),
        ),
        number_entry(
            "18",
            "threshold speed sR (m/s), R = 0.50 m",
            1.20,
            s * unit_speed,
            Verdict::MemoirError,
            format!("derived s threshold x sqrt(g R), g = {g} m/s^2; the printed 1,20 is half of n° 16's 2,40, so the error is the unit speed of n° 16, not the threshold"),
        ),
    ]
}

/// Internal consistency of the generated forms: n° 11 against n° 8 (the memoir: "au
/// coefficient 2/3 près") and the n° 12 change of variables.
fn consistency_entries(
    points: &[BTreeMap<&'static str, f64>],
    values: &[BTreeMap<&'static str, f64>],
    values_n12: &[BTreeMap<&'static str, f64>],
) -> Vec<Entry> {
    let mut entries = Vec::new();
    let outputs = &values[0];
    let mut push = |section: &str,
                    quantity: &str,
                    printed: &str,
                    derived: Vec<f64>,
                    reference: Vec<f64>,
                    what: &str| {
        let cmp = compare(&derived, &reference);
        let agrees = policy::formula(cmp.max_rel, Verdict::DerivationDiffers) == Verdict::Agrees;
        let mut note = format!("{what}, at {SAMPLE_POINTS} seeded points");
        if !agrees {
            note.push_str(&format!(
                "; largest difference at sample point {}: {} vs {}",
                cmp.worst,
                format_significant(derived[cmp.worst], 8),
                format_significant(reference[cmp.worst], 8)
            ));
        }
        entries.push(Entry {
            falsification: None,
            section: section.to_string(),
            quantity: quantity.to_string(),
            memoir: Memoir::Formula(printed.to_string()),
            derived: Derived::Numbers(BTreeMap::from([
                ("points".to_string(), SAMPLE_POINTS as f64),
                ("max_abs_diff".to_string(), cmp.max_abs),
            ])),
            rel_diff: Some(cmp.max_rel),
            verdict: policy::formula(cmp.max_rel, Verdict::DerivationDiffers),
            note,
        });
    };
    if outputs.contains_key("equilibrium_direct") && outputs.contains_key("equilibrium") {
        push(
            "11",
            "direct method vs (E) of n° 8",
            "equal to (E) of n° 8 up to the factor 2/3",
            values.iter().map(|v| v["equilibrium_direct"]).collect(),
            values.iter().map(|v| 1.5 * v["equilibrium"]).collect(),
            "generated equilibrium_direct vs 3/2 x generated equilibrium",
        );
    }
    let scale = |pt: &BTreeMap<&str, f64>| pt["g"] / pt["R"];
    for (n12, phys, what, printed) in [
        (
            "equilibrium_n12",
            "equilibrium",
            "(E) n° 12 vs n° 8",
            "E_12 = E_8 / ((g/R) sin(th) cos(th))",
        ),
        ("stability_n12", "stability", "(S) n° 12 vs n° 9", "S_12 = S_9 / (g/R)"),
        ("skid_n12", "skid", "(D) n° 12 vs n° 10", "D_12 = D_10"),
    ] {
        if !(outputs.contains_key(n12) && outputs.contains_key(phys)) {
            continue;
        }
        let reference: Vec<f64> = points
            .iter()
            .zip(values)
            .map(|(pt, v)| match n12 {
                "equilibrium_n12" => v[phys] / (scale(pt) * pt["theta"].sin() * pt["theta"].cos()),
                "stability_n12" => v[phys] / scale(pt),
                _ => v[phys],
            })
            .collect();
        push(
            "12",
            what,
            printed,
            values_n12.iter().map(|v| v[n12]).collect(),
            reference,
            &format!("generated {n12} at rates / sqrt(g/R) vs generated {phys} rescaled"),
        );
    }
    entries
}

/// The symbolic checks of `generated/hoop.checks.tsv` (compiled in).
///
/// # Errors
/// As [`parse_checks`].
pub fn hoop_checks() -> Result<Vec<SymbolicCheck>, String> {
    parse_checks(carvallo::artifacts::HOOP.checks)
}

/// Checks whose expected outcome is `false`, with the memoir's reason: a check that fails as
/// the memoir says it must is a concordance, not a discrepancy.
const FINDINGS: &[Finding] = &[
    Finding::fails_as_the_memoir_says(
        "lagrange_unmodified_nu",
        "n° 71: the memoir says Lagrange's equations do not apply to the parameters chosen",
    ),
    Finding::fails_as_the_memoir_says(
        "lagrange_unmodified_sigma",
        "n° 71: the memoir says Lagrange's equations do not apply to the parameters chosen",
    ),
];

/// Longest check detail copied into a note.
const DETAIL_CHARS: usize = 160;

/// Folds the symbolic checks into the entries. A check named `<output>_memoir` annotates the
/// formula entry of that output (its note gains "symbolic check at regen: ..."); every other
/// check becomes an entry of its own, which agrees when the check's outcome is the expected
/// one (`true`, except the checks of [`FINDINGS`]).
fn fold_checks(entries: &mut Vec<Entry>, checks: Result<Vec<SymbolicCheck>, String>) {
    let checks = match checks {
        Ok(checks) => checks,
        Err(message) => {
            entries.push(Entry {
                falsification: None,
                section: "-".into(),
                quantity: "symbolic checks".into(),
                memoir: Memoir::Formula("generated/hoop.checks.tsv".into()),
                derived: Derived::Numbers(BTreeMap::new()),
                rel_diff: None,
                verdict: policy::finding(Verdict::DerivationDiffers),
                note: format!("cannot read generated/hoop.checks.tsv: {message}"),
            });
            return;
        }
    };
    for check in checks {
        let mut detail: String = check.detail.chars().take(DETAIL_CHARS).collect();
        if detail.len() < check.detail.len() {
            detail.push_str("...");
        }
        let text = format!(
            "symbolic check at regen: {} {}: {} ({detail})",
            check.id,
            if check.holds { "holds" } else { "does not hold" },
            check.statement,
        );
        let annotated = check.id.strip_suffix("_memoir").and_then(|output| {
            let marker = format!("generated `{output}` vs transcribed");
            entries.iter_mut().find(|e| e.note.starts_with(&marker))
        });
        if let Some(entry) = annotated {
            entry.note.push_str("; ");
            entry.note.push_str(&text);
            if !check.holds {
                entry.verdict = policy::check(false, Expect::Holds);
            }
            continue;
        }
        let mut note = format!(
            "symbolic check at regen: {} ({detail})",
            if check.holds { "holds" } else { "does not hold" }
        );
        if let Some(f) = checks::find(FINDINGS, &check.id) {
            note.push_str(&format!("; expected not to hold: {}", f.why));
        }
        entries.push(Entry {
            falsification: checks::falsification(&check, checks::expect(FINDINGS, &check.id)),
            section: check.section.clone(),
            quantity: format!("check {}", check.id),
            memoir: Memoir::Formula(check.statement.clone()),
            derived: Derived::Numbers(BTreeMap::from([(
                "holds".to_string(),
                if check.holds { 1.0 } else { 0.0 },
            )])),
            rel_diff: None,
            verdict: policy::check(check.holds, checks::expect(FINDINGS, &check.id)),
            note,
        });
    }
}

/// The hoop's concordance (memoir n° 4 to 18 and the checks of n° 71–77), computed now from
/// the generated evaluators and the recorded symbolic checks.
pub fn hoop_entries() -> Vec<Entry> {
    let points = sample_points();
    let values: Vec<_> = points.iter().map(eval_all).collect();
    let values_n12: Vec<_> = points.iter().map(|p| eval_all(&normalised_point(p))).collect();
    let mut entries = inertia_entries(&points, &values);
    entries.extend(formula_entries(&points, &values, &values_n12));
    entries.extend(consistency_entries(&points, &values, &values_n12));
    entries.extend(threshold_entries());
    let formulas_agree = entries
        .iter()
        .any(|e| e.quantity == "(S) normalised" && e.verdict == Verdict::Agrees)
        && entries.iter().any(|e| e.quantity == "(E) normalised" && e.verdict == Verdict::Agrees);
    entries.extend(crate::hoop_discussion::point_entries(formulas_agree));
    fold_checks(&mut entries, hoop_checks());
    // Stable order by section number, then insertion order.
    entries.sort_by(|a, b| section_key(&a.section).total_cmp(&section_key(&b.section)));
    entries
}

/// The hoop's concordance, as every model's report names it: [`hoop_entries`].
pub fn entries() -> Vec<Entry> {
    hoop_entries()
}

/// The memoir's claims checked in this report ([`crate::claims`]): n° 1–12 and the hoop's share
/// of Chapter III (n° 71–78).
pub fn claims() -> Vec<crate::claims::Claim> {
    claims::claims()
}

/// The memoir's assertions in this report's sections, n° by n°, with how each is covered.
pub const INVENTORY: &[crate::claims::Assertion] = claims::INVENTORY;
