"""BRAMO 323 by Newton–Euler, written apart from balance as an independent second method.

Every rod is a rigid body (mass, centre of gravity, moment of inertia J about it), pistons are
point masses at the piston pins; each linkage triangle is closed exactly with exact first and
second derivatives of every angle (no series, no FFT derivatives). The crank-pin force comes
from the free bodies of each piston, link rod and the master rod in turn (the cylinder walls'
normal forces as unknowns); the kinetic energy and angular momentum from the rigid bodies.
Fraeys de Veubeke's coefficients are read off at constant speed Ω = 1 (forces per R·Ω²):
U_k of μ(θ) = 2R²(U_0 + Σ U_k/k·cos kθ), V_k of H/θ̇ = R²(V_0 + Σ V_k/k·cos kθ), R_k of the
radial pin force R·Ω²(R_0 + Σ R_k cos kθ), T_k of the pin force R·Ω²·Σ T_k e^{ikθ}.

Data: Table VIII (J, j in kg·cm·s² with g = 9.81), the radii paired symmetrically (erratum F1).
"""

import numpy as np

G = 9.81
R = 0.080
L, H, B, J = 0.330, 0.0413, 10.54, 1.250 * G / 100
LINK_L, LINK_H, LINK_B, LINK_J = 0.2615, 0.1385, 1.42, 0.144 * G / 100
PISTON = 2.972
RADII_MM = {2: 69.65, 9: 69.65, 3: 71.26, 8: 71.26, 4: 70.60, 7: 70.60, 5: 68.82, 6: 68.82}
PSI = {n: np.deg2rad(40 * (n - 1)) for n in range(1, 10)}


def _cross(lever, force):
    """z-moment of ``force`` (complex) at ``lever`` (complex)."""
    return (np.conj(lever) * force).imag


def solve(samples):
    """Kinetic energy, angular momentum and the force of the rods on the pin, Ω = 1."""
    theta = 2 * np.pi * np.arange(samples) / samples
    lam = R / L
    pin = R * np.exp(1j * theta)
    pin_d, pin_dd = 1j * pin, -pin
    s1 = -lam * np.sin(theta)
    c1 = np.sqrt(1 - s1**2)
    b1 = np.arcsin(s1)
    b1d = -lam * np.cos(theta) / c1
    b1dd = (lam * np.sin(theta) + s1 * b1d**2) / c1
    e1 = np.exp(1j * b1)
    p1, p1d, p1dd = pin + L * e1, pin_d + 1j * L * b1d * e1, pin_dd + L * (1j * b1dd - b1d**2) * e1
    g1, g1d, g1dd = pin + H * e1, pin_d + 1j * H * b1d * e1, pin_dd + H * (1j * b1dd - b1d**2) * e1
    energy = 0.5 * B * abs(g1d) ** 2 + 0.5 * J * b1d**2 + 0.5 * PISTON * abs(p1d) ** 2
    momentum = B * _cross(g1, g1d) + J * b1d
    links = []
    for n in range(2, 10):
        r, psi = RADII_MM[n] / 1000, PSI[n]
        ek = np.exp(1j * (b1 + psi))
        k, kd, kdd = pin + r * ek, pin_d + 1j * r * b1d * ek, pin_dd + r * (1j * b1dd - b1d**2) * ek
        turn = np.exp(-1j * psi)
        sn = -(k * turn).imag / LINK_L
        cn = np.sqrt(1 - sn**2)
        bn = np.arcsin(sn)
        bnd = -(kd * turn).imag / (LINK_L * cn)
        bndd = (-(kdd * turn).imag + LINK_L * sn * bnd**2) / (LINK_L * cn)
        en = np.exp(1j * (psi + bn))
        pn, pnd, pndd = (
            k + LINK_L * en,
            kd + 1j * LINK_L * bnd * en,
            kdd + LINK_L * (1j * bndd - bnd**2) * en,
        )
        gn, gnd, gndd = (
            k + LINK_H * en,
            kd + 1j * LINK_H * bnd * en,
            kdd + LINK_H * (1j * bndd - bnd**2) * en,
        )
        energy += (
            0.5 * LINK_B * abs(gnd) ** 2 + 0.5 * LINK_J * bnd**2 + 0.5 * PISTON * abs(pnd) ** 2
        )
        momentum += LINK_B * _cross(gn, gnd) + LINK_J * bnd
        links.append(dict(k=k, p=pn, pdd=pndd, g=gn, gdd=gndd, bdd=bndd, axis=np.exp(1j * psi)))
    from_links, moment_from_links = 0, 0
    for d in links:
        normal = 1j * d["axis"]
        free = -PISTON * d["pdd"]
        # the link rod's moments about its knuckle pin give the wall force on its piston
        lhs = (
            LINK_J * d["bdd"]
            + _cross(d["g"] - d["k"], LINK_B * d["gdd"])
            - _cross(d["p"] - d["k"], free)
        )
        wall = lhs / _cross(d["p"] - d["k"], normal * np.ones_like(lhs))
        on_link = LINK_B * d["gdd"] - (free + wall * normal)  # master rod -> link, at the knuckle
        from_links = from_links - on_link
        moment_from_links = moment_from_links + _cross(d["k"] - pin, -on_link)
    free1 = -PISTON * p1dd
    lhs = J * b1dd + _cross(g1 - pin, B * g1dd) - _cross(p1 - pin, free1) - moment_from_links
    wall1 = lhs / _cross(p1 - pin, 1j * np.ones_like(lhs))
    on_master = B * g1dd - (free1 + wall1 * 1j) - from_links  # crank pin -> master rod
    return theta, energy, momentum, -on_master


def _fourier(x):
    c = np.fft.rfft(x) / len(x)
    cos = 2 * c.real
    cos[0] = c[0].real
    return cos


def coefficients(samples=512):
    """U_0..U_5, V_0..V_5, R_0..R_5 and {k: T_k} for k = −5..6."""
    theta, energy, momentum, force = solve(samples)
    mu = _fourier(2 * energy)
    h = _fourier(momentum)
    radial = _fourier((force * np.exp(-1j * theta)).real / R)
    c = np.fft.fft(force / R) / samples
    return {
        "U": [mu[0] / (2 * R**2)] + [k * mu[k] / (2 * R**2) for k in range(1, 6)],
        "V": [h[0] / R**2] + [k * h[k] / R**2 for k in range(1, 6)],
        "R": list(radial[:6]),
        "T": {k: complex(c[k % samples]) for k in range(-5, 7)},
    }
