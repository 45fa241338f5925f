"""The engine on its mounts: the powertrain as a rigid body on elastic mounts, shaken by the
engine's own exact forces, moments and frame torque.

Modules: :mod:`.modes` (the six rigid-body modes and their kinetic-energy distribution),
:mod:`.axes` (the torque roll axis and the elastic axis), :mod:`.statics` (deflections under
the weight and the mean torque), :mod:`.excitation` (each order's wrench at the centre of
gravity), :mod:`.response` (the forced response, every order at every speed in one batched
solve), :mod:`.result` (the result, its JSON document and records), :mod:`.run` (the analysis,
:func:`mounts`), :mod:`.purity` (how near the mounts are to torque roll axis decoupling) and
:mod:`.decoupling` (design help: the rates that put the roll mode on the torque roll axis,
:func:`decouple`). The model, :class:`~balance_cli.model.MountSystem`, is
rebuilt with one mount changed by :meth:`~balance_cli.model.MountSystem.replace_mount`.
"""

from .axes import Axis, angle_between_deg, elastic_axis, torque_roll_axis
from .decoupling import Decoupling, VariedRate, decouple
from .excitation import Excitation, order_wrenches
from .modes import Mode, energy_distribution, natural_modes
from .purity import TraState, tra_state
from .response import Response, forced_response
from .result import CG, Crossing, MountResult
from .run import DEFAULT_MAX_ORDER, MAX_ORDER, MAX_SPEEDS, default_speeds_rpm, mounts
from .statics import StaticLoad, static_load

__all__ = [
    "mounts",
    "MountResult",
    "decouple",
    "Decoupling",
    "VariedRate",
    "TraState",
    "tra_state",
    "Mode",
    "Axis",
    "Crossing",
    "StaticLoad",
    "Response",
    "Excitation",
    "natural_modes",
    "energy_distribution",
    "torque_roll_axis",
    "elastic_axis",
    "angle_between_deg",
    "static_load",
    "order_wrenches",
    "forced_response",
    "default_speeds_rpm",
    "DEFAULT_MAX_ORDER",
    "MAX_ORDER",
    "MAX_SPEEDS",
    "CG",
]
