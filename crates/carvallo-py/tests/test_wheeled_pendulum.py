"""The two-wheeled inverted pendulum from Python (`pendulum_eigenvalues`,
`pendulum_state_space`, `simulate_pendulum`): the pitch eigenvalue against the planar
Lagrangian's closed form written here, the eigenvalues against numpy's of the returned A, the
energy conserved with the motors off, the placed feedback keeping the body up where its negation
and the open loop fall, bad arguments as errors naming the value, and the guide chapter's
example (`docs/guide/src/wheeled-pendulum.md`) printing its `# -> ` lines."""

import math
import re
import subprocess
import sys

import carvallo
import numpy as np
import pytest


def closed_form(p):
    """lambda**2 = mB g l Mt / (J Mt - mB**2 l**2), Mt = mB + 2 mW + 2 IWa / r**2,
    J = IByy + mB l**2."""
    mt = p["mB"] + 2 * p["mW"] + 2 * p["IWa"] / p["r"] ** 2
    j = p["IByy"] + p["mB"] * p["l"] ** 2
    return math.sqrt(p["mB"] * p["g"] * p["l"] * mt / (j * mt - p["mB"] ** 2 * p["l"] ** 2))


@pytest.mark.parametrize("change", [{}, {"mB": 60.0, "l": 0.7}, {"r": 0.3, "IWa": 0.1}])
def test_pitch_eigenvalue_is_the_closed_form(change):
    p = dict(carvallo.pendulum_params(), **change)
    speeds = np.array([0.0, 2.0, 6.0])
    ev = carvallo.pendulum_eigenvalues(speeds, params=change)
    assert ev.shape == (3, 4) and ev.dtype == np.complex128
    lam = closed_form(p)
    # Measured: 2e-15 relative (the runtime's test, at nine designs).
    assert np.allclose(ev[:, 0], lam, rtol=1e-12, atol=0) and np.allclose(ev[:, 3], -lam, rtol=1e-12)
    assert np.max(np.abs(ev[:, 1:3])) <= 1e-9 * lam
    a, b = carvallo.pendulum_state_space(2.0, params=change)
    assert a.shape == (4, 4) and b.shape == (4, 2)
    numpy_ev = np.sort(np.linalg.eigvals(a).real)[::-1]
    assert np.allclose(numpy_ev, ev[1].real, rtol=0, atol=1e-9 * lam)


def test_energy_is_conserved_with_the_motors_off():
    r = carvallo.simulate_pendulum(2.0, 0.1, rtol=1e-11)
    assert r["status"] == "fell" and 0.5 < r["fall_time"] < 1.0
    assert abs(abs(r["theta"][-1]) - math.pi / 2) < 1e-9
    assert r["max_energy_change"] / abs(r["energy0"]) < 1e-9
    assert r["gain"] is None and np.all(r["TL"] == 0)


def test_the_placed_feedback_keeps_the_body_up():
    r = carvallo.simulate_pendulum(4.0, 0.1, gain="placed")
    assert r["status"] == "completed" and r["fall_time"] is None
    assert abs(r["theta"][-1]) < 1e-5 and np.max(np.abs(r["theta"])) <= 0.1 + 1e-12
    assert r["gain"].shape == (2, 4)
    # The same gain negated pushes the body over.
    fell = carvallo.simulate_pendulum(4.0, 0.1, gain=-r["gain"])
    assert fell["status"] == "fell"
    own = carvallo.simulate_pendulum(4.0, -0.1, gain="placed", poles=[-4.0, -5.0, -6.0])
    assert own["status"] == "completed"


@pytest.mark.parametrize(
    "kwargs, needle",
    [
        (dict(params={"mB": -1.0}), "mB"),
        (dict(params={"mass": 1.0}), "mass"),
        (dict(pitch0=2.0), "pitch0"),
        (dict(poles=[-1.0, -2.0, -3.0]), "poles"),
        (dict(gain="placed", poles=[1.0, -2.0, -3.0]), "pole"),
        (dict(gain=[[1.0, 2.0]]), "gain"),
        (dict(t_end=-1.0), "t_end"),
    ],
)
def test_bad_arguments_name_the_value(kwargs, needle):
    args = dict(t_end=1.0, pitch0=0.1)
    args.update(kwargs)
    with pytest.raises(carvallo.ParameterError, match=needle):
        carvallo.simulate_pendulum(args.pop("t_end"), args.pop("pitch0"), **args)


def test_the_guide_example_runs(root, tmp_path):
    text = (root / "docs" / "guide" / "src" / "wheeled-pendulum.md").read_text()
    (code,) = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    (tmp_path / "example.py").write_text(code)
    out = subprocess.run([sys.executable, "example.py"], cwd=tmp_path, capture_output=True,
                         text=True, check=True)
    expected = [line[len("# -> "):] for line in code.splitlines() if line.startswith("# -> ")]
    assert len(expected) == 4 and out.stdout.splitlines() == expected
