"""Past one machine: batch propagation on dask arrays and validation sweeps on a dask.distributed cluster.

Needs the optional extra ``pip install 'orbits[dask]'`` (dask and distributed); nothing here is imported
by ``import orbits``.

- propagate_dask(r0, v0, mu, dt): dask (or NumPy) arrays in, lazy dask arrays (r, v) out. Each chunk goes
  through orbits.core.twobody.propagate.propagate, the same compiled kernel as a NumPy call, and every element
  is computed independently, so the values are bit for bit those of the single-process call.
- validate_sweep(scenes, client): one task per scene (orbits.validate.run.validate on that scene) on the
  client's workers; the report holds the same checks, values and errors as orbits.validate.run.validate (only
  the measured wall times differ).
- sweep_client(address): a Client of the scheduler at `address`, or of a LocalCluster on this machine.

Pointing it at a real cluster: start ``dask scheduler`` on one machine and ``dask worker tcp://HOST:8786``
on the others (each with orbits installed), then pass ``address="tcp://HOST:8786"`` (or
``orbits validate --sweep --scheduler tcp://HOST:8786``). To time a sweep, see
orbits.tools.bench.validate.bench_validate; results are in the README's benchmark section.
"""

import contextlib
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

if TYPE_CHECKING:
    import dask.array as da
    from dask.distributed import Client

    from orbits.validate.models import ModelScene
    from orbits.validate.run import ValidationReport
    from orbits.validate.scene import Scene

#: LocalCluster default: two single-threaded workers. They are threads of this process by default: worker
#: processes take longer to start, and each then imports orbits and compiles its heyoka integrators again,
#: which a sweep of the short built-in scenes does not win back (orbits.tools.bench.validate.bench_validate times
#: both). Processes pay off for sweeps of many long scenes; pass processes=True, or use a real cluster.
LOCAL_WORKERS = 2


def propagate_dask(r0: ArrayLike, v0: ArrayLike, mu: ArrayLike, dt: ArrayLike) -> "tuple[da.Array, da.Array]":
    """Lazy (r [m], v [m/s]) dask arrays at t0 + dt [s], chunk by chunk through orbits.core.twobody.propagate.

    r0, v0 have shape (..., 3) and broadcast with mu and dt over the batch shape, as in the NumPy call.
    The batch is chunked like the first input that spans it (dt, r0, v0, mu in that order), with the
    vector axis in one chunk.
    """
    import dask.array as da

    r0, v0, mu, dt = (da.asarray(x, dtype=float) for x in (r0, v0, mu, dt))
    batch = np.broadcast_shapes(r0.shape[:-1], v0.shape[:-1], mu.shape, dt.shape)
    chunks = _batch_chunks(batch, [(dt, dt.shape), (r0, r0.shape[:-1]), (v0, v0.shape[:-1]), (mu, mu.shape)])
    vectors = [da.broadcast_to(x, batch + (3,)).rechunk(chunks + ((3,),)) for x in (r0, v0)]
    scalars = [da.broadcast_to(x, batch)[..., None].rechunk(chunks + ((1,),)) for x in (mu, dt)]
    states = da.map_blocks(_propagate_block, *vectors, *scalars, chunks=chunks + ((6,),), dtype=float)
    return states[..., :3], states[..., 3:]


def _batch_chunks(batch, candidates):
    """Chunks of the first candidate array whose shape is the whole batch; dask's automatic ones otherwise."""
    import dask.array as da

    for array, shape in candidates:
        if shape == batch:
            return array.chunks[: len(batch)]
    return da.core.normalize_chunks("auto", batch, dtype=float)


def _propagate_block(r0, v0, mu, dt):
    """One chunk: (..., 6) array of r and v side by side."""
    from orbits.core.twobody.propagate import propagate

    r, v = propagate(r0, v0, mu[..., 0], dt[..., 0])
    return np.concatenate([r, v], axis=-1)


@contextlib.contextmanager
def sweep_client(
    address: str | None = None, workers: int = LOCAL_WORKERS, processes: bool = False
) -> "Iterator[Client]":
    """A dask.distributed Client: of the scheduler at `address`, or of a new LocalCluster of `workers`
    single-threaded workers (processes or threads), closed again on exit. A local cluster's dashboard takes a free
    port of the system's choosing, so two sweeps at once (or another dask on 8787) never collide."""
    from dask.distributed import Client, LocalCluster

    if address:
        with Client(address) as client:
            yield client
        return
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=processes, dashboard_address=":0") as cluster:
        with Client(cluster) as client:
            yield client


def validate_sweep(
    scenes: "Iterable[Scene | ModelScene]",
    client: "Client | None" = None,
    backend_names: Sequence[str] = ("rebound", "heyoka"),
    settings: dict[str, dict[str, object]] | None = None,
    progress: Callable[[str], object] | None = None,
) -> "ValidationReport":
    """ValidationReport of `scenes`, one task per scene on the client (a LocalCluster if None).

    `progress(scene_name)` is called as each scene's result arrives.
    """
    if client is None:
        with sweep_client() as own:
            return validate_sweep(scenes, own, backend_names, settings, progress)
    from dask.distributed import as_completed

    from orbits.validate.run import ValidationReport

    futures = [client.submit(_validate_one, s, tuple(backend_names), settings, pure=False) for s in scenes]
    if progress:
        for future in as_completed(futures):
            progress(future.result().name)
    return ValidationReport(scenes=client.gather(futures))


def _validate_one(scene, backend_names, settings):
    """SceneReport of one data or model scene, exactly as orbits.validate.run.validate makes it."""
    from orbits.validate.run import validate

    return validate([scene], backend_names, settings).scenes[0]
