"""Display units: the only place where newtons become per-cylinder figures or kgf."""

import math
from dataclasses import dataclass

from ..shaking import ellipse
from ..units import STANDARD_GRAVITY

__all__ = ["Scale", "order_values", "is_negligible"]

#: below this fraction of m_rec·r·ω²·n (and of that times one metre for moments) an order is zero
NEGLIGIBLE = 1e-9


@dataclass(frozen=True)
class Scale:
    """How forces and moments are shown: per cylinder (× m_rec·r·ω²·n), or in N or kgf."""

    absolute: bool = False
    units: str = "N"

    @property
    def force_label(self):
        return self.units if self.absolute else "per cyl"

    @property
    def moment_label(self):
        return "kgf·m" if self.units == "kgf" else "N·m"

    def force(self, value_n, per_cylinder_unit_n):
        if not self.absolute:
            return value_n / per_cylinder_unit_n
        return value_n / STANDARD_GRAVITY if self.units == "kgf" else value_n

    def moment(self, value_nm):
        return value_nm / STANDARD_GRAVITY if self.units == "kgf" else value_nm


def order_values(order, per_cylinder_unit_n):
    """Magnitudes, phases and ellipse of one order in SI (N, N·m, degrees).

    Components below ``NEGLIGIBLE`` of m_rec·r·ω²·n (N, or N·m) are rounding noise and
    are reported as exact zeros, phase included.
    """
    floor = NEGLIGIBLE * per_cylinder_unit_n
    clean = lambda z: z if abs(z) >= floor else 0j  # noqa: E731
    ff, fb = clean(order.force_forward), clean(order.force_backward)
    mf, mb = clean(order.moment_forward), clean(order.moment_backward)
    f_max, f_min, f_axis = ellipse(ff, fb)
    m_max, m_min, m_axis = ellipse(mf, mb)
    return {
        "force": {
            "forward_N": abs(ff), "forward_deg": _degrees(ff),
            "backward_N": abs(fb), "backward_deg": _degrees(fb),
            "max_N": f_max, "min_N": f_min, "axis_deg": math.degrees(f_axis),
        },
        "moment": {
            "forward_Nm": abs(mf), "forward_deg": _degrees(mf),
            "backward_Nm": abs(mb), "backward_deg": _degrees(mb),
            "max_Nm": m_max, "min_Nm": m_min, "axis_deg": math.degrees(m_axis),
        },
    }


def _degrees(phasor):
    """Angle of a phasor from the reference axis, positive with rotation, in [0, 360)."""
    return math.degrees(math.atan2(phasor.imag, phasor.real)) % 360.0 if phasor else 0.0


def is_negligible(values):
    """True when an order has neither force nor moment (see :func:`order_values`)."""
    return values["force"]["max_N"] == 0.0 and values["moment"]["max_Nm"] == 0.0
