"""Model description and validation (planargeo.mechanics.model) and kinematics checks."""
import numpy as np
import pytest

from planargeo.errors import CyclicTopologyError, InputError, NonFiniteError, ShapeError, TopologyError
from planargeo.mechanics.kinematics import check_state, kinematics
from planargeo.mechanics.model import JOINT_DOFS, Body, Joint, Model, chain_model, random_model

ALL_KINDS = tuple(JOINT_DOFS)


# -- validation ---------------------------------------------------------------
@pytest.mark.parametrize("mass", [0.0, -1.0])
def test_body_mass_must_be_positive(mass):
    with pytest.raises(InputError, match="mass must be positive"):
        Body(mass)


def test_body_rejects_negative_inertia_and_bad_com():
    with pytest.raises(InputError, match="inertia must be non-negative"):
        Body(1.0, inertia=-0.1)
    with pytest.raises(ShapeError, match="com"):
        Body(1.0, com=(1.0, 2.0, 3.0))
    with pytest.raises(NonFiniteError, match="mass"):
        Body(float("nan"))


def test_joint_kind_and_placement():
    with pytest.raises(InputError, match="kind must be one of"):
        Joint("hinge")
    with pytest.raises(ShapeError, match="placement"):
        Joint("revolute", (0.0, 0.0))
    assert [Joint(k).dofs for k in ALL_KINDS] == [1, 1, 2, 2, 3, 0]


def test_frozen():
    b = Body(1.0)
    with pytest.raises(AttributeError):
        b.mass = 2.0
    m = chain_model(2)
    with pytest.raises(AttributeError):
        m.parents = (-1, -1)
    with pytest.raises(ValueError):
        m.arrays()["mass"][0] = 3.0


@pytest.mark.parametrize("parents, words", [
    ([-1, 5], "index out of range"),
    ([-1, -2], "index out of range"),
    ([1, 0], "cycle"),
    ([0], "cycle"),               # a body that is its own parent
    ([-1, 2, 0], r"parents\[1\] must be below 1"),  # no cycle, but child before parent
])
def test_topology_errors(parents, words):
    n = len(parents)
    with pytest.raises(TopologyError, match=words):
        Model([Body(1.0)] * n, [Joint("revolute")] * n, parents)


@pytest.mark.parametrize("parents, cycle", [
    ([1, 0], (0, 1)),
    ([0], (0,)),                                  # a body that is its own parent
    ([-1, 3, 1, 2], (1, 3, 2)),                   # 1 -> 3 -> 2 -> 1 behind a good root
    ([-1, 0, 4, 2, 3, 1], (2, 4, 3)),             # cycle not through the first bad index
])
def test_cycle_raises_cyclic_topology_error_with_cond(parents, cycle):
    """A cycle makes 1 - C singular (thesis 9.12): the error names the cycle's bodies and carries cond = inf."""
    n = len(parents)
    with pytest.raises(CyclicTopologyError) as e:
        Model([Body(1.0)] * n, [Joint("revolute")] * n, parents)
    assert isinstance(e.value, TopologyError) and isinstance(e.value, ValueError)
    assert e.value.cond == np.inf and e.value.cycle == cycle
    path = " -> ".join(map(str, cycle + cycle[:1]))
    assert str(e.value) == (f"parents contain a cycle through bodies {path} (parents={parents}) "
                            "(condition number of 1 - C: inf)")
    # cross-check: numerically, 1 - C is singular too
    C = np.zeros((n, n))
    for i, p in enumerate(parents):
        if p >= 0:
            C[i, p] = 1.0
    assert np.linalg.cond(np.eye(n) - C) > 1e15


def test_ordering_problem_is_not_a_cycle():
    with pytest.raises(TopologyError) as e:
        Model([Body(1.0)] * 3, [Joint("revolute")] * 3, [-1, 2, 0])
    assert not isinstance(e.value, CyclicTopologyError)


def test_model_other_errors():
    with pytest.raises(TopologyError, match="one entry per body"):
        Model([Body(1.0)] * 2, [Joint("revolute")] * 2, [-1])
    with pytest.raises(InputError, match="joints must have one entry per body"):
        Model([Body(1.0)] * 2, [Joint("revolute")], [-1, 0])
    with pytest.raises(InputError, match=r"bodies\[0\] must be a Body"):
        Model(["x"], [Joint("revolute")], [-1])
    with pytest.raises(ShapeError, match="gravity"):
        Model([Body(1.0)], [Joint("revolute")], [-1], gravity=(0, 0, 1))


def test_structure_helpers():
    m = Model([Body(1.0)] * 4, [Joint("revolute"), Joint("plane"), Joint("fixed"), Joint("prismatic")],
              [-1, 0, 0, 1])
    assert m.nq == 5 and m.q_offsets == (0, 1, 4, 4, 5)
    assert m.q_slice(1) == slice(1, 4) and m.q_slice(2) == slice(4, 4)
    assert m.children(0) == (1, 2) and m.children(-1) == (0,)
    assert m.ancestors(3) == (0, 1, 3)
    # coordinates moving each body: those of the joints on its path from the ground, by hand
    assert m.ancestor_mask().astype(int).tolist() == [[1, 0, 0, 0, 0], [1, 1, 1, 1, 0], [1, 0, 0, 0, 0],
                                                      [1, 1, 1, 1, 1]]
    assert not m.is_chain and chain_model(3).is_chain
    with pytest.raises(InputError, match="i must be a body index"):
        m.q_slice(7)


def test_check_state_errors():
    m = chain_model(2)
    with pytest.raises(ShapeError, match=r"q must have shape \(\.\.\., 2\)"):
        check_state(m, [0.0])
    with pytest.raises(ShapeError, match="qd"):
        check_state(m, [0.0, 0.0], [0.0])
    with pytest.raises(NonFiniteError, match="tau"):
        check_state(m, [0.0, 0.0], [0.0, 0.0], [np.nan, 0.0])
    with pytest.raises(ShapeError, match="f_ext"):
        check_state(m, [0.0, 0.0], f_ext=np.zeros((3, 3)))
    with pytest.raises(ShapeError, match="does not broadcast"):
        check_state(m, np.zeros((3, 2)), np.zeros((4, 2)))
    with pytest.raises(InputError, match="f_ext must be real"):
        check_state(m, [0.0, 0.0], f_ext=np.zeros((2, 3), dtype=complex))


def test_check_state_none_is_zeros():
    """Every method validates its state here: qd, tau, qdd None are zeros, f_ext None is no load."""
    q, qd, tau, f_ext, qdd, shape = check_state(chain_model(2), [[0.0, 1.0]] * 3)
    for x in (qd, tau, qdd):
        assert x.dtype == np.float64 and np.array_equal(x, [0.0, 0.0])
    assert f_ext is None and shape == (3,)


# -- kinematics ---------------------------------------------------------------
def test_chain_geometry_by_hand():
    """Two unit links at q = (pi/2, -pi/2): link 1 points up, link 2 along +x from (0, 1)."""
    d = kinematics(chain_model(2), [np.pi / 2, -np.pi / 2], [1.0, 2.0])
    np.testing.assert_allclose(d.pose, [[0, 0, np.pi / 2], [0, 1, 0]], atol=1e-15)
    np.testing.assert_allclose(d.com, [[0, 0.5], [0.5, 1]], atol=1e-15)
    # revolute joints are the points [y, -x, 1] (5.51)
    np.testing.assert_allclose(d.S, [[0, 1], [0, 0], [1, 1]], atol=1e-15)
    np.testing.assert_allclose(d.v, [[0, 0, 1], [2, 0, 3]], atol=1e-15)
    # Jacobian of body 1 only sees joint 0
    np.testing.assert_allclose(d.jacobian(0), [[0, 0], [0, 0], [1, 0]], atol=1e-15)
    np.testing.assert_allclose(d.J[1], d.S)


def _state_at(m, q, qd, qdd, t, f_ext=None):
    return kinematics(m, q + qd * t + 0.5 * qdd * t * t, qd + qdd * t, f_ext)


@pytest.mark.parametrize("tree", [False, True])
def test_kinematics_against_finite_differences(tree):
    """v is the time derivative of the pose, and a = a_parent + s qdd + kappa is dv/dt (2.17-2.19),
    including the sequential-screw cross terms of multi-dof joints (erratum 2.19)."""
    m = random_model(8, seed=11, kinds=ALL_KINDS, tree=tree)
    rng = np.random.default_rng(0)
    q, qd, qdd = rng.normal(size=(3, m.nq))
    h = 1e-5
    d0, dp, dm = (_state_at(m, q, qd, qdd, t) for t in (0.0, h, -h))
    # velocity of each centre of mass from the twist at the origin: v_o + w x c
    vc = np.stack([d0.v[:, 0] - d0.v[:, 2] * d0.com[:, 1], d0.v[:, 1] + d0.v[:, 2] * d0.com[:, 0]], -1)
    np.testing.assert_allclose((dp.com - dm.com) / (2 * h), vc, atol=1e-8)
    np.testing.assert_allclose((dp.pose[:, 2] - dm.pose[:, 2]) / (2 * h), d0.v[:, 2], atol=1e-8)
    a = np.zeros((m.N, 3))
    for i, par in enumerate(m.parents):
        a[i] = (a[par] if par >= 0 else 0.0) + d0.s(i) @ qdd[m.q_slice(i)] + d0.kappa[i]
    np.testing.assert_allclose(a, (dp.v - dm.v) / (2 * h), atol=1e-7)


def test_kinematics_batch_matches_single():
    m = random_model(6, seed=2, kinds=ALL_KINDS, tree=True)
    rng = np.random.default_rng(1)
    q, qd = rng.normal(size=(2, 5, m.nq))
    fe = rng.normal(size=(5, m.N, 3))
    b = kinematics(m, q, qd, fe)
    for k in range(5):
        s = kinematics(m, q[k], qd[k], fe[k])
        for name in ("pose", "com", "origin", "S", "I", "v", "kappa", "g", "p"):
            np.testing.assert_allclose(getattr(b, name)[k], getattr(s, name), atol=1e-13, err_msg=name)


def test_gravity_wrench_acts_at_com():
    """g_i is m*gravity applied at the world centre of mass: its line passes through the com."""
    m = random_model(4, seed=3)
    d = kinematics(m, np.linspace(0.1, 0.4, m.nq))
    for i in range(m.N):
        point = np.array([d.com[i, 1], -d.com[i, 0], 1.0])  # the com as a homogeneous point
        assert abs(point @ d.g[i]) < 1e-12                    # incidence (5.69)
        np.testing.assert_allclose(d.g[i, :2], m.bodies[i].mass * np.array(m.gravity))


from hypothesis import given  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@given(st.lists(st.integers(-3, 8), min_size=1, max_size=8))
def test_property_parents_valid_or_topology_error(parents):
    """Any integer parent list either builds a model whose parents precede their children,
    or raises TopologyError (never anything else)."""
    n = len(parents)
    try:
        m = Model([Body(1.0)] * n, [Joint("revolute")] * n, parents)
    except CyclicTopologyError as e:
        assert e.cond == np.inf and len(e.cycle) >= 1
        # the reported cycle is one: each body's parent is the next one
        assert all(parents[a] == b for a, b in zip(e.cycle, e.cycle[1:] + e.cycle[:1]))
        return
    except TopologyError:
        assert any(not -1 <= p < i for i, p in enumerate(parents))
        return
    assert all(-1 <= p < i for i, p in enumerate(m.parents))
    for i in range(n):
        assert m.ancestors(i)[-1] == i and m.ancestors(i)[0] in m.children(-1)
