//! The edges of the Python boundary: what keeps a call from killing or hanging the
//! interpreter.
//!
//! - **Arguments**: every number argument is read by a named extractor ([`arg`], used with
//!   pyo3's `from_py_with`), so a negative count, an integer above $2^{64} - 1$ or an integer
//!   too large for a float ($10^{400}$) is a `ParameterError` naming the argument, never a bare
//!   `OverflowError`.
//! - **Memory**: a call computes the bytes its result and working arrays need from its
//!   arguments and refuses, before allocating, more than [`MAX_BYTES`] ([`within`]); files are
//!   read up to [`MAX_FILE_BYTES`] ([`read_text`]). Linux overcommits, so a failed allocation
//!   is not an error but a killed process: the check must come first.
//! - **Ctrl-C**: a long call runs on a worker thread with the GIL released ([`interruptible`]);
//!   the calling thread wakes every [`POLL`], re-attaches, calls `check_signals` and, on
//!   `KeyboardInterrupt`, sets the stop flag the work polls, waits for it to end and raises.

use std::io::Read;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Condvar, Mutex};
use std::time::Duration;

use pyo3::prelude::*;

use crate::common::{err, OrBad};

/// The most bytes one call may need for its result and working arrays: 1 GiB.
pub(crate) const MAX_BYTES: f64 = (1u64 << 30) as f64;

/// The largest parameter or rider file read: 16 MiB.
pub(crate) const MAX_FILE_BYTES: u64 = 16 << 20;

/// How often the calling thread of a long call looks for a signal.
pub(crate) const POLL: Duration = Duration::from_millis(50);

/// Refuses a call whose arrays need more than [`MAX_BYTES`]: `count` items (the product of
/// the sizes given by the arguments, as a float so that it cannot overflow) of `bytes_each`
/// bytes, `what` naming the arguments (`"samples = 1000000000"`).
pub(crate) fn within(what: &str, count: f64, bytes_each: f64) -> PyResult<()> {
    let bytes = count * bytes_each;
    if bytes > MAX_BYTES {
        return Err(err(format!(
            "{what} needs {:.3e} bytes, more than the limit of {} bytes (1 GiB) per call",
            bytes, MAX_BYTES as u64
        )));
    }
    Ok(())
}

/// The text of the file `path` (`what`: "parameter", "rider"), read up to [`MAX_FILE_BYTES`];
/// a longer file (or an endless device) and a directory are errors naming the path.
pub(crate) fn read_text(path: &str, what: &str) -> PyResult<String> {
    let cannot = |e: std::io::Error| {
        err(format!("cannot read {what} file `{path}`: {}", e.to_string().to_lowercase()))
    };
    let file = std::fs::File::open(path).map_err(cannot)?;
    if file.metadata().map_err(cannot)?.is_dir() {
        return Err(err(format!("cannot read {what} file `{path}`: it is a directory")));
    }
    let mut bytes = Vec::new();
    file.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes).map_err(cannot)?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(err(format!(
            "cannot read {what} file `{path}`: longer than the limit of {MAX_FILE_BYTES} bytes (16 MiB)"
        )));
    }
    String::from_utf8(bytes)
        .map_err(|_| err(format!("cannot read {what} file `{path}`: not UTF-8 text")))
}

/// Sets the flag and wakes the waiting thread when the worker ends, even by a panic.
struct Finished<'a>(&'a (Mutex<bool>, Condvar));

impl Drop for Finished<'_> {
    fn drop(&mut self) {
        *self.0 .0.lock().unwrap_or_else(|e| e.into_inner()) = true;
        self.0 .1.notify_all();
    }
}

/// Runs `work` on a worker thread with the GIL released; every [`POLL`] the calling thread
/// re-attaches and calls `check_signals`. On an exception (Ctrl-C's `KeyboardInterrupt`, or
/// one a signal handler raised) it sets the stop flag handed to `work`, waits for `work` to
/// see it and return, drops what it returned and raises the exception.
pub(crate) fn interruptible<T: Send>(
    py: Python<'_>,
    work: impl FnOnce(&AtomicBool) -> T + Send,
) -> PyResult<T> {
    let stop = AtomicBool::new(false);
    let finished = (Mutex::new(false), Condvar::new());
    std::thread::scope(|s| {
        let worker = s.spawn(|| {
            let _done = Finished(&finished);
            work(&stop)
        });
        loop {
            let done = py.detach(|| {
                let guard = finished.0.lock().unwrap_or_else(|e| e.into_inner());
                let (guard, _) = finished
                    .1
                    .wait_timeout_while(guard, POLL, |done| !*done)
                    .unwrap_or_else(|e| e.into_inner());
                *guard
            });
            if done {
                break;
            }
            if let Err(e) = py.check_signals() {
                stop.store(true, Ordering::Relaxed);
                let _ = py.detach(|| worker.join());
                return Err(e);
            }
        }
        worker.join().map_err(|panic| std::panic::resume_unwind(panic))
    })
}

/// A short form of a Python value for a message (the repr, cut to 40 characters).
fn shown(x: &Bound<'_, PyAny>) -> String {
    let r = x.repr().map(|r| r.to_string()).unwrap_or_else(|_| "?".into());
    if r.chars().count() > 40 {
        format!("{}...", r.chars().take(37).collect::<String>())
    } else {
        r
    }
}

/// A whole number from 0 to $2^{64} - 1$ (a Python or numpy integer; not a float or a bool).
pub(crate) fn whole(x: &Bound<'_, PyAny>, name: &str) -> PyResult<u64> {
    let bad = || {
        err(format!("invalid {name} {}: must be a whole number from 0 to {}", shown(x), u64::MAX))
    };
    if x.is_instance_of::<pyo3::types::PyBool>() || x.is_instance_of::<pyo3::types::PyFloat>() {
        return Err(bad());
    }
    x.extract::<u64>().or_bad(bad)
}

/// As [`whole`], as a count of items.
pub(crate) fn count(x: &Bound<'_, PyAny>, name: &str) -> PyResult<usize> {
    usize::try_from(whole(x, name)?)
        .map_err(|_| err(format!("invalid {name} {}: too large for this machine", shown(x))))
}

/// A real number (a float, or an integer that a float holds: not $10^{400}$).
pub(crate) fn real(x: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    if x.is_instance_of::<pyo3::types::PyString>() {
        return Err(err(format!("invalid {name} {}: not a number", shown(x))));
    }
    x.extract::<f64>()
        .or_bad(|| err(format!("invalid {name} {}: not a number that a float holds", shown(x))))
}

/// [`real`] or None.
pub(crate) fn optional_real(x: &Bound<'_, PyAny>, name: &str) -> PyResult<Option<f64>> {
    if x.is_none() {
        return Ok(None);
    }
    real(x, name).map(Some)
}

/// A sequence of real numbers, or None.
pub(crate) fn optional_reals(x: &Bound<'_, PyAny>, name: &str) -> PyResult<Option<Vec<f64>>> {
    if x.is_none() {
        return Ok(None);
    }
    let bad = || err(format!("invalid {name} {}: must be a sequence of numbers", shown(x)));
    if x.is_instance_of::<pyo3::types::PyString>() {
        return Err(bad());
    }
    x.try_iter()
        .or_bad(bad)?
        .map(|item| real(&item.or_bad(bad)?, name))
        .collect::<PyResult<Vec<f64>>>()
        .map(Some)
}

/// A fixed number of real numbers (a tuple or a sequence), named `name` in errors.
fn reals<const K: usize>(x: &Bound<'_, PyAny>, name: &str) -> PyResult<[f64; K]> {
    let bad = || err(format!("invalid {name} {}: must be {K} numbers", shown(x)));
    let v = optional_reals(x, name).or_bad(bad)?.ok_or_else(bad)?;
    <[f64; K]>::try_from(v).map_err(|_| bad())
}

/// The named extractors of the arguments (`#[pyo3(from_py_with = arg::samples)]`).
pub(crate) mod arg {
    use super::*;

    macro_rules! named {
        ($($f:ident: $ty:ty = $conv:ident;)*) => {$(
            pub(crate) fn $f(x: &Bound<'_, PyAny>) -> PyResult<$ty> {
                super::$conv(x, stringify!($f))
            }
        )*};
    }

    named! {
        speed: f64 = real;
        lean0: f64 = real;
        lean: f64 = real;
        steer: Option<f64> = optional_real;
        fall_angle: f64 = real;
        steer_lock: f64 = real;
        duration: f64 = real;
        step: f64 = real;
        start: f64 = real;
        stop: f64 = real;
        theta0: f64 = real;
        pitch0: f64 = real;
        t_end: f64 = real;
        s0: f64 = real;
        p0: f64 = real;
        n0: f64 = real;
        radius: f64 = real;
        mass: f64 = real;
        g: f64 = real;
        vmin: Option<f64> = optional_real;
        vmax: Option<f64> = optional_real;
        rtol: Option<f64> = optional_real;
        atol: Option<f64> = optional_real;
        torque_t: Option<Vec<f64>> = optional_reals;
        torque_roll: Option<Vec<f64>> = optional_reals;
        torque_steer: Option<Vec<f64>> = optional_reals;
        torque_lean: Option<Vec<f64>> = optional_reals;
        every: usize = count;
        count: usize = count;
        samples: usize = count;
        seed: u64 = whole;
    }

    /// `quantiles`: two numbers.
    pub(crate) fn quantiles(x: &Bound<'_, PyAny>) -> PyResult<(f64, f64)> {
        let [lo, hi] = reals::<2>(x, "quantiles")?;
        Ok((lo, hi))
    }

    /// `impulses`: a sequence of `(t, J_roll, J_steer)`.
    pub(crate) fn impulses(x: &Bound<'_, PyAny>) -> PyResult<Vec<(f64, f64, f64)>> {
        let bad = || {
            err(format!(
                "invalid impulses {}: must be a sequence of (t, J_roll, J_steer)",
                shown(x)
            ))
        };
        if x.is_instance_of::<pyo3::types::PyString>() {
            return Err(bad());
        }
        x.try_iter()
            .or_bad(bad)?
            .map(|item| {
                let [t, roll, steer] = reals::<3>(&item.or_bad(bad)?, "impulses")?;
                Ok((t, roll, steer))
            })
            .collect()
    }
}
