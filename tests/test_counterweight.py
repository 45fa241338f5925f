"""Counterweights, balancer shafts, the antivibrateur and test masses, against the papers and
hand-derived closed forms."""

import dataclasses
import json
import math

import numpy as np
import pytest
from click.testing import CliRunner
from numpy.testing import assert_allclose

from balance_cli import load
from balance_cli.cli import main
from balance_cli.analysis.balancing import Plane
from balance_cli.analysis.planes import plane_at_throw
from balance_cli.analysis.counterweight import counterweights as balance
from balance_cli.errors import CounterweightError
from conftest import CONFIGS, exact_b, make_engine

V12 = CONFIGS / "nakanishi-v12-90-2stroke.toml"
W12 = CONFIGS / "nakanishi-w12-60-2stroke.toml"
BRAMO = CONFIGS / "bramo-323.toml"
# Nakanishi's masses in the library configurations (kg) and throw pitch d (m)
M_P, M_C, A, B, M_K, D = 2.0, 2.4, 0.65, 0.35, 2.0, 0.150


def assert_nothing_below(shaking_, order, unit):
    for o in shaking_.orders[: order - 1]:
        for value in (o.force_forward, o.force_backward, o.moment_forward, o.moment_backward):
            assert abs(value) < 1e-9 * unit, (o.order, value)


def test_nakanishi_v12_counterweights_on_throws_1_and_6():
    """§ 4: m_w = (2√3/5)·(r/r_w)·{m_p + (2a + b)·m_c + m_k}; afterwards nothing below the 6th."""
    engine = load(V12)
    r_w = 0.060
    result = balance(engine, [plane_at_throw(engine, 1), plane_at_throw(engine, 6)], radius_m=r_w,
                     max_order=8)
    expected = 2 * math.sqrt(3) / 5 * (engine.crank_radius_m / r_w) * (M_P + (2 * A + B) * M_C + M_K)
    for weight in result.counterweights:
        assert_allclose(weight.mass_kg, expected, rtol=1e-9)
    # opposite each other: a pure couple
    assert_allclose(abs(result.counterweights[0].angle_deg - result.counterweights[1].angle_deg), 180, atol=1e-9)
    assert_nothing_below(result.residual, 6, engine.unit_force_n * engine.n_cylinders)


def test_nakanishi_w12_counterweights_on_throws_1_and_4():
    """§ 7: the couple √10·d·{3/2·m_p + 3(a + b/2)·m_c + m_k}·ω²r at φ = tan⁻¹(−1/3) from two
    masses 3d apart: m_w = (√10/3)·(r/r_w)·{…}; afterwards nothing below the 4th order."""
    engine = load(W12)
    result = balance(engine, [plane_at_throw(engine, 1), plane_at_throw(engine, 4)])
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
    result = balance(engine)
    (weight,) = result.counterweights
    assert_allclose(weight.mass_kg, 31.6764, atol=0.0012)
    # the same from the formula with the configuration's own masses; m by (13) from them
    links = [c for c in engine.cylinders if c.is_link]
    m = (-sum(c.knuckle_kg * c.knuckle_radius_m * math.cos(engine.bank_angles_rad[c.bank_index])
              for c in links) / engine.rod_length_m)
    formula = (engine.rotating_kg + sum(c.knuckle_kg for c in links)
               + 0.5 * sum(c.reciprocating_kg for c in engine.cylinders) + 0.5 * m)
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
    plain = balance(engine)
    result = balance(engine, antivibrateur_radius_m=0.040)
    r_omega2 = engine.crank_radius_m * engine.speed_rad_s**2
    s2 = abs(plain.residual.orders[1].force_forward) / r_omega2
    me_kg_mm = result.antivibrateur.mass_eccentricity_kgm * 1000
    assert_allclose(me_kg_mm / 43.45, s2 / 2.17276, rtol=3e-4)
    assert abs(result.residual.orders[1].force_forward) < 1e-9 * r_omega2   # S2: 100 % reduction
    assert_allclose(result.residual.orders[0].force_backward, plain.residual.orders[0].force_backward,
                    rtol=1e-12)
    # its mass rides on the pin: the counterweight grows by exactly M
    assert_allclose(result.counterweights[0].mass_kg - plain.counterweights[0].mass_kg,
                    result.antivibrateur.mass_kg, rtol=1e-9)


def test_inline4_lanchester_pair():
    """Secondary 4·B2·m·r·ω² cos 2θ = 2·B2·m·r·ω²(e^{2iθ} + e^{−2iθ}): two shafts at 2× speed,
    one each way, each m·e·(2ω)² = 2·B2·m·r·ω², i.e. m·e = m_rec·r·λ'/2 with λ' = B2 exact."""
    engine = load(CONFIGS / "inline-4-car.toml")
    result = balance(engine, shaft_orders=(2,))
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
    result = balance(engine, shaft_orders=(1,))
    backward = [s for s in result.shafts if s.speed_ratio == -1]
    assert len(backward) == 2
    assert_allclose(backward[0].mass_eccentricity_kgm, backward[1].mass_eccentricity_kgm, rtol=1e-9)
    assert_allclose(abs(backward[0].phase_deg - backward[1].phase_deg), 180, atol=1e-9)
    # each: the backward couple ½·m·r·ω²·0.1 m over the 0.1 m between the planes, at ω²
    assert_allclose(backward[0].mass_eccentricity_kgm, 0.5 * 1.0 * engine.crank_radius_m, rtol=1e-9)
    first = result.after_shafts.orders[0]
    for value in (first.force_forward, first.force_backward, first.moment_forward, first.moment_backward):
        assert abs(value) < 1e-9 * engine.unit_force_n


@pytest.mark.parametrize("factor", [0.0, 0.3, 0.5, 0.7, 1.0])
def test_single_cylinder_balance_factor(factor):
    """m·r·ω² cos θ = ½m·r·ω²(e^{iθ} + e^{−iθ}); a counterweight c·m opposite the crank adds
    −c·m·r·ω²e^{iθ}: forward |1 − 2c|/2, backward 1/2 of m·r·ω² (rotating mass cancelled)."""
    engine = make_engine([0], [(0, 0.0)], rotating=0.8)
    result = balance(engine, balance_factor=factor)
    first = result.residual.orders[0]
    unit = engine.unit_force_n
    assert_allclose(abs(first.force_forward) / unit, abs(1 - 2 * factor) / 2, atol=1e-12)
    assert_allclose(abs(first.force_backward) / unit, 0.5, atol=1e-12)


def test_half_balanced_single_leaves_a_constant_force_turning_backward():
    engine = make_engine([0], [(0, 0.0)], r=0.05, l=0.2)
    residual = balance(engine, balance_factor=0.5, max_order=8).residual
    first = residual.orders[0]
    theta = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    primary = first.force_forward * np.exp(1j * theta) + first.force_backward * np.exp(-1j * theta)
    assert_allclose(np.abs(primary), engine.unit_force_n / 2, rtol=1e-12)


def test_test_masses_are_nakanishis():
    """§ 4: m_p + (2a + b)·m_c on each pin of the V12; § 7: 3/2·m_p + 3(a + b/2)·m_c on each
    pin of the W12 (the crank's own m_k stays on the shaft)."""
    v12 = balance(load(V12), test_masses=True)
    assert_allclose(v12.test_masses_kg, [M_P + (2 * A + B) * M_C] * 6, rtol=1e-9)
    w12 = balance(load(W12), test_masses=True)
    assert_allclose(w12.test_masses_kg, [1.5 * M_P + 3 * (A + B / 2) * M_C] * 4, rtol=1e-9)


def test_shaft_with_test_masses_runs_balanced_on_the_machine():
    """Second method, by hand: on the machine each pin carries its test mass plus the crank's
    own m_k, a forward first order Σ (m_test + m_k)·r·ω²·e^{iβ_j} and its moment about z̄;
    the engine's counterweights (m·ρ·ω²·e^{iφ} in their planes) must cancel both exactly."""
    engine = load(V12)
    result = balance(engine, [plane_at_throw(engine, 1), plane_at_throw(engine, 6)], test_masses=True)
    omega2, r, z_mean = engine.speed_rad_s**2, engine.crank_radius_m, engine.mean_z_m
    force = moment = 0j
    for throw, mass in zip(engine.throws, result.test_masses_kg):
        phasor = (mass + engine.crank_kg) * r * omega2 * np.exp(1j * throw.phase_rad)
        force += phasor
        moment += (throw.z_m - z_mean) * phasor
    for weight in result.counterweights:
        phasor = weight.mass_kg * weight.radius_m * omega2 * np.exp(1j * np.radians(weight.angle_deg))
        force += phasor
        moment += (weight.plane.z_m - z_mean) * phasor
    scale = engine.per_cylinder_unit_n
    assert abs(force) < 1e-9 * scale and abs(moment) < 1e-9 * scale


def test_one_plane_cancels_the_force_and_reports_the_moment_left():
    engine = load(V12)
    result = balance(engine, [plane_at_throw(engine, 1)])
    first = result.residual.orders[0]
    assert abs(first.force_forward) < 1e-9 * engine.unit_force_n
    assert_allclose(abs(first.moment_forward), abs(result.original.orders[0].moment_forward), rtol=1e-9)


@pytest.mark.parametrize("kwargs, words", [
    (dict(planes=[Plane(0.0, 1), Plane(0.0, 1)]), "coincide"),
    (dict(planes=[Plane(0.0), Plane(0.1), Plane(0.2)]), "one plane"),
    (dict(radius_m=0.0), "greater than zero"),
    (dict(radius_m=-0.05), "greater than zero"),
    (dict(shaft_orders=(99,)), r"outside the orders analysed \(1 to 8"),
    (dict(antivibrateur_radius_m=0.04), "single-throw"),
])
def test_bad_requests(kwargs, words):
    with pytest.raises(CounterweightError, match=words):
        balance(load(V12), **kwargs)


def run(*args):
    return CliRunner().invoke(main, list(map(str, args)))


@pytest.mark.parametrize("args, words", [
    (["--planes", "1,9"], "--planes names throw 9, but the engine has throws 1 to 6"),
    (["--planes", "1,1"], "--planes coincide"),
    (["--planes", "1,two"], "--planes: cannot read 'two'"),
    (["--radius", "0 mm"], "--radius must be greater than zero"),
    (["--radius", "-5 mm"], "--radius must be greater than zero"),
    (["--radius", "5 kg"], "is a mass, but a length is needed"),
    (["--shafts", "x"], "give orders as whole numbers"),
    (["--antivibrateur"], "single-throw engine"),
    (["--shaft-offset", "1 mm,2 mm"],
     "--shaft-offset places balancer shafts, but no shaft order was asked for"),
    (["--shafts", "6", "--shaft-offset", "3:1 mm,2 mm"], "--shaft-offset names speed ratio 3"),
    (["--shafts", "6", "--shaft-offset", "1 mm"], "give LATERAL,VERTICAL"),
    (["--shafts", "6", "--shaft-offset", "x:1 mm,1 mm"], "must be a whole number"),
    (["--shafts", "6", "--shaft-offset", "6:1 kg,1 mm"], "is a mass, but a length is needed"),
    (["--shafts", "6", "--shaft-offset", "1 mm,1 mm", "--shaft-offset", "2 mm,2 mm"],
     "every shaft is placed twice"),
])
def test_cli_errors(tmp_path, args, words):
    out = tmp_path / "cw.json"
    result = run("counterweight", V12, *args, "--format", "json", "--output", out)
    assert result.exit_code != 0
    assert words in result.output and isinstance(result.exception, SystemExit)
    assert not out.exists()


def test_cli_json_contract(tmp_path):
    out = tmp_path / "cw.json"
    result = run("counterweight", V12, "--planes", "1,6", "--shafts", "6", "--test-masses",
                 "--max-order", "8", "--format", "json", "--output", out)
    assert result.exit_code == 0, result.output
    (engine,) = json.loads(out.read_text(encoding="utf-8"))["engines"]
    assert [c["throw"] for c in engine["counterweights"]] == [1, 6]
    assert set(engine["counterweights"][0]) == {"z_m", "throw", "mass_kg", "radius_m", "angle_deg"}
    assert [o["order"] for o in engine["residual"]["orders"]] == list(range(1, 9))
    assert engine["residual"]["orders"][0]["force"]["max_N"] == 0.0
    assert {s["speed_ratio"] for s in engine["shafts"]} == {6, -6}
    assert engine["after_shafts"]["orders"][5]["force"]["max_N"] == 0.0
    assert engine["test_masses_kg"] == pytest.approx([5.96] * 6, rel=1e-9)


def test_cli_table_and_csv():
    table = run("counterweight", CONFIGS / "bramo-323.toml", "--antivibrateur", "--units", "kgf")
    assert table.exit_code == 0, table.output
    assert "M·e = 0.04408 kg·m" in table.output
    csv_text = run("counterweight", V12, "--format", "csv").output
    assert csv_text.startswith("engine,config,item,quantity,value,unit")
    assert "counterweight 2,mass," in csv_text


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
            radius = (engine.rod_length_m - c.link_length_m) / (1 - 0.5 * lam**2 * f1 * math.sin(psi) ** 2)
            c = dataclasses.replace(c, knuckle_angle_rad=psi, knuckle_radius_m=radius)
        cylinders.append(c)
    return dataclasses.replace(engine, cylinders=tuple(cylinders))


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
    result = balance(bramo_with_angular_eccentricity(epsilon))
    assert_allclose(result.counterweights[0].mass_kg, s1, atol=0.03)


# --- balancer shafts as built: one shaft per speed ratio, its masses, its offset -------------

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
    result = balance(engine, planes=[Plane(-s / 2), Plane(s / 2)], shaft_orders=(1,))
    assert_allclose([w.mass_kg for w in result.counterweights], [m * d / (2 * s)] * 2, rtol=1e-9)
    assert_allclose([w.angle_deg % 360 for w in result.counterweights], [180.0, 0.0], atol=1e-9)
    (shaft,) = result.balancer_shafts
    assert shaft.speed_ratio == -1 and shaft.order == 1 and len(shaft.masses) == 2
    front, rear = sorted(shaft.masses, key=lambda x: x.z_m)
    assert_allclose([front.z_m, rear.z_m], [-s / 2, s / 2], atol=1e-15)
    assert_allclose([front.mass_eccentricity_kgm, rear.mass_eccentricity_kgm],
                    [m * r * d / (2 * s)] * 2, rtol=1e-9)
    assert_allclose(front.phase_deg, 180.0, atol=1e-9)
    assert_allclose(math.cos(math.radians(rear.phase_deg)), 1.0, atol=1e-12)   # 0° or 360°−ε
    assert_allclose(front.mass_kg(0.02), m * r * d / (2 * s) / 0.02, rtol=1e-12)
    # exact: nothing of order 1 is left, force or moment
    first = result.after_shafts.orders[0]
    for value in (first.force_forward, first.force_backward, first.moment_forward,
                  first.moment_backward):
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
    result = balance(engine, shaft_orders=(1,))
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
    for value in (first.force_forward, first.force_backward, first.moment_forward,
                  first.moment_backward):
        assert abs(value) < 1e-9 * engine.unit_force_n * d


def _inline4_pair(offsets):
    engine = load(CONFIGS / "inline-4-car.toml")
    lam = exact_b(engine.crank_radius_m / engine.rod_length_m, 2)
    # the pair opposes 4·B2·m·r·ω²·cos 2θ (along the reference axis, the vertical): each shaft's
    # force is P·e^{±2iθ} with P = −2·B2·m·r·ω²
    p = -2 * lam * engine.mean_reciprocating_kg * engine.crank_radius_m * engine.speed_rad_s**2
    return engine, balance(engine, shaft_orders=(2,), shaft_offsets_m=offsets), p


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
    assert_allclose([plus.rolling_moment.cos_nm, plus.rolling_moment.sin_nm], [-a * p, h1 * p],
                    rtol=1e-9)
    assert_allclose([minus.rolling_moment.cos_nm, minus.rolling_moment.sin_nm], [a * p, -h2 * p],
                    rtol=1e-9)
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
    for value in (second.force_forward, second.force_backward, second.moment_forward,
                  second.moment_backward):
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
    engine = dataclasses.replace(load(CONFIGS / "inline-4-car.toml"),
                                 vertical_rad=math.radians(vertical_deg))
    a = 0.1
    result = balance(engine, shaft_orders=(2,), shaft_offsets_m={2: (a, 0.0)})
    plus, minus = result.balancer_shafts
    p = plus.force_n * math.cos(math.radians(plus.masses[0].phase_deg))   # signed: −|P|
    assert_allclose([plus.rolling_moment.cos_nm, plus.rolling_moment.sin_nm],
                    [a * p * cos_sin[0], a * p * cos_sin[1]], atol=1e-9 * abs(p) * a)
    assert minus.centred and minus.rolling_moment.amplitude_nm == 0.0


@pytest.mark.parametrize("offsets, words", [
    ((0.1,), "pairs"),
    ("0.1,0.2", "pairs"),
    ((0.1, "0.2"), "lengths in metres"),
    ((0.1, math.nan), "not a finite number"),
    ({3: (0.1, 0.1)}, "speed ratio 3"),
    ({0: (0.1, 0.1)}, "speed ratio 0"),
    ({True: (0.1, 0.1)}, "speed ratio True"),
])
def test_bad_shaft_offsets(offsets, words):
    with pytest.raises(CounterweightError, match=words) as info:
        balance(load(CONFIGS / "inline-4-car.toml"), shaft_orders=(2,), shaft_offsets_m=offsets)
    assert info.value.parameter == "shaft_offsets_m"


def test_shaft_offsets_need_shafts():
    with pytest.raises(CounterweightError, match="no shaft order was asked for"):
        balance(load(CONFIGS / "inline-4-car.toml"), shaft_offsets_m=(0.1, 0.0))


def test_cli_nothing_left_in_words():
    """Orders 2, 4, 6, 8 are all an in-line 4 has: after their shafts nothing is left, said
    in words, not as an empty table; centred shafts are said to make no rolling moment."""
    result = run("counterweight", CONFIGS / "inline-4-car.toml", "--shafts", "2,4,6,8")
    assert result.exit_code == 0, result.output
    assert "After the shafts, nothing is left up to order 8" in result.output
    assert "Left after the shafts" not in result.output
    assert "Rolling moment about the crank axis of the shafts: none" in result.output
    assert "kg·mm" not in result.output
    primary = run("counterweight", CONFIGS / "inline-4-car.toml", "--shafts", "1,2")
    assert "Order 1: no shaft needed, already zero." in primary.output
    six = run("counterweight", CONFIGS / "tanaka-part3" / "3-inline-6.toml", "--max-order", "5")
    assert six.exit_code == 0, six.output
    assert "After the counterweights, nothing is left up to order 5" in six.output


def test_cli_shaft_table_and_rolling_moment():
    """The Lanchester pair at ±100 mm lateral and +50/−50 mm: each shaft's m·e in kg·m
    (m_rec·r·B2/2 = 0.003640 kg·m), and the pair's couple |P|·0.1 m, P = 2·B2·m·r·ω²."""
    engine = load(CONFIGS / "inline-4-car.toml")
    lam = exact_b(engine.crank_radius_m / engine.rod_length_m, 2)
    p = 2 * lam * engine.mean_reciprocating_kg * engine.crank_radius_m * engine.speed_rad_s**2
    result = run("counterweight", CONFIGS / "inline-4-car.toml", "--shafts", "2",
                 "--shaft-offset", "+2:100 mm,50 mm", "--shaft-offset", "-2:-100 mm,-50 mm")
    assert result.exit_code == 0, result.output
    text = result.output
    assert "m·e (kg·m)" in text and "0.003640" in text and "100, 50" in text
    together = next(line for line in text.splitlines() if "together" in line)
    assert float(together.split()[-2]) == pytest.approx(p * 0.1, rel=1e-3)


def test_cli_json_balancer_shafts(tmp_path):
    out = tmp_path / "cw.json"
    result = run("counterweight", CONFIGS / "inline-4-car.toml", "--shafts", "2",
                 "--shaft-offset", "120 mm,-80 mm", "--shaft-offset", "-2:0 mm,0 mm",
                 "--format", "json", "--output", out)
    assert result.exit_code == 0, result.output
    (engine,) = json.loads(out.read_text(encoding="utf-8"))["engines"]
    assert engine["shaft_orders"] == [2]
    # the old per-mass list, unchanged
    assert [set(s) for s in engine["shafts"]] == [
        {"order", "speed_ratio", "mass_eccentricity_kgm", "phase_deg", "z_m"}] * 2
    plus, minus = engine["balancer_shafts"]
    assert set(plus) == {"speed_ratio", "order", "turning", "offset_m", "masses", "force_N",
                         "rolling_moment"}
    assert (plus["speed_ratio"], plus["turning"], minus["speed_ratio"], minus["turning"]) == \
        (2, "with", -2, "against")
    assert plus["offset_m"] == pytest.approx({"lateral": 0.12, "vertical": -0.08})
    assert minus["offset_m"] == {"lateral": 0.0, "vertical": 0.0}
    assert set(plus["masses"][0]) == {"mass_eccentricity_kgm", "phase_deg", "z_m"}
    assert set(plus["rolling_moment"]) == {"order", "cos_Nm", "sin_Nm", "amplitude_Nm", "phase_deg"}
    assert minus["rolling_moment"]["amplitude_Nm"] == 0.0
    (pair,) = engine["shaft_rolling_moments"]
    assert pair["speed_ratios"] == [2, -2]
    # only the +2 shaft is off the axis: the pair's moment is its own
    assert pair["amplitude_Nm"] == pytest.approx(plus["rolling_moment"]["amplitude_Nm"], rel=1e-12)
    assert pair["amplitude_Nm"] == pytest.approx(plus["force_N"] * math.hypot(0.12, 0.08), rel=1e-9)
    csv_text = run("counterweight", CONFIGS / "inline-4-car.toml", "--shafts", "2",
                   "--format", "csv").output
    assert "balancer shaft 1 mass 1,mass_eccentricity," in csv_text
    assert "shafts +2 -2 rolling moment order 2,amplitude,0.0,N·m" in csv_text


TWIN_270 = """name = "270° twin"
cycle = 4
speed = "6000 rpm"
crank_radius = "35 mm"
rod_length = "120 mm"
[masses]
reciprocating = "400 g"
[[banks]]
angle = 0
[[throws]]
phase = 0
z = "0 mm"
[[throws]]
phase = 90
z = "80 mm"
"""


def test_cli_270_twin_reports_one_shaft_with_two_masses(tmp_path):
    """As test_270_twin_…: one −1 shaft, masses m·r/2 = 0.4·0.035/2 = 0.007 kg·m at 180° (throw
    1's plane) and 90° (throw 2's)."""
    config = tmp_path / "twin.toml"
    config.write_text(TWIN_270, encoding="utf-8")
    result = run("counterweight", config, "--shafts", "1", "--format", "json")
    assert result.exit_code == 0, result.output
    (engine,) = json.loads(result.output)["engines"]
    (shaft,) = engine["balancer_shafts"]
    assert shaft["speed_ratio"] == -1 and shaft["turning"] == "against"
    assert_allclose([m["mass_eccentricity_kgm"] for m in shaft["masses"]], [0.007, 0.007], rtol=1e-9)
    assert_allclose([m["phase_deg"] for m in shaft["masses"]], [180.0, 90.0], atol=1e-9)
    assert_allclose([m["z_m"] for m in shaft["masses"]], [0.0, 0.08], atol=1e-12)
    assert engine["after_shafts"]["orders"][0]["force"]["max_N"] == 0.0
    assert engine["after_shafts"]["orders"][0]["moment"]["max_Nm"] == 0.0


def test_an_axial_position_is_a_plane_not_a_bare_number():
    """1 and 1.0 would mean throw 1 and z = 1 m: a float is refused with the spelling to use,
    and Plane(z_m) at a throw's position is that throw's plane."""
    engine = make_engine([0], [(0, 0.0), (180, 0.1)])
    with pytest.raises(CounterweightError, match=r"Plane\(z_m\) for an axial position"):
        balance(engine, planes=[0.1])
    result = balance(engine, planes=[Plane(0.0), Plane(0.1)])
    assert [w.plane for w in result.counterweights] == [Plane(0.0, 1), Plane(0.1, 2)]
