"""The README stays true: its quick start is on its first screen, its two commands are verbatim, every `$ orbits`
block shows what the command prints, its Python runs as written (doctest), its contents link to its sections, its
picture is the one the code draws, and it stays short."""

import doctest
import re
import shlex
from pathlib import Path

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()
LINES = README.splitlines()


def shown_commands():
    """(command, [the lines the README shows after it]) of every `$ orbits ...` in an indented block; a line
    ending in a backslash continues the command."""
    blocks, k = [], 0
    while k < len(LINES):
        line = LINES[k]
        if line.startswith("    $ orbits "):
            command = line[6:]
            while command.endswith("\\"):
                k += 1
                command = command[:-1] + LINES[k].strip()
            shown = []
            k += 1
            while k < len(LINES) and LINES[k].startswith("    ") and not LINES[k].startswith("    $ "):
                shown.append(LINES[k][4:].rstrip())
                k += 1
            blocks.append((command, shown))
            continue
        k += 1
    return blocks


COMMANDS = shown_commands()


def test_the_quick_start_is_on_the_first_screen():
    head = "\n".join(LINES[:40])
    assert "## Quick start" in head and 'pip install -e ".[ephemeris,plot]"' in head and "python -m venv" in head
    assert head.count("    $ orbits ") >= 3


def test_the_two_commands_stay_verbatim_in_their_section():
    section = README[README.index("## The two commands"):]
    section = section[:section.index("\n## ", 1)]
    assert '    pip install -e ".[ephemeris]" && orbits validate' in section
    assert '    python -m pip install -e ".[test]" && python -m pytest' in section


def test_the_readme_is_short():
    assert len(LINES) < 450


@pytest.mark.parametrize(("command", "shown"), COMMANDS, ids=[c[:60] for c, _ in COMMANDS])
def test_every_shown_command_prints_what_the_readme_shows(command, shown, tmp_path, monkeypatch):
    """The command exits 0 within 80 columns, and the lines the README shows are lines of its output, in order
    (the README may leave lines out, never change one)."""
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(app, shlex.split(command)[1:], env={"COLUMNS": "80"})
    assert result.exit_code == 0, (command, result.output)
    printed = [line.rstrip() for line in result.output.splitlines()]
    assert max(map(len, printed)) <= 80
    position = 0
    for line in (s for s in shown if s.strip()):
        assert line in printed[position:], (command, line)
        position = printed.index(line, position) + 1


def test_the_readme_has_the_quick_starts_three_commands_and_more():
    assert len(COMMANDS) >= 10


def test_the_python_in_the_readme_runs_as_written():
    parser = doctest.DocTestParser()
    test = parser.get_doctest(README, {}, "README.md", str(ROOT / "README.md"), 0)
    assert test.examples, "the README has Python examples"
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    assert runner.failures == 0


def _anchor(heading):
    return re.sub(r"[^a-z0-9 -]", "", heading.lower()).replace(" ", "-")


def test_the_contents_link_to_sections():
    anchors = {_anchor(line.lstrip("#").strip()) for line in LINES if line.startswith("#")}
    links = re.findall(r"\]\(#([^)]+)\)", README)
    assert links and set(links) <= anchors, set(links) - anchors


def test_the_picture_is_the_one_the_code_draws(tmp_path):
    """The README's picture exists, and the script that made it draws it again."""
    import runpy

    shown = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", README)
    assert shown == ["notebooks/images/porkchop.png"] and (ROOT / shown[0]).stat().st_size > 50_000
    script = runpy.run_path(str(ROOT / "notebooks" / "make_readme_picture.py"))
    drawn = script["draw"](tmp_path / "porkchop.png")
    assert drawn.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and drawn.stat().st_size > 50_000
