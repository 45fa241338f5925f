"""Crank arrangements by brute force, written apart from balance as an independent second method.

Nothing here imports ``balance_cli``: only numpy and the standard library. The module
enumerates every even-firing crank (and firing order) of an engine, computes its shaking
forces and free moments from the Fourier series of the plain slider crank, and counts the
arrangements up to running the engine the other way round; the counts are checked against
closed forms derived by hand (below).

Conventions
-----------
- The transverse plane is the complex plane: real part along the reference axis ("up"),
  imaginary part across; angles are positive in the direction of crank rotation.
- Crank angle θ = angle of throw 1 from the reference axis. Throw j sits at θ + β_j (β_1 = 0).
  A cylinder whose axis points at bank angle γ, on a throw of phase β, is at top dead centre
  when θ ≡ γ − β (mod 360°). Two-stroke (``cycle = 2``): each cylinder fires at each of its
  TDCs, the cycle is 360°. Four-stroke (``cycle = 4``): it fires at one of its two TDCs in a
  720° cycle. In general the cycle is C = 180°·cycle.
- Slider crank, crank radius r, rod l, no pin offset: s(φ) = r cos φ + sqrt(l² − r² sin² φ),
  φ = crank angle from the cylinder axis. The reciprocating inertia force along the axis is
  −m·s̈ = m ω² r Σ_k A_k cos kφ, with A_k = k²·c_k/r, c_k the cosine coefficients of s(φ)
  (FFT on 4096 points). A_1 = 1 exactly; A_k = 0 exactly for odd k ≥ 3 because
  s − r cos φ is a function of sin² φ (set to 0, after checking the FFT gives < 1e-10).
  A cylinder on bank γ on a throw of phase β has φ = θ + β − γ and force direction e^{iγ}:
  order-k phasors F⁺ = ½ m ω² r A_k e^{ik(β−γ)} e^{iγ}, F⁻ = ½ m ω² r A_k e^{−ik(β−γ)} e^{iγ}
  (F(θ) = F⁺ e^{ikθ} + F⁻ e^{−ikθ}). A rotating mass at the pin adds m_rot r ω² e^{iβ} to F⁺
  of order 1. The largest order-k force over a revolution is |F⁺| + |F⁻|.
- Free moment of order k: Σ (z − z̄)·(force phasor) over cylinders and throws (z the axial
  position of the throw, z̄ the mean over cylinders), reported the same way (|M⁺| + |M⁻|).
- Coefficients: F_k = (largest order-k resultant) / (largest order-k force of one throw alone,
  with all its cylinders and its pin mass); M_k = (largest order-k free moment) / (that
  one-throw force × mean throw pitch d). Where the one-throw force of order k is zero (odd
  k ≥ 3 with plain rods; below 1e-12 of the largest order of that throw) the coefficient is 0.
  In-line with equal pitch: F_k = |Σ_j e^{ikβ_j}|, M_k = |Σ_j (j − (N+1)/2) e^{ikβ_j}| for k = 1
  and even k, independent of masses and rod ratio (checked in :func:`self_check`).

Arrangements (in-line)
----------------------
An arrangement is a crank (β_j, β_1 = 0) with a firing order (a cyclic sequence of cylinder
numbers written from cylinder 1). Even firing: cylinder 1 fires at 0 and the n cylinders take
the n slots 0, C/n, 2C/n, … of the cycle; cylinder j firing at a_j needs β_j ≡ −a_j (mod 360).
:func:`inline_arrangements` goes through every permutation of the slots (no symmetry
reduction) and derives the crank, the firing order and the coefficients.

Reversal (running the engine the other way round) is θ → −θ: the crank β → −β and the firing
order read backwards (1-5-3-4-2-6 ~ 1-6-2-4-3-5); "distinct" counts each pair once and names it
by the member whose firing order is lexicographically smaller. Mirror (the crank read from the
other end): throw j ↔ throw n+1−j, cylinder j → n+1−j, renormalised so that the new throw 1 is
at 0 and the new cylinder 1 fires at 0: β'_j = β_{n+1−j} − β_n, the firing order rotated to
start at cylinder n and relabelled. A mirror image balances alike but is a different
arrangement.

Closed forms (derived by hand, checked against the brute force for n ≤ 7)
-------------------------------------------------------------------------
Measure firing angles in slots: an arrangement is a bijection a: {1..n} → Z_n with a(1) = 0
(a(j) = slot of cylinder j). The firing order is the slots read in increasing order and the
crank is β_j = −a(j)·C/n mod 360, so arrangement ↔ a is one-to-one, for two-stroke (C = 360)
AND four-stroke (C = 720): in four-stroke several firing orders share one crank, but a pair
(crank, firing order) is still fixed by a. Hence the counts are the same for both cycles:

- total = (n − 1)!  (slots of cylinders 2..n).
- Reversal is a ↦ −a (slot p ↦ n − p: the order read backwards; crank β ↦ −β). A fixed point
  needs 2a(j) ≡ 0 for every j, i.e. at most the two slots 0 and n/2, so none for n ≥ 3:
  distinct = (n − 1)!/2 for n ≥ 3 (and 1 for n = 1, 2).
- Mirror is a ↦ a', a'(j) = a(n+1−j) − a(n). It commutes with reversal (a' of −a is −a'), so a
  class {a, −a} is mirror-fixed iff a' = a (case M) or a' = −a (case R); for n ≥ 3 both
  cannot hold (a = −a is impossible), and each case is closed under reversal, so
  mirror_fixed = (#M + #R)/2.
  Case M: j = n gives 2a(n) ≡ 0, a(n) ≠ 0, so n = 2m is even, a(n) = m, and
  a(n+1−j) = a(j) + m: the cylinder pairs {j, n+1−j} go onto the value pairs {x, x+m}; pair
  {1, n} onto {0, m}, the other m − 1 pairs in (m − 1)! ways with 2 orientations each:
  #M = (m − 1)!·2^(m−1) (n even), 0 (n odd).
  Case R: a(j) + a(n+1−j) ≡ c := a(n) ≠ 0 for every j: a carries the involution j ↦ n+1−j of
  the cylinders onto x ↦ c − x of Z_n, pair {1, n} onto {0, c}.
  n odd: the middle cylinder goes to the single fixed value c/2 (≠ 0, c); c is any of n − 1
  values; the other (n−3)/2 pairs in ((n−3)/2)!·2^((n−3)/2) ways:
  #R = (n − 1)·((n−3)/2)!·2^((n−3)/2).
  n = 2m even: the cylinders have no fixed point, so x ↦ c − x must have none: c odd (m
  choices); the other m − 1 pairs: #R = m·(m − 1)!·2^(m−1).
  So mirror_fixed = (n − 1)·((n−3)/2)!·2^((n−3)/2)/2 for odd n ≥ 3 (1, 4, 24 for n = 3, 5, 7)
  and (m + 1)·(m − 1)!·2^(m−1)/2 for n = 2m ≥ 4 (3, 16 for n = 4, 6); 1 for n = 1, 2.

V and W engines
---------------
:func:`v_or_w_arrangements`: one cylinder per bank on every throw, all in the throw's plane
(same z). With cylinder (bank 1, throw 1) at TDC, hence firing, at θ = γ_1, even firing means
the TDC angles γ_b − β_j (mod 360) are the firing lattice γ_1 + k·C/N (k = 0..N−1, N cylinders,
taken mod 360: each lattice point once in two-stroke). Every β_j lies on the lattice, so the
cranks (β_1 = 0) are found by backtracking over lattice phases, counting TDC hits.
"""

import itertools
import math
from collections import Counter
from functools import cache

import numpy as np

#: highest order computed
KMAX = 8
#: relative size below which a one-throw force counts as zero (coefficient then 0)
_DEN_TOL = 1e-12
#: default geometry for in-line coefficients (they do not depend on it)
_INLINE_GEOMETRY = dict(m_rec=1.0, m_rot=0.0, r=1.0, rod=4.0, omega=1.0, pitch=1.0)


def _reduce(x):
    """A degree value reduced to [0, 360) (values within 1e-9 of 360 become 0)."""
    x = float(x) % 360.0
    return 0.0 if x > 360.0 - 1e-9 or x == 0 else x


def _angle_key(x):
    """A degree value reduced to [0, 360) and rounded to 1e-6° for hashing."""
    x = round(_reduce(x), 6)
    return 0.0 if x >= 360.0 else x


# ---------------------------------------------------------------------------------------------
# slider crank and phasors


@cache
def slider_crank_coefficients(r, rod, kmax=KMAX, points=4096):
    """A_k, k = 0..kmax, of the plain slider crank: the reciprocating inertia force along the
    cylinder axis is m ω² r Σ A_k cos kφ. A_0 = 0, A_1 = 1, odd k ≥ 3 set exactly to 0."""
    phi = 2 * np.pi * np.arange(points) / points
    s = r * np.cos(phi) + np.sqrt(rod**2 - (r * np.sin(phi)) ** 2)
    spectrum = np.fft.rfft(s) / points
    c = 2 * spectrum.real  # s is even in φ: cosine coefficients
    k = np.arange(kmax + 1)
    a = k**2 * c[: kmax + 1] / r
    a[0] = 0.0
    assert abs(a[1] - 1) < 1e-10, a[1]
    for odd in range(3, kmax + 1, 2):
        assert abs(a[odd]) < 1e-10, (odd, a[odd])
        a[odd] = 0.0
    return tuple(float(x) for x in a)


def throw_phasors(phases_deg, banks_deg, m_rec, m_rot, r, rod, omega, kmax=KMAX):
    """Order-k force phasors of every throw with its cylinders and pin mass.

    Returns (plus, minus), complex arrays of shape (kmax + 1, n_throws) in N (row k; row 0 is
    zero): F_throw(θ) = plus[k] e^{ikθ} + minus[k] e^{−ikθ}. ``m_rec`` is per cylinder,
    ``m_rot`` per throw."""
    beta = np.deg2rad(np.asarray(phases_deg, float))[None, :, None]
    gamma = np.deg2rad(np.asarray(banks_deg, float))[None, None, :]
    k = np.arange(kmax + 1)[:, None, None]
    a = np.asarray(slider_crank_coefficients(float(r), float(rod), kmax))[:, None, None]
    half = 0.5 * m_rec * omega**2 * r * a
    plus = (half * np.exp(1j * k * (beta - gamma)) * np.exp(1j * gamma)).sum(axis=2)
    minus = (half * np.exp(-1j * k * (beta - gamma)) * np.exp(1j * gamma)).sum(axis=2)
    if kmax >= 1:
        plus[1] += m_rot * r * omega**2 * np.exp(1j * beta[0, :, 0])
    return plus, minus


def engine_phasors(phases_deg, banks_deg, m_rec, m_rot, r, rod, omega, pitch, kmax=KMAX):
    """Resultant force and free moment phasors, and the one-throw force, orders 0..kmax.

    Throws at z = 0, pitch, 2·pitch, …; every throw carries one cylinder per bank. Returns a
    dict of arrays indexed by k: ``F_plus``, ``F_minus`` (N), ``M_plus``, ``M_minus`` (N·m, about
    the mean z of the cylinders), ``force_max`` = |F⁺| + |F⁻|, ``moment_max`` = |M⁺| + |M⁻|,
    ``one_throw`` (largest order-k force of one throw alone), and coefficients ``F``, ``M``."""
    plus, minus = throw_phasors(phases_deg, banks_deg, m_rec, m_rot, r, rod, omega, kmax)
    n = plus.shape[1]
    z = pitch * np.arange(n)
    lever = z - z.mean()  # every throw has the same cylinders: mean over cylinders = over throws
    out = {
        "F_plus": plus.sum(axis=1),
        "F_minus": minus.sum(axis=1),
        "M_plus": (plus * lever).sum(axis=1),
        "M_minus": (minus * lever).sum(axis=1),
    }
    out["force_max"] = np.abs(out["F_plus"]) + np.abs(out["F_minus"])
    out["moment_max"] = np.abs(out["M_plus"]) + np.abs(out["M_minus"])
    one_plus, one_minus = throw_phasors([0.0], banks_deg, m_rec, m_rot, r, rod, omega, kmax)
    one = np.abs(one_plus[:, 0]) + np.abs(one_minus[:, 0])
    out["one_throw"] = one
    alive = one > _DEN_TOL * one.max()
    safe = np.where(alive, one, 1.0)
    d = pitch  # mean throw pitch of equally spaced throws
    out["F"] = np.where(alive, out["force_max"] / safe, 0.0)
    out["M"] = np.where(alive, out["moment_max"] / (safe * d), 0.0) if n > 1 else np.zeros(kmax + 1)
    return out


# ---------------------------------------------------------------------------------------------
# in-line arrangements


def _inline_from_slots(slots, n, cycle, coefficients=True):
    """The arrangement whose cylinder j fires in slot ``slots[j-1]`` (slots[0] = 0)."""
    span = 180.0 * cycle
    firing_deg = tuple(s * span / n for s in slots)
    phases = tuple(_reduce(-a) for a in firing_deg)
    firing = tuple(j + 1 for j in sorted(range(n), key=lambda j: slots[j]))
    arr = {"phases_deg": phases, "firing": firing, "firing_angles_deg": firing_deg}
    if coefficients:
        g = _INLINE_GEOMETRY
        ph = engine_phasors(
            phases, [0.0], g["m_rec"], g["m_rot"], g["r"], g["rod"], g["omega"], g["pitch"]
        )
        arr["F"] = {k: float(ph["F"][k]) for k in range(1, KMAX + 1)}
        arr["M"] = {k: float(ph["M"][k]) for k in range(1, KMAX + 1)}
    return arr


def inline_arrangements(n, cycle, coefficients=True):
    """Every even-firing arrangement of an in-line engine of ``n`` cylinders (throws at
    z = 0, d, 2d, …, cylinder j on throw j), ``cycle`` 2 or 4, by brute force over the
    permutations of the firing slots, without any symmetry reduction.

    Each item: ``phases_deg`` (β_j in [0, 360)), ``firing`` (starting with 1),
    ``firing_angles_deg`` (of cylinders 1..n), ``F`` and ``M`` (dicts k -> coefficient,
    k = 1..8; 0 for odd k ≥ 3)."""
    if cycle not in (2, 4):
        raise ValueError("cycle must be 2 or 4")
    out = []
    for rest in itertools.permutations(range(1, n)):
        out.append(_inline_from_slots((0,) + rest, n, cycle, coefficients))
    return out


def key(arr):
    """Hashable identity of an arrangement: (crank phases, firing order)."""
    return (tuple(_angle_key(b) for b in arr["phases_deg"]), tuple(arr["firing"]))


def reverse(arr):
    """The same arrangement run the other way round: β → −β, firing order read backwards."""
    firing = tuple(arr["firing"])
    out = dict(arr)
    out["phases_deg"] = tuple(_reduce(-b) for b in arr["phases_deg"])
    out["firing"] = (firing[0],) + firing[:0:-1]
    out.pop("firing_angles_deg", None)
    return out  # |Σ e^{-ikβ}| = |Σ e^{ikβ}|: F and M carry over


def mirror(arr):
    """The crank read from the other end (throw j ↔ n+1−j, cylinder j → n+1−j), renormalised so
    that throw 1 is at 0 and the firing order starts with cylinder 1. Coefficients carry over."""
    phases = list(arr["phases_deg"])
    firing = list(arr["firing"])
    n = len(phases)
    new_phases = tuple(_reduce(phases[n - 1 - j] - phases[n - 1]) for j in range(n))
    start = firing.index(n)
    rotated = firing[start:] + firing[:start]
    out = dict(arr)
    out["phases_deg"] = new_phases
    out["firing"] = tuple(n + 1 - c for c in rotated)
    out.pop("firing_angles_deg", None)
    return out


def canonical_firing(arr):
    """Canonical name of the class of ``arr``: the lexicographically smaller of its firing order
    and the reversed one."""
    return min(tuple(arr["firing"]), reverse(arr)["firing"])


def distinct(arrangements):
    """One member per class under reversal: the one whose firing order is lexicographically
    smaller (built by reversal if the list lacks it), in the order classes first appear."""
    present = {key(a): a for a in arrangements}
    classes = {}
    for a in arrangements:
        r = reverse(a)
        chosen = a if tuple(a["firing"]) <= tuple(r["firing"]) else r
        k = key(chosen)
        if k not in classes:
            classes[k] = present.get(k, chosen)
    return list(classes.values())


def classes_count_closed_form(n, cycle):
    """(total, distinct, mirror_fixed) from the hand derivation in the module docstring (the
    same for two- and four-stroke)."""
    if cycle not in (2, 4):
        raise ValueError("cycle must be 2 or 4")
    if n <= 2:
        return 1, 1, 1
    total = math.factorial(n - 1)
    if n % 2:
        h = (n - 3) // 2
        fixed = (n - 1) * math.factorial(h) * 2**h // 2
    else:
        m = n // 2
        fixed = (m + 1) * math.factorial(m - 1) * 2 ** (m - 1) // 2
    return total, total // 2, fixed


def classes_count(n, cycle):
    """(total, distinct, mirror_fixed) by brute force on the arrangements of
    :func:`inline_arrangements`: total (crank, firing order) pairs, classes under reversal,
    and classes containing their own mirror image. For n ≤ 7 the result is asserted equal to
    :func:`classes_count_closed_form`."""
    arrs = inline_arrangements(n, cycle, coefficients=False)
    keys = {key(a) for a in arrs}
    classes = {}
    for a in arrs:
        cls = frozenset((key(a), key(reverse(a))))
        assert key(reverse(a)) in keys, "reversal left the set of arrangements"
        classes.setdefault(cls, a)
    fixed = 0
    for cls, a in classes.items():
        m = key(mirror(a))
        assert m in keys, "mirror left the set of arrangements"
        fixed += m in cls
    result = (len(keys), len(classes), fixed)
    if n <= 7:
        expected = classes_count_closed_form(n, cycle)
        assert result == expected, (n, cycle, result, expected)
    return result


# ---------------------------------------------------------------------------------------------
# V and W engines


def v_or_w_arrangements(
    bank_angles_deg, n_throws, cycle, m_rec, m_rot, r, rod, pitch, omega, kmax=KMAX
):
    """Every even-firing crank (β_1 = 0, phases on the firing lattice) of an engine with one
    cylinder per bank on each of ``n_throws`` throws, all in the throw's plane.

    ``m_rec`` per cylinder (kg), ``m_rot`` per throw (kg), ``r``, ``l``, ``pitch`` in m, ``omega``
    in rad/s. Each item: ``phases_deg``; ``firing`` (two-stroke only: (throw, bank index) pairs,
    1-based, in firing order from (1, 1); None for four-stroke, where a crank admits several);
    ``F_plus``, ``F_minus`` (N), ``M_plus``, ``M_minus`` (N·m): dicts k -> complex, k = 1..kmax;
    ``force_max``, ``moment_max``, ``one_throw`` (dicts k -> float); ``F``, ``M`` (coefficients).
    """
    banks = [float(g) for g in bank_angles_deg]
    n_banks = len(banks)
    n_cyl = n_banks * n_throws
    span = 180.0 * cycle
    step = span / n_cyl
    target = Counter(_angle_key(k * step) for k in range(n_cyl))  # TDC offsets from γ_1
    lattice = sorted({_angle_key(k * step): _reduce(k * step) for k in range(n_cyl)}.values())
    offsets = [b - banks[0] for b in banks]

    found = []

    def hits(beta):
        return [_angle_key(o - beta) for o in offsets]

    def extend(phases, used):
        if len(phases) == n_throws:
            found.append(tuple(phases))
            return
        for beta in lattice:
            h = hits(beta)
            new = used.copy()
            new.update(h)
            if all(new[x] <= target.get(x, 0) for x in h):
                extend(phases + [beta], new)

    first = Counter(hits(0.0))
    if all(first[x] <= target.get(x, 0) for x in first):
        extend([0.0], first)

    out = []
    for phases in found:
        ph = engine_phasors(phases, banks, m_rec, m_rot, r, rod, omega, pitch, kmax)
        item = {"phases_deg": phases}
        if cycle == 2:
            tdc = {
                (j + 1, b + 1): _angle_key(banks[b] - phases[j] - banks[0])
                for j in range(n_throws)
                for b in range(n_banks)
            }
            item["firing"] = tuple(sorted(tdc, key=lambda c: tdc[c]))
        else:
            item["firing"] = None
        for name in ("F_plus", "F_minus", "M_plus", "M_minus"):
            item[name] = {k: complex(ph[name][k]) for k in range(1, kmax + 1)}
        for name in ("force_max", "moment_max", "one_throw", "F", "M"):
            item[name] = {k: float(ph[name][k]) for k in range(1, kmax + 1)}
        out.append(item)
    return out


def rpm_to_rad_s(rpm):
    """Angular speed in rad/s of ``rpm`` revolutions per minute."""
    return rpm * 2 * math.pi / 60


# ---------------------------------------------------------------------------------------------


def self_check(max_n=7):
    """Internal consistency: the coefficients against the in-line closed forms
    F_k = |Σ e^{ikβ}|, M_k = |Σ (j − (N+1)/2) e^{ikβ}|, the class counts against the hand
    derivation, and the in-line 3 two-stroke value M1 = M2 = √3."""
    for cycle in (2, 4):
        for n in range(1, max_n + 1):
            classes_count(n, cycle)
            for a in inline_arrangements(n, cycle):
                beta = np.deg2rad(a["phases_deg"])
                lever = np.arange(1, n + 1) - (n + 1) / 2
                for k in range(1, KMAX + 1):
                    if k > 1 and k % 2:
                        assert a["F"][k] == 0 and a["M"][k] == 0
                        continue
                    f = abs(np.exp(1j * k * beta).sum())
                    m = abs((lever * np.exp(1j * k * beta)).sum())
                    assert abs(a["F"][k] - f) < 1e-9 and abs(a["M"][k] - m) < 1e-9, (a, k)
    (i3,) = distinct(inline_arrangements(3, 2))
    assert abs(i3["M"][1] - math.sqrt(3)) < 1e-12 and abs(i3["M"][2] - math.sqrt(3)) < 1e-12
    return True
