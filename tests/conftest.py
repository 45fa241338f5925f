"""Shared helpers: building engines in code, and the shipped library."""

import math
import os
import sys
from pathlib import Path

import numpy as np
import pytest

from balance_cli.model import Cylinder, Engine, Throw

os.environ.setdefault("MPLBACKEND", "Agg")

ROOT = Path(__file__).resolve().parent.parent

#: a valid two-cylinder configuration that tests of bad input change one key at a time
TWIN = """\
name = "test twin"
cycle = 4
speed = "3000 rpm"
crank_radius = "40 mm"
rod_length = "140 mm"
firing_order = [1, 2]

[masses]
reciprocating = "500 g"

[[banks]]
angle = 0

[[throws]]
phase = 0
z = "0 mm"
[[throws]]
phase = 180
z = "90 mm"
"""
#: the twin's first cylinder alone
SINGLE = (TWIN.replace('name = "test twin"', 'name = "test single"')
          .replace("firing_order = [1, 2]\n", "").split("[[throws]]")[0] + "[[throws]]\nphase = 0\n")
CONFIGS = ROOT / "configs"
PART3 = CONFIGS / "tanaka-part3"


def make_engine(banks_deg, throws, *, r=0.08, l=0.28, m=1.0, rpm=1000.0, cycle=4, frame="fixed",
                rotating=0.0, pin_offset=0.0, links=None, firing_order=None):
    """A grid engine: one cylinder per (bank, throw), numbered bank by bank.

    ``throws`` is a list of (phase in degrees, z in metres); ``links`` is None or
    (master bank index, link length m, knuckle radius m, knuckle mass kg).
    """
    throw_objs = tuple(Throw(math.radians(p), z) for p, z in throws)
    banks = tuple(math.radians(b) for b in banks_deg)
    cylinders = []
    for b in range(len(banks)):
        for t, throw in enumerate(throw_objs):
            number = b * len(throws) + t + 1
            extra = {}
            if links is not None and b != links[0]:
                master_bank, length, radius, knuckle = links
                extra = dict(master=master_bank * len(throws) + t + 1, link_length_m=length,
                             knuckle_radius_m=radius, knuckle_angle_rad=banks[b] - banks[master_bank],
                             knuckle_kg=knuckle)
            cylinders.append(Cylinder(number, b + 1, t + 1, throw.z_m, m, **extra))
    return Engine(name="test engine", cycle=cycle, speed_rad_s=rpm * math.pi / 30.0, crank_radius_m=r,
                  rod_length_m=l, bank_angles_rad=banks, throws=throw_objs, cylinders=tuple(cylinders),
                  rotating_kg=rotating, pin_offset_m=pin_offset, frame=frame,
                  firing_order=firing_order)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    if "matplotlib.pyplot" in sys.modules:
        sys.modules["matplotlib.pyplot"].close("all")


def exact_b(q, k):
    """B_k of a plain slider-crank (inertia force = m·r·ω²·Σ B_k cos kθ) by a second method:
    the closed-form acceleration ẍ/(−rω²) = cos θ + q cos 2θ/√(1 − q² sin²θ)
    + q³ sin²2θ/(4(1 − q² sin²θ)^{3/2}), projected on cos kθ by the trapezoidal rule (exact to
    rounding for periodic integrands)."""
    theta = np.linspace(0.0, 2 * np.pi, 4096, endpoint=False)
    root = np.sqrt(1 - q**2 * np.sin(theta) ** 2)
    accel = (np.cos(theta) + q * np.cos(2 * theta) / root
             + q**3 * np.sin(2 * theta) ** 2 / (4 * root**3))
    return 2 * np.mean(accel * np.cos(k * theta))
