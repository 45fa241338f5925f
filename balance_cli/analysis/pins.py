"""The forces on the crank pins and main bearings, by virtual work.

For a virtual shift δP of one crank pin (the cylinders held), the rods riding on it do the
work F·δP = Σ m·a·δx + Σ C·β̈·δβ + Σ (p − p_c)·A·δs; the force of the rods on the pin is −F.
The shifts close that pin's part of the linkage again, once per throw, with every step of a
Richardson-extrapolated central difference at once.
"""

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..checks import is_real
from ..errors import OrderError
from ..harmonics import accelerations as harmonic_accelerations
from ..harmonics import periodic_derivative
from ..kinematics import BIG_ENDS, CRANKSHAFT_OWNERS, linkage_state
from .series import Series
from .shaking import part_values

__all__ = ["PinForce", "pin_forces"]


@dataclass(frozen=True)
class PinForce:
    """The force the rods exert on one crank pin (``throw``, 1-based), or the crankshaft on its
    main bearings together (``throw`` None), over one period, in the fixed frame.

    ``force_n`` is complex, N (real part along the reference axis); ``radial`` (outwards along
    the throw) and ``tangential`` (positive with rotation: r·tangential turns the crank) are
    given for a pin. Orders are multiples of ½ for a four-stroke with gas.
    """

    throw: int | None
    period_deg: float
    theta_deg: np.ndarray
    force_n: np.ndarray
    radial: Series | None
    tangential: Series | None

    @cached_property
    def _spectrum(self):
        return np.fft.fft(self.force_n) / self.force_n.shape[-1]

    def order(self, k):
        """Forward and backward phasors of order ``k``, N: F = F⁺·e^{ikθ} + F⁻·e^{−ikθ}; k
        from 0 to below half the samples a period, a multiple of ½ for a four-stroke with gas
        (OrderError, a KeyError, otherwise)."""
        n = self.force_n.shape[-1]
        steps = k * self.period_deg / 360.0 if is_real(k) and math.isfinite(k) else math.nan
        # order(1e300) once wrapped round the samples and answered
        if not (0 <= steps < n / 2 and abs(steps - round(steps)) < 1e-9):
            raise OrderError(
                f"order {k!r} is not among the orders of these forces (multiples of "
                f"{360 / self.period_deg:g} below {n / 2 * 360 / self.period_deg:g})"
            )
        j = int(round(steps))
        c = self._spectrum
        return complex(c[j % n]), complex(c[-j % n])

    def to_dict(self, max_order, floor_n) -> dict:
        per_turn = self.period_deg / 360.0
        orders = []
        for j in range(0, int(round(max_order * per_turn)) + 1):
            forward, backward = self.order(j / per_turn)
            if j == 0:
                # the steady part: one phasor, kept as the forward one
                backward = 0j
            # a crank pin's force is read in the crank's terms (radial, tangential, forward,
            # backward); the engine's vertical belongs to the free forces
            orders.append(
                {
                    "order": j / per_turn,
                    "force": part_values(forward, backward, floor_n, "N", components=False),
                }
            )
        entry: dict = {"throw": self.throw, "orders": orders}
        if self.radial is not None and self.tangential is not None:
            entry["radial"] = self.radial.to_dict()
            entry["tangential"] = self.tangential.to_dict()
        return entry


#: virtual shifts of a crank pin, in crank radii: ±h and ±h/2 for a Richardson-extrapolated
#: central difference (error O(h⁴), far below the noise floor at h = 1e-4)
_SHIFT = 1e-4
_STEPS = np.array([1.0, -1.0, 0.5, -0.5])


def _derivative(values):
    """d/dh at 0 from ``values`` at h = _STEPS·step (leading axis), per unit step: central
    differences extrapolated, (4·fine − coarse)/3."""
    coarse = (values[0] - values[1]) / 2
    fine = values[2] - values[3]
    return (4 * fine - coarse) / 3


def pin_forces(engine, state, turns, net_pressure, area):
    """The force of the pin on the rods riding on it, by virtual work: for a virtual shift δP
    of the pin (the cylinders held), F·δP = Σ m·a·δx + Σ C·β̈·δβ + Σ (p − p_c)·A·δs; the force
    of the rods on the pin is −F. One complex curve over the cycle per throw, N."""
    omega = engine.speed_rad_s
    angles = state.angles_rad
    n = len(angles)
    masses, rods = state.masses, state.rods
    accelerations = harmonic_accelerations(masses.positions, omega)
    # what rides on the pins: the cylinders' masses and the big ends (not the crankshaft's own
    # masses, counterweights or balancer shafts)
    weights = np.where(masses.cylinder >= BIG_ENDS, masses.masses_kg, 0.0)[:, None]
    rates = (np.conj(rods.directions) * periodic_derivative(rods.directions)).imag
    angular_accelerations = omega**2 * periodic_derivative(rates).real
    step = _SHIFT * engine.crank_radius_m
    # every shift of one pin at once: (direction along/across) × (the four steps)
    shifts = (np.array([1.0, 1j])[:, None] * _STEPS[None, :] * step).reshape(-1, 1)
    grid = np.broadcast_to(angles, (len(shifts), n))
    forces = []
    for index in range(len(engine.throws)):
        shifted = linkage_state(engine, grid, {index: shifts}, throw_index=index)
        # only what rides on this pin moves with it: the same rows of the whole engine's state
        on_pin = np.isin(masses.cylinder, shifted.masses.cylinder) & (
            (masses.cylinder > 0) | (masses.throw_index == index)
        )
        rods_on_pin = np.isin(rods.cylinder, shifted.rods.cylinder)
        size = (2, len(_STEPS))
        dx = _derivative(np.moveaxis(shifted.masses.positions.reshape(-1, *size, n), 2, 0)) / step
        du = _derivative(np.moveaxis(shifted.rods.directions.reshape(-1, *size, n), 2, 0)) / step
        inertial = (
            weights[on_pin, None] * (np.conj(accelerations[on_pin])[:, None] * dx).real
        ).sum(axis=0)
        inertial += (
            rods.corrections_kgm2[rods_on_pin, None, None]
            * angular_accelerations[rods_on_pin, None]
            * (np.conj(rods.directions[rods_on_pin])[:, None] * du).imag
        ).sum(axis=0)
        parts = np.tile(inertial, turns)  # (along, across) × cycle
        # an opposed-piston cylinder has two rods but one pressure
        numbers = list(dict.fromkeys(int(m) for m in shifted.rods.cylinder))
        if net_pressure and numbers:
            ds = (
                _derivative(
                    np.moveaxis(
                        np.array([shifted.travel[m] for m in numbers]).reshape(-1, *size, n), 2, 0
                    )
                )
                / step
            )
            parts = parts + sum(
                net_pressure[m] * area * np.tile(ds[i], turns) for i, m in enumerate(numbers)
            )
        forces.append(-(parts[0] + 1j * parts[1]))
    # each crankshaft's own masses and its counterweights load its own main bearings; a
    # balancer shaft runs in bearings of its own: its rows (throw −1, which picks the last
    # throw's crankshaft here) fall out by their owner code
    shaft_of = np.array([t.crankshaft_index for t in engine.throws])[masses.throw_index]
    crank_inertia = []
    for s_index in range(len(engine.crankshafts)):
        own = np.where(
            np.isin(masses.cylinder, CRANKSHAFT_OWNERS) & (shaft_of == s_index),
            masses.masses_kg,
            0.0,
        )
        crank_inertia.append(np.tile(-(own[:, None] * accelerations).sum(axis=0), turns))
    return forces, crank_inertia
