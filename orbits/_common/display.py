"""Display units and digits, decided in one place: the command-line tables, the HTML and one-line reprs, and the
axes of the plots all ask this module how to show a quantity.

A quantity is shown in the natural unit for its kind and size, the largest finite magnitude choosing the rung:

    length    m below 1 km, km below 1e7 km (and for 0), AU below 1e5 AU, pc below 1e5 pc, Mpc beyond
    time      s below 2 min, min below 2 h, h below 2 d, d below 1000 d, yr below 1e6 yr, Myr below 1e9 yr, Gyr
              beyond
    angle     deg; an angular rate in deg per the natural time unit of 1 rad / rate (deg / d for a planet), an
              angular frequency (a name with "frequency") in rad / s
    speed     km/s from 1 km/s, m/s below (a projectile, a radial-velocity curve); GM in km3 / s2; specific
              energy in km2 / s2; h and dA/dt in km2 / s
    rate      km / s / Mpc for a Hubble parameter; otherwise 1 / (the natural time unit of 1 / rate)
    mass      kg below 1e20 kg, Earth masses below 0.1 M_jup, Jupiter masses below 0.05 M_sun, solar masses beyond
    area      m2 below 1 km2, km2 below 1 AU2, AU2 beyond (the area an orbit sweeps)
    volume    m3 below 1e9 m3, km3 below (1e5 pc)**3, Mpc3 below (1 Gpc)**3, Gpc3 beyond

with DIGITS significant digits, in plain decimals from 1e-3 up to 10**DIGITS (10**4 at least: 7700 km shows as
7700 with 3 digits) and as "1.538875e7" or "4.739143e-4" beyond. `system="si"`
shows SI units instead, and `overrides` fixes the unit of a named quantity. A quantity that is exactly zero takes
the unit its table gives a quantity of its kind (`table_units`). Right ascension and declination read as
astronomers write them, 10h08m30.34s and +13d45m32.8s. Units are written the astronomers' way: "km / s / Mpc",
"kg m2 / s", in headers without spaces ("km/s/Mpc"). JSON is not display: it carries the exact float64 value in
SI (orbits_cli.render). Numbers never show as -0; non-finite values show as inf, -inf and nan.
"""

import html
import math
import textwrap
import unicodedata
from collections.abc import Mapping
from typing import Any

import astropy.units as u
import numpy as np

#: significant digits shown by default
DIGITS = 7
SYSTEMS = ("natural", "si")

_LENGTHS = [(1e3, u.m), (1e10, u.km), (1e5 * u.AU.to(u.m), u.AU), (1e5 * u.pc.to(u.m), u.pc), (math.inf, u.Mpc)]
_TIMES = [(120.0, u.s), (7200.0, u.min), (172800.0, u.h), (1000 * 86400.0, u.day), (1e6 * u.yr.to(u.s), u.yr),
          (1e9 * u.yr.to(u.s), u.Myr), (math.inf, u.Gyr)]
_HUBBLE = u.km / u.s / u.Mpc
#: units shown by their astronomers' names rather than astropy's (solMass)
_NAMED = {u.M_sun: "M_sun", u.M_jup: "M_jup", u.M_earth: "M_earth"}
_MASSES = [(1e20, u.kg), (0.1 * u.M_jup.to(u.kg), u.M_earth), (0.05 * u.M_sun.to(u.kg), u.M_jup), (math.inf, u.M_sun)]
_AREAS = [(1e6, u.m**2), (u.AU.to(u.m) ** 2, u.km**2), (math.inf, u.AU**2)]
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
        if "frequency" in name:  # an oscillator's angular frequency omega, which physics writes in rad / s
            return u.rad / u.s
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
    if unit.is_equivalent(u.m**2):
        return _rung(_size(q, u.m**2), _AREAS)
    if unit.is_equivalent(u.m**3):
        return _rung(_size(q, u.m**3), _VOLUMES)
    for si, natural in _FIXED:
        if unit.is_equivalent(si):
            return natural
    return unit


def si_unit(q: u.Quantity) -> u.UnitBase:
    """The SI unit of q (angles in rad, magnitudes in mag): what JSON carries and `system="si"` shows."""
    if q.unit.is_equivalent(u.one):
        return u.one
    if q.unit.is_equivalent(u.rad):
        return u.rad
    try:
        return q.unit.si
    except u.UnitConversionError:  # a magnitude is its own unit
        return q.unit


def unit_for(q: u.Quantity, name: str = "", system: str = "natural", overrides: Mapping[str, Any] | None = None):
    """The unit to show the quantity `name` in: its override, else SI or the natural unit."""
    if overrides and name in overrides:
        unit = u.Unit(overrides[name])
        if not (math.isfinite(unit.scale) and unit.scale > 0):
            raise ValueError(f"--unit {name}={overrides[name]}: a unit's scale must be a positive, finite number; "
                             f"got {number(unit.scale)}")
        if not q.unit.is_equivalent(unit):
            raise u.UnitConversionError(f"--unit {name}={overrides[name]}: {name} is in {q.unit}, not {unit}")
        return unit
    return si_unit(q) if system == "si" else natural_unit(q, name)


#: Unicode categories that a terminal would act on or hide: controls (ESC, CR, BEL ...), format characters (the
#: bidirectional overrides, zero-width joiners) and line and paragraph separators
_UNPRINTABLE = ("Cc", "Cf", "Zl", "Zp")


def printable(text: str) -> str:
    """`text` as it may reach a terminal: every control, format or separator character written as its Python
    escape ("\\x1b", "\\u202e", "\\n"), so that text read from a file (a scene's name or description) can
    neither move the cursor nor break a one-line message."""
    return "".join(ch.encode("unicode_escape").decode("ascii") if unicodedata.category(ch) in _UNPRINTABLE else ch
                   for ch in str(text))


def visible(text: str) -> bool:
    """Whether `text` has a character that shows: not only spaces, controls or invisible format characters."""
    return any(not ch.isspace() and unicodedata.category(ch) not in _UNPRINTABLE for ch in text)


def number(x: float, digits: int = DIGITS) -> str:
    """x with `digits` significant digits; never -0; inf, -inf and nan spelled out."""
    x = float(x)
    if not math.isfinite(x):
        return "nan" if math.isnan(x) else ("inf" if x > 0 else "-inf")
    if x == 0:
        return "0"
    if 1e-3 <= abs(x) < 10.0 ** max(digits, 4):
        places = digits - 1 - math.floor(math.log10(abs(x)))
        text = f"{round(x, places):.{max(places, 0)}f}"
        if abs(float(text)) >= 10.0 ** max(digits, 4):  # rounded up into the next decade
            return number(float(text), digits)
        return _trimmed(text)
    mantissa, exponent = f"{x:.{digits - 1}e}".split("e")
    return f"{_trimmed(mantissa)}e{int(exponent)}"


def _trimmed(text: str) -> str:
    """A decimal without trailing zeros after its point (and without the point if nothing follows it); "-0" as
    "0"."""
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def wrapped(text: str, width: int, initial_indent: str = "", subsequent_indent: str = "") -> list[str]:
    """`text` in lines of at most `width` columns, broken between words only: never inside a word, a hyphenated
    name ("skyfield-data") or a unit; a word longer than the line (a path) stands on a line of its own."""
    return textwrap.wrap(text, width, initial_indent=initial_indent, subsequent_indent=subsequent_indent,
                         break_long_words=False, break_on_hyphens=False)


def filled(text: str, width: int, initial_indent: str = "", subsequent_indent: str = "") -> str:
    """`wrapped` joined into one string of lines."""
    return "\n".join(wrapped(text, width, initial_indent, subsequent_indent))


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


def unit_text(unit: u.UnitBase, compact: bool = False) -> str:
    """The unit as astronomers write it ("km / s", "km / s / Mpc", "kg m2 / s", "deg", "" for a pure number);
    `compact` without spaces around the slashes ("km/s/Mpc", for a column header that must not break inside it). A
    scaled unit reads by its scale: "10^6 km" when the scale is exactly a power of ten (a scaled axis unit), else
    the scale itself ("2 s", "3 d"), so that the label always says what the shown numbers count."""
    if unit == u.one:
        return ""
    if unit in _NAMED:
        return _NAMED[unit]
    if isinstance(unit, u.CompositeUnit) and unit.scale != 1 and len(unit.bases) == 1 and unit.powers == [1]:
        return f"{_scale_text(unit.scale)} {unit.bases[0].to_string()}"
    if isinstance(unit, u.CompositeUnit) and unit.scale == 1 and len(unit.bases) > 1:
        return _composed(unit, "/" if compact else " / ")
    return unit.to_string()


#: the order of factors in a written unit: masses first in a numerator, times first in a denominator
_ORDER = {"kg": 0, "g": 0, "solMass": 0, "jupiterMass": 0, "earthMass": 0, "s": 1, "min": 1, "h": 1, "d": 1,
          "yr": 1, "Myr": 1, "Gyr": 1}


def _composed(unit: u.CompositeUnit, slash: str) -> str:
    """Numerator factors (masses first) then each denominator factor after its own slash (times first):
    km / s / Mpc, kg m2 / s, km3 / s2."""
    def factor(base, power):
        return base.to_string() + (str(abs(power)) if abs(power) != 1 else "")

    def key(pair):
        return (_ORDER.get(pair[0].to_string(), 2), pair[0].to_string())

    pairs = list(zip(unit.bases, unit.powers))
    top = [factor(b, p) for b, p in sorted((q for q in pairs if q[1] > 0), key=key)]
    bottom = [factor(b, p) for b, p in sorted((q for q in pairs if q[1] < 0), key=key)]
    joint = "\u00a0" if slash == "/" else " "  # compact: no break inside the numerator either
    return slash.join([joint.join(top) if top else "1", *bottom])


def _scale_text(scale: float) -> str:
    """A unit's scale: "10^k" when it is exactly the float nearest 10**k, else its digits ("2", "0.25")."""
    if math.isfinite(scale) and scale > 0:
        power = round(math.log10(scale))
        if float(f"1e{power}") == scale:
            return f"10^{power}"
    return number(scale, 17)


def shown(q: u.Quantity, name: str = "", system: str = "natural", overrides: Mapping[str, Any] | None = None,
          digits: int = DIGITS, unit: u.UnitBase | None = None) -> tuple[str, str]:
    """(value text, unit text) of a quantity as a table shows it (in `unit` when the table has chosen it)."""
    unit = unit_for(q, name, system, overrides) if unit is None else unit
    asked = bool(overrides) and name in overrides  # a unit the reader named is shown as asked, never re-spelt
    if name in _SEXAGESIMAL and unit == u.deg and np.size(q) <= 4 and not asked:
        texts = [_sexagesimal(float(v), *_SEXAGESIMAL[name]) for v in np.ravel(q.to_value(u.deg))]
        return ", ".join(texts), ""
    return values_text(in_unit(q, unit, name), digits), unit_text(unit)


def in_unit(q: u.Quantity, unit: u.UnitBase, name: str = "") -> np.ndarray:
    """The values of q in `unit` (float64) for display, refused (ValueError naming the quantity and the unit) where
    a finite value other than zero would leave float64's normal range there: inf (365.25 d in 1e-320 s is
    3.2e327) or a subnormal or zero (1e-300 s in 1e10 s), whose digits are lost."""
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        values = np.asarray(q.to_value(unit), dtype=float)
    given = np.asarray(q.value, dtype=float)
    lost = (np.isfinite(given) & (given != 0)) & ~(np.isfinite(values) & (np.abs(values) >= np.finfo(float).tiny))
    if np.any(lost):
        first = np.flatnonzero(np.ravel(lost))[0]
        value = np.ravel(given)[first] << q.unit
        label = f"{name} = " if name else ""
        raise ValueError(f"{label}{quantity_text(value, name)} cannot be shown in {unit_text(unit) or unit}: it would "
                         f"be {number(np.ravel(values)[first])}, outside float64's range; choose a unit nearer its "
                         f"size")
    return values


#: angles astronomers write in hours or degrees, minutes and seconds: name -> (in hours, decimals of the seconds)
_SEXAGESIMAL = {"right_ascension": (True, 2), "declination": (False, 1)}


def _sexagesimal(degrees: float, hours: bool, decimals: int) -> str:
    """10h08m30.34s for a right ascension (hours), +13d45m32.8s for a declination; the seconds rounded first, so
    that 59.996 s carries into the minutes."""
    if not math.isfinite(degrees):
        return number(degrees)
    value = abs(degrees) / 15.0 if hours else abs(degrees)
    scale = 10**decimals
    total = round(value * 3600.0 * scale)  # in units of the last shown decimal of a second
    whole, fraction = divmod(total, 3600 * scale)
    whole = whole % 24 if hours else whole  # 23h59m59.999s rounds to 00h, not 24h
    minutes, seconds = divmod(fraction, 60 * scale)
    sign = "" if hours else ("-" if degrees < 0 and total else "+")
    mark = "h" if hours else "d"
    return f"{sign}{whole:02d}{mark}{minutes:02d}m{seconds / scale:0{3 + decimals}.{decimals}f}s"


#: the unit of a quantity that is exactly zero when no other quantity of its kind in its table says otherwise
_ZERO_UNITS = [(u.m**3, u.Gpc**3)]


def table_units(quantities: Mapping[str, u.Quantity], system: str = "natural",
                overrides: Mapping[str, Any] | None = None) -> dict[str, u.UnitBase]:
    """The unit each quantity of one table is shown in (unit_for), except that a quantity which is exactly zero
    takes the unit of the first quantity of its kind in the table that is not (a lookback time of 0 in the Gyr of
    the age beside it, a distance of 0 in Mpc), else its kind's unit for zero."""
    units = {name: unit_for(q, name, system, overrides) for name, q in quantities.items()}
    if system != "natural":
        return units
    nonzero = {name: q for name, q in quantities.items() if _size(q, q.unit) > 0 or not np.size(q)}
    for name, q in quantities.items():
        if name in nonzero or (overrides and name in overrides) or q.unit.is_equivalent(u.one):
            continue
        kin = next((units[other] for other, o in nonzero.items() if o.unit.is_equivalent(q.unit)
                    and not o.unit.is_equivalent(u.one)), None)
        if kin is None:
            kin = next((zero for kind, zero in _ZERO_UNITS if q.unit.is_equivalent(kind)), units[name])
        units[name] = kin
    return units


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


#: the units a body's mass is named in, each from the smallest mass it reads well for (kg)
_MASS_UNITS = ((u.M_sun, 0.08 * u.M_sun.to(u.kg)), (u.M_jup, 0.1 * u.M_jup.to(u.kg)),
               (u.M_earth, 1e-3 * u.M_earth.to(u.kg)))


def body_name(gm: Any) -> str:
    """The catalogue body whose GM this is exactly (every element the same), "Jupiter + Io" for the two GMs of a
    catalogue pair, else the mass GM / G in the unit an astronomer would name it in: "0.1 M_sun", "3 M_jup",
    "0.5 M_earth" (kg below a thousandth of the Earth's)."""
    from orbits._common.constants import G, body_with_gm, pair_with_gm

    known = body_with_gm(gm)
    if known is not None:
        return known.name
    pair = pair_with_gm(gm)
    if pair is not None:
        return f"{pair[0].name} + {pair[1].name}"
    mass = np.unique(np.asarray(gm, dtype=float)) / G
    largest = float(np.max(np.abs(mass)))
    unit = next((unit for unit, least in _MASS_UNITS if largest >= least), u.kg)
    return summary(mass * u.kg, unit=unit).replace("solMass", "M_sun").replace("jupiterMass", "M_jup").replace(
        "earthMass", "M_earth")


class Displayed:
    """Mixin for the public objects: in a notebook, an HTML table of `quantities()` under the one-line repr."""

    def _repr_html_(self) -> str:
        return quantities_html(repr(self), self._display_quantities())

    def _display_quantities(self) -> dict:
        return self.quantities()
