"""Benchmarks behind ``orbits bench``: orbits against its peers, every figure measured in the same run.

- bench_kepler: Kepler's equation on three sets ("easy", "hard" near e = 1, "hyperbolic"), throughput
  and worst error against mpmath, for orbits (compiled kernels on one thread and on every core, and
  the NumPy fallback), heyoka's kepE cfunc (one thread and every core), rebound.M_to_E, a plain NumPy
  Newton solver, exoplanet-core and pykep.
- bench_propagate: two-body propagation of elliptic and mixed-conic states, throughput and worst
  relative position and velocity error against mpmath (orbits.tools.reference), for orbits, heyoka's
  lagrange_prop cfunc, a plain NumPy f-and-g + Newton baseline, pykep and hapsira.
- bench_api: the unit-aware API (orbits.Orbit) against the float64 core on the same inputs.
- bench_cli: cold start of the command line, as the median of repeated fresh processes, and the first run on
  a fresh install (empty kernel cache) against the second.
- bench_validate: where the time of ``orbits validate`` goes (analytic, integrator setup and compile,
  integration) per built-in scene, sequential and as a dask sweep.

Threads: numpy's element-wise functions run on one thread; heyoka's cfunc splits large batches over
its own thread pool, which bench_kepler pins with heyoka.set_nthreads; orbits' kernels split over
orbits.core._fast.num_threads(). Rows say how many threads they used. rebound is timed through its
per-call Python API, which measures the Python call overhead as much as the solver. Peers whose
package is absent are skipped with a note; every peer is imported lazily.
"""

import contextlib
import dataclasses
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import mpmath
import numpy as np

if TYPE_CHECKING:
    from orbits.scene import Scene
    from orbits.validate.models import ModelScene

#: Pairs on which the per-call rebound API is timed (its throughput is per pair, so it scales).
PER_CALL_SUBSET = 20_000
_REF_DIGITS = 30  # reference digits beyond those lost to cancellation near e = 1 and to reduction
_NEWTON_TOL = 1e-15  # absolute step tolerance of the plain NumPy Newton baseline
_NEWTON_MAX_ITER = 50


@dataclass(frozen=True)
class BenchRow:
    """One method timed on one data set.

    ``seconds`` is the best of the repeats for ``n`` pairs; errors are the worst over the first
    ``n_ref`` pairs with a finite result (NaN if none); ``n_nan`` counts non-finite results over all
    ``n`` pairs; ``status`` is "ok", "skipped" (package absent or equation not supported) or
    "raised"; ``setup_seconds`` is one-off preparation such as JIT compilation.
    """

    method: str
    dataset: str
    n: int
    seconds: float
    throughput_per_s: float
    max_rel_error: float
    max_ulp: float
    n_nan: int
    status: str
    note: str = ""
    setup_seconds: float = 0.0


@dataclass(frozen=True)
class _Dataset:
    """Benchmark inputs: eccentricities e and mean anomalies M of one equation type."""

    name: str
    hyperbolic: bool
    e: np.ndarray
    M: np.ndarray


def _as_pair(e, M):
    """Default input preparation: the two arrays as they are."""
    return e, M


@dataclass(frozen=True)
class _Method:
    """A peer adapter.  prepare(...) puts the inputs in the form the library takes (not timed); for
    Kepler solvers prepare(e, M) and solve(prepared, hyperbolic), which returns the anomalies or None
    if the equation is unsupported; for propagators prepare(states) and solve(prepared) -> (r, v)."""

    name: str
    solve: Callable[..., object]
    prepare: Callable[[np.ndarray, np.ndarray], object] = _as_pair
    setup_seconds: float = 0.0
    note: str = ""
    subset: int | None = None  # time only this many pairs (per-call APIs)


# --- data ---------------------------------------------------------------------------------------


def _datasets(n_easy, n_hard, n_hyp, seed):
    """The three benchmark data sets, drawn in order from numpy.random.default_rng(seed)."""
    rng = np.random.default_rng(seed)
    easy = _Dataset("easy", False, rng.uniform(0.0, 0.99, n_easy), rng.uniform(0.0, 2 * np.pi, n_easy))
    e_hard = 1.0 - 10.0 ** rng.uniform(-9.0, -2.0, n_hard)
    offset = 10.0 ** rng.uniform(-12.0, -3.0, n_hard)
    M_hard = np.where(np.arange(n_hard) % 2 == 0, offset, np.pi - offset)  # tiny / near pi, alternating
    hard = _Dataset("hard", False, e_hard, M_hard)
    e_hyp = 1.0 + 10.0 ** rng.uniform(-9.0, 3.0, n_hyp)
    hyp = _Dataset("hyperbolic", True, e_hyp, 10.0 ** rng.uniform(-6.0, 6.0, n_hyp))
    return [easy, hard, hyp]


# --- mpmath reference (independent of orbits.core; cross-checked against tests/mpref.py) ----------


def _extra_digits(distance_from_one):
    """Decimal digits cancelled when forming a quantity at this (float) distance from 1."""
    return max(0, -math.floor(math.log10(distance_from_one))) if distance_from_one > 0 else 0


def _newton_from_above(f, df, x, digits):
    """Root of an increasing convex f by Newton from x >= root; the iterates decrease monotonically."""
    tol = mpmath.mpf(10) ** -digits
    for _ in range(200):
        step = f(x) / df(x)
        x -= step
        if abs(step) <= tol * abs(x):
            return x
    raise ArithmeticError(f"bench reference did not converge at x={x}")


def _reference_elliptic(M, e):
    """(E, M_reduced) as mpf with E - e sin E = M_reduced = M - 2 pi round(M / 2 pi), E in [-pi, pi]."""
    digits = _REF_DIGITS + _extra_digits(1.0 - e) + max(0, math.ceil(math.log10(abs(M) + 1.0)))
    with mpmath.workdps(digits):
        M, e = mpmath.mpf(M), mpmath.mpf(e)
        Mr = M - 2 * mpmath.pi * mpmath.nint(M / (2 * mpmath.pi))
        m = abs(Mr)
        if m == 0 or e == 0:
            return Mr, Mr
        # E - e sin E >= (1 - e) E and >= (1 - e) E + e E^3 / pi^2 on [0, pi]; E <= m + e; E <= pi.
        x = min(mpmath.pi, m + e, m / (1 - e), mpmath.cbrt(mpmath.pi**2 * m / e))
        f, df = lambda E: E - e * mpmath.sin(E) - m, lambda E: 1 - e * mpmath.cos(E)
        E = _newton_from_above(f, df, x, _REF_DIGITS - 5)
        return mpmath.sign(Mr) * E, Mr


def _reference_hyperbolic(M, e):
    """H as mpf with e sinh H - H = M."""
    digits = _REF_DIGITS + _extra_digits(e - 1.0)
    with mpmath.workdps(digits):
        M, e = mpmath.mpf(M), mpmath.mpf(e)
        m = abs(M)
        if m == 0:
            return M
        # e sinh H - H >= (e - 1) H and >= e H^3 / 6, so H <= asinh((m + min(...)) / e).
        x = mpmath.asinh((m + min(m / (e - 1), mpmath.cbrt(6 * m / e))) / e)
        f, df = lambda H: e * mpmath.sinh(H) - H - m, lambda H: e * mpmath.cosh(H) - 1
        H = _newton_from_above(f, df, x, _REF_DIGITS - 5)
        return mpmath.sign(M) * H


def _references(data, n_ref):
    """[(anomaly, M_reduced)] for the first n_ref pairs (M_reduced = 0 for hyperbolic sets)."""
    pairs = zip(data.M[:n_ref].tolist(), data.e[:n_ref].tolist())
    if data.hyperbolic:
        return [(_reference_hyperbolic(M, e), 0) for M, e in pairs]
    return [_reference_elliptic(M, e) for M, e in pairs]


def _worst_errors(x, refs, periodic):
    """(max relative error, max ulp error) of the finite x[i] against refs[i] = (anomaly, M_reduced).

    Relative errors are taken with respect to max(|anomaly|, |M_reduced|), ulps at the float nearest
    the anomaly.  With periodic=True (elliptic) a result on another revolution than the reference
    (some libraries return E in [0, 2 pi)) is compared with the reference shifted by the nearest
    multiple of 2 pi.  NaN if no result is finite."""
    rel, ulp = [], []
    with mpmath.workdps(40):
        for xi, (ref, m) in zip(x.tolist(), refs):
            if not math.isfinite(xi):
                continue
            if periodic:
                ref = ref + 2 * mpmath.pi * round((xi - float(ref)) / (2 * math.pi))
            err = abs(mpmath.mpf(xi) - ref)
            scale = max(abs(ref), abs(m))
            rel.append(float(err / scale) if scale else (0.0 if err == 0 else math.inf))
            ulp.append(float(err / math.ulp(abs(float(ref)))))
    return max(rel, default=math.nan), max(ulp, default=math.nan)


# --- methods --------------------------------------------------------------------------------------


def _cores():
    """Threads the 'all cores' rows use: orbits.core._fast.num_threads() (ORBITS_NUM_THREADS or the cores)."""
    from orbits.core import _fast

    return _fast.num_threads()


@contextlib.contextmanager
def _orbits_threads(threads):
    """Run orbits' compiled kernels on `threads` threads (threads=0: the NumPy fallback) inside the block."""
    from orbits.core import _fast

    previous_threads = _fast.num_threads()
    _fast.set_num_threads(max(threads, 1))
    previous_mode = _fast.set_enabled(threads > 0)  # every batch size: the benchmark measures the kernels
    try:
        yield
    finally:
        _fast.set_num_threads(previous_threads)
        _fast.set_enabled(previous_mode)


def _orbits_method(threads):
    from orbits.core.kepler import eccentric_anomaly, hyperbolic_anomaly

    def solve(pair, hyperbolic):
        e, M = pair
        with _orbits_threads(threads):
            return hyperbolic_anomaly(M, e) if hyperbolic else eccentric_anomaly(M, e)

    start = time.perf_counter()
    with _orbits_threads(threads):  # loads (or compiles) the kernels: the first call's one-off cost
        eccentric_anomaly(0.5, 0.5), hyperbolic_anomaly(0.5, 1.5)
    setup = time.perf_counter() - start
    return _Method(_orbits_name(threads), solve, setup_seconds=setup, note=_orbits_note(threads))


def _orbits_name(threads):
    return {0: "orbits (NumPy)", 1: "orbits"}.get(threads, "orbits (all cores)")


def _orbits_note(threads):
    if threads == 0:
        return "NumPy fallback (ORBITS_JIT=0)"
    return "compiled, 1 thread" if threads == 1 else f"compiled, {threads} threads"


@contextlib.contextmanager
def _heyoka_threads(heyoka, threads):
    previous = heyoka.get_nthreads()
    heyoka.set_nthreads(threads)
    try:
        yield
    finally:
        heyoka.set_nthreads(previous)


def _heyoka_method(threads):
    import heyoka

    start = time.perf_counter()
    e, M = heyoka.make_vars("e", "M")
    cf = heyoka.cfunc([heyoka.kepE(e, M)], [e, M])
    setup = time.perf_counter() - start

    def solve(inputs, hyperbolic):
        with _heyoka_threads(heyoka, threads):
            return cf(inputs)[0]

    name = "heyoka kepE (cfunc)" if threads == 1 else "heyoka kepE (all cores)"
    return _Method(
        name,
        solve,
        lambda e, M: np.stack([e, M]),
        setup,
        f"{threads} thread{'s' if threads > 1 else ''}; elliptic only (NaN for e > 1)",
    )


def _rebound_method():
    import rebound

    def solve(pairs, hyperbolic):
        return [rebound.M_to_E(e, M) for e, M in pairs]

    return _Method(
        "rebound.M_to_E",
        solve,
        lambda e, M: list(zip(e.tolist(), M.tolist())),
        note="per-call Python API, throughput from a subset",
        subset=PER_CALL_SUBSET,
    )


def _numpy_newton_method():
    def solve(pair, hyperbolic):
        return _newton_hyperbolic(*pair) if hyperbolic else _newton_elliptic(*pair)

    return _Method(
        "numpy Newton", solve, note=f"plain baseline: abs step tol {_NEWTON_TOL:g}, <= {_NEWTON_MAX_ITER} iterations"
    )


def _newton_elliptic(e, M):
    """Plain vectorised Newton on E - e sin E = M from E0 = M + e sin M."""
    E = M + e * np.sin(M)
    with np.errstate(all="ignore"):
        for _ in range(_NEWTON_MAX_ITER):
            step = (E - e * np.sin(E) - M) / (1.0 - e * np.cos(E))
            E = E - step
            if np.all(np.abs(step) <= _NEWTON_TOL):
                break
    return E


def _newton_hyperbolic(e, M):
    """Plain vectorised Newton on e sinh H - H = M from H0 = asinh(M / e)."""
    H = np.arcsinh(M / e)
    with np.errstate(all="ignore"):
        for _ in range(_NEWTON_MAX_ITER):
            step = (e * np.sinh(H) - H - M) / (e * np.cosh(H) - 1.0)
            H = H - step
            if np.all(np.abs(step) <= _NEWTON_TOL):
                break
    return H


def _exoplanet_core_method():
    import exoplanet_core

    def solve(pair, hyperbolic):
        if hyperbolic:
            return None
        e, M = pair
        sin_f, cos_f = exoplanet_core.kepler(M, e)
        with np.errstate(divide="ignore"):  # f = pi gives tan(f/2) = inf and E = pi
            return 2.0 * np.arctan(np.sqrt((1.0 - e) / (1.0 + e)) * sin_f / (1.0 + cos_f))

    return _Method("exoplanet-core", solve, note="returns (sin f, cos f); E recovered from tan(f/2)")


def _pykep_method():
    import pykep

    def solve(pair, hyperbolic):
        e, M = pair
        return pykep.n2h_v(M, e) if hyperbolic else pykep.m2e_v(M, e)

    return _Method("pykep", solve)


_METHODS = [
    ("orbits", lambda: _orbits_method(1)),
    ("orbits (all cores)", lambda: _orbits_method(_cores())),
    ("orbits (NumPy)", lambda: _orbits_method(0)),
    ("heyoka kepE (cfunc)", lambda: _heyoka_method(1)),
    ("heyoka kepE (all cores)", lambda: _heyoka_method(_cores())),
    ("rebound.M_to_E", _rebound_method),
    ("numpy Newton", _numpy_newton_method),
    ("exoplanet-core", _exoplanet_core_method),
    ("pykep", _pykep_method),
]


# --- measurement ----------------------------------------------------------------------------------


def _skipped(name, data, note):
    """Row of a method that was not run on data."""
    return BenchRow(name, data.name, 0, math.nan, math.nan, math.nan, math.nan, 0, "skipped", note)


def _measure(method, data, refs, repeats):
    """Time method on data (best of repeats) and compare its first results with refs."""
    n = len(data.e) if method.subset is None else min(len(data.e), method.subset)
    inputs = method.prepare(data.e[:n], data.M[:n])
    best = math.inf
    try:
        for _ in range(repeats):
            start = time.perf_counter()
            result = method.solve(inputs, data.hyperbolic)
            best = min(best, time.perf_counter() - start)
    except Exception as exc:  # a peer failing on some input is a benchmark result, not a crash
        note = f"raised {type(exc).__name__}: {exc}".splitlines()[0][:200]
        nan = math.nan
        return BenchRow(method.name, data.name, n, nan, nan, nan, nan, 0, "raised", note, method.setup_seconds)
    if result is None:
        return _skipped(method.name, data, "equation not supported")
    result = np.asarray(result, dtype=float)
    max_rel, max_ulp = _worst_errors(result[: len(refs)], refs, not data.hyperbolic)
    return BenchRow(
        method.name,
        data.name,
        n,
        best,
        n / best,
        max_rel,
        max_ulp,
        int(np.count_nonzero(~np.isfinite(result))),
        "ok",
        method.note,
        method.setup_seconds,
    )


def _load(factories):
    """[(name, _Method or None, skip note)] for every (name, factory), importing peers lazily."""
    loaded = []
    for name, factory in factories:
        try:
            loaded.append((name, factory(), ""))
        except ImportError as exc:
            loaded.append((name, None, f"not installed ({exc.name or exc})"))
    return loaded


def bench_kepler(
    n_easy: int = 1_000_000,
    n_hard: int = 100_000,
    n_hyp: int = 100_000,
    n_ref: int = 2000,
    seed: int = 0,
    repeats: int = 3,
) -> list[BenchRow]:
    """Time and check every available Kepler solver on the "easy", "hard" and "hyperbolic" sets.

    easy: e ~ U[0, 0.99], M ~ U[0, 2 pi).  hard: e = 1 - 10**U(-9, -2), M alternately
    10**U(-12, -3) and pi - 10**U(-12, -3).  hyperbolic: e = 1 + 10**U(-9, 3), M = 10**U(-6, 6).
    Errors are measured against an mpmath reference on the first n_ref pairs of each set, relative to
    max(|E_ref|, |M reduced to [-pi, pi]|) for elliptic sets and to |H_ref| for the hyperbolic one;
    a method returning E in [0, 2 pi) is compared on its own revolution.  Timings exclude the
    one-off conversion of the inputs to the form each library takes.
    Returns one BenchRow per (method, data set), methods in a fixed order.
    """
    datasets = _datasets(n_easy, n_hard, n_hyp, seed)
    methods = _load(_METHODS)
    rows = []
    for data in datasets:
        refs = _references(data, min(n_ref, len(data.e)))
        for name, method, note in methods:
            row = _skipped(name, data, note) if method is None else _measure(method, data, refs, repeats)
            rows.append(row)
    return rows


# --- reporting ------------------------------------------------------------------------------------

#: Width of every plain-text table: a line never exceeds it, and no text is cut to fit (it wraps).
WIDTH = 80
_GAP = "  "


def _wrap(text, width, indent="", subsequent=None, split_words=True):
    """Lines of text, at most `width` wide; words are split only if one alone is wider than the line (and
    split_words, else that line is wider)."""
    wrapper = textwrap.TextWrapper(
        width, initial_indent=indent, subsequent_indent=indent if subsequent is None else subsequent,
        break_on_hyphens=False, break_long_words=split_words,
    )
    return wrapper.wrap(text) or [indent.rstrip()]


def _fixed(x, digits):
    """x in fixed notation with at least `digits` significant digits (all the integer digits if more)."""
    if not math.isfinite(x):
        return str(x)
    if x == 0:
        return "0"
    return f"{x:.{max(0, digits - 1 - math.floor(math.log10(abs(x))))}f}"


def _sig(x, digits=3):
    """x to `digits` significant digits: fixed notation from 0.001 to 10**digits, scientific beyond."""
    if math.isfinite(x) and x != 0 and not 1e-3 <= abs(x) < 10**digits:
        return f"{x:.{digits - 1}e}"
    return _fixed(x, digits)


def _mega(per_second):
    """A throughput in millions per second: 4 significant digits from 1 M/s, 3 below."""
    x = per_second / 1e6
    return _fixed(x, 4) if abs(x) >= 1 else _sig(x, 3)


def _table(header, rows, stack=False, width=WIDTH, first="<"):
    """Lines of a plain-text table at most `width` wide.

    header: the column titles; rows: lists of cells, the first left-aligned and wrapped (continuation lines
    indented, the other cells on the last) to what the other columns leave of `width`, the others
    right-aligned; or strings, section titles drawn as rules across the table.  stack=True wraps the titles
    word by word over several header lines, so that a column is only as wide as its longest title word or
    cell; first=">" right-aligns the first column too (numbers)."""
    cells = [r for r in rows if not isinstance(r, str)]
    widths = [
        max([len(w) for w in (title.split() if stack else [title])] + [len(r[j]) for r in cells])
        for j, title in enumerate(header)
    ]
    rest = sum(widths[1:]) + len(_GAP) * (len(widths) - 1)
    widths[0] = max(min(widths[0], width - rest), 12)
    total = sum(widths) + len(_GAP) * (len(widths) - 1)
    titles = [_wrap(t, w) if stack else [t] for t, w in zip(header, widths)]
    depth = max(map(len, titles))
    titles = [[""] * (depth - len(t)) + t for t in titles]
    lines = [_row([t[i] for t in titles], widths, first) for i in range(depth)]
    if not rows or not isinstance(rows[0], str):
        lines.append("-" * total)
    for r in rows:
        if isinstance(r, str):
            lines.extend(_section(r, max(total, len(r) + 6), width))
        else:
            lines.extend(_cells(r, widths, first, width))
    return lines


def _row(cells, widths, align="<"):
    first, *others = cells
    text = f"{first:{align}{widths[0]}}" + "".join(f"{_GAP}{c:>{w}}" for c, w in zip(others, widths[1:]))
    return text.rstrip()


def _cells(cells, widths, align="<", width=WIDTH):
    """A table row: its first cell wrapped to its column, the others on its last line (so that the text reads
    on without figures in between); a text with a word wider than its column takes whole lines instead, and
    the figures a line of their own under it."""
    first = _wrap(cells[0], widths[0], subsequent="  ", split_words=False)
    if max(map(len, first)) > widths[0]:
        first = [*_wrap(cells[0], width, subsequent="  "), ""]
    return first[:-1] + [_row([first[-1], *cells[1:]], widths, align)]


def _section(title, rule, width):
    """A section title drawn into a rule: '-- title ------' (wrapped if the title is wider than `width`)."""
    if len(title) + 6 > width:
        return _wrap(title, width, "-- ", "   ")
    return [f"-- {title} " + "-" * (min(rule, width) - len(title) - 4)]


def _notes(texts, width=WIDTH):
    """The footnote list: '[n] text' with hanging indents; `texts` maps each text to its number."""
    if not texts:
        return []
    mark_width = len(f"[{len(texts)}]")
    lines = []
    for text, number in texts.items():
        mark = f"[{number}]"
        lines.extend(_wrap(text, width, f"{mark:>{mark_width}} ", " " * (mark_width + 1)))
    return lines


def _mark(texts, text):
    """' [n]', the footnote number of text (a new one if unseen), or '' for no text."""
    if not text:
        return ""
    return f" [{texts.setdefault(text, len(texts) + 1)}]"


def _solves(row):
    """Whether the row timed a method that returned at least one finite anomaly."""
    return row.status == "ok" and row.n_nan < row.n


def _by_dataset(rows, reference, stats):
    """Table rows of a throughput benchmark: a section per data set (in order of appearance), one row per
    method with its footnote mark, then the footnote texts {text: number}."""
    texts, table = {}, []
    for dataset in dict.fromkeys(r.dataset for r in rows):
        table.append(dataset)
        for r in (r for r in rows if r.dataset == dataset):
            if r.status == "ok":
                ratio = _sig(r.throughput_per_s / reference[dataset], 3) if dataset in reference else "-"
                cells = [_mega(r.throughput_per_s), ratio, *stats(r), str(r.n_nan)]
            else:
                cells = ["-"] * 5
            table.append([r.method + _mark(texts, _note(r)), *cells])
    return table, texts


_RATIO = "ratio: throughput over that of orbits (1 thread) on the same set; above 1 is faster."


def format_rows(rows: Sequence[BenchRow]) -> str:
    """Plain-text table of bench_kepler, at most 80 columns: a section per data set, throughput (M/s), ratio
    to orbits on one thread on the same set (above 1: faster than orbits), worst relative and ulp errors,
    NaN count; the notes in a numbered list under the table."""
    reference = {r.dataset: r.throughput_per_s for r in rows if r.method == "orbits" and _solves(r)}
    table, texts = _by_dataset(rows, reference, _kepler_stats)
    lines = _table(["method", "M/s", "ratio", "rel err", "ulp", "NaN"], table)
    legend = (
        f"M/s: millions of pairs solved per second. {_RATIO} rel err, ulp: worst relative and ulp errors "
        "against mpmath. NaN: non-finite results."
    )
    return "\n".join(lines + [""] + _wrap(legend, WIDTH) + _notes(texts))


def _kepler_stats(row):
    return [f"{row.max_rel_error:.2e}", _sig(row.max_ulp)]


def _note(row):
    """The row's note, its status if not ok, and its one-off setup time."""
    note = row.note if row.status == "ok" else f"{row.status}: {row.note}"
    if row.setup_seconds:
        note = f"{note} (compile/setup {row.setup_seconds:.3f} s)".lstrip()
    return note


def rows_to_json(rows: Iterable[object]) -> list[dict[str, object]]:
    """Rows (any of the benchmarks' row classes) as JSON-ready dicts (NaN and infinity become None)."""
    return [_clean(dataclasses.asdict(r)) for r in rows]


def _clean(value):
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items()}
    return None if isinstance(value, float) and not math.isfinite(value) else value


# --- two-body propagation -------------------------------------------------------------------------

MU_EARTH = 3.986004418e14
#: States on which slow or per-state methods are timed (their throughput is per state, so it scales).
PROPAGATE_SUBSET = 100_000


@dataclass(frozen=True)
class PropagateRow:
    """One propagator on one data set: best of the repeats for n states; worst relative position and
    velocity errors against mpmath over the first n_ref states with a finite result; NaN count."""

    method: str
    dataset: str
    n: int
    seconds: float
    throughput_per_s: float
    max_position_error: float
    max_velocity_error: float
    n_nan: int
    status: str
    note: str = ""
    setup_seconds: float = 0.0


@dataclass(frozen=True)
class _States:
    """Initial states (m, m/s) about MU_EARTH and times of flight (s)."""

    name: str
    r0: np.ndarray
    v0: np.ndarray
    dt: np.ndarray


def _propagation_sets(n, seed):
    """ "elliptic": e ~ U[0, 0.95]; "mixed": a third each of those ellipses, hyperbolas with
    e - 1 = 10**U(-6, 0.5) and near-parabolic orbits with |1 - e| < 1e-3. p = 7000-21000 km, random
    orientation, true anomaly in [-1, 1] rad, time of flight U(-10, 10) periods (2 pi sqrt(p**3 / mu) for
    open orbits)."""
    rng = np.random.default_rng(seed)
    third = n // 3
    mixed = np.concatenate(
        [
            rng.uniform(0, 0.95, third),
            1 + 10 ** rng.uniform(-6, 0.5, third),
            1 + rng.uniform(-1e-3, 1e-3, n - 2 * third),
        ]
    )
    elliptic = _conic_states("elliptic", rng, rng.uniform(0, 0.95, n))
    return [elliptic, _conic_states("mixed", rng, rng.permutation(mixed))]


def _conic_states(name, rng, e):
    from orbits.core.elements import elements_to_state

    n = e.size
    p = 7e6 * rng.uniform(1, 3, n)
    angles = rng.uniform(0, np.pi, n), rng.uniform(0, 2 * np.pi, n), rng.uniform(0, 2 * np.pi, n), rng.uniform(-1, 1, n)
    r0, v0 = elements_to_state(p, e, *angles, MU_EARTH)
    with np.errstate(divide="ignore", invalid="ignore"):
        period = 2 * np.pi * np.sqrt(np.where(e < 1, p / np.abs((1 - e) * (1 + e)), p) ** 3 / MU_EARTH)
    return _States(name, r0, v0, rng.uniform(-10, 10, n) * period)


def _propagation_references(states, n_ref):
    """[(r, v)] as mpf lists from orbits.tools.reference.propagate for the first n_ref states."""
    from orbits.tools.reference import propagate

    return [propagate(states.r0[i], states.v0[i], MU_EARTH, states.dt[i]) for i in range(min(n_ref, states.dt.size))]


def _propagation_errors(r, v, refs):
    """(worst |r - r_ref| / |r_ref|, worst |v - v_ref| / |v_ref|) over the finite rows; NaN if none."""
    worst = [[], []]
    with mpmath.workdps(40):
        for i, ref in enumerate(refs):
            for k, (x, exact) in enumerate(zip((r[i], v[i]), ref)):
                if np.all(np.isfinite(x)):
                    diff = mpmath.sqrt(sum((mpmath.mpf(float(a)) - b) ** 2 for a, b in zip(x, exact)))
                    worst[k].append(float(diff / mpmath.sqrt(sum(b**2 for b in exact))))
    return max(worst[0], default=math.nan), max(worst[1], default=math.nan)


def _orbits_propagator(threads):
    from orbits.core.propagate import propagate

    def solve(states):
        with _orbits_threads(threads):
            return propagate(states.r0, states.v0, MU_EARTH, states.dt)

    start = time.perf_counter()
    with _orbits_threads(threads):
        propagate(np.array([7e6, 0.0, 0.0]), np.array([0.0, 7.5e3, 0.0]), MU_EARTH, 100.0)
    setup = time.perf_counter() - start
    subset = PROPAGATE_SUBSET if threads == 0 else None
    return _Method(_orbits_name(threads), solve, _as_states, setup, _orbits_note(threads), subset)


def _as_states(states):
    return states


def _heyoka_propagator(threads):
    """heyoka's lagrange_prop (heyoka >= 7.11) compiled as a cfunc; elliptic only."""
    import heyoka

    if not hasattr(heyoka.model, "lagrange_prop"):
        raise ImportError("heyoka.model.lagrange_prop (heyoka >= 7.11)", name="heyoka >= 7.11")
    start = time.perf_counter()
    variables = heyoka.make_vars("x", "y", "z", "vx", "vy", "vz", "mu", "t")
    pos, vel = heyoka.model.lagrange_prop(pos0=variables[:3], vel0=variables[3:6], mu=variables[6], tm=variables[7])
    cf = heyoka.cfunc(list(pos) + list(vel), variables)
    setup = time.perf_counter() - start

    def prepare(states):
        mu = np.full(states.dt.size, MU_EARTH)
        return np.ascontiguousarray(np.vstack([states.r0.T, states.v0.T, mu, states.dt]))

    def solve(inputs):
        with _heyoka_threads(heyoka, threads):
            out = cf(inputs)
        return out[:3].T, out[3:].T

    name = "heyoka lagrange_prop" if threads == 1 else "heyoka lagrange_prop (all cores)"
    return _Method(name, solve, prepare, setup, f"cfunc, {threads} thread(s); elliptic only")


def _numpy_fg_propagator():
    return _Method(
        "numpy f-and-g + Newton", _fg_newton, _as_states, note="plain baseline, elliptic only", subset=PROPAGATE_SUBSET
    )


def _fg_newton(states):
    """Plain vectorised f and g on ellipses: Newton on Kepler's equation from E = M (abs step tol 1e-15),
    no period reduction, no care for cancellation; NaN for open orbits."""
    r0, v0, dt, mu = states.r0, states.v0, states.dt, MU_EARTH
    r = np.linalg.norm(r0, axis=-1)
    rv = np.sum(r0 * v0, axis=-1)
    with np.errstate(all="ignore"):
        a = 1.0 / (2.0 / r - np.sum(v0 * v0, axis=-1) / mu)
        a = np.where(a > 0, a, np.nan)
        n = np.sqrt(mu / a**3)
        e_cos, e_sin = 1.0 - r / a, rv / np.sqrt(mu * a)
        E0 = np.arctan2(e_sin, e_cos)
        e = np.hypot(e_cos, e_sin)
        M = E0 - e_sin + n * dt
        E = _newton_elliptic(e, M)
        dE = E - E0
        f, g = 1.0 - a / r * (1.0 - np.cos(dE)), dt - (dE - np.sin(dE)) / n
        r1 = f[:, None] * r0 + g[:, None] * v0
        r1_norm = np.linalg.norm(r1, axis=-1)
        f_dot, g_dot = -np.sqrt(mu * a) * np.sin(dE) / (r * r1_norm), 1.0 - a / r1_norm * (1.0 - np.cos(dE))
        return r1, f_dot[:, None] * r0 + g_dot[:, None] * v0


def _pykep_propagator():
    import pykep

    def solve(states):
        pairs = [pykep.propagate_lagrangian(r, v, t, MU_EARTH) for r, v, t in zip(states.r0, states.v0, states.dt)]
        return np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])

    return _Method(
        "pykep propagate_lagrangian", solve, _as_states, note="per-state Python API", subset=PROPAGATE_SUBSET
    )


def _hapsira_propagator():
    from hapsira.core.propagation.farnocchia import farnocchia_rv

    def solve(states):
        pairs = [farnocchia_rv(MU_EARTH, r, v, t) for r, v, t in zip(states.r0, states.v0, states.dt)]
        return np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])

    return _Method("hapsira farnocchia", solve, _as_states, note="per-state Python API", subset=PROPAGATE_SUBSET)


_PROPAGATORS = [
    ("orbits", lambda: _orbits_propagator(1)),
    ("orbits (all cores)", lambda: _orbits_propagator(_cores())),
    ("orbits (NumPy)", lambda: _orbits_propagator(0)),
    ("heyoka lagrange_prop", lambda: _heyoka_propagator(1)),
    ("heyoka lagrange_prop (all cores)", lambda: _heyoka_propagator(_cores())),
    ("numpy f-and-g + Newton", _numpy_fg_propagator),
    ("pykep propagate_lagrangian", _pykep_propagator),
    ("hapsira farnocchia", _hapsira_propagator),
]


def _subset(states, n):
    return _States(states.name, states.r0[:n], states.v0[:n], states.dt[:n])


def _measure_propagator(method, states, refs, repeats):
    """Time method on states (best of repeats, inputs prepared outside the timing) and check its results."""
    n = states.dt.size if method.subset is None else min(states.dt.size, method.subset)
    inputs = method.prepare(_subset(states, n))
    try:
        seconds, (r, v) = _best_time(lambda: method.solve(inputs), repeats)
    except Exception as exc:  # a peer failing on some input is a benchmark result, not a crash
        return _failed_propagation(method, states, n, exc)
    r, v = np.asarray(r, dtype=float), np.asarray(v, dtype=float)
    position, velocity = _propagation_errors(r, v, refs)
    n_nan = int(np.count_nonzero(~np.all(np.isfinite(np.concatenate([r, v], axis=-1)), axis=-1)))
    return PropagateRow(
        method.name,
        states.name,
        n,
        seconds,
        n / seconds,
        position,
        velocity,
        n_nan,
        "ok",
        method.note,
        method.setup_seconds,
    )


def _failed_propagation(method, states, n, exc):
    note = f"raised {type(exc).__name__}: {exc}".splitlines()[0][:200]
    nan = math.nan
    return PropagateRow(method.name, states.name, n, nan, nan, nan, nan, 0, "raised", note, method.setup_seconds)


def _best_time(call, repeats):
    """(best wall time of `repeats` calls, the last result)."""
    best, result = math.inf, None
    for _ in range(repeats):
        start = time.perf_counter()
        result = call()
        best = min(best, time.perf_counter() - start)
    return best, result


def bench_propagate(n: int = 1_000_000, n_ref: int = 200, seed: int = 0, repeats: int = 3) -> list[PropagateRow]:
    """Time and check every available two-body propagator on the "elliptic" and "mixed" sets (see
    _propagation_sets). Errors are relative to |r| and |v| of the mpmath reference (orbits.tools.reference);
    timings exclude preparing the inputs in the form each library takes.
    Returns one PropagateRow per (method, data set)."""
    loaded = _load(_PROPAGATORS)
    rows = []
    for states in _propagation_sets(n, seed):
        refs = _propagation_references(states, n_ref)
        for name, method, note in loaded:
            if method is None:
                rows.append(PropagateRow(name, states.name, 0, *[math.nan] * 4, 0, "skipped", note))
            else:
                rows.append(_measure_propagator(method, states, refs, repeats))
    return rows


def format_propagate(rows: Sequence[PropagateRow]) -> str:
    """Plain-text table of bench_propagate, at most 80 columns: a section per data set, M states/s, ratio to
    orbits on one thread on the same set, worst relative position and velocity errors, NaN count; the notes
    in a numbered list under the table."""
    reference = {r.dataset: r.throughput_per_s for r in rows if r.method == "orbits" and r.status == "ok"}
    table, texts = _by_dataset(rows, reference, _propagation_stats)
    lines = _table(["method", "M/s", "ratio", "|dr|/r", "|dv|/v", "NaN"], table)
    legend = (
        f"M/s: millions of states propagated per second. {_RATIO} |dr|/r, |dv|/v: max |dr|/r and max |dv|/v, "
        "the worst relative position and velocity errors against mpmath. NaN: non-finite results."
    )
    return "\n".join(lines + [""] + _wrap(legend, WIDTH) + _notes(texts))


def _propagation_stats(row):
    return [f"{row.max_position_error:.2e}", f"{row.max_velocity_error:.2e}"]


# --- unit-aware API overhead ----------------------------------------------------------------------


@dataclass(frozen=True)
class ApiRow:
    """One API call against the core call it wraps, on the same inputs: seconds per call (best of the
    repeats) and the overhead, absolute and as a fraction of the core time."""

    case: str
    n: int
    core_seconds: float
    api_seconds: float
    overhead_seconds: float
    overhead_fraction: float


def _per_call(call, n, repeats):
    """Best over repeats of the mean time per call, over enough calls to last about 20 ms."""
    call()
    number = max(1, int(0.02 / max(_best_time(call, 1)[0], 1e-7))) if n < 1000 else 1
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(number):
            call()
        best = min(best, (time.perf_counter() - start) / number)
    return best


def _api_cases(n, rng):
    """[(case name, core call, API call)] on n orbits (scalars for n = 1)."""
    import astropy.units as u

    from orbits import Orbit
    from orbits.core import elements
    from orbits.core.propagate import propagate

    shape = () if n == 1 else (n,)
    a, e, nu = 7000 + rng.uniform(0, 1000, shape), rng.uniform(0, 0.5, shape), rng.uniform(-np.pi, np.pi, shape)
    a_q, nu_q, dt = a * u.km, nu * u.rad, rng.uniform(0, 1e4, shape)
    dt_q = dt * u.s
    orbit = Orbit.from_elements("Earth", a=a_q, e=e, nu=nu_q)
    r, v = orbit._state  # the state the API call uses, computed once (cached) as in any repeated use
    p, zero = a * 1e3 * (1 - e) * (1 + e), np.zeros(shape)
    return [
        ("Orbit.propagate vs core propagate", lambda: propagate(r, v, orbit.mu, dt), lambda: orbit.propagate(dt_q)),
        (
            "Orbit.from_elements vs elements_to_state",
            lambda: elements.elements_to_state(p, e, zero, zero, zero, nu, orbit.mu),
            lambda: Orbit.from_elements("Earth", a=a_q, e=e, nu=nu_q),
        ),
    ]


def bench_api(sizes: Iterable[int] = (1, 100_000, 1_000_000), seed: int = 0, repeats: int = 5) -> list[ApiRow]:
    """Overhead of the unit-aware API (orbits.Orbit) over the float64 core on the same inputs, per call,
    for scalars and arrays of the given sizes. Returns one ApiRow per (case, size)."""
    rows = []
    rng = np.random.default_rng(seed)
    for n in sizes:
        for case, core, api in _api_cases(n, rng):
            core_s, api_s = _per_call(core, n, repeats), _per_call(api, n, repeats)
            rows.append(ApiRow(case, n, core_s, api_s, api_s - core_s, (api_s - core_s) / core_s))
    return rows


def format_api(rows: Sequence[ApiRow]) -> str:
    """Plain-text table of bench_api, at most 80 columns: a section per case, a row per size; times per call
    in microseconds (4 significant digits), overhead in microseconds and as a percentage of the core time."""
    table = []
    for case in dict.fromkeys(r.case for r in rows):
        table.append(case)
        for r in (r for r in rows if r.case == case):
            times = (_fixed(t * 1e6, 4) for t in (r.core_seconds, r.api_seconds, r.overhead_seconds))
            table.append([str(r.n), *times, _fixed(r.overhead_fraction * 100, 3) + "%"])
    lines = _table(["n", "core us", "API us", "overhead us", "overhead"], table, first=">")
    legend = "us: microseconds per call, best of the repeats. overhead: API minus core, in us and as a share of core."
    return "\n".join(lines + [""] + _wrap(legend, WIDTH))


# --- command-line cold start ----------------------------------------------------------------------

#: (arguments of `orbits`, target wall time in seconds or None) of bench_cli.
CLI_COMMANDS = [
    (["--help"], 0.2),
    (["orbit", "--primary", "Earth", "--a", "42164 km", "--only", "period,speed"], 0.6),
    (["kepler", "--e", "0.9", "--M", "0.1 rad"], 0.5),
]


@dataclass(frozen=True)
class CliRow:
    """Wall time of `runs` fresh processes running one command: median and fastest; the issue's target."""

    command: str
    runs: int
    median_seconds: float
    min_seconds: float
    target_seconds: float | None


def _orbits_command():
    """The installed `orbits` script, or the same entry point through this interpreter."""
    script = shutil.which("orbits")
    return [script] if script else [sys.executable, "-c", "from orbits_cli.main import app; app()"]


#: imports every command pays before orbits does anything, timed the same way (fresh processes of this Python):
#: the floor under the cold-start targets on this machine
FLOOR_IMPORTS = ["numpy", "astropy.units"]

#: (arguments of `orbits`, target seconds or None, largest ratio to the warm run or None) of the first runs
#: bench_cli times: once with an empty kernel cache, as on a fresh install, then once more with the cache that
#: run left
FIRST_RUN_COMMANDS = [
    (["kepler", "--e", "0.9", "--M", "0.1 rad"], 1.0, None),
    (["validate", "--format", "json"], None, 1.5),
]


def bench_cli(runs: int = 10, commands: Sequence[tuple[list[str], float | None]] | None = None,
              first_runs: Sequence[tuple[list[str], float | None, float | None]] | None = None) -> list[CliRow]:
    """Cold-start wall time of each command over `runs` fresh processes (one unmeasured warm-up run
    fills the OS file cache, as on any machine that has run orbits before), after the FLOOR_IMPORTS alone (by
    default, that is when no commands are given); then each of `first_runs`
    (FIRST_RUN_COMMANDS when neither list is given) timed once with NUMBA_CACHE_DIR a new empty folder (what a
    new user waits for: anything compiled on first use) and once more warm, the target of the first run being
    its own, or its ratio to the warm run times the warm time."""
    rows = []
    floors = [([sys.executable, "-c", f"import {name}"], f"floor: python -c 'import {name}'")
              for name in (FLOOR_IMPORTS if commands is None else [])]
    timed = [(_orbits_command() + args, "orbits " + " ".join(args), target)
             for args, target in (CLI_COMMANDS if commands is None else commands)]
    for argv, label, target in [(argv, label, None) for argv, label in floors] + timed:
        _process_times(argv, 1)  # the warm-up run
        times = _process_times(argv, runs)
        rows.append(CliRow(label, runs, statistics.median(times), min(times), target))
    for args, target, ratio in (FIRST_RUN_COMMANDS if commands is None and first_runs is None else first_runs or []):
        first, warm = _first_and_warm(_orbits_command() + args)
        command = "orbits " + " ".join(args)
        rows.append(CliRow(f"{command} (first ever: empty kernel cache)", 1, first, first,
                           target if ratio is None else ratio * warm))
        rows.append(CliRow(f"{command} (second run, warm cache)", 1, warm, warm, None))
    return rows


def _first_and_warm(argv: list[str]) -> tuple[float, float]:
    """Wall times (s) of argv run twice in fresh processes sharing a new, empty numba cache folder."""
    with tempfile.TemporaryDirectory(prefix="orbits-bench-cache-") as folder:
        first, warm = _process_times(argv, 2, {**os.environ, "NUMBA_CACHE_DIR": folder})
    return first, warm


def _process_times(argv: list[str], runs: int, environment: dict[str, str] | None = None) -> list[float]:
    """Wall time (s) of each of `runs` fresh processes running argv (which must exit 0)."""
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(argv, capture_output=True, check=True, env=environment)
        times.append(time.perf_counter() - start)
    return times


def format_cli(rows: Sequence[CliRow]) -> str:
    """Plain-text table of bench_cli, at most 80 columns (a long command wraps onto indented lines)."""
    table = [
        [r.command, str(r.runs), f"{r.median_seconds:.3f}", f"{r.min_seconds:.3f}",
         f"{r.target_seconds:.2f}" if r.target_seconds else "-"]
        for r in rows
    ]
    return "\n".join(_table(["command", "runs", "median s", "min s", "target s"], table))


# --- validation: where the time goes --------------------------------------------------------------


@dataclass(frozen=True)
class ValidateRow:
    """Wall time of one scene (or of the whole run, scene "all") by stage: "analytic", "<backend> setup"
    (integrator construction; heyoka's compilation, or its cache hit) and "<backend> integration";
    "other" is the rest of validate_scene (comparisons, residuals). mode: sequential or sweep."""

    scene: str
    mode: str
    stages: dict
    total_seconds: float


def _scene_row(report, total, mode):
    stages = {"analytic": report.wall_times["analytic"]}
    for backend, setup in report.setup_times.items():
        stages[f"{backend} setup"] = setup
        stages[f"{backend} integration"] = report.wall_times[backend]
    stages["other"] = total - sum(stages.values())
    return ValidateRow(report.name, mode, stages, total)


def bench_validate(
    scenes: "Sequence[str | Scene | ModelScene] | None" = None,
    backend_names: Sequence[str] = ("rebound", "heyoka"),
    sweep: bool = True,
) -> list[ValidateRow]:
    """Time `orbits validate` stage by stage on the built-in data and model scenes (or `scenes`, names or
    loaded scenes): sequentially in this process, scene by scene, then (sweep=True, dask installed) as
    validate_sweep on a 2-worker LocalCluster of threads and of processes, whole runs only (cluster start-up
    included). A scene given by name is loaded inside its timing, as `orbits validate` does: a model scene
    makes its prediction (the "analytic" stage) when it is built, so only then do the stages add up to at most
    the total; a scene passed loaded has had that time already."""
    from orbits.validate import builtin_names, load, validate

    rows, loaded = [], []
    start_all = time.perf_counter()
    for item in scenes or builtin_names():
        start = time.perf_counter()
        scene = load(item) if isinstance(item, str) else item
        report = validate([scene], backend_names).scenes[0]
        rows.append(_scene_row(report, time.perf_counter() - start, "sequential"))
        loaded.append(scene)
    rows.append(ValidateRow("all", "sequential", {}, time.perf_counter() - start_all))
    if sweep:
        rows.extend(_sweep_rows(loaded, backend_names))
    return rows


def _sweep_rows(scenes, backend_names):
    try:
        from orbits.tools import distributed
    except ImportError:
        return []
    rows = []
    for processes in (False, True):
        start = time.perf_counter()
        try:
            with distributed.sweep_client(processes=processes) as client:
                started = time.perf_counter()
                distributed.validate_sweep(scenes, client, backend_names)
                swept = time.perf_counter()
        except ImportError:
            return []
        mode = f"sweep, 2 worker {'processes' if processes else 'threads'}"
        stages = {"cluster start": started - start, "scenes": swept - started}
        rows.append(ValidateRow("all", mode, stages, time.perf_counter() - start))
    return rows


def format_validate(rows: Sequence[ValidateRow]) -> str:
    """Plain-text tables of bench_validate, at most 80 columns: seconds in total and per stage, one line per
    scene or run.  Consecutive rows with compatible stages share a table, titled by what they have in common
    (e.g. the mode "sequential") and labelled by what varies (the scene, or the mode of the sweeps); a table
    with more stages than 80 columns hold continues, label repeated, in further blocks under it."""
    sections = []  # [(stage names, rows)]
    for r in rows:
        if sections and (r.stages.keys() <= set(sections[-1][0]) or set(sections[-1][0]) <= r.stages.keys()):
            stages, group = sections.pop()
            sections.append((list(dict.fromkeys([*stages, *r.stages])), [*group, r]))
        else:
            sections.append((list(r.stages), [r]))
    return "\n\n".join("\n".join(_validate_section(stages, group)) for stages, group in sections)


def _validate_section(stages, rows):
    """Lines of one table of format_validate."""
    fields = {"scene": [r.scene for r in rows], "mode": [r.mode for r in rows]}
    varying = [name for name, values in fields.items() if len(set(values)) > 1] or ["scene"]
    label = ", ".join(varying)
    labels = [", ".join(values) for values in zip(*(fields[name] for name in varying))]
    common = "; ".join(f"{name} {values[0]}" for name, values in fields.items() if name not in varying)
    columns = [("total", [f"{r.total_seconds:.3f}" for r in rows])]
    columns += [(s, [f"{r.stages[s]:.4f}" if s in r.stages else "" for r in rows]) for s in stages]
    lines = _wrap(f"{common}: seconds, in total and per stage" if common else "seconds, in total and per stage", WIDTH)
    for i, block in enumerate(_blocks(max(map(len, [label, *labels])), columns)):
        table = [[name, *(cells[j] for _, cells in block)] for j, name in enumerate(labels)]
        table = [row for row in table if any(row[1:])]  # a run without these stages is in the first block
        lines += [""] * (i > 0) + _table([label, *(title for title, _ in block)], table, stack=True)
    return lines


def _blocks(label_width, columns, width=WIDTH):
    """columns [(title, cells)] split into as few consecutive blocks as fit beside the label column in
    `width`, as evenly as possible."""
    need = [max([len(w) for w in title.split()] + [len(c) for c in cells]) + len(_GAP) for title, cells in columns]
    room = max(width - min(label_width, 3 * width // 5), max(need, default=0))

    def pack(capacity):
        blocks, used = [[]], 0
        for column, w in zip(columns, need):
            if blocks[-1] and used + w > capacity:
                blocks.append([])
                used = 0
            blocks[-1].append(column)
            used += w
        return blocks

    fewest = len(pack(room))
    return next(pack(c) for c in range(max(need, default=0), room + 1) if len(pack(c)) == fewest)


# --- everything -----------------------------------------------------------------------------------

#: name -> (run with default sizes, format) of every benchmark, in the order `orbits bench all` runs them.
def _bench_lambert(**options):
    from orbits.tools.bench_lambert import bench_lambert

    return bench_lambert(**options)


def _format_lambert(rows):
    from orbits.tools.bench_lambert import format_lambert

    return format_lambert(rows)


def _bench_ephemeris(**options):
    from orbits.tools.bench_ephemeris import bench_ephemeris

    return bench_ephemeris(**options)


def _format_ephemeris(rows):
    from orbits.tools.bench_ephemeris import format_ephemeris

    return format_ephemeris(rows)


#: every benchmark: name -> (run, format); Lambert's and the ephemeris' live in their own modules (which use this
#: module's table helpers) and are loaded when run
BENCHMARKS = {
    "kepler": (bench_kepler, format_rows),
    "propagate": (bench_propagate, format_propagate),
    "lambert": (_bench_lambert, _format_lambert),
    "ephemeris": (_bench_ephemeris, _format_ephemeris),
    "api": (bench_api, format_api),
    "cli": (bench_cli, format_cli),
    "validate": (bench_validate, format_validate),
}


def bench_all(**options: dict[str, Any]) -> dict[str, list[Any]]:
    """{name: rows} of every benchmark; options maps a benchmark name to its keyword arguments."""
    return {name: run(**options.get(name, {})) for name, (run, _) in BENCHMARKS.items()}


def format_report(report: Mapping[str, Sequence[Any]]) -> str:
    """Every benchmark's table under its name."""
    return "\n\n".join(f"== {name} ==\n{BENCHMARKS[name][1](rows)}" for name, rows in report.items())


def report_to_json(report: Mapping[str, Iterable[object]]) -> dict[str, list[dict[str, object]]]:
    """{name: rows as JSON-ready dicts} (NaN and infinity become None)."""
    return {name: rows_to_json(rows) for name, rows in report.items()}
