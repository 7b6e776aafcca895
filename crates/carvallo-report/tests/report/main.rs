//! The concordance tests, one binary with a module per model (as `carvallo_report`'s modules):
//! each model's expected verdicts (its findings listed), its sections present, and a snapshot
//! of its text table with numbers normalised to 4 significant digits
//! (`snapshots/report__<model>__<model>_report_text.snap`).

mod common;

mod bicycle_geometry;
mod bicycle_kinematics;
mod bicycle_rest;
mod bicycle_steady;
mod bicycle_straight;
mod bicycle_turn;
mod falsify;
mod hoop;
mod hoop_discussion;
mod policy;
mod registry;
mod unicycle;
