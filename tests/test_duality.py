"""Duals written once: what a point and a line, a twist and a wrench share is one definition.

Each shared operation is checked against closed forms written out here (not the code under
test), for both members of the pair, so the one definition must serve both:

* a twist moved to the point ``P`` is ``[vx - ω py, vy + ω px, ω]`` (the velocity of the body
  point at ``P``, thesis 4.8); a wrench moved there keeps its force and takes its moment about
  ``P``, ``τ - (px fy - py fx)`` (4.24, 4.26); the power ``v·f`` is the same at every point;
* the incidence form of a point ``[y, -x, w]`` and a line ``[fx, fy, tz]`` is their dot
  product, and the signed distance of a finite point from a finite line is
  ``(tz + y fx - x fy) / |f|`` read either way round;
* the twist projectors are the transposes of the wrench projectors (thesis 6.75 and its dual);
* the kernels' one-state and many-state entry points, forward and inverse, are one road:
  a batch gives each state the numbers it gets alone, and the inverse dynamics of the forward
  dynamics' ``q̈`` gives back ``τ``.
"""
import numpy as np
import pytest

from planargeo.geometry.elements import Line, Point
from planargeo.geometry.projective import is_at_infinity, is_ideal
from planargeo.mechanics.model import random_model
from planargeo.mechanics.subspaces import twist_projectors, wrench_projectors
from planargeo.screws.special import twist_case, wrench_case
from planargeo.screws.twists import Twist, Wrench

RNG = np.random.default_rng(24)


@pytest.mark.parametrize("seed", range(20))
def test_a_screw_moved_to_a_point_by_hand(seed):
    rng = np.random.default_rng(seed)
    (vx, vy, w), (fx, fy, tau), (px, py) = rng.normal(size=3), rng.normal(size=3), rng.normal(size=2) * 3
    v, f = Twist([vx, vy, w]), Wrench([fx, fy, tau])
    np.testing.assert_allclose(v.at([px, py]).array, [vx - w * py, vy + w * px, w], rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(f.at([px, py]).array, [fx, fy, tau - (px * fy - py * fx)], rtol=1e-14, atol=1e-14)
    power = vx * fx + vy * fy + w * tau
    for a, b in [(v, f), (f, v), (v.at([px, py]), f.at([px, py]))]:
        assert a.power(b) == pytest.approx(power, rel=1e-12, abs=1e-12)
        assert float(a @ b) == pytest.approx(power, rel=1e-12, abs=1e-12)


def test_screws_and_their_duals_checked_by_kind():
    v, f = Twist.rotation([1.0, 1.0]), Wrench.force([1.0, 0.0], [0.0, 1.0])      # pole (1, 1) on the line x = 1
    assert bool(v.reciprocal(f)) and bool(f.reciprocal(v))
    with pytest.raises(TypeError):                      # a twist pairs with a wrench only
        v @ v
    with pytest.raises(TypeError):
        f @ f
    assert v.pole == Point.from_xy(1, 1) and f.line == Line.from_point_direction((1, 0), (0, 1))


@pytest.mark.parametrize("seed", range(20))
def test_incidence_and_distance_read_either_way(seed):
    rng = np.random.default_rng(100 + seed)
    x, y = rng.normal(size=2) * 4
    fx, fy, tz = rng.normal(size=3)
    p, l = Point.from_xy(x, y), Line([fx, fy, tz])
    form = y * fx + (-x) * fy + tz                      # [y, -x, 1] · [fx, fy, tz]
    assert p.incidence(l) == pytest.approx(form, abs=1e-12) and l.incidence(p) == p.incidence(l)
    assert (p @ l) == (l @ p) == p.incidence(l)
    d = (tz + y * fx - x * fy) / np.hypot(fx, fy)
    assert p.distance_to(l) == pytest.approx(d, rel=1e-12, abs=1e-12)
    assert l.signed_distance(p) == p.distance_to(l)
    assert p.normalized() == p and l.normalized() == l
    assert p.normalized().array[2] == 1.0 and np.hypot(*l.normalized().array[:2]) == pytest.approx(1.0, rel=1e-15)


def test_ideal_elements_through_the_shared_definitions():
    P, L = Point.at_infinity((3.0, 4.0)), Line.at_infinity()
    assert is_ideal(P.normalized().array) and is_at_infinity(L.normalized().array)
    assert P @ L == 0.0 and L.incidence(P) == 0.0                   # every ideal point lies on it
    y1 = Line.from_point_direction((0, 1), (1, 0))
    assert y1.signed_distance(P) == np.inf                          # infinitely far, on y = 1's left
    assert np.isnan(y1.signed_distance(Point.at_infinity((1, 0))))  # an ideal point on the line: 0/0
    assert Point.from_xy(1, 2).distance_to(L) == np.inf
    assert twist_case(Twist.translation([1.0, 0.0])).name == "pure_translation"
    assert is_ideal(Twist.translation([1.0, 0.0]).pole.array)
    assert wrench_case(Wrench.couple(2.0)).name == "pure_couple"
    assert is_at_infinity(Wrench.couple(2.0).line.array)


def test_twist_projectors_are_the_wrench_projectors_transposed():
    M = RNG.normal(size=(50, 3, 3))
    A = M @ np.swapaxes(M, -1, -2) + 0.1 * np.eye(3)
    Q, _ = np.linalg.qr(RNG.normal(size=(3, 3)))
    for k in (1, 2):
        s, R = Q[:, :k], Q[:, k:]
        (Tw, Rw), (Tt, Rt) = wrench_projectors(A, s, R), twist_projectors(A, s, R)
        np.testing.assert_array_equal(Tt, np.swapaxes(Tw, -1, -2))
        np.testing.assert_array_equal(Rt, np.swapaxes(Rw, -1, -2))
        np.testing.assert_allclose(Tt + Rt, np.broadcast_to(np.eye(3), Tt.shape), atol=1e-10)


@pytest.mark.parametrize("wrenches", [False, True])
def test_one_state_and_many_state_kernels_are_one_road(wrenches):
    """A batch in one call (the many-state kernel) gives, bit for bit, what each state gives alone."""
    import planargeo as pg

    m = random_model(6, seed=24, kinds=("revolute", "prismatic", "fixed"), tree=True, gravity=(0.5, -9.81))
    B = 40
    rng = np.random.default_rng(7)
    q, qd, tau = (np.ascontiguousarray(rng.normal(size=(B, m.nq))) for _ in range(3))
    fe = np.ascontiguousarray(rng.normal(size=(B, m.N, 3))) if wrenches else None
    qdd = pg.forward_dynamics(m, q, qd, tau, fe)
    back = pg.inverse_dynamics(m, q, qd, qdd, fe)
    np.testing.assert_allclose(back, tau, rtol=1e-9, atol=1e-9 * np.abs(tau).max())
    for b in range(B):
        f = None if fe is None else fe[b]
        np.testing.assert_array_equal(pg.forward_dynamics(m, q[b], qd[b], tau[b], f), qdd[b])
        np.testing.assert_array_equal(pg.inverse_dynamics(m, q[b], qd[b], qdd[b], f), back[b])
