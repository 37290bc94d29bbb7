"""Compiled Kepler kernels (orbits/core/twobody/_fast_kepler.py) and their NumPy fallback, side by side.

tests/core/test_kepler.py runs against whichever implementation is active (the compiled one when numba
is installed); here the NumPy fallback is checked against mpmath as well, the two are compared on large
random batches, and the loading rules (lazy numba import, disk cache, threads) are checked.
"""

import json
import math
import os
import subprocess
import sys

import mpref
import numpy as np
import pytest

from orbits.core import _fast
from orbits.core.errors import OrbitDomainError
from orbits.core.twobody import kepler
from orbits.tools.reference import kepler_E_ulps, kepler_H_ulps

pytest.importorskip("numba")


@pytest.fixture
def numpy_only():
    previous = _fast.set_enabled(False)
    yield
    _fast.set_enabled(previous)


def ulps_apart(a, b):
    return np.max(np.abs(a - b) / np.spacing(np.maximum(np.abs(a), np.abs(b))))


def elliptic_batch(rng, n):
    """Generic, singular-corner, near-pi and huge-M pairs (M, e)."""
    M = np.concatenate(
        [
            rng.uniform(-20, 20, n),
            10 ** rng.uniform(-16, -3, n),
            math.pi - 10 ** rng.uniform(-15, 0, n),
            10 ** rng.uniform(3, 15, n),
        ]
    )
    e = np.concatenate(
        [
            rng.uniform(0, 1, n),
            1 - 10 ** rng.uniform(-16, -9, n),
            1 - 10 ** rng.uniform(-16, -1, n),
            rng.uniform(0, 1, n),
        ]
    )
    return M, e


def hyperbolic_batch(rng, n):
    M = np.concatenate([10 ** rng.uniform(-10, 6, n), 10 ** rng.uniform(-12, 1, n), 10 ** rng.uniform(6, 300, n)])
    e = 1 + np.concatenate([10 ** rng.uniform(-3, 6, n), 10 ** rng.uniform(-15, -3, n), 10 ** rng.uniform(-15, 12, n)])
    return M, e


def test_compiled_and_numpy_agree_to_a_few_ulp():
    rng = np.random.default_rng(21)
    M, e = elliptic_batch(rng, 50_000)
    Mh, eh = hyperbolic_batch(rng, 20_000)
    W = np.concatenate([10 ** rng.uniform(-300, 300, 20_000), -(10 ** rng.uniform(-5, 5, 20_000))])
    results = {}
    previous = _fast.set_enabled(True)
    try:
        for path in (True, False):  # the kernels at every batch size, then the NumPy implementation
            _fast.set_enabled(path)
            results[path] = (kepler.eccentric_anomaly(M, e), kepler.hyperbolic_anomaly(Mh, eh),
                             kepler.parabolic_anomaly(W))
    finally:
        _fast.set_enabled(previous)
    for compiled, reference in zip(results[True], results[False]):
        assert ulps_apart(compiled, reference) <= 4


@pytest.mark.parametrize("seed", [31, 32])
def test_numpy_fallback_within_4_ulp_of_mpmath(numpy_only, seed):
    rng = np.random.default_rng(seed)
    M, e = elliptic_batch(rng, 25)
    E = kepler.eccentric_anomaly(M, e)
    assert max(float(mpref.ulp_error(x, mpref.kepler_E(m, ee))) for x, m, ee in zip(E, M, e)) <= 4
    M, e = hyperbolic_batch(rng, 25)
    H = kepler.hyperbolic_anomaly(M, e)
    assert max(float(mpref.ulp_error(x, mpref.kepler_H(m, ee))) for x, m, ee in zip(H, M, e)) <= 4
    W = 10 ** rng.uniform(-300, 300, 50)
    assert max(float(mpref.ulp_error(x, mpref.barker_D(w))) for x, w in zip(kepler.parabolic_anomaly(W), W)) <= 2


def test_benchmark_sets_within_2_ulp_of_mpmath():
    """The compiled pass-1 pipeline certifies its results: worst cases on the benchmark's three sets."""
    rng = np.random.default_rng(41)
    easy_M, easy_e = rng.uniform(0, 2 * np.pi, 300), rng.uniform(0, 0.99, 300)
    offset = 10 ** rng.uniform(-12, -3, 300)
    hard_M, hard_e = np.where(np.arange(300) % 2 == 0, offset, np.pi - offset), 1 - 10 ** rng.uniform(-9, -2, 300)
    for M, e in ((easy_M, easy_e), (hard_M, hard_e)):
        E = kepler.eccentric_anomaly(M, e)
        assert max(kepler_E_ulps(x, m, ee) for x, m, ee in zip(E, M, e)) <= 2
    M, e = 10 ** rng.uniform(-6, 6, 300), 1 + 10 ** rng.uniform(-9, 3, 300)
    H = kepler.hyperbolic_anomaly(M, e)
    assert max(kepler_H_ulps(x, m, ee) for x, m, ee in zip(H, M, e)) <= 2


@pytest.mark.parametrize(
    "call, fragment",
    [
        (lambda: kepler.eccentric_anomaly(np.full(5, 0.5), np.array([0.1, 0.2, 1.0, 0.3, 0.4])), "parabolic_anomaly"),
        (lambda: kepler.eccentric_anomaly(np.array([0.5, np.nan]), 0.5), "not finite"),
        (lambda: kepler.eccentric_anomaly(np.array([0.5, 1e300]), 0.5), "too large"),
        (lambda: kepler.hyperbolic_anomaly(np.array([0.5, 1.0]), np.array([2.0, 1.0])), "outside (1.0, inf)"),
        (lambda: kepler.parabolic_anomaly(np.array([1.0, np.inf])), "not finite"),
    ],
)
def test_invalid_batches_raise_the_numpy_message(call, fragment):
    with pytest.raises(OrbitDomainError, match=fragment.replace("(", r"\(").replace(")", r"\)")):
        call()


def test_threads_do_not_change_a_bit():
    rng = np.random.default_rng(51)
    n = 4 * _fast.PARALLEL_MIN
    M, e = rng.uniform(-10, 10, n), rng.uniform(0, 1, n)
    previous = _fast.set_num_threads(1)
    try:
        single = kepler.eccentric_anomaly(M, e)
        _fast.set_num_threads(4)
        split = kepler.eccentric_anomaly(M, e)
    finally:
        _fast.set_num_threads(previous)
    assert np.array_equal(single, split)


def test_run_splits_into_contiguous_chunks():
    seen = []

    def kernel(start, stop, out):
        seen.append((start, stop))
        out[start:stop] = 1.0
        return stop - start

    out = np.zeros(5 * _fast.PARALLEL_MIN)
    previous = _fast.set_num_threads(3)
    try:
        assert _fast.run(kernel, out.size, out) == out.size
    finally:
        _fast.set_num_threads(previous)
    assert seen[0] == (0, 0)  # the first call, in the calling thread: it compiles or loads the kernel
    chunks = sorted(seen[1:])
    assert chunks[0][0] == 0 and chunks[-1][1] == out.size and len(chunks) == 3 and out.all()
    assert all(a[1] == b[0] for a, b in zip(chunks, chunks[1:]))


def test_run_goes_in_rounds_of_at_most_round_elements_a_thread():
    """Python runs between rounds, where a Ctrl-C is raised (tests/validation/test_interrupt.py)."""
    seen = []

    def kernel(start, stop, out):
        seen.append((start, stop))
        out[start:stop] += 1.0
        return 0

    out = np.zeros(7 * _fast.ROUND + 5)
    for threads in (1, 2):
        seen.clear()
        previous = _fast.set_num_threads(threads)
        try:
            assert _fast.run(kernel, out.size, out) == 0
        finally:
            _fast.set_num_threads(previous)
        chunks = sorted(c for c in seen if c[0] < c[1])
        assert max(b - a for a, b in chunks) <= _fast.ROUND and chunks[0][0] == 0 and chunks[-1][1] == out.size
        assert all(a[1] == b[0] for a, b in zip(chunks, chunks[1:]))
    np.testing.assert_array_equal(out, 2.0)  # every element once a run


def run_python(code, **env):
    environment = {**os.environ, **env}
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=environment, check=True)
    return result.stdout


def test_import_orbits_and_the_core_do_not_import_numba():
    code = ("import sys, orbits, orbits.core.twobody.kepler, orbits.core.twobody.propagate; "
            "print('numba' in sys.modules)")
    assert run_python(code).strip() == "False"


def test_orbits_jit_0_runs_numpy_without_numba():
    code = ("import sys; from orbits.core.twobody import kepler; kepler.eccentric_anomaly(1, 0.5); "
            "print('numba' in sys.modules)")
    assert run_python(code, ORBITS_JIT="0").strip() == "False"


def test_a_small_query_waits_for_no_compile_and_a_cached_kernel_serves_any_size(tmp_path):
    """The default ("auto"): on an empty cache a calculator query takes the NumPy path without importing numba; a
    batch of AUTO_MIN_BATCH elements compiles the kernel, saying so once on stderr; from then on a fresh process
    runs the cached kernel for a one-element query, loading it (a cache hit), compiling nothing."""
    cache = {"NUMBA_CACHE_DIR": str(tmp_path)}
    small = ("import sys; from orbits.core.twobody import kepler; kepler.eccentric_anomaly([0.1, 1.0], 0.5); "
             "kepler.hyperbolic_anomaly(3.0, 2.0); kepler.parabolic_anomaly(1.0); print('numba' in sys.modules)")
    assert run_python(small, **cache).strip() == "False"
    large = ("import sys, numpy as np; from orbits.core import _fast; from orbits.core.twobody import kepler; "
             "kepler.eccentric_anomaly(np.linspace(0, 3, _fast.AUTO_MIN_BATCH), 0.5); print('numba' in sys.modules)")
    result = subprocess.run([sys.executable, "-c", large], capture_output=True, text=True, check=True,
                            env={**os.environ, **cache})
    assert result.stdout.strip() == "True"
    assert [line for line in result.stderr.splitlines() if line.startswith("orbits: compiling")] != []
    one = ("import json; from orbits.core.twobody import kepler; E = kepler.eccentric_anomaly(1.0, 0.5); "
           "from orbits.core.twobody import _fast_kepler as k; "
           "print(json.dumps([float(E), sum(k.elliptic.stats.cache_hits.values()), "
           "sum(k.elliptic.stats.cache_misses.values())]))")
    result = subprocess.run([sys.executable, "-c", one], capture_output=True, text=True, check=True,
                            env={**os.environ, **cache})
    value, hits, misses = json.loads(result.stdout)
    assert (hits, misses) == (1, 0) and "compiling" not in result.stderr
    assert abs(value - kepler.eccentric_anomaly(1.0, 0.5)) <= 4 * np.spacing(value)  # either path: within 4 ulp


def test_disk_cache_is_written_then_loaded(tmp_path):
    code = (
        "import json; from orbits.core import _fast; from orbits.core.twobody import kepler, _fast_kepler; "
        "kepler.parabolic_anomaly(1.0); "
        "print(json.dumps([_fast.cache_dir(), sum(_fast_kepler.parabolic.stats.cache_hits.values())]))"
    )
    folder, hits = json.loads(run_python(code, NUMBA_CACHE_DIR=str(tmp_path), ORBITS_JIT="1"))
    written = [name for _, _, names in os.walk(folder) for name in names]
    assert folder.startswith(str(tmp_path)) and any(name.startswith("_fast_kepler.parabolic") for name in written)
    folder_again, hits_again = json.loads(run_python(code, NUMBA_CACHE_DIR=str(tmp_path), ORBITS_JIT="1"))
    assert hits == 0 and folder_again == folder and hits_again == 1


def test_cache_folder_skips_unwritable_roots(tmp_path):
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    assert _fast.first_writable([str(blocker / "sub"), str(tmp_path)], "orbits-x") == str(tmp_path / "orbits-x")
    assert _fast.first_writable([str(blocker / "sub")], "orbits-x") is None


def test_read_only_install_falls_back_to_the_temporary_folder(tmp_path):
    """With NUMBA_CACHE_DIR, the package folder and the user cache all unwritable, the cache goes to /tmp.
    (Tests run as root, for whom permissions do not stop writes: unwritable here means under a file.)"""
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    code = (
        "import os, orbits.core._fast as f; real = f.first_writable; "
        "home = os.path.dirname(f.__file__); "
        "f.first_writable = lambda roots, name: real([r for r in roots if not r.startswith(home)], name); "
        "from orbits.core.twobody import kepler; print(kepler.parabolic_anomaly(1.0), f.cache_dir())"
    )
    value, folder = run_python(
        code, NUMBA_CACHE_DIR=str(blocker / "x"), XDG_CACHE_HOME=str(blocker / "y"), TMPDIR=str(tmp_path)
    ).split()
    assert float(value) == kepler.parabolic_anomaly(1.0) and folder.startswith(str(tmp_path / "orbits-"))


def cache_folder(**env):
    """The kernels' cache folder a fresh process picks, with NUMBA_CACHE_DIR unset and `env` set."""
    environment = {k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "XDG_CACHE_HOME")}
    code = "import orbits.core._fast as f; print(f.cache_dir())"
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            env={**environment, **env}, check=True)
    return result.stdout.strip()


def test_the_cache_lives_in_the_users_cache_folder(tmp_path):
    """XDG on Linux: $XDG_CACHE_HOME/orbits, else ~/.cache/orbits (a relative XDG_CACHE_HOME is invalid and
    ignored); never the package folder while the user's folder is writable (a system-wide install cannot write
    there)."""
    assert cache_folder(XDG_CACHE_HOME=str(tmp_path / "xdg")).startswith(str(tmp_path / "xdg" / "orbits" / "orbits-"))
    home = tmp_path / "home"
    assert cache_folder(HOME=str(home)).startswith(str(home / ".cache" / "orbits" / "orbits-"))
    assert cache_folder(HOME=str(home), XDG_CACHE_HOME="relative/cache").startswith(str(home / ".cache" / "orbits"))
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    package = os.path.dirname(_fast.__file__)
    assert cache_folder(XDG_CACHE_HOME=str(blocker)).startswith(os.path.join(package, "__pycache__", "orbits-"))


def test_one_compilation_for_read_only_and_broadcast_inputs():
    """Read-only, broadcast, scalar and empty inputs all reach the kernel as one array type: one signature."""
    from orbits.core.twobody import _fast_kepler

    previous = _fast.set_enabled(True)
    try:
        M = np.linspace(0.0, 3.0, 10)
        M.flags.writeable = False
        kepler.eccentric_anomaly(M, 0.5)
        kepler.eccentric_anomaly(np.broadcast_to(M, (2, 10)), np.array([[0.1], [0.2]]))
        kepler.eccentric_anomaly(1.0, 0.5)
        kepler.eccentric_anomaly(*np.broadcast_arrays(np.zeros(0), 0.5))  # an empty broadcast view: copied, no warning
    finally:
        _fast.set_enabled(previous)
    assert len(_fast_kepler.elliptic.signatures) == 1


def test_results_do_not_depend_on_where_the_arrays_lie():
    """Inputs and outputs adjacent in one buffer, offset by 0 to 3 elements, give the results of separate arrays
    (the kernels loop over views, whatever the layout; their speed is the benchmark's alignment row)."""
    from orbits.core.twobody import _fast_kepler

    rng = np.random.default_rng(61)
    n = 5000
    M, e = rng.uniform(-10, 10, n), rng.uniform(0, 1, n)
    expected = np.empty(n)
    assert _fast_kepler.elliptic(0, n, M, e, expected) == 0
    for offset in range(4):
        buffer = np.empty(3 * n + 4)
        a, b, out = buffer[:n], buffer[n:2 * n], buffer[2 * n + offset:3 * n + offset]
        a[:], b[:] = M, e
        assert _fast_kepler.elliptic(0, n, a, b, out) == 0 and np.array_equal(out, expected)


def test_a_warm_call_reads_no_kernels_code(monkeypatch):
    """The check that a kernel's cached code is its own walked all 101 kernels' signatures on every call (25 us of
    a 40-70 us one-element call); it now runs only when the kernel ran gained a signature."""
    pytest.importorskip("numba")
    from orbits.core.twobody import kepler

    previous = _fast.set_enabled(True)
    try:
        kepler.eccentric_anomaly(np.array([1.0]), np.array([0.5]))  # compiled or loaded, and read, here
        reads = []
        monkeypatch.setattr(_fast, "_mismatched", lambda: reads.append(1))
        for _ in range(3):
            kepler.eccentric_anomaly(np.array([1.0]), np.array([0.5]))
        assert reads == []
    finally:
        _fast.set_enabled(previous)
