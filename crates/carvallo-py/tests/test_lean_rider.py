"""Moore's (2012) leaning rider from Python (`carvallo.lean_rider`, and the bicycle's
`eigenvalues`, `state_space` and `window` given its params) against BicycleParameters 1.5.2's
`MooreRiderLean2012Model` run here, live, at speeds and designs that the committed peer file
(data/mooreriderlean2012/browser_jason_peer.json) does not hold: every entry of A and B to
1e-10 of the largest, the six non-zero eigenvalues to 1e-10 relative."""

import numpy as np
import pytest

# The peer is installed by scripts/test (bicycleparameters==1.5.2): a missing one is an error,
# not a skip (a skipped module would pass with nothing compared).
import bicycleparameters.models as models
from bicycleparameters.parameter_dicts import mooreriderlean2012_browser_jason
from bicycleparameters.parameter_sets import MooreRiderLean2012ParameterSet

import carvallo

SPEEDS = [0.5, 3.0, 4.5, 7.0, 10.0]
DESIGNS = {
    "browser_jason": {},
    # A lean joint with stiffness and damping, a heavier torso and a longer hinge.
    "stiff_heavy": {"k9": 800.0, "c9": 40.0, "mg": 60.0, "ig11": 2.6, "d4": -0.7},
}


def theirs(change, v):
    par = dict(mooreriderlean2012_browser_jason, **change)
    model = models.MooreRiderLean2012Model(MooreRiderLean2012ParameterSet(par))
    return model.form_state_space_matrices(v=v)


@pytest.mark.parametrize("name", sorted(DESIGNS))
def test_state_space_and_eigenvalues_equal_bicycleparameters(name):
    params = dict(carvallo.lean_rider(), **DESIGNS[name])
    a, b = carvallo.state_space(params, SPEEDS)
    assert a.shape == (len(SPEEDS), 12, 12) and b.shape == (len(SPEEDS), 12, 3)
    ev = carvallo.eigenvalues(params, SPEEDS)
    assert ev.shape == (len(SPEEDS), 6)
    worst = [0.0, 0.0, 0.0]
    for k, v in enumerate(SPEEDS):
        ta, tb = theirs(DESIGNS[name], v)
        worst[0] = max(worst[0], np.abs(a[k] - ta).max() / np.abs(ta).max())
        worst[1] = max(worst[1], np.abs(b[k] - tb).max() / np.abs(tb).max())
        te = np.linalg.eigvals(ta)
        te = te[np.abs(te) > 1e-6]
        assert len(te) == 6, (v, te)
        te = te[np.lexsort((-te.imag, -te.real))]
        worst[2] = max(worst[2], (np.abs(ev[k] - te) / np.abs(te)).max())
    print(f"\n{name}: A {worst[0]:.1e} of max, B {worst[1]:.1e} of max, eigenvalues {worst[2]:.1e}")
    assert worst[0] < 1e-10 and worst[1] < 1e-10 and worst[2] < 1e-10, worst


def test_the_dict_is_bicycleparameters_and_the_window_says_what_it_found():
    theirs = {k: v for k, v in mooreriderlean2012_browser_jason.items() if k != "v"}
    assert carvallo.lean_rider() == theirs
    w = carvallo.window(carvallo.lean_rider())
    assert w["stable"] == [] and w["scan"] == (0.0, 20.0)
    w = carvallo.window(dict(carvallo.lean_rider(), k9=1e4, c9=100.0))
    [(lo, hi)] = w["stable"]
    # The CLI's and the runtime's tests find the same edges.
    assert abs(lo - 4.990701769990846) < 1e-8 and abs(hi - 7.109479530388491) < 1e-8, w


def test_bad_leaning_rider_params_name_the_value():
    with pytest.raises(carvallo.ParameterError, match="missing parameter `k9`"):
        p = carvallo.lean_rider()
        del p["k9"]
        carvallo.eigenvalues(p, [4.0])
    with pytest.raises(carvallo.ParameterError, match="invalid parameter mg = -1"):
        carvallo.eigenvalues(dict(carvallo.lean_rider(), mg=-1.0), [4.0])
    with pytest.raises(carvallo.ParameterError, match="unknown parameter `w`"):
        carvallo.state_space(dict(carvallo.lean_rider(), w=1.0), [4.0])


def test_simulate_keeps_the_energy_and_the_lean_torque_does_its_work():
    """Without torques the energy is kept until the passive torso falls (a status, not an
    error); with a lean torque ramping from 0 to 8 N m over 1 s its work, the integral of
    T9 dq9 (trapezoids on a fine grid), is the energy's gain."""
    r = carvallo.simulate(carvallo.lean_rider(), 5.0, 0.01, 3.0)
    assert r["status"] == "torso fell", r["status_line"]
    assert abs(abs(r["lean"][-1]) - 1.2) < 1e-12
    assert np.abs(r["energy"] - r["energy"][0]).max() < 1e-8 * r["energy"][0]
    r = carvallo.simulate(carvallo.lean_rider(), 5.0, 0.01, 3.0, every=1, method="dop853",
                          rtol=1e-11, torque_t=[0.0, 1.0], torque_lean=[0.0, 8.0])
    t, lean, e = r["t"], r["lean"], r["energy"]
    torque = np.interp(t, [0.0, 1.0], [0.0, 8.0], right=0.0)
    work = np.sum(0.5 * (torque[1:] + torque[:-1]) * np.diff(lean))
    print(f"\nramped lean torque: energy gain {e[-1] - e[0]:.9f} J, work {work:.9f} J, "
          f"{r['status_line']}")
    assert abs(work) > 1.0
    # Trapezoids at 1 ms on a smooth integrand: far below 1e-4 J.
    assert abs(e[-1] - e[0] - work) < 1e-4, (e[-1] - e[0], work)


def test_simulate_refuses_what_is_the_bicycles():
    with pytest.raises(carvallo.ParameterError, match="torque_lean is the leaning rider's"):
        carvallo.simulate(carvallo.benchmark(), 5.0, 0.01, 1.0, torque_t=[0.0, 1.0],
                          torque_lean=[1.0, 1.0])
    with pytest.raises(carvallo.ParameterError, match="not yet for the leaning rider"):
        carvallo.simulate(carvallo.lean_rider(), 5.0, 0.01, 1.0, stop_when=["lean=0.5"])
    with pytest.raises(carvallo.ParameterError, match="torque_lean needs torque_t"):
        carvallo.simulate(carvallo.lean_rider(), 5.0, 0.01, 1.0, torque_lean=[1.0])
    with pytest.raises(carvallo.ParameterError, match="invalid lean0 1.3"):
        carvallo.simulate(carvallo.lean_rider(), 5.0, 1.3, 1.0)


def test_the_guides_example_runs_as_written():
    """docs/guide/src/lean-rider.md's Python block, executed; what its comments say, asserted."""
    import re
    from conftest import ROOT
    text = (ROOT / "docs" / "guide" / "src" / "lean-rider.md").read_text()
    [code] = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    ns = {}
    exec(code, ns)
    assert ns["ev"].shape == (3, 6) and (ns["ev"].real[:, 0] > 6.5).all()
    assert ns["A"].shape == (1, 12, 12) and ns["B"].shape == (1, 12, 3)
    assert ns["labels"] == ["weave", "weave", "capsize", "caster", "torso", "torso"]
    assert ns["modal"].shape == (1, 6) and ns["vectors"].shape == (1, 6, 6)
    w = carvallo.window(dict(ns["p"], k9=1e4, c9=100.0))
    assert [(round(a, 2), round(b, 2)) for a, b in w["stable"]] == [(4.99, 7.11)]
    assert ns["run"]["status"] == "torso fell" and abs(ns["run"]["lean"][-1]) == 1.2
    assert ns["fig"].axes[0].get_title() == "Leaning rider (Browser + Jason): eigenvalues against speed"


def test_lean_feedback_is_the_joints_spring_and_damper():
    """K with k_lean_lean = 1e4 and k_lean_lean_rate = 100 (by name, or as a (3, 6) array)
    closes the loop through B; the same spring and damper as k9, c9 are in the equations."""
    p = carvallo.lean_rider()
    k = {"k_lean_lean": 1e4, "k_lean_lean_rate": 100.0}
    array = np.zeros((3, 6))
    array[2, 2], array[2, 5] = 1e4, 100.0
    speeds = [1.0, 4.0, 6.0, 9.0]
    sprung = carvallo.eigenvalues(dict(p, k9=1e4, c9=100.0), speeds)
    for gains in (k, array):
        closed = carvallo.closed_loop_eigenvalues(p, gains, speeds)
        assert closed.shape == (4, 6)
        assert (np.abs(closed - sprung) / np.abs(sprung)).max() < 1e-10
    w = carvallo.closed_loop_window(p, k)
    [(lo, hi)] = w["stable"]
    assert abs(lo - 4.990701769990846) < 1e-8 and abs(hi - 7.109479530388491) < 1e-8
    with pytest.raises(carvallo.ParameterError, match="unknown gain `k_lean_yaw`"):
        carvallo.closed_loop_eigenvalues(p, {"k_lean_yaw": 1.0}, [4.0])
    with pytest.raises(carvallo.ParameterError, match=r"shape \(3, 6\), not \[2, 4\]"):
        carvallo.closed_loop_eigenvalues(p, np.zeros((2, 4)), [4.0])


@pytest.mark.parametrize("inp,out", [("lean", "roll"), ("steer", "roll"), ("roll", "lean-rate"),
                                     ("lean", "steer-rate")])
def test_frequency_response_equals_the_peers_state_space(inp, out):
    """G(iω) of the leaning rider against C (iωI - A)^-1 B with BicycleParameters' A and B,
    solved by numpy (magnitude to 1e-9 relative; the phase equal modulo 360°, ours on the
    branch continuous in ω: no jump between neighbouring frequencies of a fine grid)."""
    inputs = {"roll": 0, "steer": 1, "lean": 2}
    states = {"roll": 3, "steer": 5, "lean": 7, "roll-rate": 8, "steer-rate": 10, "lean-rate": 11}
    omegas = np.logspace(-1, 2, 301)
    for v in [2.0, 5.0]:
        r = carvallo.frequency_response(carvallo.lean_rider(), [v], omegas, inp, out)
        ta, tb = theirs({}, v)
        g = np.array([np.linalg.solve(1j * w * np.eye(12) - ta, tb[:, inputs[inp]])[states[out]]
                      for w in omegas])
        ours = r["response"][0]
        assert (np.abs(ours - g) / np.abs(g)).max() < 1e-9
        ph = r["phase_deg"][0]
        wrapped = (ph - np.degrees(np.angle(g)) + 180.0) % 360.0 - 180.0
        assert np.abs(wrapped).max() < 1e-6
        assert np.abs(np.diff(ph)).max() < 30.0, np.abs(np.diff(ph)).max()
    with pytest.raises(carvallo.ParameterError, match="unknown input `yaw` for the leaning rider"):
        carvallo.frequency_response(carvallo.lean_rider(), [5.0], [1.0], "yaw", "roll")


def test_modes_label_the_torso_by_its_eigenvector_as_the_cli_does(cli):
    """carvallo.modes on the leaning rider: six labels, each column an eigenvector of the lateral
    block of A; the two torso roots are those whose vectors put the largest share of their
    coordinates on the lean joint q9 (computed here from the vectors); the same labels and
    eigenvalues as `carvallo eig --model lean-rider --json`."""
    p = carvallo.lean_rider()
    speeds = [0.5, 3.0, 10.0]
    labels, ev, vec = carvallo.modes(p, speeds)
    assert labels == ["weave", "weave", "capsize", "caster", "torso", "torso"]
    a, _ = carvallo.state_space(p, speeds)
    lateral = [3, 5, 7, 8, 10, 11]
    for k in range(len(speeds)):
        lat = a[k][np.ix_(lateral, lateral)]
        r = lat @ vec[k] - vec[k] @ np.diag(ev[k])
        assert np.abs(r).max() < 1e-9 * np.abs(lat).max()
        coords = np.abs(vec[k, :3, :]) ** 2
        share = coords[2] / coords.sum(axis=0)
        torso = sorted(np.argsort(share)[-2:])
        assert torso == [4, 5], (speeds[k], share)
    c = cli("eig", "--model", "lean-rider", "--speed", "3", "--json")
    assert [m["label"] for m in c["modes"]] == labels
    assert np.allclose([complex(m["re"], m["im"]) for m in c["modes"]], ev[1], rtol=0, atol=1e-12)
