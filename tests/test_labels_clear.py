"""Labels sit clear of the other elements' lines, glyphs and labels wherever a spot near them is free.

A student review found force labels under force lines and pole glyphs (the 10-link chain with every
overlay), the T/U split's labels crowding one another, and the trees' f₄, f₅, f₉ crossed by dashed
lines.  Crossings are measured here from the picture data alone (:func:`_picture_checks.crossed_labels`:
each label's box, less :data:`PAD` px of room around its text, against every other element's drawn
segments, arcs, arrow heads, markers and texts), not by the placer's raster.

Where a label still crosses something, no spot near it is free: every spot the placer may use (its
asked one, beside its line up to six label heights along it on either side, two rings of eight
around its anchor) is crossed or taken by a label placed before it.  There the count is bounded by
the old placer's count minus the crossings this change removed (old → new, the same check).
"""
from __future__ import annotations

import numpy as np
import pytest

import planargeo.widgets as pw
from planargeo.draw.chain import OVERLAYS
from planargeo.draw.picture import Picture
from planargeo.widgets import EXPLORERS, ChainExplorer, TreeExplorer

from _picture_checks import crossed_labels, label_boxes, to_px

#: the box is 1.25 font sizes high and 0.6 of one per character: room around the text a stroke may graze
PAD = 2.0

#: labels of an explorer's default state with no free spot near them: "centre of percussion" (20
#: characters) lies between the inertia circle, the axis of percussion and the body
NOT_FREE = {"PercussionExplorer": {"centre of percussion"}}


def hits(pic) -> list:
    return crossed_labels(pic, tol=PAD)


def hidden(pic) -> int:
    return sum(1 for e in pic["elements"] for p in e["parts"] if p["p"] == "text" and p.get("hidden"))


@pytest.mark.parametrize("name", sorted(EXPLORERS))
def test_default_picture_labels_cross_no_other_element(name):
    pic = getattr(pw, name)(display="agg").picture()
    # old placer: Projective 1, Chain 12, Tree 9, Subspace 3, Impulse 4, Construction 2, Articulated 4,
    # Splitting 1 crossings (Percussion 1: unchanged, not free)
    assert {text for _eid, text, _other in hits(pic)} <= NOT_FREE.get(name, set()), hits(pic)
    assert hidden(pic) == 0


def test_tree_forces_are_not_crossed_by_dashed_lines():
    pic = TreeExplorer(display="agg").picture()
    shown = {text for _eid, text, _box in label_boxes(pic)}
    assert {"f₄", "f₅", "f₉"} <= shown                 # drawn, not hidden
    assert not hits(pic), hits(pic)                    # old: f₅ by 8 elements, f₉ by f₂, 9 in all


def test_chain_with_every_overlay_force_labels_leave_lines_and_glyphs():
    ex = ChainExplorer(display="agg", links=10, **{k: True for k in OVERLAYS})
    pic = ex.picture()
    crossed = hits(pic)
    by_label: dict[str, set] = {}
    for eid, _text, other in crossed:
        by_label.setdefault(eid, set()).add(other)
    shown = {eid for eid, _text, _box in label_boxes(pic)}
    # f₁ f₂ f₃ are clear (old: f₁ under 7 elements, f₂ under 3, f₃ hidden); f₄ has no free spot near
    # it and crosses one force line (old: hidden)
    assert {"f1", "f2", "f3", "f4"} <= shown
    assert not by_label.keys() & {"f1", "f2", "f3"}, crossed
    assert by_label.get("f4", set()) <= {"p7"}
    # none of them sits on a pole's glyph (f₇'s one free spot is taken by v₈'s label: it touches a₁₀'s)
    poles = {e["id"] for e in pic["elements"] if any(p["p"] == "glyph" for p in e["parts"])}
    assert not any(by_label.get(f"f{i}", set()) & poles for i in range(1, 5))
    # the crowd as a whole: 243 crossings and 28 labels hidden with the old placer
    assert len(crossed) <= 243 - 118 and hidden(pic) <= 28 - 24


def test_chain_tu_split_labels_keep_apart():
    ex = ChainExplorer(display="agg", **{"T/U split": True})
    pic = ex.picture()
    crossed = hits(pic)
    # old: 31 crossings (sψ₁ on f₁ and Rμ₁, Rμ₁ on v₂, Uγ₂ on f₄ and Rμ₄, f₁ f₂ f₄ on the links, ...);
    # Rμ₂ lies on f₂'s line in the crowd at the base, its free spots taken by f₁ f₂ sψ₁ sψ₂ v₂
    assert {eid for eid, _text, _other in crossed} <= {"Rμ2"}, crossed
    assert len(crossed) <= 31 - 30
    split = {eid for eid, _t, _b in label_boxes(pic) if eid[:2] in ("sψ", "Rμ", "Uγ")}
    assert split == {f"{k}{i}" for k in ("sψ", "Rμ", "Uγ") for i in range(1, 5)}     # all drawn


def _placed(pic) -> dict:
    """Every label but the refusal's: where it is put (offset, alignment) or that it hides."""
    return {(e["id"], k): (p["dx"], p["dy"], p["ha"], p["va"], p.get("hidden", False))
            for e in pic["elements"] if e["id"] != "figure message"
            for k, p in enumerate(e["parts"]) if p["p"] == "text"}


def test_a_refusal_drawn_over_the_picture_moves_no_label():
    # the refusal's words and white panel are a passing note over everything (Picture.text with
    # obstacle=False): the labels stay where they are without it
    ex = ChainExplorer(display="agg")
    before = ex.picture()
    ex.set(**{"joint speeds": "fast, then faster, and then as fast as the chain can go without flying apart"})
    assert ex.message.startswith("joint speeds must be numbers")        # refused: the state is kept
    after = ex.picture()
    assert any(e["id"] == "figure message" for e in after["elements"])
    assert _placed(after) == _placed(before)


PANEL = [(-0.8, -0.8), (0.8, -0.8), (0.8, 0.2), (-0.8, 0.2)]      # its top edge 14 px above the x axis


def _panel_picture(panel: str | None) -> dict:
    """The x axis labelled f, with a white panel's edge across its label: a passing note's (drawn
    with its words, as the explorers draw a refusal), an ordinary element, or none."""
    pic = Picture((-2, 2, -2, 2), size=(300, 300), ticks=False)
    pic.line("f", [1.0, 0.0, 0.0], symbol="f")
    if panel == "note":
        pic.text("note", (0.0, 0.0), "refused", obstacle=False, z=100)
        pic.elements[-1]["parts"].insert(0, {"p": "path", "closed": True, "xy": np.array(PANEL)})
        pic.elements[-1].update(fill="white")
    elif panel == "element":
        pic.path("panel", PANEL, closed=True, fill="white", z=100)
    return pic.to_dict()


def _f_label(pic) -> list:
    return [v for (eid, _k), v in _placed(pic).items() if eid == "f"]


def test_a_panel_drawn_with_a_passing_note_moves_no_label():
    alone = _f_label(_panel_picture(None))
    assert len(alone) == 1 and _f_label(_panel_picture("note")) == alone
    # the same panel as an ordinary element: f's label leaves its edge (the check above can fail)
    assert _f_label(_panel_picture("element")) != alone
    pic = _panel_picture(None)
    ((_eid, _text, (x0, y0, x1, y1)),) = [b for b in label_boxes(pic) if b[0] == "f"]
    (px0, _), (px1, top) = to_px(pic, *PANEL[0]), to_px(pic, *PANEL[2])
    assert px0 < x0 < x1 < px1 and y0 + PAD < top < y1 - PAD       # alone, the edge crosses it
