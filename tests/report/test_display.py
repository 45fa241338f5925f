"""Names in tables made safe: escaped for Markdown and HTML (only what is markup there),
their column separators kept out of the table's columns; a heading's name shortened at a word
boundary."""

import re

import pytest

from balance_cli.report.display import markdown_text
from tests.support import BOXER, CONFIGS, invoke


def test_names_are_escaped_in_markdown(tmp_path):
    boxer = tmp_path / "boxer.toml"
    boxer.write_text(BOXER, encoding="utf-8")
    markdown = invoke("compare", boxer, "--format", "markdown").stdout
    # a tag only where its < is not escaped
    assert not re.search(r"(?<!\\)<script>", markdown) and "\\<script>" in markdown
    tables, current = [], []
    for line in markdown.splitlines() + [""]:
        if line.startswith("|"):
            current.append(line)
        elif current:
            tables.append(current)
            current = []
    assert any("Flat twin \\| opposed" in row for table in tables for row in table)
    for header, _, *rows in tables:  # the | in the name does not add a column
        for row in rows:
            assert row.replace("\\|", "").count("|") == header.replace("\\|", "").count("|")
    report = tmp_path / "report"
    assert invoke("report", boxer, "-o", report, "--html").exit_code == 0
    assert not re.search(r"(?<!\\)<script>", (report / "report.md").read_text(encoding="utf-8"))
    page = (report / "report.html").read_text(encoding="utf-8")
    # the name's tag escaped everywhere; the one <script> draws the animations
    assert "<script>alert" not in page and page.count("<script>") == 1


@pytest.mark.parametrize(
    "text, markdown",
    [
        # plain text stays as it is: & and < that open no markup
        ("MAN B&W 6S80MC-C7", "MAN B&W 6S80MC-C7"),
        ("p < 5 bar & q > 2", "p < 5 bar & q > 2"),
        # what a CommonMark renderer reads as markup, escaped with a backslash
        ("a &amp; b, &#38;", "a \\&amp; b, \\&#38;"),
        ("<b>bold</b> <!-- x -->", "\\<b>bold\\</b> \\<!-- x -->"),
        ("x_y *z* [l](u) `c` a|b \\", "x\\_y \\*z\\* \\[l\\](u) \\`c\\` a\\|b \\\\"),
    ],
)
def test_markdown_escapes_only_what_is_markup(text, markdown):
    assert markdown_text(text) == markdown


def test_a_renderer_shows_the_names_as_written():
    """A second method: a CommonMark renderer (markdown-it, where installed) turns the escaped
    text back into the text as written, HTML-escaped by the renderer itself."""
    markdown_it = pytest.importorskip("markdown_it")
    render = markdown_it.MarkdownIt("commonmark").renderInline
    for text in ("MAN B&W", "a &amp; b", "<b>x</b>", "x_y *z* [l](u) `c` \\", "p < 5 & q"):
        expected = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
        assert render(markdown_text(text)) == expected


def test_family_heading_keeps_its_ampersand(tmp_path):
    """A family named "MAN B&W 6S80": its Markdown heading reads B&W, not B&amp;W."""
    text = (CONFIGS / "marine-6-2stroke.toml").read_text(encoding="utf-8")
    name = next(line for line in text.splitlines() if line.startswith("name = "))
    path = tmp_path / "bw.toml"
    path.write_text(text.replace(name, 'name = "MAN B&W 6S80"'), encoding="utf-8")
    result = invoke("family", path, "--cylinders", "6", "--format", "markdown")
    assert result.exit_code == 0, result.output
    assert result.output.startswith("#### MAN B&W 6S80: the family")
    assert "&amp;" not in result.output


def test_percent_heading_is_cut_at_a_word(tmp_path):
    """The "% of NAME" heading holds at most 24 characters of the name: whole words and "…"
    ("In-line 4, car proportions" is "In-line 4, car…", not "In-line 4, car proporti…"), or
    the whole name where its first word alone is longer."""
    rows = {}
    for name in ("In-line 4, car proportions", "Kurzschlussläuferasynchronmotor 4"):
        text = (CONFIGS / "inline-4-car.toml").read_text(encoding="utf-8")
        line = next(x for x in text.splitlines() if x.startswith("name = "))
        path = tmp_path / "engine.toml"
        path.write_text(text.replace(line, f'name = "{name}"'), encoding="utf-8")
        output = invoke("compare", path, "--format", "markdown").output
        rows[name] = next(x for x in output.splitlines() if "% of" in x)
    assert "| % of In-line 4, car…" in rows["In-line 4, car proportions"]
    assert "proporti" not in rows["In-line 4, car proportions"]
    assert "| % of Kurzschlussläuferasynchronmotor 4 " in rows["Kurzschlussläuferasynchronmotor 4"]
