"""CasADi on PyDy's model of the nonlinear Whipple bicycle, side by side with ours (issues 35
and 36, item 4). Run by scripts/casadi-peer, which installs the pinned peers.

1. Derives SymPy's Kane model of the bicycle (scripts/pydy_whipple.py: PyDy's example, M 6 x 6
   and F 6 in Moore's coordinates) and translates M and F into CasADi SX ([`to_casadi`]: SymPy's
   `cse`, then each replacement and output rebuilt from CasADi's operations), the 26 parameters
   an input `p` as PyDy's generated code takes them. The whole right-hand side of PyDy's state
   x = (q3, q4, q7, q5, u4, u6, u7, u3, u5, u8) is one CasADi Function: q' = (u3, u4, u7, u5)
   and u' = `casadi.solve(M, F)` on SX (CasADi's symbolic solve: a QR factorisation without
   pivoting after a structural permutation, for a 6 x 6). Its state Jacobian is CasADi's
   `jacobian(xd, x)` (algorithmic differentiation of the same graph).
2. Generates C for both with CasADi's `CodeGenerator`, compiles each with a timing `main` like
   scripts/pydy_c_peer.py's (the call `noinline`, compiler barriers, the smallest of five means
   over slices of at least `--min-time / 5` s: scripts/c_timing.py) at `cc -O2`, and checks them at the bench's state
   (lean 0.1, steer 0.05, lean rate 0.2, steer rate -0.1, rear wheel rate -5/0.3, the pitch
   from the constraint): the right-hand side against `carvallo accel --state` on the nine
   derivatives both states share, the Jacobian against CasADi's own evaluation and against
   central differences of the right-hand side.
3. Times them, interleaved over `--rounds` rounds with `carvallo bench --quick --json` (its
   rows `bicycle (c) state -> state derivative`, `whole` and `kernel only`, and our state
   Jacobian where the bench has a row whose name contains `state jacobian`; otherwise that
   column says so).
4. Integrates with CasADi's integrators on the same right-hand side (CasADi's SX virtual
   machine, as `casadi.integrator` runs an SX problem, the Jacobian by AD): CVODES with BDF and
   with Adams at rtol 1e-3 ... 1e-13, atol = 1e-3 rtol (the tolerances of
   scripts/pydy_scipy_peer.py and of `carvallo bench --only simulation`), and CasADi's
   fixed-step RK4 (`rk`) at the bench's RK4 steps, from the state of pydy_scipy_peer (4.6 m/s,
   lean 0.05 rad) for 5 s. The lean error at 5 s against the same reference (ours, DOP853 at
   rtol 1e-14, atol 1e-17), wall times (the smallest of `--repeats` calls), right-hand side
   and Jacobian evaluations as CasADi's statistics count them; then ours (`carvallo
   simulate`, wall times from `carvallo bench --only simulation --json`) and the time ratios
   at equal error on the work-precision fronts, as pydy_scipy_peer prints them for SciPy.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import sympy as sm

sys.path.insert(0, str(Path(__file__).resolve().parent))
import c_timing as ct  # noqa: E402
import pydy_c_peer as cpeer  # noqa: E402
import pydy_scipy_peer as speer  # noqa: E402
import pydy_whipple as pw  # noqa: E402

# The bench's row of our Jacobian, when it has one (matched case-insensitively in its name).
OUR_JACOBIAN = "state jacobian"

CVODES = [("cvodes bdf", "bdf"), ("cvodes adams", "adams")]

DRIVER = r"""
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define CAT2(a, b) a##b
#define CAT(a, b) CAT2(a, b)

@NOW@

__attribute__((noinline)) static int call(const casadi_real **arg, casadi_real **res,
                                          casadi_int *iw, casadi_real *w) {
    return FN(arg, res, iw, w, 0);
}

/* stdin: the 10 states, the 26 constants, then the minimum seconds of the timing.
   stdout: the output's nonzeros (CasADi's column-major order), then "ns" and the nanoseconds
   per call. */
int main(void) {
    casadi_int sz_arg, sz_res, sz_iw, sz_w;
    CAT(FN, _work)(&sz_arg, &sz_res, &sz_iw, &sz_w);
    const casadi_int *sp = CAT(FN, _sparsity_out)(0);
    /* CasADi's compressed column storage, or (nrow, ncol, 1) for a dense output. */
    casadi_int ncol = sp[1], nnz = sp[2] == 1 ? sp[0] * ncol : sp[2 + ncol];
    double x[10], c[26], min_time;
    for (int i = 0; i < 10; i++) if (scanf("%lf", &x[i]) != 1) return 2;
    for (int i = 0; i < 26; i++) if (scanf("%lf", &c[i]) != 1) return 2;
    if (scanf("%lf", &min_time) != 1) return 2;
    const casadi_real **arg = malloc(sizeof(casadi_real *) * (sz_arg > 2 ? sz_arg : 2));
    casadi_real **res = malloc(sizeof(casadi_real *) * (sz_res > 1 ? sz_res : 1));
    casadi_int *iw = malloc(sizeof(casadi_int) * (sz_iw > 0 ? sz_iw : 1));
    casadi_real *w = malloc(sizeof(casadi_real) * (sz_w > 0 ? sz_w : 1));
    casadi_real *out = malloc(sizeof(casadi_real) * nnz);
    arg[0] = x;
    arg[1] = c;
    res[0] = out;
    if (call(arg, res, iw, w)) return 3;
    for (casadi_int k = 0; k < nnz; k++) printf("%.17g\n", out[k]);
@TIMING_LOOP@
    printf("ns %.3f\n", best);
    return 0;
}
""".replace("@NOW@", ct.NOW).replace(
    "@TIMING_LOOP@", ct.timing_loop("call(arg, res, iw, w);", ["x", "c", "out"]))


def to_casadi(exprs, symbols: dict):
    """The SymPy expressions `exprs` as CasADi SX: SymPy's `cse` first, then every replacement
    and output rebuilt from CasADi's operations, `symbols` mapping each free SymPy symbol to
    its SX. Numbers become doubles; sums, products, powers (square roots and reciprocals
    included), sin, cos and tan are translated; anything else is an error naming it."""
    import casadi as ca

    funcs = {sm.sin: ca.sin, sm.cos: ca.cos, sm.tan: ca.tan}
    known = dict(symbols)

    def conv(e):
        if e in known:
            return known[e]
        if e.is_Symbol:
            raise ValueError(f"unknown symbol `{e}` in the expressions to translate")
        if e.is_Number:
            return float(e)
        if e.is_Add:
            out = conv(e.args[0])
            for a in e.args[1:]:
                out = out + conv(a)
        elif e.is_Mul:
            out = conv(e.args[0])
            for a in e.args[1:]:
                out = out * conv(a)
        elif e.is_Pow:
            base, ex = conv(e.args[0]), e.args[1]
            if ex == -1:
                out = 1.0 / base
            elif ex == sm.Rational(1, 2):
                out = ca.sqrt(base)
            elif ex == 2:
                out = base * base
            elif ex.is_Number:
                out = base ** float(ex)
            else:
                out = base ** conv(ex)
        elif e.func in funcs:
            out = funcs[e.func](conv(e.args[0]))
        else:
            raise ValueError(f"no CasADi translation of `{e.func.__name__}` in `{e}`")
        known[e] = out
        return out

    replacements, reduced = sm.cse(list(exprs))
    for s, e in replacements:
        known[s] = conv(e)
    return [conv(e) for e in reduced]


def qdot_indices(model) -> list[int]:
    """For each coordinate, the index in u of its rate (PyDy's kinematical equations q' = u)."""
    out = []
    for i, e in enumerate(model.qdot):
        j = next((k for k, u in enumerate(model.u) if e == u), None)
        if j is None:
            raise ValueError(f"the kinematical equation q{i}' = {e} is not a speed")
        out.append(j)
    return out


def build(model):
    """(x, p, xd): CasADi's SX state, parameters and whole right-hand side of `model`."""
    import casadi as ca

    qs = [sm.Symbol(f.func.__name__) for f in model.q]
    us = [sm.Symbol(f.func.__name__) for f in model.u]
    x = ca.SX.sym("x", len(qs) + len(us))
    p = ca.SX.sym("p", len(model.constants))
    symbols = {s: x[k] for k, s in enumerate(qs + us)}
    symbols.update({s: p[k] for k, s in enumerate(model.constants)})
    n = len(us)
    mass = pw.to_symbols(model, model.mass_matrix)
    forcing = pw.to_symbols(model, model.forcing)
    flat = to_casadi(list(mass) + list(forcing), symbols)
    m = ca.SX(n, n)
    for i in range(n):
        for j in range(n):
            m[i, j] = flat[i * n + j]
    f = ca.vertcat(*flat[n * n:])
    ud = ca.solve(m, f)
    qd = ca.vertcat(*[x[len(qs) + j] for j in qdot_indices(model)])
    return x, p, ca.vertcat(qd, ud)


def run_driver(exe: Path, x, consts, min_time: float):
    text = "\n".join(repr(float(v)) for v in list(x) + list(consts) + [min_time]) + "\n"
    out = subprocess.run([str(exe)], input=text, capture_output=True, text=True, check=True)
    lines = out.stdout.split()
    if len(lines) < 2 or lines[-2] != "ns":
        raise SystemExit(f"error: unexpected output of {exe}: {out.stdout[-200:]}")
    return np.array([float(v) for v in lines[:-2]]), float(lines[-1])


def our_rows(carvallo: str) -> dict[str, tuple[float, int]]:
    """Our rows from `carvallo bench --quick --json`: `whole`, `kernel only` and, when the
    bench has one, `jacobian` (its row named like OUR_JACOBIAN)."""
    out = subprocess.run([carvallo, "bench", "--quick", "--json"], capture_output=True,
                         text=True, check=True)
    got = {}
    for r in json.loads(out.stdout)["rows"]:
        if r["ns"] is None:
            continue
        if r["section"] == "scenes" and r["name"] == cpeer.OURS_RHS_NAME:
            got[r["method"]] = (float(r["ns"]), r["ops"])
        elif OUR_JACOBIAN in r["name"].lower() and "jacobian" not in got:
            got["jacobian"] = (float(r["ns"]), r["ops"])
    missing = [m for _, m in cpeer.OURS_RHS if m not in got]
    if missing:
        raise SystemExit(f"error: `carvallo bench --quick --json` has no row {missing} for "
                         f"{cpeer.OURS_RHS_NAME!r}")
    return got


def jacobian_column(best: dict, label: str) -> str:
    """The text of our Jacobian's cell: its time, or why there is none."""
    if label in best:
        return f"{best[label]:.0f} ns"
    return "not measured (no such bench row)"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rounds", type=int, default=5, help="interleaved timing rounds (default 5)")
    ap.add_argument("--min-time", type=float, default=0.002,
                    help="seconds of each C timing (default 0.002, as `carvallo bench --quick`)")
    ap.add_argument("--repeats", type=int, default=3,
                    help="timed runs per integration (default 3)")
    ap.add_argument("--bench-runs", type=int, default=1,
                    help="runs of `carvallo bench --only simulation` for our wall times "
                         "(default 1; about 2 min each)")
    ap.add_argument("--no-integrators", action="store_true",
                    help="only the generated C of the right-hand side and its Jacobian")
    ap.add_argument("--carvallo", default=os.environ.get("CARVALLO_BIN", "target/release/carvallo"))
    ap.add_argument("--cc", default=os.environ.get("CC", "cc"))
    ap.add_argument("--keep", type=Path, help="write the generated C into this directory")
    a = ap.parse_args()
    for name in ("rounds", "repeats", "bench_runs"):
        if getattr(a, name) < 1:
            ap.error(f"invalid --{name.replace('_', '-')} {getattr(a, name)}: at least 1")
    if not a.min_time > 0 or not math.isfinite(a.min_time):
        ap.error(f"invalid --min-time {a.min_time}: a positive number of seconds")
    if shutil.which(a.cc) is None:
        ap.error(f"no C compiler `{a.cc}` (--cc or $CC)")

    import casadi as ca
    import pydy

    cc_version = subprocess.run([a.cc, "--version"], capture_output=True, text=True).stdout
    print(f"== CasADi {ca.__version__}, PyDy {pydy.__version__}, SymPy {sm.__version__}, "
          f"NumPy {np.__version__}, {cc_version.splitlines()[0]}, "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    model = pw.derive()
    t0 = time.perf_counter()
    x, p, xd = build(model)
    rhs = ca.Function("rhs", [x, p], [xd], ["x", "p"], ["xd"])
    jac = ca.Function("rhs_jacobian", [x, p], [ca.jacobian(xd, x)], ["x", "p"], ["jac"])
    print(f"Kane's equations derived in {model.seconds:.1f} s; M and F translated to CasADi SX, "
          f"the rhs (casadi.solve on SX) and its Jacobian (casadi.jacobian) built in "
          f"{time.perf_counter() - t0:.1f} s: {rhs.n_instructions()} and "
          f"{jac.n_instructions()} SX instructions, Jacobian nonzeros "
          f"{jac.sparsity_out(0).nnz()} of {xd.numel() * x.numel()}")

    num = pw.Numeric(model)
    consts = num.const_array
    xt = num.state(0.0, 0.1, 0.05, 0.2, -0.1, -5.0 / 0.3)
    work = Path(tempfile.mkdtemp(prefix="casadi-peer-"))
    try:
        gen = ca.CodeGenerator("casadi_whipple.c", {"with_header": False})
        gen.add(rhs)
        gen.add(jac)
        gen.generate(str(work) + os.sep)
        if a.keep:
            a.keep.mkdir(parents=True, exist_ok=True)
            shutil.copy(work / "casadi_whipple.c", a.keep / "casadi_whipple.c")
        exes = {}
        for fn in ("rhs", "rhs_jacobian"):
            src = work / f"driver_{fn}.c"
            src.write_text('#include "casadi_whipple.c"\n' + DRIVER.replace("FN", fn))
            exe = work / f"driver_{fn}"
            t0 = time.perf_counter()
            subprocess.run([a.cc, "-O2", "-o", str(exe), str(src), "-lm"], check=True,
                           cwd=work)
            print(f"CasADi's generated C for `{fn}`: `{a.cc} -O2` in "
                  f"{time.perf_counter() - t0:.1f} s")
            exes[fn] = exe

        # Checks at the bench's state.
        ours_state = [0.0, 0.0, 0.0, 0.1, 0.05, 0.0, 0.0, 0.2, -0.1, -5.0 / 0.3,
                      float(xt[3]) - model.lam]
        ours_rate = cpeer.carvallo_state_rate(a.carvallo, ours_state)
        got, _ = run_driver(exes["rhs"], xt, consts, 1e-4)
        vm = np.array(rhs(xt, consts)).ravel()
        pairs = cpeer.shared_derivatives(model, xt, got, ours_rate["derivative"])
        vs_ours = max(abs(g - o) / max(abs(o), 1e-300) for _, g, o in pairs)
        vs_vm = float(np.max(np.abs(got - vm) / np.maximum(np.abs(vm), 1e-300)))
        print(f"\n== check at the bench's state: CasADi's C rhs against `carvallo accel "
              f"--state`: worst relative difference {vs_ours:.1e} over the {len(pairs)} shared "
              f"derivatives; against CasADi's own evaluation {vs_vm:.1e}")
        jgot, _ = run_driver(exes["rhs_jacobian"], xt, consts, 1e-4)
        jvm = np.array(jac(xt, consts).nonzeros())
        jdense = np.array(jac(xt, consts).full())
        step = 1e-6
        fd = np.zeros_like(jdense)
        for k in range(len(xt)):
            hi, lo = xt.copy(), xt.copy()
            h = step * max(1.0, abs(xt[k]))
            hi[k] += h
            lo[k] -= h
            diff = np.array(rhs(hi, consts)).ravel() - np.array(rhs(lo, consts)).ravel()
            fd[:, k] = diff / (2 * h)
        scale = np.max(np.abs(jdense))
        vs_fd = float(np.max(np.abs(jdense - fd)) / scale)
        jc = float(np.max(np.abs(jgot - jvm)) / scale)
        print(f"CasADi's C Jacobian against its own evaluation: {jc:.1e}; CasADi's Jacobian "
              f"against central differences (step 1e-6) of the rhs: {vs_fd:.1e} (relative to "
              f"its largest entry {scale:.1e})")
        if max(vs_ours, vs_vm, jc) > 1e-10 or vs_fd > 1e-6:
            print("error: CasADi's right-hand side or Jacobian disagrees", file=sys.stderr)
            return 1

        print(f"\n== timing, {a.rounds} interleaved rounds (CasADi C rhs, CasADi C Jacobian, "
              f"`{a.carvallo} bench --quick --json`); minimum over the rounds")
        labels = {"rhs": "CasADi's C rhs (solve on SX), -O2",
                  "rhs_jacobian": "CasADi's C state Jacobian, -O2"}
        best: dict[str, float] = {}
        ours_ops: dict[str, int] = {}
        for r in range(a.rounds):
            line = []
            for fn, exe in exes.items():
                ns = run_driver(exe, xt, consts, a.min_time)[1]
                best[labels[fn]] = min(best.get(labels[fn], math.inf), ns)
                line.append(f"{ns:.0f}")
            got_rows = our_rows(a.carvallo)
            for label, method in cpeer.OURS_RHS + [("ours, state Jacobian", "jacobian")]:
                if method in got_rows:
                    ns, ops = got_rows[method]
                    best[label] = min(best.get(label, math.inf), ns)
                    ours_ops[label] = ops
                    line.append(f"{ns:.0f}")
            print(f"round {r + 1}: " + " ".join(line) + " ns", flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)

    whole = best[cpeer.OURS_RHS[0][0]]
    print("\n| nonlinear Whipple bicycle | CasADi C -O2 | ours | ours / CasADi |")
    print("|---|---|---|---|")
    print(f"| state -> state derivative | {best[labels['rhs']]:.0f} ns "
          f"({rhs.n_instructions()} SX instructions) | {whole:.0f} ns (StateRate::eval) | "
          f"{whole / best[labels['rhs']]:.2f} |")
    # Our Jacobian's column: filled when `carvallo bench` has a row named like OUR_JACOBIAN.
    jl, cj = "ours, state Jacobian", best[labels["rhs_jacobian"]]
    ratio = f"{best[jl] / cj:.2f}" if jl in best else "-"
    print(f"| state Jacobian (10 x 10 for CasADi; ours 11 x 11) | {cj:.0f} ns "
          f"({jac.n_instructions()} SX instructions) | {jacobian_column(best, jl)} | {ratio} |")
    print(f"| our kernel only (M3, f3, dependent rates) | | "
          f"{best[cpeer.OURS_RHS[1][0]]:.0f} ns | |")

    if a.no_integrators:
        return 0
    return integrators(a, model, num, x, p, xd)


def integrators(a, model, num, x, p, xd) -> int:
    """Section 4 of the module docs."""
    import casadi as ca

    consts = num.const_array
    x0 = num.state(0.0, speer.LEAN0, 0.0, 0.0, 0.0, -speer.SPEED / model.values["rr"])
    lean = [f.func.__name__ for f in model.q].index("q4")
    dae = {"x": x, "p": p, "ode": xd}
    ref_run = speer.simulate(a.carvallo, "--method", "dop853", "--rtol", "1e-14", "--atol",
                             "1e-17")
    ref = ref_run["lean"][-1]
    print(f"\n== {speer.PROBLEM}: reference lean(5 s) = {ref!r} rad (carvallo dop853 rtol "
          f"1e-14 atol 1e-17)")

    def timed(integ):
        out, best = None, math.inf
        for _ in range(a.repeats):
            s = time.perf_counter()
            out = integ(x0=x0, p=consts)
            best = min(best, time.perf_counter() - s)
        return np.array(out["xf"]).ravel(), best

    rows = []  # (method, rtol or step, evals, jacobians, steps, error, seconds, failure)
    for label, lmm in CVODES:
        for rtol in speer.TOLERANCES:
            opts = {"reltol": rtol, "abstol": 1e-3 * rtol, "linear_multistep_method": lmm,
                    "max_num_steps": 1_000_000}
            integ = ca.integrator("I", "cvodes", dae, 0.0, speer.DURATION, opts)
            try:
                xf, sec = timed(integ)
                st = integ.stats()
                err = abs(xf[lean] - ref)
                rows.append((label, rtol, st["nfevals"], st["n_call_jacF"], st["nsteps"], err,
                             sec, None))
            except RuntimeError as e:
                rows.append((label, rtol, 0, 0, 0, math.nan, math.nan, str(e).splitlines()[0]))
            r = rows[-1]
            print(f"  {label} rtol {rtol:.0e}: {r[2]} rhs evaluations, {r[3]} Jacobians, "
                  f"{r[4]} steps, error {r[5]:.1e}, {r[6] * 1e3:.2f} ms"
                  + (f" ({r[7]})" if r[7] else ""), flush=True)
    for h in speer.RK4_STEPS:
        n = round(speer.DURATION / h)
        integ = ca.integrator("I", "rk", dae, 0.0, speer.DURATION,
                              {"number_of_finite_elements": n})
        xf, sec = timed(integ)
        rows.append(("casadi rk4", h, 4 * n, 0, n, abs(xf[lean] - ref), sec, None))
        print(f"  casadi rk (RK4) step {h:.1e}: error {rows[-1][5]:.1e}, {sec * 1e3:.2f} ms",
              flush=True)

    print("\n== ours: `carvallo simulate`; wall times from `carvallo bench --only simulation "
          "--json`")
    bench_runs = [speer.bench_times(a.carvallo)[0] for _ in range(a.bench_runs)]

    def our_time(method, v):
        found = [speer.lookup(b, method, v)[0] for b in bench_runs]
        return min((t for t in found if t == t), default=math.nan)

    ours = []
    for method in speer.OUR_METHODS:
        for rtol in speer.TOLERANCES:
            s = speer.simulate(a.carvallo, "--method", method, "--rtol", repr(rtol))
            ours.append((method, rtol, s["rhs_evaluations"], 0, s["steps"],
                         abs(s["lean"][-1] - ref), our_time(method, rtol), None))
    for h in speer.RK4_STEPS:
        s = speer.simulate(a.carvallo, "--method", "rk4", "--step", repr(h))
        ours.append(("rk4", h, s["rhs_evaluations"], 0, s["steps"], abs(s["lean"][-1] - ref),
                     our_time("rk4", h), None))

    print("\n| who | method | rtol (RK4: step) | RHS evals | Jacobians | steps | lean error "
          "| wall time |")
    print("|---|---|---|---|---|---|---|---|")
    for who, group in [("casadi", rows), ("carvallo", ours)]:
        for method, tol, evals, jacs, steps, err, sec, fail in group:
            wall = f"{sec * 1e3:.3f} ms" if sec == sec else "-"
            note = f" ({fail})" if fail else ""
            print(f"| {who} | {method} | {tol:.1e} | {evals} | {jacs} | {steps} | "
                  f"{err:.1e}{note} | {wall} |")

    peer_methods = [label for label, _ in CVODES] + ["casadi rk4"]
    ok = [r for r in rows if r[7] is None and r[5] == r[5]]
    fronts = {m: speer.pareto([(r[5], r[6]) for r in ok if r[0] == m]) for m in peer_methods}
    fronts["best"] = speer.pareto([(r[5], r[6]) for r in ok])
    floor = min(e for e, _ in fronts["best"])
    print("\n== wall time of CasADi / carvallo at equal lean error (each CasADi method's "
          "work-precision front, log time interpolated against log error; `best` the front of "
          f"all three; `below` where CasADi reaches no such error, its smallest {floor:.1e})")
    print("| carvallo | rtol (RK4: step) | lean error | carvallo | "
          + " | ".join(peer_methods) + " | best |")
    print("|---|---|---|---|" + "---|" * (len(peer_methods) + 1))
    speedups = []
    for method, tol, evals, jacs, steps, err, sec, _ in ours:
        cells = []
        for pm in peer_methods + ["best"]:
            front = fronts[pm]
            t_peer = speer.interp_loglog([e for e, _ in front], [t for _, t in front], err)
            if not sec == sec or not front:
                cells.append("-")
            elif t_peer is not None:
                cells.append(f"{t_peer / sec:.0f}x")
                if pm == "best":
                    speedups.append((t_peer / sec, method, tol))
            elif err < min(e for e, _ in front):
                cells.append("below")
            else:
                cells.append("-")
        label = f"{tol:.2e}" if method == "rk4" else f"{tol:.0e}"
        print(f"| {method} | {label} | {err:.1e} | {sec * 1e6:.0f} us | " + " | ".join(cells)
              + " |")
    for m in speer.OUR_METHODS + ["rk4"]:
        got = [s for s in speedups if s[1] == m]
        if got:
            print(f"carvallo {m}: {min(got)[0]:.0f}x to {max(got)[0]:.0f}x faster than CasADi's "
                  f"best at equal error over {len(got)} errors")
    return 0


if __name__ == "__main__":
    sys.exit(main())
