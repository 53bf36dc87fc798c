"""Special cases of twists and wrenches named, and the passage through infinity (thesis 10.2.4).

References are hand-derived: poles, lines and powers of simple twists and wrenches
written out in coordinates ([y, -x, 1] for the point (x, y); [fx, fy, x fy - y fx] for
a force through (x, y)).
"""
from __future__ import annotations

import numpy as np
import pytest

from planargeo.errors import DegenerateGeometryError, InputError, ShapeError
from planargeo.screws.special import (CASES, SpecialCase, horizon_handle, horizon_point, pair_case,
                                      twist_case, twists_case, wrench_case, wrenches_case)
from planargeo.screws.twists import Twist, Wrench


def test_every_case_has_text_and_equation():
    for name, (text, eq) in CASES.items():
        assert text and eq[0].isdigit()
    c = twist_case([0.0, 1.0, 0.0])
    assert isinstance(c, SpecialCase) and str(c) == c.text and c.text.endswith("(4.10)")


@pytest.mark.parametrize("v, name", [
    ([0.0, 0.0, 0.0], "zero_twist"),
    ([3.0, 0.0, 0.0], "pure_translation"),
    ([2.0, -1.0, 1.0], "pure_rotation"),                       # about (1, 2)
    ([1.0, 0.0, np.cos(np.pi / 2)], "pure_translation"),        # ω = 6e-17: round-off is 0
    ([1.0, 0.0, 1e-9], "pure_rotation"),                        # a far pole, still finite
])
def test_twist_cases(v, name):
    assert twist_case(v).name == name


@pytest.mark.parametrize("f, name", [
    ([0.0, 0.0, 0.0], "zero_wrench"),
    ([0.0, 0.0, -2.0], "pure_couple"),
    ([0.0, 1.0, 2.0], "pure_force"),
])
def test_wrench_cases(f, name):
    assert wrench_case(f).name == name


def test_workless_is_incidence():
    # a force along x = 1 and a rotation about (1, 7): the pole is on the line
    f = Wrench.force([1.0, 0.0], [0.0, 2.0])
    assert pair_case(Twist.rotation([1.0, 7.0], 3.0), f).name == "workless"
    # the same rotation about (2, 7): power ω (x_f - x_pole) F = 3 · (1 - 2) · 2 = -6
    v = Twist.rotation([2.0, 7.0], 3.0)
    assert float(v @ f) == pytest.approx(-6.0)
    assert pair_case(v, f).name == "power"
    # a translation across the force (its ideal point lies in the line's direction: on the line)
    assert pair_case(Twist.translation([5.0, 0.0]), f).name == "workless"
    assert pair_case(Twist.translation([0.0, 5.0]), f).name == "power"      # along it: 5 · 2
    # a couple on a translation; anything on no motion
    assert pair_case([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]).name == "workless"
    assert pair_case([0.0, 0.0, 0.0], f).name == "zero_twist"


def test_sums_of_twists():
    assert twists_case([1.0, 0.0, 1.0], [2.0, 0.0, 2.0]).name == "coincident_poles"
    assert twists_case(Twist.rotation([0, 0], 2.0), Twist.rotation([3, 0], -2.0)).name == \
        "opposite_rotations"
    assert twists_case(Twist.rotation([0, 0], 1.0), Twist.rotation([3, 0], 2.0)).name == "rotations"
    assert twists_case(Twist.rotation([0, 0], 1.0), Twist.translation([0, 1])).name == \
        "rotation_translation"
    assert twists_case(Twist.translation([1, 0]), Twist.translation([0, 1])).name == "translations"
    assert twists_case([1.0, 2.0, 3.0], [-1.0, -2.0, -3.0]).name == "zero_sum"


def test_sums_of_wrenches():
    up0, up2 = Wrench.force([0, 0], [0, 1]), Wrench.force([2, 0], [0, 1])
    assert wrenches_case(up0, up2).name == "parallel_forces"
    assert wrenches_case(up0, -1.0 * up2).name == "couple_from_forces"
    assert wrenches_case(up0, 3.0 * up0).name == "same_line"
    assert wrenches_case(up0, Wrench.force([0, 0], [1, 0])).name == "concurrent"
    assert wrenches_case(up0, Wrench.couple(1.0)).name == "force_couple"
    assert wrenches_case(Wrench.couple(1.0), Wrench.couple(2.0)).name == "couples"
    assert wrenches_case(up0, -1.0 * up0).name == "zero_sum"


def test_bad_input_is_named():
    with pytest.raises(ShapeError, match="v must have shape"):
        twist_case(np.ones((2, 3)))
    with pytest.raises(InputError, match="rtol"):
        wrench_case([0, 1, 0], rtol=-1.0)
    with pytest.raises(InputError, match="radius"):
        horizon_point([0, 0], radius=0.0)
    with pytest.raises(DegenerateGeometryError, match="p is the zero vector"):
        horizon_handle([0.0, 0.0, 0.0])


def test_horizon_point_hand_values():
    # handle at d from the centre c = (1, 1), R = 2: the point c + d / (1 - |d|/2)
    p = horizon_point([2.0, 1.0], centre=[1.0, 1.0], radius=2.0)       # d = (1, 0), w = 1/2
    assert p[2] == 0.5 and np.allclose([-p[1] / p[2], p[0] / p[2]], [3.0, 1.0])
    p = horizon_point([1.0, 3.0], centre=[1.0, 1.0], radius=2.0)       # on the horizon, up
    assert p[2] == 0.0 and twist_case(p).name == "pure_translation"
    # the ideal point in direction (0, 1) is [a, b, 0] with (-b, a) ∝ (0, 1)
    assert p[1] == 0.0 and p[0] > 0


def test_horizon_handle_inverts_horizon_point():
    rng = np.random.default_rng(7)
    for d in rng.uniform(-0.95, 0.95, (50, 2)):
        if np.hypot(*d) >= 1.0:
            continue
        h = np.array([0.5, -0.5]) + d
        assert np.allclose(horizon_handle(horizon_point(h, [0.5, -0.5], 1.0), [0.5, -0.5], 1.0),
                           h + 0.0)
    # a handle beyond the horizon means a point shown just inside, on the opposite side
    out = horizon_handle(horizon_point([1.5, 0.0]))
    assert out[0] < 0 and np.hypot(*out) < 1.0


def test_dragging_through_infinity_is_smooth():
    """10.2.4: a handle moved across the horizon takes the pole through infinity without a jump.

    The homogeneous point moves continuously (steps as small as the handle's), the case
    passes rotation → translation → rotation, and the Euclidean pole leaves at +x and comes
    back from -x (the sign of w changes): no error, no NaN, no special branch.
    """
    hs = np.linspace(0.8, 1.2, 41)                         # includes 1.0 exactly
    P = np.array([horizon_point([h, 0.0]) for h in hs])
    steps = np.linalg.norm(np.diff(P, axis=0), axis=1)
    assert np.all(np.isfinite(P)) and steps.max() <= 1.5 * steps.min() + 1e-12
    names = [twist_case(p).name for p in P]
    k = int(np.flatnonzero(hs == 1.0)[0])
    assert names[k] == "pure_translation"
    assert set(names[:k]) == set(names[k + 1:]) == {"pure_rotation"}
    x = -P[:, 1] / np.where(P[:, 2] == 0, np.nan, P[:, 2])
    assert x[k - 1] > 50 and x[k + 1] < -50                 # off to +∞, back from -∞
    # the sum with a fixed rotation about the origin passes smoothly too
    v1 = Twist.rotation([0.0, 0.0], 1.0).array
    S = P + v1
    assert np.all(np.isfinite(S)) and np.linalg.norm(np.diff(S, axis=0), axis=1).max() < 0.05


def test_turning_a_force_line_through_parallel_is_smooth():
    """Two force lines: turning f2 through the direction of f1 moves their meet through infinity."""
    f1 = Wrench.force([0.0, 0.0], [1.0, 0.0]).array                         # the x axis
    th = np.linspace(-0.1, 0.1, 21)                                          # includes 0
    F2 = np.array([Wrench.force([0.0, 1.0], [np.cos(t), np.sin(t)]).array for t in th])
    M = np.cross(f1, F2)                                                     # meets, homogeneous
    assert np.linalg.norm(np.diff(M, axis=0), axis=1).max() < 0.02
    names = [wrenches_case(f1, f2).name for f2 in F2]
    assert names[10] == "parallel_forces" and M[10][2] == 0.0
    assert set(names) - {"parallel_forces"} == {"concurrent"}
    # the meet of y = 0 with the line through (0, 1) at angle t is (-cot t, 0)
    t = th[12]
    assert -M[12][1] / M[12][2] == pytest.approx(-1.0 / np.tan(t))
