"""A fall is a result (issue 37, item 2) and the closed-loop window's arguments (issue 39).

A slow fall ends at the steer lock (1.4 rad) instead, at one time by every method.

`simulate` ends when the lean reaches `fall_angle` (1.2 rad by default) and returns the arrays
up to then with `status` "fell", `status_line` and `fall_t`, the same fall time by RK4 and
DOP853; a start at or beyond the fall angle raises ParameterError naming lean0 whatever the
method, for the leaning rider too (with its limits out of range and a start not finite). `closed_loop_window` names the argument of a speed or gain out of its range, and a
gain table too long for the memory limit is refused on its length."""

import math

import numpy as np
import pytest

import carvallo

B = carvallo.benchmark()


def test_a_fall_is_a_result_with_its_status():
    r = carvallo.simulate(B, 2.0, 0.05, 10.0)
    assert r["status"] == "fell"
    assert r["fall_angle"] == 1.2
    t_fall = r["fall_t"]
    assert r["status_line"] == (
        f"fell at t = {t_fall!r} s: the lean reached the fall angle ±1.2 rad"
    )
    assert r["t"][-1] == t_fall and 1.9 < t_fall < 2.0
    assert abs(abs(r["lean"][-1]) - 1.2) < 1e-12
    assert np.all(np.abs(r["lean"][:-1]) < 1.2)
    assert r["events"] == []
    # DOP853 at a tight tolerance locates the same time on its dense output.
    d = carvallo.simulate(B, 2.0, 0.05, 10.0, method="dop853", rtol=1e-12)
    assert d["status"] == "fell"
    assert abs(d["fall_t"] - t_fall) < 1e-8, (d["fall_t"], t_fall)
    # Another angle: an earlier fall.
    e = carvallo.simulate(B, 2.0, 0.05, 10.0, fall_angle=0.8)
    assert e["fall_t"] < t_fall and abs(abs(e["lean"][-1]) - 0.8) < 1e-12
    # A run that does not fall, and one a stop condition ends.
    s = carvallo.simulate(B, 5.0, 0.05, 1.0)
    assert (s["status"], s["fall_t"], s["status_line"]) == ("completed", None, "completed at t = 1 s")
    s = carvallo.simulate(B, 2.0, 0.05, 10.0, stop_when=["lean=±0.5"])
    assert s["status"] == "stopped" and s["fall_t"] is None
    assert s["status_line"].startswith("stopped at t = 1.71")


def test_a_slow_fall_ends_at_the_steer_lock():
    times = []
    for method in ("rk4", "dopri5", "dop853", "vern9"):
        r = carvallo.simulate(B, 1.0, 0.05, 20.0, method=method)
        assert r["status"] == "steer lock", r["status_line"]
        assert r["fall_t"] is None and r["steer_lock"] == 1.4
        assert r["t"][-1] == r["steer_lock_t"] and abs(abs(r["steer"][-1]) - 1.4) < 1e-12
        times.append(r["steer_lock_t"])
    assert max(times) - min(times) < 1e-7, times
    m = carvallo.simulate_many(B, [1.0], [0.05], 20.0)
    assert m["fell"][0] and m["steer_lock_t"][0] == times[0] and np.isnan(m["fall_t"][0])
    for bad in (0.0, math.pi / 2, 2.0, math.inf):
        with pytest.raises(carvallo.ParameterError, match="steer lock"):
            carvallo.simulate(B, 5.0, 0.1, 1.0, steer_lock=bad)


def test_a_driven_run_falls_too():
    r = carvallo.simulate(B, 2.0, 0.05, 10.0, impulses=[(0.5, 0.0, 0.1)])
    assert r["status"] == "fell" and r["t"][-1] == r["fall_t"]
    assert abs(abs(r["lean"][-1]) - 1.2) < 1e-12


@pytest.mark.parametrize("method", ["rk4", "dopri5", "dop853", "vern9"])
def test_unphysical_starts_are_refused_by_every_method(method):
    for lean0 in (2.0, 1.2, -1.3):
        with pytest.raises(carvallo.ParameterError, match=f"invalid lean0 {lean0}: at or beyond the fall angle"):
            carvallo.simulate(B, 5.0, lean0, 1.0, method=method)
    for bad in (0.0, -0.5, 1.6, math.nan, 10**400):
        with pytest.raises(carvallo.ParameterError, match="fall"):
            carvallo.simulate(B, 5.0, 0.1, 1.0, method=method, fall_angle=bad)


def test_the_leaning_riders_start_and_limits_out_of_range_are_refused():
    """The leaning rider's: the library's LeanRider::simulate refuses them (the module has no check of its own); the
    message names the keyword. Breaking perturbation: without the library's check, lean0 = 1.2
    is integrated past the fall angle instead of refused."""
    p = carvallo.lean_rider()
    for lean0, fall in [(1.2, 1.2), (-1.3, 1.2), (0.5, 0.5)]:
        with pytest.raises(carvallo.ParameterError,
                           match=rf"invalid lean0 {lean0}: at or beyond the fall angle ±{fall} rad \(fall_angle\)"):
            carvallo.simulate(p, 3.0, lean0, 0.1, fall_angle=fall)
    with pytest.raises(carvallo.ParameterError, match=r"invalid lean0 NaN: must be finite"):
        carvallo.simulate(p, 3.0, float("nan"), 0.1)
    with pytest.raises(carvallo.ParameterError, match=r"invalid speed inf: must be finite"):
        carvallo.simulate(p, float("inf"), 0.01, 0.1)
    with pytest.raises(carvallo.ParameterError, match=r"invalid fall_angle 2.0: must lie in \(0, pi/2\] rad"):
        carvallo.simulate(p, 3.0, 0.01, 0.1, fall_angle=2.0)
    with pytest.raises(carvallo.ParameterError, match=r"invalid steer_lock 1.5707963267948966: must lie in \(0, pi/2\) rad"):
        carvallo.simulate(p, 3.0, 0.01, 0.1, steer_lock=1.5707963267948966)
    r = carvallo.simulate(p, 3.0, 0.4999, 0.5, fall_angle=0.5)
    assert r["status"] == "fell", r["status_line"]


def test_closed_loop_window_names_the_bad_argument():
    k = {"k_roll_roll": 1.0}
    cases = [
        (dict(vmax=10**400), "invalid vmax"),
        (dict(vmin=math.nan), "invalid vmin NaN: must be finite"),
        (dict(vmax=math.inf), "invalid vmax inf: must be finite"),
        (dict(vmax=1e7), r"invalid vmax 10000000.0: must lie within \[0, 1e6\] m/s"),
        (dict(vmin=-1.0), r"invalid vmin -1.0: must lie within \[0, 1e6\] m/s"),
    ]
    for kwargs, message in cases:
        with pytest.raises(carvallo.ParameterError, match=message):
            carvallo.closed_loop_window(B, k, **kwargs)
    for gains, message in [
        ({"k_roll_roll": math.nan}, "gain k_roll_roll = NaN is not finite"),
        ({"k_roll_roll": 1e13}, r"gain k_roll_roll = 10000000000000.0: must lie within \[-1e12, 1e12\]"),
        (np.full((2, 4), -1e300), r"gain k_roll_roll = -1e300: must lie within"),
        ({"speed": [0.0, 1.0], "k_steer_roll": [1.0, 1e13]}, "gain k_steer_roll = 10000000000000.0 in row 2"),
        ({"speed": [0.0, 1e300], "k_steer_roll": [1.0, 1.0]}, "gain table: speed 1e300 in row 2"),
    ]:
        with pytest.raises(carvallo.ParameterError, match=message):
            carvallo.closed_loop_window(B, gains)
    # A table too long for the limit is refused on its length (no value read).
    n = 2 * 10**7
    with pytest.raises(carvallo.ParameterError, match=f"a gain table of {n} speeds needs"):
        carvallo.closed_loop_window(B, {"speed": np.arange(n), "k_steer_roll": np.ones(n)})
    # Within the ranges, the window of the balance assist.
    w = carvallo.closed_loop_window(B, {"k_steer_roll_rate": -17.621890605880708}, vmax=1e6)
    assert abs(w["lowest_stable_speed"] - 2.0) < 1e-9
