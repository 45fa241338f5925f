"""
Car V6s
=======

Three ways of building a V6, three different engines to mount: Buick's 90° V6 of the
1970s (a V8 with two cylinders cut off: three common crank pins, odd firing), its 3800
successor (the same 90° block with each pin split by 30°, firing evenly) and Nissan's VQ35DE
(a 60° V with each pin split by 60°). This tutorial compares their free forces and couples
order by order, checks them against the textbook's phasor sums, asks what counterweights
leave and where a balancer shaft helps, and writes the result as a Markdown table for a
design note.

The engines (``configs/today/v/`` in a checkout, ``library:today/v/...`` from anywhere):

- ``v6-90-odd-fire``: Buick 231, banks at ±45°, pins 0, 240 and 120°, firing 1-6-5-4-3-2;
- ``v6-90-split-pin``: Buick 3800 Series II, the same banks, pin pairs split by 30°;
- ``v6-60-split-pin``: Nissan VQ35DE, banks at ±30°, pin pairs split by 60°, firing
  1-2-3-4-5-6.
"""

import math

import numpy as np
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.report.table import intervals, render

files = {
    "231": "library:today/v/v6-90-odd-fire",
    "3800": "library:today/v/v6-90-split-pin",
    "VQ35DE": "library:today/v/v6-60-split-pin",
}
results = {key: balance.analyse(balance.load(path)) for key, path in files.items()}
for key, r in results.items():
    pins = ", ".join(f"{math.degrees(t.phase_rad):g}" for t in r.engine.throws)
    print(f"{key:7} {r.engine.name}\n{'':7} pins at {pins}°")

# %%
# The firing intervals
# --------------------
#
# A cylinder in a bank at γ on a pin at β is at top dead centre when θ = γ − β. On the 231's
# common pins the two cylinders of a pin fire 90° apart (the bank angle), and the three pins'
# pairs 720°/3 = 240° apart, so the intervals alternate 90° and 240° − 90° = 150°: the
# odd-fire V6's uneven beat. Splitting each pin by 30° moves one bank's firings 30°:
# 90° + 30° = 150° − 30° = 120°, every interval alike. On the 60° VQ unsplit pins would give
# 60° and 180°; a 60° split makes them 120° too.
for key, r in results.items():
    print(
        f"{key:7} firing {'-'.join(map(str, r.firing.order))}, intervals "
        f"{'-'.join(f'{i:g}' for i in r.firing.intervals_deg)}"
    )

# the firing angles come from the geometry in floating point: 1e-9° is rounding
assert_allclose(results["231"].firing.intervals_deg, [150, 90] * 3, atol=1e-9)
for key in ("3800", "VQ35DE"):
    assert_allclose(results[key].firing.intervals_deg, [120] * 6, atol=1e-9)

# %%
# Free forces and couples, order by order
# ---------------------------------------
#
# Forces in newtons, couples (free moments about the engine's mid-length) in N·m, each split
# into the part turning with the crank (forward) and the part turning against it (backward).
print(f"{'':7} {'order':>5} {'F fwd':>9} {'F bwd':>9} {'M fwd':>9} {'M bwd':>9}")
for key, r in results.items():
    for k in (1, 2, 4, 6):
        o = r.order(k)
        parts = (o.force_forward, o.force_backward, o.moment_forward, o.moment_backward)
        print(f"{key:7} {k:5d} " + " ".join(f"{abs(v):9.2f}" for v in parts))

# %%
# Worked by hand
# --------------
#
# A cylinder at γ on a pin at β shakes its engine with m·r·ω²·cos(θ + β − γ) along exp(iγ) in
# the first order and m·r·ω²·A₂·cos 2(θ + β − γ) in the second (λ = r/l,
# A₂ = λ + λ³/4 + 15λ⁵/128 + 35λ⁷/512 + …). Written as phasors:
#
# - first order: forward (m·r·ω²/2)·exp(iβ), backward (m·r·ω²/2)·exp(i(2γ − β));
# - second order: forward (m·r·ω²·A₂/2)·exp(i(2β − γ)), backward (m·r·ω²·A₂/2)·exp(i(3γ − 2β)).
#
# In each bank of each engine the three pins are 120° apart, so every one of these sums
# vanishes bank by bank: **no free force of orders 1 and 2** (nor 4). The couples are the same
# sums weighted by z − z̄; each bank's three cylinders sit at −d, 0 and +d about its middle
# (d the bore spacing), so the banks' stagger drops out, and what is left, bank against bank,
# is:
#
# ======  ============================  ============================
# engine  first-order couple            second-order couple
# ======  ============================  ============================
# 231     √3·m·r·ω²·d forward           √6·m·r·ω²·A₂·d on a line
# 3800    √3·cos 15°·m·r·ω²·d forward   √3·sin 15°·m·r·ω²·A₂·d forward
#         √3·sin 15°·m·r·ω²·d backward  √3·cos 15°·m·r·ω²·A₂·d backward
# VQ35DE  1.5·m·r·ω²·d forward          1.5·m·r·ω²·A₂·d backward
# ======  ============================  ============================
#
# (the 231's second order is √6/2 forward and √6/2 backward: a rocking couple of the
# horizontal forces, a yawing couple). The script checks each against the library, which
# takes neither series nor phasors: it moves every mass exactly and Fourier-transforms.


def a2(lam):
    """A₂ to λ⁷; the next term, 0.045·λ⁹, is below 5e-6 of A₂ for λ < 0.35."""
    return lam + lam**3 / 4 + 15 * lam**5 / 128 + 35 * lam**7 / 512


root3, c15, s15 = math.sqrt(3), math.cos(math.radians(15)), math.sin(math.radians(15))
#: hand values of (M1 fwd, M1 bwd, M2 fwd, M2 bwd) in units of m·r·ω²·d; the second order
#: times A₂
hand = {
    "231": (root3, 0.0, math.sqrt(6) / 2, math.sqrt(6) / 2),
    "3800": (root3 * c15, root3 * s15, root3 * s15, root3 * c15),
    "VQ35DE": (1.5, 0.0, 0.0, 1.5),
}
for key, r in results.items():
    e = r.engine
    unit = e.mean_reciprocating_kg * e.crank_radius_m * e.speed_rad_s**2  # m·r·ω², N
    d = e.cylinder(3).z_m - e.cylinder(1).z_m  # the bore spacing: 1 and 3 are in bank 1
    A2 = a2(e.crank_radius_m / e.rod_length_m)
    first, second = r.order(1), r.order(2)
    forces = [first.force_forward, first.force_backward, second.force_forward]
    # zero by symmetry: below the engine's noise floor, 1e-9 of m·r·ω²·n
    assert_allclose(np.abs(forces + [second.force_backward]), 0.0, atol=e.noise_floor_n)
    m1p, m1m, m2p, m2m = hand[key]
    # the first order is exact (a piston's first harmonic is r·ω²·cos θ, no series): rounding
    # only; the second carries A₂'s truncated series (5e-6, rtol 2e-5); a zero is rounding,
    # below the noise floor times the engine's half-length
    floor = e.noise_floor_nm
    assert_allclose(abs(first.moment_forward), m1p * unit * d, rtol=1e-12, atol=floor)
    assert_allclose(abs(first.moment_backward), m1m * unit * d, rtol=1e-12, atol=floor)
    assert_allclose(abs(second.moment_forward), m2p * unit * d * A2, rtol=2e-5, atol=floor)
    assert_allclose(abs(second.moment_backward), m2m * unit * d * A2, rtol=2e-5, atol=floor)
    print(f"{key:7} m·r·ω² = {unit:.1f} N, d = {d * 1000:g} mm, A₂ = {A2:.5f}")

# %%
# The firing, drawn
# -----------------
#
# :func:`balance_cli.plot.firing` puts each engine's firing on a dial of its cycle (720°):
# the 231's pairs bunched 90° apart, the two even-firing engines every 120°.
dial = balance.plot.firing(list(results.values()))

# %%
# What counterweights leave
# -------------------------
#
# Counterweights on the crank turn with it: in two planes (the end throws, by default) they
# cancel the forward first-order force and couple, and nothing else.
# :func:`balance_cli.counterweights` sizes them (``balance counterweight FILE`` on the command
# line). The 231's primary couple is all forward, and so is the VQ's: their counterweights
# take the whole first order. The 3800's split pins leave a backward first-order couple,
# √3·sin 15°·m·r·ω²·d, turning against the crank, that no counterweight can touch.
weighted = {key: balance.counterweights(r) for key, r in results.items()}
for key, b in weighted.items():
    masses = "; ".join(
        f"{w.mass_kg:.3f} kg at {w.angle_deg:.0f}° (throw {w.plane.throw})"
        for w in b.counterweights
    )
    left = b.residual.order(1)
    print(f"{key:7} counterweights {masses}")
    print(
        f"{'':7} first-order couple left: {abs(left.moment_forward):.1f} forward, "
        f"{abs(left.moment_backward):.1f} backward N·m"
    )

for key, b in weighted.items():
    left = b.residual.order(1)
    # the forward part is cancelled to rounding (below the engine's noise floor, 1e-9 of
    # m·r·ω²·n times its half-length); the backward one is untouched (exactly)
    assert abs(left.moment_forward) < results[key].engine.noise_floor_nm
    assert_allclose(
        abs(left.moment_backward), abs(results[key].order(1).moment_backward), rtol=1e-12
    )

# %%
# A balancer shaft where it helps
# -------------------------------
#
# What the counterweights leave, a shaft can take: ``shaft_orders`` asks for balancer shafts
# for those orders, at k× crank speed, turning with the crank for a forward part and against
# it for a backward one, each with a mass in each correction plane.
#
# - The **3800** needs one shaft at crank speed turning against the crank (−1) for its
#   backward primary couple (the production engine carries a balance shaft). By
#   hand, its two masses, L = 240.4 mm apart, make m·e·ω²·L = √3·sin 15°·m·r·ω²·d, so
#   m·e = √3·sin 15°·m·r·d/L.
# - The **VQ35DE**'s second-order couple turns backward alone: one −2 shaft cancels it.
# - The **231**'s second-order couple lies on a line, half forward and half backward: it
#   takes a pair, +2 and −2.
choices = {"231": (2,), "3800": (1,), "VQ35DE": (2,)}
shafted = {key: balance.counterweights(r, shaft_orders=choices[key]) for key, r in results.items()}
for key, b in shafted.items():
    for shaft in b.balancer_shafts:
        print(f"{key:7} shaft {shaft.speed_ratio:+d}:")
        for m in shaft.masses:
            print(
                f"{'':9} m·e {m.mass_eccentricity_kgm * 1000:.3f} kg·mm at "
                f"{m.phase_deg:.0f}°, z {m.z_m * 1000:g} mm"
            )

ratios = {key: [s.speed_ratio for s in b.balancer_shafts] for key, b in shafted.items()}
assert ratios == {"231": [2, -2], "3800": [-1], "VQ35DE": [-2]}
e = results["3800"].engine
L = e.throws[-1].z_m - e.throws[0].z_m
d = e.cylinder(3).z_m - e.cylinder(1).z_m
me = root3 * s15 * e.mean_reciprocating_kg * e.crank_radius_m * d / L
# sized from the exact first order: rounding only
assert_allclose(
    [m.mass_eccentricity_kgm for m in shafted["3800"].balancer_shafts[0].masses], me, rtol=1e-12
)
for key, b in shafted.items():
    for k in choices[key]:
        o = b.after_shafts.order(k)
        # what the shafts cancel is gone, to rounding (below the engine's noise floor)
        assert abs(o.moment_forward) + abs(o.moment_backward) < results[key].engine.noise_floor_nm

# %%
# A table for the design note
# ---------------------------
#
# Everything above in one Markdown table, to copy into the note as it is: built from the
# records the commands write as JSON (:meth:`balance_cli.EngineResult.to_dict`) and from the
# :class:`balance_cli.Balance` results, and rendered as the commands render ``--format
# markdown`` (``balance_cli.report.table``). What is left is the largest free couple (and
# force) over a revolution, all orders together. (For the whole comparison, order by order:
# ``balance compare configs/today/v/v6-*.toml --format markdown``.)
rows = []
for key, r in results.items():
    record = r.to_dict()
    first, second = record["orders"][0]["moment"], record["orders"][1]["moment"]
    rows.append(
        [
            record["name"],
            intervals(record["firing"]),
            f"{first['forward_Nm']:.0f}/{first['backward_Nm']:.0f}",
            f"{second['forward_Nm']:.0f}/{second['backward_Nm']:.0f}",
            f"{weighted[key].residual.largest_moment():.0f}",
            " ".join(f"{s.speed_ratio:+d}" for s in shafted[key].balancer_shafts),
            f"{shafted[key].after_shafts.largest_moment():.3g}",
            f"{shafted[key].after_shafts.largest_force():.3g}",
        ]
    )
headers = [
    "Engine",
    "Intervals (°)",
    "M1 fwd/bwd (N·m)",
    "M2 fwd/bwd (N·m)",
    "Counterweights leave (N·m)",
    "Shafts",
    "Shafts leave (N·m)",
    "Force left (N)",
]
note = render(headers, rows, "markdown")
print(note)

# %%
# No V6 here has a free force of orders 1 or 2: what shakes them is couples. The
# counterweights leave the 231 its yawing second order, the 3800 its backward primary with
# its second order, and the VQ its second order turning backward at twice crank speed. The
# shafts chosen above leave the 231 and the VQ a fourth-order couple of a few N·m; the 3800's
# one shaft leaves it its second order (``shaft_orders=(1, 2)`` would add a +2 and a −2
# shaft for that). Every force left is a sixth-order one of a few newtons.


def main_order(shaking, part):
    """The order whose ellipse is largest: of the forces (part "force") or couples."""
    sizes = {
        o.order: abs(getattr(o, f"{part}_forward")) + abs(getattr(o, f"{part}_backward"))
        for o in shaking.orders
    }
    return max(sizes, key=sizes.get)


assert {key: main_order(b.after_shafts, "moment") for key, b in shafted.items()} == {
    "231": 4,
    "3800": 2,
    "VQ35DE": 4,
}
assert all(main_order(b.after_shafts, "force") == 6 for b in shafted.values())
# the 231's second order is a couple of the horizontal forces (of its banks' second orders,
# which add across the V), the VQ's a circle turning backward
assert results["231"].main_order("moment")["direction"] == "yawing"
assert results["VQ35DE"].main_order("moment")["direction"] == "rotating backward"
# a shaft at crank speed does nothing to the second order: the same phasors, to rounding
kept, had = shafted["3800"].after_shafts.order(2), weighted["3800"].residual.order(2)
assert_allclose(
    [kept.moment_forward, kept.moment_backward],
    [had.moment_forward, had.moment_backward],
    rtol=1e-12,
)

# %%
# The free couple over a revolution after the counterweights, as
# :func:`balance_cli.plot.locus` draws it with ``of="moment"``: the 231's line (yawing), the
# 3800's loop (a backward circle of the first order with the second order's ellipse riding on
# it) and the VQ's circle.
fig = balance.plot.locus(list(results.values()), of="moment")
