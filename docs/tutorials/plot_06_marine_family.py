"""
A marine engine family
======================

A maker of large two-stroke engines sells one cylinder in a family of cylinder numbers, and
its project guide tabulates for each number what the engine shakes its seating with: the
external moments of the first and second order, vertical (M1V, M2V: pitching) and horizontal
(M1H, M2H: yawing), the fourth order for some, the *power related unbalance* PRU = moment /
power (N·m/kW) with its class, the guide-force moments, and whether a moment compensator is
advised.

:func:`balance_cli.family` builds that table from one cylinder's data: for each number of
cylinders it repeats the cylinder at the family's pitch, finds the crank and firing order by
the exhaustive crank search (proved best for its objective), and analyses the engine as the
guides do. This tutorial runs it on the shipped template of the MAN B&W S80MC-C7's cylinder
(3 880 kW at 76 rpm; stroke, rod, pitch and masses estimated, as its comments say) for five
to twelve cylinders, checks the guide's statements and every moment by hand, and draws the
PRU against the number of cylinders.

The same table on the command line (see :doc:`/reference/cli`)::

    balance family template:marine-family-2stroke --cylinders 5-12 --units kN
    balance family template:marine-family-2stroke --cylinders 5-12 --format markdown
"""

import matplotlib.pyplot as plt
import numpy as np
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.report.family import family_tables
from balance_cli.units import Scale

TEMPLATE = "template:marine-family-2stroke"
result = balance.family(TEMPLATE, cylinders=range(5, 13), workers=1)
rows = {row["cylinders"]: row for row in result.to_dict()["rows"]}
print(f"objective: {result.objective}; pitch {result.pitch_m:g} m")
print(f"power a cylinder: {result.power_per_cylinder_w / 1e3:g} kW")

# %%
# The table
# ---------
#
# ``balance family --format markdown`` writes this table; in Python it is
# :mod:`balance_cli.report.family`'s rendering of the result, ready for a design note.
# Moments in kN·m; the first order is under the guides' *standard balance*: counterweights
# for the rotating masses and half the reciprocating ones, which leaves the first-order
# couple turning at constant size, so that M1V = M1H. The second and fourth orders are as
# the crank stands (no counterweight can touch them). The search's default objective is the
# sum the guides tabulate, M1V + M1H + M2V + M2H + M4V + M4H in N·m, written in the search's
# terms (``M1-:w1,M2,M4:w4``, each coefficient weighted by one cylinder's force of its order).
print(family_tables(result, Scale.of(True, "kN"), "markdown"))

# %%
# What the guides say
# -------------------
#
# The makers' guides state that six cylinders, firing 1-5-3-4-2-6, have no first-order
# moment but a second-order one that calls for a compensator, and that eight cylinders have
# no second-order moment. The search finds those firing orders by itself:
six, eight = rows[6], rows[8]
print("six:", "-".join(map(str, six["firing_order"])), "M1V", six["M1V_Nm"], "M2V", six["M2V_Nm"])
print("eight:", "-".join(map(str, eight["firing_order"])), "M2V", eight["M2V_Nm"])
assert six["firing_order"] == [1, 5, 3, 4, 2, 6]
assert six["M1V_Nm"] == six["M1H_Nm"] == 0.0 and six["second_order_compensator"]
assert eight["M2V_Nm"] == eight["M2H_Nm"] == 0.0
assert all(row["M1V_Nm"] == row["M1H_Nm"] for row in rows.values())
assert all(row["method"] == "exhaustive" for row in rows.values())

# %%
# Every moment by hand
# --------------------
#
# In an in-line engine of identical cylinders the order-k moment is one cylinder's order-k
# force times the crank's *coefficient* ``|Σ_j (z_j − z̄)·e^{ik·β_j}|``, z_j the throws' axial
# positions (at the pitch) and β_j their phases. One cylinder's forces follow from the
# piston's travel x(θ) = r·cos θ + √(l² − r²·sin² θ): the first order is exactly
# m·r·ω² (the root holds even orders only), the k-th is m·k²·ω² times ``|a_k|``, a_k the
# k-th Fourier coefficient of x, which numpy's FFT gives to rounding. Under the standard
# balance half the reciprocating first order is left vertical and half horizontal. The PRU
# is the moment over the engine's power, n × 3 880 kW.
template = balance.load_template(TEMPLATE)
m_rec = template.cylinders[0].reciprocating_kg
r, rod = 1.6, 3.4  # crank radius and rod length of the template, m
omega = 76 * 2 * np.pi / 60  # rad/s
assert_allclose([template.crank_radius_m, template.speed_rad_s], [r, omega], rtol=1e-12)

theta = np.linspace(0.0, 2 * np.pi, 256, endpoint=False)
travel = r * np.cos(theta) + np.sqrt(rod**2 - (r * np.sin(theta)) ** 2)
a = 2 * np.abs(np.fft.rfft(travel)) / theta.size
force = {1: m_rec * r * omega**2, 2: m_rec * 4 * omega**2 * a[2], 4: m_rec * 16 * omega**2 * a[4]}
print(f"one cylinder: F1 {force[1] / 1e3:.1f} kN, F2 {force[2] / 1e3:.1f} kN", end=", ")
print(f"F4 {force[4] / 1e3:.2f} kN")


def coefficient(row, k):
    n = row["cylinders"]
    z = np.arange(n) * result.pitch_m
    beta = np.radians(row["phases_deg"])
    return abs(np.sum((z - z.mean()) * np.exp(1j * k * beta)))


for n, row in rows.items():
    m1 = 0.5 * force[1] * coefficient(row, 1)
    m2, m4 = force[2] * coefficient(row, 2), force[4] * coefficient(row, 4)
    power_kw = n * 3880.0
    pru2 = m2 / power_kw
    # closed forms against the exact analysis: rounding of sums of a dozen terms and of the
    # FFT (its aliasing from order 256 is λ^128 ≈ 1e-42); atol for the moments that cancel
    scale = force[1] * result.pitch_m
    assert_allclose(
        [row["M1V_Nm"], row["M1H_Nm"], row["M2V_Nm"], row["M4V_Nm"]],
        [m1, m1, m2, m4],
        rtol=1e-9,
        atol=1e-9 * scale,
    )
    pru = {e["order"]: e for e in row["pru"]["orders"]}
    assert_allclose(pru[2]["vertical_Nm_per_kW"], pru2, rtol=1e-9, atol=1e-9)
    # the guides' classes: 120 N·m/kW and above is likely (or most likely) to need one
    assert row["second_order_compensator"] == (pru2 >= 120.0)
    print(f"{n:2d}: M1V = M1H {m1 / 1e3:7.1f} kN·m, M2V {m2 / 1e3:7.1f} kN·m, PRU2 {pru2:6.1f}")

# %%
# Other balances
# --------------
#
# Each row also gives the first order under the other named balances: ``rotating``
# (counterweights for the rotating masses only: all of the reciprocating first order left
# vertical, none horizontal) and ``crank`` (no counterweights but those built; the template
# has none). ``first_order_balance`` chooses the one the table shows, also as a balance
# factor c from 0 to 1: M1V = (1 − c), M1H = c times the reciprocating masses' couple.
seven = rows[7]
print(f"seven, standard: M1V {seven['M1V_Nm'] / 1e3:.1f}, M1H {seven['M1H_Nm'] / 1e3:.1f} kN·m")
print(
    f"seven, rotating: M1V {seven['M1V_rotating_Nm'] / 1e3:.1f}, "
    f"M1H {seven['M1H_rotating_Nm'] / 1e3:.1f} kN·m"
)
# the reciprocating couple moves from both planes into one: the same sum, twice the vertical
assert_allclose(seven["M1V_rotating_Nm"], 2 * seven["M1V_standard_Nm"], rtol=1e-12)
assert seven["M1H_rotating_Nm"] == 0.0

factor = balance.family(TEMPLATE, cylinders=[7], first_order_balance=0.3, workers=1)
seven_03 = factor.to_dict()["rows"][0]
print(
    f"seven, c = 0.3: M1V {seven_03['M1V_Nm'] / 1e3:.1f}, M1H {seven_03['M1H_Nm'] / 1e3:.1f} kN·m"
)
couple = force[1] * coefficient(seven, 1)
# the balance factor's closed form; the search's crank is the same whatever the factor
assert_allclose([seven_03["M1V_Nm"], seven_03["M1H_Nm"]], [0.7 * couple, 0.3 * couple], rtol=1e-9)

# %%
# Guide-force moments
# -------------------
#
# Each crosshead presses sideways on its guide, and the reaction through the main bearings
# makes a couple about the crank axis. The **H-type** moment is their sum, which rocks the
# engine athwartships; with even firing only the multiples of the number of cylinders
# survive. The **X-type** moment is their bimoment about the engine's middle over the guide
# distance, which twists the engine; its largest order depends on the firing order. Both come
# from inertia here (the template has no ``[gas]`` table; one would add the gas forces).
for n, row in rows.items():
    h, x = row["h_type"], row["x_type"]
    print(
        f"{n:2d}: H-type {h['amplitude_Nm'] / 1e3:8.2f} kN·m (order {h['order']:g}), "
        f"X-type {x['amplitude_Nm'] / 1e3:8.1f} kN·m (order {x['order']:g})"
    )
    assert h["order"] % n == 0

# %%
# With the guide's firing orders
# ------------------------------
#
# The guide's own seven- and eight-cylinder engines fire 1-7-2-5-4-3-6 and 1-8-3-4-7-2-5-6.
# Given as ``firing_orders``, they replace the search's. Within one engine type the PRU of
# the first order is the crank's coefficient over the number of cylinders, so its ratio
# between eight and seven cylinders depends on the firing orders alone; the guide prints
# 27,3 and 9,3 N·m/kW, a ratio of 2.935 (± 0.021 for the rounding to 0.05).
guide = balance.family(
    TEMPLATE,
    cylinders=[7, 8],
    firing_orders={7: [1, 7, 2, 5, 4, 3, 6], 8: [1, 8, 3, 4, 7, 2, 5, 6]},
)
pru1 = {
    row["cylinders"]: row["pru"]["orders"][0]["vertical_Nm_per_kW"]
    for row in guide.to_dict()["rows"]
}
print(f"PRU1: seven {pru1[7]:.2f}, eight {pru1[8]:.2f} N·m/kW, ratio {pru1[8] / pru1[7]:.4f}")
# the guide's figures, each rounded to 0.05 N·m/kW: 2.935·(0.05/27.3 + 0.05/9.3)
assert_allclose(pru1[8] / pru1[7], 27.3 / 9.3, atol=0.0212)

# %%
# The search's eight (1-7-3-5-4-6-2-8) leaves half the first-order moment of the guide's
# firing order, with no second-order moment either; a maker weighs more than these moments
# (torsional vibration, the X-type moment, bearing loads) in choosing one.
print(f"PRU1 of eight: the search's {rows[8]['pru']['orders'][0]['vertical_Nm_per_kW']:.2f}")
assert rows[8]["pru"]["orders"][0]["vertical_Nm_per_kW"] < 0.6 * pru1[8]

# %%
# The power related unbalance by number of cylinders
# --------------------------------------------------
#
# Drawn from ``result.to_dict()``: the first order (M1V = M1H under the standard balance)
# and the second (M2V), with the guides' class bounds. Five and six cylinders need a
# second-order compensator; from seven on the moments spread over more throws and more power.
counts = sorted(rows)
pru_1 = [rows[n]["pru"]["orders"][0]["vertical_Nm_per_kW"] for n in counts]
pru_2 = [rows[n]["pru"]["orders"][1]["vertical_Nm_per_kW"] for n in counts]
fig, ax = plt.subplots(figsize=(8, 4.5), layout="constrained")
x = np.arange(len(counts))
ax.bar(x - 0.2, pru_1, width=0.4, label="first order, M1V = M1H")
ax.bar(x + 0.2, pru_2, width=0.4, label="second order, M2V")
for bound, name in ((60, "unlikely"), (120, "likely"), (220, "most likely")):
    ax.axhline(bound, color="0.5", linestyle=":", linewidth=0.8)
    ax.annotate(
        f"{name} above {bound}", (len(counts) - 0.5, bound), ha="right", va="bottom", fontsize=8
    )
ax.set_xticks(x, [str(n) for n in counts])
ax.set(
    xlabel="Cylinders",
    ylabel="PRU (N·m/kW)",
    title="MAN B&W S80MC-C7 family: power related unbalance",
)
ax.legend(loc="upper center")
assert [rows[n]["second_order_compensator"] for n in counts] == [True, True] + [False] * 6

# %%
# Why six cylinders need a second-order compensator and eight do not: each cylinder's share
# (z − z̄)·F of the second-order moment, chained (:func:`balance_cli.plot.star`). The six's
# shares add up to a couple; the eight's close on themselves.
# (each re-analysed under a short name for the picture's titles)
engines = [
    balance.analyse(
        row.result.engine.replace(
            name=f"{row.cylinders} cylinders, {'-'.join(map(str, row.result.firing.order))}"
        )
    )
    for row in result.rows
    if row.cylinders in (6, 8)
]
fig = balance.plot.star(engines, order=2, of="moment")
