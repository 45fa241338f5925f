"""
Three car V6s, order by order
=============================

The spectrum of the free forces and moments of three V6s: a 90° V6 on three common crank
pins (odd-firing), a 90° V6 with pins split by 30° (even-firing) and a 60° V6 with pins split
by 60°. None shakes with more than a trace of force (a sixth order, below 2·10⁻⁴ of
m_rec·r·ω²·n); all three rock with a free moment. A counterweight at each end of the
crankshaft can cancel the first-order moment that turns with the crank (solid bars), not the
one that turns against it (hatched): only the 90° split-pin V6 has one, which is why such
engines carry a balance shaft.
"""

import balance_cli as balance

names = ["v6-90-odd-fire", "v6-90-split-pin", "v6-60-split-pin"]
results = [balance.analyse(balance.load(f"library:today/v/{name}")) for name in names]
backward = [abs(r.order(1).moment_backward) > r.engine.noise_floor_nm for r in results]
assert backward == [False, True, False]
assert max(r.counterweighted_per_cylinder for r in results) < 2e-4

fig = balance.plot.spectrum(results)
