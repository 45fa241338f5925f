"""Torques, reduced mass, tilting, frame reaction and pin forces, against hand-derived closed
forms, independent second methods and the papers."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.torque import torque
from tests.support import CONFIGS, make_engine
from tests.validation.reference import fraeys_newton_euler


def single(r=0.05, rod=0.2, m=1.0, rpm=3000.0, **extra):
    return make_engine([0], [(0, 0.0)], r=r, rod=rod, m=m, rpm=rpm, cycle=2, **extra)


def test_single_cylinder_inertia_torque_by_a_second_method():
    """Virtual work of the inertia force on the exact slider: T(θ) = −m·ẍ·∂x/∂θ = −m·ω²·x''·x'
    with the hand-derived closed forms (q = r/l, s = sin θ, c = cos θ, D = √(1 − q²s²))
    x' = −r·s·(1 + q·c/D) and x'' = −r·(c + q·cos 2θ/D + q³·sin²2θ/(4D³)) — no FFT, no library
    kinematics: agreement to 1e-10 of m·r²·ω² (the spectral derivative's rounding, about 1e-13
    of the positions, grows with the square of the highest orders), and μ = m·x'² to 1e-12
    of m·r²."""
    r, rod, m, rpm = 0.05, 0.2, 1.3, 2500.0
    engine = single(r, rod, m, rpm)
    result = torque(engine, samples=256, max_order=20)
    omega = rpm * math.pi / 30
    q = r / rod
    theta = np.radians(result.inertia.theta_deg)
    s, c = np.sin(theta), np.cos(theta)
    d = np.sqrt(1 - q**2 * s**2)
    x1 = -r * s * (1 + q * c / d)
    x2 = -r * (c + q * np.cos(2 * theta) / d + q**3 * np.sin(2 * theta) ** 2 / (4 * d**3))
    unit = m * r**2 * omega**2
    assert np.abs(result.inertia.curve - (-m * omega**2 * x2 * x1)).max() < 1e-10 * unit
    assert np.abs(result.reduced_mass.curve_kgm2 - m * x1**2).max() < 1e-12 * m * r**2


@pytest.mark.parametrize("lam", [0.1, 0.25])
def test_single_cylinder_inertia_torque_against_the_classic_series(lam):
    """m·r²·ω²·(λ/4·sin θ − ½·sin 2θ − 3λ/4·sin 3θ − λ²/4·sin 4θ): each coefficient is the
    first term of its series in λ; the next terms are of relative order λ² (sin θ, sin 3θ), λ
    (sin 2θ: −½ − λ²/32…) and λ² (sin 4θ), bounded here by 2·λ² of the coefficient."""
    r = 0.05
    result = torque(single(r=r, rod=r / lam), max_order=4)
    unit = r**2 * (3000 * math.pi / 30) ** 2
    for k, expected in ((1, lam / 4), (2, -0.5), (3, -3 * lam / 4), (4, -(lam**2) / 4)):
        cos, sin = result.inertia.order(k)
        assert abs(cos) < 1e-12 * unit
        assert abs(sin / unit - expected) <= 2 * lam**2 * abs(expected)
    assert result.inertia.mean == 0.0


def test_a_centred_piston_has_no_tilting_and_the_frame_takes_the_reverse_torque():
    result = torque(single(), max_order=8)
    assert result.tilting.range == 0.0
    assert_allclose(
        result.frame.curve, -result.total.curve, atol=1e-9 * np.abs(result.total.curve).max()
    )


@pytest.mark.parametrize("config", sorted(p.relative_to(CONFIGS) for p in CONFIGS.rglob("*.toml")))
def test_the_tangential_pin_forces_give_the_torque(config):
    """Two methods: the torque from the kinetic energy (−½ω²·dμ/dθ, plus gas) and r times the
    tangential force of the rods on the pins (virtual shifts of each pin); the crankshaft's
    own masses turn at constant radius and add nothing. Fixed-frame engines only: on a rotary
    the pin stands still and the torque acts on the crankcase."""
    engine = balance.load(CONFIGS / config)
    if engine.is_rotary:
        pytest.skip("a rotary's crank pin stands still")
    result = torque(engine, max_order=8)
    from_pins = sum(engine.crank_radius_m * p.tangential.curve for p in result.pins)
    # the virtual shifts' finite differences are good to about 1e-11 of the forces
    unit = engine.per_cylinder_unit_n * engine.crank_radius_m
    assert np.abs(from_pins - result.total.curve).max() < 1e-9 * unit


@pytest.mark.parametrize("n", [5, 7, 9])
def test_a_radial_with_plain_rods_has_only_orders_of_n(n):
    """Σ over n cylinders at 360°/n of one cylinder's μ(θ − ψ_i) keeps only orders that are
    multiples of n (Margoulis § 2; Tanaka Part I § 6, "balanced out if single obliquity")."""
    engine = make_engine([360 * i / n for i in range(n)], [(0, 0.0)], r=0.05, rod=0.2)
    result = torque(engine, max_order=2 * n)
    unit = engine.per_cylinder_unit_n * engine.crank_radius_m
    for k, cos, sin in result.inertia.orders:
        if k % n:
            assert math.hypot(cos, sin) < 1e-9 * unit, k
    mu = result.reduced_mass.curve_kgm2
    c = np.abs(np.fft.rfft(mu)) / len(mu)
    assert all(c[k] < 1e-13 * mu.mean() for k in range(1, n))
    assert c[n] > 1e-10 * mu.mean()  # of order λ^(n−1): small, but there


@pytest.mark.parametrize("cylinders", [4, 5, 6, 7, 8, 9])
def test_margoulis_reduced_mass_of_evenly_firing_four_strokes(cylinders):
    """Margoulis § 2: throws 720°/N apart (even firing of a four-stroke). One cylinder's
    μ has every order; the N together keep order k only when 2k/N is whole. So μ is constant
    up to his fourth series for odd N > 3 and even N > 6, and varies for N = 4 and 6."""
    phases = [(720 * j / cylinders) % 360 for j in range(cylinders)]
    engine = make_engine([0], [(p, 0.1 * j) for j, p in enumerate(phases)], r=0.05, rod=0.25)
    mu = torque(engine, max_order=8).reduced_mass.curve_kgm2
    c = np.abs(np.fft.rfft(mu)) / len(mu)
    for k in range(1, 9):
        if (2 * k) % cylinders:
            assert c[k] < 1e-13 * mu.mean(), k
        elif k <= 4:  # Margoulis's four series; beyond them the terms are of order λ^k
            assert c[k] > 1e-6 * mu.mean(), k
    varies_below_fourth = any(c[k] > 1e-6 * mu.mean() for k in (1, 2, 3))
    assert varies_below_fourth == (cylinders in (4, 6))


def test_bramo_against_newton_euler():
    """The library's exact μ, H, radial and rotating pin forces for the BRAMO 323 (from its
    [parts]) against an independent Newton–Euler solution with rigid rods (tests/reference/
    fraeys_newton_euler.py): 1e-9 of the largest coefficient (the two use the same data)."""
    engine = balance.load(CONFIGS / "bramo-323.toml")
    result = torque(engine, max_order=6)
    ref = fraeys_newton_euler.coefficients(512)
    r, w = engine.crank_radius_m, engine.speed_rad_s
    mu = result.reduced_mass.curve_kgm2
    c = np.fft.rfft(mu) / len(mu)
    ours_u = [c[0].real / (2 * r**2)] + [k * 2 * c[k].real / (2 * r**2) for k in range(1, 6)]
    assert_allclose(ours_u, ref["U"], atol=1e-9 * abs(ref["U"][0]))
    for k in range(1, 6):
        assert_allclose(result.inertia.order(k)[1] / (r**2 * w**2), ref["U"][k], atol=1e-9 * 16)
        assert_allclose(result.tilting.order(k)[1] / (r**2 * w**2), ref["V"][k], atol=1e-9 * 16)
    pin = result.pins[0]
    assert_allclose(pin.radial.mean / (r * w**2), ref["R"][0], atol=1e-9 * 32)
    for k in range(1, 6):
        assert_allclose(pin.radial.order(k)[0] / (r * w**2), ref["R"][k], atol=1e-9 * 32)
    for k, expected in ref["T"].items():
        forward, backward = pin.order(abs(k))
        ours = forward if k >= 0 else backward
        assert abs(ours / (r * w**2) - expected) < 1e-9 * 32, k


@pytest.mark.parametrize(
    "old, new, key",
    [
        ('link_cg = "138.5 mm"                # h, from the knuckle pin\n', "", "parts.link_cg"),
        ('link_inertia = "0.0141264 kg*m^2"   # j\n', "", "parts.link_inertia"),
    ],
)
def test_link_rods_need_all_their_part_data(tmp_path, old, new, key):
    """A link rod's centre of gravity or inertia left out would silently be zero (15 % off μ)."""
    text = (CONFIGS / "bramo-323.toml").read_text(encoding="utf-8")
    assert old in text
    path = tmp_path / "e.toml"
    path.write_text(text.replace(old, new), encoding="utf-8")
    with pytest.raises(balance.ConfigError, match=f"{key}: missing for the link rods"):
        balance.load(path)
