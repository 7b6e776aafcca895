"""Property tests (hypothesis) of every Python function that takes parameters, files or arrays:
arbitrary dicts, numbers, speeds, arrays of any shape and dtype, texts and paths give a result or
a `ValueError` (`carvallo.ParameterError`) whose message names what is wrong, never another
exception, a Rust panic (`pyo3_runtime.PanicException`, a `BaseException`) or a crash of the
interpreter. Integer arguments that do not fit their type (a negative count) are Python's
`OverflowError`, as for any extension function; the strategies keep counts small so that each
call is quick."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import carvallo

BENCH = carvallo.benchmark()
NAMES = list(carvallo.PARAM_NAMES)
SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])

awkward_floats = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, 1e-300, 1e300, -1.0, 5e-324]),
)
# A value of a parameter dict: mostly numbers, sometimes anything.
values = st.one_of(
    awkward_floats,
    st.integers(min_value=-(10**400), max_value=10**400),
    st.text(max_size=5),
    st.none(),
    st.lists(st.floats(), max_size=2),
    st.booleans(),
)


@st.composite
def params_dicts(draw):
    """The benchmark with a few values changed, keys dropped or added (any key type)."""
    d = dict(BENCH)
    for _ in range(draw(st.integers(0, 4))):
        action = draw(st.integers(0, 3))
        if action == 0:
            d[draw(st.sampled_from(NAMES))] = draw(values)
        elif action == 1 and d:
            d.pop(draw(st.sampled_from(sorted(d, key=str))), None)
        elif action == 2:
            d[draw(st.one_of(st.text(max_size=6), st.integers(), st.just("lam")))] = draw(values)
        else:
            k = draw(st.sampled_from(NAMES))
            d[k] = BENCH[k] * draw(st.floats(-2, 3))
    return d


anything = st.one_of(params_dicts(), st.none(), st.integers(), st.text(max_size=5), st.lists(st.floats(), max_size=3))
speeds = st.one_of(
    awkward_floats,
    st.lists(awkward_floats, max_size=4),
    hnp.arrays(hnp.floating_dtypes() | hnp.integer_dtypes(), hnp.array_shapes(min_dims=0, max_dims=3, max_side=3)),
    st.text(max_size=3),
    st.none(),
)


def check(call):
    """The call returns, or raises a ValueError with a message; anything else fails the test."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", carvallo.PhysicsWarning)
            call()
    except ValueError as e:
        assert str(e).strip(), repr(e)
    except OverflowError:
        pass  # an int that does not fit the argument's type (the strategies avoid most)
    except BaseException as e:  # noqa: B036 - a panic is a BaseException
        pytest.fail(f"{type(e).__name__}: {e}")


@SETTINGS
@given(p=anything, strict=st.booleans())
def test_functions_of_params(p, strict):
    for f in (carvallo.design, carvallo.matrices, carvallo.window, carvallo.speed_gradients,
              carvallo.geometry):
        check(lambda: f(p, strict=strict))


@SETTINGS
@given(w=st.floats(0.5, 2.0), c=st.floats(-0.2, 0.3), lam=st.floats(-1.4, 1.4), r_rear=st.floats(0.0, 0.6),
       r_front=st.floats(0.0, 0.6))
def test_geometry_puts_the_contacts_hubs_and_steer_axis_where_the_parameters_say(w, c, lam, r_rear, r_front):
    """The side view of any bicycle: contacts at 0 and w, hubs at the radii, the steer axis
    meeting the ground at w + c tilted back by λ, the front hub at the fork offset
    rF sin λ − c cos λ ahead of it (perpendicular to the axis)."""
    p = dict(BENCH, w=w, c=c, **{"lambda": lam}, rR=r_rear, rF=r_front)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", carvallo.PhysicsWarning)
        try:
            g = carvallo.geometry(p)
        except carvallo.ParameterError:
            return  # a bicycle the reader refuses (checked by test_functions_of_params)
    tol = 1e-12
    assert np.allclose(g["rear_hub"], [0, r_rear], atol=tol) and np.allclose(g["front_hub"], [w, r_front], atol=tol)
    assert np.allclose(g["front_contact"], [w, 0], atol=tol)
    assert np.allclose(g["trail"], [[w, 0], [w + c, 0]], atol=tol)
    (x0, h0), (x1, h1) = g["steer_axis"]
    assert abs(x0 - (w + c)) < tol and h0 == 0.0
    if h1 - h0 > 1e-9:
        assert abs(math.atan2(x0 - x1, h1 - h0) - lam) < 1e-9
    hub, foot = g["fork"]
    axis = np.array([-math.sin(lam), math.cos(lam)])
    normal = np.array([math.cos(lam), math.sin(lam)])  # forward, perpendicular to the axis
    assert abs(np.dot(hub - foot, axis)) < 1e-12
    assert abs(np.dot(hub - foot, normal) - (r_front * math.sin(lam) - c * math.cos(lam))) < 1e-12


@SETTINGS
@given(p=params_dicts(), v=speeds, strict=st.booleans())
def test_functions_of_params_and_speeds(p, v, strict):
    for f in (carvallo.state_matrix, carvallo.state_space, carvallo.modes, carvallo.eigenvalues):
        check(lambda: f(p, v, strict=strict))
    check(lambda: carvallo.frequency_response(p, v, v, "steer", "roll-rate", strict=strict))


@SETTINGS
@given(p=params_dicts(), sigma=st.one_of(params_dicts(), st.dictionaries(st.sampled_from(NAMES), values, max_size=3)), v=speeds,
       samples=st.integers(0, 40), q=st.tuples(awkward_floats, awkward_floats))
def test_uncertainty_functions(p, sigma, v, samples, q):
    check(lambda: carvallo.first_order(p, sigma))
    check(lambda: carvallo.monte_carlo(p, sigma, samples=samples, seed=samples))
    check(lambda: carvallo.eigenvalue_bands(p, sigma, v, samples=samples, quantiles=q))


@SETTINGS
@given(p=params_dicts(), name=st.one_of(st.sampled_from(NAMES), st.text(max_size=4)), a=awkward_floats, b=awkward_floats,
       count=st.integers(0, 50), method=st.sampled_from(["hurwitz", "eigen", "x"]))
def test_sweep(p, name, a, b, count, method):
    check(lambda: carvallo.sweep(p, name, a, b, count, method=method))


@SETTINGS
@given(p=params_dicts(), speed=awkward_floats, lean=awkward_floats, duration=st.one_of(awkward_floats, st.floats(0, 0.05)),
       step=st.one_of(awkward_floats, st.floats(1e-3, 0.05)), every=st.integers(0, 5))
def test_simulate(p, speed, lean, duration, step, every):
    # Long runs are cut short: only durations up to 0.05 s with steps from 1 ms are integrated.
    if math.isfinite(duration) and math.isfinite(step) and step > 0 and duration / step > 100:
        step = duration / 100
    check(lambda: carvallo.simulate(p, speed, lean, duration, step=step, every=every))


columns = st.one_of(
    speeds,
    hnp.arrays(hnp.complex_number_dtypes() | hnp.boolean_dtypes(), hnp.array_shapes(max_dims=1, max_side=3)),
    st.integers(1, 3).flatmap(lambda n: hnp.arrays(np.float64, (n,), elements=awkward_floats)),
    st.integers(1, 3).flatmap(lambda n: hnp.arrays(np.float64, (2 * n,), elements=st.floats(-1, 1)).map(lambda a: a[::2])),
)


@SETTINGS
@given(p=params_dicts(), v=columns, lean=columns, rates=st.one_of(st.none(), columns),
       duration=st.one_of(awkward_floats, st.floats(0, 0.05)), method=st.sampled_from(["rk4", "dop853", "vern9", "vern8"]))
def test_simulate_many(p, v, lean, rates, duration, method):
    # Short runs only: durations up to 0.05 s (at 1 ms for rk4).
    if math.isfinite(duration) and abs(duration) > 0.05:
        duration = 0.05
    check(lambda: carvallo.simulate_many(p, v, lean, duration, steer_rates=rates, method=method))


@SETTINGS
@given(theta=awkward_floats, s=awkward_floats, duration=st.one_of(awkward_floats, st.floats(0, 0.05)),
       radius=awkward_floats, method=st.sampled_from(["rk4", "vern9", "x"]),
       stop=st.lists(st.one_of(st.text(max_size=8), st.sampled_from(["theta=±0.5", "p=0", "s=+-1e300", "n=nan"])), max_size=9),
       rider=st.one_of(st.none(), st.dictionaries(st.sampled_from(["mass", "height", "a", "b", "c", "l", "x"]), values, max_size=7)))
def test_simulate_hoop_and_unicycle(theta, s, duration, radius, method, stop, rider):
    if math.isfinite(duration) and abs(duration) > 0.05:
        duration = 0.05
    check(lambda: carvallo.simulate_hoop(theta, s, duration, radius=radius, method=method, stop_when=stop))
    wheel = dict(mass=1.0, a1=0.375, b1=0.5, c1=0.125)
    check(lambda: carvallo.simulate_unicycle(rider, wheel, 0.5, theta, s, duration, method=method, stop_when=stop))


designs = st.one_of(
    hnp.arrays(hnp.floating_dtypes() | hnp.integer_dtypes() | hnp.boolean_dtypes(), hnp.array_shapes(min_dims=0, max_dims=3, max_side=30)),
    st.integers(1, 5).flatmap(lambda n: hnp.arrays(np.float64, (n, 26), elements=awkward_floats)),
    st.lists(st.lists(st.floats(), max_size=3), max_size=3),
    st.none(),
    st.text(max_size=3),
)


@SETTINGS
@given(p=params_dicts(), rider=st.one_of(st.dictionaries(st.sampled_from(["mB", "xB", "yB", "zB", "IBxx", "IBxz", "IByy", "IBzz", "x"]), values, max_size=9),
                                        st.text(max_size=5), st.none(), st.integers()), strict=st.booleans())
def test_add_rider(p, rider, strict):
    check(lambda: carvallo.add_rider(p, rider, strict=strict))
    check(lambda: carvallo.add_rider(p, rider, p, strict=strict))


@SETTINGS
@given(d=designs, validate=st.booleans(), strict=st.booleans())
def test_windows(d, validate, strict):
    check(lambda: carvallo.windows(d, validate=validate, strict=strict))


@SETTINGS
@given(text=st.text(max_size=300), strict=st.booleans())
def test_texts_and_files(tmp_path_factory, text, strict):
    check(lambda: carvallo.parse_parameters(text))
    d = tmp_path_factory.mktemp("h")
    f = d / "bike.txt"
    f.write_text(text)
    check(lambda: carvallo.load_parameters(str(f), strict=strict))
    check(lambda: carvallo.load_parameters(str(f), rider=str(f), strict=strict))
    check(lambda: carvallo.load_parameters(text or "x"))
    check(lambda: carvallo.load_parameters(str(d)))
