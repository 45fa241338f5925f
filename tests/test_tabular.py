"""Results a notebook takes directly: every result's records() and to_pandas(), checked against
the result's own attributes and against a value worked out apart from the library for each
kind of result; pandas missing is one clear error naming the extra."""

import inspect
import json
import math
import sys

import numpy as np
import pandas
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.cylinders import cylinder_torques
from balance_cli.analysis.series import Series
from balance_cli.tabular import Tabular
from tests.support import CONFIGS, MRW2, PITCH, inline_template_text, inline_toml

#: one cylinder of a two-stroke: m = 0.5 kg, r = 40 mm, l = 140 mm, 3000 rpm
SINGLE = """\
name = "single"
cycle = 2
speed = "3000 rpm"
crank_radius = "40 mm"
rod_length = "140 mm"

[masses]
reciprocating = "500 g"

[[banks]]
angle = 0

[[throws]]
phase = 0
"""
M, R, L = 0.5, 0.040, 0.140
OMEGA = 3000 * math.pi / 30
MRW = M * R * OMEGA**2  # 1973.9 N

#: public classes with a to_dict() that are parts of a result, not results: the result whose
#: records carry them (a new class with to_dict() must be one or the other)
PARTS = {
    "Configuration": "an input (the file's data), not a result",
    "PressureCurve": "an input read from a file",
    "CycleCurve": "an input read from a file",
    "FirstOrderBalance": "a setting of compare and family",
    "OrderComponents": "one row of EngineResult.records",
    "Firing": "EngineResult.to_dict()['firing'], shown in compare's tables",
    "Plane": "part of Counterweight",
    "Counterweight": "part of Balance (its to_dict's counterweights)",
    "Shaft": "part of Balance",
    "ShaftMass": "part of Balance",
    "BalancerShaft": "part of Balance",
    "RollingMoment": "part of Balance",
    "Antivibrateur": "part of Balance",
    "ReducedMass": "part of TorqueResult",
    "PinForce": "part of TorqueResult",
    "CrankshaftTorque": "part of TorqueResult",
    "CylinderTorque": "rows of CylinderTorques.records",
    "Moved": "one row of Regression.records",
    "Arrangement": "one row of SearchResult.records",
    "Term": "part of SearchResult (its objective)",
}


def public_classes_with_to_dict():
    return {
        name: getattr(balance, name)
        for name in balance.__all__
        if inspect.isclass(getattr(balance, name))
        and callable(getattr(getattr(balance, name), "to_dict", None))
    }


def single():
    return balance.loads(SINGLE, "single.toml")


#: two pistons 20 g apart for the twin of the fixture (1 kg each, as configured, on average)
TWIN_PISTONS = balance.workshop.PartSet(
    (balance.workshop.Piston("A", 0.81), balance.workshop.Piston("B", 0.79))
)
#: the single's reciprocating scatter, kg
SIGMA = 0.002


def piston(theta):
    """x(θ), x'(θ), x''(θ) of the piston pin along the cylinder axis, from the crank centre:
    x = r·cos θ + S, S = √(l² − r²·sin²θ), differentiated by hand."""
    s = np.sqrt(L**2 - R**2 * np.sin(theta) ** 2)
    x1 = -R * np.sin(theta) - R**2 * np.sin(theta) * np.cos(theta) / s
    x2 = (
        -R * np.cos(theta)
        - R**2 * np.cos(2 * theta) / s
        - R**4 * (np.sin(2 * theta) / 2) ** 2 / s**3
    )
    return R * np.cos(theta) + s, x1, x2


def harmonic(values, k):
    """(cos, sin) coefficients of order k of samples over one revolution."""
    c = np.fft.rfft(values) / len(values)
    return 2 * c[k].real, -2 * c[k].imag


THETA = np.arange(4096) * 2 * math.pi / 4096


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    """One of every result class, each from a small engine (a few seconds in all)."""
    folder = tmp_path_factory.mktemp("results")
    engine = single()
    result = balance.analyse(engine, samples=64, max_order=4)
    twin_text = inline_toml("twin", [0, 180], 100, cycle=2).replace(
        'name = "twin"\n', 'name = "twin"\npower = "100 kW"\n'
    )
    twin = balance.loads(twin_text, "twin.toml")
    twin_result = balance.analyse(twin, samples=64, max_order=4)
    torques = balance.torque(engine, samples=256, max_order=4)
    (folder / "single.toml").write_text(SINGLE)
    (folder / "three.toml").write_text(inline_template_text(3))
    three = balance.load_template(folder / "three.toml")
    chain = balance.loads(
        SINGLE.split("[[throws]]")[0]
        + "[[throws]]\nphase = 0\n[[throws]]\nphase = 180\n"
        + '[torsion]\nthrow_inertia = ["0.05 kg*m^2", "0.2 kg*m^2"]\n'
        + 'stiffness = ["1.5e4 N*m/rad"]\n',
        "chain.toml",
    )
    baseline = balance.compare([result]).to_dict()
    faster = balance.analyse(engine.edit(speed="6000 rpm"), samples=64, max_order=4)
    matched = balance.match(twin, TWIN_PISTONS, samples=64, max_order=4)
    return {
        "EngineResult": result,
        "Comparison": balance.compare([result, twin_result]),
        "Balance": balance.counterweights(engine, samples=64, max_order=4),
        "Balances": balance.Balances((balance.counterweights(engine, samples=64, max_order=4),)),
        "TorqueResult": torques,
        "TorqueSet": balance.TorqueSet((torques,)),
        "Series": torques.total,
        "GuideForces": torques.guide,
        "CylinderTorques": cylinder_torques(engine, samples=256, max_order=4),
        "Steadiness": balance.steadiness(
            100.0 + 30.0 * np.sin(2 * THETA), 360.0, 5.0, OMEGA, "constant"
        ),
        "PowerRelatedUnbalance": twin_result.power_related_unbalance(),
        "SweepResult": balance.sweep(
            folder / "single.toml", "speed", ["1000 rpm", "2000 rpm"], ["F1"], 64, 2
        ),
        "SweepGrid": balance.sweep_grid(
            folder / "single.toml",
            ["speed", "rod_ratio"],
            [["1000 rpm", "2000 rpm"], [3.0, 4.0]],
            ["F1"],
            64,
            2,
        ),
        "FamilyResult": balance.family(
            balance.read_configuration(folder / "three.toml"), [3], workers=1, max_order=4
        ),
        "SearchResult": balance.search(three, "M1", top=1, workers=1, max_order=2),
        "TorsionResult": balance.torsional_vibration(chain, [1000.0, 6000.0], 2),
        "Regression": balance.regression(baseline, balance.compare([faster]).to_dict()),
        "MountResult": balance.mounts(
            balance.load(CONFIGS / "mounts" / "four-mount-symmetric.toml"),
            speeds_rpm=[1000.0],
            orders=[2],
        ),
        "Decoupling": balance.decouple(
            balance.load(CONFIGS / "mounts" / "four-mount-symmetric.toml"),
            [(("front left", "front right", "rear left", "rear right"), "z")],
        ),
        "MatchResult": matched,
        "Fitting": matched.best,
        "ToleranceResult": balance.tolerance(
            engine, balance.ToleranceBand(reciprocating_kg=SIGMA), runs=400, samples=64, max_order=2
        ),
        "BobweightSheet": balance.bobweights(engine, samples=64, max_order=2),
    }


def test_every_public_result_class_gives_records_and_to_pandas(results):
    """A public class with to_dict() is a result (a Tabular, with an instance here) or a part
    of one (PARTS, with its reason): a new result without records() fails here."""
    classes = public_classes_with_to_dict()
    assert len(classes) > 30  # the search above finds them all, not none
    unsorted = sorted(set(classes) - set(PARTS) - set(results))
    assert not unsorted, f"give these records() (a Tabular) or list them as parts: {unsorted}"
    for name in results:
        cls = getattr(balance, name, None) or type(results[name])
        assert issubclass(cls, Tabular), name
        assert isinstance(results[name], cls), name
    assert not set(PARTS) & set(results)


def test_records_are_flat_rows_of_plain_values_and_to_pandas_holds_them(results):
    for name, result in results.items():
        records = result.records()
        assert isinstance(records, list) and records, name
        for row in records:
            assert isinstance(row, dict), name
            for key, value in row.items():
                assert isinstance(key, str), (name, key)
                assert value is None or isinstance(value, (bool, int, float, str)), (name, key)
        json.dumps(records, allow_nan=False)  # plain values: JSON takes them as they are
        frame = result.to_pandas()
        assert isinstance(frame, pandas.DataFrame)
        keys = list(dict.fromkeys(k for row in records for k in row))
        assert list(frame.columns) == keys, name
        assert len(frame) == len(records), name
        for i, row in enumerate(records):
            for key, value in row.items():
                cell = frame[key].iloc[i]
                if value is None:
                    assert cell is None or pandas.isna(cell), (name, key)
                else:
                    assert cell == value, (name, i, key)


def test_engine_result_records_hold_the_orders_and_one_cylinders_forces(results):
    """One cylinder alone: order 1 of the piston's force is exactly m·r·ω² (r·cos θ, the rod's
    square root has even harmonics only), half forward, half backward; order 2 is m·ω² times
    the piston's second harmonic, here from x''(θ) differentiated by hand and an FFT of 4096
    points (a smooth periodic function: the FFT is exact to rounding)."""
    result = results["EngineResult"]
    rows = result.records()
    assert [r["order"] for r in rows] == [1, 2, 3, 4]
    assert {r["engine"] for r in rows} == {"single"}
    first = rows[0]
    # the exact first order against rounding in a 64-point FFT
    assert_allclose(first["force_max_N"], MRW, rtol=1e-12)
    assert_allclose(
        [first["force_forward_N"], first["force_backward_N"]], [MRW / 2] * 2, rtol=1e-12
    )
    cos2, sin2 = harmonic(-M * OMEGA**2 * piston(THETA)[2], 2)
    assert_allclose(rows[1]["force_max_N"], math.hypot(cos2, sin2), rtol=1e-9)
    for row in rows:  # the records are the result's own phasors
        order = result.order(row["order"])
        assert_allclose(row["force_forward_N"], abs(order.force_forward), rtol=1e-12, atol=1e-9)
        assert_allclose(row["force_backward_N"], abs(order.force_backward), rtol=1e-12, atol=1e-9)
        assert row["moment_max_Nm"] == 0.0  # one cylinder has no lever
    assert set(first) >= {"force_forward_deg", "force_axis_deg", "moment_vertical_Nm"}


def test_comparison_records_are_its_engines_rows_one_after_the_other(results):
    comparison = results["Comparison"]
    rows = comparison.records()
    assert rows == [row for r in comparison.results for row in r.records()]
    assert [r["engine"] for r in rows] == ["single"] * 4 + ["twin"] * 4


def test_balance_records_give_each_stage(results):
    """A counterweight on the one throw cancels the forward first order m·r·ω²/2 and leaves the
    backward one, m·r·ω²/2: a circle turning against the crank."""
    rows = results["Balance"].records()
    assert {r["stage"] for r in rows} == {"original", "residual"}
    first = {r["stage"]: r for r in rows if r["order"] == 1}
    assert_allclose(first["original"]["force_forward_N"], MRW / 2, rtol=1e-12)
    assert first["residual"]["force_forward_N"] == 0.0  # below the noise floor: exact zero
    assert_allclose(first["residual"]["force_backward_N"], MRW / 2, rtol=1e-12)
    assert_allclose(first["residual"]["force_min_N"], MRW / 2, rtol=1e-12)
    assert results["Balances"].records() == rows


def test_torque_records_hold_every_series_and_the_inertia_torque_by_hand(results):
    """The inertia torque of one piston: T = −m·ω²·x''·x' (the piston's force on the crank
    times the travel per radian), order 2 by an FFT of x', x'' differentiated by hand; the
    leading term is −½·m·r²·ω²·sin 2θ. The mean is the row of order 0."""
    torques = results["TorqueResult"]
    rows = torques.records()
    assert {r["torque"] for r in rows} == {"inertia", "tilting", "frame", "total"}  # no gas
    total = {r["order"]: r for r in rows if r["torque"] == "total"}
    _, x1, x2 = piston(THETA)
    cos2, sin2 = harmonic(-M * OMEGA**2 * x2 * x1, 2)
    assert_allclose(
        [total[2.0]["cos_Nm"], total[2.0]["sin_Nm"]], [cos2, sin2], rtol=1e-9, atol=1e-6
    )
    assert_allclose(sin2, -0.5 * M * R**2 * OMEGA**2, rtol=0.01)  # λ² corrections: < 1 %
    assert_allclose(total[2.0]["amplitude_Nm"], math.hypot(cos2, sin2), rtol=1e-9)
    assert total[0.0]["cos_Nm"] == torques.total.mean
    for k, cos, sin in torques.total.orders:
        assert (total[k]["cos_Nm"], total[k]["sin_Nm"]) == (cos, sin)
    assert results["TorqueSet"].records() == rows


def test_series_records_by_hand():
    """X = 5 + 3·cos 2θ − 4·sin 2θ: the mean as order 0, order 2 of amplitude 5 and phase
    atan2(−4, 3) = 306.87° (the term is amplitude·cos(2θ − phase)); a negative mean's phase is
    180°."""
    series = Series.from_curve(5 + 3 * np.cos(2 * THETA) - 4 * np.sin(2 * THETA), 360.0, 3, 1e-9)
    rows = {r["order"]: r for r in series.records()}
    assert_allclose([rows[0.0]["cos_Nm"], rows[0.0]["amplitude_Nm"]], [5, 5], rtol=1e-12)
    assert rows[0.0]["phase_deg"] == 0.0
    assert_allclose(
        [rows[2.0]["cos_Nm"], rows[2.0]["sin_Nm"], rows[2.0]["amplitude_Nm"]],
        [3, -4, 5],
        rtol=1e-12,
    )
    assert_allclose(rows[2.0]["phase_deg"], math.degrees(math.atan2(-4, 3)) + 360, rtol=1e-12)
    assert rows[1.0]["amplitude_Nm"] == 0.0 and rows[3.0]["amplitude_Nm"] == 0.0
    negative = Series.from_curve(-2 + 0 * THETA, 360.0, 1, 1e-9).records()[0]
    assert negative["phase_deg"] == 180.0 and negative["amplitude_Nm"] == 2.0


def test_cylinder_torques_and_guide_forces_records(results):
    """One cylinder: its own inertia torque is the engine's; without gas its guide force's
    couple with the main bearings is the whole reaction on the frame, the torque's opposite
    (Newton's third law), so the H-type moment of order 2 is −(cos, sin) of the torque."""
    _, x1, x2 = piston(THETA)
    cos2, sin2 = harmonic(-M * OMEGA**2 * x2 * x1, 2)
    rows = results["CylinderTorques"].records()
    assert {(r["cylinder"], r["throw"], r["torque"]) for r in rows} == {(1, 1, "inertia")}
    own = {r["order"]: r for r in rows}
    assert_allclose([own[2.0]["cos_Nm"], own[2.0]["sin_Nm"]], [cos2, sin2], rtol=1e-9, atol=1e-6)
    guide = results["GuideForces"].records()
    assert {r["moment"] for r in guide} == {"H-type", "X-type"}
    h = {r["order"]: r for r in guide if r["moment"] == "H-type"}
    assert_allclose([h[2.0]["cos_Nm"], h[2.0]["sin_Nm"]], [-cos2, -sin2], rtol=1e-6, atol=1e-6)
    # one cylinder at z̄: no bimoment
    assert all(r["amplitude_Nm"] == 0.0 for r in guide if r["moment"] == "X-type")


def test_steadiness_record_by_hand(results):
    """A driving torque C_m + C·sin 2θ against a constant load C_m: the kinetic energy swings
    by ∫ C·sin 2θ over half a period of it, 2C/2 = C, so ω_max − ω_min ≈ C/(I·ω_m) and the
    steadiness ω_m/(ω_max − ω_min) ≈ I·ω_m²/C (first order in the fluctuation, 6e-4 here:
    rtol 1e-2)."""
    speed = results["Steadiness"]
    (row,) = speed.records()
    assert row == speed.to_dict()
    assert_allclose(row["steadiness"], 5.0 * OMEGA**2 / 30.0, rtol=1e-2)
    assert row["order"] == 2 and row["load"] == "constant"
    assert_allclose(row["mean_speed_rpm"], 3000.0, rtol=1e-3)


def test_power_related_unbalance_records_by_hand(results):
    """A 180° twin two-stroke, m = 1 kg, r = 50 mm, 3000 rpm, throws d = 100 mm apart, 100 kW:
    the first-order couple m·r·ω²·d is vertical; the standard balance's counterweights (half
    the reciprocating mass) turn half of it into a circle, leaving M1V = M1H = ½·m·r·ω²·d; the
    second orders are in phase, no couple. PRU = moment / 100 kW."""
    pru = results["PowerRelatedUnbalance"]
    rows = {r["order"]: r for r in pru.records()}
    half = 0.5 * MRW2 * PITCH
    assert_allclose([rows[1]["vertical_Nm"], rows[1]["horizontal_Nm"]], [half, half], rtol=1e-9)
    assert_allclose(rows[1]["vertical_Nm_per_kW"], half / 100.0, rtol=1e-9)
    assert rows[2]["vertical_Nm"] == 0.0
    assert rows[1]["balance"] == "standard" and rows[2]["balance"] == "crank"
    assert all(r["power_kW"] == 100.0 for r in rows.values())
    assert [dict(r, balance=None, power_kW=None) for r in pru.records()] == [
        dict(e, balance=None, power_kW=None) for e in pru.orders
    ]
    without = balance.analyse(single(), samples=64, max_order=2).power_related_unbalance()
    assert not without.available and without.records() == []


def test_sweep_records_keep_their_shape_and_follow_the_square_law(results):
    sweep, grid = results["SweepResult"], results["SweepGrid"]
    assert sweep.records() == [dict(p) for p in sweep.points]
    omega = np.array([1000.0, 2000.0]) * math.pi / 30
    assert_allclose([r["F1_N"] for r in sweep.records()], M * R * omega**2, rtol=1e-12)
    assert grid.records() == [dict(p) for p in grid.points]
    # the first order does not care for the rod: m·r·ω² at either ratio
    assert_allclose([r["F1_N"] for r in grid.records()], np.repeat(M * R * omega**2, 2), rtol=1e-12)


def test_family_records_by_hand(results):
    """An in-line three two-stroke (throws 120° apart, pitch d = 500 mm, m = 120 kg, r = 150 mm,
    300 rpm): as the crank stands the first-order couple is √3·d·m·r·ω², all pitching."""
    family = results["FamilyResult"]
    (row,) = family.records()
    record = family.rows[0].to_dict()
    assert row["cylinders"] == 3 and row["firing_order"] == "-".join(
        map(str, record["firing_order"])
    )
    couple = math.sqrt(3) * 0.5 * 120 * 0.150 * (300 * math.pi / 30) ** 2
    assert_allclose(row["M1V_crank_Nm"], couple, rtol=1e-9)
    assert row["M1H_crank_Nm"] == 0.0
    assert row["first_order_balance"] == "standard"
    assert row["power_kW"] is None and "PRU_M1V_Nm_per_kW" not in row
    for key in ("M1V_Nm", "M2V_Nm", "M4V_Nm", "second_order_compensator", "score", "method"):
        assert row[key] == record[key], key


def test_search_records_by_hand(results):
    """An in-line three's first-order couple coefficient is √3 (the textbook figure)."""
    search = results["SearchResult"]
    (row,) = search.records()
    best = search.arrangements[0]
    assert_allclose(row["M1"], math.sqrt(3), rtol=1e-9)
    assert row["rank"] == 1 and row["score"] == best.score
    assert row["firing_order"] == "-".join(map(str, best.firing_order))
    assert row["phases_deg"] == " ".join(f"{p:g}" for p in best.phases_deg)
    assert row["uniform"] is True and row["intervals_deg"] == "120 120 120"


def test_torsion_records_by_hand(results):
    """Two disks J1 = 0.05, J2 = 0.2 kg·m² on k = 1.5e4 N·m/rad: f = √(k·(J1 + J2)/(J1·J2))/2π
    = 97.47 Hz; order k's critical is at 60·f/k rpm (orders 1 and 2 within 1000-6000 rpm)."""
    torsion = results["TorsionResult"]
    hz = math.sqrt(1.5e4 * 0.25 / (0.05 * 0.2)) / (2 * math.pi)
    rows = torsion.records()
    assert [r["order"] for r in rows] == [2.0, 1.0]  # by speed
    for row in rows:
        assert_allclose(row["frequency_Hz"], hz, rtol=1e-10)  # a 2×2 eigenproblem
        assert_allclose(row["speed_rpm"], 60 * hz / row["order"], rtol=1e-10)
        assert row["mode"] == 1
    assert [{k: v for k, v in r.items() if k not in ("engine", "frequency_Hz")} for r in rows] == [
        c.to_dict() for c in torsion.criticals
    ]


def test_regression_records_by_hand(results):
    """The same cylinder at twice the speed: every force is ×4, a relative change of +3."""
    rows = {(r["order"], r["quantity"]): r for r in results["Regression"].records()}
    first = rows[(1, "force.max_N")]
    assert_allclose(first["baseline"], MRW, rtol=1e-12)
    assert_allclose([first["now"], first["relative_change"]], [4 * MRW, 3.0], rtol=1e-12)
    assert first["engine"] == "single"


def test_mount_records_by_hand(results):
    """The symmetric example at 1000 rpm, order 2 alone: the in-line four's secondary force
    F = A₂·(Ω/ω₀)² (vertical, at the centre of gravity) bounces the engine on 4·k_z = 800 N/mm:
    |Z| = F/(4·k_z − m·ω²), ω = 2Ω; each mount sinks by Z plus the roll's ±b·θ_x. Rows: the
    orders summed ("all") then order 2, each for the centre of gravity and the four mounts;
    with one order the sum's peaks are the order's amplitudes."""
    result = results["MountResult"]
    engine = result.engine
    part = balance.analyse(engine).order(2)
    force = abs(part.force_forward + np.conj(part.force_backward))
    omega = 2 * 1000 * math.pi / 30
    force *= (1000 * math.pi / 30 / engine.speed_rad_s) ** 2
    bounce = force / abs(800e3 - 150 * omega**2)
    rows = result.records()
    assert [(r["order"], r["where"]) for r in rows[:2]] == [
        ("all", "centre of gravity"),
        ("all", "front left"),
    ]
    assert len(rows) == 2 * 5
    # the sum over a cycle is sampled 32 times a period of the order: within 1 − cos(π/32)
    assert_allclose(rows[0]["z_m"], bounce, rtol=5e-3)
    assert_allclose(rows[5]["z_m"], bounce, rtol=1e-9)  # the order's amplitude: a 6×6 solve
    assert rows[5]["Fx_N"] is None and rows[6]["rx_rad"] is None
    assert rows[6]["where"] == "front left" and rows[6]["Fz_N"] > 0


def test_decoupling_records_by_hand(results):
    """The symmetric example is decoupled as it stands (its mounts in the plane of the centre
    of gravity answer a roll with a couple about x alone): one row per mount's z rate, each
    200 N/mm before and after, the roll mode at √(4·k_z·b²/J_xx)/2π before and after."""
    rows = results["Decoupling"].records()
    assert [(r["mount"], r["rate"], r["principal"]) for r in rows] == [
        (name, "z", 3) for name in ("front left", "front right", "rear left", "rear right")
    ]
    roll_hz = math.sqrt(4 * 200e3 * 0.25**2 / 6.0) / (2 * math.pi)
    for row in rows:
        assert row["before_N_per_m"] == 200e3
        assert_allclose(row["after_N_per_m"], 200e3, rtol=1e-12)  # no change: rounding
        assert_allclose(
            [row["frequency_before_Hz"], row["frequency_after_Hz"]], roll_hz, rtol=1e-12
        )
        assert row["exact"] is True


def test_match_records_by_hand(results):
    """Two pistons 20 g apart in a 180° twin of 1 kg reciprocating masses: each cylinder keeps
    its 1 kg less the mean piston (0.8 kg) plus its own piston; either way round the first
    order left is a line force of 20 g·r·ω² (the swap is the crank's own symmetry)."""
    result = results["MatchResult"]
    rows = result.records()
    assert [(r["fitting"], r["cylinder"]) for r in rows] == [
        ("best", 1),
        ("best", 2),
        ("given", 1),
        ("given", 2),
    ]
    given = {r["cylinder"]: r for r in rows if r["fitting"] == "given"}
    assert (given[1]["piston"], given[2]["piston"]) == ("A", "B")
    assert_allclose([given[1]["reciprocating_kg"], given[2]["reciprocating_kg"]], [1.01, 0.99])
    assert all(r["rod"] is None for r in rows)
    first = result.best.difference.order(1)
    # the line force's two halves, against rounding in a 64-point FFT
    assert_allclose(abs(first.force_forward) + abs(first.force_backward), 0.02 * MRW2, rtol=1e-12)
    assert results["Fitting"].records() == rows[:2]


def test_tolerance_records_by_hand(results):
    """One cylinder whose reciprocating mass scatters by σ: its first order is (m + σξ)·r·ω²
    along the axis, so the closed form's mean is m·r·ω² and its 95th percentile
    (m + 1.645·σ)·r·ω²; the runs' mean is within four standard errors of it."""
    result = results["ToleranceResult"]
    rows = result.records()
    assert [r["order"] for r in rows] == [1, 2]
    first = rows[0]
    unit = R * OMEGA**2
    assert_allclose(first["force_vertical_linear_mean_N"], M * unit, rtol=1e-12)
    # the standard normal's 95th percentile to 10 digits
    assert_allclose(
        first["force_vertical_linear_p95_N"], (M + 1.6448536270 * SIGMA) * unit, rtol=1e-10
    )
    spread = result.order(1).force["vertical"]
    assert abs(first["force_vertical_mean_N"] - M * unit) < 4 * spread.mean_error
    assert first["force_vertical_mean_N"] == spread.mean


def test_bobweight_records_by_hand(results):
    """One cylinder without a rotating mass: half its 500 g reciprocates with the forward first
    order, so its bobweight is 250 g."""
    (row,) = results["BobweightSheet"].records()
    assert row["throw"] == 1 and row["cylinders"] == "1"
    assert_allclose([row["factor"], row["bobweight_kg"]], [0.5, 0.25], rtol=1e-12)
    assert row["rotating_kg"] == 0.0 and row["reciprocating_kg"] == 0.5


def test_without_pandas_to_pandas_names_the_extra(results, monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas now fails
    with pytest.raises(balance.PandasUnavailable) as caught:
        results["EngineResult"].to_pandas()
    message = str(caught.value)
    assert "pip install 'engine-balance[pandas]'" in message
    assert "records()" in message and "\n" not in message
    assert isinstance(caught.value, balance.BalanceError) and isinstance(caught.value, ImportError)
    assert results["EngineResult"].records()  # the rows need nothing


def test_every_result_shows_html_in_jupyter(results):
    """Each result's HTML: its command's tables (a heading or a paragraph, and a table where
    the command prints one), or its records as a table; never the plain repr."""
    for name, result in results.items():
        text = result._repr_html_()
        assert text.startswith('<div class="balance-result">'), name
        assert "<table>" in text or name == "Steadiness", name  # steadiness is one paragraph
        assert "<script" not in text, name
    assert "steadiness ω_m/(ω_max − ω_min)" in results["Steadiness"]._repr_html_()
