"""orbits.tools.bench_lambert and `orbits bench lambert` on tiny sizes (orbits' own rows; peers as installed)."""

import json

from typer.testing import CliRunner

from orbits.tools.bench_lambert import bench_lambert, format_lambert, hard_cases
from orbits_cli.main import app


def test_rows_and_table_fit_80_columns():
    rows = bench_lambert(n=2000, n_ref=10, repeats=1, solvers=["orbits", "orbits (NumPy)", "pykep lambert_problem"])
    by_name = {r.method: r for r in rows}
    for name in ("orbits", "orbits (NumPy)"):
        row = by_name[name]
        assert row.status == "ok" and row.hard_failed == 0 and row.hard_total == len(hard_cases())
        assert row.worst_error < 1e-13 and row.throughput_per_s > 0
    text = format_lambert(rows)
    assert max(map(len, text.splitlines())) <= 80
    assert "hard failed" in text and "0/" in text


def test_missing_peers_say_not_installed():
    rows = bench_lambert(n=100, n_ref=2, repeats=1, solvers=["pykep lambert_problem", "hapsira izzo"])
    for row in rows:
        assert row.status in ("ok", "not installed")
        if row.status == "not installed":
            assert "not installed" in format_lambert(rows)


def test_cli_bench_lambert_json():
    result = CliRunner().invoke(app, ["bench", "lambert", "--transfers", "300", "--reference", "3", "--repeats",
                                      "1", "--format", "json"])
    assert result.exit_code == 0, result.output
    rows = json.loads(result.output)
    assert rows[0]["method"] == "orbits" and rows[0]["hard_failed"] == 0
