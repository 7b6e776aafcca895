"""Tests of the small pure-Python pieces of the CasADi peer (scripts/casadi_peer.py): the SymPy
to CasADi translation, the kinematic rates' indices, the Jacobian column's text. Not in the
test command (they need CasADi and SymPy); run in the peer's venv, which scripts/casadi-peer
creates: `target/casadi-venv/bin/python -m pytest -q scripts/test_casadi_peer.py`."""

import sys
from pathlib import Path
from types import SimpleNamespace

import pytest
import sympy as sm

casadi = pytest.importorskip("casadi")

sys.path.insert(0, str(Path(__file__).resolve().parent))
import casadi_peer as peer  # noqa: E402


def test_translation_evaluates_as_sympy():
    a, b, c = sm.symbols("a b c")
    exprs = [sm.sin(a) * b**2 + sm.cos(a) / b, sm.sqrt(b) - 3 * a * c + sm.tan(c),
             (a + b) ** 3 - sm.Rational(1, 3), a**-2 * sm.sin(a) ** 2 + b ** sm.Rational(3, 2)]
    x = casadi.SX.sym("x", 3)
    out = peer.to_casadi(exprs, {a: x[0], b: x[1], c: x[2]})
    f = casadi.Function("f", [x], [casadi.vertcat(*out)])
    point = {a: 0.3, b: 1.7, c: -0.4}
    got = f([point[a], point[b], point[c]]).full().ravel()
    for g, e in zip(got, exprs):
        want = float(e.subs(point))
        assert g == pytest.approx(want, rel=1e-14)


def test_common_subexpressions_are_shared_in_the_graph():
    a, b = sm.symbols("a b")
    shared = sm.sin(a * b + 1)
    x = casadi.SX.sym("x", 2)
    out = peer.to_casadi([shared * a, shared * b], {a: x[0], b: x[1]})
    f = casadi.Function("f", [x], [casadi.vertcat(*out)])
    # The shared sine is evaluated once.
    ops = [f.instruction_id(k) for k in range(f.n_instructions())]
    assert ops.count(casadi.OP_SIN) == 1
    assert ops.count(casadi.OP_MUL) == 3


def test_translation_names_what_it_cannot_translate():
    a, b = sm.symbols("a b")
    x = casadi.SX.sym("x", 1)
    with pytest.raises(ValueError, match="unknown symbol `b`"):
        peer.to_casadi([a + b], {a: x[0]})
    with pytest.raises(ValueError, match="no CasADi translation of `asinh`"):
        peer.to_casadi([sm.asinh(a)], {a: x[0]})


def test_kinematic_rates_are_found_among_the_speeds():
    t = sm.Symbol("t")
    u = [sm.Function(n)(t) for n in ("u4", "u6", "u7", "u3", "u5", "u8")]
    model = SimpleNamespace(u=u, qdot=sm.Matrix([u[3], u[0], u[2], u[4]]))
    assert peer.qdot_indices(model) == [3, 0, 2, 4]
    model.qdot = sm.Matrix([2 * u[3]])
    with pytest.raises(ValueError, match="is not a speed"):
        peer.qdot_indices(model)


def test_our_jacobian_column_says_when_it_is_not_measured():
    assert peer.jacobian_column({}, "ours, state Jacobian") == "not measured (no such bench row)"
    assert peer.jacobian_column({"ours, state Jacobian": 812.4}, "ours, state Jacobian") == "812 ns"
