"""Kinematics: the engine's linkage closed exactly (:mod:`.linkage`), once per engine and
sampling grid (:mod:`.state`), and its top dead centres (:mod:`.tdc`)."""

from .linkage import (
    BALANCER,
    BIG_ENDS,
    COUNTERWEIGHT,
    CRANK,
    CRANKSHAFT_OWNERS,
    UNKNOWN_RADIUS_M,
    LinkageState,
    MassSet,
    RodSet,
    balancer_positions,
    check_assembly,
    close_linkage,
    counterweight_angle,
    crank_angles_of,
    engine_angles,
    linkage_state,
    pin_angle,
    piston_travel,
)
from .state import FINE_SAMPLES, KinematicState, fine_travel, kinematic_state
from .tdc import tdc_angles

__all__ = [
    "BALANCER",
    "BIG_ENDS",
    "COUNTERWEIGHT",
    "CRANK",
    "CRANKSHAFT_OWNERS",
    "UNKNOWN_RADIUS_M",
    "LinkageState",
    "MassSet",
    "RodSet",
    "balancer_positions",
    "check_assembly",
    "close_linkage",
    "counterweight_angle",
    "crank_angles_of",
    "engine_angles",
    "linkage_state",
    "pin_angle",
    "piston_travel",
    "FINE_SAMPLES",
    "KinematicState",
    "fine_travel",
    "kinematic_state",
    "tdc_angles",
]
