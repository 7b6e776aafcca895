"""BicycleParameters' side of the leaning rider (issue 34 item 4): Moore's (2012) model as
BicycleParameters 1.5.2 ships it (`bicycleparameters.models.MooreRiderLean2012Model`,
generated code `bicycleparameters._mooreriderlean2012.eval_linear`), with the parameter set
data/mooreriderlean2012/browser_jason.toml (= `parameter_dicts.mooreriderlean2012_browser_jason`).

Run (from the workspace root):

    python3 -m venv target/lean-venv
    target/lean-venv/bin/pip install bicycleparameters==1.5.2
    target/lean-venv/bin/python scripts/lean-rider-peer.py

It writes data/mooreriderlean2012/browser_jason_peer.json:
- `linear`: at each speed v, A (12x12) and B (12x3) of `form_state_space_matrices(v=v)` and
  their eigenvalues (`numpy.linalg.eigvals(A)`), floats as round-trip reprs;
- `nonlinear`: `eval_linear` is the only function the module exposes; it evaluates the
  nonlinear equations internally (dependent speeds u1 u2 u3 u5 u8 and the accelerations
  u4p u6p u7p u9p, Autolev's explicit solution of Kane's equations) before differentiating.
  This script runs its source unchanged except that it also returns those locals, at three
  seeded states, with and without inputs. M and f are not exposed separately (the Autolev
  code solves the 4x4 system by Cramer's rule in its own row scaling), so the dump gives
  u' = M^{-1} f. `lam` inside eval_linear is computed from the state's own roll and steer
  (`pitch_from_roll_and_steer(q4, q7, ...)`); each state is therefore evaluated twice:
  `as_shipped` (that) and `lam_constant` (lam fixed at its upright value, the model's
  definition: the hinge and torso orientation are fixed in the rear frame).
"""

import inspect
import json
import pathlib
import tomllib

import numpy as np
import bicycleparameters
from bicycleparameters import _mooreriderlean2012 as gen
from bicycleparameters.models import MooreRiderLean2012Model
from bicycleparameters.parameter_sets import MooreRiderLean2012ParameterSet
from bicycleparameters.parameter_dicts import mooreriderlean2012_browser_jason
from dtk.bicycle import pitch_from_roll_and_steer

ROOT = pathlib.Path(__file__).resolve().parents[1]
DATA = ROOT / "data" / "mooreriderlean2012"
SPEEDS = [1.0, 2.5, 4.0, 5.0, 6.0, 8.0]


def floats(a):
    """Nested lists of round-trip float reprs (complex as [re, im])."""
    a = np.asarray(a)
    if np.iscomplexobj(a):
        return [[repr(float(z.real)), repr(float(z.imag))] for z in a.ravel()] if a.ndim == 1 \
            else [floats(r) for r in a]
    if a.ndim == 0:
        return repr(float(a))
    return [floats(r) for r in a]


def instrumented_eval_linear(lam_constant):
    """eval_linear's own source, returning also its locals; optionally lam fixed at upright."""
    src = inspect.getsource(gen.eval_linear)
    src = src.replace("def eval_linear(", "def eval_linear_locals(")
    src = src.replace("return A, B, C, D", "return A, B, C, D, dict(locals())")
    namespace = dict(vars(gen))
    if lam_constant:
        namespace["pitch_from_roll_and_steer"] = \
            lambda q4, q7, rf, rr, d1, d2, d3: pitch_from_roll_and_steer(0.0, 0.0, rf, rr, d1, d2, d3)
    exec(src, namespace)
    return namespace["eval_linear_locals"]


def main():
    par = tomllib.loads((DATA / "browser_jason.toml").read_text())
    assert par == mooreriderlean2012_browser_jason, "TOML differs from the package's dict"
    model = MooreRiderLean2012Model(MooreRiderLean2012ParameterSet(par))
    par_names = [k for k in model.parameter_set.par_strings if k != "v"]
    out = {
        "source": "bicycleparameters %s, models.MooreRiderLean2012Model, "
                  "parameter_dicts.mooreriderlean2012_browser_jason" % bicycleparameters.__version__,
        "bicycleparameters_version": bicycleparameters.__version__,
        "numpy_version": np.__version__,
        "state_names": model.state_vars,
        "input_names": model.input_vars,
        "parameters": {k: repr(par[k]) for k in sorted(par)},
        "eval_linear_parameter_order": par_names,
        "upright_pitch_q5": repr(pitch_from_roll_and_steer(0.0, 0.0, par["rf"], par["rr"],
                                                           par["d1"], par["d2"], par["d3"])),
        "linear": [],
        "nonlinear": {},
    }
    for v in SPEEDS:
        A, B = model.form_state_space_matrices(v=v)
        ev = np.linalg.eigvals(A)
        ev = ev[np.lexsort((ev.imag, ev.real))]
        out["linear"].append({"v": repr(v), "A": floats(A), "B": floats(B),
                              "eigenvalues_re_im": floats(ev)})

    # Nonlinear: three seeded states (q1..q9 incl. q5 from the holonomic constraint, u4 u6 u7 u9).
    rng = np.random.default_rng(34)
    p = np.array([par[k] for k in par_names])
    states = []
    for _ in range(3):
        q = np.zeros(9)
        q[0:2] = rng.uniform(-1.0, 1.0, 2)              # q1, q2
        q[2] = rng.uniform(-np.pi, np.pi)               # q3 yaw
        q[3] = rng.uniform(-0.3, 0.3)                   # q4 roll
        q[5] = rng.uniform(-np.pi, np.pi)               # q6 rear wheel
        q[6] = rng.uniform(-0.5, 0.5)                   # q7 steer
        q[7] = rng.uniform(-np.pi, np.pi)               # q8 front wheel
        q[8] = rng.uniform(-0.3, 0.3)                   # q9 lean
        q[4] = pitch_from_roll_and_steer(q[3], q[6], par["rf"], par["rr"], par["d1"],
                                         par["d2"], par["d3"])  # q5 pitch
        u = np.array([rng.uniform(-1, 1), -rng.uniform(1, 6) / par["rr"], rng.uniform(-1, 1),
                      rng.uniform(-1, 1)])               # u4, u6, u7, u9
        r = rng.uniform(-5, 5, 4)                        # T4, T6, T7, T9
        states.append((q, u, r))
    names = ["u1", "u2", "u3", "u5", "u8", "q1p", "q2p", "q3p", "q4p", "q5p", "q6p", "q7p",
             "q8p", "q9p", "u4p", "u6p", "u7p", "u9p"]
    for mode in ("lam_constant", "as_shipped"):
        f = instrumented_eval_linear(mode == "lam_constant")
        rows = []
        for q, u, r in states:
            for rr_ in (np.zeros(4), r):
                A13, B13, _, _, loc = f(q, u, rr_, p)
                rows.append({"q1..q9": floats(q), "u4,u6,u7,u9": floats(u),
                             "T4,T6,T7,T9": floats(rr_), "lam": repr(float(loc["lam"])),
                             "values": {n: repr(float(loc[n])) for n in names},
                             "A13_jacobian": floats(A13), "B13": floats(B13)})
        out["nonlinear"][mode] = rows
    out["nonlinear"]["note"] = ("A13/B13: eval_linear's 13x13/13x4 partials at that state, order "
                                "q1..q9,u4,u6,u7,u9 / T4,T6,T7,T9; q5 treated as independent "
                                "(Autolev warns the partials ignore that q5 is dependent).")
    (DATA / "browser_jason_peer.json").write_text(json.dumps(out, indent=1) + "\n")

    # Check of issue 34: k9 = c9 = 0 gives a real eigenvalue near +7 1/s at every speed.
    for e in out["linear"]:
        ev = np.array([complex(float(a), float(b)) for a, b in e["eigenvalues_re_im"]])
        real_pos = ev[(abs(ev.imag) < 1e-12) & (ev.real > 1)].real
        print("v = %s: real eigenvalues > 1: %s" % (e["v"], real_pos))


if __name__ == "__main__":
    main()
