"""Counterweights and balancer shafts as built: the masses an engine carries to balance itself."""

import numbers
from dataclasses import dataclass

from ..errors import ModelError
from .values import check_angle, check_quantity

__all__ = ["CounterweightMass", "BalancerMass", "BalancerShaftSpec", "MAX_SHAFT_RATIO"]

#: the fastest balancer shaft, turns per crank turn: real ones run at 1 or 2 (a few at 4);
#: much faster ones would need more samples a revolution than any analysis takes by default
MAX_SHAFT_RATIO = 16


@dataclass(frozen=True)
class CounterweightMass:
    """A counterweight as built: a mass on the crankshaft, turning with one throw.

    Parameters
    ----------
    throw : int
        the number of the throw (from 1) whose pin it is measured from
    mass_radius_kgm : float
        its unbalance m·ρ, kg·m (all that the forces and torques depend on)
    angle_rad : float
        its direction from its throw's crank pin, positive with rotation (of that throw's
        crankshaft), rad: π puts it opposite the pin
    z_m : float or None
        axial position, m; None (the default) takes its throw's ``z_m``
    radius_m : float or None
        radius of its centre of mass, m, when known (then ``mass_kg`` is m·ρ/ρ, and the
        counterweight adds m·ρ² to the reduced mass like any point mass); None: only m·ρ is
        known, which gives every force and moment, and its moment of inertia is left out
    """

    throw: int
    mass_radius_kgm: float
    angle_rad: float
    z_m: float | None = None
    radius_m: float | None = None

    def __post_init__(self):
        if (
            isinstance(self.throw, bool)
            or not isinstance(self.throw, numbers.Integral)
            or self.throw < 1
        ):
            raise ModelError(f"must be a throw number from 1, got {self.throw!r}", "throw")
        object.__setattr__(self, "throw", int(self.throw))
        check_quantity(self.mass_radius_kgm, "unbalance", "mass_radius_kgm")
        check_angle(self.angle_rad, "angle_rad")
        if self.z_m is not None:
            check_quantity(self.z_m, "length", "z_m", sign="any")
        if self.radius_m is not None:
            check_quantity(self.radius_m, "length", "radius_m")

    @property
    def throw_index(self) -> int:
        """Where its throw stands in ``Engine.throws`` (0-based, for indexing)."""
        return self.throw - 1

    @property
    def mass_kg(self) -> float | None:
        """m·ρ/ρ, kg, when the radius is known."""
        return None if self.radius_m is None else self.mass_radius_kgm / self.radius_m


@dataclass(frozen=True)
class BalancerMass:
    """One mass on a balancer shaft as built.

    Parameters
    ----------
    mass_radius_kgm : float
        its unbalance m·e, kg·m
    angle_rad : float
        its direction from the reference axis when the crank angle θ is 0, measured in the
        shaft's own sense of turning (with the crank for a positive ratio, against it for a
        negative one), rad: the mass is at ``e·exp(i·s·(|ratio|·θ + angle))`` from the shaft's
        axis, s the sign of the ratio
    z_m : float or None
        axial position, m; None (the default) takes z̄, the cylinders' mean
    eccentricity_m : float or None
        its eccentricity e, m, when known (then the mass adds m·e²·ratio² to the reduced mass,
        its kinetic energy at the shaft's speed); None: only m·e is known, which gives every
        force, moment and rolling moment, and its moment of inertia is left out
    """

    mass_radius_kgm: float
    angle_rad: float
    z_m: float | None = None
    eccentricity_m: float | None = None

    def __post_init__(self):
        check_quantity(self.mass_radius_kgm, "unbalance", "mass_radius_kgm")
        check_angle(self.angle_rad, "angle_rad")
        if self.z_m is not None:
            check_quantity(self.z_m, "length", "z_m", sign="any")
        if self.eccentricity_m is not None:
            check_quantity(self.eccentricity_m, "length", "eccentricity_m")

    @property
    def mass_kg(self) -> float | None:
        """m·e/e, kg, when the eccentricity is known."""
        return None if self.eccentricity_m is None else self.mass_radius_kgm / self.eccentricity_m


@dataclass(frozen=True)
class BalancerShaftSpec:
    """A balancer shaft as built, geared to the crankshaft.

    Parameters
    ----------
    ratio : int
        turns per crank turn, a nonzero whole number: positive with the crank, negative
        against it (±1 primary, ±2 secondary shafts)
    masses : tuple of BalancerMass
    lateral_m, vertical_m : float
        its axis from the crank axis, m, along the engine's vertical
        (:attr:`Engine.vertical_axis_rad`) and across it (lateral: 90° on from the vertical,
        with rotation)
    """

    ratio: int
    masses: tuple
    lateral_m: float = 0.0
    vertical_m: float = 0.0

    def __post_init__(self):
        ratio = self.ratio
        if (
            isinstance(ratio, bool)
            or not isinstance(ratio, numbers.Integral)
            or ratio == 0
            or abs(ratio) > MAX_SHAFT_RATIO
        ):
            raise ModelError(
                f"must be a nonzero whole number of turns per crank turn from "
                f"-{MAX_SHAFT_RATIO} to {MAX_SHAFT_RATIO} (+2 with the crank at "
                f"twice its speed, -2 against it), got {ratio!r}",
                "ratio",
            )
        object.__setattr__(self, "ratio", int(ratio))
        if isinstance(self.masses, list):
            object.__setattr__(self, "masses", tuple(self.masses))
        if (
            not isinstance(self.masses, tuple)
            or not self.masses
            or not all(isinstance(m, BalancerMass) for m in self.masses)
        ):
            raise ModelError("needs one or more BalancerMass objects", "masses")
        check_quantity(self.lateral_m, "length", "lateral_m", sign="any")
        check_quantity(self.vertical_m, "length", "vertical_m", sign="any")
