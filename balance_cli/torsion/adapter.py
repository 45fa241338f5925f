"""The openTorsion adapter: the shaft line as openTorsion's disks and shafts, and its modes.

openTorsion (Aalto University's library of disks and shafts) is an optional extra; without it
every torsional analysis stops with one line naming the extra to install.
"""

import numpy as np

from ..about import install_hint
from ..errors import AnalysisError, TorsionUnavailable

__all__ = ["require_opentorsion", "assembly_of", "natural_frequencies"]

#: a natural frequency below this share of the highest is the shaft line turning as a whole
_RIGID = 1e-6


def require_opentorsion():
    """The openTorsion module; TorsionUnavailable (one line naming the extra) without it."""
    try:
        import opentorsion
    except ImportError:
        raise TorsionUnavailable(
            f"balance torsion needs openTorsion: {install_hint('torsion')}"
        ) from None
    return opentorsion


def assembly_of(line):
    """openTorsion's Assembly of ``line``: one Disk per node, one massless Shaft per section."""
    ot = require_opentorsion()
    disks = [
        ot.Disk(i, float(j), c=float(c))
        for i, (j, c) in enumerate(zip(line.inertia, line.node_damping, strict=True))
    ]
    shafts = [
        ot.Shaft(i, i + 1, None, None, k=float(k), I=0.0, c=float(c))
        for i, (k, c) in enumerate(zip(line.stiffness, line.section_damping, strict=True))
    ]
    if not shafts:
        raise AnalysisError(
            "its shaft line has a single inertia: nothing can twist (give more "
            "throws, a front end or a flywheel)",
            "engine",
        )
    return ot.Assembly(shafts, disk_elements=disks)


def natural_frequencies(assembly):
    """Undamped natural frequencies (rad/s, ascending) and mode shapes (columns, real) of an
    openTorsion ``assembly``, the rigid-body mode of a free shaft line left out."""
    lam, vectors = assembly.undamped_modal_analysis()
    omega = np.sqrt(np.abs(lam.real))
    order = np.argsort(omega)
    omega, vectors = omega[order], vectors[:, order].real
    keep = omega > _RIGID * omega.max()
    return omega[keep], vectors[:, keep]
