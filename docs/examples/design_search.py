"""The design change of smallest relative norm that widens a bicycle's stable speed window.

A worked example of carvallo's design sensitivities (docs/guide/src/derivatives.md): SciPy's
SLSQP minimises sum(((p - p0) / p0) ** 2) over the 25 parameters other than g, subject to
capsize speed - weave speed >= the nominal width + `widen`, with the gradient of the window's
width from carvallo.speed_gradients (generated derivative code), masses, inertias, radii and
the wheelbase positive, and the moments of inertia physical (each body's principal moments
non-negative and obeying the triangle inequalities). Run it: python docs/examples/design_search.py
"""

import numpy as np
from scipy.optimize import minimize

import carvallo


def search(p0: dict, widen: float = 1.0):
    names = [n for n in carvallo.PARAM_NAMES if n != "g"]
    x0 = np.array([p0[n] for n in names])

    def design(x):
        return {**p0, **dict(zip(names, x))}

    def width_and_gradient(x):
        # An unphysical trial design (SLSQP's line search may try one) counts as a window
        # 10 m/s too narrow, so that the search steps back.
        try:
            s = carvallo.speed_gradients(design(x))
        except carvallo.ParameterError:
            return target - 10.0, np.zeros(len(x))
        width = s["capsize_speed"] - s["weave_speed"]
        grad = np.array([s["d_capsize"][n] - s["d_weave"][n] for n in names])
        return width, grad

    def inertia_slack(x):
        # >= 0 for physical moments of inertia: the wheels' (thin disc at equality) and the
        # frame's and the fork's principal moments (non-negative, triangle inequalities).
        d = design(x)
        slack = [2 * d["IRxx"] - d["IRyy"], 2 * d["IFxx"] - d["IFyy"]]
        for b in "BH":
            xx, zz, xz, yy = d[f"I{b}xx"], d[f"I{b}zz"], d[f"I{b}xz"], d[f"I{b}yy"]
            r = np.hypot((xx - zz) / 2, xz)
            moments = [(xx + zz) / 2 + r, (xx + zz) / 2 - r, yy]
            slack += [sum(moments) - 2 * m for m in moments] + moments
        return np.array(slack)

    target = 0.0
    target = width_and_gradient(x0)[0] + widen
    positive = [n[0] in "mI" and not n.endswith("xz") or n in ("rR", "rF", "w") for n in names]
    result = minimize(
        lambda x: np.sum(((x - x0) / x0) ** 2),
        x0,
        jac=lambda x: 2 * (x - x0) / x0**2,
        method="SLSQP",
        bounds=[(1e-6 if p else None, None) for p in positive],
        constraints=[
            {"type": "ineq", "fun": lambda x: width_and_gradient(x)[0] - target,
             "jac": lambda x: width_and_gradient(x)[1]},
            {"type": "ineq", "fun": inertia_slack},
        ],
        options={"ftol": 1e-12, "maxiter": 200},
    )
    return result, names, design(result.x), inertia_slack


if __name__ == "__main__":
    import warnings

    warnings.simplefilter("ignore", carvallo.PhysicsWarning)  # trial designs on a bound
    p0 = carvallo.benchmark()
    result, names, p1, _ = search(p0)
    w0, w1 = carvallo.window(p0), carvallo.window(p1)
    print(f"{result.message}: {result.nit} iterations, {result.njev} gradients")
    print("window {weave_speed:.4f} to {capsize_speed:.4f} m/s".format(**w0), end=" -> ")
    print("{weave_speed:.4f} to {capsize_speed:.4f} m/s".format(**w1))
    rel = np.array([(p1[n] - p0[n]) / p0[n] for n in names])
    print(f"relative change (2-norm): {np.linalg.norm(rel):.4f}")
    for i in np.argsort(-abs(rel))[:8]:
        print(f"  {names[i]:6} {p0[names[i]]:9.5g} -> {p1[names[i]]:9.5g}  {100 * rel[i]:+6.2f} %")
