"""Gallery figures drawn from Pictures: what is drawn sits where hand-computed geometry puts it.

Each figure is built through the registry's public ``build()``; every artist drawn
from a picture carries its element's id as ``gid`` (``"<id>:label"`` for a label).
The references are closed forms worked out here (a body point's velocity ω ẑ × r,
the centripetal acceleration −ω² r, the axis of percussion at ρ²/d beyond the centre
of mass, a stadium's radius of gyration), not the figures' own code.
"""
from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Polygon  # noqa: E402
from matplotlib.text import Annotation  # noqa: E402

from planargeo.gallery.figures import load_all  # noqa: E402

#: a picture's coordinates are rounded to 1e-5 of a view a few metres wide (Picture.to_dict)
TOL = 1e-4

SPECS = load_all()
#: the modules' old drawing code these figures must no longer use
OLD = ("planargeo.draw.artists", "planargeo.draw.constructions", "planargeo.draw.mechanism")


@pytest.fixture
def built():
    figs = []

    def build(name):
        fig = SPECS[name].build()
        figs.append(fig)
        fig.canvas.draw()
        return fig

    yield build
    for fig in figs:
        plt.close(fig)


def _artists(ax, gid):
    return [a for a in ax.get_children() if a.get_gid() == gid]


def _arrow(ax, gid):
    """(tail, tip) in data units of the one arrow of element ``gid`` (shaft start, head's tip)."""
    shafts = [a for a in _artists(ax, gid) if isinstance(a, Line2D) and len(a.get_xydata()) == 2]
    heads = [a for a in _artists(ax, gid) if isinstance(a, Polygon) and len(a.get_xy()) in (3, 4)]
    assert len(heads) == 1, f"{gid}: {len(heads)} arrow heads"
    tip = np.asarray(heads[0].get_xy()[0], float)
    shaft = min(shafts, key=lambda s: np.hypot(*(s.get_xydata()[1] - tip)))   # the one ending at the head
    return np.asarray(shaft.get_xydata()[0], float), tip


def _marker(ax, gid):
    marks = [a for a in _artists(ax, gid) if isinstance(a, Line2D) and a.get_marker() not in ("None", None, "")]
    assert len(marks) == 1, f"{gid}: {len(marks)} markers"
    return np.asarray(marks[0].get_xydata()[0], float)


def _segment(ax, gid):
    lines = [a for a in _artists(ax, gid) if isinstance(a, Line2D) and a.get_marker() in ("None", None, "")
             and len(a.get_xydata()) == 2]
    assert lines, f"{gid}: no straight line drawn"
    longest = max(lines, key=lambda a: np.hypot(*np.diff(a.get_xydata(), axis=0)[0]))   # not an arrow's shaft
    return np.asarray(longest.get_xydata(), float)


def _cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _to_px(ax, xy):
    return ax.transData.transform(np.asarray(xy, float))


# --------------------------------------------------------------------------- Figs 1.2, 1.3: the disk
OMEGA, P = 2.0, np.array([0.7, 0.35])        # the figures' spin (rad/s) and body point (m)
SCALE = 0.2                                   # metres of arrow per m/s (per m/s²)


def test_fig1_2_velocity_and_centripetal_acceleration_at_p(built):
    ax = built("fig1_2").axes[0]
    # the spin's pole at the disk's centre O
    assert np.allclose(_marker(ax, "v"), [0.0, 0.0], atol=TOL)
    # vₚ = ω ẑ × P = ω (−y, x): the arrow from P to P + 0.2 vₚ
    tail, tip = _arrow(ax, "v_P")
    assert np.allclose(tail, P, atol=TOL)
    assert np.allclose(tip, P + SCALE * OMEGA * np.array([-P[1], P[0]]), atol=TOL)
    # −ω² r, pointing at O: from P to P − 0.2 ω² P = (0.14, 0.07)
    tail, tip = _arrow(ax, "a_P")
    assert np.allclose(tail, P, atol=TOL)
    assert np.allclose(tip, [0.14, 0.07], atol=TOL)
    # P's path: the dashed circle of radius |P| about O
    path = np.vstack([a.get_xydata() for a in _artists(ax, "path of P") if isinstance(a, Line2D)])
    assert np.allclose(np.hypot(*path.T), math.hypot(*P), atol=TOL)


def test_fig1_3_body_points_at_p_before_and_after(built):
    ax = built("fig1_3").axes[0]
    assert np.allclose(_marker(ax, "P"), P, atol=TOL)
    # the body points at P 0.12 s before and after: P turned by ∓ω·0.12 about O
    for k, dt in ((0, -0.12), (2, 0.12)):
        c, s = math.cos(OMEGA * dt), math.sin(OMEGA * dt)
        assert np.allclose(_marker(ax, f"body point {k}"), [c * P[0] - s * P[1], s * P[0] + c * P[1]],
                           atol=TOL)
    tail, tip = _arrow(ax, "v_P")
    assert np.allclose(tip - tail, SCALE * OMEGA * np.array([-P[1], P[0]]), atol=TOL)
    texts = [a.get_text() for a in ax.get_children() if isinstance(a, Annotation)]
    assert "spatial acceleration a = v̇ = 0" in texts


# --------------------------------------------------------------------------- the 2-dof joint
def _meet(s1, s2):
    """Intersection of the lines through the segments s1 and s2 (each (2, 2))."""
    d1, d2 = s1[1] - s1[0], s2[1] - s2[0]
    t = _cross(s2[0] - s1[0], d2) / _cross(d1, d2)
    return s1[0] + t * d1


def test_fig6_2dof_poles_and_the_ideal_point_as_an_edge_arrow(built):
    ax = built("fig6_2dof").axes[0]
    e = np.array([math.cos(math.radians(20.0)), math.sin(math.radians(20.0))])   # the slot, 20° from x
    # s₂: the rotation about the pin at the origin
    assert np.allclose(_marker(ax, "s2"), [0.0, 0.0], atol=TOL)
    # s₁: the translation along the slot, an ideal point: an arrow along ±e at the view's edge
    assert not [a for a in _artists(ax, "s1") if isinstance(a, Line2D) and a.get_marker() == "o"]
    tail, tip = _arrow(ax, "s1")
    d = (tip - tail) / np.hypot(*(tip - tail))
    assert abs(_cross(d, e)) < TOL
    px = _to_px(ax, (tail + tip) / 2)
    bb = ax.bbox
    assert min(px[0] - bb.x0, bb.x1 - px[0], px[1] - bb.y0, bb.y1 - px[1]) < 30.0
    texts = {a.get_gid(): a.get_text() for a in ax.get_children() if isinstance(a, Annotation)}
    assert texts["s1:label"] == "s₁ at ∞"
    # U where the percussion lines T₁ and T₂ meet (TᵀU = 0)
    assert np.allclose(_marker(ax, "U"), _meet(_segment(ax, "T1"), _segment(ax, "T2")), atol=TOL)
    # the line of poles R passes through the pin (the pole of s₂) and is perpendicular to the slot
    R = _segment(ax, "R")
    assert abs(np.dot(R[1] - R[0], e)) < TOL * np.hypot(*(R[1] - R[0]))
    assert abs(_cross(R[1] - R[0], -R[0])) < TOL * np.hypot(*(R[1] - R[0]))


# --------------------------------------------------------------------------- the inertia field
def _stadium_rho2(half_length=0.8, r=0.3):
    """ρ² = J/A about the centre of a uniform stadium (rectangle 2L × 2r, two half discs)."""
    L = half_length
    A_rect, A_half = 2 * L * 2 * r, math.pi * r * r / 2
    J_rect = A_rect * ((2 * L) ** 2 + (2 * r) ** 2) / 12
    # a half disc on its flat side at x = L: ∫ (L + u)² + y² dA
    J_half = L * L * A_half + 2 * L * A_half * 4 * r / (3 * math.pi) + math.pi * r ** 4 / 4
    return (J_rect + 2 * J_half) / (A_rect + 2 * A_half)


def test_extra_inertia_field_axes_of_percussion_by_hand(built):
    ax = built("extra_inertia_field").axes[0]
    rho2 = _stadium_rho2()
    assert abs(rho2 - 0.39018) < 1e-4
    # for the pole a at distance d from the centre of mass (the origin), the axis of percussion is
    # perpendicular to the line a–c, on the far side of c, ρ²/d from it (5.67, 5.68)
    for k, a in ((1, (-1.6, 0.9)), (2, (1.3, -1.0)), (3, (0.2, 1.3))):
        a = np.array(a)
        assert np.allclose(_marker(ax, f"a{k}"), a, atol=TOL)
        seg = _segment(ax, f"Ia{k}")
        d = seg[1] - seg[0]
        assert abs(np.dot(d, a)) < TOL * np.hypot(*d) * np.hypot(*a)          # ⟂ to c–a
        foot = -a * rho2 / np.dot(a, a)
        # through the foot; the plate's round ends are drawn (and integrated) as polygons, so its ρ²
        # is below the true stadium's by < 0.5 %: the foot (≈ 0.2 m from c) within 1 mm
        assert abs(_cross(d, foot - seg[0])) / np.hypot(*d) < 1e-3
    # the pole at the centre of mass: its axis is the line at infinity, the couple's corner glyph
    assert not [a for a in _artists(ax, "Ia4") if isinstance(a, Line2D) and len(a.get_xydata()) == 2]
    arc = [a for a in _artists(ax, "Ia4") if isinstance(a, Line2D) and len(a.get_xydata()) > 2]
    assert len(arc) == 1
    centre = _to_px(ax, arc[0].get_xydata().mean(axis=0))
    assert ax.bbox.x1 - centre[0] < 45 and ax.bbox.y1 - centre[1] < 45               # upper right corner
    texts = {a.get_gid(): a.get_text() for a in ax.get_children() if isinstance(a, Annotation)}
    assert texts["Ia4:label"] == "Ia₄: couple (line at ∞)"
    # the translation a₅ = [1, 0.6, 0] (an ideal point): an edge arrow along its velocity (1, 0.6)
    tail, tip = _arrow(ax, "a5")
    u = (tip - tail) / np.hypot(*(tip - tail))
    assert np.allclose(u, np.array([1.0, 0.6]) / math.hypot(1.0, 0.6), atol=TOL)


# --------------------------------------------------------------------------- slider-crank, style key
def test_extra_slider_crank_contact_force_on_its_line_to_scale(built):
    from planargeo.gallery.figures import scene_state

    res, _ = scene_state("slider-crank")
    fx, fy, tz = (float(v) for v in res.quantities["F3"])
    ax = built("extra_slider_crank").axes[0]
    seg = _segment(ax, "F3")
    # every point of the line of action of [fx, fy, τ] has τ + y fx − x fy = 0 (4.27)
    assert np.allclose(tz + seg[:, 1] * fx - seg[:, 0] * fy, 0.0, atol=1e-3 * math.hypot(fx, fy))
    tail, tip = _arrow(ax, "F3")
    assert np.allclose(tip - tail, 0.01 * np.array([fx, fy]), atol=TOL)           # 0.01 m per N
    texts = {a.get_gid(): a.get_text() for a in ax.get_children() if isinstance(a, Annotation)}
    assert texts["F3:label"] == f"F₃ = {math.hypot(fx, fy):.1f} N"
    # a₁ and v₁ at the crank's pivot (the origin), the piston's v₃ an ideal point: an edge arrow
    assert np.allclose(_marker(ax, "a1"), [0.0, 0.0], atol=TOL)
    assert np.allclose(_marker(ax, "v1"), [0.0, 0.0], atol=TOL)
    assert texts["v3:label"] == "v₃ at ∞"


def test_extra_style_key_translation_arrow_at_the_lower_edge(built):
    ax = built("extra_style_key").axes[0]
    tail, tip = _arrow(ax, "translation")                # [−1, 0, 0]: a translation to the left
    assert tip[0] < tail[0] and abs(tip[1] - tail[1]) < TOL
    assert _to_px(ax, tail)[1] - ax.bbox.y0 < 30.0
    assert np.allclose(_marker(ax, "twist"), [1.0, 7.0], atol=TOL)          # from_xy([1, 7])
    assert np.allclose(_marker(ax, "acceleration"), [1.0, 7.0 - 1.05], atol=TOL)


# --------------------------------------------------------------------------- every ported figure
#: labels each figure must show (none hidden by the label placer for want of room)
LABELS = {
    "fig1_1": {"pole of v", "P", "r", "vₚ = ω r"},
    "fig1_2": {"v (ω = const)", "P", "vₚ", "−ω² r"},
    "fig1_3": {"v (ω = const)", "P (fixed in space)", "vₚ (constant at P)", "spatial acceleration a = v̇ = 0"},
    "fig1_4": {"f"},
    "fig6_2dof": {"R = line of poles of s", "s₁ at ∞", "s₂", "T₁", "T₂", "U", "sψ"},
    "extra_inertia_field": {"a₁", "a₂", "a₃", "a₄", "a₅ at ∞", "Ia₁", "Ia₂", "Ia₃", "Ia₄: couple (line at ∞)",
                            "Ia₅"},
    "extra_joint_splits": {"f₁", "TQ₁", "Rμ₁", "f₂", "TQ₂", "Rμ₂", "f₃", "TQ₃", "Rμ₃", "1", "2", "3",
                           "joint 1: Q = τ = 43.17", "joint 2: Q = τ = 17.49", "joint 3: Q = τ = 5.45"},
    "extra_slider_crank": {"crank", "rod", "piston", "a₁", "a₂", "a₃ at ∞", "v₁", "v₃ at ∞"},
    "extra_style_key": {"twist (pole), ω > 0", "acceleration, α < 0", "wrench (line of action)",
                        "reaction force", "momentum / active part", "construction line",
                        "inertia (radius of gyration)", "translation (ideal point) at ∞", "couple (line at ∞)"},
}
MODULES = {"fig1_1": "fields", "fig1_4": "fields", "fig1_2": "ch1", "fig1_3": "ch1", "fig6_2dof": "subspaces_2dof"}


@pytest.mark.parametrize("name", sorted(LABELS))
def test_drawn_from_a_picture_every_label_shown(name, built):
    import importlib
    import inspect

    src = inspect.getsource(importlib.import_module("planargeo.gallery.figures." + MODULES.get(name, "extra")))
    assert not any(m in src for m in OLD), f"{name}: its module still uses the old drawing code"
    fig = built(name)
    shown = set()
    for ax in fig.axes:
        assert any(a.get_gid() for a in ax.get_children()), f"{name}: nothing drawn from a picture"
        shown |= {a.get_text() for a in ax.get_children() if isinstance(a, Annotation) and a.get_visible()}
    assert LABELS[name] <= shown, f"{name}: labels missing: {LABELS[name] - shown}"
