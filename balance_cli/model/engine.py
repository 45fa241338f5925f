"""The engine: its geometry, cylinders, masses and what it carries, checked when built."""

import dataclasses
import math
from dataclasses import dataclass, field, fields

from ..errors import ModelError
from ..tolerances import NOISE_FLOOR
from .crankshaft import REFERENCE_CRANKSHAFT, Crankshaft
from .cylinder import Cylinder
from .edit import edited
from .invariants import check_engine
from .mounts import MountSystem
from .parts import GasCycle, Parts
from .scatter import ToleranceBand
from .torsion import TorsionModel
from .values import offset_position

__all__ = ["Engine", "BISECTOR_FLOOR"]

#: banks whose unit vectors add up to less than this fraction of their number have no
#: bisector worth calling vertical (within about 6° of a boxer's 180°)
BISECTOR_FLOOR = 0.05


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
        mass at the crank pin of every throw that is not the crankshaft's (big ends), kg; a
        throw's own ``rotating_kg`` overrides it (:meth:`rotating_of`)
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
    mounts : MountSystem or None
        the powertrain as a rigid body on its mounts, for ``balance mounts``, if given
    tolerances : ToleranceBand or None
        the production scatter of its parts and dimensions (``[tolerances]``), for
        :func:`balance_cli.tolerance`, if given

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
    mounts: "MountSystem | None" = None
    tolerances: "ToleranceBand | None" = None
    _by_number: dict = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        # sequences given as lists become tuples: the engine stays immutable and hashable
        for name in (
            "bank_angles_rad",
            "throws",
            "cylinders",
            "firing_order",
            "crankshafts",
            "counterweights",
            "balancer_shafts",
        ):
            value = getattr(self, name)
            if isinstance(value, list):
                object.__setattr__(self, name, tuple(value))
            elif not isinstance(value, tuple) and (name != "firing_order" or value is not None):
                # a number here failed later with "not iterable"
                raise ModelError(f"must be a list or tuple, got {value!r}", name)
        object.__setattr__(
            self, "_by_number", {c.number: c for c in self.cylinders if isinstance(c, Cylinder)}
        )
        if not self.crankshafts:
            # one way to say "one crankshaft": the reference, whether named or not
            object.__setattr__(self, "crankshafts", (REFERENCE_CRANKSHAFT,))
        if self.mounts is not None and not isinstance(self.mounts, MountSystem):
            raise ModelError(
                f"must be a MountSystem or None, got {type(self.mounts).__name__}", "mounts"
            )
        if self.power_w is not None and self.power_speed_rad_s is None:
            object.__setattr__(self, "power_speed_rad_s", self.speed_rad_s)
        check_engine(self)

    def replace(self, **changes) -> "Engine":
        """A copy with ``changes`` (field names and SI values, as the constructor takes them),
        checked like any new engine (its own invariants, as on construction)::

            faster = engine.replace(speed_rad_s=2 * engine.speed_rad_s)

        Whether the linkage can be assembled over a revolution (a link rod reaching its axis,
        an opposed bore's two pistons sweeping a volume) is checked above the model, by the
        configuration reader and first by every analysis
        (:func:`balance_cli.kinematics.linkage.check_assembly`): a copy that cannot be
        assembled is refused when it is analysed, not here.

        Raises
        ------
        ModelError
            a name that is not a field, or a value the engine cannot have
        """
        names = [f.name for f in fields(self) if f.init]
        unknown = sorted(set(changes) - set(names))
        if unknown:
            raise ModelError(
                f"Engine.replace: {', '.join(map(repr, unknown))} is not a field of "
                f"Engine; choose from {', '.join(names)}"
            )
        return dataclasses.replace(self, **changes)

    def edit(self, *, cylinder=None, throw=None, **values) -> "Engine":
        """A copy with some values changed, written as a configuration file writes them, and
        checked like any new engine.

        One cylinder's, one throw's or the engine's own values, one at a time::

            heavier = engine.edit(cylinder=3, reciprocating="550 g")
            moved = engine.edit(throw=2, phase=90, name="In-line 4, throw 2 at 90°")
            longer = engine.edit(rod_ratio=3.5, speed="3000 rpm")

        Parameters
        ----------
        cylinder : int, optional
            the number of the one cylinder whose values change: ``reciprocating`` (its
            piston's mass), ``opposed_reciprocating`` (an opposed bore's second piston),
            ``z`` (its axial position) and ``pin_offset``
        throw : int, optional
            the number (from 1) of the one throw whose values change: ``phase`` (degrees from
            throw 1, positive with rotation, a plain number from -360 to 360), ``z`` and
            ``rotating`` (the big ends at its pin, "1.3 kg", overriding the engine's)
        **values
            the keys and values; without ``cylinder`` and ``throw``, the engine's own:
            ``speed`` ("3000 rpm"), ``crank_radius``, ``rod_length``, ``pin_offset``
            ("82.5 mm"), ``rod_ratio`` (l/r, a plain number above 1: the rod length becomes
            rod_ratio × the crank radius, the new one if it changes too), ``reciprocating``
            (every cylinder's, "550 g"), ``rotating`` and ``crank`` (per throw). ``name``
            (one line of text) goes with any of them: :func:`~balance_cli.compare` tells
            engines apart by name. Masses, lengths and speeds are text with a unit, as in a
            file, in any unit a file may use.

        Returns
        -------
        Engine
            the copy; the rest as it was (a crank radius changed alone keeps the rod length;
            values derived from ``[parts]`` are not derived again)

        Raises
        ------
        ModelError
            naming the key (``parameter``): a key that is not one of the cylinder's, the
            throw's or the engine's, a value without its unit or out of range, a cylinder or
            throw the engine has not, or a copy that cannot exist (a rod no longer than the
            crank). Whether the copy's linkage can be assembled over a revolution is
            checked when it is analysed, as for :meth:`replace`.
        """
        given = dict(values)
        changes = edited(self, cylinder, throw, dict(values))
        try:
            return self.replace(**changes)
        except ModelError as exc:
            key = next(iter(given), "name")
            raise ModelError(
                f"= {given.get(key, changes.get('name'))!r} makes an engine that cannot exist: "
                f"{exc}",
                key,
            ) from None

    def cylinder(self, number):
        """The cylinder with this number."""
        return self._by_number[number]

    def is_master(self, cylinder):
        return any(c.master == cylinder.number for c in self.cylinders)

    def rod_type(self, cylinder):
        """ "plain", "master", "link" or "opposed" (two plain rods, one from each end)."""
        if cylinder.is_link:
            return "link"
        if cylinder.is_opposed:
            return "opposed"
        return "master" if self.is_master(cylinder) else "plain"

    def rotating_of(self, throw_index) -> float:
        """The big ends at the pin of the throw at ``throw_index`` (0-based): its own
        ``rotating_kg`` where it has one, else the engine's, kg."""
        own = self.throws[throw_index].rotating_kg
        return self.rotating_kg if own is None else own

    def pin_offset_of(self, cylinder) -> float:
        """The piston-pin offset of ``cylinder``: its own, else the engine's, m."""
        return self.pin_offset_m if cylinder.pin_offset_m is None else cylinder.pin_offset_m

    def counterweight_z_m(self, counterweight) -> float:
        """Where ``counterweight`` sits, m: its own ``z_m``, else its throw's."""
        if counterweight.z_m is not None:
            return counterweight.z_m
        return self.throws[counterweight.throw_index].z_m

    def balancer_z_m(self, mass) -> float:
        """Where balancer ``mass`` sits, m: its own ``z_m``, else z̄ (the cylinders' mean)."""
        return self.mean_z_m if mass.z_m is None else mass.z_m

    def balancer_centre(self, shaft) -> complex:
        """The axis of balancer ``shaft`` in the transverse plane, m (real along the reference
        axis): its vertical offset along :attr:`vertical_axis_rad`, its lateral one 90° on."""
        return offset_position(shaft.lateral_m, shaft.vertical_m, self.vertical_axis_rad)

    def crankshaft_of(self, throw_index) -> "Crankshaft":
        """The crankshaft that carries the throw at ``throw_index`` in :attr:`throws` (0-based,
        as the arrays of the kinematics index throws)."""
        return self.crankshafts[self.throws[throw_index].crankshaft_index]

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
        if (
            self.power_w is None
            or self.power_speed_rad_s is None
            or not math.isclose(self.power_speed_rad_s, self.speed_rad_s, rel_tol=1e-12)
        ):
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
    def turns_per_cycle(self) -> int:
        """Revolutions of one working cycle: 1 (two-stroke) or 2 (four-stroke)."""
        return self.cycle // 2

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
