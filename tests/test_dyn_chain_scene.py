"""The ``chain`` scene."""
import numpy as np
import pytest

from planargeo import scenes
from planargeo.errors import SceneError


def test_defaults_and_parameters():
    assert scenes.parameters("chain") == {"n": 3, "mass": 1.0, "length": 1.0, "joint": "revolute",
                                          "seed": None, "gravity": -9.81}
    r = scenes.build("chain")
    assert r.model.N == 3 and r.state == {"q": [0.0] * 3, "qd": [0.0] * 3, "tau": [0.0] * 3}
    assert "aba" in r.quantities["qdd"] and "crba" in r.quantities["qdd"]


def test_single_link_closed_form():
    r = scenes.build("chain", n=1, mass=2.0, length=0.5, gravity=-3.0)
    # (m L²/3) qdd = -m g L/2 with g = 3  ->  qdd = -1.5 g / L
    for v in r.quantities["qdd"].values():
        np.testing.assert_allclose(v, [-1.5 * 3.0 / 0.5], rtol=1e-12)


@pytest.mark.parametrize("joint", ["revolute", "prismatic"])
def test_methods_agree(joint):
    r = scenes.build("chain", n=6, joint=joint, seed=3)
    assert set(r.quantities["qdd"]) == {"aba", "projective", "mobility_split", "stacked", "crba"}
    ref = np.array(r.quantities["qdd"]["crba"])
    for name, v in r.quantities["qdd"].items():
        np.testing.assert_allclose(v, ref, rtol=1e-9, atol=1e-9, err_msg=name)
    assert r.quantities["max_disagreement"] < 1e-9


def test_seeded_state_is_reproducible():
    a, b = scenes.build("chain", seed=5), scenes.build("chain", seed=5)
    assert a.state == b.state and a.state["q"] != [0.0] * 3


@pytest.mark.parametrize("params, word", [({"n": 0}, "n must be a positive integer"),
                                          ({"n": 2.5}, "n must be a positive integer"),
                                          ({"joint": "plane"}, "joint must be"),
                                          ({"mass": -1.0}, "mass must be positive"),
                                          ({"length": 0.0}, "length must be positive"),
                                          ({"colour": 1}, "no parameter 'colour'")])
def test_bad_parameters(params, word):
    with pytest.raises(SceneError, match=word):
        scenes.build("chain", **params)
