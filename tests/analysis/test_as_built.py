"""Counterweights and balancer shafts as built in the configuration: read, analysed, proposed
in addition and written back (``counterweight --write``).

Every expected value is derived by hand in the test's docstring (the classic cross-plane V8
end-web counterweights, Lanchester's pair, the rolling moment x × F of an offset shaft), or
the slider-crank harmonic B_k of ``tests.support.exact_b`` (the closed-form acceleration
projected by the trapezoidal rule, apart from the library)."""

import json
import math
import textwrap

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.balancer import built_shafts, rolling_moment_phasor
from balance_cli.kinematics.linkage import (
    BALANCER,
    COUNTERWEIGHT,
    CRANK,
    engine_angles,
    linkage_state,
)
from balance_cli.model import BalancerMass, BalancerShaftSpec, CounterweightMass
from tests.support import CONFIGS, exact_b, invoke, write

M, ROT, R, L, RPM, D = 0.6, 0.3, 0.045, 0.15, 3000.0, 0.1
W = RPM * math.pi / 30.0
# FFT rounding is about 1e-13 of the largest force; cancellations are checked to 1e-9 of the
# force that is cancelled, a wide margin that still catches any wrong angle or size (a 1e-6
# error in either leaves 1e-6)
CANCEL = 1e-9
# figures that must not move at all (orders a counterweight or shaft does not touch): the same
# sums with a few more terms, equal to rounding
SAME = 1e-12
V8 = textwrap.dedent(f"""\
    name = "cross-plane V8"
    cycle = 4
    speed = "{RPM:g} rpm"
    crank_radius = "{R * 1e3:g} mm"
    rod_length = "{L * 1e3:g} mm"
    firing_order = [1, 5, 4, 8, 6, 3, 7, 2]

    [masses]
    reciprocating = "{M * 1e3:g} g"
    rotating = "{ROT * 1e3:g} g"

    [[banks]]
    angle = -45
    [[banks]]
    angle = 45

    [[throws]]
    phase = 0
    z = "0 mm"
    [[throws]]
    phase = 90
    z = "{D * 1e3:g} mm"
    [[throws]]
    phase = 270
    z = "{2 * D * 1e3:g} mm"
    [[throws]]
    phase = 180
    z = "{3 * D * 1e3:g} mm"
""")
I4 = textwrap.dedent(f"""\
    name = "in-line 4"
    cycle = 4
    speed = "{RPM:g} rpm"
    crank_radius = "{R * 1e3:g} mm"
    rod_length = "{L * 1e3:g} mm"
    firing_order = [1, 3, 4, 2]

    [masses]
    reciprocating = "{M * 1e3:g} g"
    rotating = "{ROT * 1e3:g} g"

    [[banks]]
    angle = 0

    [[throws]]
    phase = 0
    z = "0 mm"
    [[throws]]
    phase = 180
    z = "{D * 1e3:g} mm"
    [[throws]]
    phase = 180
    z = "{2 * D * 1e3:g} mm"
    [[throws]]
    phase = 0
    z = "{3 * D * 1e3:g} mm"
""")
#: Derivation. A throw of phase β carries two pistons at ±45° and the big ends (ROT) at its pin.
#: Each piston's first-order inertia force is m·r·ω²·cos(θ + β − γ) along its axis γ (exactly:
#: the rod adds only even orders); the two at ±45° add to a force m·r·ω²·e^{i(θ+β)} turning with
#: the crank, and the big ends to ROT·r·ω²·e^{i(θ+β)}: forward first order (m + ROT)·r·ω²·e^{iβ}
#: per throw, no backward part. Over β = 0, 90°, 270°, 180° the forces cancel (1 + i − i − 1);
#: the couple about z̄ = 1.5·d is (m + ROT)·r·ω²·d·(−1.5 − 0.5i + 0.5·(−i) + 1.5·(−1))
#: = (m + ROT)·r·ω²·d·(−3 − i), of size √10·(m + ROT)·r·ω²·d (tests/analysis/test_results.py).
#: Two counterweights in the end webs (z = 0 at throw 1, z = 3d at throw 4), phasors c₁ and c₄
#: (a mass m·ρ at direction φ adds m·ρ·ω²·e^{iφ}): c₁ + c₄ = 0 and −1.5d·c₁ + 1.5d·c₄ = −couple,
#: so c₄ = (m + ROT)·r·ω²·(1 + i/3) and c₁ = −c₄. Each has
#: m·ρ = (m + ROT)·r·|1 + i/3| = (m + ROT)·r·√10/3, the rear one at arctan(1/3) = 18.43° from
#: throw 1's pin, the front one at 198.43°. Measured from their own pins: the front one
#: 198.43° from throw 1's (phase 0), the rear one 18.43° − 180° = −161.57° from throw 4's.
ALPHA_DEG = math.degrees(math.atan(1 / 3))
V8_MR = (M + ROT) * R * math.sqrt(10) / 3
V8_WEIGHTS = textwrap.dedent(f"""\

    [[counterweights]]
    throw = 1
    mass_radius = "{V8_MR!r} kg*m"
    angle = {180 + ALPHA_DEG!r}

    [[counterweights]]
    throw = 4
    mass = "{V8_MR / 0.05!r} kg"
    radius = "50 mm"
    angle = {ALPHA_DEG - 180!r}
""")


def lanchester(mass_radius, angle_deg=180.0, extra=""):
    """[[shafts]]: a pair at ±2× crank speed, each with one mass of ``mass_radius`` kg·m at
    ``angle_deg`` in its own sense of turning, at z̄ (the default)."""
    return "".join(
        textwrap.dedent(f"""\

        [[shafts]]
        ratio = {ratio}
        {extra}
        [[shafts.masses]]
        mass_radius = "{float(mass_radius)!r} kg*m"
        angle = {float(angle_deg)!r}
    """)
        for ratio in (2, -2)
    )


ONE_WEIGHT = textwrap.dedent("""\

    [[counterweights]]
    throw = 1
    mass = "1 kg"
    radius = "40 mm"
    angle = 180
""")
ONE_SHAFT = textwrap.dedent("""\

    [[shafts]]
    ratio = 2

    [[shafts.masses]]
    mass = "1 kg"
    eccentricity = "10 mm"
    angle = 180
""")
BAD = [
    # (text, key named, words of the fix)
    (ONE_WEIGHT.replace("throw = 1\n", ""), "counterweights[1].throw", "missing"),
    (ONE_WEIGHT.replace("angle = 180\n", ""), "counterweights[1].angle", "missing"),
    (
        ONE_WEIGHT.replace('mass = "1 kg"\n', ""),
        "counterweights[1].mass",
        "missing; give mass with radius",
    ),
    (
        ONE_WEIGHT.replace('radius = "40 mm"\n', ""),
        "counterweights[1].radius",
        "missing; a mass needs its radius",
    ),
    (
        ONE_WEIGHT + 'mass_radius = "0.04 kg*m"\n',
        "counterweights[1].mass",
        "give mass with radius, or mass_radius, not both",
    ),
    (
        ONE_WEIGHT.replace("throw = 1", "throw = 5"),
        "counterweights[1].throw",
        "must be between 1 and 4",
    ),
    (
        ONE_WEIGHT.replace("throw = 1", "throw = 0"),
        "counterweights[1].throw",
        "must be between 1 and 4",
    ),
    (
        ONE_WEIGHT.replace('"1 kg"', '"1 kg*m"'),
        "counterweights[1].mass",
        "is an unbalance, but a mass is needed",
    ),
    (ONE_WEIGHT + 'colour = "red"\n', "counterweights[1].colour", "unknown key"),
    (ONE_SHAFT.replace("ratio = 2", "ratio = 0"), "shafts[1].ratio", "must not be 0"),
    (ONE_SHAFT.replace("ratio = 2", "ratio = 1.5"), "shafts[1].ratio", "expected a whole number"),
    (ONE_SHAFT.replace("ratio = 2\n", ""), "shafts[1].ratio", "missing"),
    (ONE_SHAFT.split("[[shafts.masses]]")[0], "shafts[1].masses", "missing"),
    (
        ONE_SHAFT.replace('eccentricity = "10 mm"\n', 'mass_radius = "0.01 kg*m"\n'),
        "shafts[1].masses[1].mass",
        "give mass with eccentricity, or mass_radius, not both",
    ),
    (
        ONE_SHAFT.replace('eccentricity = "10 mm"', 'eccentricity = "10 kg"'),
        "shafts[1].masses[1].eccentricity",
        "is a mass, but a length is needed",
    ),
    (
        ONE_SHAFT.replace("ratio = 2", 'ratio = 2\nlateral = "1 bananas"'),
        "shafts[1].lateral",
        "unknown unit",
    ),
    ('frame = "rotary"\n' + ONE_WEIGHT, "counterweights", "cannot be given for a rotary engine"),
    ('frame = "rotary"\n' + ONE_SHAFT, "shafts", "cannot be given for a rotary engine"),
]


def written_matches_report(tmp_path, body, *options):
    """Run ``counterweight`` with ``--write``; return (the report's JSON entry, the analysis of
    the written file)."""
    path = write(tmp_path, body)
    target = tmp_path / "balanced.toml"
    result = invoke("counterweight", path, *options, "--format", "json", "--write", target)
    assert result.exit_code == 0, result.output
    entry = json.loads(result.output)["engines"][0]
    loaded = balance.load(target)
    return entry, balance.analyse(loaded), loaded


def assert_same_orders(records, result, unit):
    """Every order of the loaded engine equals the command's record of it."""
    engine = result.engine
    for record, order in zip(records, result.shaking.orders, strict=True):
        got = order.to_dict(engine.noise_floor_n, engine.noise_floor_nm, engine.vertical_axis_rad)
        for part, key in (("force", "N"), ("moment", "Nm")):
            for which in ("forward", "backward"):
                assert_allclose(
                    got[part][f"{which}_{key}"],
                    record[part][f"{which}_{key}"],
                    atol=1e-9 * unit * (1 if part == "force" else D),
                )


def test_cross_plane_v8_end_web_counterweights_cancel_the_forward_primary():
    """The classic answer (derivation above): after the two end-web counterweights the forward
    first-order force and couple are zero; the backward first order and every other order are
    as they were (a mass turning with the crank has only a forward first order)."""
    bare = balance.analyse(balance.loads(V8, "v8.toml"))
    built = balance.analyse(balance.loads(V8 + V8_WEIGHTS, "v8.toml"))
    unit = (M + ROT) * R * W**2
    before, after = bare.order(1), built.order(1)
    # the hand couple first, so that the cancellation is of the right thing
    assert_allclose(before.moment_forward, unit * D * (-3 - 1j), rtol=1e-12)
    assert_allclose(abs(after.force_forward), 0.0, atol=CANCEL * unit)
    assert_allclose(abs(after.moment_forward), 0.0, atol=CANCEL * unit * D)
    assert_allclose(after.force_backward, before.force_backward, atol=SAME * unit)
    assert_allclose(after.moment_backward, before.moment_backward, atol=SAME * unit * D)
    for k in range(2, 9):
        assert_allclose(built.order(k).force_forward, bare.order(k).force_forward, atol=SAME * unit)
        assert_allclose(
            built.order(k).force_backward, bare.order(k).force_backward, atol=SAME * unit
        )
        assert_allclose(
            built.order(k).moment_forward, bare.order(k).moment_forward, atol=SAME * unit * D
        )


def test_counterweight_command_proposes_nothing_more_for_the_balanced_v8(tmp_path):
    """With the ideal counterweights built, the counterweights to add are zero, and the report
    says what the built ones leave (no first order) before anything else."""
    path = write(tmp_path, V8 + V8_WEIGHTS)
    result = invoke("counterweight", path, "--format", "json")
    assert result.exit_code == 0, result.output
    entry = json.loads(result.output)["engines"][0]
    assert [w["mass_kg"] for w in entry["counterweights"]] == [0.0, 0.0]
    first = entry["as_built"]["orders"][0]
    assert first["force"]["forward_N"] == 0.0 and first["moment"]["forward_Nm"] == 0.0
    built = entry["as_built"]["counterweights"]
    assert [w["throw"] for w in built] == [1, 4]
    assert_allclose([w["mass_radius_kgm"] for w in built], [V8_MR, V8_MR], rtol=1e-12)
    assert_allclose(built[1]["mass_kg"], V8_MR / 0.05, rtol=1e-12)
    text = invoke("counterweight", path)
    assert text.exit_code == 0, text.output
    assert "As built: 2 counterweights and 0 balancer shafts" in text.output
    assert "in addition to them" in text.output


def test_a_counterweight_loads_the_main_bearings_not_the_pins():
    """A counterweight is part of the crankshaft: its inertia force m·ρ·ω²·e^{i(θ+φ)} (φ its
    direction from throw 1's pin, throw 1 at phase 0) adds that much to the forward first
    order of the crankshaft's force on its main bearings, and nothing to any crank pin."""
    mr, phi = 0.01, math.radians(150.0)
    text = V8.replace('rotating = "300 g"', 'rotating = "300 g"\ncrank = "200 g"')
    bare = balance.loads(text)
    built = bare.replace(counterweights=(CounterweightMass(1, mr, phi, radius_m=0.04),))
    plain, weighted = balance.torque(bare), balance.torque(built)
    added = weighted.main_bearings.order(1)[0] - plain.main_bearings.order(1)[0]
    assert_allclose(added, mr * W**2 * np.exp(1j * phi), rtol=1e-9)
    for a, b in zip(plain.pins, weighted.pins, strict=True):
        assert_allclose(b.force_n, a.force_n, atol=SAME * M * R * W**2 * 8)
    # a mass turning at constant radius and speed: no inertia or tilting torque
    assert_allclose(weighted.frame.curve, plain.frame.curve, atol=1e-9 * M * R**2 * W**2 * 8)


def test_mass_rows_follow_the_pins_with_their_owner_codes():
    """MassSet conventions: counterweights (owner −2, throw = their throw) and balancer masses
    (owner −3, throw −1) come after the crank-pin rows; a counterweight sits at its radius in
    the direction of its pin turned by its angle (throw 2, phase 90°, 30° on: 120° at θ = 0)."""
    engine = balance.loads(V8 + V8_WEIGHTS).replace(
        crank_kg=0.1,
        counterweights=(CounterweightMass(2, 0.02, math.radians(30.0), radius_m=0.05),),
        balancer_shafts=(BalancerShaftSpec(-2, (BalancerMass(0.01, 0.0, eccentricity_m=0.02),)),),
    )
    masses = linkage_state(engine, engine_angles(64)).masses
    owners = list(masses.cylinder)
    assert owners[-2:] == [COUNTERWEIGHT, BALANCER]
    assert owners.index(COUNTERWEIGHT) > max(i for i, o in enumerate(owners) if o == CRANK)
    assert list(masses.throw_index[-2:]) == [1, -1]
    assert_allclose(masses.positions[-2, 0], 0.05 * np.exp(1j * math.radians(120.0)), rtol=1e-12)
    assert_allclose(masses.masses_kg[-2:], [0.02 / 0.05, 0.01 / 0.02], rtol=1e-12)
    # a backward shaft turns against the crank: at θ = 90° its mass is at −180°
    quarter = masses.positions[-1, 16]
    assert_allclose(quarter, 0.02 * np.exp(-1j * math.pi), atol=1e-15)


def test_lanchester_pair_cancels_the_inline_four_secondary_force_exactly():
    """In-line 4 on a flat crank: the four pistons' second orders add in phase (2β = 0 mod 360°
    for β = 0, 180°), a force 4·m·r·ω²·B₂·cos 2θ along the cylinder axis (B₂ the exact
    slider-crank harmonic, conftest.exact_b; ≈ λ), with no couple (mirror-symmetric crank).
    A shaft mass m·e at ±2ω, at 180° in its own sense, is at e·e^{±i(2θ+π)}: the pair's force is
    m·e·(2ω)²·(−e^{i2θ} − e^{−i2θ}) = −8·m·e·ω²·cos 2θ. It cancels the engine's when
    8·m·e·ω² = 4·m·r·ω²·B₂: m·e = m·r·B₂/2 per shaft, m·r·B₂ for the pair (the total
    4·m·r·ω²·B₂ / (2ω)²). Every other order is untouched, and the main bearings do not feel
    the shafts (they run in their own bearings)."""
    b2 = exact_b(R / L, 2)
    per_shaft = M * R * b2 / 2
    bare = balance.loads(I4)
    built = balance.loads(I4 + lanchester(per_shaft))
    second = 4 * M * R * W**2 * b2
    before, after = balance.analyse(bare).order(2), balance.analyse(built).order(2)
    assert_allclose(before.force_forward + before.force_backward, second, rtol=1e-9)
    assert_allclose(
        [abs(after.force_forward), abs(after.force_backward)], [0, 0], atol=CANCEL * second
    )
    assert_allclose(
        [abs(after.moment_forward), abs(after.moment_backward)], [0, 0], atol=CANCEL * second * D
    )
    for k in (1, 3, 4, 6):
        assert_allclose(
            balance.analyse(built).order(k).force_backward,
            balance.analyse(bare).order(k).force_backward,
            atol=SAME * second,
        )
    plain, shafted = balance.torque(bare), balance.torque(built)
    assert_allclose(shafted.main_bearings.force_n, plain.main_bearings.force_n, atol=SAME * second)
    # centred shafts: no rolling moment, so the frame torque is the engine's own
    assert_allclose(shafted.frame.curve, plain.frame.curve, atol=1e-9 * second * R)


def test_counterweight_command_leaves_the_lanchester_engine_alone(tmp_path):
    """Asked for second-order shafts, it finds none needed: the pair as built already cancels
    that order (proposals are additions)."""
    path = write(tmp_path, I4 + lanchester(M * R * exact_b(R / L, 2) / 2))
    result = invoke("counterweight", path, "--shafts", "2", "--format", "json")
    assert result.exit_code == 0, result.output
    entry = json.loads(result.output)["engines"][0]
    assert entry["balancer_shafts"] == []
    assert [s["speed_ratio"] for s in entry["as_built"]["balancer_shafts"]] == [2, -2]
    assert entry["as_built"]["orders"][1]["force"]["max_N"] == 0.0


def test_offset_shaft_rolling_moment_by_hand(tmp_path):
    """One shaft at +2ω with a mass m·e at α (at θ = 0), its axis at lateral offset a from the
    crank axis (lateral: 90° on from the vertical, the cylinder axis at 0°, so x = i·a).
    Its force is F(θ) = m·e·(2ω)²·e^{i(2θ+α)}, and the moment of that force, acting at x, about
    the crank axis is x × F = Im(x̄·F) = Im(−i·a·F) = −a·Re F = −4·a·m·e·ω²·cos(2θ + α)
    = c·cos 2θ + s·sin 2θ with c = −4·a·m·e·ω²·cos α, s = 4·a·m·e·ω²·sin α.
    The frame torque of ``balance torque`` changes by exactly that (its tilting couple −dH/dt
    picks it up; the inertia torque does not change), and
    ``counterweight.rolling_moment_phasor`` gives the same phasor."""
    me, alpha, a = 0.004, math.radians(30.0), 0.12
    text = I4 + textwrap.dedent(f"""\

        [[shafts]]
        ratio = 2
        lateral = "{a * 1e3:g} mm"

        [[shafts.masses]]
        mass_radius = "{me!r} kg*m"
        angle = 30
    """)
    c, s = -4 * a * me * W**2 * math.cos(alpha), 4 * a * me * W**2 * math.sin(alpha)
    scale = 4 * a * me * W**2
    bare, built = balance.loads(I4), balance.loads(text, "shaft.toml")
    plain, shafted = balance.torque(bare), balance.torque(built)
    frame = np.subtract(shafted.frame.order(2), plain.frame.order(2))
    assert_allclose(frame, [c, s], atol=1e-9 * scale)
    assert_allclose(
        np.subtract(shafted.inertia.order(2), plain.inertia.order(2)), [0, 0], atol=1e-9 * scale
    )
    phasor = rolling_moment_phasor(1j * a, me * 4 * W**2 * np.exp(1j * alpha), 2)
    assert_allclose([phasor.real, -phasor.imag], [c, s], atol=1e-12 * scale)
    moment = built_shafts(built)[0].rolling_moment
    assert_allclose([moment.cos_nm, moment.sin_nm], [c, s], atol=1e-12 * scale)
    # the same through the command line: the frame torque's JSON, with and without the shaft
    for_cli = []
    for name, body in (("bare.toml", I4), ("shaft.toml", text)):
        result = invoke("torque", write(tmp_path, body, name), "--format", "json")
        assert result.exit_code == 0, result.output
        orders = json.loads(result.output)["engines"][0]["frame"]["orders"]
        for_cli.append(next((o["cos_Nm"], o["sin_Nm"]) for o in orders if o["order"] == 2))
    assert_allclose(np.subtract(for_cli[1], for_cli[0]), [c, s], atol=1e-9 * scale)


@pytest.mark.parametrize("text, key, words", BAD)
def test_bad_as_built_tables_get_one_clear_message(tmp_path, text, key, words):
    """Each mistake names the file and the key, says what to do, exits 1 without a traceback
    and writes no output file."""
    if text.startswith("frame"):
        body = V8.replace("cycle = 4", text.split("\n")[0] + "\ncycle = 4") + text.split("\n", 1)[1]
    else:
        body = V8 + text
    path = write(tmp_path, body)
    out = tmp_path / "out.json"
    result = invoke("compare", path, "--output", out)
    assert result.exit_code == 1, result.output
    assert isinstance(result.exception, SystemExit)
    assert f"{path}: {key}: " in result.output and words in result.output, result.output
    assert len(result.output.strip().splitlines()) == 1
    assert not out.exists()


def test_library_model_errors_name_the_field():
    """Built in code, the model checks as the reader does and names its own fields."""
    engine = balance.loads(V8)
    with pytest.raises(
        balance.ModelError, match=r"counterweight 1 is on throw 9, but the engine has throws 1 to 4"
    ) as caught:
        engine.replace(counterweights=(CounterweightMass(9, 0.01, 0.0),))
    assert caught.value.parameter == "counterweights"
    with pytest.raises(balance.ModelError) as caught:
        BalancerShaftSpec(0, (BalancerMass(0.01, 0.0),))
    assert caught.value.parameter == "ratio"
    with pytest.raises(balance.ModelError) as caught:
        CounterweightMass(1, -0.01, 0.0)
    assert caught.value.parameter == "mass_radius_kgm"
    rotary = balance.load(CONFIGS / "clerget-rotary.toml")
    with pytest.raises(balance.ModelError, match="rotary") as caught:
        rotary.replace(counterweights=(CounterweightMass(1, 0.01, 0.0),))
    assert caught.value.parameter == "counterweights"


def test_unbalance_units():
    """kg·m in the spellings a drawing uses: 0.072 kg·m = 72 kg·mm = 72 000 g·mm."""
    from balance_cli.units import parse_quantity

    for text in ("0.072 kg*m", "72 kg·mm", "7.2 kg.cm", "72000 g mm", "72 g*m"):
        assert_allclose(parse_quantity(text, "unbalance"), 0.072, rtol=1e-12)


def test_write_round_trip_of_the_ideal_v8_counterweights(tmp_path):
    """The cross-plane V8 without counterweights: the two proposed ones, written back and read
    again, leave what the command reported, with no forward first order; and their size is the
    hand answer m·ρ = (m + ROT)·r·√10/3 at 198.43° and 18.43° from throw 1's pin."""
    entry, result, loaded = written_matches_report(tmp_path, V8, "--radius", "50 mm")
    unit = (M + ROT) * R * W**2
    assert_same_orders(entry["residual"]["orders"], result, unit)
    assert abs(result.order(1).force_forward) < CANCEL * unit
    assert abs(result.order(1).moment_forward) < CANCEL * unit * D
    weights = loaded.counterweights
    assert [w.throw for w in weights] == [1, 4]
    assert_allclose([w.mass_radius_kgm for w in weights], [V8_MR, V8_MR], rtol=1e-9)
    assert_allclose([w.radius_m for w in weights], [0.05, 0.05])
    # measured from their own pins: 198.43° from throw 1's, −161.57° from throw 4's
    assert_allclose(
        [
            math.remainder(math.degrees(w.angle_rad) - a, 360)
            for w, a in zip(weights, (180 + ALPHA_DEG, ALPHA_DEG - 180), strict=True)
        ],
        [0, 0],
        atol=1e-9,
    )
    # run again on the written file: nothing more to add
    again = invoke("counterweight", tmp_path / "balanced.toml", "--format", "json")
    assert [w["mass_kg"] for w in json.loads(again.output)["engines"][0]["counterweights"]] == [
        0.0,
        0.0,
    ]


def test_write_round_trip_adds_to_what_is_built(tmp_path):
    """A half-sized front counterweight as built, planes off the throws, a balance factor and
    shafts: the written file keeps the built one, adds the proposal, and leaves exactly what was
    reported (the residual after the counterweights, then after the shafts)."""
    body = I4 + ONE_WEIGHT.replace('"1 kg"', '"0.2 kg"')
    entry, result, loaded = written_matches_report(
        tmp_path,
        body,
        "--planes",
        "20 mm,280 mm",
        "--shafts",
        "2,4",
        "--shaft-offset",
        "2:100 mm,-50 mm",
    )
    unit = M * R * W**2
    assert_same_orders(entry["after_shafts"]["orders"], result, unit)
    assert len(loaded.counterweights) == 3
    assert_allclose(loaded.counterweights[0].mass_radius_kgm, 0.2 * 0.04, rtol=1e-12)
    assert sorted(s.ratio for s in loaded.balancer_shafts) == [-4, -2, 2, 4]
    placed = next(s for s in loaded.balancer_shafts if s.ratio == 2)
    assert (placed.lateral_m, placed.vertical_m) == (0.1, -0.05)
    for k in (1, 2, 4):
        assert abs(result.order(k).force_forward) < CANCEL * 4 * unit
        assert abs(result.order(k).force_backward) < CANCEL * 4 * unit
    # the written shaft's rolling moment is the one reported for the proposal
    reported = next(s for s in entry["balancer_shafts"] if s["speed_ratio"] == 2)
    rebuilt = next(s for s in built_shafts(loaded) if s.speed_ratio == 2)
    assert_allclose(
        [rebuilt.rolling_moment.cos_nm, rebuilt.rolling_moment.sin_nm],
        [reported["rolling_moment"]["cos_Nm"], reported["rolling_moment"]["sin_Nm"]],
        rtol=1e-9,
        atol=1e-9 * unit * 0.1,
    )


def test_balance_factor_counts_the_built_counterweights(tmp_path):
    """With a balance factor, the counterweights as built count towards the target: the file
    written with the proposal, balanced again with the same factor, needs nothing more."""
    body = I4 + ONE_WEIGHT
    entry, result, loaded = written_matches_report(tmp_path, body, "--balance-factor", "0.5")
    assert_same_orders(entry["residual"]["orders"], result, M * R * W**2)
    again = invoke(
        "counterweight", tmp_path / "balanced.toml", "--balance-factor", "0.5", "--format", "json"
    )
    assert again.exit_code == 0, again.output
    weights = json.loads(again.output)["engines"][0]["counterweights"]
    assert_allclose([w["mass_kg"] for w in weights], [0, 0], atol=1e-12)


TWIN_180 = textwrap.dedent("""\
    name = "180° twin"
    cycle = 4
    speed = "8000 rpm"
    crank_radius = "30 mm"
    rod_length = "110 mm"
    firing_order = [1, 2]

    [masses]
    reciprocating = "0.45 kg"

    [[banks]]
    angle = 0

    [[throws]]
    phase = 0
    z = "0 mm"
    [[throws]]
    phase = 180
    z = "93 mm"
""")


def test_written_file_has_its_own_name_and_the_figures_to_twelve_digits(tmp_path):
    """A 180° twin with reciprocating masses only (0.45 kg, r = 30 mm, d = 93 mm). By hand:
    each cylinder's forward first order is m·r·ω²/2 turning with its own pin, so a
    counterweight on each throw's plane of m/2 = 0.225 kg at crank radius, 180° from its
    pin, cancels the forward first-order force and couple. The analysis computes
    0.22499999999999998 kg; the file says 0.225 kg (twelve significant digits), under the
    name "180° twin, balanced", so compare takes it beside the original. Read back, each
    mass is within half a unit of the twelfth digit (5e-12) of the analysed one, and the
    forward first order it leaves within 1e-11 of the m/2·r·ω² each weight cancels (two
    such roundings) of zero."""
    entry, result, loaded = written_matches_report(tmp_path, TWIN_180)
    target = tmp_path / "balanced.toml"
    text = target.read_text(encoding="utf-8")
    assert text.count('mass = "0.225 kg"') == 2 and "0.22499999" not in text
    assert loaded.name == "180° twin, balanced"
    analysed = [w["mass_kg"] for w in entry["counterweights"]]
    assert_allclose(analysed, [0.225, 0.225], rtol=1e-12)  # the hand answer
    assert_allclose(
        [w.mass_radius_kgm / w.radius_m for w in loaded.counterweights], analysed, rtol=5e-12
    )
    cancelled = 0.225 * 0.03 * (8000 * math.pi / 30) ** 2
    assert abs(result.order(1).force_forward) <= 1e-11 * cancelled
    assert abs(result.order(1).moment_forward) <= 1e-11 * cancelled * 0.093
    both = invoke("compare", tmp_path / "engine.toml", target, "--format", "json")
    assert both.exit_code == 0, both.output
    names = [e["name"] for e in json.loads(both.output)["engines"]]
    assert names == ["180° twin", "180° twin, balanced"]


@pytest.mark.parametrize(
    "extra, words",
    [
        (("--antivibrateur",), "antivibrateur"),
        (("--output", "SAME"), "needs a file of its own"),
    ],
)
def test_write_refusals_leave_no_file(tmp_path, extra, words):
    path = write(tmp_path, V8)
    target = tmp_path / "out.toml"
    extra = tuple(str(target) if e == "SAME" else e for e in extra)
    result = invoke("counterweight", path, "--write", target, *extra)
    assert result.exit_code != 0 and words in result.output, result.output
    assert not target.exists()


def test_write_takes_one_file(tmp_path):
    first, second = write(tmp_path, V8, "a.toml"), write(tmp_path, I4, "b.toml")
    target = tmp_path / "out.toml"
    result = invoke("counterweight", first, second, "--write", target)
    assert result.exit_code != 0 and "writes one configuration" in result.output
    assert not target.exists()


def test_write_refuses_to_replace_its_input(tmp_path):
    path = write(tmp_path, V8)
    result = invoke("counterweight", path, "--write", path)
    assert result.exit_code != 0
    assert path.read_text(encoding="utf-8") == V8


def test_show_lists_what_is_built(tmp_path):
    path = write(tmp_path, I4 + ONE_WEIGHT + ONE_SHAFT)
    result = invoke("show", path)
    assert result.exit_code == 0, result.output
    assert "counterweight: throw 1, m·ρ 0.04000 kg·m at 180° from its pin" in result.output
    assert "shaft:         ratio +2" in result.output


def test_search_refuses_a_template_with_counterweights(tmp_path):
    """A counterweight is sized for one crank; the search chooses the crank: refused, naming
    the tables to remove."""
    template = "\n".join(
        line for line in I4.splitlines() if not line.startswith(("phase", "firing_order"))
    )
    path = write(tmp_path, template + "\n" + ONE_WEIGHT)
    result = invoke("search", path)
    assert result.exit_code == 1
    assert "remove the [[counterweights]] and [[shafts]] tables from the template" in result.output


def test_sweep_turns_a_built_counterweight(tmp_path):
    """Sweeping the rear end-web counterweight's angle (derivation above). At its right angle
    (−161.57° from throw 4's pin) the forward primary force and couple are gone. Turned half a
    turn, it equals the front one, c₁: the pair makes a force 2·c₁ and no couple about z̄ (they
    sit at ∓1.5·d from it), so the engine's own couple √10·(m + ROT)·r·ω²·d is back and the
    first-order force is 2·|c₁| = 2·(m + ROT)·r·ω²·√10/3."""
    path = write(tmp_path, V8 + V8_WEIGHTS)
    right = ALPHA_DEG - 180
    result = invoke(
        "sweep",
        path,
        "--vary",
        "counterweights[2].angle",
        "--values",
        f"{right!r},{right + 180!r}",
        "--quantity",
        "F1,M1",
        "--format",
        "json",
    )
    assert result.exit_code == 0, result.output
    points = json.loads(result.output)["points"]
    unit = (M + ROT) * R * W**2
    assert_allclose(
        [p["F1_N"] for p in points],
        [0.0, 2 * unit * math.sqrt(10) / 3],
        rtol=1e-9,
        atol=CANCEL * unit,
    )
    assert_allclose(
        [p["M1_Nm"] for p in points],
        [0.0, math.sqrt(10) * unit * D],
        rtol=1e-9,
        atol=CANCEL * unit * D,
    )


def test_backward_shaft_above_the_crank_rolls_the_engine_by_hand():
    """A shaft at −2ω, its axis at v along the vertical (the cylinder axis, 0°: x = v), one mass
    m·e at α in its own sense (against the crank): at e·e^{−i(2θ+α)}, force
    F = m·e·(2ω)²·e^{−i(2θ+α)}. Rolling moment Im(x̄·F) = v·Im F = −4·v·m·e·ω²·sin(2θ + α)
    = c·cos 2θ + s·sin 2θ with c = −4·v·m·e·ω²·sin α, s = −4·v·m·e·ω²·cos α."""
    me, alpha, v = 0.003, math.radians(40.0), -0.08
    engine = balance.loads(I4).replace(
        balancer_shafts=(BalancerShaftSpec(-2, (BalancerMass(me, alpha),), vertical_m=v),)
    )
    scale = 4 * abs(v) * me * W**2
    expected = [
        -scale * math.copysign(1, v) * math.sin(alpha),
        -scale * math.copysign(1, v) * math.cos(alpha),
    ]
    frame = np.subtract(
        balance.torque(engine).frame.order(2), balance.torque(balance.loads(I4)).frame.order(2)
    )
    assert_allclose(frame, expected, atol=1e-9 * scale)
    moment = built_shafts(engine)[0].rolling_moment
    assert_allclose([moment.cos_nm, moment.sin_nm], expected, atol=1e-12 * scale)


def test_reduced_mass_counts_known_radii_only():
    """μ = Σ m·|dx/dθ|²: a counterweight of mass m at radius ρ turning with the crank adds
    m·ρ² (|dx/dθ| = ρ), a balancer mass at e on a ratio-k shaft m·e²·k² (|dx/dθ| = k·e). Given
    as m·ρ alone the radius is unknown and so is that inertia: it is left out (at most 1e-6 of
    m·ρ·k², in kg·m²: the unbalance sits at a vanishing radius of 1 µm)."""
    bare = balance.loads(I4)
    mean = balance.torque(bare, bearings=False).reduced_mass.mean_kgm2
    known = bare.replace(
        counterweights=(CounterweightMass(1, 0.02, math.pi, radius_m=0.05),),
        balancer_shafts=(BalancerShaftSpec(-2, (BalancerMass(0.01, 0.0, eccentricity_m=0.02),)),),
    )
    added = balance.torque(known, bearings=False).reduced_mass.mean_kgm2 - mean
    assert_allclose(added, 0.02 * 0.05 + 0.01 * 0.02 * 4, rtol=1e-9)
    unknown = bare.replace(
        counterweights=(CounterweightMass(1, 0.02, math.pi),),
        balancer_shafts=(BalancerShaftSpec(-2, (BalancerMass(0.01, 0.0),)),),
    )
    added = balance.torque(unknown, bearings=False).reduced_mass.mean_kgm2 - mean
    assert 0 <= added <= 1.001e-6 * (0.02 + 0.01 * 4)


def test_write_refuses_a_rotary(tmp_path):
    """A rotary's counterweights ride on its turning crankcase, which [[counterweights]] does
    not describe: nothing is written, rather than a file that cannot be loaded."""
    target = tmp_path / "out.toml"
    result = invoke("counterweight", CONFIGS / "clerget-rotary.toml", "--write", target)
    assert result.exit_code == 1 and "rotary" in result.output, result.output
    assert len(result.output.strip().splitlines()) == 1
    assert not target.exists()


@pytest.mark.parametrize("direction", [1, -1])
def test_a_counterweight_turns_with_its_own_crankshaft(direction):
    """Two crankshafts (the second at x = 1 m, turning with or against the first, the opposed
    single of tests/analysis/test_crankshafts.py). A counterweight of unbalance m·ρ at angle α
    on throw 2 (phase β = 180° on crankshaft 2) sits at direction·(θ + β + α) about that
    crankshaft's axis: its inertia force m·ρ·ω²·e^{i·direction·(θ + β + α)} is a forward first
    order of m·ρ·ω²·e^{i(β+α)} when the shaft turns with the first, a backward one of
    m·ρ·ω²·e^{−i(β+α)} against it; it loads crankshaft 2's main bearings by that much and
    crankshaft 1's not at all."""
    from tests.support import OPPOSED_OMEGA as OMEGA, opposed_single  # noqa: I001

    me, alpha, beta = 0.05, math.radians(30.0), math.pi
    bare = opposed_single(0.0, direction)
    built = bare.replace(counterweights=(CounterweightMass(2, me, alpha, radius_m=0.06),))
    expected = me * OMEGA**2 * np.exp(1j * (beta + alpha) * direction)
    before, after = balance.analyse(bare).order(1), balance.analyse(built).order(1)
    added = (
        after.force_forward - before.force_forward
        if direction == 1
        else after.force_backward - before.force_backward
    )
    other = (
        after.force_backward - before.force_backward
        if direction == 1
        else after.force_forward - before.force_forward
    )
    assert_allclose(added, expected, rtol=1e-9)
    assert abs(other) < 1e-9 * abs(expected)
    plain, weighted = balance.torque(bare), balance.torque(built)
    first = [np.asarray(t.crankshafts[0].main_bearings.force_n) for t in (plain, weighted)]
    second = [t.crankshafts[1].main_bearings for t in (plain, weighted)]
    assert_allclose(first[1], first[0], atol=1e-9 * abs(expected))
    part = 0 if direction == 1 else 1  # PinForce.order gives (forward, backward)
    change = second[1].order(1)[part] - second[0].order(1)[part]
    assert_allclose(change, expected, rtol=1e-9)


def test_the_shipped_lanchester_engine_cancels_its_secondary_force_and_frame_torque():
    """configs/inline-4-car-lanchester.toml: the car in-line 4 with m·e = 3.6397 kg·mm on a +2
    shaft at h₊ = 70 mm above the crank axis and a −2 shaft at h₋ = −69.8 mm, both masses at
    180° in their own sense. Each shaft's force is P = 4·m·e·ω² along the vertical at its
    height: the +2 one −P·e^{i2θ}, the −2 one −P·e^{−i2θ}; their rolling moments Im(x̄·F) are
    −P·h₊·sin 2θ and +P·h₋·sin 2θ, together −P·(h₊ − h₋)·sin 2θ: the frame torque's change.
    Their forces add to −2P·cos 2θ against the engine's 4·m·r·ω²·B₂·cos 2θ (m·e rounded to
    5 figures: the force is left at 1e-4 of itself, and so is the frame torque's order 2)."""
    me, h_plus, h_minus = 3.6397e-3, 0.070, -0.0698
    car = balance.load(CONFIGS / "inline-4-car.toml")
    balanced = balance.load(CONFIGS / "inline-4-car-lanchester.toml")
    omega = car.speed_rad_s
    p = 4 * me * omega**2
    change = np.subtract(
        balance.torque(balanced).frame.order(2), balance.torque(car).frame.order(2)
    )
    assert_allclose(change, [0.0, -p * (h_plus - h_minus)], atol=1e-9 * p * 0.14)
    second = 4 * 0.55 * 0.043 * omega**2 * exact_b(43 / 143, 2)
    left = balance.analyse(balanced).order(2)
    assert abs(left.force_forward) + abs(left.force_backward) < 1e-4 * second
    frame_left = math.hypot(*balance.torque(balanced).frame.order(2))
    assert frame_left < 1e-3 * p * (h_plus - h_minus)


def test_star_shares_name_the_counterweights_and_shafts():
    """The star's shares: the built counterweights and shaft masses are their own arrows
    ("counterweights", "shafts"), and all shares still add up to the engine's phasors (the
    second order: the pair's −2·P·cos 2θ against the engine's 4·m·r·ω²·B₂·cos 2θ)."""
    result = balance.analyse(balance.load(CONFIGS / "inline-4-car-lanchester.toml"))
    shares = result.shaking.cylinder_phasors(2)
    labels = [label for label, _, _ in shares]
    assert labels == ["1", "2", "3", "4", "pins", "shafts"]
    order = result.order(2)
    assert_allclose(sum(f for _, f, _ in shares), order.force_forward, atol=1e-9 * 11495)
    assert_allclose(sum(b for _, _, b in shares), order.force_backward, atol=1e-9 * 11495)
    shafts = dict((label, (f, b)) for label, f, b in shares)["shafts"]
    p = 4 * 3.6397e-3 * result.engine.speed_rad_s**2
    assert_allclose(shafts, [-p, -p], rtol=1e-12)
    weighted = balance.analyse(balance.loads(V8 + V8_WEIGHTS))
    assert "counterweights" in [label for label, _, _ in weighted.shaking.cylinder_phasors(1)]


def test_a_built_shaft_at_crank_speed_counts_towards_the_balance_factor():
    """A shaft turning with the crank at its speed (ratio +1) makes a forward first order as a
    counterweight does: a single cylinder (0.6 kg reciprocating, 0.3 kg rotating, r = 45 mm)
    whose built +1 shaft carries 13.5 kg·mm (0.3 kg at the crank radius) opposite the pin needs,
    for a balance factor 0.5 (0.3 + 0.5·0.6 = 0.6 kg at r), only 0.3 kg more."""
    engine = balance.loads(
        textwrap.dedent("""
        name = "one with a primary shaft"
        cycle = 4
        speed = "3000 rpm"
        crank_radius = "45 mm"
        rod_length = "150 mm"
        [masses]
        reciprocating = "0.6 kg"
        rotating = "0.3 kg"
        [[banks]]
        angle = 0
        [[throws]]
        phase = 0
        [[shafts]]
        ratio = 1
        [[shafts.masses]]
        mass_radius = "13.5 kg*mm"
        angle = 180
        """)
    )
    result = balance.counterweights(engine, planes=[1], balance_factor=0.5)
    assert_allclose(sum(c.mass_kg for c in result.counterweights), 0.3, rtol=1e-9)


def test_the_text_gives_the_built_shafts_rolling_moment(tmp_path):
    """An in-line 4 with a built −2 shaft 30 mm lateral, 60 mm below the crank: its force
    m·e·(2ω)² (0.001 kg·m at 3000 rpm: 394.8 N) at the offset c rolls the engine by |c × F| up
    to |c|·F = 0.0671 m·394.8 N = 26.5 N·m; the text says so beside the built shaft, and that
    the proposed shafts (none offset) roll nothing."""
    path = tmp_path / "four.toml"
    path.write_text(
        textwrap.dedent("""
        name = "four with a shaft"
        cycle = 4
        speed = "3000 rpm"
        crank_radius = "40 mm"
        rod_length = "140 mm"
        [masses]
        reciprocating = "0.5 kg"
        [[banks]]
        angle = 0
        [[throws]]
        phase = 0
        [[throws]]
        phase = 180
        z = "90 mm"
        [[throws]]
        phase = 180
        z = "180 mm"
        [[throws]]
        phase = 0
        z = "270 mm"
        [[shafts]]
        ratio = -2
        lateral = "30 mm"
        vertical = "-60 mm"
        [[shafts.masses]]
        mass_radius = "0.001 kg*m"
        angle = 33
        """)
    )
    result = invoke("counterweight", path, "--shafts", "2")
    assert result.exit_code == 0, result.output
    assert "Rolling moment about the crank axis of the shafts as built" in result.output
    force = 0.001 * (2 * 3000 * math.pi / 30) ** 2
    record = balance.counterweights(balance.load(path)).to_dict()
    rolling = record["as_built"]["balancer_shafts"][0]["rolling_moment"]["amplitude_Nm"]
    # a rotating force at a fixed offset: the moment's amplitude is |c|·|F|
    assert_allclose(rolling, math.hypot(0.03, 0.06) * force, rtol=1e-9)
    assert "Rolling moment about the crank axis of the proposed shafts: none" in result.output
