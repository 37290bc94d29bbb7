"""Every reference in the code, the notebooks and the README is one a reader of the repository can follow: no
erratum or issue numbers, no numbered rows of a table kept elsewhere, no folders outside the repository. Where the
code departs from the course's text it says so in its own words; the table of hard corners the stability tests
follow is tests/stability/EDGE_CASES.md, and a row of it is named as "row 45 of tests/stability/EDGE_CASES.md"."""

import json
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
FOLDERS = ("orbits", "cli", "notebooks")

#: what a reader of the repository cannot follow
FOREIGN_REFERENCES = re.compile(
    r"\berrat(?:a|um)\b"  # the list of corrections to the course, which is not in the repository
    r"|\bissues?\s*#?\s*\d+"  # issue numbers ("issue 18", "issues #12"); a link to a public issue stays
    r"""|(?<![\w"'&/=])(?<!: )#\d+\b"""  # "#88", "(#88-#90)"; not a colour ("#333" after a quote, = or ": ")
    r"|(?-i:EDGE_CASES)(?!\.md\b)|(?-i:EDGE_CASES)\.md\s*#?\s*\d"  # numbered rows of a table kept elsewhere
    r"|\.\./|\bshared/|/work/|/tmp/|/root/|/home/",  # folders outside the repository
    re.IGNORECASE)


def passages(path: pathlib.Path) -> list[tuple[str, str]]:
    """What a reader sees in `path` as (where, text): a notebook's cells one by one, a text file whole; nothing for a
    binary file (a picture)."""
    data = path.read_bytes()
    if b"\0" in data:
        return []
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        return []
    if path.suffix == ".ipynb":
        return [(f"cell {number}, ", "".join(cell["source"]))
                for number, cell in enumerate(json.loads(text)["cells"], 1)]
    return [("", text)]


def text_files(folder: str) -> list[pathlib.Path]:
    """The text files under `folder`, leaving out caches and hidden folders."""
    paths = []
    for path in sorted((ROOT / folder).rglob("*")):
        parts = path.relative_to(ROOT).parts
        if path.is_file() and "__pycache__" not in parts and not any(part.startswith(".") for part in parts):
            paths.append(path)
    return paths


def foreign_references(path: pathlib.Path) -> list[str]:
    """Each reference in `path` a reader of the repository cannot follow, as "file: [cell c, ]line n: match in ..."."""
    name = path.relative_to(ROOT)
    return [f"{name}: {where}line {number}: {match.group(0)!r} in {line.strip()[:100]!r}"
            for where, text in passages(path) for number, line in enumerate(text.splitlines(), 1)
            for match in FOREIGN_REFERENCES.finditer(line)]


@pytest.mark.parametrize("folder", FOLDERS)
def test_the_code_and_the_notebooks_refer_only_to_what_the_repository_holds(folder):
    paths = text_files(folder)
    assert any(passages(path) for path in paths), f"no text files found under {folder}/"
    found = [reference for path in paths for reference in foreign_references(path)]
    assert not found, "references a reader of the repository cannot follow:\n" + "\n".join(found)


def test_the_readme_refers_only_to_what_the_repository_holds():
    found = foreign_references(ROOT / "README.md")
    assert not found, "references a reader of the repository cannot follow:\n" + "\n".join(found)


@pytest.mark.parametrize("text", [
    "ERRATA #20", "(ERRATA #88-#90)", "see the errata", "the erratum on the pendulum",  # corrections kept elsewhere
    "issue 18", "Issue #14", "issues 3 and 4", "#88-#90", "(#7)",  # issue and item numbers
    "EDGE_CASES #45", "EDGE_CASES 6.3", "EDGE_CASES.md #45", "shared/EDGE_CASES.md",  # rows of a table kept elsewhere
    "../shared/ERRATA.md", "/work/main/README.md", "/tmp/orbit.png", "/root/.cache", "/home/user/orbits",  # folders
])
def test_the_pattern_catches_each_kind_of_foreign_reference(text):
    assert FOREIGN_REFERENCES.search(text)


@pytest.mark.parametrize("text", [
    'color="#333"', "color: #333", "fill='#1f77b4'", "JPL#48", "# a comment", "x = 2  # m/s",
    "issues in prose without a number", "open issues", "an erratic orbit", "1e-15 ulp",
    "row 45 of tests/stability/EDGE_CASES.md", "[EDGE_CASES.md](tests/stability/EDGE_CASES.md)",
    "tests/stability/test_edge_cases.py", "orbits/core/twobody/kepler.py", "section XXII (binary stars)",
    "the course's chapter on rockets",
    "https://github.com/numba/numba/issues/8172",
])
def test_the_pattern_leaves_ordinary_text_alone(text):
    assert not FOREIGN_REFERENCES.search(text)
