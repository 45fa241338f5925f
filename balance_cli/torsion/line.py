"""The crankshaft's shaft line for torsional vibration: the [torsion] model's inertias,
stiffnesses and damping, free end first, with each throw's inertia from the engine's own
moving parts where the model does not give it."""

import math
from dataclasses import dataclass

import numpy as np

from ..analysis.inertia import reduced_mass_and_momentum
from ..analysis.shaking import DEFAULT_SAMPLES
from ..checks import instance
from ..errors import AnalysisError
from ..kinematics import kinematic_state
from ..model import Engine

__all__ = ["ShaftLine", "shaft_line", "throw_inertias", "torsion_model", "check_values"]


def torsion_model(engine):
    """The engine's [torsion] model, checked against its throws; AnalysisError naming what is
    missing or wrong."""
    instance(engine, Engine, "engine", hint=" (balance.load gives one)")
    model = engine.torsion
    if model is None:
        raise AnalysisError(
            f"{engine.name!r} has no [torsion] table: give its shaft line's "
            "inertias and stiffnesses (see balance's documentation, How-to: Torsional vibration)",
            "engine",
        )
    if engine.is_rotary:
        raise AnalysisError("is a rotary: its crankshaft does not turn", "engine")
    n = len(engine.throws)
    check_values(model)
    if (
        len(model.stiffness_nm_rad) != n - 1
        or len(model.throw_damping_nms_rad) != n
        or (model.throw_inertia_kgm2 is not None and len(model.throw_inertia_kgm2) != n)
    ):
        raise AnalysisError(
            f"its [torsion] table must give one inertia and damping per throw "
            f"({n}) and one stiffness per section between throws ({n - 1})",
            "engine",
        )
    return model


def check_values(model):
    """A model built in code is checked as the configuration's reader checks a file's."""
    disks = list(model.front) + [d for d in (model.flywheel, model.load) if d is not None]
    groups = [
        ("throw_inertia_kgm2", model.throw_inertia_kgm2 or (), False),
        ("web_inertia_kgm2", (model.web_inertia_kgm2,), True),
        ("stiffness_nm_rad", model.stiffness_nm_rad, False),
        ("throw_damping_nms_rad", model.throw_damping_nms_rad, True),
        ("loss_factor", (model.loss_factor,), True),
        ("front, flywheel and load inertias", [d.inertia_kgm2 for d in disks], False),
        ("front, flywheel and load stiffnesses", [d.stiffness_nm_rad for d in disks], False),
        ("front, flywheel and load damping", [d.damping_nms_rad for d in disks], True),
    ]
    for name, values, zero_ok in groups:
        for value in values:
            if not (
                isinstance(value, (int, float, np.floating))
                and math.isfinite(value)
                and (value >= 0 if zero_ok else value > 0)
            ):
                raise AnalysisError(
                    f"of the [torsion] model must be finite and "
                    f"{'not negative' if zero_ok else 'above zero'}, got "
                    f"{value!r}",
                    name,
                )


def throw_inertias(engine, samples=DEFAULT_SAMPLES) -> np.ndarray:
    """Each throw's inertia about the crank axis, kg·m²: the [torsion] table's
    ``throw_inertia``, or the mean over a revolution of the reduced mass of the parts on the
    throw (pistons, rods, pins: ½·μ_j·ω² their kinetic energy) plus ``web_inertia``."""
    model = torsion_model(engine)
    if model.throw_inertia_kgm2 is not None:
        return np.array(model.throw_inertia_kgm2, dtype=float)
    state = kinematic_state(engine, samples)
    masses, rods = state.masses, state.rods
    out = []
    for index in range(len(engine.throws)):
        # the rows riding on this throw: μ is a sum over the parts
        mu, _ = reduced_mass_and_momentum(
            engine, state.parts(masses.throw_index == index, rods.throw_index == index)
        )
        # the shaft's own inertia is the user's, in the webs
        out.append(float(np.mean(mu.real)) - engine.shaft_inertia_kgm2 + model.web_inertia_kgm2)
    return np.array(out)


@dataclass(frozen=True)
class ShaftLine:
    """The shaft line, free end first: names, inertias, section stiffnesses and damping."""

    names: tuple
    inertia: np.ndarray  # kg·m², per node
    stiffness: np.ndarray  # N·m/rad, per section (node i to i + 1)
    section_damping: np.ndarray  # N·m·s/rad, per section
    node_damping: np.ndarray  # N·m·s/rad, per node
    throw_nodes: tuple  # node of throw j (index j)


def shaft_line(engine, samples) -> ShaftLine:
    """The shaft line of ``engine``'s [torsion] model, free end first, its throws' inertias
    from :func:`throw_inertias` at ``samples`` a revolution."""
    model = torsion_model(engine)
    names, inertia, stiffness, section_c, node_c = [], [], [], [], []
    for disk in model.front:
        names.append(disk.name)
        inertia.append(disk.inertia_kgm2)
        node_c.append(0.0)
        # a front disk's section joins it to the next node aft
        stiffness.append(disk.stiffness_nm_rad)
        section_c.append(disk.damping_nms_rad)
    throws = throw_inertias(engine, samples)
    first = len(names)
    for j, value in enumerate(throws):
        names.append(f"throw {j + 1}")
        inertia.append(value)
        node_c.append(model.throw_damping_nms_rad[j])
        if j < len(throws) - 1:
            stiffness.append(model.stiffness_nm_rad[j])
            section_c.append(0.0)
    for disk in (model.flywheel, model.load):
        if disk is not None:
            names.append(disk.name)
            inertia.append(disk.inertia_kgm2)
            node_c.append(0.0)
            stiffness.append(disk.stiffness_nm_rad)
            section_c.append(disk.damping_nms_rad)
    return ShaftLine(
        tuple(names),
        np.array(inertia),
        np.array(stiffness),
        np.array(section_c),
        np.array(node_c),
        tuple(range(first, first + len(throws))),
    )
