"""The `orbits` command line: a thin layer that parses, calls one public function and renders.

Each verb lives in orbits_cli/commands/<verb>.py, which imports only typer at module level: the library,
astropy and the backends are imported inside the commands, so `orbits --help` stays fast.
"""

import sys

import typer
from typer.core import TyperGroup

from orbits_cli.commands import (
    bench,
    binary,
    collide,
    cosmology,
    escape,
    flyby,
    info,
    kepler,
    lagrange,
    lambert,
    orbit,
    pendulum,
    periodic,
    perturb,
    porkchop,
    precision,
    projectile,
    ring,
    rocket,
    transfer,
    validate,
    where,
)
from orbits_cli.options import (
    displays,
    error_text,
    refuse_repeated_options,
    refuse_retired_words,
    reports_errors,
)
from orbits_cli.pages import SUBJECTS, document


class OneLineErrors(TyperGroup):
    """The root command: a usage error (unknown verb or option, a missing or malformed value) is one line on
    stderr, "orbits: error: ...", with exit status 2, like every other input error. Its help lists the verbs by
    subject."""

    def list_commands(self, ctx) -> list[str]:
        ordered = [verb for verbs in SUBJECTS.values() for verb in verbs]
        return ordered + [name for name in super().list_commands(ctx) if name not in ordered]

    def main(self, *args, standalone_mode: bool = True, **kwargs):
        if not standalone_mode:
            return super().main(*args, standalone_mode=False, **kwargs)
        try:
            words = args[0] if args else kwargs.get("args")
            words = list(sys.argv[1:] if words is None else words)
            refuse_retired_words(self, words)
            refuse_repeated_options(self, words)
            status = super().main(*args, standalone_mode=False, **kwargs)
        except typer.TyperException as err:  # click's exceptions (typer carries its own click)
            if type(err).__name__ == "NoArgsIsHelpError":  # bare `orbits` or `orbits bench`: the help
                print(err.ctx.get_help())
                sys.exit(0)
            message = " ".join(error_text(err).split())
            print(f"orbits: error: {message}", file=sys.stderr)
            sys.exit(err.exit_code)
        except typer.Abort:
            print("orbits: interrupted", file=sys.stderr)
            sys.exit(130)
        sys.exit(status if isinstance(status, int) else 0)


app = typer.Typer(
    cls=OneLineErrors,
    help="orbits: Kepler orbits to the last float64 digit, cross-checked against rebound and heyoka.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)


def _print_version(asked: bool) -> None:
    if asked:
        from orbits import __version__

        print(f"orbits {__version__}")
        raise typer.Exit()


@app.callback()
def _root(version: bool = typer.Option(False, "--version", callback=_print_version, is_eager=True,
                                       help="Print the version and exit.")) -> None:
    """The options every verb shares are the verbs' own; the root has --version and -h / --help."""

# the verbs by subject, in the order `orbits --help` lists them (orbits_cli.pages.SUBJECTS names the panels)
app.command("orbit")(reports_errors(displays(orbit.command)))
app.command("kepler")(reports_errors(displays(kepler.command)))
app.command("binary")(reports_errors(displays(binary.command)))
app.command("flyby")(reports_errors(displays(flyby.command)))
app.add_typer(escape.app, name="escape")
app.command("lagrange")(reports_errors(displays(lagrange.command)))
app.command("ring")(reports_errors(displays(ring.command)))
app.command("periodic")(reports_errors(displays(periodic.command)))
app.add_typer(transfer.app, name="transfer")
app.command("rocket")(reports_errors(displays(rocket.command)))
app.command("lambert")(reports_errors(displays(lambert.command)))
app.command("porkchop")(reports_errors(displays(porkchop.command)))
app.add_typer(perturb.app, name="perturb")
app.command("where")(reports_errors(displays(where.command)))
app.command("cosmology")(reports_errors(displays(cosmology.command)))
app.command("collide")(reports_errors(displays(collide.command)))
app.command("projectile")(reports_errors(displays(projectile.command)))
app.command("pendulum")(reports_errors(displays(pendulum.command)))
app.command("validate")(reports_errors(validate.command))
app.command("info")(reports_errors(info.command))
bench_app = typer.Typer(help="Benchmarks: throughput and accuracy against the peers installed.", no_args_is_help=True)
app.add_typer(bench_app, name="bench")
bench_app.command("kepler")(reports_errors(bench.kepler))
bench_app.command("propagate")(reports_errors(bench.propagate))
bench_app.command("stm")(reports_errors(bench.stm))
bench_app.command("periodic")(reports_errors(bench.periodic))
bench_app.command("api")(reports_errors(bench.api))
bench_app.command("call")(reports_errors(bench.call))
bench_app.command("cli")(reports_errors(bench.cli))
bench_app.command("validate")(reports_errors(bench.validate))
bench_app.command("lambert")(reports_errors(bench.lambert))
bench_app.command("ephemeris")(reports_errors(bench.ephemeris))
bench_app.command("all")(reports_errors(bench.all_))
bench_app.command("precision")(reports_errors(precision.command))
document(app)
