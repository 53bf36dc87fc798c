"""articulated_body on one state (Python floats) against the same recursion on arrays (a batch of one).

One state of joints with at most one coordinate each runs steps 3-4 of the articulated-body
algorithm on plain floats (an explorer's update); a batch runs them on arrays.  The two codes
must give the whole workspace (A, d, a, f, q̈ and the per-joint D, U, u) to rounding (NumPy sums
a batch's rows in another order: 1e-10 of the largest entry covers speeds of 10 rad/s), on chains
and trees, revolute, prismatic and fixed joints, with gravity and external wrenches, and raise
the same error for a singular joint.
"""
import numpy as np
import pytest

from planargeo.algorithms.aba import articulated_body, forward_dynamics
from planargeo.errors import SingularConfigurationError
from planargeo.mechanics.model import Body, Joint, Model, chain_model, random_model

KINDS = [("revolute",), ("prismatic",), ("revolute", "prismatic", "fixed")]


def _close(a, b, what):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert a.shape == b.shape, what
    scale = max(np.abs(b).max(initial=0.0), 1.0)
    assert np.abs(a - b).max(initial=0.0) <= 1e-10 * scale, what


def _same_workspace(m, q, qd, tau, f_ext=None):
    one = articulated_body(m, q, qd, tau, f_ext)
    batch = articulated_body(m, q[None], qd[None], tau[None], None if f_ext is None else f_ext[None])
    for name in ("qdd", "A", "d", "a", "f"):
        _close(getattr(one, name), getattr(batch, name)[0], name)
    for name in ("D", "U", "u"):
        for i, (x, y) in enumerate(zip(getattr(one, name), getattr(batch, name))):
            assert (x is None) == (y is None), (name, i)
            if x is not None:
                _close(x, y[0], (name, i))
    return one


@pytest.mark.parametrize("kinds", KINDS)
@pytest.mark.parametrize("tree", [False, True])
@pytest.mark.parametrize("N", [1, 2, 5, 12])
def test_one_state_equals_the_array_recursion(N, tree, kinds):
    rng = np.random.default_rng(N + 7 * tree)
    m = random_model(N, seed=N, kinds=kinds, tree=tree, gravity=tuple(rng.normal(size=2) * 5))
    for seed in range(3):
        q, qd, tau = rng.normal(size=(3, m.nq)) * 10.0 ** (seed - 1)
        f_ext = rng.normal(size=(m.N, 3))
        _same_workspace(m, q, qd, tau)
        _same_workspace(m, q, qd, tau, f_ext)


def test_explorer_chain_at_rest_and_moving():
    """The chain explorer's own case: ten uniform links, at rest (zero rows) and moving."""
    m = chain_model(10)
    zero = np.zeros(10)
    w = _same_workspace(m, zero, zero, zero)
    # q̈ of the compiled kernel (another code of the same recursion)
    _close(w.qdd, forward_dynamics(m, zero, zero, zero), "q̈, kernel")
    rng = np.random.default_rng(3)
    q, qd, tau = rng.normal(size=(3, 10))
    _close(_same_workspace(m, q, qd, tau).qdd, forward_dynamics(m, q, qd, tau), "q̈, kernel")


def test_a_singular_joint_raises_as_in_a_batch():
    """A point mass on its own pivot carrying a pendulum in line with it: joint 1 is singular."""
    m = Model([Body(1.0, (0.0, 0.0), 0.0), Body(1.0, (0.5, 0.0), 0.0)],
              [Joint("revolute"), Joint("revolute", (1.0, 0.0, 0.0))], [-1, 0])
    q, qd, tau = np.array([0.3, 0.0]), np.array([0.2, -0.1]), np.zeros(2)
    with pytest.raises(SingularConfigurationError, match="joint 1 ") as one:
        articulated_body(m, q, qd, tau)
    with pytest.raises(SingularConfigurationError) as batch:
        articulated_body(m, q[None], qd[None], tau[None])
    assert str(one.value) == str(batch.value) and one.value.cond == batch.value.cond
