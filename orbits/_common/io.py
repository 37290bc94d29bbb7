"""File output, the one home of every written file (`--output`, `--plot`): targets checked before any work, regular
files replaced atomically, special files written in place, links followed.

A regular file is written to a temporary file in its folder and then os.replace'd over the target, so that
readers see the old file or the whole new one. A special file that already exists (a FIFO, /dev/null, a
terminal) is never replaced: it is opened and written in place. A symbolic link is followed to its target, which
is written (the link stays a link). A write that fails (a full disk, /dev/full, a folder where files cannot be
created such as /proc) raises OutputError with one line, and leaves no temporary file behind.
"""

import os
import stat
import tempfile
from pathlib import Path

from orbits.core.errors import OrbitDomainError, OutputError


def _resolved(path: str | os.PathLike) -> Path:
    """The file a path writes to: symbolic links followed (the last one may point at a file yet to be made)."""
    return Path(os.path.realpath(os.fspath(path)))


def _is_special(target: Path) -> bool:
    """An existing file that is neither a regular file nor a folder: a FIFO, a device, a socket."""
    try:
        mode = target.stat().st_mode
    except OSError:
        return False
    return not (stat.S_ISREG(mode) or stat.S_ISDIR(mode))


def check_target(path: str | os.PathLike, name: str = "output file") -> Path:
    """The path, once it is known to be writable: a non-empty path that is not a folder, whose folder exists and
    takes a new file (tried, then removed), or an existing special file that can be written; OrbitDomainError
    naming `name` otherwise. Call it before a long run, so that a bad target fails at once."""
    text = os.fspath(path)
    if not text.strip():
        raise OrbitDomainError(f"{name}: the path is empty; give a file name")
    target = _resolved(text)
    if target.is_dir():
        raise OrbitDomainError(f"{name}: {text} is a folder; give a file name")
    if _is_special(target):
        if not os.access(target, os.W_OK):
            raise OrbitDomainError(f"{name}: {text} cannot be written")
        return Path(text)  # a special file: written in place
    folder = target.parent
    if not folder.is_dir():
        raise OrbitDomainError(f"{name}: the folder {folder} does not exist")
    try:
        fd, probe = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    except OSError as err:
        raise OrbitDomainError(f"{name}: no file can be made in the folder {folder} ({_reason(err)})") from None
    os.close(fd)
    os.unlink(probe)
    return Path(text)


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _reason(err: OSError) -> str:
    """The system's reason for an OSError in a few words: "No space left on device"."""
    return err.strerror or type(err).__name__


def write_atomic(path: str | os.PathLike, data: str | bytes) -> None:
    """Write text or bytes to `path` so that readers see the old file or the whole new one, never a part.

    A link is followed and its target written. The file gets the usual permissions (0o666 less the umask), not
    mkstemp's private 0o600. OutputError (one line) if the file cannot be written; no temporary file is left.
    """
    target = _resolved(path)
    mode = "wb" if isinstance(data, bytes) else "w"
    try:
        if _is_special(target):
            with open(target, mode) as handle:  # a FIFO, /dev/null, a terminal: written in place, never replaced
                handle.write(data)
            return
        _replace(target, data, mode)
    except OSError as err:
        raise OutputError(f"cannot write {os.fspath(path)}: {_reason(err)}; nothing was written") from None


def _replace(target: Path, data: str | bytes, mode: str) -> None:
    """Write a temporary file beside `target`, then move it over the target in one step (removed on any failure)."""
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    try:
        os.fchmod(fd, 0o666 & ~_umask())
        with os.fdopen(fd, mode) as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
