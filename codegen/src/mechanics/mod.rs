//! The mechanics the derivations are written in: the moving trihedra, Grassmann's product and
//! derivatives of moving vectors of the memoir's n° 1–3 ([`frame`]), and the ε-series and small
//! vector algebra of the exact linearisation ([`series`]).

pub mod engine;
pub mod frame;
pub mod series;
