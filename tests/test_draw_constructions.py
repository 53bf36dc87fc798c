"""Tests of planargeo.draw.constructions and mechanism: drawn geometry against closed forms."""
from __future__ import annotations

import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, strategies as st  # noqa: E402

from planargeo.draw.constructions import (draw_acceleration_step, draw_newton_euler,  # noqa: E402
                                          draw_percussion, draw_polar_exterior,
                                          draw_polar_interior, draw_power, draw_twist_sum,
                                          draw_velocity_step, draw_wrench_sum, line_conic_points)
from planargeo.draw.mechanism import draw_joint_split, draw_model, link_polygon  # noqa: E402
from planargeo.screws.twists import inertia_matrix, unit_rotation, unit_translation  # noqa: E402


@pytest.fixture
def ax():
    fig, ax = plt.subplots()
    ax.set_xlim(-4, 4)
    ax.set_ylim(-4, 4)
    ax.set_aspect("equal")
    yield ax
    plt.close(fig)


def _xy(p):
    return np.array([-p[1] / p[2], p[0] / p[2]])


def _circle(c, r):
    # package conic of the circle |x - c| = r: p = [y, -x, 1]
    M = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    E = np.array([[1.0, 0, -c[0]], [0, 1.0, -c[1]], [-c[0], -c[1], c @ c - r * r]])
    Mi = np.linalg.inv(M)
    return Mi.T @ E @ Mi


def test_twist_sum_lever_rule(ax):
    # thesis 4.11-4.13: P = Q1 + beta (Q2 - Q1), beta = w2 / (w1 + w2)
    Q1, Q2, w1, w2 = np.array([0.0, 0.0]), np.array([3.0, 0.0]), 1.0, 2.0
    out = draw_twist_sum(w1 * unit_rotation(Q1), w2 * unit_rotation(Q2), ax)
    np.testing.assert_allclose(out["v3"].get_xy(), Q1 + w2 / (w1 + w2) * (Q2 - Q1))
    assert out["v3"].get_point()[2] == pytest.approx(w1 + w2)
    # the pole lies on the drawn lever line
    assert abs(out["v3"].get_point() @ out["lever"].get_line()) < 1e-12


def test_twist_sum_rotation_plus_translation(ax):
    # thesis 4.16: P = Q + rho n, rho = u / w, n = (-sin lam, cos lam)
    w, u, lam = 2.0, 3.0, 0.4
    Q = np.array([1.0, -0.5])
    out = draw_twist_sum(w * unit_rotation(Q), u * unit_translation([np.cos(lam), np.sin(lam)]), ax)
    np.testing.assert_allclose(out["v3"].get_xy(), Q + u / w * np.array([-np.sin(lam), np.cos(lam)]))
    ax.figure.canvas.draw()


def test_opposite_rotations_give_translation(ax):
    out = draw_twist_sum(unit_rotation([0.0, 0.0]), -unit_rotation([2.0, 0.0]), ax)
    assert out["v3"].get_xy() is None  # beta = inf: an ideal point (4.2.1)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ax.figure.canvas.draw()


def test_wrench_sum_through_meet_and_parallel_lever(ax):
    f1 = np.array([1.0, 0.0, -1.0])   # along +x through y = 1
    f2 = np.array([0.0, 1.0, 2.0])    # along +y through x = 2
    out = draw_wrench_sum(f1, f2, ax)
    P = np.cross(f1, f2)
    assert abs(P @ out["f3"].get_line()) < 1e-12
    np.testing.assert_allclose(_xy(P), [2.0, 1.0])
    # parallel forces (4.40-4.45): d3 = d1 + beta (d2 - d1), beta = F2 / (F1 + F2)
    F1, F2, d1, d2 = 2.0, 1.0, 0.0, 3.0
    g1 = np.array([0.0, -F1, -F1 * d1])  # downward through x = d1: tz = x fy
    g2 = np.array([0.0, -F2, -F2 * d2])
    f3 = draw_wrench_sum(g1, g2, ax)["f3"].get_line()
    x3 = f3[2] / f3[1]
    assert x3 == pytest.approx(d1 + F2 / (F1 + F2) * (d2 - d1))
    # force and couple (4.46): parallel at rho = tau / F
    f3 = draw_wrench_sum(np.array([0.0, 2.0, 0.0]), np.array([0.0, 0.0, 1.5]), ax)["f3"].get_line()
    assert f3[2] / f3[1] == pytest.approx(1.5 / 2.0)
    ax.figure.canvas.draw()


@given(st.floats(1.2, 3.0), st.floats(0, 2 * np.pi))
def test_polar_exterior_construction(d, th):
    fig, ax = plt.subplots()
    try:
        c, r = np.array([0.3, -0.2]), 1.0
        C = _circle(c, r)
        pxy = c + d * np.array([np.cos(th), np.sin(th)])
        p = np.array([pxy[1], -pxy[0], 1.0])
        out = draw_polar_exterior(C, p, ax)
        L = out["L"].get_line()
        # the polar of a circle: perpendicular to c->p at distance r^2/d from c (same side)
        foot = c + (r * r / d) * (pxy - c) / d
        assert abs(np.array([foot[1], -foot[0], 1.0]) @ L) < 1e-9 * np.linalg.norm(L)
        for t in out["tangents"]:
            tl = t.get_line()
            assert abs(p @ tl) < 1e-9 * np.linalg.norm(tl)
        for X in out["construction"].contacts:
            assert abs(np.linalg.norm(_xy(X) - c) - r) < 1e-9
        fig.canvas.draw()
    finally:
        plt.close(fig)


def test_polar_interior_construction(ax):
    C = _circle(np.array([0.0, 0.0]), 2.0)
    p = np.array([0.0, -1.0, 1.0])          # (1, 0)
    out = draw_polar_interior(C, p, ax, angles=(0.7, 2.0))
    L = out["L"].get_line()
    np.testing.assert_allclose(L / L[1], [0.0, 1.0, 4.0], atol=1e-9)   # x = 4 (r^2/d)
    assert line_conic_points(C, [1.0, 0.0, -5.0]) == []                 # y = 5 misses


def test_percussion_distance(ax):
    # thesis 5.67-5.68: axis at r = rho^2 / d beyond the centre of mass
    m, c, rho, d = 2.0, np.array([1.0, 0.5]), 0.6, 1.5
    I = inertia_matrix(m, c, m * rho * rho)
    a = np.array([c[1], -(c[0] - d), 1.0])   # pole at c - (d, 0)
    f = draw_percussion(I, a, ax)["f"].get_line()
    assert f[0] == pytest.approx(0.0, abs=1e-12)   # a vertical axis (force along y)
    x_axis = f[2] / f[1]                           # tz + y fx - x fy = 0 with fx = 0 (4.27)
    assert x_axis - c[0] == pytest.approx(rho * rho / d)
    ax.figure.canvas.draw()


def _momentum_closed_form(m, c, J, Q, w):
    """p = I v by hand: force m v_c (v_c = w x (c - Q)), moment about O = J w + (c x m v_c)_z."""
    vc = w * np.array([-(c[1] - Q[1]), c[0] - Q[0]])
    F = m * vc
    return np.array([F[0], F[1], J * w + c[0] * F[1] - c[1] * F[0]])


def test_power_relations(ax):
    # thesis 5.69-5.74: f through the pole of v (v^T f = 0), a on the momentum line (p^T a = 0)
    m, c, J, Q, w = 1.5, np.array([0.5, 0.2]), 0.4, np.array([1.0, -0.3]), 1.2
    I = inertia_matrix(m, c, J)
    out = draw_power(w * unit_rotation(Q), I, ax)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ax.figure.canvas.draw()
    p = _momentum_closed_form(m, c, J, Q, w)
    P = out["p"].get_line()
    np.testing.assert_allclose(P, p, rtol=1e-12)                      # p = I v
    Qh = np.array([Q[1], -Q[0], 1.0])
    f = out["f"].get_line()
    assert abs(Qh @ f) <= 1e-12 * np.linalg.norm(f)                   # f passes through v's pole
    a = out["a"].get_point()
    assert abs(p @ a) <= 1e-12 * np.linalg.norm(p) * np.linalg.norm(a)  # a lies on p
    # the drawn (clipped) momentum line satisfies the closed form's equation (4.27)
    for x, y in out["p"].get_segment():
        assert abs(p[2] + y * p[0] - x * p[1]) <= 1e-9 * np.hypot(p[0], p[1])


def test_power_velocity_at_centre_of_mass_is_a_couple(ax):
    # v at the centre of mass: p = I v = [0, 0, J w], the line at infinity (a pure couple);
    # a powerless acceleration is then a translation (an ideal point)
    m, c, J, w = 2.0, np.array([0.3, -0.4]), 0.5, 1.5
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = draw_power(w * unit_rotation(c), inertia_matrix(m, c, J), ax)
        ax.figure.canvas.draw()
    np.testing.assert_allclose(out["p"].get_line(), [0.0, 0.0, J * w], atol=1e-12)
    a = out["a"].get_point()
    assert abs(a[2]) <= 1e-12 * np.hypot(a[0], a[1])       # (numerically) an ideal point
    p = out["p"].get_line()
    assert abs(p @ a) <= 1e-12 * np.linalg.norm(p) * np.linalg.norm(a)
    # exactly a couple: exactly an ideal point
    I = inertia_matrix(m, [0.0, 0.0], J)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = draw_power(w * unit_rotation([0.0, 0.0]), I, ax)
        ax.figure.canvas.draw()
    assert out["a"].get_point()[2] == 0.0 and out["a"].get_xy() is None
    f = out["f"].get_line()
    assert abs(np.array([0.0, 0.0, 1.0]) @ f) <= 1e-12 * np.linalg.norm(f)   # f through v's pole


def test_power_translation_velocity(ax):
    # v a translation (ideal point): p = m u through the centre of mass; f is parallel to...
    # every line along the translation's normal direction has v^T f = 0
    m, c, J, u = 2.0, np.array([0.3, -0.4]), 0.5, np.array([1.0, 2.0])
    v = np.array([u[0], u[1], 0.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = draw_power(v, inertia_matrix(m, c, J), ax)
        ax.figure.canvas.draw()
    p = out["p"].get_line()
    np.testing.assert_allclose(p, [m * u[0], m * u[1], m * (c[0] * u[1] - c[1] * u[0])])
    f = out["f"].get_line()
    assert abs(v @ f) <= 1e-12 * np.linalg.norm(f) and np.any(f[:2])
    assert abs(p @ out["a"].get_point()) <= 1e-12 * np.linalg.norm(p)


def test_twist_sum_coincident_poles_draws(ax):
    # v + 2 v: the same pole (no lever line); the sum is 3 v
    v = 0.7 * unit_rotation([1.0, 0.5])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = draw_twist_sum(v, 2 * v, ax)
        ax.figure.canvas.draw()
    np.testing.assert_allclose(out["v3"].get_xy(), [1.0, 0.5])
    assert out["v3"].get_point()[2] == pytest.approx(3 * 0.7)
    assert not np.any(out["lever"].get_line())


def test_velocity_step_lever_rule(ax):
    # thesis 4.48-4.49: V_i = V_{i-1} + beta (S - V_{i-1}), beta = qd / (qd + w_{i-1})
    Vp, S, wp, qd = np.array([-1.0, 0.5]), np.array([1.0, 1.5]), 0.8, 1.7
    out = draw_velocity_step(wp * unit_rotation(Vp), unit_rotation(S), qd, ax)
    beta = qd / (qd + wp)
    np.testing.assert_allclose(out["v"].get_xy(), Vp + beta * (S - Vp))
    assert out["v"].get_point()[2] == pytest.approx(wp + qd)
    ax.figure.canvas.draw()


@pytest.mark.parametrize("V", [(0.0, 0.0), (-0.5, 0.8)])
def test_acceleration_step_bias_and_offset(ax, V):
    # thesis 4.53: kappa = w qd (S - V) rotated: a translation of magnitude |w qd k|;
    # 4.54: s qdd + kappa is a rotation qdd about a point at |w qd k / qdd| from the joint
    V, S, w, qd, qdd = np.array(V), np.array([2.0, 1.0]), 1.3, 0.9, 2.5
    ap = 0.4 * unit_rotation([-1.0, 1.0])
    out = draw_acceleration_step(ap, w * unit_rotation(V), unit_rotation(S), qd, qdd, ax)
    # hand value: with twists [vx, vy, w] (a rotation w about P is w [Py, -Px, 1]) the spatial cross
    # product (w, u) x (w', u') = (0, w z x u' + u x w' z) gives for v = w [Vy, -Vx, 1], s qd = qd [Sy, -Sx, 1]
    #   w z x (qd (Sy, -Sx)) = w qd (Sx, Sy),   (w (Vy, -Vx)) x qd z = w qd (-Vx, -Vy),
    # so kappa = [w qd (S - V)_x, w qd (S - V)_y, 0]: a translation along S - V (4.53-4.54, 2.19)
    kappa_hand = np.array([w * qd * (S - V)[0], w * qd * (S - V)[1], 0.0])
    k = np.linalg.norm(S - V)
    bias = out["bias"].get_point()
    np.testing.assert_allclose(bias, kappa_hand, rtol=1e-12, atol=1e-15)
    assert bias[2] == 0.0
    assert np.hypot(*bias[:2]) == pytest.approx(abs(w * qd * k))
    combo = out["joint_total"].get_xy()
    assert np.linalg.norm(combo - S) == pytest.approx(abs(w * qd * k / qdd))
    a = out["a"].get_point()
    np.testing.assert_allclose(a, ap + qdd * unit_rotation(S) + kappa_hand)
    assert abs(a @ out["lever"].get_line()) < 1e-12 * np.linalg.norm(a)
    ax.figure.canvas.draw()


def test_newton_euler_one_body(ax):
    # thesis 4.7, 4.55-4.56: p is the centripetal force m l w^2 through the centre of mass toward
    # the pole of v; I a the axis of percussion at rho^2/d; f_net = I a + p
    m, c, J = 2.0, np.array([1.0, 0.0]), 0.18
    Q, w = np.array([-1.0, 0.0]), 1.5                      # v: rotation about Q, l = 2
    A, alpha = np.array([1.0, -1.0]), 2.0                  # a: rotation about A, d = 1
    out = draw_newton_euler(inertia_matrix(m, c, J), alpha * unit_rotation(A),
                            w * unit_rotation(Q), ax, scale=0.1)
    p = out["p"].get_line()
    np.testing.assert_allclose(p, [-m * 2.0 * w * w, 0.0, 0.0], atol=1e-12)  # along -x through y=0
    Ia = out["Ia"].get_line()
    rho2 = J / m
    np.testing.assert_allclose(Ia / Ia[0], [1.0, 0.0, -rho2 / 1.0], atol=1e-12)  # y = rho^2/d
    np.testing.assert_allclose(out["f_net"].get_line(), Ia + p, atol=1e-12)
    ax.figure.canvas.draw()


def test_joint_split_and_model_drawing(ax):
    from planargeo.algorithms.rnea import newton_euler
    from planargeo.mechanics.joints import revolute
    from planargeo.mechanics.model import chain_model

    m = chain_model(3)
    w = newton_euler(m, [0.3, 0.4, -0.5], [1.0, 0.5, -0.2], [0.1, 0.2, 0.3])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        arts = draw_model(m, w, ax)
        assert len(arts["bodies"]) >= 3 and len(arts["joints"]) >= 3
        j = revolute(w.origin[1])
        out, (Q, mu, act, rea) = draw_joint_split(j.s, j.R, w.I[1], w.f[1], ax, name="2")
        ax.figure.canvas.draw()
    np.testing.assert_allclose(act + rea, w.f[1], atol=1e-12)
    assert abs(j.s[:, 0] @ rea) < 1e-12              # the reaction does no work on the joint
    np.testing.assert_allclose(Q, j.s.T @ w.f[1])     # Q = s^T f (6.61a)
    assert link_polygon([0, 0], [1, 0], 0.2).area == pytest.approx(0.2 + np.pi * 0.01, rel=1e-2)


def test_chain_kinematics_figures_match_4_48_and_4_54():
    """The state drawn in Figs 4.7/4.8 obeys the thesis's closed forms (4.48, 4.49, 4.53, 4.54)."""
    from planargeo.algorithms.rnea import newton_euler
    from planargeo.gallery.figures.ch4 import Q47, QD47, QDD47, _chain3

    w = newton_euler(_chain3(), Q47, QD47, QDD47)
    i = 2
    J = w.origin[i]
    w_prev, qd, qdd = w.v[i - 1][2], QD47[i], QDD47[i]
    P_prev = _xy(w.v[i - 1])
    k = np.linalg.norm(J - P_prev)
    beta = qd / (qd + w_prev)                                   # (4.48)
    np.testing.assert_allclose(_xy(w.v[i]), P_prev + beta * (J - P_prev))
    assert w.v[i][2] == pytest.approx(w_prev + qd)              # (4.49)
    assert np.hypot(*w.kappa[i][:2]) == pytest.approx(abs(w_prev * qd * k))   # (4.53)
    combo = w.s(i)[:, 0] * qdd + w.kappa[i]
    assert np.linalg.norm(_xy(combo) - J) == pytest.approx(abs(w_prev * qd * k / qdd))  # (4.54)


def test_joint_split_arrows_slide_off_the_bodies(ax):
    """With ``avoid`` every arrow stays on its own line and clear of the bodies (hand geometry)."""
    from shapely.geometry import LineString

    from planargeo.mechanics.joints import revolute
    from planargeo.screws.twists import inertia_matrix

    j = revolute([0.0, 0.0])
    A = inertia_matrix(2.0, [1.0, 0.0], 0.3)
    f = np.array([1.0, 1.0, 0.0])              # 1 N along (1, 1) through the joint (4.27)
    body = link_polygon([-1.0, -1.0], [1.0, 1.0], 0.4)    # a link lying along that line
    out, (Q, mu, act, rea) = draw_joint_split(j.s, j.R, A, f, ax, anchor=[0.0, 0.0], scale=0.5,
                                              avoid=body, clearance=0.1)
    tail, tip = out["f"].get_arrow()
    for p in (tail, tip):                      # on the line y = x
        assert p[1] == pytest.approx(p[0])
    assert np.hypot(*(tip - tail)) == pytest.approx(0.5 * np.sqrt(2))
    assert LineString([tail, tip]).distance(body) >= 0.1 - 1e-9
    for k in ("active", "reaction"):
        seg = out[k].get_arrow()
        if seg is not None:
            assert LineString(seg).distance(body) >= 0.1 - 1e-9


# --------------------------------------------------------------------------- T/U decompositions (ch. 6)
# A rod (mass m, centre of mass c, inertia J about c) on a revolute joint at P, everything by hand:
#   s = [Py, -Px, 1] (the pole P, 4.64), R = [unit x force through P, unit y force through P]:
#   R1 = [1, 0, -Py], R2 = [0, 1, Px] (a line [fx, fy, tz]: tz + y fx - x fy = 0, 4.27).
#   For a twist u = [vx, vy, w], R_kᵀu is the velocity of P along e_k (vP = (vx - w Py, vy + w Px)).
#   T = A s (sᵀAs)⁻¹ (6.36): A s is the momentum of a unit rotation about P: force m (k × r)
#   (r = c - P), moment about O = J + m (c × (k × r))_z; sᵀAs = J_P = J + m|r|².
#   U = A⁻¹R(RᵀA⁻¹R)⁻¹ (6.45) is the only U with RᵀU = 1 and sᵀAU = 0 (sᵀ A A⁻¹ R = sᵀR = 0):
#   U_k moves P with unit acceleration along e_k and has zero angular momentum about P:
#   J w + m r × (e_k + w k × r) = 0  =>  w_k = -m (r × e_k) / J_P.
M, C, JC, P = 2.0, np.array([1.7, 0.4]), 0.3, np.array([0.5, -0.3])


def _rod_by_hand():
    r = C - P
    JP = JC + M * r @ r
    s = np.array([P[1], -P[0], 1.0])
    R = np.array([[1.0, 0.0], [0.0, 1.0], [-P[1], P[0]]])
    As = np.array([-M * r[1], M * r[0], JC + M * (C[0] * r[0] + C[1] * r[1])])
    T = As / JP
    U = np.zeros((3, 2))
    for k, ek in enumerate(np.eye(2)):
        w = -M * (r[0] * ek[1] - r[1] * ek[0]) / JP
        U[:, k] = [ek[0] + w * P[1], ek[1] - w * P[0], w]
    return s, R, T, U, JP


def _rod_inertia():
    # the rigid-body inertia at the origin, written out (4.58 with the package's column order)
    return np.array([[M, 0.0, -M * C[1]], [0.0, M, M * C[0]],
                     [-M * C[1], M * C[0], JC + M * C @ C]])


def test_decomposition_hand_closed_forms(ax):
    from planargeo.draw.constructions import draw_decomposition

    s, R, T, U, _ = _rod_by_hand()
    A = _rod_inertia()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = draw_decomposition(s[:, None], R, A, ax)
        ax.figure.canvas.draw()
    np.testing.assert_allclose(out["T"].get_line(), T, rtol=1e-12)          # T = A s (sᵀAs)⁻¹
    np.testing.assert_allclose(out["s"].get_point(), s)
    for k in range(2):
        np.testing.assert_allclose(out[f"R{k + 1}"].get_line(), R[:, k])
        np.testing.assert_allclose(out[f"U{k + 1}"].get_point(), U[:, k], atol=1e-12)
    # Fig. 6.2's geometry: U1 on R2, U2 on R1 (RᵀU = 1), both on T (TᵀU = 0)
    assert abs(U[:, 0] @ R[:, 1]) < 1e-12 and abs(U[:, 1] @ R[:, 0]) < 1e-12
    assert np.all(np.abs(T @ U) < 1e-12)
    # ... and so do the drawn poles and lines, against the hand lines and poles
    Ud = np.column_stack([out["U1"].get_point(), out["U2"].get_point()])
    Td = out["T"].get_line()
    assert abs(Ud[:, 0] @ R[:, 1]) < 1e-12 and abs(Ud[:, 1] @ R[:, 0]) < 1e-12
    np.testing.assert_allclose(R.T @ Ud, np.eye(2), atol=1e-12)
    assert np.all(np.abs(Td @ U) < 1e-12) and np.all(np.abs(T @ Ud) < 1e-12)
    # the drawn (clipped) T satisfies the hand line's equation (4.27)
    for x, y in out["T"].get_segment():
        assert abs(T[2] + y * T[0] - x * T[1]) <= 1e-9 * np.hypot(*T[:2])
    # Fig. 6.1's variant: the plain percussion poles A⁻¹R_k, also on T
    out = draw_decomposition(s[:, None], R, A, ax, reactive="inverse")
    for k in range(2):
        p = out[f"AiR{k + 1}"].get_point()
        assert abs(T @ p) < 1e-12 * np.linalg.norm(p)
        np.testing.assert_allclose(A @ p, R[:, k], atol=1e-12)
    with pytest.raises(Exception, match="reactive"):
        draw_decomposition(s, R, A, ax, reactive="V")


def test_wrench_split_is_f_equals_TQ_plus_Rmu(ax):
    """(6.38): f = T Q + R μ with Q = sᵀf (the moment of f about P) and μ = Uᵀf, by hand."""
    from planargeo.draw.constructions import draw_wrench_split

    s, R, T, U, _ = _rod_by_hand()
    A = _rod_inertia()
    # 3 N along (1, 2)/√5 through the point (2, 1): tz = x fy - y fx
    F = 3.0 * np.array([1.0, 2.0]) / np.sqrt(5.0)
    f = np.array([F[0], F[1], 2.0 * F[1] - 1.0 * F[0]])
    Q = (2.0 - P[0]) * F[1] - (1.0 - P[1]) * F[0]           # moment about P: (x - P) × F
    mu = U.T @ f
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = draw_wrench_split(s, R, A, f, ax, arrow_length=0.6)
        ax.figure.canvas.draw()
    v = out["values"]
    assert v["Q"][0] == pytest.approx(Q)
    np.testing.assert_allclose(v["mu"], mu, rtol=1e-12)
    np.testing.assert_allclose(out["f1"].get_line(), T * Q, rtol=1e-12)     # the active part TQ
    np.testing.assert_allclose(out["f2"].get_line(), R @ mu, atol=1e-12)    # the reaction Rμ
    np.testing.assert_allclose(out["f1"].get_line() + out["f2"].get_line(), f, atol=1e-12)
    # Rμ passes through the joint (sᵀRμ = 0); a1 = A⁻¹TQ turns about the joint; a2 on T
    assert abs(s @ out["f2"].get_line()) < 1e-12
    a1, a2 = out["a1"].get_point(), out["a2"].get_point()
    np.testing.assert_allclose(A @ a1, T * Q, atol=1e-12)
    np.testing.assert_allclose(a1[:2] / a1[2], s[:2], atol=1e-12)           # the pole P
    assert abs(T @ a2) < 1e-12 * np.linalg.norm(a2)
    for k in ("f1", "f2"):                                  # arrow_length: 0.6 whatever |F|
        out[k].set_anchor([0.0, 0.0])
        tail, tip = out[k].get_arrow()
        assert np.hypot(*(tip - tail)) == pytest.approx(0.6)


def test_twist_split_is_a_equals_s_psi_plus_U_gamma(ax):
    """(6.44): a = s ψ + U γ with ψ = Tᵀa and γ = Rᵀa (the acceleration of P), by hand."""
    from planargeo.draw.constructions import draw_twist_split

    s, R, T, U, _ = _rod_by_hand()
    A = _rod_inertia()
    alpha, X = 1.5, np.array([2.6, -0.4])                   # α about X
    a = alpha * np.array([X[1], -X[0], 1.0])
    aP = alpha * np.array([-(P[1] - X[1]), P[0] - X[0]])    # acceleration of P: α k × (P − X)
    psi = T @ a
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = draw_twist_split(s, R, A, a, ax, parts=[1])
        ax.figure.canvas.draw()
    assert "a2" not in out and "f2" not in out               # only the part asked for is drawn
    v = out["values"]
    np.testing.assert_allclose(v["gamma"], aP, rtol=1e-12)  # γ = Rᵀa
    assert v["psi"][0] == pytest.approx(psi)
    np.testing.assert_allclose(out["a1"].get_point(), s * psi, rtol=1e-12)
    np.testing.assert_allclose(v["a2"], U @ aP, atol=1e-12)
    np.testing.assert_allclose(v["a1"] + v["a2"], a, atol=1e-12)
    np.testing.assert_allclose(out["f1"].get_line(), A @ (s * psi), rtol=1e-12)
    # f1 = A sψ is a multiple of T (6.76), f2 = A Uγ passes through the joint
    np.testing.assert_allclose(np.cross(out["f1"].get_line(), T), 0.0, atol=1e-12)
    out2 = draw_twist_split(s, R, A, a, ax, parts=(2,), show_T=False)
    np.testing.assert_allclose(out2["a2"].get_point(), U @ aP, atol=1e-12)
    assert abs(s @ out2["f2"].get_line()) < 1e-12
    with pytest.raises(Exception, match="parts"):
        draw_twist_split(s, R, A, a, ax, parts=(3,))


def test_projective_step_joint_acceleration(ax):
    """(6.98–6.101): q̈ = Tᵀa_i − Tᵀ(a_{i−1} + κ); with a_i = a_{i−1} + κ + s q̈ this is q̈ (sᵀT = 1)."""
    from planargeo.draw.constructions import draw_projective_step

    s, R, T, U, _ = _rod_by_hand()
    A = _rod_inertia()
    a_prev = 0.7 * np.array([1.0, -2.0, 1.0])
    kap = np.array([0.4, -0.9, 0.0])                        # a translation (an ideal point)
    qdd = -1.3
    a = a_prev + kap + s * qdd
    out = draw_projective_step(s, R, A, a_prev, a, kap, ax)
    ax.figure.canvas.draw()
    assert out["values"]["qdd"][0] == pytest.approx(qdd)
    assert out["values"]["psi"][0] == pytest.approx(T @ a)
    np.testing.assert_allclose(out["T"].get_line(), T, rtol=1e-12)
    np.testing.assert_allclose(out["a"].get_point(), a)
