"""A result in a Jupyter notebook: the tables the command line prints for it, as HTML.

Every result's ``_repr_html_`` (:class:`balance_cli.tabular.Tabular`) comes here, through the
renderer the package's root sets. A result that a command prints is rendered by that
command's own tables, as its ``--format markdown`` gives them with the command's default
units, and the Markdown becomes HTML here: one renderer per command, the one the command line
uses, so the notebook cannot show other figures than the terminal. A result no command prints
on its own (a power related unbalance, a torque series, guide forces, every cylinder's torque)
is shown as its records.

The Markdown read here is what this package's tables write, nothing more: headings (``#``),
pipe tables, paragraphs with ``code``, lines ending in two spaces, list items (``- ``), and
backslash escapes of punctuation (:func:`~balance_cli.report.display.markdown_text`).
"""

import html
import re

from ..analysis.balancing import Balance, Balances
from ..analysis.results import Comparison, EngineResult, compare
from ..analysis.steadiness import Steadiness
from ..analysis.torque import TorqueResult, TorqueSet
from ..cranksearch.results import SearchResult
from ..mounting.decoupling import Decoupling
from ..mounting.result import MountResult
from ..studies.family import FamilyResult
from ..studies.regress import Regression
from ..studies.sweep.results import SweepGrid, SweepResult
from ..torsion.response import TorsionResult
from ..units import Scale
from ..workshop import BobweightSheet, MatchResult, ToleranceResult
from .compare import compare_tables
from .counterweight import balance_tables
from .display import figure
from .family import family_tables
from .mounts import decoupling_tables, mount_tables
from .regress import regression_tables
from .search import search_tables
from .sweeps import sweep_tables
from .torque import steadiness_text, torque_tables
from .torsion import torsion_tables
from .workshop import bobweight_tables, match_tables, tolerance_tables

__all__ = ["result_html", "command_markdown", "markdown_html", "records_html"]

_FMT = "markdown"


def _search(result):
    arrangements = [a.result for a in result.arrangements]
    comparison = compare(arrangements) if arrangements else None
    return search_tables(result, comparison, Scale.of(False), _FMT)


#: result class -> its command's tables in Markdown, with the command's default units
_COMMANDS = (
    (Comparison, lambda r: compare_tables(r, Scale.of(False), _FMT)),
    (EngineResult, lambda r: compare_tables(compare([r]), Scale.of(False), _FMT)),
    (Balances, lambda r: balance_tables(r.balances, Scale.of(False), _FMT)),
    (Balance, lambda r: balance_tables([r], Scale.of(False), _FMT)),
    (TorqueSet, lambda r: torque_tables(r.results, Scale.of(True), _FMT)),
    (TorqueResult, lambda r: torque_tables([r], Scale.of(True), _FMT)),
    (Steadiness, steadiness_text),
    (TorsionResult, lambda r: torsion_tables([r], _FMT, Scale.of(False))),
    (MountResult, lambda r: mount_tables([r], _FMT)),
    (Decoupling, lambda r: decoupling_tables([r], _FMT)),
    (SweepResult, lambda r: sweep_tables(r, _FMT)),
    (SweepGrid, lambda r: sweep_tables(r, _FMT)),
    (FamilyResult, lambda r: family_tables(r, Scale.of(True), _FMT)),
    (SearchResult, _search),
    (Regression, lambda r: regression_tables(r, _FMT, Scale.of(True))),
    (MatchResult, lambda r: match_tables(r, Scale.of(True), _FMT)),
    (ToleranceResult, lambda r: tolerance_tables(r, Scale.of(True), _FMT)),
    (BobweightSheet, lambda r: bobweight_tables(r, Scale.of(True), _FMT)),
)


def command_markdown(result) -> str | None:
    """The Markdown that the command which prints ``result`` writes (None: none prints it)."""
    for kind, tables in _COMMANDS:
        if isinstance(result, kind):
            return tables(result)
    return None


def result_html(result) -> str:
    """``result`` as HTML: its command's tables, else its records as one table."""
    text = command_markdown(result)
    body = records_html(result.records()) if text is None else markdown_html(text)
    return f'<div class="balance-result">\n{body}\n</div>'


def _cell(value):
    if value is None:
        return "—"
    if isinstance(value, float):
        return figure(value)
    return str(value)


def records_html(records) -> str:
    """Records (flat dicts) as one HTML table, a column per key, numbers to four significant
    figures."""
    if not records:
        return "<p>(no rows)</p>"
    headers = list(dict.fromkeys(key for record in records for key in record))
    rows = [[html.escape(_cell(record.get(key))) for key in headers] for record in records]
    return _html_table([html.escape(h) for h in headers], rows)


#: a backslash before ASCII punctuation is CommonMark's escape
_ESCAPE = re.compile(r"\\([!-/:-@\[-`{-~])")
#: a column separator: a pipe not escaped
_PIPE = re.compile(r"(?<!\\)\|")
#: code between backticks not escaped
_CODE = re.compile(r"(?<!\\)`([^`]*)(?<!\\)`")


def _inline(text):
    """One line of Markdown text as HTML: code spans, escapes undone, the rest escaped."""
    out, at = [], 0
    for match in _CODE.finditer(text):
        out.append(html.escape(_ESCAPE.sub(r"\1", text[at : match.start()])))
        out.append(f"<code>{html.escape(match.group(1))}</code>")
        at = match.end()
    out.append(html.escape(_ESCAPE.sub(r"\1", text[at:])))
    return "".join(out)


def _cells(line):
    return [_inline(cell.strip()) for cell in _PIPE.split(line.strip())[1:-1]]


def _table(lines):
    """A pipe table (its header, the rule of dashes, its rows) as HTML."""
    return _html_table(_cells(lines[0]), [_cells(line) for line in lines[2:]])


def _html_table(head, rows):
    """An HTML table of cells already HTML."""
    out = ["<table>", "<thead>", "<tr>" + "".join(f"<th>{c}</th>" for c in head) + "</tr>"]
    out += ["</thead>", "<tbody>"]
    out += ["<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in rows]
    return "\n".join(out + ["</tbody>", "</table>"])


def _paragraph(lines):
    # a line ending in two spaces is a line break
    parts = [
        _inline(line.rstrip()) + ("<br>" if line.endswith("  ") and i < len(lines) - 1 else "")
        for i, line in enumerate(lines)
    ]
    return "<p>" + "\n".join(parts) + "</p>"


def markdown_html(text: str) -> str:
    """The Markdown of this package's tables as HTML."""
    out = []
    for block in re.split(r"\n[ \t]*\n", text.strip("\n")):
        lines = [line for line in block.split("\n") if line.strip()]
        while lines:
            line = lines[0]
            if heading := re.match(r"(#{1,6}) (.*)", line):
                level = len(heading.group(1))
                out.append(f"<h{level}>{_inline(heading.group(2))}</h{level}>")
                lines = lines[1:]
            elif line.lstrip().startswith("|"):
                n = next((i for i, x in enumerate(lines) if not x.lstrip().startswith("|")), None)
                out.append(_table(lines[:n]))
                lines = [] if n is None else lines[n:]
            elif line.startswith("- "):
                n = next((i for i, x in enumerate(lines) if not x.startswith("- ")), None)
                items = "".join(f"<li>{_inline(x[2:])}</li>" for x in lines[:n])
                out.append(f"<ul>{items}</ul>")
                lines = [] if n is None else lines[n:]
            else:
                n = next((i for i, x in enumerate(lines[1:], 1) if _starts_block(x)), None)
                out.append(_paragraph(lines[:n]))
                lines = [] if n is None else lines[n:]
    return "\n".join(out)


def _starts_block(line):
    """A line that ends a paragraph: a heading, a table's row or a list item."""
    return bool(re.match(r"#{1,6} ", line)) or line.lstrip().startswith("|") or line[:2] == "- "
