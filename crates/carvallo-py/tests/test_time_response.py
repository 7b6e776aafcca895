"""Time responses of the linear plant (issue 37, item 6): `time_response` (the matrix
exponential) against SciPy's `signal.step`, `signal.impulse` and `signal.lsim` on the same A, B
(`state_space`), for every bicycle and bicycle + rider of data/bicycleparameters/, at stable,
unstable and near-defective speeds; and the command line's `response --json` equal to Python's."""

import sys
import warnings

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy import signal

import carvallo

pytestmark = pytest.mark.filterwarnings("ignore::carvallo.PhysicsWarning")
from conftest import ROOT

sys.path.insert(0, str(ROOT / "scripts"))
import bicycleparameters_peer as peer  # noqa: E402

T = np.linspace(0.0, 3.0, 61)
X0 = [0.02, -0.01, 0.1, 0.2]


def load(bike, rider=None):
    r = str(peer.rider_file(bike, rider)) if rider else None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", carvallo.PhysicsWarning)
        return carvallo.load_parameters(str(peer.bicycle_file(bike)), r)[0]


def close(ours, theirs, what):
    """Within 1e-9 of the largest value of the response (SciPy's lsim steps e^{A dt} along the
    grid; both are exponentials; measured: 5.2e-14 relative over all cases)."""
    scale = max(1e-12, np.abs(theirs).max())
    d = np.abs(ours - theirs).max() / scale
    assert d < 1e-9, (what, d)


@pytest.mark.parametrize("case", peer.CASES, ids=[peer.label(b, r) for b, r in peer.CASES])
def test_time_responses_equal_scipy(case):
    params = load(*case)
    for v in (0.684, 2.0, 5.0, 8.0):
        a, b = carvallo.state_space(params, [v])
        a, b = a[0], b[0]
        for i, u in enumerate(("roll", "steer")):
            sys_ = (a, b[:, i : i + 1], np.eye(4), np.zeros((4, 1)))
            _, y = signal.step(sys_, T=T)
            close(carvallo.time_response(params, v, T, "step", u), y, (case, v, "step", u))
            _, y = signal.impulse(sys_, T=T)
            close(carvallo.time_response(params, v, T, "impulse", u), y, (case, v, "impulse", u))
        sys_ = (a, b[:, :1], np.eye(4), np.zeros((4, 1)))
        _, y, _ = signal.lsim(sys_, np.zeros_like(T), T, X0=X0)
        close(carvallo.time_response(params, v, T, "initial", x0=X0), y, (case, v, "initial"))


def test_the_cli_prints_the_same(cli):
    params = carvallo.benchmark()
    c = cli("response", "--model", "benchmark", "--speed", "4", "--kind", "step", "--input",
            "roll", "--duration", "3", "--samples", "61", "--json")
    np.testing.assert_array_equal(c["t"][-1], 3.0)
    ours = carvallo.time_response(params, 4.0, c["t"], "step", "roll")
    for k, name in enumerate(("roll", "steer", "roll_rate", "steer_rate")):
        np.testing.assert_array_equal(np.array(c[name]), ours[:, k])


def test_bad_inputs_are_named():
    p = carvallo.benchmark()
    for args, kw, msg in [
        ((p, 5.0, T, "ramp"), {}, r'invalid kind "ramp"'),
        ((p, 5.0, T, "initial"), {}, r"needs x0"),
        ((p, 5.0, T, "initial"), {"x0": [0.1]}, r"invalid x0 of 1 values"),
        ((p, 5.0, T, "step"), {"x0": X0}, r"starts from rest"),
        ((p, 5.0, [0.0, -1.0], "step"), {}, r"invalid time -1.0"),
        ((p, 5.0, "soon", "step"), {}, r"invalid times 'soon'"),
        ((p, 5.0, T, "step", "yaw"), {}, r"unknown signal \"yaw\""),
        ((p, float("nan"), T, "step"), {}, r"invalid speed NaN"),
    ]:
        with pytest.raises(carvallo.ParameterError, match=msg):
            carvallo.time_response(*args, **kw)


@settings(max_examples=40, deadline=None, derandomize=True)
@given(
    v=st.floats(-5, 15),
    t=st.lists(st.floats(0, 5), min_size=1, max_size=5),
    x0=st.lists(st.floats(-1, 1), min_size=4, max_size=4),
)
def test_superposition_and_linearity(v, t, x0):
    """The initial-condition response is linear in x0 and the impulse response from rest is the
    initial-condition response from b (B's column), for any speed and times."""
    p = carvallo.benchmark()
    a, b = carvallo.state_space(p, [v])
    one = carvallo.time_response(p, v, t, "initial", x0=x0)
    two = carvallo.time_response(p, v, t, "initial", x0=[2 * x for x in x0])
    np.testing.assert_allclose(two, 2 * one, rtol=1e-12, atol=1e-300)
    imp = carvallo.time_response(p, v, t, "impulse", "steer")
    fromb = carvallo.time_response(p, v, t, "initial", x0=list(b[0][:, 1]))
    np.testing.assert_array_equal(imp, fromb)
