"""
The engine on its mounts
========================

balance says what an engine shakes its mounts with. On its mounts the engine is a rigid body
with six natural modes — fore-aft, lateral, bounce, roll, pitch and yaw, or mixtures of them —
and what reaches the frame depends on where those modes sit against the engine's orders and
on how the mounts couple them. This tutorial takes the two worked examples of the library's
``configs/mounts``: first the symmetric one, whose six frequencies are Harris' closed forms;
then the coupled one — its modes and their kinetic-energy table, its torque roll axis, the
force each mount passes on against speed with the resonances marked — and finds the mount
rates that put its roll mode on the torque roll axis (Jeong and Singh's decoupling), then
sweeps one of those rates to see how sharp that design is.

The same on the command line (see :doc:`/howto/mounts`)::

    balance mounts library:mounts/four-mount-coupled --speeds 150:1000:2 --plot pictures/
    balance mounts library:mounts/four-mount-coupled --decouple A+B:y --decouple A:z \\
        --decouple B:x --decouple C:compression --decouple C:shear
    balance sweep library:mounts/four-mount-coupled --vary "mounts.mount[C].compression" \\
        --from "60 N/mm" --to "180 N/mm" --steps 13 --quantity roll_mode,tra_purity
"""

import math

import numpy as np
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.studies.sweep import span

# %%
# Six pure modes: the symmetric example
# -------------------------------------
#
# Four identical mounts (100 N/mm along x and y, 200 N/mm along z) at (±0.30, ±0.25, 0) m
# from the centre of gravity of a 150 kg engine whose principal axes are the engine's axes,
# J = diag(6, 9, 8) kg·m². The mounts lie in the plane of the centre of gravity and
# symmetrically about both vertical planes, so no motion couples with another and each
# frequency is one stiffness over one inertia (Harris' Shock and Vibration Handbook, ch. 3):
# fore-aft and lateral √(4·k_x/m)/2π = 8.22 Hz, bounce √(4·k_z/m)/2π = 11.62 Hz, roll
# √(4·k_z·b²/J_xx)/2π = 14.53 Hz, pitch √(4·k_z·a²/J_yy)/2π = 14.24 Hz and yaw
# √(4·(k_x·b² + k_y·a²)/J_zz)/2π = 13.90 Hz.
symmetric = balance.load("library:mounts/four-mount-symmetric")
modes = balance.mounts(symmetric, speeds_rpm=[1000.0]).modes
for mode in modes:
    print(
        f"mode {mode.number}: {mode.frequency_hz:6.3f} Hz, {mode.motion:8} {mode.purity_pct:.1f} %"
    )


def hz(stiffness, inertia):
    """√(k/m)/2π, Hz."""
    return math.sqrt(stiffness / inertia) / (2 * math.pi)


harris = {
    "fore-aft": hz(4 * 100e3, 150),
    "lateral": hz(4 * 100e3, 150),
    "bounce": hz(4 * 200e3, 150),
    "roll": hz(4 * 200e3 * 0.25**2, 6.0),
    "pitch": hz(4 * 200e3 * 0.30**2, 9.0),
    "yaw": hz(4 * (100e3 * 0.25**2 + 100e3 * 0.30**2), 8.0),
}
assert_allclose(
    [harris[k] for k in ("fore-aft", "bounce", "roll", "pitch", "yaw")],
    [8.2187, 11.6230, 14.5288, 14.2353, 13.8976],
    atol=5e-5,
)  # the figures above, to their digits
# fore-aft and lateral share a frequency: their names may come in either order
assert_allclose(sorted(m.frequency_hz for m in modes), sorted(harris.values()), rtol=1e-12)
for mode in modes:
    assert_allclose(mode.frequency_hz, harris[mode.motion], rtol=1e-12)  # eigh's rounding
    assert_allclose(mode.purity_pct, 100.0, rtol=1e-12)

# %%
# The coupled example
# -------------------
#
# The same engine (``configs/inline-4-car.toml``) as a 180 kg powertrain whose centre of
# gravity sits 0.10 m above the crank axis, with products of inertia, on four mounts at
# different heights, one of them (C) inclined at 45°: nothing is symmetric.
path = balance.config.resolve("library:mounts/four-mount-coupled")
text = path.read_text(encoding="utf-8")
print(text[text.index("[mounts]") :])
engine = balance.load(path)
result = balance.mounts(engine, speeds_rpm=np.arange(150.0, 1001.0, 5.0))

# %%
# Now every mode mixes several motions. The kinetic-energy distribution — the share of each
# mode's kinetic energy in each motion, 100·φ_j·(M·φ)_j/(φᵀ·M·φ) — is the decoupling table a
# mount report shows; each row adds up to 100 %. The mode named roll keeps less than three
# quarters of its energy in roll: a firing pulse about the crank shakes the engine sideways
# and in yaw too.
print(
    "mode   f (Hz)  motion     " + "  ".join(f"{d:>5}" for d in ("x", "y", "z", "rx", "ry", "rz"))
)
for mode in result.modes:
    shares = "  ".join(f"{round(e, 1) + 0.0:5.1f}" for e in mode.energy_pct)
    print(f"{mode.number:4}  {mode.frequency_hz:7.3f}  {mode.motion:9}  {shares}")
    assert_allclose(mode.energy_pct.sum(), 100.0, rtol=1e-12)
roll = next(m for m in result.modes if m.motion == "roll")
assert roll.purity_pct < 75.0
fig = balance.plot.energy_bars(result)

# %%
# :func:`balance_cli.plot.mount_modes` draws each mode: the engine as the uniform box of its
# mass and moments of inertia, at rest and moved in the mode, on its mounts, with the crank
# axis.
fig = balance.plot.mount_modes(result)

# %%
# The torque roll axis
# --------------------
#
# A couple about the crank axis x turns the free engine about J⁻¹·x̂ through its centre of
# gravity: the **torque roll axis**. With J = [[8, −0.4, 0.9], [−0.4, 12, 0.3], [0.9, 0.3,
# 10]] kg·m², J⁻¹·x̂ is J⁻¹'s first column, the cofactors of J's first row over det J:
# (12·10 − 0.3², −(−0.4·10 − 0.3·0.9), −0.4·0.3 − 12·0.9) = (119.91, 4.27, −10.92), a
# direction (0.9953, 0.0354, −0.0906), 5.58° off the crank axis. On its mounts alone the
# engine turns under that couple about its **elastic axis**; the angle between the two says
# how far the mounting is from decoupled (zero: the torque drives one mode only).
tra = result.torque_roll_axis
by_hand = np.array([119.91, 4.27, -10.92]) / math.sqrt(119.91**2 + 4.27**2 + 10.92**2)
assert_allclose(tra.direction, by_hand, atol=1e-12)  # exact arithmetic by hand
assert_allclose(by_hand, [0.9953, 0.0354, -0.0906], atol=5e-5)
assert_allclose(math.degrees(math.acos(by_hand[0])), 5.58, atol=5e-3)
off_x = math.degrees(math.acos(tra.direction[0]))
print(f"torque roll axis {np.round(tra.direction, 4)}, {off_x:.2f}° off x")
elastic = np.round(result.elastic_axis.direction, 4)
print(f"elastic axis {elastic}, {result.axes_angle_deg:.2f}° from it")

# %%
# What each mount passes on
# -------------------------
#
# Under the weight the four mounts carry m·g = 180 × 9.80665 = 1765.2 N between them. In
# motion, every order of the shaking force and moment and of the frame torque drives the
# six modes. An in-line four has a second-order force and even orders of torque but no odd
# or half order (no gas cycle here): each mode is driven where an even order k meets it, at
# 60·f/k rpm for a mode of f Hz, and the odd and half orders cross the modes without driving
# any. The picture marks the driven crossings "order/mode".
pressing = result.weight.force_n[:, 2].sum()
assert_allclose(-pressing, 180 * 9.80665, rtol=1e-12)
assert_allclose(180 * 9.80665, 1765.2, atol=0.05)
print(f"the mounts press down on the frame with {-pressing:.1f} N")
for crossing in result.crossings:
    if crossing.excited:
        f = result.modes[crossing.mode - 1].frequency_hz
        assert crossing.order % 2 == 0
        assert_allclose(crossing.speed_rpm, 60 * f / crossing.order, rtol=1e-12)
        where = f"mode {crossing.mode} ({crossing.motion})"
        print(f"order {crossing.order:g} drives {where} at {crossing.speed_rpm:.0f} rpm")
assert all(c.order % 2 for c in result.crossings if not c.excited)
fig = balance.plot.mount_forces(result)

# %%
# Putting the roll mode on the torque roll axis
# ---------------------------------------------
#
# The turn about the torque roll axis, q* = (0, ê), is a natural mode when the mounts
# answer it with a couple about x alone: no force and no moment about y or z, five
# conditions (Jeong and Singh 2000). They are linear in the mount rates, so five rates
# chosen freely meet them exactly, and :func:`balance_cli.decouple` takes the least change
# of those rates that does. Here: the lateral rate of A and B (one value, the pair kept
# alike), A's vertical rate, B's fore-aft rate, and C's compression and shear rates.
vary = [(("A", "B"), "y"), ("A", "z"), ("B", "x"), ("C", "compression"), ("C", "shear")]
found = balance.decouple(engine, vary)
print(f"{found.method}, exact: {found.exact}")
for rate in found.rates:
    before = ", ".join(f"{k / 1e3:.4g}" for k in dict.fromkeys(rate.before_n_m))
    print(f"{rate.label:14} {before:>6} -> {rate.after_n_m / 1e3:7.4g} N/mm")
print(f"purity {found.before.purity_pct:.1f} % -> {found.after.purity_pct:.1f} %")

# %%
# Two checks by hand. The mode is then the turn q* itself, so its frequency is the Rayleigh
# quotient of q*: ω² = Σ k·(d·(ê × r))²/(êᵀ·J·ê), each mount rate k along its direction d
# at r stretched by d·(ê × r) per radian. And a pure couple about the crank axis drives that
# mode alone: for any other mode φ, φᵀ·(0, x̂) is proportional to φᵀ·M·q* (as M·q* =
# (0, J·ê) and J·ê ∥ x̂), which the modes' M-orthogonality makes zero.
e = np.array(tra.direction)
inertia = np.array(engine.mounts.inertia_kgm2)
energy = sum(
    k * float(np.dot(d, np.cross(e, mount.position_m))) ** 2
    for mount in found.system.mounts
    for k, d in zip(mount.rates_n_m, mount.directions, strict=True)
)
rayleigh = math.sqrt(energy / float(e @ inertia @ e)) / (2 * math.pi)
print(f"TRA mode {found.after.frequency_hz:.4f} Hz; by the Rayleigh quotient {rayleigh:.4f} Hz")
assert found.exact
assert_allclose(found.after.frequency_hz, rayleigh, rtol=1e-12)  # eigh against a sum
decoupled = balance.mounts(engine, speeds_rpm=np.arange(150.0, 1001.0, 5.0), system=found.system)
couple = np.array([0, 0, 0, 1.0, 0, 0])
driven = [abs(float(m.shape @ couple)) for m in decoupled.modes]
tra_mode = decoupled.modes[found.after.mode - 1]
assert_allclose(tra_mode.energy_pct[3], 100.0, rtol=1e-12)  # all its energy about x
assert all(d < 1e-12 * max(driven) for i, d in enumerate(driven) if i != tra_mode.number - 1)
fig = balance.plot.mount_forces(decoupled)

# %%
# How sharp is the design?
# ------------------------
#
# With the other four rates at the values found (``overrides`` sets them at every point), a
# sweep of C's compression rate shows what each N/mm off costs in purity. The purity is
# 100 % at the value found (written to twelve digits, so to 1e-9) and falls on either side;
# the roll mode's frequency there is the Rayleigh quotient above.
keys = {
    "A+B:y": ["mounts.mount[A].stiffness[2]", "mounts.mount[B].stiffness[2]"],
    "A:z": ["mounts.mount[A].stiffness[3]"],
    "B:x": ["mounts.mount[B].stiffness[1]"],
    "C:shear": ["mounts.mount[C].shear"],
}
overrides = {
    key: f"{rate.after_n_m / 1e3:.12g} N/mm"
    for rate in found.rates
    for key in keys.get(rate.label, [])
}
compression = found.rates[3].after_n_m / 1e3
values = span("60 N/mm", "180 N/mm", 13) + [f"{compression:.12g} N/mm"]
sweep = balance.sweep(
    path,
    "mounts.mount[C].compression",
    sorted(values, key=lambda v: float(v.split()[0])),
    "roll_mode,tra_purity,axes_angle",
    overrides=overrides,
)
for point in sweep.points:
    roll_hz, purity = point["roll_mode_Hz"], point["tra_purity_pct"]
    print(f"{point['value']:>22}  roll {roll_hz:.3f} Hz  purity {purity:.2f} %")
at = next(p for p in sweep.points if p["value"] == f"{compression:.12g} N/mm")
assert_allclose(at["tra_purity_pct"], 100.0, atol=1e-9)
assert_allclose(at["roll_mode_Hz"], rayleigh, rtol=1e-9)
assert all(p["tra_purity_pct"] < 100.0 - 1e-6 for p in sweep.points if p is not at)
fig = balance.plot.sweep_figure(sweep)
