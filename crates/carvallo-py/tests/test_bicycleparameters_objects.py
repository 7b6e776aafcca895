"""BicycleParameters' own objects as parameters: a dict of `uncertainties` ufloats
(`bicycle.parameters['Benchmark']`) and a `bicycleparameters.Bicycle` give the results of the
same values as floats, for every bicycle and rider of data/bicycleparameters/; their standard
deviations, and their correlations where the ufloats share sources (a rider combined with the
frame, parameters computed from raw measurements), reach `first_order` as the `uncertainties`
package itself propagates them."""

import contextlib
import io
import sys
import warnings

import hypothesis.strategies as st
import numpy as np
import pytest
from bicycleparameters import Bicycle
from hypothesis import given, settings
from uncertainties import ufloat

import carvallo
from conftest import ROOT

sys.path.insert(0, str(ROOT / "scripts"))
import bicycleparameters_peer as peer  # noqa: E402

IDS = [peer.label(b, r) for b, r in peer.CASES]
# The bicycles whose raw measurements BicycleParameters computes (Silver lacks dF).
RAW = ["Balanceassistv1", "Browser", "Browserins", "Crescendo", "Fisher", "Gyro", "Pista",
       "Rigid", "Rigidcl", "Stratos", "Yellow", "Yellowrev"]


def quiet(f, *args, **kwargs):
    """`f(...)` with BicycleParameters' progress and the triangle-inequality warnings silenced
    (Browser, Yellow, Yellowrev break one: they have their own tests)."""
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore", carvallo.PhysicsWarning)
        return f(*args, **kwargs)


def bicycle(bike, rider=None, raw=False):
    b = quiet(Bicycle, bike, pathToData=str(peer.DATA), forceRawCalc=raw)
    if rider:
        quiet(b.add_rider, rider)
    return b


def floats(p):
    return {k: float(getattr(v, "nominal_value", v)) for k, v in p.items()}


def linear_std(u, grad):
    """The standard deviation of sum_i g_i p_i by the `uncertainties` package (the first-order
    standard deviation of a function with gradient g, correlations included)."""
    total = 0.0
    for name, g in grad.items():
        v = u.get(name, u.get("lam")) if name == "lambda" else u.get(name)
        total = total + g * v
    return total.std_dev


@pytest.mark.parametrize("case", peer.CASES, ids=IDS)
def test_ufloats_and_bicycles_are_their_nominal_values(case):
    """A dict of ufloats (with BicycleParameters' extra keys IRzz, IFzz, yB, the fork and
    handlebar parts, read by the file reader's rules) and the `Bicycle` itself give the window and
    the eigenvalues of the floats, exactly."""
    b = bicycle(*case)
    u = dict(b.parameters["Benchmark"])
    expected = quiet(carvallo.window, floats(u))
    assert quiet(carvallo.window, u) == expected
    assert quiet(carvallo.window, b) == expected
    np.testing.assert_array_equal(
        quiet(carvallo.eigenvalues, b, [2.0, 5.0]), quiet(carvallo.eigenvalues, floats(u), [2.0, 5.0])
    )


@pytest.mark.parametrize("case", peer.CASES, ids=IDS)
def test_first_order_of_ufloats_is_that_of_uncertainties(case):
    """`first_order(ufloats)` (sigma=None): the standard deviations of the speeds equal the
    `uncertainties` package's for the linear function with carvallo's exact gradient, to 1e-12
    relative. For a bicycle file alone its values are independent, and the result equals
    `first_order(floats, sigma)` from `load_parameters`; with a rider added they share sources."""
    b = bicycle(*case)
    u = dict(b.parameters["Benchmark"])
    if not any(hasattr(v, "std_dev") for v in u.values()):
        # Tms's file states no uncertainty: BicycleParameters reads floats.
        with pytest.raises(carvallo.ParameterError, match="no uncertainties"):
            quiet(carvallo.first_order, u)
        return
    ours = quiet(carvallo.first_order, u)
    g = quiet(carvallo.speed_gradients, floats(u))
    for speed in ("weave", "capsize"):
        if g[f"d_{speed}"] is None:
            assert ours[f"{speed}_std"] is None
            continue
        assert ours[f"{speed}_std"] == pytest.approx(linear_std(u, g[f"d_{speed}"]), rel=1e-12)
    if case[1] is None:
        params, sigma = quiet(carvallo.load_parameters, str(peer.bicycle_file(case[0])))
        independent = quiet(carvallo.first_order, params, sigma)
        for key in ("weave_std", "capsize_std"):
            if independent[key] is None:
                assert ours[key] is None
            else:
                assert ours[key] == pytest.approx(independent[key], rel=1e-9, abs=1e-300), key


@pytest.mark.parametrize("bike", RAW)
def test_correlated_raw_parameters_reach_first_order(bike):
    """The parameters BicycleParameters computes from raw measurements share sources (the
    pendulum's stiffness, the wheelbase, ...): carvallo uses their covariance, which the
    `uncertainties` package confirms, and the result differs from the independent one. Gyro's
    flywheel is refused by name (not in the model); without it the rest is used."""
    b = bicycle(bike, raw=True)
    u = dict(b.parameters["Benchmark"])
    if "mD" in u:
        with pytest.raises(carvallo.ParameterError, match=r"^invalid mD .*: a flywheel D is not in the model"):
            quiet(carvallo.first_order, b)
        u = {k: v for k, v in u.items() if k not in ("mD", "IDxx", "IDyy")}
    ours = quiet(carvallo.first_order, u)
    g = quiet(carvallo.speed_gradients, u)
    sigma = {k: getattr(v, "std_dev", 0.0) for k, v in u.items()
             if k in carvallo.PARAM_NAMES or k == "lam"}
    independent = quiet(carvallo.first_order, floats(u), sigma)
    differs = False
    for speed in ("weave", "capsize"):
        if g[f"d_{speed}"] is None:
            continue
        assert ours[f"{speed}_std"] == pytest.approx(linear_std(u, g[f"d_{speed}"]), rel=1e-12)
        differs |= abs(ours[f"{speed}_std"] / independent[f"{speed}_std"] - 1) > 1e-3
    assert differs, (ours, independent)


@settings(max_examples=40, deadline=None)
@given(
    scale=st.lists(st.floats(0.0, 0.05), min_size=4, max_size=4),
    shared=st.floats(-0.02, 0.02),
)
def test_first_order_carries_any_shared_source(scale, shared):
    """The benchmark with ufloats that share one source `s` (w, c, rR, rF all move with it) and
    have their own sources: the standard deviations equal `uncertainties`'."""
    p = carvallo.benchmark()
    s = ufloat(0.0, 1.0)
    u = dict(p)
    for name, k in zip(("w", "c", "rR", "rF"), scale):
        u[name] = ufloat(p[name], k * p[name]) + shared * p[name] * s
    ours = carvallo.first_order(u)
    g = carvallo.speed_gradients(p)
    for speed in ("weave", "capsize"):
        assert ours[f"{speed}_std"] == pytest.approx(linear_std(u, g[f"d_{speed}"]), rel=1e-12, abs=1e-15)
        assert ours[f"{speed}_speed"] == g[f"{speed}_speed"]


def test_extra_keys_follow_the_file_reader():
    p = carvallo.benchmark()
    assert carvallo.window({**p, "yB": 0.0, "IRzz": p["IRxx"]}) == carvallo.window(p)
    with pytest.raises(carvallo.ParameterError, match=r"^invalid yB 0\.1: must be zero to 1e-6 of the wheelbase"):
        carvallo.window({**p, "yB": 0.1})
    with pytest.raises(carvallo.ParameterError, match=r"^invalid IFzz 1\.0: must equal IFxx"):
        carvallo.window({**p, "IFzz": 1.0})
    with pytest.raises(carvallo.ParameterError, match=r"^invalid mQ 2\.0: unknown parameter"):
        carvallo.window({**p, "mQ": 2.0})
    with pytest.raises(carvallo.ParameterError, match=r"^invalid mD 2\.0: a flywheel D is not in the model"):
        carvallo.window({**p, "mD": 2.0})
    # Where Moore's lateral force was applied: read and ignored, as in a file.
    assert carvallo.window({**p, "xcl": 0.2, "zcl": -0.9}) == carvallo.window(p)


def test_bad_objects_are_named():
    p = carvallo.benchmark()
    with pytest.raises(carvallo.ParameterError, match=r"^params must be a dict .* not \[1, 2\]"):
        carvallo.window([1, 2])
    with pytest.raises(carvallo.ParameterError, match=r"^parameter c = 'x' is not a number"):
        carvallo.window({**p, "c": "x"})
    with pytest.raises(carvallo.ParameterError, match=r"^invalid c 0\.08: its standard deviation -1\.0"):
        carvallo.window({**p, "c": _negative_std(0.08)})
    u = {**p, "c": ufloat(0.08, 0.001)}
    with pytest.raises(carvallo.ParameterError, match="params hold ufloats"):
        carvallo.first_order(u, {"c": 0.001})
    with pytest.raises(carvallo.ParameterError, match="no uncertainties"):
        carvallo.first_order(p)

    class NoBenchmark:
        parameters = {"Measured": {}}

    with pytest.raises(carvallo.ParameterError, match=r"has no benchmark parameters"):
        carvallo.window(NoBenchmark())


def _negative_std(x):
    class Fake:
        nominal_value = x
        std_dev = -1.0

    return Fake()
