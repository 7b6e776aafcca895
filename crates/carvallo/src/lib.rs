//! Fast, verified evaluators for E. Carvallo's rolling hoop (memoir of 1897, Part I ch. I).
//!
//! The formulas are derived symbolically by the `codegen` crate and committed as IR in
//! `generated/`; the [`scene!`] macro turns a chosen subset of their outputs into plain,
//! allocation-free Rust at compile time. This crate wraps those evaluators with validated
//! parameters ([`error`]) and compares every derived formula with the memoir's printed one
//! ([`report`]).

pub use carvallo_ir as ir;
pub use carvallo_macros::scene;

pub mod bicycle_geometry;
pub mod error;
pub mod hoop;
pub mod hoop_discussion;
pub mod report;
pub mod report_bicycle_geometry;
pub mod report_unicycle;
pub mod report_hoop_discussion;
pub mod report_whipple;
pub mod unicycle;
pub mod whipple;

pub use error::ParameterError;
