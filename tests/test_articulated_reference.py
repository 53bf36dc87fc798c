"""Independent references for the dynamics of thesis chapters 6, 7 and 9.

Nothing here uses the recursions under test (articulated inertia, mobility, projective,
stacked) nor the dense CRBA solve (which shares the code that forms ``H``):

* :func:`kkt`: the loop/KKT solve in maximal coordinates
  (:func:`planargeo.algorithms.loops.constrained_dynamics_lagrange` with no contacts):
  centre of mass and angle of every body, the tree joints as hand-written position
  constraints with Lagrange multipliers, one dense solve; it shares only the poses and
  velocities of :func:`planargeo.mechanics.kinematics.kinematics`.  Every joint kind.
* :func:`pinocchio_qdd`: Pinocchio's ``aba`` on the same mechanism
  (``benchmarks/bench.py``'s ``to_pinocchio``; revolute and prismatic joints), with the
  external wrenches moved into each joint's frame.
* ``dense_articulated(model, q, qd, tau, f_ext, i)``: ``A_i`` and ``d_i`` of the
  subtree rooted at body ``i``, made free-floating by replacing joint ``i`` with a
  ``plane`` joint at the same world pose, solved by :func:`kkt`: with ``f_i = 0`` the
  body accelerates by ``a_free``, and a unit wrench ``e_k`` on it adds column ``k`` of
  ``A_i⁻¹`` (thesis 7.1: ``a_i = A_i⁻¹ (f_i - d_i)``), so ``d_i = -A_i a_free``.
* ``dense_mobility(model, q, qd, tau, f_ext, i)``: ``Lambda_i^-1`` and ``b_i`` of the
  tree with body ``i``'s descendants cut off (a chain: truncated after body ``i``; thesis
  7.28, 9.45): a wrench ``w`` on body ``i`` accelerates it by ``b_i + Lambda_i^-1 w``.
* ``dense_articulated`` and ``dense_mobility`` use Pinocchio where it models the joints
  and the KKT solve otherwise (or with ``use_kkt=True``; the two agree, tested below).
* :func:`mobility_matrix`: the tree's full mobility ``Φ = J H⁻¹ Jᵀ`` by unit wrenches
  (Pinocchio).
* :func:`newton_euler_forces`: the joint forces of given body accelerations by
  Newton-Euler, ``f_i = I_i a_i + p_i + Σ_children f_c`` (3.9, 6.102).

The helpers are imported by the other ``test_articulated*`` / projective / chain
splitting / stacked test files; the tests below check the references themselves on
hand-derived cases and against each other.
"""
from __future__ import annotations

import functools

import numpy as np
import pytest

from planargeo.algorithms.loops import constrained_dynamics_lagrange
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Body, Joint, Model, random_model
from planargeo.screws.twists import inertia_matrix

EPS = np.finfo(float).eps


def kkt(model: Model, q, qd, tau, f_ext=None) -> dict:
    """The maximal-coordinates KKT solve of the open tree: ``a`` (N, 3) at the origin and ``qdd``."""
    return constrained_dynamics_lagrange(model, q, qd, tau, f_ext, contacts=())


@functools.lru_cache(maxsize=64)
def _pinocchio_model(model: Model):
    """The Pinocchio model and its data (kept: a data of 200 joints takes 0.4 s to allocate)."""
    from bench import to_pinocchio

    pm = to_pinocchio(model)
    return pm, pm.createData()


def _pinocchio(model: Model, q, qd, tau, f_ext):
    """Pinocchio's ``aba`` and the body accelerations at the world origin (revolute and prismatic joints)."""
    import pinocchio as pin

    pm, pd = _pinocchio_model(model)
    q, qd, tau = (np.asarray(x, dtype=float) for x in (q, qd, tau))
    pin.forwardKinematics(pm, pd, q)
    fext = pin.StdVec_Force()
    fext.append(pin.Force.Zero())
    f_ext = np.zeros((model.N, 3)) if f_ext is None else np.asarray(f_ext, dtype=float)
    for i, (fx, fy, tz) in enumerate(f_ext):          # a world wrench at the origin, in joint i's frame
        fext.append(pd.oMi[i + 1].actInv(pin.Force(np.array([fx, fy, 0.0]), np.array([0.0, 0.0, tz]))))
    qdd = pin.aba(pm, pd, q, qd, tau, fext).copy()
    pin.forwardKinematics(pm, pd, q, qd, qdd)
    a = [pd.oMi[i + 1].act(pd.a[i + 1]) for i in range(model.N)]    # spatial accelerations at the origin
    return qdd, np.array([[m.linear[0], m.linear[1], m.angular[2]] for m in a])


def _pinocchio_models(model: Model) -> bool:
    return all(j.kind in ("revolute", "prismatic") for j in model.joints)


def pinocchio_qdd(model: Model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Pinocchio's ``aba`` (revolute and prismatic joints); ``f_ext`` world wrenches at the origin."""
    return _pinocchio(model, q, qd, tau, f_ext)[0]


def reference_qdd(model: Model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Pinocchio where it models the joints (revolute, prismatic), else the KKT solve."""
    if _pinocchio_models(model):
        return pinocchio_qdd(model, q, qd, tau, f_ext)
    return kkt(model, q, qd, tau, f_ext)["qdd"]


def reference_accelerations(model: Model, q, qd, tau, f_ext=None, *, use_kkt: bool = False) -> np.ndarray:
    """Body accelerations (N, 3) at the origin: Pinocchio where it models the joints, else (or ``use_kkt``) the KKT solve."""
    if _pinocchio_models(model) and not use_kkt:
        return _pinocchio(model, q, qd, tau, f_ext)[1]
    return kkt(model, q, qd, tau, f_ext)["a"]


def mobility_matrix(model: Model, q) -> np.ndarray:
    """The tree's full mobility ``Φ`` (3N×3N) by Pinocchio: block ``(i, j)`` is body ``i``'s acceleration
    per unit wrench on body ``j`` (the ``Λ⁻¹`` of 9.65-9.73, ``J H⁻¹ Jᵀ``), read off unit loads at rest."""
    z = np.zeros(model.nq)
    a0 = reference_accelerations(model, q, z, z)
    Phi = np.empty((3 * model.N, 3 * model.N))
    for c in range(3 * model.N):
        f = np.zeros(3 * model.N)
        f[c] = 1.0
        Phi[:, c] = (reference_accelerations(model, q, z, z, f.reshape(-1, 3)) - a0).reshape(-1)
    return 0.5 * (Phi + Phi.T)


def newton_euler_forces(model: Model, q, qd, a, f_ext=None) -> np.ndarray:
    """Joint forces ``f_i = I_i a_i + p_i + Σ_children f_c`` (thesis 3.9, 6.102) of body accelerations ``a``."""
    d = kinematics(model, q, qd, f_ext)
    f = np.einsum("nij,nj->ni", d.I, a) + d.p
    for i in reversed(range(model.N)):
        if model.parents[i] >= 0:
            f[model.parents[i]] += f[i]
    return f


def mass_matrix_cond(model: Model, q) -> float:
    """``cond(H)`` of ``H = Σ J_iᵀ I_i J_i`` (the definition; for tolerances only)."""
    d = kinematics(model, q)
    J = d.J
    H = np.einsum("nki,nkl,nlj->ij", J, d.I, J, optimize=True)
    return float(np.linalg.cond(H))


def subtree(model: Model, i: int) -> list[int]:
    """Body ``i`` and all its descendants, in model order."""
    out = [i]
    for k in range(i + 1, model.N):
        if model.parents[k] in out:
            out.append(k)
    return out


#: Mass of the two placeholder bodies of :func:`floating_subtree`'s ``"PPR"`` base: nothing next to real masses
_NOTHING = 1e-300


def floating_subtree(model: Model, q, qd, f_ext, i: int, base: str = "plane"):
    """The subtree rooted at ``i`` with joint ``i`` replaced by a free joint.

    ``base="plane"``: one ``plane`` joint at the same world pose; ``"PPR"``: a prismatic
    joint along x and one along y carrying placeholder bodies of mass 1e-300, then a
    revolute joint (the same coordinates ``(x, y, θ)``; for Pinocchio, which models
    revolute and prismatic joints here).  Returns ``(sub_model, q_sub, qd_sub, f_sub, keep)``:
    the same world configuration and velocities, ``keep`` the original body indices
    (``keep[0] = i`` is body ``sub_model.N - len(keep)`` of the subtree).
    """
    d = kinematics(model, q, qd)
    keep = subtree(model, i)
    idx = {k: n for n, k in enumerate(keep)}
    bodies = [model.bodies[k] for k in keep]
    joints = [Joint("plane", (0.0, 0.0, 0.0))] + [model.joints[k] for k in keep[1:]]
    parents = [-1] + [idx[model.parents[k]] for k in keep[1:]]
    sub = Model(bodies, joints, parents, model.gravity)
    x, y, th = d.pose[i]
    qs = [np.array([x, y, th])] + [np.asarray(q)[model.q_slice(k)] for k in keep[1:]]
    q_sub = np.concatenate(qs)
    # plane-joint speeds reproducing v_i: solve S_plane qd = v_i
    S_plane = kinematics(sub, q_sub).s(0)
    qds = [np.linalg.solve(S_plane, d.v[i])] + [np.asarray(qd)[model.q_slice(k)] for k in keep[1:]]
    qd_sub = np.concatenate(qds)
    f_sub = None if f_ext is None else np.asarray(f_ext)[keep]
    if base == "PPR":
        bodies = [Body(_NOTHING)] * 2 + bodies
        joints = [Joint("prismatic"), Joint("prismatic", (0.0, 0.0, np.pi / 2)),
                  Joint("revolute", (0.0, 0.0, -np.pi / 2))] + joints[1:]
        sub = Model(bodies, joints, [-1, 0, 1] + [p + 2 for p in parents[1:]], model.gravity)
        f_sub = None if f_sub is None else np.vstack([np.zeros((2, 3)), f_sub])
    return sub, q_sub, qd_sub, f_sub, keep


def _wrench_response(model, q, qd, tau, f_ext, body, use_kkt=False):
    """``(a_0, M)``: body ``body``'s acceleration with the loads ``f_ext`` and ``M[:, k]`` its change per unit wrench ``e_k``."""
    f0 = np.zeros((model.N, 3)) if f_ext is None else np.asarray(f_ext, dtype=float)
    a0 = reference_accelerations(model, q, qd, tau, f0, use_kkt=use_kkt)[body]
    M = np.empty((3, 3))
    for k in range(3):
        fk = f0.copy()
        fk[body, k] += 1.0
        M[:, k] = reference_accelerations(model, q, qd, tau, fk, use_kkt=use_kkt)[body] - a0
    return a0, M


def dense_articulated(model: Model, q, qd, tau, f_ext, i: int, *, use_kkt: bool = False):
    """Reference ``(A_i, d_i)`` from the free-floating subtree (thesis 7.1): Pinocchio where it models the
    joints (on the ``"PPR"`` base), else (or ``use_kkt``) the KKT solve (on a ``plane`` joint)."""
    kinds_ok = all(model.joints[k].kind in ("revolute", "prismatic") for k in subtree(model, i)[1:])
    base = "PPR" if kinds_ok and not use_kkt else "plane"
    sub, q_sub, qd_sub, f_sub, keep = floating_subtree(model, q, qd, f_ext, i, base)
    tau_sub = np.concatenate([np.zeros(3)] + [np.asarray(tau)[model.q_slice(k)] for k in keep[1:]])
    a_free, Ainv = _wrench_response(sub, q_sub, qd_sub, tau_sub, f_sub, sub.N - len(keep), use_kkt)
    A = np.linalg.inv(Ainv)
    return 0.5 * (A + A.T), -A @ a_free


def without_descendants(model: Model, i: int):
    """``(sub_model, keep)``: the tree with body ``i``'s descendants cut off (a chain: bodies ``0..i``)."""
    cut = set(subtree(model, i)) - {i}
    keep = [k for k in range(model.N) if k not in cut]
    idx = {k: n for n, k in enumerate(keep)}
    sub = Model([model.bodies[k] for k in keep], [model.joints[k] for k in keep],
                [idx[model.parents[k]] if model.parents[k] >= 0 else -1 for k in keep], model.gravity)
    return sub, keep


def dense_mobility(model: Model, q, qd, tau, f_ext, i: int, *, use_kkt: bool = False):
    """Reference ``(Lambda_i^-1, b_i)`` from the tree with body ``i``'s descendants cut off (thesis 7.28, 9.45):
    Pinocchio where it models the joints, else (or ``use_kkt``) the KKT solve."""
    sub, keep = without_descendants(model, i)
    cols = np.concatenate([np.arange(model.nq)[model.q_slice(k)] for k in keep])
    qs, qds, taus = (np.asarray(x)[cols] for x in (q, qd, tau))
    f_sub = None if f_ext is None else np.asarray(f_ext)[keep]
    b, Lam = _wrench_response(sub, qs, qds, taus, f_sub, keep.index(i), use_kkt)
    return 0.5 * (Lam + Lam.T), b


def random_state(model: Model, rng, *, loads: bool = True):
    q = rng.uniform(-np.pi, np.pi, model.nq)
    qd = rng.normal(size=model.nq)
    tau = rng.normal(size=model.nq)
    f_ext = rng.normal(size=(model.N, 3)) if loads else None
    return q, qd, tau, f_ext


def rtol_for(model: Model, q) -> float:
    """Relative tolerance scaled by the conditioning of the problem."""
    return max(1e-12, 100 * EPS * mass_matrix_cond(model, q))


# ---------------------------------------------------------------------------
# The references themselves, on hand-derived cases
# ---------------------------------------------------------------------------
def test_lone_free_body_articulated_inertia_is_its_inertia():
    m = Model([Body(2.0, (0.3, -0.2), 0.4)], [Joint("revolute", (1.0, 0.5, 0.3))], [-1], gravity=(0, 0))
    A, d = dense_articulated(m, [0.7], [0.0], [0.0], None, 0)
    x, y, th = kinematics(m, [0.7]).pose[0]
    c, s = np.cos(th), np.sin(th)
    com = np.array([x + c * 0.3 + s * 0.2, y + s * 0.3 - c * 0.2])
    np.testing.assert_allclose(A, inertia_matrix(2.0, com, 0.4), atol=1e-12)
    np.testing.assert_allclose(d, 0.0, atol=1e-12)


def test_pinned_body_mobility_is_rank_one_hand_form():
    # unit point mass at (1, 0) on a pin at the origin, J = 0.5: Lambda^-1 = s s^T / (J + m)
    m = Model([Body(1.0, (1.0, 0.0), 0.5)], [Joint("revolute")], [-1], gravity=(0, 0))
    Lam, b = dense_mobility(m, [0.0], [0.0], [0.0], None, 0)
    s = np.array([0.0, 0.0, 1.0])
    np.testing.assert_allclose(Lam, np.outer(s, s) / 1.5, atol=1e-14)
    np.testing.assert_allclose(b, 0.0, atol=1e-14)


def test_two_body_articulated_reference_matches_thesis_7_20():
    # thesis 7.20 checked by hand at phi = 90 degrees: m_x = m (L^2 + 8 rho^2) / (L^2 + 4 rho^2)
    mass, L, rho = 1.5, 2.0, 0.4
    bodies = [Body(mass, (L / 2, 0.0), mass * rho**2)] * 2
    model = Model(bodies, [Joint("revolute"), Joint("revolute", (L, 0.0, 0.0))], [-1, 0], gravity=(0, 0))
    A, _ = dense_articulated(model, [0.0, np.pi / 2], [0.0, 0.0], [0.0, 0.0], None, 0)
    assert A[0, 0] == pytest.approx(mass * (L**2 + 8 * rho**2) / (L**2 + 4 * rho**2), rel=1e-12)


def test_subtree_of_a_tree():
    m = Model([Body(1.0)] * 5, [Joint("revolute")] * 5, [-1, 0, 0, 1, -1])
    assert subtree(m, 0) == [0, 1, 2, 3]
    assert subtree(m, 1) == [1, 3]
    assert subtree(m, 4) == [4]
    assert without_descendants(m, 1)[1] == [0, 1, 2, 4]
    assert without_descendants(m, 1)[0].parents == (-1, 0, 0, -1)


def test_random_model_helper_is_deterministic():
    a, b = random_model(4, seed=3), random_model(4, seed=3)
    assert a == b


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("tree", [False, True])
def test_kkt_and_pinocchio_agree(seed, tree):
    # two independent references (maximal coordinates + multipliers; Pinocchio's aba) on the same states
    model = random_model(6, seed=seed, tree=tree)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    ref = pinocchio_qdd(model, q, qd, tau, f_ext)
    np.testing.assert_allclose(kkt(model, q, qd, tau, f_ext)["qdd"], ref,
                               rtol=0, atol=rtol_for(model, q) * (1 + np.abs(ref).max()))
    assert not np.allclose(pinocchio_qdd(model, q, qd, tau), ref)     # the loads are felt


def test_newton_euler_forces_of_a_hanging_pendulum():
    # unit point mass at (1, 0) on a pin at the origin, released at rest: a = [0, 0, -g] (q̈ = -g), and the pin
    # carries nothing in free fall (f = I a + p = 0)
    m = Model([Body(1.0, (1.0, 0.0), 0.0)], [Joint("revolute")], [-1])
    a = kkt(m, [0.0], [0.0], [0.0])["a"]
    np.testing.assert_allclose(a, [[0.0, 0.0, -9.81]], atol=1e-12)
    np.testing.assert_allclose(newton_euler_forces(m, [0.0], [0.0], a), 0.0, atol=1e-12)


@pytest.mark.parametrize("seed", range(3))
def test_articulated_and_mobility_references_agree_kkt_and_pinocchio(seed):
    # the free-floating subtree on a plane joint (KKT) and on the placeholder PPR base (Pinocchio)
    model = random_model(5, seed=seed, tree=seed == 1)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    for i in range(model.N):
        A_p, d_p = dense_articulated(model, q, qd, tau, f_ext, i)
        A_k, d_k = dense_articulated(model, q, qd, tau, f_ext, i, use_kkt=True)
        np.testing.assert_allclose(A_p, A_k, atol=1e-10 * np.abs(A_k).max())
        np.testing.assert_allclose(d_p, d_k, atol=1e-9 * (1 + np.abs(d_k).max()))
        L_p, b_p = dense_mobility(model, q, qd, tau, f_ext, i)
        L_k, b_k = dense_mobility(model, q, qd, tau, f_ext, i, use_kkt=True)
        np.testing.assert_allclose(L_p, L_k, atol=1e-10 * np.abs(L_k).max())
        np.testing.assert_allclose(b_p, b_k, atol=1e-9 * (1 + np.abs(b_k).max()))


def test_mobility_matrix_of_a_pinned_point_mass_by_hand():
    # unit point mass at (1, 0) on a pin at the origin, J = 0.5: Φ = s sᵀ / (J + m d²), s = [0, 0, 1]
    m = Model([Body(1.0, (1.0, 0.0), 0.5)], [Joint("revolute")], [-1])
    np.testing.assert_allclose(mobility_matrix(m, [0.0]), np.diag([0.0, 0.0, 1 / 1.5]), atol=1e-14)
