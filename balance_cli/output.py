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

__all__ = [
    "write_text",
    "write_bytes",
    "write_folder",
    "ensure_folder",
    "check_folder",
    "refuse_inputs",
    "to_json",
    "DOCUMENT_VERSION",
    "READABLE_VERSIONS",
    "STEADINESS_VERSION",
]

#: version of the JSON documents balance writes. 2 added the vertical and horizontal
#: components, the free moments' summary and an axis of None for circles; 3 gives the power
#: related unbalance's first order under a named balance (``first_order_balance``,
#: ``first_order``) and the family's first-order moments by balance; balance regress still
#: reads baselines of versions 1 and 2 (what it compares is the same in 2 and 3)
DOCUMENT_VERSION = 3
READABLE_VERSIONS = (1, 2, 3)
#: version of the steadiness document (balance steadiness --format json), counted apart
STEADINESS_VERSION = 1


def _reason(exc):
    return exc.strerror or str(exc)


_NESTED = {dict, list, tuple}
_ONE_LINE = json.JSONEncoder(ensure_ascii=False).encode


def to_json(document):
    """A JSON document as balance writes it: indented, UTF-8 text, a final newline; an object
    or list inside it that holds only numbers and strings, or objects and lists of them (an
    order with its force and moment), stays on one line (one line per order reads better,
    and the C encoder writes those lines: the pure-Python indenting encoder took longer than
    the analysis on a library's crank-pin forces)."""
    return _encode(document, "", top=True) + "\n"


def _flat(value):
    """A container of numbers and strings only."""
    values = value.values() if type(value) is dict else value
    return _NESTED.isdisjoint(map(type, values))


def _shallow(values):
    """Numbers, strings and flat containers: what one line holds."""
    return all(type(v) not in _NESTED or _flat(v) for v in values)


def _encode(value, margin, top=False):
    kind = type(value)
    if kind is dict:
        if not top and _shallow(value.values()):
            return _ONE_LINE(value)
        inner = margin + "  "
        body = ",\n".join(
            f"{inner}{_ONE_LINE(str(k))}: {_encode(v, inner)}" for k, v in value.items()
        )
        return "{\n" + body + "\n" + margin + "}" if body else "{}"
    if kind is list or kind is tuple:
        if _NESTED.isdisjoint(map(type, value)):
            return _ONE_LINE(value)
        inner = margin + "  "
        return "[\n" + ",\n".join(inner + _encode(v, inner) for v in value) + "\n" + margin + "]"
    return _ONE_LINE(value)


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


def _destination(target) -> Path:
    """The regular file to replace for ``target``: the target itself, or what its symbolic
    links lead to. A link loop, a link into a folder that does not exist, a folder, a file
    without write permission or a name ending in a separator is an OutputError."""
    shown = str(target)
    if not shown:
        raise OutputError("the output path is empty; give a file name")
    if shown.endswith(os.sep) or Path(target).is_dir():
        raise OutputError(f"{shown!r} is a folder; give a file name")
    path = Path(target)
    if path.is_symlink():
        try:
            real = Path(os.path.realpath(path, strict=True))
        except FileNotFoundError:
            real = Path(os.path.realpath(path))
            if not real.parent.is_dir():
                raise OutputError(
                    f"{shown!r} is a link to {str(real)!r}, whose folder does not "
                    "exist; create it or write elsewhere"
                ) from None
        except OSError as exc:
            raise OutputError(f"cannot write {shown!r}: {_reason(exc)}") from None
    else:
        real = Path(os.path.realpath(path))
    if real.is_file() and (not os.access(real, os.W_OK) or not real.stat().st_mode & 0o222):
        # renaming over it would replace a file its owner made read-only (root's access() says
        # yes to every file: the mode bits say what its owner meant)
        raise OutputError(
            f"cannot write {shown!r}: the file is read-only; make it writable or write elsewhere"
        )
    return real


def write_bytes(target, write):
    """Call ``write(handle)`` on a binary file handle and put what it wrote at ``target``:
    atomically for a regular file, directly for a device or FIFO."""
    shown = str(target)
    try:
        path = Path(target)
        special = _special(path)
        real = None if special else _destination(target)
    except OutputError:
        raise
    except OSError as exc:  # a name too long, say
        raise OutputError(f"cannot write {shown!r}: {_reason(exc)}") from None
    if real is None:  # special: written in place
        try:
            with open(path, "wb") as handle:
                write(handle)
        except OSError as exc:
            raise OutputError(f"cannot write {shown!r}: {_reason(exc)}") from None
        return
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
    """Write ``text`` (UTF-8) to ``target``, all at once; ``"-"`` or None is standard output
    (in UTF-8 too, whatever the locale says)."""
    if target in (None, "-"):
        _write_stdout(text.encode("utf-8"))
        return
    write_bytes(target, lambda handle: handle.write(text.encode("utf-8")))


def check_folder(target, what="the report"):
    """Raise OutputError unless ``target`` is a folder or can become one (for ``what``)."""
    shown = str(target)
    if shown in ("", "-"):
        raise OutputError(f"{shown!r} is not a folder name; give a folder for {what}")
    try:
        if os.path.lexists(target) and not Path(target).is_dir():
            if Path(target).is_symlink() and not Path(target).exists():
                os.stat(target)  # says why the link leads nowhere (a loop, say)
            raise OutputError(f"{shown!r} is not a folder; give a folder for {what}")
    except OSError as exc:
        raise OutputError(f"cannot write into {shown!r}: {_reason(exc)}") from None


def _write_stdout(data):
    if sys.stdout is None:
        raise OutputError("standard output is closed; give an output file")
    try:
        sys.stdout.flush()
        stream = getattr(sys.stdout, "buffer", None)
        if stream is None:
            sys.stdout.write(data.decode("utf-8"))
        else:
            stream.write(data)
        sys.stdout.flush()
    except OSError as exc:
        # what could not be written must not be written again when Python exits
        try:
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        except (OSError, ValueError):
            pass
        raise OutputError(f"cannot write standard output: {_reason(exc)}") from None


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
                    raise OutputError(
                        f"cannot write {str(target / name)!r}: it is not a regular "
                        "file; move it away"
                    )
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
                raise OutputError(
                    f"{str(output)!r} is an input file ({str(source)!r}); write the "
                    "output somewhere else"
                )
