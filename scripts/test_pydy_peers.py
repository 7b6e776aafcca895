"""Tests of the small pure-Python pieces of the PyDy peers (scripts/pydy_whipple.py,
scripts/pydy_scipy_peer.py, scripts/pydy_c_peer.py): the parameter conversion, the operation
count, the log-log interpolation, the whole right-hand side's kinematic rates and its map to
our state. Not in the test command (they need SymPy); run in the peers' venv:
`$(scripts/pydy-peer-venv) -m pytest -q scripts/test_pydy_peers.py`."""

import math
import sys
from pathlib import Path

from types import SimpleNamespace

import numpy as np
import pytest
import sympy as sm

sys.path.insert(0, str(Path(__file__).resolve().parent))
import pydy_c_peer as cpeer  # noqa: E402
import pydy_scipy_peer as peer  # noqa: E402
import pydy_whipple as pw  # noqa: E402


def test_benchmark_parameters_are_ours():
    b = pw.benchmark_parameters()
    assert len(b) == 26
    assert b["lambda"] == math.pi / 10
    assert (b["w"], b["c"], b["rR"], b["rF"], b["mB"], b["IHxz"]) == (
        1.02, 0.08, 0.3, 0.35, 85.0, -0.00756)


def test_moore_parameters_match_pydys_example():
    # PyDy's example prints these for the benchmark bicycle, converted by DynamicistToolKit.
    assert pw.check_parameters(pw.moore_parameters(pw.benchmark_parameters())) < 1e-14
    # Another design moves every converted value: the conversion is not a table lookup.
    b = dict(pw.benchmark_parameters(), w=1.1, c=0.1, xH=0.95)
    moved = pw.moore_parameters(b)
    assert moved["d1"] != pw.MOORE_PUBLISHED["d1"] and moved["l3"] != pw.MOORE_PUBLISHED["l3"]
    # d1 + d3 is the rear-to-front wheel centre distance across the steer axis.
    lam = b["lambda"]
    assert moved["d1"] + moved["d3"] == pytest.approx(
        b["w"] * math.cos(lam) - (b["rR"] - b["rF"]) * math.sin(lam), rel=1e-15)


def test_operations_are_counted_as_ours():
    a, b, x0 = sm.symbols("a b x0")
    t = sm.Symbol("t")
    q = sm.Function("q")(t)  # a PyDy input: a function of time, not a call
    subexprs = [(x0, sm.sin(a)), (sm.Symbol("x1"), q)]
    outputs = [x0 * b + a**2, -a * b, a - b, a / b, sm.Integer(3), b]
    # sin; mul, pow, add; neg, mul; sub; div; nothing for a number or a symbol.
    assert pw.count_ops(subexprs, outputs) == 8
    kinds = pw.op_counts(subexprs, outputs)
    assert kinds == sm.sympify("SIN + 2*MUL + POW + ADD + NEG + SUB + DIV")


def test_interpolation_is_log_log_and_never_extrapolates():
    xs = [1e-3, 1e-6, 1e-9]
    ys = [x**-0.5 for x in xs]
    assert peer.interp_loglog(xs, ys, 1e-5) == pytest.approx(1e-5**-0.5, rel=1e-12)
    assert peer.interp_loglog(xs, ys, 1e-10) is None
    assert peer.interp_loglog(xs, ys, 1e-2) is None
    assert peer.interp_loglog([1e-3, float("nan")], [1.0, 2.0], 1e-3) is None


def test_pareto_front_keeps_only_undominated_runs():
    pts = [(1e-3, 5.0), (1e-4, 4.0), (1e-5, 6.0), (1e-6, 5.5), (float("nan"), 1.0)]
    # 1e-3 at 5.0 is beaten by 1e-4 at 4.0; 1e-6 at 5.5 beats 1e-5 at 6.0.
    assert peer.pareto(pts) == [(1e-6, 5.5), (1e-4, 4.0)]


def test_speedup_summary_says_met_only_when_every_error_is():
    lines = peer.speedup_summary([(25.0, "dop853", 1e-6), (19.0, "dop853", 1e-8),
                                  (30.0, "dopri5", 1e-6)], [("dop853", 1e-12)])
    assert len(lines) == 2
    assert "19x to 25x over 2 errors, >= 20x at 1 -> NOT met; 1 more accurate" in lines[0]
    assert "30x to 30x over 1 errors, >= 20x at 1 -> met; 0 more accurate" in lines[1]


def _moore_names():
    t = sm.Symbol("t")
    q = [sm.Function(n)(t) for n in ("q3", "q4", "q7", "q5")]
    u = [sm.Function(n)(t) for n in ("u4", "u6", "u7", "u3", "u5", "u8")]
    return SimpleNamespace(q=q, u=u, qdot=sm.Matrix([u[3], u[0], u[2], u[4]]))


def test_kinematic_rates_in_c_read_the_speeds():
    model = _moore_names()
    # q3' = u3, q4' = u4, q7' = u7, q5' = u5, with the speeds after the four coordinates.
    assert cpeer.kinematics_c(model) == "xd[0] = x[7]; xd[1] = x[4]; xd[2] = x[6]; xd[3] = x[8];"
    model.qdot = sm.Matrix([2 * model.u[3]])
    with pytest.raises(SystemExit, match="is not a speed"):
        cpeer.kinematics_c(model)


def test_the_lu_counts_its_arithmetic():
    # Elimination: 5 + 4 + ... rows of 1 division, 2 per column left and 2 for the right-hand
    # side; back substitution 2 per known unknown and a division: 155 + 36.
    assert cpeer.LU6_OPS == 191


def test_shared_derivatives_pair_moores_rates_with_ours():
    model = _moore_names()
    x = np.arange(10.0)  # q3 q4 q7 q5 u4 u6 u7 u3 u5 u8
    xd = 100.0 + np.arange(10.0)  # q3' q4' q7' q5' u4' u6' u7' u3' u5' u8'
    ours = [1000.0 + k for k in range(11)]
    got = {name: (p, o) for name, p, o in cpeer.shared_derivatives(model, x, xd, ours)}
    assert got["yaw rate"] == (100.0, 1002.0)
    assert got["pitch rate"] == (103.0, 1010.0)
    assert got["front wheel rate"] == (9.0, 1006.0)
    assert got["rear wheel acceleration"] == (105.0, 1009.0)
    assert len(got) == 9


def test_the_shared_timing_loop_compiles_and_times(tmp_path):
    import shutil
    import subprocess

    import c_timing

    cc = shutil.which("cc")
    if cc is None:
        pytest.skip("no C compiler")
    src = ("#include <math.h>\n#include <stdio.h>\n#include <time.h>\n" + c_timing.NOW
           + "int main(void) {\n    double x[1] = {0.0}, min_time = 1e-4;\n"
           + c_timing.timing_loop("x[0] += 1.0;", ["x"])
           + '    printf("%.3f %g\\n", best, x[0]);\n    return 0;\n}\n')
    (tmp_path / "t.c").write_text(src)
    subprocess.run([cc, "-O2", "-o", str(tmp_path / "t"), str(tmp_path / "t.c")], check=True)
    ns, calls = map(float, subprocess.run([str(tmp_path / "t")], capture_output=True, text=True,
                                          check=True).stdout.split())
    # Five slices of at least 2e-5 s each ran the call; one call takes well under a microsecond.
    assert 0.0 < ns < 1e3
    assert calls * ns * 1e-9 >= 5 * 2e-5 * 0.99
    with pytest.raises(ValueError):
        c_timing.timing_loop("x[0] += 1.0;", [])
