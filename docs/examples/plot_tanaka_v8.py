"""
The flat-crank V8's shaking force
=================================

Tanaka (1925) compared the free forces of the aero engines of his day; the first of Part III
is a 90° V8 with a flat crank (throws at 0, 180, 180 and 0°). Its first-order forces cancel
between the throws; what is left is the second order, and it shakes the engine sideways:
Tanaka prints 8 × 0.215 cos 2θ per cylinder, in units of m_rec·r·ω², along the horizontal.

The locus below is the tip of the resultant force over one revolution, per cylinder: a line,
not an ellipse, because the forward and backward parts of the second order are equal.
"""

import balance_cli as balance

engine = balance.load("library:tanaka-part3/1a-v8-90-flat")
result = balance.analyse(engine, samples=256, max_order=8)

# %%
# The second order, per cylinder: the largest force over a revolution (the ellipse's major
# semi-axis, here all of it) divided by m_rec·r·ω²·n.
second = result.order(2)
per_cylinder = (abs(second.force_forward) + abs(second.force_backward)) / engine.per_cylinder_unit_n
print(f"second order: {per_cylinder:.4f} per cylinder (Tanaka: .215)")
print(f"largest order after the ideal counterweight: {result.main_order('force')['direction']}")

# %%
# The locus: :func:`balance_cli.plot.locus` draws it and returns the matplotlib figure.
fig = balance.plot.locus([result])
