//! The symbolic side of Carvallo: every derivation of the memoir, done with the `symbolica`
//! computer-algebra crate, and the emission of its results into `generated/`.
//!
//! This is the only library of the workspace that depends on symbolica. A derivation module
//! (one per memoir object under [`derive`]: the hoop, the unicycle, the Carvallo–Whipple
//! bicycle and Carvallo's bicycle) returns a
//! [`Derivation`]: the closed-form formulas the runtime needs, as symbolica expressions whose
//! symbols are the model's parameter and input names, plus the symbolic [`Check`]s that were run
//! on the way (for example "the modified Lagrange equations agree with the moments of the
//! inertia forces", memoir n° 72–73). The emission (module `emit`) turns a derivation into the
//! committed artifacts `generated/<model>.ir` (IR, see the `carvallo-ir` crate),
//! `generated/<model>.md` (readable text and LaTeX rendering) and
//! `generated/<model>.checks.tsv` (the checks and their outcomes).

use symbolica::atom::Atom;

/// One closed-form formula that becomes an output of the model's IR program.
#[derive(Clone, Debug)]
pub struct Formula {
    /// Output name in the IR (snake case, for example `pns_dp` or `equilibrium`).
    pub name: String,
    /// Memoir section number as printed in its table of contents (for example `"8"`).
    pub section: String,
    /// One sentence saying what the formula is, with its units.
    pub description: String,
    /// The formula; its symbols are the derivation's parameters and inputs.
    pub expr: Atom,
}

/// The outcome of one symbolic check made during a derivation.
#[derive(Clone, Debug)]
pub struct Check {
    /// Memoir section number the check belongs to.
    pub section: String,
    /// Short stable identifier (snake case), unique within the derivation.
    pub id: String,
    /// What was checked, in one sentence.
    pub statement: String,
    /// Whether it holds. A check that does not hold is a finding, not a failure: for example
    /// the *unmodified* Lagrange equations (n° 71) must fail to reproduce n° 7.
    pub holds: bool,
    /// The evidence: for example the simplified difference of the two sides.
    pub detail: String,
    /// The same check run again on a perturbed derived side (issue 38), when one is stated.
    pub perturbed: Option<Perturbed>,
}

/// A check run again with its derived side perturbed (a model symbol of it scaled, see
/// [`falsify`]): what was changed and whether the check still holds. A check that can fail
/// no longer holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Perturbed {
    /// What was changed, in words (for example "every `mu` of the derived side scaled by 9/8").
    pub what: String,
    /// Whether the check holds with the change.
    pub holds: bool,
}

/// Everything one model's derivation produces.
#[derive(Clone, Debug)]
pub struct Derivation {
    /// Model name: the IR `model` line and the file stem under `generated/`.
    pub model: String,
    /// The source file that derives it, for the generated headers (`file!()` of the
    /// derivation, for example `codegen/src/derive/hoop/mod.rs`).
    pub source: String,
    /// Parameter names (fixable by a scene), in order.
    pub params: Vec<String>,
    /// Input names (state and free variables), in order.
    pub inputs: Vec<String>,
    /// The formulas, in output order.
    pub formulas: Vec<Formula>,
    /// The symbolic checks, in the order they were made.
    pub checks: Vec<Check>,
    /// Nominal values of some parameters and inputs, by name: where the model is evaluated in
    /// practice (`derive::nominal`), for the lowering's second error sample; empty for none.
    pub nominal: Vec<(String, f64)>,
    /// Further numbers of Horner schemes the optimising lowering tries on this model after
    /// [`emit::EFFORTS`] (for a program on a hot path, where operations saved pay at every
    /// call); empty for most.
    pub horner_schemes: Vec<usize>,
}

pub mod cas;
pub mod derive;
pub mod emit;
pub mod falsify;
pub mod mechanics;
pub mod memoir;
pub mod regen;
