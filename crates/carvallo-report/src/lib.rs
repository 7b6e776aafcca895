//! The memoir concordance: every formula and number E. Carvallo printed in his memoir of 1897
//! on the hoop, the unicycle and the bicycle, set beside the value the `carvallo` library
//! derives for it when the report runs, with a verdict and a note.
//!
//! Layers: this crate depends on `carvallo` (numerics and models) and nothing in `carvallo`
//! depends on it, so a model cannot reach into the report for its maths. Each model of the
//! library has one report module here ([`REPORTS`]); they share the entry shape ([`entry`]),
//! one verdict policy ([`policy`]), the seeded sample points ([`sample`]), the reading of the
//! symbolic checks ([`checks`]) and the renderers ([`render`]).
//!
//! # Where the old paths went
//! Before this crate existed the report lived in `carvallo` itself. The names are the same:
//!
//! | old path | new path |
//! |---|---|
//! | `carvallo::report::{Entry, Verdict, Memoir, Derived}` | `carvallo_report::{Entry, Verdict, Memoir, Derived}` |
//! | `carvallo::report::{all_entries, hoop_entries}` | `carvallo_report::{all_entries, hoop_entries}` |
//! | `carvallo::report::{render_text, render_text_normalised, render_json}` | `carvallo_report::{...}` (same names) |
//! | `carvallo::report::{format_significant, normalise_numbers}` | `carvallo_report::{...}` |
//! | `carvallo::report::{AGREEMENT_TOLERANCE, REL_DIFF_FLOOR}` | `carvallo_report::policy::{...}` (also at the root) |
//! | `carvallo::report::{parse_checks, SymbolicCheck}` | `carvallo::artifacts::{...}` (re-exported here) |
//! | `carvallo::report_markdown::*` | `carvallo_report::render::markdown::*` |
//! | `carvallo::report_hoop_discussion`, `report_unicycle`, `report_whipple` | `carvallo_report::{hoop_discussion, unicycle, whipple}` |
//! | `carvallo::report_bicycle_{geometry, kinematics, rest, steady, straight, turn}` | `carvallo_report::bicycle::{geometry, ...}` |

#![warn(missing_docs)]

pub mod bicycle;
pub mod checks;
pub mod claims;
pub mod entry;
pub mod hoop;
pub mod hoop_discussion;
mod hoop_simulation;
pub mod outline;
pub mod perturb;
pub mod policy;
pub mod render;
pub mod sample;
pub mod unicycle;
pub mod whipple;

pub use checks::{parse_checks, SymbolicCheck};
pub use claims::{Assertion, Claim, Falsification, Status};
pub use entry::{Derived, Entry, Memoir, Verdict};
pub use hoop::hoop_entries;
pub use policy::{AGREEMENT_TOLERANCE, REL_DIFF_FLOOR};
pub use render::json::render_json;
pub use render::markdown::render_markdown;
pub use render::normalise::normalise_numbers;
pub use render::text::{format_significant, render_text, render_text_normalised};

/// One model's concordance: the model (as in `generated/<model>.*` and the `carvallo` module
/// of that name), the memoir's sections it covers, and the function that computes its entries.
#[derive(Clone, Copy, Debug)]
pub struct Report {
    /// The model's name (`hoop`, `bicycle_geometry`, ...).
    pub model: &'static str,
    /// The memoir's sections (n°) the report covers, as text.
    pub sections: &'static str,
    /// Computes the entries now, from the generated evaluators and the recorded checks.
    pub entries: fn() -> Vec<Entry>,
    /// Checks the memoir's claims in these sections now ([`claims`]).
    pub claims: fn() -> Vec<Claim>,
    /// Every assertion of the memoir in these sections, with how it is covered.
    pub inventory: &'static [Assertion],
}

/// Every model's report, in the order their entries are gathered by [`all_entries`] (the
/// order the models were added; a stable sort by section then puts them in memoir order, and
/// within one section this order decides, so it must not change without a reason).
pub const REPORTS: [Report; 10] = [
    Report {
        model: "hoop",
        sections: "4–19, 71–77",
        entries: hoop::entries,
        claims: hoop::claims,
        inventory: hoop::INVENTORY,
    },
    Report {
        model: "unicycle",
        sections: "21–41, 74, 78",
        entries: unicycle::entries,
        claims: unicycle::claims,
        inventory: unicycle::INVENTORY,
    },
    Report {
        model: "hoop_discussion",
        sections: "13–19",
        entries: hoop_discussion::entries,
        claims: hoop_discussion::claims,
        inventory: hoop_discussion::INVENTORY,
    },
    Report {
        model: "whipple",
        sections: "modern benchmark",
        entries: whipple::entries,
        claims: whipple::claims,
        inventory: whipple::INVENTORY,
    },
    Report {
        model: "bicycle_steady",
        sections: "79–100",
        entries: bicycle::steady::entries,
        claims: bicycle::steady::claims,
        inventory: bicycle::steady::INVENTORY,
    },
    Report {
        model: "bicycle_turn",
        sections: "101–106",
        entries: bicycle::turn::entries,
        claims: bicycle::turn::claims,
        inventory: bicycle::turn::INVENTORY,
    },
    Report {
        model: "bicycle_straight",
        sections: "107–124",
        entries: bicycle::straight::entries,
        claims: bicycle::straight::claims,
        inventory: bicycle::straight::INVENTORY,
    },
    Report {
        model: "bicycle_geometry",
        sections: "43–58",
        entries: bicycle::geometry::entries,
        claims: bicycle::geometry::claims,
        inventory: bicycle::geometry::INVENTORY,
    },
    Report {
        model: "bicycle_kinematics",
        sections: "59–69",
        entries: bicycle::kinematics::entries,
        claims: bicycle::kinematics::claims,
        inventory: bicycle::kinematics::INVENTORY,
    },
    Report {
        model: "bicycle_rest",
        sections: "67",
        entries: bicycle::rest::entries,
        claims: bicycle::rest::claims,
        inventory: bicycle::rest::INVENTORY,
    },
];

/// The whole concordance: every report of [`REPORTS`], in memoir order (a stable sort by the
/// section's leading number; entries without one last).
pub fn all_entries() -> Vec<Entry> {
    let mut entries: Vec<Entry> = REPORTS.iter().flat_map(falsified_entries).collect();
    // Stable sort: the models' own orders are kept within a section.
    entries
        .sort_by(|a, b| entry::section_key(&a.section).total_cmp(&entry::section_key(&b.section)));
    entries
}

/// The entries of `report` with their falsifications ([`perturb::falsify_entries`]): the
/// generated programs searched for the outputs an entry names are the report's own model's
/// first, then every other embedded model's.
pub fn falsified_entries(report: &Report) -> Vec<Entry> {
    let mut models: Vec<&'static str> =
        carvallo::artifacts::MODELS.iter().map(|a| a.model).collect();
    models.sort_by_key(|m| *m != report.model);
    perturb::falsify_entries((report.entries)(), &models, report.entries)
}

/// Every claim of every report, in memoir order (a stable sort by section as for the entries).
pub fn all_claims() -> Vec<Claim> {
    let mut claims: Vec<Claim> = REPORTS.iter().flat_map(|r| (r.claims)()).collect();
    claims
        .sort_by(|a, b| entry::section_key(&a.section).total_cmp(&entry::section_key(&b.section)));
    claims
}

/// Every assertion of the memoir found n° by n°, in memoir order.
pub fn all_assertions() -> Vec<Assertion> {
    let mut all: Vec<Assertion> =
        REPORTS.iter().flat_map(|r| r.inventory.iter().copied()).collect();
    all.sort_by(|a, b| entry::section_key(a.section).total_cmp(&entry::section_key(b.section)));
    all
}
