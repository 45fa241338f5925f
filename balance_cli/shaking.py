"""Free forces and moments, order by order, from the exact mass trajectories."""

import math
from dataclasses import dataclass

import numpy as np

from .harmonics import check_sampling, forward_backward, fourier, synthesize
from .kinematics import engine_angles, mass_positions

__all__ = ["OrderComponents", "Shaking", "shaking", "ellipse", "cylinder_phasors",
           "mean_cylinder_z", "per_mass_force_coefficients"]

DEFAULT_SAMPLES = 256
DEFAULT_MAX_ORDER = 8


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


def ellipse(forward, backward):
    """Largest and smallest magnitude over a revolution, and the major-axis angle (rad, mod π)."""
    a, b = abs(forward), abs(backward)
    if a == 0.0 and b == 0.0:
        axis = 0.0
    else:
        # both phasors line up where kθ + arg X⁺ = −kθ + arg X⁻
        axis = (math.atan2(forward.imag, forward.real) + math.atan2(backward.imag, backward.real)) / 2
        axis %= math.pi
    return a + b, abs(a - b), axis


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
    """

    orders: tuple
    force_coefficients: np.ndarray
    moment_coefficients: np.ndarray
    sampling_ok: bool

    def force(self, upsample=1, skip_forward_first=False):
        """The resultant force over one revolution (all orders), N, on a grid N·upsample."""
        c = self.force_coefficients.copy()
        if skip_forward_first:
            c[1] = 0.0
        return synthesize(c, upsample)

    def largest_force(self, skip_forward_first=False):
        """Largest magnitude of the resultant force over a revolution, N."""
        return float(np.abs(self.force(16, skip_forward_first)).max())

    def locus(self, order=None, skip_forward_first=False, points=720):
        """The resultant force over one revolution at ``points`` angles, N (complex: real along
        the reference axis); one order only if ``order`` is given."""
        theta = 2 * np.pi * np.arange(points) / points
        if order is not None:
            o = self.orders[order - 1]
            forward = 0j if (skip_forward_first and order == 1) else o.force_forward
            return forward * np.exp(1j * order * theta) + o.force_backward * np.exp(-1j * order * theta)
        n = self.force_coefficients.shape[-1]
        if points % n:
            raise ValueError(f"points must be a multiple of the {n} samples")
        return self.force(points // n, skip_forward_first)

    @classmethod
    def from_coefficients(cls, force, moment, max_order, sampling_ok=True):
        """Orders 1..max_order read off full coefficient arrays (N, N·m)."""
        orders = np.arange(1, max_order + 1)
        ff, fb = forward_backward(force, orders)
        mf, mb = forward_backward(moment, orders)
        table = tuple(
            OrderComponents(int(k), complex(ff[i]), complex(fb[i]), complex(mf[i]), complex(mb[i]))
            for i, k in enumerate(orders)
        )
        return cls(table, force, moment, sampling_ok)

    def plus(self, order, forward=0j, backward=0j, forward_moment=0j, backward_moment=0j):
        """A copy with phasors added to ``order`` (N, N·m): a balancer's contribution."""
        force, moment = self.force_coefficients.copy(), self.moment_coefficients.copy()
        force[order] += forward
        force[-order] += backward
        moment[order] += forward_moment
        moment[-order] += backward_moment
        return Shaking.from_coefficients(force, moment, len(self.orders), self.sampling_ok)


def mean_cylinder_z(engine):
    """z̄, the axial position free moments are taken about: the cylinders' mean, m."""
    return float(np.mean([c.z_m for c in engine.cylinders]))


def _inertia_coefficients(weighted_positions, speed_rad_s):
    """Coefficients of −Σ m·a from coefficients of Σ m·x: multiply by (kω)²."""
    coefficients = fourier(weighted_positions)
    n = coefficients.shape[-1]
    k = np.fft.fftfreq(n, 1.0 / n)
    return coefficients * (k * speed_rad_s) ** 2


def shaking(engine, samples=DEFAULT_SAMPLES, max_order=DEFAULT_MAX_ORDER):
    """Resultant shaking force and free moment of ``engine``, order by order.

    The force is the sum of the inertia forces −m·a of every point mass; the moment is
    Σ (z − z̄)·(−m·a), z̄ the mean axial position of the cylinders.
    """
    if max_order >= samples // 4:
        raise ValueError(
            f"--max-order {max_order} needs more than {4 * max_order} samples; raise --samples"
        )
    per_mass, masses = per_mass_force_coefficients(engine, samples)
    force = per_mass.sum(axis=0)
    moment = ((masses.z_m - mean_cylinder_z(engine))[:, None] * per_mass).sum(axis=0)
    ok = check_sampling(per_mass, max_order, f"{engine.name}: ")
    return Shaking.from_coefficients(force, moment, max_order, ok)


def cylinder_phasors(engine, order, samples=DEFAULT_SAMPLES):
    """Each cylinder's share of order ``order``: [(label, forward N, backward N)], the crank-pin
    masses together as "pins"; they add up to the engine's phasors (the star diagram)."""
    coefficients, masses = per_mass_force_coefficients(engine, samples)
    shares = []
    for number in [c.number for c in engine.cylinders] + ["pins"]:
        mine = masses.cylinder <= 0 if number == "pins" else masses.cylinder == number
        if number == "pins" and not mine.any():
            continue
        shares.append((str(number), complex(coefficients[mine, order].sum()),
                       complex(coefficients[mine, -order].sum())))
    return shares


def per_mass_force_coefficients(engine, samples=DEFAULT_SAMPLES):
    """Fourier coefficients of each point mass's inertia force, N, and the mass set."""
    masses = mass_positions(engine, engine_angles(samples))
    weights = masses.masses_kg[:, None] * masses.positions
    return _inertia_coefficients(weights, engine.speed_rad_s), masses
