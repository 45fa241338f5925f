"""Many engines at once: each run of a production scatter its own exact linkage, closed for all
runs together in numpy (no loop over engines), and its forces and moments order by order.

Every run is the engine's own point masses with its own dimensions: each throw's crank radius
and phase, each bank's direction, each rod's length and each cylinder's pin offset drawn
apart. A plain or master rod's piston pin is where the rod from its crank pin meets the
cylinder axis; a link rod's knuckle pin is fixed in its master rod, and its piston where the
link rod from there meets its axis: the same closing as
:func:`balance_cli.kinematics.linkage.close_linkage`, with arrays of runs in place of the
engine's numbers (a test checks that the nominal run is the engine's own analysis to rounding).
The positions at ``samples`` angles a revolution give each run's Fourier coefficients; a mass
times (kω)² times its position's coefficient is its inertia force, exactly as the engine's
analysis computes it.

Counterweights and balancer shafts as built are not scattered: their share is the nominal
one. An opposed-piston engine's dimensions are not scattered (its masses may be).
"""

from dataclasses import dataclass

import numpy as np

from ..errors import AnalysisError
from ..harmonics import fourier, orders_of
from ..kinematics import engine_angles

__all__ = ["Draws", "RunGeometry", "draw", "geometry_of", "run_coefficients"]


@dataclass(frozen=True)
class RunGeometry:
    """The dimensions of every run, SI: per throw ``radius`` and ``phase``, per bank
    ``bank``, per cylinder ``rod`` (its own rod's length: the plain or master rod's, or the
    link rod's) and ``offset`` (its pin offset, positive with its crankshaft's rotation).
    Arrays of shape (runs, n)."""

    radius: np.ndarray
    phase: np.ndarray
    bank: np.ndarray
    rod: np.ndarray
    offset: np.ndarray


@dataclass(frozen=True)
class Draws:
    """The runs' masses (per cylinder ``reciprocating``, per throw ``rotating``, kg, arrays
    (runs, n)) and dimensions (:class:`RunGeometry`, or None when none scatters)."""

    reciprocating: np.ndarray
    rotating: np.ndarray
    geometry: RunGeometry | None

    @property
    def runs(self) -> int:
        return self.reciprocating.shape[0]


def geometry_of(engine) -> RunGeometry:
    """The engine's own dimensions, as one run."""
    cylinders = engine.cylinders
    return RunGeometry(
        radius=np.full((1, len(engine.throws)), engine.crank_radius_m),
        phase=np.array([[t.phase_rad for t in engine.throws]]),
        bank=np.array([engine.bank_angles_rad]),
        rod=np.array([[c.link_length_m if c.is_link else engine.rod_length_m for c in cylinders]]),
        offset=np.array([[engine.pin_offset_of(c) for c in cylinders]]),
    )


def draw(engine, band, runs, rng) -> Draws:
    """``runs`` engines scattered by ``band`` (a ToleranceBand), each value drawn apart."""
    n, t = engine.n_cylinders, len(engine.throws)
    reciprocating = np.array([c.reciprocating_kg for c in engine.cylinders]) + (
        band.reciprocating_kg * rng.standard_normal((runs, n))
    )
    rotating = np.array([engine.rotating_of(i) for i in range(t)]) + (
        band.rotating_kg * rng.standard_normal((runs, t))
    )
    if not band.geometric:
        return Draws(reciprocating, rotating, None)
    if engine.has_opposed_pistons:
        raise AnalysisError(
            f"scatters dimensions, but {engine.name!r} has opposed pistons, whose linkage is "
            "not drawn run by run; scatter its masses only (reciprocating, rotating)",
            "tolerances",
        )
    own = geometry_of(engine)
    phase_noise = band.phase_rad * rng.standard_normal((runs, t))
    phase_noise[:, 0] = 0.0  # throw 1 is the reference the phases are measured from
    geometry = RunGeometry(
        radius=own.radius + band.crank_radius_m * rng.standard_normal((runs, t)),
        phase=own.phase + phase_noise,
        bank=own.bank + band.bank_angle_rad * rng.standard_normal((runs, own.bank.shape[1])),
        rod=own.rod + band.rod_length_m * rng.standard_normal((runs, n)),
        offset=own.offset + band.pin_offset_m * rng.standard_normal((runs, n)),
    )
    return Draws(reciprocating, rotating, geometry)


def _slider(point, centre, axis, length, offset, number):
    """Piston pins on axes at ``axis`` through ``centre`` reached by rods of ``length`` from
    ``point`` (arrays (runs, angles); the others (runs, 1))."""
    turn = np.exp(-1j * axis)
    local = (point - centre) * turn
    reach = length**2 - (offset - local.imag) ** 2
    if reach.min() <= 0.0:
        raise AnalysisError(
            f"leaves cylinder {number}'s rod unable to reach its axis in some runs: the "
            "scatter is too wide for its rod and crank",
            "tolerances",
        )
    return (local.real + np.sqrt(reach) + 1j * offset) / turn + centre


def _positions(engine, geometry, angles):
    """Every point mass's position in every run: pistons ({number: (runs, angles)}), knuckle
    pins of link rods ({number: (runs, angles)}), crank pins (a list by throw of (runs,
    angles)); fixed frame, m."""
    crank = -angles if engine.is_rotary else angles
    pins = []
    for index, throw in enumerate(engine.throws):
        shaft = engine.crankshafts[throw.crankshaft_index]
        direction = shaft.direction * (crank + shaft.phase_rad + geometry.phase[:, index, None])
        pins.append(shaft.centre + geometry.radius[:, index, None] * np.exp(1j * direction))
    pistons: dict = {}
    knuckles: dict = {}
    order = [c for c in engine.cylinders if not c.is_link] + [
        c for c in engine.cylinders if c.is_link
    ]
    index_of = {c.number: i for i, c in enumerate(engine.cylinders)}
    for c in order:
        i = index_of[c.number]
        shaft = engine.crankshaft_of(c.throw_index)
        axis = geometry.bank[:, c.bank_index, None]
        offset = shaft.direction * geometry.offset[:, i, None]
        start = pins[c.throw_index]
        if c.is_link:
            master = engine.cylinder(c.master)
            pin = pins[master.throw_index]
            length = geometry.rod[:, index_of[master.number], None]
            direction = (pistons[master.number] - pin) / length
            start = pin + c.knuckle_radius_m * direction * np.exp(1j * c.knuckle_angle_rad)
            knuckles[c.number] = start
        pistons[c.number] = _slider(
            start, shaft.centre, axis, geometry.rod[:, i, None], offset, c.number
        )
    if engine.is_rotary:
        turn = np.exp(1j * angles)
        pistons = {n: p * turn for n, p in pistons.items()}
        knuckles = {n: k * turn for n, k in knuckles.items()}
        pins = [p * turn for p in pins]
    return pistons, knuckles, pins


def run_coefficients(engine, draws, samples, basis=None):
    """Each run's force and free-moment coefficients (runs, samples), N and N·m.

    Without dimensions scattered, the runs' masses times ``basis`` (a
    :class:`~balance_cli.workshop.basis.UnitBasis` of the engine), exactly; with them, each
    run's linkage closed at ``samples`` angles and its point masses' coefficients summed.
    """
    if draws.geometry is None:
        weights = np.tile(basis.nominal_kg, (draws.runs, 1))
        for kind, values in (("piston", draws.reciprocating), ("pin", draws.rotating)):
            rows = basis.rows(kind)
            owners = (
                [c.number for c in engine.cylinders]
                if kind == "piston"
                else range(len(engine.throws))
            )
            for j, owner in enumerate(owners):
                weights[:, rows[owner]] = values[:, j]
        force = weights @ basis.force + basis.fixed_force
        moment = weights @ basis.moment + basis.fixed_moment
        return force, moment
    angles = engine_angles(samples)
    pistons, knuckles, pins = _positions(engine, draws.geometry, angles)
    mean_z = engine.mean_z_m
    lever_c = np.array([c.z_m for c in engine.cylinders]) - mean_z
    lever_t = np.array([t.z_m for t in engine.throws]) - mean_z
    pin_mass = draws.rotating + engine.crank_kg
    # Σ m·x and Σ m·(z − z̄)·x over the point masses, run by run
    weighted = np.zeros((draws.runs, samples), complex)
    levered = np.zeros((draws.runs, samples), complex)
    for i, c in enumerate(engine.cylinders):
        weighted += draws.reciprocating[:, i, None] * pistons[c.number]
        levered += (draws.reciprocating[:, i] * lever_c[i])[:, None] * pistons[c.number]
    for t, position in enumerate(pins):
        weighted += pin_mass[:, t, None] * position
        levered += (pin_mass[:, t] * lever_t[t])[:, None] * position
    for number, position in knuckles.items():
        c = engine.cylinder(number)
        weighted += c.knuckle_kg * position
        levered += c.knuckle_kg * (c.z_m - mean_z) * position
    gain = (orders_of(samples) * engine.speed_rad_s) ** 2
    force = fourier(weighted) * gain
    moment = fourier(levered) * gain
    if basis is not None:
        force, moment = force + basis.fixed_force, moment + basis.fixed_moment
    return force, moment
