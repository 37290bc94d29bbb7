"""The README's map of the code stays true: every module and package of `orbits/` is named in its section "How the
code is laid out", and every name the section puts in code type that looks like a module of ours exists."""

import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "orbits"


def map_section() -> str:
    text = (ROOT / "README.md").read_text()
    start = text.index("## How the code is laid out")
    end = text.find("\n## ", start + 1)
    return text[start:] if end < 0 else text[start:end]


def modules() -> list[str]:
    """Every module and subpackage of orbits/ by its own name (e.g. "propagate", "bench", "_fast_kepler")."""
    names = {path.stem for path in PACKAGE.rglob("*.py") if path.name != "__init__.py"}
    names |= {path.parent.name for path in PACKAGE.rglob("__init__.py") if path.parent != PACKAGE}
    return sorted(names)


def named(section: str) -> set[str]:
    """The words the section puts in code type, split at slashes and dots ("plot/frame" -> plot, frame)."""
    words = set()
    for code in re.findall(r"`([^`]+)`", section):
        words |= set(re.split(r"[/.\s(),]+", code))
    return words


@pytest.mark.parametrize("module", modules())
def test_every_module_is_on_the_map(module):
    assert module in named(map_section()), f"orbits' module {module!r} is missing from the README's map"


def test_the_map_names_no_module_that_is_gone():
    """A name in the map's table that is not a module of ours (nor a folder, verb or known word) is a stale entry."""
    section = map_section()
    table = "\n".join(line for line in section.splitlines() if line.startswith("|"))
    verbs = {path.stem for path in (ROOT / "cli" / "commands").glob("*.py")}
    others = {"orbits", "core", "validate", "plot", "manoeuvres", "<subject>", "–", "(tests against heyoka)"} | verbs
    stale = [w for w in named(table) - others if w and w not in modules()]
    assert stale == [], stale
