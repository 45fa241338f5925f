"""
The classic papers
==================

balance grew out of two reports of the Aeronautical Research Institute, Tokyo: K. Tanaka,
*The Inertia Forces and Couples and their Balancing of the Star Type Engine* (Report No. 10,
1925), and F. Nakanishi, *On the Balancing of Two-Stroke 12-Cylinder Engines* (Report No. 86,
1932). They worked by hand, with power series in the crank ratios (q = r/l of the master rod,
s = a/l' and p = r/l' of the link rods) cut after a few terms. balance computes the exact motion
of every mass over a revolution and takes its Fourier series, so the papers' figures become
checks of it, and where the two disagree the paper can be traced to a slip.

Every figure balance can compute from these papers is a record in the test suite
(``tests/validation/reference/tanaka1925.toml`` and ``nakanishi1932.toml``): the printed
value, where it is printed, a tolerance and the reason for that tolerance. :doc:`/validation`
lists them all beside balance's values, with the errata. This tutorial reproduces a few of
them from the engines shipped with balance, asserts each within its recorded tolerance, and
follows two errata to their cause.
"""

import numpy as np

import balance_cli as balance

# %%
# The figures used below, each by the id of its record: (printed, tolerance) or, for an
# erratum, (printed, tolerance, corrected). The test suite checks that they are the records'
# own.
FIGURES = {
    "T-III-1a-X-cos2": (-0.215, 0.0005),
    "T-III-pct-W12": (71, 1.0),
    "T-III-pct-W12-links": (56, 1.0),
    "T-III-pct-radial": (31, 1.0),
    "T-III-pct-rotary": (16, 1.0),
    "T-III-2a-X-sin2": (-0.152, 0.0005),
    "T-III-2a-Y-cos2": (0.051, 0.0005),
    "T-III-62-Y-formula": (0.151693, 0.0001, 0.050564),
    "T-III-5a-X-cos2": (0.067, 0.0065),
    "T-II-first": (73.1, 0.2),
    "T-II-third": (-2.0, 0.1, -0.4),
    "N-V12-interval-max": (30, 1e-6),
    "N-V12-interval-min": (30, 1e-6),
    "N-V12-sixth": (12.4762, 0.13),
    "N-V12-couple": (14514.503, 0.01),
    "N-W12-fourth-X": (371.286, 0.75),
    "N-W12-fourth-Y": (123.762, 0.25),
    "N-W12-couple": (18210.245, 0.01),
    "N-W12-couple-direction": (0.3333333333, 1e-9),
}
#: balance's value of each figure, as computed below
OURS: dict = {}

# %%
# Two helpers set a figure beside balance's value and check it. balance's values here are
# sizes (amplitudes, percentages, newtons): they are set against the size of the printed
# figure, whose sign depends on the paper's axes and the direction of its θ (the validation
# page compares signs too).


def beside(figure, ours):
    """Print a paper's figure beside balance's value; they must agree within the record's
    tolerance."""
    printed, tolerance = FIGURES[figure][:2]
    OURS[figure] = ours
    print(f"{figure:<22} paper {printed!s:>12}  balance {ours:<12.9g} ± {tolerance:g}")
    assert abs(ours - abs(printed)) <= tolerance, (figure, ours, printed)


def erratum(figure, ours):
    """The same for a figure the paper got wrong: balance disagrees with what is printed and
    agrees, within the same tolerance, with the corrected value."""
    printed, tolerance, corrected = FIGURES[figure]
    OURS[figure] = ours
    print(f"{figure:<22} paper {printed!s:>12}  balance {ours:<12.9g} ± {tolerance:g}")
    print(f"{'':<22} corrected {corrected}")
    assert abs(ours - abs(printed)) > tolerance, (figure, ours, printed)
    assert abs(ours - abs(corrected)) <= tolerance, (figure, ours, corrected)


# %%
# And one reads an order's force along and across the reference axis, whatever the origin
# and direction of the paper's θ.


def along_across(result, k):
    """Amplitudes of order ``k``'s force along and across the reference axis, per cylinder.

    The force is F⁺·e^{ikθ} + F⁻·e^{−ikθ} (real part along the axis): its along part is
    Re[(F⁺ + conj F⁻)·e^{ikθ}] and its across part Im[(F⁺ − conj F⁻)·e^{ikθ}], so their
    amplitudes are |F⁺ + conj F⁻| and |F⁺ − conj F⁻|, wherever θ is counted from."""
    order = result.order(k)
    forward, backward = order.force_forward, np.conj(order.force_backward)
    unit = result.per_cylinder_unit_n
    return abs(forward + backward) / unit, abs(forward - backward) / unit


# %%
# Part III: nine aero engines side by side
# ----------------------------------------
#
# Tanaka's Part III sets the layouts of his day side by side: a 90° V8 with a flat crank, a
# 60° W12, an in-line 6, a 60° V12 (the V8, the W12 and the V12 also with link rods), the
# nine-cylinder radial with master and link rods and the same nine cylinders as a
# rotary (the Clerget's). Every one has the Clerget's proportions (q = .297, s = .217,
# p = .361) and only reciprocating masses, so the figures compare layouts, not sizes. He
# compares what each shakes its mounts with once a crank counterweight has cancelled the
# first order that turns with the crank (a rotary's crank stands still: nothing is cancelled
# there), per cylinder, in units of m_rec·r·ω².
#
# The library holds the nine as ``library:tanaka-part3``:
part3 = [balance.analyse(engine) for engine in balance.load_many(["library:tanaka-part3"])]
v8, v8_links, w12, w12_links, inline_6, v12, v12_links, radial, rotary = part3

print(f"{'engine':<42}{'per cylinder':>14}{'% of the V8':>13}")
for result in part3:
    percent = result.percent_of(v8)
    print(f"{result.engine.name:<42}{result.counterweighted_per_cylinder:>14.4f}{percent:>13.1f}")

# %%
# In the text after his Fig. 9 he ranks them against the V8: the W12 71 %, the W12 with link
# rods 56 %, the radial 31 %, the rotary 16 %. The in-line 6 and the V12s leave only a trace
# of the sixth order, below .0005 per cylinder, which his three decimals print as .000. The
# V8's own figure is its horizontal secondary, −.215 cos 2θ per cylinder in his table: the
# amplitude of its second order across the reference axis (the bisector of its banks).
beside("T-III-pct-W12", w12.percent_of(v8))
beside("T-III-pct-W12-links", w12_links.percent_of(v8))
beside("T-III-pct-radial", radial.percent_of(v8))
beside("T-III-pct-rotary", rotary.percent_of(v8))
beside("T-III-1a-X-cos2", along_across(v8, 2)[1])
assert max(e.counterweighted_per_cylinder for e in (inline_6, v12, v12_links)) < 0.0005

# %%
# His Fig. 9 draws the loci of these forces over a revolution: where the tip of the force
# arrow goes. The V8's is nearly a line across (its secondary shakes it sideways), the W12's an
# ellipse, the radial's a circle, the rotary's a short line.
fig = balance.plot.locus(part3)

# %%
# The W12 and a slip in expression (62)
# -------------------------------------
#
# For the 60° W12 his table prints −.152 sin 2θ horizontally and +.051 cos 2θ vertically,
# and balance agrees. Yet his expression (62), from which the table should follow, writes
# the vertical secondary as ΣY = 12·½·q(1 + ¼q²) cos 2θ: per cylinder ½q(1 + ¼q²) = .15169,
# equal to the horizontal one. That is erratum T1 of the validation page.
vertical, horizontal = along_across(w12, 2)
beside("T-III-2a-X-sin2", horizontal)
beside("T-III-2a-Y-cos2", vertical)
erratum("T-III-62-Y-formula", vertical)

# %%
# Where does the factor go wrong? A cylinder at bank angle γ whose throw is at θ pushes along
# its own axis with a secondary A₂·m·r·ω²·cos 2(θ − γ), A₂ ≈ q + ¼q³. On the flat crank
# (throws at 0, 180, 180, 0°) the four cylinders of a bank add; the three banks at −60, 0 and
# 60° then give, along the middle bank, 4A₂·(cos 2θ − ½ cos 2θ) = 2A₂ cos 2θ, and across it
# 4A₂·(3/2) sin 2θ = 6A₂ sin 2θ. Per cylinder that is A₂/6 along and A₂/2 across: the
# vertical secondary is one third of the horizontal, as his table says, not equal to it as
# (62) says (½ written where ⅙ belongs).
#
# A₂ itself needs no series: it is the second harmonic of the exact piston acceleration,
# which numpy's FFT gives from the piston's position r·cos θ + √(l² − r²·sin² θ) (this is
# not balance's code: a check of it).
w12_engine = w12.engine
crank, rod = w12_engine.crank_radius_m, w12_engine.rod_length_m
theta = np.linspace(0.0, 2.0 * np.pi, 256, endpoint=False)
position = crank * np.cos(theta) + np.sqrt(rod**2 - (crank * np.sin(theta)) ** 2)
# the acceleration's order k is −k²·ω² times the position's: its size per r·ω² is 4·|c₂|/r
a2 = 4.0 * abs(np.fft.rfft(position)[2] * 2.0 / theta.size) / crank
print(f"A2 = {a2:.6f}: along A2/6 = {a2 / 6:.6f}, across A2/2 = {a2 / 2:.6f}")
# both exact: they differ by rounding only
np.testing.assert_allclose([vertical, horizontal], [a2 / 6, a2 / 2], rtol=1e-9)

# %%
# The radial with link rods and the rotary (Parts I and II)
# ---------------------------------------------------------
#
# A radial's nine cylinders on one crank pin shake it with a first order of 9/2·m·r·ω²
# turning with the crank (½ per cylinder), which a counterweight cancels. With plain rods
# the second order would cancel between the cylinders; the link rods, pinned to the master
# rod off the crank pin, leave one: .067 per cylinder in Tanaka's table, turning with the
# crank (forward), so that only a mass turning at twice the crank's speed could cancel it.
first, second = radial.order(1), radial.order(2)
unit = radial.per_cylinder_unit_n
print(f"first order per cylinder: forward {abs(first.force_forward) / unit:.4f}")
print(
    f"second order per cylinder: forward {abs(second.force_forward) / unit:.5f}, "
    f"backward {abs(second.force_backward) / unit:.5f}"
)
# the first order's closed form n/2·m·r·ω², to rounding
np.testing.assert_allclose(abs(first.force_forward) / unit, 0.5, rtol=1e-9)
assert abs(second.force_backward) < 1e-3 * abs(second.force_forward)
beside("T-III-5a-X-cos2", along_across(radial, 2)[0])

# %%
# In the rotary the crank stands still and the crankcase with its cylinders turns. Part II
# works the Clerget 130 HP out in kilograms-force: its expression (41) gives
# Σy = [73.1 + …] sin θ kg across the crank, and, as printed, − [2 + …] sin 3θ kg for the
# third order. ``library:tanaka-part3/5b-rotary-9`` is the Clerget with its reciprocating
# masses alone (W = 1 714 g, r = 80 mm, 1 250 rpm), which is what (41) counts. The first
# order agrees. The third is erratum T3: the exact value is 0.42 kg. Tanaka's own Part III
# table says so too: it prints .000 per cylinder for the rotary's third order, and 0.42 kg
# is .0002 per cylinder of m_rec·r·ω²·n (2 156 kg here), where 2 kg would print as .001.
g = 9.80665  # N per kgf
unit_kgf = rotary.per_cylinder_unit_n / g
beside("T-II-first", along_across(rotary, 1)[1] * unit_kgf)
erratum("T-II-third", along_across(rotary, 3)[1] * unit_kgf)
print(f"m_rec·r·ω²·n = {unit_kgf:.0f} kg; the third order per cylinder:")
print(f"exact {along_across(rotary, 3)[1]:.4f}, 2 kg {2.0 / unit_kgf:.4f}")
assert along_across(rotary, 3)[1] < 0.0005 < 2.0 / unit_kgf

# %%
# Nakanishi's two-stroke twelves (1932)
# -------------------------------------
#
# Nakanishi chose crankshafts for a two-stroke 90° V12 (throws 0, 120, 240, 60, 300,
# 180°) and a 60° W12 so that they fire every 30°. His paper gives formulas, not numbers:
# the library's two engines carry illustrative data (λ = l/r = 3.5, r = 80 mm, 2 000 rpm, a
# piston of m_p = 2.0 kg, a rod of m_c = 2.4 kg counted a = .65 at its big end and b = .35 at
# its small end, a crank unbalance of m_k = 2.0 kg, d = 150 mm between the cylinders), and
# his formulas are evaluated here with the same data.
v12 = balance.analyse(balance.load("library:nakanishi-v12-90-2stroke"))
w12_2s = balance.analyse(balance.load("library:nakanishi-w12-60-2stroke"))
lam, r, omega, d = 3.5, 0.080, 2000 * 2 * np.pi / 60, 0.150
m_p, m_c, a, b, m_k = 2.0, 2.4, 0.65, 0.35, 2.0
beside("N-V12-interval-max", max(v12.firing.intervals_deg))
beside("N-V12-interval-min", min(v12.firing.intervals_deg))


def orders_left(result):
    """The orders (to the 8th) whose force, and those whose free moment, stand above the
    engine's noise floor (1e-9 of m_rec·r·ω²·n): the rest cancel exactly."""
    engine, orders = result.engine, [result.order(k) for k in range(1, result.max_order + 1)]
    forces = [
        o.order
        for o in orders
        if abs(o.force_forward) + abs(o.force_backward) > engine.noise_floor_n
    ]
    moments = [
        o.order
        for o in orders
        if abs(o.moment_forward) + abs(o.moment_backward) > engine.noise_floor_nm
    ]
    print(f"{engine.name}: force in orders {forces}, free moment in orders {moments}")
    return forces, moments


assert orders_left(v12) == ([6], [1])
assert orders_left(w12_2s) == ([4, 8], [1])

# %%
# The V12 (his § 3, eq. (1)) keeps no force but the sixth order (to the eighth),
# ΣX = 6√2·A₆·(m_p + b·m_c)·ω²r with A₆ = 9/128·λ⁻⁵ + 45/512·λ⁻⁷; its series stops at λ⁻⁷,
# about 1 % short. Its first-order couple (eq. (2)) is M = 2√3·d·{m_p + (2a + b)·m_c + m_k}·ω²r.
a6 = 9 / 128 * lam**-5 + 45 / 512 * lam**-7
sixth = 6 * np.sqrt(2) * a6 * (m_p + b * m_c) * omega**2 * r
couple = 2 * np.sqrt(3) * d * (m_p + (2 * a + b) * m_c + m_k) * omega**2 * r
print(f"eq. (1): {sixth:.4f} N   eq. (2): {couple:.3f} N·m")
np.testing.assert_allclose([sixth, couple], [12.4762, 14514.503], atol=5e-4)  # as recorded
order_6 = v12.order(6)
beside("N-V12-sixth", abs(order_6.force_forward) + abs(order_6.force_backward))
beside("N-V12-couple", abs(v12.order(1).moment_forward))

# %%
# The W12 (§ 6, eq. (3)) keeps a fourth order (and, far smaller, its eighth):
# 6·A₄·(m_p + b·m_c)·ω²r across and a third of it along, A₄ = −¼λ⁻³ − 3/16·λ⁻⁵ − 35/256·λ⁻⁷,
# an ellipse with the largest and smallest semi-axes below. Its couple (eq. (5)),
# M = √10·d·{3/2·m_p + 3(a + b/2)·m_c + m_k}·ω²r, turns with the crank; its direction is
# φ = tan⁻¹(−1/3): its two components are as one to three (the sign depends on his axes).
a4 = -(1 / 4 * lam**-3 + 3 / 16 * lam**-5 + 35 / 256 * lam**-7)
fourth = abs(6 * a4 * (m_p + b * m_c) * omega**2 * r)
couple = np.sqrt(10) * d * (3 / 2 * m_p + 3 * (a + b / 2) * m_c + m_k) * omega**2 * r
print(f"eq. (3): {fourth:.3f} and {fourth / 3:.3f} N   eq. (5): {couple:.3f} N·m")
np.testing.assert_allclose([fourth, couple], [371.286, 18210.245], atol=5e-4)  # as recorded
order_4, moment = w12_2s.order(4), w12_2s.order(1).moment_forward
beside("N-W12-fourth-X", abs(order_4.force_forward) + abs(order_4.force_backward))
beside("N-W12-fourth-Y", abs(abs(order_4.force_forward) - abs(order_4.force_backward)))
beside("N-W12-couple", abs(moment))
beside("N-W12-couple-direction", abs(moment.imag / moment.real))

# %%
# The spectrum shows it all at once: each twelve leaves one order of force (the V12 the
# sixth, the W12 the fourth) and a first-order couple turning with the crank, which
# counterweights at the ends of the crankshaft can take up.
fig = balance.plot.spectrum([v12, w12_2s])
