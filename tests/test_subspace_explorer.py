"""SubspaceExplorer (thesis 6.1–6.4, 6.63–6.97) driven through its controls and drags, against hand numbers.

The references are written here by hand (Newton–Euler about the centre of mass, moments about the
pivot, thesis example 6.9's closed forms), never with the package's subspace functions.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from _picture_checks import elements, problems
from planargeo.widgets import SubspaceExplorer
from planargeo.widgets.subspace import CHECK_ROWS, CHECKS_HEADING, COM, JOINT_OPTIONS, SHOW_OPTIONS

RESIDUALS = ["sᵀT − 1", "RᵀU − 1", "TᵀU", "T sᵀ + R Uᵀ − 1", "sᵀR", "(sψ)ᵀ(Rμ)", "(Uγ)ᵀ(TQ)", "Rᵀ(sψ)"]


def unit(deg):
    return np.array([math.cos(math.radians(deg)), math.sin(math.radians(deg))])


def cross2(a, b):
    return a[0] * b[1] - a[1] * b[0]


def legible(ex):
    """Every element of the picture has its symbol and description; no two labels overlap."""
    found = problems(ex.picture())
    assert found == [], found


def residuals_print_as_zero(ex):
    assert ex.readout_values[CHECKS_HEADING] == "" and CHECKS_HEADING.endswith("(each reads 0)")
    for name in RESIDUALS:
        row = CHECK_ROWS[name][0]
        assert ex.readout_strings[row].split()[0] == "0", (name, ex.readout_strings)
        assert abs(ex.readout_values[row]) < 1e-12


@pytest.fixture
def ex():
    return SubspaceExplorer(display="agg")


def revolute_by_hand(v):
    """Moment about the pivot, J_P, ψ = Q / J_P, and the pivot's push on the body (Newton: m a_c − F)."""
    m, rho = v["m"], v["rho"]
    p = np.array([v["joint x"], v["joint y"]])
    a = np.array([v["force x"], v["force y"]])
    F = v["F"] * unit(v["force angle"])
    c = np.array(COM)
    Q = cross2(a - p, F)
    JP = m * rho ** 2 + m * (c - p) @ (c - p)
    alpha = Q / JP
    ac = alpha * np.array([-(c - p)[1], (c - p)[0]])
    push = m * ac - F
    return Q, JP, alpha, push


def test_every_joint_and_view_is_legible_and_its_power_relations_read_zero(ex):
    for label in JOINT_OPTIONS:
        for show in SHOW_OPTIONS:
            ex.set(joint=label, show=show)
            assert ex.message == ""
            assert ex.readout_values["joint"] == label
            residuals_print_as_zero(ex)
            legible(ex)


@pytest.mark.parametrize("show", list(SHOW_OPTIONS))
def test_revolute_numbers_by_hand_after_dragging_the_joint_and_the_force(ex, show):
    ex.set(show=show)
    ex.drag("joint", (0.0, 0.0), (0.4567, -0.3211), steps=7)           # off the slider grid: no snapping
    assert (ex.values["joint x"], ex.values["joint y"]) == (0.4567, -0.3211)
    ex.drag("force point", (1.6, 0.0), (2.1, 0.45), steps=5)
    Q, JP, alpha, push = revolute_by_hand(ex.values)
    r = ex.readout_values
    assert r["Q = sᵀf"] == pytest.approx(Q, rel=1e-12)
    assert r["ψ = TᵀI⁻¹f"] == pytest.approx(alpha, rel=1e-12)
    assert r["sᵀIs (6.67)"] == pytest.approx(JP, rel=1e-12)
    assert r["joint's push −Rμ, |force|"] == pytest.approx(float(np.hypot(*push)), rel=1e-12)
    assert r["pole of sψ (held body)"] == pytest.approx((0.4567, -0.3211), abs=1e-12)
    np.testing.assert_allclose(ex.state["reaction"][:2], push, atol=1e-12)
    assert ex.units["Q = sᵀf"] == "N·m" and ex.units["ψ = TᵀI⁻¹f"] == "rad/s²"
    residuals_print_as_zero(ex)
    legible(ex)


def test_force_tip_drag_sets_angle_and_magnitude(ex):
    x0, y0 = ex.handles()[3].where()
    ex.drag("force tip", (x0, y0), (1.6 + 0.3, 0.4), steps=4)          # from the point (1.6, 0): (0.3, 0.4)
    assert ex.values["force angle"] == pytest.approx(math.degrees(math.atan2(0.4, 0.3)), rel=1e-12)
    assert ex.values["F"] == pytest.approx(2 * 0.5 / 0.5, rel=1e-12)   # |tip − point| = ARROW F / 2
    Q, *_ = revolute_by_hand(ex.values)
    assert ex.readout_values["Q = sᵀf"] == pytest.approx(Q, rel=1e-12)
    legible(ex)


def test_prismatic_slide_by_hand(ex):
    ex.set(joint="prismatic", **{"joint angle": 30.0, "force angle": -160.0, "F": 2.5})
    v = ex.values
    e = unit(30.0)
    F = 2.5 * unit(-160.0)
    r = ex.readout_values
    assert r["Q = sᵀf"] == pytest.approx(F @ e, rel=1e-12)                 # the force's part along the slide
    assert r["ψ = TᵀI⁻¹f"] == pytest.approx(F @ e / v["m"], rel=1e-12)     # m ẍ = F·e (Lagrange)
    assert r["sᵀIs (6.67)"] == pytest.approx(v["m"], rel=1e-12) and ex.units["sᵀIs (6.67)"] == "kg"
    # a translation along the slide at 30°: its pole is at infinity, across the slide (5.49)
    assert r["pole of sψ (held body)"] in ("at infinity (direction (-0.5, 0.866))",
                                           "at infinity (direction (0.5, -0.866))")
    assert ex.units["Q = sᵀf"] == "N" and ex.units["μ₂ = U₂ᵀf"] == "N·m"
    legible(ex)


@pytest.mark.parametrize("label", ["revolute + prismatic", "plane joint (4.79)"])
def test_two_dof_joints_line_of_poles_and_pencil_of_T(ex, label):
    ex.set(joint=label, **{"joint angle": -35.0, "joint x": 0.3, "joint y": 0.2, "force angle": 70.0})
    st = ex.state
    # the held body's acceleration by Lagrange at rest (generalized coordinates by hand)
    v = ex.values
    e = unit(-35.0)
    n = np.array([-e[1], e[0]])
    p = np.array([0.3, 0.2])
    c = np.array(COM)
    m, J = v["m"], v["m"] * v["rho"] ** 2
    a_pt = np.array([v["force x"], v["force y"]])
    F = v["F"] * unit(70.0)
    if label == "revolute + prismatic":
        Jc = np.array([e, [-(c - p)[1], (c - p)[0]]]).T
        Jb = np.array([e, [-(a_pt - p)[1], (a_pt - p)[0]]]).T
        Jt = np.array([[0.0, 1.0]])
    else:
        Jc = Jb = np.array([e, n]).T
        Jt = np.array([[0.0, 0.0]])
    qdd = np.linalg.solve(m * Jc.T @ Jc + J * Jt.T @ Jt, Jb.T @ F)
    a = st["s_psi"]
    np.testing.assert_allclose([a[0] - a[2] * c[1], a[1] + a[2] * c[0]], Jc @ qdd, atol=1e-12)
    assert a[2] == pytest.approx((Jt @ qdd)[0], abs=1e-12)
    # the points of s span the reaction line R; the held pole lies on it; T₁, T₂ meet at U (the readout)
    R = st["R"][:, 0]
    for i in range(2):
        assert abs(st["s"][:, i] @ R) < 1e-12
    assert abs(a @ R) < 1e-12
    U = st["U"][:, 0]
    meet = np.cross(st["T"][:, 0], st["T"][:, 1])
    np.testing.assert_allclose(np.cross(meet, U), 0.0, atol=1e-12)
    if U[2] != 0:
        assert ex.readout_values["U (meet of T₁, T₂)"] == pytest.approx((-U[1] / U[2], U[0] / U[2]), abs=1e-12)
    if label == "plane joint (4.79)":                       # U is the spin about the centre of mass
        assert ex.readout_values["U (meet of T₁, T₂)"] == pytest.approx(COM, abs=1e-12)
    residuals_print_as_zero(ex)
    for show in SHOW_OPTIONS:
        ex.set(show=show)
        legible(ex)


def test_thesis_example_6_9_in_the_explorer(ex):
    """A small car (L = 1, d = 1.5, ε = 0.45, ρ = 0.5, m = 2) at rest, the ICR as the revolute joint: T (6.125),
    ω̇ (6.131) and the tyre forces μ (6.133, in the car's basis of 6.114) at ω = 0."""
    L, d, eps, rho, m, FA = 1.0, 1.5, 0.45, 0.5, 2.0, 1.0
    icr = np.array(COM) - np.array([d, (1 - eps) * L])
    front = icr + np.array([d, L])
    ex.set(**{"joint x": icr[0], "joint y": icr[1], "force x": front[0], "force y": front[1],
              "force angle": math.degrees(math.atan2(d, -L)), "F": FA, "m": m, "rho": rho})
    assert ex.message == ""
    D = rho ** 2 + d ** 2 + (1 - eps) ** 2 * L ** 2
    h = math.hypot(d, L)
    assert ex.readout_values["ψ = TᵀI⁻¹f"] == pytest.approx(FA / m * h / D, rel=1e-12)          # 6.131
    assert ex.readout_values["Q = sᵀf"] == pytest.approx(h * FA, rel=1e-12)                       # 6.120
    # T at the ICR (6.125) is T at the origin moved: the same line, moment 1 about the ICR
    T = ex.state["T"][:, 0]
    T_icr = np.array([T[0], T[1], T[2] - cross2(icr, T[:2])])
    np.testing.assert_allclose(T_icr, [-(1 - eps) * L / D, d / D, 1.0], rtol=1e-12, atol=1e-15)
    # the joint's force on the car in the car's tyre basis: R_car μ_car = reaction (6.121-6.123, Q = 0)
    reaction = ex.state["reaction"]
    R_car = np.array([[1.0, d / h], [0.0, L / h]])                  # force parts; both lines pass the ICR
    mu_car = np.linalg.solve(R_car, reaction[:2])
    np.testing.assert_allclose(mu_car, [-(eps * (1 - eps) * L ** 2 - rho ** 2) / D * h / L * FA,
                                        (eps * (2 - eps) * L ** 2 - rho ** 2) / D * d / L * FA], rtol=1e-11)
    assert reaction[2] - cross2(icr, reaction[:2]) == pytest.approx(0.0, abs=1e-13)   # through the ICR
    legible(ex)


def test_drag_to_a_singular_direction_keeps_the_last_good_state(ex):
    ex.set(joint="prismatic", **{"joint angle": 0.0})
    start = ex.handles()[1].where()
    assert start == pytest.approx((0.7, 0.0))
    ex.drag("joint direction", start, (0.35, 0.35), steps=1)            # a good step first: 45°
    shown, readout = dict(ex.values), dict(ex.readout_values)
    assert shown["joint angle"] == pytest.approx(45.0)
    ex.drag("joint direction", (0.35, 0.35), (0.0, 0.0), steps=1)       # onto the joint: no direction
    assert "joint direction cannot be on the arrow's foot" in ex.message
    assert ex.values == shown and ex.readout_values == readout
    ex.drag("joint direction", (0.0, 0.0), (0.0, 0.5), steps=1)         # and on again
    assert ex.message == "" and ex.values["joint angle"] == pytest.approx(90.0)
    legible(ex)


def test_zero_force_is_refused_by_name(ex):
    ex.set(F=0.0)
    assert "F must be non-zero" in ex.message or "force must be non-zero" in ex.message
    assert ex.values["F"] == 1.0
    tip = ex.handles()[3].where()
    ex.drag("force tip", tip, (1.6, 0.0), steps=2)
    assert "force F would be 0" in ex.message and ex.values["F"] != 0.0


def test_revolute_has_no_direction_handle_and_exports(ex, tmp_path):
    names = [h.name for h in ex.handles()]
    assert names == ["joint", "joint direction", "force point", "force tip"]
    assert ex.handles()[1].where() is None
    assert ex.export_svg(tmp_path / "s.svg").stat().st_size > 1000
    assert ex.export_png(tmp_path / "s.png").read_bytes()[:4] == b"\x89PNG"


# ---------------------------------------------------------------- issue 22: checks named, symbols explained
def test_identity_rows_are_labelled_as_checks_with_their_reason(ex):
    names = list(ex.readout_values)
    head = names.index(CHECKS_HEADING)
    checks = names[head + 1:]
    assert len(checks) == 8 and all(n.startswith("check ") and n.endswith("→ 0") for n in checks)
    meanings = ex.explain()
    for n in checks:                                     # each says why it must read 0, with an equation
        assert "(6." in meanings[n], n
    # the identities hold by independent arithmetic on s, R, T, U of the scene (6.1, 6.23, 6.22, 6.46)
    st = ex.state
    s, R, T, U = st["s"], st["R"], st["T"], st["U"]
    assert np.allclose(s.T @ T, np.eye(1)) and np.allclose(R.T @ U, np.eye(2))
    assert np.allclose(T.T @ U, 0.0) and np.allclose(s.T @ R, 0.0)


@pytest.mark.parametrize("joint", list(JOINT_OPTIONS))
def test_every_row_has_a_meaning_and_numbers_a_unit(ex, joint):
    ex.set(joint=joint)
    meanings = ex.explain()
    for k, v in ex.readout_values.items():
        assert k in meanings, k
        assert "_" not in k, k
        if isinstance(v, tuple) and all(isinstance(x, float) for x in v) and k != "sᵀIs (6.67)":
            assert ex.units[k] not in ("", "—"), k
    if JOINT_OPTIONS[joint] == "revolute_prismatic":
        # one unit per entry of the 2×2 joint-space inertia: rotation–rotation kg·m², mixed kg·m
        assert sorted(ex.units["sᵀIs (6.67)"]) == sorted(("kg", "kg·m", "kg·m", "kg·m²"))


def test_a_revolute_joint_has_no_direction_to_turn(ex):
    assert "revolute" in ex.disabled(ex.values)["joint angle"]
    before = dict(ex.readout_values)
    ex.set(**{"joint angle": 45.0})
    assert ex.readout_values == before
    ex.set(joint="prismatic")
    assert "joint angle" not in ex.disabled(ex.values)


def test_the_view_holds_every_handle_and_depends_on_the_values_only(ex):
    # a 4 N force at the right edge pointing right: its tip at x = 3.4 + 4 · ARROW / 2 = 4.4
    ex.set(**{"force x": 3.4, "force y": 1.9, "force angle": 0.0, "F": 4.0})
    tip = ex.handles()[3].where()
    assert tip == pytest.approx((4.4, 1.9))
    x0, x1, y0, y1 = ex.picture()["box"]
    for x, y in ex.mechanism_points():
        assert x0 < x < x1 and y0 < y < y1
    fresh = SubspaceExplorer(display="agg", **ex.values)
    assert fresh.picture()["box"] == [x0, x1, y0, y1]
    assert fresh.readout_strings == ex.readout_strings
    ex.reset()
    assert ex.picture()["box"] == SubspaceExplorer(display="agg").picture()["box"]
