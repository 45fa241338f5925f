"""
The balancing sheet
===================

A crankshaft is balanced on a machine that spins it with a **bobweight** clamped on each crank
pin: the rotating parts the pin carries (the big ends) and a share of the reciprocating parts
(pistons with pins, rings and clips, and the rods' small ends), so that the counterweights
ground to balance it are the ones the engine needs. Race shops balance a V8 this way, with
100 % of the rotating and 50 % of the reciprocating masses per journal. For a single or a
twin the share, the balance factor, is a choice: it trades vertical shaking for horizontal.
:func:`balance_cli.bobweights` makes the sheet, from the configuration or from weighed parts.

This tutorial checks a cross-plane V8's bobweights against the race shops' rule by hand, from
its configuration and from weighed parts, tables a boxer's, and draws a 360° twin's trade
between vertical and horizontal shaking (the Triumph 650 twin was balanced at 85 %).

The same on the command line (see :doc:`/howto/workshop`)::

    balance bobweight library:today/inline/inline-2-360 --factors 0.5,0.6,0.7,0.85
    balance bobweight matched.toml --balance-factor 0.5
"""

import math

import matplotlib.pyplot as plt
import numpy as np
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.workshop import PartSet, Piston, Rod

# %%
# A cross-plane V8 by the rule
# ----------------------------
#
# Two rods share each of the four crank pins. By default the factor is the one
# ``balance counterweight`` implies: its counterweights cancel the forward first order, and
# a plain rod's reciprocating mass makes a line force of which half turns with the crank. So
# each bobweight is the pin's rotating mass (both big ends) plus half its two cylinders'
# reciprocating masses: 1.1 kg + ½·2·0.75 kg = 1.85 kg.
v8 = balance.load("library:today/v/v8-90-cross-plane").edit(rotating="1.1 kg")
sheet = balance.bobweights(v8)
for pin in sheet.pins:
    print(
        f"pin {pin.throw} (cylinders {pin.cylinders}): {pin.rotating_kg * 1000:.0f} g + "
        f"{pin.factor:.3f} × {pin.reciprocating_kg * 1000:.0f} g = {pin.bobweight_kg * 1000:.1f} g"
    )
    # the test mass from an FFT of 256 samples: rounding
    assert_allclose(pin.bobweight_kg, 1.1 + 0.5 * 2 * 0.75, rtol=1e-9)

# %%
# From weighed parts
# ------------------
#
# With parts, the masses are theirs: each cylinder's piston and small end, each pin's two big
# ends, fitted in the order given (the first listed in cylinder 1). A pin's bobweight by hand
# is its two big ends plus half its two pistons and small ends.
rng = np.random.default_rng(650)
pistons = 0.6 + rng.normal(0, 0.002, 8)
small_ends = 0.15 + rng.normal(0, 0.001, 8)
big_ends = 0.55 + rng.normal(0, 0.003, 8)
parts = PartSet(
    tuple(Piston(f"P{i}", m) for i, m in enumerate(pistons, 1)),
    tuple(Rod(f"R{i}", s, b) for i, (s, b) in enumerate(zip(small_ends, big_ends, strict=True), 1)),
)
weighed = balance.bobweights(v8, parts)
for pin in weighed.pins:
    index = [n - 1 for n in pin.cylinders]
    by_hand = big_ends[index].sum() + 0.5 * (pistons[index].sum() + small_ends[index].sum())
    print(f"pin {pin.throw}: {pin.bobweight_kg * 1000:.2f} g (by hand {by_hand * 1000:.2f} g)")
    assert_allclose(pin.bobweight_kg, by_hand, rtol=1e-9)
weighed.to_pandas()

# %%
# A boxer
# -------
#
# A flat twin has one cylinder on each pin; the same rule holds, pin by pin. A factor may be
# chosen instead: here 60 %.
boxer = balance.load("library:today/boxer/boxer-2").edit(rotating="0.45 kg")
for pin in balance.bobweights(boxer, balance_factor=0.6).pins:
    c = boxer.cylinder(pin.cylinders[0])
    print(
        f"pin {pin.throw}: 450 g + 0.6 × {c.reciprocating_kg * 1000:.0f} g = "
        f"{pin.bobweight_kg * 1000:.0f} g"
    )
    assert_allclose(pin.bobweight_kg, 0.45 + 0.6 * c.reciprocating_kg, rtol=1e-12)

# %%
# A twin's trade
# --------------
#
# A 360° twin moves like a single of twice the mass. Counterweights for the rotating masses
# plus F times the reciprocating ones leave (1 − F)·2m·r·ω² of first-order force along the
# cylinders and F·2m·r·ω² across them: no factor removes both. Triumph's 650 twin ran at 85 %,
# taking vertical shaking out of the frame at the cost of fore-and-aft.
twin = balance.load("library:today/inline/inline-2-360")
factors = tuple(np.round(np.arange(0.5, 0.86, 0.05), 2))
trade = balance.bobweights(twin, factors=factors).trade
m = twin.cylinders[0].reciprocating_kg
unit = 2 * m * twin.crank_radius_m * twin.speed_rad_s**2
print("factor  vertical (N)  horizontal (N)  largest (N)")
for row in trade:
    print(
        f"{row.factor:6.2f}  {row.force_vertical_n:12.0f}  {row.force_horizontal_n:14.0f}  "
        f"{row.largest_force_n:11.0f}"
    )
    # the first order of a 256-sample FFT: rounding
    assert_allclose(
        [row.force_vertical_n, row.force_horizontal_n],
        [(1 - row.factor) * unit, row.factor * unit],
        rtol=1e-9,
    )
at_85 = trade[-1]
print(
    f"85 %: vertical {at_85.force_vertical_n / unit:.2f}, horizontal "
    f"{at_85.force_horizontal_n / unit:.2f} of 2m·r·ω²"
)

# %%
# The largest resultant over a revolution (all orders) is least where the first order's
# ellipse is nearest a circle, about 60 % here: the second order, along the cylinders, adds
# to the vertical first order.
fig, ax = plt.subplots(figsize=(7, 4.5), layout="constrained")
f = np.array([row.factor for row in trade]) * 100
ax.plot(f, [row.force_vertical_n / 1000 for row in trade], "o-", label="first order, vertical")
ax.plot(f, [row.force_horizontal_n / 1000 for row in trade], "s-", label="first order, horizontal")
ax.plot(f, [row.largest_force_n / 1000 for row in trade], "^-", label="largest, all orders")
ax.axvline(85, color="0.6", linestyle="--", linewidth=1)
ax.annotate("Triumph 650 ", (85, 9.0), ha="right", fontsize=8, color="0.4")
ax.set(
    xlabel="balance factor (%)",
    ylabel="kN",
    title="A 360° twin: what each balance factor leaves",
)
ax.legend(fontsize=8)
assert math.isclose(at_85.force_vertical_n / unit, 0.15, rel_tol=1e-9)
