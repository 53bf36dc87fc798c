"""The geometry of a picture's points, lines and conics, against closed forms and independent methods.

planargeo.draw.geometry (clip_line, conic_geometry, conic_curves, arc_glyph) and
Picture.point / line / conic, which draw twists as poles, wrenches as lines and
inertias as conics; then the parts of draw/ that stay matplotlib (charts, legend,
fit_view, the ``ax=None`` rule).  Ported from the tests of the former matplotlib
artists (tests/test_draw_artists.py, test_draw_mechanism.py, test_draw_signatures.py).
"""
from __future__ import annotations

import importlib
import inspect
import io
import math
import pkgutil
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, settings, strategies as st  # noqa: E402

import planargeo.draw  # noqa: E402
from planargeo.draw import sketch  # noqa: E402
from planargeo.draw.geometry import arc_glyph, clip_line, conic_curves, conic_geometry  # noqa: E402
from planargeo.draw.picture import PX_PER_PT, Picture  # noqa: E402
from planargeo.draw.render import figure  # noqa: E402
from planargeo.errors import InputError, NonFiniteError, ShapeError  # noqa: E402
from planargeo.screws.twists import inertia_matrix  # noqa: E402

BOX = (-3.0, 4.0, -2.0, 5.0)
finite = st.floats(-10, 10, allow_nan=False, allow_infinity=False)


def _pic(view=BOX, size=(280, 280)) -> Picture:
    """A picture with no margin around its plot area (its box is ``view``, widened to equal scales)."""
    return Picture(view, size=size, ticks=False, margin=(0, 0, 0, 0))


def _el(pic, id_):
    return next(e for e in pic.elements if e["id"] == id_)


def _parts(el, kind):
    return [p for p in el["parts"] if p["p"] == kind]


def _on_boundary(q, box, tol=1e-9):
    x0, x1, y0, y1 = box
    inside = x0 - tol <= q[0] <= x1 + tol and y0 - tol <= q[1] <= y1 + tol
    on = min(abs(q[0] - x0), abs(q[0] - x1), abs(q[1] - y0), abs(q[1] - y1)) <= tol
    return inside and on


def _curve_points(el) -> np.ndarray:
    """Every drawn point of a conic element: its path vertices and its ellipse sampled."""
    out = [np.zeros((0, 2))]
    for p in el["parts"]:
        if p["p"] == "path":
            out.append(np.asarray(p["xy"], float))
        elif p["p"] == "ellipse":
            t = np.linspace(0.0, 2 * np.pi, 97)
            a, b, c, d = p["m"]
            out.append(np.column_stack([p["x"] + a * np.cos(t) + b * np.sin(t),
                                        p["y"] + c * np.cos(t) + d * np.sin(t)]))
    return np.vstack(out)


def _check_on_conic(xy, C):
    """Each point (x, y) satisfies pᵀCp = 0 with p = [y, −x, 1], relative to the gradient's size."""
    xy = xy[np.all(np.isfinite(xy), axis=1)]
    assert len(xy) > 50
    P = np.column_stack([xy[:, 1], -xy[:, 0], np.ones(len(xy))])   # package points
    val = np.einsum("ni,ij,nj->n", P, C, P)
    grad = np.linalg.norm(P @ C, axis=1) * (1 + np.linalg.norm(xy, axis=1))
    assert np.max(np.abs(val) / grad) < 1e-8


def _turn(xy, c) -> float:
    """Signed angle swept by the polyline ``xy`` about ``c`` (positive: counter-clockwise)."""
    a = np.unwrap(np.arctan2(xy[:, 1] - c[1], xy[:, 0] - c[0]))
    return float(a[-1] - a[0])


# ----------------------------------------------------------------- line clipping
@given(finite, finite, finite)
def test_clipped_endpoints_on_line_and_boundary(fx, fy, tz):
    seg = clip_line([fx, fy, tz], BOX)
    if fx == 0 and fy == 0:
        assert seg is None
        return
    if seg is None:
        # the line misses the box: the box corners all lie on one side (4.27)
        xs = [(BOX[0], BOX[2]), (BOX[0], BOX[3]), (BOX[1], BOX[2]), (BOX[1], BOX[3])]
        vals = [tz + y * fx - x * fy for x, y in xs]
        assert all(v > 0 for v in vals) or all(v < 0 for v in vals)
        return
    F = np.hypot(fx, fy)
    for x, y in seg:
        assert abs(tz + y * fx - x * fy) / F <= 1e-9 * (1 + abs(tz) / F)  # on the line (4.27)
        assert _on_boundary((x, y), BOX)
    d = seg[1] - seg[0]
    assert d @ [fx, fy] >= 0                                            # along the force


def test_clip_hand_cases():
    # vertical line x = 2 (force along +y through (2, 0)): tz = x fy - y fx = 2
    np.testing.assert_allclose(clip_line([0.0, 1.0, 2.0], BOX), [[2.0, -2.0], [2.0, 5.0]])
    assert clip_line([0.0, 1.0, 10.0], BOX) is None   # x = 10, outside
    assert clip_line([0.0, 0.0, 1.0], BOX) is None    # the line at infinity


def test_a_pictures_line_is_clipped_to_its_own_view():
    """The drawn line satisfies 4.27 with its ends on the view's edge, in any view."""
    for view in (BOX, (-10.0, 10.0, -10.0, 10.0)):
        pic = _pic(view)
        pic.line("f", [1.0, -2.0, 0.5])
        (path,) = _parts(_el(pic, "f"), "path")
        for q in path["xy"]:
            assert abs(0.5 + q[1] * 1.0 - q[0] * -2.0) < 1e-9
            assert _on_boundary(q, pic.box)


# ----------------------------------------------------------------- points
@given(finite, finite, st.floats(0.05, 5) | st.floats(-5, -0.05))
def test_pole_sits_at_twist_pole_and_its_glyph_turns_with_omega(x, y, w):
    pic = _pic((-12.0, 12.0, -12.0, 12.0))
    pic.point("v", np.array([w * y, -w * x, w]), symbol="v")   # rotation w about (x, y) (4.10)
    el = _el(pic, "v")
    (mark,) = _parts(el, "mark")
    np.testing.assert_allclose([mark["x"], mark["y"]], [x, y], atol=1e-9)
    (glyph,) = _parts(el, "glyph")
    assert (glyph["x"], glyph["y"]) == (mark["x"], mark["y"])
    # the glyph drawn from the part turns counter-clockwise for w > 0 (its arc and its head)
    arc, head = arc_glyph(glyph["r"], glyph["ccw"])
    assert np.sign(_turn(arc, (0.0, 0.0))) == np.sign(w)
    tang = head[0] - arc[-1]                          # the head points on along the arc
    assert np.sign(arc[-1][0] * tang[1] - arc[-1][1] * tang[0]) == np.sign(w)


def test_glyph_grows_with_omega():
    pic = _pic()
    pic.point("slow", [0.0, 0.0, 0.5])
    pic.point("fast", [0.0, 0.0, 2.0])
    r = [_parts(_el(pic, k), "glyph")[0]["r"] for k in ("slow", "fast")]
    assert r[1] > 1.5 * r[0]


def test_ideal_point_is_an_arrow_at_the_edge():
    """A translation along +x: its point lies at +y infinity, an arrow along +x near the top edge."""
    pic = _pic()
    pic.point("u", [1.0, 0.0, 0.0], symbol="u")
    el = _el(pic, "u")
    assert not _parts(el, "mark") and not _parts(el, "glyph")
    (arrow,) = _parts(el, "arrow")
    assert arrow["dx"] > 0 and abs(arrow["dy"]) < 1e-9
    x0, x1, y0, y1 = pic.box
    assert arrow["y"] > y0 + 0.75 * (y1 - y0)
    assert x0 < arrow["x"] < x1 and arrow["y"] < y1
    assert "∞" in _parts(el, "text")[0]["text"]


def test_point_beyond_float_range_is_drawn_as_ideal():
    """[1e200, 1, 1e-200]: the pole (−1e200, 1e400) overflows; it is drawn like the ideal point
    [1e200, 1, 0], the arrow at the edge, with no warning."""
    pic = _pic()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pic.point("far", [1e200, 1.0, 1e-200])
        pic.point("ideal", [1e200, 1.0, 0.0])
        d = pic.to_dict()
        figure(d)
    far, ideal = (_el(pic, k) for k in ("far", "ideal"))
    assert not _parts(far, "mark")
    (a,), (b,) = _parts(far, "arrow"), _parts(ideal, "arrow")
    np.testing.assert_allclose([a[k] for k in ("x", "y", "dx", "dy")], [b[k] for k in ("x", "y", "dx", "dy")])


# ----------------------------------------------------------------- lines
def test_line_arrow_at_the_anchors_foot_along_the_force():
    # 2 N along +y on the line x = 1.5 (4.27: tz + y fx - x fy = 0 -> tz = 3); anchor (7, 1): foot (1.5, 1)
    pic = _pic()
    pic.line("f", [0.0, 2.0, 3.0], anchor=(7.0, 1.0), symbol="f")
    el = _el(pic, "f")
    (arrow,) = _parts(el, "arrow")
    assert (arrow["x"], arrow["y"]) == pytest.approx((1.5, 1.0))
    assert arrow["dx"] == pytest.approx(0.0, abs=1e-9) and arrow["dy"] > 0
    (text,) = _parts(el, "text")
    assert text["text"] == "f" and (text["x"], text["y"]) == pytest.approx((1.5, 1.0))
    assert np.isfinite([text["dx"], text["dy"]]).all()
    pic.line("g", [0.0, 2.0, 3.0], arrow=False)
    assert not _parts(_el(pic, "g"), "arrow")


@pytest.mark.parametrize("size", [1e-300, 1e-160, 1.0, 1e150, 1e300])
def test_line_and_arrow_of_any_finite_force(size):
    """Issue 23: a force of 1e-300 N (|f|² underflows) still has its line and arrow: the same line
    x = 1.5 along +y as [0, 2, 3] scaled, its arrow at the anchor's foot, pointing up."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pic = _pic()
        pic.line("f", [0.0, 2.0 * size, 3.0 * size], anchor=(7.0, 1.0))
        off = _pic((5.0, 6.0, -2.0, 5.0))
        off.line("f", [0.0, 2.0 * size, 3.0 * size])       # off the view: nothing, no warning
        figure(pic.to_dict()), figure(off.to_dict())
    el = _el(pic, "f")
    (path,) = _parts(el, "path")
    np.testing.assert_allclose(np.asarray(path["xy"])[:, 0], 1.5, rtol=1e-12)
    (arrow,) = _parts(el, "arrow")
    assert (arrow["x"], arrow["y"]) == pytest.approx((1.5, 1.0), rel=1e-12)
    assert arrow["dy"] > 0 and arrow["dx"] == pytest.approx(0.0, abs=1e-9)
    assert _el(off, "f")["parts"] == []


def test_couple_glyph_turns_with_the_moment():
    pic = _pic()
    pic.line("ccw", [0.0, 0.0, 1.0])
    pic.line("cw", [0.0, 0.0, -1.0])
    for k, sign in (("ccw", 1), ("cw", -1)):
        el = _el(pic, k)
        assert not _parts(el, "path")
        (glyph,) = _parts(el, "glyph")
        arc, _ = arc_glyph(glyph["r"], glyph["ccw"])
        assert np.sign(_turn(arc, (0.0, 0.0))) == sign
        assert "line at ∞" in _parts(el, "text")[0]["text"]


# ----------------------------------------------------------------- conics
def _rand_affine(rng):
    th = rng.uniform(0, 2 * np.pi)
    R = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
    H = np.eye(3)
    H[:2, :2] = R @ np.diag(rng.uniform(0.3, 3, 2))
    H[:2, 2] = rng.uniform(-2, 2, 2)
    return H


def _package_conic(E):
    """The package's matrix (points p = [y, −x, 1]) of the Euclidean conic E (points [x, y, 1])."""
    M = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    Mi = np.linalg.inv(M)
    return Mi.T @ E @ Mi


@pytest.mark.parametrize("kind,E0", [
    ("ellipse", np.diag([1.0, 1.0, -1.0])),
    ("hyperbola", np.diag([1.0, -1.0, -1.0])),
    ("hyperbola", np.diag([-1.0, 1.0, -1.0])),
    ("parabola", np.array([[1.0, 0, 0], [0, 0, -0.5], [0, -0.5, 0]])),  # x^2 - y = 0
])
def test_conic_path_satisfies_equation(rng, kind, E0):
    pic = _pic((-20.0, 20.0, -20.0, 20.0))
    for k in range(5):
        H = _rand_affine(rng)
        Hi = np.linalg.inv(H)
        C = _package_conic(Hi.T @ E0 @ Hi) * rng.uniform(-3, 3)   # the conic moved by H, any scale
        g = conic_geometry(C)
        assert g["kind"] == kind and not g["imaginary"]
        pic.conic(f"C{k}", C)
        _check_on_conic(_curve_points(_el(pic, f"C{k}")), C)


def test_hyperbola_has_both_branches():
    C = _package_conic(np.diag([1.0, -1.0, -1.0]))     # x² − y² = 1
    pic = _pic()
    pic.conic("C", C)
    paths = _parts(_el(pic, "C"), "path")
    assert len(paths) == 2
    xs = [np.asarray(p["xy"])[:, 0] for p in paths]
    assert sorted(np.sign([x.mean() for x in xs])) == [-1.0, 1.0]
    assert all(np.all(x > 0) or np.all(x < 0) for x in xs)         # one branch per path


def test_inertia_drawn_as_gyration_circle():
    m, c, J = 2.0, np.array([1.0, 0.5]), 0.5
    rho = np.sqrt(J / m)
    I = inertia_matrix(m, c, J)
    g = conic_geometry(I)
    assert g["imaginary"] and g["kind"] == "ellipse"
    pic = _pic()
    pic.conic("I", I, role="inertia")
    el = _el(pic, "I")
    np.testing.assert_allclose(np.linalg.norm(_curve_points(el) - c, axis=1), rho, rtol=1e-10)
    assert el["dash"]                                       # dashed: an imaginary conic's stand-in
    (mark,) = _parts(el, "mark")
    np.testing.assert_allclose([mark["x"], mark["y"]], c)


def test_inertia_circle_is_screws_drawable_conic(rng):
    """The drawn inertia curve lies on SCREW's drawable_conic (the radius-of-gyration circle)."""
    from planargeo.screws.inertia import drawable_conic

    pic = _pic((-5.0, 5.0, -5.0, 5.0))
    for k in range(5):
        I = inertia_matrix(rng.uniform(0.5, 3), rng.uniform(-2, 2, 2), rng.uniform(0.1, 2))
        pic.conic(f"I{k}", I, role="inertia")
        _check_on_conic(_curve_points(_el(pic, f"I{k}")), drawable_conic(I))


def test_imaginary_conic_drawn_as_geo_drawable_conic(rng):
    """Any definite conic (e.g. an articulated inertia) is drawn as conics.drawable_conic."""
    from planargeo.geometry.conics import drawable_conic

    pic = _pic((-5.0, 5.0, -5.0, 5.0))
    for k in range(5):
        B = rng.normal(size=(3, 3))
        C = B @ B.T + 0.5 * np.eye(3)      # positive definite: imaginary
        g = conic_geometry(C)
        assert g["imaginary"] and g["kind"] == "ellipse"
        pic.conic(f"C{k}", C)
        _check_on_conic(_curve_points(_el(pic, f"C{k}")), drawable_conic(C))


@given(st.lists(st.floats(-3, 3), min_size=6, max_size=6))
def test_conic_kind_agrees_with_geo_classify(c):
    """An independent classifier (planargeo.geometry.conics.classify) agrees with the drawing's."""
    from planargeo.geometry.conics import classify

    a, b, cc, d, e, f = c
    C = np.array([[a, b, d], [b, cc, e], [d, e, f]])
    if np.abs(C).max() < 1e-3:
        return
    ev = np.linalg.eigvalsh(C)
    A = np.linalg.eigvalsh(C[:2, :2])
    # stay away from class boundaries (both classifiers use tolerances there)
    if np.min(np.abs(ev)) < 1e-3 * np.abs(ev).max() or np.min(np.abs(A)) < 1e-3 * np.abs(ev).max():
        return
    t = classify(C)
    g = conic_geometry(C)
    if t.reality == "imaginary":
        assert g["imaginary"] and g["kind"] == "ellipse"
    else:
        assert g["kind"] == t.kind and not g["imaginary"]


def test_degenerate_conics():
    l1, l2 = np.array([1.0, 2.0, 0.5]), np.array([0.0, 1.0, -1.0])
    l3 = l1 + [0, 0, 1.0]
    crossing = np.outer(l1, l2) + np.outer(l2, l1)
    parallel = np.outer(l1, l3) + np.outer(l3, l1)
    double = np.outer(l1, l1)
    at_inf = np.outer(l1, [0, 0, 1.0]) + np.outer([0, 0, 1.0], l1)      # l1 and the line at infinity
    pic = _pic()
    # (a double line may come out as two copies of itself: round-off in the discriminant)
    for k, (C, n) in enumerate(((crossing, (2,)), (parallel, (2,)), (double, (1, 2)), (at_inf, (1,)))):
        g = conic_geometry(C)
        assert g["kind"] == "lines" and len(g["lines"]) in n
        for ln in g["lines"]:      # each drawn line is one of the factors (parallel homogeneous vectors)
            assert any(np.linalg.norm(np.cross(ln, f)) < 1e-7 * np.linalg.norm(ln) * np.linalg.norm(f)
                       for f in (l1, l2, l3))
        pic.conic(f"C{k}", C)
        segs = _parts(_el(pic, f"C{k}"), "path")
        assert len(segs) == len(g["lines"])
        for s in segs:   # clipped to the view, on one of the factors (a double root: √ε off, 3e-9)
            assert all(min(abs(f[2] + y * f[0] - x * f[1]) / np.hypot(*f[:2]) for f in (l1, l2, l3)) < 1e-7
                       and _on_boundary((x, y), pic.box) for x, y in s["xy"])
    assert conic_geometry(np.diag([1.0, 1.0, 0.0]))["kind"] == "point"    # x² + y² = 0: the origin
    pic.conic("O", np.diag([1.0, 1.0, 0.0]))
    (mark,) = _parts(_el(pic, "O"), "mark")
    assert (mark["x"], mark["y"]) == pytest.approx((0.0, 0.0), abs=1e-12)
    assert conic_curves(np.zeros((3, 3)), BOX) == []
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        figure(pic.to_dict())


def test_special_elements_draw_without_warnings():
    pic = Picture(BOX, size=(300, 300))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pic.point("ideal", [1.0, 2.0, 0.0], symbol="ideal")
        pic.point("zero", [0.0, 0.0, 0.0])              # zero twist: nothing
        pic.line("couple", [0.0, 0.0, 2.0], symbol="τ")   # line at infinity: couple glyph
        pic.line("nothing", [0.0, 0.0, 0.0])             # zero wrench: nothing
        pic.line("f1", [1.0, 0.0, 0.0])
        pic.line("f2", [2.0, 0.0, 1.0])                   # parallel lines
        pic.line("out", [0.0, 1.0, 100.0])                # outside the view
        pic.conic("empty", np.zeros((3, 3)))
        fig = figure(pic.to_dict())
        fig.savefig(io.BytesIO(), format="svg")
    assert [_el(pic, k)["parts"] for k in ("zero", "nothing", "out", "empty")] == [[], [], [], []]


def test_bad_conic_is_refused_by_name():
    with pytest.raises(InputError, match="conic must be symmetric"):
        _pic().conic("C", [[1, 2, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(InputError, match="used twice"):
        pic = _pic()
        pic.line("f", [1.0, 0.0, 0.0])
        pic.point("f", [0.0, 0.0, 1.0])


def test_bad_point_or_line_is_refused_by_name():
    pic = _pic()
    with pytest.raises(ShapeError, match="point"):
        pic.point("a", [1.0, 2.0])
    with pytest.raises(NonFiniteError, match="point"):
        pic.point("b", [np.nan, 0.0, 1.0])
    with pytest.raises(NonFiniteError, match="line"):
        pic.line("c", [np.nan, 0.0, 1.0])
    with pytest.raises(InputError, match="role"):
        pic.point("d", [0.0, 0.0, 1.0], role="nonsense")


# ----------------------------------------------------------------- a model's joints and contacts
def test_prismatic_slider_follows_the_joint_axis_not_the_body_angle():
    from planargeo.mechanics.kinematics import kinematics
    from planargeo.mechanics.model import Body, Joint, Model

    m = Model([Body(1.0, (0.3, 0.0), 0.1)], [Joint("revolute_prismatic", (0.0, 0.0, 0.5))], [-1])
    d = kinematics(m, [0.4, 1.2])                    # slide 0.4 along 0.5 rad, then turn by 1.2
    pic = _pic()
    out = sketch.model(pic, m, d, ground=False)
    (block,) = [e for e in out["joints"] if e["id"] == "slider 1"]
    xy = np.asarray(_parts(block, "path")[0]["xy"])
    e = xy[1] - xy[0]                                # the block's long side, along the slide
    assert math.atan2(e[1], e[0]) == pytest.approx(0.5)
    np.testing.assert_allclose(xy[:4].mean(axis=0), 0.4 * np.array([math.cos(0.5), math.sin(0.5)]))


def test_slider_crank_guide_from_the_contact():
    from planargeo.mechanics.kinematics import kinematics
    from planargeo.scenes import build

    res = build("slider-crank")                      # r = 2.29, l = 5, t = 0.5, psi = 0.4
    d = kinematics(res.model, res.state["q"])
    pic = _pic((-4.0, 4.0, -2.0, 8.0))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = sketch.model(pic, res.model, d, width=0.3)
    # hand: the piston slides on x = 0; its joint is at height r sin psi + sqrt(l² - r² cos² psi)
    h = 2.29 * np.sin(0.4) + np.sqrt(25.0 - (2.29 * np.cos(0.4)) ** 2)
    p0, e, n, hw, (s0, s1) = sketch.slider_guide(res.model.contacts[0], d.pose, out["shapes"][2])
    np.testing.assert_allclose(e, [0.0, 1.0], atol=1e-12)
    assert hw == pytest.approx(0.15 + 0.04)          # half the drawn width plus the clearance
    # the piston link runs from its joint (h) to 2t above it, buffered by the half-width 0.15
    assert p0[1] + s0 == pytest.approx(h - 0.15 - 0.3) and p0[1] + s1 == pytest.approx(h + 1.0 + 0.15 + 0.3)
    (contact,) = out["contacts"]
    walls = [np.asarray(_parts(w, "path")[0]["xy"]) for w in contact if ":wall" in w["id"]]
    assert len(walls) == 2
    np.testing.assert_allclose(sorted(w[:, 0].mean() for w in walls), [-0.19, 0.19], atol=1e-12)
    for w in walls:                                  # vertical, as long as the guide
        np.testing.assert_allclose(np.ptp(w[:, 0]), 0.0, atol=1e-12)
        assert np.ptp(w[:, 1]) == pytest.approx(s1 - s0)


def test_pin_contacts_drawn_at_the_tips():
    from planargeo.mechanics.kinematics import kinematics
    from planargeo.scenes import build

    res = build("constrained-tree")
    d = kinematics(res.model, res.state["q"])
    out = sketch.model(_pic((-6.0, 6.0, -6.0, 6.0)), res.model, d)
    assert len(out["contacts"]) == len(res.model.contacts) == 2
    for (sq,), c in zip(out["contacts"], res.model.contacts):
        x, y, th = d.pose[c.a]
        tip = np.array([x + np.cos(th), y + np.sin(th)])          # point_a = (L, 0), L = 1
        np.testing.assert_allclose(np.asarray(_parts(sq, "path")[0]["xy"]).mean(axis=0), tip, atol=1e-12)


# ----------------------------------------------------------------- charts, legend, style, views
def test_charts_curves_and_polar_axes():
    """Each curve gets its own colour and dash; a polar chart needs a polar axes."""
    from planargeo.draw.charts import CURVE_COLORS, plot_curves, polar_curves

    fig, ax = plt.subplots()
    x = np.linspace(0.0, 1.0, 5)
    try:
        lines = plot_curves(x, [x, x ** 2], ["x", "x²"], ax, ylim=(0.0, 2.0),
                            legend=dict(ncol=2, loc="upper left"))
        np.testing.assert_array_equal(lines[1].get_ydata(), x ** 2)
        assert [ln.get_color() for ln in lines] == CURVE_COLORS[:2]
        assert lines[0].get_linestyle() != lines[1].get_linestyle()
        assert ax.get_ylim() == (0.0, 2.0) and ax.get_legend()._ncols == 2
        with pytest.raises(InputError, match="ax must be a polar axes"):
            polar_curves(x, [x], ["r"], ax)
    finally:
        plt.close(fig)
    fig = plt.figure()
    try:
        pax = fig.add_subplot(projection="polar")
        (ln,) = polar_curves(x, [1.0 + x], ["r"], rlabel="r/L")     # ax=None: the current (polar) axes
        assert ln.axes is pax
        np.testing.assert_array_equal(ln.get_xydata(), np.column_stack([x, 1.0 + x]))
    finally:
        plt.close(fig)


def test_legend_and_show_default_to_the_current_axes():
    """``ax=None`` means the current axes for the legend, for sketch.show and for setup_axes."""
    from planargeo.draw.style import SUM, legend, setup_axes

    fig = plt.figure()
    try:
        ax = fig.gca()
        leg = legend([("twist", "point", "a twist"), ("reaction", "sum-line", "a sum")])
        assert ax.get_legend() is leg
        assert [t.get_text() for t in leg.get_texts()] == ["a twist", "a sum"]
        assert leg.get_lines()[1].get_linewidth() == SUM["line"]["linewidth"] == 3.4   # a sum: heavier
        pic = sketch.panel(ax, [[0.0, 0.0], [1.0, 1.0]])
        pic.point("v", [0.0, 0.0, 1.0])
        drawn = sketch.show(pic)
        assert drawn and all(a.axes is ax for _, _, a in drawn)
        assert setup_axes((0, 2, 0, 1)) is ax and ax.get_xlim() == (0, 2)
    finally:
        plt.close(fig)


def test_style_and_legend_name_the_bad_argument():
    from planargeo.draw.style import legend, style, sum_style

    with pytest.raises(InputError, match="role must be one of .* got 'force'"):
        style("force")
    with pytest.raises(InputError, match="kind must be one of \\['line', 'point'\\], got 'arc'"):
        sum_style("arc")
    fig, ax = plt.subplots()
    try:
        with pytest.raises(InputError, match="legend item kind .* got 'dot'"):
            legend([("twist", "dot", "x")], ax)
    finally:
        plt.close(fig)
    assert style("wrench", linewidth=3.0)["linewidth"] == 3.0 and style("wrench")["linewidth"] == 1.8


def test_fit_view_keeps_a_folded_chain_and_its_size():
    """Most points coincide (a chain at bend ±180°) and round-off moves them by 1e-7: the view
    still holds the tip, 1 m away (a fit that kept only the coincident points: ×1e-7 axes)."""
    from planargeo.draw.layout import fit_view

    fig, ax = plt.subplots(figsize=(4, 4))
    rng = np.random.default_rng(3)
    try:
        for _ in range(50):
            base = rng.normal(0, 2, 2)
            tip = base + rng.normal(0, 1, 2)
            folded = np.vstack([base + rng.normal(0, 1e-7, (6, 2)), tip])
            poles = base + rng.normal(0, 1e8, (2, 2))
            for pts, kw in ((folded, {}), (np.vstack([folded, poles]), {"keep": folded}),
                            (poles[:1], {"keep": folded, "min_span": 3.0})):
                fit_view(pts, ax=ax, margin=0.1, **kw)
                (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
                for p in folded:
                    assert x0 <= p[0] <= x1 and y0 <= p[1] <= y1
                size = max(np.ptp(folded, axis=0).max(), kw.get("min_span", 0.0))
                assert min(x1 - x0, y1 - y0) >= size
                assert max(x1 - x0, y1 - y0) < 10 * size + 10      # the far poles are left out
    finally:
        plt.close(fig)


def test_fit_view_refuses_what_is_no_size():
    from planargeo.draw.layout import fit_box, fit_view

    fig, ax = plt.subplots()
    try:
        with pytest.raises(InputError, match="min_span"):
            fit_view([[0, 0], [1, 1]], ax=ax, min_span=float("nan"))
        with pytest.raises(InputError, match="margin"):
            fit_view([[0, 0], [1, 1]], ax=ax, margin=-0.1)
        with pytest.raises(InputError, match="no finite point"):
            fit_view([[np.nan, 0.0]], ax=ax)
        with pytest.raises(InputError, match="aspect"):
            fit_box([[0, 0], [1, 1]], 0.0)
        with pytest.raises(TypeError):
            fit_view(ax, [[0, 0], [1, 1]])                  # the former ax-first order is gone
    finally:
        plt.close(fig)


# ----------------------------------------------------------------- ax=None, what is drawn first
#: sketch.panel sizes a picture to an axes and draws nothing: the axes is what it is made from.
EXEMPT = {"planargeo.draw.style.get_ax", "planargeo.draw.sketch.panel"}


def _public_functions():
    out = []
    for info in sorted(pkgutil.walk_packages(planargeo.draw.__path__, "planargeo.draw."), key=lambda m: m.name):
        mod = importlib.import_module(info.name)
        names = getattr(mod, "__all__", None)
        if names is None:
            names = [n for n, f in vars(mod).items() if not n.startswith("_") and inspect.isfunction(f)]
        for n in names:
            f = getattr(mod, n)
            if inspect.isfunction(f) and f.__module__ == mod.__name__:
                out.append((f"{mod.__name__}.{n}", f))
    return out


def _axes_functions():
    """Every public function of planargeo.draw (subpackages too) with an ``ax`` parameter or a
    drawing name (``draw_*``, ``plot_*``)."""
    out = []
    for qual, f in _public_functions():
        short = qual.rsplit(".", 1)[1]
        if qual not in EXEMPT and ("ax" in inspect.signature(f).parameters
                                   or short.startswith(("draw_", "plot_"))):
            out.append(pytest.param(qual, f, id=qual.removeprefix("planargeo.draw.")))
    return out


def ax_problem(f) -> str | None:
    """What is wrong with ``f``'s ``ax`` parameter, or None when it follows the rule."""
    params = list(inspect.signature(f).parameters.values())
    ax = [p for p in params if p.name == "ax"]
    if not ax:
        return "has no ax parameter"
    p = ax[0]
    positional = [q for q in params if q.kind in (q.POSITIONAL_ONLY, q.POSITIONAL_OR_KEYWORD)]
    if positional and positional[0].name == "ax" and len(positional) > 1:
        return "takes ax as its first parameter"
    if p.kind is p.POSITIONAL_ONLY:
        return "takes ax positionally only"
    if p.default is not None:
        return f"ax has default {p.default!r}, not None"
    return None


def test_the_rule_itself():
    def good(x, ax=None, *, k=1):
        pass

    def kwonly(*args, ax=None):
        pass

    def first(ax, x):
        pass

    def nodefault(x, ax):
        pass

    def alone(ax=None):
        pass

    assert ax_problem(good) is None and ax_problem(kwonly) is None and ax_problem(alone) is None
    assert ax_problem(first) == "takes ax as its first parameter"
    assert ax_problem(nodefault) == "ax has default <class 'inspect._empty'>, not None"
    assert ax_problem(lambda x: 0) == "has no ax parameter"
    assert ax_problem(sketch.panel) == "takes ax as its first parameter"     # hence exempt


def test_the_functions_that_take_an_axes_are_inspected():
    names = {p.values[0] for p in _axes_functions()}
    assert {"planargeo.draw.charts.plot_curves", "planargeo.draw.charts.polar_curves",
            "planargeo.draw.style.legend", "planargeo.draw.style.setup_axes",
            "planargeo.draw.layout.fit_view", "planargeo.draw.render.draw_picture",
            "planargeo.draw.sketch.show"} <= names


@pytest.mark.parametrize("qual, f", _axes_functions())
def test_ax_is_a_keyword_with_default_none(qual, f):
    """What is drawn comes first; ``ax`` is a parameter with default None (the current axes)."""
    problem = ax_problem(f)
    assert problem is None, f"{qual} {problem}"


# ----------------------------------------------------------------- a construction case the topic tests leave out
def test_power_velocity_at_an_off_origin_centre_of_mass_is_a_couple():
    """v about the centre of mass c ≠ O: p = I v = [0, 0, J ω] up to round-off, a pure couple
    (5.69-5.74); the powerless acceleration is then (numerically) a translation, on p, drawn at the edge."""
    from planargeo.draw.polars import power
    from planargeo.geometry.projective import is_ideal
    from planargeo.screws.twists import unit_rotation

    m, c, J, w = 2.0, np.array([0.3, -0.4]), 0.5, 1.5
    pic = Picture((-3.0, 3.0, -3.0, 3.0), size=(300, 300))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = power(pic, w * unit_rotation(c), inertia_matrix(m, c, J))
        figure(pic.to_dict())
    p, a = out["values"]["p"], out["values"]["a"]
    np.testing.assert_allclose(p, [0.0, 0.0, J * w], atol=1e-12)
    assert abs(p @ a) <= 1e-12 * np.linalg.norm(p) * np.linalg.norm(a)          # a lies on p
    assert bool(is_ideal(a)) or abs(a[2]) <= 1e-12 * np.hypot(a[0], a[1])
    el = {e["id"]: e for e in pic.elements}
    assert _parts(el["a"], "arrow") and not _parts(el["a"], "mark")           # a at the edge
    (f,) = _parts(el["f"], "path")                                           # f through v's pole c
    (x0, y0), (x1, y1) = f["xy"]
    assert abs((x1 - x0) * (c[1] - y0) - (y1 - y0) * (c[0] - x0)) < 1e-9 * math.hypot(x1 - x0, y1 - y0)


def test_the_momentum_at_an_off_origin_centre_of_mass_is_drawn():
    from planargeo.draw.polars import power
    from planargeo.screws.twists import unit_rotation

    c = np.array([0.3, -0.4])
    pic = Picture((-3.0, 3.0, -3.0, 3.0), size=(300, 300))
    power(pic, 1.5 * unit_rotation(c), inertia_matrix(2.0, c, 0.5))
    # p = I v is a couple up to round-off ([-1.1e-16, 5.6e-17, 0.75]: a line 7e15 m away, farther
    # than FAR view diagonals): drawn like the line at infinity, a couple glyph turning with τ > 0
    glyphs = [q for q in _el(pic, "p")["parts"] if q["p"] == "glyph"]
    assert len(glyphs) == 1 and glyphs[0]["ccw"] is True


def test_importing_the_drawing_package_loads_no_matplotlib():
    """``import planargeo.draw`` gives pictures without matplotlib: only the renderers load it."""
    import subprocess
    import sys

    code = ("import sys, planargeo.draw; "
            "print('matplotlib' in sys.modules, type(planargeo.draw.style).__name__, planargeo.draw.Picture.__name__)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert out == ["False", "module", "Picture"]


def test_a_models_bodies_joints_and_centres_of_mass_are_named_once():
    """Bodies named "body 1", "crank", "3": each description names the body once ("body 1", not
    "body body 1"); the centres of mass are c₁, c₂, c₃, the pins joint 1, 2, 3."""
    from planargeo.mechanics.kinematics import kinematics
    from planargeo.mechanics.model import Body, Joint, Model

    bodies = [Body(1.0, (0.5, 0.0), 0.1, name=n) for n in ("body 1", "crank", "3")]
    joints = [Joint("revolute", (0.0, 0.0, 0.0)), Joint("revolute", (1.0, 0.0, 0.0)),
              Joint("revolute", (1.0, 0.0, 0.0))]
    m = Model(bodies, joints, [-1, 0, 1], (0.0, 0.0))
    pic = _pic((-1.0, 4.0, -2.0, 2.0))
    out = sketch.model(pic, m, kinematics(m, np.zeros(3), np.zeros(3)))
    assert [e["desc"] for e in out["com"]] == ["centre of mass of body 1", "centre of mass of crank (body 2)",
                                               "centre of mass of body 3"]
    assert [e["symbol"] for e in out["com"]] == ["c₁", "c₂", "c₃"]
    assert [e["desc"] for e in out["bodies"]] == ["body 1", "crank (body 2)", "body 3"]
    pins = [e for e in out["joints"] if e["id"].startswith("joint")]
    assert [e["symbol"] for e in pins] == ["joint 1", "joint 2", "joint 3"]
    assert sketch.pin(pic, "p", (0.0, 0.0))["symbol"] == "joint"
    assert sketch.com(pic, "g", (0.0, 0.0))["symbol"] == "c"
    assert _el(pic, "g:disc")["symbol"] == "c"
    dims = [sketch.dimension(pic, k, (0, 0), (1, 0), t) for k, t in (("d1", "ρ = u/ω"), ("d2", "βk"))]
    assert [d["symbol"] for d in dims] == ["ρ", "βk"]
    assert sketch.dimension(pic, "d3", (0, 0), (1, 0), "2 m", symbol="L")["symbol"] == "L"
    # the dimension's text has the line's colour (its docstring says so): one colour per element
    assert dims[0]["color"] == planargeo.draw.COLORS["construct"]


@settings(max_examples=80, deadline=None)
@given(st.lists(st.floats(-1e3, 1e3), min_size=6, max_size=6))
def test_a_float_array_and_the_same_nested_lists_draw_one_conic(v):
    # an array's rows are read at once; the nested lists go through the full check: same geometry
    a, b, c, d, e, f = v
    C = np.array([[a, b, c], [b, d, e], [c, e, f]])
    g_arr, g_list = conic_geometry(C), conic_geometry(C.tolist())
    assert g_arr.keys() == g_list.keys() and g_arr["kind"] == g_list["kind"]
    for k in ("affine", "center", "point"):
        if k in g_arr:
            assert np.array_equal(g_arr[k], g_list[k])


def test_a_non_finite_or_huge_conic_array_is_checked_like_its_lists():
    for bad in (np.nan, np.inf, -np.inf):
        C = np.diag([1.0, 1.0, -1.0])
        C[1, 1] = bad
        with pytest.raises(NonFiniteError, match="conic must be finite"):
            conic_geometry(C)
    big = np.diag([1e308, 1e308, -1e308])        # finite, though its entries' sum is not
    assert conic_geometry(big)["kind"] == conic_geometry(big.tolist())["kind"]
    with pytest.raises(InputError, match="conic must be symmetric"):
        conic_geometry(np.array([[1.0, 2.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]]))
