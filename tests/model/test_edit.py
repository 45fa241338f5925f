"""Engine.edit: one cylinder's mass, one throw's phase, the rod ratio and the engine's own values
changed as a file writes them, checked against forces and couples worked out by hand; every
error names the key."""

import cmath
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.errors import ModelError
from tests.support import JUMO, MRW2, ROOT, inline_toml

#: one cylinder: m = 0.5 kg, r = 50 mm, l = 200 mm, 3000 rpm (two-stroke)
SINGLE = inline_toml("single", [0], 0).replace('reciprocating = "1 kg"', 'reciprocating = "500 g"')
R, OMEGA = 0.050, 3000 * math.pi / 30


def first_order(engine):
    """The first order's row of the engine's records."""
    (row, *_) = balance.analyse(engine, samples=64, max_order=2).records()
    return row


def test_one_cylinders_mass_moves_its_first_order_force_by_dm_r_omega2():
    """One cylinder's first-order force is exactly m·r·ω² (r·cos θ; the rod's square root has
    even harmonics only): 50 g more is 0.05·r·ω² more, N."""
    engine = balance.loads(SINGLE)
    before = first_order(engine)["force_max_N"]
    heavier = engine.edit(cylinder=1, reciprocating="550 g")
    assert heavier.cylinders[0].reciprocating_kg == pytest.approx(0.55, rel=1e-15)
    after = first_order(heavier)["force_max_N"]
    # 64-point FFTs of an exact cosine: rounding only
    assert_allclose(after - before, 0.050 * R * OMEGA**2, rtol=1e-10)
    assert_allclose(after, 0.55 * R * OMEGA**2, rtol=1e-12)
    assert engine.cylinders[0].reciprocating_kg == 0.5  # the original is left as it was
    # the same mass in other units is the same engine
    assert engine.edit(cylinder=1, reciprocating="0.55 kg") == heavier


def twin_couple(phases_deg, z_m, m_r_w2):
    """The forward and backward first-order couples of in-line cylinders by hand: each piston's
    first order is m·r·ω²·cos(θ + β) along the cylinder axis, ½·m·r·ω²·e^{±iβ} forward and
    backward, and the couple is Σ (z − z̄)·F."""
    mean = sum(z_m) / len(z_m)
    forward = sum(
        (z - mean) * m_r_w2 / 2 * cmath.exp(1j * math.radians(b))
        for b, z in zip(phases_deg, z_m, strict=True)
    )
    backward = sum(
        (z - mean) * m_r_w2 / 2 * cmath.exp(-1j * math.radians(b))
        for b, z in zip(phases_deg, z_m, strict=True)
    )
    return forward, backward


@pytest.mark.parametrize("phase", [90.0, 45.0, 270.0])
def test_a_throws_phase_moves_the_couple_as_the_phasor_sum_says(phase):
    """A 180° twin (m = 1 kg, r = 50 mm, 3000 rpm, throws 100 mm apart) with throw 2 moved to
    ``phase``: the couple's forward phasor is ½·m·r·ω²·(d/2)·(e^{iβ} − 1), of size
    m·r·ω²·(d/2)·|sin(β/2)| and direction 90° + β/2; the ellipse's max m·r·ω²·d·|sin(β/2)|."""
    engine = balance.loads(inline_toml("twin", [0, 180], 100))
    moved = engine.edit(throw=2, phase=phase, name=f"twin, throw 2 at {phase:g}°")
    assert moved.throws[1].phase_rad == pytest.approx(math.radians(phase), rel=1e-15)
    row = first_order(moved)
    forward, backward = twin_couple([0, phase], [0.0, 0.1], MRW2)
    # by hand: exact; the library's 64-point FFT of exact cosines: rounding (rtol 1e-9)
    assert_allclose(row["moment_forward_Nm"], abs(forward), rtol=1e-9)
    assert_allclose(row["moment_backward_Nm"], abs(backward), rtol=1e-9)
    assert_allclose(row["moment_forward_deg"], math.degrees(cmath.phase(forward)) % 360, atol=1e-9)
    assert_allclose(row["moment_forward_deg"], (90 + phase / 2) % 360, atol=1e-9)
    assert_allclose(
        row["moment_max_Nm"], MRW2 * 0.1 * abs(math.sin(math.radians(phase / 2))), rtol=1e-9
    )
    # the new name tells the two apart in a comparison
    both = balance.compare([balance.analyse(e, samples=64, max_order=2) for e in (engine, moved)])
    assert [r.engine.name for r in both.results] == ["twin", f"twin, throw 2 at {phase:g}°"]


def test_the_rod_ratio_sets_the_rod_length_and_the_second_order():
    """rod_ratio 3.5: l = 3.5·r. The second order of one piston is m·ω² times the second
    harmonic of x''(θ) = −r·cos θ − r²·cos 2θ/S − r⁴·sin²θ·cos²θ/S³, S = √(l² − r²·sin²θ)
    (differentiated by hand, an FFT of 4096 points)."""
    engine = balance.loads(SINGLE)
    longer = engine.edit(rod_ratio=3.5)
    assert longer.rod_length_m == pytest.approx(3.5 * R, rel=1e-15)
    assert longer.crank_radius_m == engine.crank_radius_m
    theta = np.arange(4096) * 2 * math.pi / 4096
    rod = 3.5 * R
    s = np.sqrt(rod**2 - R**2 * np.sin(theta) ** 2)
    x2 = (
        -R * np.cos(theta)
        - R**2 * np.cos(2 * theta) / s
        - R**4 * (np.sin(2 * theta) / 2) ** 2 / s**3
    )
    by_hand = 0.5 * OMEGA**2 * 2 * abs(np.fft.rfft(x2)[2] / 4096)
    second = balance.analyse(longer, samples=64, max_order=2).records()[1]
    assert_allclose(second["force_max_N"], by_hand, rtol=1e-9)
    # with a new crank radius, the ratio is of the new one; alone, the radius keeps the rod
    both = engine.edit(crank_radius="30 mm", rod_ratio=4)
    assert (both.crank_radius_m, both.rod_length_m) == pytest.approx((0.030, 0.120), rel=1e-15)
    assert engine.edit(crank_radius="30 mm").rod_length_m == engine.rod_length_m


def test_the_engines_own_values():
    engine = balance.loads(inline_toml("twin", [0, 180], 100))
    faster = engine.edit(speed="6000 rpm")
    assert faster.speed_rad_s == pytest.approx(2 * engine.speed_rad_s, rel=1e-15)
    # every force is m·(geometry)·ω²: twice the speed, four times the force
    assert_allclose(
        first_order(faster)["moment_max_Nm"], 4 * first_order(engine)["moment_max_Nm"], rtol=1e-12
    )
    heavier = engine.edit(reciprocating="1.2 kg", rotating="300 g", crank="0.1 kg")
    assert [c.reciprocating_kg for c in heavier.cylinders] == pytest.approx([1.2, 1.2], rel=1e-15)
    assert (heavier.rotating_kg, heavier.crank_kg) == pytest.approx((0.3, 0.1), rel=1e-15)
    assert engine.edit(pin_offset="-2 mm").pin_offset_m == pytest.approx(-0.002, rel=1e-15)
    assert engine.edit(rod_length="10 in").rod_length_m == pytest.approx(0.254, rel=1e-15)
    assert engine.edit(name="another").name == "another"


def test_one_cylinders_and_one_throws_positions():
    engine = balance.loads(inline_toml("twin", [0, 180], 100))
    edited = engine.edit(cylinder=2, z="120 mm", pin_offset="1 mm")
    assert edited.cylinders[1].z_m == pytest.approx(0.120, rel=1e-15)
    assert edited.cylinders[1].pin_offset_m == pytest.approx(0.001, rel=1e-15)
    assert edited.cylinders[0] == engine.cylinders[0]
    assert engine.edit(throw=1, z="-10 mm").throws[0].z_m == pytest.approx(-0.010, rel=1e-15)


def test_an_opposed_bores_two_pistons():
    """[masses] reciprocating sets both pistons of an opposed bore; a cylinder's
    opposed_reciprocating its second one alone."""
    engine = balance.load(ROOT / JUMO)
    both = engine.edit(reciprocating="2 kg")
    assert all(c.opposed_reciprocating_kg == pytest.approx(2.0, rel=1e-15) for c in both.cylinders)
    one = engine.edit(cylinder=1, opposed_reciprocating="2.5 kg")
    assert one.cylinders[0].opposed_reciprocating_kg == pytest.approx(2.5, rel=1e-15)
    assert one.cylinders[0].reciprocating_kg == engine.cylinders[0].reciprocating_kg


@pytest.mark.parametrize(
    ("changes", "parameter", "words"),
    [
        ({"cylinder": 9, "reciprocating": "1 kg"}, "cylinder", "cylinder numbers (1)"),
        ({"cylinder": True, "reciprocating": "1 kg"}, "cylinder", "got True"),
        ({"throw": 0, "phase": 10}, "throw", "throw numbers (1)"),
        ({"cylinder": 1, "throw": 1, "z": "1 mm"}, "cylinder", "cannot both"),
        ({"cylinder": 1, "speed": "1 rpm"}, "speed", "not a key of a cylinder"),
        ({"throw": 1, "reciprocating": "1 kg"}, "reciprocating", "not a key of a throw"),
        ({"bore": "80 mm"}, "bore", "not a key of the engine"),
        ({"reciprocating": 0.5}, "reciprocating", 'such as "550 g", got 0.5'),
        ({"speed": "3 kg"}, "speed", "angular speed is needed"),
        ({"speed": "-3000 rpm"}, "speed", "greater than zero"),
        ({"rotating": "-1 g"}, "rotating", "zero or more"),
        ({"throw": 1, "phase": "90 deg"}, "phase", "number of degrees"),
        ({"throw": 1, "phase": 400}, "phase", "from -360 to 360"),
        ({"rod_ratio": 1.0}, "rod_ratio", "greater than 1"),
        ({"rod_ratio": 3, "rod_length": "1 m"}, "rod_ratio", "cannot both"),
        ({"crank_radius": "300 mm"}, "crank_radius", "cannot exist"),
        ({"name": "two\nlines"}, "name", "cannot exist"),
        ({}, None, "nothing to change"),
    ],
)
def test_every_error_names_the_key(changes, parameter, words):
    engine = balance.loads(SINGLE)
    with pytest.raises(ModelError) as caught:
        engine.edit(**changes)
    assert caught.value.parameter == parameter
    assert words in str(caught.value)
    assert "\n" not in str(caught.value)
    if parameter:
        assert str(caught.value).startswith(parameter)
