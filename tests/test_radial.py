"""Single-row radials with plain rods: which orders survive and how they turn."""

import math

import pytest
from numpy.testing import assert_allclose

from balance_cli.analysis.shaking import shaking_forces as shaking
from tests.support import make_engine


def single_cylinder_harmonics(q, max_order):
    """B_k of one plain slider-crank (checked against the series in test_slider_crank)."""
    engine = make_engine([0], [(0, 0.0)], r=0.08, l=0.08 / q)
    result = shaking(engine, samples=256, max_order=max_order)
    return {o.order: 2 * o.force_forward.real / engine.unit_force_n for o in result.orders}


@pytest.mark.parametrize("n", [3, 4, 5, 7, 9])
def test_orders_survive_only_next_to_multiples_of_n(n):
    """Cylinder at γ: B_k cos k(θ−γ)·e^{iγ} = B_k/2·[e^{ikθ}e^{−i(k−1)γ} + e^{−ikθ}e^{i(k+1)γ}].
    Summed over γ = 2πm/n, the forward part survives when k ≡ 1 (mod n) and the backward
    part when k ≡ −1 (mod n), each with magnitude n/2·B_k·m·r·ω²."""
    q = 0.3
    max_order = 2 * n + 2
    b = single_cylinder_harmonics(q, max_order)
    engine = make_engine([360 * i / n for i in range(n)], [(0, 0.0)], r=0.08, l=0.08 / q)
    result = shaking(engine, samples=256, max_order=max_order)
    unit = engine.unit_force_n
    for order in result.orders:
        k = order.order
        forward = n / 2 * b[k] if k % n == 1 % n else 0.0
        backward = n / 2 * b[k] if (k + 1) % n == 0 else 0.0
        assert_allclose(abs(order.force_forward) / unit, abs(forward), atol=1e-12)
        assert_allclose(abs(order.force_backward) / unit, abs(backward), atol=1e-12)


def test_radial_primary_turns_forward_with_the_crank_at_half_n():
    """Lecture notes eq. 4.15: n/2·m·r·ω² directed along the first crank."""
    n = 7
    engine = make_engine([360 * i / n for i in range(n)], [(0, 0.0)])
    first = shaking(engine).orders[0]
    assert_allclose(first.force_forward, n / 2 * engine.unit_force_n, rtol=1e-12)
    assert abs(first.force_backward) < 1e-12 * engine.unit_force_n


def test_three_cylinder_radial_secondary_turns_backward():
    """n = 3: k = 2 ≡ −1 (mod 3), so 1.5·B2·m·r·ω² backward (B2 ≈ λ for small λ)."""
    q = 0.25
    engine = make_engine([0, 120, 240], [(0, 0.0)], r=0.08, l=0.08 / q)
    second = shaking(engine).orders[1]
    b2 = q + q**3 / 4 + 15 * q**5 / 128
    # first omitted term of B2: 35q⁷/512, relative below q⁶/10
    assert_allclose(abs(second.force_backward), 1.5 * b2 * engine.unit_force_n, rtol=q**6 / 10)
    assert abs(second.force_forward) < 1e-12 * engine.unit_force_n
    assert math.isclose(b2, q, rel_tol=0.02)
