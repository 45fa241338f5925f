"""The firing lattice of an even-firing search and the symmetries checked on it.

Every cylinder's top dead centre falls on one lattice of spacing s, so a throw's phase is a
lattice multiple; reversal and mirror image are used only where the template's own phasors and
lattice offsets show they keep every score and even firing.
"""

from __future__ import annotations

import math

import numpy as np

from ..analysis.firing import tdc_angles
from ..errors import AnalysisError
from ..tolerances import UNIFORM_FIRING_DEG
from ..units import round_degrees

__all__ = ["lattice", "bank_followers", "check_reversal", "check_mirror", "SYMMETRY_TOLERANCE"]

#: phasors of a symmetry check may differ by this fraction of the largest throw phasor
SYMMETRY_TOLERANCE = 1e-9


def lattice(template, allow_uneven, step_deg, followers=None):
    """Phase lattice: (P, step, capacity, base phase per throw, lattice offsets per throw).

    ``followers`` (:func:`bank_followers`): cylinders left off the lattice, which fire a fixed
    angle after a cylinder of bank 1 on their throw; the lattice is then bank 1's own (every
    bank firing evenly within itself)."""
    followers = followers or {}
    n_cyl = template.n_cylinders - len(followers)
    if allow_uneven:
        if step_deg is None:
            raise AnalysisError(
                "is needed with allow_uneven: the grid of throw phases to try, "
                "in degrees (such as 30)",
                "step_deg",
            )
        ok = (
            isinstance(step_deg, (int, float))
            and not isinstance(step_deg, bool)
            and math.isfinite(step_deg)
            and 0.1 - 1e-12 <= step_deg <= 180.0
        )
        P = round(360.0 / step_deg) if ok else 0
        if not ok or abs(P * step_deg - 360.0) > 1e-9:
            raise AnalysisError(
                f"must divide 360° into equal steps of 0.1° to 180° (such as 30 "
                f"or 45), got {step_deg!r}",
                "step_deg",
            )
        n = len(template.throws)
        return P, 360.0 / P, 0, np.zeros(n), [[] for _ in range(n)]
    if step_deg is not None:
        raise AnalysisError(
            "applies only with allow_uneven: an even-firing search takes its "
            "phases from the firing interval",
            "step_deg",
        )
    if template.cycle == 2 or n_cyl % 2:
        s = 360.0 / n_cyl
    else:
        s = 720.0 / n_cyl
    P = round(360.0 / s)
    capacity = n_cyl // P
    tdc = {c: a for c, a in tdc_angles(template).items() if c not in followers}
    first = min(c.number for c in template.cylinders if c.throw_index == 0 and c.number in tdc)
    origin = tdc[first]
    base = np.zeros(len(template.throws))
    offsets: list[list[int]] = []
    for j in range(len(template.throws)):
        mine = sorted(
            c.number for c in template.cylinders if c.throw_index == j and c.number in tdc
        )
        if not mine:
            offsets.append([])
            continue
        rel = [(tdc[c] - origin) % 360.0 for c in mine]
        base_j = rel[0] % s
        if s - base_j < UNIFORM_FIRING_DEG / 2:
            base_j = 0.0
        if j == 0 and base_j > UNIFORM_FIRING_DEG / 2:
            base_j = 0.0
        e = []
        for c, r in zip(mine, rel, strict=True):
            steps = (r - base_j) / s
            if abs(steps - round(steps)) * s > UNIFORM_FIRING_DEG / 2:
                raise AnalysisError(
                    f"cannot fire evenly: cylinders {mine[0]} and {c} ride on throw {j + 1} "
                    "with top dead centres "
                    f"{round_degrees((tdc[c] - tdc[mine[0]]) % 360.0, 3):g}° apart, not a multiple "
                    f"of the {s:g}° firing interval; search with "
                    + (
                        "even_banks (each bank firing evenly on its own) or "
                        if len(template.bank_angles_rad) > 1
                        else ""
                    )
                    + "allow_uneven and a step_deg",
                    "template",
                )
            e.append(round(steps) % P)
        base[j] = base_j
        offsets.append(e)
    return P, s, capacity, base, offsets


def bank_followers(template):
    """For a search whose banks each fire evenly on their own: every cylinder of banks 2, 3,
    ... with (the cylinder of bank 1 on its throw, the angle it fires after it, degrees in
    [0, 360)). Turning the throw moves both alike, so bank b's firing is bank 1's turned by
    that angle: even whenever bank 1's is. Needs one cylinder of every bank on every throw.

    Raises
    ------
    AnalysisError
        naming ``even_banks``, when a throw has not one cylinder of each bank
    """
    banks = len(template.bank_angles_rad)
    tdc = tdc_angles(template)
    followers = {}
    for j in range(len(template.throws)):
        mine = [c for c in template.cylinders if c.throw_index == j]
        if sorted(c.bank_index for c in mine) != list(range(banks)):
            raise AnalysisError(
                f"needs one cylinder of each of the {banks} banks on every throw, but throw "
                f"{j + 1} has {len(mine)} (banks "
                f"{', '.join(str(c.bank_index + 1) for c in mine) or 'none'}); search the "
                "template with even firing overall instead",
                "even_banks",
            )
        mate = next(c for c in mine if c.bank_index == 0)
        for c in mine:
            if c is not mate:
                followers[c.number] = (mate.number, (tdc[c.number] - tdc[mate.number]) % 360.0)
    return followers


def check_reversal(phasors, offsets, base, P, floor):
    """Reversal keeps every score when each channel's throw phasors are collinear through the
    origin, and keeps even firing when every throw's lattice offsets are symmetric about one
    common point."""
    if np.any(base != 0.0):
        return False, None
    for channel in phasors.reshape(-1, phasors.shape[1], phasors.shape[2]).transpose(0, 2, 1):
        for row in channel:  # one order of one kind: a phasor per throw
            big = np.abs(row).max()
            if big <= floor:  # rounding noise: no direction to keep
                continue
            direction = row[np.argmax(np.abs(row))] / big
            if np.abs((row * direction.conjugate()).imag).max() > SYMMETRY_TOLERANCE * big:
                return False, None
    shifts = None
    for e in offsets:
        if not e:
            continue
        fits = {t for t in range(P) if sorted((t - x) % P for x in e) == sorted(e)}
        shifts = fits if shifts is None else shifts & fits
    if shifts is not None and not shifts:
        return False, None
    return True, (min(shifts) if shifts else 0)


def check_mirror(phasors, offsets, base, floor):
    """A mirror image balances alike when throw n+1−j's phasors are throw j's times one unit
    factor per channel, and fires evenly when mirrored throws have the same lattice offsets."""
    n = phasors.shape[1]
    if n < 2 or np.any(base != 0.0):
        return False
    if any(sorted(offsets[j]) != sorted(offsets[n - 1 - j]) for j in range(n)):
        return False
    for kind in range(phasors.shape[0]):
        for k in range(phasors.shape[2]):
            row = phasors[kind, :, k]
            big = np.abs(row).max()
            if big <= floor:
                continue
            j = int(np.argmax(np.abs(row)))
            unit = row[n - 1 - j] / row[j]
            if (
                abs(abs(unit) - 1.0) > SYMMETRY_TOLERANCE
                or np.abs(row[::-1] - unit * row).max() > SYMMETRY_TOLERANCE * big
            ):
                return False
    return True
