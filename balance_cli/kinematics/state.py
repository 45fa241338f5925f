"""One kinematic state per engine and sampling grid: the linkage closed once over a revolution,
and what every analysis reads from it.

Shaking forces, torques, gas torque, guide forces, crank-pin forces and torsional excitation
all start from the same positions, rod directions and piston travel. Closing the linkage is
the costly step, so it is done once for each engine and grid and kept (the engine is
immutable, so its state never goes stale); the travel rates are computed on first use and
kept with it. Everything kept is read-only: a change in place would reach every analysis.

Two grids are in use: the analysis's own ``samples`` a revolution, and the fine grid of
:data:`FINE_SAMPLES` on which a parametric gas cycle is integrated and the swept volumes are
measured.
"""

import dataclasses
import threading
from collections import OrderedDict
from dataclasses import dataclass
from functools import cached_property
from types import MappingProxyType

import numpy as np

from ..checks import whole
from ..errors import ModelError
from ..harmonics import periodic_derivative, shifted
from .linkage import MassSet, RodSet, check_assembly, engine_angles, linkage_state

__all__ = ["KinematicState", "kinematic_state", "FINE_SAMPLES", "fine_travel"]

#: the fine grid, points a revolution (0.05°): a parametric gas cycle is integrated on it, and
#: the swept volumes read off it
FINE_SAMPLES = 7200

#: what is kept: an engine's analyses read its states again and again (its shaking, torque,
#: cylinder torques, torsion: the analysis grid and the fine grid), so the most recent few
#: states are what counts, not every engine a command has seen; and at most this memory, bytes
#: (at 256 samples a revolution a state takes 0.1 to 0.5 MB, on the fine grid 3 to 15 MB)
_KEPT_STATES = 4
_KEPT_BYTES = 64 << 20


@dataclass(frozen=True)
class KinematicState:
    """An engine's linkage closed at ``samples`` evenly spaced engine angles over a revolution.

    Attributes
    ----------
    samples : int
        engine angles a revolution
    angles_rad : ndarray, shape (samples,)
        the engine angles, rad (a rotary's crankcase angle)
    masses : MassSet
        every point mass's position in the fixed frame, with its mass, axial position and owner
    rods : RodSet
        every rod's direction, with its correcting moment of inertia
    travel : mapping
        each cylinder's piston travel from its crank axis along its axis, m, by cylinder
        number (an opposed bore: its two pistons' travels added)
    opposed_travel : mapping
        an opposed bore's far piston's own travel from its crank axis, m, by cylinder number
    crankshaft_travel : mapping
        each piston's own travel, m, by crankshaft index and then cylinder number: an opposed
        bore has one piston on each of its two crankshafts
    """

    samples: int
    angles_rad: np.ndarray
    masses: MassSet
    rods: RodSet
    travel: MappingProxyType
    opposed_travel: MappingProxyType
    crankshaft_travel: MappingProxyType

    @cached_property
    def travel_rates(self) -> MappingProxyType:
        """ds/dθ of every cylinder's travel, m/rad, by cylinder number (spectral)."""
        numbers = list(self.travel)
        rates = periodic_derivative(np.array([self.travel[n] for n in numbers])).real
        rates.flags.writeable = False
        return MappingProxyType(dict(zip(numbers, rates, strict=True)))

    @cached_property
    def crankshaft_travel_rates(self) -> MappingProxyType:
        """ds/dθ of each piston's own travel, m/rad, by crankshaft index and cylinder number."""
        out = {}
        for shaft, by_number in self.crankshaft_travel.items():
            rates = {}
            for number, travel in by_number.items():
                rates[number] = periodic_derivative(np.asarray(travel)).real
                rates[number].flags.writeable = False
            out[shaft] = MappingProxyType(rates)
        return MappingProxyType(out)

    def parts(self, masses_kept, rods_kept) -> "KinematicState":
        """This state with only the point masses and rods the boolean masks keep: the parts of
        one crankshaft, one cylinder or one throw (a reduced mass is a sum over the parts, so
        their torques add up to the engine's). Travel is kept whole."""
        masses, rods = self.masses, self.rods
        return dataclasses.replace(
            self,
            masses=dataclasses.replace(
                masses,
                **{
                    name: getattr(masses, name)[masses_kept]
                    for name in ("positions", "masses_kg", "z_m", "cylinder", "throw_index")
                },
            ),
            rods=dataclasses.replace(
                rods,
                **{
                    name: getattr(rods, name)[rods_kept]
                    for name in ("directions", "corrections_kgm2", "cylinder", "throw_index")
                },
            ),
        )


def kinematic_state(engine, samples: int) -> KinematicState:
    """The kinematic state of ``engine`` at ``samples`` engine angles a revolution: its linkage
    closed once per engine and grid, and kept.

    Raises
    ------
    ModelError
        a linkage that cannot be assembled, or ``samples`` that are not a whole number of at
        least 4
    """
    samples = whole(samples, "samples", 4, 1 << 20, error=ModelError)
    key = (engine, samples)
    with _LOCK:
        state = _STATES.get(key)
        if state is not None:
            _STATES.move_to_end(key)
            return state
    state = _closed(engine, samples)
    with _LOCK:
        _STATES[key] = state
        size = sum(_bytes(s) for s in _STATES.values())
        while len(_STATES) > 1 and (size > _KEPT_BYTES or len(_STATES) > _KEPT_STATES):
            _, dropped = _STATES.popitem(last=False)
            size -= _bytes(dropped)
    return state


_STATES: "OrderedDict[tuple, KinematicState]" = OrderedDict()
_LOCK = threading.Lock()


def _bytes(state):
    return sum(array.nbytes for array in _arrays(state))


def _closed(engine, samples):
    check_assembly(engine)
    angles = engine_angles(samples)
    closed = linkage_state(engine, angles)
    state = KinematicState(
        samples,
        angles,
        closed.masses,
        closed.rods,
        MappingProxyType(closed.travel),
        MappingProxyType(closed.opposed_travel),
        _by_crankshaft(engine, closed),
    )
    # the state is shared by every analysis of the engine: a change in place would reach
    # them all, so its arrays are read-only
    for array in _arrays(state):
        array.flags.writeable = False
    return state


def _arrays(state):
    yield state.angles_rad
    yield from (getattr(state.masses, f.name) for f in dataclasses.fields(state.masses))
    yield from (getattr(state.rods, f.name) for f in dataclasses.fields(state.rods))
    for by_number in (state.travel, state.opposed_travel, *state.crankshaft_travel.values()):
        yield from by_number.values()


def _by_crankshaft(engine, closed):
    """Each piston's own travel by crankshaft index and cylinder number (see
    :attr:`KinematicState.crankshaft_travel`)."""
    out: dict = {}
    for c in engine.cylinders:
        travel = closed.travel[c.number]
        if c.is_opposed:
            # the two pistons of a bore are on two crankshafts (the model checks it)
            own = closed.opposed_travel[c.number]
            out.setdefault(engine.throws[c.opposed_throw_index].crankshaft_index, {})[c.number] = (
                own
            )
            travel = travel - own
        out.setdefault(engine.throws[c.throw_index].crankshaft_index, {})[c.number] = travel
    return MappingProxyType({shaft: MappingProxyType(by) for shaft, by in out.items()})


def fine_travel(engine, number: int, start_deg: float) -> np.ndarray:
    """Cylinder ``number``'s piston travel over one revolution from engine angle
    ``start_deg``, on the fine grid (:data:`FINE_SAMPLES` steps, both ends included), m.

    Read off the engine's one fine-grid state, moved on by the shift theorem: the fine grid
    resolves the travel to rounding, so the result is the closed linkage's at those angles.
    """
    travel = kinematic_state(engine, FINE_SAMPLES).travel[number]
    # the mean moved out and back: the transform's rounding is then a fraction of the stroke,
    # not of the piston's whole distance from the crank axis
    mean = travel.mean()
    values = shifted(travel - mean, np.radians(start_deg)) + mean
    return np.append(values, values[0])
