"""Every pin and bearing force of a closed loop (thesis 9.61) against independent references.

* the slider-crank of 9.6: per-body Newton–Euler written by hand in maximal coordinates
  (centre of mass and angle of each body, plain trigonometry in ``_slider_crank_reference``):
  the computed reactions, gravity and the drive must give ``m c̈`` and ``I_z α`` of every body,
  with ``c̈`` and ``α`` from the reference's own multiplier solve (nothing shared with planargeo);
* random trees with loops: each joint's wrench against the joint's Lagrange multipliers in
  :func:`constrained_dynamics_lagrange` (maximal coordinates, dense KKT solve);
* open chains: against Pinocchio's joint forces ``data.f`` after ``pin.rnea``.
"""
import numpy as np
import pytest

import _slider_crank_reference as ref
from planargeo.algorithms.loops import Reaction, constrained_dynamics_lagrange, joint_wrenches, loop_solve
from planargeo.errors import InputError, ShapeError, SingularConfigurationError
from planargeo.mechanics.model import chain_model, random_model
from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_solve
from test_loops import random_loop

G = 9.81
IZ = (0.1464 * ref.M[0] * ref.R ** 2, 0.0866 * ref.M[1] * ref.L ** 2, 0.666 * ref.M[2] * ref.T ** 2)


def _com_motion(psi, psidot, drive):
    """Centre-of-mass positions, accelerations and angular accelerations of the three bodies, by hand."""
    r = ref.reference(psi, psidot, drive=drive)
    q, qd, qdd = r["q"], r["qd"], r["qdd"]
    segs = ref._segments(ref.R, ref.L, ref.T)
    c, cdd = [], []
    for key in ("c1", "c2", "c3"):
        Jc = ref.complex_step_jacobian(lambda x: ref._point(segs[key], x), q)
        c.append(ref._point(segs[key], q))
        cdd.append(Jc @ qdd + ref._point_bias(segs[key], q, qd))
    return np.array(c), np.array(cdd), np.cumsum(qdd), r


def _moment_about(w, c):
    """Moment of the wrench ``w = [fx, fy, τ_o]`` (at the origin) about the point ``c``."""
    return w[2] - (c[0] * w[1] - c[1] * w[0])


@pytest.mark.parametrize("drive", ["free", "constant-speed"])
@pytest.mark.parametrize("psi,psidot", [(0.4, 20.0), (2.1, -7.5), (-1.2, 3.0), (np.pi / 2 + 0.05, 12.0)])
def test_slider_crank_newton_euler_per_body(psi, psidot, drive):
    """Σ forces = m c̈ and Σ moments about the centre of mass = I_z α on each body, with the computed reactions."""
    model = slider_crank_model()
    _q, _qd, sol, _h = slider_crank_solve(model, psi, psidot, ref.R, ref.L, ref.T, drive)
    c, cdd, alpha, r = _com_motion(psi, psidot, drive)
    f = sol.f.reshape(3, 3)
    F = sol.F.reshape(-1, 3)
    on_body = [[f[0], -f[1]], [f[1], -f[2]], [f[2], -F[0]]]       # joint i+1 drawn by the child; -F on body a
    scale = np.abs(f).max()
    for i in range(3):
        force = sum(w[:2] for w in on_body[i]) + ref.M[i] * np.array([0.0, -G])
        moment = sum(_moment_about(w, c[i]) for w in on_body[i])
        np.testing.assert_allclose(force, ref.M[i] * cdd[i], rtol=0, atol=1e-11 * scale)
        assert abs(moment - IZ[i] * alpha[i]) < 1e-11 * scale * ref.L
    # the free pins carry no moment about themselves; the driven crank's pivot carries the drive torque
    moments = {x.symbol: x.moment for x in sol.reactions}
    assert abs(moments["f_2"]) < 1e-11 * scale and abs(moments["f_3"]) < 1e-11 * scale
    assert abs(moments["f_1"] - r["tau_drive"][0]) < 1e-10 * scale
    np.testing.assert_allclose(sol.Q, sol.tau_drive, atol=1e-10 * scale)


def test_slider_crank_reactions_named_and_placed():
    """One reaction per pin (f_1 crank pivot, f_2 crank pin, f_3 wrist pin) and one for the slider bearing F_1."""
    model = slider_crank_model()
    q, _qd, sol, h = slider_crank_solve(model, 0.4, 20.0, ref.R, ref.L, ref.T)
    assert [x.symbol for x in sol.reactions] == ["f_1", "f_2", "f_3", "F_1"]
    assert [x.kind for x in sol.reactions] == ["revolute"] * 3 + ["slider"]
    assert isinstance(sol.reaction("theta"), Reaction) and sol.reaction("F_1").name == "piston slider"
    np.testing.assert_allclose(sol.reaction("f_2").point, ref.R * np.array([np.cos(0.4), np.sin(0.4)]), atol=1e-14)
    np.testing.assert_allclose(sol.reaction("F_1").point, [0.0, h], atol=1e-12)
    # the bearing force acts on the piston with -F (9.61) and is horizontal: the slide is vertical
    np.testing.assert_allclose(sol.reaction("F_1").wrench, -sol.F, atol=0)
    assert abs(sol.reaction("F_1").wrench[1]) < 1e-12 * sol.reaction("F_1").force
    with pytest.raises(InputError, match="name must be"):
        sol.reaction("nowhere")


def _joint_rows(kind):
    return {"revolute": 2, "prismatic": 2, "revolute_prismatic": 1, "twin_prismatic": 1, "fixed": 3,
            "plane": 0}[kind]


@pytest.mark.parametrize("seed", range(12))
def test_tree_joint_wrenches_match_lagrange_multipliers(seed):
    """Random trees with 1-2 loops: f_i = the joint's constraint force Φ_iᵀ λ_i on body i + its torque s (sᵀs)⁻¹ τ."""
    m, cs, q, qd, tau, fe, Jc = random_loop(seed)
    try:
        sol = loop_solve(m, q, qd, tau, fe, cs)
    except SingularConfigurationError:
        pytest.skip("redundant closure (tested in test_loops)")
    r = constrained_dynamics_lagrange(m, q, qd, tau, fe, cs)
    Phi, lam = r["Phi"], r["lambda"]
    com = sol.data.com
    row = 0
    scale = max(1.0, np.abs(sol.f).max())
    for i, jt in enumerate(m.joints):
        k = _joint_rows(jt.kind)
        gen = Phi[row:row + k].T @ lam[row:row + k]
        row += k
        fx, fy, mc = gen[3 * i:3 * i + 3]
        w = np.array([fx, fy, mc + com[i, 0] * fy - com[i, 1] * fx])
        si = sol.data.s(i)
        if si.shape[1]:
            w = w + si @ np.linalg.solve(si.T @ si, tau[m.q_slice(i)])
        tol = 1e-9 * scale * max(1.0, np.abs(com).max())
        np.testing.assert_allclose(sol.f[3 * i:3 * i + 3], w, rtol=0, atol=tol, err_msg=f"joint {i}")


@pytest.mark.parametrize("seed", range(6))
def test_open_chain_joint_wrenches_match_pinocchio(seed):
    """An open chain (no contacts): f_i against pin.rnea's data.f (transmitted from the parent through joint i)."""
    pin = pytest.importorskip("pinocchio")
    from bench import to_pinocchio

    m = random_model(5, seed=seed, tree=bool(seed % 2))
    rng = np.random.default_rng(seed)
    q, qd, tau = rng.normal(size=(3, m.nq))
    sol = loop_solve(m, q, qd, tau, contacts=[])
    pm = to_pinocchio(m)
    pd = pm.createData()
    pin.rnea(pm, pd, q, qd, sol.qdd)
    pin.forwardKinematics(pm, pd, q, qd, sol.qdd)
    scale = max(1.0, np.abs(sol.f).max())
    for i in range(m.N):
        fi, oMi = pd.f[i + 1], pd.oMi[i + 1]
        F = oMi.rotation @ fi.linear
        p = oMi.translation
        tz = (oMi.rotation @ fi.angular)[2] + p[0] * F[1] - p[1] * F[0]
        np.testing.assert_allclose(sol.f[3 * i:3 * i + 3], [F[0], F[1], tz], rtol=0, atol=1e-10 * scale,
                                   err_msg=f"joint {i}")
    np.testing.assert_allclose(sol.Q, tau, atol=1e-10 * scale)
    np.testing.assert_allclose(sol.f, sol.tree.f, atol=1e-10 * scale)      # 9.61 with F = 0 is 9.41


def test_mu_is_the_pin_force_of_free_revolute_joints():
    """μ_i = U_iᵀ f_i (6.61b): for an unactuated revolute joint, the pin force along x and y."""
    m = chain_model(3)
    sol = loop_solve(m, [0.3, -0.4, 0.2], [1.0, 0.5, -0.2], [0.0] * 3, contacts=[])
    np.testing.assert_allclose(sol.mu.reshape(3, 2), sol.f.reshape(3, 3)[:, :2], atol=1e-12)


def test_joint_wrenches_validates_shapes():
    with pytest.raises(ShapeError, match="I, a and p"):
        joint_wrenches([-1, 0], np.eye(3), np.zeros(3), np.zeros(3))
    with pytest.raises(ShapeError, match="GtF"):
        joint_wrenches([-1], np.eye(3), np.zeros(3), np.zeros(3), np.zeros(6))
