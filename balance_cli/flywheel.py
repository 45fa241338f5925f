"""Speed fluctuation of an engine driving a load: Margoulis (1920), the steadiness factor.

The speed ω(θ) over a cycle obeys Lagrange's equation for the crank angle θ,

    (I + μ(θ))·ω·dω/dθ = C(θ) − ½·μ'(θ)·ω² − L(ω),

with I the flywheel (and propeller) inertia, μ(θ) the reduced mass of the engine's moving parts,
C the driving torque (the gas torque, or a measured torque curve with μ = 0) and L the load:
ℓ·ω² for a propeller (ℓ = C_m/ω_m²) or the constant C_m. In u = ω² it is linear,

    du/dθ = (2·C − (μ' + 2ℓ)·u) / (I + μ)         (propeller)
    d((I + μ)·u)/dθ = 2·(C − C_m)                 (constant load),

so its periodic solution is written in closed form with an integrating factor, its integrals
taken by scipy's cumulative trapezoidal rule on a grid sixteen times finer than the torque's
samples: for the propeller u(0) = u(P) fixes the constant; for a constant load the constant is
chosen for the given mean speed. (A general-purpose ODE solver, tried first, needed seconds
to follow a torque made of thousands of linear pieces: this takes milliseconds.) The steadiness
factor is ω_m/(ω_max − ω_min).

Margoulis's closed forms, for C = C_m + (ΔC/2)·sin(Nθ/2) and constant μ: r_c = ω²·N·I/(2ΔC)
(constant load), r_v = 2·C_m/ΔC (no inertia), r_h = √(r_c² + r_v²) (propeller); N is twice the
order of the torque's largest harmonic (the number of cylinders of an evenly firing
four-stroke).
"""

import math
from dataclasses import dataclass

import numpy as np

from .errors import AnalysisError
from .units import check_finite_range, rad_s_to_rpm

__all__ = ["LOADS", "Steadiness", "steadiness", "flywheel_for"]

LOADS = ("propeller", "constant")


@dataclass(frozen=True)
class Steadiness:
    """The periodic speed of an engine set, and Margoulis's factors.

    Attributes
    ----------
    theta_deg, speed_rad_s : ndarray
        the speed over one period
    inertia_kgm2 : float
        I, the flywheel and propeller (not the engine's moving parts), kg·m²
    load : str
        "propeller" or "constant"
    mean_torque_nm, torque_range_nm : float
        C_m and ΔC of the driving torque, N·m
    order : float
        the order of the driving torque's largest harmonic (N = 2·order in the closed forms)
    reduced_mass_kgm2 : float
        the mean reduced mass added to I in the closed forms, kg·m²
    """

    theta_deg: np.ndarray
    speed_rad_s: np.ndarray
    inertia_kgm2: float
    load: str
    mean_torque_nm: float
    torque_range_nm: float
    order: float
    reduced_mass_kgm2: float = 0.0

    @property
    def mean_speed_rad_s(self) -> float:
        return float(self.speed_rad_s.mean())

    @property
    def factor(self) -> float:
        """ω_m/(ω_max − ω_min), integrated."""
        spread = float(self.speed_rad_s.max() - self.speed_rad_s.min())
        return math.inf if spread == 0.0 else self.mean_speed_rad_s / spread

    def margoulis(self) -> dict:
        """Margoulis's closed forms r_c, r_v, r_h at the mean speed."""
        if self.torque_range_nm == 0.0:
            return {"r_c": math.inf, "r_v": math.inf, "r_h": math.inf}
        omega = self.mean_speed_rad_s
        inertia = self.inertia_kgm2 + self.reduced_mass_kgm2
        r_c = omega**2 * 2 * self.order * inertia / (2 * self.torque_range_nm)
        r_v = 2 * self.mean_torque_nm / self.torque_range_nm
        return {"r_c": r_c, "r_v": r_v, "r_h": math.hypot(r_c, r_v)}

    def to_dict(self) -> dict:
        """What ``steadiness --format json`` writes (speeds in rpm, torques in N·m)."""
        return {
            "mean_speed_rpm": rad_s_to_rpm(self.mean_speed_rad_s),
            "min_speed_rpm": rad_s_to_rpm(float(self.speed_rad_s.min())),
            "max_speed_rpm": rad_s_to_rpm(float(self.speed_rad_s.max())),
            "steadiness": self.factor,
            **self.margoulis(),
            "mean_torque_Nm": self.mean_torque_nm,
            "torque_range_Nm": self.torque_range_nm,
            "order": self.order,
            "inertia_kgm2": self.inertia_kgm2,
            "reduced_mass_kgm2": self.reduced_mass_kgm2,
            "load": self.load,
        }


def _periodic(values, period):
    """A callable θ -> value (linear between samples, periodic) of samples over one period."""
    n = len(values)
    x = np.arange(n + 1) * period / n
    y = np.append(values, values[0])
    return lambda theta: np.interp(np.mod(theta, period), x, y)


def _dominant_order(torque, period_deg):
    c = np.abs(np.fft.rfft(torque))
    c[0] = 0.0
    return int(np.argmax(c)) * 360.0 / period_deg


def steadiness(torque_nm, period_deg, inertia_kgm2, speed_rad_s, load="propeller",
               reduced_mass_kgm2=None) -> Steadiness:
    """The periodic speed of an engine driving a load.

    Parameters
    ----------
    torque_nm : array
        the driving torque at evenly spaced crank angles over one period, N·m (the engine's
        gas torque, or a measured torque curve)
    period_deg : float
        360 or 720
    inertia_kgm2 : float
        flywheel and propeller, kg·m² (> 0)
    speed_rad_s : float
        the mean speed, rad/s (the propeller's ℓ = C_m/ω² is taken at it)
    load : str
        "propeller" (ℓ·ω²) or "constant" (C_m)
    reduced_mass_kgm2 : array, optional
        μ(θ) of the engine's moving parts at the same angles as the torque (or one revolution
        of it); its inertia torque −½·μ'·ω² then acts at the actual speed

    Raises
    ------
    AnalysisError
        a parameter out of range, a load that is not one of LOADS, or a torque whose mean is
        not positive under a propeller
    """
    from scipy.integrate import cumulative_trapezoid   # only the steadiness needs scipy

    torque = np.asarray(torque_nm, dtype=float)
    if torque.ndim != 1 or len(torque) < 8 or not np.all(np.isfinite(torque)):
        raise AnalysisError("must be at least 8 finite values over one period", "torque_nm")
    for name, value, dimension in (("inertia_kgm2", inertia_kgm2, "moment of inertia"),
                                   ("speed_rad_s", speed_rad_s, "angular speed")):
        if isinstance(value, bool) or not isinstance(value, (int, float)) or value <= 0:
            raise AnalysisError(f"must be a number greater than zero, got {value!r}", name)
        try:
            check_finite_range(float(value), dimension)
        except Exception as exc:   # UnitError: out of the accepted range
            raise AnalysisError(f"is invalid: {exc}", name) from None
    if load not in LOADS:
        raise AnalysisError(f"must be one of {', '.join(LOADS)}, got {load!r}", "load")
    scale = float(np.abs(torque).max())
    if float(torque.max() - torque.min()) <= 1e-12 * scale:
        raise AnalysisError("does not vary over the cycle: the speed is constant and the steadiness "
                            "infinite; give a torque that varies", "torque_nm")
    period = math.radians(period_deg)
    n = len(torque)
    theta = np.arange(n) * period / n
    mu = np.zeros(n) if reduced_mass_kgm2 is None else np.resize(np.asarray(reduced_mass_kgm2), n)
    k = np.fft.fftfreq(n, 1.0 / n) * (2 * math.pi / period)
    mu_rate = np.fft.ifft(np.fft.fft(mu) * 1j * k).real
    mean_torque = float(torque.mean())
    if abs(mean_torque) <= 1e-12 * scale:
        mean_torque = 0.0   # rounding: a torque that averages out
    drive, rate, total = _periodic(torque, period), _periodic(mu_rate, period), _periodic(mu, period)
    if load == "propeller":
        if mean_torque <= 0:
            raise AnalysisError(f"has a mean of {mean_torque:.4g} N·m: a propeller absorbs only a "
                                "positive mean torque", "torque_nm")
        ell = mean_torque / speed_rad_s**2

        def slope(angle, u):
            return (2 * drive(angle) - (rate(angle) + 2 * ell) * u) / (inertia_kgm2 + total(angle))

        # the periodic solution of u' + g·u = f in closed form, u = e^(−G)·(u₀ + ∫f·e^G),
        # u₀ = e^(−G(P))·∫₀ᴾ f·e^G / (1 − e^(−G(P))), the integrals by scipy's cumulative
        # trapezoidal rule on a grid sixteen times finer than the torque's samples
        fine = np.linspace(0.0, period, 16 * n + 1)
        g = (rate(fine) + 2 * ell) / (inertia_kgm2 + total(fine))
        f = 2 * drive(fine) / (inertia_kgm2 + total(fine))
        big_g = cumulative_trapezoid(g, fine, initial=0.0)
        if big_g[-1] > 200:   # e^G would reach the limits of floating point
            raise AnalysisError("is too small for this torque and load: the speed could not "
                                "settle within the cycle; give a larger one", "inertia_kgm2")
        if big_g[-1] < 1e-12:   # 1 − e^(−G) lost to rounding
            raise AnalysisError("is too large for this propeller: its load could not hold the "
                                "speed within a cycle; give a smaller one", "inertia_kgm2")
        big_f = cumulative_trapezoid(f * np.exp(big_g), fine, initial=0.0)
        start = np.exp(-big_g[-1]) * big_f[-1] / (1 - np.exp(-big_g[-1]))
        u = np.interp(theta, fine, np.exp(-big_g) * (start + big_f))
    else:
        from scipy.optimize import brentq

        fine = np.linspace(0.0, period, 16 * n + 1)
        excess = 2 * (drive(fine) - mean_torque)
        integral = np.interp(theta, fine, cumulative_trapezoid(excess, fine, initial=0.0))
        inertia = inertia_kgm2 + mu
        lowest = float(np.max(-integral))   # (I + μ)·u must stay positive

        def mean_speed(constant):
            return float(np.sqrt((constant + integral) / inertia).mean()) - speed_rad_s

        top = lowest + inertia.max() * speed_rad_s**2 * 4 + 1.0
        if mean_speed(lowest) >= 0:
            # even a speed touching zero once a cycle averages more than the mean asked for
            raise AnalysisError("is too small for this torque: the engine would stop within the "
                                "cycle; give a larger one", "inertia_kgm2")
        constant = brentq(mean_speed, lowest, top, xtol=1e-14 * top)
        u = (constant + integral) / inertia
    if not np.all(np.isfinite(u)) or np.any(u <= 0):
        raise AnalysisError("is too small for this torque: the engine would stop within the "
                            "cycle; give a larger one", "inertia_kgm2")
    return Steadiness(np.degrees(theta), np.sqrt(u), float(inertia_kgm2), load, mean_torque,
                      float(torque.max() - torque.min()), _dominant_order(torque, period_deg),
                      float(mu.mean()))


def flywheel_for(target, torque_nm, period_deg, speed_rad_s, load="propeller",
                 reduced_mass_kgm2=None) -> float:
    """The flywheel inertia I (kg·m²) at which the integrated steadiness is ``target`` (0 when
    the smallest inertia tried, 1e-9 kg·m², already reaches it)."""
    from scipy.optimize import brentq

    if isinstance(target, bool) or not isinstance(target, (int, float)) or not target > 0.5:
        raise AnalysisError(f"must be a steadiness above ½ (the least there is), got {target!r}",
                            "target")

    def excess(inertia):
        try:
            factor = steadiness(torque_nm, period_deg, inertia, speed_rad_s, load,
                                reduced_mass_kgm2).factor
        except AnalysisError:
            return -target   # the engine stops within the cycle: far too little inertia
        return factor - target if math.isfinite(factor) else -target

    low, high = 1e-9, 1.0
    if excess(low) >= 0:
        return 0.0
    while excess(high) < 0:
        high *= 10
        if high > 1e9:
            raise AnalysisError(f"{target:g} is out of reach with this torque and load", "target")
    found = brentq(excess, low, high, xtol=1e-14, rtol=1e-10)
    # below some inertia the engine stops: the root finder then lands on that edge, where the
    # steadiness jumps past the target instead of meeting it
    reached = excess(found) + target
    if abs(reached - target) > 1e-3 * target:
        raise AnalysisError(f"{target:g} is below the least steadiness this torque and load allow "
                            f"before the engine stops (about {reached:.4g}, with {found:.4g} kg·m²); "
                            "ask for more", "target")
    return found
