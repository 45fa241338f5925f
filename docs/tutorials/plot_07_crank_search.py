"""
Searching a crankshaft
======================

An in-line engine of N cylinders can have its throws in many orders round the shaft, and
each crank can fire in several orders: (N − 1)!/2 arrangements for a two-stroke (60 for six
cylinders, about 20 million for twelve). Which leaves the least free force and couple?
Designers chose by hand and by tradition; :func:`balance_cli.search` enumerates them all,
with proof that nothing better exists.

This tutorial searches the shipped templates of an in-line six four-stroke, an in-line six
two-stroke and an in-line twelve two-stroke: objectives and their weights, the forward and
backward parts of an order, the exhaustive search against the heuristic one, the symmetries
that make the search cheap, and writing the arrangement found as a configuration. It checks
the textbook's statement about the six four-stroke by a phasor sum by hand.

The same on the command line (see :doc:`/reference/cli`)::

    balance search template:inline-6-4stroke --objective M1,M2
    balance search template:inline-6-2stroke --objective M1:4,M2 --top 3 --write best/
    balance compare best/arrangement-01.toml
"""

import math
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.config import arrangement_toml, read_configuration, resolve

# %%
# A template
# ----------
#
# A search template is an ordinary configuration whose ``[[throws]]`` give only their axial
# position ``z`` (no ``phase``) and which has no ``firing_order``: the search chooses both.
# ``template:NAME`` names one of the templates installed with balance.
path = resolve("template:inline-6-4stroke")
text = path.read_text(encoding="utf-8")
print(text[text.index("name =") : text.index("[[throws]]")].strip())
template = balance.load_template(path)
print("throws at z =", [f"{t.z_m * 1000:g} mm" for t in template.throws])

# %%
# The in-line six four-stroke
# ---------------------------
#
# The objective names what to minimise: ``F<k>`` the order-k free force and ``M<k>`` the
# order-k free couple, as coefficients (a force in units of one cylinder's largest order-k
# force, a couple in that force times the cylinder pitch), added up with their weights.
# With even firing, every top dead centre falls on a lattice of 720°/6 = 120°: a throw's
# phase is a multiple of 120°. Throw 1 stays at 0°; of the five others one more sits at 0°,
# two at 120° and two at 240°, which makes 5!/(2!·2!) = 30 cranks; each fires in
# 2^(6/2 − 1) = 4 orders (which cylinder of each pair fires first).
result = balance.search(template, "M1,M2", top=6, workers=1)
print(
    f"{result.arrangements_total} arrangements, {result.arrangements_distinct} distinct, "
    f"{result.evaluated} cranks evaluated; exhaustive: {result.exhaustive}"
)
for symmetry in result.symmetries:
    print("  symmetry:", symmetry)
assert result.arrangements_total == 30 * 4 == math.factorial(5) // (2 * 2) * 4
assert result.firing_orders_per_crank == 4

print("\nrank score  phases (°)            firing order")
for a in result.arrangements:
    phases = " ".join(f"{p:3.0f}" for p in a.phases_deg)
    order = "-".join(map(str, a.firing_order))
    print(f"{a.rank:4d} {a.score:6.4f} {phases}  {order}")

# %%
# The best crank, by hand
# -----------------------
#
# The textbooks (Heisler's *Advanced Engine Technology*, Tanaka's Part III) say an in-line
# six four-stroke on the crank 0-120-240-240-120-0 (two in-line threes, mirror images of
# each other; 0-240-120-120-240-0 is the same crank run the other way round) has no free
# force and no free couple of the first and second order. An in-line engine's identical
# cylinders all have the same order-k force, turned by k·β_j for throw j at phase β_j; so
# the order's free force is one cylinder's times ``|Σ_j e^{ik·β_j}|`` and its free couple one
# cylinder's times ``|Σ_j (z_j − z̄)·e^{ik·β_j}|``. The best crank's phases, summed by hand
# (the piston of a plain rod has no odd order above the first, so orders 4 and 6 are the
# next to look at):
best = result.arrangements[0]
beta = np.radians(best.phases_deg)
z = np.array([t.z_m for t in template.throws])
for k in (1, 2, 4, 6):
    force_sum = abs(np.sum(np.exp(1j * k * beta)))
    couple_sum = abs(np.sum((z - z.mean()) * np.exp(1j * k * beta)))
    print(f"order {k}: |Σ e^(ikβ)| = {force_sum:.3g}, |Σ (z − z̄)·e^(ikβ)| = {couple_sum:.3g} m")
    if k in (1, 2):
        # sums of six unit phasors and of lever arms ≤ 1.25 m: zero to rounding
        assert force_sum < 1e-12 and couple_sum < 1e-12
# %%
# The couples vanish at every order: the crank is symmetric about its middle, throw j
# and throw 7 − j in phase. The sixth-order forces add up in every cylinder: the
# textbook's 6·m·r·ω²·A₆ remains.
assert_allclose(abs(np.sum(np.exp(6j * beta))), 6.0, rtol=1e-12)

# %%
# The arrangement's own analysis (the one ``balance compare`` does) agrees: its orders 1 and
# 2 leave forces and couples at rounding noise beside one cylinder's first-order force.
analysed = best.result
unit_n = analysed.per_cylinder_unit_n
for k in (1, 2):
    o = analysed.order(k)
    force = abs(o.force_forward) + abs(o.force_backward)
    couple = abs(o.moment_forward) + abs(o.moment_backward)
    print(
        f"order {k}: force {force / unit_n:.1e} × m·r·ω², couple {couple / unit_n:.1e} × m·r·ω²·m"
    )
    # the exact analysis sums 256 samples a revolution: rounding, far below 1e-9
    assert force < 1e-9 * unit_n and couple < 1e-9 * unit_n

# %%
# Symmetries
# ----------
#
# Turning the whole crank changes nothing (throw 1 stays at 0°). An arrangement and the same
# engine **run the other way round** (every phase negated, the firing order read backwards)
# count once: the list shows the member with the lower firing order. So the library's truck
# diesel, crank 0-240-120-120-240-0 firing 1-5-3-6-2-4, appears as its reversal,
# 0-120-240-240-120-0 firing 1-4-2-6-3-5. A crank and its **mirror image** (read from the
# other end) balance alike but are different engines: both are listed (``mirror_of`` names
# the other's rank), and only one is evaluated. Which symmetries hold is checked on the
# template's own numbers before the search uses them.
truck = balance.load("library:today/inline/inline-6-truck-diesel")
truck_phases = [round(math.degrees(t.phase_rad)) % 360 for t in truck.throws]
reversed_phases = [-p % 360 for p in truck_phases]
firing = list(truck.firing_order)
reversed_firing = [firing[0], *reversed(firing[1:])]
print("truck:", truck_phases, firing, "-> run backwards:", reversed_phases, reversed_firing)
listed = [([round(p) for p in a.phases_deg], list(a.firing_order)) for a in result.arrangements]
assert (reversed_phases, reversed_firing) in listed
print("distinct:", result.arrangements_distinct, "= half of", result.arrangements_total)

# %%
# Objectives and weights: the two-stroke six
# ------------------------------------------
#
# A two-stroke six fires every 60°, and no crank frees it of both first- and second-order
# couples: the search makes the trade-off explicit. ``M1`` alone, ``M2`` alone, both with
# equal weights (two cranks tie, ranked then by firing order), and ``M1:4,M2`` (the first
# order four times as costly). ``M1-`` counts the first order's **backward** part only:
# the forward part turns with the crank, and counterweights on the crank can cancel it; the
# backward part needs a counter-rotating balancer.
two_stroke = balance.load_template("template:inline-6-2stroke")
print("objective  best firing order  score   M1      M2")
found = {}
for objective in ("M1", "M2", "M1,M2", "M1:4,M2", "M1-,M2"):
    found[objective] = balance.search(two_stroke, objective, top=1, workers=1).arrangements[0]
    a = found[objective]
    order = "-".join(map(str, a.firing_order))
    m1, m2 = a.coefficients["M1"], a.coefficients["M2"]
    print(f"{objective:10s} {order:17s}  {a.score:.4f}  {m1:.4f}  {m2:.4f}")

# %%
# The marine designer's classic, 1-5-3-4-2-6 (crank 0-120-240-180-300-60), is free of
# first-order couple and leaves 2√3 of the second; by hand, with the pitch d of the template:
classic = found["M1:4,M2"]
assert list(classic.firing_order) == [1, 5, 3, 4, 2, 6]
beta = np.radians(classic.phases_deg)
z = np.array([t.z_m for t in two_stroke.throws])
pitch = (z[-1] - z[0]) / (len(z) - 1)
for k, expected in ((1, 0.0), (2, 2 * math.sqrt(3))):
    by_hand = abs(np.sum((z - z.mean()) * np.exp(1j * k * beta))) / pitch
    print(f"M{k}: by hand {by_hand:.4f}, search {classic.coefficients[f'M{k}']:.4f}")
    # a sum of six phasors: rounding, far below 1e-9
    assert_allclose([by_hand, classic.coefficients[f"M{k}"]], expected, atol=1e-9)

# %%
# Exhaustive or heuristic
# -----------------------
#
# The exhaustive search evaluates every class of arrangements that its symmetries and a
# bound (a partial sum that already scores worse than the best found cannot improve) leave;
# evaluated + skipped by the bound + left out by symmetry cover them all, which is the
# proof. Where that would take too long, ``heuristic=True`` runs a local search from random
# cranks: often as good, labelled not proved. (On a problem this small it evaluates more
# than the exhaustive search does.)
exhaustive = balance.search(two_stroke, "M1,M2", top=2, workers=1)
heuristic = balance.search(two_stroke, "M1,M2", top=2, heuristic=True, restarts=20, seed=0)
for r in (exhaustive, heuristic):
    scores = ", ".join(f"{a.score:.4f}" for a in r.arrangements)
    print(f"{r.method:10s} proved: {r.exhaustive!s:5s} evaluated {r.evaluated:4d}, best {scores}")
assert heuristic.method == "heuristic" and not heuristic.exhaustive
assert heuristic.evaluated > exhaustive.evaluated
# the same best score: 2√3 (two cranks tie)
assert_allclose(heuristic.arrangements[0].score, exhaustive.arrangements[0].score, rtol=1e-12)
assert_allclose(exhaustive.arrangements[0].score, 2 * math.sqrt(3), rtol=1e-9)

# %%
# Every arrangement of the two-stroke six, by its two couples: ``top=60`` lists all the
# distinct ones. The lower left corner is empty: something is always left.
everything = balance.search(two_stroke, "M1,M2", top=60, workers=1)
m1 = np.array([a.coefficients["M1"] for a in everything.arrangements])
m2 = np.array([a.coefficients["M2"] for a in everything.arrangements])
assert len(everything.arrangements) == everything.arrangements_distinct == math.factorial(5) // 2
# no crank is free of both: the smallest M1 + M2 is the tie's 2√3
assert_allclose((m1 + m2).min(), 2 * math.sqrt(3), rtol=1e-9)
fig, ax = plt.subplots(figsize=(7, 5), layout="constrained")
ax.scatter(m1, m2, color="0.6", label="the 60 distinct arrangements (some coincide)")
for objective, marker in (("M1:4,M2", "o"), ("M1,M2", "s"), ("M2", "^")):
    a = found[objective]
    ax.scatter(
        a.coefficients["M1"],
        a.coefficients["M2"],
        marker=marker,
        s=80,
        facecolor="none",
        edgecolor="C3",
        label=f"best for {objective}: {'-'.join(map(str, a.firing_order))}",
    )
ax.set(
    xlabel="M1 (× one cylinder's first-order force × pitch)",
    ylabel="M2 (× one cylinder's second-order force × pitch)",
    title="In-line 6 two-stroke: first- against second-order couple",
)
ax.legend(fontsize=8)

# %%
# The in-line twelve two-stroke
# -----------------------------
#
# Eleven free throws make 11! = 39 916 800 arrangements, 19 958 400 distinct. Meet in the
# middle (each half's partial sums computed once, paired by the lattice points they fill)
# and the symmetries bring them to about a second on two processes.
twelve = balance.load_template("template:inline-12-2stroke")
big = balance.search(twelve, "M1,M2,M3,M4", top=3, workers=2)
print(
    f"{big.arrangements_total:,} arrangements, {big.arrangements_distinct:,} distinct, "
    f"{big.evaluated:,} evaluated, {big.pruned:,} skipped by the bound, {big.elapsed_s:.1f} s"
)
for a in big.arrangements:
    print(f"{a.rank} {a.score:.4f} {'-'.join(map(str, a.firing_order))}")
assert big.arrangements_total == math.factorial(11)
assert big.arrangements_distinct == math.factorial(11) // 2

# %%
# Writing the arrangement found
# -----------------------------
#
# ``balance search --write DIR`` writes each arrangement listed as a complete configuration
# (the template's keys with the phases, the firing order and a name). In Python,
# :func:`balance_cli.config.arrangement_toml` writes it from the template's parsed data; the
# file then loads and analyses as any other.
data = read_configuration("template:inline-6-2stroke").data
written = arrangement_toml(
    data,
    classic.phases_deg,
    classic.firing_order,
    "In-line 6 two-stroke, 1-5-3-4-2-6",
    header="written by the crank search tutorial",
)
print(written)
with tempfile.TemporaryDirectory() as folder:
    best_file = Path(folder) / "arrangement-01.toml"
    best_file.write_text(written, encoding="utf-8")
    engine = balance.load(best_file)
assert list(engine.firing_order) == [1, 5, 3, 4, 2, 6]
assert_allclose(
    [math.degrees(t.phase_rad) % 360 for t in engine.throws], classic.phases_deg, atol=1e-9
)

# %%
# The two cranks that tie for ``M1,M2``, each cylinder's share of the first-order couple
# chained (:func:`balance_cli.plot.star`): 1-5-3-4-2-6's shares close on themselves, those
# of the other leave a couple of 2√3 (and it has no second-order couple instead). The
# arrow ``pins`` is the share of the rotating masses on the crank pins, which counterweights
# would take away.
tied = [
    balance.analyse(a.engine.replace(name="-".join(map(str, a.firing_order))))
    for a in exhaustive.arrangements
]
fig = balance.plot.star(tied, order=1, of="moment")
