"""Writing results: standard output, or a file replaced atomically."""

import os
import sys
import tempfile
from pathlib import Path

__all__ = ["OutputError", "write_text"]


class OutputError(OSError):
    """The output file cannot be written; nothing was left behind."""


def write_text(target, text):
    """Write ``text`` to ``target`` ("-" is standard output) all at once.

    A file is written to a temporary neighbour and renamed over the target, so a reader
    never sees half a file and a failure leaves the old file (or none) in place.
    """
    if target in (None, "-"):
        sys.stdout.write(text)
        sys.stdout.flush()
        return
    path = Path(target)
    folder = path.parent
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the folder {str(folder)!r} for --output: {exc.strerror}") from None
    if path.is_dir():
        raise OutputError(f"--output {target!r} is a folder; give a file name")
    fd, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as handle:
            handle.write(text)
        os.replace(temporary, path)
    except OSError as exc:
        Path(temporary).unlink(missing_ok=True)
        raise OutputError(f"cannot write --output {target!r}: {exc.strerror}") from None
