"""Where the forward-dynamics methods and the geometry layer break down, against an independent reference.

The reference (``planargeo._reference``: the joint-space equations written from
scratch with world-frame Jacobians, solved in ``np.longdouble`` or exact
rational arithmetic; exact-arithmetic join / meet / polar / pole) shares no code
with the algorithms under test; ``benchmarks/breakdown.py`` runs the full study
with it.  These tests pin the behaviour the study measures, fast.
"""
from __future__ import annotations

import warnings
from fractions import Fraction

import numpy as np
import pytest

from planargeo.algorithms.aba import forward_dynamics
from planargeo.algorithms.crba import forward_dynamics_crba
from planargeo.algorithms.loops import SINGULAR_COND, constrained_dynamics_lagrange, loop_solve
from planargeo.algorithms.projective import forward_dynamics_projective
from planargeo.algorithms.stacked import forward_dynamics_stacked
from planargeo.geometry.conics import pole
from planargeo.errors import COND_LIMIT, DegenerateGeometryError, SingularConfigurationError, SingularInertiaError
from planargeo.screws.inertia import percussion_axis, percussion_pole
from planargeo.mechanics.model import chain_model
from planargeo.geometry.projective import (direction, from_xy, join, meet, normalize_line, signed_distance,
                                           to_xy)
from planargeo.screws.twists import inertia_matrix
from planargeo.scenes.chain import METHODS  # method name -> forward dynamics, one table
from reference import (  # the study's reference: one copy, shared with the benchmarks
    EPS, reference_system, reference_qdd, reference_with_info, cond_spd, rel_err, graded_chain, state,
    slider_crank_reference, folded_state, fr, cross_exact, matvec_exact, solve_exact, hom_err, cross_cond,
    matvec_cond, euclid_err, euclid_cond, distance_cond, distance_exact, decimal_err, pencil_pair,
    strip_pair, near_points, geo_inertia, pole_near_com, pole_far, line_near_infinity, line_near_com,
    GEO_MASS, GEO_COM, GEO_RHO, alternating_chain,
)


RECURSIVE = ("aba", "projective", "mobility_split", "stacked")


# =========================================================================== tests
def test_reference_matches_hand_pendulum():
    # single uniform link: J_o = m L²/3, q̈ = (τ - m g L/2 cos q) / J_o
    m = chain_model(1)
    q, tau = 0.3, 0.7
    expect = (tau - 9.81 * 0.5 * np.cos(q)) / (1 / 3)
    for mode in ("longdouble", "exact"):
        assert abs(reference_qdd(m, [q], [2.0], [tau], mode=mode)[0] - expect) < 1e-15


def test_reference_matches_hand_double_prismatic():
    # two sliders along x: H = [[m1+m2, m2], [m2, m2]], no velocity terms, no gravity along x
    m = graded_chain(2, 0.25, joint="prismatic")
    tau = np.array([1.0, 0.5])
    H = np.array([[1.25, 0.25], [0.25, 0.25]])
    assert np.allclose(reference_qdd(m, [0.1, 0.2], [1.0, -2.0], tau, mode="exact"), np.linalg.solve(H, tau),
                       rtol=1e-15, atol=0)


def test_reference_longdouble_agrees_with_exact_and_external_loads():
    m = graded_chain(6, 1e-3)
    q, qd, tau = state(6, 3)
    f = np.random.default_rng(4).uniform(-1, 1, (6, 3))
    a = reference_qdd(m, q, qd, tau, f, mode="longdouble")
    b = reference_qdd(m, q, qd, tau, f, mode="exact")
    assert rel_err(a, b) < 1e-17
    # and the package's ABA agrees with it to float64 accuracy (the reference is the right system)
    assert rel_err(forward_dynamics(m, q, qd, tau, f), b) < 1e-13


def test_long_chain_every_method_within_eps_cond():
    # N = 200 uniform chain, state(200): measured cond(H) = 6.6e8; errors aba 3e-12, projective 3.4e-11,
    # mobility_split 9e-10, crba 6.6e-9 (ε·cond = 1.5e-7); the reference resolves ~2e-12 (reverse-order solve)
    N = 200
    m = chain_model(N)
    q, qd, tau = state(N)
    ref, _, cond = reference_with_info(m, q, qd, tau)
    assert 1e8 < cond < 1e10
    for name in ("aba", "projective", "mobility_split", "crba"):      # stacked: 2 s at N = 200, checked at N = 50
        err = rel_err(METHODS[name](m, q, qd, tau), ref)
        assert err <= 100 * EPS * cond, (name, err, cond)
    # the recursive methods stay well below the bound; the dense solve is the least accurate
    assert rel_err(forward_dynamics(m, q, qd, tau), ref) < 2e-11
    assert rel_err(forward_dynamics_projective(m, q, qd, tau), ref) < 3e-10
    assert rel_err(forward_dynamics_crba(m, q, qd, tau), ref) > rel_err(forward_dynamics(m, q, qd, tau), ref)


def test_chain_50_stacked_within_eps_cond():
    m = chain_model(50)
    q, qd, tau = state(50)
    ref, _, cond = reference_with_info(m, q, qd, tau)
    assert rel_err(forward_dynamics_stacked(m, q, qd, tau), ref) <= 100 * EPS * cond


def _graded(k, reverse, joint="revolute", seed=1):
    ratio = 10.0 ** -k
    q, qd, tau = state(8, seed)
    grade = np.geomspace(1, ratio, 8)
    return graded_chain(8, ratio, reverse=reverse, joint=joint), q, qd, tau * (grade[::-1] if reverse else grade)


@pytest.mark.parametrize("name", list(METHODS))
def test_light_tip_1e10_every_method_stays_accurate(name):
    # tip links 1e-10 of the base (geometric grading, N = 8, torques scaled like the masses): cond(H) = 1.5e10
    # but every method, the dense solve included, measured <= 3e-14: the light links come last in elimination
    m, q, qd, tau = _graded(10, False)
    ref = reference_qdd(m, q, qd, tau, mode="exact")
    assert rel_err(METHODS[name](m, q, qd, tau), ref) < 1e-12


@pytest.mark.parametrize("name, bound", [("aba", 1e-11), ("projective", 4e-9), ("mobility_split", 4e-9),
                                         ("stacked", 4e-8)])
def test_light_base_1e10_recursive_methods_bounded(name, bound):
    # base links 1e-10 of the tip: measured aba 4.7e-13, projective 1.9e-10, mobility_split 1.8e-10,
    # stacked 1.7e-9 (bounds: 20x margin)
    m, q, qd, tau = _graded(10, True)
    ref = reference_qdd(m, q, qd, tau, mode="exact")
    assert rel_err(METHODS[name](m, q, qd, tau), ref) < bound


def test_light_base_1e10_dense_solve_bounded_by_eps_cond_and_worst():
    # measured: cond(H) = 2.2e10, crba error 6.8e-8 (ε·cond = 4.8e-6), 100x ABA's
    m, q, qd, tau = _graded(10, True)
    H, _ = reference_system(m, q, qd, tau)
    cond = cond_spd(H)
    assert 1e10 < cond < 1e11
    ref = reference_qdd(m, q, qd, tau, mode="exact")
    err = rel_err(forward_dynamics_crba(m, q, qd, tau), ref)
    assert 1e-9 < err <= EPS * cond, (err, cond)
    assert err > 10 * rel_err(forward_dynamics(m, q, qd, tau), ref)
    # the long-double reference is not enough here: it is off by ~1e-10
    assert rel_err(reference_qdd(m, q, qd, tau), ref) > 1e-12


def test_long_chain_of_mixed_tiny_and_huge_masses_at_cond_1e12():
    # 50 unit links, masses alternating 10^3.5 and 10^-3.5 (ratio 1e7): cond(H) ≈ 5e12 by the reference.
    # Measured: aba 3.7e-16, projective 3.6e-13, stacked 3.8e-13, crba 5.4e-13, mobility_split 6.3e-6
    # (ε cond = 1.1e-3); the long-double reference agrees with the exact one to 1e-17 at N = 20, k = 7
    m = alternating_chain(50, 7)
    q, qd, tau = state(50, 3)
    x, _, c = reference_with_info(m, q, qd, tau)
    assert 1e12 < c < 1e13
    errs = {name: rel_err(f(m, q, qd, tau), x) for name, f in METHODS.items()}
    assert errs["aba"] < 100 * EPS
    assert errs["projective"] < 1e-11 and errs["stacked"] < 1e-11
    # mobility_split is held only to ε cond(H): the study observes it as the least accurate recursive
    # method here (6.3e-6, 1e10 x ABA's error), a weakness a fix may remove, so it is not asserted
    assert max(errs.values()) <= EPS * c                              # nobody worse than ε cond(H)


def test_long_chain_of_mixed_masses_dense_solve_refuses_past_its_threshold():
    # ratio 1e8 (cond ≈ 5e13): the dense solve names the singularity with the reference's cond; ABA still ~ε
    m = alternating_chain(50, 8)
    q, qd, tau = state(50, 3)
    x, _, c = reference_with_info(m, q, qd, tau)
    with pytest.raises(SingularConfigurationError) as e:
        forward_dynamics_crba(m, q, qd, tau)
    assert 0.3 < e.value.cond / c < 3
    assert rel_err(forward_dynamics(m, q, qd, tau), x) < 100 * EPS


def test_light_base_slider_dense_solve_loses_recursive_exact():
    # parallel sliders, base 1e-8 of the tip: crba 1.2e-8 (cond 1.7e9), recursive methods ~1e-15
    m, q, qd, tau = _graded(8, True, "prismatic", seed=5)
    ref = reference_qdd(m, q, qd, tau, mode="exact")
    for name in RECURSIVE:
        assert rel_err(METHODS[name](m, q, qd, tau), ref) < 1e-14, name
    assert rel_err(forward_dynamics_crba(m, q, qd, tau), ref) > 1e-10


def test_light_base_slider_1e12_every_method_refuses():
    m, q, qd, tau = _graded(12, True, "prismatic", seed=5)
    for name, f in METHODS.items():
        with pytest.raises(SingularConfigurationError) as e:
            f(m, q, qd, tau)
        assert e.value.cond > 1e12, name


def test_folded_slider_crank_raises_beyond_threshold():
    # rod path: ψ = 0, l = r(1 + δ): cond(BᵀGΛ⁻¹GᵀB) ≈ 5.4/δ; δ = 1e-11 is past the 1e10 threshold
    model, q, qd, r, l = folded_state(1e-11, "rod")
    with pytest.raises(SingularConfigurationError) as e:
        loop_solve(model, q, qd, np.zeros(3))
    assert SINGULAR_COND < e.value.cond < 1e12
    # ... while the Lagrange solver still gets the exact answer to ~1e-16 there
    ref = slider_crank_reference(model, q, qd, np.zeros(3), r, l, mode="exact")
    assert rel_err(constrained_dynamics_lagrange(model, q, qd, np.zeros(3))["qdd"], ref) < 1e-14


def test_near_folded_slider_crank_loop_solver_agrees_with_lagrange():
    # δ = 1e-10, just before the threshold: cond 5.4e9, loop solver vs Lagrange (and vs the exact reference)
    # measured 1.9e-8 = 16 ε·cond
    model, q, qd, r, l = folded_state(1e-10, "rod")
    tau = np.zeros(3)
    sol = loop_solve(model, q, qd, tau)
    assert 1e9 < sol.cond < SINGULAR_COND
    lag = constrained_dynamics_lagrange(model, q, qd, tau)["qdd"]
    ref = slider_crank_reference(model, q, qd, tau, r, l, mode="exact")
    assert rel_err(sol.qdd, lag) <= 100 * EPS * sol.cond
    assert rel_err(sol.qdd, ref) <= 100 * EPS * sol.cond
    assert rel_err(lag, ref) < 1e-14


def test_psi_path_is_ill_posed_for_float_states():
    # l = r, ψ = 1e-4: both solvers deviate ~1e-6 from the exact answer, but so does the exact answer itself
    # when θ moves by one ulp: the float64 state cannot determine q̈ better
    model, q, qd, r, l = folded_state(1e-4, "psi")
    tau = np.zeros(3)
    ref = slider_crank_reference(model, q, qd, tau, r, l, mode="exact")
    q2 = q.copy()
    q2[1] = np.nextafter(q2[1], np.inf)
    sens = rel_err(slider_crank_reference(model, q2, qd, tau, r, l, mode="exact"), ref)
    sol = loop_solve(model, q, qd, tau)
    lag = constrained_dynamics_lagrange(model, q, qd, tau)["qdd"]
    assert rel_err(sol.qdd, ref) < 2 * sens and rel_err(lag, ref) < 2 * sens
    assert rel_err(sol.qdd, lag) < 1e-3 * sens


# ---------------------------------------------------------------------------- geometry layer (knob f)
def _no_warnings(fn, *args):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return fn(*args)


def test_geometry_reference_is_exact():
    # the meet of x = 1 and y = 2, and a percussion axis of thesis 5.64-5.66, by hand
    assert cross_exact([0.0, 1.0, -1.0], [1.0, 0.0, 2.0]) == [2, -1, -1]        # the point (1, 2), weight -1
    I = inertia_matrix(2.0, [1.0, 0.0], 0.5)
    assert matvec_exact(I, [0.0, 0.0, 1.0]) == [0, 2, Fraction(5, 2)]
    assert solve_exact(I, [0, 2, 2.5]) == [0, 0, 1]


def test_meet_of_exactly_parallel_lines_is_an_ideal_point_silently():
    # θ = 0 in strip_pair: the same direction floats, one unit apart: weight exactly 0, no warning
    rng = np.random.default_rng(7)
    for _ in range(16):
        l, m = strip_pair(0.0, rng)
        p = _no_warnings(meet, l, m)
        assert p[2] == 0.0
        assert np.all(np.isnan(_no_warnings(to_xy, p)))
        d = _no_warnings(direction, p)
        assert abs(abs(d @ (l[:2] / np.hypot(*l[:2]))) - 1) < 1e-15      # along the common direction
        assert hom_err(p, cross_exact(l, m)) < 4 * EPS


@pytest.mark.parametrize("theta", [1e-4, 1e-10, 1e-15])
def test_meet_of_near_parallel_lines_homogeneous_accurate_euclidean_eps_over_theta(theta):
    # lines one unit apart meeting ~1/θ away: measured κ ≤ 18 and homogeneous error ≤ 3.7e-16 at every θ,
    # while the Euclidean point loses ε·κ_E ≈ ε/θ (θ = 1e-15: 6e-2), as the exact answer does for 1 ulp in m
    rng = np.random.default_rng(11)
    for _ in range(8):
        l, m = strip_pair(theta, rng)
        p = _no_warnings(meet, l, m)
        exact = cross_exact(l, m)
        kappa = cross_cond(l, m, exact)
        assert kappa < 30
        assert hom_err(p, exact) < 4 * EPS
        assert euclid_err(p, exact) <= EPS * euclid_cond(kappa, exact, exact[2])
        assert euclid_cond(kappa, exact, exact[2]) > 0.1 / theta


@pytest.mark.parametrize("theta", [1e-3, 1e-8, 1e-11])
def test_meet_of_near_coincident_lines_loses_eps_kappa_below_the_limit(theta):
    # two lines through one point at angle θ: κ ≈ 1/θ, measured error ≤ 0.7 ε κ (homogeneous), ≤ ε κ_E (Euclidean)
    rng = np.random.default_rng(13)
    for _ in range(8):
        l, m = pencil_pair(theta, rng)
        p = _no_warnings(meet, l, m)
        exact = cross_exact(l, m)
        kappa = cross_cond(l, m, exact)
        assert 0.1 / theta < kappa < min(10 / theta, COND_LIMIT)
        assert hom_err(p, exact) <= EPS * kappa
        assert euclid_err(p, exact) <= EPS * euclid_cond(kappa, exact, exact[2])


def _raises_with_cond(fn, a, b):
    """The ``.cond`` of the named error ``fn(a, b)`` must raise; checked against the exact-arithmetic κ."""
    with pytest.raises(DegenerateGeometryError) as info:
        fn(a, b)
    c = info.value.cond
    exact = cross_exact(a, b)
    kappa = float("inf") if not any(exact) else cross_cond(a, b, exact)
    assert c > COND_LIMIT
    if EPS * kappa < 0.1:      # the reported κ is itself computed from a × b, good to about ε κ relative
        assert abs(c / kappa - 1) <= 4 * EPS * kappa
    else:
        assert c > 0.1 / EPS
    return c


def test_meet_refuses_a_repeated_or_rounded_copy_of_a_line_and_near_coincident_lines():
    # the rule: DegenerateGeometryError when κ = |l| |m| / |l × m| > COND_LIMIT.  A line and its double (l × m
    # exactly zero, κ = ∞) raise; so do its triple and its normalised copy (rounded: distinct float lines with
    # κ ~ 1/ε whose "meet" would be an arbitrary point of the line, measured in 140 and 135 of 200 lines before)
    l = np.array([0.3, -1.7, 0.9])
    for m in (l, 2 * l, -0.5 * l):
        assert _raises_with_cond(meet, l, m) == np.inf
    for m in (3 * l, normalize_line(l)):
        assert cross_cond(l, m, cross_exact(l, m)) > 1e15
        _raises_with_cond(meet, l, m)
    # near-coincident at θ = 1e-15 (κ ≈ 1e15): every pair refuses; with the check switched off the answer
    # keeps about one digit (measured ≤ 0.1), which is what the refusal protects from
    rng = np.random.default_rng(5)
    errs = []
    for _ in range(8):
        a, b = pencil_pair(1e-15, rng)
        assert cross_cond(a, b, cross_exact(a, b)) > 5e14
        _raises_with_cond(meet, a, b)
        errs.append(euclid_err(meet(a, b, cond_limit=np.inf), cross_exact(a, b)))
    assert max(errs) > 1e-3


@pytest.mark.parametrize("R", [1.0, 1e3])
def test_join_of_nearly_coincident_points_error_eps_kappa_then_named_error_past_the_limit(R):
    rng = np.random.default_rng(17)
    accepted = refused = 0
    for k in range(0, 18):
        p, q = near_points(R * 10.0 ** -k, R, rng)
        exact = cross_exact(p, q)
        kappa = float("inf") if not any(exact) else cross_cond(p, q, exact)
        if kappa < COND_LIMIT / 2:
            l = _no_warnings(join, p, q)
            assert hom_err(l, exact) <= EPS * kappa
            assert np.all(l[:2] == (to_xy(q) - to_xy(p)))   # the direction is exact; the moment carries the error
            accepted += 1
        elif kappa > 2 * COND_LIMIT:
            _raises_with_cond(join, p, q)
            refused += 1
    assert accepted >= 12 and refused >= 3
    assert _raises_with_cond(join, p, p.copy()) == np.inf


def test_join_one_ulp_apart_far_from_the_origin_raises_instead_of_a_wrong_line():
    # measured in the study: at R ≈ 1e3, δ ≈ 1 ulp the relative error reaches 3.5 and the line misses the
    # given point by up to 269 units.  join now names the error, with the exact κ; switched off
    # (cond_limit=inf) the line it would have returned passes far from P
    P = np.array([700.3, -512.9])
    Q = np.array([np.nextafter(P[0], np.inf), np.nextafter(P[1], -np.inf)])
    p, q = from_xy(P), from_xy(Q)
    exact = cross_exact(p, q)
    kappa = cross_cond(p, q, exact)
    assert kappa > 1e15
    _raises_with_cond(join, p, q)
    l = join(p, q, cond_limit=np.inf)
    miss = abs(float(distance_exact(fr(l), P)))
    assert miss > 1.0, miss                               # the line that was refused passes far from P


def test_percussion_axis_of_the_centre_of_mass_is_the_line_at_infinity_exactly():
    I = geo_inertia()
    f = _no_warnings(percussion_axis, I, from_xy(GEO_COM))
    assert f[0] == 0.0 and f[1] == 0.0 and f[2] > 0              # a pure couple [0, 0, J]
    assert abs(f[2] - GEO_MASS * GEO_RHO ** 2) < 4 * EPS


@pytest.mark.parametrize("d", [1e-3, 1e-9, 1e-15])
def test_percussion_axis_near_the_centre_homogeneous_accurate_distance_eps_over_d(d):
    # measured: homogeneous error ≤ 4e-16 (κ ≈ 9) at every d; the distance r = ρ²/d of the axis from c
    # loses ε κ_E ≈ ε/d (d = 1e-15: 4.9e-2)
    I = geo_inertia()
    rng = np.random.default_rng(19)
    for _ in range(8):
        a = pole_near_com(d, rng)
        f = _no_warnings(percussion_axis, I, a)
        exact = matvec_exact(I, a)
        kappa = matvec_cond(I, a, exact)
        assert kappa < 15 and hom_err(f, exact) < 4 * EPS
        r = distance_exact(exact, GEO_COM)
        # r = ρ²/d (5.68) for the distance d the rounded pole really has (c + d u rounds by ~ε |c|)
        assert abs(float(r) - GEO_RHO ** 2 / d) < (1e-12 + 4 * EPS / d) * GEO_RHO ** 2 / d
        err = decimal_err(float(signed_distance(from_xy(GEO_COM), f)), r)
        assert err <= EPS * distance_cond(kappa, exact, GEO_COM)


def test_percussion_axis_of_a_far_or_ideal_pole_passes_through_the_centre():
    I = geo_inertia()
    rng = np.random.default_rng(23)
    for R in (1e6, 1e12):
        a = pole_far(R, rng)
        f = _no_warnings(percussion_axis, I, a)
        exact = matvec_exact(I, a)
        assert hom_err(f, exact) < 4 * EPS
        assert abs(float(signed_distance(from_xy(GEO_COM), f))) < GEO_RHO ** 2 / R + 4 * EPS
    u = np.array([0.6, -0.8])
    f = _no_warnings(percussion_axis, I, np.array([u[1], -u[0], 0.0]))     # a translation
    assert abs(float(signed_distance(from_xy(GEO_COM), f))) < 4 * EPS       # the force passes through c


def test_percussion_pole_as_the_line_runs_to_infinity_or_through_the_centre():
    I = geo_inertia()
    rng = np.random.default_rng(29)
    for e in (1e-6, 1e-14):
        f = line_near_infinity(e, rng)                    # pole → c: accurate both ways (measured ≤ 6.5e-16)
        p = _no_warnings(percussion_pole, I, f)
        exact = solve_exact(I, f)
        assert hom_err(p, exact) < 8 * EPS and euclid_err(p, exact) < 8 * EPS
        f = line_near_com(e, rng)                         # pole → ∞: homogeneous accurate, Euclidean ε κ_E
        p = _no_warnings(percussion_pole, I, f)
        exact = solve_exact(I, f)
        assert hom_err(p, exact) < 8 * EPS
        kappa = float(np.linalg.cond(I))
        assert euclid_err(p, exact) <= EPS * euclid_cond(kappa, exact, exact[2])
    assert np.allclose(to_xy(percussion_pole(I, [0.0, 0.0, 1.0])), GEO_COM, rtol=0, atol=4 * EPS)


def test_pole_of_an_inertia_degenerating_to_a_point_mass_raises_past_its_threshold():
    # ρ → 0: cond₂(I) ≈ 2.7 / ρ²; the homogeneous pole loses ≤ 0.26 ε cond (measured) in its size, not its
    # position.  percussion_pole refuses at λ_min ≤ 1e-12 λ_max (ρ = 1e-6), conics.pole at cond > 1e13 (ρ = 1e-7)
    f = np.array([0.4, -1.1, 0.7])
    I5, I6, I7 = geo_inertia(1e-5), geo_inertia(1e-6), geo_inertia(1e-7)
    for fn in (pole, percussion_pole):
        p = fn(I5, f)
        exact = solve_exact(I5, f)
        assert 1e-9 < hom_err(p, exact) <= EPS * np.linalg.cond(I5)
        assert euclid_err(p, exact) < 1e-14
    with pytest.raises(SingularInertiaError) as e:
        percussion_pole(I6, f)
    assert 1e12 <= e.value.cond < 1e13
    p = pole(I6, f)                                        # 2.7e12 < 1e13: still answers, error ≤ ε cond
    assert hom_err(p, solve_exact(I6, f)) <= EPS * np.linalg.cond(I6)
    with pytest.raises(DegenerateGeometryError) as e:
        pole(I7, f)
    assert e.value.cond > 1e13
