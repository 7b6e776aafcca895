//! The concordance as JSON (`carvallo report --json`).

use crate::entry::Entry;

/// The entries as a pretty-printed JSON array of objects with the keys `section`, `quantity`,
/// `memoir`, `derived`, `rel_diff`, `verdict`, `note`.
pub fn render_json(entries: &[Entry]) -> String {
    // Serialising plain data with string keys cannot fail.
    serde_json::to_string_pretty(entries).unwrap_or_default()
}
