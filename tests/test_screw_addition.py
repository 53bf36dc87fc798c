"""Twist addition (thesis 4.2, 4.11-4.16) and wrench addition (4.4, 4.33-4.46).

References: the thesis closed forms (re-derived by hand; 4.37 corrected, see
docs/errata.md), and elementary statics/kinematics.
"""
import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from planargeo.errors import DegenerateGeometryError, ShapeError
from planargeo.screws.twists import Twist, Wrench, add_twists, add_wrenches

fin = st.floats(-10, 10, allow_nan=False, allow_infinity=False)
xy = arrays(float, 2, elements=fin)
nz = st.floats(0.2, 5) | st.floats(-5, -0.2)
ang = st.floats(-np.pi, np.pi)


def xy_of(p):
    return p[:2][::-1] * [-1, 1] / p[2]      # [y, -x, 1] -> (x, y)


# ----------------------------------------------------------------- twists
@given(xy, xy, nz, nz)
def test_two_rotations_4_11_to_4_13(q1, q2, w1, w2):
    assume(abs(w1 + w2) > 0.1)
    c = add_twists(Twist.rotation(q1, w1), Twist.rotation(q2, w2))
    assert c.case == "rotations"
    beta = w2 / (w1 + w2)                                     # 4.13
    assert c.omega3 == pytest.approx(w1 + w2)                 # 4.11
    assert c.beta == pytest.approx(beta)
    np.testing.assert_allclose(xy_of(c.P), q1 + beta * (q2 - q1), atol=1e-8 * (1 + abs(beta)) * 20)  # 4.12
    np.testing.assert_allclose(xy_of(c.Q1), q1, atol=1e-12)
    np.testing.assert_allclose(c.sum.pole_xy, xy_of(c.P), atol=1e-9 * (1 + abs(beta)) * 20)
    if c.line is not None:
        assert abs(c.P @ c.line) < 1e-8 * (1 + abs(beta)) * 20    # P on the line Q1 Q2


@given(xy, xy, nz)
def test_opposite_rotations_give_perpendicular_translation(q1, q2, w):
    assume(np.linalg.norm(q1 - q2) > 1e-3)
    c = add_twists(Twist.rotation(q1, w), Twist.rotation(q2, -w))
    assert c.case == "opposite_rotations" and c.beta == np.inf
    u = c.sum.velocity
    assert c.sum.magnitude == 0.0
    # perpendicular to Q1Q2, speed |w| |Q1Q2| (velocity of Q1 under the second rotation)
    assert abs(u @ (q2 - q1)) < 1e-9 * 100 * (1 + abs(w))
    assert np.linalg.norm(u) == pytest.approx(abs(w) * np.linalg.norm(q2 - q1))
    np.testing.assert_allclose(u, -w * np.array([-(q1 - q2)[1], (q1 - q2)[0]]), atol=1e-9 * 100)
    assert c.P[2] == 0.0 and abs(c.P @ c.line) < 1e-12


@given(xy, nz, st.floats(0.1, 5), ang, st.booleans())
def test_rotation_plus_translation_4_16(q, w, u, lam, swap):
    e = np.array([np.cos(lam), np.sin(lam)])
    n = np.array([-np.sin(lam), np.cos(lam)])
    a, b = Twist.rotation(q, w), Twist.translation(u * e)
    c = add_twists(b, a) if swap else add_twists(a, b)
    assert c.case == "rotation_translation"
    rho = u / w
    assert c.rho == pytest.approx(rho)
    assert c.omega3 == w                                       # magnitude unchanged
    np.testing.assert_allclose(xy_of(c.P), q + rho * n, atol=1e-9 * 100)   # 4.16
    assert abs(c.P @ c.line) < 1e-9 * 100


def test_translations_and_zero():
    c = add_twists(Twist.translation([1.0, 0.0]), Twist.translation([0.0, 2.0]))
    assert c.case == "translations"
    np.testing.assert_allclose(c.sum.velocity, [1.0, 2.0])
    np.testing.assert_allclose(c.line, [0.0, 0.0, 1.0])       # join of two ideal points: line at infinity
    z = add_twists(Twist.translation([1.0, 0.0]), Twist.translation([-1.0, 0.0]))
    assert z.case == "zero" and z.P is None and z.line is None


def test_same_pole():
    c = add_twists(Twist.rotation([1.0, 1.0], 1.0), Twist.rotation([1.0, 1.0], 2.0))
    assert c.case == "rotations" and c.line is None
    np.testing.assert_allclose(xy_of(c.P), [1.0, 1.0])


def test_lever_rule_matches_statics_4_14_4_15():
    # beam reactions R1, R2 at x=0 and x=L under a load F at x=a: R2 = F a / L
    L, a, F = 5.0, 2.0, 10.0
    R2 = F * a / L
    R1 = F - R2
    c = add_twists(Twist.rotation([0.0, 0.0], R1), Twist.rotation([L, 0.0], R2))
    assert c.beta == pytest.approx(R2 / (R1 + R2)) and c.omega3 == pytest.approx(F)
    np.testing.assert_allclose(xy_of(c.P), [a, 0.0])


# ----------------------------------------------------------------- wrenches
def thesis_4_35_corrected(f1, f2):
    """Meet point by slopes and intercepts with the corrected 4.37 (both intercepts -tau/fx)."""
    e1, e2 = f1[1] / f1[0], f2[1] / f2[0]                      # 4.36 slopes
    y1, y2 = -f1[2] / f1[0], -f2[2] / f2[0]                    # 4.37 corrected: true y intercepts
    return np.array([(y2 - y1) / (e1 - e2), (e1 * y2 - e2 * y1) / (e1 - e2)])


def thesis_4_35_as_printed(f1, f2):
    e1, e2 = f1[1] / f1[0], f2[1] / f2[0]
    y1, y2 = -f1[2] / f1[0], f2[2] / f2[0]                     # 4.37 as printed
    return np.array([(y1 - y2) / (e1 - e2), e2 / (e1 - e2) * y1 - e1 / (e1 - e2) * y2])   # 4.35 as printed


angle_pairs = st.tuples(ang, ang).filter(
    lambda t: abs(np.sin(t[0] - t[1])) > 0.2 and abs(np.cos(t[0])) > 0.2 and abs(np.cos(t[1])) > 0.2)


@given(xy, xy, st.floats(0.2, 5), st.floats(0.2, 5), angle_pairs)
def test_concurrent_forces_4_34_to_4_39(p1, p2, F1, F2, lams):
    l1, l2 = lams
    f1 = Wrench.force(p1, F1 * np.array([np.cos(l1), np.sin(l1)]))
    f2 = Wrench.force(p2, F2 * np.array([np.cos(l2), np.sin(l2)]))
    c = add_wrenches(f1, f2)
    assert c.case == "concurrent"
    P = thesis_4_35_corrected(f1.array, f2.array)
    np.testing.assert_allclose(xy_of(c.P), P, rtol=1e-7, atol=1e-7 * (1 + np.abs(P).max()))
    # P solves 4.34 (lies on both lines) and on the resultant line
    for f in (f1.array, f2.array, c.sum.array):
        assert abs(f[2] + P[1] * f[0] - P[0] * f[1]) < 1e-7 * (1 + np.abs(P).max()) * (1 + np.abs(f).max())
    s = f1.array[:2] + f2.array[:2]
    F3 = np.hypot(*s)
    assert c.F3 == pytest.approx(F3)                                              # 4.39
    np.testing.assert_allclose(c.sum.direction, s / F3)                           # 4.38
    assert float(c.sum.distance) == pytest.approx((f1.array[2] + f2.array[2]) / F3, abs=1e-9)  # d3


def test_thesis_4_37_as_printed_is_wrong():
    # x-axis force through (0, 1)... concrete: lines y = x + 1 and y = -x + 3 meet at (1, 2)
    f1 = Wrench.force([0.0, 1.0], [1.0, 1.0]).array
    f2 = Wrench.force([0.0, 3.0], [1.0, -1.0]).array
    np.testing.assert_allclose(thesis_4_35_corrected(f1, f2), [1.0, 2.0])
    np.testing.assert_allclose(xy_of(add_wrenches(f1, f2).P), [1.0, 2.0])
    assert not np.allclose(thesis_4_35_as_printed(f1, f2), [1.0, 2.0])


@given(xy, xy, st.floats(0.2, 5), st.floats(-5, 5).filter(lambda F: abs(F) > 0.2), ang)
def test_parallel_forces_lever_rule_4_40_to_4_45(p1, p2, F1, F2, lam):
    assume(abs(F1 + F2) > 0.1)
    e = np.array([np.cos(lam), np.sin(lam)])
    f1 = Wrench.force(p1, F1 * e)
    f2 = Wrench.force(p2, F2 * e)
    c = add_wrenches(f1, f2)
    assert c.case == "parallel"
    n = np.array([np.sin(lam), -np.cos(lam)])
    d1, d2 = p1 @ n, p2 @ n                         # signed distances along n (4.30-4.32)
    beta = F2 / (F1 + F2)                            # 4.44
    d3 = d1 + beta * (d2 - d1)                       # 4.43
    assert c.beta == pytest.approx(beta)
    assert c.d1 == pytest.approx(d1, abs=1e-9) and c.d2 == pytest.approx(d2, abs=1e-9)
    assert c.d3 == pytest.approx(d3, rel=1e-7, abs=1e-7 * (1 + abs(beta)) * 20)
    assert c.F3 == pytest.approx(abs(F1 + F2))                                    # 4.42 (unsigned)
    # the resultant line is at signed distance d3: point d3 n lies on it
    L = c.sum.array
    pt = d3 * n
    assert abs(L[2] + pt[1] * L[0] - pt[0] * L[1]) < 1e-6 * (1 + abs(beta)) * 20 * (1 + np.abs(L).max())
    assert c.P[2] == 0.0


def test_opposite_parallel_forces_give_couple():
    c = add_wrenches(Wrench.force([0.0, 0.0], [0.0, 2.0]), Wrench.force([3.0, 0.0], [0.0, -2.0]))
    assert c.case == "couple"
    np.testing.assert_allclose(c.sum.array, [0.0, 0.0, -6.0])       # moment 2 * 3, clockwise
    np.testing.assert_array_equal(c.L3, [0.0, 0.0, -1.0])          # line at infinity keeps the couple's sense
    z = add_wrenches(Wrench.force([0.0, 0.0], [0.0, 2.0]), Wrench.force([0.0, 5.0], [0.0, -2.0]))
    assert z.case == "zero" and z.L3 is None


@given(xy, st.floats(0.2, 5), ang, nz, st.booleans())
def test_force_plus_couple_4_46(p, F, lam, tau, swap):
    e = np.array([np.cos(lam), np.sin(lam)])
    f = Wrench.force(p, F * e)
    m = Wrench.couple(tau)
    c = add_wrenches(m, f) if swap else add_wrenches(f, m)
    assert c.case == "force_couple"
    rho = tau / F                                               # 4.46
    assert c.rho == pytest.approx(rho)
    assert c.F3 == pytest.approx(F)
    np.testing.assert_allclose(c.sum.direction, e, atol=1e-12)
    # shifted by rho along n = (fy, -fx)/F (4.32): the point p + rho n is on the resultant
    n = np.array([e[1], -e[0]])
    q = p + rho * n
    L = c.sum.array
    assert abs(L[2] + q[1] * L[0] - q[0] * L[1]) < 1e-9 * 100 * (1 + np.abs(L).max())
    assert c.P[2] == 0.0                                        # meet with the line at infinity


def test_two_couples():
    c = add_wrenches(Wrench.couple(1.0), Wrench.couple(2.0))
    assert c.case == "couples" and c.P is None
    np.testing.assert_allclose(c.sum.array, [0.0, 0.0, 3.0])


sane = st.floats(-10, 10).filter(lambda x: x == 0 or abs(x) > 1e-3)


@given(arrays(float, 3, elements=sane), arrays(float, 3, elements=sane))
def test_sum_line_through_meet_point(a, b):
    assume(np.abs(a).max() > 1e-3 and np.abs(b).max() > 1e-3)
    c = add_wrenches(a, b)
    k = 1e-7 * (1 + np.abs(a).max() + np.abs(b).max())
    if c.P is not None and c.L3 is not None:
        assert abs(c.P @ c.L3) <= k * np.linalg.norm(c.P) * np.linalg.norm(c.L3)
    t = add_twists(a, b)
    if t.P is not None and t.line is not None:
        assert abs(t.P @ t.line) <= k * np.linalg.norm(t.P) * np.linalg.norm(t.line)


def test_bad_construction_inputs():
    with pytest.raises(DegenerateGeometryError, match="v1 must be non-zero"):
        add_twists([0.0, 0.0, 0.0], [1.0, 0.0, 0.0])
    with pytest.raises(DegenerateGeometryError, match="f2 must be non-zero"):
        add_wrenches([1.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    with pytest.raises(ShapeError, match="f1 must have shape"):
        add_wrenches(np.ones((2, 3)), [1.0, 0.0, 0.0])
    # single values only (documented): the constructions do not broadcast
    with pytest.raises(ShapeError, match=r"^v2 must have shape \(3,\) for a construction, got shape \(2, 3\)$"):
        add_twists([1.0, 0.0, 1.0], np.ones((2, 3)))
    with pytest.raises(ShapeError, match=r"^f2 must have shape \(3,\) for a construction, got shape \(1, 3\)$"):
        add_wrenches([1.0, 0.0, 0.0], np.ones((1, 3)))
