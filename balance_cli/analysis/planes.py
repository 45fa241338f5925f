"""Correction planes: where counterweights and balancer masses go (a throw's plane, or an
axial position), and how a force and a couple are shared between two planes."""

import math
import numbers

from ..errors import CounterweightError, UnitError
from ..tolerances import SAME_POSITION_M
from ..units import check_finite_range
from .balancing import Plane

__all__ = ["plane_at_throw", "plane_at", "plane_of", "default_planes", "checked_planes", "share"]


def plane_at_throw(engine, number) -> Plane:
    """The plane of throw ``number`` (1-based)."""
    if (
        isinstance(number, bool)
        or not isinstance(number, numbers.Integral)
        or not 1 <= int(number) <= len(engine.throws)
    ):
        raise CounterweightError(
            f"names throw {number!r}, but the engine has throws 1 to "
            f"{len(engine.throws)}; give throw numbers or Plane(z_m) for axial positions",
            "planes",
        )
    return Plane(engine.throws[number - 1].z_m, int(number))


def plane_at(engine, z_m) -> Plane:
    """A plane at an axial position, m; on a throw if one sits there."""
    if isinstance(z_m, bool) or not isinstance(z_m, numbers.Real):
        raise CounterweightError(
            f"has an axial position that is not a number of metres: {z_m!r}", "planes"
        )
    try:
        check_finite_range(float(z_m), "length", smallest=False)
    except UnitError as exc:
        raise CounterweightError(
            f"has an axial position that is invalid: {exc}", "planes"
        ) from None
    for i, throw in enumerate(engine.throws, 1):
        if math.isclose(throw.z_m, z_m, abs_tol=SAME_POSITION_M):
            return Plane(throw.z_m, i)
    return Plane(float(z_m), None)


def plane_of(engine, spec):
    """A plane from a throw number, or a :class:`Plane` (one at an axial position is on the
    throw that sits there, if any)."""
    if isinstance(spec, Plane):
        located = plane_at(engine, spec.z_m)
        if spec.throw is None:
            return located
        on = plane_at_throw(engine, spec.throw)
        if not math.isclose(located.z_m, on.z_m, abs_tol=SAME_POSITION_M):
            raise CounterweightError(
                f"names throw {spec.throw} at z = {spec.z_m!r} m, but throw {spec.throw} sits at "
                f"z = {on.z_m:g} m; give the throw's number, or Plane(z_m) alone",
                "planes",
            )
        return on
    if isinstance(spec, numbers.Integral) and not isinstance(spec, bool):
        return plane_at_throw(engine, spec)
    raise CounterweightError(
        f"takes throw numbers (int, from 1) or Plane objects (Plane(z_m) for "
        f"an axial position in metres), got {spec!r}",
        "planes",
    )


def default_planes(engine):
    """The first and last throws, or one plane where every throw sits at one position."""
    first, last = plane_at_throw(engine, 1), plane_at_throw(engine, len(engine.throws))
    return (first,) if math.isclose(first.z_m, last.z_m, abs_tol=SAME_POSITION_M) else (first, last)


def checked_planes(engine, planes):
    if planes is None:
        return default_planes(engine)
    planes = tuple(plane_of(engine, p) for p in planes)
    if not 1 <= len(planes) <= 2:
        raise CounterweightError(
            f"takes one plane (force only) or two (force and moment), got {len(planes)}", "planes"
        )
    if len(planes) == 2 and math.isclose(planes[0].z_m, planes[1].z_m, abs_tol=SAME_POSITION_M):
        raise CounterweightError("coincide; choose two planes apart, or give one", "planes")
    return planes


def share(force, moment, planes, z_mean):
    """Phasors in each plane that add up to ``force`` and, with two planes, ``moment``.

    Two planes at a = z_A − z̄, b = z_B − z̄: c_A + c_B = F and a·c_A + b·c_B = M.
    """
    if len(planes) == 1:
        return (force,)
    a, b = planes[0].z_m - z_mean, planes[1].z_m - z_mean
    first = (moment - b * force) / (a - b)
    return (first, force - first)
