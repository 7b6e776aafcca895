//! The Carvallo–Whipple bicycle linearised about upright straight running: the matrices of
//! $M\ddot q + v C_1\dot q + (g K_0 + v^2 K_2) q = f$, $q = (\varphi, \delta)$ (lean, steer),
//! the characteristic polynomial, the eigenvalues and the stable speed range; and around it the
//! nonlinear model, the sweeps over designs and the uncertainty bands.
//!
//! The matrices and the polynomial coefficients are evaluated by [`scene!`](crate::scene)
//! evaluators over `generated/whipple.ir`, derived symbolically from the 25 parameters of the
//! 2007 benchmark (Meijaard, Papadopoulos, Ruina, Schwab, Proc. R. Soc. A 463, Table 1) by
//! `codegen/src/derive/whipple/mod.rs`.
//!
//! The modules build on each other in one direction: the parameters ([`WhippleParams`], the
//! array the evaluators read, and [`BicycleDesign`], the same values by name), the
//! matrices ([`Matrices`], [`matrices_scene`], [`char_poly_scene`]), the stability windows
//! ([`stability`]) and their certified classification ([`certified`]), the model
//! ([`Whipple`]), the sweeps over designs ([`sweep`]). The parameters, matrices and model are
//! re-exported here, at the path they had when they were one file. Beside them:
//! [`nonlinear`] (the full nonlinear equations, memoir Part II), [`uncertainty`] (bands from
//! parameter uncertainties), [`parameter_text`] (BicycleParameters' text format), [`plant`]
//! (the state space with roll and steer torques as inputs), [`transfer`] (its transfer
//! functions and frequency responses) and [`feedback`] (state feedback: closed-loop
//! eigenvalues and stable speed ranges), [`steady_turn`] (the steady turns of the nonlinear
//! model with their contact forces and stability) and [`drawing`] (the points of a side view).

mod design;
mod matrices;
mod model;
mod params;

pub mod certified;
pub mod drawing;
pub mod feedback;
pub mod friction;
pub mod lean_rider;
pub mod modes;
pub mod nonlinear;
pub mod parameter_text;
pub mod plant;
pub mod raw;
pub mod response;
pub mod stability;
pub mod steady_turn;
pub mod sweep;
pub mod transfer;
pub mod uncertainty;
pub mod window_lanes;
pub mod yeadon;

pub use self::design::{BicycleDesign, Body, Wheel, FIELD_PATHS};
pub use self::matrices::{char_poly_scene, matrices_scene, state_matrix, Mat2, Matrices};
pub use self::model::Whipple;
pub use self::params::{
    TriangleSlack, TriangleWarning, WhippleError, WhippleParams, BENCHMARK_TOML, MAX_MAGNITUDE,
    MIN_POSITIVE, PARAM_NAMES, SKATE_RADIUS,
};
pub use self::stability::StabilityWindow;
pub use crate::numerics::eigen::Eigenvalue;
