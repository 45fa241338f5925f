"""The torque picture (balance plot --kind torque): the data behind it and what it draws."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from balance_cli import plot
from balance_cli.errors import PlotError
from balance_cli.units import STANDARD_GRAVITY


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
            assert data[name][-1] == data[name][0]  # closed over the cycle
        assert_allclose(data["mean"], result.total.mean * scale, rtol=1e-12)
        assert_allclose(data["orders"], 0.5 * np.arange(1, 17), rtol=0, atol=0)
        assert_allclose(
            data["amplitudes"],
            [math.hypot(c, s) * scale for _, c, s in result.total.orders],
            rtol=1e-12,
            atol=0,
        )
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
    for result, total, inertia, mean in zip(torques, totals, inertias, means, strict=True):
        assert_allclose(total.get_xdata()[:-1], result.total.theta_deg, rtol=0, atol=1e-12)
        assert total.get_xdata()[-1] == result.period_deg
        assert_allclose(total.get_ydata()[:-1], result.total.curve * scale, rtol=1e-12, atol=0)
        assert_allclose(inertia.get_ydata()[:-1], result.inertia.curve * scale, rtol=1e-12, atol=0)
        assert_allclose(mean.get_ydata(), [result.total.mean * scale] * 2, rtol=1e-12, atol=0)
    for result, patch in zip(torques, bars, strict=False):
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
            assert not any(box.overlaps(other) for other in boxes[i + 1 :])
        for index, (total, box) in enumerate(zip(torque_artists(fig, "total"), boxes, strict=True)):
            points = total.get_transform().transform(
                np.column_stack([total.get_xdata(), total.get_ydata()])
            )
            column = index % columns
            assert fig.bbox.width * column / columns < points[:, 0].min()
            assert points[:, 0].max() < fig.bbox.width * (column + 1) / columns
            assert points[:, 1].max() < box.y0
        import matplotlib.pyplot as plt

        plt.close(fig)


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
