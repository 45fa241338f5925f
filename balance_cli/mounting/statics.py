"""Static deflections of the engine on its mounts: under its weight and under the reaction of
its mean torque, at the centre of gravity and at each mount."""

from dataclasses import dataclass

import numpy as np

from ..model import STANDARD_GRAVITY

__all__ = ["StaticLoad", "static_load", "weight", "torque_reaction"]


@dataclass(frozen=True)
class StaticLoad:
    """One steady load and what the mounts do under it.

    Attributes
    ----------
    name : str
        "weight" or "torque"
    wrench : ndarray, shape (6,)
        the load at the centre of gravity: forces N, moments N·m (Fx, Fy, Fz, Mx, My, Mz)
    displacement : ndarray, shape (6,)
        the centre of gravity's translation (m) and the rotation (rad)
    deflection_m : ndarray, shape (mounts, 3)
        each mount's deflection in engine axes, m
    force_n : ndarray, shape (mounts, 3)
        the force each mount passes on to the frame, engine axes, N (under the weight, the
        z components add up to −m·g: the mounts press down on the frame)
    local_deflection_m : ndarray, shape (mounts, 3)
        each deflection along the mount's own directions (compression, then the shears, for
        a mount given with compression and shear), m
    torque_nm : float or None
        the mean torque whose reaction this is, N·m (None for the weight)
    source : str
        where the load comes from, in words
    """

    name: str
    wrench: np.ndarray
    displacement: np.ndarray
    deflection_m: np.ndarray
    force_n: np.ndarray
    local_deflection_m: np.ndarray
    torque_nm: float | None = None
    source: str = ""

    def to_dict(self, names) -> dict:
        return {
            "load": self.name,
            "source": self.source,
            "torque_Nm": self.torque_nm,
            "wrench": dict(
                zip(
                    ("Fx_N", "Fy_N", "Fz_N", "Mx_Nm", "My_Nm", "Mz_Nm"),
                    _floats(self.wrench),
                    strict=True,
                )
            ),
            "centre_of_gravity": {
                **dict(zip(("x_m", "y_m", "z_m"), _floats(self.displacement[:3]), strict=True)),
                **dict(
                    zip(("rx_rad", "ry_rad", "rz_rad"), _floats(self.displacement[3:]), strict=True)
                ),
            },
            "mounts": [
                {
                    "mount": name,
                    "deflection_m": _floats(self.deflection_m[i]),
                    "local_deflection_m": _floats(self.local_deflection_m[i]),
                    "force_N": _floats(self.force_n[i]),
                }
                for i, name in enumerate(names)
            ],
        }


def _floats(values):
    return [float(v) + 0.0 for v in values]


def static_load(system, name, wrench, torque_nm=None, source="") -> StaticLoad:
    """The mounts' deflections and forces under ``wrench`` (6, at the centre of gravity)."""
    wrench = np.asarray(wrench, dtype=float)
    displacement = np.linalg.solve(system.stiffness_matrix(), wrench)
    deflection = np.array([m.transfer() @ displacement for m in system.mounts])
    force = np.array([m.stiffness() @ u for m, u in zip(system.mounts, deflection, strict=True)])
    local = np.array(
        [np.array(m.directions) @ u for m, u in zip(system.mounts, deflection, strict=True)]
    )
    return StaticLoad(name, wrench, displacement, deflection, force, local, torque_nm, source)


def weight(system) -> StaticLoad:
    """Under the weight m·g (down, −z), at the centre of gravity."""
    load = np.zeros(6)
    load[2] = -system.mass_kg * STANDARD_GRAVITY
    return static_load(system, "weight", load, source="m·g, g = 9.80665 m/s²")


def torque_reaction(system, torque_nm, source) -> StaticLoad:
    """Under the frame's reaction to a mean torque ``torque_nm`` (N·m, positive driving): the
    couple −torque about the crank's rotation vector, spin·x."""
    load = np.zeros(6)
    load[3] = -float(system.spin) * torque_nm
    return static_load(system, "torque", load, torque_nm, source)
