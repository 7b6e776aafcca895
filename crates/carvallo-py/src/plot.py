"""Figures of the bicycle with matplotlib (an optional dependency): the same figures as the
command line's ``carvallo plot geometry|eigenvalues|bode`` draws with plotters, from the same
numbers (``carvallo.geometry``, ``carvallo.modes``, ``carvallo.window``,
``carvallo.frequency_response``).

Each function returns the matplotlib ``Figure``; matplotlib is imported when a figure is drawn,
and its absence is an ``ImportError`` saying how to install it. The arguments are checked by
the Rust functions before anything is drawn: a bad one is a ``ParameterError`` (or a
``TypeError``) as for the other functions.
"""

import math

__all__ = ["plot_geometry", "plot_eigenvalues", "plot_bode"]

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")

# The command line's palette (crates/carvallo-cli/src/figures/chart.rs), so that both draw a
# curve in the same colour.
PALETTE = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2",
           "#17becf", "#bcbd22", "#000080", "#800000", "#464646"]

_MODE_COLOURS = {"weave": PALETTE[0], "capsize": PALETTE[1], "caster": PALETTE[2], "torso": PALETTE[3]}

_INPUTS = {"roll": "roll torque Tφ", "steer": "steer torque Tδ"}
# The most curves of one Bode figure (bicycles times speeds): a legend beyond it is unreadable.
MAX_CURVES = 20

_OUTPUTS = {
    "roll": "lean φ",
    "steer": "steer δ",
    "roll-rate": "lean rate dφ/dt",
    "steer-rate": "steer rate dδ/dt",
}


def _pyplot():
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:
        raise ImportError(
            "carvallo's plot functions need matplotlib, an optional dependency: "
            "pip install matplotlib"
        ) from e
    return plt


def decade_label(exponent):
    """The label of the decade 10**exponent, the exponent in superscript digits: 10⁻¹, 10⁰, 10¹."""
    return "10" + str(int(exponent)).translate(_SUPERSCRIPT)


def _decades(value, _pos=None):
    if value <= 0:
        return ""
    k = math.log10(value)
    return decade_label(round(k)) if abs(k - round(k)) < 1e-9 else ""


def _name_of(params, default):
    """A bicycleparameters.Bicycle's name (with its rider's), else `default`."""
    bike = getattr(params, "bicycleName", None)
    if not isinstance(bike, str):
        return default
    rider = getattr(params, "riderName", None)
    return f"{bike} + {rider}" if isinstance(rider, str) and rider else bike


def _is_rider(params):
    """Whether `params` is a leaning rider's dict in Moore's names (it holds mg, ig11 and d4)."""
    return isinstance(params, dict) and all(k in params for k in ("mg", "ig11", "d4"))


def _rider_name(params):
    """The name of a leaning rider's dict, as the command line names its `--model`: "Leaning
    rider (Browser + Jason)" for BicycleParameters' published set (the values of `lean_rider()`,
    `--model lean-rider`), "Leaning rider" for any other set (a dict does not keep the name of
    the file it was read from: give the file's path, or `name`)."""
    import carvallo

    published = carvallo.lean_rider()
    try:
        same = set(params) == set(published) and all(
            float(params[k]) == v for k, v in published.items())
    except (TypeError, ValueError):
        same = False
    return "Leaning rider (Browser + Jason)" if same else "Leaning rider"


def _rider_file(params):
    """`(dict, name)` for the path of a leaning rider's parameter file in Moore's names (read by
    `lean_rider(path)`), named by the file's stem without BicycleParameters' `Benchmark` suffix,
    as `carvallo plot eigenvalues --model FILE` names it; None for anything else."""
    import os
    import pathlib

    if not isinstance(params, (str, os.PathLike)):
        return None
    import carvallo

    stem = pathlib.Path(params).stem
    if stem.endswith("Benchmark") and stem != "Benchmark":
        stem = stem[: -len("Benchmark")]
    return carvallo.lean_rider(os.fspath(params)), stem


def _names(names):
    if len(names) == 1:
        return names[0]
    return ", ".join(names[:-1]) + " and " + names[-1]


def _axes(ax, size):
    plt = _pyplot()
    if ax is None:
        fig, ax = plt.subplots(figsize=size, layout="constrained")
        return fig, ax
    return ax.figure, ax


def plot_geometry(params, rider=None, name=None, ax=None):
    """The side view of the bicycle `params` (a dict, ufloats or a bicycleparameters.Bicycle), with
    the rider `rider` (a rider file or dict, as `add_rider`) drawn apart: wheels, schematic frame
    and fork, steer axis (dashed) and trail, the mass centres; titled "`name`: geometry". The
    points are `carvallo.geometry(params, rider)`'s, those of `carvallo plot geometry`."""
    import carvallo

    g = carvallo.geometry(params, rider)
    rider = isinstance(params, dict) and all(k in params for k in ("mg", "ig11", "d4"))
    name = name or _name_of(params, "Leaning rider" if rider else "Bicycle")
    fig, ax = _axes(ax, (9, 5))
    for hub, r in ((g["rear_hub"], g["rear_radius"]), (g["front_hub"], g["front_radius"])):
        t = [2 * math.pi * k / 180 for k in range(181)]
        ax.plot([hub[0] + r * math.cos(a) for a in t], [hub[1] + r * math.sin(a) for a in t],
                color="0.25")
    frame = list(g["frame"]) + [g["frame"][0]]
    ax.plot([p[0] for p in frame], [p[1] for p in frame], color="#1f77b4",
            label="frame (schematic) and fork")
    ax.plot(g["fork"][:, 0], g["fork"][:, 1], color="#1f77b4")
    axis = g["steer_axis"]
    tilt = math.degrees(math.atan2(axis[0, 0] - axis[1, 0], axis[1, 1] - axis[0, 1]))
    ax.plot(axis[:, 0], axis[:, 1], "--", color="0.25", label=f"steer axis, λ = {tilt:.1f}°")
    trail = g["trail"]
    ax.plot(trail[:, 0], trail[:, 1], color="#d62728", lw=3,
            label=f"trail c = {trail[1, 0] - trail[0, 0]:.3f} m")
    xs = [p[0] for p in g["mass_centres"].values()]
    hs = [p[1] for p in g["mass_centres"].values()]
    ax.plot(xs, hs, "o", color="black", label="mass centres")
    for label, p in g["mass_centres"].items():
        text = "whole" if label == "whole bicycle" else label
        if label == "rear wheel":
            ax.annotate(text, p, xytext=(-8, 6), textcoords="offset points", ha="right")
        else:
            ax.annotate(text, p, xytext=(6, 6), textcoords="offset points")
    ax.axhline(0.0, color="0.6", lw=1)
    ax.set_aspect("equal")
    ax.set_xlabel("x forward (m)")
    ax.set_ylabel("height (m)")
    ax.set_title(f"{name}: geometry")
    ax.legend(loc="upper right")
    return fig


def plot_eigenvalues(params, speeds=None, name=None, ax=None):
    """The eigenvalues of `params` against speed (default 301 speeds from 0 to 10 m/s), each real
    part in its mode's colour and named as `carvallo.modes` labels it (weave, capsize, caster,
    and torso for the leaning rider's params), the weave's imaginary part dashed, the stable
    range of `carvallo.window` shaded; titled "`name`: eigenvalues against speed". `params` may
    also be the path of a leaning rider's parameter file in Moore's names (read by
    `lean_rider(path)`); the name is by default the parameter set's, as `carvallo plot
    eigenvalues --model` names it: the file's stem for a path, "Leaning rider (Browser + Jason)"
    for the values of `lean_rider()`, "Leaning rider" for another rider's dict, a
    bicycleparameters.Bicycle's own names, "Bicycle" otherwise."""
    import numpy as np

    import carvallo

    loaded = _rider_file(params)
    if loaded is not None:
        params, stem = loaded
        name = name or stem
    if speeds is None:
        speeds = np.linspace(0.0, 10.0, 301)
    # Checked (and refused with a ParameterError) by modes before numpy reads them.
    labels, ev, _ = carvallo.modes(params, speeds)
    speeds = np.atleast_1d(np.asarray(speeds, float))
    if speeds.size == 0:
        raise carvallo.ParameterError("invalid speeds []: at least one speed is needed")
    name = name or (_rider_name(params) if _is_rider(params) else _name_of(params, "Bicycle"))
    fig, ax = _axes(ax, (9, 6))
    y_max = 10.0
    for a, b in carvallo.window(params)["stable"]:
        span = f"{a:.3f} < v < {b:.3f} m/s" if math.isfinite(b) else f"v > {a:.3f} m/s"
        ax.axvspan(a, min(b, speeds[-1]), color="#78c878", alpha=0.35, label=f"stable: {span}")
    done = set()
    for i, label in enumerate(labels):
        re = ev[:, i].real
        ax.plot(speeds, np.where(abs(re) <= y_max, re, np.nan), ".", ms=3,
                color=_MODE_COLOURS[label], label=None if label in done else f"{label}: Re λ")
        done.add(label)
    weave = [i for i, label in enumerate(labels) if label == "weave"]
    im = np.max(np.stack([ev[:, i].imag for i in weave]), axis=0)
    ax.plot(speeds, np.where((im > 0) & (im <= y_max), im, np.nan), "--",
            color=_MODE_COLOURS["weave"], label="weave: Im λ")
    # The legend in the corner with the fewest points under it (as the command line chooses),
    # each mode's name beside its curve, inside the frame and clear of the legend.
    v_max = speeds[-1]
    corners = [("lower right", (0.74, 1.0), (-1.0, -0.56)), ("upper right", (0.74, 1.0), (0.56, 1.0)),
               ("upper left", (0.0, 0.26), (0.56, 1.0)), ("lower left", (0.0, 0.26), (-1.0, -0.56))]
    points = [(v, e.real) for row, v in zip(ev, speeds) for e in row] + list(zip(speeds, im))

    def under(x, y, bx, by):
        return bx[0] * v_max <= x <= bx[1] * v_max and by[0] * y_max <= y <= by[1] * y_max

    loc, bx, by = min(corners, key=lambda c: sum(under(x, y, c[1], c[2]) for x, y in points))
    for label in dict.fromkeys(labels):
        re = ev[:, labels.index(label)].real
        inside = [k for k in range(len(speeds))
                  if abs(re[k]) < 0.85 * y_max and speeds[k] <= 0.93 * v_max
                  and not under(speeds[k], re[k], bx, by)]
        if inside:
            k = inside[-1]
            ax.annotate(label, (speeds[k], re[k]), xytext=(4, 8), textcoords="offset points")
    ax.axhline(0.0, color="black", lw=1)
    ax.set_xlim(speeds[0], speeds[-1])
    ax.set_ylim(-y_max, y_max)
    ax.set_xlabel("forward speed v (m/s)")
    ax.set_ylabel("eigenvalue (1/s)")
    ax.set_title(f"{name}: eigenvalues against speed")
    ax.legend(loc=loc)
    return fig


def plot_bode(bicycles, speeds=5.0, input="steer", output="roll", omegas=None, names=None,
              axes=None):
    """The Bode diagram from `input` ("roll"|"steer") to `output` ("roll"|"steer"|"roll-rate"|
    "steer-rate") of each bicycle of `bicycles` (one parameter set, or a list of them) at each of
    `speeds`, over `omegas` (default 301 from 0.1 to 100 rad/s): the magnitude (dB) above and the
    phase (degrees) below against ω on a logarithmic axis labelled by decades (10⁻¹, 10⁰, 10¹),
    one curve per bicycle and speed named in the legend by `names` (default: the
    bicycleparameters.Bicycle's name, or "bicycle 1", "bicycle 2", ...). `axes`: two matplotlib
    axes to draw into."""
    import numpy as np

    import carvallo

    if not isinstance(bicycles, (list, tuple)):
        bicycles = [bicycles]
    if not bicycles:
        raise carvallo.ParameterError("invalid bicycles []: at least one bicycle is needed")
    if omegas is None:
        omegas = np.logspace(-1, 2, 301)
    # Checked (and refused with a ParameterError) by frequency_response before numpy reads them.
    responses = [carvallo.frequency_response(b, speeds, omegas, input, output) for b in bicycles]
    speeds = np.atleast_1d(np.asarray(speeds, float))
    omegas = np.atleast_1d(np.asarray(omegas, float))
    if len(bicycles) * speeds.size > MAX_CURVES:
        raise carvallo.ParameterError(
            f"invalid speeds: {len(bicycles)} bicycles at {speeds.size} speeds are more than "
            f"the {MAX_CURVES} curves of one figure")
    if speeds.size == 0 or omegas.size == 0:
        raise carvallo.ParameterError("invalid speeds or omegas: none given")
    if (omegas <= 0).any():
        raise carvallo.ParameterError(
            f"invalid omega {float(omegas[omegas <= 0][0])!r}: the plot's logarithmic frequency axis "
            "needs positive frequencies")
    if names is None:
        default = ["Bicycle"] if len(bicycles) == 1 else [
            f"bicycle {k + 1}" for k in range(len(bicycles))]
        names = [_name_of(b, d) for b, d in zip(bicycles, default)]
    names = list(names)
    if not all(isinstance(n, str) for n in names):
        raise TypeError(f"names must be strings, not {names!r}")
    if len(names) != len(bicycles):
        raise carvallo.ParameterError(f"{len(names)} names for {len(bicycles)} bicycles")
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    if axes is None:
        plt = _pyplot()
        fig, axes = plt.subplots(2, 1, figsize=(9, 10), sharex=True, layout="constrained")
    else:
        fig = axes[0].figure
    mag_ax, phase_ax = axes
    k = 0
    for r, name in zip(responses, names):
        for i, v in enumerate(speeds):
            if len(bicycles) == 1:
                label = f"v = {v:g} m/s"
            elif len(speeds) == 1:
                label = name
            else:
                label = f"{name}, v = {v:g} m/s"
            colour = PALETTE[k % len(PALETTE)]
            mag_ax.semilogx(omegas, r["magnitude_db"][i], color=colour, label=label)
            phase_ax.semilogx(omegas, r["phase_deg"][i], color=colour)
            k += 1
    at = f", v = {speeds[0]:g} m/s" if len(speeds) == 1 else ""
    what = f"{_INPUTS.get(input, input)} to {_OUTPUTS.get(output, output)}"
    mag_ax.set_title(f"{_names(names)}: {what}{at}")
    phase_ax.set_title("Phase")
    mag_ax.set_ylabel("magnitude (dB)")
    phase_ax.set_ylabel("phase (degrees)")
    # From decade to decade, where a float holds them.
    lo = 10.0 ** math.floor(math.log10(omegas.min()))
    hi = 10.0 ** max(math.ceil(math.log10(omegas.max())), math.floor(math.log10(omegas.min())) + 1)
    for ax in axes:
        ax.set_xscale("log")
        if 0.0 < lo and math.isfinite(hi):
            ax.set_xlim(lo, hi)
        ax.xaxis.set_major_locator(LogLocator(base=10))
        ax.xaxis.set_major_formatter(FuncFormatter(_decades))
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.xaxis.set_tick_params(labelbottom=True)
        ax.set_xlabel("angular frequency ω (rad/s)")
        ax.grid(True, which="both", alpha=0.3)
    mag_ax.legend(loc="lower left")
    return fig
