"""``planargeo report`` checked against Pinocchio: the n = 50 chain (every method) and the
slider-crank of 9.6 (every withheld output, from Pinocchio's mass matrix and a multiplier solve).

Kept apart from ``test_cli_report.py`` so that, without Pinocchio, only these are skipped.
"""
from __future__ import annotations

import numpy as np
import pytest

pin = pytest.importorskip("pinocchio")

import _slider_crank_reference as scref  # noqa: E402
from test_cli_report import report_json  # noqa: E402

EPS = np.finfo(float).eps

# ---------------------------------------------------------------------------
# chain: n = 50, seed = 3, five methods against each other and against Pinocchio
# ---------------------------------------------------------------------------
def pinocchio_chain(n, mass=1.0, length=1.0, g=-9.81):
    """The issue's default chain in Pinocchio: JointModelRZ, inertia about the centre of mass."""
    pm = pin.Model()
    parent = 0
    for i in range(n):
        place = pin.SE3(np.eye(3), np.array([0.0 if i == 0 else length, 0.0, 0.0]))
        parent = pm.addJoint(parent, pin.JointModelRZ(), place, f"j{i}")
        I3 = np.diag([1.0, 1.0, mass * length ** 2 / 12])
        pm.appendBodyToJoint(parent, pin.Inertia(mass, np.array([length / 2, 0.0, 0.0]), I3), pin.SE3.Identity())
    pm.gravity = pin.Motion(np.array([0.0, g, 0.0, 0.0, 0.0, 0.0]))
    return pm


def test_chain_n50_seed3_json_every_method_agrees_with_pinocchio():
    obj = report_json("chain", "--set", "n=50", "--set", "seed=3")
    assert obj["scene"] == "chain"
    assert obj["params"]["n"] == 50 and obj["params"]["seed"] == 3
    qs = obj["quantities"]
    q, qd, tau = (np.array(qs[k]) for k in ("q", "qd", "tau"))
    for v in (q, qd, tau):
        assert v.shape == (50,)
    # the random state is numpy's default_rng(3) normal draw, as documented
    np.testing.assert_array_equal(np.stack([q, qd, tau]), np.random.default_rng(3).normal(size=(3, 50)))
    assert obj["state"] == {"q": qs["q"], "qd": qs["qd"], "tau": qs["tau"]}
    assert set(qs["qdd"]) == {"aba", "projective", "mobility_split", "stacked", "crba"}

    pm = pinocchio_chain(50)
    ref = pin.aba(pm, pm.createData(), q, qd, tau).copy()
    H = pin.crba(pm, pm.createData(), q).copy()
    H = np.triu(H) + np.triu(H, 1).T
    cond = np.linalg.cond(H)                                   # ~5e5 here
    tol = 10 * EPS * cond                                      # relative, scaled by cond(H)
    scale = np.abs(ref).max()
    qdd = {k: np.array(v) for k, v in qs["qdd"].items()}
    for name, v in qdd.items():
        assert v.shape == (50,)
        for other, w in qdd.items():
            assert np.abs(v - w).max() <= tol * scale, (name, other)
        assert np.abs(v - ref).max() <= tol * scale, name
    assert np.abs(qdd["aba"] - ref).max() <= 1e-9 * scale      # issue: 1e-9 relative for N <= 100
    # and the equations of motion themselves: H qdd + C = tau (C from Pinocchio's RNEA)
    C = pin.rnea(pm, pm.createData(), q, qd, np.zeros(50)).copy()
    assert np.abs(H @ qdd["aba"] + C - tau).max() <= 1e-9 * np.abs(tau - C).max()


# ---------------------------------------------------------------------------
# slider-crank (9.6): H and C from Pinocchio, the loop closure in plain trigonometry
# (tests/_slider_crank_reference.py), the multiplier solve [H J_cᵀ; J_c 0][q̈; ξ] = [-C; -J̇_c q̇]
# ---------------------------------------------------------------------------
def _close(x, ref, rel, scale=None):
    x, ref = np.asarray(x, dtype=float), np.asarray(ref, dtype=float)
    assert x.shape == ref.shape
    scale = np.abs(ref).max() if scale is None else scale
    err = np.abs(x - ref).max()
    assert err <= rel * scale, (err, scale)


@pytest.mark.parametrize("psi, psidot, drive", [(0.4, 20.0, "free"), (2.0, -5.0, "free"),
                                                (0.4, 20.0, "constant-speed")])
def test_slider_crank_json_outputs_against_multiplier_solve(psi, psidot, drive):
    obj = report_json("slider-crank", "--set", f"psi={psi}", "--set", f"psidot={psidot}", "--set", f"drive={drive}")
    qs = obj["quantities"]
    shapes = {"q": (3,), "qd": (3,), "v": (3, 3), "u": (3, 3), "Lambda3_inv": (3, 3), "h": (),
              "xi": (2,), "F3": (3,), "a3": (3,), "qdd": (3,), "B3": (3, 2), "tau_drive": (3,)}
    for key, shape in shapes.items():
        assert np.shape(qs[key]) == shape, key
    ref = scref.reference(psi, psidot, drive=drive, method="pinocchio")
    # Pinocchio's H and C agree with the hand-written Lagrangian of the reference module
    hand = scref.reference(psi, psidot, drive=drive, method="hand")
    _close(ref["H"], hand["H"], 1e-13)
    _close(ref["C"], hand["C"], 1e-13)
    _close(qs["q"], ref["q"], 1e-15)
    _close(qs["qd"], ref["qd"], 1e-14)
    assert qs["h"] == pytest.approx(ref["h"], rel=1e-14)
    _close(qs["B3"], ref["B3"], 1e-15)
    _close(qs["v"], ref["v"], 1e-13)
    # withheld results (measured agreement ~1e-14 relative; 1e-11 leaves a wide margin)
    _close(qs["Lambda3_inv"], ref["Lambda3_inv"], 1e-11)                      # 9.81: J3 H⁻¹ J3ᵀ
    _close(qs["u"], ref["u"], 1e-11)                                          # 9.82
    _close(qs["xi"], ref["xi"], 1e-11)                                        # 9.90: the multipliers
    _close(qs["F3"], ref["F3"], 1e-11)                                        # 9.92: B3 ξ
    _close(qs["a3"], ref["a3"], 1e-11, scale=np.abs(ref["u"]).max())         # 9.94 (cancels: scale of u)
    _close(qs["qdd"], ref["qdd"], 1e-11, scale=np.abs(ref["qdd_open"]).max())
    _close(qs["tau_drive"], ref["tau_drive"], 1e-11, scale=max(np.abs(ref["C"]).max(), 1.0))
    # the piston translates vertically: a3 = [0, ḧ, 0] at the origin
    assert abs(qs["a3"][0]) < 1e-10 * np.abs(ref["u"]).max() and abs(qs["a3"][2]) < 1e-10 * np.abs(ref["u"]).max()
