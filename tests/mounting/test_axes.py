"""The torque roll axis against J⁻¹·x̂ worked by hand, and the elastic axis against systems
whose axis of rotation under a couple is known."""

import math

import numpy as np
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.mounting import angle_between_deg, elastic_axis, torque_roll_axis
from tests.mounting.helpers import COUPLED, SYMMETRIC


def test_torque_roll_axis_of_the_coupled_example_by_hand():
    """J = [[8, −0.4, 0.9], [−0.4, 12, 0.3], [0.9, 0.3, 10]] kg·m². J⁻¹·x̂ is J⁻¹'s first
    column: the cofactors of J's first row over det J (J is symmetric).
    C₁₁ = 12·10 − 0.3·0.3 = 119.91; C₁₂ = −((−0.4)·10 − 0.3·0.9) = 4.27;
    C₁₃ = (−0.4)·0.3 − 12·0.9 = −10.92; det J = 8·119.91 − 0.4·4.27 + 0.9·(−10.92) = 947.744.
    The direction is (119.91, 4.27, −10.92)/|…|, |…| = √14 515.8874 = 120.4819:
    (0.99525, 0.03544, −0.09064), acos(0.99525) = 5.585° off the crank axis. It passes
    through the centre of gravity."""
    cofactors = np.array([119.91, 4.27, -10.92])
    assert_allclose(8 * 119.91 - 0.4 * 4.27 + 0.9 * -10.92, 947.744, rtol=1e-12)
    by_hand = cofactors / math.sqrt(14515.8874)
    assert_allclose(by_hand, [0.99525, 0.03544, -0.09064], atol=5e-6)  # printed to 5 places
    axis = torque_roll_axis(balance.load(COUPLED).mounts)
    assert_allclose(axis.direction, by_hand, rtol=0, atol=1e-12)  # exact arithmetic by hand
    assert axis.through_m == (0.0, 0.0, 0.0)
    assert_allclose(math.degrees(math.acos(by_hand[0])), 5.585, atol=5e-4)


def test_principal_axes_make_the_torque_roll_axis_the_crank_axis():
    """J = diag(6, 9, 8): J⁻¹·x̂ = (1/6, 0, 0), along x."""
    axis = torque_roll_axis(balance.load(SYMMETRIC).mounts)
    assert axis.direction == (1.0, 0.0, 0.0)


def test_elastic_axis_of_mounts_below_the_centre_of_gravity():
    """The symmetric example with every mount at z = −h, h = 0.1 m. Under a couple C about x
    the springs' energy ½·Σ[k_y·(Y + h·θ_x)² + k_z·(Z + y·θ_x)²] + ... is least with
    Y = −h·θ_x (lateral balance: 4·k_y·(Y + h·θ_x) = 0) and Z = 0 (Σ y = 0), θ_x = C/(4·k_z·b²):
    a point at height z moves Y − z·θ_x = −(h + z)·θ_x sideways, nothing at z = −h. So the
    engine turns about the line through (0, 0, −h) along x: the mounts' plane. The torque
    roll axis is x through the centre of gravity: the two are parallel, h apart."""
    system = balance.load(SYMMETRIC).mounts
    low = system.replace(
        mounts=tuple(
            m.replace(position_m=(m.position_m[0], m.position_m[1], -0.1)) for m in system.mounts
        )
    )
    axis = elastic_axis(low)
    assert_allclose(axis.direction, (1.0, 0.0, 0.0), atol=1e-12)  # rounding of K⁻¹
    assert_allclose(axis.through_m, (0.0, 0.0, -0.1), atol=1e-12)
    assert_allclose(axis.distance_m, 0.1, rtol=1e-12)
    assert angle_between_deg(axis, torque_roll_axis(low)) < 1e-9


def test_elastic_axis_of_the_symmetric_example_is_the_crank_axis():
    """The mounts in the plane of the centre of gravity: a couple about x turns the engine
    about x through the centre of gravity (Y = 0 by the reasoning above with h = 0); the angle
    to the torque roll axis is zero: decoupled, the torque excites roll alone."""
    system = balance.load(SYMMETRIC).mounts
    axis = elastic_axis(system)
    assert_allclose(axis.direction, (1.0, 0.0, 0.0), atol=1e-12)
    assert_allclose(axis.through_m, (0.0, 0.0, 0.0), atol=1e-12)
    assert angle_between_deg(axis, torque_roll_axis(system)) == 0.0


def test_elastic_axis_is_the_screw_axis_of_the_static_displacement():
    """For the coupled example, the definition checked directly: the displacement
    q = K⁻¹·(0, 0, 0, 1, 0, 0) moves each point p by u + θ × p; on the elastic axis that
    motion is along θ (a screw) and the axis' point is the one nearest the centre of
    gravity (perpendicular to θ)."""
    system = balance.load(COUPLED).mounts
    q = np.linalg.solve(system.stiffness_matrix(), [0, 0, 0, 1.0, 0, 0])
    axis = elastic_axis(system)
    p = np.array(axis.through_m)
    moved = q[:3] + np.cross(q[3:], p)
    theta = q[3:] / np.linalg.norm(q[3:])
    # the motion on the axis has no part across θ: rounding of the solve
    assert np.linalg.norm(moved - (moved @ theta) * theta) < 1e-12 * np.linalg.norm(q)
    assert abs(p @ theta) < 1e-15
    assert_allclose(np.abs(axis.direction), np.abs(theta), rtol=1e-12)


def test_angle_between_axes_is_small_angle_exact():
    """Two directions 1e-7 rad apart: 1e-7·180/π degrees, which acos would lose."""
    a = balance.mounting.Axis((1.0, 0.0, 0.0), (0.0, 0.0, 0.0))
    b = balance.mounting.Axis((math.cos(1e-7), math.sin(1e-7), 0.0), (0.0, 0.0, 0.0))
    assert_allclose(angle_between_deg(a, b), math.degrees(1e-7), rtol=1e-9)
