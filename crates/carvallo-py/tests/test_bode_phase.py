"""The Bode phase is a function of the frequency, not of the grid (issue 37, item 1): the same at a
frequency whatever other frequencies are asked for, and equal modulo 360° to SciPy's
`signal.freqresp` on BicycleParameters' own A, B (`ab_matrix`) and to BicycleParameters'
`Bicycle.plot_bode` (dtk's `control.bode`, which unwraps along its grid), for every bicycle and
bicycle + rider of data/bicycleparameters/, every input-output pair, at speeds through the capsize
and weave speeds."""

import contextlib
import io
import sys
import warnings

import numpy as np
import pytest
from scipy import signal

import carvallo

pytestmark = pytest.mark.filterwarnings("ignore::carvallo.PhysicsWarning")
from conftest import ROOT

sys.path.insert(0, str(ROOT / "scripts"))
import bicycleparameters_peer as peer  # noqa: E402

INPUTS = ["roll", "steer"]
OUTPUTS = ["roll", "steer", "roll-rate", "steer-rate"]
SPEEDS = [0.5, 2.0, 4.0, 4.5, 5.0, 6.5, 8.0]
OMEGAS = np.logspace(-1, 2, 181)


def load(bike, rider=None):
    r = str(peer.rider_file(bike, rider)) if rider else None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", carvallo.PhysicsWarning)
        return carvallo.load_parameters(str(peer.bicycle_file(bike)), r)[0]


def mod360(d):
    """`d` brought into [-180°, 180°)."""
    return (np.asarray(d) + 180.0) % 360.0 - 180.0


@pytest.mark.parametrize("case", peer.CASES, ids=[peer.label(b, r) for b, r in peer.CASES])
def test_phase_equals_scipy_freqresp_modulo_360(case):
    """Largest difference modulo 360° below 1e-7° (measured: 1.6e-8° over all cases, SciPy
    going through a transfer function whose coefficients it calls badly conditioned)."""
    params = load(*case)
    mats = peer.matrices(peer.parameters(*case))
    g = peer.parameters(*case)["g"]
    for v in SPEEDS:
        a, b = peer.ab_matrix(*mats, v, g)
        for i, u in enumerate(INPUTS):
            for o, y in enumerate(OUTPUTS):
                ours = carvallo.frequency_response(params, [v], OMEGAS, u, y)["phase_deg"][0]
                c = np.eye(4)[o : o + 1]
                _, h = signal.freqresp((a, b[:, i : i + 1], c, np.zeros((1, 1))), OMEGAS)
                d = np.abs(mod360(ours - np.degrees(np.angle(h)))).max()
                assert d < 1e-7, (case, v, u, y, d)


def test_phase_equals_bicycleparameters_plot_bode_modulo_360():
    """Browser with Jason, the issue's case, at 4 and 5 m/s (unstable and stable weave): our
    phase against `Bicycle.plot_bode`'s (its grid, np.logspace(0, 2, 1000)) modulo 360°, and
    theirs, unwrapped from 1 rad/s, differs from ours by one constant multiple of 360° on the
    whole grid (ours starts from the branch in (-180°, 180°] as ω -> 0+, not from the grid's first
    point)."""
    import matplotlib

    matplotlib.use("Agg")
    from bicycleparameters import Bicycle

    params = load("Browser", "Jason")
    with contextlib.redirect_stdout(io.StringIO()):
        bike = Bicycle("Browser", pathToData=str(peer.DATA))
        bike.add_rider("Jason")
    w = np.logspace(0, 2, 1000)
    for v in (4.0, 5.0):
        for i, u in enumerate(INPUTS):
            for o, y in enumerate(OUTPUTS):
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    _, theirs, fig = bike.plot_bode(v, i, o)
                matplotlib.pyplot.close(fig)
                ours = carvallo.frequency_response(params, [v], w, u, y)["phase_deg"][0]
                d = ours - theirs
                assert np.abs(mod360(d)).max() < 1e-6, (v, u, y)
                k = np.round(d / 360.0)
                assert (k == k[0]).all(), (v, u, y, set(k))


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_any_two_grids_give_the_same_phase(seed):
    """Browser with Jason at 5 m/s (the issue's example) and the benchmark at 4 m/s: the
    issue's three-point grid against a 201-point one, and seeded random grids holding shared
    frequencies, give bit-identical phases there."""
    rng = np.random.default_rng(seed)
    for params, v in ((load("Browser", "Jason"), 5.0), (carvallo.benchmark(), 4.0)):
        sparse = carvallo.frequency_response(params, [v], [1.0, 3.162278, 10.0], "steer", "roll")
        dense_w = np.logspace(0, 1, 201)
        dense_w[100] = 3.162278
        dense = carvallo.frequency_response(params, [v], dense_w, "steer", "roll")
        assert sparse["phase_deg"][0, 1] == dense["phase_deg"][0, 100]
        shared = 10.0 ** rng.uniform(-2, 2, 7)
        for y in OUTPUTS:
            g1 = np.concatenate([10.0 ** rng.uniform(-2, 2, 5), shared])
            g2 = np.concatenate([shared, 10.0 ** rng.uniform(-2, 2, 50)])
            p1 = carvallo.frequency_response(params, [v], g1, "steer", y)["phase_deg"][0]
            p2 = carvallo.frequency_response(params, [v], g2, "steer", y)["phase_deg"][0]
            np.testing.assert_array_equal(p1[5:], p2[:7])
    # The values: -61.624° at 3.162278 rad/s for Browser + Jason at 5 m/s.
    p = carvallo.frequency_response(load("Browser", "Jason"), [5.0], [3.162278], "steer", "roll")
    assert p["phase_deg"][0, 0] == pytest.approx(-61.624, abs=1e-3)
