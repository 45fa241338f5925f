"""Writing configurations: a search template with its throws' phases and firing order, a
configuration with counterweights and shafts as built, as TOML text."""

from collections.abc import Iterable

__all__ = ["arrangement_toml", "as_built_toml"]


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


def as_built_toml(data: dict, tables: dict, header: str = "") -> str:
    """A complete configuration: the parsed ``data`` of one (``read_configuration(path).data``)
    with the rows of ``tables`` (``{"counterweights": [...], "shafts": [...]}``, in the file's
    keys, as :meth:`balance_cli.analysis.balancing.Balance.configuration_tables` gives them) added
    after its own ``[[counterweights]]`` and ``[[shafts]]``; ``header`` becomes comment lines at
    the top. The file's comments are not kept (TOML readers drop them)."""
    data = dict(data)
    for key, rows in tables.items():
        if rows:
            data[key] = list(data.get(key, [])) + list(rows)
    return _dump(data, header)


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
