"""Writing results: standard output, or a file replaced atomically."""

import os
import sys
import tempfile
from pathlib import Path

__all__ = ["OutputError", "write_text", "write_bytes", "ensure_folder"]


class OutputError(OSError):
    """The output file cannot be written; nothing was left behind."""


def ensure_folder(folder):
    """Create ``folder`` and its parents; a clear OutputError if that cannot be done."""
    folder = Path(folder)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the folder {str(folder)!r}: {exc.strerror or exc}") from None
    if not folder.is_dir():
        raise OutputError(f"{str(folder)!r} is not a folder")
    return folder


def write_bytes(target, write):
    """Call ``write(handle)`` on a binary temporary file beside ``target``, then rename it
    over ``target``: a reader never sees half a file, a failure leaves nothing behind."""
    path = Path(target)
    folder = ensure_folder(path.parent)
    if path.is_dir():
        raise OutputError(f"{str(target)!r} is a folder; give a file name")
    fd, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=folder)
    try:
        # mkstemp makes the file private; give it the permissions any new file would have
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        with os.fdopen(fd, "wb") as handle:
            write(handle)
        os.replace(temporary, path)
    except BaseException as exc:
        Path(temporary).unlink(missing_ok=True)
        if isinstance(exc, OSError):
            raise OutputError(f"cannot write {str(target)!r}: {exc.strerror or exc}") from None
        raise


def write_text(target, text):
    """Write ``text`` to ``target`` ("-" is standard output) all at once, atomically."""
    if target in (None, "-"):
        sys.stdout.write(text)
        sys.stdout.flush()
        return
    write_bytes(target, lambda handle: handle.write(text.encode("utf-8")))
