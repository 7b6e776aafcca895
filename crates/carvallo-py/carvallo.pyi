"""Fast, verified evaluators of the Carvallo-Whipple bicycle (the `carvallo` Rust crate).

Parameters are dicts in the benchmark names of Meijaard et al. (2007) (`PARAM_NAMES`; the steer
axis tilt also as BicycleParameters' `lam`), SI units. Every error is a `ParameterError` (a
`ValueError`) whose message names the key and the value. Every function taking `params`
reads it as the parameter files are read: moments of inertia that break a triangle inequality
are computed as given with a `PhysicsWarning`, or a `ParameterError` with `strict=True`.

`params` may be a dict of floats, a dict of `uncertainties` ufloats (their nominal values; their
standard deviations and correlations go to the uncertainty functions when `sigma` is None), or a
`bicycleparameters.Bicycle` (its `parameters['Benchmark']`, with the rider once added).
BicycleParameters' extra keys (`yB`, `IRzz`, the fork `G` and handlebar `S`) obey the parameter
files' rules. Neither package is imported.

Limits (a `ParameterError` naming the argument and the limit, raised before allocating): a call
needs at most 1 GiB for its result and working arrays; files are read up to 16 MiB; counts
(`samples`, `count`, `every`, `seed`) are whole numbers from 0 to 2**64 - 1 and real arguments
numbers a float holds. A wrong Python type for a text or flag argument is a `TypeError`.
`sweep`, `windows`, `simulate`, `simulate_hoop`, `simulate_unicycle`, `simulate_pendulum`,
`simulate_many`, `closed_loop_window` (a gain table), `closed_loop_eigenvalues`, `monte_carlo` and
`eigenvalue_bands` run with the GIL
released and raise `KeyboardInterrupt` within a fraction of a second of Ctrl-C. Speeds of
`closed_loop_window` and gain tables lie within 1e6 m/s and gains within 1e12, as on the
command line.
"""

import os
import types
from typing import Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str
PARAM_NAMES: list[str]

Params = Union[Mapping[str, object], object]
Speeds = Union[float, Sequence[float], npt.NDArray[np.float64]]

class ParameterError(ValueError):
    """A bad parameter, parameter file or argument; the message names the key and the value."""

def benchmark() -> dict[str, float]:
    """The benchmark bicycle of Meijaard et al. (2007), Table 1."""

def design(params: Params, strict: bool = False) -> dict[str, object]:
    """The parameters by name: wheelbase, trail, steer_axis_tilt, gravity (floats) and the dicts
    rear_wheel, front_wheel (radius, mass, ixx, iyy) and rear_frame, front_frame (x, z, mass,
    ixx, iyy, izz, ixz)."""

class PhysicsWarning(UserWarning):
    """Parameters accepted although they break a physical law (a triangle inequality of measured
    moments of inertia); the message names the parameter and the relative violation."""

def load_parameters(
    path: str,
    rider: str | None = None,
    strict: bool = False,
    configuration: Union[str, Mapping[str, float], None] = None,
    measured: str | None = None,
) -> tuple[dict[str, float], dict[str, float]]:
    """(params, sigma) from a TOML file (anchors format) or a BicycleParameters text file, with
    the BicycleParameters rider file `rider` added to the rear frame; a broken triangle
    inequality is a PhysicsWarning, or a ParameterError when `strict`. `rider` may be a Yeadon
    measurement file, seated as Bicycle.add_rider(reCalc=True) seats it with `configuration`
    and `measured` (found by BicycleParameters' layout when not given)."""

def add_rider(
    params: Params,
    rider: Union[str, Mapping[str, float]],
    sigma: Optional[Params] = None,
    strict: bool = False,
    configuration: Union[str, Mapping[str, float], None] = None,
    measured: str | None = None,
) -> tuple[dict[str, float], dict[str, float]]:
    """(params, sigma) with a rider (a BicycleParameters rider file, or a dict of mB, xB, yB, zB,
    IBxx, IBxz, IByy, IBzz, or a Yeadon measurement file seated with `configuration` and
    `measured`) added to the rear frame, as Bicycle.add_rider."""

def yeadon_human(
    measurements: str,
    configuration: Union[str, Mapping[str, float], None] = None,
    corrected: bool = False,
) -> dict[str, object]:
    """Yeadon's body alone as yeadon.Human: mass, center_of_mass (3,), inertia (3, 3) in yeadon's
    frame, density_scale, notes; `corrected=True` fixes yeadon 2.0.1's three errors."""

def yeadon_rider(
    params: Params,
    measurements: str,
    configuration: Union[str, Mapping[str, float]],
    measured: str,
    corrected: bool = False,
) -> dict[str, object]:
    """The Yeadon body seated on the bicycle as Bicycle.add_rider(reCalc=True): rider (the eight
    values), configuration (21 angles), body, hands, residual, iterations, notes, description."""

def geometry(
    params: Params, rider: Union[str, Mapping[str, float], None] = None, strict: bool = False
) -> dict[str, object]:
    """The side view's points, as `carvallo plot geometry` draws them, each [x, h] in metres (x
    forward from the rear contact, h the height): rear_contact, rear_hub, front_contact,
    front_hub, rear_radius, front_radius, the segments steer_axis, trail, fork (2 x 2), the
    schematic frame (3 x 2), mass_centres {name: [x, h]} and masses {name: kg} (rear wheel, rear
    frame, front frame, front wheel, rider when `rider` is given apart, whole bicycle)."""

# The figures (matplotlib, an optional dependency: an ImportError saying how to install it when
# it is missing); also in the submodule `carvallo.plot`. Each returns the matplotlib Figure.
plot: types.ModuleType

def plot_geometry(
    params: Params,
    rider: Union[str, Mapping[str, float], None] = None,
    name: Optional[str] = None,
    ax: Optional[object] = None,
) -> object:
    """The side view of `geometry(params, rider)`, titled "name: geometry"."""

def plot_eigenvalues(
    params: Union[Params, str, os.PathLike],
    speeds: Optional[Speeds] = None,
    name: Optional[str] = None,
    ax: Optional[object] = None,
) -> object:
    """The eigenvalues against speed (default 0 to 10 m/s), each named by its mode as `modes`
    labels it (weave, capsize, caster; torso too for the leaning rider's params), the stable
    range shaded; titled "name: eigenvalues against speed". `params` may be the path of a
    leaning rider's file in Moore's names (read by `lean_rider(path)`). The name is by default
    the parameter set's, as `carvallo plot eigenvalues --model` names it: the file's stem,
    "Leaning rider (Browser + Jason)" for the values of `lean_rider()`, "Leaning rider" for
    another rider's dict."""

def plot_bode(
    bicycles: Union[Params, Sequence[Params]],
    speeds: Speeds = 5.0,
    input: str = "steer",
    output: str = "roll",
    omegas: Optional[Speeds] = None,
    names: Optional[Sequence[str]] = None,
    axes: Optional[Sequence[object]] = None,
) -> object:
    """The Bode diagram (magnitude above, phase below, ω on a log axis labelled 10⁻¹, 10⁰, 10¹)
    of one bicycle or a list compared, at each speed; the legend names each bicycle (`names`,
    or a bicycleparameters.Bicycle's own name)."""

def parameters_from_raw(path: str) -> tuple[dict[str, float], dict[str, float]]:
    """(params, sigma) computed from BicycleParameters' raw measurements (RawData/<name>Measured.txt)
    as Bicycle(name, pathToData, forceRawCalc=True) computes them; a front frame in two parts, a
    flywheel or more than three pendulum orientations is a ParameterError naming the key."""

def parse_parameters(text: str) -> tuple[dict[str, float], dict[str, float]]:
    """(params, sigma) from the text of a parameter file (either format)."""

def matrices(params: Params, strict: bool = False) -> dict[str, npt.NDArray[np.float64]]:
    """{"M", "C1", "K0", "K2"}: the 2x2 matrices of M q'' + v C1 q' + (g K0 + v^2 K2) q = f."""

def state_matrix(params: Params, speed: Speeds, strict: bool = False) -> npt.NDArray[np.float64]:
    """The 4x4 state matrix of (lean, steer, lean rate, steer rate); shape (n, 4, 4) for n speeds."""

def state_space(
    params: Params, speeds: Speeds, strict: bool = False
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """(A, B) with roll and steer torque as inputs, shapes (n, 4, 4) and (n, 4, 2); C = I, D = 0.
    For the leaning rider's params (`lean_rider()`), shapes (n, 12, 12) and (n, 12, 3): Moore's
    states q1 q2 q3 q4 q6 q7 q8 q9 u4 u6 u7 u9 and the torques T4, T7, T9."""

def modes(
    params: Params, speeds: Speeds, strict: bool = False
) -> tuple[list[str], npt.NDArray[np.complex128], npt.NDArray[np.complex128]]:
    """(labels, eigenvalues (n, 4), unit eigenvectors (n, 4, 4) in NumPy's convention: vectors[k, :, i] is mode i at speed k, the columns are the vectors); labels weave, weave, capsize, caster by continuation.
    For the leaning rider's params (`lean_rider()`): labels weave, weave, capsize, caster, torso,
    torso, eigenvalues (n, 6) and vectors (n, 6, 6) over roll, steer, lean and their rates."""

def frequency_response(
    params: Params, speeds: Speeds, omegas: Speeds, input: str, output: str, strict: bool = False
) -> dict[str, npt.NDArray[np.complex128] | npt.NDArray[np.float64]]:
    """G(iω) from input "roll"|"steer" torque to output "roll"|"steer"|"roll-rate"|"steer-rate": {"response" complex, "magnitude_db", "phase_deg" (continuous in ω, in (-180°, 180°] as ω -> 0+, independent of the grid)}, each (n speeds, m omegas).
    For the leaning rider's params (`lean_rider()`): input "roll"|"steer"|"lean" torque, output
    "roll"|"steer"|"lean"|"roll-rate"|"steer-rate"|"lean-rate" (lean: the torso on its joint)."""

GainTable = dict[str, Sequence[float]]

def time_response(
    params: Params,
    speed: float,
    times: Speeds,
    kind: str,
    input: str = "steer",
    x0: Sequence[float] | None = None,
    strict: bool = False,
) -> npt.NDArray[np.float64]:
    """States (n, 4) (lean, steer, lean rate, steer rate) of the linear plant after a unit "step" or "impulse" of the "roll"|"steer" torque from rest, or from x0 with no input ("initial"), by the matrix exponential."""

def closed_loop_window(
    params: Params,
    k: npt.ArrayLike | dict[str, float] | GainTable,
    vmin: float | None = None,
    vmax: float | None = None,
    strict: bool = False,
) -> dict[str, object]:
    """Closed-loop stable speed range of u = -K x, k = K (2, 4) (rows roll, steer torque; columns roll, steer, roll rate, steer rate) or gains by name, or a gain table {"speed": [...], "k_...": [...], ...} (interpolated in speed; vmin/vmax default to its speeds): {"from", "to", "stable": [(from, to), ...], "lowest_stable_speed"} (None: unbounded).
    For the leaning rider's params (`lean_rider()`): k as in closed_loop_eigenvalues, the window
    of a scan of vmin (0) to vmax (20) m/s, {"from", "to", "stable"}."""

def closed_loop_eigenvalues(
    params: Params, k: npt.ArrayLike | dict[str, float] | GainTable, speeds: Speeds, strict: bool = False
) -> npt.NDArray[np.complex128]:
    """Eigenvalues of A - B K (K = k as in closed_loop_window) at each speed, shape (n, 4), sorted by real then imaginary part (a gain table must cover the speeds).
    For the leaning rider's params (`lean_rider()`): shape (n, 6), k a dict of gains
    k_{roll|steer|lean}_{roll|steer|lean|roll_rate|steer_rate|lean_rate} or a (3, 6) array
    (rows roll, steer, lean torque; columns roll, steer, lean and their rates)."""

def eigenvalues(params: Params, speeds: Speeds, strict: bool = False) -> npt.NDArray[np.complex128]:
    """Eigenvalues at each speed, shape (n, 4), sorted by real then imaginary part. For the
    leaning rider's params (`lean_rider()`), the six of roll, steer and lean, shape (n, 6), by
    decreasing real part (the other six of the 12-state linearisation are zero)."""

def steady_turn(
    params: Params, speed: float, lean: float, steer: float | None = None, strict: bool = False
) -> list[dict[str, object]]:
    """Every steady turn at the rear contact's speed and the lean, by increasing steer."""

def window(params: Params, strict: bool = False) -> dict[str, object]:
    """{"weave_speed", "capsize_speed", "stable": [(from, to), ...]} in m/s (None if none).
    For the leaning rider's params (`lean_rider()`), {"stable", "scan", "state", "inputs"}: the
    speeds of a scan of 0 to 20 m/s where all six eigenvalues have negative real parts (empty
    for Browser + Jason's passive torso, k9 = c9 = 0)."""

def windows(
    designs: npt.NDArray[np.float64], validate: bool = True, strict: bool = False
) -> npt.NDArray[np.float64]:
    """Weave and capsize speeds of the rows of anything numpy reads as an (n, 26) array of floats
    (columns as PARAM_NAMES): (n, 2), NaN if none; rows breaking a triangle inequality give one
    PhysicsWarning counting them (an error when `strict`)."""

def sweep(
    params: Params, name: str, start: float, stop: float, count: int, method: str = "hurwitz",
    strict: bool = False,
) -> dict[str, object]:
    """Summary of the windows as `name` runs linearly from start to stop (as `carvallo sweep --json`);
    constant memory for any count, stops on Ctrl-C within a few designs."""

def simulate(
    params: Params,
    speed: float,
    lean0: float,
    duration: float,
    step: float = 0.001,
    every: int = 10,
    strict: bool = False,
    *,
    method: str = "rk4",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    stop_when: Sequence[str] = (),
    torque_t: Optional[npt.ArrayLike] = None,
    torque_roll: Optional[npt.ArrayLike] = None,
    torque_steer: Optional[npt.ArrayLike] = None,
    impulses: Sequence[tuple[float, float, float]] = (),
    k: Optional[npt.ArrayLike | dict[str, float] | GainTable] = None,
    fall_angle: float = 1.2,
    steer_lock: float = 1.4,
    torque_lean: Optional[npt.ArrayLike] = None,
) -> dict[str, object]:
    """Nonlinear simulation from upright straight running (rk4, or dopri5 / dop853 /
    vern9 with rtol, default 1e-8, and atol, default 1e-3 rtol; stop_when conditions
    such as "lean=±0.5"), as
    `carvallo simulate --json`: arrays t, lean, steer, pitch, speed_rear, rear_x, rear_y,
    front_x, front_y, energy; floats step, energy_drift, max_contact_residual; method, rtol,
    atol, rhs_evaluations, steps, rejected_steps, events (list of {"when", "t"}).

    A fall is a result: the run ends when |lean| reaches fall_angle (rad, in (0, pi/2];
    default 1.2, a stated angle), located on the integrator's interpolant; status is
    "completed", "stopped" (a stop_when condition) or "fell", with status_line
    ("fell at t = 1.94 s: ..."), fall_angle and fall_t (None unless it fell). The run ends too
    when |steer| reaches steer_lock (rad, in (0, pi/2); default 1.4, the handlebar against the
    frame, short of the equations' singularity at pi/2): status "steer lock", steer_lock and
    steer_lock_t; and when a pivot of the rolling constraints' solve falls to singular_pivot
    (0.01) of its upright value, near the equations' singular configuration (the front wheel
    broadside to the line of contacts, which a leaning bicycle meets inside the steer lock):
    status "singular", singular_t. A start at or
    beyond fall_angle, or where no pitch puts the front wheel on the ground, raises
    ParameterError naming lean0, whatever the method. Ctrl-C raises KeyboardInterrupt within
    a step.

    Driven: torques sampled at torque_t (torque_roll and/or torque_steer, N m; interpolated,
    zero outside), impulses (t, J_roll, J_steer) in N m s at multiples of step, feedback
    T = -K x with k as in closed_loop_window (a gain table read at the rear contact's speed).
    Adds arrays T_phi, T_delta, work_t and floats work, max_energy_change; energy_drift is then
    that of E - E(0) - W.

    For the leaning rider's params (`lean_rider()`): lean0 is the roll, torque_lean (with
    torque_t) the lean torque T9 beside torque_roll and torque_steer; stop_when, impulses and k
    are the bicycle's. The dict holds arrays t, roll, steer, lean (the torso on its joint), yaw,
    pitch, x, y, energy, the counts, max_energy_drift, fall_angle, steer_lock, singular_pivot,
    singular_t and status ("completed", "fell", "torso fell", "steer lock", "singular") with
    status_line. A start with |lean0| at or beyond fall_angle, limits outside their ranges, or a
    start at or beyond the singular configuration (naming the pivot) raises ParameterError."""

def simulate_many(
    params: Params,
    speeds: npt.ArrayLike,
    lean0s: npt.ArrayLike,
    duration: float,
    steer_rates: Optional[npt.ArrayLike] = None,
    step: float = 0.001,
    *,
    method: str = "rk4",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    stop_when: Sequence[str] = (),
    strict: bool = False,
) -> dict[str, object]:
    """Many simulations in parallel (GIL released), keeping the ends: arrays t_end, lean, steer,
    yaw, x, y, lean_rate, steer_rate, event_t, fall_t (the lean reaching 1.2 rad; NaN when
    not), steer_lock_t (the steer reaching 1.4 rad; NaN when not), singular_t (near the
    equations' singular configuration; NaN when not), stopped_by, fell, ok, rhs_evaluations and the list errors; each equals `simulate`'s end bit for bit, and a chunk of a batch (any slice,
    any memory layout) gives the batch's rows for it bit for bit, so chunks can run on Dask
    workers (docs/examples/basin_dask.py)."""

# Moore's (2012) leaning rider: the bicycle with the rider's torso on a lean joint (12 states).
# Its parameters, a dict in Moore's names, select the model where a bicycle's params are taken
# (state_space, eigenvalues, window, closed_loop_window, closed_loop_eigenvalues,
# frequency_response, simulate).

def lean_rider(path: str | None = None) -> dict[str, float]:
    """The parameters of Moore's (2012) leaning rider as a dict in Moore's names (36 values: the
    hinge and frame lengths d1-d4, l1-l6, the wheel radii rr, rf, the masses mc, md, me, mf, mg
    (torso), their inertias, g, and the lean joint's damping c9 and stiffness k9):
    BicycleParameters' mooreriderlean2012_browser_jason (Jason on the Browser bicycle), or the
    `name = value` file `path`. Give it to eigenvalues, state_space and window in place of a
    bicycle."""

def report() -> list[dict[str, object]]:
    """The memoir concordance, the entries of `carvallo report --json`."""

def speed_gradients(params: Params, strict: bool = False) -> dict[str, object]:
    """Weave and capsize speeds with their exact derivatives: d_weave, d_capsize dicts."""

def first_order(
    params: Params, sigma: Optional[Params] = None, strict: bool = False
) -> dict[str, Optional[float]]:
    """First-order standard deviations weave_std, capsize_std: independent parameters with the
    standard deviations `sigma`, or (sigma=None) those of ufloat params with their correlations."""

def monte_carlo(
    params: Params,
    sigma: Optional[Params] = None,
    samples: int = 10000,
    seed: int = 1897,
    strict: bool = False,
) -> dict[str, object]:
    """Seeded Monte Carlo: arrays weave and capsize (NaN if none) and the count invalid; sigma=None
    takes the standard deviations of ufloat params (drawn independently); 32 bytes a sample
    within the 1 GiB limit (about 3.3e7 samples); stops on Ctrl-C."""

def eigenvalue_bands(
    params: Params,
    sigma: Optional[Params],
    speeds: Speeds,
    samples: int = 2000,
    seed: int = 1897,
    quantiles: tuple[float, float] = (0.025, 0.975),
    strict: bool = False,
) -> dict[str, npt.NDArray[np.float64]]:
    """Quantile bands of the sorted real parts of the eigenvalues: speeds, nominal, lower, upper;
    samples x (240 + 40 x speeds) bytes within the 1 GiB limit; stops on Ctrl-C."""

def simulate_hoop(
    theta0: float,
    s0: float,
    duration: float,
    step: float = 0.001,
    every: int = 10,
    *,
    p0: float = 0.0,
    n0: float = 0.0,
    radius: float = 0.5,
    mass: float = 1.0,
    g: float = 9.81,
    method: str = "rk4",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    stop_when: Sequence[str] = (),
) -> dict[str, object]:
    """The rolling hoop (n° 7, state theta, p, n, s) by rk4 or dopri5 / dop853 / vern9 with
    rtol and atol, until duration or a stop_when condition ("theta=±0.5"): arrays t, theta, p,
    n, s; energy_drift, relative_energy_drift; method, rtol, atol, rhs_evaluations, steps,
    rejected_steps, events (list of {"when", "t"})."""

def simulate_unicycle(
    rider: dict[str, float],
    wheel: dict[str, float],
    radius: float,
    theta0: float,
    s0: float,
    duration: float,
    step: float = 0.001,
    every: int = 10,
    *,
    p0: float = 0.0,
    n0: float = 0.0,
    g: float = 9.81,
    method: str = "rk4",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    stop_when: Sequence[str] = (),
) -> dict[str, object]:
    """The mounted unicycle (n° 21-24): rider {mass, height, a, b, c, l}, wheel {mass, a1, b1,
    c1}; state, options and result as simulate_hoop."""

def pendulum_params() -> dict[str, float]:
    """The two-wheeled inverted pendulum's nominal design {r, W, mW, IWd, IWa, l, mB, IBxx, IByy,
    IBzz, g} (SI units): a personal transporter with its rider, illustrative values, not a
    published data set."""

def pendulum_eigenvalues(
    speeds: Union[float, Sequence[float], npt.NDArray[np.float64]],
    *,
    params: Optional[Mapping[str, float]] = None,
) -> npt.NDArray[np.complex128]:
    """The eigenvalues of the pendulum's linear model about upright running at each speed,
    shape (n, 4), by decreasing real part (lambda, 0, 0, -lambda); params changes values of
    pendulum_params()."""

def pendulum_state_space(
    speed: float,
    *,
    params: Optional[Mapping[str, float]] = None,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """(A, B) of the pendulum's linear model at speed: A (4, 4) over theta, thetad, thetaLd,
    thetaRd; B (4, 2) over the motor torques TL, TR."""

def simulate_pendulum(
    t_end: float,
    pitch0: float,
    *,
    speed: float = 2.0,
    params: Optional[Mapping[str, float]] = None,
    gain: Union[None, str, Sequence[Sequence[float]], npt.NDArray[np.float64]] = None,
    poles: Optional[Sequence[float]] = None,
    step: float = 0.01,
    every: int = 1,
    method: str = "dop853",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
) -> dict[str, object]:
    """The nonlinear pendulum from upright running at speed pitched by pitch0 (rad), open loop
    or under T = -K (x - x_ref) (gain "placed": poles, default -lambda, -1.5 lambda, -2 lambda;
    or K, 2 rows TL, TR of 4): arrays t, x, y, psi, theta, thetad, thetaLd, thetaRd, TL, TR;
    status ("fell" or "completed"), fall_time, energy0, max_energy_change, gain; method, rtol,
    atol, rhs_evaluations, steps, rejected_steps, events."""
