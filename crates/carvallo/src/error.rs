//! Typed errors of the runtime library.
//!
//! The evaluators themselves never fail: they are straight-line floating-point code. What can be
//! wrong is the data a user hands to a model constructor (a negative radius, a zero mass, a
//! non-finite gravity), and that is reported here with the offending name and value.
//!
//! [`ParameterError`] is the one shape of "this input value is invalid". The models' own error
//! enums, which add the failures that are not about one value (a parse error, no contact, no
//! convergence), carry it in a `Parameter` variant with a `From` conversion, so that `?` lifts
//! it and the message is the same everywhere (`invalid <name> <value>: <reason>`):
//! [`WhippleError::Parameter`](crate::whipple::WhippleError::Parameter) (its name is the
//! benchmark key), [`NonlinearError::Parameter`](crate::whipple::nonlinear::NonlinearError::Parameter),
//! [`TurnError::Parameter`](crate::bicycle::turn::TurnError::Parameter) and
//! [`ContactError::Parameter`](crate::bicycle::geometry::ContactError::Parameter) (reached
//! through [`RestError::Contact`](crate::bicycle::rest::RestError::Contact)). The sweeps'
//! [`SweepError::InvalidCount`](crate::whipple::sweep::SweepError::InvalidCount) (an integer)
//! and [`DesignsError::InvalidSpread`](crate::whipple::sweep::DesignsError::InvalidSpread) (a
//! spread of a named parameter, with its own message) keep their shapes.

use std::fmt;

/// A model parameter that cannot describe a physical system.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParameterError {
    /// The parameter `name` has the value `value`, which is not allowed for the stated reason.
    InvalidParameter {
        /// The parameter's name as the constructor spells it (for example `"radius"`).
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// Why it was rejected, in a few lower-case words (for example `"must be positive"`).
        reason: &'static str,
    },
}

impl ParameterError {
    /// Checks that `value` is finite and strictly positive, the requirement shared by lengths,
    /// masses and the gravitational acceleration.
    ///
    /// # Errors
    /// [`ParameterError::InvalidParameter`] naming `name` when `value` is NaN, infinite, zero
    /// or negative.
    pub fn check_positive(name: &'static str, value: f64) -> Result<f64, ParameterError> {
        if !value.is_finite() {
            Err(ParameterError::InvalidParameter { name, value, reason: "must be finite" })
        } else if value <= 0.0 {
            Err(ParameterError::InvalidParameter { name, value, reason: "must be positive" })
        } else {
            Ok(value)
        }
    }
}

impl fmt::Display for ParameterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParameterError::InvalidParameter { name, value, reason } => {
                write!(f, "invalid {name} {value:?}: {reason}")
            }
        }
    }
}

impl std::error::Error for ParameterError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_names_parameter_and_value() {
        let err = ParameterError::check_positive("radius", -0.5).unwrap_err();
        assert_eq!(err.to_string(), "invalid radius -0.5: must be positive");
        let err = ParameterError::check_positive("g", f64::NAN).unwrap_err();
        assert_eq!(err.to_string(), "invalid g NaN: must be finite");
        assert_eq!(ParameterError::check_positive("mass", 2.0), Ok(2.0));
    }
}
