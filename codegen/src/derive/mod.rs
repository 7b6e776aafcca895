//! Every derivation of the memoir, one folder per memoir object, and the table `cargo xtask
//! regen` runs ([`DERIVATIONS`]). The model names are the file stems under `generated/` and the
//! module paths here: `derive::bicycle::geometry` writes `generated/bicycle_geometry.*`.

pub mod bicycle;
pub mod hoop;
pub mod nominal;
pub mod symbols;
pub mod unicycle;
pub mod wheeled_pendulum;
pub mod whipple;

use anyhow::Result;

pub use symbols::declare_symbols;

use crate::Derivation;

/// A derivation entry point.
pub type DeriveFn = fn() -> Result<Derivation>;

/// Every derivation `cargo xtask regen` runs, in order: (model name, entry point).
pub const DERIVATIONS: &[(&str, DeriveFn)] = &[
    ("hoop", hoop::derive),
    ("hoop_discussion", hoop::discussion::derive),
    ("whipple", whipple::derive),
    ("unicycle", unicycle::derive),
    ("whipple_nonlinear", whipple::nonlinear::derive),
    ("bicycle_steady", bicycle::steady::derive),
    ("bicycle_geometry", bicycle::geometry::derive),
    ("bicycle_kinematics", bicycle::kinematics::derive),
    ("bicycle_straight", bicycle::straight::derive),
    ("lean_rider", whipple::lean_rider::derive),
    ("wheeled_pendulum", wheeled_pendulum::derive),
];
