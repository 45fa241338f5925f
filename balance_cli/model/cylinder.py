"""One cylinder with its rod (plain, master, link or opposed) and its reciprocating masses."""

import math
import numbers
from dataclasses import dataclass

from ..checks import is_real
from ..errors import ModelError
from .values import check_quantity

__all__ = ["Cylinder"]


@dataclass(frozen=True)
class Cylinder:
    """One cylinder with its rod.

    A cylinder with ``master`` set has a link rod pinned on the master rod of that
    cylinder, at ``knuckle_radius_m`` from the crank-pin centre and ``knuckle_angle_rad``
    from the master rod's centre line (positive with rotation). Every other cylinder has
    a plain rod of the engine's ``rod_length_m`` (a master rod is a plain rod that carries
    knuckle pins).

    Parameters
    ----------
    number : int
        cylinder number, as used in firing orders
    bank : int
        the number of its bank, from 1, in the order of ``Engine.bank_angles_rad``
    throw : int
        the number of its throw, from 1, in the order of ``Engine.throws``
    z_m : float
        axial position, m
    reciprocating_kg : float
        mass moving with the piston pin, kg
    master : int or None
        number of the cylinder whose master rod carries this link rod
    link_length_m, knuckle_radius_m : float
        link rod length and knuckle-pin radius, m (link rods only)
    knuckle_angle_rad : float
        knuckle-pin angle from the master rod's centre line, rad (link rods only)
    knuckle_kg : float
        mass moving with the knuckle pin, kg (link rods only)
    rod_inertia_kgm2 : float
        the correcting moment of inertia of this cylinder's rod (its link rod, for a link
        cylinder): what the rod's two point masses leave out of its rotational inertia, kg·m²
        (0 when only lumped masses are known; see :class:`Parts`)
    pin_offset_m : float or None
        this cylinder's piston-pin offset (desaxé), m, positive towards the direction of
        rotation of its crankshaft; None takes the engine's ``pin_offset_m``
    opposed_throw : int or None
        an opposed-piston cylinder: the number of the throw, on another crankshaft, whose rod
        drives the second piston of this bore from the other end (plain rod of ``rod_length_m``)
    opposed_reciprocating_kg : float or None
        mass moving with the second piston's pin, kg (opposed-piston cylinders only; None, the
        default, takes ``reciprocating_kg``)
    """

    number: int
    bank: int
    throw: int
    z_m: float
    reciprocating_kg: float
    master: int | None = None
    link_length_m: float = 0.0
    knuckle_radius_m: float = 0.0
    knuckle_angle_rad: float = 0.0
    knuckle_kg: float = 0.0
    rod_inertia_kgm2: float = 0.0
    pin_offset_m: float | None = None
    opposed_throw: int | None = None
    opposed_reciprocating_kg: float | None = None

    def __post_init__(self):
        # the types here, the ranges and references in the Engine that holds the cylinder
        n = self.number
        if not isinstance(n, numbers.Integral) or isinstance(n, bool) or n < 1:
            raise ModelError(f"must be a whole number from 1, got {n!r}", "number")
        object.__setattr__(self, "number", int(n))  # numpy's whole numbers as Python's
        for name in ("bank", "throw"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 1:
                raise ModelError(
                    f"cylinder {n}: {name} is a number from 1, got {value!r}", cylinder=n
                )
            object.__setattr__(self, name, int(value))
        for name in (
            "z_m",
            "reciprocating_kg",
            "link_length_m",
            "knuckle_radius_m",
            "knuckle_angle_rad",
            "knuckle_kg",
            "rod_inertia_kgm2",
            "opposed_reciprocating_kg",
        ):
            value = getattr(self, name)
            if value is None and name == "opposed_reciprocating_kg":
                continue
            if not is_real(value) or not math.isfinite(value):
                raise ModelError(
                    f"cylinder {n}: {name} must be a finite number, got {value!r}", cylinder=n
                )
        check_quantity(self.reciprocating_kg, "mass", "reciprocating_kg", cylinder=n)
        check_quantity(self.knuckle_kg, "mass", "knuckle_kg", sign="non-negative", cylinder=n)
        if self.pin_offset_m is not None:
            check_quantity(self.pin_offset_m, "length", "pin_offset_m", sign="any", cylinder=n)
        if self.opposed_throw is not None:
            far = self.opposed_throw
            if isinstance(far, bool) or not isinstance(far, numbers.Integral) or far < 1:
                raise ModelError(
                    f"cylinder {n}: opposed_throw is a throw number from 1, got {far!r}", cylinder=n
                )
            object.__setattr__(self, "opposed_throw", int(far))
            if self.master is not None:
                raise ModelError(
                    f"cylinder {n}: an opposed-piston cylinder has plain rods; it "
                    "cannot be a link-rod cylinder too",
                    cylinder=n,
                )
            if self.opposed_reciprocating_kg is None:
                # the same piston at both ends unless told otherwise, as a file reads it
                object.__setattr__(self, "opposed_reciprocating_kg", self.reciprocating_kg)
            check_quantity(
                self.opposed_reciprocating_kg, "mass", "opposed_reciprocating_kg", cylinder=n
            )
        elif self.opposed_reciprocating_kg is not None:
            raise ModelError(
                f"cylinder {n}: opposed_reciprocating_kg belongs to an opposed-piston "
                "cylinder; give its opposed_throw too, or leave the mass out",
                cylinder=n,
            )

    @property
    def is_link(self) -> bool:
        return self.master is not None

    @property
    def is_opposed(self) -> bool:
        """Two pistons in one bore, driven from its two ends by two crankshafts."""
        return self.opposed_throw is not None

    # where its bank and throws stand in the engine's tuples: 0-based, for indexing them

    @property
    def bank_index(self) -> int:
        """Where its bank stands in ``Engine.bank_angles_rad`` (0-based, for indexing)."""
        return self.bank - 1

    @property
    def throw_index(self) -> int:
        """Where its throw stands in ``Engine.throws`` (0-based, for indexing)."""
        return self.throw - 1

    @property
    def opposed_throw_index(self) -> int | None:
        """Where its opposed throw stands in ``Engine.throws`` (0-based), None if it has none."""
        return None if self.opposed_throw is None else self.opposed_throw - 1
