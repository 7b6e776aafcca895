"""The Python package `carvallo` against the Rust command line (equal results), against numpy
(eigenvalues of the same state matrix) and on bad input (exceptions naming key and value)."""

import math
import warnings

import numpy as np
import pytest

import carvallo


def test_benchmark_names_and_values():
    p = carvallo.benchmark()
    assert list(p) == carvallo.PARAM_NAMES
    assert len(p) == 26
    assert p["lambda"] == math.pi / 10
    assert p["mB"] == 85.0



def test_design_names_every_parameter():
    d = carvallo.design(carvallo.benchmark())
    assert (d["wheelbase"], d["trail"], d["steer_axis_tilt"]) == (1.02, 0.08, math.pi / 10)
    assert d["rear_frame"]["mass"] == 85.0
    assert d["front_wheel"] == {"radius": 0.35, "mass": 3.0, "ixx": 0.1405, "iyy": 0.28}
    assert len(d["rear_frame"]) == len(d["front_frame"]) == 7
    bad = dict(carvallo.benchmark(), mB=-85.0)
    with pytest.raises(carvallo.ParameterError, match="invalid mB -85.0: must be positive"):
        carvallo.design(bad)

def test_window_equals_the_cli(cli):
    w = carvallo.window(carvallo.benchmark())
    c = cli("window", "--model", "benchmark", "--json")
    assert w["weave_speed"] == c["weave_speed"]
    assert w["capsize_speed"] == c["capsize_speed"]
    assert [list(s) for s in w["stable"]] == c["stable"]


def test_window_of_a_parameter_file_is_the_published_window(cli, fixture_file):
    """The benchmark's parameter file (its values are Table 1 of Meijaard et al. 2007) read by
    `load_parameters`: the window must be the published one (Meijaard et al. 2007, section 5:
    weave 4.29238253634111 m/s, capsize 6.02426201538837 m/s). Budget: the published numbers
    are rounded to 15 significant digits (5e-15 m/s) and the edges bisected to a few ulps, so
    2e-14 m/s; a parameter misread by one part in 1e-12 moves the edges by about 1e-12 m/s."""
    params, sigma = carvallo.load_parameters(str(fixture_file))
    assert params == carvallo.benchmark()
    w = carvallo.window(params)
    assert abs(w["weave_speed"] - 4.29238253634111) <= 2e-14, w
    assert abs(w["capsize_speed"] - 6.02426201538837) <= 2e-14, w
    # The command line reads the same file to the same window (parity, not the evidence).
    c = cli("window", "--model", str(fixture_file), "--json")
    assert (w["weave_speed"], w["capsize_speed"]) == (c["weave_speed"], c["capsize_speed"])


@pytest.mark.parametrize("speed", ["0", "5", "4.292382536341107", "10"])
def test_eigenvalues_equal_the_cli(cli, speed):
    ev = carvallo.eigenvalues(carvallo.benchmark(), [float(speed)])
    c = cli("eig", "--model", "benchmark", "--speed", speed, "--json")
    assert c["speed"] == float(speed)
    assert ev.shape == (1, 4)
    assert [complex(e["re"], e["im"]) for e in c["eigenvalues"]] == list(ev[0])


def test_numpy_eigenvalues_of_the_state_matrix_agree():
    p = carvallo.benchmark()
    speeds = np.linspace(0.0, 10.0, 41)
    a = carvallo.state_matrix(p, speeds)
    assert a.shape == (41, 4, 4)
    ours = carvallo.eigenvalues(p, speeds)
    for k, v in enumerate(speeds):
        np.testing.assert_array_equal(a[k], carvallo.state_matrix(p, float(v)))
        theirs = np.linalg.eigvals(a[k])
        # Match each of ours to the nearest of numpy's (both sets of four).
        for e in ours[k]:
            d = np.min(np.abs(theirs - e))
            assert d <= 1e-12 * max(1.0, abs(e)), (v, e, theirs)
    # At 5 m/s the published benchmark values (anchors file) to 1e-12.
    ev5 = carvallo.eigenvalues(p, 5.0)[0]
    want = [-14.078389692798247, -0.77534188219584193, -0.77534188219584193, -0.32286642900408708]
    np.testing.assert_allclose(ev5.real, want, rtol=1e-12)


def test_matrices_are_the_benchmarks():
    m = carvallo.matrices(carvallo.benchmark())
    np.testing.assert_allclose(m["M"], [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]], rtol=1e-13)
    np.testing.assert_allclose(m["K2"], [[0.0, 76.59734589573222], [0.0, 2.65431523794604]], rtol=1e-13, atol=1e-14)


def test_batched_windows_equal_single_windows():
    p = carvallo.benchmark()
    base = np.array([p[n] for n in carvallo.PARAM_NAMES])
    designs = np.tile(base, (50, 1))
    designs[:, 1] = np.linspace(0.0, 0.2, 50)  # the trail c
    out = carvallo.windows(designs)
    assert out.shape == (50, 2)
    for row, (weave, capsize) in zip(designs, out):
        w = carvallo.window(dict(zip(carvallo.PARAM_NAMES, row)))
        assert weave == w["weave_speed"]
        assert capsize == w["capsize_speed"]


def test_sweep_equals_the_cli(cli):
    s = carvallo.sweep(carvallo.benchmark(), "c", 0.0, 0.2, 2001)
    c = cli("sweep", "--model", "benchmark", "--vary", "c=0.0:0.2:2001", "--method", "hurwitz", "--json")
    for key in ["count", "stable", "with_weave", "with_capsize", "failed", "from", "to"]:
        assert s[key] == c[key], key
    assert list(s["weave_speed_range"]) == c["weave_speed_range"]
    assert list(s["capsize_speed_range"]) == c["capsize_speed_range"]


def test_simulate_equals_the_cli(cli):
    s = carvallo.simulate(carvallo.benchmark(), 4.6, 0.05, 1.0)
    c = cli("simulate", "--model", "benchmark", "--speed", "4.6", "--lean0", "0.05", "--duration", "1", "--json")
    for key in ["t", "lean", "steer", "pitch", "speed_rear", "rear_x", "rear_y", "front_x", "front_y", "energy"]:
        assert isinstance(s[key], np.ndarray)
        assert s[key].tolist() == c[key], key
    assert s["energy_drift"] == c["energy_drift"]
    assert s["energy_drift"] < 1e-9


def test_adaptive_simulate_equals_the_cli(cli):
    kw = dict(method="dop853", rtol=1e-10, stop_when=["lean=±0.5"])
    s = carvallo.simulate(carvallo.benchmark(), 2.0, 0.05, 3.0, **kw)
    c = cli("simulate", "--model", "benchmark", "--speed", "2", "--lean0", "0.05", "--duration", "3",
            "--method", "dop853", "--rtol", "1e-10", "--stop-when", "lean=±0.5", "--json")
    for key in ["t", "lean", "steer", "pitch", "energy"]:
        assert s[key].tolist() == c[key], key
    for key in ["method", "rtol", "atol", "rhs_evaluations", "steps", "rejected_steps", "events", "energy_drift"]:
        assert s[key] == c[key], key
    assert s["events"][0]["when"] == "lean=±0.5" and s["t"][-1] == s["events"][0]["t"]
    assert abs(abs(s["lean"][-1]) - 0.5) < 1e-9
    r = carvallo.simulate(carvallo.benchmark(), 4.6, 0.05, 1.0)
    assert (r["method"], r["rtol"], r["steps"], r["events"]) == ("rk4", None, 1000, [])


def test_simulate_many_equals_single_runs():
    p = carvallo.benchmark()
    speeds, leans = np.array([4.6, 2.0, 3.0, 1.0]), np.array([0.05, 0.05, 0.1, 0.2])
    rates = np.array([0.0, 0.0, 0.3, 0.0])
    kw = dict(method="dop853", rtol=1e-9, stop_when=["lean=±0.5"])
    m = carvallo.simulate_many(p, speeds, leans, 3.0, steer_rates=rates, **kw)
    assert m["ok"].all() and m["errors"] == [None] * 4
    for k, (v, lean0) in enumerate(zip(speeds, leans)):
        if rates[k] != 0.0:
            continue  # simulate starts with a zero steer rate
        s = carvallo.simulate(p, v, lean0, 3.0, every=1, **kw)
        assert m["t_end"][k] == s["t"][-1] and m["lean"][k] == s["lean"][-1], k
        assert m["steer"][k] == s["steer"][-1] and m["x"][k] == s["rear_x"][-1], k
        assert m["rhs_evaluations"][k] == s["rhs_evaluations"], k
        assert bool(m["fell"][k]) == bool(s["events"]), k
        if s["events"]:
            assert m["event_t"][k] == s["events"][0]["t"] and m["stopped_by"][k] == 0
        else:
            assert math.isnan(m["event_t"][k]) and m["stopped_by"][k] == -1
    assert not m["fell"][0] and m["fell"][1]
    # Without a stop condition the slow bicycle falls: a run that ends at the fall angle, its
    # time that of the single run; a start beyond the fall angle is a failed run.
    m = carvallo.simulate_many(p, np.array([2.0, 3.0]), np.array([0.05, 2.0]), 5.0)
    s = carvallo.simulate(p, 2.0, 0.05, 5.0)
    assert m["ok"][0] and m["fell"][0] and m["errors"][0] is None
    assert m["fall_t"][0] == s["fall_t"] and math.isnan(m["event_t"][0])
    assert not m["ok"][1] and not m["fell"][1] and "at or beyond the fall angle" in m["errors"][1]
    with pytest.raises(carvallo.ParameterError, match="lean0s has 1 values for 2 speeds"):
        carvallo.simulate_many(p, np.array([1.0, 2.0]), np.array([0.0]), 1.0)
    with pytest.raises(carvallo.ParameterError, match="invalid method `euler`"):
        carvallo.simulate(p, 4.0, 0.0, 1.0, method="euler")
    with pytest.raises(carvallo.ParameterError, match="invalid stop condition `speed=1`"):
        carvallo.simulate(p, 4.0, 0.0, 1.0, stop_when=["speed=1"])
    with pytest.raises(carvallo.ParameterError, match="rtol and atol need an adaptive method"):
        carvallo.simulate(p, 4.0, 0.0, 1.0, rtol=1e-8)


def test_report_equals_the_cli(cli):
    assert carvallo.report() == cli("report", "--json")


def test_fixture_file_reads_values_and_uncertainties(fixture_file):
    params, sigma = carvallo.load_parameters(str(fixture_file))
    assert params == pytest.approx(carvallo.benchmark(), rel=1e-15)
    assert sigma["c"] == 0.0008
    assert sigma["g"] == 0.01
    assert sigma["lambda"] == 0.005


def test_first_order_agrees_with_monte_carlo(fixture_file):
    params, sigma = carvallo.load_parameters(str(fixture_file))
    f = carvallo.first_order(params, sigma)
    mc = carvallo.monte_carlo(params, sigma, samples=20000, seed=7)
    for name in ["weave", "capsize"]:
        x = mc[name]
        assert np.isfinite(x).all()
        # Stated tolerance (as in the Rust test): std to 3 %, mean to 0.25 std.
        assert abs(np.std(x, ddof=1) - f[f"{name}_std"]) <= 0.03 * f[f"{name}_std"]
        assert abs(np.mean(x) - f[f"{name}_speed"]) <= 0.25 * f[f"{name}_std"]


def test_speed_gradients_match_finite_differences():
    p = carvallo.benchmark()
    g = carvallo.speed_gradients(p)
    for name in ["c", "mB", "w"]:
        h = 1e-6 * abs(p[name])
        up = carvallo.window({**p, name: p[name] + h})
        down = carvallo.window({**p, name: p[name] - h})
        fd = (up["weave_speed"] - down["weave_speed"]) / (2 * h)
        assert g["d_weave"][name] == pytest.approx(fd, rel=1e-5, abs=1e-9)


def test_eigenvalue_bands_bracket_the_nominal_curve(fixture_file):
    params, sigma = carvallo.load_parameters(str(fixture_file))
    speeds = np.linspace(0, 10, 21)
    b = carvallo.eigenvalue_bands(params, sigma, speeds, samples=400)
    assert b["lower"].shape == b["upper"].shape == b["nominal"].shape == (21, 4)
    assert (b["lower"] <= b["nominal"] + 1e-9).all() and (b["nominal"] <= b["upper"] + 1e-9).all()
    np.testing.assert_allclose(np.sort(carvallo.eigenvalues(params, speeds).real, axis=1), b["nominal"], rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize(
    "change, message",
    [
        ({"mB": -85.0}, "invalid mB -85.0: must be positive"),
        ({"mB": "heavy"}, "parameter mB = 'heavy' is not a number"),
        ({"mass": 3.0}, "invalid mass 3.0: unknown parameter"),
        ({"lambda": 2.0}, "invalid lambda 2.0: must lie strictly between -pi/2 and pi/2"),
    ],
)
def test_bad_parameters_raise_naming_key_and_value(change, message):
    with pytest.raises(carvallo.ParameterError, match="^" + message.replace("(", r"\(")):
        carvallo.window({**carvallo.benchmark(), **change})


def test_other_bad_input_raises(tmp_path):
    p = carvallo.benchmark()
    missing = dict(p)
    del missing["c"]
    with pytest.raises(ValueError, match="missing parameter c"):
        carvallo.eigenvalues(missing, [1.0])
    with pytest.raises(carvallo.ParameterError, match="invalid speed NaN: must be finite"):
        carvallo.eigenvalues(p, [1.0, float("nan")])
    with pytest.raises(carvallo.ParameterError, match=r"shape \(n, 26\)"):
        carvallo.windows(np.zeros((3, 25)))
    bad = np.tile([p[n] for n in carvallo.PARAM_NAMES], (4, 1))
    bad[2, carvallo.PARAM_NAMES.index("mF")] = -1.0
    with pytest.raises(carvallo.ParameterError, match="design 2: invalid mF -1.0: must not be negative"):
        carvallo.windows(bad)
    with pytest.raises(carvallo.ParameterError, match="invalid uncertainty c = -1.0: must be a finite standard deviation"):
        carvallo.first_order(p, {"c": -1.0})
    with pytest.raises(carvallo.ParameterError, match="unknown parameter q"):
        carvallo.sweep(p, "q", 0, 1, 10)
    with pytest.raises(carvallo.ParameterError, match="invalid method `fast`"):
        carvallo.sweep(p, "c", 0, 1, 10, method="fast")
    with pytest.raises(carvallo.ParameterError, match="invalid duration -1.0: must be positive"):
        carvallo.simulate(p, 4.0, 0.0, -1.0)
    f = tmp_path / "bike.txt"
    f.write_text("w = 1.02+/-0.01\nc = 0.08+/-oops\n")
    with pytest.raises(carvallo.ParameterError, match=r"line 2: c: uncertainty `oops` is not a number \(`c = 0.08\+/-oops`\)"):
        carvallo.load_parameters(str(f))
    with pytest.raises(carvallo.ParameterError, match="cannot read parameter file"):
        carvallo.load_parameters(str(tmp_path / "none.txt"))


def test_the_extension_does_not_contain_symbolica():
    import importlib.metadata

    requires = importlib.metadata.requires("carvallo") or []
    assert all(r.split()[0].startswith("numpy") for r in requires), requires
    data = open(carvallo.__file__, "rb").read()
    assert b"symbolica" not in data.lower()
    assert b"carvallo" in data


def test_bicycleparameters_files_riders_and_strict(cli, root):
    data = root / "data" / "bicycleparameters"
    bike = str(data / "bicycles" / "Browser" / "Parameters" / "BrowserBenchmark.txt")
    rider = str(data / "riders" / "Jason" / "Parameters" / "JasonBrowserBenchmark.txt")
    # A measured frame breaking a triangle inequality: a PhysicsWarning naming it.
    with pytest.warns(carvallo.PhysicsWarning, match=r"IByy 1\.3163960125 breaks a triangle"):
        params, sigma = carvallo.load_parameters(bike)
    assert params["IByy"] == 1.3163960125
    with pytest.raises(carvallo.ParameterError, match=r"invalid IByy 1\.3163960125: exceeds"):
        carvallo.load_parameters(bike, strict=True)
    # With the rider the frame keeps the inequality (no warning): BicycleParameters'
    # Bicycle.add_rider (1.5.2) gives mB 81.86 +/- 2.0001, IBxx 11.35822782891604 +/-
    # 0.0284751583305407, and the CLI the same window. `strict` reads the bicycle's file first.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        params, sigma = carvallo.load_parameters(bike, rider=rider)
    assert params["mB"] == pytest.approx(81.86, rel=1e-13)
    assert params["IBxx"] == pytest.approx(11.35822782891604, rel=1e-13)
    assert sigma["IBxx"] == pytest.approx(0.0284751583305407, rel=1e-7)
    w = carvallo.window(params)
    c = cli("window", "--model", bike, "--rider", rider, "--json")
    assert (w["weave_speed"], w["capsize_speed"]) == (c["weave_speed"], c["capsize_speed"])
    with pytest.raises(carvallo.ParameterError, match=r"unknown rider parameter `IFxx`"):
        carvallo.load_parameters(bike, rider=bike)
    with pytest.raises(carvallo.ParameterError, match=r"cannot read rider file `/nonexistent`"):
        carvallo.load_parameters(bike, rider="/nonexistent")


def test_state_space_matches_the_cli_and_the_published_matrices(cli):
    p = carvallo.benchmark()
    a, b = carvallo.state_space(p, [0.0, 5.0, 7.5])
    assert a.shape == (3, 4, 4) and b.shape == (3, 4, 2)
    c = cli("statespace", "--model", "benchmark", "--speed", "0,5,7.5", "--json")
    for k in range(3):
        np.testing.assert_array_equal(a[k], np.array(c[k]["A"]))
        np.testing.assert_array_equal(b[k], np.array(c[k]["B"]))
        np.testing.assert_array_equal(a[k], carvallo.state_matrix(p, c[k]["speed"]))
    # B = [0; M^-1] with the matrices of Meijaard et al. (2007), eq. (5.3)-(5.6), as printed.
    m = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
    c1 = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
    k0 = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
    k2 = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])
    minv = np.linalg.inv(m)
    v = 5.0
    np.testing.assert_allclose(b[1][2:], minv, rtol=1e-12)
    assert np.all(b[1][:2] == 0.0)
    lower = np.hstack([-minv @ (9.81 * k0 + v * v * k2), -v * minv @ c1])
    np.testing.assert_allclose(a[1][2:], lower, rtol=0, atol=1e-12 * np.abs(lower).max())
    with pytest.raises(carvallo.ParameterError, match="invalid speed NaN"):
        carvallo.state_space(p, [1.0, float("nan")])


def test_frequency_response_is_the_state_space_resolvent_and_the_cli(cli):
    p = carvallo.benchmark()
    speeds, omegas = [2.0, 5.0], np.logspace(-1, 2, 31)
    a, b = carvallo.state_space(p, speeds)
    names = ["roll", "steer", "roll-rate", "steer-rate"]
    for j, inp in enumerate(["roll", "steer"]):
        for i, out in enumerate(names):
            fr = carvallo.frequency_response(p, speeds, omegas, inp, out)
            g = fr["response"]
            assert g.shape == (2, 31) and g.dtype == np.complex128
            for k in range(2):
                # C (iωI - A)^-1 B by numpy's solver: an independent route.
                want = np.array(
                    [np.linalg.solve(1j * w * np.eye(4) - a[k], b[k])[i, j] for w in omegas]
                )
                np.testing.assert_allclose(g[k], want, rtol=1e-11)
            np.testing.assert_allclose(fr["magnitude_db"], 20 * np.log10(np.abs(g)), rtol=1e-13)
            # The phase is G's argument modulo 360° on the branch continuous in ω from
            # (-180°, 180°] at ω -> 0+ (issue 37), not unwrapped from the grid's first point.
            d = (fr["phase_deg"] - np.degrees(np.angle(g)) + 180.0) % 360.0 - 180.0
            assert np.abs(d).max() < 1e-9
            assert (np.abs(np.diff(fr["phase_deg"], axis=1)) < 180.0).all()
    c = cli("bode", "--model", "benchmark", "--speed", "2,5", "--input", "steer", "--output",
            "roll", "--omega", ",".join(repr(float(w)) for w in omegas), "--json")
    fr = carvallo.frequency_response(p, speeds, omegas, "steer", "roll")
    got = [complex(q["re"], q["im"]) for q in c["points"]]
    assert got == list(fr["response"].reshape(-1))
    with pytest.raises(carvallo.ParameterError, match='unknown signal "yaw"'):
        carvallo.frequency_response(p, 5.0, 1.0, "steer", "yaw")
    with pytest.raises(carvallo.ParameterError, match="invalid omega -1.0: must be finite and not negative"):
        carvallo.frequency_response(p, 5.0, [-1.0], "steer", "roll")


def test_modes_are_eigenvectors_with_the_labels_of_the_cli(cli):
    p = carvallo.benchmark()
    speeds = [0.5, 5.0]
    labels, ev, vec = carvallo.modes(p, speeds)
    assert labels == ["weave", "weave", "capsize", "caster"]
    a, _ = carvallo.state_space(p, speeds)
    for k in range(2):
        # NumPy's convention (numpy.linalg.eig): the columns are the vectors, A V = V diag(λ).
        r = a[k] @ vec[k] - vec[k] @ np.diag(ev[k])
        assert np.abs(r).max() < 1e-12 * max(1.0, np.abs(a[k]).max())
        for i in range(4):
            assert np.linalg.norm(vec[k, :, i]) == pytest.approx(1.0, rel=1e-12)
            # The rows are not vectors (the layout before issue 37 was the transpose).
            assert np.abs(a[k] @ vec[k, i] - ev[k, i] * vec[k, i]).max() > 1e-3
    c = cli("eig", "--model", "benchmark", "--speed", "5", "--json")
    assert [m["label"] for m in c["modes"]] == labels
    assert [complex(m["re"], m["im"]) for m in c["modes"]] == list(ev[1])
    # Weave complex above 0.684 m/s, two positive real roots below (Meijaard et al. 2007).
    assert np.all(ev[1, :2].imag != 0) and np.all(ev[0, :2].imag == 0) and np.all(ev[0, :2].real > 0)
    with pytest.raises(carvallo.ParameterError, match="cannot be followed"):
        carvallo.modes(p, [1e308])


def _browser(root):
    path = root / "data" / "bicycleparameters" / "bicycles" / "Browser" / "Parameters" / "BrowserBenchmark.txt"
    with pytest.warns(carvallo.PhysicsWarning):
        return carvallo.load_parameters(str(path))


def test_every_function_taking_params_accepts_a_broken_triangle_inequality(cli, root):
    """Browser's measured frame breaks IByy <= IBxx + IBzz by 2.331 %: every function computes
    it with a PhysicsWarning naming the parameter (as `--model` does on the command line), and
    refuses it with strict=True (as `--strict`)."""
    params, sigma = _browser(root)
    path = str(root / "data" / "bicycleparameters" / "bicycles" / "Browser" / "Parameters" / "BrowserBenchmark.txt")
    speeds = [2.0, 5.0]
    row = np.array([[params[n] for n in carvallo.PARAM_NAMES]])
    calls = {
        "design": lambda **k: carvallo.design(params, **k),
        "matrices": lambda **k: carvallo.matrices(params, **k),
        "state_matrix": lambda **k: carvallo.state_matrix(params, 5.0, **k),
        "state_space": lambda **k: carvallo.state_space(params, speeds, **k),
        "modes": lambda **k: carvallo.modes(params, speeds, **k),
        "frequency_response": lambda **k: carvallo.frequency_response(params, speeds, [1.0, 10.0], "steer", "roll", **k),
        "closed_loop_window": lambda **k: carvallo.closed_loop_window(params, {"k_steer_roll_rate": -10.0}, **k),
        "closed_loop_eigenvalues": lambda **k: carvallo.closed_loop_eigenvalues(params, np.zeros((2, 4)), speeds, **k),
        "eigenvalues": lambda **k: carvallo.eigenvalues(params, speeds, **k),
        "window": lambda **k: carvallo.window(params, **k),
        "windows": lambda **k: carvallo.windows(row, **k),
        "sweep": lambda **k: carvallo.sweep(params, "c", 0.05, 0.1, 9, **k),
        "simulate": lambda **k: carvallo.simulate(params, 5.0, 0.01, 0.1, **k),
        "speed_gradients": lambda **k: carvallo.speed_gradients(params, **k),
        "first_order": lambda **k: carvallo.first_order(params, sigma, **k),
        "monte_carlo": lambda **k: carvallo.monte_carlo(params, sigma, samples=200, **k),
        "eigenvalue_bands": lambda **k: carvallo.eigenvalue_bands(params, sigma, speeds, samples=50, **k),
    }
    results = {}
    for name, call in calls.items():
        pattern = r"IByy 1\.3163960125 breaks a triangle inequality of the moments of inertia by 2\.331 %"
        with pytest.warns(carvallo.PhysicsWarning, match=pattern):
            results[name] = call()
        with pytest.raises(carvallo.ParameterError, match=r"invalid IByy 1\.3163960125: exceeds IBxx \+ IBzz"):
            call(strict=True)
    # The same numbers as the command line reading the file.
    c = cli("window", "--model", path, "--json")
    w = results["window"]
    assert (w["weave_speed"], w["capsize_speed"]) == (c["weave_speed"], c["capsize_speed"])
    np.testing.assert_array_equal(results["windows"][0], [c["weave_speed"], c["capsize_speed"]])
    e = cli("eig", "--model", path, "--speed", "5", "--json")["eigenvalues"]
    np.testing.assert_array_equal(results["eigenvalues"][1], [x["re"] + 1j * x["im"] for x in e])
    assert results["speed_gradients"]["weave_speed"] == w["weave_speed"]
    assert results["sweep"]["count"] == 9 and results["sweep"]["with_weave"] == 9


def test_random_sweeps_around_a_broken_inequality_keep_draws(root):
    """The sampling rule: around a nominal that breaks a triangle inequality, a draw is kept when
    it breaks none by more than the nominal does. Monte Carlo around Browser counts as invalid only
    the samples beyond Browser's own 2.331 %; with its stated uncertainties (IByy +/- 0.0040,
    0.30 % of it, and IBxx, IBzz +/- 0.0025, 0.0033) about half of them lie beyond, the normal
    draws scattering around the nominal (4953 of 10 000 measured with the default seed)."""
    params, sigma = _browser(root)
    with pytest.warns(carvallo.PhysicsWarning):
        mc = carvallo.monte_carlo(params, sigma, samples=2000)
    assert 0.3 * 2000 < mc["invalid"] < 0.7 * 2000, mc["invalid"]
    assert np.isfinite(mc["weave"]).sum() > 1900


def test_add_rider_equals_the_file_route(root):
    """`add_rider(params, rider, sigma)` gives what `load_parameters(path, rider=...)` gives, from
    a rider file or from a dict of its values (then without the rider's uncertainties)."""
    data = root / "data" / "bicycleparameters"
    bike = str(data / "bicycles" / "Rigid" / "Parameters" / "RigidBenchmark.txt")
    rider = data / "riders" / "Jason" / "Parameters" / "JasonRigidBenchmark.txt"
    params, sigma = carvallo.load_parameters(bike)
    want = carvallo.load_parameters(bike, rider=str(rider))
    assert carvallo.add_rider(params, str(rider), sigma) == want
    assert carvallo.add_rider(params, rider, sigma) == want  # a pathlib.Path
    values = {}
    for line in rider.read_text().splitlines():
        if "=" in line:
            k, v = line.split("=")
            values[k.strip()] = float(v.split("+/-")[0])
    p, s = carvallo.add_rider(params, values)
    assert p == want[0]
    assert s["IBxx"] == 0.0 and s["c"] == 0.0
    with pytest.raises(carvallo.ParameterError, match=r"^missing rider parameter IBzz"):
        carvallo.add_rider(params, {k: v for k, v in values.items() if k != "IBzz"})
    with pytest.raises(carvallo.ParameterError, match=r"^invalid rider mB -1\.0: must be positive"):
        carvallo.add_rider(params, {**values, "mB": -1.0})
    with pytest.raises(carvallo.ParameterError, match=r"^unknown rider parameter mR = 2\.0"):
        carvallo.add_rider(params, {**values, "mR": 2.0})
    with pytest.raises(carvallo.ParameterError, match=r"^invalid rider: invalid yB 0\.5"):
        carvallo.add_rider(params, {**values, "yB": 0.5})
    with pytest.raises(carvallo.ParameterError, match=r"^cannot read rider file `/nonexistent`"):
        carvallo.add_rider(params, "/nonexistent")


def test_closed_loop_window_and_eigenvalues_agree_with_numpy_and_the_cli(cli):
    p = carvallo.benchmark()
    # The balance-assist law T_delta = c * roll rate (c = 10 N m s/rad): k_steer_roll_rate = -c.
    k = np.zeros((2, 4))
    k[1, 2] = -10.0
    w = carvallo.closed_loop_window(p, k)
    assert w == carvallo.closed_loop_window(p, {"k_steer_roll_rate": -10.0})
    c = cli("window", "--model", "benchmark", "--gain", "k_steer_roll_rate=-10", "--json")
    assert [tuple(s) for s in c["stable"]] == w["stable"]
    assert c["lowest_stable_speed"] == w["lowest_stable_speed"] and w["to"] is None
    lo, hi = w["stable"][0]
    # numpy's eigenvalues of A - B K: an independent route through the state space.
    a, b = carvallo.state_space(p, [lo - 1e-6, lo + 1e-6, hi - 1e-6, hi + 1e-6])
    ev = np.linalg.eigvals(a - b @ k)
    assert [bool(np.all(e.real < 0)) for e in ev] == [False, True, True, False]
    speeds = np.linspace(0.5, 8.0, 16)
    got = carvallo.closed_loop_eigenvalues(p, k, speeds)
    a, b = carvallo.state_space(p, speeds)
    for n in range(len(speeds)):
        want = np.linalg.eigvals(a[n] - b[n] @ k)
        for z in got[n]:
            assert np.abs(want - z).min() < 1e-9 * max(1.0, np.abs(want).max())
    ce = cli("eig", "--model", "benchmark", "--speed", "3", "--gain", "k_steer_roll_rate=-10", "--json")
    assert [complex(e["re"], e["im"]) for e in ce["eigenvalues"]] == list(
        carvallo.closed_loop_eigenvalues(p, k, [3.0])[0]
    )
    # Random gains: the window's stable intervals are where numpy finds every real part < 0.
    rng = np.random.default_rng(20)
    for _ in range(20):
        k = rng.uniform(-1, 1, (2, 4)) * np.array([[200, 20, 50, 5], [20, 5, 20, 2]])
        w = carvallo.closed_loop_window(p, k, 0.0, 10.0)
        edges = [0.0] + [x for s in w["stable"] for x in s] + [10.0]
        for i, (x, y) in enumerate(zip(edges[:-1], edges[1:])):
            if y - x < 1e-6:
                continue
            a, b = carvallo.state_space(p, [0.5 * (x + y)])
            stable = bool(np.all(np.linalg.eigvals(a[0] - b[0] @ k).real < 0))
            assert stable == (i % 2 == 1), (k, w)
    with pytest.raises(carvallo.ParameterError, match="unknown gain `k_yaw`: expected one of"):
        carvallo.closed_loop_window(p, {"k_yaw": 1.0})
    with pytest.raises(carvallo.ParameterError, match=r"shape \(2, 4\), not \[4, 2\]"):
        carvallo.closed_loop_window(p, np.zeros((4, 2)))
    with pytest.raises(carvallo.ParameterError, match="invalid speed range 3 to 1"):
        carvallo.closed_loop_window(p, k, 3.0, 1.0)


def test_the_python_chapter_lists_every_function(root):
    """Every public function of the module appears in the function table of
    docs/guide/src/python.md (issue 37: state_space, modes, frequency_response,
    closed_loop_window and closed_loop_eigenvalues were missing)."""
    import re

    text = (root / "docs" / "guide" / "src" / "python.md").read_text()
    table = "\n".join(l for l in text.splitlines() if l.startswith("| `"))
    listed = set(re.findall(r"`([a-z_]+)\(", table))
    public = {n for n in dir(carvallo) if not n.startswith("_") and callable(getattr(carvallo, n))}
    public = {n for n in public if n[0].islower()}
    assert public - listed == set(), public - listed


def test_bad_speeds_and_steps_are_named():
    """Issue 37: `eigenvalues(p, "fast")` names the value; `simulate(step=0.3)` over 1 s is
    refused rather than silently run at 0.3333 s."""
    p = carvallo.benchmark()
    with pytest.raises(carvallo.ParameterError, match=r"invalid speeds 'fast'"):
        carvallo.eigenvalues(p, "fast")
    with pytest.raises(carvallo.ParameterError, match=r"invalid omegas 'x'"):
        carvallo.frequency_response(p, 5.0, "x", "steer", "roll")
    with pytest.raises(carvallo.ParameterError, match=r"step.*0\.3.*does not divide the duration"):
        carvallo.simulate(p, 5.0, 0.01, 1.0, step=0.3)
    r = carvallo.simulate(p, 5.0, 0.01, 1.0, step=0.25, every=1)
    assert r["step"] == 0.25 and len(r["t"]) == 5
