"""The report (report.md and report.html): its pictures, tables and warnings, and the page in
headless Chromium."""

import shutil
import subprocess

import pytest
from numpy.testing import assert_allclose

from tests.support import CONFIGS, PART3, V8, invoke

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
CHROME_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--enable-logging=stderr",
    "--v=0",
    "--dump-dom",
]


def dump(page, profile):
    done = subprocess.run(
        [CHROMIUM, *CHROME_FLAGS, f"--user-data-dir={profile}", page.as_uri()],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    console = [line for line in done.stderr.splitlines() if ":CONSOLE" in line]
    return done.stdout, console


def markdown_table(text, heading):
    """The rows of the first table after ``heading`` in a Markdown document, as lists of cells."""
    lines = text[text.index(heading) :].splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("|"))
    rows = []
    for line in lines[start + 2 :]:
        if not line.startswith("|"):
            break
        rows.append([cell.strip() for cell in line.strip("|").split("|")])
    return lines[start], rows


def test_report_markdown_with_relative_pictures(tmp_path):
    out = tmp_path / "report"
    result = invoke("report", PART3, "--output", out)
    assert result.exit_code == 0, result.output
    text = (out / "report.md").read_text(encoding="utf-8")
    for picture in ("locus.svg", "spectrum.svg", "star.svg", "firing.svg", "torque.svg"):
        assert f"]({picture})" in text
        assert (out / picture).read_bytes().startswith(b"<?xml")
    assert "| 90° V8, flat crank" in text and "## Counterweights" in text
    assert "0.2147" in text and "70.7" in text
    assert not (out / "report.html").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report"]  # no temporary left


@pytest.mark.skipif(
    CHROMIUM is None,
    reason="Debian's chromium is not installed (.ci/run installs it "
    "when the package index can be reached)",
)
def test_html_report_opens_in_headless_chromium_without_console_errors(tmp_path):
    # positive control: the console check does see a page's errors
    bad = tmp_path / "bad.html"
    bad.write_text('<html><body><script>console.error("boom")</script></body></html>')
    _, console = dump(bad, tmp_path / "profile-bad")
    assert any("boom" in line for line in console)

    out = tmp_path / "report"
    result = invoke("report", PART3, "--output", out, "--html")
    assert result.exit_code == 0, result.output
    page = out / "report.html"
    html = page.read_text(encoding="utf-8")
    assert ' src="http' not in html and ' href="http' not in html
    # one script, which draws every engine's animation from its data (JSON, not a script)
    assert html.count("<script>") == 1
    assert html.count('<script type="application/json" class="balance-animation-data">') == 9
    dom, console = dump(page, tmp_path / "profile")
    assert console == []
    assert dom.count('class="ba-views"') == 9
    # engines; forces, firing and the summary (Part III has no free moment, so no moment
    # table); counterweights, torques and reduced mass: every table report.md has
    tables = (out / "report.md").read_text(encoding="utf-8").count("\n|:-")
    assert dom.count("<table") == tables == 7
    assert dom.count("<figure") == 5 and dom.count("<svg") >= 5
    for name in (
        "90° V8, flat crank",
        "9-cylinder rotary",
        "Locus of the resultant force per cylinder",
        "Star of order 2",
        "Firing",
        "Torques",
        "Reduced mass",
    ):
        assert name in dom
    # the copy beside it can be moved anywhere: nothing is loaded from the folder
    moved = tmp_path / "elsewhere.html"
    shutil.copy(page, moved)
    dom_moved, console = dump(moved, tmp_path / "profile-moved")
    assert console == [] and dom_moved.count("<svg") == dom.count("<svg")


def test_report_torque_bearings_left_out_change_no_torque(torques):
    from balance_cli.analysis.torque import torque

    result = torques[0]
    light = torque(result.engine, bearings=False)
    assert light.pins == () and light.main_bearings is None and result.pins
    for name in ("inertia", "gas", "total", "frame", "tilting"):
        assert_allclose(getattr(light, name).curve, getattr(result, name).curve, rtol=0, atol=0)
    assert_allclose(light.reduced_mass.curve_kgm2, result.reduced_mass.curve_kgm2, rtol=0, atol=0)


def test_report_has_a_torque_table_picture_and_reduced_mass(tmp_path, gas_config, torques):
    out = tmp_path / "report"
    result = invoke("report", gas_config, V8, "--output", out, "--html")
    assert result.exit_code == 0, result.output
    text = (out / "report.md").read_text(encoding="utf-8")
    assert "## Torques" in text and "](torque.svg)" in text
    assert (out / "torque.svg").read_bytes().startswith(b"<?xml")
    assert 'id="torque.svg"' in (out / "report.html").read_text(encoding="utf-8")
    header, rows = markdown_table(text, "## Torques")
    assert "Mean (N·m)" in header and "Range ΔC (N·m)" in header
    table, engine = {}, None
    for cells in rows:
        engine = cells[0] or engine
        table[engine, cells[1]] = cells[2:]
    assert len(rows) == 8 and table["90° V8, flat crank", "gas"] == ["—"] * 4
    for result in torques[:2]:
        for name in ("inertia", "gas", "total", "frame"):
            series = getattr(result, name)
            if series is None:
                continue
            shown = [float(v.replace(" ", "")) for v in table[result.engine.name, name]]
            # four significant figures: half a unit of the fourth is at most 5e-4 of the value
            assert_allclose(
                shown, [series.mean, series.max, series.min, series.range], rtol=5e-4, atol=1e-12
            )
    # the mean total torque of the engine with gas: imep·V/(4π), about 191 N·m
    assert table["In-line 4, car, with gas", "total"][0] == f"{torques[0].total.mean:.4g}"
    assert 185 < torques[0].total.mean < 195
    header, rows = markdown_table(text, "Reduced mass μ")
    assert [r[0] for r in rows] == ["In-line 4, car, with gas", "90° V8, flat crank"]
    for cells, result in zip(rows, torques, strict=False):
        mu = result.reduced_mass
        assert_allclose(
            [float(c) for c in cells[1:]],
            [mu.mean_kgm2, mu.min_kgm2, mu.max_kgm2],
            rtol=1e-4,
            atol=0,
        )


def test_a_report_says_when_samples_are_too_few(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = invoke(
        "report",
        CONFIGS / "inline-4-marine.toml",
        "-o",
        "rep",
        "--samples",
        "16",
        "--max-order",
        "3",
    )
    assert result.exit_code == 0, result.output
    text = (tmp_path / "rep" / "report.md").read_text(encoding="utf-8")
    assert "1 engine, 16 samples" in text
    assert "Warning: 16 samples a revolution are too few for In-line 4 marine" in text
    assert "warning:" in result.stderr and "wrote rep/report.md" in result.stderr
    assert result.stdout == ""
