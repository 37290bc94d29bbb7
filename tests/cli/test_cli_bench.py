"""`orbits bench propagate|api|cli|validate|all` and `orbits validate --sweep` on tiny sizes."""

import json

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app


def run(*args):
    return CliRunner().invoke(app, list(args))


def test_bench_propagate_writes_the_rows_atomically(tmp_path):
    target = tmp_path / "propagate.json"
    result = run("bench", "propagate", "--states", "600", "--reference", "4", "--repeats", "1", "--output", str(target))
    assert result.exit_code == 0, result.output
    rows = json.loads(target.read_text())
    assert {r["dataset"] for r in rows} == {"elliptic", "mixed"} and "max |dr|/r" in result.output
    assert [p.name for p in tmp_path.iterdir()] == ["propagate.json"]


def test_bench_api_json_format():
    result = run("bench", "api", "--sizes", "1", "--repeats", "1", "--format", "json")
    assert result.exit_code == 0, result.output
    assert {r["case"].split()[0] for r in json.loads(result.output)} == {"Orbit.propagate", "Orbit.from_elements"}


def test_bench_call_times_each_case_beside_heyoka_where_it_has_a_cfunc():
    """One row per case and size; heyoka's kepE and lagrange_prop time the same inputs (when heyoka is installed),
    the other cases have no yardstick; every time is a positive number of seconds."""
    result = run("bench", "call", "--sizes", "1,3", "--repeats", "1", "--no-compile", "--format", "json")
    assert result.exit_code == 0, result.output
    rows = json.loads(result.output)
    cases = ["Kepler E", "propagation", "STM", "Lambert", "Orbit.propagate", "Orbit.propagate, stm=True"]
    assert [(r["case"], r["n"]) for r in rows] == [(case, n) for case in cases for n in (1, 3)]
    assert all(r["orbits_seconds"] > 0 for r in rows)
    peers = {r["case"]: r["peer"] for r in rows if r["peer_seconds"] is not None}
    pytest.importorskip("heyoka")
    assert peers == {"Kepler E": "heyoka kepE", "propagation": "heyoka lagrange_prop"}
    table = run("bench", "call", "--sizes", "1", "--repeats", "1", "--no-compile").output
    assert "Kepler E (beside heyoka kepE)" in table and max(len(line) for line in table.splitlines()) <= 80


def test_bench_api_rejects_bad_sizes():
    result = run("bench", "api", "--sizes", "1,x")
    assert result.exit_code == 2 and "comma-separated" in result.output


def test_bench_validate_without_sweep():
    result = run("bench", "validate", "--no-sweep", "--format", "json")
    assert result.exit_code == 0, result.output
    assert json.loads(result.output)[-1]["scene"] == "all"


def test_bench_cli_and_all_are_registered():
    for name in ("cli", "all"):
        result = run("bench", name, "--help")
        assert result.exit_code == 0 and "--output" in result.output


def test_validate_sweep_matches_the_sequential_run(tmp_path):
    pytest.importorskip("distributed")
    sequential, swept = tmp_path / "a.json", tmp_path / "b.json"
    assert run("validate", "circular", "flyby", "--output", str(sequential)).exit_code == 0
    result = run("validate", "circular", "flyby", "--sweep", "--output", str(swept))
    assert result.exit_code == 0, result.output
    strip = lambda path: [
        {k: v for k, v in s.items() if k in ("name", "checks", "residuals")}
        for s in json.loads(path.read_text())["scenes"]
    ]
    assert strip(sequential) == strip(swept)


def test_bench_precision_table_is_one_table_per_problem_within_80_columns(monkeypatch):
    """Each problem heads its own table; each method is one row of at most 80 columns, settings and times in a
    few characters (no wrapped or elided cell)."""
    monkeypatch.setenv("COLUMNS", "80")
    result = run("bench", "precision", "--quick", "--problem", "L4")
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert max(len(line) for line in lines) <= 80 and "…" not in result.output
    assert any(line.strip() == "Earth-Moon L4, 100 periods" for line in lines)
    rows = {line.split()[0] + " " + line.split()[1]: line for line in lines if line.startswith((" orbits", " rebound",
                                                                                                " heyoka"))}
    assert "closed form" in rows["orbits analytic"] and " us" in rows["orbits analytic"]
    assert "eps " in rows["rebound IAS15"] and "steps/P" in rows["rebound WHFast"]
    assert "tol " in rows["heyoka long"] and len(rows) == 7
