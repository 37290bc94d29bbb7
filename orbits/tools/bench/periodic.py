"""`orbits bench periodic`: periodic orbits of the restricted problem, their corrections timed and their integrations
counted, with the compiled integrator (orbits.core.periodic._fast_cr3bp, one thread) and with the NumPy one.

Cases: one corrected orbit (the Earth-Moon L2 southern halo of Az = 20,000 km, continued from its first member near
L2 to that amplitude) and a family of `members` orbits (the Earth-Moon L2 southern halo family from that first
member to the 9:2 near-rectilinear halo orbit, evenly spaced in arclength). A row counts the trajectories the
correction integrated with the state transition matrix and without (the extents and closest approaches the
search measures), their accepted steps and the Newton iterations, and checks the result: the orbit's closure after
one period of its own integration, over its size (the family: the worst member's).
"""

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from orbits.tools.bench.harness import best_time, machine, orbits_threads
from orbits.tools.bench.table import WIDTH, notes, plain_table, sig, wrap


@dataclass(frozen=True)
class PeriodicRow:
    """One case with one integrator: best wall time of the repeats (s), the trajectories integrated, their steps,
    the Newton iterations, the worst closure over one period / size; status "ok" or "raised"."""

    case: str
    method: str
    seconds: float
    integrations: int
    steps: int
    iterations: int
    closure: float
    status: str
    note: str = ""


def _closure(orbit) -> float:
    """|r(T) - r(0)| / max amplitude in the orbit's own integration."""
    import astropy.units as u

    arc = orbit._flow().arc(orbit.local_state, orbit.dimensionless_period)
    size = float(np.max(orbit.amplitudes.to_value(u.m))) / float(orbit.system.r)
    return float(np.linalg.norm(arc.end[:3] - orbit.local_state[:3])) / size


def _one_orbit(system):
    import astropy.units as u

    from orbits.periodic.family import PeriodicOrbit

    def run():
        orbit = PeriodicOrbit.halo(system, "L2", az=20_000 * u.km, branch="southern")
        return orbit, orbit.work

    return run


def _family(system, members):
    from orbits.periodic.family import PeriodicFamily

    def run():
        family = PeriodicFamily.of(system, "nrho", "L2", members=members, resonance="9:2")
        return family, family.work

    return run


def bench_periodic(members: int = 100, repeats: int = 3, numpy: bool = True) -> list[PeriodicRow]:
    """Time one corrected orbit and a family of `members` orbits with the compiled integrator and (with `numpy`)
    the NumPy one; best of `repeats` (the NumPy family once)."""
    from orbits.threebody.lagrange import RestrictedThreeBody

    system = RestrictedThreeBody.from_primaries("Earth", "Moon")
    cases = [("one orbit: EM L2 halo, Az 20,000 km", _one_orbit(system), False),
             (f"{members} members: L2 halo to 9:2 NRHO", _family(system, members), True)]
    methods = [("orbits (compiled)", 1)] + ([("orbits (NumPy)", 0)] if numpy else [])
    rows = []
    for case, run, is_family in cases:
        for method, threads in methods:
            times = 1 if is_family and threads == 0 else repeats
            try:
                with orbits_threads(threads):
                    run()  # the compiled kernel loads (or compiles) once, outside the timing
                    seconds, (result, work) = best_time(run, times)
                    members_ = result.members if is_family else [result]
                    closure = max(_closure(m) for m in members_)
            except Exception as exc:  # a failure is a benchmark result, not a crash
                note = f"raised {type(exc).__name__}: {exc}".splitlines()[0][:200]
                rows.append(PeriodicRow(case, method, math.nan, 0, 0, 0, math.nan, "raised", note))
                continue
            rows.append(PeriodicRow(case, method, seconds, work["integrations"], work["steps"], work["iterations"],
                                    closure, "ok"))
    return rows


def format_periodic(rows: Sequence[PeriodicRow]) -> str:
    """Plain-text table of bench_periodic (80 columns): a section per case; the machine on the last line."""
    table, texts = [], {}
    for case in dict.fromkeys(r.case for r in rows):
        table.append([f"{case}:", "", "", "", "", ""])
        for row in (r for r in rows if r.case == case):
            mark = texts.setdefault(row.note, len(texts) + 1) if row.note else None
            label = f"  {row.method}" + (f" [{mark}]" if mark else "")
            if row.status != "ok":
                table.append([label, row.status, "", "", "", ""])
                continue
            table.append([label, sig(row.seconds), str(row.integrations), str(row.steps), str(row.iterations),
                          f"{row.closure:.1e}"])
    lines = plain_table(["method", "s", "integr.", "steps", "Newton", "closure"], table)
    legend = ("s: best wall time of the repeats (the NumPy family: one run). integr.: trajectories integrated, with "
              "the transition matrix (corrections) or without (extents, closest approaches). steps: their accepted "
              "steps. Newton: corrector iterations. closure: worst |r(T) - r(0)| / size in the orbit's own "
              "integration.")
    return "\n".join(lines + [""] + wrap(legend, WIDTH) + notes(texts) + ["", f"Machine: {machine()}"])
