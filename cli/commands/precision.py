"""`orbits bench precision`: work-precision of every integrator against an mpmath reference."""

from typing import Annotated

import typer

from orbits_cli.options import Format, FormatOption, OutputOption, PlotOption, save_plot


def command(
    quick: Annotated[bool, typer.Option(help="100-period problems only and every other knob setting")] = False,
    problem: Annotated[
        str | None, typer.Option(help="only the problems whose name contains this text, e.g. 'L4' or 'e=0.9'")
    ] = None,
    target: Annotated[float, typer.Option(help="error the summary asks each method to reach")] = 1e-10,
    output: OutputOption = None,
    plot: PlotOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Sweep each integrator's accuracy knob on the same problems; error against run time, with a summary."""
    import dataclasses

    from orbits._common.io import write_atomic
    from orbits.tools import precision
    from orbits_cli import render
    from orbits_cli.render import precision_tables

    precision.error_target(target)  # before the runs
    chosen = [p for p in precision.problems(long=not quick) if problem is None or problem in p.name]
    if not chosen:
        raise typer.BadParameter(f"--problem: no problem name contains {problem!r}")
    rows = precision.run(chosen, precision.methods(quick=quick))
    data = {"target": target, "rows": [dataclasses.asdict(r) for r in rows],
            "summary": precision.summary(rows, target)}
    text = render.dumps(data)
    if output:
        write_atomic(output, text + "\n")
    if plot:
        from orbits.plot import work_precision

        save_plot(lambda: work_precision(rows), plot)
    if fmt == Format.json:
        print(text)
    else:
        precision_tables(data)
