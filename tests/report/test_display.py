"""Names in tables made safe: escaped for Markdown and HTML, their column separators kept
out of the table's columns."""

from tests.support import BOXER, invoke


def test_names_are_escaped_in_markdown(tmp_path):
    boxer = tmp_path / "boxer.toml"
    boxer.write_text(BOXER, encoding="utf-8")
    markdown = invoke("compare", boxer, "--format", "markdown").stdout
    assert "<script>" not in markdown and "&lt;script&gt;" in markdown
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
    assert "<script>" not in (report / "report.md").read_text(encoding="utf-8")
    assert "<script>" not in (report / "report.html").read_text(encoding="utf-8")
