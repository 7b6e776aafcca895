"""SciPy's solve_ivp on PyDy's generated right-hand side of the nonlinear Whipple bicycle, side
by side with `carvallo simulate` (issue 21, item 3). Run by scripts/pydy-scipy-peer, which
installs the pinned peers.

1. Derives SymPy's Kane model (scripts/pydy_whipple.py) and generates its right-hand side with
   PyDy's `CythonODEFunctionGenerator` (CSE, the Cython backend, PyDy's default NumPy solve of
   the 6 x 6 `M u' = F` per call). Checks it at Basu-Mandal et al.'s (2007) Table 1 state
   against the table and `carvallo accel --basu-mandal`.
2. Integrates from the state of our work-precision section (`carvallo bench --only simulation`,
   crates/carvallo-cli/src/bench/simulation.rs): the benchmark bicycle at 4.6 m/s (rear wheel
   rate -4.6/rR), lean 0.05 rad, steer and every other rate zero, for 5 s; PyDy's state also
   holds the pitch (from the holonomic constraint) and the dependent speeds (from the velocity
   constraints). SciPy's RK45, DOP853 and LSODA at rtol 1e-3 ... 1e-13, atol = 1e-3 rtol.
3. Error: |lean(5 s) - reference| with the reference ours, DOP853 at rtol 1e-14, atol 1e-17,
   cross-checked against the peer's own most accurate run and our DOPRI5 at 1e-14 (both
   agreements printed). Wall time: the smallest over `--repeats` runs of `solve_ivp` (no
   output grid). RHS evaluations: every call of the right-hand side (counted by a wrapper;
   LSODA's finite-difference Jacobians included). The pitch constraint's residual: the
   largest |front contact height| over the accepted steps (PyDy integrates the pitch, so it
   drifts; ours solves it at every evaluation).
4. Ours: `carvallo simulate --method dop853|dopri5 --rtol R --json` (final lean,
   rhs_evaluations, max_contact_residual) and RK4 at the bench's steps; wall times from
   `carvallo bench --only simulation --json` (its rows of the same problem, smallest of the
   runs before and after the peer's).
5. Prints the table, the time ratios at equal error (the peer's log time interpolated against
   its log error at each of our errors) and the targets of issue 21.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import time
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import pydy_whipple as pw  # noqa: E402

SPEED, LEAN0, DURATION = 4.6, 0.05, 5.0
PROBLEM = f"bicycle {SPEED} m/s, lean0 {LEAN0}, {DURATION:g} s"
TOLERANCES = [10.0 ** -k for k in range(3, 14)]
PEER_METHODS = ["RK45", "DOP853", "LSODA"]
OUR_METHODS = ["dop853", "dopri5"]
# The bench's RK4 steps: 0.01 s halved 0..6 times.
RK4_STEPS = [0.01 / 2 ** k for k in range(7)]


def interp_loglog(x_points, y_points, x):
    """y at x by linear interpolation of log y against log x through the points sorted by x;
    None outside their range (no extrapolation) or when fewer than two points are positive."""
    pts = sorted((math.log(a), math.log(b)) for a, b in zip(x_points, y_points)
                 if a > 0 and b > 0 and math.isfinite(a) and math.isfinite(b))
    if len(pts) < 2 or not x > 0:
        return None
    lx = math.log(x)
    if lx < pts[0][0] or lx > pts[-1][0]:
        return None
    xs, ys = zip(*pts)
    return math.exp(float(np.interp(lx, xs, ys)))


def pareto(points):
    """The (error, time) points no other point beats in both, sorted by error (the
    work-precision front); non-finite errors dropped."""
    pts = sorted((e, t) for e, t in points if e == e and e > 0 and t == t)
    front = []
    for e, t in pts:
        if not front or t < front[-1][1]:
            front.append((e, t))
    return front


def speedup_summary(speedups, unreached) -> list[str]:
    """The lines of the 20x target: `speedups` holds (peer time / ours, our method, rtol) at
    equal error, `unreached` (our method, rtol) of our runs more accurate than any peer run."""
    lines = []
    for label, pick in [("DOP853, carvallo's faster method", "dop853"), ("DOPRI5", "dopri5")]:
        got = [x for x in speedups if x[1] == pick]
        if not got:
            continue
        met = [x for x in got if x[0] >= 20]
        lines.append(
            f"carvallo >= 20x faster than SciPy + PyDy (the front of its three methods) at "
            f"equal error, carvallo {label}: {min(got)[0]:.0f}x to {max(got)[0]:.0f}x over "
            f"{len(got)} errors, >= 20x at {len(met)} -> "
            + ("met" if len(met) == len(got) else "NOT met")
            + f"; {sum(1 for u in unreached if u[0] == pick)} more accurate than any peer run")
    return lines


def simulate(carvallo: str, *extra: str) -> dict:
    cmd = [carvallo, "simulate", "--model", "benchmark", "--speed", repr(SPEED), "--lean0",
           repr(LEAN0), "--duration", repr(DURATION), "--json", *extra]
    return json.loads(subprocess.run(cmd, capture_output=True, text=True, check=True).stdout)


def bench_times(carvallo: str) -> dict:
    out = subprocess.run([carvallo, "bench", "--only", "simulation", "--json"],
                         capture_output=True, text=True, check=True)
    d = json.loads(out.stdout)
    times = {}
    for r in d["simulation"]:
        if r["problem"] == PROBLEM:
            key = (r["method"], r["rtol"] if r["rtol"] is not None else r["step"])
            times[key] = (r["ns"] * 1e-9, r["rhs_evaluations"])
    refs = [r for r in d["simulation_references"] if r["problem"] == PROBLEM]
    return times, refs


def lookup(times: dict, method: str, x: float):
    """The bench's (seconds, evaluations) of `method` at rtol or step `x` (matched to 1e-9
    relative: the bench computes its tolerances as 10^-k in Rust), or (nan, None)."""
    for (m, v), got in times.items():
        if m == method and v is not None and abs(v - x) <= 1e-9 * abs(x):
            return got
    return (math.nan, None)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeats", type=int, default=3, help="timed runs per row (default 3)")
    ap.add_argument("--bench-runs", type=int, default=2,
                    help="runs of `carvallo bench --only simulation` for our wall times, "
                         "before and after the peer's (default 2; about 2 min each)")
    ap.add_argument("--carvallo", default=os.environ.get("CARVALLO_BIN", "target/release/carvallo"))
    a = ap.parse_args()
    if a.repeats < 1:
        ap.error(f"invalid --repeats {a.repeats}: at least 1")
    if a.bench_runs < 1:
        ap.error(f"invalid --bench-runs {a.bench_runs}: at least 1")

    import pydy
    import scipy
    import sympy as sm
    from pydy.codegen.ode_function_generators import CythonODEFunctionGenerator
    from scipy.integrate import solve_ivp

    print(f"== PyDy {pydy.__version__}, SymPy {sm.__version__}, SciPy {scipy.__version__}, "
          f"NumPy {np.__version__}, {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    model = pw.derive()
    t0 = time.perf_counter()
    gen = CythonODEFunctionGenerator(model.forcing, model.q, model.u, model.constants,
                                     mass_matrix=model.mass_matrix,
                                     coordinate_derivatives=model.qdot,
                                     constants_arg_type="array")
    rhs = gen.generate()
    print(f"Kane's equations derived in {model.seconds:.1f} s; PyDy's Cython right-hand side "
          f"generated and compiled in {time.perf_counter() - t0:.1f} s")
    num = pw.Numeric(model)
    consts = num.const_array

    # Check at Basu-Mandal's state.
    x = num.basu_mandal_state()
    got = num.basu_mandal_accelerations(x, rhs(x, 0.0, consts)[4:])
    worst, _ = pw.basu_mandal_report(got)
    ours_acc = json.loads(subprocess.run(
        [a.carvallo, "accel", "--model", "benchmark", "--basu-mandal"],
        input=json.dumps({"q": pw.BASU_Q, "qd": pw.BASU_QD}), capture_output=True, text=True,
        check=True).stdout)["qdd"]
    vs_ours = max(abs(g - o) / abs(o) for g, o in zip(got, ours_acc))
    print(f"check at Basu-Mandal's Table 1 state: worst relative difference {worst:.1e} to the "
          f"table, {vs_ours:.1e} to `carvallo accel --basu-mandal`")
    if max(worst, vs_ours) > 1e-10:
        print("error: PyDy's right-hand side disagrees with Table 1 or ours", file=sys.stderr)
        return 1

    # The rounding error of PyDy's right-hand side near zero steer (the reason for its error
    # floor below).
    print("rounding error of PyDy's right-hand side against the same equations in 60 digits "
          "(largest relative error of u'; lean 0.03, lean rate 0.1, steer rate 0.2, 4.6 m/s):")
    for steer in [0.1, 1e-2, 1e-5, 1e-9, 0.0]:
        xs = num.state(0.0, 0.03, steer, 0.1, 0.2, -SPEED / model.values["rr"])
        hi = num.precise_speed_derivatives(xs)
        lo = rhs(xs, 0.0, consts)[4:]
        rel = [abs(a - b) / abs(b) for a, b in zip(lo, hi) if b != 0]
        worst_k = int(np.argmax(rel))
        print(f"  steer {steer:.0e} rad: {max(rel):.1e} (in {model.u[worst_k].func.__name__}')")

    x0 = num.state(0.0, LEAN0, 0.0, 0.0, 0.0, -SPEED / model.values["rr"])
    calls = [0]

    def f(t, y):
        calls[0] += 1
        return rhs(y, t, consts)

    def peer_run(method, rtol, atol):
        calls[0] = 0
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sol = solve_ivp(f, (0.0, DURATION), x0, method=method, rtol=rtol, atol=atol)
        ok = sol.status == 0 and abs(sol.t[-1] - DURATION) < 1e-12
        h = max(abs(num.contact(y[1], y[3], y[2])) for y in sol.y.T)
        return {"ok": ok, "message": sol.message, "lean": float(sol.y[1, -1]),
                "evals": calls[0], "steps": len(sol.t) - 1, "residual": h}

    # Reference: ours at 1e-14 (as the bench), checked by ours DOPRI5 and the peer.
    ref_run = simulate(a.carvallo, "--method", "dop853", "--rtol", "1e-14", "--atol", "1e-17")
    ref = ref_run["lean"][-1]
    d5 = simulate(a.carvallo, "--method", "dopri5", "--rtol", "1e-14", "--atol", "1e-17")
    print(f"\nreference lean(5 s) = {ref!r} rad (carvallo dop853 rtol 1e-14 atol 1e-17, "
          f"{ref_run['rhs_evaluations']} evaluations); carvallo dopri5 rtol 1e-14: "
          f"{abs(d5['lean'][-1] - ref):.1e} from it")

    print("\n== timing: `carvallo bench --only simulation --json`, then the peer's runs, then "
          "the bench again (--bench-runs)")
    bench_runs = [bench_times(a.carvallo)]
    refs = bench_runs[0][1]
    for r in refs:
        print(f"bench reference check: {r['reference']} vs {r['check']}: {r['agreement']:.1e}, "
              f"vs dopri5 1e-14: {r['agreement_dopri5']:.1e} (largest state error)")

    rows = []  # (who, method, tol label, rtol or step, evals, steps, error, seconds, residual)
    for method in PEER_METHODS:
        for rtol in TOLERANCES:
            r = peer_run(method, rtol, 1e-3 * rtol)
            best = float("inf")
            for _ in range(a.repeats):
                s = time.perf_counter()
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    solve_ivp(f, (0.0, DURATION), x0, method=method, rtol=rtol,
                              atol=1e-3 * rtol)
                best = min(best, time.perf_counter() - s)
            err = abs(r["lean"] - ref) if r["ok"] else float("nan")
            rows.append(("scipy+pydy", method, rtol, r["evals"], r["steps"], err, best,
                         r["residual"], None if r["ok"] else r["message"]))
            print(f"  scipy {method} rtol {rtol:.0e}: {r['evals']} evaluations, error "
                  f"{err:.1e}, {best * 1e3:.2f} ms" + ("" if r["ok"] else f" ({r['message']})"),
                  flush=True)

    # The peer's most accurate successful run, as a check of the reference.
    peer_ok = [r for r in rows if r[8] is None]
    closest = min(peer_ok, key=lambda r: r[5])
    print(f"peer check of the reference: scipy {closest[1]} rtol {closest[2]:.0e} is "
          f"{closest[5]:.1e} from it")

    for _ in range(a.bench_runs - 1):
        bench_runs.append(bench_times(a.carvallo))

    def our_time(method, x):
        found = [lookup(b[0], method, x)[0] for b in bench_runs]
        return min((v for v in found if v == v), default=math.nan)
    ours = []
    for method in OUR_METHODS:
        for rtol in TOLERANCES:
            s = simulate(a.carvallo, "--method", method, "--rtol", repr(rtol))
            t = our_time(method, rtol)
            bench_evals = lookup(bench_runs[0][0], method, rtol)[1]
            if bench_evals is not None and bench_evals != s["rhs_evaluations"]:
                print(f"note: bench and simulate count {bench_evals} and "
                      f"{s['rhs_evaluations']} evaluations for {method} {rtol:.0e}")
            ours.append(("carvallo", method, rtol, s["rhs_evaluations"], s["steps"],
                         abs(s["lean"][-1] - ref), t, s["max_contact_residual"], None))
    for h in RK4_STEPS:
        s = simulate(a.carvallo, "--method", "rk4", "--step", repr(h))
        t = our_time("rk4", h)
        ours.append(("carvallo", "rk4", h, s["rhs_evaluations"], s["steps"],
                     abs(s["lean"][-1] - ref), t, s["max_contact_residual"], None))

    print(f"\n== {PROBLEM}: error of the lean at 5 s against the reference")
    print("| who | method | rtol (RK4: step) | RHS evals | steps | lean error | error/rtol "
          "| error/(atol + rtol abs(lean)) | wall time | pitch constraint residual |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for who, method, tol, evals, steps, err, sec, res, fail in rows + ours:
        ratio = "" if method == "rk4" or not err == err else (
            f"{err / tol:.1e} | {err / (tol * (1e-3 + abs(ref))):.1e}")
        ratio = ratio or " | "
        wall = f"{sec * 1e3:.3f} ms" if sec == sec else "-"
        note = f" ({fail})" if fail else ""
        print(f"| {who} | {method} | {tol:.1e} | {evals} | {steps} | {err:.1e}{note} | {ratio} "
              f"| {wall} | {res:.1e} |")

    # Ratios at equal error, on the work-precision fronts.
    lean_scale = abs(ref)
    fronts = {pm: pareto([(r[5], r[6]) for r in peer_ok if r[1] == pm]) for pm in PEER_METHODS}
    fronts["best"] = pareto([(r[5], r[6]) for r in peer_ok])
    floor = min(e for e, _ in fronts["best"])
    print("\n== wall time of scipy+pydy / carvallo at equal lean error: each peer method's "
          "work-precision front (its runs no other run beats in both error and time), log time "
          "interpolated against log error; `best` the front of all three; `below` where the "
          f"peer reaches no such error (its smallest: {floor:.1e})")
    print("| carvallo | rtol | lean error | carvallo | " + " | ".join(PEER_METHODS)
          + " | best |")
    print("|---|---|---|---|" + "---|" * (len(PEER_METHODS) + 1))
    speedups, unreached = [], []
    for who, method, tol, evals, steps, err, sec, res, _ in ours:
        if method == "rk4":
            continue
        cells = []
        for pm in PEER_METHODS + ["best"]:
            front = fronts[pm]
            t_peer = interp_loglog([e for e, _ in front], [t for _, t in front], err)
            if not sec == sec:
                cells.append("-")
            elif t_peer is not None:
                cells.append(f"{t_peer / sec:.0f}x")
                if pm == "best":
                    speedups.append((t_peer / sec, method, tol))
            elif err < min(e for e, _ in front):
                cells.append("below")
                if pm == "best":
                    unreached.append((method, tol))
            else:
                cells.append("-")
        print(f"| {method} | {tol:.0e} | {err:.1e} | {sec * 1e6:.0f} us | " + " | ".join(cells)
              + " |")

    print("\n== targets of issue 21")
    for line in speedup_summary(speedups, unreached):
        print(line)
    rk4 = [r for r in ours if r[1] == "rk4"]
    fewer, compared, beyond, above = [], 0, 0, 0
    for r in ours:
        if r[1] == "rk4" or not r[5] < 1e-6:
            continue
        rk_evals = interp_loglog([x[5] for x in rk4], [x[3] for x in rk4], r[5])
        if rk_evals is None:
            # Below the smallest RK4 error: RK4 needs more than its largest count.
            if r[5] < min(x[5] for x in rk4):
                beyond += 1
                if r[3] >= max(x[3] for x in rk4):
                    fewer.append(r)
            else:
                above += 1
            continue
        compared += 1
        if r[3] >= rk_evals:
            fewer.append(r)
    print(f"adaptive fewer RHS evaluations than RK4 at every lean error below 1e-6: "
          f"{compared} rows interpolated on RK4's curve, {beyond} below its smallest error, "
          f"{above} above its largest (coarsest step 0.01 s: not compared); "
          + ("met" if not fewer else "NOT met at " + ", ".join(
              f"{r[1]} {r[2]:.0e}" for r in fewer)))
    adaptive = [r for r in ours if r[1] != "rk4"]

    def within(rows, scale):
        return [r for r in rows if 0.1 <= r[5] / scale(r) <= 10]

    def plain(r):
        return r[2]

    def lean_tol(r):
        return 1e-3 * r[2] + r[2] * lean_scale

    print("error within 10x of the estimate (neither side reports a global error estimate; "
          "the tolerance is what a user gets): lean error / rtol within [0.1, 10]: "
          f"{len(within(adaptive, plain))} of {len(adaptive)} carvallo rows (scipy+pydy "
          f"{len(within(peer_ok, plain))} of {len(peer_ok)}); lean error / (atol + rtol |lean|), "
          f"the tolerance the step control applies to the lean at 5 s: "
          f"{len(within(adaptive, lean_tol))} of {len(adaptive)} (scipy+pydy "
          f"{len(within(peer_ok, lean_tol))} of {len(peer_ok)})")
    ratios = [r[5] / lean_tol(r) for r in adaptive]
    print(f"  carvallo's lean error / (atol + rtol |lean|) ranges over "
          f"[{min(ratios):.1f}, {max(ratios):.1f}]")
    return 0


if __name__ == "__main__":
    sys.exit(main())
