"""The torque roll axis and the elastic axis of the crank's torque, and the angle between them.

A couple about the crank axis (x) turns the free engine about the **torque roll axis**: its
angular acceleration is J⁻¹·x̂ (J about the centre of gravity), so the axis has that direction
and passes through the centre of gravity. Held by its mounts alone (statically), the same
couple displaces the engine by q = K⁻¹·(0, 0, 0, x̂): a small screw motion, rotation θ and
translation u of the centre of gravity, whose axis — the **elastic axis** of the crank's torque
— has the direction of θ and passes through θ × u/|θ|² (from the centre of gravity). Where the
two axes coincide, the rotation about the torque roll axis is a natural mode (K·M⁻¹·w is then
proportional to w, w the couple): the torque excites that one mode only — Jeong and Singh's
(2000) torque roll axis decoupling.
"""

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Axis", "torque_roll_axis", "elastic_axis", "angle_between_deg"]


@dataclass(frozen=True)
class Axis:
    """A line of engine axes: its unit ``direction`` (x component positive, or else the first
    non-zero one) and the point ``through_m`` on it nearest to the centre of gravity, m from
    the centre of gravity."""

    direction: tuple
    through_m: tuple

    @property
    def distance_m(self) -> float:
        """How far the line passes from the centre of gravity, m."""
        return float(np.linalg.norm(self.through_m))

    def to_dict(self) -> dict:
        return {
            "direction": list(self.direction),
            "through_m": list(self.through_m),
            "distance_m": self.distance_m,
        }


def _oriented(vector):
    unit = np.asarray(vector, dtype=float) / np.linalg.norm(vector)
    first = next((v for v in unit if abs(v) > 1e-12), 1.0)
    return unit if first > 0 else -unit


def _tuple(vector):
    return tuple(float(v) + 0.0 for v in vector)


def torque_roll_axis(system) -> Axis:
    """J⁻¹·x̂ through the centre of gravity."""
    direction = np.linalg.solve(np.array(system.inertia_kgm2), np.array([1.0, 0.0, 0.0]))
    return Axis(_tuple(_oriented(direction)), (0.0, 0.0, 0.0))


def elastic_axis(system) -> Axis:
    """The screw axis of the static displacement under a couple about x."""
    q = np.linalg.solve(system.stiffness_matrix(), np.array([0.0, 0.0, 0.0, 1.0, 0.0, 0.0]))
    u, theta = q[:3], q[3:]
    through = np.cross(theta, u) / float(theta @ theta)
    return Axis(_tuple(_oriented(theta)), _tuple(through))


def angle_between_deg(a: Axis, b: Axis) -> float:
    """The angle between two axes' directions, 0 to 90°."""
    # atan2 of the cross and dot products keeps small angles exact, as acos would not
    cross = float(np.linalg.norm(np.cross(a.direction, b.direction)))
    return math.degrees(math.atan2(cross, abs(float(np.dot(a.direction, b.direction)))))
