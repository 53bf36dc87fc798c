"""The subspace decomposition of scene ``subspace`` (thesis 6.1–6.4, 6.63–6.97) against hand derivations.

References, written without the package's inertia matrices, T_of / U_of or Decomposition:

* Newton–Euler about the centre of mass by hand: the inertial wrench of an acceleration
  (force ``m a_c`` through ``c`` plus the couple ``J α``) and the free body's acceleration
  under a wrench;
* ``T``: the inertial wrenches of the accelerations in ``span(s)`` whose joint powers are
  the unit vectors (``sᵀT = 1``, 6.23); ``U``: the accelerations the reaction forces alone
  produce, scaled so that ``RᵀU = 1`` (6.22) — plus closed forms per joint kind;
* Lagrange's equations at rest ``M(q) q̈ = Q`` with hand-written Jacobians per joint kind;
* thesis example 6.9 (6.125, 6.127, 6.131, 6.133 at ω = 0; 6.33's missing inverse corrected).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from planargeo import scenes
from planargeo.errors import DegenerateGeometryError, SceneError

KINDS = ("revolute", "prismatic", "revolute_prismatic", "twin_prismatic")
CASES = [  # (joint point, joint angle deg, m, com, rho, force point, force angle deg, F)
    ((0.0, 0.0), 0.0, 2.0, (1.0, 0.0), 0.5, (1.6, 0.0), 90.0, 1.0),
    ((0.3, -0.4), 30.0, 1.5, (1.2, 0.5), 0.35, (0.2, 1.0), 200.0, 2.5),
    ((-1.0, 0.7), -75.0, 4.0, (0.4, -0.3), 0.8, (-0.5, -0.2), 10.0, -1.2),
]


def perp(r):
    return np.array([-r[1], r[0]])


def cross2(a, b):
    return a[0] * b[1] - a[1] * b[0]


class Body:
    """A rigid body by hand: mass, centre of mass, moment of inertia about it."""

    def __init__(self, m, c, rho):
        self.m, self.c, self.J = m, np.asarray(c, float), m * rho * rho

    def com_accel(self, a):                      # acceleration of the centre of mass of a twist at the origin
        return np.array([a[0] - a[2] * self.c[1], a[1] + a[2] * self.c[0]])

    def inertial_wrench(self, a):                # force m a_c through c, plus the couple J α (Newton–Euler)
        F = self.m * self.com_accel(a)
        return np.array([F[0], F[1], cross2(self.c, F) + self.J * a[2]])

    def free_accel(self, f):                     # the free body at rest under the wrench f
        F = np.array(f[:2])
        alpha = (f[2] - cross2(self.c, F)) / self.J       # moment about c / J
        ac = F / self.m
        return np.array([ac[0] + alpha * self.c[1], ac[1] - alpha * self.c[0], alpha])


def hand_spaces(kind, p, e):
    """s and R of the joint from its geometry (a rotation about p is the point [py, -px, 1])."""
    p, e = np.asarray(p, float), np.asarray(e, float)
    n = perp(e)
    rot = np.array([p[1], -p[0], 1.0])
    tr_e, tr_n = np.array([e[0], e[1], 0.0]), np.array([n[0], n[1], 0.0])

    def force(d):                                # unit force along d through p
        return np.array([d[0], d[1], cross2(p, d)])

    if kind == "revolute":
        return np.array([rot]).T, np.array([force((1, 0)), force((0, 1))]).T
    if kind == "prismatic":
        return np.array([tr_e]).T, np.array([force(n), [0.0, 0.0, 1.0]]).T
    if kind == "revolute_prismatic":
        return np.array([tr_e, rot]).T, np.array([force(n)]).T
    return np.array([tr_e, tr_n]).T, np.array([[0.0, 0.0, 1.0]]).T


def hand_T_U(body, s, R):
    """T from sᵀ(I a) = 1 over a ∈ span(s); U from Rᵀ a = 1 over a produced by reaction forces alone."""
    k = s.shape[1]
    W = np.array([body.inertial_wrench(s[:, i]) for i in range(k)]).T       # I s column by column
    X = np.linalg.solve(s.T @ W, np.eye(k))
    T = W @ X
    A = np.array([body.free_accel(R[:, j]) for j in range(R.shape[1])]).T   # I⁻¹ R column by column
    Y = np.linalg.solve(R.T @ A, np.eye(R.shape[1]))
    return T, A @ Y


def lagrange_accel(kind, p, e, body, point, F):
    """The held body's acceleration by Lagrange at rest: M q̈ = Q, then (a_c, α)."""
    p, e, point, F = (np.asarray(x, float) for x in (p, e, point, F))
    n = perp(e)
    if kind == "revolute":                      # q = θ about p
        Jc, Jb, Jt = perp(body.c - p)[:, None], perp(point - p)[:, None], np.array([[1.0]])
    elif kind == "prismatic":                   # q = x along e
        Jc = Jb = e[:, None]
        Jt = np.array([[0.0]])
    elif kind == "revolute_prismatic":          # q = (x along e, θ about the pin)
        Jc = np.array([e, perp(body.c - p)]).T
        Jb = np.array([e, perp(point - p)]).T
        Jt = np.array([[0.0, 1.0]])
    else:                                       # q = (x along e, y along e⊥)
        Jc = Jb = np.array([e, n]).T
        Jt = np.array([[0.0, 0.0]])
    M = body.m * Jc.T @ Jc + body.J * Jt.T @ Jt
    qdd = np.linalg.solve(M, Jb.T @ F)
    return Jc @ qdd, float((Jt @ qdd)[0])


def build(kind, case):
    p, ja, m, c, rho, a, fa, F = case
    return scenes.build("subspace", joint=kind, px=p[0], py=p[1], joint_angle_deg=ja, m=m, cx=c[0], cy=c[1],
                        rho=rho, ax=a[0], ay=a[1], force_angle_deg=fa, F=F)


def unit(deg):
    return np.array([math.cos(math.radians(deg)), math.sin(math.radians(deg))])


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("case", CASES)
def test_T_and_U_against_newton_euler_by_hand(kind, case):
    p, ja, m, c, rho = case[:5]
    q = build(kind, case).quantities
    body = Body(m, c, rho)
    s, R = hand_spaces(kind, p, unit(ja))
    np.testing.assert_allclose(q["s"], s, atol=1e-12)
    np.testing.assert_allclose(q["R"], R, atol=1e-12)
    T, U = hand_T_U(body, s, R)
    np.testing.assert_allclose(q["T"], T, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(q["U"], U, rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("case", CASES)
def test_closed_forms_per_joint_kind(case):
    p, ja, m, c, rho = (np.asarray(x, float) if isinstance(x, tuple) else x for x in case[:5])
    J, e = m * rho * rho, unit(ja)
    n = perp(e)
    # revolute: T is the force m perp(d) through c plus the couple J, over J + m d² (its line is 5.67's axis)
    d = c - p
    D = J + m * d @ d
    T = np.array([-m * d[1], m * d[0], J + m * (c @ d)]) / D
    np.testing.assert_allclose(np.ravel(build("revolute", case).quantities["T"]), T, rtol=1e-12, atol=1e-14)
    # prismatic: T is the unit force along e through the centre of mass; U₁ a unit slide across e,
    # U₂ a unit spin with the slide's point p kept still across e
    q = build("prismatic", case).quantities
    np.testing.assert_allclose(np.ravel(q["T"]), [e[0], e[1], cross2(c, e)], rtol=1e-12, atol=1e-14)
    ac = -((p - c) @ e) * n
    np.testing.assert_allclose(np.array(q["U"])[:, 0], [n[0], n[1], 0.0], atol=1e-12)
    np.testing.assert_allclose(np.array(q["U"])[:, 1], [ac[0] + c[1], ac[1] - c[0], 1.0], atol=1e-12)
    # twin prismatic (4.79): T unit forces through c along e and e⊥; U the unit spin about c
    q = build("twin_prismatic", case).quantities
    np.testing.assert_allclose(q["T"], [[e[0], n[0]], [e[1], n[1]], [cross2(c, e), cross2(c, n)]], atol=1e-12)
    np.testing.assert_allclose(np.ravel(q["U"]), [c[1], -c[0], 1.0], atol=1e-12)
    # pin in a slot: U is the push g e⊥ through p, g = 1 / (1/m + (r·e)²/J), r = p - c
    q = build("revolute_prismatic", case).quantities
    r = p - c
    g = 1.0 / (1.0 / m + (r @ e) ** 2 / J)
    alpha = g * (r @ e) / J
    acc = g / m * n
    np.testing.assert_allclose(np.ravel(q["U"]), [acc[0] + alpha * c[1], acc[1] - alpha * c[0], alpha],
                               rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("case", CASES)
def test_held_acceleration_against_lagrange(kind, case):
    p, ja, m, c, rho, a, fa, F = case
    q = build(kind, case).quantities
    body = Body(m, c, rho)
    ac, alpha = lagrange_accel(kind, p, unit(ja), body, a, F * unit(fa))
    a_held = np.array(q["s_psi"])
    scale = abs(F) / m * (1 + float(np.hypot(*c)) + float(np.hypot(*np.subtract(a, c))))
    np.testing.assert_allclose(body.com_accel(a_held), ac, atol=1e-12 * scale)
    assert a_held[2] == pytest.approx(alpha, abs=1e-12 * scale)
    # the joint's reaction is I a - f, i.e. -Rμ, and lies in the reaction space: it does no work on s
    f = np.array(q["f"])
    np.testing.assert_allclose(q["reaction"], body.inertial_wrench(a_held) - f, atol=1e-12 * abs(F) * 10)
    np.testing.assert_allclose(np.array(q["s"]).T @ np.array(q["reaction"]), 0.0, atol=1e-12 * abs(F) * 10)
    # the free body's acceleration I⁻¹ f = sψ + Uγ (6.44, 6.80-6.81)
    np.testing.assert_allclose(q["a_free"], body.free_accel(f), rtol=1e-10, atol=1e-12 * scale)
    np.testing.assert_allclose(np.add(q["s_psi"], q["U_gamma"]), q["a_free"], atol=1e-12 * scale)
    np.testing.assert_allclose(np.add(q["TQ"], q["Rmu"]), f, atol=1e-12 * abs(F) * 10)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("case", CASES)
def test_power_relations_vanish(kind, case):
    res = build(kind, case).quantities["residuals"]
    assert set(res) == {"sᵀT − 1", "RᵀU − 1", "TᵀU", "T sᵀ + R Uᵀ − 1", "sᵀR", "(sψ)ᵀ(Rμ)", "(Uγ)ᵀ(TQ)",
                        "Rᵀ(sψ)"}
    assert max(abs(v) for v in res.values()) < 1e-12


@pytest.mark.parametrize("kind", ["revolute_prismatic", "twin_prismatic"])
@pytest.mark.parametrize("case", CASES)
def test_two_dof_line_of_poles_is_R_and_T_pencil_meets_at_U(kind, case):
    """k = 2: the points s₁, s₂ span the reaction line R; the lines T₁, T₂ meet at the point U."""
    q = build(kind, case).quantities
    line, R = np.array(q["s_line"]), np.array(q["R"])[:, 0]
    np.testing.assert_allclose(np.cross(line, R), 0.0, atol=1e-12 * np.linalg.norm(R))
    meet, U = np.array(q["T_pencil"]), np.array(q["U"])[:, 0]
    np.testing.assert_allclose(np.cross(meet, U), 0.0, atol=1e-10 * np.linalg.norm(U))
    # the held body's acceleration pole lies on the line of poles (it is a combination of s)
    assert abs(np.array(q["s_psi"]) @ line) < 1e-12 * np.linalg.norm(q["s_psi"]) + 1e-15
    for one_dof in ("revolute", "prismatic"):
        q1 = build(one_dof, case).quantities
        assert q1["s_line"] is None and q1["T_pencil"] is None


def test_joint_space_and_reaction_space_inertias_by_hand():
    q = build("revolute", CASES[1]).quantities
    p, _, m, c, rho = CASES[1][:5]
    d = np.subtract(c, p)
    assert q["sIs"] == [[pytest.approx(m * rho ** 2 + m * d @ d, rel=1e-12)]]      # J_P (6.67)
    body = Body(m, c, rho)
    R = np.array(q["R"])
    RIR = R.T @ np.array([body.free_accel(R[:, j]) for j in range(2)]).T           # Rᵀ I⁻¹ R (6.71)
    np.testing.assert_allclose(q["RIR"], RIR, rtol=1e-12)


@pytest.mark.parametrize("eps, d, omega_free", [(0.45, 8.0, 0.0), (0.3, -5.0, 0.0), (1.2, 3.0, 0.0)])
def test_thesis_example_6_9_at_rest(eps, d, omega_free):
    """The car of 6.9 is a body on a revolute joint at the ICR; at ω = 0 (6.119: p = 0) 6.125-6.133 give T, U,
    ω̇ and the tyre forces μ.  U and μ of 6.127/6.133 are in the car's reaction basis R_car of 6.114
    (rear and front tyre), the scene's in the pivot's (x, y): R_car = R B, so U_car = U B⁻ᵀ and the joint's
    force on the car R_car μ_car equals the scene's ``reaction`` (−Rμ of the applied force)."""
    m, rho, L, FA = 1200.0, 1.2, 2.6, 2000.0
    h = math.hypot(d, L)
    q = scenes.build("subspace", joint="revolute", px=0.0, py=0.0, m=m, cx=d, cy=(1 - eps) * L, rho=rho,
                     ax=d, ay=L, force_angle_deg=math.degrees(math.atan2(d, -L)), F=FA).quantities
    D = rho ** 2 + d ** 2 + (1 - eps) ** 2 * L ** 2
    np.testing.assert_allclose(np.ravel(q["T"]), [-(1 - eps) * L / D, d / D, 1.0], rtol=1e-12)        # 6.125
    np.testing.assert_allclose(q["f"], [-L / h * FA, d / h * FA, h * FA], rtol=1e-12)                  # 6.120
    assert q["psi"][0] == pytest.approx(FA / m * h / D, rel=1e-12)                                       # 6.131
    B = np.array([[1.0, d / h], [0.0, L / h]])
    U_car = np.array(q["U"]) @ np.linalg.inv(B).T
    U_6_127 = np.array([[1.0, 0.0], [-d / L, h / L],
                        [(d ** 2 + (1 - eps) * L ** 2) / (L * D), -d * h / (L * D)]])
    np.testing.assert_allclose(U_car, U_6_127, rtol=1e-11, atol=1e-14)
    mu_car = np.linalg.solve(B, -np.array(q["mu"]))
    mu_6_133 = [-(eps * (1 - eps) * L ** 2 - rho ** 2) / D * h / L * FA,
                (eps * (2 - eps) * L ** 2 - rho ** 2) / D * d / L * FA]
    np.testing.assert_allclose(mu_car, mu_6_133, rtol=1e-11)


def test_erratum_6_33_printed_U_fails_R_U_equals_one():
    """6.33 prints U = I⁻¹R(RᵀI⁻¹R) without the inverse; the scene's U satisfies RᵀU = 1, the printed one not."""
    q = build("revolute", CASES[1]).quantities
    R, RIR = np.array(q["R"]), np.array(q["RIR"])
    body = Body(*(CASES[1][i] for i in (2, 3, 4)))
    IiR = np.array([body.free_accel(R[:, j]) for j in range(2)]).T
    printed = IiR @ RIR
    assert np.max(np.abs(R.T @ printed - np.eye(2))) > 1e-2
    np.testing.assert_allclose(R.T @ np.array(q["U"]), np.eye(2), atol=1e-12)


def test_bad_parameters_are_named():
    with pytest.raises(SceneError, match="^F must be non-zero, got 0.0$"):
        scenes.build("subspace", F=0.0)
    with pytest.raises(SceneError, match="^joint must be one of"):
        scenes.build("subspace", joint="ball")
    with pytest.raises(SceneError, match="^rho must be positive"):
        scenes.build("subspace", rho=0.0)


def test_subspace_state_refuses_a_zero_direction_by_name():
    from planargeo.scenes.subspace import subspace_state
    I = np.diag([1.0, 1.0, 1.0])
    with pytest.raises(DegenerateGeometryError, match="direction"):
        subspace_state("prismatic", (0.0, 0.0), (0.0, 0.0), I, [0.0, 1.0, 0.0])
    with pytest.raises(DegenerateGeometryError, match="force must be non-zero, or the wrench a pure couple"):
        subspace_state("revolute", (0.0, 0.0), (1.0, 0.0), I, [0.0, 0.0, 0.0])


@pytest.mark.parametrize("tau", [1.0, -2.5])
def test_a_pure_couple_is_an_ordinary_load(tau):
    """A couple tau (its line the line at infinity) on a body pinned at the origin, by hand.

    Body: m = 2 kg, centre of mass (1, 0), J_c = 0.5 kg·m²; about the pin J_o = J_c + m·1² = 2.5,
    so the held body turns at θ̈ = tau / J_o: a = [0, 0, θ̈] at the origin.  Newton: the pin's
    force is I a − f = [0, m θ̈, 0] (the centre of mass's acceleration times m, through the pin).
    """
    from planargeo.scenes.subspace import subspace_state
    m, J_c = 2.0, 0.5
    I = np.array([[m, 0.0, 0.0], [0.0, m, m * 1.0], [0.0, m * 1.0, J_c + m * 1.0]])
    st = subspace_state("revolute", (0.0, 0.0), (1.0, 0.0), I, [0.0, 0.0, tau])
    thdd = tau / (J_c + m)
    np.testing.assert_allclose(st["Q"], [tau], atol=1e-15)
    np.testing.assert_allclose(st["s_psi"], [0.0, 0.0, thdd], atol=1e-15)
    # Newton: the pin's force is m times the centre of mass's acceleration (0, thdd·1) minus nothing
    # applied (a couple has no force), acting through the pin (moment 0 about the origin)
    np.testing.assert_allclose(st["reaction"], [0.0, m * thdd, 0.0], atol=1e-14)
    assert all(abs(r) < 1e-14 for r in st["residuals"].values())
