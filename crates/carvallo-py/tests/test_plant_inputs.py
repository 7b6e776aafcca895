"""The nonlinear bicycle driven from Python (`simulate` with torque arrays, impulses and
feedback) against `carvallo simulate --torque-csv/--torque/--gain/--gain-table --json` (equal
results), its energy balance, and gain tables in `closed_loop_window` and
`closed_loop_eigenvalues` against `carvallo window --gain-table` and the constant gains."""

import numpy as np
import pytest

import carvallo

ARGS = ("simulate", "--model", "benchmark", "--speed", "5", "--lean0", "0", "--duration", "1", "--json")
COLUMNS = ["t", "lean", "steer", "pitch", "energy", "T_phi", "T_delta", "work_t"]


def test_driven_simulate_equals_the_cli(cli, tmp_path):
    t = np.array([0.0, 0.2, 0.5, 0.9])
    roll = np.array([0.0, 2.0, -1.0, 0.0])
    steer = np.array([0.5, 0.5, 0.0, 0.3])
    csv = tmp_path / "torques.csv"
    csv.write_text("t,T_phi,T_delta\n" + "".join(f"{float(a)!r},{float(b)!r},{float(c)!r}\n" for a, b, c in zip(t, roll, steer)))
    p = carvallo.benchmark()
    s = carvallo.simulate(p, 5.0, 0.0, 1.0, torque_t=t, torque_roll=roll, torque_steer=steer,
                          impulses=[(0.3, 0.2, 0.0)], k={"k_steer_roll_rate": -10.0})
    c = cli(*ARGS, "--torque-csv", str(csv), "--torque", "roll=impulse:0.2@0.3", "--gain", "k_steer_roll_rate=-10")
    for key in COLUMNS:
        assert isinstance(s[key], np.ndarray)
        assert s[key].tolist() == c[key], key
    for key in ["work", "max_energy_change", "energy_drift", "steps"]:
        assert s[key] == c[key], key
    # The energy balance: E - E(0) follows the work, at the integrator's error.
    assert abs(s["energy"][-1] - s["energy"][0] - s["work"]) < 1e-8
    assert s["energy_drift"] < 1e-8 < 1e-3 < s["max_energy_change"]
    # A gain table (here constant) is read at the rear contact's speed, as --gain-table.
    table = {"speed": [4.0, 6.0], "k_steer_roll_rate": [-10.0, -10.0]}
    g = carvallo.simulate(p, 5.0, 0.0, 1.0, torque_t=t, torque_steer=steer, k=table)
    gc = cli(*ARGS, "--torque-csv", str(csv), "--gain", "k_steer_roll_rate=-10")
    assert g["lean"].tolist() != gc["lean"]  # gc has the roll torque too
    h = carvallo.simulate(p, 5.0, 0.0, 1.0, torque_t=t, torque_steer=steer, k={"k_steer_roll_rate": -10.0})
    assert g["lean"].tolist() == h["lean"].tolist()
    # Undriven, the result keeps its keys.
    assert "work" not in carvallo.simulate(p, 5.0, 0.0, 0.1)


def test_bad_driven_inputs_are_named():
    p = carvallo.benchmark()
    with pytest.raises(carvallo.ParameterError, match="torque_roll: invalid torque series: time 0.1 in row 3 does not exceed the time 0.2 before it"):
        carvallo.simulate(p, 5.0, 0.0, 1.0, torque_t=[0.0, 0.2, 0.1], torque_roll=[0.0, 1.0, 0.0])
    with pytest.raises(carvallo.ParameterError, match="need their times torque_t"):
        carvallo.simulate(p, 5.0, 0.0, 1.0, torque_roll=[0.0, 1.0])
    with pytest.raises(carvallo.ParameterError, match="invalid impulse time 0.0005 s: not a multiple of the step 0.001 s"):
        carvallo.simulate(p, 5.0, 0.0, 1.0, impulses=[(0.0005, 1.0, 0.0)])
    with pytest.raises(carvallo.ParameterError, match="outside the gain table's speeds 0 to 4 m/s"):
        carvallo.simulate(p, 5.0, 0.0, 1.0, k={"speed": [0.0, 4.0], "k_roll_roll": [1.0, 1.0]})


def test_gain_tables_in_the_closed_loop_functions(cli, tmp_path):
    p = carvallo.benchmark()
    table = {"speed": [0.0, 4.0, 8.0], "k_steer_roll_rate": [-30.0, -10.0, 0.0], "k_steer_roll": [0.0, 5.0, 0.0]}
    csv = tmp_path / "gains.csv"
    csv.write_text("speed,k_steer_roll_rate,k_steer_roll\n0,-30,0\n4,-10,5\n8,0,0\n")
    w = carvallo.closed_loop_window(p, table)
    c = cli("window", "--model", "benchmark", "--gain-table", str(csv), "--json")
    assert [tuple(s) for s in c["stable"]] == w["stable"]
    assert (w["from"], w["to"]) == (0.0, 8.0) == (c["from"], c["to"])
    # Between the rows the gains are interpolated: at 2 m/s, k_steer_roll_rate = -20 and
    # k_steer_roll = 2.5, the eigenvalues those of the constant gains.
    ev = carvallo.closed_loop_eigenvalues(p, table, [2.0, 6.0])
    assert ev[0].tolist() == carvallo.closed_loop_eigenvalues(p, {"k_steer_roll_rate": -20.0, "k_steer_roll": 2.5}, [2.0])[0].tolist()
    assert ev[1].tolist() == carvallo.closed_loop_eigenvalues(p, {"k_steer_roll_rate": -5.0, "k_steer_roll": 2.5}, [6.0])[0].tolist()
    # The window's edges are where the eigenvalues of A - B K(v) cross.
    for lo, hi in w["stable"]:
        for v, stable in [(lo - 1e-6, False), (lo + 1e-6, True), (hi - 1e-6, True)]:
            if 0.0 < v < 8.0:
                e = carvallo.closed_loop_eigenvalues(p, table, [v])[0]
                assert bool(np.all(e.real < 0)) == stable, (v, e)
    with pytest.raises(carvallo.ParameterError, match="the gain table covers the speeds 0 to 8 m/s, not 9 m/s"):
        carvallo.closed_loop_eigenvalues(p, table, [9.0])
    with pytest.raises(carvallo.ParameterError, match="covers the speeds 0 to 8 m/s, not the range asked 1 to 10 m/s"):
        carvallo.closed_loop_window(p, table, 1.0, 10.0)
    with pytest.raises(carvallo.ParameterError, match="gain table: k_steer_roll has 2 values for 3 speeds"):
        carvallo.closed_loop_window(p, dict(table, k_steer_roll=[0.0, 1.0]))
    with pytest.raises(carvallo.ParameterError, match="gain table: unknown gain `k_yaw`"):
        carvallo.closed_loop_window(p, {"speed": [0.0, 1.0], "k_yaw": [0.0, 1.0]})
    with pytest.raises(carvallo.ParameterError, match="speed 1 in row 2 does not increase"):
        carvallo.closed_loop_window(p, {"speed": [1.0, 1.0], "k_roll_roll": [0.0, 1.0]})
