//! Numerical leaves shared by the models: each primitive written once, depending on nothing
//! else in the crate.

pub mod rng;
