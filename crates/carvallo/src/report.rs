//! The memoir concordance: every formula and number the memoir prints about the hoop, set
//! beside the value this workspace derives for it, with a verdict.
//!
//! Nothing here is a stored result. [`hoop_entries`] evaluates the generated evaluators (the
//! scenes of [`crate::hoop`], built at compile time from `generated/hoop.ir`) when it runs:
//! each derived formula is compared with the memoir's printed formula, transcribed by hand in the
//! same IR program as a `memoir_*` output, at a fixed seeded set of sample points; the numbers
//! of n° 4 and the straight-rolling stability threshold of n° 14/18 are recomputed from the
//! generated evaluators; the remarkable points of the stability discussion (n° 14 point F and
//! the vertical tangent of the curve (S), n° 17 bis point H) are recomputed by root finding on
//! the generated normalised (E) and (S); and the symbolic checks recorded by `cargo xtask
//! regen` in `generated/hoop.checks.tsv` are folded in.
//!
//! # Verdicts
//! * Formulas: `agrees` when the largest relative difference is at most
//!   [`AGREEMENT_TOLERANCE`], otherwise `derivation-differs` with the worst point in the note.
//! * Exact numbers (n° 4 coefficients, the threshold $s^2 = 1/4$): `agrees` within
//!   [`AGREEMENT_TOLERANCE`].
//! * Numbers Carvallo computed with his slide rule: `rounding` when within one unit of the
//!   last printed digit or $2\cdot10^{-3}$ relative; otherwise `memoir-error` when the
//!   formulas they come from agree with the memoir (the slip is in his arithmetic, the note
//!   says how his own intermediate values show it), `derivation-differs` when they do not.
//! * Symbolic checks: a check `<output>_memoir` annotates the formula entry of that output;
//!   any other check is an entry that agrees when its outcome is the expected one.
//!
//! # Comparing two formulas
//! At every sample point the relative difference is
//! $$\delta = \frac{|d - m|}{\max(|d|, |m|, \varepsilon)}$$
//! with $d$ the derived value, $m$ the memoir's, and the floor $\varepsilon$ given by
//! [`REL_DIFF_FLOOR`] (in the unit of the quantity) so that values that are both near zero
//! do not turn rounding noise into a large ratio. The entry reports the maximum over the
//! points; it *agrees* when that maximum is at most [`AGREEMENT_TOLERANCE`].

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::{Deserialize, Serialize};

use crate::hoop_discussion::bisect;

/// Largest relative difference (see the module docs) for which a derived formula and the
/// memoir's printed formula are said to agree: a few hundred units in the last place, the
/// rounding of two different but equal algebraic forms evaluated in `f64`.
pub const AGREEMENT_TOLERANCE: f64 = 1e-12;

/// The floor $\varepsilon$ of the relative difference (module docs), in the unit of the
/// compared quantity.
pub const REL_DIFF_FLOOR: f64 = 1e-9;

/// How a derived value compares with what the memoir prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    /// Equal within [`AGREEMENT_TOLERANCE`] (formulas) or exactly as printed (numbers).
    Agrees,
    /// The memoir's number is the derived one rounded (Carvallo used a slide rule, n° 14).
    Rounding,
    /// The memoir's own arithmetic or algebra is wrong, and the derivation shows where.
    MemoirError,
    /// The printed text is an OCR misreading of what the memoir means.
    Ocr,
    /// The derivation gives something else and the cause is not (yet) attributed.
    DerivationDiffers,
}

impl Verdict {
    /// The verdict as it is serialised (`agrees`, `rounding`, `memoir-error`, `ocr`,
    /// `derivation-differs`).
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Agrees => "agrees",
            Verdict::Rounding => "rounding",
            Verdict::MemoirError => "memoir-error",
            Verdict::Ocr => "ocr",
            Verdict::DerivationDiffers => "derivation-differs",
        }
    }
}

/// What the memoir prints: a number or a formula (as text).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Memoir {
    /// A printed number.
    Number(f64),
    /// A printed formula, transcribed as plain text.
    Formula(String),
}

/// What the workspace derives: one number or several named ones.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Derived {
    /// One number.
    Number(f64),
    /// Several named numbers (for example the largest difference and the number of points).
    Numbers(BTreeMap<String, f64>),
}

/// One line of the concordance.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    /// Memoir section number as printed in its table of contents (`"8"`, `"14/18"`).
    pub section: String,
    /// What is compared, in a few words.
    pub quantity: String,
    /// What the memoir prints.
    pub memoir: Memoir,
    /// What the workspace computes when the report runs.
    pub derived: Derived,
    /// The relative difference between the two, when it is meaningful.
    pub rel_diff: Option<f64>,
    /// The verdict.
    pub verdict: Verdict,
    /// Where a difference comes from, how the value was obtained, or the symbolic checks of the
    /// same section.
    pub note: String,
}

/// Formats `x` with `digits` significant digits, without trailing zeros: plain decimal for
/// magnitudes in $[10^{-4}, 10^{\min(6, \text{digits})})$, scientific otherwise.
pub fn format_significant(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let digits = digits.max(1);
    let sci = format!("{:.*e}", digits - 1, x);
    let (mantissa, exponent) = sci.split_once('e').unwrap_or((sci.as_str(), "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    if exponent >= -4 && exponent < (digits as i32).min(6) {
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        trim_zeros(&format!("{:.*}", decimals, x))
    } else {
        format!("{}e{}", trim_zeros(mantissa), exponent)
    }
}

fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// Widest memoir cell of the text table; longer formulas are cut with `...` (the JSON keeps
/// them whole).
pub const MEMOIR_CELL_CHARS: usize = 64;

fn memoir_cell(m: &Memoir) -> String {
    match m {
        Memoir::Number(x) => format_significant(*x, 10),
        Memoir::Formula(text) if text.chars().count() > MEMOIR_CELL_CHARS => {
            let cut: String = text.chars().take(MEMOIR_CELL_CHARS - 3).collect();
            format!("{cut}...")
        }
        Memoir::Formula(text) => text.clone(),
    }
}

fn derived_cell(d: &Derived) -> String {
    match d {
        Derived::Number(x) => format_significant(*x, 10),
        Derived::Numbers(map) => map
            .iter()
            .map(|(k, v)| format!("{k}={}", format_significant(*v, 10)))
            .collect::<Vec<_>>()
            .join(", "),
    }
}

fn rel_diff_cell(r: Option<f64>) -> String {
    match r {
        Some(x) => format!("{x:.1e}"),
        None => "-".to_string(),
    }
}

/// Renders the entries as an aligned plain-text table (columns n°, quantity, memoir, derived,
/// relative difference, verdict), each row followed by its note on an indented line.
pub fn render_text(entries: &[Entry]) -> String {
    render_text_with(entries, &|cell| cell)
}

/// [`render_text`] with every number to 4 significant digits ([`normalise_numbers`] applied to
/// each cell and note before the columns are laid out, so the padding does not depend on the
/// digits dropped): the form the snapshot tests compare.
pub fn render_text_normalised(entries: &[Entry]) -> String {
    render_text_with(entries, &|cell| normalise_numbers(&cell))
}

fn render_text_with(entries: &[Entry], cell: &dyn Fn(String) -> String) -> String {
    let header = ["n°", "quantity", "memoir", "derived", "rel. diff", "verdict"];
    let rows: Vec<[String; 6]> = entries
        .iter()
        .map(|e| {
            [
                e.section.clone(),
                e.quantity.clone(),
                memoir_cell(&e.memoir),
                derived_cell(&e.derived),
                rel_diff_cell(e.rel_diff),
                e.verdict.as_str().to_string(),
            ]
            .map(cell)
        })
        .collect();
    let mut widths = header.map(|h| h.chars().count());
    for row in &rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let mut out = String::new();
    let line = |cells: &[String], out: &mut String| {
        let mut text = String::new();
        for (i, (cell, w)) in cells.iter().zip(widths).enumerate() {
            if i > 0 {
                text.push_str("  ");
            }
            text.push_str(cell);
            let pad = w - cell.chars().count();
            text.extend(std::iter::repeat_n(' ', pad));
        }
        out.push_str(text.trim_end());
        out.push('\n');
    };
    line(&header.map(str::to_string), &mut out);
    let rule: Vec<String> = widths.iter().map(|w| "-".repeat(*w)).collect();
    line(&rule, &mut out);
    for (row, entry) in rows.iter().zip(entries) {
        line(row, &mut out);
        if !entry.note.is_empty() {
            let _ = writeln!(out, "    {}", cell(entry.note.clone()));
        }
    }
    out
}

/// The entries as a pretty-printed JSON array of objects with the keys `section`, `quantity`,
/// `memoir`, `derived`, `rel_diff`, `verdict`, `note`.
pub fn render_json(entries: &[Entry]) -> String {
    // Serialising plain data with string keys cannot fail.
    serde_json::to_string_pretty(entries).unwrap_or_default()
}

crate::scene! {
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

/// The symbolic checks recorded at regeneration, `generated/hoop.checks.tsv`.
const HOOP_CHECKS_TSV: &str = include_str!("../../../generated/hoop.checks.tsv");

/// A small deterministic generator (SplitMix64), so that the sample points are the same on
/// every platform and no random-number crate is needed at run time.
struct SplitMix64(u64);

impl SplitMix64 {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in $[lo, hi)$.
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }
}

/// One sample point: values for every parameter and input of the hoop model, by name.
fn sample_points() -> Vec<BTreeMap<&'static str, f64>> {
    let mut rng = SplitMix64(SAMPLE_SEED);
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
    let names: Vec<&str> = scene::PARAMS.iter().chain(scene::INPUTS.iter()).copied().collect();
    let args = std::array::from_fn(|i| point.get(names[i]).copied().unwrap_or(f64::NAN));
    let values = scene::eval_array(&args);
    scene::OUTPUTS.iter().copied().zip(values).collect()
}

/// Relative difference with the floor [`REL_DIFF_FLOOR`] (module docs).
pub(crate) fn rel_diff(derived: f64, memoir: f64) -> f64 {
    (derived - memoir).abs() / derived.abs().max(memoir.abs()).max(REL_DIFF_FLOOR)
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
        let agrees = cmp.max_rel <= AGREEMENT_TOLERANCE;
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
            section: section.to_string(),
            quantity: quantity.to_string(),
            memoir: Memoir::Formula(printed.to_string()),
            derived: Derived::Numbers(BTreeMap::from([
                ("points".to_string(), SAMPLE_POINTS as f64),
                ("max_abs_diff".to_string(), cmp.max_abs),
            ])),
            rel_diff: Some(cmp.max_rel),
            verdict: if agrees { Verdict::Agrees } else { Verdict::DerivationDiffers },
            note,
        });
    }
    entries
}

/// A number entry: `derived` against the printed `memoir`, agreeing within
/// [`AGREEMENT_TOLERANCE`], otherwise given `otherwise` as verdict.
pub(crate) fn number_entry(
    section: &str,
    quantity: &str,
    memoir: f64,
    derived: f64,
    otherwise: Verdict,
    note: String,
) -> Entry {
    let rel = rel_diff(derived, memoir);
    Entry {
        section: section.to_string(),
        quantity: quantity.to_string(),
        memoir: Memoir::Number(memoir),
        derived: Derived::Number(derived),
        rel_diff: Some(rel),
        verdict: if rel <= AGREEMENT_TOLERANCE { Verdict::Agrees } else { otherwise },
        note,
    }
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
            if spread > AGREEMENT_TOLERANCE {
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
            section: "14/18".into(),
            quantity: "upright threshold s^2 (units g/R)".into(),
            memoir: Memoir::Number(0.25),
            derived: Derived::Numbers(BTreeMap::from([
                ("stability_n12(s=0)".to_string(), stability_n12(0.0)),
                ("stability_n12(s=2)".to_string(), stability_n12(2.0)),
            ])),
            rel_diff: None,
            verdict: Verdict::DerivationDiffers,
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
            "printed s / sqrt(g/R) >= 0,5; square root of the bisected threshold".into(),
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

/// A number the memoir prints with `decimals` decimals, computed slide-rule style by Carvallo.
/// `Rounding` when the derived value is within one unit of the last printed digit or within
/// 2e-3 relative (a slide rule's three significant digits); otherwise `MemoirError` when the
/// underlying formulas agree with the memoir (so the difference is in his arithmetic),
/// `DerivationDiffers` when they do not.
pub(crate) fn printed_number(
    section: &str,
    quantity: &str,
    memoir: f64,
    decimals: i32,
    derived: f64,
    formulas_agree: bool,
    note: &str,
) -> Entry {
    let rel = rel_diff(derived, memoir);
    let close = (derived - memoir).abs() <= 10f64.powi(-decimals) || rel <= 2e-3;
    let verdict = if rel <= AGREEMENT_TOLERANCE {
        Verdict::Agrees
    } else if close {
        Verdict::Rounding
    } else if formulas_agree {
        Verdict::MemoirError
    } else {
        Verdict::DerivationDiffers
    };
    Entry {
        section: section.to_string(),
        quantity: quantity.to_string(),
        memoir: Memoir::Number(memoir),
        derived: Derived::Number(derived),
        rel_diff: Some(rel),
        verdict,
        note: note.to_string(),
    }
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
        let agrees = cmp.max_rel <= AGREEMENT_TOLERANCE;
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
            section: section.to_string(),
            quantity: quantity.to_string(),
            memoir: Memoir::Formula(printed.to_string()),
            derived: Derived::Numbers(BTreeMap::from([
                ("points".to_string(), SAMPLE_POINTS as f64),
                ("max_abs_diff".to_string(), cmp.max_abs),
            ])),
            rel_diff: Some(cmp.max_rel),
            verdict: if agrees { Verdict::Agrees } else { Verdict::DerivationDiffers },
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

/// One line of `generated/hoop.checks.tsv`.
#[derive(Clone, Debug, PartialEq)]
pub struct SymbolicCheck {
    /// Memoir section number.
    pub section: String,
    /// Stable identifier.
    pub id: String,
    /// Whether the check held at regeneration.
    pub holds: bool,
    /// What was checked.
    pub statement: String,
    /// The evidence.
    pub detail: String,
}

/// Parses the checks TSV (`#` comment lines, then `section id holds statement detail`
/// separated by tabs).
///
/// # Errors
/// A message naming the 1-based line and what is wrong with it.
pub fn parse_checks(tsv: &str) -> Result<Vec<SymbolicCheck>, String> {
    let mut checks = Vec::new();
    for (i, line) in tsv.lines().enumerate() {
        if line.starts_with('#') || line.trim().is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split('\t').collect();
        let [section, id, holds, statement, detail] = fields[..] else {
            return Err(format!(
                "line {}: expected 5 tab-separated fields, found {}",
                i + 1,
                fields.len()
            ));
        };
        let holds = match holds {
            "true" => true,
            "false" => false,
            other => {
                return Err(format!("line {}: holds must be true or false, found {other:?}", i + 1))
            }
        };
        checks.push(SymbolicCheck {
            section: section.to_string(),
            id: id.to_string(),
            holds,
            statement: statement.to_string(),
            detail: detail.to_string(),
        });
    }
    Ok(checks)
}

/// The symbolic checks of one model's `checks.tsv` (text `tsv`, file `generated/{file}`) as
/// report entries, one per check, named `{label} check {id}`. A check listed in `findings`
/// (id, verdict, reason) is expected not to hold and takes that verdict when it does not; any
/// other check agrees when it holds. The check's detail is cut to `detail_chars` characters.
/// A file that cannot be read gives a single `derivation-differs` entry saying why.
pub(crate) fn check_entries(
    tsv: &str,
    file: &str,
    label: &str,
    findings: &[(&str, Verdict, &str)],
    detail_chars: usize,
) -> Vec<Entry> {
    let checks = match parse_checks(tsv) {
        Ok(c) => c,
        Err(message) => {
            return vec![Entry {
                section: "-".into(),
                quantity: format!("{label} symbolic checks"),
                memoir: Memoir::Formula(format!("generated/{file}")),
                derived: Derived::Numbers(BTreeMap::new()),
                rel_diff: None,
                verdict: Verdict::DerivationDiffers,
                note: format!("cannot read generated/{file}: {message}"),
            }]
        }
    };
    checks
        .into_iter()
        .map(|c| {
            let finding = findings.iter().find(|(id, _, _)| *id == c.id);
            let detail: String = c.detail.chars().take(detail_chars).collect();
            let (verdict, why) = match finding {
                Some((_, v, why)) if !c.holds => (*v, format!("; {why}")),
                Some(_) => (Verdict::DerivationDiffers, "; expected not to hold".to_string()),
                None if c.holds => (Verdict::Agrees, String::new()),
                None => (Verdict::DerivationDiffers, String::new()),
            };
            Entry {
                section: c.section.clone(),
                quantity: format!("{label} check {}", c.id),
                memoir: Memoir::Formula(c.statement.clone()),
                derived: Derived::Numbers(BTreeMap::from([(
                    "holds".to_string(),
                    if c.holds { 1.0 } else { 0.0 },
                )])),
                rel_diff: None,
                verdict,
                note: format!(
                    "symbolic check at regen: {} ({detail}){why}",
                    if c.holds { "holds" } else { "does not hold" }
                ),
            }
        })
        .collect()
}

/// The symbolic checks of `generated/hoop.checks.tsv` (compiled in).
///
/// # Errors
/// As [`parse_checks`].
pub fn hoop_checks() -> Result<Vec<SymbolicCheck>, String> {
    parse_checks(HOOP_CHECKS_TSV)
}

/// Checks whose expected outcome is `false`, with the memoir's reason: a check that fails as
/// the memoir says it must is a concordance, not a discrepancy.
const EXPECTED_TO_FAIL: &[(&str, &str)] = &[
    (
        "lagrange_unmodified_nu",
        "n° 71: the memoir says Lagrange's equations do not apply to the parameters chosen",
    ),
    (
        "lagrange_unmodified_sigma",
        "n° 71: the memoir says Lagrange's equations do not apply to the parameters chosen",
    ),
];

/// Longest check detail copied into a note.
const DETAIL_CHARS: usize = 160;

/// Folds the symbolic checks into the entries. A check named `<output>_memoir` annotates the
/// formula entry of that output (its note gains "symbolic check at regen: ..."); every other
/// check becomes an entry of its own, which agrees when the check's outcome is the expected
/// one (`true`, except the checks of [`EXPECTED_TO_FAIL`]).
fn fold_checks(entries: &mut Vec<Entry>, checks: Result<Vec<SymbolicCheck>, String>) {
    let checks = match checks {
        Ok(checks) => checks,
        Err(message) => {
            entries.push(Entry {
                section: "-".into(),
                quantity: "symbolic checks".into(),
                memoir: Memoir::Formula("generated/hoop.checks.tsv".into()),
                derived: Derived::Numbers(BTreeMap::new()),
                rel_diff: None,
                verdict: Verdict::DerivationDiffers,
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
                entry.verdict = Verdict::DerivationDiffers;
            }
            continue;
        }
        let expected = EXPECTED_TO_FAIL.iter().find(|(id, _)| *id == check.id);
        let as_expected = check.holds == expected.is_none();
        let mut note = format!(
            "symbolic check at regen: {} ({detail})",
            if check.holds { "holds" } else { "does not hold" }
        );
        if let Some((_, why)) = expected {
            note.push_str(&format!("; expected not to hold: {why}"));
        }
        entries.push(Entry {
            section: check.section.clone(),
            quantity: format!("check {}", check.id),
            memoir: Memoir::Formula(check.statement.clone()),
            derived: Derived::Numbers(BTreeMap::from([(
                "holds".to_string(),
                if check.holds { 1.0 } else { 0.0 },
            )])),
            rel_diff: None,
            verdict: if as_expected { Verdict::Agrees } else { Verdict::DerivationDiffers },
            note,
        });
    }
}

/// Replaces every number in `text` (also in `key=value` and before `,;):`) by its value to 4
/// significant digits, or `~0` below 1e-12 in magnitude: the report's text with float noise
/// removed, as the snapshot tests compare it.
pub fn normalise_numbers(text: &str) -> String {
    let number = |token: &str| -> Option<String> {
        let x: f64 = token.parse().ok()?;
        Some(if x != 0.0 && x.abs() < 1e-12 { "~0".into() } else { format_significant(x, 4) })
    };
    text.lines()
        .map(|line| {
            line.split(' ')
                .map(|word| {
                    let core = word.trim_end_matches([',', ';', ')', ':']);
                    let tail = &word[core.len()..];
                    let (head, value) = match core.rsplit_once('=') {
                        Some((k, v)) => (format!("{k}="), v),
                        None => (String::new(), core),
                    };
                    match number(value) {
                        Some(n) => format!("{head}{n}{tail}"),
                        None => word.to_string(),
                    }
                })
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The whole concordance: every model's entries, in memoir order (hoop first). Each model
/// contributes one function; add new models here.
pub fn all_entries() -> Vec<Entry> {
    let mut entries = hoop_entries();
    entries.extend(crate::report_unicycle::entries());
    entries.extend(crate::report_hoop_discussion::entries());
    entries.extend(crate::report_whipple::entries());
    entries.extend(crate::report_bicycle_steady::entries());
    entries.extend(crate::report_bicycle_turn::entries());
    entries.extend(crate::report_bicycle_straight::entries());
    entries.extend(crate::report_bicycle_geometry::entries());
    entries.extend(crate::report_bicycle_kinematics::entries());
    entries.extend(crate::report_bicycle_rest::entries());
    // Stable sort: the models' own orders are kept within a section.
    entries.sort_by(|a, b| section_key(&a.section).total_cmp(&section_key(&b.section)));
    entries
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
    entries.extend(crate::report_hoop_discussion::point_entries(formulas_agree));
    fold_checks(&mut entries, hoop_checks());
    // Stable order by section number, then insertion order.
    entries.sort_by(|a, b| section_key(&a.section).total_cmp(&section_key(&b.section)));
    entries
}

fn section_key(section: &str) -> f64 {
    let digits: String = section.chars().take_while(|c| c.is_ascii_digit()).collect();
    digits.parse::<f64>().unwrap_or(f64::INFINITY)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Vec<Entry> {
        vec![
            Entry {
                section: "4".into(),
                quantity: "A / (mu R^2)".into(),
                memoir: Memoir::Number(1.5),
                derived: Derived::Number(1.5),
                rel_diff: Some(0.0),
                verdict: Verdict::Agrees,
                note: "coefficient of mu R^2".into(),
            },
            Entry {
                section: "14".into(),
                quantity: "x".into(),
                memoir: Memoir::Formula("n^2 + 1".into()),
                derived: Derived::Numbers(BTreeMap::from([("points".into(), 64.0)])),
                rel_diff: None,
                verdict: Verdict::MemoirError,
                note: String::new(),
            },
        ]
    }

    #[test]
    fn significant_digits() {
        assert_eq!(format_significant(1.5, 10), "1.5");
        assert_eq!(format_significant(0.24999999999999997, 10), "0.25");
        assert_eq!(format_significant(-123456.0, 3), "-1.23e5");
        assert_eq!(format_significant(2.5e-7, 4), "2.5e-7");
        assert_eq!(format_significant(0.0, 4), "0");
    }

    #[test]
    fn verdicts_serialise_as_kebab_case() {
        let all = [
            Verdict::Agrees,
            Verdict::Rounding,
            Verdict::MemoirError,
            Verdict::Ocr,
            Verdict::DerivationDiffers,
        ];
        for v in all {
            assert_eq!(serde_json::to_value(v).unwrap(), serde_json::json!(v.as_str()));
        }
    }

    #[test]
    fn json_has_the_seven_keys() {
        let json: serde_json::Value = serde_json::from_str(&render_json(&sample())).unwrap();
        let first = json.as_array().unwrap()[0].as_object().unwrap();
        let keys: Vec<&str> = first.keys().map(String::as_str).collect();
        let mut expected =
            vec!["section", "quantity", "memoir", "derived", "rel_diff", "verdict", "note"];
        expected.sort_unstable();
        assert_eq!(keys, expected);
        assert_eq!(first["memoir"], serde_json::json!(1.5));
        assert_eq!(json[1]["rel_diff"], serde_json::Value::Null);
        assert_eq!(json[1]["derived"]["points"], serde_json::json!(64.0));
    }

    #[test]
    fn text_table_is_aligned() {
        let text = render_text(&sample());
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines[0].starts_with("n°  quantity"));
        let col = lines[0].chars().count() - "verdict".len();
        let row: Vec<char> = lines[2].chars().collect();
        assert_eq!((row[col - 1], row[col]), (' ', 'a'));
        assert!(lines[2].contains("agrees") && lines[3] == "    coefficient of mu R^2");
        assert!(lines[4].ends_with("memoir-error"));
    }
}
