"""Counterweights, balancer shafts, the antivibrateur and test masses, against the papers and
hand-derived closed forms."""

import dataclasses
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli import load
from balance_cli.analysis.balancing import Plane
from balance_cli.analysis.counterweight import counterweights
from balance_cli.analysis.planes import plane_at_throw
from balance_cli.errors import CounterweightError
from tests.support import BRAMO, CONFIGS, V12, exact_b, make_engine

W12 = CONFIGS / "nakanishi-w12-60-2stroke.toml"
# Nakanishi's masses in the library configurations (kg) and throw pitch d (m)
M_P, M_C, A, B, M_K, D = 2.0, 2.4, 0.65, 0.35, 2.0, 0.150


def assert_nothing_below(shaking_, order, unit):
    for o in shaking_.orders[: order - 1]:
        for value in (o.force_forward, o.force_backward, o.moment_forward, o.moment_backward):
            assert abs(value) < 1e-9 * unit, (o.order, value)


def bramo_with_angular_eccentricity(epsilon, rho=6.0):
    """Fraeys de Veubeke § IV.2: sin ε_n = ε·λ·sin ψ_n, and the radii that keep the compression
    ratio ρ (§ 7): r_n = (L − l)/(1 − ½λ²f1·sin²ψ_n), f1 = 1 − 2ε(ρ + 1)/(ρ − 1) + ε².
    His positive ε (which evens out the top dead centres) turns the knuckle pin ahead of its
    cylinder in our sense of angles: ψ_n = Φ_n + ε_n (checked in test_eccentricity_sign)."""
    engine = load(BRAMO)
    lam = engine.crank_radius_m / engine.rod_length_m
    f1 = 1 - 2 * epsilon * (rho + 1) / (rho - 1) + epsilon**2
    cylinders = []
    for c in engine.cylinders:
        if c.is_link:
            phi = engine.bank_angles_rad[c.bank_index]
            psi = phi
            for _ in range(60):  # fixed point of ψ = Φ + asin(ε·λ·sin ψ)
                psi = phi + math.asin(epsilon * lam * math.sin(psi))
            radius = (engine.rod_length_m - c.link_length_m) / (
                1 - 0.5 * lam**2 * f1 * math.sin(psi) ** 2
            )
            c = dataclasses.replace(c, knuckle_angle_rad=psi, knuckle_radius_m=radius)
        cylinders.append(c)
    return dataclasses.replace(engine, cylinders=tuple(cylinders))


def _inline4_pair(offsets):
    engine = load(CONFIGS / "inline-4-car.toml")
    lam = exact_b(engine.crank_radius_m / engine.rod_length_m, 2)
    # the pair opposes 4·B2·m·r·ω²·cos 2θ (along the reference axis, the vertical): each shaft's
    # force is P·e^{±2iθ} with P = −2·B2·m·r·ω²
    p = -2 * lam * engine.mean_reciprocating_kg * engine.crank_radius_m * engine.speed_rad_s**2
    return engine, counterweights(engine, shaft_orders=(2,), shaft_offsets_m=offsets), p


def test_nakanishi_v12_counterweights_on_throws_1_and_6():
    """§ 4: m_w = (2√3/5)·(r/r_w)·{m_p + (2a + b)·m_c + m_k}; afterwards nothing below the 6th."""
    engine = load(V12)
    r_w = 0.060
    result = counterweights(
        engine, [plane_at_throw(engine, 1), plane_at_throw(engine, 6)], radius_m=r_w, max_order=8
    )
    expected = (
        2 * math.sqrt(3) / 5 * (engine.crank_radius_m / r_w) * (M_P + (2 * A + B) * M_C + M_K)
    )
    for weight in result.counterweights:
        assert_allclose(weight.mass_kg, expected, rtol=1e-9)
    # opposite each other: a pure couple
    assert_allclose(
        abs(result.counterweights[0].angle_deg - result.counterweights[1].angle_deg), 180, atol=1e-9
    )
    assert_nothing_below(result.residual, 6, engine.unit_force_n * engine.n_cylinders)


def test_nakanishi_w12_counterweights_on_throws_1_and_4():
    """§ 7: the couple √10·d·{3/2·m_p + 3(a + b/2)·m_c + m_k}·ω²r at φ = tan⁻¹(−1/3) from two
    masses 3d apart: m_w = (√10/3)·(r/r_w)·{…}; afterwards nothing below the 4th order."""
    engine = load(W12)
    result = counterweights(engine, [plane_at_throw(engine, 1), plane_at_throw(engine, 4)])
    mass = 1.5 * M_P + 3 * (A + B / 2) * M_C + M_K
    for weight in result.counterweights:
        assert_allclose(weight.mass_kg, math.sqrt(10) / 3 * mass, rtol=1e-9)
    # each counterweight at ±tan⁻¹(1/3) off the line of throws 1 and 4 (or its opposite)
    offset = math.radians(result.counterweights[0].angle_deg)
    assert_allclose(abs(math.tan(offset)), 1 / 3, rtol=1e-9)
    assert_nothing_below(result.residual, 4, engine.unit_force_n * engine.n_cylinders)


def test_bramo_counterweight_is_fraeys_de_veubeke_s1():
    """§ IV.4, Table XV (ε = 0): gG = gB(1 − K) + g(n − 1)b(1 − k) + ½g[np + (n − 1)bk + BK] + ½gm
    = 31.6071 + 0.0693 = 31.6764 kg at crank radius, from Table IX's masses. The configuration
    derives them from Table VIII's parts, where Table IX's gB(1 − K) and gBK carry a slip of
    0.0005 kg (reference records F-IX-*): with it and the 5th-order truncation (μ⁶·A ≈ 0.0004
    kg), 0.0012 kg."""
    engine = load(BRAMO)
    result = counterweights(engine)
    (weight,) = result.counterweights
    assert_allclose(weight.mass_kg, 31.6764, atol=0.0012)
    # the same from the formula with the configuration's own masses; m by (13) from them
    links = [c for c in engine.cylinders if c.is_link]
    m = (
        -sum(
            c.knuckle_kg * c.knuckle_radius_m * math.cos(engine.bank_angles_rad[c.bank_index])
            for c in links
        )
        / engine.rod_length_m
    )
    formula = (
        engine.rotating_kg
        + sum(c.knuckle_kg for c in links)
        + 0.5 * sum(c.reciprocating_kg for c in engine.cylinders)
        + 0.5 * m
    )
    assert_allclose(m, 0.1386, atol=5e-5)
    assert_allclose(weight.mass_kg, formula, atol=0.0005)
    assert_allclose(weight.angle_deg, 180.0, atol=1e-9)  # opposite the crank pin
    # S−1 is left untouched: Table XII's 0.215 kg (× RΩ²), exact 0.2140
    r_omega2 = engine.crank_radius_m * engine.speed_rad_s**2
    assert_allclose(abs(result.residual.orders[0].force_backward) / r_omega2, 0.215, rtol=0.016)
    assert abs(result.residual.orders[0].force_forward) < 1e-9 * r_omega2


def test_bramo_antivibrateur():
    """§ IV.6: a rotor on the crank pin at twice crank speed; Fraeys sizes it on the principal
    perturbation gP = 2.17276 kg: |g·M·e| = gP·R/4 = 43.45 kg·mm. Sized on the exact S2 it
    must be larger in the ratio |S2|/gP, to the printed digits (43.45: ±1.2e-4). It removes S2
    entirely (Table XIX: 98.98 %) and leaves S−1, which it cannot touch, unchanged."""
    engine = load(BRAMO)
    plain = counterweights(engine)
    result = counterweights(engine, antivibrateur_radius_m=0.040)
    r_omega2 = engine.crank_radius_m * engine.speed_rad_s**2
    s2 = abs(plain.residual.orders[1].force_forward) / r_omega2
    me_kg_mm = result.antivibrateur.mass_eccentricity_kgm * 1000
    assert_allclose(me_kg_mm / 43.45, s2 / 2.17276, rtol=3e-4)
    assert abs(result.residual.orders[1].force_forward) < 1e-9 * r_omega2  # S2: 100 % reduction
    assert_allclose(
        result.residual.orders[0].force_backward,
        plain.residual.orders[0].force_backward,
        rtol=1e-12,
    )
    # its mass rides on the pin: the counterweight grows by exactly M
    assert_allclose(
        result.counterweights[0].mass_kg - plain.counterweights[0].mass_kg,
        result.antivibrateur.mass_kg,
        rtol=1e-9,
    )


def test_inline4_lanchester_pair():
    """Secondary 4·B2·m·r·ω² cos 2θ = 2·B2·m·r·ω²(e^{2iθ} + e^{−2iθ}): two shafts at 2× speed,
    one each way, each m·e·(2ω)² = 2·B2·m·r·ω², i.e. m·e = m_rec·r·λ'/2 with λ' = B2 exact."""
    engine = load(CONFIGS / "inline-4-car.toml")
    result = counterweights(engine, shaft_orders=(2,))
    lam = exact_b(engine.crank_radius_m / engine.rod_length_m, 2)
    expected = engine.mean_reciprocating_kg * engine.crank_radius_m * lam / 2
    assert sorted(s.speed_ratio for s in result.shafts) == [-2, 2]
    for shaft in result.shafts:
        assert_allclose(shaft.mass_eccentricity_kgm, expected, rtol=1e-9)
        assert_allclose(shaft.z_m, np.mean([c.z_m for c in engine.cylinders]), atol=1e-12)
    second = result.after_shafts.orders[1]
    assert abs(second.force_forward) + abs(second.force_backward) < 1e-9 * engine.unit_force_n


def test_shaft_pairs_cancel_a_moment():
    """A two-throw 180° twin has a primary couple; with two planes the forward first order's
    moment is met by counterweights, and the backward couple by a pair of counter-rotating
    shafts apart: afterwards no first order at all."""
    engine = make_engine([0], [(0, -0.05), (180, 0.05)])
    result = counterweights(engine, shaft_orders=(1,))
    backward = [s for s in result.shafts if s.speed_ratio == -1]
    assert len(backward) == 2
    assert_allclose(backward[0].mass_eccentricity_kgm, backward[1].mass_eccentricity_kgm, rtol=1e-9)
    assert_allclose(abs(backward[0].phase_deg - backward[1].phase_deg), 180, atol=1e-9)
    # each: the backward couple ½·m·r·ω²·0.1 m over the 0.1 m between the planes, at ω²
    assert_allclose(backward[0].mass_eccentricity_kgm, 0.5 * 1.0 * engine.crank_radius_m, rtol=1e-9)
    first = result.after_shafts.orders[0]
    for value in (
        first.force_forward,
        first.force_backward,
        first.moment_forward,
        first.moment_backward,
    ):
        assert abs(value) < 1e-9 * engine.unit_force_n


@pytest.mark.parametrize("factor", [0.0, 0.3, 0.5, 0.7, 1.0])
def test_single_cylinder_balance_factor(factor):
    """m·r·ω² cos θ = ½m·r·ω²(e^{iθ} + e^{−iθ}); a counterweight c·m opposite the crank adds
    −c·m·r·ω²e^{iθ}: forward |1 − 2c|/2, backward 1/2 of m·r·ω² (rotating mass cancelled)."""
    engine = make_engine([0], [(0, 0.0)], rotating=0.8)
    result = counterweights(engine, balance_factor=factor)
    first = result.residual.orders[0]
    unit = engine.unit_force_n
    assert_allclose(abs(first.force_forward) / unit, abs(1 - 2 * factor) / 2, atol=1e-12)
    assert_allclose(abs(first.force_backward) / unit, 0.5, atol=1e-12)


def test_half_balanced_single_leaves_a_constant_force_turning_backward():
    engine = make_engine([0], [(0, 0.0)], r=0.05, rod=0.2)
    residual = counterweights(engine, balance_factor=0.5, max_order=8).residual
    first = residual.orders[0]
    theta = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    primary = first.force_forward * np.exp(1j * theta) + first.force_backward * np.exp(-1j * theta)
    assert_allclose(np.abs(primary), engine.unit_force_n / 2, rtol=1e-12)


def test_test_masses_are_nakanishis():
    """§ 4: m_p + (2a + b)·m_c on each pin of the V12; § 7: 3/2·m_p + 3(a + b/2)·m_c on each
    pin of the W12 (the crank's own m_k stays on the shaft)."""
    v12 = counterweights(load(V12), test_masses=True)
    assert_allclose(v12.test_masses_kg, [M_P + (2 * A + B) * M_C] * 6, rtol=1e-9)
    w12 = counterweights(load(W12), test_masses=True)
    assert_allclose(w12.test_masses_kg, [1.5 * M_P + 3 * (A + B / 2) * M_C] * 4, rtol=1e-9)


def test_shaft_with_test_masses_runs_balanced_on_the_machine():
    """Second method, by hand: on the machine each pin carries its test mass plus the crank's
    own m_k, a forward first order Σ (m_test + m_k)·r·ω²·e^{iβ_j} and its moment about z̄;
    the engine's counterweights (m·ρ·ω²·e^{iφ} in their planes) must cancel both exactly."""
    engine = load(V12)
    result = counterweights(
        engine, [plane_at_throw(engine, 1), plane_at_throw(engine, 6)], test_masses=True
    )
    omega2, r, z_mean = engine.speed_rad_s**2, engine.crank_radius_m, engine.mean_z_m
    force = moment = 0j
    for throw, mass in zip(engine.throws, result.test_masses_kg, strict=True):
        phasor = (mass + engine.crank_kg) * r * omega2 * np.exp(1j * throw.phase_rad)
        force += phasor
        moment += (throw.z_m - z_mean) * phasor
    for weight in result.counterweights:
        phasor = (
            weight.mass_kg * weight.radius_m * omega2 * np.exp(1j * np.radians(weight.angle_deg))
        )
        force += phasor
        moment += (weight.plane.z_m - z_mean) * phasor
    scale = engine.per_cylinder_unit_n
    assert abs(force) < 1e-9 * scale and abs(moment) < 1e-9 * scale


def test_one_plane_cancels_the_force_and_reports_the_moment_left():
    engine = load(V12)
    result = counterweights(engine, [plane_at_throw(engine, 1)])
    first = result.residual.orders[0]
    assert abs(first.force_forward) < 1e-9 * engine.unit_force_n
    assert_allclose(
        abs(first.moment_forward), abs(result.original.orders[0].moment_forward), rtol=1e-9
    )


@pytest.mark.parametrize(
    "kwargs, words",
    [
        (dict(planes=[Plane(0.0, 1), Plane(0.0, 1)]), "coincide"),
        (dict(planes=[Plane(0.0), Plane(0.1), Plane(0.2)]), "one plane"),
        (dict(radius_m=0.0), "greater than zero"),
        (dict(radius_m=-0.05), "greater than zero"),
        (dict(shaft_orders=(99,)), r"outside the orders analysed \(1 to 8"),
        (dict(antivibrateur_radius_m=0.04), "single-throw"),
    ],
)
def test_bad_requests(kwargs, words):
    with pytest.raises(CounterweightError, match=words):
        counterweights(load(V12), **kwargs)


def test_eccentricity_sign():
    """§ 7: ε = +1 (sin ε_n = λ sin ψ_n) spaces the top dead centres regularly, to second order."""
    from balance_cli.kinematics import tdc_angles

    def worst(epsilon):
        tdc = tdc_angles(bramo_with_angular_eccentricity(epsilon))
        return max(abs((tdc[n] - 40 * (n - 1) + 180) % 360 - 180) for n in tdc)

    # ε = +1 leaves only third-order irregularity (under 1°); ε = 0 about 3.6°, ε = −1 more
    assert worst(1) < 1.0 < worst(0) < worst(-1)


@pytest.mark.parametrize("epsilon, s1", [(-1, 30.9999), (0, 31.6764), (1, 32.2766)])
def test_bramo_counterweight_with_angular_eccentricity(epsilon, s1):
    """Table XV, 'S1 réel': the counterweight at crank radius for ε = −1, 0, +1. The angular
    complement (±0.55 kg) is a series to the 5th order; its next terms, about λ²·0.55 ≈ 0.03 kg,
    bound the difference."""
    result = counterweights(bramo_with_angular_eccentricity(epsilon))
    assert_allclose(result.counterweights[0].mass_kg, s1, atol=0.03)


def test_180_twin_couple_one_counter_rotating_shaft_with_two_masses():
    """A 180° twin: throws at β = 0 and 180° at z = ∓d/2 (z̄ = 0), reciprocating mass m, crank r.
    Order 1 of a plain slider-crank is exactly m·r·ω²·cos(θ + β) (the rod's part is even in
    sin θ, so only even orders) = ½m·r·ω²·(e^{i(θ+β)} + e^{−i(θ+β)}). Summed: the forces cancel,
    the couple Σ z_j·F_j = −m·r·ω²·d·cos θ splits into M⁺ = M⁻ = −½m·r·ω²·d.
    Masses c_A, c_B in planes at −s/2 and +s/2 with c_A + c_B = 0 and (s/2)(c_B − c_A) = −M
    give c_B = m·r·ω²·d/(2s) = −c_A: the counterweights are masses m·d/(2s) at crank radius,
    0° (rear) and 180° (front) from throw 1, and the backward half needs ONE shaft at −1 with
    two masses m·e = c/ω² = m·r·d/(2s), 0° at the rear plane and 180° at the front one, when
    θ = 0. With m = 1 kg, r = 0.08 m, d = 0.1 m, s = 0.3 m: m·e = 0.08·0.1/0.6 kg·m."""
    m, r, d, s = 1.0, 0.08, 0.1, 0.3
    engine = make_engine([0], [(0, -d / 2), (180, d / 2)], r=r, m=m)
    result = counterweights(engine, planes=[Plane(-s / 2), Plane(s / 2)], shaft_orders=(1,))
    assert_allclose([w.mass_kg for w in result.counterweights], [m * d / (2 * s)] * 2, rtol=1e-9)
    assert_allclose([w.angle_deg % 360 for w in result.counterweights], [180.0, 0.0], atol=1e-9)
    (shaft,) = result.balancer_shafts
    assert shaft.speed_ratio == -1 and shaft.order == 1 and len(shaft.masses) == 2
    front, rear = sorted(shaft.masses, key=lambda x: x.z_m)
    assert_allclose([front.z_m, rear.z_m], [-s / 2, s / 2], atol=1e-15)
    assert_allclose(
        [front.mass_eccentricity_kgm, rear.mass_eccentricity_kgm],
        [m * r * d / (2 * s)] * 2,
        rtol=1e-9,
    )
    assert_allclose(front.phase_deg, 180.0, atol=1e-9)
    assert_allclose(math.cos(math.radians(rear.phase_deg)), 1.0, atol=1e-12)  # 0° or 360°−ε
    assert_allclose(front.mass_kg(0.02), m * r * d / (2 * s) / 0.02, rtol=1e-12)
    # exact: nothing of order 1 is left, force or moment
    first = result.after_shafts.orders[0]
    for value in (
        first.force_forward,
        first.force_backward,
        first.moment_forward,
        first.moment_backward,
    ):
        assert abs(value) < 1e-9 * engine.unit_force_n * d
    # the per-mass list stays as before: two entries of speed ratio −1
    assert [x.speed_ratio for x in result.shafts] == [-1, -1]
    # on the crank axis it makes no rolling moment
    assert shaft.centred and shaft.rolling_moment.amplitude_nm == 0.0
    assert [mo.amplitude_nm for mo in result.rolling_moments] == [0.0]


def test_270_twin_one_counter_rotating_shaft_cancels_each_cylinder_in_its_plane():
    """A 270° twin: throws at β = 0 and 90° at z = ∓d/2. Each cylinder's backward primary is
    ½m·r·ω²·e^{−iβ_j} at z_j; with the correction planes at the throws (the default) the two
    conditions (force and moment) are met by cancelling each in its own plane: masses
    c_j = −½m·r·ω²·e^{−iβ_j}, i.e. m·e = m·r/2 at 180° − β_j: 180° (front), 90° (rear) — one
    shaft at −1 carrying both. The forward half goes the same way to the counterweights:
    m/2 at crank radius, 180° + β_j from throw 1: 180°, 270°."""
    m, r, d = 1.2, 0.05, 0.09
    engine = make_engine([0], [(0, -d / 2), (90, d / 2)], r=r, m=m)
    result = counterweights(engine, shaft_orders=(1,))
    assert_allclose([w.mass_kg for w in result.counterweights], [m / 2] * 2, rtol=1e-9)
    assert_allclose([w.angle_deg for w in result.counterweights], [180.0, 270.0], atol=1e-9)
    (shaft,) = result.balancer_shafts
    assert shaft.speed_ratio == -1
    assert_allclose([x.z_m for x in shaft.masses], [-d / 2, d / 2], atol=1e-15)
    assert_allclose([x.mass_eccentricity_kgm for x in shaft.masses], [m * r / 2] * 2, rtol=1e-9)
    assert_allclose([x.phase_deg for x in shaft.masses], [180.0, 90.0], atol=1e-9)
    # the shaft's force is the two masses' sum: |½m·r·ω²·(−1 + i)| = m·r·ω²/√2
    assert_allclose(shaft.force_n, m * r * engine.speed_rad_s**2 / math.sqrt(2), rtol=1e-9)
    first = result.after_shafts.orders[0]
    for value in (
        first.force_forward,
        first.force_backward,
        first.moment_forward,
        first.moment_backward,
    ):
        assert abs(value) < 1e-9 * engine.unit_force_n * d


def test_lanchester_pair_at_different_heights_makes_a_rolling_couple():
    """Vertical = reference axis (in-line 4). Shaft +2 at lateral a, height h₁, force
    P·e^{2iθ} = P·(cos 2θ, sin 2θ) as (vertical, lateral); shaft −2 at lateral −a, height h₂,
    force P·(cos 2θ, −sin 2θ). The moment about the crank axis of a force (F_v, F_l) at
    (v, l) is v·F_l − l·F_v (positive with rotation, lateral being 90° on from vertical):
      M₊ = P·(h₁·sin 2θ − a·cos 2θ),  M₋ = P·(−h₂·sin 2θ + a·cos 2θ),
    so the vertical halves at ±a cancel and the pair leaves M = P·(h₁ − h₂)·sin 2θ: cos part
    0, sin part P·(h₁ − h₂), amplitude |P|·|h₁ − h₂|. The forces and the pitching/yawing
    moments are those of the centred pair: nothing left of order 2."""
    a, h1, h2 = 0.10, 0.06, -0.04
    engine, result, p = _inline4_pair({2: (a, h1), -2: (-a, h2)})
    plus, minus = result.balancer_shafts
    assert (plus.speed_ratio, minus.speed_ratio) == (2, -2)
    assert_allclose(
        [plus.rolling_moment.cos_nm, plus.rolling_moment.sin_nm], [-a * p, h1 * p], rtol=1e-9
    )
    assert_allclose(
        [minus.rolling_moment.cos_nm, minus.rolling_moment.sin_nm], [a * p, -h2 * p], rtol=1e-9
    )
    assert_allclose(plus.rolling_moment.amplitude_nm, abs(p) * math.hypot(a, h1), rtol=1e-9)
    (pair,) = result.rolling_moments
    assert pair.order == 2 and pair.speed_ratios == (2, -2)
    assert_allclose(pair.sin_nm, p * (h1 - h2), rtol=1e-9)
    assert abs(pair.cos_nm) <= 1e-9 * abs(p) * a
    assert_allclose(pair.amplitude_nm, abs(p) * abs(h1 - h2), rtol=1e-9)
    # P < 0, h₁ > h₂: M = −|P|·0.1·sin 2θ = 0.1·|P|·cos(2θ − 270°)
    assert_allclose(pair.phase_deg, 270.0, atol=1e-9)
    # the offsets change no free force or moment: still nothing of order 2 left
    second = result.after_shafts.orders[1]
    for value in (
        second.force_forward,
        second.force_backward,
        second.moment_forward,
        second.moment_backward,
    ):
        assert abs(value) < 1e-9 * engine.unit_force_n


def test_lanchester_pair_at_equal_heights_leaves_no_couple():
    """Same as above with h₁ = h₂ = h: M = P·(h − h)·sin 2θ = 0, though each shaft alone turns
    the engine with amplitude |P|·√(a² + h²)."""
    a, h = 0.12, -0.08
    _, result, p = _inline4_pair({2: (a, h), -2: (-a, h)})
    for shaft in result.balancer_shafts:
        assert_allclose(shaft.rolling_moment.amplitude_nm, abs(p) * math.hypot(a, h), rtol=1e-9)
    (pair,) = result.rolling_moments
    assert_allclose([pair.cos_nm, pair.sin_nm], [0.0, 0.0], atol=1e-9 * abs(p) * a)


def test_one_offset_for_every_shaft_puts_the_pairs_force_off_axis():
    """Both shafts at the same point (lateral a, height 0): their forces add to 2P·cos 2θ
    along the vertical, acting at lateral a: M = −a·2P·cos 2θ (cos part −2aP, sin part 0)."""
    a = 0.15
    _, result, p = _inline4_pair((a, 0.0))
    (pair,) = result.rolling_moments
    assert_allclose([pair.cos_nm, pair.sin_nm], [-2 * a * p, 0.0], atol=1e-9 * abs(p) * a)


@pytest.mark.parametrize("vertical_deg, cos_sin", [(0.0, (-1.0, 0.0)), (90.0, (0.0, -1.0))])
def test_offset_follows_the_engine_vertical(vertical_deg, cos_sin):
    """Shaft +2 alone off the axis, lateral a, height 0; force P·e^{2iθ} in the reference
    frame. Lateral lies at v + 90° from the reference axis: x = a·i·e^{iv}. With v = 0,
    M = Im(−i·a·P·e^{2iθ}) = −a·P·cos 2θ; with v = 90°, x = −a and M = −a·P·sin 2θ."""
    engine = dataclasses.replace(
        load(CONFIGS / "inline-4-car.toml"), vertical_rad=math.radians(vertical_deg)
    )
    a = 0.1
    result = counterweights(engine, shaft_orders=(2,), shaft_offsets_m={2: (a, 0.0)})
    plus, minus = result.balancer_shafts
    p = plus.force_n * math.cos(math.radians(plus.masses[0].phase_deg))  # signed: −|P|
    assert_allclose(
        [plus.rolling_moment.cos_nm, plus.rolling_moment.sin_nm],
        [a * p * cos_sin[0], a * p * cos_sin[1]],
        atol=1e-9 * abs(p) * a,
    )
    assert minus.centred and minus.rolling_moment.amplitude_nm == 0.0


@pytest.mark.parametrize(
    "offsets, words",
    [
        ((0.1,), "pairs"),
        ("0.1,0.2", "pairs"),
        ((0.1, "0.2"), "lengths in metres"),
        ((0.1, math.nan), "not a finite number"),
        ({3: (0.1, 0.1)}, "speed ratio 3"),
        ({0: (0.1, 0.1)}, "speed ratio 0"),
        ({True: (0.1, 0.1)}, "speed ratio True"),
    ],
)
def test_bad_shaft_offsets(offsets, words):
    with pytest.raises(CounterweightError, match=words) as info:
        counterweights(
            load(CONFIGS / "inline-4-car.toml"), shaft_orders=(2,), shaft_offsets_m=offsets
        )
    assert info.value.parameter == "shaft_offsets_m"


def test_shaft_offsets_need_shafts():
    with pytest.raises(CounterweightError, match="no shaft order was asked for"):
        counterweights(load(CONFIGS / "inline-4-car.toml"), shaft_offsets_m=(0.1, 0.0))


def test_an_axial_position_is_a_plane_not_a_bare_number():
    """1 and 1.0 would mean throw 1 and z = 1 m: a float is refused with the spelling to use,
    and Plane(z_m) at a throw's position is that throw's plane."""
    engine = make_engine([0], [(0, 0.0), (180, 0.1)])
    with pytest.raises(CounterweightError, match=r"Plane\(z_m\) for an axial position"):
        counterweights(engine, planes=[0.1])
    result = counterweights(engine, planes=[Plane(0.0), Plane(0.1)])
    assert [w.plane for w in result.counterweights] == [Plane(0.0, 1), Plane(0.1, 2)]


def test_antivibrateur_mass_counts_with_a_balance_factor():
    """The rotor rides on the crank pin: sized by a balance factor, the counterweight must carry
    it too, so the first order left is the same with and without the rotor."""
    engine = balance.load(BRAMO)
    plain = balance.counterweights(engine, balance_factor=0.5)
    rotor = balance.counterweights(engine, balance_factor=0.5, antivibrateur_radius_m=0.04)
    unit = engine.per_cylinder_unit_n
    for a, b in (
        (plain.residual.order(1).force_forward, rotor.residual.order(1).force_forward),
        (plain.residual.order(1).force_backward, rotor.residual.order(1).force_backward),
    ):
        assert abs(a - b) < 1e-9 * unit
    assert_allclose(
        rotor.counterweights[0].mass_kg - plain.counterweights[0].mass_kg,
        rotor.antivibrateur.mass_kg * engine.crank_radius_m / rotor.counterweights[0].radius_m,
        rtol=1e-9,
    )


def test_counterweight_angle_is_measured_from_throw_one():
    """A single with its throw at 90° from the reference axis (throw 1's phase 90°): the
    counterweight sits opposite the throw, 180° from it as a throw phase is measured."""
    engine = make_engine([0], [(90, 0.0)], rotating=1.0)
    (weight,) = balance.counterweights(engine).counterweights
    assert_allclose(weight.angle_deg, 180.0, atol=1e-9)
