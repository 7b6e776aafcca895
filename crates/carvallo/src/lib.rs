//! Fast, verified evaluators for E. Carvallo's rolling hoop (memoir of 1897, Part I ch. I).
//!
//! The formulas are derived symbolically by the `codegen` crate and committed as IR in
//! `generated/`; the [`scene!`] macro turns a chosen subset of their outputs into plain,
//! allocation-free Rust at compile time. This crate wraps those evaluators with validated
//! parameters ([`error`]). The concordance with the memoir's printed formulas and numbers
//! lives in the `carvallo-report` crate, which depends on this one (the old `carvallo::report*`
//! paths are now `carvallo_report::*`).

#![warn(missing_docs)]

pub use carvallo_ir as ir;
pub use carvallo_macros::scene;

pub mod artifacts;
pub mod bench;
pub mod bicycle_geometry;
pub mod bicycle_kinematics;
pub mod bicycle_rest;
pub mod bicycle_steady;
pub mod bicycle_straight;
pub mod bicycle_turn;
pub mod certified;
pub mod error;
pub mod hoop;
pub mod hoop_discussion;
pub mod numerics;
pub mod parameter_text;
pub mod quartic;
pub mod sweep;
pub mod unicycle;
pub mod unicycle_discussion;
pub mod whipple;
pub mod whipple_nonlinear;
pub mod whipple_uncertainty;

pub use error::ParameterError;
