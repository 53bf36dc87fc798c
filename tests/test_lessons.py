"""What the lessons (notebooks/01-…-12-…) say, checked here against independent values.

The notebooks show numbers beside the values they should have; the checks that used to be ``assert``
statements in the notebooks live here, each against a value computed another way (by hand, a closed
form re-derived in the comment, Newton–Euler written out, a finite difference, Lagrange multipliers).
The first part checks the lessons' form: at least 1,200 words of prose, at least three exercises,
each with a solution in a collapsible ``<details>`` block, "What you will learn" and a summary.
"""
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
LESSONS = sorted(p for p in (ROOT / "notebooks").glob("[01][0-9]-*.ipynb") if p.name != "00-tour.ipynb")


# --------------------------------------------------------------------------------------- the form
def markdown(path) -> str:
    nb = json.loads(path.read_text(encoding="utf-8"))
    return "\n\n".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown")


def prose_words(md: str) -> int:
    """Words of prose: markdown without code blocks, display equations and HTML tags."""
    md = re.sub(r"```.*?```", " ", md, flags=re.S)
    md = re.sub(r"\$\$.*?\$\$", " ", md, flags=re.S)
    md = re.sub(r"</?(details|summary)[^>]*>", " ", md)
    return sum(1 for w in md.split() if re.search(r"[A-Za-z0-9]", w))


def exercises(md: str) -> list[tuple[str, bool]]:
    """``[(number, has a solution)]``: each **Exercise N** followed by a <details> block before the next."""
    parts = re.split(r"\*\*Exercise (\d+)", md)
    return [(parts[i], "<details>" in parts[i + 1] and "</details>" in parts[i + 1]
             and "Solution" in parts[i + 1]) for i in range(1, len(parts), 2)]


def lesson_table():
    """(name, prose words, exercises, with solutions) per lesson: the closing note's table."""
    rows = []
    for p in LESSONS:
        md = markdown(p)
        ex = exercises(md)
        rows.append((p.name, prose_words(md), len(ex), sum(ok for _, ok in ex)))
    return rows


def test_twelve_lessons():
    assert len(LESSONS) == 12, [p.name for p in LESSONS]


@pytest.mark.parametrize("path", LESSONS, ids=lambda p: p.name)
def test_lesson_form(path):
    md = markdown(path)
    assert "What you will learn" in md and "## Summary" in md
    assert prose_words(md) >= 1200, prose_words(md)
    ex = exercises(md)
    assert len(ex) >= 3 and all(ok for _, ok in ex), ex
    assert [n for n, _ in ex] == [str(k) for k in range(1, len(ex) + 1)]
    assert "Explorer" in "".join("".join(c["source"]) for c in json.loads(path.read_text())["cells"]
                                 if c["cell_type"] == "code"), "an explorer to play with"


def test_the_word_counter_counts_prose_only():
    md = "Two words\n\n```python\nx = 1 + 2 + 3\n```\n$$ a + b = c $$ <details><summary>Solution</summary>three more words</details>"
    assert prose_words(md) == 6
    assert exercises("**Exercise 1** a <details><summary>Solution</summary>x</details> **Exercise 2** b") == \
        [("1", True), ("2", False)]


# ------------------------------------------------------------------ lesson 1: screws as points and lines
def test_lesson1_twist_is_its_pole():
    import planargeo as pg
    v = pg.Twist.rotation((1.0, 2.0), omega=3.0)
    # by hand: v_O = ω k × (O − P) = 3 k × (−1, −2) = 3 (2, −1)
    np.testing.assert_allclose(v.array, [6.0, -3.0, 3.0], atol=1e-15)
    np.testing.assert_allclose(v.pole.xy, [1.0, 2.0], atol=1e-15)
    # exercise 1: both twists have the pole (1, 2)
    for arr in ([4.0, -2.0, 2.0], [-6.0, 3.0, -3.0]):
        vx, vy, w = arr
        np.testing.assert_allclose(pg.Twist(arr).pole.xy, [-vy / w, vx / w])
        np.testing.assert_allclose(pg.Twist(arr).pole.xy, [1.0, 2.0])
    # a translation is an ideal point
    assert pg.Twist.translation((0.0, 2.0)).array[2] == 0


def test_lesson1_power_is_incidence():
    import planargeo as pg
    v = pg.Twist.rotation((1.0, 2.0), omega=3.0)
    f = pg.Wrench.force((1.0, 2.0), (0.5, -1.0))
    fx, fy, tz = f.array
    assert math.isclose(tz + 2.0 * fx - 1.0 * fy, 0.0, abs_tol=1e-12)        # (1, 2) on the line (4.27)
    assert abs(float(v @ f)) < 1e-12
    g = pg.Wrench.force((0.0, 0.0), (0.0, 1.0))
    # ω × moment about the pole: 3 × ((0 − 1)·1 − (0 − 2)·0)
    assert math.isclose(float(v @ g), -3.0)
    # exercise 4: the best unit force through O is perpendicular to OP, power 3√5
    e = np.array([2.0, -1.0]) / math.sqrt(5)
    assert math.isclose(float(v @ pg.Wrench.force((0.0, 0.0), e)), 3 * math.sqrt(5))
    angles = np.linspace(0, 2 * np.pi, 721)
    best = max(float(v @ pg.Wrench.force((0.0, 0.0), (math.cos(a), math.sin(a)))) for a in angles)
    assert best <= 3 * math.sqrt(5) + 1e-12


def test_lesson1_sums():
    import planargeo as pg
    s = pg.add_twists(pg.Twist.rotation((0.0, 0.0), 1.0), pg.Twist.rotation((3.0, 0.0), 2.0))
    np.testing.assert_allclose(pg.to_xy(s.P), [(1 * 0 + 2 * 3) / 3, 0.0])     # lever rule by hand
    assert s.omega3 == 3.0 and math.isclose(s.beta, 2 / 3)
    w = pg.add_wrenches(pg.Wrench.force((0.0, 0.0), (1.0, 0.0)), pg.Wrench.couple(2.0))
    # 4.27 for [1, 0, 2]: 2 + y = 0
    assert w.sum.line.incidence(pg.Point.from_xy(5.0, -2.0)) == pytest.approx(0.0, abs=1e-12)
    assert w.rho == 2.0
    # exercise 3: (1, 0) through O plus (−1, 0) through (0, 2) is a couple of 2
    c = pg.Wrench.force((0.0, 0.0), (1.0, 0.0)) + pg.Wrench.force((0.0, 2.0), (-1.0, 0.0))
    np.testing.assert_allclose(c.array, [0.0, 0.0, 2.0], atol=1e-15)


def test_lesson1_screw_sum_explorer():
    from planargeo.widgets import ScrewSumExplorer
    ex = ScrewSumExplorer(display="agg")
    # 1 rad/s about (−1.5, 0) plus 2 rad/s about (1.5, 0.5): weighted mean of the poles
    np.testing.assert_allclose(ex.readout_values["pole of sum"], (0.5, 1 / 3))
    np.testing.assert_allclose(ex.readout_values["sum"], 3.0 * np.array([1 / 3, -0.5, 1.0]))
    ex.set(x1=-1.0, y1=0.0, size1=1.0, x2=2.0, y2=0.0, size2=2.0)
    np.testing.assert_allclose(ex.readout_values["pole of sum"], ((1 * -1.0 + 2 * 2.0) / 3, 0.0))
    ex.set(size2=-1.0)                                    # exercise 2: opposite rotations
    ro = ex.readout_values
    assert ro["case"] == "opposite rotations (4.13)"
    # by hand, [y, -x, 1] per unit rotation: 1·[0, 1, 1] − 1·[0, -2, 1] = [0, 3, 0], a translation up
    sum_ = np.array(ro["sum"], dtype=float)
    np.testing.assert_allclose(sum_, [0.0, 3.0, 0.0], atol=1e-12)
    from planargeo.geometry.projective import is_ideal
    assert is_ideal(sum_)
    # its pole is the point at infinity along Q1Q2 (the x axis), perpendicular to the translation
    assert ro["pole of sum"].startswith("at infinity (direction (")
    dx, dy = (float(t) for t in ro["pole of sum"].split("direction (")[1].rstrip(")").split(","))
    assert math.isclose(abs(dx), 1.0) and dy == 0.0


# ---------------------------------------------------- lesson 2: kinematics and equations of motion drawn
def _arm():
    from planargeo.algorithms.rnea import newton_euler
    from planargeo.widgets.chain import chain_for
    return newton_euler(chain_for(2, gravity=False), np.zeros(2), np.array([1.0, 2.0]), np.zeros(2))


def test_lesson2_arm_velocities_by_the_lever_rule():
    import planargeo as pg
    w = _arm()
    np.testing.assert_allclose(pg.to_xy(w.v[0]), [0.0, 0.0], atol=1e-15)
    # 4.48: β = q̇2/(q̇2 + ω1) = 2/3 of k = 1; ω2 = 3
    np.testing.assert_allclose(pg.to_xy(w.v[1]), [2 / 3, 0.0], atol=1e-15)
    assert w.v[1][2] == 3.0
    # exercise 1: a pole at 0.8 means q̇2 = 4: the joint point moves at 1 m/s both ways
    beta = 0.8
    qd2 = beta * 1.0 / (1 - beta)
    assert math.isclose((1.0 + qd2) * (1 - beta), 1.0)


def test_lesson2_bias_and_material_acceleration():
    w = _arm()
    np.testing.assert_allclose(w.kappa[1], [2.0, 0.0, 0.0], atol=1e-14)    # size ω1 q̇2 k2 = 2 (4.53)
    np.testing.assert_allclose(w.a[1], w.kappa[1], atol=1e-14)             # q̈ = 0, a1 = 0
    # the tip's acceleration by finite differences of its position along the motion
    def tip(t):
        th1 = 1.0 * t
        th2 = th1 + 2.0 * t
        return np.array([math.cos(th1) + math.cos(th2), math.sin(th1) + math.sin(th2)])
    h = 1e-4
    acc_fd = (tip(h) - 2 * tip(0.0) + tip(-h)) / h**2
    a, v = w.a[1], w.v[1]
    r = np.array([2.0, 0.0])
    v_tip = np.array([v[0] - v[2] * r[1], v[1] + v[2] * r[0]])
    material = np.array([a[0] - a[2] * r[1], a[1] + a[2] * r[0]]) + v[2] * np.array([-v_tip[1], v_tip[0]])
    np.testing.assert_allclose(material, acc_fd, atol=1e-5)
    np.testing.assert_allclose(acc_fd, [-10.0, 0.0], atol=1e-5)


def test_lesson2_centripetal_force():
    import planargeo as pg
    w = _arm()
    p2 = pg.bias_force(w.I[1], w.v[1])
    np.testing.assert_allclose(p2, [-(1.5 - 2 / 3) * 9.0, 0.0, 0.0], atol=1e-13)   # m l ω², toward the pole


def test_lesson2_pendulum_in_the_explorer():
    from planargeo.widgets import ChainExplorer
    ex = ChainExplorer(display="agg", links=1, angle=-30, speed=1.0)
    ro = ex.readout_values
    q = math.radians(-30)
    assert math.isclose(ro["kinetic energy (J)"], 0.5 * (1 / 3) * 1.0**2)              # ½ (m L²/3) q̇²
    assert math.isclose(ro["potential energy (J)"], 9.81 * 0.5 * math.sin(q))          # m g y_c
    alpha = -9.81 * 0.5 * math.cos(q) / (1 / 3)
    assert math.isclose(ro["q̈₁"], alpha)                                              # moment / inertia
    # exercise 4: the pin force from Newton for the centre of mass
    r = 0.5 * np.array([math.cos(q), math.sin(q)])
    a_cg = alpha * np.array([-r[1], r[0]]) - 1.0 * r
    pin = a_cg - np.array([0.0, -9.81])
    assert math.isclose(ro["|base force| (N)"], math.hypot(*pin), rel_tol=1e-9)
    np.testing.assert_allclose(pin, [-3.619, 4.542], atol=1e-3)


def test_lesson2_arm_in_the_explorer():
    import planargeo as pg
    from planargeo.widgets import ChainExplorer
    ex = ChainExplorer(display="agg", links=2, gravity=False,
                       **{"joint values (deg / m)": "0, 0", "joint speeds": "1, 2"})
    np.testing.assert_allclose(pg.to_xy(ex.state["w"].v[1]), [2 / 3, 0.0], atol=1e-12)
    ex.set(**{"joint speeds": "1, -1"})                 # exercise 2: link 2 translates
    assert abs(ex.state["w"].v[1][2]) < 1e-15


# ------------------------------------------------------------ lesson 3: projective geometry and conics
def test_lesson3_join_and_meet_by_hand():
    import planargeo as pg
    l = pg.join(pg.from_xy([0.0, 0.0]), pg.from_xy([2.0, 1.0]))
    m = pg.join(pg.from_xy([0.0, 1.0]), pg.from_xy([1.0, 1.0]))
    np.testing.assert_allclose(pg.to_xy(pg.meet(l, m)), [2.0, 1.0])
    # exercise 4 in standard coordinates [1, x, y], by hand
    L = np.cross([1.0, 0, 0], [1.0, 2.0, 1.0])
    np.testing.assert_allclose(L, [0.0, -1.0, 2.0])
    X = np.cross(L, [-1.0, 0.0, 1.0])
    np.testing.assert_allclose(X / X[0], [1.0, 2.0, 1.0])
    assert pg.meet(m, pg.join(pg.from_xy([0.0, 3.0]), pg.from_xy([5.0, 3.0])))[2] == 0


def test_lesson3_polar_of_a_circle_is_the_inversion():
    import planargeo as pg
    from planargeo.geometry.conics import conic_circle
    r, d = 1.5, 3.0
    C = conic_circle([0.0, 0.0], r)
    P = pg.from_xy([d, 0.0])
    L = pg.polar(C, P)
    assert abs(pg.from_xy([r**2 / d, 7.0]) @ L) < 1e-12 and abs(pg.from_xy([r**2 / d, -2.0]) @ L) < 1e-12
    # contact points: where the circle meets x = r²/d, y = ±√(r² − x²)
    _, X = pg.tangents_from_point(C, P)
    ys = sorted(pg.to_xy(Xk)[1] for Xk in X)
    np.testing.assert_allclose(ys, [-math.sqrt(r**2 - (r**2 / d)**2), math.sqrt(r**2 - (r**2 / d)**2)])
    # exercise 2: a point on the circle maps to its tangent (x = 1.5)
    T = pg.polar(C, pg.from_xy([r, 0.0]))
    assert abs(pg.from_xy([r, 5.0]) @ T) < 1e-12


def test_lesson3_ideal_elements_and_decomposition():
    import planargeo as pg
    from planargeo.geometry.conics import conic_ellipse
    E = conic_ellipse([1.0, -0.5], [2.0, 1.0], 0.4)
    c = pg.centre(E)
    np.testing.assert_allclose(pg.to_xy(c), [1.0, -0.5], atol=1e-12)
    for direction in ([1.0, 0.0], [0.3, 2.0]):
        ideal = np.array([direction[1], -direction[0], 0.0])
        assert abs(pg.polar(E, ideal) @ c) < 1e-12
    p_inf = pg.pole(E, [0.0, 0.0, 1.0])
    np.testing.assert_allclose(p_inf / p_inf[2], c / c[2])
    u = pg.decompose_point([1.0, 2.0, 3.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 1.0])
    np.testing.assert_allclose(u, [-2.0, -1.0, 3.0])                       # by hand
    lam = math.radians(30)                                                 # exercise 3 (5.62-5.63)
    s = np.array([math.cos(lam), math.sin(lam), 0.0])
    R = np.array([[-math.sin(lam), 0.0], [math.cos(lam), 0.0], [0.0, 1.0]])
    np.testing.assert_allclose(s @ R, 0.0, atol=1e-16)


def test_lesson3_projective_explorer():
    from planargeo.widgets import ProjectiveExplorer
    ex = ProjectiveExplorer(display="agg")
    ex.set(**{"conic": "circle", "a": 1.5, "P x": 3.0, "P y": 0.0})
    ro = ex.readout_values
    assert math.isclose(ro["polar of P: distance to origin"], 1.5**2 / 3.0)
    assert math.isclose(ro["P·M"], ro["pole(M)·polar(P)"], rel_tol=1e-12)


# ---------------------------------------------------- lesson 4: inertia as a conic, axis of percussion
def test_lesson4_axis_of_percussion_from_newton():
    import planargeo as pg
    m, rho, d, alpha = 2.0, 0.5, 1.0, 3.0
    body = pg.Inertia.from_mass(m, com=(d, 0.0), radius_of_gyration=rho)
    f = body.percussion_axis_array(alpha * pg.from_xy([0.0, 0.0]))
    # Newton: the centre of mass accelerates at d α along y; moment about the pivot J_pivot α
    np.testing.assert_allclose(f[:2], [0.0, m * d * alpha], atol=1e-14)
    assert math.isclose(f[2], m * (rho**2 + d**2) * alpha)
    assert math.isclose(f[2] / f[1], d + rho**2 / d)                       # 5.67
    c = body.percussion_axis_array(pg.from_xy([d, 0.0]))                    # pole at c: a couple
    np.testing.assert_allclose(c[:2], 0.0, atol=1e-14)
    assert c[2] != 0
    t = body.percussion_axis_array([1.0, 0.0, 0.0])                         # translation along x
    assert abs(pg.from_xy([d, 0.0]) @ t) < 1e-14                            # through the centre of mass


def test_lesson4_door_and_bat():
    import planargeo as pg
    W = 0.9
    door = pg.Inertia.from_mass(10.0, com=(W / 2, 0.0), radius_of_gyration=W / math.sqrt(12))
    axis = door.percussion_axis(pg.Point.from_xy(0.0, 0.0))
    assert axis.incidence(pg.Point.from_xy(2 * W / 3, 3.0)) == pytest.approx(0.0, abs=1e-13)
    # exercise 2: door 12 kg + handle 3 kg at the free edge; l = J_hinge / (m d) by hand = 0.7
    from planargeo.screws.twists import inertia_matrix
    both = inertia_matrix(12.0, (W / 2, 0.0), 12.0 * W**2 / 12) + inertia_matrix(3.0, (W, 0.0), 0.0)
    ax2 = pg.percussion_axis(both, pg.from_xy([0.0, 0.0]))
    assert math.isclose(ax2[2] / ax2[1], (12 * W**2 / 3 + 3 * W**2) / (15 * 0.54))
    assert math.isclose(ax2[2] / ax2[1], 0.7)


def test_lesson4_power_relations():
    import planargeo as pg
    body = pg.Inertia.from_mass(2.0, com=(1.0, 0.0), radius_of_gyration=0.5)
    v = pg.from_xy([0.0, 0.0])
    h = body.matrix @ v
    a = pg.from_xy([1.25, 0.7])
    assert abs(h @ a) < 1e-14 and abs(v @ (body.matrix @ a)) < 1e-14
    # 5.71 in general: vᵀ(I a + p) = (I v)ᵀ a for any v, a
    rng = np.random.default_rng(4)
    for _ in range(5):
        vv, aa = rng.normal(size=3), rng.normal(size=3)
        p = pg.bias_force(body.matrix, vv)
        assert math.isclose(vv @ (body.matrix @ aa + p), (body.matrix @ vv) @ aa, rel_tol=1e-12, abs_tol=1e-12)


def test_lesson4_percussion_explorer():
    from planargeo.widgets import PercussionExplorer
    bat = PercussionExplorer(display="agg", shape="uniform rod")
    rho2 = (1 + 0.08**2) / 12
    ro = bat.readout_values
    assert math.isclose(ro["radius of gyration ρ"], math.sqrt(rho2), rel_tol=1e-9)
    np.testing.assert_allclose(ro["sweet spot of the grip"], (0.5 + rho2 / 0.5, 0.0))
    assert math.isclose(ro["force for α: m d α (5.66)"], 1.0 * 0.5 * 10.0, rel_tol=1e-9)
    bat = PercussionExplorer(display="agg", shape="uniform rod", drive="impact")
    bat.controls["impact at"].value = 0.5 + rho2 / 0.5
    assert bat.readout_values["pole distance from grip"] < 1e-9
    # exercise 1: the pole whose axis passes through x = 1 is at 0.5 − 2ρ²
    bat = PercussionExplorer(display="agg", shape="uniform rod")
    bat.set(**{"pole x": 0.33, "pole y": 0.0})
    d = 0.5 - 0.33
    assert math.isclose(bat.readout_values["l = d + ρ²/d (5.67)"], d + rho2 / d, rel_tol=1e-9)


# ------------------------------------------------------------------ lesson 5: subspace decompositions
def _pinned():
    import planargeo as pg
    from planargeo.screws.twists import inertia_matrix
    m, d, J = 2.0, 1.0, 0.5
    pin = pg.revolute((0.0, 0.0))
    return m, d, J, pin, pg.Decomposition.from_joint(inertia_matrix(m, [d, 0.0], J), pin)


def test_lesson5_T_and_U_by_hand():
    m, d, J, pin, dec = _pinned()
    np.testing.assert_allclose(dec.T.ravel(), [0.0, 1 / (d + (J / m) / d), 1.0])     # axis of percussion, unit moment
    np.testing.assert_allclose(dec.U.T, [[1.0, 0.0, 0.0], [0.0, 1.0, -m * d / (J + m * d**2)]])
    np.testing.assert_allclose(pin.s.T @ dec.T, 1.0)
    np.testing.assert_allclose(pin.R.T @ dec.U, np.eye(2), atol=1e-15)
    np.testing.assert_allclose(dec.T.T @ dec.U, 0.0, atol=1e-15)


def test_lesson5_pin_reaction_against_newton_euler():
    m, d, J, pin, dec = _pinned()
    for l in (0.6, 1.25, 2.0):
        Q, mu = dec.split_wrench(np.array([0.0, 1.0, l]))
        alpha = l / (J + m * d**2)
        assert math.isclose(Q[0], l)
        np.testing.assert_allclose(-mu, [0.0, m * alpha * d - 1.0], atol=1e-14)
    # exercise 1: horizontal unit force along y = 0.5
    Q, mu = dec.split_wrench(np.array([1.0, 0.0, -0.5]))
    alpha = -0.5 / (J + m * d**2)
    pin_force = m * np.array([0.0, alpha * d]) - np.array([1.0, 0.0])
    assert math.isclose(Q[0], -0.5)
    np.testing.assert_allclose(-mu, pin_force, atol=1e-14)


def test_lesson5_prismatic_T_is_the_slide_through_the_centre_of_mass():
    import planargeo as pg
    from planargeo.screws.twists import inertia_matrix
    cx, cy = 0.7, -0.3
    dec = pg.Decomposition.from_joint(inertia_matrix(3.0, [cx, cy], 0.2), pg.prismatic(direction=(1.0, 0.0)))
    T = dec.T.ravel()
    np.testing.assert_allclose(T / T[0], [1.0, 0.0, -cy], atol=1e-14)
    assert abs(pg.from_xy([cx, cy]) @ T) < 1e-14


def test_lesson5_chain_reactions_through_their_joints():
    from planargeo.widgets import ChainExplorer
    ch = ChainExplorer(display="agg", links=3, speed=0.0, **{"T/U split": True, "velocity poles": False})
    w = ch.state["w"]
    els = {e["id"]: e for e in ch.picture()["elements"]}
    for i in range(3):
        x, y = w.origin[i]
        # the line drawn as Rμ (thesis 7.6) passes through its joint (to the picture's rounding)
        xy = np.asarray(next(p["xy"] for p in els[f"Rμ{i + 1}"]["parts"] if p["p"] == "path"),
                        float).reshape(-1, 2)
        d = xy[-1] - xy[0]
        assert abs(d[0] * (y - xy[0, 1]) - d[1] * (x - xy[0, 0])) / np.hypot(*d) < 1e-3


# ---------------------------------------------------------- lesson 6: the planar example 6.9 (the car)
def _car_newton_euler(m, rho, L, d, eps, V, FA):
    """(ω̇, rear, front) from Newton–Euler at the centre of gravity (plain vectors, no screws)."""
    w = V / d
    c = np.array([d, (1 - eps) * L]); rear, front = np.array([d, 0.0]), np.array([d, L])
    e1, e2 = np.array([1.0, 0.0]), np.array([d, L]) / math.hypot(d, L)
    roll = np.array([-L, d]) / math.hypot(d, L)
    cross = lambda r, f: r[0] * f[1] - r[1] * f[0]
    kc = np.array([-c[1], c[0]])
    A = np.array([[m * kc[0], -e1[0], -e2[0]], [m * kc[1], -e1[1], -e2[1]],
                  [m * rho**2, -cross(rear - c, e1), -cross(front - c, e2)]])
    b = np.array([m * w * w * c[0] + FA * roll[0], m * w * w * c[1] + FA * roll[1], FA * cross(front - c, roll)])
    return np.linalg.solve(A, b)


def test_lesson6_car_numbers_against_newton_euler():
    from planargeo import scenes
    res = scenes.build("car")
    p, q = res.params, res.quantities
    wd, mu1, mu2 = _car_newton_euler(p["m"], p["rho"], p["L"], p["d"], p["eps"], p["omega"] * p["d"], p["F_A"])
    assert math.isclose(q["omega_dot"], wd, rel_tol=1e-9)
    np.testing.assert_allclose(q["mu"], [mu1, mu2], rtol=1e-9)
    # the rounded values the lesson quotes
    assert round(wd, 4) == 0.2077 and round(mu1, 1) == -1102.4 and round(mu2, 1) == -1089.3


def test_lesson6_exercises():
    m, rho, L, d, eps, w = 1200.0, 1.2, 2.6, 8.0, 0.45, 0.5
    ne = lambda FA, rho=rho: _car_newton_euler(m, rho, L, d, eps, w * d, FA)
    # exercise 3: at ρ² = ε(1−ε)L² the rear force does not depend on the drive force
    rho_star = math.sqrt(eps * (1 - eps) * L**2)
    assert math.isclose(rho_star, 1.2935, abs_tol=1e-4)
    assert abs(ne(5000.0, rho_star)[1] - ne(2000.0, rho_star)[1]) < 1e-8
    assert abs(ne(5000.0, 1.30)[1] - ne(2000.0, 1.30)[1]) < 3.0
    assert abs(ne(5000.0, 1.2)[1] - ne(2000.0, 1.2)[1]) > 30.0
    # exercise 4: braking
    np.testing.assert_allclose(ne(-2000.0)[1:], [-1057.6, -1686.6], atol=0.1)


def test_lesson6_car_explorer():
    from planargeo.widgets import CarExplorer
    car = CarExplorer(display="agg")
    ro = car.readout_values
    assert math.isclose(ro["yaw rate ω"], 4.0 / 8.0)                                   # rad/s
    assert math.isclose(ro["steering angle"], math.degrees(math.atan(2.6 / 8.0)))      # degrees
    assert math.isclose(ro["lateral acceleration at G"], 0.5**2 * math.hypot(8.0, 0.55 * 2.6) / 9.81)   # in g
    for FA in (0.0, 2000.0, 5000.0):                      # the explorer starts coasting (0 N); the lesson's 2000 N set here
        car.controls["drive force (N)"].value = FA
        wd, mu1, mu2 = _car_newton_euler(1200.0, 1.2, 2.6, 8.0, 0.45, 4.0, FA)
        ro = car.readout_values
        assert math.isclose(ro["yaw acceleration ω̇"], wd, rel_tol=1e-9, abs_tol=1e-12)
        assert math.isclose(ro["rear tyre force μ₁"], mu1, rel_tol=1e-9)
        assert math.isclose(ro["front tyre force μ₂"], mu2, rel_tol=1e-9)


# ------------------------------------------------------------------------ lesson 7: articulated inertias
def _A1_dense(m, rho, L, phi):
    """Body 1 free (plane joint), body 2 pinned at (L, 0): inverse of force-on-1 -> acceleration-of-1."""
    import planargeo as pg
    from planargeo.algorithms.crba import forward_dynamics_crba
    from planargeo.mechanics.kinematics import kinematics
    bodies = [pg.Body(m, (L / 2, 0.0), m * rho**2), pg.Body(m, (L / 2, 0.0), m * rho**2)]
    model = pg.Model(bodies, [pg.Joint("plane"), pg.Joint("revolute", (L, 0.0, 0.0))], [-1, 0], gravity=(0.0, 0.0))
    q = np.array([0.0, 0.0, 0.0, phi])
    S1 = kinematics(model, q).s(0)
    mob = np.zeros((3, 3))
    for k in range(3):
        f_ext = np.zeros((2, 3)); f_ext[0, k] = 1.0
        mob[:, k] = S1 @ forward_dynamics_crba(model, q, np.zeros(4), np.zeros(4), f_ext)[:3]
    return np.linalg.inv(mob)


def _straight_chain(n, lam, m=1.0, L=1.0):
    """(d/L, m_x/m, m_y/m, A_z/(m ρ²)) by the pin-mass argument of lesson 7."""
    rho = L / lam
    my, Az, d = m, m * rho**2, L / 2
    for _ in range(n - 1):
        m_pin = my * Az / (Az + my * d**2)
        my_new = m + m_pin
        d_new = (m * L / 2 + m_pin * L) / my_new
        Az = m * rho**2 + m * (L / 2 - d_new)**2 + m_pin * (L - d_new)**2
        my, d = my_new, d_new
    return d / L, float(n), my / m, Az / (m * rho**2)


def test_lesson7_two_bodies_closed_form_and_dense():
    from planargeo import scenes
    mx = lambda phi, lam: (8 + lam**2 * (1 + math.cos(phi)**2)) / (lam**2 + 4)
    for phi in (0.0, math.pi / 4, math.pi / 2, 2.0):
        for m, rho, L in ((1.0, 0.5, 1.0), (3.0, 0.2, 1.5)):
            sc = scenes.build("two-body", m=m, rho=rho, L=L, phi=phi).quantities
            assert math.isclose(sc["mx_over_m"], mx(phi, L / rho), rel_tol=1e-9)
            np.testing.assert_allclose(sc["A1"], _A1_dense(m, rho, L, phi), rtol=1e-8, atol=1e-10)
    assert math.isclose(mx(math.pi / 4, 2.0), 1.75)
    assert math.isclose(mx(math.pi / 2, 2.0), 1.5) and math.isclose(mx(math.pi / 2, 1e6), 1.0, rel_tol=1e-9)


def test_lesson7_horizontal_chain_table():
    from planargeo import scenes
    for lam in (1.0, 2.0, 4.0, 5.0):
        assert math.isclose(_straight_chain(2, lam)[0], (lam**2 + 12) / (2 * (lam**2 + 8)))
        assert math.isclose(_straight_chain(2, lam)[2], (lam**2 + 8) / (lam**2 + 4))
        assert math.isclose(_straight_chain(2, lam)[3], 2 * (lam**2 + 4) / (lam**2 + 8))
        for n in (1, 2, 3, 4):
            r = scenes.build("horizontal-chain", n=n, lam=lam).quantities
            got = (r["d_over_L"], r["mx_over_m"], r["my_over_m"], r["Az_over_m_rho2"])
            np.testing.assert_allclose(got, _straight_chain(n, lam), rtol=1e-10)
    for n in (2, 3, 4):                           # λ = 2: d, m_y, A_z fixed; m_x = n m
        np.testing.assert_allclose(_straight_chain(n, 2.0), (2 / 3, n, 1.5, 4 / 3))


def test_lesson7_exercises():
    # exercise 1: body 2 felt at its pin across the chain, λ = 2: m/2
    m, L = 1.0, 1.0
    A, e = m * (L / 2)**2, L / 2
    assert math.isclose(m * A / (A + m * e**2), 0.5)
    # exercise 4: a rectangle's λ ≤ √12
    for h in (0.0, 0.1, 0.5):
        assert L / math.sqrt((L**2 + h**2) / 12) <= math.sqrt(12) + 1e-12


def test_lesson7_chain_explorer_tip():
    from planargeo.widgets import ChainExplorer
    ch = ChainExplorer(display="agg", links=5, speed=0.5, **{"articulated inertias": True, "acceleration poles": True})
    w = ch.state["w"]
    np.testing.assert_allclose(w.A[-1], w.I[-1])


# --------------------------------------------------------- lesson 8: mobility and chain splitting
def test_lesson8_mobility_example_against_the_joint_space_inertia():
    from planargeo import scenes
    from planargeo.screws.twists import inertia_matrix
    res = scenes.build("mobility-example")
    q = res.quantities
    m, rho, L, phi = (res.params[k] for k in ("m", "rho", "L", "phi"))
    s1, s2 = np.array([0.0, 0.0, 1.0]), np.array([0.0, -L, 1.0])
    I1 = inertia_matrix(m, [L / 2, 0.0], m * rho**2)
    I2 = inertia_matrix(m, [L + L / 2 * math.cos(phi), L / 2 * math.sin(phi)], m * rho**2)
    J1, J2 = np.column_stack([s1, np.zeros(3)]), np.column_stack([s1, s2])
    H = J1.T @ I1 @ J1 + J2.T @ I2 @ J2
    np.testing.assert_allclose(q["Lambda1_inv"], np.diag([0.0, 0.0, 4 / (m * (L**2 + 4 * rho**2))]), atol=1e-15)
    np.testing.assert_allclose(q["Lambda2_inv"], J2 @ np.linalg.solve(H, J2.T), atol=1e-12)
    eta = L / rho
    assert math.isclose(q["x_over_L"], 1 + 2 * eta**2 * math.cos(phi) / (4 + 5 * eta**2))
    assert round(q["x_over_L"], 4) == 1.2357
    # exercise 2
    assert math.isclose(scenes.build("mobility-example", phi=math.pi / 2).quantities["x_over_L"], 1.0)
    assert math.isclose(scenes.build("mobility-example", phi=0.0).quantities["x_over_L"], 4 / 3)


def test_lesson8_push_at_the_tip_by_hand():
    from planargeo.algorithms.chain_splitting import mobility_split
    from planargeo.widgets.chain import chain_for
    q, z = np.array([0.0, math.pi / 2]), np.zeros(2)
    F = np.zeros((2, 3)); F[1] = [1.0, 0.0, -1.0]
    split = mobility_split(chain_for(2, gravity=False), q, z, z, F)
    lc, Ic, c2 = 0.5, 1 / 12, math.cos(q[1])          # the textbook two-link joint-space inertia
    H = np.array([[lc**2 + Ic + (1 + lc**2 + 2 * lc * c2) + Ic, lc**2 + lc * c2 + Ic], [lc**2 + lc * c2 + Ic, lc**2 + Ic]])
    np.testing.assert_allclose(H, [[5 / 3, 1 / 3], [1 / 3, 1 / 3]])
    np.testing.assert_allclose(split.qdd, np.linalg.solve(H, [-1.0, -1.0]), atol=1e-12)
    np.testing.assert_allclose(split.f[1], [0.5, 0.0, 0.0], atol=1e-12)
    # exercise 4: a wall at the tip takes the whole push: tip x acceleration −q̈1 − q̈2 = 0 at λ = −1
    qdd = np.linalg.solve(H, [-(1 - 1.0), -(1 - 1.0)])
    assert np.allclose(qdd, 0.0)


def test_lesson8_chain_explorer_matches_splitting():
    from planargeo.algorithms.chain_splitting import mobility_split
    from planargeo.widgets import ChainExplorer
    ch = ChainExplorer(display="agg", links=4, **{"internal forces": True, "acceleration poles": True})
    cs = mobility_split(*ch.initial_state(ch.values))
    np.testing.assert_allclose(ch.state["w"].qdd, cs.qdd, rtol=1e-9, atol=1e-9)


# ------------------------------------------------------------------------------ lesson 9: car cornering
def test_lesson9_friction_demand_and_limits():
    from planargeo import scenes
    G, m, eps, d, L = 9.81, 1200.0, 0.45, 8.0, 2.6
    for V in (2.0, 4.0, 7.0):
        w = V / d
        q = scenes.build("car", omega=w, F_A=0.0, outlines=False).quantities
        # coasting: demand = centripetal acceleration of each axle in g (independent of ε)
        assert math.isclose(-q["mu"][0] / (eps * m * G), d * w**2 / G, rel_tol=1e-9)
        assert math.isclose(-q["mu"][1] / ((1 - eps) * m * G), math.hypot(d, L) * w**2 / G, rel_tol=1e-9)
    # the same with another ε: exercise 3
    q = scenes.build("car", omega=0.5, F_A=0.0, eps=0.6, outlines=False).quantities
    assert math.isclose(-q["mu"][0] / (0.6 * m * G), d * 0.25 / G, rel_tol=1e-9)
    # exercise 2: the speed limits at μ_f = 0.9
    assert round(d * math.sqrt(0.9 * G / math.hypot(d, L)), 2) == 8.20
    assert round(d * math.sqrt(0.9 * G / d), 2) == 8.40
    assert round(40 * math.sqrt(0.9 * G / math.hypot(40, L)), 2) == 18.77


def test_lesson9_car_explorer_lateral_acceleration():
    from planargeo.widgets import CarExplorer
    car = CarExplorer(display="agg")
    car.set(**{"speed (m/s)": 6.0})
    c = math.hypot(8.0, 0.55 * 2.6)
    assert math.isclose(car.readout_values["lateral acceleration at G"], (6.0 / 8.0)**2 * c / 9.81, rel_tol=1e-9)
    # exercise 1: 0.5 g at V = d √(0.5 g / |c|)
    V = 8.0 * math.sqrt(0.5 * 9.81 / c)
    assert 6.0 < V < 6.5 and round(V, 2) == 6.22


# -------------------------------------------------------------------------------------- lesson 10: trees
def test_lesson10_adjacency_trunk_and_nilpotency():
    from planargeo import scenes
    q = scenes.build("tree").quantities
    C, Dinv = np.array(q["C"]), np.array(q["Dinv"])
    parents = (-1, 0, 1, 2, 0, 4, 5, 5, 0)
    expected = np.zeros((9, 9))
    for i, p in enumerate(parents):
        if p >= 0:
            expected[i, p] = 1
    np.testing.assert_array_equal(C, expected)
    # the trunk matrix by walking each path to the root by hand
    trunk = np.zeros((9, 9))
    for i in range(9):
        j = i
        while j >= 0:
            trunk[i, j] = 1
            j = parents[j]
    np.testing.assert_array_equal(Dinv, trunk)
    assert np.linalg.matrix_power(C, 3).any() and not np.linalg.matrix_power(C, 4).any()   # exercise 2


def test_lesson10_held_still_joints_carry_their_subtrees():
    from planargeo import scenes
    from planargeo.algorithms.rnea import newton_euler
    tree = scenes.build("tree")
    held = newton_euler(tree.model, np.array(tree.state["q"]), np.zeros(9), np.zeros(9))
    subtree = [9, 3, 2, 1, 4, 3, 1, 1, 1]                                   # counted on Fig 9.1
    np.testing.assert_allclose(held.f[:, 1], 9.81 * np.array(subtree), rtol=1e-12)
    np.testing.assert_allclose(held.f[:, 0], 0.0, atol=1e-12)
    # exercise 4: torque = Σ over the subtree of m g (x_c − x_joint), from the joint angles by hand
    parents = (-1, 0, 1, 2, 0, 4, 5, 5, 0)
    q = np.array(tree.state["q"])
    th, start = np.zeros(9), np.zeros((9, 2))
    for i, p in enumerate(parents):                     # parents come before children
        th[i] = q[i] + (th[p] if p >= 0 else 0.0)
        start[i] = start[p] + [math.cos(th[p]), math.sin(th[p])] if p >= 0 else 0.0
    com = start + 0.5 * np.column_stack([np.cos(th), np.sin(th)])
    def in_subtree(k, i):
        while k >= 0:
            if k == i:
                return True
            k = parents[k]
        return False
    hand = [sum(9.81 * (com[k, 0] - start[i, 0]) for k in range(9) if in_subtree(k, i)) for i in range(9)]
    np.testing.assert_allclose(held.tau, hand, atol=1e-12)
    assert np.argmax(np.abs(held.tau)) == 4 and round(float(held.tau[4]), 1) == 17.3


def test_lesson10_stacked_and_direct_against_pinocchio():
    pin = pytest.importorskip("pinocchio")
    from bench import to_pinocchio
    from planargeo import scenes
    tree = scenes.build("tree")
    q, qd, tau = (np.array(tree.state[k]) for k in ("q", "qd", "tau"))
    pm = to_pinocchio(tree.model)
    ref = pin.aba(pm, pm.createData(), q, qd, tau)
    np.testing.assert_allclose(tree.quantities["qdd"], ref, rtol=1e-10, atol=1e-10 * abs(ref).max())
    np.testing.assert_allclose(tree.quantities["qdd_direct"], ref, rtol=1e-10, atol=1e-10 * abs(ref).max())


def test_lesson10_tree_explorer_open():
    from planargeo.widgets import TreeExplorer
    te = TreeExplorer(display="agg", **{"loops": "open (Fig 9.1)"})
    assert te.readout_values["degrees of freedom"] == 9 and "contact 4-7: |force| (N)" not in te.readout_values


# --------------------------------------------------------------- lesson 11: loops and the slider-crank
PARENTS_9_1 = (-1, 0, 1, 2, 0, 4, 5, 5, 0)


def _path(i):
    out = []
    while i >= 0:
        out.append(i)
        i = PARENTS_9_1[i]
    return out


def test_lesson11_constrained_tree_at_rest_pins_hold():
    from planargeo import scenes
    ct = scenes.build("constrained-tree", speed=0.0)
    a = np.asarray(ct.quantities["a"]).reshape(9, 3)
    F = np.asarray(ct.quantities["F"]).reshape(-1, 3)
    pose = ct.extra["solution"].data.pose
    tips = pose[:, :2] + np.column_stack([np.cos(pose[:, 2]), np.sin(pose[:, 2])])
    acc = lambda tw, p: np.array([tw[0] - tw[2] * p[1], tw[1] + tw[2] * p[0]])
    for k, (i, j) in enumerate(((3, 6), (7, 8))):
        np.testing.assert_allclose(tips[i], tips[j], atol=1e-12)
        np.testing.assert_allclose(acc(a[i], tips[i]), acc(a[j], tips[j]), atol=1e-9)
        x, y = tips[i]
        assert abs(np.dot([y, -x, 1.0], F[k])) < 1e-9 * (1 + abs(F[k]).max())     # a line through the pin


def test_lesson11_constrained_tree_against_lagrange_multipliers():
    from planargeo import scenes
    from planargeo.algorithms.crba import bias_forces, mass_matrix
    from planargeo.widgets import TreeExplorer
    ct = scenes.build("constrained-tree")
    q, qd, tau = (np.array(ct.state[k]) for k in ("q", "qd", "tau"))
    L = ct.params["length"]
    absolute = lambda x: np.array([sum(x[k] for k in _path(i)) for i in range(9)])
    e = lambda t: np.array([math.cos(t), math.sin(t)])
    e_perp = lambda t: np.array([-math.sin(t), math.cos(t)])
    th, thd = absolute(q), absolute(qd)
    tip = lambda i, th=th: sum(L * e(th[k]) for k in _path(i))

    def tip_jacobian(i):
        Jt = np.zeros((2, 9))
        for k in _path(i):
            for j in _path(k):
                Jt[:, j] += L * e_perp(th[k])
        return Jt

    pins = ((3, 6), (7, 8))
    J = np.vstack([tip_jacobian(i) - tip_jacobian(j) for i, j in pins])
    quad = lambda i: -sum(L * thd[k]**2 * e(th[k]) for k in _path(i))
    gamma = np.concatenate([quad(i) - quad(j) for i, j in pins])
    gap = lambda x: np.concatenate([tip(a, absolute(x)) - tip(b, absolute(x)) for a, b in pins])
    J_fd = np.column_stack([(gap(q + 1e-6 * dq) - gap(q - 1e-6 * dq)) / 2e-6 for dq in np.eye(9)])
    np.testing.assert_allclose(J, J_fd, atol=1e-8)
    np.testing.assert_allclose(gap(q), 0.0, atol=1e-12)
    H, C = mass_matrix(ct.model, q), bias_forces(ct.model, q, qd)
    x = np.linalg.solve(np.block([[H, -J.T], [J, np.zeros((4, 4))]]), np.concatenate([tau - C, -gamma]))
    qdd_ref, lam = x[:9], x[9:].reshape(2, 2)
    F = np.asarray(ct.quantities["F"]).reshape(-1, 3)
    np.testing.assert_allclose(ct.quantities["qdd"], qdd_ref, atol=1e-10 * abs(qdd_ref).max())
    for k, (i, j) in enumerate(pins):
        px, py = tip(i)
        fx, fy = -lam[k]
        np.testing.assert_allclose(F[k], [fx, fy, px * fy - py * fx], atol=1e-10 * abs(lam).max())
    te = TreeExplorer(display="agg", gravity=9.81, speed=1.0)     # the scene's state (the explorer starts at 0, 0.25)
    ro = te.readout_values
    for k, name in enumerate(("4-7", "8-9")):
        assert math.isclose(ro[f"|F{'₁₂'[k]}| (pin {name})"], math.hypot(*lam[k]), rel_tol=1e-9)
    assert math.isclose(ro["q̈₁ (body 1)"], qdd_ref[0], rel_tol=1e-9, abs_tol=1e-12)
    assert ro["degrees of freedom"] == 9 - 4


R_SC, L_SC, T_SC = 2.29, 5.0, 0.5
M_SC = (0.40, 0.15, 0.30)


def _h(p, l=L_SC):
    return R_SC * math.sin(p) + math.sqrt(l**2 - (R_SC * math.cos(p))**2) + T_SC


def _sc_geometry(p):
    pin = np.array([R_SC * math.cos(p), R_SC * math.sin(p)])
    wrist = np.array([0.0, _h(p) - T_SC])
    return [0.25 * pin, 0.5 * (pin + wrist), wrist + [0.0, T_SC]], [p, math.atan2(*(wrist - pin)[::-1])]


def _gen_mass(p, e=1e-5):
    Iz = (0.1464 * M_SC[0] * R_SC**2, 0.0866 * M_SC[1] * L_SC**2)     # the thesis's data (9.6)
    (c0, b0), (c1, b1) = _sc_geometry(p - e), _sc_geometry(p + e)
    dc = [(y - x) / (2 * e) for x, y in zip(c0, c1)]
    db = [(y - x) / (2 * e) for x, y in zip(b0, b1)]
    return sum(m * v @ v for m, v in zip(M_SC, dc)) + Iz[0] * db[0]**2 + Iz[1] * db[1]**2


def _psi_dd(p, w, g):
    V = lambda x: g * sum(m * c[1] for m, c in zip(M_SC, _sc_geometry(x)[0]))
    d = 1e-4
    Mp, Vp = (_gen_mass(p + d) - _gen_mass(p - d)) / (2 * d), (V(p + d) - V(p - d)) / (2 * d)
    return -(0.5 * Mp * w**2 + Vp) / _gen_mass(p)


def test_lesson11_slider_crank_state_and_kinematics():
    from planargeo import scenes
    Q = scenes.build("slider-crank").quantities
    psi = 0.4
    beta = math.acos(-R_SC * math.cos(psi) / L_SC)
    np.testing.assert_allclose(Q["q"], [psi, beta - psi, math.pi / 2 - beta], atol=1e-12)
    rate = -R_SC * math.sin(psi) * 20.0 / (L_SC * math.sin(beta))
    np.testing.assert_allclose(Q["qd"], [20.0, rate - 20.0, -rate], atol=1e-10)
    assert round(beta, 5) == 2.00628 and round(Q["q"][2], 5) == -0.43548      # exercise 2
    assert math.isclose(Q["h"], _h(psi)) and round(Q["h"], 3) == 5.925
    dh = R_SC * math.cos(psi) + R_SC**2 * math.sin(psi) * math.cos(psi) / math.sqrt(L_SC**2 - (R_SC * math.cos(psi))**2)
    assert math.isclose(Q["v"][2][1], 20.0 * dh, rel_tol=1e-9) and round(Q["v"][2][1], 3) == 50.483
    # the closed loop piston acceleration is a vertical translation; the contact force lies in B3
    assert abs(Q["a3"][0]) < 1e-9 and abs(Q["a3"][2]) < 1e-9
    B3 = np.array(Q["B3"])
    np.testing.assert_allclose(B3 @ np.array(Q["xi"]), Q["F3"], atol=1e-12)
    np.testing.assert_allclose(B3, [[1.0, 0.0], [0.0, 0.0], [-_h(psi), 1.0]])


def test_lesson11_slider_crank_against_a_one_coordinate_lagrangian():
    from planargeo import scenes
    Q = scenes.build("slider-crank").quantities                          # gravity 9.81, free crank
    assert math.isclose(Q["qdd"][0], _psi_dd(0.4, 20.0, 9.81), rel_tol=1e-5)
    free = scenes.build("slider-crank", g=0.0).quantities
    assert math.isclose(free["qdd"][0], _psi_dd(0.4, 20.0, 0.0), rel_tol=1e-5)
    e = 1e-4                                                              # driven at constant speed: h'' ψ̇²
    driven = scenes.build("slider-crank", drive="constant-speed", psi=0.4, psidot=20.0).quantities
    hpp = (_h(0.4 + e) - 2 * _h(0.4) + _h(0.4 - e)) / e**2
    assert math.isclose(driven["a"][2][1], hpp * 400.0, rel_tol=1e-4)


def test_lesson11_slider_crank_explorer():
    from planargeo.widgets import SliderCrankExplorer
    sc = SliderCrankExplorer(display="agg")
    ro = sc.readout_values
    psi0, w0 = math.radians(ro["crank angle ψ"]), sc.values["crank speed"]      # the default: 23°
    assert ro["crank angle ψ"] == 23.0 and ro["crank speed ψ̇"] == w0
    assert math.isclose(ro["ψ̈ crank"], _psi_dd(psi0, w0, 9.81), rel_tol=1e-5)
    assert math.isclose(ro["piston height h"], _h(psi0), rel_tol=1e-12)
    sc.controls["crank angle (deg)"].value = 90.0                         # exercise 3
    assert "dead centre" in sc.message
    sc.set(**{"rod length": 2.0, "crank angle (deg)": 0.0})                # exercise 4
    assert "rod too short" in sc.message
    sc.reset()
    assert sc.message == ""
    sc.set(**{"crank angle (deg)": 180.0})
    sc.set(**{"rod length": 2.29})                                         # l = r: the folded dead centre
    assert "singular" in sc.message and sc.values["rod length"] == 5.0    # refused, the last good state kept


# ------------------------------------------------------------------- lesson 12: speed against accuracy
EPS = np.finfo(float).eps


def test_lesson12_methods_agree_and_integrators_converge():
    from planargeo import scenes
    from planargeo.mechanics.model import chain_model
    from planargeo.scenes.chain import available_methods
    from planargeo.simulate.integrate import simulate
    methods = available_methods()
    for n in (1, 5, 20):
        res = scenes.build("chain", n=n, seed=n)
        assert set(res.quantities["qdd"]) == set(methods), res.quantities.get("failed")
        assert res.quantities["max_disagreement"] < 1e-7 * max(1.0, max(abs(x) for x in res.quantities["qdd"]["crba"]))
    model = chain_model(3)
    q0, qd0 = np.array([0.3, -0.2, 0.1]), np.zeros(3)
    drift = {h: simulate(model, q0, qd0, 1.0, method="RK4", dt=h).energy_drift() for h in (0.004, 0.002)}
    assert 8 < drift[0.004] / drift[0.002] < 32                              # fourth order: 16
    assert simulate(model, q0, qd0, 1.0, method="DOP853", rtol=1e-10, atol=1e-12).energy_drift() < 1e-8


def test_lesson12_geometry_refuses_on_kappa_not_on_distance():
    from fractions import Fraction
    from planargeo.errors import COND_LIMIT, DegenerateGeometryError
    from planargeo.geometry.projective import from_xy, line_through_point_direction, meet
    line = lambda p, a: line_through_point_direction(from_xy(p), (math.cos(a), math.sin(a)))

    def exact_meet(l, m):
        l, m = [Fraction(float(x)) for x in l], [Fraction(float(x)) for x in m]
        return [l[1] * m[2] - l[2] * m[1], l[2] * m[0] - l[0] * m[2], l[0] * m[1] - l[1] * m[0]]

    def kappa(l, m):
        x = exact_meet(l, m)
        return float(np.linalg.norm(l) * np.linalg.norm(m)) / math.sqrt(float(sum(v * v for v in x)))

    def rel_err(x, ref):
        d = [Fraction(float(a)) - b for a, b in zip(x, ref)]
        return math.sqrt(float(sum(v * v for v in d)) / float(sum(v * v for v in ref)))

    P, a = (0.3, 0.2), 0.7
    Q = (P[0] - math.sin(a), P[1] + math.cos(a))
    for theta in (1e-2, 1e-6, 1e-10, 1e-14):
        l, m = line(P, a), line(Q, a + theta)                              # near-parallel: exact to rounding
        assert kappa(l, m) < 10 and rel_err(meet(l, m), exact_meet(l, m)) < 4 * EPS
        l2, m2 = line(P, a), line(P, a + theta)                            # near-coincident: κ ~ 1/θ
        k = kappa(l2, m2)
        assert 0.1 < k * theta < 10
        if k <= COND_LIMIT:
            assert rel_err(meet(l2, m2), exact_meet(l2, m2)) < 4 * EPS * k
        else:
            with pytest.raises(DegenerateGeometryError) as exc:
                meet(l2, m2)
            assert exc.value.cond > COND_LIMIT
    p = meet(line(P, a), line(Q, a))                                        # exactly parallel: ideal, silently
    assert p[2] == 0


def test_lesson12_dynamics_breakdown_against_the_exact_reference():
    from reference import reference_with_info
    from planargeo.errors import SingularConfigurationError
    from planargeo.mechanics.model import Body, Joint, Model
    from planargeo.scenes.chain import available_methods
    methods = available_methods()

    def serial_chain(masses, coms, inertias):
        bodies = [Body(float(m), (float(c), 0.0), float(J)) for m, c, J in zip(masses, coms, inertias)]
        joints = [Joint("revolute", (0.0 if i == 0 else 1.0, 0.0, 0.0)) for i in range(len(bodies))]
        return Model(bodies, joints, list(range(-1, len(bodies) - 1)))

    def errors(model, q, qd, tau):
        ref, _, cond = reference_with_info(model, q, qd, tau, mode="exact")
        out = {}
        for name, f in methods.items():
            try:
                out[name] = float(np.max(np.abs(f(model, q, qd, tau) - ref)) / np.max(np.abs(ref)))
            except SingularConfigurationError as exc:
                out[name] = exc
        return cond, out

    rng = np.random.default_rng(1)
    q8, qd8, tau8 = rng.uniform(-1, 1, (3, 8))
    rows = {}
    for light in ("tip", "base"):
        masses = np.geomspace(1.0, 1e-12, 8)[:: 1 if light == "tip" else -1]
        rows[light] = errors(serial_chain(masses, [0.5] * 8, masses / 12), q8, qd8, tau8 * masses)
    for light, (cond, out) in rows.items():
        assert cond > 1e11
        assert all(isinstance(v, float) and v <= 4 * EPS * cond for v in out.values())
        assert out["aba"] < 1e-11
    assert max(rows["tip"][1].values()) < 1e-12                             # light tip: nothing breaks
    assert rows["base"][1]["crba"] > 1e-8 and rows["base"][1]["crba"] > 100 * rows["base"][1]["aba"]
    q, qd, tau = rng.uniform(-1, 1, (3, 8))                                 # a joint with no inertia: refusals
    for d, all_refuse in ((1e-2, False), (1e-7, True)):
        cond, out = errors(serial_chain([1.0] * 8, [0.5] * 7 + [d], [1 / 12] * 7 + [0.0]), q, qd, tau)
        refused = [isinstance(v, SingularConfigurationError) for v in out.values()]
        assert all(refused) if all_refuse else not any(refused)
        for v in out.values():
            if isinstance(v, SingularConfigurationError):
                assert v.cond > 1e12


def test_lesson12_folding_slider_crank_and_peers():
    pin = pytest.importorskip("pinocchio")
    from bench import to_pinocchio
    from reference import slider_crank_reference
    from planargeo.algorithms.crba import mass_matrix
    from planargeo.algorithms.loops import SINGULAR_COND, constrained_dynamics_lagrange, loop_solve
    from planargeo.errors import SingularConfigurationError
    from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
    from planargeo.widgets import ChainExplorer
    r = 2.29
    for delta, solvable in ((1e-9, True), (1e-11, False)):
        l = r * (1 + delta)
        model = slider_crank_model(l=l)
        q, qd = slider_crank_state(0.0, 20.0, r, l)
        x = slider_crank_reference(model, q, qd, np.zeros(3), r, l, mode="exact")
        lag = constrained_dynamics_lagrange(model, q, qd, np.zeros(3))["qdd"]
        assert np.max(np.abs(lag - x)) / np.max(np.abs(x)) < 1e-14            # maximal coordinates: fine
        if solvable:
            sol = loop_solve(model, q, qd, np.zeros(3))
            assert 0.1 < sol.cond * delta < 10 and sol.cond <= SINGULAR_COND
        else:
            with pytest.raises(SingularConfigurationError) as exc:
                loop_solve(model, q, qd, np.zeros(3))
            assert exc.value.cond > SINGULAR_COND
    chain = ChainExplorer(display="agg", links=6, speed=0.8, torque=1.5, **{"articulated inertias": True})
    m6, q6, qd6, tau6 = chain.initial_state(chain.values)
    pm6 = to_pinocchio(m6)
    qdd_pin = pin.aba(pm6, pm6.createData(), q6, qd6, tau6)
    assert math.isclose(chain.readout_values["q̈₁"], qdd_pin[0], rel_tol=1e-10, abs_tol=1e-12)
    assert math.isclose(chain.readout_values["kinetic energy (J)"], 0.5 * qd6 @ mass_matrix(m6, q6) @ qd6, rel_tol=1e-10)


def test_lesson12_committed_benchmark_claims():
    """The story lesson 12 tells from benchmarks/results/dynamics.json."""
    res = json.loads((ROOT / "benchmarks" / "results" / "dynamics.json").read_text())
    single = {row["N"]: row for row in res["single"]}
    for N, row in single.items():
        assert all(err <= 4 * EPS * row["ref"]["cond"] + 1e-14 for err in row["err_ref"].values()), N
    batch = {row["B"]: row for row in res["batch"]}[10000]
    assert batch["err_peer"]["pinocchio"] < 1e-12 and set(single) >= {1, 10, 100}
    assert single[10]["ratio"]["median"] < 1.5 and single[200]["ratio"]["median"] < 1
    assert batch["ratio"]["pinocchio"]["median"] < 1 and batch["ratio"]["mujoco"]["median"] < 1
