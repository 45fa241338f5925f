"""
A truck diesel's torque
=======================

The torque of a six-cylinder truck diesel at constant speed over one cycle: the inertia
torque of its moving parts, the gas torque of its pressure cycle and their sum, with the
amplitude of each order of the total. A six-cylinder four-stroke fires every 120°, so its
torque repeats every 120° of crank: only the orders 3, 6, … are left.
"""

import balance_cli as balance

torque = balance.torque(balance.load("library:today/inline/inline-6-truck-diesel"))
amplitude = {k: abs(complex(c, s)) for k, c, s in torque.total.orders}
others = [a for k, a in amplitude.items() if k % 3]
assert max(others) < 1e-4 * amplitude[3]  # nothing but rounding outside 3, 6, ...

fig = balance.plot.torque([torque])
