"""BicycleParameters' side of the comparison with carvallo on the files of data/bicycleparameters/:
its parameters (with `Bicycle.add_rider` for a rider), its eigenvalues
(`bicycleparameters.bicycle.benchmark_par_to_canonical` + `ab_matrix`) and its stable speed range
(a bisection of the sign of its largest real part). Shared by scripts/bicycleparameters-table.py
(the table of docs/guide/src/bicycleparameters.md) and the test command's
crates/carvallo-py/tests/test_bicycleparameters.py. Needs `bicycleparameters==1.5.2`.

The two-mass-skate `Tms` has zero wheel radii and zero spin inertias: BicycleParameters' formulas
divide the spin inertia by the radius (`SR = IRyy / rR`) and give NaN there. `matrices` evaluates
them at the radius `SKATE_RADIUS` instead, where `SR = 0 / SKATE_RADIUS` is exactly zero and every
other term holding the radius is multiplied by the wheel's mass, zero for `Tms`: its matrices at
that radius are those of the limit, computed by BicycleParameters' own formulas.
"""

import contextlib
import io
import pathlib

import numpy as np
from bicycleparameters import Bicycle
from bicycleparameters.bicycle import ab_matrix, benchmark_par_to_canonical
from bicycleparameters.io import load_parameter_text_file, remove_uncertainties

ROOT = pathlib.Path(__file__).resolve().parents[1]
DATA = ROOT / "data" / "bicycleparameters"
BICYCLES = [
    "Balanceassistv1", "Benchmark", "Browser", "Browserins", "Crescendo", "Fisher", "Pista",
    "Rigid", "Silver", "Tms", "Yellow", "Yellowrev",
]
RIDER = "Jason"
RIDER_PAIRS = [("Browser", RIDER), ("Rigid", RIDER), ("Balanceassistv1", RIDER)]
CASES = [(b, None) for b in BICYCLES] + RIDER_PAIRS
# Speeds (m/s) at which the eigenvalues are compared.
SPEEDS = (0.5, 2.0, 4.0, 6.0, 10.0)
# The radius standing for a zero radius (see the module docs).
SKATE_RADIUS = 1e-60
# The speed range searched for stability boundaries and its grid before bisection.
VMAX, GRID = 20.0, 2000


def bicycle_file(bike: str) -> pathlib.Path:
    return DATA / "bicycles" / bike / "Parameters" / f"{bike}Benchmark.txt"


def rider_file(bike: str, rider: str) -> pathlib.Path:
    return DATA / "riders" / rider / "Parameters" / f"{rider}{bike}Benchmark.txt"


def label(bike: str, rider) -> str:
    return bike + (f" + {rider}" if rider else "")


def uncertain_parameters(bike: str, rider=None) -> dict:
    """BicycleParameters' benchmark parameters (ufloats): the file read by `Bicycle`, the rider
    added by `Bicycle.add_rider` (which combines the rider file of the bicycle by
    `inertia.combine_bike_rider`)."""
    with contextlib.redirect_stdout(io.StringIO()):  # Bicycle and add_rider print progress
        b = Bicycle(bike, pathToData=str(DATA))
        if rider:
            b.add_rider(rider)
    return dict(b.parameters["Benchmark"])


def parameters(bike: str, rider=None) -> dict:
    """The nominal values of `uncertain_parameters`, floats."""
    return {k: float(v) for k, v in remove_uncertainties(uncertain_parameters(bike, rider)).items()}


def file_parameters(bike: str) -> dict:
    """The bicycle's file read by `bicycleparameters.io.load_parameter_text_file` alone."""
    return remove_uncertainties(load_parameter_text_file(str(bicycle_file(bike))))


def matrices(p: dict):
    """M, C1, K0, K2 by `benchmark_par_to_canonical`, a zero radius with zero spin inertia at
    `SKATE_RADIUS` (the limit, see the module docs)."""
    q = dict(p)
    for r, yy in (("rR", "IRyy"), ("rF", "IFyy")):
        if q[r] == 0.0 and q[yy] == 0.0:
            q[r] = SKATE_RADIUS
    return benchmark_par_to_canonical(q)


def eigenvalues(p: dict, v: float, mats=None) -> np.ndarray:
    """The four eigenvalues at speed `v` of `ab_matrix`'s state matrix."""
    m, c1, k0, k2 = mats if mats is not None else matrices(p)
    a, _ = ab_matrix(m, c1, k0, k2, v, p["g"])
    return np.linalg.eigvals(a)


def stability_edges(p: dict) -> list:
    """The speeds in (0, VMAX] where the largest real part of the eigenvalues changes sign:
    located on a grid of GRID speeds, then bisected to the last bit."""
    mats = matrices(p)
    stable = lambda v: max(eigenvalues(p, v, mats).real) < 0
    vs = np.linspace(VMAX / GRID, VMAX, GRID)
    s = [stable(v) for v in vs]
    edges = []
    for i in range(len(vs) - 1):
        if s[i] != s[i + 1]:
            a, b = vs[i], vs[i + 1]
            while True:
                m = 0.5 * (a + b)
                if m in (a, b):
                    break
                if stable(m) == s[i]:
                    a = m
                else:
                    b = m
            edges.append(0.5 * (a + b))
    return edges


def eigenvalue_difference(ours: np.ndarray, theirs: np.ndarray) -> float:
    """The largest distance from one of `ours` to the nearest of `theirs`, relative to
    max(1, |ours|)."""
    return max(min(abs(z - t) for t in theirs) / max(1.0, abs(z)) for z in ours)


def edges_of(stable) -> list:
    """The finite ends of carvallo's stable intervals `[(from, to), ...]` (to may be inf)."""
    return [x for ab in stable for x in ab if x is not None and np.isfinite(x) and x > 0]
