"""
When twins fire
===============

The firing diagrams of four twins over one working cycle (720° of crank): the 360° in-line
twin fires evenly, every 360°; the 180° twin at 180° then 540°; the 270° in-line twin and the
90° V-twin, at 270° then 450°, share the same uneven beat.
"""

import balance_cli as balance

names = ["inline/inline-2-360", "inline/inline-2-180", "inline/inline-2-270", "v/v-twin-90"]
results = [balance.analyse(balance.load(f"library:today/{name}")) for name in names]
intervals = [tuple(round(i, 6) for i in r.firing.intervals_deg) for r in results]
assert intervals == [(360, 360), (180, 540), (270, 450), (270, 450)]

fig = balance.plot.firing(results)
