"""SymBRiM's operation count of its Whipple bicycle beside ours (issue 34). Run by
scripts/symbrim-peer, which installs the pinned peer.

SymBRiM (mechmotum/symbrim, `symbrim` on PyPI; Stienstra, Brockie and Moore, BMD 2023,
doi:10.59490/6504c5a765e8118fc7b106c3) publishes the operation count of its Whipple bicycle as
a regression baseline: `.benchmarks/baseline.json` at commit 47b954c (2026-02-01), entry
`benchmarks/test_whipple_bicycle.py::test_whipple_bicycle_moore_brim`,
`"operation_eoms": 266664, "operation_eoms_csed": 1909`. Its benchmark
(`benchmarks/test_whipple_bicycle.py`, `create_whipple_bicycle_moore_brim`) builds
`WhippleBicycleMoore` from a flat ground, rigid rear and front frames, two knife-edge wheels and
two non-holonomic tyres, applies gravity, makes the pitch q5 the dependent coordinate and
u4, u6, u7 (roll, rear wheel, steer rates) the independent speeds (u1, u2, u3, u5, u8
dependent), and `symbrim.utilities.benchmarking.benchmark` counts
`sympy.count_ops(sympy.cse(eoms))` with `eoms = system.form_eoms(constraint_solver="CRAMER")`
after `sympy.core.cache.clear_cache()`. Those `eoms` are KanesMethod's `fr + frstar`: the three
dynamical equations of the independent speeds, residuals that still take all eight speeds and
all eight speed derivatives as unknowns (the 3 x 8 rows `k_d` of the mass matrix times u', plus
the rest). They are neither a mass matrix nor a forcing vector, and they do not eliminate the
dependent speeds.

This script:
1. Rebuilds that benchmark model exactly (the same calls, the same `clear_cache`) and counts
   as SymBRiM counts: `count_ops(eoms)` and `count_ops(cse(eoms))`. With SymPy 1.14.0 this is
   SymBRiM's published 266,664 and 1,909; SymPy 1.13.3 gives 266,594 and 1,908 (the figure
   issue 34 quotes). SymPy's `count_ops` counts every call of a function of time (`bike_q4(t)`)
   and every `Derivative` as operations; the same count with those as plain symbols (the
   inputs of a generated function) follows, by kind.
2. Forms from SymBRiM's own KanesMethod the quantity our `m3_*`, `f3_*` outputs compute: the
   3 x 3 mass matrix and the forcing of the independent speeds with the dependent speeds
   eliminated, M3 u_ind' = f3, from the pitch as an input (the holonomic constraint is not
   solved, as in ours): with `k_d` (3 x 8) and `F = -f_d` SymPy's dynamical rows
   (k_d u' = F), `Ars` SymPy's u_dep = Ars u_ind (Cramer's rule, as SymBRiM asks) and the
   acceleration constraints k_nh u' + f_dnh = 0,
       M3 = k_d[:, ind] + k_d[:, dep] Ars,   f3 = F + k_d[:, dep] k_nh[:, dep]^-1 f_dnh
   (the inverse by Cramer's rule again), the dependent speeds then u_dep = Ars u_ind. It is
   counted the same way (`count_ops(cse(...))`, plain symbols) as one straight-line program:
   the five dependent speeds as five expressions of the program and M3's six entries (upper
   triangle; it is symmetric) and f3's three as its outputs, as our program computes the
   dependent speeds once and uses them (substituting them into f3 before CSE would only
   repeat them, and makes trees SymPy cannot walk). The construction is checked numerically
   at seeded random points: M3 symmetric, and M3 u_ind' = f3 for the u' that solves SymPy's
   full 8 x 8 system (mass_matrix u' = forcing).
3. Counts ours in generated/whipple_nonlinear.ir as crates/carvallo-ir/src/count.rs does (each
   `let tN = <op> ...` other than `const` is one operation), over the cone of the `m3_*` and
   `f3_*` outputs (the instructions they depend on), by kind; and counts the same cone with
   `sympy.count_ops` per instruction, to show the two counts agree on what one operation is.
   The parameter-only part of each side (operations that read no state: our conversion of the
   benchmark parameters of Meijaard et al. to body geometry, SymBRiM's products of Moore's
   parameters) is given separately, since the two sides take different parameter sets.
"""

from __future__ import annotations

import argparse
import re
import sys
import time
from importlib.metadata import version
from pathlib import Path

import numpy as np
import sympy as sm
from sympy.core.cache import clear_cache

ROOT = Path(__file__).resolve().parent.parent
IR = ROOT / "generated" / "whipple_nonlinear.ir"

OP_NAMES = ("ADD", "SUB", "MUL", "DIV", "NEG", "POW", "SIN", "COS", "TAN")


def create_whipple_bicycle_moore_brim():
    """SymBRiM's benchmark model, as `benchmarks/test_whipple_bicycle.py` (commit 47b954c)
    builds it: returns the bicycle and its `System`."""
    from symbrim.bicycle import (
        FlatGround,
        KnifeEdgeWheel,
        NonHolonomicTire,
        RigidFrontFrame,
        RigidRearFrame,
        WhippleBicycleMoore,
    )

    bike = WhippleBicycleMoore("bike")
    bike.ground = FlatGround("ground")
    bike.rear_frame = RigidRearFrame("rear_frame")
    bike.front_frame = RigidFrontFrame("front_frame")
    bike.rear_wheel = KnifeEdgeWheel("rear_wheel")
    bike.front_wheel = KnifeEdgeWheel("front_wheel")
    bike.rear_tire = NonHolonomicTire("rear_tire")
    bike.front_tire = NonHolonomicTire("front_tire")
    bike.define_all()
    system = bike.to_system()
    system.apply_uniform_gravity(-sm.symbols("g") * bike.ground.get_normal(bike.ground.origin))
    system.q_ind = [*bike.q[:4], *bike.q[5:]]
    system.q_dep = [bike.q[4]]
    system.u_ind = [bike.u[3], *bike.u[5:7]]
    system.u_dep = [*bike.u[:3], bike.u[4], bike.u[7]]
    return bike, system


def plain_map(bike):
    """Functions of time and their derivatives as plain symbols: `bike_q4(t)` -> `q4`,
    `d/dt bike_u4(t)` -> `u4d`."""
    rep = {}
    t = sm.symbols("t")
    for x in bike.q:
        rep[x] = sm.Symbol(x.func.__name__.removeprefix("bike_"))
    for x in bike.u:
        name = x.func.__name__.removeprefix("bike_")
        rep[sm.Derivative(x, t)] = sm.Symbol(name + "d")
        rep[x] = sm.Symbol(name)
    return rep


def plain(e, rep):
    """`e` with the functions of time replaced (derivatives first)."""
    derivs = {k: v for k, v in rep.items() if isinstance(k, sm.Derivative)}
    return e.xreplace(derivs).xreplace({k: v for k, v in rep.items() if k not in derivs})


def by_kind(replacements, outputs) -> dict[str, int]:
    """`count_ops(visual=True)` summed over a CSE program, as a dict by kind."""
    total = sm.S(0)
    for e in [e for _, e in replacements] + list(outputs):
        total += sm.count_ops(e, visual=True)
    d = {}
    for term in sm.Add.make_args(total):
        if term == 0:
            continue
        c, s = term.as_coeff_Mul()
        d[str(s)] = int(c)
    return dict(sorted(d.items()))


def fmt_kinds(d: dict[str, int]) -> str:
    return ", ".join(f"{k.lower()} {n}" for k, n in d.items())


def param_only_ops(replacements, outputs, state: set) -> int:
    """Operations of a CSE program whose value reads no state symbol (directly or through
    earlier replacements)."""
    tainted = set(state)
    n = 0
    for s, e in replacements:
        if e.free_symbols & tainted:
            tainted.add(s)
        else:
            n += sm.count_ops(e)
    for e in outputs:
        if not (e.free_symbols & tainted):
            n += sm.count_ops(e)
    return n


def symbrim_side(seed: int, points: int) -> None:
    print(f"== SymBRiM {version('symbrim')} (SymPy {version('sympy')}, Python "
          f"{sys.version.split()[0]})")
    clear_cache()
    t0 = time.perf_counter()
    bike, system = create_whipple_bicycle_moore_brim()
    eoms = system.form_eoms(constraint_solver="CRAMER")
    t1 = time.perf_counter()
    km = system.eom_method
    raw = sm.count_ops(eoms)
    csed = sm.cse(eoms)
    published = sm.count_ops(csed)
    print(f"model built and eoms formed in {t1 - t0:.1f} s: eoms = fr + frstar, "
          f"{eoms.shape[0]} x {eoms.shape[1]}")
    print(f"count_ops(eoms)      = {raw}   (SymBRiM's operation_eoms; baseline 266664)")
    print(f"count_ops(cse(eoms)) = {published}   (SymBRiM's operation_eoms_csed; baseline 1909)")
    reps, red = csed
    print(f"  by kind, as SymPy counts it: {fmt_kinds(by_kind(reps, red))}")
    rep = plain_map(bike)
    peoms = plain(eoms, rep)
    preps, pred = sm.cse(peoms)
    inputs = sorted(map(str, peoms.free_symbols))
    state = {s for s in peoms.free_symbols if re.fullmatch(r"[qu]\d+d?", str(s))}
    n_plain = sm.count_ops((preps, pred))
    print(f"the same with the functions of time as plain symbols: {n_plain} ops "
          f"({fmt_kinds(by_kind(preps, pred))}); of them reading no state: "
          f"{param_only_ops(preps, pred, state)}")
    print(f"  inputs: {', '.join(s for s in inputs if s in map(str, state))} and "
          f"{len(inputs) - len(state)} parameters")
    mmf = [plain(km.mass_matrix, rep), plain(km.forcing, rep)]
    mreps, mred = sm.cse(mmf)
    print(f"SymPy's own mass_matrix (8 x 8: k_d and the acceleration constraints) and forcing (8) "
          f"of the same KanesMethod (dependent speeds as unknowns), plain symbols: count_ops(cse(...)) = "
          f"{sm.count_ops((mreps, mred))} ({fmt_kinds(by_kind(mreps, mred))})")

    # M3, f3 of the independent speeds.
    p = len(system.u_ind)
    u = list(km.u)
    uind, udep = u[:p], u[p:]
    kd, F = km._k_d, -km._f_d
    knh, fdnh, ars = km._k_nh, km._f_dnh, km._Ars
    assert all(x == 0 for x in km._f_nh), "velocity constraints not homogeneous in u"
    w = knh[:, p:].solve(fdnh, method="CRAMER")
    m3 = kd[:, :p] + kd[:, p:] * ars
    f3 = F + kd[:, p:] * w
    t2 = time.perf_counter()
    dep_defs = list(ars * sm.Matrix(uind))
    outs = [m3[0, 0], m3[0, 1], m3[0, 2], m3[1, 1], m3[1, 2], m3[2, 2], *f3]
    pdep = [plain(e, rep) for e in dep_defs]
    pouts = [plain(e, rep) for e in outs]
    dsyms = [rep[x] for x in udep]
    left = set().union(*(e.free_symbols for e in pouts)) - set(dsyms)
    udots = sorted(str(s) for s in left if str(s).endswith("d") and str(s)[0] == "u")
    assert not udots, f"speed derivatives left in M3, f3: {udots}"
    # The program: u_dep = Ars u_ind (five expressions), then M3 and f3 reading them.
    sreps, sred = sm.cse(pdep + pouts)
    t3 = time.perf_counter()
    # The dependent speeds are values of the program: give them their names.
    sreps = list(sreps) + list(zip(dsyms, sred[: len(dsyms)]))
    sred = sred[len(dsyms):]
    n_m3f3 = sm.count_ops((sreps, sred))
    st = {s for s in left | set(dsyms) if re.fullmatch(r"u\d+|q\d+", str(s))}
    used_q = sorted(str(s) for s in left if re.fullmatch(r"q\d+", str(s)))
    used_u = sorted(str(s) for s in left if re.fullmatch(r"u\d+", str(s)))
    print(f"M3 (3 x 3, 6 entries) and f3 (3) of u4, u6, u7, dependent speeds eliminated, "
          f"built from SymBRiM's KanesMethod in {t2 - t1:.1f} s, CSE {t3 - t2:.1f} s:")
    print(f"  count_ops(cse(program)) = {n_m3f3} ops ({fmt_kinds(by_kind(sreps, sred))}); "
          f"of them reading no state: {param_only_ops(sreps, sred, st)}")
    print(f"  inputs: {', '.join(used_q + used_u)} and {len(left) - len(used_q) - len(used_u)} "
          f"parameters")
    check_m3f3(km, bike, rep, pdep, pouts, dsyms, uind, seed, points)


def check_m3f3(km, bike, rep, pdep, pouts, dsyms, uind, seed, points) -> None:
    """M3 symmetric and M3 u_ind' = f3 against SymPy's full 8 x 8 system, at seeded points."""
    mm = plain(km.mass_matrix, rep)
    fo = plain(km.forcing, rep)
    qs = [rep[x] for x in bike.q]
    us = [rep[x] for x in km.u]
    ps = sorted((s for s in mm.free_symbols | fo.free_symbols | set().union(
        *(e.free_symbols for e in pouts)) if s not in set(qs) | set(us)), key=str)
    args = (qs, us, ps)
    f_full = sm.lambdify(args, [mm, fo], cse=True)
    f_dep = sm.lambdify((qs, [rep[x] for x in uind], ps), pdep, cse=True)
    f_m3 = sm.lambdify(args, pouts, cse=True)
    rng = np.random.default_rng(seed)
    worst_sym = worst_eq = worst_idle = 0.0
    idle = [i for i, s in enumerate(qs) if str(s) in ("q1", "q2", "q3", "q6", "q8")]
    for _ in range(points):
        q = rng.uniform(-0.5, 0.5, len(qs))
        ui = rng.uniform(-2.0, 2.0, len(uind))
        par = rng.uniform(0.2, 1.5, len(ps))
        ud = np.array(f_dep(q, ui, par), dtype=float)
        uu = np.concatenate([ui, ud])
        m, f = (np.array(a, dtype=float) for a in f_full(q, uu, par))
        acc = np.linalg.solve(m, f.ravel())
        v = np.array(f_m3(q, uu, par), dtype=float)
        m3 = np.array([[v[0], v[1], v[2]], [v[1], v[3], v[4]], [v[2], v[4], v[5]]])
        # The full 3 x 8 rows give the lower triangle independently: M3 = k_d [I; Ars].
        res = m3 @ acc[:3] - v[6:]
        worst_eq = max(worst_eq, np.max(np.abs(res)) / (np.max(np.abs(v[6:])) + 1e-300))
        # Yaw and the wheels' angles: read by the expressions, but the values do not depend
        # on them.
        q2 = q.copy()
        q2[idle] = rng.uniform(-3.0, 3.0, len(idle))
        ud2 = np.array(f_dep(q2, ui, par), dtype=float)
        v2 = np.array(f_m3(q2, np.concatenate([ui, ud2]), par), dtype=float)
        worst_idle = max(worst_idle, np.max(np.abs(v2 - v)) / np.max(np.abs(v)))
    # Symmetry from the unreduced matrix (the program keeps the upper triangle only).
    kd = plain(km._k_d, rep)
    m3full = kd[:, :3] + kd[:, 3:] * plain(km._Ars, rep)
    f_sym = sm.lambdify((qs, ps), m3full, cse=True)
    for _ in range(points):
        q = rng.uniform(-0.5, 0.5, len(qs))
        par = rng.uniform(0.2, 1.5, len(ps))
        a = np.array(f_sym(q, par), dtype=float)
        worst_sym = max(worst_sym, np.max(np.abs(a - a.T)) / np.max(np.abs(a)))
    print(f"  check at {points} seeded points (seed {seed}): |M3 - M3^T| / max|M3| <= "
          f"{worst_sym:.1e}; |M3 u_ind' - f3| / max|f3| <= {worst_eq:.1e} with u' from "
          f"SymPy's 8 x 8 mass_matrix u' = forcing; changing the position q1, q2, yaw q3 "
          f"and the wheel angles q6, q8 changes M3, f3 by <= {worst_idle:.1e} of max|M3, f3|")
    assert worst_sym < 1e-9 and worst_eq < 1e-9, "M3, f3 do not match SymPy's full system"
    assert worst_idle < 1e-9, "M3, f3 depend on yaw or the wheel angles"


def parse_ir(path: Path):
    """(params, inputs, lets {name: (op, args)} in order, outputs {name: value})."""
    params, inputs, lets, outputs = [], [], {}, {}
    for line in path.read_text().splitlines():
        if line.startswith("#") or not line.strip():
            continue
        w = line.split()
        if w[0] == "param":
            params.append(w[1])
        elif w[0] == "input":
            inputs.append(w[1])
        elif w[0] == "let":
            lets[w[1]] = (w[3], w[4:])
        elif w[0] == "output":
            outputs[w[1]] = w[3]
    return params, inputs, lets, outputs


def cone(lets, roots):
    """The `let`s the roots depend on."""
    seen, stack = set(), list(roots)
    while stack:
        v = stack.pop()
        if v in seen or v not in lets:
            continue
        seen.add(v)
        op, args = lets[v]
        if op != "const":
            stack.extend(args)
    return seen


def ours_side() -> None:
    params, inputs, lets, outputs = parse_ir(IR)
    ops = {k: v for k, v in lets.items() if v[0] != "const"}
    print(f"== ours: {IR.relative_to(ROOT)} ({len(params)} parameters, inputs "
          f"{', '.join(inputs)})")
    print(f"whole program: {len(ops)} ops, {len(outputs)} outputs")
    want = [n for n in outputs if n.startswith(("m3_", "f3_"))]
    for label, names in [("M3 + f3 (m3_*, f3_*)", want),
                         ("M3 alone (m3_*)", [n for n in want if n.startswith("m3_")]),
                         ("f3 alone (f3_*)", [n for n in want if n.startswith("f3_")])]:
        c = cone(lets, [outputs[n] for n in names]) & set(ops)
        kinds = {}
        for v in c:
            kinds[ops[v][0]] = kinds.get(ops[v][0], 0) + 1
        # Parameter-only: instructions that read no input, directly or indirectly.
        tainted = set(inputs)
        for v, (op, args) in lets.items():
            if any(a in tainted for a in args):
                tainted.add(v)
        param_only = sum(1 for v in c if v not in tainted)
        print(f"{label}: {len(c)} ops ({', '.join(f'{k} {n}' for k, n in sorted(kinds.items()))})"
              f"; of them reading no state: {param_only}")
        if names is want:
            n_sympy = sympy_count(lets, c)
            print(f"  the same instructions counted by sympy.count_ops one by one: {n_sympy}")


def sympy_count(lets, names) -> int:
    """`sympy.count_ops` of each instruction with its operands as symbols (constants as
    numbers): one per instruction unless SymPy folds it."""
    sym = {}

    def arg(a):
        if a in lets and lets[a][0] == "const":
            return sm.Float(lets[a][1][0]) if "." in lets[a][1][0] else sm.Integer(lets[a][1][0])
        return sym.setdefault(a, sm.Symbol(a))

    total = 0
    for v in names:
        op, args = lets[v]
        a = [arg(x) for x in args]
        e = {
            "add": lambda: sm.Add(a[0], a[1]),
            "sub": lambda: a[0] - a[1],
            "mul": lambda: sm.Mul(a[0], a[1]),
            "div": lambda: a[0] / a[1],
            "neg": lambda: -a[0],
            "sin": lambda: sm.sin(a[0]),
            "cos": lambda: sm.cos(a[0]),
            "sqrt": lambda: sm.sqrt(a[0]),
            "powi": lambda: a[0] ** int(args[1]),
        }[op]()
        total += sm.count_ops(e)
    return total


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seed", type=int, default=34)
    ap.add_argument("--points", type=int, default=20)
    ap.add_argument("--ours-only", action="store_true", help="skip SymBRiM (no SymPy work)")
    a = ap.parse_args()
    if not a.ours_only:
        symbrim_side(a.seed, a.points)
    ours_side()


if __name__ == "__main__":
    main()
