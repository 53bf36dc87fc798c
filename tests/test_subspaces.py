"""Subspace decompositions (thesis 6.1–6.4).

References from outside the code under test:
* the defining conditions of T and U (sᵀT = 1, RᵀU = 1, TᵀU = 0, A U ⟂ s) as
  hypothesis properties over random SPD inertias and every joint kind;
* a dense Lagrange-multiplier (KKT) solve of a joint-constrained body at rest,
  I a = f + R λ, Rᵀ a = 0, done here with numpy on a 6×6 system;
* hand closed forms for the pinned body of thesis 5.64 (axis of percussion 5.67);
* explicit inverses (np.linalg.inv) in the tests only.
"""
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo import errors
from planargeo.mechanics.joints import KINDS, JointSpace, prismatic, revolute
from planargeo.screws.twists import inertia_matrix
from planargeo.mechanics.subspaces import (Decomposition, T_of, U_of, active_acceleration, active_force,
                                           effective_base_inertia, effective_mobility, inertia_decomposition,
                                           inverse_inertia_decomposition, joint_space_inertia, reaction_force,
                                           reaction_space_inverse_inertia, reactive_acceleration,
                                           twist_projectors, wrench_projectors)

coord = st.floats(-4, 4, allow_nan=False)
angle = st.floats(0, 2 * np.pi, allow_nan=False)


@st.composite
def body_inertias(draw):
    """Rigid-body inertia from mass, centre of mass and radius of gyration."""
    m = draw(st.floats(0.1, 10))
    c = (draw(coord), draw(coord))
    rho = draw(st.floats(0.1, 3))
    return inertia_matrix(m, c, m * rho ** 2)


@st.composite
def spd_matrices(draw):
    """General symmetric positive definite 3×3 (an articulated inertia need not be a rigid body's)."""
    L = np.array(draw(st.lists(st.floats(-2, 2), min_size=9, max_size=9))).reshape(3, 3)
    return L @ L.T + draw(st.floats(0.1, 2)) * np.eye(3)


inertias = st.one_of(body_inertias(), spd_matrices())


@st.composite
def joints(draw):
    kind = draw(st.sampled_from(KINDS))
    lam = draw(angle)
    return JointSpace(kind, (draw(coord), draw(coord)), (np.cos(lam), np.sin(lam)))


def _kkt(I, R, f):
    """Body at rest held by a joint with reaction space R, loaded by f: I a = f + R λ, Rᵀ a = 0."""
    r = R.shape[1]
    K = np.zeros((3 + r, 3 + r))
    K[:3, :3] = I
    K[:3, 3:] = -R
    K[3:, :3] = R.T
    sol = np.linalg.solve(K, np.concatenate([f, np.zeros(r)]))
    return sol[:3], sol[3:]


def _mx(x):
    return float(np.max(np.abs(x), initial=0.0))


# --------------------------------------------------------------------------- identities (6.22, 6.23, 6.46, 6.75)
@given(joints(), inertias)
def test_pseudo_inverse_identities(j, A):
    T = T_of(A, j.s)
    U = U_of(A, j.R)
    k = j.dof
    assert T.shape == (3, k) and U.shape == (3, 3 - k)
    tol = 1e-11 * np.linalg.cond(A) * (1 + _mx(j.s) + _mx(j.R)) ** 2
    np.testing.assert_allclose(j.s.T @ T, np.eye(k), atol=tol)            # (6.23), (6.32)
    np.testing.assert_allclose(j.R.T @ U, np.eye(3 - k), atol=tol)        # (6.22), (6.35)
    np.testing.assert_allclose(T.T @ U, 0.0, atol=tol)                    # (6.46)
    np.testing.assert_allclose(T @ j.s.T + j.R @ U.T, np.eye(3), atol=tol)  # (6.75)
    np.testing.assert_allclose(j.s @ T.T + U @ j.R.T, np.eye(3), atol=tol)  # dual of (6.75)
    # defining properties: T ∈ span(A s), A U ∈ span(R) (i.e. sᵀ A U = 0)
    np.testing.assert_allclose(j.s.T @ A @ U, 0.0, atol=tol * _mx(A))
    if k:
        coef = np.linalg.lstsq(A @ j.s, T, rcond=None)[0]
        np.testing.assert_allclose(A @ j.s @ coef, T, atol=tol * (1 + _mx(T)))


@given(joints(), inertias, st.lists(st.floats(-5, 5), min_size=6, max_size=6))
def test_decomposition_round_trips(j, A, vals):
    dec = Decomposition.from_joint(A, j)
    f, a = np.array(vals[:3]), np.array(vals[3:])
    Q, mu = dec.split_wrench(f)
    psi, gamma = dec.split_twist(a)
    tol = 1e-11 * np.linalg.cond(A) * (1 + _mx(f) + _mx(a)) * (1 + _mx(j.s)) ** 2
    np.testing.assert_allclose(dec.join_wrench(Q, mu), f, atol=tol)      # (6.38)
    np.testing.assert_allclose(dec.join_twist(psi, gamma), a, atol=tol)  # (6.44)
    # the function projections agree with the class (6.61, 6.62)
    np.testing.assert_allclose(active_force(j.s, f), Q, atol=1e-12)
    np.testing.assert_allclose(reaction_force(dec.U, f), mu, atol=1e-12)
    np.testing.assert_allclose(active_acceleration(dec.T, a), psi, atol=1e-12)
    np.testing.assert_allclose(reactive_acceleration(j.R, a), gamma, atol=1e-12)
    # the active part does no work through the reactions and vice versa: components are unique
    Pa, Pr = wrench_projectors(A, j.s, j.R)
    np.testing.assert_allclose(Pa @ Pa, Pa, atol=tol)
    np.testing.assert_allclose(Pa @ Pr, 0.0, atol=tol)
    Ja, Jr = twist_projectors(A, j.s, j.R)
    np.testing.assert_allclose(Ja @ Ja, Ja, atol=tol)
    np.testing.assert_allclose(Jr @ Jr, Jr, atol=tol)


@given(joints(), body_inertias(), st.lists(st.floats(-5, 5), min_size=3, max_size=3))
def test_constrained_body_at_rest_against_lagrange_multipliers(j, I, vals):
    """Pinned body at rest loaded by f (6.63–6.74, 6.80–6.93) vs. a dense KKT solve.

    The decomposition predicts: a = s Tᵀ I⁻¹ f (effective mobility, 6.93) with γ = Rᵀa = 0,
    Q = (sᵀIs) ψ (6.67), and since I s ψ = T Q the joint reaction cancels exactly the
    reactive part of f = T Q + R μ: λ = -μ (6.73, 6.84–6.88).
    """
    f = np.array(vals)
    a_ref, lam_ref = _kkt(I, j.R, f)          # plane joint (R empty): the free body, I a = f
    if j.dof == 3:
        np.testing.assert_allclose(a_ref, np.linalg.solve(I, f), atol=1e-12 * np.linalg.cond(I) * (1 + _mx(f)))
    # the joint rate of the KKT motion, read off a = s ψ by least squares (no T involved)
    psi_ref = np.linalg.lstsq(j.s, a_ref, rcond=None)[0] if j.dof else np.zeros(0)
    dec = Decomposition.from_joint(I, j)
    tol = 1e-11 * np.linalg.cond(I) * (1 + _mx(f)) * (1 + _mx(j.s)) ** 2
    np.testing.assert_allclose(effective_mobility(I, j.s) @ f, a_ref, atol=tol)          # (6.93)
    Q, mu = dec.split_wrench(f)
    psi, gamma = dec.split_twist(a_ref)
    np.testing.assert_allclose(gamma, 0.0, atol=tol)                                    # a = s q̈ (6.72)
    np.testing.assert_allclose(psi, psi_ref, atol=tol)
    np.testing.assert_allclose(joint_space_inertia(I, j.s) @ psi_ref, Q, atol=tol * (1 + _mx(I)))   # (6.67)
    np.testing.assert_allclose(lam_ref, -mu, atol=tol * (1 + _mx(I)))          # reaction = -Rμ part
    # the projection functions (6.61, 6.62) against the same KKT reference, not against the class
    T = T_of(I, j.s)
    U = U_of(I, j.R)
    np.testing.assert_allclose(active_force(j.s, f), joint_space_inertia(I, j.s) @ psi_ref, atol=tol * (1 + _mx(I)))
    np.testing.assert_allclose(reaction_force(U, f), -lam_ref, atol=tol * (1 + _mx(I)))
    np.testing.assert_allclose(active_acceleration(T, a_ref), psi_ref, atol=tol)
    np.testing.assert_allclose(reactive_acceleration(j.R, a_ref), 0.0, atol=tol)
    # the inverse-free U (with s) is the same U
    np.testing.assert_allclose(U_of(I, j.R, s=j.s), U, atol=tol * (1 + _mx(U)))


@given(joints(), body_inertias())
def test_inertia_decompositions(j, I):
    Ia, Ib = inertia_decomposition(I, j.s, j.R)
    Ii = np.linalg.inv(I)
    tol = 1e-11 * np.linalg.cond(I) * (1 + _mx(I)) * (1 + _mx(j.s)) ** 2
    np.testing.assert_allclose(Ia + Ib, I, atol=tol)                                 # (6.76)
    Ma, Mb = inverse_inertia_decomposition(I, j.s, j.R)
    np.testing.assert_allclose(Ma + Mb, Ii, atol=tol * _mx(Ii))            # (6.79)–(6.81)
    for P in (Ia, Ib, Ma, Mb):                                                      # all symmetric
        np.testing.assert_allclose(P, P.T, atol=tol * (1 + _mx(Ii)))
    # explicit-inverse references
    s, R = j.s, j.R
    if j.dof:
        np.testing.assert_allclose(Ma, s @ np.linalg.inv(s.T @ I @ s) @ s.T, atol=tol * _mx(Ii))
    if j.dof < 3:
        np.testing.assert_allclose(Ib, R @ np.linalg.inv(R.T @ Ii @ R) @ R.T, atol=tol)
        np.testing.assert_allclose(effective_base_inertia(I, R), Ib, atol=tol)       # (6.97)
        np.testing.assert_allclose(reaction_space_inverse_inertia(I, R), R.T @ Ii @ R, atol=tol)
    if j.dof:
        np.testing.assert_allclose(joint_space_inertia(I, s), s.T @ I @ s, atol=tol)


# --------------------------------------------------------------------------- hand closed forms
@pytest.mark.parametrize("m,d,rho", [(2.0, 1.0, 0.5), (1.0, 3.0, 1.0), (5.0, 0.2, 2.0)])
def test_axis_of_percussion_5_67(m, d, rho):
    """Pinned at the origin, CG at (d, 0): T is a force along y at x = d + ρ²/d, moment 1 (5.64–5.67)."""
    I = inertia_matrix(m, [d, 0.0], m * rho ** 2)
    T = T_of(I, revolute().s)[:, 0]
    np.testing.assert_allclose(T, [0.0, d / (rho ** 2 + d ** 2), 1.0], rtol=1e-14)
    assert np.isclose(T[2] / T[1], d + rho ** 2 / d)     # line tz = x fy: x = l (5.67)


def test_prismatic_at_centre_of_mass():
    """A slider through the CG: T is a force along the slide through the CG, U = (perp/m, spin/J)."""
    m, J, lam = 3.0, 2.0, 0.4
    e = np.array([np.cos(lam), np.sin(lam)])
    I = np.diag([m, m, J])
    j = prismatic(direction=e)
    np.testing.assert_allclose(T_of(I, j.s)[:, 0], [e[0], e[1], 0.0], atol=1e-15)
    np.testing.assert_allclose(U_of(I, j.R), j.R, atol=1e-15)


def test_batches_broadcast(rng):
    Ls = rng.normal(size=(5, 3, 3))
    A = Ls @ np.swapaxes(Ls, -1, -2) + np.eye(3)
    j = revolute((0.5, -1.0))
    T = T_of(A, j.s)
    U = U_of(A, j.R)
    assert T.shape == (5, 3, 1) and U.shape == (5, 3, 2)
    for i in range(5):
        np.testing.assert_allclose(T[i], T_of(A[i], j.s), atol=1e-14)
        np.testing.assert_allclose(U[i], U_of(A[i], j.R), atol=1e-14)
    # batch of joint spaces with one inertia
    from planargeo.mechanics.joints import motion_space, reaction_space
    pts = rng.uniform(-2, 2, (4, 2))
    S, R = motion_space("revolute", pts), reaction_space("revolute", pts)
    dec = Decomposition(A[0], S, R)
    f = rng.normal(size=(4, 3))
    Q, mu = dec.split_wrench(f)
    assert Q.shape == (4, 1) and mu.shape == (4, 2)
    np.testing.assert_allclose(dec.join_wrench(Q, mu), f, atol=1e-12)
    assert effective_mobility(A[0], S).shape == (4, 3, 3)


def test_empty_spaces():
    I = np.diag([1.0, 1.0, 2.0])
    dec = Decomposition(I, np.eye(3), np.zeros((3, 0)))
    assert dec.U.shape == (3, 0)
    np.testing.assert_allclose(dec.T, np.eye(3), atol=1e-15)     # T = I s (sᵀIs)⁻¹ = I I⁻¹ for s = 1
    dec0 = Decomposition(I, np.zeros((3, 0)), np.eye(3))
    assert dec0.T.shape == (3, 0)
    np.testing.assert_allclose(dec0.U, np.eye(3), atol=1e-15)


# --------------------------------------------------------------------------- thesis misprint 6.33
def test_erratum_6_33_missing_inverse(rng):
    """6.33 prints U = A⁻¹R (RᵀA⁻¹R); that fails RᵀU = 1 (6.35). The corrected form satisfies it."""
    I = inertia_matrix(3.0, [1.0, 0.5], 0.8)
    j = revolute((0.3, -0.2))
    Ii = np.linalg.inv(I)
    printed = Ii @ j.R @ (j.R.T @ Ii @ j.R)
    assert not np.allclose(j.R.T @ printed, np.eye(2), atol=1e-3)
    U = U_of(I, j.R)
    np.testing.assert_allclose(j.R.T @ U, np.eye(2), atol=1e-13)
    np.testing.assert_allclose(U, Ii @ j.R @ np.linalg.inv(j.R.T @ Ii @ j.R), atol=1e-13)   # 6.37 / 6.45


# --------------------------------------------------------------------------- bad input
def test_singular_joint_space_inertia():
    A = np.diag([1.0, 1.0, 0.0])                       # no rotational inertia: singular along s = rotation
    with pytest.raises(errors.SingularConfigurationError, match="sᵀAs is singular") as info:
        T_of(A, revolute().s)
    assert info.value.cond == np.inf
    with pytest.raises(errors.SingularConfigurationError, match="sᵀAs is singular") as info:
        T_of(np.diag([1.0, 1.0, 1e-15]), [0.0, 0.0, 1.0])
    assert 1e14 < info.value.cond < 1e16
    with pytest.raises(errors.SingularConfigurationError, match="sᵀIs is singular"):
        effective_mobility(A, [0.0, 0.0, 1.0])
    with pytest.raises(errors.SingularConfigurationError, match="sᵀAs is singular"):
        Decomposition(np.diag([1.0, 1.0, 0.0]), revolute().s, revolute().R)


def test_singular_reaction_space_inverse_inertia():
    # a legitimate (positive definite, rigid-body) inertia with a rank-deficient reaction space:
    # both columns are the unit force along x through the pivot, so RᵀA⁻¹R = [[a, a], [a, a]] is singular
    A = inertia_matrix(2.0, [1.0, 0.0], 0.5)
    fx = revolute((0.0, 0.0)).R[:, :1]
    R = np.hstack([fx, fx])
    G = R.T @ np.linalg.inv(A) @ R                              # by an explicit inverse: rank 1
    assert G[0, 0] > 0 and abs(np.linalg.det(G)) <= 1e-15 * G[0, 0] ** 2
    with pytest.raises(errors.SingularConfigurationError, match="RᵀA⁻¹R is singular") as info:
        U_of(A, R)
    assert info.value.cond > 1e12
    with pytest.raises(errors.SingularConfigurationError, match="RᵀI⁻¹R is singular"):
        effective_base_inertia(A, R)
    # positive semi-definite but singular A where A⁻¹ is needed: SingularInertiaError with cond
    with pytest.raises(errors.SingularInertiaError, match="A must be invertible") as info:
        U_of(np.diag([1.0, 1.0, 0.0]), revolute().R)
    assert info.value.cond == np.inf
    with pytest.raises(errors.SingularInertiaError, match="I must be invertible"):
        reaction_space_inverse_inertia(np.zeros((3, 3)), revolute().R)


# --------------------------------------------------------------------------- inertia arguments: symmetric, PSD / PD
INDEF = np.diag([1.0, -1.0, 1.0])                                # indefinite: RᵀA⁻¹R could vanish
NEGDEF = -inertia_matrix(2.0, [1.0, 0.0], 0.5)                   # negative definite
NONSYM = np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
POINT_MASS = inertia_matrix(1.0, [1.0, 0.0], 0.0)                # singular, positive semi-definite
_RJ = revolute((0.0, 0.0))

# (call with the inertia as the last argument, name of the inertia argument in messages)
INERTIA_ARG_CALLS = {
    "T_of": (lambda A: T_of(A, _RJ.s), "A"),
    "U_of": (lambda A: U_of(A, _RJ.R), "A"),
    "U_of(s=)": (lambda A: U_of(A, _RJ.R, s=_RJ.s), "A"),
    "joint_space_inertia": (lambda A: joint_space_inertia(A, _RJ.s), "I"),
    "reaction_space_inverse_inertia": (lambda A: reaction_space_inverse_inertia(A, _RJ.R), "I"),
    "effective_mobility": (lambda A: effective_mobility(A, _RJ.s), "I"),
    "effective_base_inertia": (lambda A: effective_base_inertia(A, _RJ.R), "I"),
    "inertia_decomposition": (lambda A: inertia_decomposition(A, _RJ.s, _RJ.R), "I"),
    "inverse_inertia_decomposition": (lambda A: inverse_inertia_decomposition(A, _RJ.s, _RJ.R), "I"),
    "wrench_projectors": (lambda A: wrench_projectors(A, _RJ.s, _RJ.R), "A"),
    "twist_projectors": (lambda A: twist_projectors(A, _RJ.s, _RJ.R), "A"),
    "Decomposition": (lambda A: Decomposition(A, _RJ.s, _RJ.R), "A"),
    "Decomposition(name=)": (lambda A: Decomposition(A, _RJ.s, _RJ.R, name="A_3"), "A_3"),
    "Decomposition.from_joint": (lambda A: Decomposition.from_joint(A, _RJ), "A"),
}
# functions that only multiply A or invert sᵀAs: a singular (semi-definite) inertia is fine
PSD_OK = {"T_of", "U_of(s=)", "joint_space_inertia", "effective_mobility"}


@pytest.mark.parametrize("fn", sorted(INERTIA_ARG_CALLS))
@pytest.mark.parametrize("bad", [INDEF, NEGDEF, np.stack([np.eye(3), INDEF])], ids=["indefinite", "negdef", "batch"])
def test_indefinite_inertia_rejected_naming_the_argument(fn, bad):
    call, name = INERTIA_ARG_CALLS[fn]
    with pytest.raises(errors.SingularInertiaError,
                       match=rf"^{name} must be positive semi-definite, got smallest eigenvalue -") as info:
        call(bad)
    assert isinstance(info.value, ValueError) and isinstance(info.value, errors.PlanargeoError)
    assert info.value.cond == np.inf


@pytest.mark.parametrize("fn", sorted(INERTIA_ARG_CALLS))
def test_non_symmetric_inertia_rejected_naming_the_argument(fn):
    call, name = INERTIA_ARG_CALLS[fn]
    with pytest.raises(errors.InputError, match=rf"^{name} must be symmetric, got asymmetry 0\.5$"):
        call(NONSYM)


@pytest.mark.parametrize("fn", sorted(INERTIA_ARG_CALLS))
def test_singular_semidefinite_inertia_accepted_only_where_no_inverse_is_needed(fn):
    call, name = INERTIA_ARG_CALLS[fn]
    # a point mass at (1, 0) pinned at the origin: sᵀAs = m = 1, but A itself is singular
    if fn in PSD_OK:
        out = call(POINT_MASS)
        assert np.all(np.isfinite(out))
    else:
        with pytest.raises(errors.SingularInertiaError, match=rf"^{name} must be invertible") as info:
            call(POINT_MASS)
        assert info.value.cond > 1e12


def test_semidefinite_inertia_results_by_hand():
    # point mass m = 1 at (1, 0) on a pin at the origin: sᵀIs = m d² = 1, T = I s = [0, 1, 1]
    # (the force along y through the mass), s (sᵀIs)⁻¹ sᵀ = e₃ e₃ᵀ; U by hand in test_inverse_free_U...
    np.testing.assert_allclose(joint_space_inertia(POINT_MASS, _RJ.s), [[1.0]])
    np.testing.assert_allclose(T_of(POINT_MASS, _RJ.s), [[0.0], [1.0], [1.0]])
    np.testing.assert_allclose(effective_mobility(POINT_MASS, _RJ.s), np.diag([0.0, 0.0, 1.0]))
    # rounding-level negative eigenvalues (a point mass far away) are not an error
    far = inertia_matrix(3.0, [1e3, -2e3], 0.0)
    assert np.linalg.eigvalsh(far)[0] <= 1e-9 * np.abs(far).max()
    joint_space_inertia(far, _RJ.s)


def test_bad_shapes_and_values():
    with pytest.raises(errors.ShapeError, match=r"s must have shape \(\.\.\., 3, k\).*got shape \(2, 1\)"):
        T_of(np.eye(3), np.ones((2, 1)))
    with pytest.raises(errors.ShapeError, match=r"s must have shape \(\.\.\., 3, k\), got shape \(4,\)"):
        T_of(np.eye(3), np.ones(4))
    with pytest.raises(errors.ShapeError, match=r"A must have shape \(\.\.\., 3, 3\), got shape \(2, 2\)"):
        T_of(np.eye(2), [0.0, 0.0, 1.0])
    with pytest.raises(errors.NonFiniteError, match="A must be finite"):
        T_of(np.diag([1.0, np.nan, 1.0]), [0.0, 0.0, 1.0])
    with pytest.raises(errors.NonFiniteError, match="R must be finite"):
        U_of(np.eye(3), [[np.inf], [0.0], [0.0]])
    with pytest.raises(errors.InputError, match="A must be symmetric"):
        T_of([[1.0, 2.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], [0.0, 0.0, 1.0])
    with pytest.raises(errors.ShapeError, match=r"f must have shape \(\.\.\., 3\)"):
        active_force([0.0, 0.0, 1.0], [1.0, 2.0])
    with pytest.raises(errors.ShapeError, match="s and R must have 3 columns together, got s with 1 and R with 1"):
        Decomposition(np.eye(3), [0.0, 0.0, 1.0], [1.0, 0.0, 0.0])
    with pytest.raises(errors.InputError, match=r"R must be reciprocal to s \(sᵀR = 0"):
        Decomposition(np.eye(3), [0.0, 0.0, 1.0], np.eye(3)[:, 1:])
    dec = Decomposition.from_joint(np.eye(3), revolute())
    with pytest.raises(errors.ShapeError, match=r"mu must have shape \(\.\.\., 2\)"):
        dec.join_wrench([1.0], [1.0, 2.0, 3.0])


@given(joints(), inertias, st.lists(st.floats(-3, 3), min_size=12, max_size=12))
def test_projective_equations_6_106_to_6_110_against_dense_solve(j, A, vals):
    """One body on a joint whose base accelerates: f = A a + d, a = a_prev + s q̈ + κ, sᵀf = Q.

    Dense reference (numpy, unknowns a, f, q̈) versus the decomposed solution
    a = s Tᵀ A⁻¹ (T Q − d) + U Rᵀ (a_prev + κ) (6.108), f = T Q + R Uᵀ (A (a_prev + κ) + d) (6.109),
    μ = Uᵀ A U γ + Uᵀ d (6.106a), ψ (6.107) and q̈ = Tᵀ (a − a_prev − κ) (6.110).
    """
    k = j.dof
    d, base, Q = np.array(vals[0:3]), np.array(vals[3:6]), np.array(vals[6:6 + k])   # base = a_prev + κ
    n = 6 + k
    K = np.zeros((n, n))
    rhs = np.zeros(n)
    K[0:3, 0:3], K[0:3, 3:6], rhs[0:3] = A, -np.eye(3), -d            # A a − f = −d
    K[3:6, 0:3], K[3:6, 6:], rhs[3:6] = np.eye(3), -j.s, base          # a − s q̈ = a_prev + κ
    K[6:, 3:6], rhs[6:] = j.s.T, Q                                     # sᵀ f = Q
    x = np.linalg.solve(K, rhs)
    a_ref, f_ref, qdd_ref = x[0:3], x[3:6], x[6:]

    dec = Decomposition.from_joint(A, j)
    T, U, R, s = dec.T, dec.U, j.R, j.s
    gamma = reactive_acceleration(R, base)                                         # (6.101)
    psi = T.T @ np.linalg.solve(A, T @ Q - d)                                      # (6.107)
    a = s @ psi + U @ gamma                                                        # (6.108)
    mu = U.T @ A @ U @ gamma + U.T @ d                                             # (6.106a)
    f = T @ Q + R @ mu                                                             # (6.109)
    tol = 1e-12 * np.linalg.cond(A) * (1 + _mx(vals)) * (1 + _mx(s) + _mx(R)) ** 2 * (1 + _mx(A))
    np.testing.assert_allclose(a, a_ref, atol=tol)
    np.testing.assert_allclose(f, f_ref, atol=tol)
    np.testing.assert_allclose(f, A @ a + d, atol=tol)
    np.testing.assert_allclose(T.T @ (a - base), qdd_ref, atol=tol)                # (6.110)
    np.testing.assert_allclose(reaction_force(U, f_ref), mu, atol=tol)            # (6.61b)


def test_inverse_free_U_handles_a_point_mass():
    # unit point mass at (1, 0) pinned at the origin: A is singular, U by hand (thesis 7.40, ρ = 0):
    # U = [[1, 0], [0, 1], [0, -1]] (the reactive accelerations leave the mass at (1, 0) at rest... along y)
    j = revolute((0.0, 0.0))
    I = inertia_matrix(1.0, [1.0, 0.0], 0.0)
    U = U_of(I, j.R, j.s)
    np.testing.assert_allclose(U, [[1.0, 0.0], [0.0, 1.0], [0.0, -1.0]], atol=1e-15)
    with pytest.raises(errors.SingularInertiaError, match="A must be invertible"):
        U_of(I, j.R)
    with pytest.raises(errors.InputError, match=r"R must be reciprocal to s \(sᵀR = 0"):
        U_of(I, j.R, revolute((1.0, 0.0)).s)
    with pytest.raises(errors.SingularConfigurationError, match="sᵀAs of joint 7 is singular"):
        T_of(I, revolute((1.0, 0.0)).s, what="sᵀAs of joint 7")
