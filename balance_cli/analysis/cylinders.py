"""Each cylinder's own tangential torque on its throw: the excitation a torsional model takes.

A cylinder's inertia torque is −½·ω²·dμ_c/dθ with μ_c the reduced mass of its own parts (its
piston, rod and link); its gas torque −(p − p_crankcase)·A·ds/dθ. Both come from the engine's
one kinematic state and gas load, as the engine's torque does, so they add up to it.
"""

from dataclasses import dataclass

import numpy as np

from ..checks import instance
from ..errors import AnalysisError, NotInResultError
from ..harmonics import periodic_derivative
from ..kinematics import kinematic_state
from ..model import Engine
from ..output import DOCUMENT_VERSION
from ..tabular import Tabular
from ..units import rad_s_to_rpm
from .gas import gas_load, piston_gas_torque
from .inertia import reduced_mass_and_momentum
from .series import Series, cycle_series
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, check_settings

__all__ = ["CylinderTorque", "CylinderTorques", "cylinder_torques"]


@dataclass(frozen=True)
class CylinderTorque:
    """One cylinder's own tangential torque on its throw, at the engine's speed.

    ``inertia`` is what its piston, rod (and link) exert, −½·ω²·dμ_c/dθ with μ_c the reduced
    mass of its parts alone (the crank pins' masses turn at a constant radius and exert none);
    ``gas`` its gas pressure's, −(p − p_crankcase)·A·ds/dθ (None without a pressure). Both
    against θ, the crank angle of throw 1, so its firing phase is in them; the engine's total
    torque is their sum over the cylinders. ``throw`` is the throw's number (1-based).
    """

    number: int
    throw: int
    inertia: Series
    gas: Series | None

    def to_dict(self) -> dict:
        return {
            "cylinder": self.number,
            "throw": self.throw,
            "inertia": self.inertia.to_dict(),
            "gas": None if self.gas is None else self.gas.to_dict(),
        }


@dataclass(frozen=True)
class CylinderTorques(Tabular):
    """Every cylinder's own torque (:class:`CylinderTorque`, in the engine's cylinder order).

    Attributes
    ----------
    engine : Engine
    samples, max_order : int
        crank angles a revolution, and the highest order given
    cylinders : tuple of CylinderTorque
    """

    engine: Engine
    samples: int
    max_order: int
    cylinders: tuple

    def __iter__(self):
        return iter(self.cylinders)

    def __len__(self):
        return len(self.cylinders)

    def __getitem__(self, index):
        return self.cylinders[index]

    def cylinder(self, number: int) -> CylinderTorque:
        """The torque of cylinder ``number``; KeyError for a number the engine has not."""
        for c in self.cylinders:
            if c.number == number:
                return c
        raise NotInResultError(
            f"{number!r} is not one of the engine's cylinders "
            f"({', '.join(str(c.number) for c in self.cylinders)})",
            "number",
        )

    @property
    def orders(self) -> np.ndarray:
        """The orders every series gives (multiples of ½ for a four-stroke)."""
        return np.array([k for k, _, _ in self.cylinders[0].inertia.orders])

    def records(self) -> list:
        """One row per cylinder, torque and order: ``engine``, ``cylinder``, ``throw``,
        ``torque`` ("inertia", or "gas" with a pressure), then the series' row
        (:meth:`Series.records <balance_cli.Series.records>`: ``order``, the mean as order 0,
        ``cos_Nm``, ``sin_Nm``, ``amplitude_Nm``, ``phase_deg``)."""
        return [
            {
                "engine": self.engine.name,
                "cylinder": c.number,
                "throw": c.throw,
                "torque": name,
                **row,
            }
            for c in self.cylinders
            for name, series in (("inertia", c.inertia), ("gas", c.gas))
            if series is not None
            for row in series.records()
        ]

    def to_dict(self) -> dict:
        engine = self.engine
        return {
            "balance_version": DOCUMENT_VERSION,
            "name": engine.name,
            "config": engine.config_path,
            "speed_rpm": rad_s_to_rpm(engine.speed_rad_s),
            "samples": self.samples,
            "max_order": self.max_order,
            "cylinders": [c.to_dict() for c in self.cylinders],
        }


def cylinder_torques(
    engine, samples=DEFAULT_SAMPLES, max_order=DEFAULT_MAX_ORDER, pressure=None, bore_m=None
) -> CylinderTorques:
    """Every cylinder's own inertia and gas torque, from the same kinematic state, reduced mass
    and gas load as :func:`~balance_cli.torque`.

    ``pressure`` and ``bore_m`` as in :func:`~balance_cli.torque` (default the engine's [gas]
    cycle, if any). An engine of one crankshaft only (AnalysisError otherwise).
    """
    instance(engine, Engine, "engine", hint=" (balance.load gives one)")
    check_settings(samples, max_order)
    state = kinematic_state(engine, samples)
    if engine.has_several_crankshafts or any(c.is_opposed for c in engine.cylinders):
        raise AnalysisError(
            "has several crankshafts or opposed pistons; a cylinder's torque "
            "on one throw is given for one crankshaft only",
            "engine",
        )
    gas = gas_load(engine, samples, pressure, bore_m)
    omega = engine.speed_rad_s
    turns = engine.turns_per_cycle
    masses, rods = state.masses, state.rods
    out = []
    for cylinder in engine.cylinders:
        n = cylinder.number
        # only this cylinder's rows; the shaft's constant inertia in μ has no derivative: no
        # torque of its own
        mu, _ = reduced_mass_and_momentum(
            engine, state.parts(masses.cylinder == n, rods.cylinder == n)
        )
        inertia = np.tile(-0.5 * omega**2 * periodic_derivative(mu).real, turns)
        torque = None
        if gas is not None:
            torque = cycle_series(
                engine,
                piston_gas_torque(gas.net_pressure[n], gas.area_m2, state.travel_rates[n], turns),
                max_order,
            )
        out.append(
            CylinderTorque(n, cylinder.throw, cycle_series(engine, inertia, max_order), torque)
        )
    return CylinderTorques(engine, samples, max_order, tuple(out))
