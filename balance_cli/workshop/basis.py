"""What one kilogram at each point mass of an engine shakes it with: forces are linear in the
masses, so every assembly of weighed parts and every run of a mass scatter is a weighted sum
of these, exactly.

The engine's own analysis (:func:`balance_cli.analysis.shaking.shaking_forces`) of a probe
copy gives them: the same geometry with a distinct mass at each kind of point (1 kg at every
piston pin, 2 kg at every knuckle pin, 3 kg at every opposed piston, 4 kg at every crank pin's
big ends, 5 kg for the crank's own unbalance), so that each row of its point masses is known
by its mass, and its share of the force divided by that mass is the response to one kilogram.
Counterweights and balancer shafts as built are not scattered: their share of the engine's own
analysis is kept as it is.
"""

from dataclasses import dataclass, replace

import numpy as np

from ..analysis.shaking import shaking_forces
from ..kinematics import BALANCER, BIG_ENDS, COUNTERWEIGHT, CRANK
from ..model import Engine

__all__ = ["UnitBasis", "unit_basis", "PROBE_KG"]

#: the probe's mass at each kind of point, kg: distinct, so that a row is known by its mass
PROBE_KG = {"piston": 1.0, "knuckle": 2.0, "opposed": 3.0, "pin": 4.0, "crank": 5.0}


@dataclass(frozen=True)
class UnitBasis:
    """The force and free-moment coefficients of one kilogram at each point mass.

    Attributes
    ----------
    kinds : tuple of str
        each row's kind: "piston", "knuckle", "opposed", "pin" (the big ends at a crank pin)
        or "crank" (the crankshaft's own unbalance at a pin)
    owners : ndarray of int
        each row's cylinder number (piston, knuckle, opposed) or throw index, 0-based (pin,
        crank)
    force : ndarray, complex, shape (rows, samples)
        Fourier coefficients of the inertia force of 1 kg there, N/kg (k = 0, 1, …, −1)
    moment : ndarray, complex, shape (rows, samples)
        the same for the free moment about z̄, N·m/kg
    fixed_force, fixed_moment : ndarray, complex, shape (samples,)
        the counterweights' and balancer shafts' share as built, N and N·m
    nominal_kg : ndarray, shape (rows,)
        each row's mass in the engine itself, kg
    """

    kinds: tuple
    owners: np.ndarray
    force: np.ndarray
    moment: np.ndarray
    fixed_force: np.ndarray
    fixed_moment: np.ndarray
    nominal_kg: np.ndarray

    @property
    def samples(self) -> int:
        return self.force.shape[-1]

    def rows(self, kind: str) -> dict:
        """Row index of each owner of ``kind``: {cylinder number or throw index: row}."""
        return {
            int(o): i
            for i, (k, o) in enumerate(zip(self.kinds, self.owners, strict=True))
            if k == kind
        }

    def nominal(self):
        """The engine's own force and moment coefficients (N, N·m): every row at its mass."""
        return (
            self.nominal_kg @ self.force + self.fixed_force,
            self.nominal_kg @ self.moment + self.fixed_moment,
        )


def _probe(engine: Engine) -> Engine:
    """The engine with a distinct mass at each kind of point and nothing as built."""
    cylinders = tuple(
        replace(
            c,
            reciprocating_kg=PROBE_KG["piston"],
            knuckle_kg=PROBE_KG["knuckle"] if c.is_link else 0.0,
            opposed_reciprocating_kg=PROBE_KG["opposed"] if c.is_opposed else None,
        )
        for c in engine.cylinders
    )
    return engine.replace(
        cylinders=cylinders,
        throws=tuple(replace(t, rotating_kg=None) for t in engine.throws),
        rotating_kg=PROBE_KG["pin"],
        crank_kg=PROBE_KG["crank"],
        counterweights=(),
        balancer_shafts=(),
        name=f"{engine.name} (unit probe)"[:120],
    )


def _nominal_mass(engine, kind, owner):
    if kind == "piston":
        return engine.cylinder(owner).reciprocating_kg
    if kind == "knuckle":
        return engine.cylinder(owner).knuckle_kg
    if kind == "opposed":
        return engine.cylinder(owner).opposed_reciprocating_kg
    if kind == "pin":
        return engine.rotating_of(owner)
    return engine.crank_kg


def unit_basis(engine: Engine, samples: int, max_order: int) -> UnitBasis:
    """The response of ``engine`` to one kilogram at each of its point masses, from its own
    exact kinematics at ``samples`` angles a revolution (orders up to ``max_order`` checked
    for aliasing, as every analysis does)."""
    probe = shaking_forces(_probe(engine), samples, max_order)
    masses, coefficients = probe.masses, probe.mass_coefficients
    assert masses is not None and coefficients is not None  # an engine's own analysis has both
    by_mass = {v: k for k, v in PROBE_KG.items()}
    kinds, owners, rows = [], [], []
    for i, (mass, owner, throw) in enumerate(
        zip(masses.masses_kg, masses.cylinder, masses.throw_index, strict=True)
    ):
        kind = by_mass[float(mass)]
        kinds.append(kind)
        owners.append(int(throw) if owner in (BIG_ENDS, CRANK) else int(owner))
        rows.append(i)
    per_mass = coefficients[rows] / masses.masses_kg[rows, None]
    levers = masses.z_m[rows] - engine.mean_z_m
    fixed_force = np.zeros(samples, complex)
    fixed_moment = np.zeros(samples, complex)
    if engine.counterweights or engine.balancer_shafts:
        own = shaking_forces(engine, samples, max_order)
        own_masses, own_coefficients = own.masses, own.mass_coefficients
        assert own_masses is not None and own_coefficients is not None
        built = np.isin(own_masses.cylinder, (COUNTERWEIGHT, BALANCER))
        fixed_force = own_coefficients[built].sum(axis=0)
        fixed_moment = (
            (own_masses.z_m[built] - engine.mean_z_m)[:, None] * own_coefficients[built]
        ).sum(axis=0)
    return UnitBasis(
        kinds=tuple(kinds),
        owners=np.array(owners),
        force=per_mass,
        moment=levers[:, None] * per_mass,
        fixed_force=fixed_force,
        fixed_moment=fixed_moment,
        nominal_kg=np.array(
            [_nominal_mass(engine, k, o) for k, o in zip(kinds, owners, strict=True)]
        ),
    )
