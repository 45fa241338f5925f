"""Free forces and moments, order by order, from the exact mass trajectories."""

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from ..errors import AnalysisError, OrderError
from ..harmonics import check_sampling, forward_backward, fourier, orders_of, synthesize
from ..kinematics import BALANCER, BIG_ENDS, COUNTERWEIGHT, CRANK, MassSet, kinematic_state
from ..tolerances import minimum_samples
from ..units import phasor_deg, wrap_degrees

if TYPE_CHECKING:
    from ..model import Engine

__all__ = [
    "DEFAULT_SAMPLES",
    "DEFAULT_MAX_ORDER",
    "MAX_SAMPLES",
    "OrderComponents",
    "Shaking",
    "shaking_forces",
    "ellipse",
    "check_settings",
    "part_values",
    "directional",
]

DEFAULT_SAMPLES = 256
DEFAULT_MAX_ORDER = 8
#: more samples than this cost memory for nothing: 256 already resolve orders to rounding
MAX_SAMPLES = 1 << 16


def check_settings(samples, max_order):
    """Raise AnalysisError unless ``samples`` and ``max_order`` are whole numbers that work
    together: max_order ≥ 1, and samples from 4·max_order + 1 to MAX_SAMPLES."""
    for name, value in (("max_order", max_order), ("samples", samples)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
            raise AnalysisError(f"must be a whole number, got {value!r}", name)
    if max_order < 1:
        raise AnalysisError(f"must be at least 1, got {max_order}", "max_order")
    highest = (MAX_SAMPLES - 1) // 4
    if minimum_samples(max_order) > MAX_SAMPLES:
        raise AnalysisError(
            f"must be at most {highest}: {MAX_SAMPLES} samples, the most, resolve "
            f"orders up to {highest}; got {max_order}",
            "max_order",
        )
    low = minimum_samples(max_order)
    if not low <= samples <= MAX_SAMPLES:
        raise AnalysisError(
            f"must be from {low} to {MAX_SAMPLES} for orders up to {max_order} "
            f"(more than four a revolution per order), got {samples}",
            "samples",
        )


def ellipse(forward, backward):
    """Largest and smallest magnitude over a revolution, and the major-axis angle (rad, [0, π))."""
    a, b = abs(forward), abs(backward)
    if a == 0.0 and b == 0.0:
        axis = 0.0
    else:
        # both phasors line up where kθ + arg X⁺ = −kθ + arg X⁻
        axis = (
            math.atan2(forward.imag, forward.real) + math.atan2(backward.imag, backward.real)
        ) / 2
        axis = math.radians(wrap_degrees(math.degrees(axis), 180.0))
    return a + b, abs(a - b), axis


def directional(forward, backward, vertical_rad=0.0):
    """The vertical and horizontal components of an order, as complex amplitudes.

    With X(θ) = X⁺·e^{ikθ} + X⁻·e^{−ikθ} and the vertical at ``vertical_rad`` from the
    reference axis, the vertical component is Re(X·e^{−iv}) = Re(A·e^{ikθ}) with
    A = X⁺·e^{−iv} + conj(X⁻·e^{−iv}), and the horizontal one (90° on from the vertical, with
    rotation) is Im(X·e^{−iv}) = Re(B·e^{ikθ}) with B = −i·(X⁺·e^{−iv} − conj(X⁻·e^{−iv})).
    Returns (A, B): each component is |A|·cos(kθ + arg A). Applied to a free moment, A is the
    moment of the vertical forces (pitching) and B that of the horizontal ones (yawing).
    """
    turn = complex(math.cos(vertical_rad), -math.sin(vertical_rad))
    ahead, behind = forward * turn, (backward * turn).conjugate()
    return ahead + behind, -1j * (ahead - behind)


def _component(amplitude, floor):
    """Size and phase of a scalar component Re(c·e^{ikθ}) = size·cos(kθ − phase), phase in
    degrees of kθ at the positive peak; noise as exact zeros."""
    if abs(amplitude) < floor:
        return 0.0, 0.0
    return abs(amplitude), phasor_deg(amplitude.conjugate())


def part_values(forward, backward, floor, unit, vertical_rad=0.0, components=True):
    """One quantity's entry of an order (the ``force`` or ``moment`` of ``compare``'s JSON):
    magnitudes, phases and ellipse of forward and backward phasors, and (with ``components``)
    the vertical and horizontal components, noise as exact zeros. ``axis_deg`` is None where
    the ellipse is a circle (one of the phasors is zero) or nothing is left: there is no
    axis."""

    def clean(z):
        return z if abs(z) >= floor else 0j

    forward, backward = clean(forward), clean(backward)
    largest, smallest, axis = ellipse(forward, backward)
    values = {
        f"forward_{unit}": abs(forward),
        "forward_deg": phasor_deg(forward),
        f"backward_{unit}": abs(backward),
        "backward_deg": phasor_deg(backward),
        f"max_{unit}": largest,
        f"min_{unit}": smallest if smallest >= floor else 0.0,
        "axis_deg": math.degrees(axis) if forward and backward else None,
    }
    if components:
        vertical, horizontal = directional(forward, backward, vertical_rad)
        v_size, v_phase = _component(vertical, floor)
        h_size, h_phase = _component(horizontal, floor)
        values.update(
            {
                f"vertical_{unit}": v_size,
                "vertical_deg": v_phase,
                f"horizontal_{unit}": h_size,
                "horizontal_deg": h_phase,
            }
        )
    return values


@dataclass(frozen=True)
class OrderComponents:
    """Forward and backward phasors of one order: X(θ) = X⁺·e^{ikθ} + X⁻·e^{−ikθ}.

    Forces in N, moments in N·m; complex, real part along the reference axis.
    """

    order: int
    force_forward: complex
    force_backward: complex
    moment_forward: complex
    moment_backward: complex

    def to_dict(
        self,
        noise_floor_n: float = 0.0,
        noise_floor_nm: float | None = None,
        vertical_rad: float = 0.0,
    ) -> dict:
        """The order as ``compare --format json`` writes it (SI). Forces below
        ``noise_floor_n`` (N) and moments below ``noise_floor_nm`` (N·m; default the same
        number) are rounding noise: exact zeros, phase 0. ``vertical_rad`` is the engine's
        vertical (:attr:`Engine.vertical_axis_rad`), from the reference axis."""
        floor_nm = noise_floor_n if noise_floor_nm is None else noise_floor_nm
        return {
            "order": self.order,
            "force": part_values(
                self.force_forward, self.force_backward, noise_floor_n, "N", vertical_rad
            ),
            "moment": part_values(
                self.moment_forward, self.moment_backward, floor_nm, "Nm", vertical_rad
            ),
        }


@dataclass(frozen=True)
class Shaking:
    """Shaking forces and free moments of an engine.

    Attributes
    ----------
    orders : tuple of OrderComponents
        orders 1..max_order
    force_coefficients, moment_coefficients : ndarray, complex, shape (N,)
        all Fourier coefficients of the resultant force (N) and free moment (N·m)
    sampling_ok : bool
        False when the highest orders still carried energy (a SamplingWarning was issued)
    mass_coefficients : ndarray, complex, shape (n_masses, N), or None
        each point mass's share of ``force_coefficients`` (None once a balancer is added)
    masses : MassSet or None
        the point masses those shares belong to
    """

    orders: tuple
    force_coefficients: np.ndarray
    moment_coefficients: np.ndarray
    sampling_ok: bool
    mass_coefficients: np.ndarray | None = None
    masses: MassSet | None = None

    @property
    def max_order(self) -> int:
        return len(self.orders)

    def records(self, engine: "Engine") -> list:
        """Every order's JSON record (:meth:`OrderComponents.to_dict`) with ``engine``'s noise
        floors and vertical: the one place orders become records."""
        return [
            o.to_dict(engine.noise_floor_n, engine.noise_floor_nm, engine.vertical_axis_rad)
            for o in self.orders
        ]

    def order(self, k: int) -> OrderComponents:
        """Order ``k`` (1-based); KeyError outside 1..max_order."""
        if (
            isinstance(k, bool)
            or not isinstance(k, (int, np.integer))
            or not 1 <= k <= self.max_order
        ):
            raise OrderError(
                f"order {k!r} is not among the orders analysed (1 to {self.max_order})", "k"
            )
        return self.orders[k - 1]

    def force(self, upsample=1, skip_forward_first=False, skip_backward_first=False):
        """The resultant force over one revolution (all orders), N, on a grid N·upsample;
        without the forward (backward) first order when ``skip_forward_first``
        (``skip_backward_first``): what ideal counterweights on a crankshaft turning with
        (against) the first take away."""
        return _over_revolution(
            self.force_coefficients, upsample, skip_forward_first, skip_backward_first
        )

    def largest_force(self, skip_forward_first=False, skip_backward_first=False) -> float:
        """Largest magnitude of the resultant force over a revolution, N."""
        return float(np.abs(self.force(16, skip_forward_first, skip_backward_first)).max())

    def moment(self, upsample=1, skip_forward_first=False, skip_backward_first=False):
        """The free moment over one revolution (all orders), N·m, on a grid N·upsample."""
        return _over_revolution(
            self.moment_coefficients, upsample, skip_forward_first, skip_backward_first
        )

    def largest_moment(self, skip_forward_first=False, skip_backward_first=False) -> float:
        """Largest magnitude of the free moment over a revolution, N·m."""
        return float(np.abs(self.moment(16, skip_forward_first, skip_backward_first)).max())

    def locus(self, order=None, skip_forward_first=False, points=None, skip_backward_first=False):
        """The resultant force over one revolution at ``points`` angles (default four times
        the samples; all orders need a multiple of them), N (complex: real along the reference
        axis); one order only if ``order`` is given."""
        n = self.force_coefficients.shape[-1]
        points = 4 * n if points is None else points
        if (
            isinstance(points, bool)
            or not isinstance(points, int)
            or points < 1
            or (order is None and points % n)
        ):
            raise AnalysisError(
                f"must be a positive multiple of the {n} samples, got {points!r}", "points"
            )
        if order is not None:
            o = self.order(order)
            theta = 2 * np.pi * np.arange(points) / points
            forward = 0j if (skip_forward_first and order == 1) else o.force_forward
            backward = 0j if (skip_backward_first and order == 1) else o.force_backward
            return forward * np.exp(1j * order * theta) + backward * np.exp(-1j * order * theta)
        return self.force(points // n, skip_forward_first, skip_backward_first)

    def cylinder_phasors(self, order: int) -> list[tuple[str, complex, complex]]:
        """Each cylinder's share of order ``order``: [(label, forward N, backward N)], the
        crank-pin masses together as "pins", counterweights as built as "counterweights" and
        balancer-shaft masses as "shafts"; they add up to the engine's phasors (the star)."""
        if self.mass_coefficients is None or self.masses is None:
            raise AnalysisError(
                "has no per-mass shares once a balancer is added; ask the engine's own analysis",
                "cylinder_phasors",
            )
        self.order(order)
        shares = []
        owners = self.masses.cylinder
        numbers: list[int | str] = list(dict.fromkeys(int(n) for n in owners if n > 0))
        groups = {
            "pins": (BIG_ENDS, CRANK),
            "counterweights": (COUNTERWEIGHT,),
            "shafts": (BALANCER,),
        }
        for number in numbers + list(groups):
            mine = np.isin(owners, groups[number]) if number in groups else owners == number
            if number in groups and not mine.any():
                continue
            shares.append(
                (
                    str(number),
                    complex(self.mass_coefficients[mine, order].sum()),
                    complex(self.mass_coefficients[mine, -order].sum()),
                )
            )
        return shares

    def cylinder_moment_phasors(
        self, order: int, mean_z_m: float
    ) -> list[tuple[str, complex, complex]]:
        """Each cylinder's share of the free moment of order ``order``: [(label, forward N·m,
        backward N·m)], each mass's force times its lever z − ``mean_z_m`` (the engine's z̄,
        which the moments were taken about); they add up to the engine's moment phasors."""
        if self.mass_coefficients is None or self.masses is None:
            raise AnalysisError(
                "has no per-mass shares once a balancer is added; ask the engine's own analysis",
                "cylinder_moment_phasors",
            )
        levered = replace(
            self, mass_coefficients=(self.masses.z_m - mean_z_m)[:, None] * self.mass_coefficients
        )
        return levered.cylinder_phasors(order)

    def moment_locus(
        self, order=None, skip_forward_first=False, points=None, skip_backward_first=False
    ):
        """The free moment over one revolution, N·m, at the angles :meth:`locus` takes for the
        force; ``skip_forward_first`` leaves out the forward first order (an ideal
        counterweight in two planes cancels that couple as it cancels the force)."""
        # the force locus of a copy whose forces are these moments: one path for both
        swapped = replace(
            self,
            force_coefficients=self.moment_coefficients,
            orders=tuple(
                replace(o, force_forward=o.moment_forward, force_backward=o.moment_backward)
                for o in self.orders
            ),
        )
        return swapped.locus(order, skip_forward_first, points, skip_backward_first)

    @classmethod
    def from_coefficients(
        cls, force, moment, max_order, sampling_ok=True, mass_coefficients=None, masses=None
    ):
        """Orders 1..max_order read off full coefficient arrays (N, N·m)."""
        orders = np.arange(1, max_order + 1)
        ff, fb = forward_backward(force, orders)
        mf, mb = forward_backward(moment, orders)
        table = tuple(
            OrderComponents(int(k), complex(ff[i]), complex(fb[i]), complex(mf[i]), complex(mb[i]))
            for i, k in enumerate(orders)
        )
        return cls(table, force, moment, sampling_ok, mass_coefficients, masses)

    def plus(self, order, forward=0j, backward=0j, forward_moment=0j, backward_moment=0j):
        """A copy with phasors added to ``order`` (N, N·m): a balancer's contribution."""
        force, moment = self.force_coefficients.copy(), self.moment_coefficients.copy()
        force[order] += forward
        force[-order] += backward
        moment[order] += forward_moment
        moment[-order] += backward_moment
        return Shaking.from_coefficients(force, moment, self.max_order, self.sampling_ok)


def _over_revolution(coefficients, upsample, skip_forward_first, skip_backward_first=False):
    """A signal over one revolution from its coefficients, on a grid N·upsample; without its
    forward (backward) first order when an ideal counterweight takes it."""
    c = coefficients.copy()
    if skip_forward_first:
        c[1] = 0.0
    if skip_backward_first:
        c[-1] = 0.0
    return synthesize(c, upsample)


def shaking_forces(
    engine: "Engine", samples: int = DEFAULT_SAMPLES, max_order: int = DEFAULT_MAX_ORDER
) -> Shaking:
    """Resultant shaking force and free moment of ``engine``, order by order.

    The force is the sum of the inertia forces −m·a of every point mass; the moment is
    Σ (z − z̄)·(−m·a), z̄ the mean axial position of the cylinders.

    Raises
    ------
    AnalysisError
        ``samples`` or ``max_order`` out of range (see :func:`check_settings`)
    ModelError
        a linkage that cannot be assembled
    """
    check_settings(samples, max_order)
    masses = kinematic_state(engine, samples).masses
    positions = fourier(masses.masses_kg[:, None] * masses.positions)
    # the inertia force −m·a has the coefficients of m·x times (kω)²
    per_mass = positions * (orders_of(samples) * engine.speed_rad_s) ** 2
    force = per_mass.sum(axis=0)
    moment = ((masses.z_m - engine.mean_z_m)[:, None] * per_mass).sum(axis=0)
    ok = check_sampling(positions, max_order, f"{engine.name}: ")
    return Shaking.from_coefficients(force, moment, max_order, ok, per_mass, masses)
