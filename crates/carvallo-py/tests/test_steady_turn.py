"""`carvallo.steady_turn`: the steady turns of the nonlinear Carvallo–Whipple bicycle (and of the
leaning rider: upright, `carvallo.eigenvalues` of its linearisation), checked
by routes that do not use it: numpy's solution of the linear static equations
(g K0 + v^2 K2)[phi, delta] = [0, T] from `carvallo.matrices` (the linearised model, another
derivation) as the lean goes to zero, with the error falling as lean^2; `carvallo.eigenvalues`
of upright running; `carvallo.window`'s stable speeds for small leans; the friction a level
turn demands, v^2 / (g R); and bad input as a ParameterError naming the value."""

import math

import numpy as np
import pytest

import carvallo

B = carvallo.benchmark()


def forward(params, speed, lean):
    turns = [t for t in carvallo.steady_turn(params, speed, lean=lean) if abs(t["steer"]) < 0.5]
    assert len(turns) == 1, turns
    return turns[0]


def linear_static(params, speed):
    """Steer and torque per radian of lean from the linear model, by numpy."""
    m = carvallo.matrices(params)
    k = params["g"] * np.asarray(m["K0"]) + speed**2 * np.asarray(m["K2"])
    # Row 1: no roll torque, the lean given; row 2: the steer torque.
    ratio = -k[0, 0] / k[0, 1]
    return ratio, k[1, 0] + k[1, 1] * ratio


@pytest.mark.parametrize("speed", [3.0, 5.0, 8.0])
def test_small_lean_is_the_linear_static_solution_at_order_two(speed):
    ratio, torque = linear_static(B, speed)
    errors = []
    for lean in (0.04, 0.02, 0.01):
        t = forward(B, speed, lean)
        errors.append((abs(t["steer"] / lean - ratio), abs(t["steer_torque"] / lean - torque)))
    for (a, b), (c, d) in zip(errors, errors[1:]):
        assert abs(a / c - 4.0) <= 0.1 and abs(b / d - 4.0) <= 0.1, errors
    assert errors[-1][0] <= 2e-3 * abs(ratio) and errors[-1][1] <= 2e-3 * abs(torque)


@pytest.mark.parametrize("speed", [2.0, 5.0, 7.0])
def test_upright_running_has_the_linear_eigenvalues(speed):
    straight = carvallo.steady_turn(B, speed, lean=0.0, steer=0.0)
    assert len(straight) == 1 and straight[0]["steer"] == 0.0
    assert math.isinf(straight[0]["radius"])
    got = sorted(straight[0]["eigenvalues"], key=lambda z: (z.real, z.imag))
    want = sorted(carvallo.eigenvalues(B, [speed])[0], key=lambda z: (z.real, z.imag))
    for g, w in zip(got, want):
        assert abs(g - w) <= 1e-9 * max(1.0, abs(w)), (got, want)


def test_small_lean_turns_are_stable_in_the_upright_window():
    lo, hi = carvallo.window(B)["stable"][0]
    for speed in (lo - 0.1, lo + 0.1, hi - 0.1, hi + 0.1):
        assert forward(B, speed, 0.01)["stable"] == (lo < speed < hi), speed


def test_a_level_turn_demands_the_friction_of_its_centripetal_acceleration():
    # Over the whole bicycle: the lateral forces carry m v_G^2 / R_G; at the rear contact the
    # friction is near v^2 / (g R) (the mass centre's circle is a little larger).
    for speed, lean in [(5.0, 0.05), (10.0, 0.3), (4.0, -0.2)]:
        t = forward(B, speed, lean)
        rear, front = t["friction"]
        level = speed**2 / (B["g"] * abs(t["radius"]))
        assert abs(rear / level - 1.0) < 0.05 and abs(front / level - 1.0) < 0.05, t
        assert t["on_ground"] and sum(t["normal_force"]) > 0
        assert t["momentum_balance"] <= 1e-9 * 1000.0
        assert abs(t["rear_wheel_row"]) <= 1e-9


def test_steer_keeps_the_nearest_and_a_lean_without_turns_is_empty():
    every = carvallo.steady_turn(B, 5.0, lean=0.05)
    assert [t["steer"] for t in every] == sorted(t["steer"] for t in every)
    one = carvallo.steady_turn(B, 5.0, lean=0.05, steer=0.1)
    assert len(one) == 1 and one[0] == every[2]
    assert carvallo.steady_turn(B, 5.0, lean=1.55) == []


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(speed=0.0, lean=0.1), "invalid speed 0.0: must be positive"),
        (dict(speed=-2.0, lean=0.1), "invalid speed -2.0: must be positive"),
        (dict(speed=5.0, lean=float("nan")), "invalid lean NaN: must be finite"),
        (dict(speed=5.0, lean=1.6), "invalid lean 1.6: must lie strictly"),
        (dict(speed=5.0, lean="x"), "invalid lean 'x': not a number"),
        (dict(speed=5.0, lean=0.1, steer=float("inf")), "invalid steer inf: must be finite"),
    ],
)
def test_bad_input_names_the_value(kwargs, message):
    with pytest.raises(carvallo.ParameterError, match="^" + message.replace(".", r"\.")):
        carvallo.steady_turn(B, **kwargs)


def test_the_leaning_rider_upright_has_its_eigenvalues_and_a_turn_its_torso_lean():
    rider = carvallo.lean_rider()
    straight = carvallo.steady_turn(rider, 5.0, lean=0.0, steer=0.0)
    assert len(straight) == 1 and straight[0]["torso_lean"] == 0.0
    got = sorted(straight[0]["eigenvalues"], key=lambda z: (z.real, z.imag))
    want = sorted(carvallo.eigenvalues(rider, [5.0])[0], key=lambda z: (z.real, z.imag))
    assert len(got) == 6
    for g, w in zip(got, want):
        assert abs(g - w) <= 1e-9 * max(1.0, abs(w)), (got, want)
    turn = carvallo.steady_turn(rider, 5.0, lean=0.05, steer=0.0)[0]
    # The passive torso (k9 = 0) leans a little into the turn's field; its row vanishes.
    assert abs(turn["torso_lean"]) < 1e-3 and abs(turn["lean_row"]) <= 1e-9
    assert not turn["stable"] and "normal_force" not in turn
