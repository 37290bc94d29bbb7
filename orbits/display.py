"""Display units and digits, decided in one place: the command-line tables, the HTML and one-line reprs, and the
axes of the plots all ask this module how to show a quantity.

A quantity is shown in the natural unit for its kind and size, the largest finite magnitude choosing the rung:

    length    m below 1 km, km below 1e7 km (and for 0), AU below 1e5 AU, pc below 1e5 pc, Mpc beyond
    time      s below 2 min, min below 2 h, h below 2 d, d below 1000 d, yr below 1e7 yr, Gyr beyond
    angle     deg; an angular rate in deg per the natural time unit of 1 rad / rate (deg / d for a planet)
    speed     km/s from 1 km/s, m/s below (a projectile, a radial-velocity curve); GM in km3 / s2; specific
              energy in km2 / s2; h and dA/dt in km2 / s
    rate      km / s / Mpc for a Hubble parameter; otherwise 1 / (the natural time unit of 1 / rate)
    mass      kg below 1e20 kg, Earth masses below 0.1 M_jup, Jupiter masses below 0.05 M_sun, solar masses beyond
    volume    m3 below 1e9 m3, km3 below (1e5 pc)**3, Mpc3 below (1 Gpc)**3, Gpc3 beyond

with DIGITS significant digits. `system="si"` shows SI units instead, and `overrides` fixes the unit of a named
quantity. JSON is not display: it carries the exact float64 value in SI (orbits_cli.render). Numbers never show
as -0; non-finite values show as inf, -inf and nan.
"""

import html
import math
from collections.abc import Mapping
from typing import Any

import astropy.units as u
import numpy as np

#: significant digits shown by default
DIGITS = 7
SYSTEMS = ("natural", "si")

_LENGTHS = [(1e3, u.m), (1e10, u.km), (1e5 * u.AU.to(u.m), u.AU), (1e5 * u.pc.to(u.m), u.pc), (math.inf, u.Mpc)]
_TIMES = [(120.0, u.s), (7200.0, u.min), (172800.0, u.h), (1000 * 86400.0, u.day), (1e7 * u.yr.to(u.s), u.yr),
          (math.inf, u.Gyr)]
_HUBBLE = u.km / u.s / u.Mpc
#: units shown by their astronomers' names rather than astropy's (solMass)
_NAMED = {u.M_sun: "M_sun", u.M_jup: "M_jup", u.M_earth: "M_earth"}
_MASSES = [(1e20, u.kg), (0.1 * u.M_jup.to(u.kg), u.M_earth), (0.05 * u.M_sun.to(u.kg), u.M_jup), (math.inf, u.M_sun)]
_VOLUMES = [(1e9, u.m**3), ((1e5 * u.pc.to(u.m)) ** 3, u.km**3), ((1e3 * u.Mpc.to(u.m)) ** 3, u.Mpc**3),
            (math.inf, u.Gpc**3)]
_FIXED = [  # (SI unit, natural unit), tried in order after lengths, times, angles, rates and speeds
    (u.m**3 / u.s**2, u.km**3 / u.s**2),
    (u.m**2 / u.s**2, u.km**2 / u.s**2),
    (u.m**2 / u.s, u.km**2 / u.s),
]


def _size(q: u.Quantity, si: u.UnitBase) -> float:
    """Largest finite magnitude of q in the SI unit si (0 if there is none)."""
    values = np.abs(np.asarray(q.to_value(si), dtype=float)).ravel()
    finite = values[np.isfinite(values)]
    return float(finite.max()) if finite.size else 0.0


def _rung(size: float, ladder: list) -> u.UnitBase:
    return next(unit for limit, unit in ladder if size < limit)


def natural_unit(q: u.Quantity, name: str = "") -> u.UnitBase:
    """The unit a person reads `q` in (see the module docstring); the quantity's own unit if none applies."""
    unit = q.unit
    if unit.is_equivalent(u.one):
        return u.one
    if unit.is_equivalent(u.m):
        size = _size(q, u.m)
        return _rung(size, _LENGTHS) if size > 0 else u.km
    if unit.is_equivalent(u.s):
        return _rung(_size(q, u.s), _TIMES)
    if unit.is_equivalent(u.rad):
        return u.deg
    if unit.is_equivalent(u.rad / u.s):
        rate = _size(q, u.rad / u.s)
        return u.deg / _rung(1.0 / rate if rate > 0 else 0.0, _TIMES)
    if unit.is_equivalent(1 / u.s):
        if "hubble" in name:
            return _HUBBLE
        rate = _size(q, 1 / u.s)
        return _rung(1.0 / rate if rate > 0 else 0.0, _TIMES) ** -1
    if unit.is_equivalent(u.m / u.s):
        return u.km / u.s if _size(q, u.m / u.s) >= 1e3 else u.m / u.s
    if unit.is_equivalent(u.kg):
        return _rung(_size(q, u.kg), _MASSES)
    if unit.is_equivalent(u.m**3):
        return _rung(_size(q, u.m**3), _VOLUMES)
    for si, natural in _FIXED:
        if unit.is_equivalent(si):
            return natural
    return unit


def si_unit(q: u.Quantity) -> u.UnitBase:
    """The SI unit of q (angles in rad): what JSON carries and `system="si"` shows."""
    if q.unit.is_equivalent(u.one):
        return u.one
    return q.unit.si if not q.unit.is_equivalent(u.rad) else u.rad


def unit_for(q: u.Quantity, name: str = "", system: str = "natural", overrides: Mapping[str, Any] | None = None):
    """The unit to show the quantity `name` in: its override, else SI or the natural unit."""
    if overrides and name in overrides:
        unit = u.Unit(overrides[name])
        if not q.unit.is_equivalent(unit):
            raise u.UnitConversionError(f"--unit {name}={overrides[name]}: {name} is in {q.unit}, not {unit}")
        return unit
    return si_unit(q) if system == "si" else natural_unit(q, name)


def number(x: float, digits: int = DIGITS) -> str:
    """x with `digits` significant digits; never -0; inf, -inf and nan spelled out."""
    x = float(x)
    if not math.isfinite(x):
        return "nan" if math.isnan(x) else ("inf" if x > 0 else "-inf")
    if x == 0:
        return "0"
    text = f"{x:.{digits}g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        text = f"{mantissa}e{int(exponent)}"
    return text


def values_text(values: np.ndarray, digits: int = DIGITS) -> str:
    """A value, a vector "x, y, z", a short list, or for longer arrays their count and range."""
    values = np.asarray(values)
    if values.ndim == 0:
        return number(values, digits)
    flat = values.ravel()
    if flat.size <= 4:
        return ", ".join(number(v, digits) for v in flat)
    finite = flat[np.isfinite(flat)]
    if not finite.size:
        return f"{flat.size} values, none finite"
    return f"{flat.size} values in [{number(finite.min(), digits)}, {number(finite.max(), digits)}]"


def unit_text(unit: u.UnitBase) -> str:
    """The unit as people write it ("km / s", "deg", "10^6 km" for a scaled axis unit, "" for a pure number)."""
    if unit == u.one:
        return ""
    if unit in _NAMED:
        return _NAMED[unit]
    if isinstance(unit, u.CompositeUnit) and unit.scale != 1 and len(unit.bases) == 1 and unit.powers == [1]:
        return f"10^{round(math.log10(unit.scale))} {unit.bases[0].to_string()}"
    return unit.to_string()


def shown(q: u.Quantity, name: str = "", system: str = "natural", overrides: Mapping[str, Any] | None = None,
          digits: int = DIGITS) -> tuple[str, str]:
    """(value text, unit text) of a quantity as a table shows it."""
    unit = unit_for(q, name, system, overrides)
    return values_text(q.to_value(unit), digits), unit_text(unit)


def quantity_text(q: u.Quantity, name: str = "", digits: int = DIGITS) -> str:
    """E.g. "92.55760 min": the value in its natural unit, for reprs and captions."""
    value, unit = shown(q, name, digits=digits)
    return f"{value} {unit}".strip()


def axis_unit(q: u.Quantity) -> u.UnitBase:
    """The unit of a plot axis spanning q: the natural unit of its largest magnitude, counted in 10^3 or 10^6 of it
    where the ticks would otherwise carry six digits or more (a 5e6 km picture reads "x [10^6 km]", not an offset
    "1e6" in the corner)."""
    unit = natural_unit(q)
    size = _size(q, unit) if unit != u.one else 0.0
    if unit.is_equivalent(u.m) and size >= 1e5:
        power = 3 * min(int(math.log10(size)) // 3, 2)
        return u.CompositeUnit(10.0**power, [unit], [1])
    return unit


# ---- the same, typeset for pictures (matplotlib's mathtext, no LaTeX) ----------------------------------------

#: the astronomers' mass units, with their symbols
_MATH_NAMES = {"M_sun": r"M$_\odot$", "M_jup": r"M$_J$", "M_earth": r"M$_\oplus$"}


def number_math(x: float, digits: int = DIGITS) -> str:
    """`number(x, digits)` with its power of ten typeset: "1.287$\\times10^{6}$", "$10^{-8}$", "0.74"; a number
    below a million is written out, rounded to `digits` ("26600", not "2.66e4")."""
    x = float(x)
    if math.isfinite(x) and 10.0**digits <= abs(x) < 1e6:
        x = round(x, digits - 1 - math.floor(math.log10(abs(x))))
        if abs(x) < 1e6:
            return number(x, 6)
    text = number(x, digits)
    if "e" not in text:
        return text
    mantissa, exponent = text.split("e")
    power = f"10^{{{int(exponent)}}}"
    if mantissa in ("1", "-1"):
        return f"${mantissa[:-1]}{power}$"
    return f"{mantissa}$\\times{power}$"


def unit_math(unit: u.UnitBase) -> str:
    """`unit_text(unit)` typeset: powers raised ("km$^{2}$/s$^{2}$", "$10^{3}$ km"), M_sun as M$_\\odot$."""
    import re

    text = unit_text(unit)
    text = re.sub(r"^10\^(-?\d+)", r"$10^{\1}$", text)
    text = re.sub(r"(?<=[A-Za-z)])(-?\d+)\b", r"$^{\1}$", text)
    for name, math_name in _MATH_NAMES.items():
        text = text.replace(name, math_name)
    return text.replace(" / ", "/")


def quantity_math(q: u.Quantity, name: str = "", digits: int = DIGITS, unit: u.UnitBase | None = None) -> str:
    """A scalar quantity typeset for a picture, in its natural unit (or `unit`): "1.287$\\times10^{6}$ km"."""
    unit = natural_unit(q, name) if unit is None else unit
    return f"{number_math(float(q.to_value(unit)), digits)} {unit_math(unit)}".strip()


def quantities_html(title: str, quantities: Mapping[str, u.Quantity], digits: int = DIGITS) -> str:
    """An HTML table: one row per quantity, its value in natural units, and the unit."""
    rows = []
    for name, q in quantities.items():
        value, unit = shown(q, name, digits=digits)
        rows.append(f"<tr><td style='text-align:left'>{html.escape(name)}</td><td style='text-align:right'>"
                    f"{html.escape(value)}</td><td style='text-align:left'>{html.escape(unit)}</td></tr>")
    return (f"<table><caption style='text-align:left'><b>{html.escape(title)}</b></caption>"
            f"<tr><th>quantity</th><th>value</th><th>unit</th></tr>{''.join(rows)}</table>")


def validation_html(report: Any) -> str:
    """An HTML table per scene of a ValidationReport: verdict, check, analytic value, each backend's error."""
    parts = []
    for scene in report.scenes:
        names = list(scene.versions)
        head = "".join(f"<th>{html.escape(n)} error</th>" for n in names)
        rows = ""
        for check in scene.checks:
            errors = "".join(f"<td>{number(check.errors[n], 3)}</td>" for n in names)
            analytic = "-" if check.analytic is None else number(check.analytic, DIGITS)
            verdict = "pass" if check.passed else "<b style='color:red'>FAIL</b>"
            rows += (f"<tr><td>{verdict}</td><td style='text-align:left'>{html.escape(check.quantity)}</td>"
                     f"<td>{analytic}</td>{errors}<td>{number(check.tolerance, 2)}</td></tr>")
        times = ", ".join(f"{k} {v * 1e3:.1f} ms" for k, v in scene.wall_times.items())
        verdict = "passed" if scene.passed else "FAILED"
        parts.append(f"<table><caption style='text-align:left'><b>{html.escape(scene.name)}: {verdict}</b>. "
                     f"{html.escape(scene.description)}<br>wall time: {times}</caption>"
                     f"<tr><th></th><th>check</th><th>analytic</th>{head}<th>tolerance</th></tr>{rows}</table>")
    verdict = "all checks passed" if report.passed else "some checks FAILED"
    return "".join(parts) + f"<p><b>{verdict}</b> ({len(report.scenes)} scenes)</p>"


def one_line(kind: str, *parts: str) -> str:
    """The one-line repr of a public object: "Kind(part, part, ...)"."""
    return f"{kind}({', '.join(p for p in parts if p)})"


def summary(q: u.Quantity, name: str = "", digits: int = 7, unit: u.UnitBase | None = None) -> str:
    """A quantity in its natural unit (or `unit`) for a repr: "92.5576 min", or for an array "6778..42164 km"."""
    unit = natural_unit(q, name) if unit is None else unit
    values = np.asarray(q.to_value(unit), dtype=float)
    text = unit_text(unit)
    if values.size == 1:
        return f"{number(values.ravel()[0], digits)} {text}".strip()
    finite = values[np.isfinite(values)]
    low, high = (finite.min(), finite.max()) if finite.size else (np.nan, np.nan)
    span = number(low, digits) if number(low, digits) == number(high, digits) else (
        f"{number(low, digits)}..{number(high, digits)}")
    return f"{span} {text}".strip()


def body_name(gm: Any) -> str:
    """The catalogue body whose GM this is exactly (every element the same), else "GM = ... km3 / s2"."""
    from orbits.constants import body_with_gm

    known = body_with_gm(gm)
    if known is not None:
        return known.name
    return "GM = " + summary(u.Quantity(np.unique(np.asarray(gm, dtype=float)), u.m**3 / u.s**2))


class Displayed:
    """Mixin for the public objects: in a notebook, an HTML table of `quantities()` under the one-line repr."""

    def _repr_html_(self) -> str:
        return quantities_html(repr(self), self._display_quantities())

    def _display_quantities(self) -> dict:
        return self.quantities()
