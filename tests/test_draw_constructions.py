"""Tests of planargeo.draw.constructions and mechanism: drawn geometry against closed forms."""
from __future__ import annotations

import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, strategies as st  # noqa: E402

from planargeo.draw.constructions import (draw_percussion, draw_polar_exterior,  # noqa: E402
                                          draw_polar_interior, draw_power, draw_twist_sum,
                                          draw_wrench_sum, line_conic_points)
from planargeo.draw.mechanism import draw_joint_split, draw_model, link_polygon  # noqa: E402
from planargeo.screws import inertia_matrix, unit_rotation, unit_translation  # noqa: E402


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
    x_axis = -f[2] / -f[1] if f[1] else None
    # f is vertical (force along y): x = -tz / -fy ... from tz + y fx - x fy = 0 with fx = 0
    x_axis = f[2] / f[1]
    assert x_axis - c[0] == pytest.approx(rho * rho / d)
    ax.figure.canvas.draw()


def test_power_relations(ax):
    I = inertia_matrix(1.5, [0.5, 0.2], 0.4)
    out = draw_power(np.array([0.3, -1.0, 1.2]), I, ax)
    assert np.allclose(out["checks"], 0.0, atol=1e-12)


def test_joint_split_and_model_drawing(ax):
    from planargeo.algorithms.rnea import newton_euler
    from planargeo.joints import revolute
    from planargeo.model import chain_model

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
    from planargeo.draw.figures.ch4 import Q47, QD47, QDD47, _chain3

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
