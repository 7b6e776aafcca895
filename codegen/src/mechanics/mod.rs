//! The mechanics the derivations are written in: the moving trihedra, Grassmann's product and
//! derivatives of moving vectors of the memoir's n° 1–3 ([`frame`]), and the mechanics engine
//! that derives a rolling system from its description ([`engine`]).

pub mod engine;
pub mod frame;
