"""Several crankshafts, opposed pistons and per-bank/per-cylinder pin offsets, each against a
hand derivation or a second, independent computation written here."""

import math
import textwrap

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.analysis.firing import firing_sequence
from balance_cli.errors import ConfigError
from balance_cli.kinematics import tdc_angles
from tests.support import JUMO, VR6, opposed_single
from tests.support import OPPOSED_L as L
from tests.support import OPPOSED_M as M
from tests.support import OPPOSED_OMEGA as OMEGA
from tests.support import OPPOSED_R as R
from tests.support import OPPOSED_RPM as RPM


def travel_harmonic(k, r=R, rod=L, n=4096):
    """a_k of one piston's travel s(θ) = r·cos θ + √(l² − r²·sin²θ) = Σ a_k cos kθ, by the
    trapezoidal rule on the closed form (spectrally exact for a smooth periodic function): a
    method independent of balance's linkage and Fourier engine."""
    theta = 2 * np.pi * np.arange(n) / n
    s = r * np.cos(theta) + np.sqrt(rod**2 - (r * np.sin(theta)) ** 2)
    return 2 * np.mean(s * np.cos(k * theta))


GAS = '[gas]\nbore = "105 mm"\ncompression_ratio = 17\nimep = "8 bar"'


def flat8_pair(gear_phase_deg, direction, crank=(0, 180, 0, 180), pitch=0.1):
    """Two flat-8s (180° V with two rods a pin, four throws), one above the other, geared 1:1."""
    throws = "\n".join(f'[[throws]]\nphase = {p}\nz = "{i * pitch} m"' for i, p in enumerate(crank))
    throws += "\n" + "\n".join(
        f'[[throws]]\nphase = {p}\nz = "{i * pitch} m"\ncrankshaft = 2' for i, p in enumerate(crank)
    )
    return balance.loads(
        textwrap.dedent(f"""
        name = "H16"
        cycle = 4
        speed = "{RPM} rpm"
        crank_radius = "{R * 1000} mm"
        rod_length = "{L * 1000} mm"
        [masses]
        reciprocating = "{M} kg"
        [[banks]]
        angle = 0
        [[banks]]
        angle = 180
        [[crankshafts]]
        [[crankshafts]]
        y = "-250 mm"
        direction = {direction}
        phase = {gear_phase_deg}
        """)
        + throws
        + "\n"
    )


def deltic_by_hand(engine, samples=720):
    """The Deltic's free force and moment phasors of orders 1..8 from a separate computation:
    every piston placed by the slider-crank closed form from its own crankshaft, the crank pins
    by r·e^{i·d·(θ + φ)}, accelerations by central differences of fourth order on a fine grid
    and the phasors by projection: no use of balance's linkage or Fourier engine."""
    theta = 2 * np.pi * np.arange(samples) / samples
    h = theta[1]
    positions, masses, zs = [], [], []
    for c in engine.cylinders:
        for throw_index, turn in ((c.throw_index, 0.0), (c.opposed_throw_index, math.pi)):
            throw = engine.throws[throw_index]
            shaft = engine.crankshafts[throw.crankshaft_index]
            centre = complex(shaft.x_m, shaft.y_m)
            pin = engine.crank_radius_m * np.exp(
                1j * shaft.direction * (theta + shaft.phase_rad + throw.phase_rad)
            )
            axis = np.exp(1j * (engine.bank_angles_rad[c.bank_index] + turn))
            local = pin / axis
            s = local.real + np.sqrt(engine.rod_length_m**2 - local.imag**2)
            positions.append(centre + s * axis)
            masses.append(c.reciprocating_kg)
            zs.append(c.z_m)
            positions.append(centre + pin)  # the big ends at the pin
            masses.append(engine.rotating_kg / 2)  # each throw's rotating mass, per rod
            zs.append(throw.z_m)
    x = np.array(positions)
    acc = (
        (
            -np.roll(x, -2, 1)
            + 16 * np.roll(x, -1, 1)
            - 30 * x
            + 16 * np.roll(x, 1, 1)
            - np.roll(x, 2, 1)
        )
        / (12 * h**2)
        * engine.speed_rad_s**2
    )
    forces = -np.array(masses)[:, None] * acc
    z = np.array(zs)
    zbar = np.mean([c.z_m for c in engine.cylinders])
    force, moment = forces.sum(0), ((z - zbar)[:, None] * forces).sum(0)
    out = []
    for k in range(1, 9):
        fw, bw = np.exp(-1j * k * theta), np.exp(1j * k * theta)
        out.append(
            (np.mean(force * fw), np.mean(force * bw), np.mean(moment * fw), np.mean(moment * bw))
        )
    return out


def one_cylinder(top="", bank="", cylinder=""):
    return balance.loads(
        textwrap.dedent(f"""
        name = "one"
        cycle = 4
        speed = "3000 rpm"
        crank_radius = "40 mm"
        rod_length = "140 mm"
        {top}
        [masses]
        reciprocating = "0.5 kg"
        [[banks]]
        angle = 0
        {bank}
        [[throws]]
        phase = 0
        [[cylinders]]
        number = 1
        bank = 1
        throw = 1
        {cylinder}
        """)
    )


BASE = """
name = "bad"
cycle = 2
speed = "2000 rpm"
crank_radius = "80 mm"
rod_length = "320 mm"
[masses]
reciprocating = "2 kg"
[[banks]]
angle = 0
"""


@pytest.mark.parametrize("direction", [1, -1])
def test_mirror_image_opposed_pistons_leave_no_free_force(direction):
    """Two pistons moved as mirror images (x_B = D − x_A) have accelerations equal and opposite:
    no free force of any order, whichever way the second crankshaft turns (the travel along the
    bore depends on sin²θ only), and no moment (same z)."""
    result = balance.analyse(opposed_single(0.0, direction))
    floor = 1e-9 * M * R * OMEGA**2
    for k in range(1, 9):
        o = result.order(k)
        assert abs(o.force_forward) + abs(o.force_backward) < floor, k
        assert abs(o.moment_forward) + abs(o.moment_backward) < floor, k


@pytest.mark.parametrize("lead", [11.0, 20.0])
def test_an_exhaust_lead_leaves_order_k_residuals_by_hand(lead):
    """With the second piston `lead` later, x_A = s(θ), x_B = D − s(θ − ε): the order-k force
    along the bore is −m·ω²·(k²)·a_k·[cos kθ − cos k(θ − ε)]·(−1), of amplitude
    m·ω²·k²·|a_k|·2·|sin(kε/2)|: a planar force (forward = backward = half) along the bore.
    Odd orders above 1 vanish (the square root has even harmonics only); a_1 = r exactly."""
    result = balance.analyse(opposed_single(lead))
    eps = math.radians(lead)
    assert_allclose(travel_harmonic(1), R, rtol=1e-12)  # the closed form's first harmonic
    for k in range(1, 9):
        expected = M * OMEGA**2 * k**2 * abs(travel_harmonic(k)) * 2 * abs(math.sin(k * eps / 2))
        o = result.order(k)
        # rtol: the trapezoidal rule and the FFT agree to rounding; atol: the noise floor
        assert_allclose(
            abs(o.force_forward) + abs(o.force_backward),
            expected,
            rtol=1e-9,
            atol=1e-9 * M * R * OMEGA**2,
        )
        assert_allclose(
            abs(o.force_forward), abs(o.force_backward), rtol=1e-9, atol=1e-9 * M * R * OMEGA**2
        )
        if expected > 1e-6 * M * R * OMEGA**2:
            # along the bore (the reference axis): the ellipse's axis at 0° (or 180°)
            record = result.to_dict()["orders"][k - 1]["force"]
            assert min(record["axis_deg"] % 180, 180 - record["axis_deg"] % 180) < 1e-6


@pytest.mark.parametrize("lead", [0.0, 12.0])
def test_the_inner_dead_centre_lies_halfway_between_the_pistons_dead_centres(lead):
    """S(θ) = s(θ) + s(θ − ε) is symmetric about θ = ε/2 (where the second piston has reached
    half its lag), so the bore is smallest there: TDC (inner dead centre) at ε/2."""
    tdc = tdc_angles(opposed_single(lead))[1]
    assert_allclose((tdc + 180) % 360 - 180, lead / 2, atol=1e-5)


@pytest.mark.parametrize("lead", [0.0, 11.0])
def test_indicated_power_of_an_opposed_cylinder_by_hand(lead):
    """The bore's volume is A·(D − s(θ) − s(θ − ε)); its swept volume (largest minus smallest)
    keeps only the odd harmonics: 4·a_1·cos(ε/2) = 4r·cos(ε/2) (the even ones are equal at
    θ = ε/2 and ε/2 + π). The cycle is scaled to the imep, so the mean gas torque of a
    two-stroke is imep·V_s/(2π)."""
    engine = opposed_single(lead, gas=GAS)
    result = balance.torque(engine)
    area = math.pi * 0.105**2 / 4
    swept = area * 4 * R * math.cos(math.radians(lead) / 2)
    # rtol: the gas cycle's quadrature at 256 samples (the README's few 1e-4)
    assert_allclose(result.gas.mean, 8e5 * swept / (2 * math.pi), rtol=5e-4)


def test_each_crankshaft_carries_its_own_pistons_torque():
    """Mirror images turning the same way: each crankshaft drives one piston exactly as a
    single-crank engine of that piston does (the second method: balance's one-crankshaft path,
    checked against Tanaka and Margoulis), so each carries half the output, in its own sense;
    and the crankshafts' torques add up to the engine's."""
    engine = opposed_single(0.0, gas=GAS)
    result = balance.torque(engine)
    first, second = result.crankshafts
    assert (first.number, second.number, first.direction) == (1, 2, 1)
    assert_allclose(
        first.torque.curve + second.torque.curve,
        result.total.curve,
        atol=1e-9 * np.abs(result.total.curve).max(),
    )
    # the inertia alone: a plain single cylinder of the same piston
    plain = balance.loads(
        textwrap.dedent(f"""
        name = "plain"
        cycle = 2
        speed = "{RPM} rpm"
        crank_radius = "{R * 1000} mm"
        rod_length = "{L * 1000} mm"
        [masses]
        reciprocating = "{M} kg"
        [[banks]]
        angle = 0
        [[throws]]
        phase = 0
        """)
    )
    inertia_only = balance.torque(opposed_single(0.0))
    reference = balance.torque(plain).inertia.curve
    for shaft in inertia_only.crankshafts:
        assert_allclose(shaft.torque.curve, reference, atol=1e-9 * np.abs(reference).max())
    # with gas, the mirror image splits the output in halves
    assert_allclose(first.torque.mean, second.torque.mean, rtol=1e-9)


def test_the_leading_crankshaft_takes_more_of_the_power():
    """With a lead, the leading (exhaust) piston is pushed outwards while its crank still
    turns towards its outer dead centre over more of the expansion: its crankshaft carries
    more than half the mean torque (about two thirds at 11°, as opposed-piston practice
    reports for the exhaust crankshaft); the sum is the engine's."""
    # the second crank at 180° + lead leads
    engine = opposed_single(-11.0, gas=GAS)
    result = balance.torque(engine)
    first, second = (c.torque.mean for c in result.crankshafts)
    assert second > first > 0
    assert_allclose(first + second, result.total.mean, rtol=1e-9)


@pytest.mark.parametrize("direction", [1, -1])
def test_h16_primary_couples_add_or_cancel_by_the_gear_phase(direction):
    """A flat-8 (180° V, shared pins) with crank 0/180/0/180: both pistons of a pin move with
    +r·cos(θ + φ) in first order (the 180° pair's primaries add, its secondaries cancel), so a
    throw's primary force along the banks is 2·m·r·ω²·cos(θ + φ) and the couple about z̄ = 1.5d
    is 2·m·r·ω²·d·(−1.5 − 0.5·(−1) + 0.5 − 1.5·(−1))·… = −4·m·r·ω²·d·cos θ: planar, forward and
    backward parts 2·m·r·ω²·d each. The second flat-8 at gear phase 0 adds its own (turning
    either way, cos(−(θ+φ)) = cos(θ+φ)): 8·m·r·ω²·d; at 180° it cancels it."""
    d = 0.1
    one = 4 * M * R * OMEGA**2 * d
    for phase, expected in ((0, 2 * one), (180, 0.0)):
        o = balance.analyse(flat8_pair(phase, direction)).order(1)
        assert_allclose(abs(o.moment_forward) + abs(o.moment_backward), expected, atol=1e-9 * one)
        assert abs(o.force_forward) + abs(o.force_backward) < 1e-9 * one / d


def test_the_deltic_lead_closes_round_the_triangle_only_with_one_shaft_reversed():
    """A piston on a crank turning d = ±1 with its pin at d·(θ + P) is at its dead centre when
    the pin points along its bore, g: θ = d·g − P. Round the triangle A → B → C, with each bore's
    exhaust piston on its first crankshaft (bore angle α) and inlet on the next (α + 180°), the
    three leads θ_in − θ_ex add up to terms in which the phases P cancel: with all d = 1,
    3·180° ≡ 180°, so 3ε = 180° (mod 360°) and ε is 60° (or 180°, 300°), never 20°; with A
    turning against B and C the bank terms give 3ε ≡ 60°: ε = 20°, the Deltic's. The library's
    Deltic has that 20° lead in all eighteen bores, its inner dead centres 10° after the exhaust
    pistons' and 20° apart all round."""
    from balance_cli.kinematics.linkage import pin_angle

    engine = balance.load("configs/today/opposed-piston/napier-deltic-d18.toml")
    assert [s.direction for s in engine.crankshafts] == [1, -1, -1]

    def dead_centre(throw, bore_deg):
        d = engine.crankshaft_of(throw).direction
        own = d * math.degrees(pin_angle(engine, throw, 0.0))  # P, in its own sense
        return (d * bore_deg - own) % 360

    tdc = tdc_angles(engine)
    for c in engine.cylinders:
        alpha = math.degrees(engine.bank_angles_rad[c.bank_index])
        exhaust, inlet = (
            dead_centre(c.throw_index, alpha),
            dead_centre(c.opposed_throw_index, alpha + 180),
        )
        assert_allclose((inlet - exhaust) % 360, 20.0, atol=1e-9)
        assert_allclose((tdc[c.number] - exhaust) % 360, 10.0, atol=1e-5)
    assert_allclose(firing_sequence(engine).intervals_deg, [20.0] * 18, atol=1e-5)


def test_the_deltic_free_forces_and_moments_against_a_second_computation():
    """Every crank throw of the Deltic carries two rods (fork and blade): the config's
    rotating mass is both big ends, split here between its two rods. The phasors agree with
    the independent computation to its finite-difference error (h⁴ at 720 samples, about
    1e-8 of the order-8 inertia force, well below a millionth of m·r·ω²)."""
    engine = balance.load("configs/today/opposed-piston/napier-deltic-d18.toml")
    result = balance.analyse(engine)
    unit = engine.mean_reciprocating_kg * engine.crank_radius_m * engine.speed_rad_s**2
    for k, (ff, fb, mf, mb) in enumerate(deltic_by_hand(engine), 1):
        o = result.order(k)
        assert_allclose([o.force_forward, o.force_backward], [ff, fb], atol=1e-6 * unit)
        assert_allclose([o.moment_forward, o.moment_backward], [mf, mb], atol=1e-6 * unit)
    # and the hand statement: no free force of orders 1 to 5 (the three banks at 120° and the
    # eighteen bores 20° apart cancel them), couples left
    for k in range(1, 6):
        o = result.order(k)
        assert abs(o.force_forward) + abs(o.force_backward) < 1e-9 * unit * 18
    assert abs(result.order(1).moment_forward) > 1.0


def test_vr6_offsets_make_the_published_22_degree_split_fire_evenly():
    """A piston of offset e is farthest out when crank and rod are in line, at
    asin(e/(l + r)) from its axis; the two banks (15° apart, offsets ±12.5 mm) then need their
    pins 15° + 2·asin(12.5/209.15) = 21.85° apart for even 120° firing: EngineLabs' 22°."""
    engine = balance.load(VR6)
    delta = math.degrees(math.asin(0.0125 / (0.164 + 0.04515)))
    split = math.degrees(engine.throws[5].phase_rad - engine.throws[0].phase_rad)
    assert_allclose(split, 15 + 2 * delta, atol=1e-4)  # the file's phases, to 4 decimals
    assert abs(split - 22.0) < 0.5  # published to the degree
    assert_allclose(firing_sequence(engine).intervals_deg, [120.0] * 6, atol=2e-4)


def test_vr6_without_its_offsets_fires_unevenly_by_twice_the_offset_angle():
    """Taking the offsets away moves bank 1's dead centres 3.43° one way and bank 2's the other:
    in the order 1-5-3-6-2-4 (bank 1, 1, 1, 2, 2, 2) the intervals from bank 1 to bank 2 and back
    are 120 ∓ 2·asin(e/(l + r)) = 120 ∓ 6.85°."""
    engine = balance.load(VR6)
    plain = engine.replace(
        cylinders=tuple(
            balance.Cylinder(c.number, c.bank, c.throw, c.z_m, c.reciprocating_kg, pin_offset_m=0.0)
            for c in engine.cylinders
        )
    )
    two = 2 * math.degrees(math.asin(0.0125 / (0.164 + 0.04515)))
    assert_allclose(
        firing_sequence(plain).intervals_deg, [120, 120, 120 - two, 120, 120, 120 + two], atol=2e-4
    )


def test_pin_offset_by_engine_bank_or_cylinder_is_one_offset():
    """The global key is the default, a bank's overrides it and a cylinder's overrides both; the
    offset (towards the rotation) puts the dead centre asin(e/(l + r)) after the pin passes the
    axis, where crank and rod are in line."""
    offsets = [
        one_cylinder(top='pin_offset = "5 mm"'),
        one_cylinder(top='pin_offset = "-9 mm"', bank='pin_offset = "5 mm"'),
        one_cylinder(bank='pin_offset = "-9 mm"', cylinder='pin_offset = "5 mm"'),
    ]
    records = [balance.analyse(e).to_dict()["orders"] for e in offsets]
    assert records[0] == records[1] == records[2]
    expected = math.degrees(math.asin(0.005 / 0.18))
    for engine in offsets:
        assert_allclose(tdc_angles(engine)[1], expected, atol=1e-5)


@pytest.mark.parametrize(
    "text, key, words",
    [
        ('[[crankshafts]]\nx = "1 m"\n[[throws]]\nphase = 0\n', "crankshafts[1].x", "reference"),
        (
            '[[crankshafts]]\n[[crankshafts]]\nx = "1 m"\ndirection = 0\n[[throws]]\nphase = 0\n',
            "crankshafts[2].direction",
            "must be 1",
        ),
        (
            '[[crankshafts]]\n[[crankshafts]]\nx = "1 m"\ndirection = 2\n[[throws]]\nphase = 0\n',
            "crankshafts[2].direction",
            "between -1 and 1",
        ),
        ("[[throws]]\nphase = 0\ncrankshaft = 2\n", "throws[1].crankshaft", "between 1 and 1"),
        (
            '[[crankshafts]]\n[[crankshafts]]\nx = "1 m"\n[[throws]]\nphase = 0\n',
            "crankshafts[2]",
            "carries no throw",
        ),
        (
            "[[crankshafts]]\n[[crankshafts]]\n[[throws]]\nphase = 0\n[[throws]]\nphase = 0\n"
            "crankshaft = 2\n",
            "crankshafts[2]",
            "shares its axis",
        ),
        (
            '[[crankshafts]]\n[[crankshafts]]\ny = "1 m"\n[[throws]]\nphase = 0\n[[throws]]\n'
            "phase = 180\ncrankshaft = 2\n[[cylinders]]\nnumber = 1\nbank = 1\nthrow = 1\n"
            "opposed_throw = 2\n",
            "cylinders[1]",
            "off the axis",
        ),
        (
            '[[crankshafts]]\n[[crankshafts]]\nx = "0.5 m"\n[[throws]]\nphase = 0\n[[throws]]\n'
            "phase = 180\ncrankshaft = 2\n[[cylinders]]\nnumber = 1\nbank = 1\nthrow = 1\n"
            "opposed_throw = 2\n",
            "cylinders[1]",
            "could meet",
        ),
        (
            "[[throws]]\nphase = 0\n[[throws]]\nphase = 180\n[[cylinders]]\nnumber = 1\nbank = 1\n"
            "throw = 1\nopposed_throw = 2\n",
            "cylinders[1]",
            "same crankshaft",
        ),
        (
            "[[throws]]\nphase = 0\n[[cylinders]]\nnumber = 1\nbank = 1\nthrow = 1\n"
            'opposed_reciprocating = "1 kg"\n',
            "cylinders[1].opposed_reciprocating",
            "opposed_throw",
        ),
        (
            "[[throws]]\nphase = 0\n[[cylinders]]\nnumber = 1\nbank = 1\nthrow = 1\n"
            'pin_offset = "250 mm"\n',
            "cylinders[1]",
            "offset smaller",
        ),
        (
            'frame = "rotary"\n[[crankshafts]]\n[[crankshafts]]\nx = "1 m"\n[[throws]]\nphase = 0\n'
            "[[throws]]\nphase = 0\ncrankshaft = 2\n",
            "crankshafts",
            "rotary",
        ),
    ],
)
def test_bad_crankshafts_and_opposed_pistons_are_named(text, key, words):
    # top-level keys go before the first table
    top = "\n".join(line for line in text.splitlines() if line.startswith("frame"))
    text = "\n".join(line for line in text.splitlines() if not line.startswith("frame")) + "\n"
    with pytest.raises(ConfigError) as info:
        balance.loads(top + "\n" + BASE + text, name="bad.toml")
    assert info.value.key == key, str(info.value)
    assert words in str(info.value)


@pytest.mark.parametrize(
    "config",
    [
        "configs/today/opposed-piston/napier-deltic-d18.toml",
        "configs/today/opposed-piston/junkers-jumo-205.toml",
        "configs/today/h/brm-h16.toml",
    ],
)
def test_each_crankshafts_torque_is_r_times_its_pins_tangential_forces(config):
    """Two methods per crankshaft: its torque from the kinetic energy of the parts it drives
    (−½ω²·dμ_s/dθ plus the gas on its pistons) and r times the tangential forces of the rods
    on its own pins (virtual shifts of each pin), positive in its own sense of turning; the
    main-bearing load of each is its pins' forces plus its own masses'."""
    engine = balance.load(config)
    result = balance.torque(engine)
    unit = engine.per_cylinder_unit_n * engine.crank_radius_m
    for shaft in result.crankshafts:
        pins = [
            p
            for p, t in zip(result.pins, engine.throws, strict=True)
            if t.crankshaft == shaft.number
        ]
        from_pins = sum(engine.crank_radius_m * p.tangential.curve for p in pins)
        # the virtual shifts' finite differences are good to about 1e-11 of the forces
        assert np.abs(from_pins - shaft.torque.curve).max() < 1e-9 * unit
        assert_allclose(
            shaft.main_bearings.force_n,
            sum(p.force_n for p in pins),
            atol=1e-9 * unit / engine.crank_radius_m,
        )
    assert result.main_bearings is None and result.guide is None


def test_an_opposed_cylinder_cannot_carry_a_link_rod():
    text = BASE + (
        '[[crankshafts]]\n[[crankshafts]]\nx = "1 m"\n[[throws]]\nphase = 0\n'
        "[[throws]]\nphase = 180\ncrankshaft = 2\n[[cylinders]]\nnumber = 1\nbank = 1\n"
        "throw = 1\nopposed_throw = 2\n[[cylinders]]\nnumber = 2\nbank = 1\nthrow = 1\n"
        'z = "50 mm"\nmaster = 1\nlink_length = "250 mm"\nknuckle_radius = "60 mm"\n'
        "knuckle_angle = 30\n"
    )
    with pytest.raises(ConfigError, match="opposed-piston cylinder, whose rods are plain"):
        balance.loads(text, name="bad.toml")


@pytest.mark.parametrize(
    "extra, words",
    [
        # the far throw half a metre along the shaft from the bore it drives
        ('[[throws]]\nphase = 180\ncrankshaft = 2\nz = "500 mm"\n', "same bore"),
        # the far throw at 0° moves its piston with the near one: no compression
        ("[[throws]]\nphase = 0\ncrankshaft = 2\n", "move together"),
    ],
)
def test_impossible_opposed_bores_are_refused(extra, words):
    text = BASE + (
        '[[crankshafts]]\n[[crankshafts]]\nx = "1 m"\n[[throws]]\nphase = 0\n'
        + extra
        + "[[cylinders]]\nnumber = 1\nbank = 1\nthrow = 1\nopposed_throw = 2\n"
    )
    with pytest.raises(ConfigError, match=words) as info:
        balance.loads(text, name="bad.toml")
    assert info.value.key == "cylinders[1]"


def test_a_third_piston_in_an_opposed_bore_is_refused():
    """Cylinder 2 on a bank pointing back along cylinder 1's bore, from the far crankshaft,
    would sit where cylinder 1's opposed piston runs."""
    text = BASE + (
        '[[banks]]\nangle = 180\n[[crankshafts]]\n[[crankshafts]]\nx = "1 m"\n'
        "[[throws]]\nphase = 0\n[[throws]]\nphase = 180\ncrankshaft = 2\n"
        "[[cylinders]]\nnumber = 1\nbank = 1\nthrow = 1\nopposed_throw = 2\n"
        "[[cylinders]]\nnumber = 2\nbank = 2\nthrow = 2\n"
    )
    with pytest.raises(ConfigError, match="sits in the bore of cylinder 1") as info:
        balance.loads(text, name="bad.toml")
    assert info.value.key == "cylinders[2]"


def test_ideal_counterweights_on_a_reversed_crankshaft_take_the_backward_first_order():
    """Counterweights in two planes of a crankshaft turning against the first make any backward
    first-order force and couple, as those of the first make any forward one: an H16 on
    cross-plane cranks 0-90-270-180 (the library's H16 has flat ones, and no first-order
    couple at all) has a planar primary couple in each half, forward and backward parts alike;
    it is all taken, and the summary's figure is then what the other orders leave (none)."""
    result = balance.analyse(flat8_pair(45, -1, crank=(0, 90, 270, 180)))
    assert result.counterweight_cancels == (True, True)
    o = result.order(1)
    couple = M * R * OMEGA**2 * 0.1  # m·r·ω²·d: the halves' couples are √10·2 of it
    assert abs(o.moment_forward) > couple and abs(o.moment_backward) > couple
    assert result.counterweighted_moment_nm == 0.0
    single = balance.analyse(balance.load("configs/today/v/v8-90-cross-plane.toml"))
    assert single.counterweight_cancels == (True, False)


@pytest.mark.parametrize("direction", [1, -1])
@pytest.mark.parametrize("gamma, gear", [(30.0, 0.0), (-120.0, 37.0), (75.0, -50.0)])
def test_the_readmes_mirror_image_rule_for_a_slanted_bore(direction, gamma, gear):
    """The README's rule: with the near throw at 0°, a far throw at d·(γ + 180°) − γ − φ_s moves
    the far piston as the mirror image of the near one, for a bore at γ and a far crankshaft
    turning d at gear phase φ_s: no free reciprocating force of any order."""
    g = math.radians(gamma)
    far = (direction * (gamma + 180.0) - gamma - gear + 180.0) % 360.0 - 180.0
    engine = balance.loads(
        textwrap.dedent(f"""
        name = "slanted"
        cycle = 2
        speed = "{RPM} rpm"
        crank_radius = "{R * 1000} mm"
        rod_length = "{L * 1000} mm"
        [masses]
        reciprocating = "{M} kg"
        [[banks]]
        angle = {gamma}
        [[crankshafts]]
        [[crankshafts]]
        x = "{1000 * math.cos(g)!r} mm"
        y = "{1000 * math.sin(g)!r} mm"
        direction = {direction}
        phase = {gear}
        [[throws]]
        phase = 0
        [[throws]]
        phase = {far!r}
        crankshaft = 2
        [[cylinders]]
        number = 1
        bank = 1
        throw = 1
        opposed_throw = 2
        """)
    )
    result = balance.analyse(engine)
    for k in range(1, 9):
        o = result.order(k)
        assert abs(o.force_forward) + abs(o.force_backward) < 1e-9 * M * R * OMEGA**2, k


def test_the_jumo_205s_bores_by_hand():
    """The library's Jumo 205, one bore at a time (its reciprocating masses alone): with its
    upper throw moved to the mirror image (180° from the lower in its own sense) the bore's two
    pistons leave no free force of any order; at the file's 11° lead (the upper, exhaust piston
    ahead), order k leaves
    m·ω²·k²·|a_k|·2·|sin(11°·k/2)| along the bore (a_k the travel's harmonic, by quadrature)."""
    engine = balance.load(JUMO)
    one = engine.cylinders[0]
    lower, upper = engine.throws[one.throw_index], engine.throws[one.opposed_throw_index]
    # the upper (exhaust) throw at 180° + 11° from the lower: the upper piston leads by 11°
    lead = math.degrees(math.remainder(math.pi - (upper.phase_rad - lower.phase_rad), 2 * math.pi))
    assert_allclose(lead, -11.0, atol=1e-12)
    m, r, rod, omega = (
        one.reciprocating_kg,
        engine.crank_radius_m,
        engine.rod_length_m,
        engine.speed_rad_s,
    )
    for phase, eps in ((lower.phase_rad + math.pi, 0.0), (upper.phase_rad, math.radians(lead))):
        bore = engine.replace(
            throws=(balance.Throw(lower.phase_rad, 0.0), balance.Throw(phase, 0.0, 2)),
            cylinders=(balance.Cylinder(1, 1, 1, 0.0, m, opposed_throw=2),),
            rotating_kg=0.0,
            firing_order=None,
            power_w=None,
            gas=None,
        )
        result = balance.analyse(bore)
        for k in range(1, 9):
            o = result.order(k)
            expected = (
                m
                * omega**2
                * k**2
                * abs(travel_harmonic(k, r, rod))
                * 2
                * abs(math.sin(k * eps / 2))
            )
            assert_allclose(
                abs(o.force_forward) + abs(o.force_backward),
                expected,
                rtol=1e-9,
                atol=1e-9 * m * r * omega**2,
            )
