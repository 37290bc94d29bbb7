"""Dask: chunk-wise propagation and validation sweeps give the single-process results exactly."""

import numpy as np
import pytest

da = pytest.importorskip("dask.array")
pytest.importorskip("distributed")

from orbits.core.twobody import elements  # noqa: E402
from orbits.core.twobody.propagate import propagate  # noqa: E402
from orbits.tools import distributed  # noqa: E402
from orbits.validate import models, scene  # noqa: E402
from orbits.validate import scenes as scenes_module  # noqa: E402
from orbits.validate.run import validate  # noqa: E402

MU = 3.986004418e14


def states(n, seed=0):
    rng = np.random.default_rng(seed)
    e = np.concatenate([rng.uniform(0, 0.9, n // 2), 1 + 10 ** rng.uniform(-4, 0.5, n - n // 2)])
    r0, v0 = elements.elements_to_state(7e6 * rng.uniform(1, 2, n), e, 0.3, 0.2, 0.1, rng.uniform(-1, 1, n), MU)
    return r0, v0, rng.uniform(-1e5, 1e5, n)


def test_propagate_dask_matches_numpy_bit_for_bit():
    r0, v0, dt = states(5000)
    r, v = distributed.propagate_dask(da.from_array(r0, chunks=(700, 3)), v0, MU, da.from_array(dt, chunks=700))
    assert isinstance(r, da.Array) and r.chunks[0][0] == 700 and r.shape == (5000, 3)
    r_dask, v_dask = da.compute(r, v)
    r_np, v_np = propagate(r0, v0, MU, dt)
    assert np.array_equal(r_dask, r_np) and np.array_equal(v_dask, v_np)


def test_propagate_dask_broadcasts_like_numpy():
    r0, v0, _ = states(6)
    dt = da.from_array(np.linspace(0, 1e4, 4), chunks=2)
    r, v = distributed.propagate_dask(r0[:, None, :], v0[:, None, :], MU, dt)
    r_np, v_np = propagate(r0[:, None, :], v0[:, None, :], MU, np.linspace(0, 1e4, 4))
    assert r.shape == (6, 4, 3) and np.array_equal(r.compute(), r_np) and np.array_equal(v.compute(), v_np)


def test_propagate_dask_raises_the_core_error_on_compute():
    r0, v0, dt = states(10)
    dt[3] = np.nan
    r, _ = distributed.propagate_dask(r0, v0, MU, da.from_array(dt, chunks=5))
    with pytest.raises(ValueError, match="not finite"):
        r.compute(scheduler="sync")


def comparable(report):
    """The report without what a re-run changes: wall and setup times, heyoka's compile-cache flag."""
    data = report.to_dict()
    for s in data["scenes"]:
        s.pop("wall_time_s"), s.pop("setup_time_s")
        s["settings"].get("heyoka", {}).pop("cache_hit", None)
    return data


@pytest.mark.parametrize("processes", [False, True])
def test_sweep_on_a_local_cluster_gives_the_sequential_report(processes, monkeypatch):
    """The same settings in every process give the same report to the last bit. The settings are pinned here to the
    NumPy path (ORBITS_JIT=0, which worker processes inherit): under the default, a process whose kernel cache
    differs (a worker on another machine, or one that has not loaded a kernel) runs the compiled path, whose last
    bits differ within the solvers' stated accuracy."""
    from orbits.core import _fast

    monkeypatch.setenv("ORBITS_JIT", "0")
    previous = _fast.set_enabled(False)
    try:
        scenes = [scene.load(name) for name in ("circular", "flyby")]
        scenes += [scenes_module.load(models.builtin_names()[0])]
        expected = comparable(validate(scenes))
        seen = []
        with distributed.sweep_client(workers=2, processes=processes) as client:
            report = distributed.validate_sweep(scenes, client, progress=seen.append)
    finally:
        _fast.set_enabled(previous)
    assert comparable(report) == expected and sorted(seen) == sorted(s.name for s in scenes)
