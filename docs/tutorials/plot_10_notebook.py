"""
Balance in a notebook
=====================

Load an engine, look at its result as the command line would print it, take its rows into a
pandas DataFrame, change the engine in the units you would type (a throw's phase in degrees, a
piston's mass in grams) and compare the two. Every line below runs as it is in a Jupyter
notebook, where each result shows itself as the command's tables.

The engine is a motorcycle's parallel twin from the library: Kawasaki's 650, whose throws are
180° apart.
"""

import math

import balance_cli as balance

engine = balance.load("library:today/inline/inline-2-180")
result = balance.analyse(engine, max_order=4)
result

# %%
# Its rows
# --------
#
# ``records()`` gives one flat dict per row, every value a plain number or string in SI, the
# unit in the key; ``to_pandas()`` makes a DataFrame of the same rows (``pip install
# 'engine-balance[pandas]'``). An engine's rows are its orders.
frame = result.to_pandas()
frame[["order", "force_max_N", "moment_max_Nm", "moment_forward_deg"]]

# %%
# The 180° twin's pistons move in opposition: no first-order force, but a first-order couple
# of one cylinder's force m·r·ω² times the pitch d, pitching the engine. The DataFrame holds it
# (the script checks the figure against the closed form, so this page cannot drift):
m = engine.cylinders[0].reciprocating_kg
r, omega = engine.crank_radius_m, engine.speed_rad_s
d = engine.throws[1].z_m - engine.throws[0].z_m
first = frame.set_index("order").loc[1]
assert math.isclose(first["moment_max_Nm"], m * r * omega**2 * d, rel_tol=1e-9)
assert first["force_max_N"] == 0.0
print(f"first-order couple: {first['moment_max_Nm']:.0f} N·m = m·r·ω²·d")

# %%
# Change the engine
# -----------------
#
# :meth:`Engine.edit <balance_cli.Engine.edit>` returns a copy with values changed as a
# configuration file writes them, checked like any new engine: here throw 2 moves from 180° to
# 270° (the "crossplane" twin's crank), under a name of its own, since a comparison tells
# engines apart by name.
crossplane = engine.edit(throw=2, phase=270, name="The same twin, 270° crank")
moved = balance.analyse(crossplane, max_order=4)

# %%
# By hand: the two first orders are now 270° apart, so their forces add to √2·m·r·ω² (the
# magnitude of 1 + e^{i·270°} is √2) and their couple shrinks to m·r·ω²·d·sin 135° =
# m·r·ω²·d/√2.
rows = moved.to_pandas().set_index("order")
assert math.isclose(rows.loc[1, "force_max_N"], math.sqrt(2) * m * r * omega**2, rel_tol=1e-9)
assert math.isclose(rows.loc[1, "moment_max_Nm"], m * r * omega**2 * d / math.sqrt(2), rel_tol=1e-9)
rows[["force_max_N", "moment_max_Nm"]]

# %%
# Lighter pistons scale every force of the reciprocating masses: 400 g instead of 450 g is
# 8/9 of each.
lighter = balance.analyse(
    crossplane.edit(reciprocating="400 g", name="270°, 400 g pistons"), max_order=4
)
for before, after in zip(moved.records(), lighter.records(), strict=True):
    assert math.isclose(after["force_max_N"], before["force_max_N"] * 400 / 450, rel_tol=1e-9)

# %%
# Compare
# -------
#
# A comparison shows the tables of ``balance compare``; its rows are every engine's orders,
# which pandas turns into a table of engines side by side.
comparison = balance.compare([result, moved, lighter])
comparison

# %%
table = comparison.to_pandas().pivot(index="order", columns="engine", values="moment_max_Nm")
table

# %%
# A picture
# ---------
#
# :func:`balance_cli.plot.spectrum` draws every order of the three engines, force and moment.
fig = balance.plot.spectrum([result, moved, lighter], units="N")
