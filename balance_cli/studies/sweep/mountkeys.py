"""The keys of a configuration's [mounts] table a sweep can vary.

They are written as the configuration's messages name them: ``mounts.mass``,
``mounts.centre_of_gravity[3]`` (an item of a list, numbered from 1), and a mount's own keys
``mounts.mount[2].stiffness[3]`` (the second [[mounts.mount]] table's rate along z). A mount
may be named by its ``name`` instead of its number, ``mounts.mount[A].stiffness[3]``, and
``mounts.mount[*].stiffness[3]`` sets one value into every mount (four identical mounts kept
alike). Each value is set in the parsed TOML, and the engine built and checked as a file is.
"""

import re

from ...errors import SweepError
from .derived import Derived

__all__ = ["MOUNT_SCHEMA", "MOUNT_TABLE_SCHEMA", "mount_parameter", "mount_keys_hint"]

_NUMBER = "number"
#: the [mounts] table's numeric keys, with their kind; a list's items as ``key[]``
MOUNT_TABLE_SCHEMA = {
    "mass": "mass",
    "loss_factor": _NUMBER,
    "centre_of_gravity[]": "length",
    "inertia[]": "moment of inertia",
    "products[]": "moment of inertia",
}
#: a [[mounts.mount]] table's numeric keys; ``shear`` and ``damping`` may be one value or a
#: list
MOUNT_SCHEMA = {
    "position[]": "length",
    "stiffness[]": "stiffness",
    "compression": "stiffness",
    "shear": "stiffness",
    "shear[]": "stiffness",
    "axis[]": _NUMBER,
    "shear_axis[]": _NUMBER,
    "loss_factor": _NUMBER,
    "damping": "viscous damping",
    "damping[]": "viscous damping",
}
#: keys of text, never swept
_TEXT = {"name", "products_convention", "rotation"}
_TABLE_KEY = re.compile(r"^mounts\.([a-z_]+)(?:\[(\d+)\])?$")
_MOUNT_KEY = re.compile(r"^mounts\.mount\[([^\]]+)\]\.([a-z_]+)(?:\[(\d+)\])?$")


def _refused(text, problem):
    return SweepError(f"{text!r}: {problem}", "parameter")


def _item(text, table, key, index, kinds, where):
    """(kind, path within ``table``, file value) of ``key`` (with ``index``, 1-based, or
    None) in ``table``, checked against what ``table`` holds."""
    listed = key + "[]"
    if index is None and key not in kinds:
        if listed in kinds:
            raise _refused(
                text, f"{key} is a list; name one of its values, such as {key}[1] (from 1)"
            )
        raise _refused(text, f"{where} has no key {key} to vary ({_known(kinds)})")
    if index is not None and listed not in kinds:
        raise _refused(text, f"{key} is one value, not a list: write it without [{index}]")
    present = table.get(key)
    if index is None:
        if isinstance(present, list):
            raise _refused(
                text,
                f"{where} gives {key} as a list of {len(present)}; name one of its values, "
                f"such as {key}[1]",
            )
        return kinds[key], (key,), present
    if present is None:
        raise _refused(text, f"{where} has no {key}")
    if not isinstance(present, list):
        hint = f"; vary {key} itself" if key in kinds else ""
        raise _refused(text, f"{where} gives {key} as one value, not a list{hint}")
    if not 1 <= index <= len(present):
        raise _refused(text, f"{where}'s {key} has {len(present)} values, numbered from 1")
    return kinds[listed], (key, index - 1), present[index - 1]


def _known(kinds):
    return "it has " + ", ".join(k.replace("[]", "[k]") for k in kinds)


def _mounts_of(data):
    table = data.get("mounts")
    rows = table.get("mount") if isinstance(table, dict) else None
    return [row if isinstance(row, dict) else {} for row in rows] if isinstance(rows, list) else []


def _which(text, token, rows, path):
    """The 0-based numbers of the mounts ``token`` names: a number, a name, or ``*``."""
    if token == "*":
        return list(range(len(rows)))
    names = [str(row.get("name", i)) for i, row in enumerate(rows, 1)]
    if token.isdigit():
        number = int(token)
        if not 1 <= number <= len(rows):
            raise _refused(text, f"{path} has {len(rows)} [[mounts.mount]] tables, numbered from 1")
        return [number - 1]
    if token in names:
        return [names.index(token)]
    raise _refused(
        text,
        f"{path} has no mount named {token!r}; its mounts are "
        + ", ".join(f"[{i}] {n}" for i, n in enumerate(names, 1))
        + " (name one by number or name, or [*] for every mount)",
    )


def _setter(paths):
    def apply(data, value, path):
        for steps in paths:
            place = data
            for step in steps[:-1]:
                place = place[step]
            place[steps[-1]] = value

    return apply


def _canonical(number, key, index):
    return f"mounts.mount[{number}].{key}" + ("" if index is None else f"[{index}]")


def mount_parameter(data, text, path):
    """(kind, path in the parsed TOML, the file's value, Derived or None): what
    :class:`~.keys.Parameter` holds of a [mounts] key ``text`` (written as above) in the
    parsed configuration ``data``. A key naming its mount by number has a path; by name or
    ``[*]``, a :class:`~.derived.Derived` that sets it (and says which keys it sets).

    Raises
    ------
    SweepError
        no [mounts] table, an unknown key, a key of text, a list named without its item (or
        an item of a single value), a mount or an item that is not there (``parameter``)
    """
    table = data.get("mounts")
    if not isinstance(table, dict):
        raise _refused(text, f"{path} has no [mounts] table; add one to vary its keys")
    match = _MOUNT_KEY.match(text)
    if match is None:
        match = _TABLE_KEY.match(text)
        if match is None:
            raise _refused(
                text,
                "not a [mounts] key (write it as the messages name it: mounts.mass, "
                "mounts.centre_of_gravity[3], mounts.mount[1].stiffness[3], "
                "mounts.mount[A].compression, mounts.mount[*].stiffness[3])",
            )
        key, index = match.group(1), match.group(2)
        if key == "mount":
            raise _refused(
                text,
                "name a mount's key, such as mounts.mount[1].stiffness[3] (by number, by "
                "name, or [*] for every mount)",
            )
        if key in _TEXT:
            raise _refused(text, "holds text, not a number to vary")
        kind, steps, value = _item(
            text, table, key, None if index is None else int(index), MOUNT_TABLE_SCHEMA, "[mounts]"
        )
        return kind, ("mounts", *steps), value, None
    token, key, index = match.group(1).strip(), match.group(2), match.group(3)
    index = None if index is None else int(index)
    if key in _TEXT:
        raise _refused(text, "holds text, not a number to vary")
    rows = _mounts_of(data)
    chosen = _which(text, token, rows, path)
    found = []
    for i in chosen:
        where = f"mounts.mount[{i + 1}]"
        if "name" in rows[i]:
            where += f" ({rows[i]['name']})"
        found.append((i, _item(text, rows[i], key, index, MOUNT_SCHEMA, where)))
    kind = found[0][1][0]
    paths = tuple(("mounts", "mount", i, *steps) for i, (_, steps, _) in found)
    if token.isdigit():
        return kind, paths[0], found[0][1][2], None
    values = {repr(value) for _, (_, _, value) in found}
    # by name or for every mount: the keys it sets, by number, for the sweep's checks of two
    # parameters setting one key
    changes = tuple(_canonical(i + 1, key, index) for i, _ in found)
    shown = key if index is None else f"{key}[{index}]"
    meaning = (
        f"{shown} of every mount (mounts.mount[1] to [{len(rows)}]), one value for all"
        if token == "*"
        else f"{shown} of the mount named {token} ({changes[0]})"
    )
    derived = Derived(
        text,
        kind,
        changes,
        (),
        meaning,
        lambda data, path: None,
        _setter(paths),
    )
    file_value = found[0][1][2] if len(values) == 1 else None
    return kind, (), file_value, derived


def mount_keys_hint(data) -> str:
    """What the [mounts] table of ``data`` lets a sweep vary, for a message ("" without one)."""
    table = data.get("mounts")
    if not isinstance(table, dict):
        return ""
    rows = _mounts_of(data)
    return (
        f", the [mounts] keys (mounts.mass, mounts.centre_of_gravity[3], "
        f"mounts.mount[1] to [{len(rows)}] or [*] with stiffness[k], compression, shear, "
        "position[k], loss_factor, damping)"
    )
