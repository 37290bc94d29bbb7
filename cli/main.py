"""The `orbits` command line: a thin layer that parses, calls one public function and renders.

Heavy modules (astropy, the backends) are imported inside the commands so `orbits --help` stays fast.
"""

import functools
import sys
from enum import Enum
from typing import Annotated

import typer

app = typer.Typer(
    help="orbits: Kepler orbits to the last float64 digit, cross-checked against rebound and heyoka.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
)
bench_app = typer.Typer(help="Benchmarks: throughput and accuracy against the peers installed.", no_args_is_help=True)
app.add_typer(bench_app, name="bench")


class Format(str, Enum):
    table = "table"
    json = "json"


FormatOption = Annotated[Format, typer.Option("--format", help="table or json ({name: {value, unit}})")]
OnlyOption = Annotated[str | None, typer.Option("--only", help="comma-separated quantity names, e.g. period,semi_major_axis")]


def reports_errors(command):
    """Turn the library's input errors into one line on stderr and exit status 2."""

    @functools.wraps(command)
    def wrapper(*args, **kwargs):
        import astropy.units as u

        from orbits.errors import OrbitsError

        try:
            return command(*args, **kwargs)
        except (OrbitsError, ValueError, TypeError, KeyError, u.UnitsError, typer.BadParameter) as err:
            message = err.format_message() if isinstance(err, typer.BadParameter) else str(err).strip("'\"")
            print(f"orbits: error: {message}", file=sys.stderr)
            raise typer.Exit(2) from None

    return wrapper


@app.command()
@reports_errors
def orbit(
    body_name: Annotated[str | None, typer.Argument(metavar="[BODY]", help="a named body (Earth, Moon, Jupiter): its mean orbit")] = None,
    primary: Annotated[str, typer.Option(help="central body: name, mass ('5.97e24 kg') or GM ('3.986e14 m3/s2')")] = "Sun",
    a: Annotated[str | None, typer.Option("--a", help="semi-major axis, e.g. '1 AU' (negative for hyperbolas)")] = None,
    p: Annotated[str | None, typer.Option("--p", help="semi-latus rectum")] = None,
    q: Annotated[str | None, typer.Option("--q", help="periapsis distance (use for e = 1)")] = None,
    e: Annotated[float, typer.Option("--e", help="eccentricity")] = 0.0,
    inc: Annotated[str, typer.Option("--inc", help="inclination ('28.5 deg'; bare numbers are degrees)")] = "0",
    raan: Annotated[str, typer.Option("--raan", help="longitude of the ascending node")] = "0",
    argp: Annotated[str, typer.Option("--argp", help="argument of periapsis")] = "0",
    nu: Annotated[str, typer.Option("--nu", help="true anomaly")] = "0",
    r: Annotated[str | None, typer.Option("--r", help="position vector 'X,Y,Z UNIT' (with --v instead of elements)")] = None,
    v: Annotated[str | None, typer.Option("--v", help="velocity vector 'X,Y,Z UNIT'")] = None,
    mass: Annotated[str | None, typer.Option(help="orbiting body's mass, for U, K, E, L")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
):
    """Every section XXI quantity of an orbit, from elements, a state vector, or a named body."""
    from orbits_cli import params, render
    from orbits_cli.commands import orbit as command

    result, title = command.build(body_name, primary, a, p, q, e, inc, raan, argp, nu, r, v, mass)
    render.emit(title, result.quantities(params.names(only)), fmt.value)


@app.command()
@reports_errors
def kepler(
    e: Annotated[float, typer.Option("--e", help="eccentricity (any conic)")],
    mean: Annotated[str | None, typer.Option("--M", help="mean anomaly (Barker's W when e = 1), e.g. '1.2 rad'")] = None,
    true: Annotated[str | None, typer.Option("--nu", help="true anomaly, e.g. '120 deg'")] = None,
    fmt: FormatOption = Format.table,
):
    """Anomaly conversions: from the mean anomaly (--M) or the true anomaly (--nu) to all the others."""
    from orbits_cli import render
    from orbits_cli.commands import kepler as command

    render.emit(f"Kepler's equation, e = {e}", command.anomalies_from(e, mean, true), fmt.value)


@app.command()
@reports_errors
def info(fmt: FormatOption = Format.table):
    """Versions of orbits and its dependencies, cache locations, and the constants' sources."""
    from orbits_cli.commands import info as command

    command.show(fmt.value)


@bench_app.command("kepler")
@reports_errors
def bench_kepler(
    easy: Annotated[int, typer.Option(help="easy pairs, e in [0, 0.99]")] = 1_000_000,
    hard: Annotated[int, typer.Option(help="hard pairs, e in [0.99, 1 - 1e-9], M tiny or near pi")] = 100_000,
    hyperbolic: Annotated[int, typer.Option(help="hyperbolic pairs")] = 100_000,
    reference: Annotated[int, typer.Option(help="pairs per set checked against mpmath")] = 2000,
    repeats: Annotated[int, typer.Option(help="timing repeats (best is kept)")] = 3,
    output: Annotated[str | None, typer.Option(help="also write the rows as JSON to this file (atomically)")] = None,
    fmt: FormatOption = Format.table,
):
    """Kepler solvers: throughput and worst error of orbits and its peers, measured in one run."""
    import json

    from orbits.bench import bench_kepler as run, format_rows, rows_to_json
    from orbits.io import write_atomic

    rows = run(n_easy=easy, n_hard=hard, n_hyp=hyperbolic, n_ref=reference, repeats=repeats)
    text = json.dumps(rows_to_json(rows), indent=2)
    print(text if fmt == Format.json else format_rows(rows))
    if output:
        write_atomic(output, text + "\n")
