"""The native pictures of the subspace, impulse, splitting and articulated explorers, against hand geometry.

Positions are computed here by hand (axes of percussion ``x = d + ρ²/d``, poles of motions
the joint allows, clipped lines through known points), never with the package's picture code.
"""
from __future__ import annotations

import numpy as np
import pytest

from _picture_checks import elements, fill, label_boxes, overlapping_labels, problems
from planargeo.widgets import SubspaceExplorer


def _marks(el):
    return [(p["x"], p["y"]) for p in el["parts"] if p["p"] == "mark"]


def _paths(el):
    return [np.asarray(p["xy"], float) for p in el["parts"] if p["p"] == "path"]


def test_label_boxes_are_measured_from_the_picture_data():
    """A hand-made picture: one label 10 characters long at (0, 0), offset (4, 4), left/bottom."""
    pic = {"box": [-1.0, 1.0, -1.0, 1.0], "margin": [0, 0, 0, 0], "size": [200, 200], "font_px": 10.0,
           "elements": [{"id": "a", "parts": [{"p": "text", "x": 0.0, "y": 0.0, "dx": 4.0, "dy": 4.0,
                                               "text": "abcdefghij", "ha": "left", "va": "bottom"}]},
                        {"id": "b", "parts": [{"p": "text", "x": 0.5, "y": 0.0, "dx": 0.0, "dy": 0.0,
                                               "text": "xy", "ha": "right", "va": "top"}]}]}
    (_, _, a), (_, _, b) = label_boxes(pic)
    assert a == pytest.approx((104.0, 104.0, 164.0, 116.5))        # 10 × 6 px wide, 12.5 px high
    assert b == pytest.approx((138.0, 87.5, 150.0, 100.0))
    assert overlapping_labels(pic) == []
    pic["elements"][1]["parts"][0].update(y=0.1, va="bottom")    # now inside a's box
    assert len(overlapping_labels(pic)) == 1


# ------------------------------------------------------------------------------------------ subspace
def test_subspace_default_pivot_percussion_axis_and_force_by_hand():
    """Pivot at the origin, bar of m = 2, ρ = 0.5 with c at (1, 0), force of 1 N up at x = 1.6: s is the pivot,
    T the axis of percussion x = d + ρ²/d = 1.25, R the lines through the pivot, f the line x = 1.6."""
    pic = SubspaceExplorer(display="agg").picture()
    assert problems(pic) == []
    els = elements(pic)
    assert _marks(els["s1"]) == [pytest.approx((0.0, 0.0))]
    x0, x1, y0, y1 = pic["box"]
    for name, x in (("T1", 1.25), ("f", 1.6)):
        (seg,) = _paths(els[name])
        np.testing.assert_allclose(seg[:, 0], [x, x], atol=1e-4)              # vertical, clipped to the view
        np.testing.assert_allclose(sorted(seg[:, 1]), [y0, y1], atol=1e-4)
    for name in ("R1", "R2", "Rmu"):                                          # through the pivot
        (seg,) = _paths(els[name])
        d = seg[1] - seg[0]
        assert abs(d[0] * seg[0][1] - d[1] * seg[0][0]) < 1e-3 * np.hypot(*d)
    assert els["s1"]["symbol"] == "s" and "(6.1, 6.8)" in els["s1"]["desc"] and "(0, 0) m" in els["s1"]["desc"]
    assert els["T1"]["desc"].endswith("0.8 N, through (1.25, 0) m")         # T = I s / (sᵀIs): 2·1/2.5
    assert fill(pic, SubspaceExplorer(display="agg").mechanism_points()) >= 1 / 3


def test_subspace_plane_joint_ideal_motions_and_a_couple_reaction():
    """The plane joint: s₁, s₂ translations (points at infinity, edge arrows), R the line at infinity (a
    couple glyph), U the spin about the centre of mass (1, 0) where T₁ and T₂ meet."""
    ex = SubspaceExplorer(display="agg", joint="plane joint (4.79)", show="s, R, T, U")
    pic = ex.picture()
    assert problems(pic) == []
    els = elements(pic)
    for name in ("s1", "s2"):
        kinds = [p["p"] for p in els[name]["parts"]]
        assert "mark" not in kinds and "arrow" in kinds
        assert any(p["p"] == "text" and p["text"].endswith("at ∞") for p in els[name]["parts"])
    assert [p["p"] for p in els["R1"]["parts"]][0] == "glyph"
    assert _marks(els["U1"]) == [pytest.approx((1.0, 0.0))]
    assert els["U1"]["symbol"] == "U"
    texts = [p["text"] for p in els["U1"]["parts"] if p["p"] == "text"]
    assert texts == ["U (T₁ ∩ T₂)"]


def test_subspace_coinciding_points_are_one_element_with_both_names():
    """A pin in a slot struck at (1.6, 0.5) along x: U and Uγ coincide (Uγ is U times γ): one element."""
    ex = SubspaceExplorer(display="agg", joint="revolute + prismatic", show="I⁻¹f = sψ + Uγ",
                          **{"force angle": 0.0, "force y": 0.5})
    els = elements(ex.picture())
    assert "U_gamma" not in els and els["U1"]["symbol"] == "U, Uγ"
    U = ex.state["U"][:, 0]
    assert _marks(els["U1"]) == [pytest.approx((-U[1] / U[2], U[0] / U[2]), abs=1e-4)]


# ------------------------------------------------------------------------------------------ impulse
L_DOOR, W_DOOR = 0.9, 0.04


def test_impulse_door_axis_of_percussion_and_free_pole_by_hand():
    """The door (0.9 m × 0.04 m, hinge at 0) struck across at x = 0.55: the axis of percussion of the hinge is
    x = 2L/3 + w²/(6L) (5.67), the pole if free x = L/2 − (ρ_c²)/(0.55 − L/2) with ρ_c² = (L² + w²)/12."""
    from planargeo.widgets import ImpulseExplorer

    ex = ImpulseExplorer(display="agg", body="door")
    pic = ex.picture()
    assert problems(pic) == []
    els = elements(pic)
    (seg,) = _paths(els["axis"])
    np.testing.assert_allclose(seg[:, 0], 2 * L_DOOR / 3 + W_DOOR ** 2 / (6 * L_DOOR), atol=1e-5)
    assert _marks(els["centre of percussion"]) == [pytest.approx((0.600296, 0.0), abs=1e-5)]
    free = L_DOOR / 2 - (L_DOOR ** 2 + W_DOOR ** 2) / 12 / (0.55 - L_DOOR / 2)
    assert _marks(els["free pole"]) == [pytest.approx((free, 0.0), abs=1e-5)]
    assert _marks(els["pole"]) == [pytest.approx((0.0, 0.0), abs=1e-9)]              # held: about the hinge
    assert els["reaction"]["symbol"] == "ĵᵣ" and "(5.67)" in els["reaction"]["desc"]
    assert fill(pic, ex.mechanism_points()) >= 1 / 3                                   # the door fills the view


def test_impulse_a_blow_through_the_centre_of_mass_of_a_free_body_has_its_pole_at_infinity():
    """Free, struck along the body's axis through c: a translation along x, its pole the ideal point across it."""
    from planargeo.widgets import ImpulseExplorer

    ex = ImpulseExplorer(display="agg", body="door", support="free", **{"strike y": 0.0, "strike angle": 0.0,
                                                                          "strike x": 0.3})
    els = elements(ex.picture())
    kinds = [p["p"] for p in els["pole"]["parts"]]
    assert "mark" not in kinds and "arrow" in kinds
    assert "at infinity" in els["pole"]["desc"]
    assert [p["text"] for p in els["pole"]["parts"] if p["p"] == "text"] == ["v (pole) at ∞"]


# ------------------------------------------------------------------------------------------ splitting
def test_splitting_thesis_example_7_5_poles_by_hand():
    """Two bodies (ρ = L/2, φ = 45°), a couple on the tip: body 1 turns about its pin (0, 0); the pole of a₂
    lies on the x axis at x/L = 1 + 2η² cos φ / (4 + 5η²) with η = 2 (7.48), by hand here."""
    from planargeo.widgets import SplittingExplorer

    ex = SplittingExplorer(display="agg")
    pic = ex.picture()
    assert problems(pic) == []
    els = elements(pic)
    x = 1 + 2 * 4 * np.cos(np.radians(45.0)) / (4 + 5 * 4)
    assert _marks(els["a2"]) == [pytest.approx((x, 0.0), abs=1e-5)]
    assert _marks(els["a1"]) == [pytest.approx((0.0, 0.0), abs=1e-5)]
    assert _marks(els["centre"]) == [pytest.approx((0.0, 0.0), abs=1e-5)]
    assert _marks(els["split"]) == [pytest.approx((1.0, 0.0), abs=1e-5)]
    (lower,) = _paths(els["lower"])
    (upper,) = _paths(els["upper"])
    np.testing.assert_allclose(lower, [[0, 0], [1, 0]], atol=1e-5)
    np.testing.assert_allclose(upper, [[1, 0], [1 + np.sqrt(0.5), np.sqrt(0.5)]], atol=1e-5)
    assert [p["p"] for p in els["couple"]["parts"]][0] == "glyph"              # the couple: line at infinity
    assert els["couple"]["symbol"] == "−f₃" and "(7.44)" in els["couple"]["desc"]
    assert fill(pic, ex.mechanism_points()) >= 1 / 3


def test_splitting_a_translating_body_has_its_pole_at_infinity():
    """A straight chain of 3 under gravity alone, split at joint 3: whatever translates has an ideal pole
    (an edge arrow, 'at ∞'), every element keeps its symbol and description."""
    from planargeo.widgets import SplittingExplorer

    ex = SplittingExplorer(display="agg", **{"bodies n": 3, "bend φ (deg)": 0.0, "g (m/s²)": 9.81,
                                             "couple τ (N·m)": 0.0})
    assert ex.message == ""
    pic = ex.picture()
    assert problems(pic) == []
    els = elements(pic)
    assert "pole at (0, 0) m" in els["a1"]["desc"]            # body 1 held at its pin, turning
    ideal = [k for k in ("a2", "a3") if k in els and "at infinity" in els[k]["desc"]]
    assert ideal == ["a2", "a3"]                                 # the free-floating pair falls, translating
    for k in ideal:
        assert not any(p["p"] == "mark" for p in els[k]["parts"]) and any(p["p"] == "arrow" for p in els[k]["parts"])


# ------------------------------------------------------------------------------------------ articulated
def test_articulated_one_body_conic_centre_and_percussion_axis_by_hand():
    """One body of mass 1 (ρ = L/λ = 1/3) along x: Aₖ = Iₖ, centred at (1/2, 0); the axis of percussion of
    the pole a = (0, −0.8) for a rod about its centre (5.67): the line through c across ca at ρ²/|ca| beyond c."""
    from planargeo.widgets import ArticulatedExplorer

    ex = ArticulatedExplorer(display="agg", **{"bodies n": 1, "λ = L/ρ": 3.0})
    pic = ex.picture()
    assert problems(pic) == []
    els = elements(pic)
    for name in ("A1", "I1"):
        (e,) = [p for p in els[name]["parts"] if p["p"] == "ellipse"]
        assert (e["x"], e["y"]) == pytest.approx((0.5, 0.0), abs=1e-5)
    a, c, rho2 = np.array([0.0, -0.8]), np.array([0.5, 0.0]), (1 / 3) ** 2
    u = (c - a) / np.hypot(*(c - a))
    foot = c + u * rho2 / np.hypot(*(c - a))                  # the axis ⟂ ca, on the far side of c from a
    seg = _paths(els["Aa"])[0]
    for X in seg:
        assert abs((X - foot) @ u) < 1e-4
    assert _marks(els["a"]) == [pytest.approx((0.0, -0.8), abs=1e-5)]
    # the chart: one body, no outboard recursion: a single step, error 0
    assert "chart error" in els and els["chart error"]["desc"].endswith(": 0")
    assert fill(pic, ex.mechanism_points()) >= 1 / 3


def test_articulated_default_fills_the_chain_part_and_focus_fades_the_rest():
    from planargeo.widgets import ArticulatedExplorer

    ex = ArticulatedExplorer(display="agg", focus="body 3")
    pic = ex.picture()
    assert problems(pic) == []
    els = elements(pic)
    assert els["A3"].get("opacity", 1.0) == 1.0 and els["A1"]["opacity"] < 1.0 and els["I2"]["opacity"] < 1.0
    assert [p["text"] for p in els["A3"]["parts"] if p["p"] == "text"] == ["A₃"]
    assert fill(pic, ex.mechanism_points()) >= 1 / 3
    x0, x1, _, _ = pic["box"]                       # the chain's lines stay left of the chart
    for name in ("Aa", "Ia", "polar"):
        for seg in _paths(els[name]):
            assert seg[:, 0].max() <= x0 + 0.67 * (x1 - x0)


# ------------------------------------------------------------------------------------------ all four
FOUR = ["SubspaceExplorer", "ImpulseExplorer", "SplittingExplorer", "ArticulatedExplorer"]


def _random_values(ex, rng) -> dict:
    import ipywidgets as W

    vals = {}
    for k, w in ex.controls.items():
        if k == "key" or rng.random() >= 0.3:
            continue
        if isinstance(w, (W.FloatSlider, W.IntSlider)):
            x = w.min + (w.max - w.min) * rng.random()
            vals[k] = int(round(x)) if isinstance(w, W.IntSlider) else float(x)
        elif isinstance(w, W.Checkbox):
            vals[k] = bool(rng.random() < 0.5)
        elif hasattr(w, "options"):
            opts = [o[1] if isinstance(o, tuple) else o for o in w.options]
            vals[k] = opts[int(rng.integers(len(opts)))]
    return vals


@pytest.mark.parametrize("name", FOUR)
def test_every_element_described_and_no_labels_overlap_in_30_random_states(name):
    import planargeo.widgets as pw

    ex = getattr(pw, name)(display="agg")
    rng = np.random.default_rng(5)
    shown = 0
    for _ in range(30):
        ex.set(**_random_values(ex, rng))
        if ex.message:
            continue
        shown += 1
        found = problems(ex.picture())
        assert found == [], (ex.values, found)
    assert shown >= 15


@pytest.mark.parametrize("name, handle, move", [
    ("SubspaceExplorer", "force point", (0.3, 0.4)), ("ImpulseExplorer", "blow point", (0.1, 0.05)),
    ("SplittingExplorer", "tip", (-0.2, 0.1)), ("ArticulatedExplorer", "pole a", (0.5, -0.3))])
def test_a_drag_keeps_every_element_id_and_moves_the_picture(name, handle, move):
    import planargeo.widgets as pw

    ex = getattr(pw, name)(display="agg")
    before = ex.picture()
    start = np.asarray(next(h for h in ex.handles() if h.name == handle).where(), float)
    ex.drag(handle, tuple(start), tuple(start + move), steps=3)
    assert ex.message == ""
    after = ex.picture()
    assert [e["id"] for e in before["elements"]] == [e["id"] for e in after["elements"]]
    assert before["elements"] != after["elements"]
    (h,) = [h for h in after["handles"] if h["id"] == handle]
    if name != "SplittingExplorer":                     # the tip follows the bend, not the pointer
        assert (h["x"], h["y"]) == pytest.approx(tuple(start + move), abs=1e-4)
