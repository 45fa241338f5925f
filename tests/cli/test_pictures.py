"""balance plot and balance report: the pictures and report folders they write, their options,
and the errors they report in one line."""

import importlib
import sys

import matplotlib
import pytest

from balance_cli import plot
from balance_cli.cli.batch import progress
from balance_cli.units import STANDARD_GRAVITY
from tests.support import (
    CAR_GAS,
    CONFIGS,
    RADIAL,
    TWIN,
    V8,
    check_refused,
    invoke,
    snapshot,
    twin_file,
)


@pytest.mark.parametrize("kind", plot.KINDS)
def test_plot_command_writes_each_kind(tmp_path, kind):
    out = tmp_path / "deep" / f"{kind}.svg"
    result = invoke("plot", V8, RADIAL, "--kind", kind, "--output", out)
    assert result.exit_code == 0, result.output
    assert out.read_bytes().startswith(b"<?xml") and b"<svg" in out.read_bytes()
    assert sorted(p.name for p in out.parent.iterdir()) == [f"{kind}.svg"]


def test_plot_command_refuses_a_format_before_computing(tmp_path, monkeypatch):
    from balance_cli.cli import batch

    monkeypatch.setattr(batch, "analyse", lambda *a: pytest.fail("analysed before refusing"))
    for name in ("pic.jpg2", "pic"):
        result = invoke("plot", V8, "--kind", "locus", "--output", tmp_path / name)
        assert result.exit_code == 1 and "end the file name in one of" in result.output
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "args, words",
    [
        (
            ["--kind", "star", "--units", "N"],
            "--units applies to --kind locus, spectrum and torque only",
        ),
        (
            ["--kind", "firing", "--units", "per-cylinder"],
            "--units applies to --kind locus, spectrum and torque",
        ),
        (
            ["--kind", "torque", "--units", "per-cylinder"],
            "--units per-cylinder applies to --kind locus and spectrum only",
        ),
        (["--kind", "spectrum", "--order", "2"], "--order applies to --kind locus and star only"),
        (["--kind", "torque", "--order", "2"], "--order applies to --kind locus and star only"),
        (
            ["--kind", "firing", "--of", "moment"],
            "--of applies to --kind locus and star only, not firing",
        ),
        (["--kind", "spectrum", "--of", "force"], "--of applies to --kind locus and star only"),
        (["--kind", "torque", "--of", "moment"], "--of applies to --kind locus and star only"),
    ],
)
def test_plot_options_that_do_not_apply_are_usage_errors(tmp_path, args, words):
    result = invoke("plot", V8, *args, "--output", tmp_path / "p.png")
    assert result.exit_code == 2 and words in result.output
    assert not (tmp_path / "p.png").exists()


def test_plot_replaces_an_existing_file_and_reports_bad_paths(tmp_path):
    target = tmp_path / "locus.png"
    target.write_bytes(b"old")
    assert invoke("plot", V8, "--kind", "locus", "--output", target).exit_code == 0
    assert target.read_bytes().startswith(b"\x89PNG")
    blocker = tmp_path / "file"
    blocker.write_text("x")
    result = invoke("plot", V8, "--kind", "locus", "--output", blocker / "sub" / "x.png")
    assert result.exit_code == 1 and "cannot create the folder" in result.output
    result = invoke("plot", V8, "--kind", "star", "--order", "20", "--output", tmp_path / "s.png")
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


def test_plot_command_draws_torques_as_png_and_in_kgf(tmp_path, gas_config, torques):
    out = tmp_path / "torque.png"
    result = invoke("plot", gas_config, V8, "--kind", "torque", "--output", out)
    assert result.exit_code == 0, result.output
    assert out.read_bytes().startswith(b"\x89PNG")
    # two engines: two cells of 4 in (the figure at least 8 in wide) under a 0.75 in header
    assert matplotlib.image.imread(out).shape[:2] == (475, 800)
    svg = tmp_path / "torque.svg"
    result = invoke("plot", gas_config, "--kind", "torque", "--units", "kgf", "--output", svg)
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
    result = invoke(
        "plot",
        V8,
        "--kind",
        "torque",
        "--samples",
        "64",
        "--max-order",
        "3",
        "--output",
        tmp_path / "t.svg",
    )
    assert result.exit_code == 0, result.output
    assert seen == [(64, 3)]


def test_plot_command_reports_a_torque_error_in_one_line(tmp_path, monkeypatch):
    from balance_cli.errors import AnalysisError

    def refuse(engine, *args, **kwargs):
        raise AnalysisError("cannot be computed", "engine")

    monkeypatch.setattr(importlib.import_module("balance_cli.analysis.torque"), "torque", refuse)
    out = tmp_path / "t.png"
    result = invoke("plot", V8, "--kind", "torque", "--output", out)
    assert result.exit_code == 1
    assert result.output.strip().splitlines() == [f"Error: {V8}: engine cannot be computed"]
    assert "Traceback" not in result.output and not out.exists()
    # and bad configurations and settings are refused as for the other kinds
    bad = tmp_path / "bad.toml"
    bad.write_text(
        (CONFIGS / "inline-4-car.toml").read_text(encoding="utf-8")
        + CAR_GAS.replace("compression_ratio = 10", "compression_ratio = 0.5"),
        encoding="utf-8",
    )
    monkeypatch.undo()
    for args, words in (
        ([bad], "gas.compression_ratio"),
        ([V8, "--max-order", "100"], "--samples must be"),
    ):
        result = invoke("plot", *args, "--kind", "torque", "--output", out)
        assert result.exit_code == 1 and len(result.output.strip().splitlines()) == 1, result.output
        assert words in result.output and not out.exists()


def test_plot_command_draws_moments(tmp_path, couples):
    for kind in ("locus", "star"):
        out = tmp_path / f"{kind}.svg"
        result = invoke(
            "plot",
            CONFIGS / "nakanishi-v12-90-2stroke.toml",
            "--kind",
            kind,
            "--of",
            "moment",
            "--order",
            "1",
            "--output",
            out,
        )
        assert result.exit_code == 0, result.output
        assert "free moment" in out.read_text(encoding="utf-8")


def test_plot_with_an_unknown_format(tmp_path):
    config = tmp_path / "e.toml"
    config.write_text(TWIN, encoding="utf-8")
    before = snapshot(tmp_path)
    for name in ("pic", "pic.jpeg2", "pic.pgf"):
        check_refused(
            invoke("plot", config, "--kind", "locus", "-o", tmp_path / name),
            1,
            "end the file name in one of",
            before,
            tmp_path,
        )


def test_report_that_fails_half_way_leaves_nothing_behind(tmp_path):
    config = tmp_path / "e.toml"
    config.write_text(TWIN, encoding="utf-8")
    (tmp_path / "report" / "report.md").mkdir(parents=True)
    before = snapshot(tmp_path)
    result = invoke("report", config, "-o", tmp_path / "report")
    check_refused(result, 1, "report.md': it is not a regular file", before, tmp_path)


@pytest.mark.parametrize(
    "output, words", [("-", "'-' is not a folder name"), ("", "'' is not a folder name")]
)
def test_report_needs_a_folder_name(tmp_path, output, words):
    config = twin_file(tmp_path)
    before = snapshot(tmp_path)
    check_refused(invoke("report", config, "-o", output), 1, words, before, tmp_path)


@pytest.mark.parametrize(
    "command", [["plot", "--kind", "star", "-o", "s.png"], ["report", "-o", "rep"]]
)
def test_max_order_one_draws_the_first_order_star(tmp_path, monkeypatch, command):
    monkeypatch.chdir(tmp_path)
    result = invoke(command[0], CONFIGS / "inline-4-car.toml", "--max-order", "1", *command[1:])
    assert result.exit_code == 0, result.output


def test_cli_module_keeps_the_default_backend_until_it_draws():
    import subprocess
    import sys

    code = (
        "import matplotlib, sys; from balance_cli.cli import main\n"
        "assert 'matplotlib.pyplot' not in sys.modules\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


def test_plot_locus_takes_units(tmp_path):
    """--units on the locus: any system, N too, draws absolute forces (the values are
    tests/plot/test_loci.py's); written as SVG, its axis label names the unit."""
    target = tmp_path / "locus.svg"
    result = invoke("plot", V8, "--kind", "locus", "--units", "N", "--output", target)
    assert result.exit_code == 0, result.output
    text = target.read_text(encoding="utf-8")
    assert "across the reference axis (N)" in text and "per cylinder" not in text
