"""Moore's (2012) leaning rider from Python (`carvallo.lean_rider`, and the bicycle's
`eigenvalues`, `state_space` and `window` given its params) against BicycleParameters 1.5.2's
`MooreRiderLean2012Model` run here, live, at speeds and designs that the committed peer file
(data/mooreriderlean2012/browser_jason_peer.json) does not hold: every entry of A and B to
1e-10 of the largest, the six non-zero eigenvalues to 1e-10 relative."""

import numpy as np
import pytest

import carvallo

models = pytest.importorskip("bicycleparameters.models")
from bicycleparameters.parameter_dicts import mooreriderlean2012_browser_jason  # noqa: E402
from bicycleparameters.parameter_sets import MooreRiderLean2012ParameterSet  # noqa: E402

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
