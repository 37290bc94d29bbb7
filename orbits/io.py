"""Atomic file output: write to a temporary file in the target folder, then os.replace it."""

import os
import tempfile
from pathlib import Path


def write_atomic(path, data):
    """Write text or bytes to `path` so that readers see the old file or the whole new one, never a part."""
    path = Path(path)
    mode = "wb" if isinstance(data, bytes) else "w"
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent or ".")
    try:
        with os.fdopen(fd, mode) as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
