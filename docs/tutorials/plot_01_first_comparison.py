"""
A first comparison
==================

Load two engines of the library, analyse them, and compare their free forces order by
order. (A first draft: the tutorial is to be written out.)
"""

import balance_cli as balance

flat = balance.analyse(balance.load("library:tanaka-part3/1a-v8-90-flat"))
radial = balance.analyse(balance.load("library:tanaka-part3/5a-radial-9"))

# %%
# Each order's force is two phasors: the part turning with the crank (forward) and the part
# turning against it (backward). Their sum of magnitudes is the largest force over a
# revolution; divided by m_rec·r·ω²·n it is Tanaka's per-cylinder figure.
for result in (flat, radial):
    unit = result.per_cylinder_unit_n
    second = result.order(2)
    print(
        f"{result.engine.name}: forward {abs(second.force_forward) / unit:.4f}, "
        f"backward {abs(second.force_backward) / unit:.4f} per cylinder"
    )

# %%
# :func:`balance_cli.compare` puts the largest forces side by side, as percentages of a
# reference engine (the first, unless told otherwise).
comparison = balance.compare([flat, radial])
for entry in comparison.to_dict()["engines"]:
    print(entry["name"], entry["percent_of_reference"])

# %%
# The spectrum draws every order of both engines.
fig = balance.plot.spectrum([flat, radial])
