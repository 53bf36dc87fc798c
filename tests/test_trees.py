"""Scenes "tree" (Fig 9.1) and "constrained-tree" (Fig 9.2)."""
import numpy as np
import pytest

from planargeo import scenes
from planargeo.algorithms.crba import forward_dynamics_crba
from planargeo.algorithms.loops import constrained_dynamics_lagrange
from planargeo.errors import SceneError
from planargeo.kinematics import kinematics
from planargeo.simulate_loops import closure_jacobian, closure_residual


def test_registered():
    assert {"tree", "constrained-tree"} <= set(scenes.names())


@pytest.mark.parametrize("speed, g", [(1.0, 9.81), (3.0, 0.0)])
def test_tree_matches_crba(speed, g):
    res = scenes.build("tree", speed=speed, g=g)
    q, qd = res.state["q"], res.state["qd"]
    ref = forward_dynamics_crba(res.model, q, qd, np.zeros(9))
    assert np.allclose(res.quantities["qdd"], ref, atol=1e-10)
    assert np.allclose(res.quantities["qdd_direct"], ref, atol=1e-10)
    assert np.array(res.quantities["C"]).sum() == 8
    assert np.array(res.quantities["Dinv"])[7].tolist() == [1, 0, 0, 0, 1, 1, 0, 1, 0]   # row 8 of 9.13


def test_tree_pose_closes_fig_9_2_loops():
    res = scenes.build("tree")
    pose = kinematics(res.model, res.state["q"]).pose
    L = 1.0
    tip = lambda i: pose[i, :2] + L * np.array([np.cos(pose[i, 2]), np.sin(pose[i, 2])])
    assert np.allclose(tip(3), tip(6)) and np.allclose(tip(7), tip(8))


@pytest.mark.parametrize("speed, g, mass", [(1.0, 9.81, 1.0), (2.0, 0.0, 0.5)])
def test_constrained_tree_matches_lagrange(speed, g, mass):
    res = scenes.build("constrained-tree", speed=speed, g=g, mass=mass)
    Q, m = res.quantities, res.model
    q, qd = np.array(res.state["q"]), np.array(res.state["qd"])
    assert np.abs(closure_residual(m, q)).max() < 1e-14
    Jc = closure_jacobian(m, q)
    assert np.abs(Jc @ qd).max() < 1e-12 and np.linalg.matrix_rank(Jc) == 4   # 9 - 4 = 5 dof
    ref = constrained_dynamics_lagrange(m, q, qd, np.zeros(9))
    assert np.allclose(Q["qdd"], ref["qdd"], atol=1e-9)
    assert np.allclose(Q["a"], ref["a"], atol=1e-9)
    assert np.allclose(Q["F"], ref["F"], atol=1e-9)
    assert np.array_equal(np.array(Q["G"]), [[0, 0, 0, 1, 0, 0, -1, 0, 0], [0, 0, 0, 0, 0, 0, 0, 1, -1]])  # 9.49
    assert np.array_equal(np.array(Q["Upsilon"]),
                          [[0, 1, 1, 1, -1, -1, -1, 0, 0], [0, 0, 0, 0, 1, 1, 0, 1, -1]])              # 9.51


@pytest.mark.parametrize("name", ["tree", "constrained-tree"])
def test_bad_parameters(name):
    with pytest.raises(SceneError, match="length must be positive"):
        scenes.build(name, length=-1.0)
    with pytest.raises(SceneError, match="has no parameter 'colour'"):
        scenes.build(name, colour="red")
