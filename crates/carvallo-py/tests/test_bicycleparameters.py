"""carvallo against BicycleParameters 1.5.2 (installed by the test command) on every file of
data/bicycleparameters/: the 12 bicycles (the two-mass-skate `Tms` among them) and the three
bicycle + rider pairs. Eigenvalues at several speeds against `benchmark_par_to_canonical` +
`ab_matrix`, the stable speed range against a bisection of BicycleParameters' eigenvalues (from
Python and from the command line), and the rider combination against `Bicycle.add_rider`.
BicycleParameters' side is scripts/bicycleparameters_peer.py, which also prints the guide's
table (scripts/bicycleparameters-table)."""

import sys
import warnings

import numpy as np
import pytest
from uncertainties import nominal_value, std_dev

import carvallo
from conftest import ROOT

sys.path.insert(0, str(ROOT / "scripts"))
import bicycleparameters_peer as peer  # noqa: E402

IDS = [peer.label(b, r) for b, r in peer.CASES]


def quiet(f, *args):
    """`f(*args)` with the warnings of broken triangle inequalities (Browser, Yellow, Yellowrev)
    silenced: they have their own tests."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", carvallo.PhysicsWarning)
        return f(*args)


def load(bike, rider=None):
    """carvallo's parameters and standard deviations of a case."""
    r = str(peer.rider_file(bike, rider)) if rider else None
    return quiet(carvallo.load_parameters, str(peer.bicycle_file(bike)), r)


@pytest.fixture(scope="module")
def theirs():
    """BicycleParameters' parameters and stability edges of every case (computed once)."""
    out = {}
    for bike, rider in peer.CASES:
        p = peer.parameters(bike, rider)
        out[(bike, rider)] = (p, peer.stability_edges(p))
    return out


@pytest.mark.parametrize("case", peer.CASES, ids=IDS)
def test_eigenvalues_equal_bicycleparameters(case, theirs):
    """Every eigenvalue at 0.5 to 10 m/s within 1e-10 of BicycleParameters' (relative to
    max(1, |lambda|)); the largest differences measured are 5e-15 to 2e-14, 3.8e-13 for Tms (whose
    mass matrix has condition number 1.2e3)."""
    params, _ = load(*case)
    p, _ = theirs[case]
    ours = quiet(carvallo.eigenvalues, params, list(peer.SPEEDS))
    for k, v in enumerate(peer.SPEEDS):
        d = peer.eigenvalue_difference(ours[k], peer.eigenvalues(p, v))
        assert d <= 1e-10, (case, v, d, ours[k], peer.eigenvalues(p, v))


@pytest.mark.parametrize("case", peer.CASES, ids=IDS)
def test_stable_speeds_equal_bicycleparameters_bisection(case, theirs, cli):
    """The ends of the stable speed range up to 20 m/s, from Python and from `carvallo window`,
    within 1e-8 m/s of where BicycleParameters' largest real part changes sign."""
    bike, rider = case
    params, _ = load(bike, rider)
    _, edges = theirs[case]
    w = quiet(carvallo.window, params)
    args = ["window", "--model", str(peer.bicycle_file(bike)), "--json"]
    if rider:
        args += ["--rider", str(peer.rider_file(bike, rider))]
    c = cli(*args)
    assert (c["weave_speed"], c["capsize_speed"]) == (w["weave_speed"], w["capsize_speed"])
    ours = [x for x in peer.edges_of(w["stable"]) if x <= peer.VMAX]
    assert len(ours) == len(edges) >= 1, (case, ours, edges)
    for a, b in zip(ours, edges):
        assert abs(a - b) <= 1e-8, (case, ours, edges)
    assert w["weave_speed"] == pytest.approx(edges[0], abs=1e-8)


@pytest.mark.parametrize("bike, rider", peer.RIDER_PAIRS, ids=[peer.label(*c) for c in peer.RIDER_PAIRS])
def test_riders_equal_bicycle_add_rider(bike, rider):
    """`load_parameters(bike, rider=...)` equals BicycleParameters' `Bicycle.add_rider`: values to
    1e-12 relative, standard deviations (first order on both sides) to 1e-6."""
    params, sigma = load(bike, rider)
    for name, u in peer.uncertain_parameters(bike, rider).items():
        key = "lambda" if name == "lam" else name
        if key not in params:
            continue  # IRzz, IFzz, yB, ...: read and checked, not model parameters
        assert params[key] == pytest.approx(nominal_value(u), rel=1e-12, abs=1e-14), name
        assert sigma[key] == pytest.approx(std_dev(u), rel=1e-6, abs=1e-15), name


def test_the_two_mass_skate_is_the_limit_of_zero_radius(theirs):
    """Tms (Kooijman et al., Science 332, 2011): rR = rF = 0 with massless, inertia-free wheels.
    BicycleParameters' formulas divide by the radius there (IRyy/rR = 0/0: ZeroDivisionError on
    floats, NaN on numpy floats); at a radius r > 0 they are a polynomial in r plus IRyy/r = 0, and
    their eigenvalues at r = 1e-3, 1e-5, 1e-7 are carvallo's at r = 0, as are carvallo's own at
    r > 0 (a second route to the limit). No capsize speed: the coefficient of v^2 in a0 is
    proportional to the gyroscopic terms, zero here."""
    params, _ = load("Tms")
    assert params["rR"] == params["rF"] == 0.0
    p, edges = theirs[("Tms", None)]
    with pytest.raises(ZeroDivisionError):
        peer.benchmark_par_to_canonical(dict(p))
    with np.errstate(invalid="ignore"):
        raw = peer.benchmark_par_to_canonical({k: np.float64(x) for k, x in p.items()})
    assert np.isnan(raw[3]).any()
    ours = carvallo.eigenvalues(params, list(peer.SPEEDS))
    for r in (1e-3, 1e-5, 1e-7):
        wheels = {"rR": r, "rF": r}
        near = carvallo.eigenvalues({**params, **wheels}, list(peer.SPEEDS))
        for k, v in enumerate(peer.SPEEDS):
            d = peer.eigenvalue_difference(ours[k], peer.eigenvalues({**p, **wheels}, v))
            assert d <= 1e-10, (r, v, d)
            assert peer.eigenvalue_difference(ours[k], near[k]) <= 1e-10, (r, v)
    w = carvallo.window(params)
    assert w["capsize_speed"] is None and w["stable"] == [(w["weave_speed"], float("inf"))], w
    assert w["weave_speed"] == pytest.approx(edges[0], abs=1e-8) and len(edges) == 1
    # A zero radius with a spin inertia would be an infinite gyroscopic coupling.
    with pytest.raises(carvallo.ParameterError, match=r"invalid IRyy 0\.1: must be zero for a rear wheel of zero radius rR = 0"):
        carvallo.window({**params, "IRxx": 0.1, "IRyy": 0.1})
    with pytest.raises(carvallo.ParameterError, match=r"invalid IFyy 0\.2: must be zero for a front wheel of zero radius rF = 0"):
        carvallo.eigenvalues({**params, "IFxx": 0.1, "IFyy": 0.2}, [1.0])
    # The nonlinear model, whose speeds are the wheels' rotation rates, refuses it by name.
    with pytest.raises(carvallo.ParameterError, match=r"invalid rR 0\.0: must be positive for the nonlinear model"):
        carvallo.simulate(params, 3.0, 0.01, 0.1)
