"""Models with "fixed" joints: the dense reference and the integrator handle zero or fewer coordinates."""
import numpy as np
import pytest

from planargeo.algorithms.crba import bias_forces, forward_dynamics_crba, mass_matrix
from planargeo.mechanics.model import Body, Joint, Model
from planargeo.simulate.integrate import simulate


def welded(kinds=("fixed", "fixed")):
    """Two unit-mass rods (J = 0.1 about the centre, centre at 0.5) joined end to end."""
    bodies = [Body(1.0, (0.5, 0.0), 0.1), Body(1.0, (0.5, 0.0), 0.1)]
    joints = [Joint(kinds[0], (0.0, 0.0, 0.0)), Joint(kinds[1], (1.0, 0.0, 0.0))]
    return Model(bodies, joints, [-1, 0])


def test_crba_all_fixed_returns_empty_accelerations():
    m = welded()
    assert m.nq == 0
    assert mass_matrix(m, []).shape == (0, 0)
    assert bias_forces(m, [], []).shape == (0,)
    out = forward_dynamics_crba(m, [], [], [], f_ext=np.ones((2, 3)))
    assert out.shape == (0,) and out.dtype == float
    batch = forward_dynamics_crba(m, np.zeros((4, 0)), np.zeros((4, 0)), np.zeros((4, 0)))
    assert batch.shape == (4, 0)
    batch[...] = 1.0          # a fresh array, not a read-only view of the inputs


@pytest.mark.parametrize("kinds", [("revolute", "fixed"), ("fixed", "revolute")])
def test_crba_mixed_fixed_and_revolute_closed_form(kinds):
    # a compound pendulum, released horizontally: qdd = -g sum(m x_c) / (sum J + m x_c^2)
    g = 9.81
    if kinds[0] == "revolute":     # both rods swing about the origin, centres at 0.5 and 1.5
        ref = -g * (0.5 + 1.5) / (0.1 + 0.25 + 0.1 + 2.25)
    else:                           # rod 1 welded to the ground; rod 2 swings about (1, 0)
        ref = -g * 0.5 / (0.1 + 0.25)
    qdd = forward_dynamics_crba(welded(kinds), [0.0], [0.0], [0.0])
    np.testing.assert_allclose(qdd, [ref], rtol=1e-13)


@pytest.mark.parametrize("forward", [None, forward_dynamics_crba], ids=["aba", "crba"])
def test_simulate_model_without_coordinates(forward):
    r = simulate(welded(), [], [], 0.5, method="RK4", dt=0.1, forward=forward)
    assert r.status == "ok" and r.q.shape == (6, 0) and np.all(r.energy == 0.0)
    r = simulate(welded(), [], [], 0.5, forward=forward)
    assert r.status == "ok" and r.t[-1] == 0.5
