"""Top dead centres (balance_cli.kinematics.tdc): where bank angle meets crank phase, moved by
pin offsets and link rods, backwards on a rotary, in closed form for plain rods."""

import dataclasses
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli
import balance_cli as balance
from balance_cli import load
from balance_cli.kinematics import tdc_angles
from tests.support import CONFIGS, VR6, invoke, make_engine


def test_tdc_is_where_bank_angle_equals_crank_phase():
    """Throw at phase β, bank at γ: TDC when θ = γ − β (mod 360°) for plain rods, no offset."""
    engine = make_engine([-45, 45], [(0, 0.0), (120, 0.1)])
    tdc = tdc_angles(engine)
    assert_allclose([tdc[n] for n in (1, 2, 3, 4)], [315.0, 195.0, 45.0, 285.0], atol=1e-6)


def test_pin_offset_moves_tdc_to_the_collinear_position():
    """With offset e the piston is farthest out when crank and rod are collinear:
    sin ψ = e/(l + r)."""
    r, rod, e = 0.05, 0.2, 0.01
    tdc = tdc_angles(make_engine([0], [(0, 0.0)], r=r, rod=rod, pin_offset=e))
    assert_allclose(tdc[1], math.degrees(math.asin(e / (rod + r))), atol=1e-4)


def test_rotary_tdc_runs_backwards_through_the_cylinders():
    """Crankcase turning forward about a fixed crank: the cylinder at γ meets the crank when
    the crankcase angle is −γ."""
    engine = make_engine([0, 120, 240], [(0, 0.0)], frame="rotary")
    tdc = tdc_angles(engine)
    assert_allclose([tdc[1], tdc[2], tdc[3]], [0.0, 240.0, 120.0], atol=1e-6)


def test_link_rods_shift_tdc_slightly():
    """A link rod reaches its top dead centre a little after its bank angle (Fraeys de
    Veubeke § 7: θ ≈ ψ + r_n(1 − (l/L)cos ψ)·λ sin ψ/(l + R) for ε = 0): for the BRAMO
    cylinder 3 (ψ = 80°) about 2.5°. The estimate drops the small terms of its denominator
    (r_n·λ…, a few per cent of l + R): ±0.2°."""
    engine = load(CONFIGS / "bramo-323.toml")
    tdc = tdc_angles(engine)
    psi, r_n, rod, big_l, radius = math.radians(80), 0.07126, 0.2615, 0.330, 0.080
    lam = radius / big_l
    estimate = r_n * (1 - rod / big_l * math.cos(psi)) * lam * math.sin(psi) / (rod + radius)
    assert abs(tdc[3] - 80 - math.degrees(estimate)) < 0.2
    plain = dataclasses.replace(
        engine,
        cylinders=tuple(
            dataclasses.replace(c, master=None, knuckle_kg=0.0) for c in engine.cylinders
        ),
    )
    assert_allclose(tdc_angles(plain)[3], 80.0, atol=1e-6)


def test_tdc_of_cylinder_one_is_zero_not_360():
    """A plain in-line engine's cylinder 1 is at TDC at θ = 0 exactly; the TDC search lands a
    hair below 360°, which must read 0."""
    tdc = balance_cli.kinematics.tdc_angles(balance.load(CONFIGS / "inline-4-car.toml"))
    assert tdc[1] == 0.0 and all(0.0 <= a < 360.0 for a in tdc.values())
    shown = invoke("show", CONFIGS / "inline-4-car.toml").stdout
    assert "360.00" not in shown


def test_tdc_search_memory_is_linear_in_cylinders():
    """piston_travel of chosen cylinders computes only those (and their masters): the TDC
    refinement of a 400-cylinder grid needs arrays of 101 angles, not 400 × 400 × 101."""
    engine = make_engine(
        [3.6 * i for i in range(20)], [(18 * t, 0.05 * t) for t in range(20)], cycle=2
    )
    travel = balance_cli.kinematics.linkage.piston_travel(engine, [0.0, 0.1], [7])
    assert list(travel) == [7]
    tdc = balance_cli.kinematics.tdc_angles(engine)
    assert len(tdc) == 400
    cylinder = engine.cylinder(27)  # bank 2 (3.6°), throw 7 (108°): TDC at 3.6 − 108 mod 360
    assert_allclose(tdc[27], (3.6 - 108.0) % 360, atol=1e-5)
    assert cylinder.bank == 2


@pytest.mark.parametrize(
    "config", [VR6, "configs/today/h/brm-h16.toml", "configs/today/v/v6-90-odd-fire.toml"]
)
def test_closed_form_top_dead_centres_match_the_travels_maximum(config):
    """Plain rods' TDCs are computed in closed form (crank and rod in line); the second method
    is the maximum of each piston's exact travel on a grid of 1e-5° round it."""
    from balance_cli.kinematics.linkage import piston_travel

    engine = balance.load(config)
    if config == VR6:
        # a reversed copy with a gear phase too: the offset's sense follows the crankshaft
        engine = engine.replace(
            cylinders=tuple(
                balance.Cylinder(
                    c.number,
                    c.bank,
                    c.throw,
                    c.z_m,
                    c.reciprocating_kg,
                    pin_offset_m=0.02 * (1 if c.number % 2 else -1),
                )
                for c in engine.cylinders
            )
        )
    tdc = tdc_angles(engine)
    for c in engine.cylinders:
        around = np.radians(tdc[c.number] + np.linspace(-0.01, 0.01, 2001))
        travel = piston_travel(engine, around, [c.number])[c.number]
        best = math.degrees(around[np.argmax(travel)])
        assert abs((best - tdc[c.number] + 180) % 360 - 180) < 1.1e-5, c.number
