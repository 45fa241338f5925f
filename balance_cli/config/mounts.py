"""The [mounts] table: the powertrain as a rigid body (mass, centre of gravity, inertia tensor)
and its [[mounts.mount]] tables, each a point spring with three principal rates (see
:mod:`balance_cli.model.mounts` for the axes and conventions)."""

from ..errors import ConfigError, ModelError
from ..model import PRODUCT_CONVENTIONS, ROTATIONS, Mount, MountSystem, inertia_matrix
from .reader import MOUNT_KEYS, MOUNTS_KEYS, Reader

__all__ = ["read_mounts"]

#: Mount's fields -> the [[mounts.mount]] key, for the model's messages
_MOUNT_KEYS = {
    "name": "name",
    "position_m": "position",
    "loss_factor": "loss_factor",
    "damping_ns_m": "damping",
    "axis": "axis",
    "shear_axis": "shear_axis",
    "shear_n_m": "shear",
}


def _items(reader, key, count, read, counts=None):
    """A list of exactly ``count`` values (or, with ``counts``, any of those lengths; a plain
    value for a count of 1), each read by ``read(item_reader, item_key)`` so that a message
    names the item (``position[3]``)."""
    raw = reader.table.get(key)
    allowed = counts or (count,)
    if not isinstance(raw, list):
        if 1 in allowed:
            return (read(reader, key),)
        raise reader.error(key, f"expected a list of {count} values (x, y, z), got {raw!r}")
    if len(raw) not in allowed:
        wanted = " or ".join(str(n) for n in allowed if n > 1)
        raise reader.error(key, f"has {len(raw)} values but needs {wanted}")
    out = []
    for i, value in enumerate(raw, 1):
        name = f"{key}[{i}]"
        out.append(read(Reader(reader.path, {name: value}, reader.prefix, {name}), name))
    return tuple(out)


def _quantities(reader, key, dimension, sign="any", counts=None):
    return _items(reader, key, 3, lambda r, k: r.quantity(k, dimension, sign=sign), counts=counts)


def _direction(reader, key):
    values = _items(reader, key, 3, lambda r, k: r.real(k, what="a number"))
    if not any(values):
        raise reader.error(key, "must not be [0, 0, 0]: give the direction it points along")
    return values


def _mount(path, table, number, default_loss):
    r = Reader(path, table, f"mounts.mount[{number}].", MOUNT_KEYS)
    name = r.string("name", required=False, default=str(number))
    if not r.has("position"):
        raise r.error("position", 'missing; give ["x", "y", "z"] from the centre of gravity')
    position = _quantities(r, "position", "length")
    if r.has("stiffness") == (r.has("compression") or r.has("shear")):
        raise r.error(
            "stiffness",
            "give stiffness (three rates along x, y, z) or compression and shear (with "
            "axis), one of the two"
            if r.has("stiffness")
            else "missing; give stiffness = [kx, ky, kz] (along the engine's axes) or "
            "compression and shear with axis",
        )
    damping = {
        "loss_factor": r.real("loss_factor", required=False, default=default_loss, low=0, high=2),
        "damping_ns_m": (0.0, 0.0, 0.0),
    }
    if r.has("damping"):
        values = _quantities(r, "damping", "viscous damping", "non-negative", counts=(1, 3))
        damping["damping_ns_m"] = values * 3 if len(values) == 1 else values
    try:
        if r.has("stiffness"):
            for key in ("axis", "shear_axis"):
                if r.has(key):
                    raise r.error(
                        key, "belongs to compression and shear; stiffness acts along x, y, z"
                    )
            return Mount.aligned(
                name, position, _quantities(r, "stiffness", "stiffness", "positive"), **damping
            )
        for key in ("compression", "shear", "axis"):
            if not r.has(key):
                raise r.error(key, "missing; compression, shear and axis go together")
        return Mount.oriented(
            name,
            position,
            r.quantity("compression", "stiffness"),
            _quantities(r, "shear", "stiffness", "positive", counts=(1, 2)),
            _direction(r, "axis"),
            _direction(r, "shear_axis") if r.has("shear_axis") else None,
            **damping,
        )
    except ModelError as exc:
        raise r.error(_MOUNT_KEYS.get(exc.parameter or "", ""), exc.problem) from None


def read_mounts(path, data) -> MountSystem:
    """The [mounts] table of ``data`` (its parsed TOML) as a :class:`MountSystem`, naming the
    file ``path`` and the key in every error."""
    r = Reader(path, data, "mounts.", MOUNTS_KEYS)
    mass = r.quantity("mass", "mass")
    cg = (
        _quantities(r, "centre_of_gravity", "length")
        if r.has("centre_of_gravity")
        else (0.0, 0.0, 0.0)
    )
    if not r.has("inertia"):
        raise r.error(
            "inertia",
            "missing; give the moments of inertia about the centre of gravity, "
            '["Jxx", "Jyy", "Jzz"] such as ["8 kg*m^2", "12 kg*m^2", "10 kg*m^2"]',
        )
    moments = _quantities(r, "inertia", "moment of inertia", "positive")
    products = (
        _quantities(r, "products", "moment of inertia") if r.has("products") else (0.0, 0.0, 0.0)
    )
    convention = r.string(
        "products_convention", required=False, default="tensor", choices=PRODUCT_CONVENTIONS
    )
    rotation = r.string("rotation", required=False, default="clockwise", choices=ROTATIONS)
    loss = r.real("loss_factor", required=False, default=0.0, low=0, high=2)
    mounts = tuple(_mount(path, table, i, loss) for i, table in enumerate(r.tables("mount"), 1))
    try:
        return MountSystem(
            mass,
            inertia_matrix(moments, products, convention),
            mounts,
            cg,
            rotation,
        )
    except ModelError as exc:
        key, problem = {
            "inertia_kgm2": (
                "products" if r.has("products") else "inertia",
                f"the inertia tensor {exc.problem}",
            ),
            "mounts": ("mount", f"the mounts {exc.problem}"),
        }.get(exc.parameter or "", ("", str(exc)))
        raise ConfigError(path, f"mounts.{key}" if key else "mounts", problem) from None
