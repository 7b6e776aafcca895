"""The hoop and the unicycle from Python (`simulate_hoop`, `simulate_unicycle`): the
error-controlled pairs agree with RK4 at a small step (an independent route: fixed steps, no
error estimate), the hoop's fall is stopped at the time found by bisection on single RK4 steps,
and bad options are errors naming the value."""

import math

import carvallo
import numpy as np
import pytest

G, R = 9.81, 0.5
UNIT = math.sqrt(G / R)
RIDER = dict(mass=60.0, height=1.25, a=100.0, b=99.5, c=1.4, l=-0.3)
# A thin hoop of 5 kg and radius 0.5 m as the wheel: a1 = 1.5 m R², b1 = 2 m R², c1 = 0.5 m R².
WHEEL = dict(mass=5.0, a1=1.5 * 5 * R**2, b1=2.0 * 5 * R**2, c1=0.5 * 5 * R**2)


def hoop(**kw):
    return carvallo.simulate_hoop(kw.pop("theta0", 0.2), kw.pop("s0", 3 * UNIT), kw.pop("duration", 3.0),
                                  radius=R, **kw)


def unicycle(**kw):
    return carvallo.simulate_unicycle(RIDER, WHEEL, R, 0.05, 3 * UNIT, 3.0, **kw)


def largest_difference(a, b):
    assert len(a["t"]) == len(b["t"]) and np.allclose(a["t"], b["t"], rtol=0, atol=1e-12)
    return max(float(np.max(np.abs(a[k] - b[k]))) for k in ("theta", "p", "n", "s"))


@pytest.mark.parametrize("run", [hoop, unicycle])
@pytest.mark.parametrize("method", ["dopri5", "dop853", "vern9"])
def test_adaptive_pairs_agree_with_rk4_at_a_small_step(run, method):
    # Samples every 0.01 s for both: RK4 at 1e-4 s (error about 1e-13 on these motions, the
    # bench's check) and the pair's dense output.
    rk4 = run(step=1e-4, every=100)
    assert (rk4["method"], rk4["rtol"], rk4["rejected_steps"]) == ("rk4", None, 0)
    assert rk4["rhs_evaluations"] == 4 * rk4["steps"] == 4 * 30000
    r = run(step=0.01, every=1, method=method, rtol=1e-10)
    assert (r["method"], r["rtol"], r["atol"]) == (method, 1e-10, 1e-13)
    diff = largest_difference(r, rk4)
    # DOPRI5's dense output is of order 4: between its steps it errs more (the runtime's tests).
    # Measured: 1.4e-9 (hoop) and 6.2e-10 (unicycle) for DOPRI5, 1.0e-10 and 2.6e-11 for
    # DOP853, 8.2e-12 and 6.0e-13 for Verner's 9(8).
    assert diff <= (1e-8 if method == "dopri5" else 1e-9), diff
    assert r["steps"] < rk4["steps"] / 10 and r["events"] == []
    assert r["relative_energy_drift"] <= 1e-9


def bisected_fall(theta0, s0, value):
    """The time |theta| first reaches `value`: the bracketing step of an RK4 run at 1e-4 s,
    then bisection on the length of one RK4 step from its start."""
    h = 1e-4
    fine = hoop(theta0=theta0, s0=s0, duration=5.0, step=h, every=1)
    k = int(np.argmax(np.abs(fine["theta"]) >= value)) - 1
    assert k >= 0 and abs(fine["theta"][k + 1]) >= value
    start = {name: fine[name][k] for name in ("theta", "p", "n", "s")}
    lo, hi = 0.0, h
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        one = carvallo.simulate_hoop(start["theta"], start["s"], mid, step=mid, every=1, p0=start["p"],
                                     n0=start["n"], radius=R)
        if abs(one["theta"][-1]) < value:
            lo = mid
        else:
            hi = mid
    return fine["t"][k] + 0.5 * (lo + hi)


def test_a_slow_hoop_falls_at_the_bisected_time():
    exact = bisected_fall(0.1, 0.5 * UNIT, 0.5)
    for method, rtol, tol in [("rk4", None, 1e-9), ("dop853", 1e-12, 1e-10), ("vern9", 1e-12, 1e-10)]:
        kw = dict(method=method) if rtol is None else dict(method=method, rtol=rtol)
        r = hoop(theta0=0.1, s0=0.5 * UNIT, duration=5.0, stop_when=["theta=±0.5"], **kw)
        (event,) = r["events"]
        assert event["when"] == "theta=±0.5" and r["t"][-1] == event["t"]
        assert abs(event["t"] - exact) <= tol, (method, event["t"], exact)
        assert abs(abs(r["theta"][-1]) - 0.5) <= 1e-9
    # Conditions never met: the lean falls to the positive side (it passes +0.5 at 0.81 s),
    # never crossing -0.5, and the lean rate stays far below 100 rad/s.
    r = hoop(theta0=0.1, s0=0.5 * UNIT, duration=1.0, method="dop853", stop_when=["theta=-0.5", "p=+-100"])
    assert r["events"] == [] and r["t"][-1] == 1.0


def test_bad_options_are_errors_naming_the_value():
    with pytest.raises(carvallo.ParameterError, match="invalid stop condition `lean=±0.5`"):
        hoop(stop_when=["lean=±0.5"])
    with pytest.raises(carvallo.ParameterError, match="invalid stop condition `theta=±inf`"):
        hoop(stop_when=["theta=±inf"])
    with pytest.raises(carvallo.ParameterError, match="rtol and atol need an adaptive method"):
        hoop(rtol=1e-8)
    with pytest.raises(carvallo.ParameterError, match="invalid method `vern8`"):
        hoop(method="vern8")
    with pytest.raises(carvallo.ParameterError, match="radius"):
        carvallo.simulate_hoop(0.1, 1.0, 1.0, radius=-1.0)
    with pytest.raises(carvallo.ParameterError, match="invalid theta 'nan'|theta"):
        hoop(theta0=float("nan"))
    with pytest.raises(carvallo.ParameterError, match="step"):
        hoop(step=10.0)
    with pytest.raises(carvallo.ParameterError, match="unknown rider key `mass_kg`"):
        carvallo.simulate_unicycle(dict(RIDER, mass_kg=1.0), WHEEL, R, 0.05, 1.0, 1.0)
    with pytest.raises(carvallo.ParameterError, match="wheel lacks the key `c1`"):
        carvallo.simulate_unicycle(RIDER, {k: v for k, v in WHEEL.items() if k != "c1"}, R, 0.05, 1.0, 1.0)
    with pytest.raises(carvallo.ParameterError, match="wheel.a1"):
        carvallo.simulate_unicycle(RIDER, dict(WHEEL, a1=1.0), R, 0.05, 1.0, 1.0)
