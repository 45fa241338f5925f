"""Cylinder pressure over a working cycle: read from a CSV file, or a parametric cycle.

The parametric cycle is a single-zone model of each cylinder, on its own exact volume curve:

- from bottom dead centre before firing (ψ = −180°, ψ the crank angle from the firing top dead
  centre) the charge is compressed polytropically from the intake pressure;
- heat Q is released along a Wiebe curve x(ψ) = 1 − exp(−a·((ψ − ψ₀)/Δψ)^(m+1)), normalised to
  release all of Q between the start ψ₀ and ψ₀ + Δψ;
- the first law for a polytropic gas, dp = −n·p·dV/V + (n − 1)·dQ/V, is integrated exactly
  through its integrating factor: p·Vⁿ = p₁·V₁ⁿ + (n − 1)·∫ Vⁿ⁻¹ dQ;
- expansion runs to bottom dead centre (ψ = 180°), where the pressure falls to the intake
  pressure for the rest of the cycle (gas exchange without pumping work);
- Q is chosen so that the indicated mean effective pressure ∮ p dV / V_d is the one asked for
  (the indicated work is linear in Q, so two passes find it exactly).

The clearance volume of each cylinder is its own swept volume over (ε − 1).
"""

import csv
import os
from dataclasses import dataclass

import numpy as np

from .. import checks
from ..errors import AnalysisError, ConfigError, UnitError
from ..kinematics.state import FINE_SAMPLES
from ..units import DIMENSIONS, check_finite_range, parse_quantity

__all__ = [
    "PressureCurve",
    "CycleCurve",
    "read_pressure_csv",
    "read_cycle_csv",
    "cycle_pressure",
    "CYCLE_GRID_DEG",
]

#: resolution of the parametric cycle's integration, points per crank degree (the kinematics'
#: fine grid): interpolated onto the analysis grid, its cylinders agree to about 1e-6 of the
#: largest torque order
_FINE = FINE_SAMPLES // 360

#: the crank angles from the firing top dead centre (degrees, bottom dead centre to bottom dead
#: centre) at which the parametric cycle is integrated, and its piston's travel is wanted
CYCLE_GRID_DEG = np.linspace(-180.0, 180.0, 360 * _FINE + 1)


@dataclass(frozen=True)
class PressureCurve:
    """Cylinder pressure over one working cycle, from the firing top dead centre.

    Attributes
    ----------
    angles_deg : ndarray
        crank angles from the firing TDC, increasing, within one cycle
    pressures_pa : ndarray
        absolute pressure at those angles, Pa
    cycle_deg : float
        360 or 720
    source : str
        where it came from (a file, or "[gas]")
    """

    angles_deg: np.ndarray
    pressures_pa: np.ndarray
    cycle_deg: float
    source: str = ""

    def to_dict(self) -> dict:
        return {
            "source": self.source,
            "cycle_deg": self.cycle_deg,
            "angles_deg": [float(x) for x in self.angles_deg],
            "pressures_Pa": [float(x) for x in self.pressures_pa],
        }

    def at(self, angles_deg):
        """Pressure at crank angles from the firing TDC (any, wrapped into the cycle), Pa;
        linear between the given points, periodic."""
        period = self.cycle_deg
        x = np.concatenate([self.angles_deg, [self.angles_deg[0] + period]])
        y = np.concatenate([self.pressures_pa, [self.pressures_pa[0]]])
        return np.interp((np.asarray(angles_deg) - x[0]) % period + x[0], x, y)


@dataclass(frozen=True)
class CycleCurve:
    """A quantity over one working cycle as a CSV file gives it.

    Attributes
    ----------
    angles_deg : ndarray
        crank angles, increasing, within one cycle
    values : ndarray
        the quantity at those angles, SI (Pa for a pressure, N·m for a torque)
    cycle_deg : float
        360 or 720
    quantity : str
        "pressure" or "torque"
    source : str
        the file
    """

    angles_deg: np.ndarray
    values: np.ndarray
    cycle_deg: float
    quantity: str
    source: str = ""

    def to_dict(self) -> dict:
        unit = "Pa" if self.quantity == "pressure" else "Nm"
        return {
            "quantity": self.quantity,
            "source": self.source,
            "cycle_deg": self.cycle_deg,
            "angles_deg": [float(a) for a in self.angles_deg],
            f"values_{unit}": [float(v) for v in self.values],
        }


def read_pressure_csv(path, cycle_deg=None):
    """A pressure curve from a CSV file: a header ``angle_deg,pressure_<unit>`` (or
    ``angle (deg),pressure (<unit>)``), then one row per crank angle from the firing top dead
    centre, increasing, covering one working cycle once; absolute pressures, none negative.
    ``cycle_deg`` 360 or 720, or None (as the documentation gives the call) for the cycle the
    angles span.

    Raises
    ------
    ConfigError
        naming the file, the line and the fix
    """
    curve = read_cycle_csv(path, "pressure", cycle_deg)
    return PressureCurve(curve.angles_deg, curve.values, curve.cycle_deg, str(path))


def read_cycle_csv(path, quantity, cycle_deg=None):
    """Angles (degrees) and values (SI) of a quantity over one cycle from a CSV file with the
    header ``angle_deg,<quantity>_<unit>``. ``quantity`` is "pressure" (absolute, not
    negative) or "torque"; ``cycle_deg`` 360 or 720, or None to take the cycle the angles
    span (up to 360°, else 720°). Returns a :class:`CycleCurve`.

    Raises
    ------
    ConfigError
        naming the file, the line and the fix
    """
    checks.path(path)
    if quantity not in ("pressure", "torque"):
        raise AnalysisError(f"must be 'pressure' or 'torque', got {quantity!r}", "quantity")
    if cycle_deg is not None and (not checks.is_real(cycle_deg) or cycle_deg not in (360, 720)):
        raise AnalysisError(
            f"must be 360, 720 or None (the cycle the angles span), got {cycle_deg!r}", "cycle_deg"
        )
    if os.path.exists(path) and not os.path.isdir(path) and not os.path.isfile(path):
        # a FIFO or a device would block or never end: only regular files are read
        raise ConfigError(path, "", "is not a regular file; give a CSV file")
    try:
        with open(path, encoding="utf-8-sig", newline="") as handle:
            records = list(csv.reader(handle))
    except FileNotFoundError:
        raise ConfigError(path, "", "no such file; check the path") from None
    except IsADirectoryError:
        raise ConfigError(path, "", "is a folder; give a CSV file") from None
    except UnicodeDecodeError:
        raise ConfigError(path, "", "is not UTF-8 text; give a CSV file") from None
    except (OSError, csv.Error) as exc:
        raise ConfigError(
            path, "", f"cannot read the file ({getattr(exc, 'strerror', None) or exc})"
        ) from None
    rows = [
        (i, row) for i, row in enumerate(records, 1) if row and any(cell.strip() for cell in row)
    ]
    example = f"angle_deg,{quantity}_{'bar' if quantity == 'pressure' else 'Nm'}"
    if not rows:
        raise ConfigError(path, "", f"is empty; give a header {example} and one row per angle")
    line, header = rows[0]
    unit, factor = _column_unit(path, line, header, quantity, example)
    first = header[0].strip().lower()
    if first not in ("angle_deg", "angle (deg)", "angle [deg]", "angle"):
        raise ConfigError(
            path,
            f"line {line}",
            f"the first column is {header[0].strip()!r}; name "
            f"it angle_deg and give crank angles in degrees",
        )
    angles: list[float] = []
    values: list[float] = []
    for line, row in rows[1:]:
        if len(row) != 2:
            raise ConfigError(
                path,
                f"line {line}",
                f"has {len(row)} column{'' if len(row) == 1 else 's'}; give two: the angle "
                f"in degrees and the {quantity}",
            )
        try:
            angle, value = float(row[0]), float(row[1])
        except ValueError:
            raise ConfigError(
                path,
                f"line {line}",
                f"cannot read {row!r} as two numbers; write "
                "them with a decimal point (12.5, not 12,5) "
                "and separate the columns by a comma",
            ) from None
        if not np.isfinite(angle) or not np.isfinite(value):
            raise ConfigError(path, f"line {line}", "holds a number that is not finite")
        if abs(angle) > 2 * 720.0:
            raise ConfigError(
                path,
                f"line {line}",
                f"angle {angle:g}° is beyond two cycles; give "
                "crank angles in degrees over one cycle",
            )
        try:
            check_finite_range(value * factor, quantity, f"{value:g} {unit}", smallest=False)
        except UnitError as exc:
            raise ConfigError(path, f"line {line}", str(exc)) from None
        if quantity == "pressure" and value < 0:
            raise ConfigError(
                path,
                f"line {line}",
                f"pressure {value:g} {unit} is negative; give absolute pressures",
            )
        if angles and angle <= angles[-1]:
            problem = "repeats the angle" if angle == angles[-1] else "goes back"
            raise ConfigError(
                path,
                f"line {line}",
                f"{problem} ({angle:g}° after {angles[-1]:g}°); "
                "sort the rows by angle and give each once",
            )
        angles.append(angle)
        values.append(value * factor)
    if len(angles) < 8:
        raise ConfigError(path, "", f"has {len(angles)} rows; give the cycle in at least 8 points")
    angles_deg = np.array(angles)
    span = angles_deg[-1] - angles_deg[0]
    steps = np.diff(angles_deg)
    if cycle_deg is None:
        cycle_deg = 360.0 if span <= 360.0 else 720.0
    if np.isclose(span, cycle_deg, atol=1e-9 * cycle_deg):
        # the last row closes the cycle on the first: keep one of them
        angles_deg, values = angles_deg[:-1], values[:-1]
    elif span > cycle_deg or cycle_deg - span > 2 * steps.max():
        raise ConfigError(
            path,
            f"line {rows[-1][0]}",
            f"the angles cover {span:g}°, not one {cycle_deg:g}° cycle; give one cycle",
        )
    return CycleCurve(angles_deg, np.array(values), float(cycle_deg), quantity, str(path))


def _column_unit(path, line, header, quantity, example):
    """The second column's unit as written, and its factor to SI."""
    if len(header) != 2:
        raise ConfigError(
            path, f"line {line}", f"the header must name two columns, such as {example}"
        )
    name = header[1].strip()
    dimension = quantity
    for prefix, suffix in ((f"{quantity}_", ""), (f"{quantity} (", ")"), (f"{quantity} [", "]")):
        if name.lower().startswith(prefix) and name.endswith(suffix) and len(name) > len(prefix):
            unit = name[len(prefix) : len(name) - len(suffix)].strip()
            try:
                return unit, parse_quantity(f"1 {unit}", dimension)
            except UnitError as exc:
                raise ConfigError(
                    path, f"line {line}", f"the {quantity} column's unit: {exc}"
                ) from None
    units = ", ".join(DIMENSIONS[dimension])
    raise ConfigError(
        path,
        f"line {line}",
        f"the second column is {name!r}; name it {quantity}_<unit> with a unit of {units}",
    )


def _wiebe(psi, start, duration, a, m):
    """Fraction of the heat released by crank angle ψ (degrees from the firing TDC)."""
    s = np.clip((psi - start) / duration, 0.0, 1.0)
    return (1.0 - np.exp(-a * s ** (m + 1))) / (1.0 - np.exp(-a))


def _compression_expansion(psi, volume, gas, heat_j):
    """Pressure from ψ = −180° to 180° (fine grid ``psi``, volumes ``volume``)."""
    n = gas.polytropic_exponent
    released = heat_j * _wiebe(
        psi, gas.combustion_start_deg, gas.combustion_duration_deg, gas.wiebe_a, gas.wiebe_m
    )
    # p·Vⁿ = p₁·V₁ⁿ + (n − 1)·∫ Vⁿ⁻¹ dQ, by the trapezoidal rule on the fine grid
    integrand = volume ** (n - 1) * np.gradient(released, psi)
    integral = np.concatenate(
        [[0.0], np.cumsum(0.5 * (integrand[1:] + integrand[:-1]) * np.diff(psi))]
    )
    return (gas.intake_pa * volume[0] ** n + (n - 1) * integral) / volume**n


def cycle_pressure(gas, travel_m, cycle_deg, where="[gas]"):
    """The parametric cycle of one cylinder.

    Parameters
    ----------
    gas : GasCycle
    travel_m : ndarray
        the piston's distance from the crank axis, m, at the crank angles
        :data:`CYCLE_GRID_DEG` from its firing TDC
    cycle_deg : float
        360 or 720

    Returns
    -------
    PressureCurve
    """
    psi = CYCLE_GRID_DEG
    travel = np.asarray(travel_m, dtype=float)
    area = gas.piston_area_m2
    swept = area * (travel.max() - travel.min())
    clearance = swept / (gas.compression_ratio - 1)
    volume = clearance + area * (travel.max() - travel)

    def work(heat_j):
        pressure = _compression_expansion(psi, volume, gas, heat_j)
        # ∮ p dV: compression and expansion; gas exchange at constant pressure adds nothing
        return pressure, np.sum(0.5 * (pressure[1:] + pressure[:-1]) * np.diff(volume))

    motored, w0 = work(0.0)
    if gas.imep_pa is None:
        heat, pressure = 0.0, motored
    else:
        # pressure and work are affine in the heat released: two passes give both exactly
        unit, w1 = work(1.0)
        heat = (gas.imep_pa * swept - w0) / (w1 - w0)
        if heat < 0:
            raise ConfigError(
                where,
                "gas.imep",
                "is below what compression and expansion alone "
                "give; raise it or leave it out for a motored cycle",
            )
        pressure = motored + heat * (unit - motored)
    angles = np.arange(0.0, cycle_deg, 1.0 / _FINE)
    signed = (angles + cycle_deg / 2) % cycle_deg - cycle_deg / 2
    values = np.where(np.abs(signed) <= 180.0, np.interp(signed, psi, pressure), gas.intake_pa)
    return PressureCurve(angles, values, float(cycle_deg), "[gas]")
