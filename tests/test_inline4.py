"""In-line four: the lecture notes' worked example and the car engine of the library."""

import math

import pytest
from numpy.testing import assert_allclose

from balance_cli import analyse, load
from tests.support import CONFIGS


def b2_series(q):
    """Second-order coefficient of the piston acceleration, to q⁷ (Tanaka's B2 and the next
    term 35q⁷/512); the first omitted term is below 0.1·q⁹."""
    return q + q**3 / 4 + 15 * q**5 / 128 + 35 * q**7 / 512


def test_marine_example_matches_the_notes_two_term_figure_and_the_exact_value():
    """Notes: I.F. = 4·500·0.2·(2π·100/60)²·(0.2/0.8) = 10 966 N with A2 = r/l.
    Exact: the same with B2(q) instead of q, about 11 142 N; B2 to q⁷ is good to
    0.1·q⁹/B2 ≈ 1.5e-6 relative, so the tolerance is 2e-6."""
    omega = 2 * math.pi * 100 / 60
    two_term = 4 * 500 * 0.2 * omega**2 * 0.25
    assert round(two_term) == 10966
    result = analyse(load(CONFIGS / "inline-4-marine.toml"))
    second = result.shaking.orders[1]
    exact_max = abs(second.force_forward) + abs(second.force_backward)
    assert_allclose(exact_max, two_term / 0.25 * b2_series(0.25), rtol=2e-6)
    assert abs(exact_max - 11142) < 1.0
    # the notes' figure is low by the neglected higher terms of B2: 1.6 %
    assert_allclose(exact_max / two_term, b2_series(0.25) / 0.25, rtol=2e-6)


@pytest.mark.parametrize("config", ["inline-4-marine.toml", "inline-4-car.toml"])
def test_inline4_has_no_primary_force_and_no_primary_or_secondary_couple(config):
    """Σ cos β = Σ sin β = 0 and Σ z cos kβ = Σ z sin kβ = 0 for k = 1, 2 (notes eqs. 4.8, 4.9)."""
    result = analyse(load(CONFIGS / config))
    unit = result.per_cylinder_unit_n
    first, second = result.shaking.orders[0], result.shaking.orders[1]
    for value in (first.force_forward, first.force_backward, first.moment_forward,
                  first.moment_backward, second.moment_forward, second.moment_backward):
        assert abs(value) < 1e-9 * unit


def test_car_inline4_secondary_is_four_times_b2_along_the_axis():
    """4 cylinders all at cos 2θ: F2 = 4·B2(q)·m·r·ω² along the cylinder axis (axis 0° or 180°)."""
    engine = load(CONFIGS / "inline-4-car.toml")
    q = engine.crank_radius_m / engine.rod_length_m
    second = analyse(engine).shaking.orders[1]
    expected = 4 * b2_series(q) * engine.unit_force_n / 2
    # B2 to q⁷ leaves below 0.1·q⁹, relative 0.1·q⁸ ≈ 9e-6 for q = 0.3
    assert_allclose(second.force_forward, expected, rtol=0.1 * q**8)
    assert_allclose(second.force_backward, expected, rtol=0.1 * q**8)
