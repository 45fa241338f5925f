"""Every numerical tolerance of balance, with its reason, in one place.

Imports nothing: the ground floor of the package.
"""

__all__ = [
    "NOISE_FLOOR",
    "ALIASING_TOLERANCE",
    "ANGLE_TOLERANCE_DEG",
    "TDC_PRECISION_DEG",
    "UNIFORM_FIRING_DEG",
    "SAME_POSITION_M",
    "SAME_DIRECTION_RAD",
    "PHASE_FLOOR",
    "PHASE_CHANGE_DEG",
    "FIRING_CHANGE_DEG",
    "SPECTRUM_FLOOR",
    "MODE_FLOOR",
    "RESONANCE_WINDOW",
    "minimum_samples",
]

#: A force below this fraction of m_rec·r·ω²·n (N), or a moment below it times one metre
#: (N·m), is rounding noise and is reported as an exact zero. The FFT of exact positions is
#: good to about 1e-13 of the largest mass's force, so 1e-9 leaves four orders of margin and
#: still resolves the smallest order the papers print (about 1e-4).
NOISE_FLOOR = 1e-9

#: The spectral content above a quarter of the samples, weighted as it would alias into the
#: highest order reported, may be this fraction of the largest inertia force before a
#: SamplingWarning says the samples are too few (the same margin as NOISE_FLOOR).
ALIASING_TOLERANCE = 1e-9

#: An angle within this of a full period (360°, or 180° for an axis) is that period's start:
#: phases of phasors carry rounding errors of about 1e-9°, far below it.
ANGLE_TOLERANCE_DEG = 1e-6

#: The top-dead-centre search is refined to about 2e-6°; TDCs closer than this are the same.
TDC_PRECISION_DEG = 1e-3

#: Firing intervals within this of the mean count as uniform.
UNIFORM_FIRING_DEG = 0.01

#: Axial positions closer than this are the same plane.
SAME_POSITION_M = 1e-9

#: Cylinder axes closer than this (1e-6°) point the same way.
SAME_DIRECTION_RAD = 1e-8

#: Regression tables compare a phase only where its phasor exceeds this fraction of
#: m_rec·r·ω²·n: the FFT's rounding (about 1e-15 of the largest force) turns a phasor of that
#: size by about 1e-9 rad (6e-8°), well inside PHASE_CHANGE_DEG; smaller ones are not compared.
PHASE_FLOOR = 1e-6

#: A phase (or an ellipse's axis) above PHASE_FLOOR may move by this between machines.
PHASE_CHANGE_DEG = 1e-6

#: A firing angle may move by this between machines: the TDC search is good to about 2e-6°.
FIRING_CHANGE_DEG = 1e-4

#: Pictures on a log axis leave out parts below this fraction of the largest m_rec·r·ω²·n,
#: a thousand times the noise floor, so that no rounding noise is drawn.
SPECTRUM_FLOOR = 1e-6

#: A torsional mode's amplitude below this fraction of its largest is a node (exactly zero),
#: and so is a phase-vector sum below it times the number of cylinders: the eigen-solver's
#: rounding is about 1e-16 times the spread of the line's inertias and stiffnesses, so this
#: leaves room for a spread of 10⁸, and a cylinder moving 1e-8 as much as the free end
#: excites nothing a report could show.
MODE_FLOOR = 1e-8

#: An excitation frequency within this fraction of an undamped mode's natural frequency is
#: at it: K − ω²·M is singular to within rounding there (its condition grows as 1/distance).
RESONANCE_WINDOW = 1e-6


def minimum_samples(max_order):
    """Fewest samples a revolution for orders up to ``max_order``: more than four per order,
    so that a band of orders above ``max_order`` and below half the samples is left in which
    aliasing can be seen."""
    return 4 * max_order + 1
