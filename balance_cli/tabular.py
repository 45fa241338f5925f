"""Results a notebook takes directly: rows of plain values, a pandas DataFrame, an HTML table.

Every result class of balance derives from :class:`Tabular` and says what its rows are in
:meth:`Tabular.records`: one flat dict per row, every value a plain number, string, bool or
None, in SI with the unit in the key (``force_max_N``, ``moment_forward_Nm``, ``phase_deg``,
``speed_rpm``). :meth:`Tabular.to_pandas` makes a DataFrame of them (pandas is the optional
extra ``pandas``), and Jupyter shows a result as the table the command line prints for it.

That table comes from :mod:`balance_cli.report`, which sits above every result's own layer
and so cannot be imported from here. The package's root, which stands above every layer (it
re-exports them all and loads the report on demand), hands this module a renderer with
:func:`set_html_renderer` when the package is imported, before any result can exist; the
renderer imports the report only when a notebook first shows a result. The layers stay as the
import contract draws them: nothing below the report names it.
"""

import abc
from collections.abc import Callable, Iterable, Mapping

from .about import install_hint
from .errors import PandasUnavailable

__all__ = ["Tabular", "set_html_renderer", "require_pandas", "prefixed", "joined"]

#: what turns a result into HTML (set by the package's root; None: no HTML, plain repr)
_renderer: Callable[[object], str] | None = None


def set_html_renderer(renderer: Callable[[object], str] | None) -> None:
    """Make ``renderer`` (a result -> HTML text) what :meth:`Tabular._repr_html_` shows."""
    global _renderer
    _renderer = renderer


def require_pandas():
    """The pandas module; :class:`~balance_cli.errors.PandasUnavailable` (one line naming the
    extra to install) without it."""
    try:
        import pandas
    except ImportError:
        raise PandasUnavailable(
            f"to_pandas() needs pandas, which is not installed: {install_hint('pandas')} "
            "(records() gives the same rows as plain dicts without it)"
        ) from None
    return pandas


def prefixed(prefix: str, record: Mapping) -> dict:
    """``record``'s keys with ``prefix`` and an underscore before each: ``{"max_N": 1.0}``
    with "force" is ``{"force_max_N": 1.0}``."""
    return {f"{prefix}_{key}": value for key, value in record.items()}


def joined(values: Iterable, separator: str = "-") -> str:
    """A sequence as one cell of text, as the tables print it: a firing order "1-3-4-2",
    phases "0 120 240" (with ``separator`` " ")."""
    return separator.join(f"{v:g}" if isinstance(v, float) else str(v) for v in values)


class Tabular(abc.ABC):
    """A result that gives its rows: :meth:`records`, :meth:`to_pandas` and, in Jupyter, the
    table the command line prints."""

    @abc.abstractmethod
    def records(self) -> list[dict]:
        """One flat dict per row: plain values (numbers, strings, bools, None), SI, the unit
        in each key. What the rows are is the result class's own documentation."""

    def to_pandas(self):
        """:meth:`records` as a ``pandas.DataFrame``, one column per key in the records'
        order.

        Raises
        ------
        PandasUnavailable
            pandas is not installed (``pip install 'engine-balance[pandas]'``)
        """
        pandas = require_pandas()
        return pandas.DataFrame.from_records(self.records())

    def _repr_html_(self) -> str | None:
        # Jupyter's rich display: the command line's table of this result (plain repr if the
        # package's root has not set a renderer, which only a partial import could cause)
        return None if _renderer is None else _renderer(self)
