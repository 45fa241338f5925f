"""
Free moments: in-line 3, in-line 5, boxer 4
============================================

The locus of the free moment about the engine's mid-length over a revolution, all orders,
once an ideal counterweight at each end of the crankshaft has taken the part of the first
order that turns with the crank. The in-line five's couple, mostly of the second order, pitches
it (along its cylinders); of the in-line three's first-order couple the counterweights take
half, and the half left turns against the crank: its locus is a loop. The boxer four keeps
only a second-order couple across its cylinders, which yaws it.
"""

import balance_cli as balance

names = ["inline/inline-3", "inline/inline-5", "boxer/boxer-4"]
results = [balance.analyse(balance.load(f"library:today/{name}")) for name in names]
boxer = results[2].order(2).to_dict()["moment"]
assert abs(boxer["axis_deg"] - 90) < 1e-6  # across the cylinders, exactly

fig = balance.plot.locus(results, of="moment")
