"""`orbits info`: versions, cache locations and where the constants come from."""

from orbits_cli.options import Format, FormatOption


def command(fmt: FormatOption = Format.table) -> None:
    """Versions of orbits and its dependencies, cache locations, and the constants' sources."""
    show(fmt.value)


def show(fmt: str) -> None:
    """Print the facts as a table or JSON."""
    from rich import box
    from rich.markup import escape
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
    grid.add_row("python", escape(f"{facts['python']} on {facts['platform']}"))
    for section in ("versions", "caches"):
        for key, value in facts[section].items():
            grid.add_row(key, escape(value))
    grid.add_row("ephemeris", escape(facts["ephemeris"]))  # "orbits[ephemeris]" is not markup
    sources = Table(show_header=False, box=box.SIMPLE, pad_edge=False)
    sources.add_column("item", overflow="fold")
    sources.add_column("value", overflow="fold")
    for key, value in facts["constants"].items():
        sources.add_row(key, escape(value))
    render.print_tables([grid, _bodies(facts["bodies"]), sources], "orbits info")


def _bodies(rows: list):
    """The catalogue as a table in natural units: GM km3/s2, radius km, rotation d (- retrograde), and J2 (times
    1e6) beside the reference radius of its fit, which J2 is meaningless without (Neptune's 3408.43e-6 holds at
    25,225 km, not at its 24,764 km equatorial radius)."""
    from rich import box
    from rich.table import Table

    from orbits.display import number

    table = Table(box=box.SIMPLE, pad_edge=False, padding=(0, 0),
                  title="bodies (sources below; rot. < 0: retrograde; @ R: the reference radius of J2)")
    for name, justify in (("body", "left"), ("kind", "left"), ("orbits", "left"), ("GM km3/s2", "right"),
                          ("R km", "right"), ("rot. d", "right"), ("1e6 J2", "right"), ("@ R km", "right")):
        table.add_column(name, justify=justify, no_wrap=True)
    for b in rows:
        rotation = b["rotation_period_s"] / 86400.0 * (-1 if b["retrograde"] else 1)
        has_j2 = b["j2"] is not None
        table.add_row(b["name"], b["kind"], b["parent"] or "", number(b["gm_m3_s2"] / 1e9, 7),
                      number(b["radius_m"] / 1e3, 6), number(rotation, 6),
                      number(b["j2"] * 1e6, 6) if has_j2 else "",
                      number(b["j2_radius_m"] / 1e3, 6) if has_j2 else "")
    return table
