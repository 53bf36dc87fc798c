"""Slider-crank of thesis 9.6: printed values, withheld results checked by independent methods."""
import numpy as np
import pytest
from hypothesis import given, strategies as st

from planargeo import scenes
from planargeo.algorithms.crba import mass_matrix
from planargeo.algorithms.loops import constrained_dynamics_lagrange, loop_solve
from planargeo.errors import SceneError, SingularConfigurationError
from planargeo.kinematics import kinematics
from planargeo.scenes.slider_crank import slider_crank, slider_crank_model, slider_crank_state

M1, M2, M3, R, L, T = 0.40, 0.15, 0.30, 2.29, 5.00, 0.5


def _minimal_psidd(psi, psid, g=9.81, drive_free=True):
    """ψ̈ from the Lagrangian in the single coordinate ψ (closed-form geometry, complex-step derivatives).

    Independent of the package: centres of mass and angles are written out by hand.
    """
    J1, J2 = 0.1464 * M1 * R * R, 0.0866 * M2 * L * L

    def geom(p):
        beta = np.arccos(-R * np.cos(p) / L)            # ψ + θ (piston above the crank pin)
        c1 = (R / 4) * np.array([np.cos(p), np.sin(p)])
        A = R * np.array([np.cos(p), np.sin(p)])
        c2 = A + (L / 2) * np.array([np.cos(beta), np.sin(beta)])
        c3 = np.array([0 * p, R * np.sin(p) + L * np.sin(beta) + T])
        return c1, c2, c3, beta

    def d(f, p, h=1e-20):                                 # complex-step derivative
        return np.imag(f(p + 1j * h)) / h

    def Mass(p):
        dc1 = d(lambda x: geom(x)[0], p)
        dc2 = d(lambda x: geom(x)[1], p)
        dc3 = d(lambda x: geom(x)[2], p)
        db = d(lambda x: geom(x)[3], p)
        return M1 * dc1 @ dc1 + J1 + M2 * dc2 @ dc2 + J2 * db * db + M3 * dc3 @ dc3

    def V(p):
        c1, c2, c3, _ = geom(p)
        return g * (M1 * c1[1] + M2 * c2[1] + M3 * c3[1])

    h = 1e-5
    dM = (Mass(psi + h) - Mass(psi - h)) / (2 * h)
    dV = d(V, psi)
    return -(0.5 * dM * psid ** 2 + dV) / Mass(psi)


# --------------------------------------------------------------------------- printed values
def test_printed_state_and_twists_9_78_to_9_80():
    res = slider_crank()
    q, qd, v = (np.array(res.quantities[k]) for k in ("q", "qd", "v"))
    assert q[0] == 0.4 and q[2] == pytest.approx(-0.4355, abs=5e-5)               # 9.78
    assert q.sum() == pytest.approx(np.pi / 2, abs=1e-14)                          # Fig 9.3 caption
    assert qd[0] == 20.0 and abs(qd[1]) == pytest.approx(23.9343, abs=5e-5)        # 9.79 up to sign
    assert abs(qd[2]) == pytest.approx(3.9343, abs=5e-5)
    assert np.allclose(v[0], [0, 0, 20.0], atol=5e-4)                              # 9.80
    assert np.allclose(v[1], [-21.344, 50.483, -3.934], atol=5e-4)
    assert np.allclose(v[2], [0, 50.483, 0], atol=5e-4)


def test_printed_h_z3_B3_9_83_to_9_87():
    Q = slider_crank().quantities
    assert Q["h"] == pytest.approx(5.925, abs=5e-4)                               # 9.86
    assert np.allclose(Q["z3"], [0, 1, 0])                                        # 9.83
    assert np.allclose(Q["B3"], [[1, 0], [0, 0], [-5.925, 1]], atol=5e-4)          # 9.87


def test_erratum_9_78_9_79_printed_state_violates_the_loop():
    # printed θ = 1.603 does not close the loop (x of the piston pin ≠ 0) ...
    x_pin = R * np.cos(0.4) + L * np.cos(0.4 + 1.603)
    assert abs(x_pin) > 1e-2
    # ... θ = 1.6063 does
    q, qd = slider_crank_state()
    assert q[1] == pytest.approx(1.6063, abs=5e-5)
    assert abs(R * np.cos(q[0]) + L * np.cos(q[0] + q[1])) < 1e-14
    # printed rates (20, 23.9343, -3.9343) turn the piston (ψ̇+θ̇+φ̇ = 40) and give other twists
    m = slider_crank_model()
    v_printed = kinematics(m, q, [20.0, 23.9343, -3.9343]).v
    assert abs(v_printed[2, 2]) > 1 and not np.allclose(v_printed[1], [-21.344, 50.483, -3.934], atol=1e-2)
    # the corrected rates reproduce the printed twists (9.80)
    assert np.allclose(qd, [20.0, -23.9343, 3.9343], atol=5e-5)
    assert np.allclose(kinematics(m, q, qd).v[1], [-21.344, 50.483, -3.934], atol=5e-4)


# --------------------------------------------------------------------------- withheld results
@pytest.mark.parametrize("g", [9.81, 0.0])
def test_withheld_9_81_mobility_vs_dense(g):
    res = slider_crank(g=g)
    q = np.array(res.quantities["q"])
    d = kinematics(res.model, q)
    J3 = d.jacobian(2)
    ref = J3 @ np.linalg.solve(mass_matrix(res.model, q), J3.T)     # operational-space mobility of body 3
    assert np.allclose(res.quantities["Lambda3_inv"], ref, rtol=1e-10, atol=1e-10)


@pytest.mark.parametrize("g", [9.81, 0.0])
def test_withheld_9_82_open_loop_vs_maximal_coordinates(g):
    res = slider_crank(g=g)
    Q = res.quantities
    ref = constrained_dynamics_lagrange(res.model, Q["q"], Q["qd"], [0, 0, 0], contacts=[])
    assert np.allclose(Q["u"], ref["a"], rtol=1e-10, atol=1e-9)
    # "the open loop acceleration u3 is not a pure translation in the vertical direction"
    assert abs(Q["u"][2][0]) > 1 and abs(Q["u"][2][2]) > 1


@pytest.mark.parametrize("g", [9.81, 0.0])
@pytest.mark.parametrize("drive", ["free", "constant-speed"])
def test_withheld_9_90_to_9_94_vs_lagrange(g, drive):
    res = slider_crank(g=g, drive=drive)
    Q = res.quantities
    ref = constrained_dynamics_lagrange(res.model, Q["q"], Q["qd"], [0, 0, 0],
                                        prescribed={0: 0.0} if drive == "constant-speed" else None)
    assert np.allclose(Q["a3"], ref["a"][2], rtol=1e-10, atol=1e-9)                # 9.94
    assert np.allclose(Q["F3"], ref["F"][0], rtol=1e-10, atol=1e-9)                # 9.92
    assert np.allclose(Q["qdd"], ref["qdd"], rtol=1e-10, atol=1e-9)
    assert np.allclose(Q["tau_drive"], ref["tau_drive"], rtol=1e-10, atol=1e-9)
    # 9.92 = B3 ξ3 (9.91) and a3 is a pure vertical translation (text after 9.94)
    assert np.allclose(np.array(Q["B3"]) @ Q["xi"], Q["F3"])
    assert abs(Q["a3"][0]) < 1e-10 and abs(Q["a3"][2]) < 1e-10
    # 9.89: ξ3 = (B3^T Λ3^-1 B3)^-1 B3^T u3 (ν = 0 here), computed from the dense mobility
    if drive == "free":
        B3, u3, Lam = np.array(Q["B3"]), np.array(Q["u"][2]), np.array(Q["Lambda3_inv"])
        assert np.allclose(Q["xi"], np.linalg.solve(B3.T @ Lam @ B3, B3.T @ u3))


@pytest.mark.parametrize("psi, psid, g", [(0.4, 20.0, 9.81), (0.4, 20.0, 0.0), (2.0, -3.0, 9.81), (-1.0, 7.0, 9.81)])
def test_crank_acceleration_vs_minimal_lagrangian(psi, psid, g):
    res = slider_crank(psi=psi, psidot=psid, g=g)
    assert res.quantities["qdd"][0] == pytest.approx(_minimal_psidd(psi, psid, g), rel=1e-7, abs=1e-7)


def test_constant_speed_drive():
    Q = slider_crank(drive="constant-speed").quantities
    assert abs(Q["qdd"][0]) < 1e-12
    # the piston acceleration is then purely kinematic: ḧ = d²/dt² [r sin ψ + l sin β] at ψ̈ = 0
    psi, w = 0.4, 20.0
    f = lambda p: R * np.sin(p) + L * np.sin(np.arccos(-R * np.cos(p) / L))
    df = lambda p: np.imag(f(p + 1e-20j)) / 1e-20           # complex step
    h = 1e-4
    hdd = (df(psi + h) - df(psi - h)) / (2 * h) * w ** 2
    assert Q["a3"][1] == pytest.approx(hdd, rel=1e-7)


@given(st.floats(-3.0, 3.0), st.floats(-30.0, 30.0))
def test_scene_states_close_the_loop(psi, psid):
    q, qd = slider_crank_state(psi, psid)
    m = slider_crank_model()
    d = kinematics(m, q, qd)
    assert abs(d.com[2, 0]) < 1e-12                    # piston on the line x = 0
    assert abs(d.v[2, 0]) < 1e-9 * max(1, abs(psid)) and abs(d.v[2, 2]) < 1e-9 * max(1, abs(psid))
    assert d.com[2, 1] > 0                              # assembly branch: piston above the pivot


# --------------------------------------------------------------------------- singular and bad input
def test_dead_centres_of_the_thesis_crank_are_regular():
    # ψ = ±π/2 (crank and rod along the piston line) is not singular in this parametrisation
    for psi in (np.pi / 2, -np.pi / 2):
        assert slider_crank(psi=psi).quantities["cond"] < 100


def test_folded_dead_centre_raises_with_cond():
    # l = r and ψ = 0: the piston pin lands on the crank pivot; the closure loses rank
    with pytest.raises(SingularConfigurationError) as e:
        slider_crank(psi=0.0, l=R)
    assert e.value.cond > 1e10
    m = slider_crank_model(l=R)
    with pytest.raises(SingularConfigurationError, match="B\\^T G Λ\\^-1 G\\^T B is singular") as e:
        loop_solve(m, [0.0, np.pi, -np.pi / 2], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    assert e.value.cond > 1e10


def test_rod_too_short():
    with pytest.raises(SceneError, match="rod too short: l = 2 cannot reach the piston line"):
        slider_crank(psi=0.0, l=2.0)


@pytest.mark.parametrize("kw, msg", [(dict(drive="turbo"), "drive must be 'free' or 'constant-speed'"),
                                     (dict(m1=-1.0), "m1 must be positive"),
                                     (dict(t=0.0), "t must be positive")])
def test_bad_parameters(kw, msg):
    with pytest.raises(SceneError, match=msg):
        slider_crank(**kw)


def test_registry():
    assert "slider-crank" in scenes.names()
    res = scenes.build("slider-crank", psi=0.5)
    assert res.name == "slider-crank" and res.params["psi"] == 0.5
    assert scenes.parameters("slider-crank")["psidot"] == 20.0
    assert set(["q", "qd", "v", "u", "Lambda3_inv", "h", "xi", "F3", "a3", "qdd"]) <= set(res.quantities)
