"""PyDy's generated C for the nonlinear Whipple bicycle's mass matrix and forcing, side by side
with ours (issue 22, item 4). Run by scripts/pydy-c-peer, which installs the pinned peers.

1. Derives SymPy's Kane model of the bicycle (scripts/pydy_whipple.py) and generates C for
   `M` (6 x 6) and `F` (6) with PyDy's own C generator, `pydy.codegen.c_code.CMatrixGenerator`
   with `cse=True` (SymPy's `cse` over both matrices, printed by SymPy's C99 printer): the code
   PyDy's Cython ODE function generator compiles. Operations are counted after CSE as ours are
   (`pydy_whipple.count_ops`).
2. Wraps the generated `evaluate` in a timing `main` like our C peer's
   (crates/carvallo-cli/src/bench/peer.rs: the kernel `noinline`, compiler barriers around
   every call, the smallest of five means over slices of at least `--min-time / 5` s, by
   default 0.002 s as `carvallo bench --quick` times ours) and compiles it with `cc -O2` and
   with `cc -O3 -march=native`.
3. Checks both builds: `M u' = F` solved at Basu-Mandal et al.'s (2007) Table 1 state, mapped to
   their nine accelerations, against the table and against `carvallo accel --basu-mandal`.
4. Times, interleaved over `--rounds` rounds: PyDy -O2, PyDy -O3 -march=native, then
   `carvallo bench --quick --json` (its section `peer`: our generated Rust, our SSA printed as
   C at -O2 and our four-lane evaluator per evaluation, for M3 and f3 of the same bicycle);
   each column's minimum over the rounds is printed. PyDy's C is timed at the configuration of
   our bench (lean 0.1, steer 0.05, lean rate 0.2, steer rate -0.1, rear wheel rate -5/0.3, the
   pitch from the constraint).
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
import pydy_whipple as pw  # noqa: E402

HARNESS = r"""
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* stdin: 4 coordinates, 6 speeds, 26 constants, then the minimum seconds of the timing.
   stdout: the 36 + 6 outputs, then "ns" and the nanoseconds per call. */
int main(void) {
    double q[4], u[6], c[26], m[36], f[6], min_time;
    for (int i = 0; i < 4; i++) if (scanf("%lf", &q[i]) != 1) return 2;
    for (int i = 0; i < 6; i++) if (scanf("%lf", &u[i]) != 1) return 2;
    for (int i = 0; i < 26; i++) if (scanf("%lf", &c[i]) != 1) return 2;
    if (scanf("%lf", &min_time) != 1) return 2;
    evaluate(q, u, c, m, f);
    for (int k = 0; k < 36; k++) printf("%.17g\n", m[k]);
    for (int k = 0; k < 6; k++) printf("%.17g\n", f[k]);
    double slice = min_time / 5.0, best = INFINITY;
    long n = 1;
    int rounds = 0;
    while (rounds < 5) {
        double t0 = now();
        for (long r = 0; r < n; r++) {
            __asm__ volatile("" : : "r"(q), "r"(u), "r"(c), "r"(m), "r"(f) : "memory");
            evaluate(q, u, c, m, f);
            __asm__ volatile("" : : "r"(q), "r"(u), "r"(c), "r"(m), "r"(f) : "memory");
        }
        double dt = now() - t0;
        if (dt >= slice) {
            if (dt * 1e9 / (double)n < best) best = dt * 1e9 / (double)n;
            rounds++;
        } else if (dt <= 0.0) {
            n *= 16;
        } else {
            double g = 1.2 * slice / dt;
            n = (long)((double)n * (g < 16.0 ? g : 16.0)) + 1;
        }
    }
    printf("ns %.3f\n", best);
    return 0;
}
"""

BUILDS = [("PyDy's generated C, -O2", ["-O2"]),
          ("PyDy's generated C, -O3 -march=native", ["-O3", "-march=native"])]
OURS = [("ours, generated Rust, scalar", "generated Rust"),
        ("ours, our SSA printed as C, -O2", "C peer (cc -O2, same SSA)"),
        ("ours, lanes: 4, per evaluation", "generated Rust, 4 lanes")]
OURS_NAME = "bicycle (c) full nonlinear right-hand side"


def run_kernel(exe: Path, x: np.ndarray, consts: np.ndarray, min_time: float):
    text = "\n".join(repr(float(v)) for v in list(x) + list(consts) + [min_time]) + "\n"
    out = subprocess.run([str(exe)], input=text, capture_output=True, text=True, check=True)
    lines = out.stdout.split()
    vals = [float(v) for v in lines[:42]]
    if lines[42] != "ns":
        raise SystemExit(f"error: unexpected output of {exe}: {out.stdout[-200:]}")
    return np.array(vals[:36]).reshape(6, 6), np.array(vals[36:42]), float(lines[43])


def carvallo_accel(carvallo: str) -> list[float]:
    inp = json.dumps({"q": pw.BASU_Q, "qd": pw.BASU_QD})
    out = subprocess.run([carvallo, "accel", "--model", "benchmark", "--basu-mandal"],
                         input=inp, capture_output=True, text=True, check=True)
    return json.loads(out.stdout)["qdd"]


def carvallo_bench(carvallo: str) -> dict[str, tuple[float, int]]:
    out = subprocess.run([carvallo, "bench", "--quick", "--json"], capture_output=True,
                         text=True, check=True)
    rows = json.loads(out.stdout)["rows"]
    got = {}
    for r in rows:
        if r["section"] == "peer" and r["name"] == OURS_NAME and r["ns"] is not None:
            got[r["method"]] = (float(r["ns"]), int(r["ops"]))
    missing = [m for _, m in OURS if m not in got]
    if missing:
        raise SystemExit(f"error: `carvallo bench --quick --json` has no peer row {missing} "
                         f"for {OURS_NAME!r} (no C compiler?)")
    return got


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rounds", type=int, default=10, help="interleaved rounds (default 10)")
    ap.add_argument("--min-time", type=float, default=0.002,
                    help="seconds of each PyDy timing (default 0.002, the min_time of "
                         "`carvallo bench --quick`, so that both sides are timed alike)")
    ap.add_argument("--carvallo", default=os.environ.get("CARVALLO_BIN", "target/release/carvallo"))
    ap.add_argument("--cc", default=os.environ.get("CC", "cc"))
    ap.add_argument("--keep", type=Path, help="write the generated C into this directory")
    a = ap.parse_args()
    if a.rounds < 1:
        ap.error(f"invalid --rounds {a.rounds}: at least 1")
    if not a.min_time > 0 or not math.isfinite(a.min_time):
        ap.error(f"invalid --min-time {a.min_time}: a positive number of seconds")
    if shutil.which(a.cc) is None:
        ap.error(f"no C compiler `{a.cc}` (--cc or $CC)")

    import pydy
    from pydy.codegen.c_code import CMatrixGenerator

    cc_version = subprocess.run([a.cc, "--version"], capture_output=True, text=True).stdout
    print(f"== PyDy {pydy.__version__}, SymPy {sm.__version__}, NumPy {np.__version__}, "
          f"{cc_version.splitlines()[0]}")
    model = pw.derive()
    print(f"Kane's equations derived in {model.seconds:.1f} s "
          f"(benchmark -> Moore parameters agree with PyDy's example to "
          f"{pw.check_parameters(model.values):.1e})")
    t0 = time.perf_counter()
    gen = CMatrixGenerator([model.q, model.u, model.constants],
                           [model.mass_matrix, model.forcing], cse=True)
    _, source = gen.doprint()
    outputs = list(gen.simplified_matrices[0]) + list(gen.simplified_matrices[1])
    ops = pw.count_ops(gen.subexprs, outputs)
    by_op = pw.op_counts(gen.subexprs, outputs)
    print(f"C generated by pydy.codegen.c_code.CMatrixGenerator(cse=True) in "
          f"{time.perf_counter() - t0:.1f} s: {len(gen.subexprs)} CSE temporaries, "
          f"{ops} operations after CSE ({by_op})")

    source = source.replace("void evaluate(", "__attribute__((noinline)) void evaluate(", 1)
    work = Path(tempfile.mkdtemp(prefix="pydy-c-peer-"))
    try:
        (work / "kernel.c").write_text(source + HARNESS)
        if a.keep:
            a.keep.mkdir(parents=True, exist_ok=True)
            shutil.copy(work / "kernel.c", a.keep / "pydy_whipple_mf.c")
        exes = []
        for k, (label, flags) in enumerate(BUILDS):
            exe = work / f"kernel{k}"
            t0 = time.perf_counter()
            subprocess.run([a.cc, *flags, "-o", str(exe), str(work / "kernel.c"), "-lm"],
                           check=True)
            print(f"{label}: `{a.cc} {' '.join(flags)} kernel.c -lm` in "
                  f"{time.perf_counter() - t0:.1f} s")
            exes.append(exe)

        num = pw.Numeric(model)
        consts = num.const_array
        print("\n== check: Basu-Mandal et al. (2007) Table 1, M u' = F solved (numpy.linalg.solve)")
        x = num.basu_mandal_state()
        ours = carvallo_accel(a.carvallo)
        worst_all = 0.0
        for (label, _), exe in zip(BUILDS, exes):
            mm, ff, _ = run_kernel(exe, x, consts, 1e-4)
            got = num.basu_mandal_accelerations(x, np.linalg.solve(mm, ff))
            worst, table = pw.basu_mandal_report(got)
            vs_ours = max(abs(g - o) / abs(o) for g, o in zip(got, ours))
            worst_all = max(worst_all, worst, vs_ours)
            print(f"{label}: worst relative difference {worst:.1e} to Table 1, "
                  f"{vs_ours:.1e} to `carvallo accel --basu-mandal`")
            if label.endswith("-O2"):
                print(table)
        if worst_all > 1e-10:
            print(f"error: PyDy's C disagrees with Table 1 or ours by {worst_all:.1e}",
                  file=sys.stderr)
            return 1

        # The configuration of our bench (crates/carvallo-cli/src/bench/mod.rs, nonlinear_args).
        xt = num.state(0.0, 0.1, 0.05, 0.2, -0.1, -5.0 / 0.3)
        print(f"\n== timing, {a.rounds} interleaved rounds (PyDy -O2, PyDy -O3 -march=native, "
              f"`{a.carvallo} bench --quick --json`); minimum over the rounds")
        best: dict[str, float] = {}
        our_ops: dict[str, int] = {}
        for r in range(a.rounds):
            line = []
            for (label, _), exe in zip(BUILDS, exes):
                ns = run_kernel(exe, xt, consts, a.min_time)[2]
                best[label] = min(best.get(label, float("inf")), ns)
                line.append(f"{ns:.0f}")
            got = carvallo_bench(a.carvallo)
            for label, method in OURS:
                best[label] = min(best.get(label, float("inf")), got[method][0])
                our_ops[label] = got[method][1]
                line.append(f"{got[method][0]:.0f}")
            print(f"round {r + 1}: " + " ".join(line) + " ns")
    finally:
        shutil.rmtree(work, ignore_errors=True)

    print("\n| nonlinear Whipple bicycle, mass matrix + forcing | ops | ns | / PyDy -O2 |")
    print("|---|---|---|---|")
    ref = best[BUILDS[0][0]]
    for label, _ in BUILDS:
        print(f"| {label} | {ops:,} | {best[label]:.0f} | {best[label] / ref:.2f} |")
    for label, _ in OURS:
        print(f"| {label} | {our_ops[label]:,} | {best[label]:.0f} | {best[label] / ref:.2f} |")
    print(f"\nPyDy: M 6 x 6 and F 6 (all six speed derivatives, the dependent ones through the "
          f"constraints' derivatives); ours: M3 3 x 3 (6 distinct) and f3 3 (independent "
          f"speeds only, the dependent rates are other outputs). Ops: {ops:,} PyDy, "
          f"{our_ops[OURS[0][0]]:,} ours ({our_ops[OURS[0][0]] / ops:.2f}x).")
    o3 = best[BUILDS[1][0]]
    scalar, lanes = best[OURS[0][0]], best[OURS[2][0]]
    print("targets of issue 22 (ratios of this run):")
    for name, measured, required in [
        ("ops <= 1,500", our_ops[OURS[0][0]], 1500),
        ("scalar <= 0.6x PyDy -O2", scalar / ref, 0.6),
        ("lanes <= 0.3x PyDy -O2 per evaluation", lanes / ref, 0.3),
        ("scalar <= 1.0x PyDy -O3 -march=native", scalar / o3, 1.0),
    ]:
        fmt = f"{measured:,}" if isinstance(measured, int) else f"{measured:.2f}"
        print(f"  {name}: {fmt} -> {'met' if measured <= required else 'NOT met'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
