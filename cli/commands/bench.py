"""`orbits bench ...`: benchmarks that print ratios against peers measured in the same run."""

from typing import Annotated

import typer
from orbits_cli.options import Format, FormatOption


def kepler(
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

    from orbits.bench import bench_kepler as run
    from orbits.bench import format_rows, rows_to_json
    from orbits.io import write_atomic

    rows = run(n_easy=easy, n_hard=hard, n_hyp=hyperbolic, n_ref=reference, repeats=repeats)
    text = json.dumps(rows_to_json(rows), indent=2)
    print(text if fmt == Format.json else format_rows(rows))
    if output:
        write_atomic(output, text + "\n")
