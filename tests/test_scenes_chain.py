"""The ``chain`` scene: all five methods run, agree with Pinocchio, and their errors propagate."""
import numpy as np
import pytest

from planargeo import scenes
from planargeo.errors import SingularConfigurationError
from planargeo.scenes import chain as chain_mod

pin = pytest.importorskip("pinocchio")


def to_pinocchio(model):
    """Revolute -> JointModelRZ, prismatic -> JointModelPX of the rotated joint frame; inertia about the com."""
    pm = pin.Model()
    ids = []
    for b, j, p in zip(model.bodies, model.joints, model.parents):
        px, py, th = j.placement
        R = np.array([[np.cos(th), -np.sin(th), 0.0], [np.sin(th), np.cos(th), 0.0], [0.0, 0.0, 1.0]])
        jm = {"revolute": pin.JointModelRZ, "prismatic": pin.JointModelPX}[j.kind]()
        jid = pm.addJoint(0 if p < 0 else ids[p], jm, pin.SE3(R, np.array([px, py, 0.0])), f"j{len(ids)}")
        pm.appendBodyToJoint(jid, pin.Inertia(b.mass, np.array([b.com[0], b.com[1], 0.0]),
                                              np.diag([1.0, 1.0, b.inertia])), pin.SE3.Identity())
        ids.append(jid)
    pm.gravity = pin.Motion(np.array([model.gravity[0], model.gravity[1], 0.0, 0.0, 0.0, 0.0]))
    return pm


@pytest.mark.parametrize("joint", ["revolute", "prismatic"])
@pytest.mark.parametrize("n", [1, 6, 20])
def test_all_five_methods_agree_with_pinocchio(joint, n):
    r = scenes.build("chain", n=n, joint=joint, seed=3, mass=0.7, length=1.3)
    assert list(r.quantities["qdd"]) == ["aba", "projective", "mobility_split", "stacked", "crba"]
    assert r.extra["methods"] == list(r.quantities["qdd"])
    q, qd, tau = (np.array(r.state[k]) for k in ("q", "qd", "tau"))
    pm = to_pinocchio(r.model)
    ref = pin.aba(pm, pm.createData(), q, qd, tau).copy()
    z = np.zeros(n)
    g0 = pin.rnea(pm, pm.createData(), q, z, z).copy()
    H = np.array([pin.rnea(pm, pm.createData(), q, z, e).copy() - g0 for e in np.eye(n)]).T
    tol = 10 * np.finfo(float).eps * np.linalg.cond(H) * np.abs(ref).max()
    for name, v in r.quantities["qdd"].items():
        assert np.abs(np.array(v) - ref).max() <= max(tol, 1e-12 * np.abs(ref).max()), name
    assert r.quantities["max_disagreement"] <= 2 * max(tol, 1e-12 * np.abs(ref).max())


def test_zero_state_single_rod_closed_form():
    # (m L^2 / 3) qdd = m g L / 2 with g = -3: qdd = 1.5 g / L
    r = scenes.build("chain", n=1, mass=2.0, length=0.5, gravity=-3.0)
    for v in r.quantities["qdd"].values():
        np.testing.assert_allclose(v, [1.5 * -3.0 / 0.5], rtol=1e-12)


def test_method_errors_propagate(monkeypatch):
    def broken(*a, **k):
        raise SingularConfigurationError("s^T A s of joint 1 vanishes", np.inf)

    monkeypatch.setitem(chain_mod.METHODS, "stacked", broken)
    with pytest.raises(SingularConfigurationError, match="s\\^T A s of joint 1 vanishes"):
        scenes.build("chain", n=2)


def test_available_methods_is_a_copy():
    m = chain_mod.available_methods()
    m.pop("aba")
    assert "aba" in chain_mod.METHODS
