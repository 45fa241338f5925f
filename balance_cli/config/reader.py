"""Reading a configuration's text: the file as UTF-8, its TOML parsed, and each table's values
read with their types, units, ranges and signs by a :class:`Reader` that knows the table's
keys (an unknown key is an error) and names the key in every message."""

import math
import re
import tomllib
from pathlib import Path

from ..errors import ConfigError, UnitError
from ..units import parse_quantity

__all__ = [
    "Reader",
    "read_text",
    "parse_text",
    "TOP_KEYS",
    "MASS_KEYS",
    "PART_KEYS",
    "GAS_KEYS",
    "TORSION_KEYS",
    "DISK_KEYS",
    "MOUNTS_KEYS",
    "MOUNT_KEYS",
    "BANK_KEYS",
    "THROW_KEYS",
    "TOLERANCE_KEYS",
    "CRANKSHAFT_KEYS",
    "LINK_KEYS",
    "COUNTERWEIGHT_KEYS",
    "SHAFT_KEYS",
    "SHAFT_MASS_KEYS",
    "CYLINDER_KEYS",
]

#: the keys each table of the format may have: any other is an error
TOP_KEYS = {
    "name",
    "source",
    "sources",
    "estimates",
    "cycle",
    "speed",
    "crank_radius",
    "rod_length",
    "pin_offset",
    "frame",
    "firing_order",
    "vertical",
    "power",
    "masses",
    "parts",
    "gas",
    "banks",
    "throws",
    "links",
    "cylinders",
    "crankshafts",
    "counterweights",
    "shafts",
    "torsion",
    "mounts",
    "tolerances",
}
MASS_KEYS = {"reciprocating", "rotating", "knuckle", "crank"}
PART_KEYS = {
    "piston",
    "rod_mass",
    "rod_cg",
    "rod_inertia",
    "link_mass",
    "link_cg",
    "link_inertia",
    "crank",
    "crankshaft_inertia",
    "flywheel_inertia",
}
GAS_KEYS = {
    "bore",
    "compression_ratio",
    "imep",
    "intake_pressure",
    "crankcase_pressure",
    "polytropic_exponent",
    "combustion_start",
    "combustion_duration",
    "wiebe_a",
    "wiebe_m",
}
TORSION_KEYS = {
    "throw_inertia",
    "web_inertia",
    "stiffness",
    "throw_damping",
    "loss_factor",
    "shaft_diameter",
    "shaft_bore",
    "front",
    "flywheel",
    "load",
}
DISK_KEYS = {"name", "inertia", "stiffness", "damping"}
MOUNTS_KEYS = {
    "mass",
    "centre_of_gravity",
    "inertia",
    "products",
    "products_convention",
    "rotation",
    "loss_factor",
    "mount",
}
MOUNT_KEYS = {
    "name",
    "position",
    "stiffness",
    "compression",
    "shear",
    "axis",
    "shear_axis",
    "loss_factor",
    "damping",
}
BANK_KEYS = {"angle", "pin_offset"}
THROW_KEYS = {"phase", "z", "crankshaft", "rotating"}
#: [tolerances]: one standard deviation of each part's and dimension's scatter
TOLERANCE_KEYS = {
    "reciprocating",
    "rotating",
    "crank_radius",
    "rod_length",
    "phase",
    "bank_angle",
    "pin_offset",
}
CRANKSHAFT_KEYS = {"x", "y", "direction", "phase"}
LINK_KEYS = {"master_bank", "length", "knuckle_radius"}
COUNTERWEIGHT_KEYS = {"throw", "mass", "radius", "mass_radius", "angle", "z"}
SHAFT_KEYS = {"ratio", "lateral", "vertical", "masses"}
SHAFT_MASS_KEYS = {"mass", "eccentricity", "mass_radius", "angle", "z"}
CYLINDER_KEYS = {
    "number",
    "bank",
    "throw",
    "z",
    "reciprocating",
    "master",
    "link_length",
    "knuckle_radius",
    "knuckle_angle",
    "pin_offset",
    "opposed_throw",
    "opposed_reciprocating",
}
#: angles are plain numbers of degrees within one turn either way
_ANGLE_LIMIT_DEG = 360.0


class Reader:
    """Typed access to one TOML table, raising ConfigError with the key's full name."""

    def __init__(self, path, table, prefix, allowed):
        self.path, self.table, self.prefix = path, table, prefix
        if not isinstance(table, dict):
            raise ConfigError(path, prefix.rstrip("."), "expected a table")
        for key in table:
            if key not in allowed:
                known = ", ".join(sorted(allowed))
                raise ConfigError(
                    path, prefix + key, f"unknown key; check the spelling (known keys: {known})"
                )

    def error(self, key, problem):
        return ConfigError(self.path, self.prefix + key, problem)

    def has(self, key):
        return key in self.table

    def _get(self, key, required):
        if key not in self.table:
            if required:
                raise self.error(key, "missing; this key is required")
            return None
        return self.table[key]

    def quantity(self, key, dimension, required=True, default=None, sign="positive"):
        """A value with a unit, in SI; ``sign`` "positive", "non-negative" or "any"."""
        raw = self._get(key, required)
        if raw is None:
            return default
        try:
            value = parse_quantity(raw, dimension)
        except UnitError as exc:
            raise self.error(key, str(exc)) from None
        if sign == "positive" and value <= 0.0:
            raise self.error(key, f"must be greater than zero, got {raw!r}")
        if sign == "non-negative" and value < 0.0:
            raise self.error(key, f"must not be negative, got {raw!r}")
        return value + 0.0  # -0 reads as 0

    def degrees(self, key, required=True):
        raw = self._get(key, required)
        if raw is None:
            return None
        if isinstance(raw, bool) or not isinstance(raw, (int, float)) or not math.isfinite(raw):
            raise self.error(key, f"expected a number of degrees such as 40 or -22.5, got {raw!r}")
        if abs(raw) > _ANGLE_LIMIT_DEG:
            raise self.error(
                key,
                f"must be between -{_ANGLE_LIMIT_DEG:g} and "
                f"{_ANGLE_LIMIT_DEG:g} degrees, got {raw!r}",
            )
        return float(raw) + 0.0  # -0 reads as 0

    def real(self, key, required=True, default=None, low=None, high=None, what="a number"):
        """A plain number (no unit) from ``low`` to ``high``."""
        raw = self._get(key, required)
        if raw is None:
            return default
        if isinstance(raw, bool) or not isinstance(raw, (int, float)) or not math.isfinite(raw):
            raise self.error(key, f"expected {what} such as {low if low else 1}, got {raw!r}")
        if low is not None and raw < low or high is not None and raw > high:
            raise self.error(key, f"must be from {low:g} to {high:g}, got {raw!r}")
        return float(raw) + 0.0

    def integer(self, key, required=True, default=None, low=None, high=None):
        raw = self._get(key, required)
        if raw is None:
            return default
        if isinstance(raw, bool) or not isinstance(raw, int):
            raise self.error(key, f"expected a whole number, got {raw!r}")
        if low is not None and raw < low or high is not None and raw > high:
            raise self.error(key, f"must be between {low} and {high}, got {raw}")
        return raw

    def string(self, key, required=True, default=None, choices=None):
        raw = self._get(key, required)
        if raw is None:
            return default
        if not isinstance(raw, str) or not raw.strip():
            raise self.error(key, f"expected a non-empty string, got {raw!r}")
        if not raw.isprintable():
            raise self.error(key, f"must be one line of printable text, got {raw!r}")
        if choices and raw not in choices:
            options = " or ".join(f'"{c}"' for c in choices)
            raise self.error(key, f"must be {options}, got {raw!r}")
        return raw

    def tables(self, key, required=True):
        raw = self._get(key, required)
        if raw is None:
            return []
        if not isinstance(raw, list) or not raw or not all(isinstance(t, dict) for t in raw):
            table = re.sub(r"\[\d+\]", "", self.prefix + key)  # shafts[2].masses: [[shafts.masses]]
            raise self.error(key, f"expected one or more [[{table}]] tables")
        return raw


def read_text(path: Path) -> str:
    try:
        # a FIFO or a device would block or never end: only regular files are configurations
        if path.exists() and not path.is_file() and not path.is_dir():
            raise ConfigError(path, "", "is not a regular file; give a .toml file")
        data = path.read_bytes()
    except FileNotFoundError:
        raise ConfigError(path, "", "no such file; check the path") from None
    except IsADirectoryError:
        raise ConfigError(
            path, "", "is a folder; give a .toml file (or the folder where a command takes folders)"
        ) from None
    except PermissionError as exc:
        raise ConfigError(
            path, "", f"cannot read the file ({exc.strerror}); check its permissions"
        ) from None
    except OSError as exc:
        raise ConfigError(path, "", f"cannot read the file ({exc.strerror or exc})") from None
    try:
        # a byte-order mark (some Windows editors write one) was refused as "Invalid
        # statement (line 1, column 1)"; CSV files already accepted it
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise ConfigError(
            path, "", f"not UTF-8 text ({exc.reason} at byte {exc.start}); save it as UTF-8"
        ) from None
    return text


def parse_text(text, name):
    if not isinstance(text, str):
        error = ConfigError(name, "", f"text must be a str of TOML, got {type(text).__name__}")
        error.parameter = "text"
        raise error
    try:
        return tomllib.loads(text.removeprefix("\ufeff"))
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(name, "", f"not valid TOML: {exc}; fix the syntax there") from None
