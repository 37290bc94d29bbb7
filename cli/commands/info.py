"""`orbits info`: versions, cache locations and where the constants come from."""

from orbits_cli.options import Format, FormatOption


def command(fmt: FormatOption = Format.table) -> None:
    """Versions of orbits and its dependencies, cache locations, and the constants' sources."""
    show(fmt.value)


def show(fmt: str) -> None:
    """Print the facts as a table or JSON."""
    from rich import box
    from rich.table import Table

    from orbits.system import info
    from orbits_cli import render

    facts = info()
    if fmt == "json":
        print(render.dumps(facts))
        return
    grid = Table(show_header=False, box=box.SIMPLE, pad_edge=False)
    grid.add_column("item", overflow="fold")
    grid.add_column("value", overflow="fold")
    grid.add_row("python", f"{facts['python']} on {facts['platform']}")
    for section in ("versions", "caches", "constants"):
        for key, value in facts[section].items():
            grid.add_row(key, value)
    render.print_tables([grid], "orbits info")
