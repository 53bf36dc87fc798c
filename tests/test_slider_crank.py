"""Slider-crank of thesis 9.6: printed values, withheld results checked by independent methods."""
import numpy as np
import pytest
from hypothesis import given, strategies as st

from planargeo import scenes
from planargeo.algorithms.loops import constrained_dynamics_lagrange, loop_solve
from planargeo.errors import SceneError, SingularConfigurationError
from planargeo.mechanics.kinematics import kinematics
from planargeo.scenes.slider_crank import slider_crank, slider_crank_model, slider_crank_state

import _slider_crank_reference as scref

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
# References from tests/_slider_crank_reference.py: plain trigonometry, complex-step Jacobians,
# the mass matrix by hand and the multiplier solve [H J_cᵀ; J_c 0] (no planargeo code).
CASES = [(0.4, 20.0), (2.0, -5.0), (-1.0, 7.0)]


def _close(x, ref, rel=1e-11, scale=None):
    """|x - ref| <= rel * scale (scale: max |ref| unless given; measured errors are ~1e-14 relative)."""
    x, ref = np.asarray(x, dtype=float), np.asarray(ref, dtype=float)
    scale = np.abs(ref).max() if scale is None else scale
    assert x.shape == ref.shape
    err = np.abs(x - ref).max()
    assert err <= rel * max(scale, 1e-300), (err, scale)


def test_reference_is_self_consistent():
    """The reference's own pieces agree: J_c = B3ᵀ J3 (9.87), J̇3 q̇ by finite differences, H symmetric PD."""
    for psi, psid in CASES:
        ref = scref.reference(psi, psid)
        np.testing.assert_allclose(ref["Jc"], ref["B3"].T @ ref["J3"], atol=1e-13)
        q, qd = ref["q"], ref["qd"]
        assert np.abs(scref.closure(q)).max() < 1e-14 and np.abs(ref["Jc"] @ qd).max() < 1e-12
        hstep = 1e-5
        Jp = scref.body_twist_jacobian(2, q + hstep * qd, qd)[0]
        Jm = scref.body_twist_jacobian(2, q - hstep * qd, qd)[0]
        np.testing.assert_allclose((Jp - Jm) / (2 * hstep) @ qd, scref.body_twist_jacobian(2, q, qd)[1],
                                   rtol=1e-7, atol=1e-7 * np.abs(qd).max() ** 2)
        assert np.allclose(ref["H"], ref["H"].T) and np.linalg.eigvalsh(ref["H"]).min() > 0
        # the piston only translates vertically in the closed loop (text after 9.94)
        assert abs(ref["a3"][0]) < 1e-10 * np.abs(ref["u"]).max() and abs(ref["a3"][2]) < 1e-12 * np.abs(ref["u"]).max()


@pytest.mark.parametrize("psi, psid", CASES)
@pytest.mark.parametrize("g", [9.81, 0.0])
def test_withheld_9_81_mobility_vs_independent(psi, psid, g):
    """Λ3⁻¹ = J3 H⁻¹ J3ᵀ (9.81): body 3's twist Jacobian and H from plain trigonometry."""
    Q = slider_crank(psi=psi, psidot=psid, g=g).quantities
    ref = scref.reference(psi, psid, g=g)
    _close(Q["Lambda3_inv"], ref["Lambda3_inv"])                    # measured ~3e-14 relative
    # and the mobility is what maps a wrench on body 3 to its acceleration: a3 - u3 = -Λ3⁻¹ F3 (9.88)
    _close(np.array(Q["u"][2]) - np.array(Q["a3"]), ref["Lambda3_inv"] @ ref["F3"], scale=np.abs(ref["u"]).max())


@pytest.mark.parametrize("psi, psid", CASES)
@pytest.mark.parametrize("g", [9.81, 0.0])
def test_withheld_9_82_open_loop_vs_independent(psi, psid, g):
    res = slider_crank(psi=psi, psidot=psid, g=g)
    Q = res.quantities
    ref = scref.reference(psi, psid, g=g)
    _close(Q["u"], ref["u"])                                         # measured ~3e-14 relative
    _close(Q["v"], ref["v"], rel=1e-13)
    # and against the package's maximal-coordinate solve with the contact removed (another method)
    lag = constrained_dynamics_lagrange(res.model, Q["q"], Q["qd"], [0, 0, 0], contacts=[])
    assert np.allclose(Q["u"], lag["a"], rtol=1e-10, atol=1e-9)
    # "the open loop acceleration u3 is not a pure translation in the vertical direction"
    if (psi, psid) == (0.4, 20.0):
        assert abs(Q["u"][2][0]) > 1 and abs(Q["u"][2][2]) > 1


@pytest.mark.parametrize("psi, psid", CASES)
@pytest.mark.parametrize("g", [9.81, 0.0])
@pytest.mark.parametrize("drive", ["free", "constant-speed"])
def test_withheld_9_90_to_9_94_vs_multiplier_solve(psi, psid, g, drive):
    """ξ3 (9.90), F3 (9.92), a3 (9.94), q̈ and the drive torque from the multiplier solve
    [H J_cᵀ; J_c 0] of the reference (the multiplier is ξ in the basis B3 of 9.87)."""
    res = slider_crank(psi=psi, psidot=psid, g=g, drive=drive)
    Q = res.quantities
    ref = scref.reference(psi, psid, g=g, drive=drive)
    _close(Q["B3"], ref["B3"], rel=1e-14)
    _close(Q["xi"], ref["xi"])                                       # measured <= 1e-13 relative
    _close(Q["F3"], ref["F3"])
    _close(Q["a3"], ref["a3"], scale=np.abs(ref["u"]).max())         # a3 = u3 - Λ3⁻¹F3 cancels to ~1e-3 of u3
    _close(Q["qdd"], ref["qdd"], scale=np.abs(ref["qdd_open"]).max())
    _close(Q["tau_drive"], ref["tau_drive"], scale=max(np.abs(ref["tau_drive"]).max(), np.abs(ref["C"]).max()))
    # and the package's maximal-coordinate Lagrange reference
    lag = constrained_dynamics_lagrange(res.model, Q["q"], Q["qd"], [0, 0, 0],
                                        prescribed={0: 0.0} if drive == "constant-speed" else None)
    assert np.allclose(Q["F3"], lag["F"][0], rtol=1e-10, atol=1e-9)
    # 9.91 and the text after 9.94: a3 is a pure vertical translation
    assert np.allclose(np.array(Q["B3"]) @ Q["xi"], Q["F3"])
    assert abs(Q["a3"][0]) < 1e-10 * np.abs(ref["u"]).max() and abs(Q["a3"][2]) < 1e-10 * np.abs(ref["u"]).max()
    # 9.89 (ν = 0 for a free crank) holds with the reference's own Λ3⁻¹ and u3
    if drive == "free":
        B3, u3, Lam = ref["B3"], ref["u"][2], ref["Lambda3_inv"]
        _close(np.linalg.solve(B3.T @ Lam @ B3, B3.T @ u3), ref["xi"])


@pytest.mark.parametrize("psi, psid, g", [(0.4, 20.0, 9.81), (0.4, 20.0, 0.0), (2.0, -3.0, 9.81), (-1.0, 7.0, 9.81)])
def test_crank_acceleration_vs_minimal_lagrangian(psi, psid, g):
    res = slider_crank(psi=psi, psidot=psid, g=g)
    assert res.quantities["qdd"][0] == pytest.approx(_minimal_psidd(psi, psid, g), rel=1e-7, abs=1e-7)


def test_constant_speed_drive():
    Q = slider_crank(drive="constant-speed").quantities
    assert Q["qdd"][0] == 0.0                      # the drive's value exactly, not the solve's rounding
    for psi in (0.1, 1.3, 2.9):
        assert slider_crank(psi=psi, drive="constant-speed").quantities["qdd"][0] == 0.0
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


# --------------------------------------------------------------------------- Play helpers (#14 item 4)
def test_dead_centres_passed_in_order_both_ways_and_over_turns():
    from planargeo.scenes.slider_crank import dead_centre_at, dead_centres_passed

    names = [n for n, _ in dead_centres_passed(0.0, 4 * np.pi)]
    assert names == ["top dead centre", "bottom dead centre"] * 2
    back = dead_centres_passed(2.0, -2.0)
    assert [n for n, _ in back] == ["top dead centre", "bottom dead centre"]
    assert back[0][1] == pytest.approx(np.pi / 2) and back[1][1] == pytest.approx(-np.pi / 2)
    # an end exactly on a dead centre counts once: at the end of one frame, not the start of the next
    assert dead_centres_passed(1.0, np.pi / 2) == [("top dead centre", np.pi / 2)]
    assert dead_centres_passed(np.pi / 2, 2.0) == []
    assert dead_centres_passed(0.3, 0.3) == [] and dead_centre_at(0.3) == ""
    assert dead_centre_at(-np.pi / 2) == "bottom dead centre"


def test_advance_matches_the_one_coordinate_reference_and_refuses_bad_steps():
    from scipy.integrate import solve_ivp

    import _slider_crank_reference as ref
    from planargeo.errors import SceneError
    from planargeo.scenes.slider_crank import slider_crank_advance, slider_crank_model

    m = slider_crank_model()
    out = slider_crank_advance(m, 0.4, 20.0, 0.03)
    sol = solve_ivp(lambda _t, y: [y[1], ref.reference(y[0], y[1])["qdd"][0]], (0.0, 0.03), [0.4, 20.0],
                    method="DOP853", rtol=1e-11, atol=1e-12)
    assert out["psi"] == pytest.approx(sol.y[0, -1], abs=1e-7)
    assert out["psidot"] == pytest.approx(sol.y[1, -1], abs=1e-6)
    assert out["position_residual"] < 1e-9 and out["status"] == "ok"
    driven = slider_crank_advance(m, 0.4, 20.0, 0.03, drive="constant-speed")
    assert driven["psidot"] == 20.0 and driven["psi"] == pytest.approx(0.4 + 0.6, abs=1e-12)
    with pytest.raises(SceneError, match="dt must be positive"):
        slider_crank_advance(m, 0.4, 20.0, 0.0)
    with pytest.raises(SceneError, match="drive"):
        slider_crank_advance(m, 0.4, 20.0, 0.01, drive="sideways")
