"""The peer model of the nonlinear Carvallo–Whipple bicycle: SymPy's Kane formulation as PyDy
publishes it, shared by scripts/pydy-c-peer (issue 22) and scripts/pydy-scipy-peer (issue 21).

The formulation follows PyDy's example "Carvallo-Whipple Bicycle Model"
(pydy/pydy, docs/examples/carvallo-whipple.rst, BSD 3-clause licence, Copyright (c) PyDy
developers), itself after J. K. Moore, "Human Control of a Bicycle", PhD dissertation,
University of California, Davis, 2012: yaw q3, roll q4, pitch q5 and steer q7 as coordinates
(the pitch dependent through the front contact's holonomic constraint), the roll, rear wheel
and steer rates u4, u6, u7 as independent speeds and the yaw, pitch and front wheel rates
u3, u5, u8 as dependent ones (the two no-slip constraints of the front contact and the time
derivative of the holonomic constraint), `sympy.physics.mechanics.KanesMethod` for the
equations `M(q) u' = F(q, u)` (M is 6 x 6: three dynamic rows for the independent speeds, three
rows of the constraints' time derivatives). It is re-typed here, not imported, so that the
scripts need PyDy only for its code generators; the bodies, points and constraints are those
of the example, in its order (the order of the velocity constraints matters for the floating
point conditioning, as its notes say). The applied torques of the example are left out: both
peers compare the hands-free bicycle.

The parameters are converted from the 25 benchmark parameters of Meijaard et al. (2007) — read
from `crates/carvallo/src/whipple/params.rs` (`BENCHMARK_TOML`), the same text our library
reads — to Moore's set by [`moore_parameters`]: plane geometry of the rear frame C (unit
vectors c1 forward-up along the perpendicular to the steer axis, c3 down the steer axis) and of
the front frame E. The conversion is checked against the numbers PyDy's example prints
(`MOORE_PUBLISHED`).

The map between Moore's coordinates and ours (`carvallo::whipple::nonlinear`, benchmark axes):
yaw q3 = ψ, roll q4 = φ, pitch q5 = θ + λ (θ = 0 is our upright rear frame), steer q7 = δ, the
rates alike (u6 the rear wheel rate relative to the rear frame, u8 the front wheel's relative
to the fork). Basu-Mandal et al.'s (2007) coordinates follow from ours as in nonlinear.rs.
"""

from __future__ import annotations

import math
import re
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me
from sympy.core.function import AppliedUndef

ROOT = Path(__file__).resolve().parent.parent

# Moore's parameters as PyDy's example prints them for the benchmark bicycle (the check of
# `moore_parameters`).
MOORE_PUBLISHED = {
    "rf": 0.35, "rr": 0.3, "d1": 0.9534570696121849, "d3": 0.03207142672761929,
    "d2": 0.2676445084476887, "l1": 0.4707271515135145, "l2": -0.47792881146460797,
    "l4": -0.3699518200282974, "l3": -0.00597083392418685, "mc": 85.0, "md": 2.0, "me": 4.0,
    "mf": 3.0, "id11": 0.0603, "id22": 0.12, "if11": 0.1405, "if22": 0.28,
    "ic11": 7.178169776497895, "ic22": 11.0, "ic31": 3.8225535938357873,
    "ic33": 4.821830223502103, "ie11": 0.05841337700152972, "ie22": 0.06,
    "ie31": 0.009119225261946298, "ie33": 0.007586622998470264, "g": 9.81,
}

# Basu-Mandal, Chatterjee and Papadopoulos (2007), Table 1, as in
# crates/carvallo/tests/it/whipple/basu_mandal.rs: q = x, y, z, theta, psi, phi, psif, betar,
# betaf, their rates and the nine accelerations.
BASU_Q = [0.0, 0.0, 0.2440472102925, 0.0, 0.9501292851472, 3.1257073014894, 0.2311385135743,
          0.0, 0.0]
BASU_QD = [-2.8069345714545, -0.1480982396001, 0.1058778746261, 0.7830033527065,
           0.6068425835418, -0.0119185528069, 0.4859824687093, 8.9129896614890, 8.0133620584155]
BASU_QDD = [-0.5041626315047, -0.3449706619454, -1.4604528332980, 0.8353281706379,
            -7.8555281128244, 0.1205543897884, -4.6198904039403, 1.8472554144217,
            2.4548072904550]
BASU_NAMES = ["x", "y", "z", "theta", "psi", "phi", "psif", "betar", "betaf"]


def benchmark_parameters(root: Path = ROOT) -> dict[str, float]:
    """The 25 benchmark parameters and g, from our library's `BENCHMARK_TOML`."""
    import tomllib

    src = (root / "crates/carvallo/src/whipple/params.rs").read_text()
    m = re.search(r'pub const BENCHMARK_TOML: &str = r#"(.*?)"#;', src, re.S)
    if m is None:
        raise SystemExit("error: BENCHMARK_TOML not found in crates/carvallo/src/whipple/params.rs")
    table = tomllib.loads(m.group(1))["parameters"]
    out = {}
    for k, v in table.items():
        if isinstance(v, str):
            num, _, den = v.partition("/")
            if num.strip() != "pi":
                raise SystemExit(f"error: unexpected parameter text {k} = {v!r}")
            v = math.pi / float(den) if den else math.pi
        out[k] = float(v)
    return out


def moore_parameters(b: dict[str, float]) -> dict[str, float]:
    """Moore's parameters of the benchmark set `b` (see the module docs)."""
    lam = b["lambda"]
    s, c = math.sin(lam), math.cos(lam)
    # c1 = (cos λ, 0, -sin λ), c3 = (sin λ, 0, cos λ) in benchmark axes (z down).
    def along(x, z):
        return x * c - z * s, x * s + z * c

    # From the rear wheel centre (0, -rR) to the steer axis' ground point (w + c, 0).
    d1, _ = along(b["w"] + b["c"], b["rR"])
    # From the rear wheel centre to the front wheel centre (w, -rF).
    x13, d2 = along(b["w"], b["rR"] - b["rF"])
    l1, l2 = along(b["xB"], b["zB"] + b["rR"])
    l3, l4 = along(b["xH"] - b["w"], b["zH"] + b["rF"])

    def rotated(ixx, iyy, izz, ixz):
        i = np.array([[ixx, 0.0, ixz], [0.0, iyy, 0.0], [ixz, 0.0, izz]])
        e1, e3 = np.array([c, 0.0, -s]), np.array([s, 0.0, c])
        return float(e1 @ i @ e1), iyy, float(e3 @ i @ e3), float(e3 @ i @ e1)

    ic11, ic22, ic33, ic31 = rotated(b["IBxx"], b["IByy"], b["IBzz"], b["IBxz"])
    ie11, ie22, ie33, ie31 = rotated(b["IHxx"], b["IHyy"], b["IHzz"], b["IHxz"])
    return {
        "rf": b["rF"], "rr": b["rR"], "d1": d1, "d2": d2, "d3": x13 - d1,
        "l1": l1, "l2": l2, "l3": l3, "l4": l4,
        "mc": b["mB"], "md": b["mR"], "me": b["mH"], "mf": b["mF"],
        "id11": b["IRxx"], "id22": b["IRyy"], "if11": b["IFxx"], "if22": b["IFyy"],
        "ic11": ic11, "ic22": ic22, "ic33": ic33, "ic31": ic31,
        "ie11": ie11, "ie22": ie22, "ie33": ie33, "ie31": ie31, "g": b["g"],
    }


@dataclass
class Model:
    """The derived equations and what the scripts evaluate."""

    q: list  # q3 yaw, q4 roll, q7 steer, q5 pitch (KanesMethod's order)
    u: list  # u4 roll, u6 rear wheel, u7 steer, u3 yaw, u5 pitch, u8 front wheel rates
    constants: list  # Moore's parameter symbols, in MOORE_PUBLISHED's order
    mass_matrix: sm.Matrix  # 6 x 6
    forcing: sm.Matrix  # 6 x 1, the coordinate derivatives replaced by the speeds
    holonomic: sm.Expr  # front contact height, a function of q4, q5, q7
    nonholonomic: sm.Matrix  # the three velocity constraints, linear in u
    rear_centre_acc: sm.Matrix  # acceleration of the rear wheel centre in N (3 x 1)
    qdot: sm.Matrix  # q' in terms of u (the kinematical differential equations)
    lam: float
    values: dict  # Moore's parameter values by name
    seconds: float  # the derivation's wall time


def derive(params: dict[str, float] | None = None) -> Model:
    """Kane's equations of the bicycle (see the module docs) for the benchmark parameters."""
    start = time.perf_counter()
    b = params or benchmark_parameters()
    values = moore_parameters(b)
    N, A, B, C, D, E, F = (me.ReferenceFrame(n) for n in "NABCDEF")
    q3, q4, q5, q7 = me.dynamicsymbols("q3 q4 q5 q7")
    u3, u4, u5, u6, u7, u8 = me.dynamicsymbols("u3 u4 u5 u6 u7 u8")
    t = me.dynamicsymbols._t
    sym = {name: sm.Symbol(name) for name in MOORE_PUBLISHED}
    rf, rr, d1, d2, d3 = (sym[k] for k in ("rf", "rr", "d1", "d2", "d3"))
    l1, l2, l3, l4, g = (sym[k] for k in ("l1", "l2", "l3", "l4", "g"))
    mc, md, me_, mf = (sym[k] for k in ("mc", "md", "me", "mf"))

    A.orient_axis(N, q3, N.z)  # yaw
    B.orient_axis(A, q4, A.x)  # roll
    C.orient_axis(B, q5, B.y)  # pitch
    E.orient_axis(C, q7, C.z)  # steer

    dn = me.Point("dn")  # rear contact
    do = dn.locatenew("do", -rr * B.z)  # rear wheel centre
    co = do.locatenew("co", l1 * C.x + l2 * C.z)  # rear frame mass centre
    ce = do.locatenew("ce", d1 * C.x)  # steer axis point
    fo = ce.locatenew("fo", d2 * E.z + d3 * E.x)  # front wheel centre
    eo = fo.locatenew("eo", l3 * E.x + l4 * E.z)  # fork mass centre
    fn = fo.locatenew("fn", rf * E.y.cross(A.z).cross(E.y).normalize())  # front contact

    holonomic = fn.pos_from(dn).dot(A.z)
    kinematical = [q3.diff(t) - u3, q4.diff(t) - u4, q5.diff(t) - u5, q7.diff(t) - u7]

    A.set_ang_vel(N, u3 * N.z)
    B.set_ang_vel(A, u4 * A.x)
    C.set_ang_vel(B, u5 * B.y)
    D.set_ang_vel(C, u6 * C.y)
    E.set_ang_vel(C, u7 * C.z)
    F.set_ang_vel(E, u8 * E.y)

    dn.set_vel(N, 0.0 * N.x)
    do.v2pt_theory(dn, N, D)
    co.v2pt_theory(do, N, C)
    ce.v2pt_theory(do, N, C)
    fo.v2pt_theory(ce, N, E)
    eo.v2pt_theory(fo, N, E)
    fn.v2pt_theory(fo, N, F)

    # The example's order: longitudinal slip, vertical, lateral slip.
    nonholonomic = [fn.vel(N).dot(A.x), fn.vel(N).dot(A.z), fn.vel(N).dot(A.y)]

    ic = me.inertia(C, sym["ic11"], sym["ic22"], sym["ic33"], 0.0, 0.0, sym["ic31"])
    id_ = me.inertia(C, sym["id11"], sym["id22"], sym["id11"], 0.0, 0.0, 0.0)
    ie = me.inertia(E, sym["ie11"], sym["ie22"], sym["ie33"], 0.0, 0.0, sym["ie31"])
    if_ = me.inertia(E, sym["if11"], sym["if22"], sym["if11"], 0.0, 0.0, 0.0)
    bodies = [
        me.RigidBody("rear frame", co, C, mc, (ic, co)),
        me.RigidBody("rear wheel", do, D, md, (id_, do)),
        me.RigidBody("front frame", eo, E, me_, (ie, eo)),
        me.RigidBody("front wheel", fo, F, mf, (if_, fo)),
    ]
    loads = [(co, mc * g * A.z), (do, md * g * A.z), (eo, me_ * g * A.z), (fo, mf * g * A.z)]

    kane = me.KanesMethod(
        N, [q3, q4, q7], [u4, u6, u7], kd_eqs=kinematical, q_dependent=[q5],
        configuration_constraints=[holonomic], u_dependent=[u3, u5, u8],
        velocity_constraints=nonholonomic)
    kane.kanes_equations(bodies, loads)
    kdd = kane.kindiffdict()
    mass = kane.mass_matrix
    forcing = kane.forcing.xreplace(kdd)
    acc = do.acc(N).to_matrix(N).xreplace(kdd)
    return Model(
        q=list(kane.q), u=list(kane.u), constants=[sym[k] for k in MOORE_PUBLISHED],
        mass_matrix=mass, forcing=forcing, holonomic=holonomic,
        nonholonomic=sm.Matrix(nonholonomic), rear_centre_acc=acc,
        qdot=sm.Matrix([kdd[qi.diff(t)] for qi in kane.q]), lam=b["lambda"],
        values=values, seconds=time.perf_counter() - start)


def check_parameters(values: dict[str, float]) -> float:
    """The largest relative difference between our conversion and PyDy's printed numbers."""
    return max(abs(values[k] - v) / max(abs(v), 1e-300) for k, v in MOORE_PUBLISHED.items())


def to_symbols(model: Model, expr):
    """`expr` with the functions of time replaced by plain symbols named alike."""
    repl = {f: sm.Symbol(f.func.__name__) for f in model.q + model.u}
    return expr.xreplace(repl)


class Numeric:
    """Plain NumPy evaluations the scripts need besides the generated code: the pitch from the
    holonomic constraint, the dependent speeds from the velocity constraints, the rear wheel
    centre's acceleration, Basu-Mandal's table in these coordinates."""

    def __init__(self, model: Model):
        self.model = model
        consts = {s: model.values[s.name] for s in model.constants}
        self.const_array = np.array([model.values[s.name] for s in model.constants])
        q3, q4, q7, q5 = (sm.Symbol(f.func.__name__) for f in model.q)
        h = to_symbols(model, model.holonomic).xreplace(consts)
        self._h = sm.lambdify((q4, q5, q7), h, "math")
        self._dh = sm.lambdify((q4, q5, q7), h.diff(q5), "math")
        qs = [sm.Symbol(f.func.__name__) for f in model.q]
        us = [sm.Symbol(f.func.__name__) for f in model.u]
        nh = to_symbols(model, model.nonholonomic).xreplace(consts)
        udep = us[3:]
        kmat = nh.jacobian(udep)
        rest = nh.xreplace({x: 0 for x in udep})
        self._k = sm.lambdify((qs, us[:3]), kmat, "numpy")
        self._r = sm.lambdify((qs, us[:3]), rest, "numpy")
        self._nh = sm.lambdify((qs, us), nh, "numpy")
        ud = [sm.Symbol(f.func.__name__ + "d") for f in model.u]
        derivs = {f.diff(me.dynamicsymbols._t): s for f, s in zip(model.u, ud)}
        acc = to_symbols(model, model.rear_centre_acc.xreplace(derivs)).xreplace(consts)
        self._acc = sm.lambdify((qs, us, ud), acc, "numpy")

    def contact(self, lean: float, pitch_q5: float, steer: float) -> float:
        """The holonomic constraint (m): the front contact's height above the ground."""
        return self._h(lean, pitch_q5, steer)

    def pitch(self, lean: float, steer: float, guess: float | None = None) -> float:
        """Moore's pitch q5 that puts the front wheel on the ground (Newton)."""
        x = self.model.lam if guess is None else guess
        for _ in range(50):
            step = self._h(lean, x, steer) / self._dh(lean, x, steer)
            x -= step
            if abs(step) <= 1e-15 * (1.0 + abs(x)):
                return x
        raise RuntimeError(
            f"no pitch puts the front wheel on the ground at lean {lean}, steer {steer}")

    def dependent_speeds(self, q, u_ind) -> np.ndarray:
        """u3, u5, u8 from the velocity constraints at coordinates q (q3, q4, q7, q5)."""
        k = np.array(self._k(list(q), list(u_ind)), dtype=float)
        r = np.array(self._r(list(q), list(u_ind)), dtype=float).ravel()
        return np.linalg.solve(k, -r)

    def velocity_residual(self, q, u) -> float:
        """Largest |velocity constraint| (m/s) at (q, u)."""
        return float(np.max(np.abs(np.array(self._nh(list(q), list(u)), dtype=float))))

    def state(self, yaw, lean, steer, lean_rate, steer_rate, rear_wheel_rate, pitch_guess=None):
        """The PyDy state [q3, q4, q7, q5, u4, u6, u7, u3, u5, u8] at a point of ours: the pitch
        solved from the holonomic constraint, the dependent speeds from the velocity ones."""
        q5 = self.pitch(lean, steer, pitch_guess)
        q = [yaw, lean, steer, q5]
        u_ind = [lean_rate, rear_wheel_rate, steer_rate]
        return np.array(q + u_ind + list(self.dependent_speeds(q, u_ind)))

    def basu_mandal_state(self) -> np.ndarray:
        """Basu-Mandal's Table 1 state in PyDy's coordinates (the pitch and the dependent
        speeds recomputed from the constraints, as our library does)."""
        bq, bqd = BASU_Q, BASU_QD
        lean, steer = math.pi / 2 - bq[4], -bq[6]
        return self.state(-bq[3], lean, steer, -bqd[4], -bqd[6], -bqd[7],
                          pitch_guess=math.pi - bq[5] + self.model.lam)

    def precise_speed_derivatives(self, x: np.ndarray, digits: int = 60) -> list[float]:
        """u' at the state `x` (its doubles taken exactly) from M and F evaluated and solved
        with `digits` significant digits (mpmath), rounded to doubles: the reference for the
        rounding error of the generated code."""
        import mpmath

        if not hasattr(self, "_mp"):
            m = self.model
            qs = [sm.Symbol(f.func.__name__) for f in m.q]
            us = [sm.Symbol(f.func.__name__) for f in m.u]
            args = (qs, us, m.constants)
            self._mp = (sm.lambdify(args, to_symbols(m, m.mass_matrix), "mpmath", cse=True),
                        sm.lambdify(args, to_symbols(m, m.forcing), "mpmath", cse=True))
        with mpmath.workdps(digits):
            xm = [mpmath.mpf(float(v)) for v in x]
            c = [mpmath.mpf(float(v)) for v in self.const_array]
            mm = mpmath.matrix(self._mp[0](xm[:4], xm[4:], c))
            ff = mpmath.matrix(self._mp[1](xm[:4], xm[4:], c))
            ud = mpmath.lu_solve(mm, ff)
            return [float(ud[i]) for i in range(len(xm) - 4)]

    def basu_mandal_accelerations(self, x: np.ndarray, ud: np.ndarray) -> list[float]:
        """The nine accelerations of Basu-Mandal's Table 1 from the state `x` and the six speed
        derivatives `ud` (u4', u6', u7', u3', u5', u8'), by the map of nonlinear.rs."""
        q, u = list(x[:4]), list(x[4:])
        ax, ay, az = np.array(self._acc(q, u, list(ud)), dtype=float).ravel()
        u4d, u6d, u7d, u3d, u5d, u8d = ud
        return [-ax, ay, -az, -u3d, -u4d, -u5d, -u7d, -u6d, -u8d]


def basu_mandal_report(got: list[float]) -> tuple[float, str]:
    """The worst relative difference to Table 1 and a printable table."""
    lines, worst = [], 0.0
    for name, g, w in zip(BASU_NAMES, got, BASU_QDD):
        rel = abs(g - w) / abs(w)
        worst = max(worst, rel)
        lines.append(f"  {name + 'dd':<8} {g:+.13f}  table {w:+.13f}  relative {rel:.1e}")
    return worst, "\n".join(lines)


def count_ops(subexprs, outputs) -> int:
    """Operations after CSE, counted as crates/carvallo-ir/src/count.rs counts ours: every
    operation is one, constants are free. `sympy.count_ops` does that per expression — an
    n-term sum is n - 1 additions or subtractions, an n-factor product n - 1 multiplications (a
    negative coefficient one negation, a denominator one division), a power one `pow`, sin and
    cos one call each — summed over the CSE replacements and the outputs ([`op_counts`]); a
    bare symbol or number costs nothing."""
    return int(op_counts(subexprs, outputs).subs({s: 1 for s in _OP_NAMES}))


_OP_NAMES = [sm.Symbol(n) for n in ("ADD", "SUB", "MUL", "DIV", "NEG", "POW", "SIN", "COS", "TAN")]


def op_counts(subexprs, outputs) -> sm.Expr:
    """The operations of [`count_ops`] by kind, as `sympy.count_ops(visual=True)` names them
    (`546*ADD + 1460*MUL + ...`); PyDy's inputs (functions of time) are plain symbols here, not
    calls."""

    def plain(e):
        return e.xreplace({f: sm.Symbol(f.func.__name__) for f in e.atoms(AppliedUndef)})

    total = sm.S(0)
    for e in [e for _, e in subexprs] + list(outputs):
        total += sm.count_ops(plain(e), visual=True)
    unknown = total.free_symbols - set(_OP_NAMES)
    if unknown:
        raise ValueError(f"operations of unexpected kinds: {sorted(map(str, unknown))}")
    return total
