"""
The in-line three's rocking couple
==================================

A star diagram of the first-order free moment of an in-line three: each cylinder's share
(z − z̄)·F, chained, for the part turning with the crank (forward) and the part turning
against it (backward). The three throws at 120° cancel each other's forces but not their
moments: both chains stay open, by √3/2·m_rec·r·ω²·p each (p the cylinder pitch), and the
two equal parts make a couple that rocks the engine in the plane of its cylinders.
"""

import numpy as np

import balance_cli as balance

engine = balance.load("library:today/inline/inline-3")
result = balance.analyse(engine)
first, pitch = result.order(1), engine.throws[1].z_m - engine.throws[0].z_m
expected = np.sqrt(3) / 2 * engine.mean_reciprocating_kg * engine.crank_radius_m
expected *= engine.speed_rad_s**2 * pitch  # N·m; the engine has no rotating mass
np.testing.assert_allclose(
    [abs(first.moment_forward), abs(first.moment_backward)], expected, rtol=1e-9
)  # exact both ways: rounding only

fig = balance.plot.star([result], order=1, of="moment")
