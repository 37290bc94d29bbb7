"""`orbits bench ...`: benchmarks that print ratios against peers measured in the same run."""

from typing import Annotated

import typer

from orbits_cli.options import Format, FormatOption, OutputOption


def _count(name: str, limit: str):
    """A parse-time check that a count option lies in [1, orbits.tools.bench.harness.<limit>], before any work."""

    def check(value: int) -> int:
        from orbits import OrbitsError
        from orbits.tools.bench import harness

        try:
            return harness.check_count(value, name, getattr(harness, limit))
        except OrbitsError as err:
            raise typer.BadParameter(str(err).removeprefix(f"{name} = ")) from None

    return check


def _sized(help: str, name: str, limit: str = "MAX_SET"):
    return typer.Option(name, help=help, callback=_count(name, limit))


RepeatsOption = Annotated[int, _sized("timing repeats (best is kept)", "--repeats", "MAX_REPEATS")]


def _emit(data, table, fmt, output):
    """Print the table (or the JSON), and write the JSON atomically to `output` if given."""
    from orbits._common.io import write_atomic
    from orbits_cli import render

    text = render.dumps(data)
    print(text if fmt == Format.json else table)
    if output:
        write_atomic(output, text + "\n")


def kepler(
    easy: Annotated[int, _sized("easy pairs, e in [0, 0.99]", "--easy")] = 1_000_000,
    hard: Annotated[int, _sized("hard pairs, e in [0.99, 1 - 1e-9], M tiny or near pi", "--hard")] = 100_000,
    hyperbolic: Annotated[int, _sized("hyperbolic pairs", "--hyperbolic")] = 100_000,
    reference: Annotated[int, _sized("pairs per set checked against mpmath", "--reference", "MAX_REFERENCE")] = 2000,
    repeats: RepeatsOption = 3,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Kepler solvers: throughput and worst error of orbits and its peers, measured in one run."""
    from orbits.tools.bench.kepler import bench_kepler, format_rows
    from orbits.tools.bench.table import rows_to_json

    rows = bench_kepler(n_easy=easy, n_hard=hard, n_hyp=hyperbolic, n_ref=reference, repeats=repeats)
    _emit(rows_to_json(rows), format_rows(rows), fmt, output)


def propagate(
    states: Annotated[int, _sized("states per set (elliptic, mixed conics)", "--states")] = 1_000_000,
    reference: Annotated[int, _sized("states per set checked against mpmath", "--reference", "MAX_REFERENCE")] = 200,
    repeats: RepeatsOption = 3,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Two-body propagation: throughput and worst position and velocity error of orbits and its peers."""
    from orbits.tools.bench.propagate import bench_propagate, format_propagate
    from orbits.tools.bench.table import rows_to_json

    rows = bench_propagate(n=states, n_ref=reference, repeats=repeats)
    _emit(rows_to_json(rows), format_propagate(rows), fmt, output)


def stm(
    states: Annotated[int, _sized("states per set (elliptic, mixed conics)", "--states")] = 100_000,
    reference: Annotated[int, _sized("states per set checked against mpmath", "--reference", "MAX_REFERENCE")] = 20,
    repeats: RepeatsOption = 3,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """State-transition matrix d(r, v)/d(r0, v0): time per state and worst error of orbits and pykep."""
    from orbits.tools.bench.stm import bench_stm, format_stm
    from orbits.tools.bench.table import rows_to_json

    rows = bench_stm(n=states, n_ref=reference, repeats=repeats)
    _emit(rows_to_json(rows), format_stm(rows), fmt, output)


def periodic(
    members: Annotated[int, typer.Option(help="members of the family (2 to 1000)", min=2, max=1000)] = 100,
    repeats: RepeatsOption = 3,
    numpy: Annotated[bool, typer.Option("--numpy/--no-numpy", help="also time the NumPy integrator (the family "
                                        "takes about a minute with it)")] = True,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Periodic orbits: one corrected halo orbit and a family to the 9:2 NRHO, timed, integrations counted."""
    from orbits.tools.bench.periodic import bench_periodic, format_periodic
    from orbits.tools.bench.table import rows_to_json

    rows = bench_periodic(members=members, repeats=repeats, numpy=numpy)
    _emit(rows_to_json(rows), format_periodic(rows), fmt, output)


def api(
    sizes: Annotated[str, typer.Option(help="comma-separated batch sizes (1 = scalars)")] = "1,100000,1000000",
    repeats: RepeatsOption = 5,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Unit-aware API: time per call of orbits.Orbit against the float64 core on the same inputs."""
    from orbits.tools.bench.api import bench_api, format_api
    from orbits.tools.bench.table import rows_to_json

    rows = bench_api(sizes=_sizes(sizes), repeats=repeats)
    _emit(rows_to_json(rows), format_api(rows), fmt, output)


def call(
    sizes: Annotated[str, typer.Option(help="comma-separated batch sizes (1 = one element, as scalars)")] = (
        "1,1000,10000"),
    repeats: RepeatsOption = 5,
    compile_first: Annotated[bool, typer.Option(
        "--compile/--no-compile", help="compile the kernels the cache lacks first (else those calls run NumPy)"
    )] = True,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Time per call where users are: Kepler's equation, propagation, the transition matrix, Lambert and
    Orbit.propagate on one element and on small batches, one thread, default settings, beside heyoka's compiled
    kepE and lagrange_prop on the same inputs. Kernels absent from the cache are compiled first (the time is not
    counted), unless --no-compile."""
    from orbits.tools.bench.call import bench_call, format_call
    from orbits.tools.bench.table import rows_to_json

    rows = bench_call(sizes=_sizes(sizes), repeats=repeats, compile_first=compile_first)
    _emit(rows_to_json(rows), format_call(rows), fmt, output)


def _sizes(text):
    try:
        sizes = tuple(int(s) for s in text.split(",") if s.strip())
    except ValueError:
        raise typer.BadParameter(f"--sizes: {text!r} is not a comma-separated list of integers") from None
    if not sizes:
        raise typer.BadParameter(f"--sizes: {text!r} gives no size")
    check = _count("--sizes", "MAX_SET")
    try:
        return tuple(check(size) for size in sizes)
    except typer.BadParameter as err:
        raise typer.BadParameter(f"--sizes: {err.message}") from None


def cli(
    runs: Annotated[int, _sized("fresh processes per command", "--runs", "MAX_REPEATS")] = 10,
    first_run: Annotated[bool, typer.Option(help="also time each first-run command with an empty kernel cache "
                                                 "(it compiles what a new install compiles)")] = True,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Command-line cold start: median wall time of fresh `orbits` processes."""
    from orbits.tools.bench.cli import bench_cli, format_cli
    from orbits.tools.bench.table import rows_to_json

    rows = bench_cli(runs=runs) if first_run else bench_cli(runs=runs, first_runs=[])
    _emit(rows_to_json(rows), format_cli(rows), fmt, output)


def validate(
    scenes: Annotated[list[str] | None, typer.Argument(help="built-in scene names or scene files [default: "
                                                            "every built-in scene]")] = None,
    sweep: Annotated[bool, typer.Option(help="also time dask sweeps (LocalCluster of threads, of processes)")] = True,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Validation: where the time of `orbits validate` goes, scene by scene and stage by stage."""
    from orbits.tools.bench.table import rows_to_json
    from orbits.tools.bench.validate import bench_validate, format_validate

    rows = bench_validate(scenes or None, sweep=sweep)
    _emit(rows_to_json(rows), format_validate(rows), fmt, output)


def lambert(
    transfers: Annotated[int, _sized("random zero-revolution transfers (per-call peers: a subset)", "--transfers")] = (
        1_000_000),
    reference: Annotated[int, _sized("transfers checked against the mpmath propagation", "--reference",
                                     "MAX_REFERENCE")] = 200,
    repeats: RepeatsOption = 3,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Lambert solvers: throughput, arrival error and hard cases of orbits and its peers, in one run."""
    from orbits.tools.bench.lambert import bench_lambert, format_lambert
    from orbits.tools.bench.table import rows_to_json

    rows = bench_lambert(n=transfers, n_ref=reference, repeats=repeats)
    _emit(rows_to_json(rows), format_lambert(rows), fmt, output)


def ephemeris(
    epochs: Annotated[int, _sized("random TDB epochs 1900-2050", "--epochs")] = 100_000,
    repeats: RepeatsOption = 3,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """States of Mars at many epochs from DE421: orbits against jplephem and astropy reading the same file."""
    from orbits.tools.bench.ephemeris import bench_ephemeris, format_ephemeris
    from orbits.tools.bench.table import rows_to_json

    rows = bench_ephemeris(n=epochs, repeats=repeats)
    _emit(rows_to_json(rows), format_ephemeris(rows), fmt, output)


def all_(
    quick: Annotated[bool, typer.Option(help="a tenth of the default sizes and 3 CLI runs")] = False,
    only: Annotated[str | None, typer.Option(help="comma-separated benchmarks to run, e.g. kepler,lambert "
                                                  "[default: all]")] = None,
    output: OutputOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Every benchmark above in one run: one table each, one JSON object {benchmark: rows}."""
    from orbits.tools.bench.suite import bench_all, format_report, report_to_json

    options = {}
    if quick:
        options = {
            "kepler": {"n_easy": 100_000, "n_hard": 10_000, "n_hyp": 10_000, "n_ref": 200},
            "propagate": {"n": 100_000, "n_ref": 50},
            "stm": {"n": 10_000, "n_ref": 5},
            "lambert": {"n": 100_000, "n_ref": 50},
            "periodic": {"members": 10, "numpy": False},
            "ephemeris": {"n": 10_000},
            "api": {"sizes": (1, 100_000)},
            "call": {"sizes": (1, 1000)},
            "cli": {"runs": 3},
        }
    report = bench_all(names=_benchmark_names(only), **options)
    _emit(report_to_json(report), format_report(report), fmt, output)


def _benchmark_names(text: str | None) -> list[str] | None:
    """The benchmarks --only names, each checked against the suite's; None for all."""
    from orbits.tools.bench.suite import BENCHMARKS

    if text is None:
        return None
    names = [n.strip() for n in text.split(",") if n.strip()]
    unknown = [n for n in names if n not in BENCHMARKS]
    if unknown or not names:
        raise typer.BadParameter(f"--only {text!r}: choose from {', '.join(BENCHMARKS)}")
    return names
