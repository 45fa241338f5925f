"""The engine model: immutable, SI units and radians throughout, checked when built.

This is the ground floor of the analyses: it imports only the errors, tolerances and units.
An :class:`Engine` built in code is checked exactly as one read from a configuration file
(the reader puts its key names into the messages); whether its linkage can be assembled over
a revolution is checked by :func:`balance_cli.kinematics.linkage.check_assembly`, which every
analysis calls first.

Modules: :mod:`.values` (one value's checks), :mod:`.crankshaft` (crankshafts and throws),
:mod:`.cylinder`, :mod:`.as_built` (counterweights and balancer shafts), :mod:`.parts` (part
data and the gas cycle), :mod:`.torsion` (the shaft line's mass-elastic model), :mod:`.mounts`
(the powertrain as a rigid body on its mounts), :mod:`.scatter` (the production scatter of
``[tolerances]``), :mod:`.engine` (the Engine), :mod:`.edit` (its values changed as a file
writes them) and
:mod:`.invariants` (the rules it is checked against).
"""

from .as_built import MAX_SHAFT_RATIO, BalancerMass, BalancerShaftSpec, CounterweightMass
from .crankshaft import REFERENCE_CRANKSHAFT, Crankshaft, Throw
from .cylinder import Cylinder
from .engine import Engine
from .invariants import FRAMES, MAX_NAME_LENGTH
from .mounts import (
    DOF_LABELS,
    MOTIONS,
    PRODUCT_CONVENTIONS,
    ROTATIONS,
    STANDARD_GRAVITY,
    Mount,
    MountSystem,
    inertia_matrix,
    motion_name,
)
from .parts import GasCycle, Parts
from .scatter import ToleranceBand
from .torsion import ShaftDisk, TorsionModel
from .values import offset_position

__all__ = [
    "Crankshaft",
    "Throw",
    "Cylinder",
    "Engine",
    "Parts",
    "GasCycle",
    "ToleranceBand",
    "FRAMES",
    "CounterweightMass",
    "BalancerMass",
    "BalancerShaftSpec",
    "MAX_SHAFT_RATIO",
    "offset_position",
    "ShaftDisk",
    "TorsionModel",
    "MAX_NAME_LENGTH",
    "REFERENCE_CRANKSHAFT",
    "Mount",
    "MountSystem",
    "inertia_matrix",
    "motion_name",
    "MOTIONS",
    "DOF_LABELS",
    "ROTATIONS",
    "PRODUCT_CONVENTIONS",
    "STANDARD_GRAVITY",
]
