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

from ..checks import curve, is_real, positive
from ..errors import AnalysisError
from ..tabular import Tabular
from ..units import rad_s_to_rpm

__all__ = ["LOADS", "Steadiness", "steadiness", "flywheel_for"]

LOADS = ("propeller", "constant")


@dataclass(frozen=True)
class Steadiness(Tabular):
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
    base_rad_s, deviation : float, ndarray, optional
        the speed as base·(1 + deviation): a fluctuation of 1e-20 of the speed is lost to
        rounding in ω itself but not in its deviation, from which the steadiness is taken
    """

    theta_deg: np.ndarray
    speed_rad_s: np.ndarray
    inertia_kgm2: float
    load: str
    mean_torque_nm: float
    torque_range_nm: float
    order: float
    reduced_mass_kgm2: float = 0.0
    base_rad_s: float | None = None
    deviation: np.ndarray | None = None

    def _parts(self):
        if self.deviation is None:
            speed = self.speed_rad_s
            return float(speed.mean()), speed / speed.mean() - 1.0
        return self.base_rad_s, self.deviation

    @property
    def min_speed_rad_s(self) -> float:
        base, d = self._parts()
        return base * (1.0 + float(d.min()))

    @property
    def max_speed_rad_s(self) -> float:
        base, d = self._parts()
        return base * (1.0 + float(d.max()))

    @property
    def mean_speed_rad_s(self) -> float:
        # rounding is monotonic, so min ≤ mean ≤ max holds for the numbers written as well
        base, d = self._parts()
        return base * (1.0 + float(np.clip(d.mean(), d.min(), d.max())))

    @property
    def factor(self) -> float:
        """ω_m/(ω_max − ω_min), integrated; inf only when the speed does not vary at all."""
        _, d = self._parts()
        spread = float(d.max() - d.min())
        return math.inf if spread == 0.0 else (1.0 + float(d.mean())) / spread

    def margoulis(self) -> dict:
        """Margoulis's closed forms r_c, r_v, r_h at the mean speed (None beyond a double)."""
        if self.torque_range_nm == 0.0:
            return {"r_c": None, "r_v": None, "r_h": None}
        omega = self.mean_speed_rad_s
        inertia = self.inertia_kgm2 + self.reduced_mass_kgm2
        r_c = omega**2 * 2 * self.order * inertia / (2 * self.torque_range_nm)
        r_v = 2 * self.mean_torque_nm / self.torque_range_nm
        forms = {"r_c": r_c, "r_v": r_v, "r_h": math.hypot(r_c, r_v)}
        return {k: (v if math.isfinite(v) else None) for k, v in forms.items()}

    def records(self) -> list:
        """One row: :meth:`to_dict`'s figures (speeds in rpm, torques in N·m, inertias in
        kg·m²; the steadiness and Margoulis's r_c, r_v, r_h as pure numbers)."""
        return [self.to_dict()]

    def to_dict(self) -> dict:
        """What ``steadiness --format json`` writes (speeds in rpm, torques in N·m); every
        number finite (JSON has no Infinity)."""
        factor = self.factor
        return {
            "mean_speed_rpm": rad_s_to_rpm(self.mean_speed_rad_s),
            "min_speed_rpm": rad_s_to_rpm(self.min_speed_rad_s),
            "max_speed_rpm": rad_s_to_rpm(self.max_speed_rad_s),
            "steadiness": factor if math.isfinite(factor) else None,
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


def steadiness(
    torque_nm, period_deg, inertia_kgm2, speed_rad_s, load="propeller", reduced_mass_kgm2=None
) -> Steadiness:
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
    from scipy.integrate import cumulative_trapezoid  # only the steadiness needs scipy

    torque = _curve(torque_nm, "torque_nm")
    if len(torque) < 8:
        raise AnalysisError("must be at least 8 finite values over one period", "torque_nm")
    period_deg = _period(period_deg)
    inertia_kgm2 = _positive(inertia_kgm2, "inertia_kgm2", "moment of inertia")
    speed_rad_s = _positive(speed_rad_s, "speed_rad_s", "angular speed")
    if not isinstance(load, str) or load not in LOADS:
        raise AnalysisError(f"must be one of {', '.join(LOADS)}, got {load!r}", "load")
    scale = float(np.abs(torque).max())
    if float(torque.max() - torque.min()) <= 1e-12 * scale:
        raise AnalysisError(
            "does not vary over the cycle: the speed is constant and the steadiness "
            "infinite; give a torque that varies",
            "torque_nm",
        )
    period = math.radians(period_deg)
    n = len(torque)
    theta = np.arange(n) * period / n
    mu = _reduced_mass(reduced_mass_kgm2, n, period_deg)
    k = np.fft.fftfreq(n, 1.0 / n) * (2 * math.pi / period)
    mu_rate = np.fft.ifft(np.fft.fft(mu) * 1j * k).real
    mean_torque = float(torque.mean())
    if abs(mean_torque) <= 1e-12 * scale:
        mean_torque = 0.0  # rounding: a torque that averages out
    drive, rate, total = (
        _periodic(torque, period),
        _periodic(mu_rate, period),
        _periodic(mu, period),
    )
    # the speed is written base·(1 + deviation), the deviation from logarithms of ratios
    # close to 1 (log1p, expm1): ω itself cannot resolve a fluctuation below 1e-16 of it,
    # which made a steadiness of 1e17 "inf" and a mean speed below the minimum
    if load == "propeller":
        if mean_torque <= 0:
            raise AnalysisError(
                f"has a mean of {mean_torque:.4g} N·m: a propeller absorbs only a "
                "positive mean torque",
                "torque_nm",
            )
        ell = mean_torque / speed_rad_s**2

        # the periodic solution of u' + g·u = f in closed form, u = e^(−G)·(u₀ + F), F = ∫f·e^G,
        # u₀ = F(P)/(e^G(P) − 1), the integrals by scipy's cumulative trapezoidal rule on a
        # grid sixteen times finer than the torque's samples; u/u₀ = e^(−G)·(1 + F/u₀)
        fine = np.linspace(0.0, period, 16 * n + 1)
        g = (rate(fine) + 2 * ell) / (inertia_kgm2 + total(fine))
        f = 2 * drive(fine) / (inertia_kgm2 + total(fine))
        big_g = cumulative_trapezoid(g, fine, initial=0.0)
        if big_g[-1] > 200:  # e^G would reach the limits of floating point
            raise AnalysisError(
                "is too small for this torque and load: the speed could not "
                "settle within the cycle; give a larger one",
                "inertia_kgm2",
            )
        if not big_g[-1] > 0:  # no damping within a cycle: no periodic solution to pick
            raise AnalysisError(
                "is too large for this propeller: its load could not hold the "
                "speed within a cycle; give a smaller one",
                "inertia_kgm2",
            )
        big_f = cumulative_trapezoid(f * np.exp(big_g), fine, initial=0.0)
        start = big_f[-1] / math.expm1(big_g[-1])
        ratio = big_f / start
        if not start > 0 or np.any(ratio <= -1):
            raise AnalysisError(
                "is too small for this torque: the engine would stop within the "
                "cycle; give a larger one",
                "inertia_kgm2",
            )
        base = math.sqrt(start)
        deviation = np.expm1(0.5 * np.interp(theta, fine, np.log1p(ratio) - big_g))
    else:
        from scipy.optimize import brentq

        fine = np.linspace(0.0, period, 16 * n + 1)
        excess = 2 * (drive(fine) - mean_torque)
        integral = np.interp(theta, fine, cumulative_trapezoid(excess, fine, initial=0.0))
        inertia = inertia_kgm2 + mu
        lowest = float(np.max(-integral))  # (I + μ)·u must stay positive

        def mean_speed(constant):
            return float(np.sqrt((constant + integral) / inertia).mean()) - speed_rad_s

        top = lowest + inertia.max() * speed_rad_s**2 * 4 + 1.0
        if mean_speed(lowest) >= 0:
            # even a speed touching zero once a cycle averages more than the mean asked for
            raise AnalysisError(
                "is too small for this torque: the engine would stop within the "
                "cycle; give a larger one",
                "inertia_kgm2",
            )
        constant = brentq(mean_speed, lowest, top, xtol=1e-14 * top)
        if not constant > 0 or np.any(integral / constant <= -1):
            raise AnalysisError(
                "is too small for this torque: the engine would stop within the "
                "cycle; give a larger one",
                "inertia_kgm2",
            )
        # ω² = K·(1 + J/K)/(I_m·(1 + (μ − μ̄)/I_m)), I_m = I + μ̄
        mean_inertia = float(inertia.mean())
        base = math.sqrt(constant / mean_inertia)
        deviation = np.expm1(
            0.5
            * (np.log1p(integral / constant) - np.log1p((inertia - mean_inertia) / mean_inertia))
        )
    speed = base * (1.0 + deviation)
    if not (math.isfinite(base) and np.all(np.isfinite(deviation)) and np.all(speed > 0)):
        raise AnalysisError(
            "is too small for this torque: the engine would stop within the "
            "cycle; give a larger one",
            "inertia_kgm2",
        )
    result = Steadiness(
        np.degrees(theta),
        speed,
        float(inertia_kgm2),
        load,
        mean_torque,
        float(torque.max() - torque.min()),
        _dominant_order(torque, period_deg),
        float(mu.mean()),
        base,
        deviation,
    )
    if not math.isfinite(result.factor):
        # the deviation itself vanished: beyond what a double resolves even this way
        raise AnalysisError(
            "makes the speed vary by less than a double resolves (its "
            "steadiness beyond 1e300); give a smaller one or a torque that "
            "varies more",
            "inertia_kgm2",
        )
    return result


def _curve(values, name):
    return curve(values, name)


def _real(value):
    return is_real(value)


def _period(period_deg):
    if not _real(period_deg) or float(period_deg) not in (360.0, 720.0):
        raise AnalysisError(
            f"must be 360 (a two-stroke's cycle) or 720 (a four-stroke's), got {period_deg!r}",
            "period_deg",
        )
    return float(period_deg)


def _positive(value, name, dimension):
    return positive(value, name, dimension)


def _reduced_mass(values, n, period_deg):
    """μ at the torque's n angles: given there, or over one revolution of a four-stroke's
    cycle (and then repeated); other lengths were once tiled without a word."""
    if values is None:
        return np.zeros(n)
    mu = _curve(values, "reduced_mass_kgm2")
    turns = int(period_deg // 360)
    if len(mu) == n:
        pass
    elif turns == 2 and n % 2 == 0 and len(mu) == n // 2:
        mu = np.tile(mu, 2)
    else:
        one = f" or {n // 2} (one revolution)" if turns == 2 and n % 2 == 0 else ""
        raise AnalysisError(
            f"must have as many values as the torque, {n}{one}, got {len(mu)}", "reduced_mass_kgm2"
        )
    if np.any(mu < 0):
        raise AnalysisError(
            "must not be negative: it is a kinetic energy's coefficient", "reduced_mass_kgm2"
        )
    return mu


def flywheel_for(
    target, torque_nm, period_deg, speed_rad_s, load="propeller", reduced_mass_kgm2=None
) -> float:
    """The flywheel inertia I (kg·m²) at which the integrated steadiness is ``target`` (0 when
    the smallest inertia tried, 1e-9 kg·m², already reaches it)."""
    from scipy.optimize import brentq

    if not _real(target) or not 0.5 < target < math.inf:
        raise AnalysisError(
            f"must be a steadiness above ½ (the least there is), got {target!r}", "target"
        )
    target = float(target)
    # every other argument checked once, as steadiness checks it, before the root finder
    # turns an error about them into "the engine stops"
    try:
        steadiness(torque_nm, period_deg, 1.0, speed_rad_s, load, reduced_mass_kgm2)
    except AnalysisError as error:
        if error.parameter != "inertia_kgm2":  # that one is the root finder's to vary
            raise

    def factor_at(inertia):
        try:
            factor = steadiness(
                torque_nm, period_deg, inertia, speed_rad_s, load, reduced_mass_kgm2
            ).factor
        except AnalysisError:
            return None  # the engine stops within the cycle: far too little inertia
        return factor if math.isfinite(factor) else None

    def excess(inertia):
        factor = factor_at(inertia)
        return -target if factor is None else factor - target

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
    reached = factor_at(found)
    if reached is None or abs(reached - target) > 1e-3 * target:
        # the least steadiness is the one just above the edge where the engine stops (at the
        # edge itself it stops, and "about 0" was once the answer)
        for nudge in (1e-12, 1e-9, 1e-6, 1e-3, 1e-1):
            least = factor_at(found * (1 + nudge))
            if least is not None:
                break
        about = f"about {least:.10g}" if least is not None else "unknown"
        raise AnalysisError(
            f"{target:.10g} is below the least steadiness this torque and load "
            f"allow before the engine stops ({about}, with {found:.4g} kg·m²); "
            "ask for more",
            "target",
        )
    return found
