"""Writing configurations: a search template with its throws' phases and firing order, a
configuration with counterweights and shafts as built, as TOML text.

The numbers balance computes (a counterweight's mass, a shaft's offset) are written to
:data:`WRITE_DIGITS` significant digits, as the shortest decimal that reads back as that
rounded value: 0.22500000000000003 kg, the float sum of 650 g and −425 g, is written 0.225.
"""

import math
import re
from collections.abc import Iterable

from ..errors import ConfigError

__all__ = ["WRITE_DIGITS", "arrangement_toml", "as_built_toml"]

#: significant digits of a number balance computes and writes into a configuration: far
#: finer than any part is made (1e-12 of a counterweight's mass), coarse enough that the
#: float noise of the arithmetic (~1e-16) is not written
WRITE_DIGITS = 12
#: the tables :func:`as_built_toml` adds rows to
_AS_BUILT = ("counterweights", "shafts")
#: a value with a unit as the analysis writes it: a number, one space, the unit
_WITH_UNIT = re.compile(r"^([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?) (\S.*)$")


def arrangement_toml(
    template: dict,
    phases_deg: "Iterable[float]",
    firing_order: "Iterable[int] | None",
    name: str,
    header: str = "",
) -> str:
    """A complete configuration: the parsed ``template`` (see :func:`load_template`) with these
    throw phases (degrees, throw by throw), firing order (None: none, the most uniform one the
    crank allows is then found) and name; ``header`` becomes comment
    lines at the top. The template's comments are not kept (TOML readers drop them)."""
    data = dict(template)
    data["name"] = name
    phases = list(phases_deg)
    data["throws"] = [
        {"phase": p, **{k: v for k, v in t.items() if k != "phase"}}
        for t, p in zip(template["throws"], phases, strict=True)
    ]
    data.pop("firing_order", None)
    if firing_order is not None:
        data["firing_order"] = list(firing_order)
    return _dump(data, header)


def as_built_toml(data: dict, tables: dict, header: str = "", name: str | None = None) -> str:
    """A complete configuration: the parsed ``data`` of one (``read_configuration(path).data``)
    with the rows of ``tables`` (``{"counterweights": [...], "shafts": [...]}``, in the file's
    keys, as :meth:`balance_cli.analysis.balancing.Balance.configuration_tables` gives them) added
    after its own ``[[counterweights]]`` and ``[[shafts]]``, their numbers to
    :data:`WRITE_DIGITS` significant digits; ``header`` becomes comment lines at the top;
    ``name``, when given, is the new configuration's name (a file compared with the one it
    came from needs its own). The file's comments are not kept (TOML readers drop them).

    Raises
    ------
    ConfigError
        ``data`` not a dict, ``tables`` not a dict of lists of tables with keys among
        ``counterweights`` and ``shafts``, ``header`` not text, ``name`` not one line of text
    """
    if not isinstance(data, dict):
        _refuse("data", f"must be a configuration's parsed TOML (a dict), got {_kind(data)}")
    if not isinstance(tables, dict):
        _refuse(
            "tables",
            "must be a dict of rows to add, {'counterweights': [...], 'shafts': [...]} as "
            f"Balance.configuration_tables() gives it, got {_kind(tables)}",
        )
    for key, rows in tables.items():
        if key not in _AS_BUILT:
            _refuse("tables", f"has the key {key!r}; rows are added to {' and '.join(_AS_BUILT)}")
        if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
            _refuse("tables", f"[{key!r}] must be a list of tables (dicts), got {rows!r}")
    if not isinstance(header, str):
        _refuse("header", f"must be text, got {_kind(header)}")
    if name is not None and (
        not isinstance(name, str) or not name.strip() or not name.isprintable()
    ):
        _refuse("name", f"must be one line of printable text, got {name!r}")
    for parameter, value in (("data", data), ("tables", tables)):
        odd = _unwritable(value)
        if odd is not None:
            _refuse(
                parameter,
                f"holds {odd[0]!r}, which has no TOML form (give text, numbers, true or false, "
                "lists and tables with text keys)",
            )
    data = dict(data)
    if name is not None:
        data["name"] = name
    for key, rows in tables.items():
        if rows:
            data[key] = list(data.get(key, [])) + [_rounded(row) for row in rows]
    return _dump(data, header)


def _unwritable(value):
    """The first value (or key) inside ``value`` that TOML cannot hold, in a 1-tuple (so that a
    None inside shows), or None when every one has a TOML form."""
    if isinstance(value, dict):
        for key, item in value.items():
            odd = _unwritable(item) if isinstance(key, str) else (key,)
            if odd is not None:
                return odd
        return None
    if isinstance(value, list):
        return next((odd for odd in map(_unwritable, value) if odd is not None), None)
    return None if isinstance(value, (bool, int, float, str)) else (value,)


def _kind(value):
    return type(value).__name__


def _refuse(parameter, problem):
    error = ConfigError("<config>", "", f"{parameter} {problem}")
    error.parameter, error.problem = parameter, problem
    raise error


def _shortest(value: float) -> float:
    """``value`` rounded to :data:`WRITE_DIGITS` significant digits; repr() then writes the
    shortest decimal that reads back as it (and never −0.0)."""
    if not math.isfinite(value):
        return value
    return float(f"{value:.{WRITE_DIGITS}g}") + 0.0


def _rounded(value):
    """A row (or a value in one) with its computed numbers rounded by :func:`_shortest`: floats,
    and the number of a "<number> <unit>" string."""
    if isinstance(value, dict):
        return {k: _rounded(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_rounded(v) for v in value]
    if isinstance(value, float):
        return _shortest(value)
    if isinstance(value, str):
        match = _WITH_UNIT.match(value)
        if match:
            return f"{_shortest(float(match.group(1)))!r} {match.group(2)}"
    return value


def _is_tables(value):
    return isinstance(value, list) and value and all(isinstance(v, dict) for v in value)


def _dump(data, header=""):
    """TOML text of parsed configuration ``data``: plain keys first, then its tables and arrays
    of tables (``[[shafts]]`` with their ``[[shafts.masses]]``)."""
    lines = [f"# {line}".rstrip() for line in header.splitlines()]
    lines += _table_lines(data, "")
    return "\n".join(lines) + "\n"


def _table_lines(table, prefix):
    lines, tables = [], []
    for key, value in table.items():
        if isinstance(value, dict):
            tables.append((key, [value], False))
        elif _is_tables(value):
            tables.append((key, value, True))
        else:
            lines.append(f"{key} = {_toml_value(value)}")
    for key, rows, array in tables:
        name = prefix + key
        for row in rows:
            lines += ["", f"[[{name}]]" if array else f"[{name}]"]
            lines += _table_lines(row, name + ".")
    return lines


def _toml_value(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        escaped = value.replace("\\", "\\\\").replace('"', '\\"')
        return f'"{escaped}"'
    if isinstance(value, list):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    raise TypeError(f"no TOML form for {value!r}")
