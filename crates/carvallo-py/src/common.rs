//! What the functions of the Python module share, below both `python` (the bicycle) and
//! `rolling` (the hoop and the unicycle), which import it and not each other: the exceptions,
//! the reading of parameters as Python users hold them, and the integration options and run
//! counts of a simulation.
//!
//! # Parameters as given
//!
//! A parameter argument is read by [`entries_of`] from any of
//! - a dict of numbers `{name: value}`;
//! - a dict of the `uncertainties` package's ufloats (BicycleParameters'
//!   `bicycle.parameters['Benchmark']`): the nominal values are the parameters, the standard
//!   deviations their uncertainties, and [`Covariance::of`] the covariances where the ufloats
//!   share sources (values computed from raw measurements do);
//! - a `bicycleparameters.Bicycle`: its `parameters['Benchmark']`, which holds the rider once
//!   `add_rider` has been called.
//!
//! Neither package is imported: a value is a number or has `nominal_value` and `std_dev`, a
//! bicycle has a dict `parameters` with the key `Benchmark`. The names and extra keys
//! (`yB`, `IRzz`, the fork `G` and handlebar `S`) obey the parameter files' rules
//! ([`UncertainParams::from_entries`]).

use carvallo::numerics::integrate::{Integration, Method as IntegrationMethod};
use carvallo::parameter_text::{Loaded, UncertainParams};
use carvallo::whipple::{TriangleWarning, WhippleParams, PARAM_NAMES};
use carvallo::whipple_nonlinear::Stop;
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

create_exception!(
    carvallo,
    ParameterError,
    PyValueError,
    "A bad parameter, parameter file or argument; the message names the key and the value."
);

create_exception!(
    carvallo,
    PhysicsWarning,
    pyo3::exceptions::PyUserWarning,
    "Parameters accepted although they break a physical law, such as measured moments of \
     inertia that break a triangle inequality; the message names the parameter and by how much."
);

pub(crate) fn err(message: impl Into<String>) -> PyErr {
    ParameterError::new_err(message.into())
}

/// Reading an argument: its failure becomes the argument's own error (`bad`, naming the value),
/// except a failure that is not the value's fault, which passes through unchanged: Ctrl-C while
/// numpy converts a large array (`KeyboardInterrupt`), `MemoryError` and `SystemExit`. Renaming
/// those "must be a 1-d array of numbers" was a bug the Ctrl-C test of `closed_loop_window`
/// found when the signal arrived during the conversion of its 10**7-row gain table.
pub(crate) trait OrBad<T> {
    fn or_bad(self, bad: impl FnOnce() -> PyErr) -> PyResult<T>;
}

impl<T, E: Into<PyErr>> OrBad<T> for Result<T, E> {
    fn or_bad(self, bad: impl FnOnce() -> PyErr) -> PyResult<T> {
        self.map_err(|e| {
            let e: PyErr = e.into();
            if cut_short(&e) {
                e
            } else {
                bad()
            }
        })
    }
}

/// Whether `e` is not the value's fault (see [`OrBad`]): an attempt that failed with it (a
/// number tried before a sequence) must not go on to the next reading.
pub(crate) fn cut_short(e: &PyErr) -> bool {
    Python::attach(|py| {
        e.is_instance_of::<pyo3::exceptions::PyKeyboardInterrupt>(py)
            || e.is_instance_of::<pyo3::exceptions::PyMemoryError>(py)
            || e.is_instance_of::<pyo3::exceptions::PySystemExit>(py)
    })
}

fn shown(v: &Bound<'_, PyAny>) -> String {
    v.repr().map(|r| r.to_string()).unwrap_or_default()
}

/// The dict of parameters that `mapping` stands for: itself, or a BicycleParameters
/// `Bicycle`'s `parameters['Benchmark']`.
fn mapping_of<'py>(mapping: &Bound<'py, PyAny>, what: &str) -> PyResult<Bound<'py, PyDict>> {
    if let Ok(d) = mapping.cast::<PyDict>() {
        return Ok(d.clone());
    }
    if let Ok(sets) = mapping.getattr("parameters") {
        if let Ok(sets) = sets.cast::<PyDict>() {
            if let Some(b) = sets.get_item("Benchmark")? {
                return b.cast_into::<PyDict>().map_err(|_| {
                    err(format!("{what}: the bicycle's parameters['Benchmark'] is not a dict"))
                });
            }
            return Err(err(format!(
                "{what}: the bicycle {} has no benchmark parameters (parameters['Benchmark'])",
                shown(mapping)
            )));
        }
    }
    Err(err(format!(
        "{what} must be a dict of name -> number or ufloat, or a bicycleparameters.Bicycle, not {}",
        shown(mapping)
    )))
}

/// A value: a number, or an `uncertainties` ufloat `(nominal_value, std_dev)`.
fn value_of(name: &str, v: &Bound<'_, PyAny>) -> PyResult<(f64, Option<f64>)> {
    match v.extract::<f64>() {
        Ok(x) => return Ok((x, None)),
        Err(e) if cut_short(&e) => return Err(e),
        Err(_) => {}
    }
    let (Ok(n), Ok(s)) = (v.getattr("nominal_value"), v.getattr("std_dev")) else {
        return Err(err(format!("parameter {name} = {} is not a number", shown(v))));
    };
    match (n.extract::<f64>(), s.extract::<f64>()) {
        (Ok(n), Ok(s)) => Ok((n, Some(s))),
        _ => Err(err(format!("parameter {name} = {} is not a number", shown(v)))),
    }
}

/// Parameter entries `(name, value, sigma)`.
type Entries = Vec<(String, f64, f64)>;

/// `(name, value, sigma)` of every entry (sigma zero for a plain number), and whether any
/// value is a ufloat.
pub(crate) fn entries_of(mapping: &Bound<'_, PyAny>, what: &str) -> PyResult<(Entries, bool)> {
    let dict = mapping_of(mapping, what)?;
    let mut out = Vec::with_capacity(dict.len());
    let mut uncertain = false;
    for (k, v) in dict.iter() {
        let name: String =
            k.extract().or_bad(|| err(format!("{what}: key {} is not a string", shown(&k))))?;
        let (x, s) = value_of(&name, &v)?;
        uncertain |= s.is_some();
        out.push((name, x, s.unwrap_or(0.0)));
    }
    Ok((out, uncertain))
}

/// `(name, value)` pairs from a mapping of numbers (ufloats give their nominal values).
pub(crate) fn pairs(mapping: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<(String, f64)>> {
    Ok(entries_of(mapping, what)?.0.into_iter().map(|(n, v, _)| (n, v)).collect())
}

/// Each warning as a `carvallo.PhysicsWarning` (`warnings.warn`), prefixed by `source`.
pub(crate) fn warn_all(py: Python<'_>, source: &str, warnings: &[TriangleWarning]) -> PyResult<()> {
    let category = py.get_type::<PhysicsWarning>();
    for w in warnings {
        let message = std::ffi::CString::new(format!("{source}: {w}"))
            .map_err(|_| err("a warning message holds a NUL byte"))?;
        PyErr::warn(py, category.as_any(), &message, 1)?;
    }
    Ok(())
}

/// The parameters and their standard deviations as the file reader takes them, warnings
/// issued.
fn loaded_of(params: &Bound<'_, PyAny>, strict: bool) -> PyResult<(UncertainParams, bool)> {
    let (entries, uncertain) = entries_of(params, "params")?;
    let Loaded { params: u, warnings } =
        UncertainParams::from_entries(&entries, strict).map_err(|e| err(e.to_string()))?;
    warn_all(params.py(), "params", &warnings)?;
    Ok((u, uncertain))
}

/// The bicycle of a parameter argument (see the [module docs](self)), nominal values of
/// ufloats: moments of inertia breaking a triangle inequality are a `PhysicsWarning`, or an
/// error when `strict`.
pub(crate) fn params_of(mapping: &Bound<'_, PyAny>, strict: bool) -> PyResult<WhippleParams> {
    Ok(loaded_of(mapping, strict)?.0.params)
}

/// As [`params_of`], with standard deviations: the dict `sigma` (missing names have none) or,
/// when `sigma` is `None`, those of the ufloats in `params`. Both is an error; neither is an
/// error when `needed`, otherwise no uncertainty.
pub(crate) fn uncertain_of(
    params: &Bound<'_, PyAny>,
    sigma: Option<&Bound<'_, PyAny>>,
    strict: bool,
    needed: bool,
) -> PyResult<UncertainParams> {
    let (mut u, uncertain) = loaded_of(params, strict)?;
    match (sigma, uncertain) {
        (Some(_), true) => Err(err(
            "params hold ufloats with their standard deviations: give sigma=None, or plain numbers",
        )),
        (None, false) if !needed => Ok(u),
        (None, false) => Err(err(
            "no uncertainties: give sigma (a dict name -> standard deviation) or params of ufloats",
        )),
        (None, true) => Ok(u),
        (Some(s), false) => {
            u.sigma = crate::sigma_from_pairs(&pairs(s, "sigma")?).map_err(err)?;
            Ok(u)
        }
    }
}

/// The covariances of the 26 parameters held as ufloats that share sources: each ufloat's
/// `derivatives` (its linear dependence on the independent `uncertainties` variables, each
/// with its `std_dev`).
pub(crate) struct Covariance {
    /// $\partial p_i / \partial x_v$, row $i$ in the order of [`PARAM_NAMES`].
    pub jacobian: Vec<[f64; 26]>,
    /// $\sigma_v$ of each variable $x_v$.
    pub sigma: Vec<f64>,
}

impl Covariance {
    /// The sources of the parameters' ufloats, `None` when they have no `derivatives` (plain
    /// numbers, a `sigma` dict). A parameter computed by the reader (the front frame from its
    /// parts) is its own source with the reader's standard deviation `u.sigma`.
    pub(crate) fn of(
        params: &Bound<'_, PyAny>,
        u: &UncertainParams,
    ) -> PyResult<Option<Covariance>> {
        let py = params.py();
        let dict = mapping_of(params, "params")?;
        let index = PyDict::new(py);
        let mut cov = Covariance { jacobian: Vec::new(), sigma: Vec::new() };
        for (i, name) in PARAM_NAMES.iter().enumerate() {
            let v = match dict.get_item(*name)? {
                Some(v) => Some(v),
                None if *name == "lambda" => dict.get_item("lam")?,
                None => None,
            };
            let derivatives = match &v {
                Some(v) if v.extract::<f64>().is_err() => match v.getattr("derivatives") {
                    Ok(d) => Some(d.cast_into::<PyDict>().map_err(|_| {
                        err(format!("parameter {name}: its derivatives are not a dict"))
                    })?),
                    Err(_) => return Ok(None),
                },
                Some(_) => None,
                None => {
                    cov.sigma.push(u.sigma[i]);
                    let mut row = [0.0; 26];
                    row[i] = 1.0;
                    cov.jacobian.push(row);
                    None
                }
            };
            for (var, d) in derivatives.iter().flat_map(|d| d.iter()) {
                let d: f64 = d.extract().or_bad(|| {
                    err(format!("parameter {name}: a derivative {} is not a number", shown(&d)))
                })?;
                let k = match index.get_item(&var)? {
                    Some(k) => k.extract::<usize>()?,
                    None => {
                        let s: f64 = var.getattr("std_dev")?.extract()?;
                        index.set_item(&var, cov.sigma.len())?;
                        cov.sigma.push(s);
                        cov.jacobian.push([0.0; 26]);
                        cov.sigma.len() - 1
                    }
                };
                cov.jacobian[k][i] += d;
            }
        }
        Ok(Some(cov))
    }

    /// The first-order standard deviation of a function of gradient `grad`:
    /// $\sqrt{\sum_v (\sum_i g_i\, \partial p_i/\partial x_v)^2 \sigma_v^2}$.
    pub(crate) fn std(&self, grad: &[f64; 26]) -> f64 {
        self.jacobian
            .iter()
            .zip(&self.sigma)
            .filter(|(_, s)| **s != 0.0)
            .map(|(row, s)| {
                let d: f64 =
                    row.iter().zip(grad).filter(|(r, _)| **r != 0.0).map(|(r, g)| r * g).sum();
                (d * s) * (d * s)
            })
            .sum::<f64>()
            .sqrt()
    }
}

/// The integration of `method` (`rk4`, `dopri5`, `dop853`, `vern9`) with the tolerances
/// given or the
/// command line's defaults, and the parsed stop conditions.
pub(crate) fn integration_of(
    method: &str,
    rtol: Option<f64>,
    atol: Option<f64>,
    stop_when: &[String],
) -> PyResult<(Integration, Vec<Stop>)> {
    let m = IntegrationMethod::from_name(method).ok_or_else(|| {
        err(format!("invalid method `{method}`: expected rk4, dopri5, dop853 or vern9"))
    })?;
    if m == IntegrationMethod::Rk4 && (rtol.is_some() || atol.is_some()) {
        return Err(err("rtol and atol need an adaptive method (dopri5, dop853 or vern9)"));
    }
    let how = Integration::with_defaults(m, rtol, atol);
    if let Some((name, value, reason)) = how.unusable() {
        return Err(err(format!("invalid {name} {value:?}: {reason}")));
    }
    let stops = stop_when
        .iter()
        .map(|t| {
            Stop::parse(t).ok_or_else(|| {
                err(format!(
                    "invalid stop condition `{t}`: expected NAME=VALUE or NAME=±VALUE with NAME \
                     one of lean, steer, yaw, pitch, lean_rate, steer_rate, x, y"
                ))
            })
        })
        .collect::<PyResult<Vec<Stop>>>()?;
    Ok((how, stops))
}

/// The keys every simulation's dictionary shares: `method`, `rtol` and `atol` (None for a
/// fixed step), the counts `rhs_evaluations`, `steps`, `rejected_steps`, and `events`
/// (`[{"when", "t"}]`, the condition met as given).
pub(crate) fn set_run(
    d: &Bound<'_, PyDict>,
    how: &Integration,
    stats: &carvallo::numerics::integrate::Stats,
    event: Option<(String, f64)>,
) -> PyResult<()> {
    let adaptive = how.method.is_adaptive();
    d.set_item("method", how.method.name())?;
    d.set_item("rtol", adaptive.then_some(how.rtol))?;
    d.set_item("atol", adaptive.then_some(how.atol))?;
    d.set_item("rhs_evaluations", stats.rhs_evaluations)?;
    d.set_item("steps", stats.steps)?;
    d.set_item("rejected_steps", stats.rejected_steps)?;
    let events = PyList::empty(d.py());
    if let Some((when, t)) = event {
        let e = PyDict::new(d.py());
        e.set_item("when", when)?;
        e.set_item("t", t)?;
        events.append(e)?;
    }
    d.set_item("events", events)
}
