"""The `orbits` command line: a thin layer that parses, calls one public function and renders.

Each verb lives in orbits_cli/commands/<verb>.py, which imports only typer at module level: the library,
astropy and the backends are imported inside the commands, so `orbits --help` stays fast.
"""

import typer

from orbits_cli.commands import (
    bench,
    binary,
    cosmology,
    escape,
    flyby,
    info,
    kepler,
    lagrange,
    orbit,
    precision,
    ring,
    validate,
)
from orbits_cli.options import reports_errors

app = typer.Typer(
    help="orbits: Kepler orbits to the last float64 digit, cross-checked against rebound and heyoka.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
)
bench_app = typer.Typer(help="Benchmarks: throughput and accuracy against the peers installed.", no_args_is_help=True)
app.add_typer(bench_app, name="bench")

app.command("validate")(reports_errors(validate.command))
app.command("orbit")(reports_errors(orbit.command))
app.command("kepler")(reports_errors(kepler.command))
app.command("cosmology")(reports_errors(cosmology.command))
app.command("binary")(reports_errors(binary.command))
app.command("flyby")(reports_errors(flyby.command))
app.command("lagrange")(reports_errors(lagrange.command))
app.command("ring")(reports_errors(ring.command))
app.add_typer(escape.app, name="escape")
app.command("info")(reports_errors(info.command))
bench_app.command("kepler")(reports_errors(bench.kepler))
bench_app.command("propagate")(reports_errors(bench.propagate))
bench_app.command("api")(reports_errors(bench.api))
bench_app.command("cli")(reports_errors(bench.cli))
bench_app.command("validate")(reports_errors(bench.validate))
bench_app.command("all")(reports_errors(bench.all_))
bench_app.command("precision")(reports_errors(precision.command))
