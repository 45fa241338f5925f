"""Pictures drawn by the command line: the headless backend chosen, and a font's missing
characters said in one line.
"""

import contextlib
import warnings

import click

__all__ = ["use_agg", "drawing"]


def use_agg():
    """Draw without a display: the command line's choice of backend, not the library's."""
    import matplotlib

    matplotlib.use("Agg")


@contextlib.contextmanager
def drawing():
    """matplotlib warns once per character its font lacks (a name in Chinese, an emoji):
    one line says so instead."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.filterwarnings("always", message=r"Glyph \d+ .*missing from font")
        yield
    missing = [w for w in caught if "missing from font" in str(w.message)]
    if missing:
        click.echo(
            f"warning: the pictures' font lacks {len(missing)} characters of the engine "
            "names; they are drawn as boxes",
            err=True,
        )
    for w in caught:
        if w not in missing:
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)
