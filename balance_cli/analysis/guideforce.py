"""Guide forces and the guide-force moments of the marine project guides.

Every piston (a crosshead engine's crosshead) presses sideways on its guide; the equal and
opposite force reaches the frame through the main bearings, and the two make a couple about
the crank axis (MAN B&W project guides, section 17.05 "Guide Force Moments"):

- the **H-type** moment is the sum of the cylinders' couples: it rocks the engine about the
  crankshaft;
- the **X-type** moment is the bimoment Σ couple_j·(z_j − z̄) divided by the guide distance L
  (from the crankshaft to the middle of the crosshead guide, "i.e. the length of the connecting
  rod" in the guides' words): L is the rod length here, and only scales every X-type figure
  alike.

Each cylinder's guide force is solved exactly from the same linkage state the torques use
(Newton–Euler for the piston and its rod, whose point masses are lumped at its ends and whose
remaining rotational inertia is the rod's correcting moment C):

- the rod (massless between its end masses, inertia C) takes at its small end a force
  F = t·u + w·(i·u) (u its unit vector big end → small end), and its moment balance about the
  big end gives w = (C·β̈ − moments of the link rods it carries)/l;
- the piston, of mass m, obeys m·a = −F − g + i·N in its cylinder's frame (g = (p − p_c)·A,
  N the guide's lateral force on it): two equations for t and N.

A link rod's small-end force reaches its master rod at the knuckle pin (less the knuckle
mass's inertia), so link cylinders are solved before their masters.

The couple on the frame is −(s·N + e·g), s the pin's distance from the crank axis along the
cylinder axis and e the pin offset: the gas force acts along the cylinder axis, not through
an offset pin, so the piston's moment balance moves the guide force's line by e·g/N. With no
offset (every crosshead engine) it is s times the piston's force on its guide. The couples add
up to the frame reaction torque of :mod:`balance_cli.analysis.torque` (a second method: there it
comes from the kinetic energy), the crank pins' masses turning at constant radius adding
nothing.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..harmonics import accelerations as harmonic_accelerations
from ..harmonics import periodic_derivative
from ..tabular import Tabular
from .series import Series, cycle_series

__all__ = ["CylinderGuide", "GuideForces", "guide_forces"]


@dataclass(frozen=True)
class CylinderGuide:
    """One cylinder's guide force and couple over the cycle.

    Attributes
    ----------
    number : int
        the cylinder
    z_m : float
        its axial position, m
    force : Series
        the piston's (crosshead's) force on its guide, N, across the cylinder axis, positive in
        the direction of rotation
    couple : Series
        the couple of that force with the main bearings' reaction on the engine frame, about the
        crank axis, N·m, positive with rotation
    """

    number: int
    z_m: float
    force_curve: np.ndarray
    couple_curve: np.ndarray
    series: Any = field(repr=False, compare=False, default=None)

    # the orders of every cylinder's curves cost more than all else the JSON needs: they are
    # found when asked for
    @functools.cached_property
    def force(self):
        return self.series(self.force_curve, "N")

    @functools.cached_property
    def couple(self):
        return self.series(self.couple_curve, "Nm")

    def to_dict(self) -> dict:
        """The cylinder's largest guide force and couple over the cycle (the orders are the
        API's: :attr:`force`, :attr:`couple`)."""
        return {
            "cylinder": self.number,
            "z_m": self.z_m,
            "max_force_N": float(np.abs(self.force_curve).max()),
            "max_couple_Nm": float(np.abs(self.couple_curve).max()),
        }


@dataclass(frozen=True)
class GuideForces(Tabular):
    """The guide forces of an engine and its H-type and X-type guide-force moments.

    Attributes
    ----------
    h_type : Series
        Σ_j couple_j(θ), N·m (the order-k term is amplitude·cos(kθ − phase))
    x_type : Series
        Σ_j couple_j(θ)·(z_j − z̄)/L, N·m: the bimoment over the guide distance
    lever_m : float
        L, the guide distance the bimoment is divided by: the rod length, m
    mean_z_m : float
        z̄, the cylinders' mean axial position, m
    cylinders : tuple of CylinderGuide
        in the engine's cylinder order
    """

    h_type: Series
    x_type: Series
    lever_m: float
    mean_z_m: float
    cylinders: tuple

    @property
    def bimoment(self):
        """The X-type moment times L: Σ couple_j·(z_j − z̄), N·m² over the cycle."""
        return self.x_type.curve * self.lever_m

    def records(self) -> list:
        """One row per guide-force moment and order: ``moment`` ("H-type" or "X-type"),
        then the series' row (:meth:`Series.records <balance_cli.Series.records>`:
        ``order``, the mean as order 0, ``cos_Nm``, ``sin_Nm``, ``amplitude_Nm``,
        ``phase_deg``)."""
        return [
            {"moment": name, **row}
            for name, series in (("H-type", self.h_type), ("X-type", self.x_type))
            for row in series.records()
        ]

    def to_dict(self) -> dict:
        """``guide_force`` of ``torque --format json`` (see the JSON page)."""
        return {
            "lever_m": self.lever_m,
            "mean_z_m": self.mean_z_m,
            "h_type": self.h_type.to_dict(),
            "x_type": self.x_type.to_dict(),
            "cylinders": [c.to_dict() for c in self.cylinders],
        }


def _lateral(engine, state, net_pressure, area, turns):
    """(lateral force of each piston on its guide, couple on the frame), by cylinder number:
    curves over the cycle (``turns`` revolutions), N and N·m."""
    omega = engine.speed_rad_s
    masses, rods = state.masses, state.rods
    row: dict[int, int] = {}  # cylinder number: its piston's row
    for index, owner in enumerate(masses.cylinder):
        row.setdefault(int(owner), index)  # a cylinder's piston comes before its knuckle
    rod_row = {int(c): i for i, c in enumerate(rods.cylinder)}
    rates = (np.conj(rods.directions) * periodic_derivative(rods.directions)).imag
    # every mass's acceleration in one transform
    accelerations = harmonic_accelerations(masses.positions, omega)
    angular = omega**2 * periodic_derivative(rates).real
    link_moments: dict = {}
    forces, couples = {}, {}
    # link rods load their master rods: solve them first
    order = sorted(engine.cylinders, key=lambda c: not c.is_link)
    for cyl in order:
        n = cyl.number
        axis = np.exp(1j * engine.bank_angles_rad[cyl.bank_index])
        piston = masses.positions[row[n]]
        u = rods.directions[rod_row[n]]
        length = cyl.link_length_m if cyl.is_link else engine.rod_length_m
        gas = net_pressure[n] * area if net_pressure else 0.0
        w = np.tile(cyl.rod_inertia_kgm2 * angular[rod_row[n]], turns)
        if n in link_moments:
            w = w - link_moments[n]
        w = w / length
        a = np.tile(accelerations[row[n]] * np.conj(axis), turns)
        local = np.tile(u * np.conj(axis), turns)
        m = cyl.reciprocating_kg
        # each cylinder's own offset: a bank's or its own overrides the engine's
        offset = engine.pin_offset_of(cyl)
        t = (w * local.imag - gas - m * a.real) / local.real
        lateral = m * a.imag + t * local.imag + w * local.real  # the guide's force on the piston
        travel = np.tile(state.travel[n], turns)
        forces[n] = -lateral
        couples[n] = -(travel * lateral + offset * gas)
        if cyl.is_link:
            master = engine.cylinder(cyl.master)
            knuckle = piston - length * u
            big_end = (
                masses.positions[row[master.number]]
                - engine.rod_length_m * rods.directions[rod_row[master.number]]
            )
            load = (t + 1j * w) * np.tile(u, turns) - np.tile(
                cyl.knuckle_kg * harmonic_accelerations(knuckle, omega), turns
            )
            arm = np.tile(knuckle - big_end, turns)
            link_moments[master.number] = (
                link_moments.get(master.number, 0.0) + (np.conj(arm) * load).imag
            )
    return forces, couples


def guide_forces(engine, state, net_pressure, area, turns, max_order) -> GuideForces | None:
    """The guide forces of ``engine`` from its kinematic ``state`` over one revolution, with
    the net pressures (by cylinder over the cycle, Pa; empty for none) on pistons of ``area``
    m², as series of orders up to ``max_order``. None for a rotary: its cylinders turn with the
    frame, and the project guides' couples are those of an engine on its seating."""
    if engine.is_rotary:
        return None
    series = functools.partial(_series, engine, max_order)
    forces, couples = _lateral(engine, state, net_pressure, area, turns)
    mean = engine.mean_z_m
    lever = engine.rod_length_m
    cylinders = tuple(
        CylinderGuide(c.number, c.z_m, forces[c.number], couples[c.number], series)
        for c in engine.cylinders
    )
    h = sum(couples[c.number] for c in engine.cylinders)
    x = sum(couples[c.number] * (c.z_m - mean) for c in engine.cylinders) / lever
    return GuideForces(series(h, "Nm"), series(x, "Nm"), lever, mean, cylinders)


def _series(engine, max_order, values, unit):
    return cycle_series(engine, values, max_order, unit)
