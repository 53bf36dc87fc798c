"""ScrewSumExplorer: the drawn sum follows hand-derived constructions (thesis 4.2, 4.4).

What is drawn is read off the explorer's picture (``ex.picture()``): a pole is its
marker (or an arrow at the edge of the view when it is ideal), a force line its clipped
segment, a couple the glyph of the line at infinity.
"""
import re

import numpy as np
import pytest

from planargeo.draw.layout import legibility_problems
from planargeo.draw.render import figure
from planargeo.widgets.screw_sum import ScrewSumExplorer

from _picture_checks import elements, problems


def cross2(a, b) -> float:
    """The z component of the cross product of two plane vectors."""
    return float(a[0] * b[1] - a[1] * b[0])


def mark(ex, id):
    m = next(p for p in elements(ex.picture())[id]["parts"] if p["p"] == "mark")
    return np.array([m["x"], m["y"]])


def segment(ex, id):
    return np.array(next(p["xy"] for p in elements(ex.picture())[id]["parts"] if p["p"] == "path"), float)


def on_segment_line(seg, q, tol=1e-3):
    """True when the point ``q`` lies on the line through the two ends ``seg``."""
    a, b = seg
    return abs(cross2(b - a, np.asarray(q, float) - a)) <= tol * np.hypot(*(b - a))


def along(text, d):
    """True when ``text`` reads a point at infinity in the direction ``±d``."""
    if not text.startswith("at infinity (direction ("):
        return False
    got = np.array([float(v) for v in re.findall(r"-?[\d.]+", text)])
    return abs(got[0] * d[1] - got[1] * d[0]) < 1e-3 and abs(np.hypot(*got) - 1) < 1e-3


def xy(p):
    p = np.asarray(p, float)
    return np.array([-p[1] / p[2], p[0] / p[2]])


@pytest.fixture
def ex():
    return ScrewSumExplorer(display="agg")


def test_two_rotations_lever_rule(ex):
    ex.set(x1=-1.0, y1=0.5, size1=1.0, x2=2.0, y2=-1.0, size2=3.0)
    # pole of the sum = weighted mean of the poles (velocity zero there)
    P = (1.0 * np.array([-1.0, 0.5]) + 3.0 * np.array([2.0, -1.0])) / 4.0
    assert ex.readout_values["case"] == "two rotations (4.12)"
    assert ex.readout_values["β"] == pytest.approx(0.75)
    assert ex.readout_values["pole of sum"] == pytest.approx(tuple(P))
    assert mark(ex, "v3") == pytest.approx(P, abs=1e-5)
    # the pole lies on the drawn join of the two poles (incidence, 5.24), drawn heavier (a diamond)
    assert on_segment_line(segment(ex, "lever"), P)
    assert next(p for p in elements(ex.picture())["v3"]["parts"] if p["p"] == "mark")["shape"] == "D"
    # the terms' labels on one side of the lever line, the sum's on the other
    labels = {i: next(p for p in e["parts"] if p["p"] == "text") for i, e in elements(ex.picture()).items()
              if i in ("v1", "v2", "v3")}
    a, b = segment(ex, "lever")
    side = lambda t: np.sign(cross2(b - a, [t["dx"], t["dy"]]))
    assert side(labels["v1"]) == side(labels["v2"]) == -side(labels["v3"])


def test_opposite_rotations_give_a_translation(ex):
    ex.set(x1=0.0, y1=0.0, size1=1.0, x2=2.0, y2=0.0, size2=-1.0)
    assert ex.readout_values["case"] == "opposite rotations (4.13)"
    assert along(ex.readout_values["pole of sum"], (1, 0))    # ⟂ to the velocity (0, 2)
    # velocity of the sum at the origin: rotation about (2, 0) with ω=-1 gives (0, 2)
    assert ex.readout_values["sum"] == pytest.approx((0.0, 2.0, 0.0))
    parts = elements(ex.picture())["v3"]["parts"]       # its pole at infinity: an edge arrow along (0, 1)
    arrow = next(p for p in parts if p["p"] == "arrow")
    assert arrow["dx"] == pytest.approx(0.0, abs=1e-9) and arrow["dy"] > 0
    assert next(p for p in parts if p["p"] == "text")["text"] == "v₃ = v₁ + v₂ at ∞"


def test_rotation_plus_translation(ex):
    ex.set(kind2="translation", x1=0.5, y1=0.0, size1=2.0, size2=3.0, angle2=0.0)
    # P = Q + (u/ω) (e turned +90°) = (0.5, 0) + 1.5 (0, 1)
    assert ex.readout_values["ρ"] == pytest.approx(1.5)
    assert ex.readout_values["pole of sum"] == pytest.approx((0.5, 1.5))


def test_wrenches_concurrent_parallel_couple(ex):
    ex.set(add="wrenches")
    assert ex.values["kind1"] == "force" and ex.values["kind2"] == "force"
    ex.set(x1=-1.0, y1=0.0, size1=1.0, angle1=0.0, x2=2.0, y2=1.0, size2=2.0, angle2=90.0)
    assert ex.readout_values["case"] == "concurrent forces (4.4.1)"
    assert ex.readout_values["meet of lines"] == pytest.approx((2.0, 0.0))
    f3 = segment(ex, "f3")                     # along (1, 2) through the meet (2, 0)
    assert cross2(f3[1] - f3[0], [1.0, 2.0]) == pytest.approx(0.0, abs=1e-3)
    assert on_segment_line(f3, (2.0, 0.0)) and mark(ex, "P") == pytest.approx([2.0, 0.0])
    # parallel forces, lever rule: 1 N at x=-1 and 3 N at x=3, both along +y -> line x = 2
    ex.set(angle1=90.0, size2=3.0, x2=3.0)
    assert ex.readout_values["case"] == "parallel forces (4.43)"
    assert segment(ex, "f3")[:, 0] == pytest.approx([2.0, 2.0])      # the line x = 2
    assert "P" not in elements(ex.picture())                         # they meet at infinity
    # equal and opposite: moments x fy about the origin, -1 * 1 + 3 * (-1) = -4
    ex.set(size2=-1.0)
    assert ex.readout_values["case"] == "equal and opposite parallel forces (4.4.2)"
    assert ex.readout_values["sum"] == pytest.approx((0.0, 0.0, -4.0))
    f3 = elements(ex.picture())["f3"]                                # a couple: the line at infinity
    assert [p["p"] for p in f3["parts"]] == ["glyph", "text"]
    assert f3["parts"][1]["text"] == "f₃ = f₁ + f₂: couple (line at ∞)" and not f3["parts"][0]["ccw"]


def test_force_plus_couple(ex):
    ex.set(add="wrenches", kind2="couple", x1=0.0, y1=0.0, angle1=0.0, size1=2.0, size2=1.0)
    assert ex.readout_values["case"] == "force plus couple (4.46)"
    assert ex.readout_values["ρ"] == pytest.approx(0.5)


def test_zero_screw_is_a_message_not_an_exception(ex):
    good = dict(ex.readout_values)
    ex.controls["size2"].value = 0.0
    # said in the slider's symbol and unit: a zero twist is no motion (not a point, not even at infinity)
    assert ex.message.startswith("ω₂ = 0 rad/s makes v₂ the zero twist") and "ω₂ ≠ 0" in ex.message
    assert ex.readout_values == good
    assert mark(ex, "v2") == pytest.approx([1.5, 0.5])               # the shown sum is kept
    ex.controls["size2"].value = 1.0
    assert ex.message == ""


def test_meet_of_forces_on_one_line_is_not_at_infinity(ex):
    # two forces along the x-axis: their lines coincide, so they meet at every point of it
    ex.set(add="wrenches", kind1="force", kind2="force", x1=0.0, y1=0.0, angle1=0.0, size1=1.0,
           x2=1.5, y2=0.0, angle2=0.0, size2=-1.0)
    assert ex.readout_values["case"] == "the sum is zero (4.6)"
    assert ex.readout_values["meet of lines"] == "every point of their common line"
    ex.set(size2=-2.0)                                 # unequal: a force on the same line
    assert ex.readout_values["case"] == "forces on one line (4.4.1)"
    assert ex.readout_values["meet of lines"] == "every point of their common line"
    assert ex.readout_values["sum"] == pytest.approx((-1.0, 0.0, 0.0), abs=1e-12)
    # distinct parallel lines (y = 0 and y = 1) do meet at infinity
    ex.set(y2=1.0)
    assert along(ex.readout_values["meet of lines"], (1, 0))
    # crossing lines meet at a finite point: the x-axis and the vertical through x = 1.5
    ex.set(y2=0.0, angle2=90.0, size2=1.0)
    assert ex.readout_values["meet of lines"] == pytest.approx((1.5, 0.0))


# ---------------------------------------------------------------- an instrument (issue 13, 14 item 7)
STATES = [{}, dict(size2=-1.0), dict(kind2="translation"), dict(x2=-1.5, y2=0.0),
          dict(x1=-1.0, y1=0.5, x2=2.0, y2=-1.0, size2=3.0),
          dict(x1=0.5, size1=2.0, kind2="translation", size2=3.0, angle2=0.0),
          dict(kind1="translation", kind2="translation"), dict(x1=-3, y1=3, x2=3, y2=-3, size2=1.0),
          dict(add="wrenches"), dict(add="wrenches", angle2=0.0), dict(add="wrenches", kind2="couple"),
          dict(add="wrenches", angle1=90.0, size2=-1.0, x2=3.0)]


@pytest.mark.parametrize("state", STATES, ids=[str(s) for s in STATES])
def test_every_state_is_legible(ex, state):
    ex.set(**state)
    assert ex.message == ""
    pic = ex.picture()
    assert problems(pic) == []                       # every element described, no labels on each other
    assert legibility_problems(figure(pic)) == []    # and as matplotlib draws it for the exports


def test_units_and_special_case_in_the_readout(ex):
    assert ex.units["ω₁"] == "rad/s" and ex.units["pole of sum"] == "m"
    assert ex.units["F₁"] == "N" and ex.units["ρ"] == "m"
    html = ex.readout.value
    assert "rad/s" in html
    assert ex.readout_values["case"] == "two rotations (4.12)"
    ex.set(size2=-1.0)
    assert ex.readout_values["case"] == "opposite rotations (4.13)"


def test_drag_a_pole_moves_the_sum_by_the_lever_rule(ex):
    ex.set(x1=0.0, y1=0.0, size1=1.0, size2=3.0)
    ex.drag("v₂", ex.handle_position("v₂"), (2.0, 2.0), steps=5)
    assert ex.values["x2"] == pytest.approx(2.0) and ex.values["y2"] == pytest.approx(2.0)
    # P = (1 · (0, 0) + 3 · (2, 2)) / 4 (4.12), with no snapping to the 0.05 slider grid on the way
    assert ex.readout_values["pole of sum"] == pytest.approx((1.5, 1.5))
    ex.drag("v₂", (2.0, 2.0), (2.013, 2.0), steps=1)
    assert ex.values["x2"] == pytest.approx(2.013)


def test_drag_a_pole_onto_the_other(ex):
    ex.drag("v₂", ex.handle_position("v₂"), ex.handle_position("v₁"), steps=4)
    assert ex.message == ""
    assert ex.readout_values["case"] == "coincident poles (4.11)"


def test_force_lines_by_point_and_by_direction(ex):
    ex.set(add="wrenches", x1=0.0, y1=0.0, angle1=0.0, size1=1.0, x2=2.0, y2=1.0, angle2=90.0)
    assert ex.handle_position("f₂ direction") == pytest.approx((2.0, 2.0))
    assert ex.handle_position("v₂") is None                 # not a rotation now
    # turn f2 by its arrow tip through the direction of f1: the meet runs off to infinity and
    # comes back from the other side, no refusal on the way (10.2.4)
    cases = []
    for tip in [(3.0, 1.5), (3.0, 1.1), (3.0, 1.0), (3.0, 0.9), (3.0, 0.5)]:
        ex.drag("f₂ direction", ex.handle_position("f₂ direction"), tip, steps=1)
        assert ex.message == ""
        cases.append(ex.readout_values["case"])
    assert cases == ["concurrent forces (4.4.1)"] * 2 + ["parallel forces (4.43)"] + ["concurrent forces (4.4.1)"] * 2
    # the meet of y = 0 with the line through (2, 1) along (1, -0.5): (4, 0), by hand
    assert ex.readout_values["meet of lines"] == pytest.approx((4.0, 0.0))
    ex.drag("f₁", ex.handle_position("f₁"), (0.0, 1.0), steps=2)       # f1 now on y = 1
    assert ex.readout_values["meet of lines"] == pytest.approx((2.0, 1.0))


def test_direction_handle_on_its_point_is_refused_with_the_reason(ex):
    ex.set(add="wrenches")
    good = dict(ex.values)
    ex.drag("f₁ direction", ex.handle_position("f₁ direction"),
            (good["x1"], good["y1"]), steps=1)
    assert "no direction" in ex.message
    assert ex.values == good


def test_sliding_a_rate_through_the_opposite_passes_through_a_translation(ex):
    """ω2 from -0.8 to -1.2 with ω1 = 1: the sum's pole leaves to infinity and comes back (4.13)."""
    ex.set(x1=0.0, y1=0.0, size1=1.0, x2=2.0, y2=0.0)
    poles = []
    for w2 in (-0.8, -0.9, -1.0, -1.1, -1.2):
        ex.set(size2=w2)
        assert ex.message == ""
        poles.append(ex.readout_values["pole of sum"])
    # P = ω2 Q2 / (1 + ω2) on the x axis: -8, -18, ∞, 22, 12
    assert along(poles[2], (1, 0))
    assert [p[0] for p in poles[:2] + poles[3:]] == pytest.approx([-8.0, -18.0, 22.0, 12.0])


def test_round_off_prints_as_zero(ex):
    ex.set(add="wrenches", kind2="force", x1=0.0, y1=0.0, angle1=90.0, size1=1.0,
           x2=2.0, y2=0.0, angle2=90.0, size2=-1.0)
    # cos 90° = 6e-17: the couple's force part is round-off and shows as 0
    html = ex.readout.value
    assert "e-17" not in html and "e-16" not in html


# ---------------------------------------------------------------- issue 22: kinds follow the mode
def test_the_kinds_offered_follow_the_mode(ex):
    assert tuple(ex.controls["kind1"].options) == ("rotation", "translation")
    good = dict(ex.readout_values)
    ex.set(kind1="force")                     # a force is no twist: refused, nothing drawn as one
    assert "kind1" in ex.message and ex.values["kind1"] == "rotation" and ex.readout_values == good
    ex.set(add="wrenches")
    assert tuple(ex.controls["kind2"].options) == ("force", "couple")
    assert ex.values["kind1"] == ex.values["kind2"] == "force"
    # a couple of 1.5 N·m added to the force 1 N along +x through (−1.5, 0), whose moment about
    # the origin is x fy − y fx = 0: the sum is [1, 0, 1.5] (4.46), a force shifted by ρ = τ/F
    ex.set(kind2="couple", size2=1.5)
    assert ex.message == ""
    assert ex.readout_values["sum"] == pytest.approx((1.0, 0.0, 1.5))
    assert ex.readout_values["ρ"] == pytest.approx(1.5)
    ex.set(add="twists")                      # back: the couple becomes a translation, and says so
    assert ex.values["kind2"] == "translation"
    assert tuple(ex.controls["kind2"].options) == ("rotation", "translation")
    with pytest.raises(Exception, match="kind1"):
        ScrewSumExplorer(display="agg", kind1="couple")     # twists mode offers no couple


def test_sliders_name_their_unit_and_the_readout_is_short(ex):
    assert ex.controls["x1"].description == "x₁ (m)"
    assert ex.controls["size1"].description == "ω₁ (rad/s)"
    ex.set(kind2="translation")
    assert ex.controls["size2"].description == "speed u₂ (m/s)"
    ex.set(add="wrenches", kind2="couple")
    assert ex.controls["size1"].description == "force F₁ (N)"
    assert ex.controls["size2"].description == "moment τ₂ (N·m)"
    for state in STATES:
        ex.set(**{"add": "twists", **state})
        for k, text in ex.readout_strings.items():
            assert len(text) <= 36, (k, text)        # the readout column is never pushed off
        assert ex.readout_strings["β"] in ("none", "0.6667") or float(ex.readout_strings["β"])


def test_every_number_has_a_unit_and_every_row_a_meaning(ex):
    for state in STATES:
        ex.set(**{"add": "twists", **state})
        meanings = ex.explain()
        for k, v in ex.readout_values.items():
            assert k in meanings
            if isinstance(v, (float, tuple)) and k != "β":
                assert ex.units.get(k) not in (None, "", "—"), k
        units = ex.units["sum"]
        assert units == (("m/s", "m/s", "rad/s") if ex.values["add"] == "twists" else ("N", "N", "N·m"))


def test_a_fresh_explorer_from_the_values_shows_the_same(ex):
    ex.set(add="wrenches", kind2="couple", size2=2.0)
    ex.drag("f₁", ex.handle_position("f₁"), (0.5, 0.5), steps=2)
    fresh = ScrewSumExplorer(display="agg", **ex.values)
    assert fresh.readout_strings == ex.readout_strings
    ex.reset()
    assert ex.values == ScrewSumExplorer(display="agg").values and ex.message == ""


def test_controls_a_kind_does_not_use_are_disabled_with_a_reason(ex):
    off = ex.disabled(ex.values)
    assert "angle1" in off and "direction" in off["angle1"]
    ex.set(add="wrenches", kind1="couple")
    off = ex.disabled(ex.values)
    assert {"x1", "y1", "angle1"} <= set(off) and "x2" not in off
    before = dict(ex.readout_values)
    ex.set(x1=1.0, y1=-1.0, angle1=45.0)          # indeed they change nothing
    assert ex.readout_values == before


def _clear_of(pic, box, glyph) -> bool:
    """Whether a label's box (plot px, from the lower left) stays clear of a pole glyph's circle."""
    x0, x1, y0, y1 = pic["box"]
    (w, h), (ml, mr, mt, mb) = pic["size"], pic["margin"]
    k = np.array([(w - ml - mr) / (x1 - x0), (h - mt - mb) / (y1 - y0)])
    centre = (np.array([glyph["x"], glyph["y"]]) - [x0, y0]) * k
    return bool(np.hypot(*(centre - np.clip(centre, box[:2], box[2:]))) > glyph["r"])


@pytest.mark.parametrize("state", [dict(kind1="translation"), dict(kind2="translation"),
                                   dict(kind1="translation", angle1=90.0, y2=-1.0),
                                   dict(kind2="translation", x1=0.5, size1=2.0, size2=3.0, angle2=0.0)])
def test_a_translation_term_leaves_the_sums_label_off_the_other_pole(ex, state):
    # with one term a translation, the other term's pole and the sum's lie on one line (4.11): the
    # label "v₃ = v₁ + v₂" must not be drawn over that pole's glyph (the review saw it on v₂)
    from picture_checks import label_boxes

    ex.set(**state)
    pic = ex.picture()
    term = next(i for i in ("v1", "v2") if any(p["p"] == "mark" for p in elements(pic)[i]["parts"]))
    (glyph,) = [p for p in elements(pic)[term]["parts"] if p["p"] == "glyph"]
    (box,) = [b for t, b in label_boxes(pic) if t == "v₃ = v₁ + v₂"]
    assert _clear_of(pic, box, glyph), (term, box, glyph)
    assert problems(pic) == []


@pytest.mark.parametrize("state", [dict(kind2="translation"), dict(kind1="translation"),
                                   dict(kind2="translation", x1=-3.0, size1=1.0, size2=1.0)])
def test_a_translations_label_at_the_edge_is_clear_of_every_pole(ex, state):
    # the review saw "v₂ at ∞" drawn over by the sum's pole glyph at (−3.5, 0): "v₂ ⊕ ∞"
    from picture_checks import label_boxes

    ex.set(**state)
    pic = ex.picture()
    boxes = [b for t, b in label_boxes(pic) if t.endswith("at ∞")]
    assert boxes, label_boxes(pic)
    glyphs = [p for e in pic["elements"] for p in e["parts"] if p["p"] == "glyph"]
    assert len(glyphs) == 2                        # the other term's pole and the sum's, both in view
    for box in boxes:
        for g in glyphs:
            assert _clear_of(pic, box, g), (box, g)
    assert problems(pic) == []
