"""The animation's picture at any instant, drawn by matplotlib: the mechanism seen along the
crank axis (and from the side), and the phasor panels, every artist moved to an engine angle by
:meth:`Drawing.update`. A movie is this picture at each of its frames (:mod:`.animation`)."""

import math

import numpy as np

from ..units import significant
from .figure import short
from .scene import PISTON_PIN_AT, Scene

__all__ = ["Drawing", "FIRING_MARK_DEG", "magnitude"]

#: a cylinder is marked as firing for this many degrees after its firing top dead centre
FIRING_MARK_DEG = 45.0

#: colours: forward (blue) and backward (red) as in the star picture; their sum black
_FORWARD, _BACKWARD, _SUM = "C0", "C3", "k"
_PISTON, _FIRE, _ROD, _CRANK = "#d9d9d9", "#ff8c00", "#4a6f8a", "#555555"


def magnitude(value, unit):
    """A phasor's size for a label: four significant figures and its unit."""
    return f"{significant(value)} {unit}"


class Drawing:
    """The artists of one figure: the end view, the side view (when the scene has one), and
    the phasor panels, moved to any engine angle of the cycle by :meth:`update`."""

    def __init__(self, fig, view: Scene, orders):
        self.view = view
        force, moment = view.shares(orders=orders)
        floor_n, floor_nm = view.noise_floors()
        # what analyse calls rounding noise is drawn as nothing
        force = np.where(np.abs(force) < floor_n, 0j, force)
        moment = np.where(np.abs(moment) < floor_nm, 0j, moment)
        fig.suptitle(short(view.name, 80), fontsize=10, y=0.99)
        self.clock = fig.text(0.5, 0.935, "", ha="center", fontsize=8, color="0.3")
        top = (0.36, 0.53)
        if view.side_rad is None:
            self.views = [_View(fig.add_axes((0.25, top[0], 0.5, top[1])), view, None)]
        else:
            self.views = [
                _View(fig.add_axes((0.01, top[0], 0.48, top[1])), view, None),
                _View(fig.add_axes((0.51, top[0], 0.48, top[1])), view, view.side_rad),
            ]
        width = 0.98 / (2 * len(orders) + 2)
        self.panels: list = []
        for row, (name, values, floor, unit) in enumerate(
            (("F", force, floor_n, "N"), ("M", moment, floor_nm, "N·m"))
        ):
            for i in range(len(orders) + 1):
                ax = fig.add_axes((0.01 + (row * (len(orders) + 1) + i) * width, 0.02, width, 0.26))
                if i < len(orders):
                    self.panels.append(
                        _OrderPanel(ax, f"{name}{orders[i]}", orders[i], values[i], unit)
                    )
                else:
                    title = "+".join(f"{name}{k}" for k in orders)
                    self.panels.append(_SumPanel(ax, title, orders, values, floor, unit))

    def update(self, angle_deg, traced=True):
        """Every moving artist at engine angle ``angle_deg`` (degrees of the cycle)."""
        view = self.view
        points = view.at(angle_deg)
        firing = [n for a, n in view.events if (angle_deg - a) % view.cycle_deg < FIRING_MARK_DEG]
        turned = math.radians(angle_deg) if view.rotary else 0.0
        artists = [self.clock]
        for drawn in self.views:
            artists += drawn.update(points, turned, firing)
        theta = math.radians(angle_deg)
        for panel in self.panels:
            artists += panel.update(theta)
        fires = f"; firing: {', '.join(map(str, firing))}" if firing else ""
        self.clock.set_text(f"engine angle {angle_deg:.0f}° of {view.cycle_deg:.0f}°{fires}")
        return artists


#: how each linking part is drawn
_STYLES = {
    "bore": dict(color="0.7", linewidth=0.8, zorder=1),
    "crank": dict(color=_CRANK, linewidth=3.0, solid_capstyle="round", zorder=3),
    "rod": dict(color=_ROD, linewidth=1.6, solid_capstyle="round", zorder=3),
    "plate": dict(color=_ROD, linewidth=2.4, solid_capstyle="round", zorder=3),
    "weight": dict(color="k", linewidth=2.0, marker="o", markevery=[1], markersize=6, zorder=3),
    "balancer": dict(color="C2", linewidth=1.5, marker="o", markevery=[1], markersize=5, zorder=3),
}


class _View:
    """The mechanism seen along the crank axis (``side`` None: x across the reference axis, y
    along it) or from the side (x axial, y along ``side``, rad)."""

    def __init__(self, ax, view: Scene, side):
        from matplotlib.patches import Polygon

        self.view, self.side = view, side
        ax.set_axis_off()
        box = view.end_box if side is None else view.side_box
        ax.set_xlim(box[0], box[1])
        ax.set_ylim(box[2], box[3])
        ax.set_aspect("equal", adjustable="box")
        ax.set_title(
            "seen along the crank axis" if side is None else "seen from the side", fontsize=8
        )
        self.lines, self.pistons = {}, {}
        for index, part in enumerate(view.parts):
            if part.kind in _STYLES:
                (self.lines[index],) = ax.plot([], [], **_STYLES[part.kind])
            elif part.kind == "piston":
                patch = Polygon(
                    np.zeros((4, 2)),
                    closed=True,
                    facecolor=_PISTON,
                    alpha=0.85,
                    edgecolor="0.3",
                    linewidth=0.8,
                    zorder=2,
                )
                self.pistons[index] = ax.add_patch(patch)
        (self.pins,) = ax.plot(
            [], [], linestyle="none", marker="o", markersize=2.5, color="k", zorder=4
        )
        (self.sparks,) = ax.plot(
            [], [], linestyle="none", marker="*", markersize=11, color=_FIRE, zorder=5
        )
        axes = [self._xy(value, 0.0) for value in view.fixed.values()]
        ax.plot(*zip(*axes, strict=True), linestyle="none", marker="+", color="k", markersize=7)
        self.case = None
        if side is None:
            for value in view.fixed.values():
                ring = value + view.crank_radius_m * np.exp(1j * np.linspace(0, 2 * np.pi, 73))
                ax.plot(ring.imag, ring.real, color="0.85", linewidth=0.6, zorder=0)
            if view.rotary:
                (self.case,) = ax.plot([], [], color="0.45", linewidth=1.2, zorder=1)

    def _xy(self, value, z):
        """(x, y) of a point at ``value`` (m, complex) and axial position ``z`` (m)."""
        if self.side is None:
            return value.imag, value.real
        return z, (value * complex(math.cos(self.side), -math.sin(self.side))).real

    def update(self, points, turned, firing):
        view = self.view
        where = {**view.fixed, **points}
        pins, sparks = [], []
        for index, line in self.lines.items():
            part = view.parts[index]
            if part.kind == "bore":
                line.set_data(*self._bore(part, where, turned))
            else:
                ends = [self._xy(where[p], view.z_m.get(p, part.z_m)) for p in part.points]
                line.set_data([e[0] for e in ends], [e[1] for e in ends])
        for index, patch in self.pistons.items():
            part = view.parts[index]
            pin = where[part.points[0]]
            corners, crown = self._piston(part, pin, turned)
            patch.set_xy(corners)
            fires = part.cylinder in firing and part.outward == 1
            patch.set_facecolor(_FIRE if fires else _PISTON)
            pins.append(self._xy(pin, part.z_m))
            if fires:
                sparks.append(crown)
        self.pins.set_data([p[0] for p in pins], [p[1] for p in pins])
        self.sparks.set_data([p[0] for p in sparks], [p[1] for p in sparks])
        moved = [*self.lines.values(), *self.pistons.values(), self.pins, self.sparks]
        if self.case is not None:
            self.case.set_data(*self._case(turned))
            moved.append(self.case)
        return moved

    def _piston(self, part, pin, turned):
        """The piston's corners and the middle above its crown, (x, y): a rectangle of the
        bore's width and the piston's height along its axis, its pin at
        :data:`PISTON_PIN_AT` of the height from the skirt."""
        view = self.view
        u = np.exp(1j * (part.axis_rad + turned)) * part.outward
        low, high = -PISTON_PIN_AT * view.piston_m, (1 - PISTON_PIN_AT) * view.piston_m
        spark = high + 0.3 * view.piston_m
        if self.side is None:
            across = 1j * u * view.bore_m / 2
            corners = [pin + low * u - across, pin + high * u - across]
            corners += [pin + high * u + across, pin + low * u + across]
            crown = pin + spark * u
            return [(c.imag, c.real) for c in corners], (crown.imag, crown.real)
        x, y = self._xy(pin, part.z_m)
        along = (u * complex(math.cos(self.side), -math.sin(self.side))).real
        half = view.bore_m / 2
        bottom, top = y + low * along, y + high * along
        return [(x - half, bottom), (x - half, top), (x + half, top), (x + half, bottom)], (
            x,
            y + spark * along,
        )

    def _bore(self, part, where, turned):
        """The bore's two walls, as one line broken by a NaN."""
        view = self.view
        centre = where[part.points[0]]
        near, far = part.span_m
        half = 0.52 * view.bore_m
        if self.side is None:
            u = np.exp(1j * (part.axis_rad + turned))
            walls = [centre + near * u + 1j * u * half, centre + far * u + 1j * u * half]
            walls += [math.nan, centre + near * u - 1j * u * half, centre + far * u - 1j * u * half]
            return np.imag(walls), np.real(walls)
        c = self._xy(centre, part.z_m)[1]
        along = math.cos(part.axis_rad - self.side)
        z, ends = part.z_m, [c + near * along, c + far * along, math.nan]
        return [z - half, z - half, math.nan, z + half, z + half], ends[:2] + ends

    def _case(self, turned):
        """A rotary's crankcase: the polygon of its cylinders' feet, turning with it."""
        view = self.view
        axes = sorted({round(p.axis_rad, 12) for p in view.parts if p.kind == "bore"})
        radius = min(p.span_m[0] for p in view.parts if p.kind == "bore")
        corners = [radius * np.exp(1j * (a + turned)) for a in axes]
        corners.append(corners[0])
        return np.imag(corners), np.real(corners)


class _OrderPanel:
    """One order's forward phasor (blue), its backward phasor from the forward's tip (red),
    their sum (dashed), and the ellipse the sum traces (grey)."""

    def __init__(self, ax, title, k, phasors, unit):
        self.k = k
        self.forward, self.backward = phasors
        largest = abs(self.forward) + abs(self.backward)
        _panel(ax, f"{title}: {magnitude(largest, unit) if largest else 'none'}", largest)
        theta = np.linspace(0, 2 * np.pi, 121)
        path = self.forward * np.exp(1j * k * theta) + self.backward * np.exp(-1j * k * theta)
        ax.plot(path.imag, path.real, color="0.8", linewidth=0.8)
        tip = dict(marker="o", markevery=[1], markersize=3) if largest else {}
        (self.f_line,) = ax.plot([], [], color=_FORWARD, linewidth=1.6, **tip)
        (self.b_line,) = ax.plot([], [], color=_BACKWARD, linewidth=1.6, **tip)
        (self.s_line,) = ax.plot([], [], color=_SUM, linewidth=1.0, linestyle="--")

    def update(self, theta):
        f = self.forward * np.exp(1j * self.k * theta)
        total = f + self.backward * np.exp(-1j * self.k * theta)
        self.f_line.set_data([0, f.imag], [0, f.real])
        self.b_line.set_data([f.imag, total.imag], [f.real, total.real])
        self.s_line.set_data([0, total.imag], [0, total.real])
        return [self.f_line, self.b_line, self.s_line]


class _SumPanel:
    """The resultant of the orders shown: its locus over a revolution (grey), the part traced
    since the revolution began (orange) and its value now (black)."""

    def __init__(self, ax, title, orders, phasors, floor, unit):
        self.orders, self.phasors = np.array(orders), phasors
        self.theta = np.linspace(0, 2 * np.pi, 361)
        path = self._value(self.theta)
        largest = float(np.abs(path).max())
        largest = largest if largest >= floor else 0.0
        _panel(ax, f"{title}: {magnitude(largest, unit) if largest else 'none'}", largest)
        ax.plot(path.imag, path.real, color="0.8", linewidth=0.8)
        (self.trace,) = ax.plot([], [], color="C1", linewidth=1.5)
        tip = dict(marker="o", markevery=[1], markersize=3) if largest else {}
        (self.now,) = ax.plot([], [], color=_SUM, linewidth=1.6, **tip)

    def _value(self, theta):
        turns = np.exp(1j * self.orders * np.asarray(theta)[..., None])
        return (self.phasors[:, 0] * turns + self.phasors[:, 1] / turns).sum(-1)

    def update(self, theta):
        done = self.theta[self.theta <= theta % (2 * np.pi)]
        path = self._value(np.append(done, theta % (2 * np.pi)))
        self.trace.set_data(path.imag, path.real)
        self.now.set_data([0, path[-1].imag], [0, path[-1].real])
        return [self.trace, self.now]


def _panel(ax, title, largest):
    """A phasor panel: no axes, equal scales with room round the largest phasor, a cross at
    the origin."""
    ax.set_axis_off()
    limit = 1.15 * largest if largest else 1.0
    ax.set_xlim(-limit, limit)
    ax.set_ylim(-limit, limit)
    ax.set_aspect("equal", adjustable="box")
    ax.set_title(title, fontsize=7)
    ax.plot([0], [0], marker="+", color="0.5", markersize=5)
