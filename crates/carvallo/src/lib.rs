//! Fast, verified evaluators for E. Carvallo's rolling hoop (memoir of 1897, Part I ch. I).
//!
//! The formulas are derived symbolically by the `codegen` crate and committed as IR in
//! `generated/`; the [`scene!`] macro turns a chosen subset of their outputs into plain,
//! allocation-free Rust at compile time. This crate wraps those evaluators with validated
//! parameters ([`error`]). The concordance with the memoir's printed formulas and numbers
//! lives in the `carvallo-report` crate, which depends on this one (the old `carvallo::report*`
//! paths are now `carvallo_report::*`).
//!
//! # Layout
//!
//! Two layers, one direction: [`numerics`] (leaves that know no model) and one module per
//! memoir object, each mirrored by `codegen/src/derive/<model>/` and
//! `crates/carvallo-report/src/<model>`:
//!
//! * [`hoop`] (Part I ch. I) and [`hoop::discussion`];
//! * [`unicycle`] (Part I ch. II) and [`unicycle::discussion`];
//! * [`whipple`]: the linearised Carvallo–Whipple bicycle of the 2007 benchmark, with
//!   [`whipple::stability`], [`whipple::certified`], [`whipple::sweep`], [`whipple::nonlinear`],
//!   [`whipple::uncertainty`] and [`whipple::parameter_text`];
//! * [`bicycle`]: Carvallo's bicycle of Part II ([`bicycle::geometry`], [`bicycle::kinematics`],
//!   [`bicycle::rest`], [`bicycle::steady`], [`bicycle::straight`], [`bicycle::turn`]);
//! * [`wheeled_pendulum`]: the two-wheeled inverted pendulum, a rolling system that is not a
//!   bicycle, from the mechanics engine ([`wheeled_pendulum::linear`],
//!   [`wheeled_pendulum::simulation`]); not a memoir object, so it has no concordance report.
//!
//! [`artifacts`] embeds `generated/` (the only `include_str!` of it) and [`error`] holds the
//! one parameter error, which every model's error carries; [`numerics::ode::Trajectory`] is
//! the one shape of a simulated motion. The measurements of `carvallo bench` live in the
//! command line (`crates/carvallo-cli/src/bench/`).
//!
//! # Where the old paths went
//!
//! The old paths still compile (hidden re-exports), but new code should use the new ones.
//!
//! | old path | new path |
//! |---|---|
//! | `carvallo::hoop_discussion` | [`carvallo::hoop::discussion`](hoop::discussion) |
//! | `carvallo::unicycle_discussion` | [`carvallo::unicycle::discussion`](unicycle::discussion) |
//! | `carvallo::whipple::*` | `carvallo::whipple::*` (same names; the files are `whipple/{params, matrices, model}.rs`) |
//! | `carvallo::sweep::{hurwitz_window, eigen_window, scan_window, HurwitzPolys, ...}` | [`carvallo::whipple::stability`](whipple::stability) |
//! | `carvallo::sweep::{sweep, sweep_designs, SweepSummary, Designs, ...}` | [`carvallo::whipple::sweep`](whipple::sweep) |
//! | `carvallo::sweep::{eigenvalues4, MAX_SCHUR_ITERATIONS}` | [`carvallo::numerics::eigen`](numerics::eigen) |
//! | `carvallo::sweep::state_matrix` | [`carvallo::whipple::state_matrix`](whipple::state_matrix) |
//! | `carvallo::certified` | [`carvallo::whipple::certified`](whipple::certified) (`Dd` is [`numerics::dd::Dd`]) |
//! | `carvallo::quartic` | [`carvallo::numerics::quartic`](numerics::quartic) (`hard_suite` is `polynomial_suite` plus the bicycle cases of `carvallo bench`) |
//! | `carvallo::whipple_nonlinear` | [`carvallo::whipple::nonlinear`](whipple::nonlinear) |
//! | `carvallo::whipple_uncertainty` | [`carvallo::whipple::uncertainty`](whipple::uncertainty) |
//! | `carvallo::parameter_text` | [`carvallo::whipple::parameter_text`](whipple::parameter_text) |
//! | `carvallo::bicycle_{geometry, kinematics, rest, steady, straight, turn}` | [`carvallo::bicycle::{geometry, ...}`](bicycle) |
//! | `carvallo::bench::{Rng, random_design}` | [`numerics::rng::SplitMix64`], [`WhippleParams::perturbed`](whipple::WhippleParams::perturbed) |
//! | `carvallo::bench::reference_speeds` | [`carvallo::whipple::stability::reference_speeds`](whipple::stability::reference_speeds) |
//! | `carvallo::bench::{run, Config, Report, render_text, ...}` | the `carvallo` binary (`crates/carvallo-cli/src/bench/`) |
//!
//! The shapes that were repeated became one (issue 12):
//!
//! | old shape | new shape |
//! |---|---|
//! | a parameter set by string key, `params.get("mB")` | still there; by name: [`whipple::BicycleDesign`] (`design.rear_frame.mass`), [`WhippleParams::design`](whipple::WhippleParams::design), [`WhippleParams::from_design`](whipple::WhippleParams::from_design), [`Whipple::from_design`](whipple::Whipple::from_design) |
//! | `WhippleError::InvalidParameter { key, value, reason }` | [`WhippleError::Parameter`](whipple::WhippleError::Parameter)`(ParameterError::InvalidParameter { name, value, reason })`, `name` the key; same message |
//! | `NonlinearError::InvalidParameter { .. }`, `TurnError::InvalidParameter { .. }`, `ContactError::InvalidAngle { .. }` | `NonlinearError::Parameter`, `TurnError::Parameter`, `ContactError::Parameter`, each carrying a [`ParameterError`] (`From` for `?`); same messages |
//! | `hoop::Trajectory { states, energy0, max_energy_drift }` | [`numerics::ode::Trajectory`]`<[f64; 4], hoop::EnergyDrift>` ([`hoop::Trajectory`]): `states` is `samples` (with `times`), `energy0` and `max_energy_drift` read through it |
//! | `whipple::nonlinear::Trajectory { step, samples, energy_drift, max_contact_residual }` | [`numerics::ode::Trajectory`]`<Sample, Diagnostics>` ([`whipple::nonlinear::Trajectory`]): the same fields read the same way, plus `times` |

#![warn(missing_docs)]

pub use carvallo_ir as ir;
pub use carvallo_macros::scene;

pub mod artifacts;
pub mod bicycle;
pub mod error;
pub mod hoop;
pub mod numerics;
pub mod unicycle;
pub mod wheeled_pendulum;
pub mod whipple;

pub use error::ParameterError;

// The flat module names of the first layout, kept so that existing code compiles.
#[doc(hidden)]
pub use bicycle::geometry as bicycle_geometry;
#[doc(hidden)]
pub use bicycle::kinematics as bicycle_kinematics;
#[doc(hidden)]
pub use bicycle::rest as bicycle_rest;
#[doc(hidden)]
pub use bicycle::steady as bicycle_steady;
#[doc(hidden)]
pub use bicycle::straight as bicycle_straight;
#[doc(hidden)]
pub use bicycle::turn as bicycle_turn;
#[doc(hidden)]
pub use hoop::discussion as hoop_discussion;
#[doc(hidden)]
pub use numerics::quartic;
#[doc(hidden)]
pub use unicycle::discussion as unicycle_discussion;
#[doc(hidden)]
pub use whipple::certified;
#[doc(hidden)]
pub use whipple::nonlinear as whipple_nonlinear;
#[doc(hidden)]
pub use whipple::parameter_text;
#[doc(hidden)]
pub use whipple::uncertainty as whipple_uncertainty;

/// The old `carvallo::sweep`: the stability windows, the eigenvalues and the sweeps.
#[doc(hidden)]
pub mod sweep {
    pub use crate::numerics::eigen::{eigenvalues4, MAX_SCHUR_ITERATIONS};
    pub use crate::whipple::stability::*;
    pub use crate::whipple::state_matrix;
    pub use crate::whipple::sweep::*;
}

/// The library's part of the old `carvallo::bench` (the rest is in the `carvallo` binary).
#[doc(hidden)]
pub mod bench {
    use crate::numerics::rng::SplitMix64;
    pub use crate::whipple::stability::reference_speeds;
    use crate::whipple::WhippleParams;

    /// The old seeded generator: [`SplitMix64`] with `next_f64` for `next_unit`.
    #[derive(Clone, Debug)]
    pub struct Rng(pub SplitMix64);

    impl Rng {
        /// The generator with `seed`.
        pub fn new(seed: u64) -> Rng {
            Rng(SplitMix64(seed))
        }

        /// The next number in [0, 1).
        pub fn next_f64(&mut self) -> f64 {
            self.0.next_unit()
        }

        /// `x` scaled by a uniform factor in [1 - spread, 1 + spread].
        pub fn scale(&mut self, x: f64, spread: f64) -> f64 {
            self.0.scale(x, spread)
        }
    }

    /// The benchmark with every parameter scaled in [0.8, 1.2]:
    /// `WhippleParams::benchmark().perturbed(rng, 0.2)`.
    pub fn random_design(rng: &mut Rng) -> WhippleParams {
        WhippleParams::benchmark().perturbed(&mut rng.0, 0.2)
    }
}
