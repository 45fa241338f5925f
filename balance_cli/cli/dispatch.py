"""A command's output: refused before any work when it would replace an input, rendered in
the format asked for (a table or Markdown, CSV, JSON of the result's ``to_dict()``, JUnit XML),
and written atomically to standard output or the file of -o.
"""

from pathlib import Path

from ..output import refuse_inputs, to_json, write_text
from .group import reported

__all__ = ["guard", "same_path", "render", "write", "emit"]


def guard(outputs, files):
    """Refuse outputs that would replace an input, before anything is computed."""
    with reported():
        refuse_inputs(outputs, files)


def same_path(a, b):
    try:
        return Path(a).resolve() == Path(b).resolve()
    except OSError:
        return False


def render(fmt, *, json, table, csv=None, junit=None):
    """A result's text in the format ``fmt``: JSON of the document ``json()`` gives (the
    result's ``to_dict()``), ``csv()``, ``junit()`` (JUnit XML), or ``table()`` for a table
    or Markdown; only the one asked for is called."""
    if fmt == "json":
        return to_json(json())
    if fmt == "csv":
        return csv()
    if fmt == "junit":
        return junit()
    return table()


def write(output, text):
    with reported():
        write_text(output, text)


def emit(output, fmt, *, json, table, csv=None, junit=None):
    """A result rendered in the format ``fmt`` (as :func:`render` does) and written to
    ``output``."""
    write(output, render(fmt, json=json, table=table, csv=csv, junit=junit))
