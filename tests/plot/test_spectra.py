"""The spectrum picture: every order's forward and backward amplitudes, forces and moments."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli import plot
from balance_cli.errors import PlotError
from balance_cli.units import STANDARD_GRAVITY
from tests.support import CONFIGS


def test_spectrum_data_is_the_orders_of_compare_in_each_unit(library):
    """Per cylinder: |F|/(m·r·ω²·n), N·m; N: N, N·m; kgf: kgf and kgf·m (÷ 9.80665)."""
    chosen = [r for r in library if "nakanishi-v12" in r.engine.config_path]
    (result,) = chosen
    o = result.order(1)
    unit = result.per_cylinder_unit_n
    for units, force_scale, moment_scale in (
        ("per-cylinder", 1 / unit, 1.0),
        ("N", 1.0, 1.0),
        ("kgf", 1 / STANDARD_GRAVITY, 1 / STANDARD_GRAVITY),
    ):
        data = plot.spectrum_data(chosen, units)
        (engine,) = data["engines"]
        assert_allclose(
            engine["force"][0],
            [abs(o.force_forward) * force_scale, abs(o.force_backward) * force_scale],
            rtol=1e-12,
        )
        assert_allclose(
            engine["moment"][0],
            [abs(o.moment_forward) * moment_scale, abs(o.moment_backward) * moment_scale],
            rtol=1e-12,
        )
    assert plot.spectrum_data(chosen, "kgf")["moment_label"] == "free moment (kgf·m)"
    # 1 lbf·ft = 0.45359237 kg × 9.80665 m/s² × 0.3048 m
    assert plot.spectrum_data(chosen, "lbf")["moment_label"] == "free moment (lbf·ft)"
    assert_allclose(
        plot.spectrum_data(chosen, "lbf")["engines"][0]["moment"],
        plot.spectrum_data(chosen, "N")["engines"][0]["moment"] / (0.45359237 * 9.80665 * 0.3048),
        rtol=1e-12,
    )
    with pytest.raises(PlotError, match="units must be one of"):
        plot.spectrum_data(chosen, "dyn")


def test_spectrum_gives_every_engine_its_own_colour_and_aligns_its_panels(library):
    fig = plot.spectrum(library)
    force, moment = fig.axes
    assert force.get_xlim() == moment.get_xlim() == (0.5, 8.5)
    # over both panels: an engine may have bars in one only (the MAN B&W 7S80MC-C7, an in-line
    # seven, has no free force below the 14th order, only moments), or none above the panels'
    # floors, and then no colour on the axes: in configs/today the flat 12 and the H16 (two
    # flat-eights on flat cranks) have nothing in any order and the boxer 6 only a sixth-order
    # couple of 0.17 N·m, under the moment floor
    faces = {
        tuple(np.round(c.get_facecolor()[0][:3], 6))
        for ax in (force, moment)
        for c in ax.collections
    }
    data = plot.spectrum_data(library, "per-cylinder")
    shown = [
        e
        for e in data["engines"]
        if (e["force"][:8] > data["force_floor"]).any()
        or (e["moment"][:8] > data["moment_floor"]).any()
    ]
    assert len(library) == len(balance.find_configs([CONFIGS]))
    hidden = {e["name"] for e in data["engines"]} - {e["name"] for e in shown}
    assert hidden == {
        "Flat 12, 180° V (Ferrari 512 BB)",
        "Boxer 6 (Porsche 9A1 3.8)",
        "BRM H16 (two flat-8s geared)",
    }
    assert len(faces) == len(shown) == len(library) - 3
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
