"""Tests of planargeo.draw.splits: the drawn T/U decompositions (ch. 6) against closed forms by hand.

A rod (mass m, centre of mass c, inertia J about c) on a revolute joint at P, everything by hand:
  s = [Py, -Px, 1] (the pole P, 4.64), R = [unit x force through P, unit y force through P]:
  R1 = [1, 0, -Py], R2 = [0, 1, Px] (a line [fx, fy, tz]: tz + y fx - x fy = 0, 4.27).
  For a twist u = [vx, vy, w], R_kᵀu is the velocity of P along e_k (vP = (vx - w Py, vy + w Px)).
  T = A s (sᵀAs)⁻¹ (6.36): A s is the momentum of a unit rotation about P: force m (k × r)
  (r = c - P), moment about O = J + m (c × (k × r))_z; sᵀAs = J_P = J + m|r|².
  U = A⁻¹R(RᵀA⁻¹R)⁻¹ (6.45) is the only U with RᵀU = 1 and sᵀAU = 0 (sᵀ A A⁻¹ R = sᵀR = 0):
  U_k moves P with unit acceleration along e_k and has zero angular momentum about P:
  J w + m r × (e_k + w k × r) = 0  =>  w_k = -m (r × e_k) / J_P.
  A⁻¹R_k, the percussion pole of the force R_k (5.6): on the perpendicular from c to the line,
  ρ²/d beyond c (ρ² = J/m, d the distance from c to the line).

The checks read the picture's plain data (what both renderers draw): marks, clipped lines
and force arrows, and rebuild the drawn quantities from them.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from planargeo.draw.picture import Picture
from planargeo.draw.splits import (decomposition, projective_step, twist_split, twist_parts,
                                   wrench_parts, wrench_split)
from planargeo.errors import InputError, NonFiniteError, ShapeError

M, C, JC, P = 2.0, np.array([1.7, 0.4]), 0.3, np.array([0.5, -0.3])
VIEW = (-4.0, 4.0, -4.0, 4.0)


def _rod_by_hand():
    r = C - P
    JP = JC + M * r @ r
    s = np.array([P[1], -P[0], 1.0])
    R = np.array([[1.0, 0.0], [0.0, 1.0], [-P[1], P[0]]])
    As = np.array([-M * r[1], M * r[0], JC + M * (C[0] * r[0] + C[1] * r[1])])
    T = As / JP
    U = np.zeros((3, 2))
    for k, ek in enumerate(np.eye(2)):
        w = -M * (r[0] * ek[1] - r[1] * ek[0]) / JP
        U[:, k] = [ek[0] + w * P[1], ek[1] - w * P[0], w]
    return s, R, T, U, JP


def _rod_inertia():
    # the rigid-body inertia at the origin, written out (4.58 with the package's column order)
    return np.array([[M, 0.0, -M * C[1]], [0.0, M, M * C[0]],
                     [-M * C[1], M * C[0], JC + M * C @ C]])


def _xy(p):
    return np.array([-p[1] / p[2], p[0] / p[2]])


# --------------------------------------------------------------------------- reading the picture
def _data(pic):
    d = pic.to_dict()
    return d, {e["id"]: e for e in d["elements"]}


def _k(d):
    """Pixels per data unit (x, y) of a picture's data."""
    x0, x1, y0, y1 = d["box"]
    w, h = d["size"]
    ml, mr, mt, mb = d["margin"]
    return (w - ml - mr) / (x1 - x0), (h - mt - mb) / (y1 - y0)


def _parts(el, kind):
    return [p for p in el["parts"] if p["p"] == kind]


def _mark(el):
    (m,) = _parts(el, "mark")
    return np.array([m["x"], m["y"]])


def _segment(el):
    (p,) = _parts(el, "path")
    return np.asarray(p["xy"], float)


def _on(l, xy, tol=1e-4):
    """The point ``xy`` satisfies the line's equation tz + y fx − x fy = 0 (4.27), relative to |F|."""
    return abs(l[2] + xy[1] * l[0] - xy[0] * l[1]) <= tol * math.hypot(l[0], l[1])


def _drawn_force(d, el, scale):
    """The wrench [fx, fy, tz] drawn by a force element: its arrow gives the force (``scale`` m/N),
    a point of its clipped line the moment (tz = x fy − y fx)."""
    kx, ky = _k(d)
    (arr,) = _parts(el, "arrow")
    F = np.array([arr["dx"] / kx, arr["dy"] / ky]) / scale
    x, y = _segment(el)[0]
    return np.array([F[0], F[1], x * F[1] - y * F[0]])


def _arrow_length(d, el):
    kx, ky = _k(d)
    (arr,) = _parts(el, "arrow")
    return math.hypot(arr["dx"] / kx, arr["dy"] / ky)


def _described(d):
    for el in d["elements"]:
        assert el["id"] and el["role"] and el.get("symbol") and el.get("desc"), el["id"]
        assert "$" not in el["symbol"] and "\\" not in el["desc"], el["id"]


# --------------------------------------------------------------------------- decomposition
def test_decomposition_hand_closed_forms():
    """Figs 6.1-6.2: T, R and U drawn where the hand forms put them; U₁ on R₂, U₂ on R₁, all on T."""
    s, R, T, U, _ = _rod_by_hand()
    A = _rod_inertia()
    pic = Picture(VIEW, size=(400, 400), ticks=False)
    out = decomposition(pic, s[:, None], R, A)
    np.testing.assert_allclose(out["values"]["T"][:, 0], T, rtol=1e-12)
    np.testing.assert_allclose(out["values"]["U"], U, atol=1e-12)
    d, els = _data(pic)
    assert set(els) == {"s", "T", "R1", "R2", "U1", "U2"}
    np.testing.assert_allclose(_mark(els["s"]), P, atol=1e-9)               # the joint
    for k in range(2):
        np.testing.assert_allclose(_mark(els[f"U{k + 1}"]), _xy(U[:, k]), atol=1e-5)
    # the drawn lines: the clipped T on the hand line, its ends on the view's edge; R through P
    seg = _segment(els["T"])
    assert all(_on(T, q) for q in seg)
    assert all(np.isclose(abs(q[0]), 4.0) or np.isclose(abs(q[1]), 4.0) for q in seg)
    for k in range(2):
        assert all(_on(R[:, k], q) for q in _segment(els[f"R{k + 1}"]))
    # Fig. 6.2's geometry on the drawn points: U₁ on R₂ (RᵀU = 1), U₂ on R₁, both on T (TᵀU = 0)
    u1, u2 = _mark(els["U1"]), _mark(els["U2"])
    assert np.isclose(u1[0], P[0]) and np.isclose(u2[1], P[1])
    assert _on(T, u1) and _on(T, u2)
    # labels are the thesis symbols, in Unicode
    assert [els[k]["symbol"] for k in ("s", "T", "R1", "U2")] == ["s", "T", "R₁", "U₂"]
    _described(d)


def test_decomposition_inverse_marks_the_percussion_poles():
    """Fig. 6.1: the plain A⁻¹R_k are the percussion poles of the reactions, also on T."""
    s, R, T, _, _ = _rod_by_hand()
    A = _rod_inertia()
    rho2 = JC / M
    # R1 is the horizontal line y = Py, d = Cy − Py below c: the pole ρ²/d above c; R2 likewise
    by_hand = [np.array([C[0], C[1] + rho2 / (C[1] - P[1])]),
               np.array([C[0] + rho2 / (C[0] - P[0]), C[1]])]
    pic = Picture(VIEW, size=(400, 400), ticks=False)
    out = decomposition(pic, s[:, None], R, A, reactive="inverse",
                        labels={"AiR1": "$I^{-1}R_1$", "s": ""})
    d, els = _data(pic)
    for k in range(2):
        p = _mark(els[f"AiR{k + 1}"])
        np.testing.assert_allclose(p, by_hand[k], atol=1e-5)
        assert _on(T, p)
        np.testing.assert_allclose(A @ out["values"]["AiR"][:, k], R[:, k], atol=1e-12)
    texts = {e["id"]: [p["text"] for p in _parts(e, "text")] for e in d["elements"]}
    assert texts["AiR1"] == ["I⁻¹R₁"] and texts["AiR2"] == ["A⁻¹R₂"] and texts["s"] == []
    _described(d)


# --------------------------------------------------------------------------- splits
def test_twist_split_is_a_equals_s_psi_plus_U_gamma():
    """(6.44, 6.76): a = sψ + Uγ, ψ = Tᵀa, γ = Rᵀa (the acceleration of P); A a = f₁ + f₂, on the drawing."""
    s, R, T, U, _ = _rod_by_hand()
    A = _rod_inertia()
    alpha, X = 1.5, np.array([2.6, -0.4])                   # α about X
    a = alpha * np.array([X[1], -X[0], 1.0])
    aP = alpha * np.array([-(P[1] - X[1]), P[0] - X[0]])    # acceleration of P: α k × (P − X)
    psi = T @ a
    pic = Picture(VIEW, size=(400, 400), ticks=False)
    out = twist_split(pic, s, R, A, a, parts=(1, 2), scale=0.2)
    v = out["values"]
    np.testing.assert_allclose(v["gamma"], aP, rtol=1e-12)  # γ = Rᵀa
    assert v["psi"][0] == pytest.approx(psi)
    np.testing.assert_allclose(v["a1"], s * psi, rtol=1e-12)
    np.testing.assert_allclose(v["a2"], U @ aP, atol=1e-12)
    d, els = _data(pic)
    # the drawn poles: a₁ at the joint, a₂ on T where U γ puts it; the pole of a = a₁ + a₂ lies on
    # the line through them (a sum of two twists lies on their join, 4.11)
    a1, a2 = _mark(els["a1"]), _mark(els["a2"])
    np.testing.assert_allclose(a1, P, atol=1e-5)
    np.testing.assert_allclose(a2, _xy(U @ aP), atol=1e-5)
    assert _on(T, a2)
    e = a2 - a1
    assert abs(e[0] * (X[1] - a1[1]) - e[1] * (X[0] - a1[0])) < 1e-5
    # the drawn forces (arrow to scale on the drawn line) add up to A a: T-part + R-part (6.76)
    f1, f2 = _drawn_force(d, els["f1"], 0.2), _drawn_force(d, els["f2"], 0.2)
    np.testing.assert_allclose(f1 + f2, A @ a, atol=1e-3)
    np.testing.assert_allclose(np.cross(f1, T), 0.0, atol=1e-3)   # f₁ = A sψ is a multiple of T
    assert _on(f2, P, 1e-4)                                       # f₂ = A Uγ passes through P
    # the rotation glyphs turn with the rates' signs
    (g1,), (g2,) = _parts(els["a1"], "glyph"), _parts(els["a2"], "glyph")
    assert g1["ccw"] == bool(psi > 0) and g2["ccw"] == bool((U @ aP)[2] > 0)
    _described(d)


def test_twist_split_draws_the_parts_asked_for():
    s, R, T, U, _ = _rod_by_hand()
    A = _rod_inertia()
    a = 1.5 * np.array([-0.4, -2.6, 1.0])
    pic = Picture(VIEW, size=(400, 400), ticks=False)
    out = twist_split(pic, s, R, A, a, parts=[1])
    assert "a2" not in out and "f2" not in out               # only the part asked for is drawn
    assert {e["id"] for e in pic.elements} == {"T", "a1", "f1"}
    pic2 = Picture(VIEW, size=(400, 400), ticks=False)
    out2 = twist_split(pic2, s, R, A, a, parts=(2,), show_T=False, prefix="B.")
    assert {e["id"] for e in pic2.elements} == {"B.a2", "B.f2"} and "T" not in out2
    d, els = _data(pic2)
    assert _on(T, _mark(els["B.a2"]))
    assert _on(_drawn_force(d, els["B.f2"], 1.0), P, 1e-4)


def test_wrench_split_is_f_equals_TQ_plus_Rmu():
    """(6.38): f = TQ + Rμ with Q = sᵀf (the moment of f about P) and μ = Uᵀf, on the drawing."""
    s, R, T, U, _ = _rod_by_hand()
    A = _rod_inertia()
    # 3 N along (1, 2)/√5 through the point (2, 1): tz = x fy - y fx
    F = 3.0 * np.array([1.0, 2.0]) / np.sqrt(5.0)
    f = np.array([F[0], F[1], 2.0 * F[1] - 1.0 * F[0]])
    Q = (2.0 - P[0]) * F[1] - (1.0 - P[1]) * F[0]           # moment about P: (x - P) × F
    mu = U.T @ f
    pic = Picture(VIEW, size=(400, 400), ticks=False)
    out = wrench_split(pic, s, R, A, f, arrow_length=0.6, anchors={"f1": (0.0, 0.0), "f2": (0.0, 0.0)})
    v = out["values"]
    assert v["Q"][0] == pytest.approx(Q)
    np.testing.assert_allclose(v["mu"], mu, rtol=1e-12)
    np.testing.assert_allclose(v["f1"], T * Q, rtol=1e-12)
    np.testing.assert_allclose(v["f2"], R @ mu, atol=1e-12)
    d, els = _data(pic)
    # arrow_length: 0.6 whatever |F|; rebuilt with each arrow's own scale, the parts add up to f
    for k, fk in (("f1", T * Q), ("f2", R @ mu)):
        assert _arrow_length(d, els[k]) == pytest.approx(0.6, abs=1e-4)
        drawn = _drawn_force(d, els[k], 0.6 / math.hypot(*fk[:2]))
        np.testing.assert_allclose(drawn, fk, atol=1e-4)
    f1 = _drawn_force(d, els["f1"], 0.6 / math.hypot(*(T * Q)[:2]))
    f2 = _drawn_force(d, els["f2"], 0.6 / math.hypot(*(R @ mu)[:2]))
    np.testing.assert_allclose(f1 + f2, f, atol=1e-4)
    assert _on(f2, P, 1e-4)                                      # Rμ passes through the joint
    # a₁ = A⁻¹TQ turns about the joint; a₂ = A⁻¹Rμ lies on T
    np.testing.assert_allclose(_mark(els["a1"]), P, atol=1e-5)
    assert _on(T, _mark(els["a2"]))
    np.testing.assert_allclose(A @ v["a1"], T * Q, atol=1e-12)
    _described(d)


def test_parts_alone_match_the_drawn_values():
    s, R, _, _, _ = _rod_by_hand()
    A = _rod_inertia()
    f = np.array([1.0, -2.0, 0.5])
    pic = Picture(VIEW, size=(300, 300), ticks=False)
    drawn = wrench_split(pic, s, R, A, f)["values"]
    for k, v in wrench_parts(s, R, A, f).items():
        np.testing.assert_array_equal(v, drawn[k])
    a = np.array([0.3, 0.2, -1.0])
    drawn = twist_split(Picture(VIEW, size=(300, 300)), s, R, A, a)["values"]
    for k, v in twist_parts(s, R, A, a).items():
        np.testing.assert_array_equal(v, drawn[k])


# --------------------------------------------------------------------------- projective step
def test_projective_step_joint_acceleration():
    """(6.98–6.101): q̈ = Tᵀaᵢ − Tᵀ(aᵢ₋₁ + κ); with aᵢ = aᵢ₋₁ + κ + s q̈ this is q̈ (sᵀT = 1)."""
    s, R, T, U, _ = _rod_by_hand()
    A = _rod_inertia()
    a_prev = 0.7 * np.array([1.0, -2.0, 1.0])
    kap = np.array([0.4, -0.9, 0.0])                        # a translation (an ideal point)
    qdd = -1.3
    a = a_prev + kap + s * qdd
    pic = Picture(VIEW, size=(400, 400), ticks=False)
    out = projective_step(pic, s, R, A, a_prev, a, kap)
    assert out["values"]["qdd"][0] == pytest.approx(qdd)
    assert out["values"]["psi"][0] == pytest.approx(T @ a)
    assert out["values"]["psi_prev"][0] == pytest.approx(T @ a_prev)
    d, els = _data(pic)
    assert all(_on(T, q) for q in _segment(els["T"]))
    np.testing.assert_allclose(_mark(els["s"]), P, atol=1e-5)
    np.testing.assert_allclose(_mark(els["a"]), _xy(a), atol=1e-5)
    np.testing.assert_allclose(_mark(els["a_prev"]), _xy(a_prev), atol=1e-5)
    assert [els[k]["symbol"] for k in ("T", "s", "a_prev", "a")] == ["Tᵢ", "sᵢ", "aᵢ₋₁", "aᵢ"]
    assert "-1.3 rad/s²" in els["a"]["desc"]
    _described(d)


# --------------------------------------------------------------------------- bad input
def test_bad_input_is_refused_by_name_and_draws_nothing():
    s, R, _, _, _ = _rod_by_hand()
    A = _rod_inertia()
    pic = Picture(VIEW, size=(300, 300))
    with pytest.raises(InputError, match="reactive"):
        decomposition(pic, s, R, A, reactive="V")
    with pytest.raises(InputError, match="parts"):
        twist_split(pic, s, R, A, [0.0, 0.0, 1.0], parts=(3,))
    with pytest.raises(InputError, match="parts"):
        wrench_split(pic, s, R, A, [0.0, 1.0, 0.0], parts=())
    with pytest.raises(NonFiniteError, match="a"):
        twist_split(pic, s, R, A, [0.0, np.nan, 1.0])
    with pytest.raises(ShapeError, match="f must"):
        wrench_split(pic, s, R, A, [1.0, 2.0])
    with pytest.raises(ShapeError, match="kappa"):
        projective_step(pic, s, R, A, np.zeros(3), np.zeros(3), np.zeros(2))
    with pytest.raises(InputError, match="names"):
        projective_step(pic, s, R, A, np.zeros(3), np.zeros(3), np.zeros(3), names=("T", "s"))
    with pytest.raises(InputError, match="Picture"):
        decomposition(None, s, R, A)
    with pytest.raises(InputError):                         # sᵀR ≠ 0: not a joint's spaces
        decomposition(pic, s, np.array([[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]), A)
    assert pic.elements == []
