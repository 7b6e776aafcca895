//! Python bindings of the `carvallo` runtime crate: the Carvallo–Whipple bicycle's matrices,
//! eigenvalues, stability windows (one or many designs), sweeps, nonlinear simulation, the
//! uncertainty propagation of [`carvallo::whipple_uncertainty`] and the memoir concordance,
//! with numpy arrays in and out; and the two-wheeled inverted pendulum of
//! [`carvallo::wheeled_pendulum`] (its eigenvalues, state space and simulation).
//!
//! The crate has two layers. This file is plain Rust (no Python): reading a parameter mapping
//! into a validated [`WhippleParams`] with errors that name the key and the value, and the
//! uncertainties beside it. The module `python` (feature `python`, turned on by maturin through
//! `pyproject.toml`) is the PyO3 module `carvallo`; without the feature the crate builds and
//! tests with the rest of the workspace and needs no Python.

use carvallo::parameter_text::UncertainParams;
use carvallo::whipple::{TriangleWarning, WhippleParams, PARAM_NAMES};

#[cfg(feature = "python")]
mod common;
#[cfg(feature = "python")]
mod guard;
#[cfg(feature = "python")]
mod lean_rider;
#[cfg(feature = "python")]
mod python;
#[cfg(feature = "python")]
mod rolling;
#[cfg(feature = "python")]
mod steady_turn;
#[cfg(feature = "python")]
mod wheeled_pendulum;
#[cfg(feature = "python")]
mod yeadon;

/// The parameter name as written by the user: the benchmark's (`lambda`) or BicycleParameters'
/// (`lam`) name of the steer axis tilt, the others as in [`PARAM_NAMES`].
fn index_of(name: &str) -> Option<usize> {
    let key = if name == "lam" { "lambda" } else { name };
    PARAM_NAMES.iter().position(|n| *n == key)
}

/// The values of a mapping `name -> value` in the order of [`PARAM_NAMES`], every name once.
///
/// # Errors
/// A lower-case message naming the key (and the value) at fault: an unknown name, a name given
/// twice (`lam` and `lambda`), a missing name.
pub fn values_from_pairs(pairs: &[(String, f64)]) -> Result<[f64; 26], String> {
    let mut values = [f64::NAN; 26];
    let mut seen = [false; 26];
    for (name, value) in pairs {
        let k = index_of(name).ok_or_else(|| {
            format!(
                "unknown parameter {name} = {value:?} (the names are {})",
                PARAM_NAMES.join(", ")
            )
        })?;
        if seen[k] {
            return Err(format!("parameter {} given twice ({name} = {value:?})", PARAM_NAMES[k]));
        }
        seen[k] = true;
        values[k] = *value;
    }
    if let Some(k) = seen.iter().position(|s| !s) {
        return Err(format!("missing parameter {}", PARAM_NAMES[k]));
    }
    Ok(values)
}

/// A validated bicycle from a mapping `name -> value` (see [`values_from_pairs`]).
///
/// # Errors
/// As [`values_from_pairs`], or [`WhippleParams::from_values`]'s error, which names the key and
/// the value.
pub fn params_from_pairs(pairs: &[(String, f64)]) -> Result<WhippleParams, String> {
    WhippleParams::from_values(values_from_pairs(pairs)?).map_err(|e| e.to_string())
}

/// A bicycle from a mapping `name -> value` as the readers of parameter files take it
/// ([`WhippleParams::from_values_warning`]): moments of inertia breaking a triangle inequality
/// are accepted and returned as warnings, or, when `strict`, an error as in
/// [`params_from_pairs`].
///
/// # Errors
/// As [`params_from_pairs`] (with `strict`) or [`WhippleParams::from_values_warning`].
pub fn params_from_pairs_warning(
    pairs: &[(String, f64)],
    strict: bool,
) -> Result<(WhippleParams, Vec<TriangleWarning>), String> {
    let values = values_from_pairs(pairs)?;
    if strict {
        return WhippleParams::from_values(values)
            .map(|p| (p, Vec::new()))
            .map_err(|e| e.to_string());
    }
    WhippleParams::from_values_warning(values).map_err(|e| e.to_string())
}

/// Standard deviations from a mapping `name -> sigma` (missing names have none).
///
/// # Errors
/// An unknown or repeated name, or a sigma that is negative or not finite, named with its value.
pub fn sigma_from_pairs(pairs: &[(String, f64)]) -> Result<[f64; 26], String> {
    let mut sigma = [0.0; 26];
    let mut seen = [false; 26];
    for (name, s) in pairs {
        let k = index_of(name)
            .ok_or_else(|| format!("unknown parameter {name} in the uncertainties"))?;
        if seen[k] {
            return Err(format!("uncertainty of {} given twice ({name} = {s:?})", PARAM_NAMES[k]));
        }
        seen[k] = true;
        if !s.is_finite() || *s < 0.0 {
            return Err(format!(
                "invalid uncertainty {name} = {s:?}: must be a finite standard deviation of at least zero"
            ));
        }
        sigma[k] = *s;
    }
    Ok(sigma)
}

/// A bicycle with uncertainties from two mappings.
///
/// # Errors
/// As [`params_from_pairs`] and [`sigma_from_pairs`].
pub fn uncertain_from_pairs(
    params: &[(String, f64)],
    sigma: &[(String, f64)],
) -> Result<UncertainParams, String> {
    Ok(UncertainParams { params: params_from_pairs(params)?, sigma: sigma_from_pairs(sigma)? })
}

/// A bicycle with uncertainties from two mappings, broken triangle inequalities returned as
/// warnings unless `strict` (see [`params_from_pairs_warning`]).
///
/// # Errors
/// As [`params_from_pairs_warning`] and [`sigma_from_pairs`].
pub fn uncertain_from_pairs_warning(
    params: &[(String, f64)],
    sigma: &[(String, f64)],
    strict: bool,
) -> Result<(UncertainParams, Vec<TriangleWarning>), String> {
    let (params, warnings) = params_from_pairs_warning(params, strict)?;
    Ok((UncertainParams { params, sigma: sigma_from_pairs(sigma)? }, warnings))
}

/// `(name, value)` pairs of a bicycle in the order of [`PARAM_NAMES`].
pub fn pairs_of(values: &[f64; 26]) -> Vec<(String, f64)> {
    PARAM_NAMES.iter().zip(values).map(|(n, v)| (n.to_string(), *v)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn benchmark_pairs() -> Vec<(String, f64)> {
        pairs_of(WhippleParams::benchmark().values())
    }

    #[test]
    fn the_benchmark_round_trips() {
        assert_eq!(params_from_pairs(&benchmark_pairs()), Ok(WhippleParams::benchmark()));
        let mut lam = benchmark_pairs();
        lam[2].0 = "lam".into();
        assert_eq!(params_from_pairs(&lam), Ok(WhippleParams::benchmark()));
    }

    #[test]
    fn errors_name_the_key_and_value() {
        let mut p = benchmark_pairs();
        p[10].1 = -85.0;
        assert_eq!(params_from_pairs(&p).unwrap_err(), "invalid mB -85.0: must be positive");
        let mut p = benchmark_pairs();
        p.push(("mass".into(), 3.0));
        assert!(params_from_pairs(&p).unwrap_err().starts_with("unknown parameter mass = 3.0"));
        let mut p = benchmark_pairs();
        p.push(("lam".into(), 0.3));
        assert_eq!(params_from_pairs(&p).unwrap_err(), "parameter lambda given twice (lam = 0.3)");
        let p: Vec<_> = benchmark_pairs().into_iter().filter(|(n, _)| n != "c").collect();
        assert_eq!(params_from_pairs(&p).unwrap_err(), "missing parameter c");
        assert_eq!(
            sigma_from_pairs(&[("c".into(), -0.1)]).unwrap_err(),
            "invalid uncertainty c = -0.1: must be a finite standard deviation of at least zero"
        );
        assert_eq!(
            sigma_from_pairs(&[("q".into(), 0.1)]).unwrap_err(),
            "unknown parameter q in the uncertainties"
        );
    }

    #[test]
    fn broken_triangle_inequalities_are_warnings_unless_strict() {
        let mut p = benchmark_pairs();
        // IByy above IBxx + IBzz = 12.0 by 5 %.
        p[12].1 = 12.6;
        assert_eq!(
            params_from_pairs(&p).unwrap_err(),
            "invalid IByy 12.6: exceeds IBxx + IBzz, the sum of the other two principal moments (triangle inequality)"
        );
        assert_eq!(
            params_from_pairs_warning(&p, true).unwrap_err(),
            params_from_pairs(&p).unwrap_err()
        );
        let (params, warnings) = params_from_pairs_warning(&p, false).expect("computed as given");
        assert_eq!(params.get("IByy"), Some(12.6));
        assert_eq!(warnings.iter().map(|w| w.key).collect::<Vec<_>>(), ["IByy"]);
        let (u, warnings) =
            uncertain_from_pairs_warning(&p, &[("IByy".into(), 0.1)], false).expect("computed");
        assert_eq!((u.sigma[12], warnings.len()), (0.1, 1));
        p[10].1 = -85.0;
        assert_eq!(
            params_from_pairs_warning(&p, false).unwrap_err(),
            "invalid mB -85.0: must be positive"
        );
    }
}
