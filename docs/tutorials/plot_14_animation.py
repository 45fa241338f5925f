"""
Pictures that move
==================

Engineers explain balance to each other with a turning engine and rotating arrows.
:func:`balance.plot.animate <balance_cli.plot.animate>` draws both from an analysed engine: the
mechanism turning through its working cycle, every piston, rod and crank where the exact
kinematics put it, and beside it the forward and backward phasors of the orders you choose, of
the shaking force and of the free moment, their sum, and the resultant's locus being traced.
The pistons light up as they fire.

This tutorial animates GM's cross-plane V8 (the LS3 of the library), checks the one thing
its crank leaves free, a first-order couple turning with the crank, against the value worked
by hand, leaves a cylinder out as the page lets you do, and animates a radial with link rods.
The page below each cell is live: play and pause it, change its speed, step from one firing
top dead centre to the next, turn orders and cylinders on and off.
"""

import math
import tempfile
from pathlib import Path

from numpy.testing import assert_allclose
from PIL import Image

import balance_cli as balance

engine = balance.load("library:today/v/v8-90-cross-plane")
result = balance.analyse(engine)
animation = balance.plot.animate(result)  # orders 1 and 2
animation

# %%
# One instant
# -----------
#
# ``figure(angle_deg)`` draws one instant as a matplotlib figure, the same picture as each
# frame of a GIF: here 45° into the cycle, where cylinder 1 (left bank, front) reaches its
# firing top dead centre. Seen along the crank axis, the crank turns clockwise; seen from the
# side, the four throws stand 90° apart (0, 90, 270 and 180°). Below, the phasors: the force's
# first and second orders are nothing, its fourth (not shown) is what is left, and the
# first-order couple M1 turns with the crank, a circle.
fig = animation.figure(45.0)

# %%
# The couple by hand
# ------------------
#
# A piston in a bank at γ on a throw at β shakes the engine with m·r·ω²·cos(θ + β − γ) along
# its bore at first order (the rod adds only even orders): a forward phasor m·r·ω²/2·e^{iβ}
# and a backward one m·r·ω²/2·e^{−i(β − 2γ)}. Two pistons on one pin, in banks at ±45°,
# add their forward halves to m·r·ω²·e^{iβ} and cancel their backward ones. The four throws
# sit at z = 0, d, 2d, 3d with phases 0, 90, 270 and 180°; about the middle (z̄ = 1.5d) their
# levers are −1.5d, −0.5d, 0.5d, 1.5d, so the couple's forward phasor is
# m·r·ω²·d·(−1.5 − 0.5i − 0.5i − 1.5), of size √10·m·r·ω²·d, and there is no backward part:
# a couple turning with the crank, which counterweights on the crank can cancel (that is why
# the crank is cross-plane).
m = engine.cylinders[0].reciprocating_kg
r, omega = engine.crank_radius_m, engine.speed_rad_s
d = engine.throws[1].z_m - engine.throws[0].z_m
first = result.order(1)
by_hand = math.sqrt(10) * m * r * omega**2 * d
assert_allclose(abs(first.moment_forward), by_hand, rtol=1e-9)
assert abs(first.moment_backward) < engine.noise_floor_nm
assert abs(first.force_forward) < engine.noise_floor_n
print(f"M1 forward {abs(first.moment_forward):.0f} N·m = √10·m·r·ω²·d = {by_hand:.0f} N·m")

# %%
# A cylinder left out
# -------------------
#
# The page carries each cylinder's share of every phasor, so that turning a cylinder off is a
# subtraction; the free moment is then taken about the remaining cylinders' middle, as balance
# analyses an engine built without that cylinder. The V8 has no first-order force, so without
# cylinder 3 it has the opposite of that cylinder's own: forward and backward phasors of
# m·r·ω²/2 each (see above).
view = animation.scene()
force, moment = view.shares(left_out=(3,))
half = m * r * omega**2 / 2
assert_allclose(abs(force[0]), [half, half], rtol=1e-9)
reduced = engine.replace(
    name="The V8 without cylinder 3",
    cylinders=tuple(c for c in engine.cylinders if c.number != 3),
    firing_order=tuple(n for n in engine.firing_order if n != 3),
)
check = balance.analyse(reduced).order(1)
assert_allclose(force[0], [check.force_forward, check.force_backward], atol=1e-9 * half)
print(f"without cylinder 3: F1 forward and backward {abs(force[0][0]):.0f} N each = m·r·ω²/2")

# %%
# A radial with link rods
# -----------------------
#
# Tanaka's nine-cylinder radial of Part III: one master rod and eight link rods on one crank
# pin. Its firing top dead centres are not evenly spaced (a link rod's piston peaks a little
# off its bank's angle), so its firings come at 82.3°, 79.3°, 75.0°, ... apart; the page's
# step button stops at each one exactly, not on the nearest frame. The master rod's cylinder
# cannot be turned off: the link rods hang on it.
radial = balance.analyse(balance.load("library:tanaka-part3/5a-radial-9"))
intervals = radial.firing.intervals_deg
assert_allclose(intervals[:3], [82.33, 79.27, 74.95], atol=0.005)
balance.plot.animate(radial, orders=[1, 2, 4])

# %%
# A GIF and a page
# ----------------
#
# ``save`` writes the animation in the format the file name's extension names: ``.gif``
# (Pillow; 72 frames a cycle, 720 × 446 pixels, by default), ``.mp4`` (ffmpeg, where it is
# installed) or ``.html`` (the page above, self-contained). From the command line:
# ``balance animate FILE -o v8.gif -o v8.html``.
with tempfile.TemporaryDirectory() as folder:
    gif = Path(folder) / "v8.gif"
    animation.save(gif)
    with Image.open(gif) as movie:
        frames, size = movie.n_frames, movie.size
    megabytes = gif.stat().st_size / 1e6
assert frames == 72 and size == (720, 446) and megabytes < 2
print(f"v8.gif: {frames} frames of {size[0]} × {size[1]} pixels, {megabytes:.2f} MB")
