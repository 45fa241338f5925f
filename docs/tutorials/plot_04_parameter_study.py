"""
A parameter study
=================

An in-line four with a flat crank has no free force or couple of the first order, but its
four pistons shake it together twice a revolution: the second-order force, 4·m·r·ω²·A₂,
where A₂ grows with λ = r/l, the crank radius over the rod length. How much does a longer
rod buy, and how does it trade against speed? This tutorial sweeps the rod/crank ratio l/r
of the library's Honda K20A (``configs/today/inline/inline-4.toml``), checks the second
order against its closed form, and then maps rod ratio against speed over a grid.
"""

import math
import textwrap

from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.studies.sweep import span

CONFIG = "library:today/inline/inline-4"
engine = balance.load(CONFIG)
print(
    f"{engine.name}: r = {engine.crank_radius_m * 1000:g} mm, "
    f"l = {engine.rod_length_m * 1000:g} mm, "
    f"l/r = {engine.rod_length_m / engine.crank_radius_m:.3f}, "
    f"m = {engine.mean_reciprocating_kg} kg, {engine.speed_rad_s * 30 / math.pi:g} rpm"
)

# %%
# Sweeping the rod ratio
# ----------------------
#
# ``rod_ratio`` is not a key of the file but a *derived* parameter: each value l/r is written
# back into the file's ``rod_length`` (= ratio × ``crank_radius``), with the crank radius
# held, and the engine built and checked at every point as a file is.
# :func:`balance_cli.sweep` takes the file, the parameter, its values and the quantities to
# report at each: here the second- and fourth-order forces (``F2``, ``F4``: each order's
# largest value over a revolution) and the largest resultant force (``largest_force``, all
# orders, after an ideal counterweight). ``balance sweep FILE --vary rod_ratio --from 2.5
# --to 5 --steps 11 --quantity F2,F4,largest_force`` is the same from the command line.
ratios = span(2.5, 5, 11)
sweep = balance.sweep(CONFIG, "rod_ratio", ratios, quantities="F2,F4,largest_force")
print(textwrap.fill(sweep.to_dict()["parameter"]["meaning"], 78))
print(f"{'l/r':>5} {'F2 (N)':>9} {'F4 (N)':>8} {'largest (N)':>12}")
for point in sweep.points:
    print(
        f"{point['value']:5.2f} {point['F2_N']:9.0f} {point['F4_N']:8.1f} "
        f"{point['largest_force_N']:12.0f}"
    )

# %%
# The closed form, at one point
# -----------------------------
#
# A piston's acceleration is −r·ω²·(cos θ + A₂·cos 2θ − A₄·cos 4θ + …), the series of the
# exact crank-slider in λ = r/l:
#
# - A₂ = λ + λ³/4 + 15λ⁵/128 + 35λ⁷/512 + …
# - A₄ = λ³/4 + 3λ⁵/16 + 35λ⁷/256 + …
#
# The four pistons' second (and fourth) orders are all in phase on a flat crank (pins 0, 180,
# 180, 0°; 2·180° ≡ 0), so F2 = 4·m·r·ω²·A₂ and F4 = 4·m·r·ω²·A₄ along the cylinders. At
# l/r = 3.5, λ = 1/3.5 exactly (the sweep sets l = 3.5·r):
point = sweep.points[ratios.index(3.5)]
m, r, w = engine.mean_reciprocating_kg, engine.crank_radius_m, engine.speed_rad_s


def a2(lam):
    """A₂(λ) to λ⁷."""
    return lam + lam**3 / 4 + 15 * lam**5 / 128 + 35 * lam**7 / 512


def a4(lam):
    """A₄(λ) to λ⁷."""
    return lam**3 / 4 + 3 * lam**5 / 16 + 35 * lam**7 / 256


A2, A4 = a2(1 / 3.5), a4(1 / 3.5)
print(f"l/r = 3.5: F2 {point['F2_N']:.1f} N, by hand 4·m·r·ω²·A₂ = {4 * m * r * w**2 * A2:.1f} N")
print(f"           F4 {point['F4_N']:.2f} N, by hand 4·m·r·ω²·A₄ = {4 * m * r * w**2 * A4:.2f} N")
# the library moves the pistons exactly and Fourier-transforms; the series stop at λ⁷: the
# next terms are 0.045·λ⁹ in A₂ (5e-6 of it here: rtol 2e-5) and 0.10·λ⁹ in A₄ (2.2e-4 of
# it: rtol 5e-4)
assert_allclose(point["F2_N"], 4 * m * r * w**2 * A2, rtol=2e-5)
assert_allclose(point["F4_N"], 4 * m * r * w**2 * A4, rtol=5e-4)

# %%
# Over the whole sweep, F2 falls slowly: A₂ is nearly λ itself, so doubling the rod ratio
# from 2.5 to 5 little more than halves it, while the fourth order, of λ³, falls almost
# ninefold.
F2, F4 = sweep.series("F2"), sweep.series("F4")
print(f"from l/r 2.5 to 5: F2 × {F2[-1] / F2[0]:.3f}, F4 × {F4[-1] / F4[0]:.3f}")

# %%
# :func:`balance_cli.plot.sweep_figure` draws the quantities against the parameter, one panel
# per kind (here all forces), in the units asked for:
curves = balance.plot.sweep_figure(sweep, units="kN")

# %%
# Rod ratio and speed together
# ----------------------------
#
# :func:`balance_cli.sweep_grid` takes two parameters and a list of values for each, and
# analyses every pair (the first parameter's values vary slowest): here l/r from 2.5 to 5
# against the speed from 3000 to 9000 rpm. ``grid.grid("F2")`` is the quantity as an array,
# ``[i, j]`` at the i-th rod ratio and the j-th speed.
speeds = span("3000 rpm", "9000 rpm", 13)
grid = balance.sweep_grid(
    CONFIG, ["rod_ratio", "speed"], [ratios, speeds], quantities="F2,largest_force"
)
F2_grid = grid.grid("F2")
print(
    f"grid {grid.shape}: F2 from {F2_grid.min():.0f} N (l/r 5, 3000 rpm) "
    f"to {F2_grid.max():.0f} N (l/r 2.5, 9000 rpm)"
)

# %%
# Two checks by hand. A force of inertia goes as ω²: along a row the second order grows as
# the square of the speed, exactly. And the column at the file's own speed, 8000 rpm, is the
# sweep above, point for point.
rpm = [float(s.split()[0]) for s in speeds]
assert_allclose(
    F2_grid / F2_grid[:, :1], [[(n / rpm[0]) ** 2 for n in rpm]] * len(ratios), rtol=1e-12
)  # the same kinematics scaled: rounding only
assert_allclose(F2_grid[:, rpm.index(8000.0)], F2, rtol=1e-12)

# %%
# So what does a longer rod buy against speed? At 8000 rpm with the file's rod (l/r 3.23),
# the four shakes with F2 = 18.4 kN. The same force at 9000 rpm needs A₂ smaller by
# (8/9)² = 0.79: a rod ratio of about 4.1, solved from the series and checked by one more
# analysis at 9000 rpm (``overrides`` sets a key at every point of a sweep, here the speed).
file_ratio = engine.rod_length_m / engine.crank_radius_m
second = balance.analyse(engine).order(2)
at_file = abs(second.force_forward) + abs(second.force_backward)
target = (8000 / 9000) ** 2 * at_file / (4 * m * r * w**2)  # the A₂ that 9000 rpm allows
low, high = 0.1, 0.5  # λ: bisect the series for A₂(λ) = target
for _ in range(60):
    mid = (low + high) / 2
    low, high = (mid, high) if a2(mid) < target else (low, mid)
needed = 1 / low
at_needed = balance.sweep(
    CONFIG, "rod_ratio", [needed], quantities="F2", overrides={"speed": "9000 rpm"}
).points[0]["F2_N"]
print(
    f"F2 at 8000 rpm, l/r {file_ratio:.3f}: {at_file:.0f} N; "
    f"at 9000 rpm it takes l/r {needed:.3f}: {at_needed:.0f} N"
)
# the series stops at λ⁷ (5e-6 of A₂), the bisection at 1e-16: the same force to 2e-5
assert_allclose(at_needed, at_file, rtol=2e-5)
assert round(at_file, -2) == 18400 and round(needed, 1) == 4.1

# %%
# The heat maps: :func:`balance_cli.plot.sweep_figure` of a grid draws one per quantity, the
# first parameter (the rod ratio) along x and the second (the speed) up, the colour scale from
# zero, with labelled contour lines (``balance sweep FILE --vary rod_ratio ... --vary speed
# ... --plot grid.png`` from the command line). The contours of F2 climb to the right: every
# step up in speed asks for a longer rod to hold the same force, and ever more of it.
fig = balance.plot.sweep_figure(grid, units="kN")
