"""The firing picture: one spoke per firing on a dial of the working cycle."""

import math

import numpy as np
from numpy.testing import assert_allclose

from balance_cli import plot


def test_firing_figure_draws_one_spoke_per_firing(library):
    """The spokes are one line broken at NaN: (0, 0) to the rim, once per firing."""
    chosen = [r for r in library if r.engine.cycle == 2][:1] + [library[0]]
    fig = plot.firing(chosen)
    for ax, result in zip(fig.axes, chosen, strict=True):
        (line,) = [line for line in ax.lines if np.isnan(line.get_xdata()).any()]
        xs, ys = (
            np.asarray(line.get_xdata()).reshape(-1, 3),
            np.asarray(line.get_ydata()).reshape(-1, 3),
        )
        assert len(xs) == result.engine.n_cylinders
        assert not xs[:, 0].any() and not ys[:, 0].any() and np.isnan(xs[:, 2]).all()
        angles = sorted(
            math.degrees(math.atan2(x, y)) % 360 for x, y in zip(xs[:, 1], ys[:, 1], strict=True)
        )
        expected = sorted(360 * a / result.engine.cycle_deg for a in result.firing.angles_deg)
        assert_allclose(angles, expected, atol=1e-9)
