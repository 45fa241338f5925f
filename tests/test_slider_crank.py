"""A single slider-crank: the exact harmonics against the classic series and finite differences."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from balance_cli.kinematics.linkage import linkage_state
from balance_cli.analysis.shaking import shaking_forces as shaking
from tests.support import make_engine


def series(q):
    """Classic series of the piston acceleration (Tanaka 1925, B_2n; lecture notes eq. 4.17).

    Inertia force = m·r·ω²·(cos θ + B2 cos 2θ + B4 cos 4θ + B6 cos 6θ + …), q = r/l.
    """
    return {
        1: 1.0,
        2: q + q**3 / 4 + 15 * q**5 / 128,
        4: -(q**3 / 4 + 3 * q**5 / 16),
        6: 9 * q**5 / 128,
    }


@pytest.mark.parametrize("q", [0.1, 0.25, 0.297, 0.35])
def test_harmonics_match_the_series_to_its_truncation_error(q):
    """cos kθ = (e^{ikθ} + e^{−ikθ})/2: forward = backward = m·r·ω²·B_k/2, along the axis.

    The first omitted terms are 35q⁷/512, −35q⁷/256 and 45q⁷/512 (well below q⁷/4), and B8
    starts at q⁷ too, so the series and the exact values must agree to q⁷/4 in units of
    m·r·ω². The rod's correction √(l² − r² sin²θ) is even, so odd orders above the first
    are exactly zero.
    """
    engine = make_engine([0], [(0, 0.0)], r=0.08, l=0.08 / q)
    result = shaking(engine, samples=256, max_order=8)
    unit = engine.unit_force_n
    expected = series(q)
    for order in result.orders:
        b = expected.get(order.order, 0.0)
        tolerance = q**7 / 4 if order.order % 2 == 0 else 1e-12
        assert_allclose(order.force_forward / unit, b / 2, atol=tolerance)
        assert_allclose(order.force_backward / unit, b / 2, atol=tolerance)


def test_harmonics_match_second_differences_of_the_exact_positions():
    """The time signal rebuilt from the orders equals −m·ẍ by Richardson-extrapolated
    central differences of the exact linkage (h = 0.02 rad, four levels: truncation far
    below 1e-10, rounding about 1e-12 of m·r·ω²)."""
    engine = make_engine([30], [(0, 0.0)], r=0.08, l=0.26, pin_offset=0.01)
    samples = 128
    result = shaking(engine, samples=samples, max_order=20)
    angles = 2 * np.pi * np.arange(samples) / samples
    acceleration = _richardson_second_derivative(lambda a: linkage_state(engine, a).masses.positions[0],
                                                 angles, 0.02, 4)
    direct = -engine.cylinders[0].reciprocating_kg * acceleration * engine.speed_rad_s**2
    from_orders = result.force()
    assert_allclose(from_orders / engine.unit_force_n, direct / engine.unit_force_n, atol=1e-9)


def _richardson_second_derivative(f, x, h, levels):
    table = []
    for i in range(levels):
        step = h / 2**i
        table.append((f(x + step) - 2 * f(x) + f(x - step)) / step**2)
    for j in range(1, levels):
        factor = 4**j
        table = [(factor * table[i + 1] - table[i]) / (factor - 1) for i in range(len(table) - 1)]
    return table[0]
