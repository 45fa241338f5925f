"""What every picture shares: colours, files in the format their name says, the backend left
alone, the orders analysed, grids wide enough for their titles."""

import os
import subprocess
import sys

import pytest

import balance_cli as balance
from balance_cli import plot
from balance_cli.errors import PlotError
from tests.support import CONFIGS, V8


def test_colours_are_distinct_for_many_engines():
    for count in (3, 10, 17, 20, 31):
        assert len({tuple(c) for c in plot.colours(count)}) == count


@pytest.mark.parametrize(
    "name, magic",
    [
        ("p.png", b"\x89PNG"),
        ("p.pdf", b"%PDF"),
        ("p.jpeg", b"\xff\xd8\xff"),
        ("p.svg", b"<?xml"),
        ("p.eps", b"%!PS"),
        ("P.PNG", b"\x89PNG"),
    ],
)
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
    code = (
        "import matplotlib; before = matplotlib.get_backend()\n"
        "import balance_cli, balance_cli.plot\n"
        f"balance_cli.plot.locus([balance_cli.analyse(balance_cli.load({str(V8)!r}))])\n"
        "assert matplotlib.get_backend() == before, (before, matplotlib.get_backend())\n"
        "print(before)"
    )
    done = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        env={**os.environ, "MPLBACKEND": "pdf"},
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "pdf"


def test_plot_order_outside_the_analysis_is_a_plot_error():
    result = balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"), max_order=2)
    for call in (
        lambda: balance.plot.star([result], order=3),
        lambda: balance.plot.locus([result], order=0),
        lambda: balance.plot.star_chains(result, 5),
    ):
        with pytest.raises(balance.PlotError, match="is not among the orders analysed"):
            call()


def test_a_single_engine_grid_picture_is_wide_enough_for_its_title():
    result = balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"))
    for draw in (balance.plot.star, balance.plot.firing):
        width, _ = draw([result]).get_size_inches()
        assert width == balance.plot.MIN_WIDTH_IN
