//! The concordance as a Markdown document (`report.md` of `carvallo report --out DIR`): the
//! entries of [`crate::all_entries`] grouped by the memoir's part, chapter and §
//! (its table of contents, [`OUTLINE`]), each with the memoir's value, the derived value, the
//! difference and the verdict, followed by an errata section that explains every entry whose
//! verdict is not `agrees`, grouped by verdict.

use std::collections::BTreeMap;
use std::fmt::Write;

use crate::claims::{counts, Assertion, Claim, Status};
use crate::entry::{Derived, Entry, Memoir, Verdict};
pub use crate::outline::{by_division, division_of, Division, BEYOND, OUTLINE};
use crate::render::text::format_significant;

/// A table cell: pipes escaped, line breaks turned into spaces.
fn cell(text: &str) -> String {
    text.replace('|', "\\|").replace(['\n', '\r'], " ")
}

fn memoir_text(m: &Memoir) -> String {
    match m {
        Memoir::Number(x) => format_significant(*x, 10),
        Memoir::Formula(text) => format!("`{}`", text.replace('`', "'")),
    }
}

fn derived_text(d: &Derived) -> String {
    match d {
        Derived::Number(x) => format_significant(*x, 10),
        Derived::Numbers(map) => map
            .iter()
            .map(|(k, v)| format!("{k} = {}", format_significant(*v, 10)))
            .collect::<Vec<_>>()
            .join(", "),
    }
}

/// The difference column: the relative difference and, for two numbers, the signed absolute
/// difference derived − memoir.
pub fn difference_text(e: &Entry) -> String {
    let rel = e.rel_diff.map(|r| format!("{r:.1e}"));
    let abs = match (&e.memoir, &e.derived) {
        (Memoir::Number(m), Derived::Number(d)) => Some(format_significant(d - m, 3)),
        _ => None,
    };
    match (rel, abs) {
        (Some(r), Some(a)) => format!("{r} (Δ = {a})"),
        (Some(r), None) => r,
        (None, Some(a)) => format!("Δ = {a}"),
        (None, None) => "–".to_string(),
    }
}

/// The verdicts in the order of the errata section (`agrees` last, not listed there).
pub const ERRATA_ORDER: [Verdict; 4] =
    [Verdict::MemoirError, Verdict::Ocr, Verdict::Rounding, Verdict::DerivationDiffers];

fn verdict_meaning(v: Verdict) -> &'static str {
    match v {
        Verdict::MemoirError => {
            "the memoir's own arithmetic or algebra is wrong; the derivation shows where"
        }
        Verdict::Ocr => "the printed text is an OCR misreading of what the memoir means",
        Verdict::Rounding => {
            "the memoir's number is the derived one rounded (slide-rule precision), or an \
             approximation the memoir declares, within the order it neglects"
        }
        Verdict::DerivationDiffers => {
            "the derivation gives something else and the cause is not (yet) attributed"
        }
        Verdict::Agrees => "equal within the tolerance of the policy above",
    }
}

/// Renders the concordance as the Markdown report: a title, a count of the entries and of the
/// claims by verdict and of the memoir's assertions by status, then `figures_section` as given
/// (Markdown, may be empty), the entries grouped by part, chapter and § with each chapter's
/// claims after its last §, and the errata (entries and claims).
pub fn render_markdown(
    entries: &[Entry],
    claims: &[Claim],
    assertions: &[Assertion],
    figures_section: &str,
) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# Carvallo's memoir re-derived: the concordance report\n");
    let _ = writeln!(
        out,
        "E. Carvallo, *Théorie du mouvement du monocycle et de la bicyclette* (1897), every printed \
         formula and number beside the value derived symbolically in this workspace and \
         evaluated when this report was written (`carvallo report --out DIR`).\n"
    );
    let _ = writeln!(
        out,
        "{} entries: {}.\n",
        entries.len(),
        verdict_counts(entries.iter().map(|e| e.verdict))
    );
    let _ = writeln!(out, "{}\n", claims_summary(claims, assertions));
    let _ = writeln!(out, "{}", crate::policy::PREAMBLE);
    if !figures_section.is_empty() {
        out.push_str(figures_section.trim_end());
        out.push_str("\n\n");
    }
    let _ = writeln!(out, "## Concordance\n");
    let _ = writeln!(
        out,
        "Columns: the memoir's n°, the quantity, what the memoir prints, what is derived, the \
         relative difference (and the absolute one, derived − memoir, for two numbers), the \
         verdict and the note saying how the value was obtained. Each chapter ends with the \
         memoir's claims in it: what it asserts, how this workspace checks it, the verdict.\n"
    );
    // Group in the order of the outline; entries without a n° last. A chapter's claims follow
    // its last §; a chapter with claims and no entries still gets its table.
    let groups = by_division(entries);
    let (mut part, mut chapter) = ("", "");
    let mut done: Vec<&str> = Vec::new();
    for (division, list) in &groups {
        match division {
            Some(d) => {
                if d.part != part {
                    part = d.part;
                    let _ = writeln!(out, "### {part}\n");
                }
                if d.chapter != chapter {
                    flush_claims(&mut out, &mut done, chapter, claims);
                    chapter = d.chapter;
                    let _ = writeln!(out, "#### {chapter}\n");
                }
                let _ = writeln!(out, "##### {} (n° {}–{})\n", d.paragraph, d.first, d.last);
            }
            None => {
                flush_claims(&mut out, &mut done, chapter, claims);
                chapter = "";
                let _ = writeln!(out, "### {BEYOND}\n");
            }
        }
        let _ = writeln!(out, "| n° | quantity | memoir | derived | difference | verdict | note |");
        let _ = writeln!(out, "|---|---|---|---|---|---|---|");
        for e in list {
            let _ = writeln!(
                out,
                "| {} | {} | {} | {} | {} | {} | {} |",
                cell(&e.section),
                cell(&e.quantity),
                cell(&memoir_text(&e.memoir)),
                cell(&derived_text(&e.derived)),
                cell(&difference_text(e)),
                e.verdict.as_str(),
                cell(&e.note)
            );
        }
        out.push('\n');
    }
    flush_claims(&mut out, &mut done, chapter, claims);
    let rest: Vec<&Claim> =
        claims.iter().filter(|c| !done.contains(&chapter_of(&c.section))).collect();
    if !rest.is_empty() {
        let _ = writeln!(out, "### Claims of chapters without entries\n");
        claims_table(&mut out, &rest);
    }
    let _ = writeln!(out, "## Errata\n");
    let _ = writeln!(
        out,
        "Every entry and every claim whose verdict is not `agrees`, grouped by verdict, with the \
         explanation.\n"
    );
    for v in ERRATA_ORDER {
        let list: Vec<&Entry> = entries.iter().filter(|e| e.verdict == v).collect();
        let wrong: Vec<&Claim> = claims.iter().filter(|c| c.verdict == v).collect();
        let _ = writeln!(
            out,
            "### `{}` ({}): {}\n",
            v.as_str(),
            list.len() + wrong.len(),
            verdict_meaning(v)
        );
        if list.is_empty() && wrong.is_empty() {
            let _ = writeln!(out, "None.\n");
            continue;
        }
        for e in list {
            let _ = writeln!(
                out,
                "- **n° {}, {}**: memoir {}, derived {}; difference {}. {}",
                e.section,
                e.quantity.replace('\n', " "),
                memoir_text(&e.memoir),
                derived_text(&e.derived),
                difference_text(e),
                e.note.replace('\n', " ")
            );
        }
        for c in wrong {
            let _ = writeln!(
                out,
                "- **n° {}, claim**: {} Checked by: {} Evidence: {}. {}",
                c.section,
                c.claim.replace('\n', " "),
                c.how.replace('\n', " "),
                c.evidence_text(),
                c.note.replace('\n', " ")
            );
        }
        out.push('\n');
    }
    let left: Vec<&Assertion> =
        assertions.iter().filter(|a| matches!(a.status, Status::Left(_))).collect();
    if !left.is_empty() {
        let _ = writeln!(out, "## Assertions left unchecked\n");
        let _ = writeln!(
            out,
            "The memoir's assertions found n° by n° that no claim or value entry checks ({} of \
             {}), each with the reason.\n",
            left.len(),
            assertions.len()
        );
        for a in left {
            if let Status::Left(why) = a.status {
                let _ = writeln!(out, "- **n° {}**: {}. *{}*", a.section, a.says, why);
            }
        }
        out.push('\n');
    }
    out
}

/// `n agrees, n memoir-error, n ocr, n rounding, n derivation-differs` for `verdicts`.
fn verdict_counts(verdicts: impl Iterator<Item = Verdict>) -> String {
    let mut counts: BTreeMap<&str, usize> = BTreeMap::new();
    for v in verdicts {
        *counts.entry(v.as_str()).or_default() += 1;
    }
    let summary: Vec<String> = [Verdict::Agrees]
        .iter()
        .chain(ERRATA_ORDER.iter())
        .map(|v| format!("{} {}", counts.get(v.as_str()).copied().unwrap_or(0), v.as_str()))
        .collect();
    summary.join(", ")
}

/// The summary line of the claims: how many were checked and their verdicts, and the memoir's
/// assertions found, by status.
pub fn claims_summary(claims: &[Claim], assertions: &[Assertion]) -> String {
    let c = counts(assertions);
    format!(
        "{} claims: {}. The memoir's assertions found n° by n°: {} ({} checked by a claim, {} \
         decided by a value entry, {} left, each with the reason).",
        claims.len(),
        verdict_counts(claims.iter().map(|c| c.verdict)),
        c.found,
        c.checked,
        c.by_value,
        c.left
    )
}

/// The chapter of the outline a section belongs to (`""` outside the outline).
fn chapter_of(section: &str) -> &'static str {
    division_of(section).map_or("", |d| d.chapter)
}

/// Writes the claims table of `chapter` (when it has claims and was not written yet).
fn flush_claims<'a>(out: &mut String, done: &mut Vec<&'a str>, chapter: &'a str, claims: &[Claim]) {
    if chapter.is_empty() || done.contains(&chapter) {
        return;
    }
    done.push(chapter);
    let list: Vec<&Claim> = claims.iter().filter(|c| chapter_of(&c.section) == chapter).collect();
    if list.is_empty() {
        return;
    }
    let _ = writeln!(out, "##### Claims of this chapter\n");
    claims_table(out, &list);
}

fn claims_table(out: &mut String, list: &[&Claim]) {
    let _ = writeln!(out, "| n° | claim | how checked | evidence | verdict | note |");
    let _ = writeln!(out, "|---|---|---|---|---|---|");
    for c in list {
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} | {} | {} |",
            cell(&c.section),
            cell(&c.claim),
            cell(&c.how),
            cell(&c.evidence_text()),
            c.verdict.as_str(),
            cell(&c.note)
        );
    }
    out.push('\n');
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entry(section: &str, verdict: Verdict, note: &str) -> Entry {
        Entry {
            falsification: None,
            section: section.to_string(),
            quantity: format!("q {section}"),
            memoir: Memoir::Number(1.0),
            derived: Derived::Number(1.5),
            rel_diff: Some(1.0 / 3.0),
            verdict,
            note: note.to_string(),
        }
    }

    #[test]
    fn entries_are_grouped_by_the_outline_and_explained_in_the_errata() {
        let entries = [
            entry("32", Verdict::MemoirError, "slip | in n° 32"),
            entry("4", Verdict::Agrees, "exact"),
            entry("benchmark", Verdict::Agrees, "modern"),
            entry("17 bis", Verdict::Rounding, "slide rule"),
        ];
        let md = render_markdown(&entries, &[], &[], "## Figures\n\nnone");
        let at = |text: &str| md.find(text).unwrap_or_else(|| panic!("no `{text}` in\n{md}"));
        // Outline order: n° 4, 17 bis, 32, then the entries without a n°.
        assert!(at("§ I — cinématique du cerceau") < at("§ V — complément pratique"));
        assert!(at("§ V — complément pratique") < at("§ III — équilibre du monocycle"));
        assert!(at("§ III — équilibre du monocycle") < at(BEYOND));
        assert!(at("## Figures") < at("## Concordance") && at("## Concordance") < at("## Errata"));
        // The one verdict policy is stated before the concordance.
        assert!(at("How the verdicts are decided") < at("## Concordance"));
        assert!(md.contains(
            "4 entries: 2 agrees, 1 memoir-error, 0 ocr, 1 rounding, 0 derivation-differs."
        ));
        assert!(md.contains(
            "| 32 | q 32 | 1 | 1.5 | 3.3e-1 (Δ = 0.5) | memoir-error | slip \\| in n° 32 |"
        ));
        // The errata list the three non-agreeing verdict groups with their entries only.
        let errata = &md[at("## Errata")..];
        assert!(errata.contains("- **n° 32, q 32**: memoir 1, derived 1.5; difference 3.3e-1 (Δ = 0.5). slip | in n° 32"));
        assert!(errata.contains("### `rounding` (1)") && errata.contains("### `ocr` (0)"));
        assert!(!errata.contains("exact") && !errata.contains("modern"));
    }

    #[test]
    fn each_chapter_ends_with_its_claims_and_failed_claims_are_errata() {
        use crate::claims::{Assertion, Status};
        let entries = [entry("4", Verdict::Agrees, "a"), entry("32", Verdict::Agrees, "b")];
        let claim = |id: &str, section: &str, verdict| {
            Claim::new(id, section, &format!("says {id}"), "computed", &[("m", 2.0)], verdict, "")
        };
        let claims = [
            claim("c-hoop", "12", Verdict::Agrees),
            claim("c-uni", "39", Verdict::MemoirError),
            claim("c-bike", "122", Verdict::Agrees),
        ];
        let inventory = [
            Assertion { section: "12", says: "x", status: Status::Checked("c-hoop") },
            Assertion { section: "13", says: "y", status: Status::Left("no model") },
        ];
        let md = render_markdown(&entries, &claims, &inventory, "");
        let at = |text: &str| md.find(text).unwrap_or_else(|| panic!("no `{text}` in\n{md}"));
        assert!(md.contains(
            "3 claims: 2 agrees, 1 memoir-error, 0 ocr, 0 rounding, 0 derivation-differs. The \
             memoir's assertions found n° by n°: 2 (1 checked by a claim, 0 decided by a value \
             entry, 1 left, each with the reason)."
        ));
        // The hoop chapter's claims come after its § and before the unicycle chapter.
        assert!(at("| 4 | q 4") < at("| 12 | says c-hoop"));
        assert!(at("| 12 | says c-hoop") < at("#### Chapitre II — monocycle"));
        assert!(at("| 32 | q 32") < at("| 39 | says c-uni"));
        // A chapter without entries still shows its claims.
        assert!(at("### Claims of chapters without entries") < at("| 122 | says c-bike"));
        let errata = &md[at("## Errata")..];
        assert!(errata.contains("### `memoir-error` (1)"));
        assert!(
            errata.contains("- **n° 39, claim**: says c-uni Checked by: computed Evidence: m = 2.")
        );
    }

    #[test]
    fn cells_cannot_break_the_table() {
        assert_eq!(cell("a | b\nc"), "a \\| b c");
    }
}
