"""A command's output: refused before any work when it would replace an input, and written
atomically to standard output or the file of -o.
"""

from pathlib import Path

from ..output import refuse_inputs, write_text
from .group import reported

__all__ = ["guard", "same_path", "write"]


def guard(outputs, files):
    """Refuse outputs that would replace an input, before anything is computed."""
    with reported():
        refuse_inputs(outputs, files)


def same_path(a, b):
    try:
        return Path(a).resolve() == Path(b).resolve()
    except OSError:
        return False


def write(output, text):
    with reported():
        write_text(output, text)
