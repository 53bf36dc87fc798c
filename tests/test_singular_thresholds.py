"""Where each forward-dynamics method stops answering: a joint whose ``sᵀAs`` vanishes.

Every recursive method (``aba``: single-state plan, batched plan, general array
path; ``projective``; ``mobility_split``; ``stacked``) applies one rule
(:data:`planargeo.errors.COND_LIMIT`): with ``A`` and ``s`` at the joint's own
point ``P`` (its pivot), ``cond = ‖A_P‖_F ‖s_P‖² / σ_min(sᵀAs)`` and the joint is
singular when ``cond > 1e12`` (``docs/simulation.md``, "One rule for singular joints");
the rule does not change when the whole mechanism is moved.  The methods that form
``sᵀAs`` at the global origin round it by ``ε ‖A_O‖ ‖s_O‖²`` (``ε cond_O``, with
``cond_O`` the same ratio at the origin), which is what their tolerances below allow.

The cases are small enough to solve by hand (Lagrange's equations in the
relative angles, written out below), so neither the reference accelerations nor
the condition numbers come from the code under test:

* a point mass at distance ``d`` from its pivot (one link);
* a uniform rod carrying a point-mass tip at distance ``d`` from the second
  joint (two links: the tip joint at ``(L cos q1, L sin q1)``, away from the
  origin: the rule is the pendulum's there, while ``sᵀAs`` formed at the origin cancels);
* a tip body pinned at its centre of mass with radius of gyration ``ρ → 0``;
* a point-mass tip exactly on its joint (nothing along ``s``), and a very light
  (but not massless: ``Body`` refuses mass 0) tip, which the scale-free rule accepts.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from planargeo.algorithms.aba import articulated_body, forward_dynamics
from planargeo.algorithms.chain_splitting import forward_dynamics_mobility_split
from planargeo.algorithms.crba import forward_dynamics_crba
from planargeo.algorithms.projective import forward_dynamics_projective
from planargeo.algorithms.stacked import forward_dynamics_stacked
from planargeo.errors import InputError, SingularConfigurationError
from planargeo.mechanics.model import Body, Joint, Model
from planargeo.errors import COND_LIMIT

EPS = np.finfo(float).eps
G = 9.81


def _batched(m, q, qd, tau):
    # 40 copies: a batch
    k = 40
    return forward_dynamics(m, np.tile(q, (k, 1)), np.tile(qd, (k, 1)), np.tile(tau, (k, 1)))[k // 2]


METHODS = {
    "aba": forward_dynamics,
    "aba_batch": _batched,
    "aba_general": lambda m, q, qd, tau: articulated_body(m, q, qd, tau).qdd,
    "projective": forward_dynamics_projective,
    "mobility_split": forward_dynamics_mobility_split,
    "stacked": forward_dynamics_stacked,
}
D_SWEEP = [10.0 ** (-3 - k / 2) for k in range(13)]          # 1e-3 ... 1e-9, half decades
#: relative error allowed before the threshold: C_TOL ε cond (measured worst over the sweeps: 0.9 ε cond,
#: mobility_split on rod_and_tip; the methods forming sᵀAs at the origin 0.08-0.55 ε cond, aba's plan < 1e-6 ε cond)
C_TOL = 4


def _call(f, m, q, qd, tau):
    """``("ok", q̈)`` or ``("raise", cond)``."""
    try:
        return "ok", np.asarray(f(m, np.asarray(q, float), np.asarray(qd, float), np.asarray(tau, float)))
    except SingularConfigurationError as e:
        return "raise", e.cond


def _rel(x, ref):
    return float(np.linalg.norm(np.asarray(x) - ref) / np.linalg.norm(ref))


# -- hand-derived cases ---------------------------------------------------------------
def pendulum(d, q=0.4, tau=0.3, m=1.0):
    """One point mass ``m`` at distance ``d`` from a pivot at the origin.

    ``m d² q̈ = τ - m g d cos q``.  At the origin the inertia is
    ``m [[1, 0, -y], [0, 1, x], [-y, x, d²]]`` with ``(x, y) = d (cos q, sin q)``,
    ``s = [0, 0, 1]`` (the pivot is the origin): ``cond = √(2 + 2d² + d⁴) / d²``.
    """
    model = Model([Body(m, (d, 0.0), 0.0)], [Joint("revolute")], [-1])
    qdd = np.array([(tau - m * G * d * math.cos(q)) / (m * d * d)])
    cond = math.sqrt(2 + 2 * d * d + d ** 4) / (d * d)
    return model, [q], [0.7], [tau], qdd, cond


#: the rounding scale ``cond_O`` of the methods forming sᵀAs at the origin, per case (hand, see each docstring)
COND_O = {}


def rod_and_tip(d, q=(0.3, 0.2), qd=(0.1, -0.2), tau=(0.5, 0.0), m1=1.0, L=1.0, m2=1.0):
    """A uniform rod (``m1``, length ``L``, pinned at the origin) carrying a point mass ``m2`` at ``d`` from joint 2.

    Relative angles ``q1, q2``; ``c = cos q2``, ``s = sin q2``, ``c12 = cos(q1 + q2)``.
    Lagrange: ``H q̈ + h + g = τ`` with ``J1 = m1 L²/12``, ``K1 = J1 + m1 L²/4``::

        H11 = K1 + m2 (L² + d² + 2 L d c)   H12 = m2 (d² + L d c)   H22 = m2 d²
        h1 = -m2 L d s (2 q̇1 q̇2 + q̇2²)     h2 = m2 L d s q̇1²
        g1 = g ((m1/2 + m2) L cos q1 + m2 d c12)   g2 = g m2 d c12

    ``det H = m2 d² K`` with ``K = K1 + m2 L² s²``; with ``τ2 = 0`` write ``r = τ - h - g``,
    ``r2 = d ρ2``, ``ρ2 = -m2 (L s q̇1² + g c12)``; Cramer's rule, the cancellations done by hand::

        q̈1 = (r1 - r2 - L c ρ2) / K
        q̈2 = (K1 + m2 L² + m2 L d c) ρ2 / (m2 d K) - (1 + L c / d) (r1 - r2) / K

    The tip joint (articulated inertia = the tip's own) at its point ``P`` (the pivot):
    mass at ``d`` from ``P``, ``A_P = m2 [[1, 0, -δy], [0, 1, δx], [-δy, δx, d²]]``, ``s_P = [0, 0, 1]``,
    ``sᵀAs = m2 d²``: ``cond = √(2 + 2d² + d⁴) / d²``, the pendulum's, whatever ``L`` and ``q1``.
    At the origin instead (the rounding scale ``cond_O`` of the methods forming ``sᵀAs`` there):
    mass at ``p``, ``|p|² = R``, ``‖A_O‖_F = m2 √(1 + (1 + R)²)``, ``s_O = [L sin q1, -L cos q1, 1]``,
    ``‖s_O‖² = 1 + L²``.  Joint 1 sees ``K ≥ K1``: never singular.
    """
    assert tau[1] == 0.0
    q1, q2 = q
    w1, w2 = qd
    c, s, c1, c12 = math.cos(q2), math.sin(q2), math.cos(q1), math.cos(q1 + q2)
    K1 = m1 * L * L / 3
    K = K1 + m2 * L * L * s * s
    h1 = -m2 * L * d * s * (2 * w1 * w2 + w2 * w2)
    g1 = G * ((m1 / 2 + m2) * L * c1 + m2 * d * c12)
    r1 = tau[0] - h1 - g1
    rho2 = -m2 * (L * s * w1 * w1 + G * c12)
    r2 = d * rho2
    qdd1 = (r1 - r2 - L * c * rho2) / K
    qdd2 = (K1 + m2 * L * L + m2 * L * d * c) * rho2 / (m2 * d * K) - (1 + L * c / d) * (r1 - r2) / K
    px = L * c1 + d * c12
    py = L * math.sin(q1) + d * math.sin(q1 + q2)
    R = px * px + py * py
    cond = math.sqrt(2 + 2 * d * d + d ** 4) / (d * d)
    COND_O[("rod_and_tip", d, L)] = math.sqrt(1 + (1 + R) ** 2) * (1 + L * L) / (d * d)
    model = Model([Body(m1, (L / 2, 0.0), m1 * L * L / 12), Body(m2, (d, 0.0), 0.0)],
                  [Joint("revolute"), Joint("revolute", (L, 0.0, 0.0))], [-1, 0])
    return model, list(q), list(qd), list(tau), np.array([qdd1, qdd2]), cond


def tip_pinned_at_com(rho, q=(0.3, 0.2), tau=(0.5, 0.2), m1=1.0, L=1.0, m2=1.0):
    """A rod carrying a body pinned at its own centre of mass, radius of gyration ``ρ`` (``J2 = m2 ρ²``).

    No coupling through the tip's mass (it sits on joint 2): ``H = [[K2 + J2, J2], [J2, J2]]``
    with ``K2 = m1 L²/3 + m2 L²``, no velocity terms, ``g2 = 0``,
    ``g1 = g (m1/2 + m2) L cos q1``: ``q̈1 = (τ1 - g1 - τ2) / K2``, ``q̈2 = τ2 / J2 - q̈1``.
    At the tip's pivot ``P`` (its centre): ``A_P = diag(m2, m2, J2)``, ``s_P = [0, 0, 1]``,
    ``sᵀAs = J2``: ``cond = √(2 m2² + J2²) / J2``.  At the origin (``cond_O``; centre at
    ``L (cos q1, sin q1)``): ``‖A_O‖_F² = m2² (2 + 2L²) + (J2 + m2 L²)²``, ``‖s_O‖² = 1 + L²``.
    """
    J2 = m2 * rho * rho
    K2 = m1 * L * L / 3 + m2 * L * L
    qdd1 = (tau[0] - G * (m1 / 2 + m2) * L * math.cos(q[0]) - tau[1]) / K2
    qdd2 = tau[1] / J2 - qdd1
    cond = math.sqrt(2 * m2 * m2 + J2 * J2) / J2
    COND_O[("tip_pinned_at_com", rho, L)] = math.sqrt(m2 * m2 * (2 + 2 * L * L) + (J2 + m2 * L * L) ** 2) * (1 + L * L) / J2
    model = Model([Body(m1, (L / 2, 0.0), m1 * L * L / 12), Body(m2, (0.0, 0.0), J2)],
                  [Joint("revolute"), Joint("revolute", (L, 0.0, 0.0))], [-1, 0])
    return model, list(q), [0.4, -0.3], list(tau), np.array([qdd1, qdd2]), cond


CASES = {"pendulum": pendulum, "rod_and_tip": rod_and_tip, "tip_pinned_at_com": tip_pinned_at_com}


def cond_O(case, d, cond, L=1.0):
    """The hand rounding scale at the origin (``cond`` itself for the pendulum, pinned at the origin)."""
    CASES[case](d)
    return COND_O.get((case, d, L), cond)


#: (case, d) of the sweeps on either side of the threshold (by the hand condition numbers; 20 % clear of it,
#: far more than the methods' rounding of cond there, ε cond_O ≲ 1e-3)
BEFORE = [(c, d) for c in CASES for d in D_SWEEP if CASES[c](d)[5] < COND_LIMIT / 1.2]
PAST = [(c, d) for c in CASES for d in D_SWEEP if CASES[c](d)[5] > 1.2 * COND_LIMIT]


def test_closed_forms_agree_with_each_other_where_they_overlap():
    # a check of the hand algebra itself: at q2 = 0 and rest, K = K1 and q̈1 = (τ1 - g1 - r2 - L ρ2) / K1
    _, _, _, _, qdd, _ = rod_and_tip(0.1, q=(0.3, 0.0), qd=(0.0, 0.0))
    g1 = G * (1.5 * math.cos(0.3) + 0.1 * math.cos(0.3))
    rho2 = -G * math.cos(0.3)
    assert qdd[0] == pytest.approx((0.5 - g1 - 0.1 * rho2 - rho2) / (1 / 3), rel=1e-14)
    # and the dense 2x2 solve of the hand-written H, h, g (well conditioned at d = 0.5)
    d, (q1, q2), (w1, w2) = 0.5, (0.3, 0.2), (0.1, -0.2)
    c, s = math.cos(q2), math.sin(q2)
    H = np.array([[1 / 3 + 1 + d * d + 2 * d * c, d * d + d * c], [d * d + d * c, d * d]])
    h = np.array([-d * s * (2 * w1 * w2 + w2 * w2), d * s * w1 * w1])
    g = G * np.array([1.5 * math.cos(q1) + d * math.cos(q1 + q2), d * math.cos(q1 + q2)])
    ref = np.linalg.solve(H, np.array([0.5, 0.0]) - h - g)
    np.testing.assert_allclose(rod_and_tip(d)[4], ref, rtol=1e-13)


def test_the_sweeps_cross_the_threshold():
    for c in CASES:
        assert sum(1 for x in BEFORE if x[0] == c) >= 4 and sum(1 for x in PAST if x[0] == c) >= 4, c
    assert len(BEFORE) + len(PAST) == len(CASES) * len(D_SWEEP)      # no sweep point near the threshold


@pytest.mark.parametrize("case, d", BEFORE)
def test_before_the_threshold_every_method_matches_the_closed_form(case, d):
    model, q, qd, tau, ref, cond = CASES[case](d)
    cO = cond_O(case, d, cond)
    for name, f in METHODS.items():
        kind, out = _call(f, model, q, qd, tau)
        assert kind == "ok", (name, out, cond)
        err = _rel(out, ref)
        assert err <= C_TOL * EPS * cO + 4 * EPS, (name, err, EPS * cO)
    # the dense reference answers too (its own rule, on H), within ε cond(H)
    kind, out = _call(forward_dynamics_crba, model, q, qd, tau)
    if kind == "ok":
        H_cond = np.linalg.cond(_hand_H(case, model, d))
        assert _rel(out, ref) <= C_TOL * EPS * H_cond + 4 * EPS


def _hand_H(case, model, d):
    if case == "pendulum":
        return np.array([[d * d]])
    if case == "rod_and_tip":
        c = math.cos(0.2)
        return np.array([[1 / 3 + 1 + d * d + 2 * d * c, d * d + d * c], [d * d + d * c, d * d]])
    J2 = d * d
    return np.array([[4 / 3 + J2, J2], [J2, J2]])


@pytest.mark.parametrize("case, d", PAST)
def test_past_the_threshold_every_recursive_method_raises_with_the_condition_number(case, d):
    model, q, qd, tau, ref, cond = CASES[case](d)
    cO = cond_O(case, d, cond)
    for name, f in METHODS.items():
        kind, out = _call(f, model, q, qd, tau)
        assert kind == "raise", (name, out, cond)
        assert out > COND_LIMIT, name
        # the value is the hand-derived one up to the method's rounding of sᵀAs (ε cond_O relative)
        if EPS * cO < 0.1:
            assert out == pytest.approx(cond, rel=C_TOL * EPS * cO + 1e-12), (name, out, cond)


@pytest.mark.parametrize("case", list(CASES))
def test_methods_agree_on_which_states_raise_and_on_cond(case):
    raised = {}
    for d in D_SWEEP:
        model, q, qd, tau, ref, cond = CASES[case](d)
        verdicts = {name: _call(f, model, q, qd, tau) for name, f in METHODS.items()}
        kinds = {v[0] for v in verdicts.values()}
        assert len(kinds) == 1, (d, verdicts)
        raised[d] = kinds.pop() == "raise"
        assert raised[d] == (cond > COND_LIMIT), (d, cond)
        cO = cond_O(case, d, cond)
        if raised[d] and EPS * cO < 1e-3:
            conds = [v[1] for v in verdicts.values()]
            assert max(conds) / min(conds) - 1 <= 2 * C_TOL * EPS * cO
    # the sweep crosses the threshold once: small d raise, large d do not
    flags = [raised[d] for d in D_SWEEP]
    assert flags == sorted(flags) and any(flags) and not all(flags)


def test_threshold_is_where_the_hand_condition_number_crosses_the_limit():
    # pendulum: cond = √(2 + 2d² + d⁴)/d² = 1e12 at d* ≈ (√2 · 1e-12)^(1/2) = 1.189e-6; just either side
    dstar = math.sqrt(math.sqrt(2) / COND_LIMIT)
    for factor, raises in ((1.01, False), (0.99, True)):
        model, q, qd, tau, ref, cond = pendulum(dstar * factor)
        for name, f in METHODS.items():
            kind, out = _call(f, model, q, qd, tau)
            assert (kind == "raise") == raises, (name, factor, out)


def test_point_mass_tip_on_its_joint_raises_everywhere_with_infinite_cond():
    model, q, qd, tau, _, _ = rod_and_tip(1.0)
    model = Model([model.bodies[0], Body(1.0, (0.0, 0.0), 0.0)], list(model.joints), [-1, 0])
    for name, f in METHODS.items():
        kind, out = _call(f, model, q, qd, tau)
        # sᵀAs is 0 exactly; formed at the origin (where the tip joint is not) it is rounding, ~ε ‖A‖ ‖s‖²
        assert kind == "raise" and out > 0.01 / EPS, (name, kind, out)
    assert _call(forward_dynamics, model, q, qd, tau) == ("raise", math.inf)   # the plan forms it at the joint
    # the dense reference refuses too: H22 = 0 (its own rule, on H)
    with pytest.raises(SingularConfigurationError, match="mass matrix H is singular"):
        forward_dynamics_crba(model, q, qd, tau)


def test_a_massless_body_is_refused_up_front_and_a_light_tip_is_not_singular():
    with pytest.raises(InputError, match="mass must be positive"):
        Body(0.0, (0.1, 0.0), 0.0)
    # the rule is scale-free: a tip of mass 1e-30 at d = 0.1 is as regular as a heavy one
    model, q, qd, tau, ref, cond = rod_and_tip(0.1, m2=1e-30)
    assert cond < 1e4
    for name, f in METHODS.items():
        kind, out = _call(f, model, q, qd, tau)
        assert kind == "ok", (name, out)
        assert _rel(out, ref) < 1e-12, name


def test_the_tip_joint_away_from_the_origin_does_not_change_the_condition():
    # the same point-mass tip d from its joint: measured at the joint, cond = √(2 + 2d² + d⁴)/d² (hand) whether
    # the rod is 1 or 10 long; the rule used to be measured at the origin, where L = 10 gave ~1e13 and was refused
    d = 3e-5
    _, _, _, _, _, c1 = rod_and_tip(d, L=1.0)
    model, q, qd, tau, ref, c10 = rod_and_tip(d, L=10.0)
    assert c1 == c10 == pytest.approx(math.sqrt(2 + 2 * d * d + d ** 4) / (d * d), rel=1e-15)
    assert c10 < COND_LIMIT / 100
    cO = COND_O[("rod_and_tip", d, 10.0)]
    assert cO > COND_LIMIT                                  # what the old rule measured
    for name, f in METHODS.items():
        kind, out = _call(f, model, q, qd, tau)
        assert kind == "ok", (name, out)
        # the methods forming sᵀAs at the origin round it by ε cond_O; aba's plans work at the joint
        tol = 1e-12 if name in ("aba", "aba_batch") else C_TOL * EPS * cO
        assert _rel(out, ref) <= tol, (name, _rel(out, ref))


# -- far from the origin ----------------------------------------------------------------
FAR = [(x, a, th) for x in (1e3, 1e4, 1e6) for a, th in ((0.0, 0.0), (2.1, 0.0), (-0.7, 1.3))]


@pytest.mark.parametrize("x, alpha, theta", FAR)
def test_a_regular_pendulum_far_from_the_origin_is_accepted_by_every_method(x, alpha, theta):
    # a uniform rod (m = L = 1) pinned at distance x from the origin, in direction alpha, placement angle theta:
    # about the pivot J = m L²/3, gravity torque -m g (L/2) cos(θ + q), so q̈ = -1.5 g cos(θ + q) / L (hand)
    m = Model([Body(1.0, (0.5, 0.0), 1 / 12)], [Joint("revolute", (x * math.cos(alpha), x * math.sin(alpha), theta))],
              parents=[-1])
    q, qd, tau = [0.3], [0.0], [0.0]
    ref = np.array([-1.5 * G * math.cos(theta + 0.3)])
    for name, f in METHODS.items():
        kind, out = _call(f, m, q, qd, tau)
        assert kind == "ok", (name, out)
        # aba's plans form sᵀAs at the pivot: exact; the others at the origin, where its terms are ~ m x²
        # and cancel (relative rounding ~ ε x² / (m L²/3))
        tol = 1e-14 if name in ("aba", "aba_batch") else 16 * EPS * (1 + x * x) + 1e-14
        np.testing.assert_allclose(out, ref, rtol=tol, atol=0, err_msg=name)
    from planargeo.algorithms.stacked import joint_conditions
    # at the pivot: A_P = [[1, 0, 0], [0, 1, 0.5], [0, 0.5, 1/3]] turned by θ + q (Frobenius norm unchanged), s_P = ẑ
    hand = math.sqrt(2 + 2 * 0.25 + 1 / 9) / (1 / 3)
    assert joint_conditions(m, np.array(q))[0] == pytest.approx(hand, rel=16 * EPS * (1 + x * x) + 1e-14)


def _moved(model, beta, tx, ty):
    """The whole mechanism turned by ``beta`` about the origin and shifted by ``(tx, ty)`` (its root placements)."""
    c, s = math.cos(beta), math.sin(beta)
    joints = []
    for j, p in zip(model.joints, model.parents):
        if p < 0:
            x, y, th = j.placement
            j = Joint(j.kind, (c * x - s * y + tx, s * x + c * y + ty, th + beta))
        joints.append(j)
    return Model(list(model.bodies), joints, list(model.parents), model.gravity)


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 10 ** 6), n=st.integers(1, 5), tree=st.booleans(),
       beta=st.floats(-math.pi, math.pi), tx=st.floats(-10, 10), ty=st.floats(-10, 10))
def test_the_rule_is_invariant_under_moving_the_whole_mechanism(seed, n, tree, beta, tx, ty):
    from planargeo.algorithms.stacked import joint_conditions
    from planargeo.mechanics.model import random_model

    model = random_model(n, seed, tree=tree)
    moved = _moved(model, beta, tx, ty)
    rng = np.random.default_rng(seed)
    q, qd, tau = rng.uniform(-2, 2, (3, model.nq))
    c0, c1 = joint_conditions(model, q), joint_conditions(moved, q)
    finite = np.isfinite(c0)
    assert np.array_equal(finite, np.isfinite(c1))
    # sᵀAs formed at the origin rounds by ε cond_O (cond_O ≤ cond (1 + |o|²)², |o| ≲ 30 here)
    rel = 1e-9 + 1e-16 * c0[finite] * (1 + 30.0 ** 2) ** 2
    assert np.all(np.abs(c1[finite] - c0[finite]) <= rel * c0[finite]), (c0, c1)
    clear = bool(np.all((c0 < COND_LIMIT / 2) | (c0 > 2 * COND_LIMIT)))
    for name, f in METHODS.items():
        if name == "mobility_split" and tree:
            continue                                         # chains only
        k0, k1 = _call(f, model, q, qd, tau)[0], _call(f, moved, q, qd, tau)[0]
        if clear:
            assert k0 == k1, (name, c0)


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 10 ** 6), n=st.integers(1, 4), side=st.sampled_from([1 - 1e-5, 1 + 1e-5]),
       beta=st.floats(-math.pi, math.pi), far=st.sampled_from([0.0, 1.0, 1e3, 1e6]), phi=st.floats(-math.pi, math.pi))
def test_the_decision_at_the_threshold_does_not_move_with_the_mechanism(seed, n, side, beta, far, phi):
    # a random revolute chain ending in a point mass d from its joint: that (leaf) joint's cond is
    # √(2 + 2d² + d⁴)/d² (hand, at the joint), d set to put it 1e-5 (relative) either side of the limit; aba's
    # plans (single state and batched), which form sᵀAs at the joint, decide the same wherever the mechanism is
    from planargeo.mechanics.model import random_model

    base = random_model(n, seed, kinds=("revolute",))
    # cond = √(2 + 2d² + d⁴)/d² = C  <=>  (C² - 1) d⁴ - 2 d² - 2 = 0
    C = side * COND_LIMIT
    d = math.sqrt((2 + math.sqrt(4 + 8 * (C * C - 1))) / (2 * (C * C - 1)))
    model = Model(list(base.bodies) + [Body(1.0, (d, 0.0), 0.0)],
                  list(base.joints) + [Joint("revolute", (0.7, 0.2, 0.1))], list(base.parents) + [n - 1])
    moved = _moved(model, beta, far * math.cos(phi), far * math.sin(phi))
    rng = np.random.default_rng(seed)
    q, qd, tau = rng.uniform(-2, 2, (3, model.nq))
    hand = math.sqrt(2 + 2 * d * d + d ** 4) / (d * d)
    for m in (model, moved):
        for name in ("aba", "aba_batch"):
            kind, out = _call(METHODS[name], m, q, qd, tau)
            assert kind == ("raise" if side > 1 else "ok"), (name, out)
            if kind == "raise":
                assert out == pytest.approx(hand, rel=1e-9), name


def test_mobility_recursion_with_masses_mixed_over_fourteen_decades_is_a_named_error():
    # masses alternating 1e7 and 1e-7 (the breakdown study's chain, section g): in 7.38a the matrix
    # 1 + U Rᵀ Λ⁻¹ I adds 1 to products of order 1e14 and LAPACK meets an exact zero pivot; that must be
    # a SingularConfigurationError (cond = inf), never numpy's bare LinAlgError, while ABA still answers
    # and agrees with an exact-fraction solve of the joint-space equations (written independently of the package)
    import reference as ref

    model = ref.alternating_chain(20, 14)
    q, qd, tau = ref.state(20, 3)
    with pytest.raises(SingularConfigurationError, match="singular to working precision") as err:
        forward_dynamics_mobility_split(model, q, qd, tau)
    assert err.value.cond == math.inf
    exact = np.array(ref.reference_qdd(model, q, qd, tau, mode="exact"), dtype=float)
    H, _ = ref.reference_system(model, q, qd, tau, mode="exact")
    cond = ref.cond_spd(H)
    assert cond > 1e12
    assert _rel(forward_dynamics(model, q, qd, tau), exact) < 100 * EPS * cond


def _point_mass_chain(n, mass):
    """``n`` massless links of length 1, a point mass ``mass`` at each link's end (on the next pivot)."""
    bodies = [Body(mass, com=(1.0, 0.0)) for _ in range(n)]
    joints = [Joint("revolute")] + [Joint("revolute", placement=(1.0, 0.0, 0.0)) for _ in range(n - 1)]
    return Model(bodies, joints, list(range(-1, n - 1)))


@pytest.mark.parametrize("mass", [1e-170, 1.0, 1e160])
@pytest.mark.parametrize("n", [10, 401])
def test_extreme_masses_accepted_by_every_aba_path(n, mass):
    """The rule is scale-free: masses 1e-170 (squares underflow) and 1e160 (squares overflow) are regular.

    Hand closed form: a horizontal chain of point masses at rest, released, is in free fall
    at the first instant (every vertical acceleration is compatible with the links), so mass
    ``k`` (at ``x = k + 1``) has ``Σ_{j≤k} (k + 1 - j) q̈_j = -g``: ``q̈ = [-g, g, 0, 0, ...]``,
    whatever the mass.
    """
    m = _point_mass_chain(n, mass)
    g = 9.81
    want = np.zeros(n)
    want[0], want[1] = -g, g
    z = np.zeros(n)
    np.testing.assert_allclose(forward_dynamics(m, z, z, z), want, atol=1e-9)
    np.testing.assert_allclose(forward_dynamics(m, np.zeros((3, n)), np.zeros((3, n)), np.zeros((3, n))),
                               np.broadcast_to(want, (3, n)), atol=1e-9)
    # the global-origin methods round by ε ‖A_O‖ ‖s_O‖² / D, growing like (distance from the origin)²
    tol = 1e-9 if n < 100 else 1e-7
    np.testing.assert_allclose(articulated_body(m, z, z, z).qdd, want, atol=tol)
    np.testing.assert_allclose(forward_dynamics_projective(m, z, z, z), want, atol=tol)


def test_extreme_masses_joint_scale_finite():
    """``joint_scale`` does not overflow/underflow: ``‖m I_unit‖_F = m ‖I_unit‖_F`` by hand."""
    from planargeo.screws.twists import inertia_matrix
    from planargeo.mechanics.subspaces import joint_scale
    # unit point mass at (1, 0), pivot at the origin: A = [[1,0,0],[0,1,1],[0,1,1]], ‖A‖_F = √5
    for mass in (1e-170, 1e160):
        got = joint_scale(inertia_matrix(mass, [1.0, 0.0], 0.0), [0.0, 0.0, 1.0], [0.0, 0.0])
        assert math.isclose(got, mass * math.sqrt(5.0), rel_tol=1e-14)
