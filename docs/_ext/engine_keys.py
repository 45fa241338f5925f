"""The ``engine-keys`` and ``engine-units`` directives: the configuration keys' tables and
the units they are written in, from docs/howto/engine-keys.toml checked against the reader
(see keys_table.py). A key the reader accepts that the page does not list, or the reverse, is
a warning, which ``-W`` makes an error.

The tables are built as docutils nodes, so the directives work alike in reStructuredText and
in MyST Markdown pages."""

import keys_table
from docutils import nodes
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

logger = logging.getLogger(__name__)


def _entry(text, code=False):
    text = " ".join(str(text).split())
    paragraph = nodes.paragraph()
    if not text:
        paragraph += nodes.Text("—")
    elif code:
        paragraph += nodes.literal(text, text)
    else:
        paragraph += nodes.Text(text)
    return nodes.entry("", paragraph)


def _table(header, rows, widths, code_columns):
    """A table of ``rows`` (tuples of text) under ``header``; columns in ``code_columns`` are
    set as code."""
    table = nodes.table(classes=["balance-keys"])
    group = nodes.tgroup(cols=len(header))
    table += group
    for width in widths:
        group += nodes.colspec(colwidth=width)
    head = nodes.thead()
    head += nodes.row("", *(_entry(h) for h in header))
    group += head
    body = nodes.tbody()
    for row in rows:
        body += nodes.row(
            "", *(_entry(cell, i in code_columns(row, i)) for i, cell in enumerate(row))
        )
    group += body
    return table


class EngineKeysDirective(SphinxDirective):
    """Every table of configuration format version 1 with its keys."""

    def run(self):
        documented = keys_table.tables()
        for problem in keys_table.mismatches(documented):
            logger.warning("engine keys: %s", problem, location=self.get_location())
        self.env.note_dependency(str(keys_table.DATA))
        out = []
        for table in documented:
            anchor = "keys-" + (table.path.replace("[]", "").replace(".", "-") or "top")
            out.append(nodes.rubric(table.title, table.title, ids=[anchor]))
            coded = {k.name: k.default is not None for k in table.keys.values()}

            def code_columns(row, i, coded=coded):
                # key and example are TOML; a default is when it is a value, not words
                return {0, 3} | ({2} if coded[row[0]] else set())

            out.append(
                _table(
                    ("Key", "Unit", "Default", "Example", "Meaning"),
                    keys_table.rows(table),
                    (14, 14, 16, 18, 38),
                    code_columns,
                )
            )
        return out


class UnitsDirective(SphinxDirective):
    """The dimensions the keys use, their SI unit and every unit a value may be written in."""

    def run(self):
        used = {k.kind for t in keys_table.tables() for k in t.keys.values()}
        rows = [row for row in keys_table.units_rows() if row[0] in used]
        return [
            _table(("Dimension", "SI", "Units accepted"), rows, (20, 12, 68), lambda r, i: {1, 2})
        ]
