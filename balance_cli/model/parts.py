"""Part-level data (pistons, rods, crank) and the gas cycle: what the lumped masses and the gas
torque are derived from."""

import math
from dataclasses import dataclass

__all__ = ["Parts", "GasCycle"]


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
        return self.link_inertia_kgm2 - self.link_kg * self.link_cg_m * (
            link_length_m - self.link_cg_m
        )


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
