"""The engine model: immutable, SI units and radians throughout, checked when built.

This is the ground floor of the analyses: it imports only the errors, tolerances and units.
An :class:`Engine` built in code is checked exactly as one read from a configuration file
(the reader puts its key names into the messages); whether its linkage can be assembled over
a revolution is checked by :func:`balance_cli.kinematics.linkage.check_assembly`, which every analysis
calls first.
"""

import dataclasses
import math
import numbers
from dataclasses import dataclass, field, fields

from ..checks import is_real
from ..errors import ModelError, UnitError
from ..tolerances import NOISE_FLOOR, SAME_DIRECTION_RAD, SAME_POSITION_M
from ..units import check_finite_range

__all__ = ["Crankshaft", "Throw", "Cylinder", "Engine", "Parts", "GasCycle", "FRAMES",
           "CounterweightMass", "BalancerMass", "BalancerShaftSpec", "MAX_SHAFT_RATIO",
           "offset_position",
           "ShaftDisk", "TorsionModel"]

#: "fixed": the crank turns in a fixed crankcase; "rotary": the crankcase and its cylinders
#: turn about a fixed crank
FRAMES = ("fixed", "rotary")
#: banks whose unit vectors add up to less than this fraction of their number have no
#: bisector worth calling vertical (within about 6° of a boxer's 180°)
BISECTOR_FLOOR = 0.05
#: how far off the bore's axis (a fraction of the crankshafts' distance) an opposed piston's
#: crankshaft may lie
OPPOSED_AXIS_TOLERANCE = 1e-6
#: a name is shown in table cells and picture titles
MAX_NAME_LENGTH = 120
#: the fastest balancer shaft, turns per crank turn: real ones run at 1 or 2 (a few at 4);
#: much faster ones would need more samples a revolution than any analysis takes by default
MAX_SHAFT_RATIO = 16


@dataclass(frozen=True)
class Crankshaft:
    """One crankshaft of an engine with several (an H engine, an opposed-piston engine, the
    Napier Deltic), geared 1:1 to the first.

    Every crankshaft makes one turn per turn of the first (the engine angle θ): the pistons it
    drives share cylinders and a firing cycle with the others', which repeat only then.

    Parameters
    ----------
    x_m, y_m : float
        position of its axis in the transverse plane, m: along the reference axis (bank angle
        0) and across it (bank angle 90°), from the first crankshaft's axis
    direction : int
        +1 turning with the first crankshaft, −1 against it
    phase_rad : float
        its angle when the first is at 0, measured in its own sense of turning, rad: a throw of
        phase φ on it points at direction·(θ + phase_rad + φ) from the reference axis
    """

    x_m: float = 0.0
    y_m: float = 0.0
    direction: int = 1
    phase_rad: float = 0.0

    def __post_init__(self):
        _quantity(self.x_m, "length", "x_m", sign="any")
        _quantity(self.y_m, "length", "y_m", sign="any")
        if isinstance(self.direction, bool) or not isinstance(self.direction, numbers.Integral) \
                or self.direction not in (1, -1):
            raise ModelError(f"must be +1 (with the first crankshaft) or -1 (against it), got "
                             f"{self.direction!r}", "direction")
        object.__setattr__(self, "direction", int(self.direction))
        _angle(self.phase_rad, "phase_rad")

    @property
    def centre(self) -> complex:
        """The axis position as a complex number, m (real along the reference axis)."""
        return complex(self.x_m, self.y_m)


@dataclass(frozen=True)
class Throw:
    """One crank throw.

    Parameters
    ----------
    phase_rad : float
        angle of the throw relative to throw 1, positive with rotation (of its own
        crankshaft), rad
    z_m : float
        axial position, m
    crankshaft : int
        0-based index into ``Engine.crankshafts`` (0, the first, for an engine with one)
    """

    phase_rad: float
    z_m: float = 0.0
    crankshaft: int = 0

    def __post_init__(self):
        # checked here too, not only in the Engine: a Throw of NaN once built without a word
        _angle(self.phase_rad, "phase_rad")
        _quantity(self.z_m, "length", "z_m", sign="any")
        if isinstance(self.crankshaft, bool) or not isinstance(self.crankshaft, numbers.Integral) \
                or self.crankshaft < 0:
            raise ModelError(f"must be a 0-based crankshaft index, got {self.crankshaft!r}",
                             "crankshaft")
        object.__setattr__(self, "crankshaft", int(self.crankshaft))


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
    rod_inertia_kgm2 : float
        the correcting moment of inertia of this cylinder's rod (its link rod, for a link
        cylinder): what the rod's two point masses leave out of its rotational inertia, kg·m²
        (0 when only lumped masses are known; see :class:`Parts`)
    pin_offset_m : float or None
        this cylinder's piston-pin offset (desaxé), m, positive towards the direction of
        rotation of its crankshaft; None takes the engine's ``pin_offset_m``
    opposed_throw : int or None
        an opposed-piston cylinder: the 0-based throw, on another crankshaft, whose rod drives
        the second piston of this bore from the other end (plain rod of ``rod_length_m``)
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
        object.__setattr__(self, "number", int(n))   # numpy's whole numbers as Python's
        for name in ("z_m", "reciprocating_kg", "link_length_m", "knuckle_radius_m",
                     "knuckle_angle_rad", "knuckle_kg", "rod_inertia_kgm2",
                     "opposed_reciprocating_kg"):
            value = getattr(self, name)
            if value is None and name == "opposed_reciprocating_kg":
                continue
            if not is_real(value) or not math.isfinite(value):
                raise ModelError(f"cylinder {n}: {name} must be a finite number, got {value!r}",
                                 cylinder=n)
        _quantity(self.reciprocating_kg, "mass", "reciprocating_kg", cylinder=n)
        _quantity(self.knuckle_kg, "mass", "knuckle_kg", sign="non-negative", cylinder=n)
        if self.pin_offset_m is not None:
            _quantity(self.pin_offset_m, "length", "pin_offset_m", sign="any", cylinder=n)
        if self.opposed_throw is not None:
            index = self.opposed_throw
            if isinstance(index, bool) or not isinstance(index, numbers.Integral) or index < 0:
                raise ModelError(f"cylinder {n}: opposed_throw is a 0-based throw index, got "
                                 f"{index!r}", cylinder=n)
            object.__setattr__(self, "opposed_throw", int(index))
            if self.master is not None:
                raise ModelError(f"cylinder {n}: an opposed-piston cylinder has plain rods; it "
                                 "cannot be a link-rod cylinder too", cylinder=n)
            if self.opposed_reciprocating_kg is None:
                # the same piston at both ends unless told otherwise, as a file reads it
                object.__setattr__(self, "opposed_reciprocating_kg", self.reciprocating_kg)
            _quantity(self.opposed_reciprocating_kg, "mass", "opposed_reciprocating_kg",
                      cylinder=n)
        elif self.opposed_reciprocating_kg is not None:
            raise ModelError(f"cylinder {n}: opposed_reciprocating_kg belongs to an opposed-piston "
                             "cylinder; give its opposed_throw too, or leave the mass out",
                             cylinder=n)

    @property
    def is_link(self) -> bool:
        return self.master is not None

    @property
    def is_opposed(self) -> bool:
        """Two pistons in one bore, driven from its two ends by two crankshafts."""
        return self.opposed_throw is not None


@dataclass(frozen=True)
class CounterweightMass:
    """A counterweight as built: a mass on the crankshaft, turning with one throw.

    Parameters
    ----------
    throw : int
        0-based index into ``Engine.throws`` of the throw whose pin it is measured from
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
        if isinstance(self.throw, bool) or not isinstance(self.throw, numbers.Integral) \
                or self.throw < 0:
            raise ModelError(f"must be a 0-based throw index, got {self.throw!r}", "throw")
        object.__setattr__(self, "throw", int(self.throw))
        _quantity(self.mass_radius_kgm, "unbalance", "mass_radius_kgm")
        _angle(self.angle_rad, "angle_rad")
        if self.z_m is not None:
            _quantity(self.z_m, "length", "z_m", sign="any")
        if self.radius_m is not None:
            _quantity(self.radius_m, "length", "radius_m")

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
        negative one), rad: the mass is at e·exp(i·s·(|ratio|·θ + angle)) from the shaft's
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
        _quantity(self.mass_radius_kgm, "unbalance", "mass_radius_kgm")
        _angle(self.angle_rad, "angle_rad")
        if self.z_m is not None:
            _quantity(self.z_m, "length", "z_m", sign="any")
        if self.eccentricity_m is not None:
            _quantity(self.eccentricity_m, "length", "eccentricity_m")

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
        if isinstance(ratio, bool) or not isinstance(ratio, numbers.Integral) or ratio == 0 \
                or abs(ratio) > MAX_SHAFT_RATIO:
            raise ModelError(f"must be a nonzero whole number of turns per crank turn from "
                             f"-{MAX_SHAFT_RATIO} to {MAX_SHAFT_RATIO} (+2 with the crank at "
                             f"twice its speed, -2 against it), got {ratio!r}", "ratio")
        object.__setattr__(self, "ratio", int(ratio))
        if isinstance(self.masses, list):
            object.__setattr__(self, "masses", tuple(self.masses))
        if not isinstance(self.masses, tuple) or not self.masses \
                or not all(isinstance(m, BalancerMass) for m in self.masses):
            raise ModelError("needs one or more BalancerMass objects", "masses")
        _quantity(self.lateral_m, "length", "lateral_m", sign="any")
        _quantity(self.vertical_m, "length", "vertical_m", sign="any")


@dataclass(frozen=True)
class Parts:
    """Part-level data, from which the lumped point masses and the rods' rotational inertia
    are derived by the two-point rod model (Fraeys de Veubeke 1949, ch. I §§ 6 and 8).

    Parameters
    ----------
    piston_kg : float
        piston with rings and pin, per cylinder, kg
    rod_kg, rod_cg_m, rod_inertia_kgm2 : float
        plain or master rod: mass, kg; centre of gravity from the big end, m; moment of
        inertia about its centre of gravity, kg·m²
    link_kg, link_cg_m, link_inertia_kgm2 : float
        the same for a link rod, the centre of gravity from its knuckle pin (0 without links)
    crank_kg : float
        crank-equivalent rotating mass per throw (the crankshaft's own unbalance at the pin), kg
    crankshaft_inertia_kgm2, flywheel_inertia_kgm2 : float
        moments of inertia about the crank axis (for a rotary: of the turning crankcase), kg·m²
    """

    piston_kg: float
    rod_kg: float
    rod_cg_m: float
    rod_inertia_kgm2: float
    link_kg: float = 0.0
    link_cg_m: float = 0.0
    link_inertia_kgm2: float = 0.0
    crank_kg: float = 0.0
    crankshaft_inertia_kgm2: float = 0.0
    flywheel_inertia_kgm2: float = 0.0

    def small_end_share(self, rod_length_m):
        """K = H/L: the fraction of the rod's mass at its small end (the rest at the big end)."""
        return self.rod_cg_m / rod_length_m

    def rod_correction_kgm2(self, rod_length_m):
        """C = J − M·H·(L − H): the moment of inertia the rod's two point masses leave out
        (Fraeys's (12); always negative for a real rod, small beside J)."""
        return self.rod_inertia_kgm2 - self.rod_kg * self.rod_cg_m * (rod_length_m - self.rod_cg_m)

    def link_correction_kgm2(self, link_length_m):
        """c = j − m·h·(l − h) of a link rod of length ``link_length_m``."""
        return (self.link_inertia_kgm2
                - self.link_kg * self.link_cg_m * (link_length_m - self.link_cg_m))


@dataclass(frozen=True)
class GasCycle:
    """A single-zone gas cycle: polytropic compression and expansion with a Wiebe heat release
    scaled to the indicated mean effective pressure (see :mod:`balance_cli.analysis.gas`).

    Parameters
    ----------
    bore_m : float
        cylinder bore, m
    compression_ratio : float
        geometric compression ratio (> 1)
    imep_pa : float or None
        indicated mean effective pressure the heat release is scaled to, Pa (None: no
        combustion, a motored cycle)
    intake_pa, crankcase_pa : float
        pressure at the start of compression, and on the underside of the piston, Pa
    polytropic_exponent : float
        of compression and expansion
    combustion_start_deg, combustion_duration_deg : float
        start of heat release from the firing top dead centre (negative: before it), and its
        length, crank degrees
    wiebe_a, wiebe_m : float
        Wiebe's efficiency and form parameters
    """

    bore_m: float
    compression_ratio: float
    imep_pa: float | None = None
    intake_pa: float = 1.0e5
    crankcase_pa: float = 101325.0
    polytropic_exponent: float = 1.32
    combustion_start_deg: float = -10.0
    combustion_duration_deg: float = 50.0
    wiebe_a: float = 5.0
    wiebe_m: float = 2.0

    @property
    def piston_area_m2(self) -> float:
        return math.pi * self.bore_m**2 / 4


@dataclass(frozen=True)
class ShaftDisk:
    """An inertia on the shaft line outside the throws (a pulley, a damper, the flywheel, the
    driven load) and the section joining it to its neighbour towards the throws.

    Parameters
    ----------
    name : str
    inertia_kgm2 : float
        kg·m²
    stiffness_nm_rad : float
        of the joining section, N·m/rad
    damping_nms_rad : float
        viscous damping of the joining section (a damper's), N·m·s/rad
    """

    name: str
    inertia_kgm2: float
    stiffness_nm_rad: float
    damping_nms_rad: float = 0.0


@dataclass(frozen=True)
class TorsionModel:
    """The crankshaft's mass-elastic model, free end first (see :mod:`balance_cli.torsion`).

    Parameters
    ----------
    throw_inertia_kgm2 : tuple of float or None
        each throw's inertia, kg·m²; None: the mean reduced mass of the parts on the throw
        plus ``web_inertia_kgm2``
    web_inertia_kgm2 : float
        each throw's crank webs and pin, kg·m² (added to the reduced mass when
        ``throw_inertia_kgm2`` is None; 0 otherwise)
    stiffness_nm_rad : tuple of float
        the sections between consecutive throws, N·m/rad (one fewer than the throws)
    throw_damping_nms_rad : tuple of float
        absolute (viscous) damping at each throw, N·m·s/rad
    loss_factor : float
        relative damping of every section: c = loss_factor·k/Ω at frequency Ω
    front : tuple of ShaftDisk
        inertias ahead of throw 1, the free end first
    flywheel, load : ShaftDisk or None
        behind the last throw, in that order
    shaft_diameter_m, shaft_bore_m : float or None
        the crankshaft's journal diameter and bore for the shear stress τ = T·r/J_p, m
    """

    throw_inertia_kgm2: tuple | None
    web_inertia_kgm2: float
    stiffness_nm_rad: tuple
    throw_damping_nms_rad: tuple
    loss_factor: float = 0.0
    front: tuple = ()
    flywheel: ShaftDisk | None = None
    load: ShaftDisk | None = None
    shaft_diameter_m: float | None = None
    shaft_bore_m: float = 0.0


@dataclass(frozen=True)
class Engine:
    """A reciprocating engine, as the analyses see it.

    Parameters
    ----------
    name : str
        display name, one line
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
    shaft_inertia_kgm2 : float
        crankshaft and flywheel (a rotary's crankcase) about the crank axis, kg·m²
    parts : Parts or None
        the part data the masses and inertias were derived from, if given
    gas : GasCycle or None
        the gas cycle, if given
    vertical_rad : float or None
        the engine's vertical, from the reference axis, positive with rotation, rad; None
        (the default) takes the banks' bisector (see :attr:`vertical_axis_rad`)
    power_w : float or None
        the engine's power, W, at ``power_speed_rad_s`` (default: at ``speed_rad_s``)
    power_speed_rad_s : float or None
        the speed ``power_w`` is given at, rad/s; an engine analysed at another speed (after
        :meth:`replace`) has no power until it is given at that speed
    crankshafts : tuple of Crankshaft
        the crankshafts, the first the reference (at the origin, turning forward, phase 0);
        empty (the default) for the one crankshaft of most engines
    counterweights : tuple of CounterweightMass
        counterweights as built, turning with their throws (empty: none; refused on a rotary)
    balancer_shafts : tuple of BalancerShaftSpec
        balancer shafts as built (empty: none; refused on a rotary)
    torsion : TorsionModel or None
        the crankshaft's mass-elastic model for ``balance torsion``, if given

    Raises
    ------
    ModelError
        naming the field (``parameter``) or the cylinder (``cylinder``) that is wrong
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
    shaft_inertia_kgm2: float = 0.0
    parts: Parts | None = None
    gas: GasCycle | None = None
    vertical_rad: float | None = None
    power_w: float | None = None
    power_speed_rad_s: float | None = None
    crankshafts: tuple = ()
    counterweights: tuple = ()
    balancer_shafts: tuple = ()
    torsion: "TorsionModel | None" = None
    _by_number: dict = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        # sequences given as lists become tuples: the engine stays immutable and hashable
        for name in ("bank_angles_rad", "throws", "cylinders", "firing_order", "crankshafts",
                     "counterweights", "balancer_shafts"):
            value = getattr(self, name)
            if isinstance(value, list):
                object.__setattr__(self, name, tuple(value))
            elif not isinstance(value, tuple) and (name != "firing_order" or value is not None):
                # a number here failed later with "not iterable"
                raise ModelError(f"must be a list or tuple, got {value!r}", name)
        object.__setattr__(self, "_by_number", {c.number: c for c in self.cylinders
                                                if isinstance(c, Cylinder)})
        if not self.crankshafts:
            # one way to say "one crankshaft": the reference, whether named or not
            object.__setattr__(self, "crankshafts", (REFERENCE_CRANKSHAFT,))
        if self.power_w is not None and self.power_speed_rad_s is None:
            object.__setattr__(self, "power_speed_rad_s", self.speed_rad_s)
        _check(self)

    def replace(self, **changes) -> "Engine":
        """A copy with ``changes`` (field names and SI values, as the constructor takes them),
        checked like any new engine, the linkage's assembly included::

            faster = engine.replace(speed_rad_s=2 * engine.speed_rad_s)

        Raises
        ------
        ModelError
            a name that is not a field, or a value the engine cannot have
        """
        names = [f.name for f in fields(self) if f.init]
        unknown = sorted(set(changes) - set(names))
        if unknown:
            raise ModelError(f"Engine.replace: {', '.join(map(repr, unknown))} is not a field of "
                             f"Engine; choose from {', '.join(names)}")
        engine = dataclasses.replace(self, **changes)
        # the model is the package's ground floor; the assembly check lives above it, and a
        # replaced engine must be checked as fully as one read from a file
        from ..kinematics.linkage import check_assembly

        check_assembly(engine)
        return engine

    def cylinder(self, number):
        """The cylinder with this number."""
        return self._by_number[number]

    def is_master(self, cylinder):
        return any(c.master == cylinder.number for c in self.cylinders)

    def rod_type(self, cylinder):
        """"plain", "master", "link" or "opposed" (two plain rods, one from each end)."""
        if cylinder.is_link:
            return "link"
        if cylinder.is_opposed:
            return "opposed"
        return "master" if self.is_master(cylinder) else "plain"

    def pin_offset_of(self, cylinder) -> float:
        """The piston-pin offset of ``cylinder``: its own, else the engine's, m."""
        return self.pin_offset_m if cylinder.pin_offset_m is None else cylinder.pin_offset_m

    def counterweight_z_m(self, counterweight) -> float:
        """Where ``counterweight`` sits, m: its own ``z_m``, else its throw's."""
        if counterweight.z_m is not None:
            return counterweight.z_m
        return self.throws[counterweight.throw].z_m

    def balancer_z_m(self, mass) -> float:
        """Where balancer ``mass`` sits, m: its own ``z_m``, else z̄ (the cylinders' mean)."""
        return self.mean_z_m if mass.z_m is None else mass.z_m

    def balancer_centre(self, shaft) -> complex:
        """The axis of balancer ``shaft`` in the transverse plane, m (real along the reference
        axis): its vertical offset along :attr:`vertical_axis_rad`, its lateral one 90° on."""
        return offset_position(shaft.lateral_m, shaft.vertical_m, self.vertical_axis_rad)

    def crankshaft_of(self, throw_index) -> "Crankshaft":
        """The crankshaft that carries throw ``throw_index`` (0-based)."""
        return self.crankshafts[self.throws[throw_index].crankshaft]

    @property
    def has_several_crankshafts(self) -> bool:
        return len(self.crankshafts) > 1

    @property
    def has_opposed_pistons(self) -> bool:
        return any(c.is_opposed for c in self.cylinders)

    @property
    def vertical_axis_rad(self) -> float:
        """The direction called vertical, rad from the reference axis: ``vertical_rad`` when
        given; else the bisector of the banks (the cylinder axis of an in-line engine, the
        middle of a V or W); banks whose directions add up to (almost) nothing — less than
        :data:`BISECTOR_FLOOR` of their number, a radial, a boxer — leave the reference axis
        itself."""
        if self.vertical_rad is not None:
            return self.vertical_rad
        total = self._banks_sum()
        if self._banks_cancel(total):
            return 0.0
        return math.atan2(total.imag, total.real)

    @property
    def vertical_origin(self) -> str:
        """Where :attr:`vertical_axis_rad` comes from, in words."""
        if self.vertical_rad is not None:
            return "given"
        if self._banks_cancel(self._banks_sum()):
            return "the reference axis: the banks' directions add up to (almost) nothing"
        return "the banks' bisector" if len(self.bank_angles_rad) > 1 else "the cylinder axis"

    def _banks_sum(self):
        return sum(complex(math.cos(a), math.sin(a)) for a in self.bank_angles_rad)

    def _banks_cancel(self, total):
        # banks that almost cancel (a boxer at 0° and 179°, a Y a hair off 120°) have a
        # bisector that swings with the last decimal: the reference axis is steadier
        return abs(total) < BISECTOR_FLOOR * len(self.bank_angles_rad)

    @property
    def power_at_speed_w(self) -> float | None:
        """``power_w`` when it is given at the speed the engine runs at, else None, W."""
        if self.power_w is None or self.power_speed_rad_s is None or \
                not math.isclose(self.power_speed_rad_s, self.speed_rad_s, rel_tol=1e-12):
            return None
        return self.power_w

    @property
    def n_cylinders(self) -> int:
        return len(self.cylinders)

    @property
    def is_rotary(self) -> bool:
        """The crankcase turns about a fixed crank (a rotary engine)."""
        return self.frame == "rotary"

    @property
    def cycle_deg(self) -> float:
        """Crank degrees of one working cycle: 360 (two-stroke) or 720 (four-stroke)."""
        return 180.0 * self.cycle

    @property
    def mean_reciprocating_kg(self) -> float:
        return sum(c.reciprocating_kg for c in self.cylinders) / len(self.cylinders)

    @property
    def mean_z_m(self) -> float:
        """z̄, the axial position free moments are taken about: the cylinders' mean, m."""
        return sum(c.z_m for c in self.cylinders) / len(self.cylinders)

    @property
    def unit_force_n(self) -> float:
        """m_rec·r·ω² with the mean reciprocating mass per cylinder, N."""
        return self.mean_reciprocating_kg * self.crank_radius_m * self.speed_rad_s**2

    @property
    def per_cylinder_unit_n(self) -> float:
        """m_rec·r·ω²·n, N: divide a force by it to get Tanaka's per-cylinder figure."""
        return self.unit_force_n * self.n_cylinders

    @property
    def noise_floor_n(self) -> float:
        """Forces below this (N) are rounding noise: :data:`~balance_cli.tolerances.NOISE_FLOOR`
        of m_rec·r·ω²·n."""
        return NOISE_FLOOR * self.per_cylinder_unit_n

    @property
    def length_scale_m(self) -> float:
        """The lever arm of the engine's moments, m: the farthest cylinder from z̄, or the
        crank radius when the cylinders are closer together than that."""
        mean = self.mean_z_m
        return max(self.crank_radius_m, max(abs(c.z_m - mean) for c in self.cylinders))

    @property
    def noise_floor_nm(self) -> float:
        """Moments below this (N·m) are rounding noise: the force floor times the engine's
        own lever arm (:attr:`length_scale_m`), not one metre, so that a small engine's real
        couples are not taken for noise."""
        return self.noise_floor_n * self.length_scale_m


def offset_position(lateral_m, vertical_m, vertical_rad):
    """A point of the transverse plane as a complex number (real part along the reference
    axis), from its lateral and vertical distances to the crank axis, the vertical lying at
    ``vertical_rad`` from the reference axis and the lateral 90° on from it with rotation."""
    return complex(vertical_m, lateral_m) * complex(math.cos(vertical_rad), math.sin(vertical_rad))


def _quantity(value, dimension, parameter, sign="positive", cylinder=None):
    """A finite SI value within the accepted range; ``sign`` "positive", "non-negative" or "any"."""
    prefix = f"cylinder {cylinder}: {parameter} " if cylinder is not None else ""
    name = None if prefix else parameter
    if not is_real(value):
        raise ModelError(f"{prefix}must be a number, got {value!r}", name, cylinder)
    try:
        # a value that may be zero may also be tiny (rounding noise of a computed position)
        check_finite_range(float(value), dimension, smallest=sign == "positive")
    except UnitError as exc:
        raise ModelError(f"{prefix}is invalid: {exc}", name, cylinder) from None
    if sign == "positive" and value <= 0 or sign == "non-negative" and value < 0:
        need = "greater than zero" if sign == "positive" else "zero or more"
        raise ModelError(f"{prefix}must be {need}, got {value!r}", name, cylinder)


def _angle(value, parameter, cylinder=None):
    if not is_real(value) or not math.isfinite(value) or abs(value) > 2 * math.pi:
        where = f"cylinder {cylinder}: {parameter} " if cylinder is not None else ""
        raise ModelError(f"{where}must be a finite angle between -2π and 2π rad, got {value!r}",
                         None if where else parameter, cylinder)


def _check(engine):
    """Every rule an engine must satisfy, whether built in code or read from a file."""
    if not isinstance(engine.name, str) or not engine.name.strip() or not engine.name.isprintable() \
            or len(engine.name) > MAX_NAME_LENGTH:
        raise ModelError(f"must be a non-empty line of printable text of at most {MAX_NAME_LENGTH} "
                         f"characters, got {engine.name[:80]!r}" if isinstance(engine.name, str)
                         else f"must be text, got {engine.name!r}", "name")
    if isinstance(engine.cycle, bool) or not isinstance(engine.cycle, int) or engine.cycle not in (2, 4):
        raise ModelError(f"must be 2 or 4 (strokes per cycle), got {engine.cycle!r}", "cycle")
    if engine.frame not in FRAMES:
        raise ModelError(f'must be "fixed" or "rotary", got {engine.frame!r}', "frame")
    _quantity(engine.speed_rad_s, "angular speed", "speed_rad_s")
    _quantity(engine.crank_radius_m, "length", "crank_radius_m")
    _quantity(engine.rod_length_m, "length", "rod_length_m")
    _quantity(engine.pin_offset_m, "length", "pin_offset_m", sign="any")
    _quantity(engine.rotating_kg, "mass", "rotating_kg", sign="non-negative")
    _quantity(engine.crank_kg, "mass", "crank_kg", sign="non-negative")
    _quantity(engine.shaft_inertia_kgm2, "moment of inertia", "shaft_inertia_kgm2",
              sign="non-negative")
    if engine.vertical_rad is not None:
        _angle(engine.vertical_rad, "vertical_rad")
    if engine.power_w is not None:
        _quantity(engine.power_w, "power", "power_w")
        _quantity(engine.power_speed_rad_s, "angular speed", "power_speed_rad_s")
    if engine.rod_length_m <= engine.crank_radius_m + abs(engine.pin_offset_m):
        raise ModelError(
            f"of {engine.rod_length_m:g} m is not longer than the crank radius plus |pin offset| "
            f"({engine.crank_radius_m:g} m + {abs(engine.pin_offset_m):g} m), so the rod cannot "
            "reach the cylinder axis; make it longer or the crank shorter", "rod_length_m")
    _check_crankshafts(engine)
    if not engine.bank_angles_rad:
        raise ModelError("needs at least one cylinder-axis direction", "bank_angles_rad")
    directions = []
    for i, angle in enumerate(engine.bank_angles_rad):
        _angle(angle, "bank_angles_rad")
        # two banks pointing the same way put two cylinders in every bore of a throw
        direction = math.remainder(angle, 2 * math.pi)
        for j, other in enumerate(directions):
            if abs(math.remainder(direction - other, 2 * math.pi)) < SAME_DIRECTION_RAD:
                raise ModelError(f"{j + 1} and {i + 1} point the same way ({math.degrees(other):g}° "
                                 f"and {math.degrees(angle):g}°); give each bank its own direction",
                                 "bank_angles_rad")
        directions.append(direction)
    if not engine.throws or not all(isinstance(t, Throw) for t in engine.throws):
        raise ModelError("needs one or more Throw objects", "throws")
    for i, throw in enumerate(engine.throws, 1):
        _angle(throw.phase_rad, "throws")
        _quantity(throw.z_m, "length", "throws", sign="any")
        if not throw.crankshaft < len(engine.crankshafts):
            raise ModelError(f"[{i - 1}] names crankshaft index {throw.crankshaft}, but the engine "
                             f"has crankshafts 0 to {len(engine.crankshafts) - 1}; add the "
                             "crankshaft or name another", "throws")
    idle = sorted(set(range(len(engine.crankshafts))) - {t.crankshaft for t in engine.throws})
    if idle:
        raise ModelError(f"[{idle[0]}] carries no throw; give it throws or remove it",
                         "crankshafts")
    if not engine.cylinders or not all(isinstance(c, Cylinder) for c in engine.cylinders):
        raise ModelError("needs one or more Cylinder objects", "cylinders")
    numbers = [c.number for c in engine.cylinders]
    if len(set(numbers)) != len(numbers):
        twice = next(n for n in numbers if numbers.count(n) > 1)
        raise ModelError(f"cylinder {twice} is listed twice; give each a unique number",
                         cylinder=twice)
    bores = {}
    for c in engine.cylinders:
        _check_cylinder(engine, c)
        bore = (c.bank, c.throw, round(c.z_m / SAME_POSITION_M))
        if bore in bores:
            raise ModelError(
                f"cylinder {c.number} sits in the bore of cylinder {bores[bore]} (bank {c.bank + 1}, "
                f"throw {c.throw + 1}, same z); give it another bank, throw or axial position",
                cylinder=c.number)
        bores[bore] = c.number
    for c in engine.cylinders:
        # an opposed bore seen from its far end: a cylinder of a bank pointing back along it,
        # on the opposed throw, would be a third piston in it
        if not c.is_opposed:
            continue
        back = engine.bank_angles_rad[c.bank] + math.pi
        for j, angle in enumerate(engine.bank_angles_rad):
            if abs(math.remainder(angle - back, 2 * math.pi)) < SAME_DIRECTION_RAD:
                other = bores.get((j, c.opposed_throw, round(c.z_m / SAME_POSITION_M)))
                if other is not None:
                    raise ModelError(
                        f"cylinder {other} sits in the bore of cylinder {c.number}, whose opposed "
                        "piston comes from that end; give it another bank, throw or axial "
                        "position", cylinder=other)
    _check_balancers(engine)
    if engine.torsion is not None and (engine.is_rotary or engine.has_several_crankshafts):
        raise ModelError("is a shaft line of one turning crankshaft; this engine "
                         + ("is a rotary (its crank stands still)" if engine.is_rotary else
                            f"has {len(engine.crankshafts)} crankshafts")
                         + ": remove the [torsion] table", "torsion")
    if engine.firing_order is not None:
        order = list(engine.firing_order)
        if not all(isinstance(n, int) and not isinstance(n, bool) for n in order) \
                or sorted(order) != sorted(numbers):
            raise ModelError(f"{order} is not a permutation of the cylinder numbers "
                             f"{sorted(numbers)}; list every cylinder exactly once", "firing_order")


def _check_balancers(engine):
    """Counterweights on existing throws, balancer shafts of the right types; neither on a
    rotary, whose crank stands still while its crankcase turns."""
    for name, kind in (("counterweights", CounterweightMass), ("balancer_shafts", BalancerShaftSpec)):
        items = getattr(engine, name)
        if not items:
            continue
        if not all(isinstance(item, kind) for item in items):
            raise ModelError(f"needs {kind.__name__} objects", name)
        if engine.is_rotary:
            what = ("a counterweight turns with the crank, and a rotary's crank stands still"
                    if name == "counterweights" else
                    "a balancer shaft is geared to a turning crank, and a rotary's crank stands "
                    "still")
            raise ModelError(f"cannot be given for a rotary engine: {what}; remove them, or "
                             'use frame = "fixed"', name)
    for i, weight in enumerate(engine.counterweights, 1):
        if not weight.throw < len(engine.throws):
            raise ModelError(f"[{i - 1}] is on throw index {weight.throw}, but the engine has "
                             f"throws 0 to {len(engine.throws) - 1}; give one of them",
                             "counterweights")


def _check_crankshafts(engine):
    shafts = engine.crankshafts
    if not all(isinstance(s, Crankshaft) for s in shafts):
        raise ModelError("needs Crankshaft objects", "crankshafts")
    if shafts[0] != REFERENCE_CRANKSHAFT:
        raise ModelError("must begin with the reference crankshaft (at the origin, turning "
                         "forward, at phase 0); place and phase the others relative to it",
                         "crankshafts")
    if len(shafts) > 1 and engine.is_rotary:
        raise ModelError('a rotary engine turns its crankcase about one fixed crank; give one '
                         'crankshaft or frame = "fixed"', "crankshafts")
    for i, shaft in enumerate(shafts):
        for j in range(i):
            if abs(shaft.centre - shafts[j].centre) < SAME_POSITION_M:
                raise ModelError(f"[{j}] and [{i}] share an axis; give each crankshaft its own "
                                 "position", "crankshafts")


def _check_opposed(engine, c):
    """The second piston of an opposed-piston cylinder: on a throw of another crankshaft that
    lies on the cylinder's axis, far enough out that the two pistons never meet."""
    n = c.number
    if not 0 <= c.opposed_throw < len(engine.throws):
        raise ModelError(f"cylinder {n}: opposed_throw index {c.opposed_throw} is not one of the "
                         f"engine's throws (0 to {len(engine.throws) - 1})", cylinder=n)
    own, other = engine.throws[c.throw].crankshaft, engine.throws[c.opposed_throw].crankshaft
    if own == other:
        raise ModelError(f"cylinder {n}: its opposed throw is on the same crankshaft as its own "
                         "throw; an opposed piston is driven by another crankshaft, at the other "
                         "end of the bore", cylinder=n)
    # the far piston runs in this bore, at its axial position: its throw must be there too
    # (as far off it as the near throw is, for rods set side by side)
    far_z, near_z = engine.throws[c.opposed_throw].z_m, engine.throws[c.throw].z_m
    if abs(far_z - c.z_m) > abs(near_z - c.z_m) + SAME_POSITION_M:
        raise ModelError(f"cylinder {n}: its opposed throw is at z = {far_z:g} m but the bore at "
                         f"z = {c.z_m:g} m; the far piston runs in the same bore, so give its throw "
                         "the bore's axial position", cylinder=n)
    span = (engine.crankshafts[other].centre - engine.crankshafts[own].centre) \
        * complex(math.cos(engine.bank_angles_rad[c.bank]), -math.sin(engine.bank_angles_rad[c.bank]))
    # decimal inputs put a crankshaft on a slanted axis only to within rounding: a micrometre
    # a metre is accepted (the linkage then uses the exact line through the first crankshaft)
    if abs(span.imag) > max(SAME_POSITION_M, OPPOSED_AXIS_TOLERANCE * abs(span)):
        raise ModelError(f"cylinder {n}: crankshaft {other + 1} lies {abs(span.imag):g} m off the "
                         f"axis of the cylinder's bank {c.bank + 1}; an opposed piston's crankshaft "
                         "must sit on the bore's axis, at the other end", cylinder=n)
    reach = 2 * (engine.rod_length_m + engine.crank_radius_m)
    if span.real <= reach:
        where = "behind the first piston's crankshaft" if span.real <= 0 else "too close"
        raise ModelError(f"cylinder {n}: crankshaft {other + 1} is {span.real:g} m along the bore "
                         f"({where}); the two pistons could meet unless the crankshafts are more "
                         f"than 2·(rod_length + crank_radius) = {reach:g} m apart", cylinder=n)


def _check_cylinder(engine, c):
    n = c.number
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ModelError(f"cylinder numbers are whole numbers from 1, got {n!r}", "cylinders")
    for index in (c.bank, c.throw):
        if isinstance(index, bool) or not isinstance(index, int):
            raise ModelError(f"cylinder {n}: bank and throw are 0-based whole-number indices, got "
                             f"{index!r}", cylinder=n)
    if not 0 <= c.bank < len(engine.bank_angles_rad):
        raise ModelError(f"cylinder {n}: bank index {c.bank} is not one of the engine's "
                         f"{len(engine.bank_angles_rad)} banks", cylinder=n)
    if not 0 <= c.throw < len(engine.throws):
        raise ModelError(f"cylinder {n}: throw index {c.throw} is not one of the engine's "
                         f"{len(engine.throws)} throws", cylinder=n)
    _quantity(c.z_m, "length", "z_m", sign="any", cylinder=n)
    _quantity(c.reciprocating_kg, "mass", "reciprocating_kg", cylinder=n)
    _quantity(c.rod_inertia_kgm2, "moment of inertia", "rod_inertia_kgm2", sign="any", cylinder=n)
    offset = engine.pin_offset_of(c)
    if c.pin_offset_m is not None and engine.rod_length_m <= engine.crank_radius_m + abs(offset):
        raise ModelError(f"cylinder {n}: its pin_offset_m ({offset:g} m) leaves the rod "
                         f"({engine.rod_length_m:g} m) no longer than the crank radius plus "
                         f"|pin offset|, so it cannot reach the cylinder axis; make the offset "
                         "smaller", cylinder=n)
    if c.is_opposed:
        _check_opposed(engine, c)
    if not c.is_link:
        return
    master = engine._by_number.get(c.master)
    if master is None or master is c:
        raise ModelError(f"cylinder {n}: its master {c.master} is not another cylinder; give the "
                         "number of the master-rod cylinder", cylinder=n)
    if master.is_link:
        raise ModelError(f"cylinder {n}: cylinder {c.master} has a link rod itself; a link rod "
                         "must ride on a master rod", cylinder=n)
    if master.is_opposed:
        raise ModelError(f"cylinder {n}: cylinder {c.master} is an opposed-piston cylinder, whose "
                         "rods are plain; a link rod needs a master rod of its own", cylinder=n)
    if master.throw != c.throw:
        raise ModelError(f"cylinder {n}: its master, cylinder {c.master}, is on throw "
                         f"{master.throw + 1} but this one on throw {c.throw + 1}; a link rod rides "
                         "on the master rod of its own throw", cylinder=n)
    _quantity(c.link_length_m, "length", "link_length_m", cylinder=n)
    _quantity(c.knuckle_radius_m, "length", "knuckle_radius_m", cylinder=n)
    if c.knuckle_radius_m >= engine.rod_length_m:
        raise ModelError(f"cylinder {n}: knuckle_radius_m ({c.knuckle_radius_m:g} m) must be shorter "
                         f"than the master rod (rod_length_m, {engine.rod_length_m:g} m): the knuckle "
                         "pin sits on it", cylinder=n)
    _angle(c.knuckle_angle_rad, "knuckle_angle_rad", cylinder=n)
    _quantity(c.knuckle_kg, "mass", "knuckle_kg", sign="non-negative", cylinder=n)


#: the one crankshaft of an engine that names none: the reference itself (built here, once
#: the checks it runs are defined)
REFERENCE_CRANKSHAFT = Crankshaft()
