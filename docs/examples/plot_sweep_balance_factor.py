"""
A V-twin's balance factor
=========================

A 45° V-twin's crank counterweight cannot cancel its first-order force: whatever share of the
reciprocating mass it balances (the balance factor, 0 to 1) moves the force from the
vertical into the horizontal. The sweep shows the trade; designers choose a factor where the
frame takes it best.
"""

import balance_cli as balance

factors = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]
result = balance.sweep(
    "library:today/v/v-twin-45", "balance_factor", factors, quantities=["F1V", "F1H"]
)

fig = balance.plot.sweep_figure(result)
