"""Batches beyond one process: `simulate_many` on chunks of a batch gives the batch's rows bit
for bit (whatever the chunk's memory layout), and the basin-of-stability map of
docs/examples/basin_dask.py computed over a dask.distributed LocalCluster of two worker
processes equals the single-process `simulate_many` of the whole grid bit for bit. dask and
distributed are installed by scripts/test; a missing one is an error, not a skip."""

import importlib.util
import pathlib
import re

import carvallo
import numpy as np
from distributed import Client, LocalCluster, get_task_stream

ROOT = pathlib.Path(__file__).resolve().parents[3]

SPEC = importlib.util.spec_from_file_location("basin_dask", ROOT / "docs" / "examples" / "basin_dask.py")
basin = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(basin)

# A small map across the benchmark's stable window (4.29 to 6.02 m/s): 35 runs of 3 s.
SPEEDS = np.linspace(1.0, 7.0, 7)
LEANS = np.linspace(0.02, 0.4, 5)
KW = dict(duration=3.0, fall=0.5)


def same(a: dict, b: dict) -> None:
    """Every column equal bit for bit (NaN where NaN: the event time of a run without event)."""
    for key in basin.COLUMNS:
        assert a[key].dtype == b[key].dtype, key
        assert np.array_equal(a[key], b[key], equal_nan=a[key].dtype.kind == "f"), key
    assert a["errors"] == b["errors"]


def test_chunks_of_a_batch_equal_the_batch_bit_for_bit():
    p = carvallo.benchmark()
    v, lean0 = basin.grid(SPEEDS, LEANS)
    whole = carvallo.simulate_many(p, v, lean0, **basin.options(**KW))
    parts = [carvallo.simulate_many(p, v[s], lean0[s], **basin.options(**KW))
             for s in basin.chunks(v.size, 6)]
    same(basin.assemble(parts, v.shape), basin.assemble([whole], v.shape))
    # A strided slice, a list and a misaligned copy (as a buffer received over a network can
    # be) read the same values.
    misaligned = np.frombuffer(bytearray(8 * v.size + 1), dtype=np.float64, offset=1)
    misaligned[:] = v
    assert not misaligned.flags.aligned
    for speeds in (v[::2], list(v[::2]), misaligned[::2]):
        m = carvallo.simulate_many(p, speeds, lean0[::2], **basin.options(**KW))
        for key in basin.COLUMNS:
            assert np.array_equal(m[key], whole[key][::2], equal_nan=m[key].dtype.kind == "f"), key
    assert whole["fell"].any() and not whole["fell"].all()


def test_basin_map_over_two_dask_workers_equals_one_process():
    p = carvallo.benchmark()
    local = basin.basin_map_local(p, SPEEDS, LEANS, **KW)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster, timeout=60) as client:
        client.wait_for_workers(2, timeout=60)
        # The workers are other processes importing the same installed wheel.
        files = client.run(lambda: (carvallo.__file__, __import__("os").getpid()))
        assert {f for f, _ in files.values()} == {carvallo.__file__}
        assert len({pid for _, pid in files.values()}) == 2
        with get_task_stream(client) as ts:
            m = basin.basin_map(client, p, SPEEDS, LEANS, chunk=4, timeout=120, **KW)
        assert len(ts.data) == 9 and len({t["worker"] for t in ts.data}) == 2
    assert m["fell"].shape == (7, 5)
    same(m, local)
    # The map itself: at 1 m/s every start falls, the sooner the larger the lean (from 0.02 rad
    # the fork reaches its steer lock before the lean reaches 0.5 rad); at 5 m/s (inside the
    # stable window) the leans up to 0.305 rad recover, 0.4 rad does not.
    when = np.where(np.isnan(m["event_t"]), m["steer_lock_t"], m["event_t"])
    assert m["fell"][0].all() and (np.diff(when[0]) < 0).all()
    assert not np.isnan(m["steer_lock_t"][0, 0])
    assert m["fell"][4].tolist() == [False, False, False, False, True]
    assert (when[m["fell"]] > 0).all() and np.isnan(when[~m["fell"]]).all()


def test_the_guide_shows_the_function_as_written():
    """The performance chapter's ```python block of the Dask section is basin_map verbatim."""
    guide = (ROOT / "docs" / "guide" / "src" / "performance.md").read_text()
    section = guide.split("\n## Beyond one machine: Dask\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", section, flags=re.S)
    assert len(blocks) == 1 and "def basin_map(" in blocks[0]
    assert blocks[0] in (ROOT / "docs" / "examples" / "basin_dask.py").read_text()
