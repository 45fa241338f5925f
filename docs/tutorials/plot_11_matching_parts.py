"""
Matching weighed parts to cylinders
===================================

Tanaka weighed the ABC Dragonfly's nine pistons and rods (Part I, Appendix I (f), Table III):
up to 5.5 % apart, mostly because the master rod's small end is heavier than the link rods'.
Fitted as he lists them, they leave a primary force of 19.6 kg that an engine of equal masses
would not have (§ 5 (a)). An engine builder asks what comes next: *which* piston should go in
which cylinder? :func:`balance_cli.match` answers it for any engine, with proof.

This tutorial matches his nine pistons to the nine cylinders (the rods stay: the master rod is
the master rod), checks the best assignment against a brute force over all 9! of them written
here, then fits four pistons and four rods to an in-line 4, where cylinders that the crank
makes equivalent halve the work, and writes the engine as matched.

The same on the command line (see :doc:`/howto/workshop`)::

    balance match docs/data/workshop-inline-4.toml --parts docs/data/workshop-inline-4-parts.csv
    balance match ENGINE.toml --parts PARTS.csv --objective F1 --write matched.toml
"""

import dataclasses
import itertools
import math
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.config import read_configuration
from balance_cli.units import STANDARD_GRAVITY
from balance_cli.workshop import assembled_toml

folder = Path(tempfile.mkdtemp())

# %%
# A parts file
# ------------
#
# Three columns, ``kind,id,mass``: ``piston`` is a piston with its pin, rings and clips (all
# of it reciprocates); ``rod_small`` and ``rod_big`` are a rod's two ends as the two-scale
# fixture weighs them (one id, both rows). Tanaka's Table III gives each piston "with its
# accessories" and its gudgeon pin apart: their sums are the pistons here. (The main
# cylinder's pin is printed 236.3 g in the transcription; its row's sum, 1,867.3 g, and the
# column's mean, 225.5 g, both say 226.3 g.)
pistons_g = {
    "main": 1217.6 + 226.3,
    "1": 1246.2 + 226.8,
    "2": 1212.4 + 226.6,
    "3": 1241.4 + 226.7,
    "4": 1241.3 + 225.6,
    "5": 1244.7 + 220.9,
    "6": 1209.7 + 226.0,
    "7": 1236.3 + 225.1,
    "8": 1248.1 + 225.6,
}
small_ends_g = [423.4, 302.6, 298.5, 298.1, 300.6, 291.9, 292.2, 299.4, 299.2]
csv_path = folder / "dragonfly-pistons.csv"
csv_path.write_text(
    "kind,id,mass\n" + "".join(f"piston,{k},{v:.1f} g\n" for k, v in pistons_g.items()),
    encoding="utf-8",
)
print(csv_path.read_text(encoding="utf-8"))
parts = balance.read_parts_csv(csv_path)

# %%
# The engine with its rods in place
# ---------------------------------
#
# Pistons alone are matched, so each cylinder keeps the rest of its reciprocating mass as the
# configuration gives it: the configuration's mass less the mean piston, plus the piston
# fitted. Here each cylinder's configured mass is its own rod's small end plus the mean
# piston: the engine with every piston at the mean of its kind.
dragonfly = balance.load("library:abc-dragonfly")
mean = parts.mean_piston_kg()
dragonfly = dragonfly.replace(
    cylinders=tuple(
        dataclasses.replace(c, reciprocating_kg=mean + g / 1000)
        for c, g in zip(dragonfly.cylinders, small_ends_g, strict=True)
    )
)

# %%
# Table III as Tanaka fitted it, then matched
# -------------------------------------------
#
# The objective ``F1`` is the primary force (``|F⁺| + |F⁻|``, N) of what the engine as assembled
# has more than the same engine with every cylinder at the mean mass: Tanaka's measure. The
# parts "as given" are fitted in the file's order, the first in cylinder 1 (the main).
result = balance.match(dragonfly, parts, "F1")
given, best = result.given, result.best
print(
    f"{result.assignments_total:,} assignments, {result.evaluated:,} evaluated "
    f"({result.method}, {result.elapsed_s:.2f} s)"
)
first = given.difference.order(1)
kgf = abs(first.force_backward) / STANDARD_GRAVITY
angle = math.degrees(np.angle(first.force_backward))
print(f"as Tanaka fitted them: primary {kgf:.2f} kg at {angle:+.1f}° (Tanaka: 19.6 kg, −17°)")
print(f"matched: primary {best.score_n / STANDARD_GRAVITY:.2f} kg")
print("cylinder:", " ".join(f"{c.number:>4}" for c in dragonfly.cylinders))
print("as given:", " ".join(f"{p:>4}" for p in given.pistons))
print("matched: ", " ".join(f"{p:>4}" for p in best.pistons))
# printed to 0.1 kg and whole degrees
assert abs(kgf - 19.6) < 0.05 and abs(angle + 17) < 0.5

# %%
# The best assignment by brute force
# ----------------------------------
#
# Tanaka's (14)₁ gives the primary of deviations mₙ (Σ mₙ = 0) of cylinders at n·40°: a
# circle of radius ``½·ω²·r·|Σ mₙ·e^{2i·n·40°}|``. Every one of the 9! = 362 880 assignments,
# at once:
omega, r = dragonfly.speed_rad_s, dragonfly.crank_radius_m
pistons = np.array([p.mass_kg for p in parts.pistons])
small = np.array(small_ends_g) / 1000
perms = np.array(list(itertools.permutations(range(9))))
masses = pistons[perms] + small
deviations = masses - masses.mean(axis=1, keepdims=True)
primary = 0.5 * omega**2 * r * np.abs(deviations @ np.exp(2j * np.radians(40 * np.arange(9))))
k = int(np.argmin(primary))
print(f"brute force: {primary[k] / STANDARD_GRAVITY:.4f} kg, pistons {perms[k]}")
# (14)₁ is exact for the primary; the matching's FFT of 256 samples agrees to rounding
assert_allclose(best.score_n, primary[k], rtol=1e-12)
assert best.pistons == tuple(parts.pistons[i].id for i in perms[k])

# %%
# The lightest pistons go opposite the heavy master rod's small end, spread so that their
# own deviations, turned by 2·n·40°, close the chain. Each cylinder's share of the primary,
# chained, as fitted and as matched:
fig, ax = plt.subplots(figsize=(6.5, 6.0), layout="constrained")
for label, fitting, colour in (("as given", given, "C3"), ("matched", best, "C0")):
    shares = np.array([c.reciprocating_kg for c in fitting.engine.cylinders])
    shares = (shares - shares.mean()) * np.exp(2j * np.radians(40 * np.arange(9)))
    chain = np.concatenate([[0], np.cumsum(shares)]) * 0.5 * omega**2 * r / STANDARD_GRAVITY
    ax.plot(chain.real, chain.imag, "-o", color=colour, markersize=3, label=label)
    end = (chain[-1].real, chain[-1].imag)
    ax.annotate("", end, (0, 0), arrowprops={"arrowstyle": "->", "color": colour})
ax.set(
    aspect="equal",
    xlabel="kg",
    ylabel="kg",
    title="Dragonfly: each cylinder's share of the primary, chained",
)
ax.legend()

# %%
# An in-line 4 with four pistons and four rods
# --------------------------------------------
#
# With both kinds given, a cylinder's reciprocating mass is its piston plus its rod's small
# end, and a throw's rotating mass its rod's big end. The default objective is the largest
# force over a revolution (all orders) plus the largest free moment over the pitch, of what
# the deviations add. 4!·4! = 576 assignments; the crank read from the other end (1↔4, 2↔3)
# scores alike, so 288 are evaluated.
INLINE_4 = """\
name = "In-line 4, car proportions"
cycle = 4
speed = "6000 rpm"
crank_radius = "43 mm"
rod_length = "143 mm"
firing_order = [1, 3, 4, 2]

[masses]
reciprocating = "550 g"   # piston, pin, rings and clips with the rod's small end
rotating = "560 g"        # the rod's big end

[[banks]]
angle = 0
""" + "".join(
    f'\n[[throws]]\nphase = {phase}\nz = "{88 * j} mm"\n'
    for j, phase in enumerate((0, 180, 180, 0))
)
(folder / "inline-4.toml").write_text(INLINE_4, encoding="utf-8")
(folder / "parts.csv").write_text(
    """\
kind,id,mass
piston,P1,402.3 g
piston,P2,398.1 g
piston,P3,405.0 g
piston,P4,400.2 g
rod_small,R1,151.0 g
rod_big,R1,412.0 g
rod_small,R2,148.2 g
rod_big,R2,405.5 g
rod_small,R3,150.1 g
rod_big,R3,409.9 g
rod_small,R4,149.0 g
rod_big,R4,415.3 g
""",
    encoding="utf-8",
)
engine = balance.load(folder / "inline-4.toml")
four = balance.match(engine, folder / "parts.csv")
print(
    f"{four.assignments_total} assignments, {four.symmetries} symmetries, {four.evaluated} "
    f"evaluated: {four.method}"
)
print(f"as given {four.given.score_n:.1f} N, matched {four.best.score_n:.1f} N")
assert four.assignments_total == 576 and four.evaluated == 288

# %%
# By hand: the first-order force of the deviations. A piston's first order is
# m·r·ω²·cos(θ + β) along the axis (half forward, half backward), a big end's m·r·ω² turns
# with the crank; the throws are at 0 or 180°.
rows = four.best.cylinder_rows()
recip = np.array([row["reciprocating_kg"] for row in rows])
big = np.array([row["rotating_kg"] for row in rows])
signs = np.array([1, -1, -1, 1])
d_recip, d_big = recip - recip.mean(), big - big.mean()
forward = abs((0.5 * d_recip + d_big) @ signs) * engine.crank_radius_m * engine.speed_rad_s**2
backward = abs(0.5 * d_recip @ signs) * engine.crank_radius_m * engine.speed_rad_s**2
o = four.best.difference.order(1)
print(
    f"F1 forward {abs(o.force_forward):.3f} N (by hand {forward:.3f}), backward "
    f"{abs(o.force_backward):.3f} N (by hand {backward:.3f})"
)
assert_allclose([abs(o.force_forward), abs(o.force_backward)], [forward, backward], rtol=1e-9)

# %%
# The engine as matched, written
# ------------------------------
#
# :func:`balance_cli.workshop.assembled_toml` (``balance match --write``) writes the
# configuration with each cylinder's and each throw's own masses, under a name of its own, so
# that it compares beside the original.
data = read_configuration(folder / "inline-4.toml").data
text = assembled_toml(
    data, engine, four.best.engine, "written by the tutorial", four.best.engine.name
)
print(text[text.index("[[throws]]") :])
written = balance.loads(text, "matched.toml")
comparison = balance.compare([balance.analyse(engine), balance.analyse(written)])
comparison
