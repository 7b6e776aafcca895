//! The concordance report as one self-contained HTML page (`report.html` of
//! `carvallo report --out DIR`, beside `report.md`): the same entries, grouped the same way, with
//! the figures' SVG inline, the memoir's formulas typeset in a math font by a small converter
//! ([`math`]: Greek names to letters, `^` and `_` to super- and subscripts, `sqrt` to √), every
//! entry that does not simply agree linked to its erratum and back, and a filter by verdict that
//! works without JavaScript (links to `#only-VERDICT` anchors, CSS `:target` with `:has`). No
//! script, no network: the page reads the same from a file anywhere.

use std::collections::BTreeMap;
use std::fmt::Write;

use carvallo_report::render::markdown::{
    by_division, difference_text, division_of, BEYOND, ERRATA_ORDER,
};
use carvallo_report::{format_significant, Assertion, Claim, Derived, Entry, Memoir, Verdict};

/// A figure as it goes into the page: its anchor, title, caption and SVG document.
pub struct HtmlFigure<'a> {
    /// The file name of the figure beside the page (`*.svg`), also its anchor.
    pub file: &'a str,
    /// The title.
    pub title: &'a str,
    /// The caption.
    pub caption: &'a str,
    /// The SVG document.
    pub svg: &'a str,
}

/// Escapes text and turns `code` spans (Markdown backticks) into `<code>` elements.
pub fn escape_with_code(text: &str) -> String {
    escape(text)
        .split('`')
        .enumerate()
        .map(|(i, part)| if i % 2 == 1 { format!("<code>{part}</code>") } else { part.to_string() })
        .collect()
}

/// Escapes text for HTML element content and attribute values.
pub fn escape(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&#39;"),
            _ => s.push(c),
        }
    }
    s
}

/// Greek letter names as the transcriptions write them.
const GREEK: [(&str, &str); 24] = [
    ("alpha", "α"),
    ("beta", "β"),
    ("gamma", "γ"),
    ("delta", "δ"),
    ("epsilon", "ε"),
    ("zeta", "ζ"),
    ("eta", "η"),
    ("theta", "θ"),
    ("th", "θ"),
    ("iota", "ι"),
    ("kappa", "κ"),
    ("lambda", "λ"),
    ("mu", "μ"),
    ("nu", "ν"),
    ("xi", "ξ"),
    ("pi", "π"),
    ("rho", "ρ"),
    ("sigma", "σ"),
    ("tau", "τ"),
    ("phi", "φ"),
    ("chi", "χ"),
    ("psi", "ψ"),
    ("omega", "ω"),
    ("Delta", "Δ"),
];

/// A word with a Greek name, optionally followed by digits (`theta1` → θ₁).
fn greek_word(word: &str) -> Option<String> {
    let name: String = word.chars().take_while(|c| c.is_ascii_alphabetic()).collect();
    let rest = &word[name.len()..];
    if !rest.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    let letter = GREEK.iter().find(|(n, _)| *n == name)?.1;
    Some(if rest.is_empty() { letter.to_string() } else { format!("{letter}<sub>{rest}</sub>") })
}

/// The exponent or index after `^` or `_`: `{...}`, `(...)` (parentheses kept off), a signed
/// number or a word; returns it and the number of bytes consumed.
fn script(text: &str) -> (String, usize) {
    let mut chars = text.char_indices();
    match chars.next() {
        Some((_, '{')) | Some((_, '(')) => {
            let close = if text.starts_with('{') { '}' } else { ')' };
            let open = text.chars().next().unwrap_or('{');
            let mut depth = 0;
            for (i, c) in text.char_indices() {
                if c == open {
                    depth += 1;
                } else if c == close {
                    depth -= 1;
                    if depth == 0 {
                        return (text[1..i].to_string(), i + 1);
                    }
                }
            }
            (text[1..].to_string(), text.len())
        }
        Some((_, c)) if c == '-' || c == '+' || c.is_alphanumeric() || c == '.' => {
            let mut end = c.len_utf8();
            for (i, c) in chars {
                if c.is_alphanumeric() || c == '.' {
                    end = i + c.len_utf8();
                } else {
                    break;
                }
            }
            (text[..end].to_string(), end)
        }
        _ => (String::new(), 0),
    }
}

/// Typesets a transcribed formula as HTML: escaped, Greek names as letters, `a^2` and
/// `a_{ij}` as super- and subscripts, `sqrt` as √, `*` as a middle dot, `<=`, `>=`, `!=` as
/// ≤, ≥, ≠. Words that are not Greek names stay as written.
pub fn math(text: &str) -> String {
    let text = text.replace("<=", "≤").replace(">=", "≥").replace("!=", "≠");
    let mut out = String::with_capacity(text.len() * 2);
    let mut rest = text.as_str();
    while let Some(c) = rest.chars().next() {
        if c.is_ascii_alphabetic() {
            let end = rest.find(|c: char| !c.is_ascii_alphanumeric()).unwrap_or(rest.len());
            let word = &rest[..end];
            if word == "sqrt" {
                out.push('√');
            } else if let Some(g) = greek_word(word) {
                out.push_str(&g);
            } else {
                out.push_str(&escape(word));
            }
            rest = &rest[end..];
        } else if c == '^' || c == '_' {
            let (inner, used) = script(&rest[1..]);
            if used == 0 {
                out.push(c);
                rest = &rest[1..];
            } else {
                let tag = if c == '^' { "sup" } else { "sub" };
                let _ = write!(out, "<{tag}>{}</{tag}>", math(&inner));
                rest = &rest[1 + used..];
            }
        } else if c == '*' {
            out.push('·');
            rest = &rest[1..];
        } else {
            out.push_str(&escape(&c.to_string()));
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

fn memoir_html(m: &Memoir) -> String {
    match m {
        Memoir::Number(x) => format!("<span class=\"num\">{}</span>", format_significant(*x, 10)),
        Memoir::Formula(text) => format!("<span class=\"math\">{}</span>", math(text)),
    }
}

fn derived_html(d: &Derived) -> String {
    match d {
        Derived::Number(x) => format!("<span class=\"num\">{}</span>", format_significant(*x, 10)),
        Derived::Numbers(map) => map
            .iter()
            .map(|(k, v)| {
                format!("{} = <span class=\"num\">{}</span>", escape(k), format_significant(*v, 10))
            })
            .collect::<Vec<_>>()
            .join(", "),
    }
}

fn verdict_meaning(v: Verdict) -> &'static str {
    match v {
        Verdict::MemoirError => {
            "the memoir's own arithmetic or algebra is wrong; the derivation shows where"
        }
        Verdict::Ocr => "the printed text is an OCR misreading of what the memoir means",
        Verdict::Rounding => {
            "the memoir's number is the derived one rounded (slide-rule precision)"
        }
        Verdict::DerivationDiffers => {
            "the derivation gives something else and the cause is not (yet) attributed"
        }
        Verdict::Agrees => "equal within the stated tolerance",
    }
}

/// Every verdict, `agrees` first.
const VERDICTS: [Verdict; 5] = [
    Verdict::Agrees,
    Verdict::MemoirError,
    Verdict::Ocr,
    Verdict::Rounding,
    Verdict::DerivationDiffers,
];

pub(crate) const STYLE: &str = r##"
body { font-family: Georgia, "Times New Roman", serif; margin: 0 auto; max-width: 1200px; padding: 0 1.5em 4em; color: #222; line-height: 1.45; }
h1 { font-size: 1.7em; margin-top: 1.2em; }
h2 { border-bottom: 1px solid #bbb; margin-top: 2em; }
h3 { margin-top: 1.6em; } h4 { margin: 1.2em 0 0.4em; } h5 { margin: 1em 0 0.3em; font-size: 1em; }
table { border-collapse: collapse; width: 100%; font-size: 0.88em; margin-bottom: 0.8em; }
th, td { border: 1px solid #ddd; padding: 0.25em 0.4em; vertical-align: top; text-align: left; overflow-wrap: anywhere; }
th { background: #f2f2f2; }
td.n { white-space: nowrap; }
.math { font-family: "STIX Two Math", "Cambria Math", "Latin Modern Math", "DejaVu Serif", "Times New Roman", serif; font-style: italic; }
.num { font-family: "DejaVu Sans Mono", Menlo, Consolas, monospace; font-size: 0.95em; }
td.note { color: #444; font-size: 0.95em; }
.verdict { font-family: sans-serif; font-size: 0.85em; padding: 0.05em 0.4em; border-radius: 0.6em; white-space: nowrap; }
.v-agrees .verdict, .verdict.v-agrees { background: #e3f3e3; }
.v-rounding .verdict, .verdict.v-rounding { background: #eef0ff; }
.v-memoir-error .verdict, .verdict.v-memoir-error { background: #ffe0dc; }
.v-ocr .verdict, .verdict.v-ocr { background: #fff1c9; }
.v-derivation-differs .verdict, .verdict.v-derivation-differs { background: #f1dcff; }
nav.filter { position: sticky; top: 0; background: #fff; border-bottom: 1px solid #ccc; padding: 0.4em 0; font-family: sans-serif; font-size: 0.9em; z-index: 2; }
nav.filter a { margin-right: 0.8em; }
.anchor { display: block; position: relative; top: -3em; visibility: hidden; }
div.figures { display: grid; grid-template-columns: repeat(auto-fill, minmax(520px, 1fr)); gap: 1em; }
figure { margin: 0; border: 1px solid #ddd; padding: 0.6em; }
figure svg { width: 100%; height: auto; }
figcaption { font-size: 0.9em; color: #333; }
li.erratum { margin-bottom: 0.5em; }
li.erratum:target, tr:target { background: #fffbd6; }
body:has(#only-agrees:target) tr.entry:not(.v-agrees),
body:has(#only-rounding:target) tr.entry:not(.v-rounding),
body:has(#only-memoir-error:target) tr.entry:not(.v-memoir-error),
body:has(#only-ocr:target) tr.entry:not(.v-ocr),
body:has(#only-derivation-differs:target) tr.entry:not(.v-derivation-differs) { display: none; }
body:has(#only-agrees:target) a[href="#only-agrees"],
body:has(#only-rounding:target) a[href="#only-rounding"],
body:has(#only-memoir-error:target) a[href="#only-memoir-error"],
body:has(#only-ocr:target) a[href="#only-ocr"],
body:has(#only-derivation-differs:target) a[href="#only-derivation-differs"] { font-weight: bold; }
"##;

/// Renders the page: title, counts by verdict and the filter, `extra` (HTML sections placed
/// before the figures, for example the uncertainty of a parameter file; may be empty), the
/// figures, the concordance grouped by the memoir's part, chapter and § (as `report.md`) and
/// the errata, each erratum linked from its row and back.
pub fn render_html(
    entries: &[Entry],
    claims: &[Claim],
    assertions: &[Assertion],
    figures: &[HtmlFigure<'_>],
    extra: &str,
) -> String {
    let mut out = String::new();
    let _ = write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>Carvallo's memoir re-derived: the concordance report</title>\n<style>{STYLE}</style>\n\
         </head>\n<body>\n"
    );
    let _ = writeln!(out, "<h1>Carvallo's memoir re-derived: the concordance report</h1>");
    let _ = writeln!(
        out,
        "<p>E. Carvallo, <i>Théorie du mouvement du monocycle et de la bicyclette</i> (1897), every \
         printed formula and number beside the value derived symbolically in this workspace and \
         evaluated when this report was written (<code>carvallo report --out DIR</code>; the same \
         content as <code>report.md</code>).</p>"
    );
    out.push_str(&policy_html());
    let mut counts: BTreeMap<&str, usize> = BTreeMap::new();
    for e in entries {
        *counts.entry(e.verdict.as_str()).or_default() += 1;
    }
    let count = |v: Verdict| counts.get(v.as_str()).copied().unwrap_or(0);
    let summary: Vec<String> = VERDICTS
        .iter()
        .map(|v| format!("{}&nbsp;<span class=\"verdict v-{1}\">{1}</span>", count(*v), v.as_str()))
        .collect();
    let _ =
        writeln!(out, "<p id=\"summary\">{} entries: {}.</p>", entries.len(), summary.join(", "));
    let _ = writeln!(
        out,
        "<p id=\"claims-summary\">{}</p>",
        escape(&carvallo_report::render::markdown::claims_summary(claims, assertions))
    );
    // The filter: the anchors are targets of the links; CSS hides the other rows.
    out.push_str("<nav class=\"filter\" aria-label=\"filter by verdict\">Show entries: <a href=\"#concordance\">all</a>");
    for v in VERDICTS {
        let _ = write!(out, "<a href=\"#only-{0}\">only {0} ({1})</a>", v.as_str(), count(v));
    }
    out.push_str(" · <a href=\"#figures\">figures</a><a href=\"#errata\">errata</a></nav>\n");
    for v in VERDICTS {
        let _ = writeln!(out, "<span class=\"anchor\" id=\"only-{}\"></span>", v.as_str());
    }
    out.push_str(extra);
    let _ = writeln!(out, "<h2 id=\"figures\">Figures</h2>\n<div class=\"figures\">");
    for f in figures {
        let svg = f.svg.trim_start();
        let svg = match svg.strip_prefix("<?xml") {
            Some(rest) => rest.split_once("?>").map_or(rest, |(_, s)| s).trim_start(),
            None => svg,
        };
        let _ = writeln!(
            out,
            "<figure id=\"{}\">\n{}\n<figcaption><b>{}</b>. {}</figcaption>\n</figure>",
            escape(f.file),
            svg,
            escape(f.title),
            escape(f.caption)
        );
    }
    out.push_str("</div>\n");
    // Entry numbers follow the order of `entries`; errata link to the same numbers.
    let index: BTreeMap<*const Entry, usize> =
        entries.iter().enumerate().map(|(i, e)| (e as *const Entry, i + 1)).collect();
    let _ = writeln!(out, "<h2 id=\"concordance\">Concordance</h2>");
    let _ = writeln!(
        out,
        "<p>Columns: the memoir's n°, the quantity, what the memoir prints, what is derived, the \
         relative difference (and the absolute one, derived − memoir, for two numbers), the \
         verdict (linked to its erratum when it is not <i>agrees</i>) and the note saying how the \
         value was obtained.</p>"
    );
    let groups = by_division(entries);
    let (mut part, mut chapter) = ("", "");
    let mut done: Vec<&str> = Vec::new();
    for (division, list) in &groups {
        match division {
            Some(d) => {
                if d.part != part {
                    part = d.part;
                    let _ = writeln!(out, "<h3>{}</h3>", escape(part));
                }
                if d.chapter != chapter {
                    claims_html(&mut out, &mut done, chapter, claims);
                    chapter = d.chapter;
                    let _ = writeln!(out, "<h4>{}</h4>", escape(chapter));
                }
                let _ =
                    writeln!(out, "<h5>{} (n° {}–{})</h5>", escape(d.paragraph), d.first, d.last);
            }
            None => {
                claims_html(&mut out, &mut done, chapter, claims);
                chapter = "";
                let _ = writeln!(out, "<h3>{}</h3>", escape(BEYOND));
            }
        }
        out.push_str("<table>\n<thead><tr><th>n°</th><th>quantity</th><th>memoir</th><th>derived</th><th>difference</th><th>verdict</th><th>note</th></tr></thead>\n<tbody>\n");
        for e in list {
            let i = index[&(*e as *const Entry)];
            let v = e.verdict.as_str();
            let verdict = if e.verdict == Verdict::Agrees {
                format!("<span class=\"verdict\">{v}</span>")
            } else {
                format!("<a class=\"verdict\" href=\"#erratum-{i}\">{v}</a>")
            };
            let _ = writeln!(
                out,
                "<tr class=\"entry v-{v}\" id=\"entry-{i}\"><td class=\"n\">{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"num\">{}</td><td>{verdict}</td><td class=\"note\">{}</td></tr>",
                escape(&e.section),
                escape(&e.quantity),
                memoir_html(&e.memoir),
                derived_html(&e.derived),
                escape(&difference_text(e)),
                escape_with_code(&e.note)
            );
        }
        out.push_str("</tbody>\n</table>\n");
    }
    claims_html(&mut out, &mut done, chapter, claims);
    let _ = writeln!(out, "<h2 id=\"errata\">Errata</h2>");
    let _ = writeln!(
        out,
        "<p>Every entry whose verdict is not <i>agrees</i>, grouped by verdict, with the \
         explanation; ↩ goes back to the entry in the concordance.</p>"
    );
    for v in ERRATA_ORDER {
        let list: Vec<&Entry> = entries.iter().filter(|e| e.verdict == v).collect();
        let wrong: Vec<&Claim> = claims.iter().filter(|c| c.verdict == v).collect();
        let _ = writeln!(
            out,
            "<h3 id=\"errata-{0}\"><span class=\"verdict v-{0}\">{0}</span> ({1}): {2}</h3>",
            v.as_str(),
            list.len() + wrong.len(),
            verdict_meaning(v)
        );
        if list.is_empty() && wrong.is_empty() {
            out.push_str("<p>None.</p>\n");
            continue;
        }
        out.push_str("<ul>\n");
        for e in list {
            let i = index[&(e as *const Entry)];
            let _ = writeln!(
                out,
                "<li class=\"erratum\" id=\"erratum-{i}\"><b>n° {}, {}</b>: memoir {}, derived {}; difference {}. {} <a href=\"#entry-{i}\">↩</a></li>",
                escape(&e.section),
                escape(&e.quantity),
                memoir_html(&e.memoir),
                derived_html(&e.derived),
                escape(&difference_text(e)),
                escape_with_code(&e.note)
            );
        }
        for c in wrong {
            let _ = writeln!(
                out,
                "<li class=\"erratum\" id=\"claim-erratum-{0}\"><b>n° {1}, claim</b>: {2} Checked by: {3} Evidence: {4}. {5} <a href=\"#claim-{0}\">↩</a></li>",
                escape(&c.id),
                escape(&c.section),
                escape_with_code(&c.claim),
                escape_with_code(&c.how),
                escape(&c.evidence_text()),
                escape_with_code(&c.note)
            );
        }
        out.push_str("</ul>\n");
    }
    out.push_str("</body>\n</html>\n");
    out
}

/// The claims table of `chapter` after its last § (when it has claims and was not written
/// yet), each claim's verdict linked to its erratum when it is not `agrees`.
fn claims_html<'a>(out: &mut String, done: &mut Vec<&'a str>, chapter: &'a str, claims: &[Claim]) {
    if chapter.is_empty() || done.contains(&chapter) {
        return;
    }
    done.push(chapter);
    let in_chapter = |c: &&Claim| division_of(&c.section).is_some_and(|d| d.chapter == chapter);
    let list: Vec<&Claim> = claims.iter().filter(in_chapter).collect();
    if list.is_empty() {
        return;
    }
    out.push_str("<h5>Claims of this chapter</h5>\n<table class=\"claims\">\n<thead><tr><th>n°</th><th>claim</th><th>how checked</th><th>evidence</th><th>verdict</th><th>note</th></tr></thead>\n<tbody>\n");
    for c in list {
        let v = c.verdict.as_str();
        let id = escape(&c.id);
        let verdict = if c.verdict == Verdict::Agrees {
            format!("<span class=\"verdict\">{v}</span>")
        } else {
            format!("<a class=\"verdict\" href=\"#claim-erratum-{id}\">{v}</a>")
        };
        let _ = writeln!(
            out,
            "<tr class=\"claim v-{v}\" id=\"claim-{id}\"><td class=\"n\">{}</td><td>{}</td><td>{}</td><td class=\"num\">{}</td><td>{verdict}</td><td class=\"note\">{}</td></tr>",
            escape(&c.section),
            escape_with_code(&c.claim),
            escape_with_code(&c.how),
            escape(&c.evidence_text()),
            escape_with_code(&c.note)
        );
    }
    out.push_str("</tbody>\n</table>\n");
}

/// The one verdict policy (`carvallo_report::policy::PREAMBLE`, as `report.md` states it) as
/// HTML: its first line a paragraph, its `- ` lines a list, `**bold**` and `` `code` `` kept.
fn policy_html() -> String {
    let mut html = String::from("<section id=\"policy\">\n");
    let mut in_list = false;
    for line in carvallo_report::policy::PREAMBLE.lines().filter(|l| !l.trim().is_empty()) {
        let bold = |t: &str| {
            let parts: Vec<&str> = t.split("**").collect();
            parts
                .iter()
                .enumerate()
                .map(|(k, p)| if k % 2 == 1 { format!("<b>{p}</b>") } else { p.to_string() })
                .collect::<String>()
        };
        if let Some(item) = line.strip_prefix("- ") {
            if !in_list {
                html.push_str("<ul>\n");
                in_list = true;
            }
            html.push_str(&format!("<li>{}</li>\n", bold(&escape_with_code(item))));
        } else {
            html.push_str(&format!("<p>{}</p>\n", bold(&escape_with_code(line))));
        }
    }
    if in_list {
        html.push_str("</ul>\n");
    }
    html.push_str("</section>\n");
    html
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn math_typesets_greek_scripts_and_roots() {
        assert_eq!(math("mu R^2"), "μ R<sup>2</sup>");
        assert_eq!(math("theta1 + sqrt(h/R)"), "θ<sub>1</sub> + √(h/R)");
        assert_eq!(math("a_{ij} x^(n+1)"), "a<sub>ij</sub> x<sup>n+1</sup>");
        assert_eq!(math("cos^2 th < 1 & the"), "cos<sup>2</sup> θ &lt; 1 &amp; the");
        assert_eq!(math("x*y <= 3"), "x·y ≤ 3");
        assert_eq!(math("e^-1"), "e<sup>-1</sup>");
        assert_eq!(math("a ^ b"), "a ^ b");
    }

    #[test]
    fn the_page_links_entries_to_errata_and_back() {
        let entry = |verdict, section: &str| Entry {
            falsification: None,
            section: section.to_string(),
            quantity: "q <x>".to_string(),
            memoir: Memoir::Formula("mu R^2".to_string()),
            derived: Derived::Number(1.5),
            rel_diff: Some(0.0),
            verdict,
            note: "n & m".to_string(),
        };
        let entries = vec![entry(Verdict::Agrees, "4"), entry(Verdict::Ocr, "54")];
        let fig = HtmlFigure {
            file: "f.svg",
            title: "T",
            caption: "C",
            svg: "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"></svg>",
        };
        let html = render_html(&entries, &[], &[], &[fig], "");
        assert!(html.starts_with("<!DOCTYPE html>"));
        assert!(!html.contains("<script"));
        assert!(!html.contains("<?xml"));
        assert!(html.contains("<figure id=\"f.svg\">\n<svg xmlns"));
        assert!(html.contains("<tr class=\"entry v-ocr\" id=\"entry-2\">"));
        assert!(html.contains("<a class=\"verdict\" href=\"#erratum-2\">ocr</a>"));
        assert!(html.contains("id=\"erratum-2\""));
        assert!(html.contains("<a href=\"#entry-2\">↩</a>"));
        assert!(!html.contains("href=\"#erratum-1\""));
        assert!(html.contains("q &lt;x&gt;") && html.contains("n &amp; m"));
        assert!(html.contains("<span class=\"math\">μ R<sup>2</sup></span>"));
        assert!(
            html.contains("2 entries: 1&nbsp;<span class=\"verdict v-agrees\">agrees</span>, 0")
        );
        assert!(html.contains("<span class=\"anchor\" id=\"only-ocr\"></span>"));
    }
}
