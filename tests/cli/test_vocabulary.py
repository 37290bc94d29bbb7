"""One word per idea across every verb: the click tree is held to orbits_cli.vocabulary, the former spellings are
refused with a one-line hint before any work, and no verb takes a body as a bare word where another takes
--primary."""

import re
import subprocess
import sys

import pytest
import typer.main
from typer.testing import CliRunner

from orbits_cli.main import app
from orbits_cli.vocabulary import RETIRED, RETIRED_ARGUMENTS, VOCABULARY, retired_word

#: what typer adds to every command, and the root's own
FRAMEWORK = {"--help", "-h", "--install-completion", "--show-completion"}
#: the bare words a verb may take: the body of the answer (not the central body), a count, scenes
ARGUMENTS = {"orbit": ["body_name"], "where": ["body_name"], "perturb relativity": ["name"], "ring": ["n"],
             "validate": ["scenes"], "bench validate": ["scenes"]}


def verbs(command=None, path=()):
    """(verb path, click command) of every leaf of the click tree."""
    command = command or typer.main.get_command(app)
    if hasattr(command, "commands"):
        for name, sub in command.commands.items():
            yield from verbs(sub, (*path, name))
    else:
        yield " ".join(path), command


VERBS = dict(verbs())


def spellings(command):
    return {s for p in command.params for s in (*getattr(p, "opts", ()), *getattr(p, "secondary_opts", ()))
            if s.startswith("-") and s not in FRAMEWORK}


def test_the_tree_is_not_empty():
    assert len(VERBS) > 40 and "transfer hohmann" in VERBS and "perturb kozai" in VERBS


@pytest.mark.parametrize("verb", sorted(VERBS))
def test_every_option_is_a_word_of_the_vocabulary(verb):
    """An option no other verb knows under that meaning is added to the vocabulary with its idea, or renamed to
    the word that idea has (a second word for the same idea is refused below)."""
    options = {"--" + s.removeprefix("--no-").removeprefix("--") for s in spellings(VERBS[verb])}
    assert options - set(VOCABULARY) == set()


def test_one_word_per_idea():
    ideas = list(VOCABULARY.values())
    assert len(ideas) == len(set(ideas))


@pytest.mark.parametrize("verb", sorted(VERBS))
def test_bare_words_name_the_answer_never_the_central_body(verb):
    arguments = [p.name for p in VERBS[verb].params if type(p).__name__.endswith("Argument")]
    assert arguments == ARGUMENTS.get(verb, [])


@pytest.mark.parametrize(("verb", "old"), sorted(RETIRED))
def test_a_former_spelling_has_its_word_now_on_that_verb(verb, old):
    assert verb in VERBS
    assert RETIRED[verb, old] in spellings(VERBS[verb]) and old not in spellings(VERBS[verb])


@pytest.mark.parametrize("verb", sorted(RETIRED_ARGUMENTS))
def test_the_verbs_that_took_bare_bodies_take_options(verb):
    assert set(RETIRED_ARGUMENTS[verb]) <= spellings(VERBS[verb])


def hostile_uses():
    """Each former spelling used as a user who learnt it would, with a value."""
    for (verb, old), new in sorted(RETIRED.items()):
        yield pytest.param([*verb.split(), old, "1 km"], new, id=f"{verb} {old}")
    for verb, options in sorted(RETIRED_ARGUMENTS.items()):
        words = ["Earth", "Moon"][: len(options)]
        yield pytest.param([*verb.split(), *words, "--only", "x"], options[0], id=f"{verb} BODY")


@pytest.mark.parametrize(("args", "new"), list(hostile_uses()))
def test_a_former_spelling_is_refused_in_one_line_naming_the_word_now(args, new):
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("orbits: error: ") and new in lines[0], result.output
    assert "Invalid value" not in lines[0]


def test_the_hint_comes_before_any_work():
    """A former spelling beside an expensive request is refused at once, by the installed command."""
    result = subprocess.run([sys.executable, "-c", "from orbits_cli.main import app; app()", "porkchop", "--launch",
                             "2026-01-01:2028-09-27", "--arrive", "2026-06-01:2029-02-25", "--step", "1 d"],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 2 and "--launch is now --depart" in result.stderr


def test_the_hint_quotes_a_body_with_spaces():
    assert retired_word("lagrange", ["1 solMass", "Moon"]) == (
        "orbits lagrange takes its bodies as options now: --primary '1 solMass' --secondary Moon")
    assert retired_word("lagrange", ["--primary", "Earth", "--secondary", "Moon"]) is None
    assert retired_word("porkchop", ["--step", "1 d", "--", "--launch"]) is None  # after --, words are not options


def test_every_error_line_has_one_prefix():
    """Usage errors (click's) and input errors (the library's) read alike: "orbits: error: " then the problem."""
    for args in (["orbit", "--e", "abc"], ["orbit", "--primary", "Earth", "--a", "7000 km", "--plot", "x.txt"],
                 ["kepler", "--e", "0.5"], ["orbit", "Marz"]):
        result = CliRunner().invoke(app, args)
        assert result.exit_code == 2
        line, = result.output.strip().splitlines()
        assert re.match(r"orbits: error: (?!Invalid value)", line), line
