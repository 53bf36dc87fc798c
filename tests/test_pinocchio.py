"""Cross-check against Pinocchio (an independent rigid-body library).

Planar models are embedded in 3-D by ``bench.to_pinocchio``: revolute joints become
``JointModelRZ``, prismatic joints ``JointModelPX`` of a frame rotated about z; the
body inertia is given about the centre of mass (``pin.Inertia(m, com3, I3)``);
gravity is set explicitly.
"""
import numpy as np
import pytest

pin = pytest.importorskip("pinocchio")

from planargeo.algorithms.aba import forward_dynamics  # noqa: E402
from planargeo.algorithms.crba import mass_matrix  # noqa: E402
from planargeo.algorithms.rnea import inverse_dynamics  # noqa: E402
from planargeo.mechanics.model import chain_model, random_model  # noqa: E402
from bench import to_pinocchio  # noqa: E402


def test_uniform_chain_defaults():
    """The default scene chain (unit links along +x, gravity -9.81 y) against pin.aba."""
    m = chain_model(4)
    pm = to_pinocchio(m)
    pd = pm.createData()
    rng = np.random.default_rng(0)
    for _ in range(3):
        q, qd, tau = rng.normal(size=(3, 4))
        ref = pin.aba(pm, pd, q, qd, tau).copy()
        np.testing.assert_allclose(forward_dynamics(m, q, qd, tau), ref, rtol=1e-9, atol=1e-9 * np.abs(ref).max())


@pytest.mark.parametrize("N", [1, 2, 5, 10, 30, 100])
@pytest.mark.parametrize("tree", [False, True])
def test_random_models_against_pinocchio(N, tree):
    m = random_model(N, seed=7 * N + tree, kinds=("revolute", "prismatic"), tree=tree)
    pm = to_pinocchio(m)
    pd = pm.createData()
    rng = np.random.default_rng(N)
    q, qd, tau = rng.normal(size=(3, 4, m.nq))
    ours = forward_dynamics(m, q, qd, tau)   # one batched call
    for k in range(4):
        ref = pin.aba(pm, pd, q[k], qd[k], tau[k]).copy()  # copy before the next call reuses the buffer
        scale = np.abs(ref).max()
        assert np.abs(ours[k] - ref).max() <= 1e-9 * scale
        assert np.abs(forward_dynamics(m, q[k], qd[k], tau[k]) - ref).max() <= 1e-9 * scale
        # inverse dynamics and the mass matrix too
        tau_ref = pin.rnea(pm, pd, q[k], qd[k], ref).copy()
        np.testing.assert_allclose(inverse_dynamics(m, q[k], qd[k], ref), tau_ref, atol=1e-9 * np.abs(tau_ref).max())
        if tree:
            # pin.crba assumes depth-first joint order (contiguous subtrees); random trees are not
            # in that order, so build H column by column from pin.rnea instead
            z = np.zeros(m.nq)
            g = pin.rnea(pm, pd, q[k], z, z).copy()
            H_ref = np.array([pin.rnea(pm, pd, q[k], z, e).copy() - g for e in np.eye(m.nq)]).T
        else:
            H_ref = pin.crba(pm, pm.createData(), q[k]).copy()
            H_ref = np.triu(H_ref) + np.triu(H_ref, 1).T   # pinocchio may fill only the upper triangle
        np.testing.assert_allclose(mass_matrix(m, q[k]), H_ref, atol=1e-10 * np.abs(H_ref).max())
