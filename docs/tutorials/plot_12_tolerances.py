"""
What a tolerance band leaves
============================

Pistons are made to a weight tolerance, crankshafts to a stroke and phase tolerance. A
production engineer asks what a band leaves across a production run: how large a free force
or couple the worst engines in a hundred have, where a perfect one has none.
:func:`balance_cli.tolerance` draws the engines (every part and dimension apart, from a normal
scatter of its standard deviation), analyses each exactly, all at once, and sets the closed
form of the scatter's linear part beside the Monte Carlo.

This tutorial scatters a flat-crank in-line 4's piston masses and checks the first-order force
and couple against their laws worked out by hand, scatters its throws' phases, and times ten
thousand runs of a V8 with every dimension scattered.

The same on the command line (see :doc:`/howto/workshop`)::

    balance tolerance docs/data/workshop-inline-4.toml --runs 10000 --plot spread.png
"""

import math
import time

import numpy as np

import balance_cli as balance

# %%
# A band
# ------
#
# The ``[tolerances]`` table gives one standard deviation of each scatter: masses and lengths
# with their units, angles in degrees. Here only the reciprocating masses scatter, by 2 g.
FLAT_4 = """\
name = "In-line 4, flat crank"
cycle = 4
speed = "6000 rpm"
crank_radius = "43 mm"
rod_length = "143 mm"
firing_order = [1, 3, 4, 2]

[masses]
reciprocating = "550 g"

[[banks]]
angle = 0

[[throws]]
phase = 0
z = "0 mm"
[[throws]]
phase = 180
z = "88 mm"
[[throws]]
phase = 180
z = "176 mm"
[[throws]]
phase = 0
z = "264 mm"

[tolerances]
reciprocating = "2 g"
"""
engine = balance.loads(FLAT_4, "flat-4.toml")
print(engine.tolerances)
result = balance.tolerance(engine, runs=10_000, seed=1, max_order=4)
print(f"{result.runs:,} runs, {result.method}, {result.elapsed_s:.2f} s")

# %%
# The first-order force by hand
# -----------------------------
#
# The flat crank cancels the primary of equal pistons. With deviations δmᵢ it leaves
# Σ δmᵢ·r·ω²·cos(θ + βᵢ) along the axis, βᵢ = 0 or 180°: an amplitude ``|Σ sᵢ·δmᵢ|·r·ω²`` with
# sᵢ = ±1, a normal of variance 4σ² in absolute value. Its mean is 2σ·√(2/π)·r·ω² and its
# 95th percentile 1.96·2σ·r·ω².
sigma = 0.002
rw2 = engine.crank_radius_m * engine.speed_rad_s**2
mean_by_hand = 2 * sigma * math.sqrt(2 / math.pi) * rw2
p95_by_hand = 1.959964 * 2 * sigma * rw2
first = result.order(1)
runs, closed = first.force["vertical"], first.linear_force["vertical"]
print(
    f"mean:  runs {runs.mean:.2f} ± {runs.mean_error:.2f} N, closed form {closed.mean:.2f} N, "
    f"by hand {mean_by_hand:.2f} N"
)
print(
    f"95th:  runs {runs.p95:.2f} N (95 % interval {runs.p95_interval[0]:.1f}–"
    f"{runs.p95_interval[1]:.1f}), closed form {closed.p95:.2f} N, by hand {p95_by_hand:.2f} N"
)
# the Monte Carlo within four standard errors of the mean, and its percentile's interval
# holding the 95th percentile by hand
assert abs(runs.mean - mean_by_hand) < 4 * runs.mean_error
assert runs.p95_interval[0] <= p95_by_hand <= runs.p95_interval[1]
# the closed form of the linear part: the half-normal, exactly (gradients by central
# differences of a linear function: rounding)
assert abs(closed.mean / mean_by_hand - 1) < 1e-9

# %%
# The couple likewise: Σ δmᵢ·sᵢ·(zᵢ − z̄)·r·ω², a normal of variance Σ(sᵢ·zᵢ)²·σ², its lever
# arms ±132 and ±44 mm about the middle.
z = np.array([t.z_m for t in engine.throws])
s = np.array([1, -1, -1, 1])
spread = math.sqrt(np.sum((s * (z - z.mean())) ** 2)) * sigma * rw2
couple = first.moment["vertical"]
print(
    f"couple mean {couple.mean:.3f} ± {couple.mean_error:.3f} N·m, by hand "
    f"{spread * math.sqrt(2 / math.pi):.3f} N·m; 95th {couple.p95:.3f}, by hand "
    f"{1.959964 * spread:.3f} N·m"
)
assert abs(couple.mean - spread * math.sqrt(2 / math.pi)) < 4 * couple.mean_error

# %%
# The histograms of the runs, the Monte Carlo's mean and 95th percentile solid, the closed
# form's dashed: where the scatter is small and linear, the two agree.
fig = balance.plot.tolerance_histograms(result, order=1)

# %%
# A phase scatter
# ---------------
#
# Throw 1 is the reference the phases are measured from; throws 2-4 scatter by σ each. The
# first-order phasor Σ sⱼ·e^{iδⱼ} gains i·Σ sⱼ·δⱼ: an amplitude ``m·r·ω²·|Σ sⱼ·δⱼ|``, a normal of
# variance 3σ². Each run's linkage is closed with its own phases.
phase = balance.ToleranceBand(phase_rad=math.radians(0.05))
turned = balance.tolerance(engine, phase, runs=4000, seed=2, max_order=2)
m = 0.55
by_hand = math.sqrt(3) * math.radians(0.05) * m * rw2 * math.sqrt(2 / math.pi)
runs = turned.order(1).force["vertical"]
print(f"{turned.method}: mean {runs.mean:.2f} ± {runs.mean_error:.2f} N, by hand {by_hand:.2f} N")
assert abs(runs.mean - by_hand) < 4 * runs.mean_error

# %%
# Ten thousand V8s
# ----------------
#
# The library's cross-plane V8 with every part and dimension scattered: ten thousand runs,
# each its own exact linkage, in about a second (``make bench`` times it).
v8 = balance.load("library:today/v/v8-90-cross-plane").edit(rotating="1.1 kg")
band = balance.ToleranceBand(
    reciprocating_kg=0.002,
    rotating_kg=0.003,
    crank_radius_m=2e-5,
    rod_length_m=3e-5,
    phase_rad=math.radians(0.05),
    bank_angle_rad=math.radians(0.05),
    pin_offset_m=2e-5,
)
start = time.perf_counter()
production = balance.tolerance(v8, band, runs=10_000)
print(f"{production.runs:,} runs in {time.perf_counter() - start:.2f} s ({production.method})")
production.to_pandas()[
    [
        "order",
        "force_vertical_mean_N",
        "force_vertical_p95_N",
        "force_vertical_linear_p95_N",
        "moment_vertical_p95_Nm",
        "moment_vertical_linear_p95_Nm",
    ]
]
