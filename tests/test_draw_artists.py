"""Tests of planargeo.draw.artists: clipping, poles, conic paths."""
from __future__ import annotations

import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, strategies as st  # noqa: E402

from planargeo.draw.artists import (ConicArtist, LineArtist, PointArtist, clip_line,  # noqa: E402
                                    conic_geometry, plot_conic, plot_line, plot_point)
from planargeo.errors import InputError, NonFiniteError, ShapeError  # noqa: E402
from planargeo.screws.twists import inertia_matrix  # noqa: E402

BOX = (-3.0, 4.0, -2.0, 5.0)
finite = st.floats(-10, 10, allow_nan=False, allow_infinity=False)


@pytest.fixture
def ax():
    fig, ax = plt.subplots(figsize=(4, 4))
    ax.set_xlim(BOX[0], BOX[1])
    ax.set_ylim(BOX[2], BOX[3])
    ax.set_aspect("equal")
    yield ax
    plt.close(fig)


def _on_boundary(q, box, tol=1e-9):
    x0, x1, y0, y1 = box
    inside = x0 - tol <= q[0] <= x1 + tol and y0 - tol <= q[1] <= y1 + tol
    on = min(abs(q[0] - x0), abs(q[0] - x1), abs(q[1] - y0), abs(q[1] - y1)) <= tol
    return inside and on


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
    # the segment runs along the force direction
    d = seg[1] - seg[0]
    assert d @ [fx, fy] >= 0


def test_clip_hand_cases():
    # vertical line x = 2 (force along +y through (2, 0)): tz = x fy - y fx = 2
    seg = clip_line([0.0, 1.0, 2.0], BOX)
    np.testing.assert_allclose(seg, [[2.0, -2.0], [2.0, 5.0]])
    assert clip_line([0.0, 1.0, 10.0], BOX) is None  # x = 10, outside
    assert clip_line([0.0, 0.0, 1.0], BOX) is None   # line at infinity


def test_drawn_line_matches_clip(ax):
    art = plot_line([1.0, -2.0, 0.5], ax)
    ax.figure.canvas.draw()
    x, y = art._line.get_data()
    for q in zip(x, y):
        assert abs(0.5 + q[1] * 1.0 - q[0] * -2.0) < 1e-9
        assert _on_boundary(q, BOX)
    # the view changes: the endpoints follow at the next draw
    ax.set_xlim(-10, 10)
    ax.set_ylim(-10, 10)
    ax.figure.canvas.draw()
    x, y = art._line.get_data()
    for q in zip(x, y):
        assert _on_boundary(q, (-10, 10, -10, 10))


# ----------------------------------------------------------------- points
@given(finite, finite, st.floats(0.05, 5) | st.floats(-5, -0.05))
def test_pole_sits_at_twist_pole(x, y, w):
    fig, ax = plt.subplots()
    try:
        ax.set_xlim(-12, 12)
        ax.set_ylim(-12, 12)
        twist = np.array([w * y, -w * x, w])  # rotation w about (x, y) (4.10)
        art = plot_point(twist, ax)
        fig.canvas.draw()
        mx, my = art._marker.get_data()
        np.testing.assert_allclose([mx[0], my[0]], [x, y], atol=1e-9)
        # glyph sense: the arc runs counter-clockwise for w > 0
        ax_, ay_ = art._arc.get_data()
        c = ax.transData.transform([x, y])
        a0 = np.arctan2(ay_[0] - c[1], ax_[0] - c[0])
        a1 = np.arctan2(ay_[1] - c[1], ax_[1] - c[0])
        dtheta = (a1 - a0 + np.pi) % (2 * np.pi) - np.pi
        assert np.sign(dtheta) == np.sign(w)
    finally:
        plt.close(fig)


def test_glyph_grows_with_omega(ax):
    a1 = plot_point([0.0, 0.0, 0.5], ax)
    a2 = plot_point([0.0, 0.0, 2.0], ax)
    ax.figure.canvas.draw()
    r = [np.ptp(a._arc.get_data()[0]) for a in (a1, a2)]
    assert r[1] > 1.5 * r[0]


def test_ideal_point_arrow_at_edge(ax):
    art = plot_point([1.0, 0.0, 0.0], ax)  # translation along +x; the point lies at +y infinity
    ax.figure.canvas.draw()
    (x0, y0), (x1, y1) = art._arrow._posA_posB
    bb = ax.bbox
    assert x1 > x0 and abs(y1 - y0) < 1e-9          # arrow along +x
    assert y0 > bb.y0 + 0.75 * bb.height             # near the top edge
    assert art.get_xy() is None


# ----------------------------------------------------------------- conics
def _check_on_conic(art, C):
    xy = art.get_xy()
    xy = xy[np.all(np.isfinite(xy), axis=1)]
    assert len(xy) > 50
    P = np.column_stack([xy[:, 1], -xy[:, 0], np.ones(len(xy))])  # package points
    val = np.einsum("ni,ij,nj->n", P, C, P)
    # normalise by the gradient scale so far points are judged fairly
    grad = np.linalg.norm(P @ C, axis=1) * (1 + np.linalg.norm(xy, axis=1))
    assert np.max(np.abs(val) / grad) < 1e-8


def _rand_affine(rng):
    th = rng.uniform(0, 2 * np.pi)
    R = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
    H = np.eye(3)
    H[:2, :2] = R @ np.diag(rng.uniform(0.3, 3, 2))
    H[:2, 2] = rng.uniform(-2, 2, 2)
    return H


def _package_conic(E):
    M = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    Mi = np.linalg.inv(M)
    return Mi.T @ E @ Mi


@pytest.mark.parametrize("kind,E0", [
    ("ellipse", np.diag([1.0, 1.0, -1.0])),
    ("hyperbola", np.diag([1.0, -1.0, -1.0])),
    ("hyperbola", np.diag([-1.0, 1.0, -1.0])),
    ("parabola", np.array([[1.0, 0, 0], [0, 0, -0.5], [0, -0.5, 0]])),  # x^2 - y = 0
])
def test_conic_path_satisfies_equation(ax, rng, kind, E0):
    for _ in range(5):
        H = _rand_affine(rng)
        Hi = np.linalg.inv(H)
        E = Hi.T @ E0 @ Hi  # Euclidean conic moved by H
        C = _package_conic(E) * rng.uniform(-3, 3)
        art = plot_conic(C, ax)
        assert art.kind == kind and not art.imaginary
        _check_on_conic(art, C)
    ax.figure.canvas.draw()


def test_hyperbola_has_both_branches(ax):
    C = _package_conic(np.diag([1.0, -1.0, -1.0]))  # x^2 - y^2 = 1
    xy = plot_conic(C, ax).get_xy()
    xy = xy[np.isfinite(xy[:, 0])]
    assert (xy[:, 0] > 0).any() and (xy[:, 0] < 0).any()


def test_inertia_drawn_as_gyration_circle(ax):
    m, c, J = 2.0, np.array([1.0, 0.5]), 0.5
    rho = np.sqrt(J / m)
    art = plot_conic(inertia_matrix(m, c, J), ax, role="inertia")
    assert art.imaginary and art.kind == "ellipse"
    xy = art.get_xy()
    np.testing.assert_allclose(np.linalg.norm(xy - c, axis=1), rho, rtol=1e-10)
    assert art._curve.get_linestyle() in ("--", "-.", ":") or art._curve._dash_pattern[1] is not None
    ax.figure.canvas.draw()
    mx, my = art._center.get_data()
    np.testing.assert_allclose([mx[0], my[0]], c)


def test_degenerate_conics(ax):
    l1, l2 = np.array([1.0, 2.0, 0.5]), np.array([0.0, 1.0, -1.0])
    pair = np.outer(l1, l2) + np.outer(l2, l1)        # two crossing lines
    par = np.outer(l1, l1 + [0, 0, 1.0]) + np.outer(l1 + [0, 0, 1.0], l1)  # parallel lines
    dbl = np.outer(l1, l1)                              # a double line
    inf = np.outer(l1, [0, 0, 1.0]) + np.outer([0, 0, 1.0], l1)  # line and line at infinity
    for C in (pair, par, dbl, inf):
        g = conic_geometry(C)
        assert g["kind"] == "lines"
        for ln in g["lines"]:
            # each drawn line is one of the factors (parallel homogeneous vectors)
            cands = [l1, l2, l1 + [0, 0, 1.0]]
            assert any(np.linalg.norm(np.cross(ln, c)) < 1e-7 * np.linalg.norm(ln) * np.linalg.norm(c)
                       for c in cands)
        plot_conic(C, ax)
    point = np.diag([1.0, 1.0, 0.0])  # x^2 + y^2 = 0: the origin
    assert conic_geometry(point)["kind"] == "point"
    plot_conic(point, ax)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ax.figure.canvas.draw()


# ----------------------------------------------------------------- special elements draw cleanly
def test_special_elements_draw_without_warnings(ax):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        plot_point([1.0, 2.0, 0.0], ax, text="ideal")
        plot_point([0.0, 0.0, 0.0], ax)                # zero twist: nothing
        plot_line([0.0, 0.0, 2.0], ax, text="τ")         # line at infinity: couple glyph
        plot_line([0.0, 0.0, -1.0], ax, corner="lower left")
        plot_line([0.0, 0.0, 0.0], ax)                 # zero wrench: nothing
        plot_line([1.0, 0.0, 0.0], ax)
        plot_line([2.0, 0.0, 1.0], ax)                 # parallel lines
        plot_line([0.0, 1.0, 100.0], ax)               # outside the view
        plot_conic(np.zeros((3, 3)), ax)
        ax.figure.canvas.draw()
        ax.figure.savefig(__import__("io").BytesIO(), format="svg")


def test_couple_glyph_sense(ax):
    ccw = plot_line([0.0, 0.0, 1.0], ax)
    cw = plot_line([0.0, 0.0, -1.0], ax, corner="lower left")
    ax.figure.canvas.draw()
    for art, sign in ((ccw, 1), (cw, -1)):
        x, y = art._arc.get_data()
        c = np.array([x.mean(), y.mean()])
        a = np.unwrap(np.arctan2(y - c[1], x - c[0]))
        assert np.sign(a[-1] - a[0]) == sign


# ----------------------------------------------------------------- validation
def test_bad_input():
    with pytest.raises(ShapeError, match="point"):
        PointArtist([1.0, 2.0])
    with pytest.raises(NonFiniteError, match="line"):
        LineArtist([np.nan, 0.0, 1.0])
    with pytest.raises(InputError, match="conic must be symmetric"):
        ConicArtist([[1, 2, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(InputError, match="role"):
        PointArtist([0, 0, 1.0], role="nonsense")


# ----------------------------------------------------------------- cheap updates
def test_update_does_not_rebuild_conic_path(ax):
    ca = plot_conic(inertia_matrix(1.0, [0.0, 0.0], 1.0), ax, role="inertia")
    ax.figure.canvas.draw()
    x0 = ca._curve.get_xdata()
    ca.set_conic(inertia_matrix(3.0, [1.0, 2.0], 0.7))
    assert ca._geom is None           # set_* only stores: nothing computed until drawn
    ax.figure.canvas.draw()
    assert ca._curve.get_xdata() is x0   # same class: the unit path object is kept
    np.testing.assert_allclose(np.linalg.norm(ca.get_xy() - [1.0, 2.0], axis=1), np.sqrt(0.7 / 3.0))


# ----------------------------------------------------------------- cross-checks with GEO / SCREW
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


def test_inertia_circle_is_screws_drawable_conic(ax, rng):
    """The drawn inertia curve lies on SCREW's drawable_conic (the radius-of-gyration circle)."""
    from planargeo.screws.inertia import drawable_conic

    for _ in range(5):
        I = inertia_matrix(rng.uniform(0.5, 3), rng.uniform(-2, 2, 2), rng.uniform(0.1, 2))
        art = plot_conic(I, ax, role="inertia")
        _check_on_conic(art, drawable_conic(I))


def test_imaginary_conic_drawn_as_geo_drawable_conic(ax, rng):
    """Any definite conic (e.g. an articulated inertia) is drawn as conics.drawable_conic."""
    from planargeo.geometry.conics import drawable_conic

    for _ in range(5):
        B = rng.normal(size=(3, 3))
        C = B @ B.T + 0.5 * np.eye(3)   # positive definite: imaginary
        art = plot_conic(C, ax)
        assert art.imaginary and art.kind == "ellipse"
        _check_on_conic(art, drawable_conic(C))


def test_point_beyond_float_range_draws_as_ideal(ax):
    # [1e200, 1, 1e-200]: the pole (-1e200, 1e400) overflows; it is drawn like the ideal point
    # [1e200, 1, 0] (an arrow at the edge of the view), with no warning
    art = plot_point([1e200, 1.0, 1e-200], ax, text="far")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ax.figure.canvas.draw()
        assert art.get_xy() is None
    ideal = plot_point([1e200, 1.0, 0.0], ax)
    ax.figure.canvas.draw()
    np.testing.assert_allclose(art._arrow.get_path().vertices, ideal._arrow.get_path().vertices)


def test_line_arrow_ends_and_label_at_anchor(ax):
    # 2 N along +y on the line x = 1.5 (4.27: tz + y fx - x fy = 0 -> tz = 3); arrow 0.25/N at y = 1
    art = plot_line([0.0, 2.0, 3.0], ax, scale=0.25, anchor=[7.0, 1.0], text="f", text_at="anchor",
                    text_offset=(0.0, 0.0))
    tail, tip = art.get_arrow()
    np.testing.assert_allclose(tail, [1.5, 0.75])
    np.testing.assert_allclose(tip, [1.5, 1.25])
    ax.figure.canvas.draw()
    # the drawn arrow is the one get_arrow reports
    np.testing.assert_allclose(art._arrow._posA_posB, [[1.5, 0.75], [1.5, 1.25]])
    # the label sits at the arrow's middle (1.5, 1), not at its tip
    np.testing.assert_allclose(art._text.get_position(), ax.transData.transform([1.5, 1.0]))
    assert plot_line([0.0, 2.0, 3.0], ax, scale=None, anchor=[0, 0]).get_arrow() is None
    assert plot_line([0.0, 0.0, 1.0], ax, anchor=[0, 0]).get_arrow() is None     # a couple
    with pytest.raises(InputError, match="text_at"):
        plot_line([0.0, 2.0, 3.0], ax, text_at="middle")


@pytest.mark.parametrize("size", [1e-300, 1e-160, 1.0, 1e150, 1e300])
def test_line_arrow_of_any_finite_force_is_computed(ax, size):
    """Issue 23: a force of 1e-300 N (|f|² underflows) still has its line and arrow: the same line
    x = 1.5 along +y as ``[0, 2, 3]`` scaled, the arrow ``scale |f|`` long at the anchor's foot."""
    line = [0.0, 2.0 * size, 3.0 * size]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        art = plot_line(line, ax, scale=0.25 / size, anchor=[7.0, 1.0])
        tail, tip = art.get_arrow()
        ax.figure.canvas.draw()
        np.testing.assert_allclose(tail, [1.5, 0.75], rtol=1e-12)
        np.testing.assert_allclose(tip, [1.5, 1.25], rtol=1e-12)
        ax.set_xlim(5, 6)                     # the line off the view: the edge arrow, no warning
        ax.figure.canvas.draw()


def test_line_label_offset_none_is_the_default(ax):
    # text_offset None (what the constructions pass for "automatic") means the (6, 6) pt default:
    # the label sits 6 pt right and 6 pt up of the arrow tip, not at a NaN offset (dropped)
    # 1 N along +x on the line y = 2 (4.27: tz + 2 fx = 0 -> tz = -2); arrow 1/N centred at x = 0
    for off in (None, "set"):
        art = plot_line([1.0, 0.0, -2.0], ax, scale=1.0, anchor=[0.0, 0.0], text="f",
                        text_offset=None if off is None else (1.0, 1.0))
        if off == "set":
            art.set_text_offset(None)
        ax.figure.canvas.draw()
        pts = ax.figure.dpi / 72.0
        tip = ax.transData.transform([0.5, 2.0])
        x, y = art._text.get_position()
        assert np.isfinite([x, y]).all() and art._text.get_text() == "f"
        np.testing.assert_allclose([x, y], tip + 6.0 * pts, atol=1e-9)
        assert art._text.get_window_extent().width > 0
    # a point's None offset is automatic (clear of the glyph), a conic's is (6, -10)
    assert np.isfinite(plot_point([0.0, 0.0, 1.0], ax, text="P", text_offset=None)._text_offset).all()
    np.testing.assert_allclose(plot_conic(inertia_matrix(1.0, [0, 0], 1.0), ax)._text_offset, [6.0, -10.0])


def test_plot_functions_default_to_the_current_axes():
    """``ax=None`` means ``plt.gca()`` for every plot function and for the legend."""
    from planargeo.draw.style import legend

    fig = plt.figure()
    try:
        ax = fig.gca()
        arts = [plot_point([0.0, 0.0, 1.0]), plot_line([1.0, 0.0, 0.0]),
                plot_conic(np.diag([1.0, 1.0, -1.0])), plot_conic(inertia_matrix(1.0, [0, 0], 0.5), role="inertia")]
        assert all(a.axes is ax for a in arts)
        leg = legend([("twist", "point", "a twist"), ("reaction", "sum-line", "a sum")])
        assert ax.get_legend() is leg
        assert [t.get_text() for t in leg.get_texts()] == ["a twist", "a sum"]
        assert leg.get_lines()[1].get_linewidth() == 3.4       # a sum: the heavier line of SUM
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


def test_charts_curves_and_polar_axes():
    """Each curve gets its own colour and dash; a polar chart needs a polar axes."""
    from planargeo.draw.charts import CURVE_COLORS, plot_curves, polar_curves

    fig, ax = plt.subplots()
    try:
        x = np.linspace(0.0, 1.0, 5)
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


@pytest.mark.parametrize("u, ha, va", [((1.0, 0.0), "left", "center"), ((0.0, -1.0), "center", "top"),
                                       ((-0.6, 0.8), "right", "bottom")])
def test_label_beside_extends_away_along_u(ax, u, ha, va):
    """``set_text_beside(u, gap)``: the drawn label lies wholly on the ``u`` side of its anchor."""
    from matplotlib.text import Text

    art = plot_line([0.0, 1.0, 0.0], ax, scale=1.0, anchor=[0.0, 1.0], text="$F$", text_at="anchor")
    art.set_text_beside(u, 6.0)
    ax.figure.canvas.draw()
    (text,) = [c for c in art.get_children() if isinstance(c, Text) and c.get_text() == "$F$"]
    assert (text.get_horizontalalignment(), text.get_verticalalignment()) == (ha, va)
    anchor = ax.transData.transform([0.0, 1.0])
    pts = ax.figure.dpi / 72.0
    np.testing.assert_allclose(text.get_position(), anchor + 6.0 * pts * np.asarray(u))
    box = text.get_window_extent()
    corners = np.array([[box.x0, box.y0], [box.x1, box.y1]]) - anchor
    assert np.all(corners @ np.asarray(u) >= 6.0 * pts * 0.35 - 1e-9)   # beyond the anchor along u


# --------------------------------------------------------------------------- fit_view (issue 22)
def test_fit_view_keeps_a_folded_chain_and_its_size(ax):
    """Most points coincide (a chain at bend ±180°) and round-off moves them by 1e-7: the view
    still holds the tip, 1 m away (the former fit kept only the coincident points: ×1e-7 axes)."""
    from planargeo.draw.layout import fit_view

    rng = np.random.default_rng(3)
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


def test_fit_view_min_span_must_be_a_size(ax):
    from planargeo.draw.layout import fit_view

    with pytest.raises(InputError, match="min_span"):
        fit_view([[0, 0], [1, 1]], ax=ax, min_span=float("nan"))
