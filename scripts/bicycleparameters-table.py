#!/usr/bin/env python3
"""Compares `carvallo window` and `carvallo eig` on every file of data/bicycleparameters/ (and
every bicycle + rider pair) with BicycleParameters 1.5.2's own linear model and prints the table
of docs/guide/src/bicycleparameters.md. BicycleParameters' side is
scripts/bicycleparameters_peer.py, shared with the test command's
crates/carvallo-py/tests/test_bicycleparameters.py, which asserts what this table shows. Needs
`pip install bicycleparameters==1.5.2` and a built `carvallo` (its path in CARVALLO, default
target/debug/carvallo); run through scripts/bicycleparameters-table, which installs the peer
into its own venv."""
import json
import os
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bicycleparameters_peer as peer  # noqa: E402

B = os.environ.get("CARVALLO", str(peer.ROOT / "target" / "debug" / "carvallo"))


def run(*args):
    out = subprocess.run([B, *args], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def fmt(x):
    return "none (below 20)" if x is None else repr(float(x))


start = time.time()
print("| file | weave | capsize | BicycleParameters weave | capsize | speed diff | eigenvalue diff |")
print("|---|---|---|---|---|---|---|")
for bike, rider in peer.CASES:
    model = ["--model", str(peer.bicycle_file(bike))]
    if rider:
        model += ["--rider", str(peer.rider_file(bike, rider))]
    w = run("window", *model, "--json")
    p = peer.parameters(bike, rider)
    theirs = peer.stability_edges(p)
    ours = [x for x in peer.edges_of(w["stable"]) if x <= peer.VMAX]
    if len(ours) == len(theirs):
        dv = max((abs(a - b) for a, b in zip(ours, theirs)), default=0.0)
        speed = f"{dv:.1e}"
    else:
        speed = f"edges differ: carvallo {ours}, BicycleParameters {theirs}"
    worst = 0.0
    for v in peer.SPEEDS:
        e = run("eig", *model, "--speed", str(v), "--json")["eigenvalues"]
        z = np.array([x["re"] + 1j * x["im"] for x in e])
        worst = max(worst, peer.eigenvalue_difference(z, peer.eigenvalues(p, v)))
    bp = (theirs + [None, None])[:2]
    print(f"| {peer.label(bike, rider)} | {fmt(w['weave_speed'])} | {fmt(w['capsize_speed'])} "
          f"| {fmt(bp[0])} | {fmt(bp[1])} | {speed} | {worst:.1e} |", flush=True)
print(f"\n({time.time() - start:.1f} s)", file=sys.stderr)
