"""How near a mount system is to torque roll axis decoupling: the mode nearest the turn about
the torque roll axis (TRA), how pure it is, where its axis lies, and the coupling the
decoupling's rates are found by (see :mod:`.decoupling`)."""

import math
from dataclasses import dataclass

import numpy as np

from ..checks import instance
from ..model import MountSystem
from .axes import angle_between_deg, elastic_axis, torque_roll_axis
from .modes import natural_modes

__all__ = ["TraState", "tra_state", "tra_rotation", "coupling"]


@dataclass(frozen=True)
class TraState:
    """How near a mount system is to torque roll axis decoupling.

    Attributes
    ----------
    mode : int
        the natural mode nearest the rotation about the TRA (the largest ``purity_pct``),
        1 for the lowest
    frequency_hz : float
        its frequency
    motion : str
        its dominant motion (roll, where the crank axis is near the TRA)
    purity_pct : float
        the decoupling purity: 100·(φᵀ·M·q*)²/((φᵀ·M·φ)·(q*ᵀ·M·q*)), the share of the mode
        φ's kinetic energy in the rotation about the TRA q* (100: the mode is that rotation)
    tra_energy_pct : float
        the mode's kinetic-energy share in the TRA coordinate (the rotation about ê when the
        motions are taken along ê and two axes across it, Jeong and Singh's decoupling
        table): 100·(ê·θ)·(ê·J·θ)/(φᵀ·M·φ)
    axis_angle_deg : float
        the angle between the mode's axis of rotation and the TRA, 0 to 90°
    axis_offset_m : float
        how far the mode's screw axis passes from the centre of gravity (the TRA passes
        through it), m
    coupling : float
        the sine of the angle between L⁻¹·K·q* and Lᵀ·q* (L·Lᵀ = M): 0 when the rotation about
        the TRA is a natural mode, the measure the rates are found by
    axes_angle_deg : float
        the angle between the TRA and the elastic axis of the crank's torque
    """

    mode: int
    frequency_hz: float
    motion: str
    purity_pct: float
    tra_energy_pct: float
    axis_angle_deg: float
    axis_offset_m: float
    coupling: float
    axes_angle_deg: float

    def to_dict(self) -> dict:
        return {
            "mode": self.mode,
            "frequency_Hz": self.frequency_hz,
            "motion": self.motion,
            "purity_pct": self.purity_pct,
            "tra_energy_pct": self.tra_energy_pct,
            "axis_angle_deg": self.axis_angle_deg,
            "axis_offset_m": self.axis_offset_m,
            "coupling": self.coupling,
            "axes_angle_deg": self.axes_angle_deg,
        }


def tra_rotation(system):
    """q* = (0, ê): a unit rotation about the TRA, ê = J⁻¹·x̂/|J⁻¹·x̂|."""
    return np.concatenate([np.zeros(3), torque_roll_axis(system).direction])


def coupling(system, q=None):
    """|P·a|/|a| with a = L⁻¹·K·q*, P the projection across v = Lᵀ·q*."""
    q = tra_rotation(system) if q is None else q
    lower = np.linalg.cholesky(system.mass_matrix())
    a = np.linalg.solve(lower, system.stiffness_matrix() @ q)
    v = lower.T @ q
    across = a - (a @ v) / (v @ v) * v
    size = float(np.linalg.norm(a))
    return float(np.linalg.norm(across)) / size if size > 0 else 0.0


def _screw_offset(u, theta):
    """The distance of the screw axis of a small motion (u, θ) from the centre of gravity:
    |θ × u|/|θ|², m."""
    return float(np.linalg.norm(np.cross(theta, u))) / float(theta @ theta)


def tra_state(system) -> TraState:
    """How near ``system`` (a :class:`~balance_cli.model.MountSystem`) is to torque roll axis
    decoupling: the mode nearest the rotation about the TRA, its purity and its axis."""
    instance(system, MountSystem, "system", hint=" (Engine.mounts is one)")
    mass = system.mass_matrix()
    q = tra_rotation(system)
    modes = natural_modes(system)
    overlap = [float(m.shape @ mass @ q) ** 2 / float(q @ mass @ q) for m in modes]
    best = int(np.argmax(overlap))
    mode = modes[best]  # mass-normalised: φᵀ·M·φ = 1
    u, theta = mode.shape[:3], mode.shape[3:]
    e = q[3:]
    inertia = np.array(system.inertia_kgm2)
    cross = float(np.linalg.norm(np.cross(theta, e)))
    tra = torque_roll_axis(system)
    return TraState(
        mode.number,
        mode.frequency_hz,
        mode.motion,
        100.0 * overlap[best],
        100.0 * float(e @ theta) * float(e @ inertia @ theta),
        math.degrees(math.atan2(cross, abs(float(e @ theta)))),
        _screw_offset(u, theta),
        coupling(system, q),
        angle_between_deg(tra, elastic_axis(system)),
    )
