"""The streamed enumeration: the same arrangements as the tabled one (every prefix and suffix
tabled at once, the former method), its work units counted by hand, and the channels it
merges."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.cranksearch import search
from balance_cli.cranksearch.problem import merge_channels
from tests.cranksearch.test_search import inline_template
from tests.support import TEMPLATES

#: both enumerations add the same phasors in another order: rounding of sums of order one
RTOL_ORDER_OF_SUMS = 1e-12


def both(template, objective, **options):
    return [
        search(template, objective, workers=1, enumeration=enumeration, **options)
        for enumeration in ("tabled", "streamed")
    ]


def assert_same_list(tabled, streamed):
    """The same arrangements in the same order with the same scores, and the same pairs
    covered (evaluated + skipped by bound: both apply the same symmetry conditions)."""
    assert [a.firing_order for a in streamed.arrangements] == [
        a.firing_order for a in tabled.arrangements
    ]
    assert [a.phases_deg for a in streamed.arrangements] == [
        a.phases_deg for a in tabled.arrangements
    ]
    assert_allclose(
        [a.score for a in streamed.arrangements],
        [a.score for a in tabled.arrangements],
        rtol=RTOL_ORDER_OF_SUMS,
        atol=1e-12,
    )
    assert streamed.evaluated + streamed.pruned == tabled.evaluated + tabled.pruned
    assert streamed.exhaustive and tabled.exhaustive


@pytest.mark.parametrize("n", [8, 9, 10, 11, 12])
def test_streamed_and_tabled_list_the_same_in_line_two_strokes(n):
    tabled, streamed = both(inline_template(n, 2), "M1,M2,M3,M4", top=12)
    assert_same_list(tabled, streamed)
    # each crank with throw 1 at 0° once: (n − 1)!, of which a quarter or more is covered
    assert streamed.arrangements_total == math.factorial(n - 1)
    assert streamed.evaluated + streamed.pruned >= math.factorial(n - 1) // 4


@pytest.mark.parametrize(
    "n, objective, top",
    [(8, "M1,M2,M4", 20), (10, "F2,M1,M2", 10), (12, "M1,M2,M4", 10), (9, "M1,M2", 10)],
)
def test_streamed_and_tabled_list_the_same_in_line_four_strokes(n, objective, top):
    """Two cylinders on each lattice point (even n): the general enumeration, not the
    permutation table of one cylinder a point."""
    assert_same_list(*both(inline_template(n, 4), objective, top=top))


@pytest.mark.parametrize("objective", ["F1,F2,F3,F4,F5,M2,M4,M1:0.01", "M1,M2", "F1+,M1-,M2:2,M4"])
def test_streamed_and_tabled_list_the_same_v12(objective):
    """Nakanishi's 90° V12: two cylinders a throw, forward and backward parts that do not
    merge (its V pairs are not on one line)."""
    template = balance.load_template(TEMPLATES / "nakanishi-v12-90-2stroke.toml")
    assert_same_list(*both(template, objective, top=30))


def test_streamed_and_tabled_list_the_same_uneven_cranks():
    """Without even firing there is one occupancy, which the streamed plan splits by heads."""
    template = inline_template(7, 2)
    assert_same_list(*both(template, "M1,M2,F1", top=15, allow_uneven=True, step_deg=45))


def test_streamed_and_tabled_agree_with_ties_beyond_the_top():
    """The in-line 12 has many cranks free of primary couple: fifty listed, all tied at 0."""
    tabled, streamed = both(inline_template(12, 2), "M1", top=50)
    assert_same_list(tabled, streamed)
    assert_allclose([a.coefficients["M1"] for a in streamed.arrangements], 0.0, atol=1e-9)


def test_an_in_line_14s_units_are_small_and_cover_every_crank(monkeypatch):
    """Counted by hand: throw 1 at point 0 and the prefix throws 2..7 fill 6 of the other 13
    points, C(13, 6) = 1716 occupancies; each holds 6! prefixes and 7! suffixes (the rest in
    every order), 13! cranks in all. A worker builds one unit's tables at a time: 5040 rows of
    7 phases, never the 1.2 million prefixes and 17 million suffixes tabled before."""
    from balance_cli.cranksearch import run
    from balance_cli.cranksearch.units import Enumerator, plan_units

    captured = {}

    def plan(problem):
        captured["problem"] = problem
        raise _Stop

    monkeypatch.setattr(run, "plan_units", plan)
    with pytest.raises(_Stop):
        search(inline_template(14, 2), "M1,M2", workers=1)
    problem = captured["problem"]
    units, pairs = plan_units(problem)
    assert len(units) == math.comb(13, 6)
    assert set(pairs) == {math.factorial(6) * math.factorial(7)}
    assert sum(pairs) == math.factorial(13)
    digits, head = units[0]
    enumerator = Enumerator(problem)
    suffixes, sums = enumerator.rows(list(range(7, 14)), 1 - np.array(digits, np.int8))
    assert suffixes.shape == (math.factorial(7), 7) and sums.shape[0] == math.factorial(7)
    first = np.zeros(14, np.int8)
    first[0] = 1
    prefixes, _ = enumerator.rows(list(range(1, 7)), np.array(digits, np.int8) - first)
    assert prefixes.shape == (math.factorial(6), 6)
    # every prefix with every suffix fills each point once: an even-firing crank
    crank = np.concatenate([[0], prefixes[0], suffixes[0]])
    assert sorted((-crank) % 14) == list(range(14))


class _Stop(Exception):
    pass


def test_forward_and_backward_channels_merge_and_a_constant_is_set_aside():
    """By hand: channel b = 2i·conj(a) at every throw and phase has |Σ b| = 2·|Σ a| for every
    crank, so a alone with weight 1 + 2·0.5 = 2 scores alike; channel c, the same phasor at
    every phase (3 and 4 on two throws), adds 0.25·|3 + 4| = 1.75 to every score; a channel
    of zeros is dropped."""
    rng = np.random.default_rng(3)
    a = rng.normal(size=(2, 5)) + 1j * rng.normal(size=(2, 5))
    b = 2j * a.conj()
    c = np.array([[3.0] * 5, [4.0] * 5]).astype(complex)
    rotated = np.stack([a, b, c, np.zeros((2, 5))], axis=2)
    kept, weights, largest, offset = merge_channels(rotated, [1.0, 0.5, 0.25, 7.0], None)
    assert kept.shape == (2, 5, 1)
    assert_allclose(kept[:, :, 0], a, rtol=0, atol=0)
    assert_allclose(weights, [2.0], rtol=1e-15)
    assert largest is None
    assert_allclose(offset, 1.75, rtol=1e-15)


def test_an_in_line_engine_needs_half_its_channels(monkeypatch):
    """An in-line engine's throws all point one way: each order's backward sum is its forward
    sum's conjugate times a fixed factor, so M1, M2, M4 take three channels, not six (M3 is
    zero with plain rods: A₃ = 0)."""
    from balance_cli.cranksearch import run

    captured = {}
    original = run.plan_units

    def plan(problem):
        captured["channels"] = problem.rotated.shape[2]
        return original(problem)

    monkeypatch.setattr(run, "plan_units", plan)
    search(inline_template(8, 2), "M1,M2,M3,M4", workers=1)
    assert captured["channels"] == 3
