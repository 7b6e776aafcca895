//! The concordance of Carvallo's bicycle (memoir Part II): one module per chapter's model, as
//! in `carvallo::bicycle_*`.

pub mod geometry;
pub mod inertia_terms;
pub mod kinematics;
pub mod rest;
pub mod steady;
pub mod steady_claims;
pub mod straight;
pub mod turn;
