//! Numerical leaves shared by the models: each primitive written once, depending on nothing
//! else in the crate (a `tidy` test checks it).

pub mod dd;
pub mod eigen;
pub mod graeffe;
pub mod integrate;
pub mod mat2;
pub mod ode;
pub mod poly;
pub mod quartic;
pub mod rng;
