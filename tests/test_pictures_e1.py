"""The native pictures of the projective, percussion, screw-sum and construction explorers (issue 21).

Checked on the plain picture data (``ex.picture()``) that the page draws and on the
figure matplotlib draws from it for exports:

* every element has its thesis symbol and a description "meaning (equation): value";
* no two labels overlap, in the default state, after drags, with ideal points and lines,
  with the key on; texts are legible as matplotlib draws them;
* the same thing keeps the same id across states (a drag changes positions, not ids);
* the mechanism fills at least a third of the default view;
* ``readout_of`` of the shown state is the shown readout;
* hand-computed positions: a pole at infinity is an arrow at the edge, a line through
  known points, the caption never cut.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import planargeo.widgets as pw
from planargeo.draw.layout import legibility_problems
from planargeo.draw.render import figure

from _picture_checks import elements, fill, problems

#: (explorer, constructor values, then values set) visited by the checks
STATES = [
    ("ProjectiveExplorer", {}, {}),
    ("ProjectiveExplorer", {}, {"P x": 0.3, "P y": 0.2}),
    ("ProjectiveExplorer", {}, {"P at infinity": True, "M at infinity": True}),
    ("ProjectiveExplorer", {}, {"conic": "parabola", "M at infinity": True, "P x": 0.5, "P y": 2.5}),
    ("ProjectiveExplorer", {}, {"conic": "hyperbola", "P x": 0.5, "P y": 2.5}),
    ("ProjectiveExplorer", {}, {"conic": "inertia (imaginary circle)"}),
    ("PercussionExplorer", {}, {}),
    ("PercussionExplorer", {}, {"pole x": 0.3, "pole y": 0.2}),
    ("PercussionExplorer", {}, {"pole x": 0.45, "pole y": 0.0}),
    ("PercussionExplorer", {}, {"drive": "impact", "impact at": 0.3}),
    ("PercussionExplorer", {}, {"shape": "L-shape", "pole x": -0.5, "pole y": 0.5}),
    ("PercussionExplorer", {}, {"shape": "disc", "pole x": 1.5, "pole y": -1.0}),
    ("ScrewSumExplorer", {}, {}),
    ("ScrewSumExplorer", {}, {"size2": -1.0}),
    ("ScrewSumExplorer", {}, {"kind2": "translation", "angle2": 45.0}),
    ("ScrewSumExplorer", {"add": "wrenches"}, {}),
    ("ScrewSumExplorer", {"add": "wrenches"}, {"angle2": 0.0}),
    ("ScrewSumExplorer", {"add": "wrenches"}, {"kind1": "couple", "kind2": "couple"}),
    ("ConstructionExplorer", {"construction": "wrench_sum"}, {"angle2": 60.0}),
    ("ConstructionExplorer", {"construction": "acceleration"}, {"step": 4, "earlier": "shown"}),
    ("ConstructionExplorer", {"construction": "newton_euler"}, {}),
    ("ConstructionExplorer", {"construction": "through_infinity"}, {"hx": 2.0, "hy": 0.0}),
]
NAMES = ["ProjectiveExplorer", "PercussionExplorer", "ScrewSumExplorer", "ConstructionExplorer"]


def make(name, init, vals):
    ex = getattr(pw, name)(display="agg", **init)
    if vals:
        ex.set(**vals)
    assert ex.message == "", ex.message
    return ex


@pytest.mark.parametrize("name, init, vals", STATES, ids=[f"{n}-{i}-{v}" for n, i, v in STATES])
def test_every_element_described_and_no_labels_overlap(name, init, vals):
    ex = make(name, init, vals)
    pic = ex.picture()
    assert problems(pic) == []
    assert legibility_problems(figure(pic)) == []
    # a description is "meaning (equation): value": an equation number before the colon
    for e in pic["elements"]:
        if e["id"].startswith(("key ", "caption", "figure message")):
            continue
        head = e["desc"].split(":")[0]
        assert "(" in head and any(ch.isdigit() for ch in head) or e["id"] in ("grip", "body"), e["desc"]


@pytest.mark.parametrize("name, init, vals", [
    ("ScrewSumExplorer", {}, {"kind2": "translation", "angle2": 45.0, "key": True}),
    ("ProjectiveExplorer", {}, {"conic": "hyperbola", "P x": 0.5, "P y": 2.5, "key": True}),
    ("ConstructionExplorer", {"construction": "newton_euler"}, {"step": 4, "key": True}),
    ("PercussionExplorer", {}, {"shape": "disc", "pole x": 1.5, "pole y": -1.0, "key": True})])
def test_no_label_lands_on_the_key(name, init, vals):
    """The key (the base's, from the picture's symbols and meanings) shares the placer: no overlaps."""
    ex = make(name, init, vals)
    pic = ex.picture()
    assert any(e["id"].startswith("key ") for e in pic["elements"])
    assert [p for p in problems(pic) if "overlap" in p] == []


@pytest.mark.parametrize("name", NAMES)
def test_the_mechanism_fills_a_third_of_the_default_view(name):
    ex = getattr(pw, name)(display="agg")
    pic = ex.picture()
    pts = ex.mechanism_points()
    x0, x1, y0, y1 = pic["box"]
    assert np.all((pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1))
    assert fill(pic, pts) >= 1 / 3


@pytest.mark.parametrize("name", NAMES)
def test_a_drag_keeps_the_ids_and_the_readout_is_the_states(name):
    ex = getattr(pw, name)(display="agg")
    ids = [e["id"] for e in ex.picture()["elements"]]
    h = next(h for h in ex.all_handles() if h.where() is not None)
    a = np.asarray(h.where(), float)
    ex.drag(h.name, tuple(a), tuple(a + [0.1, 0.05]), steps=2)
    assert ex.message == ""
    assert [e["id"] for e in ex.picture()["elements"]] == ids
    assert ex.readout_of(ex.state) == ex.readout_values


def test_projective_pole_of_a_line_at_its_hand_computed_place():
    """Circle x² + y² = 4, the line y = 1 (angle 0°, offset 1): its pole is (0, r²/1) = (0, 4) (5.37);
    the polar of P = (3, 0) is x = 4/3 (5.36)."""
    ex = make("ProjectiveExplorer", {"conic": "circle", "a": 2.0},
              {"line angle (deg)": 0.0, "line offset": 1.0, "P x": 3.0, "P y": 0.0})
    els = elements(ex.picture())
    m = next(p for p in els["pole of M"]["parts"] if p["p"] == "mark")
    assert (m["x"], m["y"]) == pytest.approx((0.0, 4.0))
    polar = np.array(next(p["xy"] for p in els["polar"]["parts"] if p["p"] == "path"))
    assert polar[:, 0] == pytest.approx([4 / 3, 4 / 3], abs=1e-4)
    assert polar[:, 1].min() == pytest.approx(ex.picture()["box"][2]) and \
        polar[:, 1].max() == pytest.approx(ex.picture()["box"][3])           # clipped to the view
    assert els["pole of M"]["desc"] == "pole C⁻¹ M of the line M (5.37): at (0, 4) m"


def test_screw_sum_translation_pole_is_an_edge_arrow_along_the_motion():
    """v₂ a translation at 45°: its pole is ideal, drawn as an arrow at the edge whose shaft
    points along the motion (1, 1)/√2 (a twist's ideal pole, 4.10)."""
    ex = make("ScrewSumExplorer", {}, {"kind2": "translation", "angle2": 45.0, "size2": 2.0})
    parts = elements(ex.picture())["v2"]["parts"]
    arrow = next(p for p in parts if p["p"] == "arrow")
    assert arrow["dx"] == pytest.approx(arrow["dy"]) and arrow["dx"] > 0
    assert next(p for p in parts if p["p"] == "text")["text"] == "v₂ at ∞"
    assert not any(p["p"] == "mark" for p in parts)


def test_construction_caption_is_never_cut():
    """Issue 21: the caption (the step and its equation) is drawn whole, in at most two lines
    that fit the picture's width (0.6 font sizes per character)."""
    ex = make("ConstructionExplorer", {"construction": "newton_euler"}, {})
    pic = ex.picture()
    lines = [p["text"] for p in elements(pic)["caption"]["parts"] if p["p"] == "text"]
    assert len(lines) == 2
    assert " ".join(lines) == ex.caption
    width = pic["size"][0] - pic["margin"][0] - pic["margin"][1]
    assert all(6.0 + 0.6 * pic["font_px"] * len(t) <= width for t in lines)
    assert not any(p.get("hidden") for p in elements(pic)["caption"]["parts"])


def test_percussion_centre_of_percussion_by_hand():
    """Uniform rod 1 × 0.08 m, pole at the grip (0, 0): c = (0.5, 0), ρ² = (1 + 0.08²)/12; the axis is
    x = 0.5 + ρ²/0.5 and the centre of percussion is there on the x axis (5.67-5.68)."""
    ex = make("PercussionExplorer", {"shape": "uniform rod"}, {})
    rho2 = (1.0 + 0.08 ** 2) / 12.0
    els = elements(ex.picture())
    spot = next(p for p in els["spot"]["parts"] if p["p"] == "mark")
    assert (spot["x"], spot["y"]) == pytest.approx((0.5 + rho2 / 0.5, 0.0), abs=1e-5)
    axis = np.array(next(p["xy"] for p in els["axis of percussion"]["parts"] if p["p"] == "path"))
    assert axis[:, 0] == pytest.approx([0.5 + rho2 / 0.5] * 2, abs=1e-5)
    ellipse = next(p for p in els["I"]["parts"] if p["p"] == "ellipse")       # the gyration circle
    assert (ellipse["x"], ellipse["y"]) == pytest.approx((0.5, 0.0), abs=1e-9)
    assert math.sqrt(abs(np.linalg.det(np.reshape(ellipse["m"], (2, 2))))) == pytest.approx(math.sqrt(rho2), rel=1e-4)


#: readouts shown by the matplotlib explorers before they were made native (commit 8c88eba,
#: ``render``): the native ``readout_of`` shows exactly these texts
OLD_READOUTS = [
    ('ProjectiveExplorer', {}, {},
     {'P x': '2 m', 'P y': '1.5 m', 'P': '(2, 1.5) m', 'conic': 'real ellipse', 'P is': 'outside', 'polar of P: distance to origin': '0.7769 m', 'pole of M': '(-4.283, -1.189) m', 'P·M': '-2.73 m', 'pole(M)·polar(P)': '-2.73 m', 'centre': '(0, 0) m'}),
    ('ProjectiveExplorer', {}, {'P at infinity': True, 'M at infinity': True},
     {'P x': '2', 'P y': '1.5', 'P': 'at infinity (direction (0.8, 0.6))', 'conic': 'real ellipse', 'P is': 'outside (at infinity)', 'polar of P: distance to origin': '0 m', 'pole of M': '(0, 0) m', 'P·M': '0', 'pole(M)·polar(P)': '0', 'centre': '(0, 0) m'}),
    ('PercussionExplorer', {}, {'shape': 'L-shape', 'pole x': -0.5, 'pole y': 0.5},
     {'pole x': '-0.5 m', 'pole y': '0.5 m', 'mass m': '1 kg', 'radius of gyration ρ': '0.3439 m', 'centre of mass': '(0.6286, 0.07143) m', 'pole': '(-0.5, 0.5) m', 'd = |pole − c|': '1.207 m', 'r = ρ²/d (5.68)': '0.09795 m', 'l = d + ρ²/d (5.67)': '1.305 m', 'angular accel. α': '10 rad/s²', 'force for α: m d α (5.66)': '12.07 N', 'centre of percussion': '(0.7201, 0.03665) m', 'sweet spot of the grip': '(0.8143, 0.09253) m'}),
    ('ScrewSumExplorer', {}, {'kind2': 'translation', 'angle2': 45.0},
     {'ω₁': '1 rad/s', 'ω₂': '0 rad/s', 'ω₃ = ω₁ + ω₂': '1 rad/s', 'pole of sum': '(-2.914, 1.414) m', 'case': 'rotation plus translation (4.16)', 'β': 'none', 'ρ': '2 m', 'sum': '(1.414 m/s, 2.914 m/s, 1 rad/s)'}),
    ('ScrewSumExplorer', {'add': 'wrenches'}, {'kind1': 'couple', 'kind2': 'couple'},
     {'F₁': '0 N', 'F₂': '0 N', '|F₃| = |F₁ + F₂|': '0 N', 'meet of lines': 'none (the sum is zero)', 'case': 'two couples (4.46)', 'β': 'none', 'ρ': 'none', 'sum': '(0 N, 0 N, 3 N·m)'}),
    ('ConstructionExplorer', {'construction': 'wrench_sum'}, {},
     {'step': '4/4', 'equation': '4.33', 'F₁': '1 N', 'F₂': '1.5 N', 'F₃': '2.179 N', 'β': '—', 'ρ': '—', 'meet P': '(0.1443, 2.348) m', 'f₃': '(-0.25 N, 2.165 N, 0.8995 N·m)', 'case': 'concurrent forces (4.4.1)'}),
    ('ConstructionExplorer', {'construction': 'newton_euler'}, {'step': 1},
     {'step': '1/6', 'equation': '4.58, 10.2.3', 'm': '1 kg', '|Ia|': '2.704 N', '|p|': '4.5 N', '|fⁿᵉᵗ|': '2.704 N', 'τ': '2.49 N·m', 'ρ = τ/|fⁿᵉᵗ|': '0.9208 m', 'fⁿᵉᵗ': '(-1.5 N, 2.25 N, 1.365 N·m)', 'power of fⁿᵉᵗ on v': '-4.14 W', 'case': 'force on a finite line (4.27)'}),
]


@pytest.mark.parametrize("name, init, vals, shown", OLD_READOUTS, ids=[f"{r[0]}-{k}" for k, r in enumerate(OLD_READOUTS)])
def test_the_readout_is_the_one_the_matplotlib_explorer_showed(name, init, vals, shown):
    ex = make(name, init, vals)
    assert ex.readout_strings == shown


def test_two_translations_join_on_the_line_at_infinity_not_a_couple():
    """Two translations: both poles are ideal, so the lever line Q₁Q₂ is the line at infinity (5.32);
    for twists that is a line, not a couple (the word belongs to wrenches, 4.27)."""
    ex = make("ScrewSumExplorer", {}, {"kind1": "translation", "kind2": "translation"})
    lever = elements(ex.picture())["lever"]
    texts = [p["text"] for p in lever["parts"] if p["p"] == "text"]
    assert texts == ["Q₁Q₂: the line at ∞"] and not any(p["p"] == "path" for p in lever["parts"])
    c = make("ConstructionExplorer", {"construction": "wrench_sum"}, {"F2": 0.0, "tau2": 1.0})
    f2 = elements(c.picture())["f2"]          # a couple is a wrench on the line at infinity
    assert [p["text"] for p in f2["parts"] if p["p"] == "text"] == ["f₂: couple (line at ∞)"]
    assert not any(p.get("hidden") for p in f2["parts"])


@pytest.mark.parametrize("name", NAMES)
def test_a_view_from_the_page_is_the_box_shown(name):
    """The page sends the box it shows after a pan or zoom: the picture keeps exactly that box
    (a second band for the construction's caption would shift every handle under the pointer)."""
    ex = getattr(pw, name)(display="agg")
    x0, x1, y0, y1 = ex.picture()["box"]
    dx, dy = 0.1 * (x1 - x0), 0.05 * (y1 - y0)
    box = (x0 + dx, x1 + dx, y0 + dy, y1 + dy)                 # panned, same scale
    pic = ex.scene_picture(ex.state, box).to_dict()
    assert pic["box"] == pytest.approx(list(box), abs=1e-4)
