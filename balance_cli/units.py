"""Quantities with units at the edges of the program; SI and radians inside.

A configuration value such as ``"82.5 mm"`` or ``"1650 rpm"`` is parsed once, here, into SI
(metres, kilograms, radians per second), and reports turn SI back into display units here.
Nothing else in the package knows about millimetres, grams, kilogram-force or revolutions per
minute. Angles in degrees are normalised here too, once for the whole package.
"""

import math
import re
from dataclasses import dataclass

from .errors import UnitError
from .tolerances import ANGLE_TOLERANCE_DEG

__all__ = [
    "DIMENSIONS",
    "LIMITS",
    "STANDARD_GRAVITY",
    "THOUSANDS_SEPARATORS",
    "parse_quantity",
    "check_finite_range",
    "rad_s_to_rpm",
    "m_to_mm",
    "kg_to_g",
    "n_to_kgf",
    "wrap_degrees",
    "round_degrees",
    "phasor_deg",
    "angle_change",
    "UNIT_SYSTEMS",
    "unit_system",
    "significant",
    "Scale",
    "shown_unit",
    "shown_value",
]

#: m/s², the conventional value used to turn kilogram-force into newtons
STANDARD_GRAVITY = 9.80665

_RPM = 2.0 * math.pi / 60.0

_BAR = 1e5
_LBF_PER_IN = 0.45359237 * STANDARD_GRAVITY / 0.0254
_KGF_CM2 = STANDARD_GRAVITY * 1e4

#: unit symbol -> factor to SI, per dimension
DIMENSIONS = {
    "length": {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "in": 0.0254, "ft": 0.3048},
    "mass": {"kg": 1.0, "g": 1e-3, "lb": 0.45359237},
    "angular speed": {"rpm": _RPM, "rev/min": _RPM, "rad/s": 1.0, "rps": 2.0 * math.pi},
    # kgf·cm·s² is the "kg cm sec²" of the older papers (Fraeys de Veubeke's J, j)
    "moment of inertia": {
        "kg*m^2": 1.0,
        "kg*cm^2": 1e-4,
        "g*cm^2": 1e-7,
        "kg*mm^2": 1e-6,
        "lb*in^2": 0.45359237 * 0.0254**2,
        "kgf*cm*s^2": STANDARD_GRAVITY * 1e-2,
    },
    "pressure": {
        "Pa": 1.0,
        "kPa": 1e3,
        "MPa": 1e6,
        "bar": _BAR,
        "mbar": 1e2,
        "psi": 6894.757293168,
        "atm": 101325.0,
        "kgf/cm^2": _KGF_CM2,
        "at": _KGF_CM2,
    },
    "torque": {
        "N*m": 1.0,
        "Nm": 1.0,
        "kN*m": 1e3,
        "kgf*m": STANDARD_GRAVITY,
        "lbf*ft": 1.3558179483314004,
    },
    # hp is the mechanical horsepower (550 ft·lbf/s), PS the metric one (75 kgf·m/s)
    "power": {
        "W": 1.0,
        "kW": 1e3,
        "MW": 1e6,
        "hp": 550 * 0.3048 * 0.45359237 * STANDARD_GRAVITY,
        "PS": 75 * STANDARD_GRAVITY,
    },
    # a mass times its radius (a counterweight's or balancer mass's m·ρ), as balancing
    # machines and drawings give it
    "unbalance": {
        "kg*m": 1.0,
        "kg*cm": 1e-2,
        "kg*mm": 1e-3,
        "g*m": 1e-3,
        "g*cm": 1e-5,
        "g*mm": 1e-6,
        "lb*in": 0.45359237 * 0.0254,
        "oz*in": 0.45359237 / 16 * 0.0254,
    },
    # a crankshaft section's twist stiffness and a damper's or a throw's viscous damping
    "torsional stiffness": {"N*m/rad": 1.0, "kN*m/rad": 1e3, "MN*m/rad": 1e6},
    "torsional damping": {"N*m*s/rad": 1.0, "kN*m*s/rad": 1e3},
    # an engine mount's rate along one of its principal axes, and its viscous damping
    "stiffness": {
        "N/m": 1.0,
        "N/mm": 1e3,
        "kN/m": 1e3,
        "kN/mm": 1e6,
        "MN/m": 1e6,
        "lbf/in": _LBF_PER_IN,
    },
    "viscous damping": {"N*s/m": 1.0, "N*s/mm": 1e3, "kN*s/m": 1e3},
}

#: one choice of display units: force unit -> (N per force unit, moment unit, N·m per moment
#: unit). Each system pairs a force with the moment people write beside it.
_LBF = 0.45359237 * STANDARD_GRAVITY
UNIT_SYSTEMS = {
    "N": (1.0, "N·m", 1.0),
    "kN": (1e3, "kN·m", 1e3),
    "MN": (1e6, "MN·m", 1e6),
    "kgf": (STANDARD_GRAVITY, "kgf·m", STANDARD_GRAVITY),
    "lbf": (_LBF, "lbf·ft", _LBF * 0.3048),
}

#: smallest and largest magnitude (SI) of a non-zero value, per dimension, with the unit the
#: limits are shown in. Wide enough for a watch and a ship; narrow enough that m·r·ω² and its
#: moments stay far from overflow (1e22) and underflow (1e-20) in double precision.
LIMITS = {
    "length": (1e-6, 1e3, "mm", 1e-3),
    "mass": (1e-6, 1e6, "kg", 1.0),
    "angular speed": (1e-3 * _RPM, 1e6 * _RPM, "rpm", _RPM),
    "moment of inertia": (1e-12, 1e9, "kg*m^2", 1.0),
    "pressure": (1e-3, 1e10, "bar", _BAR),
    "torque": (1e-9, 1e12, "N*m", 1.0),
    "power": (1e-3, 1e10, "kW", 1e3),
    # the product of the mass and length limits
    "unbalance": (1e-12, 1e9, "kg*m", 1.0),
    "torsional stiffness": (1e-3, 1e13, "N*m/rad", 1.0),
    "torsional damping": (1e-9, 1e12, "N*m*s/rad", 1.0),
    "stiffness": (1e-3, 1e12, "N/m", 1.0),
    "viscous damping": (1e-6, 1e9, "N*s/m", 1.0),
}

#: what may set the thousands of a number apart (SI, ISO 80000-1: a space, never a comma or a
#: point), and the number from its unit: a space, a no-break space, a thin space or a narrow
#: no-break space
THOUSANDS_SEPARATORS = " \u00a0\u2009\u202f"
_AS_SPACE = str.maketrans({c: " " for c in THOUSANDS_SEPARATORS})
# ASCII digits only; the whole part's digits in groups of three, each set apart by one space
# ("14 280", "1 000 000"), or not grouped at all; any unit word, so that an unknown one is
# reported as a unit
_QUANTITY = re.compile(
    r"^\s*([-+]?(?:\d{1,3}(?: \d{3})+(?:\.\d*)?|\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)"
    r"\s*([^\s\d.+-].*?)\s*$",
    re.ASCII,
)
_EXAMPLES = {
    "length": "82.5 mm",
    "mass": "1770.4 g",
    "angular speed": "1650 rpm",
    "moment of inertia": "0.12 kg*m^2",
    "pressure": "45 bar",
    "torque": "850 N*m",
    "power": "21 MW",
    "unbalance": "0.072 kg*m",
    "torsional stiffness": "1.25e6 N*m/rad",
    "torsional damping": "2 N*m*s/rad",
    "stiffness": "250 N/mm",
    "viscous damping": "500 N*s/m",
}


def _units_of(dimension):
    return ", ".join(f'"{u}"' for u in DIMENSIONS[dimension])


def parse_quantity(text, dimension):
    """Parse ``"<number> <unit>"`` into SI.

    Parameters
    ----------
    text : str
        the value as written, e.g. ``"82.5 mm"``; the whole part's digits may be grouped by
        threes, each group set apart by one of :data:`THOUSANDS_SEPARATORS` (``"14 280 kW"``)
    dimension : str
        one of the keys of :data:`DIMENSIONS`

    Returns
    -------
    float
        the value in SI (m, kg or rad/s): finite, and zero or within :data:`LIMITS`

    Raises
    ------
    UnitError
        a missing, unknown or wrong unit, or a number out of range
    """
    example = _EXAMPLES[dimension]
    if isinstance(text, bool) or not isinstance(text, str):
        raise UnitError(f'expected a string with a unit such as "{example}", got {text!r}')
    match = _QUANTITY.match(text.translate(_AS_SPACE))
    if not match:
        raise UnitError(
            f'cannot read {text!r}: write a number and a unit, such as "{example}" (thousands '
            'may be set apart by spaces, in groups of three: "14 280 kW")'
        )
    number, written = float(match.group(1).replace(" ", "")), match.group(2)
    unit = _spelling(written)
    factors = DIMENSIONS[dimension]
    if unit not in factors:
        unit = _any_case(unit, factors, text)
    if unit not in factors:
        for other, table in DIMENSIONS.items():
            if unit in table:
                raise UnitError(
                    f"{text!r} is {_article(other)} {other}, but {_article(dimension)} "
                    f"{dimension} is needed "
                    f"(units: {_units_of(dimension)})"
                )
        raise UnitError(f"unknown unit {written!r} in {text!r} (units: {_units_of(dimension)})")
    value = number * factors[unit]
    check_finite_range(value, dimension, shown=repr(text))
    return value


#: letters whose case changes a unit's meaning, in words
_CASE_SENSITIVE = {
    "m": "small m is milli (or metre), capital M mega",
    "p": "small p is pico, capital P peta (or pascal)",
}


#: what may follow a prefix letter: the base symbols a milli-, mega-, pico- or peta- could
#: stand before in balance's units (metre, gram, pascal, bar, newton, watt), or nothing
_PREFIXED = {"", "m", "g", "pa", "bar", "n", "w"}


def _case_clash(written, meant):
    """The words for the first letter whose case differs between ``written`` and the unit
    ``meant`` where it reads as a prefix (m/M, p/P at the start of a unit or after * or /,
    before a base symbol), or None: "RPM" is rpm and "PSI" psi, but "Mm" could be
    millimetres or megametres."""
    for i, (a, b) in enumerate(zip(written, meant, strict=True)):
        if a == b or a.lower() not in _CASE_SENSITIVE or (i and written[i - 1] not in "*/"):
            continue
        rest = re.split(r"[*/^]", written[i + 1 :])[0].lower()
        if rest in _PREFIXED:
            return _CASE_SENSITIVE[a.lower()]
    return None


def _any_case(unit, factors, text):
    """The unit of ``factors`` written in other letter cases ("RPM", "Kg"), when that reading is
    the only one: a letter whose case is a prefix's meaning (m/M, p/P) is refused, naming
    both readings."""
    matches = [u for u in factors if u.lower() == unit.lower()]
    if len(matches) != 1:
        return unit
    clash = _case_clash(unit, matches[0])
    if clash:
        raise UnitError(
            f"{unit!r} in {text!r} could be read two ways ({clash}); write "
            f"{matches[0]!r} if that is meant"
        )
    return matches[0]


def unit_system(name):
    """The display units named ``name``, in any letter case where that is one reading ("kn" is
    kN; "mn" could be milli- or meganewtons and is refused): the canonical name, a key of
    :data:`UNIT_SYSTEMS`."""
    if isinstance(name, str):
        matches = [u for u in UNIT_SYSTEMS if u.lower() == name.strip().lower()]
        if matches:
            clash = _case_clash(name.strip(), matches[0])
            if clash:
                raise UnitError(
                    f"{name!r} could be read two ways ({clash}); write "
                    f"{matches[0]!r} if that is meant",
                    "units",
                )
            return matches[0]
    raise UnitError(
        f"must be one of {', '.join(UNIT_SYSTEMS)} (with moments in "
        f"{', '.join(m for _, m, _ in UNIT_SYSTEMS.values())}), got {name!r}",
        "units",
    )


@dataclass(frozen=True)
class Scale:
    """How forces and moments are shown: per cylinder (× m_rec·r·ω²·n), or in one system of
    units (:data:`~balance_cli.units.UNIT_SYSTEMS`: N and N·m, kN and kN·m, MN and MN·m,
    kgf and kgf·m, lbf and lbf·ft).

    Moments are always absolute, in the moment unit of ``units``.
    """

    absolute: bool = False
    units: str = "N"

    @classmethod
    def of(cls, absolute, units=None):
        """The scale of the command-line options: ``units`` None when none was chosen (forces
        absolute only if ``absolute``, moments in N·m); any unit chosen, N too, means absolute
        forces in it. The unit's name in any letter case."""
        if units is None:
            return cls(absolute=bool(absolute), units="N")
        return cls(absolute=True, units=unit_system(units))

    @property
    def force_label(self) -> str:
        return self.units if self.absolute else "per cyl"

    @property
    def force_unit_text(self) -> str:
        """The force unit in words, for titles and axis labels."""
        return self.units if self.absolute else "× m_rec·r·ω² per cylinder"

    @property
    def moment_label(self) -> str:
        return UNIT_SYSTEMS[self.units][1]

    @property
    def column_force(self) -> str:
        """The force unit in a CSV column name: per_cyl, N, kN, MN, kgf or lbf."""
        return self.units if self.absolute else "per_cyl"

    @property
    def column_moment(self) -> str:
        """The moment unit in a CSV column name: Nm, kNm, MNm, kgfm or lbfft."""
        return self.moment_label.replace("·", "")

    def force(self, value_n, per_cylinder_unit_n):
        if not self.absolute:
            return value_n / per_cylinder_unit_n
        return value_n / UNIT_SYSTEMS[self.units][0]

    def moment(self, value_nm):
        return value_nm / UNIT_SYSTEMS[self.units][2]


def shown_unit(quantity, units):
    """The unit a sweep's quantity is shown in, "" for a pure number."""
    scale = Scale.of(True, units)
    # frequencies, percentages and angles of the mount analysis are shown as they are
    fixed = {"Hz": "Hz", "%": "%", "deg": "°"}.get(quantity.unit, "")
    return {"N": scale.force_label, "Nm": scale.moment_label}.get(quantity.unit, fixed)


def shown_value(quantity, value_si, units):
    """A sweep's quantity in the unit it is shown in: forces and moments in ``units``'s
    system, anything else as it is."""
    scale = Scale.of(True, units)
    if quantity.unit == "N":
        return scale.force(value_si, 1.0)
    return scale.moment(value_si) if quantity.unit == "Nm" else value_si


def significant(value, digits=4):
    """``value`` as text to ``digits`` significant figures, in the notation that fits its size:
    plain from 1e-4 to below 1e9, thousands set apart by spaces ("4 980", "0.2147",
    "12 300 000"); powers of ten outside (3.142e-07); an exact zero is "0"."""
    if value == 0 or not math.isfinite(value):
        return "0" if value == 0 else str(value)
    rounded = float(f"{value:.{digits - 1}e}")
    exponent = math.floor(math.log10(abs(rounded)))
    if not -4 <= exponent < 9:
        return f"{rounded:.{digits - 1}e}"
    decimals = max(digits - 1 - exponent, 0)
    text = f"{rounded:,.{decimals}f}".replace(",", " ")
    return text


def _spelling(unit):
    """One spelling of a compound unit: "kg·m²", "kg m2", "kg.m2" and "kg*m^2" are one unit."""
    for other, canonical in (("·", "*"), (".", "*"), (" ", "*"), ("²", "^2"), ("³", "^3")):
        unit = unit.replace(other, canonical)
    unit = re.sub(r"([A-Za-z])(\d)", r"\1^\2", unit)
    return re.sub(r"\*+", "*", unit)


def _article(word):
    return "an" if word[:1] in "aeiou" else "a"


def _plural(dimension):
    return {
        "moment of inertia": "moments of inertia",
        "power": "powers",
        "torsional stiffness": "torsional stiffnesses",
        "torsional damping": "torsional damping coefficients",
        "stiffness": "stiffnesses",
        "viscous damping": "viscous damping coefficients",
    }.get(dimension, dimension + "s")


def check_finite_range(value, dimension, shown=None, smallest=True):
    """Raise UnitError unless ``value`` (SI) is finite and zero or within :data:`LIMITS`
    (with ``smallest`` False, any magnitude up to the largest)."""
    low, high, unit, factor = LIMITS[dimension]
    low = low if smallest else 0.0
    shown = shown or f"{value!r}"
    if not math.isfinite(value):
        raise UnitError(
            f'{shown} is not a finite number; give a value such as "{_EXAMPLES[dimension]}"'
        )
    if value and not low <= abs(value) <= high:
        raise UnitError(
            f"{shown} is outside the {_plural(dimension)} balance accepts: "
            f"{low / factor:g} to {high / factor:g} {unit}"
        )


def rad_s_to_rpm(speed_rad_s):
    """Angular speed, rad/s -> rev/min."""
    return speed_rad_s / _RPM


def m_to_mm(length_m):
    return length_m * 1e3


def kg_to_g(mass_kg):
    return mass_kg * 1e3


def n_to_kgf(force_n):
    """Newtons (or N·m) -> kilogram-force (or kgf·m), with standard gravity."""
    return force_n / STANDARD_GRAVITY


def wrap_degrees(angle_deg, period=360.0, tolerance=None):
    """``angle_deg`` in [0, ``period``): the one normalisation of angles in balance.

    An angle within ``tolerance`` (default ``ANGLE_TOLERANCE_DEG``)
    below a full period is rounding noise of 0 and comes out as exactly 0.
    """
    tolerance = ANGLE_TOLERANCE_DEG if tolerance is None else tolerance
    wrapped = float(angle_deg) % period
    return 0.0 if wrapped >= period - tolerance else wrapped


def round_degrees(angle_deg, digits, period=360.0):
    """``angle_deg`` rounded for display and kept in [0, ``period``): 359.996 shown with two
    digits is 0.00, not 360.00."""
    return wrap_degrees(round(angle_deg, digits), period, tolerance=0.5 * 10.0**-digits)


def phasor_deg(phasor):
    """Direction of a complex phasor from the reference axis, positive with rotation, in
    [0, 360); 0 for a zero phasor."""
    return wrap_degrees(math.degrees(math.atan2(phasor.imag, phasor.real))) if phasor else 0.0


def angle_change(before_deg, after_deg, period=360.0):
    """The signed turn from one angle to another, the short way round: in [−period/2, period/2)."""
    return (after_deg - before_deg + period / 2) % period - period / 2


def pa_to_bar(pressure_pa):
    return pressure_pa / _BAR
