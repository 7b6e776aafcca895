//! The report's text with float noise removed, as the snapshot tests compare it.

use crate::render::number::format_significant;

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
