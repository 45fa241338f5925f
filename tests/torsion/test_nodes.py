"""A throw at a node of a mode, and an undamped line at its natural frequencies: a three-inertia
symmetric line (pulley J, one throw J, flywheel J, joined by two sections k) solved by hand.

By hand: det(K − λM) = (k − λJ)·λJ·(λJ − 3k), so ω₁² = k/J with the shape (1, 0, −1) (the throw
in the middle at its node) and ω₂² = 3k/J with (1, −2, 1), scaled to its largest amplitude
(−½, 1, −½). The throw cannot excite mode 1 at any order; it excites mode 2 with a phase-vector
sum of 1 (one cylinder, β = 1).

At ω = ω₁ with the order-k torque U at the middle throw and no damping, the response is finite
(the mode is not driven): the first equation (k − ω₁²J)·θ₁ − k·θ₂ = 0 gives θ₂ = 0, the second
−k·(θ₁ + θ₃) = U and symmetry θ₁ = θ₃ give θ₁ = θ₃ = −U/(2k): each section carries |U|/2, the
free end swings |U|/(2k), and less the centre of inertia's angle −U/(3k) its elastic twist is
|U|/(6k). At ω = ω₂ the mode is driven and nothing damps it: the response is infinite.
"""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.cylinders import cylinder_torques
from balance_cli.errors import AnalysisError
from tests.support import invoke

J, K = 0.05, 1.0e4  # kg·m², N·m/rad: ω₁ = √(k/J) = 447.2 rad/s (71.18 Hz)

THREE = f"""\
name = "three inertias, throw in the middle"
cycle = 2
speed = "1500 rpm"
crank_radius = "50 mm"
rod_length = "200 mm"

[masses]
reciprocating = "1.5 kg"

[[banks]]
angle = 0

[[throws]]
phase = 0

[torsion]
throw_inertia = "{J} kg*m^2"

[[torsion.front]]
name = "pulley"
inertia = "{J} kg*m^2"
stiffness = "{K} N*m/rad"

[torsion.flywheel]
inertia = "{J} kg*m^2"
stiffness = "{K} N*m/rad"
"""

W1, W2 = math.sqrt(K / J), math.sqrt(3 * K / J)
MAX_ORDER = 4


def critical_rpm(omega, order):
    return omega / order * 60 / (2 * math.pi)


def order_torque(engine, speed_rpm, order):
    """The cylinder's order-k torque U at this speed (inertia only: it grows as Ω²), N·m."""
    (cylinder,) = cylinder_torques(engine, max_order=MAX_ORDER)
    _, cos, sin = cylinder.inertia.orders[order - 1]
    return (cos - 1j * sin) * (speed_rpm * 2 * math.pi / 60 / engine.speed_rad_s) ** 2


def test_modes_of_the_symmetric_line():
    """Frequencies √(k/J) and √(3k/J); shapes (1, 0, −1) and (−½, 1, −½), each scaled to its
    largest amplitude, the node exactly 0 (it was 1e-16 and divided the shape into 3e16)."""
    result = balance.torsional_vibration(balance.loads(THREE), [1000.0], MAX_ORDER)
    mode1, mode2 = result.modes
    # two eigenvalues of a 3×3 pencil: rounding only
    assert_allclose(
        [mode1.frequency_hz, mode2.frequency_hz], np.array([W1, W2]) / (2 * np.pi), rtol=1e-10
    )
    # the sign of a symmetric mode is whichever end comes first: compare up to it
    assert_allclose(mode1.shape * mode1.shape[0], [1.0, 0.0, -1.0], atol=1e-12)
    assert mode1.shape[1] == 0.0 and mode1.throw_amplitudes[0] == 0.0
    assert_allclose(mode2.shape, [-0.5, 1.0, -0.5], rtol=1e-10)
    assert all(v == 0.0 for v in mode1.phase_vector_sums.values())
    assert_allclose(list(mode2.phase_vector_sums.values()), 1.0, rtol=1e-12)
    assert not mode1.excited(2) and mode2.excited(2)


def test_criticals_of_a_mode_the_throw_cannot_excite_are_flagged():
    """Mode 1's criticals in 300-1800 rpm (orders 3 and 4: 1424 and 1068 rpm) are listed with
    excited False and a sum of 0; the default filter leaves them out, "all" keeps them."""
    result = balance.torsional_vibration(balance.loads(THREE), None, MAX_ORDER)
    ones = [c for c in result.criticals if c.mode == 1]
    assert_allclose(
        sorted(c.speed_rpm for c in ones),
        [critical_rpm(W1, 4), critical_rpm(W1, 3)],
        rtol=1e-10,
    )
    assert all(not c.excited and c.phase_vector_sum == 0.0 for c in ones)
    assert all(c.kind.endswith("not excited") for c in ones)
    assert not [c for c in result.filtered().criticals if c.mode == 1]
    assert result.filtered("all").criticals == result.criticals


@pytest.mark.parametrize("order", [1, 2, 3, 4])
def test_undamped_line_at_a_critical_of_the_mode_it_cannot_excite(order):
    """At ω₁ exactly (the critical speeds the analysis lists, which once ended in a LinAlgError):
    each section |U|/2, the free end |U|/(2k), its elastic twist |U|/(6k), by hand above."""
    engine = balance.loads(THREE)
    speed = critical_rpm(W1, order)
    result = balance.torsional_vibration(engine, [speed], MAX_ORDER)
    u = abs(order_torque(engine, speed, order))
    o = order - 1
    # a bordered 4×4 solve at a frequency equal to ω₁ to rounding: 1e-9 of the figures
    assert_allclose(result.order_torque_nm[0, :, o], [u / 2, u / 2], rtol=1e-9)
    assert_allclose(result.free_end_order_deg[0, o], math.degrees(u / (2 * K)), rtol=1e-9)
    assert_allclose(result.free_end_elastic_order_deg[0, o], math.degrees(u / (6 * K)), rtol=1e-9)


def test_undamped_line_at_a_critical_of_the_mode_it_excites_is_refused():
    """At ω₂ (order 4 at 1849 rpm) the driven, undamped mode 2 has an infinite response: one
    AnalysisError naming speeds_rpm and the fix; with a loss factor it is a finite peak."""
    engine = balance.loads(THREE)
    speed = critical_rpm(W2, 4)
    with pytest.raises(AnalysisError, match="infinite") as caught:
        balance.torsional_vibration(engine, [1000.0, speed], MAX_ORDER)
    assert caught.value.parameter == "speeds_rpm"
    assert "mode 2" in str(caught.value) and "loss_factor" in str(caught.value)
    damped = balance.loads(THREE.replace("[torsion]\n", "[torsion]\nloss_factor = 0.02\n"))
    result = balance.torsional_vibration(damped, [1000.0, speed], MAX_ORDER)
    assert np.all(np.isfinite(result.torque_nm))


def test_undamped_line_near_but_off_its_natural_frequency_is_solved():
    """1 % off ω₂ the undamped response is large but finite and openTorsion's: the middle
    throw's order-4 angle by hand from the modal sum over the two elastic modes and the rigid
    turning, θ₂ = Σ φ₂²·U / (m·(ω_m² − ω²)) with φ = (1, 1, 1), (1, 0, −1), (1, −2, 1) and
    m = φᵀMφ = 3J, 2J, 6J."""
    engine = balance.loads(THREE)
    speed = critical_rpm(W2, 4) * 1.01
    result = balance.torsional_vibration(engine, [speed], MAX_ORDER)
    w = 4 * speed * 2 * math.pi / 60
    u = order_torque(engine, speed, 4)
    middle = u * (1 / (3 * J * -(w**2)) + 0 + 4 / (6 * J * (W2**2 - w**2)))
    pulley = u * (1 / (3 * J * -(w**2)) + 0 + (-2) / (6 * J * (W2**2 - w**2)))
    # a section's torque k·(θ_pulley − θ_middle); conditioning 1/0.02 costs a few digits
    assert_allclose(result.order_torque_nm[0, 0, 3], K * abs(pulley - middle), rtol=1e-8)


def test_the_command_refuses_an_undamped_resonance_in_one_line(tmp_path):
    path = tmp_path / "three.toml"
    path.write_text(THREE)
    out = tmp_path / "out.json"
    result = invoke(
        "torsion", path, "--speeds", f"1000,{critical_rpm(W2, 4)!r}", "--format", "json", "-o", out
    )
    assert result.exit_code == 1
    (line,) = result.output.strip().splitlines()
    assert line.startswith(f"Error: {path}: --speeds puts order 4") and "infinite" in line
    assert "Traceback" not in result.output and not out.exists()
    # at mode 1's criticals (the throw at its node) the command answers
    result = invoke("torsion", path, "--speeds", f"{critical_rpm(W1, 4)!r}", "--criticals", "all")
    assert result.exit_code == 0, result.output
    assert "minor, not excited" in result.output or "major, not excited" in result.output
