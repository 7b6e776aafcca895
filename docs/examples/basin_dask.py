"""A basin-of-stability map of a bicycle computed over a dask.distributed cluster.

Each point of a grid over speed x initial lean is one simulation of the nonlinear bicycle
(upright straight running at that speed, released with that lean) until `duration` seconds or
the event `lean=+-fall`; the map says whether it fell (the event, the fork reaching its steer
lock first, or the contact lost) and when (`event_t`, or `steer_lock_t`). The grid is cut into chunks (slices of the flattened grid); each chunk is one call of
`carvallo.simulate_many` on a Dask worker (the GIL released, the chunk's runs in parallel on
the worker's cores), and the chunks' arrays are concatenated in their order. The runs share
nothing, so the map equals the single-process `carvallo.simulate_many` of the whole grid bit
for bit (crates/carvallo-py/tests/test_dask.py checks it on a LocalCluster of two worker
processes).

    python docs/examples/basin_dask.py [--speeds 40] [--leans 30] [--workers 2] [--png FILE]

starts a LocalCluster, prints the points per second over Dask and in one process, and draws
the map into FILE when given (matplotlib).
"""

import argparse
import time

import carvallo
import numpy as np

# The arrays of `simulate_many` kept in the map (one value per point).
COLUMNS = ("fell", "event_t", "steer_lock_t", "t_end", "lean", "steer", "lean_rate", "steer_rate",
           "ok")


def grid(speeds, leans):
    """The flattened grid, speed major: (speed of each point, initial lean of each point)."""
    v, lean0 = np.meshgrid(np.asarray(speeds, float), np.asarray(leans, float), indexing="ij")
    return v.ravel(), lean0.ravel()


def chunks(n, size):
    """Slices of at most `size` points covering 0..n in order."""
    return [slice(k, min(k + size, n)) for k in range(0, n, size)]


def options(duration, fall, method="dop853", rtol=1e-8):
    """The keyword arguments of `simulate_many` for the map: until `duration` s or |lean| = fall."""
    return dict(duration=duration, method=method, rtol=rtol, stop_when=[f"lean=±{fall}"])


def assemble(parts, shape):
    """The chunks' dicts concatenated in order, each column reshaped to the grid's shape."""
    out = {k: np.concatenate([p[k] for p in parts]).reshape(shape) for k in COLUMNS}
    out["errors"] = [e for p in parts for e in p["errors"]]
    return out


def basin_map(client, params, speeds, leans, duration=5.0, fall=0.5, chunk=64, timeout=600,
              **kw):
    """The map over the cluster of `client`: a dict of arrays of shape (len(speeds),
    len(leans)) (`fell`, `event_t`, ... as COLUMNS) and the list `errors`. The function sent
    to the workers is `carvallo.simulate_many` itself (pickled by name), so every worker runs
    the `carvallo` installed in its own environment; `timeout` (s) bounds the wait."""
    from distributed import wait

    v, lean0 = grid(speeds, leans)
    parts = chunks(v.size, chunk)
    futures = client.map(carvallo.simulate_many, [params] * len(parts),
                         [v[s] for s in parts], [lean0[s] for s in parts],
                         pure=False, **options(duration, fall, **kw))
    wait(futures, timeout=timeout)
    return assemble(client.gather(futures), (len(speeds), len(leans)))


def basin_map_local(params, speeds, leans, duration=5.0, fall=0.5, **kw):
    """The same map from one call of `simulate_many` in this process (its own threads)."""
    v, lean0 = grid(speeds, leans)
    return assemble([carvallo.simulate_many(params, v, lean0, **options(duration, fall, **kw))],
                    (len(speeds), len(leans)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--speeds", type=int, default=40, help="grid points over 0.5..8 m/s")
    ap.add_argument("--leans", type=int, default=30, help="grid points over 0.01..0.45 rad")
    ap.add_argument("--workers", type=int, default=2, help="worker processes (one thread each)")
    ap.add_argument("--chunk", type=int, default=64, help="points per task")
    ap.add_argument("--png", help="draw the map into this file")
    a = ap.parse_args()
    from distributed import Client, LocalCluster

    params = carvallo.benchmark()
    speeds, leans = np.linspace(0.5, 8.0, a.speeds), np.linspace(0.01, 0.45, a.leans)
    n = speeds.size * leans.size
    with LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        client.wait_for_workers(a.workers, timeout=60)
        basin_map(client, params, speeds[:2], leans[:2], chunk=a.chunk)  # warm the workers
        t0 = time.perf_counter()
        m = basin_map(client, params, speeds, leans, chunk=a.chunk)
        dask_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    local = basin_map_local(params, speeds, leans)
    local_s = time.perf_counter() - t0
    same = all(np.array_equal(m[k], local[k], equal_nan=m[k].dtype.kind == "f") for k in COLUMNS)
    print(f"{n} points, {a.workers} workers, chunks of {a.chunk}: {n / dask_s:.0f} points/s over "
          f"Dask ({dask_s:.2f} s), {n / local_s:.0f} points/s in one process ({local_s:.2f} s); "
          f"fell: {int(m['fell'].sum())}; equal bit for bit: {same}")
    if a.png:
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 3.6), dpi=80)
        when = np.where(np.isnan(m["event_t"]), m["steer_lock_t"], m["event_t"])
        t = np.where(m["fell"], np.nan_to_num(when, nan=0.0), np.nan)
        im = ax.pcolormesh(speeds, leans, t.T, shading="nearest", cmap="viridis")
        ax.pcolormesh(speeds, leans, np.where(m["fell"], np.nan, 1.0).T, shading="nearest",
                      cmap="Greys", vmin=0, vmax=4)
        fig.colorbar(im, ax=ax, label="time of the fall (s)")
        ax.set(xlabel="speed (m/s)", ylabel="initial lean (rad)",
               title="benchmark: fell in 5 s (|lean| = 0.5 rad or steer lock)? grey: no")
        fig.tight_layout()
        fig.savefig(a.png)


if __name__ == "__main__":
    main()
