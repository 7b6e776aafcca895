#!/usr/bin/env python3
"""Compares `carvallo window` and `carvallo eig` on every file of data/bicycleparameters/ (and
every bicycle + rider pair) with BicycleParameters 1.5.2's own linear model and prints the table
of docs/guide/src/bicycleparameters.md. Needs `pip install bicycleparameters==1.5.2` and a
built `carvallo` (its path in CARVALLO, default target/debug/carvallo); run from the repository
root, or through scripts/bicycleparameters-table, which installs the peer into its own venv.
Not part of the test command."""
import json, os, subprocess

import numpy as np
from bicycleparameters.io import load_parameter_text_file, remove_uncertainties
from bicycleparameters.bicycle import benchmark_par_to_canonical, ab_matrix
from bicycleparameters.inertia import combine_bike_rider
D = "data/bicycleparameters"
B = os.environ.get("CARVALLO", "target/debug/carvallo")
def par(bike, rider=None):
    p = load_parameter_text_file(f"{D}/bicycles/{bike}/Parameters/{bike}Benchmark.txt")
    if rider:
        r = load_parameter_text_file(f"{D}/riders/Jason/Parameters/Jason{bike}Benchmark.txt")
        p = combine_bike_rider(p, r)
    return remove_uncertainties(p)
def eig(p, v):
    M, C1, K0, K2 = benchmark_par_to_canonical(p)
    A, _ = ab_matrix(M, C1, K0, K2, v, p['g'])
    return np.linalg.eigvals(A)
def maxre(p, v): return max(eig(p, v).real)
def window(p):
    vs = np.linspace(0.01, 20, 2000)
    s = [maxre(p, v) < 0 for v in vs]
    edges = []
    for i in range(len(vs)-1):
        if s[i] != s[i+1]:
            a, b = vs[i], vs[i+1]
            for _ in range(80):
                m = 0.5*(a+b)
                if (maxre(p, m) < 0) == s[i]: a = m
                else: b = m
            edges.append(0.5*(a+b))
    return edges
rows = []
for bike, rider in [(b, None) for b in ["Balanceassistv1","Benchmark","Browser","Browserins","Crescendo","Fisher","Pista","Rigid","Silver","Yellow","Yellowrev"]] + [(b, "Jason") for b in ["Browser","Rigid","Balanceassistv1"]]:
    p = par(bike, rider)
    model = ["--model", f"{D}/bicycles/{bike}/Parameters/{bike}Benchmark.txt"]
    if rider: model += ["--rider", f"{D}/riders/Jason/Parameters/Jason{bike}Benchmark.txt"]
    w = json.loads(subprocess.run([B, "window", *model, "--json"], capture_output=True, text=True, check=True).stdout)
    edges = window(p)
    # eigenvalue differences at several speeds
    worst = 0.0
    for v in [0.5, 2.0, 4.0, 6.0, 10.0]:
        e = json.loads(subprocess.run([B, "eig", *model, "--speed", str(v), "--json"], capture_output=True, text=True, check=True).stdout)["eigenvalues"]
        ours = np.array([x["re"] + 1j*x["im"] for x in e])
        theirs = eig(p, v)
        for z in ours:
            d = min(abs(z - t) for t in theirs) / max(1.0, abs(z))
            worst = max(worst, d)
    rows.append((bike + (" + Jason" if rider else ""), w["weave_speed"], w["capsize_speed"], edges, worst, w["stable"]))
    print(rows[-1], flush=True)
print()
print("| file | carvallo weave | carvallo capsize | BicycleParameters (bisection) weave | capsize | max abs diff of speeds | max eigenvalue diff (rel, v=0.5..10) |")
print("|---|---|---|---|---|---|---|")
for name, wv, cp, edges, worst, stable in rows:
    ours = [x for ab in stable for x in ab if x is not None]
    if len(edges) == len(ours):
        dv = max(abs(a-b) for a, b in zip(edges, ours)) if edges else 0.0
    else:
        dv = float('nan')
    print(f"| {name} | {wv} | {cp} | {edges[0] if edges else None} | {edges[1] if len(edges)>1 else None} | {dv:.1e} | {worst:.1e} |" + ("" if len(edges)<=2 else f" (edges {edges})"))
