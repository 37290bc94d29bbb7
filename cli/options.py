"""Options, helpers and error handling shared by every command (imports typer only, for a fast --help): no verb
imports another; what two verbs share lives here."""

import functools
import inspect
import sys
from collections.abc import Callable
from enum import StrEnum
from typing import TYPE_CHECKING, Annotated, ParamSpec, TypeVar

import typer

if TYPE_CHECKING:
    from astropy.units import Quantity
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from orbits._common.constants import Body
    from orbits.threebody.lagrange import RestrictedThreeBody

_P = ParamSpec("_P")
_R = TypeVar("_R")


class Format(StrEnum):
    table = "table"
    json = "json"


FormatOption = Annotated[Format, typer.Option("--format", help="table or json ({name: {value, unit}})")]
OnlyOption = Annotated[
    str | None, typer.Option("--only", help="comma-separated names of the quantities to show, as the table or JSON "
                             "names them (an unknown name lists the known ones)")
]


# The orientation of a conic, shared by every verb that takes elements (bare angle numbers are degrees).
EccentricityOption = Annotated[float, typer.Option("--e", help="eccentricity")]
InclinationOption = Annotated[str, typer.Option("--inc", help="inclination ('28.5 deg'; bare numbers are degrees)")]
NodeOption = Annotated[str, typer.Option("--raan", help="longitude of the ascending node")]
PeriapsisArgumentOption = Annotated[
    str, typer.Option("--argp", help="argument of periapsis (for a binary: of star 2 relative to star 1)")
]
TrueAnomalyOption = Annotated[str, typer.Option("--nu", help="true anomaly")]

#: what a body option reads
MASS_HELP = "a body name (Earth, Moon, Sun, Jupiter), a mass ('1.989e30 kg', '1 solMass') or a GM ('3.986e14 m3/s2')"


def mass_or_body(text: str, option: str) -> "Body | Quantity":
    """A body (name), mass or GM parsed from `text`; an error naming `option` otherwise."""
    from orbits import OrbitDomainError
    from orbits._common import inputs

    try:
        return inputs.parse_primary(text)
    except OrbitDomainError as err:
        raise OrbitDomainError(f"{option}: {str(err).removeprefix('primary: ')}") from None


def three_body(primary: str, secondary: str, separation: str | None) -> "RestrictedThreeBody":
    """The RestrictedThreeBody of --primary and --secondary at --separation (None: the secondary's catalogued mean
    distance from the primary)."""
    from orbits import RestrictedThreeBody
    from orbits._common import inputs

    distance = None if separation is None else inputs.parse_quantity(separation, "length", "--separation")
    return RestrictedThreeBody.from_primaries(mass_or_body(primary, "--primary"),
                                              mass_or_body(secondary, "--secondary"), distance)


def _writable(option: str):
    """A parse-time check that a file option can be written, so that a bad target fails before any work."""

    def check(path: str | None) -> str | None:
        if path is not None:
            from orbits import OrbitDomainError
            from orbits._common.io import check_target

            if option == "--plot" and str(path).rsplit(".", 1)[-1].lower() not in ("png", "svg", "pdf"):
                raise typer.BadParameter(f"plot file {path!r} must end in .png, .svg or .pdf")
            try:
                check_target(path, option)
            except OrbitDomainError as err:
                raise typer.BadParameter(str(err).removeprefix(f"{option}: ")) from None
        return path

    return check


PlotOption = Annotated[str | None, typer.Option(
    "--plot", callback=_writable("--plot"), help="also draw a picture to this .png, .svg or .pdf file (atomically)")]
OutputOption = Annotated[str | None, typer.Option(
    "--output", callback=_writable("--output"), help="also write the JSON to this file (atomically)")]

EpochOption = Annotated[str | None, typer.Option(
    "--epoch", help="date: ISO ('2026-11-25', '2026-11-25T06:00') read as UTC, or with a scale ('... TDB', "
    "'... TT'), or J2000")]


class Ephemeris(StrEnum):
    auto = "auto"
    de421 = "de421"
    builtin = "builtin"


EphemerisOption = Annotated[Ephemeris, typer.Option(
    "--ephemeris", help="auto: JPL DE421 when orbits\\[ephemeris] is installed, else astropy's built-in")]


def save_plot(draw: "Callable[[], tuple[Figure, Axes]]", path: str) -> None:
    """Draw with `draw()` -> (fig, ax) on a non-interactive backend and save to `path` atomically."""
    try:
        import matplotlib
    except ImportError:
        raise typer.BadParameter("--plot needs matplotlib: pip install 'orbits[plot]'") from None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from orbits.plot import save

    fig, _ = draw()
    try:
        save(fig, path)
    finally:
        plt.close(fig)  # a command draws once; the figure is not kept


class Units(StrEnum):
    natural = "natural"
    si = "si"


_DISPLAY_PARAMETERS = [
    inspect.Parameter("units", inspect.Parameter.KEYWORD_ONLY, default=Units.natural, annotation=Annotated[
        Units, typer.Option("--units", help="natural (km, AU, min, d, yr, deg, km/s ...) or si")]),
    inspect.Parameter("unit", inspect.Parameter.KEYWORD_ONLY, default=None, annotation=Annotated[
        list[str] | None, typer.Option("--unit", help="show one quantity in a unit: NAME=UNIT, e.g. period=d "
                                                      "(repeatable)")]),
    inspect.Parameter("digits", inspect.Parameter.KEYWORD_ONLY, default=7, annotation=Annotated[
        int, typer.Option("--digits", min=1, max=17, help="significant digits in tables (JSON is always exact)")]),
]


def displays(command: Callable[_P, _R]) -> Callable[..., _R]:
    """Give a command the display options --units, --unit NAME=UNIT and --digits N, which set how
    orbits_cli.render shows its tables (JSON is always exact SI)."""

    @functools.wraps(command)
    def wrapper(*args, units=Units.natural, unit=None, digits=7, **kwargs):
        from orbits_cli import render

        if kwargs.get("fmt") == Format.json:  # the JSON is exact SI: a display option would be ignored
            given = [text for text, on in (("--unit", unit), ("--units si", units != Units.natural),
                                           (f"--digits {digits}", digits != 7)) if on]
            if given:
                raise typer.BadParameter(f"{', '.join(given)}: how a table shows its numbers, and --format json "
                                         f"gives every value exact, in SI: drop one of them")
        overrides = {}
        for item in unit or []:
            name, sep, value = item.partition("=")
            if not sep or not name.strip() or not value.strip():
                raise typer.BadParameter(f"--unit {item!r}: write NAME=UNIT, e.g. period=d")
            if name.strip() in overrides:
                raise typer.BadParameter(f"--unit {name.strip()} is given twice ({overrides[name.strip()]}, "
                                         f"{value.strip()}); give each quantity one unit")
            overrides[name.strip()] = value.strip()
        render.use(render.Display(units.value, overrides, digits))
        return command(*args, **kwargs)

    signature = inspect.signature(command)
    wrapper.__signature__ = signature.replace(parameters=[*signature.parameters.values(), *_DISPLAY_PARAMETERS])
    wrapper.__annotations__ = {**command.__annotations__, **{p.name: p.annotation for p in _DISPLAY_PARAMETERS}}
    return wrapper


def verb_words(group, args: list[str]) -> tuple[str, object, list[str]]:
    """(the verb's path such as "transfer hohmann", its click command, the words after it) of the words after
    `orbits`."""
    command, words, path = group, list(args), []
    while hasattr(command, "commands") and words and words[0] in command.commands:
        path.append(words[0])
        command, words = command.commands[words[0]], words[1:]
    return " ".join(path), command, words


def refuse_retired_words(group, args: list[str]) -> None:
    """A usage error naming the word now for a former spelling (orbits_cli.vocabulary.RETIRED), before any work."""
    from orbits_cli.vocabulary import retired_word

    verb, _, words = verb_words(group, args)
    hint = retired_word(verb, words)
    if hint is not None:
        raise typer.BadParameter(hint)


def refuse_repeated_options(group, args: list[str]) -> None:
    """A usage error for an option given more than once that holds one value (`--a 7000 km --a 8000 km`), or for a
    flag given both ways (`--sweep --no-sweep`): the parser would keep the last silently. Options that collect a
    list (`--unit`) may repeat. `args` are the words after `orbits`; the verb (and sub-verb) they name is found
    first."""
    _, command, words = verb_words(group, args)
    spellings = {}
    for param in getattr(command, "params", []):
        if getattr(param, "param_type_name", "") == "option":
            for spelling in [*param.opts, *param.secondary_opts]:
                spellings[spelling] = param
    seen: dict[str, list[str]] = {}
    words = iter(words[: words.index("--")] if "--" in words else words)
    for word in words:
        spelling, equals, value = word.partition("=")
        param = spellings.get(spelling)
        if param is None:
            continue
        if not param.is_flag and not equals:
            value = next(words, "")
        if param.multiple or param.count:
            continue
        seen.setdefault(param.name, []).append(spelling if param.is_flag else f"{spelling} {value!r}")
    for given in seen.values():
        if len(given) > 1:
            what = "a switch" if spellings[given[0].split(" ")[0]].is_flag else "an option that holds one value"
            raise typer.BadParameter(f"{', '.join(given)}: {what}, given {len(given)} times; give it once")


def _print_warnings(caught, ours):
    """orbits' own warnings as one line each on stderr ("orbits: warning: ..."), each message once; the others
    are given back to Python's warning machinery as they were."""
    import warnings

    seen = set()
    for item in caught:
        if issubclass(item.category, ours):
            if str(item.message) not in seen:
                from orbits._common.display import printable

                seen.add(str(item.message))
                print(f"orbits: warning: {printable(item.message)}", file=sys.stderr)
        else:
            warnings.warn_explicit(item.message, item.category, item.filename, item.lineno)


class _NotingInterrupts:
    """While active, a SIGINT is noted before Python's handler raises KeyboardInterrupt, so that an interrupt a
    library turned into another exception (an import cut short leaves a module half-loaded, and the next import
    fails with AttributeError) is still reported as an interrupt. Only in the main thread, where signals land."""

    def __init__(self) -> None:
        self.seen = False
        self.previous = None

    def __enter__(self) -> "_NotingInterrupts":
        import signal
        import threading

        if threading.current_thread() is threading.main_thread():
            self.previous = signal.getsignal(signal.SIGINT)
            signal.signal(signal.SIGINT, self._note)
        return self

    def _note(self, signum, frame) -> None:
        self.seen = True
        raise KeyboardInterrupt

    def __exit__(self, *exc) -> None:
        import signal

        if self.previous is not None:
            signal.signal(signal.SIGINT, self.previous)


def reports_errors(command: Callable[_P, _R]) -> Callable[_P, _R]:
    """Turn the library's input errors into one line on stderr and exit status 2, and Ctrl-C into "orbits:
    interrupted" and exit status 130 (whatever exception the interrupted code raised instead)."""

    @functools.wraps(command)
    def wrapper(*args, **kwargs):
        import warnings

        from orbits import OrbitsWarning

        said = []
        interrupts = _NotingInterrupts()
        try:
            try:
                with interrupts, warnings.catch_warnings(record=True) as said:
                    warnings.simplefilter("error", RuntimeWarning)  # a float64 overflow is an error, never a warning
                    warnings.simplefilter("always", OrbitsWarning)
                    return command(*args, **kwargs)
            finally:  # outside the recording: a warning passed on goes to the caller's filters, not back to `said`
                _print_warnings(said, OrbitsWarning)
        except KeyboardInterrupt:
            _report_interrupt()
        except Exception:
            if interrupts.seen:  # whatever the interrupted code raised instead of KeyboardInterrupt
                _report_interrupt()
            return _report_error()

    return wrapper


def error_text(err: Exception) -> str:
    """The message of a usage or input error without click's "Invalid value" wording: an option's problem as
    "--e: ...", every other as it reads. Every error line is then "orbits: error: " and this."""
    if isinstance(err, typer.BadParameter) and err.message:  # a missing option has no message of its own
        param = err.param
        hint = err.param_hint or (None if param is None else
                                  ("/".join(param.opts) if getattr(param, "opts", None) else param.human_readable_name))
        hint = " / ".join(hint) if isinstance(hint, list | tuple) else hint
        return err.message if hint is None else f"{str(hint).strip(chr(39))}: {err.message}"
    if hasattr(err, "format_message"):
        return err.format_message()
    return str(err.args[0]) if isinstance(err, KeyError) and err.args else str(err)


def _report_interrupt() -> None:
    print("orbits: interrupted", file=sys.stderr)
    raise typer.Exit(130) from None


def _report_error() -> None:
    """The exception being handled as one line on stderr and exit status 2, if it is an input or float64 error;
    anything else (a bug) is raised again."""
    import astropy.units as u

    from orbits import OrbitsError

    try:
        raise
    except RuntimeWarning as err:
        print(f"orbits: error: the computation left float64 ({err}); the inputs are outside what orbits can "
              f"compute", file=sys.stderr)
        raise typer.Exit(2) from None
    except (OrbitsError, ValueError, TypeError, KeyError, u.UnitsError, typer.BadParameter) as err:
        from orbits._common.display import printable

        print(f"orbits: error: {printable(error_text(err))}", file=sys.stderr)  # one line, whatever a file held
        raise typer.Exit(2) from None
