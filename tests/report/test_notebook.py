"""A result in Jupyter shows the table the command line prints: the HTML's tables hold the
same cells as the command's plain-text output, names stay text (no markup gets through), a
result no command prints shows its records, and the report is loaded only when a notebook
first shows a result."""

import math
import re
import subprocess
import sys
from html.parser import HTMLParser

import numpy as np
import pytest

import balance_cli as balance
from balance_cli import tabular
from balance_cli.report.display import figure
from balance_cli.report.notebook import result_html
from tests.support import BOXER, CONFIGS, ROOT, invoke

CAR = CONFIGS / "inline-4-car.toml"


class Tables(HTMLParser):
    """The text of an HTML page's headings and tables (rows of cells), and every tag seen."""

    def __init__(self, text):
        super().__init__()
        self.tables, self.headings, self.tags, self._cell, self._heading = [], [], set(), None, None
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        self.tags.add(tag)
        if tag == "table":
            self.tables.append([])
        elif tag == "tr":
            self.tables[-1].append([])
        elif tag in ("td", "th"):
            self._cell = ""
        elif re.fullmatch(r"h\d", tag):
            self._heading = ""

    def handle_endtag(self, tag):
        if tag in ("td", "th"):
            self.tables[-1][-1].append(self._cell)
            self._cell = None
        elif re.fullmatch(r"h\d", tag):
            self.headings.append(self._heading)
            self._heading = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell += data
        if self._heading is not None:
            self._heading += data


def plain_tables(text):
    """The tables of a command's plain-text output ("simple" format: a dashed rule under the
    header, columns two spaces or more apart), as rows of cells."""
    lines, tables = text.splitlines(), []
    for i, line in enumerate(lines):
        if i and re.fullmatch(r"-+( +-+)*", line):
            rows = [lines[i - 1]]
            for row in lines[i + 1 :]:
                if not row.strip():
                    break
                rows.append(row)
            tables.append([re.split(r"\s{2,}", row.strip()) for row in rows])
    return tables


@pytest.mark.parametrize(
    ("analysis", "command"),
    [
        (lambda e: balance.analyse(e, max_order=4), ("compare", CAR, "--max-order", "4")),
        (
            lambda e: balance.counterweights(e, max_order=4),
            ("counterweight", CAR, "--max-order", "4"),
        ),
        (lambda e: balance.torque(e, max_order=4), ("torque", CAR, "--max-order", "4")),
    ],
    ids=["compare", "counterweight", "torque"],
)
def test_the_html_holds_the_tables_the_command_prints(analysis, command):
    result = analysis(balance.load(CAR))
    page = Tables(result._repr_html_())
    printed = invoke(*command)
    assert printed.exit_code == 0, printed.output
    tables = plain_tables(printed.stdout)
    assert tables and len(page.tables) == len(tables)
    for html_table, text_table in zip(page.tables, tables, strict=True):
        assert html_table == text_table
    for heading in page.headings:  # the Markdown's headings are the text's title lines
        assert heading in printed.stdout


def test_the_compare_html_shows_the_in_line_fours_secondary_by_hand():
    """An in-line four's secondaries are in phase: per cylinder (in m_rec·r·ω²·n) the second
    order is the piston's own second harmonic over r·ω², A₂ ≈ λ + λ³/4 (an FFT of x''(θ)
    differentiated by hand, r = 43 mm and l = 143 mm as the file gives them), shown to four
    figures."""
    engine = balance.load(CAR)
    r, rod = engine.crank_radius_m, engine.rod_length_m
    theta = np.arange(4096) * 2 * math.pi / 4096
    s = np.sqrt(rod**2 - r**2 * np.sin(theta) ** 2)
    x2 = (
        -r * np.cos(theta)
        - r**2 * np.cos(2 * theta) / s
        - r**4 * (np.sin(2 * theta) / 2) ** 2 / s**3
    )
    a2 = 2 * abs(np.fft.rfft(x2)[2] / 4096) / r
    page = Tables(balance.analyse(engine, max_order=4)._repr_html_())
    forces = page.tables[0]
    header = forces[0]
    row = next(r for r in forces[1:] if r[header.index("Order")] == "2")
    assert row[header.index("F max (per cyl)")] == figure(a2)


def test_a_name_stays_text_in_the_html(tmp_path):
    """A name with a column separator and a script tag: its cell holds it as written, the
    table keeps its columns, and no script element reaches the page."""
    engine = balance.loads(BOXER)
    text = result_html(balance.analyse(engine, max_order=2))
    page = Tables(text)
    assert "script" not in page.tags and "<script>" not in text
    cells = [row[0] for table in page.tables for row in table[1:]]
    assert engine.name in cells
    for table in page.tables:
        assert len({len(row) for row in table}) == 1


def test_a_result_no_command_prints_shows_its_records():
    torques = balance.torque(balance.load(CAR), max_order=4)
    for result in (torques.total, torques.guide):
        page = Tables(result._repr_html_())
        (table,) = page.tables
        records = result.records()
        assert table[0] == list(records[0])
        assert len(table) == len(records) + 1
        second = next(i for i, r in enumerate(records) if r["order"] == 2.0) + 1
        key = next(k for k in records[0] if k.startswith("amplitude"))
        assert table[second][table[0].index(key)] == figure(records[second - 1][key])
    empty = balance.analyse(balance.load(CAR), max_order=2).power_related_unbalance()
    assert "(no rows)" in empty._repr_html_()


def test_without_a_renderer_jupyter_falls_back_to_the_plain_repr(monkeypatch):
    monkeypatch.setattr(tabular, "_renderer", None)
    assert balance.analyse(balance.load(CAR), max_order=2)._repr_html_() is None


def test_the_report_loads_when_a_notebook_first_shows_a_result():
    code = (
        "import sys, balance_cli as b\n"
        f"r = b.analyse(b.load({str(CAR)!r}), max_order=2)\n"
        "assert 'balance_cli.report' not in sys.modules\n"
        "assert r._repr_html_().startswith('<div class=\"balance-result\">')\n"
        "assert 'balance_cli.report.notebook' in sys.modules\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, cwd=ROOT)
