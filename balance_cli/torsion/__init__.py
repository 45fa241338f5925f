"""Torsional vibration of the crankshaft: the shaft line (:mod:`.line`), the excitation
(:mod:`.excitation`), the openTorsion adapter (:mod:`.adapter`), the modes as reported and
their criticals (:mod:`.modes`), the forced response (:mod:`.forced`), and the analysis and its
result (:mod:`.response`)."""

from .adapter import natural_frequencies, require_opentorsion
from .excitation import phase_vector_sum
from .line import throw_inertias
from .response import (
    CRITICAL_KINDS,
    DEFAULT_MAX_ORDER,
    MAX_SPEEDS,
    Critical,
    Mode,
    Peak,
    TorsionResult,
    default_speeds_rpm,
    first_mode_amplitudes,
    torsional_vibration,
)

__all__ = [
    "require_opentorsion",
    "first_mode_amplitudes",
    "Mode",
    "Critical",
    "Peak",
    "TorsionResult",
    "torsional_vibration",
    "throw_inertias",
    "phase_vector_sum",
    "natural_frequencies",
    "default_speeds_rpm",
    "DEFAULT_MAX_ORDER",
    "MAX_SPEEDS",
    "CRITICAL_KINDS",
]
