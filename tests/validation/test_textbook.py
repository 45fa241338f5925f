"""Today's engines (configs/today): each engine's textbook balance, derived by hand.

Notation of every derivation below. A cylinder on a bank at γ (from the reference axis, with
rotation) on a throw of phase β is at top dead centre when θ = γ − β; with φ = θ + β − γ its
piston's inertia force of order k is m·r·ω²·A_k·cos kφ along e^{iγ}, where A_k are the exact
Fourier coefficients of the slider crank (A₁ = 1, A₂ ≈ λ, A₄ ≈ −λ³/4, A₃ = A₅ = 0), measured
here by a quadrature of the closed-form piston position (a method of its own: balance samples
the linkage and takes an FFT of the accelerations). Writing cos kφ = (e^{ikφ} + e^{−ikφ})/2,
one cylinder contributes to the order-k force

    forward  F⁺ = m·r·ω²·A_k/2 · e^{ikβ}·e^{−i(k−1)γ}
    backward F⁻ = m·r·ω²·A_k/2 · e^{−ikβ}·e^{i(k+1)γ}

and to the free moment the same times (z − z̄). The per-engine tests below evaluate these sums
by hand for the textbook's crank and state the result in closed form (units m·r·ω² for forces,
m·r·ω²·d for moments, d a pitch of the file); ``test_series_sum_agrees_for_every_order`` checks
every order 1-8 of every engine against the same sums evaluated numerically.

Only reciprocating masses are given in these files (the rotating ones are the counterweights'
business), so the figures are the textbooks' reciprocating ones.
"""

import cmath
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from tests.support import ROOT, TODAY

FAMILIES = ("inline", "v", "boxer", "w")
FILES = sorted(
    p.relative_to(TODAY).as_posix() for f in FAMILIES for p in (TODAY / f).glob("*.toml")
)
#: every file of the library; those of one crankshaft without offsets are FILES, which the
#: classic per-cylinder series checks too (the others: tests/analysis/test_crankshafts.py)
ALL_FILES = sorted(p.relative_to(TODAY).as_posix() for p in TODAY.rglob("*.toml"))
#: relative size of rounding noise in an exact cancellation (sums of 2-16 phasors of size 1,
#: FFT of 256 samples): far below any figure a textbook gives
NOISE = 1e-10
#: exact values against exact values: the library's kinematics are exact, A_k from a
#: 4096-point quadrature of an analytic periodic function is exact to rounding
EXACT = 1e-9


def slider_crank_a(lam, order, samples=4096):
    """A_k of the slider crank: x/r = cos φ + √(1/λ² − sin²φ) = Σ c_k cos kφ, and the inertia
    force −m·ẍ = m·r·ω²·Σ k²·c_k·cos kφ, so A_k = k²·c_k; c_k by the trapezoidal rule, which is
    exact to rounding for a smooth periodic integrand (its error falls like e^{−samples})."""
    phi = 2 * np.pi * np.arange(samples) / samples
    x = np.cos(phi) + np.sqrt(1 / lam**2 - np.sin(phi) ** 2)
    c_k = 2 * np.mean(x * np.cos(order * phi))
    return order**2 * c_k


def engine_of(name):
    return balance.load(TODAY / name)


def mrw2(engine):
    """m·r·ω² of one cylinder, N (every file has one reciprocating mass for all cylinders)."""
    masses = {c.reciprocating_kg for c in engine.cylinders}
    assert len(masses) == 1
    return masses.pop() * engine.crank_radius_m * engine.speed_rad_s**2


def parts(name, k, pitch=None):
    """Order k of engine ``name``: (F⁺, F⁻) / m·r·ω² and (M⁺, M⁻) / (m·r·ω²·pitch), complex;
    also A_k of its slider crank. ``pitch`` in m (default the first two throws' spacing)."""
    engine = engine_of(name)
    result = balance.analyse(engine, max_order=8)
    unit = mrw2(engine)
    if pitch is None:
        pitch = engine.throws[1].z_m - engine.throws[0].z_m if len(engine.throws) > 1 else 1.0
    o = result.order(k)
    a_k = slider_crank_a(engine.crank_radius_m / engine.rod_length_m, k)
    return (
        o.force_forward / unit,
        o.force_backward / unit,
        o.moment_forward / (unit * pitch),
        o.moment_backward / (unit * pitch),
        a_k,
        engine,
    )


def assert_zero(*values, scale=1.0):
    for v in values:
        assert abs(v) < NOISE * 16 * scale, v


def line_angle_deg(forward, backward):
    """Direction of a force (or moment) of equal forward and backward parts: it oscillates
    along e^{i(arg F⁺ + arg F⁻)/2}; degrees from the reference axis, in [0, 180)."""
    return math.degrees((cmath.phase(forward) + cmath.phase(backward)) / 2) % 180.0


def intervals(name):
    return tuple(round(i, 6) for i in balance.analyse(engine_of(name)).firing.intervals_deg)


def z_pitch(name, a, b):
    """Axial distance between throws a and b (1-based) of the file, m."""
    throws = engine_of(name).throws
    return throws[b - 1].z_m - throws[a - 1].z_m


def series(engine, k):
    """The classic per-cylinder sum of the module docstring (F⁺, F⁻, M⁺, M⁻), N and N·m."""
    lam = engine.crank_radius_m / engine.rod_length_m
    a_k = slider_crank_a(lam, k)
    zbar = np.mean([c.z_m for c in engine.cylinders])
    fp = fm = mp = mm = 0j
    for c in engine.cylinders:
        gamma = engine.bank_angles_rad[c.bank_index]
        beta = engine.throws[c.throw_index].phase_rad
        scale = c.reciprocating_kg * engine.crank_radius_m * engine.speed_rad_s**2 * a_k / 2
        plus = scale * cmath.exp(1j * (k * beta - (k - 1) * gamma))
        minus = scale * cmath.exp(1j * (-k * beta + (k + 1) * gamma))
        fp, fm = fp + plus, fm + minus
        mp, mm = mp + (c.z_m - zbar) * plus, mm + (c.z_m - zbar) * minus
    return fp, fm, mp, mm


# the in-line 5 crank 0-72-288-144-216 at z' = −2..2: |Σz'e^{iβ}| and |Σz'e^{2iβ}|, by hand
# −2 − e^{i72} + e^{i144} + 2e^{i216} = −4.7361 − 1.5388i and −2 − e^{i144} + e^{i288} + 2e^{i72}
# = −0.2639 + 0.3633i: the in-line 5's two numbers, this time the other way round
V10_S1 = math.sqrt(12.5 + 5.5 * math.sqrt(5))
V10_S2 = math.sqrt(12.5 - 5.5 * math.sqrt(5))


def test_library_holds_todays_engines_in_their_families():
    assert len(FILES) == 25
    assert {f.split("/")[0] for f in FILES} == set(FAMILIES)
    assert len(ALL_FILES) == 29
    assert {f.split("/")[0] for f in ALL_FILES} == set(FAMILIES) | {"vr", "h", "opposed-piston"}


@pytest.mark.parametrize("name", FILES)
def test_series_sum_agrees_for_every_order(name):
    """Every order 1-8 of every engine: the library's FFT of the exact kinematics against the
    per-cylinder series with exact A_k (the textbooks' method), forward and backward, with phase.
    Absolute tolerance EXACT·m·r·ω²·n (·1 m for moments): both sides are exact."""
    engine = engine_of(name)
    result = balance.analyse(engine, max_order=8)
    n = len(engine.cylinders)
    unit = mrw2(engine) * n
    for k in range(1, 9):
        o = result.order(k)
        fp, fm, mp, mm = series(engine, k)
        assert_allclose([o.force_forward, o.force_backward], [fp, fm], rtol=0, atol=EXACT * unit)
        assert_allclose([o.moment_forward, o.moment_backward], [mp, mm], rtol=0, atol=EXACT * unit)


def test_inline_2_360_is_a_single_cylinder_doubled():
    """β = 0, 0: F⁺ = F⁻ = 2·A_k/2 = A_k: a force 2·m·r·ω²·A_k along the axis (γ = 0);
    the two equal forces at ±d/2 make no couple. Firing 360°/360°."""
    name = "inline/inline-2-360.toml"
    for k in (1, 2):
        fp, fm, mp, mm, a, _ = parts(name, k)
        assert_allclose([fp, fm], [a, a], rtol=EXACT)
        assert_zero(mp, mm)
    assert intervals(name) == (360.0, 360.0)


def test_inline_2_180_primary_couple_and_secondary_force():
    """β = 0, 180°. Order 1: Σe^{iβ} = 0 (no force); Σz'e^{iβ} = −½ − ½ = −1: a couple of
    amplitude m·r·ω²·d (F⁺ = F⁻ = ½). Order 2: e^{2iβ} = 1, 1: force 2·A₂ along the axis,
    no couple. Firing 180°/540°."""
    name = "inline/inline-2-180.toml"
    fp, fm, mp, mm, _, _ = parts(name, 1)
    assert_zero(fp, fm)
    assert_allclose([abs(mp), abs(mm)], [0.5, 0.5], rtol=EXACT)
    fp, fm, mp, mm, a2, _ = parts(name, 2)
    assert_allclose([fp, fm], [a2, a2], rtol=EXACT)
    assert_zero(mp, mm)
    assert intervals(name) == (180.0, 540.0)


def test_inline_2_270_has_no_secondary_force():
    """β = 0, 90° (a 270° twin: cylinder 2 fires 270° after 1). Order 1: |1 + e^{i90}| = √2:
    a force √2·m·r·ω² along the axis; |−½ + ½e^{i90}| = 1/√2: couple amplitude d/√2.
    Order 2: 1 + e^{i180} = 0: no force; |−½ − ½| = 1: couple amplitude A₂·d."""
    name = "inline/inline-2-270.toml"
    fp, fm, mp, mm, _, _ = parts(name, 1)
    assert_allclose([abs(fp), abs(fm)], [math.sqrt(2) / 2] * 2, rtol=EXACT)
    assert_allclose([abs(mp) + abs(mm)], [1 / math.sqrt(2)], rtol=EXACT)
    assert_allclose(line_angle_deg(fp, fm), 0.0, atol=1e-9)
    fp, fm, mp, mm, a2, _ = parts(name, 2)
    assert_zero(fp, fm)
    assert_allclose(abs(mp) + abs(mm), a2, rtol=EXACT)
    assert intervals(name) == (270.0, 450.0)


def test_inline_3_couples_root_three():
    """β = 0, 120°, 240° at z' = −d, 0, d. Σe^{ikβ} = 0 for k = 1, 2: no force.
    |Σz'e^{iβ}| = |e^{i240} − 1|·d = √3·d, and the same for 2β (0, 240°, 120°): primary couple
    √3·m·r·ω²·d, secondary √3·m·r·ω²·A₂·d (amplitudes, along the axis: F⁺ = F⁻ = half)."""
    name = "inline/inline-3.toml"
    for k in (1, 2):
        fp, fm, mp, mm, a, _ = parts(name, k)
        assert_zero(fp, fm)
        assert_allclose(abs(mp) + abs(mm), math.sqrt(3) * a, rtol=EXACT)
        assert_allclose(abs(mp), abs(mm), rtol=EXACT)
    assert intervals(name) == (240.0,) * 3


def test_inline_4_secondary_force_four_a2():
    """β = 0, 180, 180, 0: e^{iβ} sums to 0, e^{2iβ} = e^{4iβ} = 1 each: forces 4·A₂ and 4·A₄
    along the axis; the crank is mirror-symmetric, so Σz'e^{ikβ} = 0: no couples."""
    name = "inline/inline-4.toml"
    fp, fm, mp, mm, _, _ = parts(name, 1)
    assert_zero(fp, fm, mp, mm)
    for k in (2, 4):
        fp, fm, mp, mm, a, _ = parts(name, k)
        assert_allclose([fp, fm], [2 * a, 2 * a], rtol=EXACT)
        assert_zero(mp, mm)
    # A₂ ≈ λ + λ³/4 + 15λ⁵/128: the quadrature agrees with the series to its first omitted term
    lam = 43 / 139
    assert_allclose(slider_crank_a(lam, 2), lam + lam**3 / 4 + 15 * lam**5 / 128, rtol=0.1 * lam**6)
    assert intervals(name) == (180.0,) * 4


def test_inline_5_couples():
    """Firing 1-2-4-5-3 every 144°: β = 0, 216, 144, 72, 288 at z' = −2d..2d.
    Σe^{iβ} = Σe^{2iβ} = 0 (fifth roots of unity). By hand:
    Σz'e^{iβ} = −2 − e^{i216} + e^{i72} + 2e^{i288} = −0.2639 − 0.3633i, |·| = 0.4490;
    Σz'e^{2iβ} = −2 − e^{i72} + e^{i144} + 2e^{i216} = −4.7361 − 1.5388i, |·| = 4.9798;
    in closed form √(25/2 ∓ 11√5/2). The textbook's 0.449 and 4.98 (m·r·ω²·d, ·A₂)."""
    name = "inline/inline-5.toml"
    small, large = math.sqrt(12.5 - 5.5 * math.sqrt(5)), math.sqrt(12.5 + 5.5 * math.sqrt(5))
    assert round(small, 3) == 0.449 and round(large, 2) == 4.98
    for k, expected in ((1, small), (2, large)):
        fp, fm, mp, mm, a, _ = parts(name, k)
        assert_zero(fp, fm)
        assert_allclose(abs(mp) + abs(mm), expected * a, rtol=EXACT)
    assert intervals(name) == (144.0,) * 5


@pytest.mark.parametrize(
    "name", ["inline/inline-6.toml", "v/v12-60.toml", "boxer/flat-12-180v.toml"]
)
def test_inline_6_and_its_derivatives_are_balanced_below_the_sixth_order(name):
    """In-line 6 crank 0-240-120-120-240-0: 2β and 4β run over 0, 120, 240 twice: Σe^{ikβ} = 0
    for k = 1, 2, 4 and, the crank being mirror-symmetric, Σz'e^{ikβ} = 0. A 60° V12 is two such
    banks on one crank; the flat 12 too. Orders 3 and 5 do not exist (A₃ = A₅ = 0)."""
    for k in (1, 2, 3, 4, 5):
        fp, fm, mp, mm, _, _ = parts(name, k)
        assert_zero(fp, fm, mp, mm)


def test_inline_6_sixth_order_force():
    """6β ≡ 0 on every throw: a force 6·A₆ along the axis (F⁺ = F⁻ = 3·A₆); no couple."""
    fp, fm, mp, mm, a6, _ = parts("inline/inline-6.toml", 6)
    assert_allclose(
        [fp, fm], [3 * a6, 3 * a6], rtol=1e-7
    )  # A₆ ~ 1e-4: rounding of the larger terms
    assert_zero(mp, mm)
    assert intervals("inline/inline-6.toml") == (120.0,) * 6


def test_inline_8_fourth_order_only():
    """Crank 0-180-270-90-90-270-180-0: Σe^{iβ} = Σe^{2iβ} = 0 and mirror symmetry: no force or
    couple of orders 1, 2; 4β ≡ 0: a fourth-order force 8·A₄ (F⁺ = F⁻ = 4·A₄), no couple."""
    name = "inline/inline-8.toml"
    for k in (1, 2):
        assert_zero(*parts(name, k)[:4])
    fp, fm, mp, mm, a4, _ = parts(name, 4)
    assert_allclose([fp, fm], [4 * a4, 4 * a4], rtol=1e-7)
    assert_zero(mp, mm)
    assert intervals(name) == (90.0,) * 8


def test_v_twin_45_primary_ellipse_and_315_405_firing():
    """γ = ±22.5°, one pin (β = 0). Order 1: F⁺ = 2·½ = 1; F⁻ = ½(e^{i45} + e^{−i45}) = cos 45°.
    Order 2: F⁺ = A₂/2·(e^{−i22.5} + e^{i22.5}) = A₂·cos 22.5°; F⁻ = A₂/2·(e^{i67.5} + e^{−i67.5})
    = A₂·cos 67.5°. The front cylinder fires, the rear 360° − 45° later: 315°/405°."""
    name = "v/v-twin-45.toml"
    fp, fm, _, _, _, _ = parts(name, 1)
    assert_allclose([abs(fp), abs(fm)], [1.0, math.cos(math.radians(45))], rtol=EXACT)
    fp, fm, _, _, a2, _ = parts(name, 2)
    assert_allclose(
        [abs(fp), abs(fm)],
        [a2 * math.cos(math.radians(22.5)), a2 * math.cos(math.radians(67.5))],
        rtol=EXACT,
    )
    assert intervals(name) == (315.0, 405.0)


def test_v_twin_90_primary_rotates_at_constant_magnitude():
    """γ = ±45°: F⁻ = ½(e^{i90} + e^{−i90}) = 0, F⁺ = 1: a force m·r·ω² of constant magnitude
    turning with the crank, which a counterweight m·r opposite the pin cancels. Order 2:
    F⁺ = A₂·cos 45°, F⁻ = A₂/2·|e^{i135} + e^{−i135}| = A₂·cos 45°: a line of amplitude √2·A₂,
    F⁺ = A₂·cos 45° (argument 0) and F⁻ = −A₂·cos 45° (argument 180°): the line
    e^{i(0 + 180°)/2} is horizontal, 90° from the bisector (the engine's vertical, here the
    reference axis). Firing 270°/450°."""
    name = "v/v-twin-90.toml"
    fp, fm, _, _, _, engine = parts(name, 1)
    assert_allclose(abs(fp), 1.0, rtol=EXACT)
    assert_zero(fm)
    fp, fm, _, _, a2, _ = parts(name, 2)
    assert_allclose(abs(fp) + abs(fm), math.sqrt(2) * a2, rtol=EXACT)
    assert_allclose(abs(fp), abs(fm), rtol=EXACT)
    assert_allclose(line_angle_deg(fp, fm), 90.0, atol=1e-6)
    # a counterweight of m·r opposite the pin leaves no primary force at all
    # (the file's m = 0.50 kg: a mass m at the crank radius), and leaves the second order as it was
    cw = balance.counterweights(engine, planes=[1], radius_m=engine.crank_radius_m)
    assert_allclose(cw.counterweights[0].mass_kg, 0.50, rtol=1e-9)
    first = cw.residual.orders[0]
    assert_zero(first.force_forward / mrw2(engine), first.force_backward / mrw2(engine))
    assert intervals(name) == (270.0, 450.0)


def test_v4_90_180_rotating_primary_couple_and_horizontal_secondary():
    """Two 90° twins on pins β = 0, 180° at z' = ∓d/2. Order 1: F⁺ = Σe^{iβ} = 0; each pin's F⁻
    is 0 (as the 90° twin's): no force; M⁺ = −½·1 + ½·e^{i180} = −1: a couple m·r·ω²·d turning
    with the crank (M⁻ = 0: counterweights cancel it). Order 2: e^{2iβ} = 1 on both pins: the
    twins' horizontal √2·A₂ add to 2√2·A₂, and cancel in the couple. Firing 180-270-180-90."""
    name = "v/v4-90-180.toml"
    fp, fm, mp, mm, _, _ = parts(name, 1)
    assert_zero(fp, fm, mm)
    assert_allclose(abs(mp), 1.0, rtol=EXACT)
    fp, fm, mp, mm, a2, _ = parts(name, 2)
    assert_allclose(abs(fp) + abs(fm), 2 * math.sqrt(2) * a2, rtol=EXACT)
    assert_allclose(line_angle_deg(fp, fm), 90.0, atol=1e-6)
    assert_zero(mp, mm)
    assert intervals(name) == (180.0, 270.0, 180.0, 90.0)


def test_v6_60_split_pin_couples():
    """Banks γ = −30° (1, 3, 5), +30° (2, 4, 6); firing 1-2-3-4-5-6 every 120° puts the pins at
    β = (0, 300), (120, 60), (240, 180) for the pairs at z' = −d, 0, d.
    Forces: the six β are 60° apart: Σe^{iβ} = Σe^{2iβ} = 0; F⁻ pairs e^{2iγ}e^{−iβ} likewise.
    M1⁺ = ½[−(1 + e^{−i60}) + (e^{i240} + e^{i180})] = ½(−3): 3/2·d, rotating;
    M1⁻ = ½Σz'e^{2iγ}e^{−iβ}: pair 1 e^{−i60} + e^{i60}e^{−i300} = 0, pair 3 likewise: 0.
    M2⁺ = A₂/2·Σz'e^{2iβ}e^{−iγ}: e^{i30} + e^{−i30}e^{i600} = 0 per end pair: 0;
    M2⁻ = A₂/2·Σz'e^{−2iβ}e^{3iγ} = A₂/2·i·[2 − 2 cos 120°] = 3/2·A₂·d, turning backward.
    So a rotating primary couple (counterweights cancel it) and a counter-rotating secondary one."""
    name = "v/v6-60-split-pin.toml"
    d = z_pitch(name, 1, 3)
    fp, fm, mp, mm, _, _ = parts(name, 1, d)
    assert_zero(fp, fm, mm)
    assert_allclose(abs(mp), 1.5, rtol=EXACT)
    fp, fm, mp, mm, a2, _ = parts(name, 2, d)
    assert_zero(fp, fm, mp)
    assert_allclose(abs(mm), 1.5 * a2, rtol=EXACT)
    assert intervals(name) == (120.0,) * 6


def test_v6_90_odd_fire_couples_and_intervals():
    """Banks γ = 45° (odd), −45° (even), common pins β = 0, 240, 120 at z' = −d, 0, d (an in-line
    3's crank). Forces of orders 1, 2 vanish (Σe^{ikβ} = 0). M1⁺ = Σz'e^{iβ} = √3·d (two
    cylinders of ½ each), M1⁻ = 0 (e^{2iγ} = ±i cancel on each pin). Order 2:
    |e^{−i45} + e^{i45}| = |e^{i135} + e^{−i135}| = √2, so M2⁺ = M2⁻ = A₂/2·√3·√2: a couple of
    amplitude √6·A₂·d along a fixed line. Firing 1-6-5-4-3-2 at 150° and 90° alternately."""
    name = "v/v6-90-odd-fire.toml"
    fp, fm, mp, mm, _, _ = parts(name, 1)
    assert_zero(fp, fm, mm)
    assert_allclose(abs(mp), math.sqrt(3), rtol=EXACT)
    fp, fm, mp, mm, a2, _ = parts(name, 2)
    assert_zero(fp, fm)
    assert_allclose([abs(mp), abs(mm)], [math.sqrt(6) / 2 * a2] * 2, rtol=EXACT)
    assert intervals(name) == (150.0, 90.0) * 3


def test_v6_90_split_pin_even_fire():
    """Banks γ = 45° (odd), −45° (even); firing 1-6-5-4-3-2 every 120° puts the pins at
    β = (0, 30), (240, 270), (120, 150): 30° split. With S = 1 + e^{i30}:
    M1⁺ = ½·S·(e^{i120} − 1): |·| = ½·2cos 15°·√3 = √3·cos 15°·d;
    M1⁻ = ½·i(1 − e^{−i30})(e^{−i120} − 1): √3·sin 15°·d;
    M2⁺ = A₂/2·(e^{−i45} + e^{i105})(e^{i240} − 1): √3·cos 75° = √3·sin 15°·A₂·d;
    M2⁻ = A₂/2·(e^{i135} + e^{i165})(e^{−i240} − 1): √3·cos 15°·A₂·d. No forces of orders 1, 2."""
    name = "v/v6-90-split-pin.toml"
    d = z_pitch(name, 1, 3)
    c, s = math.cos(math.radians(15)), math.sin(math.radians(15))
    fp, fm, mp, mm, _, _ = parts(name, 1, d)
    assert_zero(fp, fm)
    assert_allclose([abs(mp), abs(mm)], [math.sqrt(3) * c, math.sqrt(3) * s], rtol=EXACT)
    fp, fm, mp, mm, a2, _ = parts(name, 2, d)
    assert_zero(fp, fm)
    assert_allclose([abs(mp), abs(mm)], [math.sqrt(3) * s * a2, math.sqrt(3) * c * a2], rtol=EXACT)
    assert intervals(name) == (120.0,) * 6


def test_v8_cross_plane_primary_couple_root_ten():
    """Pins 0-90-270-180 at z' = −1.5, −0.5, 0.5, 1.5 (d), two cylinders of ½ each:
    M1⁺ = Σz'e^{iβ} = −1.5 − 0.5i − 0.5i − 1.5 = −3 − i: √10·d, turning with the crank; M1⁻ = 0
    (γ = ±45°). Order 2: e^{2iβ} = 1, −1, −1, 1 sums to 0 and, the crank being symmetric, so
    does Σz'e^{2iβ} = −1.5 + 0.5 − 0.5 + 1.5 = 0: no secondary force or couple."""
    name = "v/v8-90-cross-plane.toml"
    fp, fm, mp, mm, _, _ = parts(name, 1)
    assert_zero(fp, fm, mm)
    assert_allclose(abs(mp), math.sqrt(10), rtol=EXACT)
    assert_zero(*parts(name, 2)[:4])
    assert intervals(name) == (90.0,) * 8


def test_v8_flat_plane_secondary_four_root_two_horizontal():
    """Two flat fours at γ = ∓45°: no primary force or couple; each bank's secondary 4·A₂ along
    its axis, e^{2i(θ − γ)} 180° apart between the banks: the vertical parts cancel, the
    horizontal ones add to 2·4·A₂·sin 45° = 4√2·A₂ (Tanaka's .215 per cylinder at λ = .297)."""
    name = "v/v8-90-flat-plane.toml"
    assert_zero(*parts(name, 1)[:4])
    fp, fm, mp, mm, a2, _ = parts(name, 2)
    assert_allclose(abs(fp) + abs(fm), 4 * math.sqrt(2) * a2, rtol=EXACT)
    assert_allclose(abs(fp), abs(fm), rtol=EXACT)
    assert_allclose(line_angle_deg(fp, fm), 90.0, atol=1e-6)
    assert_zero(mp, mm)
    assert intervals(name) == (90.0,) * 8


def test_v10_72_in_line_5_crank_couples():
    """Common pins, γ = ∓36°. M1⁺ = |S1|·d (two cylinders of ½); M1⁻ = ½|e^{−i72} + e^{i72}|·|S1|
    = cos 72°·|S1|; M2⁺ = A₂/2·|e^{i36} + e^{−i36}|·|S2| = cos 36°·A₂·|S2|;
    M2⁻ = A₂/2·|e^{−i108} + e^{i108}|·|S2| = |cos 108°|·A₂·|S2|. No forces of
    orders 1, 2 (fifth roots of unity); firing every 72°."""
    name = "v/v10-72.toml"
    fp, fm, mp, mm, _, _ = parts(name, 1)
    assert_zero(fp, fm)
    assert_allclose([abs(mp), abs(mm)], [V10_S1, math.cos(math.radians(72)) * V10_S1], rtol=EXACT)
    fp, fm, mp, mm, a2, _ = parts(name, 2)
    assert_zero(fp, fm)
    assert_allclose(
        [abs(mp), abs(mm)],
        [math.cos(math.radians(36)) * a2 * V10_S2, abs(math.cos(math.radians(108))) * a2 * V10_S2],
        rtol=EXACT,
    )
    assert intervals(name) == (72.0,) * 10


def test_v10_90_split_pin_couples():
    """γ = −45° (1-5), +45° (6-10); firing 1-6-5-10-2-7-3-8-4-9 puts pair bases
    b = 0-72-288-144-216 (the in-line 5 crank above) and each bank-2 pin 18° on.
    M1⁺ = ½|1 + e^{i18}|·|S1| = cos 9°·|S1|; M1⁻ = ½|−i + i·e^{−i18}|·|S1| = sin 9°·|S1|;
    M2⁺ = A₂/2·|e^{i45} + e^{−i9}|·|S2| = cos 27°·A₂·|S2|;
    M2⁻ = A₂/2·|e^{−i135} + e^{i99}|·|S2| = sin 27°·A₂·|S2|. No forces of orders 1, 2."""
    name = "v/v10-90-split-pin.toml"
    d = z_pitch(name, 1, 3)
    fp, fm, mp, mm, _, _ = parts(name, 1, d)
    assert_zero(fp, fm)
    assert_allclose(
        [abs(mp), abs(mm)],
        [math.cos(math.radians(9)) * V10_S1, math.sin(math.radians(9)) * V10_S1],
        rtol=EXACT,
    )
    fp, fm, mp, mm, a2, _ = parts(name, 2, d)
    assert_zero(fp, fm)
    assert_allclose(
        [abs(mp), abs(mm)],
        [math.cos(math.radians(27)) * a2 * V10_S2, math.sin(math.radians(27)) * a2 * V10_S2],
        rtol=EXACT,
    )
    assert intervals(name) == (72.0,) * 10


def test_v12_60_sixth_order_along_the_bisector():
    """Each bank an in-line 6 (force 6·A₆ along its axis, phase 6(θ − γ)); γ = ∓30° makes the
    phases 6·60° = 360° apart: in phase; the sum of 6·A₆·e^{∓i30°} is 2·6·A₆·cos 30° = 6√3·A₆
    along the bisector (the engine's vertical). Firing every 60°."""
    name = "v/v12-60.toml"
    fp, fm, mp, mm, a6, _ = parts(name, 6)
    assert_allclose(abs(fp) + abs(fm), 6 * math.sqrt(3) * a6, rtol=1e-7)
    assert_allclose(abs(fp), abs(fm), rtol=1e-7)
    assert_allclose(line_angle_deg(fp, fm), 0.0, atol=1e-4)
    assert_zero(mp, mm)
    assert intervals(name) == (60.0,) * 12


def test_boxer_2_rocking_couples_no_forces():
    """Opposed cylinders (γ = ±90°) on throws 180° apart: φ is the same for both, the axes
    opposite: the forces cancel in every order; they are d apart, so the couple of order k has
    amplitude A_k·d (F⁺ = F⁻ = ½A_k·d). Firing 360°/360°."""
    name = "boxer/boxer-2.toml"
    for k in (1, 2, 4):
        fp, fm, mp, mm, a, _ = parts(name, k)
        assert_zero(fp, fm)
        assert_allclose([abs(mp), abs(mm)], [abs(a) / 2] * 2, rtol=1e-9)
    assert intervals(name) == (360.0, 360.0)


def test_boxer_4_secondary_rocking_couple():
    """Two opposed pairs, each a boxer twin of offset d, their throws 180° apart: the primary
    couples cancel (cos(φ + 180°) = −cos φ), the secondary ones add: 2·A₂·d along a line.
    Firing 1-3-2-4 every 180°."""
    name = "boxer/boxer-4.toml"
    assert_zero(*parts(name, 1)[:4])
    fp, fm, mp, mm, a2, _ = parts(name, 2)
    assert_zero(fp, fm)
    assert_allclose([abs(mp), abs(mm)], [a2, a2], rtol=EXACT)
    assert intervals(name) == (180.0,) * 4


def test_boxer_6_balanced_below_sixth_order_then_pair_couples_add():
    """Three opposed pairs of offset d (44 mm) whose throws are 120° apart: no forces in any
    order; their couples have phases kβ over 0, 120, 240: zero for k = 1, 2, 4; for k = 6 they
    add to 3·A₆·d (F⁺ = F⁻ = 1.5·A₆·d). Firing 1-6-2-4-3-5 every 120°."""
    name = "boxer/boxer-6.toml"
    d = z_pitch(name, 1, 2)
    for k in (1, 2, 4):
        assert_zero(*parts(name, k, d)[:4])
    fp, fm, mp, mm, a6, _ = parts(name, 6, d)
    assert_zero(fp, fm)
    assert_allclose([abs(mp), abs(mm)], [1.5 * a6, 1.5 * a6], rtol=1e-7)
    assert intervals(name) == (120.0,) * 6


def test_flat_12_has_nothing_in_any_order():
    """180° V on the in-line 6 crank: two opposed cylinders on one pin have φ 180° apart and
    opposite axes: odd orders add, even orders cancel; the crank cancels the odd (first) order:
    nothing remains in orders 1-8, forces or couples. Firing every 60°."""
    name = "boxer/flat-12-180v.toml"
    for k in range(1, 9):
        assert_zero(*parts(name, k)[:4])
    assert intervals(name) == (60.0,) * 12


def test_w16_primary_couple_only():
    """Banks −52.5, −37.5, 37.5, 52.5; odd pins carry the −52.5° and 37.5° rows, even pins the
    −37.5° and 52.5° rows: each pin's two cylinders 90° apart. Odd pins 0-90-270-180 at
    z' = −3.5, −1.5, 0.5, 2.5 (d), even pins 60-150-330-240 at −2.5, −0.5, 1.5, 3.5.
    Forces: Σe^{iβ} = 0 and e^{2iγ} cancel per pin (order 1); per pin e^{−iγ} sum to √2·e^{i7.5}
    (odd) and alike (even), times Σe^{2iβ} = 0 (order 2). M1⁺ = Σz'e^{iβ} = (−6 − 2i)(1 + e^{i60}):
    √40·√3 = √120·d; M1⁻ = 0; M2: Σz'e^{2iβ} = 0 over each set of pins. Firing every 45°."""
    name = "w/w16-bugatti.toml"
    d = z_pitch(name, 1, 2)
    fp, fm, mp, mm, _, _ = parts(name, 1, d)
    assert_zero(fp, fm, mm)
    assert_allclose(abs(mp), math.sqrt(120), rtol=EXACT)
    assert_zero(*parts(name, 2, d)[:4])
    assert intervals(name) == (45.0,) * 16


def test_library_table_is_current():
    """configs/README.md is generated by tools/library_table.py and committed."""
    from tools import library_table

    committed = library_table.TARGET.read_text(encoding="utf-8")
    assert committed == library_table.render(), (
        "configs/README.md is out of date: run python tools/library_table.py"
    )


def test_library_table_figures_match_the_hand_derivations():
    """Spot checks of the table against the closed forms above, by hand: the cross-plane V8's
    M1 = √10·m·r·ω²·d with m = 0.75 kg, r = 46 mm, ω = 6000 rpm, d = 111.76 mm; the 90° twin's
    F1 per cylinder = 1/2; the in-line 2-270's F1 per cylinder = √2/2."""
    text = (ROOT / "configs" / "README.md").read_text(encoding="utf-8")
    rows = {
        line.split("|")[1].strip().split("]")[0].lstrip("["): [
            c.strip() for c in line.split("|")[1:-1]
        ]
        for line in text.splitlines()
        if line.startswith("| [today/")
    }
    omega = 6000 * 2 * math.pi / 60
    m1 = math.sqrt(10) * 0.75 * 0.046 * omega**2 * 0.11176
    assert float(rows["today/v/v8-90-cross-plane.toml"][7]) == pytest.approx(
        m1, rel=5e-3
    )  # 3 digits
    assert float(rows["today/v/v-twin-90.toml"][6]) == pytest.approx(0.5, rel=5e-3)
    assert float(rows["today/inline/inline-2-270.toml"][6]) == pytest.approx(
        math.sqrt(2) / 2, rel=5e-3
    )


@pytest.mark.parametrize("name", ALL_FILES)
def test_each_file_names_its_engine_marks_estimates_and_states_its_balance(name):
    """Each file gives a source key, the real engine in a comment block, estimates said to
    be estimates, and the textbook (or, for the W16, a derived) statement of the balance."""
    engine = engine_of(name)
    assert engine.source
    comment = [
        line
        for line in (TODAY / name).read_text(encoding="utf-8").splitlines()
        if line.startswith("#")
    ]
    text = " ".join(comment)
    assert len(comment) >= 4
    assert "estimate" in text
    assert "Textbook" in text or "Derived statement" in text
