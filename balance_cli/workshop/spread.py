"""The spread of a quantity over many runs, and the closed-form spread of its linear part.

**Monte Carlo.** Mean, median, 95th and 99th percentiles and largest of the runs' values, with
their sampling error: the standard error of the mean (s/√N) and, for each percentile, the 95 %
interval between the order statistics at ranks N·p ∓ 1.96·√(N·p·(1 − p)), which holds for any
distribution.

**Closed form.** For small scatter each complex amplitude Q (an order's vertical or horizontal
component) is linear in the scattered values: Q = Q₀ + Σⱼ gⱼ·ξⱼ, ξⱼ independent standard
normals, gⱼ its derivative times the value's standard deviation (exact for masses, from a
central difference for dimensions). Its real and imaginary parts are then normal with the
covariance C = Σⱼ (Re gⱼ, Im gⱼ)ᵀ(Re gⱼ, Im gⱼ). Where Q₀ is nothing (a balanced order), |Q|
has the distribution of the length of a zero-mean normal vector of covariance C: with
eigenvalues λ₁, λ₂, |Q|² = R²·q(φ), R² a chi-square of two degrees of freedom and φ uniform,
q(φ) = λ₁·cos²φ + λ₂·sin²φ, so P(|Q| ≤ ρ) = mean over φ of 1 − exp(−ρ²/(2·q(φ))) and
E|Q| = √(π/2)·mean over φ of √q(φ) = √(2/π)·√λ₁·E(1 − λ₂/λ₁) (E the complete elliptic integral
of the second kind); the distribution's integrand is smooth and periodic, so the trapezoidal
rule converges fast. One direction only (λ₂ = 0) is the half-normal: mean σ√(2/π), 95th percentile
1.96·σ. Where Q₀ is not nothing, |Q| ≈ |Q₀| + the normal part of Σ gⱼξⱼ along Q₀ (linearised
about the nominal), so its percentiles are |Q₀| + z_p·s.
"""

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Stats", "Linear", "stats_of", "linear_of", "PERCENTILES"]

#: the percentiles reported, and their standard normal quantiles
PERCENTILES = {95: 1.6448536269514722, 99: 2.3263478740408408}
_MEDIAN_Z = 0.0
#: points of the trapezoidal rule over φ
_PHI_POINTS = 720


@dataclass(frozen=True)
class Stats:
    """A quantity's spread over the runs (its own unit)."""

    mean: float
    median: float
    p95: float
    p99: float
    max: float
    std: float
    mean_error: float
    p95_interval: tuple
    p99_interval: tuple

    def to_dict(self, unit) -> dict:
        return {
            f"mean_{unit}": self.mean,
            f"median_{unit}": self.median,
            f"p95_{unit}": self.p95,
            f"p99_{unit}": self.p99,
            f"max_{unit}": self.max,
            f"std_{unit}": self.std,
            f"mean_error_{unit}": self.mean_error,
            f"p95_interval_{unit}": list(self.p95_interval),
            f"p99_interval_{unit}": list(self.p99_interval),
        }


def _interval(ordered, p):
    """The 95 % interval of the p-quantile: order statistics at N·p ∓ 1.96·√(N·p·(1 − p))."""
    n = len(ordered)
    half = 1.96 * math.sqrt(n * p * (1 - p))
    low = max(0, math.floor(n * p - half) - 1)
    high = min(n - 1, math.ceil(n * p + half) - 1)
    return float(ordered[low]), float(ordered[high])


def stats_of(values) -> Stats:
    """The spread of ``values`` (one per run)."""
    values = np.asarray(values, float)
    ordered = np.sort(values)
    n = len(values)
    std = float(values.std(ddof=1)) if n > 1 else 0.0
    return Stats(
        mean=float(values.mean()),
        median=float(np.median(values)),
        p95=float(np.quantile(values, 0.95)),
        p99=float(np.quantile(values, 0.99)),
        max=float(ordered[-1]),
        std=std,
        mean_error=std / math.sqrt(n),
        p95_interval=_interval(ordered, 0.95),
        p99_interval=_interval(ordered, 0.99),
    )


@dataclass(frozen=True)
class Linear:
    """The closed-form spread of a magnitude |Q| from the linear part of Q (see the module).

    ``nominal`` is |Q₀|, ``rms`` √(Σ|gⱼ|²) (the root mean square of Q − Q₀), ``model``
    "zero-mean" (Q₀ is nothing) or "about the nominal"; mean, median and percentiles of |Q|.
    """

    nominal: float
    rms: float
    model: str
    mean: float
    median: float
    p95: float
    p99: float

    def to_dict(self, unit) -> dict:
        return {
            f"nominal_{unit}": self.nominal,
            f"rms_{unit}": self.rms,
            "model": self.model,
            f"mean_{unit}": self.mean,
            f"median_{unit}": self.median,
            f"p95_{unit}": self.p95,
            f"p99_{unit}": self.p99,
        }


def _zero_mean(variances):
    """Mean, median, 95th and 99th percentile of |X|, X a zero-mean normal vector in the plane
    whose covariance has eigenvalues ``variances`` (the module's formulas)."""
    from scipy.special import ellipe

    phi = 2 * np.pi * np.arange(_PHI_POINTS) / _PHI_POINTS
    q = variances[0] * np.cos(phi) ** 2 + variances[1] * np.sin(phi) ** 2
    # mean over φ of √q(φ) = (2/π)·√λ₁·E(1 − λ₂/λ₁), E the complete elliptic integral of the
    # second kind (exact, where the trapezoidal rule meets the kink of a degenerate q)
    small, large = sorted(variances)
    mean = (
        math.sqrt(math.pi / 2) * 2 / math.pi * math.sqrt(large) * float(ellipe(1 - small / large))
    )
    top = math.sqrt(max(variances)) * 8.0

    safe = np.where(q > 0, q, 1.0)

    def cdf(rho):
        """P(|X| ≤ ρ) for each of ``rho``."""
        inside = np.exp(-(rho[:, None] ** 2) / (2 * safe))
        return (1.0 - np.where(q > 0, inside, 0.0)).mean(axis=1)

    # bisection of the three quantiles at once, to 2⁻⁶⁰ of the bracket
    wanted = np.array([0.5, 0.95, 0.99])
    low, high = np.zeros(3), np.full(3, top)
    for _ in range(60):
        middle = (low + high) / 2
        below = cdf(middle) < wanted
        low, high = np.where(below, middle, low), np.where(below, high, middle)
    median, p95, p99 = (low + high) / 2
    return mean, float(median), float(p95), float(p99)


def linear_of(nominal: complex, gradients: np.ndarray, floor: float) -> Linear:
    """The closed-form spread of |Q| for Q = ``nominal`` + Σ ``gradients``·ξ (complex, one per
    scattered value); a nominal below ``floor`` is nothing."""
    gradients = np.asarray(gradients, complex)
    rms = float(np.sqrt(np.sum(np.abs(gradients) ** 2)))
    size = abs(nominal)
    if size < floor or rms == 0.0 and size < floor:
        if rms == 0.0:
            return Linear(0.0, 0.0, "zero-mean", 0.0, 0.0, 0.0, 0.0)
        parts = np.vstack([gradients.real, gradients.imag])
        covariance = parts @ parts.T
        variances = np.clip(np.linalg.eigvalsh(covariance), 0.0, None)
        mean, median, p95, p99 = _zero_mean(variances)
        return Linear(0.0, rms, "zero-mean", mean, median, p95, p99)
    along = nominal / size
    spread = float(np.sqrt(np.sum((gradients * np.conj(along)).real ** 2)))
    return Linear(
        size,
        rms,
        "about the nominal",
        size,
        size + _MEDIAN_Z * spread,
        size + PERCENTILES[95] * spread,
        size + PERCENTILES[99] * spread,
    )
