//! Fast, verified evaluators for E. Carvallo's rolling hoop (memoir of 1897, Part I ch. I).
//!
//! The formulas are derived symbolically by the `codegen` crate and committed as IR in
//! `generated/`; the [`scene!`] macro turns a chosen subset of their outputs into plain,
//! allocation-free Rust at compile time. This crate wraps those evaluators with validated
//! parameters ([`error`]) and compares every derived formula with the memoir's printed one
//! ([`report`]).

#![warn(missing_docs)]

pub use carvallo_ir as ir;
pub use carvallo_macros::scene;

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
pub mod parameter_text;
pub mod quartic;
pub mod report;
pub mod report_bicycle_geometry;
pub mod report_bicycle_kinematics;
pub mod report_bicycle_rest;
pub mod report_bicycle_steady;
pub mod report_bicycle_straight;
pub mod report_bicycle_turn;
pub mod report_hoop_discussion;
pub mod report_markdown;
pub mod report_unicycle;
pub mod report_whipple;
pub mod sweep;
pub mod unicycle;
pub mod unicycle_discussion;
pub mod whipple;
pub mod whipple_nonlinear;
pub mod whipple_uncertainty;

pub use error::ParameterError;
