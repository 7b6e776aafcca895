"""The figures of `carvallo.plot` (matplotlib, Agg backend): the geometry points of
`carvallo.geometry` against the benchmark's table computed by hand, the same points as the
command line's `carvallo plot geometry` draws, and the figures' titles, mode labels, legends and
decade tick labels; matplotlib missing is an ImportError saying how to install it."""

import builtins
import math
import os
import pathlib
import re
import subprocess
import sys

import matplotlib
import numpy as np
import pytest

import carvallo

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[3]
# Browser breaks a triangle inequality (a PhysicsWarning, computed as given).
pytestmark = pytest.mark.filterwarnings("ignore:.*triangle inequality")
DATA = ROOT / "data" / "bicycleparameters"
BROWSER = DATA / "bicycles" / "Browser" / "Parameters" / "BrowserBenchmark.txt"
JASON = DATA / "riders" / "Jason" / "Parameters" / "JasonBrowserBenchmark.txt"


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def texts(fig):
    """Every text of a drawn figure: titles, labels, tick labels, legend entries, annotations."""
    fig.canvas.draw()
    return [t.get_text() for t in fig.findobj(matplotlib.text.Text) if t.get_text()]


def test_the_benchmark_geometry_is_the_table_by_hand():
    # Meijaard et al. 2007, Table 1: w = 1.02, c = 0.08, λ = π/10, rR = 0.3, rF = 0.35.
    g = carvallo.geometry(carvallo.benchmark())
    lam = math.pi / 10
    assert np.allclose(g["rear_contact"], [0, 0], atol=1e-15)
    assert np.allclose(g["rear_hub"], [0, 0.3], atol=1e-15)
    assert np.allclose(g["front_contact"], [1.02, 0], atol=1e-15)
    assert np.allclose(g["front_hub"], [1.02, 0.35], atol=1e-15)
    assert (g["rear_radius"], g["front_radius"]) == (0.3, 0.35)
    (x0, h0), (x1, h1) = g["trail"]
    assert (x0, h0, h1) == (1.02, 0.0, 0.0) and abs(x1 - x0 - 0.08) < 1e-15
    (a0, b0), (a1, b1) = g["steer_axis"]
    assert abs(a0 - 1.10) < 1e-15 and b0 == 0.0
    assert abs((a0 - a1) / (b1 - b0) - math.tan(lam)) < 1e-14
    hub, foot = g["fork"]
    offset = np.hypot(*(hub - foot))
    assert abs(offset - (0.35 * math.sin(lam) - 0.08 * math.cos(lam))) < 1e-14
    assert np.allclose(g["mass_centres"]["rear frame"], [0.3, 0.9], atol=1e-15)
    assert np.allclose(g["mass_centres"]["front frame"], [0.9, 0.7], atol=1e-15)
    m = g["masses"]
    assert (m["rear wheel"], m["rear frame"], m["front frame"], m["front wheel"]) == (2, 85, 4, 3)
    whole = [(85 * 0.3 + 4 * 0.9 + 3 * 1.02) / 94, (2 * 0.3 + 85 * 0.9 + 4 * 0.7 + 3 * 0.35) / 94]
    assert np.allclose(g["mass_centres"]["whole bicycle"], whole, atol=1e-14)


def test_a_rider_is_drawn_apart_and_a_file_rider_is_read():
    bike, _ = carvallo.load_parameters(str(BROWSER))
    g = carvallo.geometry(bike, str(JASON))
    # JasonBrowserBenchmark.txt: mB = 72.0, xB = 0.2909, zB = -1.1091.
    assert g["masses"]["rider"] == 72.0
    assert np.allclose(g["mass_centres"]["rider"], [0.2909, 1.1091], atol=1e-15)
    assert "rider" not in carvallo.geometry(bike)["mass_centres"]
    with pytest.raises(carvallo.ParameterError, match="missing rider parameter"):
        carvallo.geometry(bike, {"mB": 70.0})


def test_python_and_the_command_line_draw_the_same_points(tmp_path, cli):
    """The trail and the tilt the CLI's figure states are those of carvallo.geometry's points
    (`cli` fails the test if the binary is missing)."""
    exe = os.environ.get("CARVALLO_BIN", str(ROOT / "target" / "release" / "carvallo"))
    out = tmp_path / "g.svg"
    subprocess.run([exe, "plot", "geometry", "--model", str(BROWSER), "--rider", str(JASON),
                    "--out", str(out)], check=True, capture_output=True)
    svg = out.read_text()
    g = carvallo.geometry(carvallo.load_parameters(str(BROWSER))[0], str(JASON))
    (x0, _), (x1, _) = g["trail"]
    assert f"trail c = {x1 - x0:.3f} m" in svg
    (a0, b0), (a1, b1) = g["steer_axis"]
    assert f"λ = {math.degrees(math.atan2(a0 - a1, b1 - b0)):.1f}°" in svg
    assert "Browser + Jason: geometry" in svg


def test_the_figures_carry_the_name_the_modes_and_the_decades():
    bench = carvallo.benchmark()
    fig = carvallo.plot_geometry(bench, name="Benchmark bicycle")
    t = texts(fig)
    assert "Benchmark bicycle: geometry" in t
    assert {"rear frame", "front frame", "trail c = 0.080 m", "steer axis, λ = 18.0°"} <= set(t)

    fig = carvallo.plot_eigenvalues(bench, name="Benchmark bicycle")
    t = texts(fig)
    assert "Benchmark bicycle: eigenvalues against speed" in t
    assert {"weave", "capsize", "caster", "weave: Re λ", "capsize: Re λ", "caster: Re λ"} <= set(t)
    assert any(s.startswith("stable: 4.292 < v < 6.024") for s in t), t

    # The leaning rider's figure names the torso's mode beside the bicycle's, and its roots are
    # those of carvallo.modes (the torso's unstable one near +7 1/s).
    speeds = np.linspace(0.0, 8.0, 81)
    fig = carvallo.plot_eigenvalues(carvallo.lean_rider(), speeds=speeds)
    t = texts(fig)
    assert "Leaning rider (Browser + Jason): eigenvalues against speed" in t
    assert {"torso", "torso: Re λ", "weave: Re λ", "capsize: Re λ", "caster: Re λ"} <= set(t), t
    labels, ev, _ = carvallo.modes(carvallo.lean_rider(), speeds)
    torso = [ln for ln in fig.axes[0].get_lines() if ln.get_label() == "torso: Re λ"][0]
    assert np.array_equal(torso.get_ydata(), np.where(abs(ev[:, 4].real) <= 10, ev[:, 4].real, np.nan))
    assert np.all((ev[:, 4].real > 6.5) & (ev[:, 4].real < 7.6))

    short = dict(bench, c=0.06)
    fig = carvallo.plot_bode([bench, short], speeds=5.0, names=["Benchmark", "Short trail"])
    t = texts(fig)
    assert "Benchmark and Short trail: steer torque Tδ to lean φ, v = 5 m/s" in t
    assert {"Benchmark", "Short trail"} <= set(t)
    assert {"10⁻¹", "10⁰", "10¹", "10²"} <= set(t), t
    assert not any("log" in s for s in t)
    # The curves are the numbers of frequency_response.
    mag_ax = fig.axes[0]
    line = mag_ax.get_lines()[1]
    r = carvallo.frequency_response(short, [5.0], line.get_xdata(), "steer", "roll")
    assert np.array_equal(line.get_ydata(), r["magnitude_db"][0])


def test_the_riders_figure_names_the_parameter_set_it_draws(tmp_path, cli):
    """The leaning rider's eigenvalue figure is titled by the parameter set drawn, as the command
    line's `plot eigenvalues --model` titles it: a file by its stem (the same title as the
    command line's for the same file), Browser + Jason's values by their name, another rider's
    dict without Browser + Jason's name."""
    speeds = np.linspace(0.0, 8.0, 41)
    heavy = tmp_path / "heavy_torso.toml"
    published = (ROOT / "data" / "mooreriderlean2012" / "browser_jason.toml").read_text()
    heavy.write_text(re.sub(r"(?m)^mg = .*$", "mg = 60.0", published))
    assert carvallo.lean_rider(str(heavy))["mg"] == 60.0
    want = "heavy_torso: eigenvalues against speed"
    for path in (str(heavy), heavy):
        t = texts(carvallo.plot_eigenvalues(path, speeds=speeds))
        assert want in t, t
        assert not any("Browser" in s for s in t), t
    exe = os.environ.get("CARVALLO_BIN", str(ROOT / "target" / "release" / "carvallo"))
    out = tmp_path / "e.svg"
    subprocess.run([exe, "plot", "eigenvalues", "--model", str(heavy), "--v-max", "8",
                    "--out", str(out)], check=True, capture_output=True)
    assert want in out.read_text()
    # The file's values in a dict: the dict keeps no file name, and is not Browser + Jason.
    t = texts(carvallo.plot_eigenvalues(carvallo.lean_rider(str(heavy)), speeds=speeds))
    assert "Leaning rider: eigenvalues against speed" in t, t
    assert not any("Browser" in s for s in t), t
    # Browser + Jason's values, read from the committed file or built in, and a name given.
    browser = ROOT / "data" / "mooreriderlean2012" / "browser_jason.toml"
    t = texts(carvallo.plot_eigenvalues(carvallo.lean_rider(str(browser)), speeds=speeds))
    assert "Leaning rider (Browser + Jason): eigenvalues against speed" in t, t
    t = texts(carvallo.plot_eigenvalues(str(heavy), speeds=speeds, name="Jason, heavier"))
    assert "Jason, heavier: eigenvalues against speed" in t, t
    with pytest.raises(carvallo.ParameterError, match="leaning-rider file"):
        carvallo.plot_eigenvalues(str(BROWSER), speeds=speeds)


def test_the_submodule_imports_and_a_bicycle_object_names_itself():
    from carvallo.plot import plot_bode

    assert plot_bode is carvallo.plot_bode
    assert carvallo.plot.decade_label(-1) == "10⁻¹"

    class Named(dict):
        bicycleName = "Browser"
        riderName = "Jason"

    fig = carvallo.plot_bode(Named(carvallo.benchmark()), speeds=[4.0, 6.0])
    t = texts(fig)
    assert any(s.startswith("Browser + Jason: steer torque") for s in t), t
    assert {"v = 4 m/s", "v = 6 m/s"} <= set(t)
    with pytest.raises(carvallo.ParameterError, match="1 names for 2 bicycles"):
        carvallo.plot_bode([carvallo.benchmark()] * 2, names=["a"])
    # Found by the seeded fuzz of test_edges: ω = 0 (valid for frequency_response) was a bare
    # ValueError from the logarithmic axis.
    with pytest.raises(carvallo.ParameterError, match="invalid omega 0.0: the plot's log"):
        carvallo.plot_bode(carvallo.benchmark(), omegas=[0.0, 1.0])
    # And bytes, which pyo3 reads as a sequence of integers (b"\xff" as [255.0]).
    with pytest.raises(carvallo.ParameterError, match=r"invalid omegas b'\\xff': must be"):
        carvallo.plot_bode(carvallo.benchmark(), omegas=b"\xff")


def test_without_matplotlib_the_error_says_how_to_install_it(monkeypatch):
    real = builtins.__import__

    def no_matplotlib(name, *args, **kwargs):
        if name.startswith("matplotlib"):
            raise ImportError(f"No module named {name!r}")
        return real(name, *args, **kwargs)

    for key in [k for k in sys.modules if k.startswith("matplotlib")]:
        monkeypatch.delitem(sys.modules, key)
    monkeypatch.setattr(builtins, "__import__", no_matplotlib)
    with pytest.raises(ImportError, match=re.escape("pip install matplotlib")):
        carvallo.plot_geometry(carvallo.benchmark())
