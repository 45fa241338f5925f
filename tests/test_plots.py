"""Pictures and the report: the data behind each plot, the files, the HTML page in Chromium."""

import math
import shutil
import struct
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from click.testing import CliRunner
from numpy.testing import assert_allclose

from balance_cli import analyse, load
from balance_cli.cli import _progress, main
from balance_cli.report import plot
from balance_cli.shaking import cylinder_phasors
from conftest import CONFIGS, PART3

RADIAL = PART3 / "5a-radial-9.toml"
V8 = PART3 / "1a-v8-90-flat.toml"


def run(*args):
    return CliRunner().invoke(main, list(map(str, args)))


def test_radial_secondary_locus_is_a_circle_of_its_forward_amplitude():
    """F⁺e^{2iθ} + F⁻e^{−2iθ}: the radius stays within |F⁻| of |F⁺| (F⁻ is 0.06 % of F⁺)."""
    result = analyse(load(RADIAL))
    x, y = plot.locus_points(result, order=2)
    second = result.shaking.orders[1]
    unit = result.per_cylinder_unit_n
    radius = np.hypot(x, y)
    assert_allclose(radius, abs(second.force_forward) / unit, atol=abs(second.force_backward) / unit + 1e-12)


def test_flat_crank_v8_secondary_locus_is_a_segment_across():
    result = analyse(load(V8))
    x, y = plot.locus_points(result, order=2)
    assert np.abs(y).max() < 1e-12
    assert_allclose(np.abs(x).max(), 0.21473, atol=1e-5)   # √2/2·B2, test_library
    assert x.min() < 0 < x.max()


def test_locus_leaves_out_the_forward_first_order_on_a_crankshaft_only():
    radial = analyse(load(RADIAL))
    x, y = plot.locus_points(radial)
    assert np.hypot(x, y).max() < 0.07      # the 0.5 primary is counterweighted
    rotary = analyse(load(PART3 / "5b-rotary-9.toml"))
    x, y = plot.locus_points(rotary)
    assert_allclose(np.abs(x).max(), 0.0341, atol=1e-4)   # nothing removed on a rotary


@pytest.mark.parametrize("config", ["tanaka-part3/1b-v8-90-flat-links.toml", "tanaka-part3/5a-radial-9.toml",
                                    "tanaka-part3/5b-rotary-9.toml", "bramo-323.toml",
                                    "nakanishi-w12-60-2stroke.toml"])
@pytest.mark.parametrize("order", [1, 2, 4])
def test_star_polygon_closes_on_the_resultant_of_compare(config, order):
    engine = load(CONFIGS / config)
    result = analyse(engine)
    shares = cylinder_phasors(engine, order)
    o = result.shaking.orders[order - 1]
    tol = 1e-10 * result.per_cylinder_unit_n
    assert_allclose(sum(s[1] for s in shares), o.force_forward, atol=tol)
    assert_allclose(sum(s[2] for s in shares), o.force_backward, atol=tol)
    assert {s[0] for s in shares} >= {str(c.number) for c in engine.cylinders}


def png_size(path):
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


def svg_size(path):
    root = ET.parse(path).getroot()
    assert root.tag.endswith("svg")
    return root.get("width"), root.get("height")


def expected_inches(kind, count):
    if kind == "locus":
        return 8, 8
    if kind == "spectrum":
        return 12, 8
    columns, rows = plot.grid_size(count)
    return plot.CELL_IN * columns, plot.CELL_IN * rows


@pytest.mark.parametrize("kind", plot.KINDS)
@pytest.mark.parametrize("paths, count", [([PART3], 9), ([CONFIGS], 17)])
def test_each_kind_writes_png_and_svg_of_the_expected_size(tmp_path, kind, paths, count):
    width, height = expected_inches(kind, count)
    png = tmp_path / "deep" / f"{kind}.png"
    result = run("plot", *paths, "--kind", kind, "--output", png)
    assert result.exit_code == 0, result.output
    assert png_size(png) == (int(width * plot.DPI), int(height * plot.DPI))
    svg = tmp_path / f"{kind}.svg"
    assert run("plot", *paths, "--kind", kind, "--output", svg).exit_code == 0
    assert svg_size(svg) == (f"{width * 72:g}pt", f"{height * 72:g}pt")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(["deep", f"{kind}.svg"])


def test_plot_replaces_an_existing_file_and_reports_bad_paths(tmp_path):
    target = tmp_path / "locus.png"
    target.write_bytes(b"old")
    assert run("plot", V8, "--kind", "locus", "--output", target).exit_code == 0
    assert png_size(target)
    blocker = tmp_path / "file"
    blocker.write_text("x")
    result = run("plot", V8, "--kind", "locus", "--output", blocker / "sub" / "x.png")
    assert result.exit_code == 1 and "cannot create the folder" in result.output
    assert "Traceback" not in result.output
    result = run("plot", V8, "--kind", "star", "--order", "20", "--output", tmp_path / "s.png")
    assert result.exit_code == 1 and "--order 20 is above --max-order 8" in result.output


def test_progress_bar_only_on_a_terminal(monkeypatch):
    import io
    import sys

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    with _progress([1, 2, 3], "Analysing") as bar:
        assert list(bar) == [1, 2, 3]
    assert "Analysing" in terminal.getvalue()
    quiet = io.StringIO()
    monkeypatch.setattr(sys, "stderr", quiet)
    with _progress([1, 2, 3], "Analysing") as bar:
        assert list(bar) == [1, 2, 3]
    assert quiet.getvalue() == ""


def test_report_markdown_with_relative_pictures(tmp_path):
    out = tmp_path / "report"
    result = run("report", PART3, "--output", out)
    assert result.exit_code == 0, result.output
    text = (out / "report.md").read_text(encoding="utf-8")
    for picture in ("locus.svg", "spectrum.svg", "star.svg", "firing.svg"):
        assert f"]({picture})" in text
        assert svg_size(out / picture)
    assert "| 90° V8, flat crank" in text and "## Counterweights" in text
    assert "0.2147" in text and "70.7" in text
    assert not (out / "report.html").exists()


CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
CHROME_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--enable-logging=stderr", "--v=0", "--dump-dom"]


def dump(page, profile):
    done = subprocess.run([CHROMIUM, *CHROME_FLAGS, f"--user-data-dir={profile}", page.as_uri()],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    console = [line for line in done.stderr.splitlines() if ":CONSOLE" in line]
    return done.stdout, console


@pytest.mark.skipif(CHROMIUM is None, reason="Debian's chromium is not installed (.ci/run installs it "
                                             "when the package index can be reached)")
def test_html_report_opens_in_headless_chromium_without_console_errors(tmp_path):
    # positive control: the console check does see a page's errors
    bad = tmp_path / "bad.html"
    bad.write_text('<html><body><script>console.error("boom")</script></body></html>')
    _, console = dump(bad, tmp_path / "profile-bad")
    assert any("boom" in line for line in console)

    out = tmp_path / "report"
    result = run("report", PART3, "--output", out, "--html")
    assert result.exit_code == 0, result.output
    page = out / "report.html"
    html = page.read_text(encoding="utf-8")
    assert ' src="http' not in html and ' href="http' not in html and "<script" not in html
    dom, console = dump(page, tmp_path / "profile")
    assert console == []
    assert dom.count("<table") == 4          # engines, two comparison tables, counterweights
    assert dom.count("<figure") == 4 and dom.count("<svg") >= 4
    for name in ("90° V8, flat crank", "9-cylinder rotary", "Locus of the resultant force per cylinder",
                 "Star of order 2", "Firing"):
        assert name in dom
    # the copy beside it can be moved anywhere: nothing is loaded from the folder
    moved = tmp_path / "elsewhere.html"
    shutil.copy(page, moved)
    dom_moved, console = dump(moved, tmp_path / "profile-moved")
    assert console == [] and dom_moved.count("<svg") == dom.count("<svg")
