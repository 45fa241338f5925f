"""The crankshaft's mass-elastic model: its shaft line of inertias, stiffnesses and damping."""

from dataclasses import dataclass

__all__ = ["ShaftDisk", "TorsionModel"]


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

    def __post_init__(self):
        # lists given in code become tuples: the engine that holds the model stays hashable
        for name in ("throw_inertia_kgm2", "stiffness_nm_rad", "throw_damping_nms_rad", "front"):
            if isinstance(getattr(self, name), list):
                object.__setattr__(self, name, tuple(getattr(self, name)))
