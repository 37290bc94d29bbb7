"""Every notebook runs top to bottom without error, in under a minute, and is committed without outputs. A notebook
teaches: it holds no `assert` (tests/notebooks/test_notebook_numbers.py checks its numbers) and no reference a reader
of the repository cannot follow (an erratum number, an issue number, a path outside the repository)."""

import re
from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

NOTEBOOKS = sorted((Path(__file__).resolve().parents[2] / "notebooks").glob("*.ipynb"))

#: what a self-contained notebook never says: erratum and issue numbers, folders outside the repository
FOREIGN_REFERENCES = re.compile(
    r"ERRATA|errat\w*\s*#|\bissues?\s*#?\d+"  # erratum and issue numbers
    r"""|(?<!["'\w])#\d+\b"""  # "#88", but not a colour such as "#333"
    r"|\bshared/|/work/",  # folders outside the repository
    re.IGNORECASE)


def test_there_are_notebooks():
    assert len(NOTEBOOKS) >= 3


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs(path, tmp_path, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")
    notebook = nbformat.read(path, as_version=4)
    resources = {"metadata": {"path": str(tmp_path)}}
    client = NotebookClient(notebook, timeout=60, kernel_name="python3", resources=resources)
    client.execute()
    errors = [o for cell in notebook.cells for o in cell.get("outputs", []) if o.get("output_type") == "error"]
    assert not errors


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_is_committed_without_outputs(path):
    notebook = nbformat.read(path, as_version=4)
    assert all(not cell.get("outputs") and not cell.get("execution_count") for cell in notebook.cells
               if cell.cell_type == "code")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_holds_no_assert(path):
    notebook = nbformat.read(path, as_version=4)
    asserts = [line.strip() for cell in notebook.cells if cell.cell_type == "code"
               for line in cell.source.splitlines() if re.match(r"\s*assert\b", line)]
    assert not asserts, f"{path.name}: move these checks to the tests: {asserts}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_references_are_self_contained(path):
    notebook = nbformat.read(path, as_version=4)
    found = [match.group(0) for cell in notebook.cells for match in FOREIGN_REFERENCES.finditer(cell.source)]
    assert not found, f"{path.name} refers to what its reader cannot see: {found}"


def test_the_checks_catch_what_they_look_for():
    """The patterns above find what they are for, and leave ordinary text alone."""
    for text in ("see ERRATA #20", "the erratum #7", "issue 30", "issues #12", "shared/EDGE_CASES.md", "#88-#90"):
        assert FOREIGN_REFERENCES.search(text), text
    for text in ("section XXII (binary stars)", "the course's chapter on rockets", "# a comment", "x = 2  # m/s",
                 "tests/validation/test_scenes.py", "color=\"#333\""):
        assert not FOREIGN_REFERENCES.search(text), text
