"""The crank search: the enumeration against an independent brute force, the symmetry counts
against hand-derived closed forms, the papers' and textbooks' arrangements, and the search's
arguments (weights, limits, workers, progress)."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.cranksearch import parse_objective, search
from balance_cli.errors import AnalysisError, ConfigError
from tests.support import ROOT, TEMPLATES, inline_template_text, invoke, search_api
from tests.validation.reference import arrangements as reference  # independent: numpy only

#: coefficients are ratios of exact phasor sums: rounding of the FFT leaves about 1e-13
RTOL_COEFFICIENT = 1e-9


def inline_template(n, cycle, pitch_mm=500):
    """An in-line template (λ = 0.25, rotating masses too) written like a user's file."""
    throws = "\n".join(f'[[throws]]\nz = "{j * pitch_mm} mm"' for j in range(n))
    text = f"""name = "In-line {n}, {cycle}-stroke"
cycle = {cycle}
speed = "600 rpm"
crank_radius = "150 mm"
rod_length = "600 mm"
[masses]
reciprocating = "120 kg"
rotating = "80 kg"
[[banks]]
angle = 0
{throws}
"""
    import tomllib

    from balance_cli.config import build

    return build(tomllib.loads(text), f"<in-line {n}>", template=True)


def listed(result):
    """{canonical firing order: (score, coefficients)} of a search's list."""
    return {a.firing_order: (a.score, a.coefficients) for a in result.arrangements}


def template(name):
    return balance.load_template(TEMPLATES / name)


def orders_of(found):
    return [a.firing_order for a in found.arrangements]


SPEED = 2000 * 2 * math.pi / 60
NAKANISHI = [
    # template, force orders that vanish, his crank, primary couple (his eq. 2 and eq. 5)
    (
        "nakanishi-v12-90-2stroke.toml",
        5,
        (0, 120, 240, 60, 300, 180),
        480,
        60,
        2 * math.sqrt(3) * 0.15 * (2.84 + 3.12 + 2.0) * 0.08 * SPEED**2,
    ),
    (
        "nakanishi-w12-60-2stroke.toml",
        3,
        (0, 90, 270, 180),
        18,
        3,
        math.sqrt(10) * 0.15 * (1.5 * 2.84 + 4.68 + 2.0) * 0.08 * SPEED**2,
    ),
]


@pytest.mark.parametrize("n", [3, 4, 5, 6])
@pytest.mark.parametrize("cycle", [2, 4])
def test_every_distinct_arrangement_matches_the_brute_force(n, cycle):
    """Listing every distinct arrangement: the same firing orders as the reference's brute
    force (every slot permutation, no symmetry), with the same coefficients."""
    total, distinct, _ = reference.classes_count(n, cycle)
    found = search(inline_template(n, cycle), "F1,F2,M1,M2,M4", top=distinct, workers=1)
    assert (found.arrangements_total, found.arrangements_distinct) == (total, distinct)
    assert found.exhaustive
    mine = listed(found)
    assert len(mine) == distinct
    for arr in reference.distinct(reference.inline_arrangements(n, cycle)):
        order = reference.canonical_firing(arr)
        score, values = mine[order]
        expected = arr["F"][1] + arr["F"][2] + arr["M"][1] + arr["M"][2] + arr["M"][4]
        assert_allclose(score, expected, rtol=RTOL_COEFFICIENT, atol=1e-9)
        for k in (1, 2, 4):
            assert_allclose(values[f"F{k}"], arr["F"][k], atol=1e-9)
            assert_allclose(values[f"M{k}"], arr["M"][k], atol=1e-9)


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7])
@pytest.mark.parametrize("cycle", [2, 4])
def test_symmetry_counts_equal_the_hand_derived_closed_forms(n, cycle):
    """total = (n−1)!, distinct = (n−1)!/2 (n ≥ 3), the reference's closed forms, checked by
    its brute force too; the search evaluates at most about a quarter (reversal and mirror)."""
    total, distinct, _ = reference.classes_count_closed_form(n, cycle)
    assert (total, distinct) == reference.classes_count(n, cycle)[:2]
    assert total == math.factorial(n - 1)
    found = search(inline_template(n, cycle), "M1", top=1, workers=1)
    assert (found.arrangements_total, found.arrangements_distinct) == (total, distinct)
    cranks = total // found.firing_orders_per_crank
    assert found.evaluated + found.pruned <= cranks
    if cycle == 2 and n >= 6:  # few cranks are their own reversal or mirror image
        assert found.evaluated + found.pruned < 0.4 * cranks


@pytest.mark.parametrize("objective", ["M1", "M2", "F2:4,M1,M2", "F1+,M1-,M2", None])
def test_the_best_of_seven_cylinders_equal_the_brute_force(objective):
    """The ten best of 360 distinct arrangements, ties ranked by firing order, as the
    reference finds them by scoring every one."""
    terms = parse_objective(objective)
    ranked = []
    for arr in reference.distinct(reference.inline_arrangements(7, 2)):
        # in-line: the forward and backward parts of order k > 1 are half each (reciprocating
        # only); order 1 forward carries the rotating mass: (½·120 + 80)/200 of F1
        parts = {"max": 1.0, "forward": 140 / 200, "backward": 60 / 200}
        score = sum(
            t.weight
            * arr[t.kind][t.order]
            * (parts[t.part] if t.order == 1 else (1.0 if t.part == "max" else 0.5))
            for t in terms
        )
        ranked.append((round(score / 1e-9), reference.canonical_firing(arr), score))
    ranked.sort()
    found = search(inline_template(7, 2), objective, top=10, workers=1)
    assert [a.firing_order for a in found.arrangements] == [r[1] for r in ranked[:10]]
    # orders 6 and 8 (in the default objective) are ratios of forces a millionth of the
    # primary, which the FFT of positions of about the rod's length gives to ~1e-13 of the
    # primary: ~1e-7 in those coefficients
    atol = 1e-7 if objective is None else 1e-9
    assert_allclose(
        [a.score for a in found.arrangements],
        [r[2] for r in ranked[:10]],
        rtol=RTOL_COEFFICIENT,
        atol=atol,
    )


def test_inline_six_two_stroke_primary_and_secondary_couples():
    """Combustion Engines 2009 no. 4: 60 distinct arrangements; M1 = 0 leaves 1-5-3-4-2-6 with
    M2 = 2√3; M2 = 0 leaves 1-4-2-6-3-5 with M1 = 2√3 (the reference finds 2 and 4 of them)."""
    best_m1 = search(template("inline-6-2stroke.toml"), "M1", top=2)
    assert (best_m1.arrangements_total, best_m1.arrangements_distinct) == (120, 60)
    assert [a.score for a in best_m1.arrangements] == [0.0, 0.0]
    assert set(orders_of(best_m1)) == {(1, 5, 3, 4, 2, 6), (1, 4, 5, 2, 3, 6)}
    mine = next(a for a in best_m1.arrangements if a.firing_order == (1, 5, 3, 4, 2, 6))
    assert_allclose(mine.coefficients["M2"], 2 * math.sqrt(3), rtol=RTOL_COEFFICIENT)
    best_m2 = search(template("inline-6-2stroke.toml"), "M2", top=5)
    assert [a.score for a in best_m2.arrangements][:4] == [0.0] * 4
    assert best_m2.arrangements[4].score > 0.1
    other = next(a for a in best_m2.arrangements if a.firing_order == (1, 4, 2, 6, 3, 5))
    assert_allclose(other.coefficients["M1"], 2 * math.sqrt(3), rtol=RTOL_COEFFICIENT)


def test_inline_six_four_stroke_standard_crank_leaves_nothing_of_orders_one_and_two():
    """The standard crank with its firing orders (1-5-3-6-2-4 is 1-4-2-6-3-5 run the other
    way round) and its mirror image: the four the reference finds, and nothing else."""
    found = search(template("inline-6-4stroke.toml"), "F1,F2,M1,M2", top=5)
    assert found.firing_orders_per_crank == 4
    assert (found.arrangements_total, found.arrangements_distinct) == (120, 60)
    zero = {a.firing_order for a in found.arrangements if a.score == 0.0}
    assert zero == {(1, 2, 3, 6, 5, 4), (1, 2, 4, 6, 5, 3), (1, 3, 2, 6, 4, 5), (1, 4, 2, 6, 3, 5)}
    standard = next(a for a in found.arrangements if a.firing_order == (1, 4, 2, 6, 3, 5))
    assert standard.phases_deg in ((0, 120, 240, 240, 120, 0), (0, 240, 120, 120, 240, 0))


def test_inline_four_keeps_four_units_of_secondary_force_whatever_the_crank():
    found = search(template("inline-4-4stroke.toml"), "F2", top=3)
    assert found.arrangements_distinct == 3
    assert_allclose(
        [a.coefficients["F2"] for a in found.arrangements], [4.0] * 3, rtol=RTOL_COEFFICIENT
    )


def test_inline_three_couples_are_root_three():
    found = search(template("inline-3-2stroke.toml"), "M1,M2", top=1)
    assert found.arrangements_distinct == 1
    values = found.arrangements[0].coefficients
    assert_allclose([values["M1"], values["M2"]], [math.sqrt(3)] * 2, rtol=RTOL_COEFFICIENT)


@pytest.mark.parametrize("name,orders,crank,cranks,free,couple", NAKANISHI)
def test_nakanishi_cranks_are_among_the_force_free_ones(name, orders, crank, cranks, free, couple):
    """Every even-firing crank without force in orders 1–5 (V12) or 1–3 (W12), as many as the
    reference counts (120 and 6 cranks: 60 and 3 arrangements run either way), his among
    them with his primary couple (exact: only A₁ = 1 enters the primary)."""
    objective = ",".join(f"F{k}" for k in range(1, orders + 1))
    found = search(template(name), objective, top=free + 1)
    assert found.arrangements_total == cranks
    assert [a.score for a in found.arrangements[:free]] == [0.0] * free
    assert found.arrangements[free].score > 0.1
    reversed_crank = tuple((-p) % 360 for p in crank)
    his = [a for a in found.arrangements if a.phases_deg in (crank, reversed_crank)]
    assert len(his) == 1
    assert_allclose(
        his[0].result.order(1).moment_forward.__abs__()
        + abs(his[0].result.order(1).moment_backward),
        couple,
        rtol=1e-9,
    )


@pytest.mark.parametrize(
    "name,objective,crank",
    [
        (
            "nakanishi-v12-90-2stroke.toml",
            "F1,F2,F3,F4,F5,M2,M4,M1:0.01",
            (0, 120, 240, 60, 300, 180),
        ),
        ("nakanishi-w12-60-2stroke.toml", "F1,F2,F3,M2,M1:0.01", (0, 90, 270, 180)),
    ],
)
def test_nakanishi_crank_is_the_best_without_low_forces_and_secondary_couple(
    name, objective, crank
):
    """Asking also for no secondary (and fourth) couple and the least primary couple, his
    crank comes first: what he found by hand is proved optimal."""
    found = search(template(name), objective, top=2)
    assert found.exhaustive
    assert found.arrangements[0].phases_deg in (crank, tuple((-p) % 360 for p in crank))
    assert found.arrangements[1].score > found.arrangements[0].score + 0.01


def test_heuristic_is_labelled_and_finds_the_best_of_a_small_engine():
    eight = inline_template(8, 2)
    exact = search(eight, "M1,M2", top=1, workers=1)
    guess = search(eight, "M1,M2", top=1, heuristic=True, restarts=40, seed=1)
    assert (guess.exhaustive, guess.method) == (False, "heuristic")
    assert_allclose(guess.arrangements[0].score, exact.arrangements[0].score, atol=1e-9)


def test_uneven_cranks_on_a_grid_match_a_brute_force():
    """In-line 4 four-stroke, phases on a 90° grid: 4³ = 64 cranks, (64 + 8 self-reversed)/2
    = 36 distinct; the best scores as the in-line formula gives them for every crank."""
    found = search(
        inline_template(4, 4), "F1,F2,M1,M2", top=36, allow_uneven=True, step_deg=90.0, workers=1
    )
    assert (found.arrangements_total, found.arrangements_distinct) == (64, 36)
    z = np.arange(4) - 1.5
    scores = set()
    for tail in np.ndindex(4, 4, 4):
        beta = np.radians([0.0] + [90.0 * t for t in tail])
        f = [abs(np.exp(1j * k * beta).sum()) for k in (1, 2)]
        m = [abs((z * np.exp(1j * k * beta)).sum()) for k in (1, 2)]
        scores.add(round(sum(f) + sum(m), 6))
    assert sorted({round(a.score, 6) for a in found.arrangements}) == sorted(scores)
    assert not all(a.result.firing.uniform for a in found.arrangements)


@pytest.mark.parametrize(
    "text,key",
    [
        ('[[throws]]\nphase = 0\nz = "0 mm"\n[[throws]]\nz = "1 m"\n', "throws[1].phase"),
        ('firing_order = [1, 2]\n[[throws]]\nz = "0 mm"\n[[throws]]\nz = "1 m"\n', "firing_order"),
    ],
)
def test_a_template_gives_no_phases_and_no_firing_order(tmp_path, text, key):
    path = tmp_path / "t.toml"
    path.write_text(
        'name = "x"\ncycle = 2\nspeed = "1000 rpm"\ncrank_radius = "50 mm"\n'
        'rod_length = "200 mm"\n[masses]\nreciprocating = "1 kg"\n[[banks]]\n'
        "angle = 0\n" + text
    )
    with pytest.raises(ConfigError, match=key.replace("[", r"\[").replace("]", r"\]")):
        balance.load_template(path)


@pytest.mark.parametrize(
    "kwargs,parameter",
    [
        ({"objective": "Q1"}, "objective"),
        ({"objective": "F9"}, "objective"),
        ({"objective": "F2:-1"}, "objective"),
        ({"objective": "M1,M1"}, "objective"),
        ({"top": 0}, "top"),
        ({"workers": 0}, "workers"),
        ({"step_deg": 30.0}, "step_deg"),
        ({"allow_uneven": True}, "step_deg"),
        ({"allow_uneven": True, "step_deg": 7.0}, "step_deg"),
        ({"limit": 10}, "limit"),
    ],
)
def test_bad_search_settings_name_their_parameter(kwargs, parameter):
    with pytest.raises(AnalysisError) as caught:
        search(inline_template(6, 2), **kwargs)
    assert caught.value.parameter == parameter


def test_a_rotary_or_a_single_throw_has_nothing_to_arrange():
    rotary = balance.load(ROOT / "configs/clerget-rotary.toml")
    with pytest.raises(AnalysisError, match="rotary"):
        search(rotary)
    single = balance.load(ROOT / "configs/abc-dragonfly.toml")
    with pytest.raises(AnalysisError, match="one throw"):
        search(single)


def test_the_limit_is_the_count_of_cranks_over_the_symmetries():
    """What the limit refuses is known before enumerating: the cranks counted in closed form,
    (6 − 1)! = 120 for the in-line 6, over the reversal and the mirror image, 30. The
    symmetry conditions are not exact at their ties, so both enumerations evaluate or skip
    the 44 cranks (0, c1, ..., c5) (phase indices mod 6) a brute force over the 120 finds
    with (c1, c2) no greater than (−c1, −c2) and c1 at most the mirror key min(a, −a),
    a = c4 − c5."""
    assert invoke("search", TEMPLATES / "inline-6-2stroke.toml", "--limit", "30").exit_code == 0
    run = invoke("search", TEMPLATES / "inline-6-2stroke.toml", "--limit", "29")
    assert run.exit_code == 1 and "evaluates about 30" in run.output
    import itertools

    kept = 0
    for c in itertools.permutations(range(1, 6)):
        a = (c[3] - c[4]) % 6
        kept += (c[0], c[1]) <= ((-c[0]) % 6, (-c[1]) % 6) and c[0] <= min(a, (-a) % 6)
    assert kept == 44
    for enumeration in ("streamed", "tabled"):
        found = search(template("inline-6-2stroke.toml"), "M1", workers=1, enumeration=enumeration)
        assert found.evaluated + found.pruned == 44


def test_search_scores_scale_with_the_weights():
    """Weights of 1e100 and 1e-10 rank exactly as weights of 1 do (the score is linear in the
    weights); the scores are the same multiples."""
    import balance_cli as balance

    template = balance.load_template(TEMPLATES / "inline-6-2stroke.toml")
    plain = search_api(template, "M1,M2", top=6)
    for scale in (1e100, 1e-10):
        scaled = search_api(template, f"M1:{scale:g},M2:{scale:g}", top=6)
        assert [a.firing_order for a in scaled.arrangements] == [
            a.firing_order for a in plain.arrangements
        ]
        np.testing.assert_allclose(
            [a.score for a in scaled.arrangements],
            [scale * a.score for a in plain.arrangements],
            rtol=1e-12,
        )


def test_a_tiny_weight_still_ranks_the_smaller_coefficient_first():
    """Guards against ties absolute at 1e-9, with which M1:1e-10 ranked M1 = 5 above M1 = 0. The
    in-line 6 two-stroke has two cranks free of primary couple (1-5-3-6-2-4 and its mirror
    image, Den Hartog's table), so the first two listed have M1 = 0."""
    import balance_cli as balance

    template = balance.load_template(TEMPLATES / "inline-6-2stroke.toml")
    found = search_api(template, "M1:1e-10", top=4)
    m1 = [a.coefficients["M1"] for a in found.arrangements]
    np.testing.assert_allclose(m1[:2], 0.0, atol=1e-9)
    assert min(m1[2:]) > 0.5
    scores = np.array([a.score for a in found.arrangements])
    assert np.all(np.diff(scores) >= -1e-9 * scores.max())  # ranked by score, to its rounding


@pytest.mark.parametrize("n", [20, 21, 22, 23])
def test_a_template_too_large_is_refused_at_once_with_its_count(tmp_path, n):
    """Guards against a slow count: an in-line 20 to 22 took 38 to 253 s (1.7 GB) to count before
    the refusal, and an in-line 23 quoted 23^22/4 ≈ 2.3e29 cranks. Even firing leaves (n − 1)!
    cranks (Den Hartog), counted once with their reversal and evaluated once with their mirror: (n
    − 1)!/4 to evaluate."""
    import time

    import balance_cli as balance
    from balance_cli.errors import AnalysisError

    path = tmp_path / f"i{n}.toml"
    path.write_text(inline_template_text(n), encoding="utf-8")
    template = balance.load_template(path)
    started = time.perf_counter()
    with pytest.raises(AnalysisError) as caught:
        search_api(template, "M1")
    assert time.perf_counter() - started < 1.0
    assert caught.value.parameter == "limit"
    assert f"evaluates about {math.factorial(n - 1) // 4:,};" in str(caught.value)


def test_the_closed_form_count_is_the_dynamic_programmes():
    """The multinomial count of one-cylinder throws, (n − 1)!/((c − 1)!·c!^(P − 1)), against the
    count over lattice occupancies: in-line 10 two-stroke 9!, in-line 8 four-stroke 7!/2³."""
    from balance_cli.cranksearch import tables
    from balance_cli.cranksearch.problem import Problem

    for n, P, cap, expected in ((10, 10, 1, math.factorial(9)), (8, 4, 2, 630)):
        problem = Problem(
            n, P, 360.0 / P, np.zeros(n), cap, [[0]] * n, None, None, False, False, 1 + (n - 1) // 2
        )
        assert tables.count_cranks(problem) == expected
        assert tables._count_by_occupancy(problem) == expected


def test_the_pool_of_best_scores_is_linear_in_its_size():
    """Guards against a pool that sorted every score at every offer, quadratic in --top.
    Offering 200 000 distinct scores to a pool of 1000 now takes well under a second, and its
    threshold is the 1000th smallest score offered."""
    import time

    from balance_cli.cranksearch.kernel import Pool

    class Plain:
        def orbit_key(self, crank):
            return crank

    scores = np.random.default_rng(1).permutation(200_000) / 200_000
    pool = Pool(Plain(), 1000)
    started = time.perf_counter()
    for i, score in enumerate(scores):
        pool.offer(float(score), (i,))
    assert time.perf_counter() - started < 2.0
    kept = sorted(pool.best.values())[:1000]
    np.testing.assert_allclose(kept, np.arange(1000) / 200_000, rtol=0, atol=1e-15)


@pytest.mark.parametrize("weight", [math.nan, math.inf, -1.0, 0.0, "1", True])
def test_search_terms_with_a_weight_that_is_no_bound_are_refused(weight):
    """Guards against weights that are no bound: NaN or inf returned nothing and claimed
    exhaustive; a negative weight returned 7.0 where √52 exists (the bound assumes positive
    weights)."""
    import balance_cli as balance
    from balance_cli.cranksearch import Term
    from balance_cli.errors import AnalysisError

    template = balance.load_template(TEMPLATES / "inline-6-2stroke.toml")
    with pytest.raises(AnalysisError) as caught:
        search_api(template, [Term("M", 1), Term("M", 2, weight=weight)])
    assert caught.value.parameter == "objective"
    assert "M2: the weight must be a positive number" in str(caught.value)


def test_workers_are_capped_at_what_helps_and_reported_as_run():
    """Guards against --workers 1000 reporting 1000 workers while about 460 processes ran, and
    took 4.5 s instead of 1 s."""
    import balance_cli as balance
    from balance_cli.cranksearch import search
    from balance_cli.cranksearch.parallel import _cores

    template = balance.load_template(TEMPLATES / "inline-6-2stroke.toml")
    found = search(template, "M1", top=2, workers=1000)
    assert 1 <= found.workers <= _cores()
    assert [a.firing_order for a in found.arrangements] == [
        a.firing_order for a in search_api(template, "M1", top=2).arrangements
    ]


def test_progress_covers_the_listed_arrangements_analyses():
    """Guards against a silent wait: progress reached 100 % before the listed arrangements were
    analysed (minutes with a large --top). Now the analyses are counted, and progress ends at its
    total only when the result is ready."""
    import balance_cli as balance

    template = balance.load_template(TEMPLATES / "inline-6-2stroke.toml")
    calls = []
    found = search_api(
        template, "M1", top=5, progress=lambda done, total: calls.append((done, total))
    )
    totals = {total for _, total in calls}
    assert len(totals) == 1
    total = totals.pop()
    assert calls[-1][0] == total
    assert [done for done, _ in calls] == sorted(done for done, _ in calls)
    # the last five calls are the five analyses, one each
    assert [done for done, _ in calls[-5:]] == list(range(total - 4, total + 1))
    assert len(found.arrangements) == 5
