"""The library's facts, each against its cited figure and derived by hand; and every library
file saying where each of its numbers comes from.

The facts (sources named in each file's ``sources``):

- BRM H16: "each crankshaft was a flat-plane design" (EngineLabs, The Weirdest F1 Engine Ever,
  BRM's P75 H16 Double Flat-8). On 0-180-180-0 the first-order couple vanishes and, at the
  file's 90° gear phase (an estimate), the sixteen cylinders fire in pairs every 90°.
- Buick V6 (231 odd-fire and 3800): bore spacing 107.7 mm (4.240 in) (Wikipedia, Buick V6
  engine, Fireball V6: "the actual bore spacing between cylinders on the same bank remained
  unchanged at 107.7 mm (4.240")").
- Junkers Jumo 205: intake ports under the lower pistons, exhaust under the upper, "the lower
  crankshaft ran eleven degrees behind the upper" (Wikipedia, Junkers Jumo 205, Design and
  development): the exhaust pistons are on the upper, leading crankshaft.
- Split pins: the two pins of a pair sit side by side, each cylinder over its own pin, so the
  banks are staggered along the crank by a rod's width (and any flange or web between the
  pins): the Buick 3800's 3.0 mm flange (Wikipedia, Buick V6 engine), the Audi 4.2 V8 FSI's
  big ends 18.65-18.69 mm wide (Audi workshop manual).
- Yamaha YZF-R1 (2009-): a cross-plane crank firing at "uneven intervals of 270-180-90-180
  degrees" (Motorcycle Daily, 2009, quoting Yamaha).
"""

import cmath
import dataclasses
import math
import tomllib

import numpy as np
import pytest
from click.testing import CliRunner
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.cli import main
from balance_cli.config import number_paths, read_provenance
from tests.support import CONFIGS, TODAY

H16 = TODAY / "h" / "brm-h16.toml"
JUMO = TODAY / "opposed-piston" / "junkers-jumo-205.toml"
R1 = TODAY / "inline" / "inline-4-cross-plane.toml"
BUICK_ODD = TODAY / "v" / "v6-90-odd-fire.toml"
BUICK_3800 = TODAY / "v" / "v6-90-split-pin.toml"
VQ35 = TODAY / "v" / "v6-60-split-pin.toml"
AUDI_V10 = TODAY / "v" / "v10-90-split-pin.toml"
#: every file of the shipped library, by its path under configs/
LIBRARY = sorted(p.relative_to(CONFIGS).as_posix() for p in CONFIGS.rglob("*.toml"))
#: 4.240 in, m
BUICK_BORE_SPACING_M = 4.240 * 0.0254
#: the files give lengths to 0.1 mm: 107.7 mm for 107.696 mm
FILE_ROUNDING_M = 0.05e-3


def degrees_of(angles_rad):
    return [math.degrees(a) % 360.0 for a in angles_rad]


# ------------------------------------------------------------------------------ BRM H16


def test_h16_cranks_are_flat_plane_and_its_first_order_couple_is_zero():
    """Both crankshafts carry 0-180-180-0 at z = 0, d, 2d, 3d (d = 88 mm). By hand, about
    z̄ = 1.5d: Σ(z − z̄)·e^{iβ} = −1.5d·1 − 0.5d·(−1) + 0.5d·(−1) + 1.5d·1 = 0 on each shaft,
    for the pistons of both banks (each pin's two move alike in first order) and for the
    rotating masses: no first-order couple at all, where the former cross-plane crank
    0-90-270-180 left |Σ(z − z̄)·e^{iβ}| = √10·d a shaft. balance agrees to rounding (against
    m·r·ω²·d, the couple's scale)."""
    engine = balance.load(H16)
    for shaft in (1, 2):
        throws = [t for t in engine.throws if t.crankshaft == shaft]
        assert [round(p) for p in degrees_of(t.phase_rad for t in throws)] == [0, 180, 180, 0]
        z = np.array([t.z_m for t in throws])
        by_hand = sum(
            (zj - z.mean()) * cmath.exp(1j * t.phase_rad) for zj, t in zip(z, throws, strict=True)
        )
        assert abs(by_hand) < 1e-15
    scale = engine.mean_reciprocating_kg * engine.crank_radius_m * engine.speed_rad_s**2 * 0.088
    o = balance.analyse(engine).order(1)
    # rounding of sums of sixteen N·m-sized terms
    assert abs(o.moment_forward) + abs(o.moment_backward) < 1e-9 * scale
    assert abs(o.force_forward) + abs(o.force_backward) < 1e-9 * scale / 0.088


def test_h16_fires_in_pairs_every_90_degrees():
    """A piston on a crank turning d = ±1, gear phase φ, throw phase β is at top dead centre
    when its pin points along its bank γ: d·(θ + φ + β) ≡ γ, θ = d·γ − φ − β. Upper shaft
    (d = 1, φ = 0): banks 0° and 180° on pins 0° and 180°: θ = 0° or 180°, four cylinders
    each. Lower (d = −1, φ = 90°): θ = −γ − 90° − β: 90° or 270°, four each. A four-stroke
    cylinder fires at its TDC or 360° later: 8 slots 90° apart for 16 cylinders, two a slot:
    pairs every 90°, intervals 0°, 90°, 0°, 90°, ... balance finds that sequence (the most
    uniform the crank allows) and the same TDCs."""
    engine = balance.load(H16)
    by_hand = {}
    for c in engine.cylinders:
        shaft = engine.crankshaft_of(c.throw_index)
        gamma = math.degrees(engine.bank_angles_rad[c.bank_index])
        beta = math.degrees(engine.throws[c.throw_index].phase_rad)
        phi = math.degrees(shaft.phase_rad)
        by_hand[c.number] = (shaft.direction * gamma - phi - beta) % 360.0
    assert sorted(round(a) for a in by_hand.values()) == [0] * 4 + [90] * 4 + [180] * 4 + [270] * 4
    firing = balance.analyse(engine).firing
    for number, tdc in by_hand.items():
        # the TDC search is good to about 2e-6°
        assert_allclose((firing.tdc_deg[number] - tdc + 180) % 360 - 180, 0.0, atol=1e-5)
    slots = [round(a) for a in firing.angles_deg]
    assert slots == sorted(slots)
    assert slots == [90 * (k // 2) for k in range(16)]
    assert_allclose(firing.intervals_deg, [0.0, 90.0] * 8, atol=1e-5)


# ----------------------------------------------------------------------------- Buick V6


@pytest.mark.parametrize("config", [BUICK_ODD, BUICK_3800])
def test_buick_v6_bore_spacing_is_4_240_inches(config):
    """Cylinders of one bank 4.240 in (107.7 mm) apart, in both Buick files."""
    engine = balance.load(config)
    for bank in range(len(engine.bank_angles_rad)):
        z = sorted(c.z_m for c in engine.cylinders if c.bank_index == bank)
        assert_allclose(np.diff(z), BUICK_BORE_SPACING_M, atol=FILE_ROUNDING_M)


def test_buick_231_primary_couple_with_the_real_bore_spacing():
    """The odd-fire 231's primary couple is √3·m·r·ω²·d (tests/validation/test_textbook.py):
    with d = 4.240 in, m = 0.70 kg, r = 43.2 mm at 4000 rpm, by hand
    √3 · 0.70 · 0.0432 · (4000·2π/60)² · 0.107696 = 989.7 N·m; the former 105 mm made every
    moment 2.5 % low (107.696/105 = 1.0257)."""
    omega = 4000 * 2 * math.pi / 60
    by_hand = math.sqrt(3) * 0.70 * 0.0432 * omega**2 * BUICK_BORE_SPACING_M
    assert round(by_hand, 1) == 989.7
    o = balance.analyse(balance.load(BUICK_ODD)).order(1)
    # the file's 107.7 mm against 107.696 mm: 4e-5
    assert_allclose(abs(o.moment_forward) + abs(o.moment_backward), by_hand, rtol=5e-5)


# ---------------------------------------------------------------------------- Jumo 205


def test_jumo_205_exhaust_pistons_are_on_the_upper_leading_crankshaft():
    """The second crankshaft sits 1 m along the bores from the first (x along the reference
    axis, the bores' direction): it is the upper one. By hand, the lower piston (its pin at
    θ + β_l, d = 1) is at its inner dead centre when the pin points up the bore: θ = −β_l; the
    upper piston (pin at θ + β_u about the upper crank) when its pin points down the bore:
    θ = 180° − β_u. The upper (exhaust) piston leads by (−β_l) − (180° − β_u) = 11° in every
    bore: the lower crankshaft runs eleven degrees behind. A second method: both pistons'
    closed-form travel on a 0.001° grid. And the bore is smallest half way, 5.5° after the
    upper piston's dead centre (the two slider curves are mirror images about that angle):
    balance's TDC of each bore."""
    engine = balance.load(JUMO)
    lower, upper = engine.crankshafts
    assert upper.x_m > 0.5 and upper.y_m == 0.0 and engine.bank_angles_rad == (0.0,)
    r, rod = engine.crank_radius_m, engine.rod_length_m
    theta = np.radians(np.arange(0.0, 360.0, 0.001))
    tdc = balance.analyse(engine).firing.tdc_deg
    for c in engine.cylinders:
        beta_l = math.degrees(engine.throws[c.throw_index].phase_rad)
        beta_u = math.degrees(engine.throws[c.opposed_throw_index].phase_rad)
        assert engine.crankshaft_of(c.opposed_throw_index) is upper
        lead = (-beta_l - (180.0 - beta_u) + 180.0) % 360.0 - 180.0
        assert_allclose(lead, 11.0, atol=1e-12)
        # the pistons' positions along the bore, from the lower crank (closed form)
        a_l, a_u = theta + math.radians(beta_l), theta + math.radians(beta_u)
        x_lower = r * np.cos(a_l) + np.sqrt(rod**2 - (r * np.sin(a_l)) ** 2)
        x_upper = upper.x_m + r * np.cos(a_u) - np.sqrt(rod**2 - (r * np.sin(a_u)) ** 2)
        inner_lower = math.degrees(theta[np.argmax(x_lower)])
        inner_upper = math.degrees(theta[np.argmin(x_upper)])
        assert_allclose((inner_lower - inner_upper) % 360.0, 11.0, atol=0.002)  # the grid
        assert_allclose((tdc[c.number] - inner_upper) % 360.0, 5.5, atol=1e-4)


# ------------------------------------------------------------------------- split pins


@pytest.mark.parametrize(
    "config, stagger_m",
    [
        # the published 3.0 mm flange and a big end about 22 mm wide (an estimate)
        (BUICK_3800, 0.025),
        # a big end about 21 mm wide and a 6 mm web (estimates)
        (VQ35, 0.027),
        # one big end of the 4.2 V8 FSI's published 18.65-18.69 mm, to 0.1 mm
        (AUDI_V10, 0.0187),
    ],
)
def test_split_pin_banks_are_staggered_by_the_rods_width(config, stagger_m):
    """Each cylinder over its own pin: the cylinder of bank 2 sits the stagger behind its
    bank-1 partner on the next pin of the pair, all along the crank (bank 1 forward), and
    the pins of one bank keep the bore spacing between them."""
    engine = balance.load(config)
    first = sorted((c for c in engine.cylinders if c.bank_index == 0), key=lambda c: c.z_m)
    second = sorted((c for c in engine.cylinders if c.bank_index == 1), key=lambda c: c.z_m)
    assert len(first) == len(second) and len({c.throw for c in engine.cylinders}) == len(
        engine.cylinders
    )
    for a, b in zip(first, second, strict=True):
        assert b.throw == a.throw + 1  # the next pin of the pair
        assert_allclose(b.z_m - a.z_m, stagger_m, atol=1e-12)
    if config == AUDI_V10:
        assert 0.01865 - FILE_ROUNDING_M <= stagger_m <= 0.01869 + FILE_ROUNDING_M
    if config == BUICK_3800:
        assert_allclose(stagger_m - 0.003, 0.022, atol=1e-12)  # the flange and a big end


def test_split_pin_stagger_leaves_the_first_and_second_order_couples():
    """Σ(z − z̄)·F with bank 2 moved s along the crank adds (s/2)·(F_bank2 − F_bank1); each
    bank of a split-pin V6 or V10 is an in-line three or five whose forces of orders 1 and 2
    vanish (Σe^{ikβ} = 0 over its pins), so those couples keep their textbook values
    (tests/validation/test_textbook.py): here against the same engine with the stagger taken
    out, to rounding."""
    for config in (BUICK_3800, VQ35, AUDI_V10):
        engine = balance.load(config)
        pairs = engine.throws[0::2]
        flat = engine.replace(
            throws=tuple(
                t if i % 2 == 0 else balance.Throw(t.phase_rad, pairs[i // 2].z_m)
                for i, t in enumerate(engine.throws)
            ),
            cylinders=tuple(
                dataclasses.replace(c, z_m=pairs[(c.throw - 1) // 2].z_m) for c in engine.cylinders
            ),
        )
        staggered, unstaggered = balance.analyse(engine), balance.analyse(flat)
        unit = engine.per_cylinder_unit_n
        for k in (1, 2):
            a, b = staggered.order(k), unstaggered.order(k)
            assert_allclose(
                [a.moment_forward, a.moment_backward],
                [b.moment_forward, b.moment_backward],
                atol=1e-9 * unit,
            )


# -------------------------------------------------------------------------------- R1


def test_r1_fires_at_270_180_90_180():
    """Cylinder n (one bank, γ = 0) is at TDC when θ = −β_n: pins 0-270-90-180 put cylinders
    1-4 at 0°, 90°, 270°, 180°. Firing 1-3-2-4, each at its first TDC after the last
    (a four-stroke cylinder fires every other TDC): 1 at 0°, 3 at 270°, 2 at 90° + 360° =
    450°, 4 at 180° + 360° = 540°, 1 again at 720°: intervals 270°, 180°, 90°, 180°."""
    engine = balance.load(R1)
    beta = {
        c.number: math.degrees(engine.throws[c.throw_index].phase_rad) for c in engine.cylinders
    }
    tdc = {n: (-b) % 360.0 for n, b in beta.items()}
    assert tdc == {1: 0.0, 2: 90.0, 3: 270.0, 4: 180.0}
    angles = [0.0]
    for n in engine.firing_order[1:]:
        angle = tdc[n]
        while angle <= angles[-1]:
            angle += 360.0
        angles.append(angle)
    by_hand = [b - a for a, b in zip(angles, angles[1:] + [720.0], strict=True)]
    assert engine.firing_order == (1, 3, 2, 4)
    assert by_hand == [270.0, 180.0, 90.0, 180.0]
    assert_allclose(balance.analyse(engine).firing.intervals_deg, by_hand, atol=1e-5)


def test_r1_primary_couple_root_ten_and_no_secondary():
    """Pins 0-270-90-180 at z' = −1.5d..1.5d: Σe^{iβ} = 1 − i + i − 1 = 0,
    Σe^{2iβ} = 1 − 1 − 1 + 1 = 0 (no force of orders 1, 2);
    Σz'·e^{iβ} = −1.5 + 0.5i + 0.5i − 1.5 = −3 + i, |·| = √10: a primary couple √10·m·r·ω²·d
    along the axes (forward and backward halves: the R1's counter-rotating balancer);
    Σz'·e^{2iβ} = −1.5 + 0.5 − 0.5 + 1.5 = 0: no secondary couple."""
    engine = balance.load(R1)
    d = engine.throws[1].z_m - engine.throws[0].z_m
    mrw2 = engine.mean_reciprocating_kg * engine.crank_radius_m * engine.speed_rad_s**2
    result = balance.analyse(engine)
    o1, o2 = result.order(1), result.order(2)
    # exact zeros and values of sums of four phasors: rounding only
    assert abs(o1.force_forward) + abs(o1.force_backward) < 1e-9 * mrw2
    assert_allclose(
        [abs(o1.moment_forward), abs(o1.moment_backward)],
        [math.sqrt(10) / 2 * mrw2 * d] * 2,
        rtol=1e-9,
    )
    for value in (o2.force_forward, o2.force_backward, o2.moment_forward, o2.moment_backward):
        assert abs(value) < 1e-9 * mrw2


# --------------------------------------------------------------------- the library's notes


def _provenance(relative):
    data = tomllib.loads((CONFIGS / relative).read_text(encoding="utf-8"))
    return data, read_provenance(data, relative)


@pytest.mark.parametrize("relative", LIBRARY)
def test_every_number_of_every_library_file_cites_a_source_or_says_it_is_an_estimate(relative):
    """Each file gives sources; every selector of its sources and estimates names a key it
    has; every number in it (values with units, plain numbers, lists of them) is named by a
    source or by an estimate."""
    data, provenance = _provenance(relative)
    assert provenance.sources, f"{relative}: no sources"
    assert provenance.unknown_selectors(data) == [], relative
    assert provenance.unsourced(data) == [], relative


def test_the_h16s_estimates_counted_by_hand():
    """The H16 names as estimates: the lower crankshaft's phase, direction and y (3), the rod
    (1), the eight throws' z (8) and the two masses (2): 14 numbers."""
    data, provenance = _provenance("today/h/brm-h16.toml")
    assert len(provenance.estimated(data)) == 14
    # cycle, speed, crank radius, rod, vertical; two masses; two banks; the lower crankshaft's
    # y, direction and phase; the eight throws' phase and z
    assert len(number_paths(data)) == 5 + 2 + 2 + 3 + 16


def _listed(output):
    """{config: Estimates cell} of every row of ``balance list``'s tables."""
    rows = {}
    header = None
    for line in output.splitlines():
        if line.startswith("Config"):
            header = line
            continue
        if header and line.startswith("library:") and line.split()[0].endswith(".toml"):
            start = header.index("Estimates")
            end = header.index("Source")
            rows[line.split()[0]] = line[start:end].strip()
    return rows


def test_balance_list_shows_which_library_files_hold_estimates():
    """Every file of the library has a row whose Estimates cell is the number of its numbers
    that an estimate names ("none" where it has none: the Clerget, all from Tanaka's
    Appendix II)."""
    result = CliRunner().invoke(main, ["list"])
    assert result.exit_code == 0, result.output
    cells = _listed(result.output)
    assert len(cells) == len(LIBRARY)
    for relative in LIBRARY:
        data, provenance = _provenance(relative)
        count = len(provenance.estimated(data))
        assert cells[f"library:{relative}"] == (str(count) if count else "none"), relative
    assert cells["library:clerget-rotary.toml"] == "none"
    assert cells["library:today/h/brm-h16.toml"] == "14"
