"""`orbits bench ephemeris`: positions and velocities of a body at many epochs, against jplephem and astropy
reading the same DE421 file, in one run (each timed `repeats` times, the best kept).

Every reader gets the same epochs as an astropy Time in TDB (orbits and astropy) or as the two-part TDB Julian
dates (jplephem), for the same chain of kernel segments (Mars: barycentre -> Mars system barycentre -> Mars),
and each answer's largest distance from jplephem's is reported.
"""

import importlib.util
from dataclasses import dataclass

import numpy as np

from orbits.tools.bench.harness import best_time, check_sizes
from orbits.tools.bench.table import WIDTH, mega, plain_table, sig, wrap

#: the DE421 chain of Mars relative to the solar-system barycentre
_MARS = ((0, 4), (4, 499))


@dataclass(frozen=True)
class EphemerisRow:
    """One reader: states per second (positions and velocities), and largest |dr| (m) and |dv| (m/s) from
    jplephem's."""

    name: str
    status: str
    n: int
    per_second: float
    dr: float
    dv: float


def _epochs(n, seed):
    from astropy.time import Time

    jd = np.random.default_rng(seed).uniform(2415021.0, 2469807.0, n)
    return Time(jd, format="jd", scale="tdb")


def _jplephem(when):
    from orbits.ephemeris import positions as ephemeris

    kernel = ephemeris._kernel()
    jd1, jd2 = when.jd1, when.jd2

    def call():
        r = np.zeros((3, jd1.size))
        v = np.zeros((3, jd1.size))
        for pair in _MARS:
            p, d = kernel[pair].compute_and_differentiate(jd1, jd2)
            r += p
            v += d
        return (r * 1e3).T, (v * (1e3 / 86400.0)).T

    return call


def _orbits(when):
    from orbits.ephemeris import positions as ephemeris

    def call():
        state = ephemeris.state("Mars", when, center="SSB", source="de421")
        return state.r_si, state.v_si

    return call


def _astropy(when):
    import astropy.units as u
    from astropy.coordinates import get_body_barycentric_posvel

    from orbits.ephemeris import positions as ephemeris

    path = ephemeris.kernel_path()

    def call():
        r, v = get_body_barycentric_posvel("mars", when, ephemeris=path)
        return r.xyz.to_value(u.m).T, v.xyz.to_value(u.m / u.s).T

    return call


def bench_ephemeris(n: int = 100_000, seed: int = 0, repeats: int = 3) -> list[EphemerisRow]:
    """Time orbits, jplephem and astropy on the states of Mars at `n` random TDB epochs 1900-2050."""
    check_sizes(n=n, repeats=repeats)
    from orbits.ephemeris import positions as ephemeris

    if ephemeris.available_source() != "de421":
        return [EphemerisRow("orbits", "needs orbits[ephemeris] (skyfield-data, jplephem)", n, np.nan, np.nan, np.nan)]
    when = _epochs(n, seed)
    ephemeris.state("Mars", when[:2], center="SSB", source="de421")  # open the kernel outside the timing
    seconds, (r_ref, v_ref) = best_time(_jplephem(when), repeats)
    rows = [EphemerisRow("jplephem (two segments, raw)", "ok", n, n / seconds, 0.0, 0.0)]
    for name, factory in (("orbits.ephemeris.positions.state", _orbits), ("astropy get_body_barycentric_posvel",
    _astropy)):
        seconds, (r, v) = best_time(factory(when), repeats)
        rows.append(EphemerisRow(name, "ok", n, n / seconds, float(np.abs(r - r_ref).max()),
                                 float(np.abs(v - v_ref).max())))
    if importlib.util.find_spec("skyfield") is None:
        rows.append(EphemerisRow("skyfield", "not installed", n, np.nan, np.nan, np.nan))
    return rows


def format_ephemeris(rows: list[EphemerisRow]) -> str:
    """The bench as a table of at most 80 columns: M states/s, the ratio to jplephem, and the largest gaps."""
    reference = next((r.per_second for r in rows if r.name.startswith("jplephem")), np.nan)
    cells = []
    for r in rows:
        if r.status != "ok":
            cells.append([f"{r.name}: {r.status}", "-", "-", "-", "-"])
            continue
        cells.append([r.name, mega(r.per_second), sig(r.per_second / reference, 3), sig(r.dr, 2),
                      sig(r.dv, 2)])
    header = ["Mars from the barycentre, DE421", "M states/s", "x jplephem", "max |dr| m", "max |dv| m/s"]
    title = f"{rows[0].n:,} random TDB epochs 1900-2050: positions and velocities, one thread, best of the repeats"
    return "\n".join([*wrap(title, WIDTH), *plain_table(header, cells, stack=True)])
