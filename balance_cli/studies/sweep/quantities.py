"""What a sweep reports at each point: forces and moments order by order with their parts,
the largest resultant force and free moment, torques and steadiness."""

import re
from dataclasses import dataclass

from ...analysis.shaking import DEFAULT_MAX_ORDER
from ...errors import SweepError
from .mountquantities import MOUNT_QUANTITY_NAMES, mount_quantity

__all__ = ["Quantity", "quantities_of", "QUANTITY_NAMES", "DEFAULT_QUANTITIES"]


@dataclass(frozen=True)
class Quantity:
    """One quantity a sweep reports at every point.

    ``name`` as asked for (``F2V``, ``largest_moment``, ``mode_1``), ``column`` its key in the
    records (the name and the SI unit: ``F2V_N``, ``mode_1_Hz``), ``unit`` "N", "Nm", "Hz",
    "%", "deg" or "" and ``kind`` "force", "moment", "torque", "steadiness", "pru", or of the
    engine on its mounts "frequency", "decoupling", "axes angle" or "mount force"
    (:mod:`.mountquantities`); ``mount`` the mount a "mount force" is of, as named.
    """

    name: str
    column: str
    unit: str
    kind: str
    meaning: str
    order: int | None = None
    part: str | None = None
    mount: str | None = None

    def to_dict(self) -> dict:
        return {
            "name": self.name,
            "column": self.column,
            "unit": self.unit,
            "kind": self.kind,
            "meaning": self.meaning,
        }


_PARTS = {
    "": ("max", "largest over a revolution (the ellipse's semi-major axis)"),
    "V": ("vertical", "vertical component's amplitude"),
    "H": ("horizontal", "horizontal component's amplitude"),
    "+": ("forward", "forward part (turns with the crank)"),
    "-": ("backward", "backward part (turns against the crank)"),
}
_MOMENT_WORDS = {
    "V": "pitching (moment of the vertical forces), amplitude",
    "H": "yawing (moment of the horizontal forces), amplitude",
}
_NAMED = {
    "largest_force": (
        "N",
        "force",
        "largest resultant force over a revolution, all orders, after an ideal counterweight",
    ),
    "largest_moment": (
        "Nm",
        "moment",
        "largest free moment over a revolution, all orders, after an ideal two-plane counterweight",
    ),
    "torque_mean": ("Nm", "torque", "mean of the total torque (gas and inertia) at constant speed"),
    "torque_max": ("Nm", "torque", "largest total torque over the cycle"),
    "torque_min": ("Nm", "torque", "smallest total torque over the cycle"),
    "torque_range": ("Nm", "torque", "range ΔC of the total torque over the cycle"),
    "steadiness": ("", "steadiness", "steadiness ω_m/(ω_max − ω_min) with the inertia given"),
}
#: what ``quantities`` may name, for messages and help texts
QUANTITY_NAMES = (
    (
        "F<k>",
        "F<k>V",
        "F<k>H",
        "F<k>+",
        "F<k>-",
        "M<k>",
        "M<k>V",
        "M<k>H",
        "M<k>+",
        "M<k>-",
        "PRU<k>V",
        "PRU<k>H",
    )
    + tuple(_NAMED)
    + MOUNT_QUANTITY_NAMES
)
DEFAULT_QUANTITIES = ("largest_force", "largest_moment")
_ORDER_QUANTITY = re.compile(r"^([FM])(\d+)(V|H|\+|-)?$", re.IGNORECASE)
_PRU_QUANTITY = re.compile(r"^PRU(\d+)(V|H)$", re.IGNORECASE)


def quantities_of(names, max_order: int = DEFAULT_MAX_ORDER) -> tuple:
    """The :class:`Quantity` list for ``names`` (a sequence, or one string "F2,M1V"); None or
    empty gives :data:`DEFAULT_QUANTITIES`.

    Raises
    ------
    SweepError
        an unknown name, an order above ``max_order``, or a name given twice (``quantities``)
    """
    if names is None:
        names = DEFAULT_QUANTITIES
    if isinstance(names, str):
        names = [n.strip() for n in names.split(",")]
    if not isinstance(names, (list, tuple)):
        raise SweepError(
            f'must be quantity names (a list, or one string such as "F2,M1V"), got {names!r}',
            "quantities",
        )
    names = list(names)
    if not names:
        names = list(DEFAULT_QUANTITIES)
    out = []
    for raw in names:
        if not isinstance(raw, str) or not raw.strip():
            raise SweepError(
                f"holds {raw!r}: give quantity names such as F2, M1V or largest_force", "quantities"
            )
        name = raw.strip()
        match = _ORDER_QUANTITY.match(name)
        if match:
            letter, order, part = (
                match.group(1).upper(),
                int(match.group(2)),
                (match.group(3) or "").upper(),
            )
            if not 1 <= order <= max_order:
                raise SweepError(
                    f"names {name!r}, order {order}, outside the orders analysed "
                    f"(1 to {max_order}); analyse more orders or ask for a lower "
                    "one",
                    "quantities",
                )
            key, words = _PARTS[part]
            what = "force" if letter == "F" else "moment"
            if letter == "M" and part in _MOMENT_WORDS:
                words = _MOMENT_WORDS[part]
            unit = "N" if letter == "F" else "Nm"
            canonical = f"{letter}{order}{part}"
            out.append(
                Quantity(
                    canonical,
                    f"{canonical}_{unit}",
                    unit,
                    what,
                    f"order-{order} free {what}, {words}",
                    order,
                    key,
                )
            )
            continue
        match = _PRU_QUANTITY.match(name)
        if match:
            order, part = int(match.group(1)), match.group(2).upper()
            if not 1 <= order <= max_order:
                raise SweepError(
                    f"names {name!r}, order {order}, outside the orders analysed "
                    f"(1 to {max_order})",
                    "quantities",
                )
            side = "vertical" if part == "V" else "horizontal"
            out.append(
                Quantity(
                    f"PRU{order}{part}",
                    f"PRU{order}{part}_Nm_per_kW",
                    "",
                    "pru",
                    f"power related unbalance of the order-{order} "
                    f"{'pitching' if part == 'V' else 'yawing'} moment, N·m/kW",
                    order,
                    side,
                )
            )
            continue
        lowered = name.lower()
        if lowered in _NAMED:
            unit, kind, meaning = _NAMED[lowered]
            out.append(
                Quantity(lowered, f"{lowered}_{unit}" if unit else lowered, unit, kind, meaning)
            )
            continue
        of_mounts = mount_quantity(name, Quantity)
        if of_mounts is not None:
            out.append(of_mounts)
            continue
        raise SweepError(
            f"names {name!r}, which is not a quantity; give F<k> or M<k> (order k: "
            "the largest force or moment of that order) with V, H, + or - for the "
            "vertical, horizontal, forward or backward part (F2V, M1H, F1+), "
            f"one of {', '.join(_NAMED)}, or of the engine on its mounts mode_1 to mode_6, "
            "roll_mode (fore_aft, lateral, bounce, roll, pitch, yaw), tra_purity, axes_angle, "
            "mount_<m>_force or mount_<m>_Fz (a mount's name or number)",
            "quantities",
        )
    columns = [q.column for q in out]
    twice = next((c for c in columns if columns.count(c) > 1), None)
    if twice is not None:
        raise SweepError(
            f"names {twice.rsplit('_', 1)[0]!r} twice; give each quantity once", "quantities"
        )
    return tuple(out)
