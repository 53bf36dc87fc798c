"""The 2-dof twin prismatic joint (thesis 4.8.4, 4.79) as a model joint kind.

References from outside the algorithms: hand geometry of the joint frame,
Newton's law for a body that cannot turn, Lagrange's equations of a pendulum
hanging from a free carriage (derived in the test's docstring), and for
chains, trees and loops the maximal-coordinate Lagrange multipliers (the KKT solve).
"""
import numpy as np
import pytest

from planargeo.algorithms.aba import forward_dynamics
from planargeo.algorithms.chain_splitting import forward_dynamics_mobility_split
from planargeo.algorithms.crba import forward_dynamics_crba, mass_matrix
from planargeo.algorithms.loops import constrained_dynamics_lagrange, loop_solve
from planargeo.algorithms.projective import forward_dynamics_projective, projective_workspace
from planargeo.algorithms.rnea import inverse_dynamics
from planargeo.algorithms.stacked import forward_dynamics_stacked
from planargeo.mechanics.contacts import Contact, stacked_contact_spaces, contact_matrix, world_point
from planargeo.algorithms.stacked import blocks
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import JOINT_DOFS, Body, Joint, Model, random_model

G = 9.81
KINDS = ("revolute", "prismatic", "twin_prismatic", "twin_prismatic")   # twin prismatic drawn half the time
METHODS = {
    "aba": forward_dynamics,
    "projective": forward_dynamics_projective,
    "stacked": forward_dynamics_stacked,
    "crba": forward_dynamics_crba,
}


def _all_methods(model):
    out = dict(METHODS)
    if model.is_chain:
        out["mobility_split"] = forward_dynamics_mobility_split
    return out


def test_joint_kind_and_kinematics_by_hand():
    """Two dofs; the body slides by q0 along the joint frame's x and q1 along its y, never turns,
    and its motion space is the two ideal points [e, 0], [e⊥, 0] (4.79 turned by the frame angle)."""
    assert JOINT_DOFS["twin_prismatic"] == 2 and Joint("twin_prismatic").dofs == 2
    phi = 0.7
    c, s = np.cos(phi), np.sin(phi)
    m = Model([Body(1.0, (0.3, -0.2), 0.1)], [Joint("twin_prismatic", (1.0, 2.0, phi))], [-1])
    q, qd = np.array([0.5, -1.5]), np.array([2.0, 3.0])
    for state in (q, np.stack([q, q])):                  # scalar and batched kinematics
        d = kinematics(m, state, np.broadcast_to(qd, state.shape))
        pose = np.reshape(d.pose, (-1, 3))[0]
        assert np.allclose(pose, [1.0 + 0.5 * c + 1.5 * s, 2.0 + 0.5 * s - 1.5 * c, phi], atol=1e-15)
        S = np.reshape(d.S, (-1, 3, 2))[0]
        assert np.allclose(S, [[c, -s], [s, c], [0.0, 0.0]], atol=1e-15)
        v = np.reshape(d.v, (-1, 3))[0]
        assert np.allclose(v, [2.0 * c - 3.0 * s, 2.0 * s + 3.0 * c, 0.0], atol=1e-15)
        assert np.allclose(d.kappa, 0.0)                 # translations on the ground: no bias acceleration
    # with phi = 0 the motion space is 4.79 exactly
    d0 = kinematics(Model([Body(1.0)], [Joint("twin_prismatic")], [-1]), [0.3, 0.4])
    assert d0.S.tolist() == [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]


@pytest.mark.parametrize("phi", [0.0, 0.7, -2.5])
def test_single_body_newton(phi):
    """A body that cannot turn: m q̈ = Rᵀ(φ)(F + m g) + τ, wherever F acts (here off the centre of mass);
    the joint carries only the couple μ = -(P - c) × F (reaction space: the line at infinity)."""
    mass, com = 2.5, (0.3, -0.2)
    g = (1.2, -G)
    m = Model([Body(mass, com, 0.4)], [Joint("twin_prismatic", (1.0, 2.0, phi))], [-1], gravity=g)
    q, qd, tau = np.array([0.5, -1.5]), np.array([2.0, 3.0]), np.array([0.7, -1.1])
    d = kinematics(m, q)
    cx, cy = d.com[0]
    F, P = np.array([3.0, -4.0]), np.array([cx + 0.6, cy - 0.9])          # force at a point off the com
    fe = np.array([[F[0], F[1], P[0] * F[1] - P[1] * F[0]]])
    c, s = np.cos(phi), np.sin(phi)
    Rt = np.array([[c, s], [-s, c]])
    expect = (Rt @ (F + mass * np.array(g)) + tau) / mass
    for name, fd in _all_methods(m).items():
        assert np.allclose(fd(m, q, qd, tau, fe), expect, rtol=1e-13, atol=1e-13), name
    # batched ABA, two states
    assert np.allclose(forward_dynamics(m, np.stack([q, q]), qd, tau, fe), expect, rtol=1e-13)
    # inverse dynamics returns the joint forces
    assert np.allclose(inverse_dynamics(m, q, qd, expect, fe), tau, atol=1e-12)
    # reaction: the unit couple (the line at infinity), component -(P - c) × F
    ws = projective_workspace(m, q, qd, tau, fe)
    assert np.allclose(ws.R[0].ravel(), [0.0, 0.0, 1.0])
    r = P - [cx, cy]
    assert ws.mu[0][0] == pytest.approx(-(r[0] * F[1] - r[1] * F[0]), rel=1e-12)


def _carriage_pendulum(M=3.0, J0=0.7, m=1.5, l=0.8, J=0.05, gravity=(0.0, -G)):
    bodies = [Body(M, (0.0, 0.0), J0, name="carriage"), Body(m, (l, 0.0), J, name="pendulum")]
    joints = [Joint("twin_prismatic", (0.0, 0.0, 0.0)), Joint("revolute", (0.0, 0.0, 0.0))]
    return Model(bodies, joints, [-1, 0], gravity)


def _carriage_pendulum_closed_form(M, m, l, J, th, thd, tau, g=G):
    """Lagrange's equations of a pendulum (mass m, com at l from the pivot, J about the com) hanging
    from a carriage of mass M free to translate in x and y, q = (x, y, θ), gravity -g ŷ:

        T = ½(M+m)(ẋ²+ẏ²) + m l θ̇ (cθ ẏ - sθ ẋ) + ½(J + m l²) θ̇²,   V = (M+m) g y + m g l sθ

        (M+m) ẍ - m l (sθ θ̈ + cθ θ̇²) = τx
        (M+m) ÿ + m l (cθ θ̈ - sθ θ̇²) = τy - (M+m) g
        -m l sθ ẍ + m l cθ ÿ + (J + m l²) θ̈ = τθ - m g l cθ     (the θ̇ ẋ, θ̇ ẏ terms cancel)

    Eliminating ẍ, ÿ: gravity and θ̇² drop out of θ̈ (the whole system falls freely), with
    μ = m M / (M + m):  (J + μ l²) θ̈ = τθ + m l (sθ τx - cθ τy) / (M + m).
    The carriage's own rotational inertia does not appear (it cannot turn).
    """
    tx, ty, tt = tau
    sn, cs = np.sin(th), np.cos(th)
    mu = m * M / (M + m)
    thdd = (tt + m * l * (sn * tx - cs * ty) / (M + m)) / (J + mu * l * l)
    xdd = (tx + m * l * (sn * thdd + cs * thd ** 2)) / (M + m)
    ydd = (ty - m * l * (cs * thdd - sn * thd ** 2)) / (M + m) - g
    return np.array([xdd, ydd, thdd])


@pytest.mark.parametrize("th, thd, tau", [
    (-np.pi / 2, 0.0, (0.0, 0.0, 0.0)),            # hanging at rest: free fall, no swing
    (-1.2, 2.0, (0.0, 0.0, 0.0)),
    (0.4, -3.0, (1.5, -2.0, 0.8)),
    (2.9, 1.0, (0.0, (3.0 + 1.5) * G, 0.0)),      # carriage held up by its vertical joint force
])
def test_pendulum_on_twin_prismatic_carriage(th, thd, tau):
    M, J0, m, l, J = 3.0, 0.7, 1.5, 0.8, 0.05
    model = _carriage_pendulum(M, J0, m, l, J)
    q, qd = np.array([0.3, -0.6, th]), np.array([0.9, -0.4, thd])
    expect = _carriage_pendulum_closed_form(M, m, l, J, th, thd, tau)
    scale = max(1.0, np.abs(expect).max())
    for name, fd in _all_methods(model).items():
        assert np.allclose(fd(model, q, qd, np.array(tau), None), expect, rtol=1e-12, atol=1e-12 * scale), name
    # the carriage's rotational inertia plays no part
    other = _carriage_pendulum(M, 50.0, m, l, J)
    assert np.allclose(forward_dynamics(other, q, qd, np.array(tau)), expect, rtol=1e-12, atol=1e-12 * scale)
    # the hand mass matrix (from T above) against CRBA's
    sn, cs = np.sin(th), np.cos(th)
    H = np.array([[M + m, 0.0, -m * l * sn], [0.0, M + m, m * l * cs], [-m * l * sn, m * l * cs, J + m * l * l]])
    assert np.allclose(mass_matrix(model, q), H, rtol=1e-14, atol=1e-14)


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("tree", [False, True])
def test_random_chains_and_trees_match_the_kkt_solve(seed, tree):
    """Random chains/trees mixing revolute, prismatic and twin prismatic joints: every method (the dense
    CRBA solve included) against the maximal-coordinate KKT solve, single states and a batch, tolerance
    scaled by cond(H)."""
    model = random_model(8, seed=seed, kinds=KINDS, tree=tree)
    assert sum(j.kind == "twin_prismatic" for j in model.joints) >= 1
    rng = np.random.default_rng(seed)
    q, qd, tau = rng.normal(size=(3, 2, model.nq))
    fe = rng.normal(size=(2, model.N, 3))
    ref = np.array([constrained_dynamics_lagrange(model, q[k], qd[k], tau[k], fe[k])["qdd"] for k in range(2)])
    H = mass_matrix(model, q)
    tol = 1e-14 * max(np.linalg.cond(H).max(), 1.0) + 1e-12
    scale = max(np.abs(ref).max(), 1.0)
    assert np.abs(forward_dynamics(model, q, qd, tau, fe) - ref).max() <= tol * scale       # batch
    for k in range(2):
        for name, fd in _all_methods(model).items():
            got = fd(model, q[k], qd[k], tau[k], fe[k])
            assert np.abs(got - ref[k]).max() <= tol * scale, (name, k)
        assert np.abs(inverse_dynamics(model, q[k], qd[k], ref[k], fe[k]) - tau[k]).max() <= tol * scale


@pytest.mark.parametrize("th, thd, tau", [(-1.2, 2.0, (0.0, 0.0, 0.0)), (0.4, -3.0, (1.5, -2.0, 0.8))])
def test_pinned_carriage_is_a_simple_pendulum(th, thd, tau):
    """The carriage pinned to the ground at a point of it: the pendulum swings about a fixed pivot,
    (J + m l²) θ̈ = τθ - m g l cθ, and the pin carries the rest of Newton's law of the whole:
    -F (on the carriage) = m a_c - (M+m) g - τ_xy with a_c = l(-sθ θ̈ - cθ θ̇², cθ θ̈ - sθ θ̇²), through the pin."""
    M, m, l, J = 3.0, 1.5, 0.8, 0.05
    model = _carriage_pendulum(M, 0.7, m, l, J)
    q, qd = np.array([0.3, -0.6, th]), np.array([0.0, 0.0, thd])
    P = np.array([0.3 + 0.5, -0.6 + 0.2])                         # carriage point (0.5, 0.2) in the world
    pin = Contact("pin", 0, -1, (0.5, 0.2), tuple(P))
    sol = loop_solve(model, q, qd, np.array(tau), contacts=[pin])
    sn, cs = np.sin(th), np.cos(th)
    thdd = (tau[2] - m * G * l * cs) / (J + m * l * l)
    assert np.allclose(sol.qdd, [0.0, 0.0, thdd], atol=1e-12)
    ac = l * np.array([-sn * thdd - cs * thd ** 2, cs * thdd - sn * thd ** 2])
    force_on_carriage = m * ac - (M + m) * np.array([0.0, -G]) - np.array(tau[:2])
    F = -sol.F.reshape(3)
    assert np.allclose(F[:2], force_on_carriage, atol=1e-11)
    assert F[2] == pytest.approx(P[0] * F[1] - P[1] * F[0], abs=1e-11)     # a force through the pin
    ref = constrained_dynamics_lagrange(model, q, qd, np.array(tau), contacts=[pin])
    assert np.allclose(ref["qdd"], sol.qdd, atol=1e-11) and np.allclose(ref["F"].ravel(), sol.F, atol=1e-10)


@pytest.mark.parametrize("seed", [0, 1, 2, 3, 5, 8])
def test_random_loops_match_lagrange(seed):
    """Random trees with twin prismatic joints, the last body pinned to the ground (regular closures
    only: seeds whose closure Jacobian has full row rank), against the Lagrange multipliers."""
    rng = np.random.default_rng(seed)
    model = random_model(7, seed=seed, kinds=KINDS, tree=True)
    q = rng.normal(size=model.nq)
    d = kinematics(model, q)
    r = tuple(rng.normal(size=2))
    cs = [Contact("pin", model.N - 1, -1, r, tuple(world_point(d.pose, model.N - 1, r)))]
    z, B = stacked_contact_spaces(cs, d.pose)
    Jc = B.T @ blocks(contact_matrix(cs, model.N)) @ np.concatenate([d.jacobian(i) for i in range(model.N)], 0)
    sv = np.linalg.svd(Jc, compute_uv=False)
    assert sv[-1] > 1e-3 * sv[0], "seed gives a redundant closure"
    qd = rng.normal(size=model.nq)
    qd = qd - np.linalg.pinv(Jc) @ (Jc @ qd)
    tau, fe = rng.normal(size=model.nq), rng.normal(size=(model.N, 3))
    sol = loop_solve(model, q, qd, tau, fe, cs)
    ref = constrained_dynamics_lagrange(model, q, qd, tau, fe, cs)
    scale = max(1.0, np.abs(ref["a"]).max(), np.abs(ref["F"]).max())
    tol = max(1e-11, 100 * np.finfo(float).eps * np.linalg.cond(mass_matrix(model, q)) * sol.cond)
    assert np.abs(sol.a.reshape(-1, 3) - ref["a"]).max() < tol * scale
    assert np.abs(sol.F.reshape(-1, 3) - ref["F"]).max() < tol * scale
    assert np.abs(sol.qdd - ref["qdd"]).max() < tol * max(1.0, np.abs(ref["qdd"]).max())
