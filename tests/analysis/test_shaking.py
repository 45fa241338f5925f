"""Free forces and moments order by order (balance_cli.analysis.shaking): a single
slider-crank's exact harmonics against the classic series and finite differences, single-row
radials, and the sampling that resolves them."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.shaking import shaking_forces as shaking
from balance_cli.kinematics.linkage import linkage_state
from tests.support import CONFIGS, make_engine


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


def _richardson_second_derivative(f, x, h, levels):
    table = []
    for i in range(levels):
        step = h / 2**i
        table.append((f(x + step) - 2 * f(x) + f(x - step)) / step**2)
    for j in range(1, levels):
        factor = 4**j
        table = [(factor * table[i + 1] - table[i]) / (factor - 1) for i in range(len(table) - 1)]
    return table[0]


def single_cylinder_harmonics(q, max_order):
    """B_k of one plain slider-crank (checked against the series in
    test_harmonics_match_the_series_to_its_truncation_error)."""
    engine = make_engine([0], [(0, 0.0)], r=0.08, rod=0.08 / q)
    result = shaking(engine, samples=256, max_order=max_order)
    return {o.order: 2 * o.force_forward.real / engine.unit_force_n for o in result.orders}


@pytest.mark.parametrize("q", [0.1, 0.25, 0.297, 0.35])
def test_harmonics_match_the_series_to_its_truncation_error(q):
    """cos kθ = (e^{ikθ} + e^{−ikθ})/2: forward = backward = m·r·ω²·B_k/2, along the axis.

    The first omitted terms are 35q⁷/512, −35q⁷/256 and 45q⁷/512 (well below q⁷/4), and B8
    starts at q⁷ too, so the series and the exact values must agree to q⁷/4 in units of
    m·r·ω². The rod's correction √(l² − r² sin²θ) is even, so odd orders above the first
    are exactly zero.
    """
    engine = make_engine([0], [(0, 0.0)], r=0.08, rod=0.08 / q)
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
    engine = make_engine([30], [(0, 0.0)], r=0.08, rod=0.26, pin_offset=0.01)
    samples = 128
    result = shaking(engine, samples=samples, max_order=20)
    angles = 2 * np.pi * np.arange(samples) / samples
    acceleration = _richardson_second_derivative(
        lambda a: linkage_state(engine, a).masses.positions[0], angles, 0.02, 4
    )
    direct = -engine.cylinders[0].reciprocating_kg * acceleration * engine.speed_rad_s**2
    from_orders = result.force()
    assert_allclose(from_orders / engine.unit_force_n, direct / engine.unit_force_n, atol=1e-9)


@pytest.mark.parametrize("n", [3, 4, 5, 7, 9])
def test_orders_survive_only_next_to_multiples_of_n(n):
    """Cylinder at γ: B_k cos k(θ−γ)·e^{iγ} = B_k/2·[e^{ikθ}e^{−i(k−1)γ} + e^{−ikθ}e^{i(k+1)γ}].
    Summed over γ = 2πm/n, the forward part survives when k ≡ 1 (mod n) and the backward
    part when k ≡ −1 (mod n), each with magnitude n/2·B_k·m·r·ω²."""
    q = 0.3
    max_order = 2 * n + 2
    b = single_cylinder_harmonics(q, max_order)
    engine = make_engine([360 * i / n for i in range(n)], [(0, 0.0)], r=0.08, rod=0.08 / q)
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
    engine = make_engine([0, 120, 240], [(0, 0.0)], r=0.08, rod=0.08 / q)
    second = shaking(engine).orders[1]
    b2 = q + q**3 / 4 + 15 * q**5 / 128
    # first omitted term of B2: 35q⁷/512, relative below q⁶/10
    assert_allclose(abs(second.force_backward), 1.5 * b2 * engine.unit_force_n, rtol=q**6 / 10)
    assert abs(second.force_forward) < 1e-12 * engine.unit_force_n
    assert math.isclose(b2, q, rel_tol=0.02)


@pytest.mark.parametrize(
    "config",
    ["tanaka-part3/5a-radial-9.toml", "bramo-323.toml", "inline-4-car.toml", "clerget-rotary.toml"],
)
def test_odd_and_even_samples_give_the_same_orders(config):
    engine = balance.load(CONFIGS / config)
    reference = balance.analyse(engine, samples=256, max_order=8)
    unit = engine.per_cylinder_unit_n
    for samples in (101, 255, 1001, 1024):
        result = balance.analyse(engine, samples=samples, max_order=8)
        for ours, theirs in zip(result.shaking.orders, reference.shaking.orders, strict=True):
            for a, b in (
                (ours.force_forward, theirs.force_forward),
                (ours.force_backward, theirs.force_backward),
                (ours.moment_forward, theirs.moment_forward),
            ):
                assert abs(a - b) < 1e-10 * unit, (samples, ours.order)
        # the resultant's largest magnitude comes from the padded synthesis, odd or even
        assert_allclose(result.largest_force_n, reference.largest_force_n, rtol=1e-7)


@pytest.mark.parametrize("samples", [8192, 32768])
def test_more_samples_never_warn(samples):
    """pytest turns a SamplingWarning into an error (pyproject.toml)."""
    for engine in balance.load_many([CONFIGS]):
        assert balance.analyse(engine, samples=samples, max_order=8).shaking.sampling_ok


def test_too_few_samples_still_warn():
    engine = balance.load(CONFIGS / "inline-4-marine.toml")
    with pytest.warns(balance.SamplingWarning, match="16 samples a revolution are too few"):
        assert not balance.analyse(engine, samples=16, max_order=3).shaking.sampling_ok


def test_locus_points_must_fit_the_samples():
    result = balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"))
    assert len(result.shaking.locus()) == 4 * 256
    for points in (0, -4, 100, 2.5):
        with pytest.raises(balance.AnalysisError, match="points must be a positive multiple"):
            result.shaking.locus(points=points)
