"""Help pages: every command has a one-line summary and two to four examples that run; every page fits 80 columns
and wraps its description only between words; `validate --help` lists the built-in scenes."""

import re
import shlex

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app
from orbits_cli.pages import EXAMPLE_WIDTH, EXAMPLES, SUMMARY, example_lines

WIDTH = 80


def commands(typer_app=app, prefix=""):
    """(path, callback) of every leaf command, and the paths of the groups."""
    leaves, groups = [], []
    for info in typer_app.registered_commands:
        leaves.append((f"{prefix}{info.name}", info.callback))
    for group in typer_app.registered_groups:
        groups.append(f"{prefix}{group.name}")
        sub_leaves, sub_groups = commands(group.typer_instance, f"{prefix}{group.name} ")
        leaves += sub_leaves
        groups += sub_groups
    return leaves, groups


LEAVES, GROUPS = commands()
PATHS = [path for path, _ in LEAVES]


def too_wide(text):
    """Lines over 80 columns, but for a line that is one unbreakable word (a path) after its indent."""
    return [line for line in text.splitlines() if len(line) > WIDTH and len(line.split()) > 1]


def run(args, **kwargs):
    return CliRunner().invoke(app, args, env={"COLUMNS": str(WIDTH), "TERM": "dumb"}, **kwargs)


def test_every_command_has_a_summary_that_fits_the_command_list():
    missing = [p for p in PATHS + GROUPS if p not in SUMMARY]
    assert missing == []
    long = {p: len(s) for p, s in SUMMARY.items() if len(s) > 60}
    assert long == {}, "a summary longer than 60 characters wraps in the command list at 80 columns"
    assert set(SUMMARY) == set(PATHS + GROUPS), "a summary for a command that does not exist"


@pytest.mark.parametrize("path", PATHS)
def test_every_command_has_two_to_four_examples(path):
    assert 2 <= len(EXAMPLES.get(path, [])) <= 4


@pytest.mark.parametrize("path", ["", *GROUPS, *PATHS])
def test_help_pages_fit_80_columns_and_wrap_between_words(path):
    result = run([*path.split(), "--help"])
    assert result.exit_code == 0, result.output
    wide = [line for line in result.output.splitlines() if len(line) > WIDTH]
    assert wide == []
    if path in PATHS:
        doc = dict(LEAVES)[path].__doc__ or ""
        first = " ".join(doc.strip().split("\n\n")[0].split())
        text = " ".join(result.output.split())  # the page's words in order, whatever the line breaks
        assert first in text, "the description's first paragraph is broken inside a word or reordered"
        last = " ".join(" ".join(example_lines(EXAMPLES[path][-1])).split())
        assert text.rstrip().endswith(last), "the examples end the page"


@pytest.mark.parametrize("path", PATHS)
def test_every_example_is_shown_as_lines_a_shell_reads_as_the_example(path):
    """Each example is broken into lines that fit the page, each but the last continued with " \\", never inside a
    quoted value: the lines, copied into a shell, are the example's words."""
    for example in EXAMPLES[path]:
        lines = example_lines(example)
        assert all(len(line) <= EXAMPLE_WIDTH for line in lines), lines
        commands = [line for line in lines if not line.startswith("#")]
        assert all(line.endswith(" \\") for line in commands[:-1]) and not commands[-1].endswith("\\"), lines
        command = " ".join(line.removesuffix(" \\") for line in commands)
        assert shlex.split(command, comments=True) == shlex.split(example, comments=True)


def test_a_long_example_is_broken_between_options_and_never_inside_quotes():
    """A hostile example: quoted values with spaces on every option, longer than a line several times."""
    example = "orbits x " + " ".join(f'--opt{k} "{k} words in one value"' for k in range(9)) + "  # a comment"
    lines = example_lines(example)
    assert len(lines) > 3 and all(len(line) <= EXAMPLE_WIDTH for line in lines)
    assert all(line.count('"') % 2 == 0 for line in lines)
    command = " ".join(line.removesuffix(" \\") for line in lines if not line.startswith("#"))
    assert shlex.split(command, comments=True) == shlex.split(example, comments=True)


def examples():
    for path in PATHS:
        for example in EXAMPLES[path]:
            yield pytest.param(example, id=f"{path}: {example[:50]}")


@pytest.mark.parametrize("example", list(examples()))
def test_every_example_runs(example, tmp_path, monkeypatch):
    """Each example exits 0 and, unless it asks for JSON (machine output, strict and on as many columns as its strings
    need), prints nothing wider than 80 columns (files it writes go to a temporary folder)."""
    monkeypatch.chdir(tmp_path)
    command = re.sub(r"\\\n\s*", " ", example.split("  #")[0])
    args = shlex.split(command)
    assert args[0] == "orbits"
    result = run(args[1:])
    assert result.exit_code == 0, (example, result.output)
    if "--format" not in args or args[args.index("--format") + 1] != "json":
        assert too_wide(result.output) == [], example


def test_validate_help_lists_every_built_in_scene():
    from orbits.validate import builtin_names

    result = run(["validate", "--help"])
    text = " ".join(result.output.split())
    assert all(f" {name}: " in text for name in builtin_names())


def test_info_is_a_summary_within_80_columns_and_the_sources_follow_on_request():
    """orbits info fits 80 columns without breaking a word; the sources (every constant's) come with --sources."""
    from orbits._common.system import info

    short, full = run(["info"]), run(["info", "--sources"])
    assert short.exit_code == full.exit_code == 0
    assert len(short.output.splitlines()) < 60 and too_wide(full.output) == []
    words = " ".join(full.output.split())
    for name, source in info()["constants"].items():
        assert f"{name}: {' '.join(source.split())}" in words  # wrapped between words only
        assert " ".join(source.split()) not in " ".join(short.output.split())
