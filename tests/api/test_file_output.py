"""Every written file goes through orbits._common.io: a write that fails reports one line and leaves no temporary file,
links are followed and never replaced, targets where no file can be made are refused before any work."""

import errno
import os
from pathlib import Path

import pytest
from typer.testing import CliRunner

from orbits import OutputError
from orbits._common.io import check_target, write_atomic
from orbits_cli.main import app

runner = CliRunner()
FULL = Path("/dev/full")
needs_dev_full = pytest.mark.skipif(not FULL.exists(), reason="no /dev/full on this system")


def leftovers(folder: Path) -> list[str]:
    return [p.name for p in folder.iterdir() if p.name.endswith(".tmp")]


@needs_dev_full
def test_a_full_device_is_one_orbits_error():
    with pytest.raises(OutputError, match=r"^cannot write /dev/full: No space left on device; nothing was written$"):
        write_atomic(FULL, "x" * 10000)


def test_a_disk_that_fills_during_the_write_leaves_no_temporary_file(tmp_path, monkeypatch):
    target = tmp_path / "report.json"
    target.write_text("old")

    def full(fd):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(os, "fsync", full)
    with pytest.raises(OutputError, match="No space left on device"):
        write_atomic(target, "new")
    assert target.read_text() == "old" and leftovers(tmp_path) == []


def test_a_link_is_followed_and_stays_a_link(tmp_path):
    target, link = tmp_path / "target.json", tmp_path / "link.json"
    target.write_text("old")
    link.symlink_to(target.name)
    write_atomic(link, "new")
    assert link.is_symlink() and os.readlink(link) == target.name
    assert target.read_text() == "new" and leftovers(tmp_path) == []
    dangling = tmp_path / "dangling.json"
    dangling.symlink_to("made.json")  # a link to a file yet to be made: the file is made, the link kept
    write_atomic(dangling, "made")
    assert dangling.is_symlink() and (tmp_path / "made.json").read_text() == "made"


def test_a_folder_where_no_file_can_be_made_is_refused_before_any_work():
    with pytest.raises(Exception, match=r"--output: no file can be made in the folder /proc"):
        check_target("/proc/version", "--output")


@needs_dev_full
def test_the_command_line_reports_a_full_device_after_the_work_in_one_line(tmp_path):
    result = runner.invoke(app, ["bench", "api", "--sizes", "1", "--repeats", "1", "--output", str(FULL)])
    assert result.exit_code == 2
    expected = "orbits: error: cannot write /dev/full: No space left on device; nothing was written"
    assert result.stderr.strip() == expected


@needs_dev_full
def test_a_plot_through_a_link_to_a_full_device_is_one_line(tmp_path):
    pytest.importorskip("matplotlib")
    link = tmp_path / "picture.png"
    link.symlink_to(FULL)
    result = runner.invoke(app, ["orbit", "Earth", "--only", "period", "--plot", str(link)])
    assert result.exit_code == 2 and len(result.stderr.strip().splitlines()) == 1
    assert "No space left on device" in result.stderr and link.is_symlink() and leftovers(tmp_path) == []


def test_an_output_through_a_link_writes_the_target(tmp_path):
    target, link = tmp_path / "report.json", tmp_path / "link.json"
    target.write_text("old")
    link.symlink_to(target)
    result = runner.invoke(app, ["bench", "api", "--sizes", "1", "--repeats", "1", "--output", str(link)])
    assert result.exit_code == 0, result.output
    assert link.is_symlink() and target.read_text().startswith("[")


def test_a_special_target_where_no_file_can_be_made_is_refused_in_one_line():
    result = runner.invoke(app, ["bench", "api", "--sizes", "1", "--repeats", "1", "--output", "/proc/version"])
    assert result.exit_code == 2 and result.stdout == ""
    assert "no file can be made in the folder /proc" in result.stderr and len(result.stderr.splitlines()) == 1
