"""`orbits bench stm`: the state-transition matrix d(r, v)/d(r0, v0) of two-body propagation, time per state and
worst error against 50-digit mpmath central differences (orbits.tools.reference.transition_matrix), for orbits
(compiled kernel on one thread, NumPy) and pykep's propagate_lagrangian(stm=True), timed per call, where pykep
imports (its wheels pin an older heyoka than lagrange_prop needs, so the two rarely share an environment).

Sets: "elliptic" (e in [0, 0.95]) and "mixed" (a third each of those ellipses, hyperbolas with e - 1 = 10**U(-6,
0.5) and near-parabolic orbits with |1 - e| < 1e-3), p = 7000-21000 km about the Earth, flights of +-10 periods
(2 pi sqrt(p**3 / mu) on open orbits). The error is |Phi - Phi_ref| / |Phi_ref| (Frobenius norms).
"""

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from orbits.tools.bench.harness import Method, best_time, check_sizes, load_methods, machine, orbits_threads
from orbits.tools.bench.table import WIDTH, notes, plain_table, sig, wrap

MU_EARTH = 3.986004418e14
#: states pykep is timed on, one call each (its time is per call, so it scales)
PER_CALL_SUBSET = 2000


@dataclass(frozen=True)
class StmRow:
    """One method on one set: best time of the repeats for n states, microseconds per state, worst error over the
    first n_ref states against mpmath; status "ok", "skipped" or "raised"."""

    method: str
    dataset: str
    n: int
    seconds: float
    us_per_state: float
    max_rel_error: float
    status: str
    note: str = ""


@dataclass(frozen=True)
class _States:
    name: str
    r0: np.ndarray
    v0: np.ndarray
    dt: np.ndarray


def _sets(n, seed):
    from orbits.core.twobody.elements import elements_to_state

    rng = np.random.default_rng(seed)
    third = n // 3
    mixed = np.concatenate([rng.uniform(0, 0.95, third), 1 + 10 ** rng.uniform(-6, 0.5, third),
                            1 + rng.uniform(-1e-3, 1e-3, n - 2 * third)])
    sets = []
    for name, e in (("elliptic", rng.uniform(0, 0.95, n)), ("mixed", rng.permutation(mixed))):
        p = 7e6 * rng.uniform(1, 3, n)
        angles = (rng.uniform(0, np.pi, n), rng.uniform(0, 2 * np.pi, n), rng.uniform(0, 2 * np.pi, n),
                  rng.uniform(-1, 1, n))
        r0, v0 = elements_to_state(p, e, *angles, MU_EARTH)
        scale = np.where(e < 1, p / np.where(e < 1, (1 - e) * (1 + e), 1.0), p)
        sets.append(_States(name, r0, v0, rng.uniform(-10, 10, n) * 2 * np.pi * np.sqrt(scale**3 / MU_EARTH)))
    return sets


def _orbits(threads):
    from orbits.core.twobody.transition import transition_matrix

    def solve(states):
        with orbits_threads(threads):
            return transition_matrix(states.r0, states.v0, MU_EARTH, states.dt)

    name, note = ("orbits", "compiled kernel, 1 thread") if threads else ("orbits (NumPy)", "the NumPy specification")
    return Method(name, solve, lambda s: s, 0.0, note)


def _pykep():
    try:
        import pykep
    except ImportError:
        raise
    except Exception as exc:  # pykep 3.0.1 fails to import beside heyoka >= 7.11 (its wheels pin heyoka 7.10)
        raise ImportError(str(exc), name=f"pykep, which fails to import here: {type(exc).__name__}") from exc

    def solve(states):
        phi = np.empty((states.dt.size, 6, 6))
        for i in range(states.dt.size):
            _, matrix = pykep.propagate_lagrangian([states.r0[i], states.v0[i]], states.dt[i], MU_EARTH, True)
            phi[i] = matrix
        return phi

    return Method("pykep propagate_lagrangian", solve, lambda s: s, 0.0, "stm=True, per call", PER_CALL_SUBSET)


_METHODS = [("orbits", lambda: _orbits(1)), ("orbits (NumPy)", lambda: _orbits(0)),
            ("pykep propagate_lagrangian", _pykep)]


def _errors(phi, states, n_ref):
    from orbits.tools.reference import transition_matrix

    worst = 0.0
    for i in range(min(n_ref, phi.shape[0])):
        reference = np.array(transition_matrix(states.r0[i], states.v0[i], MU_EARTH, states.dt[i]), dtype=float)
        worst = max(worst, float(np.linalg.norm(phi[i] - reference) / np.linalg.norm(reference)))
    return worst


def _subset(states, n):
    return _States(states.name, states.r0[:n], states.v0[:n], states.dt[:n])


def bench_stm(n: int = 100_000, n_ref: int = 20, seed: int = 0, repeats: int = 3) -> list[StmRow]:
    """Time and check every available state-transition matrix on the elliptic and mixed sets."""
    check_sizes(n=n, n_ref=n_ref, repeats=repeats)
    rows = []
    for states in _sets(n, seed):
        for name, method, skip in load_methods(_METHODS):
            if method is None:
                rows.append(StmRow(name, states.name, 0, math.nan, math.nan, math.nan, "skipped", skip))
                continue
            data = states if method.subset is None else _subset(states, method.subset)
            try:
                seconds, phi = best_time(lambda solve=method.solve, data=data: solve(data), repeats)
            except Exception as exc:  # a peer failing is a benchmark result, not a crash
                note = f"raised {type(exc).__name__}: {exc}".splitlines()[0][:200]
                rows.append(StmRow(name, states.name, data.dt.size, math.nan, math.nan, math.nan, "raised", note))
                continue
            rows.append(StmRow(name, states.name, data.dt.size, seconds, 1e6 * seconds / data.dt.size,
                               _errors(phi, data, n_ref), "ok", method.note))
    return rows


def format_stm(rows: Sequence[StmRow]) -> str:
    """Plain-text table of bench_stm (80 columns): a section per set, microseconds per state, the ratio to orbits
    on one thread (above 1: slower than orbits), worst error; the machine on the last line."""
    reference = {r.dataset: r.us_per_state for r in rows if r.method == "orbits" and r.status == "ok"}
    table, texts = [], {}
    for dataset in dict.fromkeys(r.dataset for r in rows):
        table.append([f"{dataset}:", "", "", ""])
        for row in (r for r in rows if r.dataset == dataset):
            mark = texts.setdefault(row.note, len(texts) + 1) if row.note else None
            label = f"  {row.method}" + (f" [{mark}]" if mark else "")
            if row.status != "ok":
                table.append([label, row.status, "", ""])
                continue
            ratio = row.us_per_state / reference[dataset] if dataset in reference else math.nan
            table.append([label, sig(row.us_per_state), sig(ratio), f"{row.max_rel_error:.1e}"])
    lines = plain_table(["method", "us/state", "x orbits", "rel err"], table)
    legend = ("us/state: microseconds per state (best of the repeats). x orbits: time per state over orbits' on one "
              "thread. rel err: worst |Phi - Phi_ref| / |Phi_ref| against 50-digit mpmath central differences.")
    return "\n".join(lines + [""] + wrap(legend, WIDTH) + notes(texts) + ["", f"Machine: {machine()}"])
