"""The native pictures of the car, slider-crank and trees explorers (issue 21).

References outside the code under test:

* the readouts the matplotlib explorers gave before they were drawn natively (stored in
  ``readouts_before_native_e3.json`` from commit 8c88eba), to 1e-10;
* the car's geometry by hand: the ICR at ``(-d, 0)`` (the rear tyre drawn at the origin at
  heading 0, everything turned by the heading about the ICR), the tyres at the contacts
  ``(0, 0)`` and ``(0, L)`` turned with it, the acceleration pole of ``a = s ω̇`` at the ICR
  only when the drive makes ``ω̇ ≠ 0`` (6.131);
* the slider-crank's pins by trigonometry: the crank pin at ``r (cos ψ, sin ψ)``, the wrist
  pin on the slide ``x = 0`` at ``r sin ψ + √(l² − r² cos² ψ)``;
* the trees' links 1 m long from their joints at their angles;

and, in every state visited (default, after drags, during Play, a focus), no two labels
overlap, every element has its symbol and a description with its value, and the mechanism
fills a third of the default view's width or height.
"""
import json
import math
from pathlib import Path

import numpy as np
import pytest

from picture_checks import drawn_arrow, elements, overlapping_labels, parts, shown_labels, undescribed
from planargeo.draw.render import picture_bytes
from planargeo.widgets.car import CarExplorer
from planargeo.widgets.slider_crank import SliderCrankExplorer
from planargeo.widgets.trees import TreeExplorer

CLASSES = {"car": CarExplorer, "slider-crank": SliderCrankExplorer, "trees": TreeExplorer}
BEFORE = json.loads((Path(__file__).parent / "readouts_before_native_e3.json").read_text())["cases"]
L = 2.6


def _close(a, b) -> bool:
    if isinstance(a, (int, float)) and isinstance(b, (int, float, np.floating, np.integer)):
        return abs(float(b) - a) <= 1e-10 * max(1.0, abs(a))
    return a == b


@pytest.mark.parametrize("case", BEFORE, ids=lambda c: f"{c['explorer']}-{c['values']}-{c['frames']}")
def test_readout_is_the_one_the_matplotlib_explorer_gave(case):
    ex = CLASSES[case["explorer"]](display="agg", **case["values"])
    if case["frames"]:
        ex.advance(case["frames"])
    got = ex.readout_values
    assert list(got) == list(case["readout"])
    bad = {k: (v, got[k]) for k, v in case["readout"].items() if not _close(v, got[k])}
    assert not bad, bad
    assert ex.readout_of(ex.state) == got                 # the readout is the state's, nothing drawn


def _legible(ex):
    pic = ex.picture()
    assert overlapping_labels(pic) == []
    assert undescribed(pic) == []
    ids = [e["id"] for e in pic["elements"]]
    assert len(ids) == len(set(ids))
    return pic


def _states(name):
    """Explorers in the states a student meets: default, after drags, during Play, with overlays or a focus."""
    cls = CLASSES[name]
    yield "default", cls(display="agg")
    if name == "car":
        ex = cls(display="agg", **{"drive force (N)": 2500.0})
        ex.drag("steering", ex.handles()[1].where(), (-0.5, L - 0.6), steps=3)     # the wheel turned by 50°
        ex.drag("centre of gravity", ex.handles()[0].where(), (0.0, 0.9), steps=2)
        yield "dragged", ex
        ex.advance(12)
        yield "playing", ex
        yield "far ICR", cls(display="agg", **{"turn radius (m)": 45.0, "heading (deg)": 130.0})
        yield "slides", cls(display="agg", **{"speed (m/s)": 14.0})
    elif name == "slider-crank":
        ex = cls(display="agg", **{"velocity poles": True, "acceleration poles": True})
        ex.drag("crank pin", ex.handles()[0].where(), (-1.5, 1.0), steps=3)
        yield "dragged, poles", ex
        ex.advance(9)
        yield "playing", ex
        yield "dead centre", cls(display="agg", **{"crank angle (deg)": -90.0})
    else:
        ex = cls(display="agg", **{"velocity poles": True})
        ex.drag("tip of body 2", ex.handles()[1].where(), (-0.3, 1.9), steps=3)
        yield "dragged, poles", ex
        ex.advance(6)
        yield "playing", ex
        yield "focus", cls(display="agg", focus="F₂")
        yield "open, gravity", cls(display="agg", loops="open (Fig 9.1)", gravity=9.81)


@pytest.mark.parametrize("name", sorted(CLASSES))
def test_every_state_is_legible_and_every_element_explains_itself(name, tmp_path):
    for what, ex in _states(name):
        assert ex.message == "" or "dead centre" in ex.message, (what, ex.message)
        pic = _legible(ex)
        for el in pic["elements"]:
            assert ":" in el["desc"], (what, el["id"], el["desc"])        # meaning: value
        png = picture_bytes(pic, "png")                                    # the export draws it
        assert png[:8] == b"\x89PNG\r\n\x1a\n", what


@pytest.mark.parametrize("name", sorted(CLASSES))
def test_the_mechanism_fills_a_third_of_the_default_view(name):
    ex = CLASSES[name](display="agg")
    x0, x1, y0, y1 = ex.picture()["box"]
    pts = ex.mechanism_points()
    span = np.ptp(pts, axis=0)
    assert span[0] >= (x1 - x0) / 3 or span[1] >= (y1 - y0) / 3, (span, (x1 - x0, y1 - y0))
    assert np.all((pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1))


# ------------------------------------------------------------------------------------------ car
@pytest.mark.parametrize("d, heading", [(8.0, 0.0), (5.0, 70.0), (9.5, 215.0)])
def test_car_icr_and_tyres_at_the_hand_computed_places(d, heading):
    ex = CarExplorer(display="agg", **{"turn radius (m)": d, "heading (deg)": heading})
    els = elements(ex.picture())
    (icr,) = parts(els["ICR"], "mark")
    assert (icr["x"], icr["y"]) == pytest.approx((-d, 0.0), abs=1e-4)
    th = math.radians(heading)
    rot = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
    for eid, contact in (("rear tyre", (d, 0.0)), ("front tyre", (d, L))):
        centre = rot @ np.array(contact) + [-d, 0.0]
        xy = np.array(parts(els[eid], "path")[0]["xy"])
        assert xy.mean(axis=0) == pytest.approx(centre, abs=1e-4), eid
        assert np.hypot(*(xy[1] - xy[0])) == pytest.approx(0.7, abs=1e-4)     # a tyre 0.7 m long
    # the front tyre points along its rolling direction, square to the line to the ICR
    front = np.array(parts(els["front tyre"], "path")[0]["xy"])
    to_icr = front.mean(axis=0) - (-d, 0.0)
    assert float((front[1] - front[0]) @ to_icr) == pytest.approx(0.0, abs=1e-3)
    (g,) = parts(els["G"], "mark")
    cg = rot @ np.array([d, (1 - 0.45) * L]) + [-d, 0.0]
    assert (g["x"], g["y"]) == pytest.approx(tuple(cg), abs=1e-4)


def test_coasting_car_has_no_acceleration_pole_and_a_driven_one_has_it_at_the_icr():
    coast = CarExplorer(display="agg")
    els = elements(coast.picture())
    assert "a" not in els                                    # ω̇ = 0: a = s ω̇ = 0 (6.131)
    assert "no acceleration pole" in els["ICR"]["desc"] and "v = s ω" in els["ICR"]["desc"]
    drive = CarExplorer(display="agg", **{"drive force (N)": 2000.0})
    els = elements(drive.picture())
    (a,) = parts(els["a"], "mark")
    (icr,) = parts(els["ICR"], "mark")
    assert (a["x"], a["y"]) == (icr["x"], icr["y"]) == pytest.approx((-8.0, 0.0), abs=1e-4)
    assert "the ICR too" in els["a"]["desc"] and "acceleration pole a" in els["ICR"]["desc"]
    wd = drive.readout_values["yaw acceleration ω̇"]
    assert f"{wd:.3g} rad/s²" in els["a"]["desc"]


def test_car_drive_arrow_ends_at_its_handle():
    ex = CarExplorer(display="agg", **{"drive force (N)": 2000.0, "heading (deg)": 30.0})
    vec, mid = drawn_arrow(ex.picture(), "f_A")
    tail = mid - vec / 2
    (wheel,) = parts(elements(ex.picture())["front tyre"], "path")
    front = np.mean(np.array(wheel["xy"], float), axis=0)      # the front tyre's middle: its contact
    tip = np.array(ex.handles()[3].where())
    assert tail + vec == pytest.approx(tip, abs=1e-3)
    assert np.hypot(*vec) == pytest.approx(2.0, abs=1e-3)      # 2000 N at 1 mm/N
    assert tail == pytest.approx(front, abs=1e-3)                # from the front tyre's contact


def test_car_labels_are_off_the_body():
    """The tyre forces are labelled beside the car, not on its body (issue 21: labels piled up there)."""
    ex = CarExplorer(display="agg")
    pic = ex.picture()
    body = np.array(parts(elements(pic)["body"], "path")[0]["xy"])
    x0, x1 = body[:, 0].min(), body[:, 0].max()
    for eid in ("R₁μ₁", "R₂μ₂"):
        (t,) = parts(elements(pic)[eid], "text")
        assert t["x"] > x1, eid                                # the anchor lies right of the body
    assert {"R₁μ₁", "R₂μ₂", "G", "I", "T", "p", "v = sω (ICR)"} <= {t for _i, t in shown_labels(pic)}


# --------------------------------------------------------------------------------- slider-crank
@pytest.mark.parametrize("deg, l", [(23.0, 5.0), (140.0, 4.0), (-70.0, 6.5)])
def test_slider_crank_pins_at_their_closed_form_places(deg, l):
    ex = SliderCrankExplorer(display="agg", **{"crank angle (deg)": deg, "rod length": l})
    r = 2.29
    psi = math.radians(deg)
    pin = r * np.array([math.cos(psi), math.sin(psi)])
    wrist = np.array([0.0, r * math.sin(psi) + math.sqrt(l * l - (r * math.cos(psi)) ** 2)])
    els = elements(ex.picture())
    pins = np.array([(m["x"], m["y"]) for m in parts(els["pins"], "mark")])
    np.testing.assert_allclose(pins, [[0.0, 0.0], pin, wrist], atol=1e-4)
    np.testing.assert_allclose(parts(els["rod"], "path")[0]["xy"], [pin, wrist], atol=1e-4)
    piston = np.array(parts(els["piston"], "path")[0]["xy"])
    assert piston[:, 1].min() == pytest.approx(wrist[1], abs=1e-4) and piston[:, 1].max() == pytest.approx(
        wrist[1] + 1.0, abs=1e-4)                              # the piston 2 t = 1 m tall above the wrist pin
    assert f"{ex.readout_values['piston height h']:.4g} m" in els["piston"]["desc"]


def test_slider_crank_force_labels_sit_away_from_the_pins():
    """Each force is labelled at its arrow's head, at least 0.9 m from its joint (issue 21: labels piled up)."""
    ex = SliderCrankExplorer(display="agg")
    els = elements(ex.picture())
    for sym, key in (("f₁", "f_1"), ("f₂", "f_2"), ("f₃", "f_3"), ("F₃", "F_1")):
        (t,) = parts(els[sym], "text")
        joint = ex.state["reactions"][key].point
        assert np.hypot(t["x"] - joint[0], t["y"] - joint[1]) >= 0.9 - 1e-3, sym


def test_slider_crank_has_no_ticks_but_a_scale_bar():
    pic = SliderCrankExplorer(display="agg").picture()
    assert not pic["ticks"]
    bar = np.array(parts(elements(pic)["scale bar"], "path")[0]["xy"])
    length = float(np.hypot(*(bar[1] - bar[0])))
    assert parts(elements(pic)["scale bar"], "text")[0]["text"] == f"{length:g} m"


# ---------------------------------------------------------------------------------------- trees
def test_trees_links_from_their_joints_at_their_angles():
    ex = TreeExplorer(display="agg")
    els = elements(ex.picture())
    pose = ex.state["sol"].data.pose
    for i in range(9):
        xy = np.array(parts(els[f"body {i + 1}"], "path")[0]["xy"])
        end = pose[i, :2] + np.array([math.cos(pose[i, 2]), math.sin(pose[i, 2])])      # links 1 m long
        np.testing.assert_allclose(xy, [pose[i, :2], end], atol=1e-4)
        assert parts(els[f"body {i + 1}"], "text")[0]["text"] == str(i + 1)


def test_trees_focus_keeps_the_other_forces_faint_and_unlabelled():
    ex = TreeExplorer(display="agg", focus="F₂")
    pic = _legible(ex)
    els = elements(pic)
    forces = [f"f{s}" for s in "₁₂₃₄₅₆₇₈₉"] + ["F₁", "F₂"]
    assert [i for i, _t in shown_labels(pic) if i in forces] == ["F₂"]
    assert all(els[k]["opacity"] < 0.5 for k in forces if k != "F₂")
    assert "8-9" in els["F₂"]["desc"]
