"""File output: targets checked before any work, regular files replaced atomically, special files written in place.

A regular file is written to a temporary file in its folder and then os.replace'd over the target, so that
readers see the old file or the whole new one. A special file that already exists (a FIFO, /dev/null, a
terminal) is never replaced: it is opened and written in place.
"""

import os
import stat
import tempfile
from pathlib import Path

from orbits.core.errors import OrbitDomainError


def check_target(path: str | os.PathLike, name: str = "output file") -> Path:
    """The path, once it is known to be writable: a non-empty path that is not a folder, whose folder exists and
    can be written (or an existing special file); OrbitDomainError naming `name` otherwise. Call it before a
    long run, so that a bad target fails at once."""
    text = os.fspath(path)
    if not text.strip():
        raise OrbitDomainError(f"{name}: the path is empty; give a file name")
    target = Path(text)
    if target.is_dir():
        raise OrbitDomainError(f"{name}: {text} is a folder; give a file name")
    if target.exists() and not target.is_file():
        if not os.access(target, os.W_OK):
            raise OrbitDomainError(f"{name}: {text} cannot be written")
        return target  # a special file: written in place
    folder = target.parent
    if not folder.is_dir():
        raise OrbitDomainError(f"{name}: the folder {folder} does not exist")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise OrbitDomainError(f"{name}: the folder {folder} cannot be written")
    return target


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def write_atomic(path: str | os.PathLike, data: str | bytes) -> None:
    """Write text or bytes to `path` so that readers see the old file or the whole new one, never a part.

    The file gets the usual permissions (0o666 less the umask), not mkstemp's private 0o600.
    """
    path = Path(path)
    mode = "wb" if isinstance(data, bytes) else "w"
    if path.exists() and not stat.S_ISREG(path.stat().st_mode) and not path.is_dir():
        with open(path, mode) as handle:  # a FIFO, /dev/null, a terminal: written in place, never replaced
            handle.write(data)
        return
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent or ".")
    try:
        os.fchmod(fd, 0o666 & ~_umask())
        with os.fdopen(fd, mode) as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
