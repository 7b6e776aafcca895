//! Carvallo's bicycle, memoir Part II: the geometry of the frame and its contacts
//! ([`geometry`]), the rolling constraints ([`kinematics`]), the bicycle at rest ([`rest`]),
//! steady motion ([`steady`]), straight running and its stability ([`straight`]) and steady
//! turning ([`turn`]). Each module has its namesake in `crates/carvallo-report/src/bicycle/`
//! and, where its formulas are derived, in `codegen/src/derive/bicycle/`.

pub mod geometry;
pub mod kinematics;
pub mod rest;
pub mod steady;
pub mod straight;
pub mod turn;
