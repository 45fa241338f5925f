"""
A truck diesel's torsional vibration
====================================

A crankshaft is a torsion spring with a disk at every throw, a pulley and a damper at the
free end and a heavy flywheel at the other. Each cylinder's gas and inertia torque twists it
at every order of the engine's speed (½ orders too, for a four-stroke), and where an order's
frequency meets a natural frequency of the shaft line the twist and the torque in the shaft
peak: a *critical speed*.

This tutorial takes the in-line six truck diesel of the library (the Cummins 6BT 5.9, firing
1-5-3-6-2-4), whose configuration has a ``[torsion]`` shaft line and a ``[gas]`` cycle, and
walks through what :func:`balance_cli.torsional_vibration` finds: the natural frequencies and
mode shapes, the criticals (major and minor orders, phase-vector sums), the vibratory torque
in every section across the speed range, and the elastic twist of the free end. It checks
the first natural frequency by hand with :func:`scipy.linalg.eigh`, and the criticals, the
major orders, a phase-vector sum and the shear stress by their closed forms.

The same analysis on the command line (see :doc:`/reference/cli`)::

    balance torsion library:today/inline/inline-6-truck-diesel --criticals major
    balance torsion library:today/inline/inline-6-truck-diesel --plot pictures/

The solution of the shaft line is openTorsion's (``pip install 'engine-balance[torsion]'``).
"""

import tomllib

import matplotlib.pyplot as plt
import numpy as np
import scipy.linalg
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.config import resolve

path = resolve("library:today/inline/inline-6-truck-diesel")
engine = balance.load(path)
print(engine.name)

# %%
# The ``[torsion]`` model
# -----------------------
#
# The shaft line is given free end first: the ``[[torsion.front]]`` inertias (here a damper
# ring on rubber, the pulley hub and the gear train), each with the stiffness of the section
# joining it to the next inertia aft; one inertia per throw with the stiffness of the
# sections between throws; the flywheel with the section from the last throw. The loss
# factor damps every section (hysteretic damping), the damper's own section has its viscous
# damping, and the shaft diameter turns torques into shear stress. No maker publishes this
# engine's mass-elastic data: the file's comments say how each figure was estimated.
text = path.read_text(encoding="utf-8")
# the table itself, not the comments above it that mention it
print(text[text.index("\n[torsion]\n") + 1 :])

# %%
# The analysis sweeps 201 speeds from 20 % to 120 % of the engine's own 2500 rpm and applies
# every order from ½ to 12. It returns a :class:`~balance_cli.TorsionResult`.
result = balance.torsional_vibration(engine)
assert len(result.speeds_rpm) == 201 and result.orders.min() == 0.5 and result.orders.max() == 12
for name, inertia in zip(result.nodes, result.inertia_kgm2, strict=True):
    print(f"{name:12s} {inertia:.4f} kg·m²")

# %%
# Natural frequencies by hand
# ---------------------------
#
# Undamped, the line is M·θ̈ + K·θ = 0 with M the diagonal of the inertias and K the
# tridiagonal matrix of a chain of springs: section k between nodes i and i + 1 adds k to
# K[i, i] and K[i + 1, i + 1] and −k to K[i, i + 1] and K[i + 1, i]. The generalised
# eigenvalue problem K·v = ω²·M·v gives the natural frequencies; the first, ω = 0, is the
# free line turning as one body. We build both matrices from the TOML file's own numbers,
# without balance, and solve them with :func:`scipy.linalg.eigh`.
model = tomllib.loads(text)["torsion"]


def si(value, unit):
    """A TOML quantity in its SI unit: this file writes them all in SI already."""
    number, written = value.split()
    assert written == unit, (value, unit)
    return float(number)


front = model["front"]
inertias = (
    [si(d["inertia"], "kg*m^2") for d in front]
    + [si(j, "kg*m^2") for j in model["throw_inertia"]]
    + [si(model["flywheel"]["inertia"], "kg*m^2")]
)
sections = (
    [si(d["stiffness"], "N*m/rad") for d in front]
    + [si(k, "N*m/rad") for k in model["stiffness"]]
    + [si(model["flywheel"]["stiffness"], "N*m/rad")]
)
M = np.diag(inertias)
K = np.zeros_like(M)
for i, k in enumerate(sections):
    K[i : i + 2, i : i + 2] += k * np.array([[1.0, -1.0], [-1.0, 1.0]])
omega_squared, vectors = scipy.linalg.eigh(K, M)
by_hand_hz = np.sqrt(np.abs(omega_squared[1:])) / (2 * np.pi)

computed_hz = np.array([m.frequency_hz for m in result.modes])
for number, (ours, theirs) in enumerate(zip(by_hand_hz[:3], computed_hz[:3], strict=True), 1):
    print(f"mode {number}: by hand {ours:7.2f} Hz, balance {theirs:7.2f} Hz")
# two eigen-solvers on the same ten-by-ten matrices: they agree to rounding, far inside 1e-9
assert_allclose(computed_hz, by_hand_hz, rtol=1e-9)

# %%
# Mode shapes
# -----------
#
# Each mode's shape is the relative amplitude of every inertia, scaled so that the largest
# is +1. The first mode (about 164 Hz) is the damper's: the damper ring swings on its
# rubber against the whole crankshaft. The second (about 272 Hz) is the crankshaft's own:
# the free end and the throws swing against the flywheel, which hardly moves. A tuned damper
# does its work by adding a mode of its own below the crankshaft's and by dissipating energy
# in its rubber. (The torsion pictures draw on a figure of their own unless given one; a
# pyplot figure given is one this page's gallery collects.)
fig = balance.plot.mode_shapes(result, fig=plt.figure(figsize=(8, 4.5), layout="constrained"))
damper_mode, crank_mode = result.modes[0].shape, result.modes[1].shape
assert damper_mode[0] == 1.0 and abs(crank_mode[-1]) < 0.1

# %%
# Major and minor orders, phase-vector sums
# -----------------------------------------
#
# Every cylinder's torque has the same orders; what differs between cylinders is the phase,
# set by when each one fires. At order k the torques of the cylinders add up, for a mode
# whose amplitude at cylinder c's throw is β_c, to one cylinder's torque times the
# **phase-vector sum** ``|Σ_c β_c·e^{ik·φ_c}|``, φ_c the crank angle at which cylinder c fires.
# With all β equal the sum is the number of cylinders where every cylinder is in phase: the
# **major** orders. The six fires every 720°/6 = 120°, so k·120° must be a multiple of 360°:
# the multiples of 3.
firing_order = tomllib.loads(text)["firing_order"]
fires_at_deg = {cylinder: 120.0 * i for i, cylinder in enumerate(firing_order)}
equal = [
    abs(sum(np.exp(1j * k * np.radians(phi)) for phi in fires_at_deg.values()))
    for k in result.orders
]
major_by_hand = tuple(
    float(k) for k, s in zip(result.orders, equal, strict=True) if abs(s - 6) < 1e-9
)
print("major orders:", result.major_orders, "by hand:", major_by_hand)
assert result.major_orders == major_by_hand == (3.0, 6.0, 9.0, 12.0)

# %%
# The other orders are **minor**: only a mode's unequal amplitudes along the crank keep them
# from cancelling. Here is the phase-vector sum of the crankshaft's mode (mode 2) at its
# major order 6 and at the minor order 4½ that in-line sixes are known for, by hand from the
# eigenvector above (throws 1 to 6 are nodes 4 to 9 of the line, cylinder c on throw c).
by_hand_mode = vectors[:, 2] / vectors[np.argmax(np.abs(vectors[:, 2])), 2]
beta = by_hand_mode[3:9]
mode2 = result.modes[1]
for k in (4.5, 6.0):
    by_hand = abs(
        sum(beta[c - 1] * np.exp(1j * k * np.radians(phi)) for c, phi in fires_at_deg.items())
    )
    print(f"order {k:g}: by hand {by_hand:.4f}, balance {mode2.phase_vector_sums[k]:.4f}")
    # the same eigenvector from two solvers, each scaled to its largest amplitude +1
    assert_allclose(mode2.phase_vector_sums[k], by_hand, rtol=1e-8)

# %%
# The criticals
# -------------
#
# A critical is a speed at which an order's frequency k·n/60 equals a mode's: n = 60·f/k
# rpm. The result lists every one within the speed range; those whose phase-vector sum is
# zero (the cylinders cannot excite them) are flagged, and
# ``TorsionResult.filtered`` chooses what is listed and marked (``criticals="excited"``,
# ``"major"`` or ``"all"``, and ``orders``, ``modes``), never the response, which is always
# that of every order. Here are the major ones, and then those of orders 4½ and 6 of every
# mode:
major = result.filtered("major")


def critical_line(c):
    return (
        f"{c.speed_rpm:6.0f} rpm  mode {c.mode}  order {c.order:4g}  {c.kind:6s} "
        f"sum {c.phase_vector_sum:.3f}"
    )


for c in major.criticals:
    print(critical_line(c))
    frequency = result.modes[c.mode - 1].frequency_hz
    # n = 60·f/k exactly: the analysis computes it the same way from the same frequency
    assert_allclose(c.speed_rpm, 60.0 * frequency / c.order, rtol=1e-12)
print()
for c in result.filtered(orders=[4.5, 6]).criticals:
    print(critical_line(c))

# %%
# The Campbell diagram draws it all: the modes as horizontal lines, every order's frequency
# as a ray from the origin, the criticals chosen where they cross (filled: major orders;
# open: minor), the speed range shaded. Drawn from the result filtered to the major
# criticals, it marks those only.
fig = balance.plot.campbell(major, fig=plt.figure(figsize=(8, 5), layout="constrained"))

# %%
# Vibratory torque per section
# ----------------------------
#
# At every speed the forced response gives, in every section, the torque of each order and
# of all orders together (the largest ``|T|`` of the synthesised waveform over the cycle). The
# largest of each section, and the largest of all with the order and the mode that make it:
for name, torque_nm, speed_rpm, stress_pa in result.largest():
    print(
        f"{name:24s} {torque_nm:7.0f} N·m at {speed_rpm:6.1f} rpm, τ = {stress_pa / 1e6:5.1f} MPa"
    )
peak = result.peak()
print(
    f"\nlargest: {peak.torque_nm:.0f} N·m in {peak.section} at {peak.speed_rpm:g} rpm, "
    f"order {peak.order:g} ({'major' if peak.major else 'minor'}), mode {peak.mode} "
    f"(its critical at {peak.critical_rpm:.0f} rpm)"
)

# %%
# The peak is the crankshaft mode's sixth-order resonance, above the rated speed but inside
# the sweep's 120 %. Most sections between the throws see their largest torque lower, near
# 1 640 rpm, where two criticals meet: the damper mode's major sixth order and the crankshaft
# mode's minor tenth (``TorsionResult.near`` gives the criticals a speed of the sweep
# stands for). The front sections (damper, pulley, gear train) see their largest
# torque elsewhere: at the minor order 4½, near the damper mode's 4½-order critical
# (60·f₁/4.5), a little above it where the damper's own damping moves the peak.
print("near 1637.5 rpm:", [f"{c.order:g}/{c.mode}" for c in result.near(1637.5)])
front_section = result.sections.index("damper ring–pulley hub")
i_front = int(np.argmax(result.torque_nm[:, front_section]))
order_there = result.orders[int(np.argmax(result.order_torque_nm[i_front, front_section]))]
critical_45 = 60.0 * result.modes[0].frequency_hz / 4.5
print(
    f"damper section: largest at {result.speeds_rpm[i_front]:g} rpm, order {order_there:g}; "
    f"mode 1's 4½-order critical at {critical_45:.0f} rpm"
)
assert order_there == 4.5 and abs(result.speeds_rpm[i_front] / critical_45 - 1) < 0.05

# %%
# The shear stress follows from the torque and the solid shaft's 76 mm:
# τ = T·r/J_p = 16·T/(π·D³).
diameter_m = si(model["shaft_diameter"], "mm") / 1000.0
by_hand_pa = 16.0 * peak.torque_nm / (np.pi * diameter_m**3)
print(f"τ at the peak: by hand {by_hand_pa / 1e6:.2f} MPa")
section = result.sections.index(peak.section)
at_peak = result.stress_pa[:, section].max()
# the same formula on the same torque: equal to rounding
assert_allclose(at_peak, by_hand_pa, rtol=1e-12)
assert peak.order == 6.0 and peak.mode == 2 and peak.major
assert 2500 < peak.speed_rpm < 3000

# %%
# The picture of the sweep: one line per section, the major criticals marked, the largest
# peak labelled with its order and mode whatever its order.
fig = balance.plot.torque_speed(result, fig=plt.figure(figsize=(8, 5), layout="constrained"))

# %%
# The free end's elastic twist
# ----------------------------
#
# The free end's angular swing includes the rigid turning of the whole line (the net torque
# swinging every inertia together), large at low speed where the engine's torque is least
# smoothed. Its **elastic twist** takes that out: the free end's angle less the angle of the
# line's centre of inertia, θ₁ − Σ J_i·θ_i / Σ J_i. It is the twist that a damper works on.
whole, elastic = result.free_end_deg, result.free_end_elastic_deg
i_whole, i_elastic = int(np.argmax(whole)), int(np.argmax(elastic))
print(f"whole swing largest {whole[i_whole]:.3f}° at {result.speeds_rpm[i_whole]:g} rpm")
print(f"elastic twist largest {elastic[i_elastic]:.3f}° at {result.speeds_rpm[i_elastic]:g} rpm")

fig, ax = plt.subplots(figsize=(8, 4), layout="constrained")
ax.plot(result.speeds_rpm, whole, label="whole swing (rigid turning included)")
ax.plot(result.speeds_rpm, elastic, label="elastic twist")
ax.set(
    xlabel="Engine speed (rpm)",
    ylabel="Free end's amplitude (°)",
    title=f"{engine.name}: the free end",
)
ax.legend()
