"""Chapter 7 scenes: two-body (7.2), horizontal-chain (7.3), mobility-example (7.5).

Closed forms 7.19-7.24 are the thesis's (verified); the withheld results of
7.3 and 7.5 are computed by the scenes and checked against INDEPENDENT dense
references (free-floating subtree Schur complement, joint-space ``J H^-1 J^T``,
CRBA forward dynamics with the couple as an external load) and hand-derived
closed forms.
"""
from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo import scenes
from planargeo.errors import SceneError
from test_articulated_reference import dense_articulated, dense_mobility, reference_accelerations

pos = st.floats(0.2, 5.0)
angle = st.floats(-np.pi, np.pi)


def test_registered_with_parameters_and_defaults():
    names = scenes.names()
    for n in ("two-body", "horizontal-chain", "mobility-example"):
        assert n in names
    assert scenes.parameters("two-body") == {"m": 1.0, "rho": 0.5, "L": 1.0, "phi": np.pi / 4}
    assert scenes.parameters("horizontal-chain") == {"n": 4, "lam": 2.0}
    assert scenes.parameters("mobility-example") == {"m": 1.0, "rho": 0.5, "L": 1.0, "phi": np.pi / 4,
                                                      "tau": 1.0}


@pytest.mark.parametrize("name", ["two-body", "horizontal-chain", "mobility-example"])
def test_quantities_and_state_are_plain_json(name):
    r = scenes.build(name)
    json.dumps({"params": r.params, "state": r.state, "quantities": r.quantities})


# ---------------------------------------------------------------------------
# two-body (7.2)
# ---------------------------------------------------------------------------
@given(m=pos, rho=pos, L=pos, phi=angle)
def test_two_body_A1_closed_form_7_19(m, rho, L, phi):
    A1 = np.array(scenes.build("two-body", m=m, rho=rho, L=L, phi=phi).quantities["A1"])
    c, s = np.cos(phi), np.sin(phi)
    D = L**2 + 4 * rho**2
    expected = np.array([
        [m + m * (L**2 * c**2 + 4 * rho**2) / D, m * L**2 / D * s * c, m * L**3 / D * s * c],
        [m * L**2 / D * s * c, m + m * (L**2 * s**2 + 4 * rho**2) / D,
         m * L / 2 + (m * L**3 * s**2 + 4 * m * L * rho**2) / D],
        [m * L**3 / D * s * c, m * L / 2 + (m * L**3 * s**2 + 4 * m * L * rho**2) / D,
         m * rho**2 + 1.25 * m * L**2 - m * L**4 * c**2 / D]])
    np.testing.assert_allclose(A1, expected, rtol=1e-10, atol=1e-12 * np.abs(expected).max())


@given(m=pos, rho=pos, L=pos, phi=angle)
def test_two_body_mx_7_20_7_22(m, rho, L, phi):
    q = scenes.build("two-body", m=m, rho=rho, L=L, phi=phi).quantities
    lam = L / rho
    assert q["lam"] == pytest.approx(lam)
    assert q["m_x"] / m == pytest.approx((L**2 + 8 * rho**2 + L**2 * np.cos(phi) ** 2) / (L**2 + 4 * rho**2))
    assert q["mx_over_m"] == pytest.approx((8 + lam**2 * (1 + np.cos(phi) ** 2)) / (lam**2 + 4), rel=1e-12)


@pytest.mark.parametrize("phi", [0.0, 0.4, 1.3, 2.5])
def test_two_body_limits_7_23_7_24(phi):
    big = scenes.build("two-body", rho=1e-4, L=1.0, phi=phi).quantities["mx_over_m"]
    small = scenes.build("two-body", rho=1e4, L=1.0, phi=phi).quantities["mx_over_m"]
    assert big == pytest.approx(1 + np.cos(phi) ** 2, abs=1e-6)       # lambda -> infinity (7.23)
    assert small == pytest.approx(2.0, abs=1e-6)                      # lambda -> 0 (7.24)


def test_two_body_A1_matches_dense_schur_complement():
    r = scenes.build("two-body", m=1.3, rho=0.37, L=1.1, phi=0.7)
    A_ref, _ = dense_articulated(r.model, r.state["q"], r.state["qd"], r.state["tau"], None, 0)
    np.testing.assert_allclose(r.quantities["A1"], A_ref, atol=1e-12)


# ---------------------------------------------------------------------------
# horizontal-chain (7.3): withheld table rows, checked independently
# ---------------------------------------------------------------------------
def _dense_row(res):
    """(d/L, mx/m, my/m, Az/(m rho^2)) from the dense free-floating Schur complement (m = L = 1)."""
    A, _ = dense_articulated(res.model, res.state["q"], res.state["qd"], res.state["tau"], None, 0)
    rho = 1.0 / res.params["lam"]
    assert A[0, 1] == pytest.approx(0.0, abs=1e-12) and A[0, 2] == pytest.approx(0.0, abs=1e-12)
    d = A[1, 2] / A[1, 1]
    return d, A[0, 0], A[1, 1], (A[2, 2] - A[1, 2] ** 2 / A[1, 1]) / rho**2


@pytest.mark.parametrize("n", [1, 2, 3, 4])
@pytest.mark.parametrize("lam", [0.5, 1.0, 2.0, 3.0, 4.9])
def test_horizontal_chain_rows_match_dense(n, lam):
    res = scenes.build("horizontal-chain", n=n, lam=lam)
    q = res.quantities
    got = (q["d_over_L"], q["mx_over_m"], q["my_over_m"], q["Az_over_m_rho2"])
    np.testing.assert_allclose(got, _dense_row(res), rtol=1e-10)
    assert q["mx_over_m"] == pytest.approx(n)          # the whole chain follows a push along it


@given(lam=st.floats(0.1, 10.0))
def test_horizontal_chain_two_bodies_closed_forms(lam):
    q = scenes.build("horizontal-chain", n=2, lam=lam).quantities
    x = lam * lam
    assert q["d_over_L"] == pytest.approx((x + 12) / (2 * (x + 8)), rel=1e-12)     # 7.27
    assert q["mx_over_m"] == pytest.approx(2.0, rel=1e-12)
    assert q["my_over_m"] == pytest.approx((x + 8) / (x + 4), rel=1e-12)
    assert q["Az_over_m_rho2"] == pytest.approx(2 * (x + 4) / (x + 8), rel=1e-12)


def test_horizontal_chain_first_row_7_25():
    q = scenes.build("horizontal-chain", n=1, lam=1.7).quantities
    assert (q["d_over_L"], q["mx_over_m"], q["my_over_m"]) == (0.5, 1.0, 1.0)
    assert q["Az_over_m_rho2"] == pytest.approx(1.0, rel=1e-12)


@pytest.mark.parametrize("n", [2, 3, 4, 5, 6])
def test_horizontal_chain_lambda_2_claim(n):
    # 7.3: at lambda = 2 further bodies change nothing (d = 2L/3, 7.27), except m_x = n m
    q = scenes.build("horizontal-chain", n=n, lam=2.0).quantities
    assert q["d_over_L"] == pytest.approx(2 / 3, rel=1e-12)
    assert q["my_over_m"] == pytest.approx(1.5, rel=1e-12)
    assert q["Az_over_m_rho2"] == pytest.approx(4 / 3, rel=1e-12)
    assert q["mx_over_m"] == pytest.approx(n)


def test_horizontal_chain_claim_fails_away_from_lambda_2():
    a = scenes.build("horizontal-chain", n=2, lam=4.0).quantities
    b = scenes.build("horizontal-chain", n=4, lam=4.0).quantities
    assert abs(a["Az_over_m_rho2"] - b["Az_over_m_rho2"]) > 0.05


# ---------------------------------------------------------------------------
# mobility-example (7.5): withheld 7.43, 7.46, 7.48
# ---------------------------------------------------------------------------
@given(m=pos, rho=pos, L=pos, phi=angle)
def test_mobility_Lambda2_matches_dense_J_Hinv_JT(m, rho, L, phi):
    r = scenes.build("mobility-example", m=m, rho=rho, L=L, phi=phi)
    Lam, b = dense_mobility(r.model, r.state["q"], r.state["qd"], r.state["tau"], None, 1)
    np.testing.assert_allclose(r.quantities["Lambda2_inv"], Lam, atol=1e-9 * np.abs(Lam).max())
    np.testing.assert_allclose(b, 0.0, atol=1e-12)


@given(m=pos, rho=pos, L=pos, phi=angle, tau=st.floats(-5, 5).filter(lambda t: abs(t) > 1e-3))
def test_mobility_a2_matches_pinocchio_with_the_couple_as_a_load(m, rho, L, phi, tau):
    r = scenes.build("mobility-example", m=m, rho=rho, L=L, phi=phi, tau=tau)
    f_ext = np.zeros((2, 3))
    f_ext[1] = [0.0, 0.0, -tau]               # joint 3 pushes body 2 with -f_3 (3.1)
    a2 = reference_accelerations(r.model, r.state["q"], [0, 0], [0, 0], f_ext)[1]
    np.testing.assert_allclose(r.quantities["a2"], a2, atol=1e-9 * np.abs(a2).max())
    assert r.quantities["a2"][0] == pytest.approx(0.0, abs=1e-12)    # a twist about a point on y = 0


@given(rho=pos, L=pos, phi=angle)
def test_mobility_x_over_L_hand_closed_form(rho, L, phi):
    # x/L = 1 + 2 eta^2 cos(phi) / (4 + 5 eta^2), from H u = [1, 1] with the 2x2 joint-space inertia
    q = scenes.build("mobility-example", rho=rho, L=L, phi=phi).quantities
    eta = L / rho
    assert q["eta"] == pytest.approx(eta)
    assert q["x_over_L"] == pytest.approx(1 + 2 * eta**2 * np.cos(phi) / (4 + 5 * eta**2), rel=1e-10)


def test_mobility_subspaces_7_40_7_41_7_42():
    m, rho, L, phi = 1.0, 0.4, 1.3, 0.6
    q = scenes.build("mobility-example", m=m, rho=rho, L=L, phi=phi).quantities
    D = L**2 + 4 * rho**2
    c, s = np.cos(phi), np.sin(phi)
    np.testing.assert_allclose(q["T1"], [0, 2 * L / D, 1], atol=1e-14)
    np.testing.assert_allclose(q["U1"], [[1, 0], [0, 1], [0, -2 * L / D]], atol=1e-14)
    np.testing.assert_allclose(q["U2"], [[1, 0], [-2 * L**2 * s / D, 1 + 2 * L**2 * c / D],
                                         [2 * L * s / D, -2 * L * c / D]], atol=1e-14)
    np.testing.assert_allclose(q["T2"], [-2 * L * s / D, 2 * L * c / D, 1 + 2 * L**2 * c / D], atol=1e-14)
    Lam1 = np.zeros((3, 3))
    Lam1[2, 2] = 4 / (m * D)
    np.testing.assert_allclose(q["Lambda1_inv"], Lam1, atol=1e-14)


def test_mobility_printed_sign_would_move_the_centre():
    # with the sign of 7.38a as printed, Lambda_2^-1 (and the centre x) would be wrong
    from test_articulated_mobility import _printed_mobility
    from planargeo.mechanics.kinematics import kinematics

    r = scenes.build("mobility-example")
    d = kinematics(r.model, r.state["q"])
    printed = _printed_mobility(d.I, [d.s(0), d.s(1)], d.kappa, d.p, [np.zeros(1)] * 2)[1]
    a2 = -printed @ [0.0, 0.0, 1.0]
    x_printed = -a2[1] / a2[2]
    assert abs(x_printed - r.quantities["x_over_L"]) > 0.1


# ---------------------------------------------------------------------------
# impossible parameters
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("name, params, match", [
    ("two-body", {"m": -1.0}, "m must be positive"),
    ("two-body", {"rho": 0.0}, "rho must be positive"),
    ("two-body", {"L": float("nan")}, "L must be finite"),
    ("horizontal-chain", {"n": 0}, "n must be a positive integer"),
    ("horizontal-chain", {"n": 2.5}, "n must be a positive integer"),
    ("horizontal-chain", {"lam": -2.0}, "lam must be positive"),
    ("mobility-example", {"tau": 0.0}, "tau must be non-zero"),
    ("mobility-example", {"phi": "x"}, "phi must be numeric"),
])
def test_impossible_parameters_raise_scene_error(name, params, match):
    with pytest.raises(SceneError, match=match):
        scenes.build(name, **params)
