"""Writing results: standard output, a file replaced atomically, or a folder moved in whole.

A regular file (or a new one) is written to a temporary file beside it and renamed over it,
so a reader never sees half a file and a failure leaves nothing behind; a symbolic link is
written through (its target is replaced, the link stays). A path that is not a regular file
(a device such as /dev/null, a FIFO, /dev/stdout) is written directly. Every failure is one
:class:`OutputError` naming the path.
"""

import json
import os
import shutil
import stat
import sys
import tempfile
from pathlib import Path

from .errors import OutputError

__all__ = ["write_text", "write_bytes", "write_folder", "ensure_folder", "check_folder",
           "refuse_inputs", "to_json"]


def _reason(exc):
    return exc.strerror or str(exc)


def to_json(document):
    """A JSON document as balance writes it: indented, UTF-8 text, a final newline."""
    return json.dumps(document, indent=2, ensure_ascii=False) + "\n"


def ensure_folder(folder):
    """Create ``folder`` and its parents; a clear OutputError if that cannot be done."""
    folder = Path(folder)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the folder {str(folder)!r}: {_reason(exc)}") from None
    if not folder.is_dir():
        raise OutputError(f"{str(folder)!r} is not a folder")
    return folder


def _umask():
    umask = os.umask(0)
    os.umask(umask)
    return umask


def _mode_for(existing):
    """Permissions for a replacement: those of the file replaced, else what a new file gets."""
    try:
        return stat.S_IMODE(os.stat(existing).st_mode)
    except OSError:
        return 0o666 & ~_umask()


def _special(path):
    """True when ``path`` exists and is not a regular file or a folder (a device, a FIFO)."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return False
    return not stat.S_ISREG(mode) and not stat.S_ISDIR(mode)


def write_bytes(target, write):
    """Call ``write(handle)`` on a binary file handle and put what it wrote at ``target``:
    atomically for a regular file, directly for a device or FIFO."""
    path = Path(target)
    shown = str(target)
    if path.is_dir():
        raise OutputError(f"{shown!r} is a folder; give a file name")
    if _special(path):
        try:
            with open(path, "wb") as handle:
                write(handle)
        except OSError as exc:
            raise OutputError(f"cannot write {shown!r}: {_reason(exc)}") from None
        return
    real = Path(os.path.realpath(path))
    folder = ensure_folder(real.parent)
    try:
        # a short name: a legal file name of 250 characters must still leave room for it
        fd, temporary = tempfile.mkstemp(prefix=".bal", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise OutputError(f"cannot write {shown!r}: {_reason(exc)}") from None
    try:
        os.chmod(temporary, _mode_for(real))
        with os.fdopen(fd, "wb") as handle:
            write(handle)
        os.replace(temporary, real)
    except BaseException as exc:
        Path(temporary).unlink(missing_ok=True)
        if isinstance(exc, OSError):
            raise OutputError(f"cannot write {shown!r}: {_reason(exc)}") from None
        raise


def write_text(target, text):
    """Write ``text`` (UTF-8) to ``target``, all at once; ``"-"`` or None is standard output."""
    if target in (None, "-"):
        sys.stdout.write(text)
        sys.stdout.flush()
        return
    write_bytes(target, lambda handle: handle.write(text.encode("utf-8")))


def check_folder(target):
    """Raise OutputError when ``target`` exists and is not a folder."""
    if Path(target).exists() and not Path(target).is_dir():
        raise OutputError(f"{str(target)!r} is not a folder; give a folder for the report")


def write_folder(target, fill):
    """Fill a new temporary folder beside ``target`` with ``fill(folder)`` (which returns the
    names of the files it wrote), then move those files into ``target``: a folder that does not
    exist yet appears whole; in one that does, nothing is replaced until every file is ready
    and no destination is a folder. Returns the paths written in ``target``."""
    target = Path(target)
    check_folder(target)
    real = Path(os.path.realpath(target))
    parent = ensure_folder(real.parent)
    try:
        temporary = Path(tempfile.mkdtemp(prefix=".bal", suffix=".tmp", dir=parent))
    except OSError as exc:
        raise OutputError(f"cannot write into {str(parent)!r}: {_reason(exc)}") from None
    try:
        names = list(fill(temporary))
        if not real.exists():
            os.chmod(temporary, 0o777 & ~_umask())  # mkdtemp made it private
            os.rename(temporary, real)
        else:
            for name in names:
                destination = real / name
                if destination.is_dir() or _special(destination):
                    raise OutputError(f"cannot write {str(target / name)!r}: it is not a regular "
                                      "file; move it away")
            for name in names:
                os.replace(temporary / name, os.path.realpath(real / name))
            temporary.rmdir()
    except BaseException as exc:
        shutil.rmtree(temporary, ignore_errors=True)
        if isinstance(exc, OSError) and not isinstance(exc, OutputError):
            raise OutputError(f"cannot write {str(target)!r}: {_reason(exc)}") from None
        raise
    return [target / name for name in names]


def _same(a, b):
    try:
        return os.path.samefile(a, b)
    except OSError:
        return os.path.realpath(a) == os.path.realpath(b)


def refuse_inputs(outputs, inputs):
    """Raise OutputError when an output path is (or resolves to) one of the input files: a
    result must never replace the data it was computed from."""
    for output in outputs:
        if output in (None, "-"):
            continue
        for source in inputs:
            if _same(output, source):
                raise OutputError(f"{str(output)!r} is an input file ({str(source)!r}); write the "
                                  "output somewhere else")
