"""Fraeys de Veubeke's own series for the BRAMO 323, summed to a chosen order, written apart
from balance: what his Table XII columns U, V, R would read if truncated at that order.

His § 8 replaces the rods by point masses (Table IX: a at every piston, A the master's
excess, D at the crank pin, c and I the rods' correcting inertias, c < 0) and expands every
coefficient in powers of the crank ratio ε (R, and the knuckle radii r_n, scale with ε; L and
l stay). Here the point-mass scheme is evaluated with exact kinematics at a complex ε on a
circle and the Laurent coefficients of each part are read off by a discrete Cauchy integral,
so "summed to order m" means every term up to ε^m, with his Table IX constants as printed.

- U_k of the reduced mass μ(θ) = 2R²(U₀ + Σ U_k/k·cos kθ) (his (25)),
- V_k of the angular momentum H/θ̇ = R²(V₀ + Σ V_k/k·cos kθ),
- R_k of the radial pin force R·Ω²(R₀ + Σ R_k cos kθ), by Lagrange: ½·∂μ/∂R − d/dθ(w),
  w = Σ m·ẋ·∂x/∂R (his (35)).

Derivatives in θ are spectral, in R central differences (1e-6·R): the crank radius moves with
the radii r_n held, as in his ∂/∂R.
"""

import numpy as np

#: Table VIII (m, the link radii paired symmetrically: erratum F1)
R0, L, LINK = 0.080, 0.330, 0.2615
RADII_MM = {2: 69.65, 9: 69.65, 3: 71.26, 8: 71.26, 4: 70.60, 7: 70.60, 5: 68.82, 6: 68.82}
PSI = {n: np.deg2rad(40 * (n - 1)) for n in range(1, 10)}

#: Table IX as printed: kg, and c, I as printed in kg·(l² or L²) (his g·c/l² = −0.1469,
#: g·I/L² = 0.4441)
TABLE_IX = {"a": 3.7239, "A": 0.4281, "c": -0.1469 * LINK**2, "I": 0.4441 * L**2, "D": 14.7048}

_N = 256
_THETA = 2 * np.pi * np.arange(_N) / _N
_K = np.fft.fftfreq(_N, 1 / _N)


def _d_theta(f):
    spectrum = np.fft.fft(f, axis=-1)
    spectrum[..., _N // 2] = 0
    return np.fft.ifft(1j * _K * spectrum, axis=-1)


def _geometry(crank, eps):
    """Piston travels x and rod angles β: the master's, then the nine links' (n = 1..9),
    complex-analytic in ``crank`` and ``eps`` (the knuckle radii are eps·r_n)."""
    s1 = -(crank / L) * np.sin(_THETA)
    travels, angles = [crank * np.cos(_THETA) + L * np.sqrt(1 - s1**2)], [np.arcsin(s1)]
    for n in range(1, 10):
        # the master cylinder's own piston counts as a link too (his a at every piston): of
        # radius r₁ = L − l on the master rod, collinear with it
        r = eps * (L - LINK if n == 1 else RADII_MM[n] / 1000)
        phase = _THETA - PSI[n]
        sn = (-r * s1 - crank * np.sin(phase)) / LINK
        travels.append(crank * np.cos(phase) + r * np.sqrt(1 - s1**2) + LINK * np.sqrt(1 - sn**2))
        angles.append(np.arcsin(sn))
    return np.array(travels), np.array(angles)


def _coefficients(eps, constants):
    """U, V, R (orders 0..5) of each part of the point-mass scheme at scale ``eps``."""
    crank = eps * R0
    step = 1e-6 * R0
    x, beta = _geometry(crank, eps)
    xp, bp = _geometry(crank + step, eps)
    xm, bm = _geometry(crank - step, eps)
    x_r, beta_r = (xp - xm) / (2 * step), (bp - bm) / (2 * step)
    x_t, beta_t = _d_theta(x), _d_theta(beta)
    x_tr, beta_tr = _d_theta(x_r), _d_theta(beta_r)
    parts = {  # per unit constant: (rate, ∂/∂R, ∂rate/∂R, summed over the links?, turning?)
        "a": (x_t[1:], x_r[1:], x_tr[1:], True, False),
        "A": (x_t[0], x_r[0], x_tr[0], False, False),
        "c": (beta_t[1:], beta_r[1:], beta_tr[1:], True, True),
        "I": (beta_t[0], beta_r[0], beta_tr[0], False, True),
    }
    out = {}
    for name, (rate, d_r, rate_r, summed, turning) in parts.items():
        mu, w, dmu_dr = rate**2, rate * d_r, 2 * rate * rate_r
        momentum = rate if turning else 0 * rate
        if summed:
            mu, w, dmu_dr, momentum = mu.sum(0), w.sum(0), dmu_dr.sum(0), momentum.sum(0)
        out[name] = (mu, w, dmu_dr, momentum)
    # D at the crank pin: μ = R², no radial virtual velocity, ∂μ/∂R = 2R, H/θ̇ = R²
    ones = np.ones(_N)
    out["D"] = (crank**2 * ones, 0 * ones, 2 * crank * ones, crank**2 * ones)
    result = {}
    for name, (mu, w, dmu_dr, momentum) in out.items():
        m = constants[name]
        radial = m * (0.5 * dmu_dr - _d_theta(w)) / crank
        u, v = m * mu / (2 * crank**2), m * momentum / crank**2

        def c(f, k):
            return f.mean() if k == 0 else 2 * np.mean(f * np.cos(k * _THETA))

        result[name] = {
            "U": np.array([c(u, 0)] + [k * c(u, k) for k in range(1, 6)]),
            "V": np.array([c(v, 0)] + [k * c(v, k) for k in range(1, 6)]),
            "R": np.array([c(radial, k) for k in range(6)]),
        }
    return result


def series(order, constants=None, points=48):
    """{"U": [U₀..U₅], "V": [...], "R": [...]}, the sums of every term up to ε^``order``."""
    constants = TABLE_IX if constants is None else constants
    phis = 2 * np.pi * np.arange(points) / points
    values = [_coefficients(np.exp(1j * phi), constants) for phi in phis]
    out = {}
    for q in "UVR":
        total = np.zeros(6)
        for name in constants:
            stack = np.array([v[name][q] for v in values])
            for m in range(-1, order + 1):
                total += np.mean(stack * np.exp(-1j * m * phis)[:, None], axis=0).real
        out[q] = total
    return out


def exact(constants=None):
    """The point-mass scheme at ε = 1 (no truncation), Table IX's constants."""
    constants = TABLE_IX if constants is None else constants
    parts = _coefficients(1.0, constants)
    return {q: sum(parts[name][q] for name in constants).real for q in "UVR"}
