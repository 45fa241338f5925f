"""The engine model: immutable, SI units and radians throughout.

This is the ground floor of the package: it imports nothing from the rest of it.
"""

from dataclasses import dataclass, field

__all__ = ["Throw", "Cylinder", "Engine", "ModelError"]


class ModelError(ValueError):
    """An engine that cannot exist: a linkage that cannot be assembled, a bad reference."""


@dataclass(frozen=True)
class Throw:
    """One crank throw.

    Parameters
    ----------
    phase_rad : float
        angle of the throw relative to throw 1, positive with rotation, rad
    z_m : float
        axial position, m
    """

    phase_rad: float
    z_m: float = 0.0


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
        0-based index into ``Engine.bank_angles_rad``
    throw : int
        0-based index into ``Engine.throws``
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

    @property
    def is_link(self):
        return self.master is not None


@dataclass(frozen=True)
class Engine:
    """A reciprocating engine, as the analyses see it.

    Parameters
    ----------
    name : str
        display name
    cycle : int
        2 or 4 (strokes per cycle)
    speed_rad_s : float
        crank speed (crankcase speed for a rotary), rad/s
    crank_radius_m, rod_length_m, pin_offset_m : float
        crank radius, plain/master rod length (centre to centre) and piston-pin offset
        from the cylinder axis (positive towards the direction of rotation), m
    bank_angles_rad : tuple of float
        cylinder-axis directions from the reference axis, positive with rotation, rad
    throws : tuple of Throw
    cylinders : tuple of Cylinder
    rotating_kg : float
        mass at the crank pin of every throw that is not the crankshaft's (big ends), kg
    crank_kg : float
        the crankshaft's own unbalance of every throw, as a mass at the crank pin, kg
        (moves like ``rotating_kg``, but stays on the shaft on a balancing machine)
    frame : str
        "fixed" (the crank turns) or "rotary" (the crankcase turns about a fixed crank)
    firing_order : tuple of int or None
        cylinder numbers in firing order, if the configuration gives one
    source, config_path : str
        where the data came from, and the file it was read from
    """

    name: str
    cycle: int
    speed_rad_s: float
    crank_radius_m: float
    rod_length_m: float
    bank_angles_rad: tuple
    throws: tuple
    cylinders: tuple
    rotating_kg: float = 0.0
    crank_kg: float = 0.0
    pin_offset_m: float = 0.0
    frame: str = "fixed"
    firing_order: tuple | None = None
    source: str = ""
    config_path: str = ""
    _by_number: dict = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        object.__setattr__(self, "_by_number", {c.number: c for c in self.cylinders})

    def cylinder(self, number):
        """The cylinder with this number."""
        return self._by_number[number]

    def is_master(self, cylinder):
        return any(c.master == cylinder.number for c in self.cylinders)

    def rod_type(self, cylinder):
        """"plain", "master" or "link"."""
        if cylinder.is_link:
            return "link"
        return "master" if self.is_master(cylinder) else "plain"

    @property
    def n_cylinders(self):
        return len(self.cylinders)

    @property
    def mean_reciprocating_kg(self):
        return sum(c.reciprocating_kg for c in self.cylinders) / len(self.cylinders)

    @property
    def unit_force_n(self):
        """m_rec·r·ω² with the mean reciprocating mass per cylinder, N."""
        return self.mean_reciprocating_kg * self.crank_radius_m * self.speed_rad_s**2
