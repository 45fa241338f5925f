"""Results in an engineer's terms: directions (vertical/horizontal, pitch/yaw), the summary of
the largest free force and moment and the moment noise floor.

Every expected value is a closed form derived by hand in the test's docstring, or the
slider-crank harmonic B_k of ``tests.support.exact_b`` (the closed-form acceleration projected
by the trapezoidal rule, apart from the library)."""

import math

import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from tests.support import TWIN, exact_b, make_engine

M, R, L, RPM, D = 0.6, 0.045, 0.15, 3000.0, 0.1
W = RPM * math.pi / 30.0
UNIT = M * R * W**2  # m·r·ω² of one reciprocating mass, N
# rounding of the FFT is about 1e-13 of the largest force; 1e-9 leaves a wide margin
RTOL = 1e-9


def record(engine, order, max_order=8):
    return balance.analyse(engine, max_order=max_order).to_dict()["orders"][order - 1]


def test_cross_plane_v8_primary_couple_is_all_forward_with_equal_pitch_and_yaw():
    """90° V8, cross-plane crank (throws 0°, 90°, 270°, 180° at z = 0, d, 2d, 3d), reciprocating
    masses only. A throw's two pistons at ±45° make a first-order force m·r·ω² turning with the
    crank (exactly: the rod adds only even orders), so the couple is forward only, of size
    m·r·ω²·|Σ(z_j − z̄)·e^{iβ_j}| = m·r·ω²·d·|−1.5 − 0.5i + 0.5·(−i) + 1.5·(−1)|
    = m·r·ω²·d·|−3 − i| = √10·m·r·ω²·d.
    A turning vector has equal vertical and horizontal amplitudes."""
    engine = make_engine(
        [-45, 45], [(0, 0), (90, D), (270, 2 * D), (180, 3 * D)], r=R, rod=L, m=M, rpm=RPM
    )
    moment = record(engine, 1)["moment"]
    couple = math.sqrt(10) * UNIT * D
    assert_allclose(moment["forward_Nm"], couple, rtol=RTOL)
    assert moment["backward_Nm"] == 0.0 and moment["axis_deg"] is None
    assert_allclose([moment["vertical_Nm"], moment["horizontal_Nm"]], [couple, couple], rtol=RTOL)
    # a turning couple's components are 90° apart: yaw peaks a quarter turn after pitch
    assert_allclose((moment["horizontal_deg"] - moment["vertical_deg"]) % 360.0, 90.0, atol=1e-6)


def test_flat_plane_v8_secondary_force_is_horizontal_only():
    """90° V8, flat crank (0°, 180°, 180°, 0°): each bank is an in-line 4 whose four secondary
    forces add, 4·m·r·ω²·B₂·cos 2(θ − γ) along its axis γ = ±45°. Summed over the banks:
    4·m·r·ω²·B₂·(cos(2θ − 90°)·e^{i45°} + cos(2θ + 90°)·e^{−i45°}) = i·4√2·m·r·ω²·B₂·sin 2θ,
    across the bisector only: horizontal 4√2·m·r·ω²·|B₂|, vertical 0."""
    engine = make_engine(
        [-45, 45], [(0, 0), (180, D), (180, 2 * D), (0, 3 * D)], r=R, rod=L, m=M, rpm=RPM
    )
    force = record(engine, 2)["force"]
    expected = 4 * math.sqrt(2) * UNIT * abs(exact_b(R / L, 2))
    assert_allclose(force["horizontal_N"], expected, rtol=1e-9)
    assert force["vertical_N"] == 0.0
    assert_allclose(force["axis_deg"], 90.0, atol=1e-6)


def test_twin_180_primary_couple_pitches_and_the_summary_names_it():
    """180° twin, pitch d, one bank: the primary forces m·r·ω²·cos θ at z = 0 and
    −m·r·ω²·cos θ at z = d make the couple −m·r·ω²·d·cos θ about z̄, along the cylinder axis:
    pitching amplitude m·r·ω²·d, yaw 0; forward and backward halves m·r·ω²·d/2. After an ideal
    counterweight the backward half is left, turning: the summary's main moment order is 1,
    rotating, m·r·ω²·d/2 — the twin does not look balanced."""
    engine = make_engine([0], [(0, 0), (180, D)], r=R, rod=L, m=M, rpm=RPM)
    result = balance.analyse(engine)
    moment = result.to_dict()["orders"][0]["moment"]
    assert_allclose(moment["vertical_Nm"], UNIT * D, rtol=RTOL)
    assert moment["horizontal_Nm"] == 0.0
    assert_allclose([moment["forward_Nm"], moment["backward_Nm"]], [UNIT * D / 2] * 2, rtol=RTOL)
    main_moment = result.to_dict()["main_moment_order"]
    assert main_moment["order"] == 1 and main_moment["direction"] == "rotating backward"
    assert_allclose(main_moment["max_Nm"], UNIT * D / 2, rtol=RTOL)
    assert_allclose(result.counterweighted_moment_nm, UNIT * D / 2, rtol=1e-6)
    # without a counterweight the largest moment is the whole couple (all orders: the twin's
    # second orders are in phase and make no couple, so the first order is all of it)
    assert_allclose(result.largest_moment_nm, UNIT * D, rtol=1e-6)


def test_inline_3_primary_couple_is_all_pitch():
    """In-line 3 (0°, 120°, 240° at 0, d, 2d), reciprocating masses only: the primary couple is
    m·r·ω²·d·Re(−e^{iθ} + e^{i(θ + 240°)}), amplitude |−1 + e^{i240°}|·m·r·ω²·d = √3·m·r·ω²·d,
    along the cylinder axis: all pitching, no yaw."""
    engine = make_engine([0], [(0, 0), (120, D), (240, 2 * D)], r=R, rod=L, m=M, rpm=RPM)
    moment = record(engine, 1)["moment"]
    assert_allclose(
        [moment["max_Nm"], moment["vertical_Nm"]], [math.sqrt(3) * UNIT * D] * 2, rtol=RTOL
    )
    assert moment["horizontal_Nm"] == 0.0
    assert_allclose(moment["axis_deg"], 0.0, atol=1e-6)


def test_vertical_key_turns_the_components():
    """The 180° twin with `vertical = 90` (an engine lying on its side): the cylinder axis is
    now horizontal, so its primary couple is all yaw."""
    text = TWIN.replace("firing_order = [1, 2]\n", "vertical = 90\n")
    engine = balance.loads(text)
    assert_allclose(engine.vertical_axis_rad, math.pi / 2, rtol=1e-15)
    moment = balance.analyse(engine).to_dict()["orders"][0]["moment"]
    assert moment["vertical_Nm"] == 0.0 and moment["horizontal_Nm"] > 0.0
    with pytest.raises(balance.ConfigError, match="vertical"):
        balance.loads(TWIN + 'vertical = "up"\n')


def test_a_small_couple_above_the_engines_own_floor_is_reported():
    """In-line 3 with r/l = 0.05/0.22 and d = 0.1 m: its order-10 couple √3·d·m·r·ω²·|B₁₀| is
    about 5.6e-10 of m·r·ω²·n times one metre, below the old floor (1e-9 of that), but its
    forward and backward halves are above the floor on the engine's own lever arm
    (1e-9 · m·r·ω²·n · 0.1 m)."""
    r, rod = 0.05, 0.22
    engine = make_engine([0], [(0, 0), (120, D), (240, 2 * D)], r=r, rod=rod, m=M, rpm=RPM)
    unit = M * r * W**2
    expected = math.sqrt(3) * D * unit * abs(exact_b(r / rod, 10))
    assert expected < 1e-9 * unit * 3 * 1.0  # the old floor would have zeroed it
    assert expected / 2 > engine.noise_floor_nm
    assert engine.noise_floor_nm == pytest.approx(1e-9 * unit * 3 * D, rel=1e-12)
    moment = record(engine, 10, max_order=12)["moment"]
    # the FFT's rounding is about 1e-16 of the largest moment, 1e-7 of this one
    assert_allclose(moment["max_Nm"], expected, rtol=1e-5)
