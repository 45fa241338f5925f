"""Matching weighed parts to cylinders: Tanaka's Dragonfly (Part I § 5, Table III) against a
brute force over all 9! assignments of his pistons; an in-line 4's pistons and rods against a
brute force over all 576 assignments scored by the test's own slider-crank kinematics; the
engine as assembled, written and read back; the heuristic; every error."""

import dataclasses
import itertools
import math
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.errors import AnalysisError, ConfigError
from balance_cli.units import STANDARD_GRAVITY
from balance_cli.workshop import GRID, PartSet, Piston, Rod, assembled_toml
from tests.support import CONFIGS, JUMO

DATA = Path(__file__).resolve().parent / "data"
#: Table III: the piston side of each con. rod, g (Main, 1, ..., 8): it stays in its cylinder
SMALL_ENDS_G = [423.4, 302.6, 298.5, 298.1, 300.6, 291.9, 292.2, 299.4, 299.2]
DRAGONFLY_R, DRAGONFLY_OMEGA = 0.0825, 1650 * math.pi / 30


@pytest.fixture(scope="module")
def dragonfly():
    """The Dragonfly with each cylinder's reciprocating mass its rod's small end plus the mean
    piston: the engine with every piston at the mean of its kind, the rods where they are."""
    parts = balance.read_parts_csv(DATA / "dragonfly-table-iii-pistons.csv")
    engine = balance.load(CONFIGS / "abc-dragonfly.toml")
    mean = parts.mean_piston_kg()
    cylinders = tuple(
        dataclasses.replace(c, reciprocating_kg=mean + g / 1000)
        for c, g in zip(engine.cylinders, SMALL_ENDS_G, strict=True)
    )
    return engine.replace(cylinders=cylinders), parts


@pytest.fixture(scope="module")
def dragonfly_match(dragonfly):
    engine, parts = dragonfly
    return balance.match(engine, parts, "F1")


def _primary_kgf(deviations_kg):
    """Tanaka's (14)₁: the primary the deviations m_n of cylinders at n·40° leave (Σ m_n = 0),
    a circle of radius ½·ω²·r·|Σ m_n·e^{2i·n·40°}|, in kgf. Exact for the primary: a link
    rod's piston moves r·cos(θ − γ) at the first order as a plain rod's does."""
    gamma = np.radians(40.0 * np.arange(9))
    total = deviations_kg @ np.exp(2j * gamma)
    return 0.5 * DRAGONFLY_OMEGA**2 * DRAGONFLY_R * np.abs(total) / STANDARD_GRAVITY


def test_table_iii_as_tanaka_fitted_it_leaves_19_6_kg_at_minus_17_degrees(dragonfly_match):
    """The pistons in his order make Table III's sums; their deviations from 1,770.4 g leave
    ΣX₁' = 19.6·cos(θ − 17°) kg (Part I § 5 (a) (i)): a circle of 19.6 kg turning against the
    crank, at −17° when θ = 0."""
    given = dragonfly_match.given
    sums = [c.reciprocating_kg for c in given.engine.cylinders]
    table_iii = [1867.3, 1775.6, 1737.5, 1766.2, 1767.5, 1757.5, 1727.9, 1760.8, 1772.9]
    # grams to kilograms: float rounding only
    assert_allclose(np.array(sums) * 1000, table_iii, rtol=1e-12)
    first = given.difference.order(1)
    kgf = abs(first.force_backward) / STANDARD_GRAVITY
    # printed to 0.1 kg and whole degrees
    assert_allclose(kgf, 19.6, atol=0.05)
    assert_allclose(math.degrees(np.angle(first.force_backward)), -17.0, atol=0.5)
    assert abs(first.force_forward) < 1e-9 * abs(first.force_backward)  # Σ m_n = 0
    # Tanaka's closed form (14)₁ on the same masses agrees to rounding
    assert_allclose(kgf, _primary_kgf(np.array(sums) - np.mean(sums)), rtol=1e-12)
    assert_allclose(given.score_n / STANDARD_GRAVITY, kgf, rtol=1e-12)


def test_the_best_assignment_of_his_nine_pistons_is_the_brute_forces(dragonfly, dragonfly_match):
    """Every one of the 9! = 362 880 assignments of the pistons scored by (14)₁, vectorised:
    the least primary, and the assignment that makes it, are the matching's."""
    _, parts = dragonfly
    pistons = np.array([p.mass_kg for p in parts.pistons])
    small = np.array(SMALL_ENDS_G) / 1000
    perms = np.array(list(itertools.permutations(range(9))))
    masses = pistons[perms] + small
    primaries = _primary_kgf(masses - masses.mean(axis=1, keepdims=True))
    best = int(np.argmin(primaries))
    # one assignment is best by a clear margin (no tie within 1e-6)
    assert np.sum(primaries < primaries[best] * (1 + 1e-6)) == 1
    result = dragonfly_match
    assert result.exhaustive and result.assignments_total == math.factorial(9)
    assert result.evaluated == result.assignments_distinct
    assert result.best.pistons == tuple(parts.pistons[i].id for i in perms[best])
    assert_allclose(result.best.score_n / STANDARD_GRAVITY, primaries[best], rtol=1e-12)
    print(f"matched primary {primaries[best]:.3f} kg against 19.6 kg as fitted")
    assert primaries[best] < 5.2  # about a quarter of the 19.6 kg as fitted


def test_the_master_rods_asymmetry_leaves_no_symmetry_to_use(dragonfly_match):
    """A radial's mirror symmetry about its master cylinder carries the link rods' small ends
    onto each other only where they weigh the same; Table III's do not, so none is used."""
    assert dragonfly_match.symmetries == 1


# --- an in-line 4 with four pistons and four rods, by the test's own kinematics -------------

R, L, RPM = 0.043, 0.143, 6000.0
OMEGA = RPM * math.pi / 30
PHASES = np.radians([0.0, 180.0, 180.0, 0.0])
Z = np.array([0.0, 0.088, 0.176, 0.264])
INLINE_4 = """\
name = "In-line 4"
cycle = 4
speed = "6000 rpm"
crank_radius = "43 mm"
rod_length = "143 mm"
firing_order = [1, 3, 4, 2]

[masses]
reciprocating = "550 g"
rotating = "560 g"

[[banks]]
angle = 0
""" + "".join(
    f'\n[[throws]]\nphase = {p:g}\nz = "{z * 1000:g} mm"\n'
    for p, z in zip(np.degrees(PHASES), Z, strict=True)
)
PISTONS_G = [402.3, 398.1, 405.0, 400.2]
RODS_G = [(151.0, 412.0), (148.2, 405.5), (150.1, 409.9), (149.0, 415.3)]
PARTS_CSV = (
    "kind,id,mass\n"
    + "".join(f"piston,P{i + 1},{g} g\n" for i, g in enumerate(PISTONS_G))
    + "".join(
        f"rod_small,R{i + 1},{s} g\nrod_big,R{i + 1},{b} g\n" for i, (s, b) in enumerate(RODS_G)
    )
)
THETA = 2 * np.pi * np.arange(GRID) / GRID


def _acceleration(theta):
    """x''(θ)/ω² of a slider-crank's piston pin, x = r·cos θ + √(l² − r²·sin²θ), differentiated
    by hand."""
    s = np.sqrt(L**2 - R**2 * np.sin(theta) ** 2)
    return (
        -R * np.cos(theta) - R**2 * np.cos(2 * theta) / s - R**4 * np.sin(2 * theta) ** 2 / 4 / s**3
    )


#: each cylinder's inertia force per kg of piston (along the axis: real) and per kg at its
#: crank pin (r·ω²·e^{i(θ+β)}), over the grid
PISTON_FORCE = np.array([-(OMEGA**2) * _acceleration(THETA + b) for b in PHASES]) + 0j
PIN_FORCE = np.array([R * OMEGA**2 * np.exp(1j * (THETA + b)) for b in PHASES])
LEVER = Z - Z.mean()
PITCH = 0.088


def _scores(reciprocating, rotating):
    """The default objective of masses (assignments, cylinders), kg: of the deviations from the
    mean, the largest force over the grid plus the largest moment over it / pitch."""
    dr = reciprocating - reciprocating.mean(axis=1, keepdims=True)
    db = rotating - rotating.mean(axis=1, keepdims=True)
    force = dr @ PISTON_FORCE + db @ PIN_FORCE
    moment = (dr * LEVER) @ PISTON_FORCE + (db * LEVER) @ PIN_FORCE
    return np.abs(force).max(axis=1) + np.abs(moment).max(axis=1) / PITCH


@pytest.fixture(scope="module")
def inline_4(tmp_path_factory):
    folder = tmp_path_factory.mktemp("inline4")
    (folder / "engine.toml").write_text(INLINE_4, encoding="utf-8")
    (folder / "parts.csv").write_text(PARTS_CSV, encoding="utf-8")
    return folder


def _brute_force():
    """Every (pistons, rods) assignment: 4!·4! = 576, scored by the test's kinematics."""
    pistons = np.array(PISTONS_G) / 1000
    small = np.array([s for s, _ in RODS_G]) / 1000
    big = np.array([b for _, b in RODS_G]) / 1000
    perms = np.array(list(itertools.permutations(range(4))))
    sigma = np.repeat(perms, len(perms), axis=0)
    rho = np.tile(perms, (len(perms), 1))
    return sigma, rho, _scores(pistons[sigma] + small[rho], big[rho])


def test_the_in_line_4s_best_is_the_brute_forces_over_576(inline_4):
    """The same grid of 4320 angles (the objective's own definition, every 1/12°); the
    library's coefficients from 256 samples, evaluated on it: agreement to rounding."""
    engine = balance.load(inline_4 / "engine.toml")
    result = balance.match(engine, inline_4 / "parts.csv")
    sigma, rho, scores = _brute_force()
    assert len(scores) == 576 == result.assignments_total
    # the mirror image (1↔4, 2↔3) scores alike: 288 classes, each evaluated once
    assert result.symmetries == 2 and result.evaluated == 288
    assert_allclose(result.best.score_n, scores.min(), rtol=1e-9)
    ids = [f"P{i + 1}" for i in range(4)], [f"R{i + 1}" for i in range(4)]
    chosen = [
        k
        for k in range(len(scores))
        if tuple(ids[0][i] for i in sigma[k]) == result.best.pistons
        and tuple(ids[1][i] for i in rho[k]) == result.best.rods
    ]
    assert_allclose(scores[chosen[0]], scores.min(), rtol=1e-9)
    given = _scores(
        np.array([PISTONS_G]) / 1000 + np.array([[s for s, _ in RODS_G]]) / 1000,
        np.array([[b for _, b in RODS_G]]) / 1000,
    )[0]
    assert_allclose(result.given.score_n, given, rtol=1e-9)
    assert_allclose(result.gain_n, given - scores.min(), rtol=1e-9)
    # as assembled: each cylinder its piston and small end, each throw its big end
    for row in result.best.cylinder_rows():
        p = PISTONS_G[int(row["piston"][1:]) - 1]
        s, b = RODS_G[int(row["rod"][1:]) - 1]
        assert_allclose(
            [row["reciprocating_kg"], row["rotating_kg"]], [(p + s) / 1000, b / 1000], rtol=1e-12
        )


def test_terms_are_scored_exactly_per_order(inline_4):
    """F1 alone: the order-1 force of the deviations, |F⁺| + |F⁻| by hand from the masses
    (a piston's first order is m·r·ω²·cos(θ + β) along the axis; a big end's m·r·ω² turns)."""
    engine = balance.load(inline_4 / "engine.toml")
    result = balance.match(engine, inline_4 / "parts.csv", "F1")
    sigma, rho, _ = _brute_force()
    pistons = np.array(PISTONS_G) / 1000
    small = np.array([s for s, _ in RODS_G]) / 1000
    big = np.array([b for _, b in RODS_G]) / 1000
    dr = pistons[sigma] + small[rho]
    dr = dr - dr.mean(axis=1, keepdims=True)
    db = big[rho] - big[rho].mean(axis=1, keepdims=True)
    signs = np.cos(PHASES)
    # forward: ½·Σ dr·e^{iβ} + Σ db·e^{iβ}; backward ½·Σ dr·e^{−iβ}; all β are 0 or 180°
    forward = np.abs((0.5 * dr + db) @ signs)
    backward = np.abs(0.5 * dr @ signs)
    f1 = R * OMEGA**2 * (forward + backward)
    assert_allclose(result.best.score_n, f1.min(), rtol=1e-9, atol=1e-9)
    assert result.objective.label == "F1"


def test_the_heuristic_is_labelled_and_finds_the_in_line_4s_best(inline_4):
    engine = balance.load(inline_4 / "engine.toml")
    exhaustive = balance.match(engine, inline_4 / "parts.csv")
    heuristic = balance.match(engine, inline_4 / "parts.csv", heuristic=True, restarts=10)
    assert heuristic.method == "heuristic" and not heuristic.exhaustive
    assert heuristic.to_dict()["exhaustive"] is False
    # nothing beats the proved best; on four cylinders the exchanges reach it
    assert heuristic.best.score_n >= exhaustive.best.score_n * (1 - 1e-12)
    assert_allclose(heuristic.best.score_n, exhaustive.best.score_n, rtol=1e-9)
    # beyond the limit the heuristic is taken unless refused
    assert balance.match(engine, inline_4 / "parts.csv", limit=10).method == "heuristic"
    with pytest.raises(AnalysisError, match="limit is 10, but an exhaustive"):
        balance.match(engine, inline_4 / "parts.csv", limit=10, heuristic=False)


def test_the_engine_as_matched_is_written_and_reads_back(inline_4):
    """The configuration written holds each cylinder's and throw's masses to 12 digits, and
    analyses as the engine the matching reported."""
    engine = balance.load(inline_4 / "engine.toml")
    result = balance.match(engine, inline_4 / "parts.csv")
    data = balance.read_configuration(inline_4 / "engine.toml").data
    text = assembled_toml(data, engine, result.best.engine, "test", "In-line 4, as matched")
    written = balance.loads(text, "written.toml")
    assert written.name == "In-line 4, as matched"
    for a, b in zip(written.cylinders, result.best.engine.cylinders, strict=True):
        assert_allclose(a.reciprocating_kg, b.reciprocating_kg, rtol=1e-11)  # 12 digits
    assert [t.rotating_kg for t in written.throws] == pytest.approx(
        [t.rotating_kg for t in result.best.engine.throws], rel=1e-11
    )
    again = balance.analyse(written)
    for k in (1, 2):
        assert_allclose(
            abs(again.order(k).force_forward),
            abs(result.best.assembled.order(k).force_forward),
            rtol=1e-9,
        )


def test_pistons_alone_keep_the_rods_share_of_the_configuration(inline_4):
    """With pistons only, a cylinder's mass is the configuration's less the mean piston plus
    its own: 550 g − 401.4 g + its piston."""
    engine = balance.load(inline_4 / "engine.toml")
    parts = PartSet(tuple(Piston(f"P{i}", g / 1000) for i, g in enumerate(PISTONS_G, 1)))
    result = balance.match(engine, parts)
    mean = np.mean(PISTONS_G)
    for c, piston in zip(result.given.engine.cylinders, PISTONS_G, strict=True):
        assert_allclose(c.reciprocating_kg * 1000, 550 - mean + piston, rtol=1e-12)
    assert all(t.rotating_kg is None for t in result.given.engine.throws)


def test_parts_that_do_not_fit_are_refused_naming_why(inline_4):
    engine = balance.load(inline_4 / "engine.toml")
    three = PartSet(tuple(Piston(f"P{i}", 0.4) for i in range(3)))
    with pytest.raises(AnalysisError, match="parts lists 3 pistons for the 4 cylinders"):
        balance.match(engine, three)
    dragonfly = balance.load(CONFIGS / "abc-dragonfly.toml")
    rods = PartSet(rods=tuple(Rod(f"R{i}", 0.3, 0.5) for i in range(9)))
    with pytest.raises(AnalysisError, match="master and link rods, which are not"):
        balance.match(dragonfly, rods)
    jumo = balance.load(JUMO)
    pistons = PartSet(tuple(Piston(f"P{i}", 1.0) for i in range(jumo.n_cylinders)))
    with pytest.raises(AnalysisError, match="opposed pistons"):
        balance.match(jumo, pistons)
    with pytest.raises(AnalysisError, match="H4 is not a force or moment"):
        balance.match(engine, inline_4 / "parts.csv", "F1,H4")
    with pytest.raises(AnalysisError, match="parts must be a PartSet"):
        balance.match(engine, 42)
    with pytest.raises(ConfigError, match="no such file"):
        balance.match(engine, inline_4 / "missing.csv")
    with pytest.raises(AnalysisError, match="has the id 'P' twice"):
        PartSet((Piston("P", 0.4), Piston("P", 0.5)))
