"""planargeo.draw.sketch: the gallery's shared Picture basics, checked against hand-computed geometry."""
from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from planargeo.draw import sketch  # noqa: E402
from planargeo.draw.layout import fit_view  # noqa: E402
from planargeo.draw.picture import PX_PER_PT, Picture  # noqa: E402
from planargeo.errors import InputError  # noqa: E402
from planargeo.mechanics.contacts import Contact  # noqa: E402
from planargeo.mechanics.joints import revolute  # noqa: E402
from planargeo.mechanics.kinematics import kinematics  # noqa: E402
from planargeo.mechanics.model import Body, Joint, Model  # noqa: E402
from planargeo.screws.twists import inertia_matrix  # noqa: E402


def _pic(view=(-2.0, 2.0, -2.0, 2.0), size=(200, 200)) -> Picture:
    """A picture with no margin: ``size / (view width)`` pixels per unit on both axes."""
    return Picture(view, size=size, ticks=False, margin=(0, 0, 0, 0))


def _paths(el):
    return [np.asarray(p["xy"], float) for p in el["parts"] if p["p"] == "path"]


def _two_links():
    """Two unit links (centre of mass half way), joint 1 at the origin, joint 2 at 1 along link 1."""
    bodies = [Body(1.0, (0.5, 0.0), 1.0 / 12, name=str(i + 1)) for i in range(2)]
    joints = [Joint("revolute", (0.0, 0.0, 0.0)), Joint("revolute", (1.0, 0.0, 0.0))]
    return Model(bodies, joints, [-1, 0], (0.0, 0.0))


# --------------------------------------------------------------------------- panel
@pytest.mark.parametrize("figsize, rect, points, kw", [
    ((3.4, 2.6), (0.02, 0.02, 0.96, 0.96), [[0, 0], [1.0, 0.3], [2.0, 1.5]], dict(margin=0.2)),
    ((3.4, 4.0), (0.1, 0.05, 0.8, 0.9), [[0, 0], [3.0, 0.1]], dict(margin=0.0)),
    # a far pole is an outlier; the mechanism (keep) stays
    ((4.0, 3.0), (0.0, 0.0, 1.0, 1.0), [[1e7, 0.0], [0.2, 0.3], [0.4, 0.1], [0.5, 0.5]],
     dict(margin=0.1, keep=[[0.0, 0.0], [1.0, 1.0]])),
    ((4.0, 3.0), (0.0, 0.0, 1.0, 1.0), [[0.0, 0.0], [1e-7, 0.0]], dict(margin=0.05, min_span=2.0)),
])
def test_panel_is_the_axes_size_and_the_view_fit_view_sets(figsize, rect, points, kw):
    fig = Figure(figsize=figsize)
    ax = fig.add_axes(rect)
    pic = sketch.panel(ax, points, **kw)
    assert pic.size == (round(figsize[0] * rect[2] * 100), round(figsize[1] * rect[3] * 100))
    assert pic.margin == (0.0, 0.0, 0.0, 0.0) and pic.ticks is False
    ref = Figure(figsize=figsize).add_axes(rect)          # the old way, on its own axes
    fit_view(points, ax=ref, **kw)
    want = np.array([*ref.get_xlim(), *ref.get_ylim()])
    # the same view, up to the rounding of the axes' size to whole pixels (one pixel at most)
    px = (want[1] - want[0]) / pic.size[0]
    assert np.allclose(pic.box, want, rtol=0, atol=px)
    assert pic.box[0] <= want[0] + 1e-9 and pic.box[1] >= want[1] - 1e-9 or \
        pic.box[2] <= want[2] + 1e-9 and pic.box[3] >= want[3] - 1e-9


def test_fit_box_by_hand():
    # bounding box (0, 2) x (0, 1), margin 0.1 of the larger extent 2: (-0.2, 2.2) x (-0.2, 1.2);
    # aspect 1 widens y to 2.4 about its centre 0.5
    assert np.allclose(sketch.fit_box([[0, 0], [2, 1]], 1.0, margin=0.1), (-0.2, 2.2, -0.7, 1.7))


def test_panel_fit_height_follows_the_points_aspect():
    fig = Figure(figsize=(3.4, 2.0))
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0))
    pic = sketch.panel(ax, [[0, 0], [1, 2]], margin=0.0, fit_height=True)
    assert fig.get_size_inches()[1] == pytest.approx(4.6)     # 3.4 x 2 clamped to hmax
    assert pic.size == (340, 460)


def test_panel_errors():
    ax = Figure(figsize=(3, 3)).add_axes((0, 0, 1, 1))
    with pytest.raises(InputError, match="no finite point"):
        sketch.panel(ax, [[np.nan, 0.0]])
    with pytest.raises(InputError, match="min_span"):
        sketch.panel(ax, [[0, 0], [1, 1]], min_span=-1.0)
    with pytest.raises(InputError, match="margin"):
        sketch.panel(ax, [[0, 0], [1, 1]], margin=float("inf"))
    with pytest.raises(InputError, match="ax must be a matplotlib axes"):
        sketch.panel("not axes", [[0, 0], [1, 1]])


def test_show_draws_every_element_under_its_id():
    fig = Figure(figsize=(3, 3))
    ax = fig.add_axes((0, 0, 1, 1))
    pic = sketch.panel(ax, [[0, 0], [2, 2]])
    sketch.link(pic, "body 1", (0, 0), (2, 2))
    sketch.pin(pic, "joint 1", (0, 0))
    drawn = sketch.show(pic, ax)
    assert {gid for gid, _, _ in drawn} == {"body 1", "joint 1"}
    assert np.allclose([*ax.get_xlim(), *ax.get_ylim()], pic.box)
    with pytest.raises(InputError, match="Picture"):
        sketch.show({"elements": []}, ax)


# --------------------------------------------------------------------------- texts, lines
def test_label_offset_in_points_and_placement():
    pic = _pic()
    el = sketch.label(pic, "P", (1.0, -0.5), "$v_1$", offset=(5, -3), ha="right", va="top")
    (part,) = el["parts"]
    assert (part["text"], part["x"], part["y"], part["ha"], part["va"]) == ("v₁", 1.0, -0.5, "right", "top")
    assert part["dx"] == pytest.approx(5 * 100 / 72) and part["dy"] == pytest.approx(-3 * 100 / 72)
    assert "fixed" not in part                           # the placer may move it
    fixed = sketch.label(pic, "Q", (0, 0), "Q", fixed=True)
    assert fixed["parts"][0]["fixed"] is True
    with pytest.raises(InputError, match="xy"):
        sketch.label(pic, "R", (np.inf, 0.0), "R")
    with pytest.raises(InputError, match="offset"):
        sketch.label(pic, "S", (0, 0), "S", offset="far")


def test_segment_role_style_and_label_beside_the_middle():
    pic = _pic()
    el = sketch.segment(pic, "s", (0, 0), (2, 0), label="L")
    assert np.allclose(_paths(el)[0], [[0, 0], [2, 0]])
    assert el["dash"] == [4 * PX_PER_PT, 3 * PX_PER_PT] or np.allclose(el["dash"], [5.56, 4.17])
    text = el["parts"][-1]
    # the middle (1, 0); the normal of (2, 0) turned +90 degrees is up: 5 px above, bottom-aligned
    assert (text["x"], text["y"], text["dx"], text["dy"], text["va"]) == (1.0, 0.0, 0.0, 5.0, "bottom")
    solid = sketch.segment(pic, "t", (0, 0), (1, 1), role="wrench", dash=[])
    assert solid["dash"] is None
    with pytest.raises(InputError, match="q"):
        sketch.segment(pic, "u", (0, 0), (1, np.nan))


def test_dimension_line_ticks_and_text_by_hand():
    pic = _pic((-3.0, 3.0, -3.0, 3.0), size=(300, 300))    # 50 px per unit
    el = sketch.dimension(pic, "d", (0.0, 0.0), (0.0, 2.0), "2 m", offset=1.0, at=0.25, tick=10.0)
    line, t0, t1 = _paths(el)
    # left of p -> q = (0, 2) is -x: the line x = -1 from y = 0 to 2
    assert np.allclose(line, [[-1.0, 0.0], [-1.0, 2.0]])
    # ticks across the line, 10 px = 0.2 units long, centred on its ends
    assert np.allclose(t0, [[-0.9, 0.0], [-1.1, 0.0]]) or np.allclose(t0, [[-1.1, 0.0], [-0.9, 0.0]])
    assert np.allclose(t1, [[-0.9, 2.0], [-1.1, 2.0]]) or np.allclose(t1, [[-1.1, 2.0], [-0.9, 2.0]])
    text = el["parts"][3]
    assert (text["text"], text["x"], text["y"]) == ("2 m", -1.0, 0.5)
    # 4 pt off the line on the left, right-aligned (it extends away from the line)
    assert text["dx"] == pytest.approx(-4 * PX_PER_PT) and text["dy"] == pytest.approx(0.0, abs=1e-9)
    assert text["ha"] == "right"
    with pytest.raises(InputError, match="distinct"):
        sketch.dimension(pic, "e", (1, 1), (1, 1), "0")


def test_arrow_is_the_data_vector_in_pixels():
    pic = _pic((0.0, 4.0, 0.0, 4.0), size=(200, 200))       # 50 px per unit
    el = sketch.arrow(pic, "F", (1.0, 1.0), (2.0, 3.0), label="F")
    a = el["parts"][0]
    assert (a["x"], a["y"], a["dx"], a["dy"]) == (1.0, 1.0, 50.0, 100.0)
    assert (el["parts"][1]["x"], el["parts"][1]["y"]) == (2.0, 3.0)
    with pytest.raises(InputError, match="distinct"):
        sketch.arrow(pic, "G", (1.0, 1.0), (1.0, 1.0))


# --------------------------------------------------------------------------- mechanism parts
def test_link_polygon_is_the_stadium_about_its_segment():
    p, q, w = np.array([0.5, -0.2]), np.array([1.7, 0.7]), 0.3
    pic = _pic()
    (xy,) = _paths(sketch.link(pic, "l", p, q, width=w))
    d = q - p
    t = np.clip((xy - p) @ d / (d @ d), 0.0, 1.0)
    dist = np.hypot(*(xy - (p + t[:, None] * d)).T)        # distance of each vertex to the segment
    assert np.allclose(dist, w / 2, atol=1e-3 * w)          # every outline vertex on the stadium
    # its two far points: along the segment, w/2 beyond each end
    u = d / np.hypot(*d)
    along = (xy - p) @ u
    assert along.min() == pytest.approx(-w / 2, abs=1e-9)
    assert along.max() == pytest.approx(np.hypot(*d) + w / 2, abs=1e-9)
    el = pic.elements[-1]
    assert el["fill"] and el["alpha"] == 0.35 and el["parts"][0]["closed"] is True
    with pytest.raises(InputError, match="width"):
        sketch.link(pic, "m", p, q, width=0.0)


def test_body_in_its_frame_is_moved_by_its_pose():
    pic = _pic()
    tri = [[0.0, 0.0], [1.0, 0.0], [0.0, 0.5]]
    el = sketch.body(pic, "b", tri, pose=(1.0, -1.0, math.pi), label="B", com=(0.5, -1.0))
    xy = _paths(el)[0][:3]
    # turned half a turn, then moved to (1, -1)
    assert np.allclose(xy, [[1.0, -1.0], [0.0, -1.0], [1.0, -1.5]])
    assert el["parts"][-1]["text"] == "B"
    assert {e["id"] for e in pic.elements} == {"b", "b:com:disc", "b:com"}
    with pytest.raises(InputError, match="3 finite vertices"):
        sketch.body(pic, "c", [[0, 0], [1, 1]])


def test_body_holes_are_white():
    from shapely.geometry import Polygon as SPolygon

    ring = SPolygon([(0, 0), (2, 0), (2, 2), (0, 2)], [[(0.5, 0.5), (1.5, 0.5), (1.5, 1.5), (0.5, 1.5)]])
    pic = _pic()
    sketch.body(pic, "frame", ring)
    holes = pic.elements[-1]
    assert holes["id"] == "frame:holes" and holes["fill"] == "white"
    assert np.allclose(np.sort(_paths(holes)[0][:4], axis=0),
                       np.sort(np.array([(0.5, 0.5), (1.5, 0.5), (1.5, 1.5), (0.5, 1.5)]), axis=0))


def test_pin_com_and_frame_by_hand():
    pic = _pic()
    (disc,) = _paths(sketch.pin(pic, "j", (0.3, -0.4), radius=0.1))
    assert np.allclose(np.hypot(disc[:, 0] - 0.3, disc[:, 1] + 0.4), 0.1)
    q1, q3 = _paths(sketch.com(pic, "c", (1.0, 1.0), radius=0.2))
    # black quarters: the first (x, y >= centre) and the third (x, y <= centre) quadrants
    assert np.all(q1 >= 1.0 - 1e-12) and np.all(q3 <= 1.0 + 1e-12)
    assert np.allclose(np.hypot(*(q1[1:] - 1.0).T), 0.2)
    pic2 = _pic((-1.0, 1.0, -1.0, 1.0), size=(100, 100))     # 50 px per unit
    el = sketch.frame(pic2, "F", (0.0, 0.0), angle=math.pi / 6, length=0.8)
    arrows = [p for p in el["parts"] if p["p"] == "arrow"]
    for a, ang in zip(arrows, (math.pi / 6, math.pi / 6 + math.pi / 2)):
        tip = np.array([a["x"] + a["dx"] / 50, a["y"] + a["dy"] / 50])
        assert np.allclose(tip, 0.8 * np.array([math.cos(ang), math.sin(ang)]))
    assert [p["text"] for p in el["parts"] if p["p"] == "text"] == ["x", "y"]


def test_ground_hatch_is_on_the_right_hand_side():
    pic = _pic()
    el = sketch.ground(pic, "g", (0.0, 0.0), width=1.0, angle=math.pi / 2, depth=0.1, n=3)
    line, *strokes = _paths(el)
    assert np.allclose(line, [[0.0, -0.5], [0.0, 0.5]])            # along y
    assert len(strokes) == 3
    for s, y in zip(strokes, (-0.5, 0.0, 0.5)):
        # from the line by depth along -(e + n), e = (0, 1), n = (-1, 0): (+0.1, -0.1), to the right
        assert np.allclose(s, [[0.0, y], [0.1, y - 0.1]])
    with pytest.raises(InputError, match="n must be"):
        sketch.ground(pic, "h", (0, 0), n=1)


def test_slider_block_and_track():
    pic = _pic()
    el = sketch.slider(pic, "s", (1.0, 0.0), (1.0, 1.0), size=(0.4, 0.2), track=1.0)
    e, n = np.array([1.0, 1.0]) / math.sqrt(2), np.array([-1.0, 1.0]) / math.sqrt(2)
    block = _paths(el)[0]
    want = [np.array([1.0, 0.0]) + a * 0.2 * e + b * 0.1 * n for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    assert np.allclose(block, want)
    track = [x for x in pic.elements if x["id"] == "s:track"][0]
    line = _paths(track)[0]
    mid = np.array([1.0, 0.0]) - n * 0.1                              # half the block's height below
    assert np.allclose(line, [mid - 0.5 * e, mid + 0.5 * e])
    with pytest.raises(InputError, match="direction"):
        sketch.slider(pic, "t", (0, 0), (0.0, 0.0))


def test_model_draws_one_body_per_link_at_the_poses_by_hand():
    m = _two_links()
    q = np.array([math.pi / 2, -math.pi / 2])     # link 1 up the y axis, link 2 along x at y = 1
    d = kinematics(m, q, np.zeros(2))
    pic = _pic((-1.0, 2.0, -1.0, 2.0), size=(300, 300))
    w, r = 0.2, 0.05
    out = sketch.model(pic, m, d, width=w, pin_radius=r)
    ids = [e["id"] for e in pic.elements]
    assert [e["id"] for e in out["bodies"]] == ["body 1", "body 2"]
    assert ids.count("body 1") == 1 and ids.count("body 2") == 1
    # link 1 from the joint (0, 0) to joint 2 at (0, 1); link 2 from (0, 1) through its centre of
    # mass (0.5, 1) to (1, 1)
    for el, (lo, hi) in zip(out["bodies"], (((-w / 2, -w / 2), (w / 2, 1 + w / 2)),
                                            ((-w / 2, 1 - w / 2), (1 + w / 2, 1 + w / 2)))):
        xy = _paths(el)[0]
        assert np.allclose(xy.min(axis=0), lo, atol=1e-9) and np.allclose(xy.max(axis=0), hi, atol=1e-9)
    assert [p["text"] for p in out["bodies"][1]["parts"] if p["p"] == "text"] == ["2"]
    pins = {e["id"]: _paths(e)[0] for e in out["joints"] if e["id"].startswith("joint")}
    assert np.allclose(pins["joint 1"].mean(axis=0), (0.0, 0.0), atol=1e-12)
    assert np.allclose(pins["joint 2"].mean(axis=0), (0.0, 1.0), atol=1e-12)
    # centres of mass half way along each link
    discs = [e for e in pic.elements if e["id"].endswith(":disc")]
    assert np.allclose([_paths(e)[0].mean(axis=0) for e in discs], [(0.0, 0.5), (0.5, 1.0)], atol=1e-12)
    # the ground under joint 1 only, 1.6 pin radii below it, 10 radii wide
    (ground,) = [e for e in pic.elements if e["id"].startswith("ground")]
    assert ground["id"] == "ground 1"
    assert np.allclose(_paths(ground)[0], [[-5 * r, -1.6 * r], [5 * r, -1.6 * r]])
    # prefixes keep two models apart in one picture
    sketch.model(pic, m, d, prefix="b:", labels=False, ground=False, show_com=False)
    assert "b:body 2" in {e["id"] for e in pic.elements}
    assert out["shapes"][1].equals(sketch.model_shapes(m, d, width=w)[1])
    with pytest.raises(InputError, match="names"):
        sketch.model(_pic(), m, d, names=["one"])


def test_contacts_pin_square_and_slider_walls():
    pic = _pic((-2.0, 2.0, -1.0, 3.0))
    pose = np.array([[0.0, 2.0, math.pi / 2]])                 # body a upright on the line x = 0
    (sq,) = sketch.contact(pic, "c1", Contact("pin", 0, -1, point_a=(0.5, 0.0)), pose, size=0.2)
    # the point (0.5, 0) of body a, turned a quarter and moved: (0, 2.5)
    assert np.allclose(_paths(sq)[0], [[-0.1, 2.4], [0.1, 2.4], [0.1, 2.6], [-0.1, 2.6]])
    assert sq["fill"] == "white"
    shape = sketch.link_polygon([0, 2], [0, 3], 0.3)
    c = Contact("slider", 0, -1, point_a=(0.5, 0.0), direction=(0.0, 1.0), angle=math.pi / 2)
    walls = sketch.contact(pic, "c2", c, pose, body_shape=shape, size=0.1, clearance=0.04)
    assert [e["id"] for e in walls] == ["c2:wall 1", "c2:wall 2", "c2"]
    # walls 0.15 + 0.04 either side of the guide x = 0, from 1.85 - 0.3 to 3.15 + 0.3
    xs = sorted(float(_paths(w)[0][:, 0].mean()) for w in walls[:2])
    assert np.allclose(xs, [-0.19, 0.19])
    ys = sorted(_paths(walls[0])[0][:, 1])
    assert np.allclose(ys, [1.55, 3.45])
    assert walls[2]["parts"][0]["x"] == pytest.approx(0.0) and walls[2]["parts"][0]["y"] == pytest.approx(2.5)


def test_joint_split_parts_add_up_and_the_reaction_passes_the_joint():
    pic = _pic((-1.0, 3.0, -2.0, 2.0), size=(200, 200))        # 50 px per unit
    j = revolute([0.0, 0.0])
    A = inertia_matrix(2.0, [1.0, 0.0], 0.3)
    f = np.array([0.0, 1.0, 2.0])                               # 1 N up on the line x = 2
    out, (Q, mu, TQ, Rmu) = sketch.joint_split(pic, "j1", j.s, j.R, A, f, name="1", scale=1.0,
                                                anchor=(0.0, 0.0))
    assert np.allclose(TQ + Rmu, f)
    assert abs(Rmu[2]) < 1e-12                                  # a revolute's reaction passes its joint
    assert np.allclose(Q, np.asarray(j.s).T @ f)                # Q = sᵀ f: the torque about the joint
    arrow = [p for p in out["f"]["parts"] if p["p"] == "arrow"][0]
    # centred on the joint's foot (2, 0) on x = 2, |f| = 1 N long (50 px), pointing up
    assert (arrow["x"], arrow["y"], arrow["dx"], arrow["dy"]) == (2.0, -0.5, 0.0, 50.0)
    assert [out[k]["id"] for k in ("f", "active", "reaction")] == ["j1:f", "j1:active", "j1:reaction"]
    assert [p["text"] for p in out["reaction"]["parts"] if p["p"] == "text"] == ["Rμ₁"]
    # each arrow is scale |part| long
    for k, w in (("active", TQ), ("reaction", Rmu)):
        a = [p for p in out[k]["parts"] if p["p"] == "arrow"][0]
        assert math.hypot(a["dx"], a["dy"]) == pytest.approx(50.0 * math.hypot(*w[:2]))


def test_split_arrows_slide_clear_of_what_they_avoid():
    from shapely.geometry import LineString, Point as SPoint

    j = revolute([0.0, 0.0])
    A = inertia_matrix(2.0, [1.0, 0.0], 0.3)
    f = np.array([0.0, 1.0, 2.0])
    blob = SPoint(2.0, 0.0).buffer(0.3)                          # sits on f's arrow at the foot
    arrows, _ = sketch.split_arrows(j.s, j.R, A, f, anchor=(0.0, 0.0), avoid=blob, clearance=0.1)
    tail, tip = arrows["f"]
    assert np.allclose(tail[0], 2.0) and np.allclose(tip[0], 2.0)          # still on x = 2
    assert LineString([tail, tip]).distance(blob) >= 0.1 - 1e-9
    with pytest.raises(InputError, match="anchor"):
        sketch.split_arrows(j.s, j.R, A, f, anchor=(np.nan, 0.0))


def test_bad_picture_argument():
    with pytest.raises(InputError, match="Picture"):
        sketch.pin("not a picture", "j", (0, 0))


@pytest.mark.parametrize("module", ["sketch", "sums", "polars", "splits"])
def test_shared_docstring_entries_are_written_in(module):
    """Every drawing function's docstring has its shared entries (``{pic id}`` lines) written in.

    A function that names shared entries but lacks the decorator would show ``{pic}`` in the
    documentation and miss those parameters; the written-in text is the one of
    :data:`planargeo.draw._shared.ENTRIES`.
    """
    import importlib
    import re

    from planargeo.draw._shared import ENTRIES

    mod = importlib.import_module(f"planargeo.draw.{module}")
    docs = {name: getattr(mod, name).__doc__ or "" for name in mod.__all__ if callable(getattr(mod, name))}
    left = [name for name, doc in docs.items() if re.search(r"^ *\{[a-z ]+\}$", doc, re.M)]
    assert left == []
    # the entries are written in, indented like the rest of the section
    assert "    pic : Picture\n        Where to draw." in docs[{"sketch": "label", "sums": "twist_sum",
                                                             "polars": "percussion",
                                                             "splits": "decomposition"}[module]]
    assert ENTRIES["pic"] == "pic : Picture\n    Where to draw."
