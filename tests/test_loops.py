"""Closed loops and contacts (thesis 9.3-9.5) against Lagrange multipliers in maximal coordinates."""
import numpy as np
import pytest
from hypothesis import given, strategies as st

from planargeo.algorithms.loops import (
    branch_matrix, constrained_dynamics_lagrange, forward_dynamics_loops, loop_solve)
from planargeo.algorithms.stacked import blocks
from planargeo.mechanics.contacts import (
    B_of, Contact, contact_bias, contact_matrix, residual, z_of,
    stacked_contact_spaces, validate_contacts, world_point)
from planargeo.errors import (
    DegenerateGeometryError, InputError, ShapeError, SingularConfigurationError)
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Model, chain_model, random_model
from test_articulated_reference import mass_matrix_cond, pinocchio_qdd

FIG91 = [-1, 0, 1, 2, 0, 4, 5, 5, 0]


def _local(pose_i, P):
    x, y, th = pose_i
    c, s = np.cos(th), np.sin(th)
    d = np.asarray(P) - [x, y]
    return (c * d[0] + s * d[1], -s * d[0] + c * d[1])


def _closure_jacobian(m, cs, d):
    z, B = stacked_contact_spaces(cs, d.pose)
    Jb = np.concatenate([d.jacobian(i) for i in range(m.N)], 0)
    return B.T @ blocks(contact_matrix(cs, m.N)) @ Jb


def random_loop(seed):
    """A random tree or chain with 1-2 contacts closed at the sampled state, consistent velocities."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(3, 10))
    m = random_model(n, seed=seed, tree=bool(rng.integers(2)))
    q = rng.normal(size=m.nq)
    d = kinematics(m, q)
    a = n - 1
    r = tuple(rng.normal(size=2))
    P = tuple(world_point(d.pose, a, r))
    th = float(d.pose[a, 2])
    kind = ["pin", "slider", "weld"][int(rng.integers(3))]
    cs = [Contact("pin", a, -1, r, P) if kind == "pin" else
          Contact("slider", a, -1, r, P, direction=tuple(rng.normal(size=2)), angle=th) if kind == "slider" else
          Contact("weld", a, -1, r, P, angle=th)]
    if rng.integers(2):
        i, j = (int(x) for x in sorted(rng.choice(n, 2, replace=False))[::-1])
        ri = tuple(rng.normal(size=2))
        Pi = world_point(d.pose, i, ri)
        if rng.integers(2):
            cs.append(Contact("pin", i, j, ri, _local(d.pose[j], Pi)))
        else:
            cs.append(Contact("slider", i, j, ri, _local(d.pose[j], Pi), direction=tuple(rng.normal(size=2)),
                              angle=float(d.pose[i, 2] - d.pose[j, 2])))
    Jc = _closure_jacobian(m, cs, d)
    qd = rng.normal(size=m.nq)
    qd = qd - np.linalg.pinv(Jc) @ (Jc @ qd)
    return m, cs, q, qd, rng.normal(size=m.nq), rng.normal(size=(n, 3)), Jc


# --------------------------------------------------------------------------- contact matrices
def test_contact_and_branch_matrix_fig_9_2():
    cs = [Contact("pin", 3, 6), Contact("pin", 7, 8)]
    G = contact_matrix(cs, 9)
    assert np.array_equal(G, [[0, 0, 0, 1, 0, 0, -1, 0, 0], [0, 0, 0, 0, 0, 0, 0, 1, -1]])   # 9.49
    assert np.array_equal(branch_matrix(G, FIG91),
                          [[0, 1, 1, 1, -1, -1, -1, 0, 0], [0, 0, 0, 0, 1, 1, 0, 1, -1]])  # 9.51


@given(st.sampled_from(["pin", "slider", "weld"]), st.integers(0, 10_000))
def test_motion_and_reaction_spaces_are_dual(kind, seed):
    rng = np.random.default_rng(seed)
    pose = rng.normal(size=(2, 3))
    c = Contact(kind, 1, 0, tuple(rng.normal(size=2)), tuple(rng.normal(size=2)),
                direction=tuple(rng.normal(size=2)))
    z, B = z_of(c, pose), B_of(c, pose)
    assert z.shape == (3, c.dofs) and B.shape == (3, 3 - c.dofs)
    assert np.allclose(z.T @ B, 0, atol=1e-12)                        # 9.60
    assert np.linalg.matrix_rank(np.hstack([z, B])) == 3


@given(st.integers(0, 10_000))
def test_residual_is_position_form_of_reaction_space(seed):
    # d/dt residual = 0 for every motion in z: move body a along z by a small step
    rng = np.random.default_rng(seed)
    pose = rng.normal(size=(1, 3))
    for kind in ("pin", "slider"):
        r = tuple(rng.normal(size=2))
        P = tuple(world_point(pose, 0, r))
        c = Contact(kind, 0, -1, r, P, direction=tuple(rng.normal(size=2)), angle=float(pose[0, 2]))
        assert np.allclose(residual(c, pose), 0, atol=1e-12)
        z = z_of(c, pose)[:, 0]
        h = 1e-6
        # a twist [vx, vy, w] at the origin moves the body frame origin (x, y) with v + w × (x, y)
        x, y, th = pose[0]
        moved = pose + h * np.array([[z[0] - z[2] * y, z[1] + z[2] * x, z[2]]])
        assert np.abs(residual(c, moved)).max() < 1e-10


def test_contact_validation_errors():
    with pytest.raises(InputError, match="kind must be one of"):
        Contact("glue", 0)
    with pytest.raises(InputError, match="a must be a body index >= 0"):
        Contact("pin", -1)
    with pytest.raises(InputError, match="a and b must be different bodies"):
        Contact("pin", 2, 2)
    with pytest.raises(InputError, match="b must be a body index >= 0 or -1"):
        Contact("pin", 0, -3)
    with pytest.raises(DegenerateGeometryError, match="direction must be non-zero"):
        Contact("slider", 0, direction=(0.0, 0.0))
    with pytest.raises(ShapeError, match="point_a must have shape"):
        Contact("pin", 0, point_a=(1.0, 2.0, 3.0))
    with pytest.raises(InputError, match=r"contacts\[1\].b must be -1 or a body index in 0..2"):
        validate_contacts([Contact("pin", 0), Contact("pin", 1, 5)], 3)
    with pytest.raises(InputError, match=r"contacts\[0\] must be a Contact"):
        validate_contacts(["pin"], 3)
    with pytest.raises(ShapeError, match="pose must have shape"):
        z_of(Contact("pin", 0), np.zeros(3))


def test_contact_bias_symmetric():
    # ν = v_a × (v_a - v_b) = v_b × (v_a - v_b): either body may carry z
    from planargeo.screws.twists import crm
    rng = np.random.default_rng(0)
    va, vb = rng.normal(size=3), rng.normal(size=3)
    assert np.allclose(contact_bias(va, vb), crm(vb) @ (va - vb))
    assert np.allclose(contact_bias(va, va), 0)


# --------------------------------------------------------------------------- dynamics vs reference
def test_reference_reduces_to_pinocchio_without_contacts():
    rng = np.random.default_rng(4)
    for seed in range(5):
        m = random_model(6, seed=seed, tree=True)
        q, qd, tau, fe = (rng.normal(size=m.nq), rng.normal(size=m.nq), rng.normal(size=m.nq),
                          rng.normal(size=(6, 3)))
        ref = constrained_dynamics_lagrange(m, q, qd, tau, fe)
        assert np.allclose(ref["qdd"], pinocchio_qdd(m, q, qd, tau, fe), atol=1e-9)


def test_parallelogram_closed_form():
    # three uniform unit links, tip pinned at (1, 0): φ̈ = -6/5 g cos φ (energy in the crank angle)
    pin = Contact("pin", 2, -1, (1.0, 0.0), (1.0, 0.0))
    for phi, w in [(1.2, 1.0), (0.3, -2.0)]:
        q, qd = [phi, -phi, phi - np.pi], [w, -w, w]
        qdd = forward_dynamics_loops(chain_model(3), q, qd, [0.0] * 3, contacts=[pin])
        assert qdd[0] == pytest.approx(-1.2 * 9.81 * np.cos(phi), abs=1e-10)
        ref = constrained_dynamics_lagrange(chain_model(3), q, qd, [0.0] * 3, contacts=[pin])
        assert ref["qdd"][0] == pytest.approx(-1.2 * 9.81 * np.cos(phi), abs=1e-10)


@given(st.integers(0, 100_000))
def test_loops_match_lagrange_random(seed):
    m, cs, q, qd, tau, fe, Jc = random_loop(seed)
    try:
        sol = loop_solve(m, q, qd, tau, fe, cs)
    except SingularConfigurationError as e:
        # only (numerically) redundant closures are refused
        assert e.cond > 1e10
        sv = np.linalg.svd(Jc, compute_uv=False)
        assert Jc.shape[0] > Jc.shape[1] or sv[-1] < 1e-3 * sv[0]
        return
    ref = constrained_dynamics_lagrange(m, q, qd, tau, fe, cs)
    scale = max(1.0, np.abs(ref["a"]).max(), np.abs(ref["F"]).max())
    tol = 1e-14 * mass_matrix_cond(m, q) * sol.cond * scale + 1e-11 * scale
    assert np.abs(sol.a.reshape(-1, 3) - ref["a"]).max() < tol
    assert np.abs(sol.F.reshape(-1, 3) - ref["F"]).max() < tol
    assert np.abs(sol.qdd - ref["qdd"]).max() < tol * max(1.0, np.abs(ref["qdd"]).max())
    # the closure holds at acceleration level: B^T (G a - ν) = 0 (9.55, 9.60)
    assert np.abs(sol.B.T @ (sol.G3 @ sol.a - sol.nu)).max() < tol
    # contact rates (9.58) reproduce the relative twists for consistent velocities (9.54)
    assert np.allclose(sol.z @ sol.theta_dot, sol.G3 @ sol.data.v.reshape(-1), atol=1e-9)


def large_loop(n, seed, ncontacts, tree=True):
    """``n`` bodies (random tree or chain, revolute and prismatic joints) closed by ``ncontacts``
    contacts at the sampled state: the tip body to the ground, then body-body contacts between
    random pairs, cycling pin / slider / weld; consistent velocities, random torques and loads."""
    rng = np.random.default_rng(seed)
    m = random_model(n, seed=seed, tree=tree)
    q = rng.normal(size=m.nq)
    d = kinematics(m, q)
    cs = []
    for k in range(ncontacts):
        kind = ["pin", "slider", "weld"][k % 3]
        i, j = (n - 1, -1) if k == 0 else (int(x) for x in sorted(rng.choice(n, 2, replace=False))[::-1])
        ri = tuple(rng.normal(size=2))
        Pi = world_point(d.pose, i, ri)
        Pj = tuple(Pi) if j < 0 else _local(d.pose[j], Pi)
        rel = float(d.pose[i, 2] - (d.pose[j, 2] if j >= 0 else 0.0))
        if kind == "pin":
            cs.append(Contact("pin", i, j, ri, Pj))
        elif kind == "slider":
            cs.append(Contact("slider", i, j, ri, Pj, direction=tuple(rng.normal(size=2)), angle=rel))
        else:
            cs.append(Contact("weld", i, j, ri, Pj, angle=rel))
    Jc = _closure_jacobian(m, cs, d)
    qd = rng.normal(size=m.nq)
    qd = qd - np.linalg.pinv(Jc) @ (Jc @ qd)
    return m, cs, q, qd, rng.normal(size=m.nq), rng.normal(size=(n, 3)), Jc


# (n, contacts, seed, tree): regular closures (other seeds give redundant body-body welds)
LARGE_LOOPS = [(30, 4, 0, True), (30, 4, 1, False), (30, 6, 0, True), (30, 6, 3, False), (60, 6, 2, True),
               (60, 6, 0, False)]


@pytest.mark.parametrize("n, ncontacts, seed, tree", LARGE_LOOPS)
def test_large_closed_loops_match_lagrange(n, ncontacts, seed, tree):
    """30-60 bodies, 4-6 loops (9-14 closure rows): the constrained algorithm of 9.5 against the
    maximal-coordinate Lagrange multipliers; measured errors ~1e-15 relative (each case < 0.1 s)."""
    m, cs, q, qd, tau, fe, Jc = large_loop(n, seed, ncontacts, tree)
    assert np.linalg.matrix_rank(Jc) == Jc.shape[0]                  # independent closures
    sol = loop_solve(m, q, qd, tau, fe, cs)
    ref = constrained_dynamics_lagrange(m, q, qd, tau, fe, cs)
    scale = max(1.0, np.abs(ref["a"]).max(), np.abs(ref["F"]).max())
    rtol = max(1e-11, 100 * np.finfo(float).eps * mass_matrix_cond(m, q) * sol.cond)
    assert np.abs(sol.a.reshape(-1, 3) - ref["a"]).max() < rtol * scale
    assert np.abs(sol.F.reshape(-1, 3) - ref["F"]).max() < rtol * scale
    assert np.abs(sol.qdd - ref["qdd"]).max() < rtol * max(1.0, np.abs(ref["qdd"]).max())
    assert np.abs(sol.B.T @ (sol.G3 @ sol.a - sol.nu)).max() < rtol * scale          # 9.55, 9.60
    # and the joint accelerations keep the closures at acceleration level in joint space
    hstep = 1e-6
    Jp = _closure_jacobian(m, cs, kinematics(m, q + hstep * qd))
    Jm = _closure_jacobian(m, cs, kinematics(m, q - hstep * qd))
    Jdqd = (Jp - Jm) @ qd / (2 * hstep)
    assert np.abs(Jc @ sol.qdd + Jdqd).max() < 1e-6 * max(1.0, np.abs(Jc @ sol.qdd).max())


def test_without_contacts_is_the_tree():
    rng = np.random.default_rng(9)
    m = random_model(5, seed=9, tree=True)
    q, qd, tau = (rng.normal(size=m.nq) for _ in range(3))
    assert np.allclose(forward_dynamics_loops(m, q, qd, tau), pinocchio_qdd(m, q, qd, tau), atol=1e-10)


def test_batched_loops():
    pin = Contact("pin", 2, -1, (1.0, 0.0), (1.0, 0.0))
    phis = np.array([0.4, 0.9])
    q = np.stack([phis, -phis, phis - np.pi], -1)
    qd = np.array([[1.0, -1.0, 1.0]] * 2)
    out = forward_dynamics_loops(chain_model(3, ), q, qd, np.zeros((2, 3)), contacts=[pin])
    assert np.allclose(out[:, 0], -1.2 * 9.81 * np.cos(phis))


# --------------------------------------------------------------------------- the erratum of 9.65-9.73
def _fig92_model():
    """Fig 9.1/9.2 tree of unit links in a symmetric pose where both loops close."""
    from planargeo.scenes.trees import constrained_tree
    res = constrained_tree()
    return res.model, np.array(res.state["q"]), np.array(res.state["qd"])


def test_erratum_block_diagonal_mobility_fails_for_body_body_contacts():
    m, q, qd = _fig92_model()
    tau = np.zeros(m.nq)
    sol = loop_solve(m, q, qd, tau)
    ref = constrained_dynamics_lagrange(m, q, qd, tau)
    assert np.allclose(sol.a.reshape(-1, 3), ref["a"], atol=1e-9)
    # printed: Λ^{-1} = {{Λ_i^{-1}}} block diagonal (chain mobilities 7.37) in 9.70-9.73
    Lam = sol.tree.articulated_mobilities.Lambda_inv
    N = m.N
    Lb = np.zeros((3 * N, 3 * N))
    for i, Li in enumerate(Lam):
        Lb[3 * i:3 * i + 3, 3 * i:3 * i + 3] = Li
    G3, B = sol.G3, sol.B
    K = B.T @ G3 @ Lb @ G3.T @ B
    F = B @ np.linalg.solve(K, B.T @ (G3 @ sol.u - sol.nu))
    a_printed = sol.u - Lb @ G3.T @ F
    assert np.abs(a_printed.reshape(-1, 3) - ref["a"]).max() > 1e-2


def test_slider_crank_tip_contact_block_and_full_agree():
    # with one contact on the tip body to the ground, block (3,3) of the full mobility is Λ_3^{-1} (7.37)
    from planargeo.scenes.slider_crank import slider_crank
    res = slider_crank()
    sol = res.extra["solution"]
    Lam = sol.tree.articulated_mobilities.Lambda_inv
    assert np.allclose(Lam[2], sol.Lambda_inv[6:9, 6:9], atol=1e-10)


# --------------------------------------------------------------------------- drives and singular loops
def test_prescribed_joint_matches_reference():
    pin = Contact("pin", 2, -1, (1.0, 0.0), (1.0, 0.0))
    m = chain_model(3)
    q, qd = [0.8, -0.8, 0.8 - np.pi], [2.0, -2.0, 2.0]
    sol = loop_solve(m, q, qd, [0.0] * 3, contacts=[pin], prescribed={0: 0.5})
    assert sol.qdd[0] == 0.5                       # the prescribed value exactly, not the solve's rounding
    ref = constrained_dynamics_lagrange(m, q, qd, [0.0] * 3, contacts=[pin], prescribed={0: 0.5})
    assert np.allclose(sol.qdd, ref["qdd"], atol=1e-10)
    assert np.allclose(sol.tau_drive, ref["tau_drive"], atol=1e-9)
    # closed form: τ = (5/3) φ̈ + 2 g cos φ
    assert sol.tau_drive[0] == pytest.approx(5 / 3 * 0.5 + 2 * 9.81 * np.cos(0.8), abs=1e-9)


@pytest.mark.parametrize("q0, w, val", [(0.8, 2.0, 0.5), (0.3, -1.0, 0.0), (2.1, 5.0, -3.7), (1.1, 0.7, 1e-3)])
def test_driven_joint_acceleration_is_the_prescribed_value_exactly(q0, w, val):
    """The four-bar driven at joint 0, and the same with a second drive on the open-loop tree: the driven
    coordinates' q̈ are the prescribed floats bit for bit (the solve alone reproduces them only to
    rounding); the rest still matches the Lagrange reference, and the drive torque its closed form."""
    pin = Contact("pin", 2, -1, (1.0, 0.0), (1.0, 0.0))
    m = chain_model(3)
    q, qd = [q0, -q0, q0 - np.pi], [w, -w, w]
    sol = loop_solve(m, q, qd, [0.0] * 3, contacts=[pin], prescribed={0: val})
    assert sol.qdd[0] == val
    ref = constrained_dynamics_lagrange(m, q, qd, [0.0] * 3, contacts=[pin], prescribed={0: val})
    assert np.allclose(sol.qdd, ref["qdd"], atol=1e-10)
    assert sol.tau_drive[0] == pytest.approx(5 / 3 * val + 2 * 9.81 * np.cos(q0), abs=1e-9)
    # two drives on an open tree (no contacts): both exact, the free joint from the reference
    tree = random_model(4, seed=7, tree=True, kinds=("revolute",))
    rng = np.random.default_rng(int(1000 * q0))
    qt, qdt, taut = rng.normal(size=(3, 4))
    drives = {1: val, 3: -2.0 * val + 0.1}
    sol = loop_solve(tree, qt, qdt, taut, contacts=[], prescribed=drives)
    assert sol.qdd[1] == drives[1] and sol.qdd[3] == drives[3]
    ref = constrained_dynamics_lagrange(tree, qt, qdt, taut, contacts=[], prescribed=drives)
    assert np.allclose(sol.qdd, ref["qdd"], atol=1e-9)


def test_prescribed_errors():
    m = chain_model(2)
    with pytest.raises(InputError, match="prescribed keys must be joint indices"):
        loop_solve(m, [0, 0], [0, 0], [0, 0], prescribed={5: 0.0})


def test_redundant_closure_raises_with_cond():
    # a pendulum whose tip is also pinned: two constraints on one coordinate
    pin = Contact("pin", 0, -1, (1.0, 0.0), (0.0, -1.0))
    with pytest.raises(SingularConfigurationError, match="B\\^T G Λ\\^-1 G\\^T B is singular") as e:
        loop_solve(chain_model(1), [-np.pi / 2], [0.0], [0.0], contacts=[pin])
    assert e.value.cond > 1e10


def test_loop_solve_shape_error():
    with pytest.raises(ShapeError, match="loop_solve takes one state"):
        loop_solve(chain_model(1), np.zeros((2, 1)), np.zeros(1), np.zeros(1))


def test_model_contacts_used_by_default():
    pin = Contact("pin", 2, -1, (1.0, 0.0), (1.0, 0.0))
    base = chain_model(3)
    m = Model(base.bodies, base.joints, base.parents, base.gravity, contacts=(pin,))
    q, qd = [1.2, -1.2, 1.2 - np.pi], [1.0, -1.0, 1.0]
    assert forward_dynamics_loops(m, q, qd, [0.0] * 3)[0] == pytest.approx(-1.2 * 9.81 * np.cos(1.2))


# --------------------------------------------------------------------------- contact columns of Λ⁻¹
@pytest.mark.parametrize("n, ncontacts, seed, tree", LARGE_LOOPS[:4])
def test_column_solve_matches_full_mobility_and_lagrange(n, ncontacts, seed, tree):
    """loop_solve's default forms only Λ⁻¹ Gᵀ (tree sweeps); it agrees with the full-Λ⁻¹ transcription
    of 9.65-9.73 and with the maximal-coordinate Lagrange multipliers, and its columns are those of
    the full matrix (built only when sol.Lambda_inv is read)."""
    m, cs, q, qd, tau, fe, Jc = large_loop(n, seed, ncontacts, tree)
    col = loop_solve(m, q, qd, tau, fe, cs)
    assert not hasattr(col.tree, "_mob")                 # the full mobility was never built
    full = loop_solve(m, q, qd, tau, fe, cs, mobility="full")
    rtol = max(1e-11, 100 * np.finfo(float).eps * mass_matrix_cond(m, q) * full.cond)
    scale = max(1.0, np.abs(full.a).max(), np.abs(full.F).max())
    for name in ("a", "F", "xi", "qdd"):
        assert np.abs(getattr(col, name) - getattr(full, name)).max() < rtol * scale, name
    ref = constrained_dynamics_lagrange(m, q, qd, tau, fe, cs)
    assert np.abs(col.a.reshape(-1, 3) - ref["a"]).max() < rtol * scale
    assert np.abs(col.F.reshape(-1, 3) - ref["F"]).max() < rtol * scale
    Lam = col.Lambda_inv                                  # built now, on access
    assert np.allclose(col.Lambda_inv_Gt, Lam @ col.G3.T, atol=1e-12 * np.abs(Lam).max())
    assert np.allclose(col.contact_mobility, col.G3 @ Lam @ col.G3.T, atol=1e-12 * np.abs(Lam).max())


def test_mobility_times_is_the_mobility_on_a_hand_case():
    """Two uniform unit links pinned at the origin, straight along x, at rest, no gravity: a unit couple
    on the tip body gives it the acceleration J₂ H⁻¹ J₂ᵀ e_z (H and J₂ by hand); and mobility_times(X)
    equals the full Φ X for any X."""
    from planargeo.algorithms.stacked import stacked_solve
    m = chain_model(2, gravity=(0.0, 0.0))
    sol = stacked_solve(m, [0.0, 0.0], [0.0, 0.0], [0.0, 0.0])
    # hand mass matrix of two uniform unit links: H = [[5/3 + c, 1/3 + c/2], [1/3 + c/2, 1/3]] with c = cos q2 = 1
    H = np.array([[8 / 3, 5 / 6], [5 / 6, 1 / 3]])
    J2 = np.array([[0.0, 0.0], [0.0, -1.0], [1.0, 1.0]])        # body 2's joint-space Jacobian at the origin
    X = np.zeros((6, 1)); X[5, 0] = 1.0                         # unit couple on body 2
    qdd = np.linalg.solve(H, J2.T @ X[3:, 0])
    a2 = J2 @ qdd                                               # body 2's acceleration (no bias at rest)
    assert np.allclose(sol.mobility_times(X)[3:, 0], a2, atol=1e-12)
    rng = np.random.default_rng(0)
    Y = rng.normal(size=(6, 4))
    assert np.allclose(sol.mobility_times(Y), sol.mobility @ Y, atol=1e-12)


def test_mobility_option_is_checked():
    with pytest.raises(InputError, match="mobility must be 'columns' or 'full', got 'dense'"):
        loop_solve(chain_model(1), [0.0], [0.0], [0.0], mobility="dense")
