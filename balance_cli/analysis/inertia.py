"""The reduced mass μ(θ) and angular momentum of the moving parts, from the kinematic state.

The kinetic energy of the exact motion is T = ½·μ(θ)·θ̇², with μ(θ) = Σ m·|dx/dθ|² +
Σ C·(dβ/dθ)² + I_shaft summed over the point masses (x their positions in the fixed frame),
the rods' correcting moments of inertia C (β a rod's angle) and the shaft's own inertia; the
angular momentum about the crank axis is H = θ̇·h(θ), h = Σ m·Im(x̄·dx/dθ) + Σ C·dβ/dθ + I_shaft.
"""

import numpy as np

from ..harmonics import periodic_derivative

__all__ = ["reduced_mass_and_momentum", "parts_of_crankshaft"]


def parts_of_crankshaft(engine, state, crankshaft):
    """The parts of ``state`` that crankshaft ``crankshaft`` (0-based index) drives: its
    throws' masses and rods (a balancer-shaft mass, on throw −1, rides on no crankshaft)."""
    shaft_of = np.array([t.crankshaft_index for t in engine.throws])
    throws = state.masses.throw_index
    return state.parts(
        (throws >= 0) & (shaft_of[throws] == crankshaft),
        shaft_of[state.rods.throw_index] == crankshaft,
    )


def reduced_mass_and_momentum(engine, state, crankshaft=None):
    """μ(θ) and h(θ) = H/θ̇ over one revolution of the kinematic ``state`` (or of a subset of
    its parts, :meth:`~balance_cli.kinematics.KinematicState.parts`), kg·m²; of the parts one
    ``crankshaft`` (an index) drives, if given. The crankshaft and flywheel inertia
    (``Engine.shaft_inertia_kgm2``) belongs to the first (output) crankshaft."""
    if crankshaft is not None:
        state = parts_of_crankshaft(engine, state, crankshaft)
    masses, rods = state.masses, state.rods
    rates = periodic_derivative(masses.positions)
    weights = masses.masses_kg[:, None]
    mu = (weights * np.abs(rates) ** 2).sum(axis=0)
    h = (weights * (np.conj(masses.positions) * rates).imag).sum(axis=0)
    if np.any(rods.corrections_kgm2):
        # a rod's angular rate from its unit vector u: dβ/dθ = Im(ū·du/dθ)
        turning = (np.conj(rods.directions) * periodic_derivative(rods.directions)).imag
        corrections = rods.corrections_kgm2[:, None]
        mu = mu + (corrections * turning**2).sum(axis=0)
        h = h + (corrections * turning).sum(axis=0)
    shaft = engine.shaft_inertia_kgm2 if crankshaft in (None, 0) else 0.0
    return mu + shaft, h + shaft
