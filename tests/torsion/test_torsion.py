"""Torsional vibration: modes, phase-vector sums and forced response against hand derivations,
a Holzer table and closed forms; the [torsion] table's errors; openTorsion missing."""

import cmath
import math
import sys
import time

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import quad

import balance_cli as balance
from balance_cli.analysis.cylinders import cylinder_torques
from balance_cli.analysis.firing import firing_angles
from balance_cli.analysis.torque import torque
from balance_cli.errors import AnalysisError, ConfigError, TorsionUnavailable
from balance_cli.torsion import phase_vector_sum, throw_inertias
from balance_cli.torsion import torsional_vibration as torsion
from tests.support import INLINE6, TORSION6, TORSION_ORDERS, holzer, invoke

#: one cylinder on one throw (for the SDOF and reduced-mass checks)
SINGLE = """\
name = "test single"
cycle = 4
speed = "1500 rpm"
crank_radius = "50 mm"
rod_length = "200 mm"

[masses]
reciprocating = "1.5 kg"
rotating = "2 kg"

[[banks]]
angle = 0

[[throws]]
phase = 0
"""


def chain(inertias, stiffnesses, **extra):
    """A two-stroke engine of len(inertias) throws (all at phase 0 is enough for modes)
    whose [torsion] table gives these inertias and section stiffnesses."""
    n = len(inertias)
    throws = "".join(f"[[throws]]\nphase = {360 * i // n}\n" for i in range(n))
    table = (
        f"[torsion]\nthrow_inertia = {[f'{j} kg*m^2' for j in inertias]}\n"
        f"stiffness = {[f'{k} N*m/rad' for k in stiffnesses]}\n".replace("'", '"')
    )
    for key, value in extra.items():
        table += f"{key} = {value}\n"
    return balance.loads(
        SINGLE.replace("cycle = 4", "cycle = 2").split("[[throws]]")[0] + throws + table
    )


TEMPLATE6 = (
    INLINE6.replace("firing_order = [1, 5, 3, 6, 2, 4]\n", "")
    .replace("[[throws]]\nphase = 0\n", "[[throws]]\n")
    .replace("[[throws]]\nphase = 240\n", "[[throws]]\n")
    .replace("[[throws]]\nphase = 120\n", "[[throws]]\n")
)


def pitched_template(folder, extra=""):
    """TEMPLATE6 with its throws 120 mm apart (and ``extra`` appended), written to a file."""
    zs, out = iter(range(0, 720, 120)), []
    for line in TEMPLATE6.split("\n"):
        out.append(line)
        if line == "[[throws]]":
            out.append(f'z = "{next(zs)} mm"')
    path = folder / "template.toml"
    path.write_text("\n".join(out) + extra)
    return path


def test_two_disk_frequency():
    """Two disks J1, J2 on a shaft k (free-free): ω = √(k·(J1 + J2)/(J1·J2)); the node divides
    the shaft inversely as the inertias, so the amplitudes are in the ratio −J1/J2."""
    j1, j2, k = 0.05, 0.2, 1.5e6
    engine = chain([j1, j2], [k])
    result = torsion(engine, [1000.0], 2)
    assert len(result.modes) == 1
    expected = math.sqrt(k * (j1 + j2) / (j1 * j2)) / (2 * math.pi)
    # eigenvalues of a 2×2 pencil: rounding only
    assert_allclose(result.modes[0].frequency_hz, expected, rtol=1e-10)
    shape = result.modes[0].shape
    assert_allclose(shape[1] / shape[0], -j1 / j2, rtol=1e-9)


def test_holzer_three_masses():
    """Three disks J = (1, 2, 3) kg·m² joined by k = (1e6, 2e6) N·m/rad, free-free.

    By hand, the non-zero ω² solve J1J2J3·ω⁴ − [k1J3(J1 + J2) + k2J1(J2 + J3)]·ω² +
    k1k2(J1 + J2 + J3) = 0 (the determinant of K − ω²M divided by ω²):
    6·ω⁴ − (9e6 + 10e6)·ω² + 12e12 = 0, ω² = (19e6 ± √(361e12 − 288e12))/12 =
    (19 ± √73)/12·1e6 = 0.87135e6 and 2.29532e6 rad²/s².

    Holzer's table at those ω² (worked for the first: θ = 1, T = 0.87135e6, θ₂ = 1 − 0.87135
    = 0.12865, T = 0.87135e6 + 2·0.87135e6·0.12865 = 1.09555e6, θ₃ = 0.12865 − 0.54777 =
    −0.41913, residual 1.09555e6 + 3·0.87135e6·(−0.41913) ≈ 0) leaves no torque after the
    last disk; openTorsion's modes must agree in frequency and shape.
    """
    j, k = [1.0, 2.0, 3.0], [1e6, 2e6]
    roots = [(19 - math.sqrt(73)) / 12 * 1e6, (19 + math.sqrt(73)) / 12 * 1e6]
    result = torsion(chain(j, k), [1000.0], 2)
    assert_allclose(
        [(2 * math.pi * m.frequency_hz) ** 2 for m in result.modes], roots, rtol=1e-10
    )  # a 3×3 eigenproblem: rounding only
    for omega2, mode in zip(roots, result.modes, strict=True):
        angles, residual = holzer(j, k, omega2)
        # the residual is a difference of terms of size k·θ ~ 1e6: 1e-9 of them is rounding
        assert abs(residual) < 1e-9 * 1e6
        assert_allclose(mode.shape / mode.shape[0], angles, rtol=1e-8, atol=1e-9)
    # off a natural frequency the table leaves a torque: the check has teeth
    assert abs(holzer(j, k, 1.0e6)[1]) > 1e4


def test_inline6_firing_angles():
    """Firing 1-5-3-6-2-4 every 120°: cylinder c's firing angle (θ of its firing TDC) is
    120° × its place in the order."""
    fire = firing_angles(balance.loads(INLINE6))
    assert_allclose([fire[c] for c in (1, 5, 3, 6, 2, 4)], [0, 120, 240, 360, 480, 600], atol=1e-9)


@pytest.mark.parametrize("order", TORSION_ORDERS)
def test_inline6_equal_amplitudes(order):
    """Equal amplitudes: Σ e^{ik·120°·m}, m = 0..5, is a geometric series of ratio
    r = e^{ik·2π/3} with r⁶ = e^{i4πk} = 1 for every multiple k of ½: it sums to 6 when r = 1
    (k a multiple of 3: the major orders) and to (1 − r⁶)/(1 − r) = 0 otherwise."""
    total = abs(phase_vector_sum(np.ones(6), [0, 120, 240, 360, 480, 600], order))
    expected = 6.0 if order % 3 == 0 else 0.0
    assert_allclose(total, expected, atol=1e-12)


def test_inline6_one_node_mode_minor_orders():
    """A one-node mode with amplitudes β = (1, 0.9, 0.7, 0.5, 0.3, 0.1) at throws 1..6.
    In firing order (1, 5, 3, 6, 2, 4) the β are (1, 0.3, 0.7, 0.1, 0.9, 0.5) at 120°·m.
    By hand:
    - k = ½ (and 3½, 6½, …): angles 60°·m: real 1 + .3/2 − .7/2 − .1 − .9/2 + .5/2 = 0.5,
      imaginary (√3/2)(.3 + .7 − .9 − .5) = −0.2√3; |S| = √(0.25 + 0.12) = √0.37;
    - k = 1 (and 2): pairs at 0°, 120°, 240°: (1 + .1) + (.3 + .9)e^{i120°} + (.7 + .5)e^{i240°}
      = 1.1 − 1.2, |S| = 0.1;
    - k = 1½: alternating signs: 1 − .3 + .7 − .1 + .9 − .5 = 1.7;
    - k = 2½ is k = ½ conjugated: √0.37; k = 3 (major): Σβ = 3.5.
    """
    beta = [1.0, 0.3, 0.7, 0.1, 0.9, 0.5]
    phi = [0, 120, 240, 360, 480, 600]
    expected = {
        0.5: math.sqrt(0.37),
        1: 0.1,
        1.5: 1.7,
        2: 0.1,
        2.5: math.sqrt(0.37),
        3: 3.5,
        3.5: math.sqrt(0.37),
        4.5: 1.7,
        6: 3.5,
    }
    for k, value in expected.items():
        assert_allclose(abs(phase_vector_sum(beta, phi, k)), value, rtol=1e-12)


def test_engine_phase_vector_sums_use_the_mode():
    """The analysis sums the mode's own throw amplitudes at the cylinders' firing angles:
    recomputed by hand from the mode it reports, and the majors are the multiples of 3."""
    result = torsion(balance.loads(INLINE6 + TORSION6), [1000.0, 2000.0], 12)
    phi = {1: 0, 5: 120, 3: 240, 6: 360, 2: 480, 4: 600}
    mode = result.modes[0]
    for k in (0.5, 1.5, 3, 4.5, 6):
        by_hand = sum(
            mode.throw_amplitudes[c - 1] * cmath.exp(1j * math.radians(k * phi[c]))
            for c in range(1, 7)
        )
        assert_allclose(mode.phase_vector_sums[k], abs(by_hand), rtol=1e-12)
    assert {c.order % 3 == 0 for c in result.criticals if c.major} == {True}
    assert any(not c.major for c in result.criticals)


def test_cylinder_torques_add_up_to_the_engine_torque():
    """Each cylinder's own torque, summed, is the engine's total (μ is a sum over parts;
    the gas torque a sum over cylinders): two ways through the torque engine."""
    engine = balance.loads(
        INLINE6 + '\n[gas]\nbore = "105 mm"\ncompression_ratio = 17\nimep = "15 bar"\n'
    )
    total = torque(engine, bearings=False, guide=False).total
    cylinders = cylinder_torques(engine)
    for index, (_k, cos, sin) in enumerate(total.orders):
        parts = sum(
            complex(*c.inertia.orders[index][1:]) + complex(*c.gas.orders[index][1:])
            for c in cylinders
        )
        # floors of 1e-9 of m·r²·ω²·n per term: far below the 1e-6 N·m allowed
        assert_allclose([parts.real, parts.imag], [cos, sin], atol=1e-6 * max(1, abs(cos)))


def test_reduced_mass_throw_inertia():
    """With web_inertia, a throw's inertia is its parts' mean reduced mass plus the webs:
    m_rot·r² + m_rec·mean((ds/dθ)²) + J_web, with ds/dθ = −r·sin θ −
    r²·sin θ·cos θ/√(l² − r²·sin² θ) for a plain rod (integrated here by quadrature)."""
    r, rod, m_rec, m_rot, web = 0.05, 0.2, 1.5, 2.0, 0.03
    engine = balance.loads(
        SINGLE.replace("cycle = 4", "cycle = 2").replace(
            "phase = 0\n", "phase = 0\n[[throws]]\nphase = 180\n"
        )
        + '[torsion]\nweb_inertia = "0.03 kg*m^2"\nstiffness = "1e6 N*m/rad"\n'
    )

    def rate2(t):
        return (
            -r * math.sin(t)
            - r**2 * math.sin(t) * math.cos(t) / math.sqrt(rod**2 - r**2 * math.sin(t) ** 2)
        ) ** 2

    mean = quad(rate2, 0, 2 * math.pi)[0] / (2 * math.pi)
    expected = m_rot * r**2 + m_rec * mean + web
    # the spectral derivative of a band-limited motion is exact to rounding at 256 samples
    assert_allclose(throw_inertias(engine), [expected, expected], rtol=1e-9)


def test_single_degree_of_freedom_response():
    """One throw J on a shaft k to a flywheel of 1e9·J (a wall): the throw is a single degree
    of freedom, and each order k of its cylinder's torque U_k gives the section torque
    k_s·U_k/(k_s − J·(kΩ)² + i·c·kΩ) (c the throw's damping); the inertia part of U_k grows
    as Ω². The flywheel moves J/J_f = 1e-9 as much as the throw: that is the tolerance."""
    j, ks, c = 0.05, 2.0e5, 3.0
    engine = balance.loads(
        SINGLE + f'[torsion]\nthrow_inertia = "{j} kg*m^2"\n'
        f'throw_damping = "{c} N*m*s/rad"\n[torsion.flywheel]\n'
        f'inertia = "{j * 1e9} kg*m^2"\nstiffness = "{ks} N*m/rad"\n'
    )
    speeds = np.array([900.0, 1500.0, 2400.0])
    result = torsion(engine, speeds, 6)
    (cyl,) = cylinder_torques(engine, max_order=6)
    omega0 = engine.speed_rad_s
    for i, speed in enumerate(speeds):
        omega = speed * math.pi / 30
        for o, (k, cos, sin) in enumerate(cyl.inertia.orders):
            u = (cos - 1j * sin) * (omega / omega0) ** 2
            w = k * omega
            expected = abs(ks * u / (ks - j * w**2 + 1j * c * w))
            assert_allclose(
                result.order_torque_nm[i, 0, o], expected, rtol=1e-6, atol=1e-9 * abs(u)
            )
            # the throw is the free end: its angle is the section's torque over k
            assert_allclose(
                result.free_end_order_deg[i, o],
                math.degrees(expected / ks),
                rtol=1e-6,
                atol=1e-9 * abs(u) / ks,
            )
    # the natural frequency √(k/J) (the flywheel a wall to 1e-9)
    assert_allclose(result.modes[0].frequency_hz, math.sqrt(ks / j) / (2 * math.pi), rtol=1e-8)


def test_synthesised_peak_is_the_waveform_peak():
    """All orders together: the peak of Σ_k Re(T_k·e^{ikθ}) over the cycle, at most the sum of
    the amplitudes and at least the largest one; checked against a 20 000-point resampling."""
    result = torsion(balance.loads(INLINE6 + TORSION6), [1500.0, 2150.0], 12)
    assert np.all(result.torque_nm <= result.order_torque_nm.sum(axis=-1) * (1 + 1e-12))
    assert np.all(result.torque_nm >= result.order_torque_nm.max(axis=-1) * (1 - 1e-12))
    assert result.stress_pa is not None
    # τ = 16·T/(π·D³) for a solid shaft of D = 80 mm
    assert_allclose(result.stress_pa, 16 * result.torque_nm / (math.pi * 0.08**3), rtol=1e-12)


def test_sweep_speed():
    """A six-throw model's full sweep: 100 speeds, orders ½ to 12, well under a second."""
    engine = balance.loads(INLINE6 + TORSION6)
    torsion(engine, np.linspace(600, 2400, 100), 12)  # warm the imports
    start = time.perf_counter()
    torsion(engine, np.linspace(600, 2400, 100), 12)
    assert time.perf_counter() - start < 1.0


@pytest.mark.parametrize(
    "change, key",
    [
        (
            ('stiffness = "1.253e6 N*m/rad"', 'stiffness = ["1e6 N*m/rad", "1e6 N*m/rad"]'),
            "torsion.stiffness",
        ),
        (('stiffness = "1.253e6 N*m/rad"', 'stiffness = "1.253e6 N*m"'), "torsion.stiffness"),
        (("loss_factor = 0.035", "loss = 0.035"), "torsion.loss"),
        (('inertia = "2.075 kg*m^2"', 'inertai = "2.075 kg*m^2"'), "torsion.flywheel.inertai"),
        (
            (
                'throw_inertia = "0.0467 kg*m^2"',
                'throw_inertia = ["1 kg*m^2", "-1 kg*m^2", "1 kg*m^2", '
                '"1 kg*m^2", "1 kg*m^2", "1 kg*m^2"]',
            ),
            "torsion.throw_inertia[2]",
        ),
        (
            ('shaft_diameter = "80 mm"', 'shaft_diameter = "80 mm"\nshaft_bore = "90 mm"'),
            "torsion.shaft_bore",
        ),
        (('throw_inertia = "0.0467 kg*m^2"', ""), "torsion.throw_inertia"),
    ],
)
def test_bad_torsion_tables(change, key, tmp_path):
    text = (INLINE6 + TORSION6).replace(*change)
    with pytest.raises(ConfigError) as caught:
        balance.loads(text, "engine.toml")
    assert caught.value.key == key
    path = tmp_path / "engine.toml"
    path.write_text(text)
    out = tmp_path / "out.json"
    result = invoke("torsion", path, "--format", "json", "-o", out)
    assert result.exit_code == 1
    assert key in result.output and len(result.output.strip().splitlines()) == 1
    assert "Traceback" not in result.output and not out.exists()


def test_engine_without_torsion_table():
    with pytest.raises(AnalysisError, match=r"no \[torsion\] table"):
        torsion(balance.loads(INLINE6))


def test_missing_opentorsion(monkeypatch, tmp_path):
    """Without openTorsion: one line naming the extra; the rest of balance works."""
    monkeypatch.setitem(sys.modules, "opentorsion", None)  # import raises ImportError
    engine = balance.loads(INLINE6 + TORSION6)
    with pytest.raises(TorsionUnavailable, match=r"pip install 'engine-balance\[torsion\]'"):
        torsion(engine)
    path = tmp_path / "six.toml"
    path.write_text(INLINE6 + TORSION6)
    result = invoke("torsion", path)
    assert result.exit_code == 1
    assert result.output.strip().splitlines() == [
        "Error: balance torsion needs openTorsion: pip install 'engine-balance[torsion]'"
    ]
    assert invoke("compare", path).exit_code == 0
    assert invoke("torque", path).exit_code == 0


def test_search_v_terms_score_is_the_phase_vector_sum(tmp_path):
    """``V1,V2``: the kernel's score (the template's first mode turned with each crank) equals
    the sum of the listed arrangements' V1 and V2 worked out from their own firing angles and
    first mode (balance_cli.torsion), each |Σ β·e^{ik·φ}|/Σ|β|; and the first mode's V3 is 1
    (a major order: all cylinders in phase) for every even-firing crank."""
    path = pitched_template(tmp_path, TORSION6)
    template = balance.load_template(path)
    result = balance.search(template, "V1,V2,V3", top=6, workers=1)
    for a in result.arrangements:
        assert_allclose(
            a.score,
            a.coefficients["V1"] + a.coefficients["V2"] + a.coefficients["V3"],
            rtol=1e-9,
            atol=1e-12,
        )
        assert_allclose(a.coefficients["V3"], 1.0, rtol=1e-12)
    # the half orders are refused by name
    with pytest.raises(AnalysisError, match="whole orders only"):
        balance.search(template, "V1.5")


def test_search_v_term_needs_a_torsion_table(tmp_path):
    path = pitched_template(tmp_path)
    template = balance.load_template(path)
    with pytest.raises(AnalysisError, match=r"no \[torsion\] table"):
        balance.search(template, "M1,V2")


def test_search_tv1_is_the_largest_minor_order(tmp_path):
    """``TV1``: the first mode's largest V_k over the whole orders 1..max_order that are not
    major (for an even-firing four-stroke six, all but 3 and 6). Every arrangement listed (all
    60 distinct ones: pruning by the bound must lose none) has the score its own V_k give,
    recomputed here from balance.torsion's mode and the firing angles; the ranking is by it."""
    path = pitched_template(tmp_path, TORSION6)
    template = balance.load_template(path)
    result = balance.search(template, "TV1", top=1000, workers=1)
    assert len(result.arrangements) == result.arrangements_distinct == 60
    scores = []
    for a in result.arrangements:
        beta = torsion(a.engine, [1000.0], 8).modes[0].throw_amplitudes
        fire = firing_angles(a.engine)
        amplitudes = [beta[c.throw_index] for c in a.engine.cylinders]
        angles = [fire[c.number] for c in a.engine.cylinders]
        by_hand = max(abs(phase_vector_sum(amplitudes, angles, k)) for k in (1, 2, 4, 5, 7, 8))
        by_hand /= sum(abs(b) for b in amplitudes)
        assert_allclose(a.score, by_hand, rtol=1e-9)
        scores.append(a.score)
    # ranked by score; equal scores (to the search's 1e-9 tie) by firing order
    assert (
        all(b >= a - 1e-9 for a, b in zip(scores, scores[1:], strict=False))
        and scores[0] < scores[-1]
    )


def test_report_has_a_torsion_section(tmp_path, monkeypatch):
    """An engine with a [torsion] table gets a section in the report; one without does not
    add one; without openTorsion the section says so in one line and the report is written."""
    six = tmp_path / "six.toml"
    six.write_text(INLINE6 + TORSION6)
    plain = tmp_path / "plain.toml"
    plain.write_text(INLINE6.replace('name = "test in-line 6"', 'name = "plain six"'))
    result = invoke("report", six, plain, "-o", tmp_path / "report")
    assert result.exit_code == 0, result.output
    text = (tmp_path / "report" / "report.md").read_text()
    assert "## Torsional vibration" in text and "### test in-line 6" in text
    assert "### plain six" not in text
    assert "order 6 of mode 1" in text
    result = invoke("report", plain, "-o", tmp_path / "plain-report")
    assert "Torsional vibration" not in (tmp_path / "plain-report" / "report.md").read_text()
    monkeypatch.setitem(sys.modules, "opentorsion", None)
    result = invoke("report", six, "-o", tmp_path / "without")
    assert result.exit_code == 0, result.output
    assert (
        "Not computed: balance torsion needs openTorsion: pip install 'engine-balance[torsion]'."
        in (tmp_path / "without" / "report.md").read_text()
    )


def test_search_write_keeps_the_torsion_table(tmp_path):
    """``search --write`` writes the template's [torsion] table, sub-tables included, so the
    configuration it writes has the template's shaft line."""
    path = pitched_template(tmp_path, TORSION6)
    result = invoke(
        "search", path, "--objective", "M1,TV1", "--top", "1", "--write", tmp_path / "best"
    )
    assert result.exit_code == 0, result.output
    (written,) = (tmp_path / "best").iterdir()
    template = balance.load_template(path)
    assert balance.load(written).torsion == template.torsion


def test_library_model_checked():
    """A TorsionModel built in code is refused by name when a value is impossible."""
    import dataclasses

    engine = balance.loads(INLINE6 + TORSION6)
    for field, value, name in (
        ("stiffness_nm_rad", (1e6, -1e6, 1e6, 1e6, 1e6), "stiffness_nm_rad"),
        ("loss_factor", math.nan, "loss_factor"),
        ("throw_inertia_kgm2", (0.05,) * 5 + (0.0,), "throw_inertia_kgm2"),
    ):
        bad = engine.replace(torsion=dataclasses.replace(engine.torsion, **{field: value}))
        with pytest.raises(AnalysisError) as caught:
            torsion(bad, [1000.0])
        assert caught.value.parameter == name
    short = engine.replace(torsion=dataclasses.replace(engine.torsion, stiffness_nm_rad=(1e6,)))
    with pytest.raises(AnalysisError, match="one stiffness per section"):
        torsion(short, [1000.0])


def test_the_default_speeds_follow_the_engines_own_speed():
    """A fixed 600-2400 rpm range put a 105 rpm marine engine's sweep 23 times above its speed;
    the default is 20 % to 120 % of the engine's speed, 201 speeds."""
    engine = balance.loads(INLINE6 + TORSION6)  # 2000 rpm
    result = balance.torsional_vibration(engine)
    assert_allclose(result.speeds_rpm[[0, -1]], [400.0, 2400.0], rtol=1e-12)
    assert len(result.speeds_rpm) == 201
    slow = engine.replace(speed_rad_s=engine.speed_rad_s / 20)  # 100 rpm
    assert_allclose(
        balance.torsional_vibration(slow).speeds_rpm[[0, -1]], [20.0, 120.0], rtol=1e-12
    )


@pytest.mark.parametrize("speeds", [[1e300], [float("nan")], list(range(1, 6000)), []])
def test_the_library_refuses_speeds_it_cannot_sweep(speeds):
    engine = balance.loads(INLINE6 + TORSION6)
    with pytest.raises(AnalysisError) as info:
        balance.torsional_vibration(engine, speeds)
    assert info.value.parameter == "speeds_rpm"


def test_a_torsion_table_on_a_rotary_is_refused_when_read():
    text = (INLINE6 + TORSION6).replace(
        'speed = "2000 rpm"', 'speed = "2000 rpm"\nframe = "rotary"'
    )
    with pytest.raises(ConfigError, match="rotary") as info:
        balance.loads(text, name="rotary.toml")
    assert info.value.key == "torsion"


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        (dict(bore_m=-1.0), "bore_m"),
        (dict(bore_m=0.1), "bore_m"),  # a bore without a pressure
        (dict(speeds_rpm=True), "speeds_rpm"),
        (dict(speeds_rpm=[[1000, 2000]]), "speeds_rpm"),
        (dict(max_order=math.nan), "max_order"),
        (dict(samples="x"), "samples"),
    ],
)
def test_the_library_checks_what_the_command_line_checks(kwargs, parameter):
    """A bore without a pressure curve once failed with an AttributeError; a bool or a table
    of speeds was taken as speeds."""
    engine = balance.loads(INLINE6 + TORSION6)
    with pytest.raises(balance.BalanceError) as info:
        balance.torsional_vibration(engine, **kwargs)
    assert info.value.parameter == parameter
