"""What a chain update keeps from the last one stays true when the controls change.

The explorer keeps its "what is shown" meanings (per number of links and end joints), its
handles and the last wire form of each element; a picture's path with non-finite rows is cut
into pieces; a readout value's numbers are formatted once for both readout columns.
"""
import math
import warnings

import numpy as np
import pytest

from planargeo.draw.picture import Picture
from planargeo.widgets import ChainExplorer
from planargeo.widgets.canvas import PictureCanvas
from planargeo.widgets.readout import fmt, value_text, value_texts


@pytest.fixture
def ex():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        yield ChainExplorer(display="page", links=3)


def _joint_rows(explain: dict) -> dict:
    # one joint's rows (a subscript number), not the general row q̈ᵢ
    return {k: m for k, m in explain.items() if k.startswith("q̈") and k[-1] in "₀₁₂₃₄₅₆₇₈₉"}


def test_meanings_follow_links_and_joint_kinds(ex):
    rows = _joint_rows(ex.explain())
    assert set(rows) == {"q̈₁", "q̈₃"}
    assert "revolute, rad/s²" in rows["q̈₃"]
    ex.set(links=5)
    rows = _joint_rows(ex.explain())
    assert set(rows) == {"q̈₁", "q̈₅"}
    assert "v₅" in ex.explain()["vᵢ"]
    ex.set(joints="prismatic")
    rows = _joint_rows(ex.explain())
    assert "prismatic, m/s²" in rows["q̈₁"] and "prismatic, m/s²" in rows["q̈₅"]
    # the panel says what explain says
    assert "q̈₅" in ex.explain_box.value and "prismatic" in ex.explain_box.value
    ex.set(joints="alternating")   # joint 1 revolute, joint 5 revolute (odd joints)
    rows = _joint_rows(ex.explain())
    assert "revolute" in rows["q̈₁"] and "revolute" in rows["q̈₅"]


def test_explain_returns_a_fresh_dict(ex):
    a = ex.explain()
    a["q̈₁"] = "changed"
    assert ex.explain()["q̈₁"] != "changed"


def test_handles_follow_the_shown_chain(ex):
    # 3 links: the base and three link ends can be dragged; the end is one link length from
    # its joint
    ids = [h["id"] for h in ex.canvas.picture["handles"]]
    assert ids == ["base", "link 1 end", "link 2 end", "link 3 end"]
    ex.set(links=6)
    ids = [h["id"] for h in ex.canvas.picture["handles"]]
    assert ids == ["base"] + [f"link {i} end" for i in range(1, 7)]
    pose = ex.state["w"].pose
    x, y = ex.handle_position("link 6 end")
    assert math.hypot(x - pose[5, 0], y - pose[5, 1]) == pytest.approx(1.0)
    # a drag of the new last link's end sets its joint: the end then lies where it was dragged
    # (on the circle of one link length about its joint)
    jx, jy = pose[5, 0], pose[5, 1]
    ok, why = ex.canvas.handle_message({"type": "drag", "id": "link 6 end", "x": jx, "y": jy + 1.0, "seq": 1})
    assert ok, why
    x, y = ex.handle_position("link 6 end")
    assert (x, y) == pytest.approx((jx, jy + 1.0), abs=1e-3)


def test_path_pieces_between_non_finite_rows():
    nan = math.nan
    xy = [[0, 0], [1, 0], [nan, nan], [2, 2], [nan, 1], [3, 3], [4, 3], [5, 3], [nan, nan],
          [nan, nan], [6, 6], [7, 7]]
    pic = Picture((-10, 10, -10, 10), size=(200, 200))
    pic.path("p", xy)
    pieces = [p["xy"].tolist() for p in pic.elements[0]["parts"]]
    # by hand: rows between non-finite rows, pieces of one point left out
    assert pieces == [[[0, 0], [1, 0]], [[3, 3], [4, 3], [5, 3]], [[6, 6], [7, 7]]]
    # pieces are copies: changing the input later does not move the picture
    arr = np.array(xy, float)
    pic2 = Picture((-10, 10, -10, 10), size=(200, 200))
    pic2.path("p", arr)
    arr[:] = 0.0
    assert pic2.elements[0]["parts"][1]["xy"].tolist() == [[3, 3], [4, 3], [5, 3]]


@pytest.mark.parametrize("value, unit", [(2.5, "m"), (-0.000123456, "N"), ((1.0, 2.0), ("m", "rad")),
                                         ((1.0, 2.0), "m/s"), ("at rest", "m"), (3, "")])
def test_value_texts_are_fmt_and_value_text(value, unit):
    assert value_texts(value, unit, zero=1e-9) == (fmt(value, zero=1e-9), value_text(value, unit, zero=1e-9))


def _pic(x):
    return {"size": [200, 200], "margin": [0, 0, 0, 0], "box": [0.0, 10.0, 0.0, 10.0],
            "elements": [{"id": "m", "role": "twist", "color": "#000",
                          "parts": [{"p": "mark", "x": x, "y": 1.0, "shape": "o", "size": 6.0}]}]}


def test_canvas_sends_no_element_the_page_holds_as_rounded():
    c = PictureCanvas()
    sent = []
    c.send = lambda m, *a, **k: sent.append(m)
    c.picture = _pic(1.0)
    nd = c._snapshot()["head"]["nd"]          # 20 px per unit: a thousandth of a unit
    assert nd == math.ceil(math.log10(10 * 20))
    del sent[:]
    c.picture = _pic(1.0 + 10.0 ** -(nd + 2))   # changed below the page's precision: nothing sent
    assert sent == []
    c.picture = _pic(1.5)
    assert [m["set"] for m in sent] == [{"m": {"parts": [["M", 1.5, 1.0, "o", 6.0]]}}]
