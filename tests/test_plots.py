"""Pictures and the report: the data behind each plot, what the figures draw of it, the files,
the HTML page in Chromium. The library is analysed once per module; the command line is run
on single engines only, to check its wiring."""

import math
import os
import shutil
import subprocess
import sys

import matplotlib
import numpy as np
import pytest
from click.testing import CliRunner
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli import analyse, load, plot
from balance_cli.cli import _progress, main
from balance_cli.errors import PlotError
from balance_cli.units import STANDARD_GRAVITY
from conftest import CONFIGS, PART3

RADIAL = PART3 / "5a-radial-9.toml"
V8 = PART3 / "1a-v8-90-flat.toml"


def run(*args):
    return CliRunner().invoke(main, list(map(str, args)))


@pytest.fixture(scope="module")
def library():
    """Every engine of configs/, analysed once."""
    return [analyse(e) for e in balance.load_many([CONFIGS])]


@pytest.fixture(scope="module")
def part3():
    return {path.stem: analyse(load(path)) for path in sorted(PART3.glob("*.toml"))}


def test_radial_secondary_locus_is_a_circle_of_its_forward_amplitude(part3):
    """F⁺e^{2iθ} + F⁻e^{−2iθ}: the radius stays within |F⁻| of |F⁺| (F⁻ is 0.06 % of F⁺)."""
    result = part3["5a-radial-9"]
    x, y = plot.locus_points(result, order=2)
    second = result.order(2)
    unit = result.per_cylinder_unit_n
    assert_allclose(np.hypot(x, y), abs(second.force_forward) / unit,
                    atol=abs(second.force_backward) / unit + 1e-12)


def test_flat_crank_v8_secondary_locus_is_a_segment_across(part3):
    x, y = plot.locus_points(part3["1a-v8-90-flat"], order=2)
    assert np.abs(y).max() < 1e-12
    assert_allclose(np.abs(x).max(), 0.21473, atol=1e-5)   # √2/2·B2, test_library
    assert x.min() < 0 < x.max()


def test_locus_leaves_out_the_forward_first_order_on_a_crankshaft_only(part3):
    x, y = plot.locus_points(part3["5a-radial-9"])
    assert np.hypot(x, y).max() < 0.07      # the 0.5 primary is counterweighted
    x, y = plot.locus_points(part3["5b-rotary-9"])
    assert_allclose(np.abs(x).max(), 0.0341, atol=1e-4)   # nothing removed on a rotary


def test_locus_figure_draws_each_engines_points_with_its_own_colour(part3):
    results = list(part3.values())
    fig = plot.locus(results)
    lines = [line for line in fig.axes[0].lines if line.get_label() in {r.engine.name for r in results}]
    assert [line.get_label() for line in lines] == [r.engine.name for r in results]
    for line, result in zip(lines, results):
        x, y = plot.locus_points(result)
        assert_allclose(line.get_xdata()[:-1], x, atol=1e-15)
        assert_allclose(line.get_ydata()[:-1], y, atol=1e-15)
    assert len({line.get_color() for line in lines}) == len(lines)


def test_locus_draws_into_a_given_axes():
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    assert plot.locus([analyse(load(V8))], ax=ax) is fig and ax.lines


@pytest.mark.parametrize("config", ["tanaka-part3/1b-v8-90-flat-links.toml", "tanaka-part3/5a-radial-9.toml",
                                    "tanaka-part3/5b-rotary-9.toml", "bramo-323.toml",
                                    "nakanishi-w12-60-2stroke.toml"])
@pytest.mark.parametrize("order", [1, 2, 4])
def test_star_chain_closes_on_the_resultant_of_compare(library, config, order):
    result = next(r for r in library if r.engine.config_path.endswith(config))
    chains = plot.star_chains(result, order)
    o = result.order(order)
    unit = result.per_cylinder_unit_n
    for part, expected in (("forward", o.force_forward), ("backward", o.force_backward)):
        arrows = chains[part]
        end = arrows[-1][2] if arrows else 0j
        assert_allclose(end, expected / unit, atol=1e-10)
        # tip to tail
        for (_, _, head), (_, tail, _) in zip(arrows, arrows[1:]):
            assert head == tail
    labels = {a[0] for part in chains.values() for a in part}
    assert labels <= {str(c.number) for c in result.engine.cylinders} | {"pins"}


def test_star_figure_draws_the_chains(library):
    chosen = library[:4]
    fig = plot.star(chosen, order=2)
    for ax, result in zip(fig.axes, chosen):
        chains = plot.star_chains(result, 2)
        quivers = [c for c in ax.collections if isinstance(c, matplotlib.quiver.Quiver)]
        drawn = [part for part in ("forward", "backward") if chains[part]]
        assert len(quivers) == len(drawn)
        for quiver, part in zip(quivers, drawn):
            tails = np.array([a[1] for a in chains[part]])
            assert_allclose(quiver.X, tails.imag, atol=1e-15)    # across is horizontal
            assert_allclose(quiver.Y, tails.real, atol=1e-15)    # along is vertical
    assert [ax.axison for ax in fig.axes[len(chosen):]] == [False, False]   # a 3 × 2 grid


def test_spectrum_data_is_the_orders_of_compare_in_each_unit(library):
    """Per cylinder: |F|/(m·r·ω²·n), N·m; N: N, N·m; kgf: kgf and kgf·m (÷ 9.80665)."""
    chosen = [r for r in library if "nakanishi-v12" in r.engine.config_path]
    (result,) = chosen
    o = result.order(1)
    unit = result.per_cylinder_unit_n
    for units, force_scale, moment_scale in (("per-cylinder", 1 / unit, 1.0), ("N", 1.0, 1.0),
                                             ("kgf", 1 / STANDARD_GRAVITY, 1 / STANDARD_GRAVITY)):
        data = plot.spectrum_data(chosen, units)
        (engine,) = data["engines"]
        assert_allclose(engine["force"][0], [abs(o.force_forward) * force_scale,
                                             abs(o.force_backward) * force_scale], rtol=1e-12)
        assert_allclose(engine["moment"][0], [abs(o.moment_forward) * moment_scale,
                                              abs(o.moment_backward) * moment_scale], rtol=1e-12)
    assert plot.spectrum_data(chosen, "kgf")["moment_label"] == "free moment (kgf·m)"
    with pytest.raises(PlotError, match="units must be one of"):
        plot.spectrum_data(chosen, "lbf")


def test_spectrum_gives_every_engine_its_own_colour_and_aligns_its_panels(library):
    fig = plot.spectrum(library)
    force, moment = fig.axes
    assert force.get_xlim() == moment.get_xlim() == (0.5, 8.5)
    faces = {tuple(np.round(c.get_facecolor()[0][:3], 6)) for c in force.collections}
    assert len(faces) == len(library) == 17
    # every bar of order 1 lies inside the axis
    for ax in (force, moment):
        for collection in ax.collections:
            for path in collection.get_paths():
                assert path.vertices[:, 0].min() >= 0.5


def test_spectrum_without_free_moments_has_one_panel(part3):
    """Tanaka's Part III engines have no free moments (their cranks are symmetric)."""
    fig = plot.spectrum(part3.values())
    assert len(fig.axes) == 1
    assert "no engine has a free moment" in fig.axes[0].get_title()


def test_colours_are_distinct_for_many_engines():
    for count in (3, 10, 17, 20, 31):
        assert len({tuple(c) for c in plot.colours(count)}) == count


def test_firing_figure_draws_one_line_per_firing(library):
    chosen = [r for r in library if r.engine.cycle == 2][:1] + [library[0]]
    fig = plot.firing(chosen)
    for ax, result in zip(fig.axes, chosen):
        spokes = [line for line in ax.lines if len(line.get_xdata()) == 2]
        assert len(spokes) == result.engine.n_cylinders
        angles = sorted(math.degrees(math.atan2(line.get_xdata()[1], line.get_ydata()[1])) % 360
                        for line in spokes)
        expected = sorted(360 * a / result.engine.cycle_deg for a in result.firing.angles_deg)
        assert_allclose(angles, expected, atol=1e-9)


@pytest.mark.parametrize("name, magic", [("p.png", b"\x89PNG"), ("p.pdf", b"%PDF"),
                                         ("p.jpeg", b"\xff\xd8\xff"), ("p.svg", b"<?xml"),
                                         ("p.eps", b"%!PS"), ("P.PNG", b"\x89PNG")])
def test_save_writes_the_format_the_extension_names(tmp_path, name, magic):
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(1, 1))
    plot.save(fig, tmp_path / name)
    assert (tmp_path / name).read_bytes().startswith(magic)


@pytest.mark.parametrize("name", ["picture", "picture.gif2", "picture.txt", "picture.pgf"])
def test_save_refuses_formats_it_does_not_write(tmp_path, name):
    import matplotlib.pyplot as plt

    with pytest.raises(PlotError, match="end the file name in one of"):
        plot.save(plt.figure(), tmp_path / name)
    assert list(tmp_path.iterdir()) == []


def test_importing_the_library_and_its_plots_keeps_the_backend():
    code = ("import matplotlib; before = matplotlib.get_backend()\n"
            "import balance_cli, balance_cli.plot\n"
            "balance_cli.plot.locus([balance_cli.analyse(balance_cli.load(%r))])\n"
            "assert matplotlib.get_backend() == before, (before, matplotlib.get_backend())\n"
            "print(before)") % str(V8)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={**os.environ, "MPLBACKEND": "pdf"})
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "pdf"


@pytest.mark.parametrize("kind", plot.KINDS)
def test_plot_command_writes_each_kind(tmp_path, kind):
    out = tmp_path / "deep" / f"{kind}.svg"
    result = run("plot", V8, RADIAL, "--kind", kind, "--output", out)
    assert result.exit_code == 0, result.output
    assert out.read_bytes().startswith(b"<?xml") and b"<svg" in out.read_bytes()
    assert sorted(p.name for p in out.parent.iterdir()) == [f"{kind}.svg"]


def test_plot_command_refuses_a_format_before_computing(tmp_path, monkeypatch):
    import balance_cli.cli as cli

    monkeypatch.setattr(cli, "analyse", lambda *a: pytest.fail("analysed before refusing"))
    for name in ("pic.jpg2", "pic"):
        result = run("plot", V8, "--kind", "locus", "--output", tmp_path / name)
        assert result.exit_code == 1 and "end the file name in one of" in result.output
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("args, words", [
    (["--kind", "locus", "--units", "kgf"], "--units applies to --kind spectrum only"),
    (["--kind", "star", "--units", "N"], "--units applies to --kind spectrum only"),
    (["--kind", "spectrum", "--order", "2"], "--order applies to --kind locus and star only"),
])
def test_plot_options_that_do_not_apply_are_usage_errors(tmp_path, args, words):
    result = run("plot", V8, *args, "--output", tmp_path / "p.png")
    assert result.exit_code == 2 and words in result.output
    assert not (tmp_path / "p.png").exists()


def test_plot_replaces_an_existing_file_and_reports_bad_paths(tmp_path):
    target = tmp_path / "locus.png"
    target.write_bytes(b"old")
    assert run("plot", V8, "--kind", "locus", "--output", target).exit_code == 0
    assert target.read_bytes().startswith(b"\x89PNG")
    blocker = tmp_path / "file"
    blocker.write_text("x")
    result = run("plot", V8, "--kind", "locus", "--output", blocker / "sub" / "x.png")
    assert result.exit_code == 1 and "cannot create the folder" in result.output
    result = run("plot", V8, "--kind", "star", "--order", "20", "--output", tmp_path / "s.png")
    assert result.exit_code == 1 and "--order 20 is above --max-order 8" in result.output


def test_progress_bar_only_on_a_terminal(monkeypatch):
    import io

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
        assert (out / picture).read_bytes().startswith(b"<?xml")
    assert "| 90° V8, flat crank" in text and "## Counterweights" in text
    assert "0.2147" in text and "70.7" in text
    assert not (out / "report.html").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report"]   # no temporary left


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
