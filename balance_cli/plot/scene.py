"""What an animation of an engine shows, frame by frame: every point of its mechanism, the parts
that join them, its firings, and each cylinder's share of the forward and backward phasors of
every order.

The points come from the engine's one kinematic state
(:func:`~balance_cli.kinematics.kinematic_state`, the linkage closed once over a revolution, as
every analysis reads it): each piston pin, far piston and point mass is the state's own; a
crank pin or knuckle pin that carries no mass is where its rod's big end is, the small end less
the rod's length along the rod's direction (both the state's). The firing instants are the
same linkage closed at those angles (:func:`~balance_cli.kinematics.linkage_state`, which the
state itself is made of). The phasors are the analysis's own per-mass coefficients, grouped by
cylinder. The two renderers (the matplotlib movie and the HTML page) draw from a scene; neither
computes a position of its own.
"""

import math
from dataclasses import dataclass, field

import numpy as np

from ..analysis.firing import firing_angles
from ..checks import whole
from ..errors import PlotError
from ..kinematics import (
    BALANCER,
    BIG_ENDS,
    COUNTERWEIGHT,
    CRANK,
    crank_angles_of,
    kinematic_state,
    linkage_state,
    pin_angle,
)
from ..tolerances import NOISE_FLOOR

__all__ = ["Part", "Scene", "scene", "PART_KINDS", "PISTON_PIN_AT"]

#: what a scene's parts are: a crankshaft's axis, a crank (axis to pin), a rod (big end to
#: small end), a master rod's plate (crank pin to a knuckle pin), a piston, a cylinder's bore,
#: a counterweight and a balancer-shaft mass (each from its axis)
PART_KINDS = ("axis", "crank", "rod", "plate", "piston", "bore", "weight", "balancer")
#: where the piston pin sits along the piston, from its skirt, a fraction of its height
PISTON_PIN_AT = 0.35
#: a counterweight or balancer mass given by its unbalance alone is drawn at this fraction
#: of the crank radius from its axis (its direction is the state's)
_DRAWN_RADIUS = 0.7
#: the principal direction of the cylinders' axes is taken when their doubled angles add up
#: to at least this fraction of their number; else the engine's vertical
_PRINCIPAL_FLOOR = 0.05


@dataclass(frozen=True)
class Part:
    """One drawn part of the mechanism.

    Attributes
    ----------
    kind : str
        one of ``PART_KINDS``: axis, crank, rod, plate, piston, bore, weight, balancer
    points : tuple of str
        the names of its points in the scene's ``points`` or ``fixed``: (axis, pin)
        for a crank, (big end, small end) for a rod, (crank pin, knuckle pin) for a plate,
        (piston pin,) for a piston, (axis,) for an axis or a bore, (axis, mass) for a weight
        or a balancer mass
    z_m : float
        axial position, m (the side view's abscissa)
    cylinder : int
        the cylinder it belongs to (0 for none: a crank, an axis, a weight)
    axis_rad : float
        a piston's or bore's cylinder axis from the reference axis, rad, in the crankcase's
        frame (a rotary's turns with its crankcase, by the engine angle)
    outward : int
        a piston's crown faces along its axis (+1) or against it (−1: an opposed bore's far
        piston)
    span_m : tuple of float
        a bore's two ends, m from its axis point along its cylinder axis
    """

    kind: str
    points: tuple
    z_m: float = 0.0
    cylinder: int = 0
    axis_rad: float = 0.0
    outward: int = 1
    span_m: tuple = ()


@dataclass(frozen=True)
class Scene:
    """An engine's animation, as both renderers draw it.

    Attributes
    ----------
    name : str
        the engine's name
    cycle_deg : float
        the working cycle, degrees: 360 (two-stroke) or 720 (four-stroke)
    rotary : bool
        the crankcase turns (about a fixed crank)
    angles_rad : ndarray, shape (frames,)
        the engine angles of the frames over one revolution, rad; a four-stroke's second
        revolution shows them again
    points : dict
        each moving point's position at every frame, m, complex (real along the reference
        axis, imaginary across it, in the fixed frame): ``pN`` the piston pin of cylinder N,
        ``oN`` its far piston (an opposed bore), ``kN`` its knuckle pin (a link rod), ``tI``
        the crank pin of throw I, ``wI`` counterweight I, ``bI`` balancer-shaft mass I
    fixed : dict
        each fixed point, m, complex: ``cS`` the axis of crankshaft S, ``sI`` the axis of
        balancer shaft I
    z_m : dict
        each point's axial position, m
    parts : tuple of Part
    events : tuple of (float, int)
        (engine angle in the cycle, degrees; cylinder number) of each firing, in the cycle's
        order
    event_points : dict
        each moving point's position at each firing (as ``points``), m, complex
    bore_m, piston_m : float
        the drawn pistons' width and height, m
    end_box : tuple of float
        (left, right, bottom, top) of the end view, m: x across the reference axis, y along it
    side_rad : float or None
        the side view's vertical, rad from the reference axis (the direction the pistons move
        along most); None: no side view (a radial, a rotary: one row of cylinders)
    side_box : tuple of float
        (left, right, bottom, top) of the side view, m: x axial, y along ``side_rad``
    orders : tuple of int
        the orders of the phasor tables, 1..max_order
    groups : tuple of dict
        each share of the phasors: ``label``, ``cylinder`` (its number, 0 for the crank pins'
        masses, the counterweights and the balancer shafts, which no cylinder carries),
        ``z_m`` and ``reciprocating_kg`` (a cylinder's, for z̄ and the noise floor) and
        ``toggle`` (a cylinder that can be left out: not a master rod's, which carries link
        rods, nor a share of no cylinder)
    force : ndarray, complex, shape (groups, orders, 2)
        each share's forward and backward force phasor of each order, N
    moment : ndarray, complex, shape (groups, orders, 2)
        each share's forward and backward moment phasor about the whole engine's z̄,
        Σ (z − z̄)·F, N·m
    mean_z_m : float
        the whole engine's z̄, m
    unit_n : float
        r·ω², m/s²: a mass's m·r·ω² is the force unit of the noise floor
    """

    name: str
    cycle_deg: float
    rotary: bool
    angles_rad: np.ndarray
    points: dict
    fixed: dict
    z_m: dict
    parts: tuple
    events: tuple
    event_points: dict
    bore_m: float
    piston_m: float
    end_box: tuple
    side_rad: float | None
    side_box: tuple
    orders: tuple
    groups: tuple
    force: np.ndarray
    moment: np.ndarray
    mean_z_m: float
    unit_n: float
    crank_radius_m: float = field(default=0.0)

    @property
    def frames(self) -> int:
        """Frames a revolution."""
        return len(self.angles_rad)

    def at(self, angle_deg: float) -> dict:
        """Every point's position at engine angle ``angle_deg``: a firing's own positions when
        it is one of :attr:`events`' angles, else the nearest frame's, m (complex)."""
        for i, (angle, _) in enumerate(self.events):
            if abs(angle - angle_deg) < 1e-9:
                return {name: values[i] for name, values in self.event_points.items()}
        index = round(angle_deg / 360.0 * self.frames) % self.frames
        return {name: values[index] for name, values in self.points.items()}

    def shares(self, left_out=(), orders=None):
        """The forward and backward force (N) and moment (N·m) phasors of each order with the
        cylinders ``left_out`` left out, as :func:`balance_cli.analyse` finds them for the
        engine without those cylinders: their shares subtracted, the moment taken about the
        remaining cylinders' mean z̄. Returns two arrays, complex, shape (orders, 2)."""
        kept = np.array([g["cylinder"] not in left_out for g in self.groups])
        cylinders = [g for g in self.groups if g["cylinder"] and g["cylinder"] not in left_out]
        mean = sum(g["z_m"] for g in cylinders) / len(cylinders)
        force = self.force[kept].sum(axis=0)
        # Σ (z − z̄')·F = Σ (z − z̄)·F − (z̄' − z̄)·Σ F
        moment = self.moment[kept].sum(axis=0) - (mean - self.mean_z_m) * force
        if orders is not None:
            index = [self.orders.index(k) for k in orders]
            force, moment = force[index], moment[index]
        return force, moment

    def noise_floors(self, left_out=()):
        """The noise floors of the engine without the cylinders ``left_out``, as its analysis
        has them: (N, N·m)."""
        cylinders = [g for g in self.groups if g["cylinder"] and g["cylinder"] not in left_out]
        mass = sum(g["reciprocating_kg"] for g in cylinders)
        floor = NOISE_FLOOR * mass * self.unit_n
        mean = sum(g["z_m"] for g in cylinders) / len(cylinders)
        lever = max(self.crank_radius_m, max(abs(g["z_m"] - mean) for g in cylinders))
        return floor, floor * lever


def scene(result, frames: int = 180) -> Scene:
    """The :class:`Scene` of an analysed engine (a result of :func:`balance_cli.analyse`), at
    ``frames`` evenly spaced engine angles a revolution (at least 4).

    Raises
    ------
    PlotError
        ``frames`` that are not a whole number from 4 to 3600, or a result without per-mass
        phasors (one that a balancer was added to)
    """
    frames = whole(frames, "frames", 4, 3600, error=PlotError)
    engine = result.engine
    shaking = result.shaking
    if shaking.mass_coefficients is None or shaking.masses is None:
        raise PlotError(
            "has no per-cylinder phasors (a balancer was added to it); animate the engine's "
            "own analysis",
            "result",
        )
    state = kinematic_state(engine, frames)
    points = _points(engine, state.masses, state.rods, state.angles_rad)
    by_cylinder = firing_angles(engine)
    events = tuple(sorted((float(a), n) for n, a in by_cylinder.items()))
    at = np.radians([a for a, _ in events]) % (2 * np.pi)
    closed = linkage_state(engine, at)
    event_points = _points(engine, closed.masses, closed.rods, at)
    bore, height = _piston_size(engine)
    parts, fixed, z = _parts(engine, points, state.angles_rad, bore, height)
    groups, force, moment = _shares(engine, shaking)
    side = _side_direction(engine)
    return Scene(
        name=engine.name,
        cycle_deg=engine.cycle_deg,
        rotary=engine.is_rotary,
        angles_rad=state.angles_rad,
        points=points,
        fixed=fixed,
        z_m=z,
        parts=parts,
        events=events,
        event_points=event_points,
        bore_m=bore,
        piston_m=height,
        end_box=_end_box(engine, points, fixed, parts, bore, height),
        side_rad=side,
        side_box=() if side is None else _side_box(points, fixed, z, parts, side, bore, height),
        orders=tuple(o.order for o in shaking.orders),
        groups=groups,
        force=force,
        moment=moment,
        mean_z_m=engine.mean_z_m,
        unit_n=engine.crank_radius_m * engine.speed_rad_s**2,
        crank_radius_m=engine.crank_radius_m,
    )


def _rows(owners, number):
    return np.flatnonzero(owners == number)


def _points(engine, masses, rods, angles):
    """Every moving point at ``angles`` from a closed linkage's masses and rods (see the module
    text): pistons and masses as they are, big ends back along their rods."""
    out = {}
    pins: dict[int, np.ndarray] = {}
    for c in engine.cylinders:
        mine = _rows(masses.cylinder, c.number)
        rod_rows = _rows(rods.cylinder, c.number)
        piston = masses.positions[mine[0]]
        out[f"p{c.number}"] = piston
        # the big end: the small end less the rod along its direction (a rod's length is its
        # pins' distance)
        length = c.link_length_m if c.is_link else engine.rod_length_m
        big_end = piston - length * rods.directions[rod_rows[0]]
        if c.is_link:
            out[f"k{c.number}"] = big_end
        else:
            pins.setdefault(c.throw_index, big_end)
        if c.is_opposed:
            far = masses.positions[mine[-1]]
            out[f"o{c.number}"] = far
            pins.setdefault(
                c.opposed_throw_index, far - engine.rod_length_m * rods.directions[rod_rows[1]]
            )
    for i in range(len(engine.throws)):
        if i in pins:
            continue
        at_pin = np.flatnonzero(
            np.isin(masses.cylinder, (BIG_ENDS, CRANK)) & (masses.throw_index == i)
        )
        if at_pin.size:
            pins[i] = masses.positions[at_pin[0]]
        else:
            # a throw that carries neither a cylinder nor a mass: its pin from the crank's
            # own angle (nothing of the state is at it)
            crank = crank_angles_of(engine, angles)
            pin = engine.crank_radius_m * np.exp(1j * pin_angle(engine, i, crank))
            pins[i] = pin + engine.crankshaft_of(i).centre
    for i in sorted(pins):
        out[f"t{i + 1}"] = pins[i]
    for name, owner in (("w", COUNTERWEIGHT), ("b", BALANCER)):
        for j, row in enumerate(_rows(masses.cylinder, owner), 1):
            out[f"{name}{j}"] = masses.positions[row]
    return out


def _piston_size(engine):
    """The drawn piston's width (its bore: the [gas] table's, else the stroke's 0.9) and
    height, m."""
    bore = engine.gas.bore_m if engine.gas is not None else 1.8 * engine.crank_radius_m
    return bore, 0.6 * bore


def _parts(engine, points, angles, bore, height):
    """The parts, the fixed points and every point's axial position."""
    r = engine.crank_radius_m
    fixed = {f"c{s}": shaft.centre for s, shaft in enumerate(engine.crankshafts, 1)}
    z = {}
    parts = [Part("axis", (f"c{s}",)) for s in range(1, len(engine.crankshafts) + 1)]
    for i, throw in enumerate(engine.throws):
        centre = f"c{throw.crankshaft}"
        z[f"t{i + 1}"] = throw.z_m
        parts.append(Part("crank", (centre, f"t{i + 1}"), throw.z_m))
    for c in engine.cylinders:
        axis = engine.bank_angles_rad[c.bank_index]
        centre = f"c{engine.throws[c.throw_index].crankshaft}"
        z[f"p{c.number}"] = c.z_m
        travel = _along(points[f"p{c.number}"], fixed[centre], axis, engine, angles)
        near, far = travel.min() - PISTON_PIN_AT * height, travel.max() + 0.7 * height
        if c.is_opposed:
            z[f"o{c.number}"] = c.z_m
            travel = _along(points[f"o{c.number}"], fixed[centre], axis, engine, angles)
            far = travel.max() + PISTON_PIN_AT * height
        parts.append(Part("bore", (centre,), c.z_m, c.number, axis, 1, (near, far)))
        if c.is_link:
            z[f"k{c.number}"] = c.z_m
            master = engine.cylinder(c.master)
            parts.append(Part("plate", (f"t{master.throw}", f"k{c.number}"), c.z_m, c.master))
            big_end = f"k{c.number}"
        else:
            big_end = f"t{c.throw}"
        parts.append(Part("rod", (big_end, f"p{c.number}"), c.z_m, c.number))
        parts.append(Part("piston", (f"p{c.number}",), c.z_m, c.number, axis, 1))
        if c.is_opposed:
            parts.append(Part("rod", (f"t{c.opposed_throw}", f"o{c.number}"), c.z_m, c.number))
            parts.append(Part("piston", (f"o{c.number}",), c.z_m, c.number, axis, -1))
    for j, weight in enumerate(engine.counterweights, 1):
        z[f"w{j}"] = engine.counterweight_z_m(weight)
        centre = f"c{engine.throws[weight.throw_index].crankshaft}"
        _drawn(points, f"w{j}", fixed[centre], weight.radius_m, r)
        parts.append(Part("weight", (centre, f"w{j}"), z[f"w{j}"]))
    j = 0
    for s, shaft in enumerate(engine.balancer_shafts, 1):
        fixed[f"s{s}"] = engine.balancer_centre(shaft)
        for mass in shaft.masses:
            j += 1
            z[f"b{j}"] = engine.balancer_z_m(mass)
            _drawn(points, f"b{j}", fixed[f"s{s}"], mass.eccentricity_m, r)
            parts.append(Part("balancer", (f"s{s}", f"b{j}"), z[f"b{j}"]))
    return tuple(parts), fixed, z


def _drawn(points, name, centre, radius, crank_radius):
    """A mass known by its unbalance alone sits a micrometre from its axis: drawn instead at
    :data:`_DRAWN_RADIUS` of the crank radius, in the state's direction."""
    if radius is not None:
        return
    offset = points[name] - centre
    points[name] = centre + _DRAWN_RADIUS * crank_radius * offset / np.abs(offset)


def _along(position, centre, axis, engine, angles):
    """Distance of ``position`` from ``centre`` along the cylinder axis at ``axis`` (rad, the
    crankcase's frame; a rotary's turns by the engine angle), m, at engine angles
    ``angles``."""
    offset = position - centre
    if engine.is_rotary:
        offset = offset * np.exp(-1j * angles)
    return (offset * np.exp(-1j * axis)).real


def _end_box(engine, points, fixed, parts, bore, height):
    """The end view's extent, (left, right, bottom, top), m: every point, every bore and
    crank circle, with a margin."""
    xs: list[float] = []
    ys: list[float] = []

    def add(values):
        values = np.asarray(values).ravel()
        xs.extend((values.imag.min(), values.imag.max()))
        ys.extend((values.real.min(), values.real.max()))

    for values in points.values():
        add(values)
    for value in fixed.values():
        add([value + engine.crank_radius_m * np.exp(1j * a) for a in np.linspace(0, 6.3, 16)])
    for part in parts:
        if part.kind != "bore":
            continue
        centre = fixed[part.points[0]]
        turns = np.linspace(0, 2 * np.pi, 73) if engine.is_rotary else [0.0]
        for turn in turns:
            direction = np.exp(1j * (part.axis_rad + turn))
            across = 1j * direction * bore / 2
            for end in part.span_m:
                add([centre + end * direction + across, centre + end * direction - across])
    left, right, bottom, top = min(xs), max(xs), min(ys), max(ys)
    margin = 0.05 * max(right - left, top - bottom)
    return (left - margin, right + margin, bottom - margin, top + margin)


def _side_direction(engine):
    """The side view's vertical, rad from the reference axis: the direction the cylinders'
    axes lie along most (half the angle of the sum of their doubled angles), else the
    engine's vertical; None for an engine of one row (all its cylinders in one plane) or a
    rotary, which the end view shows whole."""
    zs = {round(c.z_m, 9) for c in engine.cylinders}
    if engine.is_rotary or len(zs) < 2:
        return None
    total = sum(np.exp(2j * engine.bank_angles_rad[c.bank_index]) for c in engine.cylinders)
    if abs(total) < _PRINCIPAL_FLOOR * engine.n_cylinders:
        return engine.vertical_axis_rad
    return float(np.angle(total) / 2)


def _side_box(points, fixed, z, parts, side, bore, height):
    """The side view's extent, (left, right, bottom, top), m: x axial, y along ``side``."""
    turn = np.exp(-1j * side)
    ys = [float((values * turn).real.min()) for values in points.values()]
    ys += [float((values * turn).real.max()) for values in points.values()]
    ys += [float((value * turn).real) for value in fixed.values()]
    for part in parts:
        if part.kind == "bore":
            centre = fixed[part.points[0]]
            for end in part.span_m:
                ys.append(float((centre * turn + end * math.cos(part.axis_rad - side)).real))
    zs = list(z.values())
    half = bore / 2
    left, right = min(zs) - half, max(zs) + half
    bottom, top = min(ys), max(ys)
    margin = 0.05 * max(right - left, top - bottom)
    return (left - margin, right + margin, bottom - margin, top + margin)


def _shares(engine, shaking):
    """Each cylinder's (and the crank pins', counterweights' and balancer shafts') share of
    every order: forward and backward force phasors, N, and moment phasors about z̄, N·m."""
    masses = shaking.masses
    coefficients = shaking.mass_coefficients
    orders = np.arange(1, shaking.max_order + 1)
    lever = (masses.z_m - engine.mean_z_m)[:, None]
    masters = {c.master for c in engine.cylinders if c.is_link}
    groups, force, moment = [], [], []

    def add(label, mine, cylinder=0, z_m=0.0, reciprocating_kg=0.0):
        if not mine.any():
            return
        groups.append(
            {
                "label": label,
                "cylinder": cylinder,
                "z_m": z_m,
                "reciprocating_kg": reciprocating_kg,
                "toggle": bool(cylinder) and cylinder not in masters,
            }
        )
        shares = coefficients[mine]
        pair = np.stack([shares[:, orders].sum(axis=0), shares[:, -orders].sum(axis=0)], -1)
        levered = lever[mine] * shares
        moments = np.stack([levered[:, orders].sum(axis=0), levered[:, -orders].sum(axis=0)], -1)
        force.append(pair)
        moment.append(moments)

    for c in engine.cylinders:
        add(str(c.number), masses.cylinder == c.number, c.number, c.z_m, c.reciprocating_kg)
    add("crank pins", np.isin(masses.cylinder, (BIG_ENDS, CRANK)))
    add("counterweights", masses.cylinder == COUNTERWEIGHT)
    add("balancer shafts", masses.cylinder == BALANCER)
    return tuple(groups), np.array(force), np.array(moment)
