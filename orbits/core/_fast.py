"""Compiled kernels: loading numba lazily, its on-disk cache, and splitting a batch over the cores.

The kernels (orbits/core/**/_fast_*.py) are numba functions compiled with
``cache=True``: the first call ever compiles them, once per machine and version; every later process
loads the machine code from the on-disk cache. numba itself is imported only when a kernel is first
needed, never by ``import orbits`` or ``orbits --help``; a first call in a fresh process still pays for
importing numba and initialising its CPU target (timings: the README's Benchmarks section).

Where the cache lives: a folder ``orbits-<digest>`` under the first writable of ``NUMBA_CACHE_DIR`` (if
set), the user's cache folder (``$XDG_CACHE_HOME`` or ``~/.cache`` on Linux)/orbits, the package's own
``orbits/core/__pycache__`` (a fallback: a system-wide install cannot write there) and the system temporary folder;
if none is writable (a read-only install with no writable home or /tmp) the
kernels compile in memory for the session. The digest hashes the kernels' source files and the
modules they take constants from: numba checks only the file that defines a cached function, so
without it a change to a helper or a constant in another file would load stale machine code.

Settings, read once per process:
- ``ORBITS_JIT`` chooses when the compiled kernels run: ``auto`` (the default) runs a kernel whose machine code is
  ready (loaded in this process or in the disk cache: ``ready``) for a batch of any size, and compiles an absent
  one only for a batch of at least AUTO_MIN_BATCH elements, so that a calculator query never waits for a compile
  (``orbits info --compile`` compiles them all ahead: ``orbits.tools.kernels``); ``1`` always; ``0`` never. The
  float64 NumPy implementations (tested against the same mpmath references) run otherwise, and when numba is not
  installed.
- ``ORBITS_NUM_THREADS`` caps the threads a large batch is split over (default: the cores this process
  may run on). The kernels release the GIL, and every element is computed independently, so the
  result does not depend on the split.
"""

import hashlib
import importlib.util
import os
import pickle
import shutil
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

#: Smallest batch worth a second thread: below it the hand-off to the thread pool outweighs the gain.
PARALLEL_MIN = 1 << 15

#: Most elements a thread computes before Python runs again (a pending Ctrl-C is raised then): at most 0.1 s of the
#: slowest kernels (a 20-revolution Lambert transfer, the transition matrix), 7 ms of propagation, 1 ms of Kepler's
#: equation (one thread, measured with orbits.core's solvers on 65,536 random elements).
ROUND = 1 << 16

#: Modules of orbits/core (paths under it) whose constants the kernels (orbits/core/**/_fast*.py) compile in.
_KERNEL_DEPENDENCIES = ("twobody/_kepler_shared.py", "twobody/_propagate_shared.py",
                        "manoeuvres/_lambert_shared.py", "_dop853_shared.py", "_roots.py", "series.py")

#: Batches from this size on compile an absent kernel ("auto" mode); smaller ones, such as a calculator query, run
#: a kernel only when its machine code is ready, and the NumPy implementation otherwise (the same algorithm and
#: accuracy: tests/core/test_fast_kepler.py, test_propagate.py, test_propagate_long_flights.py) without numba.
AUTO_MIN_BATCH = 1 << 16

#: The kernels the solvers start, by module under orbits.core: what `ready` looks for, `orbits info` reports and
#: orbits.tools.kernels compiles ahead.
ENTRY_KERNELS = {
    "twobody._fast_kepler": ("elliptic", "hyperbolic", "parabolic"),
    "twobody._fast_propagate": ("propagate",),
    "twobody._fast_transition": ("transition",),
    "manoeuvres._fast_lambert": ("solve",),
    "periodic._fast_cr3bp": ("integrate",),
}

def entry_kernels():
    """Every entry kernel's name ("twobody._fast_kepler.elliptic"), in ENTRY_KERNELS' order."""
    return [f"{module}.{name}" for module, names in ENTRY_KERNELS.items() for name in names]


_state = {"mode": None, "threads": None, "pool": None, "cache_dir": None, "announced": set(), "kernels": [],
          "checked": {}, "ready": {}, "numba": None}


def _mode():
    """"auto", True (always the kernels) or False (never): ORBITS_JIT (auto by default; 0 off, 1 always)."""
    if _state["mode"] is None:
        value = os.environ.get("ORBITS_JIT", "auto").strip().lower()
        _state["mode"] = False if value in ("0", "false", "no", "off") else (True if value in ("1", "true", "yes", "on")
                                                                             else "auto")
    return _state["mode"]


def _numba_installed():
    """Whether numba can be imported (looked up once per process: the lookup reads the file system)."""
    if _state["numba"] is None:
        _state["numba"] = importlib.util.find_spec("numba") is not None
    return _state["numba"]


def use(n, kernel):
    """Whether a batch of n elements runs the compiled `kernel` ("twobody._fast_kepler.elliptic": module under
    orbits.core, then name): never with ORBITS_JIT=0 or without numba, always with ORBITS_JIT=1 (or
    set_enabled(True)), and in the default "auto" mode when it is ready (any n) or n >= AUTO_MIN_BATCH."""
    mode = _mode()
    if mode is False or (mode == "auto" and n < AUTO_MIN_BATCH and not ready(kernel)):
        return False
    return _numba_installed() and _numba_imports()


def kernel_array(x):
    """x as the array type every kernel takes, a writable C-contiguous float64 array: x itself when it is one, else a
    copy (one array type per kernel, so numba compiles it once). A broadcast view is copied whatever its flags say
    (zero strides: one element stands for many), also when it holds one element or none."""
    x = np.asarray(x, dtype=float)
    if not (x.base is not None and 0 in x.strides) and x.flags.c_contiguous and x.flags.writeable:  # strides first:
        return x  # reading a broadcast view's writeable flag warns
    return np.array(x, dtype=float, order="C")


def ready(kernel):
    """Whether the compiled `kernel` runs without compiling: loaded in this process, or its machine code filed in
    the disk cache for this Python (looked up once per process, without importing numba). A cache written by
    another CPU model is filed but not loadable, and compiles again on first use."""
    known = _state["ready"].get(kernel)
    if known is None:
        folder = cache_dir()
        module, _, name = kernel.rpartition(".")
        index = f"*/{module.rpartition('.')[2]}.{name}-*.py{sys.version_info[0]}{sys.version_info[1]}.nbi"
        known = _state["ready"][kernel] = folder is not None and any(Path(folder).glob(index))
    return known


def _mark_ready(kernel):
    """Remember that a kernel (a numba dispatcher) has run in this process: later calls of any size may use it."""
    module = kernel.py_func.__module__.removeprefix("orbits.core.")
    _state["ready"][f"{module}.{kernel.py_func.__qualname__}"] = True


def enabled():
    """Whether the compiled kernels may run at all: ORBITS_JIT is not 0 and numba imports (imported here)."""
    return _mode() is not False and _numba_installed() and _numba_imports()


def set_enabled(flag):
    """Use the compiled kernels always (True), never (False) or from AUTO_MIN_BATCH on ("auto"); returns the
    previous mode, to restore it."""
    previous = _mode()
    _state["mode"] = flag if flag == "auto" else bool(flag)
    return previous


def announce(module):
    """Say once on stderr that the kernels of `module` compile now (nothing of them in the disk cache yet)."""
    folder = cache_dir()
    if module in _state["announced"]:
        return
    _state["announced"].add(module)
    if folder is None or not any(Path(folder).rglob(f"{module}.*.nbi")):
        kept = "see orbits info for where" if folder else "kept in memory for this run"
        print(f"orbits: compiling the {module.strip('_').replace('fast_', '').replace('_', ' ')} kernels, once "
              f"({kept})", file=sys.stderr)


def _numba_imports():
    try:
        import numba  # noqa: F401
    except ImportError:
        return False
    return True


def num_threads():
    """Threads a large batch is split over: ORBITS_NUM_THREADS, else the cores this process may use."""
    if _state["threads"] is None:
        try:
            cores = len(os.sched_getaffinity(0))
        except AttributeError:  # not on Linux
            cores = os.cpu_count() or 1
        _state["threads"] = max(1, int(os.environ.get("ORBITS_NUM_THREADS", cores)))
    return _state["threads"]


def set_num_threads(n):
    """Split large batches over at most n threads from now on; returns the previous value."""
    previous = num_threads()
    _state["threads"] = max(1, int(n))
    return previous


def jit(function=None, *, inline=False, contract=False):
    """numba.njit(function) with the options every kernel uses, cached on disk where possible.

    inline=True inlines a helper into its callers at numba IR level, which LLVM needs to vectorise a
    loop that calls it (the elliptic solver is an order of magnitude slower without).
    error_model="numpy" (IEEE results, no ZeroDivisionError branches, which would also stop LLVM from
    vectorising the loops), nogil (threads run in parallel), no fastmath: the double-double arithmetic
    needs every rounding as written, without reassociation. contract=True lets LLVM fuse a * b + c into
    one FMA (one rounding instead of two, never less accurate), for loops free of error-free
    transformations only (in (a - p) - err with p = a * b, a fused a - p would count err twice):
    helpers inlined into such a loop take its flags.
    """
    if function is None:
        return lambda f: jit(f, inline=inline, contract=contract)
    import numba

    options = {"error_model": "numpy", "nogil": True, "inline": "always" if inline else "never"}
    if contract:
        options["fastmath"] = {"contract"}
    folder = cache_dir()
    if folder is None:
        return numba.njit(**options)(function)
    previous, numba.config.CACHE_DIR = numba.config.CACHE_DIR, folder  # read when the decorator runs
    try:
        kernel = numba.njit(cache=True, **options)(function)
    finally:
        numba.config.CACHE_DIR = previous
    _state["kernels"].append(kernel)  # its cached code is checked against its name (run)
    return kernel


def cache_dir():
    """The folder of the compiled kernels' cache (see the module docstring), or None if none is writable."""
    if _state["cache_dir"] is None:
        digest = hashlib.sha256()
        folder = Path(__file__).parent
        for source in sorted(folder.rglob("_fast*.py")) + [folder / name for name in _KERNEL_DEPENDENCIES]:
            digest.update(source.read_bytes())
        name = f"orbits-{digest.hexdigest()[:16]}"
        roots = [
            os.environ.get("NUMBA_CACHE_DIR"),
            os.path.join(user_cache_home(), "orbits"),
            os.path.join(os.path.dirname(__file__), "__pycache__"),
            tempfile.gettempdir(),
        ]
        _state["cache_dir"] = first_writable([root for root in roots if root], name) or ""
    return _state["cache_dir"] or None


def user_cache_home():
    """The user's cache folder: $XDG_CACHE_HOME if set to an absolute path (the XDG base directory rule), else
    ~/Library/Caches on macOS, %LOCALAPPDATA% on Windows and ~/.cache elsewhere."""
    xdg = os.environ.get("XDG_CACHE_HOME", "")
    if os.path.isabs(xdg):
        return xdg
    if sys.platform == "darwin":
        return os.path.join(os.path.expanduser("~"), "Library", "Caches")
    if sys.platform == "win32" and os.environ.get("LOCALAPPDATA"):
        return os.environ["LOCALAPPDATA"]
    return os.path.join(os.path.expanduser("~"), ".cache")


def first_writable(roots, name):
    """The first root/name that exists or can be made and holds a new file; None if there is none."""
    for root in roots:
        path = os.path.join(root, name)
        try:
            os.makedirs(path, exist_ok=True)
            tempfile.TemporaryFile(dir=path).close()
        except OSError:
            continue
        return path
    return None


def _pool():
    if _state["pool"] is None:
        _state["pool"] = ThreadPoolExecutor(max_workers=max(2, num_threads()), thread_name_prefix="orbits")
    return _state["pool"]


#: what numba raises when its on-disk cache is truncated or corrupted (it unpickles the index and the code)
_CORRUPT_CACHE = (EOFError, pickle.UnpicklingError, OSError)


def run(kernel, n, *arrays):
    """kernel(start, stop, *arrays) over [0, n), split into contiguous chunks run by parallel threads.

    Returns the sum of the kernels' integer results (they count invalid or unconverged elements, which the
    caller then recomputes with the NumPy implementation). An on-disk cache that is unreadable, or that holds code
    that is not the function it is filed under (cache files swapped or copied over one another: numba checks an
    entry's signature, not whose code it is), is cleared, with one line on stderr, and the kernels are bypassed for
    the rest of the process (returning n: recompute all).
    """
    loaded = _signatures(kernel)
    try:
        count = _run(kernel, n, *arrays)
    except _CORRUPT_CACHE as err:
        _clear_corrupt_cache(f"was unreadable ({type(err).__name__})")
        return n
    except TypeError:  # e.g. "_halley expected 8 arguments, got 5": another function's code under this name
        if _mismatched() is None:
            raise
        _clear_corrupt_cache(f"held {_mismatched()}")
        return n
    if _signatures(kernel) == loaded:  # nothing compiled or loaded by this call: nothing new to read
        return count
    wrong = _mismatched()  # the same arity, another function's code: the counts (and results) are not this one's
    if wrong is not None:
        _clear_corrupt_cache(f"held {wrong}")
        return n
    _mark_ready(kernel)
    return count


def _signatures(kernel) -> int:
    """How many signatures a compiled kernel holds (0 for a plain function)."""
    return len(getattr(kernel, "overloads", ()))


def _mismatched():
    """"the code of A under the name B" for the first compiled kernel whose loaded code is another function's, else
    None. A kernel's code is read once per compiled or loaded signature (numba adds one to its overloads each
    time); run calls this only when the kernel it ran gained one, so a warm call reads nothing."""
    seen = _state["checked"]
    for kernel in _state["kernels"]:
        count = len(kernel.overloads)
        if seen.get(kernel) == count:
            continue
        for result in kernel.overloads.values():
            if result.fndesc.qualname != kernel.py_func.__qualname__:
                return f"the code of {result.fndesc.qualname} under the name {kernel.py_func.__qualname__}"
        seen[kernel] = count
    return None


def _clear_corrupt_cache(what):
    """Remove the cache folder's files, say so on stderr once, and use the NumPy implementations from now on."""
    folder = cache_dir()
    if folder:
        shutil.rmtree(folder, ignore_errors=True)
    _state["mode"] = False
    print(f"orbits: the compiled-kernel cache {folder} {what}; cleared it, the next run compiles the kernels again",
          file=sys.stderr)


def _run(kernel, n, *arrays):
    """The kernel over [0, n) in rounds of at most ROUND elements a thread, so that Python runs between rounds and a
    Ctrl-C stops the batch within one round (a compiled loop never looks at signals)."""
    threads = min(num_threads(), max(1, n // PARALLEL_MIN))
    if threads > 1:  # a first call compiles (or loads) the kernel: here, where Ctrl-C lands, not in a worker thread
        kernel(0, 0, *arrays)  # that the interpreter would wait for on its way out
    count = 0
    for start in range(0, n, threads * ROUND):
        stop = min(n, start + threads * ROUND)
        if threads == 1:
            count += int(kernel(start, stop, *arrays))
            continue
        bounds = np.linspace(start, stop, threads + 1).astype(np.int64)
        futures = [_pool().submit(kernel, int(a), int(b), *arrays) for a, b in zip(bounds[:-1], bounds[1:])]
        count += sum(int(f.result()) for f in futures)
    return count
