"""A quantity over one period as a Fourier series (torques, force components), and the
reduced mass of the moving parts."""

import math
from dataclasses import dataclass

import numpy as np

from ..checks import is_real
from ..errors import OrderError
from ..tabular import Tabular
from ..tolerances import NOISE_FLOOR
from ..units import phasor_deg

__all__ = ["Series", "ReducedMass", "torque_unit_nm", "cycle_series"]


@dataclass(frozen=True)
class Series(Tabular):
    """A quantity over one period: X(θ) = mean + Σ_k (cos_k·cos kθ + sin_k·sin kθ), in ``unit``
    (a torque in N·m, a force component in N).

    θ is the crank angle of throw 1 (a rotary's crankcase angle), positive with rotation; k
    runs over multiples of ½ for a four-stroke. ``curve`` holds X at ``theta_deg``.
    """

    period_deg: float
    mean: float
    orders: tuple
    theta_deg: np.ndarray
    curve: np.ndarray
    unit: str = "Nm"

    @classmethod
    def from_curve(cls, curve, period_deg, max_order, floor, unit="Nm"):
        """The series of samples ``curve`` (over one period) up to ``max_order``; terms below
        ``floor`` are rounding noise and read as exact zeros."""
        curve = np.real(curve)
        n = curve.shape[-1]
        per_turn = period_deg / 360.0
        c = np.fft.rfft(curve) / n
        orders = []
        for j in range(1, int(round(max_order * per_turn)) + 1):
            cos, sin = float(2 * c[j].real), float(-2 * c[j].imag)
            orders.append(
                (j / per_turn, cos if abs(cos) >= floor else 0.0, sin if abs(sin) >= floor else 0.0)
            )
        mean = c[0].real if abs(c[0].real) >= floor else 0.0
        theta = np.arange(n) * period_deg / n
        if np.abs(curve).max() < floor:
            curve = np.zeros_like(curve)  # rounding noise only (a centred piston's tilting)
        return cls(float(period_deg), float(mean), tuple(orders), theta, curve, unit)

    @property
    def max(self) -> float:
        return float(self.curve.max())

    @property
    def min(self) -> float:
        return float(self.curve.min())

    @property
    def range(self) -> float:
        """ΔC, the largest minus the smallest value over the period."""
        return self.max - self.min

    def order(self, k) -> tuple:
        """(cos, sin) of order ``k`` (a multiple of ½ for a four-stroke); OrderError (a
        KeyError) otherwise."""
        if is_real(k):
            for order, cos, sin in self.orders:
                if abs(order - k) < 1e-9:
                    return cos, sin
        highest = self.orders[-1][0] if self.orders else 0
        raise OrderError(
            f"order {k!r} is not among the orders of this series (multiples of "
            f"{360 / self.period_deg:g} up to {highest:g})"
        )

    def records(self) -> list:
        """One row per order, the mean first as order 0: ``order``, ``cos_<unit>``,
        ``sin_<unit>``, ``amplitude_<unit>`` and ``phase_deg``, the term being
        amplitude·cos(kθ − phase) (the mean's phase is 0, or 180 where it is negative)."""
        u = self.unit
        mean = {
            "order": 0.0,
            f"cos_{u}": self.mean,
            f"sin_{u}": 0.0,
            f"amplitude_{u}": abs(self.mean),
            "phase_deg": 180.0 if self.mean < 0 else 0.0,
        }
        return [mean, *self.to_dict()["orders"]]

    def to_dict(self) -> dict:
        """``mean_<unit>``, ``max_``, ``min_``, ``range_`` and ``orders[]`` (``order``, ``cos_``,
        ``sin_``, ``amplitude_``, ``phase_deg``: the order is amplitude·cos(kθ − phase))."""
        u = self.unit
        return {
            f"mean_{u}": self.mean,
            f"max_{u}": self.max,
            f"min_{u}": self.min,
            f"range_{u}": self.range,
            "orders": [
                {
                    "order": k,
                    f"cos_{u}": cos,
                    f"sin_{u}": sin,
                    f"amplitude_{u}": math.hypot(cos, sin),
                    "phase_deg": phasor_deg(complex(cos, sin)),
                }
                for k, cos, sin in self.orders
            ],
        }


@dataclass(frozen=True)
class ReducedMass:
    """μ(θ): the kinetic energy of the moving parts is ½·μ·ω², kg·m² (Margoulis § 2)."""

    theta_deg: np.ndarray
    curve_kgm2: np.ndarray

    @property
    def mean_kgm2(self) -> float:
        return float(self.curve_kgm2.mean())

    @property
    def min_kgm2(self) -> float:
        return float(self.curve_kgm2.min())

    @property
    def max_kgm2(self) -> float:
        return float(self.curve_kgm2.max())

    def to_dict(self) -> dict:
        return {"mean_kgm2": self.mean_kgm2, "min_kgm2": self.min_kgm2, "max_kgm2": self.max_kgm2}


def torque_unit_nm(engine) -> float:
    """m_rec·r²·ω²·n, N·m: the size torques are measured against (as forces against
    m·r·ω²·n)."""
    return engine.per_cylinder_unit_n * engine.crank_radius_m


def cycle_series(engine, values, max_order, unit="Nm") -> Series:
    """The :class:`Series` of samples ``values`` over the engine's cycle (720° for a
    four-stroke) up to ``max_order``; terms below the noise floor (of a torque, or of a force
    for ``unit`` "N") read as exact zeros."""
    floor = NOISE_FLOOR * torque_unit_nm(engine) if unit == "Nm" else engine.noise_floor_n
    return Series.from_curve(values, engine.cycle_deg, max_order, floor, unit)
