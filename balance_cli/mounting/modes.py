"""The six rigid-body modes of the engine on its mounts, each named by its dominant motion, with
the kinetic-energy distribution that says how pure it is (the decoupling table)."""

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import eigh

from ..model import DOF_LABELS, MOTIONS

__all__ = ["Mode", "natural_modes", "energy_distribution"]


def energy_distribution(shape, mass) -> np.ndarray:
    """The share of mode ``shape``'s kinetic energy in each coordinate, percent:
    100·φ_j·(M·φ)_j / (φᵀ·M·φ). They add up to 100; with products of inertia a rotation's
    share may be a little below zero (the coupling term of two rotations is split between
    them)."""
    weighted = mass @ shape
    return 100.0 * shape * weighted / float(shape @ weighted)


@dataclass(frozen=True)
class Mode:
    """One natural mode of the engine on its mounts.

    Attributes
    ----------
    number : int
        1 for the lowest frequency
    frequency_hz : float
    shape : ndarray, shape (6,)
        mass-normalised (φᵀ·M·φ = 1): translations of the centre of gravity in m/√kg, rotations
        in rad/√kg/m, in the order x, y, z, rx, ry, rz; the sign makes the dominant
        coordinate positive
    energy_pct : ndarray, shape (6,)
        the kinetic-energy distribution over the six coordinates, percent
    """

    number: int
    frequency_hz: float
    shape: np.ndarray
    energy_pct: np.ndarray

    @property
    def dominant(self) -> int:
        """The coordinate (0-5) that holds most of the mode's kinetic energy."""
        return int(np.argmax(self.energy_pct))

    @property
    def motion(self) -> str:
        """The dominant motion's name: fore-aft, lateral, bounce, roll, pitch or yaw."""
        return MOTIONS[self.dominant]

    @property
    def purity_pct(self) -> float:
        """The dominant motion's share of the kinetic energy, percent (100: decoupled)."""
        return float(self.energy_pct[self.dominant])

    @property
    def omega_rad_s(self) -> float:
        return 2.0 * math.pi * self.frequency_hz

    def to_dict(self) -> dict:
        return {
            "mode": self.number,
            "frequency_Hz": self.frequency_hz,
            "motion": self.motion,
            "purity_pct": self.purity_pct,
            "energy_pct": dict(zip(DOF_LABELS, map(float, self.energy_pct), strict=True)),
            "shape": [float(v) for v in self.shape],
        }


def natural_modes(system) -> tuple:
    """The undamped modes of ``system`` (a :class:`~balance_cli.model.MountSystem`), lowest
    first: K·φ = ω²·M·φ solved by scipy's generalised symmetric eigen-solver."""
    mass = system.mass_matrix()
    values, vectors = eigh(system.stiffness_matrix(), mass)
    modes = []
    for r in range(6):
        shape = vectors[:, r]
        energy = energy_distribution(shape, mass)
        if shape[int(np.argmax(energy))] < 0:
            shape = -shape
        modes.append(
            Mode(r + 1, math.sqrt(max(float(values[r]), 0.0)) / (2.0 * math.pi), shape, energy)
        )
    return tuple(modes)
