"""Joint motion / reaction spaces (thesis 4.8, 5.61–5.63).

References: the thesis's printed joint axes (4.64, 4.69, 4.74, 5.62, 5.63),
the twist/wrench transforms of planargeo.screws.twists (X_P, X_P_inv_T) used to look
at each basis element *from the joint*, and ranks computed with numpy.
"""
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo import errors
from planargeo.mechanics.joints import (DOF, KINDS, JointSpace, R_of, fixed, motion_space, plane, prismatic,
                              reaction_space, revolute, revolute_prismatic, twin_prismatic)
from planargeo.screws.twists import X_P, X_P_inv_T

coord = st.floats(-10, 10, allow_nan=False)
angle = st.floats(0, 2 * np.pi, allow_nan=False)
kinds = st.sampled_from(KINDS)


def _dir(lam):
    return np.array([np.cos(lam), np.sin(lam)])


# --------------------------------------------------------------------------- thesis values
@pytest.mark.parametrize("lam", [0.0, 0.3, 2.0, -1.2])
def test_prismatic_matches_thesis_5_62_5_63(lam):
    j = prismatic(direction=_dir(lam))
    c, s = np.cos(lam), np.sin(lam)
    np.testing.assert_allclose(j.s, [[c], [s], [0.0]], atol=1e-15)                   # (5.62), (4.69)
    np.testing.assert_allclose(j.R, [[-s, 0.0], [c, 0.0], [0.0, 1.0]], atol=1e-15)  # (5.63)


def test_revolute_at_origin_matches_thesis_4_64():
    np.testing.assert_array_equal(revolute().s, [[0.0], [0.0], [1.0]])


@pytest.mark.parametrize("lam", [0.0, 0.7, -2.5])
def test_revolute_prismatic_matches_thesis_4_74(lam):
    c, s = np.cos(lam), np.sin(lam)
    np.testing.assert_allclose(revolute_prismatic((0, 0), _dir(lam)).s,
                               [[c, 0.0], [s, 0.0], [0.0, 1.0]], atol=1e-15)


def test_twin_prismatic_matches_thesis_4_79():
    """Thesis 4.8.4 "plane joint": s = [e_x, e_y] (4.79); R = the couple [0, 0, 1] (line at infinity)."""
    j = twin_prismatic()
    np.testing.assert_array_equal(j.s, [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]])   # (4.79)
    np.testing.assert_array_equal(j.R, [[0.0], [0.0], [1.0]])
    np.testing.assert_array_equal(j.s.T @ j.R, [[0.0], [0.0]])                 # (5.61)
    assert j.dof == 2 and j.kind == "twin_prismatic"
    import planargeo
    assert planargeo.twin_prismatic is twin_prismatic and "twin_prismatic" in planargeo.__all__
    # plane (3 dof) is still the free joint: 4.79 plus the rotation about the frame origin
    np.testing.assert_array_equal(plane().s, np.eye(3))


@given(coord, coord, angle)
def test_twin_prismatic_rotated_and_placed(x, y, lam):
    """Frame x axis at angle λ: s = [(c, s, 0), (-s, c, 0)] (4.79 turned by λ); R is the couple wherever it is."""
    c, s = np.cos(lam), np.sin(lam)
    j = twin_prismatic(point=(x, y), direction=_dir(lam))
    np.testing.assert_allclose(j.s, [[c, -s], [s, c], [0.0, 0.0]], atol=1e-15)
    np.testing.assert_array_equal(j.R, [[0.0], [0.0], [1.0]])
    np.testing.assert_allclose(j.s.T @ j.R, 0.0, atol=0.0)                     # exact: translations are ideal
    # seen from the joint point, still two translations and a pure couple (frame changes 4.8, 4.24)
    np.testing.assert_allclose(X_P((x, y)) @ j.s, j.s, atol=1e-15)
    np.testing.assert_allclose(X_P_inv_T((x, y)) @ j.R, j.R, atol=1e-15)
    # it slides but does not turn: a rotation is not in span(s) (rank 3 with any unit rotation)
    assert np.linalg.matrix_rank(np.column_stack([j.s, [y, -x, 1.0]])) == 3


def test_twin_prismatic_subspace_identities():
    """Chapter 6 identities with a hand-derived T and U for a body with c.o.m. (a, b), mass m, inertia J about it.

    With s = [e_x, e_y] at the origin and I = [[m, 0, -m b], [0, m, m a], [-m b, m a, J + m(a²+b²)]] (4.58),
    sᵀIs = m·1, so T = I s / m = first two columns of I divided by m.  With R = [0, 0, 1], RᵀI⁻¹R = (I⁻¹)₂₂
    = 1/J (the rotational part of the mobility at the c.o.m.), so U = J · I⁻¹[:, 2] = [b, -a, 1]: the
    rotation about the centre of mass (a couple turns a free body about its c.o.m.).
    """
    from planargeo.mechanics.subspaces import Decomposition

    m, a, b, J = 2.0, 0.5, -1.5, 0.8
    I = np.array([[m, 0.0, -m * b], [0.0, m, m * a], [-m * b, m * a, J + m * (a * a + b * b)]])
    j = twin_prismatic()
    dec = Decomposition.from_joint(I, j)
    T_hand = np.array([[1.0, 0.0], [0.0, 1.0], [-b, a]])
    U_hand = np.array([[b], [-a], [1.0]])
    np.testing.assert_allclose(dec.T, T_hand, atol=1e-14)
    np.testing.assert_allclose(dec.U, U_hand, atol=1e-14)
    np.testing.assert_allclose(j.s.T @ dec.T, np.eye(2), atol=1e-14)           # sᵀT = 1
    np.testing.assert_allclose(j.R.T @ dec.U, [[1.0]], atol=1e-14)             # RᵀU = 1
    np.testing.assert_allclose(dec.T.T @ dec.U, 0.0, atol=1e-14)               # TᵀU = 0
    np.testing.assert_allclose(dec.T @ j.s.T + j.R @ dec.U.T, np.eye(3), atol=1e-14)   # (6.75)


def test_dof_and_shapes():
    for j, k in [(revolute((1, 2)), 1), (prismatic(point=(3, 0), direction=(1, 1)), 1),
                 (revolute_prismatic((1, 2), (0, 1)), 2), (twin_prismatic(point=(1, 2), direction=(0, 1)), 2),
                 (plane(), 3), (fixed((4, 5)), 0)]:
        assert j.dof == k == DOF[j.kind]
        assert j.s.shape == (3, k) and j.R.shape == (3, 3 - k)


# --------------------------------------------------------------------------- properties
@given(kinds, coord, coord, angle)
def test_reciprocity_and_completeness(kind, x, y, lam):
    """sᵀR = 0 (5.61) and [s R] spans the whole screw space, for every kind at any placement."""
    j = JointSpace(kind, (x, y), _dir(lam))
    scale = 1.0 + abs(x) + abs(y)
    np.testing.assert_allclose(j.s.T @ j.R, 0.0, atol=1e-12 * scale)
    full = np.hstack([j.s, j.R])
    assert np.linalg.matrix_rank(full, tol=1e-9) == 3
    # unit quantities: unit rotations (w = 1), unit translations, unit forces, unit couple
    for col in full.T:
        assert np.isclose(np.hypot(col[0], col[1]), 1.0) or np.isclose(col[2], 1.0)


@given(coord, coord)
def test_revolute_seen_from_its_pivot(x, y):
    """At the pivot, s is a pure rotation and the reactions are pure forces (no moment)."""
    j = revolute((x, y))
    np.testing.assert_allclose(X_P((x, y)) @ j.s[:, 0], [0.0, 0.0, 1.0], atol=1e-12)
    at_p = X_P_inv_T((x, y)) @ j.R
    np.testing.assert_allclose(at_p, [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]], atol=1e-12)


@given(coord, coord, angle)
def test_prismatic_and_slot_seen_from_the_joint(x, y, lam):
    e = _dir(lam)
    for j in (prismatic(point=(x, y), direction=e), revolute_prismatic((x, y), e)):
        force = X_P_inv_T((x, y)) @ j.R[:, 0]                 # at the joint point
        np.testing.assert_allclose(force, [-e[1], e[0], 0.0], atol=1e-12)  # perpendicular force through it
    j = revolute_prismatic((x, y), e)
    np.testing.assert_allclose(X_P((x, y)) @ j.s[:, 1], [0.0, 0.0, 1.0], atol=1e-12)


@given(coord, coord, angle)
def test_fixed_and_plane(x, y, lam):
    j = fixed((x, y))
    np.testing.assert_allclose(X_P_inv_T((x, y)) @ j.R, np.eye(3), atol=1e-12)
    np.testing.assert_array_equal(plane().s, np.eye(3))
    # plane: seen from its frame origin, the frame's x and y translations and a rotation
    e = _dir(lam)
    at_p = X_P((x, y)) @ plane((x, y), e).s
    np.testing.assert_allclose(at_p, [[e[0], -e[1], 0.0], [e[1], e[0], 0.0], [0.0, 0.0, 1.0]], atol=1e-12)


def test_vectorised_helpers_match_objects(rng):
    pts = rng.uniform(-3, 3, (4, 5, 2))
    dirs = rng.normal(size=(5, 2))
    for kind in KINDS:
        S = motion_space(kind, pts, dirs)
        R = reaction_space(kind, pts, dirs)
        assert S.shape == (4, 5, 3, DOF[kind]) and R.shape == (4, 5, 3, 3 - DOF[kind])
        for i in range(4):
            for k in range(5):
                j = JointSpace(kind, pts[i, k], dirs[k])
                np.testing.assert_allclose(S[i, k], j.s, atol=1e-14)
                np.testing.assert_allclose(R[i, k], j.R, atol=1e-14)


def test_direction_is_normalised_and_ignored_when_unused():
    np.testing.assert_allclose(prismatic(direction=(0.0, 5.0)).direction, [0.0, 1.0])
    assert revolute((1.0, 1.0)).direction is None
    # a revolute joint does not look at direction at all
    np.testing.assert_array_equal(motion_space("revolute", (1.0, 0.0), (0.0, 0.0)), [[0.0], [-1.0], [1.0]])


# --------------------------------------------------------------------------- object behaviour
def test_frozen_and_read_only():
    j = revolute((1.0, 2.0))
    with pytest.raises(AttributeError, match="frozen"):
        j.kind = "prismatic"
    with pytest.raises(ValueError):
        j.s[0, 0] = 5.0


def test_equality_hash_repr():
    assert prismatic(point=(1.0, 1.0), direction=(2.0, 0.0)) == prismatic(point=(1.0, 1.0), direction=(1.0, 0.0))
    assert revolute((1.0, 2.0)) != revolute((1.0, 2.5))
    assert revolute() != fixed()
    assert len({revolute((1, 2)), revolute((1.0, 2.0))}) == 1
    assert repr(revolute((1, 2))) == "JointSpace('revolute', point=(1.0, 2.0))"
    assert repr(prismatic(direction=(0, 2))) == "JointSpace('prismatic', point=(0.0, 0.0), direction=(0.0, 1.0))"


# --------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("make", [lambda: prismatic(direction=(0.0, 0.0)),
                                  lambda: revolute_prismatic((1.0, 1.0), (0.0, 0.0)),
                                  lambda: motion_space("prismatic", (0, 0), [[1, 0], [0, 0]]),
                                  lambda: reaction_space("revolute_prismatic", (0, 0), (0, 0))])
def test_zero_axis_is_degenerate(make):
    with pytest.raises(errors.DegenerateGeometryError, match="direction must be non-zero"):
        make()


def test_bad_shapes():
    with pytest.raises(errors.ShapeError, match=r"point must have shape \(\.\.\., 2\), got shape \(3,\)"):
        revolute((1.0, 2.0, 3.0))
    with pytest.raises(errors.ShapeError, match=r"point must have shape \(2,\), got shape \(2, 2\)"):
        revolute([[1.0, 2.0], [3.0, 4.0]])
    with pytest.raises(errors.ShapeError, match=r"direction must have shape \(\.\.\., 2\)"):
        prismatic(direction=(1.0, 0.0, 0.0))
    with pytest.raises(errors.ShapeError, match=r"direction must have shape \(2,\), got shape \(1, 2\)"):
        prismatic(direction=[[1.0, 0.0]])


def test_non_finite_and_bad_kind():
    with pytest.raises(errors.NonFiniteError, match="point must be finite"):
        revolute((np.nan, 0.0))
    with pytest.raises(errors.NonFiniteError, match="direction must be finite"):
        prismatic(direction=(np.inf, 0.0))
    with pytest.raises(errors.InputError, match="kind must be one of 'revolute'.*got 'hinge'"):
        JointSpace("hinge")
    with pytest.raises(errors.InputError, match="kind must be one of"):
        motion_space("ball", (0, 0))


@given(kinds, coord, coord, angle)
def test_motion_space_matches_model_kinematics(kind, x, y, phi):
    """Same columns, same order as the Model's kinematics (planargeo.mechanics.kinematics.joint_axes at q = 0).

    ``twin_prismatic`` is a Model joint kind too (thesis 4.79): ``s = [e, e⊥]`` with
    ``e = (cos φ, sin φ)``, by hand ``[[cos φ, -sin φ], [sin φ, cos φ], [0, 0]]`` wherever the joint is.
    """
    from planargeo.mechanics.kinematics import joint_axes

    if kind == "twin_prismatic":
        got = motion_space(kind, (x, y), _dir(phi))
        cols, _ = joint_axes("twin_prismatic", np.array(x), np.array(y), np.array(phi), np.zeros(2))
        np.testing.assert_allclose(got, np.stack(cols, axis=-1), atol=1e-12)
        c, s = math.cos(phi), math.sin(phi)
        np.testing.assert_allclose(got, [[c, -s], [s, c], [0.0, 0.0]], atol=1e-12)
        return
    k = DOF[kind]
    cols, _ = joint_axes(kind, np.array(x), np.array(y), np.array(phi), np.zeros(k))
    ref = np.stack(cols, axis=-1) if cols else np.zeros((3, 0))
    np.testing.assert_allclose(motion_space(kind, (x, y), _dir(phi)), ref, atol=1e-12)


# --------------------------------------------------------------------------- R_of (the algorithms' basis)
@given(kinds, coord, coord, angle)
def test_R_of_reads_the_joint_off_s(kind, x, y, lam):
    # the algorithms only see s (and a point of the joint): they must get the same R as the joint
    j = JointSpace(kind, (x, y), _dir(lam))
    np.testing.assert_allclose(R_of(j.s, (x, y)), j.R, atol=1e-12 * (1 + abs(x) + abs(y)))


@given(st.integers(0, 3), st.integers(0, 10_000))
def test_R_of_a_random_motion_space_is_its_reciprocal_complement(k, seed):
    # any s (not only a joint table's): R spans the wrenches reciprocal to s (sᵀR = 0, thesis 6.1)
    s = np.random.default_rng(seed).normal(size=(3, k))
    R = R_of(s)
    assert R.shape == (3, 3 - k)
    np.testing.assert_allclose(s.T @ R, 0.0, atol=1e-12 * (1 + np.abs(R).max(initial=0.0)))
    assert np.linalg.matrix_rank(np.hstack([s, R])) == 3


def test_R_of_hand_values_and_errors():
    # revolute at (2, 3): unit forces along x and y through it (thesis 7.16)
    np.testing.assert_array_equal(R_of([[3.0], [-2.0], [1.0]]), [[1, 0], [0, 1], [-3, 2]])
    # prismatic along x through (2, 3): the normal force through (2, 3) and the couple (5.63)
    np.testing.assert_array_equal(R_of([[1.0], [0.0], [0.0]], (2.0, 3.0)), [[0, 0], [1, 0], [2, 1]])
    # pin in a slot along x at (2, 3): the normal force through the pin; columns in either order
    s = np.array([[1.0, 3.0], [0.0, -2.0], [0.0, 1.0]])
    np.testing.assert_array_equal(R_of(s), [[0], [1], [2]])
    np.testing.assert_array_equal(R_of(s[:, ::-1]), [[0], [1], [2]])
    # two translations (twin prismatic, thesis 4.79): only a couple
    np.testing.assert_array_equal(R_of(np.eye(3)[:, :2]), [[0], [0], [1]])
    assert R_of(np.eye(3)).shape == (3, 0)
    np.testing.assert_array_equal(R_of(np.zeros((3, 0)), (1.0, 0.0)), [[1, 0, 0], [0, 1, 0], [0, 1, 1]])
    with pytest.raises(errors.ShapeError, match=r"s must have shape \(3, k\) with k <= 3, got shape \(2, 1\)"):
        R_of(np.zeros((2, 1)))
    with pytest.raises(errors.DegenerateGeometryError, match="direction must be non-zero"):
        R_of(np.zeros((3, 1)))


@pytest.mark.parametrize("make", [prismatic, twin_prismatic])
def test_old_positional_order_fails_clearly(make):
    """Issue 24: the point first for every joint; the old ``(direction, point)`` calls raise, never mean
    another joint."""
    for args in [((1.0, 1.0),), ((1.0, 0.0), (0.0, 3.0))]:
        with pytest.raises(errors.InputError, match=rf"{make.__name__} takes point= and direction= by name"):
            make(*args)


def test_every_constructor_takes_the_point_first():
    """Every joint constructor's first parameter is ``point``, and ``direction`` (where taken) comes after it."""
    import inspect

    for make in (revolute, prismatic, revolute_prismatic, twin_prismatic, plane, fixed):
        names = list(inspect.signature(make).parameters)
        assert names[0] == "point", make.__name__
        assert names[1:] in ([], ["direction"]), make.__name__
    # the point is where the slider's normal force acts: the reaction of a slider along +y through (3, 0)
    # is the force along x through (3, 0), i.e. the line y = 0 seen from the slide's normal (R = [1, 0, ...])
    j = prismatic(point=(3.0, 0.0), direction=(0.0, 1.0))
    np.testing.assert_allclose(j.point, [3.0, 0.0])
    np.testing.assert_allclose(j.direction, [0.0, 1.0])
    assert j == JointSpace("prismatic", (3.0, 0.0), (0.0, 1.0))
