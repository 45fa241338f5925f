"""The result of :func:`balance_cli.mounts`: the engine's modes on its mounts, its axes, static
deflections, resonances crossed and forced response, with its JSON document and records."""

from dataclasses import dataclass

import numpy as np

from ..model import Engine, MountSystem
from ..tabular import Tabular
from ..units import phasor_deg, rad_s_to_rpm
from .axes import Axis
from .response import Response
from .statics import StaticLoad

__all__ = ["Crossing", "MountResult", "CG"]

#: the name of the centre of gravity among the mounts in records and tables
CG = "centre of gravity"
#: the motion columns of a record: translations (m) and rotations (rad)
_MOTION_KEYS = ("x_m", "y_m", "z_m", "rx_rad", "ry_rad", "rz_rad")
_FORCE_KEYS = ("Fx_N", "Fy_N", "Fz_N")


@dataclass(frozen=True)
class Crossing:
    """A resonance crossed within the speeds: order ``order``'s frequency equals mode
    ``mode``'s at ``speed_rpm``; ``excited`` whether the order drives the mode there (its
    modal force is more than rounding)."""

    mode: int
    motion: str
    order: float
    speed_rpm: float
    excited: bool

    def to_dict(self) -> dict:
        return {
            "mode": self.mode,
            "motion": self.motion,
            "order": self.order,
            "speed_rpm": self.speed_rpm,
            "excited": self.excited,
        }


def _amplitude(value):
    return float(abs(value))


def _phase(value):
    # amplitude·cos(kθ − phase): the kθ of the positive peak, as torques and components give it
    return phasor_deg(complex(value).conjugate()) if value else 0.0


def _system_dict(system: MountSystem) -> dict:
    return {
        "mass_kg": system.mass_kg,
        "centre_of_gravity_m": list(system.cg_m),
        "inertia_kgm2": [list(row) for row in system.inertia_kgm2],
        "rotation": system.rotation,
        "mounts": [
            {
                "mount": m.name,
                "position_m": list(m.position_m),
                "rates_N_per_m": list(m.rates_n_m),
                "directions": [list(d) for d in m.directions],
                "loss_factor": m.loss_factor,
                "damping_Ns_per_m": list(m.damping_ns_m),
            }
            for m in system.mounts
        ],
    }


@dataclass(frozen=True)
class MountResult(Tabular):
    """The engine on its mounts: modes, axes, static deflections and forced response.

    Attributes
    ----------
    engine : Engine
    system : MountSystem
    modes : tuple of Mode
        lowest first, each with its kinetic-energy distribution
    torque_roll_axis, elastic_axis : Axis
        see :mod:`balance_cli.mounting.axes`
    axes_angle_deg : float
        the angle between them, 0 to 90°
    weight : StaticLoad
    torque_load : StaticLoad or None
        under the reaction to the mean torque (None: no gas cycle and no power given)
    orders : ndarray
        the orders applied (multiples of ½ for a four-stroke)
    speeds_rpm : ndarray
    response : Response
        complex amplitudes by speed × order and the peaks of their sum over a cycle
    crossings : tuple of Crossing
        every mode and order whose resonance lies within the speeds, by speed
    with_gas : bool
        whether the roll excitation has a gas torque, or the inertia and tilting couples alone
    """

    engine: Engine
    system: MountSystem
    modes: tuple
    torque_roll_axis: Axis
    elastic_axis: Axis
    axes_angle_deg: float
    weight: StaticLoad
    torque_load: StaticLoad | None
    orders: np.ndarray
    speeds_rpm: np.ndarray
    response: Response
    crossings: tuple
    with_gas: bool = False

    @property
    def names(self) -> tuple:
        """The mounts' names, in the system's order."""
        return self.system.names

    def largest(self) -> list:
        """Per mount: (name, peak force of each component N, at speeds rpm, largest size of
        the force vector N, at speed rpm), the orders summed over a cycle."""
        out = []
        peaks = self.response.force_peak_n
        sizes = self.response.force_magnitude_peak_n
        for m, name in enumerate(self.names):
            at = [int(np.argmax(peaks[:, m, c])) for c in range(3)]
            i = int(np.argmax(sizes[:, m]))
            out.append(
                (
                    name,
                    [float(peaks[s, m, c]) for c, s in enumerate(at)],
                    [float(self.speeds_rpm[s]) for s in at],
                    float(sizes[i, m]),
                    float(self.speeds_rpm[i]),
                )
            )
        return out

    def near(self, speed_rpm) -> tuple:
        """The crossings nearer to this speed of the sweep than to any other speed of it."""
        speeds = np.sort(self.speeds_rpm)
        i = int(np.searchsorted(speeds, speed_rpm))
        low = (speeds[i - 1] + speed_rpm) / 2 if i > 0 else -np.inf
        high = (speeds[i + 1] + speed_rpm) / 2 if i + 1 < len(speeds) else np.inf
        return tuple(c for c in self.crossings if low <= c.speed_rpm < high)

    def to_dict(self) -> dict:
        """This engine's entry of ``mounts --format json`` (SI units; see the how-to page)."""
        engine, r = self.engine, self.response
        return {
            "name": engine.name,
            "config": engine.config_path,
            "cycle": engine.cycle,
            "speed_rpm": rad_s_to_rpm(engine.speed_rad_s),
            "system": _system_dict(self.system),
            "modes": [m.to_dict() for m in self.modes],
            "torque_roll_axis": self.torque_roll_axis.to_dict(),
            "elastic_axis": self.elastic_axis.to_dict(),
            "axes_angle_deg": self.axes_angle_deg,
            "static": {
                "weight": self.weight.to_dict(self.names),
                "torque": None
                if self.torque_load is None
                else self.torque_load.to_dict(self.names),
            },
            "with_gas": self.with_gas,
            "orders": [float(k) for k in self.orders],
            "resonances": [c.to_dict() for c in self.crossings],
            "speeds": [
                {
                    "speed_rpm": float(v),
                    "motion_peak": dict(
                        zip(_MOTION_KEYS, map(float, r.motion_peak[i]), strict=True)
                    ),
                    "mounts": [
                        {
                            "mount": name,
                            "force_peak_N": [float(f) for f in r.force_peak_n[i, m]],
                            "force_magnitude_peak_N": float(r.force_magnitude_peak_n[i, m]),
                            "deflection_peak_m": [float(d) for d in r.deflection_peak_m[i, m]],
                        }
                        for m, name in enumerate(self.names)
                    ],
                    "orders": [
                        {
                            "order": float(k),
                            "motion": [_amplitude(x) for x in r.motion[i, o]],
                            "motion_deg": [_phase(x) for x in r.motion[i, o]],
                            "mounts": [
                                {
                                    "mount": name,
                                    "force_N": [_amplitude(f) for f in r.force_n[i, o, m]],
                                    "force_deg": [_phase(f) for f in r.force_n[i, o, m]],
                                }
                                for m, name in enumerate(self.names)
                            ],
                        }
                        for o, k in enumerate(self.orders)
                    ],
                }
                for i, v in enumerate(self.speeds_rpm)
            ],
        }

    def records(self) -> list:
        """The forced response in long form, one dict a speed, order and place: ``engine``,
        ``config``, ``speed_rpm``, ``order`` (a number, or "all" for the peaks of the orders
        summed over a cycle), ``where`` (a mount's name, or "centre of gravity"), the motion
        amplitudes (``x_m``, ``y_m``, ``z_m``: a mount's deflection or the centre of gravity's
        translation; ``rx_rad``, ``ry_rad``, ``rz_rad``: the rotation, centre of gravity
        only), the force a mount passes on (``Fx_N``, ``Fy_N``, ``Fz_N``, and ``F_N`` the
        largest size of the vector over a cycle, on "all" rows); None where a column does not
        apply. SI units."""
        r = self.response
        out = []
        head = {"engine": self.engine.name, "config": self.engine.config_path}

        def row(speed, order, where, motion, forces=None, size=None):
            return {
                **head,
                "speed_rpm": float(speed),
                "order": order,
                "where": where,
                **dict(zip(_MOTION_KEYS, motion, strict=True)),
                **dict(zip(_FORCE_KEYS, forces or (None,) * 3, strict=True)),
                "F_N": size,
            }

        for i, speed in enumerate(self.speeds_rpm):
            out.append(row(speed, "all", CG, [float(v) for v in r.motion_peak[i]]))
            for m, name in enumerate(self.names):
                out.append(
                    row(
                        speed,
                        "all",
                        name,
                        [float(v) for v in r.deflection_peak_m[i, m]] + [None] * 3,
                        [float(f) for f in r.force_peak_n[i, m]],
                        float(r.force_magnitude_peak_n[i, m]),
                    )
                )
            for o, k in enumerate(self.orders):
                out.append(row(speed, float(k), CG, [_amplitude(v) for v in r.motion[i, o]]))
                for m, name in enumerate(self.names):
                    out.append(
                        row(
                            speed,
                            float(k),
                            name,
                            [_amplitude(v) for v in r.deflection_m[i, o, m]] + [None] * 3,
                            [_amplitude(f) for f in r.force_n[i, o, m]],
                        )
                    )
        return out
