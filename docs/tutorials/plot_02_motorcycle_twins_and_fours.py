"""
Motorcycle twins and fours
==========================

A parallel twin can have its crank pins 360°, 180° or 270° apart, and an in-line four a
flat-plane or a cross-plane crank. Each choice trades one free force or couple for another,
and the firing intervals with them. This tutorial loads the five engines of the library,
reads their free forces and couples order by order, checks each against the textbook's
value worked by hand, and ends with a balancer shaft for the 270° twin and what it leaves.

The engines (``configs/today/inline/`` in a checkout, ``library:today/inline/...`` from
anywhere):

- ``inline-2-360``: Triumph Bonneville 865, both pistons rise together;
- ``inline-2-180``: Kawasaki Ninja 650, the pins 180° apart;
- ``inline-2-270``: Yamaha MT-07 CP2, the pins 90° apart, firing 270°/450°;
- ``inline-4``: Honda K20A, flat-plane crank 0-180-180-0;
- ``inline-4-cross-plane``: Yamaha YZF-R1 (2009), cross-plane crank 0-270-90-180.
"""

import math

from numpy.testing import assert_allclose

import balance_cli as balance

files = {
    "360° twin": "inline-2-360",
    "180° twin": "inline-2-180",
    "270° twin": "inline-2-270",
    "flat four": "inline-4",
    "cross four": "inline-4-cross-plane",
}
engines = {n: balance.load(f"library:today/inline/{file}") for n, file in files.items()}
results = {n: balance.analyse(engine) for n, engine in engines.items()}
for n, engine in engines.items():
    pins = ", ".join(f"{math.degrees(t.phase_rad):g}°" for t in engine.throws)
    print(f"{n:10} pins at {pins}")

# %%
# The firing intervals
# --------------------
#
# A cylinder fires at top dead centre, and in a four-stroke every other time round: a pin at
# β reaches the top at θ = −β, and again at 360° − β. So the 360° twin fires evenly, every
# 360°; the 180° twin at 180° then 540°; the 270° twin at 270° then 450° (a 90° V-twin's
# beat); the flat-plane four every 180°, and the R1's cross-plane four at 270, 180, 90 and
# 180° (Yamaha's figures, firing 1-3-2-4).
intervals = {n: tuple(r.firing.intervals_deg) for n, r in results.items()}
for n, r in results.items():
    order = "-".join(map(str, r.firing.order))
    print(f"{n:10} firing {order:8} intervals {'-'.join(f'{i:g}' for i in intervals[n])}")

by_hand = {
    "360° twin": (360, 360),
    "180° twin": (180, 540),
    "270° twin": (270, 450),
    "flat four": (180, 180, 180, 180),
    "cross four": (270, 180, 90, 180),
}
for n, expected in by_hand.items():
    # the firing angles come from the geometry in floating point: 1e-9° is rounding
    assert_allclose(intervals[n], expected, atol=1e-9)

# %%
# Order by order
# --------------
#
# Each order k of the free force is two phasors, F⁺ turning with the crank (forward) and F⁻
# against it (backward); over a revolution the force traces an ellipse whose largest value is
# the sum of their magnitudes. The same holds for the free couple about the engine's
# mid-length. Below, forces are in units of m·r·ω² (one cylinder's reciprocating mass, crank
# radius and angular speed: one cylinder's largest primary force) and couples in m·r·ω²·d, d
# the cylinder pitch.


def units_of(engine):
    """m·r·ω² (N) and the cylinder pitch d (m) of an in-line engine."""
    m, r, w = engine.mean_reciprocating_kg, engine.crank_radius_m, engine.speed_rad_s
    return m * r * w**2, engine.throws[1].z_m - engine.throws[0].z_m


print(f"{'':10} {'order':>5} {'F fwd':>8} {'F bwd':>8} {'M fwd':>8} {'M bwd':>8}")
for n, r in results.items():
    unit, d = units_of(r.engine)
    for k in (1, 2, 4):
        o = r.order(k)
        row = [
            abs(o.force_forward) / unit,
            abs(o.force_backward) / unit,
            abs(o.moment_forward) / (unit * d),
            abs(o.moment_backward) / (unit * d),
        ]
        print(f"{n:10} {k:5d} " + " ".join(f"{v:8.4f}" for v in row))

# %%
# What the table says, worked by hand
# -----------------------------------
#
# A piston's acceleration is −r·ω²·(cos θ + A₂·cos 2θ − A₄·cos 4θ + …) with λ = r/l,
# A₂ = λ + λ³/4 + 15λ⁵/128 + 35λ⁷/512 + … and A₄ = λ³/4 + 3λ⁵/16 + 35λ⁷/256 + … (the series
# of the exact crank-slider; its first harmonic is exactly cos θ). A force m·r·ω²·cos(θ + β)
# along the cylinder is half forward, half backward: (m·r·ω²/2)·(exp(i(θ+β)) + exp(−i(θ+β))).
# Adding the cylinders' phasors by hand:
#
# - **360° twin**: the two primaries add: forward = backward = m·r·ω², the largest first-order
#   force 2·m·r·ω²; no couple, the pistons move together. The second order adds too:
#   2·m·r·ω²·A₂.
# - **180° twin**: the primary forces cancel, but they act a pitch d apart: a rocking couple
#   m·r·ω²·d at its largest (half of it forward, half backward). The second-order forces
#   (2·180° = 360°) add: 2·m·r·ω²·A₂, and make no couple.
# - **270° twin** (pins 90° apart): the primary forces add as two phasors 90° apart,
#   1 + exp(i90°) of magnitude √2, so the largest force is √2·m·r·ω², split equally:
#   m·r·ω²/√2 forward and m·r·ω²/√2 backward; the couple is (d/2)·m·r·ω² times the magnitude
#   of exp(i90°) − 1, again √2: m·r·ω²·d/√2 at its largest, m·r·ω²·d/(2√2) each way. The
#   second orders are 180° apart: no second-order force, but a couple m·r·ω²·A₂·d.
# - **Flat-plane four**: nothing of the first order; the second orders all in phase:
#   4·m·r·ω²·A₂ along the cylinders, no couple.
# - **Cross-plane four**: Σexp(iβ) = Σexp(2iβ) = 0, no force of orders 1 and 2; the first-order
#   couple goes as Σ(z − z̄)·exp(iβ) = d·(−1.5 + 0.5i + 0.5i − 1.5) = d·(−3 + i), of magnitude
#   √10·d, so √10·m·r·ω²·d at its largest, half forward and half backward; 4β ≡ 0: a
#   fourth-order force 4·m·r·ω²·A₄.
#
# The script checks each of these against the library's numbers (which come from the exact
# motion of every mass and a Fourier transform, not from these series).


def a2(lam):
    """A₂ to λ⁷; the next term, 0.045·λ⁹, is below 5e-6 of A₂ for λ < 0.35."""
    return lam + lam**3 / 4 + 15 * lam**5 / 128 + 35 * lam**7 / 512


def a4(lam):
    """A₄ to λ⁷; the next term, 0.10·λ⁹, is below 1e-4 of A₄ for λ < 0.3."""
    return lam**3 / 4 + 3 * lam**5 / 16 + 35 * lam**7 / 256


root2, root10 = math.sqrt(2), math.sqrt(10)
#: by hand: first-order force forward, backward (× m·r·ω²); first-order couple forward,
#: backward (× m·r·ω²·d); the largest second-order force (× m·r·ω²·A₂) and couple
#: (× m·r·ω²·A₂·d)
hand = {
    "360° twin": (1, 1, 0, 0, 2, 0),
    "180° twin": (0, 0, 1 / 2, 1 / 2, 2, 0),
    "270° twin": (1 / root2, 1 / root2, 1 / (2 * root2), 1 / (2 * root2), 0, 1),
    "flat four": (0, 0, 0, 0, 4, 0),
    "cross four": (0, 0, root10 / 2, root10 / 2, 0, 0),
}
# The first order is exact (rounding only: rtol 1e-12); where A₂ enters, the series stops
# at λ⁷ (rtol 2e-5). A zero by symmetry is below the engine's noise floor (1e-9 of m·r·ω²·n,
# times its half-length for a couple).
EXACT, SERIES = 1e-12, 2e-5
for n, (f1p, f1m, m1p, m1m, f2, m2) in hand.items():
    engine = engines[n]
    unit, d = units_of(engine)
    A2 = a2(engine.crank_radius_m / engine.rod_length_m)
    fl, ml = engine.noise_floor_n, engine.noise_floor_nm
    first, second = results[n].order(1), results[n].order(2)
    assert_allclose(abs(first.force_forward), f1p * unit, rtol=EXACT, atol=fl)
    assert_allclose(abs(first.force_backward), f1m * unit, rtol=EXACT, atol=fl)
    assert_allclose(abs(first.moment_forward), m1p * unit * d, rtol=EXACT, atol=ml)
    assert_allclose(abs(first.moment_backward), m1m * unit * d, rtol=EXACT, atol=ml)
    F2 = abs(second.force_forward) + abs(second.force_backward)
    M2 = abs(second.moment_forward) + abs(second.moment_backward)
    assert_allclose(F2, f2 * unit * A2, rtol=SERIES, atol=fl)
    assert_allclose(M2, m2 * unit * A2 * d, rtol=SERIES, atol=ml)

cross = results["cross four"]
unit, d = units_of(cross.engine)
fourth = cross.order(4)
F4 = abs(fourth.force_forward) + abs(fourth.force_backward)
M1 = abs(cross.order(1).moment_forward) + abs(cross.order(1).moment_backward)
assert_allclose(
    F4, 4 * unit * a4(cross.engine.crank_radius_m / cross.engine.rod_length_m), rtol=3e-4
)  # A₄'s series to λ⁷: 1e-4 of it at the R1's λ = 0.251
print(f"cross four: first-order couple {M1:.1f} N·m (√10·m·r·ω²·d)")
print(f"            fourth-order force {F4:.1f} N (4·m·r·ω²·A₄)")

# %%
# The twins side by side
# ----------------------
#
# :func:`balance_cli.plot.spectrum` draws every order's forward (solid) and backward
# (hatched) part, forces above and free couples below, per cylinder (forces divided by
# m·r·ω²·n). The 360° twin's primary force (0.5 per cylinder each way), the 180° twin's
# primary couple, the 270° twin's primary force and couple, and the second order of each read
# off at a glance; the fourth order is small, and the higher ones far smaller still.
twins = [results[n] for n in ("360° twin", "180° twin", "270° twin")]
spectra = balance.plot.spectrum(twins)

# %%
# What a counterweight leaves
# ---------------------------
#
# Masses on the crank turn with it: they cancel a forward first order, never a backward one.
# :func:`balance_cli.plot.locus` draws the resultant force over a revolution after such an
# ideal counterweight. The 360° twin keeps a circle of m·r·ω² turning backwards (per cylinder
# 0.5, plus its second order riding on it); the 180° twin's force is its second order alone, a
# line along the cylinders; the 270° twin keeps m·r·ω²/√2 turning backwards.
loci = balance.plot.locus(twins)

# %%
# A balancer shaft for the 270° twin
# ----------------------------------
#
# What a counterweight cannot reach, a shaft turning against the crank at crank speed can:
# :func:`balance_cli.counterweights` with ``shaft_orders=(1,)`` sizes the counterweights and
# then, for the first order they leave, a shaft of speed ratio −1 with one mass in each
# correction plane (the end throws), which takes the backward force and the backward couple
# together. From the command line, the same is
# ``balance counterweight library:today/inline/inline-2-270 --shafts 1``.
#
# By hand: each cylinder's backward primary is (m·r·ω²/2)·exp(−iβ); a mass of unbalance m·e on
# a −1 shaft in that cylinder's plane makes m·e·ω² turning backward. So each mass is
# m·e = m·r/2, at 180° − β when θ = 0 (opposite the cylinder's backward phasor): 180° in the
# plane of throw 1 (β = 0°) and 90° in that of throw 2 (β = 90°).
twin = results["270° twin"]
shafted = balance.counterweights(twin, shaft_orders=(1,))
(shaft,) = shafted.balancer_shafts
m, r = twin.engine.mean_reciprocating_kg, twin.engine.crank_radius_m
for weight in shafted.counterweights:
    print(
        f"counterweight in throw {weight.plane.throw}: {weight.mass_kg:.4f} kg at "
        f"{weight.angle_deg:.1f}° from throw 1, radius {weight.radius_m * 1000:g} mm"
    )
print(f"balancer shaft, speed ratio {shaft.speed_ratio:+d}:")
for mass in shaft.masses:
    print(
        f"  m·e = {mass.mass_eccentricity_kgm * 1000:.3f} kg·mm at {mass.phase_deg:.1f}°, "
        f"z = {mass.z_m * 1000:g} mm"
    )

assert shaft.speed_ratio == -1
assert_allclose([x.mass_eccentricity_kgm for x in shaft.masses], m * r / 2, rtol=1e-12)
# angles are compared on the circle: 180° and 90°, to rounding
assert_allclose(
    [math.cos(math.radians(x.phase_deg - a)) for x, a in zip(shaft.masses, (180, 90), strict=True)],
    1.0,
    rtol=1e-12,
)

# %%
# What the shaft leaves
# ---------------------
#
# The first order is gone, force and couple; the second-order couple m·r·ω²·A₂·d and the small
# fourth-order force are untouched (a shaft at crank speed does nothing to them). Shafts at
# twice crank speed as well (``shaft_orders=(1, 2)``) would take the couple too.
left = shafted.after_shafts
unit, d = units_of(twin.engine)
lam = twin.engine.crank_radius_m / twin.engine.rod_length_m
first, second = left.order(1), left.order(2)
f1 = abs(first.force_forward) + abs(first.force_backward)
m1 = abs(first.moment_forward) + abs(first.moment_backward)
m2 = abs(second.moment_forward) + abs(second.moment_backward)
print(f"left: first order {f1:.3g} N, {m1:.3g} N·m; second-order couple {m2:.1f} N·m")
print(f"largest free couple, counterweighted: {twin.counterweighted_moment_nm:.1f} N·m")
print(f"                    with the shaft too: {left.largest_moment():.1f} N·m")
# what cancels leaves rounding only, below the engine's noise floors
assert f1 < twin.engine.noise_floor_n and m1 < twin.engine.noise_floor_nm
assert_allclose(m2, unit * a2(lam) * d, rtol=SERIES)

# %%
# The cross-plane four takes the same shaft. Its primary couple, √10/2·m·r·ω²·d each way, is
# all it has of the first order; the counterweights take the forward half and a −1 shaft with
# masses in the end planes, L = 3d apart, the backward half: m·e·ω²·3d = √10/2·m·r·ω²·d, so
# m·e = (√10/6)·m·r on each. (The R1 has such a shaft; the library's file leaves it out.) What
# is left is the fourth-order force alone, 4·m·r·ω²·A₄: no couple at all.
r1 = balance.counterweights(cross, shaft_orders=(1,))
(r1_shaft,) = r1.balancer_shafts
m, r = cross.engine.mean_reciprocating_kg, cross.engine.crank_radius_m
print(
    f"R1: shaft {r1_shaft.speed_ratio:+d}, m·e "
    + " and ".join(f"{x.mass_eccentricity_kgm * 1000:.3f}" for x in r1_shaft.masses)
    + " kg·mm"
)
print(
    f"left: couple {r1.after_shafts.largest_moment():.1f} N·m, "
    f"force {r1.after_shafts.largest_force():.1f} N"
)
assert r1_shaft.speed_ratio == -1
assert_allclose([x.mass_eccentricity_kgm for x in r1_shaft.masses], root10 / 6 * m * r, rtol=EXACT)
assert r1.after_shafts.largest_moment() < cross.engine.noise_floor_nm
# the fourth order is nearly all that is left: the eighth, 3e-4 of it, rides on it
assert_allclose(r1.after_shafts.largest_force(), F4, rtol=1e-3)

# %%
# The shaft as built
# ------------------
#
# To see the engine with its shaft, put the shaft in the engine:
# :class:`balance_cli.BalancerShaftSpec` (a speed ratio and its masses) of
# :class:`balance_cli.BalancerMass` (m·e, angle, z). A built mass's angle is measured in the
# shaft's own sense of turning, so a −1 shaft's 90° with the crank's rotation is −90° there.
# (``balance counterweight FILE --shafts 1 --write balanced.toml`` writes the same into a
# configuration.) Analysed again, the engine has no first order left for a counterweight to
# leave behind.
built = twin.engine.replace(
    name="270° twin with its balancer shaft",
    balancer_shafts=[
        balance.BalancerShaftSpec(
            -1,
            [
                balance.BalancerMass(x.mass_eccentricity_kgm, -math.radians(x.phase_deg), x.z_m)
                for x in shaft.masses
            ],
        )
    ],
)
with_shaft = balance.analyse(built)
first = with_shaft.order(1)
print(
    f"backward first order with the shaft: {abs(first.force_backward):.3g} N, "
    f"{abs(first.moment_backward):.3g} N·m"
)
assert abs(first.force_backward) < built.noise_floor_n
assert abs(first.moment_backward) < built.noise_floor_nm

# %%
# The free couple over a revolution, after an ideal counterweight, without the shaft and with
# it: the circle of the backward first-order couple goes, and the second order's line (a
# rocking couple in the cylinders' plane, twice a revolution) is what is left.
fig = balance.plot.locus([twin, with_shaft], of="moment")
