"""Pictures and the report: the data behind each plot, what the figures draw of it, the files,
the HTML page in Chromium. The library is analysed once per module; the command line is run
on single engines only, to check its wiring."""

import importlib
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
from balance_cli.cli import main
from balance_cli.cli.batch import progress
from balance_cli.errors import PlotError
from balance_cli.units import STANDARD_GRAVITY
from tests.support import CONFIGS, PART3

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
    assert len(fig.axes) == len(chosen)   # the empty cells of the grid get no axes


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
    # 1 lbf·ft = 0.45359237 kg × 9.80665 m/s² × 0.3048 m
    assert plot.spectrum_data(chosen, "lbf")["moment_label"] == "free moment (lbf·ft)"
    assert_allclose(plot.spectrum_data(chosen, "lbf")["engines"][0]["moment"],
                    plot.spectrum_data(chosen, "N")["engines"][0]["moment"]
                    / (0.45359237 * 9.80665 * 0.3048), rtol=1e-12)
    with pytest.raises(PlotError, match="units must be one of"):
        plot.spectrum_data(chosen, "dyn")


def test_spectrum_gives_every_engine_its_own_colour_and_aligns_its_panels(library):
    fig = plot.spectrum(library)
    force, moment = fig.axes
    assert force.get_xlim() == moment.get_xlim() == (0.5, 8.5)
    # over both panels: an engine may have bars in one only (the MAN B&W 7S80MC-C7, an in-line
    # seven, has no free force below the 14th order, only moments), or none above the panels'
    # floors, and then no colour on the axes: in configs/today the flat 12 has nothing in any
    # order and the boxer 6 only a sixth-order couple of 0.17 N·m, under the moment floor
    faces = {tuple(np.round(c.get_facecolor()[0][:3], 6))
             for ax in (force, moment) for c in ax.collections}
    data = plot.spectrum_data(library, "per-cylinder")
    shown = [e for e in data["engines"]
             if (e["force"][:8] > data["force_floor"]).any() or (e["moment"][:8] > data["moment_floor"]).any()]
    assert len(library) == len(balance.find_configs([CONFIGS]))
    hidden = {e["name"] for e in data["engines"]} - {e["name"] for e in shown}
    assert hidden == {"Flat 12, 180° V (Ferrari 512 BB)", "Boxer 6 (Porsche 9A1 3.8)"}
    assert len(faces) == len(shown) == len(library) - 2
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


def test_firing_figure_draws_one_spoke_per_firing(library):
    """The spokes are one line broken at NaN: (0, 0) to the rim, once per firing."""
    chosen = [r for r in library if r.engine.cycle == 2][:1] + [library[0]]
    fig = plot.firing(chosen)
    for ax, result in zip(fig.axes, chosen):
        (line,) = [line for line in ax.lines if np.isnan(line.get_xdata()).any()]
        xs, ys = np.asarray(line.get_xdata()).reshape(-1, 3), np.asarray(line.get_ydata()).reshape(-1, 3)
        assert len(xs) == result.engine.n_cylinders
        assert not xs[:, 0].any() and not ys[:, 0].any() and np.isnan(xs[:, 2]).all()
        angles = sorted(math.degrees(math.atan2(x, y)) % 360 for x, y in zip(xs[:, 1], ys[:, 1]))
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
    from balance_cli.cli import batch

    monkeypatch.setattr(batch, "analyse", lambda *a: pytest.fail("analysed before refusing"))
    for name in ("pic.jpg2", "pic"):
        result = run("plot", V8, "--kind", "locus", "--output", tmp_path / name)
        assert result.exit_code == 1 and "end the file name in one of" in result.output
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("args, words", [
    (["--kind", "locus", "--units", "kgf"], "--units applies to --kind spectrum and torque only"),
    (["--kind", "star", "--units", "N"], "--units applies to --kind spectrum and torque only"),
    (["--kind", "firing", "--units", "per-cylinder"], "--units applies to --kind spectrum and torque"),
    (["--kind", "torque", "--units", "per-cylinder"], "--units per-cylinder applies to --kind spectrum only"),
    (["--kind", "spectrum", "--order", "2"], "--order applies to --kind locus and star only"),
    (["--kind", "torque", "--order", "2"], "--order applies to --kind locus and star only"),
    (["--kind", "firing", "--of", "moment"], "--of applies to --kind locus and star only, not firing"),
    (["--kind", "spectrum", "--of", "force"], "--of applies to --kind locus and star only"),
    (["--kind", "torque", "--of", "moment"], "--of applies to --kind locus and star only"),
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
    with progress([1, 2, 3], "Analysing") as bar:
        assert list(bar) == [1, 2, 3]
    assert "Analysing" in terminal.getvalue()
    quiet = io.StringIO()
    monkeypatch.setattr(sys, "stderr", quiet)
    with progress([1, 2, 3], "Analysing") as bar:
        assert list(bar) == [1, 2, 3]
    assert quiet.getvalue() == ""


def test_report_markdown_with_relative_pictures(tmp_path):
    out = tmp_path / "report"
    result = run("report", PART3, "--output", out)
    assert result.exit_code == 0, result.output
    text = (out / "report.md").read_text(encoding="utf-8")
    for picture in ("locus.svg", "spectrum.svg", "star.svg", "firing.svg", "torque.svg"):
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
    # engines; forces, firing and the summary (Part III has no free moment, so no moment
    # table); counterweights, torques and reduced mass: every table report.md has
    tables = (out / "report.md").read_text(encoding="utf-8").count("\n|:-")
    assert dom.count("<table") == tables == 7
    assert dom.count("<figure") == 5 and dom.count("<svg") >= 5
    for name in ("90° V8, flat crank", "9-cylinder rotary", "Locus of the resultant force per cylinder",
                 "Star of order 2", "Firing", "Torques", "Reduced mass"):
        assert name in dom
    # the copy beside it can be moved anywhere: nothing is loaded from the folder
    moved = tmp_path / "elsewhere.html"
    shutil.copy(page, moved)
    dom_moved, console = dump(moved, tmp_path / "profile-moved")
    assert console == [] and dom_moved.count("<svg") == dom.count("<svg")


# --- torques: the picture (balance plot --kind torque) and the report's section -------------

GAS = """
[gas]
bore = "86 mm"
compression_ratio = 10
imep = "12 bar"
"""


@pytest.fixture(scope="module")
def gas_config(tmp_path_factory):
    """The car's in-line four with a [gas] cycle: a four-stroke with gas and half orders."""
    text = (CONFIGS / "inline-4-car.toml").read_text(encoding="utf-8")
    path = tmp_path_factory.mktemp("gas") / "inline-4-gas.toml"
    path.write_text(text.replace('name = "In-line 4, car proportions"',
                                 'name = "In-line 4, car, with gas"') + GAS, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def torques(gas_config):
    """A four-stroke with gas, a four-stroke without and a two-stroke, in that order."""
    from balance_cli.analysis.torque import torque

    return [torque(load(path)) for path in (gas_config, V8, CONFIGS / "inline-4-marine.toml",
                                            CONFIGS / "nakanishi-w12-60-2stroke.toml")]


def torque_artists(fig, label):
    from matplotlib.lines import Line2D

    return [a for a in fig.artists if isinstance(a, Line2D) and a.get_label() == label]


def test_torque_data_is_the_torque_in_each_unit(torques):
    result = torques[0]
    for units, scale in (("N", 1.0), ("kgf", 1 / STANDARD_GRAVITY)):
        data = plot.torque_data(result, units)
        assert_allclose(data["theta_deg"][:-1], result.total.theta_deg, rtol=0, atol=1e-12)
        assert data["theta_deg"][-1] == 720.0 == data["period_deg"]
        for name in ("inertia", "gas", "total"):
            curve = getattr(result, name).curve
            assert_allclose(data[name][:-1], curve * scale, rtol=1e-12, atol=0)
            assert data[name][-1] == data[name][0]                    # closed over the cycle
        assert_allclose(data["mean"], result.total.mean * scale, rtol=1e-12)
        assert_allclose(data["orders"], 0.5 * np.arange(1, 17), rtol=0, atol=0)
        assert_allclose(data["amplitudes"], [math.hypot(c, s) * scale for _, c, s in result.total.orders],
                        rtol=1e-12, atol=0)
        assert data["unit"] == ("N·m" if units == "N" else "kgf·m")
    assert plot.torque_data(torques[1])["gas"] is None
    with pytest.raises(PlotError, match="units must be one of N, kN, MN, kgf, lbf"):
        plot.torque_data(result, "per-cylinder")
    with pytest.raises(PlotError, match="needs at least one"):
        plot.torque([])


@pytest.mark.parametrize("units, scale", [("N", 1.0), ("kgf", 1 / STANDARD_GRAVITY)])
def test_torque_figure_draws_each_engines_torques_mean_and_orders(torques, units, scale):
    fig = plot.torque(torques, units)
    totals, inertias = torque_artists(fig, "total"), torque_artists(fig, "inertia")
    means, gases = torque_artists(fig, "mean total"), torque_artists(fig, "gas")
    assert len(totals) == len(inertias) == len(means) == len(torques) and len(gases) == 1
    assert_allclose(gases[0].get_ydata()[:-1], torques[0].gas.curve * scale, rtol=1e-12, atol=0)
    bars = [a for a in fig.artists if a.get_label() == "orders"]
    # the two-stroke W12's total has no order up to 8 above the noise floor: no bars drawn
    assert len(bars) == 3 and not any(math.hypot(c, s) for _, c, s in torques[3].total.orders)
    for result, total, inertia, mean in zip(torques, totals, inertias, means):
        assert_allclose(total.get_xdata()[:-1], result.total.theta_deg, rtol=0, atol=1e-12)
        assert total.get_xdata()[-1] == result.period_deg
        assert_allclose(total.get_ydata()[:-1], result.total.curve * scale, rtol=1e-12, atol=0)
        assert_allclose(inertia.get_ydata()[:-1], result.inertia.curve * scale, rtol=1e-12, atol=0)
        assert_allclose(mean.get_ydata(), [result.total.mean * scale] * 2, rtol=1e-12, atol=0)
    for result, patch in zip(torques, bars):
        # closed rectangles from 0 up to each order's amplitude, centred on the order
        corners = patch.get_path().vertices.reshape(-1, 5, 2)[:, :4]
        expected = [(k, math.hypot(c, s) * scale) for k, c, s in result.total.orders if c or s]
        assert_allclose(corners[:, :, 0].mean(axis=1), [k for k, _ in expected], rtol=0, atol=1e-12)
        assert_allclose(corners[:, :, 1].max(axis=1), [a for _, a in expected], rtol=1e-12, atol=0)
        assert_allclose(corners[:, :, 1].min(axis=1), 0.0, rtol=0, atol=0)
    labels = next(a for a in fig.artists if isinstance(a, plot.torques._Labels)).texts()
    assert f"torque ({'N·m' if units == 'N' else 'kgf·m'})" in labels
    assert {"0°", "360°", "720°", "180°", "no order up to 8"} <= set(labels)


def test_torque_figure_keeps_each_engine_in_its_cell_below_its_title(torques, library):
    """No title overlaps another, none leaves the figure, and each engine's curves stay in its
    column of the grid, below its own title (17 engines: 3 columns, 6 rows)."""
    from balance_cli.analysis.torque import torque

    for chosen in (torques, [torque(r.engine, bearings=False) for r in library]):
        fig = plot.torque(chosen)
        renderer = fig.canvas.get_renderer()
        columns, rows = plot.grid_size(len(chosen))
        titles = [t for t in fig.texts if "-stroke" in t.get_text()]
        assert len(titles) == len(chosen)
        boxes = [t.get_window_extent(renderer) for t in titles]
        for i, box in enumerate(boxes):
            assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1 and box.y1 <= fig.bbox.y1
            assert not any(box.overlaps(other) for other in boxes[i + 1:])
        for index, (total, box) in enumerate(zip(torque_artists(fig, "total"), boxes)):
            points = total.get_transform().transform(np.column_stack([total.get_xdata(),
                                                                      total.get_ydata()]))
            column = index % columns
            assert fig.bbox.width * column / columns < points[:, 0].min()
            assert points[:, 0].max() < fig.bbox.width * (column + 1) / columns
            assert points[:, 1].max() < box.y0
        import matplotlib.pyplot as plt

        plt.close(fig)


def test_plot_command_draws_torques_as_png_and_in_kgf(tmp_path, gas_config, torques):
    out = tmp_path / "torque.png"
    result = run("plot", gas_config, V8, "--kind", "torque", "--output", out)
    assert result.exit_code == 0, result.output
    assert out.read_bytes().startswith(b"\x89PNG")
    # two engines: two cells of 4 in (the figure at least 8 in wide) under a 0.75 in header
    assert matplotlib.image.imread(out).shape[:2] == (475, 800)
    svg = tmp_path / "torque.svg"
    result = run("plot", gas_config, "--kind", "torque", "--units", "kgf", "--output", svg)
    assert result.exit_code == 0, result.output
    text = svg.read_text(encoding="utf-8")
    assert "torque (kgf·m)" in text and "mean 19.46 kgf·m" in text
    assert f"{torques[0].total.mean / STANDARD_GRAVITY:.4g}" == "19.46"


def test_plot_command_torques_respect_samples_and_max_order(tmp_path, monkeypatch):
    # the module (the package's attribute balance_cli.analysis.torque may be the function)
    torque_module = importlib.import_module("balance_cli.analysis.torque")
    seen = []
    real = torque_module.torque

    def spy(engine, samples, max_order, *args, **kwargs):
        seen.append((samples, max_order))
        return real(engine, samples, max_order, *args, **kwargs)

    monkeypatch.setattr(torque_module, "torque", spy)
    result = run("plot", V8, "--kind", "torque", "--samples", "64", "--max-order", "3",
                 "--output", tmp_path / "t.svg")
    assert result.exit_code == 0, result.output
    assert seen == [(64, 3)]


def test_plot_command_reports_a_torque_error_in_one_line(tmp_path, monkeypatch):
    from balance_cli.errors import AnalysisError

    def refuse(engine, *args, **kwargs):
        raise AnalysisError("cannot be computed", "engine")

    monkeypatch.setattr(importlib.import_module("balance_cli.analysis.torque"), "torque", refuse)
    out = tmp_path / "t.png"
    result = run("plot", V8, "--kind", "torque", "--output", out)
    assert result.exit_code == 1
    assert result.output.strip().splitlines() == [f"Error: {V8}: engine cannot be computed"]
    assert "Traceback" not in result.output and not out.exists()
    # and bad configurations and settings are refused as for the other kinds
    bad = tmp_path / "bad.toml"
    bad.write_text((CONFIGS / "inline-4-car.toml").read_text(encoding="utf-8")
                   + GAS.replace("compression_ratio = 10", "compression_ratio = 0.5"), encoding="utf-8")
    monkeypatch.undo()
    for args, words in (([bad], "gas.compression_ratio"), ([V8, "--max-order", "100"], "--samples must be")):
        result = run("plot", *args, "--kind", "torque", "--output", out)
        assert result.exit_code == 1 and len(result.output.strip().splitlines()) == 1, result.output
        assert words in result.output and not out.exists()


def test_report_torque_bearings_left_out_change_no_torque(torques):
    from balance_cli.analysis.torque import torque

    result = torques[0]
    light = torque(result.engine, bearings=False)
    assert light.pins == () and light.main_bearings is None and result.pins
    for name in ("inertia", "gas", "total", "frame", "tilting"):
        assert_allclose(getattr(light, name).curve, getattr(result, name).curve, rtol=0, atol=0)
    assert_allclose(light.reduced_mass.curve_kgm2, result.reduced_mass.curve_kgm2, rtol=0, atol=0)


def markdown_table(text, heading):
    """The rows of the first table after ``heading`` in a Markdown document, as lists of cells."""
    lines = text[text.index(heading):].splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("|"))
    rows = []
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        rows.append([cell.strip() for cell in line.strip("|").split("|")])
    return lines[start], rows


def test_report_has_a_torque_table_picture_and_reduced_mass(tmp_path, gas_config, torques):
    out = tmp_path / "report"
    result = run("report", gas_config, V8, "--output", out, "--html")
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
            assert_allclose(shown, [series.mean, series.max, series.min, series.range],
                            rtol=5e-4, atol=1e-12)
    # the mean total torque of the engine with gas: imep·V/(4π), about 191 N·m
    assert table["In-line 4, car, with gas", "total"][0] == f"{torques[0].total.mean:.4g}"
    assert 185 < torques[0].total.mean < 195
    header, rows = markdown_table(text, "Reduced mass μ")
    assert [r[0] for r in rows] == ["In-line 4, car, with gas", "90° V8, flat crank"]
    for cells, result in zip(rows, torques):
        mu = result.reduced_mass
        assert_allclose([float(c) for c in cells[1:]], [mu.mean_kgm2, mu.min_kgm2, mu.max_kgm2],
                        rtol=1e-4, atol=0)


# --- couples: plot --of moment, and labels that stay readable --------------------------------

def inline_toml(name, phases, pitch_mm, cycle=2, banks=(0,)):
    """An engine with reciprocating masses only (1 kg, r = 50 mm, 3000 rpm), one throw per
    phase, ``pitch_mm`` apart: m·r·ω² = 1·0.05·(100π)² N."""
    text = (f'name = "{name}"\ncycle = {cycle}\nspeed = "3000 rpm"\ncrank_radius = "50 mm"\n'
            'rod_length = "200 mm"\n\n[masses]\nreciprocating = "1 kg"\n')
    text += "".join(f"\n[[banks]]\nangle = {b}\n" for b in banks)
    return text + "".join(f'\n[[throws]]\nphase = {p}\nz = "{j * pitch_mm} mm"\n'
                          for j, p in enumerate(phases))


MRW2 = 1.0 * 0.05 * (3000 * math.pi / 30) ** 2      # m·r·ω², N
PITCH = 0.1                                          # d, m


@pytest.fixture(scope="module")
def couples(tmp_path_factory):
    """An in-line 3 (throws 0/120/240°), a 180° twin and a cross-plane 90° V8 (throws 0, 90,
    270, 180°), all 100 mm apart; and an in-line 24 two-stroke with throws 105° apart in turn,
    which has free moments of every order (a crowded star)."""
    folder = tmp_path_factory.mktemp("couples")
    engines = {"inline-3": inline_toml("In-line 3", [0, 120, 240], 100),
               "twin": inline_toml("180° twin", [0, 180], 100, cycle=4),
               "v8-cross": inline_toml("90° V8, cross-plane", [0, 90, 270, 180], 100, cycle=4,
                                       banks=(-45, 45)),
               "inline-24": inline_toml("In-line 24", [(105 * j) % 360 for j in range(24)], 90)}
    results = {}
    for key, text in engines.items():
        path = folder / f"{key}.toml"
        path.write_text(text, encoding="utf-8")
        results[key] = analyse(load(path))
    return results


def test_inline_3_moment_star_chains_each_cylinders_lever_times_its_force(couples):
    """Cylinder i at z_i = (i − 1)·d, z̄ = d, primary force m·r·ω²·cos(θ + β_i) along the axis
    (exact for a plain rod without pin offset): forward share (z_i − z̄)·m·r·ω²/2·e^{iβ_i},
    backward the conjugate. The chain ends at the primary couple, √3/2·m·r·ω²·d each way, √3·
    m·r·ω²·d at most (issue 17's figure); cylinder 2, on z̄, has no share."""
    result = couples["inline-3"]
    chains = plot.star_chains(result, 1, of="moment")
    for part, sign in (("forward", 1), ("backward", -1)):
        arrows = chains[part]
        assert [label for label, _, _ in arrows] == ["1", "3"]
        expected = {"1": -PITCH * MRW2 / 2, "3": PITCH * MRW2 / 2 * np.exp(sign * 1j * math.radians(240))}
        for label, tail, head in arrows:
            assert_allclose(head - tail, expected[label], rtol=1e-12, atol=1e-9)
        for (_, _, head), (_, tail, _) in zip(arrows, arrows[1:]):
            assert head == tail
        end = arrows[-1][2]
        assert_allclose(abs(end), math.sqrt(3) / 2 * MRW2 * PITCH, rtol=1e-12)
        moment = result.order(1).moment_forward if part == "forward" else result.order(1).moment_backward
        assert_allclose(end, moment, rtol=1e-12, atol=1e-9)


def test_inline_3_moment_locus_is_all_pitching_until_the_counterweight_turns_half_of_it(couples):
    """Without a counterweight the primary couple M⁺e^{iθ} + M⁻e^{−iθ}, M⁻ = conj(M⁺), is real:
    a segment along the reference axis (pitching) of half-length √3·m·r·ω²·d; an ideal
    two-plane counterweight cancels M⁺ and leaves the circle of radius |M⁻| = √3/2·m·r·ω²·d."""
    result = couples["inline-3"]
    theta = 2 * np.pi * np.arange(4 * result.samples) / (4 * result.samples)
    x, y = plot.locus_points(result, 1, of="moment", counterweight=False)
    assert_allclose(x, 0.0, atol=1e-9)
    # Σ (z_i − z̄)·m·r·ω²·cos(θ + β_i) = m·r·ω²·d·(cos(θ + 240°) − cos θ),
    # of amplitude √3·m·r·ω²·d
    assert_allclose(y, MRW2 * PITCH * (np.cos(theta + math.radians(240)) - np.cos(theta)),
                    rtol=0, atol=1e-9)
    assert_allclose(np.abs(y).max(), math.sqrt(3) * MRW2 * PITCH, rtol=1e-5)   # sampled peak
    x, y = plot.locus_points(result, 1, of="moment")
    assert_allclose(np.hypot(x, y), math.sqrt(3) / 2 * MRW2 * PITCH, rtol=1e-12)


def test_twin_moment_locus_of_order_1_is_a_segment_of_half_length_m_r_w2_d(couples):
    """At θ the first-order forces are m·r·ω²·cos θ at z = 0 and −m·r·ω²·cos θ at z = d, about
    z̄ = d/2: M(θ) = −m·r·ω²·d·cos θ along the axis, forward and backward m·r·ω²·d/2 each. The
    ideal counterweight takes the forward half: a circle of radius m·r·ω²·d/2."""
    result = couples["twin"]
    theta = 2 * np.pi * np.arange(4 * result.samples) / (4 * result.samples)
    x, y = plot.locus_points(result, 1, of="moment", counterweight=False)
    assert_allclose(y, -MRW2 * PITCH * np.cos(theta), rtol=0, atol=1e-9)
    assert_allclose(x, 0.0, rtol=0, atol=1e-9)
    x, y = plot.locus_points(result, 1, of="moment")
    assert_allclose(np.hypot(x, y), MRW2 * PITCH / 2, rtol=1e-12)
    # all orders: a 180° twin's even orders are in phase at both cylinders, so their couples
    # cancel; the odd ones beyond the first are zero for a plain rod (its motion has none)
    x_all, y_all = plot.locus_points(result, of="moment", counterweight=False)
    assert_allclose(y_all, y_all.real, atol=0)
    assert_allclose(y_all, -MRW2 * PITCH * np.cos(theta), rtol=0, atol=1e-8)


def test_cross_plane_v8_primary_couple_is_all_forward_and_the_counterweight_leaves_none(couples):
    """√10·m·r·ω²·d (issue 17; each throw's two cylinders 90° apart make a rotating force
    m·r·ω²), all forward: the star's forward chain ends there, the backward one at zero, and
    after the ideal counterweight the first-order moment locus is nothing."""
    result = couples["v8-cross"]
    chains = plot.star_chains(result, 1, of="moment")
    assert_allclose(abs(chains["forward"][-1][2]), math.sqrt(10) * MRW2 * PITCH, rtol=1e-12)
    backward = chains["backward"][-1][2] if chains["backward"] else 0j
    assert abs(backward) < result.engine.noise_floor_nm
    x, y = plot.locus_points(result, 1, of="moment")
    assert not x.any() and not y.any()
    fig = plot.locus([result], 1, of="moment")
    assert fig.axes[0].lines[0].get_label() == "90° V8, cross-plane (no free moment)"


@pytest.mark.parametrize("config", ["nakanishi-v12-90-2stroke.toml", "nakanishi-w12-60-2stroke.toml",
                                    "bramo-323.toml", "inline-12.toml"])
@pytest.mark.parametrize("order", [1, 2])
def test_moment_star_closes_on_the_free_moment_of_compare(library, config, order):
    result = next(r for r in library if r.engine.config_path.endswith(config))
    chains = plot.star_chains(result, order, of="moment")
    o = result.order(order)
    for part, expected in (("forward", o.moment_forward), ("backward", o.moment_backward)):
        arrows = chains[part]
        end = arrows[-1][2] if arrows else 0j
        assert_allclose(end, expected, rtol=0, atol=1e3 * result.engine.noise_floor_nm)


def test_moment_star_and_locus_figures_draw_the_moment_in_n_m(couples):
    result = couples["inline-3"]
    fig = plot.star([result], order=1, of="moment")
    (ax,) = [a for a in fig.axes if a.axison or a.collections]
    quivers = [c for c in ax.collections if isinstance(c, matplotlib.quiver.Quiver)]
    tails = np.array([a[1] for a in plot.star_chains(result, 1, of="moment")["forward"]])
    assert_allclose(quivers[0].X, tails.imag, atol=1e-12)
    assert_allclose(quivers[0].Y, tails.real, atol=1e-12)
    texts = [t.get_text() for t in ax.texts]
    assert f"forward: |Σ| = {math.sqrt(3) / 2 * MRW2 * PITCH:.4g} N·m" in texts
    assert "free moment" in fig._suptitle.get_text()
    assert plot.stars._magnitude(4980395.12, "N·m") == "4 980 395 N·m"
    assert (plot.stars._magnitude(427.3664, "N·m") == "427.4 N·m"
            and plot.stars._magnitude(0.0, "N·m") == "0 N·m")
    fig = plot.locus([result], of="moment")
    assert "free moment" in fig.axes[0].get_title() and "N·m" in fig.axes[0].get_xlabel()
    x, y = plot.locus_points(result, of="moment")
    assert_allclose(fig.axes[0].lines[0].get_ydata()[:-1], y, atol=0)
    for call in (lambda: plot.locus([result], of="torque"), lambda: plot.star_chains(result, 1, "couple"),
                 lambda: plot.locus_points(result, of="Moment")):
        with pytest.raises(PlotError, match="of must be one of force, moment"):
            call()


@pytest.mark.parametrize("of", ["force", "moment"])
@pytest.mark.parametrize("order", [1, 2, 4])   # a plain rod has no third order
def test_star_labels_of_24_cylinders_do_not_overlap(couples, of, order):
    """The labels the renderer draws (not the placement's estimate) overlap no other label and
    no picture's title, lie inside the figure, each beside its own arrow; the longest arrows
    of each chain are labelled."""
    result = couples["inline-24"]
    fig = plot.star([result, couples["inline-3"]], order=order, of=of)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    ax = fig.axes[0]
    labels = [t for t in ax.texts if t.get_gid() == "cylinder label"]
    boxes = [t.get_window_extent(renderer) for t in labels]
    chains = plot.star_chains(result, order, of)
    arrows = chains["forward"] + chains["backward"]
    assert len(labels) >= 12
    for i, box in enumerate(boxes):
        assert not any(box.overlaps(other) for other in boxes[i + 1:]), labels[i].get_text()
        assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1
        assert fig.bbox.y0 <= box.y0 and box.y1 <= fig.bbox.y1
        for other in fig.texts + [a.title for a in fig.axes] + [t for t in ax.texts if t.get_gid() is None]:
            if other.get_text():
                assert not box.overlaps(other.get_window_extent(renderer))
    # beside its arrow: the label's centre within its size plus 3 points of the segment
    points = 72.0 / fig.dpi
    for label, box in zip(labels, boxes):
        centre = np.array([(box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2])
        near = []
        for name, tail, head in arrows:
            if name != label.get_text():
                continue
            p, q = (ax.transData.transform((z.imag, z.real)) for z in (tail, head))
            t = np.clip(np.dot(centre - p, q - p) / np.dot(q - p, q - p), 0, 1)
            near.append(np.linalg.norm(centre - (p + t * (q - p))))
        assert min(near) <= max(box.width, box.height) + 3 / points
    for part in ("forward", "backward"):
        longest = max(chains[part], key=lambda a: abs(a[2] - a[1]))[0]
        assert longest in {t.get_text() for t in labels}


def test_place_labels_refuses_overlaps_and_skips_short_segments():
    """Twelve segments crossing at one point, as the spokes of a star: each placed label box
    is clear of every other, the spoke shorter than ``shortest`` gets none."""
    angles = np.radians(np.arange(12) * 30)
    segments = [((0.0, 0.0), (60 * math.cos(a), 60 * math.sin(a))) for a in angles]
    segments.append(((0.0, 0.0), (2.0, 0.0)))
    sizes = [(8.0, 9.0)] * len(segments)
    centres = plot.place_labels(segments, sizes, shortest=5.0)
    assert centres[-1] is None and all(c is not None for c in centres[:-1])
    boxes = [(x - 4, y - 4.5, x + 4, y + 4.5) for x, y in centres[:-1]]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3])


def test_locus_legend_of_many_engines_lies_below_the_axes(library):
    fig = plot.locus(library)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    (legend,) = fig.legends
    box, axes = legend.get_window_extent(renderer), fig.axes[0].get_tightbbox(renderer)
    assert box.y1 <= axes.y0 and box.y0 >= fig.bbox.y0
    assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1
    assert len(legend.get_texts()) == len(library) > 10


def test_spectrum_legend_lies_below_the_panels_and_leaves_them_the_width(library):
    fig = plot.spectrum(library)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    (legend,) = fig.legends
    box = legend.get_window_extent(renderer)
    lowest = min(ax.get_tightbbox(renderer).y0 for ax in fig.axes)
    assert box.y1 <= lowest and box.y0 >= fig.bbox.y0
    for ax in fig.axes:
        assert ax.get_window_extent(renderer).width >= 0.85 * fig.bbox.width


def test_torque_order_axis_labels_whole_orders_and_ticks_half_orders(torques):
    """Orders to 8: every whole order labelled 1..8; a four-stroke's half orders are ticks
    without labels (short marks in the frames' path)."""
    fig = plot.torque(torques[:1])
    labels = next(a for a in fig.artists if isinstance(a, plot.torques._Labels))
    order_labels = [item[2] for item in labels.items if item[2].isdigit() and item[3] == "center"]
    assert order_labels == [str(k) for k in range(1, 9)]
    assert not any(".5" in item[2] for item in labels.items)
    data = plot.torque_data(torques[0])
    assert_allclose(data["orders"], 0.5 * np.arange(1, 17), atol=0)


def test_plot_command_draws_moments(tmp_path, couples):
    for kind in ("locus", "star"):
        out = tmp_path / f"{kind}.svg"
        result = run("plot", CONFIGS / "nakanishi-v12-90-2stroke.toml", "--kind", kind, "--of", "moment",
                     "--order", "1", "--output", out)
        assert result.exit_code == 0, result.output
        assert "free moment" in out.read_text(encoding="utf-8")


def test_star_titles_of_long_names_stay_apart(couples, tmp_path):
    """Names cut to 60 characters wrap onto two lines instead of running into the next
    picture's title; an engine with no moment says so."""
    from dataclasses import replace

    results = [analyse(replace(couples[key].engine, name=couples[key].engine.name
                               + " with a very long descriptive name for the design review"))
               for key in ("inline-3", "twin", "v8-cross")]
    fig = plot.star(results + [analyse(load(RADIAL))], order=1, of="moment")
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    titles = [ax.title for ax in fig.axes if ax.title.get_text()]
    assert len(titles) == 4 and all("\n" in t.get_text() for t in titles[:3])
    boxes = [t.get_window_extent(renderer) for t in titles]
    for i, box in enumerate(boxes):
        assert not any(box.overlaps(other) for other in boxes[i + 1:])
        assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1
        sums = [t.get_window_extent(renderer) for t in fig.axes[i].texts if "|Σ|" in t.get_text()]
        assert len(sums) == 2 and not any(box.overlaps(s) for s in sums)
    assert "no free moment of order 1" in [t.get_text() for t in fig.axes[3].texts]
