"""Tests of planargeo.draw.sums: the drawn poles and lines against the thesis's closed forms (4.11-4.56)."""
from __future__ import annotations

import math
import warnings

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from planargeo.draw.picture import Picture  # noqa: E402
from planargeo.draw.render import figure  # noqa: E402
from planargeo.draw.sums import (acceleration_step, newton_euler, twist_sum, velocity_step,  # noqa: E402
                                 wrench_sum)
from planargeo.errors import InputError, NonFiniteError, ShapeError  # noqa: E402
from planargeo.screws.twists import inertia_matrix, unit_rotation, unit_translation  # noqa: E402


@pytest.fixture
def pic():
    return Picture((-4, 4, -4, 4), size=(400, 400), ticks=False)


def _part(el, kind):
    return next(p for p in el["parts"] if p["p"] == kind)


def _at(el):
    """Where a point element's marker sits."""
    m = _part(el, "mark")
    return np.array([m["x"], m["y"]])


def _segment(el):
    """The clipped segment of a line element."""
    return np.asarray(_part(el, "path")["xy"], float)


def _cross(a, b):
    return float(a[0] * b[1] - a[1] * b[0])


def _on_segment_line(xy, seg, tol=1e-9):
    """True when the point xy lies on the infinite line through the two points of seg."""
    d = seg[1] - seg[0]
    return abs(_cross(d, np.asarray(xy) - seg[0])) / np.hypot(*d) <= tol


def _drawn_without_warnings(pic):
    import matplotlib.pyplot as plt

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fig = figure(pic.to_dict())
        fig.canvas.draw()
    plt.close(fig)


def test_twist_sum_lever_rule(pic):
    # thesis 4.11-4.13: P = Q1 + beta (Q2 - Q1), beta = w2 / (w1 + w2), omega3 = omega1 + omega2
    Q1, Q2, w1, w2 = np.array([0.0, 0.0]), np.array([3.0, 0.0]), 1.0, 2.0
    out = twist_sum(pic, w1 * unit_rotation(Q1), w2 * unit_rotation(Q2))
    P = Q1 + w2 / (w1 + w2) * (Q2 - Q1)
    np.testing.assert_allclose(_at(out["v3"]), P, atol=1e-12)
    np.testing.assert_allclose(_at(out["v1"]), Q1, atol=1e-12)
    np.testing.assert_allclose(_at(out["v2"]), Q2, atol=1e-12)
    assert "ω = 3 rad/s" in out["v3"]["desc"]
    assert "β = ω₂/(ω₁ + ω₂) = 0.6667" in out["lever"]["desc"]
    assert _on_segment_line(P, _segment(out["lever"]))          # the pole lies on the lever line
    assert _part(out["v3"], "mark")["shape"] == "D"             # the sum is marked
    assert _part(out["v3"], "glyph")["ccw"] and _part(out["v1"], "glyph")["ccw"]
    _drawn_without_warnings(pic)


def test_twist_sum_rotation_plus_translation(pic):
    # thesis 4.16: P = Q + rho n, rho = u / w, n = (-sin lam, cos lam)
    w, u, lam = 2.0, 3.0, 0.4
    Q = np.array([1.0, -0.5])
    out = twist_sum(pic, w * unit_rotation(Q), u * unit_translation([np.cos(lam), np.sin(lam)]))
    np.testing.assert_allclose(_at(out["v3"]), Q + u / w * np.array([-np.sin(lam), np.cos(lam)]),
                               atol=1e-12)
    # the translation's pole is at infinity: an arrow at the edge along the motion, no marker
    arrow = _part(out["v2"], "arrow")
    assert not any(p["p"] == "mark" for p in out["v2"]["parts"])
    assert math.atan2(arrow["dy"], arrow["dx"]) == pytest.approx(lam)
    _drawn_without_warnings(pic)


def test_opposite_rotations_give_translation(pic):
    # beta = inf (4.2.1): +1 about (0, 0) and -1 about (2, 0) is a translation, velocity (0, 2)
    out = twist_sum(pic, unit_rotation([0.0, 0.0]), -unit_rotation([2.0, 0.0]))
    assert not any(p["p"] == "mark" for p in out["v3"]["parts"])
    arrow = _part(out["v3"], "arrow")
    assert arrow["dx"] == pytest.approx(0.0, abs=1e-12) and arrow["dy"] > 0
    assert "translation of 2 m/s" in out["v3"]["desc"]
    assert "β = ∞" in out["lever"]["desc"]
    _drawn_without_warnings(pic)


def test_twist_sum_coincident_poles(pic):
    # v + 2 v: the same pole, no lever line; the sum is 3 v
    v = 0.7 * unit_rotation([1.0, 0.5])
    out = twist_sum(pic, v, 2 * v)
    np.testing.assert_allclose(_at(out["v3"]), [1.0, 0.5], atol=1e-12)
    assert "ω = 2.1 rad/s" in out["v3"]["desc"]
    assert "lever" not in out and "lever" not in {e["id"] for e in pic.elements}
    _drawn_without_warnings(pic)


def test_twist_sum_labels_on_either_side_of_the_lever(pic):
    out = twist_sum(pic, unit_rotation([-2.0, 0.0]), unit_rotation([2.0, 0.0]))
    assert _part(out["v1"], "text")["dy"] > 0 and _part(out["v2"], "text")["dy"] > 0
    assert _part(out["v3"], "text")["dy"] < 0


def test_wrench_sum_through_meet(pic):
    f1 = np.array([1.0, 0.0, -1.0])   # along +x through y = 1
    f2 = np.array([0.0, 1.0, 2.0])    # along +y through x = 2
    out = wrench_sum(pic, f1, f2, scale=0.5)
    P = np.array([2.0, 1.0])
    np.testing.assert_allclose(_at(out["meet"]), P, atol=1e-12)
    assert _on_segment_line(P, _segment(out["f3"]))
    np.testing.assert_allclose(_segment(out["f1"])[:, 1], [1.0, 1.0], atol=1e-12)
    np.testing.assert_allclose(_segment(out["f2"])[:, 0], [2.0, 2.0], atol=1e-12)
    # the parallelogram (4.33): each arrow starts at P and is 0.5 |f| long; the sum's is the diagonal
    for k, f in (("f1", f1), ("f2", f2), ("f3", f1 + f2)):
        a = _part(out[k], "arrow")
        np.testing.assert_allclose([a["x"], a["y"]], P, atol=1e-12)
        np.testing.assert_allclose([a["dx"] / pic.kx, a["dy"] / pic.ky], 0.5 * f[:2], atol=1e-12)
    corners = [np.asarray(p["xy"]) for p in out["parallelogram"]["parts"]]
    np.testing.assert_allclose(corners[0], [[2.5, 1.0], [2.5, 1.5]], atol=1e-12)
    np.testing.assert_allclose(corners[1], [[2.0, 1.5], [2.5, 1.5]], atol=1e-12)
    assert out["f3"]["width"] > out["f1"]["width"]                  # the sum is heavier
    _drawn_without_warnings(pic)


def test_wrench_sum_parallel_forces_lever_rule(pic):
    # 4.40-4.45: d3 = d1 + beta (d2 - d1), beta = F2 / (F1 + F2)
    F1, F2, d1, d2 = 2.0, 1.0, 0.0, 3.0
    g1 = np.array([0.0, -F1, -F1 * d1])  # downward through x = d1 (tz = x fy)
    g2 = np.array([0.0, -F2, -F2 * d2])
    out = wrench_sum(pic, g1, g2, scale=0.4, anchors=([0, 0.45], [3, 0.45], [0, 0.15]))
    x3 = d1 + F2 / (F1 + F2) * (d2 - d1)
    np.testing.assert_allclose(_segment(out["f3"])[:, 0], [x3, x3], atol=1e-12)
    assert "meet" not in out and "parallelogram" not in out
    # the arrow of f3 is centred on the anchor's foot (x3, 0.15), 0.4 * 3 long, pointing down
    a = _part(out["f3"], "arrow")
    np.testing.assert_allclose([a["x"], a["y"] + a["dy"] / pic.ky / 2], [x3, 0.15], atol=1e-12)
    assert a["dy"] / pic.ky == pytest.approx(-0.4 * (F1 + F2))


def test_wrench_sum_force_and_couple(pic):
    # 4.46: a force F plus a couple tau is the parallel force at rho = tau / F
    out = wrench_sum(pic, np.array([0.0, 2.0, 0.0]), np.array([0.0, 0.0, 1.5]), scale=0.4)
    np.testing.assert_allclose(_segment(out["f3"])[:, 0], [0.75, 0.75], atol=1e-12)
    # the couple is the line at infinity: a glyph (turning counter-clockwise, tau > 0), no line
    assert _part(out["f2"], "glyph")["ccw"] is True
    assert not any(p["p"] == "path" for p in out["f2"]["parts"])
    assert "couple (line at ∞)" in _part(out["f2"], "text")["text"]
    _drawn_without_warnings(pic)


def test_velocity_step_lever_rule(pic):
    # thesis 4.48-4.49: V_i = V_{i-1} + beta (S - V_{i-1}), beta = qd / (qd + w_{i-1}), w_i = w_{i-1} + qd
    Vp, S, wp, qd = np.array([-1.0, 0.5]), np.array([1.0, 1.5]), 0.8, 1.7
    out = velocity_step(pic, wp * unit_rotation(Vp), unit_rotation(S), qd, dim_offset=0.25)
    beta = qd / (qd + wp)
    np.testing.assert_allclose(_at(out["v"]), Vp + beta * (S - Vp), atol=1e-12)
    assert "ω = 2.5 rad/s" in out["v"]["desc"]
    np.testing.assert_allclose(_at(out["joint"]), S, atol=1e-12)
    # the dimension k: parallel to Vp -> S, as long, 0.25 to its left
    line = np.asarray(out["k"]["parts"][0]["xy"])
    n = np.array([-(S - Vp)[1], (S - Vp)[0]]) / np.linalg.norm(S - Vp)
    np.testing.assert_allclose(line, [Vp + 0.25 * n, S + 0.25 * n], atol=1e-12)
    assert f"{np.linalg.norm(S - Vp):.4g} m" in out["k"]["desc"]


@pytest.mark.parametrize("V", [(0.0, 0.0), (-0.5, 0.8)])
def test_acceleration_step_bias_and_offset(pic, V):
    # 4.53: kappa = w qd (S - V) rotated: a translation of magnitude |w qd k|;
    # 4.54: s qdd + kappa is a rotation qdd about a point at |w qd k / qdd| from the joint
    V, S, w, qd, qdd = np.array(V), np.array([2.0, 1.0]), 1.3, 0.9, 2.5
    ap = 0.4 * unit_rotation([-1.0, 1.0])
    out = acceleration_step(pic, ap, w * unit_rotation(V), unit_rotation(S), qd, qdd)
    # by hand, with twists [vx, vy, w] (a rotation w about P is w [Py, -Px, 1]):
    # (w, u) x (w', u') = (0, w z x u' + u x w' z) gives kappa = [w qd (S - V)_x, w qd (S - V)_y, 0]
    kappa_hand = np.array([w * qd * (S - V)[0], w * qd * (S - V)[1], 0.0])
    k = np.linalg.norm(S - V)
    np.testing.assert_allclose(out["values"]["bias"], kappa_hand, rtol=1e-12, atol=1e-15)
    # the bias is an ideal point: an edge arrow along S - V, no marker
    arrow = _part(out["bias"], "arrow")
    assert not any(p["p"] == "mark" for p in out["bias"]["parts"])
    d = (S - V) * (pic.kx, pic.ky)
    assert _cross(d, [arrow["dx"], arrow["dy"]]) == pytest.approx(0.0, abs=1e-9 * np.hypot(*d) * 40)
    assert np.dot(d, [arrow["dx"], arrow["dy"]]) > 0
    assert f"{abs(w * qd * k):.4g} m/s²" in out["bias"]["desc"]
    combo = _at(out["joint_total"])
    assert np.linalg.norm(combo - S) == pytest.approx(abs(w * qd * k / qdd))
    a = ap + qdd * unit_rotation(S) + kappa_hand
    a_xy = np.array([-a[1] / a[2], a[0] / a[2]])
    np.testing.assert_allclose(_at(out["a"]), a_xy, atol=1e-12)
    assert _on_segment_line(a_xy, _segment(out["lever"]))              # a on the line a_prev - combo
    assert _on_segment_line(combo, _segment(out["lever"]))
    assert _on_segment_line(S, _segment(out["joint_lever"]))           # combo on the joint's line
    assert _on_segment_line(combo, _segment(out["joint_lever"]))
    _drawn_without_warnings(pic)


def test_newton_euler_one_body(pic):
    # thesis 4.7, 4.55-4.56: p is the centripetal force m l w^2 through the centre of mass toward
    # the pole of v; I a the axis of percussion at rho^2/d; f_net = I a + p
    m, c, J = 2.0, np.array([1.0, 0.0]), 0.18
    Q, w = np.array([-1.0, 0.0]), 1.5                      # v: rotation about Q, l = 2
    A, alpha = np.array([1.0, -1.0]), 2.0                  # a: rotation about A, d = 1
    out = newton_euler(pic, inertia_matrix(m, c, J), alpha * unit_rotation(A), w * unit_rotation(Q),
                       scale=0.1, positions=(-1.0, -0.9, 1.0))
    rho2, l, d = J / m, 2.0, 1.0
    # p: along -x (toward Q) through y = 0, m l w^2 long at 0.1 per newton, centred 0.9 before c's foot
    np.testing.assert_allclose(_segment(out["p"])[:, 1], [0.0, 0.0], atol=1e-12)
    a = _part(out["p"], "arrow")
    assert a["dx"] / pic.kx == pytest.approx(-0.1 * m * l * w * w)
    assert a["x"] + a["dx"] / pic.kx / 2 == pytest.approx(c[0] + 0.9)
    # I a: along -x (alpha about A below c) through y = rho^2 / d
    np.testing.assert_allclose(_segment(out["Ia"])[:, 1], [rho2 / d] * 2, atol=1e-12)
    # f_net = I a + p = (-m alpha d - m l w^2, 0) through y = tau / F with tau = m alpha rho^2 (4.55)
    F = m * alpha * d + m * l * w * w
    np.testing.assert_allclose(_segment(out["f_net"])[:, 1], [m * alpha * rho2 / F] * 2, atol=1e-12)
    assert out["f_net"]["width"] > out["Ia"]["width"]
    # the inertia's circle of gyration: radius rho about c
    e = _part(out["inertia"], "ellipse")
    np.testing.assert_allclose([e["x"], e["y"]], c, atol=1e-12)
    assert math.hypot(e["m"][0], e["m"][2]) == pytest.approx(math.sqrt(rho2))
    np.testing.assert_allclose(_at(out["v"]), Q, atol=1e-12)
    np.testing.assert_allclose(_at(out["a"]), A, atol=1e-12)
    _drawn_without_warnings(pic)


def test_chain_state_of_figs_4_7_and_4_8():
    """The state drawn in Figs 4.7/4.8: the drawn poles obey 4.48, 4.49 and 4.54."""
    from planargeo.algorithms.rnea import newton_euler as rnea
    from planargeo.gallery.figures.ch4 import Q47, QD47, QDD47, _chain3

    w = rnea(_chain3(), Q47, QD47, QDD47)
    i = 2
    J = w.origin[i]
    w_prev, qd, qdd = w.v[i - 1][2], QD47[i], QDD47[i]
    P_prev = np.array([-w.v[i - 1][1], w.v[i - 1][0]]) / w_prev
    k = np.linalg.norm(J - P_prev)
    beta = qd / (qd + w_prev)                                    # (4.48)
    pic = Picture((-4, 4, -4, 4), size=(400, 400), ticks=False)
    out = velocity_step(pic, w.v[i - 1], w.s(i)[:, 0], qd)
    np.testing.assert_allclose(_at(out["v"]), P_prev + beta * (J - P_prev), atol=1e-12)
    np.testing.assert_allclose(out["values"]["v"], w.v[i], atol=1e-12)
    assert f"ω = {w_prev + qd:.4g} rad/s" in out["v"]["desc"]   # (4.49)
    pic = Picture((-4, 4, -4, 4), size=(400, 400), ticks=False)
    out = acceleration_step(pic, w.a[i - 1], w.v[i - 1], w.s(i)[:, 0], qd, qdd)
    np.testing.assert_allclose(out["values"]["bias"], w.kappa[i], atol=1e-12)
    np.testing.assert_allclose(out["values"]["a"], w.a[i], atol=1e-12)
    assert np.linalg.norm(_at(out["joint_total"]) - J) == pytest.approx(abs(w_prev * qd * k / qdd))  # (4.54)


def test_every_element_explains_itself(pic):
    outs = [twist_sum(pic, unit_rotation([0, 0]), 2 * unit_rotation([3, 0]), prefix="t "),
            wrench_sum(pic, [1.0, 0.0, -1.0], [0.0, 1.0, 2.0], scale=0.5, prefix="w "),
            velocity_step(pic, unit_rotation([-1, 0]), unit_rotation([1, 1]), 1.0, prefix="v "),
            acceleration_step(pic, unit_rotation([0, 1]), unit_rotation([0, 0]), unit_rotation([2, 0]),
                              1.0, 1.0, prefix="a "),
            newton_euler(pic, inertia_matrix(1.0, [1.0, 0.0], 0.1), unit_rotation([0, -1]),
                         unit_rotation([-1, 0]), scale=0.1, prefix="n ")]
    made = [el for out in outs for k, el in out.items() if k != "values"]
    assert len(made) == len(pic.elements) == len({el["id"] for el in made})
    for el in made:
        assert el["id"] and el["role"] and el["symbol"], el["id"]
        assert ": " in el["desc"] and "\n" not in el["desc"], el["id"]


def test_bad_input_is_refused_by_name(pic):
    with pytest.raises(ShapeError, match="v1 must have shape"):
        twist_sum(pic, [1.0, 2.0], [0.0, 0.0, 1.0])
    with pytest.raises(InputError, match="pic must be a Picture"):
        twist_sum(None, [0.0, 0.0, 1.0], [0.0, 0.0, 1.0])
    with pytest.raises(InputError, match="labels must have 3 entries"):
        twist_sum(pic, [0.0, 0.0, 1.0], [1.0, 0.0, 1.0], labels=("a", "b"))
    with pytest.raises(InputError, match="scale must be a positive number"):
        wrench_sum(pic, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], scale=-1.0)
    with pytest.raises(NonFiniteError, match="qd must be finite"):
        velocity_step(pic, [0.0, 0.0, 1.0], [0.0, -1.0, 1.0], float("nan"))
    with pytest.raises(ShapeError, match="I must have shape"):
        newton_euler(pic, np.eye(2), [0.0, 0.0, 1.0], [0.0, 0.0, 1.0])
    with pytest.raises(InputError, match="qdd must be numeric"):
        acceleration_step(pic, [0, 0, 0], [0, 0, 1], [0, -1, 1], 1.0, "fast")
    assert pic.elements == []                     # nothing half-drawn


def test_sum_arrow_head_shows_on_its_heavy_line(pic):
    # the sum's line of action is cut where its arrow's head sits (the head is narrower than the line)
    f1, f2 = np.array([1.0, 0.0, -1.0]), np.array([0.0, 1.0, 2.0])
    out = wrench_sum(pic, f1, f2, scale=1.0)
    pieces = [np.asarray(p["xy"]) for p in out["f3"]["parts"] if p["p"] == "path"]
    assert len(pieces) == 2
    tip = np.array([2.0, 1.0]) + (f1 + f2)[:2]                   # P + scale f3 (4.33)
    a = _part(out["f3"], "arrow")
    np.testing.assert_allclose([a["x"] + a["dx"] / pic.kx, a["y"] + a["dy"] / pic.ky], tip, atol=1e-12)
    u = (f1 + f2)[:2] / np.hypot(*(f1 + f2)[:2])
    along = sorted(float((q - tip) @ u) for piece in pieces for q in piece)
    assert along[1] < 0.0 < along[2]
    assert all(_on_segment_line(q, np.array([[2.0, 1.0], tip])) for piece in pieces for q in piece)
    # the labels sit at the arrows' tips (the placer's first choice)
    t = _part(out["f1"], "text")
    np.testing.assert_allclose([t["x"], t["y"]], [3.0, 1.0], atol=1e-12)


def test_couple_glyphs_in_their_corners(pic):
    out = wrench_sum(pic, [0.0, 0.0, 1.0], [0.0, 0.0, -2.0], labels=("$f_1$", "$f_2$ = couple τ", "$f_3$"))
    g1, g2, g3 = (_part(out[k], "glyph") for k in ("f1", "f2", "f3"))
    assert g1["x"] > 0 > g2["x"] and g3["x"] == g1["x"] and g3["y"] < g1["y"]   # f3 one row under f1
    assert g1["ccw"] and not g2["ccw"] and not g3["ccw"]              # tau3 = 1 - 2 < 0
    assert _part(out["f2"], "text")["text"] == "f₂ = couple τ"
    assert _part(out["f1"], "text")["text"] == "f₁: couple (line at ∞)"
