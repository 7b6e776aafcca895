//! The README and the guide cannot go stale: every `$ carvallo ...` example in the `text` code
//! blocks of `README.md` and of every page of the guide (`docs/guide/src/*.md`) is run with the
//! built binary (in a fresh temporary directory, so `report --out report` writes there) and its
//! output compared with the lines the page shows. Every relative link of the README and of the
//! guide's pages names a file that exists (the guide's build, `mkdocs build --strict` in
//! `scripts/test`, checks the links between its pages too).
//!
//! Matching rules: an expected line `...` stands for any number of output lines (also none); an
//! expected line ending in `...` matches an output line that starts with the text before it;
//! numbers are compared after rounding to 9 significant digits, so the last digits of a float
//! may differ between platforms. A command may end in `| head -N` (first N lines). Standard
//! error is appended to standard output (the README shows error messages too).
//!
//! The README's main command `report --out report` is among the examples; the directory it
//! wrote is then checked (report sections, every linked figure an SVG with text, and the
//! README's picture `docs/fig04bis_hoop_walking.svg` and the guide's hands-free figure
//! `docs/guide/src/img/benchmark_hands_free.svg` identical to the ones written now).

use std::path::{Path, PathBuf};
use std::process::Command;

struct Example {
    line: usize,
    command: String,
    expected: Vec<String>,
}

fn examples(readme: &str) -> Vec<Example> {
    let mut out: Vec<Example> = Vec::new();
    let mut in_text = false;
    // Whether the lines that follow belong to the last example (reset at every fence).
    let mut open = false;
    for (i, line) in readme.lines().enumerate() {
        if line.starts_with("```") {
            in_text = line.trim() == "```text" && !in_text;
            open = false;
            continue;
        }
        if !in_text {
            continue;
        }
        if let Some(cmd) = line.strip_prefix("$ carvallo") {
            out.push(Example {
                line: i + 1,
                command: cmd.trim().to_string(),
                expected: Vec::new(),
            });
            open = true;
        } else if line.starts_with("$ ") {
            open = false; // another program: not replayed
        } else if let (true, Some(ex)) = (open, out.last_mut()) {
            ex.expected.push(line.to_string());
        }
    }
    out
}

/// Rounds every number in `line` to 9 significant digits.
fn normalise(line: &str) -> String {
    let chars: Vec<char> = line.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let starts_number = chars[i].is_ascii_digit()
            || (chars[i] == '-' && chars.get(i + 1).is_some_and(|c| c.is_ascii_digit()));
        let after_word = i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_');
        if starts_number && !after_word {
            let mut j = i + 1;
            while j < chars.len() && (chars[j].is_ascii_digit() || chars[j] == '.') {
                j += 1;
            }
            if j < chars.len() && chars[j] == 'e' {
                let mut k = j + 1;
                if k < chars.len() && (chars[k] == '-' || chars[k] == '+') {
                    k += 1;
                }
                if k < chars.len() && chars[k].is_ascii_digit() {
                    j = k;
                    while j < chars.len() && chars[j].is_ascii_digit() {
                        j += 1;
                    }
                }
            }
            let token: String = chars[i..j].iter().collect();
            match token.parse::<f64>() {
                Ok(x) if token.contains('.') || token.contains('e') => {
                    out.push_str(&format!("{x:.8e}"))
                }
                _ => out.push_str(&token),
            }
            i = j;
        } else {
            out.push(chars[i]);
            i += 1;
        }
    }
    out
}

fn line_matches(expected: &str, actual: &str) -> bool {
    match expected.strip_suffix("...") {
        Some(prefix) => normalise(actual).starts_with(&normalise(prefix)),
        None => normalise(expected) == normalise(actual),
    }
}

/// Whether `actual` matches `expected` with `...` lines standing for any run of lines.
fn matches(expected: &[String], actual: &[&str]) -> bool {
    match expected.split_first() {
        None => actual.is_empty(),
        Some((e, rest)) if e.trim() == "..." => {
            (0..=actual.len()).any(|k| matches(rest, &actual[k..]))
        }
        Some((e, rest)) => {
            actual.split_first().is_some_and(|(a, tail)| line_matches(e, a) && matches(rest, tail))
        }
    }
}

fn run(command: &str, dir: &Path) -> String {
    let (cmd, head) = match command.split_once('|') {
        Some((c, h)) => {
            let n = h.trim().strip_prefix("head -").and_then(|n| n.parse::<usize>().ok());
            (c.trim(), Some(n.unwrap_or_else(|| panic!("unsupported pipe in `{command}`"))))
        }
        None => (command, None),
    };
    let out = Command::new(env!("CARGO_BIN_EXE_carvallo"))
        .args(cmd.split_whitespace())
        .current_dir(dir)
        .output()
        .unwrap();
    let mut text = String::from_utf8(out.stdout).unwrap();
    text.push_str(&String::from_utf8(out.stderr).unwrap());
    match head {
        Some(n) => text.lines().take(n).map(|l| format!("{l}\n")).collect(),
        None => text,
    }
}

/// A fresh directory to run the examples in, with the workspace's `data/` linked into it, so
/// that the pages' examples name the parameter files as a reader at the workspace root would.
fn scratch() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("carvallo-readme-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data");
    std::os::unix::fs::symlink(data.canonicalize().unwrap(), dir.join("data")).unwrap();
    dir
}

/// The README and the guide's pages, each with its path relative to the workspace.
fn pages() -> Vec<(String, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut names = vec!["README.md".to_string()];
    let guide = root.join("docs/guide/src");
    let mut in_guide: Vec<String> = std::fs::read_dir(&guide)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".md"))
        .map(|n| format!("docs/guide/src/{n}"))
        .collect();
    in_guide.sort();
    names.extend(in_guide);
    names
        .into_iter()
        .map(|n| {
            let text = std::fs::read_to_string(root.join(&n)).unwrap();
            (n, text)
        })
        .collect()
}

#[test]
fn every_cli_example_in_the_readme_and_the_guide_replays() {
    let pages = pages();
    assert!(pages.len() >= 10, "expected the README and the guide's pages, found {}", pages.len());
    let dir = scratch();
    let mut failures = Vec::new();
    let mut commands = Vec::new();
    for (name, text) in &pages {
        let list = examples(text);
        if name == "README.md" {
            assert!(
                list.len() >= 2,
                "expected at least 2 CLI examples in the README, found {}",
                list.len()
            );
        }
        for ex in &list {
            let output = run(&ex.command, &dir);
            let lines: Vec<&str> = output.lines().collect();
            if !matches(&ex.expected, &lines) {
                failures.push(format!(
                    "{name} line {}: `carvallo {}`\n--- the page shows:\n{}\n--- the binary prints:\n{}",
                    ex.line,
                    ex.command,
                    ex.expected.join("\n"),
                    output
                ));
            }
            commands.push(ex.command.clone());
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    assert!(commands.iter().any(|c| c == "report --out report"), "the README's main command");
    check_report_dir(&dir.join("report"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn every_relative_link_names_a_file() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut broken = Vec::new();
    for (name, text) in pages() {
        let base = root.join(&name);
        let base = base.parent().unwrap();
        for target in text.split("](").skip(1).filter_map(|t| t.split_once(')')).map(|(l, _)| l) {
            let file = target.split('#').next().unwrap_or("");
            if file.is_empty() || file.contains("://") {
                continue;
            }
            if !base.join(file).exists() {
                broken.push(format!("{name}: ({target})"));
            }
        }
    }
    assert!(broken.is_empty(), "links to no file: {}", broken.join(", "));
}

/// The directory the README's `report --out report` wrote: the report with its sections, every
/// figure it links (SVG documents with text), the HTML page with every figure inline, and the
/// README's picture identical to its copy.
fn check_report_dir(out: &Path) {
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    for heading in ["## Figures", "### Figures not drawn yet", "## Concordance", "## Errata"] {
        assert!(md.contains(heading), "report.md has no `{heading}`");
    }
    let links: Vec<&str> =
        md.split("](").skip(1).filter_map(|t| t.split_once(')')).map(|(l, _)| l).collect();
    assert!(links.len() >= 8, "report.md links {} figures", links.len());
    for link in links {
        let svg = std::fs::read_to_string(out.join(link)).unwrap();
        assert!(svg.starts_with("<svg") && svg.contains("<text"), "{link} is not an SVG with text");
        assert!(svg.len() < 400_000, "{link} is {} bytes", svg.len());
    }
    // The HTML page: every SVG figure inline, no script (the browser test opens it).
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>") && !html.contains("<script"));
    for entry in std::fs::read_dir(out).unwrap() {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        if name.ends_with(".svg") {
            assert!(html.contains(&format!("<figure id=\"{name}\">\n<svg")), "{name} not inline");
        }
    }
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/fig04bis_hoop_walking.svg");
    assert!(
        std::fs::read(&docs).unwrap()
            == std::fs::read(out.join("fig04bis_hoop_walking.svg")).unwrap(),
        "docs/fig04bis_hoop_walking.svg differs from what `carvallo report --out` writes now: \
         copy report/fig04bis_hoop_walking.svg over it"
    );
    let guide = docs.with_file_name("guide/src/img/fig04bis_hoop_walking.svg");
    assert!(
        std::fs::read(&guide).unwrap() == std::fs::read(&docs).unwrap(),
        "docs/guide/src/img/fig04bis_hoop_walking.svg differs from docs/fig04bis_hoop_walking.svg"
    );
    // The guide's hands-free figure (docs/guide/src/bicycle-steady.md) is the report's.
    let hands_free = docs.with_file_name("guide/src/img/benchmark_hands_free.svg");
    assert!(
        std::fs::read(&hands_free).unwrap()
            == std::fs::read(out.join("benchmark_hands_free.svg")).unwrap(),
        "docs/guide/src/img/benchmark_hands_free.svg differs from what `carvallo report --out` \
         writes now: copy report/benchmark_hands_free.svg over it"
    );
}

#[test]
fn the_matcher_elides_and_rounds() {
    let exp: Vec<String> = ["a 1.0000000001", "...", "z..."].map(String::from).to_vec();
    assert!(matches(&exp, &["a 1.0", "b", "c", "zebra"]));
    // Integers are compared as written.
    assert!(!line_matches("a 1.0", "a 1"));
    assert!(!matches(&exp, &["a 1.1", "zebra"]));
    assert!(!matches(&exp, &["a 1.0", "b"]));
    assert_eq!(normalise("x2 = -4.2923825363411"), "x2 = -4.29238254e0");
}
