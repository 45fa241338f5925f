"""The free end's elastic twist: its angle less the angle of the line's centre of inertia,
against a two-inertia line solved by hand.

A throw J₁ (the free end) on a section k (loss factor d: stiffness k* = k·(1 + i·d)) to a
flywheel J₂, the order's torque U at the throw. The two equations −ω²J₁θ₁ + k*(θ₁ − θ₂) = U
and −ω²J₂θ₂ − k*(θ₁ − θ₂) = 0 add to −ω²(J₁θ₁ + J₂θ₂) = U: the centre of inertia turns
θ̄ = −U/(ω²(J₁ + J₂)) (the rigid turning, what the net torque does to the whole line). Their
difference gives the twist θ₁ − θ₂ = U/(J₁·(ω*² − ω²)), ω*² = k*·(J₁ + J₂)/(J₁J₂), and the free
end's elastic twist is θ₁ − θ̄ = J₂/(J₁ + J₂)·(θ₁ − θ₂); its whole swing θ₁ = θ̄ + that.
"""

import math

import numpy as np
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.cylinders import cylinder_torques

J1, J2, K, D = 0.05, 0.4, 2.0e5, 0.04

TWO = f"""\
name = "throw and flywheel"
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
throw_inertia = "{J1} kg*m^2"
loss_factor = {D}

[torsion.flywheel]
inertia = "{J2} kg*m^2"
stiffness = "{K} N*m/rad"
"""


def test_elastic_twist_of_a_two_inertia_line():
    """Every order at three speeds (below, near and above the resonance √(k(J₁+J₂)/(J₁J₂)) =
    2121 rad/s: order 6 at 3376 rpm), the free end's whole and elastic amplitudes against the
    closed forms above."""
    engine = balance.loads(TWO)
    speeds = np.array([1200.0, 3300.0, 5000.0])
    result = balance.torsional_vibration(engine, speeds, 8)
    (cylinder,) = cylinder_torques(engine, max_order=8)
    omega0 = engine.speed_rad_s
    w_star2 = K * (1 + 1j * D) * (J1 + J2) / (J1 * J2)
    for i, speed in enumerate(speeds):
        omega = speed * math.pi / 30
        for o, (k, cos, sin) in enumerate(cylinder.inertia.orders):
            u = (cos - 1j * sin) * (omega / omega0) ** 2
            w = k * omega
            twist = u / (J1 * (w_star2 - w**2))
            rigid = -u / (w**2 * (J1 + J2))
            elastic = J2 / (J1 + J2) * twist
            # a 2×2 complex solve: rounding, 1e-9 of the amplitude (and of |U|/k for the zeros)
            floor = 1e-12 * abs(u) / K
            assert_allclose(
                result.free_end_elastic_order_deg[i, o],
                math.degrees(abs(elastic)),
                rtol=1e-9,
                atol=math.degrees(floor),
            )
            assert_allclose(
                result.free_end_order_deg[i, o],
                math.degrees(abs(rigid + elastic)),
                rtol=1e-9,
                atol=math.degrees(floor),
            )
            # and the section's torque is k*·twist (the elastic torque k·(θ₁ − θ₂) reported)
            assert_allclose(
                result.order_torque_nm[i, 0, o], K * abs(twist), rtol=1e-9, atol=1e-12 * abs(u)
            )
    # the natural frequency by hand, the loss factor aside
    assert_allclose(
        result.modes[0].frequency_hz,
        math.sqrt(K * (J1 + J2) / (J1 * J2)) / (2 * math.pi),
        rtol=1e-10,
    )


def test_the_rigid_turning_dominates_the_free_end_at_low_speed():
    """Far below the resonance the whole line turns as one: at 300 rpm (ω = 31.4 rad/s at order
    1) the closed forms give an elastic twist J₂/((J₁ + J₂)·J₁·|ω*² − ω²|)·|U| ≈ 4.0e-6·|U|
    against a rigid turning |U|/(ω²(J₁ + J₂)) ≈ 2.3e-3·|U|, so the free end's whole swing is
    nearly all rigid turning (the higher orders, smaller, do not change that); the waveform's
    elastic peak lies between its largest order's amplitude and their sum."""
    result = balance.torsional_vibration(balance.loads(TWO), [300.0, 2000.0], 8)
    assert result.free_end_elastic_deg[0] < 0.05 * result.free_end_deg[0]
    per_order = result.free_end_elastic_order_deg
    assert np.all(result.free_end_elastic_deg <= per_order.sum(axis=1) * (1 + 1e-12))
    assert np.all(result.free_end_elastic_deg >= per_order.max(axis=1) * (1 - 1e-12))
