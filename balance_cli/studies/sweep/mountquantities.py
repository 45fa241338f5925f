"""What a sweep reports of the engine on its mounts: the six natural frequencies, the frequency
of the mode each motion dominates, the torque roll axis decoupling, and the force each mount
passes on to the frame, from :func:`balance_cli.mounts` at every point.

A mount's force is the largest size of its force vector (or of one component) over a cycle,
every order up to the sweep's ``max_order`` summed — at the point's own speed, or the largest
over ``mount_speeds_rpm`` when those are given — exactly as ``balance mounts --max-order``
reports it.
"""

import re

import numpy as np

from ...errors import SweepError
from ...model import MOTIONS

__all__ = [
    "MOUNT_QUANTITY_NAMES",
    "mount_quantity",
    "check_mount_quantities",
    "measure_mounts",
    "MOUNT_KINDS",
]

#: the kinds of quantity read from the mount analysis
MOUNT_KINDS = ("frequency", "decoupling", "axes angle", "mount force")
#: the motions as quantity names spell them (fore_aft_mode)
_MOTION_WORDS = tuple(m.replace("-", "_") for m in MOTIONS)
#: what ``quantities`` may name, for messages and help texts
MOUNT_QUANTITY_NAMES = (
    "mode_<n>",
    "<motion>_mode",
    "tra_purity",
    "axes_angle",
    "mount_<m>_force",
    "mount_<m>_F<x|y|z>",
)
_MODE = re.compile(r"^mode_([1-6])(?:_Hz)?$", re.IGNORECASE)
_MOTION_MODE = re.compile(rf"^({'|'.join(_MOTION_WORDS)})_mode(?:_Hz)?$", re.IGNORECASE)
_MOUNT = re.compile(r"^mount_(.+?)_(force|F[xyz])(?:_N)?$")
_COMPONENTS = {"Fx": 0, "Fy": 1, "Fz": 2}


def mount_quantity(name, quantity_class):
    """The Quantity ``name`` asks for if it is one of the mount analysis's, else None."""
    match = _MODE.match(name)
    if match:
        n = int(match.group(1))
        return quantity_class(
            f"mode_{n}",
            f"mode_{n}_Hz",
            "Hz",
            "frequency",
            f"natural frequency of the engine's rigid-body mode {n} on its mounts (1 the "
            "lowest), Hz",
            part=str(n),
        )
    match = _MOTION_MODE.match(name)
    if match:
        word = match.group(1).lower()
        return quantity_class(
            f"{word}_mode",
            f"{word}_mode_Hz",
            "Hz",
            "frequency",
            f"natural frequency of the mode in which {word.replace('_', '-')} has its largest "
            "share of the kinetic energy, Hz",
            part=MOTIONS[_MOTION_WORDS.index(word)],
        )
    lowered = name.lower()
    if lowered in ("tra_purity", "tra_purity_pct"):
        return quantity_class(
            "tra_purity",
            "tra_purity_pct",
            "%",
            "decoupling",
            "torque roll axis decoupling purity: the share of the kinetic energy of the mode "
            "nearest the turn about the torque roll axis in that turn, %",
        )
    if lowered in ("axes_angle", "axes_angle_deg"):
        return quantity_class(
            "axes_angle",
            "axes_angle_deg",
            "deg",
            "axes angle",
            "angle between the torque roll axis and the elastic axis of the crank's torque, "
            "degrees",
        )
    match = _MOUNT.match(name)
    if match:
        mount, part = match.group(1), match.group(2)
        what = "size of the force vector" if part == "force" else f"{part} component"
        return quantity_class(
            f"mount_{mount}_{part}",
            f"mount_{mount}_{part}_N",
            "N",
            "mount force",
            f"largest {what} mount {mount} passes on to the frame over a cycle, every order "
            "summed, N",
            part=part,
            mount=mount,
        )
    return None


def _spelled(name):
    """A mount's name as a quantity spells it: runs of anything but letters, digits and _
    as one _ ("front left" -> front_left)."""
    return re.sub(r"[^A-Za-z0-9_]+", "_", name).strip("_")


def _mount_index(quantity, names):
    token = quantity.mount
    if token in names:
        return names.index(token)
    spelled = [_spelled(n) for n in names]
    if token in spelled:
        return spelled.index(token)
    if token.isdigit() and 1 <= int(token) <= len(names):
        return int(token) - 1
    return None


def check_mount_quantities(engine, wanted, path):
    """Refuse mount quantities of an engine without [mounts], and mounts it does not have.

    Raises
    ------
    SweepError
        (``quantities``)
    """
    asked = [q for q in wanted if q.kind in MOUNT_KINDS]
    if not asked:
        return
    if engine.mounts is None:
        raise SweepError(
            f"{', '.join(q.name for q in asked)} need{'s' if len(asked) == 1 else ''} the "
            f"engine on its mounts, but {path} has no [mounts] table",
            "quantities",
        )
    names = list(engine.mounts.names)
    for q in asked:
        if q.kind == "mount force" and _mount_index(q, names) is None:
            raise SweepError(
                f"names {q.name!r}, but {path} has no mount {q.mount!r}; its mounts are "
                + ", ".join(f"{_spelled(n)} ({i})" for i, n in enumerate(names, 1))
                + " (by name, with _ for spaces, or by number)",
                "quantities",
            )


def measure_mounts(engine, wanted, samples, max_order, speeds_rpm):
    """Every mount quantity of ``wanted`` at one point, SI; the mount analysis runs only when
    a force is wanted."""
    from ...mounting import mounts, natural_modes, tra_state
    from ...units import rad_s_to_rpm

    system = engine.mounts
    modes = natural_modes(system)
    asked = [q for q in wanted if q.kind in MOUNT_KINDS]
    record = {}
    state = (
        tra_state(system) if any(q.kind in ("decoupling", "axes angle") for q in asked) else None
    )
    forces = None
    if any(q.kind == "mount force" for q in asked):
        speeds = [rad_s_to_rpm(engine.speed_rad_s)] if speeds_rpm is None else speeds_rpm
        result = mounts(engine, speeds_rpm=speeds, max_order=max_order, samples=samples)
        forces = result.response
    names = list(system.names)
    for q in asked:
        if q.kind == "frequency" and q.part.isdigit():
            record[q.column] = modes[int(q.part) - 1].frequency_hz
        elif q.kind == "frequency":
            share = [m.energy_pct[MOTIONS.index(q.part)] for m in modes]
            record[q.column] = modes[int(np.argmax(share))].frequency_hz
        elif q.kind == "decoupling":
            assert state is not None
            record[q.column] = state.purity_pct
        elif q.kind == "axes angle":
            assert state is not None
            record[q.column] = state.axes_angle_deg
        else:
            assert forces is not None
            m = _mount_index(q, names)
            if q.part == "force":
                record[q.column] = float(forces.force_magnitude_peak_n[:, m].max())
            else:
                record[q.column] = float(forces.force_peak_n[:, m, _COMPONENTS[q.part]].max())
    return record
